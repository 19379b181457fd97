#include "broadphase.h"

#include <string.h>

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
  memset (bp, 0, sizeof *bp);
}

/* Boxes grow by the body's contact margin and by how far it can move in
 * this sub-step, so pairs that are apart but within the margin, or that will
 * meet before the next detection, are still reported. */
static void fill_entry (sweep_entry *e, const body *b, int axis, double slop, double h, double accel, int continuous)
{
  double m = slop * b->shape.size + body_reach (b, h, accel, continuous);
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

int broadphase_update (carom_world *world, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  int32_t i, n;
  int axis = widest_axis (world);
  double accel = v2_len (world->gravity);
  if (axis != bp->axis)
    {
      /* switch only for a clear difference, so the order stays coherent */
      bp->axis = axis;
      bp->dirty = 1;
    }
  if (!mem_reserve (&world->allocator, (void **) &bp->entries, &bp->cap, world->live_count, sizeof (sweep_entry))
      || !mem_reserve (&world->allocator, (void **) &bp->scratch, &bp->scratch_cap, world->live_count,
                       sizeof (sweep_entry)))
    return 0;
  if (bp->dirty)
    {
      n = 0;
      for (i = 0; i < world->slot_count; ++i)
        if (world->bodies[i].alive)
          {
            bp->entries[n].slot = i;
            fill_entry (&bp->entries[n], &world->bodies[i], bp->axis, world->def.slop, world->step_h, accel,
                        world->continuous);
            n++;
          }
      bp->count = n;
      merge_sort (bp->entries, bp->scratch, n);
      bp->dirty = 0;
    }
  else
    {
      n = bp->count;
      for (i = 0; i < n; ++i)
        fill_entry (&bp->entries[i], &world->bodies[bp->entries[i].slot], bp->axis, world->def.slop, world->step_h, accel,
                    world->continuous);
      if (!insertion_sort (bp->entries, n))
        merge_sort (bp->entries, bp->scratch, n);
    }

  for (i = 0; i < n; ++i)
    {
      /* a copy, and a pointer walk: the compiler cannot tell that fn leaves
       * the entries alone, and this loop runs for every nearby pair */
      const sweep_entry e = bp->entries[i];
      const sweep_entry *f, *end = bp->entries + n;
      for (f = &bp->entries[i + 1]; f < end && f->lo <= e.hi; ++f)
        {
          if (f->lo2 > e.hi2 || f->hi2 < e.lo2 || (e.is_static && f->is_static))
            continue;
          fn (world, e.slot, f->slot, user);
        }
    }
  return 1;
}
