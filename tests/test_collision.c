/* Collision detection (SAT, circles) and resolution (eq. 3.23) against
 * closed forms and conservation laws. */
#include "support.h"

#include <math.h>
#include <string.h>

#include "collide.h"

static convex_piece make_box_piece (double w, double h, vec2 *v, vec2 *n)
{
  convex_piece p;
  memset (&p, 0, sizeof p); /* no internal edges, no material */
  v[0] = v2 (-w / 2, -h / 2), v[1] = v2 (w / 2, -h / 2), v[2] = v2 (w / 2, h / 2), v[3] = v2 (-w / 2, h / 2);
  n[0] = v2 (0, -1), n[1] = v2 (1, 0), n[2] = v2 (0, 1), n[3] = v2 (-1, 0);
  p.count = 4, p.vertices = v, p.normals = n, p.center = v2 (0, 0), p.bound_radius = sqrt (w * w + h * h) / 2;
  return p;
}

static xform place (double x, double y, double angle)
{
  xform t;
  t.p = v2 (x, y);
  t.q = rot2_from_angle (angle);
  return t;
}

/* ---------------------------------------------------------- detection */

/* Face to face: two points, found by clipping (what SAT alone lacks). */
static void test_sat_face_contact_has_two_clipped_points (void **state)
{
  vec2 va[4], na[4], vb[4], nb[4];
  convex_piece a = make_box_piece (2, 2, va, na), b = make_box_piece (2, 2, vb, nb);
  manifold m;
  int i;
  (void) state;
  /* B sits on A, 0.1 deep, shifted right by 1: overlap in x is [0, 1] */
  assert_int_equal (collide_polygons_sat (&a, place (0, 0, 0), &b, place (1, 1.9, 0), 0.0, &m), 2);
  for (i = 0; i < 2; ++i)
    {
      assert_near_abs (m.points[i].normal.x, 0.0, 1e-15);
      assert_near_abs (m.points[i].normal.y, 1.0, 1e-15);
      assert_near_abs (m.points[i].depth, 0.1, 1e-12);
      assert_near_abs (m.points[i].point.y, 0.95, 1e-12); /* halfway into the overlap */
    }
  assert_near_abs (fmin (m.points[0].point.x, m.points[1].point.x), 0.0, 1e-12);
  assert_near_abs (fmax (m.points[0].point.x, m.points[1].point.x), 1.0, 1e-12);
  assert_true (m.points[0].feature != m.points[1].feature);
}

/* The minimum push vector of a rotated pair: a box tilted 45 degrees whose
 * corner pokes 0.05 into the top face of another. */
static void test_sat_rotated_corner (void **state)
{
  vec2 va[4], na[4], vb[4], nb[4];
  convex_piece a = make_box_piece (4, 1, va, na), b = make_box_piece (1, 1, vb, nb);
  manifold m;
  double half_diag = sqrt (0.5);
  (void) state;
  assert_int_equal (collide_polygons_sat (&a, place (0, 0, 0), &b, place (0.3, 0.5 + half_diag - 0.05, M_PI / 4),
                                          0.0, &m),
                    1);
  assert_near_abs (m.points[0].normal.x, 0.0, 1e-12);
  assert_near_abs (m.points[0].normal.y, 1.0, 1e-12);
  assert_near_abs (m.points[0].depth, 0.05, 1e-12);
  assert_near_abs (m.points[0].point.x, 0.3, 1e-12);
  assert_near_abs (m.points[0].point.y, 0.5 - 0.025, 1e-12);
  /* swapped: the normal flips, still from the first shape to the second */
  assert_int_equal (collide_polygons_sat (&b, place (0.3, 0.5 + half_diag - 0.05, M_PI / 4), &a, place (0, 0, 0),
                                          0.0, &m),
                    1);
  assert_near_abs (m.points[0].normal.y, -1.0, 1e-12);
}

static void test_sat_separated_touching_margin (void **state)
{
  vec2 va[4], na[4], vb[4], nb[4];
  convex_piece a = make_box_piece (1, 1, va, na), b = make_box_piece (1, 1, vb, nb);
  manifold m;
  (void) state;
  assert_int_equal (collide_polygons_sat (&a, place (0, 0, 0), &b, place (1.5, 0, 0.3), 0.01, &m), 0);
  /* apart by 0.005, within the 0.01 margin: a contact with negative depth */
  assert_int_equal (collide_polygons_sat (&a, place (0, 0, 0), &b, place (1.005, 0, 0), 0.01, &m), 2);
  assert_near_abs (m.points[0].depth, -0.005, 1e-12);
  assert_int_equal (collide_polygons_sat (&a, place (0, 0, 0), &b, place (1.02, 0, 0), 0.01, &m), 0);
}

/* A convex regular n-gon of circumradius r turned by phase. */
static convex_piece make_ngon_piece (int n, double r, double phase, vec2 *v, vec2 *nrm)
{
  convex_piece p;
  int i;
  memset (&p, 0, sizeof p);
  for (i = 0; i < n; ++i)
    v[i] = v2 (r * cos (phase + 2 * M_PI * i / n), r * sin (phase + 2 * M_PI * i / n));
  for (i = 0; i < n; ++i)
    nrm[i] = v2_normalize (v2_neg (v2_perp (v2_sub (v[(i + 1) % n], v[i]))));
  p.count = n, p.vertices = v, p.normals = nrm, p.center = v2 (0, 0), p.bound_radius = r;
  return p;
}

/* A uniform double in [0, 1) from a 64-bit LCG. */
static double uniform (uint64_t *seed)
{
  *seed = *seed * 6364136223846793005ull + 1442695040888963407ull;
  return (double) (*seed >> 11) * 0x1p-53;
}

/* A lower bound on the distance of two disjoint convex polygons, from
 * their supports alone: the largest gap between their projections over
 * DIRECTIONS evenly spread directions (the distance is the largest over
 * all directions). Turning a direction by e moves each projection by at
 * most e times the point's distance from a's centre, so the bound is
 * within GAP_SLACK (ra + rb + their centres' distance) of the distance. */
#define DIRECTIONS 720
#define GAP_SLACK (M_PI / DIRECTIONS)
static double support_gap (const convex_piece *a, xform xa, const convex_piece *b, xform xb)
{
  double best = -INFINITY;
  int k, i;
  for (k = 0; k < DIRECTIONS; ++k)
    {
      vec2 u = v2 (cos (2 * M_PI * k / DIRECTIONS), sin (2 * M_PI * k / DIRECTIONS));
      double hi_a = -INFINITY, lo_b = INFINITY;
      for (i = 0; i < a->count; ++i)
        {
          double x = v2_dot (u, v2_sub (xform_apply (xa, a->vertices[i]), xa.p));
          hi_a = x > hi_a ? x : hi_a;
        }
      for (i = 0; i < b->count; ++i)
        {
          double y = v2_dot (u, v2_sub (xform_apply (xb, b->vertices[i]), xa.p));
          lo_b = y < lo_b ? y : lo_b;
        }
      best = lo_b - hi_a > best ? lo_b - hi_a : best;
    }
  return best;
}

/* Convex pieces that overlap or touch are a contact whatever the margin
 * (a speculative margin can be many times a small piece's size), and so
 * are pieces apart by less than the margin, corner towards corner too:
 * 20000 random pairs of regular 3- to 8-gons, sizes 0.1 to 2.1, placed to
 * overlap, touch or stand apart, margins 0 to twice the larger size. Every
 * pair whose separation (the largest over the edge normals) is at most 0
 * has a point; every pair apart by less than the margin by their supports
 * (support_gap, with its slack) has one; no point is nearer than the
 * pieces are; and every point is within the margin. */
static void test_sat_pieces_within_the_margin_are_always_a_contact (void **state)
{
  uint64_t seed = 0x2545f4914f6cdd1dull;
  int trial, overlapping = 0, near = 0;
  (void) state;
  for (trial = 0; trial < 20000; ++trial)
    {
      vec2 va[8], na[8], vb[8], nb[8], axis;
      int sa = 3 + (int) (uniform (&seed) * 6), sb = 3 + (int) (uniform (&seed) * 6), k;
      double ra = 0.1 + 2.0 * uniform (&seed), rb = 0.1 + 2.0 * uniform (&seed);
      convex_piece a = make_ngon_piece (sa, ra, uniform (&seed), va, na);
      convex_piece b = make_ngon_piece (sb, rb, uniform (&seed), vb, nb);
      double dir = 2 * M_PI * uniform (&seed), dist = (ra + rb) * (0.2 + 0.9 * uniform (&seed));
      double margin = 4.0 * (ra > rb ? ra : rb) * uniform (&seed) * uniform (&seed);
      xform xa = place (uniform (&seed), uniform (&seed), 2 * M_PI * uniform (&seed));
      xform xb = place (xa.p.x + dist * cos (dir), xa.p.y + dist * sin (dir), 2 * M_PI * uniform (&seed));
      manifold m;
      int n = collide_polygons_sat (&a, xa, &b, xb, margin, &m);
      double s = polygons_separation (&a, xa, &b, xb, &axis);
      for (k = 0; k < n; ++k)
        if (!(-m.points[k].depth <= margin))
          fail_msg ("trial %d: a point %.17g apart, beyond the margin %.17g", trial, -m.points[k].depth, margin);
      if (s > 0.0)
        {
          /* the separation is at most the distance: beyond the margin,
           * nothing to look at */
          double low = s <= margin ? support_gap (&a, xa, &b, xb) : s;
          double slack = GAP_SLACK * (ra + rb + dist);
          for (k = 0; k < n; ++k)
            if (-m.points[k].depth < low - 1e-9 * (ra + rb))
              fail_msg ("trial %d: a point %.17g apart, the pieces at least %.17g", trial, -m.points[k].depth, low);
          if (low + slack < margin)
            {
              near++;
              if (n == 0)
                fail_msg ("trial %d: %d-gon r %.17g and %d-gon r %.17g are less than %.17g apart, margin %.17g: "
                          "no contact", trial, sa, ra, sb, rb, low + slack, margin);
            }
          continue;
        }
      overlapping++;
      if (n == 0)
        fail_msg ("trial %d: %d-gon r %.17g and %d-gon r %.17g overlap by %.17g, margin %.17g: no contact", trial, sa,
                  ra, sb, rb, -s, margin);
    }
  print_message ("overlapping %d near %d\n", overlapping, near);
  assert_true (overlapping > 5000 && near > 2000);
}

/* Pieces that overlap corner to corner, by a hair or by a few per cent of
 * their size: a corner of b pushed into a near one of a corner of a, b
 * turned at random about its own corner. Clipping may leave no point there
 * (the incident edge lies beside the reference face), and the pieces had
 * no contact at all (an impact's second touch, a hair after the first, was
 * then taken up by nothing: tests/test_impacts.c). 20000 random pairs of
 * regular 3- to 8-gons, sizes 0.1 to 2.1, corners within 0 to 5% of a's
 * size of each other, b's corner 1e-12 to 1e-2 of its size inside a along
 * a random direction, margins up to 2% of the smaller size: every pair
 * whose separation is at most 0 has a point, and no point is deeper than
 * the pieces' sizes. */
static void test_sat_corners_pushed_into_corners_are_a_contact (void **state)
{
  uint64_t seed = 0x636f726e657273ull;
  int trial, overlapping = 0;
  (void) state;
  for (trial = 0; trial < 20000; ++trial)
    {
      vec2 va[8], na[8], vb[8], nb[8], axis, corner_a, corner_b, d;
      int sa = 3 + (int) (uniform (&seed) * 6), sb = 3 + (int) (uniform (&seed) * 6), ia, ib, k;
      double ra = 0.1 + 2.0 * uniform (&seed), rb = 0.1 + 2.0 * uniform (&seed);
      convex_piece a = make_ngon_piece (sa, ra, uniform (&seed), va, na);
      convex_piece b = make_ngon_piece (sb, rb, uniform (&seed), vb, nb);
      xform xa = place (uniform (&seed), uniform (&seed), 2 * M_PI * uniform (&seed)), xb;
      double out = 2 * M_PI * uniform (&seed), slide = 0.05 * ra * uniform (&seed);
      double push = rb * pow (10.0, -12.0 + 10.0 * uniform (&seed)), s;
      manifold m;
      int n;
      ia = (int) (uniform (&seed) * sa), ib = (int) (uniform (&seed) * sb);
      /* a's corner, moved along a random direction by up to 5% of a */
      corner_a = v2_mad (xform_apply (xa, a.vertices[ia]), slide, v2 (cos (out), sin (out)));
      /* b turned so that its corner ib points back at a's centre, give or
       * take an eighth of a turn, then placed with that corner
       * `push` inside corner_a along the direction to a's centre */
      d = v2_normalize (v2_sub (xa.p, corner_a));
      xb.q = rot2_from_angle (atan2 (d.y, d.x) - atan2 (b.vertices[ib].y, b.vertices[ib].x)
                              + 0.5 * M_PI * (uniform (&seed) - 0.5));
      corner_b = v2_mad (corner_a, push, d);
      xb.p = v2_sub (corner_b, rot2_apply (xb.q, b.vertices[ib]));
      /* a margin of up to 2% of the smaller piece, as a slop (it sets how
       * much better the other piece's face must be to be taken) */
      n = collide_polygons_sat (&a, xa, &b, xb, 0.02 * (ra < rb ? ra : rb) * uniform (&seed), &m);
      s = polygons_separation (&a, xa, &b, xb, &axis);
      if (!(s <= 0.0))
        continue;
      overlapping++;
      if (n == 0)
        fail_msg ("trial %d: %d-gon r %.17g and %d-gon r %.17g overlap by %.17g corner to corner: no contact", trial,
                  sa, ra, sb, rb, -s);
      for (k = 0; k < n; ++k)
        if (!(m.points[k].depth <= 2.0 * (ra + rb)))
          fail_msg ("trial %d: a point %.17g deep", trial, m.points[k].depth);
    }
  print_message ("overlapping %d\n", overlapping);
  assert_true (overlapping > 5000);
}

/* A convex polygon of n corners at random angles on a circle of radius r
 * (counter-clockwise), its normals, vertex average and bounding radius as
 * shape.c sets them; a sliver when `thin` squeezes it across. */
static convex_piece make_random_piece (int n, double r, double thin, uint64_t *seed, vec2 *v, vec2 *nrm)
{
  convex_piece p;
  double angle[32], t;
  vec2 c = v2 (0, 0);
  int i, j;
  memset (&p, 0, sizeof p);
  for (i = 0; i < n; ++i)
    angle[i] = 2 * M_PI * (i + 0.9 * uniform (seed)) / n;
  for (i = 1; i < n; ++i) /* already ascending; kept so by construction */
    for (j = i; j > 0 && angle[j - 1] > angle[j]; --j)
      t = angle[j], angle[j] = angle[j - 1], angle[j - 1] = t;
  for (i = 0; i < n; ++i)
    v[i] = v2 (r * cos (angle[i]), thin * r * sin (angle[i]));
  for (i = 0; i < n; ++i)
    {
      vec2 e = v2_sub (v[(i + 1) % n], v[i]);
      nrm[i] = v2_normalize (v2 (e.y, -e.x));
      c = v2_add (c, v[i]);
    }
  p.count = n, p.vertices = v, p.normals = nrm, p.center = v2_scale (c, 1.0 / n);
  for (i = 0; i < n; ++i)
    if (v2_len (v2_sub (v[i], p.center)) > p.bound_radius)
      p.bound_radius = v2_len (v2_sub (v[i], p.center));
  return p;
}

/* The SAT test's pruned search for the most separating edge gives what
 * searching every edge gives, to the bit: the separation, the edge (the
 * first to reach it), and, within the margin, the outer edge and its
 * separation. 60000 random pairs of 3- to 20-gons (regular and irregular,
 * slivers among them; up to 16 edges pruned, more searched plainly), sizes
 * 1e-4 to 10, far from the origin or near it, placed to overlap, touch or
 * stand apart, and boxes aligned face to face, where edges tie exactly;
 * margins 0, random and infinite; and a pair placed at NaN. */
static void test_sat_pruned_search_equals_the_plain_one (void **state)
{
  uint64_t seed = 0x9e3779b97f4a7c15ull;
  int trial, within = 0, ties = 0;
  (void) state;
  for (trial = 0; trial < 60000; ++trial)
    {
      vec2 va[32], na[32], vb[32], nb[32];
      int kind = trial % 4, side;
      int sa = 3 + (int) (uniform (&seed) * 18), sb = 3 + (int) (uniform (&seed) * 18);
      double scale = pow (10.0, -4.0 + 5.0 * uniform (&seed));
      double ra = scale * (0.2 + uniform (&seed)), rb = scale * (0.2 + uniform (&seed));
      double far = trial % 3 == 0 ? 1e6 * uniform (&seed) : 0.0;
      double dir = 2 * M_PI * uniform (&seed), dist = (ra + rb) * (1.3 * uniform (&seed));
      double margins[3];
      convex_piece a, b;
      xform xa, xb;
      int m;
      if (kind == 0)
        {
          a = make_ngon_piece (sa, ra, uniform (&seed), va, na);
          b = make_ngon_piece (sb, rb, uniform (&seed), vb, nb);
        }
      else if (kind == 3)
        {
          /* boxes of one size turned alike: equal separations along
           * two faces (b diagonally off a) or all four (b on a) */
          a = make_box_piece (2 * ra, 2 * ra, va, na);
          b = make_box_piece (2 * ra, 2 * ra, vb, nb);
          dist = 2 * ra * (0.9 + 0.1 * (int) (uniform (&seed) * 3));
        }
      else
        {
          a = make_random_piece (sa, ra, kind == 2 ? 0.05 : 1.0, &seed, va, na);
          b = make_random_piece (sb, rb, 1.0, &seed, vb, nb);
        }
      if (kind == 3)
        {
          /* quarter turns, exactly; b beside, above or diagonally off a,
           * or on it */
          static const double quarter[4][2] = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } };
          int turn = (int) (uniform (&seed) * 4);
          int dx = (int) (uniform (&seed) * 3) - 1, dy = (int) (uniform (&seed) * 3) - 1;
          xa.p = v2 (far, -far);
          xa.q.c = quarter[turn][0], xa.q.s = quarter[turn][1];
          xb.p = v2 (far + dx * dist, -far + dy * dist);
          xb.q = xa.q;
        }
      else
        {
          xa = place (far + scale * uniform (&seed), -far, 2 * M_PI * uniform (&seed));
          xb = place (xa.p.x + dist * cos (dir), xa.p.y + dist * sin (dir), 2 * M_PI * uniform (&seed));
        }
      if (trial == 7)
        xb.p.x = NAN;
      margins[0] = 0.0;
      margins[1] = scale * uniform (&seed);
      margins[2] = INFINITY;
      for (side = 0; side < 2; ++side)
        for (m = 0; m < 3; ++m)
          {
            const convex_piece *p = side ? &b : &a, *q = side ? &a : &b;
            xform xp = side ? xb : xa, xq = side ? xa : xb;
            int32_t e0, e1, o0, o1, i, count = 0;
            double u0, u1, s0 = sat_max_separation_all (p, xp, q, xq, margins[m], &e0, &u0, &o0);
            double s1 = sat_max_separation (p, xp, q, xq, margins[m], &e1, &u1, &o1);
            if (s0 > margins[m] || s1 > margins[m])
              {
                if (!(s0 > margins[m] && s1 > margins[m]))
                  fail_msg ("trial %d side %d: past margin %.17g: plain %.17g, pruned %.17g", trial, side,
                            margins[m], s0, s1);
                continue;
              }
            if (memcmp (&s0, &s1, sizeof s0) != 0 || e0 != e1 || memcmp (&u0, &u1, sizeof u0) != 0 || o0 != o1)
              fail_msg ("trial %d side %d margin %.17g: plain %.17g edge %d outer %.17g %d, pruned %.17g edge %d "
                        "outer %.17g %d",
                        trial, side, margins[m], s0, e0, u0, o0, s1, e1, u1, o1);
            within++;
            /* edges that reach the largest exactly, beyond the first */
            for (i = 0; i < p->count && m == 2; ++i)
              {
                vec2 n = rot2_apply (xform_relative (xq, xp).q, p->normals[i]);
                double si = INFINITY;
                int32_t j;
                for (j = 0; j < q->count; ++j)
                  si = v2_dot (n, q->vertices[j]) < si ? v2_dot (n, q->vertices[j]) : si;
                count += si - v2_dot (n, xform_apply (xform_relative (xq, xp), p->vertices[i])) == s0;
              }
            ties += count > 1;
          }
    }
  print_message ("within the margin %d, ties %d\n", within, ties);
  assert_true (within > 150000 && ties > 1000);
}

/* A triangle with a corner on its own origin, pointing along (sx, sy). */
static convex_piece make_tip_piece (double sx, double sy, vec2 *v, vec2 *n)
{
  convex_piece p;
  int i;
  memset (&p, 0, sizeof p);
  v[0] = v2 (0, 0), v[1] = v2 (-sx, -0.3 * sy), v[2] = v2 (-0.3 * sx, -sy);
  if (sx * sy < 0) /* counter-clockwise */
    {
      vec2 t = v[1];
      v[1] = v[2], v[2] = t;
    }
  for (i = 0; i < 3; ++i)
    {
      vec2 e = v2_sub (v[(i + 1) % 3], v[i]);
      n[i] = v2_normalize (v2 (e.y, -e.x));
    }
  p.count = 3, p.vertices = v, p.normals = n;
  p.center = v2 (-0.4333 * sx, -0.4333 * sy), p.bound_radius = 1.0;
  return p;
}

/* Corners a hair apart, near the origin: the squared distance underflows
 * (below 1e-154 it is subnormal, or 0), yet the normal is a unit vector.
 * Two triangles tip to tip, the second's tip (d, d/2) from the first's, d
 * from 1e-150 to 1e-300: neither face gives a point, the corners meet
 * (corner_contact). */
static void test_sat_corner_a_hair_away_has_unit_normal (void **state)
{
  static const double gaps[] = { 1e-150, 1e-155, 1e-158, 1e-160, 1e-162, 1e-200, 1e-300 };
  vec2 va[3], na[3], vb[3], nb[3];
  convex_piece a = make_tip_piece (1, 1, va, na), b = make_tip_piece (-1, -1, vb, nb);
  size_t k;
  int i;
  (void) state;
  for (k = 0; k < sizeof gaps / sizeof gaps[0]; ++k)
    {
      manifold m;
      int n = collide_polygons_sat (&a, place (0, 0, 0), &b, place (gaps[k], gaps[k] / 2, 0), 0.1, &m);
      if (n != 1)
        fail_msg ("gap %g: %d points, not one", gaps[k], n);
      for (i = 0; i < n; ++i)
        {
          double len = hypot (m.points[i].normal.x, m.points[i].normal.y);
          if (!(fabs (len - 1.0) <= 1e-15))
            fail_msg ("gap %g: normal (%.17g, %.17g) has length %.17g", gaps[k], m.points[i].normal.x,
                      m.points[i].normal.y, len);
        }
    }
}

/* Two unit squares corner to corner, B's corner 1e-16 m to the right of
 * A's and 3e-16 m above it (near the rounding of coordinates of 0.5):
 * neither face gives a point, the corners meet (corner_contact), and the
 * direction between them, (1, 3) / sqrt 10, is rounding, not geometry. The
 * normal is the axis that separates the squares most, A's top face's
 * (0, 1). Shifted along the diagonal by up to 1e6 m, where the rounding
 * is coarser than the offset, the same. */
static void test_sat_corners_a_rounding_apart_take_the_separating_axis (void **state)
{
  static const double shifts[] = { 0.0, 1.0, 1e3, 1e6 };
  vec2 va[4], na[4], vb[4], nb[4];
  convex_piece a = make_box_piece (1, 1, va, na), b = make_box_piece (1, 1, vb, nb);
  size_t k;
  (void) state;
  for (k = 0; k < sizeof shifts / sizeof shifts[0]; ++k)
    {
      double s = shifts[k], dx = 1e-16 * (1.0 + s), dy = 3e-16 * (1.0 + s);
      manifold m;
      int n = collide_polygons_sat (&a, place (s, s, 0), &b, place (s + 1.0 + dx, s + 1.0 + dy, 0), 0.1, &m);
      if (n != 1 || !(fabs (m.points[0].normal.x) <= 1e-12 && fabs (m.points[0].normal.y - 1.0) <= 1e-12))
        fail_msg ("shift %g: %d points, normal (%.17g, %.17g), not (0, 1)", s, n, n ? m.points[0].normal.x : 0.0,
                  n ? m.points[0].normal.y : 0.0);
    }
}

/* A body deep inside another still gets a unit normal. */
static void test_sat_deep_inside_has_unit_normal (void **state)
{
  vec2 va[4], na[4], vb[4], nb[4];
  convex_piece a = make_box_piece (10, 10, va, na), b = make_box_piece (1, 1, vb, nb);
  manifold m;
  int i;
  (void) state;
  assert_true (collide_polygons_sat (&a, place (0, 0, 0), &b, place (0, 0, 0.2), 0.0, &m) > 0);
  for (i = 0; i < m.count; ++i)
    {
      assert_near_abs (v2_len (m.points[i].normal), 1.0, 1e-12);
      assert_true (m.points[i].depth > 4.0);
    }
}

static void test_circles (void **state)
{
  manifold m;
  vec2 va[4], na[4];
  convex_piece box = make_box_piece (2, 2, va, na);
  (void) state;
  assert_int_equal (collide_circles (v2 (0, 0), 1, v2 (1.5, 0), 1, 0, &m), 1);
  assert_near_abs (m.points[0].normal.x, 1.0, 1e-15);
  assert_near_abs (m.points[0].depth, 0.5, 1e-15);
  assert_near_abs (m.points[0].point.x, 0.75, 1e-15);
  assert_int_equal (collide_circles (v2 (0, 0), 1, v2 (2.5, 0), 1, 0, &m), 0);
  /* coincident centres: still a unit normal */
  assert_int_equal (collide_circles (v2 (3, 3), 1, v2 (3, 3), 2, 0, &m), 1);
  assert_near_abs (v2_len (m.points[0].normal), 1.0, 1e-15);
  /* circle against the box's face, and against its corner */
  assert_int_equal (collide_polygon_circle (&box, place (0, 0, 0), v2 (0.2, 1.4), 0.5, 0, &m), 1);
  assert_near_abs (m.points[0].normal.y, 1.0, 1e-15);
  assert_near_abs (m.points[0].depth, 0.1, 1e-12);
  assert_int_equal (collide_polygon_circle (&box, place (0, 0, 0), v2 (1.3, 1.4), 0.6, 0, &m), 1);
  assert_near_abs (m.points[0].normal.x, 0.6, 1e-12);
  assert_near_abs (m.points[0].normal.y, 0.8, 1e-12);
  assert_near_abs (m.points[0].depth, 0.1, 1e-12);
  assert_int_equal (collide_polygon_circle (&box, place (0, 0, 0), v2 (1.3, 1.4), 0.4, 0, &m), 0);
  /* centre inside the box: pushed out through the nearest face */
  assert_int_equal (collide_polygon_circle (&box, place (0, 0, 0), v2 (0.9, 0.1), 0.2, 0, &m), 1);
  assert_near_abs (m.points[0].normal.x, 1.0, 1e-15);
  assert_near_abs (m.points[0].depth, 0.3, 1e-12);
}

/* ---------------------------------------------------------- resolution */

typedef struct two_body {
  carom_world *w;
  carom_body_id a, b;
} two_body;

static carom_world *new_world (double restitution)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_world_def_init (&def, sizeof def);
  def.restitution = restitution;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  return w;
}

/* Step until no contact remains and the bodies move apart. */
static void run_collision (carom_world *w, int max_steps)
{
  int step, touched = 0;
  for (step = 0; step < max_steps; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 120), CAROM_OK);
      if (carom_world_contact_count (w) > 0)
        touched = 1;
      else if (touched)
        return;
    }
  assert_true (touched);
}

static void test_equal_masses_head_on_swap_velocities (void **state)
{
  carom_world *w = new_world (1.0);
  carom_body_def d;
  carom_body_id a, b;
  double va, vb, vy;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.x = -1.5, d.vx = 2.0;
  assert_status (carom_world_add_circle (w, &d, 0.5, &a), CAROM_OK);
  d.x = 1.5, d.vx = -1.0;
  assert_status (carom_world_add_circle (w, &d, 0.5, &b), CAROM_OK);
  run_collision (w, 1000);
  carom_body_get_velocity (w, a, &va, &vy);
  carom_body_get_velocity (w, b, &vb, NULL);
  assert_near_rel (va, -1.0, 1e-12);
  assert_near_rel (vb, 2.0, 1e-12);
  assert_near_abs (vy, 0.0, 1e-15);
  carom_world_destroy (w);
}

/* Off-centre hits between spinning polygons of different masses: momentum
 * to 1e-12 and, with e = 1, kinetic energy (rotation included) to 1e-9.
 * With continuous collision the impact is met at its time within the step,
 * never overlapping, and angular momentum about a fixed point is conserved
 * too; without, the bodies meet overlapping and the overlap is removed by
 * moving them (split impulses), which keeps energy and linear momentum but
 * moves the bodies' lever arms about that point. */
static void test_off_centre_elastic_conserves_energy_and_momentum (void **state)
{
  int trial;
  (void) state;
  for (trial = 0; trial < 24; ++trial)
    {
      carom_world *w = new_world (1.0);
      int continuous = trial < 12;
      carom_body_def d;
      carom_body_id a, b;
      double e0, e1, px0, py0, l0, px1, py1, l1;
      const double tri[] = {0, 0, 1.2, 0.1, 0.3, 0.9};
      carom_body_def_init (&d, sizeof d);
      assert_status (carom_world_set_continuous (w, continuous), CAROM_OK);
      d.x = -2.0, d.y = 0.08 * (trial % 12) - 0.45, d.vx = 3.0 + 0.1 * trial, d.vy = 0.05, d.spin = 0.7 - 0.1 * trial;
      d.angle = 0.37 * trial;
      assert_status (carom_world_add_box (w, &d, 1.0, 0.6, &a), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
      d.x = 1.0, d.y = 0.1, d.vx = -1.0, d.vy = -0.02 * trial, d.spin = -1.3, d.density = 2.5, d.angle = -0.21 * trial;
      if (trial % 2)
        assert_status (carom_world_add_polygon (w, &d, tri, 3, &b), CAROM_OK);
      else
        assert_status (carom_world_add_regular (w, &d, 5, 0.7, &b), CAROM_OK);
      e0 = world_kinetic_energy (w);
      world_momentum (w, &px0, &py0, &l0);
      run_collision (w, 2000);
      e1 = world_kinetic_energy (w);
      world_momentum (w, &px1, &py1, &l1);
      assert_near_rel (e1, e0, 1e-9);
      assert_near_abs (px1, px0, 1e-12 * (fabs (px0) + fabs (py0) + 1));
      assert_near_abs (py1, py0, 1e-12 * (fabs (px0) + fabs (py0) + 1));
      if (continuous)
        assert_near_abs (l1, l0, 1e-12 * (fabs (l0) + 1));
      carom_world_destroy (w);
    }
}

/* With e = 0 the contact points stop approaching: zero relative normal
 * velocity right after the impact (measured on the contact normal). */
static void test_inelastic_relative_normal_velocity_is_zero (void **state)
{
  carom_world *w = new_world (0.0);
  carom_body_def d;
  carom_body_id a, b;
  double va, vb, e0, e1;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.x = -1.0, d.vx = 4.0;
  assert_status (carom_world_add_box (w, &d, 1, 1, &a), CAROM_OK);
  d.x = 1.0, d.vx = 0.0, d.density = 3.0;
  assert_status (carom_world_add_box (w, &d, 1, 1, &b), CAROM_OK);
  e0 = world_kinetic_energy (w);
  while (carom_world_contact_count (w) == 0)
    carom_world_update (w, 1.0 / 120);
  /* the first contact was speculative (the gap closes within the step); the
   * next step has them touching */
  carom_world_update (w, 1.0 / 120);
  carom_body_get_velocity (w, a, &va, NULL);
  carom_body_get_velocity (w, b, &vb, NULL);
  assert_near_rel (va, vb, 1e-12);
  assert_near_rel (va, 4.0 / 4.0, 1e-12); /* m v / (m + 3m) */
  e1 = world_kinetic_energy (w);
  assert_true (e1 < e0);
  carom_world_destroy (w);
}

/* Partial restitution: the separation speed is e times the approach speed. */
static void test_restitution_scales_separation_speed (void **state)
{
  carom_world *w = new_world (0.5);
  carom_body_def d;
  carom_body_id a, b;
  double va, vb;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.x = -1.0, d.vx = 3.0;
  assert_status (carom_world_add_circle (w, &d, 0.4, &a), CAROM_OK);
  d.x = 1.0, d.vx = -1.0;
  assert_status (carom_world_add_circle (w, &d, 0.4, &b), CAROM_OK);
  run_collision (w, 1000);
  carom_body_get_velocity (w, a, &va, NULL);
  carom_body_get_velocity (w, b, &vb, NULL);
  assert_near_rel (vb - va, 0.5 * 4.0, 1e-12);
  assert_near_rel (va + vb, 2.0, 1e-12);
  carom_world_destroy (w);
}

/* Unequal materials, restitution (docs/physics.md: the larger e of the
 * two): two circles with their own e, 0.3 and 0.9, in either order and with
 * a world default between them, separate at 0.9 times their approach. */
static void test_restitution_mixing_takes_the_larger (void **state)
{
  int order;
  (void) state;
  for (order = 0; order < 2; ++order)
    {
      carom_world *w = new_world (0.5);
      carom_body_def d;
      carom_body_id a, b;
      double va, vb;
      carom_body_def_init (&d, sizeof d);
      d.x = -1.0, d.vx = 3.0, d.restitution = order ? 0.9 : 0.3;
      assert_status (carom_world_add_circle (w, &d, 0.4, &a), CAROM_OK);
      d.x = 1.0, d.vx = -1.0, d.restitution = order ? 0.3 : 0.9;
      assert_status (carom_world_add_circle (w, &d, 0.4, &b), CAROM_OK);
      run_collision (w, 1000);
      carom_body_get_velocity (w, a, &va, NULL);
      carom_body_get_velocity (w, b, &vb, NULL);
      assert_near_rel (vb - va, 0.9 * 4.0, 1e-12);
      carom_world_destroy (w);
    }
}

/* Unequal materials, friction (the geometric mean of the two mu): a box
 * sliding on a static floor, mu 0.2 on the box and 0.8 on the floor, in
 * either order, decelerates at sqrt(0.2 0.8) g = 0.4 g (the larger would
 * give 0.8 g, the smaller 0.2 g, the arithmetic mean 0.5 g). */
static void test_friction_mixing_is_the_geometric_mean (void **state)
{
  int order;
  (void) state;
  for (order = 0; order < 2; ++order)
    {
      carom_world *w = NULL;
      carom_world_def def;
      carom_body_def d;
      carom_body_id box;
      double v0, v1;
      int step;
      carom_world_def_init (&def, sizeof def);
      def.gravity_y = -10.0;
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
      d.type = CAROM_STATIC, d.y = -0.5, d.friction = order ? 0.2 : 0.8;
      assert_status (carom_world_add_box (w, &d, 200, 1, NULL), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
      d.y = 0.5, d.friction = order ? 0.8 : 0.2;
      assert_status (carom_world_add_box (w, &d, 1, 1, &box), CAROM_OK);
      for (step = 0; step < 30; ++step) /* settle */
        assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      assert_status (carom_body_set_velocity (w, box, 5.0, 0.0), CAROM_OK);
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      carom_body_get_velocity (w, box, &v0, NULL);
      for (step = 0; step < 30; ++step)
        assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      carom_body_get_velocity (w, box, &v1, NULL);
      assert_near_rel ((v0 - v1) / (30.0 / 60.0), 0.4 * 10.0, 1e-3);
      carom_world_destroy (w);
    }
}

/* A ball rolling on a static floor (friction 0.6, spin -v/r, at 1, 5 and
 * 20 m/s), and one spinning in place that friction sets rolling, stay on
 * the floor: for 2 s their height is the radius less at most the slop and
 * their vertical speed is 0 to 1e-9 of their speed; the rolling ones keep
 * their speed to 1e-9. */
static void test_rolling_ball_stays_on_the_floor (void **state)
{
  static const double speeds[] = { 1.0, 5.0, 20.0, 0.0 };
  const double r = 0.1;
  int i, step;
  (void) state;
  for (i = 0; i < 4; ++i)
    {
      carom_world *w = NULL;
      carom_world_def def;
      carom_body_def d;
      carom_body_id ball;
      double v = speeds[i], scale = v > 0.0 ? v : 5.0 * r;
      carom_world_def_init (&def, sizeof def);
      def.gravity_y = -9.81;
      def.friction = 0.6;
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 200.0, 1.0);
      carom_body_def_init (&d, sizeof d);
      d.x = -50.0, d.y = r, d.vx = v, d.spin = v > 0.0 ? -v / r : 50.0;
      assert_status (carom_world_add_circle (w, &d, r, &ball), CAROM_OK);
      for (step = 0; step < 120; ++step)
        {
          double y, vx, vy;
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          carom_body_get_position (w, ball, NULL, &y);
          carom_body_get_velocity (w, ball, &vx, &vy);
          if (!(y >= r - 0.01 * r - 1e-12 && y <= r + 1e-12) || !(fabs (vy) <= 1e-9 * scale)
              || (v > 0.0 && !(fabs (vx - v) <= 1e-9 * v)))
            fail_msg ("speed %g, step %d: height %.12g (radius %g), velocity (%.12g, %.3g)", v, step, y, r, vx, vy);
        }
      carom_world_destroy (w);
    }
}

/* A box dropped flat on a static floor comes to rest on it, without
 * jitter, sinking no more than the slop. */
static void test_box_rests_on_floor (void **state)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_body_id box;
  double y, vy, angle, y_prev = 0;
  int step;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.y = -0.5;
  assert_status (carom_world_add_box (w, &d, 20, 1, NULL), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.y = 1.0;
  assert_status (carom_world_add_box (w, &d, 1, 1, &box), CAROM_OK);
  for (step = 0; step < 600; ++step)
    {
      carom_world_update (w, 1.0 / 60);
      carom_body_get_position (w, box, NULL, &y);
      if (step > 300)
        assert_near_abs (y, y_prev, 1e-9); /* at rest: no jitter */
      y_prev = y;
    }
  carom_body_get_velocity (w, box, NULL, &vy);
  carom_body_get_angle (w, box, &angle);
  assert_true (y > 0.5 - 0.01 * 0.5 - 1e-9 && y <= 0.5 + 1e-9);
  assert_near_abs (angle, 0.0, 1e-12);
  assert_int_equal (carom_world_contact_count (w), 2);
  carom_world_destroy (w);
}

/* A box dropped into the notch of a static U shape lands inside the notch:
 * the concave outline counts, not its convex hull (which would hold the box
 * up at the top of the arms). */
static void test_u_shape_catches_box_in_notch (void **state)
{
  const double u[] = {0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3};
  int mode;
  (void) state;
  for (mode = 0; mode < 2; ++mode)
    {
      carom_world *w = NULL;
      carom_world_def def;
      carom_body_def d;
      carom_body_id u_id, box;
      double ux, uy, x, y;
      int step;
      carom_world_def_init (&def, sizeof def);
      def.gravity_y = -10;
      def.friction = 0.3;
      def.narrow_phase = mode ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
      d.type = CAROM_STATIC;
      assert_status (carom_world_add_polygon (w, &d, u, 8, &u_id), CAROM_OK);
      carom_body_get_position (w, u_id, &ux, &uy); /* the U's centroid, (0, 0) */
      carom_body_def_init (&d, sizeof d);
      /* the notch spans x in [1, 2] and y in [1, 3] of the input frame,
       * whose centroid is (1.5, 9.5 / 7) */
      d.x = 0.0, d.y = 3.0;
      assert_status (carom_world_add_box (w, &d, 0.6, 0.6, &box), CAROM_OK);
      for (step = 0; step < 180; ++step)
        assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      carom_body_get_position (w, box, &x, &y);
      /* resting on the notch floor: y = 1 + 0.3 in the input frame */
      assert_near_abs (x, 0.0, 1e-6);
      assert_near_abs (y, 1.3 - 9.5 / 7.0, 0.01);
      carom_world_destroy (w);
    }
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_sat_face_contact_has_two_clipped_points),
    cmocka_unit_test (test_sat_rotated_corner),
    cmocka_unit_test (test_sat_corner_a_hair_away_has_unit_normal),
    cmocka_unit_test (test_sat_corners_a_rounding_apart_take_the_separating_axis),
    cmocka_unit_test (test_sat_separated_touching_margin),
    cmocka_unit_test (test_sat_pieces_within_the_margin_are_always_a_contact),
    cmocka_unit_test (test_sat_corners_pushed_into_corners_are_a_contact),
    cmocka_unit_test (test_sat_deep_inside_has_unit_normal),
    cmocka_unit_test (test_sat_pruned_search_equals_the_plain_one),
    cmocka_unit_test (test_circles),
    cmocka_unit_test (test_equal_masses_head_on_swap_velocities),
    cmocka_unit_test (test_off_centre_elastic_conserves_energy_and_momentum),
    cmocka_unit_test (test_inelastic_relative_normal_velocity_is_zero),
    cmocka_unit_test (test_restitution_scales_separation_speed),
    cmocka_unit_test (test_restitution_mixing_takes_the_larger),
    cmocka_unit_test (test_friction_mixing_is_the_geometric_mean),
    cmocka_unit_test (test_rolling_ball_stays_on_the_floor),
    cmocka_unit_test (test_box_rests_on_floor),
    cmocka_unit_test (test_u_shape_catches_box_in_notch),
  };
  return cmocka_run_group_tests_name ("collision", tests, NULL, NULL);
}
