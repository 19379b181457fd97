/* The switches of the optional stages (see carom_effect) and the report of
 * which are on. Each stage tests its own switch once per sub-step, so an
 * effect that is off costs nothing per body or per contact. */
#include "world.h"

static const char *const effect_names[] = {
  "gravity", "central-gravity", "restitution", "friction", "fixed-rotation", "damping", "sleeping", "continuous", "joints",
};

const char *carom_effect_name (carom_effect effect)
{
  size_t i;
  for (i = 0; i < sizeof effect_names / sizeof effect_names[0]; ++i)
    if ((uint32_t) effect == 1u << i)
      return effect_names[i];
  return NULL;
}

uint32_t carom_world_get_effects (const carom_world *world)
{
  uint32_t e = 0;
  int32_t i;
  if (!world)
    return 0;
  if (world->gravity.x != 0.0 || world->gravity.y != 0.0)
    e |= CAROM_EFFECT_GRAVITY;
  if (world->central.active)
    e |= CAROM_EFFECT_CENTRAL_GRAVITY;
  if (world->def.restitution > 0.0)
    e |= CAROM_EFFECT_RESTITUTION;
  if (world->def.friction > 0.0)
    e |= CAROM_EFFECT_FRICTION;
  if (world->damping_linear > 0.0 || world->damping_angular > 0.0)
    e |= CAROM_EFFECT_DAMPING;
  if (world->sleeping)
    e |= CAROM_EFFECT_SLEEPING;
  if (world->continuous)
    e |= CAROM_EFFECT_CONTINUOUS;
  if (world->joints.live > 0)
    e |= CAROM_EFFECT_JOINTS;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      if (!b->alive)
        continue;
      if (b->restitution > 0.0)
        e |= CAROM_EFFECT_RESTITUTION;
      if (b->friction > 0.0)
        e |= CAROM_EFFECT_FRICTION;
      if (b->fixed_rotation)
        e |= CAROM_EFFECT_FIXED_ROTATION;
      if (b->bullet)
        e |= CAROM_EFFECT_CONTINUOUS;
    }
  return e;
}

carom_status carom_world_set_restitution (carom_world *world, double restitution)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!is_finite (restitution))
    return CAROM_ERR_NOT_FINITE;
  if (restitution < 0.0 || restitution > 1.0)
    return CAROM_ERR_BAD_ARGUMENT;
  world->def.restitution = restitution;
  return CAROM_OK;
}

carom_status carom_world_set_friction (carom_world *world, double friction)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!is_finite (friction))
    return CAROM_ERR_NOT_FINITE;
  if (friction < 0.0)
    return CAROM_ERR_BAD_ARGUMENT;
  world->def.friction = friction;
  return CAROM_OK;
}

carom_status carom_world_set_central_gravity (carom_world *world, double x, double y, double gm, double softening)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!is_finite (x) || !is_finite (y) || !is_finite (gm) || !is_finite (softening))
    return CAROM_ERR_NOT_FINITE;
  if (gm < 0.0 || softening < 0.0 || !is_moderate (x) || !is_moderate (y) || !is_moderate (gm)
      || !is_moderate (softening))
    return CAROM_ERR_BAD_ARGUMENT;
  world->central.active = gm > 0.0;
  world->central.center = v2 (x, y);
  world->central.gm = gm;
  world->central.softening2 = softening * softening;
  return CAROM_OK;
}

carom_status carom_world_set_damping (carom_world *world, double linear, double angular)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!is_finite (linear) || !is_finite (angular))
    return CAROM_ERR_NOT_FINITE;
  if (linear < 0.0 || angular < 0.0 || !is_moderate (linear) || !is_moderate (angular))
    return CAROM_ERR_BAD_ARGUMENT;
  world->damping_linear = linear;
  world->damping_angular = angular;
  return CAROM_OK;
}

carom_status carom_world_set_sleeping (carom_world *world, int32_t enabled)
{
  int32_t i;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  world->sleeping = enabled != 0;
  if (!world->sleeping)
    for (i = 0; i < world->slot_count; ++i)
      if (world->bodies[i].alive && world->bodies[i].type == CAROM_DYNAMIC)
        body_wake (&world->bodies[i]);
  return CAROM_OK;
}

carom_status carom_world_set_continuous (carom_world *world, int32_t enabled)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  world->continuous = enabled != 0;
  return CAROM_OK;
}
