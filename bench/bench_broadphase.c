/* Collision detection alone (carom_world_detect: broad phase plus narrow
 * phase, no solver, no motion) on n boxes spread uniformly, at the rain
 * scene's density (one body of size 0.5 to 1 per 1.5 x 1.5 cell), for
 * several n. Prints, per n, the time of the first detection (a full sort)
 * and the median of later ones after every body moved a little (the
 * incremental path), in total and per body. Per-body cost that stays flat
 * as n grows means O(n) or O(n log n); growing like sqrt(n) means the
 * sweep sees whole columns of the world.
 *
 * usage: bench_broadphase [N...]   (default 1000 10000 100000) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "carom.h"
#include "scenes.h"

#define REPEATS 7

static int cmp_double (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return x < y ? -1 : x > y;
}

static int run (int n)
{
  carom_world *w = NULL;
  carom_body_id *ids = calloc ((size_t) n, sizeof *ids);
  double *x = calloc ((size_t) n, sizeof *x), *y = calloc ((size_t) n, sizeof *y);
  double side = 1.5 * sqrt ((double) n), t0, cold, warm[REPEATS];
  bench_rng r;
  int i, k, cold_contacts;
  if (!ids || !x || !y || carom_world_init (&w, NULL) != CAROM_OK)
    return -1;
  bench_rng_seed (&r, 0xb0adULL + (unsigned long long) n);
  for (i = 0; i < n; ++i)
    {
      carom_body_def bd;
      double size = bench_rng_range (&r, 0.5, 1.0);
      carom_body_def_init (&bd, sizeof bd);
      bd.x = x[i] = bench_rng_range (&r, 0.0, side);
      bd.y = y[i] = bench_rng_range (&r, 0.0, side);
      bd.angle = bench_rng_range (&r, 0.0, 6.283185307179586);
      if (carom_world_add_box (w, &bd, size, size, &ids[i]) != CAROM_OK)
        return -1;
    }
  t0 = bench_now ();
  if (carom_world_detect (w) != CAROM_OK)
    return -1;
  cold = bench_now () - t0;
  cold_contacts = carom_world_contact_count (w);
  for (k = 0; k < REPEATS; ++k)
    {
      /* every body moves a little, as in one step: the order stays nearly
       * sorted */
      for (i = 0; i < n; ++i)
        {
          x[i] += bench_rng_range (&r, -0.02, 0.02);
          y[i] += bench_rng_range (&r, -0.02, 0.02);
          carom_body_set_position (w, ids[i], x[i], y[i]);
        }
      t0 = bench_now ();
      if (carom_world_detect (w) != CAROM_OK)
        return -1;
      warm[k] = bench_now () - t0;
    }
  qsort (warm, REPEATS, sizeof warm[0], cmp_double);
  printf ("engine=carom bench=detect bodies=%d contacts=%d first_ms=%.3f first_ns_per_body=%.1f moved_ms=%.3f "
          "moved_ns_per_body=%.1f\n",
          n, cold_contacts, 1e3 * cold, 1e9 * cold / n, 1e3 * warm[REPEATS / 2], 1e9 * warm[REPEATS / 2] / n);
  fflush (stdout);
  carom_world_destroy (w);
  free (ids);
  free (x);
  free (y);
  return 0;
}

int main (int argc, char **argv)
{
  static const int defaults[] = { 1000, 10000, 100000 };
  int i;
  if (argc > 1)
    {
      for (i = 1; i < argc; ++i)
        if (atoi (argv[i]) < 1 || run (atoi (argv[i])) < 0)
          return 1;
      return 0;
    }
  for (i = 0; i < 3; ++i)
    if (run (defaults[i]) < 0)
      return 1;
  return 0;
}
