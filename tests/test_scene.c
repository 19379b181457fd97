/* Scene loading: good text gives the bodies and settings it describes; any
 * bad line is reported with its line and cause and creates nothing. */
#include "support.h"

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

static carom_world *load (const char *text)
{
  carom_world *w = NULL;
  carom_scene_error err;
  err.size = sizeof err;
  if (carom_scene_load_text (&w, text, strlen (text), NULL, &err) != CAROM_OK)
    fail_msg ("scene rejected: %s", err.message);
  assert_non_null (w);
  return w;
}

/* The id of the i-th body in creation order. */
static carom_body_id body_at (const carom_world *w, int32_t i)
{
  carom_body_id ids[64];
  int32_t n = carom_world_get_bodies (w, ids, 64);
  assert_true (i < n && i < 64);
  return ids[i];
}

/* The world's joints in slot order (the order of the scene's joint lines),
 * through the debug draw: the API has no list of joints. */
typedef struct joint_list {
  carom_joint_id ids[64];
  int32_t count;
} joint_list;

static void joint_list_add (carom_joint_type type, const double *xy, carom_joint_id id, void *user)
{
  joint_list *l = user;
  (void) type;
  (void) xy;
  if (l->count < 64)
    l->ids[l->count] = id;
  l->count++;
}

static carom_joint_id joint_at (const carom_world *w, int32_t i)
{
  carom_debug_draw draw;
  joint_list l;
  l.count = 0;
  assert_status (carom_debug_draw_init (&draw, sizeof draw), CAROM_OK);
  draw.draw_bodies = draw.draw_contacts = 0;
  draw.joint = joint_list_add;
  draw.user = &l;
  assert_status (carom_world_draw (w, &draw), CAROM_OK);
  assert_int_equal (l.count, carom_world_joint_count (w));
  assert_true (i < l.count && i < 64);
  return l.ids[i];
}

/* Joint i is of `type` between bodies a and b (-1: the world) in creation
 * order, with its anchors now at (ax, ay) and (bx, by). */
static void assert_joint (const carom_world *w, int32_t i, carom_joint_type type, int32_t a, int32_t b, double ax,
                          double ay, double bx, double by)
{
  carom_joint_id id = joint_at (w, i);
  carom_joint_type t;
  carom_body_id ja, jb;
  double x0, y0, x1, y1;
  assert_status (carom_joint_get_bodies (w, id, &t, &ja, &jb), CAROM_OK);
  assert_int_equal (t, type);
  assert_true (ja == (a < 0 ? CAROM_NULL_BODY : body_at (w, a)));
  assert_true (jb == body_at (w, b));
  assert_status (carom_joint_get_anchors (w, id, &x0, &y0, &x1, &y1), CAROM_OK);
  assert_near_abs (x0, ax, 1e-12);
  assert_near_abs (y0, ay, 1e-12);
  assert_near_abs (x1, bx, 1e-12);
  assert_near_abs (y1, by, 1e-12);
}

static void test_settings_and_bodies (void **state)
{
  const char *text = "# a small scene\n"
                     "gravity 0.5 -9.81\n"
                     "restitution 0.25\n"
                     "friction 0.4\n"
                     "substeps 2\n"
                     "iterations 12\n"
                     "circle 0.5 at 1 2 velocity 3 -4 spin 1.5 density 2\n"
                     "box 2 1 at -1 0.5 angle 0.3 density 3 restitution 0.9 friction 0.1\n"
                     "regular 4 2 at 0 -3 static\n"
                     "polygon 0 0 3 0 0 3 at 5 5\n";
  carom_world *w = load (text);
  carom_body_id id;
  carom_body_type type;
  carom_shape_kind kind;
  double gx, gy, x, y, vx, vy, a, m, inertia, area, r, e, mu;
  (void) state;

  assert_int_equal (carom_world_body_count (w), 4);
  assert_status (carom_world_get_gravity (w, &gx, &gy), CAROM_OK);
  assert_near_rel (gx, 0.5, 1e-15);
  assert_near_rel (gy, -9.81, 1e-15);

  id = body_at (w, 0);
  assert_status (carom_body_get_shape (w, id, &kind, &r), CAROM_OK);
  assert_int_equal (kind, CAROM_SHAPE_CIRCLE);
  assert_near_rel (r, 0.5, 1e-15);
  carom_body_get_position (w, id, &x, &y);
  assert_near_rel (x, 1.0, 1e-15);
  assert_near_rel (y, 2.0, 1e-15);
  carom_body_get_velocity (w, id, &vx, &vy);
  assert_near_rel (vx, 3.0, 1e-15);
  assert_near_rel (vy, -4.0, 1e-15);
  carom_body_get_spin (w, id, &a);
  assert_near_rel (a, 1.5, 1e-15);
  carom_body_get_mass (w, id, &m, &inertia, &area);
  assert_near_rel (m, 2.0 * pi * 0.25, 1e-12);
  assert_near_rel (inertia, 0.5 * m * 0.25, 1e-12);
  /* no material options: the scene's world defaults */
  carom_body_get_material (w, id, &e, &mu);
  assert_near_rel (e, 0.25, 1e-15);
  assert_near_rel (mu, 0.4, 1e-15);

  id = body_at (w, 1);
  carom_body_get_position (w, id, &x, &y);
  assert_near_rel (x, -1.0, 1e-15);
  assert_near_rel (y, 0.5, 1e-15);
  carom_body_get_angle (w, id, &a);
  assert_near_rel (a, 0.3, 1e-15);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  assert_near_rel (m, 6.0, 1e-12);
  assert_near_rel (inertia, 6.0 * 5.0 / 12.0, 1e-12);
  carom_body_get_material (w, id, &e, &mu);
  assert_near_rel (e, 0.9, 1e-15);
  assert_near_rel (mu, 0.1, 1e-15);
  carom_body_get_type (w, id, &type);
  assert_int_equal (type, CAROM_DYNAMIC);

  id = body_at (w, 2);
  carom_body_get_type (w, id, &type);
  assert_int_equal (type, CAROM_STATIC);
  carom_body_get_mass (w, id, &m, NULL, &area);
  assert_true (m == 0.0);
  assert_near_rel (area, 4.0, 1e-12);

  /* the polygon's centroid (1, 1) goes to `at` */
  id = body_at (w, 3);
  carom_body_get_position (w, id, &x, &y);
  assert_near_rel (x, 5.0, 1e-12);
  assert_near_rel (y, 5.0, 1e-12);
  carom_body_get_mass (w, id, &m, NULL, NULL);
  assert_near_rel (m, 4.5, 1e-12);
  {
    double xy[6], lo_x = 1e9, lo_y = 1e9;
    int32_t n, i;
    assert_status (carom_body_get_vertices (w, id, xy, 3, &n), CAROM_OK);
    assert_int_equal (n, 3);
    for (i = 0; i < 3; ++i)
      {
        lo_x = fmin (lo_x, xy[2 * i]);
        lo_y = fmin (lo_y, xy[2 * i + 1]);
      }
    assert_near_abs (lo_x, 4.0, 1e-12);
    assert_near_abs (lo_y, 4.0, 1e-12);
  }
  carom_world_destroy (w);
}

/* bounds: four static walls outside the rectangle, thickness 5% of the
 * smaller side, with the line's material. */
static void test_bounds (void **state)
{
  carom_world *w = load ("bounds 0 0 10 4 restitution 1 friction 0\ncircle 1 at 5 2\n");
  double lo_x = 1e9, lo_y = 1e9, hi_x = -1e9, hi_y = -1e9;
  int32_t i;
  (void) state;
  assert_int_equal (carom_world_body_count (w), 5);
  for (i = 0; i < 4; ++i)
    {
      carom_body_id id = body_at (w, i);
      carom_body_type type;
      double xy[8], e, mu;
      int32_t n, k;
      carom_body_get_type (w, id, &type);
      assert_int_equal (type, CAROM_STATIC);
      carom_body_get_material (w, id, &e, &mu);
      assert_true (e == 1.0 && mu == 0.0);
      carom_body_get_vertices (w, id, xy, 4, &n);
      assert_int_equal (n, 4);
      for (k = 0; k < 4; ++k)
        {
          double x = xy[2 * k], y = xy[2 * k + 1];
          lo_x = fmin (lo_x, x), hi_x = fmax (hi_x, x);
          lo_y = fmin (lo_y, y), hi_y = fmax (hi_y, y);
          /* nothing of a wall inside the rectangle */
          assert_false (x > 1e-12 && x < 10 - 1e-12 && y > 1e-12 && y < 4 - 1e-12);
        }
    }
  assert_near_abs (lo_x, -0.2, 1e-12);
  assert_near_abs (hi_x, 10.2, 1e-12);
  assert_near_abs (lo_y, -0.2, 1e-12);
  assert_near_abs (hi_y, 4.2, 1e-12);
  carom_world_destroy (w);
}

static void test_comments_blank_lines_crlf (void **state)
{
  const char *variants[] = {
    "# header\n\n   \ncircle 1 at 1 2 # trailing comment\n\t box\t2 3  at 4 5\n# end",
    "# header\r\n\r\n   \r\ncircle 1 at 1 2 # trailing comment\r\n\t box\t2 3  at 4 5\r\n# end\r\n",
    "# header\r\r   \rcircle 1 at 1 2 # trailing comment\r\t box\t2 3  at 4 5\r# end\r",
    "\xEF\xBB\xBF# header\n\ncircle 1 at 1 2#comment right after\nbox 2 3 at 4 5\n",
  };
  size_t k;
  (void) state;
  for (k = 0; k < sizeof variants / sizeof variants[0]; ++k)
    {
      carom_world *w = load (variants[k]);
      double x, y;
      assert_int_equal (carom_world_body_count (w), 2);
      carom_body_get_position (w, body_at (w, 1), &x, &y);
      assert_true (x == 4.0 && y == 5.0);
      carom_world_destroy (w);
    }
}

static void test_empty_and_comment_only (void **state)
{
  carom_world *w = load ("");
  (void) state;
  assert_int_equal (carom_world_body_count (w), 0);
  carom_world_destroy (w);
  w = load ("# nothing here\n\n");
  assert_int_equal (carom_world_body_count (w), 0);
  carom_world_destroy (w);
  /* text need not be NUL-terminated: only `length` bytes are read */
  {
    carom_world *w2 = NULL;
    assert_status (carom_scene_load_text (&w2, "circle 1circle 2", 8, NULL, NULL), CAROM_OK);
    assert_int_equal (carom_world_body_count (w2), 1);
    carom_world_destroy (w2);
  }
}

/* Settings are applied before any body, wherever they are written; a later
 * setting overrides an earlier one. */
static void test_settings_order (void **state)
{
  carom_world *w = load ("circle 1\ngravity 0 -1\nrestitution 0.5\ngravity 0 -2\n");
  double gx, gy, e;
  (void) state;
  carom_world_get_gravity (w, &gx, &gy);
  assert_true (gx == 0.0 && gy == -2.0);
  carom_body_get_material (w, body_at (w, 0), &e, NULL);
  assert_true (e == 0.5);
  carom_world_destroy (w);
}

/* def supplies what the scene does not set. */
static void test_def_defaults (void **state)
{
  carom_world_def def;
  carom_world *w = NULL;
  double gx, gy;
  const char *t1 = "circle 1\n", *t2 = "gravity 1 2\n";
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -3.0;
  assert_status (carom_scene_load_text (&w, t1, strlen (t1), &def, NULL), CAROM_OK);
  carom_world_get_gravity (w, &gx, &gy);
  assert_true (gx == 0.0 && gy == -3.0);
  carom_world_destroy (w);
  assert_status (carom_scene_load_text (&w, t2, strlen (t2), &def, NULL), CAROM_OK);
  carom_world_get_gravity (w, &gx, &gy);
  assert_true (gx == 1.0 && gy == 2.0);
  carom_world_destroy (w);

  def.size = 3;
  w = (carom_world *) &def; /* must be reset to NULL */
  assert_status (carom_scene_load_text (&w, t1, strlen (t1), &def, NULL), CAROM_ERR_BAD_STRUCT_SIZE);
  assert_null (w);
}

/* The version 0.2 options: kinematic, sensor and the filter. */
static void test_kinematic_sensor_and_filter_options (void **state)
{
  carom_world *w = load ("gravity 0 -10\n"
                         "box 6 0.5 kinematic velocity 1 0 spin 0.5\n"
                         "box 4 1 at 0 3 static sensor\n"
                         "circle 0.5 at 0 6 category 4 mask 4294967295 group -7\n");
  carom_body_type type;
  uint32_t category, mask;
  int32_t group, sensor;
  double vx, vy, spin;
  (void) state;
  assert_status (carom_body_get_type (w, body_at (w, 0), &type), CAROM_OK);
  assert_int_equal (type, CAROM_KINEMATIC);
  assert_status (carom_body_get_velocity (w, body_at (w, 0), &vx, &vy), CAROM_OK);
  assert_status (carom_body_get_spin (w, body_at (w, 0), &spin), CAROM_OK);
  assert_true (vx == 1.0 && vy == 0.0 && spin == 0.5);
  assert_status (carom_body_is_sensor (w, body_at (w, 1), &sensor), CAROM_OK);
  assert_int_equal (sensor, 1);
  assert_status (carom_body_is_sensor (w, body_at (w, 2), &sensor), CAROM_OK);
  assert_int_equal (sensor, 0);
  assert_status (carom_body_get_filter (w, body_at (w, 2), &category, &mask, &group), CAROM_OK);
  assert_true (category == 4u && mask == 0xffffffffu && group == -7);
  assert_status (carom_body_get_filter (w, body_at (w, 1), &category, &mask, &group), CAROM_OK);
  assert_true (category == 1u && mask == 0xffffffffu && group == 0);
  carom_world_destroy (w);
}

/* Every joint statement makes the joint it says, between the bodies it
 * names (`world`: CAROM_NULL_BODY), whether they come before or after it. */
static void test_joint_statements (void **state)
{
  carom_world *w = load ("gravity 0 -10\n"
                         "joint revolute world bob at 0 5 limit -1 1 motor 0.5 20 spring 2 0.5\n"
                         "circle 0.25 at 0 3 name bob\n"
                         "box 8 0.5 at 0 -1 static name ground\n"
                         "box 1 0.5 at 0 0 name slider\n"
                         "joint prismatic ground slider at 0 0 axis 1 0 limit -2 2 motor 1 100 spring 1 0.5 collide\n"
                         "joint wheel slider wheel at 0.5 -0.3 axis 0 1 limit -0.2 0.2 motor -3 40 spring 4 0.7\n"
                         "circle 0.2 at 0.5 -0.3 name wheel\n"
                         "joint distance bob slider at 0 3 to 0 0.25 length 2.5 limit 2 3 spring 3 0.1 motor 0 5\n"
                         "joint weld slider Slider at -0.5 0.25 spring 5 1 collide\n"
                         "regular 5 0.3 at -0.5 0.5 name Slider\n"
                         "joint motor ground Slider force 200 torque 20\n"
                         "joint mouse bob at 0.1 3.1 force 1000 spring 6 0.8\n"
                         "compound at 3 3 name table\n"
                         "  box 1 0.1 at 0 0.5\n"
                         "end\n"
                         "joint weld world table at 3 3.5\n");
  double x, y;
  (void) state;
  assert_int_equal (carom_world_body_count (w), 6);
  assert_int_equal (carom_world_joint_count (w), 8);
  assert_true ((carom_world_get_effects (w) & CAROM_EFFECT_JOINTS) != 0);
  /* bodies in file order: bob 0, ground 1, slider 2, wheel 3, Slider 4
   * (names are case-sensitive), table 5 */
  assert_joint (w, 0, CAROM_JOINT_REVOLUTE, -1, 0, 0, 5, 0, 5);
  assert_joint (w, 1, CAROM_JOINT_PRISMATIC, 1, 2, 0, 0, 0, 0);
  assert_joint (w, 2, CAROM_JOINT_WHEEL, 2, 3, 0.5, -0.3, 0.5, -0.3);
  assert_joint (w, 3, CAROM_JOINT_DISTANCE, 0, 2, 0, 3, 0, 0.25);
  assert_joint (w, 4, CAROM_JOINT_WELD, 2, 4, -0.5, 0.25, -0.5, 0.25);
  /* a motor joint holds b's centre; a mouse joint: the target, then b's
   * point */
  carom_body_get_position (w, body_at (w, 4), &x, &y);
  assert_joint (w, 5, CAROM_JOINT_MOTOR, 1, 4, x, y, x, y);
  assert_joint (w, 6, CAROM_JOINT_MOUSE, -1, 0, 0.1, 3.1, 0.1, 3.1);
  assert_joint (w, 7, CAROM_JOINT_WELD, -1, 5, 3, 3.5, 3, 3.5);
  carom_world_destroy (w);
}

/* The options reach the joint: a motor turns, a limit stops, a length is
 * held, a motor joint's force holds against gravity, `collide` lets the
 * joined bodies touch. */
static void test_joint_options (void **state)
{
  carom_world *w = load ("gravity 0 -10\n"
                         "circle 0.5 at 0 0 name wheel\n"
                         "joint revolute world wheel at 0 0 motor 3 1000\n"
                         "box 0.5 0.5 at 5 0 name slider\n"
                         "joint prismatic world slider at 5 0 axis 0 1 limit -0.5 0.5\n"
                         "circle 0.2 at 10 0 name bob\n"
                         "joint distance world bob at 10 2 to 10 0 length 3\n"
                         "box 1 1 at 15 0 name lifted\n"
                         "joint motor world lifted force 1000 torque 100\n"
                         "box 1 1 at 20 0 name p\n"
                         "box 1 1 at 20.5 0 name q\n"
                         "joint weld p q at 20.25 0 collide\n"
                         "box 1 1 at 25 0 name r\n"
                         "box 1 1 at 25.5 0 name t\n"
                         "joint weld r t at 25.25 0\n");
  carom_body_id a, b, pq[2];
  double spin, x, y, ax, ay, bx, by;
  int i;
  (void) state;
  for (i = 0; i < 120; ++i)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  carom_body_get_spin (w, body_at (w, 0), &spin);
  assert_near_abs (spin, 3.0, 1e-3);
  carom_body_get_position (w, body_at (w, 1), &x, &y);
  assert_near_abs (x, 5.0, 1e-6);
  assert_near_abs (y, -0.5, 0.02);
  assert_status (carom_joint_get_anchors (w, joint_at (w, 2), &ax, &ay, &bx, &by), CAROM_OK);
  assert_near_abs (hypot (bx - ax, by - ay), 3.0, 0.01);
  carom_body_get_position (w, body_at (w, 3), &x, &y);
  assert_near_abs (x, 15.0, 1e-3);
  assert_near_abs (y, 0.0, 1e-3);
  /* both welded pairs overlap: only the `collide` pair touches */
  pq[0] = body_at (w, 4), pq[1] = body_at (w, 5);
  assert_status (carom_world_detect (w), CAROM_OK);
  assert_true (carom_world_contact_count (w) > 0);
  for (i = 0; i < carom_world_contact_count (w); ++i)
    {
      carom_world_get_contact (w, i, &a, &b, NULL, NULL, NULL, NULL, NULL);
      assert_true ((a == pq[0] && b == pq[1]) || (a == pq[1] && b == pq[0]));
    }
  carom_world_destroy (w);
}

/* Many names: the table grows, and a chain of 300 links, each line naming
 * the link of the line after it, finds every one. */
static void test_joint_chain_of_names (void **state)
{
  size_t cap = 300 * 96 + 64, len = 0;
  char *text = malloc (cap);
  carom_world *w;
  int i;
  (void) state;
  assert_non_null (text);
  for (i = 0; i < 300; ++i)
    {
      if (i == 0)
        len += (size_t) snprintf (text + len, cap - len, "joint revolute world link0 at 0 0\n");
      else
        len += (size_t) snprintf (text + len, cap - len, "joint revolute link%d link%d at %d 0\n", i - 1, i, i);
      len += (size_t) snprintf (text + len, cap - len, "box 1 0.2 at %d.5 0 name link%d\n", i, i);
    }
  w = load (text);
  free (text);
  assert_int_equal (carom_world_body_count (w), 300);
  assert_int_equal (carom_world_joint_count (w), 300);
  assert_joint (w, 0, CAROM_JOINT_REVOLUTE, -1, 0, 0, 0, 0, 0);
  assert_joint (w, 42, CAROM_JOINT_REVOLUTE, 41, 42, 42, 0, 42, 0);
  carom_world_destroy (w);
}

typedef struct bad_case {
  const char *text;
  int32_t line;
  carom_status cause;
} bad_case;

static const bad_case bad_cases[] = {
  { "circle 1\nsphere 2\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 at 0 0 colour 3\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1\n\nbox 1 at 0 0\n", 3, CAROM_ERR_SCENE_SYNTAX },             /* missing H */
  { "circle\n", 1, CAROM_ERR_SCENE_SYNTAX },                                /* missing R */
  { "circle 1 2\n", 1, CAROM_ERR_SCENE_SYNTAX },                            /* one too many */
  { "circle 1 at 0\n", 1, CAROM_ERR_SCENE_SYNTAX },                         /* missing Y */
  { "circle 1 at 0 y\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1.5x\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 at 0x10 0\n", 1, CAROM_ERR_SCENE_SYNTAX },                    /* no hex */
  { "circle 1 at 1,5 0\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle abc\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 at 0 0 at 1 1\n", 1, CAROM_ERR_SCENE_SYNTAX },                /* twice */
  { "circle 1 static 3\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "gravity 0 -10 static\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "bounds 0 0 1 1 at 2 2\n", 1, CAROM_ERR_SCENE_SYNTAX },                 /* not a bounds option */
  { "circle nan\n", 1, CAROM_ERR_NOT_FINITE },
  { "circle 1 at inf 0\n", 1, CAROM_ERR_NOT_FINITE },
  { "circle 1 velocity -Infinity 0\n", 1, CAROM_ERR_NOT_FINITE },
  { "gravity 0 1e999\n", 1, CAROM_ERR_NOT_FINITE },
  { "circle -1\n", 1, CAROM_ERR_BAD_SIZE },
  { "circle 0\n", 1, CAROM_ERR_BAD_SIZE },
  { "box 1 -2\n", 1, CAROM_ERR_BAD_SIZE },
  { "bounds 0 0 -1 1\n", 1, CAROM_ERR_BAD_SIZE },
  { "regular 5 0\n", 1, CAROM_ERR_BAD_SIZE },
  { "circle 1 density 0\n", 1, CAROM_ERR_BAD_DENSITY },
  { "circle 1 restitution 1.5\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 friction -0.1\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "restitution -1\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "friction -1\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "substeps 0\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "substeps 1000000\n", 1, CAROM_ERR_BAD_ARGUMENT },                      /* the world's limit */
  { "substeps 1.5\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "iterations 0\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "regular 2 1\n", 1, CAROM_ERR_TOO_FEW_VERTICES },
  { "regular 5000 1\n", 1, CAROM_ERR_TOO_MANY_VERTICES },
  { "regular 4.5 1\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "polygon 0 0 1 0 1 1 0\n", 1, CAROM_ERR_SCENE_SYNTAX },                 /* odd count */
  { "polygon 0 0 1 0\n", 1, CAROM_ERR_SCENE_SYNTAX },                       /* fewer than 6 numbers */
  { "polygon 0 0 2 2 2 0 0 2\n", 1, CAROM_ERR_SELF_INTERSECTING },          /* bow tie */
  { "polygon 0 0 1 0 1 0 0 1\n", 1, CAROM_ERR_REPEATED_VERTEX },
  { "polygon 0 0 1 1 2 2\n", 1, CAROM_ERR_ZERO_AREA },
  { "circle 1 static velocity 1 0\n", 1, CAROM_ERR_STATIC_BODY },
  { "circle 1 static fixed\n", 1, CAROM_ERR_STATIC_BODY },
  { "circle 1 fixed spin 2\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "box 1 1 static kinematic\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "box 1 1 kinematic fixed\n", 1, CAROM_ERR_STATIC_BODY },
  { "box 1 1 sensor 1\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "box 1 1 category\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "box 1 1 category 1.5\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "box 1 1 mask -1\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "box 1 1 mask 4294967296\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1\nbox 1 1 group 3000000000\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "box 1 1 group 0.5\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "central 0 0 -5\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "central 0 0\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "damping -0.1\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "continuous 2\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1\ncentral 1e200 0 1\n", 2, CAROM_ERR_BAD_ARGUMENT },              /* beyond CAROM_MAX_MAGNITUDE */
  { "circle 1\ndamping 1e101\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 bullet static\nbox 1 1 bullet bullet\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "damping 1 2 3\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "effects\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "effects gravity warp\n", 1, CAROM_ERR_SCENE_SYNTAX },
  /* a named effect nothing uses is reported at the effects line */
  { "gravity 0 -10\neffects gravity friction\nbox 1 1\n", 2, CAROM_ERR_BAD_ARGUMENT },
  /* errors after good bodies, and a later line's error after good lines */
  { "circle 1\r\nbox 1 1\r\n# c\r\nbox 1 1 at 0 zero\r\n", 4, CAROM_ERR_SCENE_SYNTAX },
  { "polygon 0 0 1 0 0 1 at 1 1\nregular 6 1\ncircle 1 density -2\n", 3, CAROM_ERR_BAD_DENSITY },
  /* names */
  { "circle 1 name a\nbox 1 1 name a\n", 2, CAROM_ERR_SCENE_SYNTAX },               /* given twice */
  { "compound name a\n box 1 1\nend\ncircle 1 name a\n", 4, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name world\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name 2b\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a name b\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "compound\n box 1 1 name a\nend\n", 2, CAROM_ERR_SCENE_SYNTAX },               /* shapes have none */
  { "bounds 0 0 1 1 name a\n", 1, CAROM_ERR_SCENE_SYNTAX },
  /* joints: references */
  { "circle 1 name a\n\njoint revolute a b at 0 0\n", 3, CAROM_ERR_SCENE_SYNTAX }, /* unknown name */
  { "joint revolute world b at 0 0\ncircle 1 name a\n", 1, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute a a at 0 0\n", 2, CAROM_ERR_BAD_ARGUMENT },   /* a body to itself */
  { "circle 1 name a\njoint revolute a world at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX }, /* world only as A */
  { "circle 1 name a\njoint mouse world at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a static\ncircle 1 name b kinematic\njoint weld a b at 0 0\n", 3, CAROM_ERR_STATIC_BODY },
  { "joint revolute world a at 0 0\ncircle 1 name a static\n", 1, CAROM_ERR_STATIC_BODY },
  /* joints: malformed lines */
  { "circle 1 name a\njoint\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint hinge world a at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute world\n", 2, CAROM_ERR_SCENE_SYNTAX },         /* B missing */
  { "circle 1 name a\njoint revolute world 1 at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute world a\n", 2, CAROM_ERR_SCENE_SYNTAX },       /* no at */
  { "circle 1 name a\njoint prismatic world a at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX }, /* no axis */
  { "circle 1 name a\njoint distance world a at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX }, /* no to */
  { "circle 1 name a\njoint revolute world a at 0\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute world a at 0 0 at 1 1\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute world a at 0 0 axis 1 0\n", 2, CAROM_ERR_SCENE_SYNTAX }, /* not its option */
  { "circle 1 name a\njoint weld world a at 0 0 motor 1 1\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint motor world a at 0 0\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint mouse a at 0 0 collide\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute world a at 0 0 collide 1\n", 2, CAROM_ERR_SCENE_SYNTAX },
  { "circle 1 name a\njoint revolute world a at 0 x\n", 2, CAROM_ERR_SCENE_SYNTAX },
  /* joints: values, with the world's status */
  { "circle 1 name a\njoint revolute world a at 0 nan\n", 2, CAROM_ERR_NOT_FINITE },
  { "circle 1 name a\njoint revolute world a at 0 1e101\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint revolute world a at 0 0 limit 1 -1\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint revolute world a at 0 0 motor 1 -5\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint wheel world a at 0 0 axis 0 1 spring -1 0.5\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint wheel world a at 0 0 axis 0 1 spring 4 -0.5\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint prismatic world a at 0 0 axis 0 0\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint distance world a at 1 1 to 1 1\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint distance world a at 1 1 to 1 2 length 0\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint distance world a at 1 1 to 1 2 limit 3 2\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint motor world a force -1\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint motor world a torque -1\n", 2, CAROM_ERR_BAD_ARGUMENT },
  { "circle 1 name a\njoint mouse a at 0 0 force -1\n", 2, CAROM_ERR_BAD_ARGUMENT },
  /* a joint's values are checked on its line, its names once the file is
   * read: a later line's error comes first then */
  { "joint revolute world a at 0 0 limit 1 0\ncircle -1 name a\n", 1, CAROM_ERR_BAD_ARGUMENT },
  { "joint revolute world b at 0 0\ncircle -1 name a\n", 2, CAROM_ERR_BAD_SIZE },
  { "circle 1 name a\ncircle 1 name b\njoint weld a c at 0 0\njoint weld a d at 0 0\n", 3, CAROM_ERR_SCENE_SYNTAX },
  { "gravity 0 -10\neffects gravity joints\nbox 1 1\n", 2, CAROM_ERR_BAD_ARGUMENT }, /* no joint */
};


static void test_bad_lines (void **state)
{
  size_t k;
  (void) state;
  for (k = 0; k < sizeof bad_cases / sizeof bad_cases[0]; ++k)
    {
      const bad_case *c = &bad_cases[k];
      carom_world *w = (carom_world *) &k; /* must come back NULL */
      carom_scene_error err;
      char prefix[32];
      size_t len = strlen (c->text);
      carom_status s;
      memset (&err, 0x55, sizeof err);
      err.size = sizeof err;
      s = carom_scene_load_text (&w, c->text, len, NULL, &err);
      if (s != c->cause || err.line != c->line || err.cause != c->cause)
        fail_msg ("case %zu %s: status %d, line %d, cause %d (%s); wanted line %d cause %d", k, c->text, (int) s,
                  (int) err.line, (int) err.cause, err.message, (int) c->line, (int) c->cause);
      assert_null (w);
      snprintf (prefix, sizeof prefix, "%d: ", (int) c->line);
      if (strncmp (err.message, prefix, strlen (prefix)) != 0 || strlen (err.message) < strlen (prefix) + 5)
        fail_msg ("case %zu: message '%s'", k, err.message);
    }
}

/* A few messages read as they should. */
static void test_messages (void **state)
{
  struct {
    const char *text, *message;
  } cases[] = {
    { "\nsphere 2\n", "2: unknown statement 'sphere'" },
    { "circle 1 colour 3\n", "1: circle: unknown option 'colour'" },
    { "circle 1.5x\n", "1: circle: '1.5x' is not a number" },
    { "circle -1\n", "1: circle: radius R must be positive, got -1" },
    { "polygon 0 0 2 2 2 0 0 2\n", "1: polygon: the polygon's edges cross or touch each other" },
    { "box 1 1 name a\ncircle 1 name a\n", "2: circle: the name 'a' is already the body of line 1" },
    { "box 1 1 name a\n\njoint weld world b at 0 0\n", "3: joint weld: no body is named 'b'" },
    { "box 1 1 name a\njoint revolute world a at 0 0 limit 1 0\n",
      "2: joint revolute: the limit's lower end 1 is above its upper end 0" },
    { "box 1 1 name a static\njoint revolute world a at 0 0\n", "2: joint revolute: 'a' is not a dynamic body" },
    { "box 1 1 name a static\nbox 1 1 name b kinematic\njoint weld a b at 0 0\n",
      "3: joint weld: neither 'a' nor 'b' is a dynamic body" },
    { "box 1 1 name a\njoint prismatic world a at 0 0 axis 1 0 spring 2\n",
      "2: joint prismatic: option 'spring' needs 2 numbers" },
  };
  size_t k;
  (void) state;
  for (k = 0; k < sizeof cases / sizeof cases[0]; ++k)
    {
      carom_world *w = NULL;
      carom_scene_error err;
      err.size = sizeof err;
      carom_scene_load_text (&w, cases[k].text, strlen (cases[k].text), NULL, &err);
      assert_null (w);
      assert_string_equal (err.message, cases[k].message);
    }
}

/* `length` counts, not the NUL: a NUL byte inside the text is an error. */
static void test_nul_byte (void **state)
{
  static const char text[] = "circle 1\nbox 1 1 at 0 0\0 box 1 1\n";
  carom_world *w = NULL;
  carom_scene_error err;
  (void) state;
  err.size = sizeof err;
  assert_status (carom_scene_load_text (&w, text, sizeof text - 1, NULL, &err), CAROM_ERR_SCENE_SYNTAX);
  assert_null (w);
  assert_int_equal (err.line, 2);
}

static void test_error_struct_optional (void **state)
{
  carom_world *w = NULL;
  carom_scene_error err;
  const char *bad = "circle -1\n", *good = "circle 1\n";
  (void) state;
  assert_status (carom_scene_load_text (&w, bad, strlen (bad), NULL, NULL), CAROM_ERR_BAD_SIZE);
  assert_null (w);
  /* a wrong size field: the struct is left alone */
  memset (&err, 0x55, sizeof err);
  err.size = 12;
  assert_status (carom_scene_load_text (&w, bad, strlen (bad), NULL, &err), CAROM_ERR_BAD_SIZE);
  assert_int_equal (err.line, 0x55555555);
  /* success clears it */
  err.size = sizeof err;
  assert_status (carom_scene_load_text (&w, good, strlen (good), NULL, &err), CAROM_OK);
  assert_int_equal (err.line, 0);
  assert_int_equal (err.cause, CAROM_OK);
  assert_string_equal (err.message, "");
  carom_world_destroy (w);
}

static void test_null_arguments (void **state)
{
  carom_world *w = NULL;
  carom_scene_error err;
  (void) state;
  err.size = sizeof err;
  assert_status (carom_scene_load_text (NULL, "circle 1", 8, NULL, &err), CAROM_ERR_NULL_ARGUMENT);
  assert_int_equal (err.line, 0);
  assert_status (carom_scene_load_text (&w, NULL, 8, NULL, &err), CAROM_ERR_NULL_ARGUMENT);
  assert_null (w);
  assert_status (carom_scene_load_file (&w, NULL, NULL, &err), CAROM_ERR_NULL_ARGUMENT);
  assert_status (carom_scene_load_file (NULL, "scenes/thesis.scene", NULL, &err), CAROM_ERR_NULL_ARGUMENT);
}

/* No line-length limit: a 200-vertex polygon on one line. */
static void test_long_line (void **state)
{
  size_t cap = 200 * 64 + 64, len = 0;
  char *text = malloc (cap);
  carom_world *w;
  int32_t i, n;
  double area;
  (void) state;
  len += (size_t) snprintf (text + len, cap - len, "polygon");
  for (i = 0; i < 200; ++i)
    {
      double t = 2.0 * pi * i / 200.0;
      len += (size_t) snprintf (text + len, cap - len, " %.17g %.17g", 3.0 * cos (t), 3.0 * sin (t));
    }
  snprintf (text + len, cap - len, " at 1 2 angle 0.5\n");
  w = load (text);
  free (text);
  carom_body_get_vertices (w, body_at (w, 0), NULL, 0, &n);
  assert_int_equal (n, 200);
  carom_body_get_mass (w, body_at (w, 0), NULL, NULL, &area);
  assert_near_rel (area, 0.5 * 200 * 9.0 * sin (2.0 * pi / 200.0), 1e-9);
  carom_world_destroy (w);
}

/* Counting allocator: all scratch memory goes through the caller's
 * allocator, nothing is left behind, and an allocation failure anywhere gives
 * OUT_OF_MEMORY and no world. */
typedef struct counting {
  long live, calls, fail_at;
} counting;

static void *counting_alloc (size_t size, void *user)
{
  counting *c = user;
  if (c->fail_at >= 0 && c->calls++ >= c->fail_at)
    return NULL; /* calls are only counted while failures are injected */
  c->live++;
  return malloc (size);
}

static void counting_free (void *p, size_t size, void *user)
{
  counting *c = user;
  (void) size;
  c->live--;
  free (p);
}

static void test_allocator_and_out_of_memory (void **state)
{
  const char *text = "gravity 0 -10\njoint revolute p r at 3 3\nbounds 0 0 10 10\n"
                     "polygon 0 0 1 0 1 1 0.5 0.2 0 1 at 5 5 name p\nregular 7 1 at 2 2 name r\n"
                     "joint distance world r at 2 5 to 2 2\n";
  counting c = { 0, 0, -1 };
  carom_world_def def;
  carom_world *w = NULL;
  long k;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.allocator.alloc = counting_alloc;
  def.allocator.free = counting_free;
  def.allocator.user = &c;
  assert_status (carom_scene_load_text (&w, text, strlen (text), &def, NULL), CAROM_OK);
  assert_int_equal (carom_world_body_count (w), 6);
  assert_int_equal (carom_world_joint_count (w), 2);
  carom_world_destroy (w);
  assert_int_equal (c.live, 0);

  for (k = 0;; ++k)
    {
      carom_status s;
      carom_scene_error err;
      err.size = sizeof err;
      c.calls = 0;
      c.fail_at = k;
      s = carom_scene_load_text (&w, text, strlen (text), &def, &err);
      if (s == CAROM_OK)
        {
          carom_world_destroy (w);
          break;
        }
      assert_status (s, CAROM_ERR_OUT_OF_MEMORY);
      assert_null (w);
      assert_int_equal (c.live, 0);
      assert_true (k < 10000);
    }
  assert_int_equal (c.live, 0);
  assert_true (k > 3);
}

/* Numbers use '.' whatever the C locale says. */
static void test_locale_independent (void **state)
{
  const char *locales[] = { "de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "ru_RU.UTF-8" };
  size_t k;
  (void) state;
  for (k = 0; k < sizeof locales / sizeof locales[0]; ++k)
    if (setlocale (LC_NUMERIC, locales[k]))
      break;
  if (k == sizeof locales / sizeof locales[0])
    {
      setlocale (LC_NUMERIC, "C");
      skip ();
    }
  {
    carom_world *w = load ("circle 0.5 at 1.25 -2.5e-1\n");
    double x, y, r;
    carom_body_get_position (w, body_at (w, 0), &x, &y);
    carom_body_get_shape (w, body_at (w, 0), NULL, &r);
    setlocale (LC_NUMERIC, "C");
    assert_true (x == 1.25 && y == -0.25 && r == 0.5);
    carom_world_destroy (w);
  }
}

static void test_file_errors (void **state)
{
  carom_world *w = (carom_world *) &w; /* must come back NULL */
  carom_scene_error err;
  (void) state;
  err.size = sizeof err;
  assert_status (carom_scene_load_file (&w, "scenes/no-such-file.scene", NULL, &err), CAROM_ERR_IO);
  assert_null (w);
  assert_int_equal (err.line, 0);
  assert_int_equal (err.cause, CAROM_ERR_IO);
  assert_non_null (strstr (err.message, "No such file"));
  assert_non_null (strstr (err.message, "scenes/no-such-file.scene")); /* names the file */
  /* a directory opens but cannot be read */
  assert_status (carom_scene_load_file (&w, "scenes", NULL, &err), CAROM_ERR_IO);
  assert_null (w);
}

/* Effects: switched on by the lines that use them, or named. */
static void test_effects_statements (void **state)
{
  carom_world *w = load ("central 1 2 50 0.1\ndamping 0.5 0.25\neffects sleeping central-gravity fixed-rotation\n"
                         "box 1 1 at 3 0 fixed\ncircle 0.5 at -3 0\n");
  uint32_t e;
  int32_t awake = -1;
  double angle;
  carom_body_id box;
  int i;
  (void) state;
  e = carom_world_get_effects (w);
  assert_int_equal (e, CAROM_EFFECT_CENTRAL_GRAVITY | CAROM_EFFECT_DAMPING | CAROM_EFFECT_SLEEPING
                           | CAROM_EFFECT_FIXED_ROTATION | CAROM_EFFECT_CONTINUOUS);
  box = body_at (w, 0);
  for (i = 0; i < 60; ++i)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_angle (w, box, &angle);
  assert_true (angle == 0.0);
  assert_status (carom_body_is_awake (w, box, &awake), CAROM_OK);
  assert_int_equal (awake, 1); /* falling towards the centre: not at rest */
  carom_world_destroy (w);
}

/* Continuous collision is on unless switched off: `continuous 0` switches
 * it off even when named (the scene is then rejected, as for any effect
 * named but unused), `continuous 1` or naming it keeps it on, and `bullet`
 * gives it to one body of a world without it (the effect is then reported,
 * for that body). */
static void test_continuous_statement (void **state)
{
  static const char both[] = "continuous 0\neffects continuous\ncircle 0.5\n";
  carom_world *w = load ("circle 0.5\n");
  carom_scene_error err;
  (void) state;
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_world_destroy (w);
  w = load ("continuous 0\ncircle 0.5\n");
  assert_int_equal (carom_world_get_effects (w), 0);
  carom_world_destroy (w);
  w = load ("continuous 1\ncircle 0.5\n");
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_world_destroy (w);
  w = load ("effects continuous\ncircle 0.5\n");
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_world_destroy (w);
  w = load ("continuous 0\ncircle 0.5 bullet\n");
  assert_int_equal (carom_world_get_effects (w), CAROM_EFFECT_CONTINUOUS);
  carom_world_destroy (w);
  w = NULL;
  err.size = sizeof err;
  assert_status (carom_scene_load_text (&w, both, strlen (both), NULL, &err), CAROM_ERR_BAD_ARGUMENT);
  assert_null (w);
  assert_int_equal (err.line, 2);
  assert_non_null (strstr (err.message, "continuous"));
}

/* Every shipped scene loads, with the body and joint counts it promises. */
static void test_shipped_scenes (void **state)
{
  struct {
    const char *path;
    int32_t min_bodies, max_bodies, joints;
  } scenes[] = {
    { "scenes/thesis.scene", 13, 13, 0 },
    { "scenes/balls.scene", 54, 54, 0 },
    { "scenes/pyramid.scene", 211, 211, 0 },
    { "scenes/rain.scene", 2003, 2003, 0 },
    { "scenes/gas.scene", 504, 504, 0 },
    { "scenes/platform.scene", 10, 10, 0 },
    { "scenes/pendulum.scene", 4, 4, 3 },
    { "scenes/bridge.scene", 28, 28, 21 },
    { "scenes/ragdoll.scene", 20, 20, 9 },
    { "scenes/car.scene", 7, 7, 2 },
  };
  size_t k;
  (void) state;
  for (k = 0; k < sizeof scenes / sizeof scenes[0]; ++k)
    {
      carom_world *w = NULL;
      carom_scene_error err;
      int32_t n;
      err.size = sizeof err;
      if (carom_scene_load_file (&w, scenes[k].path, NULL, &err) != CAROM_OK)
        fail_msg ("%s:%s", scenes[k].path, err.message);
      n = carom_world_body_count (w);
      if (n < scenes[k].min_bodies || n > scenes[k].max_bodies)
        fail_msg ("%s: %d bodies", scenes[k].path, (int) n);
      if (carom_world_joint_count (w) != scenes[k].joints)
        fail_msg ("%s: %d joints", scenes[k].path, (int) carom_world_joint_count (w));
      carom_world_destroy (w);
    }
}

/* gas.scene promises bodies that do not overlap at the start. */
static void test_gas_starts_apart (void **state)
{
  carom_world *w = NULL;
  int32_t i, n;
  (void) state;
  assert_status (carom_scene_load_file (&w, "scenes/gas.scene", NULL, NULL), CAROM_OK);
  assert_status (carom_world_detect (w), CAROM_OK);
  n = carom_world_contact_count (w);
  for (i = 0; i < n; ++i)
    {
      double depth;
      carom_world_get_contact (w, i, NULL, NULL, NULL, NULL, NULL, NULL, &depth);
      assert_true (depth <= 0.0);
    }
  carom_world_destroy (w);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_settings_and_bodies),
    cmocka_unit_test (test_bounds),
    cmocka_unit_test (test_comments_blank_lines_crlf),
    cmocka_unit_test (test_empty_and_comment_only),
    cmocka_unit_test (test_settings_order),
    cmocka_unit_test (test_def_defaults),
    cmocka_unit_test (test_bad_lines),
    cmocka_unit_test (test_kinematic_sensor_and_filter_options),
    cmocka_unit_test (test_joint_statements),
    cmocka_unit_test (test_joint_options),
    cmocka_unit_test (test_joint_chain_of_names),
    cmocka_unit_test (test_messages),
    cmocka_unit_test (test_nul_byte),
    cmocka_unit_test (test_error_struct_optional),
    cmocka_unit_test (test_null_arguments),
    cmocka_unit_test (test_long_line),
    cmocka_unit_test (test_allocator_and_out_of_memory),
    cmocka_unit_test (test_locale_independent),
    cmocka_unit_test (test_file_errors),
    cmocka_unit_test (test_effects_statements),
    cmocka_unit_test (test_continuous_statement),
    cmocka_unit_test (test_shipped_scenes),
    cmocka_unit_test (test_gas_starts_apart),
  };
  return cmocka_run_group_tests (tests, NULL, NULL);
}
