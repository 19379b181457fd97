/* Drawing a carom world with Cairo (no GTK): the GTK demo paints its window
 * with it and the headless runner its PNG/SVG files, so both show the same
 * picture. Everything is read through the public API; geometry is mapped to
 * screen pixels here (y flipped) so line widths and arrow heads stay in
 * pixels whatever the zoom. */
#include "render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RENDER_PI 3.14159265358979323846

/* Velocity arrows show where a body would be this much time later. */
#define RENDER_VELOCITY_TIME 0.2
/* Contact normals and the gravity arrow have a fixed length in pixels. */
#define RENDER_NORMAL_PX 14.0
#define RENDER_GRAVITY_PX 32.0
/* A joint's pins: circles of this radius in pixels at most. */
#define RENDER_PIN_PX 3.5

typedef struct rgb {
  double r, g, b;
} rgb;

/* ------------------------------------------------------------- geometry */

/* Uniform scale (pixels per world unit) and the offsets that centre the
 * view in the target when the aspect ratios differ. */
static void render_frame (const render_options *opt, double *scale, double *ox, double *oy)
{
  double vw = opt->view_x1 - opt->view_x0, vh = opt->view_y1 - opt->view_y0;
  double sx = vw > 0.0 ? opt->width / vw : 1.0, sy = vh > 0.0 ? opt->height / vh : 1.0;
  *scale = sx < sy ? sx : sy;
  *ox = 0.5 * (opt->width - vw * *scale);
  *oy = 0.5 * (opt->height - vh * *scale);
}

void render_to_screen (const render_options *opt, double wx, double wy, double *sx, double *sy)
{
  double scale, ox, oy;
  render_frame (opt, &scale, &ox, &oy);
  *sx = ox + (wx - opt->view_x0) * scale;
  *sy = opt->height - oy - (wy - opt->view_y0) * scale;
}

void render_to_world (const render_options *opt, double sx, double sy, double *wx, double *wy)
{
  double scale, ox, oy;
  render_frame (opt, &scale, &ox, &oy);
  *wx = opt->view_x0 + (sx - ox) / scale;
  *wy = opt->view_y0 + (opt->height - oy - sy) / scale;
}

/* The live bodies, in creation order; *ids must be freed. */
static int32_t render_bodies (const carom_world *world, carom_body_id **ids)
{
  int32_t n = carom_world_get_bodies (world, NULL, 0);
  *ids = malloc (((size_t) n + 1) * sizeof **ids);
  if (!*ids)
    return 0;
  n = carom_world_get_bodies (world, *ids, n);
  return n;
}

/* Shape `index` of a body: a polygon's world vertices into *xy (grown as
 * needed, *cap points), returning the count, or 0 for a circle (its centre
 * and radius in *x, *y, *r) or on failure (-1). */
static int32_t render_shape (const carom_world *world, carom_body_id id, int32_t index, double **xy, int32_t *cap,
                             double *x, double *y, double *r)
{
  int32_t n = 0;
  carom_shape_kind kind = CAROM_SHAPE_CIRCLE;
  if (carom_body_get_shape_geometry (world, id, index, &kind, x, y, r, *xy, *cap, &n) != CAROM_OK)
    return -1;
  if (kind == CAROM_SHAPE_CIRCLE)
    return isfinite (*x) && isfinite (*y) && isfinite (*r) ? 0 : -1;
  if (n > *cap)
    {
      double *grown = realloc (*xy, 2 * (size_t) n * sizeof **xy);
      if (!grown)
        return -1;
      *xy = grown;
      *cap = n;
      if (carom_body_get_shape_geometry (world, id, index, NULL, NULL, NULL, NULL, *xy, *cap, &n) != CAROM_OK)
        return -1;
    }
  return n;
}

static int32_t render_shape_count (const carom_world *world, carom_body_id id)
{
  int32_t n = 0;
  carom_body_get_shape_count (world, id, &n);
  return n;
}

void render_options_init (render_options *opt, const carom_world *world, int width, int height)
{
  memset (opt, 0, sizeof *opt);
  opt->width = width;
  opt->height = height;
  opt->show_contacts = 1;
  opt->show_centroids = 1;
  opt->show_joints = 1;
  render_fit_view (opt, world);
}

/* With height <= 0 the view is the bodies' box plus margin, whatever its
 * aspect: the runner sizes its image from it. */
void render_fit_view (render_options *opt, const carom_world *world)
{
  double lo_x = HUGE_VAL, lo_y = HUGE_VAL, hi_x = -HUGE_VAL, hi_y = -HUGE_VAL;
  double w, h, margin, *xy = NULL;
  int32_t n, i, j, k, cap = 0;
  carom_body_id *ids = NULL;
  n = render_bodies (world, &ids);
  for (i = 0; i < n; ++i)
    for (j = 0; j < render_shape_count (world, ids[i]); ++j)
      {
        double x = 0.0, y = 0.0, r = 0.0;
        int32_t count = render_shape (world, ids[i], j, &xy, &cap, &x, &y, &r);
        if (count == 0)
          {
            lo_x = fmin (lo_x, x - r), hi_x = fmax (hi_x, x + r);
            lo_y = fmin (lo_y, y - r), hi_y = fmax (hi_y, y + r);
          }
        for (k = 0; k < count; ++k)
          if (isfinite (xy[2 * k]) && isfinite (xy[2 * k + 1]))
            {
              lo_x = fmin (lo_x, xy[2 * k]), hi_x = fmax (hi_x, xy[2 * k]);
              lo_y = fmin (lo_y, xy[2 * k + 1]), hi_y = fmax (hi_y, xy[2 * k + 1]);
            }
      }
  free (ids);
  free (xy);
  if (!(lo_x <= hi_x && lo_y <= hi_y))
    lo_x = lo_y = -1.0, hi_x = hi_y = 1.0; /* nothing to show */
  w = hi_x - lo_x;
  h = hi_y - lo_y;
  margin = 0.04 * fmax (w, h);
  if (margin <= 0.0)
    margin = fmax (1.0, 0.5 * fmax (fabs (lo_x), fabs (lo_y))); /* a single point */
  lo_x -= margin, hi_x += margin, lo_y -= margin, hi_y += margin;
  if (opt->width > 0 && opt->height > 0)
    {
      /* grow the short side to the target's aspect ratio */
      double want = (double) opt->width / opt->height, have = (hi_x - lo_x) / (hi_y - lo_y);
      if (have < want)
        {
          double grow = 0.5 * ((hi_y - lo_y) * want - (hi_x - lo_x));
          lo_x -= grow, hi_x += grow;
        }
      else
        {
          double grow = 0.5 * ((hi_x - lo_x) / want - (hi_y - lo_y));
          lo_y -= grow, hi_y += grow;
        }
    }
  opt->view_x0 = lo_x, opt->view_y0 = lo_y;
  opt->view_x1 = hi_x, opt->view_y1 = hi_y;
}

/* ---------------------------------------------------------------- colour */

/* A well-mixed 64-bit hash (splitmix64's finaliser), so neighbouring ids
 * get unrelated hues. */
static uint64_t render_hash (uint64_t x)
{
  x += 0x9E3779B97F4A7C15u;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9u;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBu;
  return x ^ (x >> 31);
}

static rgb render_hsv (double h, double s, double v)
{
  double f = 6.0 * (h - floor (h)), c = v * s, x = c * (1.0 - fabs (fmod (f, 2.0) - 1.0)), m = v - c;
  rgb out;
  switch ((int) f)
    {
    case 0: out.r = c, out.g = x, out.b = 0; break;
    case 1: out.r = x, out.g = c, out.b = 0; break;
    case 2: out.r = 0, out.g = c, out.b = x; break;
    case 3: out.r = 0, out.g = x, out.b = c; break;
    case 4: out.r = x, out.g = 0, out.b = c; break;
    default: out.r = c, out.g = 0, out.b = x; break;
    }
  out.r += m, out.g += m, out.b += m;
  return out;
}

/* The body's colour: a function of its id alone, so a body keeps it from
 * frame to frame and between the demo and the runner. */
static rgb render_body_colour (carom_body_id id)
{
  uint64_t h = render_hash (id);
  double hue = (double) (h >> 40) / (double) (1u << 24);
  double sat = 0.45 + 0.25 * (double) ((h >> 8) & 0xFF) / 255.0;
  double val = 0.80 + 0.15 * (double) ((h >> 16) & 0xFF) / 255.0;
  return render_hsv (hue, sat, val);
}

/* --------------------------------------------------------------- drawing */

static void render_arrow (cairo_t *cr, double x0, double y0, double x1, double y1, double head)
{
  double dx = x1 - x0, dy = y1 - y0, len = hypot (dx, dy), ux, uy;
  if (!(len > 0.5))
    return;
  ux = dx / len, uy = dy / len;
  if (head > 0.6 * len)
    head = 0.6 * len;
  cairo_move_to (cr, x0, y0);
  cairo_line_to (cr, x1 - ux * head * 0.5, y1 - uy * head * 0.5);
  cairo_stroke (cr);
  cairo_move_to (cr, x1, y1);
  cairo_line_to (cr, x1 - ux * head - uy * head * 0.45, y1 - uy * head + ux * head * 0.45);
  cairo_line_to (cr, x1 - ux * head + uy * head * 0.45, y1 - uy * head - ux * head * 0.45);
  cairo_close_path (cr);
  cairo_fill (cr);
}

/* Faint grid lines at a power-of-ten spacing at least 40 px apart: a sense
 * of scale without axes or labels. */
static void render_grid (cairo_t *cr, const render_options *opt, double scale)
{
  double step = pow (10.0, ceil (log10 (40.0 / scale))), x0, y0, x1, y1, v;
  if (!isfinite (step) || step <= 0.0)
    return;
  render_to_world (opt, 0, opt->height, &x0, &y0);
  render_to_world (opt, opt->width, 0, &x1, &y1);
  if ((x1 - x0) / step > 1000 || (y1 - y0) / step > 1000)
    return;
  cairo_set_source_rgb (cr, 0.90, 0.90, 0.87);
  cairo_set_line_width (cr, 1.0);
  for (v = ceil (x0 / step) * step; v <= x1; v += step)
    {
      double sx, sy;
      render_to_screen (opt, v, 0, &sx, &sy);
      cairo_move_to (cr, floor (sx) + 0.5, 0);
      cairo_line_to (cr, floor (sx) + 0.5, opt->height);
    }
  for (v = ceil (y0 / step) * step; v <= y1; v += step)
    {
      double sx, sy;
      render_to_screen (opt, 0, v, &sx, &sy);
      cairo_move_to (cr, 0, floor (sy) + 0.5);
      cairo_line_to (cr, opt->width, floor (sy) + 0.5);
    }
  cairo_stroke (cr);
}

/* Trace the body's outline as the current path (each shape of a compound
 * a sub-path); returns 0 if it has no finite state to draw. */
static int render_body_path (cairo_t *cr, const render_options *opt, const carom_world *world, carom_body_id id,
                             double **xy, int32_t *cap, double scale)
{
  int32_t shapes = render_shape_count (world, id), j, k;
  double sx, sy;
  for (j = 0; j < shapes; ++j)
    {
      double x = 0.0, y = 0.0, r = 0.0;
      int32_t n = render_shape (world, id, j, xy, cap, &x, &y, &r);
      if (n < 0)
        {
          cairo_new_path (cr);
          return 0;
        }
      if (n == 0)
        {
          render_to_screen (opt, x, y, &sx, &sy);
          /* turning as polygons do on screen (y down), so the shapes of a
           * compound fill as one */
          cairo_new_sub_path (cr);
          cairo_arc_negative (cr, sx, sy, r * scale, 0.0, -2.0 * RENDER_PI);
          cairo_close_path (cr);
          continue;
        }
      for (k = 0; k < n; ++k)
        {
          if (!isfinite ((*xy)[2 * k]) || !isfinite ((*xy)[2 * k + 1]))
            {
              cairo_new_path (cr);
              return 0;
            }
          render_to_screen (opt, (*xy)[2 * k], (*xy)[2 * k + 1], &sx, &sy);
          if (k == 0)
            cairo_move_to (cr, sx, sy);
          else
            cairo_line_to (cr, sx, sy);
        }
      cairo_close_path (cr);
    }
  return shapes > 0;
}

/* Bodies are drawn through the library's debug draw (carom_world_draw):
 * one pass for the static bodies, then one for the others, so moving
 * bodies are never hidden behind walls. */
typedef struct render_pass {
  cairo_t *cr;
  const render_options *opt;
  const carom_world *world;
  double scale, line;
  int statics; /* this pass draws the static bodies (1) or the others (0) */
} render_pass;

/* Whether this pass draws `id`, and in which style. */
static int render_pass_style (const render_pass *p, carom_body_id id, carom_body_type *type, int32_t *sensor,
                              int *lit)
{
  int32_t i;
  *type = CAROM_DYNAMIC;
  carom_body_get_type (p->world, id, type);
  if ((*type == CAROM_STATIC) != p->statics)
    return 0;
  *sensor = 0;
  carom_body_is_sensor (p->world, id, sensor);
  *lit = 0;
  for (i = 0; i < p->opt->lit_count; ++i)
    *lit |= p->opt->lit[i] == id;
  return 1;
}

/* Fill and stroke the current path in the body's style. */
static void render_paint_shape (const render_pass *p, carom_body_id id, carom_body_type type, int32_t sensor,
                                int lit)
{
  cairo_t *cr = p->cr;
  rgb fill = render_body_colour (id);
  if (sensor)
    {
      /* a sensor: a pale zone, bright while something is inside */
      if (lit)
        cairo_set_source_rgba (cr, 1.0, 0.85, 0.2, 0.55);
      else
        cairo_set_source_rgba (cr, 0.55, 0.8, 0.6, 0.25);
    }
  else if (type == CAROM_STATIC)
    cairo_set_source_rgb (cr, 0.66, 0.66, 0.68);
  else if (type == CAROM_KINEMATIC)
    cairo_set_source_rgb (cr, 0.45, 0.55, 0.75);
  else
    cairo_set_source_rgba (cr, fill.r, fill.g, fill.b, 0.92);
  cairo_fill_preserve (cr);
  if (sensor)
    cairo_set_source_rgba (cr, 0.2, 0.5, 0.3, 0.8);
  else if (type == CAROM_STATIC)
    cairo_set_source_rgb (cr, 0.38, 0.38, 0.40);
  else if (type == CAROM_KINEMATIC)
    cairo_set_source_rgb (cr, 0.2, 0.25, 0.4);
  else
    cairo_set_source_rgb (cr, 0.35 * fill.r, 0.35 * fill.g, 0.35 * fill.b);
  cairo_set_line_width (cr, p->line);
  cairo_set_line_join (cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke (cr);
}

static void render_draw_polygon (const double *xy, int32_t n, carom_body_id body, void *user)
{
  const render_pass *p = user;
  carom_body_type type;
  int32_t sensor, k;
  int lit;
  if (!render_pass_style (p, body, &type, &sensor, &lit))
    return;
  for (k = 0; k < n; ++k)
    {
      double sx, sy;
      if (!isfinite (xy[2 * k]) || !isfinite (xy[2 * k + 1]))
        {
          cairo_new_path (p->cr);
          return;
        }
      render_to_screen (p->opt, xy[2 * k], xy[2 * k + 1], &sx, &sy);
      if (k == 0)
        cairo_move_to (p->cr, sx, sy);
      else
        cairo_line_to (p->cr, sx, sy);
    }
  cairo_close_path (p->cr);
  render_paint_shape (p, body, type, sensor, lit);
}

static void render_draw_circle (double x, double y, double r, double angle, carom_body_id body, void *user)
{
  const render_pass *p = user;
  carom_body_type type;
  int32_t sensor;
  int lit;
  double sx0, sy0, sx1, sy1;
  if (!render_pass_style (p, body, &type, &sensor, &lit))
    return;
  if (!isfinite (x) || !isfinite (y) || !isfinite (r) || !isfinite (angle))
    return;
  render_to_screen (p->opt, x, y, &sx0, &sy0);
  cairo_new_sub_path (p->cr);
  cairo_arc (p->cr, sx0, sy0, r * p->scale, 0.0, 2.0 * RENDER_PI);
  cairo_close_path (p->cr);
  render_paint_shape (p, body, type, sensor, lit);
  /* a radius at the body's angle, so a circle's rotation shows */
  render_to_screen (p->opt, x + r * cos (angle), y + r * sin (angle), &sx1, &sy1);
  cairo_move_to (p->cr, sx0, sy0);
  cairo_line_to (p->cr, sx1, sy1);
  cairo_stroke (p->cr);
}

/* A pin: a small ring at screen (x, y). */
static void render_pin (cairo_t *cr, double x, double y, double r)
{
  cairo_new_sub_path (cr);
  cairo_arc (cr, x, y, r, 0.0, 2.0 * RENDER_PI);
  cairo_set_source_rgb (cr, 1.0, 1.0, 1.0);
  cairo_fill_preserve (cr);
  cairo_set_source_rgb (cr, 0.12, 0.16, 0.24);
  cairo_stroke (cr);
}

/* A joint from the debug draw: xy holds a's centre, a's anchor, b's anchor
 * and b's centre (a joint to the world: its fixed point twice; a mouse
 * joint: its target twice). Thin lines from each anchor to its moving
 * body's centre (a static body's anchor is a fixed point), a line between
 * the anchors where they part (a distance joint's rod, a slider's travel),
 * a ring at each anchor; the world's fixed point gets a small ground mark,
 * and a mouse joint (the demo's grab) is an orange line from the body to
 * the pointer. */
static void render_draw_joint (carom_joint_type type, const double *xy, carom_joint_id id, void *user)
{
  const render_pass *p = user;
  cairo_t *cr = p->cr;
  double s[8], pin = fmin (RENDER_PIN_PX, fmax (1.5, 0.08 * p->scale));
  carom_body_id a = CAROM_NULL_BODY, b = CAROM_NULL_BODY;
  carom_body_type type_a = CAROM_STATIC, type_b = CAROM_STATIC; /* the world, or a body that cannot be read */
  int k;
  for (k = 0; k < 8; ++k)
    if (!isfinite (xy[k]))
      return;
  for (k = 0; k < 4; ++k)
    render_to_screen (p->opt, xy[2 * k], xy[2 * k + 1], &s[2 * k], &s[2 * k + 1]);
  cairo_save (cr);
  cairo_set_line_cap (cr, CAIRO_LINE_CAP_ROUND);
  if (type == CAROM_JOINT_MOUSE)
    {
      static const double dash[2] = { 5.0, 3.0 };
      cairo_set_source_rgba (cr, 1.0, 0.55, 0.0, 0.95);
      cairo_set_line_width (cr, 2.0);
      cairo_set_dash (cr, dash, 2, 0.0);
      cairo_move_to (cr, s[4], s[5]);
      cairo_line_to (cr, s[2], s[3]);
      cairo_stroke (cr);
      cairo_set_dash (cr, NULL, 0, 0.0);
      cairo_new_sub_path (cr);
      cairo_arc (cr, s[2], s[3], pin + 1.5, 0.0, 2.0 * RENDER_PI);
      cairo_stroke (cr);
      cairo_new_sub_path (cr);
      cairo_arc (cr, s[4], s[5], 0.7 * pin, 0.0, 2.0 * RENDER_PI);
      cairo_fill (cr);
      cairo_restore (cr);
      return;
    }
  carom_joint_get_bodies (p->world, id, NULL, &a, &b);
  carom_body_get_type (p->world, a, &type_a);
  carom_body_get_type (p->world, b, &type_b);
  cairo_set_source_rgba (cr, 0.12, 0.16, 0.24, 0.75);
  cairo_set_line_width (cr, 1.0);
  if (type_a != CAROM_STATIC)
    {
      cairo_move_to (cr, s[0], s[1]);
      cairo_line_to (cr, s[2], s[3]);
    }
  if (type_b != CAROM_STATIC)
    {
      cairo_move_to (cr, s[6], s[7]);
      cairo_line_to (cr, s[4], s[5]);
    }
  cairo_stroke (cr);
  if (hypot (s[4] - s[2], s[5] - s[3]) > 0.5)
    {
      cairo_set_source_rgba (cr, 0.12, 0.16, 0.24, 0.9);
      cairo_set_line_width (cr, type == CAROM_JOINT_DISTANCE ? 2.0 : 1.0);
      cairo_move_to (cr, s[2], s[3]);
      cairo_line_to (cr, s[4], s[5]);
      cairo_stroke (cr);
    }
  if (a == CAROM_NULL_BODY)
    {
      /* the world: a small triangle under the fixed point */
      double h = 2.2 * pin;
      cairo_set_source_rgba (cr, 0.12, 0.16, 0.24, 0.85);
      cairo_move_to (cr, s[2], s[3]);
      cairo_line_to (cr, s[2] - h, s[3] + 1.6 * h);
      cairo_line_to (cr, s[2] + h, s[3] + 1.6 * h);
      cairo_close_path (cr);
      cairo_fill (cr);
    }
  cairo_set_line_width (cr, 1.2);
  render_pin (cr, s[2], s[3], pin);
  if (hypot (s[4] - s[2], s[5] - s[3]) > 0.5)
    render_pin (cr, s[4], s[5], pin);
  cairo_restore (cr);
}

static void render_bodies_drawn (cairo_t *cr, const render_options *opt, const carom_world *world, double scale,
                                 double line)
{
  render_pass pass;
  carom_debug_draw draw;
  if (carom_debug_draw_init (&draw, sizeof draw) != CAROM_OK)
    return;
  pass.cr = cr, pass.opt = opt, pass.world = world, pass.scale = scale, pass.line = line;
  draw.polygon = render_draw_polygon;
  draw.circle = render_draw_circle;
  draw.joint = render_draw_joint;
  draw.user = &pass;
  draw.draw_contacts = 0; /* drawn by render_contacts, at a fixed size on screen */
  for (pass.statics = 1; pass.statics >= 0; --pass.statics)
    {
      /* the joints once, over every body */
      draw.draw_joints = !pass.statics && opt->show_joints;
      carom_world_draw (world, &draw);
    }
}

static void render_highlight (cairo_t *cr, const render_options *opt, const carom_world *world, double **xy,
                              int32_t *cap, double scale)
{
  if (carom_body_check (world, opt->highlight) != CAROM_OK)
    return;
  if (!render_body_path (cr, opt, world, opt->highlight, xy, cap, scale))
    return;
  cairo_set_source_rgba (cr, 1.0, 0.55, 0.0, 0.9);
  cairo_set_line_width (cr, 3.0);
  cairo_stroke (cr);
}

static void render_centroid (cairo_t *cr, const render_options *opt, const carom_world *world, carom_body_id id,
                             double scale)
{
  double x, y, sx, sy, r = fmin (3.0, fmax (1.2, 0.04 * scale));
  carom_body_get_position (world, id, &x, &y);
  if (!isfinite (x) || !isfinite (y))
    return;
  render_to_screen (opt, x, y, &sx, &sy);
  cairo_new_sub_path (cr);
  cairo_arc (cr, sx, sy, r, 0.0, 2.0 * RENDER_PI);
  cairo_set_source_rgb (cr, 0.1, 0.1, 0.1);
  cairo_fill (cr);
}

static void render_velocity (cairo_t *cr, const render_options *opt, const carom_world *world, carom_body_id id)
{
  double x, y, vx, vy, sx0, sy0, sx1, sy1;
  carom_body_get_position (world, id, &x, &y);
  carom_body_get_velocity (world, id, &vx, &vy);
  if (!isfinite (x) || !isfinite (y) || !isfinite (vx) || !isfinite (vy))
    return;
  render_to_screen (opt, x, y, &sx0, &sy0);
  render_to_screen (opt, x + RENDER_VELOCITY_TIME * vx, y + RENDER_VELOCITY_TIME * vy, &sx1, &sy1);
  cairo_set_source_rgb (cr, 0.05, 0.35, 0.75);
  cairo_set_line_width (cr, 1.5);
  render_arrow (cr, sx0, sy0, sx1, sy1, 7.0);
}

/* Contact marks shrink with the zoom (to a third of a world unit at most)
 * so a crowded scene is not painted over by them. */
static void render_contacts (cairo_t *cr, const render_options *opt, const carom_world *world, double scale)
{
  int32_t n = carom_world_contact_count (world), i;
  double normal = fmin (RENDER_NORMAL_PX, 0.33 * scale), dot = fmin (2.5, 0.06 * scale);
  cairo_set_line_width (cr, fmin (1.5, 0.04 * scale));
  for (i = 0; i < n; ++i)
    {
      double px, py, nx, ny, sx, sy;
      if (carom_world_get_contact (world, i, NULL, NULL, &px, &py, &nx, &ny, NULL) != CAROM_OK)
        continue;
      if (!isfinite (px) || !isfinite (py) || !isfinite (nx) || !isfinite (ny))
        continue;
      render_to_screen (opt, px, py, &sx, &sy);
      cairo_set_source_rgb (cr, 0.85, 0.1, 0.1);
      /* the screen's y runs down: flip the normal's y */
      render_arrow (cr, sx, sy, sx + normal * nx, sy - normal * ny, 0.35 * normal);
      cairo_new_sub_path (cr);
      cairo_arc (cr, sx, sy, dot, 0.0, 2.0 * RENDER_PI);
      cairo_fill (cr);
    }
}

/* A rounded, translucent panel behind an overlay so it reads on any scene. */
static void render_panel (cairo_t *cr, double x, double y, double w, double h)
{
  double r = 5.0;
  cairo_new_sub_path (cr);
  cairo_arc (cr, x + w - r, y + r, r, -RENDER_PI / 2, 0);
  cairo_arc (cr, x + w - r, y + h - r, r, 0, RENDER_PI / 2);
  cairo_arc (cr, x + r, y + h - r, r, RENDER_PI / 2, RENDER_PI);
  cairo_arc (cr, x + r, y + r, r, RENDER_PI, 1.5 * RENDER_PI);
  cairo_close_path (cr);
  cairo_set_source_rgba (cr, 1.0, 1.0, 1.0, 0.8);
  cairo_fill_preserve (cr);
  cairo_set_source_rgba (cr, 0.0, 0.0, 0.0, 0.25);
  cairo_set_line_width (cr, 1.0);
  cairo_stroke (cr);
}

/* Labels are drawn with a small built-in stroke font (seven-segment digits
 * and the few other characters the overlays need) instead of Cairo's toy
 * text API: no dependence on the fonts installed, identical pictures on
 * every machine, and no fontconfig caches that Valgrind reports as leaks.
 * Glyphs live in a 4 x 6 cell, y down from the top, descender to 7.5. */
typedef struct render_stroke {
  float x0, y0, x1, y1;
} render_stroke;

static const render_stroke render_segments[7] = {
  { 0, 0, 4, 0 }, { 4, 0, 4, 3 }, { 4, 3, 4, 6 }, { 0, 6, 4, 6 }, /* a b c d */
  { 0, 3, 0, 6 }, { 0, 0, 0, 3 }, { 0, 3, 4, 3 },                 /* e f g */
};
/* segments a..g as bits 0..6 for the digits 0..9 */
static const unsigned char render_digits[10] = { 0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F };

static const render_stroke render_glyph_e[] = {
  { 0, 3, 4, 3 }, { 4, 3, 4, 0 }, { 4, 0, 0, 0 }, { 0, 0, 0, 6 }, { 0, 6, 4, 6 }, { 0, 0, 0, 0 } };
static const render_stroke render_glyph_g[] = {
  { 4, 3, 0, 3 }, { 0, 3, 0, 5.5f }, { 0, 5.5f, 4, 5.5f }, { 4, 3, 4, 7.5f }, { 4, 7.5f, 0, 7.5f }, { 0, 0, 0, 0 } };
static const render_stroke render_glyph_one[] = { { 1, 1, 2.5f, 0 }, { 2.5f, 0, 2.5f, 6 }, { 0, 0, 0, 0 } };
static const render_stroke render_glyph_minus[] = { { 0.5f, 3, 3.5f, 3 }, { 0, 0, 0, 0 } };
static const render_stroke render_glyph_plus[] = { { 0.5f, 3, 3.5f, 3 }, { 2, 1.5f, 2, 4.5f }, { 0, 0, 0, 0 } };
static const render_stroke render_glyph_equals[] = { { 0.5f, 2, 3.5f, 2 }, { 0.5f, 4, 3.5f, 4 }, { 0, 0, 0, 0 } };

/* Draw `text` with its top left at (x, y), glyph cells `unit` px apart. */
static void render_label (cairo_t *cr, double x, double y, const char *text)
{
  const double unit = 2.0;
  cairo_save (cr);
  cairo_set_source_rgb (cr, 0.1, 0.1, 0.1);
  cairo_set_line_width (cr, 1.5);
  cairo_set_line_cap (cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join (cr, CAIRO_LINE_JOIN_ROUND);
  for (; *text; ++text)
    {
      const render_stroke *strokes = NULL;
      double advance = 6.0;
      int k;
      if (*text == '1')
        strokes = render_glyph_one; /* the segments' 1 sits too far right */
      else if (*text >= '0' && *text <= '9')
        {
          for (k = 0; k < 7; ++k)
            if (render_digits[*text - '0'] & (1u << k))
              {
                const render_stroke *st = &render_segments[k];
                cairo_move_to (cr, x + unit * st->x0, y + unit * st->y0);
                cairo_line_to (cr, x + unit * st->x1, y + unit * st->y1);
              }
        }
      else if (*text == '.')
        {
          cairo_new_sub_path (cr);
          cairo_arc (cr, x + unit * 0.5, y + unit * 6.0, 0.2 * unit, 0.0, 2.0 * RENDER_PI);
          advance = 2.5;
        }
      else
        switch (*text)
          {
          case 'e': strokes = render_glyph_e; break;
          case 'g': strokes = render_glyph_g; break;
          case '-': strokes = render_glyph_minus; break;
          case '+': strokes = render_glyph_plus; break;
          case '=': strokes = render_glyph_equals; break;
          default: advance = 4.0; break; /* space and anything unknown */
          }
      for (; strokes && (strokes->x0 != strokes->x1 || strokes->y0 != strokes->y1); ++strokes)
        {
          cairo_move_to (cr, x + unit * strokes->x0, y + unit * strokes->y0);
          cairo_line_to (cr, x + unit * strokes->x1, y + unit * strokes->y1);
        }
      cairo_stroke (cr);
      x += unit * advance;
    }
  cairo_restore (cr);
}

/* Gravity as an arrow of fixed length in its direction, top left, with its
 * magnitude written beside it. */
static void render_gravity (cairo_t *cr, const carom_world *world)
{
  double gx = 0.0, gy = 0.0, g, cx = 32.0, cy = 30.0;
  char text[48];
  carom_world_get_gravity (world, &gx, &gy);
  g = hypot (gx, gy);
  render_panel (cr, 8.0, 8.0, 150.0, 44.0);
  cairo_set_source_rgb (cr, 0.45, 0.2, 0.6);
  cairo_set_line_width (cr, 2.0);
  if (g > 0.0 && isfinite (g))
    render_arrow (cr, cx - 0.5 * RENDER_GRAVITY_PX * gx / g, cy + 0.5 * RENDER_GRAVITY_PX * gy / g,
                  cx + 0.5 * RENDER_GRAVITY_PX * gx / g, cy - 0.5 * RENDER_GRAVITY_PX * gy / g, 9.0);
  else
    {
      cairo_arc (cr, cx, cy, 4.0, 0.0, 2.0 * RENDER_PI);
      cairo_stroke (cr);
    }
  snprintf (text, sizeof text, "g = %.3g", g);
  render_label (cr, 60.0, 24.0, text);
}

/* The restitution in effect, as a bar from 0 to 1: the highlighted body's,
 * else the mean over the dynamic bodies. */
static void render_restitution (cairo_t *cr, const render_options *opt, const carom_world *world)
{
  double e = 0.0, x = opt->width - 158.0, y = 8.0;
  int32_t count = 0, n, i;
  carom_body_id *ids;
  char text[48];
  if (opt->highlight_body_valid && carom_body_get_material (world, opt->highlight, &e, NULL) == CAROM_OK)
    count = 1;
  else
    {
      n = render_bodies (world, &ids);
      for (i = 0; i < n; ++i)
        {
          carom_body_type type = CAROM_STATIC;
          double ei;
          carom_body_get_type (world, ids[i], &type);
          if (type == CAROM_DYNAMIC && carom_body_get_material (world, ids[i], &ei, NULL) == CAROM_OK)
            e += ei, ++count;
        }
      free (ids);
      if (count)
        e /= count;
    }
  if (!count)
    return;
  render_panel (cr, x, y, 150.0, 44.0);
  cairo_rectangle (cr, x + 10.0, y + 26.0, 130.0, 8.0);
  cairo_set_source_rgb (cr, 0.85, 0.85, 0.85);
  cairo_fill (cr);
  cairo_rectangle (cr, x + 10.0, y + 26.0, 130.0 * fmin (1.0, fmax (0.0, e)), 8.0);
  cairo_set_source_rgb (cr, 0.15, 0.55, 0.35);
  cairo_fill (cr);
  snprintf (text, sizeof text, "e = %.2f", e);
  render_label (cr, x + 10.0, y + 8.0, text);
}

void render_world (cairo_t *cr, const carom_world *world, const render_options *opt)
{
  double scale, ox, oy, line, *xy = NULL;
  int32_t n, i, cap = 0;
  carom_body_id *ids = NULL;
  render_frame (opt, &scale, &ox, &oy);
  line = fmin (1.5, fmax (0.6, 0.025 * scale));

  cairo_save (cr);
  cairo_set_source_rgb (cr, 0.97, 0.965, 0.945);
  cairo_paint (cr);
  render_grid (cr, opt, scale);

  render_bodies_drawn (cr, opt, world, scale, line);
  n = render_bodies (world, &ids);
  if (opt->highlight_body_valid)
    render_highlight (cr, opt, world, &xy, &cap, scale);
  for (i = 0; i < n && opt->show_centroids; ++i)
    render_centroid (cr, opt, world, ids[i], scale);
  for (i = 0; i < n && opt->show_velocities; ++i)
    render_velocity (cr, opt, world, ids[i]);
  if (opt->show_contacts)
    render_contacts (cr, opt, world, scale);
  if (opt->show_gravity)
    render_gravity (cr, world);
  if (opt->show_restitution)
    render_restitution (cr, opt, world);
  free (ids);
  free (xy);
  cairo_restore (cr);
}
