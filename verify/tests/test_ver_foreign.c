/*
 * test_ver_foreign.c - foreign.c: the strict CSV reader (columns by header name, '#'
 * and blank lines skipped, errors naming file, line and column) and the measurements
 * of a made-up load curve: the closed-form Fig. 6 triangle, whose area (the external
 * work) is Pmax delta_sep / 2 = 32 x 0.375 / 2 = 6.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "foreign.h"
#include "io.h"

static char path[256];

static void put(const char *text)
{
  snprintf(path, sizeof path, "/tmp/test_ver_foreign.%ld.csv", (long)getpid());
  assert_int_equal(ver_io_write_atomic(path, text), 0);
}

static void test_ver_foreign_reader(void **state)
{
  (void)state;
  static const char *const names[] = {"delta", "P_grip", "P_fixed"};
  ver_table t;
  char err[512], want[600];
  put("# delam load.csv schema 1\n\nP_grip, step ,delta\n1,1,0.1\n\n2,2,0.2\n3,3,0.3\n");
  assert_int_equal(ver_table_read(path, names, 3, 2, &t, err, sizeof err), 0);
  assert_int_equal(t.n, 3);
  assert_null(t.col[2]);
  assert_true(t.col[0][2] == 0.3 && t.col[1][1] == 2.0);
  ver_table_free(&t);
  put("delta,P\n0.1,1\n0.2,2\n0.3,3\n");
  assert_int_equal(ver_table_read(path, names, 3, 2, &t, err, sizeof err), 2);
  snprintf(want, sizeof want, "%s:1: the header has no column 'P_grip'", path);
  assert_non_null(strstr(err, want));
  put("delta,P_grip\n0.1,1\n\n0.2,nan\n0.3,3\n");
  assert_int_equal(ver_table_read(path, names, 3, 2, &t, err, sizeof err), 2);
  snprintf(want, sizeof want, "%s:4:2: column 'P_grip': 'nan' is not a finite number", path);
  assert_non_null(strstr(err, want));
  put("delta,P_grip\n0.1,1\n0.2\n");
  assert_int_equal(ver_table_read(path, names, 3, 2, &t, err, sizeof err), 2);
  snprintf(want, sizeof want, "%s:3:2: no field for column 'P_grip'", path);
  assert_non_null(strstr(err, want));
  put("delta,P_grip\n0.1,1\n0.2,2\n");
  assert_int_equal(ver_table_read(path, names, 3, 2, &t, err, sizeof err), 2);
  assert_non_null(strstr(err, "at least 3"));
  remove(path);
  assert_int_equal(ver_table_read(path, names, 3, 2, &t, err, sizeof err), 1);
}

static void test_ver_foreign_triangle(void **state)
{
  (void)state;
  static ver_case c;
  memset(&c, 0, sizeof c);
  char err[512];
  if (ver_scene_load(DELAM_SRC "/data/scenes/fig6.ini", &c.vs, err, sizeof err))
    fail_msg("%s", err);
  assert_int_equal(ver_scene_bar(&c.vs.sc, &c.ana, err, sizeof err), 0);
  c.have_ana = 1;
  /* the closed-form curve, sampled every 0.0005 to 1.0: up to 32 at 0.1875, down to 0
   * at 0.375, then zero */
  enum { N = 2001 };
  static double d[N], P[N];
  for (int i = 0; i < N; i++) {
    d[i] = 0.0005 * i;
    P[i] = d[i] <= 0.1875 ? 32.0 * d[i] / 0.1875 : d[i] <= 0.375 ? 32.0 * (0.375 - d[i]) / 0.1875 : 0.0;
  }
  ver_table ld = {N, {d, P, NULL}};
  ver_foreign_measure(&c, &ld, NULL, NULL);
  assert_true(fabs(c.peak_P - 32.0) < 1e-12);
  assert_true(fabs(c.W_ext_final - 6.0) < 1e-9);        /* the triangle's area */
  assert_true(fabs(c.k_elastic - 32.0 / 0.1875) < 1e-6); /* E H / L = 170.67 */
  assert_true(fabs(c.k_soft + 32.0 / 0.1875) < 1e-6);
  /* the analytic curve itself; a row stands for its interval, so it is compared half an
   * interval earlier: slope x 0.00025 / Pmax = 1 / 750 */
  assert_true(fabs(c.curve_l2 - 1.0 / 750.0) < 1e-4);
  assert_true(isnan(c.D_final) && isnan(c.energy_residual) && isnan(c.band_width));
  /* separation by the load (below 2 % of the peak over the window): within 1 % of 0.375 */
  assert_true(fabs(c.delta_sep / 0.375 - 1.0) < 0.01);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ver_foreign_reader),
      cmocka_unit_test(test_ver_foreign_triangle),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
