/* Box2D v3 on the benchmark scenes, for comparison with carom only.
 * Same scene data (scenes.c), same dt = 1/60 and step counts as
 * bench_carom.c; prints the same key=value line (engine=box2d3).
 *
 * Joints (the chains scene) are revolute joints at Box2D's defaults
 * (create_joints below).
 *
 * Settings: Box2D v3's defaults (b2DefaultWorldDef): 4 sub-steps per step
 * (its soft step solver; substeps=N overrides), contact hertz 30, damping
 * ratio 10, contact speed 3 m/s, continuous collision on. One worker and
 * no task callbacks, so it runs single threaded like every other engine
 * here. Sleeping is off unless sleep=1 (sleep=1 is Box2D's own default), as
 * in the Box2D 2.4 bench. iterations=N does not apply: v3 runs one
 * velocity pass and one relax pass per sub-step.
 * Box2D mixes friction as sqrt(mu_a mu_b) and restitution as the max, so
 * each shape gets the scene's mu and e. Its restitution threshold (1 m/s by
 * default) is set to 0 in the gas scene, where there is no gravity, which
 * is what carom does. Box2D computes in single precision (float).
 *
 * Built against a Box2D v3 source tree (BOX2D3_DIR, mk/bench.mk), whose
 * include/box2d/ must come before any installed Box2D 2.4 headers. */
#include <box2d/box2d.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenes.h"

static void add_shape (b2BodyId body, const bench_body *b, const bench_scene *s)
{
  b2ShapeDef sd = b2DefaultShapeDef ();
  sd.density = (float) s->density;
  sd.material.friction = (float) s->friction;
  sd.material.restitution = (float) s->restitution;
  if (b->shape == BENCH_CIRCLE)
    {
      b2Circle circle;
      circle.center = b2Vec2_zero;
      circle.radius = (float) b->radius;
      b2CreateCircleShape (body, &sd, &circle);
    }
  else
    {
      double xy[2 * B2_MAX_POLYGON_VERTICES];
      b2Vec2 v[B2_MAX_POLYGON_VERTICES];
      b2Hull hull;
      b2Polygon poly;
      int i, n = bench_body_vertices (b, xy, B2_MAX_POLYGON_VERTICES);
      for (i = 0; i < n; ++i)
        {
          v[i].x = (float) xy[2 * i];
          v[i].y = (float) xy[2 * i + 1];
        }
      hull = b2ComputeHull (v, n);
      poly = b2MakePolygon (&hull, 0.0f);
      b2CreatePolygonShape (body, &sd, &poly);
    }
}

/* A body of the scene as Box2D's: its type, pose and velocities (shapes
 * come from add_shape). */
static b2BodyId create_body (b2WorldId world, const bench_body *b)
{
  b2BodyDef bd = b2DefaultBodyDef ();
  bd.type = b->is_static ? b2_staticBody : b2_dynamicBody;
  bd.position.x = (float) b->x;
  bd.position.y = (float) b->y;
  bd.rotation = b2MakeRot ((float) b->angle);
  if (!b->is_static)
    {
      bd.linearVelocity.x = (float) b->vx;
      bd.linearVelocity.y = (float) b->vy;
      bd.angularVelocity = (float) b->spin;
    }
  return b2CreateBody (world, &bd);
}

/* The scene's joints as Box2D revolute joints at its defaults (constraint
 * hertz 60, damping ratio 2; joined bodies do not collide). A joint to the
 * world holds to one static body without shapes at the origin, made here
 * when a joint needs it. The joint angle (b's less a's) starts at 0, as in
 * the scene: frame A is a's at the anchor, frame B is turned to match it.
 * Their ids go to out[0 .. joint_count) (out may be NULL). */
static void create_joints (b2WorldId world, const b2BodyId *bodies, const bench_scene *s, b2JointId *out)
{
  b2BodyId ground = b2_nullBodyId;
  int i;
  for (i = 0; i < s->joint_count; ++i)
    {
      const bench_joint *j = &s->joints[i];
      b2RevoluteJointDef jd = b2DefaultRevoluteJointDef ();
      b2BodyId a, b = bodies[j->b];
      b2Pos p;
      b2JointId id;
      if (j->a < 0)
        {
          if (B2_IS_NULL (ground))
            {
              b2BodyDef bd = b2DefaultBodyDef ();
              ground = b2CreateBody (world, &bd);
            }
          a = ground;
        }
      else
        a = bodies[j->a];
      p.x = (float) j->x;
      p.y = (float) j->y;
      jd.base.bodyIdA = a;
      jd.base.bodyIdB = b;
      jd.base.localFrameA.p = b2Body_GetLocalPoint (a, p);
      jd.base.localFrameA.q = b2Rot_identity;
      jd.base.localFrameB.p = b2Body_GetLocalPoint (b, p);
      jd.base.localFrameB.q = b2InvMulRot (b2Body_GetRotation (b), b2Body_GetRotation (a));
      jd.enableLimit = j->enable_limit != 0;
      jd.lowerAngle = (float) j->lower;
      jd.upperAngle = (float) j->upper;
      id = b2CreateRevoluteJoint (world, &jd);
      if (out)
        out[i] = id;
    }
}

static double kinetic (const b2BodyId *bodies, const bench_scene *s)
{
  double e = 0.0;
  int i;
  for (i = 0; i < s->count; ++i)
    if (!s->bodies[i].is_static)
      {
        b2Vec2 v = b2Body_GetLinearVelocity (bodies[i]);
        e += bench_kinetic (b2Body_GetMass (bodies[i]), b2Body_GetRotationalInertia (bodies[i]), v.x, v.y,
                            b2Body_GetAngularVelocity (bodies[i]));
      }
  return e;
}

/* Touching contact points at the end. Every body's touching contacts are
 * listed; a contact is counted on the body of its shape A only, so once. */
static int contact_points (const b2BodyId *bodies, const bench_scene *s)
{
  b2ContactData *data = NULL;
  int cap = 0, points = 0, i, k;
  for (i = 0; i < s->count; ++i)
    {
      int want = b2Body_GetContactCapacity (bodies[i]), got;
      if (want > cap)
        {
          b2ContactData *grown = realloc (data, (size_t) want * sizeof *data);
          if (!grown)
            {
              free (data);
              return -1;
            }
          data = grown;
          cap = want;
        }
      got = want > 0 ? b2Body_GetContactData (bodies[i], data, want) : 0;
      for (k = 0; k < got; ++k)
        {
          b2BodyId a = b2Shape_GetBody (data[k].shapeIdA);
          if (B2_ID_EQUALS (a, bodies[i]))
            points += data[k].manifold.pointCount;
        }
    }
  free (data);
  return points;
}

int main (int argc, char **argv)
{
  bench_options o;
  bench_scene s;
  bench_result r;
  b2WorldDef wd;
  b2WorldId world;
  b2BodyId *bodies;
  b2Vec2 top0 = { 0.0f, 0.0f };
  b2Version ver = b2GetVersion ();
  char settings[128];
  double t0;
  int i, k, sub;
  const float dt = 1.0f / 60.0f;
  if (bench_begin (&o, &s, argc, argv, "bench_box2d3") < 0)
    return 2;
  bodies = calloc ((size_t) s.count, sizeof *bodies);
  if (!bodies)
    return 1;
  sub = o.substeps > 0 ? o.substeps : 4;
  wd = b2DefaultWorldDef ();
  wd.gravity.x = (float) s.gravity_x;
  wd.gravity.y = (float) s.gravity_y;
  if (s.gravity_x == 0.0 && s.gravity_y == 0.0)
    wd.restitutionThreshold = 0.0f;
  wd.enableSleep = o.sleep != 0;
  wd.workerCount = 1;
  world = b2CreateWorld (&wd);
  for (i = 0; i < s.count; ++i)
    {
      bodies[i] = create_body (world, &s.bodies[i]);
      add_shape (bodies[i], &s.bodies[i], &s);
    }
  create_joints (world, bodies, &s, NULL);

  memset (&r, 0, sizeof r);
  snprintf (settings, sizeof settings, "version=%d.%d.%d,substeps=%d,workers=1,continuous=on,sleep=%s", ver.major,
            ver.minor, ver.revision, sub, o.sleep ? "on" : "off");
  r.engine = "box2d3";
  r.settings = settings;
  r.energy_start = kinetic (bodies, &s);
  if (s.top >= 0)
    top0 = b2Body_GetPosition (bodies[s.top]);
  for (k = 0; k < o.warmup; ++k)
    b2World_Step (world, dt, sub);
  t0 = bench_now ();
  for (k = 0; k < o.steps; ++k)
    b2World_Step (world, dt, sub);
  r.seconds = bench_now () - t0;
  r.energy_end = kinetic (bodies, &s);
  for (i = 0; i < s.count; ++i)
    {
      b2Vec2 p;
      if (s.bodies[i].is_static)
        continue;
      p = b2Body_GetPosition (bodies[i]);
      r.escaped += bench_outside (&s, p.x, p.y) || !isfinite (p.x) || !isfinite (p.y);
      if (i == s.top)
        r.top_drift = hypot (p.x - top0.x, p.y - top0.y) / s.bodies[i].h;
    }
  r.contacts = contact_points (bodies, &s);
  if (s.joint_count > 0)
    {
      double *pose = malloc ((size_t) s.count * 3 * sizeof *pose);
      if (!pose)
        return 1;
      for (i = 0; i < s.count; ++i)
        {
          b2Vec2 p = b2Body_GetPosition (bodies[i]);
          pose[3 * i] = p.x, pose[3 * i + 1] = p.y;
          pose[3 * i + 2] = b2Rot_GetAngle (b2Body_GetRotation (bodies[i]));
        }
      r.joint_gap = bench_joint_gap (&s, pose);
      free (pose);
    }
  bench_report (&o, &s, &r);
  b2DestroyWorld (world);
  free (bodies);
  bench_scene_free (&s);
  return 0;
}
