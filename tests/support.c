#include "support.h"

#include <math.h>
#include <stdlib.h>

int near_rel (double a, double b, double tol)
{
  double scale = fabs (a) > fabs (b) ? fabs (a) : fabs (b);
  if (scale < 1e-300)
    scale = 1e-300;
  return fabs (a - b) <= tol * scale;
}

int world_setup (void **state)
{
  carom_world *w = NULL;
  if (carom_world_init (&w, NULL) != CAROM_OK)
    return -1;
  *state = w;
  return 0;
}

int world_teardown (void **state)
{
  carom_world_destroy (*state);
  *state = NULL;
  return 0;
}

static int32_t all_bodies (const carom_world *world, carom_body_id **ids)
{
  int32_t n = carom_world_get_bodies (world, NULL, 0);
  *ids = calloc ((size_t) n + 1, sizeof **ids);
  return carom_world_get_bodies (world, *ids, n);
}

double world_kinetic_energy (const carom_world *world)
{
  carom_body_id *ids;
  int32_t n = all_bodies (world, &ids), i;
  double e = 0.0;
  for (i = 0; i < n; ++i)
    {
      double vx, vy, w, m, inertia;
      carom_body_get_velocity (world, ids[i], &vx, &vy);
      carom_body_get_spin (world, ids[i], &w);
      carom_body_get_mass (world, ids[i], &m, &inertia, NULL);
      e += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * w * w;
    }
  free (ids);
  return e;
}

void world_momentum (const carom_world *world, double *px, double *py, double *l)
{
  carom_body_id *ids;
  int32_t n = all_bodies (world, &ids), i;
  *px = *py = *l = 0.0;
  for (i = 0; i < n; ++i)
    {
      double x, y, vx, vy, w, m, inertia;
      carom_body_get_position (world, ids[i], &x, &y);
      carom_body_get_velocity (world, ids[i], &vx, &vy);
      carom_body_get_spin (world, ids[i], &w);
      carom_body_get_mass (world, ids[i], &m, &inertia, NULL);
      *px += m * vx;
      *py += m * vy;
      *l += m * (x * vy - y * vx) + inertia * w;
    }
  free (ids);
}

uint64_t world_state_hash (const carom_world *world)
{
  int32_t count = carom_world_body_count (world);
  carom_body_id *ids = malloc ((size_t) (count > 0 ? count : 1) * sizeof *ids);
  int32_t n, i;
  uint64_t h = 1469598103934665603ull;
  assert_non_null (ids);
  n = carom_world_get_bodies (world, ids, count);
  for (i = 0; i < n; ++i)
    {
      double s[6];
      size_t k;
      const unsigned char *bytes = (const unsigned char *) s;
      carom_body_get_position (world, ids[i], &s[0], &s[1]);
      carom_body_get_angle (world, ids[i], &s[2]);
      carom_body_get_velocity (world, ids[i], &s[3], &s[4]);
      carom_body_get_spin (world, ids[i], &s[5]);
      for (k = 0; k < sizeof s; ++k)
        h = (h ^ bytes[k]) * 1099511628211ull;
    }
  free (ids);
  return h;
}
