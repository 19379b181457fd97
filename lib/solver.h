/* Collision resolution: sequential impulses over all contact points at once,
 * each impulse the one of eq. 3.23 (with the relative velocity of the
 * contact points), accumulated and clamped so contacts only push; then
 * split-impulse position correction. */
#ifndef CAROM_SOLVER_H
#define CAROM_SOLVER_H

#include "step.h"
#include "vec2.h"

struct carom_world;

/* What the iterations read and write per body, kept compact. */
typedef struct solver_body {
  vec2 v;
  double w;
  vec2 pv;      /* split-impulse pseudo-velocity */
  double pw;
  double im, ii; /* inverse mass and inertia (0: cannot be moved) */
} solver_body;

/* Room for one solver body per slot; 0 when memory ran out. Called before
 * any state changes in a sub-step, so solver_update itself cannot fail. */
int solver_reserve (struct carom_world *world);
void solver_update (struct carom_world *world, const step_context *ctx);
void solver_destroy (struct carom_world *world);

#endif
