/* Time of impact with rotation (toi.h).
 *
 * The separation g(t) of two pieces in free flight (contact_separation_at:
 * the largest over the edge normals for polygons, the distance less the
 * radius with a circle) is a lower bound of their distance, falls no faster
 * than a bound mu on how fast any feature of one can approach the other,
 * and is 0 exactly when they touch. Conservative advancement, t += g / mu,
 * never passes the first touch; a secant through its last two trials, or
 * two, four or eight times as far, usually steps past it at once (it may
 * step over a touch and a parting within that stretch, which a grazing
 * corner could make),
 * and then the touch is bracketed and found
 * by regula falsi (the Illinois variant) to a separation of
 * TOI_TOUCH times the pair's slop (near the rounding of the coordinates). */
#include "toi.h"

#include "world.h"

/* Touching: a separation below this fraction of the pair's slop. */
#define TOI_TOUCH 1e-12
/* At most this many advancements, and this many regula falsi trials. */
#define TOI_MAX_ADVANCES 128
/* The secant's trials each advancement: its point, then twice, four and
 * eight times as far. */
#define TOI_SECANT_TRIALS 4
#define TOI_MAX_REFINES 64

xform toi_pose (const carom_world *world, int32_t i, const solver_body *sb, const step_context *ctx, double t)
{
  const body *B = &world->bodies[i];
  xform x;
  x.p = v2_mad (B->p, t, sb->v);
  if (sb->moves == MOVES_DYNAMIC)
    x.p = v2_mad (x.p, 0.5 * t * t, ctx->gravity);
  x.q = B->q;
  if (t != 0.0 && sb->w != 0.0)
    {
      rot2 turn = rot2_from_angle (sb->w * t);
      x.q.c = B->q.c * turn.c - B->q.s * turn.s;
      x.q.s = B->q.s * turn.c + B->q.c * turn.s;
    }
  return x;
}

typedef struct toi_pair {
  const carom_world *world;
  const contact *k;
  const solver_body *a, *b;
  const step_context *ctx;
  double tol;
} toi_pair;

static double separation_axis (const toi_pair *p, double t, int *axis)
{
  return contact_separation_at (p->world, p->k, toi_pose (p->world, p->k->a, p->a, p->ctx, t),
                                toi_pose (p->world, p->k->b, p->b, p->ctx, t), axis);
}

static double separation (const toi_pair *p, double t)
{
  int axis;
  return separation_axis (p, t, &axis);
}

/* The touch within [lo, hi], apart at lo (slo > tol), touching or
 * overlapping at hi (shi <= 0). */
static double bracketed (const toi_pair *p, double lo, double slo, double hi, double shi)
{
  int side = 0, i;
  for (i = 0; i < TOI_MAX_REFINES; ++i)
    {
      double t = lo + slo * (hi - lo) / (slo - shi), s;
      if (!(t > lo && t < hi))
        t = 0.5 * (lo + hi);
      if (!(t > lo && t < hi))
        break; /* no double left between them */
      s = separation (p, t);
      if (s > p->tol)
        {
          lo = t, slo = s;
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

double toi_first_touch (const carom_world *world, const contact *k, const solver_body *a, const solver_body *b,
                        const step_context *ctx, double t_max)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  toi_pair p;
  vec2 ga = a->moves == MOVES_DYNAMIC ? ctx->gravity : v2 (0.0, 0.0);
  vec2 gb = b->moves == MOVES_DYNAMIC ? ctx->gravity : v2 (0.0, 0.0);
  /* how fast the separation can fall (only the axis that gives it matters:
   * the largest of several falls no faster than the largest does): the
   * centres' relative speed, gravity included; along an edge normal of A,
   * B's turn at its reach and the turn of A's normal over the distance
   * from A's centre to B's far side (and the same with A and B exchanged);
   * for a distance, each body's turn at its reach */
  double lin = v2_len (v2_sub (b->v, a->v)) + v2_len (v2_sub (gb, ga)) * t_max;
  double wa = fabs (a->w), wb = fabs (b->w), reach_a = A->shape.bound_radius, reach_b = B->shape.bound_radius;
  double t = 0.0, s;
  int i, axis;
  p.world = world, p.k = k, p.a = a, p.b = b, p.ctx = ctx;
  p.tol = TOI_TOUCH * k->slop;
  s = separation_axis (&p, 0.0, &axis);
  if (!(s > p.tol) || !(t_max > 0.0))
    return TOI_UNKNOWN;
  for (i = 0; i < TOI_MAX_ADVANCES; ++i)
    {
      xform xa = toi_pose (world, k->a, a, ctx, t), xb = toi_pose (world, k->b, b, ctx, t);
      double d = v2_len (v2_sub (xb.p, xa.p)) + lin * (t_max - t), tn, sn;
      double ab = wb * reach_b + wa * (d + reach_b), ba = wa * reach_a + wb * (d + reach_a);
      double mu = lin + (axis == CONTACT_AXIS_A ? ab : axis == CONTACT_AXIS_B ? ba : wa * reach_a + wb * reach_b);
      if (!(mu > 0.0))
        return TOI_APART; /* neither moves */
      tn = t + s / mu;
      if (!(tn < t_max))
        return TOI_APART; /* it cannot close the gap by then */
      sn = separation_axis (&p, tn, &axis);
      if (sn <= 0.0)
        return bracketed (&p, t, s, tn, sn);
      if (sn <= p.tol)
        return tn;
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
              ss = separation (&p, ts);
              if (ss <= 0.0)
                return bracketed (&p, tn, sn, ts, ss);
              if (ts == t_max)
                break;
            }
        }
      t = tn, s = sn;
    }
  return TOI_UNKNOWN;
}
