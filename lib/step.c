#include "step.h"

#include "joint.h"
#include "world.h"

/* Below this multiple of what gravity adds in a step, an approach does not
 * bounce: a body resting under gravity meets its support at about one
 * step's gravity each step, and must stay resting. */
#define RESTITUTION_THRESHOLD_STEPS 2.0
void step_context_init (step_context *ctx, const carom_world *world, double dt)
{
  ctx->dt = dt;
  ctx->inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  ctx->substeps = world->def.substeps;
  ctx->iterations = world->def.iterations;
  ctx->h = dt / ctx->substeps;
  ctx->inv_h = ctx->h > 0.0 ? 1.0 / ctx->h : 0.0;
  ctx->gravity = world->gravity;
  ctx->kick = v2_scale (world->gravity, ctx->h);
  ctx->accel = v2_len (world->gravity);
  ctx->continuous = world->continuous;
  ctx->damping = world->damping_linear > 0.0 || world->damping_angular > 0.0;
  ctx->free_flight = ctx->accel == 0.0 && !world->central.active && !world->forces_active && !ctx->damping;
  ctx->damp_v = ctx->damping ? exp (-world->damping_linear * ctx->h) : 1.0;
  ctx->damp_w = ctx->damping ? exp (-world->damping_angular * ctx->h) : 1.0;
  ctx->restitution_threshold = RESTITUTION_THRESHOLD_STEPS * ctx->accel * dt;
  ctx->push_rate = world->def.position_correction * ctx->inv_h;
  ctx->joint_hold = joint_hold_soft (ctx->h);
  ctx->sensor_reach = 0.0;
  ctx->update = world->updates;
  if (world->sensor_count > 0)
    {
      int32_t i;
      for (i = 0; i < world->slot_count; ++i)
        {
          const body *b = &world->bodies[i];
          double r;
          if (!b->alive || b->sensor || b->type == CAROM_STATIC)
            continue;
          r = body_reach (b, dt, ctx->accel, 1);
          ctx->sensor_reach = r > ctx->sensor_reach ? r : ctx->sensor_reach;
        }
    }
}
