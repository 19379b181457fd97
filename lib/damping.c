#include "damping.h"

#include "solver.h"
#include "world.h"

void damping_update (carom_world *world, const step_context *ctx)
{
  solver_body *sb = world->solver_bodies;
  int32_t i;
  if (!ctx->damping)
    return;
  /* exp(-c h) per sub-step compounds to exactly exp(-c t) at every step */
  for (i = 0; i < world->slot_count; ++i)
    if (sb[i].moves == MOVES_DYNAMIC)
      {
        sb[i].v = v2_scale (sb[i].v, ctx->damp_v);
        sb[i].w *= ctx->damp_w;
      }
}
