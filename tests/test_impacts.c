/* Impacts. Under gravity with continuous collision a bounce is the impulse
 * of eq. 3.23 at its time within the step, with gravity before it, the
 * impact, and gravity after it, so bounce heights are those of the closed
 * form, e^(2k) h0, to rounding. Without external forces, clusters of bodies
 * keep their momentum and never gain energy. */
#include "support.h"

#include <math.h>
#include <stdio.h>

#define G 9.81
#define SIZE 0.1 /* the ball's radius, the box's half side */

/* Drop a ball or a box with its bottom at h0 onto a static floor and
 * return the largest relative error of its first `apexes` apexes against
 * e^(2k) h0 (each apex from the state after the step in which it rises no
 * more: y + vy^2 / 2g, exact for free flight); *seen is how many there
 * were within `seconds`. */
static double apex_error (double h0, double e, int box, int32_t substeps, double dt, int apexes, double seconds,
                          int *seen)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_body_id id;
  double worst = 0.0, last_vy = 0.0;
  int k = 0, step, steps = (int) (seconds / dt);
  carom_world_def_init (&def, sizeof def);
  def.gravity_y = -G;
  def.restitution = e;
  def.substeps = substeps;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 10.0, 1.0);
  carom_body_def_init (&d, sizeof d);
  d.y = h0 + SIZE;
  if (box)
    assert_status (carom_world_add_box (w, &d, 2.0 * SIZE, 2.0 * SIZE, &id), CAROM_OK);
  else
    assert_status (carom_world_add_circle (w, &d, SIZE, &id), CAROM_OK);
  for (step = 0; step < steps && k < apexes; ++step)
    {
      double y, vy;
      assert_status (carom_world_update (w, dt), CAROM_OK);
      carom_body_get_position (w, id, NULL, &y);
      carom_body_get_velocity (w, id, NULL, &vy);
      if (last_vy > 0.0 && vy <= 0.0)
        {
          double apex = y + vy * vy / (2.0 * G) - SIZE, err;
          ++k;
          err = fabs (apex / (pow (e * e, k) * h0) - 1.0);
          worst = err > worst ? err : worst;
        }
      last_vy = vy;
    }
  carom_world_destroy (w);
  *seen = k;
  return worst;
}

/* A ball and a box of e = 0.5, 0.8 and 1 dropped from 13 heights in
 * [0.5, 2], at dt 1/60 and 1/120, with 1 and 4 sub-steps: each of their
 * first three apexes is e^(2k) h0 to 1e-12. (The meeting of each impact
 * falls anywhere within its step and sub-step over these heights.) */
static void test_bounce_apexes_are_the_closed_form (void **state)
{
  static const double es[] = { 0.5, 0.8, 1.0 }, dts[] = { 1.0 / 60.0, 1.0 / 120.0 };
  static const int32_t substeps[] = { 1, 4 };
  double worst = 0.0;
  int i, ie, id, is, box;
  (void) state;
  for (ie = 0; ie < 3; ++ie)
    for (id = 0; id < 2; ++id)
      for (is = 0; is < 2; ++is)
        for (box = 0; box < 2; ++box)
          for (i = 0; i <= 12; ++i)
            {
              int seen;
              double h0 = 0.5 + 0.125 * i;
              double err = apex_error (h0, es[ie], box, substeps[is], dts[id], 3, 10.0, &seen);
              if (seen < 3 || !(err < 1e-12))
                fail_msg ("%s, e %g, h0 %g, dt 1/%g, %d sub-steps: %d apexes, error %.3g", box ? "box" : "ball",
                          es[ie], h0, 1.0 / dts[id], (int) substeps[is], seen, err);
              worst = err > worst ? err : worst;
            }
  print_message ("bounce apexes against e^2k h0: largest relative error %.3g\n", worst);
}

/* An elastic ball keeps its height: every apex over 10 s at dt 1/60 is h0
 * to 1e-12. */
static void test_elastic_ball_keeps_its_height (void **state)
{
  int i;
  (void) state;
  for (i = 0; i <= 6; ++i)
    {
      int seen;
      double h0 = 0.5 + 0.25 * i, err = apex_error (h0, 1.0, 0, 4, 1.0 / 60.0, 1000, 10.0, &seen);
      if (seen < 5 || !(err < 1e-12))
        fail_msg ("h0 %g: %d apexes in 10 s, error %.3g", h0, seen, err);
    }
}

/* Twelve bodies (boxes, pentagons, discs) thrown at one another with no
 * gravity: linear momentum is kept to 1e-12 of its size and the kinetic
 * energy never rises, for e = 0, 0.5 and 1, with and without friction and
 * continuous collision. */
static void cluster_totals (const carom_world *w, const carom_body_id *ids, int n, double *px, double *py, double *e)
{
  int i;
  *px = *py = *e = 0.0;
  for (i = 0; i < n; ++i)
    {
      double m, inertia, vx, vy, spin;
      carom_body_get_mass (w, ids[i], &m, &inertia, NULL);
      carom_body_get_velocity (w, ids[i], &vx, &vy);
      carom_body_get_spin (w, ids[i], &spin);
      *px += m * vx, *py += m * vy;
      *e += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * spin * spin;
    }
}

static void test_free_clusters_keep_momentum_and_never_gain_energy (void **state)
{
  static const double es[] = { 0.0, 0.5, 1.0 }, mus[] = { 0.0, 0.5 };
  int ie, im, cont, i, step;
  (void) state;
  for (ie = 0; ie < 3; ++ie)
    for (im = 0; im < 2; ++im)
      for (cont = 0; cont < 2; ++cont)
        {
          carom_world *w = NULL;
          carom_world_def def;
          carom_body_id ids[12];
          double px0, py0, e0, worst_p = 0.0, worst_e = 0.0;
          uint32_t seed = 12345u;
          carom_world_def_init (&def, sizeof def);
          def.restitution = es[ie];
          def.friction = mus[im];
          assert_status (carom_world_init (&w, &def), CAROM_OK);
          assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
          for (i = 0; i < 12; ++i)
            {
              carom_body_def d;
              double a = 2.0 * M_PI * i / 12;
              carom_body_def_init (&d, sizeof d);
              seed = seed * 1103515245u + 12345u;
              d.x = 4.0 * cos (a), d.y = 4.0 * sin (a), d.angle = a;
              d.vx = -3.0 * cos (a) + (double) (seed >> 16) / 65536.0 - 0.5, d.vy = -3.0 * sin (a);
              d.spin = (double) (seed & 0xffffu) / 16384.0 - 2.0;
              if (i % 3 == 0)
                assert_status (carom_world_add_box (w, &d, 0.8, 0.5, &ids[i]), CAROM_OK);
              else if (i % 3 == 1)
                assert_status (carom_world_add_regular (w, &d, 5, 0.5, &ids[i]), CAROM_OK);
              else
                assert_status (carom_world_add_circle (w, &d, 0.4, &ids[i]), CAROM_OK);
            }
          cluster_totals (w, ids, 12, &px0, &py0, &e0);
          for (step = 0; step < 300; ++step)
            {
              double px, py, e;
              assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
              cluster_totals (w, ids, 12, &px, &py, &e);
              worst_p = fmax (worst_p, hypot (px - px0, py - py0) / hypot (px0, py0));
              worst_e = fmax (worst_e, e / e0 - 1.0);
            }
          if (!(worst_p < 1e-12) || !(worst_e <= 1e-12))
            fail_msg ("e %g, mu %g, continuous %d: momentum off by %.3g, energy up by %.3g", es[ie], mus[im], cont,
                      worst_p, worst_e);
          carom_world_destroy (w);
        }
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_bounce_apexes_are_the_closed_form),
    cmocka_unit_test (test_elastic_ball_keeps_its_height),
    cmocka_unit_test (test_free_clusters_keep_momentum_and_never_gain_energy),
  };
  return cmocka_run_group_tests_name ("impacts", tests, NULL, NULL);
}
