/* Joints: the store (slots with generation-checked ids, each body's list of
 * its joints) in joint.c, and the constraints the solver's sub-steps solve
 * for them in joint_solver.c. */
#ifndef CAROM_JOINT_H
#define CAROM_JOINT_H

#include "carom.h"
#include "step.h"
#include "vec2.h"

struct carom_world;
struct solver_body;

typedef struct joint {
  carom_joint_type type;
  int32_t alive;
  uint32_t generation;    /* part of the id; bumped on removal */
  int32_t a, b;           /* body slots; a = -1: the world */
  int32_t next[2];        /* the next joint of body a (side 0) and b (side
                             1), as 2 * slot + side + 1; 0 ends the list */
  int32_t prev[2];
  int32_t collide_connected;
  /* where the joint holds, in the bodies' frames, from their centres of
   * mass (the world's frame for a = -1) */
  vec2 local_a, local_b;
  vec2 local_axis;        /* unit, in a's frame */
  double reference_angle; /* b's angle less a's at creation */
  double length;          /* distance: the rest length */
  int32_t enable_limit, enable_motor, enable_spring;
  double lower, upper;
  double motor_speed, max_motor_force, max_motor_torque;
  double hertz, damping_ratio;
  vec2 target;            /* mouse: the world point b is pulled to */
  double target_angle;    /* motor: b's angle less a's it is driven to */
  /* impulses accumulated over the sub-steps, kept for warm starting */
  vec2 linear_impulse;    /* the point (prismatic: across the axis and the
                             angle; wheel: x across the axis) */
  double angular_impulse; /* weld, motor: the angle */
  double axial_impulse;   /* the spring, or a rigid distance */
  double motor_impulse, lower_impulse, upper_impulse;
  /* fixed for one update (joint_prepare) */
  vec2 ra, rb;            /* anchors from the centres, world frame */
  vec2 delta_center;      /* b's centre less a's */
  double delta_angle;     /* b's angle less a's, less reference_angle */
  vec2 axis;              /* local_axis in the world at the step's start */
  double angular_mass;    /* 1 / (1/I_a + 1/I_b), 0 if neither turns */
  joint_soft spring;      /* the joint's own spring for this sub-step */
  int32_t tree;           /* its rows are solved by the direct solve
                             (joint_tree.c) this update */
  int32_t node;           /* its node there */
  double ja[9], jb[9];    /* this pass's rows for a and b (3 x 3, row-major) */
  /* the impulse on b over the last update: summed, then over dt */
  vec2 reaction_sum;
  double reaction_torque_sum;
  vec2 reaction_force;
  double reaction_torque;
} joint;

typedef struct joints {
  joint *list;           /* slots [0, count), some dead */
  int32_t count, cap, live;
  int32_t *free_slots;   /* dead slots, reused LIFO */
  int32_t free_count, free_cap;
} joints;

/* One node of the direct solve: a body or a joint, in breadth-first order
 * from its tree's root, so every node's parent comes before it. */
typedef struct tree_node {
  int32_t body, joint;   /* the slot of one, the other -1 */
  int32_t parent;        /* its index, -1 for a root */
  int32_t rows;          /* 3 for a body; the joint's row count */
  double d[9];           /* its pivot block, then that block's inverse */
  double h[9];           /* its block of the system against its parent's */
  double l[9];           /* d^-1 h */
  double x[3];           /* right-hand side, then solution */
} tree_node;

typedef struct joint_tree {
  tree_node *nodes;
  int32_t node_count, node_cap;
  int32_t mixed;         /* some tree joint has a limit, motor or spring */
  int32_t factored;      /* the nodes hold the factors of the rows in the
                            joints' ja, jb (the bodies have not moved
                            since, or by little) */
  int32_t converged;     /* the last projection ended within its tolerance
                            (joint_tree_project): the bodies moved by no more
                            than its last Newton pass since the factors */
  int32_t *scratch;      /* the set-up's union-find, adjacency and queue;
                            sleep.c's groups */
  int32_t scratch_cap;
  double *group_time;    /* sleep.c: per group, its least sleep time */
  int32_t group_cap;
} joint_tree;

void joints_init (struct carom_world *world);
void joints_destroy (struct carom_world *world);
/* Remove every joint of the body in `slot` (it is being removed). */
void joints_forget_body (struct carom_world *world, int32_t slot);
/* Whether a joint between the bodies in slots a and b keeps them from
 * colliding (none of its joints between them has collide_connected). */
int joints_block_pair (const struct carom_world *world, int32_t a, int32_t b);
/* The live joint an id names, or NULL. */
joint *joint_lookup (const struct carom_world *world, carom_joint_id id);
carom_joint_id joint_id_of (const struct carom_world *world, int32_t slot);
/* Where its anchors are now, in world coordinates. */
void joint_anchors (const struct carom_world *world, const joint *j, vec2 *pa, vec2 *pb);

/* The solver's stages (joint_solver.c), in the order of solver.c: set up
 * once per update, then per sub-step the warm start, the solve with the
 * soft correction of the error (use_bias) and, after the move, the relax
 * pass without it; the reaction summed per sub-step. */
void joint_prepare (struct carom_world *world, const step_context *ctx);
/* After the contacts' set-up: mark the joints' bodies as constrained
 * (they move by the velocity the solver leaves), and those of groups no
 * contact acts on as moving by leapfrog (CONSTRAINED_JOINT, gravity.h). A
 * group a contact holds keeps symplectic Euler: its contacts' and joints'
 * warm-start impulses are sized for a whole sub-step's gravity before the
 * move, and with half of it after the move they would leave the group a
 * half-kick short of rest. */
void joint_mark_bodies (struct carom_world *world);
void joint_warm_start (struct carom_world *world);
void joint_solve (struct carom_world *world, const step_context *ctx, int use_bias);
void joint_project (struct carom_world *world, const step_context *ctx);
void joint_sum_reaction (struct carom_world *world);
void joint_finish (struct carom_world *world, const step_context *ctx);

/* The joints' rigid rows (a point, an angle, a line, a length) and their
 * Jacobians for the direct solve: how many (0 to 3), the rows for a and b
 * (row-major, columns vx, vy, w) with the position error of each, and the
 * rows' accumulated impulses. */
int32_t joint_row_count (const joint *j);
void joint_rows (const joint *j, const struct solver_body *A, const struct solver_body *B, double *ja, double *jb,
                 double *c);
void joint_rows_get (joint *j, double *impulse);
void joint_rows_add (joint *j, const double *impulse);

/* Whether a body's velocities and motion are finite and within
 * CAROM_MAX_MAGNITUDE: a joint's pass is kept only if they stay so. */
int joint_sane (const struct solver_body *b);
/* The same of a body with velocities v, w and motion dp, da since the
 * step began (each pass of the direct solve asks it of every body: one
 * test of the six, without a branch for each; a NaN fails it as well). */
static inline int joint_motion_sane (vec2 v, double w, vec2 dp, double da)
{
  return (fabs (v.x) <= MAX_MAGNITUDE) & (fabs (v.y) <= MAX_MAGNITUDE) & (fabs (w) <= MAX_MAGNITUDE)
         & (fabs (dp.x) <= MAX_MAGNITUDE) & (fabs (dp.y) <= MAX_MAGNITUDE) & (fabs (da) <= MAX_MAGNITUDE);
}

/* The direct solve (joint_tree.c): the joints whose bodies form a tree
 * (each tree at most one joint to the ground), solved exactly in each pass
 * in time linear in their number (Baraff's "Linear-time dynamics using
 * Lagrange multipliers", 1996). Room for it (0: out of memory), its set-up
 * per update (which joints it takes, the elimination order), the pass. */
int joint_tree_reserve (struct carom_world *world);
void joint_tree_destroy (struct carom_world *world);
void joint_tree_build (struct carom_world *world);
/* A pass: the impulses that zero every tree row's velocity error (with
 * the rows factored last, or where the bodies are if none are). */
void joint_tree_solve (struct carom_world *world);
/* A sub-step begins: its first pass factors afresh, unless the last
 * sub-step's projection converged (its factors then hold the rows where
 * the bodies are, but for its last Newton pass's correction). */
void joint_tree_next_substep (struct carom_world *world);
/* After a sub-step's move: the displacements that remove every tree row's
 * position error (to first order), leaving the velocities alone (as the
 * contacts' split impulses do). */
void joint_tree_project (struct carom_world *world, const step_context *ctx);

/* A spring of `hertz` and damping ratio `zeta` over a step h (joint_soft,
 * step.h), implicit in h, so stable at any stiffness; hertz 0 is rigid. */
joint_soft joint_soft_make (double hertz, double zeta, double h);
/* The joints' own correction of their error over a sub-step h. */
joint_soft joint_hold_soft (double h);

#endif
