/* Chipmunk2D 7 on the benchmark scenes, for comparison with carom only.
 * Same scene data (scenes.c), same dt = 1/60 and step counts as
 * bench_carom.c; prints the same key=value line. Joints (the chains scene)
 * are pivot joints (add_joints below), at Chipmunk's default error bias.
 *
 * Settings: iterations 10 (Chipmunk's usual), no sleeping (its default),
 * default bounding-box-tree spatial index. collisionSlop is set to 0.01
 * (Chipmunk's default 0.1 is tuned for pixel-sized bodies; the bodies here
 * are 0.5 to 1 units). Chipmunk multiplies the two shapes' friction and
 * elasticity, so each shape gets sqrt(mu) and e: the pair sees mu and e,
 * as in carom and Box2D. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <chipmunk/chipmunk.h>

#include "scenes.h"

typedef struct count_state {
  int points;
} count_state;

static void count_arbiter (cpBody *body, cpArbiter *arb, void *data)
{
  count_state *c = data;
  cpBody *a, *b;
  cpArbiterGetBodies (arb, &a, &b);
  (void) body;
  /* each arbiter is seen from both of its dynamic bodies: count it once */
  if (cpBodyGetType (b) == CP_BODY_TYPE_STATIC || a < b)
    c->points += cpArbiterGetCount (arb);
}

static void count_body (cpBody *body, void *data)
{
  cpBodyEachArbiter (body, count_arbiter, data);
}

static cpShape *add_shape (cpSpace *space, cpBody *body, const bench_body *b, double mu, double e)
{
  cpShape *shape;
  if (b->shape == BENCH_CIRCLE)
    shape = cpCircleShapeNew (body, b->radius, cpvzero);
  else
    {
      double xy[2 * 16];
      cpVect v[16];
      int i, n = bench_body_vertices (b, xy, 16);
      for (i = 0; i < n; ++i)
        v[i] = cpv (xy[2 * i], xy[2 * i + 1]);
      shape = cpPolyShapeNew (body, n, v, cpTransformIdentity, 0.0);
    }
  cpShapeSetFriction (shape, sqrt (mu));
  cpShapeSetElasticity (shape, e);
  return cpSpaceAddShape (space, shape);
}

/* The scene's joints as Chipmunk pivot joints (and a rotary limit joint
 * where the scene has a limit, its range moved by b's angle less a's at the
 * start), on the space's static body for a joint to the world; joined
 * bodies do not collide. Each joint's constraints go to out[2 i] (the
 * pivot) and out[2 i + 1] (the limit, or NULL); free them with
 * free_joints after the space. */
static cpConstraint **add_joints (cpSpace *space, cpBody *const *bodies, const bench_scene *s)
{
  cpConstraint **out = calloc ((size_t) (2 * s->joint_count + 1), sizeof *out);
  int i;
  if (!out)
    return NULL;
  for (i = 0; i < s->joint_count; ++i)
    {
      const bench_joint *j = &s->joints[i];
      cpBody *a = j->a < 0 ? cpSpaceGetStaticBody (space) : bodies[j->a], *b = bodies[j->b];
      out[2 * i] = cpSpaceAddConstraint (space, cpPivotJointNew (a, b, cpv (j->x, j->y)));
      cpConstraintSetCollideBodies (out[2 * i], cpFalse);
      if (j->enable_limit)
        {
          double ref = cpBodyGetAngle (b) - cpBodyGetAngle (a);
          out[2 * i + 1] = cpSpaceAddConstraint (space, cpRotaryLimitJointNew (a, b, j->lower + ref, j->upper + ref));
          cpConstraintSetCollideBodies (out[2 * i + 1], cpFalse);
        }
    }
  return out;
}

static void free_joints (cpConstraint **joints, int joint_count)
{
  int i;
  if (!joints)
    return;
  for (i = 0; i < 2 * joint_count; ++i)
    if (joints[i])
      cpConstraintFree (joints[i]);
  free (joints);
}

int main (int argc, char **argv)
{
  bench_options o;
  bench_scene s;
  bench_result r;
  cpSpace *space;
  cpBody **bodies;
  cpShape **shapes;
  cpConstraint **joints;
  count_state cs = { 0 };
  char settings[64];
  double t0, x0 = 0.0, y0 = 0.0;
  int i, iterations;
  if (bench_begin (&o, &s, argc, argv, "bench_chipmunk") < 0)
    return 2;
  bodies = calloc ((size_t) s.count, sizeof *bodies);
  shapes = calloc ((size_t) s.count, sizeof *shapes);
  if (!bodies || !shapes)
    return 1;
  iterations = o.iterations > 0 ? o.iterations : 10;
  space = cpSpaceNew ();
  cpSpaceSetIterations (space, iterations);
  cpSpaceSetGravity (space, cpv (s.gravity_x, s.gravity_y));
  cpSpaceSetCollisionSlop (space, 0.01);
  for (i = 0; i < s.count; ++i)
    {
      const bench_body *b = &s.bodies[i];
      cpBody *body;
      if (b->is_static)
        body = cpBodyNewStatic ();
      else
        {
          double m = s.density * bench_body_area (b), inertia = s.density * bench_body_inertia (b);
          body = cpBodyNew (m, inertia);
        }
      cpBodySetPosition (body, cpv (b->x, b->y));
      cpBodySetAngle (body, b->angle);
      cpSpaceAddBody (space, body);
      if (!b->is_static)
        {
          cpBodySetVelocity (body, cpv (b->vx, b->vy));
          cpBodySetAngularVelocity (body, b->spin);
        }
      shapes[i] = add_shape (space, body, b, s.friction, s.restitution);
      bodies[i] = body;
    }
  joints = add_joints (space, bodies, &s);
  if (!joints)
    return 1;
  memset (&r, 0, sizeof r);
  snprintf (settings, sizeof settings, "iterations=%d,substeps=%d,slop=0.01", iterations,
            o.substeps > 0 ? o.substeps : 1);
  r.engine = "chipmunk";
  r.settings = settings;
  for (i = 0; i < s.count; ++i)
    if (!s.bodies[i].is_static)
      {
        cpVect v = cpBodyGetVelocity (bodies[i]);
        r.energy_start += bench_kinetic (cpBodyGetMass (bodies[i]), cpBodyGetMoment (bodies[i]), v.x, v.y,
                                         cpBodyGetAngularVelocity (bodies[i]));
      }
  if (s.top >= 0)
    {
      cpVect p = cpBodyGetPosition (bodies[s.top]);
      x0 = p.x, y0 = p.y;
    }
  {
    int sub = o.substeps > 0 ? o.substeps : 1, k, j;
    double h = 1.0 / 60.0 / sub;
    for (k = 0; k < o.warmup; ++k)
      for (j = 0; j < sub; ++j)
        cpSpaceStep (space, h);
    t0 = bench_now ();
    for (k = 0; k < o.steps; ++k)
      for (j = 0; j < sub; ++j)
        cpSpaceStep (space, h);
    r.seconds = bench_now () - t0;
  }
  for (i = 0; i < s.count; ++i)
    {
      cpVect p;
      if (s.bodies[i].is_static)
        continue;
      {
        cpVect v = cpBodyGetVelocity (bodies[i]);
        r.energy_end += bench_kinetic (cpBodyGetMass (bodies[i]), cpBodyGetMoment (bodies[i]), v.x, v.y,
                                       cpBodyGetAngularVelocity (bodies[i]));
      }
      p = cpBodyGetPosition (bodies[i]);
      r.escaped += bench_outside (&s, p.x, p.y) || !isfinite (p.x) || !isfinite (p.y);
      if (i == s.top)
        r.top_drift = sqrt ((p.x - x0) * (p.x - x0) + (p.y - y0) * (p.y - y0)) / s.bodies[i].h;
    }
  cpSpaceEachBody (space, count_body, &cs);
  r.contacts = cs.points;
  if (s.joint_count > 0)
    {
      double *pose = malloc ((size_t) s.count * 3 * sizeof *pose);
      if (!pose)
        return 1;
      for (i = 0; i < s.count; ++i)
        {
          cpVect p = cpBodyGetPosition (bodies[i]);
          pose[3 * i] = p.x, pose[3 * i + 1] = p.y;
          pose[3 * i + 2] = cpBodyGetAngle (bodies[i]);
        }
      r.joint_gap = bench_joint_gap (&s, pose);
      free (pose);
    }
  bench_report (&o, &s, &r);
  cpSpaceFree (space);
  free_joints (joints, s.joint_count);
  for (i = 0; i < s.count; ++i)
    {
      cpShapeFree (shapes[i]);
      cpBodyFree (bodies[i]);
    }
  free (shapes);
  free (bodies);
  bench_scene_free (&s);
  return 0;
}
