/* The joint constraints, solved in the same sub-steps as the contacts
 * (solver.c) in the form of Catto's "soft step": each sub-step warm starts
 * from the impulses so far, solves each constraint's velocity error plus a
 * soft share of its position error (use_bias), moves the bodies, and
 * relaxes: solves the velocity error alone, rigidly, so the soft correction
 * leaves no velocity behind. The position error is measured from the
 * bodies' motion since the update began (solver_body.dp, dq, da), as the
 * contacts measure theirs: no geometry is recomputed per pass.
 *
 * Every constraint here is C(x) = 0 or C >= 0 with a Jacobian J, and the
 * impulse of a pass is lambda = -m_eff (J v + bias) with
 * m_eff = 1 / (J M^-1 J^T); a point constraint couples x and y in a 2x2
 * block, as the contact's two points do (eq. 3.23 is the 1x1 case). */
#include "joint.h"

#include "solver.h"
#include "world.h"

/* The stiffness of the joints' own correction of their error: 60 Hz, or a
 * quarter of the sub-step rate when that is lower (a spring faster than
 * that is not resolved by the sub-step), and twice critically damped so it
 * never rings. Catto's soft step uses the same. */
#define JOINT_HERTZ 60.0
#define JOINT_DAMPING_RATIO 2.0

joint_soft joint_soft_make (double hertz, double zeta, double h)
{
  joint_soft s;
  double omega, a1, a2, a3;
  if (hertz == 0.0)
    {
      s.bias_rate = 0.0, s.mass_scale = 1.0, s.impulse_scale = 0.0;
      return s;
    }
  omega = 2.0 * CAROM_PI * hertz;
  a1 = 2.0 * zeta + h * omega;
  a2 = h * omega * a1;
  a3 = 1.0 / (1.0 + a2);
  s.bias_rate = omega / a1;
  s.mass_scale = a2 * a3;
  s.impulse_scale = a3;
  return s;
}

/* Whether the joint's spring exerts a force: on, and of a frequency. */
static int springy (const joint *j)
{
  return j->enable_spring && j->hertz > 0.0;
}

static const joint_soft rigid = {0.0, 1.0, 0.0};

/* x = K^-1 b for a symmetric 2x2 K (0 where K is singular), on K scaled
 * to its largest entry so that the determinant stays within the doubles
 * however long the lever arms */
static vec2 solve22 (double k11, double k12, double k22, vec2 b)
{
  double big = fabs (k11) > fabs (k22) ? fabs (k11) : fabs (k22), det;
  big = fabs (k12) > big ? fabs (k12) : big;
  if (!(big > 0.0) || !is_finite (big))
    return v2 (0.0, 0.0);
  k11 /= big, k12 /= big, k22 /= big;
  det = k11 * k22 - k12 * k12;
  if (det != 0.0)
    det = 1.0 / (det * big);
  return v2 (det * (k22 * b.x - k12 * b.y), det * (k11 * b.y - k12 * b.x));
}

static double clamp (double x, double lo, double hi)
{
  return x < lo ? lo : x > hi ? hi : x;
}

/* The two solver bodies of a joint; the world is the inert body past the
 * last slot (all zeros: it never moves). */
static solver_body *body_a (carom_world *world, const joint *j)
{
  return &world->solver_bodies[j->a < 0 ? world->slot_count : j->a];
}

static solver_body *body_b (carom_world *world, const joint *j)
{
  return &world->solver_bodies[j->b];
}

/* What every constraint of one joint reads in one pass: the anchors now,
 * rotated with the bodies since the update began, and the separation of
 * the anchors now (b's less a's). */
typedef struct frame {
  vec2 ra, rb, d;
  double angle; /* b's angle less a's, less the reference */
} frame;

static frame frame_now (const joint *j, const solver_body *A, const solver_body *B)
{
  frame f;
  f.ra = rot2_apply (A->dq, j->ra);
  f.rb = rot2_apply (B->dq, j->rb);
  f.d = v2_add (v2_add (v2_sub (B->dp, A->dp), j->delta_center), v2_sub (f.rb, f.ra));
  f.angle = j->delta_angle + B->da - A->da;
  return f;
}

joint_soft joint_hold_soft (double h)
{
  double hertz = h > 0.0 && 0.25 / h < JOINT_HERTZ ? 0.25 / h : JOINT_HERTZ;
  return joint_soft_make (hertz, JOINT_DAMPING_RATIO, h);
}

/* The softness a rigid constraint's pass uses: the joint's correction in
 * the solve, none in the relax pass. */
static joint_soft rigid_soft (const step_context *ctx, int use_bias)
{
  return use_bias ? ctx->joint_hold : rigid;
}

/* ---------------------------------------------------------- set-up */

void joint_prepare (carom_world *world, const step_context *ctx)
{
  joints *js = &world->joints;
  int32_t i;
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      const body *B;
      vec2 pa = v2 (0.0, 0.0);
      rot2 qa;
      double angle_a = 0.0;
      solver_body *sa, *sb;
      if (!j->alive)
        continue;
      B = &world->bodies[j->b];
      qa.c = 1.0, qa.s = 0.0;
      if (j->a >= 0)
        {
          const body *A = &world->bodies[j->a];
          pa = A->p, qa = A->q, angle_a = A->angle;
        }
      j->ra = rot2_apply (qa, j->local_a);
      j->rb = rot2_apply (B->q, j->local_b);
      j->delta_center = v2_sub (B->p, pa);
      j->delta_angle = B->angle - angle_a - j->reference_angle;
      j->axis = rot2_apply (qa, j->local_axis);
      if (j->type == CAROM_JOINT_MOUSE)
        {
          /* the target is fixed in the world: measured from the world's
           * origin, a = the world */
          j->ra = j->target;
          j->delta_center = B->p;
        }
      sa = body_a (world, j);
      sb = body_b (world, j);
      j->angular_mass = sa->ii + sb->ii > 0.0 ? 1.0 / (sa->ii + sb->ii) : 0.0;
      j->spring = joint_soft_make (j->enable_spring || j->type == CAROM_JOINT_MOUSE ? j->hertz : 0.0,
                                   j->damping_ratio, ctx->h);
      if (!j->enable_motor)
        j->motor_impulse = 0.0;
      if (!j->enable_limit)
        j->lower_impulse = j->upper_impulse = 0.0;
      if (j->type == CAROM_JOINT_DISTANCE ? j->enable_spring && j->hertz == 0.0 : !springy (j))
        j->axial_impulse = 0.0;
      j->reaction_sum = v2 (0.0, 0.0);
      j->reaction_torque_sum = 0.0;
    }
  joint_tree_build (world);
}

static int32_t find (int32_t *uf, int32_t i)
{
  while (uf[i] != i)
    {
      uf[i] = uf[uf[i]];
      i = uf[i];
    }
  return i;
}

void joint_mark_bodies (carom_world *world)
{
  joints *js = &world->joints;
  solver_body *sb = world->solver_bodies;
  int32_t *uf = world->joint_tree.scratch, *touched = uf + world->slot_count, i;
  for (i = 0; i < world->slot_count; ++i)
    uf[i] = i, touched[i] = 0;
  for (i = 0; i < js->count; ++i)
    {
      const joint *j = &js->list[i];
      if (j->alive && j->a >= 0 && sb[j->a].moves == MOVES_DYNAMIC && sb[j->b].moves == MOVES_DYNAMIC)
        uf[find (uf, j->a)] = find (uf, j->b);
    }
  /* the groups some contact acts on (the only bits set so far) */
  for (i = 0; i < world->slot_count; ++i)
    if (sb[i].moves == MOVES_DYNAMIC && sb[i].constrained)
      touched[find (uf, i)] = 1;
  for (i = 0; i < js->count; ++i)
    {
      const joint *j = &js->list[i];
      int32_t side;
      if (!j->alive)
        continue;
      for (side = 0; side < 2; ++side)
        {
          int32_t slot = side ? j->b : j->a;
          solver_body *b;
          if (slot < 0)
            continue;
          b = &sb[slot];
          if (b->moves == MOVES_DYNAMIC)
            b->constrained |= CONSTRAINED_ANY | (touched[find (uf, slot)] ? 0 : CONSTRAINED_JOINT);
          else if (b->moves)
            b->constrained |= CONSTRAINED_ANY;
        }
    }
}

/* ------------------------------------------------ applying an impulse */

/* A linear impulse p at the anchors plus an angular one l on b (and their
 * opposites on a). */
static void apply (solver_body *A, solver_body *B, vec2 ra, vec2 rb, vec2 p, double l)
{
  A->v = v2_mad (A->v, -A->im, p);
  A->w -= A->ii * (v2_cross (ra, p) + l);
  B->v = v2_mad (B->v, B->im, p);
  B->w += B->ii * (v2_cross (rb, p) + l);
}

/* An impulse lambda along the axis u of a sliding constraint whose moment
 * arms are a1 (on a, from a's centre to b's anchor) and a2 (on b). */
static void apply_axial (solver_body *A, solver_body *B, vec2 u, double a1, double a2, double lambda)
{
  A->v = v2_mad (A->v, -A->im * lambda, u);
  A->w -= A->ii * a1 * lambda;
  B->v = v2_mad (B->v, B->im * lambda, u);
  B->w += B->ii * a2 * lambda;
}

/* The relative velocity of the anchors, b's less a's. */
static vec2 anchor_velocity (const solver_body *A, const solver_body *B, const frame *f)
{
  return v2_sub (v2_add (B->v, v2_cross_sv (B->w, f->rb)), v2_add (A->v, v2_cross_sv (A->w, f->ra)));
}

/* Whether a body's velocities and motion are still numbers a joint may
 * act on: finite and within CAROM_MAX_MAGNITUDE. A pass that would leave
 * them otherwise (forces beyond any joint's hold, a joint stretched across
 * the doubles) is dropped for that joint: it holds what it can. */
int joint_sane (const solver_body *b)
{
  return joint_motion_sane (b->v, b->w, b->dp, b->da);
}

/* ------------------------------------------- constraints shared by types */

/* The two anchors coincide (revolute, weld): a 2x2 block. */
static void solve_point (joint *j, solver_body *A, solver_body *B, const frame *f, joint_soft s)
{
  vec2 cdot = anchor_velocity (A, B, f);
  vec2 bias = v2_scale (f->d, s.bias_rate);
  double k11 = A->im + B->im + f->ra.y * f->ra.y * A->ii + f->rb.y * f->rb.y * B->ii;
  double k12 = -f->ra.y * f->ra.x * A->ii - f->rb.y * f->rb.x * B->ii;
  double k22 = A->im + B->im + f->ra.x * f->ra.x * A->ii + f->rb.x * f->rb.x * B->ii;
  vec2 x = solve22 (k11, k12, k22, v2_add (cdot, bias));
  vec2 impulse = v2_sub (v2_scale (x, -s.mass_scale), v2_scale (j->linear_impulse, s.impulse_scale));
  j->linear_impulse = v2_add (j->linear_impulse, impulse);
  apply (A, B, f->ra, f->rb, impulse, 0.0);
}

/* A one-sided limit on a value with speed `cdot`: value - bound >= 0. Apart,
 * it lets the bodies close the gap within the sub-step and no more
 * (speculative); past it, the solve pushes back at the joints' rate of
 * correction. Returns the impulse. */
static double limit_impulse (double *accumulated, double c, double cdot, double mass, const step_context *ctx,
                             int use_bias)
{
  double bias = 0.0, impulse, old = *accumulated;
  if (c > 0.0)
    bias = c * ctx->inv_h;
  else if (use_bias)
    bias = ctx->joint_hold.bias_rate * c;
  /* rigid, with the joints' rate of correction but none of their softness:
   * a soft limit gives way under a steady load (a motor driving into it)
   * by as much as the load is large */
  impulse = -mass * (cdot + bias);
  *accumulated = old + impulse > 0.0 ? old + impulse : 0.0;
  return *accumulated - old;
}

/* A motor: drive `cdot` to zero with at most `max` impulse in the sub-step. */
static double motor_impulse (double *accumulated, double cdot, double mass, double max)
{
  double old = *accumulated;
  *accumulated = clamp (old - mass * cdot, -max, max);
  return *accumulated - old;
}

/* The relative angle (revolute, weld, motor): a spring, a motor, limits or
 * a rigid hold, all on w_b - w_a. */
static void solve_angular (joint *j, solver_body *A, solver_body *B, const frame *f, const step_context *ctx,
                           int use_bias)
{
  double lambda;
  if (j->angular_mass == 0.0)
    return;
  if (springy (j) && j->type == CAROM_JOINT_REVOLUTE)
    {
      joint_soft s = j->spring;
      double cdot = B->w - A->w;
      lambda = -s.mass_scale * j->angular_mass * (cdot + s.bias_rate * f->angle) - s.impulse_scale * j->axial_impulse;
      j->axial_impulse += lambda;
      A->w -= A->ii * lambda, B->w += B->ii * lambda;
    }
  if (j->enable_motor && j->type == CAROM_JOINT_REVOLUTE)
    {
      lambda = motor_impulse (&j->motor_impulse, B->w - A->w - j->motor_speed, j->angular_mass,
                              j->max_motor_force * ctx->h);
      A->w -= A->ii * lambda, B->w += B->ii * lambda;
    }
  if (j->enable_limit && j->type == CAROM_JOINT_REVOLUTE)
    {
      lambda = limit_impulse (&j->lower_impulse, f->angle - j->lower, B->w - A->w, j->angular_mass, ctx, use_bias);
      A->w -= A->ii * lambda, B->w += B->ii * lambda;
      lambda = limit_impulse (&j->upper_impulse, j->upper - f->angle, A->w - B->w, j->angular_mass, ctx, use_bias);
      A->w += A->ii * lambda, B->w -= B->ii * lambda;
    }
  if (j->type == CAROM_JOINT_WELD)
    {
      joint_soft s = springy (j) ? j->spring : rigid_soft (ctx, use_bias);
      double cdot = B->w - A->w;
      lambda = -s.mass_scale * j->angular_mass * (cdot + s.bias_rate * f->angle)
               - s.impulse_scale * j->angular_impulse;
      j->angular_impulse += lambda;
      A->w -= A->ii * lambda, B->w += B->ii * lambda;
    }
}

/* ------------------------------------------------------------ by type */

static void solve_revolute (joint *j, solver_body *A, solver_body *B, const step_context *ctx, int use_bias)
{
  frame f = frame_now (j, A, B);
  solve_angular (j, A, B, &f, ctx, use_bias);
  if (!j->tree)
    solve_point (j, A, B, &f, rigid_soft (ctx, use_bias));
}

static void solve_weld (joint *j, solver_body *A, solver_body *B, const step_context *ctx, int use_bias)
{
  frame f = frame_now (j, A, B);
  if (j->tree)
    return;
  solve_angular (j, A, B, &f, ctx, use_bias);
  solve_point (j, A, B, &f, springy (j) ? j->spring : rigid_soft (ctx, use_bias));
}

/* The axial part of a prismatic or wheel joint: its spring, motor (the
 * prismatic's) and limits on the translation along the axis. */
static void solve_axial (joint *j, solver_body *A, solver_body *B, const frame *f, vec2 axis,
                         const step_context *ctx, int use_bias)
{
  double a1 = v2_cross (v2_add (f->d, f->ra), axis), a2 = v2_cross (f->rb, axis);
  double k = A->im + B->im + A->ii * a1 * a1 + B->ii * a2 * a2;
  double mass = k > 0.0 ? 1.0 / k : 0.0;
  double translation = v2_dot (axis, f->d), lambda;
#define AXIAL_SPEED() (v2_dot (axis, v2_sub (B->v, A->v)) + a2 * B->w - a1 * A->w)
  if (springy (j))
    {
      joint_soft s = j->spring;
      lambda = -s.mass_scale * mass * (AXIAL_SPEED () + s.bias_rate * translation) - s.impulse_scale * j->axial_impulse;
      j->axial_impulse += lambda;
      apply_axial (A, B, axis, a1, a2, lambda);
    }
  if (j->enable_motor && j->type == CAROM_JOINT_PRISMATIC)
    {
      lambda = motor_impulse (&j->motor_impulse, AXIAL_SPEED () - j->motor_speed, mass, j->max_motor_force * ctx->h);
      apply_axial (A, B, axis, a1, a2, lambda);
    }
  if (j->enable_limit)
    {
      lambda = limit_impulse (&j->lower_impulse, translation - j->lower, AXIAL_SPEED (), mass, ctx, use_bias);
      apply_axial (A, B, axis, a1, a2, lambda);
      lambda = limit_impulse (&j->upper_impulse, j->upper - translation, -AXIAL_SPEED (), mass, ctx, use_bias);
      apply_axial (A, B, axis, a1, a2, -lambda);
    }
#undef AXIAL_SPEED
}

static void solve_prismatic (joint *j, solver_body *A, solver_body *B, const step_context *ctx, int use_bias)
{
  frame f = frame_now (j, A, B);
  vec2 axis = rot2_apply (A->dq, j->axis), perp = v2_perp (axis);
  double s1, s2, k11, k12, k22;
  vec2 cdot, bias, x, impulse;
  joint_soft s = rigid_soft (ctx, use_bias);
  solve_axial (j, A, B, &f, axis, ctx, use_bias);
  if (j->tree)
    return;
  /* across the axis and the angle, together */
  s1 = v2_cross (v2_add (f.d, f.ra), perp);
  s2 = v2_cross (f.rb, perp);
  cdot = v2 (v2_dot (perp, v2_sub (B->v, A->v)) + s2 * B->w - s1 * A->w, B->w - A->w);
  bias = v2 (s.bias_rate * v2_dot (perp, f.d), s.bias_rate * f.angle);
  k11 = A->im + B->im + A->ii * s1 * s1 + B->ii * s2 * s2;
  k12 = A->ii * s1 + B->ii * s2;
  k22 = A->ii + B->ii;
  if (k22 == 0.0)
    k22 = 1.0; /* neither turns: the angle holds by itself */
  x = solve22 (k11, k12, k22, v2_add (cdot, bias));
  impulse = v2_sub (v2_scale (x, -s.mass_scale), v2_scale (j->linear_impulse, s.impulse_scale));
  j->linear_impulse = v2_add (j->linear_impulse, impulse);
  A->v = v2_mad (A->v, -A->im * impulse.x, perp);
  A->w -= A->ii * (s1 * impulse.x + impulse.y);
  B->v = v2_mad (B->v, B->im * impulse.x, perp);
  B->w += B->ii * (s2 * impulse.x + impulse.y);
}

static void solve_wheel (joint *j, solver_body *A, solver_body *B, const step_context *ctx, int use_bias)
{
  frame f = frame_now (j, A, B);
  vec2 axis = rot2_apply (A->dq, j->axis), perp = v2_perp (axis);
  double s1, s2, k, lambda, cdot;
  joint_soft s = rigid_soft (ctx, use_bias);
  if (j->enable_motor && j->angular_mass > 0.0)
    {
      lambda = motor_impulse (&j->motor_impulse, B->w - A->w - j->motor_speed, j->angular_mass,
                              j->max_motor_force * ctx->h);
      A->w -= A->ii * lambda, B->w += B->ii * lambda;
    }
  solve_axial (j, A, B, &f, axis, ctx, use_bias);
  if (j->tree)
    return;
  /* b's anchor stays on the line */
  s1 = v2_cross (v2_add (f.d, f.ra), perp);
  s2 = v2_cross (f.rb, perp);
  k = A->im + B->im + A->ii * s1 * s1 + B->ii * s2 * s2;
  if (k == 0.0)
    return;
  cdot = v2_dot (perp, v2_sub (B->v, A->v)) + s2 * B->w - s1 * A->w;
  lambda = -s.mass_scale / k * (cdot + s.bias_rate * v2_dot (perp, f.d)) - s.impulse_scale * j->linear_impulse.x;
  j->linear_impulse.x += lambda;
  apply_axial (A, B, perp, s1, s2, lambda);
}

static void solve_distance (joint *j, solver_body *A, solver_body *B, const step_context *ctx, int use_bias)
{
  frame f = frame_now (j, A, B);
  double len = v2_len (f.d), cra, crb, k, mass, c, lambda;
  vec2 u = len > 0.0 ? v2_scale (f.d, 1.0 / len) : v2 (1.0, 0.0);
  cra = v2_cross (f.ra, u);
  crb = v2_cross (f.rb, u);
  k = A->im + B->im + A->ii * cra * cra + B->ii * crb * crb;
  if (k == 0.0)
    return;
  mass = 1.0 / k;
#define LENGTH_SPEED() v2_dot (u, anchor_velocity (A, B, &f))
  c = len - j->length;
  if (j->enable_spring)
    {
      if (j->hertz > 0.0)
        {
          joint_soft s = j->spring;
          lambda = -s.mass_scale * mass * (LENGTH_SPEED () + s.bias_rate * c) - s.impulse_scale * j->axial_impulse;
          j->axial_impulse += lambda;
          apply (A, B, f.ra, f.rb, v2_scale (u, lambda), 0.0);
        }
    }
  else if (!j->tree)
    {
      joint_soft s = rigid_soft (ctx, use_bias);
      lambda = -s.mass_scale * mass * (LENGTH_SPEED () + s.bias_rate * c) - s.impulse_scale * j->axial_impulse;
      j->axial_impulse += lambda;
      apply (A, B, f.ra, f.rb, v2_scale (u, lambda), 0.0);
    }
  if (j->enable_limit)
    {
      lambda = limit_impulse (&j->lower_impulse, len - j->lower, LENGTH_SPEED (), mass, ctx, use_bias);
      apply (A, B, f.ra, f.rb, v2_scale (u, lambda), 0.0);
      lambda = limit_impulse (&j->upper_impulse, j->upper - len, -LENGTH_SPEED (), mass, ctx, use_bias);
      apply (A, B, f.ra, f.rb, v2_scale (u, -lambda), 0.0);
    }
  if (j->enable_motor)
    {
      lambda = motor_impulse (&j->motor_impulse, LENGTH_SPEED () - j->motor_speed, mass, j->max_motor_force * ctx->h);
      apply (A, B, f.ra, f.rb, v2_scale (u, lambda), 0.0);
    }
#undef LENGTH_SPEED
}

/* The motor joint: a drive towards its target at the joints' rate of
 * correction, rigid (none of their softness, as a limit), so a steady load
 * (gravity) does not hold it off its target, and bounded by its force and
 * torque. It drives in the relax pass too: it is a drive, not a
 * constraint, and a body it pulls keeps the speed it was brought to. */
static void solve_motor (joint *j, solver_body *A, solver_body *B, const step_context *ctx)
{
  frame f;
  joint_soft s = ctx->joint_hold;
  double k11, k12, k22, max, len;
  vec2 cdot, x, old;
  /* b's centre is held at a's anchor (the target in a's frame) */
  f.ra = rot2_apply (A->dq, j->ra);
  f.rb = v2 (0.0, 0.0);
  f.d = v2_sub (v2_add (v2_sub (B->dp, A->dp), j->delta_center), f.ra);
  f.angle = j->delta_angle + B->da - A->da - j->target_angle;
  if (j->angular_mass > 0.0)
    {
      double cdot_w = B->w - A->w, lambda, o = j->angular_impulse;
      max = j->max_motor_torque * ctx->h;
      lambda = -j->angular_mass * (cdot_w + s.bias_rate * f.angle);
      j->angular_impulse = clamp (o + lambda, -max, max);
      lambda = j->angular_impulse - o;
      A->w -= A->ii * lambda, B->w += B->ii * lambda;
    }
  cdot = anchor_velocity (A, B, &f);
  k11 = A->im + B->im + f.ra.y * f.ra.y * A->ii;
  k12 = -f.ra.y * f.ra.x * A->ii;
  k22 = A->im + B->im + f.ra.x * f.ra.x * A->ii;
  x = solve22 (k11, k12, k22, v2_add (cdot, v2_scale (f.d, s.bias_rate)));
  old = j->linear_impulse;
  j->linear_impulse = v2_sub (old, x);
  max = j->max_motor_force * ctx->h;
  len = v2_len (j->linear_impulse);
  if (len > max)
    j->linear_impulse = v2_scale (j->linear_impulse, max / len);
  apply (A, B, f.ra, f.rb, v2_sub (j->linear_impulse, old), 0.0);
}

static void solve_mouse (joint *j, solver_body *B, const step_context *ctx)
{
  frame f;
  joint_soft s = j->spring;
  double k11, k12, k22, max, len;
  vec2 cdot, x, impulse, old;
  (void) ctx;
  f.rb = rot2_apply (B->dq, j->rb);
  f.d = v2_sub (v2_add (v2_add (B->dp, j->delta_center), f.rb), j->ra);
  cdot = v2_add (B->v, v2_cross_sv (B->w, f.rb));
  k11 = B->im + f.rb.y * f.rb.y * B->ii;
  k12 = -f.rb.y * f.rb.x * B->ii;
  k22 = B->im + f.rb.x * f.rb.x * B->ii;
  x = solve22 (k11, k12, k22, v2_add (cdot, v2_scale (f.d, s.bias_rate)));
  old = j->linear_impulse;
  impulse = v2_sub (v2_scale (x, -s.mass_scale), v2_scale (old, s.impulse_scale));
  j->linear_impulse = v2_add (old, impulse);
  if (j->max_motor_force > 0.0)
    {
      max = j->max_motor_force * ctx->h;
      len = v2_len (j->linear_impulse);
      if (len > max)
        j->linear_impulse = v2_scale (j->linear_impulse, max / len);
    }
  impulse = v2_sub (j->linear_impulse, old);
  B->v = v2_mad (B->v, B->im, impulse);
  B->w += B->ii * v2_cross (f.rb, impulse);
}


/* ------------------------------------------- rows for the direct solve */

int32_t joint_row_count (const joint *j)
{
  switch (j->type)
    {
    case CAROM_JOINT_REVOLUTE:
    case CAROM_JOINT_PRISMATIC:
      return 2;
    case CAROM_JOINT_WELD:
      return springy (j) ? 0 : 3;
    case CAROM_JOINT_WHEEL:
      return 1;
    case CAROM_JOINT_DISTANCE:
      return j->enable_spring ? 0 : 1;
    default:
      return 0;
    }
}

/* One row of a Jacobian: (vx, vy, w) of a body. */
static void row (double *r, double x, double y, double w)
{
  r[0] = x, r[1] = y, r[2] = w;
}

void joint_rows (const joint *j, const solver_body *A, const solver_body *B, double *ja, double *jb, double *c)
{
  frame f = frame_now (j, A, B);
  switch (j->type)
    {
    case CAROM_JOINT_REVOLUTE:
    case CAROM_JOINT_WELD:
      /* the anchors' relative velocity v_b + w_b x r_b - v_a - w_a x r_a */
      row (ja, -1.0, 0.0, f.ra.y), row (jb, 1.0, 0.0, -f.rb.y);
      row (ja + 3, 0.0, -1.0, -f.ra.x), row (jb + 3, 0.0, 1.0, f.rb.x);
      c[0] = f.d.x, c[1] = f.d.y;
      if (j->type == CAROM_JOINT_WELD)
        {
          row (ja + 6, 0.0, 0.0, -1.0), row (jb + 6, 0.0, 0.0, 1.0);
          c[2] = f.angle;
        }
      break;
    case CAROM_JOINT_PRISMATIC:
    case CAROM_JOINT_WHEEL:
      {
        vec2 perp = v2_perp (rot2_apply (A->dq, j->axis));
        double s1 = v2_cross (v2_add (f.d, f.ra), perp), s2 = v2_cross (f.rb, perp);
        row (ja, -perp.x, -perp.y, -s1), row (jb, perp.x, perp.y, s2);
        c[0] = v2_dot (perp, f.d);
        if (j->type == CAROM_JOINT_PRISMATIC)
          {
            row (ja + 3, 0.0, 0.0, -1.0), row (jb + 3, 0.0, 0.0, 1.0);
            c[1] = f.angle;
          }
        break;
      }
    case CAROM_JOINT_DISTANCE:
      {
        double len = v2_len (f.d);
        vec2 u = len > 0.0 ? v2_scale (f.d, 1.0 / len) : v2 (1.0, 0.0);
        row (ja, -u.x, -u.y, -v2_cross (f.ra, u)), row (jb, u.x, u.y, v2_cross (f.rb, u));
        c[0] = len - j->length;
        break;
      }
    default:
      break;
    }
}

/* Where the rows' impulses accumulate (the same fields the passes above
 * use, so warm starting and the reaction read them alike). */
static double *row_impulse (joint *j, int32_t k)
{
  switch (j->type)
    {
    case CAROM_JOINT_REVOLUTE:
    case CAROM_JOINT_WELD:
      return k == 0 ? &j->linear_impulse.x : k == 1 ? &j->linear_impulse.y : &j->angular_impulse;
    case CAROM_JOINT_PRISMATIC:
    case CAROM_JOINT_WHEEL:
      return k == 0 ? &j->linear_impulse.x : &j->linear_impulse.y;
    default:
      return &j->axial_impulse;
    }
}

void joint_rows_get (joint *j, double *impulse)
{
  int32_t k, n = joint_row_count (j);
  for (k = 0; k < n; ++k)
    impulse[k] = *row_impulse (j, k);
}

void joint_rows_add (joint *j, const double *impulse)
{
  int32_t k, n = joint_row_count (j);
  for (k = 0; k < n; ++k)
    *row_impulse (j, k) += impulse[k];
}

/* ---------------------------------------------------------- the passes */

/* What the joint's accumulated impulses give b now: the force at its
 * anchor and the torque beside it. */
static void impulse_on_b (const joint *j, const solver_body *A, const solver_body *B, vec2 *p, double *l)
{
  double axial = j->axial_impulse + j->motor_impulse + j->lower_impulse - j->upper_impulse;
  switch (j->type)
    {
    case CAROM_JOINT_REVOLUTE:
      *p = j->linear_impulse, *l = axial;
      break;
    case CAROM_JOINT_WELD:
    case CAROM_JOINT_MOTOR:
      *p = j->linear_impulse, *l = j->angular_impulse;
      break;
    case CAROM_JOINT_PRISMATIC:
    case CAROM_JOINT_WHEEL:
      {
        vec2 axis = rot2_apply (A->dq, j->axis);
        double lin = j->type == CAROM_JOINT_WHEEL ? j->axial_impulse + j->lower_impulse - j->upper_impulse : axial;
        *p = v2_add (v2_scale (axis, lin), v2_scale (v2_perp (axis), j->linear_impulse.x));
        *l = j->type == CAROM_JOINT_WHEEL ? j->motor_impulse : j->linear_impulse.y;
        break;
      }
    case CAROM_JOINT_DISTANCE:
      {
        frame f = frame_now (j, A, B);
        double len = v2_len (f.d);
        vec2 u = len > 0.0 ? v2_scale (f.d, 1.0 / len) : v2 (1.0, 0.0);
        *p = v2_scale (u, axial), *l = 0.0;
        break;
      }
    default: /* mouse */
      *p = j->linear_impulse, *l = 0.0;
      break;
    }
}

/* Drop what a joint has accumulated: its warm start would leave a body
 * beyond what a joint may act on (joint_sane), so it starts from none. */
static void joint_forget_impulses (joint *j)
{
  j->linear_impulse = v2 (0.0, 0.0);
  j->angular_impulse = j->axial_impulse = 0.0;
  j->motor_impulse = j->lower_impulse = j->upper_impulse = 0.0;
}

void joint_warm_start (carom_world *world)
{
  joints *js = &world->joints;
  int32_t i;
  joint_tree_next_substep (world); /* the sub-step starts where the last one moved the bodies */
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      solver_body *SA, *SB, a, b, *A = &a, *B = &b;
      vec2 p, ra, rb;
      double l;
      if (!j->alive)
        continue;
      SA = body_a (world, j);
      SB = body_b (world, j);
      /* on copies, kept only if the bodies stay sane, as in each pass (a
       * prismatic axis's arm reaches b's anchor, which a fall under
       * gravity of CAROM_MAX_MAGNITUDE carries across the doubles) */
      a = *SA, b = *SB;
      impulse_on_b (j, A, B, &p, &l);
      rb = rot2_apply (B->dq, j->rb);
      if (j->type == CAROM_JOINT_MOUSE)
        {
          B->v = v2_mad (B->v, B->im, p);
          B->w += B->ii * v2_cross (rb, p);
        }
      else
        {
          ra = rot2_apply (A->dq, j->ra);
          if (j->type == CAROM_JOINT_MOTOR)
            rb = v2 (0.0, 0.0);
          else if (j->type == CAROM_JOINT_PRISMATIC || j->type == CAROM_JOINT_WHEEL)
            {
              /* a's moment arm reaches b's anchor: ra + d */
              frame f = frame_now (j, A, B);
              ra = v2_add (f.d, f.ra);
            }
          apply (A, B, ra, rb, p, l);
        }
      if (joint_sane (A) && joint_sane (B))
        *SA = a, *SB = b;
      else
        joint_forget_impulses (j);
    }
}

/* Whether a joint's own pass does nothing: a revolute joint of the tree
 * (its point rows are the tree's) with no spring, motor or limit, as every
 * link of a chain is. */
static int nothing_of_its_own (const joint *j)
{
  return j->type == CAROM_JOINT_REVOLUTE && j->tree && !springy (j) && !j->enable_motor && !j->enable_limit;
}

/* Each joint's own pass: what the tree does not solve. */
static void solve_each (carom_world *world, const step_context *ctx, int use_bias)
{
  joints *js = &world->joints;
  int32_t i;
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      solver_body *SA, *SB, a, b, *A = &a, *B = &b;
      vec2 linear;
      double angular, axial, motor, lower, upper;
      if (!j->alive || nothing_of_its_own (j))
        continue;
      SA = body_a (world, j);
      SB = body_b (world, j);
      /* on copies, kept only if the bodies stay sane (joint_sane) */
      a = *SA, b = *SB;
      linear = j->linear_impulse, angular = j->angular_impulse, axial = j->axial_impulse;
      motor = j->motor_impulse, lower = j->lower_impulse, upper = j->upper_impulse;
      switch (j->type)
        {
        case CAROM_JOINT_REVOLUTE:
          solve_revolute (j, A, B, ctx, use_bias);
          break;
        case CAROM_JOINT_PRISMATIC:
          solve_prismatic (j, A, B, ctx, use_bias);
          break;
        case CAROM_JOINT_DISTANCE:
          solve_distance (j, A, B, ctx, use_bias);
          break;
        case CAROM_JOINT_WELD:
          solve_weld (j, A, B, ctx, use_bias);
          break;
        case CAROM_JOINT_WHEEL:
          solve_wheel (j, A, B, ctx, use_bias);
          break;
        case CAROM_JOINT_MOTOR:
          solve_motor (j, A, B, ctx);
          break;
        default:
          solve_mouse (j, B, ctx);
          break;
        }
      if (joint_sane (A) && joint_sane (B))
        *SA = a, *SB = b;
      else
        {
          j->linear_impulse = linear, j->angular_impulse = angular, j->axial_impulse = axial;
          j->motor_impulse = motor, j->lower_impulse = lower, j->upper_impulse = upper;
        }
    }
}

void joint_solve (carom_world *world, const step_context *ctx, int use_bias)
{
  /* the rigid rows of the tree first, then each joint's own passes, so a
   * limit and a motor have the last word on the speeds they hold. Where a
   * tree joint has a limit, motor or spring of its own, the two disturb
   * each other (a limit that stops a pendulum's turn leaves its pivot
   * moving): both again, which halves what a limit is overshot by. */
  joint_tree_solve (world);
  solve_each (world, ctx, use_bias);
  if (world->joint_tree.mixed)
    {
      joint_tree_solve (world);
      solve_each (world, ctx, use_bias);
    }
}

void joint_project (carom_world *world, const step_context *ctx)
{
  joint_tree_project (world, ctx);
}

void joint_sum_reaction (carom_world *world)
{
  joints *js = &world->joints;
  int32_t i;
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      vec2 p;
      double l;
      if (!j->alive)
        continue;
      impulse_on_b (j, body_a (world, j), body_b (world, j), &p, &l);
      j->reaction_sum = v2_add (j->reaction_sum, p);
      j->reaction_torque_sum += l;
    }
}

void joint_finish (carom_world *world, const step_context *ctx)
{
  joints *js = &world->joints;
  int32_t i;
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      if (!j->alive)
        continue;
      j->reaction_force = v2_scale (j->reaction_sum, ctx->inv_dt);
      j->reaction_torque = j->reaction_torque_sum * ctx->inv_dt;
    }
}
