/* Contact and sensor events (carom_world_get_events): the pairs of bodies
 * that touch after an update, compared with those of the update before. */
#ifndef CAROM_EVENTS_H
#define CAROM_EVENTS_H

#include "carom.h"

struct carom_world;

/* A pair of bodies that touched (or overlapped a sensor) at the end of an
 * update. */
typedef struct touch {
  carom_body_id a, b;
  double x, y;        /* a point of the contact (sensor: b's centre) */
  int32_t first;      /* the pair's first contact in the list of its
                         update (what a begin event reads), -1 for a sensor */
  int32_t sensor;     /* a is a sensor, b overlaps it */
  int32_t seen;       /* (as the last update's) touches in this one too:
                         0 when made, set only in the update after */
} touch;

typedef struct events {
  touch *touches[2];  /* this update's and the last one's, in turn */
  int32_t count[2], cap[2];
  int32_t cur;        /* which is the last update's */
  int32_t *table;     /* open addressing over the last update's: base + its
                         index, and any value below base is an empty slot */
  int32_t table_cap;
  int32_t table_base; /* above every value an earlier update left */
  int32_t table_set;  /* table_cap when the table was last filled with -1 */
  carom_contact_event *list;
  int32_t event_count, event_cap;
} events;

void events_destroy (struct carom_world *world);
/* Room for this update's events, asked for before any state changes; 0
 * when memory ran out. */
int events_reserve (struct carom_world *world);
/* After the solver: this update's touching pairs and the events. */
void events_update (struct carom_world *world);

#endif
