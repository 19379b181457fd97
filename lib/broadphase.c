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
  mem_free (&world->allocator, bp->cell_ranges, (size_t) bp->ranges_cap * sizeof (int32_t));
  mem_free (&world->allocator, bp->reach, (size_t) bp->reach_cap * sizeof (double));
  mem_free (&world->allocator, bp->hits, (size_t) bp->hits_cap * sizeof (int32_t));
  mem_free (&world->allocator, bp->fat, (size_t) bp->fat_cap * sizeof (fat_box));
  mem_free (&world->allocator, bp->pairs, (size_t) bp->pairs_cap * sizeof (int32_t));
  memset (bp, 0, sizeof *bp);
}

/* Boxes grow by the body's contact margin and by how far it can move in
 * this sub-step, so pairs that are apart but within the margin, or that will
 * meet before the next detection, are still reported. */
static inline void fill_entry (broadphase *bp, sweep_entry *e, const body *b, int axis, double slop,
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

/* The entry's box grown by BROAD_FAT_FRACTION of its body's size (by
 * nothing for a size that is not finite): its fat box. */
static fat_box fattened (const sweep_entry *e, const body *b)
{
  double g = BROAD_FAT_FRACTION * b->shape.size;
  fat_box f;
  if (!(g < INFINITY))
    g = 0.0;
  f.lo = e->lo - g, f.hi = e->hi + g;
  f.lo2 = e->lo2 - g, f.hi2 = e->hi2 + g;
  f.escaped = 0;
  return f;
}

/* Whether two fat boxes overlap. */
static int fat_overlap (const fat_box *f, const fat_box *g)
{
  return (g->lo <= f->hi) & (g->hi >= f->lo) & (g->lo2 <= f->hi2) & (g->hi2 >= f->lo2);
}

/* Give every escaped entry its new fat box. */
static void refatten (carom_world *world, int32_t n)
{
  broadphase *bp = &world->broad;
  int32_t i;
  for (i = 0; i < n; ++i)
    {
      const sweep_entry *e = &bp->entries[i];
      if (bp->fat[e->slot].escaped)
        bp->fat[e->slot] = fattened (e, &world->bodies[e->slot]);
    }
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
  /* one entry more than the bodies: the sweep's sentinel */
  return mem_reserve (&world->allocator, (void **) &bp->entries, &bp->cap, world->live_count + 1, sizeof (sweep_entry))
         && mem_reserve (&world->allocator, (void **) &bp->scratch, &bp->scratch_cap, world->live_count,
                         sizeof (sweep_entry))
         && mem_reserve (&world->allocator, (void **) &bp->reach, &bp->reach_cap, world->slot_count, sizeof (double))
         && mem_reserve (&world->allocator, (void **) &bp->fat, &bp->fat_cap, world->slot_count, sizeof (fat_box))
         && mem_reserve (&world->allocator, (void **) &bp->hits, &bp->hits_cap, world->live_count, sizeof (int32_t));
}

/* Sweep the boxes (the entries sorted by `lo`) and report each pair that
 * meets (never two static bodies). */
static void sweep_boxes (carom_world *world, int32_t n, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  int32_t i;
  /* past the last entry, one whose lo is no number: f->lo <= e.hi fails
   * there whatever e.hi is, which ends every window without a test of the
   * end (reserve_entries keeps room for it) */
  bp->entries[n].lo = NAN;
  for (i = 0; i < n; ++i)
    {
      /* a copy, and a pointer walk: the compiler cannot tell that fn leaves
       * the entries alone, and this loop runs for every nearby pair. The
       * overlaps are noted without a branch (whether two boxes in the
       * window overlap is not predictable), then reported. */
      const sweep_entry e = bp->entries[i];
      const sweep_entry *f;
      int32_t *hit = bp->hits, *last = hit;
      /* only a static entry's window needs the test that two static
       * bodies make no pair: most entries are not */
      if (e.is_static)
        for (f = &bp->entries[i + 1]; f->lo <= e.hi; ++f)
          {
            *last = f->slot;
            last += (f->lo2 <= e.hi2) & (f->hi2 >= e.lo2) & !f->is_static;
          }
      else
        for (f = &bp->entries[i + 1]; f->lo <= e.hi; ++f)
          {
            *last = f->slot;
            last += (f->lo2 <= e.hi2) & (f->hi2 >= e.lo2);
          }
      for (; hit < last; ++hit)
        fn (world, e.slot, *hit, user);
    }
}

/* Keep entry i's hits (entry indices) as pairs with it. Returns 0 when
 * memory ran out. */
static int keep_hits (carom_world *world, int32_t i, int32_t hits)
{
  broadphase *bp = &world->broad;
  int32_t k;
  if (hits > 0
      && !mem_reserve (&world->allocator, (void **) &bp->pairs, &bp->pairs_cap, bp->pair_count + 2 * hits,
                       sizeof (int32_t)))
    return 0;
  for (k = 0; k < hits; ++k)
    {
      bp->pairs[bp->pair_count++] = i;
      bp->pairs[bp->pair_count++] = bp->hits[k];
    }
  return 1;
}

/* Sweep the fat boxes (the entries sorted by `lo`) and keep every pair
 * that overlaps (never two static bodies). A fat box begins at most `lead`
 * before its entry's box: once an entry's box begins more than that beyond
 * the end of this fat box, neither it nor any later one can overlap it.
 * Returns 0 when memory ran out. */
static int sweep_fat (carom_world *world, int32_t n)
{
  broadphase *bp = &world->broad;
  double lead = 0.0;
  int32_t i;
  bp->pairs_valid = 0;
  bp->pair_count = 0;
  bp->entries[n].lo = NAN; /* the sentinel, as in sweep_boxes */
  for (i = 0; i < n; ++i)
    {
      double d = bp->entries[i].lo - bp->fat[bp->entries[i].slot].lo;
      lead = d > lead ? d : lead;
    }
  for (i = 0; i < n; ++i)
    {
      const fat_box e = bp->fat[bp->entries[i].slot];
      int32_t is_static = bp->entries[i].is_static, hits = 0;
      const sweep_entry *f;
      for (f = &bp->entries[i + 1]; f->lo - lead <= e.hi; ++f)
        {
          const fat_box *g = &bp->fat[f->slot];
          bp->hits[hits] = (int32_t) (f - bp->entries);
          hits += (g->lo <= e.hi) & (g->hi >= e.lo) & (g->lo2 <= e.hi2) & (g->hi2 >= e.lo2)
                  & !(is_static & f->is_static);
        }
      if (!keep_hits (world, i, hits))
        return 0;
    }
  bp->pairs_valid = 1;
  return 1;
}

/* Mend the kept pairs for the entries whose boxes left their fat boxes:
 * their pairs go, and the pairs of their new fat boxes come in, at the end.
 * The room is found first: when memory runs out (returns 0), nothing has
 * changed. */
static int mend_kept (carom_world *world, int32_t n)
{
  broadphase *bp = &world->broad;
  int32_t i, j, kept = 0, more = 0;
  /* count the new pairs: each escaped entry's new fat box against the
   * others' (an escaped one's new one, the pair counted once) */
  for (i = 0; i < n; ++i)
    {
      const sweep_entry *e = &bp->entries[i];
      fat_box f;
      if (!bp->fat[e->slot].escaped)
        continue;
      f = fattened (e, &world->bodies[e->slot]);
      for (j = 0; j < n; ++j)
        {
          const sweep_entry *o = &bp->entries[j];
          fat_box g = bp->fat[o->slot];
          if (g.escaped)
            {
              if (j <= i)
                continue;
              g = fattened (o, &world->bodies[o->slot]);
            }
          more += fat_overlap (&f, &g) & !(e->is_static & o->is_static);
        }
    }
  if (!mem_reserve (&world->allocator, (void **) &bp->pairs, &bp->pairs_cap, bp->pair_count + 2 * more,
                    sizeof (int32_t)))
    return 0;
  /* nothing fails from here on */
  for (i = 0; i < bp->pair_count; i += 2)
    if (!bp->fat[bp->entries[bp->pairs[i]].slot].escaped && !bp->fat[bp->entries[bp->pairs[i + 1]].slot].escaped)
      {
        bp->pairs[kept++] = bp->pairs[i];
        bp->pairs[kept++] = bp->pairs[i + 1];
      }
  bp->pair_count = kept;
  /* the new fat boxes, still marked escaped until every pair is in */
  for (i = 0; i < n; ++i)
    {
      const sweep_entry *e = &bp->entries[i];
      if (bp->fat[e->slot].escaped)
        {
          bp->fat[e->slot] = fattened (e, &world->bodies[e->slot]);
          bp->fat[e->slot].escaped = 1;
        }
    }
  for (i = 0; i < n; ++i)
    {
      const fat_box e = bp->fat[bp->entries[i].slot];
      int32_t is_static = bp->entries[i].is_static, hits = 0;
      if (!e.escaped)
        continue;
      for (j = 0; j < n; ++j)
        {
          const fat_box *g = &bp->fat[bp->entries[j].slot];
          bp->hits[hits] = j;
          /* with another escaped entry, the pair is kept from the lower index */
          hits += fat_overlap (&e, g) & !(is_static & bp->entries[j].is_static) & (!g->escaped | (j > i));
        }
      keep_hits (world, i, hits); /* room reserved above */
    }
  for (i = 0; i < n; ++i)
    bp->fat[bp->entries[i].slot].escaped = 0;
  return 1;
}

/* Kept pairs tested at a time by report_kept. */
#define REPORT_CHUNK 64

/* Reporting the kept pairs of a world of PREFETCH_MIN_BODIES live bodies
 * or more (broadphase.h), the bodies of the pair PREFETCH_AHEAD places on
 * and the convex pieces of the pair half as far on are asked of the
 * memory before the pair's turn. Each pair's detection reads both bodies'
 * first four cache lines (body.h) and their pieces, and the kept pairs
 * come in the order of the bodies' boxes, not of their slots: in a world
 * that outgrows the caches the detection waited for them (`perf` on the
 * settled rain: the loads of a body's shape and of a piece's centre were
 * detect_pair's slowest instructions, and it took 14% of the time for 11%
 * of the instructions). In smaller worlds they stay in the caches from one
 * step to the next, and the requests would only add instructions. No
 * result depends on them. */
#define PREFETCH_AHEAD 4

#ifdef __GNUC__
#define prefetch(p) __builtin_prefetch (p)
#else
#define prefetch(p) ((void) 0)
#endif

static void prefetch_body (const carom_world *world, int32_t slot)
{
  const char *b = (const char *) &world->bodies[slot];
  /* a body's first four lines, wherever its 360 bytes begin in a line */
  prefetch (b);
  prefetch (b + 64);
  prefetch (b + 128);
  prefetch (b + 192);
  prefetch (b + 255);
}

/* (the body's line with shape.pieces has been asked for already) */
static void prefetch_pieces (const carom_world *world, int32_t slot)
{
  const convex_piece *p = world->bodies[slot].shape.pieces;
  if (p)
    {
      prefetch (p);
      prefetch (p->vertices);
      prefetch (p->normals);
    }
}

/* Before pair k of the n whose bodies are in slots sa[], sb[]. */
static void prefetch_pairs_ahead (const carom_world *world, const int32_t *sa, const int32_t *sb, int32_t k,
                                  int32_t n)
{
  if (k + PREFETCH_AHEAD < n)
    {
      prefetch_body (world, sa[k + PREFETCH_AHEAD]);
      prefetch_body (world, sb[k + PREFETCH_AHEAD]);
    }
  if (k + PREFETCH_AHEAD / 2 < n)
    {
      prefetch_pieces (world, sa[k + PREFETCH_AHEAD / 2]);
      prefetch_pieces (world, sb[k + PREFETCH_AHEAD / 2]);
    }
}

/* Report the n pairs of slots sa[k], sb[k] in order, the bodies of those
 * ahead asked of the memory in worlds of PREFETCH_MIN_BODIES or more. */
static void report_pairs (carom_world *world, const int32_t *sa, const int32_t *sb, int32_t n, pair_callback fn,
                          void *user)
{
  int ahead = world->live_count >= PREFETCH_MIN_BODIES;
  int32_t k;
  for (k = 0; k < n; ++k)
    {
      if (ahead)
        prefetch_pairs_ahead (world, sa, sb, k, n);
      fn (world, sa[k], sb[k], user);
    }
}

/* Report the kept pairs whose boxes meet, in the order they were kept. The
 * meetings of a chunk are noted without a branch (whether two fat boxes'
 * boxes meet is not predictable), then reported. */
static void report_kept (carom_world *world, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  int32_t i, k, met[REPORT_CHUNK], sa[REPORT_CHUNK], sb[REPORT_CHUNK];
  for (i = 0; i < bp->pair_count; i += 2 * REPORT_CHUNK)
    {
      int32_t end = i + 2 * REPORT_CHUNK < bp->pair_count ? i + 2 * REPORT_CHUNK : bp->pair_count, hits = 0;
      for (k = i; k < end; k += 2)
        {
          const sweep_entry *e = &bp->entries[bp->pairs[k]], *f = &bp->entries[bp->pairs[k + 1]];
          met[hits] = k;
          hits += (e->lo <= f->hi) & (f->lo <= e->hi) & (e->lo2 <= f->hi2) & (f->lo2 <= e->hi2);
        }
      for (k = 0; k < hits; ++k)
        {
          sa[k] = bp->entries[bp->pairs[met[k]]].slot;
          sb[k] = bp->entries[bp->pairs[met[k] + 1]].slot;
        }
      report_pairs (world, sa, sb, hits, fn, user);
    }
}

/* A detection, with the update's context ctx:
 *  - after an update whose boxes were swept, for BROAD_MOVING_STEPS
 *    updates: sweep the boxes again;
 *  - else look at the fat boxes: when more than one body in
 *    BROAD_MEND_SHARE left its fat box, give those new fat boxes and sweep
 *    the boxes (and leave the fat boxes alone for a while); when fewer did,
 *    mend the kept pairs (or, with none kept, sweep the fat boxes) and test
 *    them.
 * What a detection decides and leaves depends on the bodies and on what
 * the last successful update left: one that fails (here, or in a later
 * stage of the update) and is tried again decides the same and reports the
 * same pairs in the same order. */
int broadphase_sweep (carom_world *world, const step_context *ctx, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  int32_t i, n, escaped = 0;
  int axis = widest_axis (world), look = ctx->update >= bp->look_at;
  if (axis != bp->axis)
    {
      /* switch only for a clear difference, so the order stays coherent */
      bp->axis = axis;
      bp->dirty = 1;
    }
  if (!reserve_entries (world))
    return 0;
  bp->sorted = 0;
  if (bp->dirty)
    {
      n = bp->count = fill_all (world, ctx);
      for (i = 0; i < n; ++i)
        bp->fat[bp->entries[i].slot] = fattened (&bp->entries[i], &world->bodies[bp->entries[i].slot]);
      bp->pairs_valid = 0;
      bp->dirty = 0;
      escaped = n;
      look = 1;
    }
  else
    {
      n = bp->count;
      for (i = 0; i < n; ++i)
        {
          sweep_entry *e = &bp->entries[i];
          fat_box *f = &bp->fat[e->slot];
          fill_entry (bp, e, &world->bodies[e->slot], bp->axis, world->def.slop, ctx);
          if (look)
            {
              f->escaped = !(e->lo >= f->lo && e->hi <= f->hi && e->lo2 >= f->lo2 && e->hi2 <= f->hi2);
              escaped += f->escaped;
            }
        }
      if (!look)
        escaped = n;
    }
  if (escaped > n / BROAD_MEND_SHARE)
    {
      /* many bodies left their fat boxes: sweep the boxes */
      if (look)
        {
          refatten (world, n);
          bp->look_at = ctx->update + 1 + BROAD_MOVING_STEPS;
        }
      bp->pairs_valid = 0;
      if (!insertion_sort (bp->entries, n))
        merge_sort (bp->entries, bp->scratch, n);
      bp->sorted = 1;
      sweep_boxes (world, n, fn, user);
      return 1;
    }
  if (!bp->pairs_valid)
    {
      refatten (world, n);
      if (!insertion_sort (bp->entries, n))
        merge_sort (bp->entries, bp->scratch, n);
      bp->sorted = 1;
      if (!sweep_fat (world, n))
        return 0;
    }
  else if (escaped > 0 && !mend_kept (world, n))
    return 0;
  report_kept (world, fn, user); /* the pairs that meet are among the kept */
  return 1;
}

/* ------------------------------------------------------------- queries */

void broadphase_box (const carom_world *world, int32_t slot, double reach, sweep_entry *e)
{
  const body *b = &world->bodies[slot];
  double m = world->def.slop * b->shape.size + reach;
  vec2 lo = v2 (b->box_lo.x - m, b->box_lo.y - m), hi = v2 (b->box_hi.x + m, b->box_hi.y + m);
  e->slot = slot;
  e->is_static = b->type == CAROM_STATIC;
  e->lo = world->broad.axis == 0 ? lo.x : lo.y, e->hi = world->broad.axis == 0 ? hi.x : hi.y;
  e->lo2 = world->broad.axis == 0 ? lo.y : lo.x, e->hi2 = world->broad.axis == 0 ? hi.y : hi.x;
}

/* Whether entry a sorts before b: by lo, then by slot (a total order, so
 * the heap sort below gives the same order on every run). */
static int entry_before (const sweep_entry *a, const sweep_entry *b)
{
  return a->lo < b->lo || (a->lo == b->lo && a->slot < b->slot);
}

static void sift_down (sweep_entry *a, int32_t i, int32_t n)
{
  for (;;)
    {
      int32_t c = 2 * i + 1;
      sweep_entry t;
      if (c >= n)
        return;
      if (c + 1 < n && entry_before (&a[c], &a[c + 1]))
        ++c;
      if (!entry_before (&a[i], &a[c]))
        return;
      t = a[i], a[i] = a[c], a[c] = t;
      i = c;
    }
}

/* In place, O(k log k) with no scratch: the query's boxes live in the
 * sweep's own scratch. */
static void heap_sort (sweep_entry *a, int32_t n)
{
  int32_t i;
  for (i = n / 2 - 1; i >= 0; --i)
    sift_down (a, i, n);
  for (i = n - 1; i > 0; --i)
    {
      sweep_entry t = a[0];
      a[0] = a[i], a[i] = t;
      sift_down (a, 0, i);
    }
}

static int boxes_meet (const sweep_entry *a, const sweep_entry *b)
{
  return a->lo <= b->hi && a->hi >= b->lo && a->lo2 <= b->hi2 && a->hi2 >= b->lo2;
}

/* Whether a query box and an entry make a pair to report. */
static int query_pair (const sweep_entry *box, const sweep_entry *e)
{
  return boxes_meet (box, e) && !(box->is_static & e->is_static);
}

/* The first of the n entries (sorted by lo) whose lo is at least x. */
static int32_t first_from (const sweep_entry *a, int32_t n, double x)
{
  int32_t lo = 0, hi = n;
  while (lo < hi)
    {
      int32_t mid = lo + (hi - lo) / 2;
      if (a[mid].lo < x)
        lo = mid + 1;
      else
        hi = mid;
    }
  return lo;
}

void broadphase_query (carom_world *world, sweep_entry *boxes, int32_t k, const double *queried, pair_callback fn,
                       void *user)
{
  broadphase *bp = &world->broad;
  const sweep_entry *e = bp->entries;
  double lead = 0.0;
  int32_t i, j, n = bp->count;
  heap_sort (boxes, k);
  for (i = 0; i < k; ++i)
    {
      double w = boxes[i].hi - boxes[i].lo;
      lead = w > lead ? w : lead;
      /* the boxes among themselves: a sweep */
      for (j = i + 1; j < k && boxes[j].lo <= boxes[i].hi; ++j)
        if (boxes_meet (&boxes[i], &boxes[j]))
          fn (world, boxes[i].slot, boxes[j].slot, user);
    }
  if (bp->sorted)
    {
      /* the entries sorted by lo (this detection swept them): each box
       * looks up those that begin within the widest entry's width of it.
       * Entries wider than every box (walls, the ground) are few: each is
       * tested against every box instead, so that they do not widen the
       * lookup of all the others. */
      double wide = 0.0;
      for (i = 0; i < n; ++i)
        {
          double w = e[i].hi - e[i].lo;
          if (w <= lead)
            wide = w > wide ? w : wide;
          else if (queried[e[i].slot] == 0.0)
            for (j = 0; j < k; ++j)
              if (query_pair (&boxes[j], &e[i]))
                fn (world, boxes[j].slot, e[i].slot, user);
        }
      for (j = 0; j < k; ++j)
        for (i = first_from (e, n, boxes[j].lo - wide); i < n && e[i].lo <= boxes[j].hi; ++i)
          if (queried[e[i].slot] == 0.0 && e[i].hi - e[i].lo <= lead && query_pair (&boxes[j], &e[i]))
            fn (world, boxes[j].slot, e[i].slot, user);
      return;
    }
  for (i = 0; i < n; ++i)
    {
      if (queried[e[i].slot] != 0.0)
        continue; /* met above */
      /* from the first box that can reach the entry: none begins more
       * than lead before its end */
      for (j = first_from (boxes, k, e[i].lo - lead); j < k && boxes[j].lo <= e[i].hi; ++j)
        if (query_pair (&boxes[j], &e[i]))
          fn (world, boxes[j].slot, e[i].slot, user);
    }
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

/* The cell index of coordinate x along an axis of `count` cells: the floor
 * of (x - origin) / size within 0 .. count - 1, which for a quotient from 0
 * up to count is its truncation (no call to floor). */
static int32_t grid_cell (double x, double origin, double size, int32_t count)
{
  double c = (x - origin) / size;
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

/* The cells entry i covers, as cells_of found them for the grid's final
 * size (broadphase.cell_ranges, four per entry). */
static cell_range cells_kept (const broadphase *bp, int32_t i)
{
  const int32_t *k = &bp->cell_ranges[4 * i];
  cell_range r;
  r.a0 = k[0], r.a1 = k[1], r.b0 = k[2], r.b1 = k[3];
  return r;
}

/* fmin and fmax as x86-64's minsd and maxsd compute them (the second
 * operand when both are zeros), a NaN operand ignored as fmin and fmax
 * ignore it: the grid's bounds the same bits without a call for each. */
static inline double min_of (double x, double y)
{
  return y != y ? x : x < y ? x : y;
}

static inline double max_of (double x, double y)
{
  return y != y ? x : x > y ? x : y;
}

int broadphase_grid (carom_world *world, const step_context *ctx, pair_callback fn, void *user)
{
  broadphase *bp = &world->broad;
  const sweep_entry *e;
  grid_frame g;
  double u1, v1, limit;
  int32_t n, i, j, k, cells, total, moving = 0, sa[REPORT_CHUNK], sb[REPORT_CHUNK], found = 0;
  if (!reserve_entries (world))
    return 0;
  n = bp->count = fill_all (world, ctx);
  bp->sorted = 0;
  bp->dirty = 1; /* the sweep, if it runs again, starts afresh */
  e = bp->entries;
  if (n == 0)
    return 1;
  g.u0 = e[0].lo, u1 = e[0].hi, g.v0 = e[0].lo2, v1 = e[0].hi2, g.size = 0.0;
  for (i = 0; i < n; ++i)
    {
      g.u0 = min_of (g.u0, e[i].lo), u1 = max_of (u1, e[i].hi);
      g.v0 = min_of (g.v0, e[i].lo2), v1 = max_of (v1, e[i].hi2);
      if (!e[i].is_static)
        g.size += max_of (e[i].hi - e[i].lo, e[i].hi2 - e[i].lo2), moving++;
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
  if (!mem_reserve (&world->allocator, (void **) &bp->cell_ranges, &bp->ranges_cap, 4 * n, sizeof (int32_t)))
    return 0;
  if (!(g.size > 0.0))
    g.size = max_of (u1 - g.u0, v1 - g.v0) + 1.0;
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
          int32_t *k = &bp->cell_ranges[4 * i];
          k[0] = r.a0, k[1] = r.a1, k[2] = r.b0, k[3] = r.b1;
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
      cell_range r = cells_kept (bp, i);
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
      cell_range r = cells_kept (bp, i);
      int32_t a, b;
      for (b = r.b0; b <= r.b1; ++b)
        for (a = r.a0; a <= r.a1; ++a)
          bp->cell_items[bp->cell_fill[b * g.nu + a]++] = i;
    }

  /* the pairs found are reported REPORT_CHUNK at a time, in the order
   * found: the cells' bodies come in no order of their slots, and a world
   * this large does not keep them in the caches (report_pairs) */
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
              /* reported by the cell of the overlap's low corner only:
               * grid_cell never decreases as its coordinate grows, so the
               * corner's cell is the larger of the two boxes' first cells
               * on each axis (no division) */
              cell_range rp = cells_kept (bp, bp->cell_items[i]), rq = cells_kept (bp, bp->hits[h]);
              if ((rp.a0 > rq.a0 ? rp.a0 : rq.a0) + g.nu * (rp.b0 > rq.b0 ? rp.b0 : rq.b0) != k)
                continue;
              sa[found] = p->slot, sb[found] = q->slot;
              if (++found == REPORT_CHUNK)
                {
                  report_pairs (world, sa, sb, found, fn, user);
                  found = 0;
                }
            }
        }
    }
  report_pairs (world, sa, sb, found, fn, user);
  return 1;
}

int broadphase_update (carom_world *world, const step_context *ctx, pair_callback fn, void *user)
{
  return world->live_count >= GRID_MIN_BODIES ? broadphase_grid (world, ctx, fn, user)
                                              : broadphase_sweep (world, ctx, fn, user);
}
