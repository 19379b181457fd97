/* Keys and mouse, as in flying-balls' keyboard_input: each binding calls
 * into demo.h. The help overlay (hud.c) lists the same bindings. */
#ifndef CAROM_DEMO_CONTROLS_H
#define CAROM_DEMO_CONTROLS_H

#include "demo.h"

typedef enum controls_result {
  CONTROLS_IGNORED = 0, /* not a key of ours */
  CONTROLS_HANDLED,     /* done; the window needs a redraw */
  CONTROLS_SCENE,       /* another scene is running: update the title */
  CONTROLS_QUIT
} controls_result;

/* A key press, as a GDK keyval. */
controls_result controls_key (demo *d, unsigned keyval);

/* Mouse button 1 pressed, moved, released at (x, y) in drawing-area
 * pixels. Each returns 1 if the picture changed. */
int controls_press (demo *d, double x, double y);
int controls_motion (demo *d, double x, double y);
int controls_release (demo *d, double x, double y);

#endif
