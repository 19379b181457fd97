/* The contact constraint (eq. 3.18-3.23, with the corrections of
 * docs/physics.md): its set-up once per step, and the passes the solver's
 * sub-steps make over it. */
#ifndef CAROM_CONTACT_SOLVER_H
#define CAROM_CONTACT_SOLVER_H

#include "contact.h"
#include "solver.h"
#include "step.h"

struct carom_world;

/* Lever arms, effective masses and the separation to follow, from the
 * contacts detected at the start of the step. */
void contact_prepare (struct carom_world *world, const step_context *ctx);
/* Apply the impulses the contacts carry again (warm starting). `remaining`
 * (in this and the passes below) is the time from the impulses to the end
 * of the step. */
void contact_warm_start (struct carom_world *world, double remaining);
/* One pass over every contact: the impulses that keep its points from
 * approaching (a speculative one from passing its gap). `kicks` is how many
 * gravity kicks the sub-steps have given so far. With only_fine, only the contacts of bodies so small that a
 * sub-step's fall exceeds their slop are solved (contact.fine). Returns the
 * largest change of a point's normal speed. */
double contact_solve (struct carom_world *world, const step_context *ctx, int32_t kicks, double remaining,
                      int only_fine);
/* The push-out of overlap beyond the slop, on the pseudo-velocities alone
 * (split impulses): they move the bodies in this sub-step and are dropped,
 * so position correction never changes a velocity. `first`: the sub-step's
 * first pass, which starts from no pseudo-impulse. */
void contact_push_out (struct carom_world *world, const step_context *ctx, int first);
/* Before the sub-steps: the bouncy impacts of the step in the order they
 * happen, each the impulse of eq. 3.23 at its time, passed on through the
 * bodies it touches as pairwise impacts (the sequential model,
 * docs/physics.md). */
void contact_impacts (struct carom_world *world, const step_context *ctx);
/* After the sub-steps: points that were struck leave at e times the speed
 * they met with (eq. 3.18). */
void contact_restitution (struct carom_world *world, const step_context *ctx);
/* Then: the bodies of impacts met within the step are moved to where the
 * impact at its time of impact leaves them. */
void contact_time_of_impact (struct carom_world *world, const step_context *ctx);

/* Shock propagation (shock.c): when touching bodies differ in mass more
 * than tenfold under gravity, a pass from the ground up after the solve and
 * the second solve of each sub-step, holding each lower body still. */
void contact_shock_prepare (struct carom_world *world, const step_context *ctx);
/* Room for the step's shock rows (0 when memory ran out), and its release. */
int contact_shock_reserve (struct carom_world *world);
void contact_shock_destroy (struct carom_world *world);
void contact_shock (struct carom_world *world, const step_context *ctx);

/* The cold start (shock.c): the contacts that begin resting this step
 * (contact.cold) are given the weight they carry as their impulse to warm
 * start from. Between contact_prepare and contact_batch_prepare. */
void contact_cold_start (struct carom_world *world, const step_context *ctx);

/* ------------------------------------------- shared by the contact passes */

/* An impulse lambda along a direction d applied at the point: B gets
 * +lambda d, A gets -lambda d; ra_d = ra x d and rb_d = rb x d. */
static inline void contact_push (solver_body *a, solver_body *b, vec2 d, double ra_d, double rb_d, double lambda)
{
  a->v = v2_mad (a->v, -a->im * lambda, d);
  a->w -= a->ii * ra_d * lambda;
  b->v = v2_mad (b->v, b->im * lambda, d);
  b->w += b->ii * rb_d * lambda;
}

/* (v_bp - v_ap) . d, eq. 3.15 and the corrected 3.17, using
 * (w x r) . d = w (r x d) */
static inline double contact_speed (const solver_body *a, const solver_body *b, vec2 d, double ra_d, double rb_d)
{
  return v2_dot (v2_sub (b->v, a->v), d) + b->w * rb_d - a->w * ra_d;
}

/* The separation of a point now: at detection, plus how far the bodies'
 * copies of the point have moved apart along the normal since. */
static inline double contact_separation (const solver_body *a, const solver_body *b, const contact_point *p)
{
  vec2 d = v2_add (v2_sub (b->dp, a->dp), v2_sub (rot2_apply (b->dq, p->rb), rot2_apply (a->dq, p->ra)));
  return v2_dot (d, p->normal) + p->adjusted;
}

/* Smallest x >= 0 with w = K x + b >= 0 and x . w = 0 for a symmetric 2x2 K
 * (both points active, the first, the second, neither). Returns 0 when
 * rounding leaves no consistent case. */
static inline int contact_lcp2 (double k11, double k12, double k22, double b1, double b2, double *x1, double *x2)
{
  double det = k11 * k22 - k12 * k12;
  if (det > 1e-12 * k11 * k22)
    {
      *x1 = (-k22 * b1 + k12 * b2) / det;
      *x2 = (k12 * b1 - k11 * b2) / det;
      if (*x1 >= 0.0 && *x2 >= 0.0)
        return 1;
    }
  *x1 = -b1 / k11, *x2 = 0.0;
  if (*x1 >= 0.0 && k12 * *x1 + b2 >= 0.0)
    return 1;
  *x1 = 0.0, *x2 = -b2 / k22;
  if (*x2 >= 0.0 && k12 * *x2 + b1 >= 0.0)
    return 1;
  *x1 = *x2 = 0.0;
  return b1 >= 0.0 && b2 >= 0.0;
}


#endif
