/*
 * test_ver_io.c - io.c: CSV columns picked by header name whatever their order, a
 * missing column refused, writes that leave no temporary file, slurp's size limit,
 * mkdir -p of a nested folder.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "io.h"

static char dir[256];

static int setup(void **state)
{
  (void)state;
  snprintf(dir, sizeof dir, "/tmp/test_ver_io.%ld", (long)getpid());
  return ver_mkdir_p(dir);
}

static void test_ver_io_csv_by_header(void **state)
{
  (void)state;
  char path[512];
  snprintf(path, sizeof path, "%s/a.csv", dir);
  assert_int_equal(ver_io_write_atomic(path, "t,delta,P_grip,P_fixed\n0.5,0.1,3.25,-1\n1,0.2,x,2e3\n"), 0);
  const char *cols[2] = {"P_fixed", "delta"};
  double *v[2];
  assert_int_equal(ver_csv_read(path, cols, 2, v), 2);
  assert_true(v[0][0] == -1.0 && v[0][1] == 2000.0);
  assert_true(v[1][0] == 0.1 && v[1][1] == 0.2);
  free(v[0]);
  free(v[1]);
  /* a field that is not a number reads as NaN */
  const char *pg[1] = {"P_grip"};
  assert_int_equal(ver_csv_read(path, pg, 1, v), 2);
  assert_true(v[0][0] == 3.25 && isnan(v[0][1]));
  free(v[0]);
  /* a column the header lacks */
  const char *no[2] = {"delta", "lambda"};
  assert_int_equal(ver_csv_read(path, no, 2, v), -1);
  assert_null(v[0]);
  assert_null(v[1]);
  snprintf(path, sizeof path, "%s/missing.csv", dir);
  assert_int_equal(ver_csv_read(path, cols, 2, v), -1);
}

static void test_ver_io_atomic_and_slurp(void **state)
{
  (void)state;
  char path[512], tmp[520];
  snprintf(path, sizeof path, "%s/b.txt", dir);
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  assert_int_equal(ver_io_write_atomic(path, "hello\n"), 0);
  assert_int_equal(access(tmp, F_OK), -1);
  size_t n = 0;
  char *s = ver_io_slurp(path, &n, 0);
  assert_non_null(s);
  assert_int_equal(n, 6);
  assert_string_equal(s, "hello\n");
  free(s);
  assert_null(ver_io_slurp(path, NULL, 5));
  char dst[512];
  snprintf(dst, sizeof dst, "%s/c.txt", dir);
  assert_int_equal(ver_io_copy(path, dst), 0);
  s = ver_io_slurp(dst, NULL, 0);
  assert_string_equal(s, "hello\n");
  free(s);
  /* a folder that does not exist: nothing written, -1 */
  snprintf(path, sizeof path, "%s/no/such/b.txt", dir);
  assert_int_equal(ver_io_write_atomic(path, "x"), -1);
}

static void test_ver_io_mkdir_p(void **state)
{
  (void)state;
  char path[512];
  snprintf(path, sizeof path, "%s/x/y/z", dir);
  assert_int_equal(ver_mkdir_p(path), 0);
  struct stat st;
  assert_int_equal(stat(path, &st), 0);
  assert_true(S_ISDIR(st.st_mode));
  assert_int_equal(ver_mkdir_p(path), 0); /* exists: fine */
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_ver_io_csv_by_header),
    cmocka_unit_test(test_ver_io_atomic_and_slurp),
    cmocka_unit_test(test_ver_io_mkdir_p),
  };
  return cmocka_run_group_tests(tests, setup, NULL);
}
