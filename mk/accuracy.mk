# What accuracy costs in time (bench/accuracy*.c, bench/peers/accuracy_*):
# every error measure for each setting of each carom knob, and Chipmunk 7,
# Box2D 2.4 and (with BOX2D3_DIR, mk/bench.mk) Box2D v3 on the same measures.
#   make bench-accuracy        install the peers if missing, build, run,
#                              write docs/accuracy.md and docs/accuracy.png
#   make bench-accuracy-build  only build $(BUILD)/accuracy/*
# `make bench` runs it too (the dependency below), before its own benches.
# Raw outputs stay in $(BUILD)/accuracy/. Use a tree of your own:
#   make BUILD=build-acc bench-accuracy
# One part of the map, without the whole sweep: every program takes
# measures=NAME,... (the names of the lines' measure=), carom's also
# knobs=NAME,... (its defaults always run) and reference=0, e.g.
#   $(BUILD)/accuracy/accuracy knobs=continuous measures=cradle reference=0
#   $(BUILD)/accuracy/accuracy_box2d measures=cradle
# Peer binaries are built only when their headers exist; the check runs in
# the sub-make, after ensure-deps may have installed them. Objects and the
# link rule are the benches' own (mk/bench.mk).

include mk/bench.mk

ACC_DIR    := $(BUILD)/accuracy
ACC_COMMON := accuracy_measures scenes

ACC_BIN = $(ACC_DIR)/accuracy \
          $(if $(BENCH_HAS_CHIPMUNK),$(ACC_DIR)/accuracy_chipmunk) \
          $(if $(BENCH_HAS_BOX2D),$(ACC_DIR)/accuracy_box2d) \
          $(if $(BOX2D3_SKIP),,$(ACC_DIR)/accuracy_box2d3)

.PHONY: bench-accuracy bench-accuracy-build
bench: bench-accuracy

bench-accuracy:
	@tools/ensure-deps build peers || echo "bench-accuracy: could not install the peers; measuring carom alone"
	@$(MAKE) --no-print-directory bench-accuracy-build
	@sh bench/run-accuracy.sh $(ACC_DIR)

bench-accuracy-build: $(BUILD)/libcarom.a
	@$(MAKE) --no-print-directory $(ACC_BIN)

$(eval $(call bench_program,$(ACC_DIR)/accuracy,accuracy carom_scene $(ACC_COMMON),$(BUILD)/libcarom.a))
$(eval $(call bench_program,$(ACC_DIR)/accuracy_chipmunk,accuracy_chipmunk $(ACC_COMMON),-lchipmunk))
$(eval $(call bench_program,$(ACC_DIR)/accuracy_box2d,accuracy_box2d $(ACC_COMMON),-lbox2d))
$(eval $(call bench_program,$(ACC_DIR)/accuracy_box2d3,accuracy_box2d3 $(ACC_COMMON),$(BOX2D3_LIB)))
# the Box2D v3 bench's compile rule (its headers, C11) for its accuracy adapter too
$(BENCH_DIR)/accuracy_box2d3.o: BENCH_COMPILE_C = $(CC) $(CPPFLAGS) -Ibench -Ibench/peers -isystem $(BOX2D3_DIR)/include \
  $(filter-out -std=%,$(WARN)) -std=c11 $(OPT) $(CFLAGS) -c $< -o $@
$(BENCH_DIR)/accuracy_box2d3.o: $(BOX2D3_LIB) bench/peers/bench_box2d3.c
