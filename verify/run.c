/*
 * run.c - the time loop of one scene and its outputs.
 *
 * Stop rule: a run answers its question once the bar has separated.  Separation is
 * detected in two ways, and the first one counts:
 *  - kinematically: the separated particles (lambda past the separation threshold,
 *    eqs. 56-58) cut every row of particles, so no row still holds the bar together;
 *  - by the load: after the peak, the load averaged over the bar's longest natural
 *    period (4 L / c, so that ringing after a sudden release averages out) falls below
 *    run.sep_load times the peak (delta at the centre of that window).
 * The kinematic test catches inclined bands, where one velocity per cell keeps a few %
 * of the load on the grip after the band has failed and the load test never fires.
 * The run goes on for run.stop_margin more end displacement (so the opening grows past
 * ubar0 and the dissipation settles), and past the last requested snapshot, and never
 * beyond run.end_delta.
 *
 * Loads are written as averages over each output interval (impulse / time), which is
 * what a load cell reads; the instantaneous reaction rings at the grid's frequencies.
 *
 * Every file is written under a temporary name and renamed when complete;
 * summary.json, written last, says complete: true only for a finished run.
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

#include "metrics.h"
#include "run.h"

/* Opens dir/name.tmp for writing; commit_file renames it into place. */
static FILE *open_tmp(const char *dir, const char *name, char *tmp, size_t len)
{
  char path[1100];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return ver_io_open_tmp(path, tmp, len);
}

static int commit_file(FILE *f, const char *tmp)
{
  return ver_io_commit(f, tmp);
}

static int write_snapshot(const mpm_sim *s, const char *dir, const char *stem)
{
  const mpm_particles *p = s->p;
  char tmp[1100], name[128];
  snprintf(name, sizeof name, "%s.csv", stem);
  FILE *f = open_tmp(dir, name, tmp, sizeof tmp);
  if (!f)
    return -1;
  fprintf(f, "x0,y0,x,y,ux,uy,lambda,sxx,syy,sxy,upn,upt,sep,wcoh\n");
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.9g\n", p->x0[k], p->y0[k],
            p->x[k], p->y[k], p->x[k] - p->x0[k], p->y[k] - p->y0[k], p->lam[k], p->sxx[k], p->syy[k],
            p->sxy[k], p->upn[k], p->upt[k], p->sep[k], p->wcoh[k]);
  if (commit_file(f, tmp))
    return -1;
  /* Legacy VTK polydata, one vertex per particle, for ParaView. */
  snprintf(name, sizeof name, "%s.vtk", stem);
  if (!(f = open_tmp(dir, name, tmp, sizeof tmp)))
    return -1;
  const size_t nb = p->n - s->nhead; /* the bar's particles; the head is the machine */
  fprintf(f, "# vtk DataFile Version 3.0\ndelam particles %s t=%g\nASCII\nDATASET POLYDATA\nPOINTS %zu double\n",
          stem, s->t, nb);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g %.9g 0\n", p->x[k], p->y[k]);
  fprintf(f, "VERTICES %zu %zu\n", nb, 2 * nb);
  for (size_t k = 0; k < nb; k++)
    fprintf(f, "1 %zu\n", k);
  fprintf(f, "POINT_DATA %zu\nVECTORS displacement double\n", nb);
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] != MPM_MAT_HEAD)
      fprintf(f, "%.9g %.9g 0\n", p->x[k] - p->x0[k], p->y[k] - p->y0[k]);
  const char *fields[] = {"lambda", "sxx", "syy", "sxy"};
  const double *arrs[] = {p->lam, p->sxx, p->syy, p->sxy};
  for (int q = 0; q < 4; q++) {
    fprintf(f, "SCALARS %s double 1\nLOOKUP_TABLE default\n", fields[q]);
    for (size_t k = 0; k < p->n; k++)
      if (p->mat[k] != MPM_MAT_HEAD)
        fprintf(f, "%.9g\n", arrs[q][k]);
  }
  return commit_file(f, tmp);
}

typedef struct {
  double t, delta, Pg, Pf;
  mpm_energy e;
} row;

static int write_rows(const row *r, long n, const char *dir)
{
  char tmp[1100];
  FILE *f = open_tmp(dir, "load.csv", tmp, sizeof tmp);
  if (!f)
    return -1;
  fprintf(f, "t,delta,P_grip,P_fixed\n");
  for (long i = 0; i < n; i++)
    fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", r[i].t, r[i].delta, r[i].Pg, r[i].Pf);
  if (commit_file(f, tmp))
    return -1;
  if (!(f = open_tmp(dir, "energy.csv", tmp, sizeof tmp)))
    return -1;
  fprintf(f, "t,W_ext,KE,SE,W_coh,D\n");
  for (long i = 0; i < n; i++)
    fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", r[i].t, r[i].e.W_ext, r[i].e.KE, r[i].e.SE, r[i].e.W_coh,
            r[i].e.D);
  return commit_file(f, tmp);
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

int ver_run(const ver_scene *vs, const ver_run_opts *o, ver_summary *u, char *err, size_t errlen)
{
  memset(u, 0, sizeof *u);
  u->delta_sep = u->delta_sep_cut = u->delta_sep_load = -1;
  const mpm_scene *sc = &vs->sc;
  if (o->write_files) {
    if (ver_mkdir_p(o->outdir) != 0) {
      snprintf(err, errlen, "%s: cannot create directory: %s", o->outdir, strerror(errno));
      return 2;
    }
    /* An old summary must not vouch for the new, unfinished run, and old snapshots must
     * not sit beside new results: remove what an earlier run here wrote. */
    DIR *d = opendir(o->outdir);
    for (struct dirent *e = d ? readdir(d) : NULL; e; e = readdir(d)) {
      const char *n = e->d_name;
      if (!strncmp(n, "snap-d", 6) || !strncmp(n, "final.", 6) || !strcmp(n, "summary.json") ||
          !strcmp(n, "load.csv") || !strcmp(n, "energy.csv")) {
        char old[1400];
        snprintf(old, sizeof old, "%s/%s", o->outdir, n);
        remove(old);
      }
    }
    if (d)
      closedir(d);
  }
  mpm_sim *s;
  char kerr[512];
  mpm_status st = mpm_sim_alloc(sc, o->threads, &s, kerr, sizeof kerr);
  if (st != MPM_OK) {
    snprintf(err, errlen, "%s: %s", vs->path, kerr);
    return st == MPM_EINVAL ? 2 : 1;
  }
  const double vdt = sc->speed * sc->dt;
  const long nmax = (long)ceil(sc->end_delta / vdt - 1e-9);
  const long every = (long)fmax(1.0, floor(vs->interval / vdt + 0.5));
  const long nrows_max = nmax / every + 2;
  row *rows = malloc(sizeof(row) * (size_t)nrows_max);
  /* rows of particles, for the kinematic separation test */
  const int n1 = (int)lround(sqrt((double)sc->ppc));
  const double dpy = sc->h / n1;
  const int nprow = (int)lround(sc->H / dpy);
  uint8_t *cut = calloc((size_t)nprow, 1);
  /* separation window: 4 L / c in time, in rows */
  const double c = sqrt(sc->E / (1.0 - sc->nu * sc->nu) / sc->rho);
  const long win = (long)fmax(1.0, ceil(4.0 * sc->L / c / (sc->dt * (double)every)));
  if (!rows || !cut) {
    free(rows);
    free(cut);
    mpm_sim_free(s);
    snprintf(err, errlen, "out of memory for %ld output rows", nrows_max);
    return 1;
  }
  double last_snap = 0.0;
  for (int i = 0; i < vs->nsnap; i++)
    last_snap = fmax(last_snap, vs->snap[i]);
  int snap_done[VER_MAX_SNAP] = {0};
  char id[128];
  ver_scene_case_id(vs, id, sizeof id);
  const int show = o->progress && isatty(2);

  long nrow = 0, acc_n = 0;
  double acc_g = 0.0, acc_f = 0.0, peak = 0.0, dpeak = 0.0;
  const double w0 = ver_now_wall(), c0 = ver_now_cpu();
  double next_show = w0 + 0.5;
  int rc = 0;
  err[0] = '\0';
  while (s->step < nmax) {
    if (o->stop && *o->stop) {
      rc = 130;
      snprintf(err, errlen, "%s: stopped by a signal at step %ld (delta = %g)", id, s->step, mpm_sim_delta(s));
      break;
    }
    if (o->max_steps > 0 && s->step >= o->max_steps)
      break;
    st = mpm_sim_step(s, kerr, sizeof kerr);
    if (st != MPM_OK) {
      rc = 1;
      snprintf(err, errlen, "%s: %s: %s", id, mpm_strerror(st), kerr);
      u->status = st;
      break;
    }
    acc_g += s->P_grip;
    acc_f += s->P_fixed;
    acc_n++;
    const double delta = mpm_sim_delta(s);
    if (s->step % every == 0 || s->step == nmax) {
      row *r = &rows[nrow++];
      r->t = s->t;
      r->delta = delta;
      r->Pg = acc_g / acc_n;
      r->Pf = acc_f / acc_n;
      acc_g = acc_f = 0.0;
      acc_n = 0;
      mpm_sim_energy(s, &r->e);
      if (r->Pg > peak) {
        peak = r->Pg;
        dpeak = delta;
      }
      if (u->delta_sep_cut < 0 && s->n_separate > 0) {
        const mpm_particles *p = s->p;
        int ncut = 0;
        memset(cut, 0, (size_t)nprow);
        for (size_t k = 0; k < p->n; k++)
          if (p->sep[k] && p->mat[k] != MPM_MAT_HEAD) {
            const int j = (int)(p->y0[k] / dpy);
            if (j >= 0 && j < nprow && !cut[j]) {
              cut[j] = 1;
              ncut++;
            }
          }
        if (ncut == nprow)
          u->delta_sep_cut = delta;
      }
      if (u->delta_sep_load < 0 && peak > 0 && nrow >= win && rows[nrow - win].delta > dpeak) {
        double mg = 0.0, mf = 0.0;
        for (long i = nrow - win; i < nrow; i++) {
          mg += rows[i].Pg;
          mf += rows[i].Pf;
        }
        if (fmax(fabs(mg), fabs(mf)) / (double)win < sc->sep_load_frac * peak)
          u->delta_sep_load = 0.5 * (rows[nrow - win].delta + delta);
      }
      if (u->delta_sep < 0 && (u->delta_sep_cut >= 0 || u->delta_sep_load >= 0))
        u->delta_sep = u->delta_sep_cut >= 0 && (u->delta_sep_load < 0 || u->delta_sep_cut < u->delta_sep_load)
                           ? u->delta_sep_cut : u->delta_sep_load;
    }
    if (o->write_files)
      for (int i = 0; i < vs->nsnap; i++)
        if (!snap_done[i] && delta >= vs->snap[i] - 0.5 * vdt) {
          char stem[64];
          snprintf(stem, sizeof stem, "snap-d%.3f", vs->snap[i]);
          if (write_snapshot(s, o->outdir, stem) != 0) {
            rc = 1;
            snprintf(err, errlen, "%s/%s: cannot write: %s", o->outdir, stem, strerror(errno));
          }
          snap_done[i] = 1;
        }
    if (rc)
      break;
    if (u->delta_sep >= 0 && sc->stop_margin > 0 && delta >= u->delta_sep + sc->stop_margin &&
        delta >= last_snap)
      break;
    if (show && (s->step & 255) == 0 && ver_now_wall() > next_show) {
      next_show = ver_now_wall() + 0.5;
      fprintf(stderr, "\r%s: delta %.4f / %.4f  step %ld  P %.3f  [%.1f s]   ", id, delta, sc->end_delta,
              s->step, s->P_grip, ver_now_wall() - w0);
    }
  }
  if (show)
    fprintf(stderr, "\r%*s\r", 90, "");
  u->wall_s = ver_now_wall() - w0;
  u->cpu_s = ver_now_cpu() - c0;
  u->steps = s->step;
  u->particles = s->p->n;
  u->updates_per_s = u->wall_s > 0 ? (double)s->p->n * (double)s->step / u->wall_s : 0;
  u->peak_P = peak;
  u->delta_peak = dpeak;
  u->k_elastic = fit_elastic(rows, nrow, peak, dpeak);
  u->delta_end = mpm_sim_delta(s);
  u->n_soften = s->n_soften;
  u->n_separate = s->n_separate;
  u->n_bracketed = s->n_bracketed;
  mpm_energy e;
  mpm_sim_energy(s, &e);
  u->D_final = e.D;
  u->W_ext_final = e.W_ext;
  u->W_coh_final = e.W_coh;
  u->KE_final = e.KE;
  u->SE_final = e.SE;
  double wmax = 0.0, res = 0.0;
  for (long i = 0; i < nrow; i++)
    wmax = fmax(wmax, fabs(rows[i].e.W_ext));
  for (long i = 0; i < nrow && wmax > 0; i++)
    res = fmax(res, fabs(rows[i].e.W_ext - rows[i].e.KE - rows[i].e.SE - rows[i].e.W_coh) / wmax);
  u->energy_residual = res;
  u->complete = rc == 0;
  if (o->write_files) {
    if (write_rows(rows, nrow, o->outdir) != 0 || write_snapshot(s, o->outdir, "final") != 0 ||
        ver_summary_write(o->outdir, vs, u, err) != 0) {
      if (!rc)
        snprintf(err, errlen, "%s: cannot write the results: %s", o->outdir, strerror(errno));
      rc = rc ? rc : 1;
      u->complete = 0;
    }
  }
  free(rows);
  free(cut);
  mpm_sim_free(s);
  return rc;
}
