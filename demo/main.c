/* carom-demo: the GTK 3 + Cairo demo, in the manner of flying-balls'
 * main.c: a window with a drawing area, a timer that steps the world, the
 * draw signal painting it, keys changing gravity and restitution.
 *
 *   carom-demo [OPTIONS] [SCENE]      (carom-demo --help for the options)
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gdk/gdkkeysyms.h>
#include <gtk/gtk.h>

#include "controls.h"
#include "demo.h"
#include "scenes.h"

#define DEFAULT_WIDTH 800
#define DEFAULT_HEIGHT 600

/* Timer period: about 60 Hz, one DEMO_DT step per tick. */
#define TIMER_MS 16

typedef struct app {
  demo demo;
  GtkWidget *window;
  GtkWidget *canvas;
  cairo_surface_t *frame; /* the last frame painted on the window */
  long frames;            /* --frames: ticks left; < 0 runs until quit */
  const char *screenshot; /* --screenshot: PNG written when frames run out */
  int dirty;              /* a redraw is queued and not yet done */
  int waited;             /* ticks spent waiting for it at the end */
  int overlays;           /* demo_overlays at the last draw */
  int status;             /* exit status */
} app;

/* ---------------------------------------------------------------- window */

static void app_title (app *a)
{
  char title[256];
  snprintf (title, sizeof title, "carom demo: %s (%s)", a->demo.name,
            a->demo.entry->file ? a->demo.entry->summary : a->demo.path);
  gtk_window_set_title (GTK_WINDOW (a->window), title);
}

static void app_redraw (app *a)
{
  a->dirty = 1;
  gtk_widget_queue_draw (a->canvas);
}

/* Save the frame the window shows (the last one painted) as a PNG. */
static int app_screenshot (app *a, const char *file)
{
  cairo_status_t s = cairo_surface_write_to_png (a->frame, file);
  if (s != CAIRO_STATUS_SUCCESS)
    {
      fprintf (stderr, "carom-demo: %s: %s\n", file, cairo_status_to_string (s));
      return 1;
    }
  printf ("carom-demo: wrote %s (%dx%d)\n", file, cairo_image_surface_get_width (a->frame),
          cairo_image_surface_get_height (a->frame));
  return 0;
}

/* ---------------------------------------------------------------- signals */

/* Paint the frame into an image surface of the drawing area's size, in
 * device pixels on a HiDPI screen. */
static void app_paint (app *a)
{
  int w = gtk_widget_get_allocated_width (a->canvas), h = gtk_widget_get_allocated_height (a->canvas);
  int scale = gtk_widget_get_scale_factor (a->canvas);
  cairo_t *cr;
  if (a->frame
      && (cairo_image_surface_get_width (a->frame) != w * scale
          || cairo_image_surface_get_height (a->frame) != h * scale))
    {
      cairo_surface_destroy (a->frame);
      a->frame = NULL;
    }
  if (!a->frame)
    {
      a->frame = cairo_image_surface_create (CAIRO_FORMAT_RGB24, w * scale, h * scale);
      cairo_surface_set_device_scale (a->frame, scale, scale);
    }
  cr = cairo_create (a->frame);
  demo_draw (&a->demo, cr, w, h);
  cairo_destroy (cr);
  a->overlays = demo_overlays (&a->demo, demo_now ());
  a->dirty = 0;
}

/* Paint into an image surface, then put that on the window: one image
 * upload instead of thousands of small X requests for a busy scene, and
 * the window shows exactly the pixels --screenshot writes. */
static gboolean draw_event (GtkWidget *widget, cairo_t *cr, gpointer data)
{
  app *a = data;
  (void) widget;
  app_paint (a);
  cairo_set_source_surface (cr, a->frame, 0, 0);
  cairo_paint (cr);
  return FALSE;
}

/* As flying-balls' configure_event: the window's size moves the walls. */
static gboolean configure_event (GtkWidget *widget, GdkEventConfigure *event, gpointer data)
{
  app *a = data;
  (void) event;
  demo_resize (&a->demo, gtk_widget_get_allocated_width (widget), gtk_widget_get_allocated_height (widget));
  return FALSE;
}

static gboolean keyboard_input (GtkWidget *widget, GdkEventKey *event, gpointer data)
{
  app *a = data;
  (void) widget;
  switch (controls_key (&a->demo, event->keyval))
    {
    case CONTROLS_IGNORED:
      return FALSE;
    case CONTROLS_QUIT:
      gtk_main_quit ();
      return TRUE;
    case CONTROLS_SCENE:
      app_title (a);
      break;
    case CONTROLS_HANDLED:
      break;
    }
  app_redraw (a);
  return TRUE;
}

static gboolean button_press (GtkWidget *widget, GdkEventButton *event, gpointer data)
{
  app *a = data;
  (void) widget;
  if (event->type != GDK_BUTTON_PRESS || event->button != 1)
    return FALSE;
  if (controls_press (&a->demo, event->x, event->y))
    app_redraw (a);
  return TRUE;
}

static gboolean button_release (GtkWidget *widget, GdkEventButton *event, gpointer data)
{
  app *a = data;
  (void) widget;
  if (event->button != 1)
    return FALSE;
  if (controls_release (&a->demo, event->x, event->y))
    app_redraw (a);
  return TRUE;
}

static gboolean motion_notify (GtkWidget *widget, GdkEventMotion *event, gpointer data)
{
  app *a = data;
  (void) widget;
  if (controls_motion (&a->demo, event->x, event->y))
    app_redraw (a);
  return TRUE;
}

/* One tick: step unless paused, redraw; while paused, redraw only when a
 * timed overlay comes or goes, so a paused picture stays still. */
static gboolean timeout (gpointer data)
{
  app *a = data;
  if (a->frames == 0)
    {
      /* wait for the last step to be on screen, a second at most (the
         window may be hidden: then paint the frame ourselves) */
      if ((!a->frame || a->dirty) && ++a->waited < 1000 / TIMER_MS)
        return G_SOURCE_CONTINUE;
      if (!a->frame || a->dirty)
        app_paint (a);
      if (a->screenshot)
        a->status = app_screenshot (a, a->screenshot);
      gtk_main_quit ();
      return G_SOURCE_REMOVE;
    }
  if (!a->demo.paused)
    {
      demo_update (&a->demo);
      app_redraw (a);
    }
  else if (demo_overlays (&a->demo, demo_now ()) != a->overlays)
    app_redraw (a);
  if (a->frames > 0)
    --a->frames;
  return G_SOURCE_CONTINUE;
}

static void destroy_window (GtkWidget *widget, gpointer data)
{
  (void) widget;
  (void) data;
  gtk_main_quit ();
}

/* ---------------------------------------------------------------- options */

static void print_usage (FILE *f, const char *progname)
{
  int i;
  fprintf (f,
           "usage: %s [OPTIONS] [SCENE]\n"
           "SCENE is a scene file (docs/scenes.md) or one of the names:",
           progname);
  for (i = 0; i < scenes_count (); ++i)
    fprintf (f, " %s", scenes_get (i)->name);
  fprintf (f,
           "\n(default: %s)\n"
           "options:\n"
           "  --frames N         quit after N timer ticks (about 60 a second)\n"
           "  --screenshot FILE  then save the drawing area as PNG (default --frames 1)\n"
           "  --paused           start paused\n"
           "  --keys KEYS        press these keys first, e.g. --keys vc\n"
           "  --size WxH         window size (default %dx%d)\n"
           "  --verbose          print the view and mouse grabs\n"
           "  --help             this text\n"
           "keys: press h in the window.\n",
           scenes_get (0)->name, DEFAULT_WIDTH, DEFAULT_HEIGHT);
}

static int parse_long (const char *s, long lo, long hi, long *out)
{
  char *end;
  long v;
  errno = 0;
  v = strtol (s, &end, 10);
  if (errno || end == s || *end || v < lo || v > hi)
    return 0;
  *out = v;
  return 1;
}

typedef struct options {
  const char *scene;
  long frames;
  const char *screenshot;
  int paused, verbose;
  const char *keys;
  int width, height;
} options;

/* Returns -1 to go on, else the exit status. */
static int parse_options (int argc, char **argv, options *o)
{
  int i;
  long w, h;
  memset (o, 0, sizeof *o);
  o->frames = -1;
  o->width = DEFAULT_WIDTH, o->height = DEFAULT_HEIGHT;
  for (i = 1; i < argc; ++i)
    {
      const char *arg = argv[i], *next = i + 1 < argc ? argv[i + 1] : NULL;
      if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
        {
          print_usage (stdout, argv[0]);
          return 0;
        }
      else if (strcmp (arg, "--paused") == 0)
        o->paused = 1;
      else if (strcmp (arg, "--verbose") == 0)
        o->verbose = 1;
      else if (strcmp (arg, "--frames") == 0 && next && parse_long (next, 0, 100000000L, &o->frames))
        ++i;
      else if (strcmp (arg, "--screenshot") == 0 && next)
        o->screenshot = argv[++i];
      else if (strcmp (arg, "--keys") == 0 && next)
        o->keys = argv[++i];
      else if (strcmp (arg, "--size") == 0 && next && sscanf (next, "%ldx%ld", &w, &h) == 2 && w >= 64
               && h >= 64 && w <= 16384 && h <= 16384)
        {
          o->width = (int) w, o->height = (int) h;
          ++i;
        }
      else if (arg[0] != '-' && !o->scene)
        o->scene = arg;
      else if (strcmp (arg, "--frames") == 0 || strcmp (arg, "--screenshot") == 0 || strcmp (arg, "--keys") == 0
               || strcmp (arg, "--size") == 0)
        {
          fprintf (stderr, "%s: %s needs %s\n", argv[0], arg,
                   arg[2] == 'f' ? "a count from 0 up" : arg[3] == 'i' ? "WxH, each 64 to 16384" : "a value");
          return 2;
        }
      else
        {
          fprintf (stderr, "%s: bad option or argument '%s'\n", argv[0], arg);
          print_usage (stderr, argv[0]);
          return 2;
        }
    }
  if (o->screenshot && o->frames < 0)
    o->frames = 1;
  return -1;
}

/* The scene to start with: a file, else a name from the table. */
static int start_scene (demo *d, const options *o)
{
  const scene_entry *e = o->scene ? NULL : scenes_get (0);
  char *path;
  int ok;
  if (o->scene && !g_file_test (o->scene, G_FILE_TEST_EXISTS))
    e = scenes_find (o->scene);
  if (!e)
    return demo_init (d, scenes_file_entry (), o->scene, o->width, o->height);
  path = scenes_path (e);
  ok = demo_init (d, e, path, o->width, o->height);
  g_free (path);
  return ok;
}

/* ------------------------------------------------------------------- main */

int main (int argc, char **argv)
{
  options o;
  app a;
  int status;
  const char *k;

  gtk_parse_args (&argc, &argv); /* GTK's own options, without a display */
  status = parse_options (argc, argv, &o);
  if (status >= 0)
    return status;

  memset (&a, 0, sizeof a);
  if (!start_scene (&a.demo, &o))
    {
      demo_destroy (&a.demo);
      return 1;
    }
  a.demo.verbose = o.verbose;
  a.demo.paused = o.paused;
  a.frames = o.frames;
  a.screenshot = o.screenshot;
  for (k = o.keys; k && *k; ++k)
    if (controls_key (&a.demo, gdk_unicode_to_keyval ((guint32) (unsigned char) *k)) == CONTROLS_QUIT)
      {
        demo_destroy (&a.demo);
        return 0;
      }

  if (!gtk_init_check (&argc, &argv))
    {
      const char *display = getenv ("DISPLAY");
      fprintf (stderr,
               "%s: cannot open the display%s%s%s; for a picture without one, use the headless runner "
               "(make run-headless)\n",
               argv[0], display ? " '" : " (DISPLAY is not set", display ? display : ")", display ? "'" : "");
      demo_destroy (&a.demo);
      return 1;
    }

  a.window = gtk_window_new (GTK_WINDOW_TOPLEVEL);
  gtk_window_set_default_size (GTK_WINDOW (a.window), o.width, o.height);
  app_title (&a);
  g_signal_connect (a.window, "destroy", G_CALLBACK (destroy_window), &a);
  g_signal_connect (a.window, "key-press-event", G_CALLBACK (keyboard_input), &a);
  gtk_widget_add_events (a.window, GDK_KEY_PRESS_MASK);

  a.canvas = gtk_drawing_area_new ();
  gtk_widget_set_size_request (a.canvas, 160, 120);
  g_signal_connect (a.canvas, "configure-event", G_CALLBACK (configure_event), &a);
  g_signal_connect (a.canvas, "draw", G_CALLBACK (draw_event), &a);
  g_signal_connect (a.canvas, "button-press-event", G_CALLBACK (button_press), &a);
  g_signal_connect (a.canvas, "button-release-event", G_CALLBACK (button_release), &a);
  g_signal_connect (a.canvas, "motion-notify-event", G_CALLBACK (motion_notify), &a);
  gtk_widget_add_events (a.canvas, GDK_BUTTON_PRESS_MASK | GDK_BUTTON_RELEASE_MASK | GDK_POINTER_MOTION_MASK);
  gtk_container_add (GTK_CONTAINER (a.window), a.canvas);

  /* Below redraws and input in priority, so a step slower than the period
   * cannot starve them (a default-priority timeout would). */
  g_timeout_add_full (G_PRIORITY_DEFAULT_IDLE, TIMER_MS, timeout, &a, NULL);

  gtk_widget_show_all (a.window);
  gtk_main ();

  demo_destroy (&a.demo);
  if (a.frame)
    cairo_surface_destroy (a.frame);
  return a.status;
}
