/* The demo's scene table, in the manner of Chipmunk's demo list: a name,
 * the scene file and the lifecycle (init, update, draw, destroy) the main
 * loop calls. Number keys 1-9 and 0 pick the first ten entries in order,
 * n and p step through all of them. */
#ifndef CAROM_DEMO_SCENES_H
#define CAROM_DEMO_SCENES_H

#include <stddef.h>

#include <cairo.h>

#include "carom.h"
#include "render.h"
#include "stage.h"

typedef struct scene_entry {
  const char *name;
  const char *file;      /* under scenes/; NULL for a file named by the user */
  const char *summary;   /* one line for the help and the window title */
  carom_status (*init) (stage *s, const char *path, char *message, size_t size);
  carom_status (*update) (stage *s, double dt);
  void (*draw) (const stage *s, cairo_t *cr, const render_options *opt);
  void (*destroy) (stage *s);
} scene_entry;

/* Number of entries in the table, and entry i (0-based; NULL if out of
 * range). Entry 0 is the default scene. */
int scenes_count (void);
const scene_entry *scenes_get (int i);

/* The entry named `name`, or NULL. */
const scene_entry *scenes_find (const char *name);

/* The entry used for a scene file given on the command line. */
const scene_entry *scenes_file_entry (void);

/* Where entry `e`'s file is: scenes/FILE from the current directory if it
 * is there, else in the source tree the demo was built from. Free with
 * g_free. */
char *scenes_path (const scene_entry *e);

#endif
