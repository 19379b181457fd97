/* Bad input that tests/test_body.c, test_world.c, test_scene.c and
 * test_stability.c do not already cover (docs/reliability.md has the whole
 * table). Every refused call must return its status and change nothing;
 * every accepted call must leave the world valid: finite state, positive
 * finite mass and inertia for dynamic bodies, and finite after stepping.
 *
 * The table-driven tests try every case and then report all that failed, so
 * one failure does not hide the next. */
#include "support.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define DENORM_MIN 4.9406564584124654e-324

/* Failures of a table-driven test: each is printed when found, and the test
 * fails at its end with the count. */
typedef struct failures {
  int count;
} failures;

static void note (failures *f, const char *fmt, ...)
{
  char line[512];
  va_list ap;
  f->count++;
  va_start (ap, fmt);
  vsnprintf (line, sizeof line, fmt, ap);
  va_end (ap);
  print_message ("  FAILED CASE: %s\n", line);
}

static void report (const failures *f, const char *what)
{
  if (f->count > 0)
    fail_msg ("%d %s failed (listed above)", f->count, what);
}

/* ------------------------------------------------------------ validity */

/* Empty string if the body is valid, else what is wrong. */
static const char *body_problem (const carom_world *w, carom_body_id id)
{
  static char why[256];
  double x, y, a, vx, vy, s, m, inertia, area;
  carom_body_type type;
  why[0] = '\0';
  if (carom_body_get_position (w, id, &x, &y) != CAROM_OK || carom_body_get_angle (w, id, &a) != CAROM_OK
      || carom_body_get_velocity (w, id, &vx, &vy) != CAROM_OK || carom_body_get_spin (w, id, &s) != CAROM_OK
      || carom_body_get_mass (w, id, &m, &inertia, &area) != CAROM_OK || carom_body_get_type (w, id, &type) != CAROM_OK)
    return "a getter failed";
  if (!(isfinite (x) && isfinite (y) && isfinite (a) && isfinite (vx) && isfinite (vy) && isfinite (s)))
    snprintf (why, sizeof why, "state not finite: p (%g, %g) angle %g v (%g, %g) spin %g", x, y, a, vx, vy, s);
  else if (!(isfinite (m) && isfinite (inertia) && isfinite (area) && area > 0.0))
    snprintf (why, sizeof why, "mass %g inertia %g area %g", m, inertia, area);
  else if (type == CAROM_DYNAMIC && !(m > 0.0 && inertia > 0.0))
    snprintf (why, sizeof why, "dynamic body with mass %g inertia %g area %g", m, inertia, area);
  return why;
}

/* Empty string if every body is valid. */
static const char *world_problem (const carom_world *w)
{
  carom_body_id ids[64];
  int32_t n = carom_world_get_bodies (w, ids, 64), i;
  for (i = 0; i < n && i < 64; ++i)
    {
      const char *why = body_problem (w, ids[i]);
      if (why[0])
        return why;
    }
  return "";
}

static carom_world *new_world (double gy)
{
  carom_world *w = NULL;
  carom_world_def def;
  assert_status (carom_world_def_init (&def, sizeof def), CAROM_OK);
  def.gravity_y = gy;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  return w;
}

static void add_ground (carom_world *w, double y, double width, double height)
{
  carom_body_def d;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = CAROM_STATIC;
  d.y = y;
  assert_status (carom_world_add_box (w, &d, width, height, NULL), CAROM_OK);
}

/* ------------------------------------------------------- NULL pointers */

static void test_null_world_everywhere (void **state)
{
  carom_body_def d;
  const double tri[] = { 0, 0, 1, 0, 0, 1 };
  double x = 1.0, y = 2.0;
  carom_body_id id = 55;
  int32_t n = 7, awake = 3;
  carom_body_type type;
  carom_shape_kind kind;
  (void) state;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  assert_status (carom_world_add_circle (NULL, &d, 1.0, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_add_box (NULL, &d, 1.0, 1.0, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_add_regular (NULL, &d, 5, 1.0, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_add_polygon (NULL, &d, tri, 3, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_true (id == 55);
  assert_status (carom_world_remove_body (NULL, 1), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_check (NULL, 1), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_detect (NULL), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_update (NULL, 0.1), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_set_gravity (NULL, 0, 0), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_get_gravity (NULL, &x, &y), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_get_contact (NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL),
                 CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_position (NULL, 1, &x, &y), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_set_position (NULL, 1, 0, 0), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_angle (NULL, 1, &x), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_set_angle (NULL, 1, 0), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_velocity (NULL, 1, &x, &y), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_set_velocity (NULL, 1, 0, 0), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_spin (NULL, 1, &x), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_set_spin (NULL, 1, 0), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_mass (NULL, 1, &x, &y, NULL), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_type (NULL, 1, &type), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_shape (NULL, 1, &kind, &x), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_material (NULL, 1, &x, &y), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_vertices (NULL, 1, NULL, 0, &n), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_set_restitution (NULL, 0.5), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_set_friction (NULL, 0.5), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_set_central_gravity (NULL, 0, 0, 1, 0), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_set_damping (NULL, 0.1, 0.1), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_set_sleeping (NULL, 1), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_is_awake (NULL, 1, &awake), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_wake (NULL, 1), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_set_fixed_rotation (NULL, 1, 1), CAROM_ERR_NULL_ARGUMENT);
  assert_true (x == 1.0 && y == 2.0 && n == 7 && awake == 3); /* outputs untouched */
  assert_int_equal (carom_world_body_count (NULL), 0);
  assert_int_equal (carom_world_get_bodies (NULL, &id, 1), 0);
  assert_int_equal (carom_world_contact_count (NULL), 0);
  assert_int_equal (carom_world_get_effects (NULL), 0);
  assert_status (carom_body_def_init (NULL, sizeof d), CAROM_ERR_NULL_ARGUMENT);
}

/* NULL outputs are skipped; NULL id pointers on add are allowed. */
static void test_null_outputs_are_skipped (void **state)
{
  carom_world *w = *state;
  carom_body_id id;
  assert_status (carom_world_add_circle (w, NULL, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_add_box (w, NULL, 1.0, 2.0, &id), CAROM_OK);
  assert_status (carom_body_get_position (w, id, NULL, NULL), CAROM_OK);
  assert_status (carom_body_get_velocity (w, id, NULL, NULL), CAROM_OK);
  assert_status (carom_body_get_mass (w, id, NULL, NULL, NULL), CAROM_OK);
  assert_status (carom_body_get_shape (w, id, NULL, NULL), CAROM_OK);
  assert_status (carom_body_get_material (w, id, NULL, NULL), CAROM_OK);
  assert_status (carom_body_get_vertices (w, id, NULL, 4, NULL), CAROM_OK);
  assert_status (carom_world_get_gravity (w, NULL, NULL), CAROM_OK);
  assert_status (carom_world_detect (w), CAROM_OK);
  assert_true (carom_world_contact_count (w) > 0); /* both at the origin */
  assert_status (carom_world_get_contact (w, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL), CAROM_OK);
  assert_int_equal (carom_world_body_count (w), 2);
}

/* ------------------------------------------------- NaN and infinities */

/* Every field of the body def, one at a time, NaN, +inf and -inf. */
static void test_body_def_every_field_not_finite (void **state)
{
  carom_world *w = *state;
  const double bad[] = { NAN, INFINITY, -INFINITY };
  carom_body_def d;
  failures f;
  size_t field, k;
  memset (&f, 0, sizeof f);
  for (field = 0; field < 9; ++field)
    for (k = 0; k < 3; ++k)
      {
        carom_body_id id = 9;
        carom_status s;
        assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
        switch (field)
          {
          case 0: d.x = bad[k]; break;
          case 1: d.y = bad[k]; break;
          case 2: d.angle = bad[k]; break;
          case 3: d.vx = bad[k]; break;
          case 4: d.vy = bad[k]; break;
          case 5: d.spin = bad[k]; break;
          case 6: d.density = bad[k]; break;
          case 7: d.restitution = bad[k]; break;
          default: d.friction = bad[k]; break;
          }
        s = carom_world_add_regular (w, &d, 6, 1.0, &id);
        if (s != CAROM_ERR_NOT_FINITE || id != 9)
          note (&f, "field %zu = %g: status %d, id %s", field, bad[k], (int) s, id == 9 ? "untouched" : "written");
      }
  assert_int_equal (carom_world_body_count (w), 0);
  report (&f, "non-finite body def fields");
}

/* Every double of the world def, one at a time. */
static void test_world_def_every_field_not_finite (void **state)
{
  const double bad[] = { NAN, INFINITY, -INFINITY };
  carom_world_def d;
  failures f;
  size_t field, k;
  (void) state;
  memset (&f, 0, sizeof f);
  for (field = 0; field < 6; ++field)
    for (k = 0; k < 3; ++k)
      {
        carom_world *w = (carom_world *) &f;
        carom_status s;
        assert_status (carom_world_def_init (&d, sizeof d), CAROM_OK);
        switch (field)
          {
          case 0: d.gravity_x = bad[k]; break;
          case 1: d.gravity_y = bad[k]; break;
          case 2: d.restitution = bad[k]; break;
          case 3: d.friction = bad[k]; break;
          case 4: d.position_correction = bad[k]; break;
          default: d.slop = bad[k]; break;
          }
        s = carom_world_init (&w, &d);
        if (s != CAROM_ERR_NOT_FINITE || w != NULL)
          note (&f, "field %zu = %g: status %d", field, bad[k], (int) s);
        if (s == CAROM_OK)
          carom_world_destroy (w);
      }
  report (&f, "non-finite world def fields");
}

/* Sizes and coordinates that are not finite, for each kind of body. */
static void test_shapes_not_finite (void **state)
{
  carom_world *w = *state;
  const double tri_ninf[] = { 0, 0, 1, 0, -INFINITY, 1 };
  assert_status (carom_world_add_circle (w, NULL, INFINITY, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_circle (w, NULL, -INFINITY, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_box (w, NULL, 1.0, NAN, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_box (w, NULL, -INFINITY, 1.0, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_regular (w, NULL, 5, NAN, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_regular (w, NULL, 5, INFINITY, NULL), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_add_polygon (w, NULL, tri_ninf, 3, NULL), CAROM_ERR_NOT_FINITE);
  assert_int_equal (carom_world_body_count (w), 0);
}

/* The effect setters refuse NaN and infinities and keep their settings. */
static void test_effect_setters_not_finite_and_negative (void **state)
{
  carom_world *w = *state;
  uint32_t before = carom_world_get_effects (w);
  assert_status (carom_world_set_restitution (w, NAN), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_restitution (w, -0.1), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_restitution (w, 1.0000001), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_friction (w, INFINITY), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_friction (w, -1e-300), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_central_gravity (w, NAN, 0, 1, 0), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_central_gravity (w, 0, 0, INFINITY, 0), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_central_gravity (w, 0, 0, 1, -INFINITY), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_central_gravity (w, 0, 0, -1, 0), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_central_gravity (w, 0, 0, 1, -1), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_damping (w, NAN, 0), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_damping (w, 0, -INFINITY), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_damping (w, -0.5, 0), CAROM_ERR_BAD_ARGUMENT);
  assert_int_equal (carom_world_get_effects (w), before);
  assert_int_equal (before, CAROM_EFFECT_CONTINUOUS); /* the one effect on by default */
}

/* --------------------------------------------------- sizes and density */

static void test_zero_negative_and_signed_zero_sizes (void **state)
{
  carom_world *w = *state;
  carom_body_def d;
  assert_status (carom_world_add_circle (w, NULL, -0.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_circle (w, NULL, -DBL_MAX, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_box (w, NULL, -0.0, 1.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_box (w, NULL, -1.0, -1.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_world_add_regular (w, NULL, 3, 0.0, NULL), CAROM_ERR_BAD_SIZE);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.density = -0.0;
  assert_status (carom_world_add_circle (w, &d, 1.0, NULL), CAROM_ERR_BAD_DENSITY);
  d.density = -DENORM_MIN;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_ERR_BAD_DENSITY);
  assert_int_equal (carom_world_body_count (w), 0);
}

/* Sizes and densities at the ends of the doubles. Each must be refused with
 * a status the header documents for that call (BAD_SIZE, NOT_FINITE,
 * BAD_DENSITY; for polygons also ZERO_AREA and REPEATED_VERTEX) and create
 * nothing, or be accepted as a valid body that stays finite over a few
 * steps on a ground. */
typedef struct extreme_case {
  const char *name;
  int kind; /* 0 circle, 1 box, 2 regular, 3 U polygon */
  double a, b, density;
  int32_t n;
} extreme_case;

static const extreme_case extreme_cases[] = {
  { "circle r = 1e-100", 0, 1e-100, 0, 1, 0 },
  { "circle r = 1e-300", 0, 1e-300, 0, 1, 0 },
  { "circle r = 5e-324 (denormal)", 0, DENORM_MIN, 0, 1, 0 },
  { "circle r = 1e155", 0, 1e155, 0, 1, 0 },
  { "circle r = 1e300", 0, 1e300, 0, 1, 0 },
  { "box 1e-160 x 1e-160", 1, 1e-160, 1e-160, 1, 0 },
  { "box 1e-300 x 1e-300", 1, 1e-300, 1e-300, 1, 0 },
  { "box 1e150 x 1e150", 1, 1e150, 1e150, 1, 0 },
  { "box 1e200 x 1e200", 1, 1e200, 1e200, 1, 0 },
  { "box 1e300 x 1e-300 (area 1)", 1, 1e300, 1e-300, 1, 0 },
  { "box 1 x 1e-13 (a thin plate)", 1, 1.0, 1e-13, 1, 0 },
  { "regular 5, side 1e-120", 2, 1e-120, 0, 1, 5 },
  { "regular 5, side 1e200", 2, 1e200, 0, 1, 5 },
  { "regular 1024, side 1e-100", 2, 1e-100, 0, 1, 1024 },
  { "U polygon scaled 1e-160", 3, 1e-160, 0, 1, 8 },
  { "U polygon scaled 1e150", 3, 1e150, 0, 1, 8 },
  { "box 1 x 1, density 1e300, then 1e10 x 1e10", 1, 1e10, 1e10, 1e300, 0 },
  { "box 1e-10 x 1e-10, density 1e-300", 1, 1e-10, 1e-10, 1e-300, 0 },
  { "circle r = 1, density 5e-324", 0, 1.0, 0, DENORM_MIN, 0 },
  { "circle r = 1, density DBL_MAX", 0, 1.0, 0, DBL_MAX, 0 },
};

static void test_extreme_sizes_and_densities (void **state)
{
  static const double u[] = { 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3 };
  failures f;
  size_t k;
  (void) state;
  memset (&f, 0, sizeof f);
  for (k = 0; k < sizeof extreme_cases / sizeof extreme_cases[0]; ++k)
    {
      const extreme_case *c = &extreme_cases[k];
      carom_world *w = new_world (-9.81);
      carom_body_def d;
      carom_body_id id = 31;
      carom_status s;
      double xy[16];
      int i, allowed;
      add_ground (w, -0.5, 1e3, 1.0);
      assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
      d.density = c->density;
      d.y = c->kind == 0 ? c->a : c->kind == 1 ? 0.5 * c->b : 1.0;
      if (!isfinite (d.y) || d.y > 1e100)
        d.y = 1.0;
      switch (c->kind)
        {
        case 0: s = carom_world_add_circle (w, &d, c->a, &id); break;
        case 1: s = carom_world_add_box (w, &d, c->a, c->b, &id); break;
        case 2: s = carom_world_add_regular (w, &d, c->n, c->a, &id); break;
        default:
          for (i = 0; i < 16; ++i)
            xy[i] = u[i] * c->a;
          s = carom_world_add_polygon (w, &d, xy, 8, &id);
          break;
        }
      allowed = s == CAROM_ERR_BAD_SIZE || s == CAROM_ERR_NOT_FINITE || s == CAROM_ERR_BAD_DENSITY
                || (c->kind == 3 && (s == CAROM_ERR_ZERO_AREA || s == CAROM_ERR_REPEATED_VERTEX));
      if (s != CAROM_OK)
        {
          if (!allowed)
            note (&f, "%s: refused with %d (%s), not a status documented for this call", c->name, (int) s,
                  carom_status_string (s));
          if (id != 31 || carom_world_body_count (w) != 1)
            note (&f, "%s: refused (%d) but a body was created", c->name, (int) s);
        }
      else
        {
          const char *why = body_problem (w, id);
          if (why[0])
            note (&f, "%s: accepted, but %s", c->name, why);
          else
            {
              for (i = 0; i < 5; ++i)
                carom_world_update (w, 1.0 / 60.0);
              why = world_problem (w);
              if (why[0])
                note (&f, "%s: after 5 steps: %s", c->name, why);
            }
        }
      carom_world_destroy (w);
    }
  report (&f, "extreme sizes and densities");
}

/* ------------------------------------------------------- vertex counts */

static void test_vertex_counts (void **state)
{
  carom_world *w = *state;
  static double xy[2 * (CAROM_MAX_POLYGON_VERTICES + 1)];
  const int32_t few[] = { 2, 1, 0, -1, INT32_MIN };
  size_t k;
  int32_t i, n = -5;
  carom_body_id id;
  for (k = 0; k < sizeof few / sizeof few[0]; ++k)
    {
      assert_status (carom_world_add_polygon (w, NULL, xy, few[k], NULL), CAROM_ERR_TOO_FEW_VERTICES);
      assert_status (carom_world_add_regular (w, NULL, few[k], 1.0, NULL), CAROM_ERR_TOO_FEW_VERTICES);
    }
  assert_status (carom_world_add_polygon (w, NULL, xy, INT32_MAX, NULL), CAROM_ERR_TOO_MANY_VERTICES);
  assert_status (carom_world_add_regular (w, NULL, INT32_MAX, 1.0, NULL), CAROM_ERR_TOO_MANY_VERTICES);
  assert_int_equal (carom_world_body_count (w), 0);
  /* exactly the limit is fine */
  for (i = 0; i < CAROM_MAX_POLYGON_VERTICES; ++i)
    {
      xy[2 * i] = cos (2.0 * M_PI * i / CAROM_MAX_POLYGON_VERTICES);
      xy[2 * i + 1] = sin (2.0 * M_PI * i / CAROM_MAX_POLYGON_VERTICES);
    }
  assert_status (carom_world_add_polygon (w, NULL, xy, CAROM_MAX_POLYGON_VERTICES, &id), CAROM_OK);
  assert_status (carom_body_get_vertices (w, id, NULL, 0, &n), CAROM_OK);
  assert_int_equal (n, CAROM_MAX_POLYGON_VERTICES);
  assert_status (carom_world_add_regular (w, NULL, CAROM_MAX_POLYGON_VERTICES, 0.01, NULL), CAROM_OK);
  assert_string_equal (world_problem (w), "");
}

/* Outlines that are not simple polygons, beyond those of test_body.c. */
static void test_more_self_intersecting_polygons (void **state)
{
  carom_world *w = *state;
  const double pentagram[] = { 0, 1, 0.588, -0.809, -0.951, 0.309, 0.951, 0.309, -0.588, -0.809 };
  /* two squares sharing the vertex (1, 1): a figure eight */
  const double eight[] = { 0, 0, 1, 0, 1, 1, 2, 1, 2, 2, 1, 2, 1, 1, 0, 1 };
  /* a vertex lying on a non-adjacent edge */
  const double on_edge[] = { 0, 0, 4, 0, 4, 2, 2, 0, 0, 2 };
  /* an edge running back over the one before it */
  const double doubled[] = { 0, 0, 2, 0, 2, 1, 2, 0.5, 2, 2, 0, 2 };
  /* a hole-like loop: the outline crosses itself near the end */
  const double loop[] = { 0, 0, 3, 0, 3, 3, 1, 3, 1, 1, 2, 1, 2, 4, 0, 4 };
  carom_body_id id = 5;
  assert_status (carom_world_add_polygon (w, NULL, pentagram, 5, &id), CAROM_ERR_SELF_INTERSECTING);
  assert_status (carom_world_add_polygon (w, NULL, eight, 8, &id), CAROM_ERR_SELF_INTERSECTING);
  assert_status (carom_world_add_polygon (w, NULL, on_edge, 5, &id), CAROM_ERR_SELF_INTERSECTING);
  assert_status (carom_world_add_polygon (w, NULL, doubled, 6, &id), CAROM_ERR_SELF_INTERSECTING);
  assert_status (carom_world_add_polygon (w, NULL, loop, 8, &id), CAROM_ERR_SELF_INTERSECTING);
  assert_true (id == 5);
  assert_int_equal (carom_world_body_count (w), 0);
}

/* -------------------------------------------------------------- ids */

/* After removal every call on the id answers STALE_BODY; ids from another
 * slot generation, beyond the slots, or 0 name nothing. */
static void test_stale_id_everywhere (void **state)
{
  carom_world *w = *state;
  carom_body_id id, other, fresh;
  double x = 3.0;
  int32_t n = 4, awake = 2;
  carom_body_type type;
  carom_shape_kind kind;
  assert_status (carom_world_add_box (w, NULL, 1.0, 1.0, &id), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &other), CAROM_OK);
  assert_status (carom_world_remove_body (w, id), CAROM_OK);
  assert_status (carom_body_get_angle (w, id, &x), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_velocity (w, id, &x, NULL), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_spin (w, id, &x), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_mass (w, id, &x, NULL, NULL), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_type (w, id, &type), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_shape (w, id, &kind, &x), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_material (w, id, &x, NULL), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_vertices (w, id, NULL, 0, &n), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_set_position (w, id, 0, 0), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_set_angle (w, id, 0), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_set_spin (w, id, 0), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_is_awake (w, id, &awake), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_wake (w, id), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_set_fixed_rotation (w, id, 1), CAROM_ERR_STALE_BODY);
  assert_true (x == 3.0 && n == 4 && awake == 2);
  /* the slot is reused with a new generation */
  assert_status (carom_world_add_box (w, NULL, 1.0, 1.0, &fresh), CAROM_OK);
  assert_true ((fresh & 0xffffffffu) == (id & 0xffffffffu) && fresh != id);
  assert_status (carom_body_check (w, id), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_check (w, id + ((uint64_t) 1 << 33)), CAROM_ERR_STALE_BODY); /* a later generation */
  assert_status (carom_body_check (w, (fresh & 0xffffffff00000000u) | 3u), CAROM_ERR_STALE_BODY); /* no slot 3 */
  assert_status (carom_body_check (w, 0xffffffffu), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_check (w, UINT64_MAX), CAROM_ERR_STALE_BODY);
  assert_status (carom_world_remove_body (w, CAROM_NULL_BODY), CAROM_ERR_STALE_BODY);
  assert_int_equal (carom_world_body_count (w), 2);
  assert_status (carom_body_check (w, other), CAROM_OK);
}

/* -------------------------------------------------------- time steps */

/* A box resting on the ground, slightly overlapping it, and a ball
 * falling towards it within the contact margin. */
static carom_world *resting_scene (carom_body_id *ball)
{
  carom_world *w = new_world (-9.81);
  carom_body_def d;
  add_ground (w, -0.5, 20.0, 1.0);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.y = 0.45;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_OK);
  d.y = 1.2, d.vy = -3.0;
  assert_status (carom_world_add_circle (w, &d, 0.2, ball), CAROM_OK);
  return w;
}

static void test_bad_time_steps_and_tiny_valid_ones (void **state)
{
  /* include/carom.h: 1e-100 <= dt <= 1e100 */
  const double bad[] = { -0.0, -DENORM_MIN, -DBL_MAX, DENORM_MIN, 1e-300, 9.99e-101, 1.01e100, DBL_MAX };
  const double tiny[] = { 1e-12, 1e-50, 1e-100 };
  carom_body_id ball;
  carom_world *w = resting_scene (&ball);
  double x0, y0, x1, y1;
  size_t k;
  int i;
  failures f;
  (void) state;
  memset (&f, 0, sizeof f);
  carom_body_get_position (w, ball, &x0, &y0);
  for (k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    if (carom_world_update (w, bad[k]) != CAROM_ERR_BAD_TIME_STEP)
      note (&f, "dt = %g was not refused with BAD_TIME_STEP", bad[k]);
  carom_body_get_position (w, ball, &x1, &y1);
  assert_true (x0 == x1 && y0 == y1);
  carom_world_destroy (w);
  /* tiny but valid steps, each on a fresh scene: accepted and finite (the
   * split-impulse bias and the speculative targets divide by the step) */
  for (k = 0; k < sizeof tiny / sizeof tiny[0]; ++k)
    {
      carom_status s;
      w = resting_scene (&ball);
      s = carom_world_update (w, tiny[k]);
      if (s != CAROM_OK)
        note (&f, "dt = %g returned %d", tiny[k], (int) s);
      else if (world_problem (w)[0])
        note (&f, "one step of dt = %g: %s", tiny[k], world_problem (w));
      else
        {
          for (i = 0; i < 10; ++i)
            carom_world_update (w, 1.0 / 60.0);
          if (world_problem (w)[0])
            note (&f, "dt = %g, then 10 steps of 1/60: %s", tiny[k], world_problem (w));
        }
      carom_world_destroy (w);
    }
  report (&f, "time steps");
}

/* ---------------------------------------------------- world settings */

/* Allocators that must never be called: their def is refused. */
static void *unused_alloc (size_t size, void *user)
{
  (void) size, (void) user;
  fail_msg ("the allocator of a refused def was called");
  return NULL;
}

static void unused_free (void *p, size_t size, void *user)
{
  (void) p, (void) size, (void) user;
  fail_msg ("the free of a refused def was called");
}

static void test_world_settings_out_of_range_and_at_the_limits (void **state)
{
  typedef struct setting_case {
    const char *name;
    int field;
    double value;
    carom_status want;
  } setting_case;
  static const setting_case cases[] = {
    { "restitution -0.1", 0, -0.1, CAROM_ERR_BAD_ARGUMENT },
    { "restitution 1.1", 0, 1.1, CAROM_ERR_BAD_ARGUMENT },
    { "restitution 0", 0, 0.0, CAROM_OK },
    { "restitution 1", 0, 1.0, CAROM_OK },
    { "friction -1e-300", 1, -1e-300, CAROM_ERR_BAD_ARGUMENT },
    { "friction 1e300", 1, 1e300, CAROM_OK },
    { "substeps 0", 2, 0, CAROM_ERR_BAD_ARGUMENT },
    { "substeps -1", 2, -1, CAROM_ERR_BAD_ARGUMENT },
    { "substeps INT32_MIN", 2, INT32_MIN, CAROM_ERR_BAD_ARGUMENT },
    { "substeps 1001", 2, 1001, CAROM_ERR_BAD_ARGUMENT },
    { "substeps 1000", 2, 1000, CAROM_OK },
    { "iterations 0", 3, 0, CAROM_ERR_BAD_ARGUMENT },
    { "iterations 1001", 3, 1001, CAROM_ERR_BAD_ARGUMENT },
    { "iterations INT32_MAX", 3, INT32_MAX, CAROM_ERR_BAD_ARGUMENT },
    { "iterations 1000", 3, 1000, CAROM_OK },
    { "position_correction -0.1", 4, -0.1, CAROM_ERR_BAD_ARGUMENT },
    { "position_correction 1.5", 4, 1.5, CAROM_ERR_BAD_ARGUMENT },
    { "position_correction 0", 4, 0.0, CAROM_OK },
    { "position_correction 1", 4, 1.0, CAROM_OK },
    { "slop -0.01", 5, -0.01, CAROM_ERR_BAD_ARGUMENT },
    { "slop 1.01", 5, 1.01, CAROM_ERR_BAD_ARGUMENT },
    { "slop 0", 5, 0.0, CAROM_OK },
    { "slop 1", 5, 1.0, CAROM_OK },
    { "narrow_phase 2", 6, 2, CAROM_ERR_BAD_ARGUMENT },
    { "narrow_phase -1", 6, -1, CAROM_ERR_BAD_ARGUMENT },
    { "allocator: alloc without free", 7, 0, CAROM_ERR_BAD_ARGUMENT },
    { "allocator: free without alloc", 8, 0, CAROM_ERR_BAD_ARGUMENT },
    { "manifold_tolerance -1e-9", 10, -1e-9, CAROM_ERR_BAD_ARGUMENT },
    { "manifold_tolerance 1.01", 10, 1.01, CAROM_ERR_BAD_ARGUMENT },
    { "manifold_tolerance NaN", 10, NAN, CAROM_ERR_NOT_FINITE },
    { "manifold_tolerance inf", 10, INFINITY, CAROM_ERR_NOT_FINITE },
    { "manifold_tolerance 0", 10, 0.0, CAROM_OK },
    { "manifold_tolerance 1", 10, 1.0, CAROM_OK },
    { "size 0", 9, 0, CAROM_ERR_BAD_STRUCT_SIZE },
    { "size of 0.1's struct", 9, offsetof (carom_world_def, allocator) + sizeof (carom_allocator), CAROM_OK },
    { "size of 0.1's struct + 4", 9, offsetof (carom_world_def, allocator) + sizeof (carom_allocator) + 4,
      CAROM_ERR_BAD_STRUCT_SIZE },
    { "size sizeof - 1", 9, sizeof (carom_world_def) - 1, CAROM_ERR_BAD_STRUCT_SIZE },
    { "size sizeof + 8", 9, sizeof (carom_world_def) + 8, CAROM_ERR_BAD_STRUCT_SIZE },
    { "size UINT32_MAX", 9, UINT32_MAX, CAROM_ERR_BAD_STRUCT_SIZE },
  };
  failures f;
  size_t k;
  (void) state;
  memset (&f, 0, sizeof f);
  for (k = 0; k < sizeof cases / sizeof cases[0]; ++k)
    {
      const setting_case *c = &cases[k];
      carom_world_def d;
      carom_world *w = (carom_world *) &f;
      carom_world *scene = (carom_world *) &f;
      carom_status s, s2;
      assert_status (carom_world_def_init (&d, sizeof d), CAROM_OK);
      switch (c->field)
        {
        case 0: d.restitution = c->value; break;
        case 1: d.friction = c->value; break;
        case 2: d.substeps = (int32_t) c->value; break;
        case 3: d.iterations = (int32_t) c->value; break;
        case 4: d.position_correction = c->value; break;
        case 5: d.slop = c->value; break;
        case 6: d.narrow_phase = (carom_narrow_phase) (int32_t) c->value; break;
        case 7: d.allocator.alloc = unused_alloc; break;
        case 8: d.allocator.free = unused_free; break;
        case 10: d.manifold_tolerance = c->value; break;
        default: d.size = (uint32_t) c->value; break;
        }
      s = carom_world_init (&w, &d);
      if (s != c->want || (s != CAROM_OK) != (w == NULL))
        note (&f, "world_init, %s: status %d (%s), wanted %d", c->name, (int) s, carom_status_string (s),
              (int) c->want);
      if (s == CAROM_OK)
        carom_world_destroy (w);
      /* the scene loader takes the same def for what the text does not set */
      s2 = carom_scene_load_text (&scene, "circle 1\n", 9, &d, NULL);
      if (s2 != c->want || (s2 != CAROM_OK) != (scene == NULL))
        note (&f, "scene_load_text with def, %s: status %d, wanted %d", c->name, (int) s2, (int) c->want);
      if (s2 == CAROM_OK)
        carom_world_destroy (scene);
    }
  report (&f, "world settings");
}

/* An allocator given by half is refused (world init and the loader). */
static void test_half_allocators (void **state)
{
  carom_world_def d;
  carom_world *w = NULL;
  (void) state;
  assert_status (carom_world_def_init (&d, sizeof d), CAROM_OK);
  d.allocator.alloc = unused_alloc;
  assert_status (carom_world_init (&w, &d), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_scene_load_text (&w, "circle 1\n", 9, &d, NULL), CAROM_ERR_BAD_ARGUMENT);
  d.allocator.alloc = NULL;
  d.allocator.free = unused_free;
  assert_status (carom_world_init (&w, &d), CAROM_ERR_BAD_ARGUMENT);
  assert_null (w);
}

/* ------------------------------------------------------ struct sizes */

/* A body def with a size this library does not know is refused by every
 * add, and nothing is created. */
static void test_body_def_bad_sizes (void **state)
{
  carom_world *w = *state;
  const double tri[] = { 0, 0, 1, 0, 0, 1 };
  const uint32_t sizes[] = { 0, 4, sizeof (carom_body_def) - 1, sizeof (carom_body_def) + 1,
                             sizeof (carom_body_def) + 64, UINT32_MAX };
  carom_body_def d;
  size_t k;
  for (k = 0; k < sizeof sizes / sizeof sizes[0]; ++k)
    {
      carom_body_id id = 3;
      assert_status (carom_body_def_init (&d, sizes[k]), CAROM_ERR_BAD_STRUCT_SIZE);
      assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
      d.size = sizes[k];
      assert_status (carom_world_add_circle (w, &d, 1.0, &id), CAROM_ERR_BAD_STRUCT_SIZE);
      assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &id), CAROM_ERR_BAD_STRUCT_SIZE);
      assert_status (carom_world_add_regular (w, &d, 5, 1.0, &id), CAROM_ERR_BAD_STRUCT_SIZE);
      assert_status (carom_world_add_polygon (w, &d, tri, 3, &id), CAROM_ERR_BAD_STRUCT_SIZE);
      assert_true (id == 3);
    }
  assert_int_equal (carom_world_body_count (w), 0);
}

/* Enum fields outside their values. */
static void test_bad_enum_values (void **state)
{
  carom_world *w = *state;
  carom_body_def d;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = (carom_body_type) 3;
  assert_status (carom_world_add_circle (w, &d, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  d.type = (carom_body_type) -1;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  assert_int_equal (carom_world_body_count (w), 0);
  assert_non_null (carom_status_string ((carom_status) -1));
  assert_null (carom_effect_name ((carom_effect) 0));
  assert_null (carom_effect_name ((carom_effect) 3)); /* two bits */
  assert_null (carom_effect_name ((carom_effect) (1 << 20)));
}

/* ------------------------------------------------- buffers and indices */

/* get_vertices and get_bodies write no more than `capacity` entries. */
static void test_short_buffers (void **state)
{
  carom_world *w = *state;
  double xy[16];
  carom_body_id ids[4], id;
  int32_t n = -1, i;
  assert_status (carom_world_add_regular (w, NULL, 6, 1.0, &id), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, NULL), CAROM_OK);
  for (i = 0; i < 16; ++i)
    xy[i] = -7.0;
  assert_status (carom_body_get_vertices (w, id, xy, 2, &n), CAROM_OK);
  assert_int_equal (n, 6);
  for (i = 4; i < 16; ++i)
    assert_true (xy[i] == -7.0);
  assert_status (carom_body_get_vertices (w, id, xy, -3, &n), CAROM_OK);
  assert_true (xy[0] != -7.0 && xy[4] == -7.0);
  ids[0] = ids[1] = ids[2] = ids[3] = 77;
  assert_int_equal (carom_world_get_bodies (w, ids, 1), 3);
  assert_true (ids[1] == 77);
  assert_int_equal (carom_world_get_bodies (w, ids, -1), 3);
  assert_true (ids[1] == 77);
}

static void test_contact_index_out_of_range (void **state)
{
  carom_world *w = *state;
  double px = 9.0;
  int32_t n;
  assert_status (carom_world_add_circle (w, NULL, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_detect (w), CAROM_OK);
  n = carom_world_contact_count (w);
  assert_true (n > 0);
  assert_status (carom_world_get_contact (w, -1, NULL, NULL, &px, NULL, NULL, NULL, NULL), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_get_contact (w, n, NULL, NULL, &px, NULL, NULL, NULL, NULL), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_get_contact (w, INT32_MAX, NULL, NULL, &px, NULL, NULL, NULL, NULL),
                 CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_get_contact (w, INT32_MIN, NULL, NULL, &px, NULL, NULL, NULL, NULL),
                 CAROM_ERR_BAD_ARGUMENT);
  assert_true (px == 9.0);
}

/* Two circles with the same centre: the contact normal has no direction to
 * come from, but must still be a finite unit vector. */
static void test_coincident_centres_give_a_unit_normal (void **state)
{
  carom_world *w = *state;
  double nx, ny, depth;
  int32_t i, n;
  assert_status (carom_world_add_circle (w, NULL, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 0.5, NULL), CAROM_OK);
  assert_status (carom_world_add_box (w, NULL, 1.0, 1.0, NULL), CAROM_OK);
  assert_status (carom_world_detect (w), CAROM_OK);
  n = carom_world_contact_count (w);
  assert_true (n > 0);
  for (i = 0; i < n; ++i)
    {
      assert_status (carom_world_get_contact (w, i, NULL, NULL, NULL, NULL, &nx, &ny, &depth), CAROM_OK);
      assert_true (isfinite (depth));
      assert_near_abs (sqrt (nx * nx + ny * ny), 1.0, 1e-9);
    }
  for (i = 0; i < 30; ++i)
    assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
  assert_string_equal (world_problem (w), "");
}

/* ------------------------------------------------- static and fixed */

static void test_static_and_fixed_rotation_rules (void **state)
{
  carom_world *w = *state;
  carom_body_def d;
  carom_body_id wall, ball;
  double spin = 5.0;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = CAROM_STATIC;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &wall), CAROM_OK);
  assert_status (carom_body_set_spin (w, wall, 1.0), CAROM_ERR_STATIC_BODY);
  assert_status (carom_body_set_fixed_rotation (w, wall, 1), CAROM_ERR_STATIC_BODY);
  assert_status (carom_body_set_position (w, wall, 2.0, 0.0), CAROM_OK); /* allowed for statics */
  assert_status (carom_world_add_circle (w, NULL, 0.5, &ball), CAROM_OK);
  assert_status (carom_body_set_spin (w, ball, 3.0), CAROM_OK);
  assert_status (carom_body_set_fixed_rotation (w, ball, 1), CAROM_OK);
  assert_status (carom_body_get_spin (w, ball, &spin), CAROM_OK);
  assert_true (spin == 0.0);
  assert_status (carom_body_set_spin (w, ball, 1.0), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_set_spin (w, ball, 0.0), CAROM_OK);
  assert_status (carom_body_get_spin (w, ball, &spin), CAROM_OK);
  assert_true (spin == 0.0);
}

/* --------------------------------------------------- numeric extremes */

/* At the largest magnitudes include/carom.h accepts (CAROM_MAX_MAGNITUDE,
 * dt up to 1e100): a body far from the origin, fast, spinning fast, under
 * strong gravity. Every state must stay finite. */
typedef struct motion_case {
  const char *name;
  double x, y, vx, vy, spin, gy, dt;
  int steps, pair; /* pair: a second body on the same spot */
} motion_case;

static const motion_case motion_cases[] = {
  { "alone at (1e100, -1e100), gravity -9.81", 1e100, -1e100, 0, 0, 0, -9.81, 1.0 / 60.0, 20, 0 },
  { "velocity 1e100 from the origin, dt 1/60", 0, 0, 1e100, -1e100, 0, 0, 1.0 / 60.0, 20, 0 },
  { "spin 1e100", 0, 0, 0, 0, 1e100, 0, 1.0 / 60.0, 20, 0 },
  { "gravity -1e100 for 20 steps of 1/60", 0, 0, 0, 0, 0, -1e100, 1.0 / 60.0, 20, 0 },
  { "two unit boxes on one spot at (1e100, 0)", 1e100, 0, 0, 0, 0, 0, 1.0 / 60.0, 10, 1 },
  { "two unit boxes on one spot at (1e15, 1e15)", 1e15, 1e15, 0, 0, 0, -9.81, 1.0 / 60.0, 10, 1 },
  { "two boxes on one spot separating at 1e100", 0, 0, 1e100, 0, 0, 0, 1.0 / 60.0, 10, 1 },
  { "two boxes on one spot, spin 1e100", 0, 0, 0, 0, 1e100, 0, 1.0 / 60.0, 10, 1 },
  { "two boxes on one spot, dt 1e-100", 0, 0, 0, 0, 0, -9.81, 1e-100, 5, 1 },
  { "two boxes on one spot, dt 1e100", 0, 0, 0, 0, 0, -9.81, 1e100, 3, 1 },
};

static void test_numeric_extremes_stay_finite (void **state)
{
  failures f;
  size_t k;
  (void) state;
  memset (&f, 0, sizeof f);
  for (k = 0; k < sizeof motion_cases / sizeof motion_cases[0]; ++k)
    {
      const motion_case *c = &motion_cases[k];
      carom_world *w = new_world (c->gy);
      carom_body_def d;
      carom_status s = CAROM_OK;
      int i;
      assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
      d.x = c->x, d.y = c->y, d.vx = c->vx, d.vy = c->vy, d.spin = c->spin;
      assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_OK);
      if (c->pair)
        {
          d.vx = -c->vx, d.vy = -c->vy, d.spin = -c->spin, d.angle = 0.3;
          assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_OK);
        }
      for (i = 0; i < c->steps && s == CAROM_OK; ++i)
        {
          s = carom_world_update (w, c->dt);
          if (s == CAROM_OK && world_problem (w)[0])
            {
              note (&f, "%s: step %d: %s", c->name, i + 1, world_problem (w));
              break;
            }
        }
      if (s != CAROM_OK)
        note (&f, "%s: update returned %d", c->name, (int) s);
      carom_world_destroy (w);
    }
  report (&f, "numeric extremes");
}

/* Beyond CAROM_MAX_MAGNITUDE every call refuses the value with
 * BAD_ARGUMENT and changes nothing. */
static void test_magnitudes_beyond_the_limit_refused (void **state)
{
  carom_world *w = *state;
  carom_world *w2 = NULL;
  carom_world_def wd;
  carom_body_def d;
  carom_body_id id;
  double x, y;
  uint64_t before;
  const double big = 1e101;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.x = big;
  assert_status (carom_world_add_circle (w, &d, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  d.x = 0.0, d.vy = -big;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  d.vy = 0.0, d.spin = big;
  assert_status (carom_world_add_regular (w, &d, 5, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  d.spin = 0.0, d.angle = -1e300;
  assert_status (carom_world_add_circle (w, &d, 1.0, NULL), CAROM_ERR_BAD_ARGUMENT);
  assert_int_equal (carom_world_body_count (w), 0);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &id), CAROM_OK);
  assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  before = world_state_hash (w);
  assert_status (carom_body_set_position (w, id, 0.0, -big), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_set_angle (w, id, DBL_MAX), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_set_velocity (w, id, big, 0.0), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_set_spin (w, id, -big), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_gravity (w, 0.0, -big), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_central_gravity (w, big, 0.0, 1.0, 0.0), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_central_gravity (w, 0.0, 0.0, big, 0.0), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_damping (w, big, 0.0), CAROM_ERR_BAD_ARGUMENT);
  /* every refusal changed nothing at all: bodies, settings, effects */
  assert_true (world_state_hash (w) == before);
  assert_status (carom_body_get_position (w, id, &x, &y), CAROM_OK);
  assert_true (x == 0.0 && y == 0.0);
  assert_status (carom_world_get_gravity (w, &x, &y), CAROM_OK);
  assert_true (x == 0.0 && y == 0.0);
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS); /* the defaults */
  assert_status (carom_world_def_init (&wd, sizeof wd), CAROM_OK);
  wd.gravity_x = -big;
  assert_status (carom_world_init (&w2, &wd), CAROM_ERR_BAD_ARGUMENT);
  assert_null (w2);
}

/* Within the documented limits (CAROM_MAX_MAGNITUDE, sizes from 1e-60):
 * bodies moving so fast that after a step their positions are ~1e94 times
 * their size, where the doubles no longer resolve the contact geometry
 * (lever arms come out as rounding noise ~1e-16 |position|), and a spin so
 * fast that such noise in a lever arm dominates. No state may become NaN.
 * All three are fuzz_world findings, reduced. */
static void add_circle_at (carom_world *w, carom_body_type type, double x, double y, double r, double density)
{
  carom_body_def d;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = type, d.x = x, d.y = y, d.density = density;
  assert_status (carom_world_add_circle (w, &d, r, NULL), CAROM_OK);
}

static void test_huge_speeds_relative_to_size (void **state)
{
  failures f;
  int c, i;
  (void) state;
  memset (&f, 0, sizeof f);
  for (c = 0; c < 4; ++c)
    {
      carom_world *w = NULL;
      carom_world_def wd;
      double dt = 1.0 / 60.0;
      assert_status (carom_world_def_init (&wd, sizeof wd), CAROM_OK);
      wd.substeps = 2;
      wd.iterations = 9;
      if (c == 0)
        {
          /* a circle of radius 1.5e-58 falling at gravity 1e100 past two
           * static circles (vertex-edge narrow phase) */
          wd.gravity_x = 31.0, wd.gravity_y = -1e100;
          wd.narrow_phase = CAROM_NARROW_VERTEX_EDGE;
          assert_status (carom_world_init (&w, &wd), CAROM_OK);
          add_circle_at (w, CAROM_STATIC, 0.0, -0.5, 40.0, 1.0);
          add_circle_at (w, CAROM_STATIC, 0.0, 0.25, 1.0, 1.0);
          add_circle_at (w, CAROM_DYNAMIC, 0.0625, 0.0, 1.537109375e-58, 1.0);
        }
      else if (c == 3)
        {
          /* continuous collision on, gravity 1e100: a regular 31-gon of
           * side 7.8e-52 among two overlapping 38-gons and a 31-gon, a
           * static U. Its speculative lever arms reach 1e150 and its inverse
           * inertia is 3e201: eq. 3.23's denominator overflows (the point is
           * inert) and so did ii (r x n), making the warm start inf * 0 */
          static const double u[] = { 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3 };
          double xy[16];
          carom_body_def d;
          carom_body_id id;
          wd.gravity_x = 2.0, wd.gravity_y = 1e100;
          assert_status (carom_world_init (&w, &wd), CAROM_OK);
          assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
          assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
          d.x = d.y = 1.9375;
          assert_status (carom_world_add_regular (w, &d, 31, 7.7802734374999994e-52, NULL), CAROM_OK);
          d.type = CAROM_STATIC, d.x = d.y = d.angle = 9.875;
          for (i = 0; i < 16; ++i)
            xy[i] = u[i] * 1.9375;
          assert_status (carom_world_add_polygon (w, &d, xy, 8, &id), CAROM_OK);
          d.type = CAROM_DYNAMIC, d.vx = d.vy = d.spin = 9.875;
          assert_status (carom_world_add_regular (w, &d, 38, 9.875, NULL), CAROM_OK);
          assert_status (carom_world_update (w, 1e-12), CAROM_OK);
          assert_status (carom_body_set_angle (w, id, 9.875), CAROM_OK);
          assert_status (carom_world_add_regular (w, &d, 38, 9.875, NULL), CAROM_OK);
          assert_status (carom_world_add_regular (w, &d, 31, 11.0625, NULL), CAROM_OK);
          dt = 0.5;
        }
      else if (c == 2)
        {
          /* five frictionless circles on one spot, one spinning at 1.7e98
           * rad/s (within CAROM_MAX_MAGNITUDE), a static circle beside them:
           * spin cannot act on frictionless circles at all */
          carom_body_def d;
          wd.gravity_x = 0.0625, wd.gravity_y = 3.3125;
          assert_status (carom_world_init (&w, &wd), CAROM_OK);
          assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
          d.x = 4.0, d.y = 4.0, d.spin = 1.7369343990923917e+98;
          assert_status (carom_world_add_circle (w, &d, 16.0, NULL), CAROM_OK);
          add_circle_at (w, CAROM_STATIC, 0.0, 4.0, 1.0, 1.0);
          for (i = 0; i < 4; ++i)
            add_circle_at (w, CAROM_DYNAMIC, 4.0, 4.0, 16.0, 1.0);
        }
      else
        {
          /* overlapping circles on a static square under gravity 1.7e98,
           * sleeping on */
          carom_body_def d;
          wd.gravity_y = 1.7212478966432077e+98;
          assert_status (carom_world_init (&w, &wd), CAROM_OK);
          add_circle_at (w, CAROM_DYNAMIC, 4.0, 4.0, 16.0, 1.0);
          assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
          d.type = CAROM_STATIC, d.y = 4.0;
          assert_status (carom_world_add_regular (w, &d, 4, 40.0, NULL), CAROM_OK);
          add_circle_at (w, CAROM_DYNAMIC, 4.0, 4.0, 16.0, 1.0);
          add_circle_at (w, CAROM_DYNAMIC, 8.0, 8.0, 32.0, 32.0);
          add_circle_at (w, CAROM_DYNAMIC, 8.0, 8.0, 27.0, 32.0);
          add_circle_at (w, CAROM_DYNAMIC, 8.0, 8.0, 32.0, 32.0);
          assert_status (carom_world_set_sleeping (w, 1), CAROM_OK);
          add_circle_at (w, CAROM_STATIC, 9.0, 10.0, 1.0, 1.0);
        }
      for (i = 0; i < 10; ++i)
        {
          assert_status (carom_world_update (w, i < 2 ? 1.0 / 60.0 : dt), CAROM_OK);
          if (world_problem (w)[0])
            {
              note (&f, "case %d, step %d: %s", c, i + 1, world_problem (w));
              break;
            }
        }
      carom_world_destroy (w);
    }
  report (&f, "huge speeds relative to size");
}

/* Central gravity with no softening: a body at the centre feels nothing
 * (r = 0 is skipped), and a body very near it must not get an infinite or
 * NaN velocity. */
static void test_central_gravity_near_the_centre (void **state)
{
  const double offsets[] = { 0.0, 1e-100, 1e-160, 1e-300 };
  failures f;
  size_t k;
  (void) state;
  memset (&f, 0, sizeof f);
  for (k = 0; k < sizeof offsets / sizeof offsets[0]; ++k)
    {
      carom_world *w = new_world (0.0);
      carom_body_def d;
      int i;
      assert_status (carom_world_set_central_gravity (w, 0.0, 0.0, 1.0, 0.0), CAROM_OK);
      assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
      d.x = offsets[k];
      assert_status (carom_world_add_circle (w, &d, 0.1, NULL), CAROM_OK);
      for (i = 0; i < 10; ++i)
        {
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          if (world_problem (w)[0])
            {
              note (&f, "body at x = %g from the centre, step %d: %s", offsets[k], i + 1, world_problem (w));
              break;
            }
        }
      carom_world_destroy (w);
    }
  report (&f, "central gravity near its centre");
}

/* ------------------------------------------------------------ scenes */

/* Scene lines with extreme numbers: refused with a status on their line,
 * or loaded into a valid world that stays finite. */
static void test_scene_extremes (void **state)
{
  static const char *const texts[] = {
    "circle 1e-320\n",
    "circle 1e-100\n",
    "circle 1e200\n",
    "box 1e150 1e150\n",
    "box 1e-160 1e-160\n",
    "regular 5 1e-120\n",
    "polygon 0 0 3e150 0 3e150 3e150 2e150 3e150 2e150 1e150 1e150 1e150 1e150 3e150 0 3e150\n",
    "circle 1 density 1e-320\n",
    "circle 1 at 1e300 1e300 velocity 1e300 0\n",
    "bounds 0 0 1e308 1\n",
    "bounds -1e308 0 1e308 1\n",
    "gravity 0 -1e300\nbounds 0 0 10 10\ncircle 1 at 5 5\n",
    "box 1 1 at 8 3\nregular 8 5 velocity 1e200 5\n",
    "box 1 1 at 8 3\nregular 8 5 velocity 1e150 5\n",
    "central 0 0 1 0\ncircle 0.1 at 1e-160 0\n",
  };
  failures f;
  size_t k;
  (void) state;
  memset (&f, 0, sizeof f);
  for (k = 0; k < sizeof texts / sizeof texts[0]; ++k)
    {
      carom_world *w = NULL;
      carom_scene_error err;
      carom_status s;
      char name[48];
      int i;
      snprintf (name, sizeof name, "%s", texts[k]);
      for (i = 0; name[i]; ++i)
        if (name[i] == '\n')
          name[i] = '|';
      err.size = sizeof err;
      s = carom_scene_load_text (&w, texts[k], strlen (texts[k]), NULL, &err);
      if (s != CAROM_OK)
        {
          if (w != NULL || err.line < 1 || err.cause != s)
            note (&f, "'%s': refused with %d but line %d cause %d", name, (int) s, (int) err.line,
                  (int) err.cause);
          continue;
        }
      if (world_problem (w)[0])
        note (&f, "'%s': loaded, but %s", name, world_problem (w));
      else
        for (i = 0; i < 10; ++i)
          {
            carom_world_update (w, 1.0 / 60.0);
            if (world_problem (w)[0])
              {
                note (&f, "'%s': step %d: %s", name, i + 1, world_problem (w));
                break;
              }
          }
      carom_world_destroy (w);
    }
  report (&f, "scene extremes");
}

/* The error struct: a size larger than this library's still gets the
 * fields it knows; a NULL text with length 0 is an empty scene. */
static void test_scene_error_struct_and_empty_text (void **state)
{
  struct {
    carom_scene_error e;
    char newer_fields[32];
  } big;
  carom_world *w = NULL;
  (void) state;
  memset (&big, 0x33, sizeof big);
  big.e.size = sizeof big;
  assert_status (carom_scene_load_text (&w, "circle -1\n", 10, NULL, &big.e), CAROM_ERR_BAD_SIZE);
  assert_int_equal (big.e.line, 1);
  assert_int_equal (big.e.cause, CAROM_ERR_BAD_SIZE);
  assert_true (big.newer_fields[0] == 0x33);
  assert_status (carom_scene_load_text (&w, NULL, 0, NULL, NULL), CAROM_OK);
  assert_non_null (w);
  assert_int_equal (carom_world_body_count (w), 0);
  carom_world_destroy (w);
}


/* ------------------------------------------------ the calls of version 0.2 */

/* Every refusal of a version 0.2 call, in one table: the call, its inputs,
 * the status it must return; each must leave the world's whole state
 * (world_state_hash: bodies, pending forces, filters, user data, contacts,
 * events) as it was. */
typedef enum api_call {
  FORCE, TORQUE, IMPULSE, ANGULAR, FILTER, USER_SET, USER_GET, SENSOR_GET, FILTER_GET, RAY, CLEAR
} api_call;

typedef struct api_case {
  const char *what;
  api_call call;
  int body;          /* 0 dynamic, 1 static, 2 kinematic, 3 stale, 4 NULL world */
  double a, b, c, d;
  carom_status want;
} api_case;

static const api_case api_cases[] = {
  { "force NaN", FORCE, 0, NAN, 0, 0, 0, CAROM_ERR_NOT_FINITE },
  { "force at an infinite point", FORCE, 0, 1, 0, 0, INFINITY, CAROM_ERR_NOT_FINITE },
  { "force beyond the magnitude", FORCE, 0, 2e100, 0, 0, 0, CAROM_ERR_BAD_ARGUMENT },
  { "force at a point beyond it", FORCE, 0, 1, 0, -2e100, 0, CAROM_ERR_BAD_ARGUMENT },
  { "force on a static body", FORCE, 1, 1, 0, 0, 0, CAROM_ERR_STATIC_BODY },
  { "force on a kinematic body", FORCE, 2, 1, 0, 0, 0, CAROM_ERR_STATIC_BODY },
  { "force on a stale id", FORCE, 3, 1, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "force in no world", FORCE, 4, 1, 0, 0, 0, CAROM_ERR_NULL_ARGUMENT },
  { "torque NaN", TORQUE, 0, NAN, 0, 0, 0, CAROM_ERR_NOT_FINITE },
  { "torque beyond the magnitude", TORQUE, 0, -1e101, 0, 0, 0, CAROM_ERR_BAD_ARGUMENT },
  { "torque on a static body", TORQUE, 1, 1, 0, 0, 0, CAROM_ERR_STATIC_BODY },
  { "torque on a stale id", TORQUE, 3, 1, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "impulse -inf", IMPULSE, 0, 0, -INFINITY, 0, 0, CAROM_ERR_NOT_FINITE },
  { "impulse beyond the magnitude", IMPULSE, 0, 0, 1e101, 0, 0, CAROM_ERR_BAD_ARGUMENT },
  { "impulse giving a speed beyond it", IMPULSE, 0, 0, 9e99, 0, 0, CAROM_ERR_BAD_ARGUMENT },
  { "impulse on a kinematic body", IMPULSE, 2, 1, 0, 0, 0, CAROM_ERR_STATIC_BODY },
  { "impulse on a stale id", IMPULSE, 3, 1, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "angular impulse NaN", ANGULAR, 0, NAN, 0, 0, 0, CAROM_ERR_NOT_FINITE },
  { "angular impulse giving a spin beyond it", ANGULAR, 0, 9e99, 0, 0, 0, CAROM_ERR_BAD_ARGUMENT },
  { "angular impulse on a static body", ANGULAR, 1, 1, 0, 0, 0, CAROM_ERR_STATIC_BODY },
  { "filter on a stale id", FILTER, 3, 0, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "filter in no world", FILTER, 4, 0, 0, 0, 0, CAROM_ERR_NULL_ARGUMENT },
  { "user data on a stale id", USER_SET, 3, 0, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "user data in no world", USER_GET, 4, 0, 0, 0, 0, CAROM_ERR_NULL_ARGUMENT },
  { "user data of a stale id", USER_GET, 3, 0, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "sensor flag of a stale id", SENSOR_GET, 3, 0, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "filter of a stale id", FILTER_GET, 3, 0, 0, 0, 0, CAROM_ERR_STALE_BODY },
  { "ray from NaN", RAY, 0, NAN, 0, 1, 1, CAROM_ERR_NOT_FINITE },
  { "ray to inf", RAY, 0, 0, 0, 1, INFINITY, CAROM_ERR_NOT_FINITE },
  { "ray beyond the magnitude", RAY, 0, 0, 0, 2e100, 0, CAROM_ERR_BAD_ARGUMENT },
  { "ray in no world", RAY, 4, 0, 0, 1, 1, CAROM_ERR_NULL_ARGUMENT },
  { "forces cleared in no world", CLEAR, 4, 0, 0, 0, 0, CAROM_ERR_NULL_ARGUMENT },
};

static carom_status call_api (carom_world *w, const api_case *t, carom_body_id id)
{
  void *p = &p;
  uint32_t cat = 7, mask = 7;
  int32_t group = 7, sensor = 7;
  carom_ray_hit hit;
  carom_status s;
  hit.body = 12345;
  switch (t->call)
    {
    case FORCE: return carom_body_apply_force (w, id, t->a, t->b, t->c, t->d);
    case TORQUE: return carom_body_apply_torque (w, id, t->a);
    case IMPULSE: return carom_body_apply_impulse (w, id, t->a, t->b, t->c, t->d);
    case ANGULAR: return carom_body_apply_angular_impulse (w, id, t->a);
    case FILTER: return carom_body_set_filter (w, id, 2u, 3u, -1);
    case USER_SET: return carom_body_set_user_data (w, id, NULL);
    case USER_GET:
      s = carom_body_get_user_data (w, id, &p);
      assert_true (p == &p); /* outputs untouched */
      return s;
    case SENSOR_GET:
      s = carom_body_is_sensor (w, id, &sensor);
      assert_int_equal (sensor, 7);
      return s;
    case FILTER_GET:
      s = carom_body_get_filter (w, id, &cat, &mask, &group);
      assert_true (cat == 7 && mask == 7 && group == 7);
      return s;
    case RAY:
      s = carom_world_cast_ray (w, t->a, t->b, t->c, t->d, ~0u, &hit);
      assert_true (hit.body == 12345);
      return s;
    default: return carom_world_clear_forces (w);
    }
}

/* carom_world_add_compound: each way a shape def can be wrong, refused
 * with its status, the world unchanged and the id not written. */
typedef enum shape_fault {
  SF_NONE, SF_SIZE, SF_KIND, SF_RADIUS_ZERO, SF_RADIUS_NAN, SF_RADIUS_HUGE, SF_X_NAN, SF_X_HUGE, SF_ANGLE_INF,
  SF_DENSITY_ZERO, SF_DENSITY_NAN, SF_RESTITUTION, SF_FRICTION_NAN, SF_XY_NULL, SF_FEW, SF_MANY, SF_CROSSING,
  SF_REPEATED, SF_VERTEX_NAN, SF_MERGED
} shape_fault;

typedef struct compound_case {
  const char *what;
  shape_fault fault;
  int32_t count;      /* shapes passed (the second one carries the fault) */
  carom_status want;
} compound_case;

static const compound_case compound_cases[] = {
  { "a shape def of the wrong size", SF_SIZE, 2, CAROM_ERR_BAD_STRUCT_SIZE },
  { "a kind neither circle nor polygon", SF_KIND, 2, CAROM_ERR_BAD_ARGUMENT },
  { "a circle of radius 0", SF_RADIUS_ZERO, 2, CAROM_ERR_BAD_SIZE },
  { "a circle of radius NaN", SF_RADIUS_NAN, 2, CAROM_ERR_NOT_FINITE },
  { "a circle of radius 1e61", SF_RADIUS_HUGE, 2, CAROM_ERR_BAD_SIZE },
  { "a shape at x NaN", SF_X_NAN, 2, CAROM_ERR_NOT_FINITE },
  { "a shape at x 2e100", SF_X_HUGE, 2, CAROM_ERR_BAD_ARGUMENT },
  { "a shape turned by inf", SF_ANGLE_INF, 2, CAROM_ERR_NOT_FINITE },
  { "a shape of density 0", SF_DENSITY_ZERO, 2, CAROM_ERR_BAD_DENSITY },
  { "a shape of density NaN", SF_DENSITY_NAN, 2, CAROM_ERR_NOT_FINITE },
  { "a shape of restitution 1.5", SF_RESTITUTION, 2, CAROM_ERR_BAD_ARGUMENT },
  { "a shape of friction NaN", SF_FRICTION_NAN, 2, CAROM_ERR_NOT_FINITE },
  { "a polygon without vertices", SF_XY_NULL, 2, CAROM_ERR_NULL_ARGUMENT },
  { "a polygon of 2 vertices", SF_FEW, 2, CAROM_ERR_TOO_FEW_VERTICES },
  { "a polygon of 1025 vertices", SF_MANY, 2, CAROM_ERR_TOO_MANY_VERTICES },
  { "a polygon whose edges cross", SF_CROSSING, 2, CAROM_ERR_SELF_INTERSECTING },
  { "a polygon with a repeated vertex", SF_REPEATED, 2, CAROM_ERR_REPEATED_VERTEX },
  { "a polygon with a NaN vertex", SF_VERTEX_NAN, 2, CAROM_ERR_NOT_FINITE },
  { "a polygon placed where its vertices merge", SF_MERGED, 2, CAROM_ERR_REPEATED_VERTEX },
  { "no shapes", SF_NONE, 0, CAROM_ERR_BAD_ARGUMENT },
  { "more than CAROM_MAX_COMPOUND_SHAPES", SF_NONE, CAROM_MAX_COMPOUND_SHAPES + 1, CAROM_ERR_BAD_ARGUMENT },
};

static void test_compound_calls_refuse_bad_input (void **state)
{
  static double square[] = { 0, 0, 1, 0, 1, 1, 0, 1 }, bow[] = { 0, 0, 1, 1, 1, 0, 0, 1 };
  static double repeated[] = { 0, 0, 1, 0, 1, 0, 0, 1 }, nan_vertex[] = { 0, 0, 1, 0, 1, 1, 0, 1 };
  static carom_shape_def shapes[CAROM_MAX_COMPOUND_SHAPES + 1];
  carom_world *w = new_world (-10.0);
  carom_body_def d;
  carom_body_id id, stale;
  carom_shape_kind kind = (carom_shape_kind) 7;
  double x = 7, radius = 7, xy[8] = { 7 }, density = 7;
  int32_t count = 7, i;
  size_t k;
  (void) state;
  nan_vertex[5] = NAN;
  add_ground (w, -0.5, 20.0, 1.0);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &stale), CAROM_OK);
  assert_status (carom_world_remove_body (w, stale), CAROM_OK);
  for (i = 0; i < CAROM_MAX_COMPOUND_SHAPES + 1; ++i)
    {
      assert_status (carom_shape_def_init (&shapes[i], sizeof shapes[i]), CAROM_OK);
      shapes[i].radius = 0.5, shapes[i].x = i;
    }
  carom_body_def_init (&d, sizeof d);
  d.y = 2.0;
  for (k = 0; k < sizeof compound_cases / sizeof compound_cases[0]; ++k)
    {
      const compound_case *t = &compound_cases[k];
      carom_shape_def saved = shapes[1];
      carom_shape_def *f = &shapes[1];
      uint64_t before = world_state_hash (w);
      carom_status s;
      switch (t->fault)
        {
        case SF_NONE: break;
        case SF_SIZE: f->size = sizeof *f - 8; break;
        case SF_KIND: f->kind = (carom_shape_kind) 2; break;
        case SF_RADIUS_ZERO: f->radius = 0.0; break;
        case SF_RADIUS_NAN: f->radius = NAN; break;
        case SF_RADIUS_HUGE: f->radius = 1e61; break;
        case SF_X_NAN: f->x = NAN; break;
        case SF_X_HUGE: f->x = 2e100; break;
        case SF_ANGLE_INF: f->angle = INFINITY; break;
        case SF_DENSITY_ZERO: f->density = 0.0; break;
        case SF_DENSITY_NAN: f->density = NAN; break;
        case SF_RESTITUTION: f->restitution = 1.5; break;
        case SF_FRICTION_NAN: f->friction = NAN; break;
        case SF_XY_NULL: f->kind = CAROM_SHAPE_POLYGON, f->count = 4; break;
        case SF_FEW: f->kind = CAROM_SHAPE_POLYGON, f->xy = square, f->count = 2; break;
        case SF_MANY: f->kind = CAROM_SHAPE_POLYGON, f->xy = square, f->count = 1025; break;
        case SF_CROSSING: f->kind = CAROM_SHAPE_POLYGON, f->xy = bow, f->count = 4; break;
        case SF_REPEATED: f->kind = CAROM_SHAPE_POLYGON, f->xy = repeated, f->count = 4; break;
        case SF_VERTEX_NAN: f->kind = CAROM_SHAPE_POLYGON, f->xy = nan_vertex, f->count = 4; break;
        case SF_MERGED: f->kind = CAROM_SHAPE_POLYGON, f->xy = square, f->count = 4, f->x = 1e100; break;
        }
      id = 12345;
      s = carom_world_add_compound (w, &d, shapes, t->count, &id);
      shapes[1] = saved;
      if (s != t->want)
        fail_msg ("%s: returned %d (%s), wanted %d (%s)", t->what, (int) s, carom_status_string (s), (int) t->want,
                  carom_status_string (t->want));
      if (world_state_hash (w) != before || id != 12345)
        fail_msg ("%s: refused, but the world or the id changed", t->what);
    }
  assert_status (carom_world_add_compound (NULL, &d, shapes, 2, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_add_compound (w, &d, NULL, 2, &id), CAROM_ERR_NULL_ARGUMENT);
  d.density = 0.0; /* the body's density, which shapes of density < 0 take */
  assert_status (carom_world_add_compound (w, &d, shapes, 2, &id), CAROM_ERR_BAD_DENSITY);
  d.density = 1.0;
  assert_status (carom_shape_def_init (NULL, sizeof shapes[0]), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_shape_def_init (&shapes[0], 4), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_int_equal (carom_world_body_count (w), 1);
  /* the getters: stale ids, bad indices, outputs untouched */
  assert_status (carom_world_add_compound (w, &d, shapes, 2, &id), CAROM_OK);
  assert_status (carom_body_get_shape_count (NULL, id, &count), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_shape_count (w, stale, &count), CAROM_ERR_STALE_BODY);
  assert_int_equal (count, 7);
  assert_status (carom_body_get_shape_geometry (w, id, 2, &kind, &x, NULL, &radius, xy, 4, &count),
                 CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_get_shape_geometry (w, id, -1, &kind, &x, NULL, &radius, xy, 4, &count),
                 CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_get_shape_geometry (w, id, 0, &kind, &x, NULL, &radius, xy, -1, &count),
                 CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_get_shape_geometry (w, id, 0, &kind, &x, NULL, &radius, NULL, 4, &count),
                 CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_shape_geometry (w, stale, 0, &kind, &x, NULL, &radius, xy, 4, &count),
                 CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_shape_geometry (NULL, id, 0, &kind, &x, NULL, &radius, xy, 4, &count),
                 CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_get_shape_material (w, id, 2, &density, NULL, NULL), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_body_get_shape_material (w, stale, 0, &density, NULL, NULL), CAROM_ERR_STALE_BODY);
  assert_status (carom_body_get_shape_material (NULL, id, 0, &density, NULL, NULL), CAROM_ERR_NULL_ARGUMENT);
  assert_true (kind == (carom_shape_kind) 7 && x == 7 && radius == 7 && xy[0] == 7 && count == 7 && density == 7);
  carom_world_destroy (w);
}

static void test_version_0_2_calls_refuse_bad_input (void **state)
{
  carom_world *w = new_world (-10.0);
  carom_body_def d;
  carom_body_id ids[4];
  carom_ray_hit hit;
  carom_contact_event events[4];
  carom_debug_draw draw;
  size_t i;
  int k;
  (void) state;
  add_ground (w, -0.5, 20.0, 1.0);
  carom_body_def_init (&d, sizeof d);
  d.y = 0.5, d.density = 0.01; /* light: an impulse of 9e99 gives 9e101 */
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &ids[0]), CAROM_OK);
  d.density = 1.0;
  d.type = CAROM_STATIC, d.x = 5.0;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &ids[1]), CAROM_OK);
  d.type = CAROM_KINEMATIC, d.x = -5.0, d.vx = 0.5;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &ids[2]), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &ids[3]), CAROM_OK);
  assert_status (carom_world_remove_body (w, ids[3]), CAROM_OK);
  for (k = 0; k < 10; ++k)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  for (i = 0; i < sizeof api_cases / sizeof api_cases[0]; ++i)
    {
      const api_case *t = &api_cases[i];
      uint64_t before = world_state_hash (w);
      carom_status s = call_api (t->body == 4 ? NULL : w, t, t->body == 4 ? ids[0] : ids[t->body]);
      if (s != t->want)
        fail_msg ("%s: returned %d (%s), wanted %d (%s)", t->what, (int) s, carom_status_string (s), (int) t->want,
                  carom_status_string (t->want));
      if (world_state_hash (w) != before)
        fail_msg ("%s: refused, but the world changed", t->what);
    }
  /* the calls that return counts: minus the status, nothing written */
  {
    uint64_t before = world_state_hash (w);
    carom_body_id out[2] = { 5, 5 };
    assert_int_equal (carom_world_query_aabb (NULL, 0, 0, 1, 1, ~0u, out, 2), -CAROM_ERR_NULL_ARGUMENT);
    assert_int_equal (carom_world_query_aabb (w, 0, 0, 1, 1, ~0u, NULL, 2), -CAROM_ERR_NULL_ARGUMENT);
    assert_int_equal (carom_world_query_aabb (w, 0, 0, 1, 1, ~0u, out, -1), -CAROM_ERR_BAD_ARGUMENT);
    assert_int_equal (carom_world_query_aabb (w, 1, 0, 0, 1, ~0u, out, 2), -CAROM_ERR_BAD_ARGUMENT);
    assert_int_equal (carom_world_query_aabb (w, 0, 1, 1, 0, ~0u, out, 2), -CAROM_ERR_BAD_ARGUMENT);
    assert_int_equal (carom_world_query_aabb (w, NAN, 0, 1, 1, ~0u, out, 2), -CAROM_ERR_NOT_FINITE);
    assert_int_equal (carom_world_query_aabb (w, -2e100, 0, 1, 1, ~0u, out, 2), -CAROM_ERR_BAD_ARGUMENT);
    assert_int_equal (carom_world_query_point (NULL, 0, 0, ~0u, out, 2), -CAROM_ERR_NULL_ARGUMENT);
    assert_int_equal (carom_world_query_point (w, 0, INFINITY, ~0u, out, 2), -CAROM_ERR_NOT_FINITE);
    assert_int_equal (carom_world_query_point (w, 0, 2e100, ~0u, out, 2), -CAROM_ERR_BAD_ARGUMENT);
    assert_int_equal (carom_world_query_point (w, 0, 0, ~0u, out, -5), -CAROM_ERR_BAD_ARGUMENT);
    assert_int_equal (carom_world_get_events (NULL, events, 4), -CAROM_ERR_NULL_ARGUMENT);
    assert_int_equal (carom_world_get_events (w, NULL, 4), -CAROM_ERR_NULL_ARGUMENT);
    assert_int_equal (carom_world_get_events (w, events, -1), -CAROM_ERR_BAD_ARGUMENT);
    assert_true (out[0] == 5 && out[1] == 5);
    assert_true (world_state_hash (w) == before);
    /* a query with capacity 0 only counts; a NULL hit is refused */
    assert_true (carom_world_query_point (w, 0, 0.5, ~0u, NULL, 0) == 1);
    assert_status (carom_world_cast_ray (w, 0, 0, 1, 1, ~0u, NULL), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_world_cast_ray (w, 0, 3, 0, -3, 0u, &hit), CAROM_OK); /* nothing in mask 0 */
    assert_true (hit.body == CAROM_NULL_BODY);
  }
  /* the debug draw's struct */
  assert_status (carom_debug_draw_init (NULL, sizeof draw), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_debug_draw_init (&draw, sizeof draw - 1), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_status (carom_debug_draw_init (&draw, sizeof draw), CAROM_OK);
  assert_status (carom_world_draw (NULL, &draw), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_draw (w, NULL), CAROM_ERR_NULL_ARGUMENT);
  draw.size = 3;
  assert_status (carom_world_draw (w, &draw), CAROM_ERR_BAD_STRUCT_SIZE);
  /* a refused impulse leaves a sleeping body asleep (nothing changes) */
  {
    carom_world *sw = new_world (-10.0);
    carom_body_def sd;
    carom_body_id sleeper;
    uint64_t before;
    int32_t awake = 1;
    add_ground (sw, -0.5, 20.0, 1.0);
    carom_body_def_init (&sd, sizeof sd);
    sd.y = 0.5, sd.density = 0.01;
    assert_status (carom_world_add_box (sw, &sd, 1.0, 1.0, &sleeper), CAROM_OK);
    assert_status (carom_world_set_sleeping (sw, 1), CAROM_OK);
    for (k = 0; k < 120; ++k)
      assert_status (carom_world_update (sw, 1.0 / 60), CAROM_OK);
    assert_status (carom_body_is_awake (sw, sleeper, &awake), CAROM_OK);
    assert_int_equal (awake, 0);
    before = world_state_hash (sw);
    assert_status (carom_body_apply_impulse (sw, sleeper, 0.0, 9e99, 0.0, 0.5), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_body_apply_angular_impulse (sw, sleeper, 9e99), CAROM_ERR_BAD_ARGUMENT);
    assert_true (world_state_hash (sw) == before);
    /* and an accepted one wakes it, with the awake body's inverse mass */
    assert_status (carom_body_apply_impulse (sw, sleeper, 0.0, 0.02, 0.0, 0.5), CAROM_OK);
    assert_status (carom_body_is_awake (sw, sleeper, &awake), CAROM_OK);
    assert_int_equal (awake, 1);
    {
      double vx, vy;
      assert_status (carom_body_get_velocity (sw, sleeper, &vx, &vy), CAROM_OK);
      assert_near_rel (vy, 0.02 / 0.01, 1e-15);
    }
    carom_world_destroy (sw);
  }
  /* forces too strong for an update: refused, nothing changes, and
   * clear_forces is the way out */
  {
    uint64_t before;
    assert_status (carom_body_apply_force (w, ids[0], 9e99, 0.0, 0.0, 0.5), CAROM_OK);
    assert_status (carom_body_apply_force (w, ids[0], 9e99, 0.0, 0.0, 0.5), CAROM_ERR_BAD_ARGUMENT); /* the sum */
    before = world_state_hash (w);
    assert_status (carom_world_update (w, 1e90), CAROM_ERR_BAD_ARGUMENT);
    assert_true (world_state_hash (w) == before);
    assert_status (carom_world_clear_forces (w), CAROM_OK);
    assert_status (carom_world_update (w, 1e90), CAROM_OK);
  }
  carom_world_destroy (w);
}

/* --------------------------------------------------------------- joints */

typedef enum joint_fault {
  JF_NONE, JF_SIZE, JF_TYPE, JF_SAME, JF_A_STALE, JF_B_STALE, JF_B_NULL, JF_BOTH_STATIC, JF_MOUSE_A, JF_X_NAN,
  JF_Y_HUGE, JF_AXIS_ZERO, JF_AXIS_INF, JF_LIMIT_ORDER, JF_FORCE_NEG, JF_TORQUE_NEG, JF_HERTZ_NEG,
  JF_DAMPING_NAN, JF_LENGTH_NEG, JF_ANCHORS_SAME, JF_SPEED_INF
} joint_fault;

typedef struct joint_case {
  const char *what;
  carom_joint_type type;
  joint_fault fault;
  carom_status want;
} joint_case;

static const joint_case joint_cases[] = {
  { "a joint def of the wrong size", CAROM_JOINT_REVOLUTE, JF_SIZE, CAROM_ERR_BAD_STRUCT_SIZE },
  { "an unknown joint type", CAROM_JOINT_REVOLUTE, JF_TYPE, CAROM_ERR_BAD_ARGUMENT },
  { "a joint of a body to itself", CAROM_JOINT_WELD, JF_SAME, CAROM_ERR_BAD_ARGUMENT },
  { "a stale body a", CAROM_JOINT_REVOLUTE, JF_A_STALE, CAROM_ERR_STALE_BODY },
  { "a stale body b", CAROM_JOINT_DISTANCE, JF_B_STALE, CAROM_ERR_STALE_BODY },
  { "no body b", CAROM_JOINT_REVOLUTE, JF_B_NULL, CAROM_ERR_STALE_BODY },
  { "two static bodies", CAROM_JOINT_REVOLUTE, JF_BOTH_STATIC, CAROM_ERR_STATIC_BODY },
  { "a mouse joint with a body a", CAROM_JOINT_MOUSE, JF_MOUSE_A, CAROM_ERR_BAD_ARGUMENT },
  { "an anchor at x NaN", CAROM_JOINT_REVOLUTE, JF_X_NAN, CAROM_ERR_NOT_FINITE },
  { "an anchor at y 2e100", CAROM_JOINT_WELD, JF_Y_HUGE, CAROM_ERR_BAD_ARGUMENT },
  { "a prismatic joint without an axis", CAROM_JOINT_PRISMATIC, JF_AXIS_ZERO, CAROM_ERR_BAD_ARGUMENT },
  { "a wheel joint without an axis", CAROM_JOINT_WHEEL, JF_AXIS_ZERO, CAROM_ERR_BAD_ARGUMENT },
  { "an axis of inf", CAROM_JOINT_WHEEL, JF_AXIS_INF, CAROM_ERR_NOT_FINITE },
  { "a limit with lower > upper", CAROM_JOINT_REVOLUTE, JF_LIMIT_ORDER, CAROM_ERR_BAD_ARGUMENT },
  { "a negative motor force", CAROM_JOINT_PRISMATIC, JF_FORCE_NEG, CAROM_ERR_BAD_ARGUMENT },
  { "a negative motor torque", CAROM_JOINT_MOTOR, JF_TORQUE_NEG, CAROM_ERR_BAD_ARGUMENT },
  { "a negative hertz", CAROM_JOINT_DISTANCE, JF_HERTZ_NEG, CAROM_ERR_BAD_ARGUMENT },
  { "a damping ratio of NaN", CAROM_JOINT_WELD, JF_DAMPING_NAN, CAROM_ERR_NOT_FINITE },
  { "a negative length", CAROM_JOINT_DISTANCE, JF_LENGTH_NEG, CAROM_ERR_BAD_ARGUMENT },
  { "a distance joint of coinciding anchors", CAROM_JOINT_DISTANCE, JF_ANCHORS_SAME, CAROM_ERR_BAD_ARGUMENT },
  { "a motor speed of inf", CAROM_JOINT_REVOLUTE, JF_SPEED_INF, CAROM_ERR_NOT_FINITE },
  { "a good revolute joint (control)", CAROM_JOINT_REVOLUTE, JF_NONE, CAROM_OK },
};

/* Every bad joint def is refused with its status and changes nothing; so
 * are the joint calls on a stale id and their bad arguments. */
static void test_joint_calls_refuse_bad_input (void **state)
{
  carom_world *w = new_world (-10.0);
  carom_body_def d;
  carom_body_id a, b, ground, stale;
  carom_joint_id id, good, stale_joint;
  carom_joint_def def;
  carom_joint_type type = (carom_joint_type) 9;
  double x = 7, y = 7, t = 7;
  size_t k;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  assert_status (carom_world_add_box (w, &d, 10.0, 1.0, &ground), CAROM_OK);
  d.type = CAROM_DYNAMIC, d.y = 2.0;
  assert_status (carom_world_add_circle (w, &d, 0.5, &a), CAROM_OK);
  d.x = 2.0;
  assert_status (carom_world_add_box (w, &d, 1.0, 0.5, &b), CAROM_OK);
  assert_status (carom_world_add_circle (w, &d, 1.0, &stale), CAROM_OK);
  assert_status (carom_world_remove_body (w, stale), CAROM_OK);
  for (k = 0; k < sizeof joint_cases / sizeof joint_cases[0]; ++k)
    {
      const joint_case *c = &joint_cases[k];
      uint64_t before = world_state_hash (w);
      int32_t joints = carom_world_joint_count (w);
      carom_status s;
      assert_status (carom_joint_def_init (&def, sizeof def), CAROM_OK);
      def.type = c->type, def.a = a, def.b = b, def.x = 1.0, def.y = 2.0, def.x2 = 2.0, def.y2 = 2.0;
      def.axis_x = 1.0;
      switch (c->fault)
        {
        case JF_NONE: break;
        case JF_SIZE: def.size = sizeof def - 8; break;
        case JF_TYPE: def.type = (carom_joint_type) 7; break;
        case JF_SAME: def.a = b; break;
        case JF_A_STALE: def.a = stale; break;
        case JF_B_STALE: def.b = stale; break;
        case JF_B_NULL: def.b = CAROM_NULL_BODY; break;
        case JF_BOTH_STATIC: def.a = CAROM_NULL_BODY, def.b = ground; break;
        case JF_MOUSE_A: break;
        case JF_X_NAN: def.x = NAN; break;
        case JF_Y_HUGE: def.y = 2e100; break;
        case JF_AXIS_ZERO: def.axis_x = 0.0; break;
        case JF_AXIS_INF: def.axis_y = INFINITY; break;
        case JF_LIMIT_ORDER: def.enable_limit = 1, def.lower = 1.0, def.upper = -1.0; break;
        case JF_FORCE_NEG: def.max_motor_force = -1.0; break;
        case JF_TORQUE_NEG: def.max_motor_torque = -1.0; break;
        case JF_HERTZ_NEG: def.hertz = -1.0; break;
        case JF_DAMPING_NAN: def.damping_ratio = NAN; break;
        case JF_LENGTH_NEG: def.length = -1.0; break;
        case JF_ANCHORS_SAME: def.x2 = def.x, def.y2 = def.y; break;
        case JF_SPEED_INF: def.motor_speed = INFINITY; break;
        }
      id = 12345;
      s = carom_world_add_joint (w, &def, &id);
      if (s != c->want)
        fail_msg ("%s: returned %d (%s), wanted %d (%s)", c->what, (int) s, carom_status_string (s), (int) c->want,
                  carom_status_string (c->want));
      if (c->want != CAROM_OK && (world_state_hash (w) != before || id != 12345 || carom_world_joint_count (w) != joints))
        fail_msg ("%s: refused, but the world or the id changed", c->what);
    }
  assert_status (carom_world_add_joint (w, NULL, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_add_joint (NULL, &def, &id), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_joint_def_init (NULL, sizeof def), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_joint_def_init (&def, 3), CAROM_ERR_BAD_STRUCT_SIZE);
  /* a live joint and a stale one */
  assert_status (carom_joint_def_init (&def, sizeof def), CAROM_OK);
  def.type = CAROM_JOINT_REVOLUTE, def.a = a, def.b = b, def.x = 1.0, def.y = 2.0;
  assert_status (carom_world_add_joint (w, &def, &good), CAROM_OK);
  assert_status (carom_world_add_joint (w, &def, &stale_joint), CAROM_OK);
  assert_status (carom_world_remove_joint (w, stale_joint), CAROM_OK);
  {
    uint64_t before = world_state_hash (w);
    assert_status (carom_world_remove_joint (w, stale_joint), CAROM_ERR_STALE_JOINT);
    assert_status (carom_world_remove_joint (w, CAROM_NULL_JOINT), CAROM_ERR_STALE_JOINT);
    assert_status (carom_world_remove_joint (w, ((uint64_t) 1 << 32) | 999u), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_check (w, stale_joint), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_get_bodies (w, stale_joint, &type, &a, &b), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_get_anchors (w, stale_joint, &x, &y, &x, &y), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_get_reaction (w, stale_joint, &x, &y, &t), CAROM_ERR_STALE_JOINT);
    assert_true (type == (carom_joint_type) 9 && x == 7 && y == 7 && t == 7);
    assert_status (carom_joint_set_motor (w, stale_joint, 1, 1.0, 1.0), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_set_target (w, stale_joint, 1.0, 1.0, 0.0), CAROM_ERR_STALE_JOINT);
    /* bad values on a live joint */
    assert_status (carom_joint_set_motor (w, good, 1, NAN, 1.0), CAROM_ERR_NOT_FINITE);
    assert_status (carom_joint_set_motor (w, good, 1, 1.0, -1.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_motor (w, good, 1, 2e100, 1.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_target (w, good, 1.0, 1.0, 0.0), CAROM_ERR_BAD_ARGUMENT); /* not mouse or motor */
    assert_status (carom_joint_set_limit (w, stale_joint, 1, -1.0, 1.0), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_set_spring (w, stale_joint, 1, 1.0, 1.0), CAROM_ERR_STALE_JOINT);
    assert_status (carom_joint_set_limit (w, good, 1, NAN, 1.0), CAROM_ERR_NOT_FINITE);
    assert_status (carom_joint_set_limit (w, good, 1, 1.0, -1.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_limit (w, good, 1, -3e100, 1.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_spring (w, good, 1, INFINITY, 1.0), CAROM_ERR_NOT_FINITE);
    assert_status (carom_joint_set_spring (w, good, 1, -1.0, 1.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_spring (w, good, 1, 1.0, -1.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_limit (NULL, good, 1, -1.0, 1.0), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_joint_set_spring (NULL, good, 1, 1.0, 1.0), CAROM_ERR_NULL_ARGUMENT);
    {
      carom_joint_id ids[2] = { 5, 5 };
      assert_int_equal (carom_world_get_joints (NULL, ids, 2), -CAROM_ERR_NULL_ARGUMENT);
      assert_int_equal (carom_world_get_joints (w, NULL, 2), -CAROM_ERR_NULL_ARGUMENT);
      assert_int_equal (carom_world_get_joints (w, ids, -1), -CAROM_ERR_BAD_ARGUMENT);
      assert_int_equal (carom_body_get_joints (w, stale, ids, 2), -CAROM_ERR_STALE_BODY);
      assert_int_equal (carom_body_get_joints (NULL, a, ids, 2), -CAROM_ERR_NULL_ARGUMENT);
      assert_int_equal (carom_body_get_joints (w, a, ids, -3), -CAROM_ERR_BAD_ARGUMENT);
      assert_true (ids[0] == 5 && ids[1] == 5);
    }
    assert_status (carom_joint_check (NULL, good), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_world_remove_joint (NULL, good), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_joint_get_bodies (NULL, good, NULL, NULL, NULL), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_joint_get_anchors (NULL, good, NULL, NULL, NULL, NULL), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_joint_get_reaction (NULL, good, NULL, NULL, NULL), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_joint_set_motor (NULL, good, 1, 1.0, 1.0), CAROM_ERR_NULL_ARGUMENT);
    assert_status (carom_joint_set_target (NULL, good, 1.0, 1.0, 0.0), CAROM_ERR_NULL_ARGUMENT);
    assert_int_equal (carom_world_joint_count (NULL), 0);
    assert_true (world_state_hash (w) == before);
  }
  /* a mouse joint's target: NaN and huge are refused */
  assert_status (carom_joint_def_init (&def, sizeof def), CAROM_OK);
  def.type = CAROM_JOINT_MOUSE, def.b = b, def.x = 2.0, def.y = 2.0;
  assert_status (carom_world_add_joint (w, &def, &id), CAROM_OK);
  {
    uint64_t before = world_state_hash (w);
    assert_status (carom_joint_set_target (w, id, NAN, 1.0, 0.0), CAROM_ERR_NOT_FINITE);
    assert_status (carom_joint_set_target (w, id, 1.0, -2e100, 0.0), CAROM_ERR_BAD_ARGUMENT);
    assert_status (carom_joint_set_motor (w, id, 1, 1.0, 1.0), CAROM_ERR_BAD_ARGUMENT); /* a mouse has no motor */
    assert_status (carom_joint_set_limit (w, id, 1, -1.0, 1.0), CAROM_ERR_BAD_ARGUMENT); /* nor a limit */
    assert_true (world_state_hash (w) == before);
  }
  carom_world_destroy (w);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_null_world_everywhere),
    cmocka_unit_test_setup_teardown (test_null_outputs_are_skipped, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_body_def_every_field_not_finite, world_setup, world_teardown),
    cmocka_unit_test (test_world_def_every_field_not_finite),
    cmocka_unit_test_setup_teardown (test_shapes_not_finite, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_effect_setters_not_finite_and_negative, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_zero_negative_and_signed_zero_sizes, world_setup, world_teardown),
    cmocka_unit_test (test_extreme_sizes_and_densities),
    cmocka_unit_test_setup_teardown (test_vertex_counts, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_more_self_intersecting_polygons, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_stale_id_everywhere, world_setup, world_teardown),
    cmocka_unit_test (test_bad_time_steps_and_tiny_valid_ones),
    cmocka_unit_test (test_world_settings_out_of_range_and_at_the_limits),
    cmocka_unit_test (test_half_allocators),
    cmocka_unit_test_setup_teardown (test_body_def_bad_sizes, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_bad_enum_values, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_short_buffers, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_contact_index_out_of_range, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_coincident_centres_give_a_unit_normal, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_static_and_fixed_rotation_rules, world_setup, world_teardown),
    cmocka_unit_test (test_numeric_extremes_stay_finite),
    cmocka_unit_test_setup_teardown (test_magnitudes_beyond_the_limit_refused, world_setup, world_teardown),
    cmocka_unit_test (test_huge_speeds_relative_to_size),
    cmocka_unit_test (test_central_gravity_near_the_centre),
    cmocka_unit_test (test_scene_extremes),
    cmocka_unit_test (test_scene_error_struct_and_empty_text),
    cmocka_unit_test (test_version_0_2_calls_refuse_bad_input),
    cmocka_unit_test (test_compound_calls_refuse_bad_input),
    cmocka_unit_test (test_joint_calls_refuse_bad_input),
  };
  return cmocka_run_group_tests_name ("bad_input", tests, NULL, NULL);
}
