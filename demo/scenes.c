/* The scene table. Every shipped scene is a scene file, so the entries
 * share the stage lifecycle; a scene that needs its own per-frame logic
 * (a spawner, a motor, a driver) gets its own functions in its row. */
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

/* The car scene's driver: the motors of its wheel joints turn round when
 * the chassis passes CAR_TURN on its way to either end of the ground. Its
 * speed and torque are car.scene's (the API reads no motor back). */
#define CAR_TURN 11.0
#define CAR_SPEED 12.0
#define CAR_TORQUE 1000.0
#define CAR_MAX_WHEELS 8

typedef struct car_wheels {
  carom_joint_id ids[CAR_MAX_WHEELS];
  int count;
} car_wheels;

static void car_find_wheel (carom_joint_type type, const double *xy, carom_joint_id id, void *user)
{
  car_wheels *w = user;
  (void) xy;
  if (type == CAROM_JOINT_WHEEL && w->count < CAR_MAX_WHEELS)
    w->ids[w->count++] = id;
}

static carom_status car_update (stage *s, double dt)
{
  carom_debug_draw draw;
  car_wheels wheels;
  carom_body_id chassis = CAROM_NULL_BODY;
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0, speed = 0.0;
  int i;
  /* the wheel joints: the API lists no joints, the debug draw reports
   * each one */
  wheels.count = 0;
  if (carom_debug_draw_init (&draw, sizeof draw) == CAROM_OK)
    {
      draw.draw_bodies = draw.draw_contacts = 0;
      draw.joint = car_find_wheel;
      draw.user = &wheels;
      carom_world_draw (s->world, &draw);
    }
  if (wheels.count > 0 && carom_joint_get_bodies (s->world, wheels.ids[0], NULL, &chassis, NULL) == CAROM_OK
      && carom_body_get_position (s->world, chassis, &x, &y) == CAROM_OK
      && carom_body_get_velocity (s->world, chassis, &vx, &vy) == CAROM_OK)
    {
      /* clockwise (negative) drives to the right */
      if (x > CAR_TURN && vx > 0.0)
        speed = CAR_SPEED;
      else if (x < -CAR_TURN && vx < 0.0)
        speed = -CAR_SPEED;
      for (i = 0; i < wheels.count && speed != 0.0; ++i)
        carom_joint_set_motor (s->world, wheels.ids[i], 1, speed, CAR_TORQUE);
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
  { "pendulum", "pendulum.scene", "a pendulum and a double pendulum on revolute and distance joints", stage_init,
    stage_update, stage_draw, stage_destroy },
  { "bridge", "bridge.scene", "a chain bridge of planks on revolute joints, loaded with crates", stage_init,
    stage_update, stage_draw, stage_destroy },
  { "ragdoll", "ragdoll.scene", "a ragdoll on limited revolute joints tumbles down steps", stage_init, stage_update,
    stage_draw, stage_destroy },
  { "car", "car.scene", "a car on wheel joints: spring suspension and motors, over hills", stage_init, car_update,
    stage_draw, stage_destroy },
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
