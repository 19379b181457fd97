/* The world: settings, the body slots and each pipeline stage's state. */
#ifndef CAROM_WORLD_H
#define CAROM_WORLD_H

#include "body.h"
#include "carom.h"
#include "contact.h"
#include "broadphase.h"
#include "events.h"
#include "joint.h"

struct carom_world {
  carom_allocator allocator;
  carom_world_def def; /* settings; def.allocator is the caller's copy */
  vec2 gravity;
  uint64_t updates;     /* carom_world_update calls that succeeded */

  /* bodies: slots [0, slot_count), some dead; dead slots are reused LIFO */
  body *bodies;
  int32_t slot_count, slot_cap, live_count;
  int32_t most_pieces;  /* the most convex pieces any body has had (0
                           before any): bounds the contacts of one pair */
  int32_t *free_slots;
  int32_t free_count, free_cap;
  double *unload;   /* three per slot, reserved with each slot: removing a
                       body takes its weight off what it rested on
                       (contacts_forget_body) without allocating */
  int32_t unload_cap;

  broadphase broad;
  contacts contacts;
  joints joints;
  joint_tree joint_tree;               /* the joints' direct solve (joint_tree.c) */
  struct solver_body *solver_bodies; /* one per slot (solver.c), two cache lines each, */
  void *solver_room;                 /* from a line on in this block (mem_reserve_lines) */
  int32_t solver_cap;
  int32_t *solver_scratch;           /* the levels and level order of shock.c */
  int32_t scratch_cap;
  int32_t level_count;               /* contacts in that order this step, -1: not yet ordered */
  double *cold_load;                 /* per slot: the cold start's load (shock.c) */
  int32_t cold_load_cap;
  int32_t shock_count;               /* contacts it may hold this step */
  struct shock_row *shock_rows;      /* and what it reads of them (shock.c):
                                        all, or with waves those of more
                                        points, each wave's in a run */
  int32_t shock_cap;
  struct shock_point *shock_points;  /* the rows' points, in row order */
  int32_t shock_point_cap;
  int32_t shock_waves;               /* the rows' waves, 0: solved one at a time */
  struct shock_batch *shock_batches; /* the waves' rows four at a time, */
  void *shock_room;                  /* from a cache line on in this block (mem_reserve_lines) */
  int32_t shock_batch_cap;
  int32_t shock_batch_want;          /* batches a step wanted past the room */
  int32_t *shock_scratch;            /* the waves' making and bounds */
  int32_t shock_scratch_cap;
  int32_t *restitution_list;         /* the struck contacts of a step */
  int32_t restitution_cap;
  struct impact_shift *impact_shifts; /* per slot, and the contacts an
                                         impact acted on (contact_impacts) */
  int32_t impact_shift_cap;
  int32_t *impact_events;
  int32_t impact_events_cap;
  struct impact_saved *impact_saved; /* what contact_impacts replays from:
                                        per slot, and the contacts */
  int32_t impact_saved_cap;
  struct contact *saved_contacts;
  int32_t saved_contacts_cap;
  struct contact_point *saved_points;
  int32_t saved_points_cap;
  struct contact_batch *batches;     /* the coloured contacts, eight a batch (contact_batch.c), */
  void *batch_room;                  /* from a cache line on in this block (mem_reserve_lines) */
  int32_t batch_count, batch_cap;
  uint32_t *colour_used;             /* per slot: the colours its constraints took */
  int32_t colour_cap;
  int32_t *batch_scratch;            /* colouring's order of the contacts */
  int32_t batch_scratch_cap;
  int solver_path;                   /* the kernels this CPU runs (solver_path) */

  /* effects beyond uniform gravity, each off until set (effects.c) */
  struct {
    int active;
    vec2 center;
    double gm, softening2;
  } central;
  double damping_linear, damping_angular;
  int sleeping;
  int continuous;      /* speculative contacts as far as bodies can travel (on by default) */
  int forces_active;   /* some body has a force or torque for the next update (force.c) */
  int32_t sensor_count; /* live sensor bodies */
  int seams_dirty;     /* static bodies changed: their internal edges are
                          marked again before the next detection (seams.c) */
  events events;       /* the last update's touching pairs and events (events.c) */
};

/* Run the solver's kernels on `path` (a solver_path, contact_batch.h) from
 * the next update on; 0 if this CPU cannot (nothing changes). For the test
 * that every path gives the same bits. */
int world_set_solver_path (carom_world *world, int path);

#endif
