/* The scene table. Every shipped scene is a scene file, so the entries
 * share the stage lifecycle; a scene that needs its own per-frame logic
 * (a spawner, a motor) gets its own functions in its row. */
#include "scenes.h"

#include <string.h>

#include <glib.h>

/* The source tree's scenes/ directory, set by mk/demo.mk, so the demo also
 * finds its scenes when started from another directory. */
#ifndef DEMO_SCENE_DIR
#define DEMO_SCENE_DIR "scenes"
#endif

/* The platform scene's motor: its kinematic bodies turn back at the ends of
 * their run, then the world steps. */
#define PLATFORM_RUN 4.5

static carom_status platform_update (stage *s, double dt)
{
  carom_body_id ids[64];
  int32_t n = carom_world_get_bodies (s->world, ids, 64), i;
  for (i = 0; i < n && i < 64; ++i)
    {
      carom_body_type type = CAROM_DYNAMIC;
      double x, y, vx, vy;
      carom_body_get_type (s->world, ids[i], &type);
      if (type != CAROM_KINEMATIC)
        continue;
      carom_body_get_position (s->world, ids[i], &x, &y);
      carom_body_get_velocity (s->world, ids[i], &vx, &vy);
      if ((x > PLATFORM_RUN && vx > 0.0) || (x < -PLATFORM_RUN && vx < 0.0))
        carom_body_set_velocity (s->world, ids[i], -vx, vy);
    }
  return stage_update (s, dt);
}

static const scene_entry scenes_table[] = {
  { "thesis", "thesis.scene", "the thesis' polygons in a closed box", stage_init, stage_update, stage_draw,
    stage_destroy },
  { "balls", "balls.scene", "50 elastic balls, as the original flying-balls", stage_init, stage_update,
    stage_draw, stage_destroy },
  { "pyramid", "pyramid.scene", "a pyramid of 210 boxes: stacking", stage_init, stage_update, stage_draw,
    stage_destroy },
  { "rain", "rain.scene", "2000 polygons falling into a container", stage_init, stage_update, stage_draw,
    stage_destroy },
  { "gas", "gas.scene", "500 polygons bouncing without gravity", stage_init, stage_update, stage_draw,
    stage_destroy },
  { "platform", "platform.scene", "a kinematic platform carries boxes; a sensor lights up", stage_init,
    platform_update, stage_draw, stage_destroy },
  { "compound", "compound.scene", "bodies of several shapes: a table, a dumbbell, a hammer", stage_init,
    stage_update, stage_draw, stage_destroy },
};

static const scene_entry scenes_user = {
  "file", NULL, "a scene file", stage_init, stage_update, stage_draw, stage_destroy
};

int scenes_count (void)
{
  return (int) (sizeof scenes_table / sizeof scenes_table[0]);
}

const scene_entry *scenes_get (int i)
{
  return i >= 0 && i < scenes_count () ? &scenes_table[i] : NULL;
}

const scene_entry *scenes_find (const char *name)
{
  int i;
  for (i = 0; i < scenes_count (); ++i)
    if (strcmp (scenes_table[i].name, name) == 0)
      return &scenes_table[i];
  return NULL;
}

const scene_entry *scenes_file_entry (void)
{
  return &scenes_user;
}

char *scenes_path (const scene_entry *e)
{
  char *here;
  if (!e->file)
    return NULL;
  here = g_build_filename ("scenes", e->file, NULL);
  if (g_file_test (here, G_FILE_TEST_IS_REGULAR))
    return here;
  g_free (here);
  return g_build_filename (DEMO_SCENE_DIR, e->file, NULL);
}
