/* The contact constraint (eq. 3.18-3.23, with the corrections of
 * docs/physics.md): its set-up once per step, and the passes the solver's
 * sub-steps make over it. */
#ifndef CAROM_CONTACT_SOLVER_H
#define CAROM_CONTACT_SOLVER_H

#include <float.h>

#include "body.h"
#include "contact.h"
#include "solver.h"
#include "step.h"

struct carom_world;

/* Lever arms, effective masses and the separation to follow, from the
 * contacts detected at the start of the step. */
void contact_prepare (struct carom_world *world, const step_context *ctx);
/* The same for the contacts from `first` on, added since (their counts
 * added to the step's). */
void contact_prepare_from (struct carom_world *world, const step_context *ctx, int32_t first);
/* Apply the impulses the contacts carry again (warm starting). `remaining`
 * (in this and the passes below) is the time from the impulses to the end
 * of the step. */
void contact_warm_start (struct carom_world *world, double remaining);
/* One pass over every contact: the impulses that keep its points from
 * approaching (a speculative one from passing its gap). `kicks` is how many
 * gravity kicks the sub-steps have given so far. A `pass` past 0 is one of
 * the extra passes of the sub-step's solve: only the fine contacts that
 * take more than `pass` passes are solved (contact.fine). Returns the
 * largest change of a point's normal speed. */
double contact_solve (struct carom_world *world, const step_context *ctx, int32_t kicks, double remaining,
                      int32_t pass);

/* Bodies small for the step (contact.fine: with nothing to hold them they
 * fall more than their slop within it) take extra solve passes, past the
 * world's `iterations`: as many in all as that fall is slops, rounded up,
 * and never more than CONTACT_FINE_MAX_PASSES, ending early once a pass
 * changes no normal speed by more than CONTACT_FINE_CONVERGED of the
 * largest change the first extra pass made. Support climbs a pile one
 * contact per pass, and until it arrives a body falls; the smaller the
 * body, the more slops it falls in that time (its fall is the same, its
 * slop proportional to its size). Left to one pass a sub-step, a bin of 5
 * cm boxes sank into itself, boxes half inside others, where boxes of 15
 * cm and up settle within two slops (docs/stability.md). A stack just
 * built or just landed, with no impulses yet to warm start from, then
 * carries its weight down within the sub-step instead of sinking for
 * several steps. The end is relative, not a fixed speed: whatever a pass
 * leaves unsolved the sub-step's move turns into a tilt the slop does not
 * take back, and the tilt shifts the weight that made it, so a small
 * box's column leaned further at every step from any offset at all. Ended
 * at 1% of a sub-step's gravity speed, ten 1 cm boxes offset by 1e-9 of a
 * side fell within 2.1 s, eighteen 5 cm ones within 6.1 s
 * (test_offset_columns_of_small_boxes_stand). Bodies large enough for the
 * step cost nothing more. */
#define CONTACT_FINE_MAX_PASSES 32
#define CONTACT_FINE_CONVERGED 0.01

/* The passes a contact of slop `slop` takes when a body falls `fall` in a
 * step (contact.fine): 0 when that is within the slop. */
static inline int32_t contact_fine_passes (double fall, double slop)
{
  double r = fall / slop;
  if (!(r > 1.0))
    return 0;
  return r >= CONTACT_FINE_MAX_PASSES ? CONTACT_FINE_MAX_PASSES : (int32_t) ceil (r);
}

/* The push-out of overlap beyond the slop, on the pseudo-velocities alone
 * (split impulses): they move the bodies in this sub-step and are dropped,
 * so position correction never changes a velocity. `first`: the sub-step's
 * first pass, which starts from no pseudo-impulse. */
void contact_push_out (struct carom_world *world, const step_context *ctx, int first);

/* Shock propagation (shock.c): under gravity, where touching bodies differ
 * in mass more than tenfold and along columns (bodies resting on one
 * other), a pass from the ground up after the solve and the second solve
 * of each sub-step, holding each lower body still. */
void contact_shock_prepare (struct carom_world *world, const step_context *ctx);
/* Room for the step's shock rows (0 when memory ran out), and its release. */
int contact_shock_reserve (struct carom_world *world);
void contact_shock_destroy (struct carom_world *world);
/* `moves`: how many times the sub-steps have moved the bodies so far this
 * step (k in sub-step k before integrate_positions, k + 1 after it): the
 * pass keeps the gaps it computed at the same count. */
void contact_shock (struct carom_world *world, const step_context *ctx, int32_t moves);

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
 * (w x r) . d = w (r x d); dv = b->v - a->v, for a caller that loaded it
 * once for several points. */
static inline double contact_speed_of (vec2 dv, double w_a, double w_b, vec2 d, double ra_d, double rb_d)
{
  return v2_dot (dv, d) + w_b * rb_d - w_a * ra_d;
}

static inline double contact_speed (const solver_body *a, const solver_body *b, vec2 d, double ra_d, double rb_d)
{
  return contact_speed_of (v2_sub (b->v, a->v), a->w, b->w, d, ra_d, rb_d);
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

/* ------------------- shared by the constraint and the impacts (impact.c) */

/* Two points (a face on a face) are solved together, exactly, when their
 * 2x2 matrix is this well conditioned: one at a time, each push would tip
 * the body and the next undo it only in part, and a perfectly aligned stack
 * would sway. */
#define BLOCK_MAX_CONDITION 1e4

/* The effective mass along d of bodies whose inverse masses sum to im
 * (a->im + b->im, the first sum) and whose inverse inertias are ii_a,
 * ii_b: the functions below on values a caller loaded once for several
 * points. denominator_of is eq. 3.23's denominator, 1 / the mass. */
static inline double denominator_of (double im, double ii_a, double ii_b, double ra_d, double rb_d)
{
  return im + ii_a * ra_d * ra_d + ii_b * rb_d * rb_d;
}

static inline double effective_mass_of (double im, double ii_a, double ii_b, double ra_d, double rb_d)
{
  double k = denominator_of (im, ii_a, ii_b, ra_d, rb_d);
  /* a non-finite k (a body far smaller than the rounding of its
   * coordinates) leaves the point inert rather than poisoning the world;
   * past k > 0 (not NaN), k <= DBL_MAX is isfinite (k) in one comparison */
  return k > 0.0 && k <= DBL_MAX ? 1.0 / k : 0.0;
}

static inline double effective_mass (const solver_body *a, const solver_body *b, double ra_d, double rb_d)
{
  return effective_mass_of (a->im + b->im, a->ii, b->ii, ra_d, rb_d);
}

/* The effective masses of a point, eq. 3.23's denominator along the normal
 * and the tangent. An inert direction also loses its lever arms and its
 * impulse: ii * (r x d) may itself overflow there, and inf * 0 in a push is
 * NaN. */
ALWAYS_INLINE void point_masses_of (contact_point *p, double im, double ii_a, double ii_b)
{
  /* effective_mass_of, each direction's test made once: its mass is 0
   * exactly where k is not positive and finite (1 / k of one is at least
   * 1 / DBL_MAX, which is not 0) */
  double kn = denominator_of (im, ii_a, ii_b, p->rn_a, p->rn_b);
  double kt = denominator_of (im, ii_a, ii_b, p->rt_a, p->rt_b);
  if (kn > 0.0 && kn <= DBL_MAX)
    p->normal_mass = 1.0 / kn;
  else
    p->normal_mass = p->rn_a = p->rn_b = p->normal_impulse = 0.0;
  if (kt > 0.0 && kt <= DBL_MAX)
    p->tangent_mass = 1.0 / kt;
  else
    p->tangent_mass = p->rt_a = p->rt_b = p->tangent_impulse = 0.0;
}

ALWAYS_INLINE void point_masses (contact_point *p, const solver_body *a, const solver_body *b)
{
  point_masses_of (p, a->im + b->im, a->ii, b->ii);
}

/* The arm from a body's centre to its copy of a contact point, whose motion
 * the separation follows (contact_separation). A circle's copy is where its
 * surface meets the normal, which does not turn with the circle: its centre
 * stands for it (arm 0), or a spinning ball on the ground would seem to
 * rise off it as its bottom point turned away, and sink. */
static inline vec2 separation_arm_of (int circle, vec2 r)
{
  return circle ? v2 (0.0, 0.0) : r;
}

static inline vec2 separation_arm (const body *b, vec2 r)
{
  return separation_arm_of (b->shape.kind == CAROM_SHAPE_CIRCLE, r);
}

/* The relative acceleration along n that uniform gravity gives the two
 * bodies (per unit time; negative when it closes them). */
static inline double relative_fall (const solver_body *a, const solver_body *b, vec2 n, const step_context *ctx)
{
  vec2 ka = a->moves == MOVES_DYNAMIC ? ctx->kick : v2 (0.0, 0.0);
  vec2 kb = b->moves == MOVES_DYNAMIC ? ctx->kick : v2 (0.0, 0.0);
  return ctx->h > 0.0 ? v2_dot (v2_sub (kb, ka), n) * ctx->inv_h : 0.0;
}

/* Whether the point may act on its bodies this step (near at detection and
 * not leaving faster than gravity's threshold, or meeting within the step:
 * they then move by symplectic Euler, gravity_drift_velocity), and whether
 * it held them at detection (near, neither closing nor leaving fast: a
 * resting contact). A point that does not close within the step, or leaves
 * fast, leaves free flight exact. As bits to give both bodies, from whether
 * it is near (within the slop at detection), whether it meets within the
 * step and its normal speed vn at detection. */
static inline int32_t constrained_bits (int near, int meets, double vn, double threshold)
{
  int32_t bits = 0;
  if (meets || (near && vn < threshold))
    bits |= CONSTRAINED_ANY;
  if (near && vn >= -threshold && vn < threshold)
    bits |= CONSTRAINED_HELD;
  return bits;
}

static inline void constrain_bodies (const contact *k, const contact_point *p, solver_body *a, solver_body *b, double vn,
                              const step_context *ctx)
{
  int32_t bits = constrained_bits (p->depth >= -k->slop, p->toi >= 0.0 && p->toi < ctx->dt, vn,
                                   ctx->restitution_threshold);
  a->constrained |= bits;
  b->constrained |= bits;
}

/* The 2x2 matrix of a two-point contact: eq. 3.23's denominators and their
 * coupling (on one face the normals agree; the vertex-edge method may give
 * two points with their own normals, coupled by n1 . n2). */
static inline void pair_matrix_of (contact *k, double im, double ii_a, double ii_b)
{
  const contact_point *p1 = &k->points[0], *p2 = &k->points[1];
  double k11, k12, k22;
  k->block = 0;
  if (k->count != 2)
    return;
  k11 = im + ii_a * p1->rn_a * p1->rn_a + ii_b * p1->rn_b * p1->rn_b;
  k22 = im + ii_a * p2->rn_a * p2->rn_a + ii_b * p2->rn_b * p2->rn_b;
  k12 = im * v2_dot (p1->normal, p2->normal) + ii_a * p1->rn_a * p2->rn_a + ii_b * p1->rn_b * p2->rn_b;
  k->k11 = k11;
  k->k12 = k12;
  k->k22 = k22;
  k->block = p1->normal_mass > 0.0 && p2->normal_mass > 0.0 && k11 * k11 < BLOCK_MAX_CONDITION * (k11 * k22 - k12 * k12);
}

/* (im: a->im + b->im, as effective_mass_of) */
static inline void pair_matrix (contact *k, const solver_body *a, const solver_body *b)
{
  pair_matrix_of (k, a->im + b->im, a->ii, b->ii);
}

/* A normal impulse applied at a point, `remaining` before the end of the
 * step: with every other, it adds up to what the contact gave over the whole
 * step, and to how far that moved the bodies by the end of it (the moment,
 * see contact_time_of_impact). Only bouncy contacts (track) need the moment:
 * the time of impact leaves the others alone. */
static inline void apply_normal (solver_body *a, solver_body *b, contact_point *p, double lambda, double remaining,
                                 int track)
{
  contact_push (a, b, p->normal, p->rn_a, p->rn_b, lambda);
  p->total_impulse += lambda; /* the step's, for the events too */
  if (track)
    p->normal_moment += lambda * remaining;
}

#endif
