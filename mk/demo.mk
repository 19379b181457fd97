# The GTK 3 + Cairo demo, $(BUILD)/carom-demo (docs/demo.md).
#   make demo         build $(BUILD)/carom-demo
#   make run          with a display: the demo on scenes/thesis.scene;
#                     without one: the headless runner's $(BUILD)/thesis.png
#   make check-demo   tests/test_demo_x11.sh: the demo in Xvfb, driven by
#                     xdotool, its screenshots checked
#   make demo-shots   remake docs/img/demo-*.png with --screenshot in Xvfb
#
# It links $(BUILD)/demo/render.o, whose rule is in mk/runner.mk.

# Recursive (=) so pkg-config only runs when the demo is built. GTK's
# headers go in as system headers: -pedantic is for our code, not theirs.
DEMO_GTK_CFLAGS = $(shell pkg-config --cflags-only-I gtk+-3.0 | sed 's/\(^\| \)-I/\1-isystem /g') \
                  $(shell pkg-config --cflags-only-other gtk+-3.0)
DEMO_GTK_LIBS = $(shell pkg-config --libs gtk+-3.0)

DEMO_SRC := demo/main.c demo/demo.c demo/controls.c demo/scenes.c demo/stage.c demo/walls.c demo/grab.c \
            demo/hud.c
DEMO_OBJ := $(DEMO_SRC:demo/%.c=$(BUILD)/demo/%.o)
DEMO_BIN := $(BUILD)/carom-demo

.PHONY: demo run check-demo demo-shots

demo: $(DEMO_BIN)

$(DEMO_OBJ): $(BUILD)/demo/%.o: demo/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Idemo -DDEMO_SCENE_DIR='"$(CURDIR)/scenes"' $(DEMO_GTK_CFLAGS) $(WARN) $(OPT) $(CFLAGS) \
	  -c $< -o $@

$(DEMO_BIN): $(DEMO_OBJ) $(BUILD)/demo/render.o $(BUILD)/libcarom.a
	$(CC) $(LDFLAGS) -o $@ $^ $(DEMO_GTK_LIBS) -lm

# With a display, the demo; without one (ssh, CI), the runner's picture.
run:
	@tools/ensure-deps build demo
	@if [ -n "$$DISPLAY" ]; then \
	  $(MAKE) --no-print-directory demo && $(DEMO_BIN) scenes/thesis.scene; \
	else \
	  echo "run: DISPLAY is not set: drawing the scene headless instead"; \
	  $(MAKE) --no-print-directory run-headless; \
	fi

check-demo:
	@tools/ensure-deps build demo xtest
	@$(MAKE) --no-print-directory demo
	@sh tests/test_demo_x11.sh $(DEMO_BIN)

# The pictures in docs/demo.md: each scene after a few timer ticks in an
# 800x600 window of a private X server, then cut to a 256-colour palette
# (the busy scenes are 230 KB as true colour, 60-80 KB so).
DEMO_SHOTS := "thesis --frames 50 --keys vg" "balls --frames 120 --keys v" "pyramid --frames 180" \
              "rain --frames 150" "gas --frames 120" "platform --frames 310" \
              "compound --frames 240" "pendulum --frames 70 --keys v" "bridge --frames 100" \
              "ragdoll --frames 60" "car --frames 260" \
              "help --paused --frames 2 --keys h thesis"

demo-shots: $(DEMO_BIN)
	@tools/ensure-deps xtest
	@command -v convert >/dev/null || { echo "demo-shots: needs ImageMagick's convert (apt-get install imagemagick)"; exit 1; }
	@mkdir -p docs/img
	@for shot in $(DEMO_SHOTS); do \
	  set -- $$shot; name=$$1; shift; [ "$$name" = help ] || set -- "$$@" "$$name"; \
	  xvfb-run -a -s '-screen 0 1024x768x24' $(DEMO_BIN) --screenshot docs/img/demo-$$name.png "$$@" || exit 1; \
	  convert docs/img/demo-$$name.png -dither None -colors 256 PNG8:docs/img/demo-$$name.png || exit 1; \
	done
	@ls -l docs/img/demo-*.png
