/* Contacts solved in batches of eight lanes (contact_batch.h): colouring,
 * packing, the portable kernels and the choice of path. */
#include "contact_batch.h"
#include "contact_batch_pack.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "contact_solver.h"
#include "shock_batch.h"
#include "world.h"

/* ------------------------------------------------------------ colouring */

/* constraint_colour, inlined into the colouring of the contacts, where
 * which bodies move is known at each call. */
ALWAYS_INLINE int32_t pick_colour (uint32_t *used_a, uint32_t *used_b)
{
  uint32_t taken = (used_a ? *used_a : 0u) | (used_b ? *used_b : 0u), bit;
  int32_t colour = 0;
  if (taken == 0xffffffffu)
    return -1;
  /* the lowest clear bit */
#ifdef __GNUC__
  colour = __builtin_ctz (~taken);
  bit = 1u << colour;
#else
  for (bit = 1u; taken & bit; bit <<= 1)
    ++colour;
#endif
  if (used_a)
    *used_a |= bit;
  if (used_b)
    *used_b |= bit;
  return colour;
}

int32_t constraint_colour (uint32_t *used_a, uint32_t *used_b)
{
  return pick_colour (used_a, used_b);
}

/* What the batches solve: contacts whose whole step is the sub-steps'
 * passes. Restitution, the extra passes of small bodies and manifolds of
 * more than two points stay with contact_solver.c. */
static int batchable (const contact *k)
{
  return k->count >= 1 && k->count <= 2 && k->restitution == 0.0 && !k->fine;
}

/* The key a contact is packed by: its colour's two-point contacts, then its
 * one-point ones. */
static int32_t pack_key (const contact *k, int32_t colour)
{
  return 2 * colour + (k->count == 1);
}

/* A batchable contact's colour, as its pack_key in keys[i] (left -1 when
 * every colour is taken), marking it batched. `pass` 1 colours the
 * contacts with a body that does not move. */
ALWAYS_INLINE void colour_contact (contact *ct, int32_t i, int pass, int ma, int mb, uint32_t *used, int32_t *keys,
                                   int32_t *end)
{
  int32_t colour = pick_colour (ma ? &used[ct->a] : NULL, mb ? &used[ct->b] : NULL);
  if (colour >= 0)
    {
      keys[i] = pack_key (ct, colour + pass * CONSTRAINT_COLOURS);
      ct->batched = 1;
      end[keys[i] + 1]++;
    }
}

void contact_batch_plan (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  uint32_t *used = world->colour_used;
  batch_plan p = plan_of (world);
  int32_t *keys = p.keys, *order = p.order, *end = p.end;
  /* the contacts the second colouring takes, in list order, in the room
   * `order` has until the layout */
  int32_t *apart = order, apart_count = 0;
  int32_t i, k, n = 0;
  /* how far a body falls in the step with nothing to hold it
   * (contact_fine_passes) */
  const double fall = 0.5 * ctx->accel * ctx->dt * ctx->dt;
  for (i = 0; i <= 4 * CONSTRAINT_COLOURS; ++i)
    end[i] = 0;
  for (i = 0; i < world->slot_count; ++i)
    used[i] = 0u;
  /* greedy, in list order: each contact takes the first colour free at
   * both of its moving bodies. Contacts with a body that does not move (the
   * ground, a wall) are coloured apart, in colours solved after all the
   * others: then, as in sequential passes that reach the ground last,
   * nothing undoes within the pass what they did, and a squeezed pile
   * cannot press its bodies into the walls. */
  for (i = 0; i < c->count; ++i)
    {
      contact *ct = &c->list[i];
      keys[i] = -1;
      ct->batched = 0;
      ct->fine = contact_fine_passes (fall, ct->slop);
      if (!batchable (ct))
        continue;
      if (sb[ct->a].moves == MOVES_DYNAMIC && sb[ct->b].moves == MOVES_DYNAMIC)
        colour_contact (ct, i, 0, 1, 1, used, keys, end);
      else
        apart[apart_count++] = i;
    }
  /* the second colouring starts from no colour taken at the bodies it
   * reads: the moving bodies of its own contacts */
  for (k = 0; k < apart_count; ++k)
    {
      const contact *ct = &c->list[apart[k]];
      used[ct->a] = used[ct->b] = 0u;
    }
  for (k = 0; k < apart_count; ++k)
    {
      contact *ct = &c->list[apart[k]];
      colour_contact (ct, apart[k], 1, sb[ct->a].moves == MOVES_DYNAMIC, sb[ct->b].moves == MOVES_DYNAMIC, used,
                      keys, end);
    }
  /* Where each contact goes: a colour's batches hold its two-point
   * contacts, then its one-point ones, each kind in list order, eight to a
   * batch (a batch's unused lanes are its last), the colour's first at a
   * batch of its own. Place p is lane p % 8 of batch p / 8; `end` becomes
   * each kind's next place, and `order` tells each batch where it lies.
   * The contacts are packed in list order (contact_batch_pack), each as its
   * set-up leaves it: packed in the colours' order, the reads jumped through
   * the list and waited on memory (docs/performance.md). */
  {
    int32_t place = 0, twos = 0;
    for (k = 0; k < 2 * CONSTRAINT_COLOURS; ++k)
      {
        int32_t two = end[2 * k + 1], lanes = two + end[2 * k + 2], first = place / BATCH_LANES, j, lane;
        end[2 * k + 1] = place;
        end[2 * k + 2] = place + two;
        for (j = 0; j * BATCH_LANES < lanes; ++j)
          {
            int points = j * BATCH_LANES < two ? 2 : 1;
            contact_batch *batch = batch_at (world->batches, first + j, twos);
            order[first + j] = twos;
            twos += points == 2;
            batch->points = points;
            for (lane = lanes - j * BATCH_LANES; lane < BATCH_LANES; ++lane)
              pack_empty_lane (batch, lane, world->slot_count, points);
            ++n;
          }
        place += (lanes + BATCH_LANES - 1) / BATCH_LANES * BATCH_LANES;
      }
  }
  world->batch_count = n;
}

/* The rest, in list order, for contact_solver.c's passes (in the room the
 * keys took, each read before it is written over), and the fine ones among
 * them, in the same order, for the passes that solve those alone (in the
 * room the batches' order took: the lanes are packed). */
static void contact_batch_finish (carom_world *world)
{
  contacts *c = &world->contacts;
  batch_plan p = plan_of (world);
  int32_t *keys = p.keys, *order = p.order;
  int32_t i, k, fine_count = 0, fine_passes = 0;
  for (i = 0, k = 0; i < c->count; ++i)
    if (keys[i] < 0)
      {
        int32_t fine = c->list[i].fine;
        keys[k++] = i;
        /* by a select: which are fine is not predictable */
        order[fine_count] = i;
        fine_count += fine != 0;
        fine_passes = fine > fine_passes ? fine : fine_passes;
      }
  c->rest = keys;
  c->rest_count = k;
  c->fine_rest = order;
  c->fine_rest_count = fine_count;
  c->fine_passes = fine_passes;
}

void contact_batch_prepare (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  int32_t i;
  if (!c->packed)
    {
      contact_batch_plan (world, ctx);
      for (i = 0; i < c->count; ++i)
        if (c->list[i].batched)
          contact_batch_pack (world, i);
    }
  else if (c->cold_count > 0)
    {
      /* the cold start gave these their impulses after they were packed */
      const int32_t *order = plan_of (world).order;
      for (i = 0; i < c->count; ++i)
        if (c->list[i].batched && c->list[i].cold)
          pack_at (world, order, i);
    }
  c->packed = 0;
  contact_batch_finish (world);
}

void contact_batch_store (carom_world *world)
{
  contacts *c = &world->contacts;
  int32_t i;
  int lane, j;
  const contact_batch *b = world->batches;
  for (i = 0; i < world->batch_count; ++i, b = batch_next (b))
    {
      for (lane = 0; lane < BATCH_LANES; ++lane)
        {
          contact *k;
          if (b->contact[lane] < 0)
            continue;
          k = &c->list[b->contact[lane]];
          for (j = 0; j < k->count; ++j)
            {
              const batch_point *q = BATCH_POINT (b, j);
              k->points[j].normal_impulse = q->normal_impulse[lane];
              k->points[j].tangent_impulse = q->tangent_impulse[lane];
              k->points[j].total_impulse = q->total[lane];
            }
        }
    }
}

/* ------------------------------------------------------------ the paths */

/* The AVX2 kernels read a solver body's first twelve doubles as three rows
 * of four (contact_batch_kernel.h): v.x v.y w -, pv.x pv.y pw -, dp.x dp.y
 * dq.c dq.s. */
typedef char solver_body_layout[(offsetof (solver_body, v) == 0 && offsetof (solver_body, w) == 16
                                 && offsetof (solver_body, pv) == 32 && offsetof (solver_body, pw) == 48
                                 && offsetof (solver_body, dp) == 64 && offsetof (solver_body, dq) == 80
                                 && sizeof (rot2) == 16 && sizeof (vec2) == 16)
                                    ? 1
                                    : -1];

int solver_path_available (solver_path path)
{
  if (path == SOLVER_PATH_PORTABLE)
    return 1;
#ifdef BATCH_X86_KERNELS
  __builtin_cpu_init ();
  if (path == SOLVER_PATH_AVX2)
    return __builtin_cpu_supports ("avx2") != 0;
  if (path == SOLVER_PATH_AVX512)
    return __builtin_cpu_supports ("avx2") && __builtin_cpu_supports ("avx512f")
           && __builtin_cpu_supports ("avx512vl");
#endif
  return 0;
}

solver_path solver_path_best (void)
{
  if (solver_path_available (SOLVER_PATH_AVX512))
    return SOLVER_PATH_AVX512;
  return solver_path_available (SOLVER_PATH_AVX2) ? SOLVER_PATH_AVX2 : SOLVER_PATH_PORTABLE;
}

const batch_kernels *batch_kernels_of (solver_path path)
{
#ifdef BATCH_X86_KERNELS
  if (path == SOLVER_PATH_AVX512)
    return &batch_kernels_avx512;
  if (path == SOLVER_PATH_AVX2)
    return &batch_kernels_avx2;
#else
  (void) path;
#endif
  return &batch_kernels_portable;
}

#ifdef CAROM_DEBUG_CHECKS
/* What lets lanes share a body that does not move (contact_batch.h): it
 * has no velocity of -0. */
static void check_still_bodies (const carom_world *world)
{
  int32_t i;
  for (i = 0; i <= world->slot_count; ++i)
    {
      const solver_body *b = &world->solver_bodies[i];
      int negative_zero = (b->v.x == 0.0 && signbit (b->v.x)) || (b->v.y == 0.0 && signbit (b->v.y))
                          || (b->w == 0.0 && signbit (b->w)) || (b->pv.x == 0.0 && signbit (b->pv.x))
                          || (b->pv.y == 0.0 && signbit (b->pv.y)) || (b->pw == 0.0 && signbit (b->pw));
      if ((i == world->slot_count || b->moves != MOVES_DYNAMIC) && negative_zero)
        {
          fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: solver body %d, which does not move, has a velocity of -0\n",
                   (int) i);
          abort ();
        }
    }
}
#else
#define check_still_bodies(world) ((void) 0)
#endif

void contact_batch_warm_start (carom_world *world)
{
  check_still_bodies (world);
  batch_kernels_of ((solver_path) world->solver_path)->warm_start (world->batches, world->batch_count,
                                                                    world->solver_bodies);
}

void contact_batch_solve (carom_world *world, const step_context *ctx)
{
  check_still_bodies (world);
  batch_kernels_of ((solver_path) world->solver_path)->solve (world->batches, world->batch_count,
                                                               world->solver_bodies, ctx->inv_h);
}

void contact_batch_push_out (carom_world *world, const step_context *ctx, int first)
{
  check_still_bodies (world);
  batch_kernels_of ((solver_path) world->solver_path)->push_out (world->batches, world->batch_count,
                                                                  world->solver_bodies, ctx->push_rate, first);
}

void contact_batch_solve_push_out (carom_world *world, const step_context *ctx)
{
  check_still_bodies (world);
  batch_kernels_of ((solver_path) world->solver_path)->solve_push_out (world->batches, world->batch_count,
                                                                        world->solver_bodies, ctx->inv_h,
                                                                        ctx->push_rate);
}

/* ------------------------------------------------- the portable kernels */

/* four lanes at a time, as the AVX2 kernels */
#define KERNEL_WIDTH 4

typedef struct wide {
  double l[KERNEL_WIDTH];
} wide;
typedef struct wmask {
  int l[KERNEL_WIDTH];
} wmask;

#define LANEWISE(expr)                                                                                             \
  int i;                                                                                                           \
  for (i = 0; i < KERNEL_WIDTH; ++i)                                                                               \
    r.l[i] = (expr);                                                                                               \
  return r

ALWAYS_INLINE wide w_load (const double *p) { wide r; LANEWISE (p[i]); }
ALWAYS_INLINE void w_store (double *p, wide x) { int i; for (i = 0; i < KERNEL_WIDTH; ++i) p[i] = x.l[i]; }
ALWAYS_INLINE wide w_set1 (double d) { wide r; LANEWISE (d); }
ALWAYS_INLINE wide w_add (wide a, wide b) { wide r; LANEWISE (a.l[i] + b.l[i]); }
ALWAYS_INLINE wide w_sub (wide a, wide b) { wide r; LANEWISE (a.l[i] - b.l[i]); }
ALWAYS_INLINE wide w_mul (wide a, wide b) { wide r; LANEWISE (a.l[i] * b.l[i]); }
ALWAYS_INLINE wide w_div (wide a, wide b) { wide r; LANEWISE (a.l[i] / b.l[i]); }
ALWAYS_INLINE wide w_neg (wide a) { wide r; LANEWISE (-a.l[i]); }
ALWAYS_INLINE wide w_max (wide a, wide b) { wide r; LANEWISE (a.l[i] > b.l[i] ? a.l[i] : b.l[i]); }
ALWAYS_INLINE wide w_min (wide a, wide b) { wide r; LANEWISE (a.l[i] < b.l[i] ? a.l[i] : b.l[i]); }
ALWAYS_INLINE wmask m_gt (wide a, wide b) { wmask r; LANEWISE (a.l[i] > b.l[i]); }
ALWAYS_INLINE wmask m_ge (wide a, wide b) { wmask r; LANEWISE (a.l[i] >= b.l[i]); }
ALWAYS_INLINE wmask m_lt (wide a, wide b) { wmask r; LANEWISE (a.l[i] < b.l[i]); }
ALWAYS_INLINE wmask m_ne (wide a, wide b) { wmask r; LANEWISE (a.l[i] != b.l[i]); }
ALWAYS_INLINE wmask m_and (wmask a, wmask b) { wmask r; LANEWISE (a.l[i] & b.l[i]); }
ALWAYS_INLINE wmask m_or (wmask a, wmask b) { wmask r; LANEWISE (a.l[i] | b.l[i]); }
ALWAYS_INLINE wmask m_andnot (wmask a, wmask b) { wmask r; LANEWISE (a.l[i] & !b.l[i]); }
ALWAYS_INLINE wide w_sel (wmask m, wide a, wide b) { wide r; LANEWISE (m.l[i] ? a.l[i] : b.l[i]); }
ALWAYS_INLINE int m_any (wmask m) { return m.l[0] | m.l[1] | m.l[2] | m.l[3]; }

#define W_LOAD w_load
#define W_STORE w_store
#define W_SET1 w_set1
#define W_ADD w_add
#define W_SUB w_sub
#define W_MUL w_mul
#define W_DIV w_div
#define W_NEG w_neg
#define W_MAX w_max
#define W_MIN w_min
#define M_GT m_gt
#define M_GE m_ge
#define M_LT m_lt
#define M_NE m_ne
#define M_AND m_and
#define M_OR m_or
#define M_ANDNOT m_andnot
#define W_SEL w_sel
#define M_ANY m_any
#define KERNEL(name) name##_portable
#define KERNEL_ATTR

#include "contact_batch_kernel.h"
#include "shock_kernel.h"

const batch_kernels batch_kernels_portable
    = { contact_batch_warm_start_portable, contact_batch_solve_portable, contact_batch_push_out_portable,
        contact_batch_solve_push_out_portable, shock_batch_solve_portable };
