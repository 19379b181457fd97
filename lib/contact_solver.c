/* The contact constraint.
 *
 * For one contact point the impulse is the thesis' eq. 3.23 with its two
 * slips corrected (docs/physics.md): the relative velocity is that of the
 * contact points, v_p = v_bp - v_ap (v_ap alone in the thesis), and both
 * bodies' angular terms add with the same sign (eq. 3.17 flips the B term):
 *
 *   j = -(1 + e) v_p . n / (1/m_a + 1/m_b + (r_ap x n)^2 / I_a + (r_bp x n)^2 / I_b)
 *
 * Here n points from A to B and B receives +j n, A receives -j n (the
 * thesis' n points the other way; the formula is the same).
 *
 * Within a step the constraint is solved in two parts. In every sub-step
 * the impulses keep the points from approaching (eq. 3.23 with e = 0),
 * accumulated and clamped so contacts only push, in a pass before the
 * motion and one after it; overlap beyond the slop is pushed out on
 * separate pseudo-velocities (a fraction position_correction of it per
 * sub-step) that move the bodies and are dropped, so position correction
 * never changes a velocity and adds no kinetic energy (split impulses).
 * After the last sub-step, every point that was struck leaves at e times
 * the normal speed it met with, less the gravity after the meeting (eq.
 * 3.18): for an isolated contact the whole step then applies exactly the
 * impulse of eq. 3.23 at the moment of impact, with gravity before and
 * after it. That part, and the impacts met at their time within the step,
 * are impact.c's; the functions both use are contact_solver.h's.
 *
 * The lever arms r_ap, r_bp and the normal are those of the detection at
 * the start of the step; the separation is followed through the sub-steps
 * from the bodies' motion since then, so no geometry is recomputed. */
#include "contact_solver.h"

#include "contact_batch_pack.h"
#include "impact.h"
#include "world.h"

/* Overlap is pushed out at most this fraction of the smaller body's radius
 * (its bounding circle's) per step, so a deep overlap resolves over several
 * steps instead of launching the bodies. The radius, not the thickness: a
 * sliver that lands deep in the ground must still come out in a few steps. */
#define CONTACT_PUSH_PER_STEP 0.05

/* What the set-up of a contact's points reads of its two bodies, loaded
 * once per contact: nothing in the loop over the points changes it, and the
 * stores into the points would otherwise make the compiler load it again
 * for each of them. */
typedef struct pair_bodies {
  vec2 pa, pb;                /* the centres of mass */
  double reach_a, reach_b;    /* twice the bounding radii (lever_arms) */
  int circle_a, circle_b;
  double im;                  /* a->im + b->im (effective_mass_of) */
  double ii_a, ii_b;
  vec2 dv;                    /* b->v - a->v (contact_speed_of) */
  double w_a, w_b;
} pair_bodies;

static void pair_bodies_load (pair_bodies *pb, const body *ba, const body *bb, const solver_body *a,
                              const solver_body *b)
{
  pb->pa = ba->p;
  pb->pb = bb->p;
  pb->reach_a = 2.0 * ba->shape.bound_radius;
  pb->reach_b = 2.0 * bb->shape.bound_radius;
  pb->circle_a = ba->shape.kind == CAROM_SHAPE_CIRCLE;
  pb->circle_b = bb->shape.kind == CAROM_SHAPE_CIRCLE;
  pb->im = a->im + b->im;
  pb->ii_a = a->ii;
  pb->ii_b = b->ii;
  pb->dv = v2_sub (b->v, a->v);
  pb->w_a = a->w;
  pb->w_b = b->w;
}

/* Lever arms of a contact point. A lever arm cannot be longer than the body
 * reaches (rounding of far-apart coordinates can make it so for a tiny
 * body); a circle's normal impulse passes through its centre, so r x n is
 * exactly 0 there whatever the rounding of the point says. */
ALWAYS_INLINE void lever_arms (contact_point *p, const pair_bodies *pb, vec2 ra, vec2 rb)
{
  vec2 t = v2_perp (p->normal);
  double la = pb->reach_a + fabs (p->depth), lb = pb->reach_b + fabs (p->depth);
  if (v2_len2 (ra) > la * la)
    ra = v2_scale (ra, la / v2_len (ra));
  if (v2_len2 (rb) > lb * lb)
    rb = v2_scale (rb, lb / v2_len (rb));
  p->rn_a = pb->circle_a ? 0.0 : v2_cross (ra, p->normal);
  p->rn_b = pb->circle_b ? 0.0 : v2_cross (rb, p->normal);
  p->rt_a = v2_cross (ra, t);
  p->rt_b = v2_cross (rb, t);
  p->ra = separation_arm_of (pb->circle_a, ra);
  p->rb = separation_arm_of (pb->circle_b, rb);
  p->adjusted = -p->depth - v2_dot (v2_sub (p->rb, p->ra), p->normal);
}

/* A point still apart and closing meets the other body a time t = gap /
 * speed into the step: its lever arms are those of that moment, both
 * reaching the point where the bodies meet (moved with them), so the impulse
 * turns the bodies as the impact does. */
static void lever_arms_at_impact (contact_point *p, const pair_bodies *pb, const solver_body *a,
                                  const solver_body *b, double toi)
{
  vec2 meet = v2_mad (p->point, 0.5 * toi, v2_add (a->v, b->v));
  lever_arms (p, pb, v2_sub (meet, v2_mad (pb->pa, toi, a->v)), v2_sub (meet, v2_mad (pb->pb, toi, b->v)));
}

/* When a point a gap -depth apart, closing at vn < 0, meets under the
 * relative acceleration `fall` along its normal: the first root of
 * -depth + vn t + fall t^2 / 2 = 0, in the form that does not cancel, or
 * dt when it does not meet within the step (a closing that gravity, or the
 * bodies' own acceleration apart, stops first). */
static double meeting_time (double depth, double vn, double fall, double dt)
{
  double gap = -depth, disc = vn * vn - 2.0 * fall * gap, t;
  if (!(disc >= 0.0))
    return dt;
  t = 2.0 * gap / (-vn + sqrt (disc));
  return t < dt ? t : dt;
}

/* A warm-start impulse changes the velocities by impulse / mass. If the
 * effective mass fell since last step (a lever arm that grew, as across a
 * long speculative gap), last step's impulse would now give a larger change
 * than it ever did: it is scaled down to give the same one. Otherwise a tiny
 * body whose arm grew a thousandfold would be spun a millionfold faster at
 * once, and then overflow. */
static void rescale_warm_start (contact_point *p, double old_nm, double old_tm)
{
  /* by selects: whether a mass fell by a rounding or rose is not
   * predictable (the quotient not taken may be inf or NaN, and is unused) */
  double sn = p->normal_mass / old_nm, st = p->tangent_mass / old_tm;
  p->normal_impulse = select_double (p->normal_mass < old_nm, p->normal_impulse * sn, p->normal_impulse);
  p->tangent_impulse = select_double (p->tangent_mass < old_tm, p->tangent_impulse * st, p->tangent_impulse);
}

/* Whether a contact begins resting this step (contact_cold_start): it is
 * new (no impulse to warm start from), and each of its points is near
 * (within the slop) and neither closing nor leaving faster than gravity's
 * threshold. (A contact that was there last step with no impulse carried
 * no load, and starts from none.) */
static int begins_resting (const contact *k, const step_context *ctx)
{
  int32_t j;
  if (!k->fresh)
    return 0;
  for (j = 0; j < k->count; ++j)
    {
      const contact_point *p = &k->points[j];
      if (p->normal_impulse != 0.0 || p->depth < -k->slop || !(fabs (p->approach) < ctx->restitution_threshold))
        return 0;
    }
  return 1;
}

void contact_prepare (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  c->cold_count = 0;
  c->bouncy_count = 0;
  /* Without a bouncy contact the impacts have nothing to do, and what
   * comes between the set-up and the batches changes no point but the
   * cold start's impulses: the batches are laid out first, and each
   * batched contact packed as it is set up, while its points are at hand
   * (contact_batch_prepare packs the cold ones again). The count of the
   * detection is a hint; a bouncy contact found after all undoes it. */
  c->packed = c->bouncy_found == 0;
  if (c->packed)
    contact_batch_plan (world, ctx);
  contact_prepare_from (world, ctx, 0);
  if (c->bouncy_count > 0)
    c->packed = 0;
}

void contact_prepare_from (carom_world *world, const step_context *ctx, int32_t first)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  const double dt = ctx->dt, threshold = ctx->restitution_threshold;
  int32_t i, j, bouncy = 0, cold = 0;
  int pack = c->packed;
  for (i = first; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      const body *ba = &world->bodies[k->a], *bb = &world->bodies[k->b];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      double reach = ba->shape.bound_radius < bb->shape.bound_radius ? ba->shape.bound_radius : bb->shape.bound_radius;
      double near_depth = -k->slop;
      /* constrain_bodies' bits of every point, given to both bodies once */
      int32_t bits = 0, count = k->count;
      contact_point *points = k->points;
      /* k->friction == 0: it keeps no tangent impulse */
      int frictionless = k->friction == 0.0;
      pair_bodies pb;
      pair_bodies_load (&pb, ba, bb, a, b);
      k->max_push = CONTACT_PUSH_PER_STEP * reach * ctx->inv_dt;
      k->met = 0;
      k->queued = 0;
      k->impact_at = -1.0;
      k->pending = k->reimpacts = 0;
      k->kept = 0;
      k->event_round = -1;
      k->touch_at = -1.0;
      bouncy += k->restitution > 0.0;
      for (j = 0; j < count; ++j)
        {
          contact_point *p = &points[j];
          double old_nm = p->normal_mass, old_tm = p->tangent_mass, vn;
          int near, meets;
          lever_arms (p, &pb, v2_sub (p->point, pb.pa), v2_sub (p->point, pb.pb));
          point_masses_of (p, pb.im, pb.ii_a, pb.ii_b);
          vn = contact_speed_of (pb.dv, pb.w_a, pb.w_b, p->normal, p->rn_a, p->rn_b);
          /* before any impulse of the step (see contact_solve) */
          p->approach = vn;
          p->toi = -1.0;
          if (p->depth < 0.0 && vn < 0.0)
            {
              /* closing: it meets at toi, or is a speculative contact of the
               * whole step (toi = dt), with the arms of that moment */
              p->toi = meeting_time (p->depth, vn, relative_fall (a, b, p->normal, ctx), dt);
              lever_arms_at_impact (p, &pb, a, b, p->toi);
              point_masses_of (p, pb.im, pb.ii_a, pb.ii_b);
              p->approach = contact_speed_of (pb.dv, pb.w_a, pb.w_b, p->normal, p->rn_a, p->rn_b);
            }
          /* constrain_bodies, for both bodies once after the loop */
          near = p->depth >= near_depth;
          meets = p->toi >= 0.0 && p->toi < dt;
          bits |= constrained_bits (near, meets, vn, threshold);
          rescale_warm_start (p, old_nm, old_tm);
          if (frictionless)
            p->tangent_impulse = 0.0;
          p->after = 0.0;
          p->total_impulse = p->normal_moment = p->impact_moment = 0.0;
          p->in_impact = near || meets;
          p->tangent_total = p->tangent_moment = 0.0;
        }
      a->constrained |= bits;
      b->constrained |= bits;
      contact_impact_points (world, k, a, b, ctx);
      pair_matrix_of (k, pb.im, pb.ii_a, pb.ii_b);
      k->cold = begins_resting (k, ctx);
      cold += k->cold;
      if (pack && k->batched)
        contact_batch_pack (world, i);
    }
  c->bouncy_count += bouncy;
  c->cold_count += cold;
}

/* The same along the tangent (friction). */
static inline void apply_tangent (solver_body *a, solver_body *b, contact_point *p, double lambda, double remaining,
                                  int track)
{
  contact_push (a, b, v2_perp (p->normal), p->rt_a, p->rt_b, lambda);
  if (track)
    {
      p->tangent_total += lambda;
      p->tangent_moment += lambda * remaining;
    }
}

void contact_warm_start (carom_world *world, double remaining)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  for (i = 0; i < c->rest_count; ++i)
    {
      contact *k = &c->list[c->rest[i]];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          if (p->normal_impulse != 0.0)
            apply_normal (a, b, p, p->normal_impulse, remaining, k->restitution > 0.0);
          if (p->tangent_impulse != 0.0)
            apply_tangent (a, b, p, p->tangent_impulse, remaining, k->restitution > 0.0);
        }
    }
}

/* The part of the sub-step's gravity kick a body's drift takes back (a free
 * body's half, gravity_drift_velocity); the kick itself, or 0. */
static vec2 free_kick (const solver_body *b, const step_context *ctx)
{
  return b->moves == MOVES_DYNAMIC && !b->constrained ? ctx->kick : v2 (0.0, 0.0);
}

/* The normal speed a point's impulse aims at, as -bias: a speculative point
 * (apart by s) may close its gap within the sub-step but not pass it; a
 * touching or overlapping one may not approach. */
static double point_bias (const contact_point *p, const solver_body *a, const solver_body *b, const step_context *ctx)
{
  double s = contact_separation (a, b, p);
  if (!(s > 0.0))
    return 0.0;
  /* a free body moves by the mean of its velocities before and after the
   * kick (gravity_drift_velocity): half a kick less far than its velocity
   * says, which the gap may then take */
  return s * ctx->inv_h - 0.5 * v2_dot (v2_sub (free_kick (b, ctx), free_kick (a, ctx)), p->normal);
}

/* The push-out's target for a point, as -bias on its pseudo normal speed:
 * an overlap beyond the slop is pushed out, a fraction position_correction
 * of it per sub-step, no faster than max_push; 0 within the slop. */
static double push_bias (const contact *k, const contact_point *p, const solver_body *a, const solver_body *b,
                         const step_context *ctx)
{
  double s = contact_separation (a, b, p), bias;
  if (s + k->slop >= 0.0)
    return 0.0;
  bias = ctx->push_rate * (s + k->slop);
  return bias < -k->max_push ? -k->max_push : bias;
}

/* Returns the change of the point's normal speed. */
static double solve_point (solver_body *a, solver_body *b, contact_point *p, double bias, double remaining,
                           int track)
{
  double vn = contact_speed (a, b, p->normal, p->rn_a, p->rn_b);
  double acc = p->normal_impulse - p->normal_mass * (vn + bias), d;
  if (acc < 0.0)
    acc = 0.0;
  d = acc - p->normal_impulse;
  apply_normal (a, b, p, d, remaining, track);
  p->normal_impulse = acc;
  return p->normal_mass > 0.0 ? fabs (d) / p->normal_mass : 0.0;
}


/* Both points of a block at once: the accumulated impulses x >= 0 with
 * K x + (vn + bias - K x_now) >= 0, complementary. Returns 0 when rounding
 * leaves no consistent case (the caller solves the points one at a time). */
static int solve_block (solver_body *a, solver_body *b, contact *k, const double *bias, double remaining,
                        double *change)
{
  contact_point *p1 = &k->points[0], *p2 = &k->points[1];
  double x1 = p1->normal_impulse, x2 = p2->normal_impulse, y1, y2;
  double b1 = contact_speed (a, b, p1->normal, p1->rn_a, p1->rn_b) + bias[0] - (k->k11 * x1 + k->k12 * x2);
  double b2 = contact_speed (a, b, p2->normal, p2->rn_a, p2->rn_b) + bias[1] - (k->k12 * x1 + k->k22 * x2);
  if (!contact_lcp2 (k->k11, k->k12, k->k22, b1, b2, &y1, &y2))
    return 0;
  apply_normal (a, b, p1, y1 - x1, remaining, k->restitution > 0.0);
  apply_normal (a, b, p2, y2 - x2, remaining, k->restitution > 0.0);
  p1->normal_impulse = y1;
  p2->normal_impulse = y2;
  {
    double v1 = fabs (k->k11 * (y1 - x1) + k->k12 * (y2 - x2)), v2 = fabs (k->k12 * (y1 - x1) + k->k22 * (y2 - x2));
    *change = v1 > v2 ? v1 : v2;
  }
  return 1;
}

/* The first pass in which a contact pushes is when its bodies met. What
 * restitution reverses is the normal speed they met with, taken for every
 * point of every contact on the velocities before any contact impulse of
 * the step (prepare) plus what gravity added until the meeting: measured on
 * one common state, so that for e = 1 the impulses of all the contacts
 * together change no energy. A point apart at detection meets at its time
 * of impact when it was closing, else (closed by gravity) at the sub-step of
 * this first push; what gravity adds from then to the end of the step is
 * kept apart (`after`): the bounce leaves at e times the meeting speed less
 * it, so no gravity is counted twice and none is lost (exact bounce
 * heights). A point that already touched or overlapped when the step began
 * met the other body before it, in a step that has already applied its
 * gravity: none of this step's is part of its approach or taken from its
 * bounce. */
static void note_meeting (contact *k, const solver_body *a, const solver_body *b, const step_context *ctx,
                          int32_t kicks)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    k->met |= k->points[j].normal_impulse > 0.0;
  if (k->met)
    for (j = 0; j < k->count; ++j)
      {
        contact_point *p = &k->points[j];
        double fall, meet;
        if (p->depth >= 0.0)
          continue;
        fall = relative_fall (a, b, p->normal, ctx);
        meet = p->toi >= 0.0 ? p->toi : kicks * ctx->h;
        p->approach += fall * meet;
        p->after = fall * (ctx->dt - meet);
      }
}

/* Coulomb friction: the tangent impulse stays within mu times the normal
 * impulse. */
static void solve_friction (solver_body *a, solver_body *b, contact *k, double remaining)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      vec2 t;
      double vt, limit, acc;
      /* no normal impulse: the limit is 0, so a tangent impulse of 0 stays 0 */
      if (p->normal_impulse == 0.0 && p->tangent_impulse == 0.0)
        continue;
      t = v2_perp (p->normal);
      vt = contact_speed (a, b, t, p->rt_a, p->rt_b);
      limit = k->friction * p->normal_impulse;
      acc = p->tangent_impulse - p->tangent_mass * vt;
      acc = acc > limit ? limit : (acc < -limit ? -limit : acc);
      apply_tangent (a, b, p, acc - p->tangent_impulse, remaining, k->restitution > 0.0);
      p->tangent_impulse = acc;
    }
}

/* Whether every point of the contact is apart (its bias, the gap it may
 * close in a sub-step, is positive). */
static int apart (const contact *k, const double *bias)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    if (!(bias[j] > 0.0))
      return 0;
  return 1;
}

double contact_solve (carom_world *world, const step_context *ctx, int32_t kicks, double remaining, int32_t pass)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  const int32_t *ids = pass > 0 ? c->fine_rest : c->rest;
  int32_t i, j, n = pass > 0 ? c->fine_rest_count : c->rest_count;
  double most = 0.0;
  for (i = 0; i < n; ++i)
    {
      contact *k = &c->list[ids[i]];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      double bias[MANIFOLD_MAX_POINTS], change = 0.0;
      if (k->fine <= pass && pass > 0)
        continue;
      for (j = 0; j < k->count; ++j)
        bias[j] = point_bias (&k->points[j], a, b, ctx);
      if (remaining <= 0.0 && k->restitution > 0.0 && !k->met && apart (k, bias))
        continue; /* they meet after the step, if at all: the next step's
                     impact, at its time, not a bounce from here */
      if (!(k->block && solve_block (a, b, k, bias, remaining, &change)))
        for (j = 0; j < k->count; ++j)
          {
            double d = solve_point (a, b, &k->points[j], bias[j], remaining, k->restitution > 0.0);
            change = d > change ? d : change;
          }
      most = change > most ? change : most;
      if (!k->met)
        note_meeting (k, a, b, ctx, kicks);
      if (k->friction > 0.0)
        solve_friction (a, b, k, remaining);
    }
  return most;
}

/* ------------------------------------------------------------ push-out */

/* The pseudo-velocity versions of contact_speed and contact_push: the
 * push-out moves the bodies through these alone. */
static inline double pseudo_speed (const solver_body *a, const solver_body *b, vec2 d, double ra_d, double rb_d)
{
  return v2_dot (v2_sub (b->pv, a->pv), d) + b->pw * rb_d - a->pw * ra_d;
}

static inline void pseudo_push (solver_body *a, solver_body *b, vec2 d, double ra_d, double rb_d, double lambda)
{
  a->pv = v2_mad (a->pv, -a->im * lambda, d);
  a->pw -= a->ii * ra_d * lambda;
  b->pv = v2_mad (b->pv, b->im * lambda, d);
  b->pw += b->ii * rb_d * lambda;
}

void contact_push_out (carom_world *world, const step_context *ctx, int first)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  for (i = 0; i < c->rest_count; ++i)
    {
      contact *k = &c->list[c->rest[i]];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      double bias[MANIFOLD_MAX_POINTS];
      int any = 0;
      for (j = 0; j < k->count; ++j)
        {
          if (first)
            k->points[j].push_impulse = 0.0; /* last sub-step's was dropped with the move */
          bias[j] = push_bias (k, &k->points[j], a, b, ctx);
          any |= bias[j] < 0.0 || k->points[j].push_impulse > 0.0;
        }
      if (!any)
        continue;
      if (k->block)
        {
          contact_point *p1 = &k->points[0], *p2 = &k->points[1];
          double x1 = p1->push_impulse, x2 = p2->push_impulse, y1, y2;
          double b1 = pseudo_speed (a, b, p1->normal, p1->rn_a, p1->rn_b) + bias[0] - (k->k11 * x1 + k->k12 * x2);
          double b2 = pseudo_speed (a, b, p2->normal, p2->rn_a, p2->rn_b) + bias[1] - (k->k12 * x1 + k->k22 * x2);
          if (contact_lcp2 (k->k11, k->k12, k->k22, b1, b2, &y1, &y2))
            {
              pseudo_push (a, b, p1->normal, p1->rn_a, p1->rn_b, y1 - x1);
              pseudo_push (a, b, p2->normal, p2->rn_a, p2->rn_b, y2 - x2);
              p1->push_impulse = y1;
              p2->push_impulse = y2;
              continue;
            }
        }
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          double acc = p->push_impulse
                       - p->normal_mass * (pseudo_speed (a, b, p->normal, p->rn_a, p->rn_b) + bias[j]);
          if (acc < 0.0)
            acc = 0.0;
          pseudo_push (a, b, p->normal, p->rn_a, p->rn_b, acc - p->push_impulse);
          p->push_impulse = acc;
        }
    }
}
