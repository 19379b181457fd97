/* Bodies: a slot array with generation-checked ids, mass properties from
 * their shape, and the state the solver and integrator work on. */
#ifndef CAROM_BODY_H
#define CAROM_BODY_H

#include "carom.h"
#include "shape.h"
#include "vec2.h"

typedef struct body {
  /* The fields are in the order the step reads them, so that each stage
   * touches few of the body's cache lines (64 bytes each): the first line
   * is the state (the solver's gather and finish, detection's poses), the
   * second what detection, the broad phase and the solver read of every
   * body, the third the flags and filters of on_pair, the fourth the
   * shape's own first line (shape.h). The rest is read rarely. */
  /* state: position of the centre of mass, rotation, velocities, angle */
  vec2 p;
  rot2 q;          /* cos and sin of angle, refreshed after each move */
  vec2 v;
  double w;
  double angle;
  /* statics have zero inverses and so never move */
  double inv_mass, inv_inertia;
  vec2 box_lo, box_hi;          /* world-space bounding box */
  double restitution, friction; /* as given; < 0 means the world default */
  carom_body_type type;
  int32_t alive;
  int32_t asleep;         /* sleeping: zero inverse mass, not moved */
  int32_t bullet;         /* continuous collision even when the world's is off */
  uint32_t category, mask;
  int32_t group;
  int32_t sensor;         /* reports overlaps, takes part in no contact */
  int32_t joint_head;     /* its first joint, as joint.h's next[] (0: none) */
  int32_t joint_count;    /* how many joints it has */
  uint32_t generation;          /* part of the id; bumped on removal */
  int32_t fixed_rotation; /* non-rotating: inv_inertia stays 0 */
  shape shape;
  /* mass properties */
  double mass, inertia;
  double density;               /* as given (a compound's parts keep their own) */
  double sleep_time;      /* how long it has been slow enough to sleep */
  /* what the program asked for (version 0.2) */
  vec2 force;             /* over the next update (force.c) */
  double torque;          /* about the centre of mass */
  void *user_data;
} body;

struct carom_world;

void bodies_init (struct carom_world *world);
void bodies_destroy (struct carom_world *world);

/* Make sure a slot is free and that removing a body later cannot fail
 * for lack of room in the free list (TOO_MANY_BODIES, OUT_OF_MEMORY);
 * changes no visible state. Then place a fully built shape, and what the
 * def says, in that slot: cannot fail. */
carom_status body_reserve_slot (struct carom_world *world);
carom_body_id body_commit (struct carom_world *world, const carom_body_def *def, const shape *s);

/* The live body an id names, or NULL. */
body *body_lookup (const struct carom_world *world, carom_body_id id);
carom_body_id body_id_of (const struct carom_world *world, int32_t slot);
/* The same, from the body in that slot. */
static inline carom_body_id body_slot_id (const body *b, int32_t slot)
{
  return ((uint64_t) b->generation << 32) | (uint64_t) (uint32_t) (slot + 1);
}

/* How far any point of the body can move in time h at velocities v and w:
 * (|v| + |w| R) h, plus
 * what an acceleration of magnitude `accel` (gravity) adds within h. A body
 * that is not swept (body_swept: the world's continuous collision off, not
 * a bullet, not fast for its size) has its contacts looked for no further
 * ahead than 2% of its size, except between pieces that were in contact the
 * step before and do not bounce (contact.c, pair_pieces). */
static inline double body_reach_at (const body *b, vec2 v, double w, double h, double accel)
{
  return h * (v2_len (v) + fabs (w) * b->shape.bound_radius + (b->inv_mass > 0.0 ? accel * h : 0.0));
}

/* The same at its own velocities. */
static inline double body_reach_uncapped (const body *b, double h, double accel)
{
  return body_reach_at (b, b->v, b->w, h, accel);
}

/* A body moves fast when its own motion (its velocities, not gravity's
 * fall) carries it further within a step than this fraction of its size
 * (Box2D v3 draws the same line). A slower body meets what it did not see
 * at the detection at most that deep: about the distance from the centre
 * of a convex body to its nearest side, so what it struck is pushed back
 * the way it came. A faster one could cross a thinner body whole (a card
 * falling on a card). Fast bodies are swept (continuous collision) whether
 * or not the world's is on; slow ones cost nothing more. */
#define BODY_FAST_FRACTION 0.5

/* Whether continuous collision applies to a body whose uncapped reach over
 * the step dt is r (body_reach_uncapped): the world's (`continuous`), a
 * bullet, or a body that moves fast. */
static inline int body_swept (const body *b, double r, double dt, double accel, int continuous)
{
  double fall = b->inv_mass > 0.0 ? accel * dt * dt : 0.0;
  return continuous || b->bullet || r - fall > BODY_FAST_FRACTION * b->shape.size;
}

/* Whether continuous collision applies to a pair of bodies in an update of
 * dt, their uncapped reaches ra and rb: either is swept. (The detection's
 * reaches, for a pair it found: contact_pair_swept.) */
static inline int body_pair_swept (const body *a, double ra, const body *b, double rb, double dt, double accel,
                                   int continuous)
{
  return body_swept (a, ra, dt, accel, continuous) || body_swept (b, rb, dt, accel, continuous);
}

/* body_reach from its uncapped value r, for a body that is swept or not. */
static inline double body_reach_capped (const body *b, double r, int swept)
{
  double cap = 0.02 * b->shape.size;
  return swept || r < cap ? r : cap;
}

/* How far two bodies can close on each other in time h: in free flight no
 * point of one moves against any point of the other faster than |v_b - v_a|
 * + |w_a| R_a + |w_b| R_b, and gravity adds at most accel h^2 (as
 * body_reach_uncapped: both fall alike, or one does not fall). With
 * `stopped`, either may also be stopped within the step by what it lands on
 * (the box below in a stack that falls onto the ground), and the other then
 * closes on it at its own speed: the largest of |v_b - v_a|, |v_a| and |v_b|
 * (a bounce that throws one back is met by the search after the impacts,
 * contacts_after_impacts). Never more than the sum of their
 * body_reach_uncapped, and less for bodies that fly together. */
static inline double body_pair_reach (const body *a, const body *b, double h, double accel, int stopped)
{
  double fall = a->inv_mass > 0.0 || b->inv_mass > 0.0 ? accel * h : 0.0;
  double closing = v2_len (v2_sub (b->v, a->v));
  if (stopped)
    {
      double sa = v2_len (a->v), sb = v2_len (b->v), fastest = sa > sb ? sa : sb;
      closing = fastest > closing ? fastest : closing;
    }
  return h * (closing + fabs (a->w) * a->shape.bound_radius + fabs (b->w) * b->shape.bound_radius + fall);
}

static inline double body_reach (const body *b, double h, double accel, int continuous)
{
  double r = body_reach_uncapped (b, h, accel);
  return body_reach_capped (b, r, body_swept (b, r, h, accel, continuous));
}

/* Whether two bodies' filters let them collide (carom_body_def). */
static inline int body_filters_pass (const body *a, const body *b)
{
  if (a->group != 0 && a->group == b->group)
    return a->group > 0;
  return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

/* A kinematic body that moves: it wakes what it touches. */
static inline int body_kinematic_moving (const body *b)
{
  return b->type == CAROM_KINEMATIC && (b->v.x != 0.0 || b->v.y != 0.0 || b->w != 0.0);
}

/* Whether the body's shape (its true outline) contains the world point p
 * (query.c). */
int body_contains (const body *b, vec2 p);

/* Sleep and wake: a sleeping body keeps its mass but acts as static (zero
 * inverse mass) and does not move; waking restores its inverses. */
void body_sleep (body *b);
void body_wake (body *b);

/* Refresh the rotation cache and bounding box after a move. */
void body_sync (body *b);

#endif
