/* The long hard cases (docs/stability.md), run natively by `make stress`
 * and by `make check`: too long for Valgrind. Each prints its measured
 * value beside its bound; the last line counts them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carom.h"
#include "heavy_chain.h"
#include "kinetic.h"

static int passed, failed;

static void report (const char *name, int ok, const char *fmt, double measured, double bound)
{
  printf ("%s %s: ", ok ? "ok  " : "FAIL", name);
  printf (fmt, measured, bound);
  printf ("\n");
  if (ok)
    passed++;
  else
    failed++;
}

static carom_world *load (const char *path)
{
  carom_world *w = NULL;
  carom_scene_error err;
  err.size = sizeof err;
  if (carom_scene_load_file (&w, path, NULL, &err) != CAROM_OK)
    {
      fprintf (stderr, "%s: %s\n", path, err.message);
      exit (2);
    }
  return w;
}

/* Case 2: the 20-row pyramid (scenes/pyramid.scene), 10 s. Bound: the top
 * box moves less than 1% of its size from where it was built. */
static void pyramid (void)
{
  carom_world *w = load ("scenes/pyramid.scene");
  carom_body_id ids[256];
  int32_t n = carom_world_get_bodies (w, ids, 256), i, top = 0;
  double x0, y0, x, y, best = -INFINITY;
  for (i = 0; i < n; ++i)
    {
      carom_body_get_position (w, ids[i], &x, &y);
      if (y > best)
        best = y, top = i;
    }
  carom_body_get_position (w, ids[top], &x0, &y0);
  for (i = 0; i < 600; ++i)
    carom_world_update (w, 1.0 / 60);
  carom_body_get_position (w, ids[top], &x, &y);
  report ("pyramid: top box moved / size after 10 s", hypot (x - x0, y - y0) < 0.01, "%.5f (bound %.2f)",
          hypot (x - x0, y - y0), 0.01);
  carom_world_destroy (w);
}

/* Case 10: the elastic gas (scenes/gas.scene: 500 polygons, e = 1, no
 * friction, no gravity), 100 000 steps. Bounds: nothing NaN, every body
 * still inside the box, kinetic energy within the stated drift. */
static void gas (void)
{
  carom_world *w = load ("scenes/gas.scene");
  carom_body_id ids[600];
  int32_t n = carom_world_get_bodies (w, ids, 600), i, escaped = 0, nan = 0;
  double e0 = kinetic (w, ids, n), e1, drift;
  for (i = 0; i < 100000; ++i)
    carom_world_update (w, 1.0 / 60);
  for (i = 0; i < n; ++i)
    {
      double x, y, m;
      carom_body_get_position (w, ids[i], &x, &y);
      carom_body_get_mass (w, ids[i], &m, NULL, NULL);
      if (!isfinite (x) || !isfinite (y))
        nan++;
      else if (m > 0.0 && (x < 0.0 || x > 50.0 || y < 0.0 || y > 40.0)) /* bounds 0 0 50 40 */
        escaped++;
    }
  e1 = kinetic (w, ids, n);
  drift = e1 / e0 - 1.0;
  report ("gas: bodies with a NaN state after 100000 steps", nan == 0, "%.0f (bound %.0f)", nan, 0);
  report ("gas: bodies outside the box after 100000 steps", escaped == 0, "%.0f (bound %.0f)", escaped, 0);
  report ("gas: |kinetic energy drift| over 100000 steps", fabs (drift) < 0.01, "%.4f (bound %.2f)", drift, 0.01);
  carom_world_destroy (w);
}

/* The gas again, 2000 steps (33 s), as the stability table states it: the
 * kinetic energy within 0.1% at every step, not only at the end. */
static void gas_short (void)
{
  carom_world *w = load ("scenes/gas.scene");
  carom_body_id ids[600];
  int32_t n = carom_world_get_bodies (w, ids, 600), i;
  double e0 = kinetic (w, ids, n), worst = 0.0;
  for (i = 0; i < 2000; ++i)
    {
      double d;
      carom_world_update (w, 1.0 / 60);
      d = fabs (kinetic (w, ids, n) / e0 - 1.0);
      worst = d > worst ? d : worst;
    }
  report ("gas: largest |kinetic energy drift| over 2000 steps", worst < 1e-3, "%.2e (bound %.0e)", worst, 1e-3);
  carom_world_destroy (w);
}

/* Stacks at the library defaults, 10 s at dt 1/60: n boxes w x h built
 * exactly touching on a static ground, friction mu. Bounds, as the largest
 * excursion over the run: the top box moves sideways less than 1% of its
 * width and sinks less than 1% of the stack's height, and no body's centre
 * ever goes below the ground's top. */
static void stack (const char *name, int n, double w, double h, double mu)
{
  carom_world *world;
  carom_world_def def;
  carom_body_def d;
  carom_body_id ids[64];
  double x0, y0, side = 0.0, sag = 0.0, lowest = INFINITY;
  char label[128];
  int i, step;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -9.81;
  def.friction = mu;
  if (n > 64 || carom_world_init (&world, &def) != CAROM_OK)
    exit (2);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -10.0 * h;
  carom_world_add_box (world, &d, 100.0 * w, 20.0 * h, NULL);
  for (i = 0; i < n; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.y = h * (i + 0.5);
      if (carom_world_add_box (world, &d, w, h, &ids[i]) != CAROM_OK)
        exit (2);
    }
  carom_body_get_position (world, ids[n - 1], &x0, &y0);
  for (step = 0; step < 600; ++step)
    {
      double x, y;
      carom_world_update (world, 1.0 / 60);
      carom_body_get_position (world, ids[n - 1], &x, &y);
      side = fabs (x - x0) > side ? fabs (x - x0) : side;
      sag = y0 - y > sag ? y0 - y : sag;
      for (i = 0; i < n; ++i)
        {
          carom_body_get_position (world, ids[i], NULL, &y);
          lowest = y < lowest ? y : lowest;
        }
    }
  snprintf (label, sizeof label, "%s: top's largest sideways motion / width", name);
  report (label, side < 0.01 * w, "%.2e (bound %.0e)", side / w, 0.01);
  snprintf (label, sizeof label, "%s: top's largest sag / stack height", name);
  report (label, sag < 0.01 * n * h, "%.2e (bound %.0e)", sag / (n * h), 0.01);
  snprintf (label, sizeof label, "%s: lowest centre / box height", name);
  report (label, lowest > 0.0, "%.3f (bound > %.0f)", lowest / h, 0.0);
  carom_world_destroy (world);
}

/* Case 18: the heavy chain of tests/test_joints.c swinging down, from 256
 * starts a millionth of a radian apart (where it snaps taut again is
 * chaotic: one start says little). Bound: its joints' gaps never add up to
 * 1% of its length. */
static void chain_swings (void)
{
  double worst = 0.0;
  int k;
  for (k = 0; k < 256; ++k)
    {
      double r = heavy_chain_stretch (10.0, 1, k * 1e-6, 480);
      if (r < 0.0)
        exit (2);
      worst = r > worst ? r : worst;
    }
  report ("heavy chain swinging, 256 starts: largest stretch / length", worst < 0.01, "%.2e (bound %.0e)", worst,
          0.01);
}

/* The fastest any of the n + 1 bodies `ids` moves upward (along -g). */
static double fastest_up (const carom_world *w, const carom_body_id *ids, int n)
{
  double up = 0.0, vx, vy;
  int i;
  for (i = 0; i < n; ++i)
    {
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      up = vy > up ? vy : up;
    }
  return up;
}

/* A 1 x 1 box (e = 0, friction 0.3) dropped from h onto a column of n
 * resting 1 x 1 boxes shifted 0.01 alternately left and right (built
 * touching on a static ground), 4 s at the defaults, continuous collision
 * on or off. Returns the fastest upward speed of any box over the run,
 * over the impact speed sqrt (2 g h). */
static double drop_on_column (int n, double h, int continuous)
{
  carom_world *w;
  carom_world_def def;
  carom_body_def d;
  carom_body_id ids[16];
  double worst = 0.0;
  int i, step;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 0.3;
  if (n > 15 || carom_world_init (&w, &def) != CAROM_OK || carom_world_set_continuous (w, continuous) != CAROM_OK)
    exit (2);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC, d.y = -1.0;
  carom_world_add_box (w, &d, 200.0, 2.0, NULL);
  for (i = 0; i <= n; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.x = i % 2 == 0 ? -0.01 : 0.01;
      d.y = 0.5 + i + (i == n ? h : 0.0);
      if (carom_world_add_box (w, &d, 1.0, 1.0, &ids[i]) != CAROM_OK)
        exit (2);
    }
  for (step = 0; step < 240; ++step)
    {
      double up;
      carom_world_update (w, 1.0 / 60);
      up = fastest_up (w, ids, n + 1);
      worst = up > worst ? up : worst;
    }
  carom_world_destroy (w);
  return worst / sqrt (2.0 * 10.0 * h);
}

/* Case 17, a known failure: an inelastic box dropped on a column of boxes
 * at rest does not throw anything up. Over columns of 1, 2, 4, 8 and 14
 * boxes, drops of 0.5, 1 and 2 m, continuous collision on and off: no box
 * ever rises faster than 1% of the impact speed. */
static void drops_on_columns (void)
{
  static const int columns[] = { 1, 2, 4, 8, 14 };
  static const double heights[] = { 0.5, 1.0, 2.0 };
  double worst = 0.0, at_h = 0.0;
  size_t i, j;
  int continuous, at_n = 0, at_c = 0;
  for (i = 0; i < sizeof columns / sizeof columns[0]; ++i)
    for (j = 0; j < sizeof heights / sizeof heights[0]; ++j)
      for (continuous = 0; continuous <= 1; ++continuous)
        {
          double r = drop_on_column (columns[i], heights[j], continuous);
          if (r > worst)
            worst = r, at_n = columns[i], at_h = heights[j], at_c = continuous;
        }
  report ("box dropped on a column (e = 0): fastest rise / impact speed", worst < 0.01, "%.3f (bound %.2f)", worst,
          0.01);
  printf ("     the worst: a column of %d, dropped %g m, continuous collision %s\n", at_n, at_h, at_c ? "on" : "off");
}

/* A world for piles of boxes of side `size` (friction 0.6, g = 10), its
 * ground a static box 40 sides wide whose top is at y = 0. */
static carom_world *pile_world (double size, int continuous)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 0.6;
  if (carom_world_init (&w, &def) != CAROM_OK || carom_world_set_continuous (w, continuous) != CAROM_OK)
    exit (2);
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.y = -0.5 * size;
  carom_world_add_box (w, &d, 40 * size, size, NULL);
  return w;
}

/* Steps a pile 10 s at dt 1/60: the deepest contact over the last second,
 * as a fraction of a side. */
static double pile_deepest (carom_world *w, double size)
{
  double deepest = 0.0;
  int k, step;
  for (step = 0; step < 600; ++step)
    {
      carom_world_update (w, 1.0 / 60);
      for (k = 0; step >= 540 && k < carom_world_contact_count (w); ++k)
        {
          double depth;
          carom_world_get_contact (w, k, NULL, NULL, NULL, NULL, NULL, NULL, &depth);
          deepest = depth > deepest ? depth : deepest;
        }
    }
  return deepest / size;
}

/* One bin of 200 boxes of side `size`, dropped from an 11-wide grid 1.6
 * sides apart, each turned 0.37 rad more than the last, between two walls
 * 20 sides apart: pile_deepest. */
static double bin_of_boxes (double size, int continuous)
{
  carom_world *w = pile_world (size, continuous);
  carom_body_def d;
  double deepest;
  int i;
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.x = -10 * size, d.y = 20 * size;
  carom_world_add_box (w, &d, size, 40 * size, NULL);
  d.x = 10 * size;
  carom_world_add_box (w, &d, size, 40 * size, NULL);
  carom_body_def_init (&d, sizeof d);
  for (i = 0; i < 200; ++i)
    {
      d.x = (-8 + (i % 11) * 1.6) * size, d.y = (2 + (i / 11) * 1.6) * size, d.angle = 0.37 * i;
      carom_world_add_box (w, &d, size, size, NULL);
    }
  deepest = pile_deepest (w, size);
  carom_world_destroy (w);
  return deepest;
}

/* A column of 18 boxes of side 5 cm built 2.5 mm apart: pile_deepest, and
 * whether the column has fallen (its top below 17 sides). */
static double column_of_small_boxes (int continuous, int *fallen)
{
  double size = 0.05, deepest, x, y;
  carom_world *w = pile_world (size, continuous);
  carom_body_def d;
  carom_body_id top = CAROM_NULL_BODY;
  int i;
  carom_body_def_init (&d, sizeof d);
  for (i = 0; i < 18; ++i)
    {
      d.y = (i + 0.5) * size + (i + 1) * 0.05 * size;
      carom_world_add_box (w, &d, size, size, &top);
    }
  deepest = pile_deepest (w, size);
  carom_body_get_position (w, top, &x, &y);
  carom_world_destroy (w);
  *fallen = y < 17.0 * size;
  return deepest;
}

/* Case 19, a known failure: piles of small boxes settle without boxes left
 * inside each other. Bins of 200 boxes of side 5 cm, 10 cm, 50 cm and 1 m,
 * and a column of 18 boxes of side 5 cm built 2.5 mm apart, continuous
 * collision on and off: over the last second of 10 s, no contact deeper
 * than 2% of a side (two slops), and the column stands. */
static void piles_of_small_boxes (void)
{
  static const double sizes[] = { 0.05, 0.1, 0.5, 1.0 };
  double worst = 0.0, at_size = 0.0;
  size_t i;
  int continuous, at_c = 0, fallen = 0;
  for (i = 0; i < sizeof sizes / sizeof sizes[0]; ++i)
    for (continuous = 0; continuous <= 1; ++continuous)
      {
        double r = bin_of_boxes (sizes[i], continuous);
        printf ("     %g m boxes, continuous collision %s: deepest %.3f of a side\n", sizes[i], continuous ? "on" : "off",
                r);
        if (r > worst)
          worst = r, at_size = sizes[i], at_c = continuous;
      }
  for (continuous = 0; continuous <= 1; ++continuous)
    {
      int fell;
      double r = column_of_small_boxes (continuous, &fell);
      printf ("     a column of 18 5 cm boxes, continuous collision %s: deepest %.3f of a side%s\n",
              continuous ? "on" : "off", r, fell ? ", fallen" : "");
      fallen += fell;
      if (r > worst)
        worst = r, at_size = -1.0, at_c = continuous;
    }
  report ("piles of small boxes: deepest contact over the last second / side", worst < 0.02 && fallen == 0,
          "%.3f (bound %.2f; and the column stands)", worst, 0.02);
  printf ("     columns fallen: %d of 2\n", fallen);
  if (at_size > 0.0)
    printf ("     the worst: a bin of %g m boxes, continuous collision %s\n", at_size, at_c ? "on" : "off");
  else
    printf ("     the worst: the column, continuous collision %s\n", at_c ? "on" : "off");
}

/* The cases carom is known to fail at the defaults, with their figures
 * from `stress --all`: left out of the default run (make stress) until
 * carom meets their bounds. */
static const struct
{
  const char *name;
  void (*run) (void);
  const char *known;
} known_failures[] = {
  { "box dropped on a column", drops_on_columns,
    "fastest rise / impact speed 0.106 (bound 0.01; a column of 1, dropped 1 m): the impulse that stopped the "
    "impact is warm started into the next sub-step, and a pass down the column takes back only part of it" },
  { "piles of small boxes", piles_of_small_boxes,
    "deepest contact over the last second / side 0.039 (bound 0.02; a bin of 5 cm boxes, continuous collision "
    "off; 0.013 on; 10 cm 0.007; 50 cm and 1 m within the slop), and a column of 18 5 cm boxes falls over "
    "without continuous collision: a column of small boxes leans from any offset, and the lean grows "
    "(docs/stability.md, case 19c)" },
};

int main (int argc, char **argv)
{
  int all = argc > 1 && strcmp (argv[1], "--all") == 0, skipped = 0;
  size_t k;
  if (argc > 1 && !all)
    {
      fprintf (stderr, "usage: %s [--all]\n", argv[0]);
      return 2;
    }
  pyramid ();
  gas ();
  gas_short ();
  stack ("tower of 30 unit boxes, friction 0.6", 30, 1.0, 1.0, 0.6);
  stack ("tower of 15 unit boxes, no friction", 15, 1.0, 1.0, 0.0);
  stack ("40 planks 2 x 0.5, friction 0.6", 40, 2.0, 0.5, 0.6);
  stack ("ten 1 cm boxes, friction 0.6", 10, 0.01, 0.01, 0.6);
  chain_swings ();
  for (k = 0; k < sizeof known_failures / sizeof known_failures[0]; ++k)
    if (all)
      known_failures[k].run ();
    else
      {
        printf ("skip %s: known failure: %s\n", known_failures[k].name, known_failures[k].known);
        skipped++;
      }
  printf ("stress: %d passed, %d failed, %d skipped\n", passed, failed, skipped);
  return failed ? 1 : 0;
}
