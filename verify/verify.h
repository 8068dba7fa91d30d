/*
 * verify.h - `delam verify`: sweeps of the scenes over h and particles per cell,
 * each run checked against the closed-form bar (analytic/ana.h, docs/model.md sec. 5),
 * then cross-case checks (energy invariance over h and ppc, observed order of
 * convergence of the load-deflection curve).
 *
 * The sweep itself (verify.c: case list, runs in child processes, reading the per-case
 * output files, verdicts, verify.json/verify.csv); what it measures is metrics.h, how
 * one check is judged is check.h.
 */
#ifndef DELAM_VERIFY_H
#define DELAM_VERIFY_H

#include <stddef.h>

#include "check.h"
#include "metrics.h"

/* ---- the sweep (verify.c) ---- */
typedef struct {
  int full;              /* 0: the --quick subset, 1: every scene x h x ppc               */
  int angles;            /* 1: the inclined scene files at other angles (--angles)        */
  int jobs;              /* parallel cases                                                */
  const char *outdir;    /* DIR: DIR/<case-id>/, DIR/verify.json, DIR/verify.csv         */
  const char *scenes;    /* folder of the scene files (data/scenes)                      */
  const char *self;      /* path of the delam program, for --list                        */
  int list;              /* 1: print one `delam run` line per case and stop               */
  int merge;             /* 1: do not run; check what DIR already holds                  */
  const char *method;    /* a preset every case runs with (--method NAME), or NULL        */
  int merge_found;       /* with merge: the cases of either list whose folders DIR holds
                            (neither --quick nor --full given)                           */
} ver_verify_opts;

/* Runs (or lists, or merges) the sweep.  Returns 0 when no pass-class check failed,
 * 1 when one did, 2 on bad input (a scene that does not load, an unwritable DIR). */
int ver_verify(const ver_verify_opts *o);

#endif
