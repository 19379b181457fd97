/* Status line and help overlay. */
#include "hud.h"

#include <string.h>

#include "carom.h"

#include <math.h>
#include <stdio.h>

void hud_init (hud *h, double now)
{
  h->step_ms = 0.0;
  h->fps = 0.0;
  h->frames = 0;
  h->since = now;
}

void hud_update (hud *h, double now)
{
  ++h->frames;
  if (now - h->since >= 0.5)
    {
      h->fps = h->frames / (now - h->since);
      h->frames = 0;
      h->since = now;
    }
}

void hud_step_time (hud *h, double ms)
{
  h->step_ms = h->step_ms > 0.0 ? 0.9 * h->step_ms + 0.1 * ms : ms;
}

static void hud_font (cairo_t *cr, double size, int bold)
{
  cairo_select_font_face (cr, "monospace", CAIRO_FONT_SLANT_NORMAL,
                          bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size (cr, size);
}

/* Energy with an SI-style suffix so the field keeps its width. */
static void hud_energy (char *buf, size_t size, double e)
{
  if (!isfinite (e))
    snprintf (buf, size, "-");
  else if (fabs (e) >= 1e6)
    snprintf (buf, size, "%.2fM", e / 1e6);
  else if (fabs (e) >= 1e4)
    snprintf (buf, size, "%.1fk", e / 1e3);
  else
    snprintf (buf, size, "%.1f", e);
}

void hud_draw_status (cairo_t *cr, const hud *h, const hud_status *st, double y, double width)
{
  char text[3][384], energy[32], rate[32], effects[128] = "";
  uint32_t bit;
  cairo_text_extents_t ext, help;
  double base = y + HUD_STATUS_HEIGHT - 8.0, room;
  int i;
  cairo_save (cr);
  cairo_rectangle (cr, 0, y, width, HUD_STATUS_HEIGHT);
  cairo_set_source_rgb (cr, 0.16, 0.17, 0.19);
  cairo_fill (cr);

  hud_energy (energy, sizeof energy, st->energy);
  if (st->paused)
    snprintf (rate, sizeof rate, "PAUSED");
  else
    snprintf (rate, sizeof rate, "%3.0f fps", h->fps);
  /* the effect stages the world runs, by their short names */
  for (bit = CAROM_EFFECT_CENTRAL_GRAVITY; bit <= CAROM_EFFECT_CONTINUOUS; bit <<= 1)
    if ((st->effects & bit) && bit != CAROM_EFFECT_RESTITUTION)
      {
        strncat (effects, " ", sizeof effects - strlen (effects) - 1);
        strncat (effects, carom_effect_name ((carom_effect) bit), sizeof effects - strlen (effects) - 1);
      }
  /* the longest form that fits beside "h: help": a narrow window or many
   * effects drop the words, then gravity, then the scene's name */
  snprintf (text[0], sizeof text[0], "%s  %d bodies  %d contacts  %6.2f ms/step  %s  KE %s  e %.2f  g (%.3g, %.3g)%s%s",
            st->scene, st->bodies, st->contacts, h->step_ms, rate, energy, st->restitution, st->gx, st->gy,
            effects, st->holding ? "  holding" : "");
  snprintf (text[1], sizeof text[1], "%s  %d b  %d c  %.2f ms  %s  KE %s  e %.2f %s%s", st->scene, st->bodies,
            st->contacts, h->step_ms, rate, energy, st->restitution, effects, st->holding ? "  holding" : "");
  snprintf (text[2], sizeof text[2], "%d b  %d c  %.2f ms  %s  KE %s %s", st->bodies, st->contacts, h->step_ms,
            rate, energy, effects);
  hud_font (cr, 12.0, 0);
  cairo_text_extents (cr, "h: help", &help);
  room = width - help.x_advance - 32.0;
  for (i = 0; i < 2; ++i)
    {
      cairo_text_extents (cr, text[i], &ext);
      if (ext.x_advance <= room)
        break;
    }
  cairo_set_source_rgb (cr, 0.90, 0.91, 0.88);
  cairo_move_to (cr, 8.0, base);
  cairo_show_text (cr, text[i]);

  if (width - help.x_advance - 8.0 > 8.0)
    {
      cairo_rectangle (cr, width - help.x_advance - 16.0, y, help.x_advance + 16.0, HUD_STATUS_HEIGHT);
      cairo_set_source_rgb (cr, 0.16, 0.17, 0.19);
      cairo_fill (cr);
      cairo_set_source_rgb (cr, 0.62, 0.64, 0.60);
      cairo_move_to (cr, width - help.x_advance - 8.0, base);
      cairo_show_text (cr, "h: help");
    }
  cairo_restore (cr);
}

static const char *const hud_help_lines[][2] = {
  { "1 ... 7", "scenes: thesis balls pyramid rain gas platform compound" },
  { "8 9 0", "scenes: pendulum bridge ragdoll" },
  { "n p", "next / previous scene (after 0: car)" },
  { "arrows", "change gravity" },
  { "g", "show the gravity vector" },
  { "+ - PgUp PgDn", "restitution up / down" },
  { "space", "pause / run" },
  { ".", "one step while paused" },
  { "v", "velocity arrows" },
  { "c", "contact points and normals" },
  { "j", "joints: anchors and bodies' centres" },
  { "r", "restart the scene" },
  { "f", "friction on / off (world default 0.5)" },
  { "d", "damping on / off" },
  { "o", "central gravity (orbit the view's centre)" },
  { "s", "sleeping on / off" },
  { "t", "continuous collision on / off (no tunnelling)" },
  { "h", "this help" },
  { "q Esc", "quit" },
  { "mouse", "drag a body (a mouse joint), release to throw" },
};

void hud_draw_help (cairo_t *cr, double width, double height)
{
  int n = (int) (sizeof hud_help_lines / sizeof hud_help_lines[0]), i;
  double line = 19.0, key_w = 0.0, text_w = 0.0, w, h, x, y, r = 8.0, pi = 3.14159265358979323846;
  cairo_text_extents_t ext;
  cairo_save (cr);
  for (i = 0; i < n; ++i)
    {
      hud_font (cr, 12.5, 1);
      cairo_text_extents (cr, hud_help_lines[i][0], &ext);
      key_w = fmax (key_w, ext.x_advance);
      hud_font (cr, 12.5, 0);
      cairo_text_extents (cr, hud_help_lines[i][1], &ext);
      text_w = fmax (text_w, ext.x_advance);
    }
  key_w += 20.0;
  w = 36.0 + key_w + text_w;
  h = 48.0 + n * line;
  x = floor (0.5 * (width - w));
  y = floor (0.5 * (height - h));
  cairo_new_sub_path (cr);
  cairo_arc (cr, x + w - r, y + r, r, -0.5 * pi, 0.0);
  cairo_arc (cr, x + w - r, y + h - r, r, 0.0, 0.5 * pi);
  cairo_arc (cr, x + r, y + h - r, r, 0.5 * pi, pi);
  cairo_arc (cr, x + r, y + r, r, pi, 1.5 * pi);
  cairo_close_path (cr);
  cairo_set_source_rgba (cr, 0.12, 0.13, 0.15, 0.88);
  cairo_fill (cr);

  hud_font (cr, 14.0, 1);
  cairo_set_source_rgb (cr, 1.0, 1.0, 1.0);
  cairo_move_to (cr, x + 18.0, y + 28.0);
  cairo_show_text (cr, "carom demo: keys");
  for (i = 0; i < n; ++i)
    {
      double ty = y + 52.0 + i * line;
      hud_font (cr, 12.5, 1);
      cairo_set_source_rgb (cr, 1.0, 0.80, 0.45);
      cairo_move_to (cr, x + 18.0, ty);
      cairo_show_text (cr, hud_help_lines[i][0]);
      hud_font (cr, 12.5, 0);
      cairo_set_source_rgb (cr, 0.92, 0.92, 0.90);
      cairo_move_to (cr, x + 18.0 + key_w, ty);
      cairo_show_text (cr, hud_help_lines[i][1]);
    }
  cairo_restore (cr);
}
