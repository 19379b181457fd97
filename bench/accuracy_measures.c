/* The accuracy measures (see accuracy.h), engine-neutral: every engine is
 * measured by this code through its acc_engine table. */
#include "accuracy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ACC_PI 3.14159265358979323846

/* ------------------------------------------------------------ helpers */

double acc_body_size (const bench_body *b)
{
  if (b->shape == BENCH_BOX)
    return b->w > b->h ? b->w : b->h;
  return 2.0 * b->radius;
}

/* Room for `count` bodies and as many joints. */
static int scene_alloc (bench_scene *s, const char *name, int count)
{
  memset (s, 0, sizeof *s);
  strncpy (s->name, name, sizeof s->name - 1);
  s->density = 1.0;
  s->top = -1;
  s->bodies = calloc ((size_t) count, sizeof *s->bodies);
  s->joints = calloc ((size_t) count, sizeof *s->joints);
  s->count = 0;
  if (s->bodies && s->joints)
    return 0;
  bench_scene_free (s);
  return -1;
}

static bench_body *scene_add (bench_scene *s, bench_shape shape, double a, double b, int is_static)
{
  bench_body *p = &s->bodies[s->count++];
  memset (p, 0, sizeof *p);
  p->shape = shape;
  p->is_static = is_static;
  if (shape == BENCH_BOX)
    {
      p->w = a, p->h = b;
      p->radius = 0.5 * sqrt (a * a + b * b);
    }
  else if (shape == BENCH_REGULAR)
    {
      p->sides = (int) b;
      p->radius = a;
      p->side = 2.0 * a * sin (ACC_PI / p->sides);
    }
  else
    p->radius = a;
  if (!is_static)
    s->dynamic_count++;
  return p;
}

/* A revolute joint between bodies a (-1: the world) and b at (x, y). */
static bench_joint *scene_join (bench_scene *s, int a, int b, double x, double y)
{
  bench_joint *j = &s->joints[s->joint_count++];
  memset (j, 0, sizeof *j);
  j->a = a, j->b = b;
  j->x = x, j->y = y;
  return j;
}

static int steps_for (double seconds, const acc_settings *set)
{
  return (int) floor (seconds / set->dt + 0.5);
}

/* A world being stepped, with the wall time of its step calls. */
typedef struct acc_run {
  const acc_engine *e;
  const acc_settings *set;
  void *w;
  double seconds;
  int steps;
} acc_run;

static int run_begin (acc_run *r, const acc_engine *e, const acc_settings *set, const bench_scene *s)
{
  memset (r, 0, sizeof *r);
  r->e = e, r->set = set;
  r->w = e->create (s, set);
  return r->w ? 0 : -1;
}

static int run_step (acc_run *r)
{
  double t0 = bench_now ();
  int rc = r->e->step (r->w);
  r->seconds += bench_now () - t0;
  r->steps++;
  return rc;
}

static void run_end (acc_run *r, acc_result *res)
{
  if (r->steps > 0)
    {
      res->ms_step = 1e3 * r->seconds / r->steps;
      res->ms_frame = res->ms_step * (1.0 / 60.0) / r->set->dt;
    }
  if (r->w)
    r->e->destroy (r->w);
  r->w = NULL;
}

static void result_init (acc_result *r, const char *measure)
{
  memset (r, 0, sizeof *r);
  r->measure = measure;
  r->ok = 1;
}

static void result_put (acc_result *r, const char *key, double value)
{
  if (r->nkeys < ACC_MAX_KEYS)
    {
      r->keys[r->nkeys] = key;
      r->values[r->nkeys++] = value;
    }
}

void acc_print (const acc_engine *e, const acc_settings *set, const acc_result *r, const char *extra)
{
  int i;
  printf ("acc engine=%s knob=%s value=%s measure=%s ms_step=%.5f ms_frame=%.5f", e->name, set->knob, set->value,
          r->measure, r->ms_step, r->ms_frame);
  for (i = 0; i < r->nkeys; ++i)
    printf (" %s=%.6g", r->keys[i], r->values[i]);
  if (!r->ok)
    printf (" failed=1");
  if (extra)
    printf (" %s", extra);
  printf ("\n");
  fflush (stdout);
}

/* Kinetic energy, linear momentum and angular momentum about the origin of
 * the dynamic bodies. */
static void totals (const acc_run *r, const bench_scene *s, double *ke, double *px, double *py, double *l,
                    double *scale_p, double *scale_l)
{
  int i;
  double k = 0, x = 0, y = 0, a = 0, sp = 0, sl = 0;
  for (i = 0; i < s->count; ++i)
    {
      acc_state st;
      if (s->bodies[i].is_static)
        continue;
      r->e->state (r->w, i, &st);
      k += bench_kinetic (st.mass, st.inertia, st.vx, st.vy, st.spin);
      x += st.mass * st.vx, y += st.mass * st.vy;
      a += st.mass * (st.x * st.vy - st.y * st.vx) + st.inertia * st.spin;
      sp += st.mass * hypot (st.vx, st.vy);
      sl += st.mass * fabs (st.x * st.vy - st.y * st.vx) + st.inertia * fabs (st.spin);
    }
  if (ke)
    *ke = k;
  if (px)
    *px = x, *py = y;
  if (l)
    *l = a;
  if (scale_p)
    *scale_p = sp;
  if (scale_l)
    *scale_l = sl;
}

/* Penetration statistics: depth over the smaller dynamic body's size. */
#define PEN_BINS 2000 /* of 0.001 body size each; the last one holds the rest */
typedef struct pen_stats {
  const bench_scene *s;
  double max, sum;
  long n;
  long hist[PEN_BINS];
} pen_stats;

/* The depth below which 99% of the touching points lie (to 0.001). */
static double pen_p99 (const pen_stats *p)
{
  long seen = 0;
  int i;
  for (i = 0; i < PEN_BINS; ++i)
    if ((seen += p->hist[i]) >= 0.99 * p->n)
      return (i + 1) * 0.001;
  return PEN_BINS * 0.001;
}

static void pen_add (void *user, int a, int b, double depth)
{
  pen_stats *p = user;
  double size = 1e300, rel;
  if (depth < 0.0)
    return;
  if (a >= 0 && !p->s->bodies[a].is_static)
    size = acc_body_size (&p->s->bodies[a]);
  if (b >= 0 && !p->s->bodies[b].is_static && acc_body_size (&p->s->bodies[b]) < size)
    size = acc_body_size (&p->s->bodies[b]);
  if (size == 1e300)
    return;
  rel = depth / size;
  if (rel > p->max)
    p->max = rel;
  p->sum += rel;
  p->n++;
  p->hist[rel < 0.001 * (PEN_BINS - 1) ? (int) (rel / 0.001) : PEN_BINS - 1]++;
}

static int count_outside (const acc_run *r, const bench_scene *s)
{
  int i, n = 0;
  for (i = 0; i < s->count; ++i)
    {
      acc_state st;
      if (s->bodies[i].is_static)
        continue;
      r->e->state (r->w, i, &st);
      n += bench_outside (s, st.x, st.y) || !isfinite (st.x) || !isfinite (st.y);
    }
  return n;
}

/* ------------------------------------------------ two-body collision */

/* World vertices of polygon body b at time t of free flight (no gravity). */
static int vertices_at (const bench_body *b, double t, double *xy)
{
  double local[2 * 16], c, s, x = b->x + b->vx * t, y = b->y + b->vy * t, a = b->angle + b->spin * t;
  int i, n = bench_body_vertices (b, local, 16);
  c = cos (a), s = sin (a);
  for (i = 0; i < n; ++i)
    {
      xy[2 * i] = x + c * local[2 * i] - s * local[2 * i + 1];
      xy[2 * i + 1] = y + s * local[2 * i] + c * local[2 * i + 1];
    }
  return n;
}

/* Signed distance from (px, py) to the convex CCW polygon's edge i's line,
 * positive outside. */
static double edge_distance (const double *xy, int n, int i, double px, double py, double *nx, double *ny)
{
  int j = (i + 1) % n;
  double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1], len = hypot (ex, ey);
  *nx = ey / len, *ny = -ex / len;
  return (px - xy[2 * i]) * *nx + (py - xy[2 * i + 1]) * *ny;
}

/* Depth of (px, py) inside the polygon (> 0 inside), and the outward normal
 * of the nearest edge. */
static double inside_depth (const double *xy, int n, double px, double py, double *nx, double *ny)
{
  double best = -1e300;
  int i;
  for (i = 0; i < n; ++i)
    {
      double ex, ey, d = edge_distance (xy, n, i, px, py, &ex, &ey);
      if (-d < -best || i == 0)
        {
          best = d;
          *nx = ex, *ny = ey;
        }
    }
  return -best;
}

/* Deepest vertex of one polygon inside the other at time t: > 0 when they
 * overlap. Sets the vertex (px, py) and the normal from a to b. */
static double overlap_at (const bench_body *a, const bench_body *b, double t, double *px, double *py, double *nx,
                          double *ny)
{
  double va[32], vb[32], best = -1e300;
  int na = vertices_at (a, t, va), nb = vertices_at (b, t, vb), i;
  for (i = 0; i < na; ++i)
    {
      double mx = 0.0, my = 0.0, d = inside_depth (vb, nb, va[2 * i], va[2 * i + 1], &mx, &my);
      if (d > best)
        best = d, *px = va[2 * i], *py = va[2 * i + 1], *nx = -mx, *ny = -my;
    }
  for (i = 0; i < nb; ++i)
    {
      double mx = 0.0, my = 0.0, d = inside_depth (va, na, vb[2 * i], vb[2 * i + 1], &mx, &my);
      if (d > best)
        best = d, *px = vb[2 * i], *py = vb[2 * i + 1], *nx = mx, *ny = my;
    }
  return best;
}

/* The exact eq. 3.23 outcome of the first contact of two convex polygons in
 * free flight (e, no friction): the time of first contact by scanning and
 * bisection, its point and normal, then the impulse. Returns -1 if they never
 * meet within `horizon`, or meet again afterwards (then the closed form does
 * not describe the run). */
static int exact_collision (const bench_scene *s, double e, double horizon, double out[6])
{
  const bench_body *a = &s->bodies[0], *b = &s->bodies[1];
  double lo = 0.0, hi = -1.0, t, px, py, nx, ny, ma, mb, ia, ib, rax, ray, rbx, rby, vpx, vpy, vn, ran, rbn, j;
  int k;
  for (t = 0.0; t <= horizon; t += 1e-4)
    {
      if (overlap_at (a, b, t, &px, &py, &nx, &ny) > 0.0)
        {
          hi = t;
          break;
        }
      lo = t;
    }
  if (hi < 0.0)
    {
      if (getenv ("ACC_DEBUG"))
        fprintf (stderr, "exact_collision: no contact\n");
      return -1;
    }
  for (k = 0; k < 60; ++k)
    {
      double mid = 0.5 * (lo + hi);
      if (overlap_at (a, b, mid, &px, &py, &nx, &ny) > 0.0)
        hi = mid;
      else
        lo = mid;
    }
  overlap_at (a, b, hi, &px, &py, &nx, &ny);
  ma = s->density * bench_body_area (a), mb = s->density * bench_body_area (b);
  ia = s->density * bench_body_inertia (a), ib = s->density * bench_body_inertia (b);
  rax = px - (a->x + a->vx * hi), ray = py - (a->y + a->vy * hi);
  rbx = px - (b->x + b->vx * hi), rby = py - (b->y + b->vy * hi);
  /* v_p = v_bp - v_ap, omega x r = (-omega r_y, omega r_x) */
  vpx = (b->vx - b->spin * rby) - (a->vx - a->spin * ray);
  vpy = (b->vy + b->spin * rbx) - (a->vy + a->spin * rax);
  vn = vpx * nx + vpy * ny;
  if (getenv ("ACC_DEBUG"))
    fprintf (stderr, "exact_collision: t=%.6f p=(%.4f, %.4f) n=(%.4f, %.4f) vn=%.4f\n", hi, px, py, nx, ny, vn);
  if (vn >= 0.0)
    return -1;
  ran = rax * ny - ray * nx, rbn = rbx * ny - rby * nx;
  j = -(1.0 + e) * vn / (1.0 / ma + 1.0 / mb + ran * ran / ia + rbn * rbn / ib);
  out[0] = a->vx - j * nx / ma, out[1] = a->vy - j * ny / ma, out[2] = a->spin - ran * j / ia;
  out[3] = b->vx + j * nx / mb, out[4] = b->vy + j * ny / mb, out[5] = b->spin + rbn * j / ib;
  /* no second contact: fly the bodies on from the impact with the new
   * velocities */
  {
    bench_body a2 = *a, b2 = *b;
    a2.x += a->vx * hi, a2.y += a->vy * hi, a2.angle += a->spin * hi;
    b2.x += b->vx * hi, b2.y += b->vy * hi, b2.angle += b->spin * hi;
    a2.vx = out[0], a2.vy = out[1], a2.spin = out[2];
    b2.vx = out[3], b2.vy = out[4], b2.spin = out[5];
    for (t = 1e-3; t < horizon; t += 1e-3)
      if (overlap_at (&a2, &b2, t, &px, &py, &nx, &ny) > 0.0)
        {
          if (getenv ("ACC_DEBUG"))
            fprintf (stderr, "exact_collision: second contact at %.4f after\n", t);
          return -1;
        }
  }
  return 0;
}

/* Error of the two bodies' final velocities against `want` (vx, vy, spin of
 * a then b): sqrt(sum |dv|^2 + (rho dspin)^2) over the closing speed, rho
 * the radius of gyration. */
static double velocity_error (const acc_run *r, const bench_scene *s, const double want[6])
{
  double sum = 0.0, closing = hypot (s->bodies[1].vx - s->bodies[0].vx, s->bodies[1].vy - s->bodies[0].vy);
  int i;
  for (i = 0; i < 2; ++i)
    {
      acc_state st;
      double rho;
      r->e->state (r->w, i, &st);
      rho = sqrt (st.inertia / st.mass);
      sum += pow (st.vx - want[3 * i], 2) + pow (st.vy - want[3 * i + 1], 2)
             + pow (rho * (st.spin - want[3 * i + 2]), 2);
    }
  return sqrt (sum) / closing;
}

static int run_seconds (acc_run *r, double seconds)
{
  int k, n = steps_for (seconds, r->set);
  for (k = 0; k < n; ++k)
    if (run_step (r) != 0)
      return -1;
  return 0;
}

/* run_seconds, noting the penetration of every touching contact point
 * after every step (pen_add). */
static int run_penetration (acc_run *r, const bench_scene *s, double seconds, pen_stats *pen)
{
  int k, n = steps_for (seconds, r->set);
  memset (pen, 0, sizeof *pen);
  pen->s = s;
  for (k = 0; k < n; ++k)
    {
      if (run_step (r) != 0)
        return -1;
      r->e->contacts (r->w, pen_add, pen);
    }
  return 0;
}

/* Head-on: two equal 1 x 1 boxes face to face swap velocities. Off-centre:
 * a spinning 1 x 0.6 box hits a spinning pentagon with a corner, against
 * the exact impulse at the exact first contact. e = 1, no friction, no
 * gravity. */
int acc_collision (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  bench_body *p;
  acc_run r;
  double want[6], ke0, ke1, headon, offcentre;
  int rc = 0;
  result_init (res, "collision");

  if (scene_alloc (&s, "headon", 2) < 0)
    return -1;
  s.restitution = 1.0;
  p = scene_add (&s, BENCH_BOX, 1.0, 1.0, 0);
  p->x = -1.5, p->vx = 3.0;
  p = scene_add (&s, BENCH_BOX, 1.0, 1.0, 0);
  p->x = 1.5, p->vx = -1.0;
  want[0] = -1.0, want[1] = 0.0, want[2] = 0.0, want[3] = 3.0, want[4] = 0.0, want[5] = 0.0;
  if (run_begin (&r, e, set, &s) < 0 || run_seconds (&r, 1.0) < 0)
    rc = -1;
  headon = rc ? NAN : velocity_error (&r, &s, want);
  run_end (&r, res);
  bench_scene_free (&s);

  if (scene_alloc (&s, "offcentre", 2) < 0)
    return -1;
  s.restitution = 1.0;
  p = scene_add (&s, BENCH_BOX, 1.0, 0.6, 0);
  p->x = -1.5, p->y = 0.3, p->angle = 0.5, p->vx = 4.0, p->spin = -1.5;
  p = scene_add (&s, BENCH_REGULAR, 0.5, 5, 0);
  p->x = 1.0, p->y = -0.1, p->angle = 0.2, p->vx = -2.0, p->vy = 0.5, p->spin = 1.0;
  if (exact_collision (&s, 1.0, 1.5, want) < 0)
    {
      fprintf (stderr, "accuracy: the off-centre collision is not a single contact; change its set-up\n");
      bench_scene_free (&s);
      return -1;
    }
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      totals (&r, &s, &ke0, NULL, NULL, NULL, NULL, NULL);
      if (run_seconds (&r, 1.5) < 0)
        rc = -1;
      totals (&r, &s, &ke1, NULL, NULL, NULL, NULL, NULL);
    }
  offcentre = rc ? NAN : velocity_error (&r, &s, want);
  run_end (&r, res);
  bench_scene_free (&s);
  result_put (res, "headon_err", headon);
  result_put (res, "offcentre_err", offcentre);
  result_put (res, "energy_change", rc ? NAN : ke1 / ke0 - 1.0);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ projectile, bounce */

/* A 1 x 1 box thrown at (3, 8) under g = -10, no ground: its position
 * after 2 s against x0 + v0 t + g t^2 / 2, over its size. */
int acc_projectile (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  bench_body *p;
  acc_run r;
  acc_state st;
  double t;
  int rc = 0;
  result_init (res, "projectile");
  if (scene_alloc (&s, "projectile", 1) < 0)
    return -1;
  s.gravity_y = -10.0;
  p = scene_add (&s, BENCH_BOX, 1.0, 1.0, 0);
  p->vx = 3.0, p->vy = 8.0;
  if (run_begin (&r, e, set, &s) < 0 || run_seconds (&r, 2.0) < 0)
    rc = -1;
  if (!rc)
    {
      t = r.steps * set->dt;
      e->state (r.w, 0, &st);
      result_put (res, "err", hypot (st.x - 3.0 * t, st.y - (8.0 * t - 5.0 * t * t)));
    }
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* Drop `shape` (circle of diameter 1 or 1 x 1 box) from h0 = 2 (its bottom
 * above the ground) with e = 0.5: height of the bottom at the top of the
 * first bounce. The top is taken from the last state still rising, as
 * y + vy^2 / 2g (exact for free flight), so sampling by steps adds no error. */
static int bounce_height (const acc_engine *e, const acc_settings *set, bench_shape shape, double *height)
{
  bench_scene s;
  bench_body *p;
  acc_run r;
  const double h0 = 2.0, g = 10.0;
  int rc = -1, k, n = steps_for (3.0, set), fell = 0;
  if (scene_alloc (&s, "bounce", 2) < 0)
    return -1;
  s.gravity_y = -g;
  s.restitution = 0.5;
  p = scene_add (&s, BENCH_BOX, 20.0, 1.0, 1);
  p->y = -0.5;
  p = shape == BENCH_BOX ? scene_add (&s, BENCH_BOX, 1.0, 1.0, 0) : scene_add (&s, BENCH_CIRCLE, 0.5, 0, 0);
  p->y = 0.5 + h0;
  *height = NAN;
  if (run_begin (&r, e, set, &s) == 0)
    for (k = 0; k < n; ++k)
      {
        acc_state st;
        if (run_step (&r) != 0)
          break;
        e->state (r.w, 1, &st);
        if (st.vy < -1e-9)
          {
            if (fell == 2) /* falling again: *height holds the top */
              {
                rc = 0;
                break;
              }
            fell = 1;
          }
        else if (fell && st.vy > 1e-9)
          {
            fell = 2;
            *height = st.y - 0.5 + st.vy * st.vy / (2.0 * g);
          }
      }
  run_end (&r, &(acc_result){ 0 });
  bench_scene_free (&s);
  return rc;
}

int acc_bounce (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  const double want = 0.5 * 0.5 * 2.0;
  double hc, hb;
  int rc;
  result_init (res, "bounce");
  rc = bounce_height (e, set, BENCH_CIRCLE, &hc);
  rc |= bounce_height (e, set, BENCH_BOX, &hb);
  result_put (res, "circle_height", hc);
  result_put (res, "circle_err", hc / want - 1.0);
  result_put (res, "box_height", hb);
  result_put (res, "box_err", hb / want - 1.0);
  /* cost: one more run, timed, of the box */
  {
    bench_scene s;
    bench_body *p;
    acc_run r;
    if (scene_alloc (&s, "bounce", 2) == 0)
      {
        s.gravity_y = -10.0, s.restitution = 0.5;
        p = scene_add (&s, BENCH_BOX, 20.0, 1.0, 1);
        p->y = -0.5;
        p = scene_add (&s, BENCH_BOX, 1.0, 1.0, 0);
        p->y = 2.5;
        if (run_begin (&r, e, set, &s) == 0)
          run_seconds (&r, 3.0);
        run_end (&r, res);
        bench_scene_free (&s);
      }
  }
  res->ok = rc == 0;
  return rc;
}

/* A 1 x 1 box dropped ACC_DROP_HEIGHT (its bottom above the column's top)
 * onto a column of n 1 x 1 boxes resting on a static ground, the boxes
 * shifted 0.01 alternately left and right, e = 0, friction 0.3,
 * ACC_DROP_SECONDS: the fastest any box moves upward after any step, over
 * the impact speed sqrt (2 g h). An inelastic impact throws nothing up. */
static int drop_rise (const acc_engine *e, const acc_settings *set, int n, double *rise, acc_result *timed)
{
  bench_scene s;
  bench_body *p;
  acc_run r;
  const double g = 10.0;
  int rc = -1, i, k, steps = steps_for (ACC_DROP_SECONDS, set);
  *rise = NAN;
  if (scene_alloc (&s, "drop", n + 2) < 0)
    return -1;
  s.gravity_y = -g;
  s.restitution = 0.0;
  s.friction = 0.3;
  p = scene_add (&s, BENCH_BOX, 200.0, 2.0, 1);
  p->y = -1.0;
  for (i = 0; i <= n; ++i)
    {
      p = scene_add (&s, BENCH_BOX, 1.0, 1.0, 0);
      p->x = i % 2 == 0 ? -0.01 : 0.01;
      p->y = 0.5 + i + (i == n ? ACC_DROP_HEIGHT : 0.0);
    }
  if (run_begin (&r, e, set, &s) == 0)
    {
      double fastest = 0.0;
      for (k = 0; k < steps; ++k)
        {
          if (run_step (&r) != 0)
            break;
          for (i = 1; i <= n + 1; ++i)
            {
              acc_state st;
              e->state (r.w, i, &st);
              fastest = st.vy > fastest ? st.vy : fastest;
            }
        }
      if (k == steps)
        {
          *rise = fastest / sqrt (2.0 * g * ACC_DROP_HEIGHT);
          rc = 0;
        }
    }
  run_end (&r, timed ? timed : &(acc_result){ 0 });
  bench_scene_free (&s);
  return rc;
}

/* Columns of 2 and of 8; the cost is the 8's run. */
int acc_drop (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  double r2, r8;
  int rc;
  result_init (res, "drop");
  rc = drop_rise (e, set, 2, &r2, NULL);
  rc |= drop_rise (e, set, 8, &r8, res);
  result_put (res, "rise_2", r2);
  result_put (res, "rise_8", r8);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ conservation */

/* The bench's gas scene (e = 1, no friction, closed walls): kinetic energy
 * at the end over the start, minus 1, after ACC_GAS_SECONDS (2000 steps at
 * 1/60), and how deep its bodies overlap on the way (penetration over every
 * step, as in the pyramid and the rain). */
int acc_gas (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  acc_run r;
  pen_stats pen;
  double e0 = 0.0, e1 = 0.0;
  int rc = 0;
  result_init (res, "gas");
  if (bench_scene_make (&s, "gas", ACC_GAS_BODIES) < 0)
    return -1;
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      totals (&r, &s, &e0, NULL, NULL, NULL, NULL, NULL);
      rc = run_penetration (&r, &s, ACC_GAS_SECONDS, &pen);
      totals (&r, &s, &e1, NULL, NULL, NULL, NULL, NULL);
      result_put (res, "energy_drift", e1 / e0 - 1.0);
      result_put (res, "pen_max", pen.max);
      result_put (res, "pen_p99", pen_p99 (&pen));
      result_put (res, "escaped", count_outside (&r, &s));
    }
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* A closed world without walls: the gas scene's polygons without its walls,
 * their velocities turned towards the centre (v - 0.4 x) so that they pile
 * up and collide many times; e = 0.5, friction 0.3, no gravity. Linear and
 * angular momentum (about the origin) at the end against the start, over
 * sum m |v| and sum (m |x cross v| + I |spin|) at the start. */
int acc_momentum (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene gas, s;
  acc_run r;
  double px0, py0, l0, px1, py1, l1, sp, sl;
  int i, rc = 0;
  result_init (res, "momentum");
  if (bench_scene_make (&gas, "gas", ACC_MOMENTUM_BODIES) < 0)
    return -1;
  if (scene_alloc (&s, "momentum", gas.count) < 0)
    {
      bench_scene_free (&gas);
      return -1;
    }
  s.restitution = 0.5, s.friction = 0.3;
  for (i = 0; i < gas.count; ++i)
    if (!gas.bodies[i].is_static)
      {
        bench_body *b = &s.bodies[s.count++];
        *b = gas.bodies[i];
        b->vx -= 0.4 * b->x, b->vy -= 0.4 * b->y;
        b->spin = 0.5 * b->vx;
        s.dynamic_count++;
      }
  s.in_lo_x = s.in_lo_y = -1e300, s.in_hi_x = s.in_hi_y = 1e300;
  bench_scene_free (&gas);
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      totals (&r, &s, NULL, &px0, &py0, &l0, &sp, &sl);
      rc = run_seconds (&r, ACC_MOMENTUM_SECONDS);
      totals (&r, &s, NULL, &px1, &py1, &l1, NULL, NULL);
      result_put (res, "p_err", hypot (px1 - px0, py1 - py0) / sp);
      result_put (res, "l_err", fabs (l1 - l0) / sl);
    }
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ contacts */

/* The bench's pyramid (210 boxes), 10 s: penetration over every step, and
 * how far the top box sank (down is positive) and moved, over its size. */
int acc_pyramid (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  acc_run r;
  pen_stats pen;
  acc_state a, b;
  int rc = 0;
  result_init (res, "pyramid");
  if (bench_scene_make (&s, "pyramid", ACC_PYRAMID_BODIES) < 0)
    return -1;
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      double size = acc_body_size (&s.bodies[s.top]);
      e->state (r.w, s.top, &a);
      rc = run_penetration (&r, &s, ACC_PYRAMID_SECONDS, &pen);
      e->state (r.w, s.top, &b);
      result_put (res, "pen_max", pen.max);
      result_put (res, "pen_mean", pen.n ? pen.sum / pen.n : 0.0);
      result_put (res, "pen_p99", pen_p99 (&pen));
      result_put (res, "top_sink", (a.y - b.y) / size);
      result_put (res, "top_drift", hypot (b.x - a.x, b.y - a.y) / size);
      result_put (res, "escaped", count_outside (&r, &s));
    }
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* The bench's rain with ACC_RAIN_BODIES polygons for ACC_RAIN_SECONDS (every
 * row has landed by then): penetration over every step. */
int acc_rain (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  acc_run r;
  pen_stats pen;
  int rc = 0;
  result_init (res, "rain");
  if (bench_scene_make (&s, "rain", ACC_RAIN_BODIES) < 0)
    return -1;
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      rc = run_penetration (&r, &s, ACC_RAIN_SECONDS, &pen);
      result_put (res, "pen_max", pen.max);
      result_put (res, "pen_mean", pen.n ? pen.sum / pen.n : 0.0);
      result_put (res, "pen_p99", pen_p99 (&pen));
      result_put (res, "escaped", count_outside (&r, &s));
    }
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* 20 circles (diameter 0.1 to 0.2) and 20 boxes (0.1 x 0.1, random angle)
 * at 50 to 300 m/s against a static wall 0.1 thick (at 300 m/s a body moves
 * 5 m, 50 wall thicknesses, per 1/60 s step). e = 0, no friction, no
 * gravity, 0.5 s. A body whose centre ends beyond the wall tunnelled. */
int acc_tunnel (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  bench_rng rng;
  acc_run r;
  bench_body *p;
  int i, rc = 0, circles = 0, boxes = 0;
  result_init (res, "tunnel");
  if (scene_alloc (&s, "tunnel", 41) < 0)
    return -1;
  bench_rng_seed (&rng, 0x74756e6e656cULL);
  p = scene_add (&s, BENCH_BOX, 0.1, 60.0, 1);
  for (i = 0; i < 40; ++i)
    {
      p = i % 2 ? scene_add (&s, BENCH_BOX, 0.1, 0.1, 0)
                : scene_add (&s, BENCH_CIRCLE, bench_rng_range (&rng, 0.05, 0.1), 0, 0);
      p->x = -10.0 - bench_rng_range (&rng, 0.0, 5.0);
      p->y = -19.5 + i;
      p->angle = bench_rng_range (&rng, 0.0, ACC_PI);
      p->vx = 50.0 + 250.0 * i / 39.0;
    }
  if (run_begin (&r, e, set, &s) < 0 || run_seconds (&r, 0.5) < 0)
    rc = -1;
  else
    for (i = 1; i < s.count; ++i)
      {
        acc_state st;
        e->state (r.w, i, &st);
        if (!(st.x < 0.0))
          {
            if (s.bodies[i].shape == BENCH_CIRCLE)
              circles++;
            else
              boxes++;
          }
      }
  result_put (res, "tunnelled", circles + boxes);
  result_put (res, "circles", circles);
  result_put (res, "boxes", boxes);
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ spinning bar */

/* The largest x of polygon body b's corners at time t of free flight (no
 * gravity), and that corner's offset (rx, ry) from the centre. */
static double reach_x (const bench_body *b, double t, double *rx, double *ry)
{
  double xy[32], best = -1e300;
  int i, n = vertices_at (b, t, xy);
  for (i = 0; i < n; ++i)
    if (xy[2 * i] > best)
      {
        best = xy[2 * i];
        *rx = xy[2 * i] - (b->x + b->vx * t), *ry = xy[2 * i + 1] - (b->y + b->vy * t);
      }
  return best;
}

/* The first impact of polygon body b in free flight on a static wall whose
 * face is the line x = face, the wall to its right: one corner touches
 * first (found by a scan of 1e-6 s and bisection). Eq. 3.23 for a single
 * point against an immovable body, n = (-1, 0) from the wall to the body,
 * r the corner's offset: v_n = (v + w x r) . n = -(vx - w r_y), r x n =
 * r_y, J = -(1 + e) v_n / (1/m + r_y^2 / I), and after it vx - J/m, vy,
 * w + r_y J / I (out[0..2]). Returns -1 if it does not touch within
 * `horizon`, or touches again within it after the impact (flown on with
 * the new velocities): then one impact is not the answer. */
static int wall_impact (const bench_scene *s, const bench_body *b, double face, double e, double horizon,
                        double out[3])
{
  double lo = 0.0, hi = -1.0, t, rx = 0.0, ry = 0.0, m, inertia, vn, j;
  int k;
  for (t = 0.0; t <= horizon; t += 1e-6)
    {
      if (reach_x (b, t, &rx, &ry) >= face)
        {
          hi = t;
          break;
        }
      lo = t;
    }
  if (hi < 0.0)
    return -1;
  for (k = 0; k < 100; ++k)
    {
      double mid = 0.5 * (lo + hi);
      if (reach_x (b, mid, &rx, &ry) >= face)
        hi = mid;
      else
        lo = mid;
    }
  reach_x (b, hi, &rx, &ry);
  m = s->density * bench_body_area (b), inertia = s->density * bench_body_inertia (b);
  vn = -(b->vx - b->spin * ry);
  if (vn >= 0.0)
    return -1;
  j = -(1.0 + e) * vn / (1.0 / m + ry * ry / inertia);
  out[0] = b->vx - j / m, out[1] = b->vy, out[2] = b->spin + ry * j / inertia;
  if (getenv ("ACC_DEBUG"))
    fprintf (stderr, "wall_impact: t=%.6f r=(%.4f, %.4f) vn=%.4f -> v=(%.6f, %.6f) w=%.6f\n", hi, rx, ry, vn, out[0],
             out[1], out[2]);
  {
    /* no second touch: from just after the impact until the body is
     * farther from the face than its circumradius, moving away */
    bench_body after = *b;
    after.x += b->vx * hi, after.y += b->vy * hi, after.angle += b->spin * hi;
    after.vx = out[0], after.vy = out[1], after.spin = out[2];
    for (t = 1e-6; t < horizon - hi; t += 1e-6)
      {
        if (reach_x (&after, t, &rx, &ry) >= face)
          return -1;
        if (after.vx < 0.0 && after.x + after.vx * t < face - after.radius)
          break;
      }
  }
  return 0;
}

/* One run of acc_spin_bar at `spin`: the error of the bar's velocity and
 * spin at the end against the closed form, the deepest any corner went
 * past the wall's face (over the bar's size), and whether its centre ever
 * did. */
static int spin_bar_run (const acc_engine *e, const acc_settings *set, double spin, double *err, double *depth,
                         int *crossed, acc_result *timed)
{
  const double seconds = ACC_SPIN_BAR_SECONDS;
  bench_scene s;
  bench_body *p;
  acc_run r;
  double want[3], rx, ry, size;
  int rc = -1, k, n = steps_for (seconds, set);
  *err = *depth = NAN;
  *crossed = 0;
  if (scene_alloc (&s, "spin_bar", 2) < 0)
    return -1;
  s.restitution = 1.0;
  p = scene_add (&s, BENCH_BOX, 1.0, 20.0, 1); /* its face at x = 0 */
  p->x = 0.5;
  p = scene_add (&s, BENCH_BOX, 4.0, 0.05, 0);
  p->angle = 0.3, p->vx = 2.0, p->spin = spin;
  p->x = -reach_x (p, 0.0, &rx, &ry) - 0.1, p->y = 0.3;
  size = acc_body_size (p);
  if (wall_impact (&s, p, 0.0, 1.0, seconds, want) < 0)
    {
      fprintf (stderr, "accuracy: the spinning bar at %g rad/s does not strike the wall once; change its set-up\n",
               spin);
      bench_scene_free (&s);
      return -1;
    }
  if (run_begin (&r, e, set, &s) == 0)
    {
      double deepest = 0.0, rho = sqrt (bench_body_inertia (p) / bench_body_area (p));
      acc_state st;
      for (k = 0; k < n; ++k)
        {
          bench_body now = *p;
          if (run_step (&r) != 0)
            break;
          e->state (r.w, 1, &st);
          now.x = st.x, now.y = st.y, now.angle = st.angle;
          now.vx = now.vy = now.spin = 0.0;
          deepest = fmax (deepest, reach_x (&now, 0.0, &rx, &ry));
          *crossed |= !(st.x < 0.0);
        }
      if (k == n)
        {
          *err = (fabs (st.vx - want[0]) + fabs (st.vy - want[1]) + rho * fabs (st.spin - want[2]))
                 / (fabs (want[0]) + rho * fabs (want[2]));
          *depth = deepest / size;
          rc = 0;
        }
    }
  run_end (&r, timed ? timed : &(acc_result){ 0 });
  bench_scene_free (&s);
  return rc;
}

/* A 4 x 0.05 bar (density 1) spinning at 60 and at 200 rad/s (its ends at
 * 120 and 400 m/s, 2 and 6.7 m a 1/60 s step), thrown at 2 m/s at a static
 * wall, e = 1, no friction, no gravity: it strikes the wall with one
 * corner and flies off. Its velocity and spin after ACC_SPIN_BAR_SECONDS
 * against eq. 3.23 for that single corner at the moment it touches
 * (wall_impact, from the scene's start; the start, angle 0.3 and 0.1 from
 * the wall, is one where one impact is the whole answer):
 * (|dvx| + |dvy| + rho |dw|) / (|vx'| + rho |w'|), rho the radius of
 * gyration; the deepest a corner went past the wall's face after any step,
 * over the bar's size; and the runs in which its centre passed the face.
 * tests/test_impacts.c, test_spinning_bar_leaves_a_wall_as_the_closed_form,
 * asserts this at the library's defaults from 24 angles. */
int acc_spin_bar (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  double err60, err200, depth60, depth200;
  int crossed60, crossed200, rc;
  result_init (res, "spin_bar");
  rc = spin_bar_run (e, set, 60.0, &err60, &depth60, &crossed60, NULL);
  rc |= spin_bar_run (e, set, 200.0, &err200, &depth200, &crossed200, res);
  result_put (res, "err_60", err60);
  result_put (res, "err_200", err200);
  result_put (res, "depth", fmax (depth60, depth200));
  result_put (res, "crossed", crossed60 + crossed200);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ seams */

/* ACC_SEAM_TILES touching static 1 x 1 tiles, their tops at y = 0 from
 * x = 0, gravity 10 down, no friction, e = 0, and one body of size 0.2
 * (a circle of radius 0.1 or a 0.2 x 0.2 box) at (x, y) moving at vx. */
static int seams_scene (bench_scene *s, bench_shape shape, double x, double y, double vx)
{
  bench_body *p;
  int i;
  if (scene_alloc (s, "seams", ACC_SEAM_TILES + 1) < 0)
    return -1;
  s->gravity_y = -10.0;
  for (i = 0; i < ACC_SEAM_TILES; ++i)
    {
      p = scene_add (s, BENCH_BOX, 1.0, 1.0, 1);
      p->x = i + 0.5, p->y = -0.5;
    }
  p = shape == BENCH_BOX ? scene_add (s, BENCH_BOX, 0.2, 0.2, 0) : scene_add (s, BENCH_CIRCLE, 0.1, 0, 0);
  p->x = x, p->y = y, p->vx = vx;
  return 0;
}

/* One body over the seams: its resting height first (where it comes to
 * rest in 1 s from touching the floor at x = 20.5, so that a skin or an
 * allowed overlap is not counted as a rise), then from there, at x = 0.5,
 * sliding at v0 = 5 m/s until it passes x = ACC_SEAM_TILES - 1 (or 20 s):
 * the largest |vx - v0| / v0 and the largest rise above the resting
 * height, over its size, after any step; *crossed 0 if it never got
 * across. */
static int seams_run (const acc_engine *e, const acc_settings *set, bench_shape shape, double *speed, double *rise,
                      int *crossed, acc_result *timed)
{
  const double v0 = 5.0, size = 0.2;
  bench_scene s;
  acc_run r;
  acc_state st;
  double rest = NAN;
  int rc = -1, k, n;
  *speed = *rise = NAN;
  *crossed = 0;
  if (seams_scene (&s, shape, 20.5, 0.5 * size, 0.0) < 0)
    return -1;
  if (run_begin (&r, e, set, &s) == 0 && run_seconds (&r, 1.0) == 0)
    {
      e->state (r.w, ACC_SEAM_TILES, &st);
      rest = st.y;
    }
  run_end (&r, &(acc_result){ 0 });
  bench_scene_free (&s);
  if (!isfinite (rest) || seams_scene (&s, shape, 0.5, rest, v0) < 0)
    return -1;
  n = steps_for (20.0, set);
  if (run_begin (&r, e, set, &s) == 0)
    {
      double worst_v = 0.0, worst_y = 0.0;
      for (k = 0; k < n; ++k)
        {
          if (run_step (&r) != 0)
            break;
          e->state (r.w, ACC_SEAM_TILES, &st);
          worst_v = fmax (worst_v, fabs (st.vx - v0) / v0);
          worst_y = fmax (worst_y, (st.y - rest) / size);
          if (st.x > ACC_SEAM_TILES - 1.0)
            {
              *crossed = 1;
              break;
            }
        }
      if (k == n || *crossed)
        {
          *speed = worst_v, *rise = worst_y;
          rc = 0;
        }
    }
  run_end (&r, timed ? timed : &(acc_result){ 0 });
  bench_scene_free (&s);
  return rc;
}

/* Seams: a floor of ACC_SEAM_TILES touching static 1 x 1 boxes (floor
 * tiles) is one flat surface. A circle (radius 0.1) and a 0.2 x 0.2 box
 * slide over it at 5 m/s, gravity 10 down, no friction, e = 0: nothing
 * should slow them (the closed form: vx = 5 throughout) or lift them off
 * the floor; a ghost collision with a tile's side at a seam does both.
 * The largest |vx - 5| / 5 and the largest rise above the resting height
 * (over the body's size, 0.2) over the crossing, and how many of the two
 * did not get across in 20 s. tests/test_seams.c,
 * test_bodies_cross_touching_tiles_smoothly, asserts this (within 1% and
 * 1 mm) at the library's defaults with continuous collision off and on. */
int acc_seams (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  double cs, cr, bs, br;
  int cc, bc, rc;
  result_init (res, "seams");
  rc = seams_run (e, set, BENCH_CIRCLE, &cs, &cr, &cc, NULL);
  rc |= seams_run (e, set, BENCH_BOX, &bs, &br, &bc, res);
  result_put (res, "circle_speed", cs);
  result_put (res, "circle_rise", cr);
  result_put (res, "box_speed", bs);
  result_put (res, "box_rise", br);
  result_put (res, "stuck", rc ? NAN : 2 - cc - bc);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ Newton's cradle */

/* A row of n equal touching balls (radius 0.1) on the x axis, e = 1, no
 * friction, no gravity, the first moving at v0 = 1 m/s into the others at
 * rest, ACC_CRADLE_SECONDS: the largest |v| of the first n - 1 balls over
 * v0, and |v - (v0, 0)| of the last over v0. */
static int cradle_run (const acc_engine *e, const acc_settings *set, int n, double *rest, double *last,
                       acc_result *timed)
{
  const double r = 0.1, v0 = 1.0;
  bench_scene s;
  bench_body *p;
  acc_run run;
  int i, rc = -1;
  *rest = *last = NAN;
  if (scene_alloc (&s, "cradle", n) < 0)
    return -1;
  s.restitution = 1.0;
  for (i = 0; i < n; ++i)
    {
      p = scene_add (&s, BENCH_CIRCLE, r, 0, 0);
      p->x = 2.0 * r * i;
      p->vx = i == 0 ? v0 : 0.0;
    }
  if (run_begin (&run, e, set, &s) == 0 && run_seconds (&run, ACC_CRADLE_SECONDS) == 0)
    {
      double worst = 0.0;
      for (i = 0; i < n; ++i)
        {
          acc_state st;
          e->state (run.w, i, &st);
          if (i < n - 1)
            worst = fmax (worst, hypot (st.vx, st.vy) / v0);
          else
            *last = hypot (st.vx - v0, st.vy) / v0;
        }
      *rest = worst;
      rc = 0;
    }
  run_end (&run, timed ? timed : &(acc_result){ 0 });
  bench_scene_free (&s);
  return rc;
}

/* Newton's cradle: rows of 5 and of 3 equal touching balls, the first
 * striking the others at 1 m/s, e = 1. The closed form is the sequential
 * model (pairwise eq. 3.23 impacts between neighbours, left to right):
 * each ball stops and passes its velocity on, so only the last leaves, at
 * v0, and the others stay at rest. A solver that treats the touching row
 * as one simultaneous impact spreads the velocity over the row instead.
 * After ACC_CRADLE_SECONDS: the largest |v| of the balls that should be
 * at rest over v0, and the last ball's velocity error over v0.
 * tests/test_impacts.c, test_newtons_cradle_is_sequential, asserts this at
 * the library's defaults (and with unequal masses, e = 0.8 and on a floor
 * under gravity). The cost is the 5's run. */
int acc_cradle (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  double rest5, last5, rest3, last3;
  int rc;
  result_init (res, "cradle");
  rc = cradle_run (e, set, 3, &rest3, &last3, NULL);
  rc |= cradle_run (e, set, 5, &rest5, &last5, res);
  result_put (res, "rest_5", rest5);
  result_put (res, "last_5", last5);
  result_put (res, "rest_3", rest3);
  result_put (res, "last_3", last3);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ joints */

/* Every joint scene has gravity g = 10 down, no friction or restitution,
 * and its bodies at rest at the start. */
#define ACC_G 10.0

/* K(k), the complete elliptic integral of the first kind, by the
 * arithmetic-geometric mean. */
static double elliptic_k (double k)
{
  double a = 1.0, b = sqrt (1.0 - k * k);
  int i;
  for (i = 0; i < 60; ++i)
    {
      double m = 0.5 * (a + b);
      b = sqrt (a * b);
      a = m;
    }
  return ACC_PI / (2.0 * a);
}

/* The joints' gaps added up: how far apart each joint's two anchors are
 * now, the points of its bodies that were both at the joint at the start
 * (bench_joint_gap, the benches' own measure, from the bodies' poses;
 * `pose` holds 3 doubles per body). */
static double joint_gaps (const acc_run *r, const bench_scene *s, double *pose)
{
  int i;
  for (i = 0; i < s->count; ++i)
    {
      acc_state st;
      r->e->state (r->w, i, &st);
      pose[3 * i] = st.x, pose[3 * i + 1] = st.y, pose[3 * i + 2] = st.angle;
    }
  return bench_joint_gap (s, pose) * s->joint_count;
}

/* Kinetic plus potential energy of the dynamic bodies (y = 0: none). */
static double mechanical (const acc_run *r, const bench_scene *s)
{
  double sum = 0.0;
  int i;
  for (i = 0; i < s->count; ++i)
    {
      acc_state st;
      if (s->bodies[i].is_static)
        continue;
      r->e->state (r->w, i, &st);
      sum += bench_kinetic (st.mass, st.inertia, st.vx, st.vy, st.spin) + st.mass * ACC_G * st.y;
    }
  return sum;
}

static int joint_scene (bench_scene *s, const char *name, int count)
{
  if (scene_alloc (s, name, count) < 0)
    return -1;
  s->gravity_y = -ACC_G;
  return 0;
}

/* A small disc (radius 0.05) on a 1 m revolute joint to a fixed point at the
 * origin, let go at rest theta0 from the vertical, for ACC_PENDULUM_SECONDS:
 * the period from the upward zero crossings of its x (between two steps by
 * linear interpolation: the swing is fastest there and its acceleration
 * is 0), the relative error against 4 sqrt(I / (m g d)) K(sin(theta0 / 2)),
 * I about the pivot from the engine's own mass and inertia. The amplitude
 * at the end from the energy (cos theta = 1 - E / (m g d), E = kinetic +
 * m g (y + d)) over theta0, minus 1. The rod's largest |length - 1| to
 * *stretch, if larger. */
static int pendulum_run (const acc_engine *e, const acc_settings *set, double degrees, double *period_err,
                         double *amplitude, double *stretch, acc_result *res)
{
  const double d = 1.0, th0 = degrees * ACC_PI / 180.0;
  bench_scene s;
  bench_body *p;
  acc_run r;
  acc_state st;
  double t = 0.0, first = -1.0, last = -1.0, lastx, exact, cosa;
  int rc = 0, k, n = steps_for (ACC_PENDULUM_SECONDS, set), periods = 0;
  *period_err = *amplitude = NAN;
  if (joint_scene (&s, "pendulum", 1) < 0)
    return -1;
  p = scene_add (&s, BENCH_CIRCLE, 0.05, 0, 0);
  p->x = d * sin (th0), p->y = -d * cos (th0);
  scene_join (&s, -1, 0, 0.0, 0.0);
  if (run_begin (&r, e, set, &s) < 0)
    {
      bench_scene_free (&s);
      return -1;
    }
  e->state (r.w, 0, &st);
  exact = 4.0 * sqrt ((st.inertia + st.mass * d * d) / (st.mass * ACC_G * d)) * elliptic_k (sin (0.5 * th0));
  lastx = st.x;
  for (k = 0; k < n && rc == 0; ++k)
    {
      double len;
      rc = run_step (&r);
      t += set->dt;
      e->state (r.w, 0, &st);
      len = fabs (hypot (st.x, st.y) - d) / d;
      if (!(len <= *stretch))
        *stretch = len;
      if (lastx < 0.0 && st.x >= 0.0)
        {
          double tc = t - set->dt + set->dt * (-lastx) / (st.x - lastx);
          if (first < 0.0)
            first = tc;
          else
            ++periods;
          last = tc;
        }
      lastx = st.x;
    }
  if (rc == 0 && periods > 0)
    *period_err = (last - first) / periods / exact - 1.0;
  else
    rc = -1;
  cosa = 1.0 - (bench_kinetic (st.mass, st.inertia, st.vx, st.vy, st.spin) + st.mass * ACC_G * (st.y + d))
                   / (st.mass * ACC_G * d);
  *amplitude = acos (cosa < -1.0 ? -1.0 : cosa > 1.0 ? 1.0 : cosa) / th0 - 1.0;
  run_end (&r, res);
  bench_scene_free (&s);
  return rc;
}

/* The pendulum let go at 10 and at 90 degrees; the cost is the 90's run. */
int acc_pendulum (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  double err10, err90, amp10, amp90, stretch = 0.0;
  int rc;
  result_init (res, "pendulum");
  rc = pendulum_run (e, set, 10.0, &err10, &amp10, &stretch, res);
  rc |= pendulum_run (e, set, 90.0, &err90, &amp90, &stretch, res);
  result_put (res, "period_err_10", err10);
  result_put (res, "period_err_90", err90);
  result_put (res, "amplitude_10", amp10);
  result_put (res, "amplitude_90", amp90);
  result_put (res, "stretch", stretch);
  res->ok = rc == 0;
  return rc ? -1 : 0;
}

/* Two small discs (radius 0.05) on 1 m rods, a revolute joint at the pivot
 * (the origin) and one at the first disc's centre, let go at rest with both
 * rods horizontal, for ACC_DOUBLE_PENDULUM_SECONDS: the largest |E - E0|
 * after any step, and E - E0 at the end, over the energy it can spend (E0
 * less the energy hanging straight down, -m1 g - 2 m2 g). */
int acc_double_pendulum (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  bench_body *p;
  acc_run r;
  acc_state a, b;
  double e0, budget, worst = 0.0, end = NAN;
  int rc = 0, k, n = steps_for (ACC_DOUBLE_PENDULUM_SECONDS, set);
  result_init (res, "double_pendulum");
  if (joint_scene (&s, "double_pendulum", 2) < 0)
    return -1;
  p = scene_add (&s, BENCH_CIRCLE, 0.05, 0, 0);
  p->x = 1.0;
  p = scene_add (&s, BENCH_CIRCLE, 0.05, 0, 0);
  p->x = 2.0;
  scene_join (&s, -1, 0, 0.0, 0.0);
  scene_join (&s, 0, 1, 1.0, 0.0);
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      e->state (r.w, 0, &a);
      e->state (r.w, 1, &b);
      e0 = mechanical (&r, &s);
      budget = e0 - (-a.mass * ACC_G * 1.0 - b.mass * ACC_G * 2.0);
      for (k = 0; k < n && rc == 0; ++k)
        {
          double de;
          rc = run_step (&r);
          de = fabs (mechanical (&r, &s) - e0) / budget;
          if (!(de <= worst))
            worst = de;
        }
      end = (mechanical (&r, &s) - e0) / budget;
    }
  result_put (res, "energy_err", rc ? NAN : worst);
  result_put (res, "energy_end", rc ? NAN : end);
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* ACC_CHAIN_LINKS links (0.25 x 0.05 boxes) on revolute joints at their
 * ends, the first one's to a fixed point at the origin, holding a box of 100
 * links' mass (a square of side sqrt(100 x 0.25 x 0.05), the same density)
 * joined at the middle of its near side; hung straight down or laid out
 * horizontal. The largest, after any step, of the joints' gaps added up,
 * over the chain's length (10). */
static int chain_run (const acc_engine *e, const acc_settings *set, int horizontal, double seconds, double *gap,
                      acc_result *res)
{
  const double link = 0.25, thick = 0.05, side = sqrt (100.0 * link * thick);
  double pose[3 * (ACC_CHAIN_LINKS + 1)];
  bench_scene s;
  acc_run r;
  int i, k, rc = 0, n = steps_for (seconds, set);
  *gap = NAN;
  if (joint_scene (&s, "chain", ACC_CHAIN_LINKS + 1) < 0)
    return -1;
  for (i = 0; i <= ACC_CHAIN_LINKS; ++i)
    {
      double along = i < ACC_CHAIN_LINKS ? (i + 0.5) * link : ACC_CHAIN_LINKS * link + 0.5 * side;
      bench_body *p = i < ACC_CHAIN_LINKS ? scene_add (&s, BENCH_BOX, link, thick, 0)
                                          : scene_add (&s, BENCH_BOX, side, side, 0);
      p->x = horizontal ? along : 0.0;
      p->y = horizontal ? 0.0 : -along;
      p->angle = horizontal || i == ACC_CHAIN_LINKS ? 0.0 : 0.5 * ACC_PI;
      scene_join (&s, i - 1, i, horizontal ? i * link : 0.0, horizontal ? 0.0 : -i * link);
    }
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    {
      double worst = 0.0;
      for (k = 0; k < n && rc == 0; ++k)
        {
          double sum;
          rc = run_step (&r);
          sum = joint_gaps (&r, &s, pose) / (ACC_CHAIN_LINKS * link);
          if (!(sum <= worst))
            worst = sum;
        }
      if (rc == 0)
        *gap = worst;
    }
  run_end (&r, res);
  bench_scene_free (&s);
  return rc;
}

/* The heavy chain at rest (hung straight, ACC_CHAIN_REST_SECONDS) and
 * swinging down from horizontal (ACC_CHAIN_SWING_SECONDS, through the
 * moment it snaps taut and on); the cost is the swing's run. */
int acc_chain (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  double rest, swing;
  int rc;
  result_init (res, "chain");
  rc = chain_run (e, set, 0, ACC_CHAIN_REST_SECONDS, &rest, res);
  rc |= chain_run (e, set, 1, ACC_CHAIN_SWING_SECONDS, &swing, res);
  result_put (res, "rest_gap", rest);
  result_put (res, "swing_gap", swing);
  res->ok = rc == 0;
  return rc ? -1 : 0;
}

/* A 0.4 x 1 box hung at rest by a revolute joint at the middle of its top
 * edge to a fixed point, for ACC_HANGING_SECONDS: the joint's force on it
 * (its constraint force), |reaction| / (m g) - 1 at the end, and the largest
 * | |reaction| / (m g) - 1 | over the last second. */
int acc_hanging (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  bench_scene s;
  bench_body *p;
  acc_run r;
  double end = NAN, worst = 0.0;
  int rc = 0, k, n = steps_for (ACC_HANGING_SECONDS, set), from = n - steps_for (1.0, set);
  result_init (res, "hanging");
  if (joint_scene (&s, "hanging", 1) < 0)
    return -1;
  p = scene_add (&s, BENCH_BOX, 0.4, 1.0, 0);
  p->y = -0.5;
  scene_join (&s, -1, 0, 0.0, 0.0);
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    for (k = 0; k < n && rc == 0; ++k)
      {
        acc_state st;
        double fx = 0.0, fy = 0.0;
        rc = run_step (&r);
        e->state (r.w, 0, &st);
        e->joint_force (r.w, 0, &fx, &fy);
        end = hypot (fx, fy) / (st.mass * ACC_G) - 1.0;
        if (k >= from && !(fabs (end) <= worst))
          worst = fabs (end);
      }
  result_put (res, "reaction_err", rc ? NAN : end);
  result_put (res, "reaction_worst", rc ? NAN : worst);
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* A 1 x 0.1 bar on a revolute joint at one end to a fixed point, let go at
 * rest horizontal, falls onto the joint's lower limit of -0.5 rad (upper
 * +0.5), for ACC_LIMIT_SECONDS: the most it went past the limit, and how
 * far past it it rests at the end (negative: short of it), in degrees. */
int acc_limit (const acc_engine *e, const acc_settings *set, acc_result *res)
{
  const double lower = -0.5;
  bench_scene s;
  bench_body *p;
  bench_joint *j;
  acc_run r;
  acc_state st;
  double lowest = 0.0, end = NAN;
  int rc = 0, k, n = steps_for (ACC_LIMIT_SECONDS, set);
  result_init (res, "limit");
  if (joint_scene (&s, "limit", 1) < 0)
    return -1;
  p = scene_add (&s, BENCH_BOX, 1.0, 0.1, 0);
  p->x = 0.5;
  j = scene_join (&s, -1, 0, 0.0, 0.0);
  j->enable_limit = 1, j->lower = lower, j->upper = 0.5;
  if (run_begin (&r, e, set, &s) < 0)
    rc = -1;
  else
    for (k = 0; k < n && rc == 0; ++k)
      {
        rc = run_step (&r);
        e->state (r.w, 0, &st);
        if (!(st.angle >= lowest))
          lowest = st.angle;
        end = st.angle;
      }
  result_put (res, "overshoot_deg", rc ? NAN : (lowest < lower ? lower - lowest : 0.0) * 180.0 / ACC_PI);
  result_put (res, "rest_deg", rc ? NAN : (lower - end) * 180.0 / ACC_PI);
  run_end (&r, res);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* ------------------------------------------------ reference runs */

static int make_reference_scene (bench_scene *s, const char *scene)
{
  if (strcmp (scene, "pyramid") == 0)
    return bench_scene_make (s, "pyramid", ACC_PYRAMID_BODIES);
  return bench_scene_make (s, "rain", ACC_RAIN_BODIES);
}

static int trajectory (const acc_engine *e, const acc_settings *set, const bench_scene *s, double *out,
                       acc_result *res)
{
  acc_run r;
  int k, i, j = 0, rc = 0, n = steps_for (ACC_REFERENCE_SECONDS, set);
  if (run_begin (&r, e, set, s) < 0)
    return -1;
  for (k = 1; k <= n && rc == 0; ++k)
    {
      rc = run_step (&r);
      /* sample when the step lands on k / ACC_SAMPLES of the run */
      if (rc == 0 && (k * ACC_SAMPLES) % n == 0)
        for (i = 0; i < s->count; ++i)
          {
            acc_state st;
            if (s->bodies[i].is_static)
              continue;
            e->state (r.w, i, &st);
            out[j++] = st.x, out[j++] = st.y;
          }
    }
  if (j != ACC_SAMPLES * 2 * s->dynamic_count)
    rc = -1;
  run_end (&r, res);
  return rc;
}

int acc_trajectory (const acc_engine *e, const acc_settings *set, const char *scene, double **out, int *count)
{
  bench_scene s;
  acc_result res;
  int rc;
  if (make_reference_scene (&s, scene) < 0)
    return -1;
  *count = ACC_SAMPLES * 2 * s.dynamic_count;
  *out = malloc ((size_t) *count * sizeof **out);
  rc = *out ? trajectory (e, set, &s, *out, &res) : -1;
  bench_scene_free (&s);
  return rc;
}

int acc_reference (const acc_engine *e, const acc_settings *set, const char *scene, const double *ref,
                   acc_result *res)
{
  bench_scene s;
  double *pos, sum = 0.0;
  int i, k, j = 0, rc;
  result_init (res, strcmp (scene, "pyramid") == 0 ? "ref_pyramid" : "ref_rain");
  if (make_reference_scene (&s, scene) < 0)
    return -1;
  pos = malloc ((size_t) ACC_SAMPLES * 2 * s.dynamic_count * sizeof *pos);
  rc = pos ? trajectory (e, set, &s, pos, res) : -1;
  if (rc == 0)
    {
      for (k = 0; k < ACC_SAMPLES; ++k)
        for (i = 0; i < s.count; ++i)
          {
            double size;
            if (s.bodies[i].is_static)
              continue;
            size = acc_body_size (&s.bodies[i]);
            sum += (pow (pos[j] - ref[j], 2) + pow (pos[j + 1] - ref[j + 1], 2)) / (size * size);
            j += 2;
          }
      result_put (res, "rms", sqrt (sum / (ACC_SAMPLES * s.dynamic_count)));
    }
  free (pos);
  bench_scene_free (&s);
  res->ok = rc == 0;
  return rc;
}

/* Every measure above except the reference runs, by the name its lines
 * carry, in the map's order. */
const acc_measure acc_measures[] = {
  { "collision", acc_collision },
  { "projectile", acc_projectile },
  { "bounce", acc_bounce },
  { "drop", acc_drop },
  { "gas", acc_gas },
  { "momentum", acc_momentum },
  { "pyramid", acc_pyramid },
  { "rain", acc_rain },
  { "tunnel", acc_tunnel },
  { "spin_bar", acc_spin_bar },
  { "seams", acc_seams },
  { "cradle", acc_cradle },
  { "pendulum", acc_pendulum },
  { "double_pendulum", acc_double_pendulum },
  { "chain", acc_chain },
  { "hanging", acc_hanging },
  { "limit", acc_limit },
  { NULL, NULL },
};

int acc_wanted (const char *list, const char *name)
{
  const char *p = list;
  size_t k = strlen (name);
  if (!list)
    return 1;
  while ((p = strstr (p, name)))
    {
      if ((p == list || p[-1] == ',') && (p[k] == ',' || p[k] == '\0'))
        return 1;
      p += k;
    }
  return 0;
}

int acc_run_all (const acc_engine *e, const acc_settings *set, const char *only)
{
  const acc_measure *m;
  int rc = 0;
  for (m = acc_measures; m->name; ++m)
    {
      acc_result r;
      if (!acc_wanted (only, m->name))
        continue;
      if (m->run (e, set, &r) < 0)
        {
          r.ok = 0;
          rc = -1;
        }
      acc_print (e, set, &r, NULL);
    }
  return rc;
}
