/* What each effect stage costs per step (issue "Simulate only the effects a
 * scene calls for").
 *
 * Two scenes from bench/scenes.c, each in several variants that differ from
 * the scene as defined with every effect off, continuous collision (the
 * library's one default effect) too (the "off" baseline), by one effect:
 * switched on and
 * doing something, switched on but doing (next to) nothing, or, for an
 * effect the scene already uses, switched off. Every variant is its own
 * world built from the same scene data.
 *
 *   mode=time   all variants of a scene in one process, `repeats` times:
 *               fresh worlds, `warmup` untimed steps each, then `steps`
 *               timed steps in chunks of `chunk`, the variants in turn (the
 *               order rotating), so that machine noise hits them alike. A
 *               repeat's figure is the mean ms per step over all its timed
 *               steps (as an instruction count is); one key=value line per
 *               variant gives the median over the repeats, its ratio to the
 *               baseline's median, every repeat, and what the effect did to
 *               the world at the end (energy, bodies asleep, bodies out of
 *               the container, contact points, largest distance of a body
 *               from where it is in the baseline world).
 *   mode=count  one variant (variant=NAME): the warm-up, then the same
 *               `steps` steps inside measured_steps, which callgrind counts
 *               alone (--toggle-collect=measured_steps), so the
 *               instructions cover exactly the steps that mode=time timed.
 *   mode=list   the variants, one "scene=S variant=V" line each.
 *
 * usage: bench_effects [mode=time|count|list] [scene=gas|pyramid|all]
 *                      [variant=NAME] [warmup=N] [steps=N] [chunk=N]
 *                      [repeats=N]
 * Defaults: all scenes, warmup 60, steps 630, chunk 10, repeats 7, dt 1/60. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carom.h"
#include "carom_scene.h"
#include "scenes.h"

#define DT (1.0 / 60.0)
#define MAX_VARIANTS 24
#define MAX_REPEATS 101

/* What a variant changes, applied to a world built from the scene data. */
typedef enum change {
  CH_NONE,
  CH_GRAVITY,     /* a, b: uniform gravity */
  CH_CENTRAL,     /* a, b, c, d: centre, gm, softening */
  CH_FRICTION,    /* a: world friction */
  CH_RESTITUTION, /* a: world restitution */
  CH_DAMPING,     /* a, b: linear, angular */
  CH_SLEEPING,
  CH_FIXED,       /* fixed rotation on every dynamic body */
  CH_CONTINUOUS   /* continuous collision on */
} change;

typedef struct variant {
  const char *scene;
  const char *name;
  const char *kind; /* off | on | idle (on, doing next to nothing) | stage-off */
  change what;
  double a, b, c, d;
  const char *about; /* one line for the report */
} variant;

/* Gas: a closed box about 46 x 44 centred on the origin, no gravity, e = 1,
 * mu = 0. Pyramid: 20 rows of unit boxes on the ground (y = 0), gravity -10,
 * mu 0.6, e = 0. */
static const variant variants[] = {
  { "gas", "off", "off", CH_NONE, 0, 0, 0, 0, "the scene as defined: e = 1, no gravity, no friction" },
  { "gas", "gravity", "on", CH_GRAVITY, 0, -10, 0, 0, "+ uniform gravity (0, -10)" },
  { "gas", "gravity-tiny", "idle", CH_GRAVITY, 0, -1e-300, 0, 0, "+ uniform gravity (0, -1e-300)" },
  { "gas", "central", "on", CH_CENTRAL, 0, 0, 1000, 1, "+ central gravity to the box centre, gm 1000, softening 1" },
  { "gas", "central-tiny", "idle", CH_CENTRAL, 0, 0, 1e-300, 0, "+ central gravity, gm 1e-300" },
  { "gas", "friction", "on", CH_FRICTION, 0.5, 0, 0, 0, "+ friction 0.5" },
  { "gas", "friction-tiny", "idle", CH_FRICTION, 1e-150, 0, 0, 0,
    "+ friction 1e-150 (bodies mix as sqrt(mu_a mu_b): 1e-300 would give 0)" },
  { "gas", "damping", "on", CH_DAMPING, 0.1, 0.1, 0, 0, "+ damping 0.1 / 0.1" },
  { "gas", "damping-1e-12", "idle", CH_DAMPING, 1e-12, 1e-12, 0, 0, "+ damping 1e-12 / 1e-12" },
  { "gas", "damping-tiny", "idle", CH_DAMPING, 1e-300, 1e-300, 0, 0,
    "+ damping 1e-300 / 1e-300 (factor exp(-c h) rounds to exactly 1)" },
  { "gas", "sleeping", "idle", CH_SLEEPING, 0, 0, 0, 0, "+ sleeping (gas bodies never slow down)" },
  { "gas", "fixed", "on", CH_FIXED, 0, 0, 0, 0, "+ fixed rotation on every body" },
  { "gas", "restitution-0.5", "on", CH_RESTITUTION, 0.5, 0, 0, 0, "restitution 0.5 instead of 1" },
  { "gas", "restitution-0", "stage-off", CH_RESTITUTION, 0, 0, 0, 0, "restitution 0: the stage off" },
  { "gas", "continuous", "on", CH_CONTINUOUS, 0, 0, 0, 0, "+ continuous collision (the library's default)" },
  { "pyramid", "off", "off", CH_NONE, 0, 0, 0, 0, "the scene as defined: gravity -10, friction 0.6, e = 0" },
  { "pyramid", "friction-0", "stage-off", CH_FRICTION, 0, 0, 0, 0, "friction 0: the stage off" },
  { "pyramid", "sleeping", "on", CH_SLEEPING, 0, 0, 0, 0, "+ sleeping" },
  { "pyramid", "damping", "on", CH_DAMPING, 0.1, 0.1, 0, 0, "+ damping 0.1 / 0.1" },
  { "pyramid", "damping-tiny", "idle", CH_DAMPING, 1e-300, 1e-300, 0, 0, "+ damping 1e-300 / 1e-300" },
  { "pyramid", "central", "on", CH_CENTRAL, 0, -20, 2000, 1,
    "+ central gravity to (0, -20), below the base, gm 2000, softening 1" },
  { "pyramid", "central-tiny", "idle", CH_CENTRAL, 0, -20, 1e-300, 0, "+ central gravity, gm 1e-300" },
  { "pyramid", "restitution-0.5", "on", CH_RESTITUTION, 0.5, 0, 0, 0, "+ restitution 0.5" },
  { "pyramid", "fixed", "idle", CH_FIXED, 0, 0, 0, 0, "+ fixed rotation on every box (a standing pyramid barely spins)" },
  { "pyramid", "continuous", "on", CH_CONTINUOUS, 0, 0, 0, 0, "+ continuous collision (the library's default)" },
};
#define VARIANT_COUNT ((int) (sizeof variants / sizeof variants[0]))

typedef struct options {
  char mode[8], scene[16], variant[32];
  int warmup, steps, chunk, repeats;
} options;

typedef struct run {
  const variant *v;
  carom_world *world;
  carom_body_id *ids;
  double ms[MAX_REPEATS]; /* mean ms per timed step of each repeat */
  double energy_start;
} run;

static int parse (options *o, int argc, char **argv)
{
  int i;
  memset (o, 0, sizeof *o);
  strcpy (o->mode, "time");
  strcpy (o->scene, "all");
  o->warmup = 60;
  o->steps = 630;
  o->chunk = 10;
  o->repeats = 7;
  for (i = 1; i < argc; ++i)
    {
      const char *a = argv[i], *eq = strchr (a, '=');
      if (!eq)
        return -1;
      if (strncmp (a, "mode=", 5) == 0)
        snprintf (o->mode, sizeof o->mode, "%s", eq + 1);
      else if (strncmp (a, "scene=", 6) == 0)
        snprintf (o->scene, sizeof o->scene, "%s", eq + 1);
      else if (strncmp (a, "variant=", 8) == 0)
        snprintf (o->variant, sizeof o->variant, "%s", eq + 1);
      else if (strncmp (a, "warmup=", 7) == 0)
        o->warmup = atoi (eq + 1);
      else if (strncmp (a, "steps=", 6) == 0)
        o->steps = atoi (eq + 1);
      else if (strncmp (a, "repeats=", 8) == 0)
        o->repeats = atoi (eq + 1);
      else if (strncmp (a, "chunk=", 6) == 0)
        o->chunk = atoi (eq + 1);
      else
        return -1;
    }
  if (o->warmup < 0 || o->steps < 1 || o->chunk < 1 || o->repeats < 1 || o->repeats > MAX_REPEATS)
    return -1;
  return 0;
}

static carom_status apply (carom_world *w, const variant *v, const bench_scene *s, const carom_body_id *ids)
{
  carom_status st = CAROM_OK;
  int i;
  switch (v->what)
    {
    case CH_NONE:
      break;
    case CH_GRAVITY:
      st = carom_world_set_gravity (w, v->a, v->b);
      break;
    case CH_CENTRAL:
      st = carom_world_set_central_gravity (w, v->a, v->b, v->c, v->d);
      break;
    case CH_FRICTION:
      st = carom_world_set_friction (w, v->a);
      break;
    case CH_RESTITUTION:
      st = carom_world_set_restitution (w, v->a);
      break;
    case CH_DAMPING:
      st = carom_world_set_damping (w, v->a, v->b);
      break;
    case CH_SLEEPING:
      st = carom_world_set_sleeping (w, 1);
      break;
    case CH_CONTINUOUS:
      st = carom_world_set_continuous (w, 1);
      break;
    case CH_FIXED:
      for (i = 0; i < s->count && st == CAROM_OK; ++i)
        if (!s->bodies[i].is_static)
          st = carom_body_set_fixed_rotation (w, ids[i], 1);
      break;
    }
  return st;
}

/* The scene as bench_carom builds it (world defaults for every body), then
 * the variant's change through the API. */
static int build (run *r, const bench_scene *s)
{
  carom_world_def def;
  carom_status st;
  int failed = 0;
  bench_carom_def (&def, s);
  if (carom_world_init (&r->world, &def) != CAROM_OK)
    return -1;
  r->ids = calloc ((size_t) s->count, sizeof *r->ids);
  if (!r->ids)
    return -1;
  st = bench_carom_add_bodies (r->world, s, r->ids, &failed);
  if (st != CAROM_OK)
    {
      fprintf (stderr, "bench_effects: body %d: %s\n", failed, carom_status_string (st));
      return -1;
    }
  /* every effect off, continuous collision (on by default) too; the
     variant's change then switches one on */
  st = carom_world_set_continuous (r->world, 0);
  if (st == CAROM_OK)
    st = apply (r->world, r->v, s, r->ids);
  if (st != CAROM_OK)
    {
      fprintf (stderr, "bench_effects: %s/%s: %s\n", s->name, r->v->name, carom_status_string (st));
      return -1;
    }
  return 0;
}

static void release (run *r)
{
  carom_world_destroy (r->world);
  free (r->ids);
  r->world = NULL;
  r->ids = NULL;
}

static int steps (carom_world *w, int n)
{
  int k;
  for (k = 0; k < n; ++k)
    if (carom_world_update (w, DT) != CAROM_OK)
      return -1;
  return 0;
}

/* The steps callgrind counts (--toggle-collect=measured_steps); kept out of
 * line so that its name stays in the profile. */
static __attribute__ ((noinline)) int measured_steps (carom_world *w, int n)
{
  return steps (w, n);
}

/* Kinetic energy of the dynamic bodies (plus the potential energy of the
 * uniform gravity, zero at the origin, so that a falling scene keeps it). */
static double energy (const run *r, const bench_scene *s)
{
  double e = 0.0, gx, gy;
  int i;
  carom_world_get_gravity (r->world, &gx, &gy);
  for (i = 0; i < s->count; ++i)
    {
      double m, inertia, vx, vy, spin, x, y;
      if (s->bodies[i].is_static)
        continue;
      carom_body_get_mass (r->world, r->ids[i], &m, &inertia, NULL);
      carom_body_get_velocity (r->world, r->ids[i], &vx, &vy);
      carom_body_get_spin (r->world, r->ids[i], &spin);
      carom_body_get_position (r->world, r->ids[i], &x, &y);
      e += bench_kinetic (m, inertia, vx, vy, spin) - m * (gx * x + gy * y);
    }
  return e;
}

static int asleep (const run *r, const bench_scene *s)
{
  int i, n = 0;
  for (i = 0; i < s->count; ++i)
    {
      int32_t awake = 1;
      if (!s->bodies[i].is_static && carom_body_is_awake (r->world, r->ids[i], &awake) == CAROM_OK && !awake)
        n++;
    }
  return n;
}

/* Dynamic bodies whose centre is outside the scene's container (or not
 * finite): thrown out or tunnelled. */
static int escaped (const run *r, const bench_scene *s)
{
  int i, n = 0;
  for (i = 0; i < s->count; ++i)
    {
      double x, y;
      if (s->bodies[i].is_static)
        continue;
      carom_body_get_position (r->world, r->ids[i], &x, &y);
      n += bench_outside (s, x, y) || !isfinite (x) || !isfinite (y);
    }
  return n;
}

/* Largest distance between a body here and the same body in `base`. */
static double deviation (const run *r, const run *base, const bench_scene *s)
{
  double worst = 0.0;
  int i;
  for (i = 0; i < s->count; ++i)
    {
      double x, y, bx, by, d;
      carom_body_get_position (r->world, r->ids[i], &x, &y);
      carom_body_get_position (base->world, base->ids[i], &bx, &by);
      d = hypot (x - bx, y - by);
      if (!(d <= worst))
        worst = d;
    }
  return worst;
}

static int compare_double (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return (x > y) - (x < y);
}

static double median (const double *v, int n)
{
  double tmp[MAX_REPEATS];
  memcpy (tmp, v, (size_t) n * sizeof *v);
  qsort (tmp, (size_t) n, sizeof *tmp, compare_double);
  return n % 2 ? tmp[n / 2] : 0.5 * (tmp[n / 2 - 1] + tmp[n / 2]);
}

static double smallest (const double *v, int n)
{
  double m = v[0];
  int i;
  for (i = 1; i < n; ++i)
    if (v[i] < m)
      m = v[i];
  return m;
}

/* "gravity,friction" or "none" */
static void effect_list (uint32_t bits, char *out, size_t cap)
{
  uint32_t bit;
  size_t len = 0;
  out[0] = '\0';
  for (bit = 1; bit <= CAROM_EFFECT_SLEEPING; bit <<= 1)
    if (bits & bit)
      len += (size_t) snprintf (out + len, len < cap ? cap - len : 0, "%s%s", len ? "," : "",
                                carom_effect_name ((carom_effect) bit));
  if (!out[0])
    snprintf (out, cap, "none");
}

static void print_head (const bench_scene *s, const run *r, const options *o)
{
  char eff[160];
  effect_list (carom_world_get_effects (r->world), eff, sizeof eff);
  printf ("scene=%s variant=%s kind=%s bodies=%d warmup=%d steps=%d effects=%s", s->name, r->v->name, r->v->kind,
          s->dynamic_count, o->warmup, o->steps, eff);
}

static int time_scene (const options *o, const char *name)
{
  bench_scene s;
  run *runs;
  int n = 0, i, k, q, rc = 0;
  double base_ms = 0.0;
  if (bench_scene_make (&s, name, strcmp (name, "gas") == 0 ? BENCH_GAS_BODIES : BENCH_PYRAMID_BODIES) < 0)
    return -1;
  runs = calloc (MAX_VARIANTS, sizeof *runs);
  if (!runs)
    return -1;
  for (i = 0; i < VARIANT_COUNT && n < MAX_VARIANTS; ++i)
    if (strcmp (variants[i].scene, name) == 0)
      runs[n++].v = &variants[i];
  /* each repeat: fresh worlds, the warm-up, then the timed steps in chunks,
   * every variant in turn, so that noise hits them alike; a repeat's figure
   * is its mean over all timed steps, as an instruction count is */
  for (k = 0; k < o->repeats && rc == 0; ++k)
    {
      double total[MAX_VARIANTS] = { 0.0 };
      for (i = 0; i < n && rc == 0; ++i)
        {
          release (&runs[i]);
          if (build (&runs[i], &s) < 0)
            return -1;
          runs[i].energy_start = energy (&runs[i], &s);
          rc = steps (runs[i].world, o->warmup);
        }
      for (q = 0; q * o->chunk < o->steps && rc == 0; ++q)
        {
          int m = o->steps - q * o->chunk < o->chunk ? o->steps - q * o->chunk : o->chunk;
          for (i = 0; i < n && rc == 0; ++i)
            {
              int j = (i + q + k) % n;
              double t0 = bench_now ();
              rc = steps (runs[j].world, m);
              total[j] += bench_now () - t0;
            }
        }
      for (i = 0; i < n; ++i)
        runs[i].ms[k] = 1e3 * total[i] / o->steps;
    }
  if (rc)
    {
      fprintf (stderr, "bench_effects: %s: update failed\n", name);
      return -1;
    }
  base_ms = median (runs[0].ms, o->repeats); /* the first variant is the baseline */
  for (i = 0; i < n; ++i)
    {
      run *r = &runs[i];
      double ms = median (r->ms, o->repeats), e = energy (r, &s);
      print_head (&s, r, o);
      printf (" ms_per_step=%.4f ratio=%.3f ms_min=%.4f contacts=%d asleep=%d escaped=%d energy_ratio=%.4g "
              "dev_from_off=%.3g",
              ms, ms / base_ms, smallest (r->ms, o->repeats), carom_world_contact_count (r->world), asleep (r, &s),
              escaped (r, &s), r->energy_start != 0.0 ? e / r->energy_start : 0.0, deviation (r, &runs[0], &s));
      printf (" ms_repeats=");
      for (k = 0; k < o->repeats; ++k)
        printf ("%s%.4f", k ? "," : "", r->ms[k]);
      printf ("\n");
    }
  fflush (stdout);
  for (i = 0; i < n; ++i)
    release (&runs[i]);
  free (runs);
  bench_scene_free (&s);
  return 0;
}

static int count_variant (const options *o)
{
  bench_scene s;
  run r;
  int i;
  memset (&r, 0, sizeof r);
  for (i = 0; i < VARIANT_COUNT; ++i)
    if ((strcmp (o->scene, "all") == 0 || strcmp (variants[i].scene, o->scene) == 0)
        && strcmp (variants[i].name, o->variant) == 0)
      break;
  if (i == VARIANT_COUNT)
    {
      fprintf (stderr, "bench_effects: no variant %s/%s (mode=list)\n", o->scene, o->variant);
      return -1;
    }
  r.v = &variants[i];
  if (bench_scene_make (&s, r.v->scene, strcmp (r.v->scene, "gas") == 0 ? BENCH_GAS_BODIES : BENCH_PYRAMID_BODIES)
      < 0)
    return -1;
  if (build (&r, &s) < 0 || steps (r.world, o->warmup) < 0 || measured_steps (r.world, o->steps) < 0)
    {
      fprintf (stderr, "bench_effects: %s/%s failed\n", r.v->scene, r.v->name);
      return -1;
    }
  print_head (&s, &r, o);
  printf (" contacts=%d asleep=%d escaped=%d\n", carom_world_contact_count (r.world), asleep (&r, &s),
          escaped (&r, &s));
  release (&r);
  bench_scene_free (&s);
  return 0;
}

int main (int argc, char **argv)
{
  options o;
  int i;
  if (parse (&o, argc, argv) < 0)
    {
      fprintf (stderr, "usage: %s [mode=time|count|list] [scene=gas|pyramid|all] [variant=NAME] [warmup=N] "
                       "[steps=N] [chunk=N] [repeats=N]\n", argv[0]);
      return 2;
    }
  if (strcmp (o.mode, "list") == 0)
    {
      for (i = 0; i < VARIANT_COUNT; ++i)
        if (strcmp (o.scene, "all") == 0 || strcmp (o.scene, variants[i].scene) == 0)
          printf ("scene=%s variant=%s kind=%s about=%s\n", variants[i].scene, variants[i].name, variants[i].kind,
                  variants[i].about);
      return 0;
    }
  if (strcmp (o.mode, "count") == 0)
    return count_variant (&o) < 0;
  if (strcmp (o.mode, "time") != 0)
    return 2;
  if (strcmp (o.scene, "all") == 0 || strcmp (o.scene, "gas") == 0)
    if (time_scene (&o, "gas") < 0)
      return 1;
  if (strcmp (o.scene, "all") == 0 || strcmp (o.scene, "pyramid") == 0)
    if (time_scene (&o, "pyramid") < 0)
      return 1;
  return 0;
}
