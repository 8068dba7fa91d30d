/*
 * report_text.c - the words of `delam report` (report.h): which figures, in which
 * order; the placeholders their templates (reports/text/<figure>.md) are filled with,
 * set here from the runs; the data tables beside them; and the document as a whole.
 * The prose itself is in the templates.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "io.h"
#include "metrics.h"
#include "report.h"

/* The figures, in order; "scheme" only where time.scheme=musl exists, "rate" only where
 * the scene folder has iface90.ini (its cases, REP_WAVE), "specimens" only where it has
 * dcb.ini (REP_SPEC). */
static const char *const FIGS[] = {"fig3", "fig6a", "fig6b", "fig6c", "fig7a", "fig7b", "fig7c", "fig7d",
                                   "fig8a", "fig8b", "fig8c", "energy", "conv", "rate", "workprec", "stab",
                                   "snapback", "separation", "scheme", "specimens"};

void ver_report_plan_figs(report *R)
{
  R->nfig = 0;
  int wave = 0, spec = 0;
  for (int k = 0; k < R->r.n; k++) {
    wave |= (R->r.c[k].role & REP_WAVE) != 0;
    spec |= (R->r.c[k].role & REP_SPEC) != 0;
  }
  for (size_t i = 0; i < sizeof FIGS / sizeof FIGS[0] && R->nfig < REP_MAX_FIGS; i++) {
    if (!strcmp(FIGS[i], "scheme") && !R->r.have_musl)
      continue;
    if (!strcmp(FIGS[i], "rate") && !wave)
      continue;
    if (!strcmp(FIGS[i], "specimens") && !spec)
      continue;
    rep_fig *f = &R->fig[R->nfig++];
    snprintf(f->name, sizeof f->name, "%s", FIGS[i]);
    f->status = -1;
  }
}

/* ---- placeholders ---- */

static void num(report *R, const char *key, const char *field, double x)
{
  char k[160];
  snprintf(k, sizeof k, "%s:%s", key, field);
  rep_vars_num(&R->vars, k, x);
}

static void word(report *R, const char *key, const char *field, const char *w)
{
  char k[160];
  snprintf(k, sizeof k, "%s:%s", key, field);
  rep_vars_set(&R->vars, k, "%s", w);
}

/* How a run ended, in words. */
static void ended(const rep_case *c, char *buf, size_t len)
{
  if (c->complete)
    snprintf(buf, len, "the run completed (to delta = %.3g, %ld steps, %.3g s CPU)", c->delta_end, c->steps,
             c->cpu_s);
  else
    snprintf(buf, len, "the run STOPPED EARLY at delta = %.3g (%.200s)", c->delta_end,
             c->error[0] ? c->error : "no message");
}

/* Every field of case c under the name key ("key:field"). */
static void case_vars(report *R, const char *key, const rep_case *c)
{
  if (!c || !c->have) {
    word(R, key, "id", c ? c->id : "(no run)");
    word(R, key, "ended", "the run is missing");
    return;
  }
  char buf[400];
  word(R, key, "id", c->id);
  ver_report_method(c, buf, sizeof buf);
  word(R, key, "method", buf);
  num(R, key, "h", c->h);
  num(R, key, "ppc", c->ppc);
  num(R, key, "peak_P", c->peak_P);
  num(R, key, "delta_peak", c->delta_peak);
  num(R, key, "delta_sep", c->delta_sep >= 0 ? c->delta_sep : NAN);
  num(R, key, "k_elastic", c->k_elastic);
  num(R, key, "k_soft", c->k_soft);
  num(R, key, "D_final", c->D_final);
  num(R, key, "curve_err", c->curve_err);
  num(R, key, "curve_wave", c->curve_wave);
  num(R, key, "wave_peak", c->wave_peak);
  num(R, key, "drop_width", c->drop_width);
  num(R, key, "delta_end", c->delta_end);
  num(R, key, "cpu_s", c->cpu_s);
  snprintf(buf, sizeof buf, "%+.1f", 100 * (c->peak_P / c->bar.Pmax - 1));
  word(R, key, "peak_pct", buf);
  snprintf(buf, sizeof buf, "%+.0f", 100 * c->diss_err);
  word(R, key, "D_pct", buf);
  ended(c, buf, sizeof buf);
  word(R, key, "ended", buf);
  word(R, key, "complete", c->complete ? "complete" : "stopped early");
  num(R, key, "Pmax", c->bar.Pmax);
  num(R, key, "ana_delta_peak", c->bar.delta_peak);
  num(R, key, "ana_delta_sep", c->bar.delta_sep);
  num(R, key, "ana_k_elastic", c->bar.k_elastic);
  num(R, key, "ana_k_soft", c->bar.k_soft_peak);
  num(R, key, "D_sep", c->bar.D_sep);
  num(R, key, "g", c->bar.g);
}

/* From a snapshot (delta < 0: final.csv): the band width in cells of the particles
 * with lambda > lam_min (ver_band_width), the mean vertical displacement of the left
 * quarter of the bar, and the largest lambda. */
static void snapshot_stats(const rep_case *c, double delta, double lam_min, double *band, double *uy_left,
                           double *max_lam)
{
  *band = *uy_left = *max_lam = NAN;
  if (!c || !c->have)
    return;
  char p[REP_PATH + 48];
  if (delta < 0)
    snprintf(p, sizeof p, "%s/final.csv", c->dir);
  else
    snprintf(p, sizeof p, "%s/snap-d%.3f.csv", c->dir, delta);
  static const char *const cols[4] = {"x0", "y0", "uy", "lambda"};
  double *v[4];
  const long n = ver_csv_read(p, cols, 4, v);
  if (n > 0) {
    int nl = 0;
    double su = 0, ml = 0;
    for (long i = 0; i < n; i++) {
      ml = fmax(ml, v[3][i]);
      if (v[0][i] < 0.25 * c->bar.p.L) {
        su += v[2][i];
        nl++;
      }
    }
    *band = ver_band_width(v[0], v[1], v[3], (size_t)n, lam_min, c->bar.p.alpha_deg, c->h, c->ppc, c->bar.p.H,
                           NULL, NULL);
    *uy_left = nl ? su / nl : NAN;
    *max_lam = ml;
  }
  for (int j = 0; j < 4; j++)
    free(v[j]);
}

/* decohesion.path = interface: the smallest and largest lambda of the line's segments in
 * case c's snapshot at delta; 0 when it has no line file. */
static int line_lambda(const rep_case *c, double delta, double *lo, double *hi)
{
  if (!c || !c->have)
    return 0;
  char p[REP_PATH + 48];
  if (delta < 0.0) /* the end of the run */
    snprintf(p, sizeof p, "%s/final-line.csv", c->dir);
  else
    snprintf(p, sizeof p, "%s/snap-d%.3f-line.csv", c->dir, delta);
  static const char *const col[1] = {"lambda"};
  double *v[1];
  const long n = ver_csv_read(p, col, 1, v);
  *lo = INFINITY;
  *hi = -INFINITY;
  for (long k = 0; k < n; k++) {
    *lo = fmin(*lo, v[0][k]);
    *hi = fmax(*hi, v[0][k]);
  }
  free(v[0]);
  return n > 0;
}

/* The pictures' cases and what their snapshots show. */
static void pic_vars(report *R)
{
  const rep_ctx *r = &R->r;
  static const char *const sc[3] = {"fig6", "fig7", "fig8"};
  for (int i = 0; i < 3; i++) {
    char key[32];
    snprintf(key, sizeof key, "paper_%s", sc[i]);
    const rep_case *pc = ver_report_first(r, REP_PAPER, sc[i]);
    case_vars(R, key, pc ? pc : ver_report_first(r, REP_PIC, sc[i]));
    if (i > 0) { /* the interface beside the scene file's method (report_cases.c), or the file's own */
      snprintf(key, sizeof key, "iface_%s", sc[i]);
      const rep_case *ic = ver_report_first(r, REP_IFACE, sc[i]), *own = ver_report_first(r, REP_PIC, sc[i]);
      char s[600], m[192] = "";
      if (ic && ic->have) {
        ver_report_method(ic, m, sizeof m);
        snprintf(s, sizeof s, "With the crack as a cohesive interface (%s, %s; docs/methods.md, the scene file "
                 "otherwise as written): peak %.4g (%+.1f %% against the analytic %.4g), softening slope %.4g, "
                 "dissipation %.4g (%+.1f %% against the analytic).", ic->id, m, ic->peak_P,
                 100.0 * (ic->peak_P / ic->bar.Pmax - 1.0), ic->bar.Pmax, ic->k_soft, ic->D_final, 100.0 * ic->diss_err);
      } else if (own && !strcmp(own->path, "interface")) {
        snprintf(s, sizeof s, "The scene file's own method is the cohesive interface (docs/methods.md): its curves "
                 "above are the interface's.");
      } else {
        snprintf(s, sizeof s, "The cohesive interface did not run here (the scene file does not take it).");
      }
      word(R, key, "para", s);
    }
    snprintf(key, sizeof key, "pic_%s", sc[i]);
    const rep_case *c = ver_report_first(r, REP_PIC, sc[i]);
    case_vars(R, key, c);
    double band, uy, ml;
    snapshot_stats(c, c ? c->last_snap : -1, VER_BAND_LAMBDA, &band, &uy, &ml);
    num(R, key, "band_last", band);
    snapshot_stats(c, -1, VER_BAND_LAMBDA, &band, &uy, &ml);
    num(R, key, "band_final", band);
    num(R, key, "uy_final", uy);
    { /* what failed at the end: a band of particles, or the interface's line */
      double lo, hi;
      char s[300];
      const int line = line_lambda(c, -1.0, &lo, &hi);
      if (line && lo == hi)
        snprintf(s, sizeof s, "no particle fails (decohesion.path = interface): every segment of the line ends at "
                 "lambda %.3g", lo);
      else if (line)
        snprintf(s, sizeof s, "no particle fails (decohesion.path = interface): the line's segments end at lambda "
                 "%.3g to %.3g", lo, hi);
      else
        snprintf(s, sizeof s, "the failed particles (lambda > 0.5) form a band %.3g cells wide", band);
      word(R, key, "failed_final", s);
    }
    char pkey[32]; /* the paper's method's left quarter, beside */
    snprintf(pkey, sizeof pkey, "paper_%s", sc[i]);
    snapshot_stats(pc ? pc : c, -1, VER_BAND_LAMBDA, &band, &uy, &ml);
    num(R, pkey, "uy_final", uy);
    if (i == 1) {
      snapshot_stats(c, 0.28, 0.01, &band, &uy, &ml);
      num(R, key, "band028", band);
      num(R, key, "lam028", ml);
      /* what the picture at 0.28 shows: a band of particles, or the interface's line */
      double lo, hi;
      char s[300];
      if (line_lambda(c, 0.28, &lo, &hi))
        snprintf(s, sizeof s, "no particle softens (decohesion.path = interface): the line's segments carry lambda "
                 "%.3g to %.3g", lo, hi);
      else
        snprintf(s, sizeof s, "the particles with lambda > 0.01 form a band %.3g cells wide (their area over the crack "
                 "length); the largest lambda is %.3g", band, ml);
      word(R, key, "front028", s);
    }
  }
}

/* Fig. 3: snapback or not for q = 0.8, 1, 1.2 and g = 0.75, 1.25, 2. */
static void fig3_vars(report *R)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      ana_bar b;
      char key[64];
      snprintf(key, sizeof key, "fig3:q%g:g%g", rep_fig3_q[i], rep_fig3_g[j]);
      rep_vars_set(&R->vars, key, "%s",
                   ver_report_fig3_bar(i, j, &b) != 0 ? "n/a" : b.snapback ? "snapback" : "no snapback");
    }
}

/* Fig. 6(c): 1, 4 and 9 particles per cell at h = 8. */
static void ppc_vars(report *R)
{
  const rep_ctx *r = &R->r;
  const rep_case *c1 = ver_report_sweep(r, "fig6", 8, 1), *c4 = ver_report_sweep(r, "fig6", 8, 4),
                 *c9 = ver_report_sweep(r, "fig6", 8, 9);
  const double r41 = c1 && c4 ? c4->curve_err / c1->curve_err : NAN;
  const double r94 = c4 && c9 ? c9->curve_err / c4->curve_err : NAN;
  rep_vars_num(&R->vars, "ppc:ratio_4_1", r41);
  rep_vars_num(&R->vars, "ppc:ratio_9_4", r94);
  rep_vars_set(&R->vars, "ppc:4_vs_1", "%s", r41 < 1 ? "better" : "NOT better");
  rep_vars_set(&R->vars, "ppc:9_vs_4", "%s", r94 < 1 ? "better" : "not better");
}

/* Convergence fits and the cheapest run within 5 % per scene. */
static void sweep_vars(report *R)
{
  const rep_ctx *r = &R->r;
  for (int s = 0; s < REP_NSWEEP; s++) {
    const char *sc = rep_sweep_scene[s];
    char key[64];
    snprintf(key, sizeof key, "fit:%s", sc);
    num(R, key, "p_curve", R->fits[s].p_curve);
    /* whether the curve approaches the analytic one, in words (fig6b's text) */
    word(R, key, "approach", R->fits[s].p_curve >= 0.5 ? "approaches the analytic one" : "does NOT approach the analytic one");
    if (R->fits[s].n > 0 && R->fits[s].n_diss_exact == R->fits[s].n)
      word(R, key, "p_diss", "none (D exact to rounding on every grid)");
    else /* the fit leaves out any grid at rounding */
      num(R, key, "p_diss", R->fits[s].p_diss);
    num(R, key, "n", R->fits[s].n);
    num(R, key, "until", rep_sweep_until[s]);
    const rep_case *best = NULL;
    for (int i = 0; i < r->n; i++) {
      const rep_case *c = &r->c[i];
      if ((c->role & REP_SWEEP) && c->have && !strcmp(c->scene, sc) && c->curve_err < 0.05 &&
          (!best || c->cpu_s < best->cpu_s))
        best = c;
    }
    snprintf(key, sizeof key, "best:%s", sc);
    if (best)
      rep_vars_set(&R->vars, key, "h = %g with %d ppc (error %.3g, %.3g s)", best->h, best->ppc, best->curve_err,
                   best->cpu_s);
    else
      rep_vars_set(&R->vars, key, "none");
  }
  double ups = 0;
  int nu = 0;
  for (int i = 0; i < r->n; i++)
    if (r->c[i].have && !r->c[i].static_run && r->c[i].cpu_s > 0.5 && r->c[i].steps > 0) {
      ups += r->c[i].particles * (double)r->c[i].steps / r->c[i].cpu_s;
      nu++;
    }
  rep_vars_num(&R->vars, "run:updates_per_cpu_s", nu ? ups / nu : NAN);
  rep_vars_num(&R->vars, "run:sweep_from", R->sweep_from);
  rep_vars_set(&R->vars, "run:from", "%s", R->r.from[0] ? R->r.from : "(none)");
}

/* The figure "rate": iface90.ini's runs by h (rate_iface_h<h>), and how far the exact
 * solution at the grip speed itself lies from the quasi-static curve (rate:static). */
static void rate_vars(report *R)
{
  const rep_ctx *r = &R->r;
  const rep_case *w = NULL;
  for (double h = 8; h >= 1; h /= 2) {
    const rep_case *q = ver_report_role_at(r, REP_WAVE, h, 1);
    char key[64];
    snprintf(key, sizeof key, "rate_iface_h%g", h);
    case_vars(R, key, q);
    if (q && q->have && q->bar_ok && isfinite(q->wave_peak))
      w = q;
  }
  double e = NAN;
  if (w) {
    const ana_wave_params wp = ver_report_wave_params(w);
    ana_wave a;
    if (ana_wave_init(&w->bar, &wp, w->cmp_end + 0.01, &a, NULL, 0) == ANA_OK) {
      enum { N = 2000 };
      static double d[N], P[N];
      for (int i = 0; i < N; i++) {
        d[i] = w->cmp_end * (i + 1) / N;
        P[i] = ana_wave_load_at(&a, d[i] - 0.5 * w->cmp_end / N); /* at the interval's midpoint */
      }
      e = ver_curve_err_bar(&w->bar, d, P, N, w->cmp_end, NULL, 0);
      ana_wave_free(&a);
    }
    num(R, "rate", "speed", w->speed);
  }
  num(R, "rate", "static", e);
}

/* The time-step sweep's bounds. */
static void stab_vars(report *R)
{
  const rep_ctx *r = &R->r;
  const double crit = ver_report_dt_crit(r, "fig6", 8), base = ver_report_stab_base(r);
  double last_ok = NAN, first_bad = NAN;
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (!(c->role & REP_STAB))
      continue;
    const int o = ver_report_stab_outcome(c, base);
    if (o == REP_STABLE && !(c->tag < last_ok))
      last_ok = c->tag;
    if (o != REP_STABLE && !(c->tag > first_bad))
      first_bad = c->tag;
  }
  rep_vars_num(&R->vars, "stab:crit", crit);
  rep_vars_set(&R->vars, "stab:paper_ratio", "%.2f", 0.1 / crit);
  rep_vars_num(&R->vars, "stab:base", base);
  rep_vars_num(&R->vars, "stab:noisy", REP_STAB_NOISY);
  rep_vars_set(&R->vars, "stab:last_ok", "%.2f", last_ok);
  rep_vars_set(&R->vars, "stab:first_bad", "%.2f", first_bad);
  const double b = 1 / sqrt(2.0);
  rep_vars_set(&R->vars, "stab:bracket", "%s", last_ok < b && first_bad > b ? "lies" : "does NOT lie");
  rep_vars_set(&R->vars, "stab:margin", "%.2f", crit * b / 0.1);
}

void ver_report_set_vars(report *R)
{
  const rep_ctx *r = &R->r;
  for (int i = 0; i < r->n; i++)
    case_vars(R, r->c[i].id, &r->c[i]);
  for (int s = 0; s < REP_NSWEEP; s++)
    for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5)
      for (double h = 8; h >= 1; h /= 2) {
        char key[64];
        snprintf(key, sizeof key, "sw_%s_h%g_ppc%d", rep_sweep_scene[s], h, ppc);
        case_vars(R, key, ver_report_sweep(r, rep_sweep_scene[s], h, ppc));
      }
  pic_vars(R);
  fig3_vars(R);
  ppc_vars(R);
  sweep_vars(R);
  stab_vars(R);
  rate_vars(R);
  ver_report_static_vars(R);
  ver_report_qs_vars(R);
  ver_report_spec_vars(R);
}
