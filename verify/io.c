/*
 * io.c - whole-file reads, atomic writes, mkdir -p, CSV columns by header, clocks
 * (io.h).
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "datadir.h"
#include "io.h"

char *ver_io_slurp(const char *path, size_t *len, size_t max)
{
  FILE *f = ver_open_regular(path, NULL);
  if (!f)
    return NULL;
  struct stat st; /* room for the whole file at once where its size is known */
  size_t cap = fstat(fileno(f), &st) == 0 && st.st_size > 0 ? (size_t)st.st_size + 2 : 1 << 16, n = 0;
  if (max && cap > max + 2)
    cap = max + 2;
  char *buf = malloc(cap);
  while (buf) {
    n += fread(buf + n, 1, cap - n - 1, f);
    if (max && n > max) {
      fclose(f);
      free(buf);
      errno = EFBIG;
      return NULL;
    }
    if (n + 1 < cap)
      break;
    char *nb = realloc(buf, cap *= 2);
    if (!nb)
      free(buf);
    buf = nb;
  }
  const int bad = ferror(f), e = buf ? errno : ENOMEM;
  fclose(f);
  if (!buf || bad) {
    free(buf);
    errno = e;
    return NULL;
  }
  buf[n] = '\0';
  if (len)
    *len = n;
  return buf;
}

int ver_mkdir_p(const char *dir)
{
  char buf[1024];
  if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf) {
    errno = ENAMETOOLONG;
    return -1;
  }
  for (char *p = buf + 1; *p; p++)
    if (*p == '/') {
      *p = '\0';
      if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return -1;
      *p = '/';
    }
  if (mkdir(buf, 0777) == 0)
    return 0;
  struct stat st; /* there already: as a folder, or the path is not one */
  if (errno != EEXIST)
    return -1;
  if (stat(buf, &st) != 0)
    return -1; /* a dangling or looping link: stat's errno */
  if (S_ISDIR(st.st_mode))
    return 0;
  errno = ENOTDIR;
  return -1;
}

FILE *ver_io_open_tmp(const char *path, char *tmp, size_t len)
{
  /* the pid makes the name this process's own: two writers never share a temporary */
  if (snprintf(tmp, len, "%s.%ld.tmp", path, (long)getpid()) >= (int)len) {
    errno = ENAMETOOLONG;
    return NULL;
  }
  return fopen(tmp, "w");
}

int ver_io_tmp_final(const char *tmp, char *fin, size_t len)
{
  const char *dot = strrchr(tmp, '.');
  const char *p = dot;
  while (p && p > tmp && p[-1] >= '0' && p[-1] <= '9')
    p--;
  if (!dot || strcmp(dot, ".tmp") || p == dot || p <= tmp || p[-1] != '.' || (size_t)(p - 1 - tmp) >= len)
    return -1;
  memcpy(fin, tmp, (size_t)(p - 1 - tmp));
  fin[p - 1 - tmp] = '\0';
  return 0;
}

int ver_io_commit(FILE *f, const char *tmp)
{
  const int bad = ferror(f);
  int e = bad ? (errno ? errno : EIO) : 0;
  if (fclose(f) != 0 && !e)
    e = errno;
  char fin[4096];
  if (!e && ver_io_tmp_final(tmp, fin, sizeof fin) != 0)
    e = EINVAL;
  if (!e && rename(tmp, fin) != 0)
    e = errno;
  if (e) {
    remove(tmp);
    errno = e;
    return -1;
  }
  return 0;
}

int ver_io_write_atomic(const char *path, const char *text)
{
  char tmp[4096];
  FILE *f = ver_io_open_tmp(path, tmp, sizeof tmp);
  if (!f)
    return -1;
  fputs(text, f);
  return ver_io_commit(f, tmp);
}

int ver_io_copy(const char *src, const char *dst)
{
  size_t n = 0;
  char *buf = ver_io_slurp(src, &n, 0);
  if (!buf)
    return -1;
  char tmp[4096];
  FILE *f = ver_io_open_tmp(dst, tmp, sizeof tmp);
  if (!f) {
    free(buf);
    return -1;
  }
  fwrite(buf, 1, n, f);
  free(buf);
  return ver_io_commit(f, tmp);
}

/* Index of the header field name in a CSV header line, or -1. */
static int column(const char *header, const char *name)
{
  int k = 0;
  const size_t n = strlen(name);
  for (const char *s = header; *s; k++) {
    const char *e = s + strcspn(s, ",\r\n");
    if ((size_t)(e - s) == n && !strncmp(s, name, n))
      return k;
    if (*e != ',')
      break;
    s = e + 1;
  }
  return -1;
}

/* Parses one data line into out[j][row] for the wanted fields idx[j]. */
static void csv_row(const char *line, const int *idx, int ncol, double **out, long row)
{
  for (int j = 0; j < ncol; j++)
    out[j][row] = NAN;
  const char *s = line;
  for (int k = 0; *s && *s != '\n'; k++) {
    for (int j = 0; j < ncol; j++)
      if (idx[j] == k) {
        char *end;
        const double v = strtod(s, &end);
        if (end != s)
          out[j][row] = v;
      }
    s += strcspn(s, ",\n");
    if (*s != ',')
      break;
    s++;
  }
}

long ver_csv_read(const char *path, const char *const *cols, int ncol, double **out)
{
  for (int j = 0; j < ncol; j++)
    out[j] = NULL;
  char *txt = ver_io_slurp(path, NULL, 0);
  if (!txt)
    return -1;
  /* leading '#' lines (the schema line of delam's files) come before the header */
  char *head = txt;
  while (*head == '#') {
    char *nl = strchr(head, '\n');
    head = nl ? nl + 1 : head + strlen(head);
  }
  int idx[64];
  long rows = 0;
  for (const char *s = strchr(head, '\n'); s; s = strchr(s + 1, '\n'))
    rows += s[1] != '\0' && s[1] != '\n';
  int ok = ncol <= 64;
  for (int j = 0; ok && j < ncol; j++)
    ok = (idx[j] = column(head, cols[j])) >= 0 && (out[j] = malloc(sizeof(double) * (size_t)(rows + 1)));
  long n = 0;
  for (char *s = strchr(head, '\n'); ok && s && n < rows; s = strchr(s, '\n')) {
    s++;
    if (*s == '\0' || *s == '\n')
      continue;
    csv_row(s, idx, ncol, out, n++);
  }
  free(txt);
  if (!ok) {
    for (int j = 0; j < ncol; j++) {
      free(out[j]);
      out[j] = NULL;
    }
    return -1;
  }
  return n;
}

int ver_io_lock_dir(const char *dir, char *err, size_t errlen)
{
  char path[4200];
  snprintf(path, sizeof path, "%s/" VER_LOCK_NAME, dir);
  const int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int e = errno;
    snprintf(err, errlen, "%s: cannot create: %s", path, strerror(e));
    errno = e;
    return -1;
  }
  /* a POSIX record lock on the whole file: the system drops it when this process ends
   * (however it ends), and F_GETLK names the process that holds it */
  struct flock lk = {.l_type = F_WRLCK, .l_whence = SEEK_SET, .l_start = 0, .l_len = 0};
  if (fcntl(fd, F_SETLK, &lk) == 0)
    return fd;
  const int e = errno;
  struct flock q = {.l_type = F_WRLCK, .l_whence = SEEK_SET, .l_start = 0, .l_len = 0};
  if ((e == EACCES || e == EAGAIN) && fcntl(fd, F_GETLK, &q) == 0 && q.l_type != F_UNLCK)
    snprintf(err, errlen, "%s: another delam process (pid %ld) is writing this folder; wait for it to end or choose "
             "another folder", dir, (long)q.l_pid);
  else if (e == EACCES || e == EAGAIN)
    snprintf(err, errlen, "%s: another delam process is writing this folder; wait for it to end or choose another "
             "folder", dir);
  else
    snprintf(err, errlen, "%s: cannot lock: %s", path, strerror(e));
  close(fd);
  errno = e == EACCES ? EAGAIN : e; /* EAGAIN: held by another process */
  return -1;
}

long ver_io_lock_holder(const char *dir)
{
  char path[4200];
  snprintf(path, sizeof path, "%s/" VER_LOCK_NAME, dir);
  const int fd = open(path, O_RDWR | O_CLOEXEC);
  if (fd < 0)
    return 0;
  struct flock q = {.l_type = F_WRLCK, .l_whence = SEEK_SET, .l_start = 0, .l_len = 0};
  const long pid = fcntl(fd, F_GETLK, &q) == 0 && q.l_type != F_UNLCK ? (long)q.l_pid : 0;
  close(fd);
  return pid;
}

double ver_now_wall(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double ver_now_cpu(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
