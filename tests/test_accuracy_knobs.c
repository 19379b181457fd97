/* Each knob of carom_world_def moves the error the way its documentation
 * says, on small cases and without timing anything: every test runs the same
 * case at two settings and asserts error(better) < margin * error(worse).
 * The measured cost of these knobs is in docs/accuracy.md (make
 * bench-accuracy). */
#include "support.h"

#include <math.h>
#include <string.h>

/* A world with gravity (0, gy) and e; the knobs are set by the caller. */
static carom_world_def make_def (double gy, double restitution)
{
  carom_world_def def;
  assert_status (carom_world_def_init (&def, sizeof def), CAROM_OK);
  def.gravity_y = gy;
  def.restitution = restitution;
  def.friction = 0.6;
  return def;
}

static carom_world *make_world (const carom_world_def *def)
{
  carom_world *w = NULL;
  assert_status (carom_world_init (&w, def), CAROM_OK);
  return w;
}

/* Largest penetration depth among the contacts the last update found. */
static double max_depth (const carom_world *w)
{
  int32_t i, n = carom_world_contact_count (w);
  double worst = 0.0;
  for (i = 0; i < n; ++i)
    {
      double depth;
      assert_status (carom_world_get_contact (w, i, NULL, NULL, NULL, NULL, NULL, NULL, &depth), CAROM_OK);
      if (depth > worst)
        worst = depth;
    }
  return worst;
}

/* A pyramid of `rows` rows of unit boxes on a static ground, each box of a
 * row resting on two of the row below (1.1 apart, so it overlaps each by
 * 0.45), the rows built 0.006 apart: just beyond the slop (0.005), within
 * the contacts' margin, so their contacts exist from the first step, apart,
 * and the boxes settle onto each other as the passes allow (a pile built
 * touching starts from the weight each contact carries, contact_cold_start;
 * a column's contacts are held by shock propagation, shock.c, whatever the
 * knobs; a box on two is left to the passes). Stepped for `steps` steps of
 * dt: the deepest penetration seen at any step, and how far the top box
 * ends below its stacked height. */
static void pyramid_errors (const carom_world_def *def, int rows, int steps, double dt, double *penetration,
                            double *sink)
{
  carom_world *w = make_world (def);
  carom_body_id top = CAROM_NULL_BODY;
  double x, y0 = 0.5 + (rows - 1), y1;
  int i, r;
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 20.0, 1.0);
  for (r = 0; r < rows; ++r)
    for (i = 0; i < rows - r; ++i)
      top = add_box (w, CAROM_DYNAMIC, 1.1 * (i - 0.5 * (rows - r - 1)), 0.506 + 1.006 * r, 0.0, 1.0, 1.0);
  *penetration = 0.0;
  for (i = 0; i < steps; ++i)
    {
      double d;
      assert_status (carom_world_update (w, dt), CAROM_OK);
      d = max_depth (w);
      if (d > *penetration)
        *penetration = d;
    }
  carom_body_get_position (w, top, &x, &y1);
  *sink = y0 - y1;
  carom_world_destroy (w);
}

static void test_more_substeps_less_penetration (void **state)
{
  carom_world_def one = make_def (-10.0, 0.0), four = one;
  double pen1, pen4, sink1, sink4;
  (void) state;
  one.substeps = 1;
  four.substeps = 4;
  pyramid_errors (&one, 5, 60, 1.0 / 60.0, &pen1, &sink1);
  pyramid_errors (&four, 5, 60, 1.0 / 60.0, &pen4, &sink4);
  print_message ("pyramid of 5 rows, 1 s: substeps 1: penetration %.3g sink %.3g; substeps 4: %.3g, %.3g\n", pen1,
                 sink1, pen4, sink4);
  assert_true (pen1 > 0.0);
  assert_true (pen4 < 0.5 * pen1);
  assert_true (sink4 < 0.5 * sink1);
}

static void test_more_iterations_less_penetration (void **state)
{
  carom_world_def few = make_def (-10.0, 0.0), many = few;
  double pen2, pen16, sink2, sink16;
  (void) state;
  few.iterations = 2;
  many.iterations = 16;
  pyramid_errors (&few, 5, 60, 1.0 / 60.0, &pen2, &sink2);
  pyramid_errors (&many, 5, 60, 1.0 / 60.0, &pen16, &sink16);
  print_message ("pyramid of 5 rows, 1 s: iterations 2: penetration %.3g sink %.3g; iterations 16: %.3g, %.3g\n",
                 pen2, sink2, pen16, sink16);
  assert_true (pen16 < 0.5 * pen2);
  assert_true (sink16 < 0.5 * sink2);
}

/* Two boxes created overlapping by 0.2 (no gravity): the overlap left after
 * 5 steps, measured by a detection on the final positions. */
static double overlap_left (double position_correction, double restitution)
{
  carom_world_def def = make_def (0.0, restitution);
  carom_world *w;
  double depth;
  def.position_correction = position_correction;
  w = make_world (&def);
  add_box (w, CAROM_DYNAMIC, 0.0, 0.0, 0.0, 1.0, 1.0);
  add_box (w, CAROM_DYNAMIC, 0.98, 0.0, 0.0, 1.0, 1.0);
  assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
  assert_status (carom_world_detect (w), CAROM_OK);
  depth = max_depth (w);
  carom_world_destroy (w);
  return depth;
}

/* Position correction removes that fraction of the overlap beyond the slop
 * (1% of the size 2 A / P = 0.5 of a unit box: 0.005) per sub-step: an
 * overlap of 0.02 after one step of 4 sub-steps is 0.015 0.95^4 + slop =
 * 0.0172 with 0.05, and 0.015 0.6^4 + slop = 0.0069 with 0.4 (both below
 * the push-out speed limit). */
static void test_more_position_correction_less_overlap (void **state)
{
  double e;
  (void) state;
  /* e = 0: the contact is solved in a batch; e = 0.5: one at a time */
  for (e = 0.0; e <= 0.5; e += 0.5)
    {
      double low = overlap_left (0.05, e), high = overlap_left (0.4, e);
      print_message ("overlap 0.02 after 1 step, e %g: position_correction 0.05: %.3g, 0.4: %.3g\n", e, low, high);
      assert_near_abs (low, 0.015 * pow (0.95, 4) + 0.005, 1e-6);
      assert_near_abs (high, 0.015 * pow (0.6, 4) + 0.005, 1e-6);
    }
}

/* A circle of diameter 1 dropped from 2 (its bottom above the ground) with
 * e = 0.5: |top of the first bounce / (e^2 h0) - 1|, the top taken from the
 * last rising state as y + v^2 / 2g. */
static double bounce_error (double dt, int substeps, int continuous)
{
  carom_world_def def = make_def (-10.0, 0.5);
  carom_world *w;
  carom_body_def d;
  carom_body_id ball;
  double top = -1.0;
  int i, fell = 0, n = (int) (3.0 / dt);
  def.substeps = substeps;
  w = make_world (&def);
  assert_status (carom_world_set_continuous (w, continuous), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 20.0, 1.0);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.y = 2.5;
  assert_status (carom_world_add_circle (w, &d, 0.5, &ball), CAROM_OK);
  for (i = 0; i < n; ++i)
    {
      double x, y, vx, vy;
      assert_status (carom_world_update (w, dt), CAROM_OK);
      carom_body_get_position (w, ball, &x, &y);
      carom_body_get_velocity (w, ball, &vx, &vy);
      if (vy < -1e-9)
        {
          if (fell == 2)
            break;
          fell = 1;
        }
      else if (fell && vy > 1e-9)
        {
          fell = 2;
          top = y - 0.5 + vy * vy / 20.0;
        }
    }
  carom_world_destroy (w);
  assert_true (top > 0.0);
  return fabs (top / 0.5 - 1.0);
}

/* Free flight under a central 1/r^2 attraction is integrated with a first
 * order method, so its error is one that dt controls: the radius of a
 * circular orbit strays less with a smaller dt, and 4 sub-steps of 1/60 are
 * the same as dt 1/240. */
static double orbit_error (double dt, int substeps)
{
  carom_world_def def = make_def (0.0, 0.0);
  carom_world *w;
  carom_body_def d;
  carom_body_id sat;
  double worst = 0.0, x, y;
  int i, n = (int) (20.0 / dt);
  def.substeps = substeps;
  w = make_world (&def);
  assert_status (carom_world_set_central_gravity (w, 0.0, 0.0, 100.0, 0.0), CAROM_OK);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.x = 10.0, d.vy = sqrt (100.0 / 10.0);
  assert_status (carom_world_add_circle (w, &d, 0.1, &sat), CAROM_OK);
  for (i = 0; i < n; ++i)
    {
      assert_status (carom_world_update (w, dt), CAROM_OK);
      carom_body_get_position (w, sat, &x, &y);
      worst = fmax (worst, fabs (sqrt (x * x + y * y) / 10.0 - 1.0));
    }
  carom_world_destroy (w);
  return worst;
}

static void test_smaller_dt_smaller_error (void **state)
{
  double coarse = orbit_error (1.0 / 60.0, 1), fine = orbit_error (1.0 / 240.0, 1);
  double sub = orbit_error (1.0 / 60.0, 4), bounce = bounce_error (1.0 / 60.0, 1, 1);
  double plain = bounce_error (1.0 / 60.0, 1, 0);
  (void) state;
  print_message ("orbit radius error: dt 1/60: %.3g, dt 1/240: %.3g, dt 1/60 with 4 substeps: %.3g; "
                 "bounce height error at dt 1/60: %.3g with continuous collision, %.3g without\n", coarse, fine,
                 sub, bounce, plain);
  assert_true (fine < 0.5 * coarse);
  assert_true (sub < 0.5 * coarse);
  /* with continuous collision the impact is placed at its time within the
   * step, with gravity before and after it: even at the coarsest step the
   * bounce height is e^2 h to rounding (tests/test_impacts.c sweeps heights,
   * steps and sub-steps); without, the ball meets the floor overlapping it,
   * and its bounce starts from there (within 2%, the approach speed taken
   * without the gravity of the step after the impact) */
  assert_true (bounce < 1e-12);
  assert_true (plain < 0.02);
  assert_true (bounce < plain);
}

/* A box resting on a box with a small overlap, and a tilted box touching a
 * box with one corner: both narrow phases find the contact, with the normal
 * along y and the depth of the overlap. */
static void find_contact (carom_narrow_phase method, double angle, double y, double want_depth)
{
  carom_world_def def = make_def (0.0, 0.0);
  carom_world *w;
  carom_body_id a, b, ca, cb;
  double nx, ny, depth;
  def.narrow_phase = method;
  w = make_world (&def);
  a = add_box (w, CAROM_STATIC, 0.0, 0.0, 0.0, 2.0, 1.0);
  b = add_box (w, CAROM_DYNAMIC, 0.1, y, angle, 1.0, 1.0);
  assert_status (carom_world_detect (w), CAROM_OK);
  assert_true (carom_world_contact_count (w) >= 1);
  assert_status (carom_world_get_contact (w, 0, &ca, &cb, NULL, NULL, &nx, &ny, &depth), CAROM_OK);
  assert_true ((ca == a && cb == b) || (ca == b && cb == a));
  assert_near_abs (fabs (ny), 1.0, 1e-9);
  assert_near_abs (nx, 0.0, 1e-9);
  assert_near_abs (max_depth (w), want_depth, 1e-9);
  carom_world_destroy (w);
}

static void test_sat_and_vertex_edge_both_find_contact (void **state)
{
  const double corner = 0.5 * sqrt (2.0); /* half-diagonal of the unit box */
  (void) state;
  find_contact (CAROM_NARROW_SAT, 0.0, 0.98, 0.02);
  find_contact (CAROM_NARROW_VERTEX_EDGE, 0.0, 0.98, 0.02);
  find_contact (CAROM_NARROW_SAT, M_PI / 4.0, 0.5 + corner - 0.03, 0.03);
  find_contact (CAROM_NARROW_VERTEX_EDGE, M_PI / 4.0, 0.5 + corner - 0.03, 0.03);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_more_substeps_less_penetration),
    cmocka_unit_test (test_more_iterations_less_penetration),
    cmocka_unit_test (test_more_position_correction_less_overlap),
    cmocka_unit_test (test_smaller_dt_smaller_error),
    cmocka_unit_test (test_sat_and_vertex_edge_both_find_contact),
  };
  return cmocka_run_group_tests (tests, NULL, NULL);
}
