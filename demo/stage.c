/* The stage: a world loaded from a scene file, stepped, drawn, destroyed,
 * and rebuilt when the demo changes what the API cannot change in place. */
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

/* Load `text` into a new world and find its walls. */
static carom_status stage_load (const char *path, const char *text, size_t length, carom_world **world,
                                walls *w, stage_scan *scan, char *message, size_t size)
{
  carom_scene_error error;
  carom_status s;
  memset (&error, 0, sizeof error);
  error.size = sizeof error;
  s = carom_scene_load_text (world, text, length, NULL, &error);
  if (s != CAROM_OK)
    {
      /* the library's message starts with "LINE: " when it has a line */
      if (error.message[0])
        snprintf (message, size, "%s:%s", path, error.message);
      else
        snprintf (message, size, "%s: %s", path, carom_status_string (s));
      return s;
    }
  stage_scan_text (scan, text, length);
  walls_init (w, *world, scan->has_bounds ? scan->bounds : NULL, scan->bounds_restitution, scan->bounds_friction);
  return CAROM_OK;
}

carom_status stage_init (stage *s, const char *path, char *message, size_t size)
{
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
  st = stage_load (path, text, length, &s->world, &s->walls, &scan, message, size);
  if (st != CAROM_OK)
    {
      g_free (text);
      return st;
    }
  s->path = g_strdup (path);
  s->text = text;
  s->length = length;
  s->restitution = scan.restitution;
  return CAROM_OK;
}

carom_status stage_update (stage *s, double dt)
{
  gint64 start = g_get_monotonic_time ();
  carom_status st = carom_world_update (s->world, dt);
  s->step_ms = 1e-3 * (double) (g_get_monotonic_time () - start);
  return st;
}

void stage_draw (const stage *s, cairo_t *cr, const render_options *opt)
{
  render_world (cr, s->world, opt);
}

void stage_destroy (stage *s)
{
  carom_world_destroy (s->world);
  g_free (s->path);
  g_free (s->text);
  memset (s, 0, sizeof *s);
}

/* ---------------------------------------------------------- restitution */

/* The ids of the bodies that are not walls, in creation order: the same
 * sequence in a world rebuilt from the same text. *ids must be freed. */
static int32_t stage_movers (const carom_world *world, const walls *w, carom_body_id **ids)
{
  int32_t n = carom_world_get_bodies (world, NULL, 0), i, m = 0;
  *ids = malloc (((size_t) n + 1) * sizeof **ids);
  if (!*ids)
    return -1;
  n = carom_world_get_bodies (world, *ids, n);
  for (i = 0; i < n; ++i)
    if (!walls_contains (w, (*ids)[i]))
      (*ids)[m++] = (*ids)[i];
  return m;
}

/* Copy the state of each body of `from` onto its twin in `to`. */
static carom_status stage_copy_bodies (const carom_world *from, const walls *wf, carom_world *to, const walls *wt,
                                       carom_body_id *held)
{
  carom_body_id *a = NULL, *b = NULL, moved = CAROM_NULL_BODY;
  int32_t na = stage_movers (from, wf, &a), nb = stage_movers (to, wt, &b), i;
  carom_status s = CAROM_OK;
  if (na < 0 || nb < 0)
    s = CAROM_ERR_OUT_OF_MEMORY;
  else if (na != nb)
    s = CAROM_ERR_BAD_ARGUMENT; /* the file changed under us */
  for (i = 0; s == CAROM_OK && i < na; ++i)
    {
      carom_body_type type = CAROM_STATIC;
      double x, y, angle, vx, vy, spin;
      if (held && *held == a[i])
        moved = b[i];
      carom_body_get_type (from, a[i], &type);
      if (type != CAROM_DYNAMIC)
        continue;
      carom_body_get_position (from, a[i], &x, &y);
      carom_body_get_angle (from, a[i], &angle);
      carom_body_get_velocity (from, a[i], &vx, &vy);
      carom_body_get_spin (from, a[i], &spin);
      carom_body_set_position (to, b[i], x, y);
      carom_body_set_angle (to, b[i], angle);
      carom_body_set_velocity (to, b[i], vx, vy);
      carom_body_set_spin (to, b[i], spin);
    }
  if (s == CAROM_OK && held)
    *held = moved;
  free (a);
  free (b);
  return s;
}

carom_status stage_set_restitution (stage *s, double e, carom_body_id *held, char *message, size_t size)
{
  char number[G_ASCII_DTOSTR_BUF_SIZE];
  carom_world *world = NULL;
  stage_scan scan;
  walls w;
  carom_status st;
  double gx = 0.0, gy = 0.0;
  GString *text;
  message[0] = '\0';
  if (!s->world)
    return CAROM_ERR_NULL_ARGUMENT;
  if (!(e >= 0.0 && e <= 1.0))
    return CAROM_ERR_BAD_ARGUMENT;
  /* a later setting overrides an earlier one: append ours (locale-free) */
  text = g_string_new_len (s->text, (gssize) s->length);
  g_string_append_printf (text, "\nrestitution %s\n", g_ascii_formatd (number, sizeof number, "%.6f", e));
  st = stage_load (s->path, text->str, text->len, &world, &w, &scan, message, size);
  g_string_free (text, TRUE);
  if (st == CAROM_OK && s->walls.present)
    st = walls_update (&w, world, s->walls.right, s->walls.top);
  if (st == CAROM_OK)
    st = stage_copy_bodies (s->world, &s->walls, world, &w, held);
  if (st == CAROM_OK)
    {
      carom_world_get_gravity (s->world, &gx, &gy);
      carom_world_set_gravity (world, gx, gy);
      st = carom_world_detect (world);
    }
  if (st != CAROM_OK)
    {
      carom_world_destroy (world);
      if (!message[0])
        snprintf (message, size, "%s: cannot rebuild the world: %s", s->path, carom_status_string (st));
      return st;
    }
  carom_world_destroy (s->world);
  s->world = world;
  s->walls = w;
  s->restitution = e;
  return CAROM_OK;
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
