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

#include "world.h"

static void apply_impulse (body *a, body *b, const contact_point *p, vec2 impulse)
{
  a->v = v2_mad (a->v, -a->inv_mass, impulse);
  a->w -= a->inv_inertia * v2_cross (p->ra, impulse);
  b->v = v2_mad (b->v, b->inv_mass, impulse);
  b->w += b->inv_inertia * v2_cross (p->rb, impulse);
}

/* v_bp - v_ap, eq. 3.15 and the corrected 3.17 */
static vec2 relative_velocity (const body *a, const body *b, const contact_point *p)
{
  vec2 vap = v2_add (a->v, v2_cross_sv (a->w, p->ra));
  vec2 vbp = v2_add (b->v, v2_cross_sv (b->w, p->rb));
  return v2_sub (vbp, vap);
}

static double effective_mass (const body *a, const body *b, vec2 ra, vec2 rb, vec2 dir)
{
  double rna = v2_cross (ra, dir), rnb = v2_cross (rb, dir);
  double k = a->inv_mass + b->inv_mass + a->inv_inertia * rna * rna + b->inv_inertia * rnb * rnb;
  return k > 0.0 ? 1.0 / k : 0.0;
}

static void prepare (carom_world *world, double h)
{
  contacts *c = &world->contacts;
  double g = v2_len (world->gravity);
  /* below this approach speed a contact does not bounce: the speed a body
   * resting under gravity gains in one sub-step, so resting stays resting;
   * with no gravity every approach bounces */
  double threshold = 2.0 * g * h;
  double beta = world->def.position_correction;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      body *a = &world->bodies[k->a], *b = &world->bodies[k->b];
      double vn[MANIFOLD_MAX_POINTS];
      int impact = 0;
      a->touching = b->touching = 1;
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          p->ra = v2_sub (p->point, a->p);
          p->rb = v2_sub (p->point, b->p);
          p->normal_mass = effective_mass (a, b, p->ra, p->rb, p->normal); /* eq. 3.23's denominator */
          p->tangent_mass = effective_mass (a, b, p->ra, p->rb, v2_perp (p->normal));
          vn[j] = v2_dot (relative_velocity (a, b, p), p->normal);
          /* an impact: a point approaching faster than the threshold that
           * reaches the other body within this sub-step */
          if (k->restitution > 0.0 && vn[j] < -threshold && vn[j] * h - p->depth < 0.0)
            impact = 1;
          p->bias = p->depth > k->slop ? beta * (p->depth - k->slop) / h : 0.0;
          p->pseudo_impulse = 0.0;
          if (k->friction == 0.0)
            p->tangent_impulse = 0.0;
        }
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          if (impact)
            /* eq. 3.18 at every point of the manifold: each may leave at e
             * times its own approach speed. Then the impulses change the
             * kinetic energy by sum_i j_i (v_i,before + v_i,after) / 2, which
             * is zero for e = 1 at the exact solution: elastic impacts
             * conserve energy even with several points at once. */
            p->target = -k->restitution * vn[j];
          else
            {
              /* a speculative point (apart by -depth) may close its gap but
               * not pass it; a touching one may not approach */
              p->target = p->depth < 0.0 ? p->depth / h : 0.0;
              /* a separating point that other impacts push back gets eq.
               * 3.18 too, so a chain of bodies hit at once stays elastic
               * (the same energy argument as above) */
              if (k->restitution > 0.0 && vn[j] > 0.0 && -k->restitution * vn[j] < p->target)
                p->target = -k->restitution * vn[j];
            }
        }
    }
  /* warm start with last step's impulses, only once every target above was
   * measured on the velocities before any impulse */
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      body *a = &world->bodies[k->a], *b = &world->bodies[k->b];
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          vec2 t = v2_perp (p->normal);
          apply_impulse (a, b, p, v2_add (v2_scale (p->normal, p->normal_impulse), v2_scale (t, p->tangent_impulse)));
        }
    }
}

/* Two points on one face (a box lying flat) solved together, exactly: the
 * 2x2 linear complementarity problem  w = K x + b, x >= 0, w >= 0, x.w = 0,
 * by trying each set of active points in turn. Sequential impulses would
 * only approach this answer as iterations go to infinity. Returns 0 when the
 * two points are (nearly) redundant and the caller should iterate instead. */
static int solve_pair_block (body *a, body *b, contact *k)
{
  contact_point *p1 = &k->points[0], *p2 = &k->points[1];
  vec2 n = p1->normal;
  double r1a = v2_cross (p1->ra, n), r1b = v2_cross (p1->rb, n);
  double r2a = v2_cross (p2->ra, n), r2b = v2_cross (p2->rb, n);
  double im = a->inv_mass + b->inv_mass;
  double k11 = im + a->inv_inertia * r1a * r1a + b->inv_inertia * r1b * r1b;
  double k22 = im + a->inv_inertia * r2a * r2a + b->inv_inertia * r2b * r2b;
  double k12 = im + a->inv_inertia * r1a * r2a + b->inv_inertia * r1b * r2b;
  double det = k11 * k22 - k12 * k12;
  double x1_old = p1->normal_impulse, x2_old = p2->normal_impulse, x1, x2, b1, b2;
  if (p2->normal.x != n.x || p2->normal.y != n.y || !(k11 * k11 < 1e4 * det))
    return 0;
  /* b: the velocity error with the current impulses taken back out */
  b1 = v2_dot (relative_velocity (a, b, p1), n) - p1->target - (k11 * x1_old + k12 * x2_old);
  b2 = v2_dot (relative_velocity (a, b, p2), n) - p2->target - (k12 * x1_old + k22 * x2_old);
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
  apply_impulse (a, b, p1, v2_scale (n, x1 - x1_old));
  apply_impulse (a, b, p2, v2_scale (n, x2 - x2_old));
  p1->normal_impulse = x1;
  p2->normal_impulse = x2;
  return 1;
}

static void solve_velocities (carom_world *world)
{
  contacts *c = &world->contacts;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      body *a = &world->bodies[k->a], *b = &world->bodies[k->b];
      if (k->friction > 0.0)
        for (j = 0; j < k->count; ++j)
          {
            /* Coulomb: the tangent impulse stays within mu times the normal
             * impulse */
            contact_point *p = &k->points[j];
            vec2 t = v2_perp (p->normal);
            double vt = v2_dot (relative_velocity (a, b, p), t);
            double limit = k->friction * p->normal_impulse;
            double acc = p->tangent_impulse - p->tangent_mass * vt;
            acc = acc > limit ? limit : (acc < -limit ? -limit : acc);
            apply_impulse (a, b, p, v2_scale (t, acc - p->tangent_impulse));
            p->tangent_impulse = acc;
          }
      if (k->count == 2 && solve_pair_block (a, b, k))
        continue;
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          double vn = v2_dot (relative_velocity (a, b, p), p->normal);
          double acc = p->normal_impulse - p->normal_mass * (vn - p->target);
          if (acc < 0.0)
            acc = 0.0;
          apply_impulse (a, b, p, v2_scale (p->normal, acc - p->normal_impulse));
          p->normal_impulse = acc;
        }
    }
}

static void apply_pseudo (body *a, body *b, const contact_point *p, vec2 impulse)
{
  a->pv = v2_mad (a->pv, -a->inv_mass, impulse);
  a->pw -= a->inv_inertia * v2_cross (p->ra, impulse);
  b->pv = v2_mad (b->pv, b->inv_mass, impulse);
  b->pw += b->inv_inertia * v2_cross (p->rb, impulse);
}

static void solve_positions (carom_world *world)
{
  contacts *c = &world->contacts;
  int32_t i, j;
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      body *a = &world->bodies[k->a], *b = &world->bodies[k->b];
      for (j = 0; j < k->count; ++j)
        {
          contact_point *p = &k->points[j];
          vec2 pa, pb;
          double vn, acc;
          if (p->bias == 0.0 && p->pseudo_impulse == 0.0)
            continue;
          pa = v2_add (a->pv, v2_cross_sv (a->pw, p->ra));
          pb = v2_add (b->pv, v2_cross_sv (b->pw, p->rb));
          vn = v2_dot (v2_sub (pb, pa), p->normal);
          acc = p->pseudo_impulse - p->normal_mass * (vn - p->bias);
          if (acc < 0.0)
            acc = 0.0;
          apply_pseudo (a, b, p, v2_scale (p->normal, acc - p->pseudo_impulse));
          p->pseudo_impulse = acc;
        }
    }
}

void solver_update (carom_world *world, double h)
{
  int32_t it;
  if (world->contacts.count == 0)
    return;
  prepare (world, h);
  for (it = 0; it < world->def.iterations; ++it)
    solve_velocities (world);
  for (it = 0; it < world->def.iterations; ++it)
    solve_positions (world);
}
