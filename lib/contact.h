/* Contacts: the narrow phase run on every pair the broad phase reports, kept
 * from one step to the next so the solver can start from last step's
 * impulses (warm starting). */
#ifndef CAROM_CONTACT_H
#define CAROM_CONTACT_H

#include "collide.h"

struct step_context;

typedef struct contact_point {
  vec2 point, normal;   /* world frame at detection; normal from body a to body b */
  double depth;         /* penetration at detection (negative: apart); for
                           an impact's point, minus its separation at the
                           start of the step along the touch's normal
                           (impact.c), where the sub-steps follow it from */
  double found;         /* the penetration where point and normal were
                           found: at detection, or at the touch of an
                           impact (carom_world_get_contact) */
  uint32_t feature;
  int32_t in_impact;    /* takes part in its contact's impact
                           (contact_impacts): near at detection, meeting
                           within the step, or of the touch (not a guard,
                           impact.c) */
  /* the contact constraint's data (contact_solver.c), fixed for the step */
  vec2 ra, rb;          /* from each centre of mass to the point */
  double rn_a, rn_b;    /* ra x n, rb x n */
  double rt_a, rt_b;    /* ra x t, rb x t, t the tangent */
  double normal_mass;   /* 1 / (denominator of eq. 3.23) */
  double tangent_mass;
  double adjusted;      /* separation at detection less (rb - ra) . n: the
                           separation is adjusted + (moved b - moved a) . n */
  double push_impulse;  /* the push-out's pseudo-impulse in this sub-step */
  double approach;      /* normal relative speed the point met with (what
                           restitution reverses; see impact.c) */
  double after;         /* what gravity adds to its normal speed from the
                           meeting to the end of the step */
  double normal_impulse, tangent_impulse; /* accumulated in the sub-steps,
                                             kept for warm starting */
  double total_impulse, tangent_total;    /* all the impulse of this step
                                             (each sub-step's, and
                                             restitution's) */
  double normal_moment, tangent_moment;   /* sum of impulse x time left in
                                             the step when applied */
  double impact_moment;                   /* sum of the impacts' impulses x
                                             their time into the step
                                             (contact_impacts) */
  double toi;                             /* apart and closing at detection:
                                             when it meets, else -1 */
  /* where the point was last computed: a's copy of it and the normal in
   * body a's frame, b's copy in body b's (manifold reuse, contact.c) */
  vec2 local_a, local_b, local_normal;
} contact_point;

typedef struct contact {
  /* the first 64 bytes: what most passes over all the contacts read
   * (colouring, packing, the levels, events) */
  int32_t a, b;               /* body slots */
  int32_t piece_a, piece_b;   /* convex pieces (or -1 for the whole outline) */
  int32_t count;
  int32_t first_point;        /* index of points[0] among all points */
  contact_point *points;      /* its `count` points: those of its list's pool
                                 from first_point on */
  double restitution, friction;
  int32_t block;              /* two points solved as one 2x2 problem */
  int32_t fine;               /* its bodies fall more than the slop in a
                                 step: the solve passes it takes in a
                                 sub-step at most (contact_fine_passes),
                                 else 0 */
  int32_t batched;            /* solved in a batch this step (contact_batch.c):
                                 one past its place in the batches once
                                 packed */
  int32_t cold;               /* begins resting this step: fresh, near,
                                 neither closing nor leaving fast
                                 (contact_cold_start gives it an impulse) */
  double slop;                /* overlap left alone, from the bodies' sizes */
  double max_push;            /* fastest push-out speed, from the bodies' radii */
  double k11, k12, k22;       /* its matrix (eq. 3.23's denominators and their coupling) */
  int32_t met;                /* pushed this step (its approach is measured) */
  int32_t reused;             /* this step's points are last step's, moved */
  int32_t fresh;              /* last step had no contact of these pieces */
  int32_t queued;             /* waiting in contact_impacts' work list */
  xform computed_at;          /* b's pose in a's frame when the points were
                                 last computed by the narrow phase */
  double impact_at;           /* when its impact happens in the step (a seed
                                 of contact_impacts) */
  double touch_at;            /* the moment `touches` was found for */
  int32_t pending;            /* a seed contact_impacts has yet to take */
  int32_t reimpacts;          /* times it was searched for a next touch */
  int32_t event_round;        /* the last impact (seed) that acted on it */
  int32_t touches;            /* whether its pieces touch then (contact_impacts) */
  double gap;                 /* at detection, never more than the pieces'
                                 distance when they are apart (manifold.gap,
                                 and no point's separation) */
  int32_t kept;               /* kept as it was before the step's impacts
                                 changed it (impact.c, impact_keep) */
  int32_t clear;              /* at detection: its pieces cannot touch
                                 within the step in free flight (contact.c,
                                 clear_of_step) */
  int32_t separation_known;   /* the SAT measured the pieces at this
                                 step's poses (not a reused manifold, nor
                                 another test): its separation and face
                                 (manifold.separation) follow */
  int32_t separation_face;
  double separation;
} contact;

typedef struct contacts {
  contact *list;         /* this step's contacts */
  int32_t count, cap;
  contact *old;          /* last step's, for warm starting */
  int32_t old_count, old_cap;
  contact_point *pool;   /* the points of `list`, point_count of them, each
                            contact's in a row (a manifold has 1 to
                            MANIFOLD_MAX_POINTS: most have 1 or 2) */
  int32_t pool_cap;
  contact_point *old_pool; /* those of `old` */
  int32_t old_pool_cap;
  int32_t *table;        /* open-addressing hash over `old`, built when
                            first needed in a detection (table_built) */
  int32_t table_cap;
  int32_t table_built;
  int32_t cursor;        /* the old contact after the last one matched */
  int32_t point_count;
  int32_t cold_count;    /* contacts marked cold this step */
  int32_t bouncy_count;  /* contacts with restitution this step (contact_prepare) */
  int32_t bouncy_found;  /* contacts with restitution the detection made */
  int32_t packed;        /* contact_prepare packed the batched contacts'
                            lanes as it set them up (contact_batch_pack) */
  int32_t room_count;    /* the most contacts and points this step may */
  int32_t room_points;   /* hold: what solver_reserve kept room for */
  int32_t impacts;       /* impacts contact_impacts made this step */
  int32_t kept, kept_points; /* contacts and points impact_keep kept */
  const int32_t *rest;   /* this step's contacts the batches leave to the
                            one-at-a-time passes (contact_batch_prepare) */
  int32_t rest_count;
  const int32_t *fine_rest; /* those of `rest` that are fine, in its order */
  int32_t fine_rest_count;
  int32_t fine_passes;   /* the most passes a fine one takes (contact.fine) */
  int32_t *sensors;      /* this detection's pairs with a sensor: pairs of
                            slots, the sensor first (events.c tests their
                            overlap at the end of the update) */
  int32_t sensor_count, sensor_cap; /* pairs, and room in int32_t */
  int32_t clear_count;   /* contacts the detection found clear */
  double dt;             /* the step the detection looked ahead over */
  unsigned char *pushed; /* per slot: a dynamic body something other than
                            an impact may push within the step (a contact
                            within the slop, a joint): drop_clear */
  int32_t pushed_cap;
  int32_t *deferred;     /* this detection's bouncy pairs whose bounding
                            circles stay apart through the step
                            (circles_clear_of_step): pairs of slots */
  int32_t deferred_count, deferred_cap; /* pairs, and room in int32_t */
  int out_of_memory;
} contacts;

struct carom_world;

void contacts_init (struct carom_world *world);
void contacts_destroy (struct carom_world *world);
/* Detect all contacts at the current positions, carrying over the impulses
 * of matching points from the previous detection. */
carom_status contacts_update (struct carom_world *world, const struct step_context *ctx);
/* Point every contact at its points again (after the pool moved). */
void contacts_point_again (struct carom_world *world);
/* Undo the last contacts_update (a later stage of the sub-step failed). */
void contacts_undo (struct carom_world *world);
/* Whether some convex piece of a overlaps some piece of b (or the circles)
 * where they are now: the sensors' test (events.c). */
struct body;
int contact_bodies_overlap (const struct body *a, const struct body *b);
/* The narrow phase of contact k's two pieces with its bodies placed at xa
 * and xb instead of where they are (the time of impact, toi.c); two convex
 * polygons take their reference face by `toward` (from a towards b) when it
 * is not NULL (collide_polygons_sat_toward). */
void contact_collide_at (const struct carom_world *world, const contact *k, xform xa, xform xb, double margin,
                         const vec2 *toward, manifold *m);
/* How far contact k's two pieces reach towards each other along the unit
 * axis n (A's along n, B's along -n, each from its body's centre), their
 * bodies turned to qa and qb and then by at most turn_a and turn_b either
 * way: with the centres' gap along n, a bound on the pieces' gap along n
 * through any such turn. */
double contact_reach_along (const struct carom_world *world, const contact *k, rot2 qa, rot2 qb, vec2 n, double turn_a,
                            double turn_b);
/* Contact k's piece of one body (side 0: A, 1: B) placed at x and moving
 * at velocity vel and spin w: the largest d . q over its points q (a
 * circle's radius included) and the largest rate d . q' of any of them. */
void contact_piece_envelope (const struct carom_world *world, const contact *k, int side, xform x, vec2 vel, double w,
                             vec2 d, double *reach, double *rate);
/* The same piece: the earliest tau >= 0 at which the gap one of its points
 * leaves to a level other + other_rate tau (which it must stay below along
 * d), -(d . q + d . q' tau) - level, less curve tau^2 / 2, falls to 0;
 * INFINITY when none does. */
double contact_piece_first_reach (const struct carom_world *world, const contact *k, int side, xform x, vec2 vel,
                                  double w, vec2 d, double other, double other_rate, double curve);
/* Contact k's pieces placed at xa and xb and moving at (va, wa), (vb, wb):
 * the earliest tau >= 0 at which some point of A and some point of B could
 * meet along the fixed axis n (from A towards B), each pair's gap along n
 * closing at the pair's rate now, less curve tau^2 / 2; INFINITY when none
 * does, -1 when the pieces have too many points to pair up (more than
 * CONTACT_PAIRED_POINTS on both, or their product beyond its square). */
/* The first root tau >= 0 of g0 + g1 tau - curve tau^2 / 2 (g0 >= 0): when
 * a gap g0, changing at g1 now and closing at most by curve tau^2 / 2 more,
 * can first close; in the form that does not cancel, INFINITY when it
 * never does. */
static inline double contact_gap_root (double g0, double g1, double curve)
{
  double disc = g1 * g1 + 2.0 * curve * g0, den;
  if (!(disc >= 0.0))
    return INFINITY;
  den = sqrt (disc) - g1;
  return den > 0.0 ? 2.0 * g0 / den : INFINITY;
}
#define CONTACT_PAIRED_POINTS 16
double contact_pieces_first_meeting (const struct carom_world *world, const contact *k, xform xa, vec2 va, double wa,
                                     xform xb, vec2 vb, double wb, vec2 n, double curve);
/* The separation of contact k's two pieces placed at xa and xb: the largest
 * over the edge normals for two polygons (polygons_separation), the
 * distance less the radius with a circle. Never more than their distance;
 * 0 when they touch. It is the gap between the pieces' projections on the
 * unit axis *axis (from A towards B): an edge normal, or the direction of
 * the distance. */
double contact_separation_at (const struct carom_world *world, const contact *k, xform xa, xform xb, vec2 *axis);
/* The face a separation of two polygon pieces was measured on: the edge
 * `edge` of the reference piece `ref` (A's piece when side is 0, B's when
 * 1), the other piece `inc`; pa, pb: A's and B's pieces. ref is NULL when
 * a circle's distance gave the separation. */
typedef struct contact_face {
  const convex_piece *ref, *inc, *pa, *pb;
  int32_t edge;
  int side;
} contact_face;
/* contact_separation_at, and the face it was measured on. */
double contact_separation_face_at (const struct carom_world *world, const contact *k, xform xa, xform xb, vec2 *axis,
                                   contact_face *face);
/* The same at the bodies' poses of the detection, from what the SAT found
 * there (contact.separation_known), to the bit: 1, or 0 when it found
 * nothing (another test, or a reused manifold), and the caller measures. */
int contact_separation_face_detected (const struct carom_world *world, const contact *k, vec2 *axis,
                                      contact_face *face, double *separation);
/* Contact k's convex piece of one body (side 0: A, 1: B), in its body's
 * frame: a circle body's one circle (made in `circle`), a polygon's or a
 * compound's piece; NULL for the vertex-edge method's whole outline. */
const convex_piece *contact_piece (const struct carom_world *world, const contact *k, int side, convex_piece *circle);
/* Whether continuous collision applies to the pair of bodies in slots a
 * and b in this step: either is swept (body_swept: the world's continuous
 * collision, a bullet, or a body that moves fast for its size), judged
 * from the reach the detection found (broadphase.reach). */
int contact_pair_swept (const struct carom_world *world, int32_t a, int32_t b, const struct step_context *ctx);
/* After the impacts of a step (contact_impacts): the pairs a body whose
 * velocities they changed can now reach in the step that have no contact,
 * detected looking as far ahead as the bodies' velocities before and after
 * carry them, and added to the list (the room kept for them,
 * contacts_headroom, bounds how many; the rest wait for the next
 * detection). Returns the index of the first contact added. */
int32_t contacts_after_impacts (struct carom_world *world, const struct step_context *ctx);
/* The contacts the update keeps room for beyond the detection's
 * (contacts_after_impacts): none without restitution; else one for each
 * contact with restitution, 8 more, and those of one pair of the
 * world's largest compounds (at most AFTER_IMPACT_PAIR_ROOT squared).
 * solver_reserve asks once per update and keeps the sum in
 * contacts.room_count, which every array per contact is sized by: the
 * headroom itself grows as contacts with restitution are added. */
#define AFTER_IMPACT_PAIR_ROOT 16
int32_t contacts_headroom (const struct carom_world *world);
/* Forget every contact that involves `slot` (the body is being removed). */
void contacts_forget_body (struct carom_world *world, int32_t slot);

#endif
