#include "support.h"

#include <math.h>
#include <stdlib.h>

#include "world.h"

int near_rel (double a, double b, double tol)
{
  double scale = fabs (a) > fabs (b) ? fabs (a) : fabs (b);
  if (scale < 1e-300)
    scale = 1e-300;
  return fabs (a - b) <= tol * scale;
}

int world_setup (void **state)
{
  carom_world *w = NULL;
  if (carom_world_init (&w, NULL) != CAROM_OK)
    return -1;
  *state = w;
  return 0;
}

carom_world *world_with (double gx, double gy, double restitution, double friction)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_world_def_init (&def, sizeof def);
  def.gravity_x = gx, def.gravity_y = gy;
  def.restitution = restitution;
  def.friction = friction;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  return w;
}

double tipping_box_depth (double manifold_tolerance, double side, double degrees, int continuous)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_id box;
  double a = degrees * M_PI / 180.0, deepest = 0.0;
  int step;
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -10.0;
  def.friction = 0.6;
  def.manifold_tolerance = manifold_tolerance;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, continuous), CAROM_OK);
  add_box (w, CAROM_STATIC, 0, -0.5, 0, 100, 1);
  box = add_box (w, CAROM_DYNAMIC, 0, 0.5 * side * (cos (a) + sin (a)) + 0.001 * side, a, side, side);
  for (step = 0; step < 240; ++step)
    {
      double x, y, q;
      assert_status (carom_world_update (w, 1.0 / 60), CAROM_OK);
      carom_body_get_position (w, box, &x, &y);
      carom_body_get_angle (w, box, &q);
      deepest = fmax (deepest, (0.5 * side * (fabs (cos (q)) + fabs (sin (q))) - y) / side);
    }
  carom_world_destroy (w);
  return deepest;
}

int world_teardown (void **state)
{
  carom_world_destroy (*state);
  *state = NULL;
  return 0;
}

static int32_t all_bodies (const carom_world *world, carom_body_id **ids)
{
  int32_t n = carom_world_get_bodies (world, NULL, 0);
  *ids = calloc ((size_t) n + 1, sizeof **ids);
  return carom_world_get_bodies (world, *ids, n);
}

double world_kinetic_energy (const carom_world *world)
{
  carom_body_id *ids;
  int32_t n = all_bodies (world, &ids), i;
  double e = 0.0;
  for (i = 0; i < n; ++i)
    {
      double vx, vy, w, m, inertia;
      carom_body_get_velocity (world, ids[i], &vx, &vy);
      carom_body_get_spin (world, ids[i], &w);
      carom_body_get_mass (world, ids[i], &m, &inertia, NULL);
      e += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * w * w;
    }
  free (ids);
  return e;
}

void world_momentum (const carom_world *world, double *px, double *py, double *l)
{
  carom_body_id *ids;
  int32_t n = all_bodies (world, &ids), i;
  *px = *py = *l = 0.0;
  for (i = 0; i < n; ++i)
    {
      double x, y, vx, vy, w, m, inertia;
      carom_body_get_position (world, ids[i], &x, &y);
      carom_body_get_velocity (world, ids[i], &vx, &vy);
      carom_body_get_spin (world, ids[i], &w);
      carom_body_get_mass (world, ids[i], &m, &inertia, NULL);
      *px += m * vx;
      *py += m * vy;
      *l += m * (x * vy - y * vx) + inertia * w;
    }
  free (ids);
}

carom_body_id add_box (carom_world *w, carom_body_type type, double x, double y, double angle, double width,
                       double height)
{
  carom_body_def d;
  carom_body_id id = CAROM_NULL_BODY;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = type;
  d.x = x, d.y = y, d.angle = angle;
  assert_status (carom_world_add_box (w, &d, width, height, &id), CAROM_OK);
  return id;
}

/* FNV-1a over raw bytes. */
static uint64_t mix (uint64_t h, const void *p, size_t n)
{
  const unsigned char *bytes = p;
  size_t k;
  for (k = 0; k < n; ++k)
    h = (h ^ bytes[k]) * 1099511628211ull;
  return h;
}

uint64_t world_state_hash (const carom_world *world)
{
  uint64_t h = 1469598103934665603ull;
  int32_t i, j;
  /* the settings and every effect's state */
  h = mix (h, &world->gravity, sizeof world->gravity);
  h = mix (h, &world->def.restitution, sizeof world->def.restitution);
  h = mix (h, &world->def.friction, sizeof world->def.friction);
  h = mix (h, &world->central.active, sizeof world->central.active);
  h = mix (h, &world->central.center, sizeof world->central.center);
  h = mix (h, &world->central.gm, sizeof world->central.gm);
  h = mix (h, &world->central.softening2, sizeof world->central.softening2);
  h = mix (h, &world->damping_linear, sizeof world->damping_linear);
  h = mix (h, &world->damping_angular, sizeof world->damping_angular);
  h = mix (h, &world->sleeping, sizeof world->sleeping);
  h = mix (h, &world->continuous, sizeof world->continuous);
  /* every live body: its id, state, material and sleep */
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *b = &world->bodies[i];
      carom_body_id id;
      if (!b->alive)
        continue;
      id = body_id_of (world, i);
      h = mix (h, &id, sizeof id);
      h = mix (h, &b->p, sizeof b->p);
      h = mix (h, &b->angle, sizeof b->angle);
      h = mix (h, &b->v, sizeof b->v);
      h = mix (h, &b->w, sizeof b->w);
      h = mix (h, &b->inv_mass, sizeof b->inv_mass);
      h = mix (h, &b->inv_inertia, sizeof b->inv_inertia);
      h = mix (h, &b->restitution, sizeof b->restitution);
      h = mix (h, &b->friction, sizeof b->friction);
      h = mix (h, &b->fixed_rotation, sizeof b->fixed_rotation);
      h = mix (h, &b->bullet, sizeof b->bullet);
      h = mix (h, &b->asleep, sizeof b->asleep);
      h = mix (h, &b->sleep_time, sizeof b->sleep_time);
      h = mix (h, &b->force, sizeof b->force);
      h = mix (h, &b->torque, sizeof b->torque);
      h = mix (h, &b->user_data, sizeof b->user_data);
      h = mix (h, &b->category, sizeof b->category);
      h = mix (h, &b->mask, sizeof b->mask);
      h = mix (h, &b->group, sizeof b->group);
      h = mix (h, &b->sensor, sizeof b->sensor);
    }
  h = mix (h, &world->forces_active, sizeof world->forces_active);
  /* the last update's events and the pairs the next one compares with */
  h = mix (h, &world->events.event_count, sizeof world->events.event_count);
  for (i = 0; i < world->events.event_count; ++i)
    h = mix (h, &world->events.list[i], sizeof world->events.list[i]);
  h = mix (h, &world->events.count[world->events.cur], sizeof (int32_t));
  for (i = 0; i < world->events.count[world->events.cur]; ++i)
    {
      const touch *t = &world->events.touches[world->events.cur][i];
      h = mix (h, &t->a, sizeof t->a);
      h = mix (h, &t->b, sizeof t->b);
      h = mix (h, &t->sensor, sizeof t->sensor);
    }
  /* every contact, with what it carries to the next step */
  for (i = 0; i < world->contacts.count; ++i)
    {
      const contact *k = &world->contacts.list[i];
      h = mix (h, &k->a, sizeof k->a);
      h = mix (h, &k->b, sizeof k->b);
      h = mix (h, &k->piece_a, sizeof k->piece_a);
      h = mix (h, &k->piece_b, sizeof k->piece_b);
      h = mix (h, &k->count, sizeof k->count);
      h = mix (h, &k->computed_at, sizeof k->computed_at);
      for (j = 0; j < k->count; ++j)
        {
          const contact_point *p = &k->points[j];
          h = mix (h, &p->point, sizeof p->point);
          h = mix (h, &p->normal, sizeof p->normal);
          h = mix (h, &p->depth, sizeof p->depth);
          h = mix (h, &p->feature, sizeof p->feature);
          h = mix (h, &p->normal_impulse, sizeof p->normal_impulse);
          h = mix (h, &p->tangent_impulse, sizeof p->tangent_impulse);
          h = mix (h, &p->normal_mass, sizeof p->normal_mass);
          h = mix (h, &p->tangent_mass, sizeof p->tangent_mass);
          h = mix (h, &p->local_a, sizeof p->local_a);
          h = mix (h, &p->local_b, sizeof p->local_b);
          h = mix (h, &p->local_normal, sizeof p->local_normal);
        }
    }
  /* every live joint: its id, what it holds and the impulses it carries */
  for (i = 0; i < world->joints.count; ++i)
    {
      const joint *jt = &world->joints.list[i];
      carom_joint_id id;
      if (!jt->alive)
        continue;
      id = joint_id_of (world, i);
      h = mix (h, &id, sizeof id);
      h = mix (h, &jt->type, sizeof jt->type);
      h = mix (h, &jt->a, sizeof jt->a);
      h = mix (h, &jt->b, sizeof jt->b);
      h = mix (h, &jt->collide_connected, sizeof jt->collide_connected);
      h = mix (h, &jt->local_a, sizeof jt->local_a);
      h = mix (h, &jt->local_b, sizeof jt->local_b);
      h = mix (h, &jt->local_axis, sizeof jt->local_axis);
      h = mix (h, &jt->reference_angle, sizeof jt->reference_angle);
      h = mix (h, &jt->length, sizeof jt->length);
      h = mix (h, &jt->enable_limit, sizeof jt->enable_limit);
      h = mix (h, &jt->enable_motor, sizeof jt->enable_motor);
      h = mix (h, &jt->enable_spring, sizeof jt->enable_spring);
      h = mix (h, &jt->lower, sizeof jt->lower);
      h = mix (h, &jt->upper, sizeof jt->upper);
      h = mix (h, &jt->motor_speed, sizeof jt->motor_speed);
      h = mix (h, &jt->max_motor_force, sizeof jt->max_motor_force);
      h = mix (h, &jt->max_motor_torque, sizeof jt->max_motor_torque);
      h = mix (h, &jt->hertz, sizeof jt->hertz);
      h = mix (h, &jt->damping_ratio, sizeof jt->damping_ratio);
      h = mix (h, &jt->target, sizeof jt->target);
      h = mix (h, &jt->target_angle, sizeof jt->target_angle);
      h = mix (h, &jt->linear_impulse, sizeof jt->linear_impulse);
      h = mix (h, &jt->angular_impulse, sizeof jt->angular_impulse);
      h = mix (h, &jt->axial_impulse, sizeof jt->axial_impulse);
      h = mix (h, &jt->motor_impulse, sizeof jt->motor_impulse);
      h = mix (h, &jt->lower_impulse, sizeof jt->lower_impulse);
      h = mix (h, &jt->upper_impulse, sizeof jt->upper_impulse);
      h = mix (h, &jt->reaction_force, sizeof jt->reaction_force);
      h = mix (h, &jt->reaction_torque, sizeof jt->reaction_torque);
    }
  h = mix (h, &world->joints.live, sizeof world->joints.live);
  return h;
}
