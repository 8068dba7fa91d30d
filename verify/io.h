/*
 * io.h - the file and clock helpers every part of verify/ uses (prefix ver_io_):
 * whole-file reads, writes that leave nothing half-written (a temporary name, then
 * rename), mkdir -p, numeric CSV columns picked by their header name, file copies,
 * and the two clocks (monotonic wall time, process CPU time).
 */
#ifndef DELAM_VER_IO_H
#define DELAM_VER_IO_H

#include <stddef.h>
#include <stdio.h>

/* The whole file of a regular file, NUL-terminated (malloc'd; caller frees); *len (if
 * not NULL) gets its size.  NULL with errno set if it cannot be read, EINVAL if it is not
 * a regular file, EFBIG if it is larger than max bytes (max 0: no limit). */
char *ver_io_slurp(const char *path, size_t *len, size_t max);

/* mkdir -p; 0 or -1 with errno set (ENOTDIR where the path or a part of it is there
 * as something other than a folder). */
int ver_mkdir_p(const char *dir);

/* Opens path.<pid>.tmp for writing (the name goes to tmp); ver_io_commit closes it and
 * renames it to path if every write succeeded, else removes it.  0, or -1 with errno
 * (that of the first failure: a write, the close or the rename). */
FILE *ver_io_open_tmp(const char *path, char *tmp, size_t len);
int ver_io_commit(FILE *f, const char *tmp);
/* The name a temporary of ver_io_open_tmp is committed to (tmp less ".<pid>.tmp") into
 * fin; 0, or -1 if tmp is no such name. */
int ver_io_tmp_final(const char *tmp, char *fin, size_t len);
/* Writes text to path the same way.  0 or -1. */
int ver_io_write_atomic(const char *path, const char *text);
/* Copies src to dst (through dst.tmp).  0 or -1. */
int ver_io_copy(const char *src, const char *dst);

/* One writer per folder: locks DIR/.delam.lock (created if missing) for this process
 * until it closes the returned descriptor or ends.  The descriptor, or -1 with err:
 * "DIR: another delam process (pid N) is writing this folder ..." and errno EAGAIN when
 * another holds it. */
#define VER_LOCK_NAME ".delam.lock"
int ver_io_lock_dir(const char *dir, char *err, size_t errlen);
/* The pid of the process that holds DIR's lock now, 0 if none. */
long ver_io_lock_holder(const char *dir);

/* Numeric CSV with a header line: the columns named in cols (ncol of them), as malloc'd
 * arrays out[0..ncol-1] (caller frees each; NULL on failure).  A field that is not a
 * number reads as NaN.  Returns the number of rows; -1 if the file cannot be read or
 * lacks one of the columns. */
long ver_csv_read(const char *path, const char *const *cols, int ncol, double **out);

/* Seconds on the monotonic clock and of CPU time used by this process. */
double ver_now_wall(void);
double ver_now_cpu(void);

#endif
