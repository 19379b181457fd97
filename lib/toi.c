/* Time of impact with rotation (toi.h).
 *
 * The separation g(t) of two pieces in free flight (contact_separation_at:
 * the largest over the edge normals for polygons, the distance less the
 * radius with a circle) is the gap between their projections on an axis n,
 * is a lower bound of their distance and is 0 exactly when they touch.
 * Held fixed in the world, the gap along n can close no faster than the
 * centres approach along n plus each body's spin times its reach (the
 * turning of a shape moves its extent along a fixed direction no faster):
 * conservative advancement by the time that bound takes to close g never
 * passes the first touch, and a bound that never closes it ends the search
 * at once. A polygon's face is also followed as it turns with its body
 * (face_time): a pair that leaves an impact slowly while spinning closes
 * fast along any fixed axis (the face's far end swings in) but not on its
 * own face, and would otherwise be crept away from by advances as small
 * as its gap. A secant through its last two trials, or two, four or eight
 * times as far, usually steps past the touch at once (it may step over a
 * touch and a parting within that stretch, which a grazing corner could
 * make), and then the touch is bracketed and found by regula falsi (the
 * Illinois variant) to a separation of TOI_TOUCH times the pair's slop (near
 * the rounding of the coordinates). A search from the start of the step
 * begins from the detection's own measure of the pieces (the SAT's
 * separation and face at the same poses), which it would only repeat. */
#include "toi.h"

#include "world.h"

/* At most this many advancements, and this many regula falsi trials. With
 * continuous collision (the world's, or a bullet's) the search goes on
 * longer: a body that leaves an impact spinning fast creeps away from the
 * touch, each advance bounded by its whole spin, so the gap grows only by
 * a fixed factor per advance (about 1.13 for a body leaving at 2 m/s
 * spinning at 40 rad/s); from the 1e-11 m just after the impact, 128
 * advances reach 1e-4 m and give up, leaving a corner swinging in to the
 * sub-steps (the elastic gas: 9 cm deep; 1024: it is found). A slower
 * impact creeps slower still: a triangle spinning at 20 rad/s that leaves
 * at 0.2 m/s gains about 1.5% per advance, and 1024 advances reached 4e-5 s
 * past the impact (the gap 9e-6 m), where the search gave up and its next
 * corner sank 9 mm; 4096 reach the end of the step at that rate. */
#define TOI_MAX_ADVANCES 128
#define TOI_MAX_ADVANCES_SWEPT 4096
/* The secant's trials each advancement: its point, then twice, four and
 * eight times as far. */
#define TOI_SECANT_TRIALS 4
#define TOI_MAX_REFINES 64
/* A bound on the gap that stays above this fraction of the slop through
 * the step is a verdict of apart (well clear of rounding; nearer, the
 * search decides). */
#define TOI_APART_CLEAR 1e-6

xform toi_pose (const carom_world *world, int32_t i, const solver_body *sb, const step_context *ctx, double t,
                const impact_shift *shift)
{
  const body *B = &world->bodies[i];
  double turned = sb->w * t;
  xform x;
  x.p = v2_mad (B->p, t, sb->v);
  if (shift)
    x.p = v2_add (x.p, shift->p), turned += shift->a;
  if (sb->moves == MOVES_DYNAMIC)
    x.p = v2_mad (x.p, 0.5 * t * t, ctx->gravity);
  x.q = turned != 0.0 ? rot2_then (B->q, rot2_from_angle (turned)) : B->q;
  return x;
}

typedef struct toi_pair {
  const carom_world *world;
  const contact *k;
  const solver_body *a, *b;
  const step_context *ctx;
  const impact_shift *shift_a, *shift_b;
  double tol;
} toi_pair;

static double separation_axis (const toi_pair *p, double t, vec2 *axis)
{
  return contact_separation_at (p->world, p->k, toi_pose (p->world, p->k->a, p->a, p->ctx, t, p->shift_a),
                                toi_pose (p->world, p->k->b, p->b, p->ctx, t, p->shift_b), axis);
}

/* The same, and the face it was measured on. */
static double separation_face (const toi_pair *p, double t, vec2 *axis, contact_face *face)
{
  return contact_separation_face_at (p->world, p->k, toi_pose (p->world, p->k->a, p->a, p->ctx, t, p->shift_a),
                                     toi_pose (p->world, p->k->b, p->b, p->ctx, t, p->shift_b), axis, face);
}

#ifdef CAROM_DEBUG_CHECKS
#include <stdio.h>
#include <stdlib.h>
/* The test builds' check of separation_at_start: the detection's measure
 * is the one the search would make, to the bit. */
static void check_detected (const toi_pair *p, double s, vec2 axis, const contact_face *face)
{
  contact_face f;
  vec2 n;
  double measured = separation_face (p, 0.0, &n, &f);
  if (measured != s || n.x != axis.x || n.y != axis.y || f.ref != face->ref || f.edge != face->edge)
    {
      fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: the detection's separation is not the time of impact's at 0\n");
      abort ();
    }
}
#else
#define check_detected(p, s, axis, face) ((void) 0)
#endif

/* separation_face at the start of the step, where the bodies are as the
 * detection found them (no impact has moved them: no shifts): the SAT's
 * own measure there when it made one, which the search's first
 * measure would repeat (most searches end at their first advance, where
 * that measure was half their cost). */
static double separation_at_start (const toi_pair *p, vec2 *axis, contact_face *face)
{
  double s;
  if (!p->shift_a && !p->shift_b && contact_separation_face_detected (p->world, p->k, axis, face, &s))
    {
      check_detected (p, s, *axis, face);
      return s;
    }
  return separation_face (p, 0.0, axis, face);
}

/* How long after t two polygon pieces cannot touch, measured on the face
 * `face` of the reference piece (R, the body it belongs to) turning with
 * it, not held fixed in the world: while every vertex of the incident
 * piece (I) lies beyond the line of that face, the pieces are apart (both
 * convex). In R's frame a vertex of I sits at y = R^T u, u its offset from
 * R's centre in the world, and y'' = R^T (u'' - 2 w_R J u' - w_R^2 u) with
 * u' = v_I - v_R + w_I J r (r: the vertex's arm on I) and u'' = g_I - g_R -
 * w_I^2 r. So its gap beyond the face line closes at its rate now (the
 * material points' relative velocity along the face normal) less at most
 * C t^2 / 2, C = |g_I - g_R| + w_I^2 |r| + 2 |w_R| (|v_I - v_R| + |w_I| |r|)
 * + w_R^2 |u|, with |v_I - v_R| and |u| bounded over the rest of the step.
 * The fixed-axis bounds (closing_time, reach_time) take a turning face's
 * far end as closing on the other piece; here it does not move, so a pair
 * just apart after an impact, leaving slowly as it spins, is not crept
 * away from by tiny advances. The first vertex's root, or INFINITY. */
double toi_face_clear (const convex_piece *ref, int32_t edge, xform xr, vec2 vr, double wr, const convex_piece *inc,
                       xform xi, vec2 vi, double wi, double dg, double span)
{
  vec2 n = rot2_apply (xr.q, ref->normals[edge]);
  double at = v2_dot (n, v2_add (xr.p, rot2_apply (xr.q, ref->vertices[edge])));
  double dv = v2_len (v2_sub (vi, vr)) + dg * span, awr = fabs (wr), awi = fabs (wi), first = INFINITY;
  int32_t j;
  for (j = 0; j < inc->count; ++j)
    {
      vec2 r = rot2_apply (xi.q, inc->vertices[j]), x = v2_add (xi.p, r), u = v2_sub (x, xr.p);
      double gap = v2_dot (n, x) - at, lr = v2_len (r), moving = dv + awi * lr, tau;
      double rate = v2_dot (n, v2_sub (v2_add (vi, v2_scale (v2_perp (r), wi)), v2_add (vr, v2_scale (v2_perp (u), wr))));
      double curve = dg + awi * awi * lr + 2.0 * awr * moving + awr * awr * (v2_len (u) + moving * span);
      if (!(gap > 0.0))
        return 0.0;
      tau = contact_gap_root (gap, rate, curve);
      first = tau < first ? tau : first;
    }
  return first;
}

static double face_time (const toi_pair *p, const contact_face *face, double t, double t_max, vec2 ga, vec2 gb)
{
  const solver_body *R = face->side ? p->b : p->a, *I = face->side ? p->a : p->b;
  vec2 gr = face->side ? gb : ga, gi = face->side ? ga : gb;
  xform xr = toi_pose (p->world, face->side ? p->k->b : p->k->a, R, p->ctx, t, face->side ? p->shift_b : p->shift_a);
  xform xi = toi_pose (p->world, face->side ? p->k->a : p->k->b, I, p->ctx, t, face->side ? p->shift_a : p->shift_b);
  return toi_face_clear (face->ref, face->edge, xr, v2_mad (R->v, t, gr), R->w, face->inc, xi, v2_mad (I->v, t, gi),
                         I->w, v2_len (v2_sub (gi, gr)), t_max - t);
}

/* The touch within [lo, hi], apart at lo (slo > tol) along the axis
 * *axis, touching or overlapping at hi (shi <= 0); *axis follows lo. */
static double bracketed (const toi_pair *p, double lo, double slo, double hi, double shi, vec2 *axis)
{
  int side = 0, i;
  for (i = 0; i < TOI_MAX_REFINES; ++i)
    {
      double t = lo + slo * (hi - lo) / (slo - shi), s;
      vec2 n;
      if (!(t > lo && t < hi))
        t = 0.5 * (lo + hi);
      if (!(t > lo && t < hi))
        break; /* no double left between them */
      s = separation_axis (p, t, &n);
      if (s > p->tol)
        {
          lo = t, slo = s, *axis = n;
          if (side == 1)
            shi *= 0.5;
          side = 1;
        }
      else if (s <= 0.0)
        {
          hi = t, shi = s;
          if (side == -1)
            slo *= 0.5;
          side = -1;
        }
      else
        return t;
    }
  return lo;
}

/* The first time within [0, t_max] at which two circles of radii summing to
 * `reach`, centres d apart (B's less A's) and moving at v (B's velocity
 * less A's), meet, or -1 if they do not: |d + v t| = reach, the smaller
 * root (in the form that does not cancel). */
static double circles_meet (vec2 d, vec2 v, double reach, double t_max)
{
  double c = v2_dot (d, d) - reach * reach, dv = v2_dot (d, v), vv = v2_dot (v, v), disc, t;
  if (c <= 0.0)
    return 0.0;
  if (!(dv < 0.0))
    return -1.0; /* not closing */
  disc = dv * dv - vv * c;
  if (disc < 0.0)
    return -1.0; /* passing by */
  t = c / (sqrt (disc) - dv);
  return t <= t_max ? t : -1.0;
}

/* Whether the pieces stay apart along the fixed world axis n for a time
 * `span` from poses xa, xb: their gap along n is at least the centres' gap
 * along n less how far the pieces reach along it through any turn their
 * bodies can take in that time (contact_reach_along, |w| span each), and
 * the centres' gap grows as (n . v) t + (n . g) t^2 / 2 (v, g: B's velocity
 * and gravity less A's). Its least value, clear of the touch by more than
 * rounding, is a verdict for the price of two projections: most pairs that
 * only the turning of their bodies might bring together end here. */
static int fixed_axis_apart (const toi_pair *p, xform xa, xform xb, vec2 n, vec2 v, vec2 g, double span)
{
  double reach = contact_reach_along (p->world, p->k, xa.q, xb.q, n, fabs (p->a->w) * span, fabs (p->b->w) * span);
  double g0 = v2_dot (n, v2_sub (xb.p, xa.p)) - reach;
  double rate = v2_dot (n, v), curve = v2_dot (n, g);
  double least = g0 + span * (rate + 0.5 * curve * span), t;
  least = g0 < least ? g0 : least;
  t = curve > 0.0 ? -rate / curve : 0.0;
  if (t > 0.0 && t < span)
    {
      double at = g0 + t * (rate + 0.5 * curve * t);
      least = at < least ? at : least;
    }
  return least > TOI_APART_CLEAR * p->k->slop;
}

/* How long after t a gap s along the fixed axis n takes to close at the
 * fastest: the centres approach along n at -n . v (B's velocity less A's at
 * t), gaining -n . g per unit time at most, and the turning moves the
 * pieces' extents along n by `turn` per unit time at most: the first root
 * of s = c1 tau + c2 tau^2 / 2 (in the form that does not cancel), or
 * infinity when the bound never closes the gap. */
static double closing_time (double s, vec2 n, vec2 v, vec2 g, double turn)
{
  double c1 = turn - v2_dot (n, v), c2 = -v2_dot (n, g);
  if (c2 > 0.0)
    return 2.0 * s / (c1 + sqrt (c1 * c1 + 2.0 * c2 * s));
  return c1 > 0.0 ? s / c1 : INFINITY;
}

/* How long after t the pieces cannot touch, from their points' motion at
 * t along the fixed axis n (which their gap along n bounds from below):
 * each point moves along n at its rate now, and no faster away from that
 * than its acceleration allows, gravity plus w^2 times its body's reach.
 * Pieces of few points are taken pair by pair (the first pair that could
 * meet); else each point of one piece against how far the other piece can
 * reach along n by then (its extent and fastest rate now, and the same
 * bound), the later of the two pieces' first meetings. A second-order
 * bound: a corner leaving after an impact, or passing by, does not hold the
 * search back as the first-order one (closing_time) does. */
static double reach_time (const toi_pair *p, double t, vec2 n, vec2 ga, vec2 gb)
{
  const body *A = &p->world->bodies[p->k->a], *B = &p->world->bodies[p->k->b];
  xform xa = toi_pose (p->world, p->k->a, p->a, p->ctx, t, p->shift_a);
  xform xb = toi_pose (p->world, p->k->b, p->b, p->ctx, t, p->shift_b);
  vec2 va = v2_mad (p->a->v, t, ga), vb = v2_mad (p->b->v, t, gb);
  double curve = p->a->w * p->a->w * A->shape.bound_radius + p->b->w * p->b->w * B->shape.bound_radius
                 - v2_dot (n, v2_sub (gb, ga));
  double ea, ra, eb, rb, tb, ta, paired = contact_pieces_first_meeting (p->world, p->k, xa, va, p->a->w, xb, vb,
                                                                       p->b->w, n, curve);
  if (paired >= 0.0)
    return paired;
  contact_piece_envelope (p->world, p->k, 0, xa, va, p->a->w, n, &ea, &ra);
  contact_piece_envelope (p->world, p->k, 1, xb, vb, p->b->w, v2_neg (n), &eb, &rb);
  tb = contact_piece_first_reach (p->world, p->k, 1, xb, vb, p->b->w, v2_neg (n), ea, ra, curve);
  ta = contact_piece_first_reach (p->world, p->k, 0, xa, va, p->a->w, n, eb, rb, curve);
  return ta > tb ? ta : tb;
}

/* The vertex-edge method's whole outlines: no pieces named (-1), two
 * polygons. */
static int whole_outlines (const body *A, const body *B, const contact *k)
{
  return k->piece_a < 0 && k->piece_b < 0 && A->shape.kind == CAROM_SHAPE_POLYGON
         && B->shape.kind == CAROM_SHAPE_POLYGON;
}

/* Whole outlines of which one is concave (the vertex-edge method's): the
 * union of their convex pieces (shape.pieces), which first touch where the
 * first pair of pieces does. Each pair is searched as any pair of pieces,
 * no further than the earliest touch found so far; a pair that touches
 * already (or whose search ran out) leaves the whole unknown, as it would
 * leave itself. */
static double outlines_first_touch (const carom_world *world, const contact *k, const solver_body *a,
                                    const solver_body *b, const step_context *ctx, double t_from, double t_max,
                                    const impact_shift *shifts, vec2 *axis)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  contact pieces = *k;
  double first = TOI_APART;
  vec2 best = v2 (0.0, 0.0), n;
  int32_t i, j;
  pieces.separation_known = 0;
  for (i = 0; i < A->shape.piece_count; ++i)
    for (j = 0; j < B->shape.piece_count; ++j)
      {
        double t;
        pieces.piece_a = i, pieces.piece_b = j;
        t = toi_first_touch (world, &pieces, a, b, ctx, t_from, first > t_from ? first : t_max, shifts, &n);
        if (t == TOI_UNKNOWN)
          return TOI_UNKNOWN;
        if (t >= 0.0 && (first < 0.0 || t < first))
          first = t, best = n;
      }
  if (first >= 0.0 && axis)
    *axis = best;
  return first;
}

double toi_first_touch (const carom_world *world, const contact *k, const solver_body *a, const solver_body *b,
                        const step_context *ctx, double t_from, double t_max, const impact_shift *shifts, vec2 *axis)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  contact pieces;
  toi_pair p;
  vec2 ga = a->moves == MOVES_DYNAMIC ? ctx->gravity : v2 (0.0, 0.0);
  vec2 gb = b->moves == MOVES_DYNAMIC ? ctx->gravity : v2 (0.0, 0.0);
  vec2 v = v2_sub (b->v, a->v), g = v2_sub (gb, ga), n, ignored;
  contact_face face;
  double reach_a = A->shape.bound_radius, reach_b = B->shape.bound_radius;
  double turn = fabs (a->w) * reach_a + fabs (b->w) * reach_b;
  double t = t_from, s = 0.0;
  /* the reaches afresh: some callers ran no detection (tests/test_toi.c) */
  int i, advances = body_pair_swept (A, body_reach_uncapped (A, ctx->dt, ctx->accel), B,
                                     body_reach_uncapped (B, ctx->dt, ctx->accel), ctx->dt, ctx->accel, ctx->continuous)
                        ? TOI_MAX_ADVANCES_SWEPT
                        : TOI_MAX_ADVANCES;
  if (whole_outlines (A, B, k))
    {
      /* convex whole outlines: each is its single piece, the same surface,
       * whose separation and faces the search follows */
      if (!A->shape.convex || !B->shape.convex)
        return outlines_first_touch (world, k, a, b, ctx, t_from, t_max, shifts, axis);
      pieces = *k;
      pieces.piece_a = pieces.piece_b = 0;
      pieces.separation_known = 0;
      k = &pieces;
    }
  p.world = world, p.k = k, p.a = a, p.b = b, p.ctx = ctx;
  p.shift_a = shifts ? &shifts[k->a] : NULL;
  p.shift_b = shifts ? &shifts[k->b] : NULL;
  p.tol = TOI_TOUCH * k->slop;
  if (!axis)
    axis = &ignored;
  if (!(t_max > t))
    return TOI_UNKNOWN;
  {
    /* From where the bodies are at t_from, moving at vt, two verdicts that
     * cost less than a separation (neither calls pieces that touch now
     * apart). The bodies' bounding circles hold every piece at any angle:
     * no touch comes before they meet, none at all if they do not (what
     * gravity can bend their centres' path by, at most |g| span^2 / 2,
     * widens them). */
    xform xa = toi_pose (world, k->a, a, ctx, t, p.shift_a), xb = toi_pose (world, k->b, b, ctx, t, p.shift_b);
    vec2 vt = v2_mad (v, t, g);
    double span = t_max - t, meet, s0 = 0.0, t0 = t;
    /* a search again after an impact (t_from > 0) most often finds the
     * pieces still touching: that first */
    if (t_from > 0.0 && !((s = s0 = separation_face (&p, t, &n, &face)) > p.tol))
      return TOI_UNKNOWN;
    meet = circles_meet (v2_sub (xb.p, xa.p), vt, reach_a + reach_b + 0.5 * v2_len (g) * span * span, span);
    if (meet < 0.0 || fixed_axis_apart (&p, xa, xb, k->points[0].normal, vt, g, span))
      return TOI_APART;
    if (t_from == 0.0 && !((s = s0 = separation_at_start (&p, &n, &face)) > p.tol))
      return TOI_UNKNOWN;
    *axis = n;
    if (meet > 0.0)
      {
        t += meet;
        s = separation_face (&p, t, &n, &face);
        if (s <= 0.0)
          return bracketed (&p, t0, s0, t, s, axis);
        if (s <= p.tol)
          return t;
        *axis = n;
      }
  }
  for (i = 0; i < advances; ++i)
    {
      double first = closing_time (s, n, v2_mad (v, t, g), g, turn), sn, tn, second;
      /* the face's own bound first: past the step, no other is needed */
      if (face.ref)
        {
          double third = face_time (&p, &face, t, t_max, ga, gb);
          first = third > first ? third : first;
          if (!(t + first < t_max))
            return TOI_APART;
        }
      second = reach_time (&p, t, n, ga, gb);
      tn = t + (second > first ? second : first);
      if (!(tn < t_max))
        return TOI_APART; /* it cannot close the gap by then */
      sn = separation_face (&p, tn, &n, &face);
      if (sn <= 0.0)
        return bracketed (&p, t, s, tn, sn, axis);
      if (sn <= p.tol)
        return tn;
      *axis = n;
      if (sn < s)
        {
          /* where it would touch if it kept closing as over the last
           * advance: not safe to stand on, but overlapping there brackets
           * the touch */
          double step = sn * (tn - t) / (s - sn), ts, ss;
          int k;
          /* still apart there: a fall that slows (a corner turning away
           * as it nears), where advancing only creeps up on the touch;
           * twice, four and eight times as far bracket it */
          for (k = 0; k < TOI_SECANT_TRIALS; ++k, step *= 2.0)
            {
              ts = tn + step < t_max ? tn + step : t_max;
              ss = separation_axis (&p, ts, &ignored);
              if (ss <= 0.0)
                return bracketed (&p, tn, sn, ts, ss, axis);
              if (ts == t_max)
                break;
            }
        }
      t = tn, s = sn;
    }
  return TOI_UNKNOWN;
}
