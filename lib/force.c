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

/* An impulse j at the world point p, eq. 3.23's effect on one body:
 * v += j / m, w += ((p - c) x j + angular) / I, with the inverses of the
 * awake body (a sleeping one keeps 0 until woken). A result beyond
 * CAROM_MAX_MAGNITUDE is refused, and then nothing changes, sleep
 * included; otherwise the body wakes. */
static carom_status apply_impulse (body *b, vec2 j, vec2 p, double angular)
{
  double im = 1.0 / b->mass, ii = b->fixed_rotation ? 0.0 : 1.0 / b->inertia;
  vec2 v = v2_mad (b->v, im, j);
  double w = b->w + (v2_cross (v2_sub (p, b->p), j) + angular) * ii;
  if (!is_finite (v.x) || !is_finite (v.y) || !is_finite (w) || !is_moderate (v.x) || !is_moderate (v.y)
      || !is_moderate (w))
    return CAROM_ERR_BAD_ARGUMENT;
  body_wake (b);
  b->v = v;
  b->w = w;
  return CAROM_OK;
}

carom_status carom_body_apply_impulse (carom_world *world, carom_body_id id, double jx, double jy, double px,
                                       double py)
{
  body *b;
  carom_status st = dynamic_body (world, id, &b);
  if (st == CAROM_OK)
    st = check_numbers (jx, jy, px, py);
  if (st != CAROM_OK)
    return st;
  return apply_impulse (b, v2 (jx, jy), v2 (px, py), 0.0);
}

carom_status carom_body_apply_angular_impulse (carom_world *world, carom_body_id id, double j)
{
  body *b;
  carom_status st = dynamic_body (world, id, &b);
  if (st == CAROM_OK)
    st = check_numbers (j, 0.0, 0.0, 0.0);
  if (st != CAROM_OK)
    return st;
  return apply_impulse (b, v2 (0.0, 0.0), b->p, j);
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
