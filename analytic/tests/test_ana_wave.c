/*
 * test_ana_wave.c - the bar at a finite grip speed (analytic/ana_wave.c) against values
 * that do not come from its time stepping: the homogeneous state before the onset, the
 * closed form of the first transit (before any reflection is back at the grip), and the
 * quasi-static closed form of ana.c as the speed goes to zero.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "ana.h"

static ana_bar fig6(void)
{
  ana_params p;
  ana_params_default(&p);
  ana_bar bar;
  char err[200];
  if (ana_bar_init(&p, &bar, err, sizeof err) != ANA_OK)
    fail_msg("ana_bar_init: %s", err);
  return bar;
}

static ana_wave solve(const ana_bar *bar, double speed, double xg, double delta_end)
{
  const ana_wave_params wp = {speed, 1.0, xg, 0.98};
  ana_wave w;
  char err[200];
  if (ana_wave_init(bar, &wp, delta_end, &w, err, sizeof err) != ANA_OK)
    fail_msg("ana_wave_init: %s", err);
  return w;
}

/* Before the onset the bar is homogeneous: P = E H delta / L, and the grip learns of
 * the onset one transit Tg later, so the line holds to delta = (t_onset + Tg) V. */
static void test_ana_wave_before_onset(void **state)
{
  (void)state;
  const ana_bar bar = fig6();
  const double V = 0.001;
  ana_wave w = solve(&bar, V, 96.0, 0.3);
  assert_true(fabs(w.t_onset - 187.5) < 1e-9); /* snf L / (E V) */
  assert_true(fabs(w.Tg - 3.0) < 1e-12);       /* 96 / sqrt(1024) */
  const double dlast = (w.t_onset + w.Tg) * V;
  for (double d = 0.001; d < dlast - 1e-9; d += 0.0017) {
    const double P = ana_wave_load_at(&w, d);
    if (fabs(P - bar.k_elastic * d) > 1e-9 * bar.Pmax)
      fail_msg("delta %.4f: P %.12g, want E H delta / L = %.12g", d, P, bar.k_elastic * d);
  }
  /* the load there: Pmax + k_elastic V Tg, 1.6 % over the quasi-static peak */
  const double Pg = ana_wave_load_at(&w, dlast);
  if (fabs(Pg - (bar.Pmax + bar.k_elastic * V * w.Tg)) > 1e-6 * bar.Pmax)
    fail_msg("load when the wave arrives: %.9g, want %.9g", Pg, bar.Pmax + bar.k_elastic * V * w.Tg);
  ana_wave_free(&w);
}

/* Until a reflection from either end is back at the plane (2 min(Tg, Tf) after the
 * onset), nothing comes in: with s = t - t_onset, kh = E V / L and Z = rho c the
 * opening obeys dw/ds = alpha w + 2 kh s / Z, alpha = 2 snf^2 / (U0 Z), so
 *     w(s) = (2 kh / Z) (exp(alpha s) - 1 - alpha s) / alpha^2,
 * T = snf (1 - snf w / U0), and the grip, one transit Tg later, reads
 *     P(t) = H (sigma_h(t) - 2 (sigma_h(t - Tg) - T(t - Tg))).
 * The plane is off centre (xg 80) so that the two ends' echoes differ. */
static void test_ana_wave_first_transit(void **state)
{
  (void)state;
  const ana_bar bar = fig6();
  const double V = 0.004, xg = 80.0, c = 32.0, Z = 32.0, snf = 1.0, U0 = 0.375, H = 32.0;
  const double kh = 1024.0 * V / 192.0, alpha = 2.0 * snf * snf / (U0 * Z);
  ana_wave w = solve(&bar, V, xg, 0.3);
  const double Tg = xg / c, Tf = (192.0 - xg) / c, t0 = w.t_onset;
  double worst = 0.0;
  for (double s = 0.05; s < 2.0 * fmin(Tg, Tf); s += 0.05) {
    const double ss = s;
    const double wo = (2.0 * kh / Z) * (exp(alpha * ss) - 1.0 - alpha * ss) / (alpha * alpha);
    const double T = snf * (1.0 - snf * wo / U0), sh = kh * (t0 + ss), t = t0 + ss + Tg;
    const double want = H * (kh * t - 2.0 * (sh - T));
    worst = fmax(worst, fabs(ana_wave_load_at(&w, t * V) - want) / bar.Pmax);
  }
  if (!(worst < 1e-6))
    fail_msg("first transit: largest |P - closed form| / Pmax = %.3g (want < 1e-6)", worst);
  ana_wave_free(&w);
}

/* As the speed goes to zero the solution tends to the quasi-static closed form: the RMS
 * of P_wave - P_static over Pmax, to where lambda reaches 0.98, is the rate's error.  It
 * is the unloading wave's lag (Tg V, the overshoot) and the ringing it starts, both of
 * the order of V, so it must fall by about 4 for each quartering of V: asserted > 2.5
 * per quartering and below 0.5 % at V = 0.00025. */
static void test_ana_wave_static_limit(void **state)
{
  (void)state;
  const ana_bar bar = fig6();
  double d98, P98;
  ana_bar_softening_point(&bar, 0.02, &d98, &P98);
  const double Vs[3] = {0.004, 0.001, 0.00025};
  double e[3];
  for (int k = 0; k < 3; k++) {
    ana_wave w = solve(&bar, Vs[k], 96.0, d98 + 0.01);
    double s = 0.0;
    int m = 0;
    for (double d = 0.0005; d <= d98; d += 0.0005, m++) {
      const double x = ana_wave_load_at(&w, d) - ana_bar_load_at(&bar, d);
      s += x * x;
    }
    e[k] = sqrt(s / m) / bar.Pmax;
    ana_wave_free(&w);
  }
  print_message("# rate error (RMS / Pmax) at V 0.004, 0.001, 0.00025: %.5f %.5f %.5f\n", e[0], e[1], e[2]);
  assert_true(e[0] / e[1] > 2.5);
  assert_true(e[1] / e[2] > 2.5);
  assert_true(e[2] < 0.005);
}

/* What it does not solve, it refuses. */
static void test_ana_wave_refuses(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.alpha_deg = 60.0;
  ana_bar bar;
  char err[200];
  assert_int_equal(ana_bar_init(&p, &bar, err, sizeof err), ANA_OK);
  ana_wave w;
  const ana_wave_params wp = {0.001, 1.0, 96.0, 0.98};
  assert_int_equal(ana_wave_init(&bar, &wp, 0.5, &w, err, sizeof err), ANA_EINVAL);
  const ana_bar b6 = fig6();
  const ana_wave_params bad[] = {{0.0, 1.0, 96.0, 0.98}, {0.001, 1.0, 192.0, 0.98}, {0.001, 1.0, 96.0, 0.0},
                                 {0.001, -1.0, 96.0, 0.98}};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++)
    assert_int_equal(ana_wave_init(&b6, &bad[i], 0.5, &w, err, sizeof err), ANA_EINVAL);
  assert_int_equal(ana_wave_init(&b6, &wp, -1.0, &w, NULL, 0), ANA_EINVAL);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ana_wave_before_onset),
      cmocka_unit_test(test_ana_wave_first_transit),
      cmocka_unit_test(test_ana_wave_static_limit),
      cmocka_unit_test(test_ana_wave_refuses),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
