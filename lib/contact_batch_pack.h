/* Packing a contact into its batch's lane (contact_batch.c lays the
 * batches out; contact_prepare packs each batched contact as it sets it
 * up, contact_batch_prepare the rest of the time). */
#ifndef CAROM_CONTACT_BATCH_PACK_H
#define CAROM_CONTACT_BATCH_PACK_H

#include "contact_batch.h"
#include "contact_solver.h"
#include "world.h"

/* Lane `lane` of point j of a batch, unused: every number 0, so it
 * computes impulses of 0. */
static inline void pack_point_empty (batch_point *q, int lane)
{
  q->nx[lane] = q->ny[lane] = 0.0;
  q->ra_x[lane] = q->ra_y[lane] = q->rb_x[lane] = q->rb_y[lane] = 0.0;
  q->adjusted[lane] = 0.0;
  q->rn_a[lane] = q->rn_b[lane] = q->rt_a[lane] = q->rt_b[lane] = 0.0;
  q->normal_mass[lane] = q->tangent_mass[lane] = 0.0;
  q->normal_impulse[lane] = q->tangent_impulse[lane] = 0.0;
  q->total[lane] = 0.0;
}

/* An unused lane of batch c: the inert body on both sides and every number
 * 0, so it computes impulses of 0 and moves nothing (as pack_lane, every
 * field the kernels read). */
static inline void pack_empty_lane (contact_batch *c, int lane, int32_t inert, int points)
{
  int j;
  c->a[lane] = c->b[lane] = inert;
  c->contact[lane] = -1;
  c->im_a[lane] = c->ii_a[lane] = c->im_b[lane] = c->ii_b[lane] = 0.0;
  c->friction[lane] = c->slop[lane] = c->max_push[lane] = 0.0;
  if (points == 2)
    {
      c->two.k11[lane] = c->two.k12[lane] = c->two.k22[lane] = c->two.pair[lane] = 0.0;
      c->two.i11[lane] = c->two.i12[lane] = c->two.i22[lane] = c->two.block[lane] = 0.0;
    }
  for (j = 0; j < points; ++j)
    pack_point_empty (BATCH_POINT (c, j), lane);
}

/* Lane `lane` of point j of a batch: contact point p. Not push_impulse: a
 * sub-step's first push-out pass starts from none (first) and stores it
 * before any pass reads it. */
ALWAYS_INLINE void pack_point (batch_point *restrict q, int lane, const contact_point *restrict p)
{
  q->nx[lane] = p->normal.x;
  q->ny[lane] = p->normal.y;
  q->ra_x[lane] = p->ra.x;
  q->ra_y[lane] = p->ra.y;
  q->rb_x[lane] = p->rb.x;
  q->rb_y[lane] = p->rb.y;
  q->adjusted[lane] = p->adjusted;
  q->rn_a[lane] = p->rn_a;
  q->rn_b[lane] = p->rn_b;
  q->rt_a[lane] = p->rt_a;
  q->rt_b[lane] = p->rt_b;
  q->normal_mass[lane] = p->normal_mass;
  q->tangent_mass[lane] = p->tangent_mass;
  q->normal_impulse[lane] = p->normal_impulse;
  q->tangent_impulse[lane] = p->tangent_impulse;
  q->total[lane] = p->total_impulse; /* an impact's (contact_impacts) */
}

/* Lane `lane` of batch c: contact k (index `index`). Every field of the
 * lane the kernels read is written (the batches are not cleared between
 * steps): the second point's only where the batch has two (points 2). */
ALWAYS_INLINE void pack_lane (contact_batch *restrict c, int lane, const contact *restrict k, int32_t index,
                       const solver_body *restrict sb, int points)
{
  const solver_body *a = &sb[k->a], *b = &sb[k->b];
  c->a[lane] = k->a;
  c->b[lane] = k->b;
  c->contact[lane] = index;
  c->im_a[lane] = a->im;
  c->ii_a[lane] = a->ii;
  c->im_b[lane] = b->im;
  c->ii_b[lane] = b->ii;
  c->friction[lane] = k->friction;
  c->slop[lane] = k->slop;
  c->max_push[lane] = k->max_push;
  pack_point (&c->p0, lane, &k->points[0]);
  /* a batch of one-point lanes has no room for the rest */
  if (points == 1)
    return;
  if (k->block)
    {
      double det = k->k11 * k->k22 - k->k12 * k->k12;
      /* contact_lcp2's first case, as the inverse of K when it has one */
      int invertible = det > 1e-12 * k->k11 * k->k22;
      c->two.k11[lane] = k->k11;
      c->two.k12[lane] = k->k12;
      c->two.k22[lane] = k->k22;
      c->two.pair[lane] = 1.0;
      c->two.i11[lane] = invertible ? k->k22 / det : 0.0;
      c->two.i12[lane] = invertible ? -k->k12 / det : 0.0;
      c->two.i22[lane] = invertible ? k->k11 / det : 0.0;
      c->two.block[lane] = invertible ? 1.0 : 0.0;
    }
  else
    {
      c->two.k11[lane] = c->two.k12[lane] = c->two.k22[lane] = c->two.pair[lane] = 0.0;
      c->two.i11[lane] = c->two.i12[lane] = c->two.i22[lane] = c->two.block[lane] = 0.0;
    }
  if (k->count == 2)
    pack_point (&c->two.p1, lane, &k->points[1]);
  else
    pack_point_empty (&c->two.p1, lane);
}

/* Batch number `index` of the step's, `twos` of those before it of
 * two-point lanes (the rest of one-point lanes, CONTACT_BATCH_SIZE). */
static inline contact_batch *batch_at (contact_batch *batches, int32_t index, int32_t twos)
{
  return (contact_batch *) ((char *) batches + (size_t) index * CONTACT_BATCH_SIZE (1)
                            + (size_t) twos * (CONTACT_BATCH_SIZE (2) - CONTACT_BATCH_SIZE (1)));
}

/* The colouring's arrays in world->batch_scratch: keys[i], contact i's
 * pack_key (-1 when it is not batched); order[b], the two-point batches
 * before batch b (then the fine rest, contact_batch_finish); end[], each
 * kind's next place. */
typedef struct batch_plan {
  int32_t *keys, *order, *end;
} batch_plan;

static inline batch_plan plan_of (carom_world *world)
{
  batch_plan p;
  p.keys = world->batch_scratch;
  p.order = p.keys + world->contacts.count;
  p.end = p.order + world->contacts.count;
  return p;
}

/* Contact i's lane at its place (contact.batched, one past it). */
ALWAYS_INLINE void pack_at (carom_world *world, const int32_t *order, int32_t i)
{
  const contact *k = &world->contacts.list[i];
  int32_t at = k->batched - 1;
  contact_batch *to = batch_at (world->batches, at / BATCH_LANES, order[at / BATCH_LANES]);
  pack_lane (to, at % BATCH_LANES, k, i, world->solver_bodies, to->points);
}

static inline void contact_batch_pack (carom_world *world, int32_t i)
{
  batch_plan p = plan_of (world);
  /* the next place of its kind: the contacts come in list order */
  world->contacts.list[i].batched = p.end[p.keys[i] + 1]++ + 1;
  pack_at (world, p.order, i);
}

#endif
