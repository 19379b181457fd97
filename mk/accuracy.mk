# What accuracy costs in time (bench/accuracy*.c, bench/peers/accuracy_*):
# every error measure for each setting of each carom knob, and Chipmunk 7 and
# Box2D 2.4 on the same measures.
#   make bench-accuracy        install the peers if missing, build, run,
#                              write docs/accuracy.md and docs/accuracy.png
#   make bench-accuracy-build  only build $(BUILD)/accuracy/*
# `make bench` runs it too (the dependency below), before its own benches.
# Raw outputs stay in $(BUILD)/accuracy/. Use a tree of your own:
#   make BUILD=build-acc bench-accuracy
# Peer binaries are built only when their headers exist; the check runs in
# the sub-make, after ensure-deps may have installed them.

ACC_DIR      := $(BUILD)/accuracy
ACC_CXXFLAGS := -std=c++17 -Wall -Wextra
ACC_HAS_CHIPMUNK = $(shell printf '\043include <chipmunk/chipmunk.h>\n' | $(CC) -E -x c - >/dev/null 2>&1 && echo yes)
ACC_HAS_BOX2D = $(shell printf '\043include <box2d/box2d.h>\n' | $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)
ACC_COMMON   := $(ACC_DIR)/accuracy_measures.o $(ACC_DIR)/scenes.o

ACC_BIN = $(ACC_DIR)/accuracy \
          $(if $(ACC_HAS_CHIPMUNK),$(ACC_DIR)/accuracy_chipmunk) \
          $(if $(ACC_HAS_BOX2D),$(ACC_DIR)/accuracy_box2d)

.PHONY: bench-accuracy bench-accuracy-build
bench: bench-accuracy

bench-accuracy:
	@tools/ensure-deps build peers || echo "bench-accuracy: could not install the peers; measuring carom alone"
	@$(MAKE) --no-print-directory bench-accuracy-build
	@sh bench/run-accuracy.sh $(ACC_DIR)

bench-accuracy-build: $(BUILD)/libcarom.a
	@$(MAKE) --no-print-directory $(ACC_BIN)

$(ACC_DIR)/%.o: bench/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ibench $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(ACC_DIR)/%.o: bench/peers/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ibench $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(ACC_DIR)/%.o: bench/peers/%.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) -Ibench $(ACC_CXXFLAGS) $(OPT) $(CXXFLAGS) -c $< -o $@

$(ACC_DIR)/accuracy: $(ACC_DIR)/accuracy.o $(ACC_DIR)/carom_scene.o $(ACC_COMMON) $(BUILD)/libcarom.a
	$(CC) $(LDFLAGS) -o $@ $^ -lm

$(ACC_DIR)/accuracy_chipmunk: $(ACC_DIR)/accuracy_chipmunk.o $(ACC_COMMON)
	$(CC) $(LDFLAGS) -o $@ $^ -lchipmunk -lm

$(ACC_DIR)/accuracy_box2d: $(ACC_DIR)/accuracy_box2d.o $(ACC_COMMON)
	$(CXX) $(LDFLAGS) -o $@ $^ -lbox2d -lm
