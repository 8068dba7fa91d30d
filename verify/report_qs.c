/*
 * report_qs.c - the quasi-static solver in `delam report` (report.h; docs/static.md):
 * its runs of the snapback scenes (REP_QS: fig8, a45, a30), drawn beside the explicit
 * runs and the analytic branch in Fig. 8(c) and the snapback figure, and Fig. 3's nine
 * bars computed by the kernel (REP_QS3: iface90.ini with q set and U0 chosen for g by
 * eq. 35), drawn over the closed form of eq. 34.  Each run is measured by its distance
 * from the analytic path (ver_curve_path, snapback included).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "metrics.h"
#include "report.h"
#include "scene.h"

/* The snapback scenes run statically, at the grid where docs/static.md measures them. */
static const char *const qs_scene[3] = {"fig8", "a45", "a30"};
#define QS_H 4.0
#define QS_PPC 4
/* Fig. 3's bars: iface90.ini's interface at its coarsest grid, whose uniform opening is a
 * discrete solution: every row on eq. 34 (curve_path 2e-7 to 4e-4, the chords of the
 * curved branches, docs/static.md).  fig6.ini's band is 0.0016-0.0039 off, and at q 0.8
 * each of its particles' onset is a snapback of its own: two of the nine bars stopped. */
#define QS3_SCENE "iface90"
#define QS3_H 8.0
#define QS3_PPC 4

/* U0 giving the file's bar the ratio g at alpha 90: eq. 35, g = E U0 / (L r0^2), with
 * the file's E, L and r0 (r0 does not depend on U0).  NaN if the file does not load. */
static double qs3_U0(const rep_ctx *r, double g)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  ana_bar b;
  snprintf(path, sizeof path, "%.900s/%s.ini", r->scenes, QS3_SCENE);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0 || ver_scene_bar(&vs.sc, &b, err, sizeof err) != 0 ||
      vs.sc.alpha_deg != 90.0)
    return NAN;
  return g * vs.sc.L * b.r0 * b.r0 / vs.sc.E;
}

void ver_report_qs_cases(rep_ctx *r)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  for (int s = 0; s < 3; s++) {
    snprintf(path, sizeof path, "%.900s/%s.ini", r->scenes, qs_scene[s]);
    if (ver_scene_load(path, &vs, err, sizeof err) == 0)
      ver_report_add(r, qs_scene[s], QS_H, QS_PPC, 0, 0, "solver.type=static", NULL, REP_QS, 0);
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      const double U0 = qs3_U0(r, rep_fig3_g[j]);
      if (!isfinite(U0))
        return;
      char q[64], u[64], v[40];
      snprintf(q, sizeof q, "decohesion.q=%g", rep_fig3_q[i]);
      ver_scene_fmt_num(U0, v, sizeof v);
      snprintf(u, sizeof u, "decohesion.U0=%s", v);
      const char *sets[3] = {"solver.type=static", q, u};
      /* tag: the index of (q, g), 3 i + j */
      ver_report_add_sets(r, QS3_SCENE, QS3_H, QS3_PPC, 0, 0, sets, 3, REP_QS3, 3 * i + j);
    }
}

/* The static run of a snapback scene (REP_QS), with a result, or NULL. */
static const rep_case *qs_case(const rep_ctx *r, const char *scene)
{
  const rep_case *c = ver_report_first(r, REP_QS, scene);
  return c && c->have ? c : NULL;
}

/* Fig. 3's kernel run of (q_i, g_j), with a result, or NULL. */
static const rep_case *qs3_case(const rep_ctx *r, int i, int j)
{
  for (int k = 0; k < r->n; k++)
    if ((r->c[k].role & REP_QS3) && r->c[k].tag == 3 * i + j && r->c[k].have)
      return &r->c[k];
  return NULL;
}

/* curve_path and delta_5 of a run against its own bar (the scene with the case's
 * overrides); NaN where it has no rows or no bar. */
static double qs_path(const rep_case *c, double *d5)
{
  *d5 = NAN;
  if (!c || !c->bar_ok)
    return NAN;
  double *d, *P;
  const int n = ver_report_load(c, &d, &P);
  const double e = n > 0 ? ver_curve_path(&c->bar, d, P, (size_t)n, d5) : NAN;
  free(d);
  free(P);
  return e;
}

/* The load of a run's last row (NaN without rows). */
static double qs_last_P(const rep_case *c)
{
  double *d, *P;
  const int n = ver_report_load(c, &d, &P);
  const double last = n > 0 ? P[n - 1] : NAN;
  free(d);
  free(P);
  return last;
}

/* ", stopped" for a run that ended early (a key's note; where, in the text), else "". */
static void qs_note(const rep_case *c, char *buf, size_t len)
{
  snprintf(buf, len, "%s", c && !c->complete ? ", stopped" : "");
}

/* Fig. 3 in the kernel's axes: E e_ave / r0 with e_ave = delta / L, and
 * sigma* = P / (H r0) (unit thickness), to the closed form's end (report_plot.c). */
static void qs3_write(const rep_ctx *r, int i, int j, FILE *vars)
{
  char name[64], p[REP_PATH + 96];
  snprintf(name, sizeof name, "fig3-kernel-q%g-g%g.csv", rep_fig3_q[i], rep_fig3_g[j]);
  snprintf(p, sizeof p, "%s/data/%s", r->out, name);
  FILE *f = fopen(p, "w");
  if (!f) {
    if (r->io_bad)
      (*r->io_bad)++;
    return;
  }
  /* the header alone where the run is missing: gnuplot then draws no points */
  fprintf(f, "estar,sstar\n");
  const rep_case *c = qs3_case(r, i, j);
  if (c && c->bar_ok) {
    const ana_bar *b = &c->bar;
    double *d, *P;
    const int n = ver_report_load(c, &d, &P);
    for (int m = 0; m < n; m++) {
      const double es = d[m] / b->p.L * b->p.E / b->r0;
      if (es > 2.6)
        break;
      fprintf(f, "%.10g,%.10g\n", es, P[m] / (b->p.H * b->r0));
    }
    free(d);
    free(P);
  }
  if (ferror(f) | fclose(f)) {
    remove(p);
    if (r->io_bad)
      (*r->io_bad)++;
  }
  /* the figure's key is short: where it stopped is in the text */
  fprintf(vars, "f3k_note_%d_%d = \"%s\"\nf3k_have_%d_%d = %d\n", i, j, c && !c->complete ? ", stopped" : "", i, j,
          c != NULL);
}

void ver_report_qs_write(const rep_ctx *r, FILE *vars)
{
  for (int s = 0; s < 3; s++) {
    const rep_case *c = qs_case(r, qs_scene[s]);
    double d5;
    const double e = qs_path(c, &d5);
    char note[160];
    qs_note(c, note, sizeof note);
    fprintf(vars, "qs_%s = \"%s\"\nqs_%s_note = \"%s\"\nqs_%s_path = %.6g\nqs_%s_h = %g\nqs_%s_ppc = %d\n",
            qs_scene[s], c ? c->id : "", qs_scene[s], note, qs_scene[s], isfinite(e) ? e : -1, qs_scene[s],
            QS_H, qs_scene[s], QS_PPC);
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      qs3_write(r, i, j, vars);
  fprintf(vars, "f3k_h = %g\nf3k_ppc = %d\n", QS3_H, QS3_PPC);
}

/* How a static run went, in words, under "qs_<scene>:..." and "fig3k:...". */
void ver_report_qs_vars(report *R)
{
  const rep_ctx *r = &R->r;
  for (int s = 0; s < 3; s++) {
    const rep_case *c = qs_case(r, qs_scene[s]);
    char key[64], buf[1400];
    double d5;
    const double e = qs_path(c, &d5);
    snprintf(key, sizeof key, "qs_%s:para", qs_scene[s]);
    if (!c)
      snprintf(buf, sizeof buf, "The quasi-static solver's run of %s.ini at h = %g, %d ppc is missing.", qs_scene[s],
               QS_H, QS_PPC);
    else if (c->complete)
      snprintf(buf, sizeof buf,
               "Quasi-static solver (%.150s, `--solver static`, h = %g, %d ppc; docs/static.md): every row an "
               "equilibrium state, traced along the path through the snapback. Its distance from the analytic path "
               "(curve_path, RMS in (delta / delta_peak, P / Pmax)) is %.2g, delta_5 (where the load falls to 5 %% "
               "of Pmax, less the branch's delta there, over delta_peak) %+.2g; peak %.4g (%+.1f %% against the "
               "analytic), dissipation %.4g against %.4g; %ld increments, %.3g s CPU.",
               c->id, c->h, c->ppc, e, d5, c->peak_P, 100 * (c->peak_P / c->bar.Pmax - 1), c->D_final, c->bar.D_sep,
               c->steps, c->cpu_s);
    else
      snprintf(buf, sizeof buf,
               "Quasi-static solver (%.150s, `--solver static`, h = %g, %d ppc; docs/static.md): the run STOPPED at "
               "delta = %.3g, P = %.2f Pmax (its message: %.300s); its rows up to there are drawn, marked as stopped "
               "in the key. Their distance from the analytic path (curve_path, to the last row) is %.2g; peak %.4g "
               "(%+.1f %% against the analytic); %ld increments, %.3g s CPU.",
               c->id, c->h, c->ppc, c->delta_end, qs_last_P(c) / c->bar.Pmax, c->error[0] ? c->error : "none", e,
               c->peak_P, 100 * (c->peak_P / c->bar.Pmax - 1), c->steps, c->cpu_s);
    rep_vars_set(&R->vars, key, "%s", buf);
  }
  /* Fig. 3: the largest curve_path over the complete runs, and the runs that stopped */
  double worst = -1;
  const rep_case *wc = NULL;
  char stopped[400] = "";
  int nstop = 0, ndone = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      const rep_case *c = qs3_case(r, i, j);
      double d5;
      const double e = qs_path(c, &d5);
      if (c && c->complete && isfinite(e)) {
        ndone++;
        if (e > worst) {
          worst = e;
          wc = c;
        }
      } else {
        const size_t l = strlen(stopped);
        snprintf(stopped + l, sizeof stopped - l, "%sq = %g, g = %g%s", nstop ? "; " : "", rep_fig3_q[i],
                 rep_fig3_g[j], c ? "" : " (missing)");
        if (c && c->bar_ok) {
          const size_t m = strlen(stopped);
          snprintf(stopped + m, sizeof stopped - m, " (stopped at E e_ave / r0 = %.3g)",
                   c->delta_end / c->bar.p.L * c->bar.p.E / c->bar.r0);
        }
        nstop++;
      }
    }
  rep_vars_num(&R->vars, "fig3k:h", QS3_H);
  rep_vars_num(&R->vars, "fig3k:ppc", QS3_PPC);
  rep_vars_num(&R->vars, "fig3k:done", ndone);
  rep_vars_num(&R->vars, "fig3k:worst", worst >= 0 ? worst : NAN);
  if (wc)
    rep_vars_set(&R->vars, "fig3k:worst_case", "q = %g, g = %g: %s", rep_fig3_q[(int)wc->tag / 3],
                 rep_fig3_g[(int)wc->tag % 3], wc->id);
  else
    rep_vars_set(&R->vars, "fig3k:worst_case", "no complete run");
  rep_vars_set(&R->vars, "fig3k:stopped", "%s", nstop ? stopped : "none");
}
