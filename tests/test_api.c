/* What a program drives carom with (version 0.2): forces and impulses,
 * kinematic bodies, user data, filtering, sensors, ray casts and queries,
 * contact events and the debug draw. */
#include "support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static carom_world *new_world (double gy)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = gy;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  return w;
}

static carom_body_id circle_at (carom_world *w, carom_body_type type, double x, double y, double r)
{
  carom_body_def d;
  carom_body_id id;
  carom_body_def_init (&d, sizeof d);
  d.type = type, d.x = x, d.y = y;
  assert_status (carom_world_add_circle (w, &d, r, &id), CAROM_OK);
  return id;
}

/* ------------------------------------------------- forces and impulses */

static void test_impulse_changes_velocity_by_j_over_m (void **state)
{
  carom_world *w = new_world (0.0);
  carom_body_id box = add_box (w, CAROM_DYNAMIC, 1.0, 2.0, 0.3, 2.0, 1.0);
  double m, inertia, vx, vy, spin, x, y, rx, ry;
  (void) state;
  assert_status (carom_body_get_mass (w, box, &m, &inertia, NULL), CAROM_OK);
  assert_status (carom_body_apply_impulse (w, box, 3.0, -4.0, 1.0, 2.0), CAROM_OK);
  assert_status (carom_body_get_velocity (w, box, &vx, &vy), CAROM_OK);
  assert_status (carom_body_get_spin (w, box, &spin), CAROM_OK);
  assert_near_rel (vx, 3.0 / m, 1e-15);
  assert_near_rel (vy, -4.0 / m, 1e-15);
  assert_true (spin == 0.0); /* at the centre: no spin */
  /* at an offset r: the spin changes by r x J / I */
  assert_status (carom_body_get_position (w, box, &x, &y), CAROM_OK);
  rx = 0.4, ry = -0.3;
  assert_status (carom_body_apply_impulse (w, box, 0.0, 2.0, x + rx, y + ry), CAROM_OK);
  assert_status (carom_body_get_spin (w, box, &spin), CAROM_OK);
  assert_near_rel (spin, (rx * 2.0 - ry * 0.0) / inertia, 1e-14);
  assert_status (carom_body_apply_angular_impulse (w, box, 1.5), CAROM_OK);
  assert_status (carom_body_get_spin (w, box, &vx), CAROM_OK);
  assert_near_rel (vx - spin, 1.5 / inertia, 1e-13);
  carom_world_destroy (w);
}

static void test_force_over_one_update_gives_f_dt_over_m (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (0.0);
  carom_body_id box = add_box (w, CAROM_DYNAMIC, 0.0, 0.0, 0.0, 1.0, 2.0);
  double m, inertia, vx, vy, spin, x, y;
  (void) state;
  assert_status (carom_body_get_mass (w, box, &m, &inertia, NULL), CAROM_OK);
  assert_status (carom_body_apply_force (w, box, 6.0, 0.0, 0.0, 0.0), CAROM_OK);
  assert_status (carom_body_apply_force (w, box, 0.0, -2.0, 0.0, 0.0), CAROM_OK); /* they add up */
  assert_status (carom_body_apply_torque (w, box, 0.75), CAROM_OK);
  assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_velocity (w, box, &vx, &vy), CAROM_OK);
  assert_status (carom_body_get_spin (w, box, &spin), CAROM_OK);
  assert_status (carom_body_get_position (w, box, &x, &y), CAROM_OK);
  assert_near_rel (vx, 6.0 * dt / m, 1e-13);
  assert_near_rel (vy, -2.0 * dt / m, 1e-13);
  assert_near_rel (spin, 0.75 * dt / inertia, 1e-13);
  /* free flight under a constant force: x = F t^2 / 2m exactly */
  assert_near_rel (x, 0.5 * 6.0 * dt * dt / m, 1e-12);
  assert_near_rel (y, -0.5 * 2.0 * dt * dt / m, 1e-12);
  /* then cleared: the next update keeps the velocity */
  assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_velocity (w, box, &x, &y), CAROM_OK);
  assert_true (x == vx && y == vy);
  /* a force off the centre turns the body: torque (p - c) x F */
  assert_status (carom_body_get_position (w, box, &x, &y), CAROM_OK);
  assert_status (carom_body_get_spin (w, box, &vx), CAROM_OK);
  assert_status (carom_body_apply_force (w, box, 0.0, 3.0, x + 0.5, y), CAROM_OK);
  assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_spin (w, box, &spin), CAROM_OK);
  assert_near_rel (spin - vx, 0.5 * 3.0 * dt / inertia, 1e-12);
  carom_world_destroy (w);
}

/* A resting body pushed sideways by a force slides as F = m a says
 * (no friction). */
static void test_force_on_a_resting_body (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_body_id box;
  double m, vx, vy;
  int i;
  (void) state;
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 100.0, 1.0);
  box = add_box (w, CAROM_DYNAMIC, 0.0, 0.5, 0.0, 1.0, 1.0);
  for (i = 0; i < 60; ++i)
    assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_mass (w, box, &m, NULL, NULL), CAROM_OK);
  for (i = 0; i < 30; ++i)
    {
      assert_status (carom_body_apply_force (w, box, 2.0 * m, 0.0, 0.0, 0.0), CAROM_OK);
      assert_status (carom_world_update (w, dt), CAROM_OK);
    }
  assert_status (carom_body_get_velocity (w, box, &vx, &vy), CAROM_OK);
  assert_near_rel (vx, 2.0 * 30 * dt, 1e-9);
  assert_near_abs (vy, 0.0, 1e-9);
  carom_world_destroy (w);
}

/* -------------------------------------------------------------- kinematic */

static void test_kinematic_platform_carries_a_box (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_body_def d;
  carom_body_id platform, box;
  double px, py, vx, vy, bx, by, m, inertia;
  carom_body_type type;
  int i;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_KINEMATIC, d.vx = 1.0, d.friction = 0.6;
  assert_status (carom_world_add_box (w, &d, 6.0, 0.5, &platform), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.y = 0.25 + 0.5, d.friction = 0.6;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &box), CAROM_OK);
  assert_status (carom_body_get_type (w, platform, &type), CAROM_OK);
  assert_int_equal (type, CAROM_KINEMATIC);
  assert_status (carom_body_get_mass (w, platform, &m, &inertia, NULL), CAROM_OK);
  assert_true (m == 0.0 && inertia == 0.0);
  for (i = 1; i <= 120; ++i)
    {
      assert_status (carom_world_update (w, dt), CAROM_OK);
      assert_status (carom_body_get_position (w, platform, &px, &py), CAROM_OK);
      assert_status (carom_body_get_velocity (w, platform, &vx, &vy), CAROM_OK);
      /* on its line, at its speed, whatever rests on it and whatever gravity */
      assert_true (py == 0.0 && vy == 0.0 && vx == 1.0);
      assert_near_rel (px, i * dt, 1e-12);
    }
  assert_status (carom_body_get_velocity (w, box, &bx, &by), CAROM_OK);
  assert_status (carom_body_get_position (w, box, &px, &py), CAROM_OK);
  assert_near_abs (bx, 1.0, 1e-3);
  assert_near_abs (by, 0.0, 1e-3);
  assert_true (py > 0.7 && py < 0.76); /* still on it */
  /* forces are refused, velocities are the program's */
  assert_status (carom_body_apply_force (w, platform, 1, 0, 0, 0), CAROM_ERR_STATIC_BODY);
  assert_status (carom_body_set_velocity (w, platform, 0.0, 0.5), CAROM_OK);
  assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_position (w, platform, &bx, &by), CAROM_OK);
  assert_near_rel (by, 0.5 * dt, 1e-12);
  carom_world_destroy (w);
}

/* A moving kinematic body wakes what it touches and is never pushed. */
static void test_kinematic_pushes_and_is_never_pushed (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (0.0);
  carom_body_def d;
  carom_body_id wall, ball;
  double x, y, vx, vy;
  int i;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_KINEMATIC, d.vx = 2.0, d.x = -2.0;
  assert_status (carom_world_add_box (w, &d, 0.5, 4.0, &wall), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.density = 1e6; /* as heavy as you like */
  assert_status (carom_world_add_circle (w, &d, 0.5, &ball), CAROM_OK);
  for (i = 0; i < 60; ++i)
    assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_position (w, wall, &x, &y), CAROM_OK);
  assert_near_abs (x, -2.0 + 2.0, 1e-12);
  assert_status (carom_body_get_velocity (w, ball, &vx, &vy), CAROM_OK);
  assert_true (vx >= 2.0 - 1e-9); /* pushed ahead at least as fast */
  carom_world_destroy (w);
}

/* ------------------------------------------------------------- user data */

static void test_user_data (void **state)
{
  carom_world *w = new_world (0.0);
  carom_body_def d;
  carom_body_id a, b;
  int tag = 7, other = 8;
  void *p = &other;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  assert_null (d.user_data);
  d.user_data = &tag;
  assert_status (carom_world_add_circle (w, &d, 1.0, &a), CAROM_OK);
  assert_status (carom_world_add_circle (w, NULL, 1.0, &b), CAROM_OK);
  assert_status (carom_body_get_user_data (w, a, &p), CAROM_OK);
  assert_ptr_equal (p, &tag);
  assert_status (carom_body_get_user_data (w, b, &p), CAROM_OK);
  assert_null (p);
  assert_status (carom_body_set_user_data (w, b, &other), CAROM_OK);
  assert_status (carom_body_get_user_data (w, b, &p), CAROM_OK);
  assert_ptr_equal (p, &other);
  assert_status (carom_body_get_user_data (w, b, NULL), CAROM_OK);
  carom_world_destroy (w);
}

/* -------------------------------------------------------------- filtering */

/* Two balls dropped on a ground: whether each lands, as the filter rule
 * says. */
static int lands (uint32_t cat_a, uint32_t mask_a, int32_t group_a, uint32_t cat_b, uint32_t mask_b, int32_t group_b)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_body_def d;
  carom_body_id ball;
  double x, y;
  int i;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -0.5, d.category = cat_a, d.mask = mask_a, d.group = group_a;
  assert_status (carom_world_add_box (w, &d, 10.0, 1.0, NULL), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.y = 1.0, d.category = cat_b, d.mask = mask_b, d.group = group_b;
  assert_status (carom_world_add_circle (w, &d, 0.5, &ball), CAROM_OK);
  for (i = 0; i < 60; ++i)
    assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_position (w, ball, &x, &y), CAROM_OK);
  carom_world_destroy (w);
  return y > 0.4;
}

static void test_filtering (void **state)
{
  (void) state;
  assert_true (lands (1, ~0u, 0, 1, ~0u, 0));      /* the defaults collide */
  assert_true (lands (2, 4, 0, 4, 2, 0));          /* each in the other's mask */
  assert_false (lands (2, 4, 0, 4, 1, 0));         /* a's category not in b's mask */
  assert_false (lands (2, 0, 0, 4, ~0u, 0));       /* b's category not in a's mask */
  assert_false (lands (1, ~0u, -3, 1, ~0u, -3));   /* the same negative group: never */
  assert_true (lands (1, ~0u, -3, 1, ~0u, -4));    /* different groups: the bits decide */
  assert_true (lands (2, 0, 5, 4, 0, 5));          /* the same positive group: always */
  assert_false (lands (2, 0, 5, 4, 0, 6));
  {
    carom_world *w = new_world (0.0);
    carom_body_id b = circle_at (w, CAROM_DYNAMIC, 0, 0, 1);
    uint32_t c, m;
    int32_t g;
    assert_status (carom_body_get_filter (w, b, &c, &m, &g), CAROM_OK);
    assert_true (c == 1u && m == 0xffffffffu && g == 0);
    assert_status (carom_body_set_filter (w, b, 8u, 3u, -2), CAROM_OK);
    assert_status (carom_body_get_filter (w, b, &c, &m, &g), CAROM_OK);
    assert_true (c == 8u && m == 3u && g == -2);
    carom_world_destroy (w);
  }
}

/* set_filter takes effect from the next update: a resting ball whose mask
 * drops the ground falls through it. */
static void test_set_filter_lets_a_body_fall_through (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_body_id ball;
  double x, y;
  int i;
  (void) state;
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 10.0, 1.0);
  ball = circle_at (w, CAROM_DYNAMIC, 0.0, 0.5, 0.5);
  assert_status (carom_world_set_sleeping (w, 1), CAROM_OK);
  for (i = 0; i < 120; ++i)
    assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_set_filter (w, ball, 1u, 0u, 0), CAROM_OK);
  for (i = 0; i < 60; ++i)
    assert_status (carom_world_update (w, dt), CAROM_OK);
  assert_status (carom_body_get_position (w, ball, &x, &y), CAROM_OK);
  assert_true (y < -3.0);
  carom_world_destroy (w);
}

/* ---------------------------------------------------------------- sensors */

static void test_sensor_reports_and_never_pushes (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_body_def d;
  carom_body_id sensor, ball;
  carom_contact_event ev[8];
  int i, begins = 0, ends = 0, begin_step = -1, end_step = -1;
  int32_t n, k, is;
  double x, y, vx, vy;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.sensor = 1, d.y = 0.0;
  assert_status (carom_world_add_box (w, &d, 4.0, 1.0, &sensor), CAROM_OK);
  assert_status (carom_body_is_sensor (w, sensor, &is), CAROM_OK);
  assert_int_equal (is, 1);
  ball = circle_at (w, CAROM_DYNAMIC, 0.0, 2.1, 0.25);
  for (i = 1; i <= 90; ++i)
    {
      assert_status (carom_world_update (w, dt), CAROM_OK);
      n = carom_world_get_events (w, ev, 8);
      assert_true (n >= 0 && n <= 8);
      for (k = 0; k < n; ++k)
        {
          assert_true (ev[k].type == CAROM_EVENT_SENSOR_BEGIN || ev[k].type == CAROM_EVENT_SENSOR_END);
          assert_true (ev[k].a == sensor && ev[k].b == ball);
          if (ev[k].type == CAROM_EVENT_SENSOR_BEGIN)
            begins++, begin_step = i;
          else
            ends++, end_step = i;
        }
      assert_int_equal (carom_world_contact_count (w), 0); /* no contact, ever */
    }
  assert_true (begins == 1 && ends == 1 && begin_step < end_step);
  /* it fell as if nothing were there */
  assert_status (carom_body_get_position (w, ball, &x, &y), CAROM_OK);
  assert_status (carom_body_get_velocity (w, ball, &vx, &vy), CAROM_OK);
  assert_near_rel (vy, -10.0 * 90 * dt, 1e-9);
  assert_near_rel (y, 2.1 - 0.5 * 10.0 * (90 * dt) * (90 * dt), 1e-9);
  /* the events describe the end of each update: the overlap began in the
   * first update that ended with the ball's bottom below the sensor's top
   * (centre at 0.5 + 0.25), and ended in the first that ended with its top
   * below the sensor's bottom (centre at -0.5 - 0.25) */
  assert_int_equal (begin_step, (int) ceil (sqrt (2.0 * (2.1 - 0.75) / 10.0) / dt));
  assert_int_equal (end_step, (int) ceil (sqrt (2.0 * (2.1 + 0.75) / 10.0) / dt));
  carom_world_destroy (w);
}

/* ------------------------------------------------------------------- rays */

/* The y of a polygon's centroid, from its vertices (the shoelace sums). */
static double centroid_y (const double *xy, int n)
{
  double cy = 0.0, area = 0.0;
  int i;
  for (i = 0; i < n; ++i)
    {
      double x0 = xy[2 * i], y0 = xy[2 * i + 1], x1 = xy[(2 * i + 2) % (2 * n)], y1 = xy[(2 * i + 3) % (2 * n)];
      double c = x0 * y1 - x1 * y0;
      area += c;
      cy += (y0 + y1) * c;
    }
  return cy / (3.0 * area);
}

static void test_rays_hit_the_true_outline (void **state)
{
  /* a U, open upwards: its notch is 1 wide and 1.5 deep */
  static const double u[] = { -1.5, 0.0, 1.5, 0.0, 1.5, 2.0, 0.5, 2.0, 0.5, 0.5, -0.5, 0.5, -0.5, 2.0, -1.5, 2.0 };
  carom_world *w = new_world (0.0);
  carom_body_def d;
  carom_body_id box, ball, cup;
  carom_ray_hit hit;
  double cx, cy;
  (void) state;
  box = add_box (w, CAROM_STATIC, 0.0, 0.0, 0.0, 2.0, 2.0);
  ball = circle_at (w, CAROM_DYNAMIC, 10.0, 0.0, 1.0);
  carom_body_def_init (&d, sizeof d);
  d.x = 20.0, d.y = 0.0;
  assert_status (carom_world_add_polygon (w, &d, u, 8, &cup), CAROM_OK);
  /* the box's left face at x = -1 */
  assert_status (carom_world_cast_ray (w, -5.0, 0.25, 5.0, 0.25, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == box);
  assert_near_abs (hit.x, -1.0, 1e-12);
  assert_near_abs (hit.y, 0.25, 1e-12);
  assert_near_abs (hit.nx, -1.0, 1e-12);
  assert_near_abs (hit.ny, 0.0, 1e-12);
  assert_near_abs (hit.fraction, 0.4, 1e-12);
  /* the circle, at 45 degrees: from (10 - 3, -3) towards its centre */
  assert_status (carom_world_cast_ray (w, 7.0, -3.0, 10.0, 0.0, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == ball);
  assert_near_abs (hit.x, 10.0 - sqrt (0.5), 1e-9);
  assert_near_abs (hit.y, -sqrt (0.5), 1e-9);
  assert_near_abs (hit.nx, -sqrt (0.5), 1e-12);
  assert_near_abs (hit.ny, -sqrt (0.5), 1e-12);
  assert_near_abs (hit.fraction, (sqrt (18.0) - 1.0) / sqrt (18.0), 1e-12);
  /* straight down into the cup's notch: the notch's floor, not the rim's
   * line (the centroid is the body's position, so place the ray from it) */
  assert_status (carom_body_get_position (w, cup, &cx, &cy), CAROM_OK);
  assert_status (carom_world_cast_ray (w, 20.0, 10.0, 20.0, -10.0, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == cup);
  assert_near_abs (hit.x, 20.0, 1e-9);
  /* in the input's frame the notch floor lies at y = 0.5; the body's
   * position is the polygon's centroid */
  assert_near_abs (hit.y, cy + 0.5 - centroid_y (u, 8), 1e-9);
  assert_near_abs (hit.nx, 0.0, 1e-12);
  assert_near_abs (hit.ny, 1.0, 1e-12);
  /* misses: past the box, short of it, and masked out */
  assert_status (carom_world_cast_ray (w, -5.0, 1.5, 5.0, 1.5, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == CAROM_NULL_BODY);
  assert_status (carom_world_cast_ray (w, -5.0, 0.0, -1.5, 0.0, ~0u, &hit), CAROM_OK);
  assert_true (hit.body == CAROM_NULL_BODY);
  assert_status (carom_body_set_filter (w, box, 2u, ~0u, 0), CAROM_OK);
  assert_status (carom_world_cast_ray (w, -5.0, 0.25, 15.0, 0.25, 1u, &hit), CAROM_OK);
  assert_true (hit.body == ball); /* the box is skipped, the ball behind it is hit */
  assert_near_abs (hit.x, 10.0 - sqrt (1.0 - 0.0625), 1e-9);
  /* from inside the box: its faces are not entered; the ball is */
  assert_status (carom_world_cast_ray (w, 0.0, 0.0, 12.0, 0.0, 2u, &hit), CAROM_OK);
  assert_true (hit.body == CAROM_NULL_BODY);
  carom_world_destroy (w);
}

/* -------------------------------------------------------------- queries */

static uint32_t lcg (uint32_t *s)
{
  *s = *s * 1664525u + 1013904223u;
  return *s >> 8;
}

static double uniform (uint32_t *s, double lo, double hi)
{
  return lo + (hi - lo) * (double) lcg (s) / 16777216.0;
}

/* The brute-force answers, from the public getters alone. */
static int brute_box (const carom_world *w, carom_body_id id, double x0, double y0, double x1, double y1)
{
  double xy[32], lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY, r, px, py;
  int32_t n, i;
  carom_shape_kind kind;
  carom_body_get_shape (w, id, &kind, &r);
  carom_body_get_position (w, id, &px, &py);
  if (kind == CAROM_SHAPE_CIRCLE)
    lo_x = px - r, hi_x = px + r, lo_y = py - r, hi_y = py + r;
  else
    {
      carom_body_get_vertices (w, id, xy, 16, &n);
      for (i = 0; i < n; ++i)
        {
          lo_x = fmin (lo_x, xy[2 * i]), hi_x = fmax (hi_x, xy[2 * i]);
          lo_y = fmin (lo_y, xy[2 * i + 1]), hi_y = fmax (hi_y, xy[2 * i + 1]);
        }
    }
  return !(hi_x < x0 || lo_x > x1 || hi_y < y0 || lo_y > y1);
}

static int brute_point (const carom_world *w, carom_body_id id, double x, double y)
{
  double xy[32], r, px, py;
  int32_t n, i, j;
  int inside = 0;
  carom_shape_kind kind;
  carom_body_get_shape (w, id, &kind, &r);
  carom_body_get_position (w, id, &px, &py);
  if (kind == CAROM_SHAPE_CIRCLE)
    return (x - px) * (x - px) + (y - py) * (y - py) <= r * r;
  carom_body_get_vertices (w, id, xy, 16, &n);
  for (i = 0, j = n - 1; i < n; j = i++)
    if ((xy[2 * i + 1] > y) != (xy[2 * j + 1] > y)
        && x < xy[2 * i] + (y - xy[2 * i + 1]) * (xy[2 * j] - xy[2 * i]) / (xy[2 * j + 1] - xy[2 * i + 1]))
      inside = !inside;
  return inside;
}

static void test_queries_match_brute_force_over_10k_bodies (void **state)
{
  static const double notch[] = { -0.6, -0.4, 0.6, -0.4, 0.6, 0.4, 0.0, 0.0, -0.6, 0.4 };
  enum { N = 10000 };
  carom_world *w = new_world (0.0);
  carom_body_id *ids = malloc (N * sizeof *ids), *got = malloc (N * sizeof *got);
  uint32_t seed = 99u;
  int i, q, total_box = 0, total_point = 0;
  (void) state;
  assert_non_null (ids);
  assert_non_null (got);
  for (i = 0; i < N; ++i)
    {
      carom_body_def d;
      carom_body_def_init (&d, sizeof d);
      d.x = uniform (&seed, -100.0, 100.0), d.y = uniform (&seed, -100.0, 100.0);
      d.angle = uniform (&seed, 0.0, 6.28);
      d.category = 1u << (i % 3);
      if (i % 3 == 0)
        assert_status (carom_world_add_circle (w, &d, uniform (&seed, 0.2, 1.0), &ids[i]), CAROM_OK);
      else if (i % 3 == 1)
        assert_status (carom_world_add_box (w, &d, uniform (&seed, 0.2, 2.0), uniform (&seed, 0.2, 2.0), &ids[i]),
                       CAROM_OK);
      else
        assert_status (carom_world_add_polygon (w, &d, notch, 5, &ids[i]), CAROM_OK);
    }
  for (q = 0; q < 200; ++q)
    {
      double x0 = uniform (&seed, -110.0, 100.0), y0 = uniform (&seed, -110.0, 100.0);
      double x1 = x0 + uniform (&seed, 0.0, 15.0), y1 = y0 + uniform (&seed, 0.0, 15.0);
      uint32_t mask = q % 2 ? ~0u : 5u;
      int32_t n = carom_world_query_aabb (w, x0, y0, x1, y1, mask, got, N), k = 0;
      for (i = 0; i < N; ++i)
        if ((((uint32_t) 1 << (i % 3)) & mask) && brute_box (w, ids[i], x0, y0, x1, y1))
          {
            assert_true (k < n && got[k] == ids[i]); /* the same, in creation order */
            ++k;
          }
      assert_int_equal (n, k);
      total_box += n;
      n = carom_world_query_point (w, x0, y0, mask, got, N), k = 0;
      for (i = 0; i < N; ++i)
        if ((((uint32_t) 1 << (i % 3)) & mask) && brute_point (w, ids[i], x0, y0))
          {
            assert_true (k < n && got[k] == ids[i]);
            ++k;
          }
      assert_int_equal (n, k);
      total_point += n;
    }
  /* they found plenty; and capacity 0 only counts */
  assert_true (total_box > 1000 && total_point > 20);
  assert_int_equal (carom_world_query_aabb (w, -200, -200, 200, 200, ~0u, NULL, 0), N);
  printf ("queries: %d box hits, %d point hits over 200 queries\n", total_box, total_point);
  free (ids);
  free (got);
  carom_world_destroy (w);
}

/* A concave polygon's notch does not contain a point. */
static void test_point_query_in_a_notch (void **state)
{
  static const double u[] = { -1.5, 0.0, 1.5, 0.0, 1.5, 2.0, 0.5, 2.0, 0.5, 0.5, -0.5, 0.5, -0.5, 2.0, -1.5, 2.0 };
  carom_world *w = new_world (0.0);
  carom_body_def d;
  carom_body_id cup, got[4];
  double cx, cy;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  assert_status (carom_world_add_polygon (w, &d, u, 8, &cup), CAROM_OK);
  carom_body_get_position (w, cup, &cx, &cy);
  /* the notch's middle is (0, 1.25) in the input's frame, whose centroid is
   * at the body's position (the origin here) */
  assert_int_equal (carom_world_query_point (w, 0.0, cy + 1.25 - centroid_y (u, 8), ~0u, got, 4), 0);
  assert_int_equal (carom_world_query_point (w, 1.0, cy + 1.25 - centroid_y (u, 8), ~0u, got, 4), 1);
  assert_true (got[0] == cup);
  carom_world_destroy (w);
}

/* ----------------------------------------------------------------- events */

static void test_dropped_ball_begin_event_reports_its_approach (void **state)
{
  const double dt = 1.0 / 60, h = 1.0;
  carom_world *w = new_world (-10.0);
  carom_body_id ground, ball;
  carom_contact_event ev[8];
  int i, begins = 0;
  int32_t n, k;
  (void) state;
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  ground = add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 10.0, 1.0);
  ball = circle_at (w, CAROM_DYNAMIC, 0.0, h + 0.25, 0.25);
  for (i = 0; i < 120; ++i)
    {
      assert_status (carom_world_update (w, dt), CAROM_OK);
      n = carom_world_get_events (w, ev, 8);
      for (k = 0; k < n; ++k)
        if (ev[k].type == CAROM_EVENT_CONTACT_BEGIN)
          {
            double speed = sqrt (2.0 * 10.0 * h);
            begins++;
            assert_true ((ev[k].a == ground && ev[k].b == ball) || (ev[k].a == ball && ev[k].b == ground));
            printf ("begin: approach %.4f m/s (free fall from %g m: %.4f), impulse %.4f\n", ev[k].approach_speed, h,
                    speed, ev[k].normal_impulse);
            assert_true (fabs (ev[k].approach_speed - speed) <= 0.05 * speed);
            assert_true (ev[k].normal_impulse > 0.0);
            assert_near_abs (fabs (ev[k].ny), 1.0, 1e-9);
            assert_near_abs (ev[k].y, 0.0, 0.1); /* a point of the contact, found ahead */
          }
    }
  assert_int_equal (begins, 1); /* it lands once and stays */
  carom_world_destroy (w);
}

/* Bouncing and tumbling bodies: every begin has its end, pairs never begin
 * twice without ending, and removing a body ends its pairs. */
static void test_begin_and_end_events_pair_up (void **state)
{
  enum { MAXP = 4096 };
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_contact_event ev[256];
  static carom_body_id open_a[MAXP], open_b[MAXP];
  int open = 0, begins = 0, ends = 0, i, j;
  int32_t n, k;
  carom_body_id ids[64];
  (void) state;
  assert_status (carom_world_set_restitution (w, 0.6), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 20.0, 1.0);
  for (i = 0; i < 30; ++i)
    {
      carom_body_def d;
      carom_body_def_init (&d, sizeof d);
      d.x = -6.0 + 0.43 * i, d.y = 1.0 + 0.7 * (i % 5), d.spin = 0.3 * (i % 4);
      if (i % 2)
        assert_status (carom_world_add_circle (w, &d, 0.3, &ids[i]), CAROM_OK);
      else
        assert_status (carom_world_add_box (w, &d, 0.5, 0.4, &ids[i]), CAROM_OK);
    }
  for (i = 0; i < 400; ++i)
    {
      if (i == 300)
        for (j = 0; j < 30; j += 3)
          assert_status (carom_world_remove_body (w, ids[j]), CAROM_OK);
      assert_status (carom_world_update (w, dt), CAROM_OK);
      n = carom_world_get_events (w, ev, 256);
      assert_true (n >= 0 && n <= 256);
      for (k = 0; k < n; ++k)
        {
          int found = -1, m;
          for (m = 0; m < open; ++m)
            if (open_a[m] == ev[k].a && open_b[m] == ev[k].b)
              found = m;
          if (ev[k].type == CAROM_EVENT_CONTACT_BEGIN)
            {
              assert_int_equal (found, -1);
              assert_true (open < MAXP);
              open_a[open] = ev[k].a, open_b[open] = ev[k].b, ++open;
              begins++;
            }
          else
            {
              assert_int_equal (ev[k].type, CAROM_EVENT_CONTACT_END);
              assert_true (found >= 0);
              open_a[found] = open_a[open - 1], open_b[found] = open_b[open - 1], --open;
              ends++;
            }
        }
    }
  printf ("events: %d begins, %d ends, %d pairs touching at the end\n", begins, ends, open);
  assert_true (begins > 30 && ends > 10);
  /* what is still open touches now: no pair involves a removed body */
  for (i = 0; i < open; ++i)
    assert_true (carom_body_check (w, open_a[i]) == CAROM_OK && carom_body_check (w, open_b[i]) == CAROM_OK);
  carom_world_destroy (w);
}

/* A body that falls asleep on the ground still touches it: no end event
 * while it sleeps; woken and thrown up, it ends, and lands again. */
static void test_sleeping_pairs_do_not_end (void **state)
{
  const double dt = 1.0 / 60;
  carom_world *w = new_world (-10.0);
  carom_contact_event ev[8];
  carom_body_id box;
  int i, begins = 0, ends = 0, slept = 0;
  int32_t n, k, awake;
  (void) state;
  assert_status (carom_world_set_sleeping (w, 1), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 10.0, 1.0);
  box = add_box (w, CAROM_DYNAMIC, 0.0, 0.5, 0.0, 1.0, 1.0);
  for (i = 0; i < 240; ++i)
    {
      if (i == 150)
        {
          assert_status (carom_body_is_awake (w, box, &awake), CAROM_OK);
          slept = !awake;
          assert_status (carom_body_apply_impulse (w, box, 0.0, 5.0, 0.0, 0.5), CAROM_OK);
        }
      assert_status (carom_world_update (w, dt), CAROM_OK);
      n = carom_world_get_events (w, ev, 8);
      for (k = 0; k < n; ++k)
        {
          begins += ev[k].type == CAROM_EVENT_CONTACT_BEGIN;
          ends += ev[k].type == CAROM_EVENT_CONTACT_END;
          /* nothing ends while it sleeps, before the throw */
          assert_false (i < 150 && ev[k].type == CAROM_EVENT_CONTACT_END);
        }
    }
  assert_true (slept);
  assert_int_equal (begins, 2); /* built resting, then the landing */
  assert_int_equal (ends, 1);   /* the throw */
  carom_world_destroy (w);
}

/* ------------------------------------------------------------ debug draw */

typedef struct draw_count {
  int polygons, circles, segments, points, vertices;
} draw_count;

static void on_polygon (const double *xy, int32_t count, carom_body_id body, void *user)
{
  draw_count *c = user;
  (void) xy, (void) body;
  c->polygons++, c->vertices += count;
}

static void on_circle (double x, double y, double r, double angle, carom_body_id body, void *user)
{
  draw_count *c = user;
  (void) x, (void) y, (void) r, (void) angle, (void) body;
  c->circles++;
}

static void on_segment (double x0, double y0, double x1, double y1, void *user)
{
  draw_count *c = user;
  (void) x0, (void) y0, (void) x1, (void) y1;
  c->segments++;
}

static void on_point (double x, double y, void *user)
{
  draw_count *c = user;
  (void) x, (void) y;
  c->points++;
}

static void test_debug_draw_draws_everything (void **state)
{
  carom_world *w = new_world (-10.0);
  carom_debug_draw draw;
  draw_count c = { 0, 0, 0, 0, 0 };
  int i;
  (void) state;
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 10.0, 1.0);
  add_box (w, CAROM_DYNAMIC, 0.0, 0.5, 0.0, 1.0, 1.0);
  circle_at (w, CAROM_DYNAMIC, 2.0, 0.5, 0.5);
  for (i = 0; i < 10; ++i)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  assert_status (carom_debug_draw_init (&draw, sizeof draw), CAROM_OK);
  assert_true (draw.draw_bodies == 1 && draw.draw_contacts == 1 && !draw.polygon);
  assert_status (carom_world_draw (w, &draw), CAROM_OK); /* no callbacks: nothing */
  draw.polygon = on_polygon, draw.circle = on_circle, draw.segment = on_segment, draw.point = on_point;
  draw.user = &c;
  assert_status (carom_world_draw (w, &draw), CAROM_OK);
  assert_true (c.polygons == 2 && c.circles == 1 && c.vertices == 8);
  assert_int_equal (c.points, carom_world_contact_count (w));
  assert_int_equal (c.segments, carom_world_contact_count (w));
  assert_true (c.points >= 3);
  draw.draw_contacts = 0;
  assert_status (carom_world_draw (w, &draw), CAROM_OK);
  assert_int_equal (c.points, carom_world_contact_count (w));
  carom_world_destroy (w);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_impulse_changes_velocity_by_j_over_m),
    cmocka_unit_test (test_force_over_one_update_gives_f_dt_over_m),
    cmocka_unit_test (test_force_on_a_resting_body),
    cmocka_unit_test (test_kinematic_platform_carries_a_box),
    cmocka_unit_test (test_kinematic_pushes_and_is_never_pushed),
    cmocka_unit_test (test_user_data),
    cmocka_unit_test (test_filtering),
    cmocka_unit_test (test_set_filter_lets_a_body_fall_through),
    cmocka_unit_test (test_sensor_reports_and_never_pushes),
    cmocka_unit_test (test_rays_hit_the_true_outline),
    cmocka_unit_test (test_queries_match_brute_force_over_10k_bodies),
    cmocka_unit_test (test_point_query_in_a_notch),
    cmocka_unit_test (test_dropped_ball_begin_event_reports_its_approach),
    cmocka_unit_test (test_begin_and_end_events_pair_up),
    cmocka_unit_test (test_sleeping_pairs_do_not_end),
    cmocka_unit_test (test_debug_draw_draws_everything),
  };
  return cmocka_run_group_tests (tests, NULL, NULL);
}
