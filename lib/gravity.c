#include "gravity.h"

#include "world.h"

/* Attraction towards a point mass, 1/r^2 softened (the original
 * flying-balls' gravity.c): a = gm (c - x) / (r^2 + s^2)^(3/2). */
static vec2 central_dv (const carom_world *world, const body *b, double h)
{
  vec2 d = v2_sub (world->central.center, b->p);
  /* no closer than a millionth of the body's size: the centre itself is a
   * singularity */
  double r2 = v2_len2 (d) + world->central.softening2;
  if (r2 < 1e-12 * b->shape.size * b->shape.size)
    r2 = 1e-12 * b->shape.size * b->shape.size;
  return v2_scale (d, world->central.gm * h / (r2 * sqrt (r2)));
}

vec2 gravity_dv (const carom_world *world, const body *b, double h)
{
  vec2 dv = v2 (0.0, 0.0);
  if (!b->alive || b->inv_mass == 0.0)
    return dv;
  if (world->central.active)
    dv = central_dv (world, b, h);
  return v2_mad (dv, h, world->gravity);
}

void gravity_update (carom_world *world, const step_context *ctx)
{
  double h = ctx->h;
  vec2 dv = ctx->kick;
  int32_t i;
  if (world->central.active)
    for (i = 0; i < world->slot_count; ++i)
      {
        body *b = &world->bodies[i];
        if (b->alive && b->inv_mass > 0.0)
          b->v = v2_add (b->v, central_dv (world, b, h));
      }
  if (world->gravity.x == 0.0 && world->gravity.y == 0.0)
    return;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (b->alive && b->inv_mass > 0.0)
        b->v = v2_add (b->v, dv);
    }
}
