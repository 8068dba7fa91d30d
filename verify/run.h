/*
 * run.h - one run of a scene: the time loop, the stop rule, and the output files
 * (load.csv, energy.csv, snapshots as CSV and legacy VTK, summary.json).
 */
#ifndef DELAM_RUN_H
#define DELAM_RUN_H

#include <signal.h>

#include "io.h"
#include "scene.h"
#include "summary.h"

typedef struct {
  const char *outdir;            /* where the files go (created if missing)         */
  int progress;                  /* 1: show progress on stderr (if it is a terminal) */
  int write_files;               /* 0: measure only (bench)                          */
  volatile sig_atomic_t *stop;   /* set by a signal handler to stop cleanly, or NULL */
  long max_steps;                /* > 0: stop after this many steps (bench)          */
  int threads;                   /* OpenMP threads (0: leave as is)                  */
} ver_run_opts;

/* Runs the scene.  Returns 0 (complete), 1 (the run failed: message in err),
 * 2 (bad input), 130 (stopped by a signal). */
int ver_run(const ver_scene *vs, const ver_run_opts *o, ver_summary *sum, char *err, size_t errlen);

#endif
