#include "gravity.h"

#include "world.h"

/* Attraction towards a point mass, 1/r^2 softened (the original
 * flying-balls' gravity.c): a = gm (c - x) / (r^2 + s^2)^(3/2). */
static void central_update (carom_world *world, double h)
{
  vec2 c = world->central.center;
  double gm_h = world->central.gm * h, s2 = world->central.softening2;
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      vec2 d;
      double r2;
      if (!b->alive || b->inv_mass == 0.0)
        continue;
      d = v2_sub (c, b->p);
      /* no closer than a millionth of the body's size: the centre itself
       * is a singularity */
      r2 = v2_len2 (d) + s2;
      if (r2 < 1e-12 * b->shape.size * b->shape.size)
        r2 = 1e-12 * b->shape.size * b->shape.size;
      b->v = v2_mad (b->v, gm_h / (r2 * sqrt (r2)), d);
    }
}

void gravity_update (carom_world *world, double h)
{
  vec2 dv = v2_scale (world->gravity, h);
  int32_t i;
  if (world->central.active)
    central_update (world, h);
  if (world->gravity.x == 0.0 && world->gravity.y == 0.0)
    return;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (b->alive && b->inv_mass > 0.0)
        b->v = v2_add (b->v, dv);
    }
}
