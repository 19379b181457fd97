#include "gravity.h"

#include "world.h"

void gravity_update (carom_world *world, double h)
{
  vec2 dv = v2_scale (world->gravity, h);
  int32_t i;
  if (world->gravity.x == 0.0 && world->gravity.y == 0.0)
    return;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (b->alive && b->inv_mass > 0.0)
        b->v = v2_add (b->v, dv);
    }
}
