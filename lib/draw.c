/* Debug draw (carom_world_draw): the bodies and contacts as the program's
 * callbacks draw them. */
#include <stddef.h>
#include <string.h>

#include "world.h"

/* 0.2's carom_debug_draw came first without the joints' fields; it and
 * this one are accepted */
#define DEBUG_DRAW_SIZE_BODIES (offsetof (carom_debug_draw, draw_contacts) + sizeof (int32_t))
#define DEBUG_DRAW_SIZE sizeof (carom_debug_draw)

static int known_size (uint32_t size)
{
  return size == DEBUG_DRAW_SIZE || size == DEBUG_DRAW_SIZE_BODIES;
}

carom_status carom_debug_draw_init (carom_debug_draw *draw, uint32_t size)
{
  if (!draw)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!known_size (size))
    return CAROM_ERR_BAD_STRUCT_SIZE;
  memset (draw, 0, size);
  draw->size = size;
  draw->draw_bodies = 1;
  draw->draw_contacts = 1;
  if (size == DEBUG_DRAW_SIZE)
    draw->draw_joints = 1;
  return CAROM_OK;
}

/* A joint: the centre of a, a's anchor, b's anchor, the centre of b. */
static void draw_joint (const carom_world *world, int32_t slot, const carom_debug_draw *d)
{
  const joint *j = &world->joints.list[slot];
  vec2 pa, pb, ca, cb = world->bodies[j->b].p;
  double xy[8];
  joint_anchors (world, j, &pa, &pb);
  ca = j->a >= 0 && j->type != CAROM_JOINT_MOUSE ? world->bodies[j->a].p : pa;
  xy[0] = ca.x, xy[1] = ca.y, xy[2] = pa.x, xy[3] = pa.y;
  xy[4] = pb.x, xy[5] = pb.y, xy[6] = cb.x, xy[7] = cb.y;
  d->joint (j->type, xy, joint_id_of (world, slot), d->user);
}

static void draw_body (const carom_world *world, int32_t slot, const carom_debug_draw *d, double *xy)
{
  const body *b = &world->bodies[slot];
  carom_body_id id = body_id_of (world, slot);
  xform x;
  int32_t i, k;
  x.p = b->p, x.q = b->q;
  for (k = 0; k < shape_part_count (&b->shape); ++k)
    {
      vec2 c;
      const shape *s = shape_part_at (&b->shape, k, &c);
      if (s->kind == CAROM_SHAPE_CIRCLE)
        {
          if (d->circle)
            {
              c = xform_apply (x, c);
              d->circle (c.x, c.y, s->radius, b->angle, id, d->user);
            }
        }
      else if (d->polygon)
        {
          for (i = 0; i < s->count; ++i)
            {
              vec2 v = xform_apply (x, s->vertices[i]);
              xy[2 * i] = v.x, xy[2 * i + 1] = v.y;
            }
          d->polygon (xy, s->count, id, d->user);
        }
    }
}

carom_status carom_world_draw (const carom_world *world, const carom_debug_draw *draw)
{
  double xy[2 * CAROM_MAX_POLYGON_VERTICES];
  int32_t i, j;
  if (!world || !draw)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!known_size (draw->size))
    return CAROM_ERR_BAD_STRUCT_SIZE;
  if (draw->draw_bodies)
    for (i = 0; i < world->slot_count; ++i)
      if (world->bodies[i].alive)
        draw_body (world, i, draw, xy);
  if (draw->size == DEBUG_DRAW_SIZE && draw->draw_joints && draw->joint)
    for (i = 0; i < world->joints.count; ++i)
      if (world->joints.list[i].alive)
        draw_joint (world, i, draw);
  if (draw->draw_contacts)
    for (i = 0; i < world->contacts.count; ++i)
      {
        const contact *k = &world->contacts.list[i];
        const body *a = &world->bodies[k->a], *b = &world->bodies[k->b];
        double len = 0.2 * (a->shape.size < b->shape.size ? a->shape.size : b->shape.size);
        for (j = 0; j < k->count; ++j)
          {
            const contact_point *p = &k->points[j];
            if (draw->point)
              draw->point (p->point.x, p->point.y, draw->user);
            if (draw->segment)
              draw->segment (p->point.x, p->point.y, p->point.x + len * p->normal.x, p->point.y + len * p->normal.y,
                             draw->user);
          }
      }
  return CAROM_OK;
}
