/*
 * datadir.c - finding the scene files (datadir.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "datadir.h"
#include "delam_config.h"

static int is_dir(const char *p)
{
  struct stat st;
  return p && *p && stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

static int is_file(const char *p)
{
  struct stat st;
  return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

/* <folder of the running program>/../share/delam/scenes, or "" */
static void exe_relative(char *out, size_t len)
{
  char exe[4096];
  out[0] = '\0';
  const ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (k <= 0)
    return;
  exe[k] = '\0';
  char *slash = strrchr(exe, '/');
  if (!slash)
    return;
  *slash = '\0';
  snprintf(out, len, "%.4000s/../share/delam/scenes", exe);
}

const char *ver_report_dir(void)
{
  static char found[4200]; /* holds the answer; valid until the next call */
  const char *env = getenv("DELAM_REPORTS");
  if (is_dir(env)) {
    snprintf(found, sizeof found, "%s", env);
    return found;
  }
  if (is_file("reports/common.gp"))
    return "reports";
  exe_relative(found, sizeof found);
  char *scenes = strstr(found, "/scenes");
  if (scenes) {
    snprintf(scenes, sizeof found - (size_t)(scenes - found), "/reports");
    if (is_dir(found))
      return found;
  }
  if (is_dir(DELAM_INSTALLED_REPORTS))
    return DELAM_INSTALLED_REPORTS;
  if (is_dir(DELAM_SOURCE_REPORTS))
    return DELAM_SOURCE_REPORTS;
  return NULL;
}

const char *ver_scene_dir(void)
{
  /* holds the answer; valid until the next call */
  static char found[4200];
  const char *env = getenv("DELAM_SCENES");
  if (is_dir(env)) {
    snprintf(found, sizeof found, "%s", env);
    return found;
  }
  if (is_dir("data/scenes"))
    return "data/scenes";
  exe_relative(found, sizeof found);
  if (is_dir(found))
    return found;
  if (is_dir(DELAM_INSTALLED_SCENES))
    return DELAM_INSTALLED_SCENES;
  if (is_dir(DELAM_SOURCE_SCENES))
    return DELAM_SOURCE_SCENES;
  return NULL;
}

int ver_scene_resolve(const char *arg, char *out, size_t len, char *err, size_t errlen)
{
  if (is_file(arg) || strchr(arg, '/')) {
    snprintf(out, len, "%s", arg); /* a path: the scene reader names it if it is missing */
    return 0;
  }
  const char *dir = ver_scene_dir();
  const size_t n = strlen(arg);
  const char *ext = n > 4 && !strcmp(arg + n - 4, ".ini") ? "" : ".ini";
  if (dir) {
    snprintf(out, len, "%s/%s%s", dir, arg, ext);
    if (is_file(out))
      return 0;
  }
  snprintf(err, errlen,
           "%s: no such file, and no scene %s%s in the scene folder (%s; tried $DELAM_SCENES, "
           "./data/scenes, <program>/../share/delam/scenes, %s, %s)",
           arg, arg, ext, dir ? dir : "none found", DELAM_INSTALLED_SCENES, DELAM_SOURCE_SCENES);
  return 2;
}
