/* Helpers shared by the test binaries. */
#ifndef CAROM_TEST_SUPPORT_H
#define CAROM_TEST_SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "carom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* |a - b| <= tol * max(|a|, |b|, tiny) */
int near_rel (double a, double b, double tol);
#define assert_near_rel(a, b, tol)                                            \
  do {                                                                        \
    double a_ = (a), b_ = (b);                                                \
    if (!near_rel (a_, b_, tol))                                              \
      fail_msg ("%s = %.17g, %s = %.17g, relative tolerance %g", #a, a_, #b,  \
                b_, (double) (tol));                                          \
  } while (0)
#define assert_near_abs(a, b, tol)                                            \
  do {                                                                        \
    double a_ = (a), b_ = (b);                                                \
    if (!(a_ - b_ <= (tol) && b_ - a_ <= (tol)))                              \
      fail_msg ("%s = %.17g, %s = %.17g, absolute tolerance %g", #a, a_, #b,  \
                b_, (double) (tol));                                          \
  } while (0)
#define assert_status(expr, want)                                             \
  do {                                                                        \
    carom_status s_ = (expr);                                                 \
    if (s_ != (want))                                                         \
      fail_msg ("%s returned %d (%s), wanted %d (%s)", #expr, (int) s_,       \
                carom_status_string (s_), (int) (want),                       \
                carom_status_string (want));                                  \
  } while (0)

/* cmocka fixtures mirroring the world's init/destroy: *state is the world. */
int world_setup (void **state);
int world_teardown (void **state);

/* A world at the library defaults but for gravity (gx, gy) and the world's
 * restitution and friction; asserts that it was made. */
carom_world *world_with (double gx, double gy, double restitution, double friction);

/* A square of side `side` standing on its corner, turned by `degrees`,
 * on a static ground (gravity 10, friction 0.6, the given manifold
 * tolerance, the other settings the defaults) tips over onto its face in
 * 4 s: the deepest any of its corners reaches below the ground, over the
 * side. */
double tipping_box_depth (double manifold_tolerance, double side, double degrees, int continuous);

/* Add a width x height box of the given type at (x, y), turned by angle;
 * asserts that it was added and returns its id. */
carom_body_id add_box (carom_world *w, carom_body_type type, double x, double y, double angle, double width,
                       double height);
/* Total kinetic energy (translational and rotational) of all bodies. */
double world_kinetic_energy (const carom_world *world);
/* FNV-1a hash of the whole state a step depends on: settings and effects,
 * every live body (id, pose, velocities, inverse masses, materials, sleep,
 * pending forces, user data, filter, sensor), the last update's events,
 * every contact with the impulses it carries to the next step and its
 * manifold's reuse data, and every joint with what it holds and carries.
 * Equal only for bit-identical states. */
uint64_t world_state_hash (const carom_world *world);
/* Total linear momentum and angular momentum about the origin. */
void world_momentum (const carom_world *world, double *px, double *py, double *l);

#endif
