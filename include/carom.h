/*
 * carom: a 2D rigid-body physics library in C99 with a stable C ABI.
 *
 * Conventions: double precision everywhere, radians, counter-clockwise
 * positive angles, y up. SI units are suggested, never assumed.
 *
 * Every fallible call returns a carom_status (CAROM_OK = 0) and changes
 * nothing when it fails. Bodies are named by carom_body_id values: a removed
 * body's id is detected as stale (CAROM_ERR_STALE_BODY), never dereferenced.
 *
 * Structs that cross the ABI start with a `size` field and only ever grow by
 * appending fields. Callers fill them with the matching *_def_init, passing
 * the size they were compiled with (`carom_world_def_init (&def, sizeof def)`):
 * a program built against an older header keeps working with a newer
 * library, which uses defaults for the fields the program does not know.
 * Enums are 32-bit (each has a 0x7fffffff member to pin its size).
 */
#ifndef CAROM_H
#define CAROM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && defined(CAROM_BUILD_SHARED)
#define CAROM_API __declspec(dllexport)
#elif defined(__GNUC__) || defined(__clang__)
#define CAROM_API __attribute__((visibility("default")))
#else
#define CAROM_API
#endif

/* ---------------------------------------------------------------- version */

#define CAROM_VERSION_MAJOR 0
#define CAROM_VERSION_MINOR 2
#define CAROM_VERSION_PATCH 0
/** MAJOR * 10000 + MINOR * 100 + PATCH of the headers compiled against. */
#define CAROM_VERSION                                                          \
  (CAROM_VERSION_MAJOR * 10000 + CAROM_VERSION_MINOR * 100 + CAROM_VERSION_PATCH)

/** The version of the library linked at run time, encoded as CAROM_VERSION. */
CAROM_API uint32_t carom_version (void);

/* ----------------------------------------------------------------- status */

/** Result of every fallible call. Values are stable: new ones are appended. */
typedef enum carom_status {
  CAROM_OK = 0,
  CAROM_ERR_NULL_ARGUMENT = 1,      /**< a required pointer was NULL */
  CAROM_ERR_NOT_FINITE = 2,         /**< a number was NaN or infinite */
  CAROM_ERR_BAD_SIZE = 3,           /**< a size or radius was zero or negative */
  CAROM_ERR_BAD_DENSITY = 4,        /**< density zero or negative, or a mass out of range */
  CAROM_ERR_TOO_FEW_VERTICES = 5,   /**< a polygon needs at least 3 vertices */
  CAROM_ERR_TOO_MANY_VERTICES = 6,  /**< more than CAROM_MAX_POLYGON_VERTICES */
  CAROM_ERR_REPEATED_VERTEX = 7,    /**< two consecutive vertices coincide */
  CAROM_ERR_SELF_INTERSECTING = 8,  /**< polygon edges cross each other */
  CAROM_ERR_ZERO_AREA = 9,          /**< polygon (nearly) without area */
  CAROM_ERR_BAD_TIME_STEP = 10,     /**< dt was zero, negative, NaN or inf */
  CAROM_ERR_STALE_BODY = 11,        /**< body id is unknown or was removed */
  CAROM_ERR_OUT_OF_MEMORY = 12,     /**< an allocation failed */
  CAROM_ERR_BAD_ARGUMENT = 13,      /**< a value outside its documented range */
  CAROM_ERR_BAD_STRUCT_SIZE = 14,   /**< a def's size field is not one we know */
  CAROM_ERR_TOO_MANY_BODIES = 15,   /**< the world holds CAROM_MAX_BODIES */
  CAROM_ERR_STATIC_BODY = 16,       /**< the call needs a dynamic body */
  CAROM_ERR_SCENE_SYNTAX = 17,      /**< a scene file line is malformed */
  CAROM_ERR_IO = 18,                /**< a file could not be read */
  CAROM_ERR_STALE_JOINT = 19,       /**< joint id is unknown or was removed
                                         (version 0.2) */
  CAROM_STATUS_FORCE_32 = 0x7fffffff
} carom_status;

/** A short English sentence for a status; never NULL, also for unknown codes. */
CAROM_API const char *carom_status_string (carom_status status);

/* ----------------------------------------------------------------- limits */

/** Largest vertex count accepted for one polygon. */
#define CAROM_MAX_POLYGON_VERTICES 1024
/** Most shapes in one compound body (version 0.2). */
#define CAROM_MAX_COMPOUND_SHAPES 256
/** Largest magnitude accepted for coordinates, angles, velocities, spins,
 * accelerations and rates (BAD_ARGUMENT beyond), so that the products the
 * solver forms stay within doubles. Time steps lie in [1e-100, 1e100]. */
#define CAROM_MAX_MAGNITUDE 1e100
/** Largest number of live bodies in one world (ids carry a 24-bit index). */
#define CAROM_MAX_BODIES (1 << 24)

/* -------------------------------------------------------------- allocator */

/**
 * Optional allocator. `alloc` returns NULL on failure; `free` takes what
 * `alloc` returned (and the size that was asked for). Both get `user`.
 */
typedef struct carom_allocator {
  void *(*alloc) (size_t size, void *user);
  void (*free) (void *ptr, size_t size, void *user);
  void *user;
} carom_allocator;

/* ------------------------------------------------------------------ world */

/** A body's id: a slot index and a generation. 0 is never a valid id. */
typedef uint64_t carom_body_id;
#define CAROM_NULL_BODY ((carom_body_id)0)

/** An opaque simulation world. All its memory is freed by destroy. */
typedef struct carom_world carom_world;

/** Narrow-phase method for pairs of convex polygons. */
typedef enum carom_narrow_phase {
  /** Separating axis theorem with clipped contact points (thesis 3.2.1). */
  CAROM_NARROW_SAT = 0,
  /** The thesis' vertex-edge method on the true outline (thesis 3.2.2). */
  CAROM_NARROW_VERTEX_EDGE = 1,
  CAROM_NARROW_FORCE_32 = 0x7fffffff
} carom_narrow_phase;

/**
 * World settings. Fill with carom_world_def_init, then change fields.
 * substeps, iterations, position_correction, slop and narrow_phase are the
 * knobs that trade time for accuracy; docs/accuracy.md measures what each
 * one costs and what error it removes (more substeps help almost every
 * error; more iterations help stacks; the other three help overlap).
 * Contacts are found once per update; the sub-steps solve them again and
 * again as the bodies move, which is what holds stacks at the defaults.
 */
typedef struct carom_world_def {
  uint32_t size;           /**< the caller's sizeof, set by def_init */
  double gravity_x;        /**< uniform gravity, default (0, 0) */
  double gravity_y;
  double restitution;      /**< default e for bodies, in [0, 1]; default 0 */
  double friction;         /**< default Coulomb mu, >= 0; default 0 */
  int32_t substeps;        /**< sub-steps per update, >= 1; default 4 */
  int32_t iterations;      /**< solver passes per sub-step (each a solve
                                and a relax pass), >= 1; default 1 */
  double position_correction; /**< fraction of the overlap beyond the slop
                                   removed per sub-step, in [0, 1];
                                   default 0.2 */
  double slop;             /**< overlap allowed before correction, as a
                                fraction of the smaller body's size (twice
                                its area over its perimeter); default 0.01 */
  carom_narrow_phase narrow_phase; /**< convex polygon method; default SAT */
  carom_allocator allocator; /**< alloc == NULL means malloc/free */
  /* ---- version 0.2 */
  double manifold_tolerance; /**< a pair of convex polygons keeps last
                                  step's contact points (moved with the
                                  bodies) while its relative pose stays
                                  within this fraction of the smaller
                                  body's size and this many radians of
                                  where they were last computed (SAT only);
                                  0 recomputes every step; in [0, 1];
                                  default 0.01 */
} carom_world_def;

/**
 * Fill `def` with the defaults above and set its size field to `size`, the
 * caller's sizeof (carom_world_def); writes no byte past `size`. Errors:
 * NULL_ARGUMENT, BAD_STRUCT_SIZE (not the size of the struct in a released
 * version of this header: 0.1's, without manifold_tolerance, or this one's).
 */
CAROM_API carom_status carom_world_def_init (carom_world_def *def,
                                             uint32_t size);

/**
 * Create a world. `def` may be NULL for the defaults.
 * Errors: NULL_ARGUMENT (world), BAD_STRUCT_SIZE, NOT_FINITE, BAD_ARGUMENT,
 * OUT_OF_MEMORY. On error *world is set to NULL.
 */
CAROM_API carom_status carom_world_init (carom_world **world,
                                         const carom_world_def *def);

/** Destroy a world and every body in it. Safe on NULL. */
CAROM_API void carom_world_destroy (carom_world *world);

/**
 * Advance the world by `dt` (time units, 1e-100 <= dt <= 1e100): collision
 * detection once, then forces, collision resolution and integration in
 * `substeps` sub-steps. Errors: NULL_ARGUMENT, BAD_TIME_STEP, BAD_ARGUMENT
 * (the forces applied would change a velocity by more than
 * CAROM_MAX_MAGNITUDE: carom_world_clear_forces) and OUT_OF_MEMORY change
 * nothing (memory is only asked for before the first
 * sub-step); after OUT_OF_MEMORY the world is valid and usable, and the
 * same update, repeated, gives what it would have given.
 */
CAROM_API carom_status carom_world_update (carom_world *world, double dt);

/** Set uniform gravity. Errors: NULL_ARGUMENT, NOT_FINITE. */
CAROM_API carom_status carom_world_set_gravity (carom_world *world, double gx,
                                                double gy);
/** Read uniform gravity. */
CAROM_API carom_status carom_world_get_gravity (const carom_world *world,
                                                double *gx, double *gy);

/** Number of live bodies (0 for NULL). */
CAROM_API int32_t carom_world_body_count (const carom_world *world);

/**
 * Ids of the live bodies in creation order: writes up to `capacity` ids and
 * returns how many bodies there are (call with capacity 0 to size a buffer).
 */
CAROM_API int32_t carom_world_get_bodies (const carom_world *world,
                                          carom_body_id *ids, int32_t capacity);

/* --------------------------------------------------------------- contacts */

/**
 * Run collision detection alone on the current positions (no resolution, no
 * motion), replacing the contacts that carom_world_update left. Errors:
 * NULL_ARGUMENT, OUT_OF_MEMORY.
 */
CAROM_API carom_status carom_world_detect (carom_world *world);

/** Number of contact points found by the last update or detect. */
CAROM_API int32_t carom_world_contact_count (const carom_world *world);

/**
 * Contact point `index` (0 <= index < count): the two bodies, the impact
 * point, the unit normal pointing from body a to body b, and the penetration
 * depth (negative when the bodies are apart but within the contact margin),
 * as found at the start of the update, or, for a point an impact moved
 * within the update, at the touch (with continuous collision).
 * NULL outputs are skipped. Errors: NULL_ARGUMENT, BAD_ARGUMENT (index).
 */
CAROM_API carom_status carom_world_get_contact (const carom_world *world,
                                                int32_t index, carom_body_id *a,
                                                carom_body_id *b, double *px,
                                                double *py, double *nx,
                                                double *ny, double *depth);

/* ----------------------------------------------------------------- bodies */

typedef enum carom_body_type {
  CAROM_DYNAMIC = 0, /**< moves under gravity, contacts, forces and impulses */
  CAROM_STATIC = 1,  /**< never moves: infinite mass (zero inverse mass) */
  /** moves at the velocity and spin it is given, whatever touches it:
   * infinite mass (pushes dynamic bodies, is never pushed), no gravity, no
   * forces; never sleeps (version 0.2) */
  CAROM_KINEMATIC = 2,
  CAROM_BODY_TYPE_FORCE_32 = 0x7fffffff
} carom_body_type;

/** Shape kinds, as reported by carom_body_get_shape. */
typedef enum carom_shape_kind {
  CAROM_SHAPE_CIRCLE = 0,
  CAROM_SHAPE_POLYGON = 1, /**< boxes and regular polygons are polygons too */
  /** a body of several circles and polygons (carom_world_add_compound;
   * version 0.2) */
  CAROM_SHAPE_COMPOUND = 2,
  CAROM_SHAPE_KIND_FORCE_32 = 0x7fffffff
} carom_shape_kind;

/** Body settings. Fill with carom_body_def_init, then change fields. */
typedef struct carom_body_def {
  uint32_t size;        /**< the caller's sizeof, set by def_init */
  carom_body_type type; /**< default CAROM_DYNAMIC */
  double x, y;          /**< position of the centre of mass; default 0 */
  double angle;         /**< radians, counter-clockwise; default 0 */
  double vx, vy;        /**< linear velocity; default 0 */
  double spin;          /**< angular velocity, rad per time unit; default 0 */
  double density;       /**< mass per unit area, > 0; default 1 */
  double restitution;   /**< e in [0, 1], or < 0 for the world default */
  double friction;      /**< mu >= 0, or < 0 for the world default */
  /* ---- version 0.2 */
  void *user_data;      /**< the caller's, returned by
                             carom_body_get_user_data; default NULL */
  uint32_t category;    /**< collision filtering: the body's category bits;
                             default 1 */
  uint32_t mask;        /**< the categories it collides with; default all
                             bits. Bodies a and b collide when
                             (a.category & b.mask) && (b.category & a.mask) */
  int32_t group;        /**< non-zero: two bodies of the same group always
                             collide (> 0) or never (< 0), whatever their
                             bits; default 0 */
  int32_t sensor;       /**< non-zero: the body reports what overlaps it as
                             CAROM_EVENT_SENSOR_* events and neither pushes
                             nor is pushed by anything; default 0 */
} carom_body_def;

/** Fill `def` with the defaults above, as carom_world_def_init does (0.1's
 * size, without the version 0.2 fields, is accepted too). */
CAROM_API carom_status carom_body_def_init (carom_body_def *def,
                                            uint32_t size);

/**
 * Add a circle of radius `radius` centred on (def->x, def->y). Inertia
 * m r^2 / 2. Sizes (radius, width, height, side, polygon extent) must lie
 * between 1e-60 and 1e60 length units, a dynamic body's mass between
 * 1e-200 and 1e200 and its inertia between 1e-300 and the largest double
 * (BAD_SIZE, or BAD_DENSITY when the density is what makes them leave that
 * range). `def` may be NULL for the defaults. On success *id names the new
 * body (id may be NULL). Errors: NULL_ARGUMENT, BAD_STRUCT_SIZE, NOT_FINITE,
 * BAD_SIZE, BAD_DENSITY, BAD_ARGUMENT, TOO_MANY_BODIES, OUT_OF_MEMORY.
 */
CAROM_API carom_status carom_world_add_circle (carom_world *world,
                                               const carom_body_def *def,
                                               double radius,
                                               carom_body_id *id);

/** Add a `width` x `height` box; inertia m (w^2 + h^2) / 12 (eq. 3.4).
 * BAD_SIZE also for a plate thinner than 1e-10 of its length. */
CAROM_API carom_status carom_world_add_box (carom_world *world,
                                            const carom_body_def *def,
                                            double width, double height,
                                            carom_body_id *id);

/**
 * Add a regular polygon with `n` sides of length `side`, one vertex on the
 * +x axis before rotation; inertia m l^2 / 24 (1 + 3 cot^2(pi/n)) (eq. 3.6).
 * Errors as carom_world_add_circle, plus TOO_FEW_VERTICES (n < 3) and
 * TOO_MANY_VERTICES.
 */
CAROM_API carom_status carom_world_add_regular (carom_world *world,
                                                const carom_body_def *def,
                                                int32_t n, double side,
                                                carom_body_id *id);

/**
 * Add a simple polygon, convex or concave, from `count` vertices given as
 * x0, y0, x1, y1, ... in either winding. The vertices are copied and
 * re-expressed about the polygon's centroid, which is placed at
 * (def->x, def->y); inertia by signed sub-triangles (eq. 3.13, 3.14).
 * Errors as carom_world_add_regular, plus REPEATED_VERTEX, ZERO_AREA (also
 * for an extent under 1e-60), BAD_SIZE (an extent over 1e60) and
 * SELF_INTERSECTING.
 */
CAROM_API carom_status carom_world_add_polygon (carom_world *world,
                                                const carom_body_def *def,
                                                const double *xy,
                                                int32_t count,
                                                carom_body_id *id);

/**
 * One shape of a compound body (version 0.2). Fill with
 * carom_shape_def_init, then change fields.
 */
typedef struct carom_shape_def {
  uint32_t size;          /**< the caller's sizeof, set by def_init */
  carom_shape_kind kind;  /**< CAROM_SHAPE_CIRCLE (default) or
                               CAROM_SHAPE_POLYGON */
  double x, y;            /**< where it sits in the body's coordinates: a
                               circle's centre; a polygon's vertices are
                               turned by `angle`, then moved by (x, y);
                               default 0 */
  double angle;           /**< radians; default 0 */
  double radius;          /**< a circle's; default 0 (must be set) */
  const double *xy;       /**< a polygon's vertices, x0, y0, x1, y1, ...,
                               either winding, convex or concave (read
                               during the call only); default NULL */
  int32_t count;          /**< how many vertices; default 0 */
  double density;         /**< mass per unit area, > 0, or < 0 for the
                               body def's; default -1 */
  double restitution;     /**< e in [0, 1], or < 0 for the body's; default
                               -1 */
  double friction;        /**< mu >= 0, or < 0 for the body's; default -1 */
} carom_shape_def;

/** Fill `def` with the defaults above. Errors: NULL_ARGUMENT,
 * BAD_STRUCT_SIZE. */
CAROM_API carom_status carom_shape_def_init (carom_shape_def *def,
                                             uint32_t size);

/**
 * Add a body made of `count` shapes (1 to CAROM_MAX_COMPOUND_SHAPES), any
 * mix of circles and polygons (concave ones too), each with its own density
 * and material (version 0.2). The shapes are given in body coordinates;
 * the centre of mass of their union is placed at (def->x, def->y) and the
 * body turned by def->angle about it. Mass is the sum of the shapes'
 * masses, inertia the sum of their inertias moved to the centre of mass by
 * the parallel axis theorem (so shapes that overlap count their common
 * area once for each). A contact between two shapes takes their materials;
 * carom_body_get_material reports the body def's. Compounds collide by the
 * SAT narrow phase whatever the world's narrow_phase. Errors as
 * carom_world_add_polygon and carom_world_add_circle for each shape (each
 * shape's size and vertex checks), plus NULL_ARGUMENT (shapes, or a
 * polygon's xy), BAD_STRUCT_SIZE (a shape's size), BAD_ARGUMENT (count out
 * of range, a kind not circle or polygon, a restitution over 1).
 */
CAROM_API carom_status carom_world_add_compound (carom_world *world,
                                                 const carom_body_def *def,
                                                 const carom_shape_def *shapes,
                                                 int32_t count,
                                                 carom_body_id *id);

/** Remove a body; its id becomes stale. What it touched wakes, and its
 * weight comes off the impulses of the contacts beneath it, which the next
 * update starts from (docs/physics.md). Errors: NULL_ARGUMENT, STALE_BODY. */
CAROM_API carom_status carom_world_remove_body (carom_world *world,
                                                carom_body_id id);

/** CAROM_OK if `id` names a live body of `world`, else STALE_BODY. */
CAROM_API carom_status carom_body_check (const carom_world *world,
                                         carom_body_id id);

/* Body state. Getters write through non-NULL pointers (a NULL output is
 * skipped); all return NULL_ARGUMENT for a NULL world, STALE_BODY for a bad
 * id, and setters NOT_FINITE for a non-finite value. Setting the position or
 * velocity of a static body returns STATIC_BODY except for the position. */
CAROM_API carom_status carom_body_get_position (const carom_world *world,
                                                carom_body_id id, double *x,
                                                double *y);
CAROM_API carom_status carom_body_set_position (carom_world *world,
                                                carom_body_id id, double x,
                                                double y);
CAROM_API carom_status carom_body_get_angle (const carom_world *world,
                                             carom_body_id id, double *angle);
CAROM_API carom_status carom_body_set_angle (carom_world *world,
                                             carom_body_id id, double angle);
CAROM_API carom_status carom_body_get_velocity (const carom_world *world,
                                                carom_body_id id, double *vx,
                                                double *vy);
CAROM_API carom_status carom_body_set_velocity (carom_world *world,
                                                carom_body_id id, double vx,
                                                double vy);
CAROM_API carom_status carom_body_get_spin (const carom_world *world,
                                            carom_body_id id, double *spin);
CAROM_API carom_status carom_body_set_spin (carom_world *world,
                                            carom_body_id id, double spin);

/** Mass (0 for static bodies), inertia about the centre of mass (0 for
 * static bodies), and area. */
CAROM_API carom_status carom_body_get_mass (const carom_world *world,
                                            carom_body_id id, double *mass,
                                            double *inertia, double *area);
CAROM_API carom_status carom_body_get_type (const carom_world *world,
                                            carom_body_id id,
                                            carom_body_type *type);
CAROM_API carom_status carom_body_get_shape (const carom_world *world,
                                             carom_body_id id,
                                             carom_shape_kind *kind,
                                             double *radius);
/** Restitution and friction in effect for the body (after world defaults). */
CAROM_API carom_status carom_body_get_material (const carom_world *world,
                                                carom_body_id id,
                                                double *restitution,
                                                double *friction);

/**
 * The polygon's vertices in world coordinates, counter-clockwise: writes up to
 * `capacity` points as x0, y0, x1, y1, ... into `xy` (2 * capacity doubles)
 * and the vertex count into *count (0 for a circle and for a compound,
 * whose shapes carom_body_get_shape_geometry gives one by one).
 */
CAROM_API carom_status carom_body_get_vertices (const carom_world *world,
                                                carom_body_id id, double *xy,
                                                int32_t capacity,
                                                int32_t *count);

/**
 * The shapes a body is made of (version 0.2): 1 for a circle or polygon
 * body, the number of shapes of a compound. Errors: NULL_ARGUMENT,
 * STALE_BODY.
 */
CAROM_API carom_status carom_body_get_shape_count (const carom_world *world,
                                                   carom_body_id id,
                                                   int32_t *count);

/**
 * Shape `index` (0 <= index < carom_body_get_shape_count) of a body, in
 * world coordinates: its kind (circle or polygon), its centroid (a
 * circle's centre), its radius (a polygon's: the farthest vertex from its
 * centroid), and a polygon's vertices counter-clockwise as
 * carom_body_get_vertices writes them (up to `capacity` points; *count is
 * the vertex count, 0 for a circle). NULL outputs are skipped. Errors:
 * NULL_ARGUMENT, STALE_BODY, BAD_ARGUMENT (index; capacity < 0).
 */
CAROM_API carom_status carom_body_get_shape_geometry (
    const carom_world *world, carom_body_id id, int32_t index,
    carom_shape_kind *kind, double *x, double *y, double *radius, double *xy,
    int32_t capacity, int32_t *count);

/**
 * Shape `index`'s density and the restitution and friction its contacts
 * use (the body's where the shape gave none, after world defaults). A
 * static body's shapes report the density they were given. Errors as
 * carom_body_get_shape_geometry.
 */
CAROM_API carom_status carom_body_get_shape_material (
    const carom_world *world, carom_body_id id, int32_t index,
    double *density, double *restitution, double *friction);

/* ----------------------------------------------- forces, data, filtering */

/**
 * Forces (version 0.2). A force (fx, fy) at the world point (px, py), and a
 * torque, act on a dynamic body over the next carom_world_update (each
 * sub-step's velocity change is F h / m, and (p - c) x F h / I, c the centre
 * of mass) and are then cleared; calls add up. Wakes the body. Errors:
 * NULL_ARGUMENT, STALE_BODY, NOT_FINITE, BAD_ARGUMENT (a magnitude over
 * CAROM_MAX_MAGNITUDE), STATIC_BODY (static and kinematic bodies take no
 * forces).
 */
CAROM_API carom_status carom_body_apply_force (carom_world *world,
                                               carom_body_id id, double fx,
                                               double fy, double px,
                                               double py);
CAROM_API carom_status carom_body_apply_torque (carom_world *world,
                                                carom_body_id id,
                                                double torque);
/** Drop every force and torque not yet applied (as an update does after
 * applying them). carom_world_update refuses, with BAD_ARGUMENT, forces
 * that would change a velocity by more than CAROM_MAX_MAGNITUDE over its
 * dt; this is the way out. Errors: NULL_ARGUMENT. */
CAROM_API carom_status carom_world_clear_forces (carom_world *world);

/**
 * Impulses (version 0.2): an impulse (jx, jy) at the world point (px, py)
 * changes the velocity at once by J / m and the spin by (p - c) x J / I; an
 * angular impulse changes the spin by j / I. Wakes the body. Errors as
 * carom_body_apply_force (a non-rotating body takes no spin).
 */
CAROM_API carom_status carom_body_apply_impulse (carom_world *world,
                                                 carom_body_id id, double jx,
                                                 double jy, double px,
                                                 double py);
CAROM_API carom_status carom_body_apply_angular_impulse (carom_world *world,
                                                         carom_body_id id,
                                                         double j);

/** The caller's pointer kept with a body (version 0.2). Errors:
 * NULL_ARGUMENT, STALE_BODY. */
CAROM_API carom_status carom_body_get_user_data (const carom_world *world,
                                                 carom_body_id id,
                                                 void **data);
CAROM_API carom_status carom_body_set_user_data (carom_world *world,
                                                 carom_body_id id,
                                                 void *data);

/** A body's collision filter (carom_body_def's category, mask and group),
 * in effect from the next update (version 0.2). Wakes the body. Errors:
 * NULL_ARGUMENT, STALE_BODY. */
CAROM_API carom_status carom_body_set_filter (carom_world *world,
                                              carom_body_id id,
                                              uint32_t category,
                                              uint32_t mask, int32_t group);
CAROM_API carom_status carom_body_get_filter (const carom_world *world,
                                              carom_body_id id,
                                              uint32_t *category,
                                              uint32_t *mask, int32_t *group);
/** Whether a body is a sensor (1) or not (0) (version 0.2). */
CAROM_API carom_status carom_body_is_sensor (const carom_world *world,
                                             carom_body_id id,
                                             int32_t *sensor);

/* ---------------------------------------------------------------- queries */

/** The first body a ray meets (carom_world_cast_ray). */
typedef struct carom_ray_hit {
  carom_body_id body;  /**< CAROM_NULL_BODY when nothing was hit */
  double x, y;         /**< where it meets the body's outline */
  double nx, ny;       /**< the outline's outward unit normal there */
  double fraction;     /**< of the segment, in [0, 1], to the hit */
} carom_ray_hit;

/**
 * The first body the segment from (x0, y0) to (x1, y1) enters, among those
 * whose category & mask is non-zero (sensors included): on the true
 * outline (circles, concave polygons too), with the outward normal there
 * and the fraction of the segment. A body the segment starts inside is hit
 * only where the segment enters it again. Nothing hit: hit->body is
 * CAROM_NULL_BODY, status OK. Bodies in any state count, sleeping ones
 * included; it looks at every body's bounding box (O(bodies)). Errors:
 * NULL_ARGUMENT (world, hit), NOT_FINITE, BAD_ARGUMENT (a coordinate over
 * CAROM_MAX_MAGNITUDE); *hit is unchanged then.
 */
CAROM_API carom_status carom_world_cast_ray (const carom_world *world,
                                             double x0, double y0, double x1,
                                             double y1, uint32_t mask,
                                             carom_ray_hit *hit);

/**
 * The bodies whose tight bounding box overlaps the box [x0, x1] x [y0, y1]
 * (edges included), and those whose shape contains the point (x, y) (the
 * true outline: a concave polygon's notch does not), among those whose
 * category & mask is non-zero, in creation order. Both write up to
 * `capacity` ids and return how many bodies there are, as
 * carom_world_get_bodies does; on bad input they write nothing and return
 * minus a carom_status: -CAROM_ERR_NULL_ARGUMENT (world, or ids with a
 * capacity > 0), -CAROM_ERR_NOT_FINITE, -CAROM_ERR_BAD_ARGUMENT (a
 * negative capacity, x0 > x1 or y0 > y1, a coordinate over
 * CAROM_MAX_MAGNITUDE).
 */
CAROM_API int32_t carom_world_query_aabb (const carom_world *world, double x0,
                                          double y0, double x1, double y1,
                                          uint32_t mask, carom_body_id *ids,
                                          int32_t capacity);
CAROM_API int32_t carom_world_query_point (const carom_world *world, double x,
                                           double y, uint32_t mask,
                                           carom_body_id *ids,
                                           int32_t capacity);

/* ----------------------------------------------------------------- events */

typedef enum carom_event_type {
  CAROM_EVENT_CONTACT_BEGIN = 0, /**< two bodies began to touch */
  CAROM_EVENT_CONTACT_END = 1,   /**< they stopped (or one was removed) */
  CAROM_EVENT_SENSOR_BEGIN = 2,  /**< a body began to overlap sensor a */
  CAROM_EVENT_SENSOR_END = 3,    /**< it stopped (or one was removed) */
  CAROM_EVENT_TYPE_FORCE_32 = 0x7fffffff
} carom_event_type;

/** What happened between two bodies in the last update. */
typedef struct carom_contact_event {
  carom_event_type type;
  carom_body_id a, b;     /**< for sensor events, a is the sensor */
  double x, y;            /**< begin: a point of the contact (sensor: b's
                               centre); end: where it was last */
  double nx, ny;          /**< begin: the unit normal from a to b (sensor:
                               0, 0) */
  double approach_speed;  /**< contact begin: how fast the points closed at
                               the start of the update, >= 0 */
  double normal_impulse;  /**< contact begin: the normal impulse the
                               contact gave in the update (restitution's
                               included); 0 otherwise */
} carom_contact_event;

/**
 * The events of the last carom_world_update, in a fixed order (begins in
 * contact order, then ends; contacts before sensors). Two bodies touch when
 * some point of theirs overlaps or received impulse in the update; a pair
 * begins when it touches and did not in the update before, ends when it
 * did and does not, or when one of its bodies was removed (the id is then
 * stale); a pair whose bodies fell asleep touching stays touching. Every
 * begin is followed, some updates later, by one end. Writes up
 * to `capacity` events and returns how many there were; bad input as
 * carom_world_query_aabb (-CAROM_ERR_NULL_ARGUMENT, -CAROM_ERR_BAD_ARGUMENT).
 */
CAROM_API int32_t carom_world_get_events (const carom_world *world,
                                          carom_contact_event *events,
                                          int32_t capacity);

/* ----------------------------------------------------------------- joints */

/** A joint's id: a slot index and a generation. 0 is never a valid id
 * (version 0.2). */
typedef uint64_t carom_joint_id;
#define CAROM_NULL_JOINT ((carom_joint_id)0)

/**
 * What a joint holds (docs/joints.md). Every joint is a constraint of the
 * same sub-stepped solver as the contacts, and soft: it corrects its error
 * at a stiffness tied to the sub-step, so it stays stable at large mass
 * ratios, and is rigid again in the relax pass after each sub-step's move.
 */
typedef enum carom_joint_type {
  /** a shared point: b turns about the anchor on a; limit: the relative
   * angle; motor: the relative spin, with max_motor_force a torque; spring:
   * a torsion spring towards the angle at creation */
  CAROM_JOINT_REVOLUTE = 0,
  /** b slides along the axis fixed in a, without turning relative to a;
   * limit and spring: the translation along the axis from creation;
   * motor: the sliding speed */
  CAROM_JOINT_PRISMATIC = 1,
  /** the anchors keep their distance (length, or their distance at
   * creation); spring: a spring of that rest length; limit: the length
   * stays in [lower, upper]; motor: the rate the length changes at */
  CAROM_JOINT_DISTANCE = 2,
  /** b is fixed to a; spring: softly, at hertz and damping_ratio */
  CAROM_JOINT_WELD = 3,
  /** the anchor on b stays on the axis through the anchor on a (b turns
   * freely): a wheel on a suspension; spring: along the axis; limit: the
   * translation along it; motor: the wheel's spin relative to a (a torque) */
  CAROM_JOINT_WHEEL = 4,
  /** b is driven towards its pose relative to a at creation (or set by
   * carom_joint_set_target), with at most max_motor_force and
   * max_motor_torque */
  CAROM_JOINT_MOTOR = 5,
  /** the point of b at (x, y) is pulled towards a target that moves
   * (carom_joint_set_target): a soft spring of hertz (0: 5 Hz) and
   * damping_ratio (0: 0.7) with at most max_motor_force (0: no bound);
   * a must be CAROM_NULL_BODY */
  CAROM_JOINT_MOUSE = 6,
  CAROM_JOINT_TYPE_FORCE_32 = 0x7fffffff
} carom_joint_type;

/** Joint settings. Fill with carom_joint_def_init (everything 0), then set
 * the fields its type uses; the others are ignored. */
typedef struct carom_joint_def {
  uint32_t size;          /**< the caller's sizeof, set by def_init */
  carom_joint_type type;
  carom_body_id a, b;     /**< the bodies; a may be CAROM_NULL_BODY for the
                               world itself (a fixed point); b must be a
                               body, and one of them dynamic */
  double x, y;            /**< the anchor in world coordinates at creation
                               (distance: the anchor on a; mouse: the point
                               of b grabbed, and the first target) */
  double x2, y2;          /**< distance: the anchor on b */
  double axis_x, axis_y;  /**< prismatic, wheel: the axis in world
                               coordinates (any non-zero length) */
  int32_t enable_limit;
  double lower, upper;    /**< relative angle, translation or length;
                               lower <= upper */
  int32_t enable_motor;
  double motor_speed;     /**< rad per time unit, or length per time unit */
  double max_motor_force; /**< >= 0; a torque for revolute and wheel */
  int32_t enable_spring;
  double hertz;           /**< the spring's frequency, >= 0; 0 exerts no
                               force (free within the limit: a distance
                               joint is then a rope), except for a weld,
                               which 0 leaves rigid */
  double damping_ratio;   /**< >= 0; 1 is critical damping */
  int32_t collide_connected; /**< non-zero: a and b still collide */
  double length;          /**< distance: the rest length, > 0; 0 for the
                               anchors' distance at creation */
  double max_motor_torque; /**< motor joint: the most torque, >= 0 */
} carom_joint_def;

/** Fill `def` with zeros and set its size field to `size` (the caller's
 * sizeof). Errors: NULL_ARGUMENT, BAD_STRUCT_SIZE. */
CAROM_API carom_status carom_joint_def_init (carom_joint_def *def,
                                             uint32_t size);

/**
 * Add a joint between def->a and def->b. It wakes both. The bodies stop
 * colliding with each other unless collide_connected. On success *id names
 * it (id may be NULL). Errors: NULL_ARGUMENT, BAD_STRUCT_SIZE, NOT_FINITE,
 * STALE_BODY, BAD_ARGUMENT (an unknown type, a == b, a not NULL for a mouse
 * joint, a zero axis, anchors that coincide for a distance joint without a
 * length, lower > upper, a negative force, torque, hertz, damping ratio
 * or length, a magnitude beyond CAROM_MAX_MAGNITUDE), STATIC_BODY (neither
 * body is dynamic), OUT_OF_MEMORY.
 */
CAROM_API carom_status carom_world_add_joint (carom_world *world,
                                              const carom_joint_def *def,
                                              carom_joint_id *id);

/** Remove a joint (removing a body removes its joints, whose ids are then
 * refused as stale). Errors: NULL_ARGUMENT, STALE_JOINT. */
CAROM_API carom_status carom_world_remove_joint (carom_world *world,
                                                 carom_joint_id id);

/** OK if `id` names a live joint, else STALE_JOINT (NULL_ARGUMENT). */
CAROM_API carom_status carom_joint_check (const carom_world *world,
                                          carom_joint_id id);

/** How many live joints the world holds (0 for NULL). */
CAROM_API int32_t carom_world_joint_count (const carom_world *world);

/**
 * Ids of the live joints in slot order, and of those of one body (in a
 * fixed order): each writes up to `capacity` ids and returns how many there
 * are, as carom_world_query_aabb does; on bad input it writes nothing and
 * returns minus a carom_status: -CAROM_ERR_NULL_ARGUMENT (world, or ids
 * with a capacity > 0), -CAROM_ERR_BAD_ARGUMENT (a negative capacity),
 * -CAROM_ERR_STALE_BODY.
 */
CAROM_API int32_t carom_world_get_joints (const carom_world *world,
                                          carom_joint_id *ids,
                                          int32_t capacity);
CAROM_API int32_t carom_body_get_joints (const carom_world *world,
                                         carom_body_id id,
                                         carom_joint_id *ids,
                                         int32_t capacity);

/** The joint's type and bodies (a is CAROM_NULL_BODY for the world); any
 * output may be NULL. Errors: NULL_ARGUMENT, STALE_JOINT. */
CAROM_API carom_status carom_joint_get_bodies (const carom_world *world,
                                               carom_joint_id id,
                                               carom_joint_type *type,
                                               carom_body_id *a,
                                               carom_body_id *b);

/** The two anchors now, in world coordinates: a's, then b's (a mouse
 * joint's target stands for a's, as in the debug draw); any output may be
 * NULL. Errors: NULL_ARGUMENT, STALE_JOINT. */
CAROM_API carom_status carom_joint_get_anchors (const carom_world *world,
                                                carom_joint_id id,
                                                double *ax, double *ay,
                                                double *bx, double *by);

/**
 * The constraint force (fx, fy) and torque on body b, averaged over the
 * last update: all the impulse the joint gave b in it, over its dt; the
 * force acts at b's anchor, the torque is the part of the joint's moment
 * that is not the force's (0 for a distance or mouse joint). Zero before
 * the first update. Any output may be NULL. Errors: NULL_ARGUMENT,
 * STALE_JOINT.
 */
CAROM_API carom_status carom_joint_get_reaction (const carom_world *world,
                                                 carom_joint_id id,
                                                 double *fx, double *fy,
                                                 double *torque);

/** Turn the motor on or off and set its speed and its most force (a torque
 * for revolute and wheel joints); wakes the bodies. Errors: NULL_ARGUMENT,
 * STALE_JOINT, NOT_FINITE, BAD_ARGUMENT (a weld, motor or mouse joint, a
 * negative force, a magnitude beyond CAROM_MAX_MAGNITUDE). */
CAROM_API carom_status carom_joint_set_motor (carom_world *world,
                                              carom_joint_id id,
                                              int32_t enable, double speed,
                                              double max_force);

/** Turn the limit on or off and set its range (revolute: the relative
 * angle; prismatic, wheel: the translation; distance: the length); wakes
 * the bodies. Errors: NULL_ARGUMENT, STALE_JOINT, NOT_FINITE, BAD_ARGUMENT
 * (a weld, motor or mouse joint, lower > upper when enabling it, a
 * magnitude beyond CAROM_MAX_MAGNITUDE). */
CAROM_API carom_status carom_joint_set_limit (carom_world *world,
                                              carom_joint_id id,
                                              int32_t enable, double lower,
                                              double upper);

/** Turn the spring on or off and set its frequency and damping ratio (as
 * carom_joint_def says; a mouse joint's are its pull, 0 for its defaults,
 * and `enable` is ignored); wakes the bodies. Errors: NULL_ARGUMENT,
 * STALE_JOINT, NOT_FINITE, BAD_ARGUMENT (a motor joint, a negative hertz
 * or damping ratio, a magnitude beyond CAROM_MAX_MAGNITUDE). */
CAROM_API carom_status carom_joint_set_spring (carom_world *world,
                                               carom_joint_id id,
                                               int32_t enable, double hertz,
                                               double damping_ratio);

/**
 * Move a joint's target; wakes its bodies. Mouse joint: the world point
 * (x, y) b's grabbed point is pulled to (angle ignored). Motor joint: the
 * pose b is driven to, as b's centre in a's frame and b's angle less a's.
 * Errors: NULL_ARGUMENT, STALE_JOINT, NOT_FINITE, BAD_ARGUMENT (another
 * type, a magnitude beyond CAROM_MAX_MAGNITUDE).
 */
CAROM_API carom_status carom_joint_set_target (carom_world *world,
                                               carom_joint_id id, double x,
                                               double y, double angle);

/* ------------------------------------------------------------- debug draw */

/**
 * Callbacks carom_world_draw calls to draw a world (any may be NULL: that
 * kind is not drawn). Fill with carom_debug_draw_init, then set fields.
 */
typedef struct carom_debug_draw {
  uint32_t size;  /**< the caller's sizeof, set by def_init */
  /** a polygon body's outline, counter-clockwise, in world coordinates
   * (a compound body's shapes are drawn one by one, with its id) */
  void (*polygon) (const double *xy, int32_t count, carom_body_id body,
                   void *user);
  /** a circle body (angle: where its radius marker points) */
  void (*circle) (double x, double y, double radius, double angle,
                  carom_body_id body, void *user);
  /** a contact's normal, from its point, 0.2 of the smaller body's size long */
  void (*segment) (double x0, double y0, double x1, double y1, void *user);
  /** a contact point */
  void (*point) (double x, double y, void *user);
  void *user;             /**< passed to every callback */
  int32_t draw_bodies;    /**< default 1 */
  int32_t draw_contacts;  /**< points and normals of the last update's
                               contacts; default 1 */
  /* ---- version 0.2, joints */
  /** a joint: xy holds four points, the centre of body a, the anchor on
   * a, the anchor on b and the centre of body b (for a joint to the world
   * the first two are its fixed point; for a mouse joint, its target) */
  void (*joint) (carom_joint_type type, const double *xy, carom_joint_id id,
                 void *user);
  int32_t draw_joints;    /**< default 1 */
} carom_debug_draw;

/** Fill `draw` with no callbacks and the defaults above. Errors:
 * NULL_ARGUMENT, BAD_STRUCT_SIZE. */
CAROM_API carom_status carom_debug_draw_init (carom_debug_draw *draw,
                                              uint32_t size);

/** Draw every live body in slot order, then the joints, then the
 * contacts. A carom_debug_draw without the joint fields (its size ends at
 * draw_contacts) is accepted too. Errors:
 * NULL_ARGUMENT, BAD_STRUCT_SIZE. */
CAROM_API carom_status carom_world_draw (const carom_world *world,
                                         const carom_debug_draw *draw);

/* ---------------------------------------------------------------- effects */

/**
 * The stages of a world's update beyond the core (detect, solve, drift).
 * Each is off until asked for, and costs nothing per body or contact while
 * off. carom_world_get_effects reports the active ones as a bit set.
 */
typedef enum carom_effect {
  CAROM_EFFECT_GRAVITY = 1 << 0,         /**< uniform gravity is not (0, 0) */
  CAROM_EFFECT_CENTRAL_GRAVITY = 1 << 1, /**< attraction to a point mass */
  CAROM_EFFECT_RESTITUTION = 1 << 2,     /**< some contact can bounce (e > 0) */
  CAROM_EFFECT_FRICTION = 1 << 3,        /**< some contact has mu > 0 */
  CAROM_EFFECT_FIXED_ROTATION = 1 << 4,  /**< some body is non-rotating */
  CAROM_EFFECT_DAMPING = 1 << 5,         /**< linear or angular damping */
  CAROM_EFFECT_SLEEPING = 1 << 6,        /**< bodies at rest are put to sleep */
  CAROM_EFFECT_CONTINUOUS = 1 << 7,      /**< fast bodies never tunnel */
  CAROM_EFFECT_JOINTS = 1 << 8,          /**< the world has a joint (0.2) */
  CAROM_EFFECT_FORCE_32 = 0x7fffffff
} carom_effect;

/** The active effects, a bit set of carom_effect (0 for NULL). */
CAROM_API uint32_t carom_world_get_effects (const carom_world *world);

/** Name of one effect ("gravity", "central-gravity", "restitution",
 * "friction", "fixed-rotation", "damping", "sleeping", "continuous",
 * "joints"), or NULL. */
CAROM_API const char *carom_effect_name (carom_effect effect);

/** Default restitution e in [0, 1] and friction mu >= 0 for bodies that
 * have none of their own. Errors: NULL_ARGUMENT, NOT_FINITE, BAD_ARGUMENT. */
CAROM_API carom_status carom_world_set_restitution (carom_world *world,
                                                    double restitution);
CAROM_API carom_status carom_world_set_friction (carom_world *world,
                                                 double friction);

/**
 * Newtonian attraction of every dynamic body towards a fixed point mass at
 * (x, y): acceleration gm / (r^2 + softening^2) toward it, with
 * r the distance to the body's centre of mass (the original flying-balls'
 * gravity.c). gm = 0 switches it off. Errors: NULL_ARGUMENT, NOT_FINITE,
 * BAD_ARGUMENT (gm or softening negative).
 */
CAROM_API carom_status carom_world_set_central_gravity (carom_world *world,
                                                        double x, double y,
                                                        double gm,
                                                        double softening);

/**
 * Damping: velocities decay as exp(-linear t) and spins as exp(-angular t),
 * exactly at every step. (0, 0) switches it off. Errors: NULL_ARGUMENT,
 * NOT_FINITE, BAD_ARGUMENT (negative).
 */
CAROM_API carom_status carom_world_set_damping (carom_world *world,
                                                double linear, double angular);

/**
 * Sleeping: a body slower than 5% of its size per second (and 0.035 rad/s)
 * for half a second stops being simulated until something touches it
 * faster than that, the API moves it, or carom_body_wake is called. Sleeping
 * bodies report zero velocity and take part in no contact. enabled = 0
 * switches it off and wakes everything. Errors: NULL_ARGUMENT.
 */
CAROM_API carom_status carom_world_set_sleeping (carom_world *world,
                                                 int32_t enabled);

/**
 * Continuous collision: contacts are looked for as far ahead as the bodies
 * can close on each other in the step (speculative contacts), so a body
 * cannot pass through a thin wall, and an impact is solved at its time
 * within the step (exact bounce heights, docs/accuracy.md). On by default,
 * the one effect that is: a world switches it off with enabled = 0. Off, a
 * body that moves more than half its size in a step still has it; for the
 * others only pairs within 2% of the smaller body's size ahead are found,
 * which saves pairs and time-of-impact work in crowded fast scenes (the
 * elastic gas steps about a fifth faster, docs/effects.md), and a body that
 * moves further than that in a step meets others overlapping (a falling box
 * bounces about 15% too high at dt 1/60), or passes a body thinner than its
 * travel. Bodies marked with carom_body_set_bullet keep it when the world's
 * is off. Errors: NULL_ARGUMENT.
 */
CAROM_API carom_status carom_world_set_continuous (carom_world *world,
                                                   int32_t enabled);

/** Keep continuous collision for this body even when the world's is off. */
CAROM_API carom_status carom_body_set_bullet (carom_world *world,
                                              carom_body_id id,
                                              int32_t bullet);

/** Whether a body is awake (1) or asleep (0). */
CAROM_API carom_status carom_body_is_awake (const carom_world *world,
                                            carom_body_id id,
                                            int32_t *awake);

/** Wake a sleeping body (no effect on an awake one). */
CAROM_API carom_status carom_body_wake (carom_world *world, carom_body_id id);

/**
 * Make a body non-rotating (infinite inertia: contacts never spin it, its
 * spin is set to 0) or rotating again. Errors: NULL_ARGUMENT, STALE_BODY,
 * STATIC_BODY.
 */
CAROM_API carom_status carom_body_set_fixed_rotation (carom_world *world,
                                                      carom_body_id id,
                                                      int32_t fixed);

/* ----------------------------------------------------------------- scenes */

/** Where and why a scene failed to load. */
typedef struct carom_scene_error {
  uint32_t size;         /**< the caller's sizeof; set by the caller */
  int32_t line;          /**< 1-based line of the error, 0 if none */
  carom_status cause;    /**< the status that rejected the line */
  char message[256];     /**< "LINE: what is wrong", NUL-terminated */
} carom_scene_error;

/**
 * Build a new world from scene text (format: docs/scenes.md). The whole text
 * is checked first; on any error nothing is created, *world is NULL, and
 * `error` (may be NULL; its size field must be set) says where and why.
 * `def` (may be NULL) supplies settings the scene does not set, including the
 * allocator. Errors: NULL_ARGUMENT, SCENE_SYNTAX or the status a body or
 * setting on that line was rejected with, OUT_OF_MEMORY.
 */
CAROM_API carom_status carom_scene_load_text (carom_world **world,
                                              const char *text,
                                              size_t length,
                                              const carom_world_def *def,
                                              carom_scene_error *error);

/** carom_scene_load_text on a file's contents; IO if it cannot be read. */
CAROM_API carom_status carom_scene_load_file (carom_world **world,
                                              const char *path,
                                              const carom_world_def *def,
                                              carom_scene_error *error);

#ifdef __cplusplus
}
#endif

#endif /* CAROM_H */
