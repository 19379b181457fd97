# Benchmarks (bench/): carom against Chipmunk 7, Box2D 2.4 and Box2D v3 on
# the same scenes, carom's scaling, memory and broad phase, and a callgrind
# profile.
#   make bench         install the peers if missing (tools/ensure-deps peers),
#                      build, run everything, write docs/performance.md
#   make bench-build   only build $(BUILD)/bench/*
# Every engine's bench is compiled with $(OPT) (-O2 -g by default), carom's
# library with $(LIB_OPT) (-O3 -g) as the Makefile builds it; Chipmunk
# and Box2D 2.4 are Debian's packaged libraries. Raw outputs and profiles
# stay in $(BUILD)/bench/. Use a tree of your own: make BUILD=build-bench bench
#
# Box2D v3 is not packaged; it is built from a source tree named by
# BOX2D3_DIR (a checkout of github erincatto/box2d), once, with CMake in
# Release (its own flags), as a static library:
#   make bench BOX2D3_DIR=/path/to/box2d
# Without it the Box2D v3 bench is skipped.
#
# Peer benches are built only when their headers exist; the check runs in the
# sub-make, after ensure-deps may have installed them.
#
# The compile and link rules below serve every bench program (this file,
# mk/effects.mk, mk/accuracy.mk): each source under bench/ and bench/peers/
# compiles once into $(BENCH_DIR)/NAME.o, and each program is linked by
# $(call bench_program,...). The other fragments include this one first.

ifndef BENCH_MK_INCLUDED
BENCH_MK_INCLUDED := 1

BENCH_DIR := $(BUILD)/bench
CXX       ?= c++
BENCH_CXXFLAGS := -std=c++17 -Wall -Wextra
BENCH_HAS_CHIPMUNK = $(shell printf '\043include <chipmunk/chipmunk.h>\n' | $(CC) -E -x c - >/dev/null 2>&1 && echo yes)
BENCH_HAS_BOX2D = $(shell printf '\043include <box2d/box2d.h>\n' | $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)

# ------------------------------------------------------------ Box2D v3
BOX2D3_DIR ?=
BOX2D3_BUILD := $(BUILD)/box2d3
BOX2D3_LIB   := $(BOX2D3_BUILD)/src/libbox2d.a
BOX2D3_JOBS  ?= $(shell nproc 2>/dev/null || echo 1)
BOX2D3_CMAKE := -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF -DBOX2D_SAMPLES=OFF \
                -DBOX2D_UNIT_TESTS=OFF -DBOX2D_BENCHMARKS=OFF -DBOX2D_DOCS=OFF
# A v3 tree has include/box2d/types.h (2.4 has b2_*.h headers instead).
BOX2D3_TREE = $(and $(BOX2D3_DIR),$(wildcard $(BOX2D3_DIR)/CMakeLists.txt),$(wildcard $(BOX2D3_DIR)/include/box2d/types.h))
BOX2D3_HAS_CMAKE = $(shell command -v cmake >/dev/null 2>&1 && echo yes)
BOX2D3_SKIP = $(if $(BOX2D3_TREE),$(if $(BOX2D3_HAS_CMAKE),,cmake not found (tools/ensure-deps peers installs it)),set BOX2D3_DIR to a Box2D v3 source tree (github erincatto/box2d))

BENCH_BIN = $(BENCH_DIR)/bench_carom $(BENCH_DIR)/bench_broadphase \
            $(if $(BENCH_HAS_CHIPMUNK),$(BENCH_DIR)/bench_chipmunk) \
            $(if $(BENCH_HAS_BOX2D),$(BENCH_DIR)/bench_box2d) \
            $(if $(BOX2D3_SKIP),,$(BENCH_DIR)/bench_box2d3 $(BENCH_DIR)/box2d3-version.txt)

.PHONY: bench bench-build

bench:
	@tools/ensure-deps build peers || echo "bench: could not install the peers; benchmarking carom alone"
	@$(MAKE) --no-print-directory bench-build
	@sh bench/run-bench.sh $(BENCH_DIR)

bench-build: $(BUILD)/libcarom.a
	@$(if $(BOX2D3_SKIP),echo "bench: Box2D v3 skipped: $(BOX2D3_SKIP)",:)
	@$(MAKE) --no-print-directory $(BENCH_BIN)

# ------------------------------------------------------------ objects
BENCH_COMPILE_C = $(CC) $(CPPFLAGS) -Ibench $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(BENCH_DIR)/%.o: bench/%.c bench/scenes.h
	@mkdir -p $(@D)
	$(BENCH_COMPILE_C)

$(BENCH_DIR)/%.o: bench/peers/%.c bench/scenes.h
	@mkdir -p $(@D)
	$(BENCH_COMPILE_C)

$(BENCH_DIR)/%.o: bench/peers/%.cpp bench/scenes.h
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) -Ibench $(BENCH_CXXFLAGS) $(OPT) $(CXXFLAGS) -c $< -o $@

# Box2D v3's headers need C11 (anonymous unions) and must shadow Debian's
# Box2D 2.4 headers, which share the <box2d/box2d.h> name: -isystem comes
# before the system directories and keeps its headers' warnings out.
$(BENCH_DIR)/bench_box2d3.o: BENCH_COMPILE_C = $(CC) $(CPPFLAGS) -Ibench -isystem $(BOX2D3_DIR)/include \
  $(filter-out -std=%,$(WARN)) -std=c11 $(OPT) $(CFLAGS) -c $< -o $@
$(BENCH_DIR)/bench_box2d3.o: $(BOX2D3_LIB)

# ------------------------------------------------------------ programs
# $(call bench_program,PROGRAM,OBJECTS,LIBRARIES): link PROGRAM from the
# named objects of $(BENCH_DIR) and LIBRARIES, then -lm. Archives (*.a)
# among LIBRARIES are prerequisites too. Linked by $(CXX) when one of the
# objects comes from C++.
define bench_program
$(1): $(2:%=$(BENCH_DIR)/%.o) $(filter %.a,$(3))
	@mkdir -p $$(@D)
	$(if $(wildcard $(2:%=bench/peers/%.cpp)),$$(CXX),$$(CC)) $$(LDFLAGS) -o $$@ $$^ $(filter-out %.a,$(3)) -lm
endef

$(eval $(call bench_program,$(BENCH_DIR)/bench_carom,bench_carom carom_scene scenes,$(BUILD)/libcarom.a))
$(eval $(call bench_program,$(BENCH_DIR)/bench_broadphase,bench_broadphase scenes,$(BUILD)/libcarom.a))
$(eval $(call bench_program,$(BENCH_DIR)/bench_chipmunk,bench_chipmunk scenes,-lchipmunk))
$(eval $(call bench_program,$(BENCH_DIR)/bench_box2d,bench_box2d scenes,-lbox2d))
$(eval $(call bench_program,$(BENCH_DIR)/bench_box2d3,bench_box2d3 scenes,$(BOX2D3_LIB)))

# Box2D v3 itself, rebuilt when a file of its library changes. Its commit
# and version (from its CMakeLists.txt) go into box2d3-version.txt, written
# at every build, for bench/run-bench.sh to print.
$(BOX2D3_LIB): $(if $(BOX2D3_TREE),$(BOX2D3_DIR)/CMakeLists.txt $(BOX2D3_DIR)/src/CMakeLists.txt \
               $(wildcard $(BOX2D3_DIR)/src/*.c $(BOX2D3_DIR)/src/*.h $(BOX2D3_DIR)/include/box2d/*.h))
	@mkdir -p $(BOX2D3_BUILD)
	CC="$(CC)" CXX="$(CXX)" cmake -S $(BOX2D3_DIR) -B $(BOX2D3_BUILD) $(BOX2D3_CMAKE) >$(BOX2D3_BUILD)/configure.log 2>&1 \
	  || { cat $(BOX2D3_BUILD)/configure.log; exit 1; }
	MAKEFLAGS= cmake --build $(BOX2D3_BUILD) --target box2d --parallel $(BOX2D3_JOBS)
	@touch $@

.PHONY: $(BENCH_DIR)/box2d3-version.txt
$(BENCH_DIR)/box2d3-version.txt: $(BOX2D3_LIB)
	@mkdir -p $(@D)
	@commit=$$(git -C $(BOX2D3_DIR) rev-parse HEAD 2>/dev/null) || commit=unknown; \
	date=$$(git -C $(BOX2D3_DIR) log -1 --format=%cs 2>/dev/null) || date=unknown; \
	version=$$(sed -n 's/^[[:space:]]*VERSION[[:space:]]\{1,\}\([0-9.]*\).*/\1/p' $(BOX2D3_DIR)/CMakeLists.txt | head -n 1); \
	printf 'commit=%s date=%s version=%s dir=%s build=%s\n' "$$commit" "$${date:-unknown}" "$${version:-unknown}" \
	  "$(abspath $(BOX2D3_DIR))" "cmake-Release" >$@
	@cat $@

endif
