#ifndef CAROM_DAMPING_H
#define CAROM_DAMPING_H

#include "step.h"

struct carom_world;

/* Velocities decay as exp(-linear t), spins as exp(-angular t): one
 * sub-step's factor (ctx->damp_v, ctx->damp_w) on every body the sub-steps
 * move; nothing at all when damping is off. */
void damping_update (struct carom_world *world, const step_context *ctx);

#endif
