/* Making bodies: each carom_world_add_* call checks its def and sizes,
 * builds the shape (shape.c, where every mass formula lives), checks the
 * mass it gives and places the body in the store (body.c). Nothing changes
 * on any error. */
#include "body.h"

#include <string.h>

#include "def.h"
#include "world.h"

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
  return body_reserve_slot (world);
}

/* After building the shape (st its status): check its mass and make it a
 * body, or free it. */
static carom_status finish_add (carom_world *world, const carom_body_def *def, carom_status st, shape *s,
                                carom_body_id *id)
{
  carom_body_id new_id;
  if (st != CAROM_OK)
    return st;
  st = check_mass (def, s);
  if (st != CAROM_OK)
    {
      shape_destroy (s, &world->allocator);
      return st;
    }
  new_id = body_commit (world, def, s);
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
  return finish_add (world, def, shape_init_circle (&s, radius), &s, id);
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
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, shape_init_polygon (&s, &world->allocator, xy, count, &centroid), &s, id);
}

/* A box's sizes; a plate thinner than 1e-10 of its length has no interior
 * to collide. */
static carom_status check_box (double width, double height)
{
  if (!is_finite (width) || !is_finite (height))
    return CAROM_ERR_NOT_FINITE;
  if (width <= 0.0 || height <= 0.0 || !size_in_range (width) || !size_in_range (height))
    return CAROM_ERR_BAD_SIZE;
  if (width < 1e-10 * height || height < 1e-10 * width)
    return CAROM_ERR_BAD_SIZE;
  return CAROM_OK;
}

carom_status carom_world_add_box (carom_world *world, const carom_body_def *def, double width, double height,
                                  carom_body_id *id)
{
  carom_body_def defaults;
  shape s;
  carom_status st = begin_add (world, &def, &defaults);
  if (st == CAROM_OK)
    st = check_box (width, height);
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, shape_init_box (&s, &world->allocator, width, height), &s, id);
}

static carom_status check_regular (int32_t n, double side)
{
  if (n < 3)
    return CAROM_ERR_TOO_FEW_VERTICES;
  if (n > CAROM_MAX_POLYGON_VERTICES)
    return CAROM_ERR_TOO_MANY_VERTICES;
  if (!is_finite (side))
    return CAROM_ERR_NOT_FINITE;
  if (side <= 0.0 || !size_in_range (side))
    return CAROM_ERR_BAD_SIZE;
  return CAROM_OK;
}

carom_status carom_world_add_regular (carom_world *world, const carom_body_def *def, int32_t n, double side,
                                      carom_body_id *id)
{
  carom_body_def defaults;
  shape s;
  carom_status st = begin_add (world, &def, &defaults);
  if (st == CAROM_OK)
    st = check_regular (n, side);
  if (st != CAROM_OK)
    return st;
  return finish_add (world, def, shape_init_regular (&s, &world->allocator, n, side), &s, id);
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
  rot2 turn;
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
  turn = rot2_from_angle (d.angle);
  c = turn.c, s = turn.s;
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
  return finish_add (world, def, st, &s, id);
}

