/* carom's accuracy against its knobs: every measure of accuracy_measures.c
 * for each setting of each knob of carom_world_def (substeps, iterations,
 * position_correction, slop, narrow_phase), of continuous collision and of dt,
 * one knob at a time
 * from the defaults, plus the presets fast and precise; and the reference
 * runs (pyramid and rain against a run at dt 1/120, 32 substeps,
 * 50 iterations). Prints "acc ..." lines (accuracy.h) for
 * bench/run-accuracy.sh.
 *
 * usage: accuracy [knobs=substeps,iterations,...] [measures=collision,gas,...]
 *                 [reference=0|1]
 * (knobs= and measures= keep to the settings and measures named, the
 * defaults always run; the reference runs are the measures ref_pyramid and
 * ref_rain.)
 * (ACC_DEBUG=1 in the environment prints the exact first contact of the
 * off-centre collision case.)
 * The defaults are read from carom_world_def_init, never restated here. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"
#include "carom.h"
#include "carom_scene.h"

/* ------------------------------------------------------------ engine */

typedef struct id_index {
  carom_body_id id;
  int index;
} id_index;

typedef struct carom_handle {
  carom_world *world;
  carom_body_id *ids; /* scene index -> id */
  id_index *map;      /* sorted by id */
  carom_joint_id *joints; /* scene joint index -> id */
  int count;
  double dt;
} carom_handle;

static int by_id (const void *a, const void *b)
{
  carom_body_id x = ((const id_index *) a)->id, y = ((const id_index *) b)->id;
  return x < y ? -1 : x > y;
}

static void carom_destroy (void *p)
{
  carom_handle *h = p;
  if (!h)
    return;
  carom_world_destroy (h->world);
  free (h->ids);
  free (h->map);
  free (h->joints);
  free (h);
}

static void *carom_create (const bench_scene *s, const acc_settings *set)
{
  carom_world_def def;
  carom_handle *h = calloc (1, sizeof *h);
  int i;
  if (!h)
    return NULL;
  h->ids = calloc ((size_t) s->count + 1, sizeof *h->ids);
  h->map = calloc ((size_t) s->count + 1, sizeof *h->map);
  h->joints = calloc ((size_t) s->joint_count + 1, sizeof *h->joints);
  h->count = s->count;
  h->dt = set->dt;
  bench_carom_def (&def, s);
  def.substeps = set->substeps;
  def.iterations = set->iterations;
  def.position_correction = set->position_correction;
  def.slop = set->slop;
  def.manifold_tolerance = set->manifold_tolerance;
  def.narrow_phase = set->narrow_phase ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
  if (!h->ids || !h->map || !h->joints || carom_world_init (&h->world, &def) != CAROM_OK
      || carom_world_set_continuous (h->world, set->continuous) != CAROM_OK)
    {
      carom_destroy (h);
      return NULL;
    }
  {
    int failed = 0;
    carom_status st = bench_carom_add_bodies (h->world, s, h->ids, &failed);
    if (st != CAROM_OK)
      {
        fprintf (stderr, "accuracy: body %d of %s: %s\n", failed, s->name, carom_status_string (st));
        carom_destroy (h);
        return NULL;
      }
    st = bench_carom_add_joints (h->world, s, h->ids, h->joints, &failed);
    if (st != CAROM_OK)
      {
        fprintf (stderr, "accuracy: joint %d of %s: %s\n", failed, s->name, carom_status_string (st));
        carom_destroy (h);
        return NULL;
      }
  }
  for (i = 0; i < s->count; ++i)
    h->map[i].id = h->ids[i], h->map[i].index = i;
  qsort (h->map, (size_t) s->count, sizeof *h->map, by_id);
  return h;
}

static int carom_step (void *p)
{
  carom_handle *h = p;
  return carom_world_update (h->world, h->dt) == CAROM_OK ? 0 : -1;
}

static void carom_state (void *p, int i, acc_state *o)
{
  carom_handle *h = p;
  carom_body_get_position (h->world, h->ids[i], &o->x, &o->y);
  carom_body_get_angle (h->world, h->ids[i], &o->angle);
  carom_body_get_velocity (h->world, h->ids[i], &o->vx, &o->vy);
  carom_body_get_spin (h->world, h->ids[i], &o->spin);
  carom_body_get_mass (h->world, h->ids[i], &o->mass, &o->inertia, NULL);
}

static int index_of (const carom_handle *h, carom_body_id id)
{
  id_index key, *hit;
  key.id = id;
  hit = bsearch (&key, h->map, (size_t) h->count, sizeof *h->map, by_id);
  return hit ? hit->index : -1;
}

static void carom_contacts (void *p, acc_contact_fn fn, void *user)
{
  carom_handle *h = p;
  int32_t i, n = carom_world_contact_count (h->world);
  for (i = 0; i < n; ++i)
    {
      carom_body_id a, b;
      double depth;
      if (carom_world_get_contact (h->world, i, &a, &b, NULL, NULL, NULL, NULL, &depth) == CAROM_OK)
        fn (user, index_of (h, a), index_of (h, b), depth);
    }
}

/* carom_joint_get_reaction: the force on b averaged over the last update. */
static void carom_joint_force (void *p, int joint, double *fx, double *fy)
{
  carom_handle *h = p;
  carom_joint_get_reaction (h->world, h->joints[joint], fx, fy, NULL);
}

static const acc_engine carom_engine = {
  "carom", "see knob and value", carom_create, carom_step, carom_state, carom_contacts, carom_destroy,
  carom_joint_force,
};

/* ------------------------------------------------------------ sweep */

static int settings_default (acc_settings *set)
{
  carom_world_def def;
  memset (set, 0, sizeof *set);
  carom_world *fresh = NULL;
  if (carom_world_def_init (&def, sizeof def) != CAROM_OK || carom_world_init (&fresh, &def) != CAROM_OK)
    return -1;
  /* continuous collision is an effect, not a def field: a fresh world has
     the library's default */
  set->continuous = (carom_world_get_effects (fresh) & CAROM_EFFECT_CONTINUOUS) != 0;
  carom_world_destroy (fresh);
  strcpy (set->knob, "default");
  strcpy (set->value, "balanced");
  set->substeps = def.substeps;
  set->iterations = def.iterations;
  set->position_correction = def.position_correction;
  set->slop = def.slop;
  set->manifold_tolerance = def.manifold_tolerance;
  set->narrow_phase = def.narrow_phase == CAROM_NARROW_VERTEX_EDGE;
  set->dt = 1.0 / 60.0;
  return 0;
}

#define N_MEASURES 32 /* room for acc_measures, then the 2 reference runs */

typedef struct sweep {
  acc_settings def;
  acc_result def_results[N_MEASURES];
  double *ref[2]; /* pyramid, rain; NULL: not run */
  const char *measures; /* measures=, NULL: all */
  int failures;
} sweep;

static const char *const ref_scenes[2] = { "pyramid", "rain" }, *const ref_measures[2] = { "ref_pyramid", "ref_rain" };

/* Run every measure for `set`; keep the results in `keep` (may be NULL). */
static void run_setting (sweep *w, const acc_settings *set, acc_result *keep)
{
  int i, n = 0;
  while (acc_measures[n].name)
    ++n;
  for (i = 0; i < n + 2; ++i)
    {
      acc_result r;
      int rc;
      if (i < n && acc_wanted (w->measures, acc_measures[i].name))
        rc = acc_measures[i].run (&carom_engine, set, &r);
      else if (i >= n && w->ref[i - n])
        rc = acc_reference (&carom_engine, set, ref_scenes[i - n], w->ref[i - n], &r);
      else
        continue;
      if (rc < 0)
        {
          r.ok = 0;
          w->failures++;
        }
      acc_print (&carom_engine, set, &r, NULL);
      if (keep)
        keep[i] = r;
    }
}

/* The default's lines again, labelled as one point of a knob's curve. */
static void repeat_default (const sweep *w, const acc_settings *set)
{
  int i;
  for (i = 0; i < N_MEASURES; ++i)
    if (w->def_results[i].measure)
      acc_print (&carom_engine, set, &w->def_results[i], "dup=1");
}

typedef enum knob_id { K_SUBSTEPS, K_ITERATIONS, K_CORRECTION, K_SLOP, K_MANIFOLD, K_NARROW, K_CONTINUOUS, K_DT } knob_id;

static void knob (sweep *w, const char *only, knob_id k, const char *name, const double *values, int n)
{
  int i;
  if (!acc_wanted (only, name))
    return;
  for (i = 0; i < n; ++i)
    {
      acc_settings set = w->def;
      int same;
      strcpy (set.knob, name);
      switch (k)
        {
        case K_SUBSTEPS:
          set.substeps = (int) values[i];
          snprintf (set.value, sizeof set.value, "%d", set.substeps);
          break;
        case K_ITERATIONS:
          set.iterations = (int) values[i];
          snprintf (set.value, sizeof set.value, "%d", set.iterations);
          break;
        case K_CORRECTION:
          set.position_correction = values[i];
          snprintf (set.value, sizeof set.value, "%g", values[i]);
          break;
        case K_SLOP:
          set.slop = values[i];
          snprintf (set.value, sizeof set.value, "%g", values[i]);
          break;
        case K_MANIFOLD:
          set.manifold_tolerance = values[i];
          snprintf (set.value, sizeof set.value, "%g", values[i]);
          break;
        case K_NARROW:
          set.narrow_phase = (int) values[i];
          strcpy (set.value, set.narrow_phase ? "vertex-edge" : "SAT");
          break;
        case K_CONTINUOUS:
          set.continuous = (int) values[i];
          strcpy (set.value, set.continuous ? "on" : "off");
          break;
        case K_DT:
          set.dt = 1.0 / values[i];
          snprintf (set.value, sizeof set.value, "1/%g", values[i]);
          break;
        }
      same = set.substeps == w->def.substeps && set.iterations == w->def.iterations
             && set.position_correction == w->def.position_correction && set.slop == w->def.slop
             && set.manifold_tolerance == w->def.manifold_tolerance
             && set.narrow_phase == w->def.narrow_phase && set.continuous == w->def.continuous
             && set.dt == w->def.dt;
      fprintf (stderr, "accuracy: %s=%s\n", set.knob, set.value);
      if (same)
        repeat_default (w, &set);
      else
        run_setting (w, &set, NULL);
    }
}

static void preset (sweep *w, const char *only, const char *name, int substeps, int iterations, int continuous)
{
  acc_settings set = w->def;
  if (!acc_wanted (only, "preset"))
    return;
  strcpy (set.knob, "preset");
  strcpy (set.value, name);
  set.substeps = substeps, set.iterations = iterations, set.continuous = continuous;
  fprintf (stderr, "accuracy: preset %s\n", name);
  run_setting (w, &set, NULL);
}

int main (int argc, char **argv)
{
  static const double substeps[] = { 1, 2, 4, 8, 16 }, iterations[] = { 1, 2, 4, 8 },
                      correction[] = { 0.05, 0.1, 0.2, 0.4, 0.8 }, slop[] = { 0.001, 0.005, 0.01, 0.02 },
                      manifold[] = { 0, 0.001, 0.01, 0.05, 0.2 },
                      narrow[] = { 0, 1 }, continuous[] = { 0, 1 }, rate[] = { 30, 60, 120, 240 };
  const char *only = NULL;
  sweep w;
  int i, with_reference = 1;
  memset (&w, 0, sizeof w);
  for (i = 1; i < argc; ++i)
    if (strncmp (argv[i], "knobs=", 6) == 0)
      only = argv[i] + 6;
    else if (strncmp (argv[i], "measures=", 9) == 0)
      w.measures = argv[i] + 9;
    else if (strncmp (argv[i], "reference=", 10) == 0)
      with_reference = atoi (argv[i] + 10);
    else
      {
        fprintf (stderr, "usage: %s [knobs=substeps,iterations,position_correction,slop,manifold_tolerance,narrow_phase,continuous,dt,preset] "
                         "[measures=collision,projectile,...,ref_pyramid,ref_rain] [reference=0|1]\n", argv[0]);
        return 2;
      }
  for (i = 0; acc_measures[i].name; ++i)
    ;
  if (i + 2 > N_MEASURES)
    {
      fprintf (stderr, "accuracy: %d measures: raise N_MEASURES\n", i);
      return 1;
    }
  if (settings_default (&w.def) < 0)
    {
      fprintf (stderr, "accuracy: carom_world_def_init failed\n");
      return 1;
    }
  printf ("defaults substeps=%d iterations=%d position_correction=%g slop=%g manifold_tolerance=%g narrow_phase=%s "
          "continuous=%s dt=1/60\n",
          w.def.substeps, w.def.iterations, w.def.position_correction, w.def.slop, w.def.manifold_tolerance,
          w.def.narrow_phase ? "vertex-edge" : "SAT", w.def.continuous ? "on" : "off");

  if (with_reference)
    {
      /* the reference, and a check of it: the same at half its resolution */
      acc_settings ref = w.def, half;
      strcpy (ref.knob, "reference");
      strcpy (ref.value, "32x50@1/120");
      ref.dt = 1.0 / 120.0, ref.substeps = 32, ref.iterations = 50, ref.manifold_tolerance = 0.0;
      half = ref;
      strcpy (half.value, "16x50@1/120");
      half.substeps = 16;
      for (i = 0; i < 2; ++i)
        {
          acc_result r;
          int count;
          if (!acc_wanted (w.measures, ref_measures[i]))
            continue;
          fprintf (stderr, "accuracy: reference %s\n", ref_scenes[i]);
          if (acc_trajectory (&carom_engine, &ref, ref_scenes[i], &w.ref[i], &count) < 0)
            {
              fprintf (stderr, "accuracy: the reference run of %s failed\n", ref_scenes[i]);
              return 1;
            }
          if (acc_reference (&carom_engine, &half, ref_scenes[i], w.ref[i], &r) < 0)
            w.failures++;
          acc_print (&carom_engine, &half, &r, NULL);
        }
    }

  fprintf (stderr, "accuracy: defaults\n");
  run_setting (&w, &w.def, w.def_results);
  knob (&w, only, K_SUBSTEPS, "substeps", substeps, 5);
  knob (&w, only, K_ITERATIONS, "iterations", iterations, 4);
  knob (&w, only, K_CORRECTION, "position_correction", correction, 5);
  knob (&w, only, K_SLOP, "slop", slop, 4);
  knob (&w, only, K_MANIFOLD, "manifold_tolerance", manifold, 5);
  knob (&w, only, K_NARROW, "narrow_phase", narrow, 2);
  knob (&w, only, K_CONTINUOUS, "continuous", continuous, 2);
  knob (&w, only, K_DT, "dt", rate, 4);
  preset (&w, only, "fast", 2, 1, 0);
  preset (&w, only, "precise", 8, 2, 1);
  free (w.ref[0]);
  free (w.ref[1]);
  if (w.failures)
    fprintf (stderr, "accuracy: %d measures failed\n", w.failures);
  return w.failures ? 1 : 0;
}
