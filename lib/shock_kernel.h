/* The shock rows' kernel of shock_batch.h, written once over four lanes in
 * the operations of batch_lanes.h, which the including file includes first
 * (itself or by contact_batch_kernel.h), with KERNEL_WIDTH 4. Each lane does what shock.c's shock_row_solve does for
 * its row, in the same order of operations; its branches become masks:
 * a lane that shock_row_solve would leave takes an impulse of 0, and its
 * upper body is written back unchanged (by a select: adding a zero would
 * turn -0 into +0). */

/* a shock batch is one register of lanes */
typedef char KERNEL (shock_width)[KERNEL_WIDTH == SHOCK_LANES ? 1 : -1];

#ifdef CAROM_DEBUG_CHECKS
#include <stdio.h>
#include <stdlib.h>
#endif

/* The separation of point p now (contact_batch_kernel.h's separation_of). */
KERNEL_FN wide KERNEL (shock_separation) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, const shock_lane_point *p)
{
  return KERNEL (separation_of) (a, b, p->ra_x, p->ra_y, p->rb_x, p->rb_y, p->nx, p->ny, p->adjusted);
}

/* shock_gap: the separation over a sub-step where positive, else 0 */
KERNEL_FN wide KERNEL (shock_gap) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, const shock_lane_point *p, wide ih)
{
  wide zero = W_SET1 (0.0), s = KERNEL (shock_separation) (a, b, p);
  return W_SEL (M_GT (s, zero), W_MUL (s, ih), zero);
}

/* contact_lcp2 on every lane, its cases in its order by masks (a lane where
 * none holds takes 0, as contact_lcp2's caller then applies nothing). */
KERNEL_FN void KERNEL (shock_lcp2) (const shock_batch *c, wide b1, wide b2, wide *x1, wide *x2)
{
  wide zero = W_SET1 (0.0);
  wide k11 = W_LOAD (c->k11), k12 = W_LOAD (c->k12), k22 = W_LOAD (c->k22);
  wide det = W_SUB (W_MUL (k11, k22), W_MUL (k12, k12));
  wmask regular = M_GT (det, W_MUL (W_MUL (W_SET1 (1e-12), k11), k22));
  wide y1 = W_DIV (W_ADD (W_MUL (W_NEG (k22), b1), W_MUL (k12, b2)), det);
  wide y2 = W_DIV (W_SUB (W_MUL (k12, b1), W_MUL (k11, b2)), det);
  wmask both = M_AND (regular, M_AND (M_GE (y1, zero), M_GE (y2, zero)));
  wide z1 = W_DIV (W_NEG (b1), k11);
  wmask first = M_AND (M_GE (z1, zero), M_GE (W_ADD (W_MUL (k12, z1), b2), zero));
  wide z2 = W_DIV (W_NEG (b2), k22);
  wmask second = M_AND (M_GE (z2, zero), M_GE (W_ADD (W_MUL (k12, z2), b1), zero));
  *x1 = W_SEL (both, y1, W_SEL (first, z1, zero));
  *x2 = W_SEL (both, y2, W_SEL (first, zero, W_SEL (second, z2, zero)));
}

/* One point's impulse alone: -err / mass where err < 0 and mass > 0. */
KERNEL_FN wide KERNEL (shock_single) (wide err, wide mass)
{
  wide zero = W_SET1 (0.0);
  return W_SEL (M_AND (M_LT (err, zero), M_GT (mass, zero)), W_DIV (W_NEG (err), mass), zero);
}

KERNEL_FN void KERNEL (shock_batch) (shock_batch *c, int np, solver_body *sb, wide neg_tol, wide ih, int32_t moves)
{
  KERNEL (lanes) a, b, up;
  wide zero = W_SET1 (0.0), err[2], x[2];
  wmask below = M_LT (zero, zero), active;
  wmask on_a;
  int j;
  KERNEL (gather_velocities) (sb, c->a, &a, 0);
  KERNEL (gather_velocities) (sb, c->b, &b, 0);
  for (j = 0; j < np; ++j)
    {
      const shock_lane_point *p = &c->p[j];
      err[j] = KERNEL (speed) (&a, &b, W_LOAD (p->nx), W_LOAD (p->ny), W_LOAD (p->rn_a), W_LOAD (p->rn_b));
      below = M_OR (below, M_LT (err[j], neg_tol));
    }
  /* every lane within tolerance: the batch is left (exact on every path) */
  if (!M_ANY (below))
    return;
  KERNEL (gather_motion) (sb, c->a, &a);
  KERNEL (gather_motion) (sb, c->b, &b);
  if (c->gap_at != moves)
    {
      for (j = 0; j < np; ++j)
        W_STORE (c->p[j].gap, KERNEL (shock_gap) (&a, &b, &c->p[j], ih));
      c->gap_at = moves;
    }
#ifdef CAROM_DEBUG_CHECKS
  else
    for (j = 0; j < np; ++j)
      {
        double now[SHOCK_LANES];
        int i;
        W_STORE (now, KERNEL (shock_gap) (&a, &b, &c->p[j], ih));
        for (i = 0; i < SHOCK_LANES; ++i)
          if (now[i] != c->p[j].gap[i])
            {
              fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: shock propagation kept a gap the bodies moved from\n");
              abort ();
            }
      }
#endif
  active = M_LT (zero, zero);
  for (j = 0; j < np; ++j)
    {
      err[j] = W_ADD (err[j], W_LOAD (c->p[j].gap));
      active = M_OR (active, M_LT (err[j], neg_tol));
    }
  active = M_AND (active, below);
  if (!M_ANY (active))
    return;
  if (np == 2)
    {
      wide f1, f2;
      wmask face = M_GT (W_LOAD (c->face), zero);
      KERNEL (shock_lcp2) (c, err[0], err[1], &f1, &f2);
      x[0] = W_SEL (face, f1, KERNEL (shock_single) (err[0], W_LOAD (c->p[0].mass)));
      x[1] = W_SEL (face, f2, KERNEL (shock_single) (err[1], W_LOAD (c->p[1].mass)));
    }
  else
    x[0] = KERNEL (shock_single) (err[0], W_LOAD (c->p[0].mass));
  /* hold the lower body still: only the upper one takes the impulse */
  on_a = M_GT (W_LOAD (c->up_is_a), zero);
  up.vx = W_SEL (on_a, a.vx, b.vx);
  up.vy = W_SEL (on_a, a.vy, b.vy);
  up.w = W_SEL (on_a, a.w, b.w);
  for (j = 0; j < np; ++j)
    {
      const shock_lane_point *p = &c->p[j];
      wide xj = W_SEL (active, x[j], zero);
      wmask push = M_NE (xj, zero);
      wide s = W_MUL (W_LOAD (c->im_up), xj);
      up.vx = W_SEL (push, W_ADD (up.vx, W_MUL (s, W_LOAD (p->nx))), up.vx);
      up.vy = W_SEL (push, W_ADD (up.vy, W_MUL (s, W_LOAD (p->ny))), up.vy);
      up.w = W_SEL (push, W_ADD (up.w, W_MUL (W_LOAD (p->ang), xj)), up.w);
    }
  KERNEL (scatter) (sb, c->up, &up, 0);
}

/* static, unless the including file exports it (SHOCK_KERNEL_LINKAGE
 * empty) for another file's table of kernels */
#ifndef SHOCK_KERNEL_LINKAGE
#define SHOCK_KERNEL_LINKAGE static
#endif

SHOCK_KERNEL_LINKAGE KERNEL_ATTR void KERNEL (shock_batch_solve) (shock_batch *c, int32_t n, int points,
                                                               solver_body *sb, double tol, double inv_h,
                                                               int32_t moves)
{
  wide neg_tol = W_SET1 (-tol), ih = W_SET1 (inv_h);
  int32_t i;
  if (points == 2)
    for (i = 0; i < n; ++i)
      KERNEL (shock_batch) (&c[i], 2, sb, neg_tol, ih, moves);
  else
    for (i = 0; i < n; ++i)
      KERNEL (shock_batch) (&c[i], 1, sb, neg_tol, ih, moves);
}
