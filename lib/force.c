/* Forces and impulses a program applies (force.h). */
#include "force.h"

#include "def.h"
#include "solver.h"
#include "world.h"

/* The dynamic body `id` names, woken, or the status that refuses it. */
static carom_status dynamic_body (carom_world *world, carom_body_id id, body **out)
{
  body *b;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  b = body_lookup (world, id);
  if (!b)
    return CAROM_ERR_STALE_BODY;
  if (b->type != CAROM_DYNAMIC)
    return CAROM_ERR_STATIC_BODY;
  *out = b;
  return CAROM_OK;
}

static carom_status check_numbers (double a, double b, double c, double d)
{
  if (!is_finite (a) || !is_finite (b) || !is_finite (c) || !is_finite (d))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (a) || !is_moderate (b) || !is_moderate (c) || !is_moderate (d))
    return CAROM_ERR_BAD_ARGUMENT;
  return CAROM_OK;
}

/* Adds a force and a torque, refusing sums beyond CAROM_MAX_MAGNITUDE. */
static carom_status add_force (carom_world *world, body *b, vec2 f, double torque)
{
  vec2 nf = v2_add (b->force, f);
  double nt = b->torque + torque;
  if (!is_moderate (nf.x) || !is_moderate (nf.y) || !is_moderate (nt))
    return CAROM_ERR_BAD_ARGUMENT;
  b->force = nf;
  b->torque = nt;
  world->forces_active = 1;
  body_wake (b);
  return CAROM_OK;
}

carom_status carom_body_apply_force (carom_world *world, carom_body_id id, double fx, double fy, double px,
                                     double py)
{
  body *b;
  carom_status st = dynamic_body (world, id, &b);
  vec2 f = v2 (fx, fy);
  if (st == CAROM_OK)
    st = check_numbers (fx, fy, px, py);
  if (st != CAROM_OK)
    return st;
  /* the torque of F about the centre of mass: (p - c) x F */
  return add_force (world, b, f, v2_cross (v2_sub (v2 (px, py), b->p), f));
}

carom_status carom_body_apply_torque (carom_world *world, carom_body_id id, double torque)
{
  body *b;
  carom_status st = dynamic_body (world, id, &b);
  if (st == CAROM_OK)
    st = check_numbers (torque, 0.0, 0.0, 0.0);
  if (st != CAROM_OK)
    return st;
  return add_force (world, b, v2 (0.0, 0.0), torque);
}

/* v += dv, w += dw, refusing results beyond CAROM_MAX_MAGNITUDE. */
static carom_status change_velocity (body *b, vec2 dv, double dw)
{
  vec2 v = v2_add (b->v, dv);
  double w = b->w + dw;
  if (!is_finite (v.x) || !is_finite (v.y) || !is_finite (w) || !is_moderate (v.x) || !is_moderate (v.y)
      || !is_moderate (w))
    return CAROM_ERR_BAD_ARGUMENT;
  b->v = v;
  b->w = w;
  return CAROM_OK;
}

carom_status carom_body_apply_impulse (carom_world *world, carom_body_id id, double jx, double jy, double px,
                                       double py)
{
  body *b;
  vec2 j = v2 (jx, jy);
  carom_status st = dynamic_body (world, id, &b);
  if (st == CAROM_OK)
    st = check_numbers (jx, jy, px, py);
  if (st != CAROM_OK)
    return st;
  body_wake (b); /* a sleeping body's inverse masses are 0 until then */
  /* eq. 3.23's effect on one body: dv = J / m, dw = (p - c) x J / I */
  return change_velocity (b, v2_scale (j, b->inv_mass), v2_cross (v2_sub (v2 (px, py), b->p), j) * b->inv_inertia);
}

carom_status carom_body_apply_angular_impulse (carom_world *world, carom_body_id id, double j)
{
  body *b;
  carom_status st = dynamic_body (world, id, &b);
  if (st == CAROM_OK)
    st = check_numbers (j, 0.0, 0.0, 0.0);
  if (st != CAROM_OK)
    return st;
  body_wake (b);
  return change_velocity (b, v2 (0.0, 0.0), j * b->inv_inertia);
}

carom_status force_check (const carom_world *world, double dt)
{
  int32_t i;
  if (!world->forces_active)
    return CAROM_OK;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      double dv, dw;
      if (!b->alive || b->type != CAROM_DYNAMIC)
        continue;
      dv = v2_len (b->force) * (1.0 / b->mass) * dt;
      dw = fabs (b->torque) * (b->fixed_rotation ? 0.0 : 1.0 / b->inertia) * dt;
      if (!is_moderate (dv) || !is_moderate (dw) || !is_moderate (b->v.x + dv) || !is_moderate (b->w + dw))
        return CAROM_ERR_BAD_ARGUMENT;
    }
  return CAROM_OK;
}

void force_kick (carom_world *world, const step_context *ctx)
{
  solver_body *sb = world->solver_bodies;
  int32_t i;
  if (!world->forces_active)
    return;
  for (i = 0; i < world->slot_count; ++i)
    if (sb[i].moves == MOVES_DYNAMIC)
      {
        const body *b = &world->bodies[i];
        sb[i].v = v2_mad (sb[i].v, sb[i].im * ctx->h, b->force);
        sb[i].w += b->torque * (sb[i].ii * ctx->h);
      }
}

void force_drift_undo (carom_world *world, const step_context *ctx)
{
  solver_body *sb = world->solver_bodies;
  int32_t i;
  if (!world->forces_active)
    return;
  for (i = 0; i < world->slot_count; ++i)
    if (sb[i].moves == MOVES_DYNAMIC && !sb[i].constrained)
      sb[i].dp = v2_mad (sb[i].dp, -0.5 * ctx->h * (sb[i].im * ctx->h), world->bodies[i].force);
}

void force_clear (carom_world *world)
{
  int32_t i;
  if (!world->forces_active)
    return;
  for (i = 0; i < world->slot_count; ++i)
    {
      world->bodies[i].force = v2 (0.0, 0.0);
      world->bodies[i].torque = 0.0;
    }
  world->forces_active = 0;
}

carom_status carom_world_clear_forces (carom_world *world)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  force_clear (world);
  return CAROM_OK;
}
