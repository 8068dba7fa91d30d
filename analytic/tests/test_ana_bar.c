/*
 * test_ana_bar.c - the closed-form bar (analytic/ana.c) against numbers that do not
 * come from it: the paper's quoted values (Figs. 6-8, sec. 5.1), hand-reduced closed
 * forms, the energy identity by our own trapezoid rule, and finite differences.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ana.h"

#define PI 3.14159265358979323846

/* |got - want| <= tol |want| (or <= tol when want == 0), with a readable failure. */
static void assert_rel(double got, double want, double tol, const char *what)
{
  const double err = want == 0.0 ? fabs(got) : fabs(got - want) / fabs(want);
  if (!(err <= tol))
    fail_msg("%s: got %.10g, want %.10g (rel err %.3g > %.3g)", what, got, want, err, tol);
}

static void assert_abs(double got, double want, double tol, const char *what)
{
  if (!(fabs(got - want) <= tol))
    fail_msg("%s: got %.10g, want %.10g (abs err %.3g > %.3g)", what, got, want, fabs(got - want), tol);
}

static ana_bar make_bar(const ana_params *p)
{
  ana_bar bar;
  char err[200];
  const int rc = ana_bar_init(p, &bar, err, sizeof err);
  if (rc != ANA_OK)
    fail_msg("ana_bar_init rejected a valid case: %s", err);
  return bar;
}

/* Fig. 6 (alpha 90, Mode I): r0 = snf = 1, Pmax = snf H = 32, g = 2 (paper, sec. 5.1),
 * elastic slope E H / L = 1024*32/192 = 512/3 = 170.67 and, with g = 2 and q = 1,
 * softening slope (512/3)/(1 - 2) = -170.67 (the paper rounds both to 171). */
static void test_ana_bar_fig6_numbers(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  const ana_bar bar = make_bar(&p);
  assert_rel(bar.r0, 1.0, 1e-12, "r0");
  assert_rel(bar.g, 2.0, 1e-12, "g");
  assert_rel(bar.Pmax, 32.0, 1e-12, "Pmax");
  assert_rel(bar.k_elastic, 512.0 / 3.0, 1e-12, "k_elastic");
  assert_rel(bar.k_elastic, 170.67, 1e-4, "k_elastic vs 170.67");
  assert_rel(bar.k_soft_peak, -512.0 / 3.0, 1e-12, "k_soft_peak");
  assert_rel(ana_bar_softening_slope(&bar, 0.5), -170.67, 1e-4, "softening slope mid-branch");
  /* delta_peak = r0 L / E = 0.1875; separation at upx = U0 = 0.375 (ubar0 = L/512) */
  assert_rel(bar.delta_peak, 0.1875, 1e-12, "delta_peak");
  assert_rel(bar.delta_sep, 0.375, 1e-12, "delta_sep");
  assert_int_equal(bar.snapback, 0);
  assert_true(bar.sstar_turn == -1.0);
  /* q = 1: a triangle (0,0)-(0.1875,32)-(0.375,0), area 6 = UF * area = 0.1875 * 32 */
  assert_rel(bar.W_sep, 6.0, 1e-12, "W_sep");
  assert_rel(ana_bar_work(&bar, 1.0), 6.0, 1e-8, "ana_bar_work to separation");
}

/* Fig. 7: alpha 60, Mode I (snf 1, stf 10).  Paper: g = 1.3, no snapback.
 * By hand: 1/r0^2 = (3/4)(3/4 + 1/400), g = 2.2575/sqrt(3) = 1.3034. */
static void test_ana_bar_fig7_g(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.alpha_deg = 60.0;
  const ana_bar bar = make_bar(&p);
  assert_abs(bar.g, 1.30, 0.005, "g (paper, 2 decimals)");
  assert_rel(bar.g, 2.2575 / sqrt(3.0), 1e-9, "g (hand closed form)");
  assert_int_equal(bar.snapback, 0);
}

/* Fig. 8: alpha 60, Mode II (snf 10, stf 1, s0 = snf).  By hand 1/r0^2 =
 * (3/4)(3/400 + 1/4), g = 0.7725/sqrt(3) = 0.44600; the paper prints 0.43 (docs/model.md
 * sec. 6).  Either way g < 1 with q = 1: snapback over the whole branch. */
static void test_ana_bar_fig8_g(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.alpha_deg = 60.0;
  p.snf = 10.0;
  p.stf = 1.0;
  p.s0 = 10.0;
  const ana_bar bar = make_bar(&p);
  assert_abs(bar.g, 0.446, 5e-4, "g (formula)");
  assert_rel(bar.g, 0.43, 0.05, "g within 5% of the paper's 0.43");
  assert_int_equal(bar.snapback, 1);
  assert_true(ana_bar_softening_slope(&bar, 0.5) > 0.0);
}

/* The other laminate angles of sec. 5.1, Mode I, reduced by hand:
 * 45 deg: 1/r0^2 = (1/2)(1/2 + 1/200), g = 1.01/sqrt(2);
 * 30 deg: 1/r0^2 = (1/4)(1/4 + 3/400) = 103/1600, g = 2 (103/1600)/(1/2) = 0.2575. */
static void test_ana_bar_g_45_30(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.alpha_deg = 45.0;
  ana_bar bar = make_bar(&p);
  assert_rel(bar.g, 1.01 / sqrt(2.0), 1e-9, "g at 45");
  assert_rel(bar.r0, sqrt(400.0 / 101.0), 1e-12, "r0 at 45");
  assert_int_equal(bar.snapback, 1);
  p.alpha_deg = 30.0;
  bar = make_bar(&p);
  assert_rel(bar.g, 0.2575, 1e-9, "g at 30");
  assert_rel(bar.r0, sqrt(1600.0 / 103.0), 1e-12, "r0 at 30");
  assert_rel(bar.Pmax, 32.0 * sqrt(1600.0 / 103.0), 1e-12, "Pmax at 30");
  assert_int_equal(bar.snapback, 1);
}

/* eq. 25: UD = U0, UU = -U0/(q+1), UF = q U0/(q+1), per unit area H / sin a. */
static void test_ana_bar_energy_split(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.alpha_deg = 30.0;
  p.q = 1.5;
  const ana_bar bar = make_bar(&p);
  assert_rel(bar.UD, 0.375, 1e-12, "UD");
  assert_rel(bar.UU, -0.15, 1e-12, "UU");
  assert_rel(bar.UF, 0.225, 1e-12, "UF");
  assert_rel(bar.area, 64.0, 1e-12, "area = H / sin 30");
  assert_rel(bar.W_sep, 0.225 * 64.0, 1e-12, "W_sep");
  assert_rel(bar.D_sep, 0.375 * 64.0, 1e-12, "D_sep");
}

/* Area under ana_bar_curve by our own trapezoid rule (signed, along the path). */
static double trapezoid_area(const ana_bar *bar, double delta_end, int n)
{
  double *d = malloc((size_t)n * sizeof *d), *P = malloc((size_t)n * sizeof *P);
  assert_non_null(d);
  assert_non_null(P);
  const int k = ana_bar_curve(bar, delta_end, n, d, P);
  assert_true(k >= 4 && k <= n);
  double w = 0.0;
  for (int i = 1; i < k; i++)
    w += 0.5 * (P[i] + P[i - 1]) * (d[i] - d[i - 1]);
  free(d);
  free(P);
  return w;
}

/* External work to separation = UF * area (eq. 25), for both models, any q, several
 * angles, with and without snapback: the curve's area is checked by a trapezoid rule
 * written here, and ana_bar_work (GSL quadrature) against the same number. */
static void test_ana_bar_energy_identity(void **state)
{
  (void)state;
  const double qs[] = {0.8, 1.0, 1.2};
  const double as[] = {90.0, 60.0, 45.0, 30.0};
  char what[120];
  for (int model = 1; model <= 2; model++)
    for (size_t i = 0; i < sizeof qs / sizeof qs[0]; i++)
      for (size_t j = 0; j < sizeof as / sizeof as[0]; j++) {
        ana_params p;
        ana_params_default(&p);
        p.q = qs[i];
        p.alpha_deg = as[j];
        p.model = model;
        const ana_bar bar = make_bar(&p);
        /* independent of the program: UF from eq. 25 and the area H / sin a */
        const double a = as[j] * PI / 180.0;
        double want = p.q * p.U0 / (p.q + 1.0) * p.H / sin(a);
        if (model == 2) { /* opening share kappa = r0^2 sin^4 a / snf^2 (ana.c header) */
          const double inv_r0sq = sin(a) * sin(a) * (sin(a) * sin(a) / (p.snf * p.snf) + cos(a) * cos(a) / (p.stf * p.stf));
          want *= pow(sin(a), 4) / (p.snf * p.snf) / inv_r0sq;
        }
        const double dend = 1.5 * fmax(bar.delta_peak, bar.delta_sep);
        snprintf(what, sizeof what, "model %d q %.1f alpha %.0f: trapezoid area", model, p.q, as[j]);
        assert_rel(trapezoid_area(&bar, dend, 2000), want, 1e-3, what);
        snprintf(what, sizeof what, "model %d q %.1f alpha %.0f: W_sep", model, p.q, as[j]);
        assert_rel(bar.W_sep, want, 1e-12, what);
        snprintf(what, sizeof what, "model %d q %.1f alpha %.0f: ana_bar_work", model, p.q, as[j]);
        assert_rel(ana_bar_work(&bar, dend), want, 1e-8, what);
      }
}

/* Snapback flag and sstar_turn against the sign of dP/ddelta from central finite
 * differences of ana_bar_softening_point, over the Fig. 3 grid q = 0.8, 1, 1.2 and
 * g = 0.75, 1.25, 2 (g set through L = E U0 / g at alpha 90) plus g = 1.1 < q = 1.2. */
static void test_ana_bar_snapback_classification(void **state)
{
  (void)state;
  const double qs[] = {0.8, 1.0, 1.2};
  const double gs[] = {0.75, 1.1, 1.25, 2.0};
  const int N = 4000;
  const double h = 1e-6;
  char what[160];
  for (size_t i = 0; i < sizeof qs / sizeof qs[0]; i++)
    for (size_t j = 0; j < sizeof gs / sizeof gs[0]; j++) {
      ana_params p;
      ana_params_default(&p);
      p.q = qs[i];
      p.L = p.E * p.U0 / gs[j];
      const ana_bar bar = make_bar(&p);
      assert_rel(bar.g, gs[j], 1e-12, "g set through L");
      int any_pos = 0;
      double s_first_pos = -1.0, s_last_pos = -1.0;
      for (int k = 1; k < N; k++) {
        const double s = (double)k / N;
        double d1, P1, d2, P2;
        ana_bar_softening_point(&bar, s - h, &d1, &P1);
        ana_bar_softening_point(&bar, s + h, &d2, &P2);
        const double slope_fd = (P2 - P1) / (d2 - d1);
        if (slope_fd > 0.0) {
          any_pos = 1;
          if (s_first_pos < 0.0)
            s_first_pos = s;
          s_last_pos = s;
        }
        /* the closed-form slope of eq. 36 has the finite-difference sign, away from
         * the vertical tangent */
        const double slope = ana_bar_softening_slope(&bar, s);
        if (fabs(slope_fd) < 1e6 && fabs(slope_fd) > 1e-6) {
          snprintf(what, sizeof what, "q %.1f g %.2f s* %.4f: sign of eq. 36 slope", p.q, gs[j], s);
          if ((slope > 0.0) != (slope_fd > 0.0))
            fail_msg("%s: %g vs finite difference %g", what, slope, slope_fd);
        }
      }
      snprintf(what, sizeof what, "q %.1f g %.2f: snapback flag", p.q, gs[j]);
      if (bar.snapback != any_pos)
        fail_msg("%s: flag %d, finite differences say %d", what, bar.snapback, any_pos);
      if (!any_pos) {
        assert_true(bar.sstar_turn == -1.0);
        continue;
      }
      /* the snapback part is [0, turn) for q > 1 and (turn, 1] for q < 1 */
      const double tol = 2.0 / N;
      if (p.q > 1.0) {
        assert_abs(s_first_pos, 1.0 / N, 1e-12, "q > 1: snapback reaches separation");
        assert_abs(bar.sstar_turn, s_last_pos, tol, what);
      } else if (p.q < 1.0) {
        assert_abs(s_last_pos, 1.0 - 1.0 / N, 1e-12, "q < 1: snapback starts at the peak");
        if (bar.sstar_turn < 1.0)
          assert_abs(bar.sstar_turn, s_first_pos, tol, what);
        else
          assert_abs(s_first_pos, 1.0 / N, 1e-12, "q < 1, g <= q: whole branch");
      } else {
        assert_true(s_first_pos == 1.0 / N && s_last_pos == 1.0 - 1.0 / N);
        assert_true(bar.sstar_turn == 1.0);
      }
    }
}

/* Model 2 (eq. 37) equals Model 1 at 90 deg; at 60 deg g2 = E U0 sin^3 a/(L snf^2)
 * = 2 (3 sqrt 3 / 8) = 1.2990 for the Fig. 7 data. */
static void test_ana_bar_model2(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.q = 1.2;
  const ana_bar b1 = make_bar(&p);
  p.model = 2;
  const ana_bar b2 = make_bar(&p);
  assert_rel(b2.g, b1.g, 1e-14, "g");
  assert_rel(b2.r0, b1.r0, 1e-14, "r0");
  assert_rel(b2.delta_sep, b1.delta_sep, 1e-14, "delta_sep");
  assert_rel(b2.k_soft_peak, b1.k_soft_peak, 1e-14, "k_soft_peak");
  assert_rel(b2.W_sep, b1.W_sep, 1e-14, "W_sep");
  assert_rel(b2.D_sep, b1.D_sep, 1e-14, "D_sep");
  assert_int_equal(b2.snapback, b1.snapback);
  assert_rel(ana_bar_load_at(&b2, 0.3), ana_bar_load_at(&b1, 0.3), 1e-12, "load at 0.3");

  p.alpha_deg = 60.0;
  const ana_bar b3 = make_bar(&p);
  assert_rel(b3.g, 2.0 * 3.0 * sqrt(3.0) / 8.0, 1e-12, "g2 at 60");
  assert_abs(b3.mec[1], 0.0, 0.0, "no tangential decohesion in Model 2");
}

/* ana_bar_load_at on the Fig. 6 triangle (hand geometry) and, for a snapback case,
 * on the first branch met along sigma*. */
static void test_ana_bar_load_at(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  ana_bar bar = make_bar(&p);
  assert_rel(ana_bar_load_at(&bar, 0.1), 0.1 * 512.0 / 3.0, 1e-12, "elastic");
  assert_rel(ana_bar_load_at(&bar, 0.1875), 32.0, 1e-12, "peak");
  /* softening line from (0.1875, 32) to (0.375, 0) */
  assert_rel(ana_bar_load_at(&bar, 0.28), 32.0 * (0.375 - 0.28) / 0.1875, 1e-10, "softening");
  assert_rel(ana_bar_load_at(&bar, 0.5), 0.0, 0.0, "separated");
  /* work to 0.28: triangle 3 plus a trapezoid */
  const double P28 = 32.0 * (0.375 - 0.28) / 0.1875;
  assert_rel(ana_bar_work(&bar, 0.28), 3.0 + 0.5 * (32.0 + P28) * (0.28 - 0.1875), 1e-9, "work to 0.28");
  assert_rel(ana_bar_work(&bar, 0.1), 0.5 * 512.0 / 3.0 * 0.01, 1e-12, "elastic work");

  /* q = 1.2, g = 0.75: delta rises after the peak, then snaps back near separation.
   * A delta on the rising part is first met there, so the load round-trips. */
  p.q = 1.2;
  p.L = p.E * p.U0 / 0.75;
  bar = make_bar(&p);
  assert_int_equal(bar.snapback, 1);
  assert_true(bar.sstar_turn > 0.0 && bar.sstar_turn < 1.0);
  for (double s = 0.99; s > bar.sstar_turn + 0.01; s -= 0.05) {
    double d, P;
    ana_bar_softening_point(&bar, s, &d, &P);
    assert_rel(ana_bar_load_at(&bar, d), P, 1e-9, "round trip on the rising part");
  }
  /* beyond the largest delta of the branch only the separated branch remains */
  double dmax, Pt;
  ana_bar_softening_point(&bar, bar.sstar_turn, &dmax, &Pt);
  assert_true(dmax > bar.delta_sep);
  assert_rel(ana_bar_load_at(&bar, dmax * 1.001), 0.0, 0.0, "past the turn");
}

/* Curve layout: origin, peak, softening in decreasing load, P = 0 at delta_end. */
static void test_ana_bar_curve_shape(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  p.q = 0.8; /* snapback just after the peak */
  const ana_bar bar = make_bar(&p);
  double d[200], P[200];
  const int k = ana_bar_curve(&bar, 1.0, 200, d, P);
  assert_int_equal(k, 200);
  assert_true(d[0] == 0.0 && P[0] == 0.0);
  assert_rel(d[1], bar.delta_peak, 1e-14, "peak delta");
  assert_rel(P[1], bar.Pmax, 1e-14, "peak load");
  for (int i = 2; i < k; i++)
    assert_true(P[i] <= P[i - 1]);
  assert_true(d[2] < d[1]); /* snapback: delta decreases right after the peak */
  assert_rel(d[k - 2], bar.delta_sep, 1e-12, "separation point");
  assert_rel(P[k - 2], 0.0, 0.0, "zero load at separation");
  assert_rel(d[k - 1], 1.0, 0.0, "end");
  /* too few points, bad delta_end */
  assert_int_equal(ana_bar_curve(&bar, 1.0, 3, d, P), 0);
  assert_int_equal(ana_bar_curve(&bar, NAN, 200, d, P), 0);
  /* elastic only */
  assert_int_equal(ana_bar_curve(&bar, 0.1, 200, d, P), 2);
  assert_rel(P[1], 0.1 * 512.0 / 3.0, 1e-12, "elastic end point");
}

static void expect_einval(ana_params p, const char *name)
{
  ana_bar bar;
  char err[200] = "";
  const int rc = ana_bar_init(&p, &bar, err, sizeof err);
  if (rc != ANA_EINVAL)
    fail_msg("%s: accepted a bad value (rc %d)", name, rc);
  if (!strstr(err, name) || !strstr(err, "allowed") || strchr(err, '\n'))
    fail_msg("%s: message does not name it and its range on one line: '%s'", name, err);
}

/* Every validation rule of ana_bar_init, once each (and once with NaN / inf). */
static void test_ana_bar_invalid_inputs(void **state)
{
  (void)state;
  ana_params p0, p;
  ana_params_default(&p0);
  p = p0; p.alpha_deg = 0.0; expect_einval(p, "alpha");
  p = p0; p.alpha_deg = 90.5; expect_einval(p, "alpha");
  p = p0; p.alpha_deg = NAN; expect_einval(p, "alpha");
  p = p0; p.snf = 0.0; expect_einval(p, "snf");
  p = p0; p.stf = -1.0; expect_einval(p, "stf");
  p = p0; p.U0 = 0.0; expect_einval(p, "U0");
  p = p0; p.s0 = -0.5; expect_einval(p, "s0");
  p = p0; p.q = 0.0; expect_einval(p, "q");
  p = p0; p.E = INFINITY; expect_einval(p, "E");
  p = p0; p.L = 0.0; expect_einval(p, "L");
  p = p0; p.H = NAN; expect_einval(p, "H");
  p = p0; p.nu = 0.6; expect_einval(p, "nu");
  p = p0; p.model = 3; expect_einval(p, "model");
  p = p0; p.model = 0; expect_einval(p, "model");
  /* boundary values that are allowed */
  p = p0; p.alpha_deg = 90.0; make_bar(&p);
  p = p0; p.alpha_deg = 1e-3; make_bar(&p);
  /* no message buffer is fine */
  ana_bar bar;
  p = p0; p.q = -1.0;
  assert_int_equal(ana_bar_init(&p, &bar, NULL, 0), ANA_EINVAL);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ana_bar_fig6_numbers),
      cmocka_unit_test(test_ana_bar_fig7_g),
      cmocka_unit_test(test_ana_bar_fig8_g),
      cmocka_unit_test(test_ana_bar_g_45_30),
      cmocka_unit_test(test_ana_bar_energy_split),
      cmocka_unit_test(test_ana_bar_energy_identity),
      cmocka_unit_test(test_ana_bar_snapback_classification),
      cmocka_unit_test(test_ana_bar_model2),
      cmocka_unit_test(test_ana_bar_load_at),
      cmocka_unit_test(test_ana_bar_curve_shape),
      cmocka_unit_test(test_ana_bar_invalid_inputs),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
