/*
 * test_mpm_gimp.c - the uGIMP weights of mpm_shape.h against their definition, not
 * against the table they are coded from: the weight of node i is the bilinear hat N_i
 * averaged over the particle's domain [x_p - l, x_p + l] (Bardenhagen and Kober 2004),
 * here integrated numerically with GSL.  Also: partition of unity, exact reproduction
 * of linear fields and their gradients, continuity across cell edges, the quadratic
 * B-spline at one particle per cell, and finite differences of the weights.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>
#include <gsl/gsl_integration.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "test_util.h"
#include "mpm_shape.h"

#define NPTS 20000
static const double lcs[] = {0.5, 0.25, 1.0 / 6.0, 0.125}; /* 1, 4, 9, 16 ppc */
#define NLC (int)(sizeof lcs / sizeof lcs[0])

typedef struct {
  double node; /* node position, cells */
} hat_par;

static double hat(double x, void *par)
{
  const double d = fabs(x - ((const hat_par *)par)->node);
  return d < 1.0 ? 1.0 - d : 0.0;
}

/* (1 / 2 lc) int_{f - lc}^{f + lc} N_node(x) dx, adaptive quadrature with the hat's
 * kinks as break points. */
static double gimp_by_quadrature(double f, double lc, double node, gsl_integration_workspace *w)
{
  hat_par par = {node};
  gsl_function F = {hat, &par};
  double pts[5];
  size_t np = 0;
  pts[np++] = f - lc;
  for (int k = -1; k <= 1; k++) {
    const double b = node + k;
    if (b > f - lc && b < f + lc)
      pts[np++] = b;
  }
  pts[np++] = f + lc;
  double r, err;
  gsl_integration_qagp(&F, pts, np, 1e-14, 1e-12, 1000, w, &r, &err);
  return r / (2.0 * lc);
}

static void test_mpm_gimp_matches_domain_average(void **state)
{
  (void)state;
  gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
  uint64_t seed = 7;
  for (int l = 0; l < NLC; l++)
    for (int n = 0; n < NPTS / 10; n++) {
      const double f = 2.0 + 5.0 * urand(&seed);
      mpm_gimp1 o;
      mpm_gimp_1d(f, lcs[l], &o);
      /* the three nodes are the nearest and its neighbours; all others weigh 0 */
      assert_int_equal(o.i0, (int)floor(f + 0.5) - 1);
      for (int a = 0; a < 3; a++)
        assert_abs(o.S[a], gimp_by_quadrature(f, lcs[l], o.i0 + a, w), 1e-12, "S vs domain average of N");
      assert_abs(gimp_by_quadrature(f, lcs[l], o.i0 - 1, w), 0.0, 1e-14, "node i0 - 1 outside support");
      assert_abs(gimp_by_quadrature(f, lcs[l], o.i0 + 3, w), 0.0, 1e-14, "node i0 + 3 outside support");
    }
  gsl_integration_workspace_free(w);
}

/* sum S = 1, sum dS = 0, sum S x_i = x_p, sum dS x_i = 1 (in cells). */
static void test_mpm_gimp_partition_and_linear(void **state)
{
  (void)state;
  uint64_t seed = 11;
  for (int l = 0; l < NLC; l++)
    for (int n = 0; n < NPTS; n++) {
      const double f = 1.0 + 6.0 * urand(&seed);
      mpm_gimp1 o;
      mpm_gimp_1d(f, lcs[l], &o);
      double s = 0.0, ds = 0.0, sx = 0.0, dsx = 0.0;
      for (int a = 0; a < 3; a++) {
        assert_true(o.S[a] >= 0.0 && o.S[a] <= 1.0);
        s += o.S[a];
        ds += o.dS[a];
        sx += o.S[a] * (o.i0 + a);
        dsx += o.dS[a] * (o.i0 + a);
      }
      assert_abs(s, 1.0, 1e-14, "partition of unity");
      assert_abs(ds, 0.0, 1e-14, "gradient sum");
      assert_abs(sx, f, 1e-13, "linear reproduction");
      assert_abs(dsx, 1.0, 1e-13, "gradient of a linear field");
    }
}

/* Central differences of S against dS, away from the points where dS has a kink. */
static void test_mpm_gimp_gradient_finite_difference(void **state)
{
  (void)state;
  uint64_t seed = 13;
  const double e = 1e-6;
  for (int l = 0; l < NLC; l++)
    for (int n = 0; n < NPTS / 4; n++) {
      const double f = 2.0 + 4.0 * urand(&seed);
      mpm_gimp1 o, op, om;
      mpm_gimp_1d(f, lcs[l], &o);
      mpm_gimp_1d(f + e, lcs[l], &op);
      mpm_gimp_1d(f - e, lcs[l], &om);
      if (op.i0 != o.i0 || om.i0 != o.i0)
        continue; /* the stencil moves: compared by the continuity test */
      for (int a = 0; a < 3; a++)
        assert_abs((op.S[a] - om.S[a]) / (2.0 * e), o.dS[a], 1e-6, "dS vs central difference");
    }
}

/* Weights and gradients are continuous where the stencil changes (half-way between
 * nodes) and at the cell edges: the property that removes the cell-crossing error. */
static void test_mpm_gimp_continuous(void **state)
{
  (void)state;
  const double e = 1e-10;
  for (int l = 0; l < NLC; l++)
    for (int c = 2; c < 6; c++)
      for (int half = 0; half < 2; half++) {
        const double f = c + 0.5 * half;
        double wl[8] = {0}, wr[8] = {0}, gl[8] = {0}, gr[8] = {0};
        mpm_gimp1 a, b;
        mpm_gimp_1d(f - e, lcs[l], &a);
        mpm_gimp_1d(f + e, lcs[l], &b);
        for (int k = 0; k < 3; k++) {
          wl[a.i0 - c + 3 + k] = a.S[k];
          gl[a.i0 - c + 3 + k] = a.dS[k];
          wr[b.i0 - c + 3 + k] = b.S[k];
          gr[b.i0 - c + 3 + k] = b.dS[k];
        }
        for (int k = 0; k < 8; k++) {
          assert_abs(wl[k], wr[k], 1e-9, "S continuous");
          assert_abs(gl[k], gr[k], 1e-8, "dS continuous");
        }
      }
}

/* One particle per cell (lc = 1/2): the quadratic B-spline, 3/4 - d^2 and (3/2 - |d|)^2 / 2. */
static void test_mpm_gimp_bspline_at_one_ppc(void **state)
{
  (void)state;
  uint64_t seed = 17;
  for (int n = 0; n < NPTS; n++) {
    const double f = 2.0 + 4.0 * urand(&seed);
    mpm_gimp1 o;
    mpm_gimp_1d(f, 0.5, &o);
    for (int a = 0; a < 3; a++) {
      const double d = fabs(f - (o.i0 + a));
      const double b = d < 0.5 ? 0.75 - d * d : (d < 1.5 ? 0.5 * (1.5 - d) * (1.5 - d) : 0.0);
      assert_abs(o.S[a], b, 1e-14, "quadratic B-spline");
    }
  }
}

/* The support test: a particle whose 3 x 3 nodes leave the grid is outside. */
static void test_mpm_gimp_inside(void **state)
{
  (void)state;
  mpm_grid *g = mpm_grid_alloc(7, 4, -3.25, 1.5, 0.75);
  assert_non_null(g);
  assert_true(mpm_gimp_inside(g, -3.25 + 0.75 * 0.5, 1.5 + 0.75 * 0.5));
  assert_false(mpm_gimp_inside(g, -3.25 + 0.75 * 0.49, 1.5 + 0.75 * 2.0));
  assert_false(mpm_gimp_inside(g, -3.25 + 0.75 * 6.5, 1.5 + 0.75 * 2.0));
  assert_true(mpm_gimp_inside(g, -3.25 + 0.75 * 6.49, 1.5 + 0.75 * 3.49));
  assert_false(mpm_gimp_inside(g, -3.25 + 0.75 * 3.0, 1.5 + 0.75 * 3.5));
  assert_false(mpm_gimp_inside(g, NAN, 2.0));
  mpm_grid_free(g);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_gimp_matches_domain_average),
      cmocka_unit_test(test_mpm_gimp_partition_and_linear),
      cmocka_unit_test(test_mpm_gimp_gradient_finite_difference),
      cmocka_unit_test(test_mpm_gimp_continuous),
      cmocka_unit_test(test_mpm_gimp_bspline_at_one_ppc),
      cmocka_unit_test(test_mpm_gimp_inside),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
