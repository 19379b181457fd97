/* carom: the headless runner. Loads a scene file, steps it without a display
 * and reports one line of key=value numbers, optionally a CSV trace of the
 * bodies and a PNG or SVG of the last frame (usage: docs/scenes.md). Exit
 * status: 0 done, 1 the scene or a file failed, 2 bad command line. */
#define _POSIX_C_SOURCE 200809L

#include <cairo-svg.h>
#include <cairo.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "carom.h"
#include "render.h"

#define RUNNER_MAX_WIDTH 16384
#define RUNNER_BAND 60 /* pixels above the scene for the overlays */

static const char runner_usage[] =
  "usage: carom run FILE [options]   load FILE, step it, print one line of key=value results\n"
  "       carom check FILE           only validate FILE\n"
  "       carom --help\n"
  "\n"
  "run options:\n"
  "  --steps N       number of steps (default 600)\n"
  "  --dt S          time step (default 1/60)\n"
  "  --substeps K    sub-steps per step, overriding the scene's\n"
  "  --csv OUT       write the final state as CSV to OUT ('-' = standard output)\n"
  "  --every K       with --csv: also every K-th step (from step 0), with a step column\n"
  "  --png OUT.png   draw the final frame as PNG\n"
  "  --svg OUT.svg   draw the final frame as SVG\n"
  "  --width PX      picture width (default 800); the height follows the scene\n"
  "\n"
  "output keys: bodies joints steps dt ms_per_step energy_start energy_end\n"
  "kinetic_start kinetic_end momentum_x momentum_y angular_momentum max_penetration\n"
  "contacts nan effects\n"
  "(energy = kinetic + gravitational potential; see docs/scenes.md)\n";

typedef struct runner_args {
  const char *command, *file;
  long steps;
  double dt;
  long substeps; /* 0: the scene's */
  const char *csv, *png, *svg;
  long every;    /* 0: final state only */
  long width;
} runner_args;

typedef struct runner_totals {
  double kinetic, potential;
  double px, py, l;
  int finite;
} runner_totals;

/* ---------------------------------------------------------- command line */

static int runner_bad_usage (const char *fmt, const char *arg)
{
  fprintf (stderr, "carom: ");
  fprintf (stderr, fmt, arg);
  fprintf (stderr, "\n(see carom --help)\n");
  return 2;
}

static int runner_parse_long (const char *name, const char *s, long lo, long hi, long *out)
{
  char *end;
  long v;
  errno = 0;
  v = strtol (s, &end, 10);
  if (end == s || *end || errno == ERANGE || v < lo || v > hi)
    {
      fprintf (stderr, "carom: %s wants a whole number from %ld to %ld, got '%s'\n(see carom --help)\n", name, lo,
               hi, s);
      return 2;
    }
  *out = v;
  return 0;
}

static int runner_parse_dt (const char *s, double *out)
{
  char *end;
  double v = strtod (s, &end);
  if (end == s || *end || !isfinite (v) || v <= 0.0)
    return runner_bad_usage ("--dt wants a positive number, got '%s'", s);
  *out = v;
  return 0;
}

/* Options take their value as the next argument or after '='. */
static int runner_parse (int argc, char **argv, runner_args *a)
{
  int i;
  memset (a, 0, sizeof *a);
  a->command = argv[1];
  a->steps = 600;
  a->dt = 1.0 / 60.0;
  a->width = 800;
  for (i = 2; i < argc; ++i)
    {
      const char *arg = argv[i], *value = NULL, *eq;
      char name[32];
      size_t len;
      int rc = 0;
      if (arg[0] != '-' || arg[1] == '\0')
        {
          if (a->file)
            return runner_bad_usage ("more than one scene file: '%s'", arg);
          a->file = arg;
          continue;
        }
      if (strcmp (a->command, "run") != 0)
        return runner_bad_usage ("'check' takes no options: '%s'", arg);
      eq = strchr (arg, '=');
      len = eq ? (size_t) (eq - arg) : strlen (arg);
      if (len >= sizeof name)
        return runner_bad_usage ("unknown option '%s'", arg);
      memcpy (name, arg, len);
      name[len] = '\0';
      if (strcmp (name, "--steps") && strcmp (name, "--dt") && strcmp (name, "--substeps") && strcmp (name, "--csv")
          && strcmp (name, "--every") && strcmp (name, "--png") && strcmp (name, "--svg") && strcmp (name, "--width"))
        return runner_bad_usage ("unknown option '%s'", arg);
      if (eq)
        value = eq + 1;
      else if (i + 1 < argc)
        value = argv[++i];
      else
        return runner_bad_usage ("%s needs a value", name);
      if (!strcmp (name, "--steps"))
        rc = runner_parse_long (name, value, 0, 1000000000L, &a->steps);
      else if (!strcmp (name, "--dt"))
        rc = runner_parse_dt (value, &a->dt);
      else if (!strcmp (name, "--substeps"))
        rc = runner_parse_long (name, value, 1, 1000000L, &a->substeps);
      else if (!strcmp (name, "--every"))
        rc = runner_parse_long (name, value, 1, 1000000000L, &a->every);
      else if (!strcmp (name, "--width"))
        rc = runner_parse_long (name, value, 16, RUNNER_MAX_WIDTH, &a->width);
      else if (!*value)
        return runner_bad_usage ("%s needs a file name", name);
      else if (!strcmp (name, "--csv"))
        a->csv = value;
      else if (!strcmp (name, "--png"))
        a->png = value;
      else
        a->svg = value;
      if (rc)
        return rc;
    }
  if (!a->file)
    return runner_bad_usage ("%s needs a scene FILE", a->command);
  if (a->every && !a->csv)
    return runner_bad_usage ("%s needs --csv", "--every");
  return 0;
}

/* ---------------------------------------------------------------- loading */

/* The file's bytes, with room to append a line; NULL and a message on
 * failure. */
static char *runner_read (const char *path, size_t extra, size_t *length)
{
  FILE *f = fopen (path, "rb");
  char *text = NULL;
  size_t len = 0, cap = 0;
  if (!f)
    {
      fprintf (stderr, "%s: cannot open: %s\n", path, strerror (errno));
      return NULL;
    }
  for (;;)
    {
      size_t got;
      if (cap - len < 4096 + extra)
        {
          char *t = realloc (text, cap = 2 * cap + 4096 + extra);
          if (!t)
            {
              fprintf (stderr, "%s: out of memory\n", path);
              break;
            }
          text = t;
        }
      got = fread (text + len, 1, cap - len - extra, f);
      len += got;
      if (got == 0)
        {
          if (!ferror (f))
            {
              fclose (f);
              *length = len;
              return text;
            }
          fprintf (stderr, "%s: cannot read: %s\n", path, strerror (errno));
          break;
        }
    }
  fclose (f);
  free (text);
  return NULL;
}

/* Load FILE; --substeps is appended as a last `substeps` line, which
 * overrides the scene's (a later setting wins). Errors as FILE:LINE: ... */
static carom_world *runner_load (const runner_args *a)
{
  char override[64] = "";
  carom_scene_error err;
  carom_world *world = NULL;
  size_t len = 0, extra;
  char *text;
  if (a->substeps)
    snprintf (override, sizeof override, "\nsubsteps %ld\n", a->substeps);
  extra = strlen (override);
  text = runner_read (a->file, extra, &len);
  if (!text)
    return NULL;
  memcpy (text + len, override, extra);
  err.size = sizeof err;
  if (carom_scene_load_text (&world, text, len + extra, NULL, &err) != CAROM_OK)
    {
      if (err.line > 0)
        fprintf (stderr, "%s:%s\n", a->file, err.message);
      else
        fprintf (stderr, "%s: %s\n", a->file, err.message);
    }
  free (text);
  return world;
}

/* ---------------------------------------------------------------- numbers */

static void runner_totals_of (const carom_world *w, const carom_body_id *ids, int32_t n, runner_totals *t)
{
  double gx = 0.0, gy = 0.0;
  int32_t i;
  memset (t, 0, sizeof *t);
  t->finite = 1;
  carom_world_get_gravity (w, &gx, &gy);
  for (i = 0; i < n; ++i)
    {
      double x = 0, y = 0, a = 0, vx = 0, vy = 0, s = 0, m = 0, inertia = 0;
      carom_body_get_position (w, ids[i], &x, &y);
      carom_body_get_angle (w, ids[i], &a);
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      carom_body_get_spin (w, ids[i], &s);
      carom_body_get_mass (w, ids[i], &m, &inertia, NULL);
      if (!isfinite (x) || !isfinite (y) || !isfinite (a) || !isfinite (vx) || !isfinite (vy) || !isfinite (s))
        t->finite = 0;
      t->kinetic += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * s * s;
      t->potential -= m * (gx * x + gy * y); /* zero for statics: m = 0 */
      t->px += m * vx;
      t->py += m * vy;
      t->l += m * (x * vy - y * vx) + inertia * s;
    }
}

static double runner_max_depth (const carom_world *w, double deepest)
{
  int32_t n = carom_world_contact_count (w), i;
  for (i = 0; i < n; ++i)
    {
      double d;
      if (carom_world_get_contact (w, i, NULL, NULL, NULL, NULL, NULL, NULL, &d) == CAROM_OK && d > deepest)
        deepest = d;
    }
  return deepest;
}

static double runner_now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* -------------------------------------------------------------------- CSV */

/* Rows of the bodies' state; with step >= 0 a leading step column. Ids are
 * the bodies' places in creation order (file order), stable across runs. */
static void runner_csv_rows (FILE *f, const carom_world *w, const carom_body_id *ids, int32_t n, long step)
{
  int32_t i;
  for (i = 0; i < n; ++i)
    {
      double x = 0, y = 0, a = 0, vx = 0, vy = 0, s = 0, m = 0, inertia = 0;
      carom_shape_kind kind = CAROM_SHAPE_POLYGON;
      carom_body_get_position (w, ids[i], &x, &y);
      carom_body_get_angle (w, ids[i], &a);
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      carom_body_get_spin (w, ids[i], &s);
      carom_body_get_mass (w, ids[i], &m, &inertia, NULL);
      carom_body_get_shape (w, ids[i], &kind, NULL);
      if (step >= 0)
        fprintf (f, "%ld,", step);
      fprintf (f, "%ld,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", (long) i,
               kind == CAROM_SHAPE_CIRCLE ? "circle" : kind == CAROM_SHAPE_COMPOUND ? "compound" : "polygon", x, y, a,
               vx, vy, s, m, inertia);
    }
}

static void runner_csv_header (FILE *f, int with_step)
{
  fprintf (f, "%sid,kind,x,y,angle,vx,vy,spin,mass,inertia\n", with_step ? "step," : "");
}

/* --------------------------------------------------------------- pictures */

static int runner_draw (const runner_args *a, const carom_world *w, const char *path, int svg)
{
  render_options opt;
  cairo_surface_t *surface;
  cairo_t *cr;
  cairo_status_t st;
  double aspect;
  int height;
  render_options_init (&opt, w, (int) a->width, 0);
  aspect = (opt.view_y1 - opt.view_y0) / (opt.view_x1 - opt.view_x0);
  height = (int) lround (a->width * (isfinite (aspect) ? aspect : 1.0));
  height = height < 16 ? 16 : height > RUNNER_MAX_WIDTH ? RUNNER_MAX_WIDTH : height;
  /* a band on top for the gravity and restitution overlays, so they never
   * cover the scene */
  opt.view_y1 += RUNNER_BAND * (opt.view_x1 - opt.view_x0) / a->width;
  opt.height = height + RUNNER_BAND;
  opt.show_velocities = 1;
  opt.show_gravity = 1;
  opt.show_restitution = 1;
  if (svg)
    surface = cairo_svg_surface_create (path, opt.width, opt.height);
  else
    surface = cairo_image_surface_create (CAIRO_FORMAT_ARGB32, opt.width, opt.height);
  cr = cairo_create (surface);
  render_world (cr, w, &opt);
  cairo_destroy (cr);
  if (svg)
    cairo_surface_finish (surface);
  st = cairo_surface_status (surface);
  if (st == CAIRO_STATUS_SUCCESS && !svg)
    st = cairo_surface_write_to_png (surface, path);
  cairo_surface_destroy (surface);
  /* drop cairo's font caches, so Valgrind sees every block freed */
  cairo_debug_reset_static_data ();
  if (st != CAIRO_STATUS_SUCCESS)
    {
      fprintf (stderr, "%s: cannot write: %s\n", path, cairo_status_to_string (st));
      return 1;
    }
  return 0;
}

/* -------------------------------------------------------------- commands */

static int runner_check (const runner_args *a)
{
  carom_world *w = runner_load (a);
  if (!w)
    return 1;
  printf ("%s: ok\n", a->file);
  carom_world_destroy (w);
  return 0;
}

static int runner_run (const runner_args *a)
{
  carom_world *w = runner_load (a);
  carom_body_id *ids;
  FILE *csv = NULL;
  runner_totals start, end;
  double seconds = 0.0, deepest = 0.0;
  int32_t n;
  long step;
  int rc = 0;
  if (!w)
    return 1;
  n = carom_world_get_bodies (w, NULL, 0);
  ids = malloc (((size_t) n + 1) * sizeof *ids);
  if (!ids)
    {
      fprintf (stderr, "carom: out of memory\n");
      carom_world_destroy (w);
      return 1;
    }
  n = carom_world_get_bodies (w, ids, n);
  if (a->csv)
    {
      csv = strcmp (a->csv, "-") == 0 ? stdout : fopen (a->csv, "w");
      if (!csv)
        {
          fprintf (stderr, "%s: cannot open: %s\n", a->csv, strerror (errno));
          free (ids);
          carom_world_destroy (w);
          return 1;
        }
      runner_csv_header (csv, a->every > 0);
      if (a->every)
        runner_csv_rows (csv, w, ids, n, 0);
    }

  runner_totals_of (w, ids, n, &start);
  for (step = 1; step <= a->steps; ++step)
    {
      double t0 = runner_now ();
      carom_status s = carom_world_update (w, a->dt);
      seconds += runner_now () - t0;
      if (s != CAROM_OK)
        {
          fprintf (stderr, "%s: step %ld: %s\n", a->file, step, carom_status_string (s));
          rc = 1;
          break;
        }
      deepest = runner_max_depth (w, deepest);
      if (a->every && (step % a->every == 0 || step == a->steps))
        runner_csv_rows (csv, w, ids, n, step);
    }
  if (csv && !a->every)
    runner_csv_rows (csv, w, ids, n, -1);
  if (csv && csv != stdout && fclose (csv) != 0)
    {
      fprintf (stderr, "%s: cannot write: %s\n", a->csv, strerror (errno));
      rc = 1;
    }

  if (rc == 0)
    {
      char effects[160] = "";
      uint32_t mask = carom_world_get_effects (w), bit;
      for (bit = 1; bit; bit <<= 1)
        if ((mask & bit) && carom_effect_name ((carom_effect) bit))
          {
            if (effects[0])
              strcat (effects, ",");
            strcat (effects, carom_effect_name ((carom_effect) bit));
          }
      runner_totals_of (w, ids, n, &end);
      printf ("bodies=%ld joints=%ld steps=%ld dt=%.17g ms_per_step=%.6f energy_start=%.17g energy_end=%.17g "
              "kinetic_start=%.17g kinetic_end=%.17g momentum_x=%.17g momentum_y=%.17g angular_momentum=%.17g "
              "max_penetration=%.17g contacts=%ld nan=%d effects=%s\n",
              (long) n, (long) carom_world_joint_count (w), a->steps, a->dt,
              a->steps ? 1e3 * seconds / (double) a->steps : 0.0, start.kinetic + start.potential,
              end.kinetic + end.potential, start.kinetic, end.kinetic, end.px, end.py, end.l, deepest,
              (long) carom_world_contact_count (w), end.finite ? 0 : 1, effects[0] ? effects : "none");
      fflush (stdout);
      if (a->png && runner_draw (a, w, a->png, 0))
        rc = 1;
      if (a->svg && runner_draw (a, w, a->svg, 1))
        rc = 1;
    }
  free (ids);
  carom_world_destroy (w);
  return rc;
}

int main (int argc, char **argv)
{
  runner_args a;
  int rc;
  if (argc < 2)
    {
      fputs (runner_usage, stderr);
      return 2;
    }
  if (!strcmp (argv[1], "--help") || !strcmp (argv[1], "-h") || !strcmp (argv[1], "help"))
    {
      fputs (runner_usage, stdout);
      return 0;
    }
  if (strcmp (argv[1], "run") && strcmp (argv[1], "check"))
    return runner_bad_usage ("unknown command '%s'", argv[1]);
  rc = runner_parse (argc, argv, &a);
  if (rc)
    return rc;
  return strcmp (a.command, "run") == 0 ? runner_run (&a) : runner_check (&a);
}
