/* Shock propagation's rows solved four at a time (shock.c).
 *
 * A row of the pass reads both its bodies and writes its upper one. Rows
 * are put in waves: a row goes one wave after the last that wrote either
 * of its bodies (in level order no row writes a body an earlier one read:
 * shock.c's make_waves). Within a wave no two rows share a body that one
 * of them writes, so its rows can be solved in any order, or at once, and
 * the pass gives the level order's results to the bit. Each wave's rows of one and of two points are packed
 * into batches of four lanes (structure of arrays); one kernel, written
 * once over the lanes in contact_batch_kernel.h's operations
 * (shock_kernel.h), solves them on the portable path and on AVX2 with the
 * same bits. Rows of more points stay rows, solved one at a time within
 * their wave. */
#ifndef CAROM_SHOCK_BATCH_H
#define CAROM_SHOCK_BATCH_H

#include <stddef.h>
#include <stdint.h>

#include "contact_batch.h"
#include "vec2.h"

struct solver_body;

/* What the pass reads of a contact it may hold, copied once per step
 * (contact_shock_prepare): into a batch's lane for a row of one or two
 * points, into a row for one of more points or when the rows are solved
 * one at a time (in level order), so the passes stream through it:
 * which body is the upper one, and its share of the point's effective mass
 * with the lower body held still. A row's points follow those of the row
 * before it in world.shock_points: rows of one or two points (nearly all)
 * take no room for the four a contact may have. The impulse raises vn:
 * +x n on b, or -x n on a; its sign is folded into im_up and ang (x times
 * -1 is exact, so the upper body moves by the same bits either way). */
typedef struct shock_point {
  vec2 normal, ra, rb;
  double adjusted, rn_a, rn_b;
  double mass;         /* up->im + up->ii r_up^2, r_up = r x n at the upper body */
  double ang;          /* up->ii r_up, negated when the upper body is a */
  double gap;          /* what a speculative gap lets the point approach by
                          (shock_gap), at the positions gap_at */
} shock_point;

/* shock_row.kind of a block (which has two points) */
#define SHOCK_FACE 0

typedef struct shock_row {
  /* the solver bodies (solver_bodies does not move within a step), and
   * the upper one, which alone takes the impulse */
  const struct solver_body *a, *b;
  struct solver_body *up;
  int32_t count;
  int32_t kind;        /* SHOCK_FACE for a block, else count */
  int32_t gap_at;      /* the positions of the points' gaps (contact_shock's
                          `moves`), -1 before the first */
  double im_up;        /* up->im, negated when the upper body is a */
  double k11, k12, k22; /* the 2x2 matrix with the lower body held (block) */
  shock_point *p;       /* its `count` points */
} shock_row;

/* The lanes of a shock batch: four on every path (a wave rarely has more
 * rows to fill eight). */
#define SHOCK_LANES 4

/* One point of a batch's four lanes: shock.c's shock_point. */
typedef struct shock_lane_point {
  double nx[SHOCK_LANES], ny[SHOCK_LANES];
  double ra_x[SHOCK_LANES], ra_y[SHOCK_LANES], rb_x[SHOCK_LANES], rb_y[SHOCK_LANES];
  double adjusted[SHOCK_LANES], rn_a[SHOCK_LANES], rn_b[SHOCK_LANES];
  double mass[SHOCK_LANES], ang[SHOCK_LANES];
  double gap[SHOCK_LANES]; /* kept at the positions gap_at */
} shock_lane_point;

/* Four rows (unused lanes on the inert body, every number 0). A batch of
 * one-point rows never reads its second point's bytes. The batches begin
 * on a cache line (world.shock_room); the header of indices fills one, and
 * each array of four doubles half of one: no load of a row spans two. */
typedef struct shock_batch {
  int32_t a[SHOCK_LANES], b[SHOCK_LANES], up[SHOCK_LANES]; /* solver bodies; up is a or b */
  int32_t gap_at;                                          /* as shock_row.gap_at */
  int32_t unused[3];                                       /* (to a line) */
  double up_is_a[SHOCK_LANES]; /* 1 where the upper body is a */
  double im_up[SHOCK_LANES];
  double face[SHOCK_LANES];    /* 1 where the row is a block (two points) */
  double k11[SHOCK_LANES], k12[SHOCK_LANES], k22[SHOCK_LANES];
  shock_lane_point p[2];
} shock_batch;

/* (C99 has no static assertion: an array of -1 elements if they fail) */
typedef char shock_header_is_a_line[offsetof (shock_batch, up_is_a) == 64 && sizeof (shock_batch) % 32 == 0 ? 1 : -1];

#endif
