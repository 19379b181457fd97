/* Impacts: what restitution does (eq. 3.18 and 3.23 at the moment two
 * bodies meet), apart from the contact constraint that keeps them from
 * approaching (contact_solver.c). */
#ifndef CAROM_IMPACT_H
#define CAROM_IMPACT_H

#include "contact_solver.h"

struct carom_world;

/* contact_point.in_impact of a point an impact bounced, and of one that
 * bounced before its contact struck again at another point (it takes no
 * part in that impact) */
#define IMPACT_BOUNCED 2
#define IMPACT_DONE 3

/* In contact_prepare, for contact k once its points are set up: when its
 * bodies may fly free into an impact within the step, its points become
 * those of the first touch (toi.c), with the lever arms of that moment; a
 * pair that does not touch within the step takes no impulse in it. */
void contact_impact_points (struct carom_world *world, contact *k, solver_body *a, solver_body *b,
                            const step_context *ctx);
/* Before the sub-steps: the bouncy impacts of the step in the order they
 * happen, each the impulse of eq. 3.23 at its time, passed on through the
 * bodies it touches as pairwise impacts (the sequential model,
 * docs/physics.md). */
void contact_impacts (struct carom_world *world, const step_context *ctx);
/* Room for what contact_impacts may replay its impacts from (0 when memory
 * ran out; solver_reserve), and its release. */
int contact_impacts_reserve (struct carom_world *world);
void contact_impacts_destroy (struct carom_world *world);
/* After the sub-steps: points that were struck leave at e times the speed
 * they met with (eq. 3.18). */
void contact_restitution (struct carom_world *world, const step_context *ctx);
/* Then: the bodies of impacts met within the step are moved to where the
 * impact at its time of impact leaves them. */
void contact_time_of_impact (struct carom_world *world, const step_context *ctx);

#endif
