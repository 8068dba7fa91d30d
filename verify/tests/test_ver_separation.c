/*
 * test_ver_separation.c - the separation detector (separation.c) alone, on made-up
 * particles and loads: the cut test fires only when every particle row holds a
 * separated particle (head particles do not count), the load test only after the peak
 * and once the window's mean falls below the fraction, at the window's centre; the
 * earlier of the two is delta_sep.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "separation.h"

/* A bar of height 32, h 8, 4 ppc: rows 4 apart, 8 rows. */
static void test_ver_separation_cut(void **state)
{
  (void)state;
  ver_sep d;
  assert_int_equal(ver_sep_init(&d, 32, 8, 4, 3, 0.02), 0);
  assert_int_equal(d.nrow, 8);
  double y0[9];
  uint8_t sep[9] = {0}, mat[9] = {0};
  for (int j = 0; j < 8; j++)
    y0[j] = 4.0 * j + 2.0;
  y0[8] = 30.0; /* a head particle in the top row */
  mat[8] = 2;
  for (int j = 0; j < 7; j++)
    sep[j] = 1;
  sep[8] = 1;
  ver_sep_cut(&d, y0, sep, mat, 2, 9, 0.30);
  assert_true(d.delta_cut < 0); /* the top row is held by the bar; the head does not count */
  sep[7] = 1;
  ver_sep_cut(&d, y0, sep, mat, 2, 9, 0.31);
  assert_true(d.delta_cut == 0.31);
  ver_sep_load(&d, 0.31, 5, 5, 32, 0.19);
  assert_true(d.delta_sep == 0.31);
  ver_sep_free(&d);
}

/* Window of 4 rows, threshold 0.02 of the peak 30 (0.6): rows every 0.01. */
static void test_ver_separation_load(void **state)
{
  (void)state;
  ver_sep d;
  assert_int_equal(ver_sep_init(&d, 32, 8, 1, 4, 0.02), 0);
  const double P[] = {10, 20, 30, 0, 0, 0, 0.1, 0.1, 0.1, 0.1};
  double peak = 0, dpeak = 0;
  for (int i = 0; i < 10; i++) {
    const double delta = 0.01 * (i + 1);
    if (P[i] > peak) {
      peak = P[i];
      dpeak = delta;
    }
    ver_sep_load(&d, delta, P[i], -P[i], peak, dpeak);
    if (i < 6) /* rows 4..7 (0.04 .. 0.07): the first window wholly after the peak at 0.03 */
      assert_true(d.delta_load < 0);
  }
  /* the window 0.04 .. 0.07 has mean 0.025 < 0.6: found at row 7, centre 0.055 */
  assert_true(fabs(d.delta_load - 0.055) < 1e-12);
  assert_true(d.delta_sep == d.delta_load);
  assert_true(d.delta_cut < 0);
  ver_sep_free(&d);
}

/* Both on the same row: the load's window centre is earlier than the cut's delta. */
static void test_ver_separation_first_counts(void **state)
{
  (void)state;
  ver_sep d;
  assert_int_equal(ver_sep_init(&d, 8, 8, 1, 2, 0.5), 0);
  double y0[1] = {4};
  uint8_t sep[1] = {1};
  ver_sep_load(&d, 0.1, 10, 10, 10, 0.1);
  ver_sep_load(&d, 0.2, 1, 1, 10, 0.1);
  ver_sep_cut(&d, y0, sep, NULL, 0, 1, 0.3);
  ver_sep_load(&d, 0.3, 1, 1, 10, 0.1);
  assert_true(d.delta_cut == 0.3);
  assert_true(fabs(d.delta_load - 0.25) < 1e-12);
  assert_true(fabs(d.delta_sep - 0.25) < 1e-12);
  ver_sep_free(&d);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_ver_separation_cut),
    cmocka_unit_test(test_ver_separation_load),
    cmocka_unit_test(test_ver_separation_first_counts),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
