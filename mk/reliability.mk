# Reliability (docs/reliability.md): sanitizers, fuzzing, allocation failure.
#   make sanitize           the library and every tests/test_*.c built with
#                           ASan + UBSan ($(BUILD)/asan), each test binary run
#                           directly (no Valgrind); fails on any report
#   make fuzz               the three libFuzzer targets of fuzz/ ($(BUILD)/fuzz),
#                           FUZZ_SECONDS each (default 60) from fuzz/corpus/
#   make fuzz-smoke         a fixed number of runs each, seed 1, from the
#                           committed seeds only (about 10 s each)
#   make mutate             every mutant of tests/mutants.txt built and the
#                           fast tests run on it (tools/mutate): each must
#                           be caught
#   make check-reliability  sanitize, fuzz-smoke, then mutate (what CI runs)
# The allocation-failure test, tests/test_alloc_failure.c, is an ordinary
# cmocka test: make check runs it under Valgrind, make sanitize under ASan.
#
# SAN_CC (default clang) may be set to gcc for the sanitize build; the fuzz
# targets need clang's libFuzzer. Extra libFuzzer flags: FUZZ_ARGS.

SAN_CC      ?= clang
SAN_FLAGS   := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all -g -O1
SAN_DIR     := $(BUILD)/asan
SAN_LIB_OBJ := $(LIB_SRC:lib/%.c=$(SAN_DIR)/lib/%.o)
SAN_TEST_BIN := $(TEST_SRC:tests/%.c=$(SAN_DIR)/tests/%)
# allow_user_segv_handler=0: ASan, not cmocka, reports a crash in a test
SAN_ENV     := ASAN_OPTIONS=detect_leaks=1:allow_user_segv_handler=0:detect_stack_use_after_return=1:strict_string_checks=1 \
               UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

FUZZ_CC      ?= clang
# GRID_MIN_BODIES=8: fuzzed worlds of 8 bodies or more use the grid broad
# phase, smaller ones the sweep
FUZZ_FLAGS   := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1 \
                -DGRID_MIN_BODIES=8
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_LIB_OBJ := $(LIB_SRC:lib/%.c=$(FUZZ_DIR)/lib/%.o)
FUZZ_TARGETS := scene polygon world
FUZZ_BIN     := $(FUZZ_TARGETS:%=$(FUZZ_DIR)/fuzz_%)
FUZZ_SECONDS ?= 60
FUZZ_ARGS    ?=

.PHONY: sanitize sanitize-build fuzz fuzz-smoke fuzz-build check-reliability mutate

mutate:
	@tools/ensure-deps build check
	@tools/mutate $(BUILD)

# ------------------------------------------------------------ sanitizers

$(SAN_LIB_OBJ): $(SAN_DIR)/lib/%.o: lib/%.c
	@mkdir -p $(@D)
	$(SAN_CC) $(CPPFLAGS) -Ilib $(WARN) $(SAN_FLAGS) $(CFLAGS) -c $< -o $@

$(SAN_DIR)/libcarom.a: $(SAN_LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(SAN_DIR)/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	$(SAN_CC) $(CPPFLAGS) -Ilib -Itests $(WARN) $(SAN_FLAGS) $(CFLAGS) -c $< -o $@

$(SAN_TEST_BIN): $(SAN_DIR)/tests/%: $(SAN_DIR)/tests/%.o $(SAN_DIR)/tests/support.o $(SAN_DIR)/libcarom.a
	$(SAN_CC) $(SAN_FLAGS) $(LDFLAGS) -o $@ $^ -lcmocka -lm

sanitize-build: $(SAN_TEST_BIN)

# Each binary's output is shown; its cmocka counts are summed, and a binary
# that exits non-zero or prints a sanitizer report without a cmocka failure
# counts as one failure.
sanitize:
	@tools/ensure-deps build check sanitize
	@$(MAKE) --no-print-directory sanitize-build
	@passed=0; failed=0; bad=""; \
	for t in $(SAN_TEST_BIN); do \
	  log=$$t.log; \
	  $(SAN_ENV) $$t >$$log 2>&1; rc=$$?; \
	  cat $$log; \
	  p=$$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' $$log | tail -n 1); \
	  f=$$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' $$log | tail -n 1); \
	  passed=$$((passed + $${p:-0})); failed=$$((failed + $${f:-0})); \
	  if [ $$rc -ne 0 ] || grep -q -e 'ERROR: AddressSanitizer' -e 'ERROR: LeakSanitizer' -e 'runtime error:' $$log; then \
	    if [ -z "$$f" ] || [ "$$f" = 0 ]; then failed=$$((failed + 1)); fi; \
	    bad="$$bad $${t##*/}"; \
	  fi; \
	done; \
	if [ -n "$$bad" ]; then echo "sanitize: failing binaries:$$bad"; fi; \
	echo "sanitize: $$passed passed, $$failed failed"; \
	[ -z "$$bad" ]

# ---------------------------------------------------------------- fuzzing

$(FUZZ_LIB_OBJ): $(FUZZ_DIR)/lib/%.o: lib/%.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CPPFLAGS) -Ilib $(WARN) $(FUZZ_FLAGS) $(CFLAGS) -c $< -o $@

$(FUZZ_DIR)/libcarom.a: $(FUZZ_LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(FUZZ_BIN:%=%.o): $(FUZZ_DIR)/%.o: fuzz/%.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CPPFLAGS) -Ifuzz $(WARN) $(FUZZ_FLAGS) $(CFLAGS) -c $< -o $@

$(FUZZ_BIN): $(FUZZ_DIR)/%: $(FUZZ_DIR)/%.o $(FUZZ_DIR)/libcarom.a
	$(FUZZ_CC) -fsanitize=fuzzer,address,undefined $(LDFLAGS) -o $@ $^ -lm

fuzz-build: $(FUZZ_BIN)

fuzz:
	@tools/ensure-deps build sanitize
	@$(MAKE) --no-print-directory fuzz-build
	@sh fuzz/run-fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS) "$(FUZZ_ARGS)" $(FUZZ_TARGETS)

# CI and make check: every committed seed, then a fixed number of runs with
# a fixed seed, so a fast machine tries no more than a slow one (the
# mutations still vary a little from run to run: fuzz/run-fuzz.sh).
fuzz-smoke:
	@tools/ensure-deps build sanitize
	@$(MAKE) --no-print-directory fuzz-build
	@sh fuzz/run-fuzz.sh $(FUZZ_DIR) smoke "$(FUZZ_ARGS)" $(FUZZ_TARGETS)

# Both run even when the first fails, so CI sees every failure at once.
check-reliability:
	@rc=0; \
	$(MAKE) --no-print-directory sanitize || rc=1; \
	$(MAKE) --no-print-directory fuzz-smoke || rc=1; \
	$(MAKE) --no-print-directory mutate || rc=1; \
	if [ $$rc -ne 0 ]; then echo "check-reliability: FAILED"; else echo "check-reliability: OK"; fi; \
	exit $$rc

# ($(FUZZ_DIR)/*.d is included by the Makefile itself)
-include $(wildcard $(SAN_DIR)/*/*.d $(FUZZ_DIR)/*/*.d)
