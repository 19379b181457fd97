#include "gravity.h"

#include "world.h"

/* Attraction towards a point mass, 1/r^2 softened (the original
 * flying-balls' gravity.c): a = gm (c - x) / (r^2 + s^2)^(3/2), with x where
 * the body is now within the step. */
static vec2 central_dv (const carom_world *world, const body *b, vec2 x, double h)
{
  vec2 d = v2_sub (world->central.center, x);
  /* no closer than a millionth of the body's size: the centre itself is a
   * singularity */
  double r2 = v2_len2 (d) + world->central.softening2;
  if (r2 < 1e-12 * b->shape.size * b->shape.size)
    r2 = 1e-12 * b->shape.size * b->shape.size;
  return v2_scale (d, world->central.gm * h / (r2 * sqrt (r2)));
}

void gravity_kick (carom_world *world, const step_context *ctx)
{
  solver_body *sb = world->solver_bodies;
  int32_t i;
  if (world->central.active)
    for (i = 0; i < world->slot_count; ++i)
      if (sb[i].moves == MOVES_DYNAMIC)
        {
          const body *b = &world->bodies[i];
          sb[i].v = v2_add (sb[i].v, central_dv (world, b, v2_add (b->p, sb[i].dp), ctx->h));
        }
  if (ctx->gravity.x == 0.0 && ctx->gravity.y == 0.0)
    return;
  {
    /* in locals: the stores to the velocities might alias them as far as
     * the compiler knows */
    vec2 kick = ctx->kick;
    int32_t n = world->slot_count;
    for (i = 0; i < n; ++i)
      if (sb[i].moves == MOVES_DYNAMIC)
        sb[i].v = v2_add (sb[i].v, kick);
  }
}

/* Bodies held by joints move by leapfrog (RATTLE, with the joints'
 * projections, joint_tree.c): half of the sub-step's uniform kick before
 * the move, half after it, so a swing's energy error is second order in
 * the sub-step instead of first. gravity_joint_hold takes the second half
 * back after gravity_kick; gravity_joint_kick gives it after the move. */
static void joint_half_kick (carom_world *world, const step_context *ctx, double sign)
{
  solver_body *sb = world->solver_bodies;
  vec2 half = v2_scale (ctx->kick, 0.5 * sign);
  int32_t i;
  if (ctx->gravity.x == 0.0 && ctx->gravity.y == 0.0)
    return;
  for (i = 0; i < world->slot_count; ++i)
    if (sb[i].constrained & CONSTRAINED_JOINT)
      sb[i].v = v2_add (sb[i].v, half);
}

void gravity_joint_hold (carom_world *world, const step_context *ctx)
{
  joint_half_kick (world, ctx, -1.0);
}

void gravity_joint_kick (carom_world *world, const step_context *ctx)
{
  joint_half_kick (world, ctx, 1.0);
}
