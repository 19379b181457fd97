/* The four benchmark scenes as plain data, and the small harness the
 * engines' benches share (see scenes.h). */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define BENCH_PI 3.14159265358979323846
#define BENCH_SEED 0x5eed0c0a7011ULL

void bench_rng_seed (bench_rng *r, unsigned long long seed)
{
  r->state = seed;
}

static unsigned long long rng_next (bench_rng *r)
{
  unsigned long long z = (r->state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double bench_rng_uniform (bench_rng *r)
{
  return (double) (rng_next (r) >> 11) * (1.0 / 9007199254740992.0);
}

double bench_rng_range (bench_rng *r, double lo, double hi)
{
  return lo + (hi - lo) * bench_rng_uniform (r);
}

int bench_body_vertices (const bench_body *b, double *xy, int max)
{
  int i;
  if (b->shape == BENCH_BOX)
    {
      double hw = 0.5 * b->w, hh = 0.5 * b->h;
      if (max < 4)
        return 0;
      xy[0] = -hw, xy[1] = -hh, xy[2] = hw, xy[3] = -hh;
      xy[4] = hw, xy[5] = hh, xy[6] = -hw, xy[7] = hh;
      return 4;
    }
  if (b->shape == BENCH_REGULAR && b->sides <= max)
    {
      for (i = 0; i < b->sides; ++i)
        {
          double t = 2.0 * BENCH_PI * i / b->sides;
          xy[2 * i] = b->radius * cos (t);
          xy[2 * i + 1] = b->radius * sin (t);
        }
      return b->sides;
    }
  return 0;
}

double bench_body_area (const bench_body *b)
{
  double xy[2 * 16], a = 0.0;
  int i, n;
  if (b->shape == BENCH_CIRCLE)
    return BENCH_PI * b->radius * b->radius;
  n = bench_body_vertices (b, xy, 16);
  for (i = 0; i < n; ++i)
    {
      int j = (i + 1) % n;
      a += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
  return 0.5 * a;
}

double bench_body_inertia (const bench_body *b)
{
  double xy[2 * 16], s = 0.0;
  int i, n;
  if (b->shape == BENCH_CIRCLE)
    return 0.5 * bench_body_area (b) * b->radius * b->radius;
  /* about the origin, which is the centroid of every shape made here */
  n = bench_body_vertices (b, xy, 16);
  for (i = 0; i < n; ++i)
    {
      int j = (i + 1) % n;
      double x0 = xy[2 * i], y0 = xy[2 * i + 1], x1 = xy[2 * j], y1 = xy[2 * j + 1];
      double c = x0 * y1 - x1 * y0;
      s += c * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1);
    }
  return s / 12.0;
}

static bench_body static_box (double x, double y, double w, double h)
{
  bench_body b;
  memset (&b, 0, sizeof b);
  b.shape = BENCH_BOX;
  b.w = w, b.h = h;
  b.radius = 0.5 * sqrt (w * w + h * h);
  b.x = x, b.y = y;
  b.is_static = 1;
  return b;
}

/* A random polygon of size (circumscribed diameter of the n-gons, side of
 * the boxes) in [0.5, 1): box, triangle, pentagon or hexagon. */
static bench_body random_polygon (bench_rng *r)
{
  static const int kinds[4] = { 4, 3, 5, 6 };
  bench_body b;
  int k = (int) (bench_rng_uniform (r) * 4.0);
  double size = bench_rng_range (r, 0.5, 1.0);
  memset (&b, 0, sizeof b);
  if (kinds[k] == 4)
    {
      b.shape = BENCH_BOX;
      b.w = b.h = size;
      b.radius = size * sqrt (0.5);
    }
  else
    {
      b.shape = BENCH_REGULAR;
      b.sides = kinds[k];
      b.radius = 0.5 * size;
      b.side = 2.0 * b.radius * sin (BENCH_PI / b.sides);
    }
  b.angle = bench_rng_range (r, 0.0, 2.0 * BENCH_PI);
  return b;
}

static int alloc_bodies (bench_scene *s, int count)
{
  s->bodies = calloc ((size_t) count, sizeof *s->bodies);
  return s->bodies ? 0 : -1;
}

static int make_pyramid (bench_scene *s, int n)
{
  int rows = 0, i, j, k = 0;
  const double gap = 0.05;
  while ((rows + 1) * (rows + 2) / 2 <= n)
    rows++;
  if (rows < 1 || alloc_bodies (s, rows * (rows + 1) / 2 + 1) < 0)
    return -1;
  s->gravity_y = -10.0;
  s->friction = 0.6;
  s->bodies[k++] = static_box (0.0, -0.5, 2.0 * rows + 20.0, 1.0);
  for (i = 0; i < rows; ++i)
    for (j = 0; j < rows - i; ++j)
      {
        bench_body *b = &s->bodies[k++];
        b->shape = BENCH_BOX;
        b->w = b->h = 1.0;
        b->radius = sqrt (0.5);
        b->x = (j - 0.5 * (rows - i - 1)) * (1.0 + gap);
        b->y = 0.5 + i;
      }
  s->count = k;
  s->dynamic_count = k - 1;
  s->top = k - 1;
  s->in_lo_x = -rows - 10.0, s->in_hi_x = rows + 10.0;
  s->in_lo_y = 0.0, s->in_hi_y = rows + 1.0;
  return 0;
}

static int make_rain (bench_scene *s, int n)
{
  bench_rng r;
  const double spacing = 1.5, jitter = 0.02, y0 = 4.0;
  int cols = (int) ceil (sqrt ((double) n)), rows = (n + cols - 1) / cols, i, k = 0;
  double width = cols * spacing, wall = y0 + rows * spacing + 1.0;
  if (alloc_bodies (s, n + 3) < 0)
    return -1;
  bench_rng_seed (&r, BENCH_SEED ^ 0x7261696eULL);
  s->gravity_y = -10.0;
  s->friction = 0.6;
  s->bodies[k++] = static_box (0.0, -0.5, width + 2.0, 1.0);
  s->bodies[k++] = static_box (-0.5 * width - 0.5, 0.5 * wall, 1.0, wall);
  s->bodies[k++] = static_box (0.5 * width + 0.5, 0.5 * wall, 1.0, wall);
  for (i = 0; i < n; ++i)
    {
      bench_body *b = &s->bodies[k++];
      *b = random_polygon (&r);
      b->x = -0.5 * width + (i % cols + 0.5) * spacing + bench_rng_range (&r, -jitter, jitter);
      b->y = y0 + (i / cols) * spacing + bench_rng_range (&r, -jitter, jitter);
      b->vx = bench_rng_range (&r, -0.5, 0.5);
      b->spin = bench_rng_range (&r, -1.0, 1.0);
    }
  s->count = k;
  s->dynamic_count = n;
  s->in_lo_x = -0.5 * width, s->in_hi_x = 0.5 * width;
  s->in_lo_y = 0.0, s->in_hi_y = wall;
  return 0;
}

static int make_gas (bench_scene *s, int n)
{
  bench_rng r;
  const double spacing = 2.0, jitter = 0.25, vmax = 5.0;
  int cols = (int) ceil (sqrt ((double) n)), rows = (n + cols - 1) / cols, i, k = 0;
  double width = cols * spacing, height = rows * spacing;
  if (alloc_bodies (s, n + 4) < 0)
    return -1;
  bench_rng_seed (&r, BENCH_SEED ^ 0x676173ULL);
  s->restitution = 1.0;
  s->bodies[k++] = static_box (0.0, -0.5 * height - 0.5, width + 2.0, 1.0);
  s->bodies[k++] = static_box (0.0, 0.5 * height + 0.5, width + 2.0, 1.0);
  s->bodies[k++] = static_box (-0.5 * width - 0.5, 0.0, 1.0, height);
  s->bodies[k++] = static_box (0.5 * width + 0.5, 0.0, 1.0, height);
  for (i = 0; i < n; ++i)
    {
      bench_body *b = &s->bodies[k++];
      double speed = vmax * sqrt (bench_rng_uniform (&r)); /* uniform in the disc */
      double dir = bench_rng_range (&r, 0.0, 2.0 * BENCH_PI);
      *b = random_polygon (&r);
      b->x = -0.5 * width + (i % cols + 0.5) * spacing + bench_rng_range (&r, -jitter, jitter);
      b->y = -0.5 * height + (i / cols + 0.5) * spacing + bench_rng_range (&r, -jitter, jitter);
      b->vx = speed * cos (dir);
      b->vy = speed * sin (dir);
    }
  s->count = k;
  s->dynamic_count = n;
  s->in_lo_x = -0.5 * width, s->in_hi_x = 0.5 * width;
  s->in_lo_y = -0.5 * height, s->in_hi_y = 0.5 * height;
  return 0;
}

/* Chains of BENCH_CHAIN_LINKS links, each hung from its own fixed point on
 * a square grid and laid straight at 45 degrees below the horizontal, to
 * the right: joint 0 of a chain holds its first link to the world, joint k
 * its links k - 1 and k at their shared end. */
static int make_chains (bench_scene *s, int n)
{
  const double link = 0.25, thick = 0.05, spacing = 24.0, c = cos (-0.25 * BENCH_PI), sn = sin (-0.25 * BENCH_PI);
  int chains = n / BENCH_CHAIN_LINKS > 0 ? n / BENCH_CHAIN_LINKS : 1, cols = (int) ceil (sqrt ((double) chains));
  int rows = (chains + cols - 1) / cols, i, k, count = chains * BENCH_CHAIN_LINKS;
  if (alloc_bodies (s, count) < 0)
    return -1;
  s->joints = calloc ((size_t) count, sizeof *s->joints);
  if (!s->joints)
    return -1;
  s->gravity_y = -10.0;
  s->friction = 0.6;
  for (i = 0; i < chains; ++i)
    {
      double px = (i % cols) * spacing, py = -(i / cols) * spacing;
      for (k = 0; k < BENCH_CHAIN_LINKS; ++k)
        {
          int index = i * BENCH_CHAIN_LINKS + k;
          bench_body *b = &s->bodies[index];
          bench_joint *j = &s->joints[index];
          b->shape = BENCH_BOX;
          b->w = link, b->h = thick;
          b->radius = 0.5 * sqrt (link * link + thick * thick);
          b->x = px + (k + 0.5) * link * c, b->y = py + (k + 0.5) * link * sn;
          b->angle = -0.25 * BENCH_PI;
          j->a = k == 0 ? -1 : index - 1;
          j->b = index;
          j->x = px + k * link * c, j->y = py + k * link * sn;
        }
    }
  s->count = count;
  s->dynamic_count = count;
  s->joint_count = count;
  s->in_lo_x = -0.5 * spacing, s->in_hi_x = (cols - 0.5) * spacing;
  s->in_lo_y = -(rows - 0.5) * spacing, s->in_hi_y = 0.5 * spacing;
  return 0;
}

int bench_scene_make (bench_scene *scene, const char *name, int n)
{
  int rc;
  memset (scene, 0, sizeof *scene);
  if (!name || n < 1 || n > 50000000)
    return -1;
  strncpy (scene->name, name, sizeof scene->name - 1);
  scene->density = 1.0;
  scene->top = -1;
  if (strcmp (name, "pyramid") == 0)
    rc = make_pyramid (scene, n);
  else if (strcmp (name, "rain") == 0)
    rc = make_rain (scene, n);
  else if (strcmp (name, "gas") == 0)
    rc = make_gas (scene, n);
  else if (strcmp (name, "chains") == 0)
    rc = make_chains (scene, n);
  else
    rc = -1;
  if (rc < 0)
    bench_scene_free (scene);
  return rc;
}

void bench_scene_free (bench_scene *scene)
{
  if (!scene)
    return;
  free (scene->bodies);
  free (scene->joints);
  memset (scene, 0, sizeof *scene);
}

/* ---------------------------------------------------------- harness */

static int default_bodies (const char *scene)
{
  if (strcmp (scene, "rain") == 0)
    return BENCH_RAIN_BODIES;
  if (strcmp (scene, "gas") == 0)
    return BENCH_GAS_BODIES;
  if (strcmp (scene, "chains") == 0)
    return BENCH_CHAINS_BODIES;
  return BENCH_PYRAMID_BODIES;
}

int bench_parse (bench_options *o, int argc, char **argv)
{
  int i;
  memset (o, 0, sizeof *o);
  strcpy (o->scene, "pyramid");
  strcpy (o->mode, "time");
  o->steps = 540;
  o->warmup = 60;
  o->continuous = -1;
  for (i = 1; i < argc; ++i)
    {
      const char *a = argv[i], *eq = strchr (a, '=');
      size_t k = eq ? (size_t) (eq - a) : 0;
      int *num = NULL;
      if (!eq)
        goto usage;
      if (k == 5 && strncmp (a, "scene", 5) == 0)
        {
          strncpy (o->scene, eq + 1, sizeof o->scene - 1);
          continue;
        }
      if (k == 4 && strncmp (a, "mode", 4) == 0)
        {
          strncpy (o->mode, eq + 1, sizeof o->mode - 1);
          continue;
        }
      if (k == 6 && strncmp (a, "bodies", 6) == 0)
        num = &o->bodies;
      else if (k == 5 && strncmp (a, "steps", 5) == 0)
        num = &o->steps;
      else if (k == 6 && strncmp (a, "warmup", 6) == 0)
        num = &o->warmup;
      else if (k == 8 && strncmp (a, "substeps", 8) == 0)
        num = &o->substeps;
      else if (k == 10 && strncmp (a, "iterations", 10) == 0)
        num = &o->iterations;
      else if (k == 5 && strncmp (a, "sleep", 5) == 0)
        num = &o->sleep;
      else if (k == 10 && strncmp (a, "continuous", 10) == 0)
        num = &o->continuous;
      else
        goto usage;
      *num = atoi (eq + 1);
      if (*num < 0)
        goto usage;
    }
  if (o->bodies == 0)
    o->bodies = default_bodies (o->scene);
  return 0;
usage:
  fprintf (stderr, "usage: %s [scene=pyramid|rain|gas|chains] [bodies=N] [steps=N] [warmup=N] [substeps=N] "
                   "[iterations=N] [mode=time|mem|hash] [sleep=0|1] [continuous=0|1]\n", argv[0]);
  return -1;
}

double bench_now (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

double bench_kinetic (double mass, double inertia, double vx, double vy, double spin)
{
  return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * spin * spin;
}

/* Where the point of body i that was at (x, y) at the start is now (the
 * point itself for i = -1, the world). */
static void carried (const bench_scene *s, const double *pose, int i, double x, double y, double *px, double *py)
{
  const bench_body *b;
  double c, sn, lx, ly;
  if (i < 0)
    {
      *px = x, *py = y;
      return;
    }
  b = &s->bodies[i];
  c = cos (b->angle), sn = sin (b->angle);
  lx = c * (x - b->x) + sn * (y - b->y);
  ly = -sn * (x - b->x) + c * (y - b->y);
  c = cos (pose[3 * i + 2]), sn = sin (pose[3 * i + 2]);
  *px = pose[3 * i] + c * lx - sn * ly;
  *py = pose[3 * i + 1] + sn * lx + c * ly;
}

double bench_joint_gap (const bench_scene *s, const double *pose)
{
  double sum = 0.0;
  int k;
  for (k = 0; k < s->joint_count; ++k)
    {
      const bench_joint *j = &s->joints[k];
      double ax, ay, bx, by;
      carried (s, pose, j->a, j->x, j->y, &ax, &ay);
      carried (s, pose, j->b, j->x, j->y, &bx, &by);
      sum += hypot (bx - ax, by - ay);
    }
  return s->joint_count > 0 ? sum / s->joint_count : 0.0;
}

int bench_outside (const bench_scene *s, double x, double y)
{
  return !(x >= s->in_lo_x && x <= s->in_hi_x && y >= s->in_lo_y && y <= s->in_hi_y);
}

void bench_report (const bench_options *o, const bench_scene *s, const bench_result *r)
{
  printf ("engine=%s scene=%s bodies=%d steps=%d ms_per_step=%.4f", r->engine, s->name, s->dynamic_count, o->steps,
          o->steps > 0 ? 1e3 * r->seconds / o->steps : 0.0);
  if (r->energy_start > 0.0)
    printf (" energy_drift=%.4f", r->energy_end / r->energy_start - 1.0);
  else
    printf (" energy_drift=-");
  if (s->top >= 0)
    printf (" top_drift=%.4f", r->top_drift);
  else
    printf (" top_drift=-");
  printf (" escaped=%d contacts=%d", r->escaped, r->contacts);
  if (s->joint_count > 0)
    printf (" joints=%d joint_gap=%.3g", s->joint_count, r->joint_gap);
  printf (" settings=%s\n", r->settings);
  fflush (stdout);
}

int bench_begin (bench_options *o, bench_scene *s, int argc, char **argv, const char *program)
{
  if (bench_parse (o, argc, argv) < 0)
    return -1;
  if (bench_scene_make (s, o->scene, o->bodies) < 0)
    {
      fprintf (stderr, "%s: cannot make scene %s of %d bodies\n", program, o->scene, o->bodies);
      return -1;
    }
  return 0;
}
