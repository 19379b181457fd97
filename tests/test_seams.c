/* Seams: static shapes that touch (floor tiles) form one surface. A body
 * sliding or rolling over the seams keeps its speed and does not hop (no
 * ghost collisions on the tiles' shared edges), with continuous collision
 * off and on; an edge only partly covered is still a surface; moving a
 * static body makes its seams again. */
#include "support.h"

#include "collide.h"

#include <math.h>
#include <stdio.h>

#define G 9.81
#define SIZE 0.1 /* the circle's radius, the box's half side */

enum { SLIDING_CIRCLE, SLIDING_BOX, ROLLING_CIRCLE };
static const char *const kind_name[] = { "sliding circle", "sliding box", "rolling circle" };

/* 40 touching tiles with their tops at y = 0 from x = 0, widths from
 * `widths` in turn; returns the floor's length. */
static double add_tiles (carom_world *w, const double *widths, int n_widths, carom_body_id *ids)
{
  double x = 0.0;
  int i;
  for (i = 0; i < 40; ++i)
    {
      double wd = widths[i % n_widths];
      carom_body_id id = add_box (w, CAROM_STATIC, x + 0.5 * wd, -0.5, 0.0, wd, 1.0);
      if (ids)
        ids[i] = id;
      x += wd;
    }
  return x;
}

static carom_body_id add_mover (carom_world *w, int kind, double v)
{
  carom_body_def d;
  carom_body_id id;
  carom_body_def_init (&d, sizeof d);
  d.x = 0.5, d.y = SIZE, d.vx = v;
  if (kind == SLIDING_BOX)
    assert_status (carom_world_add_box (w, &d, 2.0 * SIZE, 2.0 * SIZE, &id), CAROM_OK);
  else
    {
      d.spin = kind == ROLLING_CIRCLE ? -v / SIZE : 0.0;
      assert_status (carom_world_add_circle (w, &d, SIZE, &id), CAROM_OK);
    }
  return id;
}

/* Steps until the body passes x_end (or 20 s); its largest change of speed
 * from v0 (relative) and its largest rise above where it started. */
static void cross (carom_world *w, carom_body_id id, double v0, double x_end, double *speed_err, double *rise,
                   int *crossed)
{
  int step;
  *speed_err = *rise = 0.0;
  *crossed = 0;
  for (step = 0; step < 1200; ++step)
    {
      double x, y, vx, vy;
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      carom_body_get_position (w, id, &x, &y);
      carom_body_get_velocity (w, id, &vx, &vy);
      *speed_err = fmax (*speed_err, fabs (hypot (vx, vy) / v0 - 1.0));
      *rise = fmax (*rise, y - SIZE);
      if (x > x_end)
        {
          *crossed = 1;
          return;
        }
    }
}

/* A sliding circle, a sliding box (no friction) and a rolling circle
 * (friction 0.6), at 2, 5 and 8 m/s, over 40 tiles of equal and of
 * uneven widths, continuous collision off and on, with either narrow phase
 * for the box (SAT's pieces, or the vertex-edge method's whole outlines):
 * each crosses the floor with its speed within 1% and never more than 1 mm
 * above its start. */
static void test_bodies_cross_touching_tiles_smoothly (void **state)
{
  static const double even[] = { 1.0 }, uneven[] = { 0.7, 1.3, 0.45, 1.0, 0.93 }, speeds[] = { 2.0, 5.0, 8.0 };
  static const carom_narrow_phase narrow[] = { CAROM_NARROW_SAT, CAROM_NARROW_VERTEX_EDGE };
  double worst_v = 0.0, worst_rise = 0.0;
  int kind, cont, sv, layout, np;
  (void) state;
  for (np = 0; np < 2; ++np)
    for (kind = 0; kind < 3; ++kind)
      for (cont = 0; cont < 2; ++cont)
        for (sv = 0; sv < 3; ++sv)
          for (layout = 0; layout < 2; ++layout)
            {
              carom_world *w = NULL;
              carom_world_def def;
              carom_body_id id;
              double length, speed_err, rise;
              int crossed;
              carom_world_def_init (&def, sizeof def);
              def.gravity_y = -G;
              def.friction = kind == ROLLING_CIRCLE ? 0.6 : 0.0;
              def.narrow_phase = narrow[np];
              assert_status (carom_world_init (&w, &def), CAROM_OK);
              assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
              length = layout ? add_tiles (w, uneven, 5, NULL) : add_tiles (w, even, 1, NULL);
              id = add_mover (w, kind, speeds[sv]);
              cross (w, id, speeds[sv], length - 1.0, &speed_err, &rise, &crossed);
              if (!crossed || !(speed_err < 0.01) || !(rise < 1e-3))
                fail_msg ("%s at %g m/s, %s tiles, continuous %d, %s: %s, speed off by %.3g, rose %.3g m",
                          kind_name[kind], speeds[sv], layout ? "uneven" : "even", cont, np ? "vertex-edge" : "SAT",
                          crossed ? "crossed" : "did not cross", speed_err, rise);
              worst_v = fmax (worst_v, speed_err);
              worst_rise = fmax (worst_rise, rise);
              carom_world_destroy (w);
            }
  print_message ("over the seams: speed off by at most %.3g, rise at most %.3g m\n", worst_v, worst_rise);
}

/* An edge only partly covered is still a surface: a small static block on
 * a long static floor covers part of the floor's top; a circle rolling at
 * the block still hits its side (and goes no farther), and a ball dropped
 * on the floor beside it lands on the floor. */
static void test_partly_covered_edge_stays_a_surface (void **state)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_body_id ball, drop;
  double x, y;
  int step;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -G;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  add_box (w, CAROM_STATIC, 10.0, -0.5, 0.0, 20.0, 1.0);
  add_box (w, CAROM_STATIC, 5.25, 0.25, 0.0, 0.5, 0.5); /* its bottom lies on the floor's top */
  carom_body_def_init (&d, sizeof d);
  d.x = 2.0, d.y = SIZE, d.vx = 3.0;
  assert_status (carom_world_add_circle (w, &d, SIZE, &ball), CAROM_OK);
  d.x = 8.0, d.y = 1.0, d.vx = 0.0;
  assert_status (carom_world_add_circle (w, &d, SIZE, &drop), CAROM_OK);
  for (step = 0; step < 180; ++step)
    assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
  carom_body_get_position (w, ball, &x, NULL);
  assert_true (x < 5.0 - SIZE + 0.01);
  carom_body_get_position (w, drop, NULL, &y);
  assert_near_abs (y, SIZE, 0.015 * SIZE); /* resting within the slop, 1% of its size */
  carom_world_destroy (w);
}

/* Moving a static body makes its seams again: one of the tiles raised by
 * 2 cm is a step, and a sliding box is stopped or thrown by it; put back,
 * the floor is smooth again. With either narrow phase (the vertex-edge
 * method reads its outlines' seams from their pieces, seams_outline). */
static void test_moving_a_static_body_makes_its_seams_again (void **state)
{
  static const double even[] = { 1.0 };
  int round;
  (void) state;
  for (round = 0; round < 4; ++round)
    {
      carom_world *w = NULL;
      carom_world_def def;
      carom_body_id tiles[40], id;
      double speed_err, rise;
      int crossed;
      carom_world_def_init (&def, sizeof def);
      def.gravity_y = -G;
      def.narrow_phase = round < 2 ? CAROM_NARROW_SAT : CAROM_NARROW_VERTEX_EDGE;
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      add_tiles (w, even, 1, tiles);
      id = add_mover (w, SLIDING_BOX, 5.0);
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK); /* seams made for the flat floor */
      assert_status (carom_body_set_position (w, tiles[10], 10.5, -0.48), CAROM_OK);
      if (round % 2 == 1)
        assert_status (carom_body_set_position (w, tiles[10], 10.5, -0.5), CAROM_OK);
      cross (w, id, 5.0, 39.0, &speed_err, &rise, &crossed);
      if (round % 2 == 0)
        assert_true (!crossed || speed_err > 0.05 || rise > 1e-3);
      else
        assert_true (crossed && speed_err < 0.01 && rise < 1e-3);
      carom_world_destroy (w);
    }
}

/* A static polygon from world coordinates xy (n vertices). */
static void add_static_polygon (carom_world *w, const double *xy, int n)
{
  carom_body_def d;
  double area = 0.0, cx = 0.0, cy = 0.0;
  int i;
  for (i = 0; i < n; ++i)
    {
      int j = (i + 1) % n;
      double c = xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
      area += c;
      cx += (xy[2 * i] + xy[2 * j]) * c;
      cy += (xy[2 * i + 1] + xy[2 * j + 1]) * c;
    }
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.x = cx / (3.0 * area), d.y = cy / (3.0 * area);
  assert_status (carom_world_add_polygon (w, &d, xy, n, NULL), CAROM_OK);
}

/* The vertex-edge method reads the seams of any outline off its pieces
 * (seams_outline): a floor of 40 tiles 1 m wide, in turn a box, a box with
 * a vertex straight through in the middle of its top (convex, but its one
 * piece drops that vertex, so its edges are not the outline's; and that
 * vertex is no corner) and a box notched from below (concave: pieces), is
 * crossed by a box sliding at 5 m/s with its speed within 1% and no hop,
 * continuous collision off and on. */
static void test_vertex_edge_reads_seams_of_any_outline (void **state)
{
  int cont, i;
  (void) state;
  for (cont = 0; cont < 2; ++cont)
    {
      carom_world *w = NULL;
      carom_world_def def;
      carom_body_id id;
      double speed_err, rise;
      int crossed;
      carom_world_def_init (&def, sizeof def);
      def.gravity_y = -G;
      def.friction = 0.0;
      def.narrow_phase = CAROM_NARROW_VERTEX_EDGE;
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
      for (i = 0; i < 40; ++i)
        {
          double x = i;
          const double flat[] = { x, -1.0, x + 1.0, -1.0, x + 1.0, 0.0, x + 0.5, 0.0, x, 0.0 };
          const double notched[] = { x, -1.0, x + 0.4, -1.0, x + 0.5, -0.5, x + 0.6, -1.0, x + 1.0, -1.0, x + 1.0, 0.0,
                                     x, 0.0 };
          if (i % 3 == 0)
            add_box (w, CAROM_STATIC, x + 0.5, -0.5, 0.0, 1.0, 1.0);
          else if (i % 3 == 1)
            add_static_polygon (w, flat, 5);
          else
            add_static_polygon (w, notched, 7);
        }
      id = add_mover (w, SLIDING_BOX, 5.0);
      cross (w, id, 5.0, 39.0, &speed_err, &rise, &crossed);
      if (!crossed || !(speed_err < 0.01) || !(rise < 1e-3))
        fail_msg ("continuous %d: %s, speed off by %.3g, rose %.3g m", cont, crossed ? "crossed" : "did not cross",
                  speed_err, rise);
      carom_world_destroy (w);
    }
}

/* The vertex-edge method on outlines with seams (collide.h): a box's
 * corner 1 cm past a tile's left side, a seam, and 2 cm below its top
 * came in through the seam, shallower than through the top: it is met on
 * the top (the box's bottom along it, one parallel contact at the middle of
 * their 1 cm of overlap), and the tile's corner at the seam, inside the
 * box, is no corner (the face goes on across it). Without the seams the
 * corner is met on the tile's side, across the floor. */
static void test_vertex_edge_meets_no_seam (void **state)
{
  static const vec2 unit[4] = { { -0.5, -0.5 }, { 0.5, -0.5 }, { 0.5, 0.5 }, { -0.5, 0.5 } };
  static const vec2 small[4] = { { -0.1, -0.1 }, { 0.1, -0.1 }, { 0.1, 0.1 }, { -0.1, 0.1 } };
  xform tile, box;
  manifold m;
  int32_t i, side;
  (void) state;
  tile.p = v2 (0.5, -0.5), tile.q = rot2_from_angle (0.0);
  box.p = v2 (-0.09, 0.08), box.q = rot2_from_angle (0.0);
  /* edges 1 and 3, the tile's sides, are seams; the tile as A and as B */
  for (side = 0; side < 2; ++side)
    {
      double up = side ? -1.0 : 1.0; /* the normal points from A to B */
      if (side)
        collide_polygons_vertex_edge_seams (small, 4, 0u, box, unit, 4, 0xau, tile, 0.01, &m);
      else
        collide_polygons_vertex_edge_seams (unit, 4, 0xau, tile, small, 4, 0u, box, 0.01, &m);
      assert_int_equal (m.count, 1);
      assert_near_abs (m.points[0].normal.x, 0.0, 1e-15);
      assert_near_abs (m.points[0].normal.y, up, 1e-15);
      assert_near_abs (m.points[0].depth, 0.02, 1e-15);
      assert_near_abs (m.points[0].point.x, 0.005, 1e-15);
      assert_near_abs (m.points[0].point.y, -0.01, 1e-15);
    }
  collide_polygons_vertex_edge (unit, 4, tile, small, 4, box, 0.01, &m);
  for (i = 0; i < m.count && m.points[i].normal.x == 0.0; ++i)
    ;
  assert_true (i < m.count); /* a normal across the floor */
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_bodies_cross_touching_tiles_smoothly),
    cmocka_unit_test (test_partly_covered_edge_stays_a_surface),
    cmocka_unit_test (test_moving_a_static_body_makes_its_seams_again),
    cmocka_unit_test (test_vertex_edge_meets_no_seam),
    cmocka_unit_test (test_vertex_edge_reads_seams_of_any_outline),
  };
  return cmocka_run_group_tests_name ("seams", tests, NULL, NULL);
}
