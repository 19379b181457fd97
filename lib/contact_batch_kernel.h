/* The batch kernels of contact_batch.h, written once over four lanes.
 *
 * The including file defines the lanes (a type `wide` of four doubles, a
 * mask type `wmask`, the operations W_* and M_* below), KERNEL(name) to name
 * its copy of each function and KERNEL_ATTR for the attributes every
 * function of the copy needs. Every operation is one IEEE rounding (or
 * none), taken in the order written: the copies give the same bits.
 *
 *   W_LOAD(p) W_STORE(p, x) W_SET1(d)            four doubles
 *   W_ADD W_SUB W_MUL W_DIV W_NEG                arithmetic
 *   W_MAX(a, b)  a > b ? a : b    W_MIN(a, b)  a < b ? a : b   (per lane)
 *   M_GT M_GE M_LT M_NE(a, b) M_AND M_OR M_ANDNOT(m, n) (m and not n)
 *   W_SEL(m, a, b)  m ? a : b      M_ANY(m)  some lane of m is set (an int)
 *
 * The equations are those of contact_solver.c, whose comments say why:
 * eq. 3.23 with e = 0 per point, the 2x2 block of a two-point face, Coulomb
 * friction, and the split-impulse push-out. */

/* The helpers are inlined into each pass, where the point count is a
 * constant (1 or 2): each pass has a copy for each count. */
#ifdef __GNUC__
#define KERNEL_FN static inline __attribute__ ((always_inline)) KERNEL_ATTR
#else
#define KERNEL_FN static inline KERNEL_ATTR
#endif

typedef struct KERNEL (lanes) {
  wide vx, vy, w; /* velocity, or the push-out's pseudo-velocity */
  wide px, py;    /* displacement since the step began */
  wide qc, qs;    /* rotation since the step began */
} KERNEL (lanes);

#ifdef KERNEL_TRANSPOSE
/* Four bodies' rows of four doubles in, their columns out (and back). */
KERNEL_FN void KERNEL (transpose) (wide r0, wide r1, wide r2, wide r3, wide *c0, wide *c1, wide *c2, wide *c3)
{
  wide t0 = _mm256_unpacklo_pd (r0, r1), t1 = _mm256_unpackhi_pd (r0, r1);
  wide t2 = _mm256_unpacklo_pd (r2, r3), t3 = _mm256_unpackhi_pd (r2, r3);
  *c0 = _mm256_permute2f128_pd (t0, t2, 0x20);
  *c1 = _mm256_permute2f128_pd (t1, t3, 0x20);
  *c2 = _mm256_permute2f128_pd (t0, t2, 0x31);
  *c3 = _mm256_permute2f128_pd (t1, t3, 0x31);
}

/* solver_body begins with three rows of four doubles, v.x v.y w -,
 * pv.x pv.y pw -, dp.x dp.y dq.c dq.s (checked in contact_batch.c): the
 * velocities are the row at 0 (pseudo: at 4), the motion since the step
 * began the row at 8. */
KERNEL_FN void KERNEL (gather_velocities) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o, int pseudo)
{
  int at = pseudo ? 4 : 0;
  wide rest;
  KERNEL (transpose) (W_LOAD (&sb[idx[0]].v.x + at), W_LOAD (&sb[idx[1]].v.x + at), W_LOAD (&sb[idx[2]].v.x + at),
                      W_LOAD (&sb[idx[3]].v.x + at), &o->vx, &o->vy, &o->w, &rest);
}

KERNEL_FN void KERNEL (gather_motion) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o)
{
  KERNEL (transpose) (W_LOAD (&sb[idx[0]].v.x + 8), W_LOAD (&sb[idx[1]].v.x + 8), W_LOAD (&sb[idx[2]].v.x + 8),
                      W_LOAD (&sb[idx[3]].v.x + 8), &o->px, &o->py, &o->qc, &o->qs);
}

/* Lanes write back in order, the fourth double of each row 0; a body that
 * two lanes share does not move (it has no colour), and both write its
 * unchanged velocity. */
KERNEL_FN void KERNEL (scatter) (solver_body *sb, const int32_t *idx, const KERNEL (lanes) *o, int pseudo)
{
  double *b0 = &sb[idx[0]].v.x, *b1 = &sb[idx[1]].v.x, *b2 = &sb[idx[2]].v.x, *b3 = &sb[idx[3]].v.x;
  int at = pseudo ? 4 : 0;
  wide r0, r1, r2, r3;
  /* the row's fourth double is unused */
  KERNEL (transpose) (o->vx, o->vy, o->w, _mm256_setzero_pd (), &r0, &r1, &r2, &r3);
  W_STORE (b0 + at, r0);
  W_STORE (b1 + at, r1);
  W_STORE (b2 + at, r2);
  W_STORE (b3 + at, r3);
}
#else
/* The velocities (pseudo: the pseudo-velocities) of the lanes' bodies. */
KERNEL_FN void KERNEL (gather_velocities) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o, int pseudo)
{
  double t[3][BATCH_LANES];
  int i;
  for (i = 0; i < BATCH_LANES; ++i)
    {
      const solver_body *s = &sb[idx[i]];
      t[0][i] = pseudo ? s->pv.x : s->v.x;
      t[1][i] = pseudo ? s->pv.y : s->v.y;
      t[2][i] = pseudo ? s->pw : s->w;
    }
  o->vx = W_LOAD (t[0]);
  o->vy = W_LOAD (t[1]);
  o->w = W_LOAD (t[2]);
}

/* Their motion since the step began. */
KERNEL_FN void KERNEL (gather_motion) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o)
{
  double t[4][BATCH_LANES];
  int i;
  for (i = 0; i < BATCH_LANES; ++i)
    {
      const solver_body *s = &sb[idx[i]];
      t[0][i] = s->dp.x;
      t[1][i] = s->dp.y;
      t[2][i] = s->dq.c;
      t[3][i] = s->dq.s;
    }
  o->px = W_LOAD (t[0]);
  o->py = W_LOAD (t[1]);
  o->qc = W_LOAD (t[2]);
  o->qs = W_LOAD (t[3]);
}

/* Lanes write back in order; a body that two lanes share does not move
 * (it has no colour), and both write its unchanged velocity. */
KERNEL_FN void KERNEL (scatter) (solver_body *sb, const int32_t *idx, const KERNEL (lanes) *o, int pseudo)
{
  double t[3][BATCH_LANES];
  int i;
  W_STORE (t[0], o->vx);
  W_STORE (t[1], o->vy);
  W_STORE (t[2], o->w);
  for (i = 0; i < BATCH_LANES; ++i)
    {
      solver_body *s = &sb[idx[i]];
      if (pseudo)
        s->pv.x = t[0][i], s->pv.y = t[1][i], s->pw = t[2][i];
      else
        s->v.x = t[0][i], s->v.y = t[1][i], s->w = t[2][i];
    }
}
#endif

/* The velocities (pseudo: the pseudo-velocities) and the motion since the
 * step began of the lanes' bodies. */
KERNEL_FN void KERNEL (gather) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o, int pseudo)
{
  KERNEL (gather_velocities) (sb, idx, o, pseudo);
  KERNEL (gather_motion) (sb, idx, o);
}

/* The pseudo-velocities alone into o, whose motion since the step began
 * (gathered with the velocities) stays. */
KERNEL_FN void KERNEL (gather_pseudo) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o)
{
  KERNEL (gather_velocities) (sb, idx, o, 1);
}

/* The masses of a batch's lanes. */
typedef struct KERNEL (mass) {
  wide im_a, ii_a, im_b, ii_b;
} KERNEL (mass);

KERNEL_FN KERNEL (mass) KERNEL (masses) (const contact_batch *c)
{
  KERNEL (mass) m;
  m.im_a = W_LOAD (c->im_a);
  m.ii_a = W_LOAD (c->ii_a);
  m.im_b = W_LOAD (c->im_b);
  m.ii_b = W_LOAD (c->ii_b);
  return m;
}

/* (v_bp - v_ap) . d, as contact_speed */
KERNEL_FN wide KERNEL (speed) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, wide dx, wide dy, wide ra_d, wide rb_d)
{
  wide rel = W_ADD (W_MUL (W_SUB (b->vx, a->vx), dx), W_MUL (W_SUB (b->vy, a->vy), dy));
  return W_SUB (W_ADD (rel, W_MUL (b->w, rb_d)), W_MUL (a->w, ra_d));
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

/* The separation of a point now, as contact_separation, from its arms ra
 * and rb, normal n and adjusted separation (four lanes each). */
KERNEL_FN wide KERNEL (separation_of) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, const double *ra_x,
                                       const double *ra_y, const double *rb_x, const double *rb_y, const double *nx,
                                       const double *ny, const double *adjusted)
{
  wide rax = W_LOAD (ra_x), ray = W_LOAD (ra_y), rbx = W_LOAD (rb_x), rby = W_LOAD (rb_y);
  wide dx = W_ADD (W_SUB (b->px, a->px),
                   W_SUB (W_SUB (W_MUL (b->qc, rbx), W_MUL (b->qs, rby)), W_SUB (W_MUL (a->qc, rax), W_MUL (a->qs, ray))));
  wide dy = W_ADD (W_SUB (b->py, a->py),
                   W_SUB (W_ADD (W_MUL (b->qs, rbx), W_MUL (b->qc, rby)), W_ADD (W_MUL (a->qs, rax), W_MUL (a->qc, ray))));
  return W_ADD (W_ADD (W_MUL (dx, W_LOAD (nx)), W_MUL (dy, W_LOAD (ny))), W_LOAD (adjusted));
}

/* the separation of point p now */
KERNEL_FN wide KERNEL (separation) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, const batch_point *p)
{
  return KERNEL (separation_of) (a, b, p->ra_x, p->ra_y, p->rb_x, p->rb_y, p->nx, p->ny, p->adjusted);
}

/* contact_lcp2 on every lane, with the inverses set up once per step
 * (contact_batch.c): the four cases in its order, the first that holds
 * taken. Returns the lanes where one holds. */
KERNEL_FN wmask KERNEL (lcp2) (const contact_batch *c, wide b1, wide b2, wide *x1, wide *x2)
{
  wide zero = W_SET1 (0.0), k12 = W_LOAD (c->two.k12);
  wide y1 = W_NEG (W_ADD (W_MUL (W_LOAD (c->two.i11), b1), W_MUL (W_LOAD (c->two.i12), b2)));
  wide y2 = W_NEG (W_ADD (W_MUL (W_LOAD (c->two.i12), b1), W_MUL (W_LOAD (c->two.i22), b2)));
  wmask both = M_AND (M_GT (W_LOAD (c->two.block), zero), M_AND (M_GE (y1, zero), M_GE (y2, zero)));
  wide z1 = W_NEG (W_MUL (b1, W_LOAD (c->p0.normal_mass)));
  wmask first = M_AND (M_GE (z1, zero), M_GE (W_ADD (W_MUL (k12, z1), b2), zero));
  wide z2 = W_NEG (W_MUL (b2, W_LOAD (c->two.p1.normal_mass)));
  wmask second = M_AND (M_GE (z2, zero), M_GE (W_ADD (W_MUL (k12, z2), b1), zero));
  wmask neither = M_AND (M_GE (b1, zero), M_GE (b2, zero));
  *x1 = W_SEL (both, y1, W_SEL (first, z1, zero));
  *x2 = W_SEL (both, y2, W_SEL (first, zero, W_SEL (second, z2, zero)));
  return M_OR (M_OR (both, first), M_OR (second, neither));
}

/* The normal impulses of a batch: both points at once where the lane is a
 * block and the 2x2 problem has a consistent case, else one after the
 * other. `use` masks the lanes that solve at all; `bias` is -target speed. */
KERNEL_FN void KERNEL (normal) (const contact_batch *c, KERNEL (lanes) *a, KERNEL (lanes) *b, const KERNEL (mass) *m,
                                const wide *bias, wide *x, wmask use)
{
  const batch_point *p0 = &c->p0, *p1 = &c->two.p1;
  wide zero = W_SET1 (0.0);
  wide n0x = W_LOAD (p0->nx), n0y = W_LOAD (p0->ny), n1x = W_LOAD (p1->nx), n1y = W_LOAD (p1->ny);
  wide r0a = W_LOAD (p0->rn_a), r0b = W_LOAD (p0->rn_b), r1a = W_LOAD (p1->rn_a), r1b = W_LOAD (p1->rn_b);
  wide k11 = W_LOAD (c->two.k11), k12 = W_LOAD (c->two.k12), k22 = W_LOAD (c->two.k22);
  wide y0, y1, acc, d;
  wide b0 = W_SUB (W_ADD (KERNEL (speed) (a, b, n0x, n0y, r0a, r0b), bias[0]), W_ADD (W_MUL (k11, x[0]), W_MUL (k12, x[1])));
  wide b1 = W_SUB (W_ADD (KERNEL (speed) (a, b, n1x, n1y, r1a, r1b), bias[1]), W_ADD (W_MUL (k12, x[0]), W_MUL (k22, x[1])));
  wmask ok = M_AND (M_AND (KERNEL (lcp2) (c, b0, b1, &y0, &y1), M_GT (W_LOAD (c->two.pair), zero)), use);
  wmask one = M_ANDNOT (use, ok);
  /* a part no lane takes is skipped (on every path alike: M_ANY is exact) */
  if (M_ANY (ok))
    {
      KERNEL (push) (a, b, m, n0x, n0y, r0a, r0b, W_SEL (ok, W_SUB (y0, x[0]), zero));
      KERNEL (push) (a, b, m, n1x, n1y, r1a, r1b, W_SEL (ok, W_SUB (y1, x[1]), zero));
      x[0] = W_SEL (ok, y0, x[0]);
      x[1] = W_SEL (ok, y1, x[1]);
    }
  if (M_ANY (one))
    {
      acc = W_MAX (W_SUB (x[0], W_MUL (W_LOAD (p0->normal_mass), W_ADD (KERNEL (speed) (a, b, n0x, n0y, r0a, r0b), bias[0]))), zero);
      d = W_SEL (one, W_SUB (acc, x[0]), zero);
      KERNEL (push) (a, b, m, n0x, n0y, r0a, r0b, d);
      x[0] = W_SEL (one, acc, x[0]);
      acc = W_MAX (W_SUB (x[1], W_MUL (W_LOAD (p1->normal_mass), W_ADD (KERNEL (speed) (a, b, n1x, n1y, r1a, r1b), bias[1]))), zero);
      d = W_SEL (one, W_SUB (acc, x[1]), zero);
      KERNEL (push) (a, b, m, n1x, n1y, r1a, r1b, d);
      x[1] = W_SEL (one, acc, x[1]);
    }
}

/* The normal impulses of a batch whose lanes have one point each: what
 * KERNEL (normal) does on such lanes (none is a block), without the second
 * point's zeros. */
KERNEL_FN void KERNEL (normal1) (const contact_batch *c, KERNEL (lanes) *a, KERNEL (lanes) *b, const KERNEL (mass) *m,
                                 const wide *bias, wide *x, wmask use)
{
  const batch_point *p0 = &c->p0;
  wide zero = W_SET1 (0.0);
  wide n0x = W_LOAD (p0->nx), n0y = W_LOAD (p0->ny), r0a = W_LOAD (p0->rn_a), r0b = W_LOAD (p0->rn_b);
  wide acc = W_MAX (W_SUB (x[0], W_MUL (W_LOAD (p0->normal_mass), W_ADD (KERNEL (speed) (a, b, n0x, n0y, r0a, r0b), bias[0]))), zero);
  KERNEL (push) (a, b, m, n0x, n0y, r0a, r0b, W_SEL (use, W_SUB (acc, x[0]), zero));
  x[0] = W_SEL (use, acc, x[0]);
}

/* The warm start of one batch of np-point lanes. */
KERNEL_FN void KERNEL (warm_start_batch) (contact_batch *c, solver_body *sb, int np)
{
  KERNEL (lanes) a, b;
  KERNEL (mass) m = KERNEL (masses) (c);
  int j;
  KERNEL (gather) (sb, c->a, &a, 0);
  KERNEL (gather) (sb, c->b, &b, 0);
  for (j = 0; j < np; ++j)
    {
      batch_point *p = BATCH_POINT (c, j);
      wide nx = W_LOAD (p->nx), ny = W_LOAD (p->ny);
      KERNEL (push) (&a, &b, &m, nx, ny, W_LOAD (p->rn_a), W_LOAD (p->rn_b), W_LOAD (p->normal_impulse));
      W_STORE (p->total, W_ADD (W_LOAD (p->total), W_LOAD (p->normal_impulse)));
      KERNEL (push) (&a, &b, &m, W_NEG (ny), nx, W_LOAD (p->rt_a), W_LOAD (p->rt_b), W_LOAD (p->tangent_impulse));
    }
  KERNEL (scatter) (sb, c->a, &a, 0);
  KERNEL (scatter) (sb, c->b, &b, 0);
}

static KERNEL_ATTR void KERNEL (contact_batch_warm_start) (contact_batch *c, int32_t n, solver_body *sb)
{
  int32_t i;
  for (i = 0; i < n; ++i, c = batch_next (c))
    if (c->points > 1)
      KERNEL (warm_start_batch) (c, sb, 2);
    else
      KERNEL (warm_start_batch) (c, sb, 1);
}

/* The separation of both points of a batch now (the solve's speculative
 * bias and the push-out's overlap both start from it). */
KERNEL_FN void KERNEL (separations) (const contact_batch *c, const KERNEL (lanes) *a, const KERNEL (lanes) *b, wide *s,
                                     int np)
{
  s[0] = KERNEL (separation) (a, b, &c->p0);
  s[1] = np > 1 ? KERNEL (separation) (a, b, &c->two.p1) : W_SET1 (0.0);
}

/* One solve pass of a batch on its bodies' velocities a, b, the points
 * separated by s: the normal impulses, then friction. */
KERNEL_FN void KERNEL (solve_lanes) (contact_batch *c, KERNEL (lanes) *a, KERNEL (lanes) *b, const KERNEL (mass) *m,
                                     const wide *s, wide ih, int np)
{
  wide zero = W_SET1 (0.0);
  wide bias[2], x[2], before[2], friction = W_LOAD (c->friction);
  int j;
  for (j = 0; j < np; ++j)
    {
      /* a speculative point may close its gap within the sub-step */
      bias[j] = W_SEL (M_GT (s[j], zero), W_MUL (s[j], ih), zero);
      x[j] = before[j] = W_LOAD (BATCH_POINT (c, j)->normal_impulse);
    }
  if (np > 1)
    KERNEL (normal) (c, a, b, m, bias, x, M_GE (zero, zero));
  else
    KERNEL (normal1) (c, a, b, m, bias, x, M_GE (zero, zero));
  for (j = 0; j < np; ++j)
    {
      batch_point *p = BATCH_POINT (c, j);
      wide tx = W_NEG (W_LOAD (p->ny)), ty = W_LOAD (p->nx), rta = W_LOAD (p->rt_a), rtb = W_LOAD (p->rt_b);
      wide old = W_LOAD (p->tangent_impulse), limit = W_MUL (friction, x[j]);
      wide acc = W_SUB (old, W_MUL (W_LOAD (p->tangent_mass), KERNEL (speed) (a, b, tx, ty, rta, rtb)));
      acc = W_MIN (W_MAX (acc, W_NEG (limit)), limit);
      KERNEL (push) (a, b, m, tx, ty, rta, rtb, W_SUB (acc, old));
      W_STORE (p->tangent_impulse, acc);
      W_STORE (p->normal_impulse, x[j]);
      W_STORE (p->total, W_ADD (W_LOAD (p->total), W_SUB (x[j], before[j])));
    }
}

/* One push-out pass of a batch on its bodies' pseudo-velocities a, b, the
 * points separated by s. Returns 0 where no lane had overlap to push out
 * nor a push so far (the bodies keep their pseudo-velocities). */
KERNEL_FN int KERNEL (push_lanes) (contact_batch *c, KERNEL (lanes) *a, KERNEL (lanes) *b, const KERNEL (mass) *m,
                                   const wide *s, wide rate, int first, int np)
{
  wide zero = W_SET1 (0.0), bias[2], x[2], slop = W_LOAD (c->slop), fastest = W_NEG (W_LOAD (c->max_push));
  wmask use = M_GT (zero, zero);
  int j;
  for (j = 0; j < np; ++j)
    {
      /* overlap beyond the slop, a fraction of it per sub-step, no faster
       * than max_push */
      wide e = W_ADD (s[j], slop);
      bias[j] = W_SEL (M_GE (e, zero), zero, W_MAX (W_MUL (rate, e), fastest));
      /* last sub-step's push was dropped with the move */
      x[j] = first ? zero : W_LOAD (BATCH_POINT (c, j)->push_impulse);
      use = M_OR (use, M_OR (M_LT (bias[j], zero), M_GT (x[j], zero)));
    }
  if (M_ANY (use))
    {
      if (np > 1)
        KERNEL (normal) (c, a, b, m, bias, x, use);
      else
        KERNEL (normal1) (c, a, b, m, bias, x, use);
    }
  for (j = 0; j < np; ++j)
    W_STORE (BATCH_POINT (c, j)->push_impulse, x[j]);
  return M_ANY (use);
}

/* A batch's bodies (their velocities, or pseudo-velocities) into a, b and
 * its points' separations into s: what every pass starts from. Returns its
 * masses. */
KERNEL_FN KERNEL (mass) KERNEL (load_batch) (const contact_batch *c, const solver_body *sb, KERNEL (lanes) *a,
                                             KERNEL (lanes) *b, wide *s, int pseudo, int np)
{
  KERNEL (gather) (sb, c->a, a, pseudo);
  KERNEL (gather) (sb, c->b, b, pseudo);
  KERNEL (separations) (c, a, b, s, np);
  return KERNEL (masses) (c);
}

/* One solve pass of one batch of np-point lanes. */
KERNEL_FN void KERNEL (solve_batch) (contact_batch *c, solver_body *sb, wide ih, int np)
{
  KERNEL (lanes) a, b;
  wide s[2];
  KERNEL (mass) m = KERNEL (load_batch) (c, sb, &a, &b, s, 0, np);
  KERNEL (solve_lanes) (c, &a, &b, &m, s, ih, np);
  KERNEL (scatter) (sb, c->a, &a, 0);
  KERNEL (scatter) (sb, c->b, &b, 0);
}

static KERNEL_ATTR void KERNEL (contact_batch_solve) (contact_batch *c, int32_t n, solver_body *sb, double inv_h)
{
  wide ih = W_SET1 (inv_h);
  int32_t i;
  for (i = 0; i < n; ++i, c = batch_next (c))
    if (c->points > 1)
      KERNEL (solve_batch) (c, sb, ih, 2);
    else
      KERNEL (solve_batch) (c, sb, ih, 1);
}

/* One push-out pass of one batch of np-point lanes. */
KERNEL_FN void KERNEL (push_out_batch) (contact_batch *c, solver_body *sb, wide rate, int first, int np)
{
  KERNEL (lanes) a, b;
  wide s[2];
  KERNEL (mass) m = KERNEL (load_batch) (c, sb, &a, &b, s, 1, np);
  if (!KERNEL (push_lanes) (c, &a, &b, &m, s, rate, first, np))
    return;
  KERNEL (scatter) (sb, c->a, &a, 1);
  KERNEL (scatter) (sb, c->b, &b, 1);
}

static KERNEL_ATTR void KERNEL (contact_batch_push_out) (contact_batch *c, int32_t n, solver_body *sb, double push_rate,
                                                  int first)
{
  wide rate = W_SET1 (push_rate);
  int32_t i;
  for (i = 0; i < n; ++i, c = batch_next (c))
    if (c->points > 1)
      KERNEL (push_out_batch) (c, sb, rate, first, 2);
    else
      KERNEL (push_out_batch) (c, sb, rate, first, 1);
}

/* A solve pass and the sub-step's first push-out pass in one walk over the
 * batches: the push-out reads the pseudo-velocities and the motion since
 * the step began, which the solve leaves alone, so each batch is loaded
 * once, its separations computed once, and the results are those of the
 * two passes one after the other. */
KERNEL_FN void KERNEL (solve_push_out_batch) (contact_batch *c, solver_body *sb, wide ih, wide rate, int np)
{
  KERNEL (lanes) a, b, pa, pb;
  KERNEL (mass) m = KERNEL (masses) (c);
  wide s[2];
  KERNEL (gather) (sb, c->a, &a, 0);
  KERNEL (gather) (sb, c->b, &b, 0);
  /* the pseudo-velocities before the velocities are written back: a
   * load overlapping a store just made would wait for it */
  pa = a, pb = b;
  KERNEL (gather_pseudo) (sb, c->a, &pa);
  KERNEL (gather_pseudo) (sb, c->b, &pb);
  KERNEL (separations) (c, &a, &b, s, np);
  KERNEL (solve_lanes) (c, &a, &b, &m, s, ih, np);
  KERNEL (scatter) (sb, c->a, &a, 0);
  KERNEL (scatter) (sb, c->b, &b, 0);
  if (!KERNEL (push_lanes) (c, &pa, &pb, &m, s, rate, 1, np))
    return;
  KERNEL (scatter) (sb, c->a, &pa, 1);
  KERNEL (scatter) (sb, c->b, &pb, 1);
}

static KERNEL_ATTR void KERNEL (contact_batch_solve_push_out) (contact_batch *c, int32_t n, solver_body *sb, double inv_h,
                                                        double push_rate)
{
  wide ih = W_SET1 (inv_h), rate = W_SET1 (push_rate);
  int32_t i;
  for (i = 0; i < n; ++i, c = batch_next (c))
    if (c->points > 1)
      KERNEL (solve_push_out_batch) (c, sb, ih, rate, 2);
    else
      KERNEL (solve_push_out_batch) (c, sb, ih, rate, 1);
}
