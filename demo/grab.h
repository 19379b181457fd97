/* Grabbing a body with the mouse: press on it, drag, release to throw.
 * While held, the body is pinned under the pointer every step (its velocity
 * is the pointer's, its spin zero); on release it keeps the pointer's
 * velocity. Plain C on the public API; times are in seconds. */
#ifndef CAROM_DEMO_GRAB_H
#define CAROM_DEMO_GRAB_H

#include "carom.h"

typedef struct grab {
  carom_body_id body;   /* CAROM_NULL_BODY when nothing is held */
  double lx, ly;        /* the grabbed point, in the body's own frame */
  double mx, my;        /* the pointer, world coordinates */
  double vx, vy;        /* the pointer's velocity, smoothed */
  double t;             /* time of the last pointer position */
  double max_speed;     /* throws are capped at this speed */
} grab;

void grab_init (grab *g);

/* The dynamic body under world point (x, y), or CAROM_NULL_BODY. */
carom_body_id grab_pick (const carom_world *world, double x, double y);

/* Start holding the body under (x, y); returns 1 if there was one. */
int grab_begin (grab *g, carom_world *world, double x, double y, double now, double max_speed);

/* The pointer moved to (x, y). */
void grab_move (grab *g, double x, double y, double now);

/* Pin the held body under the pointer; call before each step, and after a
 * move while paused. Lets go if the body is gone. */
void grab_update (grab *g, carom_world *world, double now);

/* Let go: the body keeps the pointer's recent velocity. */
void grab_end (grab *g, carom_world *world, double now);

#endif
