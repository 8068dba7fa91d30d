/*
 * mpm_static_lin.c - the quasi-static solver's linear algebra: the tangent over the free
 * degrees of freedom in compressed columns, and its LU with partial pivoting (the tangent
 * is unsymmetric and indefinite once the bar softens).  Two factorizations, chosen once
 * per pattern by their cost (docs/static.md): GSL's banded LU (2 n p^2 flops, bandwidth p;
 * any band under MPM_LIN_BAND_SMALL flops, as KLU's other rounding sends a45 at h 8,
 * 1 ppc off its path), or KLU (SuiteSparse) on AMD's ordering of A + A' computed once per
 * pattern, refactorized on the same pivot order and redone with pivoting when the pivots
 * grow (MPM_LIN_RGROWTH).  The determinant's sign: mpm_lin_det_sign.
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
#define MPM_LIN_SING 1e-12    /* a least pivot below this share of the largest: singular to rounding */
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
  double *Axf;             /* the values it factorized (mpm_lin_same)                     */
  unsigned char *seen;     /* n: a permutation's cycles (mpm_lin_det_sign)                */
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
  free(l->Axf);
  free(l->seen);
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
  l->Axf = calloc(nnz ? nnz : 1, sizeof(double));
  l->seen = malloc((size_t)n + 1);
  if (!l->Ax || !l->Axf || !l->seen) {
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
  const mpm_status st = l->AB ? factor_band(l) : factor_klu(l);
  l->held = st == MPM_OK && (l->AB || l->held);
  if (l->held)
    memcpy(l->Axf, l->Ax, sizeof(double) * mpm_lin_nnz(l));
  return st;
}

int mpm_lin_same(const mpm_lin *l)
{
  return l->held && memcmp(l->Axf, l->Ax, sizeof(double) * mpm_lin_nnz(l)) == 0;
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

/* The sign of a permutation of 0 .. n-1 given as p (its cycles' parities); seen: n bytes
 * of scratch. */
static int perm_sign(const int *p, int n, unsigned char *seen)
{
  int s = 1;
  if (n <= 0)
    return s;
  memset(seen, 0, (size_t)n);
  for (int i = 0; i < n; i++) {
    if (seen[i])
      continue;
    int len = 0;
    for (int j = i; !seen[j]; j = p[j], len++)
      seen[j] = 1;
    if (len % 2 == 0)
      s = -s;
  }
  return s;
}

/* The sign of the last factors' determinant: LU with partial pivoting gives det = the
 * permutations' signs times the product of U's diagonal; 0 where none are held or the
 * matrix is singular to rounding, its least pivot below MPM_LIN_SING of the largest
 * (one quadrature point a cell's hourglass modes leave 1e-16; the interface's stiff ties
 * 1e-5): there the sign is rounding's.  U's negative pivots are not the matrix's inertia
 * once rows are exchanged, so only the sign is given. */
int mpm_lin_det_sign(const mpm_lin *l)
{
  if (!l->held)
    return 0;
  int s = 1;
  double umin = INFINITY, umax = 0.0;
  for (int j = 0; j < l->n; j++) {
    /* band: P A = L U, GSL's row swaps and U's diagonal; KLU, one block: P R^-1 A Q = L U
     * with R's scale factors positive and L's diagonal 1 */
    const double u = l->AB ? gsl_matrix_get(l->AB, (size_t)j, 2 * l->p) : ((const double *)l->kn->Udiag)[j];
    if (l->AB && gsl_vector_uint_get(l->piv, (size_t)j) != (unsigned)j)
      s = -s;
    s = u < 0.0 ? -s : s;
    umin = fmin(umin, fabs(u));
    umax = fmax(umax, fabs(u));
  }
  if (!l->AB)
    s *= perm_sign(l->kn->Pnum, l->n, l->seen) * perm_sign(l->ks->Q, l->n, l->seen);
  return umin >= MPM_LIN_SING * umax ? s : 0;
}
