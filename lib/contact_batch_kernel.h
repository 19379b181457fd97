/* The batch kernels of contact_batch.h, written once over KERNEL_WIDTH
 * lanes in the operations of batch_lanes.h (which the including file
 * defines, as that file says).
 *
 * A batch has BATCH_LANES (eight) lanes. A kernel of four walks it in two
 * groups of four, lanes 0-3 then 4-7 (o, the group's first lane, offsets
 * every array it reads), and leaves a group with no contact (a batch's
 * unused lanes are its last); one of eight takes the batch at once (o is
 * 0). Within a batch no two lanes share a body that moves, and bodies that
 * do not move keep their velocities to the bit (solver.c's gather; the
 * impulses and arms being finite, which the world's checks keep): so
 * either walk gives the same bits.
 *
 * The equations are those of contact_solver.c, whose comments say why:
 * eq. 3.23 with e = 0 per point, the 2x2 block of a two-point face, Coulomb
 * friction, and the split-impulse push-out. */

#include "batch_lanes.h"

/* The masses of a batch's lanes. */
typedef struct KERNEL (mass) {
  wide im_a, ii_a, im_b, ii_b;
} KERNEL (mass);

KERNEL_FN KERNEL (mass) KERNEL (masses) (const contact_batch *c, int o)
{
  KERNEL (mass) m;
  m.im_a = W_LOAD (c->im_a + o);
  m.ii_a = W_LOAD (c->ii_a + o);
  m.im_b = W_LOAD (c->im_b + o);
  m.ii_b = W_LOAD (c->ii_b + o);
  return m;
}

/* an impulse lambda along d: B gets +lambda d, A -lambda d, as contact_push */
KERNEL_FN void KERNEL (push) (KERNEL (lanes) *a, KERNEL (lanes) *b, const KERNEL (mass) *m, wide dx, wide dy, wide ra_d,
                             wide rb_d, wide lambda)
{
  wide sa = W_MUL (W_NEG (m->im_a), lambda), sb = W_MUL (m->im_b, lambda);
  a->vx = W_ADD (a->vx, W_MUL (sa, dx));
  a->vy = W_ADD (a->vy, W_MUL (sa, dy));
  a->w = W_SUB (a->w, W_MUL (W_MUL (m->ii_a, ra_d), lambda));
  b->vx = W_ADD (b->vx, W_MUL (sb, dx));
  b->vy = W_ADD (b->vy, W_MUL (sb, dy));
  b->w = W_ADD (b->w, W_MUL (W_MUL (m->ii_b, rb_d), lambda));
}

/* The same on the lanes of groups g (M_GROUPS) alone. */
KERNEL_FN void KERNEL (push_in) (wmask g, KERNEL (lanes) *a, KERNEL (lanes) *b, const KERNEL (mass) *m, wide dx,
                                wide dy, wide ra_d, wide rb_d, wide lambda)
{
  wide sa = W_MUL (W_NEG (m->im_a), lambda), sb = W_MUL (m->im_b, lambda);
  a->vx = W_MERGE (g, W_ADD (a->vx, W_MUL (sa, dx)), a->vx);
  a->vy = W_MERGE (g, W_ADD (a->vy, W_MUL (sa, dy)), a->vy);
  a->w = W_MERGE (g, W_SUB (a->w, W_MUL (W_MUL (m->ii_a, ra_d), lambda)), a->w);
  b->vx = W_MERGE (g, W_ADD (b->vx, W_MUL (sb, dx)), b->vx);
  b->vy = W_MERGE (g, W_ADD (b->vy, W_MUL (sb, dy)), b->vy);
  b->w = W_MERGE (g, W_ADD (b->w, W_MUL (W_MUL (m->ii_b, rb_d), lambda)), b->w);
}

/* the separation of point p now, lanes o on */
KERNEL_FN wide KERNEL (separation) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, const batch_point *p, int o)
{
  return KERNEL (separation_of) (a, b, p->ra_x + o, p->ra_y + o, p->rb_x + o, p->rb_y + o, p->nx + o, p->ny + o,
                                 p->adjusted + o);
}

/* contact_lcp2 on every lane, with the inverses set up once per step
 * (contact_batch.c): the four cases in its order, the first that holds
 * taken. Returns the lanes where one holds. */
KERNEL_FN wmask KERNEL (lcp2) (const contact_batch *c, int o, wide b1, wide b2, wide *x1, wide *x2)
{
  wide zero = W_SET1 (0.0), k12 = W_LOAD (c->two.k12 + o);
  wide y1 = W_NEG (W_ADD (W_MUL (W_LOAD (c->two.i11 + o), b1), W_MUL (W_LOAD (c->two.i12 + o), b2)));
  wide y2 = W_NEG (W_ADD (W_MUL (W_LOAD (c->two.i12 + o), b1), W_MUL (W_LOAD (c->two.i22 + o), b2)));
  wmask both = M_AND (M_GT (W_LOAD (c->two.block + o), zero), M_AND (M_GE (y1, zero), M_GE (y2, zero)));
  wide z1 = W_NEG (W_MUL (b1, W_LOAD (c->p0.normal_mass + o)));
  wmask first = M_AND (M_GE (z1, zero), M_GE (W_ADD (W_MUL (k12, z1), b2), zero));
  wide z2 = W_NEG (W_MUL (b2, W_LOAD (c->two.p1.normal_mass + o)));
  wmask second = M_AND (M_GE (z2, zero), M_GE (W_ADD (W_MUL (k12, z2), b1), zero));
  wmask neither = M_AND (M_GE (b1, zero), M_GE (b2, zero));
  *x1 = W_SEL (both, y1, W_SEL (first, z1, zero));
  *x2 = W_SEL (both, y2, W_SEL (first, zero, W_SEL (second, z2, zero)));
  return M_OR (M_OR (both, first), M_OR (second, neither));
}

/* The normal impulses of a batch: both points at once where the lane is a
 * block and the 2x2 problem has a consistent case, else one after the
 * other. `use` masks the lanes that solve at all; `bias` is -target speed. */
KERNEL_FN void KERNEL (normal) (const contact_batch *c, int o, KERNEL (lanes) *a, KERNEL (lanes) *b,
                                const KERNEL (mass) *m, const wide *bias, wide *x, wmask use)
{
  const batch_point *p0 = &c->p0, *p1 = &c->two.p1;
  wide zero = W_SET1 (0.0);
  wide n0x = W_LOAD (p0->nx + o), n0y = W_LOAD (p0->ny + o), n1x = W_LOAD (p1->nx + o), n1y = W_LOAD (p1->ny + o);
  wide r0a = W_LOAD (p0->rn_a + o), r0b = W_LOAD (p0->rn_b + o), r1a = W_LOAD (p1->rn_a + o),
       r1b = W_LOAD (p1->rn_b + o);
  wide k11 = W_LOAD (c->two.k11 + o), k12 = W_LOAD (c->two.k12 + o), k22 = W_LOAD (c->two.k22 + o);
  wide y0, y1, acc, d;
  wide b0 = W_SUB (W_ADD (KERNEL (speed) (a, b, n0x, n0y, r0a, r0b), bias[0]), W_ADD (W_MUL (k11, x[0]), W_MUL (k12, x[1])));
  wide b1 = W_SUB (W_ADD (KERNEL (speed) (a, b, n1x, n1y, r1a, r1b), bias[1]), W_ADD (W_MUL (k12, x[0]), W_MUL (k22, x[1])));
  wmask ok = M_AND (M_AND (KERNEL (lcp2) (c, o, b0, b1, &y0, &y1), M_GT (W_LOAD (c->two.pair + o), zero)), use);
  wmask one = M_ANDNOT (use, ok);
  /* a part no lane of a group takes is skipped (on every path alike: M_ANY
   * is exact) */
  wmask g = M_GROUPS (ok);
  if (M_ANY (g))
    {
      KERNEL (push_in) (g, a, b, m, n0x, n0y, r0a, r0b, W_SEL (ok, W_SUB (y0, x[0]), zero));
      KERNEL (push_in) (g, a, b, m, n1x, n1y, r1a, r1b, W_SEL (ok, W_SUB (y1, x[1]), zero));
      x[0] = W_SEL (ok, y0, x[0]);
      x[1] = W_SEL (ok, y1, x[1]);
    }
  g = M_GROUPS (one);
  if (M_ANY (g))
    {
      acc = W_MAX (W_SUB (x[0], W_MUL (W_LOAD (p0->normal_mass + o), W_ADD (KERNEL (speed) (a, b, n0x, n0y, r0a, r0b), bias[0]))), zero);
      d = W_SEL (one, W_SUB (acc, x[0]), zero);
      KERNEL (push_in) (g, a, b, m, n0x, n0y, r0a, r0b, d);
      x[0] = W_SEL (one, acc, x[0]);
      acc = W_MAX (W_SUB (x[1], W_MUL (W_LOAD (p1->normal_mass + o), W_ADD (KERNEL (speed) (a, b, n1x, n1y, r1a, r1b), bias[1]))), zero);
      d = W_SEL (one, W_SUB (acc, x[1]), zero);
      KERNEL (push_in) (g, a, b, m, n1x, n1y, r1a, r1b, d);
      x[1] = W_SEL (one, acc, x[1]);
    }
}

/* The normal impulses of a batch whose lanes have one point each: what
 * KERNEL (normal) does on such lanes (none is a block), without the second
 * point's zeros; on the lanes of groups g (M_GROUPS (use)) alone. */
KERNEL_FN void KERNEL (normal1) (const contact_batch *c, int o, KERNEL (lanes) *a, KERNEL (lanes) *b,
                                 const KERNEL (mass) *m, const wide *bias, wide *x, wmask use, wmask g)
{
  const batch_point *p0 = &c->p0;
  wide zero = W_SET1 (0.0);
  wide n0x = W_LOAD (p0->nx + o), n0y = W_LOAD (p0->ny + o), r0a = W_LOAD (p0->rn_a + o), r0b = W_LOAD (p0->rn_b + o);
  wide acc = W_MAX (W_SUB (x[0], W_MUL (W_LOAD (p0->normal_mass + o), W_ADD (KERNEL (speed) (a, b, n0x, n0y, r0a, r0b), bias[0]))), zero);
  KERNEL (push_in) (g, a, b, m, n0x, n0y, r0a, r0b, W_SEL (use, W_SUB (acc, x[0]), zero));
  x[0] = W_SEL (use, acc, x[0]);
}

/* The warm start of lanes o on of one batch of np-point lanes. */
KERNEL_FN void KERNEL (warm_start_batch) (contact_batch *c, int o, solver_body *sb, int np)
{
  KERNEL (lanes) a, b;
  KERNEL (mass) m = KERNEL (masses) (c, o);
  int j;
  KERNEL (gather) (sb, c->a + o, &a, 0);
  KERNEL (gather) (sb, c->b + o, &b, 0);
  for (j = 0; j < np; ++j)
    {
      batch_point *p = BATCH_POINT (c, j);
      wide nx = W_LOAD (p->nx + o), ny = W_LOAD (p->ny + o);
      KERNEL (push) (&a, &b, &m, nx, ny, W_LOAD (p->rn_a + o), W_LOAD (p->rn_b + o), W_LOAD (p->normal_impulse + o));
      W_STORE (p->total + o, W_ADD (W_LOAD (p->total + o), W_LOAD (p->normal_impulse + o)));
      KERNEL (push) (&a, &b, &m, W_NEG (ny), nx, W_LOAD (p->rt_a + o), W_LOAD (p->rt_b + o),
                     W_LOAD (p->tangent_impulse + o));
    }
  KERNEL (scatter) (sb, c->a + o, &a, 0);
  KERNEL (scatter) (sb, c->b + o, &b, 0);
}

/* Each group of lanes of batch c that the kernel takes at once: from lane
 * 0, KERNEL_WIDTH lanes at a time, while the group has a contact. */
#define KERNEL_GROUP_EACH(c, o)                                                                                    \
  for ((o) = 0; (o) < BATCH_LANES && ((o) == 0 || (c)->contact[o] >= 0); (o) += KERNEL_WIDTH)

static KERNEL_ATTR void KERNEL (contact_batch_warm_start) (contact_batch *c, int32_t n, solver_body *sb)
{
  int32_t i;
  int o;
  for (i = 0; i < n; ++i, c = batch_next (c))
    KERNEL_GROUP_EACH (c, o)
      {
        if (c->points > 1)
          KERNEL (warm_start_batch) (c, o, sb, 2);
        else
          KERNEL (warm_start_batch) (c, o, sb, 1);
      }
}

/* The separation of both points of a batch now (the solve's speculative
 * bias and the push-out's overlap both start from it). */
KERNEL_FN void KERNEL (separations) (const contact_batch *c, int o, const KERNEL (lanes) *a, const KERNEL (lanes) *b,
                                     wide *s, int np)
{
  s[0] = KERNEL (separation) (a, b, &c->p0, o);
  s[1] = np > 1 ? KERNEL (separation) (a, b, &c->two.p1, o) : W_SET1 (0.0);
}

/* One solve pass of a batch on its bodies' velocities a, b, the points
 * separated by s: the normal impulses, then friction. */
KERNEL_FN void KERNEL (solve_lanes) (contact_batch *c, int o, KERNEL (lanes) *a, KERNEL (lanes) *b,
                                     const KERNEL (mass) *m, const wide *s, wide ih, int np)
{
  wide zero = W_SET1 (0.0);
  wide bias[2], x[2], before[2], friction = W_LOAD (c->friction + o);
  wmask all = M_GE (zero, zero);
  int j;
  for (j = 0; j < np; ++j)
    {
      /* a speculative point may close its gap within the sub-step */
      bias[j] = W_SEL (M_GT (s[j], zero), W_MUL (s[j], ih), zero);
      x[j] = before[j] = W_LOAD (BATCH_POINT (c, j)->normal_impulse + o);
    }
  if (np > 1)
    KERNEL (normal) (c, o, a, b, m, bias, x, all);
  else
    KERNEL (normal1) (c, o, a, b, m, bias, x, all, all);
  for (j = 0; j < np; ++j)
    {
      batch_point *p = BATCH_POINT (c, j);
      wide tx = W_NEG (W_LOAD (p->ny + o)), ty = W_LOAD (p->nx + o), rta = W_LOAD (p->rt_a + o),
           rtb = W_LOAD (p->rt_b + o);
      wide old = W_LOAD (p->tangent_impulse + o), limit = W_MUL (friction, x[j]);
      wide acc = W_SUB (old, W_MUL (W_LOAD (p->tangent_mass + o), KERNEL (speed) (a, b, tx, ty, rta, rtb)));
      acc = W_MIN (W_MAX (acc, W_NEG (limit)), limit);
      KERNEL (push) (a, b, m, tx, ty, rta, rtb, W_SUB (acc, old));
      W_STORE (p->tangent_impulse + o, acc);
      W_STORE (p->normal_impulse + o, x[j]);
      W_STORE (p->total + o, W_ADD (W_LOAD (p->total + o), W_SUB (x[j], before[j])));
    }
}

/* One push-out pass of a batch on its bodies' pseudo-velocities a, b, the
 * points separated by s. Returns 0 where no lane had overlap to push out
 * nor a push so far (the bodies keep their pseudo-velocities). */
KERNEL_FN int KERNEL (push_lanes) (contact_batch *c, int o, KERNEL (lanes) *a, KERNEL (lanes) *b,
                                   const KERNEL (mass) *m, const wide *s, wide rate, int first, int np)
{
  wide zero = W_SET1 (0.0), bias[2], x[2], slop = W_LOAD (c->slop + o), fastest = W_NEG (W_LOAD (c->max_push + o));
  wmask use = M_GT (zero, zero);
  int j;
  for (j = 0; j < np; ++j)
    {
      /* overlap beyond the slop, a fraction of it per sub-step, no faster
       * than max_push */
      wide e = W_ADD (s[j], slop);
      bias[j] = W_SEL (M_GE (e, zero), zero, W_MAX (W_MUL (rate, e), fastest));
      /* last sub-step's push was dropped with the move */
      x[j] = first ? zero : W_LOAD (BATCH_POINT (c, j)->push_impulse + o);
      use = M_OR (use, M_OR (M_LT (bias[j], zero), M_GT (x[j], zero)));
    }
  if (M_ANY (use))
    {
      if (np > 1)
        KERNEL (normal) (c, o, a, b, m, bias, x, use);
      else
        KERNEL (normal1) (c, o, a, b, m, bias, x, use, M_GROUPS (use));
    }
  for (j = 0; j < np; ++j)
    W_STORE (BATCH_POINT (c, j)->push_impulse + o, x[j]);
  return M_ANY (use);
}

/* A batch's bodies (their velocities, or pseudo-velocities) into a, b and
 * its points' separations into s: what every pass starts from. Returns its
 * masses. */
KERNEL_FN KERNEL (mass) KERNEL (load_batch) (const contact_batch *c, int o, const solver_body *sb, KERNEL (lanes) *a,
                                             KERNEL (lanes) *b, wide *s, int pseudo, int np)
{
  KERNEL (gather) (sb, c->a + o, a, pseudo);
  KERNEL (gather) (sb, c->b + o, b, pseudo);
  KERNEL (separations) (c, o, a, b, s, np);
  return KERNEL (masses) (c, o);
}

/* One solve pass of lanes o on of one batch of np-point lanes. */
KERNEL_FN void KERNEL (solve_batch) (contact_batch *c, int o, solver_body *sb, wide ih, int np)
{
  KERNEL (lanes) a, b;
  wide s[2];
  KERNEL (mass) m = KERNEL (load_batch) (c, o, sb, &a, &b, s, 0, np);
  KERNEL (solve_lanes) (c, o, &a, &b, &m, s, ih, np);
  KERNEL (scatter) (sb, c->a + o, &a, 0);
  KERNEL (scatter) (sb, c->b + o, &b, 0);
}

static KERNEL_ATTR void KERNEL (contact_batch_solve) (contact_batch *c, int32_t n, solver_body *sb, double inv_h)
{
  wide ih = W_SET1 (inv_h);
  int32_t i;
  int o;
  for (i = 0; i < n; ++i, c = batch_next (c))
    KERNEL_GROUP_EACH (c, o)
      {
        if (c->points > 1)
          KERNEL (solve_batch) (c, o, sb, ih, 2);
        else
          KERNEL (solve_batch) (c, o, sb, ih, 1);
      }
}

/* One push-out pass of lanes o on of one batch of np-point lanes. */
KERNEL_FN void KERNEL (push_out_batch) (contact_batch *c, int o, solver_body *sb, wide rate, int first, int np)
{
  KERNEL (lanes) a, b;
  wide s[2];
  KERNEL (mass) m = KERNEL (load_batch) (c, o, sb, &a, &b, s, 1, np);
  if (!KERNEL (push_lanes) (c, o, &a, &b, &m, s, rate, first, np))
    return;
  KERNEL (scatter) (sb, c->a + o, &a, 1);
  KERNEL (scatter) (sb, c->b + o, &b, 1);
}

static KERNEL_ATTR void KERNEL (contact_batch_push_out) (contact_batch *c, int32_t n, solver_body *sb, double push_rate,
                                                  int first)
{
  wide rate = W_SET1 (push_rate);
  int32_t i;
  int o;
  for (i = 0; i < n; ++i, c = batch_next (c))
    KERNEL_GROUP_EACH (c, o)
      {
        if (c->points > 1)
          KERNEL (push_out_batch) (c, o, sb, rate, first, 2);
        else
          KERNEL (push_out_batch) (c, o, sb, rate, first, 1);
      }
}

/* A solve pass and the sub-step's first push-out pass in one walk over the
 * batches: the push-out reads the pseudo-velocities and the motion since
 * the step began, which the solve leaves alone, so each batch is loaded
 * once, its separations computed once, and the results are those of the
 * two passes one after the other. */
KERNEL_FN void KERNEL (solve_push_out_batch) (contact_batch *c, int o, solver_body *sb, wide ih, wide rate, int np)
{
  KERNEL (lanes) a, b, pa, pb;
  KERNEL (mass) m = KERNEL (masses) (c, o);
  wide s[2];
  KERNEL (gather) (sb, c->a + o, &a, 0);
  KERNEL (gather) (sb, c->b + o, &b, 0);
  /* the pseudo-velocities before the velocities are written back: a
   * load overlapping a store just made would wait for it */
  pa = a, pb = b;
  KERNEL (gather_pseudo) (sb, c->a + o, &pa);
  KERNEL (gather_pseudo) (sb, c->b + o, &pb);
  KERNEL (separations) (c, o, &a, &b, s, np);
  KERNEL (solve_lanes) (c, o, &a, &b, &m, s, ih, np);
  KERNEL (scatter) (sb, c->a + o, &a, 0);
  KERNEL (scatter) (sb, c->b + o, &b, 0);
  if (!KERNEL (push_lanes) (c, o, &pa, &pb, &m, s, rate, 1, np))
    return;
  KERNEL (scatter) (sb, c->a + o, &pa, 1);
  KERNEL (scatter) (sb, c->b + o, &pb, 1);
}

static KERNEL_ATTR void KERNEL (contact_batch_solve_push_out) (contact_batch *c, int32_t n, solver_body *sb, double inv_h,
                                                        double push_rate)
{
  wide ih = W_SET1 (inv_h), rate = W_SET1 (push_rate);
  int32_t i;
  int o;
  for (i = 0; i < n; ++i, c = batch_next (c))
    KERNEL_GROUP_EACH (c, o)
      {
        if (c->points > 1)
          KERNEL (solve_push_out_batch) (c, o, sb, ih, rate, 2);
        else
          KERNEL (solve_push_out_batch) (c, o, sb, ih, rate, 1);
      }
}
