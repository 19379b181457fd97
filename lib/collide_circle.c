/* Narrow phase for circles: circle-circle and convex polygon-circle. */
#include "collide.h"

static void set_point (manifold *m, vec2 point, vec2 normal, double depth, uint32_t feature)
{
  m->points[0].point = point;
  m->points[0].normal = normal;
  m->points[0].depth = depth;
  m->points[0].feature = feature;
  m->count = 1;
}

int32_t collide_circles (vec2 ca, double ra, vec2 cb, double rb, double margin, manifold *m)
{
  vec2 d = v2_sub (cb, ca), n;
  double dist = hypot (d.x, d.y), depth; /* the squared length may underflow */
  m->count = 0;
  m->gap = INFINITY;
  m->separation_face = MANIFOLD_NO_FACE;
  if (dist > ra + rb + margin)
    return 0;
  /* coincident centres have no direction between them: pick +x, so the
   * result is still a unit normal and the same on every run */
  n = dist > 0.0 ? v2 (d.x / dist, d.y / dist) : v2 (1.0, 0.0);
  depth = ra + rb - dist;
  /* the impact point halfway between the two surfaces */
  set_point (m, v2_mad (ca, ra - 0.5 * depth, n), n, depth, 0);
  return 1;
}

int32_t collide_polygon_circle (const convex_piece *a, xform xa, vec2 cb, double rb, double margin, manifold *m)
{
  vec2 c = xform_apply_inv (xa, cb); /* circle centre in the polygon's frame */
  double best = -INFINITY, apart = -INFINITY, depth;
  int32_t i, edge = -1, n = a->count;
  vec2 v1, v2_, normal, surface;
  m->count = 0;
  m->gap = INFINITY;
  m->separation_face = MANIFOLD_NO_FACE;
  for (i = 0; i < n; ++i)
    {
      double s = v2_dot (a->normals[i], v2_sub (c, a->vertices[i]));
      apart = s > apart ? s : apart;
      /* the face it is met on: none of a seam (seams.h) */
      if (s > best && !piece_edge_internal (a, i))
        {
          best = s;
          edge = i;
        }
    }
  if (apart > rb + margin || edge < 0)
    return 0;
  v1 = a->vertices[edge];
  v2_ = a->vertices[(edge + 1) % n];
  normal = a->normals[edge];
  if (best > 0.0)
    {
      /* centre outside: the closest feature is a vertex or the edge itself */
      double u1 = v2_dot (v2_sub (c, v1), v2_sub (v2_, v1));
      double u2 = v2_dot (v2_sub (c, v2_), v2_sub (v1, v2_));
      vec2 corner = u1 <= 0.0 ? v1 : v2_;
      /* a corner next to a seam is no corner: the face goes on across it */
      int seam = u1 <= 0.0 ? piece_edge_internal (a, (edge + n - 1) % n) : piece_edge_internal (a, (edge + 1) % n);
      if ((u1 <= 0.0 || u2 <= 0.0) && !seam)
        {
          vec2 d = v2_sub (c, corner);
          double dist = hypot (d.x, d.y);
          if (dist > rb + margin)
            return 0;
          if (dist > 0.0)
            normal = v2 (d.x / dist, d.y / dist);
          depth = rb - dist;
          surface = corner;
          set_point (m, xform_apply (xa, v2_mad (surface, -0.5 * depth, normal)), rot2_apply (xa.q, normal),
                     depth, (uint32_t) (u1 <= 0.0 ? edge : (edge + 1) % n) | 0x10000u);
          return 1;
        }
    }
  /* the face region, or the centre inside the polygon */
  depth = rb - best;
  surface = v2_mad (c, -best, normal); /* centre projected on the edge */
  set_point (m, xform_apply (xa, v2_mad (surface, -0.5 * depth, normal)), rot2_apply (xa.q, normal), depth,
             (uint32_t) edge);
  return 1;
}
