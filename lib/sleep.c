#include "sleep.h"

#include "world.h"

/* Slow enough to sleep: 5% of the body's size per second and 2 degrees per
 * second, for half a second. Relative to size, so a scene sleeps the same
 * at any scale. */
#define SLEEP_LINEAR 0.05
#define SLEEP_ANGULAR 0.035
#define SLEEP_TIME 0.5

/* Joined bodies sleep and wake together: the groups their joints make
 * (union-find over the joints' dynamic bodies, in the joint tree's
 * scratch, which the update has reserved). Returns the parents, or NULL
 * without joints; groups[slot_count + i] is scratch for the caller. */
static int32_t find (int32_t *uf, int32_t i)
{
  while (uf[i] != i)
    {
      uf[i] = uf[uf[i]];
      i = uf[i];
    }
  return i;
}

static int32_t *joint_groups (carom_world *world)
{
  int32_t *uf = world->joint_tree.scratch;
  int32_t i;
  if (world->joints.live == 0)
    return NULL;
  for (i = 0; i < world->slot_count; ++i)
    uf[i] = i;
  for (i = 0; i < world->joints.count; ++i)
    {
      const joint *j = &world->joints.list[i];
      if (j->alive && j->a >= 0 && world->bodies[j->a].type == CAROM_DYNAMIC
          && world->bodies[j->b].type == CAROM_DYNAMIC)
        uf[find (uf, j->a)] = find (uf, j->b);
    }
  return uf;
}

/* A body held by a mouse joint stays awake: it is being dragged. */
static void keep_dragged_awake (carom_world *world)
{
  int32_t i;
  for (i = 0; i < world->joints.count; ++i)
    {
      const joint *j = &world->joints.list[i];
      if (j->alive && j->type == CAROM_JOINT_MOUSE)
        body_wake (&world->bodies[j->b]);
    }
}

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
  /* a group with one member awake is awake */
  if (world->joints.live > 0)
    {
      int32_t *uf = joint_groups (world), *awake = uf + world->slot_count;
      keep_dragged_awake (world);
      for (i = 0; i < world->slot_count; ++i)
        awake[i] = 0;
      for (i = 0; i < world->slot_count; ++i)
        if (world->bodies[i].alive && world->bodies[i].type == CAROM_DYNAMIC && !world->bodies[i].asleep)
          awake[find (uf, i)] = 1;
      for (i = 0; i < world->slot_count; ++i)
        if (world->bodies[i].alive && world->bodies[i].asleep && awake[find (uf, i)])
          body_wake (&world->bodies[i]);
    }
}

void sleep_update (carom_world *world, const step_context *ctx)
{
  double h = ctx->dt; /* sleep is judged once per update */
  int32_t i, *uf = NULL;
  double *least = NULL;
  if (!world->sleeping)
    return;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (!b->alive || b->type != CAROM_DYNAMIC || b->asleep)
        continue;
      b->sleep_time = is_slow (b) ? b->sleep_time + h : 0.0;
    }
  if (world->joints.live > 0)
    {
      /* a group sleeps when its last member has been slow long enough */
      keep_dragged_awake (world);
      uf = joint_groups (world);
      least = world->joint_tree.group_time;
      for (i = 0; i < world->slot_count; ++i)
        least[i] = INFINITY;
      for (i = 0; i < world->slot_count; ++i)
        {
          const body *b = &world->bodies[i];
          int32_t r;
          if (!b->alive || b->type != CAROM_DYNAMIC || b->asleep)
            continue;
          r = find (uf, i);
          least[r] = b->sleep_time < least[r] ? b->sleep_time : least[r];
        }
    }
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (!b->alive || b->type != CAROM_DYNAMIC || b->asleep)
        continue;
      if ((uf ? least[find (uf, i)] : b->sleep_time) >= SLEEP_TIME)
        body_sleep (b);
    }
}
