/* The joint store and the joint calls of the public API: slots with ids
 * that detect staleness (slot index + generation, as for bodies), each
 * body's doubly linked list of its joints (so removing a body removes its
 * joints, and a pair's filter finds them), and the checks of a def. The
 * constraints themselves are in joint_solver.c. */
#include "joint.h"

#include <string.h>

#include "world.h"

/* Mouse joint defaults where the def leaves 0 (carom.h) */
#define MOUSE_HERTZ 5.0
#define MOUSE_DAMPING_RATIO 0.7

void joints_init (carom_world *world)
{
  memset (&world->joints, 0, sizeof world->joints);
}

void joints_destroy (carom_world *world)
{
  joints *js = &world->joints;
  mem_free (&world->allocator, js->list, (size_t) js->cap * sizeof (joint));
  mem_free (&world->allocator, js->free_slots, (size_t) js->free_cap * sizeof (int32_t));
  joints_init (world);
}

carom_joint_id joint_id_of (const carom_world *world, int32_t slot)
{
  return ((uint64_t) world->joints.list[slot].generation << 32) | (uint64_t) (uint32_t) (slot + 1);
}

joint *joint_lookup (const carom_world *world, carom_joint_id id)
{
  uint64_t index = id & 0xffffffffu;
  joint *j;
  if (!world || index == 0 || index > (uint64_t) world->joints.count)
    return NULL;
  j = &world->joints.list[index - 1];
  return j->alive && j->generation == (uint32_t) (id >> 32) ? j : NULL;
}

/* ------------------------------------------------------- the body lists */

static int32_t *edge_next (carom_world *world, int32_t key)
{
  return &world->joints.list[(key - 1) >> 1].next[(key - 1) & 1];
}

static int32_t *edge_prev (carom_world *world, int32_t key)
{
  return &world->joints.list[(key - 1) >> 1].prev[(key - 1) & 1];
}

static void link (carom_world *world, int32_t slot, int32_t side)
{
  joint *j = &world->joints.list[slot];
  int32_t body_slot = side ? j->b : j->a;
  int32_t key = 2 * slot + side + 1;
  body *b;
  if (body_slot < 0)
    return;
  b = &world->bodies[body_slot];
  j->next[side] = b->joint_head;
  j->prev[side] = 0;
  if (b->joint_head)
    *edge_prev (world, b->joint_head) = key;
  b->joint_head = key;
  b->joint_count++;
}

static void unlink (carom_world *world, int32_t slot, int32_t side)
{
  joint *j = &world->joints.list[slot];
  int32_t body_slot = side ? j->b : j->a;
  body *b;
  if (body_slot < 0)
    return;
  b = &world->bodies[body_slot];
  if (j->prev[side])
    *edge_next (world, j->prev[side]) = j->next[side];
  else
    b->joint_head = j->next[side];
  if (j->next[side])
    *edge_prev (world, j->next[side]) = j->prev[side];
  b->joint_count--;
}

static void joint_free (carom_world *world, int32_t slot)
{
  joint *j = &world->joints.list[slot];
  unlink (world, slot, 0);
  unlink (world, slot, 1);
  j->alive = 0;
  j->generation = j->generation == UINT32_MAX ? 1 : j->generation + 1;
  world->joints.free_slots[world->joints.free_count++] = slot; /* room reserved at creation */
  world->joints.live--;
  world->broad.dirty = 1; /* the pair may collide again */
}

void joints_forget_body (carom_world *world, int32_t slot)
{
  body *b = &world->bodies[slot];
  while (b->joint_head)
    {
      int32_t js = (b->joint_head - 1) >> 1;
      joint *j = &world->joints.list[js];
      int32_t other = j->a == slot ? j->b : j->a;
      if (other >= 0 && world->bodies[other].type == CAROM_DYNAMIC)
        body_wake (&world->bodies[other]);
      joint_free (world, js);
    }
}

int joints_block_pair (const carom_world *world, int32_t a, int32_t b)
{
  const body *A = &world->bodies[a], *B = &world->bodies[b];
  int32_t key;
  if (!A->joint_head || !B->joint_head)
    return 0;
  if (A->joint_count > B->joint_count)
    {
      int32_t t = a;
      a = b, b = t;
      A = B;
    }
  /* walk the shorter list */
  for (key = A->joint_head; key;)
    {
      const joint *j = &world->joints.list[(key - 1) >> 1];
      int32_t side = (key - 1) & 1;
      if ((side ? j->a : j->b) == b && !j->collide_connected)
        return 1;
      key = j->next[side];
    }
  return 0;
}

void joint_anchors (const carom_world *world, const joint *j, vec2 *pa, vec2 *pb)
{
  const body *B = &world->bodies[j->b];
  *pb = v2_add (B->p, rot2_apply (B->q, j->local_b));
  if (j->type == CAROM_JOINT_MOUSE)
    *pa = j->target;
  else if (j->a < 0)
    *pa = j->local_a;
  else
    {
      const body *A = &world->bodies[j->a];
      *pa = v2_add (A->p, rot2_apply (A->q, j->local_a));
    }
}

/* ------------------------------------------------------------- the API */

#define JOINT_DEF_SIZE_0_2 sizeof (carom_joint_def)

carom_status carom_joint_def_init (carom_joint_def *def, uint32_t size)
{
  if (!def)
    return CAROM_ERR_NULL_ARGUMENT;
  if (size != JOINT_DEF_SIZE_0_2)
    return CAROM_ERR_BAD_STRUCT_SIZE;
  memset (def, 0, size);
  def->size = size;
  return CAROM_OK;
}

static carom_status check_def (const carom_world *world, const carom_joint_def *d, body **pa, body **pb)
{
  const double values[] = {d->x, d->y, d->x2, d->y2, d->axis_x, d->axis_y, d->lower, d->upper, d->motor_speed,
                           d->max_motor_force, d->hertz, d->damping_ratio, d->length, d->max_motor_torque};
  size_t i;
  if (d->size != JOINT_DEF_SIZE_0_2)
    return CAROM_ERR_BAD_STRUCT_SIZE;
  for (i = 0; i < sizeof values / sizeof values[0]; ++i)
    if (!is_finite (values[i]))
      return CAROM_ERR_NOT_FINITE;
  for (i = 0; i < sizeof values / sizeof values[0]; ++i)
    if (!is_moderate (values[i]))
      return CAROM_ERR_BAD_ARGUMENT;
  if ((uint32_t) d->type > (uint32_t) CAROM_JOINT_MOUSE)
    return CAROM_ERR_BAD_ARGUMENT;
  *pa = NULL;
  if (d->a != CAROM_NULL_BODY)
    {
      *pa = body_lookup (world, d->a);
      if (!*pa)
        return CAROM_ERR_STALE_BODY;
    }
  *pb = body_lookup (world, d->b);
  if (!*pb)
    return CAROM_ERR_STALE_BODY;
  if (d->a == d->b || (d->type == CAROM_JOINT_MOUSE && d->a != CAROM_NULL_BODY))
    return CAROM_ERR_BAD_ARGUMENT;
  if ((d->enable_limit && d->lower > d->upper) || d->max_motor_force < 0.0 || d->max_motor_torque < 0.0
      || d->hertz < 0.0 || d->damping_ratio < 0.0 || d->length < 0.0)
    return CAROM_ERR_BAD_ARGUMENT;
  if ((d->type == CAROM_JOINT_PRISMATIC || d->type == CAROM_JOINT_WHEEL)
      && !(d->axis_x * d->axis_x + d->axis_y * d->axis_y > 0.0))
    return CAROM_ERR_BAD_ARGUMENT;
  if (d->type == CAROM_JOINT_DISTANCE && d->length == 0.0
      && !(v2_len (v2 (d->x2 - d->x, d->y2 - d->y)) > 1e-12 * (1.0 + fabs (d->x) + fabs (d->y))))
    return CAROM_ERR_BAD_ARGUMENT;
  if ((*pa == NULL || (*pa)->type != CAROM_DYNAMIC) && (*pb)->type != CAROM_DYNAMIC)
    return CAROM_ERR_STATIC_BODY;
  return CAROM_OK;
}

/* A body's frame for the joint: its centre of mass and rotation (the world
 * for NULL). */
static xform frame_of (const body *b)
{
  xform x;
  if (!b)
    {
      x.p = v2 (0.0, 0.0);
      x.q.c = 1.0, x.q.s = 0.0;
      return x;
    }
  x.p = b->p, x.q = b->q;
  return x;
}

carom_status carom_world_add_joint (carom_world *world, const carom_joint_def *def, carom_joint_id *id)
{
  joints *js;
  body *A, *B;
  joint *j;
  xform fa, fb;
  vec2 anchor_a, anchor_b;
  int32_t slot;
  carom_status st;
  if (!world || !def)
    return CAROM_ERR_NULL_ARGUMENT;
  st = check_def (world, def, &A, &B);
  if (st != CAROM_OK)
    return st;
  js = &world->joints;
  if (js->free_count == 0 && js->count >= INT32_MAX / 2 - 1)
    return CAROM_ERR_OUT_OF_MEMORY;
  if ((js->free_count == 0
       && !mem_reserve (&world->allocator, (void **) &js->list, &js->cap, js->count + 1, sizeof (joint)))
      || !mem_reserve (&world->allocator, (void **) &js->free_slots, &js->free_cap, js->live + 1,
                       sizeof (int32_t)))
    return CAROM_ERR_OUT_OF_MEMORY;
  if (js->free_count > 0)
    slot = js->free_slots[--js->free_count];
  else
    {
      slot = js->count++;
      js->list[slot].generation = 1;
    }
  j = &js->list[slot];
  {
    uint32_t generation = j->generation;
    memset (j, 0, sizeof *j);
    j->generation = generation;
  }
  j->alive = 1;
  j->type = def->type;
  j->a = A ? (int32_t) (A - world->bodies) : -1;
  j->b = (int32_t) (B - world->bodies);
  j->collide_connected = def->collide_connected != 0;
  j->enable_limit = def->enable_limit != 0;
  j->enable_motor = def->enable_motor != 0;
  j->enable_spring = def->enable_spring != 0;
  j->lower = def->lower;
  j->upper = def->upper;
  j->motor_speed = def->motor_speed;
  j->max_motor_force = def->max_motor_force;
  j->max_motor_torque = def->max_motor_torque;
  j->hertz = def->hertz;
  j->damping_ratio = def->damping_ratio;
  fa = frame_of (A);
  fb = frame_of (B);
  anchor_a = v2 (def->x, def->y);
  anchor_b = def->type == CAROM_JOINT_DISTANCE ? v2 (def->x2, def->y2) : anchor_a;
  if (def->type == CAROM_JOINT_MOTOR)
    anchor_a = anchor_b = B->p; /* b's centre, held where it is in a's frame */
  j->local_a = xform_apply_inv (fa, anchor_a);
  j->local_b = xform_apply_inv (fb, anchor_b);
  j->reference_angle = B->angle - (A ? A->angle : 0.0);
  if (def->type == CAROM_JOINT_PRISMATIC || def->type == CAROM_JOINT_WHEEL)
    j->local_axis = rot2_apply_inv (fa.q, v2_normalize (v2 (def->axis_x, def->axis_y)));
  j->length = def->length > 0.0 ? def->length : v2_len (v2_sub (anchor_b, anchor_a));
  if (def->type == CAROM_JOINT_MOUSE)
    {
      j->target = anchor_a;
      if (j->hertz == 0.0)
        j->hertz = MOUSE_HERTZ;
      if (j->damping_ratio == 0.0)
        j->damping_ratio = MOUSE_DAMPING_RATIO;
    }
  if (def->type == CAROM_JOINT_MOTOR)
    {
      j->reference_angle = 0.0;
      j->target_angle = B->angle - (A ? A->angle : 0.0);
    }
  link (world, slot, 0);
  link (world, slot, 1);
  js->live++;
  if (A && A->type == CAROM_DYNAMIC)
    body_wake (A);
  if (B->type == CAROM_DYNAMIC)
    body_wake (B);
  world->broad.dirty = 1; /* pairs it now keeps apart */
  if (id)
    *id = joint_id_of (world, slot);
  return CAROM_OK;
}

/* The joint of a call: the status for a NULL world or a stale id, with
 * *j NULL, or OK. */
static carom_status live_joint (const carom_world *world, carom_joint_id id, joint **j)
{
  *j = world ? joint_lookup (world, id) : NULL;
  return !world ? CAROM_ERR_NULL_ARGUMENT : *j ? CAROM_OK : CAROM_ERR_STALE_JOINT;
}

/* Write a pair of numbers to the outputs a call was given. */
static void put2 (double *x, double *y, vec2 v)
{
  if (x)
    *x = v.x;
  if (y)
    *y = v.y;
}

carom_status carom_world_remove_joint (carom_world *world, carom_joint_id id)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  if (j->a >= 0 && world->bodies[j->a].type == CAROM_DYNAMIC)
    body_wake (&world->bodies[j->a]);
  if (world->bodies[j->b].type == CAROM_DYNAMIC)
    body_wake (&world->bodies[j->b]);
  joint_free (world, (int32_t) (j - world->joints.list));
  return CAROM_OK;
}

carom_status carom_joint_check (const carom_world *world, carom_joint_id id)
{
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  return joint_lookup (world, id) ? CAROM_OK : CAROM_ERR_STALE_JOINT;
}

int32_t carom_world_joint_count (const carom_world *world)
{
  return world ? world->joints.live : 0;
}

int32_t carom_world_get_joints (const carom_world *world, carom_joint_id *ids, int32_t capacity)
{
  int32_t i, k = 0;
  if (!world || (!ids && capacity > 0))
    return -CAROM_ERR_NULL_ARGUMENT;
  if (capacity < 0)
    return -CAROM_ERR_BAD_ARGUMENT;
  for (i = 0; i < world->joints.count; ++i)
    if (world->joints.list[i].alive)
      {
        if (k < capacity)
          ids[k] = joint_id_of (world, i);
        k++;
      }
  return k;
}

int32_t carom_body_get_joints (const carom_world *world, carom_body_id id, carom_joint_id *ids, int32_t capacity)
{
  const body *b;
  int32_t key, k = 0;
  if (!world || (!ids && capacity > 0))
    return -CAROM_ERR_NULL_ARGUMENT;
  if (capacity < 0)
    return -CAROM_ERR_BAD_ARGUMENT;
  b = body_lookup (world, id);
  if (!b)
    return -CAROM_ERR_STALE_BODY;
  for (key = b->joint_head; key;)
    {
      int32_t slot = (key - 1) >> 1;
      if (k < capacity)
        ids[k] = joint_id_of (world, slot);
      k++;
      key = world->joints.list[slot].next[(key - 1) & 1];
    }
  return k;
}

carom_status carom_joint_get_bodies (const carom_world *world, carom_joint_id id, carom_joint_type *type,
                                     carom_body_id *a, carom_body_id *b)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  if (type)
    *type = j->type;
  if (a)
    *a = j->a < 0 ? CAROM_NULL_BODY : body_id_of (world, j->a);
  if (b)
    *b = body_id_of (world, j->b);
  return CAROM_OK;
}

carom_status carom_joint_get_anchors (const carom_world *world, carom_joint_id id, double *ax, double *ay,
                                      double *bx, double *by)
{
  joint *j;
  vec2 pa, pb;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  joint_anchors (world, j, &pa, &pb);
  put2 (ax, ay, pa);
  put2 (bx, by, pb);
  return CAROM_OK;
}

carom_status carom_joint_get_reaction (const carom_world *world, carom_joint_id id, double *fx, double *fy,
                                       double *torque)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  put2 (fx, fy, j->reaction_force);
  if (torque)
    *torque = j->reaction_torque;
  return CAROM_OK;
}

static void wake_joint (carom_world *world, const joint *j)
{
  if (j->a >= 0 && world->bodies[j->a].type == CAROM_DYNAMIC)
    body_wake (&world->bodies[j->a]);
  if (world->bodies[j->b].type == CAROM_DYNAMIC)
    body_wake (&world->bodies[j->b]);
}

carom_status carom_joint_set_motor (carom_world *world, carom_joint_id id, int32_t enable, double speed,
                                    double max_force)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  if (!is_finite (speed) || !is_finite (max_force))
    return CAROM_ERR_NOT_FINITE;
  if (j->type == CAROM_JOINT_MOTOR || j->type == CAROM_JOINT_MOUSE || j->type == CAROM_JOINT_WELD
      || max_force < 0.0 || !is_moderate (speed) || !is_moderate (max_force))
    return CAROM_ERR_BAD_ARGUMENT;
  j->enable_motor = enable != 0;
  j->motor_speed = speed;
  j->max_motor_force = max_force;
  if (!j->enable_motor)
    j->motor_impulse = 0.0;
  wake_joint (world, j);
  return CAROM_OK;
}

carom_status carom_joint_set_limit (carom_world *world, carom_joint_id id, int32_t enable, double lower, double upper)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  if (!is_finite (lower) || !is_finite (upper))
    return CAROM_ERR_NOT_FINITE;
  if (j->type == CAROM_JOINT_WELD || j->type == CAROM_JOINT_MOTOR || j->type == CAROM_JOINT_MOUSE
      || !is_moderate (lower) || !is_moderate (upper) || (enable && lower > upper))
    return CAROM_ERR_BAD_ARGUMENT;
  j->enable_limit = enable != 0;
  j->lower = lower;
  j->upper = upper;
  wake_joint (world, j);
  return CAROM_OK;
}

carom_status carom_joint_set_spring (carom_world *world, carom_joint_id id, int32_t enable, double hertz,
                                     double damping_ratio)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  if (!is_finite (hertz) || !is_finite (damping_ratio))
    return CAROM_ERR_NOT_FINITE;
  if (j->type == CAROM_JOINT_MOTOR || hertz < 0.0 || damping_ratio < 0.0 || !is_moderate (hertz)
      || !is_moderate (damping_ratio))
    return CAROM_ERR_BAD_ARGUMENT;
  if (j->type == CAROM_JOINT_MOUSE)
    {
      j->hertz = hertz > 0.0 ? hertz : MOUSE_HERTZ;
      j->damping_ratio = damping_ratio > 0.0 ? damping_ratio : MOUSE_DAMPING_RATIO;
    }
  else
    {
      j->enable_spring = enable != 0;
      j->hertz = hertz;
      j->damping_ratio = damping_ratio;
    }
  wake_joint (world, j);
  return CAROM_OK;
}

carom_status carom_joint_set_target (carom_world *world, carom_joint_id id, double x, double y, double angle)
{
  joint *j;
  carom_status st = live_joint (world, id, &j);
  if (st != CAROM_OK)
    return st;
  if (!is_finite (x) || !is_finite (y) || !is_finite (angle))
    return CAROM_ERR_NOT_FINITE;
  if ((j->type != CAROM_JOINT_MOUSE && j->type != CAROM_JOINT_MOTOR) || !is_moderate (x) || !is_moderate (y)
      || !is_moderate (angle))
    return CAROM_ERR_BAD_ARGUMENT;
  if (j->type == CAROM_JOINT_MOUSE)
    j->target = v2 (x, y);
  else
    {
      j->local_a = v2 (x, y);
      j->target_angle = angle;
    }
  wake_joint (world, j);
  return CAROM_OK;
}
