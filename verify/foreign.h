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
#define VER_TABLE_MAXBYTES (64 << 20) /* a larger CSV file is refused */

/* Numeric columns of a CSV file, picked by header name. */
typedef struct {
  long n;                          /* data rows                              */
  double *col[VER_TABLE_MAXCOL];   /* the wanted columns (NULL: not in file) */
} ver_table;

/* Reads path: leading '#' lines and blank lines are skipped, the first other line is
 * the header; the columns names[0..nname-1] (nname <= VER_TABLE_MAXCOL), of which the
 * first nreq must be there, are read from every row, each field a finite number.
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

#endif
