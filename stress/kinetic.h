/* Shared by the stress programs (stress.c, solver2d.c). */
#ifndef CAROM_STRESS_KINETIC_H
#define CAROM_STRESS_KINETIC_H

#include "carom.h"

/* Kinetic energy, translational and rotational, of the bodies `ids`. */
static double kinetic (const carom_world *w, const carom_body_id *ids, int n)
{
  double e = 0.0;
  int i;
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

#endif
