/* The world's lifecycle, settings, and free motion against closed forms. */
#include "support.h"

#include <stdlib.h>

#include <math.h>
#include <string.h>

static void test_init_destroy_and_null (void **state)
{
  carom_world *w = NULL;
  carom_world_def def;
  (void) state;
  carom_world_destroy (NULL); /* safe */
  assert_status (carom_world_init (NULL, NULL), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_world_update (NULL, 0.1), CAROM_ERR_NULL_ARGUMENT);
  carom_world_def_init (&def, sizeof def);
  assert_int_equal (def.size, sizeof def);
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_non_null (w);
  assert_int_equal (carom_world_body_count (w), 0);
  assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  carom_world_destroy (w);
  assert_true (carom_version () == CAROM_VERSION);
  assert_string_equal (carom_status_string (CAROM_OK), "ok");
  assert_string_equal (carom_status_string ((carom_status) 999), "unknown status");
}

static void test_bad_world_defs (void **state)
{
  carom_world *w = (carom_world *) 1;
  carom_world_def def;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = NAN;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_NOT_FINITE);
  assert_null (w);
  carom_world_def_init (&def, sizeof def);
  def.restitution = 1.01;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_ARGUMENT);
  carom_world_def_init (&def, sizeof def);
  def.substeps = 0;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_ARGUMENT);
  carom_world_def_init (&def, sizeof def);
  def.iterations = -3;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_ARGUMENT);
  carom_world_def_init (&def, sizeof def);
  def.size = 8;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_null (w);
}

static void test_bad_time_step_changes_nothing (void **state)
{
  carom_world *w = *state;
  carom_body_id id;
  carom_body_def def;
  const double bad[] = {0.0, -0.01, NAN, INFINITY, -INFINITY};
  size_t i;
  double x, y, vx, vy;
  carom_body_def_init (&def, sizeof def);
  def.vx = 1.0;
  carom_world_set_gravity (w, 0, -10);
  assert_status (carom_world_add_circle (w, &def, 1.0, &id), CAROM_OK);
  for (i = 0; i < sizeof bad / sizeof bad[0]; ++i)
    assert_status (carom_world_update (w, bad[i]), CAROM_ERR_BAD_TIME_STEP);
  carom_body_get_position (w, id, &x, &y);
  carom_body_get_velocity (w, id, &vx, &vy);
  assert_true (x == 0.0 && y == 0.0 && vx == 1.0 && vy == 0.0);
  assert_status (carom_world_set_gravity (w, NAN, 0), CAROM_ERR_NOT_FINITE);
  carom_world_get_gravity (w, &x, &y);
  assert_true (x == 0.0 && y == -10.0);
}

/* Leapfrog integration is exact for uniform gravity: the closed form
 * x = x0 + v0 t + g t^2 / 2 holds to rounding after any number of steps. */
static void test_projectile_matches_closed_form (void **state)
{
  carom_world *w = *state;
  carom_body_def def;
  carom_body_id id;
  const double g = -9.81, dt = 1.0 / 60, vx0 = 3.0, vy0 = 12.0;
  double x, y, vx, vy, angle;
  int step;
  carom_world_set_gravity (w, 0.0, g);
  carom_body_def_init (&def, sizeof def);
  def.x = 1.0, def.y = 2.0, def.vx = vx0, def.vy = vy0, def.spin = 0.5;
  assert_status (carom_world_add_regular (w, &def, 5, 0.3, &id), CAROM_OK);
  for (step = 1; step <= 300; ++step)
    {
      double t = step * dt;
      assert_status (carom_world_update (w, dt), CAROM_OK);
      carom_body_get_position (w, id, &x, &y);
      carom_body_get_velocity (w, id, &vx, &vy);
      carom_body_get_angle (w, id, &angle);
      assert_near_rel (x, 1.0 + vx0 * t, 1e-12);
      assert_near_abs (y, 2.0 + vy0 * t + 0.5 * g * t * t, 1e-11);
      assert_near_abs (vy, vy0 + g * t, 1e-11);
      assert_near_rel (angle, 0.5 * t, 1e-12);
    }
}

static void test_free_fall_with_substeps (void **state)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def bd;
  carom_body_id id;
  double y;
  int step;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -9.81;
  def.substeps = 4;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  carom_body_def_init (&bd, sizeof bd);
  bd.y = 100.0;
  assert_status (carom_world_add_box (w, &bd, 1, 1, &id), CAROM_OK);
  for (step = 0; step < 120; ++step)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_position (w, id, NULL, &y);
  assert_near_rel (y, 100.0 - 0.5 * 9.81 * 4.0, 1e-12);
  carom_world_destroy (w);
}

/* Two worlds in one process do not see each other. */
static void test_two_worlds_are_independent (void **state)
{
  carom_world *a = NULL, *b = NULL;
  carom_body_id ia, ib;
  double ya, yb;
  int step;
  (void) state;
  assert_status (carom_world_init (&a, NULL), CAROM_OK);
  assert_status (carom_world_init (&b, NULL), CAROM_OK);
  carom_world_set_gravity (a, 0, -10);
  assert_status (carom_world_add_circle (a, NULL, 1.0, &ia), CAROM_OK);
  assert_status (carom_world_add_circle (b, NULL, 1.0, &ib), CAROM_OK);
  assert_true (ia == ib); /* the same first id in each world ... */
  for (step = 0; step < 10; ++step)
    {
      carom_world_update (a, 0.1);
      carom_world_update (b, 0.1);
    }
  carom_body_get_position (a, ia, NULL, &ya);
  carom_body_get_position (b, ib, NULL, &yb);
  assert_near_rel (ya, -0.5 * 10 * 1.0, 1e-12); /* ... but separate bodies */
  assert_true (yb == 0.0);
  carom_world_remove_body (a, ia);
  assert_status (carom_body_check (b, ib), CAROM_OK);
  carom_world_destroy (a);
  assert_status (carom_world_update (b, 0.1), CAROM_OK);
  carom_world_destroy (b);
}

/* A world with contacts of every kind and every effect on: a stack, a
 * bouncing pair, friction, damping, sleeping, central gravity. */
static carom_world *busy_world (void)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  int i;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 0.4;
  def.restitution = 0.3;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_damping (w, 0.05, 0.05), CAROM_OK);
  assert_status (carom_world_set_sleeping (w, 1), CAROM_OK);
  assert_status (carom_world_set_central_gravity (w, 0, -50, 100, 1), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -0.5;
  assert_status (carom_world_add_box (w, &d, 40, 1, NULL), CAROM_OK);
  for (i = 0; i < 6; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.x = 0.02 * i, d.y = 0.5 + 1.01 * i, d.angle = 0.01 * i;
      assert_status (carom_world_add_box (w, &d, 1, 1, NULL), CAROM_OK);
    }
  carom_body_def_init (&d, sizeof d);
  d.x = -5, d.y = 3, d.vx = 4, d.restitution = 0.9;
  assert_status (carom_world_add_circle (w, &d, 0.4, NULL), CAROM_OK);
  d.x = 5, d.vx = -4, d.spin = 2;
  assert_status (carom_world_add_regular (w, &d, 5, 0.6, NULL), CAROM_OK);
  return w;
}

/* The same world stepped alone and stepped in turn with another one (with
 * one contact, so anything counted across worlds changes parity): the same
 * state, bit for bit, at every step, and the other one too. */
static void test_two_busy_worlds_interleaved_equal_alone (void **state)
{
  carom_world *alone = busy_world (), *mixed = busy_world (), *other = NULL, *other_alone = NULL;
  carom_world_def def;
  carom_body_def d;
  int step, k, most = 0, asleep = 0;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -3.0;
  for (k = 0; k < 2; ++k)
    {
      carom_world **w = k ? &other_alone : &other;
      assert_status (carom_world_init (w, &def), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
      d.type = CAROM_STATIC, d.y = -0.5;
      assert_status (carom_world_add_box (*w, &d, 10, 1, NULL), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
      d.y = 0.6, d.spin = 0.5;
      assert_status (carom_world_add_circle (*w, &d, 0.5, NULL), CAROM_OK);
    }
  for (step = 0; step < 300; ++step)
    {
      carom_body_id ids[16];
      int32_t n, i;
      assert_status (carom_world_update (alone, 1.0 / 60), CAROM_OK);
      assert_status (carom_world_update (other_alone, 1.0 / 60), CAROM_OK);
      most = carom_world_contact_count (alone) > most ? carom_world_contact_count (alone) : most;
      n = carom_world_get_bodies (alone, ids, 16);
      for (i = 0; i < n; ++i)
        {
          int32_t awake;
          assert_status (carom_body_is_awake (alone, ids[i], &awake), CAROM_OK);
          asleep += !awake;
        }
    }
  for (step = 0; step < 300; ++step)
    {
      assert_status (carom_world_update (mixed, 1.0 / 60), CAROM_OK);
      assert_status (carom_world_update (other, 1.0 / 60), CAROM_OK);
    }
  /* it did collide, and some of it slept; the other world has its one contact */
  assert_true (most > 10 && asleep > 0 && carom_world_contact_count (other) == 1);
  assert_true (world_state_hash (alone) == world_state_hash (mixed));
  assert_true (world_state_hash (other_alone) == world_state_hash (other));
  carom_world_destroy (alone);
  carom_world_destroy (mixed);
  carom_world_destroy (other);
  carom_world_destroy (other_alone);
}

/* An allocator that only counts. */
typedef struct counting {
  long calls;
} counting;

static void *count_alloc (size_t size, void *user)
{
  ((counting *) user)->calls++;
  return malloc (size);
}

static void count_free (void *ptr, size_t size, void *user)
{
  (void) size, (void) user;
  free (ptr);
}

/* No allocation in a steady step: once the contacts are there, an update
 * asks the allocator for nothing (a pile of 30 boxes and circles settling
 * on a floor, then 300 more steps with the same contacts). */
static void test_steady_steps_allocate_nothing (void **state)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  counting c = { 0 };
  long settled;
  int i, step, contacts;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 0.5;
  def.allocator.alloc = count_alloc, def.allocator.free = count_free, def.allocator.user = &c;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -0.5;
  assert_status (carom_world_add_box (w, &d, 40, 1, NULL), CAROM_OK);
  for (i = 0; i < 30; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.x = -3.0 + (i % 6) * 1.1, d.y = 0.5 + (i / 6) * 1.05;
      if (i % 2)
        assert_status (carom_world_add_box (w, &d, 1, 1, NULL), CAROM_OK);
      else
        assert_status (carom_world_add_circle (w, &d, 0.5, NULL), CAROM_OK);
    }
  /* and a row of boxes on the ground 0.013 apart: near enough for the broad
   * phase (each box's bounds grow by its slop, 0.005, and its reach in a
   * step, 0.0028), too far for a contact (the pair's margin, 0.0106), so
   * each step has pairs without a contact among those with one */
  for (i = 0; i < 6; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.x = 10.0 + i * 1.013, d.y = 0.5;
      assert_status (carom_world_add_box (w, &d, 1, 1, NULL), CAROM_OK);
    }
  for (step = 0; step < 300; ++step)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  settled = c.calls;
  contacts = carom_world_contact_count (w);
  for (step = 0; step < 300; ++step)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  assert_int_equal (carom_world_contact_count (w), contacts);
  assert_true (contacts > 30);
  assert_int_equal (c.calls, settled);
  carom_world_destroy (w);
}

/* Removing a body drops its contacts and keeps the others as they were:
 * boxes resting in a row on the ground (each with its own two points), the
 * middle one removed; every remaining contact point reads as it did. */
typedef struct seen_point {
  carom_body_id a, b;
  double px, py, nx, ny, depth;
} seen_point;

static int32_t read_contacts (const carom_world *w, seen_point *out, int32_t cap)
{
  int32_t i, n = carom_world_contact_count (w);
  assert_true (n <= cap);
  for (i = 0; i < n; ++i)
    assert_status (carom_world_get_contact (w, i, &out[i].a, &out[i].b, &out[i].px, &out[i].py, &out[i].nx,
                                            &out[i].ny, &out[i].depth),
                   CAROM_OK);
  return n;
}

static void test_removing_a_body_keeps_the_other_contacts (void **state)
{
  carom_world *w = world_with (0.0, -10.0, 0.0, 0.5);
  carom_body_def d;
  carom_body_id ids[7];
  seen_point before[64], after[64];
  int32_t nb, na, i, j, kept = 0;
  int step;
  (void) state;
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 40.0, 1.0);
  for (i = 0; i < 7; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.x = -6.0 + 2.0 * i, d.y = 0.5, d.angle = 0.01 * i;
      assert_status (carom_world_add_box (w, &d, 1, 1, &ids[i]), CAROM_OK);
    }
  for (step = 0; step < 30; ++step)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  nb = read_contacts (w, before, 64);
  assert_true (nb >= 14);
  assert_status (carom_world_remove_body (w, ids[2]), CAROM_OK);
  na = read_contacts (w, after, 64);
  for (i = 0, j = 0; i < nb; ++i)
    {
      if (before[i].a == ids[2] || before[i].b == ids[2])
        continue;
      assert_true (j < na);
      assert_true (after[j].a == before[i].a && after[j].b == before[i].b);
      assert_true (after[j].px == before[i].px && after[j].py == before[i].py && after[j].nx == before[i].nx
                   && after[j].ny == before[i].ny && after[j].depth == before[i].depth);
      ++j, ++kept;
    }
  assert_int_equal (j, na);
  assert_true (kept >= 12);
  carom_world_destroy (w);
}

static void test_get_bodies (void **state)
{
  carom_world *w = *state;
  carom_body_id ids[3], out[3];
  int i;
  for (i = 0; i < 3; ++i)
    assert_status (carom_world_add_circle (w, NULL, 1.0 + i, &ids[i]), CAROM_OK);
  assert_int_equal (carom_world_get_bodies (w, NULL, 0), 3);
  assert_int_equal (carom_world_get_bodies (w, out, 3), 3);
  for (i = 0; i < 3; ++i)
    assert_true (out[i] == ids[i]);
  carom_world_remove_body (w, ids[1]);
  assert_int_equal (carom_world_get_bodies (w, out, 1), 2);
  assert_true (out[0] == ids[0]);
}

/* Versioned structs: def_init writes no byte past the size the caller gives,
 * and refuses sizes it does not know (a newer caller's larger struct, or
 * less than version 0.1's). */
static void test_def_init_respects_the_callers_size (void **state)
{
  unsigned char buf[sizeof (carom_world_def) + 32];
  carom_world_def def;
  carom_body_def bd;
  carom_world *w = NULL;
  size_t i;
  (void) state;
  memset (buf, 0xAB, sizeof buf);
  assert_status (carom_world_def_init ((carom_world_def *) (void *) buf, sizeof (carom_world_def)), CAROM_OK);
  for (i = sizeof (carom_world_def); i < sizeof buf; ++i)
    assert_int_equal (buf[i], 0xAB);
  memset (buf, 0xAB, sizeof buf);
  assert_status (carom_world_def_init ((carom_world_def *) (void *) buf, sizeof (carom_world_def) + 8),
                 CAROM_ERR_BAD_STRUCT_SIZE);
  for (i = 0; i < sizeof buf; ++i)
    assert_int_equal (buf[i], 0xAB); /* refused: nothing written */
  assert_status (carom_world_def_init (&def, 4), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_status (carom_world_def_init (NULL, sizeof def), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_body_def_init (&bd, sizeof bd + 1), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_status (carom_body_def_init (&bd, sizeof bd), CAROM_OK);
  assert_int_equal (bd.size, sizeof bd);
  assert_true (bd.density == 1.0 && bd.restitution < 0.0);
  /* a def claiming to be larger than this library's is refused by init */
  assert_status (carom_world_def_init (&def, sizeof def), CAROM_OK);
  def.size = sizeof def + 8;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_null (w);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_init_destroy_and_null),
    cmocka_unit_test (test_bad_world_defs),
    cmocka_unit_test (test_def_init_respects_the_callers_size),
    cmocka_unit_test_setup_teardown (test_bad_time_step_changes_nothing, world_setup, world_teardown),
    cmocka_unit_test_setup_teardown (test_projectile_matches_closed_form, world_setup, world_teardown),
    cmocka_unit_test (test_free_fall_with_substeps),
    cmocka_unit_test (test_two_worlds_are_independent),
    cmocka_unit_test (test_two_busy_worlds_interleaved_equal_alone),
    cmocka_unit_test (test_steady_steps_allocate_nothing),
    cmocka_unit_test (test_removing_a_body_keeps_the_other_contacts),
    cmocka_unit_test_setup_teardown (test_get_bodies, world_setup, world_teardown),
  };
  return cmocka_run_group_tests_name ("world", tests, NULL, NULL);
}
