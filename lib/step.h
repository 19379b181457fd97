/* The step context: what every stage of a sub-step needs to know about it,
 * computed once by the world's update and handed to each stage (detection,
 * gravity, damping, the solver, the drift, sleep). Nothing of it is kept in
 * the world between sub-steps. */
#ifndef CAROM_STEP_H
#define CAROM_STEP_H

#include "vec2.h"

typedef struct step_context {
  double h, inv_h;  /* the sub-step; 0 for detection outside any update */
  vec2 gravity;     /* uniform gravity */
  vec2 kick;        /* gravity * h: the velocity a sub-step's gravity adds */
  double accel;     /* |gravity|: how far bodies can fall within h (reach) */
  int continuous;   /* the world's continuous collision: contacts are looked
                       for as far as bodies can travel in h */
} step_context;

struct carom_world;

/* The context of a sub-step of length h (h = 0: detection alone, with no
 * look-ahead). */
void step_context_init (step_context *ctx, const struct carom_world *world, double h);

#endif
