/* The demo's state and what its keys and timer do with it, apart from GTK:
 * main.c wires these to the window's signals, controls.c to the keys and
 * the mouse. */
#ifndef CAROM_DEMO_DEMO_H
#define CAROM_DEMO_DEMO_H

#include <cairo.h>

#include "carom.h"
#include "grab.h"
#include "hud.h"
#include "render.h"
#include "scenes.h"
#include "stage.h"

/* Simulated time per timer tick: the timer runs at about 60 Hz. */
#define DEMO_DT (1.0 / 60.0)
/* Arrow keys change gravity by this much (m/s^2 in SI scenes). */
#define DEMO_GRAVITY_STEP 2.0
/* +/- change restitution by this much. */
#define DEMO_RESTITUTION_STEP 0.1
/* Gravity vector and restitution bar stay up this long after a change. */
#define DEMO_OVERLAY_TIME 2.0

typedef struct demo {
  const scene_entry *entry; /* the running scene's row in the table */
  char *path;               /* its file */
  char *name;               /* shown in the status line and the title */
  stage stage;
  render_options opt;
  grab grab;
  hud hud;
  int paused;
  int show_help;
  int show_gravity;         /* `g`: the gravity vector stays up */
  double gravity_until;     /* a change shows it until then (seconds) */
  double restitution_until; /* likewise the restitution bar */
  int width, height;        /* the drawing area, status line included */
  /* layout at scene start: the walls move once the window grows past it */
  int sized;                /* demo_resize has been told the real size */
  int base_width, base_height;
  double base_view[4];      /* the scene's bodies plus margin, world units */
  double base_scale;        /* pixels per world unit at scene start */
  int verbose;              /* print the view and grabs on stdout */
} demo;

/* Seconds on the monotonic clock. */
double demo_now (void);

/* Start with the table entry `e` on the file `path` in a width x height
 * drawing area. Returns 0 and prints "FILE:LINE: message" on stderr if the
 * scene does not load; the demo is then empty (destroy is still safe). */
int demo_init (demo *d, const scene_entry *e, const char *path, int width, int height);

/* Switch to another scene; on failure print why and keep the current one. */
int demo_load (demo *d, const scene_entry *e, const char *path);

/* Reload the running scene from its file. */
int demo_restart (demo *d);

/* The drawing area is now width x height: fit the view, move the walls. */
void demo_resize (demo *d, int width, int height);

/* One timer tick's simulation step (checking a held body first). */
void demo_update (demo *d);

/* Paint a frame into width x height: world, overlays, status line. */
void demo_draw (demo *d, cairo_t *cr, int width, int height);

/* Change gravity by (dx, dy) and show the gravity vector for a while. */
void demo_change_gravity (demo *d, double dx, double dy);

/* Switch an effect stage on or off (friction, damping, sleeping, central
 * gravity): the keys f, d, s and o. */
void demo_toggle_effect (demo *d, carom_effect effect);

/* Change the world's restitution by `delta` and show the bar. */
void demo_change_restitution (demo *d, double delta);

/* Which timed overlays are up now, as bits: lets a paused demo redraw only
 * when one of them comes or goes. */
int demo_overlays (const demo *d, double now);

void demo_destroy (demo *d);

#endif
