/* The stage: the world a scene file builds, with what the demo reads from
 * the file beside it (its restitution, its walls). The lifecycle functions
 * are the ones the scene table (scenes.h) lists. */
#ifndef CAROM_DEMO_STAGE_H
#define CAROM_DEMO_STAGE_H

#include <stddef.h>

#include <cairo.h>

#include "carom.h"
#include "render.h"
#include "walls.h"

/* Sensors whose overlaps the stage follows (to light them up). */
#define STAGE_MAX_SENSORS 16

typedef struct stage {
  char *path;            /* the scene file */
  carom_world *world;
  double restitution;    /* the world's default restitution: the file's
                            last `restitution` line, or what the demo set
                            since */
  walls walls;           /* the `bounds` walls, if the file has them */
  double step_ms;        /* wall-clock time of the last update */
  /* sensors and how many bodies overlap each, from the events */
  carom_body_id sensors[STAGE_MAX_SENSORS];
  int32_t inside[STAGE_MAX_SENSORS];
  int32_t sensor_count;
} stage;

/* Read and load a scene file. On failure the stage is empty, and `message`
 * (size bytes) holds "FILE:LINE: what is wrong" or "FILE: why". */
carom_status stage_init (stage *s, const char *path, char *message, size_t size);

/* One carom_world_update of dt, timed into s->step_ms. */
carom_status stage_update (stage *s, double dt);

/* Paint the world with render_world. */
void stage_draw (const stage *s, cairo_t *cr, const render_options *opt);

/* Free everything; safe on a zeroed or destroyed stage. */
void stage_destroy (stage *s);

/* Change the world's default restitution (carom_world_set_restitution),
 * remembering it: the API has no getter. */
carom_status stage_set_restitution (stage *s, double e);

/* Kinetic energy of the dynamic bodies: sum of m v^2 / 2 + I w^2 / 2. */
double stage_kinetic_energy (const stage *s);

#endif
