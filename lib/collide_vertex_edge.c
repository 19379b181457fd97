/* The thesis' vertex-edge collision test (3.2.2) on the true outlines of two
 * simple polygons, convex or concave.
 *
 * Every vertex V of one polygon P is tested against the other polygon Q, in
 * Q's body frame:
 *   - V inside Q (winding number, so a concave notch is not filled in): the
 *     penetrated edge is the one V's adjacent segments V(i-1)V and V(i+1)V
 *     last cross on their way in (fig. 3.8). When the two segments come in
 *     through different edges (vertex on vertex, fig. 3.11, or V next to a
 *     corner of Q), the thesis took whichever edge came up first; here it is
 *     the crossed edge of least penetration, then the lower index, so the
 *     choice does not depend on loop order. When neither segment crosses
 *     (both neighbours inside too, e.g. P wholly inside Q), the nearest edge
 *     of Q is used, so there is always a finite unit normal.
 *   - V outside Q: a contact only if V is within `margin` of an edge and its
 *     projection falls on that edge (the nearest such edge); depth is then
 *     minus the distance.
 * Then, if one of V's own edges is antiparallel to the chosen edge and the
 * two overlap (fig. 3.9), the contact is the parallel-edge one instead.
 *
 * Seams (seams.h): an internal edge of a static outline, shared with
 * another static shape, is never the penetrated edge nor one of a parallel
 * pair, as SAT takes no face from a seam: a vertex that came in through a
 * seam (a box sliding over tiles, its front corner a hair below the next
 * tile's top) is met on the crossed edge that is not one, else on the
 * nearest edge that is not one, so it slides on across the surface the
 * seam continues instead of catching on the tile's side (a ghost
 * collision). And a vertex next to a seam is no corner: the face goes on
 * across it (as a circle meets it, collide_circle.c), so it makes only the
 * parallel contact of its outer edge, never a vertex-edge one: a box
 * sliding on a tile, its bottom on the tiles' line, met the next tile's
 * corner with its front face, at the end of that face (and the first
 * tile's corner there as well), and stopped.
 *
 * Choices the solver relies on:
 *   - Normals point from A to B: minus Q's outward edge normal when P is A,
 *     Q's outward edge normal when P is B. Depth is the distance of V from
 *     the penetrated edge's line, positive when overlapping.
 *   - Parallel edges give ONE contact, at the midpoint of the overlap of the
 *     two edges (fig. 3.10), as the thesis did. It is computed from the
 *     (edge of A, edge of B) pair alone, whichever vertex found it, so the
 *     two vertices of the edge (and the vertex of the other polygon, when
 *     both polygons have a corner inside the other) give the same point,
 *     which is kept once. The point is halfway between the two edge lines,
 *     so swapping A and B gives the same point; the normal is the bisector of
 *     the two edges' normals, which is the face normal when they are exactly
 *     parallel. Edges count as parallel within PARALLEL_SIN, and only while
 *     both ends of the overlap are within `margin`: a slightly tilted resting
 *     box beyond that gets two vertex contacts, one per corner.
 *   - feature ids (uint32_t), stable while the same features touch:
 *       vertex-edge:  (owner << 31) | (vertex << 15) | edge
 *                     owner 0 = vertex of A against edge of B, 1 = the reverse
 *       parallel:     (1 << 30) | (edge of A << 15) | edge of B
 *     indices are taken modulo 2^15 (CAROM_MAX_POLYGON_VERTICES is far below).
 *   - At most MANIFOLD_MAX_POINTS contacts: the deepest, ties broken by the
 *     lower feature id, listed in that order. */
#include "collide.h"

#include "seams.h"

/* |sin| of the angle under which two edges count as parallel (fig. 3.9). */
#define PARALLEL_SIN 1e-6
/* A vertex the winding test puts outside may lie this far (relative to the
 * edge length) on the inner side of an edge and still count as touching it:
 * points on the boundary fall either way by rounding. */
#define ON_EDGE_REL 1e-9

#define FEATURE_INDEX_MASK 0x7FFFu
#define FEATURE_OWNER_B (1u << 31)
#define FEATURE_PARALLEL (1u << 30)

/* The two polygons as given (A, B), the polygon whose vertices are tested
 * (P) and the one they are tested against (Q), with the transform taking P's
 * body frame into Q's. */
typedef struct ve_pass {
  const vec2 *va, *vb;
  int32_t na, nb;
  xform xa, xb;
  double margin;
  const vec2 *vp;
  int32_t np;
  xform xp;
  const vec2 *vq;
  int32_t nq;
  xform xq;
  xform p_to_q;
  int owner_b; /* P is polygon B */
  uint64_t internal_a, internal_b, internal_p, internal_q; /* seams: bit i, edge i */
} ve_pass;

static int32_t next_index (int32_t i, int32_t n) { return i + 1 < n ? i + 1 : 0; }
static int32_t prev_index (int32_t i, int32_t n) { return i > 0 ? i - 1 : n - 1; }

/* Whether edge j of an outline with seams `internal` is internal. */
static int seam (uint64_t internal, int32_t j)
{
  return j < 64 && ((internal >> j) & 1u);
}

/* Signed distance of v from the line of edge j of Q, positive outside (the
 * outward normal of a counter-clockwise edge e is (e.y, -e.x)). Returns 0 for
 * a zero-length edge, which then takes part in nothing. */
static int edge_distance (const ve_pass *s, int32_t j, vec2 v, double *dist)
{
  vec2 q0 = s->vq[j], e = v2_sub (s->vq[next_index (j, s->nq)], q0);
  double len = v2_len (e);
  if (!(len > 0.0))
    return 0;
  *dist = v2_cross (v2_sub (v, q0), e) / len;
  return 1;
}

/* Nonzero winding number of v about Q's outline: the true outline, so a
 * point in a concave notch is outside. */
static int inside_q (const ve_pass *s, vec2 v)
{
  int32_t j, wn = 0;
  for (j = 0; j < s->nq; ++j)
    {
      vec2 a = s->vq[j], b = s->vq[next_index (j, s->nq)];
      double side = v2_cross (v2_sub (b, a), v2_sub (v, a));
      if (a.y <= v.y)
        {
          if (b.y > v.y && side > 0.0)
            ++wn;
        }
      else if (b.y <= v.y && side < 0.0)
        --wn;
    }
  return wn != 0;
}

/* The edge of Q through which the segment n -> v last enters Q before
 * reaching v (fig. 3.8's crossing of e_j), or -1. Entering means moving
 * against the edge's outward normal, i.e. cross (v - n, e) < 0. Ties (the
 * segment through a corner of Q) go to the shallower edge, then the lower
 * index. */
static int32_t last_entry (const ve_pass *s, vec2 n, vec2 v)
{
  vec2 r = v2_sub (v, n);
  int32_t j, best = -1;
  double best_t = 0.0, best_depth = 0.0;
  for (j = 0; j < s->nq; ++j)
    {
      vec2 q0 = s->vq[j], e = v2_sub (s->vq[next_index (j, s->nq)], q0);
      vec2 w = v2_sub (q0, n);
      double den = v2_cross (r, e), tn, un, t, d;
      if (!(den < 0.0) || seam (s->internal_q, j))
        continue;
      /* t along n -> v and u along the edge, both in [0, 1]; den < 0 */
      tn = v2_cross (w, e);
      un = v2_cross (w, r);
      if (tn > 0.0 || tn < den || un > 0.0 || un < den)
        continue;
      t = tn / den;
      if (!edge_distance (s, j, v, &d))
        continue;
      if (best < 0 || t > best_t || (t == best_t && -d < best_depth))
        {
          best = j;
          best_t = t;
          best_depth = -d;
        }
    }
  return best;
}

/* The edge of Q nearest to v (distance to the segment) that is not a seam
 * (`seams` 0: any edge): the fallback when v is inside Q and no crossing
 * is found. When the nearest point is a corner of Q, its two edges tie
 * exactly (the distance is taken to the corner itself, not through each
 * edge, so rounding cannot pick one); at a reflex corner v may lie outside
 * one of the two edge lines, so the tie goes to an edge v is behind, then
 * the shallower, then the lower index. */
static int32_t nearest_edge (const ve_pass *s, vec2 v, uint64_t seams)
{
  int32_t j, best = -1;
  double best_d2 = 0.0, best_dist = 0.0;
  for (j = 0; j < s->nq; ++j)
    {
      vec2 q0 = s->vq[j], q1 = s->vq[next_index (j, s->nq)], e = v2_sub (q1, q0);
      vec2 w = v2_sub (v, q0);
      double len2 = v2_len2 (e), t, d2, dist;
      if (!(len2 > 0.0) || seam (seams, j) || !edge_distance (s, j, v, &dist))
        continue;
      t = v2_dot (w, e);
      if (t <= 0.0)
        d2 = v2_len2 (w);
      else if (t >= len2)
        d2 = v2_len2 (v2_sub (v, q1));
      else
        d2 = dist * dist;
      if (best < 0 || d2 < best_d2
          || (d2 == best_d2
              && ((dist <= 0.0 && best_dist > 0.0)
                  || ((dist <= 0.0) == (best_dist <= 0.0) && dist > best_dist))))
        {
          best = j;
          best_d2 = d2;
          best_dist = dist;
        }
    }
  return best;
}

/* For v outside Q: the nearest edge within margin whose segment v projects
 * onto, not a seam, or -1. */
static int32_t margin_edge (const ve_pass *s, vec2 v, double margin)
{
  int32_t j, best = -1;
  double best_d = 0.0;
  for (j = 0; j < s->nq; ++j)
    {
      vec2 q0 = s->vq[j], e = v2_sub (s->vq[next_index (j, s->nq)], q0);
      double len2 = v2_len2 (e), t, d;
      if (!(len2 > 0.0) || seam (s->internal_q, j) || !edge_distance (s, j, v, &d))
        continue;
      if (d > margin || d < -ON_EDGE_REL * sqrt (len2))
        continue;
      t = v2_dot (v2_sub (v, q0), e);
      if (t < 0.0 || t > len2)
        continue;
      if (best < 0 || d < best_d)
        {
          best = j;
          best_d = d;
        }
    }
  return best;
}

/* Point on segment p0 -> p1 whose projection on an axis is t, given the
 * projections t0, t1 of its ends (t0 != t1). */
static vec2 at_projection (vec2 p0, vec2 p1, double t0, double t1, double t)
{
  return v2_lerp (p0, p1, (t - t0) / (t1 - t0));
}

/* Parallel-edge contact between edge ka of A and edge jb of B (fig. 3.9 and
 * 3.10), in the world frame: the edges must be antiparallel within
 * PARALLEL_SIN, overlap along their common direction over a nonzero length,
 * and be within margin of each other at both ends of the overlap, neither
 * of them a seam. The point
 * is the midpoint of the overlap, halfway between the two edges. Computed
 * from the pair only, so every vertex that finds the pair gets the same
 * bits. */
static int parallel_contact (const ve_pass *s, int32_t ka, int32_t jb, manifold_point *c)
{
  vec2 a0 = xform_apply (s->xa, s->va[ka]), a1 = xform_apply (s->xa, s->va[next_index (ka, s->na)]);
  vec2 b0 = xform_apply (s->xb, s->vb[jb]), b1 = xform_apply (s->xb, s->vb[next_index (jb, s->nb)]);
  vec2 ua = v2_normalize (v2_sub (a1, a0)), ub = v2_normalize (v2_sub (b1, b0));
  vec2 u, n, am, bm;
  double ta1, tb0, tb1, lo, hi, mid, d_lo, d_hi;
  if (seam (s->internal_a, ka) || seam (s->internal_b, jb))
    return 0;
  if (v2_dot (ua, ub) >= 0.0 || fabs (v2_cross (ua, ub)) > PARALLEL_SIN)
    return 0;
  /* Axis along A's edge (fig. 3.10), taken as the bisector of the two edge
   * directions so that swapping A and B only flips its sign. */
  u = v2_normalize (v2_sub (ua, ub));
  n = v2 (u.y, -u.x); /* outward for A's edge: from A towards B */
  ta1 = v2_dot (v2_sub (a1, a0), u);
  tb0 = v2_dot (v2_sub (b0, a0), u);
  tb1 = v2_dot (v2_sub (b1, a0), u);
  if (!(ta1 > 0.0) || !(tb0 > tb1))
    return 0;
  lo = tb1 > 0.0 ? tb1 : 0.0;
  hi = tb0 < ta1 ? tb0 : ta1;
  if (!(hi > lo))
    return 0;
  d_lo = v2_dot (v2_sub (at_projection (a0, a1, 0.0, ta1, lo), at_projection (b0, b1, tb0, tb1, lo)), n);
  d_hi = v2_dot (v2_sub (at_projection (a0, a1, 0.0, ta1, hi), at_projection (b0, b1, tb0, tb1, hi)), n);
  if (d_lo < -s->margin || d_hi < -s->margin)
    return 0; /* tilted enough that one end is out of reach: two vertices */
  mid = 0.5 * (lo + hi);
  am = at_projection (a0, a1, 0.0, ta1, mid);
  bm = at_projection (b0, b1, tb0, tb1, mid);
  c->point = v2_scale (v2_add (am, bm), 0.5);
  c->normal = n;
  c->depth = v2_dot (v2_sub (am, bm), n);
  c->feature = FEATURE_PARALLEL | ((uint32_t) ka & FEATURE_INDEX_MASK) << 15 | ((uint32_t) jb & FEATURE_INDEX_MASK);
  return 1;
}

/* x ranks before y: deeper, then lower feature id. A total order, so the
 * kept set does not depend on the order contacts are found in. */
static int ranks_before (const manifold_point *x, const manifold_point *y)
{
  return x->depth > y->depth || (x->depth == y->depth && x->feature < y->feature);
}

/* Add c unless its feature is already there (a parallel pair found twice);
 * when full, it replaces the lowest-ranked point if it ranks before it. */
static void manifold_offer (manifold *m, const manifold_point *c)
{
  int32_t k, worst = 0;
  if (!is_finite (c->point.x) || !is_finite (c->point.y) || !is_finite (c->depth)
      || !is_finite (c->normal.x) || !is_finite (c->normal.y) || v2_len2 (c->normal) == 0.0)
    return;
  for (k = 0; k < m->count; ++k)
    if (m->points[k].feature == c->feature)
      return;
  if (m->count < MANIFOLD_MAX_POINTS)
    {
      m->points[m->count++] = *c;
      return;
    }
  for (k = 1; k < m->count; ++k)
    if (ranks_before (&m->points[worst], &m->points[k]))
      worst = k;
  if (ranks_before (c, &m->points[worst]))
    m->points[worst] = *c;
}

/* Whether the outline runs straight on through v (from vprev to vnext),
 * to the tolerance shape.c drops such vertices from a convex piece with:
 * such a vertex is no corner, only a point of the face through it, which
 * meets another polygon only by that face (the parallel contact) or by the
 * other's corners. Taken for a corner, the middle vertex of a tile's flat
 * top met the front face of a box sliding over it at the end of that face
 * and stopped it, where SAT, on the piece without it, did not. */
static int straight_through (vec2 vprev, vec2 v, vec2 vnext)
{
  vec2 e1 = v2_sub (v, vprev), e2 = v2_sub (vnext, v);
  return fabs (v2_cross (e1, e2)) <= 1e-12 * v2_len (e1) * v2_len (e2) && v2_dot (e1, e2) > 0.0;
}

/* The contact for vertex i of P (at v in Q's frame, neighbours vprev and
 * vnext), if any. */
static void vertex_contact (const ve_pass *s, int32_t i, vec2 vprev, vec2 v, vec2 vnext, manifold *m)
{
  manifold_point c;
  int32_t e, k;
  double d;
  if (inside_q (s, v))
    {
      int32_t ep = last_entry (s, vprev, v), en = last_entry (s, vnext, v);
      if (ep < 0 && en < 0)
        {
          /* deep inside, no crossing (or only through seams); an outline
           * of seams only keeps its nearest edge, for a finite normal */
          e = nearest_edge (s, v, s->internal_q);
          if (e < 0)
            e = nearest_edge (s, v, 0u);
        }
      else if (en < 0 || ep == en)
        e = ep; /* fig. 3.8, or one segment crossing (fig. 3.9) */
      else if (ep < 0)
        e = en;
      else
        {
          /* fig. 3.11: the two segments cross different edges */
          double dp = 0.0, dn = 0.0;
          edge_distance (s, ep, v, &dp);
          edge_distance (s, en, v, &dn);
          /* shallower = larger signed distance (both are <= 0) */
          e = (dp > dn || (dp == dn && ep < en)) ? ep : en;
        }
    }
  else
    e = margin_edge (s, v, s->margin);
  if (e < 0 || !edge_distance (s, e, v, &d))
    return;

  /* fig. 3.9: one of V's own edges lies along the penetrated edge */
  for (k = 0; k < 2; ++k)
    {
      int32_t pe = k == 0 ? prev_index (i, s->np) : i;
      if (s->owner_b ? parallel_contact (s, e, pe, &c) : parallel_contact (s, pe, e, &c))
        {
          manifold_offer (m, &c);
          return;
        }
    }
  /* a vertex next to a seam: the face goes on across it */
  if (seam (s->internal_p, prev_index (i, s->np)) || seam (s->internal_p, i))
    return;
  if (straight_through (vprev, v, vnext))
    return;

  {
    vec2 q0 = s->vq[e], q1 = s->vq[next_index (e, s->nq)];
    vec2 outward = v2_normalize (rot2_apply (s->xq.q, v2 (q1.y - q0.y, q0.x - q1.x)));
    c.point = xform_apply (s->xp, s->vp[i]);
    c.normal = s->owner_b ? outward : v2_neg (outward);
    c.depth = -d;
    c.feature = (s->owner_b ? FEATURE_OWNER_B : 0u) | ((uint32_t) i & FEATURE_INDEX_MASK) << 15
                | ((uint32_t) e & FEATURE_INDEX_MASK);
    manifold_offer (m, &c);
  }
}

/* All vertices of P against Q: of A against B (owner_b 0) or of B against
 * A (owner_b 1). */
static void vertex_pass (ve_pass *s, int owner_b, manifold *m)
{
  vec2 lo, hi, vprev, v, vnext;
  int32_t i, j;
  s->owner_b = owner_b;
  s->vp = owner_b ? s->vb : s->va;
  s->np = owner_b ? s->nb : s->na;
  s->xp = owner_b ? s->xb : s->xa;
  s->vq = owner_b ? s->va : s->vb;
  s->nq = owner_b ? s->na : s->nb;
  s->xq = owner_b ? s->xa : s->xb;
  s->internal_p = owner_b ? s->internal_b : s->internal_a;
  s->internal_q = owner_b ? s->internal_a : s->internal_b;
  s->p_to_q = xform_relative (s->xq, s->xp);

  /* Q's box in its own frame, grown by margin: vertices of P outside it can
   * neither be inside Q nor within margin of it. */
  lo = hi = s->vq[0];
  for (j = 1; j < s->nq; ++j)
    {
      lo = v2_min (lo, s->vq[j]);
      hi = v2_max (hi, s->vq[j]);
    }
  lo = v2_sub (lo, v2 (s->margin, s->margin));
  hi = v2_add (hi, v2 (s->margin, s->margin));

  vprev = xform_apply (s->p_to_q, s->vp[s->np - 1]);
  v = xform_apply (s->p_to_q, s->vp[0]);
  for (i = 0; i < s->np; ++i)
    {
      vnext = xform_apply (s->p_to_q, s->vp[next_index (i, s->np)]);
      if (v.x >= lo.x && v.x <= hi.x && v.y >= lo.y && v.y <= hi.y)
        vertex_contact (s, i, vprev, v, vnext, m);
      vprev = v;
      v = vnext;
    }
}

int32_t collide_polygons_vertex_edge (const vec2 *va, int32_t na, xform xa, const vec2 *vb, int32_t nb, xform xb,
                                      double margin, manifold *m)
{
  return collide_polygons_vertex_edge_seams (va, na, 0u, xa, vb, nb, 0u, xb, margin, m);
}

int32_t collide_outlines_vertex_edge (const shape *sa, xform xa, const shape *sb, xform xb, double margin, manifold *m)
{
  return collide_polygons_vertex_edge_seams (sa->vertices, sa->count, seams_outline (sa), xa, sb->vertices, sb->count,
                                             seams_outline (sb), xb, margin, m);
}

int32_t collide_polygons_vertex_edge_seams (const vec2 *va, int32_t na, uint64_t internal_a, xform xa, const vec2 *vb,
                                            int32_t nb, uint64_t internal_b, xform xb, double margin, manifold *m)
{
  ve_pass s;
  int32_t i, j;
  if (!m)
    return 0;
  m->count = 0;
  m->gap = INFINITY;
  m->separation_face = MANIFOLD_NO_FACE;
  if (!va || !vb || na < 3 || nb < 3)
    return 0;
  if (!(margin >= 0.0))
    margin = 0.0;

  s.va = va;
  s.na = na;
  s.xa = xa;
  s.vb = vb;
  s.nb = nb;
  s.xb = xb;
  s.margin = margin;
  s.internal_a = internal_a;
  s.internal_b = internal_b;
  /* Vertices of A against B, then of B against A. */
  vertex_pass (&s, 0, m);
  vertex_pass (&s, 1, m);

  /* Deepest first, so the order is the same whatever found them first. */
  for (i = 1; i < m->count; ++i)
    for (j = i; j > 0 && ranks_before (&m->points[j], &m->points[j - 1]); --j)
      {
        manifold_point t = m->points[j];
        m->points[j] = m->points[j - 1];
        m->points[j - 1] = t;
      }
  return m->count;
}
