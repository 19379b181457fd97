/* Small 2D vector and rotation helpers used by every module (internal). */
#ifndef CAROM_VEC2_H
#define CAROM_VEC2_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#define CAROM_PI 3.14159265358979323846

/* A helper inlined into its callers even where the compiler would not: for
 * the few small functions of the per-contact loops whose vector arguments
 * would otherwise go through memory at each call. */
#ifdef __GNUC__
#define ALWAYS_INLINE static inline __attribute__ ((always_inline))
#else
#define ALWAYS_INLINE static inline
#endif

/* c ? a : b, the same bits, computed without a branch: for a choice the
 * data make unpredictable, which compilers often turn into a jump. Not for
 * a running best inside a loop: there the masks lengthen the chain each
 * turn waits on (the SAT's nearest-vertex search stepped the gas 12%
 * slower with them), and the compiler's own min or max is better. */
static inline double select_double (int c, double a, double b)
{
  uint64_t ua, ub, m = (uint64_t) 0 - (uint64_t) (c != 0);
  memcpy (&ua, &a, sizeof ua);
  memcpy (&ub, &b, sizeof ub);
  ua = (ua & m) | (ub & ~m);
  memcpy (&a, &ua, sizeof a);
  return a;
}

/* The same for two slots. */
static inline int32_t select_int (int c, int32_t a, int32_t b)
{
  int32_t m = -(int32_t) (c != 0);
  return (a & m) | (b & ~m);
}

typedef struct vec2 {
  double x, y;
} vec2;

/* A rotation kept as its cosine and sine, so it is computed once per step. */
typedef struct rot2 {
  double c, s;
} rot2;

/* A rigid transform: rotate, then translate. */
typedef struct xform {
  vec2 p;
  rot2 q;
} xform;

static inline vec2 v2 (double x, double y) { vec2 v = {x, y}; return v; }
static inline vec2 v2_add (vec2 a, vec2 b) { return v2 (a.x + b.x, a.y + b.y); }
static inline vec2 v2_sub (vec2 a, vec2 b) { return v2 (a.x - b.x, a.y - b.y); }
static inline vec2 v2_scale (vec2 a, double s) { return v2 (a.x * s, a.y * s); }
static inline vec2 v2_neg (vec2 a) { return v2 (-a.x, -a.y); }
static inline double v2_dot (vec2 a, vec2 b) { return a.x * b.x + a.y * b.y; }
/* z component of the 3D cross product of (a, 0) and (b, 0). */
static inline double v2_cross (vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }
/* w x r for an angular velocity w along z (thesis, after eq. 3.16). */
static inline vec2 v2_cross_sv (double w, vec2 r) { return v2 (-w * r.y, w * r.x); }
/* The left perpendicular: (x, y) -> (-y, x). */
static inline vec2 v2_perp (vec2 a) { return v2 (-a.y, a.x); }
static inline double v2_len2 (vec2 a) { return v2_dot (a, a); }
static inline double v2_len (vec2 a) { return sqrt (v2_dot (a, a)); }
/* Whether sqrt (a . a) <= r surely holds, found without the square root: a
 * . a below r^2 by more than the rounding of both (four units in the last
 * place) makes the root below r, and rounding it to r's format cannot take
 * it past r. Where r^2 is subnormal the squares fall on the same coarse
 * grid, and one a whole step below r^2's is below r^2; where r^2
 * overflows, any finite a . a is below it (an infinite one fails the
 * strict test). 0 says nothing: the caller takes the root. */
static inline int v2_len_surely_within (vec2 a, double r)
{
  return r > 0.0 && v2_dot (a, a) < r * r * (1.0 - 0x1p-50);
}
/* sqrt (a . a) <= r, the same answer, the root taken only where the
 * squares cannot give it. */
static inline int v2_len_at_most (vec2 a, double r)
{
  return v2_len_surely_within (a, r) || v2_len (a) <= r;
}
static inline vec2 v2_mad (vec2 a, double s, vec2 b) { return v2 (a.x + s * b.x, a.y + s * b.y); }
static inline vec2 v2_lerp (vec2 a, vec2 b, double t) { return v2 (a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)); }
static inline vec2 v2_min (vec2 a, vec2 b) { return v2 (a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y); }
static inline vec2 v2_max (vec2 a, vec2 b) { return v2 (a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y); }

/* Unit vector along a; returns (0, 0) for a zero vector. hypot, because
 * the squared length of a tiny vector underflows. */
static inline vec2 v2_normalize (vec2 a)
{
  double l = hypot (a.x, a.y);
  /* divide rather than multiply by 1 / l, which overflows for subnormal l */
  return l > 0.0 ? v2 (a.x / l, a.y / l) : v2 (0.0, 0.0);
}

/* (cos angle, sin angle), the same bits on every machine (angle.c) */
rot2 rot2_from_angle (double angle);
static inline vec2 rot2_apply (rot2 q, vec2 v) { return v2 (q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y); }
static inline vec2 rot2_apply_inv (rot2 q, vec2 v) { return v2 (q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y); }
/* q turned further by r (their angles added) */
static inline rot2 rot2_then (rot2 q, rot2 r)
{
  rot2 x;
  x.c = q.c * r.c - q.s * r.s;
  x.s = q.s * r.c + q.c * r.s;
  return x;
}

static inline vec2 xform_apply (xform t, vec2 v) { return v2_add (rot2_apply (t.q, v), t.p); }
static inline vec2 xform_apply_inv (xform t, vec2 v) { return rot2_apply_inv (t.q, v2_sub (v, t.p)); }

/* B expressed in A's frame: inv(A) * B. */
static inline xform xform_relative (xform a, xform b)
{
  xform r;
  r.q.c = a.q.c * b.q.c + a.q.s * b.q.s;
  r.q.s = a.q.c * b.q.s - a.q.s * b.q.c;
  r.p = rot2_apply_inv (a.q, v2_sub (b.p, a.p));
  return r;
}

static inline int is_finite (double x) { return isfinite (x) != 0; }

/* The largest magnitude accepted for a coordinate, velocity, spin,
 * acceleration or time step (CAROM_MAX_MAGNITUDE): products of a few such
 * numbers, which the solver forms, stay within doubles. */
#define MAX_MAGNITUDE 1e100
/* The masses a dynamic body may have (carom_world_add_*: BAD_DENSITY). */
#define MIN_MASS 1e-200
#define MAX_MASS 1e200
#define MIN_INERTIA 1e-300
static inline int is_moderate (double x) { return x >= -MAX_MAGNITUDE && x <= MAX_MAGNITUDE; }

#endif
