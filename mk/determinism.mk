# Determinism across processes, compilers and optimisation levels
# (tests/determinism.c, docs/reliability.md):
#   make check-determinism   build the library and tests/determinism.c with
#                            each of DET_CONFIGS into $(BUILD)/determinism/,
#                            run each (its own process) and require that all
#                            print the same hash for every scene
# The library is always compiled with -ffp-contract=off (Makefile): no
# compiler may fuse a * b + c into one rounding.

DET_DIR     := $(BUILD)/determinism
DET_CONFIGS ?= gcc:-O0 gcc:-O2 gcc:-O3 clang:-O0 clang:-O2 clang:-O3

.PHONY: check-determinism

check-determinism:
	@tools/ensure-deps build sanitize
	@rm -rf $(DET_DIR); mkdir -p $(DET_DIR); rc=0; first=""; \
	for cfg in $(DET_CONFIGS); do \
	  cc=$${cfg%%:*}; opt=$${cfg#*:}; out=$(DET_DIR)/$$cc$$opt; \
	  $$cc -std=c99 $$opt -ffp-contract=off -Iinclude -Ilib lib/*.c tests/determinism.c -lm -o $$out \
	    || { echo "determinism: $$cc $$opt does not build"; rc=1; continue; }; \
	  $$out scenes >$$out.txt || { echo "determinism: $$cc $$opt failed to run"; rc=1; continue; }; \
	  if [ -z "$$first" ]; then first=$$out.txt; cat $$first; \
	  elif cmp -s $$first $$out.txt; then echo "ok   $$cc $$opt: the same hashes as $$(basename $$first .txt)"; \
	  else echo "FAIL $$cc $$opt differs from $$(basename $$first .txt):"; diff $$first $$out.txt; rc=1; fi; \
	done; \
	n=$$(echo $(DET_CONFIGS) | wc -w); \
	if [ $$rc -eq 0 ]; then echo "determinism: $$n passed, 0 failed"; else echo "determinism: FAILED"; fi; \
	exit $$rc
