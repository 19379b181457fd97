/* Shock propagation.
 *
 * Sequential impulses pass momentum between bodies a little per iteration,
 * about the ratio of the masses at a time: a box a thousand times heavier
 * than the one it stands on presses it through the ground long before the
 * iterations converge. Under gravity, when touching bodies differ in mass
 * more than tenfold, one more pass after the iterations
 * goes through the contacts from the ground up (levels: a static body is 0,
 * a body touching level k is k + 1) and solves each with its lower body held
 * still, so every body rests on what is below it whatever the masses
 * (Guendelman, Bridson and Fedkiw's shock propagation). The pass only
 * removes approach: it applies no impulse where the iterations already
 * succeeded. */

#include "contact_solver.h"

#include "world.h"

/* Levels of the bodies and the contacts in level order, in `order`. Returns
 * the number of contacts ordered (those touching a level-0 body's pile). */
static int32_t order_by_level (carom_world *world, int32_t *order)
{
  const contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  int32_t n = world->slot_count, i, head = 0, tail = 0, count = 0;
  int32_t *level = world->solver_scratch, *start = level + n, *adj = start + n + 1, *queue = adj + 2 * c->count;
  for (i = 0; i <= n; ++i)
    start[i] = 0;
  for (i = 0; i < c->count; ++i)
    {
      start[c->list[i].a + 1]++;
      start[c->list[i].b + 1]++;
    }
  for (i = 0; i < n; ++i)
    start[i + 1] += start[i];
  for (i = 0; i < c->count; ++i)
    {
      adj[start[c->list[i].a]++] = i;
      adj[start[c->list[i].b]++] = i;
    }
  for (i = n; i > 0; --i)
    start[i] = start[i - 1];
  start[0] = 0;
  for (i = 0; i < n; ++i)
    {
      level[i] = -1;
      if (sb[i].im == 0.0 && start[i + 1] > start[i])
        {
          level[i] = 0;
          queue[tail++] = i;
        }
    }
  while (head < tail)
    {
      int32_t u = queue[head++], e;
      for (e = start[u]; e < start[u + 1]; ++e)
        {
          const contact *k = &c->list[adj[e]];
          int32_t v = k->a == u ? k->b : k->a;
          if (level[v] < 0)
            {
              level[v] = level[u] + 1;
              queue[tail++] = v;
            }
          /* contacts in the order their lower body is reached */
          if (level[v] > level[u])
            order[count++] = adj[e];
        }
    }
  return count;
}

static void shock_pass (carom_world *world, const step_context *ctx, const int32_t *order, int32_t count, double tol)
{
  vec2 up_dir = v2_neg (v2_normalize (ctx->gravity));
  const contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  const int32_t *level = world->solver_scratch;
  int32_t i, j;
  for (i = 0; i < count; ++i)
    {
      const contact *k = &c->list[order[i]];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      /* hold the lower body still: only the upper one takes the impulse */
      int a_is_lower = level[k->a] < level[k->b];
      solver_body *up = a_is_lower ? b : a;
      double err[MANIFOLD_MAX_POINTS], x[MANIFOLD_MAX_POINTS], worst = 0.0;
      /* only where the upper body rests on the lower one: the normal from
       * lower to upper within 60 degrees of straight up */
      double lift = v2_dot (k->points[0].normal, up_dir);
      if ((a_is_lower ? lift : -lift) < 0.5)
        continue;
      for (j = 0; j < k->count; ++j)
        {
          const contact_point *p = &k->points[j];
          /* the relative normal speed of b against a, as everywhere, against
           * what the point may approach by (a speculative gap) */
          double s = contact_separation (a, b, p);
          err[j] = contact_speed (a, b, p->normal, p->rn_a, p->rn_b) + (s > 0.0 ? s * ctx->inv_h : 0.0);
          worst = err[j] < worst ? err[j] : worst;
          x[j] = 0.0;
        }
      if (worst >= -tol)
        continue; /* the iterations did well enough here */
      if (k->block)
        {
          /* a face: both points at once, so the push does not tip the body */
          double r1 = a_is_lower ? k->points[0].rn_b : k->points[0].rn_a;
          double r2 = a_is_lower ? k->points[1].rn_b : k->points[1].rn_a;
          double n12 = v2_dot (k->points[0].normal, k->points[1].normal);
          if (!contact_lcp2 (up->im + up->ii * r1 * r1, up->im * n12 + up->ii * r1 * r2, up->im + up->ii * r2 * r2, err[0],
                     err[1], &x[0], &x[1]))
            continue;
        }
      else
        for (j = 0; j < k->count; ++j)
          {
            double r = a_is_lower ? k->points[j].rn_b : k->points[j].rn_a, m = up->im + up->ii * r * r;
            x[j] = err[j] < 0.0 && m > 0.0 ? -err[j] / m : 0.0;
          }
      for (j = 0; j < k->count; ++j)
        {
          const contact_point *p = &k->points[j];
          double r_up = a_is_lower ? p->rn_b : p->rn_a;
          /* raising vn: +x n on b, or -x n on a */
          double lambda = a_is_lower ? x[j] : -x[j];
          if (x[j] == 0.0)
            continue;
          up->v = v2_mad (up->v, up->im * lambda, p->normal);
          up->w += up->ii * r_up * lambda;
        }
    }
}

/* Whether two touching dynamic bodies differ in mass more than tenfold:
 * below that the iterations handle stacks well, and holding lower bodies
 * still in a loose pile (rain) only moves contacts around. */
static int heavy_on_light (const carom_world *world)
{
  const contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  int32_t i;
  for (i = 0; i < c->count; ++i)
    {
      double ia = sb[c->list[i].a].im, ib = sb[c->list[i].b].im;
      if (ia > 0.0 && ib > 0.0 && (ia > 10.0 * ib || ib > 10.0 * ia))
        return 1;
    }
  return 0;
}

/* Shock propagation for the step, if it needs it: the contacts in level
 * order, once per step (contact_prepare's contacts do not change within
 * it). */
void contact_shock_prepare (carom_world *world, const step_context *ctx)
{
  world->shock_count = 0;
  if ((ctx->gravity.x != 0.0 || ctx->gravity.y != 0.0) && heavy_on_light (world))
    world->shock_count = order_by_level (world, world->solver_scratch + 3 * world->slot_count + 1
                                                    + 2 * world->contacts.count);
}

/* 0.1% of the speed gravity adds in a sub-step: below that the iterations
 * are left alone */
#define SHOCK_TOLERANCE 1e-3

void contact_shock (carom_world *world, const step_context *ctx)
{
  if (world->shock_count > 0)
    shock_pass (world, ctx, world->solver_scratch + 3 * world->slot_count + 1 + 2 * world->contacts.count,
                world->shock_count, SHOCK_TOLERANCE * ctx->accel * ctx->h);
}
