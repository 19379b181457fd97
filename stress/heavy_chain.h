/* The heavy chain, shared by stress/stress.c (case 18) and
 * tests/test_joints.c. */
#ifndef CAROM_STRESS_HEAVY_CHAIN_H
#define CAROM_STRESS_HEAVY_CHAIN_H

#include <math.h>

#include "carom.h"

/* A chain of 40 links (0.25 x 0.05 boxes on revolute joints) hung from the
 * world by its first link, holding a 0.5 x 0.5 box of 100 links' mass, in a
 * world at the library defaults with gravity (0, -g): hanging straight down
 * (horizontal 0), or let go horizontal but for `tilt` (radians up). After
 * each of `steps` updates of 1/60 s, its joints' gaps summed over its
 * length: returns the largest, or -1 when a call fails. */
static double heavy_chain_stretch (double g, int horizontal, double tilt, int steps)
{
  enum { LINKS = 40 };
  const double link = 0.25, side = 0.5, hpi = 1.57079632679489661923;
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_joint_def jd;
  carom_joint_id joints[LINKS + 1];
  carom_body_id prev = CAROM_NULL_BODY, id;
  double m, worst = 0.0;
  int i, s, ok;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -g;
  if (carom_world_init (&w, &def) != CAROM_OK)
    return -1.0;
  carom_body_def_init (&d, sizeof d);
  carom_joint_def_init (&jd, sizeof jd);
  jd.type = CAROM_JOINT_REVOLUTE;
  for (i = 0, ok = 1; i <= LINKS && ok; ++i)
    {
      double along = i < LINKS ? (i + 0.5) * link : LINKS * link + side / 2.0;
      d.x = horizontal ? along * cos (tilt) : 0.0;
      d.y = horizontal ? along * sin (tilt) : -along;
      d.angle = horizontal ? tilt : i == LINKS ? 0.0 : hpi;
      if (i < LINKS)
        ok = carom_world_add_box (w, &d, link, 0.05, &id) == CAROM_OK;
      else
        {
          ok = carom_body_get_mass (w, prev, &m, NULL, NULL) == CAROM_OK;
          d.density = 100.0 * m / (side * side);
          ok = ok && carom_world_add_box (w, &d, side, side, &id) == CAROM_OK;
        }
      jd.a = prev, jd.b = id;
      jd.x = horizontal ? i * link * cos (tilt) : 0.0;
      jd.y = horizontal ? i * link * sin (tilt) : -i * link;
      ok = ok && carom_world_add_joint (w, &jd, &joints[i]) == CAROM_OK;
      prev = id;
    }
  for (s = 0; s < steps && ok; ++s)
    {
      double gaps = 0.0;
      ok = carom_world_update (w, 1.0 / 60.0) == CAROM_OK;
      for (i = 0; i <= LINKS && ok; ++i)
        {
          double ax, ay, bx, by;
          ok = carom_joint_get_anchors (w, joints[i], &ax, &ay, &bx, &by) == CAROM_OK;
          gaps += ok ? hypot (bx - ax, by - ay) : 0.0;
        }
      gaps /= LINKS * link;
      worst = gaps > worst ? gaps : worst;
    }
  carom_world_destroy (w);
  return ok ? worst : -1.0;
}

#endif
