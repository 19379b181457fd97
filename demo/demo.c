/* The demo's state machine: scenes, view, stepping and painting, with the
 * GTK signal handlers (main.c) and the key bindings (controls.c) as thin
 * layers on top. */
#include "demo.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <glib.h>

double demo_now (void)
{
  return 1e-6 * (double) g_get_monotonic_time ();
}

/* The area the world is drawn in: the drawing area less the status line. */
static void demo_area (const demo *d, int *w, int *h)
{
  *w = d->width > 1 ? d->width : 1;
  *h = d->height - HUD_STATUS_HEIGHT > 1 ? d->height - HUD_STATUS_HEIGHT : 1;
}

/* The view: the scene's bodies at start (plus however far the walls have
 * moved since), grown on its short side to the area's aspect ratio. */
static void demo_fit (demo *d)
{
  double x0 = d->base_view[0], y0 = d->base_view[1], x1 = d->base_view[2], y1 = d->base_view[3], want, have;
  int w, h;
  demo_area (d, &w, &h);
  if (d->stage.walls.present)
    {
      x1 += d->stage.walls.right - d->stage.walls.x1;
      y1 += d->stage.walls.top - d->stage.walls.y1;
    }
  want = (double) w / h;
  have = (x1 - x0) / (y1 - y0);
  if (have < want)
    {
      double grow = 0.5 * ((y1 - y0) * want - (x1 - x0));
      x0 -= grow, x1 += grow;
    }
  else
    {
      double grow = 0.5 * ((x1 - x0) / want - (y1 - y0));
      y0 -= grow, y1 += grow;
    }
  d->opt.width = w, d->opt.height = h;
  d->opt.view_x0 = x0, d->opt.view_y0 = y0;
  d->opt.view_x1 = x1, d->opt.view_y1 = y1;
  if (d->verbose)
    {
      printf ("carom-demo: view %.6g %.6g %.6g %.6g in %dx%d px\n", x0, y0, x1, y1, w, h);
      fflush (stdout);
    }
}

/* Remember the layout at scene start. */
static void demo_base (demo *d)
{
  render_options fit;
  memset (&fit, 0, sizeof fit); /* height 0: the bodies' box plus margin */
  render_fit_view (&fit, d->stage.world);
  d->base_view[0] = fit.view_x0, d->base_view[1] = fit.view_y0;
  d->base_view[2] = fit.view_x1, d->base_view[3] = fit.view_y1;
  d->base_width = d->width, d->base_height = d->height;
  demo_fit (d);
  d->base_scale = d->opt.width / (d->opt.view_x1 - d->opt.view_x0);
}

/* "thesis" for a table scene, the file's base name without .scene else. */
static char *demo_scene_name (const scene_entry *e, const char *path)
{
  char *base;
  if (e->file)
    return g_strdup (e->name);
  base = g_path_get_basename (path);
  if (g_str_has_suffix (base, ".scene") && strlen (base) > 6)
    base[strlen (base) - 6] = '\0';
  return base;
}

int demo_load (demo *d, const scene_entry *e, const char *path)
{
  char message[512];
  stage next;
  if (e->init (&next, path, message, sizeof message) != CAROM_OK)
    {
      fprintf (stderr, "%s\n", message);
      return 0;
    }
  if (d->entry)
    d->entry->destroy (&d->stage);
  g_free (d->path);
  g_free (d->name);
  d->stage = next;
  d->entry = e;
  d->path = g_strdup (path);
  d->name = demo_scene_name (e, path);
  grab_init (&d->grab);
  hud_init (&d->hud, demo_now ());
  carom_world_detect (d->stage.world); /* contacts to show before the first step */
  demo_base (d);
  return 1;
}

int demo_init (demo *d, const scene_entry *e, const char *path, int width, int height)
{
  memset (d, 0, sizeof *d);
  d->width = width, d->height = height;
  /* as render_options_init: centroids, contacts and joints shown, vectors
   * hidden */
  d->opt.show_centroids = 1;
  d->opt.show_contacts = 1;
  d->opt.show_joints = 1;
  grab_init (&d->grab);
  hud_init (&d->hud, demo_now ());
  return demo_load (d, e, path);
}

int demo_restart (demo *d)
{
  char *path = g_strdup (d->path);
  int ok = demo_load (d, d->entry, path);
  g_free (path);
  return ok;
}

void demo_resize (demo *d, int width, int height)
{
  walls *w = &d->stage.walls;
  d->width = width, d->height = height;
  if (!d->entry)
    return;
  if (!d->sized)
    {
      /* the window's first real size, whatever a window manager made of
         the one asked for: the scene starts as its file has it */
      d->sized = 1;
      demo_base (d);
      return;
    }
  if (w->present && d->base_scale > 0.0)
    {
      double right = w->x1 + fmax (0.0, (width - d->base_width) / d->base_scale);
      double top = w->y1 + fmax (0.0, (height - d->base_height) / d->base_scale);
      if (walls_update (w, d->stage.world, right, top) == CAROM_OK && d->paused)
        carom_world_detect (d->stage.world);
    }
  demo_fit (d);
}

void demo_update (demo *d)
{
  carom_status s;
  if (!d->entry)
    return;
  grab_update (&d->grab, d->stage.world);
  s = d->entry->update (&d->stage, DEMO_DT);
  if (s != CAROM_OK)
    {
      fprintf (stderr, "carom-demo: %s: update failed: %s; pausing\n", d->name, carom_status_string (s));
      d->paused = 1;
      return;
    }
  hud_step_time (&d->hud, d->stage.step_ms);
}

int demo_overlays (const demo *d, double now)
{
  return (now < d->gravity_until ? 1 : 0) | (now < d->restitution_until ? 2 : 0);
}

void demo_draw (demo *d, cairo_t *cr, int width, int height)
{
  double now = demo_now (), gx = 0.0, gy = 0.0;
  int overlays = demo_overlays (d, now);
  hud_status st;
  if (width != d->width || height != d->height)
    demo_resize (d, width, height);
  cairo_save (cr);
  cairo_set_source_rgb (cr, 0.16, 0.17, 0.19);
  cairo_paint (cr);
  cairo_restore (cr);
  if (!d->entry)
    return;
  hud_update (&d->hud, now);
  d->opt.show_gravity = d->show_gravity || (overlays & 1);
  d->opt.show_restitution = (overlays & 2) != 0;
  d->opt.highlight_body_valid = d->grab.body != CAROM_NULL_BODY;
  d->opt.highlight = d->grab.body;

  cairo_save (cr);
  cairo_rectangle (cr, 0, 0, d->opt.width, d->opt.height);
  cairo_clip (cr);
  d->entry->draw (&d->stage, cr, &d->opt);
  if (d->show_help)
    hud_draw_help (cr, d->opt.width, d->opt.height);
  cairo_restore (cr);

  carom_world_get_gravity (d->stage.world, &gx, &gy);
  st.scene = d->name;
  st.bodies = carom_world_body_count (d->stage.world);
  st.contacts = carom_world_contact_count (d->stage.world);
  st.energy = stage_kinetic_energy (&d->stage);
  st.gx = gx, st.gy = gy;
  st.restitution = d->stage.restitution;
  st.paused = d->paused;
  st.holding = d->grab.body != CAROM_NULL_BODY;
  st.effects = carom_world_get_effects (d->stage.world);
  hud_draw_status (cr, &d->hud, &st, height - HUD_STATUS_HEIGHT, width);
}

void demo_change_gravity (demo *d, double dx, double dy)
{
  double gx = 0.0, gy = 0.0;
  if (!d->entry)
    return;
  carom_world_get_gravity (d->stage.world, &gx, &gy);
  gx += dx, gy += dy;
  /* land on zero exactly rather than on 1e-16 */
  if (fabs (gx) < 1e-9)
    gx = 0.0;
  if (fabs (gy) < 1e-9)
    gy = 0.0;
  carom_world_set_gravity (d->stage.world, gx, gy);
  d->gravity_until = demo_now () + DEMO_OVERLAY_TIME;
}

void demo_change_restitution (demo *d, double delta)
{
  carom_status s;
  double e;
  if (!d->entry)
    return;
  e = floor (100.0 * (d->stage.restitution + delta) + 0.5) / 100.0;
  e = fmin (1.0, fmax (0.0, e));
  d->restitution_until = demo_now () + DEMO_OVERLAY_TIME;
  s = stage_set_restitution (&d->stage, e);
  if (s != CAROM_OK)
    fprintf (stderr, "carom-demo: restitution %.2f: %s\n", e, carom_status_string (s));
}

void demo_toggle_effect (demo *d, carom_effect effect)
{
  carom_world *w = d->stage.world;
  int on;
  if (!d->entry || !w)
    return;
  on = (carom_world_get_effects (w) & (uint32_t) effect) != 0;
  switch (effect)
    {
    case CAROM_EFFECT_FRICTION:
      carom_world_set_friction (w, on ? 0.0 : 0.5);
      break;
    case CAROM_EFFECT_DAMPING:
      carom_world_set_damping (w, on ? 0.0 : 0.5, on ? 0.0 : 0.5);
      break;
    case CAROM_EFFECT_SLEEPING:
      carom_world_set_sleeping (w, !on);
      break;
    case CAROM_EFFECT_CONTINUOUS:
      carom_world_set_continuous (w, !on);
      break;
    case CAROM_EFFECT_CENTRAL_GRAVITY:
      {
        /* a pull towards the view's centre strong enough to orbit in a few
         * seconds: gm = (size / 2)^3 (2 pi / 4 s)^2 */
        double cx = 0.5 * (d->opt.view_x0 + d->opt.view_x1), cy = 0.5 * (d->opt.view_y0 + d->opt.view_y1);
        double r = 0.25 * (d->opt.view_x1 - d->opt.view_x0);
        carom_world_set_central_gravity (w, cx, cy, on ? 0.0 : r * r * r * 2.47, on ? 0.0 : 0.1 * r);
        break;
      }
    default:
      break;
    }
}

void demo_destroy (demo *d)
{
  if (d->entry)
    d->entry->destroy (&d->stage);
  g_free (d->path);
  g_free (d->name);
  memset (d, 0, sizeof *d);
}
