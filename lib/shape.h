/* Shapes: circles and simple polygons, their validation, their exact mass
 * properties (thesis 3.1) and the convex pieces a concave polygon is split
 * into for collision detection. All geometry is in the body's frame, with the
 * origin at the centre of mass. */
#ifndef CAROM_SHAPE_H
#define CAROM_SHAPE_H

#include "alloc.h"
#include "carom.h"
#include "vec2.h"

/* A convex polygon, counter-clockwise; normals[i] is the outward unit normal
 * of the edge from vertices[i] to vertices[i + 1]. */
typedef struct convex_piece {
  int32_t count;
  vec2 *vertices;
  vec2 *normals;
  vec2 center;         /* centre of its bounding circle (for piece culling) */
  double bound_radius; /* every vertex lies within this of `center` */
  int32_t alloc_count; /* vertices allocated (count may be less) */
} convex_piece;

typedef struct shape {
  carom_shape_kind kind;
  double radius;        /* circles only */
  int32_t count;        /* polygon outline: vertex count */
  vec2 *vertices;       /* polygon outline, counter-clockwise, about centroid */
  vec2 *normals;        /* outline edge normals */
  int convex;           /* the outline is convex: one piece */
  int pieces_shared;    /* pieces[0] uses the outline's own arrays */
  int32_t piece_count;
  int32_t piece_alloc;  /* pieces allocated (>= piece_count) */
  convex_piece *pieces;
  double area;
  double unit_inertia;  /* moment of inertia about the centroid at density 1 */
  double bound_radius;  /* max distance of any point from the centroid */
  double size;          /* length scale 2 * area / perimeter, for tolerances */
} shape;

/* Mass properties of a simple polygon, either winding: signed area (positive
 * when counter-clockwise), centroid, and the polar moment of inertia about
 * the centroid at density 1, by the sub-triangles of eq. 3.13 and 3.14 with
 * signed areas (so a centroid outside the polygon is handled). */
void polygon_mass (const vec2 *v, int32_t n, double *signed_area, vec2 *centroid, double *unit_inertia);

/* Check a raw vertex list: count, finiteness, repeated consecutive vertices,
 * zero area, self-intersection. Returns the status a caller gets. */
carom_status polygon_validate (const double *xy, int32_t n);

/* Build shapes. Polygon input must have passed polygon_validate; it is copied,
 * made counter-clockwise and moved so the centroid is at the origin; the
 * centroid of the input is written to *centroid. */
carom_status shape_init_circle (shape *s, double radius);
carom_status shape_init_polygon (shape *s, const carom_allocator *a, const double *xy, int32_t n, vec2 *centroid);
void shape_destroy (shape *s, const carom_allocator *a);

#endif
