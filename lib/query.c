/* Queries on the world as it is: the first body a ray meets, the bodies a
 * box overlaps, the bodies that contain a point. Each looks at every live
 * body's bounding box (O(bodies)) and then at the true outline. */
#include <math.h>

#include "world.h"

static int in_mask (const body *b, uint32_t mask)
{
  return (b->category & mask) != 0;
}

static int boxes_overlap (const body *b, vec2 lo, vec2 hi)
{
  return !(b->box_hi.x < lo.x || b->box_lo.x > hi.x || b->box_hi.y < lo.y || b->box_lo.y > hi.y);
}

/* Non-finite numbers before ones too large, as everywhere. */
static carom_status check_points (double x0, double y0, double x1, double y1)
{
  if (!is_finite (x0) || !is_finite (y0) || !is_finite (x1) || !is_finite (y1))
    return CAROM_ERR_NOT_FINITE;
  if (!is_moderate (x0) || !is_moderate (y0) || !is_moderate (x1) || !is_moderate (y1))
    return CAROM_ERR_BAD_ARGUMENT;
  return CAROM_OK;
}

/* ------------------------------------------------------------------ rays */

/* Where the segment p0 + t d (t in [0, best)) enters a circle: the smaller
 * root of |p0 + t d - c|^2 = r^2, if the segment starts outside. */
static int ray_circle (vec2 p0, vec2 d, vec2 c, double r, double best, double *t, vec2 *n)
{
  vec2 m = v2_sub (p0, c);
  double a = v2_dot (d, d), b = v2_dot (m, d), q = v2_dot (m, m) - r * r, disc, s;
  if (q < 0.0 || b > 0.0 || a == 0.0)
    return 0; /* starts inside, or heads away */
  disc = b * b - a * q;
  if (disc < 0.0)
    return 0;
  s = (-b - sqrt (disc)) / a;
  if (!(s >= 0.0 && s <= 1.0 && s < best))
    return 0;
  *t = s;
  *n = v2_scale (v2_add (m, v2_scale (d, s)), 1.0 / r);
  return 1;
}

/* Where the segment (body frame) enters the polygon outline first: the
 * crossings of the edges it meets from outside (d . n < 0). */
static int ray_polygon (const shape *s, vec2 p0, vec2 d, double best, double *t, vec2 *n)
{
  int32_t i, hit = 0;
  for (i = 0; i < s->count; ++i)
    {
      vec2 v = s->vertices[i], w = s->vertices[i + 1 == s->count ? 0 : i + 1], e = v2_sub (w, v);
      vec2 f = v2_sub (v, p0);
      double den = v2_cross (d, e), u, ti;
      if (!(v2_dot (d, s->normals[i]) < 0.0) || den == 0.0)
        continue;
      ti = v2_cross (f, e) / den;
      u = v2_cross (f, d) / den;
      if (ti >= 0.0 && ti <= 1.0 && u >= 0.0 && u <= 1.0 && ti < best)
        {
          best = ti;
          *t = ti;
          *n = s->normals[i];
          hit = 1;
        }
    }
  return hit;
}

/* Where the segment enters the body first (any of a compound's shapes). */
static int ray_body (const body *b, vec2 p0, vec2 d, double best, double *t, vec2 *n)
{
  xform x;
  vec2 q0, qd;
  int32_t i, found = 0;
  if (b->shape.kind == CAROM_SHAPE_CIRCLE)
    return ray_circle (p0, d, b->p, b->shape.radius, best, t, n);
  /* in the body's frame, the normal back to the world's */
  x.p = b->p, x.q = b->q;
  q0 = xform_apply_inv (x, p0);
  qd = rot2_apply_inv (b->q, d);
  for (i = 0; i < shape_part_count (&b->shape); ++i)
    {
      vec2 c;
      const shape *s = shape_part_at (&b->shape, i, &c);
      if (s->kind == CAROM_SHAPE_CIRCLE ? ray_circle (q0, qd, c, s->radius, best, t, n)
                                         : ray_polygon (s, q0, qd, best, t, n))
        {
          best = *t;
          found = 1;
        }
    }
  if (found)
    *n = rot2_apply (b->q, *n);
  return found;
}

carom_status carom_world_cast_ray (const carom_world *world, double x0, double y0, double x1, double y1,
                                   uint32_t mask, carom_ray_hit *hit)
{
  vec2 p0 = v2 (x0, y0), d = v2 (x1 - x0, y1 - y0), lo, hi;
  double best = INFINITY;
  carom_ray_hit out;
  carom_status st;
  int32_t i;
  if (!world || !hit)
    return CAROM_ERR_NULL_ARGUMENT;
  st = check_points (x0, y0, x1, y1);
  if (st != CAROM_OK)
    return st;
  lo = v2_min (p0, v2 (x1, y1));
  hi = v2_max (p0, v2 (x1, y1));
  out.body = CAROM_NULL_BODY;
  out.x = x1, out.y = y1, out.nx = out.ny = 0.0, out.fraction = 1.0;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      double t;
      vec2 n;
      int found;
      if (!b->alive || !in_mask (b, mask) || !boxes_overlap (b, lo, hi))
        continue;
      found = ray_body (b, p0, d, best, &t, &n);
      if (!found)
        continue;
      best = t;
      out.body = body_id_of (world, i);
      out.fraction = t;
      out.x = x0 + t * d.x, out.y = y0 + t * d.y;
      out.nx = n.x, out.ny = n.y;
    }
  *hit = out;
  return CAROM_OK;
}

/* ----------------------------------------------------- boxes and points */

static int32_t check_list (const carom_world *world, const carom_body_id *ids, int32_t capacity)
{
  if (!world || (!ids && capacity > 0))
    return -(int32_t) CAROM_ERR_NULL_ARGUMENT;
  if (capacity < 0)
    return -(int32_t) CAROM_ERR_BAD_ARGUMENT;
  return 0;
}

int32_t carom_world_query_aabb (const carom_world *world, double x0, double y0, double x1, double y1, uint32_t mask,
                                carom_body_id *ids, int32_t capacity)
{
  int32_t i, k = 0, bad = check_list (world, ids, capacity);
  carom_status st;
  if (bad)
    return bad;
  st = check_points (x0, y0, x1, y1);
  if (st != CAROM_OK)
    return -(int32_t) st;
  if (x0 > x1 || y0 > y1)
    return -(int32_t) CAROM_ERR_BAD_ARGUMENT;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      if (!b->alive || !in_mask (b, mask) || !boxes_overlap (b, v2 (x0, y0), v2 (x1, y1)))
        continue;
      if (k < capacity)
        ids[k] = body_id_of (world, i);
      ++k;
    }
  return k;
}

/* Whether the outline (body frame) contains p: an odd number of edges
 * crossed by the ray from p towards +x. */
static int polygon_contains (const shape *s, vec2 p)
{
  int32_t i, j, inside = 0;
  for (i = 0, j = s->count - 1; i < s->count; j = i++)
    {
      vec2 a = s->vertices[i], b = s->vertices[j];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
        inside = !inside;
    }
  return inside;
}

int body_contains (const body *b, vec2 p)
{
  if (p.x < b->box_lo.x || p.x > b->box_hi.x || p.y < b->box_lo.y || p.y > b->box_hi.y)
    return 0;
  if (b->shape.kind == CAROM_SHAPE_CIRCLE)
    return v2_len2 (v2_sub (p, b->p)) <= b->shape.radius * b->shape.radius;
  {
    xform x;
    vec2 q, c;
    int32_t i;
    x.p = b->p, x.q = b->q;
    q = xform_apply_inv (x, p);
    for (i = 0; i < shape_part_count (&b->shape); ++i)
      {
        const shape *s = shape_part_at (&b->shape, i, &c);
        if (s->kind == CAROM_SHAPE_CIRCLE ? v2_len2 (v2_sub (q, c)) <= s->radius * s->radius : polygon_contains (s, q))
          return 1;
      }
    return 0;
  }
}

int32_t carom_world_query_point (const carom_world *world, double x, double y, uint32_t mask, carom_body_id *ids,
                                 int32_t capacity)
{
  int32_t i, k = 0, bad = check_list (world, ids, capacity);
  carom_status st;
  if (bad)
    return bad;
  st = check_points (x, y, 0.0, 0.0);
  if (st != CAROM_OK)
    return -(int32_t) st;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      if (!b->alive || !in_mask (b, mask) || !body_contains (b, v2 (x, y)))
        continue;
      if (k < capacity)
        ids[k] = body_id_of (world, i);
      ++k;
    }
  return k;
}
