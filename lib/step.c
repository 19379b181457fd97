#include "step.h"

#include "world.h"

void step_context_init (step_context *ctx, const carom_world *world, double h)
{
  ctx->h = h;
  ctx->inv_h = h > 0.0 ? 1.0 / h : 0.0;
  ctx->gravity = world->gravity;
  ctx->kick = v2_scale (world->gravity, h);
  ctx->accel = v2_len (world->gravity);
  ctx->continuous = world->continuous;
}
