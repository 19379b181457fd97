/* The demo's heads-up display: the status line along the bottom (bodies,
 * contacts, ms per step, frames per second, kinetic energy) and the help
 * overlay. Cairo only. */
#ifndef CAROM_DEMO_HUD_H
#define CAROM_DEMO_HUD_H

#include <cairo.h>
#include <stdint.h>

/* Height of the status line in pixels. */
#define HUD_STATUS_HEIGHT 24

typedef struct hud {
  double step_ms;     /* time per carom_world_update, smoothed */
  double fps;         /* frames drawn per second */
  int frames;         /* frames drawn since `since` */
  double since;       /* seconds */
} hud;

/* What the status line shows besides the timings. */
typedef struct hud_status {
  const char *scene;
  int bodies, contacts;
  double energy;
  double gx, gy;
  double restitution;
  int paused;
  int holding;        /* a body is held by the mouse */
  uint32_t effects;   /* carom_world_get_effects */
} hud_status;

void hud_init (hud *h, double now);

/* Count one drawn frame at time `now` (seconds). */
void hud_update (hud *h, double now);

/* Fold one step's duration into the average. */
void hud_step_time (hud *h, double ms);

/* The status line across (0, y)-(width, y + HUD_STATUS_HEIGHT). */
void hud_draw_status (cairo_t *cr, const hud *h, const hud_status *st, double y, double width);

/* The help overlay, centred in width x height. */
void hud_draw_help (cairo_t *cr, double width, double height);

#endif
