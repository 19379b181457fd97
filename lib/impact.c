/* Impacts: restitution, and the moment of meeting.
 *
 * A bouncy contact (e > 0) that closes fast is an impact: its points leave
 * at minus e times the normal speed they met with (eq. 3.18), by the
 * impulse of eq. 3.23 with the corrections of docs/physics.md. Three stages
 * make it exact within a step:
 *
 * - before the sub-steps (contact_impacts), the impacts of the step in the
 *   order they happen, each at its time of impact (toi.c) with the lever
 *   arms of that moment, passed on through the bodies it touches as
 *   pairwise impacts (the sequential model, docs/physics.md);
 * - after them (contact_restitution), every point that was struck in the
 *   sub-steps leaves at e times the speed it met with, less what gravity
 *   added after the meeting;
 * - then (contact_time_of_impact), the bodies are moved to where an
 *   impulse at the moment of meeting leaves them.
 *
 * contact_prepare asks contact_impact_points for the points of a pair that
 * flies free into a touch within the step. The constraint that keeps
 * contact points from approaching is contact_solver.c's. */
#include "impact.h"

#include "toi.h"
#include "world.h"

#include <string.h>

/* The restitution solve iterates over the struck contacts until no point's
 * normal speed changes by more than this fraction of the fastest approach
 * (bodies struck on several sides at once, a cluster or a row, reach every
 * point's target together only as the passes converge), and at most this
 * many passes. */
#define RESTITUTION_TOLERANCE 1e-10
#define RESTITUTION_MAX_ITERATIONS 100

/* An impact passed on through touching bodies (contact_impacts) makes at
 * most this many pairwise impacts per contact of the step: with e < 1 a
 * row rings on ever more softly, and the rest is left to the sub-steps. */
#define IMPACT_MAX_EVENTS 64
/* A contact an impact acted on is searched for a next touch within the step
 * from this fraction of the step after it (its points are leaving: at the
 * impact itself they still touch), at most this many times a step: a
 * fast-spinning face grinding on a corner bounces off it a dozen times in
 * a step (13 in test_impacts' case), and what the searches leave falls to
 * the sub-steps. */
#define REIMPACT_DELAY 1e-9
#define REIMPACT_MAX 32
/* Only for contacts whose moving bodies touched at most this many other
 * moving bodies each at detection (sparse). */
#define REIMPACT_DEGREE 2
/* One pair of bodies meeting through several contacts at once (pieces of a
 * concave or compound body) takes one impact on all of them
 * (impact_group_event), of at most this many contacts; its solve passes
 * stop when every point is within IMPACT_GROUP_TOLERANCE of the fastest
 * approach of its target (at it with an impulse, at least at it without),
 * or within the rounding of its own speed, IMPACT_GROUP_ROUNDING of the
 * terms that make it up (a slow approach of fast bodies can come no nearer:
 * concave bodies created on top of one another and spinning into each
 * other stalled at 3e-16 of their speeds, 1e-12 of their approach, and
 * took all the passes: fuzz/corpus/scene/overlapping-concave.scene), at
 * most IMPACT_GROUP_PASSES. Points that say the same of the bodies (four
 * corners of one face on another) leave the passes no single answer to
 * settle on, and they converge slowly: in the accuracy map's elastic gas
 * with the vertex-edge method most such impacts take one pass and a few
 * take hundreds or thousands; stopped after 1000 (when the impulses
 * changed by less than 1e-13 of the largest) they left that gas 1.1e-11
 * of its energy off (build/accuracy/accuracy knobs=narrow_phase
 * measures=gas), 6.7e-15 stopped on the targets, 1.2e-14 on the targets
 * or their rounding (both rounding: the gas then takes another of its
 * chaotic paths). */
#define IMPACT_GROUP_MAX 8
#define IMPACT_GROUP_TOLERANCE 1e-13
#define IMPACT_GROUP_ROUNDING (32.0 * DBL_EPSILON)
#define IMPACT_GROUP_PASSES 10000
/* The passes over their points all the groups of one run of the impacts
 * take at most (a group's passes times its points): past it, each group
 * takes what is left, and at least one pass. A group whose targets cannot
 * all be met (bodies created deep inside one another, each of their
 * pieces closing on the other from opposite sides) takes every pass it is
 * allowed without converging: `make fuzz` found worlds of two such bodies
 * (fuzz/corpus/world/e8ed1379... and f551f790...) whose groups took all
 * 10000 passes, dozens of them a step: 87 s and 2.3 s to replay, 0.13 s
 * and under 0.01 s with this bound (built -O2, without the sanitizers;
 * 0.86 s and 0.05 s with ten times it). The scenes that converge need a
 * small part of it: the vertex-edge gas above at most 1264 in a run. */
#define IMPACT_GROUP_WORK 200000
/* Times a step looks for the new pairs of bodies its impacts set moving
 * (contacts_after_impacts), each after the impacts found so far. */
#define AFTER_IMPACT_PASSES 4

/* How far two bodies' centres can close along n in the step: their
 * relative velocity's approach, and what gravity adds (at most one body's
 * fall). Along the axis of a separating face, pieces that only translate
 * close by this and no more; turning adds its own reach. */
static double closing_reach (vec2 v, vec2 n, const step_context *ctx)
{
  double approach = -v2_dot (v, n) * ctx->dt;
  return (approach > 0.0 ? approach : 0.0) + 0.5 * ctx->accel * ctx->dt * ctx->dt;
}

/* The first test of a contact that may fly into an impact (see
 * impact_within_step): no point touching, nor near and slow. One such
 * point rules the contact out whatever the others say; most contacts
 * (those resting) are ruled out by it, before anything else is computed. */
static int all_apart (const contact *k, const step_context *ctx)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    {
      const contact_point *p = &k->points[j];
      if (!(p->depth < 0.0) || (p->depth >= -k->slop && !(fabs (p->approach) >= ctx->restitution_threshold)))
        return 0;
    }
  return 1;
}

/* A contact whose bodies may fly free into an impact within the step:
 * every point apart at detection, none resting (near and slow), and one
 * closing faster than resting contact ever does and meeting within the
 * step, or within the distance the bodies' turning carries them. With
 * continuous collision (the world's or a bullet's), within the distance
 * their turning and their approach along the normal carry them: a fast
 * spinning body swings in a corner that is none of the detected points,
 * and the points' own estimate (their speed at the arms of the detection)
 * misses it (the elastic gas: 5 cm deep). Its pieces are polygons' convex
 * pieces or circles, or the vertex-edge method's whole outlines (toi.h).
 * The first part, all_apart, is its caller's. */
static int impact_within_step (const carom_world *world, const contact *k, const solver_body *a,
                               const solver_body *b, const step_context *ctx)
{
  const body *ba, *bb;
  double turn;
  int swept = -1; /* contact_pair_swept, asked once it is needed */
  vec2 v;
  int32_t j;
  ba = &world->bodies[k->a], bb = &world->bodies[k->b];
  /* how far the bodies' turning can carry their surfaces in the step */
  turn = (fabs (a->w) * ba->shape.bound_radius + fabs (b->w) * bb->shape.bound_radius) * ctx->dt;
  v = v2_sub (b->v, a->v);
  for (j = 0; j < k->count; ++j)
    {
      const contact_point *p = &k->points[j];
      if (p->approach < -ctx->restitution_threshold && p->toi >= 0.0 && p->toi < ctx->dt)
        return 1;
      /* a fast turn can bring another corner in, which the points' own
       * linear estimate does not see; and the gap that closes is the
       * pieces' (k->gap), which a point clipped to a face can overstate */
      if (swept < 0)
        swept = contact_pair_swept (world, k->a, k->b, ctx);
      if (k->gap < turn + (swept ? closing_reach (v, p->normal, ctx) : 0.0))
        return 1;
    }
  return 0;
}

/* The impulse side of a point of an impact at its time t: lever arms ra, rb
 * of that moment (a circle's normal impulse through its centre), no impulse
 * carried in, and the approach measured on them. */
static void impact_arms (contact *k, contact_point *p, const body *ba, const body *bb, solver_body *a, solver_body *b,
                         const step_context *ctx, double t, vec2 ra, vec2 rb)
{
  vec2 tangent = v2_perp (p->normal);
  double vn;
  p->rn_a = ba->shape.kind == CAROM_SHAPE_CIRCLE ? 0.0 : v2_cross (ra, p->normal);
  p->rn_b = bb->shape.kind == CAROM_SHAPE_CIRCLE ? 0.0 : v2_cross (rb, p->normal);
  p->rt_a = v2_cross (ra, tangent);
  p->rt_b = v2_cross (rb, tangent);
  p->normal_impulse = p->tangent_impulse = 0.0;
  point_masses (p, a, b);
  vn = contact_speed (a, b, p->normal, p->rn_a, p->rn_b);
  p->toi = t;
  constrain_bodies (k, p, a, b, vn, ctx);
  p->approach = vn;
}

/* A point of an impact at its time of impact t, from the narrow phase's
 * point q there (the bodies at xa, xb, turned by turn_a, turn_b since the
 * step began): the normal, the point and the lever arms of eq. 3.23 are
 * those of the touch. Its separation is still followed from the start of
 * the step (contact_separation) through its two bodies' copies of it,
 * carried back from the touch along their free flight; its depth is minus
 * that separation at the start. An impulse there, at that time, with arms
 * of that moment, keeps the pair's angular momentum about any point
 * (contact_time_of_impact). */
static void impact_point (contact *k, contact_point *p, const manifold_point *q, const body *ba, const body *bb,
                          solver_body *a, solver_body *b, const step_context *ctx, double t, xform xa, xform xb,
                          rot2 turn_a, rot2 turn_b)
{
  vec2 ra = v2_sub (q->point, xa.p), rb = v2_sub (q->point, xb.p);
  vec2 ra0 = separation_arm (ba, rot2_apply_inv (turn_a, ra)), rb0 = separation_arm (bb, rot2_apply_inv (turn_b, rb));
  /* how far each copy moved from the start to the touch */
  vec2 moved_a = v2_sub (v2_add (xa.p, rot2_apply (turn_a, ra0)), v2_add (ba->p, ra0));
  vec2 moved_b = v2_sub (v2_add (xb.p, rot2_apply (turn_b, rb0)), v2_add (bb->p, rb0));
  double s0 = -q->depth - v2_dot (v2_sub (moved_b, moved_a), q->normal);
  p->point = q->point;
  p->normal = q->normal;
  p->feature = q->feature;
  p->depth = -s0;
  p->found = q->depth;
  p->ra = ra0;
  p->rb = rb0;
  p->adjusted = s0 - v2_dot (v2_sub (rb0, ra0), q->normal);
  impact_arms (k, p, ba, bb, a, b, ctx, t, ra, rb);
  /* a point that bounced earlier in the step stays bounced when it is of a
   * later touch: it takes part in that impact as any point, but its bounce
   * is done, and the end of the step must not take its speed now, leaving,
   * for an approach to reflect (contact_restitution would pull the bounce
   * back, and contact_time_of_impact move the bodies for it) */
  if (p->in_impact == IMPACT_BOUNCED || p->in_impact == IMPACT_DONE)
    {
      p->in_impact = IMPACT_BOUNCED;
      p->approach = 0.0;
    }
  else
    p->in_impact = 1;
}

/* A detected point of an impact that the touch has no point for: it keeps
 * its normal and follows its separation from the detection, as any point,
 * but its impulse, if any, is taken at the time of impact t too, at the
 * midpoint of its two bodies' copies of it then, so the contact's every
 * impulse is of one moment and keeps the pair's angular momentum. */
static void impact_guard_point (contact *k, contact_point *p, const body *ba, const body *bb, solver_body *a,
                                solver_body *b, const step_context *ctx, double t, xform xa, xform xb,
                                rot2 turn_a, rot2 turn_b)
{
  vec2 ra0 = v2_sub (p->point, ba->p), rb0 = v2_sub (p->point, bb->p), ra, rb, mid;
  mid = v2_scale (v2_add (v2_add (xa.p, rot2_apply (turn_a, ra0)), v2_add (xb.p, rot2_apply (turn_b, rb0))), 0.5);
  ra = v2_sub (mid, xa.p);
  rb = v2_sub (mid, xb.p);
  p->ra = separation_arm (ba, ra0);
  p->rb = separation_arm (bb, rb0);
  p->adjusted = -p->depth - v2_dot (v2_sub (p->rb, p->ra), p->normal);
  impact_arms (k, p, ba, bb, a, b, ctx, t, ra, rb);
  p->in_impact = 0; /* it does not touch then */
}

/* The points of contact k's touch at time t (toi.c), the bodies in free
 * flight until then (shifted by `shifts`, or NULL): the points of the touch
 * (within the slop of it) take the place of the detected points of the same
 * features. The deepest, if no feature matches, takes the place of `first`
 * (a slot index). When `guard`, the other detected points stay
 * (impact_guard_point): they guard the rest of the step (a body an impact
 * sets spinning turns its other corners towards the surface); else they are
 * left as they are (an impact again, contact_impacts). Returns the slots
 * taken, a bit each. */
static uint32_t touch_points (carom_world *world, contact *k, const body *ba, const body *bb, solver_body *a,
                              solver_body *b, const step_context *ctx, double t, const vec2 *toward,
                              const impact_shift *shifts, int32_t first, int guard)
{
  const impact_shift *sa = shifts ? &shifts[k->a] : NULL, *sh = shifts ? &shifts[k->b] : NULL;
  xform xa = toi_pose (world, k->a, a, ctx, t, sa), xb = toi_pose (world, k->b, b, ctx, t, sh);
  rot2 turn_a = rot2_from_angle (sa ? a->w * t + sa->a : a->w * t);
  rot2 turn_b = rot2_from_angle (sh ? b->w * t + sh->a : b->w * t);
  manifold m;
  uint32_t taken = 0u;
  int32_t i, j;
  contact_collide_at (world, k, xa, xb, k->slop, toward, &m);
  for (i = 1; i < m.count; ++i) /* deepest first */
    for (j = i; j > 0 && m.points[j].depth > m.points[j - 1].depth; --j)
      {
        manifold_point q = m.points[j];
        m.points[j] = m.points[j - 1];
        m.points[j - 1] = q;
      }
  for (i = 0; i < m.count; ++i)
    {
      int32_t at = -1;
      for (j = 0; j < k->count; ++j)
        if (!(taken & (1u << j)) && k->points[j].feature == m.points[i].feature)
          at = j;
      if (at < 0 && i == 0)
        at = first;
      if (at < 0)
        continue;
      taken |= 1u << at;
      impact_point (k, &k->points[at], &m.points[i], ba, bb, a, b, ctx, t, xa, xb, turn_a, turn_b);
    }
  if (taken && guard)
    for (j = 0; j < k->count; ++j)
      if (!(taken & (1u << j)))
        impact_guard_point (k, &k->points[j], ba, bb, a, b, ctx, t, xa, xb, turn_a, turn_b);
  return taken;
}

/* A contact whose pieces, in free flight, do not touch for the rest of the
 * step takes no impulse in it: a point closing fast, its lever arm
 * turning, only seemed to (the passes take its normal speed at the arm of
 * the detection), or, after an impact, the sub-steps (which move the
 * bodies at their final velocities from the start of the step) would see
 * the pair meet where it does not. */
static void impact_inert (contact *k)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      p->rn_a = p->rn_b = p->rt_a = p->rt_b = 0.0;
      p->normal_mass = p->tangent_mass = 0.0;
      p->normal_impulse = p->tangent_impulse = 0.0;
    }
  k->block = 0;
}

/* Keep contact k and its points as they were before the impacts changed
 * them, once (contact_impacts' replay puts them back). */
static void impact_keep (carom_world *world, contact *k)
{
  contacts *c = &world->contacts;
  int32_t i = (int32_t) (k - c->list);
  if (k->kept)
    return;
  world->saved_contacts[c->kept] = *k;
  world->saved_contacts[c->kept].first_point = i; /* where it goes back */
  memcpy (world->saved_points + c->kept_points, k->points, (size_t) k->count * sizeof (contact_point));
  c->kept_points += k->count;
  c->kept++;
  k->kept = 1;
}

/* Put back the contacts impact_keep kept, and their points. */
static void impact_restore (carom_world *world)
{
  contacts *c = &world->contacts;
  int32_t i, p = 0;
  for (i = 0; i < c->kept; ++i)
    {
      const contact *s = &world->saved_contacts[i];
      contact *k = &c->list[s->first_point];
      int32_t first = k->first_point;
      contact_point *points = k->points;
      *k = *s;
      k->first_point = first, k->points = points, k->kept = 0;
      memcpy (points, world->saved_points + p, (size_t) s->count * sizeof (contact_point));
      p += s->count;
    }
  c->kept = c->kept_points = 0;
}

/* Whether the time of impact's verdict of apart (TOI_APART) holds for the
 * rest of the step, so the contact can take no impulse in it. The search
 * follows both bodies in free flight, where two bodies that both fall never
 * close by gravity; but either may be stopped within the step by what it
 * rests on or strikes (a box landing on the ground, another falling just
 * above it), and the other then closes on it by up to accel dt^2 / 2 more.
 * Such a pair stays an ordinary speculative contact in the sub-steps, which
 * act only when its gap closes. */
static int apart_holds (const solver_body *a, const solver_body *b, const step_context *ctx)
{
  return !(ctx->accel > 0.0 && a->moves == MOVES_DYNAMIC && b->moves == MOVES_DYNAMIC);
}

/* An impact (impact_within_step) where its pieces first touch, each body in
 * free flight until then (toi.c): touch_points, the deepest taking the place
 * of the detected point meeting first (or, when none meets by itself, the
 * touch being another corner turned in, of the first). When the pieces do
 * not touch within the step, the contact takes no impulse in it. */
static void impact_points (carom_world *world, contact *k, const body *ba, const body *bb, solver_body *a,
                           solver_body *b, const step_context *ctx)
{
  vec2 axis;
  double t = toi_first_touch (world, k, a, b, ctx, 0.0, ctx->dt, NULL, &axis);
  int32_t j, first = -1;
  if (t == TOI_APART && apart_holds (a, b, ctx))
    {
      impact_inert (k);
      for (j = 0; j < k->count; ++j)
        k->points[j].toi = -1.0;
      return;
    }
  if (t < 0.0)
    return;
  for (j = 0; j < k->count; ++j)
    if (k->points[j].toi >= 0.0 && (first < 0 || k->points[j].toi < k->points[first].toi))
      first = j;
  touch_points (world, k, ba, bb, a, b, ctx, t, &axis, NULL, first < 0 ? 0 : first, 1);
}


/* contact_impact_points past all_apart, out of line:
 * the contacts that test rules out (most) then leave without setting up
 * the frame the rest needs. */
#ifdef __GNUC__
__attribute__ ((noinline))
#endif
static void impact_search (carom_world *world, contact *k, solver_body *a, solver_body *b, const step_context *ctx)
{
  if (impact_within_step (world, k, a, b, ctx))
    impact_points (world, k, &world->bodies[k->a], &world->bodies[k->b], a, b, ctx);
}

void contact_impact_points (carom_world *world, contact *k, solver_body *a, solver_body *b, const step_context *ctx)
{
  if (all_apart (k, ctx))
    impact_search (world, k, a, b, ctx);
}

/* ------------------------------------------------------------ impacts */

/* The approach speed below which a point along normal n does not bounce:
 * the step's threshold (what gravity adds in two steps) for the part of
 * gravity along n. Resting contact meets its support at about one step's
 * gravity along its normal; a contact across gravity (a ball striking a row
 * on a floor) meets none, and bounces at any speed. */
static double impact_threshold (const step_context *ctx, vec2 n)
{
  return ctx->accel > 0.0 ? ctx->restitution_threshold * fabs (v2_dot (ctx->gravity, n)) / ctx->accel : 0.0;
}

/* An impact of the step: a bouncy contact (e > 0) that closes faster than
 * resting contact ever does (impact_threshold), touching now (within
 * TOI_TOUCH: it meets at 0) or apart and meeting within the step (at its
 * earliest point's time of impact). A contact with some point touching now
 * and closing, however slowly, meets at 0 too: its pieces already touch,
 * and until a later time of impact its bodies' flight (impact_shift) would
 * carry that point on into the other body unchecked (a pentagon rocking on
 * another body, one corner resting on it while the turn brings the next
 * corner down within the step, sank the resting one 1.1 cm). */
static int impact_seed (const contact *k, const step_context *ctx, double *at)
{
  int32_t j, seed = 0, touching = 0;
  double t = ctx->dt;
  if (k->restitution == 0.0)
    return 0;
  for (j = 0; j < k->count; ++j)
    {
      const contact_point *p = &k->points[j];
      double when;
      touching |= p->normal_mass != 0.0 && p->depth >= -TOI_TOUCH * k->slop && p->approach < 0.0;
      if (p->normal_mass == 0.0 || !(p->approach < -impact_threshold (ctx, p->normal)))
        continue;
      if (p->depth < 0.0 && p->toi >= 0.0 && p->toi < ctx->dt)
        when = p->toi;
      else if (p->depth >= -TOI_TOUCH * k->slop)
        when = 0.0;
      else
        continue;
      seed = 1;
      t = when < t ? when : t;
    }
  *at = touching ? 0.0 : t;
  return seed;
}

/* Whether an impact at time t passes on through contact k: it is an
 * impact of the step at that moment, or its pieces touch then (within
 * TOI_TOUCH of it: at the start of the step some point, later in the
 * bodies' flight since the impacts, impact_shift). A contact apart then is
 * not passed: if its bodies now close on it within the step, that is an
 * impact in turn at its own time (impact_again). */
static int impact_passes (const carom_world *world, contact *k, const step_context *ctx, double t)
{
  const solver_body *sb = world->solver_bodies;
  double touch = TOI_TOUCH * k->slop;
  int32_t j;
  vec2 axis;
  if (k->impact_at == t)
    return 1;
  if (t > 0.0)
    {
      /* where the bodies are at t does not change with the impacts at t:
       * once found for a moment, it holds for the rest of it */
      if (k->touch_at != t)
        {
          k->touch_at = t;
          k->touches = k->count > 0
                       && contact_separation_at (world, k,
                                                 toi_pose (world, k->a, &sb[k->a], ctx, t, &world->impact_shifts[k->a]),
                                                 toi_pose (world, k->b, &sb[k->b], ctx, t, &world->impact_shifts[k->b]),
                                                 &axis)
                              <= touch;
        }
      return k->touches;
    }
  for (j = 0; j < k->count; ++j)
    if (k->points[j].depth >= -touch)
      return 1;
  return 0;
}

/* Whether a point takes part in its contact's impacts (contact_impacts). */
static int takes_impact (const contact_point *p)
{
  return p->in_impact == 1 || p->in_impact == IMPACT_BOUNCED;
}

/* Coulomb friction in an impact at time t: each point that took a normal
 * impulse lambda takes the tangent impulse that stops its slip then (the
 * bodies' velocities now, plus what gravity adds along the tangent until
 * t), within mu lambda. It slows the slip and never reverses it, so it
 * takes energy and never gives any; the sub-steps after it brake a slip
 * that is left by mu times their own normal impulses, as for any contact.
 * (Impact events are bouncy contacts' only.) Without it a ball bouncing off
 * a rough floor would keep its whole slip and gain no spin. */
static void impact_friction (contact *k, solver_body *a, solver_body *b, const step_context *ctx, double t,
                             const double *lambda)
{
  int32_t j;
  if (k->friction == 0.0)
    return;
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      vec2 tangent = v2_perp (p->normal);
      double vt, limit, jt;
      if (!(lambda[j] > 0.0) || p->tangent_mass == 0.0)
        continue;
      vt = contact_speed (a, b, tangent, p->rt_a, p->rt_b) + relative_fall (a, b, tangent, ctx) * t;
      limit = k->friction * lambda[j];
      jt = -p->tangent_mass * vt;
      jt = jt > limit ? limit : (jt < -limit ? -limit : jt);
      contact_push (a, b, tangent, p->rt_a, p->rt_b, jt);
      p->tangent_total += jt;
    }
}

/* The pairwise impact of contact k at time t into the step, if it closes
 * there faster than `tol` beyond its impact_threshold: each point's normal
 * speed then (the bodies' velocities now, plus what gravity adds until t)
 * leaves at minus e times itself; eq. 3.23 for one point, both at once (the
 * 2x2 problem) for two (more than two: impact_group_event). Its impulses
 * count towards the step's totals, and
 * each body's velocity change times t towards its shift (impact_shift),
 * the move that puts it where an impulse at t leaves it
 * (contact_time_of_impact); the bounce is an event of its step and is not
 * warm started. Returns whether it acted. */
static int impact_event (contact *k, solver_body *a, solver_body *b, impact_shift *shifts, const step_context *ctx,
                         double t, double tol)
{
  double speed[MANIFOLD_MAX_POINTS], lambda[MANIFOLD_MAX_POINTS];
  vec2 va = a->v, vb = b->v;
  double wa = a->w, wb = b->w;
  int32_t j, closing = 0, taking = 0;
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      lambda[j] = 0.0;
      speed[j] = contact_speed (a, b, p->normal, p->rn_a, p->rn_b) + relative_fall (a, b, p->normal, ctx) * t;
      if (!takes_impact (p) || p->normal_mass == 0.0)
        continue;
      ++taking;
      closing |= speed[j] < -(tol + impact_threshold (ctx, p->normal));
    }
  if (!closing)
    return 0;
  if (k->count == 2 && k->block && taking == 2)
    {
      /* a closing point leaves at e times its speed; one leaving already
       * may be pushed back to minus its speed at most (the time reverse
       * of a bounce), so no impulse adds energy */
      double b1 = (1.0 + (speed[0] < 0.0 ? k->restitution : 1.0)) * speed[0];
      double b2 = (1.0 + (speed[1] < 0.0 ? k->restitution : 1.0)) * speed[1];
      if (!contact_lcp2 (k->k11, k->k12, k->k22, b1, b2, &lambda[0], &lambda[1]))
        lambda[0] = lambda[1] = 0.0;
    }
  else
    {
      /* one at a time: the deepest-closing first */
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          double vn = contact_speed (a, b, p->normal, p->rn_a, p->rn_b) + relative_fall (a, b, p->normal, ctx) * t;
          lambda[j] = takes_impact (p) && vn < 0.0 ? -(1.0 + k->restitution) * vn * p->normal_mass : 0.0;
          contact_push (a, b, p->normal, p->rn_a, p->rn_b, lambda[j]);
        }
      for (j = 0; j < k->count; ++j)
        contact_push (a, b, k->points[j].normal, k->points[j].rn_a, k->points[j].rn_b, -lambda[j]);
    }
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      if (lambda[j] == 0.0)
        continue;
      contact_push (a, b, p->normal, p->rn_a, p->rn_b, lambda[j]);
      p->total_impulse += lambda[j];
      p->impact_moment += lambda[j] * t;
    }
  impact_friction (k, a, b, ctx, t, lambda);
  shifts[k->a].p = v2_mad (shifts[k->a].p, -t, v2_sub (a->v, va));
  shifts[k->a].a -= (a->w - wa) * t;
  shifts[k->b].p = v2_mad (shifts[k->b].p, -t, v2_sub (b->v, vb));
  shifts[k->b].a -= (b->w - wb) * t;
  shifts[k->a].at = shifts[k->b].at = t;
  /* the bounce is done: the end of the step does not bounce its points
   * again, nor does a sub-step's first push count as its meeting */
  for (j = 0; j < k->count; ++j)
    if (takes_impact (&k->points[j]) && k->points[j].normal_mass > 0.0)
      {
        k->points[j].approach = 0.0;
        k->points[j].in_impact = IMPACT_BOUNCED;
      }
  k->met = 1;
  return 1;
}

/* Contact k's points after a touch took those of `taken` (touch_points,
 * a bit each): the others take no part in its impact (one that bounced
 * earlier in the step is done), and its matrix is its points' now. */
static void touch_taken (contact *k, uint32_t taken, const solver_body *a, const solver_body *b)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    if (!(taken & (1u << j)))
      k->points[j].in_impact = k->points[j].in_impact == IMPACT_BOUNCED ? IMPACT_DONE
                               : k->points[j].in_impact == 1           ? 0
                                                                        : k->points[j].in_impact;
  pair_matrix (k, a, b);
}

/* The points of an impact on several contacts of one pair of bodies
 * (impact_group_event), and each one's own. */
typedef struct group_point {
  contact *k;
  contact_point *p;
  double fall;   /* its relative_fall times t */
  double target; /* the normal speed it may leave with, at least */
  double lambda;
} group_point;

/* The size of the terms a group point's distance from its target sums
 * (contact_speed, its fall and its target): what its rounding scales with. */
static double speed_terms (const solver_body *a, const solver_body *b, const contact_point *p, const group_point *g)
{
  return fabs (a->v.x) + fabs (a->v.y) + fabs (b->v.x) + fabs (b->v.y) + fabs (a->w * p->rn_a) + fabs (b->w * p->rn_b)
         + fabs (g->fall) + fabs (g->target);
}

/* The impact at time t of a pair of bodies that meets through the `count`
 * contacts of `group` at once (the first, the one whose impact it is; the
 * others the contacts of its pair of bodies whose pieces are within the
 * slop of touching then, whose points of the touch touch_points took): as
 * one contact's two points are one block (impact_event), all of their
 * points together. Each closing point leaves at e times the speed it met
 * with, no faster where the others' impulses push it off; one already
 * leaving is pushed back to minus its speed at most (the time reverse of a
 * bounce, so no impulse adds energy): the impulses lambda >= 0 of that
 * complementarity problem, found by projected Gauss-Seidel passes on the
 * fixed targets until every point meets its target. Taken one contact
 * after the other (the sequential model), an H landing flat on its two
 * feet would leave turning, the first foot's bounce tipping it onto the
 * second. The same for one contact of more than two points (count 1: the
 * vertex-edge method's concave outline, both feet in one contact).
 * Otherwise as impact_event: friction, the totals, the shifts. The passes
 * stop as IMPACT_GROUP_TOLERANCE says, and take from `work`, what the run
 * of the impacts has left of IMPACT_GROUP_WORK. Returns whether it acted. */
static int impact_group_event (contact *const *group, int32_t count, solver_body *a, solver_body *b,
                               impact_shift *shifts, const step_context *ctx, double t, double tol, int64_t *work)
{
  group_point g[IMPACT_GROUP_MAX * MANIFOLD_MAX_POINTS];
  vec2 va = a->v, vb = b->v;
  double wa = a->w, wb = b->w, scale = 0.0;
  int32_t i, j, m, n = 0, pass, passes, closing = 0;
  for (m = 0; m < count; ++m)
    for (j = 0; j < group[m]->count; ++j)
      {
        contact *k = group[m];
        contact_point *p = &k->points[j];
        double speed;
        if (!takes_impact (p) || p->normal_mass == 0.0)
          continue;
        g[n].k = k, g[n].p = p, g[n].lambda = 0.0;
        g[n].fall = relative_fall (a, b, p->normal, ctx) * t;
        speed = contact_speed (a, b, p->normal, p->rn_a, p->rn_b) + g[n].fall;
        g[n].target = speed < 0.0 ? -k->restitution * speed : -speed;
        scale = fabs (speed) > scale ? fabs (speed) : scale;
        closing |= speed < -(tol + impact_threshold (ctx, p->normal));
        ++n;
      }
  if (!closing)
    return 0;
  passes = *work / n < IMPACT_GROUP_PASSES ? (int32_t) (*work / n) : IMPACT_GROUP_PASSES;
  passes = passes > 1 ? passes : 1;
  for (pass = 0; pass < passes; ++pass)
    {
      double residual = 0.0;
      for (i = 0; i < n; ++i)
        {
          contact_point *p = g[i].p;
          double vn = contact_speed (a, b, p->normal, p->rn_a, p->rn_b) + g[i].fall;
          double next = g[i].lambda + (g[i].target - vn) * p->normal_mass;
          next = next > 0.0 ? next : 0.0;
          contact_push (a, b, p->normal, p->rn_a, p->rn_b, next - g[i].lambda);
          g[i].lambda = next;
        }
      /* how far the points are from their targets now (below one with an
       * impulse, short of it without), beyond the rounding of their speeds */
      for (i = 0; i < n; ++i)
        {
          contact_point *p = g[i].p;
          double off = contact_speed (a, b, p->normal, p->rn_a, p->rn_b) + g[i].fall - g[i].target;
          off = (g[i].lambda > 0.0 ? fabs (off) : -off) - IMPACT_GROUP_ROUNDING * speed_terms (a, b, p, &g[i]);
          residual = off > residual ? off : residual;
        }
      if (!(residual > IMPACT_GROUP_TOLERANCE * scale))
        break;
    }
  *work -= (int64_t) (pass < passes ? pass + 1 : passes) * n;
  for (m = 0; m < count; ++m)
    {
      contact *k = group[m];
      double lambda[MANIFOLD_MAX_POINTS] = {0.0, 0.0, 0.0, 0.0};
      for (i = 0; i < n; ++i)
        if (g[i].k == k)
          {
            lambda[g[i].p - k->points] = g[i].lambda;
            g[i].p->total_impulse += g[i].lambda;
            g[i].p->impact_moment += g[i].lambda * t;
          }
      impact_friction (k, a, b, ctx, t, lambda);
      for (j = 0; j < k->count; ++j)
        if (takes_impact (&k->points[j]) && k->points[j].normal_mass > 0.0)
          {
            k->points[j].approach = 0.0;
            k->points[j].in_impact = IMPACT_BOUNCED;
          }
      k->met = 1;
    }
  shifts[group[0]->a].p = v2_mad (shifts[group[0]->a].p, -t, v2_sub (a->v, va));
  shifts[group[0]->a].a -= (a->w - wa) * t;
  shifts[group[0]->b].p = v2_mad (shifts[group[0]->b].p, -t, v2_sub (b->v, vb));
  shifts[group[0]->b].a -= (b->w - wb) * t;
  shifts[group[0]->a].at = shifts[group[0]->b].at = t;
  return 1;
}

/* The contacts of contact `index`'s pair of bodies (a row of the list,
 * contact.c) that meet with it at time t: seeded at t, or their pieces
 * within the slop of touching then (the bodies in their flight since the
 * impacts, impact_shift), their points of that touch taken (touch_points);
 * into group after the contact itself, at most IMPACT_GROUP_MAX in all.
 * Returns how many. */
static int32_t impact_group (carom_world *world, int32_t index, const step_context *ctx, double t, contact **group)
{
  contacts *c = &world->contacts;
  contact *k = &c->list[index];
  const body *ba = &world->bodies[k->a], *bb = &world->bodies[k->b];
  solver_body *a = &world->solver_bodies[k->a], *b = &world->solver_bodies[k->b];
  int32_t lo = index, hi = index + 1, i, n = 1;
  group[0] = k;
  while (lo > 0 && c->list[lo - 1].a == k->a && c->list[lo - 1].b == k->b)
    --lo;
  while (hi < c->count && c->list[hi].a == k->a && c->list[hi].b == k->b)
    ++hi;
  for (i = lo; i < hi && n < IMPACT_GROUP_MAX; ++i)
    {
      contact *o = &c->list[i];
      uint32_t taken;
      vec2 axis;
      if (o == k || o->count == 0 || o->restitution == 0.0)
        continue;
      if (!(o->pending && o->impact_at == t)
          && !(contact_separation_at (world, o, toi_pose (world, o->a, a, ctx, t, &world->impact_shifts[o->a]),
                                      toi_pose (world, o->b, b, ctx, t, &world->impact_shifts[o->b]), &axis)
               <= o->slop))
        continue;
      impact_keep (world, o);
      taken = touch_points (world, o, ba, bb, a, b, ctx, t, NULL, world->impact_shifts, 0, 0);
      if (!taken)
        continue;
      touch_taken (o, taken, a, b);
      group[n++] = o;
    }
  return n;
}

/* Contact k's next touch within the step after an impact at t changed its
 * bodies' velocities (its own, or one passed on through its bodies): the
 * time of impact from t in their flight since (impact_shift), from a moment
 * after t when k itself just struck (its points leave; at t they still
 * touch). A touch takes its points (touch_points: the deepest in a slot
 * that has not bounced, if there is one; the bounced points of the other
 * slots take no part in it) and makes k a seed at that time; no touch
 * takes k's seed back, if it had one. Returns the time, or a negative. */
static double impact_again (carom_world *world, contact *k, const step_context *ctx, double t, int struck)
{
  const body *ba = &world->bodies[k->a], *bb = &world->bodies[k->b];
  solver_body *a = &world->solver_bodies[k->a], *b = &world->solver_bodies[k->b];
  double from = struck ? t + REIMPACT_DELAY * ctx->dt : t, at;
  vec2 axis;
  uint32_t taken;
  int32_t j, first = 0;
  /* no bounce to search for, or searched enough: the sub-steps take it as
   * any contact (TOI_APART would leave it without impulse for the rest of
   * the step) */
  if (k->restitution == 0.0 || k->count == 0 || k->reimpacts >= REIMPACT_MAX)
    return TOI_UNKNOWN;
  /* struck at the start while overlapping: still overlapping after it */
  for (j = 0; j < k->count && struck && t == 0.0; ++j)
    if (k->points[j].depth > 0.0)
      return TOI_UNKNOWN;
  impact_keep (world, k);
  k->reimpacts++;
  at = toi_first_touch (world, k, a, b, ctx, from, ctx->dt, world->impact_shifts, &axis);
  if (at < 0.0)
    return at;
  for (j = k->count - 1; j >= 0; --j)
    if (k->points[j].in_impact != IMPACT_BOUNCED && k->points[j].in_impact != IMPACT_DONE)
      first = j;
  taken = touch_points (world, k, ba, bb, a, b, ctx, at, &axis, world->impact_shifts, first, 0);
  if (!taken)
    return -1.0;
  touch_taken (k, taken, a, b);
  return at;
}

/* How many other moving bodies body i touched at detection (a contact with
 * some point within its slop). */
static int32_t touching_contacts (const contacts *c, const solver_body *sb, int32_t i, const int32_t *start,
                                  const int32_t *adj)
{
  int32_t e, j, n = 0;
  for (e = start[i]; e < start[i + 1]; ++e)
    {
      const contact *o = &c->list[adj[e]];
      if (sb[o->a].im == 0.0 || sb[o->b].im == 0.0)
        continue;
      for (j = 0; j < o->count; ++j)
        if (o->points[j].depth >= -o->slop)
          {
            ++n;
            break;
          }
    }
  return n;
}

/* Whether neither moving body of contact k touched more than
 * REIMPACT_DEGREE other moving bodies at detection: impacts in turn are
 * looked for where bodies meet one or two others at a time (a row, a gas,
 * a body and a wall or floor); within a packed cluster, where every impact
 * would send all its neighbours searching, they are left to the
 * sub-steps. */
static int sparse (const contacts *c, const contact *k, const solver_body *sb, const int32_t *start,
                   const int32_t *adj)
{
  return (sb[k->a].im == 0.0 || touching_contacts (c, sb, k->a, start, adj) <= REIMPACT_DEGREE)
         && (sb[k->b].im == 0.0 || touching_contacts (c, sb, k->b, start, adj) <= REIMPACT_DEGREE);
}

/* Seed `i` at time at into the queue seeds[head..n), in time order (ties
 * after those already there); the taken part before head is dropped when
 * the room (cap) runs out. */
static void seed_insert (contacts *c, int32_t *seeds, int32_t *head, int32_t *n, int32_t cap, int32_t i, double at)
{
  int32_t j;
  if (*n == cap)
    {
      memmove (seeds, seeds + *head, (size_t) (*n - *head) * sizeof *seeds);
      *n -= *head;
      *head = 0;
    }
  for (j = (*n)++; j > *head && c->list[seeds[j - 1]].impact_at > at; --j)
    seeds[j] = seeds[j - 1];
  seeds[j] = i;
  c->list[i].impact_at = at;
  c->list[i].pending = 1;
}

static void seed_remove (contacts *c, int32_t *seeds, int32_t head, int32_t *n, int32_t i)
{
  int32_t j, o = head;
  for (j = head; j < *n; ++j)
    if (seeds[j] != i)
      seeds[o++] = seeds[j];
  *n = o;
  c->list[i].pending = 0;
}

/* Whether new contact k (contacts_after_impacts), whose search from `from`
 * found no touch ahead, touches already at `from`: its pieces met before
 * the last impact of one of its bodies, in a flight that impact then
 * changed (contact_impacts then runs the step's impacts again). */
static int met_before (const carom_world *world, const contact *k, const step_context *ctx, double from, double at)
{
  const solver_body *sb = world->solver_bodies;
  vec2 axis;
  if (at != TOI_UNKNOWN || k->restitution == 0.0 || k->count == 0 || !(from > 0.0))
    return 0;
  return contact_separation_at (world, k,
                                toi_pose (world, k->a, &sb[k->a], ctx, from, &world->impact_shifts[k->a]),
                                toi_pose (world, k->b, &sb[k->b], ctx, from, &world->impact_shifts[k->b]), &axis)
         <= TOI_TOUCH * k->slop;
}

/* One run of the step's impacts (contact_impacts). With `may_stop`, returns
 * 1 as soon as a pair that the impacts brought together is found to have
 * met before the last impact of one of its bodies (met_before): the impacts
 * after that meeting assumed a flight that did not happen, and the run
 * stops there. Else 0, the run complete. */
static int impacts_run (carom_world *world, const step_context *ctx, int may_stop)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  impact_shift *shifts = world->impact_shifts;
  int32_t *seeds = world->restitution_list, *work = world->batch_scratch, *events = world->impact_events;
  int32_t *start = NULL, *adj = NULL;
  int32_t i, j, m, n = 0, head = 0, round = 0, passes = 0, members;
  contact *group[IMPACT_GROUP_MAX];
  double fastest = 0.0, tol;
  int64_t group_work = IMPACT_GROUP_WORK;
  c->impacts = 0;
  for (i = 0; i <= world->slot_count; ++i)
    shifts[i].p = v2 (0.0, 0.0), shifts[i].a = 0.0, shifts[i].at = 0.0;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      double at;
      if (!impact_seed (k, ctx, &at))
        continue;
      for (j = 0; j < k->count; ++j)
        fastest = fmax (fastest, -k->points[j].approach);
      /* in the order they happen (insertion: ties keep list order) */
      seed_insert (c, seeds, &head, &n, c->count, i, at);
    }
  if (n == 0)
    return 0;
  tol = RESTITUTION_TOLERANCE * fastest;
  solver_contact_adjacency (world, &start, &adj, NULL);
  while (head < n)
    {
      /* the impact, then the impacts it makes through the bodies it
       * touches, all at its moment, until nothing there closes (a work
       * list of contacts, each in it once at a time: a ring of c->count) */
      int32_t seed = seeds[head++];
      double t = c->list[seed].impact_at;
      int32_t ring = 0, queued = 1, tried = 0, limit = IMPACT_MAX_EVENTS * (c->count + 1), acted = 0, cand = 0;
      c->list[seed].pending = 0;
      ++round;
      work[0] = seed;
      c->list[seed].queued = 1;
      while (queued > 0 && tried < limit)
        {
          contact *k = &c->list[work[ring]];
          int32_t e, side, index = work[ring];
          ring = (ring + 1) % c->count;
          --queued;
          k->queued = 0;
          ++tried;
          impact_keep (world, k);
          members = impact_group (world, index, ctx, t, group);
          if (!(members > 1 || k->count > 2
                    ? impact_group_event (group, members, &sb[k->a], &sb[k->b], shifts, ctx, t, tol, &group_work)
                    : impact_event (k, &sb[k->a], &sb[k->b], shifts, ctx, t, tol)))
            continue;
          ++c->impacts;
          for (m = 0; m < members; ++m)
            {
              int32_t at = (int32_t) (group[m] - c->list);
              if (group[m]->event_round != round)
                events[acted++] = at;
              group[m]->event_round = round;
              if (m > 0 && group[m]->pending)
                seed_remove (c, seeds, head, &n, at);
            }
          for (side = 0; side < 2; ++side)
            {
              int32_t body = side ? k->b : k->a;
              if (sb[body].im == 0.0)
                continue;
              for (e = start[body]; e < start[body + 1]; ++e)
                {
                  contact *o = &c->list[adj[e]];
                  if (o->queued || !impact_passes (world, o, ctx, t))
                    continue;
                  o->queued = 1;
                  work[(ring + queued) % c->count] = adj[e];
                  ++queued;
                }
            }
        }
      while (queued > 0) /* the limit cut it short */
        {
          c->list[work[ring]].queued = 0;
          ring = (ring + 1) % c->count;
          --queued;
        }
      /* what these impacts set moving may strike again within the step:
       * the contacts they acted on and the bouncy contacts of their moving
       * bodies (the work list, now free, holds them) */
      for (i = 0; i < acted; ++i)
        {
          contact *k = &c->list[events[i]];
          int32_t side, e;
          if (!k->queued && sparse (c, k, sb, start, adj))
            k->queued = 1, work[cand++] = events[i];
          for (side = 0; side < 2; ++side)
            {
              int32_t body = side ? k->b : k->a;
              if (sb[body].im == 0.0)
                continue;
              for (e = start[body]; e < start[body + 1]; ++e)
                if (!c->list[adj[e]].queued && c->list[adj[e]].restitution > 0.0
                    && sparse (c, &c->list[adj[e]], sb, start, adj))
                  c->list[adj[e]].queued = 1, work[cand++] = adj[e];
            }
        }
      for (i = 0; i < cand; ++i)
        {
          contact *k = &c->list[work[i]];
          double at;
          k->queued = 0;
          at = impact_again (world, k, ctx, t, k->event_round == round);
          if (k->pending && (at >= 0.0 || at == TOI_APART))
            seed_remove (c, seeds, head, &n, work[i]);
          if (at >= 0.0)
            seed_insert (c, seeds, &head, &n, c->count, work[i], at);
          else if (at == TOI_APART)
            {
              impact_keep (world, k);
              impact_inert (k);
            }
        }
      if (head == n && passes < AFTER_IMPACT_PASSES)
        {
          /* bodies the impacts set moving faster than their detection
           * looked ahead for: their new pairs, met in turn */
          int32_t first = contacts_after_impacts (world, ctx), m;
          ++passes;
          if (first < c->count)
            {
              contact_prepare_from (world, ctx, first);
              solver_contact_adjacency (world, &start, &adj, NULL);
              for (m = first; m < c->count; ++m)
                {
                  contact *k = &c->list[m];
                  double from = fmax (shifts[k->a].at, shifts[k->b].at), at;
                  k->queued = 0;
                  at = impact_again (world, k, ctx, from, 0);
                  if (may_stop && met_before (world, k, ctx, from, at))
                    return 1;
                  if (at >= 0.0)
                    seed_insert (c, seeds, &head, &n, c->count, m, at);
                  else if (at == TOI_APART)
                    {
                      impact_keep (world, k);
                      impact_inert (k);
                    }
                }
            }
        }
    }
  /* what the end of the step bounces (contact_restitution) is measured on
   * one common state, for e = 1 to keep the energy: now the one after the
   * impacts */
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          if (p->in_impact != IMPACT_BOUNCED && p->in_impact != IMPACT_DONE)
            p->approach = contact_speed (&sb[k->a], &sb[k->b], p->normal, p->rn_a, p->rn_b);
        }
    }
  return 0;
}

/* What a replay of the step's impacts starts from: each body's velocity and
 * spin before any impact, and each contact an impact changed as
 * contact_prepare left it, kept when first changed (impact_keep), with its
 * points. */
typedef struct impact_saved {
  vec2 v;
  double w;
} impact_saved;

int contact_impacts_reserve (carom_world *world)
{
  const contacts *c = &world->contacts;
  return mem_reserve (&world->allocator, (void **) &world->impact_saved, &world->impact_saved_cap,
                      world->slot_count + 1, sizeof (impact_saved))
         && mem_reserve (&world->allocator, (void **) &world->saved_contacts, &world->saved_contacts_cap,
                         c->room_count, sizeof (contact))
         && mem_reserve (&world->allocator, (void **) &world->saved_points, &world->saved_points_cap,
                         c->room_points, sizeof (contact_point));
}

void contact_impacts_destroy (carom_world *world)
{
  mem_free (&world->allocator, world->impact_saved, (size_t) world->impact_saved_cap * sizeof (impact_saved));
  mem_free (&world->allocator, world->saved_contacts, (size_t) world->saved_contacts_cap * sizeof (contact));
  mem_free (&world->allocator, world->saved_points, (size_t) world->saved_points_cap * sizeof (contact_point));
  world->impact_saved = NULL;
  world->saved_contacts = NULL;
  world->saved_points = NULL;
  world->impact_saved_cap = world->saved_contacts_cap = world->saved_points_cap = 0;
}

/* The impacts of the step run once more when the first run found a pair it
 * brought together meeting before the last impact of one of its bodies
 * (impacts_run): from the state before any impact, with that pair's
 * contact now among the step's from the start, so its meeting comes in its
 * turn. At most this many runs again. */
#define IMPACT_REPLAYS 1

void contact_impacts (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  impact_saved *saved = world->impact_saved;
  int32_t count = c->count, cold = c->cold_count;
  int32_t bouncy = c->bouncy_count, i, replays;
  c->impacts = 0;
  if (c->bouncy_count == 0)
    return;
  /* (the room for it was kept with the room for contacts after impacts,
   * which bouncy contacts always have: solver_reserve) */
  for (i = 0; i <= world->slot_count; ++i)
    saved[i].v = sb[i].v, saved[i].w = sb[i].w;
  c->kept = c->kept_points = 0;
  for (replays = 0; impacts_run (world, ctx, replays < IMPACT_REPLAYS); ++replays)
    {
      int32_t first = count;
      /* back to before the impacts: the bodies' velocities, the contacts
       * they changed, and every contact's place in the impacts' order; the
       * contacts found after the impacts stay, set up again for the
       * velocities before them */
      for (i = 0; i <= world->slot_count; ++i)
        sb[i].v = saved[i].v, sb[i].w = saved[i].w;
      impact_restore (world);
      for (i = 0; i < count; ++i)
        {
          contact *k = &c->list[i];
          k->impact_at = k->touch_at = -1.0;
          k->pending = k->queued = k->reimpacts = 0;
          k->event_round = -1;
        }
      c->cold_count = cold, c->bouncy_count = bouncy;
      world->level_count = -1;
      contact_prepare_from (world, ctx, first);
      count = c->count;
      cold = c->cold_count, bouncy = c->bouncy_count;
    }
}

/* Whether a point takes part in restitution: some impulse of the step acted
 * on it, and it met the other body faster than the threshold, or was
 * leaving it faster than that and was pushed back by impacts elsewhere (a
 * row or a cluster struck at once). Either way its target is eq. 3.18: it
 * may end no slower than e times its normal speed before the step,
 * reversed. At every point that carries impulse, that is what keeps an
 * elastic cluster's energy: the impulses then change it by
 * sum_i j_i (v_i,before + v_i,after) / 2 = 0. */
static int struck (const contact_point *p, double threshold)
{
  return p->total_impulse > 0.0 && (p->approach < -threshold || p->approach > threshold);
}

/* The restitution problem of a two-point contact, exactly: the totals of
 * the step's impulses x >= 0 with K x + b >= 0, complementary, where b is
 * the error from the targets with the current totals taken back out. */
static int restitution_pair (solver_body *a, solver_body *b, contact *k)
{
  contact_point *p1 = &k->points[0], *p2 = &k->points[1];
  double x1, x2;
  double b1 = contact_speed (a, b, p1->normal, p1->rn_a, p1->rn_b) + k->restitution * p1->approach - p1->after
              - (k->k11 * p1->total_impulse + k->k12 * p2->total_impulse);
  double b2 = contact_speed (a, b, p2->normal, p2->rn_a, p2->rn_b) + k->restitution * p2->approach - p2->after
              - (k->k12 * p1->total_impulse + k->k22 * p2->total_impulse);
  if (!k->block || !contact_lcp2 (k->k11, k->k12, k->k22, b1, b2, &x1, &x2))
    return 0;
  apply_normal (a, b, p1, x1 - p1->total_impulse, 0.0, 1);
  apply_normal (a, b, p2, x2 - p2->total_impulse, 0.0, 1);
  return 1;
}

/* One restitution pass over contact k; returns the largest change of a
 * point's normal speed it made. The impulses it adds count towards the
 * step's totals, never towards what the contact carries to the next step
 * (normal_impulse): the bounce is an event of this step, and warm starting
 * it again would push bodies that already fly apart. */
static double restitution_pass (solver_body *a, solver_body *b, contact *k, double threshold)
{
  double most = 0.0;
  int32_t j;
  if (k->count == 2 && struck (&k->points[0], threshold) && struck (&k->points[1], threshold))
    {
      double t1 = k->points[0].total_impulse, t2 = k->points[1].total_impulse;
      if (restitution_pair (a, b, k))
        {
          double d1 = k->points[0].total_impulse - t1, d2 = k->points[1].total_impulse - t2;
          double v1 = fabs (k->k11 * d1 + k->k12 * d2), v2 = fabs (k->k12 * d1 + k->k22 * d2);
          return v1 > v2 ? v1 : v2;
        }
    }
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      double vn, acc, d;
      if (!struck (p, threshold))
        continue;
      vn = contact_speed (a, b, p->normal, p->rn_a, p->rn_b);
      acc = p->total_impulse - p->normal_mass * (vn + k->restitution * p->approach - p->after);
      if (acc < 0.0)
        acc = 0.0;
      d = p->normal_mass > 0.0 ? fabs (acc - p->total_impulse) / p->normal_mass : 0.0;
      most = d > most ? d : most;
      apply_normal (a, b, p, acc - p->total_impulse, 0.0, 1);
    }
  return most;
}

void contact_restitution (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t *list = world->restitution_list;
  double threshold = ctx->restitution_threshold, fastest = 0.0;
  int32_t i, j, it, n = 0;
  for (i = 0; i < c->count; ++i)
    {
      const contact *k = &c->list[i];
      int any = 0;
      if (k->restitution == 0.0)
        continue;
      for (j = 0; j < k->count; ++j)
        if (struck (&k->points[j], threshold))
          {
            any = 1;
            fastest = fabs (k->points[j].approach) > fastest ? fabs (k->points[j].approach) : fastest;
          }
      if (any)
        list[n++] = i;
    }
  for (it = 0; it < RESTITUTION_MAX_ITERATIONS && n > 0; ++it)
    {
      double most = 0.0;
      for (i = 0; i < n; ++i)
        {
          contact *k = &c->list[list[i]];
          double d = restitution_pass (&sb[k->a], &sb[k->b], k, threshold);
          most = d > most ? d : most;
        }
      if (most <= RESTITUTION_TOLERANCE * fastest)
        break;
    }
}

/* An impact met within the step (a point apart at detection and struck,
 * faster than resting contact ever approaches) happened at one moment, toi, with lever arms of that moment: its
 * total impulse P changes the velocities then, and moves the bodies by
 * P (dt - toi) / m by the end of the step. The sub-steps applied it in parts
 * at other moments (the approach stopped at the sub-step of meeting, the
 * bounce at the end), and moved the bodies by their moment, the sum of
 * lambda (dt - t) over the parts, instead. The difference is made up here,
 * on the positions alone: the bodies end where the exact event leaves
 * them, with the velocities it leaves them (no energy changes), and the
 * impulse then conserves angular momentum about any point, as the event
 * does. Only bouncy contacts need it: without restitution the speculative
 * solve already stops the approach exactly where the bodies meet. */
/* A body some contact acts on moves by symplectic Euler in every sub-step
 * (gravity_drift_velocity), which takes it g h^2 / 2 further along gravity
 * per sub-step than free flight: a contact that holds it takes that back,
 * but a body that flew free until an impact within the step and was held by
 * nothing at detection ends g h dt / 2 too far. Once per body. */
static void impact_drift (solver_body *b, const step_context *ctx)
{
  if (b->moves != MOVES_DYNAMIC || (b->constrained & (CONSTRAINED_HELD | CONSTRAINED_DRIFT_FIXED)))
    return;
  b->constrained |= CONSTRAINED_DRIFT_FIXED;
  b->dp = v2_mad (b->dp, -0.5 * ctx->dt, ctx->kick);
}

void contact_time_of_impact (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  /* contact_impacts applied each impact at the start of the step, which
   * moved the bodies by P dt / m by its end, where the event at t moves
   * them P (dt - t) / m: the difference, P t / m, back (the shift, which
   * sums it over the body's impacts) */
  if (c->impacts > 0)
    for (i = 0; i < world->slot_count; ++i)
      {
        sb[i].dp = v2_add (sb[i].dp, world->impact_shifts[i].p);
        sb[i].da += world->impact_shifts[i].a;
      }
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      for (j = 0; j < k->count && c->impacts > 0; ++j)
        if (k->points[j].impact_moment != 0.0 && k->points[j].toi >= 0.0)
          {
            impact_drift (a, ctx);
            impact_drift (b, ctx);
          }
      if (k->restitution == 0.0)
        continue; /* the approach stopped at the meeting: already exact */
      for (j = 0; j < k->count; ++j)
        {
          const contact_point *p = &k->points[j];
          double late = ctx->dt - p->toi, dn, dt_;
          vec2 t;
          if (p->toi < 0.0 || !struck (p, ctx->restitution_threshold))
            continue;
          dn = p->total_impulse * late - p->normal_moment;
          dt_ = p->tangent_total * late - p->tangent_moment;
          t = v2_perp (p->normal);
          a->dp = v2_sub (a->dp, v2_add (v2_scale (p->normal, a->im * dn), v2_scale (t, a->im * dt_)));
          a->da -= a->ii * (p->rn_a * dn + p->rt_a * dt_);
          b->dp = v2_add (b->dp, v2_add (v2_scale (p->normal, b->im * dn), v2_scale (t, b->im * dt_)));
          b->da += b->ii * (p->rn_b * dn + p->rt_b * dt_);
          impact_drift (a, ctx);
          impact_drift (b, ctx);
        }
    }
}
