/* The step context: what every stage of one carom_world_update needs to
 * know about the step, computed once and handed to each stage (detection,
 * the solver's sub-steps, gravity, damping, sleep). Nothing of it is kept in
 * the world between steps. */
#ifndef CAROM_STEP_H
#define CAROM_STEP_H

#include <stdint.h>

#include "vec2.h"

/* A soft constraint's coefficients for one sub-step of length h (Catto's
 * "soft step"; joint.h): the impulse of a pass is
 * -mass_scale m (Cdot + bias_rate C) - impulse_scale (impulse so far). */
typedef struct joint_soft {
  double bias_rate, mass_scale, impulse_scale;
} joint_soft;

typedef struct step_context {
  double dt, inv_dt;     /* the whole update; detection looks this far ahead */
  double h, inv_h;       /* one sub-step */
  int32_t substeps, iterations;
  vec2 gravity;          /* uniform gravity */
  vec2 kick;             /* gravity * h: the velocity a sub-step's gravity adds */
  double accel;          /* |gravity|: how far bodies can fall within dt (reach) */
  int continuous;        /* the world's continuous collision: contacts are
                            looked for as far as bodies can travel in dt */
  int damping;           /* damping is on: v *= damp_v, w *= damp_w per sub-step */
  int free_flight;       /* bodies fly free between their contacts' and
                            joints' impulses: no gravity, uniform or
                            central, no force, no damping (with them a
                            body that comes to rest on another within
                            the step is pushed by more than its flight
                            says: contact.c, clear_of_step) */
  double damp_v, damp_w;
  /* contacts: below this approach speed a contact does not bounce (what
   * gravity adds in two steps, so resting stays resting; 0 without
   * gravity, where every approach bounces) */
  double restitution_threshold;
  double push_rate;      /* overlap pushed out per unit time: position_correction / h */
  joint_soft joint_hold;  /* how a joint corrects its error in a sub-step's
                            solve (joint_hold_soft) */
  double sensor_reach;   /* how far the fastest body can travel in dt, when
                            the world has a sensor (broadphase.c); else 0 */
  uint64_t update;       /* the world's successful updates before this one: a
                            failed update tried again has the same */
} step_context;

struct carom_world;

/* The context of an update of dt (dt = 0: detection alone, outside any
 * update, with no look-ahead). */
void step_context_init (step_context *ctx, const struct carom_world *world, double dt);

#endif
