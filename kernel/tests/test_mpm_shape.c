/*
 * test_mpm_shape.c - the bilinear shape functions of mpm_shape.h (sec. 2) against
 * properties that hold for any bilinear interpolation, whatever the code: partition
 * of unity, zero gradient sum, exact reproduction of linear fields and of their
 * gradients, central finite differences of N, and the column-major node numbering
 * that mpm.h documents (node (i, j) at i * nny + j).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "test_util.h"
#include "mpm_shape.h"

#define NPTS 20000

/* An off-centre, non-square grid so that row/column mix-ups and origin errors show. */
static mpm_grid *test_grid(void)
{
  mpm_grid *g = mpm_grid_alloc(7, 4, -3.25, 1.5, 0.75);
  assert_non_null(g);
  return g;
}

/* Coordinates of node index k, decoded with the documented layout k = i * nny + j. */
static void node_xy(const mpm_grid *g, size_t k, double *x, double *y)
{
  const size_t i = k / (size_t)g->nny, j = k % (size_t)g->nny;
  *x = g->ox + (double)i * g->h;
  *y = g->oy + (double)j * g->h;
}

/* The four node indices in mpm_shape_eval's order (i,j), (i+1,j), (i,j+1), (i+1,j+1). */
static void four_nodes(const mpm_grid *g, const mpm_shape *s, size_t k[4])
{
  const size_t nny = (size_t)g->nny;
  k[0] = s->n00;
  k[1] = s->n00 + nny;
  k[2] = s->n00 + 1;
  k[3] = s->n00 + nny + 1;
}

static void random_inside(const mpm_grid *g, uint64_t *seed, double *x, double *y)
{
  *x = g->ox + urand(seed) * g->ncx * g->h;
  *y = g->oy + urand(seed) * g->ncy * g->h;
}

/* sum N = 1 and sum grad N = 0 at random points, and 0 <= N <= 1. */
static void test_mpm_shape_partition_of_unity(void **state)
{
  (void)state;
  mpm_grid *g = test_grid();
  uint64_t seed = 12345;
  for (int n = 0; n < NPTS; n++) {
    double x, y, N[4], Gx[4], Gy[4];
    random_inside(g, &seed, &x, &y);
    mpm_shape s;
    assert_int_equal(mpm_shape_at(g, x, y, &s), 1);
    mpm_shape_eval(&s, g->h, N, Gx, Gy);
    double sn = 0.0, sgx = 0.0, sgy = 0.0;
    for (int a = 0; a < 4; a++) {
      assert_true(N[a] >= 0.0 && N[a] <= 1.0);
      sn += N[a];
      sgx += Gx[a];
      sgy += Gy[a];
    }
    assert_rel(sn, 1.0, 1e-14, "sum N");
    /* gradients are O(1/h); their sum must vanish to rounding of that scale */
    assert_abs(sgx, 0.0, 1e-14 / g->h, "sum Gx");
    assert_abs(sgy, 0.0, 1e-14 / g->h, "sum Gy");
  }
  mpm_grid_free(g);
}

/* Linear completeness: sum N_i x_i = x, sum N_i y_i = y, sum G_i (x) x_i = identity,
 * with x_i decoded from the node index (so the numbering is checked as well). */
static void test_mpm_shape_linear_reproduction(void **state)
{
  (void)state;
  mpm_grid *g = test_grid();
  uint64_t seed = 777;
  for (int n = 0; n < NPTS; n++) {
    double x, y, N[4], Gx[4], Gy[4];
    random_inside(g, &seed, &x, &y);
    mpm_shape s;
    assert_int_equal(mpm_shape_at(g, x, y, &s), 1);
    mpm_shape_eval(&s, g->h, N, Gx, Gy);
    size_t k[4];
    four_nodes(g, &s, k);
    double rx = 0.0, ry = 0.0, gxx = 0.0, gxy = 0.0, gyx = 0.0, gyy = 0.0, rf = 0.0;
    for (int a = 0; a < 4; a++) {
      double xi, yi;
      node_xy(g, k[a], &xi, &yi);
      rx += N[a] * xi;
      ry += N[a] * yi;
      gxx += Gx[a] * xi;
      gxy += Gx[a] * yi;
      gyx += Gy[a] * xi;
      gyy += Gy[a] * yi;
      rf += N[a] * (2.0 - 3.0 * xi + 0.5 * yi); /* an arbitrary affine field */
    }
    assert_abs(rx, x, 1e-13, "sum N x_i");
    assert_abs(ry, y, 1e-13, "sum N y_i");
    assert_rel(gxx, 1.0, 1e-12, "sum Gx x_i");
    assert_rel(gyy, 1.0, 1e-12, "sum Gy y_i");
    assert_abs(gxy, 0.0, 1e-12, "sum Gx y_i");
    assert_abs(gyx, 0.0, 1e-12, "sum Gy x_i");
    assert_abs(rf, 2.0 - 3.0 * x + 0.5 * y, 1e-12, "affine field");
  }
  mpm_grid_free(g);
}

/* N_i at node j is delta_ij: at every interior node of every cell corner the weights
 * pick exactly that node (decoded coordinates equal the point). */
static void test_mpm_shape_kronecker_at_nodes(void **state)
{
  (void)state;
  mpm_grid *g = test_grid();
  for (int i = 0; i < g->ncx; i++)
    for (int j = 0; j < g->ncy; j++) {
      const double x = g->ox + i * g->h, y = g->oy + j * g->h;
      mpm_shape s;
      double N[4], Gx[4], Gy[4];
      assert_int_equal(mpm_shape_at(g, x, y, &s), 1);
      mpm_shape_eval(&s, g->h, N, Gx, Gy);
      assert_int_equal(s.n00, mpm_grid_node(g, i, j));
      assert_rel(N[0], 1.0, 1e-14, "N at own node");
      for (int a = 1; a < 4; a++)
        assert_abs(N[a], 0.0, 1e-14, "N at other node");
    }
  mpm_grid_free(g);
}

/* grad N against central differences of N inside one cell (N is bilinear, so the
 * difference is exact up to rounding when both points stay in the cell). */
static void test_mpm_shape_gradient_finite_difference(void **state)
{
  (void)state;
  mpm_grid *g = test_grid();
  uint64_t seed = 99;
  const double eps = 1e-6 * g->h;
  for (int n = 0; n < 2000; n++) {
    /* a point at least 2 eps away from the cell's edges */
    const int ci = (int)(urand(&seed) * g->ncx), cj = (int)(urand(&seed) * g->ncy);
    const double x = g->ox + (ci + 0.01 + 0.98 * urand(&seed)) * g->h;
    const double y = g->oy + (cj + 0.01 + 0.98 * urand(&seed)) * g->h;
    mpm_shape s, sp, sm;
    double N[4], Gx[4], Gy[4], Np[4], Nm[4], d1[4], d2[4];
    assert_int_equal(mpm_shape_at(g, x, y, &s), 1);
    assert_int_equal(s.n00, mpm_grid_node(g, ci, cj));
    mpm_shape_eval(&s, g->h, N, Gx, Gy);
    mpm_shape_at(g, x + eps, y, &sp);
    mpm_shape_at(g, x - eps, y, &sm);
    assert_int_equal(sp.n00, s.n00);
    assert_int_equal(sm.n00, s.n00);
    mpm_shape_eval(&sp, g->h, Np, d1, d2);
    mpm_shape_eval(&sm, g->h, Nm, d1, d2);
    for (int a = 0; a < 4; a++)
      assert_abs((Np[a] - Nm[a]) / (2.0 * eps), Gx[a], 1e-6 / g->h, "Gx vs finite difference");
    mpm_shape_at(g, x, y + eps, &sp);
    mpm_shape_at(g, x, y - eps, &sm);
    mpm_shape_eval(&sp, g->h, Np, d1, d2);
    mpm_shape_eval(&sm, g->h, Nm, d1, d2);
    for (int a = 0; a < 4; a++)
      assert_abs((Np[a] - Nm[a]) / (2.0 * eps), Gy[a], 1e-6 / g->h, "Gy vs finite difference");
  }
  mpm_grid_free(g);
}

/* Points outside [ox, ox + ncx h) x [oy, oy + ncy h) (and NaN) are rejected, with the
 * documented fallback (first cell, weights that put everything on node 0). */
static void test_mpm_shape_outside_rejected(void **state)
{
  (void)state;
  mpm_grid *g = test_grid();
  const double x1 = g->ox + g->ncx * g->h, y1 = g->oy + g->ncy * g->h;
  const double xm = g->ox + 0.5 * g->ncx * g->h, ym = g->oy + 0.5 * g->ncy * g->h;
  const double bad[][2] = {
      {g->ox - 1e-12, ym}, {x1, ym}, {x1 + 5.0, ym}, {xm, g->oy - 1e-9}, {xm, y1},
      {xm, y1 + 100.0}, {NAN, ym}, {xm, NAN}, {INFINITY, ym}, {xm, -INFINITY}, {-1e300, 1e300},
  };
  for (size_t b = 0; b < sizeof bad / sizeof bad[0]; b++) {
    mpm_shape s;
    s.n00 = 12345;
    if (mpm_shape_at(g, bad[b][0], bad[b][1], &s) != 0)
      fail_msg("point %zu (%g, %g) outside the grid was accepted", b, bad[b][0], bad[b][1]);
    assert_int_equal(s.n00, 0);
    assert_rel(s.wx0 * s.wy0, 1.0, 0.0, "fallback weight");
  }
  /* the lower edges belong to the grid, the upper ones do not */
  mpm_shape s;
  assert_int_equal(mpm_shape_at(g, g->ox, g->oy, &s), 1);
  assert_int_equal(s.n00, 0);
  assert_int_equal(mpm_shape_at(g, x1 - 1e-9, y1 - 1e-9, &s), 1);
  assert_int_equal(s.n00, mpm_grid_node(g, g->ncx - 1, g->ncy - 1));
  mpm_grid_free(g);
}

/* Column-major numbering: node (i, j) at i * nny + j, all indices distinct and within
 * nnx * nny, and a point in cell (i, j) gets n00 = node (i, j). */
static void test_mpm_shape_node_column_major(void **state)
{
  (void)state;
  mpm_grid *g = test_grid();
  assert_int_equal(g->nnx, g->ncx + 1);
  assert_int_equal(g->nny, g->ncy + 1);
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  unsigned char *seen = calloc(nn, 1);
  assert_non_null(seen);
  for (int i = 0; i < g->nnx; i++)
    for (int j = 0; j < g->nny; j++) {
      const size_t k = mpm_grid_node(g, i, j);
      assert_true(k < nn);
      assert_int_equal(k, (size_t)i * (size_t)(g->ncy + 1) + (size_t)j);
      assert_int_equal(seen[k], 0);
      seen[k] = 1;
      if (j + 1 < g->nny)
        assert_int_equal(mpm_grid_node(g, i, j + 1), k + 1); /* j runs fastest */
    }
  free(seen);
  for (int i = 0; i < g->ncx; i++)
    for (int j = 0; j < g->ncy; j++) {
      mpm_shape s;
      const double x = g->ox + (i + 0.3) * g->h, y = g->oy + (j + 0.6) * g->h;
      assert_int_equal(mpm_shape_at(g, x, y, &s), 1);
      assert_int_equal(s.n00, mpm_grid_node(g, i, j));
      /* the weights are the hats of the local coordinate (0.3, 0.6) */
      assert_rel(s.wx1, 0.3, 1e-12, "wx1");
      assert_rel(s.wy1, 0.6, 1e-12, "wy1");
    }
  mpm_grid_free(g);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_shape_partition_of_unity),
      cmocka_unit_test(test_mpm_shape_linear_reproduction),
      cmocka_unit_test(test_mpm_shape_kronecker_at_nodes),
      cmocka_unit_test(test_mpm_shape_gradient_finite_difference),
      cmocka_unit_test(test_mpm_shape_outside_rejected),
      cmocka_unit_test(test_mpm_shape_node_column_major),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
