/* What the batch kernels (contact_batch_kernel.h, shock_kernel.h) share:
 * their operations on lanes, and the gathering of the lanes' bodies.
 *
 * The including file defines the lanes (a type `wide` of KERNEL_WIDTH
 * doubles, 4 unless it says 8, a mask type `wmask`, the operations W_* and
 * M_* below), KERNEL(name) to name its copy of each function and
 * KERNEL_ATTR for the attributes every function of the copy needs. Every
 * operation is one IEEE rounding (or none), taken in the order written: the
 * copies give the same bits.
 *
 *   W_LOAD(p) W_STORE(p, x) W_SET1(d)            KERNEL_WIDTH doubles
 *   W_ADD W_SUB W_MUL W_DIV W_NEG                arithmetic
 *   W_MAX(a, b)  a > b ? a : b    W_MIN(a, b)  a < b ? a : b   (per lane)
 *   M_GT M_GE M_LT M_NE(a, b) M_AND M_OR M_ANDNOT(m, n) (m and not n)
 *   W_SEL(m, a, b)  m ? a : b      M_ANY(m)  some lane of m is set (an int)
 *   M_GROUPS(m)  the lanes of each group of four that has a lane of m
 *   W_MERGE(g, a, b)  a on the lanes of g = M_GROUPS(m), b on the others
 *
 * A kernel of four lanes skips a part of a pass that none of its lanes
 * takes; one of eight skips it for each group of four that takes none
 * (M_GROUPS, W_MERGE), so that it gives the bits of two kernels of four,
 * even where adding an impulse of 0 would turn a velocity of -0 into +0.
 * On four lanes a group is the whole register: M_GROUPS(m) may be m, and
 * W_MERGE(g, a, b), used only where M_ANY(g), a. */
#ifndef KERNEL_WIDTH
#define KERNEL_WIDTH 4
#endif

#if KERNEL_WIDTH == 4
#define M_GROUPS(m) (m)
#define W_MERGE(g, a, b) ((void) (g), (a))
#endif

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
/* solver_body begins with three rows of four doubles, v.x v.y w -,
 * pv.x pv.y pw -, dp.x dp.y dq.c dq.s (checked in contact_batch.c): the
 * velocities are the row at 0 (pseudo: at 4), the motion since the step
 * began the row at 8. KERNEL (columns) reads the row at `at` of the lanes'
 * bodies as four columns; KERNEL (scatter) writes columns vx, vy, w back
 * as their rows, the fourth double of each row 0, the lanes in order. */
#if KERNEL_WIDTH == 8
/* The rows two to a register (0 and 2, 1 and 3, 4 and 6, 5 and 7), a 4 x 4
 * transpose on each half, the halves' columns brought together by the last
 * shuffle. */
KERNEL_FN void KERNEL (columns) (const solver_body *sb, const int32_t *idx, int at, wide *c0, wide *c1, wide *c2,
                                 wide *c3)
{
#define KERNEL_ROWS(i, j)                                                                                          \
  _mm512_insertf64x4 (_mm512_castpd256_pd512 (_mm256_loadu_pd (&sb[idx[i]].v.x + at)),                           \
                      _mm256_loadu_pd (&sb[idx[j]].v.x + at), 1)
  wide x = KERNEL_ROWS (0, 2), y = KERNEL_ROWS (1, 3), z = KERNEL_ROWS (4, 6), w = KERNEL_ROWS (5, 7);
#undef KERNEL_ROWS
  wide lo_xy = _mm512_unpacklo_pd (x, y), lo_zw = _mm512_unpacklo_pd (z, w);
  wide hi_xy = _mm512_unpackhi_pd (x, y), hi_zw = _mm512_unpackhi_pd (z, w);
  *c0 = _mm512_shuffle_f64x2 (lo_xy, lo_zw, 0x88);
  *c1 = _mm512_shuffle_f64x2 (hi_xy, hi_zw, 0x88);
  *c2 = _mm512_shuffle_f64x2 (lo_xy, lo_zw, 0xdd);
  *c3 = _mm512_shuffle_f64x2 (hi_xy, hi_zw, 0xdd);
}

/* Rows i and i + 2 of a register from the lanes' pairs (x y) and (w 0). */
KERNEL_FN void KERNEL (scatter) (solver_body *sb, const int32_t *idx, const KERNEL (lanes) *o, int pseudo)
{
  int at = pseudo ? 4 : 0;
  wide zero = _mm512_setzero_pd ();
  wide xy_even = _mm512_unpacklo_pd (o->vx, o->vy), xy_odd = _mm512_unpackhi_pd (o->vx, o->vy);
  wide w_even = _mm512_unpacklo_pd (o->w, zero), w_odd = _mm512_unpackhi_pd (o->w, zero);
  const __m512i first = _mm512_set_epi64 (11, 10, 3, 2, 9, 8, 1, 0);
  const __m512i second = _mm512_set_epi64 (15, 14, 7, 6, 13, 12, 5, 4);
  wide r02 = _mm512_permutex2var_pd (xy_even, first, w_even), r13 = _mm512_permutex2var_pd (xy_odd, first, w_odd);
  wide r46 = _mm512_permutex2var_pd (xy_even, second, w_even);
  wide r57 = _mm512_permutex2var_pd (xy_odd, second, w_odd);
  _mm256_storeu_pd (&sb[idx[0]].v.x + at, _mm512_castpd512_pd256 (r02));
  _mm256_storeu_pd (&sb[idx[1]].v.x + at, _mm512_castpd512_pd256 (r13));
  _mm256_storeu_pd (&sb[idx[2]].v.x + at, _mm512_extractf64x4_pd (r02, 1));
  _mm256_storeu_pd (&sb[idx[3]].v.x + at, _mm512_extractf64x4_pd (r13, 1));
  _mm256_storeu_pd (&sb[idx[4]].v.x + at, _mm512_castpd512_pd256 (r46));
  _mm256_storeu_pd (&sb[idx[5]].v.x + at, _mm512_castpd512_pd256 (r57));
  _mm256_storeu_pd (&sb[idx[6]].v.x + at, _mm512_extractf64x4_pd (r46, 1));
  _mm256_storeu_pd (&sb[idx[7]].v.x + at, _mm512_extractf64x4_pd (r57, 1));
}
#else
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

KERNEL_FN void KERNEL (columns) (const solver_body *sb, const int32_t *idx, int at, wide *c0, wide *c1, wide *c2,
                                 wide *c3)
{
  KERNEL (transpose) (W_LOAD (&sb[idx[0]].v.x + at), W_LOAD (&sb[idx[1]].v.x + at), W_LOAD (&sb[idx[2]].v.x + at),
                      W_LOAD (&sb[idx[3]].v.x + at), c0, c1, c2, c3);
}

KERNEL_FN void KERNEL (scatter) (solver_body *sb, const int32_t *idx, const KERNEL (lanes) *o, int pseudo)
{
  int at = pseudo ? 4 : 0;
  wide r0, r1, r2, r3;
  KERNEL (transpose) (o->vx, o->vy, o->w, _mm256_setzero_pd (), &r0, &r1, &r2, &r3);
  W_STORE (&sb[idx[0]].v.x + at, r0);
  W_STORE (&sb[idx[1]].v.x + at, r1);
  W_STORE (&sb[idx[2]].v.x + at, r2);
  W_STORE (&sb[idx[3]].v.x + at, r3);
}
#endif

/* The velocities (pseudo: the pseudo-velocities) of the lanes' bodies. */
KERNEL_FN void KERNEL (gather_velocities) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o, int pseudo)
{
  wide rest;
  KERNEL (columns) (sb, idx, pseudo ? 4 : 0, &o->vx, &o->vy, &o->w, &rest);
}

/* Their motion since the step began. */
KERNEL_FN void KERNEL (gather_motion) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o)
{
  KERNEL (columns) (sb, idx, 8, &o->px, &o->py, &o->qc, &o->qs);
}
#else
/* The velocities (pseudo: the pseudo-velocities) of the lanes' bodies. */
KERNEL_FN void KERNEL (gather_velocities) (const solver_body *sb, const int32_t *idx, KERNEL (lanes) *o, int pseudo)
{
  double t[3][KERNEL_WIDTH];
  int i;
  for (i = 0; i < KERNEL_WIDTH; ++i)
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
  double t[4][KERNEL_WIDTH];
  int i;
  for (i = 0; i < KERNEL_WIDTH; ++i)
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

/* Lanes write back in order. */
KERNEL_FN void KERNEL (scatter) (solver_body *sb, const int32_t *idx, const KERNEL (lanes) *o, int pseudo)
{
  double t[3][KERNEL_WIDTH];
  int i;
  W_STORE (t[0], o->vx);
  W_STORE (t[1], o->vy);
  W_STORE (t[2], o->w);
  for (i = 0; i < KERNEL_WIDTH; ++i)
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

/* (v_bp - v_ap) . d, as contact_speed */
KERNEL_FN wide KERNEL (speed) (const KERNEL (lanes) *a, const KERNEL (lanes) *b, wide dx, wide dy, wide ra_d, wide rb_d)
{
  wide rel = W_ADD (W_MUL (W_SUB (b->vx, a->vx), dx), W_MUL (W_SUB (b->vy, a->vy), dy));
  return W_SUB (W_ADD (rel, W_MUL (b->w, rb_d)), W_MUL (a->w, ra_d));
}

/* The separation of a point now, as contact_separation, from its arms ra
 * and rb, normal n and adjusted separation (KERNEL_WIDTH lanes each). */
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
