/* Hard cases stay numerically stable: each test names its bound. The long
 * runs (pyramid, 100 000-step gas) live in the stress suite, not here. */
#include "support.h"

#include <math.h>
#include <string.h>

static void add_static_box (carom_world *w, double x, double y, double wd, double ht)
{
  carom_body_def d;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.x = x, d.y = y;
  assert_status (carom_world_add_box (w, &d, wd, ht, NULL), CAROM_OK);
}

/* Every body's state is finite. */
static void assert_world_finite (const carom_world *w)
{
  carom_body_id ids[512];
  int32_t n = carom_world_get_bodies (w, ids, 512), i;
  for (i = 0; i < n; ++i)
    {
      double x, y, a, vx, vy, s;
      carom_body_get_position (w, ids[i], &x, &y);
      carom_body_get_angle (w, ids[i], &a);
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      carom_body_get_spin (w, ids[i], &s);
      assert_true (isfinite (x) && isfinite (y) && isfinite (a) && isfinite (vx) && isfinite (vy) && isfinite (s));
    }
}

/* A stack of `n` boxes of side `size` on a ground at (ox, oy). Returns the
 * top box. */
static carom_body_id build_stack (carom_world *w, int n, double size, double ox, double oy)
{
  carom_body_def d;
  carom_body_id top = 0;
  int i;
  add_static_box (w, ox, oy - 0.5 * size, 20 * size, size);
  carom_body_def_init (&d, sizeof d);
  for (i = 0; i < n; ++i)
    {
      d.x = ox, d.y = oy + (i + 0.5) * size;
      assert_status (carom_world_add_box (w, &d, size, size, &top), CAROM_OK);
    }
  return top;
}

/* Case 1 (and 5, 6): a stack of 10 boxes, 10 s at 60 Hz. Bound: after it
 * settles (1 s), the top box's largest excursion from where it settled is
 * under 1% of its size, sideways under 0.1%. Checked at size 1 at the
 * origin, at 1e-3 and 1e3 scale (with gravity scaled), and at (1e6, 1e6). */
static void run_stack_case (double size, double ox, double oy)
{
  carom_world *w = world_with (0, -10 * size, 0, 0.6);
  carom_body_id top = build_stack (w, 10, size, ox, oy);
  double x0 = 0, y0 = 0, x, y, up = 0.0, side = 0.0;
  int step;
  for (step = 0; step < 600; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      carom_body_get_position (w, top, &x, &y);
      if (step == 59)
        x0 = x, y0 = y;
      if (step > 59)
        {
          up = fabs (y - y0) > up ? fabs (y - y0) : up;
          side = fabs (x - x0) > side ? fabs (x - x0) : side;
        }
    }
  assert_true (up < 0.01 * size);
  assert_true (side < 0.001 * size);
  /* and it stands where it was built, within the slop of each layer */
  assert_true (fabs (x - ox) < 0.001 * size);
  assert_true (fabs (y - (oy + 9.5 * size)) < 10 * 0.01 * size);
  assert_world_finite (w);
  carom_world_destroy (w);
}

static void test_stack_of_10_top_moves_under_1pct (void **state)
{
  (void) state;
  run_stack_case (1.0, 0.0, 0.0);
}

static void test_stack_scaled_1e_minus_3_and_1e3 (void **state)
{
  (void) state;
  run_stack_case (1e-3, 0.0, 0.0);
  run_stack_case (1e3, 0.0, 0.0);
}

/* Case 1b: a tower of 20 unit boxes built exactly touching, at the
 * defaults. Its contacts begin resting with no impulse to warm start from,
 * and support would reach its top only after 20 passes (2.5 steps), the
 * top falling freely until then; the cold start (shock.c) gives each
 * contact the weight it carries instead. Bound: over 10 s the top never
 * sags or moves sideways by more than 1e-9 of the tower's height. */
static void test_tower_built_at_rest_does_not_sag (void **state)
{
  carom_world *w = world_with (0, -10, 0, 0.6);
  carom_body_id top = CAROM_NULL_BODY;
  double x, y, worst = 0.0;
  int i, step;
  (void) state;
  add_static_box (w, 0, -0.5, 20, 1);
  for (i = 0; i < 20; ++i)
    top = add_box (w, CAROM_DYNAMIC, 0.0, 0.5 + i, 0.0, 1.0, 1.0);
  for (step = 0; step < 600; ++step)
    {
      carom_world_update (w, 1.0 / 60);
      carom_body_get_position (w, top, &x, &y);
      worst = fmax (worst, fmax (fabs (19.5 - y), fabs (x)));
    }
  assert_true (worst < 1e-9 * 20.0);
  carom_world_destroy (w);
}

/* Case 4: mass ratio 1000:1 on the ground, the heavy box above and below.
 * Bound: after 10 s both rest (speeds under 1e-3 of a size per second),
 * where they were built within 2 slops, no sideways creep. */
static void test_mass_ratio_1000_both_ways (void **state)
{
  int order;
  (void) state;
  for (order = 0; order < 2; ++order)
    {
      carom_world *w = world_with (0, -10, 0, 0.6);
      carom_body_def d;
      carom_body_id lower, upper;
      double vx, vy, x1, y1, x2, y2;
      int step;
      add_static_box (w, 0, -0.5, 20, 1);
      carom_body_def_init (&d, sizeof d);
      d.y = 0.5, d.density = order ? 1000.0 : 1.0;
      assert_status (carom_world_add_box (w, &d, 1, 1, &lower), CAROM_OK);
      d.y = 1.5, d.density = order ? 1.0 : 1000.0;
      assert_status (carom_world_add_box (w, &d, 1, 1, &upper), CAROM_OK);
      for (step = 0; step < 600; ++step)
        carom_world_update (w, 1.0 / 60);
      carom_body_get_velocity (w, upper, &vx, &vy);
      assert_true (fabs (vx) < 1e-3 && fabs (vy) < 1e-3);
      carom_body_get_position (w, lower, &x1, &y1);
      carom_body_get_position (w, upper, &x2, &y2);
      /* the slop is 1% of the smaller size (0.25 for a unit box): 0.0025 */
      assert_true (fabs (y1 - 0.5) < 2 * 0.0025 && fabs (y2 - 1.5) < 4 * 0.0025);
      assert_true (fabs (x1) < 1e-6 && fabs (x2) < 1e-6);
      carom_world_destroy (w);
    }
}

/* Case 4b: the heavy box (1000:1) on a column of three light ones, and on
 * a column of two light ones that stands on two side by side. Shock
 * propagation holds the heavy-on-light contact and every contact below it
 * (shock.c): the bodies the heavy box's weight must pass through, whether
 * or not they rest on one body each. Bound: over 10 s the heavy box never
 * sinks more than a slop per contact beneath it (0.005 each, size 0.5 of a
 * unit box); on the column of three it ends at rest (under 1e-3 per
 * second), without sideways creep. */
static void test_mass_ratio_1000_on_a_column (void **state)
{
  int pyramid;
  (void) state;
  for (pyramid = 0; pyramid < 2; ++pyramid)
    {
      carom_world *w = world_with (0, -10, 0, 0.6);
      carom_body_def d;
      carom_body_id heavy = CAROM_NULL_BODY;
      const int levels = 4;
      double x, y, vx, vy, sink = 0.0, top = levels - 0.5; /* its stacked height */
      int i, step;
      add_static_box (w, 0, -0.5, 20, 1);
      /* built 0.006 apart, just beyond the slop: the contacts start apart,
       * not resting, so no cold start holds them; shock propagation must */
      for (i = 0; i < levels; ++i)
        {
          carom_body_def_init (&d, sizeof d);
          d.y = 0.5 + i + 0.006 * (i + 1), d.density = i == levels - 1 ? 1000.0 : 1.0;
          d.x = pyramid && i == 0 ? -0.55 : 0.0;
          assert_status (carom_world_add_box (w, &d, 1, 1, &heavy), CAROM_OK);
          if (pyramid && i == 0)
            {
              d.x = 0.55;
              assert_status (carom_world_add_box (w, &d, 1, 1, NULL), CAROM_OK);
            }
        }
      for (step = 0; step < 600; ++step)
        {
          carom_world_update (w, 1.0 / 60);
          carom_body_get_position (w, heavy, &x, &y);
          sink = top - y > sink ? top - y : sink;
        }
      carom_body_get_velocity (w, heavy, &vx, &vy);
      print_message ("heavy box on %s: sank %.3g, ends at (%.3g, %.3g) m/s, %.3g sideways\n",
                     pyramid ? "two on two" : "a column of three", sink, vx, vy, x);
      assert_true (sink < levels * 0.005);
      /* on two it creeps sideways (docs/stability.md, not yet held) */
      if (!pyramid)
        assert_true (fabs (vx) < 1e-3 && fabs (vy) < 1e-3 && fabs (x) < 1e-6);
      carom_world_destroy (w);
    }
}

/* Fuzz finding F10: a box 1e122 times heavier than the one it lands on,
 * spinning, under the vertex-edge method. Bound: every state finite, and
 * the light box, squeezed out from under it, stays on the ground. */
/* Fuzz finding F11: a world friction of 1e308 mixed as sqrt (mu mu) is
 * infinite, and the batches' friction limit mu times a zero normal impulse
 * was NaN. A box resting on the ground and a circle landing beside it
 * must stay finite, and hold fast. */
static void test_huge_friction_stays_finite (void **state)
{
  carom_world *w;
  carom_world_def def;
  carom_body_id box;
  double vx, vy;
  int step;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 1e308;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  add_static_box (w, 0, -0.5, 40, 1);
  box = add_box (w, CAROM_DYNAMIC, 0.0, 0.5, 0.0, 1.0, 1.0);
  assert_status (carom_body_set_velocity (w, box, 1.0, 0.0), CAROM_OK);
  for (step = 0; step < 60; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      assert_world_finite (w);
    }
  carom_body_get_velocity (w, box, &vx, &vy);
  assert_near_abs (vx, 0.0, 1e-9); /* stopped by the friction at once */
  carom_world_destroy (w);
}

static void test_extreme_mass_ratio_stays_finite (void **state)
{
  carom_world *w;
  carom_world_def def;
  carom_body_def d;
  carom_body_id light;
  double x, y;
  int step;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -9.7265625;
  def.substeps = 1;
  def.iterations = 2;
  def.narrow_phase = CAROM_NARROW_VERTEX_EDGE;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  add_static_box (w, 0, -0.5, 40, 1);
  carom_body_def_init (&d, sizeof d);
  d.y = 0.25;
  assert_status (carom_world_add_box (w, &d, 0.5, 1.0, &light), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.x = 0.5, d.y = 3.0, d.angle = 1.0, d.spin = 4.0, d.density = 2.6183001116790237e+122;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_OK);
  for (step = 0; step < 120; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      assert_world_finite (w);
    }
  carom_body_get_position (w, light, &x, &y);
  /* squeezed out sideways, but on the ground: not through it, not launched */
  assert_true (fabs (x) < 20.0 && y > 0.0 && y < 1.0);
  carom_world_destroy (w);
}

/* A light circle resting in a V groove (two static boxes at 45 degrees)
 * under a circle heavier by 1e3 to 1e196, resting on it off-centre (the
 * contact leaning 6 to 29 degrees), gravity (-2, -9.81), built at rest, so
 * every contact starts cold. Bound: neither body ever moves faster than
 * gravity alone makes it in the run (|g| t, 5 m/s in 0.5 s). The cold
 * start's sideways share on the light body once launched it at 1e7 m/s for
 * a ratio of 1e10 and to infinity beyond 1e190. */
static void test_light_body_under_a_heavy_one_is_not_launched (void **state)
{
  static const double ratios[] = { 1e3, 1e10, 1e50, 1e100, 1e150, 1e196 };
  const double rl = 0.5, rh = 0.5, yl = -1.0 + sqrt (2.0) * (1.0 + rl), steps = 30, dt = 1.0 / 60;
  const double bound = hypot (2.0, 9.81) * steps * dt;
  double worst = 0.0;
  size_t r;
  int o, i, k;
  (void) state;
  for (r = 0; r < sizeof ratios / sizeof ratios[0]; ++r)
    for (o = 0; o < 6; ++o)
      {
        carom_world *w = world_with (-2.0, -9.81, 0.0, 0.6);
        carom_body_def d;
        carom_body_id ids[2];
        double lean = 0.1 + 0.08 * o;
        add_box (w, CAROM_STATIC, -1.0, 0.0, M_PI / 4, 2.0, 2.0);
        add_box (w, CAROM_STATIC, 1.0, 0.0, -M_PI / 4, 2.0, 2.0);
        carom_body_def_init (&d, sizeof d);
        d.y = yl;
        assert_status (carom_world_add_circle (w, &d, rl, &ids[0]), CAROM_OK);
        d.x = (rl + rh) * sin (lean), d.y = yl + (rl + rh) * cos (lean), d.density = ratios[r];
        assert_status (carom_world_add_circle (w, &d, rh, &ids[1]), CAROM_OK);
        for (i = 0; i < steps; ++i)
          {
            assert_status (carom_world_update (w, dt), CAROM_OK);
            for (k = 0; k < 2; ++k)
              {
                double vx, vy, speed;
                carom_body_get_velocity (w, ids[k], &vx, &vy);
                speed = hypot (vx, vy);
                if (!(speed <= worst))
                  worst = speed;
              }
          }
        carom_world_destroy (w);
      }
  print_message ("light under heavy: fastest %.3g m/s (bound %.3g)\n", worst, bound);
  assert_true (worst <= bound);
}

/* An elastic cluster: 60 polygons (boxes, pentagons, triangles) in a closed
 * 12 x 12 box, no gravity, e = 1, speeds up to 5, 600 steps. Bound: the
 * kinetic energy within 1e-4 of its start at every step (impacts on several
 * sides at once included: docs/stability.md). */
static void test_elastic_cluster_keeps_its_energy (void **state)
{
  carom_world *w = world_with (0, 0, 1.0, 0);
  carom_body_def d;
  double e0, worst = 0.0;
  int i, step;
  (void) state;
  add_static_box (w, 0, -6.5, 14, 1);
  add_static_box (w, 0, 6.5, 14, 1);
  add_static_box (w, -6.5, 0, 1, 12);
  add_static_box (w, 6.5, 0, 1, 12);
  for (i = 0; i < 60; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.x = -5.0 + (i % 8) * 1.4, d.y = -5.0 + (i / 8) * 1.4, d.angle = 0.7 * i;
      d.vx = ((i * 7) % 11) * 0.9 - 4.5, d.vy = ((i * 5) % 9) * 1.1 - 4.4, d.spin = ((i * 3) % 5) - 2.0;
      if (i % 3 == 0)
        assert_status (carom_world_add_box (w, &d, 0.8, 0.5, NULL), CAROM_OK);
      else if (i % 3 == 1)
        assert_status (carom_world_add_regular (w, &d, 5, 0.45, NULL), CAROM_OK);
      else
        {
          const double tri[] = {0, 0, 0.7, 0.1, 0.2, 0.6};
          assert_status (carom_world_add_polygon (w, &d, tri, 3, NULL), CAROM_OK);
        }
    }
  e0 = world_kinetic_energy (w);
  for (step = 0; step < 600; ++step)
    {
      double e;
      carom_world_update (w, 1.0 / 60);
      e = fabs (world_kinetic_energy (w) / e0 - 1.0);
      worst = e > worst ? e : worst;
    }
  print_message ("elastic cluster: largest energy drift over 600 steps %.3g\n", worst);
  assert_true (worst < 1e-4);
  carom_world_destroy (w);
}

/* Small boxes under full gravity: five 1 cm boxes, g = 9.81, dt 1/60 (a free
 * one falls a quarter of its height per step), built exactly touching, and
 * again built 0.1 mm apart (twice their slop: their contacts start apart,
 * not resting, and the boxes settle onto each other as the solver's passes
 * allow, with no cold start to hold them). Bound: over 2 s the top's
 * largest sag below its stacked height stays under 1% of the stack's
 * height, and it moves no more than that sideways. */
static void test_small_boxes_under_full_gravity_stand (void **state)
{
  int gap;
  (void) state;
  for (gap = 0; gap < 2; ++gap)
    {
      carom_world *w = world_with (0, -9.81, 0, 0.6);
      carom_body_def d;
      carom_body_id top = CAROM_NULL_BODY;
      double x, y, sag = 0.0, side = 0.0, size = 0.01, y0 = 4.5 * size;
      int i, step;
      add_static_box (w, 0.0, -0.5 * size, 20 * size, size);
      carom_body_def_init (&d, sizeof d);
      for (i = 0; i < 5; ++i)
        {
          d.y = (i + 0.5) * size + (gap ? (i + 1) * 1e-4 : 0.0);
          assert_status (carom_world_add_box (w, &d, size, size, &top), CAROM_OK);
        }
      for (step = 0; step < 120; ++step)
        {
          assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
          carom_body_get_position (w, top, &x, &y);
          sag = y0 - y > sag ? y0 - y : sag;
          side = fabs (x) > side ? fabs (x) : side;
        }
      print_message ("five 1 cm boxes, %s: largest sag %.3g of the height\n", gap ? "0.1 mm apart" : "touching",
                     sag / (5 * size));
      assert_true (sag < 0.01 * 5 * size);
      assert_true (side < 0.01 * 5 * size);
      assert_world_finite (w);
      carom_world_destroy (w);
    }
}

/* Piles of small boxes: 60 boxes of one size dropped from a grid 1.6 sides
 * apart (six columns, each box turned 0.37 rad more than the last) into a
 * bin 11.6 sides wide, at the library defaults with g = 10 and friction
 * 0.6, for 3 s; sizes from 1.5 cm to 50 cm. A box that falls more than its
 * slop in a step takes extra solve passes (contact_fine_passes); with one
 * pass a sub-step, support climbing the pile one contact per pass, the 2 cm
 * boxes ended a third of a side inside each other (0.32) and the 3 cm ones
 * 0.28. Bound: over the last half second no contact is deeper than two
 * slops (2% of a side). (1 cm boxes end at 3.2%: docs/stability.md, case
 * 19.) */
static void test_piles_of_small_boxes_settle_within_the_slop (void **state)
{
  static const double sizes[] = {0.015, 0.02, 0.03, 0.05, 0.1, 0.14, 0.2, 0.5};
  size_t s;
  (void) state;
  for (s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
    {
      double size = sizes[s], deepest = 0.0;
      carom_world *w = world_with (0, -10.0, 0, 0.6);
      carom_body_def d;
      int i, step, k;
      add_static_box (w, 0.0, -0.5 * size, 16 * size, size);
      add_static_box (w, -5.8 * size, 20 * size, size, 40 * size);
      add_static_box (w, 5.8 * size, 20 * size, size, 40 * size);
      carom_body_def_init (&d, sizeof d);
      for (i = 0; i < 60; ++i)
        {
          d.x = (-4.0 + (i % 6) * 1.6) * size, d.y = (2.0 + (i / 6) * 1.6) * size, d.angle = 0.37 * i;
          assert_status (carom_world_add_box (w, &d, size, size, NULL), CAROM_OK);
        }
      for (step = 0; step < 180; ++step)
        {
          assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
          for (k = 0; step >= 150 && k < carom_world_contact_count (w); ++k)
            {
              double depth;
              assert_status (carom_world_get_contact (w, k, NULL, NULL, NULL, NULL, NULL, NULL, &depth), CAROM_OK);
              deepest = depth > deepest ? depth : deepest;
            }
        }
      print_message ("60 boxes of %g m: deepest contact over the last half second %.3f of a side\n", size,
                     deepest / size);
      assert_true (deepest < 0.02 * size);
      assert_world_finite (w);
      carom_world_destroy (w);
    }
}

/* Columns of small boxes offset by a hair: ten boxes of 1 cm, eighteen of
 * 5 cm and eighteen of 10 cm, friction 0.6, g = 10, built touching, each
 * box 1e-9 of a side left or right of the one below it, at the defaults,
 * for 10 s. A rigid column stands however it is offset, while its weight
 * stays over its base. Bound: no box's centre moves sideways more than 1%
 * of a side from where it was built. (With the fine passes ended at a fixed
 * speed, contact_solver.h, the 1 cm column fell within 2.1 s and the 5 cm
 * one within 6.1 s. The lean still grows: the 5 cm and 10 cm columns fall
 * at 29 s and 24 s, docs/stability.md.) */
static void test_offset_columns_of_small_boxes_stand (void **state)
{
  static const struct { double size; int count; } columns[] = {{0.01, 10}, {0.05, 18}, {0.1, 18}};
  size_t c;
  (void) state;
  for (c = 0; c < sizeof columns / sizeof columns[0]; ++c)
    {
      double size = columns[c].size, worst = 0.0;
      carom_world *w = world_with (0, -10.0, 0, 0.6);
      carom_body_def d;
      carom_body_id ids[18];
      int i, step, n = columns[c].count;
      add_static_box (w, 0.0, -0.5 * size, 40 * size, size);
      carom_body_def_init (&d, sizeof d);
      for (i = 0; i < n; ++i)
        {
          d.x = (i % 2 ? 1e-9 : -1e-9) * size, d.y = (i + 0.5) * size;
          assert_status (carom_world_add_box (w, &d, size, size, &ids[i]), CAROM_OK);
        }
      for (step = 0; step < 600; ++step)
        {
          assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
          for (i = 0; i < n; ++i)
            {
              double x, y;
              carom_body_get_position (w, ids[i], &x, &y);
              x = fabs (x - (i % 2 ? 1e-9 : -1e-9) * size);
              worst = x > worst ? x : worst;
            }
        }
      print_message ("%d boxes of %g m offset 1e-9: largest sideways motion %.3g of a side\n", n, size, worst / size);
      assert_true (worst < 0.01 * size);
      assert_world_finite (w);
      carom_world_destroy (w);
    }
}

/* Columns whose boxes land on each other: 5 and 10 boxes of side 10 cm,
 * 5 to 20 of side 1 m, built apart by 0, 2% and 10% of a side and shifted
 * alternately 1% of a side left and right (Solver2D's vertical stack),
 * friction 0.3, g = 10, for 10 s, continuous collision off and on. The
 * passes carry a landing down the column one contact per pass, and the
 * warm start brings it back up: the column rang along its length, its
 * boxes sinking into each other and thrown back up, clear of the ones
 * below (by up to 21% of a side; ten 10 cm boxes built touching fell).
 * Shock propagation holds the column (shock.c). Bounds, for every column:
 * once two neighbours have met (within the slop, 1% of a side) the gap
 * between them never opens past the slop again, the top never moves
 * sideways more than 5% of a side from where it was built, and at 10 s it
 * is less than 1% of the column's height below its stacked height. (Ten
 * 10 cm boxes built touching move their top 2.4% of a side, twenty 1 m
 * ones 1.3%; longer columns of small boxes still fall, docs/stability.md,
 * case 19.) */
static void test_columns_land_without_ringing (void **state)
{
  static const double gaps[] = {0.0, 0.02, 0.1};
  double worst_gap = 0.0, worst_side = 0.0, worst_sag = 0.0;
  int small, n, gi, cont;
  (void) state;
  for (small = 0; small < 2; ++small)
    for (n = 5; n <= (small ? 10 : 20); n += 5)
      for (gi = 0; gi < 3; ++gi)
        for (cont = 0; cont < 2; ++cont)
          {
            carom_world *w = world_with (0, -10, 0, 0.3);
            carom_body_def d;
            carom_body_id ids[20];
            double size = small ? 0.1 : 1.0, x0, x, y, side = 0.0, sag, opened = 0.0;
            int met[20] = {0}, i, step;
            assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
            add_static_box (w, 0.0, -size, 200 * size, 2 * size);
            carom_body_def_init (&d, sizeof d);
            for (i = 0; i < n; ++i)
              {
                d.x = (i % 2 ? 0.01 : -0.01) * size;
                d.y = size * (0.5 + i * (1.0 + gaps[gi]));
                assert_status (carom_world_add_box (w, &d, size, size, &ids[i]), CAROM_OK);
              }
            x0 = d.x; /* where the top was built */
            for (step = 0; step < 600; ++step)
              {
                double below;
                assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
                carom_body_get_position (w, ids[0], NULL, &below);
                for (i = 1; i < n; ++i)
                  {
                    double at, gap;
                    carom_body_get_position (w, ids[i], NULL, &at);
                    gap = at - below - size;
                    if (gap <= 0.01 * size)
                      met[i] = 1;
                    else if (met[i] && gap > opened)
                      opened = gap;
                    below = at;
                  }
                carom_body_get_position (w, ids[n - 1], &x, &y);
                side = fabs (x - x0) > side ? fabs (x - x0) : side;
              }
            sag = size * (n - 0.5) - y;
            if (!(opened <= 0.01 * size && side < 0.05 * size && sag < 0.01 * n * size))
              fail_msg ("%d boxes of %g, %g of a side apart, continuous %d: a gap opened %.3g of a side, the top "
                        "moved %.3g of a side, sagged %.3g of the height",
                        n, size, gaps[gi], cont, opened / size, side / size, sag / (n * size));
            assert_world_finite (w);
            worst_gap = opened / size > worst_gap ? opened / size : worst_gap;
            worst_side = side / size > worst_side ? side / size : worst_side;
            worst_sag = sag / (n * size) > worst_sag ? sag / (n * size) : worst_sag;
            carom_world_destroy (w);
          }
  print_message ("columns: gaps reopened at most %.3g of a side, tops moved %.3g of a side, sagged %.3g of the "
                 "height\n", worst_gap, worst_side, worst_sag);
}

/* Stacks that land on themselves with continuous collision: five boxes of
 * side 1 cm, 10 cm and 1 m, built apart by 0 to 25 slops (the world's slop
 * times a side) and let fall under g = 9.81. The time of impact follows
 * each pair in free flight, where two falling boxes never close; but the
 * lower one is stopped within the step by what it lands on, and the upper
 * then falls onto it (a 1 cm box 0.1 mm above another sank 30% of the
 * stack's height, each contact taken as apart for its whole step). Bounds,
 * for every size and gap: no overlap ever deeper than 2% of a side (two
 * slops), and from 1 s on the top sags less than 1% of the stack's height
 * below its stacked height and moves sideways less than 1% of a side. */
static void test_continuous_stacks_land_on_each_other (void **state)
{
  const double sizes[] = {0.01, 0.1, 1.0}, gaps[] = {0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 25.0};
  double worst_depth = 0.0, worst_sag = 0.0;
  size_t si, gi;
  (void) state;
  for (si = 0; si < sizeof sizes / sizeof sizes[0]; ++si)
    for (gi = 0; gi < sizeof gaps / sizeof gaps[0]; ++gi)
      {
        carom_world *w = world_with (0, -9.81, 0, 0.6);
        carom_body_def d;
        carom_body_id top = CAROM_NULL_BODY;
        double size = sizes[si], gap = gaps[gi] * 0.01 * size, y0 = 4.5 * size;
        double x, y, deepest = 0.0, sag = 0.0, side = 0.0;
        int i, k, step;
        carom_world_set_continuous (w, 1);
        add_static_box (w, 0.0, -0.5 * size, 20 * size, size);
        carom_body_def_init (&d, sizeof d);
        for (i = 0; i < 5; ++i)
          {
            d.y = (i + 0.5) * size + (i + 1) * gap;
            assert_status (carom_world_add_box (w, &d, size, size, &top), CAROM_OK);
          }
        for (step = 0; step < 180; ++step)
          {
            assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
            for (k = 0; k < carom_world_contact_count (w); ++k)
              {
                double depth;
                carom_world_get_contact (w, k, NULL, NULL, NULL, NULL, NULL, NULL, &depth);
                deepest = depth > deepest ? depth : deepest;
              }
            carom_body_get_position (w, top, &x, &y);
            if (step >= 60)
              {
                sag = y0 - y > sag ? y0 - y : sag;
                side = fabs (x) > side ? fabs (x) : side;
              }
          }
        assert_true (deepest < 0.02 * size);
        assert_true (sag < 0.01 * 5 * size);
        assert_true (side < 0.01 * size);
        assert_world_finite (w);
        worst_depth = deepest / size > worst_depth ? deepest / size : worst_depth;
        worst_sag = sag / (5 * size) > worst_sag ? sag / (5 * size) : worst_sag;
        carom_world_destroy (w);
      }
  print_message ("stacks landing with continuous collision: deepest %.3g of a side, sag %.3g of the height\n",
                 worst_depth, worst_sag);
}

static void test_stack_far_from_origin_1e6 (void **state)
{
  (void) state;
  run_stack_case (1.0, 1e6, 1e6);
}

/* Case 3: a bullet at 300 m/s against a wall thinner than one step's travel
 * (5 m per step at 60 Hz, wall 0.1 m), 4 m tall or only 0.4 m (then the
 * bullet is well clear of it where the step ends): never passes. */
static void test_bullet_300_never_passes_thin_wall (void **state)
{
  int shape;
  (void) state;
  for (shape = 0; shape < 4; ++shape)
    {
      carom_world *w = world_with (0, 0, 0, 0);
      carom_body_def d;
      carom_body_id b;
      double x;
      int step;
      /* continuous collision, which a scene with bullets calls for: on for
       * the world when the bullet is a circle, on for the body alone (a
       * "bullet") when it is a polygon */
      if (shape % 2 == 0)
        assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
      add_static_box (w, 10.0, 0.0, 0.1, shape < 2 ? 4.0 : 0.4);
      carom_body_def_init (&d, sizeof d);
      d.x = -3.3, d.vx = 300.0;
      if (shape % 2)
        {
          assert_status (carom_world_add_regular (w, &d, 5, 0.1, &b), CAROM_OK);
          assert_status (carom_body_set_bullet (w, b, 1), CAROM_OK);
        }
      else
        assert_status (carom_world_add_circle (w, &d, 0.05, &b), CAROM_OK);
      for (step = 0; step < 120; ++step)
        {
          carom_world_update (w, 1.0 / 60);
          carom_body_get_position (w, b, &x, NULL);
          assert_true (x < 10.0);
        }
      carom_world_destroy (w);
    }
}

/* Case 11: overlapping at creation, they separate without exploding.
 * Bound: kinetic energy stays at rounding level (the push-out moves the
 * bodies and the relax pass takes its velocity back: a push left behind at
 * even 1e-9 of the push speed would show) and the boxes end apart. */
static void test_overlap_recovery_adds_no_energy (void **state)
{
  carom_world *w = world_with (0, 0, 0, 0);
  carom_body_def d;
  carom_body_id a, b;
  double xa, xb;
  int step;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.x = -0.25;
  assert_status (carom_world_add_box (w, &d, 1, 1, &a), CAROM_OK);
  d.x = 0.25, d.angle = 0.1;
  assert_status (carom_world_add_box (w, &d, 1, 1, &b), CAROM_OK);
  for (step = 0; step < 300; ++step)
    carom_world_update (w, 1.0 / 60);
  assert_true (world_kinetic_energy (w) < 1e-24);
  carom_body_get_position (w, a, &xa, NULL);
  carom_body_get_position (w, b, &xb, NULL);
  assert_true (xb - xa > 0.95);
  assert_world_finite (w);
  carom_world_destroy (w);
}

/* Case 12: degenerate steps: dt 1e-9 and 1 s, many bodies at exactly the
 * same spot, a body exactly on a wall's corner. Bound: all finite. */
static void test_degenerate_steps_stay_finite (void **state)
{
  carom_world *w = world_with (0, -10, 0.5, 0.3);
  carom_body_def d;
  int i;
  (void) state;
  add_static_box (w, 0, -0.5, 10, 1);
  carom_body_def_init (&d, sizeof d);
  d.y = 3;
  for (i = 0; i < 20; ++i)
    assert_status (i % 2 ? carom_world_add_circle (w, &d, 0.3, NULL) : carom_world_add_box (w, &d, 0.5, 0.5, NULL),
                   CAROM_OK);
  d.x = 5.0, d.y = 0.0; /* centred on the ground's top-right corner */
  assert_status (carom_world_add_box (w, &d, 0.4, 0.4, NULL), CAROM_OK);
  for (i = 0; i < 30; ++i)
    assert_status (carom_world_update (w, 1e-9), CAROM_OK);
  assert_world_finite (w);
  for (i = 0; i < 5; ++i)
    assert_status (carom_world_update (w, 1.0), CAROM_OK);
  assert_world_finite (w);
  for (i = 0; i < 120; ++i)
    assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
  assert_world_finite (w);
  carom_world_destroy (w);
}

/* Determinism: the same calls give bit-identical states. A hash of all
 * body states (world_state_hash) after 300 steps of a busy scene, run in
 * two worlds interleaved in one process. */
static carom_world *busy_scene (void)
{
  carom_world *w = world_with (0, -10, 0.3, 0.5);
  carom_body_def d;
  int i;
  add_static_box (w, 0, -0.5, 20, 1);
  add_static_box (w, -10, 5, 1, 12);
  add_static_box (w, 10, 5, 1, 12);
  carom_body_def_init (&d, sizeof d);
  for (i = 0; i < 60; ++i)
    {
      d.x = -8 + (i % 12) * 1.4, d.y = 1 + (i / 12) * 1.3, d.angle = 0.1 * i, d.vx = (i % 5) - 2.0;
      if (i % 3 == 0)
        assert_status (carom_world_add_circle (w, &d, 0.4, NULL), CAROM_OK);
      else if (i % 3 == 1)
        assert_status (carom_world_add_box (w, &d, 0.8, 0.5, NULL), CAROM_OK);
      else
        assert_status (carom_world_add_regular (w, &d, 3 + i % 5, 0.5, NULL), CAROM_OK);
    }
  return w;
}

static void test_determinism_bit_identical (void **state)
{
  carom_world *a = busy_scene (), *b = busy_scene ();
  int step;
  (void) state;
  for (step = 0; step < 300; ++step)
    {
      carom_world_update (a, 1.0 / 60);
      carom_world_update (b, 1.0 / 60);
    }
  assert_true (world_state_hash (a) == world_state_hash (b));
  /* and the hash does see a change */
  carom_world_update (b, 1.0 / 60);
  assert_true (world_state_hash (a) != world_state_hash (b));
  carom_world_destroy (a);
  carom_world_destroy (b);
}

/* Case 9 (short form): two U shapes hooked into each other and shaken by
 * their velocities: they stay caught and no energy is gained (e = 0). */
static void test_concave_interlock_stays_caught (void **state)
{
  carom_world *w = world_with (0, 0, 0, 0);
  const double u[] = {0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3};
  const double n[] = {0, 3, 0, 0, 1, 0, 1, 2, 2, 2, 2, 0, 3, 0, 3, 3};
  carom_body_def d;
  carom_body_id a, b;
  double e0, ya, yb;
  int step;
  (void) state;
  carom_body_def_init (&d, sizeof d);
  d.vy = 1.0;
  assert_status (carom_world_add_polygon (w, &d, u, 8, &a), CAROM_OK);
  /* an upside-down U whose right arm hangs in the first U's notch */
  d.x = 1.0 + 0.0, d.y = 2.9, d.vy = -1.0;
  assert_status (carom_world_add_polygon (w, &d, n, 8, &b), CAROM_OK);
  e0 = world_kinetic_energy (w);
  for (step = 0; step < 600; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      assert_true (world_kinetic_energy (w) <= e0 * (1 + 1e-9));
    }
  carom_body_get_position (w, a, NULL, &ya);
  carom_body_get_position (w, b, NULL, &yb);
  assert_true (fabs (yb - ya) < 4.0);
  assert_world_finite (w);
  carom_world_destroy (w);
}

/* Case 7: awkward geometry. Inertia against closed forms (a triangle's
 * polar moment about its centroid is m (a^2 + b^2 + c^2) / 36), and each
 * shape dropped on the ground (from 3 m, turned 0.3 rad, e = 0, mu = 0.5)
 * settles on it, finite, overlapping it less than 2 slops. Returns its
 * speed at 10 s; *rise_out is the most its energy (kinetic and potential)
 * ever rose above the least it had had before, over m g, and *travel_out
 * the farthest it went sideways. */
static double settle_on_ground (const double *xy, int n, double *depth_out, double *rise_out, double *travel_out)
{
  carom_world *w = world_with (0, -10, 0, 0.5);
  carom_body_def d;
  carom_body_id id;
  double x, y, vx, vy, spin, m, inertia, deepest = 0.0, least = INFINITY, rise = 0.0, travel = 0.0;
  int step, k;
  add_static_box (w, 0, -0.5, 40, 1);
  carom_body_def_init (&d, sizeof d);
  d.y = 3.0, d.angle = 0.3;
  assert_status (carom_world_add_polygon (w, &d, xy, n, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  for (step = 0; step < 600; ++step)
    {
      double e;
      carom_world_update (w, 1.0 / 60);
      for (k = 0; k < carom_world_contact_count (w); ++k)
        {
          double nx, ny, depth;
          carom_world_get_contact (w, k, NULL, NULL, NULL, NULL, &nx, &ny, &depth);
          assert_near_abs (nx * nx + ny * ny, 1.0, 1e-12);
          if (step > 300 && depth > deepest)
            deepest = depth;
        }
      carom_body_get_position (w, id, &x, &y);
      carom_body_get_velocity (w, id, &vx, &vy);
      carom_body_get_spin (w, id, &spin);
      e = 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * spin * spin + m * 10.0 * y;
      rise = e - least > rise ? e - least : rise;
      least = e < least ? e : least;
      travel = fabs (x) > travel ? fabs (x) : travel;
    }
  assert_world_finite (w);
  carom_world_destroy (w);
  *depth_out = deepest;
  *rise_out = rise / (m * 10.0);
  *travel_out = travel;
  return sqrt (vx * vx + vy * vy);
}

static void test_awkward_geometry (void **state)
{
  const double sliver[] = {0, 0, 10, 0, 5, 0.01};                 /* aspect 1000:1 */
  const double collinear[] = {-1, -0.5, 0, -0.5, 1, -0.5, 1, 0.5, 0, 0.5, -1, 0.5}; /* 2 x 1 box, midpoints */
  const double near_dup[] = {-1, -0.5, 1, -0.5, 1, 0.5, 1 - 1e-9, 0.5, -1, 0.5}; /* two vertices 1e-9 apart */
  const double short_edge[] = {-1, -0.5, 1, -0.5, 1, 0.5 - 1e-6, 1 - 1e-6, 0.5, -1, 0.5};
  double circle64[128];
  carom_world *w = world_with (0, 0, 0, 0);
  carom_body_id id;
  double m, inertia, a2, b2, c2, depth, rise, travel;
  int i;
  (void) state;
  for (i = 0; i < 64; ++i)
    {
      circle64[2 * i] = cos (2 * M_PI * i / 64);
      circle64[2 * i + 1] = sin (2 * M_PI * i / 64);
    }
  assert_status (carom_world_add_polygon (w, NULL, sliver, 3, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  a2 = 100.0, b2 = 25.0 + 1e-4, c2 = 25.0 + 1e-4;
  assert_near_rel (inertia, m * (a2 + b2 + c2) / 36.0, 1e-9);
  assert_status (carom_world_add_polygon (w, NULL, collinear, 6, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  assert_near_rel (inertia, m * (4.0 + 1.0) / 12.0, 1e-12); /* the 2 x 1 box, eq. 3.4 */
  assert_status (carom_world_add_polygon (w, NULL, near_dup, 5, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  assert_near_rel (inertia, m * 5.0 / 12.0, 1e-8);
  assert_status (carom_world_add_polygon (w, NULL, short_edge, 5, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  assert_near_rel (inertia, m * 5.0 / 12.0, 1e-5);
  assert_status (carom_world_add_polygon (w, NULL, circle64, 64, &id), CAROM_OK);
  carom_body_get_mass (w, id, &m, &inertia, NULL);
  assert_near_rel (inertia, 0.5 * m, 0.01); /* close to a disc's m r^2 / 2 */
  carom_world_destroy (w);
  /* and each comes to rest on the ground: slower than 1% of its size per
   * second at 10 s, overlapping less than 2 slops (1% of its size each) */
  assert_true (settle_on_ground (sliver, 3, &depth, &rise, &travel) < 0.1 && depth < 2 * 0.01 * 0.01);
  assert_true (settle_on_ground (collinear, 6, &depth, &rise, &travel) < 0.01 && depth < 2 * 0.01 * 0.34);
  assert_true (settle_on_ground (near_dup, 5, &depth, &rise, &travel) < 0.01 && depth < 2 * 0.01 * 0.34);
  assert_true (settle_on_ground (short_edge, 5, &depth, &rise, &travel) < 0.01 && depth < 2 * 0.01 * 0.34);
  /* but the 64-gon, landing on a corner, need not: on a face it is a
   * rocking block 2 sin (pi / 64) = 0.098 wide whose centre is cos (pi /
   * 64) = 0.9988 above it, and each corner's impact keeps (I_c - 2 m b^2)
   * / I_c = 99.7% of its spin (I_c = 1.5 m about a corner, b = 0.049), so
   * a rigid one rocks on for minutes. Bounds: it overlaps the ground less
   * than 2 slops, its energy never rises by more than lifting it out of
   * that overlap would add (m g times 2 slops; the push-out moves it), and
   * it rocks on one face: it never goes sideways as far as a face's
   * width. */
  settle_on_ground (circle64, 64, &depth, &rise, &travel);
  print_message ("64-gon: deepest %.3g, energy rose at most m g %.3g, went %.3g sideways\n", depth, rise, travel);
  assert_true (depth < 2 * 0.01 * 0.5);
  assert_true (rise <= 2 * 0.01 * 0.5);
  assert_true (travel < 2.0 * sin (M_PI / 64));
}

/* Case 8: the thesis' own hard cases under its vertex-edge method, at many
 * angles and speeds: parallel edges (fig. 3.9) and vertex on vertex
 * (fig. 3.11). Bounds: every normal unit to 1e-12, nothing NaN, no energy
 * gained (e = 1) beyond 1e-9, and no sticking: the boxes end apart and
 * moving apart. */
static void test_thesis_hard_cases_many_angles (void **state)
{
  int kind, k;
  (void) state;
  for (kind = 0; kind < 2; ++kind)
    for (k = 0; k < 12; ++k)
      {
        carom_world *w = NULL;
        carom_world_def def;
        carom_body_def d;
        carom_body_id a, b;
        double speed = 0.5 + k, tilt = kind ? M_PI / 4 : 0.02 * (k - 6), e0, e1, xa, xb, va, vb;
        int step, i;
        carom_world_def_init (&def, sizeof def);
        def.restitution = 1.0;
        def.narrow_phase = CAROM_NARROW_VERTEX_EDGE;
        assert_status (carom_world_init (&w, &def), CAROM_OK);
        carom_body_def_init (&d, sizeof d);
        d.x = -1.5, d.vx = speed, d.angle = kind ? M_PI / 4 + 0.01 * k : 0.0, d.y = kind ? 0.0 : 0.05 * k;
        assert_status (carom_world_add_box (w, &d, 1, 1, &a), CAROM_OK);
        d.x = 1.5, d.vx = -speed, d.angle = tilt, d.y = 0.0;
        assert_status (carom_world_add_box (w, &d, 1, 1, &b), CAROM_OK);
        e0 = world_kinetic_energy (w);
        for (step = 0; step < 480; ++step) /* the slowest pair meets after 2 s */
          {
            assert_status (carom_world_update (w, 1.0 / 120), CAROM_OK);
            for (i = 0; i < carom_world_contact_count (w); ++i)
              {
                double nx, ny;
                carom_world_get_contact (w, i, NULL, NULL, NULL, NULL, &nx, &ny, NULL);
                assert_near_abs (nx * nx + ny * ny, 1.0, 1e-12);
              }
          }
        assert_world_finite (w);
        e1 = world_kinetic_energy (w);
        assert_true (e1 <= e0 * (1 + 1e-9));
        carom_body_get_position (w, a, &xa, NULL);
        carom_body_get_position (w, b, &xb, NULL);
        carom_body_get_velocity (w, a, &va, NULL);
        carom_body_get_velocity (w, b, &vb, NULL);
        assert_true (xb - xa > 1.5 && vb - va > 0.0);
        carom_world_destroy (w);
      }
}

/* An elastic gas under gravity settles into a bouncing pile: its total
 * energy (kinetic plus potential) must not grow, and nothing leaves the
 * box. (Letting bouncy contacts wait under gravity once pumped energy in:
 * the pile's bodies fell into each other and position correction lifted
 * them for free, a factor of 10^4 in 10 s.) Bound: energy at most 1% above
 * its start, no body outside the box. */
static void test_elastic_pile_under_gravity_gains_no_energy (void **state)
{
  carom_world *w = world_with (0, -10, 1.0, 0);
  carom_body_def d;
  carom_body_id ids[128];
  double e0 = 0.0, e1 = 0.0;
  int32_t n, i;
  int step;
  (void) state;
  add_static_box (w, 0, -0.5, 22, 1);
  add_static_box (w, 0, 20.5, 22, 1);
  add_static_box (w, -10.5, 10, 1, 20);
  add_static_box (w, 10.5, 10, 1, 20);
  carom_body_def_init (&d, sizeof d);
  for (i = 0; i < 100; ++i)
    {
      d.x = -9 + (i % 10) * 2.0, d.y = 1 + (i / 10) * 1.8, d.angle = 0.3 * i;
      d.vx = ((i * 7) % 11) - 5.0, d.vy = ((i * 3) % 7) - 3.0;
      assert_status (i % 2 ? carom_world_add_box (w, &d, 0.8, 0.6, NULL) : carom_world_add_regular (w, &d, 5, 0.5, NULL),
                     CAROM_OK);
    }
  n = carom_world_get_bodies (w, ids, 128);
  for (i = 0; i < n; ++i)
    {
      double y, m;
      carom_body_get_position (w, ids[i], NULL, &y);
      carom_body_get_mass (w, ids[i], &m, NULL, NULL);
      e0 += m * 10 * y;
    }
  e0 += world_kinetic_energy (w);
  for (step = 0; step < 600; ++step)
    carom_world_update (w, 1.0 / 60);
  for (i = 0; i < n; ++i)
    {
      double x, y, m;
      carom_body_get_position (w, ids[i], &x, &y);
      carom_body_get_mass (w, ids[i], &m, NULL, NULL);
      e1 += m * 10 * y;
      if (m > 0.0)
        assert_true (fabs (x) < 10.0 && y > 0.0 && y < 20.0);
    }
  e1 += world_kinetic_energy (w);
  assert_true (e1 <= 1.01 * e0);
  assert_world_finite (w);
  carom_world_destroy (w);
}

/* A heavy body taken off a pile (carom_world_remove_body): the impulses
 * the contacts beneath it carry into the next step held its weight too,
 * and must not throw up what carried it. Three cases: Solver2D's circles
 * (the top one 100 times denser), a column of four boxes under one 50
 * times denser, and a box 50 times denser across two columns of three.
 * Bound: in the 2 s after the removal no remaining body rises more than
 * 1% of its size above where it was, nor moves faster than 1% of the
 * speed gravity gives in one step per unit of size. */
static void test_removing_a_heavy_top_throws_nothing_up (void **state)
{
  int kase;
  (void) state;
  for (kase = 0; kase < 3; ++kase)
    {
      carom_world *w = world_with (0, -10, 0, 0.6);
      carom_body_def d;
      carom_body_id ids[8], heavy = 0;
      double y0[8], size[8], rise = 0.0, fastest = 0.0;
      int n = 0, i, k;
      add_static_box (w, 0.0, -0.5, 40.0, 1.0);
      carom_body_def_init (&d, sizeof d);
      if (kase == 0)
        for (i = 0; i < 3; ++i)
          {
            d.x = 0.0, d.y = 0.5 + i, d.density = i == 2 ? 100.0 : 1.0;
            assert_status (carom_world_add_circle (w, &d, 0.5, &ids[n]), CAROM_OK);
            size[n++] = 1.0;
          }
      else if (kase == 1)
        for (i = 0; i < 5; ++i)
          {
            d.x = 0.0, d.y = 0.5 + i, d.density = i == 4 ? 50.0 : 1.0;
            assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &ids[n]), CAROM_OK);
            size[n++] = 1.0;
          }
      else
        {
          for (i = 0; i < 6; ++i)
            {
              d.x = i < 3 ? -1.0 : 1.0, d.y = 0.5 + i % 3, d.density = 1.0;
              assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &ids[n]), CAROM_OK);
              size[n++] = 1.0;
            }
          d.x = 0.0, d.y = 3.25, d.density = 50.0;
          assert_status (carom_world_add_box (w, &d, 3.0, 0.5, &ids[n]), CAROM_OK);
          size[n++] = 0.5;
        }
      heavy = ids[n - 1];
      for (k = 0; k < 120; ++k)
        assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      for (i = 0; i < n - 1; ++i)
        {
          double x;
          carom_body_get_position (w, ids[i], &x, &y0[i]);
        }
      assert_status (carom_world_remove_body (w, heavy), CAROM_OK);
      for (k = 0; k < 120; ++k)
        {
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          for (i = 0; i < n - 1; ++i)
            {
              double x, y, vx, vy;
              carom_body_get_position (w, ids[i], &x, &y);
              carom_body_get_velocity (w, ids[i], &vx, &vy);
              rise = fmax (rise, (y - y0[i]) / size[i]);
              fastest = fmax (fastest, sqrt (vx * vx + vy * vy) / size[i]);
            }
        }
      if (!(rise < 0.01 && fastest < 0.01 * 10.0 / 60.0))
        fail_msg ("case %d: rose %.3g of its size, fastest %.3g sizes/s (bounds 0.01, %.3g)", kase, rise, fastest,
                  0.01 * 10.0 / 60.0);
      carom_world_destroy (w);
    }
}

/* A box tipping over from its corner onto its face: while it turns, its
 * far corner is out of reach of the contact, and it comes down faster the
 * further the box has turned. Bound: boxes of side 0.1 to 3 tipped from 3
 * to 43 degrees land with no corner deeper in the ground than the slop
 * (1% of the size 2 A / P, half a side for a square: 0.5% of the side),
 * with continuous collision on (the default) and off. Before a pair that
 * touched the step before looked as far ahead as its bodies can move, a
 * 10 cm box landed 8.5% of its side deep and a 1 m one 1.4% (continuous
 * collision off, then the default). */
static void test_tipping_boxes_land_within_the_slop (void **state)
{
  static const double sides[] = { 0.1, 0.5, 1.0, 3.0 };
  carom_world_def def;
  double worst = 0.0;
  size_t i;
  int deg, cont;
  (void) state;
  carom_world_def_init (&def, sizeof def);
  for (cont = 0; cont < 2; ++cont)
    for (i = 0; i < sizeof sides / sizeof sides[0]; ++i)
      for (deg = 3; deg <= 43; deg += 4)
        {
          double depth = tipping_box_depth (def.manifold_tolerance, sides[i], deg, cont);
          if (!(depth <= 0.005))
            fail_msg ("side %g tipped from %d degrees, continuous %d: a corner %.4g of the side deep", sides[i], deg,
                      cont, depth);
          worst = fmax (worst, depth);
        }
  print_message ("tipping boxes: deepest corner %.3g of the side\n", worst);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_stack_of_10_top_moves_under_1pct),
    cmocka_unit_test (test_stack_scaled_1e_minus_3_and_1e3),
    cmocka_unit_test (test_tower_built_at_rest_does_not_sag),
    cmocka_unit_test (test_mass_ratio_1000_both_ways),
    cmocka_unit_test (test_mass_ratio_1000_on_a_column),
    cmocka_unit_test (test_stack_far_from_origin_1e6),
    cmocka_unit_test (test_extreme_mass_ratio_stays_finite),
    cmocka_unit_test (test_light_body_under_a_heavy_one_is_not_launched),
    cmocka_unit_test (test_huge_friction_stays_finite),
    cmocka_unit_test (test_small_boxes_under_full_gravity_stand),
    cmocka_unit_test (test_piles_of_small_boxes_settle_within_the_slop),
    cmocka_unit_test (test_offset_columns_of_small_boxes_stand),
    cmocka_unit_test (test_continuous_stacks_land_on_each_other),
    cmocka_unit_test (test_columns_land_without_ringing),
    cmocka_unit_test (test_elastic_cluster_keeps_its_energy),
    cmocka_unit_test (test_bullet_300_never_passes_thin_wall),
    cmocka_unit_test (test_overlap_recovery_adds_no_energy),
    cmocka_unit_test (test_degenerate_steps_stay_finite),
    cmocka_unit_test (test_determinism_bit_identical),
    cmocka_unit_test (test_concave_interlock_stays_caught),
    cmocka_unit_test (test_awkward_geometry),
    cmocka_unit_test (test_elastic_pile_under_gravity_gains_no_energy),
    cmocka_unit_test (test_removing_a_heavy_top_throws_nothing_up),
    cmocka_unit_test (test_tipping_boxes_land_within_the_slop),
    cmocka_unit_test (test_thesis_hard_cases_many_angles),
  };
  return cmocka_run_group_tests_name ("stability", tests, NULL, NULL);
}
