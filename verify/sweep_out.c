/*
 * sweep_out.c - what `delam verify` writes (sweep.h): verify.json (every check with
 * its class, tolerance, bounds and note), verify.csv (one row a case), the printed
 * check lines and the closing table.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "io.h"
#include "summary.h"
#include "sweep.h"

static cJSON *num_or_null(double v)
{
  return isfinite(v) ? cJSON_CreateNumber(v) : cJSON_CreateNull();
}

cJSON *ver_check_json(const ver_check *k)
{
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "name", k->name);
  cJSON_AddStringToObject(o, "class", k->cls == VER_CLASS_KNOWN ? "known-limit" : "pass");
  cJSON_AddItemToObject(o, "measured", num_or_null(k->measured));
  cJSON_AddItemToObject(o, "reference", num_or_null(k->reference));
  cJSON_AddItemToObject(o, "error", num_or_null(k->error));
  cJSON_AddStringToObject(o, "error_kind", k->rel ? "relative" : "absolute");
  cJSON_AddItemToObject(o, "tolerance", num_or_null(k->tol));
  if (k->cls == VER_CLASS_KNOWN) {
    cJSON *b = cJSON_CreateArray();
    cJSON_AddItemToArray(b, num_or_null(k->lim_lo));
    cJSON_AddItemToArray(b, num_or_null(k->lim_hi));
    cJSON_AddItemToObject(o, "known_limit_bounds", b);
  }
  cJSON_AddStringToObject(o, "verdict", ver_verdict_name(k->verdict));
  cJSON_AddStringToObject(o, "note", k->note);
  return o;
}

static int write_text(const char *dir, const char *name, const char *text)
{
  char path[1200];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return ver_io_write_atomic(path, text);
}

int ver_sweep_write_json(const ver_verify_opts *o, const ver_case *cs, int n, const ver_cross *x, int nx, double wall,
                      int rc)
{
  cJSON *root = cJSON_CreateObject();
  cJSON_AddNumberToObject(root, "schema", VER_SCHEMA_VERIFY);
  cJSON_AddStringToObject(root, "mode", o->merge_found ? "found" : o->full ? "full" : o->angles ? "angles" : "quick");
  cJSON_AddStringToObject(root, "dir", o->outdir);
  cJSON_AddBoolToObject(root, "merged", o->merge);
  cJSON_AddNumberToObject(root, "jobs", o->jobs);
  cJSON_AddNumberToObject(root, "wall_s", wall);
  cJSON *arr = cJSON_AddArrayToObject(root, "cases");
  int counts[3] = {0, 0, 0}, cfail = 0;
  for (int i = 0; i < n; i++) {
    const ver_case *c = &cs[i];
    cJSON *co = cJSON_CreateObject();
    cJSON_AddStringToObject(co, "id", c->id);
    cJSON_AddStringToObject(co, "scene", c->scene);
    cJSON_AddStringToObject(co, "scene_file", c->path);
    cJSON_AddStringToObject(co, "variant", c->var.suffix);
    cJSON_AddNumberToObject(co, "h", c->vs.sc.h);
    cJSON_AddNumberToObject(co, "ppc", c->vs.sc.ppc);
    cJSON_AddNumberToObject(co, "dt", c->vs.sc.dt);
    cJSON_AddNumberToObject(co, "alpha", c->vs.sc.alpha_deg);
    cJSON_AddNumberToObject(co, "end_delta", c->end_delta);
    cJSON *sets = cJSON_AddArrayToObject(co, "sets");
    for (int s = 0; s < c->nset; s++)
      cJSON_AddItemToArray(sets, cJSON_CreateString(c->sets[s]));
    cJSON_AddItemToObject(co, "wall_s", num_or_null(c->wall_s));
    cJSON_AddNumberToObject(co, "exit_status", c->exit_code);
    cJSON_AddBoolToObject(co, "complete", c->complete);
    if (c->error[0])
      cJSON_AddStringToObject(co, "error", c->error);
    cJSON_AddStringToObject(co, "verdict", ver_verdict_name(c->verdict));
    cJSON_AddItemToObject(co, "D_diffuse", num_or_null(c->D_diffuse));
    if (c->have_ana) {
      cJSON *an = cJSON_AddObjectToObject(co, "analytic");
      cJSON_AddNumberToObject(an, "Pmax", c->ana.Pmax);
      cJSON_AddNumberToObject(an, "k_elastic", c->ana.k_elastic);
      cJSON_AddNumberToObject(an, "k_soft_peak", c->ana.k_soft_peak);
      cJSON_AddNumberToObject(an, "delta_sep", c->ana.delta_sep);
      cJSON_AddNumberToObject(an, "g", c->ana.g);
      cJSON_AddBoolToObject(an, "snapback", c->ana.snapback);
      cJSON_AddNumberToObject(an, "D_sep", c->ana.D_sep);
      cJSON_AddNumberToObject(an, "W_sep", c->ana.W_sep);
    }
    cJSON *ck = cJSON_AddArrayToObject(co, "checks");
    for (int j = 0; j < c->nchk; j++) {
      cJSON_AddItemToArray(ck, ver_check_json(&c->chk[j]));
      counts[c->chk[j].verdict]++;
    }
    cfail += c->verdict == VER_FAIL;
    cJSON_AddItemToArray(arr, co);
  }
  cJSON *xa = cJSON_AddArrayToObject(root, "cross");
  for (int i = 0; i < nx; i++) {
    const ver_cross *g = &x[i];
    cJSON *go = ver_check_json(&g->chk);
    cJSON_AddStringToObject(go, "scene", g->scene);
    cJSON_AddStringToObject(go, "over", g->over);
    cJSON_AddNumberToObject(go, strcmp(g->over, "h") ? "h" : "ppc", g->fixed);
    cJSON *pts = cJSON_AddArrayToObject(go, "points");
    for (int j = 0; j < g->n; j++) {
      cJSON *p = cJSON_CreateObject();
      cJSON_AddStringToObject(p, "case", g->ids[j]);
      cJSON_AddNumberToObject(p, g->over, g->x[j]);
      cJSON_AddItemToObject(p, g->yname[0] ? g->yname : strcmp(g->name, "order_h") ? "D_final" : "curve_l2",
                            num_or_null(g->y[j]));
      cJSON_AddItemToArray(pts, p);
    }
    cJSON_AddItemToArray(xa, go);
    counts[g->chk.verdict]++;
  }
  cJSON *s = cJSON_AddObjectToObject(root, "summary");
  cJSON_AddNumberToObject(s, "cases", n);
  cJSON_AddNumberToObject(s, "failed_cases", cfail);
  cJSON_AddNumberToObject(s, "checks_pass", counts[VER_PASS]);
  cJSON_AddNumberToObject(s, "checks_fail", counts[VER_FAIL]);
  cJSON_AddNumberToObject(s, "checks_known_limit", counts[VER_KNOWN]);
  cJSON_AddNumberToObject(s, "exit_status", rc);
  char *txt = cJSON_Print(root);
  cJSON_Delete(root);
  if (!txt)
    return -1;
  const int r = write_text(o->outdir, "verify.json", txt);
  free(txt);
  return r;
}

const ver_check *ver_case_check(const ver_case *c, const char *name)
{
  for (int i = 0; i < c->nchk; i++)
    if (!strcmp(c->chk[i].name, name))
      return &c->chk[i];
  return NULL;
}

static double chk_err(const ver_case *c, const char *name)
{
  const ver_check *k = ver_case_check(c, name);
  return k ? k->error : NAN;
}

int ver_sweep_write_csv(const ver_verify_opts *o, const ver_case *cs, int n)
{
  size_t cap = 4096 + (size_t)n * 1024, len = 0;
  char *buf = malloc(cap);
  if (!buf)
    return -1;
  len += (size_t)snprintf(buf + len, cap - len,
                          "# delam verify.csv schema %d\n"
                          "case,scene,variant,h,ppc,verdict,complete,exit_status,wall_s,peak_P,peak_err,"
                          "k_elastic_err,k_soft,k_soft_err,delta_sep,delta_sep_err,D_final,D_err,D_diffuse,W_ext_final,"
                          "W_err,energy_residual,band_width,band_extent,crack_angle,curve_l2,curve_wave,load_after_sep,n_fail,n_known,"
                          "error\n",
                          VER_SCHEMA_VERIFY);
  for (int i = 0; i < n; i++) {
    const ver_case *c = &cs[i];
    int nf = 0, nk = 0;
    for (int j = 0; j < c->nchk; j++) {
      nf += c->chk[j].verdict == VER_FAIL;
      nk += c->chk[j].verdict == VER_KNOWN;
    }
    char err[600];
    snprintf(err, sizeof err, "%s", c->error);
    for (char *p = err; *p; p++)
      if (*p == '"' || *p == ',' || *p == '\n')
        *p = ' ';
    len += (size_t)snprintf(buf + len, cap - len,
                            "%s,%s,%s,%g,%d,%s,%d,%d,%.4g,%.9g,%.6g,%.6g,%.9g,%.6g,%.6g,%.6g,%.9g,%.6g,%.4g,%.9g,%.6g,"
                            "%.6g,%.4g,%.4g,%.4g,%.6g,%.6g,%.4g,%d,%d,%s\n",
                            c->id, c->scene, c->var.suffix, c->vs.sc.h, c->vs.sc.ppc, ver_verdict_name(c->verdict),
                            c->complete, c->exit_code, c->wall_s, c->peak_P, chk_err(c, "peak_P"),
                            chk_err(c, "k_elastic"), c->k_soft, chk_err(c, "k_soft"), c->delta_sep,
                            chk_err(c, "delta_sep"), c->D_final, chk_err(c, "D_final"), c->D_diffuse, c->W_ext_final,
                            chk_err(c, "W_ext_final"), c->energy_residual, c->band_width, c->band_extent, c->angle,
                            c->curve_l2, c->curve_wave, c->P_after, nf, nk, err);
    if (len >= cap - 1)
      break;
  }
  const int r = write_text(o->outdir, "verify.csv", buf);
  free(buf);
  return r;
}

int ver_sweep_write_cross_csv(const ver_verify_opts *o, const ver_cross *x, int nx)
{
  size_t cap = 4096 + (size_t)nx * 1024, len = 0;
  char *buf = malloc(cap);
  if (!buf)
    return -1;
  len += (size_t)snprintf(buf + len, cap - len,
                          "# delam verify_cross.csv schema 1\n"
                          "check,scene,over,held,held_value,verdict,measured,reference,error,tolerance,points,note\n");
  for (int i = 0; i < nx && len < cap - 1; i++) {
    const ver_cross *g = &x[i];
    char pts[512] = "", note[sizeof g->chk.note];
    size_t l = 0;
    for (int j = 0; j < g->n && l < sizeof pts - 40; j++)
      l += (size_t)snprintf(pts + l, sizeof pts - l, "%s%s=%g:%.9g", j ? ";" : "", g->over, g->x[j], g->y[j]);
    snprintf(note, sizeof note, "%s", g->chk.note);
    for (char *p = note; *p; p++)
      if (*p == '"' || *p == ',' || *p == '\n')
        *p = ' ';
    len += (size_t)snprintf(buf + len, cap - len, "%s,%s,%s,%s,%g,%s,%.9g,%.9g,%.9g,%g,%s,%s\n", g->chk.name,
                            g->scene, g->over, strcmp(g->over, "h") ? "h" : "ppc", g->fixed, ver_verdict_name(g->chk.verdict), g->chk.measured, g->chk.reference,
                            g->chk.error, g->chk.tol, pts, note);
  }
  const int r = write_text(o->outdir, "verify_cross.csv", buf);
  free(buf);
  return r;
}

static const char *VNAME[] = {"PASS", "FAIL", "KNOWN-LIMIT"};

void ver_sweep_print_check(const char *id, const ver_check *k)
{
  char err[64];
  if (k->rel)
    snprintf(err, sizeof err, "err %+.3g %% (tol %g %%)", 100 * k->error, 100 * k->tol);
  else
    snprintf(err, sizeof err, "err %+.4g (tol %g)", k->error, k->tol);
  printf("%-11s %s %s: measured %.6g, reference %.6g, %s%s -- %s\n", VNAME[k->verdict], id, k->name,
         k->measured, k->reference, err, k->cls == VER_CLASS_KNOWN ? " [known-limit class]" : "", k->note);
}

void ver_sweep_print_table(const ver_case *cs, int n, const ver_cross *x, int nx)
{
  printf("\n%-28s %9s %9s %9s %9s %9s %9s %7s  %s\n", "case", "peak err", "D err", "D diffuse", "E resid",
         "curve L2", "wave L2", "wall s", "verdict");
  for (int i = 0; i < n; i++) {
    const ver_case *c = &cs[i];
    printf("%-28s %+8.2f%% %+8.2f%% %8.2f%% %9.2e %9.4f %9.4f %7.1f  %s%s%s\n", c->id, 100 * chk_err(c, "peak_P"),
           100 * chk_err(c, "D_final"), 100 * c->D_diffuse, c->energy_residual, c->curve_l2, c->curve_wave, c->wall_s,
           VNAME[c->verdict],
           c->error[0] ? ": " : "", c->error);
  }
  for (int i = 0; i < nx; i++) {
    const ver_cross *g = &x[i];
    char pts[512] = "";
    size_t l = 0;
    for (int j = 0; j < g->n && l < sizeof pts - 40; j++)
      l += (size_t)snprintf(pts + l, sizeof pts - l, "%s%s %g: %.4g", j ? ", " : "", g->over, g->x[j], g->y[j]);
    printf("%-11s %s %s at %s %g: %.4g (%s)\n", VNAME[g->chk.verdict], g->scene, g->name,
           strcmp(g->over, "h") ? "h" : "ppc", g->fixed, g->chk.measured, pts);
  }
}

