#include "sleep.h"

#include "world.h"

/* Slow enough to sleep: 5% of the body's size per second and 2 degrees per
 * second, for half a second. Relative to size, so a scene sleeps the same
 * at any scale. */
#define SLEEP_LINEAR 0.05
#define SLEEP_ANGULAR 0.035
#define SLEEP_TIME 0.5

static int is_slow (const body *b)
{
  double tol = SLEEP_LINEAR * b->shape.size;
  return v2_len2 (b->v) <= tol * tol && fabs (b->w) <= SLEEP_ANGULAR;
}

void sleep_wake_touched (carom_world *world)
{
  const contacts *c = &world->contacts;
  int32_t i;
  if (!world->sleeping)
    return;
  for (i = 0; i < c->count; ++i)
    {
      body *a = &world->bodies[c->list[i].a], *b = &world->bodies[c->list[i].b];
      if (a->asleep && !b->asleep && ((b->type == CAROM_DYNAMIC && !is_slow (b)) || body_kinematic_moving (b)))
        body_wake (a);
      else if (b->asleep && !a->asleep && ((a->type == CAROM_DYNAMIC && !is_slow (a)) || body_kinematic_moving (a)))
        body_wake (b);
    }
}

void sleep_update (carom_world *world, const step_context *ctx)
{
  double h = ctx->dt; /* sleep is judged once per update */
  int32_t i;
  if (!world->sleeping)
    return;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (!b->alive || b->type != CAROM_DYNAMIC || b->asleep)
        continue;
      if (!is_slow (b))
        {
          b->sleep_time = 0.0;
          continue;
        }
      b->sleep_time += h;
      if (b->sleep_time >= SLEEP_TIME)
        body_sleep (b);
    }
}
