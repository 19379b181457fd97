# What each effect stage costs per step (bench/bench_effects.c): the gas and
# pyramid scenes with one effect switched on, on but idle, or off; time
# (interleaved, median) and instructions (callgrind).
#   make bench-effects        build, run, write docs/effects.md (~3 minutes)
#   make bench-effects-build  only build $(BUILD)/effects/bench_effects
# Raw outputs and callgrind profiles stay in $(BUILD)/effects/. Use a tree of
# your own: make BUILD=build-eff bench-effects
# Objects and the link rule are the benches' own (mk/bench.mk).

include mk/bench.mk

EFF_DIR := $(BUILD)/effects

.PHONY: bench-effects bench-effects-build

bench-effects: bench-effects-build
	@sh bench/run-effects.sh $(EFF_DIR)

bench-effects-build: $(BUILD)/libcarom.a
	@$(MAKE) --no-print-directory $(EFF_DIR)/bench_effects

$(eval $(call bench_program,$(EFF_DIR)/bench_effects,bench_effects carom_scene scenes,$(BUILD)/libcarom.a))
bench: bench-effects
