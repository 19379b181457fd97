/* Narrow phase: exact tests between pairs of shapes placed in the world.
 * Each returns the number of contact points written to the manifold (0 when
 * the shapes are farther apart than `margin`). Normals are unit vectors that
 * point from the first shape to the second; depth is the penetration along
 * the normal (negative when apart but within `margin`). */
#ifndef CAROM_COLLIDE_H
#define CAROM_COLLIDE_H

#include "shape.h"
#include "vec2.h"

#define MANIFOLD_MAX_POINTS 4

typedef struct manifold_point {
  vec2 point;       /* impact point, world frame */
  vec2 normal;      /* unit, from the first shape towards the second */
  double depth;     /* penetration along normal */
  uint32_t feature; /* which vertex/edge pair made it, to match across steps */
} manifold_point;

typedef struct manifold {
  int32_t count;
  manifold_point points[MANIFOLD_MAX_POINTS];
  /* never more than the pieces' distance when they are apart: the
   * separation along the reference face's normal (the points, clipped to
   * that face, can lie farther apart than the pieces do); INFINITY where
   * the points' own depths tell it */
  double gap;
  /* Two polygon pieces (the SAT): their largest separation over both
   * pieces' edge normals at these poses and the edge it was found on,
   * bit for bit what polygons_separation_face gives (its `face`: an edge of
   * a, or -1 - an edge of b); MANIFOLD_NO_FACE from the other tests. */
  double separation;
  int32_t separation_face;
} manifold;

#define MANIFOLD_NO_FACE INT32_MIN

int32_t collide_circles (vec2 ca, double ra, vec2 cb, double rb, double margin, manifold *m);

/* Convex polygon piece (body frame, placed by xa) against a circle. */
int32_t collide_polygon_circle (const convex_piece *a, xform xa, vec2 cb, double rb, double margin, manifold *m);

/* The largest separation of two convex pieces along their edge normals (the
 * candidate axes of thesis fig. 3.7): negative when they overlap, 0 when
 * they touch, and when apart never more than their distance: the gap
 * between the two pieces' projections on that edge normal, *axis, turned to
 * point from a towards b. */
double polygons_separation (const convex_piece *a, xform xa, const convex_piece *b, xform xb, vec2 *axis);
/* The reference face a point of collide_polygons_sat's manifold was
 * clipped to, from its feature: edge *edge of a (*side 0) or of b (*side 1);
 * 0 for a corner's point, which has none. */
int sat_feature_face (uint32_t feature, int *side, int32_t *edge);
/* The outward normal of a face of two pieces, turned to point from a to
 * b: an edge of a, or -1 - an edge of b (polygons_separation_face's
 * `face`). */
vec2 polygons_face_axis (const convex_piece *a, xform xa, const convex_piece *b, xform xb, int32_t face);
/* polygons_separation, and the face whose normal that is: edge e of a as
 * e, edge e of b as -1 - e. */
double polygons_separation_face (const convex_piece *a, xform xa, const convex_piece *b, xform xb, vec2 *axis,
                                 int32_t *face);

/* The largest separation of piece q from p's edges and its edge (the
 * first to reach it), every edge searched in turn until the largest so far
 * exceeds `margin`; *outer and *outer_edge the same over the edges that are
 * not internal (seams.h; -1: none). The SAT test prunes the edges that
 * cannot win and must give exactly this (tests/test_collision.c). */
double sat_max_separation_all (const convex_piece *p, xform xp, const convex_piece *q, xform xq, double margin,
                               int32_t *edge, double *outer, int32_t *outer_edge);
/* The same, pruned, as collide_polygons_sat and polygons_separation use
 * it. */
double sat_max_separation (const convex_piece *p, xform xp, const convex_piece *q, xform xq, double margin,
                           int32_t *edge, double *outer, int32_t *outer_edge);

/* Separating axis theorem with the minimum push vector (thesis 3.2.1): the
 * axis of least overlap among the edge normals of both pieces gives the
 * normal; the contact points, which SAT alone does not give, come from
 * clipping the incident edge against the reference edge's side planes (up to
 * two points). */
int32_t collide_polygons_sat (const convex_piece *a, xform xa, const convex_piece *b, xform xb, double margin, manifold *m);
/* The same with the reference face chosen by a direction instead of the
 * hysteresis that keeps it from flickering between steps: of the two
 * pieces' faces that separate them most, the one whose outward normal (a's,
 * or b's turned round) lies nearer the unit vector `toward` (from a towards
 * b). Where the time of impact finds two pieces touching corner to corner,
 * both faces are at separation 0 there, and the face the pair closed on is
 * the one that separated them just before (toi.c): the hysteresis could
 * take the other, across which the pieces do not approach, and their
 * impact would then take no impulse. With `toward` NULL, exactly
 * collide_polygons_sat. */
int32_t collide_polygons_sat_toward (const convex_piece *a, xform xa, const convex_piece *b, xform xb, double margin,
                                     const vec2 *toward, manifold *m);

/* The thesis' vertex-edge method (3.2.2) on the true outlines, convex or
 * concave (counter-clockwise, body frame): vertices of one polygon inside the
 * other give impact points, the penetrated edge gives the normal, including
 * the parallel-edge and vertex-on-vertex cases. */
int32_t collide_polygons_vertex_edge (const vec2 *va, int32_t na, xform xa, const vec2 *vb, int32_t nb, xform xb, double margin, manifold *m);
/* The same with seams: bit i of internal_a (internal_b) says edge i of A's
 * (B's) outline is internal (seams.h), and no contact takes such an edge as
 * its penetrated edge or as one of a parallel pair. */
int32_t collide_polygons_vertex_edge_seams (const vec2 *va, int32_t na, uint64_t internal_a, xform xa, const vec2 *vb,
                                            int32_t nb, uint64_t internal_b, xform xb, double margin, manifold *m);
/* Two polygon shapes' whole outlines, each with its seams (seams_outline):
 * the world's vertex-edge narrow phase. */
int32_t collide_outlines_vertex_edge (const shape *sa, xform xa, const shape *sb, xform xb, double margin, manifold *m);

#endif
