/* Bodies: exact mass properties (thesis 3.1), bad input, stale ids. */
#include "support.h"

#include <math.h>
#include <string.h>

#include "vec2.h"

/* ---- inertia against closed forms computed here, independently ---- */

typedef struct rect {
  double x0, y0, x1, y1;
} rect;

/* Polar moment of a union of disjoint rectangles about its centroid, by
 * eq. 3.4 for each and the parallel-axis theorem. Density 1. */
static double rects_inertia (const rect *r, int n, double *area_out)
{
  double area = 0, cx = 0, cy = 0, inertia = 0;
  int i;
  for (i = 0; i < n; ++i)
    {
      double w = r[i].x1 - r[i].x0, h = r[i].y1 - r[i].y0, a = w * h;
      area += a;
      cx += a * 0.5 * (r[i].x0 + r[i].x1);
      cy += a * 0.5 * (r[i].y0 + r[i].y1);
    }
  cx /= area;
  cy /= area;
  for (i = 0; i < n; ++i)
    {
      double w = r[i].x1 - r[i].x0, h = r[i].y1 - r[i].y0, a = w * h;
      double dx = 0.5 * (r[i].x0 + r[i].x1) - cx, dy = 0.5 * (r[i].y0 + r[i].y1) - cy;
      inertia += a * (w * w + h * h) / 12.0 + a * (dx * dx + dy * dy);
    }
  *area_out = area;
  return inertia;
}

static carom_body_id add_poly (carom_world *w, const double *xy, int n)
{
  carom_body_id id = 0;
  assert_status (carom_world_add_polygon (w, NULL, xy, n, &id), CAROM_OK);
  return id;
}

static void check_inertia (carom_world *w, carom_body_id id, double want_i, double want_area)
{
  double m, inertia, area;
  assert_status (carom_body_get_mass (w, id, &m, &inertia, &area), CAROM_OK);
  assert_near_rel (area, want_area, 1e-12);
  assert_near_rel (m, want_area, 1e-12); /* density 1 */
  assert_near_rel (inertia, want_i, 1e-12);
}

static void test_l_shape_inertia (void **state)
{
  carom_world *w = *state;
  const double l[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 3, 0, 3};
  const rect parts[] = {{0, 0, 2, 1}, {0, 1, 1, 3}};
  double area, want = rects_inertia (parts, 2, &area);
  check_inertia (w, add_poly (w, l, 6), want, area);
}

/* The U's centroid lies in its notch, outside the polygon: signed
 * sub-triangles must still give the right answer. */
static void test_u_shape_inertia (void **state)
{
  carom_world *w = *state;
  const double u[] = {0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3};
  const rect parts[] = {{0, 0, 3, 1}, {0, 1, 1, 3}, {2, 1, 3, 3}};
  double area, want = rects_inertia (parts, 3, &area), x, y;
  carom_body_id id = add_poly (w, u, 8);
  check_inertia (w, id, want, area);
  /* the body sits at the centroid given by the caller: (0, 0) */
  assert_status (carom_body_get_position (w, id, &x, &y), CAROM_OK);
  assert_true (x == 0.0 && y == 0.0);
}

static void test_c_shape_inertia (void **state)
{
  carom_world *w = *state;
  const double c[] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 2, 4, 2, 4, 3, 0, 3};
  const rect parts[] = {{0, 0, 4, 1}, {0, 1, 1, 2}, {0, 2, 4, 3}};
  double area, want = rects_inertia (parts, 3, &area);
  check_inertia (w, add_poly (w, c, 8), want, area);
}

static void test_box_formula_matches_polygon_sum (void **state)
{
  carom_world *w = *state;
  const double wdt = 3.7, hgt = 0.45;
  const double xy[] = {-wdt / 2, -hgt / 2, wdt / 2, -hgt / 2, wdt / 2, hgt / 2, -wdt / 2, hgt / 2};
  carom_body_id box, poly;
  double mb, ib, mp, ip;
  assert_status (carom_world_add_box (w, NULL, wdt, hgt, &box), CAROM_OK);
  poly = add_poly (w, xy, 4);
  carom_body_get_mass (w, box, &mb, &ib, NULL);
  carom_body_get_mass (w, poly, &mp, &ip, NULL);
  assert_near_rel (ib, mb * (wdt * wdt + hgt * hgt) / 12.0, 1e-12); /* eq. 3.4 */
  assert_near_rel (ib, ip, 1e-12);
  assert_near_rel (mb, mp, 1e-12);
}

static void test_regular_formula_matches_polygon_sum (void **state)
{
  carom_world *w = *state;
  int n;
  for (n = 3; n <= 64; n = n < 8 ? n + 1 : n * 2)
    {
      const double side = 0.8;
      double xy[2 * 64], mr, ir, mp, ip, radius = side / (2 * sin (M_PI / n));
      double cot = 1.0 / tan (M_PI / n);
      carom_body_id reg, poly;
      int i;
      for (i = 0; i < n; ++i)
        {
          xy[2 * i] = radius * cos (2 * M_PI * i / n);
          xy[2 * i + 1] = radius * sin (2 * M_PI * i / n);
        }
      assert_status (carom_world_add_regular (w, NULL, n, side, &reg), CAROM_OK);
      poly = add_poly (w, xy, n);
      carom_body_get_mass (w, reg, &mr, &ir, NULL);
      carom_body_get_mass (w, poly, &mp, &ip, NULL);
      assert_near_rel (ir, mr * side * side / 24.0 * (1 + 3 * cot * cot), 1e-12); /* eq. 3.6 */
      assert_near_rel (ir, ip, 1e-12);
      assert_near_rel (mr, mp, 1e-12);
    }
}

static void test_inertia_independent_of_winding_and_translation (void **state)
{
  carom_world *w = *state;
  const double u[] = {0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3};
  double rev[16], moved[16], i0, i1, i2, m0, m1, m2;
  int k;
  for (k = 0; k < 8; ++k)
    {
      rev[2 * k] = u[2 * (7 - k)];
      rev[2 * k + 1] = u[2 * (7 - k) + 1];
      moved[2 * k] = u[2 * k] + 1000.0;
      moved[2 * k + 1] = u[2 * k + 1] - 1000.0;
    }
  carom_body_get_mass (w, add_poly (w, u, 8), &m0, &i0, NULL);
  carom_body_get_mass (w, add_poly (w, rev, 8), &m1, &i1, NULL);
  carom_body_get_mass (w, add_poly (w, moved, 8), &m2, &i2, NULL);
  assert_near_rel (i0, i1, 1e-12);
  assert_near_rel (m0, m1, 1e-12);
  assert_near_rel (i0, i2, 1e-12);
  assert_near_rel (m0, m2, 1e-12);
}

static void test_circle_inertia_and_vertices (void **state)
{
  carom_world *w = *state;
  carom_body_id c, b;
  carom_body_def def;
  double m, inertia, xy[8];
  int32_t count = -1;
  assert_status (carom_world_add_circle (w, NULL, 0.5, &c), CAROM_OK);
  carom_body_get_mass (w, c, &m, &inertia, NULL);
  assert_near_rel (m, M_PI * 0.25, 1e-15);
  assert_near_rel (inertia, 0.5 * m * 0.25, 1e-15);
  assert_status (carom_body_get_vertices (w, c, xy, 4, &count), CAROM_OK);
  assert_int_equal (count, 0);
  carom_body_def_init (&def, sizeof def);
  def.x = 10, def.y = 20, def.angle = M_PI / 2;
  assert_status (carom_world_add_box (w, &def, 2, 1, &b), CAROM_OK);
  assert_status (carom_body_get_vertices (w, b, xy, 4, &count), CAROM_OK);
  assert_int_equal (count, 4);
  /* (-1, -0.5) rotated a quarter turn is (0.5, -1) */
  assert_near_abs (xy[0], 10.5, 1e-12);
  assert_near_abs (xy[1], 19.0, 1e-12);
}

static void test_static_body_has_no_inverse_infinity (void **state)
{
  carom_world *w = *state;
  carom_body_def def;
  carom_body_id id;
  double m = -1, inertia = -1;
  carom_body_def_init (&def, sizeof def);
  def.type = CAROM_STATIC;
  assert_status (carom_world_add_box (w, &def, 10, 1, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  assert_true (m == 0.0 && inertia == 0.0);
  assert_status (carom_body_set_velocity (w, id, 1, 0), CAROM_ERR_STATIC_BODY);
  assert_status (carom_world_update (w, 0.01), CAROM_OK);
}

/* ---- bad input: a specific status, nothing created ---- */

static void expect_polygon_error (carom_world *w, const double *xy, int n, carom_status want)
{
  carom_body_id id = 12345;
  int32_t before = carom_world_body_count (w);
  assert_status (carom_world_add_polygon (w, NULL, xy, n, &id), want);
  assert_int_equal (carom_world_body_count (w), before);
  assert_true (id == 12345); /* untouched */
}

static void test_bad_polygons (void **state)
{
  carom_world *w = *state;
  const double two[] = {0, 0, 1, 0};
  const double nan_xy[] = {0, 0, 1, 0, NAN, 1};
  const double inf_xy[] = {0, 0, 1, 0, 0, INFINITY};
  const double repeated[] = {0, 0, 1, 0, 1, 0, 0, 1};
  const double closing_repeat[] = {0, 0, 1, 0, 0, 1, 0, 0};
  const double bowtie[] = {0, 0, 1, 1, 1, 0, 0, 1};
  const double collinear[] = {0, 0, 1, 0, 2, 0};
  const double spike[] = {0, 0, 2, 0, 1, 0, 1, 1};
  const double touching[] = {0, 0, 4, 0, 4, 4, 2, 0.0, 0, 4};
  static double many[2 * (CAROM_MAX_POLYGON_VERTICES + 1)];
  expect_polygon_error (w, two, 2, CAROM_ERR_TOO_FEW_VERTICES);
  expect_polygon_error (w, nan_xy, 3, CAROM_ERR_NOT_FINITE);
  expect_polygon_error (w, inf_xy, 3, CAROM_ERR_NOT_FINITE);
  expect_polygon_error (w, repeated, 4, CAROM_ERR_REPEATED_VERTEX);
  expect_polygon_error (w, closing_repeat, 4, CAROM_ERR_REPEATED_VERTEX);
  expect_polygon_error (w, bowtie, 4, CAROM_ERR_SELF_INTERSECTING);
  expect_polygon_error (w, collinear, 3, CAROM_ERR_ZERO_AREA);
  expect_polygon_error (w, spike, 4, CAROM_ERR_SELF_INTERSECTING);
  expect_polygon_error (w, touching, 5, CAROM_ERR_SELF_INTERSECTING);
  expect_polygon_error (w, many, CAROM_MAX_POLYGON_VERTICES + 1, CAROM_ERR_TOO_MANY_VERTICES);
  expect_polygon_error (w, NULL, 3, CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_add_polygon (NULL, NULL, two, 3, NULL), CAROM_ERR_NULL_ARGUMENT);
}

static void test_bad_shapes_and_defs (void **state)
{
  carom_world *w = *state;
  carom_body_def def;
  assert_status (carom_world_add_circle (w, NULL, 0.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_circle (w, NULL, -1.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_circle (w, NULL, NAN, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_box (w, NULL, 1.0, 0.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_box (w, NULL, INFINITY, 1.0, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_regular (w, NULL, 2, 1.0, NULL), CAROM_ERR_TOO_FEW_VERTICES);
  assert_status (carom_world_add_regular (w, NULL, CAROM_MAX_POLYGON_VERTICES + 1, 1.0, NULL),
                 CAROM_ERR_TOO_MANY_VERTICES);
  assert_status (carom_world_add_regular (w, NULL, 5, -2.0, NULL), CAROM_ERR_BAD_SIZE);
  carom_body_def_init (&def, sizeof def);
  def.density = 0.0;
  assert_status (carom_world_add_circle (w, &def, 1.0, NULL), CAROM_ERR_BAD_DENSITY);
  def.density = -1.0;
  assert_status (carom_world_add_box (w, &def, 1.0, 1.0, NULL), CAROM_ERR_BAD_DENSITY);
  carom_body_def_init (&def, sizeof def);
  def.vx = NAN;
  assert_status (carom_world_add_circle (w, &def, 1.0, NULL), CAROM_ERR_NOT_FINITE);
  carom_body_def_init (&def, sizeof def);
  def.restitution = 1.5;
  assert_status (carom_world_add_circle (w, &def, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  carom_body_def_init (&def, sizeof def);
  def.size = 4;
  assert_status (carom_world_add_circle (w, &def, 1.0, NULL), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_int_equal (carom_world_body_count (w), 0);
}

/* A dynamic body's mass must lie in [1e-200, 1e200]: a U of density 1.5e-309
 * (mass 1e-308, its inverse still finite) once made eq. 3.23's denominator
 * overflow for some points of a contact and not others, and the world turned
 * to NaN. Static bodies have no mass to bound. */
static void test_mass_range (void **state)
{
  static const double u[] = { 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3 }; /* area 7 */
  carom_world *w = *state;
  carom_body_def def;
  carom_body_id id;
  double m;
  carom_body_def_init (&def, sizeof def);
  def.density = 1e-200;
  assert_status (carom_world_add_box (w, &def, 1.0, 1.0, &id), CAROM_OK);
  assert_status (carom_body_get_mass (w, id, &m, NULL, NULL), CAROM_OK);
  assert_true (m == 1e-200);
  def.density = 0.99e-200;
  assert_status (carom_world_add_box (w, &def, 1.0, 1.0, NULL), CAROM_ERR_BAD_DENSITY);
  def.density = 1e200;
  assert_status (carom_world_add_box (w, &def, 1.0, 1.0, NULL), CAROM_OK);
  def.density = 1.01e200;
  assert_status (carom_world_add_box (w, &def, 1.0, 1.0, NULL), CAROM_ERR_BAD_DENSITY);
  def.density = 1.455901395071813e-309;
  assert_status (carom_world_add_polygon (w, &def, u, 8, NULL), CAROM_ERR_BAD_DENSITY);
  assert_int_equal (carom_world_body_count (w), 2);
  def.type = CAROM_STATIC;
  assert_status (carom_world_add_polygon (w, &def, u, 8, NULL), CAROM_OK);
  assert_int_equal (carom_world_body_count (w), 3);
}

static void test_stale_ids (void **state)
{
  carom_world *w = *state;
  carom_body_id a, b, c;
  double x;
  assert_status (carom_world_add_circle (w, NULL, 1.0, &a), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &b), CAROM_OK);
  assert_status (carom_world_remove_body (w, a), CAROM_OK);
  assert_status (carom_world_remove_body (w, a), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_position (w, a, &x, NULL), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_set_velocity (w, a, 1, 1), CAROM_ERR_STALE_BODY);
  /* the freed slot is reused, but the old id stays stale */
  assert_status (carom_world_add_circle (w, NULL, 2.0, &c), CAROM_OK);
  assert_true (c != a);
  assert_status (carom_body_check (w, a), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_check (w, c), CAROM_OK);
  assert_status (carom_body_check (w, b), CAROM_OK);
  assert_status (carom_body_check (w, CAROM_NULL_BODY), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_check (w, 0xffffffffffull), CAROM_ERR_STALE_BODY);
  assert_int_equal (carom_world_body_count (w), 2);
}

static void test_setters_refuse_non_finite (void **state)
{
  carom_world *w = *state;
  carom_body_id id;
  carom_body_def d;
  double x, y;
  uint64_t before;
  assert_status (carom_world_set_gravity (w, 0.0, -10.0), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -0.5;
  assert_status (carom_world_add_box (w, &d, 10.0, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &id), CAROM_OK);
  assert_status (carom_body_set_position (w, id, 1.0, 2.0), CAROM_OK);
  assert_status (carom_body_set_velocity (w, id, 0.5, -1.0), CAROM_OK);
  assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  before = world_state_hash (w);
  assert_status (carom_body_set_position (w, id, NAN, 0.0), CAROM_ERR_NOT_FINITE);
  assert_status (carom_body_set_angle (w, id, INFINITY), CAROM_ERR_NOT_FINITE);
  assert_status (carom_body_set_velocity (w, id, 0.0, -INFINITY), CAROM_ERR_NOT_FINITE);
  assert_status (carom_body_set_velocity (w, id, NAN, 0.0), CAROM_ERR_NOT_FINITE);
  assert_status (carom_body_set_spin (w, id, NAN), CAROM_ERR_NOT_FINITE);
  /* nothing changed: pose, velocities, sleep, contacts, settings */
  assert_true (world_state_hash (w) == before);
  carom_body_get_position (w, id, &x, &y);
  assert_true (isfinite (x) && isfinite (y));
}

/* A body's rotation from its angle (lib/angle.c, not the C library's sin
 * and cos): within 4 units in the last place of libm's over every quadrant
 * and every size of angle it reduces itself (up to 1e6), exact at 0, of
 * unit length to rounding, and the angle set is the angle read back. */
static void test_rotation_of_an_angle (void **state)
{
  static const double spans[] = { 1e-6, 0.5, 3.2, 7.0, 100.0, 1e4, 9.9e5, 3e6 };
  uint64_t x = 0x9E3779B97F4A7C15ull;
  double worst = 0.0;
  size_t i;
  int k;
  (void) state;
  for (i = 0; i < sizeof spans / sizeof spans[0]; ++i)
    for (k = 0; k < 20000; ++k)
      {
        double a, c, s, uc, us, e;
        rot2 q;
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        a = spans[i] * (2.0 * (double) (x >> 11) / 9007199254740992.0 - 1.0);
        q = rot2_from_angle (a);
        c = cos (a), s = sin (a);
        uc = nextafter (fabs (c), INFINITY) - fabs (c);
        us = nextafter (fabs (s), INFINITY) - fabs (s);
        e = fabs (q.c - c) / uc > fabs (q.s - s) / us ? fabs (q.c - c) / uc : fabs (q.s - s) / us;
        if (!(e <= 4.0))
          fail_msg ("angle %.17g: (%.17g, %.17g), libm (%.17g, %.17g): %.1f ulp", a, q.c, q.s, c, s, e);
        worst = e > worst ? e : worst;
        assert_true (fabs (q.c * q.c + q.s * q.s - 1.0) <= 4.5e-16);
      }
  assert_true (rot2_from_angle (0.0).c == 1.0 && rot2_from_angle (0.0).s == 0.0);
  print_message ("rotation of an angle: worst %.2f ulp from libm over %d angles\n", worst,
                 (int) (20000 * (sizeof spans / sizeof spans[0])));
}

/* v2_len_surely_within, which detection asks before it takes a square
 * root (and v2_len_at_most, which then takes it if need be, always the
 * root's answer): whenever it answers, sqrt (d . d) <= r holds (the comparison it
 * stands for decides the same), over lengths from tiny to huge, near the
 * bound on both sides to the last place, where r^2 is subnormal or
 * overflows, and for infinities, NaNs and a negative r; and it answers
 * for every length clearly below r whose square is a number and not 0, or
 * it would save nothing. */
static void test_length_within_without_a_root (void **state)
{
  static const double scales[] = { 1e-300, 1e-160, 1.5e-154, 1e-150, 1e-8, 1.0, 3.0, 1e8, 1e150, 1.3e154, 1e160 };
  uint64_t x = 0x2545F4914F6CDD1Dull;
  int answered = 0, clear = 0;
  size_t i;
  int k;
  (void) state;
  for (i = 0; i < sizeof scales / sizeof scales[0]; ++i)
    for (k = 0; k < 20000; ++k)
      {
        double r, t, f;
        vec2 d;
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        r = scales[i] * (1.0 + (double) (x >> 11) / 9007199254740992.0);
        t = 2.0 * CAROM_PI * (double) (x & 0xffff) / 65536.0;
        /* the length: a fraction of r, or r itself moved by a few units
         * in its last place either way */
        f = k % 2 ? (double) ((x >> 20) & 0xfff) / 4096.0 : 1.0 + (double) ((int) ((x >> 40) & 15) - 8) * 0x1p-52;
        d = v2 (f * r * cos (t), f * r * sin (t));
        if (v2_len_at_most (d, r) != (sqrt (v2_dot (d, d)) <= r))
          fail_msg ("(%.17g, %.17g) at most %.17g: not the root's answer", d.x, d.y, r);
        if (v2_len_surely_within (d, r))
          {
            ++answered;
            if (!(sqrt (v2_dot (d, d)) <= r))
              fail_msg ("(%.17g, %.17g) within %.17g without a root, %.17g with it", d.x, d.y, r, v2_len (d));
          }
        else if (k % 2 && f < 0.99 && r * r * 0.99 > 0.0 && isfinite (v2_dot (d, d)))
          fail_msg ("(%.17g, %.17g) clearly within %.17g, not answered", d.x, d.y, r);
        clear += k % 2 && f < 0.99;
      }
  assert_false (v2_len_surely_within (v2 (NAN, 0.0), 1.0));
  assert_false (v2_len_surely_within (v2 (INFINITY, 0.0), 1e200));
  assert_false (v2_len_surely_within (v2 (0.0, 0.0), NAN));
  assert_false (v2_len_surely_within (v2 (0.0, 0.0), 0.0));
  assert_false (v2_len_surely_within (v2 (1.0, 0.0), 1.0));
  assert_false (v2_len_surely_within (v2 (0.0, 0.0), -1.0));
  print_message ("length within without a root: answered %d of %d lengths, %d of them clearly within\n", answered,
                 (int) (20000 * (sizeof scales / sizeof scales[0])), clear);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test_setup_teardown (test_l_shape_inertia, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_u_shape_inertia, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_c_shape_inertia, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_box_formula_matches_polygon_sum, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_regular_formula_matches_polygon_sum, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_inertia_independent_of_winding_and_translation, world_setup,
                                     world_teardown),
    cmocka_unit_test_setup_teardown (test_circle_inertia_and_vertices, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_static_body_has_no_inverse_infinity, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_bad_polygons, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_bad_shapes_and_defs, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_mass_range, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_stale_ids, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_setters_refuse_non_finite, world_setup, world_teardown),
    cmocka_unit_test (test_rotation_of_an_angle),
    cmocka_unit_test (test_length_within_without_a_root),
  };
  return cmocka_run_group_tests_name ("body", tests, NULL, NULL);
}
