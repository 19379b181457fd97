/* Effects: each stage against a closed form, and all stages off changing
 * nothing at all. */
#include "support.h"

#include <math.h>

static carom_world *new_world (double gy, double friction)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = gy;
  def.friction = friction;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  return w;
}

/* A busy scene with every optional stage off. `toggle` switches each stage
 * on and off again before stepping. */
static carom_world *busy_scene (int toggle)
{
  carom_world *w = NULL;
  carom_body_def d;
  carom_body_id first = 0;
  int i;
  assert_status (carom_world_init (&w, NULL), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.y = -0.5;
  carom_world_add_box (w, &d, 20, 1, NULL);
  d.x = -10, d.y = 5;
  carom_world_add_box (w, &d, 1, 12, NULL);
  d.x = 10;
  carom_world_add_box (w, &d, 1, 12, NULL);
  d.x = 0, d.y = 10.5;
  carom_world_add_box (w, &d, 20, 1, NULL);
  carom_body_def_init (&d, sizeof d);
  for (i = 0; i < 60; ++i)
    {
      carom_body_id id;
      d.x = -8 + (i % 12) * 1.4, d.y = 1 + (i / 12) * 1.3, d.angle = 0.1 * i;
      d.vx = (i % 5) - 2.0, d.vy = ((i * 7) % 5) - 2.0, d.spin = 0.3 * ((i % 3) - 1);
      if (i % 3 == 0)
        carom_world_add_circle (w, &d, 0.4, &id);
      else if (i % 3 == 1)
        carom_world_add_box (w, &d, 0.8, 0.5, &id);
      else
        carom_world_add_regular (w, &d, 3 + i % 5, 0.5, &id);
      if (i == 1) /* a body without spin: fixing rotation zeroes spin */
        first = id;
    }
  if (toggle)
    {
      /* every stage on, then off again (continuous collision, on by
         default, the other way round) */
      carom_world_set_gravity (w, 0, -10);
      carom_world_set_central_gravity (w, 1, 2, 30, 0.5);
      carom_world_set_damping (w, 0.3, 0.2);
      carom_world_set_sleeping (w, 1);
      carom_world_set_restitution (w, 0.5);
      carom_world_set_friction (w, 0.4);
      carom_body_set_fixed_rotation (w, first, 1);
      carom_body_set_bullet (w, first, 1);
      carom_world_set_continuous (w, 0);
      assert_int_not_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
      carom_world_set_gravity (w, 0, 0);
      carom_world_set_central_gravity (w, 0, 0, 0, 0);
      carom_world_set_damping (w, 0, 0);
      carom_world_set_sleeping (w, 0);
      carom_world_set_restitution (w, 0);
      carom_world_set_friction (w, 0);
      carom_body_set_fixed_rotation (w, first, 0);
      carom_body_set_bullet (w, first, 0);
      carom_world_set_continuous (w, 1);
    }
  return w;
}

/* Switching the machinery on and off changes nothing but what is asked for:
 * a world whose stages were all switched on and then off again computes bit
 * for bit the trajectories of one whose stages were never touched. (When
 * the stages were added, the same scene also hashed to the same value as on
 * the library before they existed: see docs/effects.md.) */
static void test_stages_switched_off_change_nothing (void **state)
{
  carom_world *plain = busy_scene (0), *toggled = busy_scene (1);
  int i;
  (void) state;
  assert_int_equal (carom_world_get_effects (plain), CAROM_EFFECT_CONTINUOUS);
  assert_int_equal (carom_world_get_effects (toggled), CAROM_EFFECT_CONTINUOUS);
  for (i = 0; i < 300; ++i)
    {
      carom_world_update (plain, 1.0 / 60);
      carom_world_update (toggled, 1.0 / 60);
    }
  assert_true (world_state_hash (plain) == world_state_hash (toggled));
  carom_world_destroy (plain);
  carom_world_destroy (toggled);
}

static void test_effects_are_reported_when_used (void **state)
{
  carom_world *w = new_world (0, 0);
  carom_body_id b = add_box (w, CAROM_DYNAMIC, 0, 0, 0, 1, 1);
  uint32_t all = CAROM_EFFECT_GRAVITY | CAROM_EFFECT_CENTRAL_GRAVITY | CAROM_EFFECT_RESTITUTION
                 | CAROM_EFFECT_FRICTION | CAROM_EFFECT_FIXED_ROTATION | CAROM_EFFECT_DAMPING | CAROM_EFFECT_SLEEPING
                 | CAROM_EFFECT_CONTINUOUS;
  (void) state;
  /* continuous collision alone is on by default */
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_world_set_continuous (w, 0);
  assert_int_equal (carom_world_get_effects (w), 0);
  carom_body_set_bullet (w, b, 1); /* a bullet has it for itself */
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_body_set_bullet (w, b, 0);
  carom_world_set_continuous (w, 1);
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_world_set_gravity (w, 0, -1);
  carom_world_set_central_gravity (w, 0, 0, 1, 0);
  carom_world_set_restitution (w, 0.5);
  carom_world_set_friction (w, 0.5);
  carom_body_set_fixed_rotation (w, b, 1);
  carom_world_set_damping (w, 0.1, 0);
  carom_world_set_sleeping (w, 1);
  assert_int_equal (carom_world_get_effects (w), all);
  carom_world_set_gravity (w, 0, 0);
  carom_world_set_central_gravity (w, 0, 0, 0, 0);
  carom_world_set_restitution (w, 0);
  carom_world_set_friction (w, 0);
  carom_body_set_fixed_rotation (w, b, 0);
  carom_world_set_damping (w, 0, 0);
  carom_world_set_sleeping (w, 0);
  carom_world_set_continuous (w, 0);
  assert_int_equal (carom_world_get_effects (w), 0);
  assert_string_equal (carom_effect_name (CAROM_EFFECT_SLEEPING), "sleeping");
  assert_null (carom_effect_name ((carom_effect) 3));
  assert_status (carom_world_set_damping (w, -1, 0), CAROM_ERR_BAD_ARGUMENT);
  assert_status (carom_world_set_central_gravity (w, 0, 0, NAN, 0), CAROM_ERR_NOT_FINITE);
  assert_status (carom_world_set_restitution (w, 1.5), CAROM_ERR_BAD_ARGUMENT);
  carom_world_destroy (w);
}

/* Central gravity: a circular orbit keeps its radius within 0.5% over five
 * periods (symplectic Euler: the error oscillates, it does not grow). */
static void test_circular_orbit_radius_bounded (void **state)
{
  carom_world *w = new_world (0, 0);
  carom_body_def d;
  carom_body_id sat;
  const double gm = 100.0, r0 = 10.0, v0 = sqrt (gm / r0), period = 2 * M_PI * r0 / v0;
  double rmin = r0, rmax = r0, x, y;
  int step, steps = (int) (5 * period * 60);
  (void) state;
  assert_status (carom_world_set_central_gravity (w, 0, 0, gm, 0), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.x = r0, d.vy = v0;
  assert_status (carom_world_add_circle (w, &d, 0.1, &sat), CAROM_OK);
  for (step = 0; step < steps; ++step)
    {
      double r;
      carom_world_update (w, 1.0 / 60);
      carom_body_get_position (w, sat, &x, &y);
      r = sqrt (x * x + y * y);
      rmin = fmin (rmin, r), rmax = fmax (rmax, r);
    }
  assert_true (rmax - r0 < 0.005 * r0 && r0 - rmin < 0.005 * r0);
  carom_world_destroy (w);
}

/* Friction: a box sliding on flat ground stops after v^2 / (2 mu g), within
 * 2%; on a slope below the friction angle it does not slide, above it does. */
static void test_friction_stopping_distance (void **state)
{
  const double mu = 0.5, g = 10.0, v0 = 5.0;
  carom_world *w = new_world (-g, mu);
  carom_body_id box;
  double x, vx;
  int step;
  (void) state;
  add_box (w, CAROM_STATIC, 0, -0.5, 0, 100, 1);
  box = add_box (w, CAROM_DYNAMIC, 0, 0.25, 0, 0.5, 0.5);
  for (step = 0; step < 30; ++step)
    carom_world_update (w, 1.0 / 120); /* settle on the ground first */
  assert_status (carom_body_set_velocity (w, box, v0, 0), CAROM_OK);
  for (step = 0; step < 600; ++step)
    carom_world_update (w, 1.0 / 120);
  carom_body_get_position (w, box, &x, NULL);
  carom_body_get_velocity (w, box, &vx, NULL);
  assert_near_abs (vx, 0.0, 1e-9);
  assert_near_rel (x, v0 * v0 / (2 * mu * g), 0.02);
  carom_world_destroy (w);
}

static double slide_on_slope (double slope, double mu)
{
  carom_world *w = new_world (-10, mu);
  carom_body_id box;
  double x0, y0, x, y;
  int step;
  /* a long static ramp through the origin, and a box resting on it */
  add_box (w, CAROM_STATIC, 0, 0, slope, 40, 1);
  box = add_box (w, CAROM_DYNAMIC, -sin (slope) * 0.75, cos (slope) * 0.75, slope, 1, 0.5);
  carom_body_get_position (w, box, &x0, &y0);
  for (step = 0; step < 120; ++step)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_position (w, box, &x, &y);
  carom_world_destroy (w);
  return sqrt ((x - x0) * (x - x0) + (y - y0) * (y - y0));
}

static void test_friction_angle (void **state)
{
  (void) state;
  assert_true (slide_on_slope (0.4, 0.6) < 1e-3);  /* tan 0.4 = 0.42 < 0.6 */
  assert_true (slide_on_slope (0.7, 0.6) > 1.0);   /* tan 0.7 = 0.84 > 0.6 */
}

/* Damping: v(t) = v0 exp(-c t) and w(t) = w0 exp(-k t) at every step. */
static void test_damping_decay_is_exponential (void **state)
{
  carom_world *w = new_world (0, 0);
  carom_body_def d;
  carom_body_id b;
  int step;
  (void) state;
  assert_status (carom_world_set_damping (w, 0.7, 1.3), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.vx = 3.0, d.spin = 2.0;
  assert_status (carom_world_add_regular (w, &d, 6, 0.5, &b), CAROM_OK);
  for (step = 1; step <= 240; ++step)
    {
      double vx, spin, t = step / 60.0;
      carom_world_update (w, 1.0 / 60);
      carom_body_get_velocity (w, b, &vx, NULL);
      carom_body_get_spin (w, b, &spin);
      assert_near_rel (vx, 3.0 * exp (-0.7 * t), 1e-12);
      assert_near_rel (spin, 2.0 * exp (-1.3 * t), 1e-12);
    }
  carom_world_destroy (w);
}

/* A non-rotating box dropped on a corner lands without turning at all. */
static void test_fixed_rotation_never_rotates (void **state)
{
  carom_world *w = new_world (-10, 0.5);
  carom_body_id box;
  double angle;
  int step;
  (void) state;
  add_box (w, CAROM_STATIC, 0, -0.5, 0, 20, 1);
  box = add_box (w, CAROM_DYNAMIC, 0.3, 2.0, 0.6, 1, 0.5);
  assert_status (carom_body_set_fixed_rotation (w, box, 1), CAROM_OK);
  assert_status (carom_body_set_spin (w, box, 1.0), CAROM_ERR_BAD_ARGUMENT);
  for (step = 0; step < 180; ++step)
    {
      carom_world_update (w, 1.0 / 60);
      carom_body_get_angle (w, box, &angle);
      assert_true (angle == 0.6);
    }
  carom_world_destroy (w);
}

/* Sleeping: a resting stack falls asleep (and then costs no contacts); a
 * ball thrown at it wakes it and knocks it. */
static void test_sleeping_stack_wakes_when_hit (void **state)
{
  carom_world *w = new_world (-10, 0.6);
  carom_body_id boxes[3], ball;
  carom_body_def d;
  int32_t awake;
  double x;
  int i, step;
  (void) state;
  add_box (w, CAROM_STATIC, 0, -0.5, 0, 40, 1);
  for (i = 0; i < 3; ++i)
    boxes[i] = add_box (w, CAROM_DYNAMIC, 0, 0.5 + i, 0, 1, 1);
  assert_status (carom_world_set_sleeping (w, 1), CAROM_OK);
  for (step = 0; step < 120; ++step)
    carom_world_update (w, 1.0 / 60);
  for (i = 0; i < 3; ++i)
    {
      assert_status (carom_body_is_awake (w, boxes[i], &awake), CAROM_OK);
      assert_int_equal (awake, 0);
    }
  assert_int_equal (carom_world_contact_count (w), 0);
  carom_body_def_init (&d, sizeof d);
  d.x = -6, d.y = 2.5, d.vx = 15.0, d.density = 5.0;
  assert_status (carom_world_add_circle (w, &d, 0.3, &ball), CAROM_OK);
  for (step = 0; step < 60; ++step)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_position (w, boxes[2], &x, NULL);
  assert_true (x > 0.05); /* the top box was pushed */
  carom_world_destroy (w);
}

/* Continuous collision. A body that moves more than half its size in a
 * step is swept whatever the switch (body_swept): a circle at 300 m/s
 * never passes a wall thinner than its travel per step, with the world's
 * switch off or on, or marked as a bullet. */
static double bullet_x_after (int world_continuous, int bullet)
{
  carom_world *w = new_world (0, 0);
  carom_body_def d;
  carom_body_id b;
  double x;
  int step;
  assert_status (carom_world_set_continuous (w, world_continuous), CAROM_OK);
  add_box (w, CAROM_STATIC, 10.0, 0.0, 0.0, 0.1, 4.0);
  carom_body_def_init (&d, sizeof d);
  d.x = -3.3, d.vx = 300.0;
  assert_status (carom_world_add_circle (w, &d, 0.05, &b), CAROM_OK);
  assert_status (carom_body_set_bullet (w, b, bullet), CAROM_OK);
  for (step = 0; step < 60; ++step)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_position (w, b, &x, NULL);
  carom_world_destroy (w);
  return x;
}

/* The switch sweeps the slow bodies too: a unit box (size 2 A / P = 0.5)
 * at 12 m/s moves 0.2 in a step, under half its size, towards a static one
 * 0.15 away. Off, its contact is looked for only 2% of its size ahead
 * and it comes into the other 0.05 deep; on, it is met where they touch
 * (within the slop, 0.005). Returns the overlap after one step. */
static double slow_box_overlap (int world_continuous)
{
  carom_world *w = new_world (0, 0);
  carom_body_id b;
  double x;
  assert_status (carom_world_set_continuous (w, world_continuous), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, 0.0, 0.0, 1.0, 1.0);
  b = add_box (w, CAROM_DYNAMIC, 1.15, 0.0, 0.0, 1.0, 1.0);
  assert_status (carom_body_set_velocity (w, b, -12.0, 0.0), CAROM_OK);
  assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  carom_body_get_position (w, b, &x, NULL);
  carom_world_destroy (w);
  return 1.0 - x;
}

static void test_continuous_collision_switch (void **state)
{
  (void) state;
  assert_true (bullet_x_after (1, 0) < 10.0); /* on: stopped by the wall */
  assert_true (bullet_x_after (0, 0) < 10.0); /* off: fast for its size */
  assert_true (bullet_x_after (0, 1) < 10.0); /* off, and a bullet */
  assert_true (slow_box_overlap (0) > 0.04);
  assert_true (slow_box_overlap (1) < 0.005);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_stages_switched_off_change_nothing),
    cmocka_unit_test (test_effects_are_reported_when_used),
    cmocka_unit_test (test_circular_orbit_radius_bounded),
    cmocka_unit_test (test_friction_stopping_distance),
    cmocka_unit_test (test_friction_angle),
    cmocka_unit_test (test_damping_decay_is_exponential),
    cmocka_unit_test (test_fixed_rotation_never_rotates),
    cmocka_unit_test (test_sleeping_stack_wakes_when_hit),
    cmocka_unit_test (test_continuous_collision_switch),
  };
  return cmocka_run_group_tests_name ("effects", tests, NULL, NULL);
}
