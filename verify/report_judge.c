/*
 * report_judge.c - the judging part of `delam report` (report.h): the checks of
 * `delam verify` (run here with --quick unless --from names a verify folder), shown
 * per case with its verdict and counted; and the numbers the paper states beside the
 * ones measured here, each with the rule it is held to.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "io.h"
#include "metrics.h"
#include "report.h"

#define PROG "delam report"

int ver_report_run_verify(report *R)
{
  rep_ctx *r = &R->r;
  snprintf(R->verify_dir, sizeof R->verify_dir, "%.1000s/verify", r->cache);
  char jobs[16], log[REP_PATH + 32];
  snprintf(jobs, sizeof jobs, "%d", r->jobs);
  snprintf(log, sizeof log, "%.1000s/verify.log", r->cache);
  char *argv[] = {r->exe, "verify", "--quick", "--out", R->verify_dir, "--scenes", r->scenes, "--jobs", jobs, NULL};
  char **argvs[1] = {argv};
  char *logs[1] = {log}, *names[1] = {"delam verify --quick"};
  int st = -1;
  fprintf(stderr, PROG ": the checks: delam verify --quick --out %s (log %s)\n", R->verify_dir, log);
  ver_report_spawn_all(argvs, NULL, logs, names, 1, 1, &st, "checks", NULL);
  R->verify_rc = st;
  if (st < 0 || st > 1)
    return 2;
  snprintf(r->from, sizeof r->from, "%s", R->verify_dir);
  return 0;
}

cJSON *ver_report_read_verify(const char *from)
{
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/verify.json", from);
  char *buf = ver_io_slurp(p, NULL, 0);
  if (!buf)
    return NULL;
  cJSON *o = cJSON_Parse(buf);
  free(buf);
  if (!o)
    fprintf(stderr, PROG ": %s is not JSON; going on without it\n", p);
  return o;
}

static const char *jstr(const cJSON *o, const char *k)
{
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
  return cJSON_IsString(v) ? v->valuestring : "";
}

static double jnum(const cJSON *o, const char *k)
{
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
  return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static int row_class(const char *verdict)
{
  return !strcmp(verdict, "pass") ? REP_ROW_PASS : !strcmp(verdict, "known-limit") ? REP_ROW_KNOWN : REP_ROW_FAIL;
}

/* The checks of a case that did not pass, as "name (verdict, err)" list. */
static void not_passed(const cJSON *checks, char *buf, size_t len)
{
  size_t n = 0;
  buf[0] = '\0';
  const cJSON *k;
  cJSON_ArrayForEach(k, checks)
  {
    const char *v = jstr(k, "verdict");
    if (!strcmp(v, "pass") || n + 80 > len)
      continue;
    n += (size_t)snprintf(buf + n, len - n, "%s%s %s (%+.3g)", n ? "; " : "", jstr(k, "name"), v,
                          jnum(k, "error"));
  }
  if (!n)
    snprintf(buf, len, "all pass");
}

static void verdict_cases(report *R, const cJSON *cases, int cnt[3])
{
  static const char *const head[6] = {"case", "verdict", "peak P", "D", "RMS load error", "checks not passed"};
  rep_table *t = rep_doc_table(&R->doc, 6, head);
  const cJSON *c;
  cJSON_ArrayForEach(c, cases)
  {
    const char *v = jstr(c, "verdict");
    const int k = row_class(v);
    cnt[k == REP_ROW_PASS ? 0 : k == REP_ROW_FAIL ? 1 : 2]++;
    double peak = NAN, D = NAN, l2 = NAN;
    const cJSON *ck;
    cJSON_ArrayForEach(ck, cJSON_GetObjectItemCaseSensitive(c, "checks"))
    {
      const char *nm = jstr(ck, "name");
      if (!strcmp(nm, "peak_P"))
        peak = jnum(ck, "measured");
      else if (!strcmp(nm, "D_final"))
        D = jnum(ck, "measured");
      else if (!strcmp(nm, "curve_l2"))
        l2 = jnum(ck, "measured");
    }
    char np[1200];
    not_passed(cJSON_GetObjectItemCaseSensitive(c, "checks"), np, sizeof np);
    rep_table_row(t, k, "%s\t%s\t%.4g\t%.4g\t%.3g\t%s", jstr(c, "id"), v, peak, D, l2, np);
  }
}

static void verdict_cross(report *R, const cJSON *cross, int cnt[3])
{
  static const char *const head[7] = {"scene", "check", "at", "measured", "tolerance", "verdict", "why"};
  rep_table *t = rep_doc_table(&R->doc, 7, head);
  const cJSON *x;
  cJSON_ArrayForEach(x, cross)
  {
    const char *v = jstr(x, "verdict");
    const int k = row_class(v);
    cnt[k == REP_ROW_PASS ? 0 : k == REP_ROW_FAIL ? 1 : 2]++;
    const char *held = strcmp(jstr(x, "over"), "h") ? "h" : "ppc"; /* what is held fixed */
    /* the reason where a verdict needs one: a known limit, a failure, or a pass of an
     * order below zero (under the curve floor, where an order means nothing) */
    const int why = k != REP_ROW_PASS || jnum(x, "measured") < 0.0;
    rep_table_row(t, k, "%s\t%s\t%s %g\t%.4g\t%.4g\t%s\t%s", jstr(x, "scene"), jstr(x, "name"), held, jnum(x, held),
                  jnum(x, "measured"), jnum(x, "tolerance"), v, why ? jstr(x, "note") : "");
  }
}

/* Every check of every case, for the record. */
static void verdict_all(report *R, const cJSON *cases)
{
  static const char *const head[8] = {"case", "check", "class", "measured", "reference", "tolerance", "verdict",
                                      "why (known limits and failures)"};
  rep_table *t = rep_doc_table(&R->doc, 8, head);
  const cJSON *c, *k;
  cJSON_ArrayForEach(c, cases)
  {
    cJSON_ArrayForEach(k, cJSON_GetObjectItemCaseSensitive(c, "checks"))
    {
      const char *v = jstr(k, "verdict");
      const int cls = row_class(v);
      rep_table_row(t, cls, "%s\t%s\t%s\t%.6g\t%.6g\t%.3g\t%s\t%s", jstr(c, "id"), jstr(k, "name"), jstr(k, "class"),
                    jnum(k, "measured"), jnum(k, "reference"), jnum(k, "tolerance"), v,
                    cls == REP_ROW_PASS ? "" : jstr(k, "note"));
    }
  }
}

/* Verdict counts of a JSON array of objects with "verdict". */
static void count(const cJSON *arr, int cnt[3])
{
  const cJSON *c;
  cJSON_ArrayForEach(c, arr)
  {
    const int k = row_class(jstr(c, "verdict"));
    cnt[k == REP_ROW_PASS ? 0 : k == REP_ROW_FAIL ? 1 : 2]++;
  }
}

void ver_report_verdict_summary(report *R)
{
  if (!R->verify) {
    rep_doc_para(&R->doc, "No verify.json was found, so no case is judged here: run make report (which runs "
                          "delam verify --quick first) or give --from a delam verify folder.");
    return;
  }
  const cJSON *cases = cJSON_GetObjectItemCaseSensitive(R->verify, "cases");
  const cJSON *cross = cJSON_GetObjectItemCaseSensitive(R->verify, "cross");
  const cJSON *s = cJSON_GetObjectItemCaseSensitive(R->verify, "summary");
  int cc[3] = {0, 0, 0}, xc[3] = {0, 0, 0};
  count(cases, cc);
  count(cross, xc);
  rep_vars *v = &R->vars;
  rep_vars_set(v, "verify:mode", "%s", jstr(R->verify, "mode"));
  rep_vars_set(v, "verify:cases", "%d", cc[0] + cc[1] + cc[2]);
  rep_vars_set(v, "verify:cases_pass", "%d", cc[0]);
  rep_vars_set(v, "verify:cases_fail", "%d", cc[1]);
  rep_vars_set(v, "verify:cases_known", "%d", cc[2]);
  rep_vars_set(v, "verify:checks_pass", "%.0f", jnum(s, "checks_pass"));
  rep_vars_set(v, "verify:checks_fail", "%.0f", jnum(s, "checks_fail"));
  rep_vars_set(v, "verify:checks_known", "%.0f", jnum(s, "checks_known_limit"));
  rep_vars_set(v, "verify:cross_pass", "%d", xc[0]);
  rep_vars_set(v, "verify:cross_fail", "%d", xc[1]);
  rep_vars_set(v, "verify:cross_known", "%d", xc[2]);
  char path[2 * REP_PATH];
  snprintf(path, sizeof path, "%s/text/verdicts.md", R->r.gpdir);
  rep_doc_template(&R->doc, v, path, NULL, NULL);
}

void ver_report_verdicts(report *R)
{
  rep_doc_head(&R->doc, 2, "verdicts", "Verdicts of the checks");
  if (!R->verify) {
    rep_doc_para(&R->doc, "No verify.json was found: no case is judged here.");
    return;
  }
  const cJSON *cases = cJSON_GetObjectItemCaseSensitive(R->verify, "cases");
  const cJSON *cross = cJSON_GetObjectItemCaseSensitive(R->verify, "cross");
  char path[2 * REP_PATH];
  snprintf(path, sizeof path, "%s/text/verdicts-key.md", R->r.gpdir);
  rep_doc_template(&R->doc, &R->vars, path, NULL, NULL);
  int dummy[3] = {0, 0, 0};
  verdict_cases(R, cases, dummy);
  verdict_cross(R, cross, dummy);
  rep_doc_head(&R->doc, 3, "checks", "Every check");
  verdict_all(R, cases);
}

/* The crack angle (the separated particles, lambda >= the run's separation threshold)
 * and band width (lambda > 0.5) of a case's final state. */
static void final_band(const rep_case *c, double *angle, double *band)
{
  *angle = *band = NAN;
  if (!c || !c->have)
    return;
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/final.csv", c->dir);
  static const char *const cols[3] = {"x0", "y0", "lambda"};
  double *v[3];
  const long n = ver_csv_read(p, cols, 3, v);
  if (n > 0) {
    *angle = ver_crack_angle(v[0], v[1], v[2], (size_t)n, c->sep_threshold);
    *band = ver_band_width(v[0], v[1], v[2], (size_t)n, VER_BAND_LAMBDA, c->bar.p.alpha_deg, c->h, c->ppc,
                           c->bar.p.H, NULL, NULL);
  }
  for (int j = 0; j < 3; j++)
    free(v[j]);
}

/* One row: agrees when lo <= measured <= hi. */
static void paper_row(rep_table *t, const char *what, const char *paper, double measured, const char *fmt,
                      const rep_case *c, const char *rule, double lo, double hi)
{
  char m[64];
  if (isfinite(measured))
    snprintf(m, sizeof m, fmt, measured);
  else
    snprintf(m, sizeof m, "n/a");
  const int ok = isfinite(measured) && measured >= lo && measured <= hi;
  rep_table_row(t, ok ? REP_ROW_PASS : REP_ROW_FAIL, "%s\t%s\t%s\t%s\t%s\t%s", what, paper, m,
                c ? c->id : "(no run)", rule, ok ? "agrees" : "differs");
}

void ver_report_paper_table(report *R)
{
  const rep_ctx *r = &R->r;
  rep_doc_head(&R->doc, 2, "paper", "The paper's numbers beside the measured ones");
  char path[2 * REP_PATH];
  snprintf(path, sizeof path, "%s/text/paper.md", r->gpdir);
  rep_doc_template(&R->doc, &R->vars, path, NULL, NULL);
  static const char *const head[6] = {"quantity", "paper", "measured", "case", "agrees when", "verdict"};
  rep_table *t = rep_doc_table(&R->doc, 6, head);
  const rep_case *f6 = ver_report_sweep(r, "fig6", 2, 4);
  /* the paper's method where the scene file chooses another (report_cases.c), else the
   * scene file's own run: these are the paper's numbers */
  const rep_case *f7 = ver_report_first(r, REP_PAPER, "fig7"), *f8 = ver_report_first(r, REP_PAPER, "fig8");
  if (!f7 || !f7->have)
    f7 = ver_report_first(r, REP_PIC, "fig7");
  if (!f8 || !f8->have)
    f8 = ver_report_first(r, REP_PIC, "fig8");
  paper_row(t, "Fig. 6: peak load", "32", f6 ? f6->peak_P : NAN, "%.4g", f6, "within 3 %", 32 * 0.97, 32 * 1.03);
  paper_row(t, "Fig. 6: elastic slope", "+171", f6 ? f6->k_elastic : NAN, "%+.4g", f6, "within 5 %", 171 * 0.95,
            171 * 1.05);
  paper_row(t, "Fig. 6: softening slope", "-171", f6 ? f6->k_soft : NAN, "%+.4g", f6, "within 5 %", -171 * 1.05,
            -171 * 0.95);
  paper_row(t, "Fig. 7: g (eq. 35)", "1.3", f7 && f7->bar_ok ? f7->bar.g : NAN, "%.3g", f7,
            "within 5 % (the paper rounds)", 1.3 * 0.95, 1.3 * 1.05);
  double angle, band;
  final_band(f7, &angle, &band);
  paper_row(t, "Fig. 7: angle of the failed band", "~60 deg", angle, "%.3g deg", f7, "within 10 deg", 50, 70);
  paper_row(t, "Fig. 7: width of the failed band", "~2 cells", band, "%.3g cells", f7, "1.5 to 2.5 cells", 1.5,
            2.5);
  paper_row(t, "Fig. 8: g (eq. 35)", "0.43 (0.446 by eq. 35)", f8 && f8->bar_ok ? f8->bar.g : NAN, "%.3g", f8,
            "within 5 % of 0.43", 0.43 * 0.95, 0.43 * 1.05);
  const rep_case *c1 = ver_report_sweep(r, "fig6", 8, 1), *c4 = ver_report_sweep(r, "fig6", 8, 4),
                 *c9 = ver_report_sweep(r, "fig6", 8, 9);
  const double r41 = c1 && c4 ? c4->curve_err / c1->curve_err : NAN;
  const double r94 = c4 && c9 ? c9->curve_err / c4->curve_err : NAN;
  paper_row(t, "Fig. 6(c): 4 ppc against 1 (load error ratio, h = 8)", "4 ppc better", r41, "%.3g", c4,
            "ratio below 1", 0, 1 - 1e-12);
  paper_row(t, "Fig. 6(c): 9 ppc against 4 (load error ratio, h = 8)", "9 ppc no better", r94, "%.3g", c9,
            "ratio 1 or more", 1, INFINITY);
}
