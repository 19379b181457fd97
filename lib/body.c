/* Bodies: creation with exact mass properties, removal, ids that detect
 * staleness (slot index + generation, as Box2D v3), and state accessors. */
#include "body.h"

#include <string.h>

#include "def.h"
#include "world.h"

void bodies_init (carom_world *world)
{
  world->bodies = NULL;
  world->slot_count = world->slot_cap = world->live_count = 0;
  world->free_slots = NULL;
  world->free_count = world->free_cap = 0;
}

void bodies_destroy (carom_world *world)
{
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    if (world->bodies[i].alive)
      shape_destroy (&world->bodies[i].shape, &world->allocator);
  mem_free (&world->allocator, world->bodies, (size_t) world->slot_cap * sizeof (body));
  mem_free (&world->allocator, world->free_slots, (size_t) world->free_cap * sizeof (int32_t));
  bodies_init (world);
}

carom_body_id body_id_of (const carom_world *world, int32_t slot)
{
  return ((uint64_t) world->bodies[slot].generation << 32) | (uint64_t) (uint32_t) (slot + 1);
}

body *body_lookup (const carom_world *world, carom_body_id id)
{
  uint64_t index = (id & 0xffffffffu);
  body *b;
  if (!world || index == 0 || index > (uint64_t) world->slot_count)
    return NULL;
  b = &world->bodies[index - 1];
  if (!b->alive || b->generation != (uint32_t) (id >> 32))
    return NULL;
  return b;
}

void body_sleep (body *b)
{
  b->asleep = 1;
  b->v = v2 (0.0, 0.0);
  b->w = 0.0;
  b->inv_mass = 0.0;
  b->inv_inertia = 0.0;
}

void body_wake (body *b)
{
  b->sleep_time = 0.0;
  if (!b->asleep)
    return;
  b->asleep = 0;
  b->inv_mass = 1.0 / b->mass;
  b->inv_inertia = b->fixed_rotation ? 0.0 : 1.0 / b->inertia;
}

/* A circle or polygon shape's box, `center` its centre in the body frame. */
static void part_box (const shape *s, vec2 center, xform t, vec2 *lo, vec2 *hi)
{
  int32_t i;
  if (s->kind == CAROM_SHAPE_CIRCLE)
    {
      vec2 c = xform_apply (t, center);
      *lo = v2 (c.x - s->radius, c.y - s->radius);
      *hi = v2 (c.x + s->radius, c.y + s->radius);
      return;
    }
  *lo = *hi = xform_apply (t, s->vertices[0]);
  for (i = 1; i < s->count; ++i)
    {
      vec2 v = xform_apply (t, s->vertices[i]);
      *lo = v2_min (*lo, v);
      *hi = v2_max (*hi, v);
    }
}

void body_sync (body *b)
{
  xform t;
  int32_t i;
  b->q = rot2_from_angle (b->angle);
  t.p = b->p;
  t.q = b->q;
  if (b->shape.kind != CAROM_SHAPE_COMPOUND)
    {
      part_box (&b->shape, v2 (0.0, 0.0), t, &b->box_lo, &b->box_hi);
      return;
    }
  for (i = 0; i < b->shape.part_count; ++i)
    {
      vec2 lo, hi;
      part_box (&b->shape.parts[i].s, b->shape.parts[i].center, t, &lo, &hi);
      b->box_lo = i == 0 ? lo : v2_min (b->box_lo, lo);
      b->box_hi = i == 0 ? hi : v2_max (b->box_hi, hi);
    }
}

/* ------------------------------------------------------------- creation */

static carom_status check_def (const carom_body_def *def)
{
  if (!is_finite (def->x) || !is_finite (def->y) || !is_finite (def->angle) || !is_finite (def->vx)
      || !is_finite (def->vy) || !is_finite (def->spin) || !is_finite (def->density)
      || !is_finite (def->restitution) || !is_finite (def->friction))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (def->x) || !is_moderate (def->y) || !is_moderate (def->angle) || !is_moderate (def->vx)
      || !is_moderate (def->vy) || !is_moderate (def->spin))
    return CAROM_ERR_BAD_ARGUMENT;
  if (def->type != CAROM_DYNAMIC && def->type != CAROM_STATIC && def->type != CAROM_KINEMATIC)
    return CAROM_ERR_BAD_ARGUMENT;
  if (def->density <= 0.0)
    return CAROM_ERR_BAD_DENSITY;
  if (def->restitution > 1.0)
    return CAROM_ERR_BAD_ARGUMENT;
  return CAROM_OK;
}

/* Make sure a slot is free and that removing a body later cannot fail for
 * lack of room in the free list. Changes no visible state. */
static carom_status reserve_slot (carom_world *world)
{
  if (world->live_count >= CAROM_MAX_BODIES)
    return CAROM_ERR_TOO_MANY_BODIES;
  if (world->free_count == 0
      && !mem_reserve (&world->allocator, (void **) &world->bodies, &world->slot_cap, world->slot_count + 1,
                       sizeof (body)))
    return CAROM_ERR_OUT_OF_MEMORY;
  if (!mem_reserve (&world->allocator, (void **) &world->free_slots, &world->free_cap, world->live_count + 1,
                    sizeof (int32_t)))
    return CAROM_ERR_OUT_OF_MEMORY;
  return CAROM_OK;
}

/* Sizes whose fourth power (inertia) and 1e-12 fraction (tolerances) stay
 * within doubles: from 1e-60 to 1e60 length units. */
static int size_in_range (double x)
{
  return x > 1e-60 && x < 1e60;
}

/* Mass and inertia must be usable numbers: a shape so small or large, or a
 * density so extreme, that they underflow to 0 or overflow to infinity
 * would give an infinite inverse mass and poison every contact it joins.
 * (Statics keep zero inverses and only need a finite size.) */
static carom_status check_mass (const carom_body_def *def, const shape *s)
{
  double m, inertia;
  shape_mass (s, def->density, &m, &inertia);
  if (s->kind == CAROM_SHAPE_COMPOUND)
    {
      /* the parts' own densities place the centre of mass, static or not */
      if (!(m > 0.0) || !is_finite (m) || !(inertia > 0.0) || !is_finite (inertia))
        return CAROM_ERR_BAD_DENSITY;
    }
  else if (!(s->unit_inertia > 0.0) || !is_finite (s->unit_inertia))
    return CAROM_ERR_BAD_SIZE;
  if (!(s->area > 0.0) || !is_finite (s->area) || !(s->size > 0.0) || !is_finite (s->bound_radius))
    return CAROM_ERR_BAD_SIZE;
  /* A mass outside [1e-200, 1e200], or an inertia below 1e-300, is
   * refused: a body of mass 1e-308 (finite, and so is its inverse) has
   * inverse masses so close to overflow that eq. 3.23's denominator
   * overflows at some points of a contact and not at others, and the
   * world turned to NaN. Sizes from 1e-60 to 1e60 at densities from 1e-30
   * to 1e30 stay well inside. */
  if (def->type == CAROM_DYNAMIC
      && (!(m >= MIN_MASS && m <= MAX_MASS) || !(inertia >= MIN_INERTIA) || !is_finite (inertia)))
    return CAROM_ERR_BAD_DENSITY;
  return CAROM_OK;
}

/* Place a fully built shape into a new body. Cannot fail: reserve_slot ran. */
static carom_body_id commit_body (carom_world *world, const carom_body_def *def, const shape *s)
{
  int32_t slot;
  body *b;
  uint32_t generation;
  if (world->free_count > 0)
    slot = world->free_slots[--world->free_count];
  else
    {
      slot = world->slot_count++;
      world->bodies[slot].generation = 1;
    }
  b = &world->bodies[slot];
  generation = b->generation;
  memset (b, 0, sizeof *b);
  b->generation = generation;
  b->alive = 1;
  b->type = def->type;
  b->shape = *s;
  b->p = v2 (def->x, def->y);
  b->angle = def->angle;
  b->density = def->density;
  b->restitution = def->restitution;
  b->friction = def->friction;
  b->user_data = def->user_data;
  b->category = def->category;
  b->mask = def->mask;
  b->group = def->group;
  b->sensor = def->sensor != 0;
  if (def->type == CAROM_KINEMATIC)
    {
      b->v = v2 (def->vx, def->vy);
      b->w = def->spin;
    }
  if (def->type == CAROM_DYNAMIC)
    {
      b->v = v2 (def->vx, def->vy);
      b->w = def->spin;
      shape_mass (s, def->density, &b->mass, &b->inertia);
      b->inv_mass = 1.0 / b->mass;
      b->inv_inertia = 1.0 / b->inertia;
    }
  body_sync (b);
  world->sensor_count += b->sensor;
  world->live_count++;
  world->broad.dirty = 1;
  return body_id_of (world, slot);
}

/* Read the caller's def (any known version, or NULL for the defaults) into
 * `local` and point *def at it. */
static carom_status begin_add (carom_world *world, const carom_body_def **def, carom_body_def *local)
{
  carom_status st;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  st = body_def_import (*def, local);
  if (st != CAROM_OK)
    return st;
  *def = local;
  st = check_def (*def);
  if (st != CAROM_OK)
    return st;
  return reserve_slot (world);
}

/* Check the built shape's mass and make it a body, or free it. */
static carom_status finish_add (carom_world *world, const carom_body_def *def, shape *s, carom_body_id *id)
{
  carom_body_id new_id;
  carom_status st = check_mass (def, s);
  if (st != CAROM_OK)
    {
      shape_destroy (s, &world->allocator);
      return st;
    }
  new_id = commit_body (world, def, s);
  if (id)
    *id = new_id;
  return CAROM_OK;
}

static carom_status check_radius (double radius)
{
  if (!is_finite (radius))
    return CAROM_ERR_NOT_FINITE;
  if (radius <= 0.0 || !size_in_range (radius))
    return CAROM_ERR_BAD_SIZE;
  return CAROM_OK;
}

carom_status carom_world_add_circle (carom_world *world, const carom_body_def *def, double radius, carom_body_id *id)
{
  carom_body_def defaults;
  shape s;
  carom_status st = begin_add (world, &def, &defaults);
  if (st == CAROM_OK)
    st = check_radius (radius);
  if (st != CAROM_OK)
    return st;
  shape_init_circle (&s, radius);
  return finish_add (world, def, &s, id);
}

carom_status carom_world_add_polygon (carom_world *world, const carom_body_def *def, const double *xy, int32_t count,
                                      carom_body_id *id)
{
  carom_body_def defaults;
  shape s;
  vec2 centroid; /* the body's position is its centre of mass: def->x, y */
  carom_status st = begin_add (world, &def, &defaults);
  if (st == CAROM_OK)
    st = polygon_validate (xy, count);
  if (st == CAROM_OK)
    st = shape_init_polygon (&s, &world->allocator, xy, count, &centroid);
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, &s, id);
}

carom_status carom_world_add_box (carom_world *world, const carom_body_def *def, double width, double height,
                                  carom_body_id *id)
{
  carom_body_def defaults;
  shape s;
  carom_status st = begin_add (world, &def, &defaults);
  if (st != CAROM_OK)
    return st;
  if (!is_finite (width) || !is_finite (height))
    return CAROM_ERR_NOT_FINITE;
  if (width <= 0.0 || height <= 0.0 || !size_in_range (width) || !size_in_range (height))
    return CAROM_ERR_BAD_SIZE;
  /* a plate thinner than 1e-10 of its length has no interior to collide */
  if (width < 1e-10 * height || height < 1e-10 * width)
    return CAROM_ERR_BAD_SIZE;
  st = shape_init_box (&s, &world->allocator, width, height);
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, &s, id);
}

carom_status carom_world_add_regular (carom_world *world, const carom_body_def *def, int32_t n, double side,
                                      carom_body_id *id)
{
  carom_body_def defaults;
  shape s;
  carom_status st = begin_add (world, &def, &defaults);
  if (st != CAROM_OK)
    return st;
  if (n < 3)
    return CAROM_ERR_TOO_FEW_VERTICES;
  if (n > CAROM_MAX_POLYGON_VERTICES)
    return CAROM_ERR_TOO_MANY_VERTICES;
  if (!is_finite (side))
    return CAROM_ERR_NOT_FINITE;
  if (side <= 0.0 || !size_in_range (side))
    return CAROM_ERR_BAD_SIZE;
  st = shape_init_regular (&s, &world->allocator, n, side);
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, &s, id);
}

/* ------------------------------------------------------------ compounds */

/* One shape def checked against the body's, and its part built. `xy` has
 * room for CAROM_MAX_POLYGON_VERTICES points. */
static carom_status build_part (carom_world *world, const carom_body_def *body_def, const carom_shape_def *in,
                                shape_part *part, double *xy)
{
  carom_shape_def d;
  carom_status st = shape_def_import (in, &d);
  double c, s;
  int32_t i;
  if (st != CAROM_OK)
    return st;
  if (!is_finite (d.x) || !is_finite (d.y) || !is_finite (d.angle) || !is_finite (d.density)
      || !is_finite (d.restitution) || !is_finite (d.friction))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (d.x) || !is_moderate (d.y) || !is_moderate (d.angle) || d.restitution > 1.0
      || (d.kind != CAROM_SHAPE_CIRCLE && d.kind != CAROM_SHAPE_POLYGON))
    return CAROM_ERR_BAD_ARGUMENT;
  if (d.density == 0.0)
    return CAROM_ERR_BAD_DENSITY;
  memset (part, 0, sizeof *part);
  part->density = d.density > 0.0 ? d.density : body_def->density;
  part->restitution = d.restitution;
  part->friction = d.friction;
  if (d.kind == CAROM_SHAPE_CIRCLE)
    {
      st = check_radius (d.radius);
      if (st != CAROM_OK)
        return st;
      shape_init_circle (&part->s, d.radius);
      part->center = v2 (d.x, d.y);
      return CAROM_OK;
    }
  st = polygon_validate (d.xy, d.count);
  if (st != CAROM_OK)
    return st;
  c = cos (d.angle), s = sin (d.angle);
  for (i = 0; i < d.count; ++i)
    {
      double x = d.xy[2 * i], y = d.xy[2 * i + 1];
      xy[2 * i] = d.x + (c * x - s * y);
      xy[2 * i + 1] = d.y + (s * x + c * y);
    }
  /* placed, it must still be a valid polygon: far out, rounding can merge
   * vertices (it cannot leave the range: |x| <= 1e100 and sizes < 1e60) */
  st = polygon_validate (xy, d.count);
  if (st != CAROM_OK)
    return st;
  return shape_init_polygon (&part->s, &world->allocator, xy, d.count, &part->center);
}

carom_status carom_world_add_compound (carom_world *world, const carom_body_def *def, const carom_shape_def *shapes,
                                       int32_t count, carom_body_id *id)
{
  carom_body_def defaults;
  shape_part *parts = NULL;
  double *xy = NULL;
  shape s;
  vec2 centroid; /* the union's centre of mass goes to def->x, y */
  int32_t i, built = 0;
  carom_status st = begin_add (world, &def, &defaults);
  if (st != CAROM_OK)
    return st;
  if (!shapes)
    return CAROM_ERR_NULL_ARGUMENT;
  if (count < 1 || count > CAROM_MAX_COMPOUND_SHAPES)
    return CAROM_ERR_BAD_ARGUMENT;
  parts = mem_alloc (&world->allocator, (size_t) count * sizeof (shape_part));
  xy = mem_alloc (&world->allocator, (size_t) CAROM_MAX_POLYGON_VERTICES * 2 * sizeof (double));
  st = parts && xy ? CAROM_OK : CAROM_ERR_OUT_OF_MEMORY;
  for (i = 0; i < count && st == CAROM_OK; ++i)
    {
      st = build_part (world, def, &shapes[i], &parts[i], xy);
      built += st == CAROM_OK;
    }
  if (st == CAROM_OK)
    st = shape_init_compound (&s, &world->allocator, parts, count, &centroid);
  if (st != CAROM_OK)
    for (i = 0; i < built; ++i)
      shape_destroy (&parts[i].s, &world->allocator);
  mem_free (&world->allocator, parts, (size_t) count * sizeof (shape_part));
  mem_free (&world->allocator, xy, (size_t) CAROM_MAX_POLYGON_VERTICES * 2 * sizeof (double));
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, &s, id);
}

carom_status carom_world_remove_body (carom_world *world, carom_body_id id)
{
  body *b;
  int32_t slot;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  b = body_lookup (world, id);
  if (!b)
    return CAROM_ERR_STALE_BODY;
  slot = (int32_t) (b - world->bodies);
  contacts_forget_body (world, slot); /* also wakes the bodies it touched */
  shape_destroy (&b->shape, &world->allocator);
  world->sensor_count -= b->sensor;
  b->alive = 0;
  b->generation = b->generation == UINT32_MAX ? 1 : b->generation + 1;
  world->free_slots[world->free_count++] = slot; /* room reserved at creation */
  world->live_count--;
  world->broad.dirty = 1;
  return CAROM_OK;
}

carom_status carom_body_check (const carom_world *world, carom_body_id id)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  return body_lookup (world, id) ? CAROM_OK : CAROM_ERR_STALE_BODY;
}

int32_t carom_world_body_count (const carom_world *world)
{
  return world ? world->live_count : 0;
}

int32_t carom_world_get_bodies (const carom_world *world, carom_body_id *ids, int32_t capacity)
{
  int32_t i, k = 0;
  if (!world)
    return 0;
  for (i = 0; i < world->slot_count; ++i)
    if (world->bodies[i].alive)
      {
        if (ids && k < capacity)
          ids[k] = body_id_of (world, i);
        k++;
      }
  return k;
}

/* ------------------------------------------------------------ accessors */

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
