/* Allocation failure, injected at every allocation a scenario makes.
 *
 * A checking allocator fails exactly its k-th allocation (or every one from
 * the k-th on) and records every block with the size it was asked for. The
 * scenario (a world with the allocator; a circle, a box, a regular polygon
 * and a concave U; detect; 30 steps with contacts; a removal; another body;
 * destroy) runs for k = 1, 2, ... until it completes without meeting the
 * failure. For every k:
 *   - the call that meets the failure returns CAROM_ERR_OUT_OF_MEMORY, and no
 *     call returns it without having met a failure;
 *   - it changes nothing: no body added, every body's state and the contact
 *     list as before (the promise of include/carom.h), with any number of
 *     sub-steps;
 *   - the world stays usable: the same call, repeated once allocations
 *     succeed again, succeeds;
 *   - and it then goes on exactly as if nothing had failed: every call's
 *     result equals, bit for bit, that of a reference world run in lockstep
 *     whose allocations never fail (so a failure loses nothing the next
 *     steps depend on, such as the impulses kept for warm starting);
 *   - at the end every byte is freed, and `free` got the size `alloc` got.
 * The scene loader is run the same way through the def it takes. */
#include "support.h"
#include "world.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ allocator */

enum { FAIL_ONCE, FAIL_FROM };

/* Blocks carry a header with the requested size and a tag, so `free` can be
 * checked against what `alloc` handed out. */
typedef struct block_header {
  size_t size;
  unsigned long tag;
  unsigned long pad[2]; /* keeps the user block 16-byte aligned */
} block_header;

#define BLOCK_TAG 0xC0FFEE42ul

typedef struct checking_alloc {
  long calls;          /* allocations asked for */
  long fail_at;        /* 1-based call that fails; 0: never */
  int mode;            /* FAIL_ONCE or FAIL_FROM */
  long failures;       /* allocations refused so far */
  long live_blocks;
  size_t live_bytes;
  long bad_frees;      /* size mismatch, unknown block, NULL */
  long bad_users;      /* wrong `user` pointer */
} checking_alloc;

static void *checking_alloc_fn (size_t size, void *user)
{
  checking_alloc *c = user;
  block_header *h;
  c->calls++;
  if (c->fail_at > 0 && (c->calls == c->fail_at || (c->mode == FAIL_FROM && c->calls > c->fail_at)))
    {
      c->failures++;
      return NULL;
    }
  h = malloc (sizeof *h + size);
  if (!h)
    return NULL;
  h->size = size;
  h->tag = BLOCK_TAG;
  c->live_blocks++;
  c->live_bytes += size;
  return h + 1;
}

static void checking_free_fn (void *ptr, size_t size, void *user)
{
  checking_alloc *c = user;
  block_header *h;
  if (!ptr)
    {
      c->bad_frees++; /* mem_free never passes NULL on */
      return;
    }
  h = (block_header *) ptr - 1;
  if (h->tag != BLOCK_TAG || h->size != size)
    {
      c->bad_frees++;
      fprintf (stderr, "free: block of %zu bytes freed as %zu (tag %lx)\n", h->size, size, h->tag);
      return; /* leaked on purpose: Valgrind reports it too */
    }
  h->tag = 0;
  c->live_blocks--;
  c->live_bytes -= size;
  free (h);
}

static void checking_reset (checking_alloc *c, long fail_at, int mode)
{
  memset (c, 0, sizeof *c);
  c->fail_at = fail_at;
  c->mode = mode;
}

static void use_allocator (carom_world_def *def, checking_alloc *c)
{
  assert_status (carom_world_def_init (def, sizeof *def), CAROM_OK);
  def->allocator.alloc = checking_alloc_fn;
  def->allocator.free = checking_free_fn;
  def->allocator.user = c;
}

/* ------------------------------------------------------- world snapshots */

#define MAX_IDS 128
#define MAX_CONTACTS 512
#define MAX_EVENTS 256

typedef struct body_state {
  carom_body_id id;
  double x, y, angle, vx, vy, spin, mass, inertia, area;
} body_state;

typedef struct contact_state {
  carom_body_id a, b;
  double px, py, nx, ny, depth;
} contact_state;

typedef struct world_state {
  int32_t body_count, contact_count, event_count, joint_count;
  body_state bodies[MAX_IDS];
  contact_state contacts[MAX_CONTACTS];
  carom_contact_event events[MAX_EVENTS];
} world_state;

static void snapshot (const carom_world *w, world_state *s)
{
  carom_body_id ids[MAX_IDS];
  int32_t i;
  memset (s, 0, sizeof *s);
  s->body_count = carom_world_get_bodies (w, ids, MAX_IDS);
  s->joint_count = carom_world_joint_count (w);
  assert_true (s->body_count <= MAX_IDS);
  assert_int_equal (s->body_count, carom_world_body_count (w));
  for (i = 0; i < s->body_count; ++i)
    {
      body_state *b = &s->bodies[i];
      b->id = ids[i];
      assert_status (carom_body_get_position (w, ids[i], &b->x, &b->y), CAROM_OK);
      assert_status (carom_body_get_angle (w, ids[i], &b->angle), CAROM_OK);
      assert_status (carom_body_get_velocity (w, ids[i], &b->vx, &b->vy), CAROM_OK);
      assert_status (carom_body_get_spin (w, ids[i], &b->spin), CAROM_OK);
      assert_status (carom_body_get_mass (w, ids[i], &b->mass, &b->inertia, &b->area), CAROM_OK);
    }
  s->event_count = carom_world_get_events (w, s->events, MAX_EVENTS);
  assert_true (s->event_count >= 0 && s->event_count <= MAX_EVENTS);
  s->contact_count = carom_world_contact_count (w);
  for (i = 0; i < s->contact_count && i < MAX_CONTACTS; ++i)
    {
      contact_state *c = &s->contacts[i];
      assert_status (carom_world_get_contact (w, i, &c->a, &c->b, &c->px, &c->py, &c->nx, &c->ny, &c->depth),
                     CAROM_OK);
    }
}

/* Bit-for-bit the same bodies and contacts: 1, or 0 and what differs. */
static int same_state (const world_state *a, const world_state *b, char *why, size_t why_size)
{
  int32_t i;
  if (a->body_count != b->body_count)
    {
      snprintf (why, why_size, "the body count went from %d to %d", (int) a->body_count, (int) b->body_count);
      return 0;
    }
  for (i = 0; i < a->body_count; ++i)
    if (memcmp (&a->bodies[i], &b->bodies[i], sizeof a->bodies[i]) != 0)
      {
        snprintf (why, why_size, "body %d changed: x %.17g -> %.17g, y %.17g -> %.17g, vy %.17g -> %.17g", (int) i,
                  a->bodies[i].x, b->bodies[i].x, a->bodies[i].y, b->bodies[i].y, a->bodies[i].vy,
                  b->bodies[i].vy);
        return 0;
      }
  if (a->joint_count != b->joint_count)
    {
      snprintf (why, why_size, "the joint count went from %d to %d", (int) a->joint_count, (int) b->joint_count);
      return 0;
    }
  if (a->event_count != b->event_count || memcmp (a->events, b->events, sizeof a->events) != 0)
    {
      snprintf (why, why_size, "the events changed (%d, then %d of them)", (int) a->event_count,
                (int) b->event_count);
      return 0;
    }
  if (a->contact_count != b->contact_count)
    {
      snprintf (why, why_size, "the contact count went from %d to %d", (int) a->contact_count,
                (int) b->contact_count);
      return 0;
    }
  for (i = 0; i < a->contact_count && i < MAX_CONTACTS; ++i)
    if (memcmp (&a->contacts[i], &b->contacts[i], sizeof a->contacts[i]) != 0)
      {
        snprintf (why, why_size, "contact %d changed", (int) i);
        return 0;
      }
  return 1;
}

static void assert_world_finite (const carom_world *w)
{
  world_state *s = malloc (sizeof *s);
  int32_t i;
  assert_non_null (s);
  snapshot (w, s);
  for (i = 0; i < s->body_count; ++i)
    {
      const body_state *b = &s->bodies[i];
      assert_true (isfinite (b->x) && isfinite (b->y) && isfinite (b->angle) && isfinite (b->vx)
                   && isfinite (b->vy) && isfinite (b->spin));
    }
  free (s);
}

/* ------------------------------------------------------------- scenario */

typedef enum step_kind {
  ADD_GROUND,
  ADD_CIRCLE,
  ADD_BOX,
  ADD_REGULAR,
  ADD_U,
  ADD_LATE_BOX,
  ADD_SENSOR,
  ADD_KINEMATIC,
  ADD_COMPOUND,
  ADD_JOINTS,
  DETECT,
  UPDATE,
  REMOVE,
  REMOVE_JOINT,
  PUSH,
  QUERY
} step_kind;


typedef struct scenario {
  checking_alloc *alloc;
  carom_world *w;
  long k;
  int oom_calls;          /* calls that returned OUT_OF_MEMORY */
  int32_t max_contacts;   /* most contact points seen after a step */
  carom_body_id circle, box;
  carom_joint_id hinge;   /* the box's joint to the world (ADD_JOINTS) */
  /* the same calls on a world whose allocations never fail (FAIL_ONCE) */
  carom_world *ref;
  world_state *ref_state; /* after its last call */
} scenario;

/* The reference world: the def's settings with the default allocator. */
static void start_reference (scenario *sc, const carom_world_def *def)
{
  carom_world_def d = *def;
  d.allocator.alloc = NULL, d.allocator.free = NULL, d.allocator.user = NULL;
  assert_status (carom_world_init (&sc->ref, &d), CAROM_OK);
  sc->ref_state = malloc (sizeof (world_state));
  assert_non_null (sc->ref_state);
}

static void stop_reference (scenario *sc)
{
  carom_world_destroy (sc->ref);
  sc->ref = NULL;
  free (sc->ref_state);
  sc->ref_state = NULL;
}

static carom_status add_body (carom_world *w, step_kind kind, carom_body_id *id)
{
  static const double u[] = { 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3 };
  carom_body_def d;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  switch (kind)
    {
    case ADD_GROUND:
      d.type = CAROM_STATIC;
      d.y = -0.5;
      return carom_world_add_box (w, &d, 40.0, 1.0, id);
    case ADD_CIRCLE:
      d.x = -3.0, d.y = 0.45; /* overlaps the ground a little: contacts at once */
      return carom_world_add_circle (w, &d, 0.5, id);
    case ADD_BOX:
      d.x = 0.0, d.y = 0.5, d.angle = 0.1;
      return carom_world_add_box (w, &d, 1.0, 1.0, id);
    case ADD_REGULAR:
      d.x = 3.0, d.y = 0.8, d.spin = 1.0;
      return carom_world_add_regular (w, &d, 7, 0.5, id);
    case ADD_U:
      d.x = 0.0, d.y = 2.2, d.vy = -1.0; /* lands on the box */
      return carom_world_add_polygon (w, &d, u, 8, id);
    case ADD_LATE_BOX:
      d.x = -3.0, d.y = 2.0;
      return carom_world_add_box (w, &d, 0.7, 0.3, id);
    case ADD_SENSOR: /* where the U lands: it reports, pushes nothing */
      d.type = CAROM_STATIC, d.sensor = 1, d.x = 0.0, d.y = 1.5;
      return carom_world_add_box (w, &d, 4.0, 1.0, id);
    case ADD_KINEMATIC: /* sweeps into the regular polygon */
      d.type = CAROM_KINEMATIC, d.x = 6.0, d.y = 0.6, d.vx = -1.0;
      return carom_world_add_box (w, &d, 0.5, 1.0, id);
    case ADD_COMPOUND: /* a disc, a U (pieces of its own) and a bar, landing left */
      {
        carom_shape_def parts[3];
        int i;
        for (i = 0; i < 3; ++i)
          assert_status (carom_shape_def_init (&parts[i], sizeof parts[i]), CAROM_OK);
        parts[0].radius = 0.4, parts[0].x = -1.0;
        parts[1].kind = CAROM_SHAPE_POLYGON, parts[1].xy = u, parts[1].count = 8, parts[1].angle = 0.2;
        parts[1].density = 0.5, parts[1].friction = 0.9;
        parts[2].kind = CAROM_SHAPE_POLYGON, parts[2].xy = u, parts[2].count = 4, parts[2].x = -1.5;
        d.x = -8.0, d.y = 1.2;
        return carom_world_add_compound (w, &d, parts, 3, id);
      }
    default:
      break;
    }
  fail_msg ("not a body kind: %d", (int) kind);
  return CAROM_ERR_BAD_ARGUMENT;
}

static carom_status do_step (scenario *sc, carom_world *w, step_kind kind)
{
  carom_body_id id = 777;
  carom_status s;
  switch (kind)
    {
    case DETECT:
      return carom_world_detect (w);
    case UPDATE:
      return carom_world_update (w, 1.0 / 60.0);
    case REMOVE:
      return carom_world_remove_body (w, sc->circle);
    case REMOVE_JOINT:
      return carom_world_remove_joint (w, sc->hinge);
    case ADD_JOINTS: /* the box hinged to the world, the circle roped to it, a mouse on the compound */
      {
        carom_joint_def d;
        carom_joint_id ids[3] = { 777, 777, 777 };
        carom_body_id all[16];
        int32_t n = carom_world_get_bodies (w, all, 16);
        carom_joint_def_init (&d, sizeof d);
        d.type = CAROM_JOINT_REVOLUTE, d.b = sc->box, d.x = 1.0, d.y = 3.0;
        s = carom_world_add_joint (w, &d, &ids[0]);
        if (s == CAROM_OK)
          {
            d.type = CAROM_JOINT_DISTANCE, d.a = sc->box, d.b = sc->circle, d.x2 = -1.0, d.y2 = 1.0;
            d.enable_spring = 1, d.hertz = 2.0;
            s = carom_world_add_joint (w, &d, &ids[1]);
          }
        if (s == CAROM_OK)
          {
            carom_joint_def_init (&d, sizeof d);
            d.type = CAROM_JOINT_MOUSE, d.b = all[n - 1], d.x = -8.0, d.y = 1.2, d.max_motor_force = 100.0;
            s = carom_world_add_joint (w, &d, &ids[2]);
          }
        if (s != CAROM_OK)
          {
            /* each call is checked alone: undo the ones that went in */
            int i;
            for (i = 0; i < 3; ++i)
              if (ids[i] != 777)
                assert_status (carom_world_remove_joint (w, ids[i]), CAROM_OK);
            return s;
          }
        sc->hinge = ids[0];
        /* setting a limit and a spring later allocates nothing */
        {
          long calls = sc->alloc->calls;
          assert_status (carom_joint_set_limit (w, ids[0], 1, -1.0, 1.0), CAROM_OK);
          assert_status (carom_joint_set_spring (w, ids[1], 1, 3.0, 0.5), CAROM_OK);
          if (w != sc->ref)
            assert_true (sc->alloc->calls == calls);
        }
        return CAROM_OK;
      }
    case PUSH: /* forces and impulses allocate nothing; they act on the next update */
      s = carom_body_apply_force (w, sc->box, 5.0, 0.0, 0.1, 0.6);
      if (s == CAROM_OK)
        s = carom_body_apply_impulse (w, sc->box, 0.0, 0.1, 0.0, 0.5);
      return s;
    case QUERY: /* queries, events, the debug draw and the shape getters allocate nothing */
      {
        carom_ray_hit hit;
        carom_body_id ids[8];
        carom_debug_draw draw;
        long calls = sc->alloc->calls;
        assert_status (carom_world_cast_ray (w, -10.0, 0.5, 10.0, 0.5, ~0u, &hit), CAROM_OK);
        assert_true (carom_world_query_aabb (w, -5.0, -1.0, 5.0, 3.0, ~0u, ids, 8) >= 0);
        assert_true (carom_world_query_point (w, 0.0, 0.5, ~0u, ids, 8) >= 0);
        assert_true (carom_world_get_events (w, NULL, 0) >= 0);
        {
          carom_joint_id joints[4];
          assert_true (carom_world_get_joints (w, joints, 4) >= 0);
          if (sc->box)
            assert_true (carom_body_get_joints (w, sc->box, joints, 4) >= 0);
        }
        assert_status (carom_debug_draw_init (&draw, sizeof draw), CAROM_OK);
        assert_status (carom_world_draw (w, &draw), CAROM_OK);
        {
          /* and the shapes of every body, compounds included */
          int32_t n = carom_world_get_bodies (w, ids, 8), i, count, k;
          for (i = 0; i < n && i < 8; ++i)
            {
              double xy[16], density;
              assert_status (carom_body_get_shape_count (w, ids[i], &count), CAROM_OK);
              for (k = 0; k < count; ++k)
                {
                  assert_status (carom_body_get_shape_geometry (w, ids[i], k, NULL, NULL, NULL, NULL, xy, 8, NULL),
                                 CAROM_OK);
                  assert_status (carom_body_get_shape_material (w, ids[i], k, &density, NULL, NULL), CAROM_OK);
                }
            }
        }
        if (w != sc->ref)
          assert_true (sc->alloc->calls == calls);
        return CAROM_OK;
      }
    default:
      s = add_body (w, kind, &id);
      if (s == CAROM_OK)
        {
          assert_status (carom_body_check (w, id), CAROM_OK);
          if (kind == ADD_CIRCLE)
            sc->circle = id;
          if (kind == ADD_BOX)
            sc->box = id;
        }
      else
        assert_true (id == 777); /* *id untouched on failure */
      return s;
    }
}

/* The call on the reference world, and its state after it. (The removal
 * names the reference's own circle: ids are equal in the two worlds.) */
static void reference_step (scenario *sc, step_kind kind)
{
  assert_status (do_step (sc, sc->ref, kind), CAROM_OK);
  snapshot (sc->ref, sc->ref_state);
}

static const char *step_name (step_kind kind)
{
  static const char *names[] = { "add ground", "add circle", "add box", "add regular", "add U",
                                 "add late box", "add sensor", "add kinematic", "add compound", "add joints", "detect", "update", "remove",
                                 "remove joint", "push", "query" };
  return names[kind];
}

/* One call of the scenario, checked as the header comment says; repeated
 * once after an out-of-memory failure (FAIL_ONCE: allocations succeed again). */
static int checked_call (scenario *sc, step_kind kind)
{
  world_state *before = malloc (sizeof *before), *after = malloc (sizeof *after);
  long failures = sc->alloc->failures;
  carom_status s;
  char why[256];
  int ok = 1;
  assert_non_null (before);
  assert_non_null (after);
  snapshot (sc->w, before);
  if (sc->ref)
    reference_step (sc, kind);
  s = do_step (sc, sc->w, kind);
  snapshot (sc->w, after);
  if (s == CAROM_ERR_OUT_OF_MEMORY)
    {
      if (sc->alloc->failures == failures)
        fail_msg ("k=%ld: %s returned OUT_OF_MEMORY although no allocation failed", sc->k, step_name (kind));
      sc->oom_calls++;
      if (!same_state (before, after, why, sizeof why))
        fail_msg ("k=%ld: %s failed but %s", sc->k, step_name (kind), why);
      if (sc->alloc->mode == FAIL_FROM)
        ok = 0;
      else
        {
          s = do_step (sc, sc->w, kind);
          if (s != CAROM_OK)
            fail_msg ("k=%ld: %s repeated after an out-of-memory failure returned %d (%s)", sc->k,
                      step_name (kind), (int) s, carom_status_string (s));
          snapshot (sc->w, after);
          if (sc->ref && !same_state (sc->ref_state, after, why, sizeof why))
            fail_msg ("k=%ld: %s, repeated after an out-of-memory failure, differs from the world whose "
                      "allocations never failed: %s", sc->k, step_name (kind), why);
        }
    }
  else if (s != CAROM_OK)
    fail_msg ("k=%ld: %s returned %d (%s), wanted OK or OUT_OF_MEMORY", sc->k, step_name (kind), (int) s,
              carom_status_string (s));
  else if (sc->ref && !same_state (sc->ref_state, after, why, sizeof why))
    fail_msg ("k=%ld: %s differs from the world whose allocations never failed: %s", sc->k, step_name (kind), why);
  free (before);
  free (after);
  return ok;
}

/* Returns the number of calls that returned OUT_OF_MEMORY. */
static int run_scenario (checking_alloc *c, long k, int mode, carom_narrow_phase narrow, int32_t substeps,
                         int32_t *max_contacts)
{
  static const step_kind adds[] = { ADD_GROUND, ADD_CIRCLE, ADD_BOX,    ADD_REGULAR,
                                    ADD_U,      ADD_SENSOR, ADD_KINEMATIC, ADD_COMPOUND };
  scenario sc;
  carom_world_def def;
  carom_status s;
  size_t i;
  int step;
  int32_t bodies = 0;

  memset (&sc, 0, sizeof sc);
  sc.alloc = c;
  sc.k = k;
  use_allocator (&def, c);
  def.gravity_y = -10.0;
  def.narrow_phase = narrow;
  def.substeps = substeps;
  checking_reset (c, k, mode);

  sc.w = (carom_world *) &sc; /* must come back NULL on failure */
  s = carom_world_init (&sc.w, &def);
  if (s == CAROM_ERR_OUT_OF_MEMORY)
    {
      assert_true (c->failures > 0);
      assert_null (sc.w);
      assert_int_equal (c->live_blocks, 0);
      if (mode == FAIL_FROM)
        return 1;
      sc.oom_calls++;
      s = carom_world_init (&sc.w, &def);
    }
  assert_status (s, CAROM_OK);
  assert_non_null (sc.w);
  if (mode == FAIL_ONCE)
    start_reference (&sc, &def);

  for (i = 0; i < sizeof adds / sizeof adds[0]; ++i)
    {
      if (!checked_call (&sc, adds[i]))
        goto out;
      assert_int_equal (carom_world_body_count (sc.w), ++bodies);
    }
  if (!checked_call (&sc, ADD_JOINTS))
    goto out;
  assert_int_equal (carom_world_joint_count (sc.w), 3);
  if (!checked_call (&sc, DETECT))
    goto out;
  assert_true (carom_world_contact_count (sc.w) > 0);
  for (step = 0; step < 30; ++step)
    {
      if (!checked_call (&sc, UPDATE))
        goto out;
      if (carom_world_contact_count (sc.w) > sc.max_contacts)
        sc.max_contacts = carom_world_contact_count (sc.w);
      assert_world_finite (sc.w);
      if (step % 5 == 2 && (!checked_call (&sc, PUSH) || !checked_call (&sc, QUERY)))
        goto out;
      if (step == 15)
        {
          if (!checked_call (&sc, REMOVE))
            goto out;
          assert_int_equal (carom_world_body_count (sc.w), --bodies);
          assert_status (carom_body_check (sc.w, sc.circle), CAROM_ERR_STALE_BODY);
          if (!checked_call (&sc, ADD_LATE_BOX))
            goto out;
          assert_int_equal (carom_world_body_count (sc.w), ++bodies);
          /* the circle's rope went with it */
          assert_int_equal (carom_world_joint_count (sc.w), 2);
        }
      if (step == 20)
        {
          if (!checked_call (&sc, REMOVE_JOINT))
            goto out;
          assert_int_equal (carom_world_joint_count (sc.w), 1);
        }
    }
  assert_int_equal (carom_world_body_count (sc.w), bodies);
out:
  if (max_contacts)
    *max_contacts = sc.max_contacts;
  if (sc.ref)
    stop_reference (&sc);
  carom_world_destroy (sc.w);
  if (c->live_blocks != 0 || c->live_bytes != 0)
    fail_msg ("k=%ld: %ld blocks (%zu bytes) still allocated after destroy", k, c->live_blocks, c->live_bytes);
  if (c->bad_frees != 0)
    fail_msg ("k=%ld: %ld frees with a size other than the allocated one", k, c->bad_frees);
  return sc.oom_calls;
}

/* For k = 1, 2, ...: until the k-th allocation is never reached. */
static void sweep (int mode, carom_narrow_phase narrow, int32_t substeps)
{
  checking_alloc c;
  long k, total;
  int32_t max_contacts = 0;
  int ooms = 0;
  /* without failures: how many allocations the scenario makes */
  run_scenario (&c, 0, FAIL_ONCE, narrow, substeps, &max_contacts);
  total = c.calls;
  assert_true (total > 10);
  assert_true (max_contacts > 0); /* the scenario does collide */
  for (k = 1;; ++k)
    {
      int n = run_scenario (&c, k, mode, narrow, substeps, NULL);
      if (c.failures == 0)
        break;
      if (n == 0 && mode == FAIL_FROM)
        fail_msg ("k=%ld: an allocation failed but no call returned OUT_OF_MEMORY", k);
      ooms += n;
      assert_true (k <= total + 1);
    }
  assert_int_equal (k, total + 1); /* every allocation was made to fail once */
  assert_true (ooms > 0);
  print_message ("%ld allocations, each failed once; %d calls returned OUT_OF_MEMORY\n", total, ooms);
}

static void test_fail_each_allocation_once_sat (void **state)
{
  (void) state;
  sweep (FAIL_ONCE, CAROM_NARROW_SAT, 1);
}

static void test_fail_each_allocation_once_vertex_edge (void **state)
{
  (void) state;
  sweep (FAIL_ONCE, CAROM_NARROW_VERTEX_EDGE, 1);
}

/* A failed update changes nothing with several sub-steps too (include/carom.h:
 * the world is unchanged on error), and goes on as if it had not failed. */
static void test_fail_each_allocation_once_substeps (void **state)
{
  (void) state;
  sweep (FAIL_ONCE, CAROM_NARROW_SAT, 3);
}

/* A run of updates of which each allocation fails once (run k fails the
 * k-th allocation the updates make; run 0 fails none and counts them): the
 * failed update must leave the world as it was, then succeed, and every
 * update must match the reference world's. `build` makes the bodies of the
 * tested world (which = 0) and the reference (1), `before` acts on both
 * before update `step`, `check` looks at the world run 0 ends with. */
typedef struct update_run {
  int32_t substeps, steps;
  void (*build) (carom_world *w, int which, void *data);
  void (*before) (carom_world *w, int which, int step, void *data);
  void (*check) (carom_world *w);
  void *data;
} update_run;

static void each_update_allocation_fails_once (const update_run *u)
{
  checking_alloc c;
  carom_world_def def;
  scenario sc;
  long k, setup_calls, total = -1;
  int step, n, ooms = 0;
  use_allocator (&def, &c);
  def.gravity_y = -10.0;
  if (u->substeps > 0)
    def.substeps = u->substeps;
  for (k = 0;; ++k)
    {
      carom_world *worlds[2];
      memset (&sc, 0, sizeof sc);
      sc.alloc = &c;
      checking_reset (&c, 0, FAIL_ONCE);
      assert_status (carom_world_init (&sc.w, &def), CAROM_OK);
      start_reference (&sc, &def);
      worlds[0] = sc.w, worlds[1] = sc.ref;
      for (n = 0; n < 2; ++n)
        u->build (worlds[n], n, u->data);
      setup_calls = c.calls;
      c.fail_at = k > 0 ? setup_calls + k : 0;
      sc.k = k;
      for (step = 0; step < u->steps; ++step)
        {
          if (u->before)
            for (n = 0; n < 2; ++n)
              u->before (worlds[n], n, step, u->data);
          checked_call (&sc, UPDATE);
        }
      if (k == 0)
        {
          total = c.calls - setup_calls;
          assert_true (total > 2);
          u->check (sc.w);
        }
      ooms += sc.oom_calls;
      if (sc.ref)
        stop_reference (&sc);
      carom_world_destroy (sc.w);
      assert_int_equal (c.live_blocks, 0);
      assert_int_equal (c.bad_frees, 0);
      if (k > 0 && c.failures == 0)
        break;
    }
  assert_int_equal (k, total + 1);
  assert_true (ooms > 0);
}

static void add_ground (carom_world *w, double x, double width)
{
  carom_body_def d;
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.type = CAROM_STATIC, d.x = x, d.y = -0.5;
  assert_status (carom_world_add_box (w, &d, width, 1.0, NULL), CAROM_OK);
}

/* Rain: 24 boxes in 4 columns land on the ground and on each other one
 * after the other, so the contact list keeps growing during updates of 4
 * sub-steps and its buffers are reallocated in later updates too; 90
 * updates. */
static void rain_build (carom_world *w, int which, void *data)
{
  carom_body_def d;
  int i;
  (void) which, (void) data;
  add_ground (w, 0.0, 40.0);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  for (i = 0; i < 24; ++i)
    {
      /* 4 columns of 6 boxes, each column a little higher: the stacks'
       * contacts interact, so a lost warm start shows */
      d.x = -6.0 + 3.0 * (i % 4), d.y = 0.5 + 1.05 * (i / 4) + 0.3 * (i % 4);
      assert_status (carom_world_add_box (w, &d, 0.9, 0.9, NULL), CAROM_OK);
    }
}

static void rain_check (carom_world *w)
{
  assert_int_equal (carom_world_contact_count (w), 24 * 2); /* all landed, face on face */
}

static void test_rain_update_out_of_memory_with_substeps (void **state)
{
  update_run u = { 4, 90, rain_build, NULL, rain_check, NULL };
  (void) state;
  each_update_allocation_fails_once (&u);
}

/* The broad phase's kept pairs (lib/broadphase.h): 100 unit boxes resting
 * on a floor 2 apart, still long enough that the broad phase keeps the
 * pairs of their fat boxes; then, update after update, one of them is
 * moved to the end of a row of touching boxes, so that the kept pairs are
 * mended for it and grow past their room; 75 updates. */
static void row_build (carom_world *w, int which, void *data)
{
  carom_body_id (*ids)[101] = data;
  carom_body_def d;
  int i;
  add_ground (w, 150.0, 320.0);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  for (i = 0; i < 100; ++i)
    {
      d.x = 2.0 * i, d.y = 0.5;
      assert_status (carom_world_add_box (w, &d, 1.0, 1.0, NULL), CAROM_OK);
    }
  assert_int_equal (carom_world_get_bodies (w, ids[which], 101), 101);
}

static void row_before (carom_world *w, int which, int step, void *data)
{
  carom_body_id (*ids)[101] = data;
  int moved = step - 12;
  /* from update 12 on, the next box to the end of the row at x = 210 */
  if (moved >= 0 && moved < 60)
    assert_status (carom_body_set_position (w, ids[which][1 + moved], 210.0 + 1.0 * moved, 0.5), CAROM_OK);
}

static void row_check (carom_world *w)
{
  /* the row stands: each box on the floor, and touching the next */
  assert_true (carom_world_contact_count (w) >= 2 * 100 + 59);
  assert_true (w->broad.pairs_valid);
}

static void test_kept_pairs_out_of_memory (void **state)
{
  carom_body_id ids[2][101];
  update_run u = { 0, 75, row_build, row_before, row_check, ids };
  (void) state;
  each_update_allocation_fails_once (&u);
}

/* Impacts that set bodies moving further than their detection looked:
 * three rows of five equal balls (radius 0.1, e = 1), 8 mm apart (beyond
 * the contact margin at rest), struck by a first ball touching the next at
 * 3 m/s, falling side by side, continuous collision on. Within the first
 * step each struck ball meets the next (contacts_after_impacts, in the room
 * the update keeps for them); 20 updates. */
static void struck_build (carom_world *w, int which, void *data)
{
  carom_body_def d;
  int row, i;
  (void) which;
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
  d.restitution = 1.0, d.friction = 0.0;
  for (row = 0; row < 3; ++row)
    for (i = 0; i < 5; ++i)
      {
        d.x = i == 0 ? 0.0 : 0.2 + 0.208 * (i - 1), d.y = 10.0 + 2.0 * row;
        d.vx = i == 0 ? 3.0 : 0.0;
        assert_status (carom_world_add_circle (w, &d, 0.1, &((carom_body_id *) data)[15 * which + 5 * row + i]),
                       CAROM_OK);
      }
}

static carom_body_id struck_ids[30];

static void struck_check (carom_world *w)
{
  int row, i;
  /* the last ball of each row leaves at the striker's speed, the others
   * stay (world 0's ids) */
  for (row = 0; row < 3; ++row)
    for (i = 0; i < 5; ++i)
      {
        double vx;
        assert_status (carom_body_get_velocity (w, struck_ids[5 * row + i], &vx, NULL), CAROM_OK);
        assert_true (fabs (vx - (i == 4 ? 3.0 : 0.0)) < 1e-9);
      }
}

static void test_struck_bodies_out_of_memory (void **state)
{
  update_run u = { 0, 20, struck_build, NULL, struck_check, struck_ids };
  (void) state;
  each_update_allocation_fails_once (&u);
}

/* The grid broad phase (worlds of GRID_MIN_BODIES bodies and more): each
 * allocation the first update makes fails once, in a world of 4100 bodies
 * falling onto a floor; the update reports OUT_OF_MEMORY and leaves every
 * body bit for bit as it was, then succeeds. */
static void test_grid_update_out_of_memory (void **state)
{
  checking_alloc c;
  carom_world_def def;
  carom_body_def d;
  long k, setup_calls;
  int i, ooms = 0;
  (void) state;
  use_allocator (&def, &c);
  def.gravity_y = -10.0;
  for (k = 1;; ++k)
    {
      carom_world *w = NULL;
      uint64_t before;
      carom_status s;
      checking_reset (&c, 0, FAIL_ONCE);
      assert_status (carom_world_init (&w, &def), CAROM_OK);
      assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
      d.type = CAROM_STATIC, d.x = 50.0, d.y = -0.5;
      assert_status (carom_world_add_box (w, &d, 110.0, 1.0, NULL), CAROM_OK);
      assert_status (carom_body_def_init (&d, sizeof d), CAROM_OK);
      for (i = 0; i < 4100; ++i)
        {
          d.x = (i % 100) * 1.0, d.y = 0.45 + (i / 100) * 0.95;
          assert_status (carom_world_add_circle (w, &d, 0.45, NULL), CAROM_OK);
        }
      before = world_state_hash (w);
      setup_calls = c.calls;
      c.fail_at = setup_calls + k;
      s = carom_world_update (w, 1.0 / 60.0);
      if (c.failures == 0)
        {
          assert_status (s, CAROM_OK);
          assert_true (carom_world_contact_count (w) >= 100); /* the bottom row on the floor */
          carom_world_destroy (w);
          break;
        }
      assert_status (s, CAROM_ERR_OUT_OF_MEMORY);
      assert_true (world_state_hash (w) == before);
      ooms++;
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      assert_true (world_state_hash (w) != before);
      carom_world_destroy (w);
      assert_int_equal (c.live_blocks, 0);
      assert_int_equal (c.bad_frees, 0);
    }
  assert_int_equal (ooms, k - 1);
  assert_true (ooms >= 3); /* the grid's three arrays at least */
}

/* Out of memory for good from the k-th allocation: the failing call reports
 * it and destroy still frees everything. */
static void test_fail_every_allocation_from_k (void **state)
{
  (void) state;
  sweep (FAIL_FROM, CAROM_NARROW_SAT, 1);
}

/* -------------------------------------------------------------- scenes */

static const char scene_text[] = "gravity 0 -9.81\n"
                                 "restitution 0.3\n"
                                 "substeps 2\n"
                                 "bounds 0 0 10 8\n"
                                 "circle 0.5 at 2 1 velocity 1 0\n"
                                 "box 1 0.5 at 5 0.3 angle 0.2\n"
                                 "regular 6 0.4 at 7 1 spin 1\n"
                                 "polygon 0 0 3 0 3 3 2 3 2 1 1 1 1 3 0 3 at 5 3 velocity 0 -1\n"
                                 "polygon 0 0 1.2 0 0.3 0.9 at 8.5 3 static\n";

/* Each allocation of the loader fails once: OUT_OF_MEMORY, no world, every
 * byte back, the error struct naming the cause. */
static void scene_sweep (const char *path)
{
  checking_alloc c;
  carom_world_def def;
  carom_world *w = NULL;
  long k, total;
  carom_status s;
  use_allocator (&def, &c);
  checking_reset (&c, 0, FAIL_ONCE);
  s = path ? carom_scene_load_file (&w, path, &def, NULL)
           : carom_scene_load_text (&w, scene_text, sizeof scene_text - 1, &def, NULL);
  assert_status (s, CAROM_OK);
  total = c.calls; /* the loader's allocations */
  assert_true (carom_world_body_count (w) >= 9);
  assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
  carom_world_destroy (w);
  assert_int_equal (c.live_blocks, 0);
  assert_true (total > 10);
  for (k = 1; k <= total; ++k)
    {
      carom_scene_error err;
      int step;
      memset (&err, 0x55, sizeof err);
      err.size = sizeof err;
      checking_reset (&c, k, FAIL_ONCE);
      w = (carom_world *) &c; /* must come back NULL on failure */
      s = path ? carom_scene_load_file (&w, path, &def, &err)
               : carom_scene_load_text (&w, scene_text, sizeof scene_text - 1, &def, &err);
      if (s == CAROM_OK)
        {
          /* the loader may have recovered (the failed block was scratch);
           * the world must then be complete and work */
          assert_non_null (w);
          assert_true (carom_world_body_count (w) >= 9);
          for (step = 0; step < 5; ++step)
            assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          assert_world_finite (w);
          carom_world_destroy (w);
        }
      else
        {
          if (s != CAROM_ERR_OUT_OF_MEMORY)
            fail_msg ("%s, allocation %ld of %ld failed: status %d (%s) '%s'", path ? path : "text", k, total,
                      (int) s, carom_status_string (s), err.message);
          assert_null (w);
          assert_int_equal (err.cause, CAROM_ERR_OUT_OF_MEMORY);
          assert_non_null (memchr (err.message, '\0', sizeof err.message));
        }
      assert_true (c.failures == 1);
      if (c.live_blocks != 0 || c.bad_frees != 0)
        fail_msg ("%s, allocation %ld failed: %ld blocks (%zu bytes) left, %ld bad frees", path ? path : "text", k,
                  c.live_blocks, c.live_bytes, c.bad_frees);
    }
}

static void test_scene_text_out_of_memory (void **state)
{
  (void) state;
  scene_sweep (NULL);
}

static void test_scene_file_out_of_memory (void **state)
{
  (void) state;
  scene_sweep ("scenes/thesis.scene");
  scene_sweep ("scenes/compound.scene"); /* compound blocks: their shapes, the trial world */
}

/* A def whose allocator has alloc but no free is refused before any
 * allocation (BAD_ARGUMENT), by the world and by the loader. */
static void test_half_allocator_rejected (void **state)
{
  checking_alloc c;
  carom_world_def def;
  carom_world *w = (carom_world *) &c;
  (void) state;
  use_allocator (&def, &c);
  checking_reset (&c, 0, FAIL_ONCE);
  def.allocator.free = NULL;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_ARGUMENT);
  assert_null (w);
  w = (carom_world *) &c;
  assert_status (carom_scene_load_text (&w, "circle 1\n", 9, &def, NULL), CAROM_ERR_BAD_ARGUMENT);
  assert_null (w);
  def.allocator.free = checking_free_fn;
  def.allocator.alloc = NULL;
  assert_status (carom_world_init (&w, &def), CAROM_ERR_BAD_ARGUMENT);
  assert_int_equal (c.calls, 0);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_fail_each_allocation_once_sat),
    cmocka_unit_test (test_fail_each_allocation_once_vertex_edge),
    cmocka_unit_test (test_fail_each_allocation_once_substeps),
    cmocka_unit_test (test_rain_update_out_of_memory_with_substeps),
    cmocka_unit_test (test_kept_pairs_out_of_memory),
    cmocka_unit_test (test_struck_bodies_out_of_memory),
    cmocka_unit_test (test_grid_update_out_of_memory),
    cmocka_unit_test (test_fail_every_allocation_from_k),
    cmocka_unit_test (test_scene_text_out_of_memory),
    cmocka_unit_test (test_scene_file_out_of_memory),
    cmocka_unit_test (test_half_allocator_rejected),
  };
  return cmocka_run_group_tests_name ("alloc_failure", tests, NULL, NULL);
}
