/* Broad phase: sort and sweep over bounding boxes along the axis where the
 * bodies spread most. Bodies move little between steps, so the sorted order is
 * repaired by insertion sort in about O(n); a full merge sort, O(n log n),
 * runs when bodies are added or the order is badly shuffled.
 *
 * Each body also has a fat box: its box grown by a tenth of its size, made
 * anew when the box leaves it. The pairs of fat boxes that overlap are
 * kept, and the pairs whose boxes meet are among them: while few bodies
 * leave their fat boxes (a pile at rest, a pyramid), a detection mends the
 * kept pairs for those bodies alone and tests the kept pairs, with no sort
 * and no sweep; while many do (bodies falling, a gas), it sweeps the boxes.
 *
 * From GRID_MIN_BODIES bodies on, a uniform grid replaces the sweep, whose
 * cost grows as n sqrt(n) in crowded worlds. Pairs whose boxes overlap go to
 * a plain callback, as the original c_index did. */
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

typedef struct fat_box {
  double lo, hi, lo2, hi2; /* along the sweep axis, and the other */
  int32_t escaped;         /* the body's box has left it (found again in
                              each detection that looks) */
} fat_box;

/* A fat box is a body's box grown by this fraction of its size
 * (shape.size) on every side. */
#define BROAD_FAT_FRACTION 0.1
/* While at most one body in this many leaves its fat box, the kept pairs
 * are mended for those bodies (each tested against every other body:
 * cheaper than a sweep while they are few); when more do, the boxes are
 * swept. */
#define BROAD_MEND_SHARE 64
/* After an update whose detection swept the boxes, the fat boxes are left
 * alone for this many more updates (they stay valid where they still hold
 * their boxes), then looked at again. */
#define BROAD_MOVING_STEPS 8

/* Worlds of this many live bodies or more have the bodies of the kept
 * pairs asked of the memory ahead of their turn (broadphase.c,
 * report_kept). */
#define PREFETCH_MIN_BODIES 1024

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
  int32_t *cell_ranges; /* the cells each entry covers: 4 per entry */
  int32_t ranges_cap;
  double *reach;     /* per slot, this detection's body_reach_uncapped
                        (the pairs' margins, contact.c) */
  int32_t reach_cap;
  fat_box *fat;      /* per slot */
  int32_t fat_cap;
  int32_t *pairs;    /* the kept pairs of overlapping fat boxes: entry
                        indices, two per pair */
  int32_t pair_count, pairs_cap; /* pairs, and room in int32_t */
  uint64_t look_at;  /* the update (step_context.update) from which the fat
                        boxes are looked at again (BROAD_MOVING_STEPS):
                        counted in updates, so that a failed update tried
                        again decides as it did */
  int pairs_valid;   /* the kept pairs are all the pairs of overlapping fat
                        boxes (never two static bodies), and the entries
                        are in the order they index */
  int sorted;        /* the entries are in the order of lo (the last
                        detection sorted them) */
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
 * same set of pairs (in its own order: the sweep's depends on whether it
 * swept or tested its kept pairs). */
int broadphase_sweep (struct carom_world *world, const struct step_context *ctx, pair_callback fn, void *user);
int broadphase_grid (struct carom_world *world, const struct step_context *ctx, pair_callback fn, void *user);

/* The box of the body in `slot`, grown by the contact margin and `reach`,
 * as an entry of this detection's axis. */
void broadphase_box (const struct carom_world *world, int32_t slot, double reach, sweep_entry *e);
/* Report each pair of one of the k boxes (broadphase_box; sorted here) and
 * a body whose box of the last detection meets it, or of two of the boxes
 * that meet, once (never two static bodies, never a body with itself), the
 * box's body first. The bodies of the boxes are those whose `queried` (per
 * slot) is not 0, and each box holds its body's box of the detection. The
 * boxes may be broad.scratch: the detection no longer needs it. */
void broadphase_query (struct carom_world *world, sweep_entry *boxes, int32_t k, const double *queried,
                       pair_callback fn, void *user);

#endif
