/* Erin Catto's Solver2D contact samples (samples/collection/sample_contact.cpp
 * of github.com/erincatto/solver2d), ported to carom's public API and run at
 * the library defaults (carom_world_def_init: 4 sub-steps, 1 iteration) at
 * dt 1/60 with the samples' gravity (0, -10), sizes, positions, densities,
 * friction and restitution. Each sample has one bound that says whether it
 * behaves as the sample means; docs/stability.md ("Solver2D's contact
 * samples") states them and what carom reaches.
 *
 * What the port changes, because carom has no such shape or call:
 *   - Solver2D's segments (one-sided ground lines) are static boxes 1 thick
 *     whose top face lies on the segment, as long as the segment;
 *   - Confined's walls are capsules of radius 0.5: static boxes covering the
 *     capsules' straight parts (their inner faces are the capsules' inner
 *     faces; only the rounded outer ends are missing, which nothing touches);
 *   - gravityScale 0 (Rush, Confined): every dynamic body of those samples
 *     has it, so the world's gravity is 0 there;
 *   - Rush pulls each body with a force of 1000 N towards the origin, added
 *     in every sub-step by Solver2D. carom has no per-body force: the force
 *     is applied as its impulse over the step, a velocity change F dt / m
 *     set before each update, which the sub-steps then solve against;
 *   - Double Domino's impulse (0.2, 0) at the first domino's top is given as
 *     the velocity and spin it produces.
 * Every sample runs 10 s (600 steps) but the Friction Ramp (40 s).
 *
 * Usage: solver2d [--all] [--only=NAME] [--substeps=N] [--iterations=N].
 * Without --all the samples carom is known to fail at the defaults are not
 * run: each prints a "skip" line with its figures from a --all run, and the
 * closing line counts them. With --all every sample runs and a failure exits
 * 1; --only runs the one sample of that name (known failure or not);
 * --substeps and --iterations replace the defaults. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carom.h"
#include "kinetic.h"

#define DT (1.0 / 60.0)
#define PI 3.14159265358979323846

static int passed, failed;
/* --substeps=N, --iterations=N: the world's, instead of the defaults (to
 * see what more solver work buys; 0: the default) */
static int substeps, iterations;

static void report (const char *name, int ok, const char *fmt, ...)
{
  va_list ap;
  printf ("%s %s: ", ok ? "ok  " : "FAIL", name);
  va_start (ap, fmt);
  vprintf (fmt, ap);
  va_end (ap);
  printf ("\n");
  fflush (stdout);
  if (ok)
    passed++;
  else
    failed++;
}

static void check (carom_status s, const char *what)
{
  if (s != CAROM_OK)
    {
      fprintf (stderr, "solver2d: %s: %s\n", what, carom_status_string (s));
      exit (2);
    }
}

/* A world at the library defaults with gravity (0, gy). */
static carom_world *world_new (double gy)
{
  carom_world *w;
  carom_world_def def;
  check (carom_world_def_init (&def, sizeof def), "world_def_init");
  def.gravity_y = gy;
  if (substeps > 0)
    def.substeps = substeps;
  if (iterations > 0)
    def.iterations = iterations;
  check (carom_world_init (&w, &def), "world_init");
  return w;
}

static void step (carom_world *w)
{
  check (carom_world_update (w, DT), "world_update");
}

static void body_def (carom_body_def *d, carom_body_type type, double x, double y, double angle, double density,
                      double friction)
{
  carom_body_def_init (d, sizeof *d);
  d->type = type, d->x = x, d->y = y, d->angle = angle;
  d->density = density, d->friction = friction, d->restitution = 0.0;
}

static carom_body_id box (carom_world *w, carom_body_type type, double x, double y, double angle, double width,
                          double height, double density, double friction)
{
  carom_body_def d;
  carom_body_id id;
  body_def (&d, type, x, y, angle, density, friction);
  check (carom_world_add_box (w, &d, width, height, &id), "add_box");
  return id;
}

static carom_body_id circle (carom_world *w, carom_body_type type, double x, double y, double radius,
                             double density, double friction)
{
  carom_body_def d;
  carom_body_id id;
  body_def (&d, type, x, y, 0.0, density, friction);
  check (carom_world_add_circle (w, &d, radius, &id), "add_circle");
  return id;
}

/* A dynamic polygon whose vertices are given in world coordinates: carom
 * places a polygon's centroid at the def's position, so put it where the
 * outline's centroid is. */
static carom_body_id polygon (carom_world *w, const double *xy, int n, double friction)
{
  carom_body_def d;
  carom_body_id id;
  double a = 0.0, cx = 0.0, cy = 0.0, local[64];
  int i;
  for (i = 0; i < n; ++i)
    {
      int j = (i + 1) % n;
      double c = xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
      a += c;
      cx += (xy[2 * i] + xy[2 * j]) * c;
      cy += (xy[2 * i + 1] + xy[2 * j + 1]) * c;
    }
  cx /= 3.0 * a, cy /= 3.0 * a;
  for (i = 0; i < n; ++i)
    local[2 * i] = xy[2 * i] - cx, local[2 * i + 1] = xy[2 * i + 1] - cy;
  body_def (&d, CAROM_DYNAMIC, cx, cy, 0.0, 1.0, friction);
  check (carom_world_add_polygon (w, &d, local, n, &id), "add_polygon");
  return id;
}

/* A Solver2D segment from x0 to x1 at height y: a static box 1 thick below it. */
static void segment (carom_world *w, double x0, double x1, double y, double friction)
{
  box (w, CAROM_STATIC, 0.5 * (x0 + x1), y - 0.5, 0.0, x1 - x0, 1.0, 1.0, friction);
}

static void pos (const carom_world *w, carom_body_id id, double *x, double *y)
{
  check (carom_body_get_position (w, id, x, y), "get_position");
}

static double angle_of (const carom_world *w, carom_body_id id)
{
  double a;
  check (carom_body_get_angle (w, id, &a), "get_angle");
  return a;
}

static double speed (const carom_world *w, carom_body_id id)
{
  double vx, vy;
  check (carom_body_get_velocity (w, id, &vx, &vy), "get_velocity");
  return hypot (vx, vy);
}

static double max2 (double a, double b)
{
  return a > b || a != a ? a : b; /* NaN wins, so it fails every bound */
}

/* The largest distance of a box's corners from where they would be at the
 * pose (x, y, angle). */
static double corner_offset (const carom_world *w, carom_body_id id, double width, double height, double x,
                             double y, double angle)
{
  double px, py, a = angle_of (w, id), worst = 0.0;
  int i;
  pos (w, id, &px, &py);
  for (i = 0; i < 4; ++i)
    {
      double cx = (i & 1 ? 0.5 : -0.5) * width, cy = (i & 2 ? 0.5 : -0.5) * height;
      double ax = px + cos (a) * cx - sin (a) * cy, ay = py + sin (a) * cx + cos (a) * cy;
      double bx = x + cos (angle) * cx - sin (angle) * cy, by = y + sin (angle) * cx + cos (angle) * cy;
      worst = max2 (worst, hypot (ax - bx, ay - by));
    }
  return worst;
}

/* Single Box: a 2 x 2 box dropped from y = 4 onto the ground, friction 0.5.
 * Bound: once landed (from 2 s on) it rests flat where it fell: no corner
 * ever more than 1% of its side from the resting pose (0, 1, 0). */
static void single_box (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id b;
  double worst = 0.0;
  int i;
  segment (w, -66.0, 66.0, 0.0, 0.5);
  b = box (w, CAROM_DYNAMIC, 0.0, 4.0, 0.0, 2.0, 2.0, 1.0, 0.5);
  for (i = 1; i <= 600; ++i)
    {
      step (w);
      if (i >= 120)
        worst = max2 (worst, corner_offset (w, b, 2.0, 2.0, 0.0, 1.0, 0.0));
    }
  report ("Single Box: largest corner distance from rest after 2 s / side", worst < 0.01 * 2.0,
          "%.2e (bound %.0e)", worst / 2.0, 0.01);
  carom_world_destroy (w);
}

/* Warm Start Energy: three circles r = 0.5 stacked touching on the ground,
 * the top one 100 times denser; after 120 steps the heavy one is removed.
 * The impulses the lower two carried under it must not launch them when it
 * goes: from then on neither rises more than 1% of its radius above where
 * it was built. */
static void warm_start_energy (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id c[3];
  double rise = 0.0, vmax = 0.0;
  int i, k;
  segment (w, -10.0, 10.0, 0.0, 0.6);
  for (k = 0; k < 3; ++k)
    c[k] = circle (w, CAROM_DYNAMIC, 0.0, 0.5 + k, 0.5, k == 2 ? 100.0 : 1.0, 0.6);
  for (i = 0; i < 600; ++i)
    {
      if (i == 120)
        check (carom_world_remove_body (w, c[2]), "remove_body");
      step (w);
      if (i >= 120)
        for (k = 0; k < 2; ++k)
          {
            double x, y;
            pos (w, c[k], &x, &y);
            rise = max2 (rise, y - (0.5 + k));
            vmax = max2 (vmax, speed (w, c[k]));
          }
    }
  report ("Warm Start Energy: largest rise above the built height after the removal / radius", rise < 0.01 * 0.5,
          "%.2e (bound %.0e; fastest %.3f m/s)", rise / 0.5, 0.01, vmax);
  carom_world_destroy (w);
}

/* High Mass Ratio 1: three pyramids of 2 x 2 boxes, base 10, each topped by
 * a box 100, 200 and 300 times denser dropped from 2 m above its place;
 * friction 0.5. Bound: the light boxes are not crushed: from 3 s on no heavy
 * box is ever lower than its exactly stacked height by more than 1% of a
 * light box's side per layer beneath it (9 layers: 0.18 m). */
static void high_mass_ratio_1 (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id heavy[3];
  double sink = 0.0;
  int i, j;
  segment (w, -66.0, 66.0, 0.0, 0.5);
  for (j = 0; j < 3; ++j)
    {
      int count = 10;
      double offset = -20.0 + 2.0 * (count + 1.0) * j, y = 1.0;
      while (count > 0)
        {
          for (i = 0; i < count; ++i)
            {
              double coeff = i - 0.5 * count;
              carom_body_id id = box (w, CAROM_DYNAMIC, 2.0 * coeff + offset, count == 1 ? y + 2.0 : y, 0.0, 2.0,
                                      2.0, count == 1 ? (j + 1.0) * 100.0 : 1.0, 0.5);
              if (count == 1)
                heavy[j] = id;
            }
          --count;
          y += 2.0;
        }
    }
  for (i = 1; i <= 600; ++i)
    {
      step (w);
      if (i >= 180)
        for (j = 0; j < 3; ++j)
          {
            double x, y;
            pos (w, heavy[j], &x, &y);
            sink = max2 (sink, 19.0 - y);
          }
    }
  report ("High Mass Ratio 1: heavy boxes' largest sink after 3 s / (9 layers x light side)",
          sink < 0.01 * 2.0 * 9, "%.2e (bound %.0e)", sink / (2.0 * 9), 0.01);
  carom_world_destroy (w);
}

/* High Mass Ratio 2 and 3: a 20 x 20 box dropped from 15 m onto two 1 x 1
 * boxes 18 m apart (mass ratio 400), friction 0.6; 2 stands on a 40 m
 * ground segment, 3 on an 80 x 4 ground box (the same thing in carom, whose
 * ground is always a box). Bound: the small boxes are not crushed: from 3 s
 * on the big box is never lower than its stacked height (11) by more than
 * 1% of a small box's side. */
static void high_mass_ratio_23 (const char *name, double ground_width, double ground_height)
{
  carom_world *w = world_new (-10.0);
  carom_body_id big;
  double sink = 0.0;
  char label[160];
  int i;
  box (w, CAROM_STATIC, 0.0, -0.5 * ground_height, 0.0, ground_width, ground_height, 1.0, 0.6);
  box (w, CAROM_DYNAMIC, -9.0, 0.5, 0.0, 1.0, 1.0, 1.0, 0.6);
  box (w, CAROM_DYNAMIC, 9.0, 0.5, 0.0, 1.0, 1.0, 1.0, 0.6);
  big = box (w, CAROM_DYNAMIC, 0.0, 26.0, 0.0, 20.0, 20.0, 1.0, 0.6);
  for (i = 1; i <= 600; ++i)
    {
      step (w);
      if (i >= 180)
        {
          double x, y;
          pos (w, big, &x, &y);
          sink = max2 (sink, 11.0 - y);
        }
    }
  snprintf (label, sizeof label, "%s: big box's largest sink after 3 s / small side", name);
  report (label, sink < 0.01 * 1.0, "%.2e (bound %.0e)", sink / 1.0, 0.01);
  carom_world_destroy (w);
}

/* Friction Ramp: five 1 x 1 boxes (density 25, friction 0.75, 0.5, 0.35,
 * 0.1, 0) dropped onto a zig-zag of three ramps tilted 0.25 rad (friction
 * 0.2) above the ground. Mixed by the geometric mean, as in Solver2D, the
 * first three have 0.39, 0.32 and 0.26, above tan 0.25 = 0.255: Coulomb
 * friction brakes them, and they come to rest on a ramp (the 0.26 box lands
 * sliding at about 3 m/s and brakes at only 0.09 m/s^2, so it leaves the
 * first ramp and stops about 24 s in, on the second); the last two (0.14,
 * 0) speed up and slide down all the ramps to the ground. Run 40 s. Bounds:
 * every braking box moves less than 1% of its side over the last 5 s and
 * lies on a ramp (centre above y = 2); every sliding box has left the
 * ramps (centre below y = 1: on the ground, or, frictionless, slid off its
 * end). */
static void friction_ramp (void)
{
  static const double mu[5] = { 0.75, 0.5, 0.35, 0.1, 0.0 };
  carom_world *w = world_new (-10.0);
  carom_body_id b[5];
  double x35[5], y35[5], creep = 0.0, stick_low = INFINITY, slide_high = -INFINITY;
  int i, k, sticks[5];
  segment (w, -40.0, 40.0, 0.0, 0.2);
  box (w, CAROM_STATIC, -4.0, 22.0, -0.25, 26.0, 0.5, 1.0, 0.2);
  box (w, CAROM_STATIC, 10.5, 19.0, 0.0, 0.5, 2.0, 1.0, 0.2);
  box (w, CAROM_STATIC, 4.0, 14.0, 0.25, 26.0, 0.5, 1.0, 0.2);
  box (w, CAROM_STATIC, -10.5, 11.0, 0.0, 0.5, 2.0, 1.0, 0.2);
  box (w, CAROM_STATIC, -4.0, 6.0, -0.25, 26.0, 0.5, 1.0, 0.2);
  for (k = 0; k < 5; ++k)
    {
      b[k] = box (w, CAROM_DYNAMIC, -15.0 + 4.0 * k, 28.0, 0.0, 1.0, 1.0, 25.0, mu[k]);
      sticks[k] = sqrt (0.2 * mu[k]) > tan (0.25);
    }
  for (i = 1; i <= 2400; ++i)
    {
      step (w);
      for (k = 0; k < 5; ++k)
        {
          double x, y;
          pos (w, b[k], &x, &y);
          if (i == 2100)
            x35[k] = x, y35[k] = y;
          else if (i > 2100 && sticks[k])
            creep = max2 (creep, hypot (x - x35[k], y - y35[k]));
          if (i == 2400 && sticks[k])
            stick_low = fmin (stick_low, y);
          else if (i == 2400)
            slide_high = max2 (slide_high, y);
        }
    }
  report ("Friction Ramp: braking boxes' largest motion over the last 5 s / side",
          creep < 0.01 && stick_low > 2.0 && slide_high < 1.0,
          "%.2e (bound %.0e); their lowest centre %.2f (bound > 2); sliding boxes' highest %.2f (bound < 1)", creep,
          0.01, stick_low, slide_high);
  carom_world_destroy (w);
}

/* Overlap Recovery: a pyramid of ten 1 x 1 boxes, base 4, built with each
 * box overlapping its neighbours by a quarter of its side, on the ground.
 * Bound: they push apart without being launched: no body ever faster than
 * 1 m/s, and after 10 s no contact deeper than 2 slops (carom's slop: 1% of
 * the smaller body's size, 0.005 m for these boxes). */
static void overlap_recovery (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id ids[10];
  int n = 0, i, j, c;
  double fraction = 0.75, extent = 0.5, y = extent, vmax = 0.0, deepest = 0.0, slop = 0.01 * 0.5;
  segment (w, -40.0, 40.0, 0.0, 0.6);
  for (i = 0; i < 4; ++i)
    {
      double x = fraction * extent * (i - 4);
      for (j = i; j < 4; ++j)
        {
          ids[n++] = box (w, CAROM_DYNAMIC, x, y, 0.0, 1.0, 1.0, 1.0, 0.6);
          x += 2.0 * fraction * extent;
        }
      y += 2.0 * fraction * extent;
    }
  for (i = 0; i < 600; ++i)
    {
      step (w);
      for (j = 0; j < n; ++j)
        vmax = max2 (vmax, speed (w, ids[j]));
    }
  for (c = 0; c < carom_world_contact_count (w); ++c)
    {
      double depth;
      check (carom_world_get_contact (w, c, NULL, NULL, NULL, NULL, NULL, NULL, &depth), "get_contact");
      deepest = max2 (deepest, depth);
    }
  report ("Overlap Recovery: fastest body (m/s); deepest contact at 10 s / slop", vmax < 1.0 && deepest < 2.0 * slop,
          "%.3f (bound 1); %.2f (bound 2)", vmax, deepest / slop);
  carom_world_destroy (w);
}

/* Vertical Stack: fifteen 1 x 1 boxes, friction 0.3, built 0.1 apart and
 * shifted alternately 0.01 left and right, fall onto each other. Bound: the
 * stack stands: the top box never moves sideways more than 1% of its side
 * from where it was built, and at 10 s it is less than 1% of the stack's
 * height (0.15 m) below its stacked height (14.5). */
static void vertical_stack (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id ids[15];
  double side = 0.0, x0 = -0.01, x, y; /* the top box, k = 14, starts at -0.01 */
  int i, k;
  box (w, CAROM_STATIC, 0.0, -1.0, 0.0, 200.0, 2.0, 1.0, 0.6);
  for (k = 0; k < 15; ++k)
    ids[k] = box (w, CAROM_DYNAMIC, k % 2 == 0 ? -0.01 : 0.01, 0.55 + 1.1 * k, 0.0, 1.0, 1.0, 1.0, 0.3);
  for (i = 0; i < 600; ++i)
    {
      step (w);
      pos (w, ids[14], &x, &y);
      side = max2 (side, fabs (x - x0));
    }
  report ("Vertical Stack: top's largest sideways motion / side", side < 0.01 && 14.5 - y < 0.01 * 15.0,
          "%.2e (bound %.0e); top's sag at 10 s / stack height %.2e (bound %.0e)", side, 0.01, (14.5 - y) / 15.0,
          0.01);
  carom_world_destroy (w);
}

/* Pyramid: base 100, 5050 unit boxes built exactly touching (Solver2D's
 * release build; its debug build uses base 20), friction 0.6. Bound: it
 * stands: the top box never moves more than 1% of its side from where it
 * was built. */
static void pyramid (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id top = CAROM_NULL_BODY;
  double h = 0.5, worst = 0.0, x0 = 0.0, y0 = 0.0;
  int base = 100, i, j;
  box (w, CAROM_STATIC, 0.0, -1.0, 0.0, 200.0, 2.0, 1.0, 0.6);
  for (i = 0; i < base; ++i)
    {
      double y = (2.0 * i + 1.0) * h;
      for (j = i; j < base; ++j)
        {
          double x = (i + 1.0) * h + 2.0 * (j - i) * h - h * base;
          top = box (w, CAROM_DYNAMIC, x, y, 0.0, 1.0, 1.0, 1.0, 0.6);
          x0 = x, y0 = y;
        }
    }
  for (i = 0; i < 600; ++i)
    {
      double x, y;
      step (w);
      pos (w, top, &x, &y);
      worst = max2 (worst, hypot (x - x0, y - y0));
    }
  report ("Pyramid: top box's largest motion / side", worst < 0.01, "%.2e (bound %.0e)", worst, 0.01);
  carom_world_destroy (w);
}

/* Rush: 400 circles r = 0.5 (density 100, friction 0.2) on a spiral from
 * 5 m to 25 m, each pulled by 1000 N towards a static circle at the origin,
 * no gravity. They rush in and pile up around it. Bound: nothing explodes:
 * every state finite, and the mechanical energy (kinetic plus the pull's
 * potential F r) never above its start by more than 1%: contacts and
 * friction only take energy away. */
static void rush (void)
{
  enum { COUNT = 400 };
  carom_world *w = world_new (0.0);
  carom_body_id ids[COUNT];
  double distance = 5.0, ang = 0.0, force = 1000.0, mass, e0 = 0.0, worst = -INFINITY;
  int i, k, nan = 0;
  circle (w, CAROM_STATIC, 0.0, 0.0, 0.5, 100.0, 0.2);
  for (k = 0; k < COUNT; ++k)
    {
      ids[k] = circle (w, CAROM_DYNAMIC, distance * cos (ang), distance * sin (ang), 0.5, 100.0, 0.2);
      e0 += force * distance;
      ang += 1.0 / 5.0;
      distance += 0.05;
    }
  carom_body_get_mass (w, ids[0], &mass, NULL, NULL);
  for (i = 0; i < 600; ++i)
    {
      double e;
      for (k = 0; k < COUNT; ++k)
        {
          double x, y, vx, vy, r;
          pos (w, ids[k], &x, &y);
          r = hypot (x, y);
          if (!(r >= 0.1)) /* Solver2D's: no pull within 0.1 of the centre */
            continue;
          carom_body_get_velocity (w, ids[k], &vx, &vy);
          check (carom_body_set_velocity (w, ids[k], vx - force / mass * DT * x / r, vy - force / mass * DT * y / r),
                 "set_velocity");
        }
      step (w);
      e = kinetic (w, ids, COUNT);
      for (k = 0; k < COUNT; ++k)
        {
          double x, y;
          pos (w, ids[k], &x, &y);
          if (!isfinite (x) || !isfinite (y))
            nan++;
          e += force * hypot (x, y);
        }
      worst = max2 (worst, e / e0 - 1.0);
    }
  report ("Rush: largest mechanical energy gain / start", nan == 0 && worst < 0.01,
          "%+.2e (bound %.0e); non-finite states %d (bound 0)", worst, 0.01, nan);
  carom_world_destroy (w);
}

/* Arch: the 17 blocks of Solver2D's arch (its two curves scaled by 0.25:
 * a span of 12 m, 11 m high), friction 0.6, with four 4 x 1 boxes stacked
 * on its keystone. Bound: it stands: the top box never moves more than 1%
 * of its height (0.01 m) from where it was built. */
static void arch (void)
{
  static const double ps1[9][2] = { { 16.0, 0.0 },
                                    { 14.93803712795643, 5.133601056842984 },
                                    { 13.79871746027416, 10.24928069555078 },
                                    { 12.56252963284711, 15.34107019122473 },
                                    { 11.20040987372525, 20.39856541571217 },
                                    { 9.66521217819836, 25.40369899225096 },
                                    { 7.87179930638133, 30.3179337000085 },
                                    { 5.635199558196225, 35.03820717801641 },
                                    { 2.405937953536585, 39.09554102558315 } };
  static const double ps2[9][2] = { { 24.0, 0.0 },
                                    { 22.33619528222415, 6.02299846205841 },
                                    { 20.54936888969905, 12.00964361211476 },
                                    { 18.60854610798073, 17.9470321677465 },
                                    { 16.46769273811807, 23.81367936585418 },
                                    { 14.05325025774858, 29.57079353071012 },
                                    { 11.23551045834022, 35.13775818285372 },
                                    { 7.752568160730571, 40.30450679009583 },
                                    { 3.016931552701656, 44.28891593799322 } };
  carom_world *w = world_new (-10.0);
  double p1[9][2], p2[9][2], q[8], worst = 0.0, y0 = 0.0;
  carom_body_id top = CAROM_NULL_BODY;
  int i;
  for (i = 0; i < 9; ++i)
    p1[i][0] = 0.25 * ps1[i][0], p1[i][1] = 0.25 * ps1[i][1], p2[i][0] = 0.25 * ps2[i][0],
    p2[i][1] = 0.25 * ps2[i][1];
  segment (w, -100.0, 100.0, 0.0, 0.6);
  for (i = 0; i < 8; ++i)
    {
      q[0] = p1[i][0], q[1] = p1[i][1], q[2] = p2[i][0], q[3] = p2[i][1];
      q[4] = p2[i + 1][0], q[5] = p2[i + 1][1], q[6] = p1[i + 1][0], q[7] = p1[i + 1][1];
      polygon (w, q, 4, 0.6);
    }
  for (i = 0; i < 8; ++i)
    {
      q[0] = -p2[i][0], q[1] = p2[i][1], q[2] = -p1[i][0], q[3] = p1[i][1];
      q[4] = -p1[i + 1][0], q[5] = p1[i + 1][1], q[6] = -p2[i + 1][0], q[7] = p2[i + 1][1];
      polygon (w, q, 4, 0.6);
    }
  q[0] = p1[8][0], q[1] = p1[8][1], q[2] = p2[8][0], q[3] = p2[8][1];
  q[4] = -p2[8][0], q[5] = p2[8][1], q[6] = -p1[8][0], q[7] = p1[8][1];
  polygon (w, q, 4, 0.6);
  for (i = 0; i < 4; ++i)
    {
      y0 = 0.5 + p2[8][1] + 1.0 * i;
      top = box (w, CAROM_DYNAMIC, 0.0, y0, 0.0, 4.0, 1.0, 1.0, 0.6);
    }
  for (i = 0; i < 600; ++i)
    {
      double x, y;
      step (w);
      pos (w, top, &x, &y);
      worst = max2 (worst, hypot (x, y - y0));
    }
  report ("Arch: top box's largest motion / height", worst < 0.01, "%.2e (bound %.0e)", worst, 0.01);
  carom_world_destroy (w);
}

/* Double Domino: fifteen 0.25 x 1 dominoes 1 m apart, friction 0.6; the
 * first is struck at its top by an impulse (0.2, 0). Bound: they fall in
 * sequence: each domino tips past 30 degrees, none before the one behind it,
 * the last one included (15 of 15). */
static void double_domino (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id ids[15];
  int tipped_at[15], i, k, in_order = 0;
  double x = -0.5 * 15, m, inertia, last;
  box (w, CAROM_STATIC, 0.0, -1.0, 0.0, 200.0, 2.0, 1.0, 0.6);
  for (k = 0; k < 15; ++k)
    {
      ids[k] = box (w, CAROM_DYNAMIC, x, 0.5, 0.0, 0.25, 1.0, 1.0, 0.6);
      tipped_at[k] = -1;
      x += 1.0;
    }
  /* the impulse J = (0.2, 0) at (x0, 1.0), 0.5 above the centre: v = J / m,
   * spin = (r x J) / I = -0.5 * 0.2 / I */
  carom_body_get_mass (w, ids[0], &m, &inertia, NULL);
  check (carom_body_set_velocity (w, ids[0], 0.2 / m, 0.0), "set_velocity");
  check (carom_body_set_spin (w, ids[0], -0.5 * 0.2 / inertia), "set_spin");
  for (i = 1; i <= 600; ++i)
    {
      step (w);
      for (k = 0; k < 15; ++k)
        if (tipped_at[k] < 0 && fabs (angle_of (w, ids[k])) > PI / 6)
          tipped_at[k] = i;
    }
  for (k = 0; k < 15; ++k)
    if (tipped_at[k] >= 0 && (k == 0 || (tipped_at[k - 1] >= 0 && tipped_at[k] >= tipped_at[k - 1])))
      in_order++;
    else
      break;
  last = fabs (angle_of (w, ids[14])) * 180.0 / PI;
  report ("Double Domino: dominoes tipped past 30 degrees in sequence", in_order == 15,
          "%d (bound 15); the last one's final tilt %.0f degrees", in_order, last);
  carom_world_destroy (w);
}

/* Confined: 625 circles r = 0.5 on a 25 x 25 grid 0.72 apart (so each
 * overlaps its neighbours), no gravity, friction 0.6, in a closed box whose
 * inside is 20 x 19.5: less than the 491 m^2 the circles cover, so they can
 * never all come apart. Bound: nothing explodes: no centre ever leaves the
 * inside, and no body is ever faster than 1 m/s. */
static void confined (void)
{
  enum { GRID = 25 };
  carom_world *w = world_new (0.0);
  carom_body_id ids[GRID * GRID];
  int n = 0, i, k, out = 0;
  double vmax = 0.0;
  /* the capsules' straight parts: floor and ceiling 22 x 1 centred on
   * y = 0 and 20.5, walls 1 x 21.5 centred on x = -10.5 and 10.5 */
  box (w, CAROM_STATIC, 0.0, 0.0, 0.0, 22.0, 1.0, 1.0, 0.6);
  box (w, CAROM_STATIC, 0.0, 20.5, 0.0, 22.0, 1.0, 1.0, 0.6);
  box (w, CAROM_STATIC, -10.5, 10.25, 0.0, 1.0, 21.5, 1.0, 0.6);
  box (w, CAROM_STATIC, 10.5, 10.25, 0.0, 1.0, 21.5, 1.0, 0.6);
  for (i = 0; i < GRID; ++i)
    for (k = 0; k < GRID; ++k)
      ids[n++] = circle (w, CAROM_DYNAMIC, -8.75 + i * 18.0 / GRID, 1.5 + k * 18.0 / GRID, 0.5, 1.0, 0.6);
  for (i = 0; i < 600; ++i)
    {
      step (w);
      for (k = 0; k < n; ++k)
        {
          double x, y;
          pos (w, ids[k], &x, &y);
          if (!(x > -10.0 && x < 10.0 && y > 0.5 && y < 20.0))
            out++;
          vmax = max2 (vmax, speed (w, ids[k]));
        }
    }
  report ("Confined: fastest body (m/s)", out == 0 && vmax < 1.0,
          "%.3f (bound 1); centre-steps outside the box %d (bound 0)", vmax, out);
  carom_world_destroy (w);
}

/* Card House (from PEEL): 40 cards 0.002 x 0.4, friction 0.7, in five
 * levels of leaning pairs at +-25 degrees with flat cards across them, on
 * an 80 x 4 ground box. It is built with gaps: each leaning pair's tops
 * 4 mm apart, each level's feet 2 mm above the flat card below, and the
 * feet of the lowest 1.7 mm in the ground; closing them lowers the top
 * cards by 2.3 cm in the first second (the upper levels falling onto the
 * lower ones at up to 1 m/s: cards thinner than a sub-step's fall, which
 * stay on them only because bodies that fast for their size are swept,
 * body_swept). Bound: then it stands: from 1 s on the two top cards never
 * move more than 1% of a card's length (4 mm). */
static void card_house (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id ids[64];
  double h = 0.2, t = 0.001, a0 = 25.0 * PI / 180.0, a1 = -a0, a2 = 0.5 * PI, z0 = 0.0, y = h - 0.02;
  double x0[64], y0[64], x1[64], y1[64], top_y = -INFINITY, worst = 0.0, settle = 0.0;
  int nb = 5, n = 0, i, k;
  box (w, CAROM_STATIC, 0.0, -2.0, 0.0, 80.0, 4.0, 1.0, 0.7);
  while (nb)
    {
      double z = z0;
      for (i = 0; i < nb; i++)
        {
          if (i != nb - 1)
            ids[n++] = box (w, CAROM_DYNAMIC, z + 0.25, y + h - 0.015, a2, 2.0 * t, 2.0 * h, 1.0, 0.7);
          ids[n++] = box (w, CAROM_DYNAMIC, z, y, a1, 2.0 * t, 2.0 * h, 1.0, 0.7);
          z += 0.175;
          ids[n++] = box (w, CAROM_DYNAMIC, z, y, a0, 2.0 * t, 2.0 * h, 1.0, 0.7);
          z += 0.175;
        }
      y += h * 2.0 - 0.03;
      z0 += 0.175;
      nb--;
    }
  for (k = 0; k < n; ++k)
    {
      pos (w, ids[k], &x0[k], &y0[k]);
      top_y = fmax (top_y, y0[k]);
    }
  for (i = 1; i <= 600; ++i)
    {
      step (w);
      for (k = 0; k < n; ++k)
        if (y0[k] == top_y)
          {
            double x, yy;
            pos (w, ids[k], &x, &yy);
            if (i == 60)
              {
                x1[k] = x, y1[k] = yy;
                settle = max2 (settle, hypot (x - x0[k], yy - y0[k]));
              }
            else if (i > 60)
              worst = max2 (worst, hypot (x - x1[k], yy - y1[k]));
          }
    }
  report ("Card House: top cards' largest motion from 1 s on / card length", worst < 0.01 * 2.0 * h,
          "%.2e (bound %.0e; in the first second %.2e)", worst / (2.0 * h), 0.01, settle / (2.0 * h));
  carom_world_destroy (w);
}

/* Circle Stack: ten circles r = 1, friction 0.6, dropped from 4 m, 7 m, ...
 * 31 m onto the ground, where they land on each other in a column. Bound:
 * the column stands: no circle ever more than 1% of its radius off the
 * vertical it fell along, and from 5 s on the top one never more than 1% of
 * the column's height (0.2 m) below its stacked height (19). */
static void circle_stack (void)
{
  carom_world *w = world_new (-10.0);
  carom_body_id ids[10];
  double side = 0.0, sag = 0.0;
  int i, k;
  segment (w, -40.0, 40.0, 0.0, 0.6);
  for (k = 0; k < 10; ++k)
    ids[k] = circle (w, CAROM_DYNAMIC, 0.0, 4.0 + 3.0 * k, 1.0, 1.0, 0.6);
  for (i = 1; i <= 600; ++i)
    {
      double x, y;
      step (w);
      for (k = 0; k < 10; ++k)
        {
          pos (w, ids[k], &x, &y);
          side = max2 (side, fabs (x));
        }
      pos (w, ids[9], &x, &y);
      if (i >= 300)
        sag = max2 (sag, 19.0 - y);
    }
  report ("Circle Stack: largest sideways motion / radius", side < 0.01 && sag < 0.01 * 20.0,
          "%.2e (bound %.0e); top's sag after 5 s / column height %.2e (bound %.0e)", side, 0.01, sag / 20.0, 0.01);
  carom_world_destroy (w);
}

static void high_mass_ratio_2 (void)
{
  high_mass_ratio_23 ("High Mass Ratio 2", 40.0, 1.0);
}

static void high_mass_ratio_3 (void)
{
  high_mass_ratio_23 ("High Mass Ratio 3", 80.0, 4.0);
}

/* The samples in sample_contact.cpp's order. `known` is NULL for a sample
 * carom passes at the defaults, else its figures from `solver2d --all`: the
 * sample is then left out of the default run (make stress) and says so. */
static const struct
{
  const char *name;
  void (*run) (void);
  const char *known;
} samples[] = {
  { "Single Box", single_box, NULL },
  { "Warm Start Energy", warm_start_energy, NULL },
  { "High Mass Ratio 1", high_mass_ratio_1, NULL },
  { "High Mass Ratio 2", high_mass_ratio_2, NULL },
  { "High Mass Ratio 3", high_mass_ratio_3, NULL },
  { "Friction Ramp", friction_ramp, NULL },
  { "Overlap Recovery", overlap_recovery, NULL },
  { "Vertical Stack", vertical_stack, NULL },
  { "Pyramid", pyramid, "top box's largest motion / side 1.54e+00 (bound 1e-02)" },
  { "Rush", rush, NULL },
  { "Arch", arch, "top box's largest motion / height 3.63e-02 (bound 1e-02)" },
  { "Double Domino", double_domino, NULL },
  { "Confined", confined, NULL },
  { "Card House", card_house, NULL },
  { "Circle Stack", circle_stack, NULL },
};

int main (int argc, char **argv)
{
  int all = 0, skipped = 0, i;
  const char *only = NULL;
  size_t k;
  for (i = 1; i < argc; ++i)
    if (strcmp (argv[i], "--all") == 0)
      all = 1;
    else if (strncmp (argv[i], "--substeps=", 11) == 0 && atoi (argv[i] + 11) > 0)
      substeps = atoi (argv[i] + 11);
    else if (strncmp (argv[i], "--iterations=", 13) == 0 && atoi (argv[i] + 13) > 0)
      iterations = atoi (argv[i] + 13);
    else if (strncmp (argv[i], "--only=", 7) == 0)
      only = argv[i] + 7, all = 1;
    else
      {
        fprintf (stderr, "usage: %s [--all] [--only=NAME] [--substeps=N] [--iterations=N]\n", argv[0]);
        return 2;
      }
  for (k = 0; k < sizeof samples / sizeof samples[0]; ++k)
    if (only && strcmp (only, samples[k].name) != 0)
      continue;
    else if (!all && samples[k].known)
      {
        printf ("skip %s: known failure: %s\n", samples[k].name, samples[k].known);
        skipped++;
      }
    else
      samples[k].run ();
  if (skipped)
    printf ("solver2d: %d passed, %d failed, %d skipped\n", passed, failed, skipped);
  else
    printf ("solver2d: %d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
