/* The long hard cases (docs/stability.md), run natively by `make stress`
 * and by `make check`: too long for Valgrind. Each prints its measured
 * value beside its bound; the last line counts them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "carom.h"

static int passed, failed;

static void report (const char *name, int ok, const char *fmt, double measured, double bound)
{
  printf ("%s %s: ", ok ? "ok  " : "FAIL", name);
  printf (fmt, measured, bound);
  printf ("\n");
  if (ok)
    passed++;
  else
    failed++;
}

static carom_world *load (const char *path)
{
  carom_world *w = NULL;
  carom_scene_error err;
  err.size = sizeof err;
  if (carom_scene_load_file (&w, path, NULL, &err) != CAROM_OK)
    {
      fprintf (stderr, "%s: %s\n", path, err.message);
      exit (2);
    }
  return w;
}

static double kinetic (const carom_world *w, const carom_body_id *ids, int32_t n)
{
  double e = 0.0;
  int32_t i;
  for (i = 0; i < n; ++i)
    {
      double vx, vy, s, m, inertia;
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      carom_body_get_spin (w, ids[i], &s);
      carom_body_get_mass (w, ids[i], &m, &inertia, NULL);
      e += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * s * s;
    }
  return e;
}

/* Case 2: the 20-row pyramid (scenes/pyramid.scene), 10 s. Bound: the top
 * box moves less than 1% of its size from where it was built. */
static void pyramid (void)
{
  carom_world *w = load ("scenes/pyramid.scene");
  carom_body_id ids[256];
  int32_t n = carom_world_get_bodies (w, ids, 256), i, top = 0;
  double x0, y0, x, y, best = -INFINITY;
  for (i = 0; i < n; ++i)
    {
      carom_body_get_position (w, ids[i], &x, &y);
      if (y > best)
        best = y, top = i;
    }
  carom_body_get_position (w, ids[top], &x0, &y0);
  for (i = 0; i < 600; ++i)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_position (w, ids[top], &x, &y);
  report ("pyramid: top box moved / size after 10 s", hypot (x - x0, y - y0) < 0.01, "%.5f (bound %.2f)",
          hypot (x - x0, y - y0), 0.01);
  carom_world_destroy (w);
}

/* Case 10: the elastic gas (scenes/gas.scene: 500 polygons, e = 1, no
 * friction, no gravity), 100 000 steps. Bounds: nothing NaN, every body
 * still inside the box, kinetic energy within the stated drift. */
static void gas (void)
{
  carom_world *w = load ("scenes/gas.scene");
  carom_body_id ids[600];
  int32_t n = carom_world_get_bodies (w, ids, 600), i, escaped = 0, nan = 0;
  double e0 = kinetic (w, ids, n), e1, drift;
  for (i = 0; i < 100000; ++i)
    carom_world_update (w, 1.0 / 60);
  for (i = 0; i < n; ++i)
    {
      double x, y, m;
      carom_body_get_position (w, ids[i], &x, &y);
      carom_body_get_mass (w, ids[i], &m, NULL, NULL);
      if (!isfinite (x) || !isfinite (y))
        nan++;
      else if (m > 0.0 && (x < 0.0 || x > 50.0 || y < 0.0 || y > 40.0)) /* bounds 0 0 50 40 */
        escaped++;
    }
  e1 = kinetic (w, ids, n);
  drift = e1 / e0 - 1.0;
  report ("gas: bodies with a NaN state after 100000 steps", nan == 0, "%.0f (bound %.0f)", nan, 0);
  report ("gas: bodies outside the box after 100000 steps", escaped == 0, "%.0f (bound %.0f)", escaped, 0);
  report ("gas: |kinetic energy drift| over 100000 steps at 1 sub-step", fabs (drift) < 0.10,
          "%.4f (bound %.2f)", drift, 0.10);
  carom_world_destroy (w);
}

int main (void)
{
  pyramid ();
  gas ();
  printf ("stress: %d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
