# The headless runner, $(BUILD)/carom: loads a scene, runs it without a
# display and reports numbers, a CSV trace and a PNG/SVG picture
# (docs/scenes.md). Cairo only, no GTK.
#   make runner         build $(BUILD)/carom
#   make run-headless   run scenes/thesis.scene, draw $(BUILD)/thesis.png
#   make check-runner   tests/test_runner.sh on $(BUILD)/carom
#
# $(BUILD)/demo/render.o is shared with the GTK demo, which links it too.

# Recursive (=) so pkg-config only runs when the runner is built.
CAIRO_CFLAGS = $(shell pkg-config --cflags cairo)
CAIRO_LIBS = $(shell pkg-config --libs cairo)

RUNNER_OBJ := $(BUILD)/demo/runner.o $(BUILD)/demo/render.o

.PHONY: runner run-headless check-runner

runner: $(BUILD)/carom

$(RUNNER_OBJ): $(BUILD)/demo/%.o: demo/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Idemo $(CAIRO_CFLAGS) $(WARN) $(OPT) $(CFLAGS) -c $< -o $@

$(BUILD)/carom: $(RUNNER_OBJ) $(BUILD)/libcarom.a
	$(CC) $(LDFLAGS) -o $@ $^ $(CAIRO_LIBS) -lm

run-headless: $(BUILD)/carom
	$(BUILD)/carom run scenes/thesis.scene --png $(BUILD)/thesis.png
	@echo "run-headless: wrote $(BUILD)/thesis.png"

check-runner: $(BUILD)/carom
	@sh tests/test_runner.sh $(BUILD)/carom
