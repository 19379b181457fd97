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
# the sub-make, after ensure-deps may have installed them. Objects and the
# link rule are the benches' own (mk/bench.mk).

include mk/bench.mk

ACC_DIR    := $(BUILD)/accuracy
ACC_COMMON := accuracy_measures scenes

ACC_BIN = $(ACC_DIR)/accuracy \
          $(if $(BENCH_HAS_CHIPMUNK),$(ACC_DIR)/accuracy_chipmunk) \
          $(if $(BENCH_HAS_BOX2D),$(ACC_DIR)/accuracy_box2d)

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
