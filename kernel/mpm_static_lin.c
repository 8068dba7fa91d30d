/*
 * mpm_static_lin.c - the quasi-static solver's linear algebra: the tangent over the free
 * degrees of freedom, assembled into a compressed-column matrix, and its LU with partial
 * pivoting.  The tangent is unsymmetric (the associated law's flow direction frozen at the
 * trial state) and indefinite once the bar softens, so Cholesky will not do.
 *
 * Two factorizations, chosen once per pattern by their cost (docs/static.md):
 *  - GSL's banded LU, 2 n p^2 flops for bandwidth p (the unknowns are numbered node by
 *    node along the grid's columns, so p is about twice a column of nodes): the band of
 *    a bar without a split line (Fig. 6: p 36 at h 2, 4 ppc), and any band of under
 *    MPM_LIN_BAND_SMALL flops (KLU's other rounding sends a45 at h 8, 1 ppc, off its path);
 *  - KLU (SuiteSparse) beyond, on AMD's fill-reducing ordering of A + A' computed once per
 *    pattern (KLU's estimate of its flops decides), its first factorization with partial
 *    pivoting and the next ones on the same pivot order (klu_refactor: no search, no
 *    allocation), redone with pivoting when the pivots grow (MPM_LIN_RGROWTH) or one is
 *    zero.  A split line's second slots widen the band to p 83 at h 2, where KLU's
 *    flops are a fifth of the band's (a30).
 * The sign of the determinant of the last factors: mpm_lin_det_sign.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>
#include <suitesparse/klu.h>
#include <suitesparse/umfpack.h>

#include "mpm_kernel.h"
#include "mpm_static.h"

#define MPM_LIN_BAND_MAX 160 /* bands up to this many unknowns either side of the diagonal */
#define MPM_LIN_BAND_RATE 1.5 /* measured: a band flop costs 1 / 1.5 of a KLU flop here (Fig. 6,
                                 h 1, 9 ppc: band 1.2e8 and KLU 9.1e7 flops, the same time) */
#define MPM_LIN_BAND_SMALL 1e7 /* flops: a band this cheap (a few ms) is kept whatever KLU's cost,
                                   the factorization of the bar scenes at h 8 and 4 unchanged   */
#define MPM_LIN_RGROWTH 1e-6 /* a refactorization whose reciprocal pivot growth is below this
                                is redone with pivoting                                       */

struct mpm_lin {
  int n;
  int *Ap, *Ai;
  double *Ax;
  size_t p;                /* bandwidth: the largest |row - column| of the pattern      */
  gsl_matrix *AB;          /* banded: n x (3 p + 1), GSL's layout (NULL: KLU)             */
  gsl_vector_uint *piv;
  klu_common kc;
  klu_symbolic *ks;        /* the ordering (KLU)                                          */
  klu_numeric *kn;         /* the factors (KLU)                                           */
  int held;                /* 1: the last factorization succeeded                         */
};

void mpm_lin_free(mpm_lin *l)
{
  if (!l)
    return;
  if (l->kn)
    klu_free_numeric(&l->kn, &l->kc);
  if (l->ks)
    klu_free_symbolic(&l->ks, &l->kc);
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
  klu_defaults(&l->kc);
  l->kc.btf = 0; /* one block: the tangent of a connected body is irreducible */
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
  l->ks = n > 0 ? klu_analyze(n, l->Ap, l->Ai, &l->kc) : NULL;
  const double band = 2.0 * n * (double)l->p * (double)l->p;
  if (n > 0 && l->p <= MPM_LIN_BAND_MAX && l->p < (size_t)n &&
      (!l->ks || band <= MPM_LIN_BAND_SMALL || band <= MPM_LIN_BAND_RATE * l->ks->est_flops)) {
    if (l->ks)
      klu_free_symbolic(&l->ks, &l->kc);
    l->AB = gsl_matrix_alloc((size_t)n, 3 * l->p + 1);
    l->piv = gsl_vector_uint_alloc((size_t)n);
    if (!l->AB || !l->piv) {
      mpm_lin_free(l);
      return NULL;
    }
  } else if (!l->ks) {
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
  return MPM_OK;
}

/* KLU: the last pivot order's refactorization where it is sound, else with pivoting */
static mpm_status factor_klu(mpm_lin *l)
{
  if (l->kn && klu_refactor(l->Ap, l->Ai, l->Ax, l->ks, l->kn, &l->kc) &&
      klu_rgrowth(l->Ap, l->Ai, l->Ax, l->ks, l->kn, &l->kc) && l->kc.rgrowth >= MPM_LIN_RGROWTH) {
    l->held = 1;
    return MPM_OK;
  }
  if (l->kn)
    klu_free_numeric(&l->kn, &l->kc);
  l->kn = klu_factor(l->Ap, l->Ai, l->Ax, l->ks, &l->kc);
  if (!l->kn)
    return l->kc.status == KLU_OUT_OF_MEMORY ? MPM_ENOMEM : MPM_ENOTFINITE;
  /* a zero or non-finite pivot: singular (KLU stops at an exact zero only) */
  l->held = l->kc.status == KLU_OK && klu_rcond(l->ks, l->kn, &l->kc) && l->kc.rcond > 0.0;
  return l->held ? MPM_OK : MPM_ENOTFINITE;
}

mpm_status mpm_lin_factor(mpm_lin *l)
{
  l->held = 0;
  if (!l->AB)
    return factor_klu(l);
  const mpm_status st = factor_band(l);
  l->held = st == MPM_OK;
  return st;
}

mpm_status mpm_lin_solve(mpm_lin *l, const double *b, double *x)
{
  if (!l->held)
    return MPM_ENOTFINITE;
  if (l->AB) {
    gsl_vector_const_view bv = gsl_vector_const_view_array(b, (size_t)l->n);
    gsl_vector_view xv = gsl_vector_view_array(x, (size_t)l->n);
    gsl_linalg_LU_band_solve(l->p, l->p, l->AB, l->piv, &bv.vector, &xv.vector);
    return MPM_OK;
  }
  memcpy(x, b, sizeof(double) * (size_t)l->n);
  return klu_solve(l->ks, l->kn, l->n, 1, x, &l->kc) ? MPM_OK : MPM_ENOTFINITE;
}

/* The sign of a permutation of 0 .. n-1 given as p (its cycles' parities); 0 on bad memory. */
static int perm_sign(const int *p, int n)
{
  unsigned char *seen = calloc((size_t)n + 1, 1);
  if (!seen)
    return 0;
  int s = 1;
  for (int i = 0; i < n; i++) {
    if (seen[i])
      continue;
    int len = 0;
    for (int j = i; !seen[j]; j = p[j], len++)
      seen[j] = 1;
    if (len % 2 == 0)
      s = -s;
  }
  free(seen);
  return s;
}

int mpm_lin_det_sign(const mpm_lin *l)
{
  if (!l->held)
    return 0;
  int s = 1;
  if (l->AB) { /* P A = L U: GSL's row swaps, then U's diagonal */
    for (int j = 0; j < l->n; j++) {
      s = gsl_vector_uint_get(l->piv, (size_t)j) != (unsigned)j ? -s : s;
      s = gsl_matrix_get(l->AB, (size_t)j, 2 * l->p) < 0.0 ? -s : s;
    }
    return s;
  }
  /* KLU, one block: P R^-1 A Q = L U with R's scale factors positive, L unit diagonal */
  const double *u = l->kn->Udiag;
  for (int j = 0; j < l->n; j++)
    s = u[j] < 0.0 ? -s : s;
  return s * perm_sign(l->kn->Pnum, l->n) * perm_sign(l->ks->Q, l->n);
}
