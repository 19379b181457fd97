/* Damping: velocities decay as exp(-c t), applied exactly each sub-step. */
#ifndef CAROM_DAMPING_H
#define CAROM_DAMPING_H

#include "step.h"

struct carom_world;

/* Nothing at all when both rates are zero. */
void damping_update (struct carom_world *world, const step_context *ctx);

#endif
