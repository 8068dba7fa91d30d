/*
 * test_ver_io.c - io.c: CSV columns picked by header name whatever their order, a
 * missing column refused, writes that leave no temporary file, slurp's size limit,
 * mkdir -p of a nested folder; the faults: a FIFO refused without blocking, the size
 * limit's errno, mkdir -p over a file, temporary names, a folder's lock held by another
 * process named with its pid.
 */
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "datadir.h"
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
  char path[512], tmp[560];
  snprintf(path, sizeof path, "%s/b.txt", dir);
  snprintf(tmp, sizeof tmp, "%s.%ld.tmp", path, (long)getpid());
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

static void test_ver_io_faults(void **state)
{
  (void)state;
  char path[512], tmp[600], fin[600];
  const char *what = NULL;
  snprintf(path, sizeof path, "%s/fifo", dir);
  assert_int_equal(mkfifo(path, 0600), 0);
  errno = 0;
  assert_null(ver_open_regular(path, &what)); /* returns at once: no writer needed */
  assert_int_equal(errno, EINVAL);
  assert_string_equal(what, "a FIFO");
  assert_null(ver_io_slurp(path, NULL, 0));
  assert_int_equal(errno, EINVAL);
  snprintf(path, sizeof path, "%s/d.txt", dir);
  assert_int_equal(ver_io_write_atomic(path, "0123456789"), 0);
  assert_null(ver_io_slurp(path, NULL, 9));
  assert_int_equal(errno, EFBIG);
  assert_int_equal(ver_mkdir_p(path), -1); /* a file: not a folder */
  assert_int_equal(errno, ENOTDIR);
  FILE *f = ver_io_open_tmp(path, tmp, sizeof tmp);
  assert_non_null(f);
  assert_int_equal(ver_io_tmp_final(tmp, fin, sizeof fin), 0);
  assert_string_equal(fin, path);
  assert_non_null(strstr(tmp, ".tmp"));
  assert_int_equal(ver_io_commit(f, tmp), 0);
  /* the lock: held here, a child is refused and told this pid */
  char err[1400];
  const int fd = ver_io_lock_dir(dir, err, sizeof err);
  assert_true(fd >= 0);
  int pipefd[2];
  assert_int_equal(pipe(pipefd), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    const int r = ver_io_lock_dir(dir, err, sizeof err);
    const ssize_t w = write(pipefd[1], err, strlen(err) + 1);
    _exit(r < 0 && w > 0 ? 0 : 1);
  }
  char got[1400] = "", want[200];
  assert_true(read(pipefd[0], got, sizeof got - 1) > 0);
  int ws;
  assert_int_equal(waitpid(pid, &ws, 0), pid);
  assert_true(WIFEXITED(ws) && WEXITSTATUS(ws) == 0);
  snprintf(want, sizeof want, "another delam process (pid %ld) is writing this folder", (long)getpid());
  assert_non_null(strstr(got, want));
  close(fd);
  close(pipefd[0]);
  close(pipefd[1]);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_ver_io_csv_by_header),
    cmocka_unit_test(test_ver_io_atomic_and_slurp),
    cmocka_unit_test(test_ver_io_mkdir_p),
    cmocka_unit_test(test_ver_io_faults),
  };
  return cmocka_run_group_tests(tests, setup, NULL);
}
