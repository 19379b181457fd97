/* The broad phase's two methods, the sweep (worlds below GRID_MIN_BODIES
 * bodies) and the grid (from there on), report exactly the same pairs, each
 * once, whatever the scene: crowded mixed sizes with long walls, bodies on a
 * line, worlds spread over 1e89, one box covering all, boxes reaching past
 * the doubles, statics only; and the sweep's kept pairs, mended as bodies
 * leave their fat boxes, report what the grid does as bodies jump about. */
#include "support.h"

#include <stdlib.h>

#include "broadphase.h"
#include "step.h"
#include "world.h"

typedef struct pair_list {
  int64_t *keys;
  int32_t count, cap;
} pair_list;

static void collect (carom_world *world, int32_t a, int32_t b, void *user)
{
  pair_list *l = user;
  (void) world;
  if (l->count == l->cap)
    {
      l->cap = l->cap ? 2 * l->cap : 1024;
      l->keys = realloc (l->keys, (size_t) l->cap * sizeof *l->keys);
      assert_non_null (l->keys);
    }
  l->keys[l->count++] = a < b ? (int64_t) a << 32 | b : (int64_t) b << 32 | a;
}

static int compare_keys (const void *x, const void *y)
{
  int64_t a = *(const int64_t *) x, b = *(const int64_t *) y;
  return a < b ? -1 : a > b;
}

/* Both methods on the same world: the same sorted pairs, none twice.
 * Returns the number of pairs. */
static int32_t same_pairs_in (carom_world *w, double dt)
{
  pair_list sweep = { NULL, 0, 0 }, grid = { NULL, 0, 0 };
  int32_t i, count;
  step_context ctx;
  step_context_init (&ctx, w, dt);
  assert_int_equal (broadphase_sweep (w, &ctx, collect, &sweep), 1);
  assert_int_equal (broadphase_grid (w, &ctx, collect, &grid), 1);
  assert_int_equal (sweep.count, grid.count);
  if (grid.count > 0) /* (no pairs: no array to sort) */
    {
      qsort (sweep.keys, (size_t) sweep.count, sizeof *sweep.keys, compare_keys);
      qsort (grid.keys, (size_t) grid.count, sizeof *grid.keys, compare_keys);
    }
  for (i = 0; i < grid.count; ++i)
    {
      assert_true (sweep.keys[i] == grid.keys[i]);
      if (i > 0)
        assert_true (grid.keys[i] != grid.keys[i - 1]);
    }
  count = grid.count;
  free (sweep.keys);
  free (grid.keys);
  return count;
}

/* The sweep alone (the grid would make it start afresh), as the detection
 * of an update, against every two of the boxes it filled: the same sorted
 * pairs. Returns their number. */
static int32_t sweep_pairs_in (carom_world *w, double dt)
{
  pair_list sweep = { NULL, 0, 0 }, all = { NULL, 0, 0 };
  const broadphase *bp = &w->broad;
  int32_t i, j, count;
  step_context ctx;
  step_context_init (&ctx, w, dt);
  assert_int_equal (broadphase_sweep (w, &ctx, collect, &sweep), 1);
  w->updates++; /* as a successful update counts itself */
  for (i = 0; i < bp->count; ++i)
    for (j = i + 1; j < bp->count; ++j)
      {
        const sweep_entry *e = &bp->entries[i], *f = &bp->entries[j];
        if (e->lo <= f->hi && f->lo <= e->hi && e->lo2 <= f->hi2 && f->lo2 <= e->hi2 && !(e->is_static && f->is_static))
          collect (w, e->slot, f->slot, &all);
      }
  assert_int_equal (sweep.count, all.count);
  if (all.count > 0)
    {
      qsort (sweep.keys, (size_t) sweep.count, sizeof *sweep.keys, compare_keys);
      qsort (all.keys, (size_t) all.count, sizeof *all.keys, compare_keys);
    }
  for (i = 0; i < all.count; ++i)
    assert_true (sweep.keys[i] == all.keys[i]);
  count = all.count;
  free (sweep.keys);
  free (all.keys);
  return count;
}

/* Both methods, then the sweep again and again (nothing moves): the first
 * detections sweep the boxes, the later ones test the kept pairs; each
 * reports the same pairs. */
static int32_t same_pairs (carom_world *w)
{
  int32_t i, count = same_pairs_in (w, 0.0);
  for (i = 0; i < BROAD_MOVING_STEPS + 2; ++i)
    assert_int_equal (sweep_pairs_in (w, 0.0), count);
  assert_true (w->broad.pairs_valid || count == 0);
  return count;
}

/* A small deterministic generator, so the scene is the same everywhere. */
static double next_unit (uint32_t *state)
{
  *state = *state * 1664525u + 1013904223u;
  return (double) (*state >> 8) / 16777216.0;
}

static void add_body (carom_world *w, carom_body_type type, double x, double y, double size, int kind)
{
  carom_body_def d;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = type, d.x = x, d.y = y, d.angle = x * 0.1;
  switch (kind % 3)
    {
    case 0: assert_status (carom_world_add_circle (w, &d, 0.5 * size, NULL), CAROM_OK); break;
    case 1: assert_status (carom_world_add_box (w, &d, size, 0.6 * size, NULL), CAROM_OK); break;
    default: assert_status (carom_world_add_regular (w, &d, 5, 0.6 * size, NULL), CAROM_OK); break;
    }
}

static carom_world *new_world (void)
{
  carom_world *w = NULL;
  assert_status (carom_world_init (&w, NULL), CAROM_OK);
  return w;
}

static void test_crowded_mixed_sizes_with_walls (void **state)
{
  carom_world *w = new_world ();
  uint32_t seed = 12345;
  int32_t i, pairs;
  (void) state;
  /* walls around a 150 x 150 field, a few large statics inside */
  {
    carom_body_def d;
    assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
    d.type = CAROM_STATIC;
    d.x = 75, d.y = -1;
    assert_status (carom_world_add_box (w, &d, 152, 2, NULL), CAROM_OK);
    d.x = 75, d.y = 151;
    assert_status (carom_world_add_box (w, &d, 152, 2, NULL), CAROM_OK);
    d.x = -1, d.y = 75;
    assert_status (carom_world_add_box (w, &d, 2, 152, NULL), CAROM_OK);
    d.x = 151, d.y = 75;
    assert_status (carom_world_add_box (w, &d, 2, 152, NULL), CAROM_OK);
  }
  for (i = 0; i < 20; ++i)
    add_body (w, CAROM_STATIC, 150 * next_unit (&seed), 150 * next_unit (&seed), 2 + 8 * next_unit (&seed), i);
  for (i = 0; i < 5000; ++i)
    add_body (w, CAROM_DYNAMIC, 150 * next_unit (&seed), 150 * next_unit (&seed), 0.2 + 2.8 * next_unit (&seed), i);
  assert_true (carom_world_body_count (w) >= GRID_MIN_BODIES);
  pairs = same_pairs (w);
  print_message ("crowded: %d bodies, %d pairs\n", (int) carom_world_body_count (w), (int) pairs);
  assert_true (pairs > 5000);
  /* and after some steps, with bodies moved and the grid in charge */
  for (i = 0; i < 5; ++i)
    assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
  assert_true (same_pairs (w) > 5000);
  carom_world_destroy (w);
}

static void test_degenerate_layouts (void **state)
{
  carom_world *w;
  int32_t i;
  (void) state;
  /* bodies on a line a million apart, and a touching cluster */
  w = new_world ();
  for (i = 0; i < 300; ++i)
    add_body (w, CAROM_DYNAMIC, 1e6 * i, 0, 1, i);
  for (i = 0; i < 300; ++i)
    add_body (w, CAROM_DYNAMIC, 0.5 * (i % 20), 0.5 * (i / 20), 1, i);
  assert_true (same_pairs (w) > 300);
  carom_world_destroy (w);
  /* spread over 1e89, far apart */
  w = new_world ();
  for (i = 0; i < 200; ++i)
    add_body (w, CAROM_DYNAMIC, 1e88 * (i % 14), 1e88 * (i / 14), 1 + i, i);
  assert_int_equal (same_pairs (w), 0);
  carom_world_destroy (w);
  /* spread over 1e51, and one static box covering them all */
  w = new_world ();
  for (i = 0; i < 200; ++i)
    add_body (w, CAROM_DYNAMIC, 1e50 * (i % 14), 1e50 * (i / 14), 1 + i, i);
  add_body (w, CAROM_STATIC, 6e50, 6e50, 1e53, 1);
  assert_int_equal (same_pairs (w), 200);
  carom_world_destroy (w);
  /* boxes reaching past the doubles (bodies at 1e100 m/s looked ahead over
   * a sub-step of 1e300 s, with continuous collision): no grid spans them,
   * the same pairs still come out */
  w = new_world ();
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  for (i = 0; i < 20; ++i)
    add_body (w, CAROM_DYNAMIC, 3.0 * i, 0, 1, i);
  {
    carom_body_id ids[20];
    assert_int_equal (carom_world_get_bodies (w, ids, 20), 20);
    assert_status (carom_body_set_velocity (w, ids[0], 1e100, 0), CAROM_OK);
    assert_status (carom_body_set_velocity (w, ids[19], 0, -1e100), CAROM_OK);
  }
  assert_true (same_pairs_in (w, 1e300) > 0);
  carom_world_destroy (w);
  /* statics only: nothing to report; one body: nothing either */
  w = new_world ();
  for (i = 0; i < 50; ++i)
    add_body (w, CAROM_STATIC, 0.5 * i, 0, 1, i);
  assert_int_equal (same_pairs (w), 0);
  carom_world_destroy (w);
  w = new_world ();
  add_body (w, CAROM_DYNAMIC, 0, 0, 1, 0);
  assert_int_equal (same_pairs (w), 0);
  carom_world_destroy (w);
}

/* n bodies of mixed shapes and sizes in a loose grid on a static floor;
 * detection after detection (`rounds` of them), none, a few or many of
 * them jump (by a bit, or across the world): the sweep reports the pairs
 * whose boxes meet every time, more than min_pairs. Returns how many
 * times the kept pairs were tested alone, mended for the few jumps, and
 * the boxes swept for the many. */
static void jumping_bodies (int32_t n, int32_t rounds, int32_t min_pairs, int32_t *kept, int32_t *mended,
                            int32_t *swept)
{
  carom_world *w = new_world ();
  carom_body_id *ids = malloc ((size_t) (n + 1) * sizeof *ids);
  uint32_t seed = 777;
  int32_t i, round;
  assert_non_null (ids);
  *kept = *mended = *swept = 0;
  add_body (w, CAROM_STATIC, 10, -1, 30, 1);
  for (i = 0; i < n; ++i)
    add_body (w, CAROM_DYNAMIC, 1.1 * (i % 20), 1.1 * (i / 20), 0.6 + 0.6 * next_unit (&seed), i);
  assert_int_equal (carom_world_get_bodies (w, ids, n + 1), n + 1);
  for (round = 0; round < rounds; ++round)
    {
      /* none for a while, then one to four jumping, now and then thirty */
      int32_t jumps = round < 12 ? 0 : round % 40 == 39 ? 30 : round % 3 == 0 ? 0 : 1 + (int32_t) (4 * next_unit (&seed));
      int escaped_before = 0;
      for (i = 0; i < jumps; ++i)
        {
          carom_body_id id = ids[1 + (int32_t) (n * next_unit (&seed))];
          double x, y, far = next_unit (&seed) < 0.3 ? 20.0 : 0.4;
          assert_status (carom_body_get_position (w, id, &x, &y), CAROM_OK);
          assert_status (carom_body_set_position (w, id, x + far * (next_unit (&seed) - 0.5),
                                                  y + far * (next_unit (&seed) - 0.5)),
                         CAROM_OK);
        }
      escaped_before = jumps > 0 && w->broad.pairs_valid && w->updates >= w->broad.look_at;
      assert_true (sweep_pairs_in (w, 1.0 / 60.0) > min_pairs);
      if (jumps == 0)
        *kept += w->broad.pairs_valid;
      else if (escaped_before && w->broad.pairs_valid)
        (*mended)++;
      else if (!w->broad.pairs_valid)
        (*swept)++;
    }
  free (ids);
  carom_world_destroy (w);
}

/* 400 bodies, 120 detections: each way of reporting was taken. */
static void test_kept_pairs_follow_jumping_bodies (void **state)
{
  int32_t kept, mended, swept;
  (void) state;
  jumping_bodies (400, 120, 400, &kept, &mended, &swept);
  print_message ("kept pairs tested alone %d times, mended %d times, boxes swept %d times\n", (int) kept,
                 (int) mended, (int) swept);
  assert_true (kept >= 5 && mended >= 5 && swept >= 5);
}

/* The same in a world large enough that the kept pairs' bodies are asked
 * of the memory ahead of their turn (PREFETCH_MIN_BODIES, still below the
 * grid's GRID_MIN_BODIES): the same pairs, with the kept pairs tested
 * alone, and mended. */
static void test_kept_pairs_of_a_large_world (void **state)
{
  int32_t kept, mended, swept, n = PREFETCH_MIN_BODIES + 100;
  (void) state;
  assert_true (n + 1 < GRID_MIN_BODIES);
  jumping_bodies (n, 24, 500, &kept, &mended, &swept);
  print_message ("kept pairs tested alone %d times, mended %d times, boxes swept %d times\n", (int) kept,
                 (int) mended, (int) swept);
  assert_true (kept >= 5 && mended >= 5);
}

/* Two unit boxes 0.08 apart along the sweep axis, nothing moving, until
 * the sweep keeps their pair (their fat boxes, each 0.05 wider, overlap);
 * then each moves 0.04 towards the other, inside its fat box: they meet,
 * and the kept pairs report them. */
static void test_kept_pairs_hold_bodies_closing_within_their_fat_boxes (void **state)
{
  carom_world *w = new_world ();
  carom_body_id ids[2];
  carom_body_def d;
  int32_t i;
  (void) state;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  assert_status (carom_world_add_box (w, &d, 1, 1, &ids[0]), CAROM_OK);
  d.x = 1.08;
  assert_status (carom_world_add_box (w, &d, 1, 1, &ids[1]), CAROM_OK);
  for (i = 0; i < BROAD_MOVING_STEPS + 2; ++i)
    assert_int_equal (sweep_pairs_in (w, 1.0 / 60.0), 0);
  assert_true (w->broad.pairs_valid && w->broad.pair_count == 2);
  assert_status (carom_body_set_position (w, ids[0], 0.04, 0.0), CAROM_OK);
  assert_status (carom_body_set_position (w, ids[1], 1.04, 0.0), CAROM_OK);
  assert_int_equal (sweep_pairs_in (w, 1.0 / 60.0), 1);
  assert_true (w->broad.pairs_valid);
  carom_world_destroy (w);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_kept_pairs_hold_bodies_closing_within_their_fat_boxes),
    cmocka_unit_test (test_kept_pairs_follow_jumping_bodies),
    cmocka_unit_test (test_kept_pairs_of_a_large_world),
    cmocka_unit_test (test_crowded_mixed_sizes_with_walls),
    cmocka_unit_test (test_degenerate_layouts),
  };
  return cmocka_run_group_tests (tests, NULL, NULL);
}
