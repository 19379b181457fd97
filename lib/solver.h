/* The solver: the order of the stages within one update (solver.c) and the
 * per-body state every constraint reads and writes. The contact constraint
 * itself is in contact_solver.c. */
#ifndef CAROM_SOLVER_H
#define CAROM_SOLVER_H

#include "step.h"
#include "vec2.h"

struct carom_world;

/* What the sub-steps read and write per body, kept compact: velocities,
 * the motion since the step began (so constraints measure their current
 * error without recomputing any geometry), and inverse mass and inertia. */
/* solver_body.moves */
enum {
  MOVES_NOT = 0,       /* static, asleep or dead */
  MOVES_DYNAMIC = 1,   /* awake and dynamic: gravity, forces, contacts */
  MOVES_KINEMATIC = 2  /* at its own velocity, infinite mass */
};

/* How a body's free flight within the step stands after the impacts of
 * contact_impacts changed its velocity at their times: those velocities
 * act from the start of the step in the sub-steps, so the body's true path
 * after its last impact is its start pose shifted by minus each velocity
 * change times its time (p, and the angle a), plus its velocity now times
 * the time (toi_pose). The shift is the move contact_time_of_impact makes
 * at the end of the step. */
typedef struct impact_shift {
  vec2 p;
  double a;
  double at; /* the time of the last impact that changed its velocities */
} impact_shift;

/* solver_body.constrained: some constraint acts on the body this step (it
 * moves by symplectic Euler, see gravity_drift_velocity); one of its
 * contacts held it at detection (touching, or apart but not closing); its
 * drift was corrected after an impact (contact_time_of_impact); a joint
 * holds it. */
#define CONSTRAINED_ANY 1
#define CONSTRAINED_HELD 2
#define CONSTRAINED_DRIFT_FIXED 4
#define CONSTRAINED_JOINT 8 /* a joint holds it (joint_solver.c, gravity.c) */

typedef struct solver_body {
  /* three rows of four doubles, which the AVX2 and AVX-512 batch kernels
   * load and store whole (batch_lanes.h): the velocities, the
   * pseudo-velocities and the motion since the step began. A row never
   * overlaps another, so a row just stored is read back without waiting
   * (a load that overlaps part of a recent store stalls until it is
   * written). */
  vec2 v;
  double w;
  double row_end_v;  /* unused */
  vec2 pv;       /* push-out pseudo-velocity of this sub-step: it moves the
                    body, then is dropped (split impulses: no energy) */
  double pw;
  double row_end_pv; /* unused */
  vec2 dp;       /* displacement of the centre of mass since the step began */
  rot2 dq;       /* rotation since the step began (for the constraints) */
  double da;     /* the same rotation as an angle (for the body) */
  double im, ii; /* inverse mass and inertia (0: cannot be moved) */
  int32_t constrained; /* some constraint acts on it this step: CONSTRAINED_* bits */
  int32_t moves;       /* MOVES_*: whether and how the sub-steps move it */
} solver_body;

/* (an array of -1 elements if it is not two cache lines) */
typedef char solver_body_is_two_lines[sizeof (solver_body) == 128 ? 1 : -1];

/* Room for one solver body per slot; 0 when memory ran out. Called before
 * any state changes in a step, so solver_step itself cannot fail. */
int solver_reserve (struct carom_world *world);
/* Each body's contacts: those of slot i are adj[start[i]] to
 * adj[start[i + 1] - 1], and other[e] is the body at the far end of
 * contact adj[e] (so a walk over the graph need not read the contacts);
 * in solver_scratch, which shock.c's levels also use. `other` may be
 * NULL. */
void solver_contact_adjacency (struct carom_world *world, int32_t **start, int32_t **adj, int32_t **other);
/* One update: the sub-steps over the contacts found at its start. */
void solver_step (struct carom_world *world, const step_context *ctx);
void solver_destroy (struct carom_world *world);

#endif
