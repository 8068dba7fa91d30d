/*
 * check_folder.c - the folder `delam check` judges (check_folder.h): whether delam wrote
 * it, whether the run finished, and the scene it is judged against.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "check_folder.h"
#include "datadir.h"
#include "io.h"

/* The first line of DIR/name starts with prefix (delam's schema line): 1, else 0. */
static int has_schema_line(const char *dir, const char *name, const char *prefix)
{
  char path[1400], head[64] = "";
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = ver_open_regular(path, NULL);
  if (!f)
    return 0;
  if (!fgets(head, sizeof head, f))
    head[0] = '\0';
  fclose(f);
  return !strncmp(head, prefix, strlen(prefix));
}

/* A scene.ini that is there is delam's or must read as a scene; load.csv alone is not
 * taken as delam's: the README's tour makes another code's folder by cutting columns
 * out of delam's load.csv, comment line and all. */
int ver_check_ours(const char *dir)
{
  char path[1400];
  struct stat st;
  snprintf(path, sizeof path, "%s/scene.ini", dir);
  return lstat(path, &st) == 0 || has_schema_line(dir, "energy.csv", "# delam energy.csv") ||
         has_schema_line(dir, "final.csv", "# delam particles.csv");
}

/* s for a one-line message: control bytes (a newline in a run's error) shown as '?'. */
static const char *shown_line(const char *s, char *buf, size_t len)
{
  snprintf(buf, len, "%s", s);
  for (char *p = buf; *p; p++)
    if ((unsigned char)*p < 0x20 || *p == 0x7f)
      *p = '?';
  return buf;
}

/* What "complete" holds when it is not true, for a message: the JSON text of the value. */
static void json_shown(const cJSON *v, char *buf, size_t len)
{
  char *t = cJSON_PrintUnformatted(v);
  char line[64];
  snprintf(buf, len, "%s%s", shown_line(t ? t : "?", line, sizeof line), t && strlen(t) > 60 ? "..." : "");
  free(t);
}

/* The lock, then summary.json read whole (cJSON_ParseWithOpts: nothing may follow the object). */
int ver_check_finished(const char *dir, int ours, char *scene, size_t slen, char *err, size_t errlen)
{
  char path[1400];
  scene[0] = '\0';
  const long holder = ver_io_lock_holder(dir);
  if (holder > 0) {
    snprintf(err, errlen, "%s: a delam process (pid %ld) is writing this folder now: not judged", dir, holder);
    return 2;
  }
  snprintf(path, sizeof path, "%s/summary.json", dir);
  struct stat st;
  if (lstat(path, &st) != 0) {
    if (!ours)
      return 0;
    snprintf(path, sizeof path, "%s/scene.ini", dir);
    snprintf(err, errlen, "%s: delam's %s but no summary.json: the run has not finished (killed, or it failed to "
             "write it); not judged", dir, lstat(path, &st) == 0 ? "scene.ini" : "files (energy.csv or final.csv "
             "with its schema line)");
    return 2;
  }
  size_t len = 0;
  char *txt = ver_io_slurp(path, &len, 1 << 20);
  if (!txt) {
    const int e = errno;
    if (e == EINVAL && stat(path, &st) == 0)
      snprintf(err, errlen, "%s: %s, not a regular file: the run's record is damaged; not judged", path,
               ver_file_kind(st.st_mode));
    else if (e == EFBIG)
      snprintf(err, errlen, "%s: larger than 1 MiB (delam writes about 4 KiB): not a run's record; not judged", path);
    else
      snprintf(err, errlen, "%s: cannot read: %s; not judged", path, strerror(e));
    return 2;
  }
  const char *end = NULL;
  cJSON *o = cJSON_ParseWithOpts(txt, &end, 1); /* the whole file, nothing after it */
  if (!o || !cJSON_IsObject(o)) {
    const size_t at = o ? 0 : end ? (size_t)(end - txt) : len;
    if (!o && strlen(txt) < len)
      snprintf(err, errlen, "%s: a NUL byte at byte %zu: not JSON text; the run's record is damaged, not judged",
               path, strlen(txt) + 1);
    else if (!o)
      snprintf(err, errlen, "%s: not whole JSON (%s %zu of its %zu bytes): the run's record is damaged or cut "
               "short; not judged", path, at >= len ? "it ends before the JSON does, after" : "unexpected text at byte",
               at >= len ? len : at + 1, len);
    else
      snprintf(err, errlen, "%s: JSON but not an object: the run's record is damaged; not judged", path);
    cJSON_Delete(o);
    free(txt);
    return 2;
  }
  free(txt);
  const cJSON *c = cJSON_GetObjectItemCaseSensitive(o, "complete");
  const cJSON *un = cJSON_GetObjectItemCaseSensitive(o, "unstable");
  const cJSON *made = cJSON_GetObjectItemCaseSensitive(o, "energy_created");
  const cJSON *d = cJSON_GetObjectItemCaseSensitive(o, "delta_end");
  const cJSON *e = cJSON_GetObjectItemCaseSensitive(o, "error");
  const cJSON *s = cJSON_GetObjectItemCaseSensitive(o, "scene");
  if (cJSON_IsString(s))
    snprintf(scene, slen, "%s", s->valuestring);
  int rc = 2;
  char shown[80], line[304];
  if (cJSON_IsFalse(c))
    snprintf(err, errlen, "%s says complete: false (the run stopped at delta %.6g%s%.300s): an interrupted or "
             "failed run is not judged", path, cJSON_IsNumber(d) ? d->valuedouble : NAN,
             cJSON_IsString(e) ? ": " : "", cJSON_IsString(e) ? shown_line(e->valuestring, line, sizeof line) : "");
  else if (c && !cJSON_IsTrue(c)) {
    json_shown(c, shown, sizeof shown);
    snprintf(err, errlen, "%s: \"complete\" is %s, not true: the run's record is damaged; not judged", path, shown);
  } else if (!c && ours)
    snprintf(err, errlen, "%s: no \"complete\" key: the run's record is damaged; not judged", path);
  else if (cJSON_IsTrue(un))
    snprintf(err, errlen, "%s says unstable: true (the run made energy, %.3g of the largest work, and ran on under "
             "--allow-unstable): not judged", path, cJSON_IsNumber(made) ? made->valuedouble : NAN);
  else
    rc = 0;
  cJSON_Delete(o);
  return rc;
}

/* The scene SCENE with --method, --h, --ppc and --set; where delam wrote the folder
 * (own, its scene.ini; else NULL), the run's h, ppc, method and solver where no option
 * gives them. */
static int build_scene(const char *arg, const ver_scene *own, const char *method, double h, double ppc,
                       const char *const *sets, int nset, ver_scene *vs, char *err, size_t errlen)
{
  char path[4400], buf[160], num[40];
  if (ver_scene_resolve(arg, path, sizeof path, err, errlen) || ver_scene_parse(path, vs, err, errlen))
    return 2;
  if (own) {
    if (h <= 0)
      h = own->sc.h;
    if (ppc <= 0)
      ppc = own->sc.ppc;
    /* rows of equilibrium states, not interval averages: judged as such */
    if (own->sc.solver == MPM_SOLVER_STATIC && ver_scene_set(vs, "solver.type=static", err, errlen))
      return 2;
    if (!method && own->preset >= 0 && own->preset != vs->preset)
      method = ver_method_name(own->preset); /* the run's --method */
  }
  if (method) {
    snprintf(buf, sizeof buf, "method.preset=%s", method);
    if (ver_scene_set(vs, buf, err, errlen))
      return 2;
  }
  if (h > 0) {
    ver_scene_fmt_num(vs->sc.dt * h / vs->sc.h, num, sizeof num); /* the file's Courant number */
    snprintf(buf, sizeof buf, "time.dt=%s", num);
    if (ver_scene_set(vs, buf, err, errlen))
      return 2;
    ver_scene_fmt_num(h, num, sizeof num);
    snprintf(buf, sizeof buf, "grid.h=%s", num);
    if (ver_scene_set(vs, buf, err, errlen))
      return 2;
  }
  if (ppc > 0) {
    ver_scene_fmt_num(ppc, num, sizeof num);
    snprintf(buf, sizeof buf, "grid.ppc=%s", num);
    if (ver_scene_set(vs, buf, err, errlen))
      return 2;
  }
  for (int i = 0; i < nset; i++)
    if (ver_scene_set(vs, sets[i], err, errlen))
      return 2;
  vs->allow_unstable = 1; /* nothing is run here */
  return ver_scene_validate(vs, err, errlen);
}

/* The keys a check's reference or measurement reads (scene_bar.c: the closed-form bar;
 * policy.c: the classes and tolerances; foreign.c, sweep_cases.c: the separation
 * window, the wave solution, the grip's direction).  A folder's scene.ini that differs
 * from the scene given on one of them was another problem: judging it against that
 * scene would report the difference as the run's error. */
static const char *const REF_KEYS[] = {
  "bar.L", "bar.H", "material.E", "material.nu", "material.rho", "decohesion.model", "decohesion.alpha",
  "decohesion.snf", "decohesion.stf", "decohesion.U0", "decohesion.s0", "decohesion.q", "decohesion.separation",
  "decohesion.Le", "decohesion.path", "imperfection.x", "grid.h", "grid.ppc", "grid.fields", "loading.control",
  "loading.speed", "run.sep_load", "solver.type", "vibration.mode",
};

/* The effective scene's text (ver_scene_write_ini, every key with its value); malloc'd. */
static char *scene_text(const ver_scene *vs)
{
  char *txt = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&txt, &len);
  if (!f)
    return NULL;
  const int bad = ver_scene_write_ini(vs, f);
  if (fclose(f) || bad) {
    free(txt);
    return NULL;
  }
  return txt;
}

/* The value of "section.key" in a scene's text into out ("" if it has none). */
static void scene_value(const char *txt, const char *skey, char *out, size_t len)
{
  const char *dot = strchr(skey, '.');
  const size_t sl = (size_t)(dot - skey), kl = strlen(dot + 1);
  int in = 0;
  out[0] = '\0';
  for (const char *l = txt; l && *l; l = strchr(l, '\n'), l = l ? l + 1 : NULL) {
    const size_t ll = strcspn(l, "\n");
    if (*l == '[')
      in = ll == sl + 2 && !strncmp(l + 1, skey, sl) && l[sl + 1] == ']';
    else if (in && !strncmp(l, dot + 1, kl) && !strncmp(l + kl, " = ", 3)) {
      snprintf(out, len, "%.*s", (int)(ll - kl - 3), l + kl + 3);
      return;
    }
  }
}

/* The REF_KEYS on which scene a (the one given) and b (the folder's scene.ini) differ,
 * as "key (A in ANAME, B in the run)" into out; how many (-1: out of memory). */
static int scene_diff(const ver_scene *a, const char *aname, const ver_scene *b, char *out, size_t len)
{
  char *ta = scene_text(a), *tb = scene_text(b), va[64], vb[64];
  int n = 0;
  out[0] = '\0';
  if (!ta || !tb)
    n = -1;
  for (size_t i = 0; n >= 0 && i < sizeof REF_KEYS / sizeof REF_KEYS[0]; i++) {
    scene_value(ta, REF_KEYS[i], va, sizeof va);
    scene_value(tb, REF_KEYS[i], vb, sizeof vb);
    if (strcmp(va, vb)) {
      const size_t at = strlen(out);
      snprintf(out + at, len - at, "%s%s (%s in %s, %s in the run)", n ? "; " : "", REF_KEYS[i], va[0] ? va : "none",
               aname, vb[0] ? vb : "none");
      n++;
    }
  }
  free(ta);
  free(tb);
  return n;
}

int ver_check_scene(const ver_check_opts *o, const char *summary_scene, ver_scene *vs, char *err, size_t errlen)
{
  char own[1400];
  struct stat st;
  snprintf(own, sizeof own, "%s/scene.ini", o->dir);
  if (lstat(own, &st) != 0) {
    if (!o->scene) {
      snprintf(err, errlen, "%s has no scene.ini (another code's folder): needs --scene SCENE, the scene it was "
               "meant to compute (usage: delam check [--scene SCENE] DIR)", o->dir);
      return 2;
    }
    return build_scene(o->scene, NULL, o->method, o->h, o->ppc, o->sets, o->nset, vs, err, errlen);
  }
  static ver_scene run, given; /* large */
  if (ver_scene_parse(own, &run, err, errlen))
    return 2; /* there but unreadable: not silently judged as another case */
  run.allow_unstable = 1;
  if (ver_scene_validate(&run, err, errlen))
    return 2;
  if (o->scene || o->method || o->h > 0 || o->ppc > 0 || o->nset > 0) {
    if (build_scene(o->scene ? o->scene : own, &run, o->method, o->h, o->ppc, o->sets, o->nset, &given, err, errlen))
      return 2;
    char diff[2400], gname[160];
    const int opts = o->nset || o->method || o->h > 0 || o->ppc > 0;
    snprintf(gname, sizeof gname, "%s%s", o->scene ? given.name : "the options", o->scene && opts ? " with the options" : "");
    const int nd = scene_diff(&given, gname, &run, diff, sizeof diff);
    if (nd) {
      if (nd < 0)
        snprintf(err, errlen, "%s: out of memory comparing it with the scene given", own);
      else
        snprintf(err, errlen, "%s: the run computed another problem than %s, on %d key%s that change%s a "
                 "reference: %s; judge it against its own scene with `delam check %s`", own, gname, nd,
                 nd > 1 ? "s" : "", nd > 1 ? "" : "s", diff, o->dir);
      return 2;
    }
  }
  *vs = run;
  /* the scene's name in the labels: the one given, else the run's own (summary.json) */
  snprintf(vs->name, sizeof vs->name, "%s", o->scene ? given.name : summary_scene[0] ? summary_scene : run.name);
  return 0;
}

