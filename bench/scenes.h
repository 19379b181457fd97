/* The benchmark scenes as plain data, one generator for every engine.
 *
 * bench_scene_make fills a list of bodies (shape, size, pose, velocity,
 * static flag), a list of joints, and the world settings (gravity,
 * restitution, friction) of one of the four scenes. carom, Chipmunk and
 * Box2D benches all build their worlds from this data, so all engines start
 * from the same state. The
 * generator has its own PRNG with a fixed seed: the same name and body count
 * give the same scene on every machine and in every language binding.
 *
 *   pyramid  rows of 1 x 1 boxes on a static ground box; n = dynamic bodies,
 *            rounded down to a triangular number (210 = 20 rows).
 *            gravity -10, friction 0.6, restitution 0.
 *   rain     n mixed polygons (boxes, triangles, pentagons, hexagons, size
 *            0.5 to 1) on a jittered grid, falling into an open-top static
 *            container. gravity -10, friction 0.6, restitution 0.
 *   gas      n mixed polygons on a jittered grid (no overlap) with random
 *            velocities |v| <= 5 in a closed box of static walls.
 *            no gravity, restitution 1, friction 0.
 *   chains   n / 40 chains of 40 links (0.25 x 0.05 boxes, revolute joints
 *            at their ends; the first link's to a fixed point), each laid
 *            straight at 45 degrees below the horizontal and let go, on a
 *            grid 24 apart so that the chains (10 long) never meet: one
 *            joint per link. gravity -10, friction 0.6, restitution 0.
 */
#ifndef CAROM_BENCH_SCENES_H
#define CAROM_BENCH_SCENES_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum bench_shape {
  BENCH_BOX = 0,     /* w x h rectangle centred on its position */
  BENCH_REGULAR = 1, /* n sides of length `side`, one vertex on +x (local) */
  BENCH_CIRCLE = 2,  /* radius */
} bench_shape;

typedef struct bench_body {
  bench_shape shape;
  int sides;          /* BENCH_REGULAR: n */
  double w, h;        /* BENCH_BOX */
  double side;        /* BENCH_REGULAR: edge length */
  double radius;      /* BENCH_CIRCLE; for polygons the circumradius */
  double x, y, angle; /* pose of the centroid */
  double vx, vy, spin;
  int is_static;
} bench_body;

/* A revolute joint: bodies a and b (indices into the scene's bodies; a = -1
 * is the world, a fixed point) share the point (x, y), given in world
 * coordinates at the start. With enable_limit, b's angle less a's, less
 * that difference at the start, stays within [lower, upper]. Joined bodies
 * do not collide. */
typedef struct bench_joint {
  int a, b;
  double x, y;
  int enable_limit;
  double lower, upper;
} bench_joint;

typedef struct bench_scene {
  char name[16];
  double gravity_x, gravity_y;
  double restitution, friction;
  double density;      /* every dynamic body */
  bench_body *bodies;  /* statics first, then dynamics */
  int count;           /* all bodies */
  int dynamic_count;
  int top;             /* pyramid: index of the top box, else -1 */
  bench_joint *joints; /* NULL when there are none */
  int joint_count;
  /* container interior (rain, gas): a body whose centre ends outside it
   * escaped or tunnelled */
  double in_lo_x, in_lo_y, in_hi_x, in_hi_y;
} bench_scene;

/* Fill `scene` with scene `name` ("pyramid", "rain", "gas", "chains") of about `n`
 * dynamic bodies. Returns 0 on success, -1 for an unknown name, a bad count
 * or no memory. Free with bench_scene_free. */
int bench_scene_make (bench_scene *scene, const char *name, int n);
void bench_scene_free (bench_scene *scene);

/* Local vertices of a polygon body (box or regular), counter-clockwise, as
 * x0, y0, x1, y1, ...; `xy` holds 2 * max doubles. Returns the count, 0 for
 * a circle. */
int bench_body_vertices (const bench_body *b, double *xy, int max);
/* Area of the body's shape. */
double bench_body_area (const bench_body *b);
/* Inertia about the centroid per unit density. */
double bench_body_inertia (const bench_body *b);

/* Default body counts of the headline scenes. */
#define BENCH_PYRAMID_BODIES 210
#define BENCH_RAIN_BODIES 2000
#define BENCH_GAS_BODIES 500
#define BENCH_CHAINS_BODIES 1000
#define BENCH_CHAIN_LINKS 40

/* ---------------------------------------------------------- harness */

/* Command line of every engine's bench, as key=value words:
 *   scene=pyramid|rain|gas|chains  bodies=N  steps=N (timed)  warmup=N (untimed,
 *   before the timed steps)  substeps=N iterations=N (0: engine default)
 *   mode=time|mem|hash (mem: carom only, counts allocated bytes; hash: carom
 *   only, a hash of the end state)
 *   sleep=0|1 (engines that can put resting bodies to sleep; default 0)
 *   continuous=0|1 (carom only: continuous collision; default the library's) */
typedef struct bench_options {
  char scene[16];
  int bodies, steps, warmup;
  int substeps, iterations;
  int sleep;
  int continuous; /* -1: the library's default; 0 or 1: set */
  char mode[8];
} bench_options;

/* Parse argv into `o`; defaults: pyramid, the scene's default count, 540
 * timed steps after 60 warm-up steps (10 s at 1/60). Returns 0, or -1 after
 * printing a usage message to stderr. */
int bench_parse (bench_options *o, int argc, char **argv);

/* Every bench's start: parse argv into `o`, then make its scene in `s`;
 * prints what went wrong, naming `program`, and returns -1 on error. */
int bench_begin (bench_options *o, bench_scene *s, int argc, char **argv, const char *program);

/* Seconds on CLOCK_MONOTONIC. */
double bench_now (void);

/* What each bench measures at the end, printed by bench_report. */
typedef struct bench_result {
  const char *engine;
  const char *settings;     /* e.g. "substeps=1,iterations=8" */
  double seconds;           /* wall time of the timed steps only */
  double energy_start, energy_end; /* kinetic energy, dynamic bodies */
  double top_drift;         /* pyramid: |top box moved| / box size */
  int escaped;              /* bodies whose centre left the container */
  int contacts;             /* contact points at the end, -1 unknown */
  double joint_gap;         /* scenes with joints: bench_joint_gap at the end */
} bench_result;

/* Accumulate the kinetic energy of one body. */
double bench_kinetic (double mass, double inertia, double vx, double vy, double spin);
/* The mean distance between the joints' two anchors, the points of their
 * bodies that were at the joint at the start carried with the bodies to
 * their poses now (pose[3 i], pose[3 i + 1], pose[3 i + 2]: body i's x, y
 * and angle); the same for every engine. 0 without joints. */
double bench_joint_gap (const bench_scene *s, const double *pose);
/* 1 when (x, y) lies outside the scene's container interior. */
int bench_outside (const bench_scene *s, double x, double y);
/* Print one line: engine scene bodies steps ms_per_step energy_drift
 * top_drift escaped contacts settings (and joints=N joint_gap=G before
 * settings when the scene has joints). */
void bench_report (const bench_options *o, const bench_scene *s, const bench_result *r);

/* Small deterministic PRNG (splitmix64), for the benches' own use too. */
typedef struct bench_rng {
  unsigned long long state;
} bench_rng;
void bench_rng_seed (bench_rng *r, unsigned long long seed);
/* Uniform in [0, 1). */
double bench_rng_uniform (bench_rng *r);
/* Uniform in [lo, hi). */
double bench_rng_range (bench_rng *r, double lo, double hi);

#ifdef __cplusplus
}
#endif

#endif
