/* Shock propagation.
 *
 * Sequential impulses pass momentum between bodies a little per iteration,
 * about the ratio of the masses at a time: a box a thousand times heavier
 * than the one it stands on presses it through the ground long before the
 * iterations converge. And they pass it one contact per pass: a column of
 * boxes landing on each other rings along its length, its boxes sinking
 * into each other and thrown back up (docs/stability.md). Under gravity,
 * one more pass after the iterations goes through the contacts from the
 * ground up (levels: a static body is 0, a body touching level k is k + 1)
 * and solves each with its lower body held still, so every body rests on
 * what is below it (Guendelman, Bridson and Fedkiw's shock propagation).
 * The pass only removes approach: it applies no impulse where the
 * iterations already succeeded. It holds only
 *
 * - the contacts that carry a heavy body's weight onto a light one (ten
 *   times lighter): those of such a pair;
 * - columns: the contact of a body that rests on one inelastic contact
 *   with one dynamic body and on nothing else. Its whole weight goes
 *   through that contact, so holding the lower body still is the column's
 *   own solution. A body that rests on two (a pyramid's) shares its weight
 *   between them, which holding each lower body in turn does not: through
 *   every stack the benchmarks' 20-row pyramid's top moved 2.6% of its
 *   size in 10 s instead of 0.004%. A bouncy contact's impacts are
 *   impact.c's, whose restitution the pass's impulses would escape (an
 *   elastic pile gained energy);
 *
 * and, for either, those from it down to the ground, whose lower bodies
 * must stay still for it. Elsewhere in the same pile the iterations do as
 * well on their own.
 *
 * The rows are solved in waves, four at a time, with the level order's
 * results (shock_batch.h); a step whose waves need more batches than the
 * room kept solves them one at a time. */

#include "contact_solver.h"

#include "shock_batch.h"
#include "world.h"

/* Levels of the bodies and the contacts in level order, in `order`. Returns
 * the number of contacts ordered (those touching a level-0 body's pile). */
static int32_t order_by_level (carom_world *world, int32_t *order)
{
  const contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  int32_t n = world->slot_count, i, head = 0, tail = 0, count = 0;
  int32_t *level = world->solver_scratch, *start, *adj, *other, *queue;
  solver_contact_adjacency (world, &start, &adj, &other);
  queue = adj + 2 * c->count;
  for (i = 0; i < n; ++i)
    {
      level[i] = -1;
      if (sb[i].im == 0.0 && start[i + 1] > start[i])
        {
          level[i] = 0;
          queue[tail++] = i;
        }
    }
  /* by selects, every store made and the count moved past it or not:
   * whether a body is new and whether a contact goes up are not
   * predictable (solver_reserve keeps a slot past the queue and past the
   * order for the last stores, which no count moves past) */
  while (head < tail)
    {
      int32_t u = queue[head++], e, lu = level[u];
      for (e = start[u]; e < start[u + 1]; ++e)
        {
          int32_t v = other[e], fresh = level[v] < 0, lv = select_int (fresh, lu + 1, level[v]);
          level[v] = lv;
          queue[tail] = v;
          tail += fresh;
          /* contacts in the order their lower body is reached */
          order[count] = adj[e];
          count += lv > lu;
        }
    }
  return count;
}

/* Whether contact k's body a is the lower of its two (level order): the
 * other, upper, one rests on it, and a row of shock propagation moves it
 * alone. */
static int lower_is_a (const contact *k, const int32_t *level)
{
  return level[k->a] < level[k->b];
}

/* Whether the normal of a contact of `order` points up from its lower body
 * to its upper one within 60 degrees: the upper one rests on it. */
static int rests_on (const contact *k, const int32_t *level, vec2 up_dir)
{
  double lift = v2_dot (k->points[0].normal, up_dir);
  return (lower_is_a (k, level) ? lift : -lift) >= 0.5;
}

/* Touching bodies differ in mass more than this: below it the iterations
 * carry a stack's weight well, and holding lower bodies still only moves
 * contacts around. */
#define SHOCK_MASS_RATIO 10.0

static int heavy_on_light_pair (const solver_body *a, const solver_body *b)
{
  return a->im > 0.0 && b->im > 0.0 && (a->im > SHOCK_MASS_RATIO * b->im || b->im > SHOCK_MASS_RATIO * a->im);
}

/* A contact a column may rest on: inelastic, its lower body dynamic (not
 * static, asleep or kinematic: im 0). */
static int column_link (const contact *k, const solver_body *lower)
{
  return k->restitution == 0.0 && lower->im > 0.0;
}

/* count_supports' flag on both bodies of a heavy-on-light contact (above
 * any count of supports). */
#define SUPPORT_HEAVY (1 << 30)

/* Which bodies the pass holds others on, in `mark`, which holds
 * count_supports' counts: every dynamic body that rests on a column's link
 * alone, both bodies of every heavy-on-light contact, then, going down the
 * levels, every body such a body rests on. The contacts of `order` that
 * make rows (the upper body marked and resting on the lower one, the
 * normal from lower to upper within 60 degrees of straight up) go into
 * `rows`, in reverse order; returns how many. */
static int32_t mark_loaded (carom_world *world, vec2 up_dir, const int32_t *order, int32_t count, int32_t *mark,
                            int32_t *rows)
{
  const contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  const int32_t *level = world->solver_scratch;
  int32_t i, n = 0;
  for (i = 0; i < world->slot_count; ++i)
    mark[i] = (mark[i] & SUPPORT_HEAVY) != 0 || (mark[i] == 1 && sb[i].im > 0.0);
  /* `order` goes up the levels, so backwards a body is marked (for good)
   * before the contacts it rests on are reached */
  for (i = count - 1; i >= 0; --i)
    {
      const contact *k = &c->list[order[i]];
      int a_is_lower = lower_is_a (k, level);
      if (mark[a_is_lower ? k->b : k->a])
        {
          mark[a_is_lower ? k->a : k->b] = 1;
          rows[n] = order[i];
          n += rests_on (k, level, up_dir);
        }
    }
  return n;
}

/* Contact point p as a row's point with upper body `up`. */
static void row_point (shock_point *q, const contact_point *p, const solver_body *up, int a_is_lower)
{
  double r_up = a_is_lower ? p->rn_b : p->rn_a;
  q->normal = p->normal, q->ra = p->ra, q->rb = p->rb;
  q->adjusted = p->adjusted, q->rn_a = p->rn_a, q->rn_b = p->rn_b;
  q->mass = up->im + up->ii * r_up * r_up;
  q->ang = a_is_lower ? up->ii * r_up : -(up->ii * r_up);
}

/* The 2x2 matrix of a block's row, the lower body held still. */
static void row_matrix (const contact *k, const solver_body *up, int a_is_lower, double *k11, double *k12,
                        double *k22)
{
  double r1 = a_is_lower ? k->points[0].rn_b : k->points[0].rn_a;
  double r2 = a_is_lower ? k->points[1].rn_b : k->points[1].rn_a;
  double n12 = v2_dot (k->points[0].normal, k->points[1].normal);
  *k11 = up->im + up->ii * r1 * r1;
  *k12 = up->im * n12 + up->ii * r1 * r2;
  *k22 = up->im + up->ii * r2 * r2;
}

/* Row r of contact k, its points from `points` on; returns past them. */
static shock_point *make_row (shock_row *r, const contact *k, const int32_t *level, solver_body *sb,
                              shock_point *points)
{
  int a_is_lower = lower_is_a (k, level);
  solver_body *up = a_is_lower ? &sb[k->b] : &sb[k->a];
  int32_t j;
  r->a = &sb[k->a], r->b = &sb[k->b];
  r->up = up;
  r->im_up = a_is_lower ? up->im : -up->im;
  r->count = k->count;
  r->kind = k->block ? SHOCK_FACE : k->count;
  r->gap_at = -1;
  r->p = points;
  for (j = 0; j < k->count; ++j)
    row_point (&r->p[j], &k->points[j], up, a_is_lower);
  if (k->block)
    row_matrix (k, up, a_is_lower, &r->k11, &r->k12, &r->k22);
  return points + k->count;
}

/* The rows of the n contacts of `list` (mark_loaded's), in level order. */
static void make_rows (carom_world *world, const int32_t *list, int32_t n)
{
  const contacts *c = &world->contacts;
  shock_point *points = world->shock_points;
  int32_t i;
  for (i = 0; i < n; ++i)
    points = make_row (&world->shock_rows[i], &c->list[list[n - 1 - i]], world->solver_scratch,
                       world->solver_bodies, points);
}

/* The separation of a row's point now, as contact_separation. */
static inline double row_separation (const solver_body *a, const solver_body *b, const shock_point *p)
{
  vec2 d = v2_add (v2_sub (b->dp, a->dp), v2_sub (rot2_apply (b->dq, p->rb), rot2_apply (a->dq, p->ra)));
  return v2_dot (d, p->normal) + p->adjusted;
}

/* What a row's point may approach by over a sub-step at the bodies'
 * positions now: its speculative gap (by a select: whether a point is apart
 * is not predictable). */
static inline double shock_gap (const solver_body *a, const solver_body *b, const shock_point *p, double inv_h)
{
  double s = row_separation (a, b, p);
  return select_double (s > 0.0, s * inv_h, 0.0);
}

#ifdef CAROM_DEBUG_CHECKS
#include <stdio.h>
#include <stdlib.h>
/* The test builds' check of contact_shock's `moves`: a gap kept from an
 * earlier pass at the same count is the gap now, to the bit. */
static void check_gaps (const solver_body *a, const solver_body *b, const shock_row *r, double inv_h)
{
  int32_t j;
  for (j = 0; j < r->count; ++j)
    if (shock_gap (a, b, &r->p[j], inv_h) != r->p[j].gap)
      {
        fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: shock propagation kept a gap the bodies moved from\n");
        abort ();
      }
}
#else
#define check_gaps(a, b, r, inv_h) ((void) 0)
#endif

/* One row of the pass, for `count` of its points, a block or not: called
 * with both constant for the rows of one point and of two (nearly all),
 * whose loops the compiler then unrolls and whose tests it drops. */
static inline void shock_row_solve (shock_row *r, int32_t count, int block, double tol, double inv_h, int32_t moves)
{
  const solver_body *a = r->a, *b = r->b;
  /* hold the lower body still: only the upper one takes the impulse */
  solver_body *up = r->up;
  vec2 dv = v2_sub (b->v, a->v);
  /* x is written below for every point of a row that is solved */
  double err[MANIFOLD_MAX_POINTS], x[MANIFOLD_MAX_POINTS];
  int32_t j;
  int below = 0;
  /* the relative normal speed of b against a, as everywhere (contact_speed);
   * a row is solved when some point's error is below -tol (tol >= 0: the
   * least error and 0 is below it then; a NaN error is never below) */
  for (j = 0; j < count; ++j)
    {
      const shock_point *p = &r->p[j];
      err[j] = contact_speed_of (dv, a->w, b->w, p->normal, p->rn_a, p->rn_b);
      below |= err[j] < -tol;
    }
  /* the gaps only raise the errors: a row the speeds leave within
   * tolerance is left whatever they are, without computing them */
  if (!below)
    return; /* the iterations did well enough here */
  /* against what the point may approach by; positions change once a
   * sub-step, so the gaps are computed once for the two passes that see
   * the same positions, when first needed */
  if (r->gap_at != moves)
    {
      for (j = 0; j < count; ++j)
        r->p[j].gap = shock_gap (a, b, &r->p[j], inv_h);
      r->gap_at = moves;
    }
  else
    check_gaps (a, b, r, inv_h);
  below = 0;
  for (j = 0; j < count; ++j)
    {
      err[j] += r->p[j].gap;
      below |= err[j] < -tol;
    }
  if (!below)
    return;
  if (block)
    {
      /* a face: both points at once, so the push does not tip the body */
      if (!contact_lcp2 (r->k11, r->k12, r->k22, err[0], err[1], &x[0], &x[1]))
        return;
    }
  else
    for (j = 0; j < count; ++j)
      x[j] = err[j] < 0.0 && r->p[j].mass > 0.0 ? -err[j] / r->p[j].mass : 0.0;
  for (j = 0; j < count; ++j)
    if (x[j] != 0.0)
      {
        up->v = v2_mad (up->v, r->im_up * x[j], r->p[j].normal);
        up->w += r->p[j].ang * x[j];
      }
}

/* One row, by its kind (shock_row_solve's constants). */
static void shock_row_pass (shock_row *r, double tol, double inv_h, int32_t moves)
{
  switch (r->kind)
    {
    case SHOCK_FACE:
      shock_row_solve (r, 2, 1, tol, inv_h, moves);
      break;
    case 1:
      shock_row_solve (r, 1, 0, tol, inv_h, moves);
      break;
    case 2:
      shock_row_solve (r, 2, 0, tol, inv_h, moves);
      break;
    default:
      shock_row_solve (r, r->count, 0, tol, inv_h, moves);
    }
}

/* ----------------------------------------------------------------- waves */

/* A row's place in its wave: with two points (a block or not), one, or
 * more (solved one at a time). */
enum { WAVE_TWO = 0, WAVE_ONE = 1, WAVE_MORE = 2, WAVE_KINDS = 3 };

static int wave_kind (const contact *k)
{
  return k->count == 2 ? WAVE_TWO : k->count == 1 ? WAVE_ONE : WAVE_MORE;
}

/* The room contact_shock_prepare takes in world.shock_scratch for n rows:
 * their contacts (mark_loaded's), each row's wave, the bodies' first waves
 * that may write them, and the waves' cursors. */
static size_t wave_scratch (int32_t rows, int32_t slots)
{
  return 5 * (size_t) rows + WAVE_KINDS + (size_t) (slots + 1);
}

/* An unused lane: the inert body on both sides, every number 0. */
static void pack_empty (shock_batch *c, int lane, int32_t inert, int np)
{
  int j;
  c->a[lane] = c->b[lane] = c->up[lane] = inert;
  c->up_is_a[lane] = 1.0;
  c->im_up[lane] = c->face[lane] = 0.0;
  c->k11[lane] = c->k12[lane] = c->k22[lane] = 0.0;
  for (j = 0; j < np; ++j)
    {
      shock_lane_point *q = &c->p[j];
      q->nx[lane] = q->ny[lane] = q->ra_x[lane] = q->ra_y[lane] = q->rb_x[lane] = q->rb_y[lane] = 0.0;
      q->adjusted[lane] = q->rn_a[lane] = q->rn_b[lane] = q->mass[lane] = q->ang[lane] = q->gap[lane] = 0.0;
    }
}

/* Lane `lane` of batch c: the row of contact k (of one or two points). */
static void pack_contact (shock_batch *c, int lane, const contact *k, const int32_t *level, const solver_body *sb)
{
  int j, a_is_lower = lower_is_a (k, level), face = k->block;
  const solver_body *up = a_is_lower ? &sb[k->b] : &sb[k->a];
  c->a[lane] = k->a;
  c->b[lane] = k->b;
  c->up[lane] = a_is_lower ? k->b : k->a;
  c->up_is_a[lane] = !a_is_lower;
  c->im_up[lane] = a_is_lower ? up->im : -up->im;
  c->face[lane] = face;
  c->k11[lane] = c->k12[lane] = c->k22[lane] = 0.0;
  if (face)
    row_matrix (k, up, a_is_lower, &c->k11[lane], &c->k12[lane], &c->k22[lane]);
  for (j = 0; j < k->count; ++j)
    {
      shock_point p;
      shock_lane_point *q = &c->p[j];
      row_point (&p, &k->points[j], up, a_is_lower);
      q->nx[lane] = p.normal.x, q->ny[lane] = p.normal.y;
      q->ra_x[lane] = p.ra.x, q->ra_y[lane] = p.ra.y, q->rb_x[lane] = p.rb.x, q->rb_y[lane] = p.rb.y;
      q->adjusted[lane] = p.adjusted, q->rn_a[lane] = p.rn_a, q->rn_b[lane] = p.rn_b;
      q->mass[lane] = p.mass, q->ang[lane] = p.ang;
      q->gap[lane] = 0.0;
    }
}

/* Where make_waves keeps, in world.shock_scratch, the waves' cursors:
 * after the rows' contacts, each row's wave and each body's first free
 * wave. */
static int32_t *wave_cursors (carom_world *world)
{
  return world->shock_scratch + 2 * (size_t) world->shock_count + (world->slot_count + 1);
}

/* The waves of the step's rows, the contacts of `list` (mark_loaded's,
 * world.shock_count of them, in reverse level order), and their batches
 * (shock_batch.h), packed from the contacts; only the rows of more points
 * are made rows (world.shock_rows, each wave's after the last one's). Returns how
 * many waves, or 0 when the rows are to be solved one at a time: there are
 * none, or they need more batches than the room kept, which the next
 * step's reserve makes (either way gives the same bits); the caller then
 * makes every row. */
static int32_t make_waves (carom_world *world, const int32_t *list)
{
  const contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  const int32_t *level = world->solver_scratch;
  shock_batch *batches = world->shock_batches;
  shock_point *points = world->shock_points;
  int32_t n = world->shock_count, slots = world->slot_count + 1, inert = world->slot_count;
  int32_t *wave = world->shock_scratch + n, *written = wave + n, *at = wave_cursors (world);
  int32_t waves = 0, batch_count = 0, more_count = 0, i, w;
  for (i = 0; i < slots; ++i)
    written[i] = 0;
  /* a row goes after the last wave that wrote either of its bodies
   * (written[x] is the first wave past it). In level order that is all:
   * a body is written as an upper body by the rows from the level below
   * it, which come before every row from its own level, where it is read
   * as the lower one; so no row writes a body an earlier row read. */
  for (i = 0; i < n; ++i)
    {
      const contact *k = &c->list[list[n - 1 - i]];
      int a_is_lower = lower_is_a (k, level);
      int32_t up = a_is_lower ? k->b : k->a, low = a_is_lower ? k->a : k->b;
      w = written[up] > written[low] ? written[up] : written[low];
      wave[i] = w;
      written[up] = w + 1;
      /* no body was written past the last wave, so a row opens at most
       * one new wave: its counts start from 0 */
      if (w == waves)
        {
          at[WAVE_KINDS * w + WAVE_TWO] = at[WAVE_KINDS * w + WAVE_ONE] = at[WAVE_KINDS * w + WAVE_MORE] = 0;
          waves = w + 1;
        }
      ++at[WAVE_KINDS * w + wave_kind (k)];
    }
  /* wave by wave, its batches of two-point rows, then of one-point rows;
   * the cursors count lanes from the batches' start (the rows of more
   * points: rows from world.shock_rows' start) */
  for (w = 0; w < waves; ++w)
    {
      int32_t *cur = &at[WAVE_KINDS * w], two = cur[WAVE_TWO], one = cur[WAVE_ONE], extra = cur[WAVE_MORE];
      cur[WAVE_TWO] = SHOCK_LANES * batch_count;
      batch_count += (two + SHOCK_LANES - 1) / SHOCK_LANES;
      cur[WAVE_ONE] = SHOCK_LANES * batch_count;
      batch_count += (one + SHOCK_LANES - 1) / SHOCK_LANES;
      cur[WAVE_MORE] = more_count;
      more_count += extra;
    }
  if (batch_count > mem_lines_usable (world->shock_batch_cap, sizeof (shock_batch)))
    {
      world->shock_batch_want = batch_count;
      return 0;
    }
  for (i = 0; i < n; ++i)
    {
      const contact *k = &c->list[list[n - 1 - i]];
      int kind = wave_kind (k);
      int32_t place = at[WAVE_KINDS * wave[i] + kind]++;
      if (kind == WAVE_MORE)
        points = make_row (&world->shock_rows[place], k, level, sb, points);
      else
        pack_contact (&batches[place / SHOCK_LANES], place % SHOCK_LANES, k, level, sb);
    }
  /* each cursor now ends its run: fill the last batch's unused lanes */
  for (w = 0; w < waves; ++w)
    {
      int kind;
      for (kind = WAVE_TWO; kind <= WAVE_ONE; ++kind)
        {
          int32_t end = at[WAVE_KINDS * w + kind], lane;
          for (lane = end % SHOCK_LANES; lane > 0 && lane < SHOCK_LANES; ++lane)
            pack_empty (&batches[end / SHOCK_LANES], lane, inert, kind == WAVE_TWO ? 2 : 1);
        }
    }
  for (i = 0; i < batch_count; ++i)
    batches[i].gap_at = -1;
  return waves;
}

/* The rows' pass wave by wave: each wave's batches, then its rows of more
 * points (make_waves' cursors give where each run ends). */
static void wave_pass (carom_world *world, double tol, double inv_h, int32_t moves)
{
  const int32_t *at = wave_cursors (world);
  shock_batch *batches = world->shock_batches;
  void (*solve) (shock_batch *, int32_t, int, solver_body *, double, double, int32_t)
    = batch_kernels_of ((solver_path) world->solver_path)->shock;
  int32_t w, begin = 0, m = 0;
  for (w = 0; w < world->shock_waves; ++w)
    {
      const int32_t *c = &at[WAVE_KINDS * w];
      int32_t two_end = (c[WAVE_TWO] + SHOCK_LANES - 1) / SHOCK_LANES;
      int32_t one_end = (c[WAVE_ONE] + SHOCK_LANES - 1) / SHOCK_LANES;
      if (two_end > begin)
        solve (&batches[begin], two_end - begin, 2, world->solver_bodies, tol, inv_h, moves);
      if (one_end > two_end)
        solve (&batches[two_end], one_end - two_end, 1, world->solver_bodies, tol, inv_h, moves);
      for (; m < c[WAVE_MORE]; ++m)
        shock_row_pass (&world->shock_rows[m], tol, inv_h, moves);
      begin = one_end;
    }
}

static void shock_pass (carom_world *world, const step_context *ctx, double tol, int32_t moves)
{
  shock_row *rows = world->shock_rows;
  double inv_h = ctx->inv_h;
  int32_t i;
  if (world->shock_waves > 0)
    {
      wave_pass (world, tol, inv_h, moves);
      return;
    }
  for (i = 0; i < world->shock_count; ++i)
    shock_row_pass (&rows[i], tol, inv_h, moves);
}

int contact_shock_reserve (carom_world *world)
{
  /* solver_reserve's room; batches as many as a step wanted */
  int32_t usable = mem_lines_usable (world->shock_batch_cap, sizeof (shock_batch));
  int32_t want = world->shock_batch_want > usable ? world->shock_batch_want : usable;
  size_t scratch = wave_scratch (world->contacts.room_count, world->slot_count);
  if (scratch > INT32_MAX)
    return 0;
  return mem_reserve (&world->allocator, (void **) &world->shock_rows, &world->shock_cap,
                      world->contacts.room_count, sizeof (shock_row))
         && mem_reserve (&world->allocator, (void **) &world->shock_points, &world->shock_point_cap,
                         world->contacts.room_points, sizeof (shock_point))
         && mem_reserve (&world->allocator, (void **) &world->shock_scratch, &world->shock_scratch_cap,
                         (int32_t) scratch, sizeof (int32_t))
         && mem_reserve_lines (&world->allocator, &world->shock_room, (void **) &world->shock_batches,
                               &world->shock_batch_cap, want, sizeof (shock_batch));
}

void contact_shock_destroy (carom_world *world)
{
  mem_free (&world->allocator, world->shock_rows, (size_t) world->shock_cap * sizeof (shock_row));
  mem_free (&world->allocator, world->shock_points, (size_t) world->shock_point_cap * sizeof (shock_point));
  mem_free (&world->allocator, world->shock_scratch, (size_t) world->shock_scratch_cap * sizeof (int32_t));
  mem_free (&world->allocator, world->shock_room, (size_t) world->shock_batch_cap * sizeof (shock_batch));
  world->shock_rows = NULL;
  world->shock_points = NULL;
  world->shock_scratch = NULL;
  world->shock_batches = NULL;
  world->shock_room = NULL;
  world->shock_cap = world->shock_point_cap = world->shock_scratch_cap = world->shock_batch_cap = 0;
  world->shock_batch_want = 0;
}

/* What each body rests on, in `count` (one per slot): a column's link
 * counted 1 and any other support 2, so a body on a link alone counts 1;
 * the body a contact's normal points up to (within 60 degrees, as
 * rests_on) rests on the other. Both bodies of a heavy-on-light contact
 * are flagged SUPPORT_HEAVY besides, for mark_loaded (so it need not walk
 * the contacts again). Returns whether the step needs shock
 * propagation: some two touching dynamic bodies differ in mass more than
 * SHOCK_MASS_RATIO, or some dynamic body rests on a column's link alone.
 * By the normals, not the levels: those are not computed yet, and not
 * worth computing for a world that needs neither. */
static int count_supports (const carom_world *world, vec2 up_dir, int32_t *count)
{
  const contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  int32_t i;
  int needs = 0;
  for (i = 0; i < world->slot_count; ++i)
    count[i] = 0;
  for (i = 0; i < c->count; ++i)
    {
      const contact *k = &c->list[i];
      double lift = v2_dot (k->points[0].normal, up_dir);
      if (heavy_on_light_pair (&sb[k->a], &sb[k->b]))
        {
          needs = 1;
          count[k->a] |= SUPPORT_HEAVY;
          count[k->b] |= SUPPORT_HEAVY;
        }
      /* the normal points from a to b: b rests on a when it points up */
      if (lift >= 0.5)
        count[k->b] += column_link (k, &sb[k->a]) ? 1 : 2;
      else if (lift <= -0.5)
        count[k->a] += column_link (k, &sb[k->b]) ? 1 : 2;
    }
  for (i = 0; i < world->slot_count && !needs; ++i)
    needs = count[i] == 1 && sb[i].im > 0.0;
  return needs;
}

/* Where the level order goes in solver_scratch (solver_reserve's room:
 * after the levels, the adjacency's starts and contacts, and the queue
 * with its spare slot), and the marks after it and its spare slot. */
static int32_t *level_order (carom_world *world)
{
  return world->solver_scratch + 3 * world->slot_count + 2 + 2 * world->contacts.count;
}

static int32_t *level_marks (carom_world *world)
{
  return level_order (world) + world->contacts.count + 1;
}

/* The contacts in level order (`order`) and the bodies' levels, computed
 * at most once a step, for the cold start and shock propagation, which both
 * go along them (contact_prepare's contacts do not change within a step):
 * how many contacts are ordered. */
static int32_t levels (carom_world *world, int32_t **order)
{
  *order = level_order (world);
  if (world->level_count < 0)
    world->level_count = order_by_level (world, *order);
  return world->level_count;
}


/* Shock propagation for the step, if it needs it. */
void contact_shock_prepare (carom_world *world, const step_context *ctx)
{
  int32_t *order, *mark, count;
  vec2 up_dir;
  world->shock_count = world->shock_waves = 0;
  if (ctx->gravity.x == 0.0 && ctx->gravity.y == 0.0)
    return;
  up_dir = v2_neg (v2_normalize (ctx->gravity));
  mark = level_marks (world);
  if (!count_supports (world, up_dir, mark))
    return;
#ifdef CAROM_DEBUG_CHECKS
  {
    /* the levels' walk makes its last stores past the order, into the
     * spare slot before the marks (order_by_level) */
    int32_t first = mark[0];
    count = levels (world, &order);
    if (mark[0] != first)
      {
        fprintf (stderr, "carom: CAROM_DEBUG_CHECKS: the levels' walk wrote past its order\n");
        abort ();
      }
  }
#else
  count = levels (world, &order);
#endif
  world->shock_count = mark_loaded (world, up_dir, order, count, mark, world->shock_scratch);
  world->shock_waves = make_waves (world, world->shock_scratch);
  if (world->shock_waves == 0)
    make_rows (world, world->shock_scratch, world->shock_count);
}

/* The cold start. A pile built at rest has no impulses to warm start from,
 * and support spreads up it one contact per solver pass: with 8 passes a
 * step, the top of a pile 20 contacts high falls freely for steps before
 * support reaches it, and keeps the overlap it made (within the slop, which
 * position correction leaves alone). So each contact that begins resting
 * (contact.cold) starts from the weight it carries instead: going down the
 * levels, each body's weight over one sub-step (m |g| h, what a resting
 * contact's accumulated impulse comes to) plus what rests on it, shared
 * equally among the contacts it rests on, and shared equally between a
 * contact's points along its normal. A body that rests on some contact
 * with an impulse of its own already is left to the passes, and passes
 * nothing down. A column comes out exact; a pyramid's edges, whose loads
 * are not shared equally, close to it.
 *
 * A dynamic body carries at most COLD_MAX_LOAD times its own weight this
 * way: what it is started with from above and below cancels along the
 * normals' lift but not sideways (the normals lean up to 60 degrees), so a
 * light body under one heavier by 1e190 would be started at a speed past
 * any the world allows. A contact whose load is beyond that is left to
 * the passes and to shock propagation, as one that was not cold. */
#define COLD_MAX_LOAD 1e6

void contact_cold_start (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  double *load = world->cold_load;
  int32_t *order, *supports, count, i, j;
  const int32_t *level = world->solver_scratch;
  vec2 up_dir;
  if (c->cold_count == 0 || (ctx->gravity.x == 0.0 && ctx->gravity.y == 0.0))
    return;
  up_dir = v2_neg (v2_normalize (ctx->gravity));
  count = levels (world, &order);
  supports = level_marks (world);
  for (i = 0; i < world->slot_count; ++i)
    {
      load[i] = sb[i].moves == MOVES_DYNAMIC && sb[i].im > 0.0 ? ctx->accel * ctx->h / sb[i].im : 0.0;
      supports[i] = 0;
    }
  /* how many cold contacts each body rests on, or -1 when it rests on one
   * that is not cold */
  for (i = 0; i < count; ++i)
    {
      const contact *k = &c->list[order[i]];
      int32_t up = lower_is_a (k, level) ? k->b : k->a;
      if (rests_on (k, level, up_dir) && supports[up] >= 0)
        supports[up] = k->cold ? supports[up] + 1 : -1;
    }
  /* down the levels: a body's load is complete when the contacts it rests
   * on are reached */
  for (i = count - 1; i >= 0; --i)
    {
      contact *k = &c->list[order[i]];
      int a_is_lower = lower_is_a (k, level);
      int32_t up = a_is_lower ? k->b : k->a, low = a_is_lower ? k->a : k->b;
      double share, lift;
      if (!k->cold || supports[up] <= 0 || !rests_on (k, level, up_dir))
        continue;
      share = load[up] / supports[up];
      if (sb[low].moves == MOVES_DYNAMIC && !(share * sb[low].im <= COLD_MAX_LOAD * ctx->accel * ctx->h))
        continue;
      lift = fabs (v2_dot (k->points[0].normal, up_dir));
      for (j = 0; j < k->count; ++j)
        k->points[j].normal_impulse = share / (k->count * lift);
      load[low] += share;
    }
}

/* 0.1% of the speed gravity adds in a sub-step: below that the iterations
 * are left alone */
#define SHOCK_TOLERANCE 1e-3

void contact_shock (carom_world *world, const step_context *ctx, int32_t moves)
{
  if (world->shock_count > 0)
    shock_pass (world, ctx, SHOCK_TOLERANCE * ctx->accel * ctx->h, moves);
}
