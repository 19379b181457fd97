/* Grabbing a body with the mouse: press on it, drag, release to throw.
 * While held, a mouse joint (CAROM_JOINT_MOUSE) pulls the grabbed point of
 * the body towards the pointer, a soft spring whose force is bounded by a
 * thousand times the body's weight: the body swings, collides and drags
 * what is joined to it as any other force would move it. On release the
 * joint is removed and the body keeps the velocity it has, capped. Plain C
 * on the public API. */
#ifndef CAROM_DEMO_GRAB_H
#define CAROM_DEMO_GRAB_H

#include "carom.h"

typedef struct grab {
  carom_body_id body;   /* CAROM_NULL_BODY when nothing is held */
  carom_joint_id joint; /* the mouse joint holding it */
  double mx, my;        /* the pointer, world coordinates: the target */
  double max_speed;     /* the body's speed is capped at this */
} grab;

void grab_init (grab *g);

/* The dynamic body under world point (x, y), or CAROM_NULL_BODY. */
carom_body_id grab_pick (const carom_world *world, double x, double y);

/* Start holding the body under (x, y) by that point (letting go of what
 * was held before); returns 1 if there was one. */
int grab_begin (grab *g, carom_world *world, double x, double y, double max_speed);

/* The pointer moved to (x, y): the joint's new target. */
void grab_move (grab *g, carom_world *world, double x, double y);

/* Before each step: lets go if the body (and so its joint) is gone, and
 * caps the held body's speed. */
void grab_update (grab *g, carom_world *world);

/* Where the grabbed point of the body is now (*x, *y); 0 if nothing is
 * held. */
int grab_point (const grab *g, const carom_world *world, double *x, double *y);

/* Let go: the joint is removed, the body keeps its (capped) velocity. */
void grab_end (grab *g, carom_world *world);

#endif
