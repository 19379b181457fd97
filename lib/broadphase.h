/* Broad phase: sort and sweep over bounding boxes along the axis where the
 * bodies spread most. Bodies move little between steps, so the sorted order is
 * repaired by insertion sort in about O(n); a full merge sort, O(n log n),
 * runs when bodies are added or the order is badly shuffled. From
 * GRID_MIN_BODIES bodies on, a uniform grid replaces the sweep, whose cost
 * grows as n sqrt(n) in crowded worlds. Pairs whose boxes overlap go to a
 * plain callback, as the original c_index did. */
#ifndef CAROM_BROADPHASE_H
#define CAROM_BROADPHASE_H

#include <stdint.h>

struct carom_world;
struct step_context;

typedef struct sweep_entry {
  double lo, hi;     /* extent along the sweep axis */
  double lo2, hi2;   /* extent along the other axis */
  int32_t slot;
  int32_t is_static;
} sweep_entry;

/* Worlds of this many live bodies use the grid. (The fuzz build lowers it,
 * so that small fuzzed worlds exercise both methods.) */
#ifndef GRID_MIN_BODIES
#define GRID_MIN_BODIES 4096
#endif

typedef struct broadphase {
  sweep_entry *entries, *scratch;
  int32_t count, cap, scratch_cap;
  int32_t *hits;     /* the sweep's overlapping entries of one entry */
  int32_t hits_cap;
  int32_t *cell_start, *cell_items, *cell_fill; /* the grid's cells */
  int32_t cell_cap, items_cap, fill_cap;
  double *reach;     /* per slot, this detection's body_reach_uncapped
                        (the pairs' margins, contact.c) */
  int32_t reach_cap;
  int axis;          /* 0: sweep along x, 1: along y */
  int dirty;         /* bodies were added or removed: rebuild */
} broadphase;

typedef void (*pair_callback) (struct carom_world *world, int32_t a, int32_t b, void *user);

void broadphase_init (struct carom_world *world);
void broadphase_destroy (struct carom_world *world);
/* Sort, then report each overlapping pair once (never two static bodies).
 * Returns 0 when memory ran out (nothing reported), 1 otherwise. */
int broadphase_update (struct carom_world *world, const struct step_context *ctx, pair_callback fn, void *user);

/* The two methods broadphase_update chooses between, each reporting the
 * same set of pairs (in its own order). */
int broadphase_sweep (struct carom_world *world, const struct step_context *ctx, pair_callback fn, void *user);
int broadphase_grid (struct carom_world *world, const struct step_context *ctx, pair_callback fn, void *user);

#endif
