/* Mouse grab: picking with the library's point query (the true outline, so
 * concave polygons work), holding with a mouse joint. */
#include "grab.h"

#include <math.h>
#include <stdlib.h>

/* The joint's most force, in the body's weights (Box2D's testbed uses
 * 1000 too): strong enough to lift anything quickly, bounded so a body
 * pulled into a wall or held by other joints does not take an impulse the
 * solver cannot balance. */
#define GRAB_WEIGHTS 1000.0
/* The weight is taken at this gravity at least, so a body can be moved in
 * a world without gravity (m/s^2). */
#define GRAB_MIN_GRAVITY 9.81

void grab_init (grab *g)
{
  g->body = CAROM_NULL_BODY;
  g->joint = CAROM_NULL_JOINT;
  g->mx = g->my = 0.0;
  g->max_speed = HUGE_VAL;
}

carom_body_id grab_pick (const carom_world *world, double x, double y)
{
  carom_body_id *ids, found = CAROM_NULL_BODY;
  /* the bodies whose true outline contains the point (the library's point
   * query), in creation order: the last drawn is on top */
  int32_t n = carom_world_query_point (world, x, y, 0xffffffffu, NULL, 0), i;
  if (n <= 0)
    return CAROM_NULL_BODY;
  ids = malloc ((size_t) n * sizeof *ids);
  if (!ids)
    return CAROM_NULL_BODY;
  n = carom_world_query_point (world, x, y, 0xffffffffu, ids, n);
  for (i = n - 1; i >= 0 && found == CAROM_NULL_BODY; --i)
    {
      carom_body_type type = CAROM_STATIC;
      int32_t sensor = 0;
      carom_body_get_type (world, ids[i], &type);
      carom_body_is_sensor (world, ids[i], &sensor);
      if (type == CAROM_DYNAMIC && !sensor)
        found = ids[i];
    }
  free (ids);
  return found;
}

int grab_begin (grab *g, carom_world *world, double x, double y, double max_speed)
{
  carom_joint_def def;
  double mass = 0.0, gx = 0.0, gy = 0.0;
  carom_body_id id = grab_pick (world, x, y);
  grab_end (g, world);
  if (id == CAROM_NULL_BODY || carom_joint_def_init (&def, sizeof def) != CAROM_OK)
    return 0;
  carom_body_get_mass (world, id, &mass, NULL, NULL);
  carom_world_get_gravity (world, &gx, &gy);
  def.type = CAROM_JOINT_MOUSE;
  def.a = CAROM_NULL_BODY;
  def.b = id;
  def.x = x, def.y = y;
  /* hertz and damping_ratio 0: the joint's own 5 Hz and 0.7 */
  def.max_motor_force = GRAB_WEIGHTS * mass * fmax (hypot (gx, gy), GRAB_MIN_GRAVITY);
  if (!isfinite (def.max_motor_force) || def.max_motor_force > CAROM_MAX_MAGNITUDE)
    def.max_motor_force = 0.0; /* no bound */
  if (carom_world_add_joint (world, &def, &g->joint) != CAROM_OK)
    return 0;
  g->body = id;
  g->mx = x, g->my = y;
  g->max_speed = max_speed > 0.0 ? max_speed : HUGE_VAL;
  return 1;
}

void grab_move (grab *g, carom_world *world, double x, double y)
{
  if (g->body == CAROM_NULL_BODY)
    return;
  g->mx = x, g->my = y;
  if (carom_joint_set_target (world, g->joint, x, y, 0.0) != CAROM_OK)
    grab_init (g); /* the body and its joint are gone */
}

/* A throw is capped at max_speed, so a flick cannot send the body through
 * a wall in one step. */
static void grab_cap_speed (const grab *g, carom_world *world)
{
  double vx = 0.0, vy = 0.0, speed;
  carom_body_get_velocity (world, g->body, &vx, &vy);
  speed = hypot (vx, vy);
  if (speed > g->max_speed && isfinite (speed))
    carom_body_set_velocity (world, g->body, vx * g->max_speed / speed, vy * g->max_speed / speed);
}

void grab_update (grab *g, carom_world *world)
{
  if (g->body == CAROM_NULL_BODY)
    return;
  if (carom_joint_check (world, g->joint) != CAROM_OK)
    {
      grab_init (g);
      return;
    }
  grab_cap_speed (g, world);
}

int grab_point (const grab *g, const carom_world *world, double *x, double *y)
{
  /* a mouse joint's anchors: the target, then the body's point */
  return g->body != CAROM_NULL_BODY && carom_joint_get_anchors (world, g->joint, NULL, NULL, x, y) == CAROM_OK;
}

void grab_end (grab *g, carom_world *world)
{
  if (g->body != CAROM_NULL_BODY && carom_joint_check (world, g->joint) == CAROM_OK)
    {
      carom_world_remove_joint (world, g->joint);
      grab_cap_speed (g, world);
    }
  grab_init (g);
}
