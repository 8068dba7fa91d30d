/*
 * io.c - whole-file reads, atomic writes, mkdir -p, CSV columns by header, clocks
 * (io.h).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

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
  return (mkdir(buf, 0777) != 0 && errno != EEXIST) ? -1 : 0;
}

FILE *ver_io_open_tmp(const char *path, char *tmp, size_t len)
{
  if (snprintf(tmp, len, "%s.tmp", path) >= (int)len) {
    errno = ENAMETOOLONG;
    return NULL;
  }
  return fopen(tmp, "w");
}

int ver_io_commit(FILE *f, const char *tmp)
{
  const int bad = ferror(f);
  if (fclose(f) != 0 || bad) {
    remove(tmp);
    return -1;
  }
  char fin[4096];
  const size_t n = strlen(tmp);
  if (n < 5 || n >= sizeof fin) {
    remove(tmp);
    return -1;
  }
  memcpy(fin, tmp, n - 4);
  fin[n - 4] = '\0';
  if (rename(tmp, fin) != 0) {
    remove(tmp);
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
