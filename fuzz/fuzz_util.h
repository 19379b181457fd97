/* Helpers shared by the libFuzzer targets in fuzz/ (docs/reliability.md):
 * a reader that turns the fuzzer's bytes into numbers, and the checks every
 * target makes. A finding is reported with FUZZ_FINDING, which prints what
 * is wrong and aborts, so libFuzzer saves the input. */
#ifndef CAROM_FUZZ_UTIL_H
#define CAROM_FUZZ_UTIL_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carom.h"

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

#define FUZZ_FINDING(...)                                                      \
  do {                                                                         \
    fprintf (stderr, "FINDING: ");                                             \
    fprintf (stderr, __VA_ARGS__);                                             \
    fputc ('\n', stderr);                                                      \
    abort ();                                                                  \
  } while (0)

/* The statuses carom defines; anything else returned is a finding. */
static inline int fuzz_known_status (carom_status s)
{
  return s >= CAROM_OK && s <= CAROM_ERR_STALE_JOINT;
}

/* ------------------------------------------------------------ the reader */

/* The input, consumed from the front; reads past the end give zeros. */
typedef struct fuzz_input {
  const uint8_t *p;
  size_t n;
} fuzz_input;

static inline uint8_t fuzz_u8 (fuzz_input *in)
{
  uint8_t b = 0;
  if (in->n > 0)
    {
      b = *in->p++;
      in->n--;
    }
  return b;
}

static inline uint16_t fuzz_u16 (fuzz_input *in)
{
  uint16_t lo = fuzz_u8 (in);
  return (uint16_t) (lo | (uint16_t) (fuzz_u8 (in) << 8));
}

static inline uint32_t fuzz_u32 (fuzz_input *in)
{
  uint32_t lo = fuzz_u16 (in);
  return lo | ((uint32_t) fuzz_u16 (in) << 16);
}

/* Any 64-bit pattern: NaNs, infinities, subnormals, everything. */
static inline double fuzz_raw_double (fuzz_input *in)
{
  uint8_t b[8];
  double d;
  int i;
  for (i = 0; i < 8; ++i)
    b[i] = fuzz_u8 (in);
  memcpy (&d, b, sizeof d);
  return d;
}

/* Values that break naive arithmetic. */
static const double fuzz_specials[] = {
  0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, -1e-300, 1e300, -1e300, 1e-160, 1e160, 1e154, 1e-154,
  DBL_MAX, -DBL_MAX, DBL_MIN, 4.9406564584124654e-324, 1e-12, 1e12, 3.14159265358979323846,
  1e-308, 1e308, 2.2250738585072014e-308 / 3.0,
};
#define FUZZ_SPECIAL_COUNT (sizeof fuzz_specials / sizeof fuzz_specials[0])

/* A number for a quantity: mostly ordinary, sometimes extreme, sometimes
 * not finite, so every range check and every overflow is reached.
 * `finite_only` leaves NaN and infinities out. */
static inline double fuzz_number (fuzz_input *in, int finite_only)
{
  uint8_t sel = fuzz_u8 (in);
  double v;
  switch (sel % 8)
    {
    case 0: /* a small integer */
      return (double) (int8_t) fuzz_u8 (in);
    case 1: /* a fraction in [-128, 128) with 1/256 steps */
      return (int16_t) fuzz_u16 (in) / 256.0;
    case 2: /* a decimal mantissa times 10^e, e in [-320, 320) */
      {
        double m = (int16_t) fuzz_u16 (in) / 1024.0;
        int e = (int) (fuzz_u16 (in) % 640) - 320;
        v = m * pow (10.0, e);
        if (finite_only && !isfinite (v))
          v = m;
        return v;
      }
    case 3:
      return fuzz_specials[fuzz_u8 (in) % FUZZ_SPECIAL_COUNT];
    case 4: /* any bit pattern */
      v = fuzz_raw_double (in);
      if (finite_only && !isfinite (v))
        v = 0.0;
      return v;
    case 5: /* not finite */
      if (finite_only)
        return 2.0;
      switch (fuzz_u8 (in) % 3)
        {
        case 0: return NAN;
        case 1: return INFINITY;
        default: return -INFINITY;
        }
    default: /* a plain value in [0, 16) */
      return fuzz_u8 (in) / 16.0;
    }
}

/* ------------------------------------------------------------ the checks */

static inline int fuzz_finite6 (double a, double b, double c, double d, double e, double f)
{
  return isfinite (a) && isfinite (b) && isfinite (c) && isfinite (d) && isfinite (e) && isfinite (f);
}

/* Every body's state and every contact is finite, and each call on a live
 * id answers OK. `what` names the moment for the report. */
static inline void fuzz_check_world (const carom_world *w, const char *what)
{
  carom_body_id stack_ids[64], *ids = stack_ids;
  int32_t n = carom_world_get_bodies (w, NULL, 0), i;
  if (n < 0 || n != carom_world_body_count (w))
    FUZZ_FINDING ("%s: get_bodies says %d, body_count %d", what, (int) n, (int) carom_world_body_count (w));
  if (n > 64)
    {
      ids = malloc ((size_t) n * sizeof *ids);
      if (!ids)
        abort ();
    }
  if (carom_world_get_bodies (w, ids, n) != n)
    FUZZ_FINDING ("%s: get_bodies changed its count", what);
  for (i = 0; i < n; ++i)
    {
      double x, y, a, vx, vy, s, m, inertia, area;
      carom_body_type type;
      if (carom_body_get_position (w, ids[i], &x, &y) != CAROM_OK || carom_body_get_angle (w, ids[i], &a) != CAROM_OK
          || carom_body_get_velocity (w, ids[i], &vx, &vy) != CAROM_OK
          || carom_body_get_spin (w, ids[i], &s) != CAROM_OK
          || carom_body_get_mass (w, ids[i], &m, &inertia, &area) != CAROM_OK
          || carom_body_get_type (w, ids[i], &type) != CAROM_OK)
        FUZZ_FINDING ("%s: a getter failed on live body %d", what, (int) i);
      if (!fuzz_finite6 (x, y, a, vx, vy, s))
        FUZZ_FINDING ("%s: body %d of %d not finite: p (%g, %g) angle %g v (%g, %g) spin %g", what, (int) i,
                      (int) n, x, y, a, vx, vy, s);
      if (!isfinite (m) || !isfinite (inertia) || !isfinite (area) || !(area > 0.0))
        FUZZ_FINDING ("%s: body %d mass %g inertia %g area %g", what, (int) i, m, inertia, area);
      if (type == CAROM_DYNAMIC ? !(m > 0.0 && inertia > 0.0) : (m != 0.0 || inertia != 0.0))
        FUZZ_FINDING ("%s: body %d (%s) mass %g inertia %g", what, (int) i, type == CAROM_DYNAMIC ? "dynamic" : "static",
                      m, inertia);
    }
  if (ids != stack_ids)
    free (ids);
  n = carom_world_contact_count (w);
  for (i = 0; i < n; ++i)
    {
      carom_body_id a, b;
      double px, py, nx, ny, depth, len;
      if (carom_world_get_contact (w, i, &a, &b, &px, &py, &nx, &ny, &depth) != CAROM_OK)
        FUZZ_FINDING ("%s: contact %d of %d cannot be read", what, (int) i, (int) n);
      if (!isfinite (px) || !isfinite (py) || !isfinite (nx) || !isfinite (ny) || !isfinite (depth))
        FUZZ_FINDING ("%s: contact %d not finite: p (%g, %g) n (%g, %g) depth %g", what, (int) i, px, py, nx, ny,
                      depth);
      len = sqrt (nx * nx + ny * ny);
      if (!(fabs (len - 1.0) < 1e-6))
        FUZZ_FINDING ("%s: contact %d normal (%g, %g) is not a unit vector", what, (int) i, nx, ny);
      if (carom_body_check (w, a) != CAROM_OK || carom_body_check (w, b) != CAROM_OK || a == b)
        FUZZ_FINDING ("%s: contact %d names a dead body or the same body twice", what, (int) i);
    }
  if (carom_world_get_contact (w, n, NULL, NULL, NULL, NULL, NULL, NULL, NULL) != CAROM_ERR_BAD_ARGUMENT)
    FUZZ_FINDING ("%s: contact index %d (the count) was accepted", what, (int) n);
}

#endif
