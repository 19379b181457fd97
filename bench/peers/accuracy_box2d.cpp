// Box2D 2.4 through the accuracy measures (bench/accuracy.h), for comparison
// with carom only. The scenes are built by the Box2D bench's own code:
// bench_box2d.cpp is included here with its main renamed, so its add_fixture
// (shapes, friction, restitution and the restitution threshold) and
// create_joints (revolute joints) are the ones used. Its settings: velocity
// iterations 8, position iterations 3, continuous collision on, sleeping
// off, dt 1/60; restitution threshold 1 m/s, 0 in scenes without gravity
// (see bench_box2d.cpp). Box2D computes in float.
#define main bench_box2d_main
#include "bench_box2d.cpp"
#undef main

#include <cstdlib>
#include <cstring>

#include "accuracy.h"

namespace {

struct b2_handle {
  b2World *world;
  std::vector<b2Body *> bodies;
  std::vector<b2RevoluteJoint *> joints;
  float dt;
};

void *b2_create (const bench_scene *s, const acc_settings *set)
{
  b2_handle *h = new b2_handle;
  float threshold = (s->gravity_x == 0.0 && s->gravity_y == 0.0) ? 0.0f : 1.0f;
  h->dt = (float) set->dt;
  h->world = new b2World (b2Vec2 ((float) s->gravity_x, (float) s->gravity_y));
  h->world->SetAllowSleeping (false);
  h->bodies.resize ((size_t) s->count);
  for (int i = 0; i < s->count; ++i)
    {
      const bench_body *b = &s->bodies[i];
      h->bodies[(size_t) i] = create_body (h->world, b);
      h->bodies[(size_t) i]->GetUserData ().pointer = (uintptr_t) i;
      add_fixture (h->bodies[(size_t) i], b, s, threshold);
    }
  h->joints = create_joints (h->world, h->bodies, *s);
  return h;
}

int b2_step (void *p)
{
  b2_handle *h = static_cast<b2_handle *> (p);
  h->world->Step (h->dt, 8, 3);
  return 0;
}

void b2_state (void *p, int i, acc_state *o)
{
  b2_handle *h = static_cast<b2_handle *> (p);
  const b2Body *b = h->bodies[(size_t) i];
  b2Vec2 x = b->GetPosition (), v = b->GetLinearVelocity ();
  o->x = x.x, o->y = x.y, o->vx = v.x, o->vy = v.y;
  o->angle = b->GetAngle ();
  o->spin = b->GetAngularVelocity ();
  o->mass = b->GetMass ();
  o->inertia = b->GetInertia ();
}

void b2_contacts (void *p, acc_contact_fn fn, void *user)
{
  b2_handle *h = static_cast<b2_handle *> (p);
  for (b2Contact *c = h->world->GetContactList (); c; c = c->GetNext ())
    {
      if (!c->IsTouching ())
        continue;
      b2WorldManifold wm;
      c->GetWorldManifold (&wm);
      int a = (int) c->GetFixtureA ()->GetBody ()->GetUserData ().pointer;
      int b = (int) c->GetFixtureB ()->GetBody ()->GetUserData ().pointer;
      for (int k = 0; k < c->GetManifold ()->pointCount; ++k)
        fn (user, a, b, -wm.separations[k]);
    }
}

// GetReactionForce: the force on body B, in the world frame.
void b2_joint_force (void *p, int joint, double *fx, double *fy)
{
  b2_handle *h = static_cast<b2_handle *> (p);
  b2Vec2 f = h->joints[(size_t) joint]->GetReactionForce (1.0f / h->dt);
  *fx = f.x, *fy = f.y;
}

void b2_destroy (void *p)
{
  b2_handle *h = static_cast<b2_handle *> (p);
  if (!h)
    return;
  delete h->world;
  delete h;
}

} // namespace

int main (int argc, char **argv)
{
  const char *only = NULL;
  if (argc > 2 || (argc == 2 && std::strncmp (argv[1], "measures=", 9) != 0))
    {
      std::fprintf (stderr, "usage: accuracy_box2d [measures=collision,projectile,...]\n");
      return 2;
    }
  if (argc == 2)
    only = argv[1] + 9;
  static const acc_engine engine = {
    "box2d", "velocityIterations=8,positionIterations=3,sleep=off,dt=1/60", b2_create, b2_step, b2_state,
    b2_contacts, b2_destroy, b2_joint_force,
  };
  acc_settings set;
  std::memset (&set, 0, sizeof set);
  std::strcpy (set.knob, "peer");
  std::strcpy (set.value, "usual");
  set.dt = 1.0 / 60.0;
  return acc_run_all (&engine, &set, only) < 0;
}
