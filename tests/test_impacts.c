/* Impacts. Under gravity with continuous collision a bounce is the impulse
 * of eq. 3.23 at its time within the step, with gravity before it, the
 * impact, and gravity after it, so bounce heights are those of the closed
 * form, e^(2k) h0, to rounding. Without external forces, clusters of bodies
 * keep their momentum and never gain energy. */
#include "support.h"

#include "impact.h"
#include "world.h"

#include <math.h>
#include <stdio.h>

#define G 9.81
#define SIZE 0.1 /* the ball's radius, the box's half side */

/* Drop a ball (shape 0), a box (1) or a T (2: a concave outline standing
 * on its stem's one flat end, 0.95 SIZE below its centroid), with its
 * bottom at h0 onto a static floor and return
 * the largest relative error of its first `apexes` apexes against e^(2k)
 * h0 (each apex from the state after the step in which it rises no more:
 * y + vy^2 / 2g, exact for free flight); *seen is how many there were
 * within `seconds`. */
static double apex_error (double h0, double e, int shape, carom_narrow_phase narrow, int32_t substeps, double dt,
                          int apexes, double seconds, int *seen)
{
  /* the T about its centroid: a stem 2/3 SIZE wide and SIZE high under a
   * bar 2 SIZE wide and SIZE / 2 high; the centroid is SIZE / 20 below
   * their joint */
  const double s = SIZE, n = SIZE / 3.0, c = SIZE / 20.0;
  const double t[] = { -n, -s + c, n, -s + c, n, c, s, c, s, s / 2 + c, -s, s / 2 + c, -s, c, -n, c };
  const double bottom = shape == 2 ? s - c : s;
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
  def.narrow_phase = narrow;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 10.0, 1.0);
  carom_body_def_init (&d, sizeof d);
  d.y = h0 + bottom;
  if (shape == 2)
    assert_status (carom_world_add_polygon (w, &d, t, 8, &id), CAROM_OK);
  else if (shape == 1)
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
          double apex = y + vy * vy / (2.0 * G) - bottom, err;
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
 * falls anywhere within its step and sub-step over these heights.) The box
 * also with the vertex-edge method, whose convex whole outline takes its
 * time of impact as its one piece; and a T with it, whose concave outline
 * takes none: its impact is at its points' own meeting time, the root of
 * the gap closing under gravity. */
static void test_bounce_apexes_are_the_closed_form (void **state)
{
  static const double es[] = { 0.5, 0.8, 1.0 }, dts[] = { 1.0 / 60.0, 1.0 / 120.0 };
  static const int32_t substeps[] = { 1, 4 };
  double worst = 0.0;
  int i, ie, id, is, kind;
  (void) state;
  for (ie = 0; ie < 3; ++ie)
    for (id = 0; id < 2; ++id)
      for (is = 0; is < 2; ++is)
        for (kind = 0; kind < 4; ++kind) /* ball, box, box and H by the vertex-edge method */
          for (i = 0; i <= 12; ++i)
            {
              static const char *const names[] = { "ball", "box", "vertex-edge box", "vertex-edge T" };
              int seen;
              double h0 = 0.5 + 0.125 * i;
              double err = apex_error (h0, es[ie], kind == 3 ? 2 : kind > 0, kind >= 2 ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT,
                                       substeps[is], dts[id], 3, 10.0, &seen);
              if (seen < 3 || !(err < 1e-12))
                fail_msg ("%s, e %g, h0 %g, dt 1/%g, %d sub-steps: %d apexes, error %.3g", names[kind], es[ie], h0,
                          1.0 / dts[id], (int) substeps[is], seen, err);
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
      double h0 = 0.5 + 0.25 * i, err = apex_error (h0, 1.0, 0, CAROM_NARROW_SAT, 4, 1.0 / 60.0, 1000, 10.0, &seen);
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

/* ------------------------------------------- off-centre impacts, closed form */

/* A box of half sides hx, hy in free flight, no gravity: its centre at
 * (cx + vx t, cy + vy t), its angle a0 + w t. The largest x of its corners
 * at t; *corner is which. */
static double box_reach_x (double hx, double hy, double cx, double vx, double a0, double w, double t, int *corner)
{
  const double lx[4] = { -hx, hx, hx, -hx }, ly[4] = { -hy, -hy, hy, hy };
  double a = a0 + w * t, best = -INFINITY;
  int i;
  for (i = 0; i < 4; ++i)
    {
      double x = cx + vx * t + cos (a) * lx[i] - sin (a) * ly[i];
      if (x > best)
        best = x, *corner = i;
    }
  return best;
}

/* Whether a corner reaches the wall face x = 0 within (t_from, t_to] (a
 * fine scan). */
static int box_touches (double hx, double hy, double cx, double vx, double a0, double w, double t_from, double t_to)
{
  double t;
  int c;
  for (t = t_from + 1e-6; t <= t_to; t += 1e-6)
    if (box_reach_x (hx, hy, cx, vx, a0, w, t, &c) >= 0.0)
      return 1;
  return 0;
}

/* The first time a corner reaches x = 0 (a fine scan, then bisection). */
static double box_first_touch (double hx, double hy, double cx, double vx, double a0, double w)
{
  double lo = 0.0, hi;
  int c, i;
  for (hi = 1e-6; box_reach_x (hx, hy, cx, vx, a0, w, hi, &c) < 0.0; lo = hi, hi += 1e-6)
    ;
  for (i = 0; i < 200; ++i)
    {
      double mid = 0.5 * (lo + hi);
      if (box_reach_x (hx, hy, cx, vx, a0, w, mid, &c) >= 0.0)
        hi = mid;
      else
        lo = mid;
    }
  return hi;
}

/* The first impact of a body of mass m and inertia `inertia` about its
 * centre whose outermost points are a box's corners (half sides hx, hy) in
 * free flight from (cx, .) at (vx0, .), angle a0, spin w0, on the wall face
 * x = 0: its time (returned), the angle and corner then, and eq. 3.23's
 * velocity and spin after it, with n = (-1, 0) from the wall to the body:
 * (v + w x r) . n = -(vx - w r_y) and r x n = r_y. */
static double corner_impact (double hx, double hy, double m, double inertia, double cx, double vx0, double a0,
                             double w0, double e, double *a, int *corner, double *want_vx, double *want_w)
{
  double t, ry, vpn, j;
  t = box_first_touch (hx, hy, cx, vx0, a0, w0);
  *a = a0 + w0 * t;
  box_reach_x (hx, hy, cx, vx0, a0, w0, t, corner);
  ry = sin (*a) * (*corner == 1 || *corner == 2 ? hx : -hx) + cos (*a) * (*corner >= 2 ? hy : -hy);
  vpn = -(vx0 - w0 * ry);
  j = -(1.0 + e) * vpn / (1.0 / m + ry * ry / inertia);
  *want_vx = vx0 - j / m;
  *want_w = w0 + ry * j / inertia;
  return t;
}

/* A 0.5 x 0.3 box, tilted so one corner leads, spinning at 0, +-3 and +-12
 * rad/s, thrown at a static wall at (2.5, vy) from 24 angles and 5
 * distances, e = 1 and 0.5, continuous collision on: the step of its
 * impact leaves it with eq. 3.23's velocity and spin for the impulse at the
 * corner, at the moment it touches, to 1e-9 of its speed, and where that
 * event leaves it, to 1e-9 of a step's travel. (The detection
 * at the step's start sees the corner some way off, turned otherwise; the
 * point and the arm of the impact are those of the touch. Only isolated
 * corners count: where another corner is near enough to reach the wall
 * within the step, or the closed form's box touches it again, one impact
 * is not the answer.) */
static void test_corner_hit_is_the_closed_form (void **state)
{
  static const double es[] = { 1.0, 0.5 }, spins[] = { 0.0, 3.0, -3.0, 12.0, -12.0 };
  const double dt = 1.0 / 60.0, hx = 0.25, hy = 0.15, vx0 = 2.5, m = 4.0 * hx * hy;
  const double inertia = m * (4.0 * hx * hx + 4.0 * hy * hy) / 12.0, rho = sqrt (inertia / m);
  double worst = 0.0;
  int ie, ia, id, is, checked = 0, spun = 0;
  (void) state;
  for (is = 0; is < 5; ++is)
    for (ie = 0; ie < 2; ++ie)
      for (ia = 0; ia < 24; ++ia)
        for (id = 0; id < 5; ++id)
          {
            carom_world *w = NULL;
            carom_world_def def;
            carom_body_def d;
            carom_body_id box;
            double a0 = 0.1 + 2.0 * M_PI * ia / 24.0, vy0 = 0.3 * (ia % 3 - 1), w0 = spins[is], cx, t_hit, a;
            double want_vx, want_vy, want_w, vx, vy, ws, err, reach;
            int corner, step, hit_step, isolated, i;
            cx = -box_reach_x (hx, hy, 0.0, 0.0, a0, 0.0, 0.0, &corner) - 0.05 - 0.23 * vx0 * dt * id;
            t_hit = corner_impact (hx, hy, m, inertia, cx, vx0, a0, w0, es[ie], &a, &corner, &want_vx, &want_w);
            hit_step = (int) floor (t_hit / dt);
            want_vy = vy0;
            /* an isolated corner: every other corner stays farther from the
             * wall at the touch than it can travel in a step, before the
             * impact or after it */
            reach = (fabs (vx0) + fabs (want_vx) + (fabs (w0) + fabs (want_w)) * hypot (hx, hy)) * dt;
            isolated = 1;
            for (i = 0; i < 4; ++i)
              if (i != corner)
                {
                  double x = cx + vx0 * t_hit + cos (a) * (i == 1 || i == 2 ? hx : -hx) - sin (a) * (i >= 2 ? hy : -hy);
                  isolated &= -x > reach;
                }
            if (!isolated
                || box_touches (hx, hy, cx + vx0 * t_hit - want_vx * t_hit, want_vx, a - want_w * t_hit, want_w, t_hit,
                                (hit_step + 1) * dt))
              continue;
            carom_world_def_init (&def, sizeof def);
            def.restitution = es[ie];
            assert_status (carom_world_init (&w, &def), CAROM_OK);
            assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
            add_box (w, CAROM_STATIC, 0.5, 0.0, 0.0, 1.0, 20.0);
            carom_body_def_init (&d, sizeof d);
            d.x = cx, d.y = 0.2, d.angle = a0, d.vx = vx0, d.vy = vy0, d.spin = w0;
            assert_status (carom_world_add_box (w, &d, 2.0 * hx, 2.0 * hy, &box), CAROM_OK);
            for (step = 0; step <= hit_step; ++step)
              assert_status (carom_world_update (w, dt), CAROM_OK);
            carom_body_get_velocity (w, box, &vx, &vy);
            carom_body_get_spin (w, box, &ws);
            err = (fabs (vx - want_vx) + fabs (vy - want_vy) + fabs (ws - want_w) * rho) / (fabs (vx0) + fabs (vy0));
            {
              /* and where the event leaves it: free flight to the touch,
               * then at the new velocities to the end of the step */
              double end = (hit_step + 1) * dt, x, y, ang, pos;
              carom_body_get_position (w, box, &x, &y);
              carom_body_get_angle (w, box, &ang);
              pos = (fabs (x - (cx + vx0 * t_hit + want_vx * (end - t_hit))) + fabs (y - (0.2 + vy0 * end))
                     + fabs (ang - (a + want_w * (end - t_hit))) * rho)
                    / ((fabs (vx0) + fabs (vy0)) * dt);
              err = pos > err ? pos : err;
            }
            if (!(err < 1e-9))
              fail_msg ("e %g, spin %g, angle %g, start %g: v (%.12g, %.12g) w %.12g, closed form (%.12g, %.12g) w "
                        "%.12g: error %.3g",
                        es[ie], w0, a0, cx, vx, vy, ws, want_vx, want_vy, want_w, err);
            worst = err > worst ? err : worst;
            ++checked;
            spun += w0 != 0.0;
            carom_world_destroy (w);
          }
  assert_true (checked >= 120 && spun >= 60);
  print_message ("corner hits: %d against the closed form (%d spinning), largest error %.3g\n", checked, spun, worst);
}

/* A 4 x 0.05 bar (density 1) spinning at 60 and 200 rad/s, thrown at a
 * static wall at 2 m/s from 24 starting angles, e = 1 and 0.5, at the
 * library defaults (its ends move 2 m a step or more, far more than half
 * its size: it is swept, body_swept) and with continuous collision on:
 * the step of its first impact leaves it with eq. 3.23's
 * velocity and spin at the corner and the moment where it first touches
 * (found here by scanning the free flight), to 1e-6 of its speed; and over
 * 1 s no corner passes into the wall by more than its slop. With either
 * narrow phase, and the bar convex or notched (a V 0.01 deep in the middle
 * of each long side: concave, its mass and inertia the library's): the
 * vertex-edge method's whole outlines have their time of impact as their
 * single pieces do when convex, and as their convex pieces' earliest when
 * not (toi_first_touch). (At 200 rad/s
 * its ends move 400 m/s, 6.7 m a step: the first corner that touches is
 * seldom the one the detection saw nearest, and some corners sweep past
 * within a centimetre without touching.) */
static void test_spinning_bar_leaves_a_wall_as_the_closed_form (void **state)
{
  static const double spins[] = { 60.0, 200.0 }, es[] = { 1.0, 0.5 };
  const double dt = 1.0 / 60.0, hx = 2.0, hy = 0.025, vx0 = 2.0, notch = 0.01;
  const double notched_xy[] = { -hx, -hy, 0.0, -hy + notch, hx, -hy, hx, hy, 0.0, hy - notch, -hx, hy };
  double worst = 0.0, deepest = 0.0;
  int is, ie, ia, cont, np, notched;
  (void) state;
  for (notched = 0; notched < 2; ++notched)
    for (np = 0; np < 2; ++np)
      for (cont = 0; cont < 2; ++cont)
        for (is = 0; is < 2; ++is)
          for (ie = 0; ie < 2; ++ie)
            for (ia = 0; ia < 24; ++ia)
              {
                carom_world *w = NULL;
                carom_world_def def;
                carom_body_def d;
                carom_body_id bar;
                double a0 = 2.0 * M_PI * ia / 24.0, w0 = spins[is] * (ia % 2 ? -1.0 : 1.0), cx, t_hit, a;
                double want_vx, want_w, vx, vy, ws, err, m, inertia, rho;
                int corner, step, hit_step;
                cx = -box_reach_x (hx, hy, 0.0, 0.0, a0, 0.0, 0.0, &corner) - 0.1 - 0.37 * vx0 * dt * (ia % 5);
                carom_world_def_init (&def, sizeof def);
                def.restitution = es[ie];
                def.narrow_phase = np ? CAROM_NARROW_VERTEX_EDGE : CAROM_NARROW_SAT;
                assert_status (carom_world_init (&w, &def), CAROM_OK);
                assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
                add_box (w, CAROM_STATIC, 0.5, 0.0, 0.0, 1.0, 20.0);
                carom_body_def_init (&d, sizeof d);
                d.x = cx, d.y = 0.3, d.angle = a0, d.vx = vx0, d.spin = w0;
                if (notched)
                  assert_status (carom_world_add_polygon (w, &d, notched_xy, 6, &bar), CAROM_OK);
                else
                  assert_status (carom_world_add_box (w, &d, 2.0 * hx, 2.0 * hy, &bar), CAROM_OK);
                assert_status (carom_body_get_mass (w, bar, &m, &inertia, NULL), CAROM_OK);
                rho = sqrt (inertia / m);
                t_hit = corner_impact (hx, hy, m, inertia, cx, vx0, a0, w0, es[ie], &a, &corner, &want_vx, &want_w);
                hit_step = (int) floor (t_hit / dt);
                for (step = 0; step <= hit_step; ++step)
                  assert_status (carom_world_update (w, dt), CAROM_OK);
                carom_body_get_velocity (w, bar, &vx, &vy);
                carom_body_get_spin (w, bar, &ws);
                err = (fabs (vx - want_vx) + fabs (vy) + fabs (ws - want_w) * rho)
                      / (fabs (want_vx) + fabs (want_w) * rho);
                if (!(err < 1e-6))
                  fail_msg ("%s%s, continuous %d, spin %g, e %g, angle %g: v (%.9g, %.9g) w %.9g, closed form "
                            "(%.9g, 0) w %.9g: error %.3g",
                            np ? "vertex-edge" : "SAT", notched ? ", notched" : "", cont, w0, es[ie], a0, vx, vy, ws,
                            want_vx, want_w, err);
                worst = fmax (worst, err);
                for (; step < 60; ++step)
                  {
                    double x, ang;
                    assert_status (carom_world_update (w, dt), CAROM_OK);
                    carom_body_get_position (w, bar, &x, NULL);
                    carom_body_get_angle (w, bar, &ang);
                    deepest = fmax (deepest, box_reach_x (hx, hy, x, 0.0, ang, 0.0, 0.0, &corner));
                  }
                carom_world_destroy (w);
              }
  /* the slop: 1% of the bar's size, twice its area over its perimeter */
  if (!(deepest <= 0.01 * 2.0 * (4.0 * hx * hy) / (4.0 * (hx + hy)) + 1e-12))
    fail_msg ("a corner went %g into the wall", deepest);
  print_message ("spinning bar: largest error against the closed form %.3g, deepest corner %.3g\n", worst, deepest);
}

/* Two discs passing off-centre (offsets 0 to 0.9 of the sum of their radii),
 * e = 1 and 0.5, continuous collision on: after the step of the impact,
 * their velocities are eq. 3.23's along the line of their centres at the
 * moment they touch, to 1e-9 of the closing speed. */
static void test_off_centre_discs_are_the_closed_form (void **state)
{
  static const double es[] = { 1.0, 0.5 };
  const double dt = 1.0 / 60.0, ra = 0.3, rb = 0.2, va = 6.0, vb = -3.0;
  double worst = 0.0;
  int ie, io, id;
  (void) state;
  for (ie = 0; ie < 2; ++ie)
    for (io = 0; io < 10; ++io)
      for (id = 0; id < 4; ++id)
        {
          carom_world *w = NULL;
          carom_world_def def;
          carom_body_def d;
          carom_body_id a, b;
          double off = 0.09 * io * (ra + rb), gap = 0.1 + 0.31 * (va - vb) * dt * id, ma = M_PI * ra * ra,
                 mb = M_PI * rb * rb;
          double dx0 = ra + rb + gap, dy0 = off, dvx = vb - va, t_hit, nx, ny, vn, j, got[4], want[4], err;
          int step, hit_step;
          /* |(dx0 + dvx t, dy0)| = ra + rb */
          t_hit = (-dx0 + sqrt ((ra + rb) * (ra + rb) - dy0 * dy0)) / dvx;
          hit_step = (int) floor (t_hit / dt);
          nx = (dx0 + dvx * t_hit) / (ra + rb), ny = dy0 / (ra + rb);
          vn = dvx * nx;
          j = -(1.0 + es[ie]) * vn / (1.0 / ma + 1.0 / mb);
          want[0] = va - j * nx / ma, want[1] = -j * ny / ma, want[2] = vb + j * nx / mb, want[3] = j * ny / mb;
          carom_world_def_init (&def, sizeof def);
          def.restitution = es[ie];
          assert_status (carom_world_init (&w, &def), CAROM_OK);
          assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
          carom_body_def_init (&d, sizeof d);
          d.x = 0.0, d.vx = va;
          assert_status (carom_world_add_circle (w, &d, ra, &a), CAROM_OK);
          d.x = dx0, d.y = dy0, d.vx = vb;
          assert_status (carom_world_add_circle (w, &d, rb, &b), CAROM_OK);
          for (step = 0; step <= hit_step; ++step)
            assert_status (carom_world_update (w, dt), CAROM_OK);
          carom_body_get_velocity (w, a, &got[0], &got[1]);
          carom_body_get_velocity (w, b, &got[2], &got[3]);
          err = (fabs (got[0] - want[0]) + fabs (got[1] - want[1]) + fabs (got[2] - want[2]) + fabs (got[3] - want[3]))
                / (va - vb);
          if (!(err < 1e-9))
            fail_msg ("e %g, offset %g, gap %g: a (%.12g, %.12g) b (%.12g, %.12g), closed form a (%.12g, %.12g) b "
                      "(%.12g, %.12g): error %.3g",
                      es[ie], off, gap, got[0], got[1], got[2], got[3], want[0], want[1], want[2], want[3], err);
          worst = err > worst ? err : worst;
          carom_world_destroy (w);
        }
  print_message ("off-centre discs: largest error %.3g\n", worst);
}

/* ------------------------------------------------------ Newton's cradle */

/* The sequential model of a row of balls on a line: pairwise impacts
 * (eq. 3.23 in one dimension) between neighbours, left to right, again
 * until no neighbours close. */
static void row_sequential (const double *m, double *v, int n, double e)
{
  int sweep, i, any = 1;
  for (sweep = 0; sweep < 10000 && any; ++sweep)
    for (any = 0, i = 0; i + 1 < n; ++i)
      if (v[i] - v[i + 1] > 1e-15)
        {
          double j = (1.0 + e) * (v[i] - v[i + 1]) / (1.0 / m[i] + 1.0 / m[i + 1]);
          v[i] -= j / m[i];
          v[i + 1] += j / m[i + 1];
          any = 1;
        }
}

/* A row of n balls of radius r on the x axis (on a frictionless floor under
 * gravity when grav; restitution e; continuous collision cont), the first
 * first_gap from the second and moving at v0 along the row, the others gap
 * apart and at rest: the world, and each ball's id, mass, position and
 * velocity. */
static carom_world *row_world (double e, int grav, int cont, int n, double r, double v0, const double *density,
                               double gap, double first_gap, carom_body_id *ids, double *m, double *x, double *v)
{
  carom_world *w = NULL;
  carom_world_def def;
  int i;
  carom_world_def_init (&def, sizeof def);
  def.restitution = e;
  def.gravity_y = grav ? -G : 0.0;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
  if (grav)
    add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 20.0, 1.0);
  for (i = 0; i < n; ++i)
    {
      carom_body_def d;
      carom_body_def_init (&d, sizeof d);
      d.x = i == 0 ? 0.0 : 2.0 * r + first_gap + (2.0 * r + gap) * (i - 1), d.y = r;
      d.density = density[i], d.vx = i == 0 ? v0 : 0.0;
      assert_status (carom_world_add_circle (w, &d, r, &ids[i]), CAROM_OK);
      m[i] = d.density * M_PI * r * r;
      x[i] = d.x, v[i] = d.vx;
    }
  return w;
}

/* Rows of touching balls (radius 0.1) struck at one end at 1 m/s by their
 * first ball, touching the next: 3 and 5 equal balls with e = 1 (the last
 * leaves with the striker's speed, the others stay at rest), unequal masses
 * (density 2 and 3 for some balls) and e = 0.8. Without gravity, and on a
 * frictionless floor under gravity, with continuous collision off and on:
 * after the impact every ball's velocity is the sequential model's, to
 * 1e-9 of the striker's speed, and the row keeps its momentum. */
static void test_newtons_cradle_is_sequential (void **state)
{
  static const double densities[][5] = {
    { 1, 1, 1, 1, 1 }, { 1, 1, 1, 1, 1 }, { 2, 1, 1, 1, 1 }, { 1, 1, 3, 1, 1 }, { 1, 1, 1, 1, 1 } };
  static const int counts[] = { 3, 5, 3, 5, 5 };
  static const double es[] = { 1.0, 1.0, 1.0, 1.0, 0.8 };
  const double r = 0.1, v0 = 1.0;
  double worst = 0.0;
  int c, grav, cont;
  (void) state;
  for (c = 0; c < 5; ++c)
    for (grav = 0; grav < 2; ++grav)
      for (cont = 0; cont < 2; ++cont)
        {
          carom_body_id ids[5];
          double m[5], x[5], want[5], err = 0.0;
          int i, n = counts[c];
          carom_world *w = row_world (es[c], grav, cont, n, r, v0, densities[c], 0.0, 0.0, ids, m, x, want);
          row_sequential (m, want, n, es[c]);
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          for (i = 0; i < n; ++i)
            {
              double vx, vy;
              carom_body_get_velocity (w, ids[i], &vx, &vy);
              err = fmax (err, (fabs (vx - want[i]) + fabs (vy)) / v0);
            }
          if (!(err < 1e-9))
            {
              double vx[5];
              for (i = 0; i < n; ++i)
                carom_body_get_velocity (w, ids[i], &vx[i], NULL);
              fail_msg ("%d balls, e %g, case %d, gravity %d, continuous %d: velocities %.6g %.6g %.6g %.6g %.6g, "
                        "sequential %.6g %.6g %.6g %.6g %.6g: error %.3g",
                        n, es[c], c, grav, cont, vx[0], vx[1], vx[2], n > 3 ? vx[3] : 0.0, n > 4 ? vx[4] : 0.0,
                        want[0], want[1], want[2], n > 3 ? want[3] : 0.0, n > 4 ? want[4] : 0.0, err);
            }
          worst = fmax (worst, err);
          carom_world_destroy (w);
        }
  print_message ("Newton's cradle: largest error against the sequential model %.3g\n", worst);
}

/* Spinning polygons thrown at a wall, one corner just touching it and the
 * spin bringing the next one in within the same step (e = 1, no friction,
 * no gravity): 3- to 6-gons of side 0.4 and 0.72, at any angle, the
 * nearest corner 0 to 5 mm from a static wall, spinning at 5 to 20 rad/s,
 * at 3 to 8 m/s towards it, continuous collision off and on; and the same
 * against a free spinning body. Every strike is an impact at its own time,
 * with its own lever arms, from the velocities the last left: the kinetic
 * energy stays within 1e-9 of its start at every step for 20 steps, and the
 * pair's momentum within 1e-9 of its size. */
static void test_spinning_polygons_strike_again_within_a_step (void **state)
{
  uint64_t seed = 0x737472696b65ULL;
  double worst = 0.0;
  int n, cont;
  (void) state;
  for (n = 0; n < 500; ++n)
    for (cont = 0; cont < 2; ++cont)
      {
        carom_world *w = NULL;
        carom_world_def def;
        carom_body_def d;
        carom_body_id ids[2];
        double px0, py0, e0, px, py, e, p0 = 0.0, u[6], side = n % 2 ? 0.72 : 0.4, radius, top = -INFINITY;
        int i, step, free_target = n % 3 == 2, sides = 3 + n % 4;
        for (i = 0; i < 6; ++i)
          {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            u[i] = (double) (seed >> 11) * (1.0 / 9007199254740992.0);
          }
        carom_world_def_init (&def, sizeof def);
        def.restitution = 1.0;
        assert_status (carom_world_init (&w, &def), CAROM_OK);
        assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
        carom_body_def_init (&d, sizeof d);
        d.type = free_target ? CAROM_DYNAMIC : CAROM_STATIC;
        d.y = 0.5, d.spin = free_target ? 8.0 * (u[5] - 0.5) : 0.0;
        assert_status (carom_world_add_box (w, &d, free_target ? 1.0 : 20.0, 1.0, &ids[1]), CAROM_OK);
        /* the polygon's corners (one on +x before turning) at radius R */
        carom_body_def_init (&d, sizeof d);
        d.angle = 2.0 * M_PI * u[1];
        radius = side / (2.0 * sin (M_PI / sides));
        for (i = 0; i < sides; ++i)
          top = fmax (top, radius * sin (d.angle + 2.0 * M_PI * i / sides));
        d.y = -top - 0.005 * u[0];
        d.vx = 4.0 * (u[2] - 0.5), d.vy = 3.0 + 5.0 * u[3];
        d.spin = (u[4] < 0.5 ? -1.0 : 1.0) * (5.0 + 30.0 * fabs (u[4] - 0.5));
        assert_status (carom_world_add_regular (w, &d, sides, side, &ids[0]), CAROM_OK);
        cluster_totals (w, ids, 2, &px0, &py0, &e0);
        for (i = 0; i < 2; ++i)
          {
            double m, vx, vy;
            carom_body_get_mass (w, ids[i], &m, NULL, NULL);
            carom_body_get_velocity (w, ids[i], &vx, &vy);
            p0 += m * hypot (vx, vy);
          }
        for (step = 0; step < 20; ++step)
          {
            double err;
            assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
            cluster_totals (w, ids, 2, &px, &py, &e);
            err = fabs (e / e0 - 1.0);
            if (free_target)
              err = fmax (err, hypot (px - px0, py - py0) / p0);
            if (!(err < 1e-9))
              fail_msg ("case %d (%d-gon, %s target), continuous %d, step %d: energy %.3g, error %.3g", n, sides,
                        free_target ? "free" : "static", cont, step, e / e0 - 1.0, err);
            worst = fmax (worst, err);
          }
        carom_world_destroy (w);
      }
  print_message ("spinning polygons striking again: largest energy or momentum error %.3g\n", worst);
}

/* A row of balls on the x axis, radius r, apart by gaps, in free flight
 * for time T: each pairwise impact at its time (the earliest closing pair
 * first), eq. 3.23 along the line. The reference for rows with gaps. */
static void row_events (const double *m, double *x, double *v, int n, double r, double e, double T)
{
  double t = 0.0;
  int guard, i;
  for (guard = 0; guard < 100000; ++guard)
    {
      double first = T - t;
      int at = -1;
      for (i = 0; i + 1 < n; ++i)
        if (v[i] > v[i + 1])
          {
            double when = (x[i + 1] - x[i] - 2.0 * r) / (v[i] - v[i + 1]);
            when = when < 0.0 ? 0.0 : when;
            if (when < first)
              first = when, at = i;
          }
      for (i = 0; i < n; ++i)
        x[i] += v[i] * first;
      t += first;
      if (at < 0)
        break;
      {
        double j = (1.0 + e) * (v[at] - v[at + 1]) / (1.0 / m[at] + 1.0 / m[at + 1]);
        v[at] -= j / m[at];
        v[at + 1] += j / m[at + 1];
      }
    }
}

/* Rows of balls (radius 0.1) apart by 0.1, 0.25 and 0.5 mm (within the
 * contact margin of bodies at rest, so their contacts are found at the
 * start of the step), struck at one end at 1 m/s by a ball that touches the
 * first or is as far from it as the rest: equal and unequal masses,
 * e = 1 and 0.8, without gravity and on a frictionless floor, continuous
 * collision off and on. A body an impact sets moving meets the next at its
 * own time within the step, and so on down the row: after four steps every
 * ball's velocity is that of the pairwise impacts at their times
 * (row_events) to 1e-9 of the striker's speed, and its position to 1e-9 of
 * a step's travel. */
static void test_rows_with_gaps_are_impacts_in_turn (void **state)
{
  static const double densities[][5] = { { 1, 1, 1, 1, 1 }, { 2, 1, 1, 1, 1 }, { 1, 1, 3, 1, 1 }, { 1, 1, 1, 1, 1 } };
  static const int counts[] = { 5, 3, 5, 5 };
  static const double es[] = { 1.0, 1.0, 1.0, 0.8 };
  static const double gaps[] = { 0.0001, 0.00025, 0.0005 };
  const double r = 0.1, v0 = 1.0, dt = 1.0 / 60.0;
  double worst = 0.0;
  int c, gi, grav, cont;
  (void) state;
  for (c = 0; c < 4; ++c)
    for (gi = 0; gi < 6; ++gi) /* the last three: the striker touching the first */
      for (grav = 0; grav < 2; ++grav)
        for (cont = 0; cont < 2; ++cont)
          {
            carom_body_id ids[5];
            double m[5], x[5], v[5], err = 0.0;
            int i, n = counts[c], step;
            carom_world *w = row_world (es[c], grav, cont, n, r, v0, densities[c], gaps[gi % 3],
                                        gi >= 3 ? 0.0 : gaps[gi % 3], ids, m, x, v);
            row_events (m, x, v, n, r, es[c], 4.0 * dt);
            for (step = 0; step < 4; ++step)
              assert_status (carom_world_update (w, dt), CAROM_OK);
            for (i = 0; i < n; ++i)
              {
                double vx, vy, px, py;
                carom_body_get_velocity (w, ids[i], &vx, &vy);
                carom_body_get_position (w, ids[i], &px, &py);
                err = fmax (err, fmax ((fabs (vx - v[i]) + fabs (vy)) / v0, fabs (px - x[i]) / (v0 * dt)));
              }
            if (!(err < 1e-9))
              {
                double vx[5];
                for (i = 0; i < n; ++i)
                  carom_body_get_velocity (w, ids[i], &vx[i], NULL);
                fail_msg ("%d balls %.1f mm apart, e %g, case %d, gravity %d, continuous %d: velocities %.6g %.6g %.6g "
                          "%.6g %.6g, impacts in turn %.6g %.6g %.6g %.6g %.6g: error %.3g",
                          n, 1e3 * gaps[gi % 3], es[c], c, grav, cont, vx[0], vx[1], vx[2], n > 3 ? vx[3] : 0.0,
                          n > 4 ? vx[4] : 0.0, v[0], v[1], v[2], n > 3 ? v[3] : 0.0, n > 4 ? v[4] : 0.0, err);
              }
            worst = fmax (worst, err);
            carom_world_destroy (w);
          }
  print_message ("rows with gaps: largest error against impacts in turn %.3g\n", worst);
}

/* Rows of balls (radius 0.1) whose gaps, 3 to 20 mm, are beyond the
 * contact margin of bodies at rest (1 mm: their pairs have no contact at
 * the start of the step), struck by a first ball touching the next at 3
 * and 6 m/s: each ball an impact sets moving meets the next within the
 * same step. Equal and unequal masses, e = 1 and 0.8, without gravity,
 * continuous collision on; and off for equal balls with e = 1 at 6 m/s
 * for one step (each struck ball then leaves at the striker's speed and
 * travels more than half its size in the step, which gives it continuous
 * collision; a slower one meets the next as any body without it does, as
 * deep as it travels).
 * After one step and after four, every ball's
 * velocity is that of the pairwise impacts at their times (row_events) to
 * 1e-9 of the striker's speed, its position to 1e-9 of a step's travel,
 * and no two balls overlap. And rows of four struck from both ends at
 * 3 m/s, the middle two 20 to 80 mm apart: both set moving, they meet each
 * other within the step. */
static void test_struck_bodies_meet_what_the_detection_did_not_see (void **state)
{
  static const double densities[][5] = { { 1, 1, 1, 1, 1 }, { 2, 1, 1, 1, 1 }, { 1, 1, 3, 1, 1 }, { 1, 1, 1, 1, 1 } };
  static const int counts[] = { 3, 5, 5, 5 };
  static const double es[] = { 1.0, 1.0, 1.0, 0.8 };
  static const double gaps[] = { 0.003, 0.008, 0.02 };
  const double r = 0.1, dt = 1.0 / 60.0;
  double worst = 0.0;
  int c, gi, sp, steps;
  (void) state;
  for (c = 0; c < 4; ++c)
    for (gi = 0; gi < 3; ++gi)
      for (sp = 0; sp < (c == 0 ? 3 : 2); ++sp) /* 3 m/s and 6 m/s continuous on, 6 m/s off */
        for (steps = 1; steps <= (sp < 2 ? 4 : 1); steps += 3)
          {
            carom_body_id ids[5];
            double m[5], x[5], v[5], err = 0.0, v0 = sp == 0 ? 3.0 : 6.0, xs[5];
            int i, n = counts[c], step;
            carom_world *w = row_world (es[c], 0, sp < 2, n, r, v0, densities[c], gaps[gi], 0.0, ids, m, x, v);
            row_events (m, x, v, n, r, es[c], steps * dt);
            for (step = 0; step < steps; ++step)
              assert_status (carom_world_update (w, dt), CAROM_OK);
            for (i = 0; i < n; ++i)
              {
                double vx, vy, py;
                carom_body_get_velocity (w, ids[i], &vx, &vy);
                carom_body_get_position (w, ids[i], &xs[i], &py);
                err = fmax (err, fmax ((fabs (vx - v[i]) + fabs (vy)) / v0, fabs (xs[i] - x[i]) / (v0 * dt)));
                if (i > 0 && !(xs[i] - xs[i - 1] >= 2.0 * r - 1e-9 * v0 * dt))
                  fail_msg ("%d balls %.0f mm apart at %g m/s, case %d: balls %d and %d overlap by %.3g m", n,
                            1e3 * gaps[gi], v0, c, i - 1, i, 2.0 * r - (xs[i] - xs[i - 1]));
              }
            if (!(err < 1e-9))
              fail_msg ("%d balls %.0f mm apart at %g m/s (continuous %d), e %g, case %d, %d steps: error %.3g "
                        "against impacts in turn",
                        n, 1e3 * gaps[gi], v0, sp < 2, es[c], c, steps, err);
            worst = fmax (worst, err);
            carom_world_destroy (w);
          }
  /* struck from both ends: the two middle balls, both set moving, meet
   * each other (neither had a contact with the other at detection) */
  for (gi = 0; gi < 3; ++gi)
    {
      static const double ones[] = { 1, 1, 1, 1 };
      static const double mid_gaps[] = { 0.02, 0.05, 0.08 };
      carom_body_id ids[4];
      double m[4], x[4], v[4], err = 0.0, v0 = 3.0;
      int i, step;
      carom_world *w = row_world (1.0, 0, 1, 4, r, v0, ones, 0.0, 0.0, ids, m, x, v);
      /* the last ball touching the third, the middle gap as given */
      for (i = 2; i < 4; ++i)
        {
          x[i] += mid_gaps[gi];
          assert_status (carom_body_set_position (w, ids[i], x[i], r), CAROM_OK);
        }
      v[3] = -v0;
      assert_status (carom_body_set_velocity (w, ids[3], -v0, 0.0), CAROM_OK);
      row_events (m, x, v, 4, r, 1.0, 4.0 * dt);
      for (step = 0; step < 4; ++step)
        assert_status (carom_world_update (w, dt), CAROM_OK);
      for (i = 0; i < 4; ++i)
        {
          double vx, vy, px, py;
          carom_body_get_velocity (w, ids[i], &vx, &vy);
          carom_body_get_position (w, ids[i], &px, &py);
          err = fmax (err, fmax ((fabs (vx - v[i]) + fabs (vy)) / v0, fabs (px - x[i]) / (v0 * dt)));
        }
      if (!(err < 1e-9))
        fail_msg ("a row struck from both ends, the middle %.0f mm apart: error %.3g against impacts in turn",
                  1e3 * mid_gaps[gi], err);
      worst = fmax (worst, err);
      carom_world_destroy (w);
    }
  print_message ("rows beyond the margin: largest error against impacts in turn %.3g\n", worst);
}

/* A static comb (a concave polygon of `teeth` teeth 2 cm wide every 5 cm,
 * pointing to -x from x = tip, 40 cm long, on a 20 cm spine), its
 * centroid placed where the outline says. */
static void add_comb (carom_world *w, int teeth, double tip, double y)
{
  double xy[2 * (4 * 24 + 2)], area = 0.0, cx = 0.0, cy = 0.0;
  int n = 0, i, m;
  carom_body_def d;
  carom_body_id id;
  assert_true (teeth <= 24);
  xy[n++] = tip + 0.6, xy[n++] = y - 0.025 * teeth;
  xy[n++] = tip + 0.6, xy[n++] = y + 0.025 * teeth;
  for (i = teeth - 1; i >= 0; --i)
    {
      double y0 = y - 0.025 * teeth + 0.05 * i;
      xy[n++] = tip + 0.4, xy[n++] = y0 + 0.05;
      xy[n++] = tip, xy[n++] = y0 + 0.04;
      xy[n++] = tip, xy[n++] = y0 + 0.02;
      xy[n++] = tip + 0.4, xy[n++] = y0 + 0.01;
    }
  m = n / 2;
  for (i = 0; i < m; ++i)
    {
      int j = (i + 1) % m;
      double c = xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
      area += c, cx += (xy[2 * i] + xy[2 * j]) * c, cy += (xy[2 * i + 1] + xy[2 * j + 1]) * c;
    }
  carom_body_def_init (&d, sizeof d);
  d.type = CAROM_STATIC;
  d.x = cx / (3.0 * area), d.y = cy / (3.0 * area);
  assert_status (carom_world_add_polygon (w, &d, xy, m, &id), CAROM_OK);
}

/* A striker (r = 0.1, e = 1) sets a resting ball moving at v0 into a
 * static comb it had no contact with: a pair with a contact for each of
 * the comb's pieces, found after the impact (contacts_after_impacts).
 * Forty touching balls without restitution far away first make the
 * contact list's room much larger than the update keeps for contacts
 * added after the impacts. After each update the contacts fit the room
 * every array per contact was sized by (contacts.room_count: an update
 * that went past it wrote past those arrays). Returns how deep the
 * deepest ball ended an update past the comb's tips. */
static double comb_run (int rows, int teeth, double v0)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_body_id id, balls[16];
  double deepest = 0.0;
  int i, step;
  assert_true (rows <= 16);
  carom_world_def_init (&def, sizeof def);
  def.restitution = 1.0;
  def.friction = 0.0;
  def.gravity_y = 0.0;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  for (i = 0; i < 40; ++i)
    {
      carom_body_def_init (&d, sizeof d);
      d.restitution = 0.0;
      d.x = 100.0 + 0.2 * i, d.y = 50.0;
      assert_status (carom_world_add_circle (w, &d, 0.1, &id), CAROM_OK);
    }
  for (i = 0; i < rows; ++i)
    {
      add_comb (w, teeth, 0.75, 2.0 * i);
      carom_body_def_init (&d, sizeof d);
      d.y = 2.0 * i, d.vx = v0;
      assert_status (carom_world_add_circle (w, &d, 0.1, &id), CAROM_OK);
      d.x = 0.2, d.vx = 0.0;
      assert_status (carom_world_add_circle (w, &d, 0.1, &balls[i]), CAROM_OK);
    }
  for (step = 0; step < 6; ++step)
    {
      const contacts *c = &w->contacts;
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      if (!(c->count <= c->room_count && c->point_count <= c->room_points))
        fail_msg ("%d combs of %d teeth at %g m/s: %d contacts and %d points in room for %d and %d", rows, teeth, v0,
                  c->count, c->point_count, c->room_count, c->room_points);
      for (i = 0; i < rows; ++i)
        {
          double x, y;
          carom_body_get_position (w, balls[i], &x, &y);
          assert_true (isfinite (x) && isfinite (y));
          deepest = fmax (deepest, x + 0.1 - 0.75);
        }
    }
  carom_world_destroy (w);
  return deepest;
}

/* One comb: the room kept holds the pair, and the ball never ends an
 * update past the tips (without it, the pair waited for the next
 * detection and the ball was stopped 5 cm deep by the last guard).
 * Sixteen: more than the room holds, those left over wait. */
static void test_struck_body_meets_a_compound_within_the_room_kept (void **state)
{
  static const int teeth[] = { 4, 12, 20 };
  static const double speeds[] = { 30.0, 45.0 };
  int t, v, rows;
  (void) state;
  for (rows = 1; rows <= 16; rows += 15)
    for (t = 0; t < 3; ++t)
      for (v = 0; v < 2; ++v)
        {
          double deepest = comb_run (rows, teeth[t], speeds[v]);
          print_message ("%d comb(s) of %d teeth, struck at %g m/s: deepest %.3g m past the tips\n", rows, teeth[t],
                         speeds[v], deepest);
          if (rows == 1 && !(deepest <= 0.0))
            fail_msg ("a ball struck into a comb of %d teeth at %g m/s sank %.3g m into it", teeth[t], speeds[v],
                      deepest);
        }
}

/* A bouncy striker (e = 1) stops against a resting ball without
 * restitution and sets it moving at v0 into what it had no contact with at
 * detection, 0.1 to 0.3 m away: a static wall or a free box (1 x 4), both
 * without restitution. The pair found after the impact has e = 0: the
 * sub-steps stop the approach where the two meet, within the step (it was
 * made inert instead, the ball flying on into the wall until the last
 * guard stopped it, still at v0). After the first update the ball has no
 * speed left into the wall, or moves with the box, which carries the
 * striker's momentum, to 1e-9 of v0; it is nowhere past the face (the
 * slop allows 1% of r; a tenth of that is asked). */
static void test_struck_body_without_restitution_stops_at_what_it_meets (void **state)
{
  static const double gaps[] = { 0.1, 0.2, 0.3 }, speeds[] = { 20.0, 30.0, 45.0 };
  double worst = 0.0;
  int g, v, dyn;
  (void) state;
  for (dyn = 0; dyn < 2; ++dyn)
    for (g = 0; g < 3; ++g)
      for (v = 0; v < 3; ++v)
        {
          const double r = 0.1, v0 = speeds[v], face = 2.0 * r + r + gaps[g];
          carom_world *w = NULL;
          carom_world_def def;
          carom_body_def d;
          carom_body_id striker, ball, target;
          double bx, by, vx, vy, tvx, tvy, svx, svy, err, m_ball = M_PI * r * r, m_box = 4.0, ox, oy;
          carom_world_def_init (&def, sizeof def);
          def.restitution = 0.0, def.friction = 0.0, def.gravity_y = 0.0;
          assert_status (carom_world_init (&w, &def), CAROM_OK);
          assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
          carom_body_def_init (&d, sizeof d);
          d.type = dyn ? CAROM_DYNAMIC : CAROM_STATIC, d.x = face + 0.5;
          assert_status (carom_world_add_box (w, &d, 1.0, 4.0, &target), CAROM_OK);
          carom_body_def_init (&d, sizeof d);
          d.vx = v0, d.restitution = 1.0;
          assert_status (carom_world_add_circle (w, &d, r, &striker), CAROM_OK);
          carom_body_def_init (&d, sizeof d);
          d.x = 2.0 * r;
          assert_status (carom_world_add_circle (w, &d, r, &ball), CAROM_OK);
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          carom_body_get_position (w, ball, &bx, &by);
          carom_body_get_velocity (w, ball, &svx, &svy);
          carom_body_get_velocity (w, target, &tvx, &tvy);
          carom_body_get_velocity (w, striker, &vx, &vy);
          carom_body_get_position (w, target, &ox, &oy);
          if (dyn)
            err = fmax (fabs (svx - tvx), fabs (m_ball * (vx + svx) + m_box * tvx - m_ball * v0) / m_ball) / v0;
          else
            err = fmax (svx, 0.0) / v0;
          if (!(err <= 1e-9) || !(bx + r <= ox - 0.5 + 1e-3 * r))
            fail_msg ("%s %g m away, struck at %g m/s: the ball at %.6f (the face at %g) moving at %g, the target at "
                      "%g, the striker at %g (error %.3g)",
                      dyn ? "a free box" : "a wall", gaps[g], v0, bx, ox - 0.5, svx, tvx, vx, err);
          worst = fmax (worst, err);
          carom_world_destroy (w);
        }
  print_message ("struck without restitution: largest error %.3g of the striker's speed\n", worst);
}

/* Coulomb friction in an impact: a disc (radius r, no gravity) strikes a
 * static floor at normal speed vn and tangent speed vt, e = 0.5, with
 * continuous collision on. The impact's normal impulse is J = (1 + e) m vn;
 * its friction stops the slip at the contact if mu J reaches the impulse
 * that does, m vt / 3 for a disc (the tangent's effective mass, 1 / (1/m +
 * r^2 / I)): then vx = 2 vt / 3 and the disc rolls, w = -vx / r. Else it
 * slides: vx = vt - mu J / m and w = -mu J r / I. Eight cases of each kind,
 * over where in the step the disc meets the floor: the closed form to
 * 1e-12. */
static void test_impact_friction_is_coulombs (void **state)
{
  static const double cases[][3] = { { 10.0, 3.0, 0.6 }, { 4.0, 1.0, 1.0 }, { 2.0, 6.0, 0.2 }, { 5.0, 8.0, 0.3 } };
  int c, g;
  (void) state;
  for (c = 0; c < 4; ++c)
    for (g = 0; g < 8; ++g)
      {
        double vn = cases[c][0], vt = cases[c][1], mu = cases[c][2], e = 0.5, r = 0.5, J = (1.0 + e) * vn;
        double gap = (0.05 + 0.1 * g) * vn / 60.0, vx, vy, w, want_vx, want_w;
        carom_world *w_ = world_with (0.0, 0.0, e, mu);
        carom_body_def d;
        carom_body_id id;
        assert_status (carom_world_set_continuous (w_, 1), CAROM_OK);
        add_box (w_, CAROM_STATIC, 0.0, -0.5, 0.0, 40.0, 1.0);
        carom_body_def_init (&d, sizeof d);
        d.y = r + gap, d.vx = vt, d.vy = -vn;
        assert_status (carom_world_add_circle (w_, &d, r, &id), CAROM_OK);
        assert_status (carom_world_update (w_, 1.0 / 60.0), CAROM_OK);
        carom_body_get_velocity (w_, id, &vx, &vy);
        carom_body_get_spin (w_, id, &w);
        if (mu * J >= vt / 3.0)
          want_vx = 2.0 * vt / 3.0, want_w = -want_vx / r;
        else
          want_vx = vt - mu * J, want_w = -mu * J * r / (0.5 * r * r);
        if (fabs (vx - want_vx) > 1e-12 * vt || fabs (w - want_w) > 1e-12 * vt / r || fabs (vy - e * vn) > 1e-12 * vn)
          fail_msg ("vn %g vt %g mu %g gap %g: v (%.15g, %.15g) w %.15g, want (%.15g, %.15g) w %.15g", vn, vt, mu, gap,
                    vx, vy, w, want_vx, e * vn, want_w);
        carom_world_destroy (w_);
      }
}

/* A closed box of 100 polygons (boxes, pentagons and triangles of size 0.5
 * to 1, the gas of the benchmarks at a fifth of its count) thrown about at
 * up to 5 m/s and spinning at up to 20 rad/s, e = 1, no friction, no
 * gravity, continuous collision on, for 20 s. Fast-spinning bodies leave
 * impacts creeping away from the touch and swing in corners that are none
 * of their contacts' detected points: every one of those must be an impact
 * at its own time, or the sub-steps take it up and the gas loses energy.
 * The kinetic energy stays within 1e-9 of its start after every step (it
 * lost 2.3e-4 while the time of impact gave up after 128 advancements and
 * only the detected points' own approach said whether a pair could meet).
 * Three such gases (other velocities and sizes) without spin, then three
 * with: no contact is ever deeper than 1% of the smallest side without
 * spin, 5% with. A body an impact sets moving meets, within the step,
 * bodies its detection had no contact with (contacts_after_impacts); over
 * seven gases each, the deepest was 0.3% to 16.6% without spin and 5.6% to
 * 21.9% with it before, 0.18% and 5.1% then. Over 64 gases each, 5 without
 * spin and 11 with went deeper than 1% while a touch corner to corner took
 * the face that did not close, and a pair found after the impacts that had
 * met before a later one took no impact, and the search for the next
 * touch of a slow impact gave up (below:
 * test_corner_touches_take_the_face_they_closed_on,
 * test_pairs_met_before_a_later_impact_take_their_turn,
 * test_slow_impact_of_fast_spinners_is_searched_to_the_end_of_the_step);
 * now only the one built overlapping does, and these six stay within 1e-14
 * of the smallest side. The bounds hold for
 * these six gases, not yet for every gas. And a point an impact bounced is reported where it touched
 * (carom_world_get_contact), within the slop: it was reported at its
 * separation at the start of the step along the touch's normal, from where
 * the sub-steps follow it, which for a body struck again is a depth no
 * detection ever found (7.6 mm, 1.5 slops, in the first spinning gas). */
static double unit_random (uint64_t *seed)
{
  *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double) (*seed >> 11) * (1.0 / 9007199254740992.0);
}

static double elastic_gas_deepest (double spin, int run, double *energy, double *struck_depth)
{
  const double box = 14.0, smallest = 0.5;
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def d;
  carom_body_id ids[100];
  uint64_t seed = 0x676173ULL + 7919ULL * (uint64_t) run;
  double e0 = 0.0, worst_e = 0.0, deepest = 0.0, struck = -INFINITY;
  int i, step;
  carom_world_def_init (&def, sizeof def);
  def.restitution = 1.0;
  def.friction = 0.0;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5 * box - 0.5, 0.0, box + 2.0, 1.0);
  add_box (w, CAROM_STATIC, 0.0, 0.5 * box + 0.5, 0.0, box + 2.0, 1.0);
  add_box (w, CAROM_STATIC, -0.5 * box - 0.5, 0.0, 0.0, 1.0, box + 2.0);
  add_box (w, CAROM_STATIC, 0.5 * box + 0.5, 0.0, 0.0, 1.0, box + 2.0);
  for (i = 0; i < 100; ++i)
    {
      double size = smallest + 0.5 * unit_random (&seed), a = 2.0 * M_PI * unit_random (&seed);
      double speed = 5.0 * unit_random (&seed);
      carom_body_def_init (&d, sizeof d);
      d.x = -0.5 * box + 0.7 + 1.4 * (i % 10), d.y = -0.5 * box + 0.7 + 1.4 * (i / 10);
      d.angle = 2.0 * M_PI * unit_random (&seed);
      d.vx = speed * cos (a), d.vy = speed * sin (a);
      d.spin = spin * (unit_random (&seed) - 0.5);
      if (i % 3 == 0)
        assert_status (carom_world_add_box (w, &d, size, size, &ids[i]), CAROM_OK);
      else if (i % 3 == 1)
        assert_status (carom_world_add_regular (w, &d, 5, 0.6 * size, &ids[i]), CAROM_OK);
      else
        assert_status (carom_world_add_regular (w, &d, 3, size, &ids[i]), CAROM_OK);
    }
  for (step = -1; step < 1200; ++step)
    {
      double px, py, e;
      int32_t c;
      if (step >= 0)
        assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      cluster_totals (w, ids, 100, &px, &py, &e);
      if (step < 0)
        e0 = e;
      worst_e = fmax (worst_e, fabs (e / e0 - 1.0));
      for (c = 0; c < carom_world_contact_count (w); ++c)
        {
          double depth;
          assert_status (carom_world_get_contact (w, c, NULL, NULL, NULL, NULL, NULL, NULL, &depth), CAROM_OK);
          deepest = fmax (deepest, depth);
        }
      /* a point an impact within the step bounced is reported no deeper
       * than where it touched */
      for (c = 0; c < w->contacts.count; ++c)
        {
          const contact *k = &w->contacts.list[c];
          int32_t j;
          for (j = 0; j < k->count; ++j)
            {
              int32_t bounced = k->points[j].in_impact == IMPACT_BOUNCED || k->points[j].in_impact == IMPACT_DONE;
              double depth;
              if (!(k->impact_at > 0.0 && bounced))
                continue;
              assert_status (carom_world_get_contact (w, k->first_point + j, NULL, NULL, NULL, NULL, NULL, NULL,
                                                      &depth),
                             CAROM_OK);
              struck = fmax (struck, depth / k->slop);
            }
        }
    }
  carom_world_destroy (w);
  *energy = worst_e;
  *struck_depth = struck;
  return deepest / smallest;
}

/* A unit box, or with `round` a circle of unit diameter, at (x, 0). */
static carom_body_id add_unit_body (carom_world *w, double x, int round)
{
  carom_body_def d;
  carom_body_id id;
  if (!round)
    return add_box (w, CAROM_DYNAMIC, x, 0.0, 0.0, 1.0, 1.0);
  carom_body_def_init (&d, sizeof d);
  d.x = x;
  assert_status (carom_world_add_circle (w, &d, 0.5, &id), CAROM_OK);
  return id;
}

/* Two unit boxes (with `round`, circles of unit diameter) side by side, 5
 * cm apart, e = 1, no gravity, continuous collision on, B given velocity
 * (bvx, bvy), A (0, 5) m/s; with `third`, a third body resting against A's
 * far side (a contact within the slop), with `damping`, the world's damping
 * on. The contact points of A and B listed after one step. */
static int32_t side_by_side_contacts (double bvx, double bvy, int third, int damping, int round)
{
  carom_world *w = world_with (0.0, 0.0, 1.0, 0.0);
  carom_body_id a = add_unit_body (w, 0.0, round);
  carom_body_id b = add_unit_body (w, 1.05, round);
  int32_t n = 0, i;
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  assert_status (carom_body_set_velocity (w, a, 0.0, 5.0), CAROM_OK);
  assert_status (carom_body_set_velocity (w, b, bvx, bvy), CAROM_OK);
  if (third)
    {
      carom_body_id c = add_unit_body (w, -1.0, round);
      assert_status (carom_body_set_velocity (w, c, 0.0, 5.0), CAROM_OK);
    }
  if (damping)
    assert_status (carom_world_set_damping (w, 0.1, 0.1), CAROM_OK);
  assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
  for (i = 0; i < carom_world_contact_count (w); ++i)
    {
      carom_body_id p, q;
      assert_status (carom_world_get_contact (w, i, &p, &q, NULL, NULL, NULL, NULL, NULL), CAROM_OK);
      n += (p == a && q == b) || (p == b && q == a);
    }
  carom_world_destroy (w);
  return n;
}

/* With continuous collision a bouncy pair looks ahead as far as free
 * flight can close it, in any direction (contact.c, detect_pair); where
 * the bodies fly free (no gravity, force or damping), a pair whose free
 * flight cannot close its gap within the step, judged on its reference
 * face as it turns (clear_of_step), has no contact, unless a body of it
 * touches another or has a joint, and so can be pushed by more than an
 * impact. B leaving A at 3 m/s, or sliding by at 5 m/s (either within
 * the look-ahead of the relative speed): no contact; B closing at 5 m/s
 * on the 5 cm gap: one; sliding by but A pressed by a third body, or
 * damped: the contact stays. Boxes, whose bounding circles overlap, take
 * the verdict on the face; circles, whose bounding circles are the
 * bodies, take it before any narrow phase (circles_clear_of_step) and are
 * looked at again when pushed. */
static void test_free_flight_lists_no_contact_that_cannot_touch (void **state)
{
  int round;
  (void) state;
  for (round = 0; round < 2; ++round)
    {
      assert_int_equal (side_by_side_contacts (3.0, 5.0, 0, 0, round), 0);  /* leaving at 3 m/s */
      assert_int_equal (side_by_side_contacts (0.0, 10.0, 0, 0, round), 0); /* sliding by at 5 m/s */
      assert_true (side_by_side_contacts (-5.0, 5.0, 0, 0, round) >= 1);
      assert_true (side_by_side_contacts (0.0, 10.0, 1, 0, round) >= 1);
      assert_true (side_by_side_contacts (0.0, 10.0, 0, 1, round) >= 1);
    }
}

static void test_elastic_gas_with_continuous_collision_keeps_its_energy (void **state)
{
  static const double spins[] = { 0.0, 40.0 }, bounds[] = { 0.01, 0.05 };
  int i, run;
  (void) state;
  for (i = 0; i < 2; ++i)
    for (run = 0; run < 3; ++run)
      {
        double worst_e, struck, deepest = elastic_gas_deepest (spins[i], run, &worst_e, &struck);
        print_message ("elastic gas %d, continuous, spins to %g rad/s: energy within %.3g, deepest contact %.3g of the "
                       "smallest side, struck points reported at most %.3g slops deep\n",
                       run, 0.5 * spins[i], worst_e, deepest, struck);
        if (!(worst_e < 1e-9) || !(deepest < bounds[i]) || !(struck <= 1.0))
          fail_msg ("gas %d, spins to %g rad/s: energy off by %.3g, deepest contact %.3g of the smallest side, a "
                    "struck point reported %.3g slops deep",
                    run, 0.5 * spins[i], worst_e, deepest, struck);
      }
}

/* An empty world for elastic pairs: e = 1, no friction, no gravity,
 * continuous collision on. */
static carom_world *elastic_world (void)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_world_def_init (&def, sizeof def);
  def.restitution = 1.0;
  def.friction = 0.0;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  return w;
}

/* A body of an elastic pair: a regular polygon of `sides` corners (0: a
 * square of side `size`; else `size` as carom_world_add_regular takes it),
 * its pose, velocity and spin. */
typedef struct flying_body {
  int sides;
  double size, x, y, angle, vx, vy, spin;
} flying_body;

/* Add body f to w, turned by th about the origin (its velocity with it). */
static void add_turned (carom_world *w, const flying_body *f, double th)
{
  double c = cos (th), s = sin (th);
  carom_body_def d;
  carom_body_def_init (&d, sizeof d);
  d.x = c * f->x - s * f->y, d.y = s * f->x + c * f->y, d.angle = f->angle + th;
  d.vx = c * f->vx - s * f->vy, d.vy = s * f->vx + c * f->vy, d.spin = f->spin;
  if (f->sides == 0)
    assert_status (carom_world_add_box (w, &d, f->size, f->size, NULL), CAROM_OK);
  else
    assert_status (carom_world_add_regular (w, &d, f->sides, f->size, NULL), CAROM_OK);
}

/* A world (e = 1, no friction, no gravity, continuous collision on) of the
 * two bodies, the whole pair turned by th about the origin. */
static carom_world *turned_pair (const flying_body *body, double th)
{
  carom_world *w = elastic_world ();
  add_turned (w, &body[0], th);
  add_turned (w, &body[1], th);
  return w;
}

/* The deepest of the world's contact points (negative when all are apart). */
static double deepest_contact (const carom_world *w)
{
  double deepest = -INFINITY;
  int32_t k;
  for (k = 0; k < carom_world_contact_count (w); ++k)
    {
      double depth;
      assert_status (carom_world_get_contact (w, k, NULL, NULL, NULL, NULL, NULL, NULL, &depth), CAROM_OK);
      deepest = fmax (deepest, depth);
    }
  return deepest;
}

/* The pair turned to 64 orientations, each stepped `steps` times at 1/60 s:
 * fails when a contact is found deeper than 1e-9 m after any step. Returns
 * how many orientations met (made an impact) in their first step; *most
 * (when not NULL) takes the most impacts of any step. */
static int turned_pair_never_overlaps (const flying_body *pair, int steps, int *most)
{
  int turn, met = 0;
  for (turn = 0; turn < 64; ++turn)
    {
      carom_world *w = turned_pair (pair, 2.0 * M_PI * turn / 64.0);
      int step;
      for (step = 0; step < steps; ++step)
        {
          double depth;
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          met += step == 0 && w->contacts.impacts > 0;
          if (most && w->contacts.impacts > *most)
            *most = w->contacts.impacts;
          if (!((depth = deepest_contact (w)) <= 1e-9))
            fail_msg ("turn %d, step %d: a contact found %.3g m deep", turn, step, depth);
        }
      carom_world_destroy (w);
    }
  return met;
}

/* A pentagon and a triangle of such a gas, flying without spin. The
 * detection's one point, clipped to the reference face, lies 0.088 m from
 * it, while the pieces are 0.078 m apart along its normal and close 0.081
 * m along it in the step. Judged by the point they could not meet within
 * the step: the sub-steps took up the touch, and the next detection found
 * them 3.7 mm deep (0.6% of the triangle's size) in every one of 64
 * orientations. Judged by the pieces' gap (contact.gap, the separation of
 * the reference face), the same pair, turned to 64 orientations, meets at
 * its time of impact and is reported where it touched. */
static void test_pair_meets_by_its_gap_not_its_clipped_point (void **state)
{
  static const flying_body pair[2] = {
    { 5, 0.6 * 0.6192458872989095, -0.3113558654585082, 0.1150121692597329, 2.6082170276771404, 2.474092581784209,
      -0.72846712063086472, 0.0 },
    { 3, 0.53005775762443941, 0.3152642858004739, -0.0760707815884987, 0.38381806816973085, -4.1548775502816655,
      -2.3663209850442746, 0.0 } };
  (void) state;
  assert_int_equal (turned_pair_never_overlaps (pair, 2, NULL), 64);
}

/* Two hexagons flying without spin (one of 20000 random pairs thrown at
 * each other) meet corner to corner. The touch the time of impact finds
 * is a hair apart (1.7e-16 m), and the corner contact's normal, the
 * direction between its two points, was the rounding of their
 * coordinates: (0, -1) here, across the approach, so the impact reversed
 * only part of it, B slid off A's corner into the face beside it, and the
 * next detection found the hexagons 4.5 cm deep. A corner contact that
 * near takes the separating axis (collide_sat.c, CORNER_NOISE), and the
 * pair bounces off it. The same pair, turned to 64 orientations (whether
 * the corners meet or pass turns on rounding, and on the turn): no contact
 * deeper than 1e-9 m after the step. */
static void test_corners_meeting_bounce_off_the_separating_axis (void **state)
{
  static const flying_body pair[2] = {
    { 6, 0.77429463515976704, 0.0, 0.0, 4.9537008979097896, 0.0, 0.0, 0.0 },
    { 6, 0.61094233855868629, 1.4123669434035984, -0.3263555765561173, 3.0150051347241407, -8.0602899100151362,
      4.3055175069028904, 0.0 } };
  int met;
  (void) state;
  met = turned_pair_never_overlaps (pair, 2, NULL);
  print_message ("%d of 64 turns met in the first step\n", met);
  assert_true (met >= 32);
}

/* Pairs of regular 3- to 6-gons (sizes 0.5 to 1, at random angles, no
 * spin) thrown at each other at 1 to 10 m/s, e = 1, no friction, no
 * gravity, continuous collision on, 20000 pairs for 6 steps each: the
 * first impact sets them spinning, and some meet again, corner first,
 * within a step or two. No contact is ever found deeper than 1e-9 m (each
 * impact met at its time, each touch reported where it touched). Whether a
 * pair may meet within the step is judged from the pieces' gap
 * (contact.gap): a point clipped to the reference face lies farther apart
 * than the pieces may, and judged by it 9 of these pairs were left to the
 * sub-steps and found up to 2.1 cm deep. */
static void test_polygon_pairs_thrown_at_each_other_never_overlap (void **state)
{
  uint64_t seed = 0x7061697273ULL;
  int r, deep = 0;
  double deepest = 0.0;
  (void) state;
  for (r = 0; r < 20000; ++r)
    {
      carom_world *w = elastic_world ();
      carom_body_def d;
      double size[2], dir = 2.0 * M_PI * unit_random (&seed), speed = 1.0 + 9.0 * unit_random (&seed);
      double miss = unit_random (&seed) - 0.5;
      int i, step;
      for (i = 0; i < 2; ++i)
        {
          int sides = 3 + (int) (4.0 * unit_random (&seed));
          size[i] = 0.5 + 0.5 * unit_random (&seed);
          carom_body_def_init (&d, sizeof d);
          d.angle = 2.0 * M_PI * unit_random (&seed);
          if (i == 1)
            {
              /* about one body apart along dir (sideways by miss), flying
               * back at the first */
              double gap = size[0] + size[1] + speed / 60.0 * unit_random (&seed);
              d.x = gap * cos (dir) - miss * size[0] * sin (dir), d.y = gap * sin (dir) + miss * size[0] * cos (dir);
              d.vx = -speed * cos (dir), d.vy = -speed * sin (dir);
            }
          assert_status (carom_world_add_regular (w, &d, sides, size[i], NULL), CAROM_OK);
        }
      for (step = 0; step < 6; ++step)
        {
          double worst;
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          worst = deepest_contact (w);
          deepest = fmax (deepest, worst);
          if (worst > 1e-9)
            {
              if (deep++ < 5)
                print_message ("pair %d, step %d: a contact %.3g m deep\n", r, step, worst);
              break;
            }
        }
      carom_world_destroy (w);
    }
  print_message ("%d of 20000 pairs overlapped, deepest %.3g m\n", deep, deepest);
  assert_int_equal (deep, 0);
}

/* A pentagon spinning at 17 rad/s and a box of an elastic gas, grinding
 * along each other: a face turns into a corner again and again, each bounce 0.2 m/s, up to 13 impacts in a step, 1.4 ms apart.
 * With at most 8 searches for a next touch per contact and step
 * (REIMPACT_MAX), the rest of the step fell to the sub-steps and the pair
 * ended 1.7 cm deep within three steps. The same pair, turned to 64
 * orientations, for four steps: no contact deeper than 1e-9 m. */
static void test_spinning_face_grinding_on_a_corner_never_sinks_in (void **state)
{
  static const flying_body pair[2] = {
    { 5, 0.6 * 0.67445460694974813, -0.2573143208988258, -0.471235557972582, 2.3520877031353917, 1.7045593535608203,
      5.5657836915742598, 17.292019448172276 },
    { 0, 0.90100932597382222, -0.0391710984337816, 0.5287995262881426, 2.2018696472039569, -0.5857553666113916,
      0.78344017164688928, 1.7925141224262668 } };
  int most = 0;
  (void) state;
  turned_pair_never_overlaps (pair, 4, &most);
  print_message ("at most %d impacts in a step\n", most);
  assert_true (most > 8);
}

/* Three pairs of spinning pentagons and hexagons (of 100000 random pairs
 * thrown at each other at 1 to 10 m/s, spinning at up to 30 rad/s) meet
 * corner to corner. At the touch the time of impact finds, both pieces'
 * faces there are at separation 0, and the hysteresis that keeps a pair's
 * reference face from flickering between steps took A's, across which the
 * corners do not approach (they close at 13 m/s along B's): the impact
 * gave no impulse, and the next detection found the pair up to 5.6 cm deep.
 * At a touch the reference face is the one that separated the pieces just
 * before it (toi.c, collide_polygons_sat_toward). Each pair turned to 64
 * orientations, six steps: no contact deeper than 1e-9 m. */
static void test_corner_touches_take_the_face_they_closed_on (void **state)
{
  static const flying_body pairs[3][2] = {
    { { 5, 0.86922484234202346, 0.0, 0.0, 3.5485252713992885, 0.0, 0.0, -23.02348854401837 },
      { 5, 0.59961147650344193, -1.3063181329930389, 0.7319304413251061, 1.3765876593139255, 5.0946601563448368,
        -4.2984408761465875, -27.780820099495884 } },
    { { 5, 0.90340348074254284, 0.0, 0.0, 2.0449768074789731, 0.0, 0.0, -14.950287979153815 },
      { 6, 0.69210659098647143, -0.53311209325657427, -1.5122026023577817, 4.4114150618529768, 2.4168841469934494,
        6.3950335106681448, -19.184055372365144 } },
    { { 6, 0.972218196970419, 0.0, 0.0, 2.8558079355719461, 0.0, 0.0, 21.934817077375808 },
      { 5, 0.57874998225192342, 0.38616077665589871, 1.6662331473697209, 3.3568386816983438, -1.0527491036453478,
        -9.4945340534980804, 14.610590701206839 } } };
  int i;
  (void) state;
  for (i = 0; i < 3; ++i)
    turned_pair_never_overlaps (pairs[i], 6, NULL);
}

/* Two triangles of an elastic gas (elastic_gas_deepest without spin, run
 * 43, its step 346: they spin at -13.5 and -20 rad/s from earlier impacts)
 * meet at 0.22 m/s. Searched from just after that impact, the next touch
 * creeps: each conservative advance is bounded by the bodies' whole spin,
 * while the corner that struck leaves at 0.22 m/s, so each gains about
 * 1.5% on the last, and 1024 advances (TOI_MAX_ADVANCES_SWEPT as it was)
 * reached only 4e-5 s past the impact: the search gave up, the sub-steps
 * took the pair, and its next corner sank 9.3 mm. The pair turned to 64
 * orientations, three steps: no contact deeper than 1e-9 m. */
static void test_slow_impact_of_fast_spinners_is_searched_to_the_end_of_the_step (void **state)
{
  static const flying_body pair[2] = {
    { 3, 0.68059147195345826, 3.4489506915581289, 4.3370618051633301, -19.587348225000888, 4.4711610506978481,
      0.95362695244725193, -13.498007056710463 },
    { 3, 0.75028838535703746, 4.0876406173496003, 4.7138877582902889, -0.89558472854730709, -3.972519040791652,
      -1.1123390660395978, -20.083474455490148 } };
  (void) state;
  turned_pair_never_overlaps (pair, 3, NULL);
}

/* Eight bodies of an elastic gas near its floor, and its walls: the gas of
 * elastic_gas_deepest (above) without spin, run 34, before its step 509
 * (no gravity, e = 1). A triangle struck within the step is sent at a
 * box it had no contact with at the detection, and strikes something
 * else later in the step; the pair found after the impacts had met before
 * that later impact, in a flight the impact then changed, and its search
 * for a touch from the last impact found it already overlapping: it took
 * no impact, and the next detection found it 10.3 cm deep. The impacts of
 * the step now run again with that pair among them (contact_impacts,
 * IMPACT_REPLAYS), and it meets in its turn. Turned to 64 orientations (the
 * walls with it), two steps: no contact deeper than 1e-9 m. */
static void test_pairs_met_before_a_later_impact_take_their_turn (void **state)
{
  static const flying_body cluster[8] = {
    { 0, 0.52904012936365918, -0.39052228030465141, -6.5952481288221438, -2.2665387723498123, 2.4834694034627263,
      -2.0012412328464402, -3.6568357106193661 },
    { 0, 0.70548681751797704, -0.27575941728679565, -4.6048908923140184, 23.853839367489979, -0.77481751853980063,
      -0.29865089640929665, 2.1359785909577367 },
    { 3, 0.86119855765089015, -1.5070627048273373, -6.5624651243991226, 13.692918858816737, 0.013317589152966214,
      -0.62353833285803628, -0.30749492306090531 },
    { 0, 0.52797319465300852, -3.8031454145534154, -5.6228447014684235, 48.618927485402949, 0.33494381689400932,
      1.00720147101903, -3.2210661515770092 },
    { 0, 0.85494238884721008, -1.3893415264270632, -5.6765666691017582, 7.9551195448317626, -1.4567193717106774,
      -3.4867361897908116, -4.7801401825163854 },
    { 5, 0.58947465383878661, -3.0600781988883798, -5.2091376964089458, 4.8611474715010852, 5.5829964681272424,
      -2.7407239538420312, 4.3791872757127797 },
    { 3, 0.9932783733573245, -2.2212465487728541, -5.9386609680133207, 3.5393131073952224, -0.86874700113618619,
      0.49502151938181627, -0.38697272598608112 },
    { 5, 0.34879062767186225, -1.3414157611718642, -4.9356156598875254, -7.9080384020897121, 4.0006658632072787,
      -4.9912609137570119, 21.363562191676227 } };
  static const double wall_x[4] = { 0.0, 0.0, -7.5, 7.5 }, wall_y[4] = { -7.5, 7.5, 0.0, 0.0 };
  static const double wall_w[4] = { 16.0, 16.0, 1.0, 1.0 }, wall_h[4] = { 1.0, 1.0, 16.0, 16.0 };
  int turn, i, step;
  (void) state;
  for (turn = 0; turn < 64; ++turn)
    {
      double th = 2.0 * M_PI * turn / 64.0, c = cos (th), s = sin (th);
      carom_world *w = elastic_world ();
      for (i = 0; i < 4; ++i)
        add_box (w, CAROM_STATIC, c * wall_x[i] - s * wall_y[i], s * wall_x[i] + c * wall_y[i], th, wall_w[i],
                 wall_h[i]);
      for (i = 0; i < 8; ++i)
        add_turned (w, &cluster[i], th);
      for (step = 0; step < 2; ++step)
        {
          double depth;
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          if (!((depth = deepest_contact (w)) <= 1e-9))
            fail_msg ("turn %d, step %d: a contact found %.3g m deep", turn, step, depth);
        }
      carom_world_destroy (w);
    }
}

/* A world with a static floor under gravity (e, continuous collision on)
 * and one body resting its lowest corner on it: a box 2 s x s (n = 4) or a
 * regular n-gon of circumradius s, at angle a0, spinning at `spin`, its
 * lowest corner moving at (u, -d). Its corners about its centre at a0 go
 * in cx, cy (n of them). */
static carom_world *corner_world (int n, double s, double a0, double e, double spin, double u, double d, double *cx,
                                  double *cy, carom_body_id *id)
{
  carom_world *w = NULL;
  carom_world_def def;
  carom_body_def bd;
  double lowx = 0.0, lowy = INFINITY;
  int i;
  for (i = 0; i < n; ++i)
    {
      if (n == 4)
        {
          double hx = (i == 0 || i == 3) ? s : -s, hy = i < 2 ? 0.5 * s : -0.5 * s;
          cx[i] = cos (a0) * hx - sin (a0) * hy, cy[i] = sin (a0) * hx + cos (a0) * hy;
        }
      else
        cx[i] = s * cos (a0 + 2.0 * M_PI * i / n), cy[i] = s * sin (a0 + 2.0 * M_PI * i / n);
      if (cy[i] < lowy)
        lowx = cx[i], lowy = cy[i];
    }
  carom_world_def_init (&def, sizeof def);
  def.restitution = e;
  def.gravity_y = -G;
  assert_status (carom_world_init (&w, &def), CAROM_OK);
  assert_status (carom_world_set_continuous (w, 1), CAROM_OK);
  add_box (w, CAROM_STATIC, 0.0, -0.5, 0.0, 100.0, 1.0);
  carom_body_def_init (&bd, sizeof bd);
  bd.y = -lowy, bd.angle = a0, bd.spin = spin;
  bd.vx = u + spin * lowy, bd.vy = -d - spin * lowx;
  if (n == 4)
    assert_status (carom_world_add_box (w, &bd, 2.0 * s, s, id), CAROM_OK);
  else
    assert_status (carom_world_add_regular (w, &bd, n, 2.0 * s * sin (M_PI / n), id), CAROM_OK);
  return w;
}

/* How far the body's deepest corner is below the floor (0 if none). */
static double deepest_corner (const carom_world *w, carom_body_id id, int n, const double *cx, const double *cy,
                              double a0)
{
  double x, y, a, deepest = 0.0;
  int i;
  carom_body_get_position (w, id, &x, &y);
  carom_body_get_angle (w, id, &a);
  for (i = 0; i < n; ++i)
    deepest = fmax (deepest, -(y + sin (a - a0) * cx[i] + cos (a - a0) * cy[i]));
  return deepest;
}

/* A body rocking on a corner: a box (2 s x s), a triangle or a pentagon
 * (circumradius s, 0.3 to 1 m), e from 0.2 to 1, its lowest corner just
 * touching a static floor under gravity and moving at (u, -d) (|u| < 1,
 * d < 0.3 m/s), spinning at up to 10 rad/s either way, so that another
 * corner may come down within the step. A contact with a point touching
 * and closing meets at the start of the step, however slowly it closes
 * (impact_seed): met at the other corner's later time of impact, the
 * touching corner flew on into the floor until then (11.8 slops deep in
 * one of these draws, and more than one slop in 10 of 4000). After the
 * first step no corner is deeper than the slop, 1% of 2 area / perimeter
 * (2 s / 3 for the box, s cos(pi / n) for the polygons): measured, at
 * most 0.33 of it in 4000 draws. */
static void test_body_rocking_on_a_corner_never_sinks_it (void **state)
{
  uint64_t seed = 0x726f636bULL;
  double worst = 0.0;
  int run;
  (void) state;
  for (run = 0; run < 2000; ++run)
    {
      int shape = (int) (3.0 * unit_random (&seed)), n = shape == 0 ? 4 : shape == 1 ? 5 : 3;
      double s = 0.3 + 0.7 * unit_random (&seed), e = 0.2 + 0.8 * unit_random (&seed);
      double a0 = 2.0 * M_PI * unit_random (&seed), spin = 20.0 * (unit_random (&seed) - 0.5);
      double d = 0.3 * unit_random (&seed), u = 2.0 * (unit_random (&seed) - 0.5);
      double cx[5], cy[5], slop = 0.01 * (n == 4 ? 2.0 * s / 3.0 : s * cos (M_PI / n)), deepest;
      carom_body_id id;
      carom_world *w = corner_world (n, s, a0, e, spin, u, d, cx, cy, &id);
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      deepest = deepest_corner (w, id, n, cx, cy, a0);
      if (!(deepest <= slop))
        fail_msg ("draw %d: a %d-gon of size %.3f (e %.3f, spin %.3f, corner at (%.3f, %.3f) m/s) sank a corner "
                  "%.3g m, %.3g slops",
                  run, n, s, e, spin, u, -d, deepest, deepest / slop);
      worst = fmax (worst, deepest / slop);
      carom_world_destroy (w);
    }
  print_message ("bodies rocking on a corner: deepest corner after the step %.3g of the slop\n", worst);
}

/* A box (2 s x s, s from 0.3 to 1 m, e from 0.2 to 0.8) tilted by 3 to 20
 * degrees, its lowest corner just touching a static floor and closing at
 * up to 0.3 m/s, turning at up to 3 rad/s towards lying flat, for one
 * second: it rocks from corner to corner and settles. When the other
 * corner strikes, the turn the impact gives the box brings the first
 * corner back to the floor later in the step: that touch takes in the
 * corner that bounced as well, which stays bounced (impact_point). Taken
 * for a fresh point, its speed then, leaving, was read as an approach to
 * reflect at the end of the step, which pulled the bounce back and moved
 * the box for it: the resting corner went up to 4.2 slops deep (22 draws
 * of 1000 beyond two slops, in a probe of the same class). Now no corner
 * goes deeper than twice the slop (measured: 1.16 of it in these 500
 * draws, 1.45 in the probe's 1000). */
static void test_box_landing_flat_never_sinks_a_corner (void **state)
{
  uint64_t seed = 0x666c6174ULL;
  double worst = 0.0;
  int run;
  (void) state;
  for (run = 0; run < 500; ++run)
    {
      double s = 0.3 + 0.7 * unit_random (&seed), e = 0.2 + 0.6 * unit_random (&seed);
      double tilt = (3.0 + 17.0 * unit_random (&seed)) * M_PI / 180.0, sign = unit_random (&seed) < 0.5 ? -1.0 : 1.0;
      double a0 = sign * tilt, spin = -sign * 3.0 * unit_random (&seed), d = 0.3 * unit_random (&seed);
      double cx[4], cy[4], slop = 0.01 * 2.0 * s / 3.0, deepest = 0.0;
      carom_body_id id;
      carom_world *w = corner_world (4, s, a0, e, spin, 0.0, d, cx, cy, &id);
      int step;
      for (step = 0; step < 60; ++step)
        {
          assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
          deepest = fmax (deepest, deepest_corner (w, id, 4, cx, cy, a0));
        }
      if (!(deepest <= 2.0 * slop))
        fail_msg ("draw %d: a box of size %.3f (e %.3f, tilt %.3f, spin %.3f) sank a corner %.3g m, %.3g slops", run,
                  s, e, a0, spin, deepest, deepest / slop);
      worst = fmax (worst, deepest / slop);
      carom_world_destroy (w);
    }
  print_message ("boxes landing flat: deepest corner %.3g of the slop\n", worst);
}

/* The thesis' own scene (scenes/thesis.scene: seven bodies in a box, two
 * static triangles, e = 0.8, gravity, continuous collision) for 60 s: no
 * contact is ever deeper than twice the slop of its triangle (the smallest
 * body: 1% of its size, 2 area / perimeter = 0.3156, is 3.2 mm). Bodies
 * rock on one another there, one corner resting while the turn brings the
 * next one down within the step: when that impact was taken at its own
 * time, the resting corner flew free into the other body until then (one
 * such step left it 1.1 cm deep; the deepest contact in 60 s was 1.9 cm,
 * now 4.6 mm). */
static void test_thesis_scene_stays_within_twice_the_slop (void **state)
{
  const double slop = 0.01 * 2.0 * 0.54 / (1.2 + sqrt (0.81 + 0.81) + sqrt (0.09 + 0.81));
  carom_world *w = NULL;
  double deepest = 0.0;
  int step;
  (void) state;
  assert_status (carom_scene_load_file (&w, "scenes/thesis.scene", NULL, NULL), CAROM_OK);
  for (step = 0; step < 3600; ++step)
    {
      int32_t c;
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      for (c = 0; c < carom_world_contact_count (w); ++c)
        {
          double depth;
          assert_status (carom_world_get_contact (w, c, NULL, NULL, NULL, NULL, NULL, NULL, &depth), CAROM_OK);
          deepest = fmax (deepest, depth);
        }
    }
  carom_world_destroy (w);
  print_message ("thesis scene: deepest contact %.3g m, %.3g of its triangle's slop\n", deepest, deepest / slop);
  if (!(deepest < 2.0 * slop))
    fail_msg ("deepest contact %.3g m, %.3g of the triangle's slop", deepest, deepest / slop);
}

/* At the library defaults (continuous collision on), and with the world's
 * continuous collision off, where bodies at 300 m/s, moving far more than
 * half their size in a step, are swept all the same (body_swept): a circle of radius 0.05, a 0.1 box and a 0.4 x 0.01 card
 * spinning at 50 rad/s, each with e = 0 and 0.5, thrown at a static wall
 * 0.1 thick (far thinner than their 5 m per step) from 24 starting
 * offsets within a step's travel, at three angles: none ever gets its
 * centre past the wall's face, and every state stays finite. The wall is
 * 200 long, so that a card sliding along it (e = 0, no friction, up to 89
 * m/s) does not reach its end in the 30 steps. The spinning card with e =
 * 0 leaves its first impact turning at up to 1160 rad/s about the struck
 * end with its centre still closing at 220 m/s, and its other end swings
 * through the wall within the step; the contacts do not see that, and the
 * guard (tunnel.c) stops it: without it 36 of these 432 runs passed with
 * the world's continuous collision off. */
static int thrown_through (int shape, double e, double angle, double from, int disc, int cont)
{
  carom_world *w = world_with (0.0, 0.0, e, 0.0);
  carom_body_def d;
  carom_body_id b;
  int step, through = 0;
  assert_status (carom_world_set_continuous (w, cont), CAROM_OK);
  carom_body_def_init (&d, sizeof d);
  if (disc)
    {
      d.type = CAROM_STATIC, d.x = 10.3;
      assert_status (carom_world_add_circle (w, &d, 0.3, &b), CAROM_OK);
      carom_body_def_init (&d, sizeof d);
    }
  else
    add_box (w, CAROM_STATIC, 10.05, 0.0, 0.0, 0.1, 200.0);
  d.x = from, d.y = -(10.0 - from) * tan (angle);
  d.vx = 300.0 * cos (angle), d.vy = 300.0 * sin (angle);
  d.spin = shape == 2 ? 50.0 : 0.0;
  if (shape == 0)
    assert_status (carom_world_add_circle (w, &d, 0.05, &b), CAROM_OK);
  else
    assert_status (carom_world_add_box (w, &d, shape == 1 ? 0.1 : 0.4, shape == 1 ? 0.1 : 0.01, &b), CAROM_OK);
  for (step = 0; step < 30 && !through; ++step)
    {
      double x, y;
      assert_status (carom_world_update (w, 1.0 / 60.0), CAROM_OK);
      assert_status (carom_body_get_position (w, b, &x, &y), CAROM_OK);
      assert_true (isfinite (x) && isfinite (y));
      /* past the wall's face; for the disc, into it or past it within its
       * shadow */
      through = disc ? hypot (x - 10.3, y) < 0.3 || (x > 10.3 && fabs (y) < 0.3) : x > 10.0;
    }
  carom_world_destroy (w);
  return through;
}

static void test_fast_bodies_never_pass_a_thin_wall_with_continuous_collision_on_or_off (void **state)
{
  static const double angles[] = { 0.0, 0.3, -0.5 };
  int shape, phase, a, e, cont, passed = 0, runs = 0;
  (void) state;
  for (cont = 0; cont < 2; ++cont)
    for (shape = 0; shape < 3; ++shape)
      for (e = 0; e < 2; ++e)
        for (a = 0; a < 3; ++a)
          for (phase = 0; phase < 24; ++phase, ++runs)
            passed += thrown_through (shape, 0.5 * e, angles[a], 2.0 - 5.0 * phase / 24.0, 0, cont);
  print_message ("%d of %d runs passed the wall\n", passed, runs);
  assert_int_equal (passed, 0);
}

/* The same spinning card thrown head-on at a static disc of radius 0.3
 * (e = 0 and 0.5, 24 offsets, the world's continuous collision off and
 * on): its centre never enters the disc nor gets past its centre within
 * its shadow (without the guard, 7 of the 48 runs with it off went
 * through). */
static void test_spinning_card_never_passes_a_disc (void **state)
{
  int phase, e, cont, passed = 0;
  (void) state;
  for (cont = 0; cont < 2; ++cont)
    for (e = 0; e < 2; ++e)
      for (phase = 0; phase < 24; ++phase)
        passed += thrown_through (2, 0.5 * e, 0.0, 2.0 - 5.0 * phase / 24.0, 1, cont);
  print_message ("%d of 96 runs passed the disc\n", passed);
  assert_int_equal (passed, 0);
}

int main (void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test (test_bounce_apexes_are_the_closed_form),
    cmocka_unit_test (test_rows_with_gaps_are_impacts_in_turn),
    cmocka_unit_test (test_struck_bodies_meet_what_the_detection_did_not_see),
    cmocka_unit_test (test_struck_body_meets_a_compound_within_the_room_kept),
    cmocka_unit_test (test_struck_body_without_restitution_stops_at_what_it_meets),
    cmocka_unit_test (test_body_rocking_on_a_corner_never_sinks_it),
    cmocka_unit_test (test_box_landing_flat_never_sinks_a_corner),
    cmocka_unit_test (test_spinning_polygons_strike_again_within_a_step),
    cmocka_unit_test (test_elastic_ball_keeps_its_height),
    cmocka_unit_test (test_free_clusters_keep_momentum_and_never_gain_energy),
    cmocka_unit_test (test_corner_hit_is_the_closed_form),
    cmocka_unit_test (test_off_centre_discs_are_the_closed_form),
    cmocka_unit_test (test_newtons_cradle_is_sequential),
    cmocka_unit_test (test_spinning_bar_leaves_a_wall_as_the_closed_form),
    cmocka_unit_test (test_impact_friction_is_coulombs),
    cmocka_unit_test (test_elastic_gas_with_continuous_collision_keeps_its_energy),
    cmocka_unit_test (test_free_flight_lists_no_contact_that_cannot_touch),
    cmocka_unit_test (test_pair_meets_by_its_gap_not_its_clipped_point),
    cmocka_unit_test (test_corners_meeting_bounce_off_the_separating_axis),
    cmocka_unit_test (test_polygon_pairs_thrown_at_each_other_never_overlap),
    cmocka_unit_test (test_spinning_face_grinding_on_a_corner_never_sinks_in),
    cmocka_unit_test (test_corner_touches_take_the_face_they_closed_on),
    cmocka_unit_test (test_pairs_met_before_a_later_impact_take_their_turn),
    cmocka_unit_test (test_slow_impact_of_fast_spinners_is_searched_to_the_end_of_the_step),
    cmocka_unit_test (test_thesis_scene_stays_within_twice_the_slop),
    cmocka_unit_test (test_fast_bodies_never_pass_a_thin_wall_with_continuous_collision_on_or_off),
    cmocka_unit_test (test_spinning_card_never_passes_a_disc),
  };
  return cmocka_run_group_tests_name ("impacts", tests, NULL, NULL);
}
