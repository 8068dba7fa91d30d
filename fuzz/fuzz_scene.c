/*
 * fuzz_scene.c - libFuzzer target for the scene parser and validator (verify/scene.c).
 *
 * The input is a scene file.  Comment lines ";set S.K=V" in it are also applied as
 * command-line overrides (ver_scene_set), so that one corpus covers both ways in.
 * Besides the sanitizers, it checks the contract of scene.h: a refused scene gives
 * status 2 and one line "fuzz.ini:LINE: ..." (or "fuzz.ini: command line: ..."), with
 * LINE inside the file; an accepted scene passes the kernel's own check.
 * Built and run by `make fuzz`.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

#define NAME "fuzz.ini"

/* Aborts (a crash for libFuzzer) unless err is one well-formed message. */
static void check_message(const char *err, int nlines)
{
  const size_t n = strlen(NAME);
  if (!err[0] || strchr(err, '\n') || strncmp(err, NAME, n) != 0)
    abort();
  if (!strncmp(err + n, ": command line: ", 16))
    return;
  if (err[n] != ':')
    abort();
  char *end;
  const long line = strtol(err + n + 1, &end, 10);
  if (line < 1 || line > nlines + 1 || strncmp(end, ": ", 2) != 0)
    abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size > 1 << 16)
    return 0;
  char *text = malloc(size + 1);
  if (!text)
    return 0;
  memcpy(text, data, size);
  text[size] = '\0';
  int nlines = 1;
  for (const char *p = text; *p; p++)
    nlines += *p == '\n';

  ver_scene vs;
  char err[1024] = "";
  int r = ver_scene_parse_string(text, NAME, &vs, err, sizeof err);
  for (const char *p = text; !r && (p = strstr(p, ";set ")) != NULL; p += 5) {
    char set[300];
    const size_t len = strcspn(p + 5, "\n");
    if (len >= sizeof set)
      continue;
    memcpy(set, p + 5, len);
    set[len] = '\0';
    r = ver_scene_set(&vs, set, err, sizeof err);
  }
  if (!r)
    r = ver_scene_validate(&vs, err, sizeof err);
  if (r) {
    if (r != 2)
      abort();
    check_message(err, nlines);
  } else {
    char e2[256], id[128];
    if (mpm_scene_check(&vs.sc, e2, sizeof e2) != MPM_OK || !(vs.sc.dt > 0) || vs.nsnap > VER_MAX_SNAP)
      abort();
    ver_scene_case_id(&vs, id, sizeof id);
  }
  free(text);
  return 0;
}
