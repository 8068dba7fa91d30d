/*
 * cmd_report.c - `delam report [--from DIR] [--out DIR]`: the paper's figures and the
 * report around them.
 *
 * 1. Decides the cases the figures need (report_run.c), reuses complete results from
 *    --from or the cache out/report/<case-id>/, runs the rest as `delam run` children.
 * 2. Measures each run against the analytic bar (report_data.c) and writes the plot data
 *    to OUT/data/ (analytic curves, sweep tables, data/vars.gp with fitted numbers, and a
 *    link data/<case-id> to each run's folder).
 * 3. Runs the gnuplot scripts reports/<figure>.gp in OUT (PNG and SVG).
 * 4. Writes OUT/index.html and OUT/REPORT.md: per figure, the paper's claim and what
 *    was measured, with the numbers filled in here from the runs (never typed by hand).
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <dirent.h>

#include <cjson/cJSON.h>

#include "cmd.h"
#include "io.h"
#include "metrics.h"
#include "report.h"
#include "run.h"
#include "datadir.h"
#include "scene.h"
#include "summary.h"

#define PROG "delam report"

/* ---- growing strings, for the report text ---- */
typedef struct {
  char *s;
  size_t n, cap;
} sbuf;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void sb_printf(sbuf *b, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  char tmp[1];
  va_list aq;
  va_copy(aq, ap);
  const int k = vsnprintf(tmp, 0, fmt, aq);
  va_end(aq);
  if (k < 0) {
    va_end(ap);
    return;
  }
  if (b->n + (size_t)k + 1 > b->cap) {
    size_t cap = b->cap ? b->cap : 256;
    while (b->n + (size_t)k + 1 > cap)
      cap *= 2;
    char *ns = realloc(b->s, cap);
    if (!ns) {
      va_end(ap);
      return;
    }
    b->s = ns;
    b->cap = cap;
  }
  vsnprintf(b->s + b->n, b->cap - b->n, fmt, ap);
  b->n += (size_t)k;
  va_end(ap);
}

/* ---- the figures and their paragraphs ---- */
#define MAX_FIGS 24
typedef struct {
  char name[32];    /* reports/<name>.gp -> OUT/<name>.png, .svg */
  char title[160];
  sbuf text;
  int status;       /* gnuplot exit status for the PNG */
} fig;

typedef struct {
  rep_ctx r;
  fig f[MAX_FIGS];
  int nf;
  cJSON *verify;    /* --from DIR/verify.json, or NULL */
  int sweep_from;   /* sweep points taken from --from */
} report;

static fig *add_fig(report *R, const char *name, const char *title)
{
  if (R->nf >= MAX_FIGS)
    return NULL;
  fig *f = &R->f[R->nf++];
  memset(f, 0, sizeof *f);
  snprintf(f->name, sizeof f->name, "%s", name);
  snprintf(f->title, sizeof f->title, "%s", title);
  f->status = -1;
  return f;
}

/* ---- the case list ---- */
static const char *const sweep_scene[] = {"fig6", "fig7", "fig8"};
static const double sweep_until[] = {0.6, 1.2, 1.2};
#define NSWEEP 3
static const double stab_ratio[] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.72, 0.74, 0.76, 0.78, 0.8, 0.9, 1.0, 1.1};
#define NSTAB (int)(sizeof stab_ratio / sizeof stab_ratio[0])

/* h / c, MODEL.md's 1-D bound: the unit of the time-step sweep, so that the figure
 * shows where the step really fails (1/sqrt(2) of it).  The kernel validates the 2-D
 * bound mpm_scene_dt_crit() = h / (c sqrt 2). */
static double scene_dt_crit(const rep_ctx *r, const char *scene, double h)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0)
    return NAN;
  vs.sc.h = h;
  return sqrt(2.0) * mpm_scene_dt_crit(&vs.sc);
}

/* Does the scene table know time.scheme=musl (the modified-USL option)? */
static int knows_musl(const rep_ctx *r)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%s/fig6.ini", r->scenes);
  if (ver_scene_parse(path, &vs, err, sizeof err) != 0)
    return 0;
  return ver_scene_set(&vs, "time.scheme=musl", err, sizeof err) == 0;
}

/* The sweep case of (scene, h, ppc), or -1. */
static int find_sweep(const rep_ctx *r, const char *scene, double h, int ppc)
{
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if ((c->role & REP_SWEEP) && !strcmp(c->scene, scene) && c->h == h && c->ppc == ppc)
      return i;
  }
  return -1;
}

/* --from DIR: every DIR/<case>/summary.json run with the scene's defaults joins the sweep. */
static int scan_from(report *R)
{
  rep_ctx *r = &R->r;
  DIR *d = opendir(r->from);
  int n = 0;
  if (!d)
    return 0;
  const struct dirent *e;
  while ((e = readdir(d)) && r->n < REP_MAX_CASES) {
    if (e->d_name[0] == '.')
      continue;
    rep_case tmp;
    memset(&tmp, 0, sizeof tmp);
    snprintf(tmp.dir, sizeof tmp.dir, "%.800s/%.200s", r->from, e->d_name);
    if (ver_report_read_summary(&tmp) != 0 || !tmp.complete)
      continue;
    ver_summary_doc sd;
    if (ver_summary_read(tmp.dir, &sd) != 0)
      continue;
    int ok = sd.scene[0] && isfinite(sd.h) && sd.ppc > 0 && isfinite(sd.dt) &&
             (!sd.le[0] || !strcmp(sd.le, "cell")) && (!isfinite(sd.sep_threshold) || sd.sep_threshold == 0.98);
    /* the paper's time step only: dt / h as in the scene file */
    if (ok) {
      const double crit = scene_dt_crit(r, sd.scene, sd.h);
      const double ref = scene_dt_crit(r, sd.scene, 8.0);
      ok = isfinite(crit) && fabs(sd.dt / crit - 0.1 / ref) < 1e-6 && find_sweep(r, sd.scene, sd.h, sd.ppc) < 0;
    }
    if (ok) {
      rep_case *c = &r->c[r->n++];
      *c = tmp;
      snprintf(c->id, sizeof c->id, "%.80s", e->d_name);
      if (ver_report_find(r, c->id) != r->n - 1)
        snprintf(c->id, sizeof c->id, "%.80s@verify", e->d_name);
      snprintf(c->scene, sizeof c->scene, "%.31s", sd.scene);
      c->h = sd.h;
      c->ppc = sd.ppc;
      c->role = REP_SWEEP;
      c->have = c->reused = 1;
      c->exit_status = 0;
      c->last_snap = -1;
      c->curve_err = c->max_dev = c->diss_err = c->k_soft = c->drop_width = NAN;
      n++;
    }
  }
  closedir(d);
  return n;
}

static void build_cases(report *R)
{
  rep_ctx *r = &R->r;
  /* pictures: each scene's own run (its grid, all its snapshots) */
  /* Fig. 6(a) runs to delta = 5: under USL the gripped end tears once the bar end has
   * passed the gripped node column (nearly empty node, measured at delta = 2.0 on h = 4);
   * MUSL does not, so the pictures use it. */
  ver_report_add(r, "fig6", 4, 1, 0, 0, "time.scheme=musl", NULL, REP_PIC, 0);
  ver_report_add(r, "fig7", 2, 1, 0, 0, NULL, NULL, REP_PIC, 0);
  ver_report_add(r, "fig8", 2, 1, 0, 0, NULL, NULL, REP_PIC | REP_SNAP, 0);
  /* sweep over h and particles per cell, to a little past separation */
  const int from_n = r->from[0] ? scan_from(R) : 0;
  R->sweep_from = from_n;
  if (from_n)
    fprintf(stderr, PROG ": %d runs of %s join the h x ppc sweep\n", from_n, r->from);
  /* the sweep's points that --from does not have are run here */
  for (int s = 0; s < NSWEEP; s++)
      for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5)
        /* 9 ppc at h = 2 only where it is cheap (fig6 stops at 0.6): inclined runs to 1.2
         * at h = 2 with 9 ppc cost ~28 CPU-s each, a fifth of the report's budget */
        for (double h = 8; h >= (ppc == 1 ? 1 : ppc == 9 && s > 0 ? 4 : 2); h /= 2)
          if (find_sweep(r, sweep_scene[s], h, ppc) < 0)
            ver_report_add(r, sweep_scene[s], h, ppc, 0, sweep_until[s], NULL, NULL, REP_SWEEP, 0);
  /* time-step sweep: fig6, h = 8, 1 ppc, to delta 0.5 */
  const double crit = scene_dt_crit(r, "fig6", 8);
  for (int i = 0; i < NSTAB; i++)
    ver_report_add(r, "fig6", 8, 1, stab_ratio[i] * crit, 0.5, NULL, NULL, REP_STAB, stab_ratio[i]);
  /* snapback scenes (g < 1) on two grids */
  for (double h = 4; h >= 2; h /= 2) {
    ver_report_add(r, "a45", h, 1, 0, 0, NULL, NULL, REP_SNAP, 0);
    ver_report_add(r, "a30", h, 1, 0, 0, NULL, NULL, REP_SNAP, 0);
  }
  /* separation threshold */
  ver_report_add(r, "fig6", 8, 4, 0, 0.6, "decohesion.separation=0.98", NULL, REP_SEP, 0.98);
  ver_report_add(r, "fig6", 8, 4, 0, 0.6, "decohesion.separation=0.8", NULL, REP_SEP, 0.8);
  /* usl vs musl on an inclined scene, if the option exists */
  r->have_musl = knows_musl(r);
  if (r->have_musl) {
    ver_report_add(r, "fig7", 4, 1, 0, 1.0, "time.scheme=usl", NULL, REP_SCHEME, 0);
    ver_report_add(r, "fig7", 4, 1, 0, 1.0, "time.scheme=musl", NULL, REP_SCHEME, 1);
    ver_report_add(r, "fig8", 4, 1, 0, 1.0, "time.scheme=usl", NULL, REP_SCHEME, 0);
    ver_report_add(r, "fig8", 4, 1, 0, 1.0, "time.scheme=musl", NULL, REP_SCHEME, 1);
  }
}

/* ---- plot data ---- */
static FILE *open_data(const rep_ctx *r, const char *name)
{
  char p[REP_PATH + 96];
  snprintf(p, sizeof p, "%s/data/%s", r->out, name);
  FILE *f = fopen(p, "w");
  if (!f)
    fprintf(stderr, PROG ": cannot write %s: %s\n", p, strerror(errno));
  return f;
}

static void link_case(const rep_ctx *r, const rep_case *c)
{
  char link[REP_PATH + 128], target[2 * REP_PATH + 8];
  snprintf(link, sizeof link, "%s/data/%s", r->out, c->id);
  unlink(link);
  ver_report_abs(c->dir, target, sizeof target);
  if (symlink(target, link) != 0)
    fprintf(stderr, PROG ": cannot link %s to %s\n", link, c->dir);
}

/* Analytic load-deflection curve of a bar to delta_end. */
static void write_ana_curve(const rep_ctx *r, const char *name, const ana_bar *b, double delta_end)
{
  enum { NPT = 2001 };
  static double d[NPT], P[NPT];
  const int k = ana_bar_curve(b, delta_end, NPT, d, P);
  FILE *f = open_data(r, name);
  if (!f)
    return;
  fprintf(f, "delta,P\n");
  for (int i = 0; i < k; i++)
    fprintf(f, "%.10g,%.10g\n", d[i], P[i]);
  fclose(f);
}

static const rep_case *first_case(const rep_ctx *r, int role, const char *scene)
{
  for (int i = 0; i < r->n; i++)
    if ((r->c[i].role & role) && !strcmp(r->c[i].scene, scene))
      return &r->c[i];
  return NULL;
}

/* Fig. 3: sigma* against E e_ave / r0 for q = 0.8, 1, 1.2 and g = 0.75, 1.25, 2 (L chosen
 * for g: with r0 = 1 and alpha = 90, g = E U0 / L). */
static const double f3_q[] = {0.8, 1.0, 1.2}, f3_g[] = {0.75, 1.25, 2.0};

static void write_fig3(const rep_ctx *r, FILE *vars)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      ana_params p;
      ana_params_default(&p);
      p.q = f3_q[i];
      p.L = p.E * p.U0 / f3_g[j];
      ana_bar b;
      if (ana_bar_init(&p, &b, NULL, 0) != ANA_OK)
        continue;
      enum { NPT = 1201 };
      static double d[NPT], P[NPT];
      const int k = ana_bar_curve(&b, 2.6 * b.r0 * p.L / p.E, NPT, d, P);
      char name[64];
      snprintf(name, sizeof name, "fig3-q%g-g%g.csv", f3_q[i], f3_g[j]);
      FILE *f = open_data(r, name);
      if (!f)
        continue;
      fprintf(f, "estar,sstar\n");
      for (int m = 0; m < k; m++)
        fprintf(f, "%.10g,%.10g\n", d[m] / p.L * p.E / b.r0, P[m] / b.Pmax);
      fclose(f);
      fprintf(vars, "f3_snap_%d_%d = %d\n", i, j, b.snapback);
    }
}

typedef struct {
  double p_curve, c_curve, p_diss, c_diss; /* fitted err = exp(c) h^p (1 ppc)  */
  int n;                                   /* points in the fit                */
} conv_fit;

static conv_fit fits[NSWEEP];

static void write_sweeps(const rep_ctx *r, FILE *vars)
{
  for (int s = 0; s < NSWEEP; s++) {
    double hh[8], ec[8], ed[8];
    for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5) {
      char name[64];
      snprintf(name, sizeof name, "sweep-%s-ppc%d.dat", sweep_scene[s], ppc);
      FILE *f = open_data(r, name);
      if (!f)
        continue;
      fprintf(f, "h,curve_err,abs_diss_err,cpu_s,complete,particles\n");
      int n = 0;
      for (double h = 8; h >= 0.5; h /= 2) {
        const int k = find_sweep(r, sweep_scene[s], h, ppc);
        if (k < 0 || !r->c[k].have || !isfinite(r->c[k].curve_err))
          continue;
        const rep_case *c = &r->c[k];
        fprintf(f, "%g,%.6g,%.6g,%.6g,%d,%.0f\n", h, c->curve_err, fabs(c->diss_err), c->cpu_s, c->complete,
                c->particles);
        if (ppc == 1 && n < 8 && c->complete) {
          hh[n] = h;
          ec[n] = c->curve_err;
          ed[n] = fabs(c->diss_err);
          n++;
        }
      }
      fclose(f);
      if (ppc == 1) {
        conv_fit *cf = &fits[s];
        cf->n = n;
        cf->p_curve = ver_conv_order(hh, ec, (size_t)n, &cf->c_curve);
        cf->p_diss = ver_conv_order(hh, ed, (size_t)n, &cf->c_diss);
        fprintf(vars, "p_curve_%s = %.6g\nc_curve_%s = %.6g\np_diss_%s = %.6g\nc_diss_%s = %.6g\n",
                sweep_scene[s], isfinite(cf->p_curve) ? cf->p_curve : 0, sweep_scene[s],
                isfinite(cf->c_curve) ? cf->c_curve : -50, sweep_scene[s],
                isfinite(cf->p_diss) ? cf->p_diss : 0, sweep_scene[s], isfinite(cf->c_diss) ? cf->c_diss : -50);
      }
    }
  }
}

/* Time-step sweep outcome: blown up if the run failed or the load left any sane
 * range; noisy if its curve error exceeds the smallest-dt run's by more than a
 * third of... see STAB_NOISY. */
#define STAB_NOISY 0.02 /* curve error (RMS / Pmax) above the smallest dt's by this: noisy */

static int stab_outcome(const rep_case *c, double base)
{
  if (!c->have || c->exit_status != 0 || !isfinite(c->max_absP) || c->max_absP > 10 * c->bar.Pmax ||
      !isfinite(c->curve_err))
    return REP_BLOWN;
  return c->curve_err > base + STAB_NOISY ? REP_NOISY : REP_STABLE;
}

static double stab_base(const rep_ctx *r)
{
  double base = NAN;
  for (int i = 0; i < r->n; i++)
    if ((r->c[i].role & REP_STAB) && r->c[i].exit_status == 0 && isfinite(r->c[i].curve_err) &&
        !(r->c[i].curve_err >= base))
      base = r->c[i].curve_err;
  return isfinite(base) ? base : 0;
}

static void write_stab(const rep_ctx *r, FILE *vars)
{
  FILE *f = open_data(r, "stab.dat");
  if (!f)
    return;
  fprintf(f, "dt_ratio,dt,outcome,curve_err,delta_reached\n"); /* outcome: 0 stable, 1 noisy, 2 blown up */
  const double base = stab_base(r);
  sbuf ids = {0}, labs = {0};
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (!(c->role & REP_STAB))
      continue;
    const int o = stab_outcome(c, base);
    fprintf(f, "%.4g,%.6g,%d,%.6g,%.6g\n", c->tag, c->dt, o, isfinite(c->curve_err) ? c->curve_err : 1.0,
            c->delta_end);
    if (o != REP_BLOWN) {
      sb_printf(&ids, "%s%s", ids.n ? " " : "", c->id);
      sb_printf(&labs, "%s%.2f", labs.n ? " " : "", c->tag);
    }
  }
  fclose(f);
  fprintf(vars, "stab_ids = \"%s\"\nstab_labs = \"%s\"\n", ids.s ? ids.s : "", labs.s ? labs.s : "");
  free(ids.s);
  free(labs.s);
}

/* " (stopped at delta = X)" for a run that ended early, else "" (legend labels). */
static void write_note(FILE *vars, const char *key, const rep_case *c)
{
  if (c && c->have && !c->complete)
    fprintf(vars, "%s_note = \" (stopped at {/Symbol d} = %.3g)\"\n", key, c->delta_end);
  else
    fprintf(vars, "%s_note = \"\"\n", key);
}

static void write_vars_case(FILE *vars, const char *key, const rep_case *c)
{
  write_note(vars, key, c);
  fprintf(vars, "%s = \"%s\"\n%s_hw = %.6g\n", key, c ? c->id : "", key, c ? 0.5 * c->h / sqrt(c->ppc) : 1.0);
  fprintf(vars, "%s_end = %.6g\n", key, c && c->have ? c->delta_end : 0.0);
}

static void write_data(report *R)
{
  rep_ctx *r = &R->r;
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/data", r->out);
  ver_mkdir_p(p);
  FILE *vars = open_data(r, "vars.gp");
  if (!vars)
    return;
  fprintf(vars, "# written by delam report\n");
  for (int i = 0; i < r->n; i++)
    if (r->c[i].have)
      link_case(r, &r->c[i]);
  const char *scenes[] = {"fig6", "fig7", "fig8", "a45", "a30"};
  for (int s = 0; s < 5; s++) {
    const rep_case *c = NULL;
    for (int i = 0; i < r->n && !c; i++)
      if (!strcmp(r->c[i].scene, scenes[s]) && r->c[i].bar_ok)
        c = &r->c[i];
    if (!c)
      continue;
    char name[64];
    snprintf(name, sizeof name, "ana-%s.csv", scenes[s]);
    write_ana_curve(r, name, &c->bar, !strcmp(scenes[s], "fig6") ? 5.2 : 2.2);
    fprintf(vars, "Pmax_%s = %.6g\ng_%s = %.6g\nalpha_%s = %g\n", scenes[s], c->bar.Pmax, scenes[s], c->bar.g,
            scenes[s], c->bar.p.alpha_deg);
  }
  write_fig3(r, vars);
  write_sweeps(r, vars);
  write_stab(r, vars);
  write_vars_case(vars, "pic_fig6", first_case(r, REP_PIC, "fig6"));
  write_vars_case(vars, "pic_fig7", first_case(r, REP_PIC, "fig7"));
  write_vars_case(vars, "pic_fig8", first_case(r, REP_PIC, "fig8"));
  fprintf(vars, "dt_crit8 = %.6g\nhave_musl = %d\n", scene_dt_crit(r, "fig6", 8), r->have_musl);
  /* the sweep's ids by scene, h and ppc, for the load-deflection panels */
  for (int s = 0; s < NSWEEP; s++)
    for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5)
      for (double h = 8; h >= 1; h /= 2) {
        const int k = find_sweep(r, sweep_scene[s], h, ppc);
        char key[64];
        snprintf(key, sizeof key, "sw_%s_h%g_ppc%d", sweep_scene[s], h, ppc);
        fprintf(vars, "%s = \"%s\"\n", key, k >= 0 && r->c[k].have ? r->c[k].id : "");
        write_note(vars, key, k >= 0 ? &r->c[k] : NULL);
      }
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (c->role & (REP_SNAP | REP_SEP | REP_SCHEME)) {
      char key[128];
      snprintf(key, sizeof key, "id_%s", c->id);
      for (char *q = key; *q; q++)
        if (*q == '-' || *q == '.' || *q == '=')
          *q = '_';
      fprintf(vars, "%s = \"%s\"\n", key, c->have ? c->id : "");
      write_note(vars, key, c);
    }
  }
  fclose(vars);
}

/* ---- gnuplot ---- */
static void run_gnuplot(report *R)
{
  rep_ctx *r = &R->r;
  const int n = 2 * R->nf;
  char ***argvs = calloc((size_t)n, sizeof *argvs);
  char **logs = calloc((size_t)n, sizeof *logs), **names = calloc((size_t)n, sizeof *names);
  int *st = calloc((size_t)n, sizeof *st);
  enum { ALEN = 2 * REP_PATH + 256 };
  char *store = calloc((size_t)n, 6 * ALEN);
  char **avs = calloc((size_t)n * 6, sizeof *avs);
  if (!argvs || !logs || !names || !st || !store || !avs) {
    fprintf(stderr, PROG ": out of memory\n");
    goto out;
  }
  char gpabs[2 * REP_PATH + 8], logdir[REP_PATH + 16];
  ver_report_abs(r->gpdir, gpabs, sizeof gpabs);
  snprintf(logdir, sizeof logdir, "%s/logs", r->out);
  ver_mkdir_p(logdir);
  for (int i = 0; i < n; i++) {
    const fig *f = &R->f[i / 2];
    const char *fmt = i % 2 ? "svg" : "png";
    char *s = store + (size_t)i * 6 * ALEN;
    char **av = avs + (size_t)i * 6;
    snprintf(s, ALEN, "gnuplot");
    snprintf(s + ALEN, ALEN, "-e");
    snprintf(s + 2 * ALEN, ALEN, "fmt='%s'; gpdir='%.2000s'; name='%s'", fmt, gpabs, f->name);
    snprintf(s + 3 * ALEN, ALEN, "%.2000s/%s.gp", gpabs, f->name);
    for (int k = 0; k < 4; k++)
      av[k] = s + (size_t)k * ALEN;
    av[4] = NULL;
    argvs[i] = av;
    logs[i] = s + 4 * ALEN;
    /* logs are opened after chdir into OUT */
    snprintf(logs[i], ALEN, "logs/%s.%s.log", f->name, fmt);
    names[i] = s + 5 * ALEN;
    snprintf(names[i], ALEN, "%s.%s", f->name, fmt);
  }
  ver_report_spawn_all(argvs, r->out, logs, names, n, r->jobs, st, "gnuplot");
  for (int i = 0; i < n; i += 2) {
    R->f[i / 2].status = st[i];
    if (st[i] != 0 || st[i + 1] != 0)
      fprintf(stderr, PROG ": gnuplot %s failed (see %s/%s)\n", R->f[i / 2].name, r->out, logs[i]);
  }
out:
  free(argvs);
  free(logs);
  free(names);
  free(st);
  free(store);
  free(avs);
}

/* ---- the text ---- */
static const rep_case *cs(const rep_ctx *r, const char *id)
{
  const int k = ver_report_find(r, id);
  return k >= 0 && r->c[k].have ? &r->c[k] : NULL;
}

static const rep_case *sw(const rep_ctx *r, const char *scene, double h, int ppc)
{
  const int k = find_sweep(r, scene, h, ppc);
  return k >= 0 && r->c[k].have ? &r->c[k] : NULL;
}

/* How a run ended, in words. */
static void ended(sbuf *b, const rep_case *c)
{
  if (!c) {
    sb_printf(b, "the run is missing");
    return;
  }
  if (c->complete)
    sb_printf(b, "the run completed (to delta = %.3g, %ld steps, %.3g s CPU)", c->delta_end, c->steps, c->cpu_s);
  else
    sb_printf(b, "the run STOPPED EARLY at delta = %.3g (%s)", c->delta_end, c->error[0] ? c->error : "no message");
}

/* From a snapshot (delta < 0: final.csv): the width in cells of the band of particles
 * with lambda > lam_min (ver_band_width: their area over the crack length), the mean
 * vertical displacement of the left quarter of the bar, and the largest lambda. */
static void snapshot_stats(const rep_case *c, double delta, double lam_min, double *band, double *uy_left,
                           double *max_lam)
{
  *band = *uy_left = *max_lam = NAN;
  if (!c)
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
    /* damaged area / crack length, in cells (metrics.h) */
    *band = ver_band_width(v[0], v[1], v[3], (size_t)n, lam_min, c->bar.p.alpha_deg, c->h, c->ppc, c->bar.p.H,
                           NULL, NULL);
    *uy_left = nl ? su / nl : NAN;
    *max_lam = ml;
  }
  for (int j = 0; j < 4; j++)
    free(v[j]);
}

static void peak_words(sbuf *b, const rep_case *c)
{
  if (!c)
    return;
  sb_printf(b, "peak load %.4g (analytic %.4g, %+.1f %%) at delta = %.4g (analytic %.4g); elastic slope %.4g "
               "(analytic %.4g)",
            c->peak_P, c->bar.Pmax, 100 * (c->peak_P / c->bar.Pmax - 1), c->delta_peak, c->bar.delta_peak,
            c->k_elastic, c->bar.k_elastic);
}

static void text_fig3(report *R)
{
  fig *f = add_fig(R, "fig3", "Fig. 3: analytic stress-strain curves of the bar (snapback)");
  if (!f)
    return;
  sbuf *b = &f->text;
  sb_printf(b, "Paper (sec. 3.2, eqs. 34-36): the average strain of the bar is e = (r0/E)[s* + (1-s*)^(1/q) g]; the "
               "softening branch turns back (snapback, load reversal) when q (1-s*)^(1-1/q) > g, that is for q = 1 "
               "exactly when g < 1, for q > 1 when g < q, and for q < 1 always, just after the peak. "
               "Computed here with the analytic module (alpha = 90, r0 = 1, L = E U0 / g): ");
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      ana_params p;
      ana_params_default(&p);
      p.q = f3_q[i];
      p.L = p.E * p.U0 / f3_g[j];
      ana_bar bar;
      if (ana_bar_init(&p, &bar, NULL, 0) != ANA_OK)
        continue;
      sb_printf(b, "q = %g, g = %g: %s%s", f3_q[i], f3_g[j],
                bar.snapback ? "snapback" : "no snapback", i == 2 && j == 2 ? ". " : "; ");
    }
  sb_printf(b, "Snapback branches are the parts of the curves where the strain decreases while the stress falls.");
}

static void text_fig6(report *R)
{
  const rep_ctx *r = &R->r;
  const rep_case *pic = first_case(r, REP_PIC, "fig6");
  fig *f = add_fig(R, "fig6a", "Fig. 6(a): transverse laminate (alpha = 90), particles coloured by lambda, h = 4");
  if (!f)
    return;
  sbuf *b = &f->text;
  double band, uy, ml;
  snapshot_stats(pic, pic ? pic->last_snap : 5.0, 0.5, &band, &uy, &ml);
  sb_printf(b, "Paper: the decohesion stays in a single line of cells; the bar separates there and the left part "
               "moves with the grip. Measured (%s): ", pic ? pic->id : "no run");
  ended(b, pic);
  if (pic && pic->have) {
    sb_printf(b, "; ");
    peak_words(b, pic);
    sb_printf(b, "; separation detected at delta = %.4g (analytic %.4g). At the last picture the failed particles "
                 "(lambda >= 0.5) cover %.3g cells' width in all (a band one cell wide gives 1).",
              pic->delta_sep, pic->bar.delta_sep, band);
  }

  f = add_fig(R, "fig6b", "Fig. 6(b): load against deflection for h = 8, 4, 2, 1 (1 particle per cell)");
  if (!f)
    return;
  b = &f->text;
  sb_printf(b, "Paper: the load-deflection curves on the refined grids approach the analytic curve "
               "(peak 32, slopes +171 and -171, separation at delta = 0.375). Measured (RMS load error / Pmax over "
               "0 < delta <= the analytic separation point, or the peak if that comes later, as in delam verify): ");
  for (double h = 8; h >= 1; h /= 2) {
    const rep_case *c = sw(r, "fig6", h, 1);
    if (c)
      sb_printf(b, "h = %g: error %.3g, peak %.4g, softening slope %.4g, dissipation %.4g (analytic %.4g)%s%s", h,
                c->curve_err, c->peak_P, c->k_soft, c->D_final, c->bar.D_sep,
                c->complete ? "" : " (the run STOPPED EARLY)", h > 1 ? "; " : ".");
    else
      sb_printf(b, "h = %g: no run%s", h, h > 1 ? "; " : ".");
  }

  f = add_fig(R, "fig6c", "Fig. 6(c): load against deflection for 1, 4 and 9 particles per cell (h = 8)");
  if (!f)
    return;
  b = &f->text;
  const rep_case *c1 = sw(r, "fig6", 8, 1), *c4 = sw(r, "fig6", 8, 4), *c9 = sw(r, "fig6", 8, 9);
  sb_printf(b, "Paper: 4 particles per cell agree with the analytic curve clearly better than 1; 9 add nothing over 4. "
               "Measured RMS load error / Pmax: ");
  if (c1 && c4 && c9) {
    sb_printf(b, "1 ppc %.3g, 4 ppc %.3g, 9 ppc %.3g; peak loads %.4g, %.4g, %.4g; dissipation %.4g, %.4g, %.4g "
                 "(analytic %.4g). ",
              c1->curve_err, c4->curve_err, c9->curve_err, c1->peak_P, c4->peak_P, c9->peak_P, c1->D_final,
              c4->D_final, c9->D_final, c1->bar.D_sep);
    sb_printf(b, "So 4 ppc is %s than 1 (ratio %.2f) and 9 is %s than 4 (ratio %.2f).",
              c4->curve_err < c1->curve_err ? "better" : "NOT better", c4->curve_err / c1->curve_err,
              c9->curve_err < c4->curve_err ? "better" : "not better", c9->curve_err / c4->curve_err);
  } else {
    sb_printf(b, "runs missing.");
  }
}

static void text_inclined(report *R, const char *scene)
{
  const rep_ctx *r = &R->r;
  const rep_case *pic = first_case(r, REP_PIC, scene);
  const int mode1 = !strcmp(scene, "fig7");
  char name[32], title[160];
  double band, uy, ml;
  fig *f;
  sbuf *b;
  if (mode1) {
    f = add_fig(R, "fig7a", "Fig. 7(a): Mode I at 60 deg, decohesion at delta = 0.24, 0.25, 0.26, 0.28 (h = 2)");
    if (!f)
      return;
    b = &f->text;
    snapshot_stats(pic, 0.28, 0.01, &band, &uy, &ml);
    sb_printf(b, "Paper: the decohesion front propagates from the imperfection at close to 60 deg through the fixed "
                 "grid, in a band about two cells wide. Measured (%s): at delta = 0.28 the particles with lambda >= "
                 "0.01 cover a band %.3g cells wide (their area over the crack length); largest lambda %.3g; ",
              pic ? pic->id : "no run", band, ml);
    ended(b, pic);
    sb_printf(b, ".");
  }
  snprintf(name, sizeof name, "%s%s", scene, mode1 ? "b" : "a");
  snprintf(title, sizeof title, "Fig. %s(%s): Mode %s at 60 deg, particles at delta = 0.7, 1.2, 1.7, 2.0 (h = 2)",
           mode1 ? "7" : "8", mode1 ? "b" : "a", mode1 ? "I" : "II");
  f = add_fig(R, name, title);
  if (!f)
    return;
  b = &f->text;
  snapshot_stats(pic, -1, 0.5, &band, &uy, &ml);
  sb_printf(b, "Paper: the bar separates along the inclined band; %s Measured: ",
            mode1 ? "the left part moves off with the grip."
                  : "after separation the left part of the bar moves upward (shear transferred before separation).");
  ended(b, pic);
  if (pic && pic->have)
    sb_printf(b, "; at the last written state (delta = %.3g) the left quarter of the bar has moved by uy = %.3g on "
                 "average and the failed particles (lambda >= 0.5) form a band %.3g cells wide. Panels without a "
                 "picture are past the end of the run.",
              pic->delta_end, uy, band);
  else
    sb_printf(b, ".");

  snprintf(name, sizeof name, "%s%s", scene, mode1 ? "c" : "b");
  snprintf(title, sizeof title, "Fig. %s(%s): displacement trajectories at delta = 0.35 (h = 2, arrows scaled up)",
           mode1 ? "7" : "8", mode1 ? "c" : "b");
  f = add_fig(R, name, title);
  if (!f)
    return;
  b = &f->text;
  sb_printf(b, "Paper: the displacements at delta = 0.35 show the two parts of the bar moving apart across the "
               "inclined band%s. The arrows go from each particle's initial position towards its position at delta = "
               "0.35, with the displacement multiplied by the factor in the title.",
            mode1 ? "" : ", with a sliding (shear) component along it");

  snprintf(name, sizeof name, "%s%s", scene, mode1 ? "d" : "c");
  snprintf(title, sizeof title, "Fig. %s(%s): load against deflection, Mode %s at 60 deg", mode1 ? "7" : "8",
           mode1 ? "d" : "c", mode1 ? "I" : "II");
  f = add_fig(R, name, title);
  if (!f)
    return;
  b = &f->text;
  if (mode1)
    sb_printf(b, "Paper: the numerical softening slope is softer than the analytic one (extra dissipation in a band "
                 "about two cells wide), then a traction reversal handled by dropping the traction to zero, with an "
                 "abrupt load drop and ringing. ");
  else
    sb_printf(b, "Paper: the analytic solution predicts load reversal (g = 0.43 in the paper, %.3g by eq. 35); "
                 "numerically the spread band hides the reversal. ",
              pic ? pic->bar.g : NAN);
  sb_printf(b, "Measured (%s): ", pic ? pic->id : "no run");
  if (pic && pic->have) {
    peak_words(b, pic);
    sb_printf(b, "; softening slope %.4g (analytic just after the peak %.4g); the load fell from 0.9 to 0.1 of its "
                 "peak over delta %.3g; dissipation %.4g against the analytic %.4g (%+.0f %%); ",
              pic->k_soft, pic->bar.k_soft_peak, pic->drop_width, pic->D_final, pic->bar.D_sep,
              100 * pic->diss_err);
  }
  ended(b, pic);
  sb_printf(b, ".");
}

static void text_conv(report *R)
{
  const rep_ctx *r = &R->r;
  fig *f = add_fig(R, "conv", "Convergence: load-curve and dissipation errors against h (1 particle per cell)");
  if (!f)
    return;
  sbuf *b = &f->text;
  sb_printf(b, "Paper: a convergence study over h (sec. 4.4). Curve error = RMS of (P - P_analytic) / Pmax over "
               "0 < delta <= the analytic separation point (or the peak, for snapback bars; the definition delam verify uses); dissipation error = |D / (U0 H / sin alpha) - 1| at the "
               "end of the run; orders are least-squares slopes of log error against log h over the complete runs. ");
  if (R->sweep_from)
    sb_printf(b, "%d of the runs come from %s (each to its own end); ", R->sweep_from, r->from);
  sb_printf(b, "%suns made by delam report go to delta %g (%s), %g (%s), %g (%s). ", R->sweep_from ? "r" : "R",
            sweep_until[0], sweep_scene[0],
            sweep_until[1], sweep_scene[1], sweep_until[2], sweep_scene[2]);
  for (int s = 0; s < NSWEEP; s++) {
    const conv_fit *cf = &fits[s];
    sb_printf(b, "%s: curve-error order %.2f, dissipation-error order %.2f over %d grids (", sweep_scene[s],
              cf->p_curve, cf->p_diss, cf->n);
    int first = 1;
    for (double h = 8; h >= 1; h /= 2) {
      const rep_case *c = sw(r, sweep_scene[s], h, 1);
      if (!c)
        continue;
      sb_printf(b, "%sh = %g: %.3g, %.3g%s", first ? "" : "; ", h, c->curve_err, fabs(c->diss_err),
                c->complete ? "" : " (stopped early, not fitted)");
      first = 0;
    }
    sb_printf(b, ")%s", s + 1 < NSWEEP ? ". " : ".");
  }
  if (R->verify) {
    const cJSON *x;
    int first = 1;
    cJSON_ArrayForEach(x, cJSON_GetObjectItemCaseSensitive(R->verify, "cross"))
    {
      const cJSON *nm = cJSON_GetObjectItemCaseSensitive(x, "name"), *sc = cJSON_GetObjectItemCaseSensitive(x, "scene");
      const cJSON *m = cJSON_GetObjectItemCaseSensitive(x, "measured"), *v = cJSON_GetObjectItemCaseSensitive(x, "verdict");
      if (!cJSON_IsString(nm) || strncmp(nm->valuestring, "order", 5) || !cJSON_IsNumber(m))
        continue;
      sb_printf(b, "%s%s %s %.3g (%s)", first ? " delam verify measured: " : "; ",
                cJSON_IsString(sc) ? sc->valuestring : "?", nm->valuestring, m->valuedouble,
                cJSON_IsString(v) ? v->valuestring : "?");
      first = 0;
    }
    sb_printf(b, "%sThe checks of delam verify are listed at the end of this report.", first ? " " : ". ");
  }
}

static void text_workprec(report *R)
{
  const rep_ctx *r = &R->r;
  fig *f = add_fig(R, "workprec", "Work-precision: load-curve error against CPU time");
  if (!f)
    return;
  sbuf *b = &f->text;
  sb_printf(b, "One line per number of particles per cell, one point per grid (h = 8 on the left, then 4, 2, 1). "
               "Cheapest run within 5 %% RMS load error, per scene: ");
  for (int s = 0; s < NSWEEP; s++) {
    const rep_case *best = NULL;
    for (int i = 0; i < r->n; i++) {
      const rep_case *c = &r->c[i];
      if ((c->role & REP_SWEEP) && c->have && !strcmp(c->scene, sweep_scene[s]) && c->curve_err < 0.05 &&
          (!best || c->cpu_s < best->cpu_s))
        best = c;
    }
    if (best)
      sb_printf(b, "%s: h = %g with %d ppc (error %.3g, %.3g s)", sweep_scene[s], best->h, best->ppc, best->curve_err,
                best->cpu_s);
    else
      sb_printf(b, "%s: none", sweep_scene[s]);
    sb_printf(b, "%s", s + 1 < NSWEEP ? "; " : ". ");
  }
  double ups = 0;
  int nu = 0;
  for (int i = 0; i < r->n; i++)
    if (r->c[i].have && r->c[i].cpu_s > 0.5 && r->c[i].steps > 0) {
      /* per CPU second: wall-clock rates depend on what else the machine runs */
      ups += r->c[i].particles * (double)r->c[i].steps / r->c[i].cpu_s;
      nu++;
    }
  if (nu)
    sb_printf(b, "The kernel ran at %.3g particle-updates per CPU second on average (runs over 0.5 s CPU, one thread "
                 "each).",
              ups / nu);
}

static void text_stab(report *R)
{
  const rep_ctx *r = &R->r;
  fig *f = add_fig(R, "stab", "Stability: time-step sweep (fig6, h = 8, 1 ppc, to delta 0.5)");
  if (!f)
    return;
  sbuf *b = &f->text;
  const double crit = scene_dt_crit(r, "fig6", 8), base = stab_base(r);
  double last_ok = NAN, first_bad = NAN;
  sb_printf(b, "MODEL.md: the explicit step is stable for dt < dt_crit = h / c = %.4g (c = sqrt(E/(1-nu^2)/rho)); the "
               "paper uses dt = 0.1 = %.2f dt_crit. Outcome per run: blown up if delam run failed or |P| exceeded "
               "10 Pmax; noisy if the RMS load error exceeds the smallest-dt run's (%.3g) by more than %.2g; stable "
               "otherwise. Measured: ",
            crit, 0.1 / crit, base, STAB_NOISY);
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (!(c->role & REP_STAB))
      continue;
    const int o = stab_outcome(c, base);
    if (o == REP_STABLE && !(c->tag < last_ok))
      last_ok = c->tag;
    if (o != REP_STABLE && !(c->tag > first_bad))
      first_bad = c->tag;
    sb_printf(b, "%.2f: %s", c->tag, o == REP_STABLE ? "stable" : o == REP_NOISY ? "noisy" : "blown up");
    if (o == REP_BLOWN)
      sb_printf(b, " at delta %.3g", c->delta_end);
    else
      sb_printf(b, " (error %.3g)", c->curve_err);
    sb_printf(b, "; ");
  }
  sb_printf(b, "largest stable dt / dt_crit %.2f, smallest unstable %.2f.", last_ok, first_bad);
  /* the 1-D bound of MODEL.md is not the grid's: a 2-D explicit bilinear grid with
   * lumped mass is bounded by h / (c sqrt 2) (the diagonal mode) */
  if (last_ok < 1 / sqrt(2.0) && first_bad > 1 / sqrt(2.0))
    sb_printf(b, " The limit lies between the two, where 1/sqrt(2) = %.3f is: the observed bound is the 2-D one, "
                 "dt < h / (c sqrt 2), not the 1-D h / c of MODEL.md, and it is the one delam run validates; the "
                 "paper's dt = 0.1 keeps a factor %.2f to it.",
              1 / sqrt(2.0), crit / sqrt(2.0) / 0.1);
}

static void text_snapback(report *R)
{
  const rep_ctx *r = &R->r;
  fig *f = add_fig(R, "snapback", "Snapback scenes (analytic g < 1): a45, a30 and fig8 against the analytic curve");
  if (!f)
    return;
  sbuf *b = &f->text;
  sb_printf(b, "Analytic: for q = 1 the softening branch turns back when g < 1, so under displacement control the "
               "load must drop vertically at the peak. Measured: ");
  const char *ids[] = {"a45-h4-ppc1", "a45-h2-ppc1", "a30-h4-ppc1", "a30-h2-ppc1", NULL};
  for (int i = 0; ids[i]; i++) {
    const rep_case *c = cs(r, ids[i]);
    if (!c) {
      sb_printf(b, "%s: no result; ", ids[i]);
      continue;
    }
    sb_printf(b, "%s (g = %.3g): peak %.4g (analytic %.4g), load fell from 0.9 to 0.1 of its peak over delta %.3g, "
                 "dissipation %.4g (analytic %.4g), %s; ",
              c->id, c->bar.g, c->peak_P, c->bar.Pmax, c->drop_width, c->D_final, c->bar.D_sep,
              c->complete ? "complete" : "stopped early");
  }
  const rep_case *c = first_case(r, REP_PIC, "fig8");
  if (c && c->have)
    sb_printf(b, "%s (g = %.3g): peak %.4g (analytic %.4g), drop over delta %.3g.", c->id, c->bar.g, c->peak_P,
              c->bar.Pmax, c->drop_width);
}

static void text_sep(report *R)
{
  const rep_ctx *r = &R->r;
  fig *f = add_fig(R, "separation", "Separation threshold: lambda = 0.8 against 0.98 (fig6, h = 8, 4 ppc)");
  if (!f)
    return;
  sbuf *b = &f->text;
  const rep_case *a = cs(r, "fig6-h8-ppc4-u0.6-separation0.98"), *c = cs(r, "fig6-h8-ppc4-u0.6-separation0.8");
  sb_printf(b, "Paper (sec. 4.3): the separation algorithm takes over at lambda = 0.98; 0.8 made no difference. ");
  if (a && c)
    sb_printf(b, "Measured: threshold 0.98: peak %.4g, RMS error %.3g, dissipation %.4g, separation at delta %.4g; "
                 "threshold 0.8: peak %.4g, RMS error %.3g, dissipation %.4g, separation at delta %.4g.",
              a->peak_P, a->curve_err, a->D_final, a->delta_sep, c->peak_P, c->curve_err, c->D_final, c->delta_sep);
  else
    sb_printf(b, "Runs missing.");
}

static void text_scheme(report *R)
{
  const rep_ctx *r = &R->r;
  if (!r->have_musl)
    return;
  fig *f = add_fig(R, "scheme", "Update scheme: USL (paper) against modified USL (fig7 and fig8, h = 4)");
  if (!f)
    return;
  sbuf *b = &f->text;
  sb_printf(b, "The paper updates the stress after the particles (USL); MUSL recomputes the grid velocity from the "
               "updated particle momenta first. The inclined scene files (fig7, fig8, a45, a30) choose MUSL, because "
               "USL was seen to throw particles off the grid after an inclined separation. Measured (to delta = 1): ");
  const char *ids[] = {"fig7-h4-ppc1-u1-schemeusl", "fig7-h4-ppc1-u1-schememusl", "fig8-h4-ppc1-u1-schemeusl",
                       "fig8-h4-ppc1-u1-schememusl", NULL};
  for (int i = 0; ids[i]; i++) {
    const rep_case *c = cs(r, ids[i]);
    if (c)
      sb_printf(b, "%s: peak %.4g, RMS error %.3g, dissipation %.4g (analytic %.4g), %s%s", c->id, c->peak_P,
                c->curve_err, c->D_final, c->bar.D_sep, c->complete ? "complete" : "stopped early",
                ids[i + 1] ? "; " : ".");
  }
}

/* ---- index.html and REPORT.md ---- */
static void html_escape(FILE *f, const char *s)
{
  for (; s && *s; s++) {
    if (*s == '<')
      fputs("&lt;", f);
    else if (*s == '>')
      fputs("&gt;", f);
    else if (*s == '&')
      fputs("&amp;", f);
    else
      fputc(*s, f);
  }
}

/* Every object below node with a "verdict" and a "measured" value is one check; it is
 * named by the nearest case "id" above it (or its own scene and "over"). */
static void collect_checks(const cJSON *node, const char *ctx, FILE *md, FILE *html, int count[3])
{
  if (!node)
    return;
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(node, "verdict");
  const cJSON *id = cJSON_GetObjectItemCaseSensitive(node, "id");
  if (cJSON_IsObject(node) && v && cJSON_GetObjectItemCaseSensitive(node, "measured")) {
    const cJSON *nm = cJSON_GetObjectItemCaseSensitive(node, "name");
    const cJSON *sc = cJSON_GetObjectItemCaseSensitive(node, "scene");
    const cJSON *over = cJSON_GetObjectItemCaseSensitive(node, "over");
    char name[256];
    if (cJSON_IsString(sc) && cJSON_IsString(over))
      snprintf(name, sizeof name, "%.60s %.80s (over %.20s)", sc->valuestring,
               cJSON_IsString(nm) ? nm->valuestring : "?", over->valuestring);
    else
      snprintf(name, sizeof name, "%.100s %.100s", ctx, cJSON_IsString(nm) ? nm->valuestring : "?");
    char verdict[32];
    if (cJSON_IsString(v))
      snprintf(verdict, sizeof verdict, "%s", v->valuestring);
    else
      snprintf(verdict, sizeof verdict, "%s", cJSON_IsTrue(v) ? "pass" : "fail");
    const int k = !strcmp(verdict, "pass") || !strcmp(verdict, "PASS") ? 0
                  : !strcmp(verdict, "fail") || !strcmp(verdict, "FAIL") ? 1 : 2;
    count[k]++;
    char val[3][64];
    const char *keys[3] = {"measured", "reference", "tolerance"};
    for (int i = 0; i < 3; i++) {
      const cJSON *x = cJSON_GetObjectItemCaseSensitive(node, keys[i]);
      if (cJSON_IsNumber(x))
        snprintf(val[i], sizeof val[i], "%.4g", x->valuedouble);
      else if (cJSON_IsString(x))
        snprintf(val[i], sizeof val[i], "%.60s", x->valuestring);
      else
        snprintf(val[i], sizeof val[i], "-");
    }
    fprintf(md, "| %s | %s | %s | %s | %s |\n", name, val[0], val[1], val[2], verdict);
    fprintf(html, "<tr class=\"%s\"><td>", k == 0 ? "pass" : k == 1 ? "fail" : "known");
    html_escape(html, name);
    fprintf(html, "</td><td>%s</td><td>%s</td><td>%s</td><td>", val[0], val[1], val[2]);
    html_escape(html, verdict);
    fprintf(html, "</td></tr>\n");
    return;
  }
  const char *sub = cJSON_IsString(id) ? id->valuestring : ctx;
  const cJSON *ch;
  cJSON_ArrayForEach(ch, node)
  {
    if (cJSON_IsObject(ch) || cJSON_IsArray(ch))
      collect_checks(ch, sub, md, html, count);
  }
}

static int write_report(report *R, double t_runs, double t_total)
{
  const rep_ctx *r = &R->r;
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/REPORT.md", r->out);
  FILE *md = fopen(p, "w");
  snprintf(p, sizeof p, "%s/index.html", r->out);
  FILE *html = fopen(p, "w");
  if (!md || !html) {
    fprintf(stderr, PROG ": cannot write the report in %s\n", r->out);
    if (md)
      fclose(md);
    if (html)
      fclose(html);
    return 1;
  }
  char when[64];
  const time_t now = time(NULL);
  strftime(when, sizeof when, "%Y-%m-%d %H:%M", localtime(&now));
  int nrun = 0, nreused = 0, nincomplete = 0;
  for (int i = 0; i < r->n; i++) {
    nrun += r->c[i].have && !r->c[i].reused;
    nreused += r->c[i].reused;
    nincomplete += r->c[i].have && !r->c[i].complete && !(r->c[i].role & REP_STAB);
  }
  fprintf(md, "# delam: verification report\n\nSchreyer, Sulsky and Zhou (2002), \"Modeling delamination as a strong "
              "discontinuity with the material point method\": the paper's figures reproduced with the delam kernel. "
              "Written by `delam report` on %s: %d runs (%d made now, %d reused from the cache%s), runs took %.0f s, "
              "the whole report %.0f s. %d of the runs meant to complete stopped early (see the table at the end).\n\n",
          when, r->n, nrun, nreused, r->from[0] ? " or --from" : "", t_runs, t_total, nincomplete);
  fprintf(html, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>delam report</title>\n<style>"
                "body{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em;line-height:1.4}"
                "img{max-width:100%%;border:1px solid #ccc}td,th{border:1px solid #ccc;padding:2px 6px;font-size:90%%}"
                "table{border-collapse:collapse}tr.fail td{background:#fdd}tr.pass td{background:#efe}"
                "tr.known td{background:#ffd}"
                "</style></head><body>\n<h1>delam: verification report</h1>\n<p>Schreyer, Sulsky and Zhou (2002), "
                "&ldquo;Modeling delamination as a strong discontinuity with the material point method&rdquo;: the "
                "paper's figures reproduced with the delam kernel. Written by <code>delam report</code> on %s: %d runs "
                "(%d made now, %d reused), runs took %.0f s, the whole report %.0f s. %d of the runs meant to complete "
                "stopped early (see the table at the end).</p>\n",
          when, r->n, nrun, nreused, t_runs, t_total, nincomplete);
  for (int i = 0; i < R->nf; i++) {
    const fig *f = &R->f[i];
    fprintf(md, "## %s\n\n![%s](%s.png)\n\n%s\n\n", f->title, f->name, f->name, f->text.s ? f->text.s : "");
    fprintf(html, "<h2 id=\"%s\">", f->name);
    html_escape(html, f->title);
    fprintf(html, "</h2>\n<a href=\"%s.svg\"><img src=\"%s.png\" alt=\"%s\"></a>\n<p>", f->name, f->name, f->name);
    if (f->status != 0)
      fprintf(html, "<b>(gnuplot failed for this figure; see logs/%s.png.log)</b> ", f->name);
    html_escape(html, f->text.s);
    fprintf(html, "</p>\n");
  }
  if (R->verify) {
    int cnt[3] = {0, 0, 0};
    fprintf(md, "## Checks from delam verify (%s/verify.json)\n\n| check | measured | reference | tolerance | verdict |\n"
                "|---|---|---|---|---|\n", r->from);
    fprintf(html, "<h2>Checks from delam verify</h2>\n<table><tr><th>check</th><th>measured</th><th>reference</th>"
                  "<th>tolerance</th><th>verdict</th></tr>\n");
    collect_checks(R->verify, "", md, html, cnt);
    fprintf(md, "\n%d passed, %d failed, %d at a known limit of the method (the paper reports the same deviation).\n\n",
            cnt[0], cnt[1], cnt[2]);
    fprintf(html, "</table>\n<p>%d passed, %d failed, %d at a known limit of the method (the paper reports the "
                  "same deviation).</p>\n", cnt[0], cnt[1], cnt[2]);
  } else if (r->from[0]) {
    fprintf(md, "(No %s/verify.json: numbers above come from the runs' summary.json files.)\n\n", r->from);
    fprintf(html, "<p>(No verify.json in --from: numbers above come from the runs' summary.json files.)</p>\n");
  }
  fprintf(md, "## All runs\n\n| case | complete | delta end | peak P | delta peak | D | RMS err | CPU s | from |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  fprintf(html, "<h2>All runs</h2>\n<table><tr><th>case</th><th>complete</th><th>delta end</th><th>peak P</th>"
                "<th>delta peak</th><th>D</th><th>RMS err</th><th>CPU s</th><th>from</th></tr>\n");
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (!c->have) {
      fprintf(md, "| %s | no result | | | | | | | |\n", c->id);
      fprintf(html, "<tr class=\"fail\"><td>%s</td><td colspan=8>no result</td></tr>\n", c->id);
      continue;
    }
    const char *src = c->reused ? "reused" : "run now";
    fprintf(md, "| %s | %s | %.3g | %.4g | %.4g | %.4g | %.3g | %.3g | %s |\n", c->id, c->complete ? "yes" : "NO",
            c->delta_end, c->peak_P, c->delta_peak, c->D_final, c->curve_err, c->cpu_s, src);
    fprintf(html, "<tr class=\"%s\"><td>%s</td><td>%s</td><td>%.3g</td><td>%.4g</td><td>%.4g</td><td>%.4g</td>"
                  "<td>%.3g</td><td>%.3g</td><td>%s</td></tr>\n",
            c->complete ? "pass" : "fail", c->id, c->complete ? "yes" : "no", c->delta_end, c->peak_P,
            c->delta_peak, c->D_final, c->curve_err, c->cpu_s, src);
  }
  fprintf(html, "</table>\n</body></html>\n");
  const int werr = ferror(md) || ferror(html);
  fclose(md);
  fclose(html);
  return werr ? 1 : 0;
}

static cJSON *read_verify(const char *from)
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

static void usage(FILE *f)
{
  fprintf(f, "usage: " PROG " [--from DIR] [--out DIR] [options]\n"
             "Runs the cases the paper's figures need (or reuses them), plots them with gnuplot\n"
             "(reports/*.gp; PNG and SVG) and writes OUT/index.html and OUT/REPORT.md.\n\n"
             "options:\n"
             "  --from DIR     a `delam verify` output folder: DIR/verify.json and DIR/<case-id>/ runs\n"
             "  --out DIR      where the report goes (default reports/out)\n"
             "  --cache DIR    where runs are kept and reused (default out/report)\n"
             "  --scenes DIR   scene files (default: $DELAM_SCENES, ./data/scenes, or the\n"
             "                 installed or source tree's scenes)\n"
             "  --gp DIR       gnuplot scripts (default reports)\n"
             "  --jobs N       runs at once (default 2)\n"
             "  --rerun        ignore cached runs\n"
             "  --help         this text\n"
             "exit status: 0 report written, 1 some figure or run is missing, 2 bad usage\n");
}

int ver_cmd_report(int argc, char **argv)
{
  static report R;
  memset(&R, 0, sizeof R);
  rep_ctx *r = &R.r;
  snprintf(r->out, sizeof r->out, "reports/out");
  snprintf(r->cache, sizeof r->cache, "out/report");
  const char *scenes = ver_scene_dir();
  snprintf(r->scenes, sizeof r->scenes, "%s", scenes ? scenes : "data/scenes");
  snprintf(r->gpdir, sizeof r->gpdir, "reports");
  r->jobs = 2;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    char *dst = NULL;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(a, "--rerun")) {
      r->rerun = 1;
      continue;
    } else if (!strcmp(a, "--from"))
      dst = r->from;
    else if (!strcmp(a, "--out"))
      dst = r->out;
    else if (!strcmp(a, "--cache"))
      dst = r->cache;
    else if (!strcmp(a, "--scenes"))
      dst = r->scenes;
    else if (!strcmp(a, "--gp"))
      dst = r->gpdir;
    else if (!strcmp(a, "--jobs")) {
      char *end;
      const long j = v ? strtol(v, &end, 10) : 0;
      if (!v || *end || j < 1 || j > 64) {
        fprintf(stderr, PROG ": --jobs: '%s' is not an integer in [1, 64]\n", v ? v : "");
        return 2;
      }
      r->jobs = (int)j;
      i++;
      continue;
    } else {
      fprintf(stderr, PROG ": unknown argument '%s' (see " PROG " --help)\n", a);
      return 2;
    }
    if (!v || !*v) {
      fprintf(stderr, PROG ": %s needs a folder\n", a);
      return 2;
    }
    snprintf(dst, REP_PATH, "%s", v);
    i++;
  }
  if (r->from[0]) {
    struct stat st;
    if (stat(r->from, &st) != 0 || !S_ISDIR(st.st_mode)) {
      fprintf(stderr, PROG ": --from: '%s' is not a folder\n", r->from);
      return 2;
    }
    R.verify = read_verify(r->from);
  }
  const ssize_t k = readlink("/proc/self/exe", r->exe, sizeof r->exe - 1);
  if (k <= 0) {
    fprintf(stderr, PROG ": cannot find the delam program (/proc/self/exe)\n");
    return 2;
  }
  r->exe[k] = '\0';
  char probe[REP_PATH + 32];
  snprintf(probe, sizeof probe, "%s/fig6.ini", r->scenes);
  if (access(probe, R_OK) != 0) {
    fprintf(stderr, PROG ": no scene files in '%s' (run from the repository, or give --scenes)\n", r->scenes);
    return 2;
  }
  if (ver_mkdir_p(r->out) != 0 || ver_mkdir_p(r->cache) != 0) {
    fprintf(stderr, PROG ": cannot create %s or %s\n", r->out, r->cache);
    return 2;
  }
  const double t0 = ver_now_wall();
  build_cases(&R);
  const int missing = ver_report_run_cases(r);
  const double t_runs = ver_now_wall() - t0;
  for (int i = 0; i < r->n; i++)
    ver_report_measure(r, &r->c[i]);
  write_data(&R);
  text_fig3(&R);
  text_fig6(&R);
  text_inclined(&R, "fig7");
  text_inclined(&R, "fig8");
  text_conv(&R);
  text_workprec(&R);
  text_stab(&R);
  text_snapback(&R);
  text_sep(&R);
  text_scheme(&R);
  run_gnuplot(&R);
  int bad = missing;
  for (int i = 0; i < R.nf; i++)
    bad += R.f[i].status != 0;
  const int rc = write_report(&R, t_runs, ver_now_wall() - t0);
  for (int i = 0; i < R.nf; i++)
    free(R.f[i].text.s);
  cJSON_Delete(R.verify);
  fprintf(stderr, PROG ": %s/index.html and %s/REPORT.md written in %.1f s%s\n", r->out, r->out,
          ver_now_wall() - t0, bad ? " (with missing parts, see above)" : "");
  return rc ? 1 : bad ? 1 : 0;
}
