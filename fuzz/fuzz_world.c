/* Fuzz target: a whole world from fuzzed settings, bodies and calls.
 *
 * The bytes choose, in order:
 *   1. world settings, each field default or fuzzed (NaN, infinities, values
 *      outside the documented ranges, a wrong struct size). The target
 *      predicts from include/carom.h whether carom_world_init must accept
 *      them: an invalid def must be refused with one of the statuses that
 *      apply to it (and *world NULL), a valid one accepted. The world is then
 *      made from the fuzzed settings brought into range (sub-steps and
 *      iterations capped so an input stays fast).
 *   2. up to 12 bodies: circle, box, regular polygon or polygon (a U or an
 *      arrow, scaled), with fuzzed type, position, angle, velocity, spin,
 *      density, restitution, friction and size. Each add is checked the same
 *      way: refused with an applicable status and nothing created, or
 *      accepted with finite, positive mass properties (fuzz_check_world).
 *   3. up to 48 operations: update with a fuzzed dt (NaN, 0, negative, inf,
 *      outside [1e-100, 1e100] must give BAD_TIME_STEP and change nothing),
 *      remove a body (its id then stale everywhere), set position / angle /
 *      velocity / spin / gravity (non-finite values refused with NOT_FINITE,
 *      values beyond CAROM_MAX_MAGNITUDE with BAD_ARGUMENT, and nothing
 *      changed; STATIC_BODY for a static body's velocity), the effects
 *      (restitution, friction, central gravity, damping, sleeping, fixed
 *      rotation, wake, continuous collision for the world or one body), add
 *      a body, detect, calls with stale and made-up ids, and the calls of
 *      version 0.2 (forces, impulses, filters, user data, ray casts,
 *      queries, events, the debug draw, compound bodies and their shapes,
 *      joints of every type with fuzzed anchors, axes, limits, motors and
 *      springs, and the joint calls, listings and setters: op_api).
 * After every operation every body's state and every contact must be finite.
 *
 * Extreme but finite values are fed to every call. include/carom.h bounds
 * coordinates, angles, velocities, spins, gravity and rates by
 * CAROM_MAX_MAGNITUDE (BAD_ARGUMENT beyond), sizes by [1e-60, 1e60]
 * (BAD_SIZE) and dt by [1e-100, 1e100] (BAD_TIME_STEP): values beyond are
 * checked to be refused, values up to the limits to be accepted, and every
 * body the library accepts is simulated. Only the steps themselves are kept
 * to dt in [1e-12, 10], so 48 of them cannot carry a body from the limits
 * past the doubles by plain free fall (dt 1e-100 and 1e100 are tried by
 * tests/test_bad_input.c). */
#include "fuzz_util.h"

#define MAX_BODIES 12
#define MAX_OPS 48
#define MAG CAROM_MAX_MAGNITUDE /* coordinates, velocities, gravity, rates */
#define SIZE_LO 1e-60             /* sizes: include/carom.h, add_circle */
#define SIZE_HI 1e60
#define DT_LO 1e-100              /* carom_world_update */
#define DT_HI 1e100
#define DT_MIN 1e-12              /* the steps this target takes */
#define DT_MAX 10.0

/* Bit sets of statuses. */
#define BIT(s) (1u << (s))

/* Build with -DFUZZ_TRACE to replay a finding call by call on stderr. */
#ifdef FUZZ_TRACE
#define TRACE(...) fprintf (stderr, __VA_ARGS__)
#else
#define TRACE(...) ((void) 0)
#endif

typedef struct fuzz_world {
  fuzz_input in;
  carom_world *w;
  carom_body_id ids[64];
  int fixed[64]; /* made non-rotating */
  int count;
  carom_body_id dead[16]; /* removed ids: stale for good */
  int dead_count;
  carom_joint_id joints[32]; /* added joints (stale once a body of theirs goes) */
  int joint_count;
  carom_joint_id dead_joints[16];
  int dead_joint_count;
} fuzz_world;

static int in_range (double v, double lo, double hi)
{
  return v >= lo && v <= hi;
}

/* Finite but beyond CAROM_MAX_MAGNITUDE. */
static int too_big (double v)
{
  return isfinite (v) && fabs (v) > MAG;
}

static double clamp_mag (double v, double max)
{
  if (!isfinite (v))
    return 0.0;
  return v > max ? max : v < -max ? -max : v;
}

static void report_status (const char *call, carom_status got, unsigned allowed)
{
  FUZZ_FINDING ("%s returned %d (%s); allowed set 0x%x", call, (int) got, carom_status_string (got), allowed);
}

/* ---------------------------------------------------------- world settings */

/* The size of version 0.1's carom_world_def, which ended at the allocator:
 * the library takes it as well as its own. */
#define WORLD_DEF_0_1_SIZE (offsetof (carom_world_def, allocator) + sizeof (carom_allocator))
/* And of its carom_body_def, which ended at friction. */
#define BODY_DEF_0_1_SIZE (offsetof (carom_body_def, friction) + sizeof (double))

/* The statuses carom_world_init may return for `d` (0: it must accept). */
static unsigned world_def_problems (const carom_world_def *d)
{
  unsigned p = 0;
  if (d->size != sizeof *d && d->size != WORLD_DEF_0_1_SIZE)
    return BIT (CAROM_ERR_BAD_STRUCT_SIZE);
  if (!isfinite (d->gravity_x) || !isfinite (d->gravity_y) || !isfinite (d->restitution) || !isfinite (d->friction)
      || !isfinite (d->position_correction) || !isfinite (d->slop)
      || (d->size == sizeof *d && !isfinite (d->manifold_tolerance))) /* 0.1's def ends before it */
    p |= BIT (CAROM_ERR_NOT_FINITE);
  if (too_big (d->gravity_x) || too_big (d->gravity_y) || (isfinite (d->restitution) && !in_range (d->restitution, 0.0, 1.0))
      || (isfinite (d->friction) && d->friction < 0.0)
      || d->substeps < 1 || d->substeps > 1000 || d->iterations < 1 || d->iterations > 1000
      || (isfinite (d->position_correction) && !in_range (d->position_correction, 0.0, 1.0))
      || (isfinite (d->slop) && !in_range (d->slop, 0.0, 1.0))
      || (d->size == sizeof *d && isfinite (d->manifold_tolerance) && !in_range (d->manifold_tolerance, 0.0, 1.0))
      || (d->narrow_phase != CAROM_NARROW_SAT && d->narrow_phase != CAROM_NARROW_VERTEX_EDGE)
      || (!d->allocator.alloc != !d->allocator.free))
    p |= BIT (CAROM_ERR_BAD_ARGUMENT);
  return p;
}

static void *never_called_alloc (size_t size, void *user)
{
  (void) size, (void) user;
  FUZZ_FINDING ("the allocator of a refused def was used");
  return NULL;
}

static void make_world (fuzz_world *f)
{
  carom_world_def d, ok;
  carom_world *probe = (carom_world *) f;
  uint8_t which = fuzz_u8 (&f->in), extra = fuzz_u8 (&f->in);
  unsigned problems;
  carom_status s;

  /* def_init itself: a wrong size is refused and writes nothing */
  if (extra & 0x80)
    {
      unsigned char buf[sizeof (carom_world_def) + 16];
      uint32_t size = fuzz_u32 (&f->in);
      memset (buf, 0xA5, sizeof buf);
      s = carom_world_def_init ((carom_world_def *) (void *) buf, size);
      if (size == sizeof (carom_world_def) || size == WORLD_DEF_0_1_SIZE ? s != CAROM_OK
                                                                         : s != CAROM_ERR_BAD_STRUCT_SIZE)
        FUZZ_FINDING ("world_def_init (size %lu) returned %d", (unsigned long) size, (int) s);
      if (s != CAROM_OK)
        {
          size_t i;
          for (i = 0; i < sizeof buf; ++i)
            if (buf[i] != 0xA5)
              FUZZ_FINDING ("world_def_init refused size %lu but wrote byte %zu", (unsigned long) size, i);
        }
    }

  if (carom_world_def_init (&d, sizeof d) != CAROM_OK)
    FUZZ_FINDING ("world_def_init failed");
  if (which & 1)
    d.gravity_x = fuzz_number (&f->in, 0), d.gravity_y = fuzz_number (&f->in, 0);
  if (which & 2)
    d.restitution = fuzz_number (&f->in, 0);
  if (which & 4)
    d.friction = fuzz_number (&f->in, 0);
  if (which & 8)
    d.substeps = (int32_t) fuzz_u32 (&f->in);
  if (which & 16)
    d.iterations = (int32_t) fuzz_u32 (&f->in);
  if (which & 32)
    d.position_correction = fuzz_number (&f->in, 0);
  if (which & 64)
    d.slop = fuzz_number (&f->in, 0);
  if (which & 128)
    d.narrow_phase = (carom_narrow_phase) (int32_t) fuzz_u32 (&f->in);
  else
    d.narrow_phase = (extra & 1) ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
  if ((extra & 0x80) && (which & 1))
    d.manifold_tolerance = fuzz_number (&f->in, 0);
  if ((extra & 0x0e) == 0x0e)
    d.size = fuzz_u32 (&f->in);
  if ((extra & 0x70) == 0x70)
    d.allocator.alloc = never_called_alloc; /* without free: refused */

  problems = world_def_problems (&d);
  s = carom_world_init (&probe, &d);
  if (problems == 0)
    {
      if (s != CAROM_OK)
        report_status ("world_init of a valid def", s, 0);
      carom_world_destroy (probe);
    }
  else
    {
      if (s == CAROM_OK || !(problems & BIT (s)))
        report_status ("world_init of an invalid def", s, problems);
      if (probe != NULL)
        FUZZ_FINDING ("world_init failed but *world is not NULL");
    }

  /* the world that runs: the same settings, in range and cheap */
  if (carom_world_def_init (&ok, sizeof ok) != CAROM_OK)
    FUZZ_FINDING ("world_def_init failed");
  ok.gravity_x = clamp_mag (d.gravity_x, MAG);
  ok.gravity_y = clamp_mag (d.gravity_y, MAG);
  ok.restitution = in_range (d.restitution, 0.0, 1.0) ? d.restitution : 0.5;
  ok.friction = in_range (d.friction, 0.0, 1e6) ? d.friction : 0.3;
  ok.substeps = 1 + (int32_t) ((uint32_t) d.substeps % 4);
  ok.iterations = 1 + (int32_t) ((uint32_t) d.iterations % 16);
  ok.position_correction = in_range (d.position_correction, 0.0, 1.0) ? d.position_correction : 0.2;
  ok.slop = in_range (d.slop, 0.0, 1.0) ? d.slop : 0.01;
  ok.manifold_tolerance = in_range (d.manifold_tolerance, 0.0, 1.0) ? d.manifold_tolerance : 0.01;
  ok.narrow_phase = (extra & 1) ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
  TRACE ("world: gravity (%.17g, %.17g) e %.17g mu %.17g substeps %d iterations %d correction %.17g slop %.17g "
         "manifold %.17g narrow %d\n", ok.gravity_x, ok.gravity_y, ok.restitution, ok.friction, (int) ok.substeps,
         (int) ok.iterations, ok.position_correction, ok.slop, ok.manifold_tolerance, (int) ok.narrow_phase);
  if (carom_world_init (&f->w, &ok) != CAROM_OK)
    FUZZ_FINDING ("world_init of a clamped def failed");
}

/* ------------------------------------------------------------------ bodies */

/* A U (concave, its centroid outside it) or an arrow head, scaled. */
static const double shape_u[] = { 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3 };
static const double shape_arrow[] = { 0, 0, 2, -1, 1, 0, 2, 1 };

static void add_fuzzed_body (fuzz_world *f)
{
  fuzz_input *in = &f->in;
  carom_body_def d;
  carom_body_id id = 99;
  uint8_t kind = fuzz_u8 (in) % 4, flags = fuzz_u8 (in);
  unsigned problems = 0, extreme_ok;
  double size1 = fuzz_number (in, 0), size2 = 1.0, xy[16];
  int32_t n = 0, before = carom_world_body_count (f->w), i;
  int must_accept, known_size;
  carom_status s;

  if (carom_body_def_init (&d, sizeof d) != CAROM_OK)
    FUZZ_FINDING ("body_def_init failed");
  if (flags & 1)
    d.type = CAROM_STATIC;
  if (flags & 2)
    d.x = fuzz_number (in, 0), d.y = fuzz_number (in, 0);
  else
    d.x = (int8_t) fuzz_u8 (in) * 0.25, d.y = (int8_t) fuzz_u8 (in) * 0.25;
  if (flags & 4)
    d.angle = fuzz_number (in, 0);
  if (flags & 8)
    d.vx = fuzz_number (in, 0), d.vy = fuzz_number (in, 0);
  if (flags & 16)
    d.spin = fuzz_number (in, 0);
  if (flags & 32)
    d.density = fuzz_number (in, 0);
  if (flags & 64)
    d.restitution = fuzz_number (in, 0), d.friction = fuzz_number (in, 0);
  if ((flags & 0x81) == 0x81)
    d.type = (carom_body_type) (int32_t) fuzz_u32 (in); /* mostly not a type */
  if ((flags & 0x82) == 0x82 && fuzz_u8 (in) < 16)
    d.size = fuzz_u32 (in);
  if ((flags & 0x84) == 0x84)
    {
      /* version 0.2: kinematic, sensor, filter */
      uint8_t more = fuzz_u8 (in);
      if (more & 1)
        d.type = CAROM_KINEMATIC;
      d.sensor = (more & 2) != 0;
      if (more & 4)
        d.category = fuzz_u32 (in), d.mask = fuzz_u32 (in), d.group = (int32_t) fuzz_u32 (in);
    }

  /* the def's own problems, in include/carom.h's terms (0.1's size is
   * known too: the fields of 0.2 keep their defaults then) */
  known_size = d.size == sizeof d || d.size == BODY_DEF_0_1_SIZE;
  if (!known_size)
    problems |= BIT (CAROM_ERR_BAD_STRUCT_SIZE);
  if (!fuzz_finite6 (d.x, d.y, d.angle, d.vx, d.vy, d.spin) || !isfinite (d.density) || !isfinite (d.restitution)
      || !isfinite (d.friction))
    problems |= BIT (CAROM_ERR_NOT_FINITE);
  if ((d.type != CAROM_DYNAMIC && d.type != CAROM_STATIC && d.type != CAROM_KINEMATIC) || too_big (d.x) || too_big (d.y) || too_big (d.angle)
      || too_big (d.vx) || too_big (d.vy) || too_big (d.spin))
    problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
  if (isfinite (d.density) && d.density <= 0.0)
    problems |= BIT (CAROM_ERR_BAD_DENSITY);
  if (isfinite (d.restitution) && d.restitution > 1.0)
    problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
  if (!known_size)
    problems = BIT (CAROM_ERR_BAD_STRUCT_SIZE); /* nothing else is read */

  /* the shape's (a polygon's size1 scales its outline, any sign; its extent
   * is checked below) */
  if (!isfinite (size1))
    problems |= BIT (CAROM_ERR_NOT_FINITE);
  else if (kind != 3 && (size1 <= 0.0 || !in_range (size1, SIZE_LO, SIZE_HI)))
    problems |= BIT (CAROM_ERR_BAD_SIZE);
  switch (kind)
    {
    case 0:
      s = carom_world_add_circle (f->w, &d, size1, &id);
      break;
    case 1:
      size2 = fuzz_number (in, 0);
      if (!isfinite (size2))
        problems |= BIT (CAROM_ERR_NOT_FINITE);
      else if (size2 <= 0.0 || !in_range (size2, SIZE_LO, SIZE_HI))
        problems |= BIT (CAROM_ERR_BAD_SIZE);
      else if (isfinite (size1) && (size1 < 1e-10 * size2 || size2 < 1e-10 * size1))
        problems |= BIT (CAROM_ERR_BAD_SIZE); /* a plate thinner than 1e-10 of its length */
      s = carom_world_add_box (f->w, &d, size1, size2, &id);
      break;
    case 2:
      n = (int32_t) (fuzz_u8 (in) % 40);
      if (fuzz_u8 (in) == 0xff)
        n = (int32_t) fuzz_u32 (in);
      if (n < 3)
        problems |= BIT (CAROM_ERR_TOO_FEW_VERTICES);
      if (n > CAROM_MAX_POLYGON_VERTICES)
        problems |= BIT (CAROM_ERR_TOO_MANY_VERTICES);
      s = carom_world_add_regular (f->w, &d, n, size1, &id);
      break;
    default:
      {
        const double *src = (flags & 128) ? shape_arrow : shape_u;
        n = (flags & 128) ? 4 : 8;
        double lx = 0.0, ly = 0.0, hx = 0.0, hy = 0.0, extent;
        for (i = 0; i < 2 * n; ++i)
          xy[i] = src[i] * size1;
        for (i = 0; i < n; ++i)
          {
            lx = fmin (lx, xy[2 * i]), hx = fmax (hx, xy[2 * i]);
            ly = fmin (ly, xy[2 * i + 1]), hy = fmax (hy, xy[2 * i + 1]);
          }
        /* the extent as the library measures it: the bounding box's
         * diagonal; within 0.1% of a limit either answer is right */
        extent = sqrt ((hx - lx) * (hx - lx) + (hy - ly) * (hy - ly));
        if (isfinite (size1) && size1 != 0.0 && fabs (size1) < 1e150)
          extent = fabs (size1) * sqrt (((hx - lx) / size1) * ((hx - lx) / size1)
                                        + ((hy - ly) / size1) * ((hy - ly) / size1));
        if (size1 == 0.0)
          problems |= BIT (CAROM_ERR_REPEATED_VERTEX) | BIT (CAROM_ERR_ZERO_AREA);
        else if (isfinite (size1) && !in_range (extent, SIZE_LO * 0.999, SIZE_HI * 1.001))
          /* its extent: BAD_SIZE says the header; a polygon that small is
           * also truthfully (nearly) without area or vertices apart */
          problems |= BIT (CAROM_ERR_BAD_SIZE) | BIT (CAROM_ERR_NOT_FINITE) | BIT (CAROM_ERR_ZERO_AREA)
                      | BIT (CAROM_ERR_REPEATED_VERTEX);
        s = carom_world_add_polygon (f->w, &d, xy, n, &id);
      }
      break;
    }
  TRACE ("add kind %d type %d size %.17g x %.17g n %d density %.17g at (%.17g, %.17g) angle %.17g v (%.17g, %.17g) "
         "spin %.17g e %.17g mu %.17g: status %d\n", kind, (int) d.type, size1, size2, (int) n, d.density, d.x, d.y,
         d.angle, d.vx, d.vy, d.spin, d.restitution, d.friction, (int) s);
  if (!fuzz_known_status (s))
    FUZZ_FINDING ("add (kind %d) returned unknown status %d", kind, (int) s);

  /* sizes, densities and shapes whose mass properties may leave the
   * doubles, or boxes thinner than the library's relative tolerance: the
   * library may refuse them, with a status include/carom.h documents for
   * that call (the polygon statuses only for add_polygon) */
  extreme_ok = BIT (CAROM_ERR_NOT_FINITE) | BIT (CAROM_ERR_BAD_SIZE) | BIT (CAROM_ERR_BAD_DENSITY);
  if (kind == 3)
    extreme_ok |= BIT (CAROM_ERR_ZERO_AREA) | BIT (CAROM_ERR_REPEATED_VERTEX);
  must_accept = in_range (fabs (size1), 1e-30, 1e30) && in_range (fabs (size2), 1e-30, 1e30)
                && in_range (fabs (size1) / fabs (size2), 1e-6, 1e6) && in_range (d.density, 1e-30, 1e30);
  if (problems != 0)
    {
      if (s == CAROM_OK || !(problems & BIT (s)))
        FUZZ_FINDING ("add (kind %d, type %d, size %g x %g, n %d, density %g, at (%g, %g), angle %g, v (%g, %g), "
                      "spin %g, e %g, mu %g) of an invalid body returned %d (%s); allowed set 0x%x",
                      kind, (int) d.type, size1, size2, (int) n, d.density, d.x, d.y, d.angle, d.vx, d.vy, d.spin,
                      d.restitution, d.friction, (int) s, carom_status_string (s), problems);
    }
  else if (s != CAROM_OK && (must_accept || !(extreme_ok & BIT (s))))
    FUZZ_FINDING ("add (kind %d, size %g x %g, density %g, n %d) of a valid body returned %d (%s)", kind, size1,
                  size2, d.density, (int) n, (int) s, carom_status_string (s));

  if (s != CAROM_OK)
    {
      if (id != 99)
        FUZZ_FINDING ("a refused add wrote *id");
      if (carom_world_body_count (f->w) != before)
        FUZZ_FINDING ("a refused add changed the body count");
      return;
    }
  if (carom_world_body_count (f->w) != before + 1 || carom_body_check (f->w, id) != CAROM_OK)
    FUZZ_FINDING ("an accepted body is not in the world");
  fuzz_check_world (f->w, "after an add");

  /* every accepted body is within the documented limits (checked above);
   * keep at most 64 */
  if (f->count >= 64)
    {
      if (carom_world_remove_body (f->w, id) != CAROM_OK)
        FUZZ_FINDING ("removing a new body failed");
      if (carom_body_check (f->w, id) != CAROM_ERR_STALE_BODY)
        FUZZ_FINDING ("a removed body is still there");
      return;
    }
  f->fixed[f->count] = 0;
  f->ids[f->count++] = id;
}

/* -------------------------------------------------------------- operations */

/* Every body's state, to check that a refused call changed nothing. */
typedef struct state {
  double v[8];
} state;

static void read_states (const fuzz_world *f, state *st)
{
  int i;
  for (i = 0; i < f->count; ++i)
    {
      double *v = st[i].v;
      carom_body_get_position (f->w, f->ids[i], &v[0], &v[1]);
      carom_body_get_angle (f->w, f->ids[i], &v[2]);
      carom_body_get_velocity (f->w, f->ids[i], &v[3], &v[4]);
      carom_body_get_spin (f->w, f->ids[i], &v[5]);
      carom_world_get_gravity (f->w, &v[6], &v[7]);
    }
}

static void expect_unchanged (const fuzz_world *f, const state *before, const char *call)
{
  state after[64];
  int i;
  read_states (f, after);
  for (i = 0; i < f->count; ++i)
    if (memcmp (before[i].v, after[i].v, sizeof after[i].v) != 0)
      FUZZ_FINDING ("%s was refused but body %d changed", call, i);
}

static void op_update (fuzz_world *f)
{
  state before[64];
  double dt;
  carom_status s;
  switch (fuzz_u8 (&f->in) % 4)
    {
    case 0: dt = 1.0 / 60.0; break;
    case 1: dt = 1.0 / 240.0; break;
    default: dt = fuzz_number (&f->in, 0); break;
    }
  if (!isfinite (dt) || !(dt >= DT_LO) || dt > DT_HI)
    {
      read_states (f, before);
      s = carom_world_update (f->w, dt);
      if (s != CAROM_ERR_BAD_TIME_STEP)
        FUZZ_FINDING ("update with dt %g returned %d, not BAD_TIME_STEP", dt, (int) s);
      expect_unchanged (f, before, "update with a bad dt");
      return;
    }
  dt = dt < DT_MIN ? DT_MIN : dt > DT_MAX ? DT_MAX : dt;
  TRACE ("update %.17g\n", dt);
  s = carom_world_update (f->w, dt);
  if (s != CAROM_OK)
    FUZZ_FINDING ("update with dt %g returned %d (%s)", dt, (int) s, carom_status_string (s));
}

static void op_remove (fuzz_world *f)
{
  int k;
  carom_body_id id;
  double x;
  if (f->count == 0)
    return;
  k = fuzz_u8 (&f->in) % f->count;
  id = f->ids[k];
  TRACE ("remove body %d\n", k);
  if (carom_world_remove_body (f->w, id) != CAROM_OK)
    FUZZ_FINDING ("remove of a live body failed");
  f->ids[k] = f->ids[--f->count];
  f->fixed[k] = f->fixed[f->count];
  if (f->dead_count < 16)
    f->dead[f->dead_count++] = id;
  if (carom_world_remove_body (f->w, id) != CAROM_ERR_STALE_BODY || carom_body_check (f->w, id) != CAROM_ERR_STALE_BODY
      || carom_body_get_position (f->w, id, &x, NULL) != CAROM_ERR_STALE_BODY
      || carom_body_set_velocity (f->w, id, 1.0, 0.0) != CAROM_ERR_STALE_BODY)
    FUZZ_FINDING ("a removed id is not stale");
}

static void op_set (fuzz_world *f)
{
  state before[64];
  uint8_t what = fuzz_u8 (&f->in) % 5;
  int k = f->count ? fuzz_u8 (&f->in) % f->count : 0;
  double a = fuzz_number (&f->in, 0), b = fuzz_number (&f->in, 0);
  carom_body_id id = f->count ? f->ids[k] : 0;
  carom_body_type type = CAROM_DYNAMIC;
  carom_status s;
  int one = what == 1 || what == 3; /* angle and spin take one value */
  int finite = isfinite (a) && (one || isfinite (b));
  int big = too_big (a) || (!one && too_big (b));
  if (what != 4 && f->count == 0)
    return;
  if (what != 4)
    carom_body_get_type (f->w, id, &type);
  TRACE ("set %d body %d (%.17g, %.17g)\n", what, k, a, b);
  read_states (f, before);
  switch (what)
    {
    case 0: s = carom_body_set_position (f->w, id, a, b); break;
    case 1: s = carom_body_set_angle (f->w, id, a); break;
    case 2: s = carom_body_set_velocity (f->w, id, a, b); break;
    case 3: s = carom_body_set_spin (f->w, id, a); break;
    default: s = carom_world_set_gravity (f->w, a, b); break;
    }
  if (!finite)
    {
      if (s != CAROM_ERR_NOT_FINITE && !(s == CAROM_ERR_STATIC_BODY && type == CAROM_STATIC && (what == 2 || what == 3)))
        FUZZ_FINDING ("setter %d with a non-finite value returned %d", what, (int) s);
      expect_unchanged (f, before, "a setter with a non-finite value");
    }
  else if (big)
    {
      if (s != CAROM_ERR_BAD_ARGUMENT && !(s == CAROM_ERR_STATIC_BODY && type == CAROM_STATIC && (what == 2 || what == 3)))
        FUZZ_FINDING ("setter %d with %g, %g beyond CAROM_MAX_MAGNITUDE returned %d", what, a, b, (int) s);
      expect_unchanged (f, before, "a setter with a value beyond CAROM_MAX_MAGNITUDE");
    }
  else if ((what == 2 || what == 3) && type == CAROM_STATIC)
    {
      if (s != CAROM_ERR_STATIC_BODY)
        FUZZ_FINDING ("setting a static body's velocity returned %d", (int) s);
      expect_unchanged (f, before, "a static body's velocity");
    }
  else if (what == 3 && f->fixed[k] && a != 0.0)
    {
      if (s != CAROM_ERR_BAD_ARGUMENT)
        FUZZ_FINDING ("spinning a non-rotating body returned %d", (int) s);
      expect_unchanged (f, before, "spinning a non-rotating body");
    }
  else if (s != CAROM_OK)
    FUZZ_FINDING ("setter %d (%g, %g) returned %d", what, a, b, (int) s);
}

/* The effect setters: non-finite values give NOT_FINITE, negative ones,
 * ones beyond CAROM_MAX_MAGNITUDE and a restitution above 1 BAD_ARGUMENT,
 * and nothing changes; valid values must be accepted. */
static void op_effects (fuzz_world *f)
{
  state before[64];
  uint8_t what = fuzz_u8 (&f->in) % 9;
  double a = fuzz_number (&f->in, 0), b = fuzz_number (&f->in, 0), c = 0.0, d = 0.0;
  int k = f->count ? fuzz_u8 (&f->in) % f->count : 0;
  unsigned problems = 0;
  carom_status s;
  carom_body_type type = CAROM_DYNAMIC;
  int32_t awake = -1;
  if (what == 2)
    c = fuzz_number (&f->in, 0), d = fuzz_number (&f->in, 0);
  TRACE ("effect %d body %d (%.17g, %.17g, %.17g, %.17g)\n", what, k, a, b, c, d);
  read_states (f, before);
  switch (what)
    {
    case 0:
      if (!isfinite (a))
        problems = BIT (CAROM_ERR_NOT_FINITE);
      else if (a < 0.0 || a > 1.0)
        problems = BIT (CAROM_ERR_BAD_ARGUMENT);
      s = carom_world_set_restitution (f->w, a);
      break;
    case 1:
      if (!isfinite (a))
        problems = BIT (CAROM_ERR_NOT_FINITE);
      else if (a < 0.0)
        problems = BIT (CAROM_ERR_BAD_ARGUMENT);
      s = carom_world_set_friction (f->w, a);
      break;
    case 2: /* central gravity at (a, b), gm c, softening d */
      if (!isfinite (a) || !isfinite (b) || !isfinite (c) || !isfinite (d))
        problems |= BIT (CAROM_ERR_NOT_FINITE);
      if ((isfinite (c) && c < 0.0) || (isfinite (d) && d < 0.0) || too_big (a) || too_big (b) || too_big (c)
          || too_big (d))
        problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
      s = carom_world_set_central_gravity (f->w, a, b, c, d);
      break;
    case 3:
      if (!isfinite (a) || !isfinite (b))
        problems |= BIT (CAROM_ERR_NOT_FINITE);
      if ((isfinite (a) && a < 0.0) || (isfinite (b) && b < 0.0) || too_big (a) || too_big (b))
        problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
      s = carom_world_set_damping (f->w, a, b);
      break;
    case 4:
      s = carom_world_set_sleeping (f->w, a > 0.0);
      break;
    case 5:
      if (f->count == 0)
        return;
      carom_body_get_type (f->w, f->ids[k], &type);
      s = carom_body_set_fixed_rotation (f->w, f->ids[k], a > 0.0);
      if (type != CAROM_DYNAMIC) /* static and kinematic bodies have no inertia to fix */
        problems = BIT (CAROM_ERR_STATIC_BODY);
      else if (s == CAROM_OK)
        f->fixed[k] = a > 0.0;
      break;
    case 7:
      s = carom_world_set_continuous (f->w, a > 0.0);
      break;
    case 8:
      if (f->count == 0)
        return;
      s = carom_body_set_bullet (f->w, f->ids[k], a > 0.0);
      break;
    default:
      if (f->count == 0)
        return;
      if (carom_body_is_awake (f->w, f->ids[k], &awake) != CAROM_OK || (awake != 0 && awake != 1))
        FUZZ_FINDING ("is_awake failed or said %d", (int) awake);
      s = carom_body_wake (f->w, f->ids[k]);
      break;
    }
  if (problems)
    {
      if (s == CAROM_OK || !(problems & BIT (s)))
        report_status ("an effect setter with bad values", s, problems);
      expect_unchanged (f, before, "an effect setter with bad values");
    }
  else if (s != CAROM_OK)
    FUZZ_FINDING ("effect setter %d (%g, %g, %g, %g) returned %d (%s)", what, a, b, c, d, (int) s,
                  carom_status_string (s));
}

/* ------------------------------------------------------ version 0.2 calls */

static void count_polygon (const double *xy, int32_t count, carom_body_id body, void *user)
{
  (void) xy, (void) count, (void) body;
  ++*(int *) user;
}

static void count_circle (double x, double y, double r, double angle, carom_body_id body, void *user)
{
  (void) x, (void) y, (void) r, (void) angle, (void) body;
  ++*(int *) user;
}

/* A compound of up to 4 fuzzed shapes (circles, a U or an arrow, or no
 * kind at all), each at a fuzzed place with a fuzzed size, density and
 * material: refused with a status that applies and nothing created, or
 * accepted with finite, positive mass properties; its shapes then read
 * back (count, geometry, material) within what was given. */
static void add_fuzzed_compound (fuzz_world *f)
{
  carom_shape_def shapes[4];
  double xy[4][16];
  carom_body_def d;
  carom_body_id id = 99;
  int32_t count = (int32_t) (fuzz_u8 (&f->in) % 5), before = carom_world_body_count (f->w), i, j, n;
  unsigned problems = 0, extreme = 0;
  carom_status s;
  if (carom_body_def_init (&d, sizeof d) != CAROM_OK)
    FUZZ_FINDING ("body_def_init failed");
  d.x = (int8_t) fuzz_u8 (&f->in) * 0.25, d.y = (int8_t) fuzz_u8 (&f->in) * 0.25;
  if (fuzz_u8 (&f->in) & 1)
    d.type = CAROM_STATIC;
  if (count == 0)
    problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
  for (i = 0; i < count; ++i)
    {
      carom_shape_def *sh = &shapes[i];
      uint8_t flags = fuzz_u8 (&f->in);
      double size = (flags & 1) ? fuzz_number (&f->in, 0) : 0.25 + (fuzz_u8 (&f->in) & 7) * 0.25;
      if (carom_shape_def_init (sh, sizeof *sh) != CAROM_OK)
        FUZZ_FINDING ("shape_def_init failed");
      sh->x = (int8_t) fuzz_u8 (&f->in) * 0.25, sh->y = (int8_t) fuzz_u8 (&f->in) * 0.25;
      if (flags & 2)
        sh->x = fuzz_number (&f->in, 0), sh->angle = fuzz_number (&f->in, 0);
      if (flags & 4)
        sh->density = fuzz_number (&f->in, 0);
      if (flags & 8)
        sh->restitution = fuzz_number (&f->in, 0), sh->friction = fuzz_number (&f->in, 0);
      sh->kind = (flags & 16) ? CAROM_SHAPE_POLYGON : CAROM_SHAPE_CIRCLE;
      if ((flags & 0x60) == 0x60)
        sh->kind = (carom_shape_kind) (int32_t) fuzz_u32 (&f->in);
      if (!isfinite (sh->x) || !isfinite (sh->angle) || !isfinite (sh->density) || !isfinite (sh->restitution)
          || !isfinite (sh->friction) || !isfinite (size))
        problems |= BIT (CAROM_ERR_NOT_FINITE);
      if (too_big (sh->x) || too_big (sh->angle) || sh->restitution > 1.0
          || (sh->kind != CAROM_SHAPE_CIRCLE && sh->kind != CAROM_SHAPE_POLYGON))
        problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
      if (sh->density == 0.0)
        problems |= BIT (CAROM_ERR_BAD_DENSITY);
      if (sh->kind == CAROM_SHAPE_POLYGON)
        {
          const double *src = (flags & 128) ? shape_arrow : shape_u;
          n = (flags & 128) ? 4 : 8;
          for (j = 0; j < 2 * n; ++j)
            xy[i][j] = src[j] * size;
          sh->xy = xy[i], sh->count = n;
          if (size == 0.0)
            problems |= BIT (CAROM_ERR_REPEATED_VERTEX);
          /* far out or turned, rounding may merge, flatten or cross
           * vertices: the polygon statuses are truthful then */
          extreme |= BIT (CAROM_ERR_REPEATED_VERTEX) | BIT (CAROM_ERR_ZERO_AREA) | BIT (CAROM_ERR_SELF_INTERSECTING);
        }
      else
        {
          sh->radius = size;
          if (isfinite (size) && !(size > SIZE_LO && size < SIZE_HI))
            problems |= BIT (CAROM_ERR_BAD_SIZE);
        }
      if (!in_range (fabs (size), 1e-30, 1e30) || !(sh->density < 0.0 || in_range (sh->density, 1e-30, 1e30))
          || !in_range (fabs (sh->x), 0.0, 1e30))
        extreme |= BIT (CAROM_ERR_BAD_SIZE) | BIT (CAROM_ERR_BAD_DENSITY) | BIT (CAROM_ERR_NOT_FINITE);
    }
  s = carom_world_add_compound (f->w, &d, shapes, count, &id);
  TRACE ("add compound of %d shapes: status %d\n", (int) count, (int) s);
  if (!fuzz_known_status (s))
    FUZZ_FINDING ("add_compound returned unknown status %d", (int) s);
  if (problems != 0 ? s == CAROM_OK || !((problems | extreme) & BIT (s)) : s != CAROM_OK && !(extreme & BIT (s)))
    FUZZ_FINDING ("add_compound of %d shapes returned %d (%s); problems 0x%x, extreme 0x%x", (int) count, (int) s,
                  carom_status_string (s), problems, extreme);
  if (s != CAROM_OK)
    {
      if (id != 99 || carom_world_body_count (f->w) != before)
        FUZZ_FINDING ("a refused add_compound wrote *id or changed the body count");
      return;
    }
  if (carom_body_get_shape_count (f->w, id, &n) != CAROM_OK || n != count)
    FUZZ_FINDING ("a compound of %d shapes has %d", (int) count, (int) n);
  for (i = 0; i < count; ++i)
    {
      carom_shape_kind kind;
      double x, y, r, density, e, mu, v[32];
      int32_t vn;
      if (carom_body_get_shape_geometry (f->w, id, i, &kind, &x, &y, &r, v, 16, &vn) != CAROM_OK
          || carom_body_get_shape_material (f->w, id, i, &density, &e, &mu) != CAROM_OK)
        FUZZ_FINDING ("shape %d of a compound cannot be read", (int) i);
      if (kind != shapes[i].kind || vn != (kind == CAROM_SHAPE_POLYGON ? shapes[i].count : 0) || !(r > 0.0)
          || !(density > 0.0) || !(e >= 0.0 && e <= 1.0) || !(mu >= 0.0))
        FUZZ_FINDING ("shape %d of a compound reads back wrong", (int) i);
    }
  fuzz_check_world (f->w, "after a compound");
  if (f->count >= 64)
    {
      if (carom_world_remove_body (f->w, id) != CAROM_OK)
        FUZZ_FINDING ("removing a new compound failed");
      return;
    }
  f->fixed[f->count] = 0;
  f->ids[f->count++] = id;
}

/* A joint of a fuzzed type between two of the bodies (or the world, a
 * stale or a made-up body), with fuzzed anchors, axis, limits, motor and
 * spring: refused with a status that applies and nothing changed, or
 * accepted and then simulated. */
static void add_fuzzed_joint (fuzz_world *f)
{
  carom_joint_def d;
  carom_joint_id id = 99;
  uint8_t flags = fuzz_u8 (&f->in), pick_a = fuzz_u8 (&f->in), pick_b = fuzz_u8 (&f->in);
  int32_t before = carom_world_joint_count (f->w);
  unsigned problems = 0, extreme = 0;
  carom_body_type ta = CAROM_STATIC, tb = CAROM_STATIC;
  carom_status s;
  double values[14];
  size_t i;
  if (carom_joint_def_init (&d, sizeof d) != CAROM_OK)
    FUZZ_FINDING ("joint_def_init failed");
  d.type = (carom_joint_type) (fuzz_u8 (&f->in) % 8); /* 7: not a type */
  d.a = f->count && pick_a < 200 ? f->ids[pick_a % f->count] : pick_a < 240 ? CAROM_NULL_BODY
        : f->dead_count ? f->dead[pick_a % f->dead_count] : (carom_body_id) fuzz_u32 (&f->in);
  d.b = f->count && pick_b < 220 ? f->ids[pick_b % f->count] : pick_b < 240 ? CAROM_NULL_BODY
        : f->dead_count ? f->dead[pick_b % f->dead_count] : (carom_body_id) fuzz_u32 (&f->in);
  if (d.type == CAROM_JOINT_MOUSE && (flags & 1))
    d.a = CAROM_NULL_BODY;
  /* anchors near the bodies, or fuzzed */
  if (carom_body_get_position (f->w, d.b, &d.x, &d.y) != CAROM_OK)
    d.x = d.y = 0.0;
  d.x += (int8_t) fuzz_u8 (&f->in) * 0.125, d.y += (int8_t) fuzz_u8 (&f->in) * 0.125;
  d.x2 = d.x + (int8_t) fuzz_u8 (&f->in) * 0.125, d.y2 = d.y + (int8_t) fuzz_u8 (&f->in) * 0.125;
  d.axis_x = (int8_t) fuzz_u8 (&f->in), d.axis_y = (int8_t) fuzz_u8 (&f->in);
  if (flags & 2)
    d.x = fuzz_number (&f->in, 0), d.y2 = fuzz_number (&f->in, 0), d.axis_x = fuzz_number (&f->in, 0);
  d.enable_limit = (flags & 4) != 0;
  d.lower = (int8_t) fuzz_u8 (&f->in) * 0.05, d.upper = (int8_t) fuzz_u8 (&f->in) * 0.05;
  if (flags & 8)
    d.lower = fuzz_number (&f->in, 0);
  d.enable_motor = (flags & 16) != 0;
  d.motor_speed = (int8_t) fuzz_u8 (&f->in) * 0.5, d.max_motor_force = fuzz_u8 (&f->in) * 10.0;
  d.max_motor_torque = fuzz_u8 (&f->in) * 10.0;
  if (flags & 32)
    d.motor_speed = fuzz_number (&f->in, 0), d.max_motor_force = fuzz_number (&f->in, 0);
  d.enable_spring = (flags & 64) != 0;
  d.hertz = fuzz_u8 (&f->in) * 0.25, d.damping_ratio = fuzz_u8 (&f->in) * 0.05;
  if (flags & 128)
    d.hertz = fuzz_number (&f->in, 0), d.damping_ratio = fuzz_number (&f->in, 0), d.length = fuzz_number (&f->in, 0);
  d.collide_connected = fuzz_u8 (&f->in) & 1;
  /* what include/carom.h says must be refused */
  values[0] = d.x, values[1] = d.y, values[2] = d.x2, values[3] = d.y2, values[4] = d.axis_x, values[5] = d.axis_y;
  values[6] = d.lower, values[7] = d.upper, values[8] = d.motor_speed, values[9] = d.max_motor_force;
  values[10] = d.hertz, values[11] = d.damping_ratio, values[12] = d.length, values[13] = d.max_motor_torque;
  for (i = 0; i < 14; ++i)
    {
      if (!isfinite (values[i]))
        problems |= BIT (CAROM_ERR_NOT_FINITE);
      if (too_big (values[i]))
        problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
    }
  if (d.type > CAROM_JOINT_MOUSE || d.a == d.b || (d.type == CAROM_JOINT_MOUSE && d.a != CAROM_NULL_BODY)
      || (d.enable_limit && d.lower > d.upper) || d.max_motor_force < 0.0 || d.max_motor_torque < 0.0
      || d.hertz < 0.0 || d.damping_ratio < 0.0 || d.length < 0.0
      || ((d.type == CAROM_JOINT_PRISMATIC || d.type == CAROM_JOINT_WHEEL)
          && !(d.axis_x * d.axis_x + d.axis_y * d.axis_y > 0.0))) /* no direction, or one that underflows */
    problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
  if (d.type == CAROM_JOINT_DISTANCE && d.length == 0.0 && d.x == d.x2 && d.y == d.y2)
    problems |= BIT (CAROM_ERR_BAD_ARGUMENT);
  /* anchors that differ by rounding alone, axes that underflow */
  extreme |= BIT (CAROM_ERR_BAD_ARGUMENT);
  if ((d.a != CAROM_NULL_BODY && carom_body_get_type (f->w, d.a, &ta) != CAROM_OK)
      || carom_body_get_type (f->w, d.b, &tb) != CAROM_OK)
    problems |= BIT (CAROM_ERR_STALE_BODY);
  else if (ta != CAROM_DYNAMIC && tb != CAROM_DYNAMIC)
    problems |= BIT (CAROM_ERR_STATIC_BODY);
  s = carom_world_add_joint (f->w, &d, &id);
  TRACE ("add joint type %d: status %d\n", (int) d.type, (int) s);
  if (!fuzz_known_status (s))
    FUZZ_FINDING ("add_joint returned unknown status %d", (int) s);
  if (problems != 0 ? s == CAROM_OK || !(problems & BIT (s)) : s != CAROM_OK && !(extreme & BIT (s)))
    FUZZ_FINDING ("add_joint type %d returned %d (%s); problems 0x%x", (int) d.type, (int) s,
                  carom_status_string (s), problems);
  if (s != CAROM_OK)
    {
      if (id != 99 || carom_world_joint_count (f->w) != before)
        FUZZ_FINDING ("a refused add_joint wrote *id or changed the joint count");
      return;
    }
  if (carom_joint_check (f->w, id) != CAROM_OK || carom_world_joint_count (f->w) != before + 1)
    FUZZ_FINDING ("an added joint is not live");
  if (f->joint_count < 32)
    f->joints[f->joint_count++] = id;
}

/* The calls on a joint: one of those added (maybe gone with a body since),
 * a removed one or a made-up id, with fuzzed motor and target values. */
static void op_joint (fuzz_world *f)
{
  uint8_t what = fuzz_u8 (&f->in) % 8, pick = fuzz_u8 (&f->in);
  double a = fuzz_number (&f->in, 0), b = fuzz_number (&f->in, 0), c = fuzz_number (&f->in, 0);
  carom_joint_id id = f->joint_count && pick < 200 ? f->joints[pick % f->joint_count]
                      : f->dead_joint_count && pick < 230 ? f->dead_joints[pick % f->dead_joint_count]
                                                          : (carom_joint_id) fuzz_u32 (&f->in) << 32 | fuzz_u32 (&f->in);
  int live = carom_joint_check (f->w, id) == CAROM_OK, i;
  carom_joint_type type = CAROM_JOINT_REVOLUTE;
  carom_body_id ba, bb;
  double x[4], fx, fy, t;
  carom_status s;
  int finite = isfinite (a) && isfinite (b) && isfinite (c), big = too_big (a) || too_big (b) || too_big (c);
  for (i = 0; i < f->dead_joint_count; ++i)
    if (carom_joint_check (f->w, f->dead_joints[i]) != CAROM_ERR_STALE_JOINT)
      FUZZ_FINDING ("removed joint %d came back", i);
  {
    /* the lists agree with the count and with each other */
    carom_joint_id all[64], mine[64];
    int32_t n = carom_world_get_joints (f->w, all, 64), k, m;
    if (n != carom_world_joint_count (f->w))
      FUZZ_FINDING ("get_joints says %d, joint_count %d", (int) n, (int) carom_world_joint_count (f->w));
    for (k = 0; k < n && k < 64; ++k)
      if (carom_joint_check (f->w, all[k]) != CAROM_OK)
        FUZZ_FINDING ("get_joints lists a stale joint");
    if (f->count > 0)
      {
        m = carom_body_get_joints (f->w, f->ids[pick % f->count], mine, 64);
        if (m < 0 ? m != -CAROM_ERR_STALE_BODY : m > n)
          FUZZ_FINDING ("body_get_joints returned %d of %d joints", (int) m, (int) n);
      }
  }
  if (live && carom_joint_get_bodies (f->w, id, &type, &ba, &bb) != CAROM_OK)
    FUZZ_FINDING ("a live joint's bodies cannot be read");
  if (live && (carom_body_check (f->w, bb) != CAROM_OK || (ba != CAROM_NULL_BODY && carom_body_check (f->w, ba) != CAROM_OK)))
    FUZZ_FINDING ("a live joint names a removed body");
  TRACE ("joint call %d on %s joint: (%.17g, %.17g, %.17g)\n", what, live ? "a live" : "a stale", a, b, c);
  switch (what)
    {
    case 0: /* (c is not an argument of this one) */
      finite = isfinite (a) && isfinite (b), big = too_big (a) || too_big (b);
      s = carom_joint_set_motor (f->w, id, 1, a, fabs (b));
      if (!live ? s != CAROM_ERR_STALE_JOINT
                : !finite ? s != CAROM_ERR_NOT_FINITE
                : (big || type == CAROM_JOINT_MOTOR || type == CAROM_JOINT_MOUSE || type == CAROM_JOINT_WELD)
                    ? s != CAROM_ERR_BAD_ARGUMENT
                    : s != CAROM_OK)
        FUZZ_FINDING ("set_motor (%.17g, %.17g) on a %s joint of type %d returned %d", a, b,
                      live ? "live" : "stale", (int) type, (int) s);
      break;
    case 1:
      s = carom_joint_set_target (f->w, id, a, b, c);
      if (!live ? s != CAROM_ERR_STALE_JOINT
                : !finite ? s != CAROM_ERR_NOT_FINITE
                : (big || (type != CAROM_JOINT_MOTOR && type != CAROM_JOINT_MOUSE)) ? s != CAROM_ERR_BAD_ARGUMENT
                                                                                     : s != CAROM_OK)
        FUZZ_FINDING ("set_target on a %s joint of type %d returned %d", live ? "live" : "stale", (int) type, (int) s);
      break;
    case 4: /* the limit: lower a, upper a + |b| (or b when c < 0, maybe below a) */
      {
        double upper = c < 0.0 ? b : a + fabs (b);
        int bad_type = type == CAROM_JOINT_WELD || type == CAROM_JOINT_MOTOR || type == CAROM_JOINT_MOUSE;
        s = carom_joint_set_limit (f->w, id, 1, a, upper);
        if (!live ? s != CAROM_ERR_STALE_JOINT
                  : !(isfinite (a) && isfinite (upper)) ? s != CAROM_ERR_NOT_FINITE
                  : (bad_type || too_big (a) || too_big (upper) || a > upper) ? s != CAROM_ERR_BAD_ARGUMENT
                                                                             : s != CAROM_OK)
          FUZZ_FINDING ("set_limit (%.17g, %.17g) on a %s joint of type %d returned %d", a, upper,
                        live ? "live" : "stale", (int) type, (int) s);
        break;
      }
    case 5:
      s = carom_joint_set_spring (f->w, id, (pick & 1) != 0, a, b);
      if (!live ? s != CAROM_ERR_STALE_JOINT
                : !(isfinite (a) && isfinite (b)) ? s != CAROM_ERR_NOT_FINITE
                : (type == CAROM_JOINT_MOTOR || a < 0.0 || b < 0.0 || too_big (a) || too_big (b))
                    ? s != CAROM_ERR_BAD_ARGUMENT
                    : s != CAROM_OK)
        FUZZ_FINDING ("set_spring (%.17g, %.17g) on a %s joint of type %d returned %d", a, b, live ? "live" : "stale",
                      (int) type, (int) s);
      break;
    case 2:
      s = carom_world_remove_joint (f->w, id);
      if (s != (live ? CAROM_OK : CAROM_ERR_STALE_JOINT))
        FUZZ_FINDING ("remove_joint of a %s joint returned %d", live ? "live" : "stale", (int) s);
      if (live && f->dead_joint_count < 16)
        f->dead_joints[f->dead_joint_count++] = id;
      break;
    default:
      s = carom_joint_get_reaction (f->w, id, &fx, &fy, &t);
      if (s == CAROM_OK && (!isfinite (fx) || !isfinite (fy) || !isfinite (t)))
        FUZZ_FINDING ("a joint's reaction is not finite");
      if (carom_joint_get_anchors (f->w, id, &x[0], &x[1], &x[2], &x[3]) != s)
        FUZZ_FINDING ("get_anchors and get_reaction disagree about the id");
      if (s != (live ? CAROM_OK : CAROM_ERR_STALE_JOINT))
        FUZZ_FINDING ("get_reaction of a %s joint returned %d", live ? "live" : "stale", (int) s);
      for (i = 0; s == CAROM_OK && i < 4; ++i)
        if (!isfinite (x[i]))
          FUZZ_FINDING ("a joint's anchor is not finite");
      break;
    }
}

/* Forces, impulses, filters, user data, ray casts, queries, events and the
 * debug draw with fuzzed arguments: non-finite numbers give NOT_FINITE,
 * ones beyond CAROM_MAX_MAGNITUDE BAD_ARGUMENT (also a sum or a resulting
 * velocity beyond it), a static or kinematic body STATIC_BODY for forces
 * and impulses, and nothing changes then; what is accepted leaves the
 * world finite, and what the queries report is consistent. */
static void op_api (fuzz_world *f)
{
  state before[64];
  uint8_t what = fuzz_u8 (&f->in) % 13;
  int k = f->count ? fuzz_u8 (&f->in) % f->count : 0;
  double a = fuzz_number (&f->in, 0), b = fuzz_number (&f->in, 0), c = fuzz_number (&f->in, 0),
         d = fuzz_number (&f->in, 0);
  uint32_t mask = fuzz_u32 (&f->in);
  carom_body_id id = f->count ? f->ids[k] : 0;
  carom_body_type type = CAROM_DYNAMIC;
  carom_status s = CAROM_OK;
  int finite = isfinite (a) && isfinite (b) && isfinite (c) && isfinite (d);
  int big = too_big (a) || too_big (b) || too_big (c) || too_big (d);
  if (what == 10)
    {
      add_fuzzed_compound (f);
      return;
    }
  if (what == 11)
    {
      add_fuzzed_joint (f);
      return;
    }
  if (what == 12)
    {
      op_joint (f);
      return;
    }
  if (f->count == 0 && what < 6)
    return;
  if (f->count)
    carom_body_get_type (f->w, id, &type);
  TRACE ("api %d body %d (%.17g, %.17g, %.17g, %.17g) mask %x\n", what, k, a, b, c, d, mask);
  read_states (f, before);
  if (what < 4)
    {
      switch (what)
        {
        case 0: s = carom_body_apply_force (f->w, id, a, b, c, d); break;
        case 1: s = carom_body_apply_torque (f->w, id, a), finite = isfinite (a), big = too_big (a); break;
        case 2: s = carom_body_apply_impulse (f->w, id, a, b, c, d); break;
        default: s = carom_body_apply_angular_impulse (f->w, id, a), finite = isfinite (a), big = too_big (a); break;
        }
      if (type != CAROM_DYNAMIC ? s != CAROM_ERR_STATIC_BODY
          : !finite                ? s != CAROM_ERR_NOT_FINITE
          : big                    ? s != CAROM_ERR_BAD_ARGUMENT
                                   : s != CAROM_OK && s != CAROM_ERR_BAD_ARGUMENT)
        FUZZ_FINDING ("force or impulse call %d (%g, %g, %g, %g) on a body of type %d returned %d", what, a, b, c, d,
                      (int) type, (int) s);
      if (s != CAROM_OK)
        expect_unchanged (f, before, "a refused force or impulse");
      if (s == CAROM_OK && what < 2)
        carom_world_clear_forces (f->w); /* else most updates after would be refused as too strong */
      return;
    }
  switch (what)
    {
    case 4:
      {
        uint32_t cat, m;
        int32_t g;
        if (carom_body_set_filter (f->w, id, (uint32_t) fuzz_u32 (&f->in), mask, (int32_t) fuzz_u32 (&f->in))
                != CAROM_OK
            || carom_body_get_filter (f->w, id, &cat, &m, &g) != CAROM_OK || m != mask)
          FUZZ_FINDING ("set_filter and get_filter disagree");
        break;
      }
    case 5:
      {
        void *p = NULL;
        if (carom_body_set_user_data (f->w, id, f) != CAROM_OK || carom_body_get_user_data (f->w, id, &p) != CAROM_OK
            || p != f)
          FUZZ_FINDING ("user data did not come back");
        break;
      }
    case 6:
      {
        carom_ray_hit hit;
        hit.body = 4242;
        s = carom_world_cast_ray (f->w, a, b, c, d, mask, &hit);
        if (!finite ? s != CAROM_ERR_NOT_FINITE : big ? s != CAROM_ERR_BAD_ARGUMENT : s != CAROM_OK)
          FUZZ_FINDING ("cast_ray (%g, %g, %g, %g) returned %d", a, b, c, d, (int) s);
        if (s != CAROM_OK && hit.body != 4242)
          FUZZ_FINDING ("a refused cast_ray wrote its hit");
        if (s == CAROM_OK && hit.body != CAROM_NULL_BODY
            && (carom_body_check (f->w, hit.body) != CAROM_OK || !(hit.fraction >= 0.0 && hit.fraction <= 1.0)
                || !isfinite (hit.x) || !isfinite (hit.y) || !isfinite (hit.nx) || !isfinite (hit.ny)))
          FUZZ_FINDING ("cast_ray hit a body that is not there, or at a bad fraction %g", hit.fraction);
        break;
      }
    case 7:
    case 8:
      {
        carom_body_id ids[64];
        int32_t n = what == 7 ? carom_world_query_aabb (f->w, a, b, c, d, mask, ids, 64)
                              : carom_world_query_point (f->w, a, b, mask, ids, 64);
        int bad_box = what == 7 && finite && !big && (a > c || b > d);
        int ok_numbers = what == 7 ? finite : isfinite (a) && isfinite (b);
        int ok_size = what == 7 ? !big : !too_big (a) && !too_big (b);
        if (!ok_numbers ? n != -CAROM_ERR_NOT_FINITE
            : !ok_size || bad_box ? n != -CAROM_ERR_BAD_ARGUMENT
                                  : n < 0 || n > carom_world_body_count (f->w))
          FUZZ_FINDING ("query %d (%g, %g, %g, %g) returned %d", what, a, b, c, d, (int) n);
        for (k = 0; k < n && k < 64; ++k)
          if (carom_body_check (f->w, ids[k]) != CAROM_OK)
            FUZZ_FINDING ("a query returned a body that is not there");
        break;
      }
    default:
      {
        carom_contact_event ev[32];
        carom_debug_draw draw;
        int drawn = 0, shapes = 0;
        int32_t n = carom_world_get_events (f->w, ev, 32);
        if (n < 0)
          FUZZ_FINDING ("get_events returned %d", (int) n);
        for (k = 0; k < n && k < 32; ++k)
          if ((int) ev[k].type < 0 || ev[k].type > CAROM_EVENT_SENSOR_END || !isfinite (ev[k].x)
              || !isfinite (ev[k].approach_speed) || !isfinite (ev[k].normal_impulse))
            FUZZ_FINDING ("event %d is not one", (int) k);
        carom_debug_draw_init (&draw, sizeof draw);
        draw.polygon = count_polygon, draw.circle = count_circle, draw.user = &drawn;
        for (k = 0; k < f->count; ++k)
          {
            int32_t m = 0;
            if (carom_body_get_shape_count (f->w, f->ids[k], &m) != CAROM_OK || m < 1)
              FUZZ_FINDING ("body %d has no shapes", k);
            shapes += m;
          }
        if (carom_world_draw (f->w, &draw) != CAROM_OK || drawn != shapes)
          FUZZ_FINDING ("the debug draw drew %d shapes of %d", drawn, shapes);
        break;
      }
    }
}

/* Ids that name nothing: removed ones, 0, and made-up ones. */
static void op_bad_ids (fuzz_world *f)
{
  carom_body_id id;
  double x;
  int i;
  uint64_t made_up = (uint64_t) fuzz_u32 (&f->in) << 32 | fuzz_u32 (&f->in);
  for (i = 0; i < f->dead_count; ++i)
    if (carom_body_check (f->w, f->dead[i]) != CAROM_ERR_STALE_BODY)
      FUZZ_FINDING ("removed id %d came back", i);
  if (carom_body_check (f->w, CAROM_NULL_BODY) != CAROM_ERR_STALE_BODY)
    FUZZ_FINDING ("the null id is live");
  id = (carom_body_id) made_up;
  if (carom_body_get_position (f->w, id, &x, NULL) == CAROM_OK)
    {
      for (i = 0; i < f->count; ++i)
        if (f->ids[i] == id)
          return;
      FUZZ_FINDING ("made-up id %llx names a body", (unsigned long long) id);
    }
  else if (carom_body_check (f->w, id) != CAROM_ERR_STALE_BODY)
    FUZZ_FINDING ("made-up id %llx: not STALE_BODY", (unsigned long long) id);
}

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  fuzz_world f;
  int i, bodies, ops;
  memset (&f, 0, sizeof f);
  f.in.p = data;
  f.in.n = size;
  make_world (&f);
  bodies = fuzz_u8 (&f.in) % (MAX_BODIES + 1);
  for (i = 0; i < bodies; ++i)
    add_fuzzed_body (&f);
  fuzz_check_world (f.w, "after the bodies");
  ops = fuzz_u8 (&f.in) % (MAX_OPS + 1);
  for (i = 0; i < ops && f.in.n > 0; ++i)
    {
      switch (fuzz_u8 (&f.in) % 10)
        {
        case 0:
        case 1:
        case 2: op_update (&f); break;
        case 3: op_remove (&f); break;
        case 4: op_set (&f); break;
        case 5: add_fuzzed_body (&f); break;
        case 6:
          if (carom_world_detect (f.w) != CAROM_OK)
            FUZZ_FINDING ("detect failed");
          break;
        case 7: op_effects (&f); break;
        case 8: op_api (&f); break;
        default: op_bad_ids (&f); break;
        }
      fuzz_check_world (f.w, "after an operation");
    }
  carom_world_destroy (f.w);
  return 0;
}
