/* Gravity: uniform acceleration, a velocity kick before the solver sees the
 * velocities (the drift makes free flight exact; see world.c). */
#ifndef CAROM_GRAVITY_H
#define CAROM_GRAVITY_H

#include "body.h"
#include "step.h"

struct carom_world;

/* v += g * h for every dynamic body, plus the central attraction when it
 * is on; nothing at all when both are off. */
void gravity_update (struct carom_world *world, const step_context *ctx);

/* The velocity gravity_update gives body b in a sub-step of h, computed
 * where it stands now (the solver uses it to tell an impact's approach
 * from what gravity added after the bodies met). */
vec2 gravity_dv (const struct carom_world *world, const body *b, double h);

#endif
