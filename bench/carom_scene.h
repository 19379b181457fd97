/* Building a carom world from a bench scene: shared by every carom bench
 * (speed, effects, accuracy), so they all measure the same world. */
#ifndef CAROM_BENCH_CAROM_SCENE_H
#define CAROM_BENCH_CAROM_SCENE_H

#include "carom.h"
#include "scenes.h"

/* The library defaults with the scene's gravity, restitution and friction. */
void bench_carom_def (carom_world_def *def, const bench_scene *s);

/* Add the scene's bodies to `world`, their ids to ids[0 .. count). Returns
 * CAROM_OK or the status of the first body refused, whose index goes to
 * *failed (may be NULL). */
carom_status bench_carom_add_bodies (carom_world *world, const bench_scene *s, carom_body_id *ids, int *failed);

/* Add the scene's joints to `world` (its bodies' ids in ids[], as
 * bench_carom_add_bodies left them), their ids to joints[0 .. joint_count)
 * (joints may be NULL). Returns CAROM_OK or the status of the first joint
 * refused, whose index goes to *failed (may be NULL). */
carom_status bench_carom_add_joints (carom_world *world, const bench_scene *s, const carom_body_id *ids,
                                     carom_joint_id *joints, int *failed);

#endif
