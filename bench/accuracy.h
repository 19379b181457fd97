/* What accuracy costs in time: the measures, written once for every engine.
 *
 * Each engine (carom in bench/accuracy.c, Chipmunk 7 in
 * bench/peers/accuracy_chipmunk.c, Box2D 2.4 in bench/peers/accuracy_box2d.cpp
 * and Box2D v3 in bench/peers/accuracy_box2d3.c) supplies an acc_engine:
 * build a world from a bench_scene (bench/scenes.h, the one generator every
 * bench uses: its bodies and its revolute joints), step it, read a body's
 * state, list the contact points, read a joint's force. The measures
 * (bench/accuracy_measures.c) only use that table, so every engine is
 * measured by the same code on the same scenes. Where a joint's anchors
 * are is computed by the measures from the bodies' states (the points of
 * the bodies that were at the joint at the start), the same way for every
 * engine.
 *
 * Output: one line per measure and setting, key=value words, read by
 * bench/run-accuracy.sh:
 *   acc engine=E knob=K value=V measure=M ms_step=T ms_frame=F key=value...
 * ms_step is the wall time of one step call (the step calls only); ms_frame
 * is the wall time per 1/60 s of simulated time (ms_step * (1/60) / dt), the
 * fair cost when dt changes. Errors are relative to body size where a length
 * is involved: a body's size is its side (box), its circumscribed diameter
 * (regular polygon) or its diameter (circle). */
#ifndef CAROM_BENCH_ACCURACY_H
#define CAROM_BENCH_ACCURACY_H

#include "scenes.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The settings of one run. Peers use only dt and keep their usual settings. */
typedef struct acc_settings {
  char knob[32];   /* "default", "substeps", ... "preset", "peer" */
  char value[16];  /* as printed */
  int substeps, iterations;
  double position_correction, slop;
  double manifold_tolerance; /* carom_world_def.manifold_tolerance */
  int narrow_phase; /* 0: SAT, 1: vertex-edge (carom's enum values) */
  int continuous;   /* carom_world_set_continuous (on by default) */
  double dt;
} acc_settings;

typedef struct acc_state {
  double x, y, angle, vx, vy, spin, mass, inertia;
} acc_state;

/* One contact point between scene bodies a and b (indices into the scene's
 * bodies; -1 if unknown), depth > 0 when overlapping. */
typedef void (*acc_contact_fn) (void *user, int a, int b, double depth);

typedef struct acc_engine {
  const char *name;
  const char *settings; /* the engine's own settings, for the doc */
  /* Build a world from `s` (all of s->bodies, statics included, then
   * s->joints in their order). NULL on failure. */
  void *(*create) (const bench_scene *s, const acc_settings *set);
  /* One step of set->dt; 0 on success. */
  int (*step) (void *world);
  void (*state) (void *world, int body, acc_state *out);
  /* Call fn for each touching contact point found by the last step. */
  void (*contacts) (void *world, acc_contact_fn fn, void *user);
  void (*destroy) (void *world);
  /* The force joint `joint` (an index into s->joints) gave its body b in
   * the last step (its impulse over the step, in the world frame; the
   * measures use its magnitude). */
  void (*joint_force) (void *world, int joint, double *fx, double *fy);
} acc_engine;

/* The results of one measure: up to ACC_MAX_KEYS named numbers. */
#define ACC_MAX_KEYS 8
typedef struct acc_result {
  const char *measure;
  double ms_step, ms_frame;
  int nkeys;
  const char *keys[ACC_MAX_KEYS];
  double values[ACC_MAX_KEYS];
  int ok; /* 0 when the engine failed (the line says failed=1) */
} acc_result;

/* The measures. Each fills `r` and returns 0, or -1 when the run failed. */
int acc_collision (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_projectile (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_bounce (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_gas (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_momentum (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_pyramid (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_rain (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_tunnel (const acc_engine *e, const acc_settings *set, acc_result *r);
/* An inelastic box dropped on a column of boxes at rest: how fast anything
 * rises (it should not). */
int acc_drop (const acc_engine *e, const acc_settings *set, acc_result *r);
/* A fast-spinning bar striking a wall with one corner, against eq. 3.23. */
int acc_spin_bar (const acc_engine *e, const acc_settings *set, acc_result *r);
/* Bodies sliding over a floor of touching static tiles: speed kept, no hop. */
int acc_seams (const acc_engine *e, const acc_settings *set, acc_result *r);
/* Newton's cradle: rows of equal touching balls struck at one end. */
int acc_cradle (const acc_engine *e, const acc_settings *set, acc_result *r);
/* Joints (revolute, each engine's defaults): a pendulum's period, a double
 * pendulum's energy, a heavy chain's stretch, a hanging body's reaction, a
 * limit's overshoot. */
int acc_pendulum (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_double_pendulum (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_chain (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_hanging (const acc_engine *e, const acc_settings *set, acc_result *r);
int acc_limit (const acc_engine *e, const acc_settings *set, acc_result *r);

/* Reference runs: body positions of `scene` ("pyramid" or "rain") at
 * ACC_SAMPLES equally spaced times up to ACC_REFERENCE_SECONDS, as x, y per
 * dynamic body per sample (ACC_SAMPLES * 2 * dynamic bodies doubles, malloc'd
 * into *out). acc_reference_error compares a run with such a reference: the
 * RMS over bodies and samples of |position - reference| / body size. */
#define ACC_SAMPLES 4
#define ACC_REFERENCE_SECONDS 2.0
int acc_trajectory (const acc_engine *e, const acc_settings *set, const char *scene, double **out, int *count);
int acc_reference (const acc_engine *e, const acc_settings *set, const char *scene, const double *ref,
                   acc_result *r);

/* Scene sizes used by the measures (the steps are capped so that the whole
 * sweep runs in minutes; docs/accuracy.md states them). */
#define ACC_GAS_BODIES 500
#define ACC_GAS_SECONDS (2000.0 / 60.0)
#define ACC_PYRAMID_BODIES 210
#define ACC_PYRAMID_SECONDS 10.0
#define ACC_RAIN_BODIES 500
#define ACC_RAIN_SECONDS 5.0
#define ACC_MOMENTUM_BODIES 200
#define ACC_MOMENTUM_SECONDS 5.0
#define ACC_PENDULUM_SECONDS 40.0
#define ACC_DOUBLE_PENDULUM_SECONDS 10.0
#define ACC_CHAIN_LINKS 40
#define ACC_CHAIN_REST_SECONDS 5.0
#define ACC_CHAIN_SWING_SECONDS 8.0
#define ACC_HANGING_SECONDS 2.0
#define ACC_LIMIT_SECONDS 3.0
#define ACC_DROP_SECONDS 4.0
#define ACC_DROP_HEIGHT 1.0
#define ACC_SPIN_BAR_SECONDS 1.0
#define ACC_SEAM_TILES 40
#define ACC_CRADLE_SECONDS 1.0

/* The size of a body, as above. */
double acc_body_size (const bench_body *b);
/* Print r as one "acc ..." line; `extra` (may be NULL) is appended. */
void acc_print (const acc_engine *e, const acc_settings *set, const acc_result *r, const char *extra);
/* The measures by name ("collision", ... as their lines' measure=), every
 * one above except the reference runs, ended by a NULL name. */
typedef struct acc_measure {
  const char *name;
  int (*run) (const acc_engine *e, const acc_settings *set, acc_result *r);
} acc_measure;
extern const acc_measure acc_measures[];
/* 1 when `name` is one of the comma-separated `list` (NULL: all). */
int acc_wanted (const char *list, const char *name);
/* Run the measures named in `only` (comma-separated; NULL: every one) and
 * print their lines. */
int acc_run_all (const acc_engine *e, const acc_settings *set, const char *only);

#ifdef __cplusplus
}
#endif

#endif
