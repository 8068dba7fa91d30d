/*
 * run_out.h - the files of one run (run_out.c), private to verify/.
 */
#ifndef DELAM_VER_RUN_OUT_H
#define DELAM_VER_RUN_OUT_H

#include <stdio.h>

#include "mpm.h"

#define VER_RUN_BAD 1400 /* bytes of the message that says which file failed and why */

/* One output row: the loads averaged over the interval that ends at t (a static run: the
 * equilibrium state of the increment) and the energies there. */
typedef struct {
  double t, delta, Pg, Pf;
  double tip;              /* the crack front's x (NAN: the specimen has no pre-crack) */
  double zone;             /* the process zone's far end (NAN: no pre-crack)          */
  double det;              /* static: the sign of the tangent's determinant (NAN: explicit) */
  mpm_energy e;
} ver_run_row;


/* Opens dir/name under a temporary name for writing; ver_run_commit renames it into place.
 * Either, failing, says which file and why in bad (VER_RUN_BAD bytes), errno kept. */
FILE *ver_run_open_tmp(const char *dir, const char *name, char *tmp, size_t len, char *bad);
int ver_run_commit(FILE *f, const char *tmp, char *bad);
/* <stem>.csv and <stem>.vtp of the bar's particles, and the line's <stem>-line.csv and
 * .vtp where there is one (the interface, the split beams); 0, or -1 with bad. */
int ver_run_write_snapshot(const mpm_sim *s, const char *dir, const char *stem, char *bad);
/* load.csv and energy.csv of the n rows; 0, or -1 with bad. */
int ver_run_write_rows(const ver_run_row *r, long n, const char *dir, char *bad);

#endif
