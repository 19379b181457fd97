/* The body store: a slot array with ids that detect staleness (slot index
 * + generation, as Box2D v3), a body's placement into a slot and its
 * removal, sleep and wake, and the bounding box kept in step with its pose.
 * Bodies are made by body_create.c, read and set by body_state.c. */
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
  world->unload = NULL;
  world->unload_cap = 0;
}

void bodies_destroy (carom_world *world)
{
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    if (world->bodies[i].alive)
      shape_destroy (&world->bodies[i].shape, &world->allocator);
  mem_free (&world->allocator, world->bodies, (size_t) world->slot_cap * sizeof (body));
  mem_free (&world->allocator, world->free_slots, (size_t) world->free_cap * sizeof (int32_t));
  mem_free (&world->allocator, world->unload, (size_t) world->unload_cap * sizeof (double));
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

#ifdef __SSE2__
#include <emmintrin.h>

/* xform_apply of the vertex v as a pair of lanes, the rotation given as
 * (c, s) and (-s, c) and the translation as (p.x, p.y). */
ALWAYS_INLINE __m128d turn_move (__m128d cs, __m128d nsc, __m128d p, const vec2 *v)
{
  return _mm_add_pd (_mm_add_pd (_mm_mul_pd (cs, _mm_load1_pd (&v->x)), _mm_mul_pd (nsc, _mm_load1_pd (&v->y))), p);
}
#endif

/* A circle or polygon shape's box, `center` its centre in the body frame. */
ALWAYS_INLINE void part_box (const shape *s, vec2 center, xform t, vec2 *lo, vec2 *hi)
{
  int32_t i;
  if (s->kind == CAROM_SHAPE_CIRCLE)
    {
      vec2 c = xform_apply (t, center);
      *lo = v2 (c.x - s->radius, c.y - s->radius);
      *hi = v2 (c.x + s->radius, c.y + s->radius);
      return;
    }
#ifdef __SSE2__
  /* x and y in the two lanes of one register: each lane the operations of
   * xform_apply, v2_min and v2_max in their order, so the same bits. The
   * x lane's c x - s y is c x + (-s) y, the same sum (IEEE subtraction
   * adds the negated operand, and negation is exact); minpd and maxpd
   * return their first operand when it is less (greater), else the
   * second, as v2_min (l, v) and v2_max (h, v) do. */
  {
    __m128d cs = _mm_set_pd (t.q.s, t.q.c), nsc = _mm_set_pd (t.q.c, -t.q.s), p = _mm_set_pd (t.p.y, t.p.x);
    __m128d l, h, v;
    l = h = turn_move (cs, nsc, p, &s->vertices[0]);
    for (i = 1; i < s->count; ++i)
      {
        v = turn_move (cs, nsc, p, &s->vertices[i]);
        l = _mm_min_pd (l, v);
        h = _mm_max_pd (h, v);
      }
    _mm_storeu_pd (&lo->x, l);
    _mm_storeu_pd (&hi->x, h);
  }
#else
  vec2 l, h;
  /* in locals: through lo and hi, which might alias the vertices as far
   * as the compiler knows, every step would go through memory */
  l = h = xform_apply (t, s->vertices[0]);
  for (i = 1; i < s->count; ++i)
    {
      vec2 v = xform_apply (t, s->vertices[i]);
      l = v2_min (l, v);
      h = v2_max (h, v);
    }
  *lo = l;
  *hi = h;
#endif
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

/* ---------------------------------------------------------------- slots */

/* Make sure a slot is free and that removing a body later cannot fail for
 * lack of room in the free list. Changes no visible state. */
carom_status body_reserve_slot (carom_world *world)
{
  if (world->live_count >= CAROM_MAX_BODIES)
    return CAROM_ERR_TOO_MANY_BODIES;
  if (world->free_count == 0
      && !mem_reserve (&world->allocator, (void **) &world->bodies, &world->slot_cap, world->slot_count + 1,
                       sizeof (body)))
    return CAROM_ERR_OUT_OF_MEMORY;
  if (!mem_reserve (&world->allocator, (void **) &world->free_slots, &world->free_cap, world->live_count + 1,
                    sizeof (int32_t))
      || !mem_reserve (&world->allocator, (void **) &world->unload, &world->unload_cap, 3 * (world->slot_count + 1),
                       sizeof (double)))
    return CAROM_ERR_OUT_OF_MEMORY;
  return CAROM_OK;
}

/* Place a fully built shape into a new body. Cannot fail: reserve_slot ran. */
carom_body_id body_commit (carom_world *world, const carom_body_def *def, const shape *s)
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
  if (s->piece_count > world->most_pieces)
    world->most_pieces = s->piece_count;
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
  world->seams_dirty |= b->type == CAROM_STATIC;
  return body_id_of (world, slot);
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
  joints_forget_body (world, slot);   /* and those it was joined to */
  shape_destroy (&b->shape, &world->allocator);
  world->seams_dirty |= b->type == CAROM_STATIC;
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

