/* The vertex-edge narrow phase (thesis 3.2.2): fig. 3.8 vertex into edge,
 * fig. 3.9/3.10 parallel edges, fig. 3.11 vertex on vertex, margins, concave
 * outlines, containment, and the symmetries the solver relies on (swapping A
 * and B flips normals; moving both rigidly moves the contacts with them). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <math.h>

#include "collide.h"

#define TOL 1e-12
#define PARALLEL_BIT (1u << 30)
#define OWNER_B_BIT (1u << 31)

#define VE_NEAR(a, b)                                                         \
  do {                                                                        \
    double a_ = (a), b_ = (b);                                                \
    if (!(fabs (a_ - b_) <= TOL))                                             \
      fail_msg ("%s = %.17g, %s = %.17g, tolerance %g", #a, a_, #b, b_, TOL); \
  } while (0)

/* ------------------------------------------------------------ helpers */

static xform xf (double angle, double x, double y)
{
  xform t;
  t.q = rot2_from_angle (angle);
  t.p = v2 (x, y);
  return t;
}

/* t after x: rotate and move a placement x by the rigid motion t. */
static xform xf_then (xform t, xform x)
{
  xform r;
  r.q.c = t.q.c * x.q.c - t.q.s * x.q.s;
  r.q.s = t.q.s * x.q.c + t.q.c * x.q.s;
  r.p = xform_apply (t, x.p);
  return r;
}

/* Every point finite, every normal finite and unit to 1e-12, and the count
 * agrees with the manifold. */
static void check_sane (const manifold *m, int32_t ret)
{
  int32_t k;
  assert_int_equal (ret, m->count);
  assert_true (m->count >= 0 && m->count <= MANIFOLD_MAX_POINTS);
  for (k = 0; k < m->count; ++k)
    {
      const manifold_point *p = &m->points[k];
      assert_true (isfinite (p->point.x) && isfinite (p->point.y));
      assert_true (isfinite (p->normal.x) && isfinite (p->normal.y));
      assert_true (isfinite (p->depth));
      VE_NEAR (v2_len (p->normal), 1.0);
    }
}

static int32_t collide (const vec2 *va, int32_t na, xform xa, const vec2 *vb, int32_t nb, xform xb, double margin,
                        manifold *m)
{
  int32_t ret;
  m->count = -7; /* must be overwritten */
  ret = collide_polygons_vertex_edge (va, na, xa, vb, nb, xb, margin, m);
  check_sane (m, ret);
  return ret;
}

static void expect_point (const manifold_point *p, double px, double py, double nx, double ny, double depth)
{
  VE_NEAR (p->point.x, px);
  VE_NEAR (p->point.y, py);
  VE_NEAR (p->normal.x, nx);
  VE_NEAR (p->normal.y, ny);
  VE_NEAR (p->depth, depth);
}

static const manifold_point *by_feature (const manifold *m, uint32_t feature)
{
  int32_t k;
  for (k = 0; k < m->count; ++k)
    if (m->points[k].feature == feature)
      return &m->points[k];
  fail_msg ("no contact with feature 0x%08x", (unsigned) feature);
  return NULL;
}

static const manifold_point *by_position (const manifold *m, vec2 at)
{
  int32_t k;
  for (k = 0; k < m->count; ++k)
    if (v2_len (v2_sub (m->points[k].point, at)) <= 1e-9)
      return &m->points[k];
  fail_msg ("no contact at (%.17g, %.17g)", at.x, at.y);
  return NULL;
}

static uint32_t vertex_feature (int owner_b, uint32_t vertex, uint32_t edge)
{
  return (owner_b ? OWNER_B_BIT : 0u) | vertex << 15 | edge;
}

static uint32_t parallel_feature (uint32_t edge_a, uint32_t edge_b)
{
  return PARALLEL_BIT | edge_a << 15 | edge_b;
}

/* ------------------------------------------------------------ shapes */

/* Square of half-size 0.5 about its centre. */
static const vec2 square_half[] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
/* Unit square turned 45 degrees: corners on the axes at distance 1. */
static const vec2 diamond[] = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
/* Square of half-size 1. */
static const vec2 square_one[] = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};
/* A wide floor: x in [-2, 2], y in [-1, 0]; edge 2 is the top. */
static const vec2 floor_box[] = {{-2.0, -1.0}, {2.0, -1.0}, {2.0, 0.0}, {-2.0, 0.0}};
/* 2 x 1 box about its centre; edge 0 bottom, edge 2 top. */
static const vec2 plank[] = {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {-1.0, 0.5}};
/* U: notch x in [1, 2], y in [1, 3]; edge 4 (2,1) -> (1,1) is the notch floor. */
static const vec2 u_shape[] = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
/* Small box of half-size 0.3; edge 0 is the bottom. */
static const vec2 small_box[] = {{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}};
/* L: foot [0, 3] x [0, 1], leg [0, 1] x [0, 3]. */
static const vec2 l_shape[] = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
/* Big box of half-size 2. */
static const vec2 big_box[] = {{-2.0, -2.0}, {2.0, -2.0}, {2.0, 2.0}, {-2.0, 2.0}};

/* A pair placed in the world, with the margin to use. */
typedef struct scene {
  const vec2 *va;
  int32_t na;
  xform xa;
  const vec2 *vb;
  int32_t nb;
  xform xb;
  double margin;
} scene;

static int32_t run (const scene *s, manifold *m)
{
  return collide (s->va, s->na, s->xa, s->vb, s->nb, s->xb, s->margin, m);
}

/* fig. 3.8: the bottom corner of a square turned 45 degrees, at (0.3, -0.1),
 * 0.1 into the top of the floor. */
static scene scene_general (void)
{
  scene s = {square_half, 4, {{0.0, 0.0}, {1.0, 0.0}}, floor_box, 4, {{0.0, 0.0}, {1.0, 0.0}}, 0.0};
  s.xa = xf (CAROM_PI / 4.0, 0.3, sqrt (0.5) - 0.1);
  return s;
}

/* fig. 3.9/3.10: two planks face to face, B 1 to the right and overlapping
 * A's top by 0.1: A's top edge x in [-1, 1] at y = 0.5, B's bottom edge
 * x in [0, 2] at y = 0.4. */
static scene scene_parallel (void)
{
  scene s = {plank, 4, {{0.0, 0.0}, {1.0, 0.0}}, plank, 4, {{1.0, 0.9}, {1.0, 0.0}}, 0.0};
  return s;
}

/* fig. 3.11: the diamond's right corner (1, 0) inside B = [0.8, 2.8] x
 * [-0.1, 1.9], and B's corner (0.8, -0.1) inside the diamond. */
static scene scene_vertex_vertex (void)
{
  scene s = {diamond, 4, {{0.0, 0.0}, {1.0, 0.0}}, square_one, 4, {{1.8, 0.9}, {1.0, 0.0}}, 0.0};
  return s;
}

/* Two L shapes hooked: B is A turned half a turn, its leg 0.05 into A's foot
 * and its foot 0.05 onto A's leg. */
static scene scene_hooked (void)
{
  scene s = {l_shape, 6, {{0.0, 0.0}, {1.0, 0.0}}, l_shape, 6, {{0.0, 0.0}, {1.0, 0.0}}, 0.0};
  s.xb = xf (CAROM_PI, 2.5, 3.95);
  return s;
}

/* A box resting 0.05 into the floor of the U's notch. */
static scene scene_notch_floor (void)
{
  scene s = {u_shape, 8, {{0.0, 0.0}, {1.0, 0.0}}, small_box, 4, {{1.5, 1.25}, {1.0, 0.0}}, 0.01};
  return s;
}

/* ------------------------------------------------------------ tests */

static void test_general_vertex_edge (void **state)
{
  scene s = scene_general ();
  manifold m;
  (void) state;
  assert_int_equal (run (&s, &m), 1);
  /* A's vertex in B: minus the outward normal (0, 1) of B's top */
  expect_point (&m.points[0], 0.3, -0.1, 0.0, -1.0, 0.1);
  assert_int_equal (m.points[0].feature, vertex_feature (0, 0, 2));

  /* and a margin changes nothing for a penetrating vertex */
  s.margin = 0.05;
  assert_int_equal (run (&s, &m), 1);
  expect_point (&m.points[0], 0.3, -0.1, 0.0, -1.0, 0.1);
}

static void test_parallel_offset (void **state)
{
  scene s = scene_parallel ();
  manifold m;
  (void) state;
  /* A's corner (1, 0.5) is in B and B's corner (0, 0.4) is in A; both
   * find the same pair of parallel edges, which gives one contact at the
   * middle of the overlap x in [0, 1], halfway between the edges. */
  assert_int_equal (run (&s, &m), 1);
  expect_point (&m.points[0], 0.5, 0.45, 0.0, 1.0, 0.1);
  assert_int_equal (m.points[0].feature, parallel_feature (2, 0));
}

static void test_parallel_inside (void **state)
{
  /* fig. 3.9 proper: A's top edge wholly inside B, 0.1 past B's bottom;
   * each top vertex has one segment crossing and one parallel. */
  static const vec2 wide[] = {{-3.0, 0.0}, {3.0, 0.0}, {3.0, 2.0}, {-3.0, 2.0}};
  manifold m;
  (void) state;
  assert_int_equal (collide (plank, 4, xf (0.0, 0.2, -0.4), wide, 4, xf (0.0, 0.0, 0.0), 0.0, &m), 1);
  expect_point (&m.points[0], 0.2, 0.05, 0.0, 1.0, 0.1);
  assert_int_equal (m.points[0].feature, parallel_feature (2, 0));
}

static void test_vertex_on_vertex (void **state)
{
  scene s = scene_vertex_vertex ();
  manifold m, again;
  int32_t k;
  (void) state;
  assert_int_equal (run (&s, &m), 2);
  /* The diamond's corner (1, 0): its segments cross B's bottom (depth 0.1)
   * and B's left side (depth 0.2); the shallower one wins. */
  expect_point (&m.points[0], 1.0, 0.0, 0.0, 1.0, 0.1);
  assert_int_equal (m.points[0].feature, vertex_feature (0, 1, 0));
  /* B's corner (0.8, -0.1): crosses the diamond's lower right edge (depth
   * 0.1 / sqrt 2) and upper right edge (0.3 / sqrt 2); the normal is the
   * outward normal of A's lower right edge. */
  expect_point (&m.points[1], 0.8, -0.1, sqrt (0.5), -sqrt (0.5), 0.1 * sqrt (0.5));
  assert_int_equal (m.points[1].feature, vertex_feature (1, 0, 0));

  /* deterministic: the same bits again */
  assert_int_equal (run (&s, &again), 2);
  for (k = 0; k < 2; ++k)
    {
      assert_true (again.points[k].point.x == m.points[k].point.x);
      assert_true (again.points[k].point.y == m.points[k].point.y);
      assert_true (again.points[k].normal.x == m.points[k].normal.x);
      assert_true (again.points[k].normal.y == m.points[k].normal.y);
      assert_true (again.points[k].depth == m.points[k].depth);
      assert_int_equal (again.points[k].feature, m.points[k].feature);
    }
}

static void test_separated (void **state)
{
  scene s = scene_general ();
  manifold m;
  (void) state;
  s.xa = xf (CAROM_PI / 4.0, 0.3, 5.0);
  s.margin = 0.1;
  assert_int_equal (run (&s, &m), 0);
  assert_int_equal (m.count, 0);
  /* bounding boxes overlap, outlines do not */
  s.xa = xf (CAROM_PI / 4.0, 2.55, 0.6);
  assert_int_equal (run (&s, &m), 0);
}

static void test_margin_vertex (void **state)
{
  scene s = scene_general ();
  manifold m;
  (void) state;
  /* the corner 0.05 above the floor */
  s.xa = xf (CAROM_PI / 4.0, 0.3, sqrt (0.5) + 0.05);
  s.margin = 0.1;
  assert_int_equal (run (&s, &m), 1);
  expect_point (&m.points[0], 0.3, 0.05, 0.0, -1.0, -0.05);
  assert_int_equal (m.points[0].feature, vertex_feature (0, 0, 2));
  s.margin = 0.04;
  assert_int_equal (run (&s, &m), 0);
  s.margin = 0.0;
  assert_int_equal (run (&s, &m), 0);
  /* within margin of the line but projecting past the end of the edge */
  s.xa = xf (CAROM_PI / 4.0, 2.03, sqrt (0.5) + 0.05);
  s.margin = 0.1;
  assert_int_equal (run (&s, &m), 0);
}

static void test_margin_parallel (void **state)
{
  scene s = scene_parallel ();
  manifold m;
  (void) state;
  s.xb = xf (0.0, 1.0, 1.05); /* gap of 0.05 between the faces */
  s.margin = 0.1;
  assert_int_equal (run (&s, &m), 1);
  expect_point (&m.points[0], 0.5, 0.525, 0.0, 1.0, -0.05);
  assert_int_equal (m.points[0].feature, parallel_feature (2, 0));
  s.margin = 0.03;
  assert_int_equal (run (&s, &m), 0);
}

static void test_concave_notch (void **state)
{
  scene s = scene_notch_floor ();
  manifold m;
  (void) state;
  /* in the notch, clear of the walls and the floor: the convex hull of the
   * U would contain the box, the true outline does not */
  s.xb = xf (0.0, 1.5, 2.0);
  assert_int_equal (run (&s, &m), 0);
  /* resting 0.05 into the notch floor: one parallel contact, normal up
   * from the U (A) to the box (B) */
  s = scene_notch_floor ();
  assert_int_equal (run (&s, &m), 1);
  expect_point (&m.points[0], 1.5, 0.975, 0.0, 1.0, 0.05);
  assert_int_equal (m.points[0].feature, parallel_feature (4, 0));
  /* tilted, one corner into the floor: a vertex contact, still up */
  s.xb = xf (0.2, 1.5, 1.0 + 0.3 * (cos (0.2) + sin (0.2)) - 0.02);
  assert_int_equal (run (&s, &m), 1);
  VE_NEAR (m.points[0].normal.x, 0.0);
  VE_NEAR (m.points[0].normal.y, 1.0);
  VE_NEAR (m.points[0].depth, 0.02);
  VE_NEAR (m.points[0].point.y, 0.98);
  assert_int_equal (m.points[0].feature, vertex_feature (1, 0, 4));
}

static void test_concave_hooked (void **state)
{
  scene s = scene_hooked ();
  manifold m;
  (void) state;
  assert_int_equal (run (&s, &m), 2);
  /* B's leg bottom (edge 4) on A's foot top (edge 2), overlap x in [1.5, 2.5] */
  expect_point (by_feature (&m, parallel_feature (2, 4)), 2.0, 0.975, 0.0, 1.0, 0.05);
  /* A's leg top (edge 4) under B's foot bottom (edge 2), overlap x in [0, 1] */
  expect_point (by_feature (&m, parallel_feature (4, 2)), 0.5, 2.975, 0.0, 1.0, 0.05);
}

static void test_contained (void **state)
{
  /* a small turned box wholly inside a big one: no segment crosses, each
   * vertex falls back to the nearest side */
  manifold m;
  int32_t k, pass;
  (void) state;
  for (pass = 0; pass < 2; ++pass)
    {
      xform inner = xf (0.3, 0.1, 0.05), outer = xf (0.0, 0.0, 0.0);
      double sign = pass == 0 ? 1.0 : -1.0;
      if (pass == 0)
        assert_int_equal (collide (big_box, 4, outer, small_box, 4, inner, 0.0, &m), 4);
      else
        assert_int_equal (collide (small_box, 4, inner, big_box, 4, outer, 0.0, &m), 4);
      for (k = 0; k < 4; ++k)
        {
          const manifold_point *p = &m.points[k];
          vec2 v = p->point;
          double dx = 2.0 - fabs (v.x), dy = 2.0 - fabs (v.y);
          /* B inside A: outward normal of A's nearest side; reversed when
           * the small box is A */
          if (dx < dy)
            {
              VE_NEAR (p->normal.x, sign * (v.x > 0.0 ? 1.0 : -1.0));
              VE_NEAR (p->normal.y, 0.0);
              VE_NEAR (p->depth, dx);
            }
          else
            {
              VE_NEAR (p->normal.x, 0.0);
              VE_NEAR (p->normal.y, sign * (v.y > 0.0 ? 1.0 : -1.0));
              VE_NEAR (p->depth, dy);
            }
          assert_true (p->depth > 0.0);
        }
    }
}

static void test_keeps_deepest_four (void **state)
{
  /* a comb whose six teeth go 0.01 .. 0.06 into the floor: the four
   * deepest are kept, deepest first */
  static const double d[6] = {0.01, 0.06, 0.02, 0.05, 0.03, 0.04};
  static const vec2 deep_floor[] = {{-1.0, -1.0}, {6.0, -1.0}, {6.0, 0.0}, {-1.0, 0.0}};
  static const int32_t want_tooth[4] = {1, 3, 5, 4};
  vec2 comb[13];
  manifold m;
  int32_t k;
  (void) state;
  for (k = 0; k < 6; ++k)
    {
      comb[2 * k] = v2 ((double) k, -d[k]);
      if (k < 5)
        comb[2 * k + 1] = v2 (k + 0.5, 0.5);
    }
  comb[11] = v2 (5.0, 2.0);
  comb[12] = v2 (0.0, 2.0);
  assert_int_equal (collide (comb, 13, xf (0.0, 0.0, 0.0), deep_floor, 4, xf (0.0, 0.0, 0.0), 0.0, &m), 4);
  for (k = 0; k < 4; ++k)
    {
      int32_t t = want_tooth[k];
      expect_point (&m.points[k], (double) t, -d[t], 0.0, -1.0, d[t]);
      assert_int_equal (m.points[k].feature, vertex_feature (0, (uint32_t) (2 * t), 2));
    }
}

/* Swapping A and B gives the same points and depths with normals flipped. */
static void check_swap (const scene *s, int32_t want)
{
  scene t = {s->vb, s->nb, s->xb, s->va, s->na, s->xa, s->margin};
  manifold m, w;
  int32_t k;
  assert_int_equal (run (s, &m), want);
  assert_int_equal (run (&t, &w), want);
  for (k = 0; k < m.count; ++k)
    {
      const manifold_point *p = &m.points[k], *q = by_position (&w, p->point);
      VE_NEAR (q->point.x, p->point.x);
      VE_NEAR (q->point.y, p->point.y);
      VE_NEAR (q->normal.x, -p->normal.x);
      VE_NEAR (q->normal.y, -p->normal.y);
      VE_NEAR (q->depth, p->depth);
    }
}

static void test_swap_flips_normal (void **state)
{
  scene s;
  (void) state;
  s = scene_general ();
  check_swap (&s, 1);
  s = scene_parallel ();
  check_swap (&s, 1);
  s = scene_vertex_vertex ();
  check_swap (&s, 2);
  s = scene_hooked ();
  check_swap (&s, 2);
  s = scene_notch_floor ();
  check_swap (&s, 1);
  s = scene_parallel ();
  s.xb = xf (0.0, 1.0, 1.05);
  s.margin = 0.1;
  check_swap (&s, 1);
}

/* Moving both polygons by one rigid motion moves the contacts with them:
 * points transformed, normals rotated, depths and features unchanged. */
static void check_moved (const scene *s, int32_t want)
{
  xform t = xf (0.3, 100.0, -50.0);
  scene u = *s;
  manifold m, w;
  int32_t k;
  u.xa = xf_then (t, s->xa);
  u.xb = xf_then (t, s->xb);
  assert_int_equal (run (s, &m), want);
  assert_int_equal (run (&u, &w), want);
  for (k = 0; k < m.count; ++k)
    {
      const manifold_point *p = &m.points[k], *q = by_feature (&w, p->feature);
      vec2 at = xform_apply (t, p->point), n = rot2_apply (t.q, p->normal);
      VE_NEAR (q->point.x, at.x);
      VE_NEAR (q->point.y, at.y);
      VE_NEAR (q->normal.x, n.x);
      VE_NEAR (q->normal.y, n.y);
      VE_NEAR (q->depth, p->depth);
    }
}

static void test_rigid_motion (void **state)
{
  scene s;
  manifold m;
  (void) state;
  s = scene_general ();
  check_moved (&s, 1);
  s = scene_parallel ();
  check_moved (&s, 1);
  s = scene_vertex_vertex ();
  check_moved (&s, 2);
  s = scene_hooked ();
  check_moved (&s, 2);
  s = scene_notch_floor ();
  check_moved (&s, 1);

  /* spelled out for fig. 3.8: A at angle 0.3 + 45 degrees, both moved by
   * (100, -50) after turning 0.3 */
  s = scene_general ();
  s.xa = xf (0.3 + CAROM_PI / 4.0, 100.0 + cos (0.3) * 0.3 - sin (0.3) * (sqrt (0.5) - 0.1),
             -50.0 + sin (0.3) * 0.3 + cos (0.3) * (sqrt (0.5) - 0.1));
  s.xb = xf (0.3, 100.0, -50.0);
  assert_int_equal (run (&s, &m), 1);
  expect_point (&m.points[0], 100.0 + cos (0.3) * 0.3 + sin (0.3) * 0.1, -50.0 + sin (0.3) * 0.3 - cos (0.3) * 0.1,
                sin (0.3), -cos (0.3), 0.1);
  assert_int_equal (m.points[0].feature, vertex_feature (0, 0, 2));
}

static void test_bad_input (void **state)
{
  manifold m;
  xform id = xf (0.0, 0.0, 0.0);
  (void) state;
  assert_int_equal (collide (NULL, 4, id, square_one, 4, id, 0.0, &m), 0);
  assert_int_equal (collide (square_one, 4, id, NULL, 4, id, 0.0, &m), 0);
  assert_int_equal (collide (square_one, 2, id, square_one, 4, id, 0.0, &m), 0);
  assert_int_equal (collide (square_one, 4, id, square_one, 0, id, 0.0, &m), 0);
  assert_int_equal (collide_polygons_vertex_edge (square_one, 4, id, square_one, 4, id, 0.0, NULL), 0);
  /* a negative or NaN margin is no margin */
  assert_int_equal (collide (square_one, 4, id, square_one, 4, xf (0.0, 2.05, 0.5), -1.0, &m), 0);
  assert_int_equal (collide (square_one, 4, id, square_one, 4, xf (0.0, 2.05, 0.5), NAN, &m), 0);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_general_vertex_edge),
    cmocka_unit_test (test_parallel_offset),
    cmocka_unit_test (test_parallel_inside),
    cmocka_unit_test (test_vertex_on_vertex),
    cmocka_unit_test (test_separated),
    cmocka_unit_test (test_margin_vertex),
    cmocka_unit_test (test_margin_parallel),
    cmocka_unit_test (test_concave_notch),
    cmocka_unit_test (test_concave_hooked),
    cmocka_unit_test (test_contained),
    cmocka_unit_test (test_keeps_deepest_four),
    cmocka_unit_test (test_swap_flips_normal),
    cmocka_unit_test (test_rigid_motion),
    cmocka_unit_test (test_bad_input),
  };
  return cmocka_run_group_tests (tests, NULL, NULL);
}
