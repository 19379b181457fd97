#include "damping.h"

#include "world.h"

void damping_update (carom_world *world, const step_context *ctx)
{
  double h = ctx->h;
  double kv, kw;
  int32_t i;
  if (world->damping_linear == 0.0 && world->damping_angular == 0.0)
    return;
  /* exp(-c h) per step compounds to exactly exp(-c t) at every step */
  kv = exp (-world->damping_linear * h);
  kw = exp (-world->damping_angular * h);
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (!b->alive || b->inv_mass == 0.0)
        continue;
      b->v = v2_scale (b->v, kv);
      b->w *= kw;
    }
}
