/*
 * foreign.h - judging a run folder that any code wrote (`delam check`, cmd_check.c):
 * a strict reader of numeric CSV files and the measurements of a ver_case (sweep.h)
 * from them, so that policy.c can apply verify's own checks.
 */
#ifndef DELAM_VER_FOREIGN_H
#define DELAM_VER_FOREIGN_H

#include <stddef.h>

#include "sweep.h"

#define VER_TABLE_MAXCOL 16
#define VER_TABLE_MAXBYTES (256 << 20) /* a larger CSV file is refused (2 M rows of delam's load.csv: 97 MB) */

/* Numeric columns of a CSV file, picked by header name. */
typedef struct {
  long n;                          /* data rows                              */
  double *col[VER_TABLE_MAXCOL];   /* the wanted columns (NULL: not in file) */
} ver_table;

/* Reads path: leading '#' lines and blank lines are skipped, the first other line is
 * the header; the columns names[0..nname-1] (nname <= VER_TABLE_MAXCOL), of which the
 * first nreq must be there, are read from every row, each field a finite number.  A
 * leading UTF-8 byte-order mark is skipped; UTF-16 text is refused, named.
 * Returns 0; 1 if the file does not exist; 2 with "file:line:column: what" (or
 * "file:line: ...") in err.  At least 3 data rows. */
int ver_table_read(const char *path, const char *const *names, int nname, int nreq, ver_table *t, char *err,
                   size_t errlen);
void ver_table_free(ver_table *t);

/* Fills c's measured numbers from a load table (delta, P_grip, P_fixed or NULL), an
 * energy table (W_ext, KE, SE, W_coh, D, then the ledger L_bc, L_flip, L_scheme,
 * W_head, L_contact, L_debris, L_damp, each NULL if absent; or en NULL) and a particle table (x0, y0, lambda; or pt
 * NULL).  c->vs and c->ana (have_ana) must be set.  Without en the external work is the
 * area under the load curve and D, the energy residual are NaN; without pt the band
 * numbers are NaN. */
void ver_foreign_measure(ver_case *c, const ver_table *ld, const ver_table *en, const ver_table *pt);

/* The load test of separation on rows at any spacing: the first delta, after the peak of
 * P, at which the means of P and Pf over the window (delta - span, delta] (each row's load
 * standing for its interval since the row before) both fall below frac x the peak; the
 * window's centre is returned (as separation.h's test on delam's evenly spaced rows, a
 * window of span / spacing rows).  NaN if they never do.  Linear in the rows. */
double ver_sep_window(const double *d, const double *P, const double *Pf, size_t n, double span, double frac);

/* The first row i (0-based) where d[i] < d[i - 1], or -1: a delta that goes back. */
long ver_foreign_backstep(const double *d, long n);

/* How far energy.csv's W_ext (W, m rows, times et or NULL) is from the area under
 * load.csv's P_grip(delta) (d, P, n rows, times lt or NULL) at the same times (at the
 * same rows when a file lacks t): the largest gap over the larger of max |W_ext| and
 * max area, in *rel, the energy.csv data row (1-based) where it is in *row and the
 * area there in *area.
 * 0; 2 with why when the rows cannot be matched: different row counts without t in
 * both, a t that goes back, or files that end at different times. */
int ver_foreign_work(const double *lt, const double *d, const double *P, long n, const double *et, const double *W,
                     long m, double *rel, long *row, double *area, char *why, size_t len);

/* W_ext against the load curve's area: the largest gap allowed, as a fraction of the
 * work (delam's own fig6 runs: 0.0013, the trapezoid over output rows against the
 * work summed every step). */
#define VER_WORK_AGREE 0.01

#endif
