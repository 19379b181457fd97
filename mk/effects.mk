# What each effect stage costs per step (bench/bench_effects.c): the gas and
# pyramid scenes with one effect switched on, on but idle, or off; time
# (interleaved, median) and instructions (callgrind).
#   make bench-effects        build, run, write docs/effects.md (~3 minutes)
#   make bench-effects-build  only build $(BUILD)/effects/bench_effects
# Raw outputs and callgrind profiles stay in $(BUILD)/effects/. Use a tree of
# your own: make BUILD=build-eff bench-effects

EFF_DIR := $(BUILD)/effects

.PHONY: bench-effects bench-effects-build

bench-effects: bench-effects-build
	@sh bench/run-effects.sh $(EFF_DIR)

bench-effects-build: $(BUILD)/libcarom.a
	@$(MAKE) --no-print-directory $(EFF_DIR)/bench_effects

$(EFF_DIR)/%.o: bench/%.c bench/scenes.h
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ibench $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(EFF_DIR)/bench_effects: $(EFF_DIR)/bench_effects.o $(EFF_DIR)/carom_scene.o $(EFF_DIR)/scenes.o $(BUILD)/libcarom.a
	$(CC) $(LDFLAGS) -o $@ $^ -lm
bench: bench-effects
