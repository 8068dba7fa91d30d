/*
 * summary.c - summary.json written and read by the same table of fields (summary.h).
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "build_info.h"
#include "io.h"
#include "summary.h"

/* The numbers of ver_summary, by their JSON name. */
enum { F_DBL, F_LONG, F_SIZE };
static const struct {
  const char *key;
  size_t off;
  int kind;
} NUMS[] = {
  {"peak_P", offsetof(ver_summary, peak_P), F_DBL},
  {"delta_peak", offsetof(ver_summary, delta_peak), F_DBL},
  {"delta_sep", offsetof(ver_summary, delta_sep), F_DBL},
  {"delta_sep_cut", offsetof(ver_summary, delta_sep_cut), F_DBL},
  {"delta_sep_load", offsetof(ver_summary, delta_sep_load), F_DBL},
  {"k_elastic", offsetof(ver_summary, k_elastic), F_DBL},
  {"D_final", offsetof(ver_summary, D_final), F_DBL},
  {"D_cut", offsetof(ver_summary, D_cut), F_DBL},
  {"D_after_cut", offsetof(ver_summary, D_after_cut), F_DBL},
  {"W_ext_final", offsetof(ver_summary, W_ext_final), F_DBL},
  {"W_coh_final", offsetof(ver_summary, W_coh_final), F_DBL},
  {"KE_final", offsetof(ver_summary, KE_final), F_DBL},
  {"SE_final", offsetof(ver_summary, SE_final), F_DBL},
  {"energy_residual", offsetof(ver_summary, energy_residual), F_DBL},
  {"energy_unbooked", offsetof(ver_summary, energy_unbooked), F_DBL},
  {"energy_created", offsetof(ver_summary, energy_created), F_DBL},
  {"L_bc_final", offsetof(ver_summary, L_bc_final), F_DBL},
  {"L_flip_final", offsetof(ver_summary, L_flip_final), F_DBL},
  {"L_scheme_final", offsetof(ver_summary, L_scheme_final), F_DBL},
  {"W_head_final", offsetof(ver_summary, W_head_final), F_DBL},
  {"L_contact_final", offsetof(ver_summary, L_contact_final), F_DBL},
  {"L_debris_final", offsetof(ver_summary, L_debris_final), F_DBL},
  {"L_damp_final", offsetof(ver_summary, L_damp_final), F_DBL},
  {"energy_start", offsetof(ver_summary, energy_start), F_DBL},
  {"energy_kept", offsetof(ver_summary, energy_kept), F_DBL},
  {"period", offsetof(ver_summary, period), F_DBL},
  {"period_exact", offsetof(ver_summary, period_exact), F_DBL},
  {"period_error", offsetof(ver_summary, period_error), F_DBL},
  {"delta_end", offsetof(ver_summary, delta_end), F_DBL},
  {"steps", offsetof(ver_summary, steps), F_LONG},
  {"particles", offsetof(ver_summary, particles), F_SIZE},
  {"n_soften", offsetof(ver_summary, n_soften), F_LONG},
  {"n_separate", offsetof(ver_summary, n_separate), F_LONG},
  {"n_bracketed", offsetof(ver_summary, n_bracketed), F_LONG},
  {"n_debris", offsetof(ver_summary, n_debris), F_LONG},
  {"crack_tip_final", offsetof(ver_summary, crack_tip_final), F_DBL},
  {"gap_min", offsetof(ver_summary, gap_min), F_DBL},
  {"wall_s", offsetof(ver_summary, wall_s), F_DBL},
  {"cpu_s", offsetof(ver_summary, cpu_s), F_DBL},
  {"updates_per_s", offsetof(ver_summary, updates_per_s), F_DBL},
  {"increments", offsetof(ver_summary, increments), F_LONG},
  {"newton", offsetof(ver_summary, newton), F_LONG},
  {"factorizations", offsetof(ver_summary, factorizations), F_LONG},
  {"updates", offsetof(ver_summary, updates), F_LONG},
  {"cuts", offsetof(ver_summary, cuts), F_LONG},
  {"severed", offsetof(ver_summary, severed), F_LONG},
  {"t_eval", offsetof(ver_summary, t_eval), F_DBL},
  {"t_factor", offsetof(ver_summary, t_factor), F_DBL},
  {"t_solve", offsetof(ver_summary, t_solve), F_DBL},
};
#define NNUMS (sizeof NUMS / sizeof NUMS[0])

/* The run's method: its preset, where that was named, and the method keys that differ
 * from it (from the file or the command line). */
static void add_method(cJSON *o, const ver_scene *vs)
{
  cJSON *m = cJSON_AddObjectToObject(o, "method");
  cJSON_AddStringToObject(m, "preset", ver_method_name(vs->preset));
  cJSON_AddStringToObject(m, "named_in", ver_method_where(vs));
  char diff[32][64];
  const int n = ver_method_overrides(vs, diff, 32);
  cJSON *d = cJSON_AddArrayToObject(m, "differs");
  for (int i = 0; i < n; i++)
    cJSON_AddItemToArray(d, cJSON_CreateString(diff[i]));
}

/* The static path's critical points (docs/static.md, "Stability"): each the first
 * increment past it, its delta and load, and its kind. */
static void add_critical(cJSON *o, const ver_summary *u)
{
  static const char *const kind[] = {"", "tie of a uniform state", "limit point", "bifurcation"};
  cJSON_AddNumberToObject(o, "critical_points_total", (double)u->ncrit);
  cJSON *a = cJSON_AddArrayToObject(o, "critical_points");
  for (long i = 0; i < u->ncrit && i < VER_CRIT_MAX; i++) {
    cJSON *c = cJSON_CreateObject();
    cJSON_AddNumberToObject(c, "increment", (double)u->crit[i].increment);
    cJSON_AddNumberToObject(c, "delta", u->crit[i].delta);
    cJSON_AddNumberToObject(c, "P", u->crit[i].P);
    const int k = u->crit[i].kind;
    cJSON_AddStringToObject(c, "kind", k >= 1 && k <= 3 ? kind[k] : "unknown");
    cJSON_AddItemToArray(a, c);
  }
}

int ver_summary_write(const char *dir, const ver_scene *vs, const ver_summary *u, const char *errmsg)
{
  cJSON *o = cJSON_CreateObject();
  char id[600];
  ver_scene_case_id(vs, id, sizeof id);
  cJSON_AddNumberToObject(o, "schema", VER_SCHEMA_SUMMARY);
  cJSON_AddStringToObject(o, "case", id);
  cJSON_AddStringToObject(o, "scene", vs->name);
  cJSON_AddStringToObject(o, "scene_file", vs->path);
  cJSON_AddNumberToObject(o, "h", vs->sc.h);
  cJSON_AddNumberToObject(o, "ppc", vs->sc.ppc);
  cJSON_AddNumberToObject(o, "dt", vs->sc.dt);
  /* the words of the scene files (one table, scene.c) */
  cJSON_AddStringToObject(o, "Le", ver_scene_word(vs, "decohesion", "Le"));
  cJSON_AddStringToObject(o, "fields", ver_scene_word(vs, "grid", "fields"));
  cJSON_AddStringToObject(o, "scheme", ver_scene_word(vs, "time", "scheme"));
  cJSON_AddStringToObject(o, "bc", ver_scene_word(vs, "grid", "bc"));
  cJSON_AddStringToObject(o, "shape", ver_scene_word(vs, "grid", "shape"));
  cJSON_AddStringToObject(o, "solver", ver_scene_word(vs, "solver", "type"));
  cJSON_AddNumberToObject(o, "separation_threshold", vs->sc.sep_threshold);
  cJSON_AddNumberToObject(o, "damping", vs->sc.damping);
  cJSON_AddNumberToObject(o, "damping_beta", vs->sc.damping_beta);
  cJSON_AddNumberToObject(o, "speed", vs->sc.speed);
  cJSON_AddStringToObject(o, "damping_from", ver_scene_word(vs, "time", "damping_from"));
  cJSON_AddStringToObject(o, "damping_about", ver_scene_word(vs, "time", "damping_about"));
  /* how the rate was given: "critical" (set from the bar, 2 pi sqrt(E / rho) / L) or "rate" */
  cJSON_AddStringToObject(o, "damping_rule", vs->damping_critical ? "critical" : "rate");
  cJSON_AddStringToObject(o, "path", ver_scene_word(vs, "decohesion", "path"));
  cJSON_AddStringToObject(o, "reversed_shear", ver_scene_word(vs, "decohesion", "reversed_shear"));
  cJSON_AddStringToObject(o, "motion", ver_scene_word(vs, "grid", "motion"));
  cJSON_AddNumberToObject(o, "path_reach", vs->sc.path_reach);
  cJSON_AddBoolToObject(o, "complete", u->complete);
  if (u->unstable)
    cJSON_AddBoolToObject(o, "unstable", 1);
  if (errmsg && errmsg[0])
    cJSON_AddStringToObject(o, "error", errmsg);
  for (size_t i = 0; i < NNUMS; i++) {
    const char *p = (const char *)u + NUMS[i].off;
    double v;
    if (NUMS[i].kind == F_DBL)
      memcpy(&v, p, sizeof v);
    else if (NUMS[i].kind == F_LONG) {
      long l;
      memcpy(&l, p, sizeof l);
      v = (double)l;
    } else {
      size_t z;
      memcpy(&z, p, sizeof z);
      v = (double)z;
    }
    cJSON_AddNumberToObject(o, NUMS[i].key, v);
  }
  if (u->static_run)
    add_critical(o, u);
  /* provenance: what reproduces the run, and what built the program */
  cJSON_AddStringToObject(o, "version", ver_build_version());
  cJSON_AddStringToObject(o, "compiler", ver_build_compiler());
  cJSON_AddStringToObject(o, "flags", ver_build_flags());
  cJSON *th = cJSON_AddObjectToObject(o, "threads");
  cJSON_AddStringToObject(th, "requested", u->threads_req > 0 ? "fixed" : "auto");
  cJSON_AddNumberToObject(th, "max", u->threads_max);
  cJSON_AddNumberToObject(th, "steps_multi", (double)u->steps_multi);
  cJSON_AddNumberToObject(th, "probes", (double)u->probes);
  cJSON_AddNumberToObject(th, "probes_skipped_busy", (double)u->probes_busy);
  cJSON *ov = cJSON_AddArrayToObject(o, "overrides");
  for (int i = 0; i < vs->nover; i++)
    cJSON_AddItemToArray(ov, cJSON_CreateString(vs->over[i]));
  add_method(o, vs);
  char *ini = NULL;
  size_t inilen = 0;
  FILE *mf = open_memstream(&ini, &inilen);
  if (mf) {
    const int bad = ver_scene_write_ini(vs, mf);
    fclose(mf);
    if (!bad && ini)
      cJSON_AddStringToObject(o, "effective_scene", ini);
  }
  free(ini);
  char *txt = cJSON_Print(o);
  cJSON_Delete(o);
  if (!txt)
    return -1;
  char path[1200], tmp[1300];
  snprintf(path, sizeof path, "%s/summary.json", dir);
  FILE *f = ver_io_open_tmp(path, tmp, sizeof tmp);
  if (!f) {
    free(txt);
    return -1;
  }
  fputs(txt, f);
  fputc('\n', f);
  free(txt);
  return ver_io_commit(f, tmp);
}

static double jnum(const cJSON *o, const char *key)
{
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
  return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static void jstr(const cJSON *o, const char *key, char *dst, size_t len)
{
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
  snprintf(dst, len, "%s", cJSON_IsString(v) ? v->valuestring : "");
}

int ver_summary_read(const char *dir, ver_summary_doc *d)
{
  char path[1200];
  snprintf(path, sizeof path, "%s/summary.json", dir);
  memset(d, 0, sizeof *d);
  char *txt = ver_io_slurp(path, NULL, 1 << 20);
  cJSON *o = txt ? cJSON_Parse(txt) : NULL;
  free(txt);
  if (!o)
    return -1;
  jstr(o, "case", d->case_id, sizeof d->case_id);
  jstr(o, "scene", d->scene, sizeof d->scene);
  jstr(o, "scene_file", d->scene_file, sizeof d->scene_file);
  jstr(o, "Le", d->le, sizeof d->le);
  jstr(o, "scheme", d->scheme, sizeof d->scheme);
  jstr(o, "shape", d->shape, sizeof d->shape);
  jstr(o, "fields", d->fields, sizeof d->fields);
  jstr(o, "damping_from", d->damping_from, sizeof d->damping_from);
  jstr(o, "damping_about", d->damping_about, sizeof d->damping_about);
  jstr(o, "path", d->path, sizeof d->path);
  jstr(o, "reversed_shear", d->reversed_shear, sizeof d->reversed_shear);
  jstr(o, "motion", d->motion, sizeof d->motion);
  d->path_reach = jnum(o, "path_reach");
  jstr(o, "error", d->error, sizeof d->error);
  d->h = jnum(o, "h");
  d->dt = jnum(o, "dt");
  d->sep_threshold = jnum(o, "separation_threshold");
  d->damping = jnum(o, "damping"); /* NaN from a run before time.damping: none */
  d->damping_beta = jnum(o, "damping_beta"); /* NaN before time.damping_beta: none */
  d->speed = jnum(o, "speed");     /* NaN from a run before it was written */
  const double ppc = jnum(o, "ppc");
  d->ppc = ppc >= 1 && ppc <= 1024 ? (int)ppc : 0; /* a scene's range; a value beyond an int is not cast */
  ver_summary *u = &d->u;
  u->complete = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(o, "complete"));
  for (size_t i = 0; i < NNUMS; i++) {
    char *p = (char *)u + NUMS[i].off;
    const double v = jnum(o, NUMS[i].key);
    if (NUMS[i].kind == F_DBL)
      memcpy(p, &v, sizeof v);
    else if (NUMS[i].kind == F_LONG) {
      /* counts: a value outside what a long holds (a damaged file) reads as 0, not cast */
      const long l = v > -9e18 && v < 9e18 ? (long)v : 0;
      memcpy(p, &l, sizeof l);
    } else {
      const size_t z = v > 0 && v < 9e18 ? (size_t)v : 0;
      memcpy(p, &z, sizeof z);
    }
  }
  char solver[16]; /* "static" or "explicit" ("" before the key: explicit) */
  jstr(o, "solver", solver, sizeof solver);
  u->static_run = !strcmp(solver, "static");
  cJSON_Delete(o);
  return 0;
}

double ver_summary_booked(const ver_summary *u)
{
  const double t[] = {u->L_bc_final,      u->L_flip_final,   u->L_scheme_final, u->W_head_final,
                      u->L_contact_final, u->L_debris_final, u->L_damp_final};
  double b = 0.0;
  for (size_t i = 0; i < sizeof t / sizeof *t; i++)
    b += isfinite(t[i]) ? t[i] : 0.0;
  return b;
}

double ver_summary_scheme_loss(const ver_summary *u)
{
  return u->L_bc_final + u->L_flip_final + u->L_scheme_final;
}
