# Benchmarks (bench/): carom against Chipmunk 7 and Box2D 2.4 on the same
# scenes, carom's scaling, memory and broad phase, and a callgrind profile.
#   make bench         install the peers if missing (tools/ensure-deps peers),
#                      build, run everything, write docs/performance.md
#   make bench-build   only build $(BUILD)/bench/*
# Every engine's bench is compiled with $(OPT) (-O2 -g by default); the peers
# are Debian's packaged libraries. Raw outputs and profiles stay in
# $(BUILD)/bench/. Use a tree of your own: make BUILD=build-bench bench
#
# Peer benches are built only when their headers exist; the check runs in the
# sub-make, after ensure-deps may have installed them.

BENCH_DIR := $(BUILD)/bench
CXX       ?= c++
BENCH_CXXFLAGS := -std=c++17 -Wall -Wextra
BENCH_HAS_CHIPMUNK = $(shell printf '\043include <chipmunk/chipmunk.h>\n' | $(CC) -E -x c - >/dev/null 2>&1 && echo yes)
BENCH_HAS_BOX2D = $(shell printf '\043include <box2d/box2d.h>\n' | $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)

BENCH_BIN = $(BENCH_DIR)/bench_carom $(BENCH_DIR)/bench_broadphase \
            $(if $(BENCH_HAS_CHIPMUNK),$(BENCH_DIR)/bench_chipmunk) \
            $(if $(BENCH_HAS_BOX2D),$(BENCH_DIR)/bench_box2d)

.PHONY: bench bench-build

bench:
	@tools/ensure-deps build peers || echo "bench: could not install the peers; benchmarking carom alone"
	@$(MAKE) --no-print-directory bench-build
	@sh bench/run-bench.sh $(BENCH_DIR)

bench-build: $(BUILD)/libcarom.a
	@$(MAKE) --no-print-directory $(BENCH_BIN)

$(BENCH_DIR)/%.o: bench/%.c bench/scenes.h
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ibench $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(BENCH_DIR)/%.o: bench/peers/%.c bench/scenes.h
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ibench $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(BENCH_DIR)/%.o: bench/peers/%.cpp bench/scenes.h
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) -Ibench $(BENCH_CXXFLAGS) $(OPT) $(CXXFLAGS) -c $< -o $@

$(BENCH_DIR)/bench_carom: $(BENCH_DIR)/bench_carom.o $(BENCH_DIR)/carom_scene.o $(BENCH_DIR)/scenes.o $(BUILD)/libcarom.a
	$(CC) $(LDFLAGS) -o $@ $^ -lm

$(BENCH_DIR)/bench_broadphase: $(BENCH_DIR)/bench_broadphase.o $(BENCH_DIR)/scenes.o $(BUILD)/libcarom.a
	$(CC) $(LDFLAGS) -o $@ $^ -lm

$(BENCH_DIR)/bench_chipmunk: $(BENCH_DIR)/bench_chipmunk.o $(BENCH_DIR)/scenes.o
	$(CC) $(LDFLAGS) -o $@ $^ -lchipmunk -lm

$(BENCH_DIR)/bench_box2d: $(BENCH_DIR)/bench_box2d.o $(BENCH_DIR)/scenes.o
	$(CXX) $(LDFLAGS) -o $@ $^ -lbox2d -lm
