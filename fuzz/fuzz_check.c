/*
 * fuzz_check.c - libFuzzer target for the readers of `delam check` (verify/foreign.c's
 * CSV reader, verify/check_folder.c's summary.json reader).
 *
 * The input's first byte chooses the reader (even: a load.csv, odd: a summary.json) and
 * the rest is the file.  Besides the sanitizers, it checks their contracts: a CSV read
 * gives 0 with at least 3 rows of finite numbers, or 2 with one line naming the file; a
 * summary.json is accepted only if it is one whole JSON object whose "complete" is true
 * (decided here again with cJSON, independently), else refused with one line naming it.
 * Built and run by `make fuzz-check`.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "check_folder.h"
#include "foreign.h"

static char dir[64];

/* Writes data to dir/name; 0 or -1. */
static int put(const char *name, const uint8_t *data, size_t size)
{
  char path[128];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "wb");
  if (!f)
    return -1;
  const size_t w = fwrite(data, 1, size, f);
  return fclose(f) == 0 && w == size ? 0 : -1;
}

/* Aborts unless err is one line that starts with prefix. */
static void one_line(const char *err, const char *prefix)
{
  if (!err[0] || strchr(err, '\n') || strncmp(err, prefix, strlen(prefix)))
    abort();
}

static void fuzz_csv(const uint8_t *data, size_t size)
{
  static const char *const names[] = {"delta", "P_grip", "P_fixed", "t"};
  char path[128], err[600] = "";
  snprintf(path, sizeof path, "%s/load.csv", dir);
  if (put("load.csv", data, size))
    return;
  ver_table t;
  const int rc = ver_table_read(path, names, 4, 2, &t, err, sizeof err);
  if (rc == 0) {
    if (t.n < 3 || !t.col[0] || !t.col[1])
      abort();
    for (long i = 0; i < t.n; i++)
      for (int j = 0; j < 4; j++)
        if (t.col[j] && !isfinite(t.col[j][i]))
          abort();
    ver_table_free(&t);
  } else if (rc == 2)
    one_line(err, path);
  else
    abort(); /* the file is there: 1 (no such file) is wrong */
}

static void fuzz_summary(const uint8_t *data, size_t size)
{
  char err[4800] = "", scene[64], path[128];
  snprintf(path, sizeof path, "%s/summary.json", dir);
  if (put("summary.json", data, size))
    return;
  const int rc = ver_check_finished(dir, 1, scene, sizeof scene, err, sizeof err);
  /* the contract, decided here: a whole JSON object, "complete" literally true */
  char *txt = malloc(size + 1);
  if (!txt)
    return;
  memcpy(txt, data, size);
  txt[size] = '\0';
  const char *end = NULL;
  cJSON *o = memchr(data, 0, size) ? NULL : cJSON_ParseWithOpts(txt, &end, 1);
  const int ok = o && cJSON_IsObject(o) && cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(o, "complete"));
  cJSON_Delete(o);
  free(txt);
  if (ok != (rc == 0))
    abort();
  if (rc)
    one_line(err, path);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (!dir[0]) {
    snprintf(dir, sizeof dir, "/tmp/fuzz-check.%ld", (long)getpid());
    char cmd[96];
    snprintf(cmd, sizeof cmd, "mkdir -p %s", dir);
    if (system(cmd) != 0)
      abort();
  }
  if (size == 0)
    return 0;
  if (data[0] % 2 == 0)
    fuzz_csv(data + 1, size - 1);
  else
    fuzz_summary(data + 1, size - 1);
  return 0;
}
