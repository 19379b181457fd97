/* Mouse grab: picking with the library's point query (the true outline, so
 * concave polygons work), and throwing with the pointer's smoothed
 * velocity. */
#include "grab.h"

#include <math.h>
#include <stdlib.h>

/* A pointer that has not moved for this long is at rest. */
#define GRAB_REST_TIME 0.06

void grab_init (grab *g)
{
  g->body = CAROM_NULL_BODY;
  g->lx = g->ly = g->mx = g->my = g->vx = g->vy = g->t = 0.0;
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

int grab_begin (grab *g, carom_world *world, double x, double y, double now, double max_speed)
{
  double cx, cy, a = 0.0, dx, dy;
  carom_body_id id = grab_pick (world, x, y);
  grab_init (g);
  if (id == CAROM_NULL_BODY)
    return 0;
  carom_body_get_position (world, id, &cx, &cy);
  carom_body_get_angle (world, id, &a);
  dx = x - cx, dy = y - cy;
  g->body = id;
  g->lx = cos (a) * dx + sin (a) * dy;
  g->ly = -sin (a) * dx + cos (a) * dy;
  g->mx = x, g->my = y;
  g->t = now;
  g->max_speed = max_speed > 0.0 ? max_speed : HUGE_VAL;
  return 1;
}

void grab_move (grab *g, double x, double y, double now)
{
  double dt = now - g->t;
  if (g->body == CAROM_NULL_BODY)
    return;
  if (dt > 1e-4)
    {
      double k = dt > GRAB_REST_TIME ? 1.0 : 0.6; /* after a rest, start afresh */
      g->vx = k * (x - g->mx) / dt + (1.0 - k) * g->vx;
      g->vy = k * (y - g->my) / dt + (1.0 - k) * g->vy;
      g->t = now;
    }
  g->mx = x, g->my = y;
}

/* The pointer's velocity now: zero once it has rested, capped. */
static void grab_velocity (const grab *g, double now, double *vx, double *vy)
{
  double speed = hypot (g->vx, g->vy), k = 1.0;
  if (now - g->t > GRAB_REST_TIME || !isfinite (speed))
    {
      *vx = *vy = 0.0;
      return;
    }
  if (speed > g->max_speed)
    k = g->max_speed / speed;
  *vx = k * g->vx, *vy = k * g->vy;
}

void grab_update (grab *g, carom_world *world, double now)
{
  double a = 0.0, vx, vy;
  if (g->body == CAROM_NULL_BODY)
    return;
  if (carom_body_check (world, g->body) != CAROM_OK)
    {
      grab_init (g);
      return;
    }
  carom_body_get_angle (world, g->body, &a);
  grab_velocity (g, now, &vx, &vy);
  carom_body_set_position (world, g->body, g->mx - (cos (a) * g->lx - sin (a) * g->ly),
                           g->my - (sin (a) * g->lx + cos (a) * g->ly));
  carom_body_set_velocity (world, g->body, vx, vy);
  carom_body_set_spin (world, g->body, 0.0);
}

void grab_end (grab *g, carom_world *world, double now)
{
  double vx, vy;
  if (g->body != CAROM_NULL_BODY && carom_body_check (world, g->body) == CAROM_OK)
    {
      grab_velocity (g, now, &vx, &vy);
      carom_body_set_velocity (world, g->body, vx, vy);
    }
  grab_init (g);
}
