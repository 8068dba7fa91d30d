/*
 * report_compose.c - the document of `delam report` (report.h): the introduction, the
 * verdicts of the checks, the paper's numbers beside the measured ones, one section a
 * figure (its template's title as the caption, its paragraphs, the figure, a data
 * table where numbers are many), and every run.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "report.h"

static const char *num(double x, char *buf, size_t len)
{
  if (isfinite(x))
    snprintf(buf, len, "%.4g", x);
  else
    snprintf(buf, len, "n/a");
  return buf;
}

/* Fig. 6(b) and the convergence figure: the 1-ppc sweep by h. */
static void table_sweep(report *R, const char *scene)
{
  static const char *const head[7] = {"case", "h", "RMS load error / Pmax", "peak P", "softening slope", "D",
                                      "D analytic"};
  rep_table *t = rep_doc_table(&R->doc, 7, head);
  for (double h = 8; h >= 1; h /= 2) {
    const rep_case *c = ver_report_sweep(&R->r, scene, h, 1);
    char a[32], b[32], d[32], e[32], f[32];
    if (c)
      rep_table_row(t, c->complete ? REP_ROW_PLAIN : REP_ROW_FAIL, "%s\t%g\t%s\t%s\t%s\t%s\t%s", c->id, h,
                    num(c->curve_err, a, sizeof a), num(c->peak_P, b, sizeof b), num(c->k_soft, d, sizeof d),
                    num(c->D_final, e, sizeof e), num(c->bar.D_sep, f, sizeof f));
    else
      rep_table_row(t, REP_ROW_FAIL, "(no run)\t%g\t\t\t\t\t", h);
  }
}

static void table_stab(report *R)
{
  static const char *const head[5] = {"dt / dt_crit", "dt", "outcome", "RMS load error / Pmax", "delta reached"};
  rep_table *t = rep_doc_table(&R->doc, 5, head);
  const double base = ver_report_stab_base(&R->r);
  for (int i = 0; i < R->r.n; i++) {
    const rep_case *c = &R->r.c[i];
    if (!(c->role & REP_STAB))
      continue;
    const int o = ver_report_stab_outcome(c, base);
    char a[32], b[32];
    rep_table_row(t, o == REP_STABLE ? REP_ROW_PASS : o == REP_NOISY ? REP_ROW_KNOWN : REP_ROW_FAIL,
                  "%.2f\t%.4g\t%s\t%s\t%s", c->tag, c->dt,
                  o == REP_STABLE ? "stable" : o == REP_NOISY ? "noisy" : "blown up",
                  o == REP_BLOWN ? "-" : num(c->curve_err, a, sizeof a), num(c->delta_end, b, sizeof b));
  }
}

/* Cases with role among mask (pictures of snapback scenes, the scheme pair, ...). */
static void table_role(report *R, int mask)
{
  static const char *const head[8] = {"case", "method", "g", "peak P (analytic)", "drop width", "D (analytic)",
                                      "RMS load error", "run"};
  rep_table *t = rep_doc_table(&R->doc, 8, head);
  for (int i = 0; i < R->r.n; i++) {
    const rep_case *c = &R->r.c[i];
    if (!(c->role & mask) || !c->have)
      continue;
    char a[32], b[32], d[32], e[32], f[32], g[32], m[192];
    ver_report_method(c, m, sizeof m);
    rep_table_row(t, c->complete ? REP_ROW_PLAIN : REP_ROW_FAIL, "%s\t%s\t%s\t%s (%s)\t%s\t%s (%.4g)\t%s\t%s", c->id,
                  m, num(c->bar.g, a, sizeof a),
                  num(c->peak_P, b, sizeof b), num(c->bar.Pmax, d, sizeof d), num(c->drop_width, e, sizeof e),
                  num(c->D_final, f, sizeof f), c->bar.D_sep, num(c->curve_err, g, sizeof g),
                  c->complete ? "complete" : "stopped early");
  }
}

static void table_runs(report *R)
{
  static const char *const head[10] = {"case", "method", "complete", "delta end", "peak P", "delta peak", "D",
                                       "RMS load error", "CPU s", "from"};
  rep_table *t = rep_doc_table(&R->doc, 10, head);
  for (int i = 0; i < R->r.n; i++) {
    const rep_case *c = &R->r.c[i];
    if (!c->have) {
      rep_table_row(t, REP_ROW_FAIL, "%s\t\tno result\t\t\t\t\t\t\t", c->id);
      continue;
    }
    char a[32], b[32], d[32], e[32], m[192];
    ver_report_method(c, m, sizeof m);
    rep_table_row(t, c->complete || (c->role & REP_STAB) ? REP_ROW_PLAIN : REP_ROW_FAIL,
                  "%s\t%s\t%s\t%.3g\t%s\t%s\t%s\t%s\t%.3g\t%s", c->id, m,
                  c->complete ? "yes" : "NO", c->delta_end, num(c->peak_P, a, sizeof a),
                  num(c->delta_peak, b, sizeof b), num(c->D_final, d, sizeof d), num(c->curve_err, e, sizeof e),
                  c->cpu_s, c->reused ? "reused" : "run now");
  }
}

/* The figure "rate": fig6.ini's 1-ppc sweep and iface90.ini's runs, each against the
 * quasi-static curve and against the exact solution at the grip speed. */
static void table_rate(report *R)
{
  static const char *const head[7] = {"case", "method", "h", "peak P (exact at the speed)",
                                      "RMS load error / Pmax: quasi-static", "against the exact solution", "D"};
  rep_table *t = rep_doc_table(&R->doc, 7, head);
  for (int k = 0; k < 2; k++)
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = k ? ver_report_role_at(&R->r, REP_WAVE, h, 1) : ver_report_sweep(&R->r, "fig6", h, 1);
      if (!c)
        continue;
      char a[32], b[32], d[32], e[32], f[32], m[192];
      ver_report_method(c, m, sizeof m);
      rep_table_row(t, c->complete ? REP_ROW_PLAIN : REP_ROW_FAIL, "%s\t%s\t%g\t%s (%s)\t%s\t%s\t%s", c->id, m, h,
                    num(c->peak_P, a, sizeof a), num(c->wave_peak, b, sizeof b), num(c->curve_err, d, sizeof d),
                    num(c->curve_wave, e, sizeof e), num(c->D_final, f, sizeof f));
    }
}

/* The data table that goes with a figure, if any. */
static void fig_table(report *R, const char *name)
{
  if (!strcmp(name, "fig6b"))
    table_sweep(R, "fig6");
  else if (!strcmp(name, "conv")) {
    for (int s = 0; s < REP_NSWEEP; s++)
      table_sweep(R, rep_sweep_scene[s]);
    ver_report_static_table(R);
  }
  else if (!strcmp(name, "stab"))
    table_stab(R);
  else if (!strcmp(name, "rate"))
    table_rate(R);
  else if (!strcmp(name, "snapback"))
    table_role(R, REP_SNAP);
  else if (!strcmp(name, "scheme"))
    table_role(R, REP_SCHEME);
  else if (!strcmp(name, "separation"))
    table_role(R, REP_SEP);
  else if (!strcmp(name, "specimens"))
    ver_report_spec_table(R);
}

/* One figure's section from reports/text/<name>.md. */
static void fig_section(report *R, const rep_fig *f)
{
  char path[2 * REP_PATH];
  snprintf(path, sizeof path, "%s/text/%s.md", R->r.gpdir, f->name);
  rep_doc tmp = {0};
  char *title = NULL, *caption = NULL;
  rep_doc_template(&tmp, &R->vars, path, &title, &caption);
  rep_doc_head(&R->doc, 2, f->name, title ? title : f->name);
  rep_doc_fig(&R->doc, f->name, caption ? caption : title ? title : f->name, f->status != 0);
  for (int i = 0; i < tmp.n; i++)
    rep_doc_para(&R->doc, tmp.b[i].text);
  fig_table(R, f->name);
  free(title);
  free(caption);
  rep_doc_free(&tmp);
}

/* A template's paragraphs straight into the document (no title). */
static void text(report *R, const char *name)
{
  char path[2 * REP_PATH];
  snprintf(path, sizeof path, "%s/text/%s.md", R->r.gpdir, name);
  rep_doc_template(&R->doc, &R->vars, path, NULL, NULL);
}

void ver_report_compose(report *R)
{
  const rep_ctx *r = &R->r;
  char when[64];
  const time_t now = time(NULL);
  strftime(when, sizeof when, "%Y-%m-%d %H:%M", localtime(&now));
  int nrun = 0, nreused = 0, nincomplete = 0;
  for (int i = 0; i < r->n; i++) {
    nrun += r->c[i].have && !r->c[i].reused;
    nreused += r->c[i].reused;
    nincomplete += r->c[i].have && !r->c[i].complete && !(r->c[i].role & REP_STAB);
  }
  rep_vars_set(&R->vars, "report:when", "%s", when);
  rep_vars_set(&R->vars, "report:runs", "%d", r->n);
  rep_vars_set(&R->vars, "report:made", "%d", nrun);
  rep_vars_set(&R->vars, "report:reused", "%d", nreused);
  rep_vars_set(&R->vars, "report:incomplete", "%d", nincomplete);
  rep_vars_set(&R->vars, "report:t_runs", "%.0f", R->t_runs);
  rep_vars_set(&R->vars, "report:verify", "%s", R->verify_dir[0] ? R->verify_dir : "(none)");
  /* the summary, the contents and the figures first; the long tables after them */
  rep_doc_head(&R->doc, 1, "top", "delam: verification report");
  ver_report_verdict_summary(R);
  rep_doc_toc(&R->doc);
  ver_report_paper_table(R);
  for (int i = 0; i < R->nfig; i++)
    fig_section(R, &R->fig[i]);
  ver_report_verdicts(R);
  rep_doc_head(&R->doc, 2, "about", "How this report was made");
  text(R, "intro");
  rep_doc_head(&R->doc, 2, "runs", "All runs");
  text(R, "runs");
  table_runs(R);
}
