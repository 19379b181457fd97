// Box2D 2.4 on the benchmark scenes, for comparison with carom only.
// Same scene data (scenes.c), same dt = 1/60 and step counts as
// bench_carom.c; prints the same key=value line. Joints (the chains scene)
// are revolute joints (create_joints below).
//
// Settings: velocityIterations 8, positionIterations 3 (Box2D's usual),
// continuous collision on (its default), sleeping off unless sleep=1
// (carom and Chipmunk do not sleep, so without it every engine steps every
// body every step; sleep=1 is Box2D's own default).
// Box2D mixes friction as sqrt(mu_a mu_b) and restitution as the max, so
// each fixture gets the scene's mu and e. Its restitution threshold (1 m/s
// by default) is set to 0 in the gas scene, where there is no gravity,
// which is what carom does (its threshold is 2 g h). Box2D computes in
// single precision (float); carom and Chipmunk in double.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "scenes.h"

static void add_fixture (b2Body *body, const bench_body *b, const bench_scene *s, float threshold)
{
  b2FixtureDef fd;
  b2PolygonShape poly;
  b2CircleShape circle;
  if (b->shape == BENCH_CIRCLE)
    {
      circle.m_radius = (float) b->radius;
      fd.shape = &circle;
    }
  else
    {
      double xy[2 * b2_maxPolygonVertices];
      b2Vec2 v[b2_maxPolygonVertices];
      int n = bench_body_vertices (b, xy, b2_maxPolygonVertices);
      for (int i = 0; i < n; ++i)
        v[i].Set ((float) xy[2 * i], (float) xy[2 * i + 1]);
      poly.Set (v, n);
      fd.shape = &poly;
    }
  fd.density = (float) s->density;
  fd.friction = (float) s->friction;
  fd.restitution = (float) s->restitution;
  fd.restitutionThreshold = threshold;
  body->CreateFixture (&fd);
}

// A body of the scene as Box2D's: its type, pose and velocities (shapes
// come from add_fixture).
static b2Body *create_body (b2World *world, const bench_body *b)
{
  b2BodyDef bd;
  bd.type = b->is_static ? b2_staticBody : b2_dynamicBody;
  bd.position.Set ((float) b->x, (float) b->y);
  bd.angle = (float) b->angle;
  if (!b->is_static)
    {
      bd.linearVelocity.Set ((float) b->vx, (float) b->vy);
      bd.angularVelocity = (float) b->spin;
    }
  return world->CreateBody (&bd);
}

// The scene's joints as Box2D revolute joints (Initialize sets the anchors
// and the reference angle; joined bodies do not collide). A joint to the
// world holds to one static body without fixtures, made here when needed.
static std::vector<b2RevoluteJoint *> create_joints (b2World *world, const std::vector<b2Body *> &bodies,
                                                     const bench_scene &s)
{
  std::vector<b2RevoluteJoint *> out;
  b2Body *ground = nullptr;
  for (int i = 0; i < s.joint_count; ++i)
    {
      const bench_joint *j = &s.joints[i];
      if (j->a < 0 && !ground)
        {
          b2BodyDef bd;
          ground = world->CreateBody (&bd);
        }
      b2RevoluteJointDef jd;
      jd.Initialize (j->a < 0 ? ground : bodies[(size_t) j->a], bodies[(size_t) j->b],
                     b2Vec2 ((float) j->x, (float) j->y));
      jd.enableLimit = j->enable_limit != 0;
      jd.lowerAngle = (float) j->lower;
      jd.upperAngle = (float) j->upper;
      out.push_back (static_cast<b2RevoluteJoint *> (world->CreateJoint (&jd)));
    }
  return out;
}

static double kinetic (const std::vector<b2Body *> &bodies, const bench_scene &s)
{
  double e = 0.0;
  for (int i = 0; i < s.count; ++i)
    if (!s.bodies[i].is_static)
      {
        b2Vec2 v = bodies[i]->GetLinearVelocity ();
        e += bench_kinetic (bodies[i]->GetMass (), bodies[i]->GetInertia (), v.x, v.y,
                            bodies[i]->GetAngularVelocity ());
      }
  return e;
}

int main (int argc, char **argv)
{
  bench_options o;
  bench_scene s;
  if (bench_begin (&o, &s, argc, argv, "bench_box2d") < 0)
    return 2;
  int velocity_iterations = o.iterations > 0 ? o.iterations : 8, position_iterations = 3;
  int sub = o.substeps > 0 ? o.substeps : 1;
  float threshold = (s.gravity_x == 0.0 && s.gravity_y == 0.0) ? 0.0f : 1.0f;
  b2World *world = new b2World (b2Vec2 ((float) s.gravity_x, (float) s.gravity_y));
  world->SetAllowSleeping (o.sleep != 0);
  std::vector<b2Body *> bodies ((size_t) s.count);
  for (int i = 0; i < s.count; ++i)
    {
      const bench_body *b = &s.bodies[i];
      bodies[i] = create_body (world, b);
      add_fixture (bodies[i], b, &s, threshold);
    }
  create_joints (world, bodies, s);

  bench_result r;
  std::memset (&r, 0, sizeof r);
  char settings[96];
  std::snprintf (settings, sizeof settings, "velocityIterations=%d,positionIterations=%d,substeps=%d,sleep=%s",
                 velocity_iterations, position_iterations, sub, o.sleep ? "on" : "off");
  r.engine = "box2d";
  r.settings = settings;
  r.energy_start = kinetic (bodies, s);
  b2Vec2 top0 (0.0f, 0.0f);
  if (s.top >= 0)
    top0 = bodies[s.top]->GetPosition ();
  float h = 1.0f / 60.0f / sub;
  for (int k = 0; k < o.warmup; ++k)
    for (int j = 0; j < sub; ++j)
      world->Step (h, velocity_iterations, position_iterations);
  double t0 = bench_now ();
  for (int k = 0; k < o.steps; ++k)
    for (int j = 0; j < sub; ++j)
      world->Step (h, velocity_iterations, position_iterations);
  r.seconds = bench_now () - t0;
  r.energy_end = kinetic (bodies, s);
  for (int i = 0; i < s.count; ++i)
    {
      if (s.bodies[i].is_static)
        continue;
      b2Vec2 p = bodies[i]->GetPosition ();
      r.escaped += bench_outside (&s, p.x, p.y) || !std::isfinite (p.x) || !std::isfinite (p.y);
      if (i == s.top)
        r.top_drift = std::hypot (p.x - top0.x, p.y - top0.y) / s.bodies[i].h;
    }
  r.contacts = 0;
  for (b2Contact *c = world->GetContactList (); c; c = c->GetNext ())
    if (c->IsTouching ())
      r.contacts += c->GetManifold ()->pointCount;
  if (s.joint_count > 0)
    {
      std::vector<double> pose ((size_t) s.count * 3);
      for (int i = 0; i < s.count; ++i)
        {
          b2Vec2 p = bodies[(size_t) i]->GetPosition ();
          pose[3 * (size_t) i] = p.x, pose[3 * (size_t) i + 1] = p.y;
          pose[3 * (size_t) i + 2] = bodies[(size_t) i]->GetAngle ();
        }
      r.joint_gap = bench_joint_gap (&s, pose.data ());
    }
  bench_report (&o, &s, &r);
  delete world;
  bench_scene_free (&s);
  return 0;
}
