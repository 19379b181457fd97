# carom: a 2D rigid-body physics library in C99.
#   make          library (build/libcarom.so, build/libcarom.a)
#   make check    every test under Valgrind
#   make run      the demo (or, without a display, a headless render)
# Output goes to $(BUILD); `make BUILD=other` keeps separate trees.

BUILD   ?= build
CC      ?= cc
OPT     ?= -O2 -g
WARN    := -std=c99 -Wall -Wextra -pedantic -Wstrict-prototypes -Wmissing-prototypes
ifdef CI
WARN    += -Werror
endif
CFLAGS  ?=
CPPFLAGS += -Iinclude -MMD -MP
LDLIBS_LIB := -lm
# No value-changing floating-point flags for the library: no a * b + c fused
# into one rounding (docs/reliability.md: results are the same bits with any
# compiler and optimisation level, make check-determinism).
LIB_FP  := -ffp-contract=off
# The library at -O3, as Box2D v3's release build: fewer instructions a step
# than -O2 (docs/performance.md) and the same bits. -O2 is kept for the rest.
LIB_OPT ?= $(patsubst -O2,-O3,$(OPT))

# The version lives in one place, include/carom.h's CAROM_VERSION_* macros;
# the Python package reads it there too (setup.py), and tools/check-version
# (make check) compares Cargo.toml, Cargo.lock and the bindings' constants.
carom_version_part = $(shell sed -n 's/^\#define CAROM_VERSION_$(1) \([0-9][0-9]*\).*/\1/p' include/carom.h)
VERSION_MAJOR := $(call carom_version_part,MAJOR)
VERSION       := $(VERSION_MAJOR).$(call carom_version_part,MINOR).$(call carom_version_part,PATCH)
SONAME  := libcarom.so.$(VERSION_MAJOR)
SO_REAL := $(BUILD)/libcarom.so.$(VERSION)

LIB_SRC := $(sort $(wildcard lib/*.c))
LIB_OBJ := $(LIB_SRC:lib/%.c=$(BUILD)/lib/%.o)
LIB_PIC := $(LIB_SRC:lib/%.c=$(BUILD)/pic/%.o)
LIB_DBG := $(LIB_SRC:lib/%.c=$(BUILD)/debug/%.o)

TEST_SRC := $(sort $(wildcard tests/test_*.c))
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
VALGRIND := valgrind -q --leak-check=full --show-leak-kinds=definite,indirect,possible --errors-for-leak-kinds=definite,indirect,possible --error-exitcode=1

.PHONY: all lib check tests deps-check clean run bench
all: lib

lib: $(BUILD)/libcarom.a $(BUILD)/libcarom.so

$(BUILD)/lib/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ilib $(WARN) $(LIB_OPT) $(LIB_FP) $(CFLAGS) -fvisibility=hidden -c $< -o $@

$(BUILD)/pic/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ilib $(WARN) $(LIB_OPT) $(LIB_FP) $(CFLAGS) -fvisibility=hidden -fPIC -c $< -o $@

# The static library is one relocatable object whose hidden (internal)
# symbols are made local, so a program linking it statically sees only
# carom_* names and cannot clash with ours. Tests, which call internal
# functions, link the plain archive instead.
$(BUILD)/libcarom.a: $(LIB_OBJ)
	@rm -f $@
	ld -r -o $(BUILD)/carom-all.o $^
	objcopy --localize-hidden $(BUILD)/carom-all.o
	ar rcs $@ $(BUILD)/carom-all.o

# The tests link a build with CAROM_DEBUG_CHECKS: after every sub-step it
# aborts, naming the body, if any state is not finite.
$(BUILD)/debug/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ilib $(WARN) $(LIB_OPT) $(LIB_FP) $(CFLAGS) -DCAROM_DEBUG_CHECKS -fvisibility=hidden -c $< -o $@

$(BUILD)/libcarom-internal.a: $(LIB_DBG)
	@rm -f $@
	ar rcs $@ $^

$(SO_REAL): $(LIB_PIC)
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,--no-undefined $(LDFLAGS) -o $@ $^ $(LDLIBS_LIB)

$(BUILD)/libcarom.so: $(SO_REAL)
	ln -sf libcarom.so.$(VERSION) $(BUILD)/$(SONAME)
	ln -sf $(SONAME) $@

# ---------------------------------------------------------------- tests
deps-check:
	@tools/ensure-deps build check demo

tests: $(TEST_BIN)

$(BUILD)/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ilib -Itests $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(BUILD)/tests/test_%: $(BUILD)/tests/test_%.o $(BUILD)/tests/support.o $(BUILD)/libcarom-internal.a
	$(CC) $(LDFLAGS) -o $@ $^ -lcmocka -lm

# Every test: the cmocka binaries under Valgrind, the README's example, and
# each part's own checks (runner, demo under Xvfb, ABI, install, bindings)
# when its fragment is present.
CHECK_PARTS := $(if $(wildcard mk/runner.mk),check-runner) $(if $(wildcard mk/demo.mk),check-demo) \
               $(if $(wildcard mk/bindings.mk),check-bindings) $(if $(wildcard mk/stress.mk),check-stress) \
               $(if $(wildcard mk/reliability.mk),check-reliability) \
               $(if $(wildcard mk/determinism.mk),check-determinism)

# Every part's output goes to $(BUILD)/check.log too; the closing line sums
# the tests as the runners counted them (tools/check-summary), skipped ones
# included, and a part that fails stops the run after it.
CHECK_LOG := $(BUILD)/check.log

check: deps-check
	@$(MAKE) --no-print-directory tests lib
	@mkdir -p $(BUILD); : >$(CHECK_LOG); rc=0; \
	tools/check-part $(CHECK_LOG) tools/run-tests "$(VALGRIND)" $(TEST_BIN) || rc=1; \
	[ $$rc -eq 0 ] && { tools/check-part $(CHECK_LOG) tools/check-readme $(BUILD) || rc=1; }; \
	[ $$rc -eq 0 ] && { tools/check-part $(CHECK_LOG) tools/check-exports $(BUILD) || rc=1; }; \
	[ $$rc -eq 0 ] && { tools/check-part $(CHECK_LOG) tools/check-api-doc || rc=1; }; \
	[ $$rc -eq 0 ] && { tools/check-part $(CHECK_LOG) tools/api-reference --check || rc=1; }; \
	[ $$rc -eq 0 ] && { tools/check-part $(CHECK_LOG) tools/check-version || rc=1; }; \
	[ $$rc -eq 0 ] && { tools/check-part $(CHECK_LOG) tools/check-ffi $(BUILD) || rc=1; }; \
	for part in $(CHECK_PARTS); do \
	  [ $$rc -eq 0 ] || break; \
	  tools/check-part $(CHECK_LOG) $(MAKE) --no-print-directory $$part || { rc=1; echo "check: $$part FAILED"; }; \
	done; \
	tools/check-summary $(CHECK_LOG) $$rc; exit $$rc

clean:
	rm -rf $(BUILD)

-include $(wildcard $(BUILD)/*/*.d)

# Each part of the project beyond the library and its tests (runner, demo,
# benchmarks, bindings, ...) keeps its rules in a fragment of its own.
include $(sort $(wildcard mk/*.mk))

# tools/check-version reads the version the Makefile computes.
.PHONY: print-version
print-version:
	@echo $(VERSION)
