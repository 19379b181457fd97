/* carom on the benchmark scenes: builds a scene from scenes.c (its bodies,
 * then its joints), steps it at dt = 1/60 (warm-up, then timed steps) and
 * prints one key=value line.
 *
 * mode=mem instead counts the bytes carom holds, through a counting
 * allocator (carom_world_def.allocator): after building, after one
 * detection at the start, and after the steps; printed as bytes per body
 * and per contact point.
 *
 * mode=hash steps the warm-up and timed steps untimed and prints a hash of
 * the bits of every body's position, angle, velocity and spin at the end:
 * a change meant to make carom faster without changing its results must
 * leave it as it was. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carom.h"
#include "carom_scene.h"
#include "scenes.h"

typedef struct counter {
  size_t live, peak, calls;
} counter;

static void *count_alloc (size_t size, void *user)
{
  counter *c = user;
  void *p = malloc (size);
  if (p)
    {
      c->live += size;
      c->calls++;
      if (c->live > c->peak)
        c->peak = c->live;
    }
  return p;
}

static void count_free (void *ptr, size_t size, void *user)
{
  counter *c = user;
  c->live -= size;
  free (ptr);
}

static int build (carom_world **world, const bench_scene *s, const bench_options *o, counter *count,
                  carom_body_id *ids)
{
  carom_world_def def;
  carom_status st;
  int failed = 0;
  bench_carom_def (&def, s);
  if (o->substeps > 0)
    def.substeps = o->substeps;
  if (o->iterations > 0)
    def.iterations = o->iterations;
  if (count)
    {
      def.allocator.alloc = count_alloc;
      def.allocator.free = count_free;
      def.allocator.user = count;
    }
  if (carom_world_init (world, &def) != CAROM_OK)
    return -1;
  if ((o->sleep && carom_world_set_sleeping (*world, 1) != CAROM_OK)
      || (o->continuous >= 0 && carom_world_set_continuous (*world, o->continuous) != CAROM_OK))
    return -1;
  st = bench_carom_add_bodies (*world, s, ids, &failed);
  if (st != CAROM_OK)
    {
      fprintf (stderr, "bench_carom: body %d: %s\n", failed, carom_status_string (st));
      return -1;
    }
  st = bench_carom_add_joints (*world, s, ids, NULL, &failed);
  if (st != CAROM_OK)
    {
      fprintf (stderr, "bench_carom: joint %d: %s\n", failed, carom_status_string (st));
      return -1;
    }
  return 0;
}

static double kinetic (const carom_world *w, const bench_scene *s, const carom_body_id *ids)
{
  double e = 0.0;
  int i;
  for (i = 0; i < s->count; ++i)
    {
      double m, inertia, vx, vy, spin;
      if (s->bodies[i].is_static)
        continue;
      carom_body_get_mass (w, ids[i], &m, &inertia, NULL);
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      carom_body_get_spin (w, ids[i], &spin);
      e += bench_kinetic (m, inertia, vx, vy, spin);
    }
  return e;
}

static int step (carom_world *w, int n)
{
  int k;
  for (k = 0; k < n; ++k)
    if (carom_world_update (w, 1.0 / 60.0) != CAROM_OK)
      return -1;
  return 0;
}

/* Bytes held by a world built from `s` (and, with `detect`, after one
 * detection), counted by the allocator. */
static int held_bytes (const bench_scene *s, const bench_options *o, carom_body_id *ids, int detect, size_t *built,
                       size_t *detected)
{
  counter c = { 0, 0, 0 };
  carom_world *w = NULL;
  if (build (&w, s, o, &c, ids) < 0)
    return -1;
  *built = c.live;
  if (detect && carom_world_detect (w) != CAROM_OK)
    return -1;
  *detected = c.live;
  carom_world_destroy (w);
  return 0;
}

/* Bytes per body: the world built, less an empty world. Bytes per contact
 * point: the world after the steps, less the world built and less its broad
 * phase, over the contact points alive at the end. The broad phase alone is
 * measured on a copy of the scene with every body static (static pairs are
 * never tested, so it holds no contacts). Arrays grow by doubling and the
 * contacts are double-buffered (this step's and last step's, for warm
 * starting), so these are the bytes held, not the bytes used. */
static int run_mem (const bench_options *o, const bench_scene *s, carom_body_id *ids)
{
  counter c = { 0, 0, 0 };
  carom_world *w = NULL;
  bench_scene none, frozen;
  size_t empty, built, frozen_built, frozen_detected, stepped, broad;
  int i, contacts;
  memset (&none, 0, sizeof none);
  none.density = 1.0;
  frozen = *s;
  frozen.joint_count = 0; /* joints need a dynamic body */
  frozen.bodies = malloc ((size_t) s->count * sizeof *s->bodies);
  if (!frozen.bodies)
    return -1;
  for (i = 0; i < s->count; ++i)
    {
      frozen.bodies[i] = s->bodies[i];
      frozen.bodies[i].is_static = 1;
    }
  if (held_bytes (&none, o, NULL, 0, &empty, &empty) < 0
      || held_bytes (&frozen, o, ids, 1, &frozen_built, &frozen_detected) < 0)
    return -1;
  free (frozen.bodies);
  broad = frozen_detected - frozen_built;
  if (build (&w, s, o, &c, ids) < 0)
    return -1;
  built = c.live;
  if (step (w, o->warmup + o->steps) < 0)
    return -1;
  stepped = c.live;
  contacts = carom_world_contact_count (w);
  printf ("engine=carom scene=%s bodies=%d steps=%d empty_bytes=%zu built_bytes=%zu broadphase_bytes=%zu "
          "stepped_bytes=%zu peak_bytes=%zu contacts=%d bytes_per_body=%.1f broadphase_bytes_per_body=%.1f "
          "bytes_per_contact=%.1f\n",
          s->name, s->count, o->warmup + o->steps, empty, built, broad, stepped, c.peak, contacts,
          (double) (built - empty) / s->count, (double) broad / s->count,
          contacts > 0 ? (double) (stepped - built - broad) / contacts : 0.0);
  carom_world_destroy (w);
  return 0;
}

/* FNV-1a over the bits of each body's state, in body order. */
static unsigned long long state_hash (const carom_world *w, const bench_scene *s, const carom_body_id *ids)
{
  unsigned long long h = 1469598103934665603ull;
  int i, k;
  size_t j;
  for (i = 0; i < s->count; ++i)
    {
      double q[6];
      carom_body_get_position (w, ids[i], &q[0], &q[1]);
      carom_body_get_angle (w, ids[i], &q[2]);
      carom_body_get_velocity (w, ids[i], &q[3], &q[4]);
      carom_body_get_spin (w, ids[i], &q[5]);
      for (k = 0; k < 6; ++k)
        {
          unsigned char b[sizeof (double)];
          memcpy (b, &q[k], sizeof b);
          for (j = 0; j < sizeof b; ++j)
            h = (h ^ b[j]) * 1099511628211ull;
        }
    }
  return h;
}

int main (int argc, char **argv)
{
  bench_options o;
  bench_scene s;
  bench_result r;
  carom_world *w = NULL;
  carom_body_id *ids;
  char settings[64];
  double t0, x0 = 0.0, y0 = 0.0;
  int i, rc = 0;
  if (bench_begin (&o, &s, argc, argv, "bench_carom") < 0)
    return 2;
  ids = calloc ((size_t) s.count, sizeof *ids);
  if (!ids)
    return 1;
  if (strcmp (o.mode, "mem") == 0)
    {
      rc = run_mem (&o, &s, ids) < 0;
      free (ids);
      bench_scene_free (&s);
      return rc;
    }
  memset (&r, 0, sizeof r);
  if (build (&w, &s, &o, NULL, ids) < 0)
    return 1;
  if (strcmp (o.mode, "hash") == 0)
    {
      rc = step (w, o.warmup + o.steps) < 0;
      printf ("engine=carom scene=%s bodies=%d steps=%d hash=%016llx contacts=%ld\n", o.scene, s.count,
              o.warmup + o.steps, state_hash (w, &s, ids), (long) carom_world_contact_count (w));
      carom_world_destroy (w);
      free (ids);
      bench_scene_free (&s);
      return rc;
    }
  {
    carom_world_def def;
    carom_world_def_init (&def, sizeof def);
    snprintf (settings, sizeof settings, "substeps=%d,iterations=%d", o.substeps > 0 ? o.substeps : def.substeps,
              o.iterations > 0 ? o.iterations : def.iterations);
  }
  r.engine = "carom";
  r.settings = settings;
  r.energy_start = kinetic (w, &s, ids);
  if (s.top >= 0)
    carom_body_get_position (w, ids[s.top], &x0, &y0);
  if (step (w, o.warmup) < 0)
    rc = 1;
  t0 = bench_now ();
  for (i = 0; i < o.steps && rc == 0; ++i)
    if (carom_world_update (w, 1.0 / 60.0) != CAROM_OK)
      rc = 1;
  r.seconds = bench_now () - t0;
  r.energy_end = kinetic (w, &s, ids);
  if (s.top >= 0)
    {
      double x, y;
      carom_body_get_position (w, ids[s.top], &x, &y);
      r.top_drift = sqrt ((x - x0) * (x - x0) + (y - y0) * (y - y0)) / s.bodies[s.top].h;
    }
  for (i = 0; i < s.count; ++i)
    {
      double x, y;
      if (s.bodies[i].is_static)
        continue;
      carom_body_get_position (w, ids[i], &x, &y);
      r.escaped += bench_outside (&s, x, y) || !isfinite (x) || !isfinite (y);
    }
  r.contacts = carom_world_contact_count (w);
  if (s.joint_count > 0)
    {
      double *pose = malloc ((size_t) s.count * 3 * sizeof *pose);
      if (!pose)
        return 1;
      for (i = 0; i < s.count; ++i)
        {
          carom_body_get_position (w, ids[i], &pose[3 * i], &pose[3 * i + 1]);
          carom_body_get_angle (w, ids[i], &pose[3 * i + 2]);
        }
      r.joint_gap = bench_joint_gap (&s, pose);
      free (pose);
    }
  if (rc)
    fprintf (stderr, "bench_carom: update failed\n");
  bench_report (&o, &s, &r);
  carom_world_destroy (w);
  free (ids);
  bench_scene_free (&s);
  return rc;
}
