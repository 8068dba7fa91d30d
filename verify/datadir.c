/*
 * datadir.c - finding the scene files and opening them (datadir.h).
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "datadir.h"
#include "delam_config.h"

const char *ver_file_kind(unsigned mode)
{
  return S_ISDIR(mode)   ? "a directory"
         : S_ISFIFO(mode) ? "a FIFO"
         : S_ISCHR(mode)  ? "a character device"
         : S_ISBLK(mode)  ? "a block device"
         : S_ISSOCK(mode) ? "a socket"
         : S_ISREG(mode)  ? "a regular file"
                          : "not a regular file";
}

FILE *ver_open_regular(const char *path, const char **what)
{
  if (what)
    *what = NULL;
  /* O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer */
  const int fd = open(path, O_RDONLY | O_NONBLOCK);
  if (fd < 0)
    return NULL;
  struct stat st;
  const int e = fstat(fd, &st) != 0 ? errno : S_ISREG(st.st_mode) ? 0 : EINVAL;
  if (e) {
    if (e == EINVAL && what)
      *what = ver_file_kind(st.st_mode);
    close(fd);
    errno = e;
    return NULL;
  }
  const int fl = fcntl(fd, F_GETFL);
  FILE *f = fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) < 0 ? NULL : fdopen(fd, "rb");
  if (!f) {
    const int fe = errno;
    close(fd);
    errno = fe;
  }
  return f;
}

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

static int exists(const char *p)
{
  struct stat st;
  return stat(p, &st) == 0;
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
  if (exists(arg) || strchr(arg, '/')) {
    /* a path: the scene reader names it if it is missing or not a regular file */
    snprintf(out, len, "%s", arg);
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
