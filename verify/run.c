/*
 * run.c - the time loop of one scene and its outputs.
 *
 * Stop rule: the run has answered once the bar has separated, detected the first of two
 * ways: kinematically, separated particles (eqs. 56-58) cut every particle row; or by
 * the load, after the peak its mean over the bar's longest period 4 L / c falls below
 * run.sep_load times the peak.  The run goes on for run.stop_margin more end
 * displacement and past the last requested snapshot, never beyond run.end_delta.
 *
 * Loads are written as averages over each output interval (impulse / time), which is
 * what a load cell reads.  Every file is written under a temporary name and renamed when
 * complete; summary.json, written last, says complete: true only for a finished run.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "build_info.h"
#include "io.h"
#include "metrics.h"
#include "run.h"
#include "run_out.h"
#include "separation.h"

#define VER_STATIC_MAX_INC 100000 /* a static run's increments: rows are allocated for them */

typedef ver_run_row row;

/* sum m vx sin(k X) over the bar's particles: the velocity of the axial mode k */
static double modal_velocity(const mpm_sim *s, double k)
{
  mpm_particle_view v;
  mpm_sim_particles(s, &v);
  const mpm_particle_view *p = &v;
  double a = 0.0;
  for (size_t i = 0; i < p->n; i++)
    if (p->mat[i] != MPM_MAT_HEAD)
      a += p->m[i] * p->vx[i] * sin(k * p->x0[i]);
  return a;
}

/* Elastic slope of the written rows (metrics.h, one definition). */
static double fit_elastic(const row *r, long n, double peak, double delta_peak)
{
  double *d = malloc(2 * (size_t)(n + 1) * sizeof *d), k = NAN;
  if (!d)
    return NAN;
  for (long i = 0; i < n; i++) {
    d[i] = r[i].delta;
    d[n + i] = r[i].Pg;
  }
  k = ver_elastic_slope(d, d + n, (size_t)n, peak, delta_peak, VER_ELASTIC_LO, VER_ELASTIC_HI);
  free(d);
  return k;
}

/* The folder for one run, this process its one writer: created, locked (a second run
 * into it is refused, naming the first's pid), then cleared of what an earlier run
 * wrote, so that an old summary cannot vouch for the new run and old snapshots do not
 * sit beside new results; temporaries an interrupted run left go too.  The lock's
 * descriptor in *lock (closed when the run is over).  0, 1 (cannot write there) or 2
 * (--out is not a folder, or another run holds it), with err. */
static int prepare_outdir(const char *dir, int *lock, char *err, size_t errlen)
{
  *lock = -1;
  if (ver_mkdir_p(dir) != 0) {
    const int e = errno;
    snprintf(err, errlen, "%s: cannot create the folder: %s", dir, strerror(e));
    return e == ENOTDIR || e == ENAMETOOLONG || e == ELOOP ? 2 : 1;
  }
  if ((*lock = ver_io_lock_dir(dir, err, errlen)) < 0)
    return errno == EAGAIN ? 2 : 1;
  DIR *d = opendir(dir);
  for (struct dirent *e = d ? readdir(d) : NULL; e; e = readdir(d)) {
    const char *n = e->d_name;
    const size_t len = strlen(n);
    if (!strncmp(n, "snap-d", 6) || !strncmp(n, "final.", 6) || !strncmp(n, "final-line.", 11) ||
        !strcmp(n, "snapshots.pvd") ||
        !strcmp(n, "summary.json") || !strcmp(n, "load.csv") || !strcmp(n, "energy.csv") ||
        !strcmp(n, "scene.ini") || !strcmp(n, "check.json") || !strcmp(n, "plot.png") ||
        (len > 4 && !strcmp(n + len - 4, ".tmp"))) {
      char old[1400];
      snprintf(old, sizeof old, "%s/%s", dir, n);
      remove(old);
    }
  }
  if (d)
    closedir(d);
  return 0;
}

/* scene.ini: the effective scene, which `delam run scene.ini` reproduces. */
static int write_scene_ini(const ver_scene *vs, const char *dir)
{
  char path[1200], tmp[1300];
  snprintf(path, sizeof path, "%s/scene.ini", dir);
  FILE *f = ver_io_open_tmp(path, tmp, sizeof tmp);
  if (!f)
    return -1;
  if (ver_scene_write_ini(vs, f) != 0) {
    fclose(f);
    remove(tmp);
    return -1;
  }
  return ver_io_commit(f, tmp);
}

/* The state of one run's time loop. */
typedef struct {
  const ver_scene *vs;
  const ver_run_opts *o;
  mpm_sim *s;
  mpm_static *q;                 /* solver.type = static: the increments' solver, else NULL */
  double D_sep;                  /* static: D on the row where the load test fired (delta may
                                    go back on a snapback: not a function of delta)      */
  row *rows;
  long nrow, nmax, every, acc_n;
  double vdt, last_snap, acc_g, acc_f, peak, dpeak;
  ver_sep sep;
  mpm_energy e0;                 /* the energies at the start                        */
  double wmax;                   /* max(E0, |W_ext|) so far                          */
  double made_at;                /* delta where the run first made VER_CREATED_TOL of it (-1) */
  /* vibration.mode > 0: zero crossings of the modal velocity give the period */
  double kmode, modal_prev, t_prev, cross_first, cross_last;
  long ncross;
  int snap_done[VER_MAX_SNAP];
  char id[600];
} run_state;

/* Allocates the rows and the separation detector (before the loop: no malloc in it). */
static int run_setup(run_state *r, char *err, size_t errlen)
{
  const mpm_scene *sc = &r->vs->sc;
  r->vdt = sc->speed * sc->dt;
  r->nmax = (long)ceil(sc->end_delta / r->vdt - 1e-9);
  if (r->q) { /* a row per increment, no time to average the load over */
    r->vdt = 0.0;
    r->nmax = VER_STATIC_MAX_INC;
  }
  /* loading.control = dissipation: the grip may move back for a while, so the steps to
   * end_delta are not known; three times the grip's own budget, and the loop stops at
   * end_delta */
  if (sc->control == MPM_CONTROL_DISSIPATION)
    r->nmax *= 3;
  r->every = r->q ? 1 : (long)fmax(1.0, floor(r->vs->interval / r->vdt + 0.5));
  const long nrows_max = r->nmax / r->every + 2;
  r->rows = malloc(sizeof(row) * (size_t)nrows_max);
  /* separation: the load window is 4 L / c in time, in rows (separation.h) */
  const double c = sqrt(sc->E / (1.0 - sc->nu * sc->nu) / sc->rho);
  const long win = r->q ? 1 : (long)fmax(1.0, ceil(4.0 * sc->L / c / (sc->dt * (double)r->every)));
  const int sep_ok = ver_sep_init(&r->sep, sc->H, sc->h, sc->ppc, win, r->vs->sep_load_frac) == 0;
  if (!r->rows || !sep_ok) {
    snprintf(err, errlen, "out of memory for %ld output rows", nrows_max);
    return 1;
  }
  for (int i = 0; i < r->vs->nsnap; i++)
    r->last_snap = fmax(r->last_snap, r->vs->snap[i]);
  ver_scene_case_id(r->vs, r->id, sizeof r->id);
  mpm_sim_energy(r->s, &r->e0);
  r->made_at = -1.0;
  r->kmode = sc->vib_mode * ANA_PI / sc->L;
  r->modal_prev = sc->vib_mode > 0 ? modal_velocity(r->s, r->kmode) : 0.0;
  r->cross_first = r->cross_last = -1.0;
  return 0;
}

/* After a step: accumulates the loads; on an output row records it and asks the
 * separation detector. */
static void take_step(run_state *r, ver_summary *u, double delta)
{
  mpm_sim *s = r->s;
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  r->acc_g += in.P_grip;
  r->acc_f += in.P_fixed;
  r->acc_n++;
  if (!(in.step % r->every == 0 || in.step == r->nmax))
    return;
  row *w = &r->rows[r->nrow++];
  w->t = in.t;
  w->delta = delta;
  w->Pg = r->acc_g / r->acc_n;
  w->Pf = r->acc_f / r->acc_n;
  w->tip = in.crack_tip;
  w->zone = in.zone_end;
  w->det = NAN;
  if (r->q) { /* the state's stability and the critical point crossed to it (docs/static.md) */
    mpm_static_stats qs;
    mpm_static_stats_get(r->q, &qs);
    w->det = qs.det_sign;
    if (qs.crit && u->ncrit++ < VER_CRIT_MAX)
      u->crit[u->ncrit - 1] = (ver_crit){in.step, delta, w->Pg, qs.crit};
  }
  r->acc_g = r->acc_f = 0.0;
  r->acc_n = 0;
  mpm_sim_energy(s, &w->e);
  /* energy the run made: every booked loss is work taken out, so KE + SE + W_coh above
   * W_ext + E0 is an unstable step (fig6 at 1 ppc past 0.64 of the CFL bound, once a
   * particle separates) */
  const double E0 = r->e0.KE + r->e0.SE;
  r->wmax = fmax(r->wmax, fmax(E0, fabs(w->e.W_ext)));
  const double made = r->wmax > 0.0 ? (w->e.KE + w->e.SE + w->e.W_coh - w->e.W_ext - E0) / r->wmax : 0.0;
  u->energy_created = fmax(u->energy_created, made);
  if (made > VER_CREATED_TOL && r->made_at < 0.0)
    r->made_at = delta;
  if (r->vs->sc.vib_mode > 0) {
    const double a = modal_velocity(s, r->kmode);
    if ((a > 0.0) != (r->modal_prev > 0.0)) { /* a crossing, interpolated between rows */
      const double tc = r->t_prev + (w->t - r->t_prev) * r->modal_prev / (r->modal_prev - a);
      if (r->cross_first < 0)
        r->cross_first = tc;
      r->cross_last = tc;
      r->ncross++;
    }
    r->modal_prev = a;
    r->t_prev = w->t;
  }
  if (w->Pg > r->peak) {
    r->peak = w->Pg;
    r->dpeak = delta;
  }
  if (in.n_separate > 0) {
    mpm_particle_view p;
    mpm_sim_particles(s, &p);
    ver_sep_cut(&r->sep, p.y0, p.sep, p.mat, MPM_MAT_HEAD, p.n, delta);
  }
  if (in.cut && mpm_sim_scene(s)->path == MPM_PATH_IFACE)
    ver_sep_through(&r->sep, delta);
  if (r->q) { /* equilibrium rows: separated at the first row past the peak below sep_load of it */
    if (r->sep.delta_load < 0 && r->peak > 0.0 && w->Pg < r->peak && w->Pg <= r->vs->sep_load_frac * r->peak) {
      r->sep.delta_load = delta;
      r->D_sep = w->e.D;
      /* the rows are exact states: where separating at lambda = 1 leaves no load, not this
       * row's delta, which lies as far from it as the rows are spaced (a30 at h 1: 0.1992
       * against 0.1903) */
      const row *pv = r->nrow >= 2 ? &r->rows[r->nrow - 2] : NULL;
      if (r->sep.delta_sep < 0)
        r->sep.delta_sep = pv && r->vs->sc.sep_threshold >= 1.0 ? ver_sep_static(pv->delta, pv->Pg, delta, w->Pg, 0.0)
                                                                 : delta;
    }
  } else
    ver_sep_load(&r->sep, delta, w->Pg, w->Pf, r->peak, r->dpeak);
  u->delta_sep_cut = r->sep.delta_cut;
  u->delta_sep_load = r->sep.delta_load;
  u->delta_sep = r->sep.delta_sep;
}

/* Writes the snapshots that are due at delta; 0, or 1 with err. */
static int take_snapshots(run_state *r, double delta, char *err, size_t errlen)
{
  int rc = 0;
  for (int i = 0; i < r->vs->nsnap; i++)
    if (!r->snap_done[i] && delta >= r->vs->snap[i] - 0.5 * r->vdt) {
      char stem[64];
      snprintf(stem, sizeof stem, "snap-d%.3f", r->vs->snap[i]);
      char bad[VER_RUN_BAD];
      if (ver_run_write_snapshot(r->s, r->o->outdir, stem, bad) != 0) {
        rc = 1;
        snprintf(err, errlen, "%s", bad);
      }
      r->snap_done[i] = 1;
    }
  return rc;
}

/* The energy residual of the rows (metrics.h: the one definition, also `delam check`'s). */
static double energy_residual(const row *rows, long n, double E0, double *raw)
{
  double *buf = malloc(VER_ENERGY_COLS * (size_t)(n + 1) * sizeof *buf), res;
  if (!buf) {
    *raw = NAN;
    return NAN;
  }
  const double *e[VER_ENERGY_COLS];
  for (int j = 0; j < VER_ENERGY_COLS; j++)
    e[j] = buf + (size_t)j * (size_t)(n + 1);
  for (long i = 0; i < n; i++) {
    const mpm_energy *q = &rows[i].e;
    const double v[VER_ENERGY_COLS] = {q->W_ext,  q->KE,       q->SE,     q->W_coh,     q->L_bc,
                                       q->L_flip, q->L_scheme, q->W_head, q->L_contact, q->L_debris, q->L_damp};
    for (int j = 0; j < VER_ENERGY_COLS; j++)
      buf[(size_t)j * (size_t)(n + 1) + (size_t)i] = v[j];
  }
  res = ver_energy_residual(e, (size_t)n, E0, raw);
  free(buf);
  return res;
}

/* The summary's numbers at the end of the loop. */
static void finish(const run_state *r, ver_summary *u, double w0, double c0)
{
  const mpm_sim *s = r->s;
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  mpm_particle_view p;
  mpm_sim_particles(s, &p);
  u->wall_s = ver_now_wall() - w0;
  u->cpu_s = ver_now_cpu() - c0;
  u->steps = in.step;
  u->threads_req = r->o->threads;
  mpm_threads_info ti;
  mpm_sim_threads(s, &ti);
  u->threads_max = ti.nmax;
  u->steps_multi = ti.steps_multi;
  u->probes = ti.nprobe;
  u->probes_busy = ti.nbusy;
  u->particles = p.n;
  u->updates_per_s = u->wall_s > 0 ? (double)p.n * (double)in.step / u->wall_s : 0;
  u->peak_P = r->peak;
  u->delta_peak = r->dpeak;
  u->k_elastic = fit_elastic(r->rows, r->nrow, r->peak, r->dpeak);
  u->delta_end = mpm_sim_delta(s);
  u->n_soften = in.n_soften;
  u->n_separate = in.n_separate;
  u->n_bracketed = in.n_bracketed;
  if (r->q) {
    mpm_static_stats qs;
    mpm_static_stats_get(r->q, &qs);
    u->static_run = 1;
    u->increments = qs.increments;
    u->newton = qs.newton;
    u->factorizations = qs.factorizations;
    u->updates = qs.updates;
    u->cuts = qs.cuts;
    u->severed = qs.severed;
    u->unknowns = qs.unknowns;
    u->t_eval = qs.t_eval;
    u->t_factor = qs.t_factor;
    u->t_solve = qs.t_solve;
  }
  mpm_energy e;
  mpm_sim_energy(s, &e);
  u->D_final = e.D;
  /* the dissipation at the detected separation: the output row at delta_sep (the cut
   * test fires on a row; the load test's window centre takes the first row at or past it) */
  u->D_cut = NAN;
  if (r->nrow > 0) {
    double *b = malloc(2 * sizeof(double) * (size_t)r->nrow);
    if (b) {
      for (long i = 0; i < r->nrow; i++) {
        b[i] = r->rows[i].delta;
        b[r->nrow + i] = r->rows[i].e.D;
      }
      u->D_cut = ver_value_at(b, b + r->nrow, (size_t)r->nrow, u->delta_sep);
      free(b);
    }
  }
  if (r->q)
    u->D_cut = u->delta_sep >= 0 ? r->D_sep : NAN;
  u->D_after_cut = u->D_final - u->D_cut;
  u->W_ext_final = e.W_ext;
  u->W_coh_final = e.W_coh;
  u->KE_final = e.KE;
  u->SE_final = e.SE;
  u->L_bc_final = e.L_bc;
  u->L_flip_final = e.L_flip;
  u->L_scheme_final = e.L_scheme;
  u->W_head_final = e.W_head;
  u->L_contact_final = e.L_contact;
  u->L_debris_final = e.L_debris;
  u->L_damp_final = e.L_damp;
  u->n_debris = in.n_debris;
  u->crack_tip_final = in.crack_tip;
  u->gap_min = isfinite(in.gap_min) ? in.gap_min : NAN;
  const double E0 = r->e0.KE + r->e0.SE;
  u->energy_residual = energy_residual(r->rows, r->nrow, E0, &u->energy_unbooked);
  u->energy_start = E0;
  const mpm_scene *sc = &r->vs->sc;
  /* what a free vibration kept; a loaded run's KE + SE is not a kept energy (the brittle
   * release read 6.99) */
  u->energy_kept = sc->vib_mode > 0 && E0 > 0 ? (e.KE + e.SE) / E0 : NAN;
  u->period = r->ncross >= 3 ? 2.0 * (r->cross_last - r->cross_first) / (double)(r->ncross - 1) : NAN;
  u->period_exact = sc->vib_mode > 0 ? ver_scene_vib_period(sc) : NAN;
  u->period_error = u->period / u->period_exact - 1.0;
}

/* Steps (static: increments) the sim has taken. */
static long steps_taken(const mpm_sim *s)
{
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  return in.step;
}

/* The time loop: steps until the end, the stop rule, a failure or a signal. */
static int run_loop(run_state *r, ver_summary *u, double w0, char *err, size_t errlen)
{
  mpm_sim *s = r->s;
  const mpm_scene *sc = mpm_sim_scene(s);
  const ver_run_opts *o = r->o;
  const int show = o->progress && isatty(2);
  double next_show = w0 + 0.5;
  char kerr[512];
  int rc = 0;
  while (steps_taken(s) < r->nmax && !rc) {
    if (o->stop && *o->stop) {
      snprintf(err, errlen, "%s: stopped by a signal at step %ld (delta = %g)", r->id, steps_taken(s),
               mpm_sim_delta(s));
      rc = 130;
      break;
    }
    if (o->max_steps > 0 && steps_taken(s) >= o->max_steps)
      break;
    const mpm_status st = r->q ? mpm_static_step(r->q, kerr, sizeof kerr) : mpm_sim_step(s, kerr, sizeof kerr);
    if (st != MPM_OK) {
      snprintf(err, errlen, "%s: %s: %s", r->id, mpm_strerror(st), kerr);
      u->status = st;
      rc = 1;
      break;
    }
    const double delta = mpm_sim_delta(s);
    take_step(r, u, delta);
    if (r->made_at >= 0.0 && !r->vs->allow_unstable) {
      snprintf(err, errlen, "%s: the run made energy: KE + SE + W_coh exceeded W_ext + E0 by %.3g of the largest "
               "work at delta = %g (an unstable step: try a smaller --dt or more particles per cell; "
               "--allow-unstable runs on and marks the run unstable)", r->id, u->energy_created, r->made_at);
      rc = 1;
      break;
    }
    if (o->write_files && take_snapshots(r, delta, err, errlen))
      rc = 1;
    if (!rc && u->delta_sep >= 0 && r->vs->stop_margin > 0 && delta >= u->delta_sep + r->vs->stop_margin &&
        delta >= r->last_snap)
      break;
    if ((r->q || sc->control == MPM_CONTROL_DISSIPATION) && delta >= sc->end_delta - 0.5 * r->vdt)
      break;
    mpm_sim_info in;
    mpm_sim_info_get(s, &in);
    if (show && (r->q || (in.step & 255) == 0) && ver_now_wall() > next_show) {
      next_show = ver_now_wall() + 0.5;
      fprintf(stderr, "\r%s: delta %.4f / %.4f  step %ld  P %.3f  [%.1f s]   ", r->id, delta, r->vs->sc.end_delta,
              in.step, in.P_grip, ver_now_wall() - w0);
    }
  }
  if (show)
    fprintf(stderr, "\r%*s\r", 90, "");
  return rc;
}

/* snapshots.pvd: the snapshots written, as one ParaView time series (time = delta):
 * part 0 the particles' .vtp, part 1 the line's where there is one (VTK's collection
 * reader reads only VTK XML files, hence .vtp; docs/output-formats.md). */
static int write_pvd(const run_state *r, const char *dir, char *bad)
{
  int any = 0;
  for (int i = 0; i < r->vs->nsnap; i++)
    any |= r->snap_done[i];
  if (!any)
    return 0;
  char tmp[1100];
  FILE *f = ver_run_open_tmp(dir, "snapshots.pvd", tmp, sizeof tmp, bad);
  if (!f)
    return -1;
  const int line = mpm_iface_pieces(r->s) > 0;
  fprintf(f, "<?xml version=\"1.0\"?>\n<!-- delam snapshots.pvd schema %d: time is the end displacement delta -->\n"
          "<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n", VER_SCHEMA_PVD);
  for (int i = 0; i < r->vs->nsnap; i++)
    if (r->snap_done[i]) {
      const double d = r->vs->snap[i];
      fprintf(f, "<DataSet timestep=\"%.6g\" part=\"0\" name=\"particles\" file=\"snap-d%.3f.vtp\"/>\n", d, d);
      if (line)
        fprintf(f, "<DataSet timestep=\"%.6g\" part=\"1\" name=\"line\" file=\"snap-d%.3f-line.vtp\"/>\n", d, d);
    }
  fputs("</Collection>\n</VTKFile>\n", f);
  return ver_run_commit(f, tmp, bad);
}

/* The files of a run whose loop ended with rc (err holds its reason if rc): load.csv,
 * energy.csv and the final particles, then summary.json last, written even where the
 * others failed, so that the folder says the run did not finish.  The run's status,
 * 1 if a file could not be written (err names it and why). */
static int write_results(run_state *r, ver_summary *u, int rc, char *err, size_t errlen)
{
  const char *dir = r->o->outdir;
  char bad[VER_RUN_BAD];
  const int files = ver_run_write_rows(r->rows, r->nrow, dir, bad) != 0 || ver_run_write_snapshot(r->s, dir, "final", bad) != 0 ||
                    write_pvd(r, dir, bad) != 0;
  if (files) {
    u->complete = 0;
    if (!rc)
      snprintf(err, errlen, "%s", bad);
    rc = rc ? rc : 1;
  }
  if (ver_summary_write(dir, r->vs, u, err) != 0) {
    const int e = errno;
    const size_t n = strlen(err);
    snprintf(err + n, errlen - n, "%s%s/summary.json: cannot write: %s", n ? "; " : "", dir, strerror(e));
    u->complete = 0;
    rc = rc ? rc : 1;
  }
  return rc;
}

int ver_run(const ver_scene *vs, const ver_run_opts *o, ver_summary *u, char *err, size_t errlen)
{
  memset(u, 0, sizeof *u);
  u->delta_sep = u->delta_sep_cut = u->delta_sep_load = -1;
  run_state r;
  memset(&r, 0, sizeof r);
  r.vs = vs;
  r.o = o;
  /* the kernel's refusal (a scene it cannot lay out) leaves the folder as it was */
  char kerr[512];
  if (ver_static_refusal(&vs->sc, kerr, sizeof kerr)) {
    snprintf(err, errlen, "%s: %s", vs->path, kerr);
    return 2;
  }
  const mpm_status st = mpm_sim_alloc(&vs->sc, o->threads, &r.s, kerr, sizeof kerr);
  if (st != MPM_OK) {
    snprintf(err, errlen, "%s: %s", vs->path, kerr);
    return st == MPM_EINVAL ? 2 : 1;
  }
  if (vs->sc.solver == MPM_SOLVER_STATIC) {
    const mpm_status qst = mpm_static_alloc(r.s, &r.q, kerr, sizeof kerr);
    if (qst != MPM_OK) {
      snprintf(err, errlen, "%s: %s", vs->path, kerr);
      mpm_sim_free(r.s);
      return qst == MPM_EINVAL ? 2 : 1;
    }
  }
  int lock = -1, prc = o->write_files ? prepare_outdir(o->outdir, &lock, err, errlen) : 0;
  if (!prc && o->write_files && write_scene_ini(vs, o->outdir) != 0) {
    snprintf(err, errlen, "%s/scene.ini: cannot write: %s", o->outdir, strerror(errno));
    prc = 1;
  }
  if (prc) {
    if (lock >= 0)
      close(lock);
    mpm_static_free(r.q);
    mpm_sim_free(r.s);
    return prc;
  }
  int rc = run_setup(&r, err, errlen);
  if (!rc) {
    const double w0 = ver_now_wall(), c0 = ver_now_cpu();
    err[0] = '\0';
    rc = run_loop(&r, u, w0, err, errlen);
    finish(&r, u, w0, c0);
    u->complete = rc == 0;
    u->unstable = r.made_at >= 0.0; /* --allow-unstable ran on: the folder says so */
    if (o->write_files)
      rc = write_results(&r, u, rc, err, errlen);
  }
  free(r.rows);
  ver_sep_free(&r.sep);
  mpm_static_free(r.q);
  mpm_sim_free(r.s);
  if (lock >= 0)
    close(lock); /* after summary.json: the folder is the next writer's */
  return rc;
}
