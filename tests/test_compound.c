/* Bodies of several shapes (carom_world_add_compound): mass properties of
 * the union against closed forms, contacts with each shape's material,
 * queries and the debug draw on each shape, and the scene format's
 * compound blocks. */
#include "support.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static carom_world *new_world (double gy, double restitution, double friction)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = gy;
  if (restitution >= 0.0)
    def.restitution = restitution;
  if (friction >= 0.0)
    def.friction = friction;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  return w;
}

static carom_shape_def circle_shape (double x, double y, double r, double density)
{
  carom_shape_def s;
  assert_status (carom_shape_def_init (&s, sizeof s), CAROM_OK);
  s.kind = CAROM_SHAPE_CIRCLE;
  s.x = x, s.y = y, s.radius = r, s.density = density;
  return s;
}

/* A w x h box centred on (x, y), turned by angle; `xy` must outlive the
 * def (8 doubles). */
static carom_shape_def box_shape (double *xy, double x, double y, double angle, double w, double h, double density)
{
  carom_shape_def s;
  assert_status (carom_shape_def_init (&s, sizeof s), CAROM_OK);
  xy[0] = -0.5 * w, xy[1] = -0.5 * h, xy[2] = 0.5 * w, xy[3] = -0.5 * h;
  xy[4] = 0.5 * w, xy[5] = 0.5 * h, xy[6] = -0.5 * w, xy[7] = 0.5 * h;
  s.kind = CAROM_SHAPE_POLYGON;
  s.x = x, s.y = y, s.angle = angle, s.xy = xy, s.count = 4, s.density = density;
  return s;
}

static carom_body_id add_compound (carom_world *w, carom_body_type type, double x, double y, double angle,
                                   const carom_shape_def *shapes, int32_t count)
{
  carom_body_def d;
  carom_body_id id;
  carom_body_def_init (&d, sizeof d);
  d.type = type, d.x = x, d.y = y, d.angle = angle;
  assert_status (carom_world_add_compound (w, &d, shapes, count, &id), CAROM_OK);
  return id;
}

/* ------------------------------------------------------ mass properties */

/* Two discs of different densities joined by a bar: mass, centre of mass
 * and inertia by the parallel axis theorem, worked out here by hand. */
static void test_dumbbell_mass_matches_closed_form (void **state)
{
  const double r = 0.5, L = 2.0, bw = 3.0, bh = 0.4, rho1 = 2.0, rho2 = 1.0, rho3 = 0.5, angle = 0.7;
  carom_world *w = new_world (0.0, -1.0, -1.0);
  double xy[8], m1 = rho1 * M_PI * r * r, m2 = rho2 * M_PI * r * r, m3 = rho3 * bw * bh, m, c, inertia;
  double got_m, got_i, area, x, y, rad, density;
  carom_shape_def shapes[3];
  carom_shape_kind kind;
  carom_body_id id;
  int32_t count;
  (void) state;
  shapes[0] = circle_shape (-L, 0.0, r, rho1);
  shapes[1] = circle_shape (L, 0.0, r, -1.0); /* the body's density: 1 */
  shapes[2] = box_shape (xy, 0.0, 0.0, 0.0, bw, bh, rho3);
  id = add_compound (w, CAROM_DYNAMIC, 1.0, 2.0, angle, shapes, 3);
  m = m1 + m2 + m3;
  c = (m2 * L - m1 * L) / m; /* the centre of mass on the bar's axis */
  inertia = m1 * r * r / 2 + m1 * (L + c) * (L + c) + m2 * r * r / 2 + m2 * (L - c) * (L - c)
            + m3 * (bw * bw + bh * bh) / 12 + m3 * c * c;
  assert_status (carom_body_get_mass (w, id, &got_m, &got_i, &area), CAROM_OK);
  assert_near_rel (got_m, m, 1e-15);
  assert_near_rel (got_i, inertia, 1e-14);
  assert_near_rel (area, 2 * M_PI * r * r + bw * bh, 1e-15);
  /* the centre of mass sits at the body's position; each shape about it */
  assert_status (carom_body_get_shape_count (w, id, &count), CAROM_OK);
  assert_int_equal (count, 3);
  assert_status (carom_body_get_shape_geometry (w, id, 0, &kind, &x, &y, &rad, NULL, 0, &count), CAROM_OK);
  assert_int_equal (kind, CAROM_SHAPE_CIRCLE);
  assert_int_equal (count, 0);
  assert_near_abs (x, 1.0 + cos (angle) * (-L - c), 1e-14);
  assert_near_abs (y, 2.0 + sin (angle) * (-L - c), 1e-14);
  assert_near_rel (rad, r, 1e-15);
  assert_status (carom_body_get_shape_geometry (w, id, 2, &kind, &x, &y, &rad, xy, 4, &count), CAROM_OK);
  assert_int_equal (kind, CAROM_SHAPE_POLYGON);
  assert_int_equal (count, 4);
  assert_near_abs (x, 1.0 - cos (angle) * c, 1e-14);
  assert_near_abs (xy[0], 1.0 + cos (angle) * (-0.5 * bw - c) - sin (angle) * (-0.5 * bh), 1e-14);
  assert_near_abs (xy[1], 2.0 + sin (angle) * (-0.5 * bw - c) + cos (angle) * (-0.5 * bh), 1e-14);
  assert_status (carom_body_get_shape_material (w, id, 1, &density, NULL, NULL), CAROM_OK);
  assert_near_rel (density, 1.0, 0.0);
  assert_status (carom_body_get_shape_material (w, id, 0, &density, NULL, NULL), CAROM_OK);
  assert_near_rel (density, rho1, 0.0);
  carom_world_destroy (w);
}

/* An L of two boxes (one of them given as a turned polygon) has the mass
 * properties of the same L as one concave polygon (eq. 3.13, 3.14). */
static void test_l_of_two_boxes_is_the_concave_l (void **state)
{
  static const double l[] = { 0, 0, 2, 0, 2, 1, 1, 1, 1, 3, 0, 3 };
  carom_world *w = new_world (0.0, -1.0, -1.0);
  double xy1[8], xy2[8], m1, i1, m2, i2, x, y;
  carom_shape_def shapes[2];
  carom_body_def d;
  carom_body_id one, two;
  (void) state;
  shapes[0] = box_shape (xy1, 1.0, 0.5, 0.0, 2.0, 1.0, -1.0);
  /* the upright arm as a 2 x 1 box turned a quarter turn */
  shapes[1] = box_shape (xy2, 0.5, 2.0, 0.5 * M_PI, 2.0, 1.0, -1.0);
  carom_body_def_init (&d, sizeof d);
  d.density = 3.0, d.x = 4.0, d.y = -1.0;
  assert_status (carom_world_add_compound (w, &d, shapes, 2, &two), CAROM_OK);
  assert_status (carom_world_add_polygon (w, &d, l, 6, &one), CAROM_OK);
  assert_status (carom_body_get_mass (w, one, &m1, &i1, NULL), CAROM_OK);
  assert_status (carom_body_get_mass (w, two, &m2, &i2, NULL), CAROM_OK);
  assert_near_rel (m2, m1, 1e-14);
  assert_near_rel (m2, 12.0, 1e-14);
  assert_near_rel (i2, i1, 1e-13);
  /* the foot's centroid: (1, 0.5) less the L's centroid (3/4, 5/4) */
  assert_status (carom_body_get_shape_geometry (w, two, 0, NULL, &x, &y, NULL, NULL, 0, NULL), CAROM_OK);
  assert_near_abs (x, 4.0 + 1.0 - 0.75, 1e-14);
  assert_near_abs (y, -1.0 + 0.5 - 1.25, 1e-14);
  carom_world_destroy (w);
}

/* A shape far from the caller's origin loses nothing: the same dumbbell
 * given at 1e6 has the same inertia. */
static void test_far_shapes_keep_their_inertia (void **state)
{
  carom_world *w = new_world (0.0, -1.0, -1.0);
  carom_shape_def near_[2], far_[2];
  double m1, i1, m2, i2;
  carom_body_id a, b;
  (void) state;
  near_[0] = circle_shape (-1.0, 0.0, 0.5, 1.0);
  near_[1] = circle_shape (1.0, 0.3, 0.25, 2.0);
  far_[0] = circle_shape (1e6 - 1.0, 1e6, 0.5, 1.0);
  far_[1] = circle_shape (1e6 + 1.0, 1e6 + 0.3, 0.25, 2.0);
  a = add_compound (w, CAROM_DYNAMIC, 0.0, 0.0, 0.0, near_, 2);
  b = add_compound (w, CAROM_DYNAMIC, 0.0, 5.0, 0.0, far_, 2);
  assert_status (carom_body_get_mass (w, a, &m1, &i1, NULL), CAROM_OK);
  assert_status (carom_body_get_mass (w, b, &m2, &i2, NULL), CAROM_OK);
  assert_near_rel (m2, m1, 1e-15);
  assert_near_rel (i2, i1, 1e-9);
  carom_world_destroy (w);
}

/* ------------------------------------------------------------ contacts */

/* A table (a top and two legs) dropped on the ground stands on both legs,
 * level. */
static void test_table_stands_on_its_legs (void **state)
{
  carom_world *w = new_world (-9.81, 0.0, 0.6);
  double top[8], leg1[8], leg2[8], x, y, angle, vx, vy, spin, lo = 1e9;
  carom_shape_def shapes[3];
  carom_body_id ground, table;
  int32_t i, n, legs = 0;
  (void) state;
  ground = add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 20.0, 1.0);
  shapes[0] = box_shape (top, 0.0, 1.0, 0.0, 2.0, 0.2, -1.0);
  shapes[1] = box_shape (leg1, -0.9, 0.45, 0.0, 0.2, 0.9, -1.0);
  shapes[2] = box_shape (leg2, 0.9, 0.45, 0.0, 0.2, 0.9, -1.0);
  table = add_compound (w, CAROM_DYNAMIC, 0.3, 2.0, 0.0, shapes, 3);
  for (i = 0; i < 240; ++i)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  carom_body_get_position (w, table, &x, &y);
  carom_body_get_angle (w, table, &angle);
  carom_body_get_velocity (w, table, &vx, &vy);
  carom_body_get_spin (w, table, &spin);
  assert_near_abs (angle, 0.0, 1e-3);
  assert_near_abs (x, 0.3, 1e-3);
  assert_true (fabs (vx) + fabs (vy) + fabs (spin) < 1e-3);
  /* resting: the lowest point (a leg's foot) within the slop of y = 0 */
  for (i = 1; i < 3; ++i)
    {
      double v[8];
      int32_t k;
      assert_status (carom_body_get_shape_geometry (w, table, i, NULL, NULL, NULL, NULL, v, 4, &n), CAROM_OK);
      for (k = 0; k < 4; ++k)
        lo = fmin (lo, v[2 * k + 1]);
    }
  assert_near_abs (lo, 0.0, 0.01);
  /* each leg holds a contact with the ground, near its own x */
  n = carom_world_contact_count (w);
  for (i = 0; i < n; ++i)
    {
      carom_body_id a, b;
      double px;
      assert_status (carom_world_get_contact (w, i, &a, &b, &px, NULL, NULL, NULL, NULL), CAROM_OK);
      assert_true ((a == ground && b == table) || (a == table && b == ground));
      legs |= px < x ? 1 : 2;
      /* at a corner of a foot: 0.8 or 1.0 from the centre line */
      assert_true (fabs (fabs (px - x) - 0.9) <= 0.1 + 1e-3);
    }
  assert_int_equal (legs, 3);
  carom_world_destroy (w);
}

/* A dumbbell made before its ground (its discs the first of each pair of
 * shapes, so their contacts are turned round) rests level on both discs. */
static void test_dumbbell_rests_on_its_discs (void **state)
{
  carom_world *w = new_world (-9.81, 0.0, 0.5);
  double bar[8], y, angle, vx, vy;
  carom_shape_def shapes[3];
  carom_body_id id;
  int i;
  (void) state;
  shapes[0] = circle_shape (-1.0, 0.0, 0.4, -1.0);
  shapes[1] = circle_shape (1.0, 0.0, 0.4, -1.0);
  shapes[2] = box_shape (bar, 0.0, 0.0, 0.0, 1.2, 0.2, -1.0);
  id = add_compound (w, CAROM_DYNAMIC, 0.0, 1.0, 0.0, shapes, 3);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 20.0, 1.0);
  for (i = 0; i < 240; ++i)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  carom_body_get_position (w, id, NULL, &y);
  carom_body_get_angle (w, id, &angle);
  carom_body_get_velocity (w, id, &vx, &vy);
  assert_near_abs (y, 0.4, 0.01);
  assert_near_abs (angle, 0.0, 1e-2);
  assert_true (fabs (vx) + fabs (vy) < 1e-3);
  assert_int_equal (carom_world_contact_count (w), 2);
  carom_world_destroy (w);
}

/* Two equal dumbbells meet disc to disc along their axis with e = 1: they
 * swap velocities, as two equal bodies do, and neither turns. */
static void test_dumbbells_swap_velocities_head_on (void **state)
{
  carom_world *w = new_world (0.0, 1.0, 0.0);
  double bar_a[8], bar_b[8], va, vb, vy, spin_a, spin_b;
  carom_shape_def shapes[3];
  carom_body_id a, b;
  carom_body_def d;
  int step, touched = 0;
  (void) state;
  shapes[0] = circle_shape (-1.0, 0.0, 0.4, -1.0);
  shapes[1] = circle_shape (1.0, 0.0, 0.4, -1.0);
  shapes[2] = box_shape (bar_a, 0.0, 0.0, 0.0, 1.2, 0.2, -1.0);
  carom_body_def_init (&d, sizeof d);
  d.x = -2.0, d.vx = 2.0;
  assert_status (carom_world_add_compound (w, &d, shapes, 3, &a), CAROM_OK);
  shapes[2] = box_shape (bar_b, 0.0, 0.0, 0.0, 1.2, 0.2, -1.0);
  d.x = 1.5, d.vx = -1.0;
  assert_status (carom_world_add_compound (w, &d, shapes, 3, &b), CAROM_OK);
  for (step = 0; step < 1000; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 120), CAROM_OK);
      if (carom_world_contact_count (w) > 0)
        touched = 1;
      else if (touched)
        break;
    }
  assert_true (touched);
  carom_body_get_velocity (w, a, &va, &vy);
  carom_body_get_velocity (w, b, &vb, NULL);
  carom_body_get_spin (w, a, &spin_a);
  carom_body_get_spin (w, b, &spin_b);
  assert_near_rel (va, -1.0, 1e-12);
  assert_near_rel (vb, 2.0, 1e-12);
  assert_near_abs (vy, 0.0, 1e-15);
  assert_near_abs (spin_a, 0.0, 1e-15);
  assert_near_abs (spin_b, 0.0, 1e-15);
  carom_world_destroy (w);
}

/* A static floor 10 x 1, its top at y = 0. */
static void add_floor (carom_world *w)
{
  carom_body_def d;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -0.5;
  assert_status (carom_world_add_box (w, &d, 10.0, 1.0, NULL), CAROM_OK);
}

/* Drop body `id` of w (at rest, its lowest side flat 0.1 above a static
 * floor at y = 0, given vx) from `height` more and step until its first
 * bounce is over (it rises); its velocity and spin then, and the speed it
 * struck with. */
static void first_bounce (carom_world *w, carom_body_id id, double *vx, double *vy, double *spin, double *struck)
{
  int step;
  double last = 0.0;
  for (step = 0; step < 2000; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      assert_status (carom_body_get_velocity (w, id, vx, vy), CAROM_OK);
      if (*vy > 0.0)
        break;
      last = *vy;
    }
  assert_true (*vy > 0.0);
  assert_status (carom_body_get_spin (w, id, spin), CAROM_OK);
  *struck = -last;
}

/* A body that lands flat on several of its pieces at once takes one impact
 * on all of them, as a box takes one on its two corners (lib/impact.c,
 * impact_group_event): a rectangle made of two boxes side by side (a
 * compound, split at a half, a third or a fifth) leaves the floor as the
 * one box of the same outline does, for e = 0.5, 0.8 and 1, with and
 * without friction, dropped straight or sliding, from 0.5 or 1.3 m, flat
 * or tilted by a millionth of a radian (its pieces then touch one after
 * the other, the later within the slop, as the box's second corner): the
 * normal speed to 1e-9 of the speed struck with, the slip and the turn to
 * 1e-9 without friction and to 1e-6 with it (Coulomb friction in an impact
 * is taken point by point, impact_friction, and the normal impulse shares
 * out among the compound's four points, two of them on the seam, not as
 * among the box's two: 2e-7 in the tilted cases); and a
 * symmetric H (a concave polygon, 0.2 wide, on two feet 0.067 wide) rises
 * as the box does, without turning (but for what friction under it turns
 * it by when it slides), with either narrow phase (the vertex-edge
 * method's one contact of the H holds the points of both feet: more than
 * two points of one contact are one impact as well; its time of impact is
 * its convex pieces' earliest). Taken one piece after the other,
 * the first foot's bounce tipped the body onto the second: the H left at
 * 15 rad/s. */
static void test_landing_flat_on_several_pieces_is_one_impact (void **state)
{
  static const double splits[] = { 0.5, 1.0 / 3.0, 0.2 }, es[] = { 0.5, 0.8, 1.0 }, heights[] = { 0.5, 1.3 };
  static const double h_outline[] = { -0.1,  -0.1,  -0.033, -0.1,  -0.033, -0.033, 0.033,  -0.033,
                                      0.033, -0.1,  0.1,    -0.1,  0.1,    0.1,    0.033,  0.1,
                                      0.033, 0.033, -0.033, 0.033, -0.033, 0.1,    -0.1,   0.1 };
  const double width = 0.6, tall = 0.2;
  int si, ei, hi, slide, rough, tilted, vertex_edge, cases = 0;
  double worst_normal = 0.0, worst_slip = 0.0, worst_h = 0.0, vx, vy, spin, struck;
  carom_world *w;
  carom_world_def def;
  carom_body_def d;
  carom_body_id id;
  (void) state;
  for (ei = 0; ei < 3; ++ei)
    for (hi = 0; hi < 2; ++hi)
      for (rough = 0; rough < 2; ++rough)
        for (slide = 0; slide < 2; ++slide)
          for (tilted = 0; tilted < 2; ++tilted)
            {
              double vx0 = slide ? 1.0 : 0.0, y0 = 0.1 + 0.5 * tall + heights[hi];
              double box_v[2], box_w, box_struck;
              w = new_world (-9.81, es[ei], rough ? 0.5 : 0.0);
              add_floor (w);
              carom_body_def_init (&d, sizeof d);
              d.y = y0, d.vx = vx0, d.angle = tilted ? 1e-6 : 0.0;
              assert_status (carom_world_add_box (w, &d, width, tall, &id), CAROM_OK);
              first_bounce (w, id, &box_v[0], &box_v[1], &box_w, &box_struck);
              carom_world_destroy (w);
              for (si = 0; si < 3; ++si)
                {
                  double left = splits[si] * width, xy1[8], xy2[8];
                  carom_shape_def halves[2];
                  w = new_world (-9.81, es[ei], rough ? 0.5 : 0.0);
                  add_floor (w);
                  halves[0] = box_shape (xy1, -0.5 * width + 0.5 * left, 0.0, 0.0, left, tall, -1.0);
                  halves[1] = box_shape (xy2, 0.5 * left, 0.0, 0.0, width - left, tall, -1.0);
                  carom_body_def_init (&d, sizeof d);
                  d.y = y0, d.vx = vx0, d.angle = tilted ? 1e-6 : 0.0;
                  assert_status (carom_world_add_compound (w, &d, halves, 2, &id), CAROM_OK);
                  first_bounce (w, id, &vx, &vy, &spin, &struck);
                  carom_world_destroy (w);
                  worst_normal = fmax (worst_normal, fabs (vy - box_v[1]) / box_struck);
                  worst_slip = fmax (worst_slip, fmax (fabs (vx - box_v[0]), fabs (spin - box_w) * width) / box_struck);
                  if (!(fabs (vy - box_v[1]) <= 1e-9 * box_struck
                        && fmax (fabs (vx - box_v[0]), fabs (spin - box_w) * width)
                               <= (rough ? 1e-6 : 1e-9) * box_struck))
                    fail_msg ("split %.3g, e %g, from %g m, friction %d, sliding %d, tilted %d: the compound leaves at "
                              "(%.9g, %.9g) turning at %.3g rad/s, the box at (%.9g, %.9g), %.3g rad/s",
                              splits[si], es[ei], heights[hi], rough, slide, tilted, vx, vy, spin, box_v[0], box_v[1],
                              box_w);
                  ++cases;
                }
              for (vertex_edge = 0; vertex_edge < 2; ++vertex_edge)
                {
                  carom_world_def_init (&def, sizeof def);
                  def.gravity_y = -9.81, def.restitution = es[ei], def.friction = rough ? 0.5 : 0.0;
                  def.narrow_phase = vertex_edge ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
                  assert_status (carom_world_init (&w, &def), CAROM_OK);
                  add_floor (w);
                  carom_body_def_init (&d, sizeof d);
                  d.y = y0, d.vx = vx0, d.angle = tilted ? 1e-6 : 0.0;
                  assert_status (carom_world_add_polygon (w, &d, h_outline, 12, &id), CAROM_OK);
                  first_bounce (w, id, &vx, &vy, &spin, &struck);
                  carom_world_destroy (w);
                  /* landing flat, any body rises as the box does (tilted,
                   * its lowest corner starts higher), with either method;
                   * one sliding on a rough floor turns by the friction
                   * under it */
                  if (!(rough && slide))
                    worst_h = fmax (worst_h, fabs (spin) * 0.2 / struck);
                  if (!((tilted || fabs (vy - box_v[1]) <= 1e-9 * struck)
                        && (rough && slide ? 1 : fabs (spin) * 0.2 <= 1e-9 * struck)))
                    fail_msg ("the H (%s), e %g, from %g m, friction %d, sliding %d: leaves at %.9g (the box: %.9g) "
                              "turning at %.3g rad/s",
                              vertex_edge ? "vertex-edge" : "SAT", es[ei], heights[hi], rough, slide, vy, box_v[1],
                              spin);
                }
            }
  print_message ("%d compounds left the floor as their box did: normal speed within %.3g, slip and turn within %.3g "
                 "of the speed they struck with; the H turning at most %.3g of it\n",
                 cases, worst_normal, worst_slip, worst_h);
}

/* On a slope of tan 0.5 (friction 1) the shape's own friction decides, not
 * the body's: a box shape of friction 1 on a body of 0.1 holds
 * (sqrt(1 x 1) > 0.5), a box shape of 0.1 on a body of 1 slides
 * (sqrt(0.1 x 1) < 0.5). */
static void test_shape_friction_decides_on_a_slope (void **state)
{
  const double slope = atan (0.5);
  carom_world *w = new_world (-9.81, 0.0, 1.0);
  double xy1[8], xy2[8], x0[2], y0[2], x, y, e, mu;
  carom_shape_def grippy, slippery;
  carom_body_def d;
  carom_body_id ids[2];
  int i;
  (void) state;
  grippy = box_shape (xy1, 0.0, 0.0, 0.0, 1.0, 0.5, -1.0);
  grippy.friction = 1.0;
  slippery = box_shape (xy2, 0.0, 0.0, 0.0, 1.0, 0.5, -1.0);
  slippery.friction = 0.1;
  carom_body_def_init (&d, sizeof d);
  d.angle = slope;
  for (i = 0; i < 2; ++i)
    {
      d.friction = i == 0 ? 0.1 : 1.0;
      /* resting on the slope's top face, 5 m apart along it */
      double along = i == 0 ? -3.0 : 3.0;
      d.x = along * cos (slope) - 0.75 * sin (slope);
      d.y = along * sin (slope) + 0.75 * cos (slope);
      assert_status (carom_world_add_compound (w, &d, i == 0 ? &grippy : &slippery, 1, &ids[i]), CAROM_OK);
      carom_body_get_position (w, ids[i], &x0[i], &y0[i]);
      /* the slope between the two, so each side of a pair is a compound
       * once (the lower slot is a pair's first) */
      if (i == 0)
        add_box (w, CAROM_STATIC, 0.0, 0.0, slope, 40.0, 1.0); /* friction: the world's 1 */
    }
  assert_status (carom_body_get_shape_material (w, ids[0], 0, NULL, &e, &mu), CAROM_OK);
  assert_near_rel (mu, 1.0, 0.0);
  assert_status (carom_body_get_shape_material (w, ids[1], 0, NULL, &e, &mu), CAROM_OK);
  assert_near_rel (mu, 0.1, 0.0);
  assert_near_abs (e, 0.0, 0.0);
  for (i = 0; i < 120; ++i)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  carom_body_get_position (w, ids[0], &x, &y);
  assert_true (hypot (x - x0[0], y - y0[0]) < 2e-3);
  carom_body_get_position (w, ids[1], &x, &y);
  /* slid down: (g sin - mu g cos) t^2 / 2 = 3.2 m in 2 s at mu 0.316 */
  assert_true (hypot (x - x0[1], y - y0[1]) > 2.0);
  assert_true (y < y0[1]);
  carom_world_destroy (w);
}

/* Static compounds (a floor of tiles in one body) carry what rests on
 * them, and a compound sensor sees what enters any of its shapes. */
static void test_static_and_sensor_compounds (void **state)
{
  carom_world *w = new_world (-9.81, 0.0, 0.5);
  double t1[8], t2[8], x, y;
  carom_shape_def tiles[2], zone[2];
  carom_contact_event ev[8];
  carom_body_def d;
  carom_body_id ball, sensor;
  int i, began = 0;
  (void) state;
  tiles[0] = box_shape (t1, -1.0, 0.0, 0.0, 2.0, 0.5, -1.0);
  tiles[1] = box_shape (t2, 1.0, 0.0, 0.0, 2.0, 0.5, -1.0);
  add_compound (w, CAROM_STATIC, 0.0, -0.25, 0.0, tiles, 2);
  zone[0] = circle_shape (-3.0, 0.0, 0.3, -1.0);
  zone[1] = circle_shape (0.5, 0.0, 0.3, -1.0); /* where the ball falls */
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.sensor = 1, d.x = -1.25, d.y = 1.0;
  assert_status (carom_world_add_compound (w, &d, zone, 2, &sensor), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  /* above the second zone: its centre is at -1.25 + (0.5 - (-1.25)), the
   * zones' centroid being -1.25 */
  d.x = 0.5, d.y = 2.0;
  assert_status (carom_world_add_circle (w, &d, 0.1, &ball), CAROM_OK);
  for (i = 0; i < 180; ++i)
    {
      int32_t k, n;
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      n = carom_world_get_events (w, ev, 8);
      for (k = 0; k < n && k < 8; ++k)
        if (ev[k].type == CAROM_EVENT_SENSOR_BEGIN && ev[k].a == sensor && ev[k].b == ball)
          began++;
    }
  assert_int_equal (began, 1);
  carom_body_get_position (w, ball, &x, &y);
  assert_near_abs (y, 0.1, 0.01);
  assert_near_abs (x, 0.5, 1e-9);
  carom_world_destroy (w);
}

/* -------------------------------------------------------------- queries */

static void test_queries_see_each_shape (void **state)
{
  /* a disc at (-2, 0) and a unit box at (2, 0): their centre of mass at
   * cx, placed at the origin */
  const double ac = M_PI * 0.25, cx = (ac * -2.0 + 1.0 * 2.0) / (ac + 1.0);
  carom_world *w = new_world (0.0, -1.0, -1.0);
  double xy[8];
  carom_shape_def shapes[2];
  carom_ray_hit hit;
  carom_body_id id, ids[2];
  (void) state;
  shapes[0] = circle_shape (-2.0, 0.0, 0.5, -1.0);
  shapes[1] = box_shape (xy, 2.0, 0.0, 0.0, 1.0, 1.0, -1.0);
  id = add_compound (w, CAROM_DYNAMIC, 0.0, 0.0, 0.0, shapes, 2);
  /* along y = 0.3 from the left: the disc, at x = -2 - sqrt(0.25 - 0.09) */
  assert_status (carom_world_cast_ray (w, -10.0, 0.3, 10.0, 0.3, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == id);
  assert_near_abs (hit.x, -2.0 - cx - 0.4, 1e-12);
  assert_near_abs (hit.nx, -0.8, 1e-12);
  assert_near_abs (hit.ny, 0.6, 1e-12);
  assert_near_abs (hit.fraction, (hit.x + 10.0) / 20.0, 1e-15);
  /* from the right: the box's face */
  assert_status (carom_world_cast_ray (w, 10.0, 0.3, -10.0, 0.3, ~0u, &hit), CAROM_OK);
  assert_near_abs (hit.x, 2.5 - cx, 1e-12);
  assert_near_abs (hit.nx, 1.0, 1e-15);
  /* between the shapes, inside the body's box: nothing */
  assert_status (carom_world_cast_ray (w, -cx, 3.0, -cx, -3.0, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == CAROM_NULL_BODY);
  assert_int_equal (carom_world_query_point (w, -cx, 0.0, ~0u, ids, 2), 0);
  assert_int_equal (carom_world_query_point (w, -2.0 - cx + 0.45, 0.0, ~0u, ids, 2), 1);
  assert_int_equal (carom_world_query_point (w, 2.45 - cx, 0.45, ~0u, ids, 2), 1);
  assert_int_equal (carom_world_query_point (w, 2.55 - cx, 0.45, ~0u, ids, 2), 0);
  /* the tight box of the union */
  assert_int_equal (carom_world_query_aabb (w, 2.49 - cx, -0.6, 2.6 - cx, 0.6, ~0u, ids, 2), 1);
  assert_int_equal (carom_world_query_aabb (w, 2.51 - cx, -0.6, 2.6 - cx, 0.6, ~0u, ids, 2), 0);
  assert_int_equal (carom_world_query_aabb (w, -3.0 - cx, 0.49, -1.0 - cx, 0.6, ~0u, ids, 2), 1);
  assert_int_equal (carom_world_query_aabb (w, -3.0 - cx, 0.51, -1.0 - cx, 0.6, ~0u, ids, 2), 0);
  carom_world_destroy (w);
}

typedef struct draw_count {
  int circles, polygons;
  carom_body_id last;
} draw_count;

static void count_circle (double x, double y, double r, double angle, carom_body_id body, void *user)
{
  draw_count *c = user;
  (void) x, (void) y, (void) r, (void) angle;
  c->circles++;
  c->last = body;
}

static void count_polygon (const double *xy, int32_t n, carom_body_id body, void *user)
{
  draw_count *c = user;
  (void) xy, (void) n;
  c->polygons++;
  c->last = body;
}

static void test_debug_draw_draws_each_shape (void **state)
{
  static const double notch[] = { 0, 0, 2, 0, 2, 2, 1, 1, 0, 2 };
  carom_world *w = new_world (0.0, -1.0, -1.0);
  carom_shape_def shapes[3];
  carom_debug_draw draw;
  draw_count c = { 0, 0, 0 };
  carom_body_id id;
  (void) state;
  shapes[0] = circle_shape (-2.0, 0.0, 0.5, -1.0);
  shapes[1] = circle_shape (-3.0, 0.0, 0.5, -1.0);
  assert_status (carom_shape_def_init (&shapes[2], sizeof shapes[2]), CAROM_OK);
  shapes[2].kind = CAROM_SHAPE_POLYGON, shapes[2].xy = notch, shapes[2].count = 5;
  id = add_compound (w, CAROM_DYNAMIC, 0.0, 0.0, 0.0, shapes, 3);
  assert_status (carom_debug_draw_init (&draw, sizeof draw), CAROM_OK);
  draw.circle = count_circle, draw.polygon = count_polygon, draw.user = &c;
  assert_status (carom_world_draw (w, &draw), CAROM_OK);
  assert_int_equal (c.circles, 2);
  assert_int_equal (c.polygons, 1);
  assert_true (c.last == id);
  carom_world_destroy (w);
}

/* --------------------------------------------------------------- scenes */

static void test_scene_compound_is_the_api_compound (void **state)
{
  static const char text[] = "compound at 1 2 angle 0.5 friction 0.3\n"
                             "  circle 0.5 at -1 0 density 2 restitution 0.5\n"
                             "  box 1 0.5 at 0.5 0 angle 0.25\n"
                             "  regular 6 0.3 at 0 1 friction 0.9\n"
                             "  polygon 0 0 1 0 1 1 0.5 0.5 0 1 at 0 -1\n"
                             "end\n"
                             "circle 0.25 at 5 5\n";
  static const double notch[] = { 0, 0, 1, 0, 1, 1, 0.5, 0.5, 0, 1 };
  carom_world *scene = NULL, *w = new_world (0.0, -1.0, -1.0);
  carom_scene_error err;
  double box[8], hexagon[12], m1, i1, m2, i2, density, e, mu;
  carom_shape_def shapes[4];
  carom_body_def d;
  carom_body_id ids[2], id;
  int32_t n, k;
  (void) state;
  err.size = sizeof err;
  assert_status (carom_scene_load_text (&scene, text, sizeof text - 1, NULL, &err), CAROM_OK);
  assert_int_equal (carom_world_get_bodies (scene, ids, 2), 2);
  shapes[0] = circle_shape (-1.0, 0.0, 0.5, 2.0);
  shapes[0].restitution = 0.5;
  shapes[1] = box_shape (box, 0.5, 0.0, 0.25, 1.0, 0.5, -1.0);
  assert_status (carom_shape_def_init (&shapes[2], sizeof shapes[2]), CAROM_OK);
  for (k = 0; k < 6; ++k)
    {
      double r = 0.3 / (2.0 * sin (M_PI / 6));
      hexagon[2 * k] = r * cos (2.0 * M_PI * k / 6), hexagon[2 * k + 1] = r * sin (2.0 * M_PI * k / 6);
    }
  shapes[2].kind = CAROM_SHAPE_POLYGON, shapes[2].xy = hexagon, shapes[2].count = 6, shapes[2].y = 1.0;
  shapes[2].friction = 0.9;
  assert_status (carom_shape_def_init (&shapes[3], sizeof shapes[3]), CAROM_OK);
  shapes[3].kind = CAROM_SHAPE_POLYGON, shapes[3].xy = notch, shapes[3].count = 5, shapes[3].y = -1.0;
  carom_body_def_init (&d, sizeof d);
  d.x = 1.0, d.y = 2.0, d.angle = 0.5, d.friction = 0.3;
  assert_status (carom_world_add_compound (w, &d, shapes, 4, &id), CAROM_OK);
  assert_status (carom_body_get_mass (scene, ids[0], &m1, &i1, NULL), CAROM_OK);
  assert_status (carom_body_get_mass (w, id, &m2, &i2, NULL), CAROM_OK);
  assert_true (m1 == m2 && i1 == i2);
  assert_status (carom_body_get_shape_count (scene, ids[0], &n), CAROM_OK);
  assert_int_equal (n, 4);
  for (k = 0; k < 4; ++k)
    {
      double x1, y1, x2, y2;
      assert_status (carom_body_get_shape_geometry (scene, ids[0], k, NULL, &x1, &y1, NULL, NULL, 0, NULL), CAROM_OK);
      assert_status (carom_body_get_shape_geometry (w, id, k, NULL, &x2, &y2, NULL, NULL, 0, NULL), CAROM_OK);
      assert_true (x1 == x2 && y1 == y2);
    }
  assert_status (carom_body_get_shape_material (scene, ids[0], 0, &density, &e, &mu), CAROM_OK);
  assert_true (density == 2.0 && e == 0.5 && mu == 0.3);
  assert_status (carom_body_get_shape_material (scene, ids[0], 2, &density, &e, &mu), CAROM_OK);
  assert_true (density == 1.0 && mu == 0.9);
  carom_world_destroy (scene);
  carom_world_destroy (w);
}

typedef struct bad_scene {
  const char *text;
  int32_t line;
  carom_status cause;
} bad_scene;

static void test_scene_compound_errors_name_their_line (void **state)
{
  static const bad_scene cases[] = {
    { "compound\n  circle 1\n", 1, CAROM_ERR_SCENE_SYNTAX },                  /* no end */
    { "circle 1\nend\n", 2, CAROM_ERR_SCENE_SYNTAX },                         /* end alone */
    { "compound\nend\n", 2, CAROM_ERR_BAD_ARGUMENT },                         /* no shapes */
    { "compound\n  circle 1\n  compound\nend\n", 3, CAROM_ERR_SCENE_SYNTAX }, /* nested */
    { "compound\n  gravity 0 1\nend\n", 2, CAROM_ERR_SCENE_SYNTAX },          /* a setting inside */
    { "compound\n  circle 1 velocity 1 0\nend\n", 2, CAROM_ERR_SCENE_SYNTAX },
    { "compound\n  circle 1\n  circle -1 at 2 0\nend\n", 3, CAROM_ERR_BAD_SIZE },
    { "compound\n  box 1 1\n  polygon 0 0 1 1 1 0 0 1\nend\n", 3, CAROM_ERR_SELF_INTERSECTING },
    { "compound\n  circle 1 density 0\nend\n", 2, CAROM_ERR_BAD_DENSITY },
    { "compound\n  circle 1 restitution 2\nend\n", 2, CAROM_ERR_BAD_ARGUMENT },
    { "compound\n  circle 1 at 1e200 0\nend\n", 2, CAROM_ERR_BAD_ARGUMENT },
    { "compound velocity 1 0 static\n  circle 1\nend\n", 1, CAROM_ERR_STATIC_BODY },
    /* a union too heavy to simulate: reported at its end */
    { "compound density 1e100\n  circle 4.3e49\n  circle 4.3e49 at 1e50 0\nend\n", 4, CAROM_ERR_BAD_DENSITY },
  };
  size_t i;
  (void) state;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i)
    {
      carom_world *world = (carom_world *) &world;
      carom_scene_error err;
      carom_status s;
      err.size = sizeof err;
      s = carom_scene_load_text (&world, cases[i].text, strlen (cases[i].text), NULL, &err);
      if (s != cases[i].cause || err.line != cases[i].line || world != NULL)
        fail_msg ("case %d: status %d (%s), line %d, wanted %d at line %d", (int) i, (int) s, err.message,
                  (int) err.line, (int) cases[i].cause, (int) cases[i].line);
    }
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_dumbbell_mass_matches_closed_form),
    cmocka_unit_test (test_l_of_two_boxes_is_the_concave_l),
    cmocka_unit_test (test_far_shapes_keep_their_inertia),
    cmocka_unit_test (test_table_stands_on_its_legs),
    cmocka_unit_test (test_dumbbell_rests_on_its_discs),
    cmocka_unit_test (test_dumbbells_swap_velocities_head_on),
    cmocka_unit_test (test_landing_flat_on_several_pieces_is_one_impact),
    cmocka_unit_test (test_shape_friction_decides_on_a_slope),
    cmocka_unit_test (test_static_and_sensor_compounds),
    cmocka_unit_test (test_queries_see_each_shape),
    cmocka_unit_test (test_debug_draw_draws_each_shape),
    cmocka_unit_test (test_scene_compound_is_the_api_compound),
    cmocka_unit_test (test_scene_compound_errors_name_their_line),
  };
  return cmocka_run_group_tests_name ("compound", tests, NULL, NULL);
}
