/*
 * test_mpm_mms.c - code verification of the MPM step by a manufactured solution (after
 * Wallstedt and Guilkey's, small strain, plane stress, nu = 0): the order of accuracy of
 * the particle displacement on three grids.
 *   u(X, t) = A sin(pi X / L) sin(w t),  v = 0,  w = 1.5 pi c / L,
 *   b_x = u_tt - (E / rho) u_XX = A ((pi c / L)^2 - w^2) sin(pi X / L) sin(w t),
 * held at X = 0, L; start u = 0, vx = A w sin(pi X / L).  Error: RMS over the particles
 * of (x - X - u(X, t)) / A at t = 10, h = 8, 4, 2, dt = 0.1 h / 8, 1 ppc.  |u| < h / 60,
 * so no particle leaves its cell and the step is a linear finite element with midpoint
 * quadrature: second order.  Asserted: observed order >= 1.8 for USL and MUSL with
 * grid.bc = consistent and USL with lagrangian, and the error at h 2 below 1 %.  MUSL
 * with lagrangian (1.65, its v' at held nodes not the held one) is not asserted
 * (docs/verification.md).
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

static double mms_error(double h, int scheme, int bc)
{
  double e;
  char err[256] = "";
  if (mpm_mms_error(h, scheme, bc, &e, err, sizeof err) != MPM_OK)
    fail_msg("mms h %g: %s", h, err);
  return e;
}

static void mms_order(int scheme, int bc, const char *name)
{
  const double hs[3] = {8.0, 4.0, 2.0};
  double e[3];
  for (int i = 0; i < 3; i++)
    e[i] = mms_error(hs[i], scheme, bc);
  const double p01 = log(e[0] / e[1]) / log(2.0), p12 = log(e[1] / e[2]) / log(2.0);
  /* least-squares slope over the three grids */
  double mx = 0, my = 0, sxy = 0, sxx = 0;
  for (int i = 0; i < 3; i++) {
    mx += log(hs[i]) / 3.0;
    my += log(e[i]) / 3.0;
  }
  for (int i = 0; i < 3; i++) {
    sxy += (log(hs[i]) - mx) * (log(e[i]) - my);
    sxx += (log(hs[i]) - mx) * (log(hs[i]) - mx);
  }
  const double p = sxy / sxx;
  printf("# mms %s: error %.4g %.4g %.4g at h 8 4 2 (dt 0.1 h / 8), order %.3f (pairs %.3f, %.3f)\n", name, e[0],
         e[1], e[2], p, p01, p12);
  if (!(p >= 1.8))
    fail_msg("mms %s: observed order %.3f < 1.8 (errors %.4g %.4g %.4g)", name, p, e[0], e[1], e[2]);
  if (!(e[2] < 0.01))
    fail_msg("mms %s: error at h 2 %.4g >= 1 %%", name, e[2]);
}

static void test_mpm_mms_usl(void **state)
{
  (void)state;
  mms_order(MPM_SCHEME_USL, MPM_BC_CONSISTENT, "usl consistent");
  mms_order(MPM_SCHEME_USL, MPM_BC_LAGRANGIAN, "usl lagrangian");
}

static void test_mpm_mms_musl(void **state)
{
  (void)state;
  mms_order(MPM_SCHEME_MUSL, MPM_BC_CONSISTENT, "musl consistent");
}

/* The body force hook is refused where it is not implemented. */
static void test_mpm_mms_refused(void **state)
{
  (void)state;
  mpm_scene sc = mpm_mms_scene(8.0, MPM_SCHEME_USL, MPM_BC_CONSISTENT);
  sc.shape = MPM_SHAPE_GIMP;
  mpm_sim *s = NULL;
  char err[256] = "";
  assert_int_equal(mpm_sim_alloc(&sc, 1, &s, err, sizeof err), MPM_EINVAL);
  assert_non_null(strstr(err, "body force"));
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_mpm_mms_usl),
    cmocka_unit_test(test_mpm_mms_musl),
    cmocka_unit_test(test_mpm_mms_refused),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
