/* Sleeping: bodies that stay slow for a while stop being simulated until
 * something touches them faster than that. Per body, without islands: a
 * resting pile falls asleep together because all its bodies are slow, and
 * wakes from where it is hit outwards, one contact layer per sub-step.
 * Bodies joined by joints are the exception: they sleep together, when the
 * last of them has been slow long enough, and wake together. */
#ifndef CAROM_SLEEP_H
#define CAROM_SLEEP_H

#include "step.h"

struct carom_world;

/* After detection: wake sleeping bodies touched by a fast awake one. */
void sleep_wake_touched (struct carom_world *world);
/* After the drift: advance sleep timers, put slow bodies to sleep. */
void sleep_update (struct carom_world *world, const step_context *ctx);

#endif
