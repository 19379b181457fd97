/* Separating axis theorem for convex pieces (thesis 3.2.1), with contact
 * points from clipping, which the thesis names as SAT's pitfall. */
#include "collide.h"
#ifdef __SSE2__
#include <emmintrin.h>
#endif

/* The gap between an edge of another piece, whose outward normal is n and
 * whose line lies at `offset` along it, and piece q's nearest vertex (all
 * in q's frame): the separation along that edge (thesis fig. 3.7). */
static inline double edge_separation (const convex_piece *q, vec2 n, double offset)
{
  double s = INFINITY;
  int32_t j;
  for (j = 0; j < q->count; ++j)
    {
      double d = v2_dot (n, q->vertices[j]);
      s = d < s ? d : s;
    }
  return s - offset;
}

/* The edge of `p` (placed by xp) whose outward normal separates it most from
 * `q` (placed by xq): the candidate axes of thesis fig. 3.7. The separation
 * along an axis is the gap between p's edge and q's nearest vertex; the
 * largest over the axes is minus the length of the minimum push vector.
 * Every edge in turn, stopping at the first whose separation makes the
 * largest so far exceed `margin` (a separating axis: no contact, the rest
 * cannot matter); *outer is the largest over the edges that are not
 * internal (seams.h), *outer_edge its edge (-1: none). */
double sat_max_separation_all (const convex_piece *p, xform xp, const convex_piece *q, xform xq, double margin,
                               int32_t *edge, double *outer, int32_t *outer_edge)
{
  xform rel = xform_relative (xq, xp); /* p in q's frame */
  double best = -INFINITY, out = -INFINITY;
  int32_t i, best_edge = 0, out_edge = -1;
  /* the running bests in locals, updated by selects: which edge wins is
   * not predictable, and through the pointers every edge would store and
   * reload them */
  for (i = 0; i < p->count; ++i)
    {
      vec2 n = rot2_apply (rel.q, p->normals[i]);
      double s = edge_separation (q, n, v2_dot (n, xform_apply (rel, p->vertices[i])));
      int take = (s > out) & !piece_edge_internal (p, i);
      out = take ? s : out;
      out_edge = take ? i : out_edge;
      take = s > best;
      best = take ? s : best;
      best_edge = take ? i : best_edge;
      if (best > margin)
        break;
    }
  *edge = best_edge;
  *outer = out;
  *outer_edge = out_edge;
  return best;
}

/* Pieces of more edges than this, or with internal edges, take the plain
 * search. */
#define SAT_PRUNE_MAX_EDGES 16
/* How far a computed separation may lie above its bound computed another
 * way (in the other piece's frame), through rounding, relative to the size
 * of the coordinates: a few units in the last place would do. */
#define SAT_PRUNE_ROUNDING 1e-9

/* The lowest set bit of m (not 0). */
static inline int32_t lowest_bit (uint32_t m)
{
#ifdef __GNUC__
  return __builtin_ctz (m);
#else
  int32_t i = 0;
  for (; !(m & 1u); m >>= 1)
    ++i;
  return i;
#endif
}

/* Bit i set for each of the n gaps that is not below `least` (a gap that
 * is no number is kept), without a branch (which are kept is not
 * predictable).
 * With SSE2, two gaps a compare: gap[n] is set (a number, whatever it
 * is), and its bit is dropped. */
static inline uint32_t keep_mask (const double *gap, int32_t n, double least)
{
  uint32_t keep = 0;
  int32_t i;
#ifdef __SSE2__
  __m128d l = _mm_set1_pd (least);
  for (i = 0; i < n; i += 2)
    keep |= (uint32_t) _mm_movemask_pd (_mm_cmpnlt_pd (_mm_loadu_pd (gap + i), l)) << i;
  keep &= (1u << n) - 1u;
#else
  for (i = 0; i < n; ++i)
    keep |= (uint32_t) !(gap[i] < least) << i;
#endif
  return keep;
}

/* Edge i of p searched as the plain search does, taken as the best if it
 * beats it. Returns whether the best now exceeds the margin (the search
 * stops). */
static inline int edge_taken (const convex_piece *p, const convex_piece *q, xform rel, int32_t i, double margin,
                              double *best, int32_t *best_edge)
{
  vec2 n = rot2_apply (rel.q, p->normals[i]);
  double s = edge_separation (q, n, v2_dot (n, xform_apply (rel, p->vertices[i])));
  int take = s > *best;
  *best = take ? s : *best;
  *best_edge = take ? i : *best_edge;
  return *best > margin;
}

/* sat_max_separation_all's result, bit for bit, without the nearest-vertex
 * search for edges that cannot win. q's vertices lie within its bounding
 * radius R of its vertex average c, which lies within q: an edge's
 * separation is at most its gap to c, and at least that gap less R. So the
 * largest separation is at least the largest gap less R, and an edge whose
 * gap to c is below that (by more than rounding: the gaps are taken in p's
 * own frame, without turning each edge into q's) cannot win. The rest are
 * searched in order, as the plain search takes them and with its
 * arithmetic: the same largest, the same first edge to reach it, the same
 * stop past the margin (an edge passed over may be past the margin where
 * the plain search would stop at it, but then both end past it, and
 * callers look no further). */
static inline double max_separation (const convex_piece *p, xform xp, const convex_piece *q, xform xq, double margin,
                                     int32_t *edge, double *outer, int32_t *outer_edge)
{
  xform rel;
  vec2 c;
  /* room for one past the last edge (keep_mask) */
  double gap[SAT_PRUNE_MAX_EDGES + 1], least, best = -INFINITY, top = -INFINITY;
  int32_t i, best_edge = 0;
  uint32_t keep = 0;
  if (p->count > SAT_PRUNE_MAX_EDGES || p->internal != 0)
    return sat_max_separation_all (p, xp, q, xq, margin, edge, outer, outer_edge);
  rel = xform_relative (xq, xp); /* p in q's frame */
  c = xform_apply_inv (rel, q->center);
  for (i = 0; i < p->count; ++i)
    {
      gap[i] = v2_dot (p->normals[i], v2_sub (c, p->vertices[i]));
      top = gap[i] > top ? gap[i] : top;
    }
  gap[i] = 0.0;
  least = top - q->bound_radius
          - SAT_PRUNE_ROUNDING * (fabs (rel.p.x) + fabs (rel.p.y) + fabs (p->center.x) + fabs (p->center.y)
                                  + fabs (q->center.x) + fabs (q->center.y) + p->bound_radius + q->bound_radius);
  /* the edges that may win, then searched in order */
  keep = keep_mask (gap, p->count, least);
  for (; keep; keep &= keep - 1)
    if (edge_taken (p, q, rel, lowest_bit (keep), margin, &best, &best_edge))
      break;
  /* no internal edges: the largest over the outer ones is the largest
   * (none when no separation was a number) */
  *edge = best_edge;
  *outer = best;
  *outer_edge = best > -INFINITY ? best_edge : -1;
  return best;
}

/* max_separation, for callers outside: sat_collide has it inline, where
 * the two poses are not passed on the stack twice for every pair. */
double sat_max_separation (const convex_piece *p, xform xp, const convex_piece *q, xform xq, double margin,
                          int32_t *edge, double *outer, int32_t *outer_edge)
{
  return max_separation (p, xp, q, xq, margin, edge, outer, outer_edge);
}

/* The face of the larger of the two pieces' separations: edge_a, or -1 -
 * edge_b when b's is larger. */
static inline int32_t separation_face (double sep_a, int32_t edge_a, double sep_b, int32_t edge_b)
{
  return sep_b > sep_a ? -1 - edge_b : edge_a;
}

vec2 polygons_face_axis (const convex_piece *a, xform xa, const convex_piece *b, xform xb, int32_t face)
{
  return face < 0 ? v2_neg (rot2_apply (xb.q, b->normals[-1 - face])) : rot2_apply (xa.q, a->normals[face]);
}

double polygons_separation_face (const convex_piece *a, xform xa, const convex_piece *b, xform xb, vec2 *axis,
                                 int32_t *face)
{
  int32_t edge_a, edge_b, outer_edge;
  double outer, sa = sat_max_separation (a, xa, b, xb, INFINITY, &edge_a, &outer, &outer_edge);
  double sb = sat_max_separation (b, xb, a, xa, INFINITY, &edge_b, &outer, &outer_edge);
  *face = separation_face (sa, edge_a, sb, edge_b);
  *axis = polygons_face_axis (a, xa, b, xb, *face);
  return sa > sb ? sa : sb;
}

double polygons_separation (const convex_piece *a, xform xa, const convex_piece *b, xform xb, vec2 *axis)
{
  int32_t face;
  return polygons_separation_face (a, xa, b, xb, axis, &face);
}

/* The largest hysteresis between the two pieces' faces, over the smaller
 * piece's bounding radius. A tenth of a margin of slop size keeps nearly
 * equal faces from flickering between steps; a margin that looks ahead
 * as far as a fast body travels (continuous collision) can be many times a
 * piece's size, and a tenth of it would prefer a face that lies beside the
 * other piece, where clipping leaves no point: overlapping pieces would
 * then have no contact (test_sat_pieces_within_the_margin_are_always_a_contact). */
#define SAT_FACE_HYSTERESIS 0.005

/* collide_polygons_sat_toward takes the face whose normal lies nearer
 * `toward` only when its cosine with it is larger by this much (the normals
 * about 2.6 degrees apart when one is `toward` itself): nearly parallel
 * faces (a box landing flat on another) keep the face the detections keep
 * (the hysteresis), so the points' features match the next step's and keep
 * their warm start. */
#define SAT_TOWARD_TOLERANCE 1e-3

/* Below this fraction of their coordinates' and sizes' scale, two points
 * are too near for the direction between them to mean anything. */
#define CORNER_NOISE 1e-9

/* The feature of a corner contact (corner_contact): bits 16 to 29 all set,
 * which no reference edge's are. */
#define CORNER_FEATURE 0x3fff0000u

typedef struct clip_vertex {
  vec2 v;
  uint32_t id;
} clip_vertex;

int sat_feature_face (uint32_t feature, int *side, int32_t *edge)
{
  if ((feature & CORNER_FEATURE) == CORNER_FEATURE)
    return 0;
  *side = (int) (feature >> 31);
  *edge = (int32_t) ((feature >> 16) & 0x7fffu);
  return 1;
}

/* Keep the part of segment `in` where dot(n, x) <= offset (Sutherland-Hodgman
 * on one plane). Returns the number of points kept (0 to 2). A vertex within
 * `tol` of the plane counts as on it and keeps its own id: boxes of equal
 * width stacked exactly have their corners on each other's side planes, and
 * rounding must not flip those points between "vertex" and "clipped" ids
 * from one step to the next (which would drop their warm-start impulse). */
static inline int clip_segment (clip_vertex out[2], const clip_vertex in[2], vec2 n, double offset,
                                uint32_t plane_id, double tol)
{
  int count = 0;
  double d0 = v2_dot (n, in[0].v) - offset, d1 = v2_dot (n, in[1].v) - offset;
  if (d0 <= tol)
    out[count++] = in[0];
  if (d1 <= tol)
    out[count++] = in[1];
  if ((d0 < -tol && d1 > tol) || (d0 > tol && d1 < -tol))
    {
      double t = d0 / (d0 - d1);
      out[count].v = v2_lerp (in[0].v, in[1].v, t);
      out[count].id = plane_id;
      count++;
    }
  return count;
}

/* The point of segment [p, q] nearest to x: an end itself when it is
 * one (p + 1 (q - p) rounds q's smallest digits away, and a corner a hair
 * from it would be found on it). */
static vec2 nearest_on_segment (vec2 p, vec2 q, vec2 x)
{
  vec2 d = v2_sub (q, p);
  double len2 = v2_dot (d, d), u = len2 > 0.0 ? v2_dot (v2_sub (x, p), d) / len2 : 0.0;
  return u <= 0.0 ? p : u >= 1.0 ? q : v2_mad (p, u, d);
}

/* The nearest pair of points of a vertex of one piece and an edge of the
 * other, over both ways round: *pa on a, *pb on b, their squared distance
 * returned; *feature names the vertex, the edge and whose vertex it was. */
static double nearest_corner (const convex_piece *a, xform xa, const convex_piece *b, xform xb, vec2 *pa, vec2 *pb,
                              uint32_t *feature)
{
  double best = INFINITY;
  int side, i, j;
  for (side = 0; side < 2; ++side)
    {
      const convex_piece *v = side ? b : a, *e = side ? a : b;
      xform xv = side ? xb : xa, xe = side ? xa : xb;
      for (i = 0; i < v->count; ++i)
        {
          vec2 x = xform_apply (xv, v->vertices[i]);
          for (j = 0; j < e->count; ++j)
            {
              vec2 c = nearest_on_segment (xform_apply (xe, e->vertices[j]),
                                           xform_apply (xe, e->vertices[(j + 1) % e->count]), x);
              double d2 = v2_len2 (v2_sub (c, x));
              if (d2 < best)
                {
                  best = d2;
                  *pa = side ? c : x;
                  *pb = side ? x : c;
                  *feature = CORNER_FEATURE | ((uint32_t) side << 30) | ((uint32_t) (i & 0xff) << 8)
                             | (uint32_t) (j & 0xff);
                }
            }
        }
    }
  return best;
}

/* Two pieces apart whose faces give no point (clipping leaves less than an
 * edge: each piece's nearest vertex lies beside the other's face, corner
 * towards corner) meet where they are nearest: one point there, the normal
 * from a's nearest point to b's, if within the margin. The separating
 * axis alone would let them pass each other's corners unseen, and a body
 * closing fast on a corner would be met only once deep in it. Not for
 * pieces with seams (seams.h), which meet only on their faces. */
static int32_t corner_contact (const convex_piece *a, xform xa, const convex_piece *b, xform xb, double margin,
                               vec2 axis, manifold *m)
{
  vec2 pa = v2 (0.0, 0.0), pb = v2 (0.0, 0.0);
  uint32_t feature = 0u;
  double d, scale;
  m->count = 0;
  if (a->internal || b->internal)
    return 0;
  nearest_corner (a, xa, b, xb, &pa, &pb, &feature);
  /* their distance by hypot: its square underflows below 1e-154, and the
   * normal would be no unit vector */
  d = hypot (pb.x - pa.x, pb.y - pa.y);
  if (!(d > 0.0) || d > margin)
    return 0;
  /* a hair apart (a touch that the time of impact found), the direction
   * between the two points is the rounding of their coordinates, any way
   * round: the separating axis stands for it (an impact along the noise
   * took a normal across the approach, found the corners leaving, and let
   * them pass into each other) */
  scale = fabs (pa.x) + fabs (pa.y) + a->bound_radius + b->bound_radius;
  m->points[0].normal = d <= CORNER_NOISE * scale ? axis : v2_scale (v2_sub (pb, pa), 1.0 / d);
  m->points[0].point = v2_scale (v2_add (pa, pb), 0.5);
  m->points[0].depth = -d;
  m->points[0].feature = feature;
  m->count = 1;
  return 1;
}

/* The normal (from a to b) of the edge that separates the pieces most. */
static vec2 separating_axis (const convex_piece *a, xform xa, int32_t edge_a, double sep_a, const convex_piece *b,
                             xform xb, int32_t edge_b, double sep_b)
{
  return polygons_face_axis (a, xa, b, xb, separation_face (sep_a, edge_a, sep_b, edge_b));
}

/* The axis of a corner contact: `toward` when given
 * (collide_polygons_sat_toward), else the separating axis. */
static vec2 meeting_axis (const convex_piece *a, xform xa, int32_t edge_a, double sep_a, const convex_piece *b, xform xb,
                          int32_t edge_b, double sep_b, const vec2 *toward)
{
  return toward ? *toward : separating_axis (a, xa, edge_a, sep_a, b, xb, edge_b, sep_b);
}

/* Overlapping pieces whose faces give no point (clipping leaves less than
 * an edge: a corner pushed into the other piece next to its corner, the
 * incident edge lying beside the reference face) meet at the other piece's
 * vertex deepest behind the face of least overlap: one point, that face's
 * normal, its depth the face's overlap. Without it they had no contact at
 * all, however deep (2 times in 2000 steps of the bench gas, up to 2.0 mm;
 * 11 times in the rain's, up to 4.9 mm). */
static int32_t deepest_vertex (const convex_piece *ref, xform xref, int32_t ref_edge, const convex_piece *inc,
                               xform xinc, int flip, manifold *m)
{
  vec2 n = rot2_apply (xref.q, ref->normals[ref_edge]), v1 = xform_apply (xref, ref->vertices[ref_edge]);
  double deepest = INFINITY;
  int32_t i, at = 0;
  for (i = 0; i < inc->count; ++i)
    {
      double sep = v2_dot (n, v2_sub (xform_apply (xinc, inc->vertices[i]), v1));
      if (sep < deepest)
        deepest = sep, at = i;
    }
  m->points[0].point = v2_mad (xform_apply (xinc, inc->vertices[at]), -0.5 * deepest, n);
  m->points[0].normal = flip ? v2_neg (n) : n;
  m->points[0].depth = -deepest;
  m->points[0].feature = ((uint32_t) flip << 31) | ((uint32_t) (ref_edge & 0x7fff) << 16) | (uint32_t) at;
  m->count = 1;
  return 1;
}

/* collide_polygons_sat, with the reference face chosen by `toward` when it
 * is not NULL (collide_polygons_sat_toward). */
static int32_t sat_collide (const convex_piece *a, xform xa, const convex_piece *b, xform xb, double margin,
                            const vec2 *toward, manifold *m)
{
  int32_t edge_a, edge_b, outer_a, outer_b, ref_edge, inc_edge = 0, i, n_inc, flip, tries;
  const convex_piece *ref, *inc;
  xform xref, xinc;
  double sep_a, sep_b, face_a, face_b, best = INFINITY, side_tol;
  /* the hysteresis between the two pieces' faces (below): a tenth of the
   * margin, but no more than SAT_FACE_HYSTERESIS of the smaller piece */
  double most = SAT_FACE_HYSTERESIS * (a->bound_radius < b->bound_radius ? a->bound_radius : b->bound_radius);
  double tol = 0.1 * margin < most ? 0.1 * margin : most;
  vec2 n_ref, v1, v2_, tangent;
  clip_vertex seg[2], clip1[2], clip2[2];
  m->count = 0;
  m->gap = INFINITY;
  m->separation_face = MANIFOLD_NO_FACE;
  sep_a = max_separation (a, xa, b, xb, margin, &edge_a, &face_a, &outer_a);
  if (sep_a > margin)
    return 0;
  sep_b = max_separation (b, xb, a, xa, margin, &edge_b, &face_b, &outer_b);
  if (sep_b > margin)
    return 0;
  /* neither search stopped at the margin: both are the whole searches
   * polygons_separation_face makes, and it takes the larger as here */
  m->separation = sep_a > sep_b ? sep_a : sep_b;
  m->separation_face = separation_face (sep_a, edge_a, sep_b, edge_b);
  /* the faces a contact may take: none of a seam (seams.h), though the
   * separation test above counts every axis */
  if (outer_a < 0 && outer_b < 0)
    return 0;
  /* prefer A's face unless B's is clearly better, so the choice does not
   * flicker between steps for nearly equal candidates; `toward` overrules
   * that where the other face's outward normal lies clearly nearer it */
  flip = outer_a < 0 || (outer_b >= 0 && face_b > face_a + tol);
  if (toward && outer_a >= 0 && outer_b >= 0)
    {
      double along_a = v2_dot (rot2_apply (xa.q, a->normals[outer_a]), *toward);
      double along_b = -v2_dot (rot2_apply (xb.q, b->normals[outer_b]), *toward);
      if ((flip ? along_a - along_b : along_b - along_a) > SAT_TOWARD_TOLERANCE)
        flip = !flip;
    }
  for (tries = 0;; ++tries)
    {
      if (flip)
        ref = b, xref = xb, inc = a, xinc = xa, ref_edge = outer_b;
      else
        ref = a, xref = xa, inc = b, xinc = xb, ref_edge = outer_a;
      n_ref = rot2_apply (xref.q, ref->normals[ref_edge]);
      /* incident edge: the one on the other piece facing the reference
       * normal most directly */
      n_inc = inc->count;
      best = INFINITY;
      for (i = 0; i < n_inc; ++i)
        {
          double d = v2_dot (n_ref, rot2_apply (xinc.q, inc->normals[i]));
          if (d < best)
            {
              best = d;
              inc_edge = i;
            }
        }
      /* nor the incident one: a face against a seam is met on the other
       * piece's own face, the surface the seam continues */
      if (!piece_edge_internal (inc, inc_edge))
        break;
      if (tries == 1 || (flip ? outer_a : outer_b) < 0)
        return 0;
      flip = !flip;
    }
  seg[0].v = xform_apply (xinc, inc->vertices[inc_edge]);
  seg[0].id = (uint32_t) inc_edge;
  seg[1].v = xform_apply (xinc, inc->vertices[(inc_edge + 1) % n_inc]);
  seg[1].id = (uint32_t) ((inc_edge + 1) % n_inc);
  v1 = xform_apply (xref, ref->vertices[ref_edge]);
  v2_ = xform_apply (xref, ref->vertices[(ref_edge + 1) % ref->count]);
  tangent = v2_normalize (v2_sub (v2_, v1));
  side_tol = 1e-9 * v2_len (v2_sub (v2_, v1));
  /* clip to the reference edge's two side planes; an incident edge that
   * lies beside the reference edge meets the other piece at a corner */
  if (clip_segment (clip1, seg, v2_neg (tangent), -v2_dot (tangent, v1), 0x8000u, side_tol) < 2
      || clip_segment (clip2, clip1, tangent, v2_dot (tangent, v2_), 0x8001u, side_tol) < 2)
    {
      /* the face that separates them most, without the hysteresis: the
       * one of least overlap; with seams, the face taken above (a body
       * sliding over tiles meets their surface, not its own side) */
      int by_b = a->internal || b->internal ? flip : outer_b >= 0 && (outer_a < 0 || face_b > face_a);
      if (sep_a > 0.0 || sep_b > 0.0)
        return corner_contact (a, xa, b, xb, margin, meeting_axis (a, xa, edge_a, sep_a, b, xb, edge_b, sep_b, toward),
                               m);
      return by_b ? deepest_vertex (b, xb, outer_b, a, xa, 1, m) : deepest_vertex (a, xa, outer_a, b, xb, 0, m);
    }
  m->gap = flip ? face_b : face_a;
  for (i = 0; i < 2; ++i)
    {
      double sep = v2_dot (n_ref, v2_sub (clip2[i].v, v1));
      manifold_point *mp;
      if (sep > margin)
        continue;
      mp = &m->points[m->count++];
      /* the point halfway between the incident vertex and the reference face */
      mp->point = v2_mad (clip2[i].v, -0.5 * sep, n_ref);
      mp->normal = flip ? v2_neg (n_ref) : n_ref;
      mp->depth = -sep;
      mp->feature = ((uint32_t) flip << 31) | ((uint32_t) (ref_edge & 0x7fff) << 16) | clip2[i].id;
    }
  if (m->count == 0 && (sep_a > 0.0 || sep_b > 0.0))
    return corner_contact (a, xa, b, xb, margin, meeting_axis (a, xa, edge_a, sep_a, b, xb, edge_b, sep_b, toward), m);
  return m->count;
}

int32_t collide_polygons_sat (const convex_piece *a, xform xa, const convex_piece *b, xform xb, double margin, manifold *m)
{
  return sat_collide (a, xa, b, xb, margin, NULL, m);
}

int32_t collide_polygons_sat_toward (const convex_piece *a, xform xa, const convex_piece *b, xform xb, double margin,
                                     const vec2 *toward, manifold *m)
{
  return sat_collide (a, xa, b, xb, margin, toward, m);
}
