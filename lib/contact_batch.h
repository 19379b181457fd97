/* Contacts solved in batches of eight.
 *
 * The contacts that need nothing but the sub-steps' passes (no restitution,
 * at most two points, bodies large enough for one pass) are coloured: no
 * two contacts of a colour share a body that moves, so the contacts of one
 * colour can be solved in any order, or at once. Each colour is packed into
 * batches of eight lanes (structure of arrays) that one kernel solves lane
 * by lane: the portable kernel in contact_batch.c and the same kernel on
 * AVX2 registers in contact_batch_avx2.c, each four lanes at a time (a
 * batch in two groups of four), and with AVX-512's registers, a batch at
 * once, in contact_batch_avx512.c; chosen at run time from the CPU. All are
 * one source (contact_batch_kernel.h) over the same operations in the same
 * order, with no fused or approximate arithmetic, so they give the same
 * bits. Bodies that do not move (static, asleep, kinematic) take no colour
 * and may be shared by lanes: the impulses they take are zeros, which
 * leave their velocities to the bit (solver.c's gather gives them no -0),
 * so lanes that write them back write what they read. Unused lanes point
 * at an inert body that takes nothing.
 * Contacts with such a body are coloured apart and solved after the others
 * (the ground last, so nothing undoes it within a pass). Within a colour,
 * two-point contacts are packed before one-point ones: the order within a
 * colour changes no result, and a batch of one-point contacts alone takes
 * half the work (a lane's unused second point would only add zeros).
 *
 * The rest (bouncy contacts, small bodies, contacts of more than two points,
 * and those a body with every colour taken leaves over) are solved after
 * the batches by the one-at-a-time passes of contact_solver.c.
 *
 * The batches serve any constraint between two bodies: colouring looks at
 * the pair alone (constraint_colour). */
#ifndef CAROM_CONTACT_BATCH_H
#define CAROM_CONTACT_BATCH_H

#include <stddef.h>
#include <stdint.h>

#include "step.h"

struct carom_world;
struct solver_body;

/* the lanes of a batch: one AVX-512 register of doubles, two of AVX2 */
#define BATCH_LANES 8
/* Colours of the constraint graph (as many again for the constraints with
 * a body that does not move); a constraint whose bodies have used them all
 * is left over (solved one at a time, after the batches). */
#define CONSTRAINT_COLOURS 32

typedef enum solver_path { SOLVER_PATH_PORTABLE = 0, SOLVER_PATH_AVX2 = 1, SOLVER_PATH_AVX512 = 2 } solver_path;
#define SOLVER_PATHS 3

typedef struct batch_point {
  double nx[BATCH_LANES], ny[BATCH_LANES];
  double ra_x[BATCH_LANES], ra_y[BATCH_LANES], rb_x[BATCH_LANES], rb_y[BATCH_LANES];
  double adjusted[BATCH_LANES];
  double rn_a[BATCH_LANES], rn_b[BATCH_LANES], rt_a[BATCH_LANES], rt_b[BATCH_LANES];
  double normal_mass[BATCH_LANES], tangent_mass[BATCH_LANES];
  double normal_impulse[BATCH_LANES], tangent_impulse[BATCH_LANES], push_impulse[BATCH_LANES];
  double total[BATCH_LANES]; /* the step's normal impulse (contact_point.total_impulse) */
} batch_point;

/* What only a batch of two-point lanes has: the 2x2 problem of its faces
 * and its second point. */
typedef struct batch_pair {
  double k11[BATCH_LANES], k12[BATCH_LANES], k22[BATCH_LANES]; /* the 2x2 matrix K */
  double i11[BATCH_LANES], i12[BATCH_LANES], i22[BATCH_LANES]; /* its inverse */
  double pair[BATCH_LANES];  /* 1: the two points are solved as one 2x2 problem */
  double block[BATCH_LANES]; /* 1: and K is invertible (contact_lcp2's first case) */
  batch_point p1;
} batch_pair;

/* The batches begin on a cache line (world.batch_room), and every array
 * of doubles of a batch fills one line of its own: the header of indices
 * is padded to two lines, and the arrays after it are eight doubles, so a
 * batch's size is a multiple of a line too. A pass then reads only the
 * lines of the arrays it uses, and no load of eight lanes (AVX-512) or of
 * four (AVX2) spans two lines. */
#define BATCH_HEADER_PAD (32 - 3 * BATCH_LANES - 1)

/* The batches lie one after the other, each as long as its lanes need: a
 * batch of one-point lanes (points 1) ends where `two` would begin, so the
 * passes stream through about half the bytes for it (1664 of 3264; in a
 * settled pile most contacts touch at one point). batch_next steps over
 * one. */
typedef struct contact_batch {
  int32_t a[BATCH_LANES], b[BATCH_LANES]; /* solver bodies (the inert one in unused lanes) */
  int32_t contact[BATCH_LANES];           /* index in the contact list, -1 unused */
  int32_t points;                         /* the most points of its lanes' contacts: 1 or 2 */
  int32_t unused[BATCH_HEADER_PAD];
  double im_a[BATCH_LANES], ii_a[BATCH_LANES], im_b[BATCH_LANES], ii_b[BATCH_LANES];
  double friction[BATCH_LANES], slop[BATCH_LANES], max_push[BATCH_LANES];
  batch_point p0;
  batch_pair two;                         /* points 2 only */
} contact_batch;

/* (C99 has no static assertion: an array of -1 elements if they fail) */
typedef char batch_header_is_two_lines[offsetof (contact_batch, im_a) == 128 ? 1 : -1];
typedef char batch_sizes_are_lines[sizeof (contact_batch) % 64 == 0 && offsetof (contact_batch, two) % 64 == 0 ? 1 : -1];

/* The bytes a batch of `points`-point lanes takes. */
#define CONTACT_BATCH_SIZE(points) ((points) > 1 ? sizeof (contact_batch) : offsetof (contact_batch, two))

/* Point j of batch c (0 or 1; 1 only where it has two). */
#define BATCH_POINT(c, j) ((j) == 0 ? &(c)->p0 : &(c)->two.p1)

/* The batch after c. */
static inline contact_batch *batch_next (const contact_batch *c)
{
  return (contact_batch *) ((char *) c + CONTACT_BATCH_SIZE (c->points));
}

/* The path this CPU runs best (AVX2 where the CPU has it). */
solver_path solver_path_best (void);
/* Whether this CPU can run `path`. */
int solver_path_available (solver_path path);

/* The colour of a constraint between moving-or-not bodies with colour sets
 * used_a, used_b (NULL: the body does not move and takes no colour), marked
 * as used in both; -1 when every colour is taken. */
int32_t constraint_colour (uint32_t *used_a, uint32_t *used_b);

/* Colour the contacts contact_prepare set up and pack the batchable ones
 * (marking them contact.batched); the rest stay for contact_solver.c.
 * Where contact_prepare packed them as it set them up (contacts.packed),
 * only the lanes of those the cold start changed are packed again. */
void contact_batch_prepare (struct carom_world *world, const step_context *ctx);
/* Its parts, for a set-up that packs each contact while its points are at
 * hand: the colouring and the batches' layout (contact.fine too, which
 * decides what is batched; contact.batched marks those that are), then
 * contact i's lane, contact_prepare having set it up, the contacts taken
 * in list order. */
void contact_batch_plan (struct carom_world *world, const step_context *ctx);
/* (contact_batch_pack is contact_batch_pack.h's) */
/* The passes of contact_solver.h over the batches. */
void contact_batch_warm_start (struct carom_world *world);
void contact_batch_solve (struct carom_world *world, const step_context *ctx);
void contact_batch_push_out (struct carom_world *world, const step_context *ctx, int first);
/* contact_batch_solve, then contact_batch_push_out (first), in one walk
 * over the batches, with the same results: the push-out reads nothing the
 * solve writes. The solver runs it as the sub-step's last solve pass, where
 * nothing but velocity passes comes before its first push-out. */
void contact_batch_solve_push_out (struct carom_world *world, const step_context *ctx);
/* The impulses the batches accumulated back into their contacts (for the
 * next step's warm start and for carom_world_get_contacts). */
void contact_batch_store (struct carom_world *world);

/* One path's kernels (contact_batch_kernel.h, and shock propagation's,
 * shock_kernel.h): the portable ones (contact_batch.c) and, where the
 * compiler builds them (BATCH_X86_KERNELS), the AVX2 and AVX-512 ones
 * (contact_batch_avx2.c, contact_batch_avx512.c with shock_avx512.c). */
struct shock_batch;
typedef struct batch_kernels {
  void (*warm_start) (contact_batch *c, int32_t n, struct solver_body *sb);
  void (*solve) (contact_batch *c, int32_t n, struct solver_body *sb, double inv_h);
  void (*push_out) (contact_batch *c, int32_t n, struct solver_body *sb, double push_rate, int first);
  void (*solve_push_out) (contact_batch *c, int32_t n, struct solver_body *sb, double inv_h, double push_rate);
  /* over n shock batches whose lanes have `points` points (1 or 2); tol
   * and inv_h as shock.c's pass */
  void (*shock) (struct shock_batch *c, int32_t n, int points, struct solver_body *sb, double tol, double inv_h,
                 int32_t moves);
} batch_kernels;

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
#define BATCH_X86_KERNELS 1
#endif

extern const batch_kernels batch_kernels_portable;
#ifdef BATCH_X86_KERNELS
extern const batch_kernels batch_kernels_avx2, batch_kernels_avx512;
/* (shock_avx512.c's, in batch_kernels_avx512) */
void shock_batch_solve_avx512 (struct shock_batch *c, int32_t n, int points, struct solver_body *sb, double tol,
                               double inv_h, int32_t moves);
#endif

/* The kernels of `path` (one the CPU has, solver_path_available). */
const batch_kernels *batch_kernels_of (solver_path path);

#endif
