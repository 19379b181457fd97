/* Box2D v3 through the accuracy measures (bench/accuracy.h), for comparison
 * with carom only. The scenes are built by the Box2D v3 bench's own code:
 * bench_box2d3.c is included here with its main renamed, so its add_shape
 * and create_body (shapes, friction, restitution) and create_joints
 * (revolute joints at Box2D's defaults) are the ones used. Its
 * settings: Box2D v3's defaults (4 sub-steps, contact hertz 30, continuous
 * collision on), one worker, sleeping off, dt 1/60; restitution threshold
 * 0 in scenes without gravity, its default 1 m/s otherwise (as
 * bench_box2d3.c). Box2D computes in float. */
#define main bench_box2d3_main
int bench_box2d3_main (int argc, char **argv);
#include "bench_box2d3.c"
#undef main

#include "accuracy.h"

typedef struct b3_handle {
  b2WorldId world;
  b2BodyId *bodies;
  b2JointId *joints;
  int count;
  float dt;
} b3_handle;

static void *b3_create (const bench_scene *s, const acc_settings *set)
{
  b3_handle *h = calloc (1, sizeof *h);
  b2WorldDef wd = b2DefaultWorldDef ();
  int i;
  if (!h)
    return NULL;
  h->bodies = calloc ((size_t) s->count + 1, sizeof *h->bodies);
  h->joints = calloc ((size_t) s->joint_count + 1, sizeof *h->joints);
  if (!h->bodies || !h->joints)
    {
      free (h->bodies);
      free (h->joints);
      free (h);
      return NULL;
    }
  h->count = s->count;
  h->dt = (float) set->dt;
  wd.gravity.x = (float) s->gravity_x;
  wd.gravity.y = (float) s->gravity_y;
  if (s->gravity_x == 0.0 && s->gravity_y == 0.0)
    wd.restitutionThreshold = 0.0f;
  wd.enableSleep = false;
  wd.workerCount = 1;
  h->world = b2CreateWorld (&wd);
  for (i = 0; i < s->count; ++i)
    {
      h->bodies[i] = create_body (h->world, &s->bodies[i]);
      b2Body_SetUserData (h->bodies[i], (void *) (intptr_t) i);
      add_shape (h->bodies[i], &s->bodies[i], s);
    }
  create_joints (h->world, h->bodies, s, h->joints);
  return h;
}

static int b3_step (void *p)
{
  b3_handle *h = p;
  b2World_Step (h->world, h->dt, 4);
  return 0;
}

static void b3_state (void *p, int i, acc_state *o)
{
  b3_handle *h = p;
  b2Vec2 x = b2Body_GetPosition (h->bodies[i]), v = b2Body_GetLinearVelocity (h->bodies[i]);
  o->x = x.x, o->y = x.y, o->vx = v.x, o->vy = v.y;
  o->angle = b2Rot_GetAngle (b2Body_GetRotation (h->bodies[i]));
  o->spin = b2Body_GetAngularVelocity (h->bodies[i]);
  o->mass = b2Body_GetMass (h->bodies[i]);
  o->inertia = b2Body_GetRotationalInertia (h->bodies[i]);
}

/* Every body's contacts, each counted on its shape A's body only. */
static void b3_contacts (void *p, acc_contact_fn fn, void *user)
{
  b3_handle *h = p;
  b2ContactData *data = NULL;
  int cap = 0, i, k, j;
  for (i = 0; i < h->count; ++i)
    {
      int want = b2Body_GetContactCapacity (h->bodies[i]), got;
      if (want > cap)
        {
          b2ContactData *grown = realloc (data, (size_t) want * sizeof *data);
          if (!grown)
            break;
          data = grown;
          cap = want;
        }
      got = want > 0 ? b2Body_GetContactData (h->bodies[i], data, want) : 0;
      for (k = 0; k < got; ++k)
        {
          b2BodyId a = b2Shape_GetBody (data[k].shapeIdA), b = b2Shape_GetBody (data[k].shapeIdB);
          if (!B2_ID_EQUALS (a, h->bodies[i]))
            continue;
          for (j = 0; j < data[k].manifold.pointCount; ++j)
            fn (user, (int) (intptr_t) b2Body_GetUserData (a), (int) (intptr_t) b2Body_GetUserData (b),
                -data[k].manifold.points[j].separation);
        }
    }
  free (data);
}

/* b2Joint_GetConstraintForce: the force on body B, in the world frame. */
static void b3_joint_force (void *p, int joint, double *fx, double *fy)
{
  b3_handle *h = p;
  b2Vec2 f = b2Joint_GetConstraintForce (h->joints[joint]);
  *fx = f.x, *fy = f.y;
}

static void b3_destroy (void *p)
{
  b3_handle *h = p;
  if (!h)
    return;
  b2DestroyWorld (h->world);
  free (h->bodies);
  free (h->joints);
  free (h);
}

int main (int argc, char **argv)
{
  static const acc_engine engine = {
    "box2d3", "version=3,substeps=4,workers=1,continuous=on,sleep=off,dt=1/60", b3_create, b3_step, b3_state,
    b3_contacts, b3_destroy, b3_joint_force,
  };
  acc_settings set;
  const char *only = NULL;
  if (argc > 2 || (argc == 2 && strncmp (argv[1], "measures=", 9) != 0))
    {
      fprintf (stderr, "usage: accuracy_box2d3 [measures=collision,projectile,...]\n");
      return 2;
    }
  if (argc == 2)
    only = argv[1] + 9;
  memset (&set, 0, sizeof set);
  strcpy (set.knob, "peer");
  strcpy (set.value, "usual");
  set.dt = 1.0 / 60.0;
  return acc_run_all (&engine, &set, only) < 0;
}
