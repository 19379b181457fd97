# The long stability cases (stress/stress.c), run natively: make stress.
.PHONY: stress check-stress

$(BUILD)/stress: stress/stress.c $(BUILD)/libcarom.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(WARN) $(OPT) $(CFLAGS) -o $@ $< $(BUILD)/libcarom.a -lm

stress check-stress: $(BUILD)/stress
	$(BUILD)/stress
