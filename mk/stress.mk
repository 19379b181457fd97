# The long stability cases (stress/stress.c) and Solver2D's contact samples
# (stress/solver2d.c), run natively: make stress.
.PHONY: stress check-stress

$(BUILD)/stress: stress/stress.c stress/kinetic.h stress/heavy_chain.h $(BUILD)/libcarom.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(WARN) $(OPT) $(CFLAGS) -o $@ $< $(BUILD)/libcarom.a -lm

$(BUILD)/solver2d: stress/solver2d.c stress/kinetic.h $(BUILD)/libcarom.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(WARN) $(OPT) $(CFLAGS) -o $@ $< $(BUILD)/libcarom.a -lm

# Both run even when the first fails; the target fails if either does.
# solver2d leaves out the samples it lists as known failures (solver2d --all
# runs them).
stress check-stress: $(BUILD)/stress $(BUILD)/solver2d
	@rc=0; $(BUILD)/stress || rc=1; $(BUILD)/solver2d || rc=1; exit $$rc
