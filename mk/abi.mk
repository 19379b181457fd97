# The ABI check (docs/abi.md): the shared library's ABI, as libabigail reads
# it from the DWARF of the exported functions and the types of include/, is
# compared with the committed baseline abi/libcarom.abi.
#   make abi-check     fail on any change that is not an addition
#   make abi-baseline  accept the current ABI: rewrite abi/libcarom.abi
#   make check-abi     tests/test_abi.sh (exports, abi-check, a caught break)
#
# Allowed: new functions, new enumerators at the end, new fields at the end
# of the size-prefixed structs (abi/carom.abignore). Anything else fails.
# abidiff's exit status is a bit set: 1 error, 2 usage, 4 ABI change,
# 8 incompatible change. libabigail sets 8 only for removed symbols; a changed
# parameter type or struct layout sets 4 alone, so with additions filtered
# out (--no-added-syms) any non-zero status is a failure.

ABI_BASELINE := abi/libcarom.abi
ABI_SUPPR    := abi/carom.abignore
ABI_DUMP     := $(BUILD)/abi/libcarom.abi
ABI_REPORT   := $(BUILD)/abi/abidiff.txt
# No paths of the build machine in the dump: the baseline is committed.
ABIDW_FLAGS  := --headers-dir include --drop-private-types --no-corpus-path \
                --no-comp-dir-path --short-locs
ABIDIFF_FLAGS := --suppressions $(ABI_SUPPR) --no-added-syms

.PHONY: abi-dump abi-check abi-baseline check-abi

# abidw without DWARF sees symbols but no types, and would compare nothing.
abi-dump: $(BUILD)/libcarom.so
	@tools/ensure-deps abi
	@if ! readelf -S $(SO_REAL) | grep -q '\.debug_info'; then \
	  echo "abi: $(SO_REAL) has no debug information; build it with -g (OPT='-O2 -g')" >&2; \
	  exit 1; fi
	@mkdir -p $(BUILD)/abi
	abidw $(ABIDW_FLAGS) --out-file $(ABI_DUMP) $(SO_REAL)

abi-check: abi-dump
	@if [ ! -f $(ABI_BASELINE) ]; then \
	  echo "abi-check: no baseline $(ABI_BASELINE); run 'make abi-baseline' and commit it" >&2; \
	  exit 1; fi
	@rc=0; abidiff $(ABIDIFF_FLAGS) $(ABI_BASELINE) $(ABI_DUMP) >$(ABI_REPORT) 2>&1 || rc=$$?; \
	sed -e '/^$$/d' $(ABI_REPORT); \
	if [ $$rc -eq 0 ]; then \
	  added=$$(abidiff --suppressions $(ABI_SUPPR) --added-fns $(ABI_BASELINE) $(ABI_DUMP) \
	           | sed -n "s/^  \[A\] 'function \(.*\)'.*/\1/p"); \
	  if [ -n "$$added" ]; then \
	    echo "abi-check: added since the baseline (allowed):"; \
	    echo "$$added" | sed 's/^/  /'; fi; \
	  echo "abi-check: OK, compatible with $(ABI_BASELINE)"; \
	elif [ $$((rc & 3)) -ne 0 ]; then \
	  echo "abi-check: abidiff failed (exit status $$rc)" >&2; exit 1; \
	else \
	  if [ $$((rc & 8)) -ne 0 ]; then kind="INCOMPATIBLE change (removed symbols)"; \
	  else kind="incompatible change (not an addition)"; fi; \
	  echo "abi-check: FAILED: $$kind, abidiff exit status $$rc" >&2; \
	  echo "abi-check: keep the old ABI, or bump VERSION_MAJOR and run 'make abi-baseline' (docs/abi.md)" >&2; \
	  exit 1; \
	fi

abi-baseline: abi-dump
	@mkdir -p $(dir $(ABI_BASELINE))
	cp $(ABI_DUMP) $(ABI_BASELINE)
	@echo "abi-baseline: wrote $(ABI_BASELINE) from $(SO_REAL); commit it"

check-abi: $(BUILD)/libcarom.a $(BUILD)/libcarom.so
	@MAKE="$(MAKE)" sh tests/test_abi.sh $(BUILD)
