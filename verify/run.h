/*
 * run.h - one run of a scene: the time loop, the stop rule, and the output files
 * (load.csv, energy.csv, snapshots as CSV and legacy VTK, summary.json).
 */
#ifndef DELAM_RUN_H
#define DELAM_RUN_H

#include <signal.h>

#include "scene.h"

typedef struct {
  const char *outdir;            /* where the files go (created if missing)         */
  int progress;                  /* 1: show progress on stderr (if it is a terminal) */
  int write_files;               /* 0: measure only (bench)                          */
  volatile sig_atomic_t *stop;   /* set by a signal handler to stop cleanly, or NULL */
  long max_steps;                /* > 0: stop after this many steps (bench)          */
  int threads;                   /* OpenMP threads (0: leave as is)                  */
} ver_run_opts;

typedef struct {
  double peak_P, delta_peak;     /* largest (interval-averaged) grip load and where  */
  double delta_sep;              /* separation: the first of delta_sep_cut and delta_sep_load; -1 if none */
  double delta_sep_cut;          /* first delta at which separated particles cut every particle row */
  double delta_sep_load;         /* first delta after the peak with the windowed |P| < sep_load * peak */
  double k_elastic;              /* least-squares slope of P(delta) for P < 0.6 peak before the peak */
  double D_final, W_ext_final, W_coh_final, KE_final, SE_final;
  double energy_residual;        /* max |W_ext - KE - SE - W_coh| / max(W_ext) over the rows */
  double delta_end;              /* where the run stopped                            */
  long steps;
  size_t particles;
  long n_soften, n_separate, n_bracketed;
  double wall_s, cpu_s, updates_per_s;
  int complete;                  /* 1 if the run reached its stop rule               */
  int status;                    /* mpm_status of the run                            */
} ver_summary;

/* mkdir -p; 0 or -1 with errno set. */
int ver_mkdir_p(const char *dir);

/* Runs the scene.  Returns 0 (complete), 1 (the run failed: message in err),
 * 2 (bad input), 130 (stopped by a signal). */
int ver_run(const ver_scene *vs, const ver_run_opts *o, ver_summary *sum, char *err, size_t errlen);

#endif
