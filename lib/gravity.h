/* Gravity: uniform acceleration and the attraction of a central point mass,
 * as a velocity kick at the start of each sub-step, and the half of that
 * kick a free body takes back when it moves (its undo), so that free flight
 * is exact. Both live here, side by side. */
#ifndef CAROM_GRAVITY_H
#define CAROM_GRAVITY_H

#include "solver.h"
#include "step.h"

struct carom_world;

/* v += g h for every body the sub-steps move, plus the central attraction
 * when it is on; nothing at all when both are off. */
void gravity_kick (struct carom_world *world, const step_context *ctx);

/* Bodies held by joints (CONSTRAINED_JOINT) take the uniform kick in two
 * halves, one before the sub-step's move and one after (leapfrog):
 * gravity_joint_hold takes back the half of gravity_kick's kick that is
 * due after the move, gravity_joint_kick gives it then. */
void gravity_joint_hold (struct carom_world *world, const step_context *ctx);
void gravity_joint_kick (struct carom_world *world, const step_context *ctx);

/* The velocity a body moves with over a sub-step. A free body moves with
 * the mean of its velocities before and after the uniform kick,
 * x += (v - g h / 2) h, which is x0 + v0 t + g t^2 / 2 at every sub-step:
 * exact for uniform gravity. A body some constraint acts on moves with the
 * velocity the solver left it (symplectic Euler), so a body at rest stays
 * exactly at rest. `back` is v2_scale (ctx->kick, -0.5), which a loop over
 * the bodies holds in a local (the stores to the bodies might alias the
 * context as far as the compiler knows: it would be loaded and multiplied
 * for each). */
static inline vec2 gravity_drift_velocity (vec2 back, const solver_body *b)
{
  return b->constrained ? b->v : v2_add (b->v, back);
}

#endif
