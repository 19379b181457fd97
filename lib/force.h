/* Forces and impulses a program applies (carom_body_apply_*): a force acts
 * over the next update as a velocity kick in each sub-step, beside
 * gravity's, with the same half-kick undo for a free body (gravity.h), and
 * is cleared after it; an impulse changes the velocity at once. */
#ifndef CAROM_FORCE_H
#define CAROM_FORCE_H

#include "carom.h"
#include "step.h"

struct carom_world;

/* Whether the forces pending would change some velocity by more than
 * CAROM_MAX_MAGNITUDE over an update of dt (then the update is refused). */
carom_status force_check (const struct carom_world *world, double dt);
/* v += F h / m, w += T h / I for every body the sub-steps move. */
void force_kick (struct carom_world *world, const step_context *ctx);
/* After a sub-step's move: a free body takes back half its kick, so a
 * constant force moves it by F t^2 / 2m exactly (gravity_drift_velocity). */
void force_drift_undo (struct carom_world *world, const step_context *ctx);
/* After the update: every force and torque back to 0. */
void force_clear (struct carom_world *world);

#endif
