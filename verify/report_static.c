/*
 * report_static.c - the quasi-static solver's lines of the convergence figure and the
 * work-precision chart (report.h): fig6, fig7 and fig8 with solver.type = static at
 * REP_STATIC_PPC particles per cell, h = 8, 4, 2 (and 1 for fig6); their error against
 * the analytic path by h, its fitted order and verdict; and the explicit runs' rate error,
 * measured as the distance of the explicit curve from the static one at the same h and ppc.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "metrics.h"
#include "report.h"

/* The finest h of each sweep scene's static line (CPU s at 4 ppc, one thread, measured
 * on a loaded machine): fig6 h 1 29 s; fig7 h 2 5.1 s, fig8 h 2 44 s, and h 1 several
 * times more. */
static const double static_hmin[REP_NSWEEP] = {1, 2, 2};

/* The least fitted order called convergence: below it the error falls by less than 30 %
 * at each halving of h (2^-0.5 = 0.71). */
#define REP_ORDER_MIN 0.5
#define REP_FLOOR_SHARE 0.1 /* of the bound: below it at every grid, the error is at its floor */

void ver_report_static_cases(report *R)
{
  rep_ctx *r = &R->r;
  for (int s = 0; s < REP_NSWEEP; s++)
    for (double h = 8; h >= static_hmin[s]; h /= 2) {
      /* until 0: the scene's own stop rule, past the fall of the load that curve_path needs */
      const int k = ver_report_add(r, rep_sweep_scene[s], h, REP_STATIC_PPC, 0, 0, "solver.type=static", NULL,
                                   REP_STATIC, 0);
      if (k >= 0) /* particles (the paper's 192 x 32 bar) x increments (a few hundred), not steps */
        r->c[k].cost = 1e3 * 192 * 32 / (h * h) * REP_STATIC_PPC;
    }
}

/* The static case of (scene, h) with results, or NULL. */
static const rep_case *static_at(const rep_ctx *r, const char *scene, double h)
{
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if ((c->role & REP_STATIC) && c->have && c->static_run && !strcmp(c->scene, scene) && c->h == h &&
        c->ppc == REP_STATIC_PPC)
      return c;
  }
  return NULL;
}

/* The explicit run e's rate error: RMS of (P_e - P_s(delta)) / Pmax over e's rows up to
 * its curve-error window (ver_curve_end) and no further than the static run s follows
 * delta forward (ver_curve_err_curve: the explicit curve error with the static curve in
 * place of the analytic one).  NaN where either has no rows. */
static double rate_dist(const rep_case *e, const rep_case *s)
{
  double *ed, *eP, *sd, *sP;
  const int ne = ver_report_load(e, &ed, &eP), ns = ver_report_load(s, &sd, &sP);
  double dist = NAN;
  if (ne > 0 && ns > 0 && e->bar_ok)
    dist = ver_curve_err_curve(sd, sP, (size_t)ns, ed, eP, (size_t)ne, e->cmp_end, e->bar.Pmax);
  free(ed);
  free(eP);
  free(sd);
  free(sP);
  return dist;
}

/* The bound of verify's curve_path check (policy.c): the verdict's "within". */
static double path_tol(const rep_case *c)
{
  return c->bar.p.alpha_deg == 90.0 ? VER_PATH_TOL_90 : VER_PATH_TOL_INCLINED;
}

static void data_failed(const rep_ctx *r, const char *path, int e)
{
  fprintf(stderr, "delam report: %s: cannot write: %s\n", path, strerror(e));
  if (r->io_bad)
    (*r->io_bad)++;
}

void ver_report_write_static(report *R, FILE *vars)
{
  const rep_ctx *r = &R->r;
  for (int s = 0; s < REP_NSWEEP; s++) {
    const char *sc = rep_sweep_scene[s];
    char name[64];
    snprintf(name, sizeof name, "data/sweep-%s-static.dat", sc);
    char path[REP_PATH + 96];
    snprintf(path, sizeof path, "%s/%s", r->out, name);
    FILE *f = fopen(path, "w");
    if (!f)
      data_failed(r, path, errno);
    if (f)
      fprintf(f, "h,curve_path,curve_err,abs_diss_err,cpu_s,complete,particles,rate_dist,explicit_err,"
                 "explicit_cpu_s\n");
    double hh[8], ep[8];
    int n = 0, falls = 1, within = 1, floor = 1;
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = static_at(r, sc, h);
      if (!c || !isfinite(c->curve_path))
        continue;
      const rep_case *e = ver_report_sweep(r, sc, h, REP_STATIC_PPC);
      const double rd = e && e->have ? rate_dist(e, c) : NAN;
      if (f)
        fprintf(f, "%g,%.6g,%.6g,%.6g,%.6g,%d,%.0f,%.6g,%.6g,%.6g\n", h, c->curve_path, c->curve_err,
                fabs(c->diss_err), c->cpu_s, c->complete, c->particles, rd, e && e->have ? e->curve_err : NAN,
                e && e->have ? e->cpu_s : NAN);
      if (c->complete && n < 8) {
        falls &= n == 0 || c->curve_path < ep[n - 1];
        within &= c->curve_path <= path_tol(c);
        floor &= c->curve_path <= REP_FLOOR_SHARE * path_tol(c);
        hh[n] = h;
        ep[n++] = c->curve_path;
      }
    }
    if (f) { /* a file not written whole is removed: no figure is drawn from part of it */
      const int bad = ferror(f), e0 = errno; /* errno of the failed write, if one failed */
      const int cl = fclose(f), e = cl != 0 ? errno : e0;
      if (cl != 0 || bad) {
        remove(path);
        data_failed(r, path, e ? e : EIO);
      }
    }
    rep_fit *ft = &R->sfits[s];
    memset(ft, 0, sizeof *ft);
    ft->n = n;
    ft->p_curve = ver_conv_order(hh, ep, (size_t)n, &ft->c_curve);
    ft->p_diss = ft->c_diss = NAN;
    /* converges: an order of REP_ORDER_MIN or more from three grids or more, the error
     * falling at every refinement, each grid within verify's bound; levels off: the
     * order is above zero but below that (a floor h does not remove); at the floor:
     * every grid below REP_FLOOR_SHARE of the bound without that trend (the inclined
     * interface: 4e-7 at h 8, where its two segments open as one, 1e-4 below; an order
     * fitted to those says nothing) */
    const char *v = n < 3                                     ? "too few grids"
                    : floor && !(ft->p_curve >= REP_ORDER_MIN && falls)
                        ? "at the floor, below a tenth of the bound"
                    : !(ft->p_curve > 0)                      ? "does NOT converge"
                    : ft->p_curve < REP_ORDER_MIN || !falls   ? (within ? "levels off, within the bound"
                                                                        : "levels off, above the bound")
                    : within                                  ? "converges"
                                                              : "converges, above the bound";
    snprintf(R->sverdict[s], sizeof R->sverdict[s], "%s", v);
    fprintf(vars, "p_static_%s = %.6g\nc_static_%s = %.6g\nv_static_%s = \"%s\"\n", sc,
            isfinite(ft->p_curve) ? ft->p_curve : 0, sc, isfinite(ft->c_curve) ? ft->c_curve : -50, sc, v);
  }
}

void ver_report_static_vars(report *R)
{
  const rep_ctx *r = &R->r;
  for (int s = 0; s < REP_NSWEEP; s++) {
    const char *sc = rep_sweep_scene[s];
    char key[64];
    snprintf(key, sizeof key, "static:%s:p", sc);
    rep_vars_num(&R->vars, key, R->sfits[s].p_curve);
    snprintf(key, sizeof key, "static:%s:n", sc);
    rep_vars_num(&R->vars, key, R->sfits[s].n);
    snprintf(key, sizeof key, "static:%s:verdict", sc);
    rep_vars_set(&R->vars, key, "%s", R->sverdict[s][0] ? R->sverdict[s] : "no runs");
    /* the finest complete grid's curve_path, and the explicit runs' rate error there */
    const rep_case *fin = NULL;
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = static_at(r, sc, h);
      if (c && c->complete && isfinite(c->curve_path))
        fin = c;
    }
    snprintf(key, sizeof key, "static:%s:finest", sc);
    if (fin)
      rep_vars_set(&R->vars, key, "%.2g at h = %g (%.2g CPU s)", fin->curve_path, fin->h, fin->cpu_s);
    else
      rep_vars_set(&R->vars, key, "none");
    /* the work-precision line from its cheapest to its dearest run: the load error, or
     * curve_path on a snapback bar (the quantities workprec.gp draws) */
    const rep_case *lo = NULL, *hi = NULL;
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = static_at(r, sc, h);
      if (c && c->complete) {
        lo = lo ? lo : c;
        hi = c;
      }
    }
    snprintf(key, sizeof key, "static:%s:wp", sc);
    if (lo && hi != lo) {
      const int sb = lo->bar_ok && lo->bar.snapback;
      rep_vars_set(&R->vars, key, "%s %.2g to %.2g over %.2g to %.2g CPU s", sb ? "curve_path" : "load error",
                   sb ? lo->curve_path : lo->curve_err, sb ? hi->curve_path : hi->curve_err, lo->cpu_s, hi->cpu_s);
    } else
      rep_vars_set(&R->vars, key, "n/a");
    snprintf(key, sizeof key, "rate:%s", sc);
    char buf[160] = "";
    size_t len = 0;
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = static_at(r, sc, h), *e = ver_report_sweep(r, sc, h, REP_STATIC_PPC);
      const double d = c && e && e->have ? rate_dist(e, c) : NAN;
      if (isfinite(d) && len < sizeof buf)
        len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%.2g (h %g)", len ? ", " : "", d, h);
    }
    rep_vars_set(&R->vars, key, "%s", len ? buf : "none");
  }
}

static const char *fmt_num(double x, char *buf, size_t len)
{
  snprintf(buf, len, isfinite(x) ? "%.4g" : "n/a", x);
  return buf;
}

void ver_report_static_table(report *R)
{
  static const char *const head[8] = {"case", "h", "curve_path", "RMS load error / Pmax", "D", "D analytic",
                                      "CPU s", "explicit 4 ppc: distance from it"};
  rep_table *t = rep_doc_table(&R->doc, 8, head);
  for (int s = 0; s < REP_NSWEEP; s++)
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = static_at(&R->r, rep_sweep_scene[s], h);
      const rep_case *e = ver_report_sweep(&R->r, rep_sweep_scene[s], h, REP_STATIC_PPC);
      if (!c)
        continue;
      char a[32], b[32], d[32], f[32], g[32];
      rep_table_row(t, c->complete ? REP_ROW_PLAIN : REP_ROW_FAIL, "%s\t%g\t%s\t%s\t%s\t%s\t%.3g\t%s", c->id, h,
                    fmt_num(c->curve_path, a, sizeof a), fmt_num(c->curve_err, b, sizeof b),
                    fmt_num(c->D_final, d, sizeof d), fmt_num(c->bar.D_sep, f, sizeof f), c->cpu_s,
                    fmt_num(e && e->have ? rate_dist(e, c) : NAN, g, sizeof g));
    }
}
