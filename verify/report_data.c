/*
 * report_data.c - what `delam report` reads back from a run (summary.json, load.csv)
 * and what it measures against the analytic bar, through the one definition of each
 * quantity (metrics.h): curve error, softening slope, width of the load drop,
 * dissipation error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "metrics.h"
#include "report.h"
#include "scene.h"
#include "summary.h"

int ver_report_read_summary(rep_case *c)
{
  ver_summary_doc d;
  if (ver_summary_read(c->dir, &d) != 0)
    return -1;
  const ver_summary *u = &d.u;
  c->complete = u->complete;
  c->peak_P = u->peak_P;
  c->delta_peak = u->delta_peak;
  c->delta_sep = u->delta_sep;
  c->k_elastic = u->k_elastic;
  c->D_final = u->D_final;
  c->W_ext_final = u->W_ext_final;
  c->energy_residual = u->energy_residual;
  c->delta_end = u->delta_end;
  c->cpu_s = u->cpu_s;
  c->wall_s = u->wall_s;
  c->updates_per_s = u->updates_per_s;
  c->dt_used = d.dt;
  c->steps = u->steps;
  c->particles = (double)u->particles;
  c->sep_threshold = d.sep_threshold;
  c->damping = isfinite(d.damping) ? d.damping : 0.0;
  c->damping_beta = isfinite(d.damping_beta) ? d.damping_beta : 0.0;
  snprintf(c->scheme, sizeof c->scheme, "%s", d.scheme);
  snprintf(c->shape, sizeof c->shape, "%s", d.shape);
  snprintf(c->fields, sizeof c->fields, "%s", d.fields);
  snprintf(c->damping_from, sizeof c->damping_from, "%s", d.damping_from);
  snprintf(c->damping_about, sizeof c->damping_about, "%s", d.damping_about);
  snprintf(c->path, sizeof c->path, "%s", d.path);
  snprintf(c->reversed_shear, sizeof c->reversed_shear, "%s", d.reversed_shear);
  c->path_reach = d.path_reach;
  c->static_run = u->static_run;
  snprintf(c->le, sizeof c->le, "%s", d.le);
  snprintf(c->error, sizeof c->error, "%.255s", d.error);
  return 0;
}

int ver_report_load(const rep_case *c, double **delta, double **P)
{
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/load.csv", c->dir);
  static const char *const cols[2] = {"delta", "P_grip"};
  double *o[2];
  const long n = ver_csv_read(p, cols, 2, o);
  *delta = o[0];
  *P = o[1];
  return n > 0 ? (int)n : 0;
}

/* The analytic bar of case c: its scene file with its overrides (Fig. 3's bars set q and
 * U0; the method's keys leave the bar as it is), with the density and the flaw's x (where
 * the plane of the exact solution at the grip speed lies). */
static int scene_bar(const rep_ctx *r, const rep_case *c, ana_bar *bar, double *rho, double *imp_x)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%s/%s.ini", r->scenes, c->scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0)
    return -1;
  for (int j = 0; j < c->nset; j++)
    if (ver_scene_set(&vs, c->set[j], err, sizeof err) != 0)
      return -1;
  if (vs.sc.specimen != MPM_SPEC_BAR) /* a split beam: its references are report_spec.c's */
    return -1;
  *rho = vs.sc.rho;
  *imp_x = vs.sc.imp_x;
  return ver_scene_bar(&vs.sc, bar, err, sizeof err) == 0 ? 0 : -1;
}

ana_wave_params ver_report_wave_params(const rep_case *c)
{
  const ana_wave_params wp = {c->speed, c->rho, c->imp_x, isfinite(c->sep_threshold) ? c->sep_threshold : 0.98};
  return wp;
}

void ver_report_measure(const rep_ctx *r, rep_case *c)
{
  c->rho = c->imp_x = NAN;
  c->bar_ok = scene_bar(r, c, &c->bar, &c->rho, &c->imp_x) == 0;
  c->curve_wave = c->wave_peak = c->curve_path = NAN;
  if (!c->have || !c->bar_ok)
    return;
  const ana_bar *b = &c->bar;
  c->diss_err = c->D_final / b->D_sep - 1.0;
  double *d, *P;
  const int n = ver_report_load(c, &d, &P);
  c->rows = n;
  /* the curve error of delam verify: up to where lambda reaches the threshold */
  c->cmp_end = ver_curve_end(b, isfinite(c->sep_threshold) && c->sep_threshold > 0 ? c->sep_threshold : 1.0);
  double mabs = 0;
  for (int i = 0; i < n; i++)
    mabs = isfinite(P[i]) ? fmax(mabs, fabs(P[i])) : INFINITY;
  c->max_absP = mabs;
  if (n > 0) {
    /* a static run's rows are states, compared at their own delta (ver_curve_l2) */
    c->curve_err = ver_curve_err_bar(b, d, P, (size_t)n, c->cmp_end, &c->max_dev, c->static_run);
    if (c->static_run)
      c->curve_path = ver_curve_path(b, d, P, (size_t)n, NULL);
    if (c->static_run && b->snapback) /* P(delta) has two values: curve_path judges the path */
      c->curve_err = c->max_dev = NAN;
    const ana_wave_params wp = ver_report_wave_params(c);
    c->curve_wave = ver_curve_err_wave(b, wp.speed, wp.rho, wp.xg, wp.thr, d, P, (size_t)n, c->cmp_end, NULL,
                                       &c->wave_peak, NULL);
    c->k_soft = ver_softening_slope(d, P, (size_t)n, VER_SOFT_HI, VER_SOFT_LO);
    c->drop_width = ver_drop_width(d, P, (size_t)n);
  }
  free(d);
  free(P);
}

void ver_report_method(const rep_case *c, char *buf, size_t len)
{
  char damp[96] = "", beta[32] = "";
  if (c->damping_beta > 0.0)
    snprintf(beta, sizeof beta, ", beta %.3g", c->damping_beta);
  if (c->damping > 0.0 || c->damping_beta > 0.0)
    snprintf(damp, sizeof damp, ", damped%s%s (c %.4g%s)", !strcmp(c->damping_from, "cut") ? " from the cut" : "",
             !strcmp(c->damping_about, "parts") ? " about the parts" : "", c->damping, beta);
  char path[64] = "";
  if (!strcmp(c->path, "line"))
    snprintf(path, sizeof path, ", on its line (reach %g h)", c->path_reach);
  if (!strcmp(c->path, "interface")) { /* no particle softens: Le and the shear rule are unused */
    snprintf(buf, len, "%s, %s, cohesive interface between two fields%s", !strcmp(c->scheme, "musl") ? "MUSL" : "USL",
             !strcmp(c->shape, "gimp") ? "uGIMP" : "bilinear", damp);
    return;
  }
  snprintf(buf, len, "%s, %s, %s field%s, Le = %s%s%s%s", !strcmp(c->scheme, "musl") ? "MUSL" : "USL",
           !strcmp(c->shape, "gimp") ? "uGIMP" : "bilinear", c->fields[0] ? c->fields : "one",
           !strcmp(c->fields, "two") ? "s" : "", c->le[0] ? c->le : "cell", path, damp,
           !strcmp(c->reversed_shear, "closing") ? ", reversed shear closing" : "");
}
