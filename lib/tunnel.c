/* The last guard of continuous collision (tunnel.h).
 *
 * Speculative contacts and the time of impact meet a fast body where it
 * first touches what it strikes, and the step goes on from there with the
 * velocities the impact leaves. What they cannot see is a touch the step
 * itself brings about after that: a thin card spinning at 50 rad/s, struck
 * at one end by a wall with e = 0, leaves the impact turning at over 1000
 * rad/s about that end while its centre still moves at over 200 m/s, and its
 * other end swings through the wall within the same step. The sub-steps
 * follow each contact point with the lever arms of its touch, and a body
 * that turns by radians in a sub-step is not where those arms say.
 *
 * So the motion of the step is checked once more before the bodies take it,
 * for each contact of a dynamic body with a static piece. The body has
 * passed into the piece when its centre's path (from where it was to where
 * it would end) crosses into it from outside, since a body's centre lies
 * about its size (2 area / perimeter) inside its own surface; or when it
 * began the step apart from the piece or within the slop of it and would
 * end overlapping it by more than BODY_FAST_FRACTION of its size, deeper
 * than any contact the solver resolved leaves it. Neither can happen in a
 * step whose surface moves less than that (its motion plus its turn times
 * its reach), which most steps of most bodies do: those are not looked at.
 * The body then stops on its path (its start and end poses, the angle
 * turning in proportion) where it overlaps the piece by half the contact's
 * slop, found by bisection, and keeps its velocities: the next step meets
 * the static body as a contact. (Box2D v3 stops fast bodies at their time
 * of impact against static shapes in the same way; here it is a guard that
 * acts only where the contacts failed.) A body whose centre skirts a small
 * static piece can still cut through its edge within a step without going
 * deep into it; and two moving bodies are not guarded against each other. */
#include "tunnel.h"

#include "solver.h"
#include "world.h"

/* Bisection steps for the pose of the first overlap: the path's length
 * over 2^60, far below any slop. */
#define TUNNEL_REFINES 60
/* The body stops where the pieces overlap by this fraction of the slop:
 * within it, so the contact holds it there as resting, and clear of its
 * edge, so that the rounding of the pose it is put in does not leave it a
 * hair beyond the slop, where the next step's guard would not act. */
#define TUNNEL_STOP 0.5

/* The first t in [0, 1] at which the point c0 + t d enters the static piece
 * P placed at x; -1 when it never does within that span, or starts in it
 * (on its boundary counts as in). A polygon's edges are half-planes
 * n . (y - v) <= 0, clipped in turn (Cyrus-Beck); a circle's is the
 * smaller root of |c0 + t d - c| = r. */
static double segment_enters (const convex_piece *P, xform x, vec2 c0, vec2 d)
{
  vec2 c = xform_apply_inv (x, c0), e = rot2_apply_inv (x.q, d);
  double lo = 0.0, hi = 1.0;
  int32_t j, inside = 1;
  if (P->count == 0)
    {
      vec2 m = v2_sub (c, P->center);
      double cc = v2_dot (m, m) - P->radius * P->radius, me = v2_dot (m, e), ee = v2_dot (e, e), disc, t;
      if (!(cc > 0.0) || !(me < 0.0))
        return -1.0; /* in it already, or not closing on it */
      disc = me * me - ee * cc;
      if (!(disc >= 0.0))
        return -1.0;
      t = cc / (sqrt (disc) - me);
      return t <= 1.0 ? t : -1.0;
    }
  for (j = 0; j < P->count; ++j)
    {
      double num = v2_dot (P->normals[j], v2_sub (P->vertices[j], c)), den = v2_dot (P->normals[j], e);
      inside &= num >= 0.0;
      if (den == 0.0)
        {
          if (num < 0.0)
            return -1.0; /* along the edge, outside it */
          continue;
        }
      if (den < 0.0)
        lo = num / den > lo ? num / den : lo;
      else
        hi = num / den < hi ? num / den : hi;
      if (!(lo <= hi))
        return -1.0;
    }
  return inside ? -1.0 : lo;
}

/* Body B (its solver body s) placed a fraction t along its motion of the step. */
static xform along (const body *B, const solver_body *s, double t)
{
  xform x;
  x.p = v2_mad (B->p, t, s->dp);
  x.q = rot2_then (B->q, rot2_from_angle (s->da * t));
  return x;
}

void tunnel_guard (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  (void) ctx;
  for (i = 0; i < c->count; ++i)
    {
      const contact *k = &c->list[i];
      const body *S, *D;
      solver_body *m;
      int side; /* which is static */
      convex_piece circle;
      const convex_piece *P;
      xform xs, x0;
      vec2 axis;
      double enter, lo = 0.0, hi, deep;
      /* most contacts are between two bodies that are not static, and
       * most of the rest's bodies moved little: those are left first */
      if (world->bodies[k->a].type == CAROM_STATIC)
        side = 0;
      else if (world->bodies[k->b].type == CAROM_STATIC)
        side = 1;
      else
        continue;
      m = &sb[side ? k->a : k->b];
      if (m->moves != MOVES_DYNAMIC)
        continue;
      S = &world->bodies[side ? k->b : k->a];
      D = &world->bodies[side ? k->a : k->b];
      deep = BODY_FAST_FRACTION * D->shape.size;
      /* how far its surface moved: less than `deep`, and it can neither
       * have gone that deep nor crossed (its centre lies about its size
       * inside its surface) */
      if (!(v2_len (m->dp) + fabs (m->da) * D->shape.bound_radius > deep))
        continue;
      P = contact_piece (world, k, side, &circle);
      if (!P)
        continue; /* the vertex-edge method's whole outline: not convex */
      xs.p = S->p, xs.q = S->q;
      enter = segment_enters (P, xs, D->p, m->dp);
      if (enter >= 0.0)
        hi = enter;
      else
        {
          xform x1 = along (D, m, 1.0);
          if (!(contact_separation_at (world, k, side ? x1 : xs, side ? xs : x1, &axis) < -deep))
            continue;
          hi = 1.0;
        }
      x0.p = D->p, x0.q = D->q;
      if (!(contact_separation_at (world, k, side ? x0 : xs, side ? xs : x0, &axis) >= -k->slop))
        continue; /* deep in it from the start: the push-out's */
      for (j = 0; j < TUNNEL_REFINES; ++j)
        {
          double mid = 0.5 * (lo + hi);
          xform x = along (D, m, mid);
          if (!(mid > lo && mid < hi))
            break;
          if (contact_separation_at (world, k, side ? x : xs, side ? xs : x, &axis) >= -TUNNEL_STOP * k->slop)
            lo = mid;
          else
            hi = mid;
        }
      /* (not scaled by a 0, which an infinite motion would turn to NaN) */
      m->dp = lo > 0.0 ? v2_scale (m->dp, lo) : v2 (0.0, 0.0);
      m->da = lo > 0.0 ? m->da * lo : 0.0;
      m->dq = rot2_from_angle (m->da);
    }
}
