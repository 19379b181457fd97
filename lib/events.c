/* Contact and sensor events (events.h). */
#include "events.h"

#include <string.h>

#include "world.h"

void events_destroy (carom_world *world)
{
  events *e = &world->events;
  int k;
  for (k = 0; k < 2; ++k)
    mem_free (&world->allocator, e->touches[k], (size_t) e->cap[k] * sizeof (touch));
  mem_free (&world->allocator, e->table, (size_t) e->table_cap * sizeof (int32_t));
  mem_free (&world->allocator, e->list, (size_t) e->event_cap * sizeof (carom_contact_event));
  memset (e, 0, sizeof *e);
}

/* Open addressing over the last update's pairs: twice their count, a power
 * of two. */
static int32_t table_size (int32_t count)
{
  int32_t n = 16;
  while (n < 2 * count)
    n *= 2;
  return n;
}

int events_reserve (carom_world *world)
{
  events *e = &world->events;
  int32_t now = world->contacts.room_count + world->contacts.sensor_count; /* after solver_reserve */
  int32_t last = e->count[e->cur];
  int32_t fresh = 1 - e->cur, table = table_size (last);
  /* this update's pairs, and the last one's that sleep on (events_update) */
  return mem_reserve (&world->allocator, (void **) &e->touches[fresh], &e->cap[fresh], now + last, sizeof (touch))
         && mem_reserve (&world->allocator, (void **) &e->table, &e->table_cap, table, sizeof (int32_t))
         && mem_reserve (&world->allocator, (void **) &e->list, &e->event_cap, now + last,
                         sizeof (carom_contact_event));
}

static uint32_t pair_hash (carom_body_id a, carom_body_id b, int32_t sensor)
{
  uint64_t h = (a ^ (b << 20) ^ (b >> 44) ^ (uint64_t) sensor << 63) * 0x9e3779b97f4a7c15ull;
  return (uint32_t) (h >> 32);
}

static int32_t find (const int32_t *table, int32_t base, const touch *old, int32_t mask, const touch *t)
{
  uint32_t i = pair_hash (t->a, t->b, t->sensor) & (uint32_t) mask;
  for (;; i = (i + 1) & (uint32_t) mask)
    {
      int32_t k = table[i] - base;
      if (k < 0)
        return -1;
      if (old[k].a == t->a && old[k].b == t->b && old[k].sensor == t->sensor)
        return k;
    }
}

static int point_touches (const contact_point *p)
{
  return p->depth >= 0.0 || p->total_impulse > 0.0;
}

/* The contact's first point that touches, or NULL. */
static const contact_point *first_touching (const contact *c)
{
  int32_t j;
  for (j = 0; j < c->count; ++j)
    if (point_touches (&c->points[j]))
      return &c->points[j];
  return NULL;
}

/* The contacts of one pair of bodies are consecutive in the list (one
 * broad-phase pair gives all of its pieces' contacts): they touch when
 * some point overlaps or received impulse in the update. */
static int32_t contact_touches (const carom_world *world, touch *out)
{
  /* the list and its count in locals: through the int32_t stores to out,
   * which might alias them as far as the compiler knows, every use would
   * reload them */
  const contact *list = world->contacts.list;
  const body *bodies = world->bodies;
  int32_t count = world->contacts.count, i = 0, n = 0;
  while (i < count)
    {
      int32_t a = list[i].a, b = list[i].b, first = i;
      const contact_point *found = first_touching (&list[i]);
      touch *t;
      /* the pair's other contacts (the first one's bodies are its own) */
      for (++i; i < count && list[i].a == a && list[i].b == b; ++i)
        if (!found)
          found = first_touching (&list[i]);
      if (!found)
        continue;
      t = &out[n++];
      t->a = body_slot_id (&bodies[a], a);
      t->b = body_slot_id (&bodies[b], b);
      t->x = found->point.x, t->y = found->point.y;
      t->first = first;
      t->sensor = t->seen = 0;
    }
  return n;
}

/* A begin event: what the pair's contacts say about the update. */
static void emit_begin (events *e, const carom_world *world, const touch *t)
{
  const contacts *c = &world->contacts;
  carom_contact_event *v = &e->list[e->event_count++];
  int32_t i, j, a, b;
  int first = 1;
  memset (v, 0, sizeof *v); /* no stray padding bytes reach the caller */
  v->type = t->sensor ? CAROM_EVENT_SENSOR_BEGIN : CAROM_EVENT_CONTACT_BEGIN;
  v->a = t->a, v->b = t->b;
  v->x = t->x, v->y = t->y;
  if (t->sensor)
    return;
  a = c->list[t->first].a, b = c->list[t->first].b;
  for (i = t->first; i < c->count && c->list[i].a == a && c->list[i].b == b; ++i)
    for (j = 0; j < c->list[i].count; ++j)
      {
        const contact_point *p = &c->list[i].points[j];
        if (!point_touches (p))
          continue;
        if (first)
          v->nx = p->normal.x, v->ny = p->normal.y, first = 0;
        v->approach_speed = -p->approach > v->approach_speed ? -p->approach : v->approach_speed;
        v->normal_impulse += p->total_impulse;
      }
}

static void emit_end (events *e, const touch *t)
{
  carom_contact_event *v = &e->list[e->event_count++];
  memset (v, 0, sizeof *v);
  v->type = t->sensor ? CAROM_EVENT_SENSOR_END : CAROM_EVENT_CONTACT_END;
  v->a = t->a, v->b = t->b;
  v->x = t->x, v->y = t->y;
}

/* A pair of bodies that still exist and neither of which can move (asleep,
 * or static, or kinematic at rest): detection makes no contact for it, but
 * the bodies touch as they did, and the pair carries on without an end. */
static int sleeps_on (const carom_world *world, const touch *t)
{
  const body *a = body_lookup (world, t->a), *b = body_lookup (world, t->b);
  return a && b && a->inv_mass == 0.0 && b->inv_mass == 0.0 && !body_kinematic_moving (a)
         && !body_kinematic_moving (b);
}

/* The same pairs in the same order as the last update: the common case of
 * a steady scene, which needs no table and makes no event. */
static int same_pairs (const touch *old, int32_t old_count, const touch *cur, int32_t n)
{
  int32_t i;
  if (old_count != n)
    return 0;
  for (i = 0; i < n; ++i)
    if (old[i].a != cur[i].a || old[i].b != cur[i].b || old[i].sensor != cur[i].sensor)
      return 0;
  return 1;
}

/* The table over the last update's pairs (events.table_base and up). The
 * table is not cleared for each update: the values an earlier one left
 * are below this one's base, and so empty; only a table just grown (its
 * new part unset), or a base that would pass INT32_MAX, starts again from
 * -1 everywhere. */
static int32_t *build_table (events *e, const touch *old, int32_t old_count, int32_t *base_out, int32_t *mask_out)
{
  int32_t i, base, *table, mask = table_size (old_count) - 1;
  if (e->table_set != e->table_cap || e->table_base > INT32_MAX - old_count)
    {
      for (i = 0; i < e->table_cap; ++i)
        e->table[i] = -1;
      e->table_set = e->table_cap;
      e->table_base = 0;
    }
  /* in locals: through the int32_t stores to the table, which might alias
   * e's fields as far as the compiler knows, every use would reload them */
  table = e->table, base = e->table_base;
  for (i = 0; i < old_count; ++i)
    {
      uint32_t h = pair_hash (old[i].a, old[i].b, old[i].sensor) & (uint32_t) mask;
      while (table[h] >= base)
        h = (h + 1) & (uint32_t) mask;
      table[h] = base + i;
    }
  *base_out = base;
  *mask_out = mask;
  return table;
}

void events_update (carom_world *world)
{
  events *e = &world->events;
  const contacts *c = &world->contacts;
  int32_t last = e->cur, now = 1 - e->cur, old_count = e->count[last], mask = 0, base = 0, i, k, n;
  int32_t *table = NULL;
  touch *old = e->touches[last], *cur = e->touches[now];
  n = contact_touches (world, cur);
  for (i = 0; i < c->sensor_count; ++i)
    {
      const body *v = &world->bodies[c->sensors[2 * i + 1]];
      touch *t;
      if (!contact_bodies_overlap (&world->bodies[c->sensors[2 * i]], v))
        continue;
      t = &cur[n++];
      t->a = body_id_of (world, c->sensors[2 * i]);
      t->b = body_id_of (world, c->sensors[2 * i + 1]);
      t->x = v->p.x, t->y = v->p.y;
      t->first = -1;
      t->sensor = 1;
      t->seen = 0;
    }
  e->count[now] = n;
  e->event_count = 0;
  e->cur = now;
  if (same_pairs (old, old_count, cur, n))
    return;
  /* the pairs come in the order of the contacts, which is mostly last
   * update's: the old pair after the last one matched is tried first, and
   * a table over the old pairs is built only when that fails */
  for (i = 0, k = 0; i < n; ++i)
    {
      int32_t found = -1;
      if (k < old_count && old[k].a == cur[i].a && old[k].b == cur[i].b && old[k].sensor == cur[i].sensor)
        found = k;
      else
        {
          if (!table)
            table = build_table (e, old, old_count, &base, &mask);
          found = find (table, base, old, mask, &cur[i]);
        }
      if (found >= 0)
        {
          old[found].seen = 1;
          k = found + 1;
        }
      else
        emit_begin (e, world, &cur[i]);
    }
  for (i = 0; i < old_count; ++i)
    if (!old[i].seen)
      {
        if (!old[i].sensor && sleeps_on (world, &old[i]))
          cur[e->count[now]++] = old[i]; /* still touching, asleep: no end */
        else
          emit_end (e, &old[i]);
      }
  if (table)
    e->table_base = base + old_count;
}

int32_t carom_world_get_events (const carom_world *world, carom_contact_event *list, int32_t capacity)
{
  const events *e;
  int32_t i;
  if (!world)
    return -(int32_t) CAROM_ERR_NULL_ARGUMENT;
  if (capacity < 0)
    return -(int32_t) CAROM_ERR_BAD_ARGUMENT;
  if (!list && capacity > 0)
    return -(int32_t) CAROM_ERR_NULL_ARGUMENT;
  e = &world->events;
  for (i = 0; i < e->event_count && i < capacity; ++i)
    list[i] = e->list[i];
  return e->event_count;
}
