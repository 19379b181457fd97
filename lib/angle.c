/* The rotation of an angle: its cosine and sine, computed here rather than
 * by the C library, so that a body's rotation (body_sync) and the poses the
 * time of impact tries (toi.c) are the same bits on every machine, whatever
 * its libm, and cost less than a call of the library's sin and cos.
 *
 * The angle is reduced to r = angle - k pi/2, |r| <= pi/4, with pi/2 in
 * three parts (Cody and Waite: the first two have 33 bits, so k times them
 * is exact for |k| < 2^20, and so is the first subtraction), then sin r and
 * cos r are their Taylor series, to r^17 and r^16, by Horner's rule: the
 * first term left out is below 2^-55 of the result for |r| <= pi/4, and the
 * error is about one rounding (tests/test_body.c compares with libm over
 * every quadrant). Beyond |angle| = 1e6 (k near 2^20) the C library's
 * functions take over. */
#include "vec2.h"

#define PIO2_1 1.5707963267341256       /* 0x1.921fb544p+0: pi/2's first 33 bits */
#define PIO2_2 6.077100506303966e-11    /* 0x1.0b4611a6p-34: its next 33 */
#define PIO2_3 2.0222662487959506e-21   /* the rest, rounded */
#define TWO_OVER_PI 0.6366197723675814
#define REDUCE_MAX 1e6

/* The series one at a time: what a machine without SSE2 computes, and
 * what the test builds check the two lanes against. */
#if !defined(__SSE2__) || defined(CAROM_DEBUG_CHECKS)
/* sin r for |r| <= pi/4: r - r^3/3! + ... + r^17/17! */
static double sin_reduced (double r)
{
  double z = r * r;
  double p = -1.0 / 355687428096000.0; /* -1/17! */
  p = 1.0 / 1307674368000.0 + z * p;    /* 1/15! */
  p = -1.0 / 6227020800.0 + z * p;      /* -1/13! */
  p = 1.0 / 39916800.0 + z * p;         /* 1/11! */
  p = -1.0 / 362880.0 + z * p;          /* -1/9! */
  p = 1.0 / 5040.0 + z * p;             /* 1/7! */
  p = -1.0 / 120.0 + z * p;             /* -1/5! */
  p = 1.0 / 6.0 + z * p;                /* 1/3! */
  return r - (r * z) * p;
}

/* cos r for |r| <= pi/4: 1 - r^2/2! + ... + r^16/16! */
static double cos_reduced (double r)
{
  double z = r * r;
  double p = 1.0 / 20922789888000.0; /* 1/16! */
  p = -1.0 / 87178291200.0 + z * p;  /* -1/14! */
  p = 1.0 / 479001600.0 + z * p;     /* 1/12! */
  p = -1.0 / 3628800.0 + z * p;      /* -1/10! */
  p = 1.0 / 40320.0 + z * p;         /* 1/8! */
  p = -1.0 / 720.0 + z * p;          /* -1/6! */
  p = 1.0 / 24.0 + z * p;            /* 1/4! */
  return 1.0 - (0.5 * z - (z * z) * p);
}
#endif

#ifdef __SSE2__
#include <emmintrin.h>
#ifdef CAROM_DEBUG_CHECKS
#include <stdio.h>
#include <stdlib.h>
#endif

/* Both series at once, cosine in the low lane and sine in the high one:
 * the steps of Horner's rule side by side, each lane the same operations
 * in the same order as cos_reduced and sin_reduced, so the same bits in
 * half the instructions. The sine's series has one term more: its first
 * step is taken alone. */
static void cos_sin_reduced (double r, double *c, double *s)
{
  double z = r * r;
  double ps = 1.0 / 1307674368000.0 + z * (-1.0 / 355687428096000.0); /* 1/15! - z/17! */
  __m128d zz = _mm_set1_pd (z);
  __m128d p = _mm_set_pd (ps, 1.0 / 20922789888000.0); /* 1/16! */
  p = _mm_add_pd (_mm_set_pd (-1.0 / 6227020800.0, -1.0 / 87178291200.0), _mm_mul_pd (zz, p));
  p = _mm_add_pd (_mm_set_pd (1.0 / 39916800.0, 1.0 / 479001600.0), _mm_mul_pd (zz, p));
  p = _mm_add_pd (_mm_set_pd (-1.0 / 362880.0, -1.0 / 3628800.0), _mm_mul_pd (zz, p));
  p = _mm_add_pd (_mm_set_pd (1.0 / 5040.0, 1.0 / 40320.0), _mm_mul_pd (zz, p));
  p = _mm_add_pd (_mm_set_pd (-1.0 / 120.0, -1.0 / 720.0), _mm_mul_pd (zz, p));
  p = _mm_add_pd (_mm_set_pd (1.0 / 6.0, 1.0 / 24.0), _mm_mul_pd (zz, p));
  /* (0.5 z - z^2 p_c, r - (r z) p_s) */
  p = _mm_sub_pd (_mm_set_pd (r, 0.5 * z), _mm_mul_pd (_mm_set_pd (r * z, z * z), p));
  *c = 1.0 - _mm_cvtsd_f64 (p);
  *s = _mm_cvtsd_f64 (_mm_unpackhi_pd (p, p));
#ifdef CAROM_DEBUG_CHECKS
  if (memcmp (c, &(double) { cos_reduced (r) }, sizeof *c) || memcmp (s, &(double) { sin_reduced (r) }, sizeof *s))
    {
      fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: the paired series differ from cos_reduced and sin_reduced\n");
      abort ();
    }
#endif
}

#define SIGN ((uint64_t) 1 << 63)
#define ALL (~(uint64_t) 0)
/* After k quarter turns, k mod 4: the mask that swaps the lanes (c, s),
 * then the sign bits that negate them. */
static const uint64_t quarter_masks[4][4] = {
  { 0, 0, 0, 0 },       /* (c, s) */
  { ALL, ALL, SIGN, 0 }, /* (-s, c) */
  { 0, 0, SIGN, SIGN },  /* (-c, -s) */
  { ALL, ALL, 0, SIGN }, /* (s, -c) */
};
#else
static void cos_sin_reduced (double r, double *c, double *s)
{
  *c = cos_reduced (r), *s = sin_reduced (r);
}
#endif

rot2 rot2_from_angle (double angle)
{
  double k, r, c, s, x;
  long n;
  rot2 q;
  if (!(fabs (angle) <= REDUCE_MAX))
    {
      q.c = cos (angle), q.s = sin (angle);
      return q;
    }
  /* the nearest k (a tie either way: |r| <= pi/4 for both), by a
   * conversion that truncates, not a call of floor */
  x = angle * TWO_OVER_PI;
  n = (long) (x + copysign (0.5, x)); /* x - 0.5 below 0: the same sum */
  k = (double) n;
  r = ((angle - k * PIO2_1) - k * PIO2_2) - k * PIO2_3;
  cos_sin_reduced (r, &c, &s);
  /* turned by k quarter turns, k mod 4 (two's complement: -1 & 3 is 3):
   * (c, s), (-s, c), (-c, -s), (s, -c), on the bits, without branches (a
   * body's quadrant is not predictable): an odd k swaps c and s through
   * a mask, and a negation is the sign bit flipped, as unary minus does */
#ifdef __SSE2__
  {
    /* both lanes at once, the masks of k mod 4 from quarter_masks */
    const uint64_t *m = quarter_masks[n & 3];
    __m128d v = _mm_set_pd (s, c), w = _mm_shuffle_pd (v, v, 1);
    v = _mm_xor_pd (v, _mm_and_pd (_mm_xor_pd (v, w), _mm_castsi128_pd (_mm_loadu_si128 ((const __m128i *) m))));
    v = _mm_xor_pd (v, _mm_castsi128_pd (_mm_loadu_si128 ((const __m128i *) (m + 2))));
    q.c = _mm_cvtsd_f64 (v);
    q.s = _mm_cvtsd_f64 (_mm_unpackhi_pd (v, v));
  }
#else
  {
    uint64_t uc, us, swap, m = (uint64_t) 0 - (uint64_t) (n & 1);
    memcpy (&uc, &c, sizeof uc);
    memcpy (&us, &s, sizeof us);
    swap = (uc ^ us) & m;
    uc ^= swap ^ ((uint64_t) ((n + 1) & 2) << 62);
    us ^= swap ^ ((uint64_t) (n & 2) << 62);
    memcpy (&q.c, &uc, sizeof q.c);
    memcpy (&q.s, &us, sizeof q.s);
  }
#endif
  return q;
}
