/* Drawing a carom world with Cairo: shared by the GTK demo and the headless
 * runner's PNG/SVG output, so both show the same picture. */
#ifndef CAROM_DEMO_RENDER_H
#define CAROM_DEMO_RENDER_H

#include <cairo.h>

#include "carom.h"

typedef struct render_options {
  int width, height;        /* target size in pixels */
  double view_x0, view_y0;  /* world rectangle shown (y up) */
  double view_x1, view_y1;
  int show_velocities;      /* velocity arrows */
  int show_contacts;        /* impact points and normals */
  int show_centroids;       /* centre-of-mass dots */
  int show_gravity;         /* gravity vector */
  int show_restitution;     /* restitution bar */
  int show_joints;          /* joints: their anchors and bodies' centres */
  int highlight_body_valid; /* draw `highlight` body outlined (mouse grab) */
  carom_body_id highlight;
  const carom_body_id *lit; /* sensors drawn lit: something is inside */
  int lit_count;
} render_options;

/* Defaults: everything fitted to the world's bodies, centroids, contacts
 * and joints shown, vectors hidden. */
void render_options_init (render_options *opt, const carom_world *world, int width, int height);

/* Fit view_* to the bounding box of all bodies with a small margin, keeping
 * the aspect ratio of width x height. */
void render_fit_view (render_options *opt, const carom_world *world);

/* Paint the world: background, bodies filled in their own colour (statics
 * grey), outlines, joints, then the overlays asked for. */
void render_world (cairo_t *cr, const carom_world *world, const render_options *opt);

/* Map between screen pixels and world coordinates under `opt`. */
void render_to_world (const render_options *opt, double sx, double sy, double *wx, double *wy);
void render_to_screen (const render_options *opt, double wx, double wy, double *sx, double *sy);

#endif
