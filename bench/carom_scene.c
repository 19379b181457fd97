#include "carom_scene.h"

void bench_carom_def (carom_world_def *def, const bench_scene *s)
{
  carom_world_def_init (def, sizeof *def);
  def->gravity_x = s->gravity_x;
  def->gravity_y = s->gravity_y;
  def->restitution = s->restitution;
  def->friction = s->friction;
}

carom_status bench_carom_add_bodies (carom_world *world, const bench_scene *s, carom_body_id *ids, int *failed)
{
  int i;
  for (i = 0; i < s->count; ++i)
    {
      const bench_body *b = &s->bodies[i];
      carom_body_def bd;
      carom_status st;
      carom_body_def_init (&bd, sizeof bd);
      bd.type = b->is_static ? CAROM_STATIC : CAROM_DYNAMIC;
      bd.x = b->x, bd.y = b->y, bd.angle = b->angle;
      bd.vx = b->vx, bd.vy = b->vy, bd.spin = b->spin;
      bd.density = s->density;
      if (b->shape == BENCH_BOX)
        st = carom_world_add_box (world, &bd, b->w, b->h, &ids[i]);
      else if (b->shape == BENCH_REGULAR)
        st = carom_world_add_regular (world, &bd, b->sides, b->side, &ids[i]);
      else
        st = carom_world_add_circle (world, &bd, b->radius, &ids[i]);
      if (st != CAROM_OK)
        {
          if (failed)
            *failed = i;
          return st;
        }
    }
  return CAROM_OK;
}

carom_status bench_carom_add_joints (carom_world *world, const bench_scene *s, const carom_body_id *ids,
                                     carom_joint_id *joints, int *failed)
{
  int i;
  for (i = 0; i < s->joint_count; ++i)
    {
      const bench_joint *j = &s->joints[i];
      carom_joint_def jd;
      carom_status st;
      carom_joint_def_init (&jd, sizeof jd);
      jd.type = CAROM_JOINT_REVOLUTE;
      jd.a = j->a < 0 ? CAROM_NULL_BODY : ids[j->a];
      jd.b = ids[j->b];
      jd.x = j->x, jd.y = j->y;
      jd.enable_limit = j->enable_limit;
      jd.lower = j->lower, jd.upper = j->upper;
      st = carom_world_add_joint (world, &jd, joints ? &joints[i] : NULL);
      if (st != CAROM_OK)
        {
          if (failed)
            *failed = i;
          return st;
        }
    }
  return CAROM_OK;
}
