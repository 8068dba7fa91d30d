/*
 * test_ver_metrics.c - the measured quantities of verify/ (metrics.c, check.c) on
 * synthetic data whose answers are known by construction: exact lines, a made-up
 * load-deflection curve with a known softening slope, particle bands of known width
 * and angle, errors C h^p of known order.  Every degenerate input is hit on purpose.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cmocka.h>

#include "check.h"
#include "metrics.h"

#define PI 3.14159265358979323846

static void assert_rel(double got, double want, double tol, const char *what)
{
  const double err = want == 0.0 ? fabs(got) : fabs(got - want) / fabs(want);
  if (!(err <= tol))
    fail_msg("%s: got %.10g, want %.10g (rel err %.3g > %.3g)", what, got, want, err, tol);
}

static void test_ver_metrics_fit_line_exact(void **state)
{
  (void)state;
  double x[5], y[5], s, b;
  for (int i = 0; i < 5; i++) {
    x[i] = 0.1 * i;
    y[i] = -170.5 * x[i] + 3.25;
  }
  assert_int_equal(ver_fit_line(x, y, 5, &s, &b), 0);
  assert_rel(s, -170.5, 1e-12, "slope");
  assert_rel(b, 3.25, 1e-12, "intercept");
  /* degenerate: one point, all x equal */
  assert_int_equal(ver_fit_line(x, y, 1, &s, &b), -1);
  const double xs[3] = {2, 2, 2};
  assert_int_equal(ver_fit_line(xs, y, 3, &s, &b), -1);
}

/* A bar curve: elastic slope 170.67 to P = 32 at delta 0.1875, then linear softening
 * with slope -170.67 to zero, then zero.  The fit over 0.8-0.2 of the peak must give
 * the softening slope exactly, ignoring the elastic rows and the zero tail. */
static void test_ver_metrics_softening_slope_bar(void **state)
{
  (void)state;
  enum { N = 600 };
  double d[N], P[N];
  const double k = 512.0 / 3.0, dp = 0.1875;
  for (int i = 0; i < N; i++) {
    d[i] = 0.001 * (i + 1);
    P[i] = d[i] <= dp ? k * d[i] : fmax(0.0, 32.0 - k * (d[i] - dp));
  }
  assert_rel(ver_softening_slope(d, P, N, 0.8, 0.2), -k, 1e-9, "softening slope");
  /* a late bump above 0.2 peak after the load fell below it is not part of the fit */
  P[N - 5] = 20.0;
  assert_rel(ver_softening_slope(d, P, N, 0.8, 0.2), -k, 1e-9, "softening slope, late bump");
  /* no softening rows: NaN */
  double Pe[N];
  for (int i = 0; i < N; i++)
    Pe[i] = k * d[i];
  assert_true(isnan(ver_softening_slope(d, Pe, N, 0.8, 0.2)));
  assert_true(isnan(ver_softening_slope(d, P, 0, 0.8, 0.2)));
  /* a drop from the peak to zero between two rows (a snapback's release): the secant
   * across it, -32 / 0.001 */
  double Ps[N];
  for (int i = 0; i < N; i++)
    Ps[i] = d[i] <= dp ? k * d[i] : 0.0;
  const int ipk = (int)(dp / 0.001) - 1; /* the last row at or before dp */
  assert_rel(ver_softening_slope(d, Ps, N, 0.8, 0.2), -Ps[ipk] / (d[ipk + 1] - d[ipk]), 1e-9, "softening secant");
}

/* A grid of particles on [0,192]x[0,32], h = 4, ppc = 4 (offsets h/4, 3h/4); the band
 * is the cells with x in [96, 100) (alpha 90): width 1 cell, extent 1 cell. */
static void test_ver_metrics_band_width_vertical(void **state)
{
  (void)state;
  const double h = 4;
  const int ns = 2, ppc = 4;
  const size_t n = (size_t)(192 / h * ns) * (size_t)(32 / h * ns);
  double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *l = malloc(n * sizeof *l);
  size_t k = 0;
  for (int i = 0; i < 192 / 4 * ns; i++)
    for (int j = 0; j < 32 / 4 * ns; j++) {
      x[k] = (i + 0.5) * h / ns;
      y[k] = (j + 0.5) * h / ns;
      l[k] = (x[k] >= 96 && x[k] < 100) ? 1.0 : 0.0;
      k++;
    }
  double ext;
  size_t cnt;
  assert_rel(ver_band_width(x, y, l, n, 0.5, 90, h, ppc, 32, &ext, &cnt), 1.0, 1e-12, "width, one cell");
  assert_rel(ext, 1.0, 1e-12, "extent, one cell");
  assert_int_equal(cnt, 32); /* 8 cells of 4 particles */
  assert_rel(ver_crack_angle(x, y, l, n, 0.5), 90.0, 1e-9, "angle of a vertical band");
  /* two cells wide: both measures say 2 */
  for (size_t i = 0; i < n; i++)
    l[i] = (x[i] >= 96 && x[i] < 104) ? 0.9 : 0.1;
  assert_rel(ver_band_width(x, y, l, n, 0.5, 90, h, ppc, 32, &ext, &cnt), 2.0, 1e-12, "width, two cells");
  assert_rel(ext, 2.0, 1e-12, "extent, two cells");
  /* nothing decohered */
  for (size_t i = 0; i < n; i++)
    l[i] = 0.0;
  assert_true(ver_band_width(x, y, l, n, 0.5, 90, h, ppc, 32, &ext, &cnt) == 0.0);
  assert_int_equal(cnt, 0);
  assert_true(isnan(ver_crack_angle(x, y, l, n, 0.5)));
  free(x), free(y), free(l);
}

/* The band: 2 particles at lambda 1.2 (counted as 1) and 0.8; the rest: 10 at 0.02 and
 * 5 at 0: outside the band 0.2 of 2.0 in all, a share of 0.1. */
static void test_ver_metrics_diffuse_share(void **state)
{
  (void)state;
  double l[17] = {1.2, 0.8};
  for (int i = 2; i < 12; i++)
    l[i] = 0.02;
  assert_rel(ver_diffuse_share(l, 17, 0.5), 0.2 / 2.0, 1e-12, "diffuse share");
  for (int i = 0; i < 17; i++)
    l[i] = 0.0;
  assert_true(ver_diffuse_share(l, 17, 0.5) == 0.0);
  l[0] = 0.3; /* all decohesion below the threshold: all diffuse */
  assert_rel(ver_diffuse_share(l, 17, 0.5), 1.0, 1e-12, "all diffuse");
}

/* Particles on a fine lattice, decohered within a strip of width w about a line
 * at 60 deg through (96, 16): the band's mean width is w / h cells, its angle 60. */
static void test_ver_metrics_band_inclined(void **state)
{
  (void)state;
  const double h = 2, a = 60 * PI / 180, nx = sin(a), ny = -cos(a), w = 4.0;
  const int ns = 3, ppc = 9;
  const int ni = (int)(192 / h) * ns, nj = (int)(32 / h) * ns;
  const size_t n = (size_t)ni * (size_t)nj;
  double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *l = malloc(n * sizeof *l);
  size_t k = 0;
  for (int i = 0; i < ni; i++)
    for (int j = 0; j < nj; j++) {
      x[k] = (i + 0.5) * h / ns;
      y[k] = (j + 0.5) * h / ns;
      const double s = (x[k] - 96) * nx + (y[k] - 16) * ny;
      l[k] = fabs(s) < 0.5 * w ? 1.0 : 0.0;
      k++;
    }
  double ext;
  size_t cnt;
  const double wid = ver_band_width(x, y, l, n, 0.5, 60, h, ppc, 32, &ext, &cnt);
  assert_rel(wid, w / h, 0.02, "inclined band width in cells");
  assert_rel(ext, w / h, 0.2, "inclined band extent in cells");
  /* the strip is cut by the bar's top and bottom into a parallelogram, which tilts its
   * principal axis by a few tenths of a degree */
  assert_rel(ver_crack_angle(x, y, l, n, 0.5), 60.0, 0.01, "inclined band angle");
  /* the same band mirrored: 120 deg, and the wrapped difference to 60 is 60 */
  for (size_t i = 0; i < n; i++)
    x[i] = 192 - x[i];
  const double a2 = ver_crack_angle(x, y, l, n, 0.5);
  assert_rel(a2, 120.0, 0.01, "mirrored angle");
  assert_rel(ver_angle_diff(a2, 60), 60.0, 0.02, "wrapped difference");
  free(x), free(y), free(l);
}

static void test_ver_metrics_angle_diff_wraps(void **state)
{
  (void)state;
  assert_rel(ver_angle_diff(179, 1), -2.0, 1e-12, "179 vs 1");
  assert_rel(ver_angle_diff(1, 179), 2.0, 1e-12, "1 vs 179");
  assert_rel(ver_angle_diff(90, 90), 0.0, 1e-12, "equal");
  assert_rel(ver_angle_diff(0, 90), 90.0, 1e-12, "perpendicular: +90");
}

static void test_ver_metrics_conv_order(void **state)
{
  (void)state;
  const double h[4] = {8, 4, 2, 1};
  double e[4];
  for (int i = 0; i < 4; i++)
    e[i] = 0.03 * pow(h[i] / 8, 1.5);
  assert_rel(ver_conv_order(h, e, 4, NULL), 1.5, 1e-12, "order 1.5");
  assert_rel(ver_conv_order(h, e, 2, NULL), 1.5, 1e-12, "order from two points");
  assert_true(isnan(ver_conv_order(h, e, 1, NULL)));
  e[2] = 0.0;
  assert_true(isnan(ver_conv_order(h, e, 4, NULL)));
  const double hh[3] = {4, 4, 4}, ee[3] = {1, 2, 3};
  assert_true(isnan(ver_conv_order(hh, ee, 3, NULL)));
}

static void test_ver_metrics_spread(void **state)
{
  (void)state;
  const double v[3] = {12.0, 12.3, 11.7};
  assert_rel(ver_spread(v, 3), 0.6 / 12.0, 1e-12, "spread");
  assert_true(isnan(ver_spread(v, 0)));
  const double z[2] = {-1, 1};
  assert_true(isnan(ver_spread(z, 2)));
}

static double line_ref(const void *ctx, double d)
{
  return *(const double *)ctx * d;
}

/* Rows that are the reference shifted by a constant c give RMS |c| / scale; rows past
 * delta_end are ignored; comparison is at each interval's midpoint. */
static void test_ver_metrics_curve_l2(void **state)
{
  (void)state;
  enum { N = 100 };
  double d[N], P[N];
  const double k = 2.0;
  for (int i = 0; i < N; i++) {
    d[i] = 0.01 * (i + 1);
    P[i] = k * (d[i] - 0.005) + 0.5; /* interval average of k delta, plus 0.5 */
  }
  P[N - 1] = 1e6; /* beyond delta_end */
  assert_rel(ver_curve_l2(d, P, N, 0.995, 10.0, line_ref, &k, NULL, 0), 0.05, 1e-9, "constant offset");
  assert_true(isnan(ver_curve_l2(d, P, N, 0.0, 10.0, line_ref, &k, NULL, 0)));
}

/* A run against a reference run's rows, by hand: the triangle (0,0)-(1,1)-(2,0); the
 * run's rows at 0.5, 1, 1.5 are interval averages, compared at 0.25, 0.75, 1.25 where the
 * triangle is 0.25, 0.75, 0.75: P 0.35, 0.75, 0.55 miss by 0.1, 0, -0.2, RMS sqrt(0.05 / 3).
 * With the reference moving back after delta 1 (a snapback), only delta <= 1 counts. */
static void test_ver_metrics_curve_err_curve(void **state)
{
  (void)state;
  const double rd[2] = {1, 2}, rP[2] = {1, 0}, d[3] = {0.5, 1.0, 1.5}, P[3] = {0.35, 0.75, 0.55};
  assert_rel(ver_curve_err_curve(rd, rP, 2, d, P, 3, 5.0, 1.0), sqrt(0.05 / 3), 1e-12, "triangle");
  assert_rel(ver_curve_err_curve(rd, rP, 2, d, P, 3, 5.0, 2.0), 0.5 * sqrt(0.05 / 3), 1e-12, "scale");
  const double sd[3] = {0.5, 1.0, 0.8}, sP[3] = {0.5, 1.0, 0.5};
  assert_rel(ver_curve_err_curve(sd, sP, 3, d, P, 3, 5.0, 1.0), sqrt(0.01 / 2), 1e-12, "snapback prefix");
  assert_true(isnan(ver_curve_err_curve(rd, rP, 0, d, P, 3, 5.0, 1.0)));
}

static void test_ver_metrics_judge(void **state)
{
  (void)state;
  ver_check c;
  memset(&c, 0, sizeof c);
  c.measured = 31.4;
  c.reference = 32;
  c.rel = 1;
  c.tol = 0.03;
  c.lim_lo = -INFINITY;
  c.lim_hi = INFINITY;
  ver_check_judge(&c);
  assert_int_equal(c.verdict, VER_PASS);
  c.tol = 0.01;
  ver_check_judge(&c);
  assert_int_equal(c.verdict, VER_FAIL);
  /* known-limit inside its bounds, fail outside them */
  c.cls = VER_CLASS_KNOWN;
  c.lim_lo = -0.05;
  c.lim_hi = 0.0;
  ver_check_judge(&c);
  assert_int_equal(c.verdict, VER_KNOWN);
  c.measured = 40;
  ver_check_judge(&c);
  assert_int_equal(c.verdict, VER_FAIL);
  /* not finite: fail whatever the class */
  c.measured = NAN;
  ver_check_judge(&c);
  assert_int_equal(c.verdict, VER_FAIL);
  c.measured = 1;
  c.reference = 0;
  ver_check_judge(&c);
  assert_int_equal(c.verdict, VER_FAIL);
  assert_string_equal(ver_verdict_name(VER_KNOWN), "known-limit");
  assert_string_equal(ver_verdict_name(VER_PASS), "pass");
  assert_string_equal(ver_verdict_name(VER_FAIL), "fail");
}

/* Hand-computed: points (0, 1), (1, 3), (2, 4): mean x 1, mean y 8/3, sxx 2, sxy 3,
 * slope 3/2, intercept 8/3 - 3/2 = 7/6. */
static void test_ver_metrics_fit_line_by_hand(void **state)
{
  (void)state;
  const double x[3] = {0, 1, 2}, y[3] = {1, 3, 4};
  double s, b;
  assert_int_equal(ver_fit_line(x, y, 3, &s, &b), 0);
  assert_rel(s, 1.5, 1e-14, "slope 3/2");
  assert_rel(b, 7.0 / 6.0, 1e-14, "intercept 7/6");
}

/* Elastic slope: rows (delta, P) = (0.05, 5), (0.1, 10), (0.2, 21), (0.3, 30), (0.4, 50)
 * with peak 50 at 0.4: the band 0.1 .. 0.6 of the peak (5 .. 30) keeps the first four;
 * their line: mean x 0.1625, mean y 16.5, sxx 0.036875, sxy 3.725 -> 101.0169...
 * (3.725 / 0.036875). */
static void test_ver_metrics_elastic_slope_by_hand(void **state)
{
  (void)state;
  const double d[5] = {0.05, 0.1, 0.2, 0.3, 0.4}, P[5] = {5, 10, 21, 30, 50};
  assert_rel(ver_elastic_slope(d, P, 5, 50, 0.4, VER_ELASTIC_LO, VER_ELASTIC_HI), 3.725 / 0.036875, 1e-12,
             "elastic slope");
  /* fewer than 3 rows in the band, and no row under it (5 >= 0.1 x 50) to start a secant */
  assert_true(isnan(ver_elastic_slope(d, P, 5, 50, 0.15, VER_ELASTIC_LO, VER_ELASTIC_HI)));
  /* a line given at its corners (the closed form's curve: (0, 0), then the peak): the
   * secant from the last row under 0.1 of the peak to the first over 0.6, 32 / 0.1875 */
  const double cd[3] = {0.0, 0.1875, 0.2}, cP[3] = {0.0, 32.0, 30.0};
  assert_rel(ver_elastic_slope(cd, cP, 3, 32.0, 0.1875, VER_ELASTIC_LO, VER_ELASTIC_HI), 32.0 / 0.1875, 1e-15,
             "secant across the band");
}

/* Softening slope: peak 32 at delta 0.2, then P = 32 - 171 (delta - 0.2) sampled every
 * 0.02: the 0.8 .. 0.2 band (25.6 .. 6.4) holds only exact points of that line, so the
 * slope is -171 (the paper's Fig. 6 number). */
static void test_ver_metrics_softening_paper_line(void **state)
{
  (void)state;
  double d[40], P[40];
  int n = 0;
  for (int i = 0; i <= 10; i++, n++) {
    d[n] = 0.02 * i;
    P[n] = 160.0 * d[n];
  }
  for (int i = 1; n < 40; i++, n++) {
    d[n] = 0.2 + 0.02 * i;
    P[n] = fmax(0.0, 32.0 - 171.0 * (d[n] - 0.2));
  }
  assert_rel(ver_softening_slope(d, P, (size_t)n, VER_SOFT_HI, VER_SOFT_LO), -171.0, 1e-9, "softening -171");
  /* the drop: P < 0.9 * 32 = 28.8 first at delta 0.22 (P 28.58), P < 3.2 first at
   * delta 0.38 (P 1.22): width 0.16 */
  assert_rel(ver_drop_width(d, P, (size_t)n), 0.16, 1e-9, "drop width");
}

/* Curve error by hand: rows at delta 0.1, 0.2, 0.3 (intervals from 0), P = 1, 2, 2
 * against ref(delta) = 10 delta at the midpoints 0.05, 0.15, 0.25: differences 0.5,
 * 0.5, -0.5; RMS 0.5, largest 0.5; scale 2 -> 0.25, 0.25. */
static double ten_delta(const void *ctx, double delta)
{
  (void)ctx;
  return 10.0 * delta;
}

static void test_ver_metrics_curve_by_hand(void **state)
{
  (void)state;
  const double d[3] = {0.1, 0.2, 0.3}, P[3] = {1, 2, 2};
  double mx;
  assert_rel(ver_curve_l2(d, P, 3, 0.3, 2.0, ten_delta, NULL, &mx, 0), 0.25, 1e-12, "RMS / scale");
  assert_rel(mx, 0.25, 1e-12, "max dev / scale");
  /* only the first two rows: delta_end 0.2 */
  assert_rel(ver_curve_l2(d, P, 3, 0.2, 1.0, ten_delta, NULL, NULL, 0), 0.5, 1e-12, "two rows");
}

/* Order with its constant: e = 0.01 h^2 at h = 8, 4, 2 -> p 2, log C = log 0.01. */
static void test_ver_metrics_order_constant(void **state)
{
  (void)state;
  const double h[3] = {8, 4, 2}, e[3] = {0.64, 0.16, 0.04};
  double c;
  assert_rel(ver_conv_order(h, e, 3, &c), 2.0, 1e-12, "order 2");
  assert_rel(c, log(0.01), 1e-12, "log C");
}

/* The separation reference at threshold 1 is the analytic delta_sep (fig6: 0.375). */
static void test_ver_metrics_sep_ref(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  ana_bar b;
  assert_int_equal(ana_bar_init(&p, &b, NULL, 0), ANA_OK);
  assert_rel(ver_sep_ref(&b, 1.0), b.delta_sep, 0, "threshold 1");
  assert_true(ver_sep_ref(&b, 0.8) < b.delta_sep);
  assert_rel(ver_curve_end(&b, 1.0), b.delta_sep, 0, "no snapback: the window ends at separation");
  /* Fig. 8's bar (Mode II at 60 deg, g = 0.446 < 1): snapback, lambda = 1 before the peak */
  p.alpha_deg = 60;
  p.snf = p.s0 = 10; /* data/scenes/fig8.ini: snf = s0 = 10, stf = 1, Model 1 */
  p.stf = 1;
  p.model = 1;
  assert_int_equal(ana_bar_init(&p, &b, NULL, 0), ANA_OK);
  assert_rel(b.g, 0.446, 2e-3, "fig8 g by eq. 35");
  assert_true(b.snapback);
  assert_true(ver_sep_ref(&b, 1.0) < b.delta_peak);
  assert_rel(ver_curve_end(&b, 1.0), b.delta_peak, 0, "snapback: the window ends at the peak");
}

/* The energy residual by hand: two rows with W_ext 1, 2, KE 0.5, 0.5, SE 0.25, 1,
 * W_coh 0, 0.25 miss 0.25 each (over max W_ext = 2: 0.125); booking L_bc = 0.25 explains
 * it all; E0 = 4 is the larger scale and enters the balance. */
static void test_ver_metrics_energy_residual(void **state)
{
  (void)state;
  const double W[2] = {1, 2}, KE[2] = {0.5, 0.5}, SE[2] = {0.25, 1}, Wc[2] = {0, 0.25}, Lb[2] = {0.25, 0.25};
  const double *e[VER_ENERGY_COLS] = {W, KE, SE, Wc, NULL, NULL, NULL, NULL, NULL, NULL};
  double raw = -1;
  assert_true(fabs(ver_energy_residual(e, 2, 0.0, &raw) - 0.125) < 1e-15);
  assert_true(fabs(raw - 0.125) < 1e-15);
  e[4] = Lb;
  assert_true(fabs(ver_energy_residual(e, 2, 0.0, &raw) - 0.0) < 1e-15);
  assert_true(fabs(raw - 0.125) < 1e-15);
  /* E0 = 4: misses 4.25 and 4.25 less booked 0.25 -> 4 / 4 */
  assert_true(fabs(ver_energy_residual(e, 2, 4.0, NULL) - 1.0) < 1e-15);
}

/* GCI by hand.  f = 1 + h^2 / 100 at h 1, 2, 4: f1 1.01, f2 1.04, f3 1.16; conv = 0.03 /
 * 0.12 = 0.25, p = ln 4 / ln 2 = 2 (sensible in [0.5, 2]), Fs 1.25, GCI_12 =
 * 1.25 (0.03 / 1.01) / 3 = 0.0123762..., GCI_23 = 1.25 (0.12 / 1.04) / 3 = 0.0480769...,
 * asym = GCI_23 / (4 GCI_12) = 1.01 / 1.04.  Then values whose p (ln 9 / ln 2 = 3.17)
 * is above p_hi 2: Fs 3 and p 2; a divergent and an oscillating triple: Fs 3, p 0.5. */
static void test_ver_metrics_gci(void **state)
{
  (void)state;
  ver_gci_result g;
  assert_int_equal(ver_gci(1.01, 1.04, 1.16, 2.0, 0.5, 2.0, &g), 0);
  assert_rel(g.conv, 0.25, 1e-12, "conv");
  assert_rel(g.p, 2.0, 1e-12, "p");
  assert_int_equal(g.sensible, 1);
  assert_rel(g.fs, 1.25, 0, "Fs");
  assert_rel(g.gci12, 1.25 * 0.03 / 1.01 / 3.0, 1e-12, "GCI_12");
  assert_rel(g.gci23, 1.25 * 0.12 / 1.04 / 3.0, 1e-12, "GCI_23");
  assert_rel(g.asym, 1.01 / 1.04, 1e-12, "asymptotic ratio");
  /* f2 - f1 = 0.01, f3 - f2 = 0.09: p = log2 9 > 2 */
  assert_int_equal(ver_gci(2.0, 2.01, 2.1, 2.0, 0.5, 2.0, &g), 0);
  assert_rel(g.p, log(9.0) / log(2.0), 1e-12, "p above the range");
  assert_int_equal(g.sensible, 0);
  assert_rel(g.fs, 3.0, 0, "Fs 3 for p out of range");
  assert_rel(g.p_used, 2.0, 0, "p clamped");
  assert_rel(g.gci12, 3.0 * 0.01 / 2.0 / 3.0, 1e-12, "GCI_12 with Fs 3, p 2");
  /* divergent: differences 0.2 then 0.1 (conv 2), p NaN -> 0.5 */
  assert_int_equal(ver_gci(1.3, 1.1, 1.0, 2.0, 0.5, 2.0, &g), 0);
  assert_rel(g.conv, 2.0, 1e-12, "conv divergent");
  assert_true(isnan(g.p) || g.p < 0);
  assert_int_equal(g.sensible, 0);
  assert_rel(g.gci12, 3.0 * (0.2 / 1.3) / (sqrt(2.0) - 1.0), 1e-12, "GCI_12 divergent");
  /* oscillating: conv < 0 */
  assert_int_equal(ver_gci(1.0, 1.1, 1.05, 2.0, 0.5, 2.0, &g), 0);
  assert_true(g.conv < 0);
  assert_int_equal(g.sensible, 0);
  assert_rel(g.fs, 3.0, 0, "Fs oscillating");
  /* degenerate inputs */
  assert_int_equal(ver_gci(1.0, 1.0, 1.2, 2.0, 0.5, 2.0, &g), -1);
  assert_rel(g.gci12, 0.0, 0, "equal fine values");
  assert_true(isnan(g.gci23));
  /* equal to rounding on all three grids (fig7's D = U0 area / sin 60 deg at h 2, 4, 8
   * differs in its last bits): no order is read from the noise */
  const double d = 0.375 * 32.0 / sin(acos(-1.0) / 3.0);
  assert_int_equal(ver_gci(d * (1.0 + 2.0 * DBL_EPSILON), d, d * (1.0 - 2.0 * DBL_EPSILON), 2.0, 0.5, 2.0, &g), -1);
  assert_rel(g.gci12, 0.0, 0, "ties: GCI_12");
  assert_rel(g.gci23, 0.0, 0, "ties: GCI_23");
  assert_true(isnan(g.conv) && isnan(g.p));
  /* a real difference of 1e-9 is not a tie */
  assert_int_equal(ver_gci(d * (1.0 + 1e-9), d, d * (1.0 - 1e-9), 2.0, 0.5, 2.0, &g), 0);
  assert_true(g.gci12 > 0.0);
  assert_int_equal(ver_gci(1.0, 1.1, 1.2, 1.0, 0.5, 2.0, &g), -1);
  assert_int_equal(ver_gci(0.0, 1.1, 1.2, 2.0, 0.5, 2.0, &g), -1);
  assert_true(isnan(g.gci12));
}

/* The value at a row (summary.json's D_cut): a made-up D(delta) on rows 0.0005 apart,
 * D = 12 before the cut row at 0.439, growing by 1 a row after it; the cut row's D is
 * 12.5 by construction.  A delta between rows (the load test's window centre) takes the
 * next row; no separation (-1) or a delta past the last row gives NaN. */
static void test_ver_metrics_value_at_row(void **state)
{
  (void)state;
  enum { N = 1000 };
  double d[N], D[N];
  const int icut = 878; /* 878 x 0.0005 = 0.439 */
  for (int i = 0; i < N; i++) {
    d[i] = 0.0005 * (i + 1) - 0.0005; /* rounding as a running sum would have it */
    D[i] = i < icut ? 12.0 : i == icut ? 12.5 : 12.5 + (i - icut);
  }
  assert_true(ver_value_at(d, D, N, 0.439) == 12.5);
  assert_true(ver_value_at(d, D, N, 0.43925) == 13.5);
  assert_true(ver_value_at(d, D, N, 0.0) == 12.0);
  assert_true(isnan(ver_value_at(d, D, N, -1.0)));
  assert_true(isnan(ver_value_at(d, D, N, 0.6)));
  assert_true(isnan(ver_value_at(d, D, N, NAN)));
}

/* The load after separation: a ringing 0.4 P0 cos(w t) exp(-t / tau) past delta 1 is
 * largest, from delta 1.5 on, at the first row there: its |P| / peak is known in closed
 * form; from past the last row, the last row's; a zero peak, NaN. */
static void test_ver_metrics_load_after(void **state)
{
  (void)state;
  enum { N = 2001 };
  double d[N], P[N];
  const double P0 = 80.0, tau = 0.2;
  for (int i = 0; i < N; i++) {
    d[i] = 2.0 * i / (N - 1);
    P[i] = d[i] <= 1.0 ? P0 * d[i] : 0.4 * P0 * cos(2.0 * PI * 40.0 * (d[i] - 1.0)) * exp(-(d[i] - 1.0) / tau);
  }
  /* delta 1.5 is row 1500, a whole number of periods past 1: cos = 1 there */
  /* separation at 1.5 - VER_LOAD_SETTLE: the window opens at 1.5 */
  const double s = VER_LOAD_SETTLE;
  assert_rel(ver_load_after(d, P, N, 1.5 - s, P0, NULL, NULL), 0.4 * exp(-0.5 / tau), 1e-9, "first row past 1.5");
  assert_true(fabs(ver_load_after(d, P, N, 0.0 - s, P0, NULL, NULL) - 1.0) < 1e-12);
  assert_rel(ver_load_after(d, P, N, 2.5 - s, P0, NULL, NULL), 0.4 * exp(-1.0 / tau), 1e-9, "the last row");
  assert_true(isnan(ver_load_after(d, P, N, 1.5 - s, 0.0, NULL, NULL)));
  assert_true(isnan(ver_load_after(d, P, N, NAN, P0, NULL, NULL)));
  /* the sign: past delta 1.001 a tension of 0.01 P0 up to delta 1.5, then a push of
   * 0.03 P0 (two separated parts meeting): |P| 0.03, tension 0.01, compression 0.03; the
   * ringing above, from 1.5, whole periods of cos from row 1500: its largest tension is
   * the first row's, its largest compression half a period later, 0.4 exp(-(0.5 +
   * 1 / 80) / tau) */
  double Q[N], t, c;
  for (int i = 0; i < N; i++)
    Q[i] = d[i] <= 1.0 ? P0 * d[i] : (d[i] <= 1.5 ? 0.01 : -0.03) * P0;
  assert_rel(ver_load_after(d, Q, N, 1.001 - s, P0, &t, &c), 0.03, 1e-12, "|P| of the push");
  assert_rel(t, 0.01, 1e-12, "tension");
  assert_rel(c, 0.03, 1e-12, "compression");
  ver_load_after(d, Q, N, 1.6 - s, P0, &t, &c);
  assert_true(t == 0.0 && fabs(c - 0.03) < 1e-12);
  ver_load_after(d, P, N, 1.5 - s, P0, &t, &c);
  assert_rel(t, 0.4 * exp(-0.5 / tau), 1e-9, "ringing's tension");
  assert_true(c > 0.0 && c <= 0.4 * exp(-0.5 / tau));
  ver_load_after(d, P, N, NAN, P0, &t, &c);
  assert_true(isnan(t) && isnan(c));
}

/* ver_curve_path as its definition reads, by brute force: the analytic path at 2001
 * points of sigma* (then P = 0), every segment visited for every point, points every
 * 0.002 along the run's polyline from the origin to its first row past the peak at or
 * under 1 % of Pmax.  An independent copy of the documented rule for small inputs. */
static double path_brute(const ana_bar *b, const double *d, const double *P, size_t n)
{
  enum { M = 2004 };
  static double px[M], py[M];
  double dpk, Ppk;
  ana_bar_softening_point(b, 1.0, &dpk, &Ppk);
  px[0] = py[0] = 0.0;
  for (int k = 0; k <= 2000; k++) {
    double x, y;
    ana_bar_softening_point(b, 1.0 - k / 2000.0, &x, &y);
    px[k + 1] = x / dpk;
    py[k + 1] = y / b->Pmax;
  }
  px[2002] = px[2001] + 1e3;
  py[2002] = 0.0;
  size_t ipk = 0, end = n - 1;
  for (size_t i = 1; i < n; i++)
    if (P[i] > P[ipk])
      ipk = i;
  for (size_t i = ipk; i < n; i++)
    if (P[i] <= 0.01 * b->Pmax) {
      end = i;
      break;
    }
  double s = 0.0, m = 0.0, x0 = 0.0, y0 = 0.0;
  for (size_t i = 0; i <= end; i++) {
    const double x1 = d[i] / dpk, y1 = P[i] / b->Pmax;
    const long k = (long)ceil(hypot(x1 - x0, y1 - y0) / 0.002);
    for (long j = 1; j <= k; j++) {
      const double x = x0 + (double)j / (double)k * (x1 - x0), y = y0 + (double)j / (double)k * (y1 - y0);
      double best = INFINITY;
      for (int q = 0; q + 1 < 2003; q++) {
        const double ax = px[q], ay = py[q], bx = px[q + 1] - ax, by = py[q + 1] - ay, l2 = bx * bx + by * by;
        const double t = l2 > 0 ? fmin(1.0, fmax(0.0, ((x - ax) * bx + (y - ay) * by) / l2)) : 0.0;
        best = fmin(best, (x - ax - t * bx) * (x - ax - t * bx) + (y - ay - t * by) * (y - ay - t * by));
      }
      s += best;
      m += 1.0;
    }
    x0 = x1;
    y0 = y1;
  }
  return sqrt(s / m);
}

/* curve_path against path_brute on rows that wander about the path (fig6's bar, and
 * Fig. 8's, which snaps back): the searched distance is the brute-force one. */
static void test_ver_metrics_curve_path_brute(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  for (int bar = 0; bar < 2; bar++) {
    if (bar) {
      p.alpha_deg = 60;
      p.snf = p.s0 = 10;
      p.stf = 1;
    }
    ana_bar b;
    assert_int_equal(ana_bar_init(&p, &b, NULL, 0), ANA_OK);
    enum { N = 240 };
    double d[N], P[N];
    for (int i = 0; i < N; i++) { /* along sigma*, off the path by up to 8 % of Pmax */
      double x, y;
      const double u = (double)i / (N - 1);
      if (u < 0.3)
        x = u / 0.3 * b.delta_peak, y = x / b.delta_peak * b.Pmax;
      else
        ana_bar_softening_point(&b, 1.0 - (u - 0.3) / 0.7, &x, &y);
      d[i] = x * (1.0 + 0.05 * sin(7.0 * i));
      P[i] = y + 0.08 * b.Pmax * sin(3.0 * i) + (i == N / 2 ? 3.0 * b.Pmax : 0.0);
    }
    const double want = path_brute(&b, d, P, N), got = ver_curve_path(&b, d, P, N, NULL);
    assert_true(want > 0.01);
    assert_rel(got, want, 1e-12, bar ? "fig8's bar" : "fig6's bar");
  }
}

/* 2,000,000 rows on fig6's path with one row at P = 1e12 (the sampling's int overflowed
 * at about 1e9 and left the row out, 8.7e7 took minutes): in under 2 s, the distance of
 * a spike of height Y = 1e12 / Pmax in normalised units, whose points dominate: the RMS
 * of y over [0, Y] up and down, Y / sqrt 3 (the rest of the path counts 1 in 1e10). */
static void test_ver_metrics_curve_path_outlier(void **state)
{
  (void)state;
  ana_params p;
  ana_params_default(&p);
  ana_bar b;
  assert_int_equal(ana_bar_init(&p, &b, NULL, 0), ANA_OK);
  const size_t n = 2000000;
  double *d = malloc(n * sizeof *d), *P = malloc(n * sizeof *P);
  assert_non_null(d);
  assert_non_null(P);
  for (size_t i = 0; i < n; i++) {
    d[i] = (double)(i + 1) * 2.5e-7;
    P[i] = ana_bar_load_at(&b, d[i]);
  }
  P[n / 2] = 1e12;
  const clock_t t0 = clock();
  const double e = ver_curve_path(&b, d, P, n, NULL);
  const double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
  assert_rel(e, 1e12 / b.Pmax / sqrt(3.0), 2e-3, "a spike of 1e12");
  if (!(secs < 2.0))
    fail_msg("2 M rows took %.2f s", secs);
  P[n / 2] = 1e300; /* beyond the doubles once squared: as far as can be, never NaN */
  assert_true(ver_curve_path(&b, d, P, n, NULL) == DBL_MAX);
  P[n / 2] = ana_bar_load_at(&b, d[n / 2]);
  assert_true(ver_curve_path(&b, d, P, n, NULL) < 1e-6);
  free(d);
  free(P);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_ver_metrics_fit_line_exact),
    cmocka_unit_test(test_ver_metrics_softening_slope_bar),
    cmocka_unit_test(test_ver_metrics_band_width_vertical),
    cmocka_unit_test(test_ver_metrics_band_inclined),
    cmocka_unit_test(test_ver_metrics_diffuse_share),
    cmocka_unit_test(test_ver_metrics_angle_diff_wraps),
    cmocka_unit_test(test_ver_metrics_conv_order),
    cmocka_unit_test(test_ver_metrics_spread),
    cmocka_unit_test(test_ver_metrics_curve_l2),
    cmocka_unit_test(test_ver_metrics_curve_err_curve),
    cmocka_unit_test(test_ver_metrics_judge),
    cmocka_unit_test(test_ver_metrics_fit_line_by_hand),
    cmocka_unit_test(test_ver_metrics_elastic_slope_by_hand),
    cmocka_unit_test(test_ver_metrics_softening_paper_line),
    cmocka_unit_test(test_ver_metrics_curve_by_hand),
    cmocka_unit_test(test_ver_metrics_order_constant),
    cmocka_unit_test(test_ver_metrics_sep_ref),
    cmocka_unit_test(test_ver_metrics_energy_residual),
    cmocka_unit_test(test_ver_metrics_gci),
    cmocka_unit_test(test_ver_metrics_value_at_row),
    cmocka_unit_test(test_ver_metrics_load_after),
    cmocka_unit_test(test_ver_metrics_curve_path_brute),
    cmocka_unit_test(test_ver_metrics_curve_path_outlier),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
