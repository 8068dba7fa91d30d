/*
 * report_plot.c - the plot data of `delam report` (OUT/data/: analytic curves, sweep
 * tables, vars.gp with the fitted numbers and case ids, a copy of each run's result
 * files) and the gnuplot runs over reports/<figure>.gp (report.h).
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io.h"
#include "metrics.h"
#include "report.h"

#define PROG "delam report"

static void data_failed(const rep_ctx *r, const char *path, int e)
{
  fprintf(stderr, PROG ": %s: cannot write: %s\n", path, strerror(e));
  if (r->io_bad)
    (*r->io_bad)++;
}

FILE *ver_report_open_data(const rep_ctx *r, const char *name)
{
  char p[REP_PATH + 96];
  snprintf(p, sizeof p, "%s/data/%s", r->out, name);
  FILE *f = fopen(p, "w");
  if (!f)
    data_failed(r, p, errno);
  return f;
}

/* Closes a file of ver_report_open_data; one that could not be written whole (a full disk) is
 * removed and counted, so that no figure is drawn from part of it. */
void ver_report_close_data(const rep_ctx *r, FILE *f, const char *name)
{
  char p[REP_PATH + 96];
  snprintf(p, sizeof p, "%s/data/%s", r->out, name);
  const int bad = ferror(f);
  int e = bad ? (errno ? errno : EIO) : 0;
  if (fclose(f) != 0 && !e)
    e = errno ? errno : EIO;
  if (e) {
    remove(p);
    data_failed(r, p, e);
  }
}

/* A copy of the run's result files in OUT/data/<id>/ (CSV and JSON; the particle
 * snapshots only for the pictures): the report folder holds everything it shows, and
 * no link points out of it. */
static void copy_case(const rep_ctx *r, const rep_case *c)
{
  char dst[REP_PATH + 128];
  snprintf(dst, sizeof dst, "%s/data/%s", r->out, c->id);
  struct stat st;
  if (lstat(dst, &st) == 0 && S_ISLNK(st.st_mode))
    unlink(dst); /* a link left by an older report */
  if (ver_mkdir_p(dst) != 0) {
    fprintf(stderr, PROG ": cannot create %s\n", dst);
    return;
  }
  DIR *d = opendir(c->dir);
  for (const struct dirent *e = d ? readdir(d) : NULL; e; e = readdir(d)) {
    const char *n = e->d_name;
    const size_t l = strlen(n);
    const int pic_only = !strncmp(n, "snap-", 5) || !strncmp(n, "final", 5); /* only pictures draw these */
    const int keep = !strcmp(n + l - 4, ".csv") || !strcmp(n + l - 5, ".json") || !strcmp(n, "scene.ini");
    if (l > 5 && keep && (!pic_only || (c->role & REP_PIC))) {
      char a[2 * REP_PATH + 64], b[2 * REP_PATH + 256];
      snprintf(a, sizeof a, "%s/%s", c->dir, n);
      snprintf(b, sizeof b, "%s/%s", dst, n);
      if (ver_io_copy(a, b) != 0)
        data_failed(r, b, errno);
    }
  }
  if (d)
    closedir(d);
}

/* Analytic load-deflection curve of a bar to delta_end. */
static void write_ana_curve(const rep_ctx *r, const char *name, const ana_bar *b, double delta_end)
{
  enum { NPT = 2001 };
  static double d[NPT], P[NPT];
  const int k = ana_bar_curve(b, delta_end, NPT, d, P);
  FILE *f = ver_report_open_data(r, name);
  if (!f)
    return;
  fprintf(f, "delta,P\n");
  for (int i = 0; i < k; i++)
    fprintf(f, "%.10g,%.10g\n", d[i], P[i]);
  ver_report_close_data(r, f, name);
}

/* The figure "rate": the exact solution at the grip speed of iface90.ini's bar (Fig. 6's)
 * as wave.csv, and rate.dat, the curve errors of fig6.ini's 1-ppc sweep and of
 * iface90.ini's runs against the quasi-static curve and against that solution by h;
 * vars rate_fig6_h<h>, rate_iface_h<h> (case ids). */
static void write_rate(const rep_ctx *r, FILE *vars)
{
  const rep_case *w = NULL;
  for (int i = 0; i < r->n && !w; i++)
    if ((r->c[i].role & REP_WAVE) && r->c[i].have && r->c[i].bar_ok && isfinite(r->c[i].wave_peak))
      w = &r->c[i];
  fprintf(vars, "have_rate = %d\n", w != NULL);
  if (!w)
    return;
  char err[200];
  const ana_wave_params wp = ver_report_wave_params(w);
  ana_wave a;
  if (ana_wave_init(&w->bar, &wp, 0.6, &a, err, sizeof err) == ANA_OK) {
    FILE *f = ver_report_open_data(r, "wave.csv");
    if (f) {
      fprintf(f, "delta,P\n");
      for (int i = 0; i <= 1200; i++)
        fprintf(f, "%.10g,%.10g\n", 0.0005 * i, ana_wave_load_at(&a, 0.0005 * i));
      ver_report_close_data(r, f, "wave.csv");
    }
    ana_wave_free(&a);
  }
  FILE *f = ver_report_open_data(r, "rate.dat");
  if (f)
    fprintf(f, "# h fig6_static fig6_exact iface90_static iface90_exact\n");
  for (double h = 8; h >= 1; h /= 2) {
    const rep_case *p = ver_report_sweep(r, "fig6", h, 1), *q = ver_report_role_at(r, REP_WAVE, h, 1);
    if (f)
      fprintf(f, "%g %.6g %.6g %.6g %.6g\n", h, p ? p->curve_err : NAN, p ? p->curve_wave : NAN, q ? q->curve_err : NAN,
              q ? q->curve_wave : NAN);
    fprintf(vars, "rate_fig6_h%g = \"%s\"\nrate_iface_h%g = \"%s\"\n", h, p ? p->id : "", h, q ? q->id : "");
  }
  if (f)
    ver_report_close_data(r, f, "rate.dat");
}

/* Fig. 3: sigma* against E e_ave / r0 for q = 0.8, 1, 1.2 and g = 0.75, 1.25, 2 (L chosen
 * for g: with r0 = 1 and alpha = 90, g = E U0 / L). */
const double rep_fig3_q[3] = {0.8, 1.0, 1.2}, rep_fig3_g[3] = {0.75, 1.25, 2.0};

int ver_report_fig3_bar(int i, int j, ana_bar *b)
{
  ana_params p;
  ana_params_default(&p);
  p.q = rep_fig3_q[i];
  p.L = p.E * p.U0 / rep_fig3_g[j];
  return ana_bar_init(&p, b, NULL, 0) == ANA_OK ? 0 : -1;
}

static void write_fig3(const rep_ctx *r, FILE *vars)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      ana_bar b;
      if (ver_report_fig3_bar(i, j, &b) != 0)
        continue;
      const ana_params p = b.p;
      enum { NPT = 1201 };
      static double d[NPT], P[NPT];
      const int k = ana_bar_curve(&b, 2.6 * b.r0 * p.L / p.E, NPT, d, P);
      char name[64];
      snprintf(name, sizeof name, "fig3-q%g-g%g.csv", rep_fig3_q[i], rep_fig3_g[j]);
      FILE *f = ver_report_open_data(r, name);
      if (!f)
        continue;
      fprintf(f, "estar,sstar\n");
      for (int m = 0; m < k; m++)
        fprintf(f, "%.10g,%.10g\n", d[m] / p.L * p.E / b.r0, P[m] / b.Pmax);
      ver_report_close_data(r, f, name);
      fprintf(vars, "f3_snap_%d_%d = %d\n", i, j, b.snapback);
    }
}

/* The paper-method, interface or band-method sweep of an inclined scene (report_cases.c,
 * tag 1, role REP_PAPER, REP_IFACE or REP_BAND): sweep-<scene>-<what>.dat, the columns of the other sweep tables. */
static void write_method_sweep(const rep_ctx *r, const char *scene, int role, const char *what)
{
  char name[64];
  snprintf(name, sizeof name, "sweep-%s-%s.dat", scene, what);
  FILE *f = NULL;
  for (double h = 8; h >= 0.5; h /= 2)
    for (int i = 0; i < r->n; i++) {
      const rep_case *c = &r->c[i];
      if (!(c->role & role) || c->tag != 1 || strcmp(c->scene, scene) || c->h != h || !c->have ||
          !isfinite(c->curve_err))
        continue;
      if (!f && !(f = ver_report_open_data(r, name)))
        return;
      if (ftell(f) == 0)
        fprintf(f, "h,curve_err,abs_diss_err,cpu_s,complete,particles\n");
      fprintf(f, "%g,%.6g,%.6g,%.6g,%d,%.0f\n", h, c->curve_err, fabs(c->diss_err), c->cpu_s, c->complete,
              c->particles);
    }
  if (f)
    ver_report_close_data(r, f, name);
}

static void write_sweeps(const rep_ctx *r, rep_fit *fits, FILE *vars)
{
  for (int s = 1; s < REP_NSWEEP; s++) {
    write_method_sweep(r, rep_sweep_scene[s], REP_PAPER, "paper");
    write_method_sweep(r, rep_sweep_scene[s], REP_IFACE, "iface");
    write_method_sweep(r, rep_sweep_scene[s], REP_BAND, "band");
  }
  for (int s = 0; s < REP_NSWEEP; s++) {
    double hh[8], ec[8], ed[8];
    for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5) {
      char name[64];
      snprintf(name, sizeof name, "sweep-%s-ppc%d.dat", rep_sweep_scene[s], ppc);
      FILE *f = ver_report_open_data(r, name);
      if (!f)
        continue;
      fprintf(f, "h,curve_err,abs_diss_err,cpu_s,complete,particles\n");
      int n = 0, nd = 0, nexact = 0;
      double hd[8];
      for (double h = 8; h >= 0.5; h /= 2) {
        const int k = ver_report_find_sweep(r, rep_sweep_scene[s], h, ppc);
        if (k < 0 || !r->c[k].have || !isfinite(r->c[k].curve_err))
          continue;
        const rep_case *c = &r->c[k];
        fprintf(f, "%g,%.6g,%.6g,%.6g,%d,%.0f\n", h, c->curve_err, fabs(c->diss_err), c->cpu_s, c->complete,
                c->particles);
        if (ppc == 1 && n < 8 && c->complete) {
          hh[n] = h;
          ec[n] = c->curve_err;
          n++;
          if (fabs(c->diss_err) < REP_ROUNDING)
            nexact++;
          else {
            hd[nd] = h;
            ed[nd++] = fabs(c->diss_err);
          }
        }
      }
      ver_report_close_data(r, f, name);
      if (ppc == 1) {
        rep_fit *cf = &fits[s];
        cf->n = n;
        cf->n_diss_exact = nexact;
        cf->p_curve = ver_conv_order(hh, ec, (size_t)n, &cf->c_curve);
        cf->p_diss = ver_conv_order(hd, ed, (size_t)nd, &cf->c_diss);
        fprintf(vars, "exact_diss_%s = %d\n", rep_sweep_scene[s], nexact == n && n > 0);
        fprintf(vars, "p_curve_%s = %.6g\nc_curve_%s = %.6g\np_diss_%s = %.6g\nc_diss_%s = %.6g\n",
                rep_sweep_scene[s], isfinite(cf->p_curve) ? cf->p_curve : 0, rep_sweep_scene[s],
                isfinite(cf->c_curve) ? cf->c_curve : -50, rep_sweep_scene[s],
                isfinite(cf->p_diss) ? cf->p_diss : 0, rep_sweep_scene[s], isfinite(cf->c_diss) ? cf->c_diss : -50);
      }
    }
  }
}

/* Time-step sweep outcome: blown up if the run failed or the load left any sane
 * range; noisy if its curve error exceeds the smallest-dt run's by more than a
 * third of... see REP_STAB_NOISY. */

int ver_report_stab_outcome(const rep_case *c, double base)
{
  if (!c->have || c->exit_status != 0 || !isfinite(c->max_absP) || c->max_absP > 10 * c->bar.Pmax ||
      !isfinite(c->curve_err))
    return REP_BLOWN;
  return c->curve_err > base + REP_STAB_NOISY ? REP_NOISY : REP_STABLE;
}

double ver_report_stab_base(const rep_ctx *r)
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
  FILE *f = ver_report_open_data(r, "stab.dat");
  if (!f)
    return;
  fprintf(f, "dt_ratio,dt,outcome,curve_err,delta_reached\n"); /* outcome: 0 stable, 1 noisy, 2 blown up */
  const double base = ver_report_stab_base(r);
  rep_str ids = {0}, labs = {0};
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (!(c->role & REP_STAB))
      continue;
    const int o = ver_report_stab_outcome(c, base);
    fprintf(f, "%.4g,%.6g,%d,%.6g,%.6g\n", c->tag, c->dt, o, isfinite(c->curve_err) ? c->curve_err : 1.0,
            c->delta_end);
    if (o != REP_BLOWN) {
      rep_str_printf(&ids, "%s%s", ids.n ? " " : "", c->id);
      rep_str_printf(&labs, "%s%.2f", labs.n ? " " : "", c->tag);
    }
  }
  ver_report_close_data(r, f, "stab.dat");
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
  fprintf(vars, "%s_speed = %.6g\n", key, c && c->speed > 0 ? c->speed : 1.0);
  fprintf(vars, "%s_Dsep = %.6g\n", key, c && isfinite(c->bar.D_sep) ? c->bar.D_sep : 0.0);
  char m[192] = "";
  if (c)
    ver_report_method(c, m, sizeof m);
  /* a long label breaks before its damping, so that a figure's title fits its width */
  char *dmp = strlen(m) > 90 ? strstr(m, ", damped") : NULL;
  if (dmp)
    *dmp = '\0';
  fprintf(vars, "%s_method = \"%s%s%s, h = %g, %d ppc\"\n", key, m, dmp ? ",\\n" : "", dmp ? dmp + 2 : "",
          c ? c->h : 0.0, c ? c->ppc : 0);
}

/* The largest lambda in the snapshots ds of case c (1 if none is read): the top of the
 * colour scale of a picture whose decohesion is still small. */
static double max_lambda(const rep_case *c, const double *ds, int nd)
{
  double m = 0;
  for (int i = 0; c && i < nd; i++) {
    char p[REP_PATH + 48];
    snprintf(p, sizeof p, "%s/snap-d%.3f.csv", c->dir, ds[i]);
    static const char *const col[1] = {"lambda"};
    double *v[1];
    const long n = ver_csv_read(p, col, 1, v);
    for (long k = 0; k < n; k++)
      m = fmax(m, v[0][k]);
    free(v[0]);
    /* decohesion.path = interface: the line's segments carry lambda */
    snprintf(p, sizeof p, "%s/snap-d%.3f-line.csv", c->dir, ds[i]);
    const long nl = ver_csv_read(p, col, 1, v);
    for (long k = 0; k < nl; k++)
      m = fmax(m, v[0][k]);
    free(v[0]);
  }
  return m > 0 ? m : 1.0;
}

void ver_report_write_data(report *R)
{
  rep_ctx *r = &R->r;
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/data", r->out);
  ver_mkdir_p(p);
  FILE *vars = ver_report_open_data(r, "vars.gp");
  if (!vars)
    return;
  fprintf(vars, "# written by delam report\n");
  for (int i = 0; i < r->n; i++)
    if (r->c[i].have)
      copy_case(r, &r->c[i]);
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
  ver_report_qs_write(r, vars);
  ver_report_spec_write(r, vars);
  write_sweeps(r, R->fits, vars);
  ver_report_write_static(R, vars);
  write_stab(r, vars);
  write_rate(r, vars);
  write_vars_case(vars, "pic_fig6", ver_report_first(r, REP_PIC, "fig6"));
  write_vars_case(vars, "pic_fig7", ver_report_first(r, REP_PIC, "fig7"));
  write_vars_case(vars, "pic_fig8", ver_report_first(r, REP_PIC, "fig8"));
  write_vars_case(vars, "paper_fig7", ver_report_first(r, REP_PAPER, "fig7"));
  write_vars_case(vars, "paper_fig8", ver_report_first(r, REP_PAPER, "fig8"));
  write_vars_case(vars, "iface_fig7", ver_report_first(r, REP_IFACE, "fig7"));
  write_vars_case(vars, "iface_fig8", ver_report_first(r, REP_IFACE, "fig8"));
  static const double f7a[4] = {0.24, 0.25, 0.26, 0.28};
  fprintf(vars, "lam_max_fig7a = %.6g\n", max_lambda(ver_report_first(r, REP_PIC, "fig7"), f7a, 4));
  fprintf(vars, "dt_crit8 = %.6g\nhave_musl = %d\n", ver_report_dt_crit(r, "fig6", 8), r->have_musl);
  /* the sweep's ids by scene, h and ppc, for the load-deflection panels */
  for (int s = 0; s < REP_NSWEEP; s++)
    for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5)
      for (double h = 8; h >= 1; h /= 2) {
        const int k = ver_report_find_sweep(r, rep_sweep_scene[s], h, ppc);
        char key[64];
        snprintf(key, sizeof key, "sw_%s_h%g_ppc%d", rep_sweep_scene[s], h, ppc);
        fprintf(vars, "%s = \"%s\"\n", key, k >= 0 && r->c[k].have ? r->c[k].id : "");
        write_note(vars, key, k >= 0 ? &r->c[k] : NULL);
      }
  /* the scheme pair of each inclined picture scene, whatever overrides made its id */
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if ((c->role & REP_SCHEME) && (!strcmp(c->scene, "fig7") || !strcmp(c->scene, "fig8")))
      fprintf(vars, "scheme_%s_%s = \"%s\"\n", c->scene, c->tag == 1 ? "musl" : "usl", c->have ? c->id : "");
  }
  /* the snapshot and separation cases by id (the scheme pair has its names above: its
   * ids, with every override in them, passed gnuplot's length for a variable name) */
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if (c->role & (REP_SNAP | REP_SEP)) {
      char key[128];
      snprintf(key, sizeof key, "id_%s", c->id);
      for (char *q = key; *q; q++)
        if (*q == '-' || *q == '.' || *q == '=')
          *q = '_';
      fprintf(vars, "%s = \"%s\"\n", key, c->have ? c->id : "");
      write_note(vars, key, c);
    }
  }
  ver_report_close_data(r, vars, "vars.gp");
}

/* 1 if the figure file ends as a whole one does: its last 64 bytes hold end (a PNG's
 * IEND chunk, an SVG's closing tag). */
static int figure_whole(const char *path, const char *end)
{
  FILE *f = fopen(path, "rb");
  char tail[65] = "";
  size_t k = 0;
  if (f && fseek(f, -64, SEEK_END) != 0)
    rewind(f); /* shorter than 64 bytes */
  if (f) {
    k = fread(tail, 1, 64, f);
    fclose(f);
  }
  for (size_t i = 0; i + strlen(end) <= k; i++)
    if (!memcmp(tail + i, end, strlen(end)))
      return 1;
  return 0;
}

void ver_report_gnuplot(report *R)
{
  rep_ctx *r = &R->r;
  const int n = 2 * R->nfig;
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
    const rep_fig *f = &R->fig[i / 2];
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
  ver_report_spawn_all(argvs, r->out, logs, names, n, r->jobs, st, "gnuplot", NULL);
  for (int i = 0; i < n; i++) { /* gnuplot may exit 0 leaving an empty or cut file (a full disk) */
    char p[2 * REP_PATH];
    snprintf(p, sizeof p, "%s/%s", r->out, names[i]);
    if (st[i] > 0) /* failed or stopped: what it wrote is no figure */
      remove(p);
    else if (st[i] == 0 && !figure_whole(p, i % 2 ? "</svg>" : "IEND")) {
      fprintf(stderr, PROG ": %s: not whole after gnuplot (no %s at its end): removed, the figure is missing\n",
              p, i % 2 ? "</svg>" : "PNG IEND chunk");
      remove(p);
      st[i] = 1;
    }
  }
  for (int i = 0; i < n; i += 2) {
    R->fig[i / 2].status = st[i] ? st[i] : st[i + 1];
    if (st[i] != 0 || st[i + 1] != 0)
      fprintf(stderr, PROG ": gnuplot %s failed (see %s/%s)\n", R->fig[i / 2].name, r->out, logs[i]);
  }
out:
  free(argvs);
  free(logs);
  free(names);
  free(st);
  free(store);
  free(avs);
}

void ver_report_no_figures(report *R)
{
  fprintf(stderr, PROG ": %d data files could not be written: no figure is drawn from part of its data\n",
          R->data_bad);
  for (int i = 0; i < R->nfig; i++) {
    char p[REP_PATH + 64];
    R->fig[i].status = 1;
    snprintf(p, sizeof p, "%s/%s.png", R->r.out, R->fig[i].name);
    remove(p);
    snprintf(p, sizeof p, "%s/%s.svg", R->r.out, R->fig[i].name);
    remove(p);
  }
}
