/* Mouse grab: picking by point-in-polygon (even-odd, so concave outlines
 * work) or distance to a circle's centre, and throwing with the pointer's
 * smoothed velocity. */
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

static int grab_inside_polygon (const double *xy, int32_t n, double x, double y)
{
  int32_t i, j;
  int inside = 0;
  for (i = 0, j = n - 1; i < n; j = i++)
    {
      double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
      if ((yi > y) != (yj > y) && x < xj + (y - yj) * (xi - xj) / (yi - yj))
        inside = !inside;
    }
  return inside;
}

static int grab_hits (const carom_world *world, carom_body_id id, double x, double y, double **xy, int32_t *cap)
{
  int32_t n = 0;
  if (carom_body_get_vertices (world, id, NULL, 0, &n) != CAROM_OK)
    return 0;
  if (n == 0)
    {
      double cx, cy, r = 0.0;
      carom_body_get_position (world, id, &cx, &cy);
      carom_body_get_shape (world, id, NULL, &r);
      return hypot (x - cx, y - cy) <= r;
    }
  if (n > *cap)
    {
      double *grown = realloc (*xy, 2 * (size_t) n * sizeof **xy);
      if (!grown)
        return 0;
      *xy = grown;
      *cap = n;
    }
  carom_body_get_vertices (world, id, *xy, *cap, &n);
  return grab_inside_polygon (*xy, n, x, y);
}

carom_body_id grab_pick (const carom_world *world, double x, double y)
{
  carom_body_id *ids, found = CAROM_NULL_BODY;
  double *xy = NULL;
  int32_t n = carom_world_get_bodies (world, NULL, 0), i, cap = 0;
  ids = malloc (((size_t) n + 1) * sizeof *ids);
  if (!ids)
    return CAROM_NULL_BODY;
  n = carom_world_get_bodies (world, ids, n);
  /* the last drawn is on top */
  for (i = n - 1; i >= 0 && found == CAROM_NULL_BODY; --i)
    {
      carom_body_type type = CAROM_STATIC;
      carom_body_get_type (world, ids[i], &type);
      if (type == CAROM_DYNAMIC && grab_hits (world, ids[i], x, y, &xy, &cap))
        found = ids[i];
    }
  free (xy);
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
