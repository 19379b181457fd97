/* The last guard of continuous collision: no body's centre crosses into a
 * static body within a step. */
#ifndef CAROM_TUNNEL_H
#define CAROM_TUNNEL_H

#include "step.h"

struct carom_world;

/* After the step's motion is known (contact_time_of_impact) and before the
 * bodies take it: a dynamic body that has a contact with a static piece
 * and whose centre's path from where it was to where it would end crosses
 * into that piece from outside, or that began the step within the slop of
 * it and would end overlapping it by more than BODY_FAST_FRACTION of its
 * size, stops on that path where the two overlap by half the contact's
 * slop, its velocities kept (the next step meets the static body as a
 * contact). */
void tunnel_guard (struct carom_world *world, const step_context *ctx);

#endif
