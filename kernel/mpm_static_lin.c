/*
 * mpm_static_lin.c - the quasi-static solver's linear algebra: the tangent over the free
 * degrees of freedom, assembled into a compressed-column matrix, and its LU with partial
 * pivoting (the tangent is unsymmetric and indefinite once the bar softens).  Two
 * factorizations, chosen by the pattern's bandwidth p (unknowns numbered node by node
 * along the grid's columns): GSL's banded LU where p <= MPM_LIN_BAND_MAX, UMFPACK
 * (SuiteSparse) beyond, with its fill-reducing ordering computed once per run.  Their
 * times: docs/static.md.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>
#include <suitesparse/umfpack.h>

#include "mpm_kernel.h"
#include "mpm_static.h"

#define MPM_LIN_BAND_MAX 160 /* bands up to this many unknowns either side of the diagonal */
#define MPM_LIN_SING 1e-12   /* a least pivot below this share of the largest: singular to rounding */

struct mpm_lin {
  int n;
  int *Ap, *Ai;
  double *Ax;
  size_t p;                /* bandwidth: the largest |row - column| of the pattern      */
  gsl_matrix *AB;          /* banded: n x (3 p + 1), GSL's layout (NULL: UMFPACK)         */
  gsl_vector_uint *piv;
  void *sym, *num;         /* UMFPACK's; num is also "factors held" for the band          */
  double ctl[UMFPACK_CONTROL], info[UMFPACK_INFO];
};

void mpm_lin_free(mpm_lin *l)
{
  if (!l)
    return;
  if (l->num && !l->AB)
    umfpack_di_free_numeric(&l->num);
  if (l->sym)
    umfpack_di_free_symbolic(&l->sym);
  gsl_matrix_free(l->AB);
  gsl_vector_uint_free(l->piv);
  free(l->Ap);
  free(l->Ai);
  free(l->Ax);
  free(l);
}

mpm_lin *mpm_lin_alloc(int n, size_t nz, const int *ti, const int *tj, int *map)
{
  mpm_lin *l = calloc(1, sizeof *l);
  if (!l)
    return NULL;
  l->n = n;
  umfpack_di_defaults(l->ctl);
  /* the pattern is symmetric (a stiffness): order A + A' and prefer the diagonal */
  l->ctl[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
  l->Ap = malloc(sizeof(int) * ((size_t)n + 1));
  l->Ai = malloc(sizeof(int) * (nz ? nz : 1));
  if (!l->Ap || !l->Ai || umfpack_di_triplet_to_col(n, n, (int)nz, ti, tj, NULL, l->Ap, l->Ai, NULL, map) != UMFPACK_OK) {
    mpm_lin_free(l);
    return NULL;
  }
  const size_t nnz = (size_t)l->Ap[n];
  l->Ax = calloc(nnz ? nnz : 1, sizeof(double));
  if (!l->Ax) {
    mpm_lin_free(l);
    return NULL;
  }
  for (size_t k = 0; k < nz; k++) {
    const size_t d = (size_t)abs(ti[k] - tj[k]);
    l->p = d > l->p ? d : l->p;
  }
  if (n > 0 && l->p <= MPM_LIN_BAND_MAX && l->p < (size_t)n) {
    l->AB = gsl_matrix_alloc((size_t)n, 3 * l->p + 1);
    l->piv = gsl_vector_uint_alloc((size_t)n);
    if (!l->AB || !l->piv) {
      mpm_lin_free(l);
      return NULL;
    }
  } else if (umfpack_di_symbolic(n, n, l->Ap, l->Ai, NULL, &l->sym, l->ctl, l->info) != UMFPACK_OK) {
    mpm_lin_free(l);
    return NULL;
  }
  return l;
}

double *mpm_lin_values(mpm_lin *l)
{
  return l->Ax;
}

size_t mpm_lin_nnz(const mpm_lin *l)
{
  return (size_t)l->Ap[l->n];
}

/* GSL's band layout: A(i, j) at AB(j, 2 p + i - j), columns 0 to p - 1 the LU's fill */
static mpm_status factor_band(mpm_lin *l)
{
  const size_t p = l->p;
  gsl_matrix_set_zero(l->AB);
  for (int j = 0; j < l->n; j++)
    for (int k = l->Ap[j]; k < l->Ap[j + 1]; k++)
      gsl_matrix_set(l->AB, (size_t)j, 2 * p + (size_t)l->Ai[k] - (size_t)j, l->Ax[k]);
  /* (its dimensions are right by construction: GSL reports nothing else; a zero pivot
   * shows in U's diagonal) */
  gsl_linalg_LU_band_decomp((size_t)l->n, p, p, l->AB, l->piv);
  for (int j = 0; j < l->n; j++) { /* a zero pivot: singular */
    const double u = gsl_matrix_get(l->AB, (size_t)j, 2 * p);
    if (!(u != 0.0) || u != u)
      return MPM_ENOTFINITE;
  }
  l->num = l; /* factors held */
  return MPM_OK;
}

mpm_status mpm_lin_factor(mpm_lin *l)
{
  if (l->AB) {
    l->num = NULL;
    return factor_band(l);
  }
  if (l->num)
    umfpack_di_free_numeric(&l->num);
  const int st = umfpack_di_numeric(l->Ap, l->Ai, l->Ax, l->sym, &l->num, l->ctl, l->info);
  if (st == UMFPACK_ERROR_out_of_memory)
    return MPM_ENOMEM;
  if (st != UMFPACK_OK) { /* singular (a warning with factors) or not finite */
    if (l->num)
      umfpack_di_free_numeric(&l->num);
    return MPM_ENOTFINITE;
  }
  return MPM_OK;
}

mpm_status mpm_lin_solve(mpm_lin *l, const double *b, double *x)
{
  if (!l->num)
    return MPM_ENOTFINITE;
  if (l->AB) {
    gsl_vector_const_view bv = gsl_vector_const_view_array(b, (size_t)l->n);
    gsl_vector_view xv = gsl_vector_view_array(x, (size_t)l->n);
    gsl_linalg_LU_band_solve(l->p, l->p, l->AB, l->piv, &bv.vector, &xv.vector);
    return MPM_OK;
  }
  const int st = umfpack_di_solve(UMFPACK_A, l->Ap, l->Ai, l->Ax, x, b, l->num, l->ctl, l->info);
  return st == UMFPACK_OK ? MPM_OK : MPM_ENOTFINITE;
}

/* The sign of the last factorization's determinant (LU with partial pivoting: det =
 * (-1)^(row exchanges) times the product of U's diagonal; UMFPACK computes it from its
 * factors with their scaling); 0 where no factors are held or the matrix is singular to
 * rounding, its least pivot below MPM_LIN_SING of the largest (UMFPACK's rcond is that
 * ratio): there the sign is rounding's (one quadrature point a cell, whose hourglass
 * modes leave pivots of 1e-16 of the largest; the interface's stiff ties 1e-5).  The
 * count of U's negative pivots is not the matrix's inertia once rows are exchanged, so
 * only the sign is given. */
int mpm_lin_det_sign(const mpm_lin *l)
{
  if (!l->num)
    return 0;
  if (!l->AB) {
    double mx = 0.0, ex = 0.0;
    if (!(l->info[UMFPACK_RCOND] >= MPM_LIN_SING) || umfpack_di_get_determinant(&mx, &ex, l->num, NULL) != UMFPACK_OK)
      return 0;
    return (mx > 0.0) - (mx < 0.0);
  }
  int s = 1;
  double umin = INFINITY, umax = 0.0;
  for (int j = 0; j < l->n; j++) {
    const double u = gsl_matrix_get(l->AB, (size_t)j, 2 * l->p);
    umin = fmin(umin, fabs(u));
    umax = fmax(umax, fabs(u));
    if (u < 0.0)
      s = -s;
    if (gsl_vector_uint_get(l->piv, (size_t)j) != (unsigned)j)
      s = -s;
  }
  return umin >= MPM_LIN_SING * umax ? s : 0;
}
