/* Collision resolution by sequential impulses.
 *
 * For one contact point the impulse is the thesis' eq. 3.23 with its two
 * slips corrected: the relative velocity is that of the contact points,
 * v_p = v_bp - v_ap (v_ap alone in the thesis), and both bodies' angular
 * terms add with the same sign (eq. 3.17 flips the B term):
 *
 *   j = -(1 + e) v_p . n / (1/m_a + 1/m_b + (r_ap x n)^2 / I_a + (r_bp x n)^2 / I_b)
 *
 * Here n points from A to B and B receives +j n, A receives -j n (the
 * thesis' n points the other way; the formula is the same). Many contacts
 * at once (stacks, a box lying on the floor) are solved together by
 * iterating: each pass applies at every point the impulse that makes its
 * relative normal velocity reach its target, keeping the accumulated impulse
 * non-negative, so contacts only push. A single isolated contact is solved
 * exactly by the first pass (eq. 3.23), and later passes do nothing.
 *
 * Overlap is removed by split impulses: the same iteration on
 * pseudo-velocities that move the bodies apart during the drift and are then
 * dropped, so position correction never changes the real velocities and
 * adds no kinetic energy (the thesis' minimum push vector, split by mass,
 * is the one-contact case of this). */
#include "solver.h"

#include "gravity.h"
#include "world.h"

/* The solver works on a compact copy of what it reads and writes per body
 * (64 bytes instead of the whole body), gathered before and scattered
 * after: the iterations touch each body many times. */
static void gather (carom_world *world)
{
  solver_body *sb = world->solver_bodies;
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      sb[i].v = b->v;
      sb[i].w = b->w;
      sb[i].pv = v2 (0.0, 0.0);
      sb[i].pw = 0.0;
      sb[i].im = b->alive ? b->inv_mass : 0.0;
      sb[i].ii = b->alive ? b->inv_inertia : 0.0;
    }
}

static void scatter (carom_world *world)
{
  const solver_body *sb = world->solver_bodies;
  int32_t i;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (sb[i].im == 0.0 && sb[i].ii == 0.0)
        continue; /* static, sleeping or dead: nothing changed */
      b->v = sb[i].v;
      b->w = sb[i].w;
      b->pv = sb[i].pv;
      b->pw = sb[i].pw;
    }
}

/* An impulse lambda along a direction d applied at the point: B gets
 * +lambda d, A gets -lambda d; ra_d = ra x d and rb_d = rb x d. */
static inline void push (solver_body *a, solver_body *b, vec2 d, double ra_d, double rb_d, double lambda)
{
  a->v = v2_mad (a->v, -a->im * lambda, d);
  a->w -= a->ii * ra_d * lambda;
  b->v = v2_mad (b->v, b->im * lambda, d);
  b->w += b->ii * rb_d * lambda;
}

/* The same on the pseudo-velocities (position correction). */
static inline void push_pseudo (solver_body *a, solver_body *b, vec2 d, double ra_d, double rb_d, double lambda)
{
  a->pv = v2_mad (a->pv, -a->im * lambda, d);
  a->pw -= a->ii * ra_d * lambda;
  b->pv = v2_mad (b->pv, b->im * lambda, d);
  b->pw += b->ii * rb_d * lambda;
}

/* (v_bp - v_ap) . d, eq. 3.15 and the corrected 3.17, using
 * (w x r) . d = w (r x d) */
static inline double relative_speed (const solver_body *a, const solver_body *b, vec2 d, double ra_d, double rb_d)
{
  return v2_dot (v2_sub (b->v, a->v), d) + b->w * rb_d - a->w * ra_d;
}

/* The same on the pseudo-velocities (position correction). */
static inline double pseudo_relative_speed (const solver_body *a, const solver_body *b, vec2 d, double ra_d,
                                            double rb_d)
{
  return v2_dot (v2_sub (b->pv, a->pv), d) + b->pw * rb_d - a->pw * ra_d;
}

static double effective_mass (const solver_body *a, const solver_body *b, double ra_d, double rb_d)
{
  double k = a->im + b->im + a->ii * ra_d * ra_d + b->ii * rb_d * rb_d;
  /* a non-finite k (a body far smaller than the rounding of its
   * coordinates) leaves the point inert rather than poisoning the world */
  return k > 0.0 && isfinite (k) ? 1.0 / k : 0.0;
}

/* The effective masses of a point, eq. 3.23's denominator along the normal
 * and the tangent. An inert direction also loses its lever arms and its
 * impulse: ii * (r x d) may itself overflow there, and inf * 0 in push is
 * NaN. */
static void point_masses (contact_point *p, const solver_body *a, const solver_body *b)
{
  p->normal_mass = effective_mass (a, b, p->rn_a, p->rn_b);
  p->tangent_mass = effective_mass (a, b, p->rt_a, p->rt_b);
  if (p->normal_mass == 0.0)
    p->rn_a = p->rn_b = p->normal_impulse = 0.0;
  if (p->tangent_mass == 0.0)
    p->rt_a = p->rt_b = p->tangent_impulse = 0.0;
}

/* Lever arms of a contact point. A lever arm cannot be longer than the body
 * reaches (rounding of far-apart coordinates can make it so for a tiny
 * body); a circle's normal impulse passes through its centre, so r x n is
 * exactly 0 there whatever the rounding of the point says. */
static void lever_arms (contact_point *p, const body *ba, const body *bb, vec2 ra, vec2 rb)
{
  vec2 t = v2_perp (p->normal);
  double la = 2.0 * ba->shape.bound_radius + fabs (p->depth), lb = 2.0 * bb->shape.bound_radius + fabs (p->depth);
  double na = v2_len (ra), nb = v2_len (rb);
  if (na > la)
    ra = v2_scale (ra, la / na);
  if (nb > lb)
    rb = v2_scale (rb, lb / nb);
  p->ra = ra;
  p->rb = rb;
  p->rn_a = ba->shape.kind == CAROM_SHAPE_CIRCLE ? 0.0 : v2_cross (ra, p->normal);
  p->rn_b = bb->shape.kind == CAROM_SHAPE_CIRCLE ? 0.0 : v2_cross (rb, p->normal);
  p->rt_a = v2_cross (ra, t);
  p->rt_b = v2_cross (rb, t);
}

/* Whether a point approaching at vn (< 0 when approaching) faster than the
 * threshold reaches the other body within this sub-step. */
static int reaches (const contact *k, const contact_point *p, double vn, double threshold, double h)
{
  return k->restitution > 0.0 && vn < -threshold && vn * h - p->depth < 0.0;
}

/* Targets of a contact's points from their normal speeds vn before any
 * impulse of this sub-step; dg is the part of vn that gravity added this
 * sub-step after the bodies met. */
static void set_targets (contact *k, const double *vn, const double *dg, int impact, double h)
{
  int32_t j;
  for (j = 0; j < k->count; ++j)
    {
      contact_point *p = &k->points[j];
      if (impact)
        {
          /* eq. 3.18 at every point of the manifold: each may leave at e
           * times its own approach speed. Then the impulses change the
           * kinetic energy by sum_i j_i (v_i,before + v_i,after) / 2, which
           * is zero for e = 1 at the exact solution: elastic impacts
           * conserve energy even with several points at once. */
          p->target = -k->restitution * (vn[j] - dg[j]) + dg[j];
        }
      else
        {
          /* a speculative point (apart by -depth) may close its gap but not
           * pass it; a touching one may not approach */
          p->target = p->depth < 0.0 ? p->depth / h : 0.0;
          /* a separating point that other impacts push back gets eq. 3.18
           * too, so a chain of bodies hit at once stays elastic (the same
           * energy argument as above) */
          if (k->restitution > 0.0 && vn[j] > 0.0 && -k->restitution * vn[j] < p->target)
            p->target = -k->restitution * (vn[j] - dg[j]) + dg[j];
        }
    }
}

static void prepare (carom_world *world, double h)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  double g = v2_len (world->gravity);
  /* below this approach speed a contact does not bounce: the speed a body
   * resting under gravity gains in one sub-step, so resting stays resting;
   * with no gravity every approach bounces */
  double threshold = 2.0 * g * h;
  double beta = world->def.position_correction;
  int forces = g > 0.0 || world->central.active;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      body *ba = &world->bodies[k->a], *bb = &world->bodies[k->b];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      double vn[MANIFOLD_MAX_POINTS], dg[MANIFOLD_MAX_POINTS] = { 0.0 }, old_nm[MANIFOLD_MAX_POINTS], old_tm[MANIFOLD_MAX_POINTS];
      int impact = 0;
      ba->touching = bb->touching = 1;
      k->overlapping = 0;
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          old_nm[j] = p->normal_mass;
          old_tm[j] = p->tangent_mass;
          lever_arms (p, ba, bb, v2_sub (p->point, ba->p), v2_sub (p->point, bb->p));
          point_masses (p, a, b);
          vn[j] = relative_speed (a, b, p->normal, p->rn_a, p->rn_b);
          /* an impact: a point approaching faster than the threshold that
           * reaches the other body within this sub-step */
          if (reaches (k, p, vn[j], threshold, h))
            impact = 1;
          p->bias = p->depth > k->slop ? beta * (p->depth - k->slop) / h : 0.0;
          k->overlapping |= p->bias != 0.0;
          p->pseudo_impulse = 0.0;
          p->toi = 0.0;
          if (k->friction == 0.0)
            p->tangent_impulse = 0.0;
        }
      /* An impact is solved where it happens: a time t = depth / vn into
       * the step (for points still apart), with the bodies moved by their
       * velocities to that moment and the impact point moved with them.
       * Both bodies' lever arms then reach the same point of space, so the
       * impulses conserve angular momentum about any point exactly, and
       * apply_time_of_impact puts the bodies where the event leaves them. */
      if (impact)
        for (j = 0; j < k->count; ++j)
          {
            contact_point *p = &k->points[j];
            vec2 meet;
            double toi;
            if (!(p->depth < 0.0 && vn[j] < 0.0))
              continue;
            toi = p->depth / vn[j] < h ? p->depth / vn[j] : h;
            p->toi = toi;
            meet = v2_mad (p->point, 0.5 * toi, v2_add (a->v, b->v));
            lever_arms (p, ba, bb, v2_sub (meet, v2_mad (ba->p, toi, a->v)), v2_sub (meet, v2_mad (bb->p, toi, b->v)));
            point_masses (p, a, b);
            vn[j] = relative_speed (a, b, p->normal, p->rn_a, p->rn_b);
          }
      /* two points solved together: their 2x2 matrix, if well conditioned
       * (on one face the normals agree; the vertex-edge method may give two
       * points with their own normals, coupled by n1 . n2) */
      k->block = 0;
      if (k->count == 2)
        {
          const contact_point *p1 = &k->points[0], *p2 = &k->points[1];
          double im = a->im + b->im;
          k->k11 = im + a->ii * p1->rn_a * p1->rn_a + b->ii * p1->rn_b * p1->rn_b;
          k->k22 = im + a->ii * p2->rn_a * p2->rn_a + b->ii * p2->rn_b * p2->rn_b;
          k->k12 = im * v2_dot (p1->normal, p2->normal) + a->ii * p1->rn_a * p2->rn_a + b->ii * p1->rn_b * p2->rn_b;
          k->det = k->k11 * k->k22 - k->k12 * k->k12;
          k->block = k->k11 * k->k11 < 1e4 * k->det && p1->normal_mass > 0.0 && p2->normal_mass > 0.0;
        }
      /* A bouncy contact (e >= 0.5) still apart that does not close its gap
       * on its own this sub-step sits this step out. Constraining it would
       * stop its bodies at the gap's closing speed when an impact elsewhere
       * sends them into each other, silently absorbing the rest of their
       * approach (an elastic gas lost a quarter of its energy in 3000 steps
       * that way); left alone they meet in the next step as an impact of
       * their own, eq. 3.18 and all, and the overlap of that one step is
       * removed by split impulses, which add no energy. Less bouncy contacts
       * are always solved: for them absorbing is close to what e asks, and
       * piles (rain) would otherwise sink into each other. And nothing waits
       * under gravity (uniform or central): bodies let fall into each other
       * and pushed back out by position correction, which lifts them for
       * free, would pump energy into a bouncy pile (an elastic gas under
       * gravity gained a factor of 10^4 in 10 s that way). */
      k->deferred = !impact && k->restitution >= 0.5 && !forces;
      for (j = 0; j < k->count; ++j)
        if (k->points[j].depth >= 0.0)
          k->deferred = 0;
      if (k->deferred)
        for (j = 0; j < k->count; ++j)
          k->points[j].normal_impulse = k->points[j].tangent_impulse = 0.0;
      else
        {
          /* An impact between bodies that already touch or overlap (none
           * was looked for further ahead) happened before this sub-step's
           * gravity: eq. 3.18 applies to the approach without it, and
           * gravity then acts on the bounce, which it did not before. (A
           * ball hitting the floor at dt 1/60 bounced 17% too high, and an
           * elastic pile under gravity gained 15% energy in 10 s.) */
          if (impact && forces)
            {
              vec2 dgab = v2_sub (gravity_dv (world, bb, h), gravity_dv (world, ba, h));
              for (j = 0; j < k->count; ++j)
                if (k->points[j].depth >= 0.0 && vn[j] - v2_dot (dgab, k->points[j].normal) < 0.0)
                  dg[j] = v2_dot (dgab, k->points[j].normal);
            }
          set_targets (k, vn, dg, impact, h);
        }
      /* A warm-start impulse changes the velocities by impulse / mass. If
       * the effective mass fell since last step (a lever arm that grew, as
       * across a long speculative gap), last step's impulse would now give a
       * larger change than it ever did: it is scaled down to give the same
       * one. Otherwise a tiny body whose arm grew a thousandfold would be
       * spun a millionfold faster at once, and then overflow. */
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          if (p->normal_mass < old_nm[j])
            p->normal_impulse *= p->normal_mass / old_nm[j];
          if (p->tangent_mass < old_tm[j])
            p->tangent_impulse *= p->tangent_mass / old_tm[j];
        }
    }
  /* warm start with last step's impulses, only once every target above was
   * measured on the velocities before any impulse */
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      for (j = 0; j < k->count; ++j)
        {
          const contact_point *p = &k->points[j];
          push (a, b, p->normal, p->rn_a, p->rn_b, p->normal_impulse);
          if (p->tangent_impulse != 0.0)
            push (a, b, v2_perp (p->normal), p->rt_a, p->rt_b, p->tangent_impulse);
        }
    }
}

/* Two points (a box lying flat) solved together, exactly: the
 * 2x2 linear complementarity problem  w = K x + b, x >= 0, w >= 0, x.w = 0,
 * by trying each set of active points in turn. Sequential impulses would
 * only approach this answer as iterations go to infinity. Returns 0 when the
 * two points are (nearly) redundant and the caller should iterate instead. */
/* An impact solved at the start of the step really happened a time t into
 * it, after the bodies closed their gap. Leaving at their new velocities for
 * the whole step, they would end too far apart by the gap plus what they
 * would have travelled towards each other, (v_before - v_after) t per body:
 * a ball would bounce from where it was, not from the floor (+20% bounce
 * height at e = 0.5). Each body is moved back by exactly that, through the
 * pseudo-velocities (an impulse of -t / h times the contact's): positions
 * then match the exact event, velocities are untouched (no energy), and the
 * state is the true one, so angular momentum stays conserved too. */
static void apply_time_of_impact (carom_world *world, double h)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      for (j = 0; j < k->count; ++j)
        {
          const contact_point *p = &k->points[j];
          double f;
          vec2 t;
          if (p->toi <= 0.0)
            continue;
          f = -p->toi / h;
          t = v2_perp (p->normal);
          push_pseudo (a, b, p->normal, p->rn_a, p->rn_b, f * p->normal_impulse);
          push_pseudo (a, b, t, p->rt_a, p->rt_b, f * p->tangent_impulse);
        }
    }
}

static int solve_pair_block (solver_body *a, solver_body *b, contact *k)
{
  contact_point *p1 = &k->points[0], *p2 = &k->points[1];
  double k11 = k->k11, k22 = k->k22, k12 = k->k12, det = k->det;
  double x1_old = p1->normal_impulse, x2_old = p2->normal_impulse, x1, x2, b1, b2;
  /* b: the velocity error with the current impulses taken back out */
  b1 = relative_speed (a, b, p1->normal, p1->rn_a, p1->rn_b) - p1->target - (k11 * x1_old + k12 * x2_old);
  b2 = relative_speed (a, b, p2->normal, p2->rn_a, p2->rn_b) - p2->target - (k12 * x1_old + k22 * x2_old);
  /* both points push */
  x1 = (-k22 * b1 + k12 * b2) / det;
  x2 = (k12 * b1 - k11 * b2) / det;
  if (!(x1 >= 0.0 && x2 >= 0.0))
    {
      /* only the first pushes */
      x1 = -b1 / k11, x2 = 0.0;
      if (!(x1 >= 0.0 && k12 * x1 + b2 >= 0.0))
        {
          /* only the second */
          x1 = 0.0, x2 = -b2 / k22;
          if (!(x2 >= 0.0 && k12 * x2 + b1 >= 0.0))
            {
              /* neither: both separate on their own */
              x1 = x2 = 0.0;
              if (!(b1 >= 0.0 && b2 >= 0.0))
                return 0; /* rounding left no consistent case */
            }
        }
    }
  push (a, b, p1->normal, p1->rn_a, p1->rn_b, x1 - x1_old);
  push (a, b, p2->normal, p2->rn_a, p2->rn_b, x2 - x2_old);
  p1->normal_impulse = x1;
  p2->normal_impulse = x2;
  return 1;
}

static void solve_velocities (carom_world *world)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      if (k->deferred)
        continue;
      if (k->friction > 0.0)
        for (j = 0; j < k->count; ++j)
          {
            /* Coulomb: the tangent impulse stays within mu times the normal
             * impulse */
            contact_point *p = &k->points[j];
            vec2 t;
            double vt, limit, acc;
            /* no normal impulse (a third of rain's points): the limit is 0,
             * so a tangent impulse of 0 stays 0 */
            if (p->normal_impulse == 0.0 && p->tangent_impulse == 0.0)
              continue;
            t = v2_perp (p->normal);
            vt = relative_speed (a, b, t, p->rt_a, p->rt_b);
            limit = k->friction * p->normal_impulse;
            acc = p->tangent_impulse - p->tangent_mass * vt;
            acc = acc > limit ? limit : (acc < -limit ? -limit : acc);
            push (a, b, t, p->rt_a, p->rt_b, acc - p->tangent_impulse);
            p->tangent_impulse = acc;
          }
      if (k->block && solve_pair_block (a, b, k))
        continue;
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          double vn = relative_speed (a, b, p->normal, p->rn_a, p->rn_b);
          double acc = p->normal_impulse - p->normal_mass * (vn - p->target);
          if (acc < 0.0)
            acc = 0.0;
          push (a, b, p->normal, p->rn_a, p->rn_b, acc - p->normal_impulse);
          p->normal_impulse = acc;
        }
    }
}

static void solve_positions (carom_world *world)
{
  contacts *c = &world->contacts;
  solver_body *sb = world->solver_bodies;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      solver_body *a = &sb[k->a], *b = &sb[k->b];
      if (!k->overlapping)
        continue;
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          double vn, acc;
          /* pseudo_impulse starts at 0, so a point without bias never acts */
          if (p->bias == 0.0)
            continue;
          vn = pseudo_relative_speed (a, b, p->normal, p->rn_a, p->rn_b);
          acc = p->pseudo_impulse - p->normal_mass * (vn - p->bias);
          if (acc < 0.0)
            acc = 0.0;
          push_pseudo (a, b, p->normal, p->rn_a, p->rn_b, acc - p->pseudo_impulse);
          p->pseudo_impulse = acc;
        }
    }
}

/* ------------------------------------------------------ shock propagation
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

/* Smallest x >= 0 with K x + b >= 0 and complementarity, for a 2x2
 * symmetric K (the case enumeration of solve_pair_block, from x = 0). */
static int lcp2 (double k11, double k12, double k22, double b1, double b2, double *x1, double *x2)
{
  double det = k11 * k22 - k12 * k12;
  if (det > 1e-12 * k11 * k22)
    {
      *x1 = (-k22 * b1 + k12 * b2) / det;
      *x2 = (k12 * b1 - k11 * b2) / det;
      if (*x1 >= 0.0 && *x2 >= 0.0)
        return 1;
    }
  *x1 = -b1 / k11, *x2 = 0.0;
  if (*x1 >= 0.0 && k12 * *x1 + b2 >= 0.0)
    return 1;
  *x1 = 0.0, *x2 = -b2 / k22;
  if (*x2 >= 0.0 && k12 * *x2 + b1 >= 0.0)
    return 1;
  *x1 = *x2 = 0.0;
  return b1 >= 0.0 && b2 >= 0.0;
}

static void shock_pass (carom_world *world, const int32_t *order, int32_t count, int pseudo, double tol)
{
  vec2 up_dir = v2_neg (v2_normalize (world->gravity));
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
          /* the relative normal speed of b against a, as everywhere */
          double vn = pseudo ? pseudo_relative_speed (a, b, p->normal, p->rn_a, p->rn_b)
                             : relative_speed (a, b, p->normal, p->rn_a, p->rn_b);
          err[j] = vn - (pseudo ? p->bias : p->target);
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
          if (!lcp2 (up->im + up->ii * r1 * r1, up->im * n12 + up->ii * r1 * r2, up->im + up->ii * r2 * r2, err[0],
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
          if (pseudo)
            {
              up->pv = v2_mad (up->pv, up->im * lambda, p->normal);
              up->pw += up->ii * r_up * lambda;
            }
          else
            {
              up->v = v2_mad (up->v, up->im * lambda, p->normal);
              up->w += up->ii * r_up * lambda;
            }
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

int solver_reserve (carom_world *world)
{
  int32_t need = 4 * world->slot_count + 1 + 3 * world->contacts.count;
  return mem_reserve (&world->allocator, (void **) &world->solver_bodies, &world->solver_cap, world->slot_count,
                      sizeof (solver_body))
         && mem_reserve (&world->allocator, (void **) &world->solver_scratch, &world->scratch_cap, need,
                         sizeof (int32_t));
}

void solver_destroy (carom_world *world)
{
  mem_free (&world->allocator, world->solver_bodies, (size_t) world->solver_cap * sizeof (solver_body));
  mem_free (&world->allocator, world->solver_scratch, (size_t) world->scratch_cap * sizeof (int32_t));
  world->solver_bodies = NULL;
  world->solver_scratch = NULL;
  world->solver_cap = world->scratch_cap = 0;
}

void solver_update (carom_world *world, const step_context *ctx)
{
  double h = ctx->h;
  int32_t it, shocked, *order = NULL;
  double tol = 0.0;
  if (world->contacts.count == 0)
    return;
  gather (world);
  prepare (world, h);
  for (it = 0; it < world->def.iterations; ++it)
    solve_velocities (world);
  apply_time_of_impact (world, h);
  shocked = 0;
  if ((world->gravity.x != 0.0 || world->gravity.y != 0.0) && heavy_on_light (world))
    {
      order = world->solver_scratch + 3 * world->slot_count + 1 + 2 * world->contacts.count;
      shocked = order_by_level (world, order);
      /* 0.1% of the speed gravity adds in a sub-step: below that the
       * iterations are left alone */
      tol = 1e-3 * v2_len (world->gravity) * h;
      shock_pass (world, order, shocked, 0, tol);
    }
  for (it = 0; it < world->def.iterations; ++it)
    solve_positions (world);
  if (shocked)
    shock_pass (world, order, shocked, 1, tol);
  scatter (world);
}
