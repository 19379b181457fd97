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
 * of the edge from vertices[i] to vertices[i + 1]. A compound body's circle
 * parts are pieces too: count 0, the circle of `radius` about `center`. */
typedef struct convex_piece {
  int32_t count;
  vec2 *vertices;
  vec2 *normals;
  vec2 center;         /* centre of its bounding circle (for piece culling):
                          a polygon piece's vertex average, which lies
                          within it (collide_sat.c prunes by it) */
  double bound_radius; /* every vertex lies within this of `center` */
  int32_t alloc_count; /* vertices allocated (count may be less) */
  double radius;       /* a circle piece's radius (count 0), else 0 */
  double restitution, friction; /* its part's material; < 0: the body's */
  uint64_t internal;   /* bit i: edge i is internal, shared with another
                          static piece (seams.c); 0 for moving bodies */
} convex_piece;

/* Whether edge i of a piece is internal (a seam, seams.h). */
static inline int piece_edge_internal (const convex_piece *p, int32_t i)
{
  return i < 64 && ((p->internal >> i) & 1u);
}

struct shape_part;

/* A circle, a simple polygon, or a compound of several of them (its parts,
 * placed in the body's frame). */
typedef struct shape {
  /* first what detection reads of every body (one cache line) */
  carom_shape_kind kind;
  int32_t count;        /* polygon outline: vertex count */
  int32_t piece_count;
  int32_t part_count;   /* compounds only (below) */
  double radius;        /* circles only */
  double bound_radius;  /* max distance of any point from the centroid */
  double size;          /* length scale 2 * area / perimeter, for tolerances
                           (a compound's: its smallest part's) */
  convex_piece *pieces;
  vec2 *vertices;       /* polygon outline, counter-clockwise, about centroid */
  vec2 *normals;        /* outline edge normals */
  int convex;           /* the outline is convex: one piece */
  int pieces_shared;    /* pieces[0] uses the outline's own arrays */
  int32_t piece_alloc;  /* pieces allocated (>= piece_count) */
  double area;
  double unit_inertia;  /* moment of inertia about the centroid at density 1 */
  /* compounds only: the parts, whose pieces `pieces` lists (sharing their
   * vertices), and the mass and inertia about the centroid of the union
   * at the parts' own densities */
  struct shape_part *parts;
  double mass, inertia;
} shape;

/* A part of a compound: a circle or polygon shape whose geometry is
 * already in the compound's frame (a polygon's vertices; a circle's centre
 * is `center`), its density and material (< 0: the body's). */
typedef struct shape_part {
  shape s;
  vec2 center;          /* its centroid in the compound's frame */
  double density, restitution, friction;
} shape_part;

/* The parts of any shape: a circle or polygon is its own single part,
 * centred at the origin. */
static inline int32_t shape_part_count (const shape *s)
{
  return s->kind == CAROM_SHAPE_COMPOUND ? s->part_count : 1;
}
static inline const shape *shape_part_at (const shape *s, int32_t i, vec2 *center)
{
  if (s->kind != CAROM_SHAPE_COMPOUND)
    {
      *center = v2 (0.0, 0.0);
      return s;
    }
  *center = s->parts[i].center;
  return &s->parts[i].s;
}

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
 * centroid of the input is written to *centroid. Boxes and regular polygons
 * take their inertia from the closed forms (eq. 3.4, 3.6). */
carom_status shape_init_circle (shape *s, double radius);
carom_status shape_init_polygon (shape *s, const carom_allocator *a, const double *xy, int32_t n, vec2 *centroid);
/* The outlines of a width x height box (4 points, counter-clockwise from
 * the lower left) and of a regular n-gon with sides `side` (one vertex on
 * +x), about the origin, into xy. */
void box_vertices (double width, double height, double *xy);
void regular_vertices (int32_t n, double side, double *xy);
carom_status shape_init_box (shape *s, const carom_allocator *a, double width, double height);
carom_status shape_init_regular (shape *s, const carom_allocator *a, int32_t n, double side);

/* A compound of `count` parts, each already built (circle or polygon,
 * centred on its own centroid) with its centroid at centers[i] in the
 * caller's frame: the union's centre of mass (densities[i] weighting each
 * part) becomes the origin, the parts move with it, and its mass and
 * inertia are the parts' by the parallel axis theorem. The compound takes
 * over the parts (the caller's `parts` array is copied; on error the parts
 * are left to the caller). *centroid is the union's centre of mass in the
 * caller's frame. */
carom_status shape_init_compound (shape *s, const carom_allocator *a, const shape_part *parts, int32_t count,
                                  vec2 *centroid);
void shape_destroy (shape *s, const carom_allocator *a);

/* Mass and inertia about the centroid at `density` (a compound's parts
 * carry their own densities and ignore it). */
void shape_mass (const shape *s, double density, double *mass, double *inertia);

#endif
