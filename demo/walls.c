/* Moving a scene's `bounds` walls. The library has no call that resizes a
 * body, so a wall that must get longer is removed and added again; the new
 * ones are added first, so a failure leaves the old box standing. */
#include "walls.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The ids of all bodies (malloc'd, the caller frees), their count in *n. */
static carom_body_id *walls_bodies (const carom_world *world, int32_t *n)
{
  carom_body_id *ids;
  *n = carom_world_get_bodies (world, NULL, 0);
  ids = malloc (((size_t) *n + 1) * sizeof *ids);
  if (ids)
    *n = carom_world_get_bodies (world, ids, *n);
  return ids;
}

/* Centre and size of each wall for a box (x0, y0)-(x1, y1) with walls of
 * thickness t outside it; the floor and ceiling run past the corners, as in
 * the scene loader, so the box has no gaps. */
static void walls_layout (double x0, double y0, double x1, double y1, double t, double centre[WALL_COUNT][2],
                          double size[WALL_COUNT][2])
{
  double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), w = x1 - x0, h = y1 - y0;
  centre[WALL_BOTTOM][0] = cx, centre[WALL_BOTTOM][1] = y0 - 0.5 * t;
  centre[WALL_TOP][0] = cx, centre[WALL_TOP][1] = y1 + 0.5 * t;
  centre[WALL_LEFT][0] = x0 - 0.5 * t, centre[WALL_LEFT][1] = cy;
  centre[WALL_RIGHT][0] = x1 + 0.5 * t, centre[WALL_RIGHT][1] = cy;
  size[WALL_BOTTOM][0] = size[WALL_TOP][0] = w + 2.0 * t;
  size[WALL_BOTTOM][1] = size[WALL_TOP][1] = t;
  size[WALL_LEFT][0] = size[WALL_RIGHT][0] = t;
  size[WALL_LEFT][1] = size[WALL_RIGHT][1] = h;
}

/* A static four-vertex body centred at (x, y) within `eps`, not yet taken. */
static int walls_match (const walls *w, const carom_world *world, carom_body_id id, double x, double y, double eps)
{
  carom_body_type type = CAROM_DYNAMIC;
  double bx, by;
  int32_t count = 0;
  int k;
  for (k = 0; k < WALL_COUNT; ++k)
    if (w->id[k] == id)
      return 0;
  if (carom_body_get_type (world, id, &type) != CAROM_OK || type != CAROM_STATIC)
    return 0;
  if (carom_body_get_vertices (world, id, NULL, 0, &count) != CAROM_OK || count != 4)
    return 0;
  carom_body_get_position (world, id, &bx, &by);
  return fabs (bx - x) <= eps && fabs (by - y) <= eps;
}

void walls_init (walls *w, const carom_world *world, const double rect[4], double restitution, double friction)
{
  double centre[WALL_COUNT][2], size[WALL_COUNT][2], eps;
  carom_body_id *ids;
  int32_t n, i;
  int k, found = 0;
  memset (w, 0, sizeof *w);
  if (!rect || !world)
    return;
  w->x0 = rect[0], w->y0 = rect[1], w->x1 = rect[2], w->y1 = rect[3];
  w->right = w->x1, w->top = w->y1;
  w->thickness = 0.05 * fmin (w->x1 - w->x0, w->y1 - w->y0);
  w->restitution = restitution;
  w->friction = friction;
  walls_layout (w->x0, w->y0, w->x1, w->y1, w->thickness, centre, size);
  eps = 1e-9 * fmax (fmax (fabs (w->x0), fabs (w->x1)), fmax (fabs (w->y0), fabs (w->y1))) + 1e-12;
  ids = walls_bodies (world, &n);
  if (!ids)
    return;
  for (k = 0; k < WALL_COUNT; ++k)
    for (i = 0; i < n; ++i)
      if (walls_match (w, world, ids[i], centre[k][0], centre[k][1], eps))
        {
          w->id[k] = ids[i];
          ++found;
          break;
        }
  free (ids);
  w->present = found == WALL_COUNT;
}

int walls_contains (const walls *w, carom_body_id id)
{
  int k;
  if (!w->present)
    return 0;
  for (k = 0; k < WALL_COUNT; ++k)
    if (w->id[k] == id)
      return 1;
  return 0;
}

/* How far a body's outline reaches from its centre of mass, and its
 * largest x and y. */
static void walls_body_extent (const carom_world *world, carom_body_id id, double *reach, double *mx, double *my)
{
  double xy[2 * 64], x, y, r = 0.0, *v = xy;
  int32_t count = 0, k;
  carom_body_get_position (world, id, &x, &y);
  *reach = 0.0, *mx = x, *my = y;
  if (carom_body_get_vertices (world, id, xy, 64, &count) != CAROM_OK)
    return;
  if (count == 0)
    {
      carom_body_get_shape (world, id, NULL, &r);
      *reach = r, *mx = x + r, *my = y + r;
      return;
    }
  if (count > 64)
    {
      v = malloc (2 * (size_t) count * sizeof *v);
      if (!v || carom_body_get_vertices (world, id, v, count, &count) != CAROM_OK)
        {
          free (v);
          return;
        }
    }
  for (k = 0; k < count; ++k)
    {
      *reach = fmax (*reach, hypot (v[2 * k] - x, v[2 * k + 1] - y));
      *mx = fmax (*mx, v[2 * k]), *my = fmax (*my, v[2 * k + 1]);
    }
  if (v != xy)
    free (v);
}

/* Put dynamic bodies that were inside the old box but now stick out of the
 * new right wall or ceiling back inside, as flying-balls' ball_reposition. */
static void walls_gather (const walls *w, carom_world *world, double old_right, double old_top)
{
  carom_body_id *ids;
  int32_t n, i;
  ids = walls_bodies (world, &n);
  if (!ids)
    return;
  for (i = 0; i < n; ++i)
    {
      carom_body_type type = CAROM_STATIC;
      double x, y, r, mx, my, nx, ny;
      carom_body_get_type (world, ids[i], &type);
      if (type != CAROM_DYNAMIC)
        continue;
      carom_body_get_position (world, ids[i], &x, &y);
      if (x < w->x0 || x > old_right || y < w->y0 || y > old_top)
        continue; /* not in the box: leave it be */
      walls_body_extent (world, ids[i], &r, &mx, &my);
      nx = fmin (x, w->right - r);
      ny = fmin (y, w->top - r);
      nx = fmax (nx, fmin (w->x0 + r, 0.5 * (w->x0 + w->right)));
      ny = fmax (ny, fmin (w->y0 + r, 0.5 * (w->y0 + w->top)));
      if (nx != x || ny != y)
        carom_body_set_position (world, ids[i], nx, ny);
    }
  free (ids);
}

/* Static bodies fixed to the right wall or the ceiling (their outline
 * reaches it, as the thesis scene's triangles) move with it. */
static void walls_carry (const walls *w, carom_world *world, double old_right, double old_top)
{
  double tol = 1e-6 * fmax (w->x1 - w->x0, w->y1 - w->y0), dx = w->right - old_right, dy = w->top - old_top;
  carom_body_id *ids;
  int32_t n, i;
  ids = walls_bodies (world, &n);
  if (!ids)
    return;
  for (i = 0; i < n; ++i)
    {
      carom_body_type type = CAROM_DYNAMIC;
      double x, y, r, mx, my, sx = 0.0, sy = 0.0;
      carom_body_get_type (world, ids[i], &type);
      if (type != CAROM_STATIC || walls_contains (w, ids[i]))
        continue;
      walls_body_extent (world, ids[i], &r, &mx, &my);
      if (mx >= old_right - tol && mx <= old_right + w->thickness + tol)
        sx = dx;
      if (my >= old_top - tol && my <= old_top + w->thickness + tol)
        sy = dy;
      if (sx == 0.0 && sy == 0.0)
        continue;
      carom_body_get_position (world, ids[i], &x, &y);
      carom_body_set_position (world, ids[i], x + sx, y + sy);
    }
  free (ids);
}

carom_status walls_update (walls *w, carom_world *world, double right, double top)
{
  double centre[WALL_COUNT][2], size[WALL_COUNT][2], old_right = w->right, old_top = w->top;
  carom_body_id fresh[WALL_COUNT] = { CAROM_NULL_BODY, CAROM_NULL_BODY, CAROM_NULL_BODY, CAROM_NULL_BODY };
  carom_body_def def;
  carom_status s = CAROM_OK;
  int k;
  if (!w->present)
    return CAROM_OK;
  if (!(right > w->x0) || !(top > w->y0) || !isfinite (right) || !isfinite (top))
    return CAROM_ERR_BAD_ARGUMENT;
  if (right == w->right && top == w->top)
    return CAROM_OK;
  walls_layout (w->x0, w->y0, right, top, w->thickness, centre, size);
  carom_body_def_init (&def, sizeof def);
  def.type = CAROM_STATIC;
  def.restitution = w->restitution;
  def.friction = w->friction;
  for (k = 0; k < WALL_COUNT && s == CAROM_OK; ++k)
    {
      def.x = centre[k][0], def.y = centre[k][1];
      s = carom_world_add_box (world, &def, size[k][0], size[k][1], &fresh[k]);
    }
  if (s != CAROM_OK)
    {
      for (k = 0; k < WALL_COUNT; ++k)
        if (fresh[k] != CAROM_NULL_BODY)
          carom_world_remove_body (world, fresh[k]);
      return s;
    }
  for (k = 0; k < WALL_COUNT; ++k)
    {
      carom_world_remove_body (world, w->id[k]);
      w->id[k] = fresh[k];
    }
  w->right = right, w->top = top;
  walls_carry (w, world, old_right, old_top);
  if (right < old_right || top < old_top)
    walls_gather (w, world, old_right, old_top);
  return CAROM_OK;
}
