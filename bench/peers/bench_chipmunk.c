/* Chipmunk2D 7 on the benchmark scenes, for comparison with carom only.
 * Same scene data (scenes.c), same dt = 1/60 and step counts as
 * bench_carom.c; prints the same key=value line.
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

int main (int argc, char **argv)
{
  bench_options o;
  bench_scene s;
  bench_result r;
  cpSpace *space;
  cpBody **bodies;
  cpShape **shapes;
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
  bench_report (&o, &s, &r);
  cpSpaceFree (space);
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
