#include "broadphase.h"

#include <math.h>
#include <string.h>

#include "step.h"
#include "world.h"

void broadphase_init (carom_world *world)
{
  memset (&world->broad, 0, sizeof world->broad);
  world->broad.dirty = 1;
}

void broadphase_destroy (carom_world *world)
{
  broadphase *bp = &world->broad;
  mem_free (&world->allocator, bp->entries, (size_t) bp->cap * sizeof (sweep_entry));
  mem_free (&world->allocator, bp->scratch, (size_t) bp->scratch_cap * sizeof (sweep_entry));
  mem_free (&world->allocator, bp->cell_start, (size_t) bp->cell_cap * sizeof (int32_t));
  mem_free (&world->allocator, bp->cell_items, (size_t) bp->items_cap * sizeof (int32_t));
  mem_free (&world->allocator, bp->cell_fill, (size_t) bp->fill_cap * sizeof (int32_t));
  mem_free (&world->allocator, bp->reach, (size_t) bp->reach_cap * sizeof (double));
  mem_free (&world->allocator, bp->hits, (size_t) bp->hits_cap * sizeof (int32_t));
  memset (bp, 0, sizeof *bp);
}

/* Boxes grow by the body's contact margin and by how far it can move in
 * this sub-step, so pairs that are apart but within the margin, or that will
 * meet before the next detection, are still reported. */
static void fill_entry (broadphase *bp, sweep_entry *e, const body *b, int axis, double slop,
                        const step_context *ctx)
{
  double r = body_reach_uncapped (b, ctx->dt, ctx->accel);
  double m = slop * b->shape.size + body_reach_capped (b, r, body_swept (b, r, ctx->dt, ctx->accel, ctx->continuous));
  bp->reach[e->slot] = r;
  /* a sensor's box reaches as far as the fastest body can travel in the
   * update: what overlaps it at the end is among its pairs */
  if (b->sensor)
    m += ctx->sensor_reach;
  if (axis == 0)
    {
      e->lo = b->box_lo.x - m, e->hi = b->box_hi.x + m;
      e->lo2 = b->box_lo.y - m, e->hi2 = b->box_hi.y + m;
    }
  else
    {
      e->lo = b->box_lo.y - m, e->hi = b->box_hi.y + m;
      e->lo2 = b->box_lo.x - m, e->hi2 = b->box_hi.x + m;
    }
  e->is_static = b->type == CAROM_STATIC;
}

/* Stable bottom-up merge sort by `lo`: the same order on every machine. */
static void merge_sort (sweep_entry *a, sweep_entry *tmp, int32_t n)
{
  int32_t width, i;
  for (width = 1; width < n; width *= 2)
    {
      for (i = 0; i < n; i += 2 * width)
        {
          int32_t lo = i, mid = i + width < n ? i + width : n, hi = i + 2 * width < n ? i + 2 * width : n;
          int32_t p = lo, q = mid, k = lo;
          while (p < mid && q < hi)
            tmp[k++] = a[q].lo < a[p].lo ? a[q++] : a[p++];
          while (p < mid)
            tmp[k++] = a[p++];
          while (q < hi)
            tmp[k++] = a[q++];
        }
      memcpy (a, tmp, (size_t) n * sizeof *a);
    }
}

/* Insertion sort, cheap when bodies moved little; gives up (returns 0) when
 * the order is too shuffled for it to stay near linear. */
static int insertion_sort (sweep_entry *a, int32_t n)
{
  int64_t moves = 0, budget = 8 * (int64_t) n + 64;
  int32_t i;
  for (i = 1; i < n; ++i)
    {
      sweep_entry e = a[i];
      int32_t j = i - 1;
      while (j >= 0 && a[j].lo > e.lo)
        {
          a[j + 1] = a[j];
          j--;
          if (++moves > budget)
            {
              a[j + 1] = e; /* keep the array a permutation */
              return 0;
            }
        }
      a[j + 1] = e;
    }
  return 1;
}

/* The axis along which the bodies' centres spread most. */
static int widest_axis (const carom_world *world)
{
  double sx = 0, sy = 0, sxx = 0, syy = 0;
  int32_t i, n = 0;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      if (!b->alive)
        continue;
      sx += b->p.x, sy += b->p.y;
      sxx += b->p.x * b->p.x, syy += b->p.y * b->p.y;
      n++;
    }
  if (n == 0)
    return 0;
  return syy - sy * sy / n > 1.5 * (sxx - sx * sx / n) ? 1 : 0;
}

/* Fill one entry per live body, in slot order (the grid needs no order). */
static int32_t fill_all (carom_world *world, const step_context *ctx)
{
  broadphase *bp = &world->broad;
  int32_t i, n = 0;
  for (i = 0; i < world->slot_count; ++i)
    if (world->bodies[i].alive)
      {
        bp->entries[n].slot = i;
        fill_entry (bp, &bp->entries[n], &world->bodies[i], bp->axis, world->def.slop, ctx);
        n++;
      }
  return n;
}

static int reserve_entries (carom_world *world)
{
  broadphase *bp = &world->broad;
  return mem_reserve (&world->allocator, (void **) &bp->entries, &bp->cap, world->live_count, sizeof (sweep_entry))
         && mem_reserve (&world->allocator, (void **) &bp->scratch, &bp->scratch_cap, world->live_count,
                         sizeof (sweep_entry))
         && mem_reserve (&world->allocator, (void **) &bp->reach, &bp->reach_cap, world->slot_count, sizeof (double))
         && mem_reserve (&world->allocator, (void **) &bp->hits, &bp->hits_cap, world->live_count, sizeof (int32_t));
}

int broadphase_sweep (carom_world *world, const step_context *ctx, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  int32_t i, n;
  int axis = widest_axis (world);
  if (axis != bp->axis)
    {
      /* switch only for a clear difference, so the order stays coherent */
      bp->axis = axis;
      bp->dirty = 1;
    }
  if (!reserve_entries (world))
    return 0;
  if (bp->dirty)
    {
      n = bp->count = fill_all (world, ctx);
      merge_sort (bp->entries, bp->scratch, n);
      bp->dirty = 0;
    }
  else
    {
      n = bp->count;
      for (i = 0; i < n; ++i)
        fill_entry (bp, &bp->entries[i], &world->bodies[bp->entries[i].slot], bp->axis, world->def.slop, ctx);
      if (!insertion_sort (bp->entries, n))
        merge_sort (bp->entries, bp->scratch, n);
    }

  for (i = 0; i < n; ++i)
    {
      /* a copy, and a pointer walk: the compiler cannot tell that fn leaves
       * the entries alone, and this loop runs for every nearby pair. The
       * overlaps are noted without a branch (whether two boxes in the
       * window overlap is not predictable), then reported. */
      const sweep_entry e = bp->entries[i];
      const sweep_entry *f, *end = bp->entries + n;
      int32_t hits = 0, k;
      for (f = &bp->entries[i + 1]; f < end && f->lo <= e.hi; ++f)
        {
          bp->hits[hits] = f->slot;
          hits += (f->lo2 <= e.hi2) & (f->hi2 >= e.lo2) & !(e.is_static & f->is_static);
        }
      for (k = 0; k < hits; ++k)
        fn (world, e.slot, bp->hits[k], user);
    }
  return 1;
}

/* ---------------------------------------------------------------- grid
 *
 * A sweep along one axis tests every body against the whole strip of the
 * world that overlaps it on that axis: about sqrt(n) others in a crowded
 * square world, so its cost grows as n sqrt(n). From GRID_MIN_BODIES on, the
 * boxes go into a uniform grid instead, cells about the size of a typical
 * body (at most 4 cells per body), each box into every cell it covers, and
 * each cell's boxes are tested against each other: about constant work per
 * body. A pair that shares several cells is reported from one only, the
 * cell of the corner (max of the two lows, on both axes), which both cover. */

/* The cell index of coordinate x along an axis of `count` cells. */
static int32_t grid_cell (double x, double origin, double size, int32_t count)
{
  double c = floor ((x - origin) / size);
  return !(c >= 0.0) ? 0 : c >= (double) count ? count - 1 : (int32_t) c;
}

/* The grid's frame: origin (u0, v0), square cells of `size`, nu x nv. */
typedef struct grid_frame {
  double u0, v0, size;
  int32_t nu, nv;
} grid_frame;

/* The cells a box covers: columns a0..a1, rows b0..b1. */
typedef struct cell_range {
  int32_t a0, a1, b0, b1;
} cell_range;

static cell_range cells_of (const sweep_entry *e, const grid_frame *g)
{
  cell_range r;
  r.a0 = grid_cell (e->lo, g->u0, g->size, g->nu), r.a1 = grid_cell (e->hi, g->u0, g->size, g->nu);
  r.b0 = grid_cell (e->lo2, g->v0, g->size, g->nv), r.b1 = grid_cell (e->hi2, g->v0, g->size, g->nv);
  return r;
}

int broadphase_grid (carom_world *world, const step_context *ctx, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  const sweep_entry *e;
  grid_frame g;
  double u1, v1, limit;
  int32_t n, i, j, k, cells, total, moving = 0;
  if (!reserve_entries (world))
    return 0;
  n = fill_all (world, ctx);
  bp->dirty = 1; /* the sweep, if it runs again, starts afresh */
  e = bp->entries;
  if (n == 0)
    return 1;
  g.u0 = e[0].lo, u1 = e[0].hi, g.v0 = e[0].lo2, v1 = e[0].hi2, g.size = 0.0;
  for (i = 0; i < n; ++i)
    {
      g.u0 = fmin (g.u0, e[i].lo), u1 = fmax (u1, e[i].hi);
      g.v0 = fmin (g.v0, e[i].lo2), v1 = fmax (v1, e[i].hi2);
      if (!e[i].is_static)
        g.size += fmax (e[i].hi - e[i].lo, e[i].hi2 - e[i].lo2), moving++;
    }
  if (moving == 0)
    return 1; /* static pairs are never reported */
  /* boxes reaching past the doubles (a body of 1e100 moving at 1e100 for
   * 8 s): no grid spans them, and the sweep needs no cells */
  if (!(isfinite (u1 - g.u0) && isfinite (v1 - g.v0) && isfinite (g.size)))
    return broadphase_sweep (world, ctx, fn, user);
  /* cells of the mean moving box, but no more than 4 per body */
  g.size /= moving;
  limit = 4.0 * n + 16.0;
  if (!(g.size > 0.0))
    g.size = fmax (u1 - g.u0, v1 - g.v0) + 1.0;
  /* and no more than 8 cell places per body in all (walls cover many) */
  for (;;)
    {
      double places = 0.0;
      while ((floor ((u1 - g.u0) / g.size) + 1.0) * (floor ((v1 - g.v0) / g.size) + 1.0) > limit)
        g.size *= 2.0;
      g.nu = (int32_t) floor ((u1 - g.u0) / g.size) + 1;
      g.nv = (int32_t) floor ((v1 - g.v0) / g.size) + 1;
      for (i = 0; i < n; ++i)
        {
          cell_range r = cells_of (&e[i], &g);
          places += (double) (r.a1 - r.a0 + 1) * (r.b1 - r.b0 + 1);
        }
      if (places <= 2.0 * limit)
        {
          total = (int32_t) places;
          break;
        }
      g.size *= 2.0;
    }
  cells = g.nu * g.nv;

  /* count each cell's boxes, then place the boxes (in slot order) */
  if (!mem_reserve (&world->allocator, (void **) &bp->cell_start, &bp->cell_cap, cells + 1, sizeof (int32_t))
      || !mem_reserve (&world->allocator, (void **) &bp->cell_items, &bp->items_cap, total, sizeof (int32_t))
      || !mem_reserve (&world->allocator, (void **) &bp->cell_fill, &bp->fill_cap, cells, sizeof (int32_t)))
    return 0;
  memset (bp->cell_start, 0, (size_t) (cells + 1) * sizeof (int32_t));
  for (i = 0; i < n; ++i)
    {
      cell_range r = cells_of (&e[i], &g);
      int32_t a, b;
      for (b = r.b0; b <= r.b1; ++b)
        for (a = r.a0; a <= r.a1; ++a)
          bp->cell_start[b * g.nu + a + 1]++;
    }
  for (k = 0; k < cells; ++k)
    bp->cell_start[k + 1] += bp->cell_start[k];
  memcpy (bp->cell_fill, bp->cell_start, (size_t) cells * sizeof (int32_t));
  for (i = 0; i < n; ++i)
    {
      cell_range r = cells_of (&e[i], &g);
      int32_t a, b;
      for (b = r.b0; b <= r.b1; ++b)
        for (a = r.a0; a <= r.a1; ++a)
          bp->cell_items[bp->cell_fill[b * g.nu + a]++] = i;
    }

  for (k = 0; k < cells; ++k)
    {
      int32_t first = bp->cell_start[k], last = bp->cell_start[k + 1];
      for (i = first; i < last; ++i)
        {
          const sweep_entry *p = &e[bp->cell_items[i]];
          int32_t hits = 0, h;
          /* the overlaps noted without a branch, as in the sweep */
          for (j = i + 1; j < last; ++j)
            {
              const sweep_entry *q = &e[bp->cell_items[j]];
              bp->hits[hits] = bp->cell_items[j];
              hits += (q->lo <= p->hi) & (q->hi >= p->lo) & (q->lo2 <= p->hi2) & (q->hi2 >= p->lo2)
                      & !(p->is_static & q->is_static);
            }
          for (h = 0; h < hits; ++h)
            {
              const sweep_entry *q = &e[bp->hits[h]];
              /* reported by the cell of the overlap's low corner only */
              if (grid_cell (fmax (p->lo, q->lo), g.u0, g.size, g.nu)
                      + g.nu * grid_cell (fmax (p->lo2, q->lo2), g.v0, g.size, g.nv)
                  != k)
                continue;
              fn (world, p->slot, q->slot, user);
            }
        }
    }
  return 1;
}

int broadphase_update (carom_world *world, const step_context *ctx, pair_callback fn, void *user)
{
  return world->live_count >= GRID_MIN_BODIES ? broadphase_grid (world, ctx, fn, user)
                                              : broadphase_sweep (world, ctx, fn, user);
}
