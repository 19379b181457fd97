/* The world and its update pipeline, in the flying-balls lifecycle:
 * init, update (per sub-step: detect, wake, gravity, damping, solve, drift,
 * sleep),
 * destroy. */
#include "world.h"

#include <string.h>

#include "damping.h"
#include "def.h"
#include "gravity.h"
#include "sleep.h"
#include "solver.h"
#include "step.h"

static carom_status check_def (const carom_world_def *def)
{
  if (!is_finite (def->gravity_x) || !is_finite (def->gravity_y) || !is_finite (def->restitution)
      || !is_finite (def->friction) || !is_finite (def->position_correction) || !is_finite (def->slop))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (def->gravity_x) || !is_moderate (def->gravity_y) || def->restitution < 0.0
      || def->restitution > 1.0 || def->friction < 0.0 || def->substeps < 1
      || def->substeps > 1000 || def->iterations < 1 || def->iterations > 1000 || def->position_correction < 0.0
      || def->position_correction > 1.0 || def->slop < 0.0 || def->slop > 1.0
      || (def->narrow_phase != CAROM_NARROW_SAT && def->narrow_phase != CAROM_NARROW_VERTEX_EDGE)
      || (!def->allocator.alloc != !def->allocator.free))
    return CAROM_ERR_BAD_ARGUMENT;
  return CAROM_OK;
}

carom_status carom_world_init (carom_world **world, const carom_world_def *def)
{
  carom_world_def settings;
  carom_world *w;
  carom_status st;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  *world = NULL;
  st = world_def_import (def, &settings);
  if (st != CAROM_OK)
    return st;
  def = &settings;
  st = check_def (def);
  if (st != CAROM_OK)
    return st;
  w = mem_alloc (&def->allocator, sizeof *w);
  if (!w)
    return CAROM_ERR_OUT_OF_MEMORY;
  memset (w, 0, sizeof *w);
  w->allocator = def->allocator;
  w->def = *def;
  w->gravity = v2 (def->gravity_x, def->gravity_y);
  bodies_init (w);
  broadphase_init (w);
  contacts_init (w);
  *world = w;
  return CAROM_OK;
}

void carom_world_destroy (carom_world *world)
{
  carom_allocator a;
  if (!world)
    return;
  solver_destroy (world);
  contacts_destroy (world);
  broadphase_destroy (world);
  bodies_destroy (world);
  a = world->allocator;
  mem_free (&a, world, sizeof *world);
}

/* Move every dynamic body with its velocity plus the position-correction
 * pseudo-velocity, which is then dropped. A free body moves with the mean of
 * its velocities before and after the gravity kick, x += (v - g h / 2) h,
 * which is exact for uniform gravity (x0 + v0 t + g t^2 / 2 at every step);
 * a body in contact moves with the velocity the solver left it (symplectic
 * Euler), so a body at rest stays exactly at rest with zero velocity. */
static void drift (carom_world *world, const step_context *ctx)
{
  double h = ctx->h;
  vec2 half_kick = v2_scale (ctx->kick, 0.5);
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      vec2 v;
      if (!b->alive || b->type == CAROM_STATIC || b->asleep)
        continue;
      v = b->touching ? b->v : v2_sub (b->v, half_kick);
      b->p = v2_mad (b->p, h, v2_add (v, b->pv));
      b->angle += h * (b->w + b->pw);
      b->pv = v2 (0.0, 0.0);
      b->pw = 0.0;
      b->touching = 0;
      body_sync (b);
    }
}

#ifdef CAROM_DEBUG_CHECKS
#include <stdio.h>
#include <stdlib.h>
/* The test builds' "no NaN ever" check: every state finite after every
 * sub-step, or stop at once, naming the body. */
static void check_finite (const carom_world *world)
{
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      if (b->alive
          && !(is_finite (b->p.x) && is_finite (b->p.y) && is_finite (b->angle) && is_finite (b->v.x)
               && is_finite (b->v.y) && is_finite (b->w)))
        {
          fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: body in slot %ld is not finite after a sub-step\n", (long) i);
          abort ();
        }
    }
}
#else
#define check_finite(world) ((void) 0)
#endif

static carom_status substep (carom_world *world, double h)
{
  step_context ctx;
  carom_status st;
  step_context_init (&ctx, world, h);
  st = contacts_update (world, &ctx);
  if (st != CAROM_OK)
    return st;
  if (!solver_reserve (world))
    {
      contacts_undo (world); /* nothing has changed */
      return CAROM_ERR_OUT_OF_MEMORY;
    }
  sleep_wake_touched (world);
  gravity_update (world, &ctx);
  damping_update (world, &ctx);
  solver_update (world, &ctx);
  drift (world, &ctx);
  sleep_update (world, &ctx);
  check_finite (world);
  return CAROM_OK;
}

carom_status carom_world_update (carom_world *world, double dt)
{
  int32_t k;
  double h;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  /* 1e-100 to 1e100: divided by, and multiplied into velocities, it must
   * keep the solver's numbers within doubles */
  if (!is_finite (dt) || !(dt >= 1e-100) || dt > MAX_MAGNITUDE)
    return CAROM_ERR_BAD_TIME_STEP;
  h = dt / world->def.substeps;
  for (k = 0; k < world->def.substeps; ++k)
    {
      carom_status st = substep (world, h);
      if (st != CAROM_OK)
        return st;
    }
  return CAROM_OK;
}

carom_status carom_world_set_gravity (carom_world *world, double gx, double gy)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!is_finite (gx) || !is_finite (gy))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (gx) || !is_moderate (gy))
    return CAROM_ERR_BAD_ARGUMENT;
  world->gravity = v2 (gx, gy);
  world->def.gravity_x = gx;
  world->def.gravity_y = gy;
  return CAROM_OK;
}

carom_status carom_world_get_gravity (const carom_world *world, double *gx, double *gy)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (gx)
    *gx = world->gravity.x;
  if (gy)
    *gy = world->gravity.y;
  return CAROM_OK;
}
