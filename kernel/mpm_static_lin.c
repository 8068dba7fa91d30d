/*
 * mpm_static_lin.c - the quasi-static solver's linear algebra: the tangent over the free
 * degrees of freedom as a compressed-column matrix, factorized by UMFPACK (SuiteSparse).
 *
 * Why UMFPACK: the tangent is unsymmetric (the associated law's flow direction frozen at
 * the trial state) and indefinite once a band softens, so Cholesky will not do; its
 * pattern is fixed for the run, so the fill-reducing ordering is computed once and each
 * Newton iteration pays for the numerical LU only.
 */
#include <stdlib.h>
#include <string.h>

#include <suitesparse/umfpack.h>

#include "mpm_kernel.h"
#include "mpm_static.h"

struct mpm_lin {
  int n;
  int *Ap, *Ai;
  double *Ax;
  void *sym, *num;
  double ctl[UMFPACK_CONTROL], info[UMFPACK_INFO];
};

void mpm_lin_free(mpm_lin *l)
{
  if (!l)
    return;
  if (l->num)
    umfpack_di_free_numeric(&l->num);
  if (l->sym)
    umfpack_di_free_symbolic(&l->sym);
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
  if (!l->Ax || umfpack_di_symbolic(n, n, l->Ap, l->Ai, NULL, &l->sym, l->ctl, l->info) != UMFPACK_OK) {
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

mpm_status mpm_lin_factor(mpm_lin *l)
{
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
  const int st = umfpack_di_solve(UMFPACK_A, l->Ap, l->Ai, l->Ax, x, b, l->num, l->ctl, l->info);
  return st == UMFPACK_OK ? MPM_OK : MPM_ENOTFINITE;
}
