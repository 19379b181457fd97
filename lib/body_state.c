/* A body's state and what it is made of, read and set through the public
 * API by id. */
#include "body.h"

#include "world.h"

#define LOOKUP(world, id, b)                                                   \
  do {                                                                         \
    if (!(world))                                                              \
      return CAROM_ERR_NULL_ARGUMENT;                                          \
    (b) = body_lookup ((world), (id));                                         \
    if (!(b))                                                                  \
      return CAROM_ERR_STALE_BODY;                                             \
  } while (0)

carom_status carom_body_get_position (const carom_world *world, carom_body_id id, double *x, double *y)
{
  const body *b;
  LOOKUP (world, id, b);
  if (x)
    *x = b->p.x;
  if (y)
    *y = b->p.y;
  return CAROM_OK;
}

carom_status carom_body_set_position (carom_world *world, carom_body_id id, double x, double y)
{
  body *b;
  LOOKUP (world, id, b);
  if (!is_finite (x) || !is_finite (y))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (x) || !is_moderate (y))
    return CAROM_ERR_BAD_ARGUMENT;
  b->p = v2 (x, y);
  body_wake (b);
  body_sync (b);
  world->seams_dirty |= b->type == CAROM_STATIC;
  return CAROM_OK;
}

carom_status carom_body_get_angle (const carom_world *world, carom_body_id id, double *angle)
{
  const body *b;
  LOOKUP (world, id, b);
  if (angle)
    *angle = b->angle;
  return CAROM_OK;
}

carom_status carom_body_set_angle (carom_world *world, carom_body_id id, double angle)
{
  body *b;
  LOOKUP (world, id, b);
  if (!is_finite (angle))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (angle))
    return CAROM_ERR_BAD_ARGUMENT;
  b->angle = angle;
  body_wake (b);
  body_sync (b);
  world->seams_dirty |= b->type == CAROM_STATIC;
  return CAROM_OK;
}

carom_status carom_body_get_velocity (const carom_world *world, carom_body_id id, double *vx, double *vy)
{
  const body *b;
  LOOKUP (world, id, b);
  if (vx)
    *vx = b->v.x;
  if (vy)
    *vy = b->v.y;
  return CAROM_OK;
}

carom_status carom_body_set_velocity (carom_world *world, carom_body_id id, double vx, double vy)
{
  body *b;
  LOOKUP (world, id, b);
  if (!is_finite (vx) || !is_finite (vy))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (vx) || !is_moderate (vy))
    return CAROM_ERR_BAD_ARGUMENT;
  if (b->type == CAROM_STATIC)
    return CAROM_ERR_STATIC_BODY;
  body_wake (b);
  b->v = v2 (vx, vy);
  return CAROM_OK;
}

carom_status carom_body_get_spin (const carom_world *world, carom_body_id id, double *spin)
{
  const body *b;
  LOOKUP (world, id, b);
  if (spin)
    *spin = b->w;
  return CAROM_OK;
}

carom_status carom_body_is_awake (const carom_world *world, carom_body_id id, int32_t *awake)
{
  const body *b;
  LOOKUP (world, id, b);
  if (awake)
    *awake = !b->asleep;
  return CAROM_OK;
}

carom_status carom_body_wake (carom_world *world, carom_body_id id)
{
  body *b;
  LOOKUP (world, id, b);
  body_wake (b);
  return CAROM_OK;
}

carom_status carom_body_set_bullet (carom_world *world, carom_body_id id, int32_t bullet)
{
  body *b;
  LOOKUP (world, id, b);
  b->bullet = bullet != 0;
  return CAROM_OK;
}

carom_status carom_body_set_fixed_rotation (carom_world *world, carom_body_id id, int32_t fixed)
{
  body *b;
  LOOKUP (world, id, b);
  if (b->type != CAROM_DYNAMIC)
    return CAROM_ERR_STATIC_BODY;
  body_wake (b);
  b->fixed_rotation = fixed != 0;
  b->w = fixed ? 0.0 : b->w;
  b->inv_inertia = fixed ? 0.0 : 1.0 / b->inertia;
  return CAROM_OK;
}

carom_status carom_body_set_spin (carom_world *world, carom_body_id id, double spin)
{
  body *b;
  LOOKUP (world, id, b);
  if (!is_finite (spin))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (spin))
    return CAROM_ERR_BAD_ARGUMENT;
  if (b->type == CAROM_STATIC)
    return CAROM_ERR_STATIC_BODY;
  if (b->fixed_rotation && spin != 0.0)
    return CAROM_ERR_BAD_ARGUMENT; /* a non-rotating body never rotates */
  body_wake (b);
  b->w = spin;
  return CAROM_OK;
}

carom_status carom_body_get_mass (const carom_world *world, carom_body_id id, double *mass, double *inertia,
                                  double *area)
{
  const body *b;
  LOOKUP (world, id, b);
  if (mass)
    *mass = b->mass;
  if (inertia)
    *inertia = b->inertia;
  if (area)
    *area = b->shape.area;
  return CAROM_OK;
}

carom_status carom_body_get_type (const carom_world *world, carom_body_id id, carom_body_type *type)
{
  const body *b;
  LOOKUP (world, id, b);
  if (type)
    *type = b->type;
  return CAROM_OK;
}

carom_status carom_body_get_shape (const carom_world *world, carom_body_id id, carom_shape_kind *kind, double *radius)
{
  const body *b;
  LOOKUP (world, id, b);
  if (kind)
    *kind = b->shape.kind;
  if (radius)
    *radius = b->shape.kind == CAROM_SHAPE_CIRCLE ? b->shape.radius : b->shape.bound_radius;
  return CAROM_OK;
}

carom_status carom_body_get_material (const carom_world *world, carom_body_id id, double *restitution,
                                      double *friction)
{
  const body *b;
  LOOKUP (world, id, b);
  if (restitution)
    *restitution = b->restitution >= 0.0 ? b->restitution : world->def.restitution;
  if (friction)
    *friction = b->friction >= 0.0 ? b->friction : world->def.friction;
  return CAROM_OK;
}

carom_status carom_body_get_vertices (const carom_world *world, carom_body_id id, double *xy, int32_t capacity,
                                      int32_t *count)
{
  const body *b;
  xform t;
  int32_t i;
  LOOKUP (world, id, b);
  if (count)
    *count = b->shape.kind == CAROM_SHAPE_POLYGON ? b->shape.count : 0;
  if (b->shape.kind != CAROM_SHAPE_POLYGON || !xy)
    return CAROM_OK;
  t.p = b->p;
  t.q = b->q;
  for (i = 0; i < b->shape.count && i < capacity; ++i)
    {
      vec2 v = xform_apply (t, b->shape.vertices[i]);
      xy[2 * i] = v.x;
      xy[2 * i + 1] = v.y;
    }
  return CAROM_OK;
}

carom_status carom_body_get_shape_count (const carom_world *world, carom_body_id id, int32_t *count)
{
  const body *b;
  LOOKUP (world, id, b);
  if (count)
    *count = shape_part_count (&b->shape);
  return CAROM_OK;
}

carom_status carom_body_get_shape_geometry (const carom_world *world, carom_body_id id, int32_t index,
                                            carom_shape_kind *kind, double *x, double *y, double *radius, double *xy,
                                            int32_t capacity, int32_t *count)
{
  const body *b;
  const shape *s;
  vec2 center;
  xform t;
  int32_t i;
  LOOKUP (world, id, b);
  if (index < 0 || index >= shape_part_count (&b->shape) || capacity < 0)
    return CAROM_ERR_BAD_ARGUMENT;
  if (xy == NULL && capacity > 0)
    return CAROM_ERR_NULL_ARGUMENT;
  s = shape_part_at (&b->shape, index, &center);
  t.p = b->p;
  t.q = b->q;
  center = xform_apply (t, center);
  if (kind)
    *kind = s->kind;
  if (x)
    *x = center.x;
  if (y)
    *y = center.y;
  if (radius)
    *radius = s->kind == CAROM_SHAPE_CIRCLE ? s->radius : s->bound_radius;
  if (count)
    *count = s->kind == CAROM_SHAPE_POLYGON ? s->count : 0;
  if (s->kind == CAROM_SHAPE_POLYGON)
    for (i = 0; i < s->count && i < capacity; ++i)
      {
        vec2 v = xform_apply (t, s->vertices[i]);
        xy[2 * i] = v.x;
        xy[2 * i + 1] = v.y;
      }
  return CAROM_OK;
}

carom_status carom_body_get_shape_material (const carom_world *world, carom_body_id id, int32_t index,
                                            double *density, double *restitution, double *friction)
{
  const body *b;
  double e, mu, rho;
  LOOKUP (world, id, b);
  if (index < 0 || index >= shape_part_count (&b->shape))
    return CAROM_ERR_BAD_ARGUMENT;
  e = b->restitution, mu = b->friction, rho = b->density;
  if (b->shape.kind == CAROM_SHAPE_COMPOUND)
    {
      const shape_part *p = &b->shape.parts[index];
      rho = p->density;
      if (p->restitution >= 0.0)
        e = p->restitution;
      if (p->friction >= 0.0)
        mu = p->friction;
    }
  if (density)
    *density = rho;
  if (restitution)
    *restitution = e >= 0.0 ? e : world->def.restitution;
  if (friction)
    *friction = mu >= 0.0 ? mu : world->def.friction;
  return CAROM_OK;
}

carom_status carom_body_get_user_data (const carom_world *world, carom_body_id id, void **data)
{
  const body *b;
  LOOKUP (world, id, b);
  if (data)
    *data = b->user_data;
  return CAROM_OK;
}

carom_status carom_body_set_user_data (carom_world *world, carom_body_id id, void *data)
{
  body *b;
  LOOKUP (world, id, b);
  b->user_data = data;
  return CAROM_OK;
}

carom_status carom_body_set_filter (carom_world *world, carom_body_id id, uint32_t category, uint32_t mask,
                                    int32_t group)
{
  body *b;
  LOOKUP (world, id, b);
  b->category = category;
  b->mask = mask;
  b->group = group;
  /* a body asleep on what it may no longer touch must fall */
  body_wake (b);
  return CAROM_OK;
}

carom_status carom_body_get_filter (const carom_world *world, carom_body_id id, uint32_t *category, uint32_t *mask,
                                    int32_t *group)
{
  const body *b;
  LOOKUP (world, id, b);
  if (category)
    *category = b->category;
  if (mask)
    *mask = b->mask;
  if (group)
    *group = b->group;
  return CAROM_OK;
}

carom_status carom_body_is_sensor (const carom_world *world, carom_body_id id, int32_t *sensor)
{
  const body *b;
  LOOKUP (world, id, b);
  if (sensor)
    *sensor = b->sensor;
  return CAROM_OK;
}
