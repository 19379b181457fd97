/* The coloured batches (lib/contact_batch.c): a proper colouring, and the
 * same bits from every solver path this CPU has. */
#include "support.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact_batch.h"
#include "contact_batch_pack.h"
#include "contact_solver.h"
#include "shock_batch.h"
#include "solver.h"
#include "world.h"

/* A pile with every kind of contact the batches take and leave: a
 * pyramid (two-point faces, the 2x2 block), tumbling polygons and circles
 * (one-point contacts, friction), a body 50 times heavier than the boxes it
 * lands on (shock propagation), a bouncy ball and a concave polygon (left
 * to the one-at-a-time passes). */
static carom_world *pile (void)
{
  static const double notch[] = { -0.6, -0.4, 0.6, -0.4, 0.6, 0.4, 0.0, 0.0, -0.6, 0.4 };
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  uint32_t seed = 12345u;
  int row, i;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 0.6;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 60.0, 1.0);
  for (row = 0; row < 8; ++row)
    for (i = 0; i < 8 - row; ++i)
      add_box (w, CAROM_DYNAMIC, -10.0 + 1.05 * i + 0.525 * row, 0.5 + 1.0 * row, 0.0, 1.0, 1.0);
  for (i = 0; i < 40; ++i)
    {
      seed = seed * 1664525u + 1013904223u;
      carom_body_def_init (&d, sizeof d);
      d.x = 2.0 + (double) (i % 8) * 1.3, d.y = 1.0 + (double) (i / 8) * 1.4;
      d.angle = (double) (seed >> 8) / 16777216.0;
      d.spin = 0.5 * (double) (i % 3);
      if (i % 3 == 0)
        assert_status (carom_world_add_circle (w, &d, 0.4 + 0.02 * (i % 5), NULL), CAROM_OK);
      else
        assert_status (carom_world_add_regular (w, &d, 3 + i % 5, 0.5, NULL), CAROM_OK);
    }
  carom_body_def_init (&d, sizeof d);
  d.x = -7.0, d.y = 12.0, d.density = 50.0;
  assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.x = 14.0, d.y = 4.0, d.restitution = 0.8;
  assert_status (carom_world_add_circle (w, &d, 0.3, NULL), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  d.x = 16.0, d.y = 2.0;
  assert_status (carom_world_add_polygon (w, &d, notch, 5, NULL), CAROM_OK);
  {
    /* two compounds, a dumbbell and the notch on a disc, landing on the pile */
    carom_shape_def parts[2];
    int k;
    for (k = 0; k < 2; ++k)
      assert_status (carom_shape_def_init (&parts[k], sizeof parts[k]), CAROM_OK);
    parts[0].radius = 0.4, parts[0].x = -0.8;
    parts[1].radius = 0.3, parts[1].x = 0.8, parts[1].friction = 0.1;
    carom_body_def_init (&d, sizeof d);
    d.x = -6.0, d.y = 10.0, d.spin = 1.0;
    assert_status (carom_world_add_compound (w, &d, parts, 2, NULL), CAROM_OK);
    parts[1].kind = CAROM_SHAPE_POLYGON, parts[1].xy = notch, parts[1].count = 5, parts[1].y = 0.5;
    d.x = -4.0, d.y = 14.0;
    assert_status (carom_world_add_compound (w, &d, parts, 2, NULL), CAROM_OK);
  }
  /* a row of boxes side by side and one sliding into a wall: normals along
   * x, whose zero y the paths must negate alike */
  for (i = 0; i < 4; ++i)
    add_box (w, CAROM_DYNAMIC, 20.0 + 1.0 * i, 0.5, 0.0, 1.0, 1.0);
  add_box (w, CAROM_STATIC, 25.0, 1.0, 0.0, 1.0, 2.0);
  carom_body_def_init (&d, sizeof d);
  d.x = 23.0, d.y = 1.5, d.vx = 2.0;
  assert_status (carom_world_add_box (w, &d, 0.8, 0.8, NULL), CAROM_OK);
  return w;
}

/* In every batch the lanes' moving bodies are distinct (they are solved at
 * once), every batched contact sits in exactly one lane, the one its place
 * names, no lane's contact has more points than its batch solves, and a
 * contact left out is one the batches do not take or one whose bodies used
 * every colour. Counts the batches of one-point lanes alone in *single. */
static void check_batches (const carom_world *w, int32_t *batched_total, int32_t *single)
{
  const contacts *c = &w->contacts;
  int32_t i, lanes = 0, marked = 0;
  int l, m;
  const contact_batch *b = w->batches;
  for (i = 0; i < w->batch_count; ++i, b = batch_next (b))
    {
      assert_true (b->points == 1 || b->points == 2);
      *single += b->points == 1;
      for (l = 0; l < BATCH_LANES; ++l)
        {
          int32_t body[2];
          if (b->contact[l] < 0)
            {
              assert_int_equal (b->a[l], w->slot_count);
              assert_int_equal (b->b[l], w->slot_count);
              continue;
            }
          ++lanes;
          /* lane l of batch i is place 4 i + l: one past it is what the
           * contact holds (the cold start packs it again from there) */
          assert_int_equal (c->list[b->contact[l]].batched, BATCH_LANES * i + l + 1);
          assert_true (c->list[b->contact[l]].count <= b->points);
          body[0] = b->a[l], body[1] = b->b[l];
          for (m = l + 1; m < BATCH_LANES; ++m)
            {
              int s;
              if (b->contact[m] < 0)
                continue;
              assert_true (b->contact[m] != b->contact[l]);
              for (s = 0; s < 2; ++s)
                if (w->solver_bodies[body[s]].moves == MOVES_DYNAMIC)
                  assert_true (b->a[m] != body[s] && b->b[m] != body[s]);
            }
        }
    }
  for (i = 0; i < c->count; ++i)
    marked += c->list[i].batched != 0;
  assert_int_equal (lanes, marked);
  *batched_total += marked;
}

static void test_batches_are_properly_coloured (void **state)
{
  carom_world *w = pile ();
  int32_t step, batched = 0, leftover = 0, single = 0, batches = 0;
  (void) state;
  for (step = 0; step < 240; ++step)
    {
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      check_batches (w, &batched, &single);
      leftover += w->contacts.count;
      batches += w->batch_count;
    }
  leftover -= batched;
  /* both kinds of contact happened, and both kinds of batch */
  assert_true (batched > 1000 && leftover > 0);
  assert_true (single > 100 && batches - single > 100);
  carom_world_destroy (w);
}

static void test_constraint_colour_takes_the_first_free (void **state)
{
  uint32_t a = 0, b = 0;
  int32_t k;
  (void) state;
  assert_int_equal (constraint_colour (&a, &b), 0);
  assert_int_equal (constraint_colour (&a, NULL), 1);
  assert_int_equal (constraint_colour (NULL, &b), 1);
  assert_int_equal (constraint_colour (&a, &b), 2);
  assert_int_equal (constraint_colour (NULL, NULL), 0);
  for (k = 3; k < CONSTRAINT_COLOURS; ++k)
    assert_int_equal (constraint_colour (&a, NULL), k);
  assert_true (a == 0xffffffffu);
  /* every colour taken at a: left over, and b keeps its colours */
  assert_int_equal (constraint_colour (&a, &b), -1);
  assert_true (b == 0x7u);
}

/* The same pile on every path the CPU has: the same bits at every step. */
static void test_every_path_gives_the_same_bits (void **state)
{
  const int paths[SOLVER_PATHS] = { SOLVER_PATH_PORTABLE, SOLVER_PATH_AVX2, SOLVER_PATH_AVX512 };
  uint64_t hash[SOLVER_PATHS][200];
  int p, step, ran = 0, q;
  (void) state;
  for (p = 0; p < SOLVER_PATHS; ++p)
    {
      carom_world *w;
      if (!solver_path_available ((solver_path) paths[p]))
        {
          printf ("solver path %d: not on this CPU, not compared\n", paths[p]);
          continue;
        }
      w = pile ();
      assert_true (world_set_solver_path (w, paths[p]));
      for (step = 0; step < 200; ++step)
        {
          assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
          hash[ran][step] = world_state_hash (w);
        }
      carom_world_destroy (w);
      ++ran;
    }
  for (q = 1; q < ran; ++q)
    for (step = 0; step < 200; ++step)
      if (hash[0][step] != hash[q][step])
        fail_msg ("path %d of those this CPU has differs from the portable one from step %d", q, step);
  /* the default is the best path */
  {
    carom_world *w = pile ();
    assert_int_equal (w->solver_path, (int) solver_path_best ());
    /* the best is the last of the paths the CPU has: AVX-512 over AVX2
     * over the portable kernels */
    for (q = SOLVER_PATHS - 1; !solver_path_available ((solver_path) q); --q)
      ;
    assert_int_equal (w->solver_path, q);
    assert_false (world_set_solver_path (w, 99));
    carom_world_destroy (w);
  }
}

/* The kernels themselves, on batches made up lane by lane: every pass on
 * every path the CPU has gives the same bits, the signs of zeros too. The
 * kernels of four lanes take a batch of eight in two groups; AVX-512's
 * takes it at once, skipping a part of a pass only for a group that has no
 * lane in it (batch_lanes.h): velocities of -0 on bodies that move, lanes
 * that take a push beside lanes that do not, 2x2 blocks beside points
 * solved alone, speculative gaps and overlaps, batches with an empty
 * second group and with a part-filled one. Bodies that do not move have no
 * velocity of -0 (solver.c's gather), and are shared by lanes. */
#define KB_BATCHES 96
/* three that do not move, and two for each lane of each batch: no batch
 * moves another's bodies, which would make a zero of one a number again */
#define KB_BODIES (3 + 2 * BATCH_LANES * KB_BATCHES)

static uint32_t kb_seed;

static double kb_uniform (double lo, double hi)
{
  kb_seed = kb_seed * 1664525u + 1013904223u;
  return lo + (hi - lo) * (double) (kb_seed >> 8) / 16777216.0;
}

/* a velocity: a third exactly -0 or +0 */
static double kb_velocity (void)
{
  double u = kb_uniform (0.0, 1.0);
  return u < 0.17 ? -0.0 : u < 0.33 ? 0.0 : kb_uniform (-2.0, 2.0);
}

/* mode 0: apart, no push so far; 1: anything; 2: overlapping */
static void kb_point (batch_point *q, int lane, int apart, int mode)
{
  double a = kb_uniform (0.0, 6.283185307179586);
  /* some normals along an axis exactly, whose other part is +0 or -0 */
  double nx = apart ? 0.0 : cos (a), ny = apart ? 1.0 : sin (a);
  if (kb_uniform (0.0, 1.0) < 0.2)
    nx = -0.0;
  q->nx[lane] = nx, q->ny[lane] = ny;
  q->ra_x[lane] = kb_uniform (-0.5, 0.5), q->ra_y[lane] = kb_uniform (-0.5, 0.5);
  q->rb_x[lane] = kb_uniform (-0.5, 0.5), q->rb_y[lane] = kb_uniform (-0.5, 0.5);
  q->adjusted[lane] = mode == 0 ? kb_uniform (0.01, 0.02) : mode == 2 ? kb_uniform (-0.03, -0.01) : kb_uniform (-0.03, 0.02);
  q->rn_a[lane] = q->ra_x[lane] * ny - q->ra_y[lane] * nx;
  q->rn_b[lane] = q->rb_x[lane] * ny - q->rb_y[lane] * nx;
  q->rt_a[lane] = q->ra_x[lane] * nx + q->ra_y[lane] * ny;
  q->rt_b[lane] = q->rb_x[lane] * nx + q->rb_y[lane] * ny;
  q->normal_mass[lane] = kb_uniform (0.2, 2.0);
  q->tangent_mass[lane] = kb_uniform (0.2, 2.0);
  q->normal_impulse[lane] = kb_uniform (0.0, 1.0) < 0.3 ? 0.0 : kb_uniform (0.0, 0.5);
  q->tangent_impulse[lane] = kb_uniform (0.0, 1.0) < 0.3 ? 0.0 : kb_uniform (-0.2, 0.2);
  q->push_impulse[lane] = mode == 0 || kb_uniform (0.0, 1.0) < 0.5 ? 0.0 : kb_uniform (0.0, 0.1);
  q->total[lane] = 0.0;
}

/* New velocities and pseudo-velocities for the bodies that move, a third
 * of them zeros of either sign. */
static void kb_refresh (solver_body *sb)
{
  int i;
  for (i = 3; i < KB_BODIES; ++i)
    {
      sb[i].v = v2 (kb_velocity (), kb_velocity ());
      sb[i].w = kb_velocity ();
      sb[i].pv = v2 (kb_velocity (), kb_velocity ());
      sb[i].pw = kb_velocity ();
    }
}

/* Batches, one after the other, into `room`; their count of lanes used
 * into used[]. Bodies 0-2 do not move; KB_BODIES is the inert body. */
static size_t kb_batches (unsigned char *room, solver_body *sb, int *used)
{
  size_t at = 0;
  int i, lane, j;
  for (i = 0; i < KB_BODIES + 1; ++i)
    {
      solver_body *b = &sb[i];
      double t = kb_uniform (-0.05, 0.05);
      memset (b, 0, sizeof *b);
      if (i >= 3 && i < KB_BODIES)
        {
          b->v = v2 (kb_velocity (), kb_velocity ());
          b->w = kb_velocity ();
          b->pv = v2 (kb_velocity (), kb_velocity ());
          b->pw = kb_velocity ();
          b->im = kb_uniform (0.2, 2.0);
          b->ii = kb_uniform (0.2, 4.0);
          b->moves = MOVES_DYNAMIC;
        }
      else if (i < 3)
        b->v = v2 (i == 1 ? 0.5 : 0.0, 0.0); /* the ground; a belt; a wall */
      b->dp = i < 3 || i == KB_BODIES ? v2 (0.0, 0.0) : v2 (kb_uniform (-0.01, 0.01), kb_uniform (-0.01, 0.01));
      b->dq.c = i < 3 || i == KB_BODIES ? 1.0 : cos (t);
      b->dq.s = i < 3 || i == KB_BODIES ? 0.0 : sin (t);
    }
  for (i = 0; i < KB_BATCHES; ++i)
    {
      contact_batch *c = (contact_batch *) (room + at);
      int points = i % 3 == 0 ? 1 : 2;
      /* full, a part-filled second group, an empty one */
      int lanes = i % 4 == 0 ? 3 : i % 4 == 1 ? 6 : BATCH_LANES;
      int apart = i % 5 == 4; /* against the bodies that do not move */
      int first = 3 + i * 2 * BATCH_LANES, mode;
      c->points = points;
      used[i] = lanes;
      for (lane = 0; lane < BATCH_LANES; ++lane)
        {
          if (lane >= lanes)
            {
              pack_empty_lane (c, lane, KB_BODIES, points);
              /* the library leaves it to a sub-step's first push-out pass;
               * here a later one may come first */
              for (j = 0; j < points; ++j)
                BATCH_POINT (c, j)->push_impulse[lane] = 0.0;
              continue;
            }
          /* each group of four alike, so that one takes a part of a pass
           * the other does not */
          mode = (i + lane / 4) % 3;
          c->contact[lane] = lane;
          /* the bodies that do not move on either side, shared by lanes */
          c->a[lane] = apart && lane % 2 == 0 ? lane % 3 : first + 2 * lane;
          c->b[lane] = apart && lane % 2 == 1 ? lane % 3 : first + 2 * lane + 1;
          c->im_a[lane] = sb[c->a[lane]].im, c->ii_a[lane] = sb[c->a[lane]].ii;
          c->im_b[lane] = sb[c->b[lane]].im, c->ii_b[lane] = sb[c->b[lane]].ii;
          c->friction[lane] = lane % 3 == 0 ? 0.0 : kb_uniform (0.1, 1.0);
          c->slop[lane] = 0.005;
          c->max_push[lane] = kb_uniform (0.1, 1.0);
          for (j = 0; j < points; ++j)
            kb_point (BATCH_POINT (c, j), lane, apart, mode);
          if (points == 2)
            {
              double k11 = kb_uniform (0.5, 2.0), k22 = kb_uniform (0.5, 2.0), k12 = kb_uniform (-0.4, 0.4);
              double det = k11 * k22 - k12 * k12;
              int pair = mode == 2 || (mode == 1 && kb_uniform (0.0, 1.0) < 0.7);
              int block = pair && (mode == 2 || kb_uniform (0.0, 1.0) < 0.7);
              c->two.k11[lane] = pair ? k11 : 0.0, c->two.k12[lane] = pair ? k12 : 0.0;
              c->two.k22[lane] = pair ? k22 : 0.0, c->two.pair[lane] = pair;
              c->two.i11[lane] = block ? k22 / det : 0.0, c->two.i12[lane] = block ? -k12 / det : 0.0;
              c->two.i22[lane] = block ? k11 / det : 0.0, c->two.block[lane] = block;
            }
        }
      at += CONTACT_BATCH_SIZE (points);
    }
  return at;
}

#define KB_ROUNDS 3
#define KB_PASSES 5

/* The bodies' bytes, summed (FNV-1a). */
static uint64_t kb_sum (const solver_body *sb)
{
  const unsigned char *b = (const unsigned char *) sb;
  uint64_t h = 14695981039346656037u;
  size_t i;
  for (i = 0; i < (KB_BODIES + 1) * sizeof (solver_body); ++i)
    h = (h ^ b[i]) * 1099511628211u;
  return h;
}

static void test_kernels_agree_lane_by_lane (void **state)
{
  static const int paths[SOLVER_PATHS] = { SOLVER_PATH_PORTABLE, SOLVER_PATH_AVX2, SOLVER_PATH_AVX512 };
  solver_body *sb[SOLVER_PATHS];
  unsigned char *room[SOLVER_PATHS];
  int used[KB_BATCHES];
  uint64_t sums[SOLVER_PATHS][KB_ROUNDS][KB_PASSES];
  size_t bytes = 0;
  int p, ran = 0, round, q, pass;
  (void) state;
  for (p = 0; p < SOLVER_PATHS; ++p)
    {
      const batch_kernels *k;
      if (!solver_path_available ((solver_path) paths[p]))
        continue;
      k = batch_kernels_of ((solver_path) paths[p]);
      sb[ran] = test_malloc ((KB_BODIES + 1) * sizeof (solver_body));
      room[ran] = test_malloc (KB_BATCHES * sizeof (contact_batch));
      kb_seed = 777u;
      bytes = kb_batches (room[ran], sb[ran], used);
      /* each pass from new velocities (the passes before would have made
       * most zeros of the bodies numbers), the bodies' bytes after it
       * summed */
      for (round = 0; round < KB_ROUNDS; ++round)
        {
          contact_batch *c = (contact_batch *) room[ran];
          uint64_t *sum = sums[ran][round];
          kb_refresh (sb[ran]);
          k->solve (c, KB_BATCHES, sb[ran], 240.0);
          sum[0] = kb_sum (sb[ran]);
          kb_refresh (sb[ran]);
          k->push_out (c, KB_BATCHES, sb[ran], 0.2 * 240.0, 1);
          sum[1] = kb_sum (sb[ran]);
          kb_refresh (sb[ran]);
          k->push_out (c, KB_BATCHES, sb[ran], 0.2 * 240.0, 0);
          sum[2] = kb_sum (sb[ran]);
          kb_refresh (sb[ran]);
          k->solve_push_out (c, KB_BATCHES, sb[ran], 240.0, 0.2 * 240.0);
          sum[3] = kb_sum (sb[ran]);
          kb_refresh (sb[ran]);
          k->warm_start (c, KB_BATCHES, sb[ran]);
          sum[4] = kb_sum (sb[ran]);
        }
      ++ran;
    }
  assert_true (bytes > 0);
  for (q = 1; q < ran; ++q)
    {
      const unsigned char *x = room[0], *y = room[q];
      int i, lane, j;
      for (round = 0; round < KB_ROUNDS; ++round)
        for (pass = 0; pass < KB_PASSES; ++pass)
          if (sums[q][round][pass] != sums[0][round][pass])
            fail_msg ("path %d of those this CPU has moves the bodies otherwise than the portable one (pass %d of "
                      "round %d)",
                      q, pass, round);
      /* the lanes' impulses (the unused lanes of a group the kernels of
       * four leave are not compared) */
      for (i = 0; i < KB_BATCHES; ++i)
        {
          const contact_batch *c = (const contact_batch *) x, *d = (const contact_batch *) y;
          for (lane = 0; lane < used[i]; ++lane)
            for (j = 0; j < c->points; ++j)
              {
                const batch_point *u = BATCH_POINT (c, j), *v = BATCH_POINT (d, j);
                if (memcmp (&u->normal_impulse[lane], &v->normal_impulse[lane], sizeof (double)) != 0
                    || memcmp (&u->tangent_impulse[lane], &v->tangent_impulse[lane], sizeof (double)) != 0
                    || memcmp (&u->push_impulse[lane], &v->push_impulse[lane], sizeof (double)) != 0
                    || memcmp (&u->total[lane], &v->total[lane], sizeof (double)) != 0)
                  fail_msg ("path %d: batch %d lane %d point %d differs from the portable path", q, i, lane, j);
              }
          x += CONTACT_BATCH_SIZE (c->points);
          y += CONTACT_BATCH_SIZE (d->points);
        }
    }
  printf ("kernels of %d paths compared on %d batches\n", ran, KB_BATCHES);
  for (q = 0; q < ran; ++q)
    {
      test_free (sb[q]);
      test_free (room[q]);
    }
}

/* What lets a batch's lanes share a body that does not move: the solver
 * gives such a body no velocity of -0 (solver.c's gather), so the +0 and -0
 * impulses it takes (its inverse masses are 0) leave it to the bit. A
 * kinematic body given -0 in every part of its velocity has +0 in the
 * solver and keeps its -0 outside it, and one under a row of boxes steps
 * on every path alike. */
static void test_bodies_that_do_not_move_have_no_negative_zero (void **state)
{
  const int paths[SOLVER_PATHS] = { SOLVER_PATH_PORTABLE, SOLVER_PATH_AVX2, SOLVER_PATH_AVX512 };
  uint64_t hash[SOLVER_PATHS];
  int p, ran = 0, i, step;
  (void) state;
  for (p = 0; p < SOLVER_PATHS; ++p)
    {
      carom_world *w = NULL;
      carom_body_id lone;
      double vx, vy, spin;
      carom_world_def def;
      carom_body_def d;
      if (!solver_path_available ((solver_path) paths[p]))
        continue;
      carom_world_def_init (&def, sizeof def);
      def.gravity_y = -10.0;
      def.friction = 0.5;
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      assert_true (world_set_solver_path (w, paths[p]));
      carom_body_def_init (&d, sizeof d);
      d.type = CAROM_KINEMATIC;
      d.vx = -0.0, d.vy = -0.0, d.spin = -0.0;
      /* one alone, far off, which no contact touches; one under the boxes */
      d.x = 100.0;
      assert_status (carom_world_add_box (w, &d, 1.0, 1.0, &lone), CAROM_OK);
      d.x = 0.0;
      assert_status (carom_world_add_box (w, &d, 30.0, 1.0, NULL), CAROM_OK);
      for (i = 0; i < 12; ++i)
        add_box (w, CAROM_DYNAMIC, -12.0 + 2.0 * i, 1.0, 0.0, 1.0, 1.0);
      for (step = 0; step < 60; ++step)
        {
          assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
          for (i = 0; i < 2; ++i)
            {
              assert_false (signbit (w->solver_bodies[i].v.x));
              assert_false (signbit (w->solver_bodies[i].v.y));
              assert_false (signbit (w->solver_bodies[i].w));
            }
          /* and keeps the velocity it was given, exactly */
          assert_status (carom_body_get_velocity (w, lone, &vx, &vy), CAROM_OK);
          assert_status (carom_body_get_spin (w, lone, &spin), CAROM_OK);
          assert_true (vx == 0.0 && signbit (vx) && vy == 0.0 && signbit (vy) && spin == 0.0 && signbit (spin));
        }
      hash[ran++] = world_state_hash (w);
      carom_world_destroy (w);
    }
  for (i = 1; i < ran; ++i)
    assert_true (hash[i] == hash[0]);
}

/* Columns for shock propagation's waves: stacks of boxes, some capped by
 * a body fifty times heavier (with a post beside the cap), some with a
 * disc, a compound or a comb on top (rows of one, two and more points),
 * set down a little apart and askew so that they rattle as they land. The
 * vertex-edge narrow phase gives contacts of more than two points. With
 * the allocator `alloc` when it is not NULL. */
static carom_world *columns_with (carom_narrow_phase narrow, const carom_allocator *alloc)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  int col, i;
  carom_world_def_init (&def, sizeof def);
  if (alloc)
    def.allocator = *alloc;
  def.gravity_y = -10.0;
  def.friction = 0.6;
  def.narrow_phase = narrow;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 80.0, 1.0);
  for (col = 0; col < 12; ++col)
    {
      double x = -30.0 + 5.0 * col, y = 0.55;
      int height = 2 + col % 6;
      for (i = 0; i < height; ++i, y += 1.05)
        add_box (w, CAROM_DYNAMIC, x + 0.03 * (i % 3), y, 0.02 * ((i + col) % 3 - 1), 1.0, 1.0);
      carom_body_def_init (&d, sizeof d);
      d.x = x, d.y = y + 0.5;
      switch (col % 4)
        {
        case 0:
          d.density = 50.0;
          assert_status (carom_world_add_box (w, &d, 1.2, 0.8, NULL), CAROM_OK);
          /* a post on the ground against the heavy cap's side: a contact
           * of a body held up (the cap) with one of a lower level, which
           * it does not rest on */
          add_box (w, CAROM_DYNAMIC, x + 0.76, 0.5 * (y + 0.9), 0.0, 0.3, y + 0.9);
          break;
        case 1:
          assert_status (carom_world_add_circle (w, &d, 0.45, NULL), CAROM_OK);
          break;
        case 2:
          {
            static const double block[] = { -0.22, -0.3, 0.22, -0.3, 0.22, 0.3, -0.22, 0.3 };
            carom_shape_def parts[2];
            int k;
            for (k = 0; k < 2; ++k)
              {
                assert_status (carom_shape_def_init (&parts[k], sizeof parts[k]), CAROM_OK);
                parts[k].kind = CAROM_SHAPE_POLYGON;
                parts[k].xy = block, parts[k].count = 4;
                parts[k].x = k == 0 ? -0.25 : 0.25;
              }
            d.density = 20.0;
            assert_status (carom_world_add_compound (w, &d, parts, 2, NULL), CAROM_OK);
          }
          break;
        default:
          {
            /* a comb, its three teeth down: a contact of three points */
            static const double comb[] = { -0.6, -0.3, -0.4, -0.3, -0.4, 0.0, -0.1, 0.0, -0.1, -0.3, 0.1, -0.3,
                                           0.1,  0.0,  0.4,  0.0,  0.4,  -0.3, 0.6, -0.3, 0.6,  0.3,  -0.6, 0.3 };
            d.density = 20.0;
            assert_status (carom_world_add_polygon (w, &d, comb, 12, NULL), CAROM_OK);
          }
        }
    }
  return w;
}

/* Shock propagation's rows solved in waves, four at a time (shock_batch.h),
 * give the bits of the rows solved one at a time in level order, on every
 * path: the one world keeps its batches, the other has them released
 * before each step (contact_shock_destroy), which leaves no room for any
 * and so solves its rows one at a time. With either narrow phase. */
static void test_shock_waves_keep_the_level_order (void **state)
{
  const int paths[SOLVER_PATHS] = { SOLVER_PATH_PORTABLE, SOLVER_PATH_AVX2, SOLVER_PATH_AVX512 };
  int p, narrow, more_anywhere = 0;
  (void) state;
  for (p = 0; p < 2 * SOLVER_PATHS; ++p)
    {
      carom_world *waves, *rows;
      int32_t step, waved = 0, most_waves = 0, rows_alone = 0, more = 0;
      narrow = p / SOLVER_PATHS ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
      if (!solver_path_available ((solver_path) paths[p % SOLVER_PATHS]))
        continue;
      waves = columns_with ((carom_narrow_phase) narrow, NULL);
      rows = columns_with ((carom_narrow_phase) narrow, NULL);
      assert_true (world_set_solver_path (waves, paths[p % SOLVER_PATHS]));
      assert_true (world_set_solver_path (rows, paths[p % SOLVER_PATHS]));
      for (step = 0; step < 300; ++step)
        {
          int32_t i;
          contact_shock_destroy (rows);
          assert_status (carom_world_update (waves, 1.0 / 60), CAROM_OK);
          assert_status (carom_world_update (rows, 1.0 / 60), CAROM_OK);
          if (world_state_hash (waves) != world_state_hash (rows))
            fail_msg ("path %d, narrow phase %d: the waves differ from the rows one at a time at step %d",
                      paths[p % SOLVER_PATHS], narrow, (int) step);
          assert_int_equal (rows->shock_waves, 0);
          /* a row's upper body rests on its lower one: the normal (from a
           * to b) points up to it within 60 degrees (the world that solves
           * its rows one at a time makes them all; the other, those of
           * more points only) */
          assert_int_equal (rows->shock_count, waves->shock_count);
          for (i = 0; i < rows->shock_count; ++i)
            {
              const shock_row *r = &rows->shock_rows[i];
              double lift = r->p[0].normal.y;
              assert_true ((r->up == r->b ? lift : -lift) >= 0.5);
            }
          rows_alone += rows->shock_count > 0;
          waved += waves->shock_waves > 0;
          most_waves = waves->shock_waves > most_waves ? waves->shock_waves : most_waves;
          for (i = 0; i < rows->shock_count; ++i)
            more += waves->shock_waves > 0 && rows->shock_rows[i].count > 2;
        }
      /* the waves ran, many deep, rows of more points among them; the
       * other world solved its rows one at a time */
      printf ("path %d, narrow phase %d: %d steps in waves (at most %d), %d rows of more points, %d steps one at a "
              "time\n",
              paths[p % SOLVER_PATHS], narrow, (int) waved, (int) most_waves, (int) more, (int) rows_alone);
      assert_true (waved > 250 && most_waves >= 6 && rows_alone > 250);
      more_anywhere += more;
      carom_world_destroy (waves);
      carom_world_destroy (rows);
    }
  assert_true (more_anywhere > 100);
}

/* An allocator whose blocks begin at every offset from a cache line in
 * turn (8, 16, .., 56, 0 bytes past one), the block's own start kept in the
 * eight bytes before it. */
typedef struct skewed {
  int next;
  long live;
} skewed;

static void *skewed_alloc (size_t size, void *user)
{
  skewed *k = user;
  size_t offset = (size_t) (8 * (1 + k->next++ % 8)) % 64;
  char *raw = malloc (size + 128), *p;
  if (!raw)
    return NULL;
  p = raw + 64 + ((offset - (uintptr_t) raw % 64) % 64);
  memcpy (p - sizeof raw, &raw, sizeof raw);
  k->live++;
  return p;
}

static void skewed_free (void *ptr, size_t size, void *user)
{
  char *raw;
  (void) size;
  memcpy (&raw, (char *) ptr - sizeof raw, sizeof raw);
  ((skewed *) user)->live--;
  free (raw);
}

static int on_a_line (const void *p)
{
  return (uintptr_t) p % 64 == 0;
}

/* mem_reserve_lines: from every offset of the allocator's block, the array
 * begins on a line and its `need` elements lie within the block, for
 * elements smaller and larger than a line; nothing is allocated while
 * nothing is needed. */
static void test_room_from_a_line_holds_what_is_needed (void **state)
{
  static const size_t elems[] = { 8, 24, 64, 100, 3264 };
  skewed k = { 0, 0 };
  carom_allocator alloc;
  int e, start, need;
  (void) state;
  alloc.alloc = skewed_alloc, alloc.free = skewed_free, alloc.user = &k;
  for (e = 0; e < 5; ++e)
    for (start = 0; start < 8; ++start)
      {
        void *room = NULL, *array = NULL;
        int32_t cap = 0;
        assert_true (mem_reserve_lines (&alloc, &room, &array, &cap, 0, elems[e]));
        assert_null (room);
        assert_null (array);
        k.next = start;
        for (need = 1; need <= 40; need += 3)
          {
            assert_true (mem_reserve_lines (&alloc, &room, &array, &cap, need, elems[e]));
            assert_true (on_a_line (array));
            assert_true (mem_lines_usable (cap, elems[e]) >= need);
            assert_true ((char *) array + (size_t) need * elems[e] <= (char *) room + (size_t) cap * elems[e]);
            assert_true ((char *) array + (size_t) mem_lines_usable (cap, elems[e]) * elems[e]
                         <= (char *) room + (size_t) cap * elems[e]);
          }
        mem_free (&alloc, room, (size_t) cap * elems[e]);
      }
  assert_int_equal (k.live, 0);
}

/* The batches, their shock propagation's and the solver bodies begin on a
 * cache line whatever the allocator gives (each of their arrays of lanes
 * then lies within a line, contact_batch.h), and the results are the bits
 * of a world on the usual allocator. */
static void test_batches_begin_on_a_cache_line (void **state)
{
  skewed k = { 0, 0 };
  carom_allocator alloc;
  carom_world *plain, *skew;
  int32_t step, waved = 0, batched = 0;
  (void) state;
  alloc.alloc = skewed_alloc, alloc.free = skewed_free, alloc.user = &k;
  plain = columns_with (CAROM_NARROW_SAT, NULL);
  skew = columns_with (CAROM_NARROW_SAT, &alloc);
  for (step = 0; step < 120; ++step)
    {
      assert_status (carom_world_update (plain, 1.0 / 60), CAROM_OK);
      assert_status (carom_world_update (skew, 1.0 / 60), CAROM_OK);
      assert_true (world_state_hash (plain) == world_state_hash (skew));
      assert_true (on_a_line (skew->solver_bodies));
      if (skew->batch_count > 0)
        assert_true (on_a_line (skew->batches)), ++batched;
      if (skew->shock_waves > 0)
        assert_true (on_a_line (skew->shock_batches)), ++waved;
    }
  /* the blocks came at every offset, and both kinds of batch were used */
  assert_true (k.next >= 8 && batched > 0 && waved > 0);
  carom_world_destroy (plain);
  carom_world_destroy (skew);
  assert_int_equal (k.live, 0);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_constraint_colour_takes_the_first_free),
    cmocka_unit_test (test_batches_are_properly_coloured),
    cmocka_unit_test (test_every_path_gives_the_same_bits),
    cmocka_unit_test (test_kernels_agree_lane_by_lane),
    cmocka_unit_test (test_bodies_that_do_not_move_have_no_negative_zero),
    cmocka_unit_test (test_shock_waves_keep_the_level_order),
    cmocka_unit_test (test_room_from_a_line_holds_what_is_needed),
    cmocka_unit_test (test_batches_begin_on_a_cache_line),
  };
  return cmocka_run_group_tests (tests, NULL, NULL);
}
