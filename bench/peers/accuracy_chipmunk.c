/* Chipmunk 7 through the accuracy measures (bench/accuracy.h), for
 * comparison with carom only. The scenes are built by the Chipmunk bench's
 * own code: bench_chipmunk.c is included here with its main renamed, so its
 * add_shape (shapes, friction and elasticity mixing) and add_joints (pivot
 * joints, rotary limit joints) are the ones used. Its settings: iterations
 * 10, collision slop 0.01, no sleeping, dt 1/60 (see bench_chipmunk.c).
 * Chipmunk multiplies the two shapes' elasticity, so each shape gets
 * sqrt(e) (the bench passes e, which is the same for its only elastic
 * scene, e = 1). */
#include <stdint.h>

#define main bench_chipmunk_main
int main (int argc, char **argv);
#include "bench_chipmunk.c"
#undef main

#include "accuracy.h"

typedef struct cp_handle {
  cpSpace *space;
  cpBody **bodies;
  cpShape **shapes;
  cpConstraint **joints; /* add_joints: pivot, limit (or NULL) per joint */
  int joint_count;
  int count;
  double dt;
} cp_handle;

static void cp_destroy (void *p)
{
  cp_handle *h = p;
  int i;
  if (!h)
    return;
  if (h->space)
    cpSpaceFree (h->space);
  free_joints (h->joints, h->joint_count);
  for (i = 0; i < h->count; ++i)
    {
      if (h->shapes && h->shapes[i])
        cpShapeFree (h->shapes[i]);
      if (h->bodies && h->bodies[i])
        cpBodyFree (h->bodies[i]);
    }
  free (h->shapes);
  free (h->bodies);
  free (h);
}

static void *cp_create (const bench_scene *s, const acc_settings *set)
{
  cp_handle *h = calloc (1, sizeof *h);
  int i;
  if (!h)
    return NULL;
  h->bodies = calloc ((size_t) s->count + 1, sizeof *h->bodies);
  h->shapes = calloc ((size_t) s->count + 1, sizeof *h->shapes);
  if (!h->bodies || !h->shapes)
    {
      cp_destroy (h);
      return NULL;
    }
  h->dt = set->dt;
  h->space = cpSpaceNew ();
  cpSpaceSetIterations (h->space, 10);
  cpSpaceSetGravity (h->space, cpv (s->gravity_x, s->gravity_y));
  cpSpaceSetCollisionSlop (h->space, 0.01);
  for (i = 0; i < s->count; ++i)
    {
      const bench_body *b = &s->bodies[i];
      cpBody *body;
      if (b->is_static)
        body = cpBodyNewStatic ();
      else
        body = cpBodyNew (s->density * bench_body_area (b), s->density * bench_body_inertia (b));
      cpBodySetPosition (body, cpv (b->x, b->y));
      cpBodySetAngle (body, b->angle);
      cpBodySetUserData (body, (cpDataPointer) (intptr_t) i);
      cpSpaceAddBody (h->space, body);
      if (!b->is_static)
        {
          cpBodySetVelocity (body, cpv (b->vx, b->vy));
          cpBodySetAngularVelocity (body, b->spin);
        }
      h->bodies[i] = body;
      h->count = i + 1;
      h->shapes[i] = add_shape (h->space, body, b, s->friction, sqrt (s->restitution));
    }
  h->joints = add_joints (h->space, h->bodies, s);
  h->joint_count = s->joint_count;
  if (!h->joints)
    {
      cp_destroy (h);
      return NULL;
    }
  return h;
}

static int cp_step (void *p)
{
  cp_handle *h = p;
  cpSpaceStep (h->space, h->dt);
  return 0;
}

static void cp_state (void *p, int i, acc_state *o)
{
  cp_handle *h = p;
  cpBody *b = h->bodies[i];
  cpVect x = cpBodyGetPosition (b), v = cpBodyGetVelocity (b);
  o->x = x.x, o->y = x.y, o->vx = v.x, o->vy = v.y;
  o->angle = cpBodyGetAngle (b);
  o->spin = cpBodyGetAngularVelocity (b);
  o->mass = cpBodyGetMass (b);
  o->inertia = cpBodyGetMoment (b);
}

typedef struct cp_visit {
  acc_contact_fn fn;
  void *user;
} cp_visit;

static void cp_arbiter (cpBody *body, cpArbiter *arb, void *data)
{
  cp_visit *v = data;
  cpBody *a, *b;
  int i, n;
  cpArbiterGetBodies (arb, &a, &b);
  (void) body;
  /* a is the body being visited; see each arbiter once */
  if (cpBodyGetType (a) != CP_BODY_TYPE_DYNAMIC)
    return;
  if (cpBodyGetType (b) == CP_BODY_TYPE_DYNAMIC && !(a < b))
    return;
  n = cpArbiterGetCount (arb);
  for (i = 0; i < n; ++i)
    v->fn (v->user, (int) (intptr_t) cpBodyGetUserData (a), (int) (intptr_t) cpBodyGetUserData (b),
           -cpArbiterGetDepth (arb, i));
}

static void cp_body (cpBody *body, void *data)
{
  cpBodyEachArbiter (body, cp_arbiter, data);
}

static void cp_contacts (void *p, acc_contact_fn fn, void *user)
{
  cp_handle *h = p;
  cp_visit v;
  v.fn = fn, v.user = user;
  cpSpaceEachBody (h->space, cp_body, &v);
}

/* Chipmunk gives a constraint's impulse of the last step as a magnitude
 * only (cpConstraintGetImpulse): it goes to fy, over the step. */
static void cp_joint_force (void *p, int joint, double *fx, double *fy)
{
  cp_handle *h = p;
  *fx = 0.0;
  *fy = cpConstraintGetImpulse (h->joints[2 * joint]) / h->dt;
}

static const acc_engine chipmunk_engine = {
  "chipmunk", "iterations=10,slop=0.01,dt=1/60", cp_create, cp_step, cp_state, cp_contacts, cp_destroy,
  cp_joint_force,
};

int main (int argc, char **argv)
{
  acc_settings set;
  const char *only = NULL;
  if (argc > 2 || (argc == 2 && strncmp (argv[1], "measures=", 9) != 0))
    {
      fprintf (stderr, "usage: accuracy_chipmunk [measures=collision,projectile,...]\n");
      return 2;
    }
  if (argc == 2)
    only = argv[1] + 9;
  memset (&set, 0, sizeof set);
  strcpy (set.knob, "peer");
  strcpy (set.value, "usual");
  set.dt = 1.0 / 60.0;
  return acc_run_all (&chipmunk_engine, &set, only) < 0;
}
