/* The four walls a scene's `bounds` line builds (docs/scenes.md), found
 * again in a loaded world so the demo can move them when its window grows,
 * as flying-balls' configure_event moved the window edges. Plain C on the
 * public API, no GTK. */
#ifndef CAROM_DEMO_WALLS_H
#define CAROM_DEMO_WALLS_H

#include "carom.h"

enum { WALL_BOTTOM, WALL_TOP, WALL_LEFT, WALL_RIGHT, WALL_COUNT };

typedef struct walls {
  int present;                 /* the four walls were found */
  double x0, y0, x1, y1;       /* the rectangle of the `bounds` line */
  double thickness;            /* 5% of its smaller side, as the loader */
  double restitution;          /* the line's own, or < 0 for the world's */
  double friction;             /* the line's own, or < 0 for the world's */
  double right, top;           /* where the box ends now (x1, y1 at load) */
  carom_body_id id[WALL_COUNT];
} walls;

/* Look for the walls of `bounds X0 Y0 X1 Y1` (rect[4]) in `world`: four
 * static boxes just outside the rectangle. w->present says if they were all
 * found; without a bounds line pass rect NULL. */
void walls_init (walls *w, const carom_world *world, const double rect[4], double restitution, double friction);

/* Move the right wall to x = right and the ceiling to y = top (the floor
 * and the left wall stay), rebuilding the walls at their new lengths.
 * Static bodies fixed to those two walls move with them; dynamic bodies
 * left outside are brought back in. Nothing changes on error. */
carom_status walls_update (walls *w, carom_world *world, double right, double top);

/* 1 if `id` is one of the walls. */
int walls_contains (const walls *w, carom_body_id id);

#endif
