/* The order of the stages in one update (sub-stepping after Catto's "soft
 * step"): the contacts are detected once, at the start (contact.c), and set
 * up once (contact_prepare; those that begin resting start from the weight
 * they carry, contact_cold_start); then each of `substeps` sub-steps
 *
 *   kicks the velocities with gravity and damping,
 *   applies the impulses the contacts carried so far (warm starting),
 *   solves the contacts (iterations passes, more for small bodies),
 *   pushes overlap out on pseudo-velocities (split impulses, iterations
 *   passes), which never touch the velocities (so the batches' first
 *   push-out pass rides along with their last solve pass),
 *   moves the bodies by their velocities plus the pseudo-velocities, which
 *   are then dropped,
 *   and solves again (iterations passes);
 *
 * and at the end, restitution, once, on the points that were struck. Small
 * sub-steps make the few passes enough: a stack converges over the
 * sub-steps as it would over many iterations of one step, at the cost of
 * no extra detection. */
#include "solver.h"

#include "contact_batch.h"
#include "contact_solver.h"
#include "impact.h"
#include "damping.h"
#include "force.h"
#include "gravity.h"
#include "joint.h"
#include "tunnel.h"
#include "world.h"

#include <string.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

/* The solver's compact copy of what it reads and writes per body (128 bytes
 * instead of the whole body, two cache lines from a line on, so that no row
 * of it spans two), gathered before the sub-steps and written back after:
 * the passes touch each body many times. Every slot's is built anew here,
 * so the copies need not outlive a step (mem_reserve_lines keeps none). */
static void gather (carom_world *world)
{
  solver_body *sb = world->solver_bodies;
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      int moves = !b->alive ? MOVES_NOT
                  : b->type == CAROM_DYNAMIC && !b->asleep ? MOVES_DYNAMIC
                  : b->type == CAROM_KINEMATIC ? MOVES_KINEMATIC
                                               : MOVES_NOT;
      /* built whole and stored at once: wide stores instead of one per
       * field */
      solver_body s;
      s.v = b->v;
      s.w = b->w;
      /* A body that does not move under the constraints keeps its
       * velocities to the bit through the passes: an impulse on it is
       * +0 or -0 times its inverse masses of 0 (impulses and arms are
       * finite), and adding either zero leaves every number but -0 as it
       * was. So that no lane of a batch can change what another reads
       * (contact_batch_kernel.h), a -0 is made +0 here (finish does not
       * write it back). */
      if (moves != MOVES_DYNAMIC)
        s.v.x += 0.0, s.v.y += 0.0, s.w += 0.0;
      s.dp = v2 (0.0, 0.0);
      s.pv = v2 (0.0, 0.0);
      s.pw = 0.0;
      s.row_end_v = s.row_end_pv = 0.0;
      s.dq.c = 1.0, s.dq.s = 0.0;
      s.da = 0.0;
      s.im = moves == MOVES_DYNAMIC ? b->inv_mass : 0.0;
      s.ii = moves == MOVES_DYNAMIC ? b->inv_inertia : 0.0;
      /* a kinematic body moves with the velocity it was given, exactly */
      s.constrained = moves == MOVES_KINEMATIC;
      s.moves = moves;
      sb[i] = s;
    }
  /* the inert body of the batches' unused lanes (contact_batch.h), and
   * the ground of joints to the world: never moved, never turned */
  memset (&sb[world->slot_count], 0, sizeof *sb);
  sb[world->slot_count].dq.c = 1.0;
}

/* Move every body the sub-steps move by its velocity over one sub-step.
 * The angle is summed exactly; the rotation the constraints use is advanced
 * by the first-order step, renormalised (its error, of order (w h)^3, only
 * shifts where a contact thinks its points are within one step). */
static void integrate_positions (carom_world *world, const step_context *ctx)
{
  solver_body *sb = world->solver_bodies;
  double h = ctx->h;
  vec2 back = v2_scale (ctx->kick, -0.5);
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      solver_body *b = &sb[i];
      double a;
      if (!b->moves)
        continue;
      b->dp = v2_mad (b->dp, h, v2_add (gravity_drift_velocity (back, b), b->pv));
      a = h * (b->w + b->pw);
      b->pv = v2 (0.0, 0.0);
      b->pw = 0.0;
      /* c - a s written as c + (-a) s, the same bits (IEEE subtraction is
       * the addition of the negated operand, and negation is exact): two
       * like sums, which the compiler makes into fewer instructions */
#ifdef __SSE2__
      /* the two sums in the two lanes of one register, and the square
       * root by the instruction, without the library's check for a
       * negative argument (c^2 + s^2 is none): the same operations in
       * the same order, so the same bits */
      {
        __m128d q = _mm_loadu_pd (&b->dq.c), r, sq;
        r = _mm_add_pd (q, _mm_mul_pd (_mm_set_pd (a, -a), _mm_shuffle_pd (q, q, 1)));
        sq = _mm_mul_pd (r, r);
        sq = _mm_sqrt_sd (sq, _mm_add_sd (sq, _mm_unpackhi_pd (sq, sq)));
        sq = _mm_div_sd (_mm_set_sd (1.0), sq);
        _mm_storeu_pd (&b->dq.c, _mm_mul_pd (r, _mm_unpacklo_pd (sq, sq)));
      }
#else
      {
        double c = b->dq.c + (-a) * b->dq.s;
        double s = b->dq.s + a * b->dq.c;
        double n = 1.0 / sqrt (c * c + s * s);
        b->dq.c = c * n, b->dq.s = s * n;
      }
#endif
      b->da += a;
    }
}

/* Write the new velocities and poses back to the bodies. */
static void finish (carom_world *world)
{
  const solver_body *sb = world->solver_bodies;
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (!sb[i].moves)
        continue;
      /* a kinematic body keeps the velocity it was given, exactly (its
       * solver copy may have had a -0 made +0, gather) */
      if (sb[i].moves == MOVES_DYNAMIC)
        {
          b->v = sb[i].v;
          b->w = sb[i].w;
        }
      b->p = v2_add (b->p, sb[i].dp);
      b->angle += sb[i].da;
      body_sync (b);
    }
}

int solver_reserve (carom_world *world)
{
  /* shock.c: levels, adjacency starts, queue and marks (or the cold
   * start's supports) per body; adjacency (two per contact), the level
   * order, and the adjacency's other bodies (two per contact) per contact;
   * a spare slot after the queue and after the order (order_by_level) */
  contacts *c = &world->contacts;
  int32_t room = contacts_headroom (world), count = c->count + room;
  int32_t need = 4 * world->slot_count + 3 + 5 * count;
  int32_t batches = count / BATCH_LANES + 2 * CONSTRAINT_COLOURS;
  /* the contacts added after the impacts (contacts_after_impacts) go in
   * room kept now: nothing is allocated within the step. Every array per
   * contact, here and in events_reserve, is sized by room_count, and
   * contacts_after_impacts adds none past it. */
  if (room > 0)
    {
      if (!mem_reserve (&world->allocator, (void **) &c->list, &c->cap, count, sizeof (contact))
          || !mem_reserve (&world->allocator, (void **) &c->pool, &c->pool_cap,
                           c->point_count + MANIFOLD_MAX_POINTS * room, sizeof (contact_point)))
        return 0;
      contacts_point_again (world); /* the pool may have moved */
    }
  c->room_count = count;
  c->room_points = c->point_count + MANIFOLD_MAX_POINTS * room;
  return mem_reserve_lines (&world->allocator, &world->solver_room, (void **) &world->solver_bodies,
                            &world->solver_cap, world->slot_count + 1, sizeof (solver_body))
         && mem_reserve_lines (&world->allocator, &world->batch_room, (void **) &world->batches, &world->batch_cap,
                               batches, sizeof (contact_batch))
         && mem_reserve (&world->allocator, (void **) &world->colour_used, &world->colour_cap, world->slot_count,
                         sizeof (uint32_t))
         && mem_reserve (&world->allocator, (void **) &world->batch_scratch, &world->batch_scratch_cap,
                         2 * count + 4 * CONSTRAINT_COLOURS + 1, sizeof (int32_t))
         && mem_reserve (&world->allocator, (void **) &world->solver_scratch, &world->scratch_cap, need,
                         sizeof (int32_t))
         && mem_reserve (&world->allocator, (void **) &world->cold_load, &world->cold_load_cap, world->slot_count,
                         sizeof (double))
         && contact_shock_reserve (world) && joint_tree_reserve (world)
         && mem_reserve (&world->allocator, (void **) &world->restitution_list, &world->restitution_cap,
                         count, sizeof (int32_t))
         && mem_reserve (&world->allocator, (void **) &world->impact_shifts, &world->impact_shift_cap,
                         world->slot_count + 1, sizeof (impact_shift))
         && mem_reserve (&world->allocator, (void **) &world->impact_events, &world->impact_events_cap,
                         count, sizeof (int32_t))
         && (room == 0 || contact_impacts_reserve (world));
}

void solver_destroy (carom_world *world)
{
  mem_free (&world->allocator, world->solver_room, (size_t) world->solver_cap * sizeof (solver_body));
  mem_free (&world->allocator, world->solver_scratch, (size_t) world->scratch_cap * sizeof (int32_t));
  mem_free (&world->allocator, world->cold_load, (size_t) world->cold_load_cap * sizeof (double));
  world->cold_load = NULL;
  world->cold_load_cap = 0;
  mem_free (&world->allocator, world->restitution_list, (size_t) world->restitution_cap * sizeof (int32_t));
  mem_free (&world->allocator, world->impact_shifts, (size_t) world->impact_shift_cap * sizeof (impact_shift));
  mem_free (&world->allocator, world->impact_events, (size_t) world->impact_events_cap * sizeof (int32_t));
  contact_impacts_destroy (world);
  world->impact_shifts = NULL;
  world->impact_events = NULL;
  world->impact_shift_cap = world->impact_events_cap = 0;
  contact_shock_destroy (world);
  joint_tree_destroy (world);
  mem_free (&world->allocator, world->batch_room, (size_t) world->batch_cap * sizeof (contact_batch));
  mem_free (&world->allocator, world->colour_used, (size_t) world->colour_cap * sizeof (uint32_t));
  mem_free (&world->allocator, world->batch_scratch, (size_t) world->batch_scratch_cap * sizeof (int32_t));
  world->batches = NULL;
  world->batch_room = NULL;
  world->colour_used = NULL;
  world->batch_scratch = NULL;
  world->batch_cap = world->colour_cap = world->batch_scratch_cap = 0;
  world->solver_bodies = NULL;
  world->solver_room = NULL;
  world->solver_scratch = NULL;
  world->restitution_list = NULL;
  world->solver_cap = world->scratch_cap = world->restitution_cap = 0;
}

void solver_contact_adjacency (carom_world *world, int32_t **start_out, int32_t **adj_out, int32_t **other_out)
{
  /* the contacts in locals, and each next place read once: through the
   * int32_t stores, which might alias them as far as the compiler knows,
   * every use would reload them */
  const contact *list = world->contacts.list;
  int32_t count = world->contacts.count;
  int32_t n = world->slot_count, i;
  int32_t *start = world->solver_scratch + n, *adj = start + n + 1;
  int32_t *other = world->solver_scratch + 4 * n + 3 + 3 * count;
  for (i = 0; i <= n; ++i)
    start[i] = 0;
  for (i = 0; i < count; ++i)
    {
      start[list[i].a + 1]++;
      start[list[i].b + 1]++;
    }
  for (i = 0; i < n; ++i)
    start[i + 1] += start[i];
  for (i = 0; i < count; ++i)
    {
      int32_t a = list[i].a, b = list[i].b, e;
      e = start[a]++;
      other[e] = b;
      adj[e] = i;
      e = start[b]++;
      other[e] = a;
      adj[e] = i;
    }
  for (i = n; i > 0; --i)
    start[i] = start[i - 1];
  start[0] = 0;
  *start_out = start;
  *adj_out = adj;
  if (other_out)
    *other_out = other;
}

void solver_step (carom_world *world, const step_context *ctx)
{
  int contacts = world->contacts.count > 0;
  int joints = world->joints.live > 0;
  int32_t k, it;
  gather (world);
  if (joints)
    joint_prepare (world, ctx);
  if (contacts)
    {
      world->level_count = -1;
      contact_prepare (world, ctx);
      contact_impacts (world, ctx);
      contact_cold_start (world, ctx);
      contact_batch_prepare (world, ctx);
      contact_shock_prepare (world, ctx);
    }
  if (joints)
    joint_mark_bodies (world);
  for (k = 0; k < ctx->substeps; ++k)
    {
      gravity_kick (world, ctx);
      if (joints)
        gravity_joint_hold (world, ctx);
      force_kick (world, ctx);
      damping_update (world, ctx);
      if (joints)
        joint_warm_start (world);
      if (contacts)
        {
          contact_batch_warm_start (world);
          contact_warm_start (world, ctx->dt - k * ctx->h);
        }
      for (it = 0; it < ctx->iterations; ++it)
        {
          if (joints)
            joint_solve (world, ctx, 1);
          if (contacts)
            {
              /* the batches' last solve pass walks them once with their
               * first push-out pass (which reads nothing a velocity pass
               * writes) */
              if (it + 1 < ctx->iterations)
                contact_batch_solve (world, ctx);
              else
                contact_batch_solve_push_out (world, ctx);
              contact_solve (world, ctx, k + 1, ctx->dt - k * ctx->h, 0);
            }
        }
      if (contacts)
        {
          double first = 0.0;
          for (; it < world->contacts.fine_passes; ++it)
            {
              double change = contact_solve (world, ctx, k + 1, ctx->dt - k * ctx->h, it);
              first = it == ctx->iterations ? change : first;
              if (!(change > CONTACT_FINE_CONVERGED * first))
                break;
            }
          contact_shock (world, ctx, k);
          for (it = 0; it < ctx->iterations; ++it)
            {
              if (it > 0)
                contact_batch_push_out (world, ctx, 0);
              contact_push_out (world, ctx, it == 0);
            }
        }
      integrate_positions (world, ctx);
      force_drift_undo (world, ctx);
      if (joints)
        {
          joint_project (world, ctx);
          gravity_joint_kick (world, ctx);
        }
      /* relax: the velocity errors alone, without the joints' correction */
      for (it = 0; it < ctx->iterations; ++it)
        {
          if (joints)
            joint_solve (world, ctx, 0);
          if (contacts)
            {
              contact_batch_solve (world, ctx);
              contact_solve (world, ctx, k + 1, ctx->dt - (k + 1) * ctx->h, 0);
            }
        }
      if (contacts)
        contact_shock (world, ctx, k + 1);
      if (joints)
        joint_sum_reaction (world);
    }
  if (contacts)
    {
      contact_batch_store (world);
      contact_restitution (world, ctx);
      contact_time_of_impact (world, ctx);
      tunnel_guard (world, ctx);
    }
  if (joints)
    joint_finish (world, ctx);
  finish (world);
}
