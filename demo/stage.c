/* The stage: a world loaded from a scene file, stepped, drawn, destroyed. */
#include "stage.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <glib.h>

/* ------------------------------------------------------------ scanning */

/* What the demo reads from the text itself (the library has already
 * checked it): the last `restitution` setting and the first `bounds` line
 * with its own material options. */
typedef struct stage_scan {
  double restitution;
  int has_bounds;
  double bounds[4];
  double bounds_restitution, bounds_friction;
} stage_scan;

#define STAGE_MAX_TOKENS 16

/* Split one line (up to a '#') into at most STAGE_MAX_TOKENS tokens. */
static int stage_split (const char *line, size_t len, char *buf, size_t cap, char **tok)
{
  size_t n = len < cap - 1 ? len : cap - 1;
  int count = 0;
  char *c;
  memcpy (buf, line, n);
  buf[n] = '\0';
  c = strchr (buf, '#');
  if (c)
    *c = '\0';
  for (c = buf; *c && count < STAGE_MAX_TOKENS;)
    {
      while (*c == ' ' || *c == '\t' || *c == '\v' || *c == '\f')
        ++c;
      if (!*c)
        break;
      tok[count++] = c;
      while (*c && *c != ' ' && *c != '\t' && *c != '\v' && *c != '\f')
        ++c;
      if (*c)
        *c++ = '\0';
    }
  return count;
}

static void stage_scan_line (stage_scan *scan, char **tok, int count)
{
  int k;
  if (count == 2 && strcmp (tok[0], "restitution") == 0)
    scan->restitution = g_ascii_strtod (tok[1], NULL);
  if (count >= 5 && strcmp (tok[0], "bounds") == 0 && !scan->has_bounds)
    {
      scan->has_bounds = 1;
      for (k = 0; k < 4; ++k)
        scan->bounds[k] = g_ascii_strtod (tok[1 + k], NULL);
      for (k = 5; k + 1 < count; ++k)
        if (strcmp (tok[k], "restitution") == 0)
          scan->bounds_restitution = g_ascii_strtod (tok[++k], NULL);
        else if (strcmp (tok[k], "friction") == 0)
          scan->bounds_friction = g_ascii_strtod (tok[++k], NULL);
    }
}

static void stage_scan_text (stage_scan *scan, const char *text, size_t length)
{
  char buf[1024], *tok[STAGE_MAX_TOKENS];
  size_t at = 0;
  memset (scan, 0, sizeof *scan);
  scan->restitution = 0.0; /* carom_world_def_init's */
  scan->bounds_restitution = scan->bounds_friction = -1.0;
  while (at < length)
    {
      size_t end = at;
      while (end < length && text[end] != '\n' && text[end] != '\r')
        ++end;
      stage_scan_line (scan, tok, stage_split (text + at, end - at, buf, sizeof buf, tok));
      at = end + 1;
    }
}

/* ------------------------------------------------------------ lifecycle */

carom_status stage_init (stage *s, const char *path, char *message, size_t size)
{
  carom_scene_error error;
  GError *gerror = NULL;
  stage_scan scan;
  gchar *text = NULL;
  gsize length = 0;
  carom_status st;
  memset (s, 0, sizeof *s);
  if (!g_file_get_contents (path, &text, &length, &gerror))
    {
      snprintf (message, size, "%s: cannot read: %s", path, gerror ? gerror->message : "unknown error");
      g_clear_error (&gerror);
      return CAROM_ERR_IO;
    }
  memset (&error, 0, sizeof error);
  error.size = sizeof error;
  st = carom_scene_load_text (&s->world, text, length, NULL, &error);
  if (st != CAROM_OK)
    {
      /* the library's message starts with "LINE: " when it has a line */
      if (error.message[0])
        snprintf (message, size, "%s:%s", path, error.message);
      else
        snprintf (message, size, "%s: %s", path, carom_status_string (st));
      g_free (text);
      return st;
    }
  stage_scan_text (&scan, text, length);
  g_free (text);
  walls_init (&s->walls, s->world, scan.has_bounds ? scan.bounds : NULL, scan.bounds_restitution,
              scan.bounds_friction);
  s->path = g_strdup (path);
  s->restitution = scan.restitution;
  return CAROM_OK;
}

/* The sensor events of the last update: how many bodies are inside each
 * sensor. */
static void stage_follow_sensors (stage *s)
{
  carom_contact_event ev[64];
  int32_t n = carom_world_get_events (s->world, ev, 64), i, k;
  for (i = 0; i < n && i < 64; ++i)
    {
      int d = ev[i].type == CAROM_EVENT_SENSOR_BEGIN ? 1 : ev[i].type == CAROM_EVENT_SENSOR_END ? -1 : 0;
      if (d == 0)
        continue;
      for (k = 0; k < s->sensor_count && s->sensors[k] != ev[i].a; ++k)
        ;
      if (k == s->sensor_count)
        {
          if (k == STAGE_MAX_SENSORS)
            continue;
          s->sensors[k] = ev[i].a;
          s->inside[k] = 0;
          s->sensor_count++;
        }
      s->inside[k] += d;
    }
}

carom_status stage_update (stage *s, double dt)
{
  gint64 start = g_get_monotonic_time ();
  carom_status st = carom_world_update (s->world, dt);
  s->step_ms = 1e-3 * (double) (g_get_monotonic_time () - start);
  if (st == CAROM_OK)
    stage_follow_sensors (s);
  return st;
}

void stage_draw (const stage *s, cairo_t *cr, const render_options *opt)
{
  render_options o = *opt;
  carom_body_id lit[STAGE_MAX_SENSORS];
  int32_t k;
  o.lit = lit;
  o.lit_count = 0;
  for (k = 0; k < s->sensor_count; ++k)
    if (s->inside[k] > 0)
      lit[o.lit_count++] = s->sensors[k];
  render_world (cr, s->world, &o);
}

void stage_destroy (stage *s)
{
  carom_world_destroy (s->world);
  g_free (s->path);
  memset (s, 0, sizeof *s);
}

carom_status stage_set_restitution (stage *s, double e)
{
  carom_status st = carom_world_set_restitution (s->world, e);
  if (st == CAROM_OK)
    s->restitution = e;
  return st;
}

double stage_kinetic_energy (const stage *s)
{
  carom_body_id *ids;
  double energy = 0.0;
  int32_t n = carom_world_get_bodies (s->world, NULL, 0), i;
  ids = malloc (((size_t) n + 1) * sizeof *ids);
  if (!ids)
    return NAN;
  n = carom_world_get_bodies (s->world, ids, n);
  for (i = 0; i < n; ++i)
    {
      double m = 0.0, inertia = 0.0, vx = 0.0, vy = 0.0, spin = 0.0;
      carom_body_get_mass (s->world, ids[i], &m, &inertia, NULL);
      if (m <= 0.0)
        continue;
      carom_body_get_velocity (s->world, ids[i], &vx, &vy);
      carom_body_get_spin (s->world, ids[i], &spin);
      energy += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * spin * spin;
    }
  free (ids);
  return energy;
}
