/*
 * test_mpm_static_mms.c - code verification of the quasi-static solver where stress
 * varies: the manufactured solution of kernel/mpm_static_mms.c,
 *   u_x = A sin(pi X / L) cos(pi Y / H),  u_y = A cos(pi X / L) sin(pi Y / (2 H)),
 * with its body force and the exact u on the perimeter nodes, one linear solve.  The
 * particles are a bilinear element's midpoint quadrature, so second order (Strang's
 * lemma).  Asserted per shape at 4 ppc and bilinear at 9 ppc, h 8, 4, 2:
 *  - the observed order of the particle and free-node errors >= 1.8;
 *  - at h 2 the particle error within 10 % of the bilinear interpolant's own error of
 *    the field at the same points (interp_error, from the closed form alone);
 *  - uGIMP's errors equal bilinear's to 1e-9 (at the laid places its weights are the
 *    hats'; docs/static.md);
 *  - a shape, h or ppc the solver cannot take is MPM_EINVAL.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "test_util.h"

#define SM_PI 3.14159265358979323846
#define SM_L 192.0
#define SM_H 32.0

/* The manufactured field over its amplitude, written here from the formula above. */
static void field(double X, double Y, double u[2])
{
  u[0] = sin(SM_PI * X / SM_L) * cos(SM_PI * Y / SM_H);
  u[1] = cos(SM_PI * X / SM_L) * sin(0.5 * SM_PI * Y / SM_H);
}

/* The RMS error, over the amplitude, of the bilinear interpolant of the field's nodal
 * values at the particles laid n x n per cell of h (centres of equal squares). */
static double interp_error(double h, int n)
{
  const int cx = (int)lround(SM_L / h), cy = (int)lround(SM_H / h);
  const double d = h / n;
  double e2 = 0.0;
  long np = 0;
  for (int j = 0; j < cy * n; j++)
    for (int i = 0; i < cx * n; i++, np++) {
      const double X = (i + 0.5) * d, Y = (j + 0.5) * d;
      const int ci = i / n, cj = j / n;
      const double rx = X / h - ci, ry = Y / h - cj;
      double u[2], c00[2], c10[2], c01[2], c11[2];
      field(X, Y, u);
      field(ci * h, cj * h, c00);
      field((ci + 1) * h, cj * h, c10);
      field(ci * h, (cj + 1) * h, c01);
      field((ci + 1) * h, (cj + 1) * h, c11);
      for (int k = 0; k < 2; k++) {
        const double ui = (1 - rx) * (1 - ry) * c00[k] + rx * (1 - ry) * c10[k] + (1 - rx) * ry * c01[k] + rx * ry * c11[k];
        e2 += (ui - u[k]) * (ui - u[k]);
      }
    }
  return sqrt(e2 / (double)np);
}

static void mms_errors(int shape, int ppc, double e[3], double en[3])
{
  char err[256] = "";
  for (int i = 0; i < 3; i++) {
    const double h = 8.0 / (double)(1 << i);
    if (mpm_static_mms_error(h, shape, ppc, &e[i], &en[i], err, sizeof err) != MPM_OK)
      fail_msg("static mms h %g: %s", h, err);
  }
}

static void check_orders(int shape, int ppc, const char *id)
{
  double e[3], en[3];
  mms_errors(shape, ppc, e, en);
  const double p01 = log2(e[0] / e[1]), p12 = log2(e[1] / e[2]);
  const double n01 = log2(en[0] / en[1]), n12 = log2(en[1] / en[2]);
  const double ei = interp_error(2.0, (int)lround(sqrt((double)ppc)));
  printf("# %s: particle error %.4g %.4g %.4g at h 8 4 2, order %.3f %.3f; nodal %.4g %.4g %.4g, order %.3f %.3f; "
         "h 2 over the interpolant's %.4g: %.3f\n", id, e[0], e[1], e[2], p01, p12, en[0], en[1], en[2], n01, n12, ei,
         e[2] / ei);
  if (!(p01 >= 1.8 && p12 >= 1.8))
    fail_msg("%s: particle error order %.3f, %.3f < 1.8 (errors %.4g %.4g %.4g)", id, p01, p12, e[0], e[1], e[2]);
  if (!(n01 >= 1.8 && n12 >= 1.8))
    fail_msg("%s: nodal error order %.3f, %.3f < 1.8 (errors %.4g %.4g %.4g)", id, n01, n12, en[0], en[1], en[2]);
  assert_rel(e[2], ei, 0.1, "particle error at h 2 against the bilinear interpolant's");
}

static void test_mpm_static_mms_linear_ppc4(void **state)
{
  (void)state;
  check_orders(MPM_SHAPE_LINEAR, 4, "static-mms-linear-ppc4");
}

static void test_mpm_static_mms_linear_ppc9(void **state)
{
  (void)state;
  check_orders(MPM_SHAPE_LINEAR, 9, "static-mms-linear-ppc9");
}

static void test_mpm_static_mms_gimp_ppc4(void **state)
{
  (void)state;
  check_orders(MPM_SHAPE_GIMP, 4, "static-mms-gimp-ppc4");
}

/* At the laid places uGIMP's weights are bilinear's (the header): the same solution. */
static void test_mpm_static_mms_gimp_is_bilinear(void **state)
{
  (void)state;
  for (int ppc = 4; ppc <= 9; ppc += 5) {
    double el[3], enl[3], eg[3], eng[3];
    mms_errors(MPM_SHAPE_LINEAR, ppc, el, enl);
    mms_errors(MPM_SHAPE_GIMP, ppc, eg, eng);
    for (int i = 0; i < 3; i++) {
      assert_rel(eg[i], el[i], 1e-9, "uGIMP's particle error against bilinear's");
      assert_rel(eng[i], enl[i], 1e-9, "uGIMP's nodal error against bilinear's");
    }
  }
}

static void test_mpm_static_mms_refuses(void **state)
{
  (void)state;
  double e = 0.0;
  char err[256] = "";
  assert_int_equal(mpm_static_mms_error(4.0, 7, 4, &e, NULL, err, sizeof err), MPM_EINVAL);
  assert_true(isnan(e));
  assert_int_equal(mpm_static_mms_error(5.0, MPM_SHAPE_LINEAR, 4, &e, NULL, err, sizeof err), MPM_EINVAL);
  assert_int_equal(mpm_static_mms_error(4.0, MPM_SHAPE_LINEAR, 3, &e, NULL, err, sizeof err), MPM_EINVAL);
  /* one quadrature point per bilinear cell: the static solver's refusal */
  assert_int_equal(mpm_static_mms_error(4.0, MPM_SHAPE_LINEAR, 1, &e, NULL, err, sizeof err), MPM_EINVAL);
  assert_non_null(strstr(err, "hourglass"));
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_mpm_static_mms_linear_ppc4),
    cmocka_unit_test(test_mpm_static_mms_linear_ppc9),
    cmocka_unit_test(test_mpm_static_mms_gimp_ppc4),
    cmocka_unit_test(test_mpm_static_mms_gimp_is_bilinear),
    cmocka_unit_test(test_mpm_static_mms_refuses),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
