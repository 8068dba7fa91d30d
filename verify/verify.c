/*
 * verify.c - the sweep behind `delam verify` (verify.h): which cases, running them in
 * child processes (a crashing case cannot take the sweep with it), reading each
 * case's summary.json, load.csv and final.csv, checking them against the closed-form
 * bar (analytic/ana.h, MODEL.md sec. 5), the cross-case checks, and verify.json /
 * verify.csv / the closing table.
 *
 * Every check's class and tolerance is set in check_policy() below, next to the
 * reason for it; the same numbers land in verify.json and on every printed line.
 */
#include <assert.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "ana.h"
#include "io.h"
#include "run.h"
#include "summary.h"
#include "scene.h"
#include "verify.h"

#define PI 3.14159265358979323846
#define MAXSET 4
#define NCHECK 11
#define MAXCROSS 64

/* A variant of a scene: a suffix for the case id and the override it stands for. */
typedef struct {
  const char *suffix; /* "" for the scene as written */
  const char *set;    /* "section.key=value" or NULL */
} variant;

static const variant V_BASE = {"", NULL};
static const variant V_LEP = {"Leparticle", "decohesion.Le=particle"};
static const variant V_SEP8 = {"sep0.8", "decohesion.separation=0.8"};

typedef struct {
  /* what to run */
  char id[128];
  char scene[64];
  char path[600];
  variant var;
  double h;
  int ppc;
  char sets[MAXSET][128];      /* the --set overrides, as `delam run` gets them     */
  int nset;
  ver_scene vs;                /* the scene as the run sees it                      */
  int have_ana;
  ana_bar ana;
  double end_delta;
  double cost;                 /* particles x steps to the end, for scheduling       */
  /* how the run went */
  int exit_code;               /* child's exit status; -1 not run (merge)            */
  int term_sig;                /* signal that killed the child, 0 if none            */
  double wall_s;               /* wall time of the child (or summary wall_s on merge) */
  int have_summary, complete;
  char error[600];
  /* measured */
  double peak_P, delta_peak, delta_sep, k_elastic, D_final, W_ext_final, energy_residual, delta_end;
  double k_soft, curve_l2, band_width, band_extent, angle;
  double D_diffuse;  /* dissipation outside the band, over U0 x area (ver_diffuse_share) */
  size_t band_count;
  ver_check chk[NCHECK];
  int nchk;
  int verdict;
} vcase;

typedef struct {
  char name[64];          /* "D_invariance_h", "D_invariance_ppc", "order_h"          */
  char scene[64];
  char over[8];           /* "h" or "ppc": what varies                               */
  double fixed;           /* the ppc (or h) held fixed                                */
  int n;
  double x[8], y[8];      /* the varying parameter and the number per case            */
  char ids[8][128];
  ver_check chk;
} vcross;

/* ------------------------------------------------------------------ scenes */

/* The scene file with the same overrides `delam run --h H --ppc N --set ...` applies
 * (cmd_run.c: dt scaled with h to keep the file's Courant number). */
static int build_scene(const char *path, double h, int ppc, char sets[][128], int nset, ver_scene *vs,
                       char *err, size_t len)
{
  if (ver_scene_parse(path, vs, err, len))
    return 2;
  char buf[128];
  if (h > 0) {
    const double dt = vs->sc.dt * h / vs->sc.h;
    snprintf(buf, sizeof buf, "grid.h=%.17g", h);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
    snprintf(buf, sizeof buf, "time.dt=%.17g", dt);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
  }
  if (ppc > 0) {
    snprintf(buf, sizeof buf, "grid.ppc=%d", ppc);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
  }
  for (int i = 0; i < nset; i++)
    if (ver_scene_set(vs, sets[i], err, len))
      return 2;
  return ver_scene_validate(vs, err, len);
}

static int is_a90(const vcase *c)
{
  return fabs(c->vs.sc.alpha_deg - 90.0) < 1e-9;
}

/* Sets up case c: id, overrides, the analytic bar and the end displacement.
 * end_delta covers separation with margin (the run stops itself stop_margin past
 * separation, and the grid is sized to end_delta, so it is kept as small as is safe):
 * 4 x the analytic delta_sep, at least 1, for alpha = 90; inclined bands dissipate
 * several times U0 per area (paper, Fig. 7) and separate later: at least 1.2, past
 * every separation measured (0.61 to 0.87 on h = 2 and 4); a band that has not cut the
 * bar by then is reported as not separating. */
static int case_init(vcase *c, const char *path, const char *scene, double h, int ppc, variant v, char *err,
                     size_t len)
{
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  snprintf(c->scene, sizeof c->scene, "%s", scene);
  c->var = v;
  c->h = h;
  c->ppc = ppc;
  c->exit_code = -1;
  c->delta_sep = NAN;
  if (v.set)
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "%s", v.set);
  if (build_scene(path, h, ppc, c->sets, c->nset, &c->vs, err, len))
    return 2;
  char aerr[256];
  double mult = 4.0, least = 1.0;
  if (c->vs.sc.model > 0 && ver_scene_bar(&c->vs.sc, &c->ana, aerr, sizeof aerr) == 0) {
    c->have_ana = 1;
    if (!is_a90(c))
      least = 1.2;
    c->end_delta = fmax(least, mult * c->ana.delta_sep);
  } else {
    c->end_delta = c->vs.sc.end_delta;
  }
  c->nset = 0;
  /* one snapshot at delta 0 stands for none: an empty list is refused by the scene
   * reader, and snapshots later than separation would keep the run going */
  snprintf(c->sets[c->nset++], sizeof c->sets[0], "output.snapshots=0");
  snprintf(c->sets[c->nset++], sizeof c->sets[0], "run.end_delta=%.6g", c->end_delta);
  if (v.set)
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "%s", v.set);
  if (build_scene(path, h, ppc, c->sets, c->nset, &c->vs, err, len))
    return 2;
  char base[100];
  ver_scene_case_id(&c->vs, base, sizeof base);
  snprintf(c->id, sizeof c->id, "%s%s%s", base, v.suffix[0] ? "-" : "", v.suffix);
  const mpm_scene *sc = &c->vs.sc;
  c->cost = (sc->L / sc->h) * (sc->H / sc->h) * sc->ppc * (c->end_delta / (sc->speed * sc->dt));
  return 0;
}

static int cmp_str(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The case list: the quick subset, or every scene of the folder x h x ppc. */
static int make_cases(const ver_verify_opts *o, vcase **out, int *nout)
{
  char err[1024];
  vcase *cs = NULL;
  int n = 0;
  if (!o->full) {
    static const struct {
      const char *scene;
      double h;
      int ppc;
      const variant *v;
    } q[] = {
      {"fig6", 8, 1, &V_BASE}, {"fig6", 8, 4, &V_BASE}, {"fig6", 4, 4, &V_BASE},
      {"fig6", 4, 1, &V_BASE}, {"fig6", 2, 4, &V_BASE},
      {"fig6", 8, 4, &V_LEP},  {"fig6", 8, 4, &V_SEP8},
      {"fig7", 4, 4, &V_BASE},
    };
    const int nq = (int)(sizeof q / sizeof q[0]);
    cs = calloc((size_t)nq, sizeof *cs);
    if (!cs)
      return 2;
    for (int i = 0; i < nq; i++) {
      char path[600];
      snprintf(path, sizeof path, "%s/%s.ini", o->scenes, q[i].scene);
      if (case_init(&cs[n], path, q[i].scene, q[i].h, q[i].ppc, *q[i].v, err, sizeof err)) {
        fprintf(stderr, "delam verify: %s\n", err);
        free(cs);
        return 2;
      }
      n++;
    }
  } else {
    DIR *d = opendir(o->scenes);
    if (!d) {
      fprintf(stderr, "delam verify: %s: cannot open the scene folder: %s\n", o->scenes, strerror(errno));
      return 2;
    }
    char *names[256];
    int nn = 0;
    struct dirent *e;
    while ((e = readdir(d)) && nn < 256) {
      const size_t l = strlen(e->d_name);
      if (l > 4 && !strcmp(e->d_name + l - 4, ".ini") && e->d_name[0] != '.')
        names[nn++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)nn, sizeof names[0], cmp_str);
    static const double hs[] = {8, 4, 2, 1};
    static const int ps[] = {1, 4, 9};
    cs = calloc((size_t)(nn * 12 + 1), sizeof *cs);
    int rc = cs ? 0 : 2;
    for (int i = 0; i < nn && !rc; i++) {
      char path[600], scene[64];
      snprintf(path, sizeof path, "%s/%s", o->scenes, names[i]);
      snprintf(scene, sizeof scene, "%.*s", (int)strlen(names[i]) - 4, names[i]);
      for (int a = 0; a < 4 && !rc; a++)
        for (int b = 0; b < 3 && !rc; b++) {
          if (case_init(&cs[n], path, scene, hs[a], ps[b], V_BASE, err, sizeof err)) {
            fprintf(stderr, "delam verify: %s\n", err);
            rc = 2;
          } else
            n++;
        }
    }
    for (int i = 0; i < nn; i++)
      free(names[i]);
    if (rc) {
      free(cs);
      return rc;
    }
    if (n == 0) {
      fprintf(stderr, "delam verify: %s: no scene files (*.ini)\n", o->scenes);
      free(cs);
      return 2;
    }
  }
  *out = cs;
  *nout = n;
  return 0;
}

/* ------------------------------------------------------------------ running */

static void case_dir(const ver_verify_opts *o, const vcase *c, char *buf, size_t len)
{
  snprintf(buf, len, "%s/%s", o->outdir, c->id);
}

/* In the child: one run, its error text (if any) to DIR/<id>/error.txt. */
static void child_run(const ver_verify_opts *o, const vcase *c, int threads)
{
  char dir[800], path[900], err[1024] = "";
  case_dir(o, c, dir, sizeof dir);
  snprintf(path, sizeof path, "%s/error.txt", dir);
  remove(path);
  ver_run_opts ro = {dir, 0, 1, NULL, 0, threads};
  ver_summary u;
  const int rc = ver_run(&c->vs, &ro, &u, err, sizeof err);
  if (rc) {
    FILE *f = fopen(path, "w");
    if (f) {
      fprintf(f, "%s\n", err);
      fclose(f);
    }
  }
  fflush(NULL);
  _exit(rc & 0xff);
}

static void show_running(const vcase *cs, const int *slot_case, int jobs, int done, int total)
{
  fprintf(stderr, "verify: [%d/%d done] running:", done, total);
  for (int j = 0; j < jobs; j++)
    if (slot_case[j] >= 0)
      fprintf(stderr, " %s", cs[slot_case[j]].id);
  fprintf(stderr, "\n");
}

/* Runs every case, at most o->jobs at a time, costliest first. */
static int run_cases(const ver_verify_opts *o, vcase *cs, int n)
{
  int *order = malloc(sizeof(int) * (size_t)n);
  pid_t *slot_pid = calloc((size_t)o->jobs, sizeof(pid_t));
  int *slot_case = malloc(sizeof(int) * (size_t)o->jobs);
  double *slot_t0 = calloc((size_t)o->jobs, sizeof(double));
  if (!order || !slot_pid || !slot_case || !slot_t0) {
    free(order), free(slot_pid), free(slot_case), free(slot_t0);
    return 2;
  }
  for (int i = 0; i < n; i++)
    order[i] = i;
  /* insertion sort by cost, descending (n is small) */
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && cs[order[j]].cost > cs[order[j - 1]].cost; j--) {
      const int t = order[j];
      order[j] = order[j - 1];
      order[j - 1] = t;
    }
  for (int j = 0; j < o->jobs; j++)
    slot_case[j] = -1;
  const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
  const int threads = (int)fmax(1.0, (double)(ncpu > 0 ? ncpu : 1) / o->jobs);
  int next = 0, done = 0, running = 0;
  while (done < n) {
    int started = 0;
    while (running < o->jobs && next < n) {
      int j = 0;
      while (slot_case[j] >= 0)
        j++;
      vcase *c = &cs[order[next++]];
      fflush(NULL);
      const pid_t pid = fork();
      if (pid == 0)
        child_run(o, c, threads);
      if (pid < 0) {
        snprintf(c->error, sizeof c->error, "fork failed: %s", strerror(errno));
        c->exit_code = 1;
        done++;
        continue;
      }
      slot_pid[j] = pid;
      slot_case[j] = (int)(c - cs);
      slot_t0[j] = ver_now_wall();
      running++;
      started = 1;
    }
    if (started)
      show_running(cs, slot_case, o->jobs, done, n);
    if (running == 0)
      continue;
    int status;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR)
        continue;
      break;
    }
    int j = 0;
    while (j < o->jobs && slot_pid[j] != pid)
      j++;
    if (j == o->jobs)
      continue;
    vcase *c = &cs[slot_case[j]];
    c->wall_s = ver_now_wall() - slot_t0[j];
    if (WIFEXITED(status))
      c->exit_code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) {
      c->exit_code = 128 + WTERMSIG(status);
      c->term_sig = WTERMSIG(status);
    }
    slot_case[j] = -1;
    slot_pid[j] = 0;
    running--;
    done++;
    fprintf(stderr, "verify: [%d/%d done] %s finished in %.1f s (exit %d%s)\n", done, n, c->id, c->wall_s,
            c->exit_code, c->term_sig ? ", killed by a signal" : "");
  }
  free(order), free(slot_pid), free(slot_case), free(slot_t0);
  return 0;
}

/* ------------------------------------------------------------------ reading */

/* Analytic end displacement where lambda reaches the separation threshold. */
static double sep_ref(const vcase *c)
{
  return ver_sep_ref(&c->ana, c->vs.sc.sep_threshold);
}

/* Reads what the run left in DIR/<id>/ and measures from it. */
static void case_read(const ver_verify_opts *o, vcase *c)
{
  char dir[800], path[900];
  case_dir(o, c, dir, sizeof dir);
  c->peak_P = c->delta_peak = c->delta_sep = c->k_elastic = NAN;
  c->D_final = c->W_ext_final = c->energy_residual = c->delta_end = NAN;
  c->k_soft = c->curve_l2 = c->band_width = c->band_extent = c->angle = c->D_diffuse = NAN;
  ver_summary_doc sd;
  if (ver_summary_read(dir, &sd) == 0) {
    const ver_summary *u = &sd.u;
    c->have_summary = 1;
    c->complete = u->complete;
    if (sd.error[0] && !c->error[0])
      snprintf(c->error, sizeof c->error, "%s", sd.error);
    c->peak_P = u->peak_P;
    c->delta_peak = u->delta_peak;
    c->delta_sep = u->delta_sep;
    if (c->delta_sep < 0)
      c->delta_sep = NAN; /* -1: no separation detected before end_delta */
    c->k_elastic = u->k_elastic;
    c->D_final = u->D_final;
    c->W_ext_final = u->W_ext_final;
    c->energy_residual = u->energy_residual;
    c->delta_end = u->delta_end;
    if (c->exit_code < 0)
      c->wall_s = u->wall_s;
  }
  if (!c->error[0]) {
    snprintf(path, sizeof path, "%s/error.txt", dir);
    char *et = ver_io_slurp(path, NULL, 1 << 16);
    if (et) {
      char *nl = strchr(et, '\n');
      if (nl)
        *nl = '\0';
      snprintf(c->error, sizeof c->error, "%s", et);
      free(et);
    }
  }
  if (!c->have_summary && !c->error[0]) {
    if (c->term_sig)
      snprintf(c->error, sizeof c->error, "killed by signal %d (%s); no summary.json", c->term_sig,
               strsignal(c->term_sig));
    else
      snprintf(c->error, sizeof c->error, "no summary.json in %.400s (not run, or the run crashed)", dir);
  }
  if (c->term_sig && c->have_summary)
    c->complete = 0;
  static const char *const lcols[] = {"delta", "P_grip"};
  double *lc[2];
  snprintf(path, sizeof path, "%s/load.csv", dir);
  const long nl = ver_csv_read(path, lcols, 2, lc);
  if (nl > 0 && c->have_ana) {
    c->k_soft = ver_softening_slope(lc[0], lc[1], (size_t)nl, VER_SOFT_HI, VER_SOFT_LO);
    c->curve_l2 = ver_curve_err_bar(&c->ana, lc[0], lc[1], (size_t)nl, ver_curve_end(&c->ana, c->vs.sc.sep_threshold), NULL);
  }
  for (int k = 0; k < 2; k++)
    free(lc[k]);
  static const char *const fcols[] = {"x0", "y0", "lambda"};
  double *fc[3];
  snprintf(path, sizeof path, "%s/final.csv", dir);
  const long nf = ver_csv_read(path, fcols, 3, fc);
  if (nf > 0) {
    const mpm_scene *sc = &c->vs.sc;
    const double thr = VER_BAND_LAMBDA;
    c->band_width = ver_band_width(fc[0], fc[1], fc[2], (size_t)nf, thr, sc->alpha_deg, sc->h, sc->ppc, sc->H,
                                   &c->band_extent, &c->band_count);
    c->angle = ver_crack_angle(fc[0], fc[1], fc[2], (size_t)nf, thr);
    if (c->have_ana && c->ana.D_sep > 0.0)
      c->D_diffuse = ver_diffuse_share(fc[2], (size_t)nf, thr) * c->D_final / c->ana.D_sep;
  }
  for (int k = 0; k < 3; k++)
    free(fc[k]);
}

/* ------------------------------------------------------------------ checks */

static ver_check *add_check(vcase *c, const char *name, double measured, double reference, int rel)
{
  assert(c->nchk < NCHECK);
  ver_check *k = &c->chk[c->nchk++];
  memset(k, 0, sizeof *k);
  k->name = name;
  k->measured = measured;
  k->reference = reference;
  k->rel = rel;
  k->cls = VER_CLASS_PASS;
  k->lim_lo = -INFINITY;
  k->lim_hi = INFINITY;
  return k;
}

static void known(ver_check *k, double lo, double hi)
{
  k->cls = VER_CLASS_KNOWN;
  k->lim_lo = lo;
  k->lim_hi = hi;
}

/*
 * The checks of one case, each with its class and tolerance, and why.
 *
 * Classes come from the physics of the scene, decided before looking at a run:
 *  - alpha = 90 (Fig. 6): the band lies along a grid line, one cell wide; the
 *    paper's curves agree with the analytic ones.  Every check is pass-class.
 *  - alpha != 90 (Figs. 7, 8, a45, a30): the band spreads over about two cells
 *    (paper, Fig. 7 discussion), so it dissipates more than U0 per area, softens more
 *    gently, separates later and takes more external work: D, W_ext, delta_sep, the
 *    softening slope and the curve error are known-limit, bounded by what a band up to
 *    ~3 cells wide can do (D <= 4 D_sep, separation before 4 x delta_sep, ...).  Band
 *    width is known-limit (reference: 1 cell; the paper sees ~2).
 *  - analytic snapback (g below its limit: fig8, a45, a30): the explicit method cannot
 *    follow the load reversal; the softening slope is then negative where the
 *    analytic one is positive (known-limit).
 *  - Le = particle with several particles per cell (MODEL.md open point): the strain is
 *    uniform along x inside a cell, so all sqrt(ppc) sub-columns of the band cell soften
 *    together, each with Le = h / sqrt(ppc): the band dissipates sqrt(ppc) x U0 per area.
 *    This case measures that choice; D, W_ext, delta_sep, softening and curve error are
 *    known-limit, bounded by sqrt(ppc) x the analytic value (+10 %).
 *  - peak load, elastic slope, energy balance and crack angle are pass-class everywhere.
 */
/* Curve errors below this fraction of Pmax are at the loading-rate floor. */
#define VER_CURVE_FLOOR 0.02

static void check_policy(vcase *c)
{
  const ana_bar *a = &c->ana;
  const mpm_scene *sc = &c->vs.sc;
  const int a90 = is_a90(c), snap = a->snapback;
  const int lep = sc->le_mode == MPM_LE_PARTICLE && sc->ppc > 1;
  const double nside = sqrt((double)sc->ppc);
  const int ppc1 = sc->ppc == 1;
  ver_check *k;
  c->nchk = 0;

  k = add_check(c, "run", c->complete ? 1.0 : 0.0, 1.0, 0);
  k->tol = 0;
  snprintf(k->note, sizeof k->note, "the run reached its stop rule with finite state%s%s",
           c->error[0] ? ": " : "", c->error[0] ? c->error : "");

  /* one particle per cell samples the stress at the cell centre only; the peak is
   * reached a little early (paper, Fig. 6c: 4 per cell clearly better than 1) */
  k = add_check(c, "peak_P", c->peak_P, a->Pmax, 1);
  k->tol = ppc1 ? 0.03 : 0.01;
  snprintf(k->note, sizeof k->note, "peak grip load vs Pmax = r0 H (eq. 30); tol %g %% (ppc %d)", 100 * k->tol,
           sc->ppc);

  k = add_check(c, "k_elastic", c->k_elastic, a->k_elastic, 1);
  k->tol = 0.01;
  snprintf(k->note, sizeof k->note, "least-squares dP/ddelta for 0.1-0.6 peak vs E H / L");

  k = add_check(c, "k_soft", c->k_soft, a->k_soft_peak, 1);
  k->tol = ppc1 ? 0.10 : 0.05;
  if (snap) {
    known(k, -INFINITY, -1.0); /* measured slope negative where the analytic one is positive */
    snprintf(k->note, sizeof k->note, "fit over 0.8-0.2 peak after the peak vs eq. 36; analytic snapback "
             "(g = %.3g): explicit runs cannot follow it, so known-limit if negative", a->g);
  } else if (!a90 || lep) {
    known(k, 0.0, 1.0); /* softer (less steep) but still softening */
    snprintf(k->note, sizeof k->note, "fit over 0.8-0.2 peak after the peak vs eq. 36; %s: known-limit if "
             "softer but negative", lep ? "Le = particle doubles the band's compliance" : "inclined band is wider");
  } else
    snprintf(k->note, sizeof k->note, "fit over 0.8-0.2 peak after the peak vs eq. 36");

  /* The run detects separation when the load averaged over 4 L / c falls below
   * sep_load x peak and reports the window's centre: about half a window (0.011 in
   * delta at the paper's speed, 3 % of fig6's 0.375) after the drop.  The analytic
   * reference is where lambda reaches the separation threshold (eqs. 31, 34), which is
   * delta_sep itself for a threshold of 1. */
  const double dref = sep_ref(c);
  k = add_check(c, "delta_sep", c->delta_sep, dref, 1);
  k->tol = ppc1 ? 0.06 : 0.04;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 3.0);
  snprintf(k->note, sizeof k->note, "detected separation vs analytic delta at lambda = %g (%.4g)",
           sc->sep_threshold, dref);

  k = add_check(c, "D_final", c->D_final, a->D_sep, 1);
  k->tol = 0.02;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 3.0);
  snprintf(k->note, sizeof k->note, "dissipation at the end vs UD x area = %.4g%s", a->D_sep,
           !a90 && !lep ? " (inclined band: more, paper Fig. 7)" : "");

  /* W_ext also holds the kinetic and elastic energy still in the bar at the end.  The
   * inclined bound is the dissipation bound (4 D_sep): the work ends up dissipated, and
   * where the traction is dropped at separation (or an unfollowed snapback releases
   * stored energy) it is not the analytic UF per area that the work is compared with. */
  k = add_check(c, "W_ext_final", c->W_ext_final, a->W_sep, 1);
  k->tol = 0.03;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 4.0 * a->D_sep / a->W_sep - 1.0);
  snprintf(k->note, sizeof k->note, "external work at the end vs UF x area = %.4g", a->W_sep);

  /* Inclined scenes: after the band has failed, the single-valued velocity of a cell
   * still couples the two parts (the paper, Fig. 8 discussion: separation "not as clean",
   * stresses built up until the separation is a cell wide); a load of a few % of the peak
   * persists and its work is not all accounted for.  Known-limit up to 15 %. */
  k = add_check(c, "energy_residual", c->energy_residual, 0.0, 0);
  k->tol = 0.02;
  if (!a90)
    known(k, 0.0, 0.15);
  snprintf(k->note, sizeof k->note, "max |W_ext - KE - SE - W_coh| / max W_ext over the rows%s",
           a90 ? "" : " (inclined: residual load after the band fails, known-limit to 0.15)");

  k = add_check(c, "band_width", c->band_width, 1.0, 0);
  k->tol = 0.5;
  if (!a90)
    known(k, -0.5, 2.0);
  snprintf(k->note, sizeof k->note, "cells: (particles with lambda > 0.5) x h^2/ppc / (H / sin a) / h; "
           "projected extent %.3g cells, %zu particles", c->band_extent, c->band_count);

  /* a staircase of cells through a fixed grid approximates the line; the coarser the
   * grid the larger the deviation it can show */
  k = add_check(c, "crack_angle", c->angle, sc->alpha_deg, 0);
  k->measured = c->angle;
  k->tol = a90 ? 1.0 : 10.0;
  snprintf(k->note, sizeof k->note, "principal axis of the decohered particles' x0, y0 vs alpha (deg)");

  k = add_check(c, "curve_l2", c->curve_l2, 0.0, 0);
  k->tol = ppc1 ? 0.04 : 0.03;
  if (!a90 || lep || snap)
    known(k, 0.0, 0.35);
  snprintf(k->note, sizeof k->note, "RMS of P - P_ana(delta) / Pmax over rows up to lambda = %g or the peak "
           "(delta %.4g)", sc->sep_threshold, ver_curve_end(a, sc->sep_threshold));

  /* the angle of a line is defined mod 180: judge the wrapped difference */
  for (int i = 0; i < c->nchk; i++) {
    ver_check *q = &c->chk[i];
    if (!c->have_ana && strcmp(q->name, "run")) {
      q->measured = NAN;
      snprintf(q->note, sizeof q->note, "no analytic reference for this scene");
    }
    ver_check_judge(q);
    if (!strcmp(q->name, "crack_angle") && isfinite(q->measured)) {
      q->error = ver_angle_diff(q->measured, q->reference);
      q->verdict = fabs(q->error) <= q->tol ? VER_PASS : VER_FAIL;
    }
  }
  c->verdict = VER_PASS;
  for (int i = 0; i < c->nchk; i++) {
    if (c->chk[i].verdict == VER_FAIL)
      c->verdict = VER_FAIL;
    else if (c->chk[i].verdict == VER_KNOWN && c->verdict == VER_PASS)
      c->verdict = VER_KNOWN;
  }
}

/* ------------------------------------------------------------------ across cases */

static int cross_add(vcross *x, int *nx, const char *name, const char *scene, const char *over, double fixed)
{
  for (int i = 0; i < *nx; i++)
    if (!strcmp(x[i].name, name) && !strcmp(x[i].scene, scene) && x[i].fixed == fixed)
      return i;
  if (*nx == MAXCROSS)
    return -1;
  vcross *g = &x[(*nx)++];
  memset(g, 0, sizeof *g);
  snprintf(g->name, sizeof g->name, "%s", name);
  snprintf(g->scene, sizeof g->scene, "%s", scene);
  snprintf(g->over, sizeof g->over, "%s", over);
  g->fixed = fixed;
  return *nx - 1;
}

/*
 * Energy invariance: the spread (max - min) / mean of D_final over h (ppc fixed) and
 * over ppc (h fixed), per scene, scene-as-written cases only.  alpha = 90: pass-class,
 * 2 %.  Inclined: known-limit up to 50 % (the band's width in cells, hence its
 * dissipation, changes with the grid).
 *
 * Order of convergence: least-squares slope p of log(curve_l2) against log(h), per
 * scene and ppc.  Only the elastic branch is plain discretisation error; on the
 * softening branch the model is regularised by Le = h (the band is one cell whatever
 * h), and the error has a floor set by the ringing of a dynamic run at a finite
 * loading rate (its amplitude depends on the speed, not on h).  So no positive rate
 * is claimed: alpha = 90 is pass-class one-sided, p >= 0 (the error must not grow
 * under refinement).  Inclined: the band never becomes a sharp line, known-limit for
 * p >= -1 (the error not growing faster than 1/h).
 */
static int cross_checks(vcase *cs, int n, vcross *x)
{
  int nx = 0;
  for (int i = 0; i < n; i++) {
    vcase *c = &cs[i];
    if (c->var.set || !c->complete || !c->have_ana)
      continue;
    const char *names[3] = {"D_invariance_h", "D_invariance_ppc", "order_h"};
    const char *over[3] = {"h", "ppc", "h"};
    const double fixed[3] = {c->ppc, c->h, c->ppc};
    const double xv[3] = {c->h, c->ppc, c->h};
    const double yv[3] = {c->D_final, c->D_final, c->curve_l2};
    for (int t = 0; t < 3; t++) {
      const int gi = cross_add(x, &nx, names[t], c->scene, over[t], fixed[t]);
      if (gi < 0 || x[gi].n == 8)
        continue;
      vcross *g = &x[gi];
      g->x[g->n] = xv[t];
      g->y[g->n] = yv[t];
      snprintf(g->ids[g->n], sizeof g->ids[0], "%s", c->id);
      g->n++;
    }
    /* remember alpha = 90 in the group through the check's class below */
  }
  int m = 0;
  for (int i = 0; i < nx; i++) {
    vcross *g = &x[i];
    if (g->n < 2)
      continue;
    int a90 = 1;
    for (int j = 0; j < n; j++)
      if (!strcmp(cs[j].scene, g->scene))
        a90 = is_a90(&cs[j]);
    ver_check *k = &g->chk;
    memset(k, 0, sizeof *k);
    k->lim_lo = -INFINITY;
    k->lim_hi = INFINITY;
    if (!strcmp(g->name, "order_h")) {
      k->name = "order_h";
      k->measured = ver_conv_order(g->x, g->y, (size_t)g->n, NULL);
      k->reference = 0.0;
      k->tol = 0.0;
      snprintf(k->note, sizeof k->note, "observed order p of curve_l2 ~ h^p (ppc %g); one-sided: pass if p >= 0",
               g->fixed);
      ver_check_judge(k);
      if (isfinite(k->error) && k->error >= 0.0)
        k->verdict = VER_PASS; /* one-sided: any order >= 0 passes */
      /* An order is only meaningful while the discretisation error dominates.  Where
       * every error is already below VER_CURVE_FLOOR of Pmax (fig6 at 4 and 9 per cell:
       * about 1 %, the ringing of the quasi-static loading, which h does not reduce) the
       * check passes and says so, with the measured order kept. */
      double emax = 0.0;
      for (int j = 0; j < g->n; j++)
        emax = fmax(emax, g->y[j]);
      if (k->verdict != VER_PASS && emax < VER_CURVE_FLOOR) {
        k->verdict = VER_PASS;
        snprintf(k->note, sizeof k->note, "observed order p of curve_l2 ~ h^p (ppc %g); every error is below "
                 "the %g floor (largest %.3g), where the order is not meaningful", g->fixed, VER_CURVE_FLOOR, emax);
      }
      if (!a90) {
        k->cls = VER_CLASS_KNOWN;
        k->lim_lo = -1.0;
        if (isfinite(k->error) && k->verdict == VER_FAIL && k->error >= k->lim_lo)
          k->verdict = VER_KNOWN;
      }
    } else {
      k->name = strcmp(g->name, "D_invariance_h") ? "D_invariance_ppc" : "D_invariance_h";
      k->measured = ver_spread(g->y, (size_t)g->n);
      k->reference = 0.0;
      k->tol = 0.02;
      if (!a90) {
        k->cls = VER_CLASS_KNOWN;
        k->lim_lo = 0.0;
        k->lim_hi = 0.5;
      }
      snprintf(k->note, sizeof k->note, "(max - min) / mean of D_final over %s at %s %g", g->over,
               strcmp(g->over, "h") ? "h" : "ppc", g->fixed);
      ver_check_judge(k);
    }
    x[m++] = *g;
  }
  return m;
}

/* ------------------------------------------------------------------ output */

static cJSON *num_or_null(double v)
{
  return isfinite(v) ? cJSON_CreateNumber(v) : cJSON_CreateNull();
}

static cJSON *check_json(const ver_check *k)
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

static int write_json(const ver_verify_opts *o, const vcase *cs, int n, const vcross *x, int nx, double wall,
                      int rc)
{
  cJSON *root = cJSON_CreateObject();
  cJSON_AddStringToObject(root, "mode", o->merge_found ? "found" : o->full ? "full" : "quick");
  cJSON_AddStringToObject(root, "dir", o->outdir);
  cJSON_AddBoolToObject(root, "merged", o->merge);
  cJSON_AddNumberToObject(root, "jobs", o->jobs);
  cJSON_AddNumberToObject(root, "wall_s", wall);
  cJSON *arr = cJSON_AddArrayToObject(root, "cases");
  int counts[3] = {0, 0, 0}, cfail = 0;
  for (int i = 0; i < n; i++) {
    const vcase *c = &cs[i];
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
      cJSON_AddItemToArray(ck, check_json(&c->chk[j]));
      counts[c->chk[j].verdict]++;
    }
    cfail += c->verdict == VER_FAIL;
    cJSON_AddItemToArray(arr, co);
  }
  cJSON *xa = cJSON_AddArrayToObject(root, "cross");
  for (int i = 0; i < nx; i++) {
    const vcross *g = &x[i];
    cJSON *go = check_json(&g->chk);
    cJSON_AddStringToObject(go, "scene", g->scene);
    cJSON_AddStringToObject(go, "over", g->over);
    cJSON_AddNumberToObject(go, strcmp(g->over, "h") ? "h" : "ppc", g->fixed);
    cJSON *pts = cJSON_AddArrayToObject(go, "points");
    for (int j = 0; j < g->n; j++) {
      cJSON *p = cJSON_CreateObject();
      cJSON_AddStringToObject(p, "case", g->ids[j]);
      cJSON_AddNumberToObject(p, g->over, g->x[j]);
      cJSON_AddItemToObject(p, strcmp(g->name, "order_h") ? "D_final" : "curve_l2", num_or_null(g->y[j]));
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

static const ver_check *find_chk(const vcase *c, const char *name)
{
  for (int i = 0; i < c->nchk; i++)
    if (!strcmp(c->chk[i].name, name))
      return &c->chk[i];
  return NULL;
}

static double chk_err(const vcase *c, const char *name)
{
  const ver_check *k = find_chk(c, name);
  return k ? k->error : NAN;
}

static int write_csv(const ver_verify_opts *o, const vcase *cs, int n)
{
  size_t cap = 4096 + (size_t)n * 1024, len = 0;
  char *buf = malloc(cap);
  if (!buf)
    return -1;
  len += (size_t)snprintf(buf + len, cap - len,
                          "case,scene,variant,h,ppc,verdict,complete,exit_status,wall_s,peak_P,peak_err,"
                          "k_elastic_err,k_soft,k_soft_err,delta_sep,delta_sep_err,D_final,D_err,D_diffuse,W_ext_final,"
                          "W_err,energy_residual,band_width,band_extent,crack_angle,curve_l2,n_fail,n_known,error\n");
  for (int i = 0; i < n; i++) {
    const vcase *c = &cs[i];
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
                            "%.6g,%.4g,%.4g,%.4g,%.6g,%d,%d,%s\n",
                            c->id, c->scene, c->var.suffix, c->vs.sc.h, c->vs.sc.ppc, ver_verdict_name(c->verdict),
                            c->complete, c->exit_code, c->wall_s, c->peak_P, chk_err(c, "peak_P"),
                            chk_err(c, "k_elastic"), c->k_soft, chk_err(c, "k_soft"), c->delta_sep,
                            chk_err(c, "delta_sep"), c->D_final, chk_err(c, "D_final"), c->D_diffuse, c->W_ext_final,
                            chk_err(c, "W_ext_final"), c->energy_residual, c->band_width, c->band_extent, c->angle,
                            c->curve_l2, nf, nk, err);
    if (len >= cap - 1)
      break;
  }
  const int r = write_text(o->outdir, "verify.csv", buf);
  free(buf);
  return r;
}

static const char *VNAME[] = {"PASS", "FAIL", "KNOWN-LIMIT"};

static void print_check(const char *id, const ver_check *k)
{
  char err[64];
  if (k->rel)
    snprintf(err, sizeof err, "err %+.3g %% (tol %g %%)", 100 * k->error, 100 * k->tol);
  else
    snprintf(err, sizeof err, "err %+.4g (tol %g)", k->error, k->tol);
  printf("%-11s %s %s: measured %.6g, reference %.6g, %s%s -- %s\n", VNAME[k->verdict], id, k->name,
         k->measured, k->reference, err, k->cls == VER_CLASS_KNOWN ? " [known-limit class]" : "", k->note);
}

static void print_table(const vcase *cs, int n, const vcross *x, int nx)
{
  printf("\n%-28s %9s %9s %9s %9s %9s %7s  %s\n", "case", "peak err", "D err", "D diffuse", "E resid",
         "curve L2", "wall s", "verdict");
  for (int i = 0; i < n; i++) {
    const vcase *c = &cs[i];
    printf("%-28s %+8.2f%% %+8.2f%% %8.2f%% %9.2e %9.4f %7.1f  %s%s%s\n", c->id, 100 * chk_err(c, "peak_P"),
           100 * chk_err(c, "D_final"), 100 * c->D_diffuse, c->energy_residual, c->curve_l2, c->wall_s,
           VNAME[c->verdict],
           c->error[0] ? ": " : "", c->error);
  }
  for (int i = 0; i < nx; i++) {
    const vcross *g = &x[i];
    char pts[512] = "";
    size_t l = 0;
    for (int j = 0; j < g->n && l < sizeof pts - 40; j++)
      l += (size_t)snprintf(pts + l, sizeof pts - l, "%s%s %g: %.4g", j ? ", " : "", g->over, g->x[j], g->y[j]);
    printf("%-11s %s %s at %s %g: %.4g (%s)\n", VNAME[g->chk.verdict], g->scene, g->name,
           strcmp(g->over, "h") ? "h" : "ppc", g->fixed, g->chk.measured, pts);
  }
}

/* ------------------------------------------------------------------ driver */

/* Keeps the cases whose folder DIR holds; their number. */
static int keep_found(const ver_verify_opts *o, vcase *cs, int n)
{
  int m = 0;
  for (int i = 0; i < n; i++) {
    char dir[1200];
    struct stat st;
    case_dir(o, &cs[i], dir, sizeof dir);
    if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode))
      cs[m++] = cs[i];
  }
  return m;
}

int ver_verify(const ver_verify_opts *o)
{
  vcase *cs;
  int n;
  int mk = make_cases(o, &cs, &n);
  if (mk)
    return mk;
  if (o->merge_found) {
    /* the cases of both lists (full, then the quick variants) that DIR holds */
    ver_verify_opts q = *o;
    q.full = !o->full;
    vcase *cq;
    int nq;
    if ((mk = make_cases(&q, &cq, &nq))) {
      free(cs);
      return mk;
    }
    vcase *all = realloc(cs, (size_t)(n + nq) * sizeof *cs);
    if (!all) {
      free(cs);
      free(cq);
      return 2;
    }
    cs = all;
    for (int i = 0; i < nq; i++) {
      int dup = 0;
      for (int j = 0; j < n && !dup; j++)
        dup = !strcmp(cs[j].id, cq[i].id);
      if (!dup)
        cs[n++] = cq[i];
    }
    free(cq);
    n = keep_found(o, cs, n);
    if (n == 0) {
      fprintf(stderr, "delam verify: %s holds no case folder of the full or the quick list\n", o->outdir);
      free(cs);
      return 2;
    }
  }
  if (o->list) {
    for (int i = 0; i < n; i++) {
      const vcase *c = &cs[i];
      printf("%s run %s --h %g --ppc %d", o->self, c->path, c->h, c->ppc);
      for (int s = 0; s < c->nset; s++)
        printf(" --set %s", c->sets[s]);
      /* one thread per case: a dispatcher runs many at once, and OpenMP teams that
       * outnumber the cores spin against each other (9 cases at once, 2 threads each,
       * on 2 cores: minutes instead of seconds) */
      printf(" --threads 1 --quiet --out %s/%s\n", o->outdir, c->id);
    }
    free(cs);
    return 0;
  }
  if (ver_mkdir_p(o->outdir) != 0) {
    fprintf(stderr, "delam verify: %s: cannot create: %s\n", o->outdir, strerror(errno));
    free(cs);
    return 2;
  }
  const double w0 = ver_now_wall();
  if (!o->merge) {
    fprintf(stderr, "verify: %d cases, %d at a time, into %s/\n", n, o->jobs, o->outdir);
    if (run_cases(o, cs, n)) {
      free(cs);
      return 2;
    }
  }
  for (int i = 0; i < n; i++) {
    case_read(o, &cs[i]);
    check_policy(&cs[i]);
    for (int j = 0; j < cs[i].nchk; j++)
      print_check(cs[i].id, &cs[i].chk[j]);
  }
  vcross x[MAXCROSS];
  const int nx = cross_checks(cs, n, x);
  for (int i = 0; i < nx; i++) {
    char id[160];
    snprintf(id, sizeof id, "%s/%s%g", x[i].scene, strcmp(x[i].over, "h") ? "h" : "ppc", x[i].fixed);
    print_check(id, &x[i].chk);
  }
  int rc = 0;
  for (int i = 0; i < n; i++)
    if (cs[i].verdict == VER_FAIL)
      rc = 1;
  for (int i = 0; i < nx; i++)
    if (x[i].chk.verdict == VER_FAIL)
      rc = 1;
  print_table(cs, n, x, nx);
  const double wall = ver_now_wall() - w0;
  if (write_json(o, cs, n, x, nx, wall, rc) || write_csv(o, cs, n)) {
    fprintf(stderr, "delam verify: %s: cannot write verify.json / verify.csv: %s\n", o->outdir, strerror(errno));
    rc = rc ? rc : 2;
  }
  printf("\nverify: %d cases in %.1f s -> %s/verify.json, verify.csv: %s\n", n, wall, o->outdir,
         rc ? "FAIL (a check failed)" : "no failed check");
  free(cs);
  return rc;
}
