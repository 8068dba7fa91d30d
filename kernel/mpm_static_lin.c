/*
 * mpm_static_lin.c - the quasi-static solver's linear algebra: the tangent (unsymmetric,
 * indefinite once the bar softens) in compressed columns and its LU with partial
 * pivoting, chosen once per pattern by cost (docs/static.md): GSL's banded LU (2 n p^2
 * flops; any band under MPM_LIN_BAND_SMALL flops) or KLU on AMD's ordering, refactorized
 * on its pivot order while the pivots hold (MPM_LIN_RGROWTH).  Where a factorization
 * costs more than MPM_LIN_LR_MIN flops, the factors of a base A0 (the first, elastic,
 * tangent) are kept and A = A0 + E D E' solved by the Sherman-Morrison-Woodbury identity,
 * E the unknowns S of the entries that differ from A0 (particles and segments off the
 * elastic path): a dense LU of I + D Z_SS, Z = A0^-1 E, and a refinement on A, in place
 * of a sparse LU.  Where that costs more, A is factorized on its own, and after
 * MPM_LIN_LR_ADOPT such with few changes between them A becomes the base (a crack's
 * separated segments).  The determinant's sign: mpm_lin_det_sign.
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
#define MPM_LIN_LR_MIN 1e7  /* flops: factorizations cheaper than this are redone each time   */
#define MPM_LIN_LR_CAP 384  /* the most columns of A0^-1 held (and unknowns in S)             */
#define MPM_LIN_LR_ADOPT 3  /* factorizations on their own in a row that make a new base      */
#define MPM_LIN_LR_PIVOT 1e-9 /* a base whose least pivot is below this share of the largest
                                  takes no update (one particle a cell's hourglass modes:
                                  2e-15 on the DCB at h 2; stiff ties at 4 ppc: 2e-6)     */
#define MPM_LIN_RFALL 1e-6  /* a corrected solve refined no closer than this to b: A on its own */
#define MPM_LIN_REFINE 4    /* refinements of a corrected solve, at most                      */
#define MPM_LIN_RTOL 1e-10  /* ... until its residual is this share of the right-hand side's  */

/* One LU: GSL's band or KLU's numeric factors (the ordering is the mpm_lin's). */
typedef struct {
  gsl_matrix *AB;          /* banded: n x (3 p + 1), GSL's layout (NULL: KLU)             */
  gsl_vector_uint *piv;
  klu_numeric *kn;
} lin_lu;

struct mpm_lin {
  int n;
  int *Ap, *Ai;
  double *Ax;
  size_t p;                /* bandwidth: the largest |row - column| of the pattern      */
  int band;                /* 1: GSL's band LU, 0: KLU                                   */
  klu_common kc;
  klu_symbolic *ks;        /* the ordering (KLU)                                          */
  lin_lu lu[2];            /* [0]: A's or the base's; [1]: A's on its own (low-rank only)  */
  int cur;                 /* the factors the solves use: 0 or 1                         */
  int held;                /* 1: the last factorization succeeded                         */
  double *Axf;             /* the values it factorized (mpm_lin_same)                     */
  unsigned char *seen;     /* n: a permutation's cycles (mpm_lin_det_sign)                */
  /* the low-rank correction (NULL Ab: none, every factorization from scratch) */
  double fflops, sflops;   /* a factorization's and a solve's flops                       */
  double *Ab;              /* the base A0, whose factors are lu[0]                         */
  int based;               /* 1: lu[0] holds A0's factors                                  */
  int lowrank;             /* 1: the solves are A0's corrected on S (cur 0)                */
  int upd;                 /* 1: the last factorization was such a correction              */
  long nfact, nupd;        /* factorizations and corrections since mpm_lin_counts last read */
  int fails;               /* factorizations on their own in a row                         */
  int bsign;               /* the sign of det A0 (0: singular to rounding)                 */
  int bpoor;               /* 1: A0's pivots spread past MPM_LIN_LR_PIVOT: no update on it   */
  int nbase;               /* bases factorized                                              */
  int lroff;               /* 1: the first base was poor: no update for this pattern, the
                              factorization its cost chose (band0) every time            */
  int band0;               /* the band by the factorization's cost (before the update's KLU) */
  int nz, cap;             /* columns of A0^-1 held, and the most it may hold              */
  int *zu, *zof;           /* each column's unknown; each unknown's column or -1            */
  double *Z;               /* n x cap, column-major: A0^-1 e_u for the unknowns zu         */
  int ns;                  /* |S|: the unknowns of the entries that differ from A0 now     */
  int *sidx, *spos;        /* S's unknowns in order (n); each unknown's place in S or -1   */
  gsl_matrix *M;           /* cap x cap: I + D Z_SS's LU in its leading ns x ns            */
  size_t *mperm;           /* its row exchanges                                            */
  int msign;               /* the sign of det (I + D Z_SS)                                  */
  double *w;               /* cap: scratch                                                 */
  double *r, *dx;          /* n: a refinement's residual and step                          */
  size_t nchg;             /* the entries that differ from A0: their unknowns and A - A0   */
  int *ci, *cj;
  double *cv;
};

static void lu_free(mpm_lin *l, lin_lu *f)
{
  if (f->kn)
    klu_free_numeric(&f->kn, &l->kc);
  gsl_matrix_free(f->AB);
  gsl_vector_uint_free(f->piv);
  f->AB = NULL;
  f->piv = NULL;
}

void mpm_lin_free(mpm_lin *l)
{
  if (!l)
    return;
  lu_free(l, &l->lu[0]);
  lu_free(l, &l->lu[1]);
  if (l->ks)
    klu_free_symbolic(&l->ks, &l->kc);
  void *f[] = {l->Ap, l->Ai, l->Ax, l->Axf, l->seen, l->Ab, l->zu, l->zof, l->Z, l->sidx, l->spos, l->mperm, l->w, l->r, l->dx, l->ci, l->cj, l->cv};
  for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
    free(f[i]);
  gsl_matrix_free(l->M);
  free(l);
}

static int lu_alloc(mpm_lin *l, lin_lu *f, int band)
{
  if (!band)
    return 1;
  f->AB = gsl_matrix_alloc((size_t)l->n, 3 * l->p + 1);
  f->piv = gsl_vector_uint_alloc((size_t)l->n);
  return f->AB && f->piv;
}

static int lowrank_alloc(mpm_lin *l)
{
  const size_t n = (size_t)l->n, nnz = (size_t)l->Ap[l->n];
  l->cap = l->n < MPM_LIN_LR_CAP ? l->n : MPM_LIN_LR_CAP;
  const size_t cap = (size_t)l->cap;
  l->Ab = malloc(sizeof(double) * nnz);
  l->zu = malloc(sizeof(int) * cap);
  l->zof = malloc(sizeof(int) * n);
  l->Z = malloc(sizeof(double) * n * cap);
  l->sidx = malloc(sizeof(int) * n);
  l->spos = malloc(sizeof(int) * n);
  l->M = gsl_matrix_alloc(cap, cap);
  l->mperm = malloc(sizeof(size_t) * cap);
  l->w = malloc(sizeof(double) * cap);
  l->r = malloc(sizeof(double) * n);
  l->dx = malloc(sizeof(double) * n);
  l->ci = malloc(sizeof(int) * nnz);
  l->cj = malloc(sizeof(int) * nnz);
  l->cv = malloc(sizeof(double) * nnz);
  if (!l->Ab || !l->zu || !l->zof || !l->Z || !l->sidx || !l->spos || !l->M || !l->mperm || !l->w || !l->r || !l->dx || !l->ci || !l->cj ||
      !l->cv || !lu_alloc(l, &l->lu[1], l->band))
    return 0;
  for (size_t i = 0; i < n; i++)
    l->spos[i] = l->zof[i] = -1;
  return 1;
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
  l->band = n > 0 && l->p <= MPM_LIN_BAND_MAX && l->p < (size_t)n &&
            (!l->ks || band <= MPM_LIN_BAND_SMALL || band <= MPM_LIN_BAND_RATE * l->ks->est_flops);
  /* with the low-rank correction the solves outnumber the factorizations: KLU where its
   * factors are the sparser (Fig. 6, h 1, 9 ppc: 1.2e6 entries against the band's 2.6e6,
   * a solve 1.35 ms against 3.5) */
  l->band0 = l->band;
  if (l->band && l->ks && fmin(band, l->ks->est_flops) > MPM_LIN_LR_MIN && l->ks->lnz + l->ks->unz < 3.0 * n * (double)l->p)
    l->band = 0;
  if (l->band && l->ks)
    klu_free_symbolic(&l->ks, &l->kc);
  if ((!l->band && !l->ks) || !lu_alloc(l, &l->lu[0], l->band0)) {
    mpm_lin_free(l);
    return NULL;
  }
  l->fflops = l->band ? band : l->ks->est_flops;
  l->sflops = l->band ? 6.0 * n * (double)l->p : 2.0 * (l->ks->lnz + l->ks->unz);
  if (l->fflops > MPM_LIN_LR_MIN && !lowrank_alloc(l)) {
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
static mpm_status factor_band(mpm_lin *l, lin_lu *f)
{
  const size_t p = l->p;
  gsl_matrix_set_zero(f->AB);
  for (int j = 0; j < l->n; j++)
    for (int k = l->Ap[j]; k < l->Ap[j + 1]; k++)
      gsl_matrix_set(f->AB, (size_t)j, 2 * p + (size_t)l->Ai[k] - (size_t)j, l->Ax[k]);
  /* (its dimensions are right by construction: GSL reports nothing else; a zero pivot
   * shows in U's diagonal) */
  gsl_linalg_LU_band_decomp((size_t)l->n, p, p, f->AB, f->piv);
  for (int j = 0; j < l->n; j++) { /* a zero pivot: singular */
    const double u = gsl_matrix_get(f->AB, (size_t)j, 2 * p);
    if (!(u != 0.0) || u != u)
      return MPM_ENOTFINITE;
  }
  return MPM_OK;
}

/* KLU: the last pivot order's refactorization where it is sound, else with pivoting */
static mpm_status factor_klu(mpm_lin *l, lin_lu *f)
{
  if (f->kn && klu_refactor(l->Ap, l->Ai, l->Ax, l->ks, f->kn, &l->kc) &&
      klu_rgrowth(l->Ap, l->Ai, l->Ax, l->ks, f->kn, &l->kc) && l->kc.rgrowth >= MPM_LIN_RGROWTH)
    return MPM_OK;
  if (f->kn)
    klu_free_numeric(&f->kn, &l->kc);
  f->kn = klu_factor(l->Ap, l->Ai, l->Ax, l->ks, &l->kc);
  if (!f->kn)
    return l->kc.status == KLU_OUT_OF_MEMORY ? MPM_ENOMEM : MPM_ENOTFINITE;
  /* a zero or non-finite pivot: singular (KLU stops at an exact zero only) */
  return l->kc.status == KLU_OK && klu_rcond(l->ks, f->kn, &l->kc) && l->kc.rcond > 0.0 ? MPM_OK : MPM_ENOTFINITE;
}

static mpm_status factor_lu(mpm_lin *l, lin_lu *f)
{
  return l->band ? factor_band(l, f) : factor_klu(l, f);
}

/* x = A^-1 b with the factors f; x and b may not alias. */
static mpm_status solve_lu(mpm_lin *l, lin_lu *f, const double *b, double *x)
{
  if (l->band) {
    gsl_vector_const_view bv = gsl_vector_const_view_array(b, (size_t)l->n);
    gsl_vector_view xv = gsl_vector_view_array(x, (size_t)l->n);
    gsl_linalg_LU_band_solve(l->p, l->p, f->AB, f->piv, &bv.vector, &xv.vector);
    return MPM_OK;
  }
  memcpy(x, b, sizeof(double) * (size_t)l->n);
  return klu_solve(l->ks, f->kn, l->n, 1, x, &l->kc) ? MPM_OK : MPM_ENOTFINITE;
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

/* The sign of the determinant of the factors f: LU with partial pivoting gives det = the
 * permutations' signs times the product of U's diagonal; 0 where the matrix is singular
 * to rounding, its least pivot below MPM_LIN_SING of the largest (one quadrature point a
 * cell's hourglass modes leave 1e-16; the interface's stiff ties 1e-5): there the sign is
 * rounding's.  U's negative pivots are not the matrix's inertia once rows are exchanged,
 * so only the sign is given. */
static int lu_det_sign(const mpm_lin *l, const lin_lu *f, double *ratio)
{
  int s = 1;
  double umin = INFINITY, umax = 0.0;
  for (int j = 0; j < l->n; j++) {
    /* band: P A = L U, GSL's row swaps and U's diagonal; KLU, one block: P R^-1 A Q = L U
     * with R's scale factors positive and L's diagonal 1 */
    const double u = l->band ? gsl_matrix_get(f->AB, (size_t)j, 2 * l->p) : ((const double *)f->kn->Udiag)[j];
    if (l->band && gsl_vector_uint_get(f->piv, (size_t)j) != (unsigned)j)
      s = -s;
    s = u < 0.0 ? -s : s;
    umin = fmin(umin, fabs(u));
    umax = fmax(umax, fabs(u));
  }
  if (!l->band)
    s *= perm_sign(f->kn->Pnum, l->n, l->seen) * perm_sign(l->ks->Q, l->n, l->seen);
  if (ratio)
    *ratio = umin / umax;
  return umin >= MPM_LIN_SING * umax ? s : 0;
}

/* Empties S. */
static void s_clear(mpm_lin *l)
{
  for (int a = 0; a < l->ns; a++)
    l->spos[l->sidx[a]] = -1;
  l->ns = 0;
  l->nchg = 0;
}

/* A's factors as the base A0: no columns of A0^-1 yet, S empty. */
static mpm_status factor_base(mpm_lin *l)
{
  l->based = 0;
  const mpm_status st = factor_lu(l, &l->lu[0]);
  if (st != MPM_OK)
    return st;
  memcpy(l->Ab, l->Ax, sizeof(double) * mpm_lin_nnz(l));
  s_clear(l);
  for (int c = 0; c < l->nz; c++)
    l->zof[l->zu[c]] = -1;
  l->nz = 0;
  l->based = 1;
  double ratio = 0.0;
  l->bsign = lu_det_sign(l, &l->lu[0], &ratio);
  l->bpoor = !(ratio >= MPM_LIN_LR_PIVOT);
  l->msign = 1;
  if (l->nbase++ == 0 && l->bpoor) { /* the elastic tangent itself: the update never pays */
    l->lroff = 1;
    if (l->band0 && !l->band) {
      l->band = 1;
      return factor_lu(l, &l->lu[0]);
    }
  }
  return MPM_OK;
}

/* Makes room for `need` more columns of A0^-1: those of unknowns outside S are dropped
 * (a zone's unknowns that went back to A0's entries).  0 if S's alone do not fit. */
static int z_room(mpm_lin *l, int need)
{
  if (l->nz + need <= l->cap)
    return 1;
  int kept = 0;
  for (int c = 0; c < l->nz; c++) {
    const int u = l->zu[c];
    if (l->spos[u] < 0) {
      l->zof[u] = -1;
      continue;
    }
    if (kept != c)
      memcpy(l->Z + (size_t)l->n * (size_t)kept, l->Z + (size_t)l->n * (size_t)c, sizeof(double) * (size_t)l->n);
    l->zu[kept] = u;
    l->zof[u] = kept++;
  }
  l->nz = kept;
  return l->nz + need <= l->cap;
}

/* The columns of A0^-1 that S's unknowns lack, all at once; 0 if they do not fit. */
static int z_fill(mpm_lin *l)
{
  const int n = l->n;
  int need = 0;
  for (int a = 0; a < l->ns; a++)
    need += l->zof[l->sidx[a]] < 0;
  if (!z_room(l, need))
    return 0;
  const int nz0 = l->nz;
  double *Zn = l->Z + (size_t)n * (size_t)nz0;
  memset(Zn, 0, sizeof(double) * (size_t)n * (size_t)need);
  for (int a = 0; a < l->ns; a++)
    if (l->zof[l->sidx[a]] < 0) {
      Zn[(size_t)n * (size_t)(l->nz - nz0) + (size_t)l->sidx[a]] = 1.0;
      l->zu[l->nz] = l->sidx[a];
      l->zof[l->sidx[a]] = l->nz++;
    }
  if (l->band) {
    for (int c = 0; c < need; c++) {
      gsl_vector_view zv = gsl_vector_view_array(Zn + (size_t)n * (size_t)c, (size_t)n);
      gsl_linalg_LU_band_svx(l->p, l->p, l->lu[0].AB, l->lu[0].piv, &zv.vector);
    }
    return 1;
  }
  return need == 0 || klu_solve(l->ks, l->lu[0].kn, n, need, Zn, &l->kc);
}

/* A = A0 + E D E' (Sherman-Morrison-Woodbury), E the unknowns S of the entries that
 * differ from A0: the columns of A0^-1 that S needs (kept while A0 is: a softening
 * zone's unknowns return each Newton iteration) and the LU of I + D Z_SS.  0 where the
 * correction's recurring flops reach half a factorization's, S or the columns do not
 * fit, or the correction is singular: A is then factorized on its own. */
static int factor_lowrank(mpm_lin *l)
{
  const int n = l->n;
  size_t m = 0;
  s_clear(l);
  for (int j = 0; j < n; j++)
    for (int k = l->Ap[j]; k < l->Ap[j + 1]; k++)
      if (l->Ax[k] != l->Ab[k]) {
        const int i = l->Ai[k];
        if (l->spos[i] < 0) {
          l->spos[i] = l->ns;
          l->sidx[l->ns++] = i;
        }
        if (l->spos[j] < 0) {
          l->spos[j] = l->ns;
          l->sidx[l->ns++] = j;
        }
        if (l->ns > l->cap)
          return 0;
        l->ci[m] = i;
        l->cj[m] = j;
        l->cv[m++] = l->Ax[k] - l->Ab[k];
      }
  l->nchg = m;
  const double ns = l->ns;
  if (2.0 * (double)m * ns + (2.0 / 3.0) * ns * ns * ns + 4.0 * n * ns > 0.5 * l->fflops || !z_fill(l))
    return 0;
  /* M = I + D Z_SS: M(a, b) gains D(a, c) Z(c, b) for each changed entry (a, c) */
  const size_t S = (size_t)l->ns;
  gsl_matrix_view Mv = gsl_matrix_submatrix(l->M, 0, 0, S, S);
  gsl_matrix_set_identity(&Mv.matrix);
  for (size_t b = 0; b < S; b++) {
    const double *z = l->Z + (size_t)n * (size_t)l->zof[l->sidx[b]];
    for (size_t e = 0; e < m; e++)
      *gsl_matrix_ptr(l->M, (size_t)l->spos[l->ci[e]], b) += l->cv[e] * z[l->cj[e]];
  }
  gsl_permutation perm = {S, l->mperm};
  int signum = 1;
  gsl_linalg_LU_decomp(&Mv.matrix, &perm, &signum);
  double umin = INFINITY, umax = 0.0;
  for (size_t a = 0; a < S; a++) {
    const double u = gsl_matrix_get(&Mv.matrix, a, a);
    if (!(u != 0.0) || !isfinite(u))
      return 0;
    signum = u < 0.0 ? -signum : signum;
    umin = fmin(umin, fabs(u));
    umax = fmax(umax, fabs(u));
  }
  l->msign = umin >= MPM_LIN_SING * umax ? signum : 0;
  return 1;
}

/* 1 if A differs from the last factors' values on few unknowns (at most half the
 * columns A0^-1 may hold): changes that stay near a front, where A is a base worth
 * adopting, not iterates that flip particles over the whole body. */
static int settled(mpm_lin *l)
{
  int cnt = 0;
  s_clear(l);
  for (int j = 0; j < l->n && cnt <= l->cap / 2; j++)
    for (int k = l->Ap[j]; k < l->Ap[j + 1]; k++)
      if (l->Ax[k] != l->Axf[k] && l->spos[l->Ai[k]] < 0) {
        l->spos[l->Ai[k]] = l->ns;
        l->sidx[l->ns++] = l->Ai[k];
        cnt++;
      }
  s_clear(l);
  return cnt <= l->cap / 2;
}

mpm_status mpm_lin_factor(mpm_lin *l)
{
  mpm_status st = MPM_OK;
  l->held = 0;
  l->cur = 0;
  l->lowrank = l->upd = 0;
  if (!l->Ab || l->lroff)
    st = factor_lu(l, &l->lu[0]);
  else if (l->based && !l->bpoor && factor_lowrank(l)) {
    l->lowrank = l->upd = 1;
    l->fails = 0;
  } else if (!l->based || l->bpoor || (++l->fails >= MPM_LIN_LR_ADOPT && settled(l))) {
    /* (a poor base is replaced each time: A's own factorization, as without the update) */
    st = factor_base(l);
    l->lowrank = st == MPM_OK && !l->lroff;
    l->fails = 0;
  } else {
    s_clear(l);
    l->cur = 1;
    st = factor_lu(l, &l->lu[1]);
  }
  l->held = st == MPM_OK;
  if (l->held)
    memcpy(l->Axf, l->Ax, sizeof(double) * mpm_lin_nnz(l));
  if (l->upd)
    l->nupd++;
  else
    l->nfact++;
  return st;
}

void mpm_lin_counts(mpm_lin *l, long *fact, long *upd)
{
  *fact += l->nfact;
  *upd += l->nupd;
  l->nfact = l->nupd = 0;
}

int mpm_lin_updated(const mpm_lin *l)
{
  return l->held && l->upd;
}

int mpm_lin_same(const mpm_lin *l)
{
  return l->held && memcmp(l->Axf, l->Ax, sizeof(double) * mpm_lin_nnz(l)) == 0;
}

/* x = A^-1 b by the correction: x = y - Z t, (I + D Z_SS) t = D y_S, y = A0^-1 b. */
static mpm_status solve_lowrank(mpm_lin *l, const double *b, double *x)
{
  const mpm_status st = solve_lu(l, &l->lu[0], b, x);
  if (st != MPM_OK || l->ns == 0)
    return st;
  const size_t S = (size_t)l->ns, n = (size_t)l->n;
  memset(l->w, 0, sizeof(double) * S);
  for (size_t e = 0; e < l->nchg; e++)
    l->w[l->spos[l->ci[e]]] += l->cv[e] * x[l->cj[e]];
  gsl_matrix_view Mv = gsl_matrix_submatrix(l->M, 0, 0, S, S);
  gsl_permutation perm = {S, l->mperm};
  gsl_vector_view wv = gsl_vector_view_array(l->w, S);
  gsl_linalg_LU_svx(&Mv.matrix, &perm, &wv.vector);
  for (size_t a = 0; a < S; a++) {
    const double t = l->w[a], *z = l->Z + n * (size_t)l->zof[l->sidx[a]];
    for (size_t i = 0; i < n; i++)
      x[i] -= t * z[i];
  }
  return MPM_OK;
}

/* r = b - A x; returns max |r| */
static double residual(const mpm_lin *l, const double *b, const double *x, double *r)
{
  memcpy(r, b, sizeof(double) * (size_t)l->n);
  for (int j = 0; j < l->n; j++)
    for (int k = l->Ap[j]; k < l->Ap[j + 1]; k++)
      r[l->Ai[k]] -= l->Ax[k] * x[j];
  double m = 0.0;
  for (int i = 0; i < l->n; i++)
    m = fmax(m, fabs(r[i]));
  return m;
}

mpm_status mpm_lin_solve(mpm_lin *l, const double *b, double *x)
{
  if (!l->held)
    return MPM_ENOTFINITE;
  if (!l->lowrank || l->ns == 0)
    return solve_lu(l, &l->lu[l->cur], b, x);
  mpm_status st = solve_lowrank(l, b, x);
  /* the correction cancels where a stiff tie lets go (D ~ the tie, Z ~ its inverse):
   * refined on A itself while that lowers the residual */
  double bmax = 0.0;
  for (int i = 0; i < l->n; i++)
    bmax = fmax(bmax, fabs(b[i]));
  double r0 = residual(l, b, x, l->r);
  for (int it = 0; st == MPM_OK && it < MPM_LIN_REFINE && r0 > MPM_LIN_RTOL * bmax; it++) {
    if ((st = solve_lowrank(l, l->r, l->dx)) != MPM_OK)
      break;
    for (int i = 0; i < l->n; i++)
      x[i] += l->dx[i];
    const double r1 = residual(l, b, x, l->r);
    if (!(r1 < 0.5 * r0))
      break;
    r0 = r1;
  }
  if (st == MPM_OK && r0 <= MPM_LIN_RFALL * bmax)
    return MPM_OK;
  /* the correction does not converge: A factorized on its own after all (counted as a
   * factorization, not a correction) */
  s_clear(l);
  l->lowrank = l->upd = 0;
  l->nupd--;
  l->nfact++;
  l->cur = 1;
  l->fails++;
  st = factor_lu(l, &l->lu[1]);
  l->held = st == MPM_OK;
  return st == MPM_OK ? solve_lu(l, &l->lu[1], b, x) : st;
}

int mpm_lin_det_sign(const mpm_lin *l)
{
  if (!l->held)
    return 0;
  /* det A = det A0 det (I + D Z_SS) */
  return l->lowrank ? l->bsign * l->msign : lu_det_sign(l, &l->lu[l->cur], NULL);
}
