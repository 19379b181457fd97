/* The world and its update pipeline, in the flying-balls lifecycle: init,
 * update (detect, wake, the solver's sub-steps, sleep), destroy. */
#include "world.h"

#include <string.h>

#include "contact_batch.h"
#include "def.h"
#include "force.h"
#include "sleep.h"
#include "solver.h"
#include "step.h"

static carom_status check_def (const carom_world_def *def)
{
  if (!is_finite (def->gravity_x) || !is_finite (def->gravity_y) || !is_finite (def->restitution)
      || !is_finite (def->friction) || !is_finite (def->position_correction) || !is_finite (def->slop)
      || !is_finite (def->manifold_tolerance))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (def->gravity_x) || !is_moderate (def->gravity_y) || def->restitution < 0.0
      || def->restitution > 1.0 || def->friction < 0.0 || def->substeps < 1
      || def->substeps > 1000 || def->iterations < 1 || def->iterations > 1000 || def->position_correction < 0.0
      || def->position_correction > 1.0 || def->slop < 0.0 || def->slop > 1.0
      || def->manifold_tolerance < 0.0 || def->manifold_tolerance > 1.0
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
  w->solver_path = solver_path_best ();
  w->continuous = 1; /* the one effect on by default: impacts at their time, no tunnelling */
  bodies_init (w);
  broadphase_init (w);
  contacts_init (w);
  joints_init (w);
  *world = w;
  return CAROM_OK;
}

void carom_world_destroy (carom_world *world)
{
  carom_allocator a;
  if (!world)
    return;
  solver_destroy (world);
  events_destroy (world);
  contacts_destroy (world);
  joints_destroy (world);
  broadphase_destroy (world);
  bodies_destroy (world);
  a = world->allocator;
  mem_free (&a, world, sizeof *world);
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

carom_status carom_world_update (carom_world *world, double dt)
{
  step_context ctx;
  carom_status st;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  /* 1e-100 to 1e100: divided by, and multiplied into velocities, it must
   * keep the solver's numbers within doubles */
  if (!is_finite (dt) || !(dt >= 1e-100) || dt > MAX_MAGNITUDE)
    return CAROM_ERR_BAD_TIME_STEP;
  st = force_check (world, dt);
  if (st != CAROM_OK)
    return st;
  step_context_init (&ctx, world, dt);
  st = contacts_update (world, &ctx);
  if (st != CAROM_OK)
    return st;
  if (!solver_reserve (world) || !events_reserve (world))
    {
      contacts_undo (world); /* nothing has changed */
      return CAROM_ERR_OUT_OF_MEMORY;
    }
  sleep_wake_touched (world);
  solver_step (world, &ctx);
  events_update (world);
  force_clear (world);
  sleep_update (world, &ctx);
  check_finite (world);
  world->updates++;
  return CAROM_OK;
}

int world_set_solver_path (carom_world *world, int path)
{
  if (!solver_path_available ((solver_path) path))
    return 0;
  world->solver_path = path;
  return 1;
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
