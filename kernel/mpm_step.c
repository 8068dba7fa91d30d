/*
 * mpm_step.c - one explicit MPM step as a list of named phases (mpm_phase.h): start,
 * scatter, the scheme's phase before the node update, node update (mpm_nodes.c), the
 * scheme's gather, end (head, ledger).  Scheme and hooks are chosen once
 * (mpm_step_setup).  The paper's USL (sec. 2):
 *
 *   p2g   m_i, (m v)_i, f_i = -sum_p V_p sigma_p . G_ip            eqs. 2, 3
 *   grid  v_i = (m v)_i / m_i,  v^L_i = v_i + dt f_i / m_i; BCs      eq. 4
 *   g2p   x_p += dt sum v^L_i N_ip,  v_p += sum (v^L_i - v_i) N_ip    eqs. 5, 6
 *         de_p = dt sym(sum v^L_i (x) G_ip), then the decohesion update  eq. 7
 *
 * N and G at the step's start; the ledger's terms: docs/verification.md.  Scatters run by
 * strips (mpm_sort.c), gathers per particle (the elastic trial eight at a time, those that
 * may soften updated after the chunk): the same bits for any thread count.
 */
#include <assert.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "mpm_fields.h"
#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_specimen.h"
#include "mpm_gimp.h"
#include "mpm_node.h"
#include "mpm_nodes.h"
#include "mpm_phase.h"
#include "mpm_scatter.h"
#include "mpm_shape.h"

static int thread_id(void)
{
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

/* Names the first particle whose state is not finite; 0 if there is none. */
static int name_nonfinite(const mpm_sim *s, char *err, size_t errlen)
{
  const mpm_particles *p = s->p;
  const char *names[] = {"x", "y", "vx", "vy", "sxx", "syy", "sxy", "lambda"};
  for (size_t k = 0; k < p->n; k++) {
    const double v[] = {p->x[k], p->y[k], p->vx[k], p->vy[k], p->sxx[k], p->syy[k], p->sxy[k], p->lam[k]};
    for (int f = 0; f < 8; f++)
      if (!isfinite(v[f])) {
        snprintf(err, errlen, "step %ld: particle at X = %g, Y = %g: %s is not finite", s->step, p->x0[k],
                 p->y0[k], names[f]);
        return 1;
      }
  }
  return 0;
}


struct g2p_acc {
  long soften, separate, bracketed;
  double tconst;   /* seconds in the full constitutive update */
  int bad;         /* the update returned non-finite */
  int resort;      /* a particle drifted out of its strip's safe range */
  size_t bad_k;
};

/* fmin(x, 1) without the library call (NaN gives 1 as fmin does) */
static inline double min1(double x)
{
  return x < 1.0 ? x : 1.0;
}

/* The softening step of the particles in d's list in one batch (mpm_dcoh_soften_batch)
 * when they share one material with q = 1; 1 if it ran (d's bok says which took it). */
static int flush_batch(const mpm_sim *s, const mpm_particles *p, mpm_defer *d)
{
  const uint8_t mi = p->mat[d->k[0]];
  const mpm_material *m = &s->mat[mi];
  if (m->model == MPM_DCOH_NONE || m->q != 1.0)
    return 0;
  for (size_t i = 0; i < d->n; i++) {
    const size_t k = d->k[i];
    if (p->mat[k] != mi)
      return 0;
    d->bst[0][i] = p->sxx[k];
    d->bst[1][i] = p->syy[k];
    d->bst[2][i] = p->sxy[k];
    d->bst[3][i] = p->lam[k];
    d->bst[4][i] = p->upn[k];
    d->bst[5][i] = p->upt[k];
    d->bsep[i] = p->sep[k];
    for (int c = 0; c < 3; c++)
      d->bde[c][i] = d->de[i][c];
  }
  double *const st[6] = {d->bst[0], d->bst[1], d->bst[2], d->bst[3], d->bst[4], d->bst[5]};
  const double *const de[3] = {d->bde[0], d->bde[1], d->bde[2]};
  mpm_dcoh_soften_batch(m, d->n, st, d->bsep, de, d->bw, d->bok);
  return 1;
}

/* The full decohesion update (sec. 4) of the particles in the thread's list, in list
 * order, off the hot loop; one timing per batch.  Returns the ledger's
 * sum m sigma_new : deps over them (ledger_step). */
static inline __attribute__((always_inline)) double flush_impl(const mpm_sim *s, int q, mpm_particles *restrict p,
                                                                mpm_defer *d, mpm_dwork *dw, g2p_acc *acc,
                                                                const int rows)
{
  if (d->n == 0)
    return 0.0;
  const double t0 = mpm_wall();
  double qs = 0.0;
  const int bat = !rows && flush_batch(s, p, d);
  double led_d = s->led_part[q][MPM_LED_D]; /* summed in a register, in the same order */
  long soften = 0, separate = 0, bracketed = 0;
  for (size_t i = 0; i < d->n; i++) {
    const size_t k = d->k[i];
    const mpm_material *m = &s->mat[p->mat[k]];
    mpm_band *b = s->band;
    mpm_material mrow;
    int j = 0;
    if (rows && m->model != MPM_DCOH_NONE && !p->sep[k]) { /* Le = row: this row's measured length */
      j = mpm_band_row(b, p->y0[k]);
      mrow = *m;
      mrow.Le = mpm_band_le(b, j);
      mrow.kL = mrow.ubar0 / mrow.Le;
      m = &mrow;
    }
    const mpm_dstate in = {p->sxx[k], p->syy[k], p->sxy[k], p->lam[k], p->upn[k], p->upt[k], p->sep[k]};
    mpm_dstate o;
    mpm_dinfo info;
    if (bat && d->bok[i]) { /* softened in the batch */
      o = (mpm_dstate){d->bst[0][i], d->bst[1][i], d->bst[2][i], d->bst[3][i], d->bst[4][i], d->bst[5][i], 0};
      info = (mpm_dinfo){MPM_DPATH_SOFTEN, 1, 0, d->bw[i]};
    } else if (mpm_dcoh_update(m, &in, d->de[i], &o, &info, dw) != MPM_OK && (!acc->bad || k < acc->bad_k)) {
      acc->bad = 1;
      acc->bad_k = k;
    }
    const double *de = d->de[i];
    qs += p->m[k] * (o.sxx * de[0] + o.syy * de[1] + o.sxy * (2.0 * de[2]));
    p->sxx[k] = o.sxx;
    p->syy[k] = o.syy;
    p->sxy[k] = o.sxy;
    p->lam[k] = o.lam;
    p->upn[k] = o.upn;
    p->upt[k] = o.upt;
    p->sep[k] = (uint8_t)o.sep;
    /* the batch's particles: q = 1, not separated; (1 - lambda)^2 as mpm_dcoh_str2 has it */
    p->str2[k] = bat && d->bok[i] ? (1.0 - o.lam) * (1.0 - o.lam) : mpm_dcoh_str2(m, o.lam, o.sep);
    /* the decohesion strain is d ud / Le while softening, d ud / Lopen once separating */
    p->wcoh[k] += info.w * p->V[k] / (info.path == MPM_DPATH_SOFTEN ? m->Le : m->Lopen);
    const double dl = min1(o.lam) - min1(in.lam);
    double dd = 0.0;
    if (!rows) {
      dd = m->U0 * dl * p->V[k] / m->Le;
    } else if (m == &mrow) {
      /* Le = row: a particle's dissipation ends where it separates, the rest of its
       * 1 - lambda charged at the row's Le then */
      dd = m->U0 * (info.path == MPM_DPATH_SEPARATE ? 1.0 - min1(in.lam) : dl) * p->V[k] / m->Le;
      double *a = b->acc + 3 * ((size_t)q * (size_t)b->nrow + (size_t)j);
      if (info.path == MPM_DPATH_SOFTEN &&
          (b->reach <= 0.0 || !(b->lam[j] > 0.0) || fabs(p->x0[k] - b->xl[j]) <= b->reach))
        a[0] += dl;
      const double lv = o.sep ? 1.0 : min1(o.lam); /* a separated particle: the row's crack is through */
      if (lv > a[1]) {
        a[1] = lv;
        a[2] = p->x0[k];
      }
    }
    p->dis[k] += dd;
    led_d += dd;
    soften += info.path == MPM_DPATH_SOFTEN;
    separate += info.path == MPM_DPATH_SEPARATE;
    bracketed += info.bracketed;
  }
  s->led_part[q][MPM_LED_D] = led_d;
  acc->soften += soften;
  acc->separate += separate;
  acc->bracketed += bracketed;
  d->n = 0;
  acc->tconst += mpm_wall() - t0;
  return qs;
}

/* decohesion.Le = row (mpm_band.c) or any other Le: chosen once (mpm_step_setup). */
static __attribute__((noinline)) double flush_plain(const mpm_sim *s, int q, mpm_particles *p, mpm_defer *d,
                                                     mpm_dwork *dw, g2p_acc *acc)
{
  return flush_impl(s, q, p, d, dw, acc, 0);
}

static __attribute__((noinline)) double flush_rows(const mpm_sim *s, int q, mpm_particles *p, mpm_defer *d,
                                                    mpm_dwork *dw, g2p_acc *acc)
{
  return flush_impl(s, q, p, d, dw, acc, 1);
}

/* What a gather pass does (g2p_strip_impl): move the particles (eq. 5), update their
 * velocities (eq. 6), and take a strain increment (eq. 7) from lanes (px, py) or
 * (fx, fy), then the constitutive update. */
enum {
  G2P_X = 1,        /* x += dt sum v^L N (lanes px, py)                  */
  G2P_V = 2,        /* v += sum d N (lanes fx, fy)                       */
  G2P_STRAIN_P = 4, /* strain from lanes px, py (USL: v^L)               */
  G2P_STRAIN_F = 8, /* strain from lanes fx, fy (MUSL: v'; USF: v_i)     */
  G2P_TWO = 16      /* a band is cut: test each stencil for split nodes   */
};
#define G2P_USL (G2P_X | G2P_V | G2P_STRAIN_P)
#define G2P_MUSL (G2P_X | G2P_STRAIN_F)
#define G2P_MOVE (G2P_X | G2P_V)

/* The gather's interpolation at a particle at (xk, yk), for g2p_strip_impl: the lanes S
 * of the node records and their frac dt x and y derivatives GX, GY (dtihx, dtihy).  two:
 * near a separated band, the particle's side's field (mpm_fields.c).  uGIMP: 3 x 3 nodes. */
static inline __attribute__((always_inline)) void g2p_gather_gimp(const mpm_grid *g, const mpm_node *restrict nd,
                                                                   const mpm_particles *p, size_t k, double xk,
                                                                   double yk, double lcx, double lcy, double dtihx,
                                                                   double dtihy, const int two, mpm_v4 *S,
                                                                   mpm_v4 *GX, mpm_v4 *GY)
{
  const double ihx = g->ihx, ihy = g->ihy, ox = g->ox;
  const size_t nny = (size_t)g->nny;
  mpm_gimp1 sx, sy;
  mpm_gimp_1d((xk - ox) * ihx, lcx, &sx);
  mpm_gimp_1d((yk - g->oy) * ihy, lcy, &sy);
  mpm_v4 DX, DY;
  const size_t n0 = (size_t)sx.i0 * nny + (size_t)sy.i0;
  if (two && mpm_fields_any(g->fld, n0, nny))
    mpm_fields_gather(g->fld, (mpm_node *)nd, nny, &sx, &sy,
                      mpm_fields_pside(g->fld, n0, nny, &sx, &sy, xk, yk, p->x0[k], p->y0[k], g->h), S,
                      &DX, &DY);
  else
    mpm_gimp_gather(nd, nny, &sx, &sy, S, &DX, &DY);
  *GX = dtihx * DX;
  *GY = dtihy * DY;
}

/* The same with the paper's bilinear shapes: 2 x 2 nodes. */
static inline __attribute__((always_inline)) void g2p_gather_lin(const mpm_grid *g, const mpm_node *restrict nd,
                                                                  double xk, double yk, double dtihx, double dtihy,
                                                                  const int two, mpm_v4 *S, mpm_v4 *GX, mpm_v4 *GY)
{
  const size_t nny = (size_t)g->nny;
  mpm_shape sh;
  mpm_shape_inside(g, xk, yk, &sh); /* inside: checked by the scatter */
  const double rx = sh.wx1, ry = sh.wy1;
  const size_t n00 = sh.n00, n01 = n00 + 1, n10 = n00 + nny, n11 = n10 + 1;
  const mpm_node *r00 = nd + n00, *r10 = nd + n10, *r01 = nd + n01, *r11 = nd + n11;
  if (two && mpm_fields_any4(g->fld, n00, nny)) { /* near a separated band */
    size_t n[4];
    double w[4];
    mpm_shape_stencil(&sh, nny, n, w);
    const int side = mpm_fields_side_w(g->fld, n, w, 4, xk, yk, g->h);
    r00 = mpm_fields_node(g->fld, (mpm_node *)nd, n00, side);
    r10 = mpm_fields_node(g->fld, (mpm_node *)nd, n10, side);
    r01 = mpm_fields_node(g->fld, (mpm_node *)nd, n01, side);
    r11 = mpm_fields_node(g->fld, (mpm_node *)nd, n11, side);
  }
  const mpm_v4 a00 = node_load4(r00), a10 = node_load4(r10);
  const mpm_v4 a01 = node_load4(r01), a11 = node_load4(r11);
  /* The bilinear field and its gradient (eq. 7) from the same differences:
   * b0, b1 interpolate along x on the cell's lower and upper edges. */
  const mpm_v4 d0 = a10 - a00, d1 = a11 - a01;
  const mpm_v4 b0 = a00 + rx * d0, b1 = a01 + rx * d1, db = b1 - b0;
  *S = b0 + ry * db;
  *GX = dtihx * (d0 + ry * (d1 - d0));
  *GY = dtihy * db;
}

/* Particle k's stress from its strain increment (de0, de1, the tensor shear g2 / 2) for
 * g2p_strip_impl: the viscous stress of time.damping_beta (rate factor bvis; the
 * ledger's sum in *bv), then the elastic trial, kept (1 if not: the full update decides)
 * with its ledger term in *qs.
 * Sec. 4: the trial is kept where F <= 0 (eq. 23), tested as
 * <s_nn / snf>^2 + (s_nt / stf)^2 < (1 - lambda^q)^2 with the strength cached (str2k < 0
 * once separated: always the full update).  It rounds differently from the full update,
 * so anything within MPM_TRIAL_SAFE of the surface goes to the full update.  A
 * non-finite trial makes b NaN (NaN * 0 is NaN), fails the test, and is reported by the
 * full update: the finiteness check of the state costs nothing here.  (A non-finite
 * velocity or position shows up one step later, in the strain or in the scatter.) */
static inline __attribute__((always_inline)) int g2p_trial(const mpm_particles *p, size_t k, const mpm_material *m,
                                                            double de0, double de1, double g2, double bvis,
                                                            double *restrict sxx, double *restrict syy,
                                                            double *restrict sxy, double str2k, double *qs,
                                                            double *bv)
{
  const double de2 = 0.5 * g2;
  if (p->vxx) {
    /* stiffness-proportional damping: sigma_v = beta C : grad v, none on a separated
     * particle (its failure plane carries no traction) */
    *bv += m->mp * (p->vxx[k] * de0 + p->vyy[k] * de1 + p->vxy[k] * g2);
    const double r = p->sep[k] ? 0.0 : bvis;
    p->vxx[k] = r * (m->E1 * de0 + m->E2 * de1);
    p->vyy[k] = r * (m->E2 * de0 + m->E1 * de1);
    p->vxy[k] = r * 2.0 * m->G * de2;
  }
  double t[3];
  mpm_dcoh_trial(m, sxx[k], syy[k], sxy[k], de0, de1, de2, &t[0], &t[1], &t[2]);
  if (__builtin_expect(!mpm_dcoh_trial_inside(m, t, str2k), 0))
    return 1;
  *qs += m->mp * (t[0] * de0 + t[1] * de1 + t[2] * g2);
  sxx[k] = t[0];
  syy[k] = t[1];
  sxy[k] = t[2];
  return 0;
}

/* Eight particles in one vector (GCC's vector extension): elementwise IEEE arithmetic,
 * so each lane rounds as the scalar code does; comparisons give lane masks. */
typedef long long g2p_m8 __attribute__((vector_size(64)));

static inline mpm_v8 v8_at(const double *x)
{
  mpm_v8 v;
  memcpy(&v, x, sizeof v);
  return v;
}

/* a product as rounded, out of the compiler's sight: not fused into the sum it feeds,
 * as g2p_trial's a * a (computed in a branch of its own) is not */
static inline mpm_v8 v8_rounded(mpm_v8 x)
{
  __asm__("" : "+m"(x));
  return x;
}

/* g2p_trial without the viscous stress on eight lanes: the trial stress (kept where the
 * lane passes), keep (the lanes that pass) and the ledger's term q (qs += m->mp q). */
static inline __attribute__((always_inline)) void trial8(const mpm_material *m, mpm_v8 de0, mpm_v8 de1, mpm_v8 g2,
                                                         mpm_v8 *sx, mpm_v8 *sy, mpm_v8 *sxy, mpm_v8 str2,
                                                         mpm_v8 *q, g2p_m8 *keep)
{
  const mpm_v8 de2 = 0.5 * g2, zero = {0.0};
  const mpm_v8 txx = *sx + m->E1 * de0 + m->E2 * de1;
  const mpm_v8 tyy = *sy + m->E2 * de0 + m->E1 * de1;
  const mpm_v8 txy = *sxy + 2.0 * m->G * de2;
  const mpm_v8 sn = m->fn[0] * txx + m->fn[1] * tyy + m->fn[2] * txy;
  const g2p_m8 pos = sn > 0.0;
  const mpm_v8 a = (mpm_v8)((pos & (g2p_m8)sn) | (~pos & (g2p_m8)zero));
  const mpm_v8 b = m->ft[0] * txx + m->ft[1] * tyy + m->ft[2] * txy;
  const g2p_m8 k = v8_rounded(a * a) + b * b < MPM_TRIAL_SAFE * str2;
  *q = txx * de0 + tyy * de1 + txy * g2;
  *sx = (mpm_v8)((k & (g2p_m8)txx) | (~k & (g2p_m8)*sx));
  *sy = (mpm_v8)((k & (g2p_m8)tyy) | (~k & (g2p_m8)*sy));
  *sxy = (mpm_v8)((k & (g2p_m8)txy) | (~k & (g2p_m8)*sxy));
  *keep = k;
}

/* The particles of a group of eight (w of them, from k on) after their trial: in
 * particle order, the ledger's sum (acc, as g2p_trial adds it) where the trial passed,
 * the list for the full update where it failed. */
static inline __attribute__((always_inline)) void trial8_book(mpm_defer *d, size_t *nd, size_t k, size_t w,
                                                              const double *t0, const double *t1,
                                                              const double *tg, double mp, mpm_v8 q, g2p_m8 keep,
                                                              double *acc)
{
  for (size_t j = 0; j < w; j++) {
    if (keep[j]) {
      *acc += mp * q[j];
    } else {
      d->k[*nd] = k + j;
      d->de[*nd][0] = t0[j];
      d->de[*nd][1] = t1[j];
      d->de[*nd][2] = 0.5 * tg[j];
      (*nd)++;
    }
  }
}

/* The elastic trial of the n particles from k0 on, all of material m and without the
 * viscous stress, eight at a time (the last n % 8 through a padded copy), from their
 * strain increments t0, t1 (de0, de1) and tg (g2): the trial stress kept where it
 * passes, the rest listed in d; each lane is g2p_trial's arithmetic, the same bits.
 * Returns the list's length. */
static size_t g2p_trial_chunk(const mpm_particles *p, const mpm_material *m, size_t k0, size_t n, const double *t0,
                              const double *t1, const double *tg, mpm_defer *d, double *qs)
{
  double *const st[3] = {p->sxx + k0, p->syy + k0, p->sxy + k0};
  const double *str2 = p->str2 + k0;
  double acc = *qs;
  size_t i = 0, nd = 0;
  for (; i + 8 <= n; i += 8) {
    mpm_v8 sx = v8_at(st[0] + i), sy = v8_at(st[1] + i), sxy = v8_at(st[2] + i), q;
    g2p_m8 keep;
    trial8(m, v8_at(t0 + i), v8_at(t1 + i), v8_at(tg + i), &sx, &sy, &sxy, v8_at(str2 + i), &q, &keep);
    memcpy(st[0] + i, &sx, sizeof sx);
    memcpy(st[1] + i, &sy, sizeof sy);
    memcpy(st[2] + i, &sxy, sizeof sxy);
    trial8_book(d, &nd, k0 + i, 8, t0 + i, t1 + i, tg + i, m->mp, q, keep, &acc);
  }
  if (i < n) { /* the last lanes through a zeroed copy (the arrays end with the particles) */
    const size_t w = n - i;
    double pad[4][8] = {{0.0}}; /* sxx, syy, sxy, str2 */
    const double *src[4] = {st[0] + i, st[1] + i, st[2] + i, str2 + i};
    for (int c = 0; c < 4; c++)
      for (size_t j = 0; j < w; j++)
        pad[c][j] = src[c][j];
    mpm_v8 sx = v8_at(pad[0]), sy = v8_at(pad[1]), sxy = v8_at(pad[2]), q;
    g2p_m8 keep;
    trial8(m, v8_at(t0 + i), v8_at(t1 + i), v8_at(tg + i), &sx, &sy, &sxy, v8_at(pad[3]), &q, &keep);
    for (size_t j = 0; j < w; j++) {
      st[0][i + j] = sx[j];
      st[1][i + j] = sy[j];
      st[2][i + j] = sxy[j];
    }
    trial8_book(d, &nd, k0 + i, w, t0 + i, t1 + i, tg + i, m->mp, q, keep, &acc);
  }
  *qs = acc;
  return nd;
}

/* The trial of chunk [c0, c1) from d's strain increments (tde), after its moves: eight
 * at a time when the chunk is of one material (g2p_trial_chunk), else one by one
 * (g2p_trial); the ledger's sum into *qs and the list for the full update in particle
 * order.  Returns the list's length. */
static size_t g2p_trial_rest(const mpm_sim *s, mpm_defer *d, size_t c0, size_t c1, int mixed, double *qs)
{
  const mpm_particles *p = s->p;
  const size_t n = c1 - c0;
  const double *t0 = d->tde[0], *t1 = d->tde[1], *tg = d->tde[2];
  if (!mixed)
    return g2p_trial_chunk(p, &s->mat[p->mat[c0]], c0, n, t0, t1, tg, d, qs);
  size_t nd = 0;
  double bv = 0.0;
  for (size_t i = 0; i < n; i++)
    if (g2p_trial(p, c0 + i, &s->mat[p->mat[c0 + i]], t0[i], t1[i], tg[i], 0.0, p->sxx, p->syy, p->sxy,
                  p->str2[c0 + i], qs, &bv)) {
      d->k[nd] = c0 + i;
      d->de[nd][0] = t0[i];
      d->de[nd][1] = t1[i];
      d->de[nd][2] = 0.5 * tg[i];
      nd++;
    }
  return nd;
}

/* eqs. 5-7 and the constitutive update for the particles of strip q.  The four node
 * records give, in one weighted sum each, the interpolated values of every lane (S) and
 * their x and y derivatives (GX, GY).  USL: strain from v^L (lanes px, py).  MUSL:
 * velocities were already updated; strain from v' (lanes fx, fy).  USF: a strain pass
 * from v_i (lanes fx, fy) and, after the new forces, a pass that only moves.  frac: the
 * share of the step's strain increment (USAVG: 1/2 in each of two passes).  Adds the
 * ledger's particle sums of strip q. */
static inline __attribute__((always_inline)) void g2p_strip_impl(mpm_sim *s, int q, const int mode, const int gimp,
                                                                  double frac, mpm_defer *d, mpm_dwork *dw,
                                                                  g2p_acc *acc)
{
  const mpm_grid geo = *s->g, *g = &geo; /* a local copy: no store below can alias it */
  const mpm_particles *p = s->p;
  const double ihx = g->ihx, ihy = g->ihy, dt = s->sc.dt, ox = g->ox;
  const int strain = mode & (G2P_STRAIN_P | G2P_STRAIN_F);
  const int ux = (mode & G2P_STRAIN_F) ? GFX : GPX, uy = ux + 1; /* the lanes of the strain velocity */
  const double dtihx = frac * dt * ihx, dtihy = frac * dt * ihy;
  /* the safe columns [q S - 1, (q + 1) S + 1) of strip q (mpm_sort.c); for uGIMP's
   * wider support, half a column of the dual grid beyond the strip */
  const double drift = gimp ? 0.5 : 1.0, shift = gimp ? 0.5 : 0.0;
  const double clo = q * MPM_STRIP - drift, chi = (q + 1) * MPM_STRIP + drift;
  double lcx = 0.0, lcy = 0.0;
  if (gimp)
    mpm_gimp_lc(s, &lcx, &lcy);
  const size_t end = s->strip_start[q + 1];
  /* ledger: sum m sigma_new : deps (ledger_step), and sum m |dv_p|^2 in kv, with each
   * particle's mass taken from its material (mpm_material.mp), already in cache for the
   * elastic trial: reading p->m here cost 3 % of the USL step (h 2, 4 ppc) */
  double qs = 0.0;
  /* time.damping_beta: the viscous stress's rate factor beta / (frac dt) while it acts,
   * and the ledger's sum m sigma_v : deps of the viscous stress scattered this step */
  const double bvis = (p->vxx && (s->sc.damping_from == MPM_DAMP_START || s->cut))
                          ? s->sc.damping_beta / (frac * dt) : 0.0;
  double bv = 0.0;
  mpm_v4 kv = {0.0, 0.0, 0.0, 0.0};
  /* the strip's leftmost and rightmost new positions: a particle left the safe columns
   * iff one of those did (the column is monotone in x, rounding included); NaN ignored */
  double xlo = INFINITY, xhi = -INFINITY;
  /* without the viscous stress the trial runs after each chunk's moves, eight at a time */
  const int chunk8 = !p->vxx;
  double *restrict tde0 = d->tde[0], *restrict tde1 = d->tde[1], *restrict tdg = d->tde[2];
  /* Chunks of at most MPM_DEFER particles: the list cannot overflow inside one, and the
   * full updates run after it, outside the restrict-qualified block. */
  for (size_t c0 = s->strip_start[q]; c0 < end; c0 += MPM_DEFER) {
    const size_t c1 = end - c0 < MPM_DEFER ? end : c0 + MPM_DEFER;
    const mpm_node *restrict nd = g->nd;
    double *restrict x = p->x, *restrict y = p->y, *restrict vx = p->vx, *restrict vy = p->vy;
    double *restrict sxx = p->sxx, *restrict syy = p->syy, *restrict sxy = p->sxy;
    const double *restrict str2 = p->str2;
    const uint8_t *restrict pmat = p->mat;
    const mpm_material *restrict mat = s->mat;
    size_t *restrict dk = d->k;
    double(*restrict dde)[3] = d->de;
    size_t nd_ = 0;
    int mixed = 0; /* a chunk of more than one material: the trial one by one */
    for (size_t k = c0; k < c1; k++) {
      mpm_v4 S, GX, GY; /* field, frac dt d/dx, frac dt d/dy */
      if (gimp)
        g2p_gather_gimp(g, nd, p, k, x[k], y[k], lcx, lcy, dtihx, dtihy, mode & G2P_TWO, &S, &GX, &GY);
      else
        g2p_gather_lin(g, nd, x[k], y[k], dtihx, dtihy, mode & G2P_TWO, &S, &GX, &GY);
      /* eq. 5 (and eq. 6 for USL) */
      double xn = x[k];
      if (mode & G2P_X) {
        xn += dt * S[GPX];
        x[k] = xn;
        y[k] += dt * S[GPY];
      }
      if (mode & G2P_V) {
        vx[k] += S[GFX];
        vy[k] += S[GFY];
        kv += mat[pmat[k]].mp * (S * S); /* lanes GFX, GFY: m |dv_p|^2 */
      }
      if (strain && chunk8) { /* the trial after the loop, eight at a time */
        tde0[k - c0] = GX[ux];
        tde1[k - c0] = GY[uy];
        tdg[k - c0] = GY[ux] + GX[uy];
        mixed |= pmat[k] != pmat[c0];
      } else if (strain) {
        const double de0 = GX[ux], de1 = GY[uy], g2 = GY[ux] + GX[uy];
        /* the elastic trial (sec. 4), or the list for the full update */
        if (g2p_trial(p, k, &mat[pmat[k]], de0, de1, g2, bvis, sxx, syy, sxy, str2[k], &qs, &bv)) {
          dk[nd_] = k;
          dde[nd_][0] = de0;
          dde[nd_][1] = de1;
          dde[nd_][2] = 0.5 * g2;
          nd_++;
        }
      }
      if (mode & G2P_X) {
        xlo = xn < xlo ? xn : xlo;
        xhi = xn > xhi ? xn : xhi;
      }
    }
    if (strain && chunk8)
      nd_ = g2p_trial_rest(s, d, c0, c1, mixed, &qs);
    d->n = nd_;
    qs += s->ph->flush(s, q, s->p, d, dw, acc);
  }
  if ((mode & G2P_X) && xlo <= xhi) {
    const double clo_x = (xlo - ox) * ihx + shift, chi_x = (xhi - ox) * ihx + shift;
    acc->resort |= (clo_x < clo) | (chi_x >= chi);
  }
  s->led_part[q][MPM_LED_KP] += kv[GFX] + kv[GFY];
  s->led_part[q][MPM_LED_QS] += qs;
  s->led_part[q][MPM_LED_BV] += bv;
}

/* One copy of the loop per pass kind and shape, with and without the two-field test,
 * so that each reads only the lanes it needs and the bilinear USL loop stays as it
 * was; mpm_step_setup picks the shape's row once. */
#define G2P_FN(name, mode, gimp, fr)                                                                   \
  static void name(mpm_sim *s, int q, double frac, mpm_defer *d, mpm_dwork *dw, g2p_acc *acc)          \
  {                                                                                                    \
    (void)frac;                                                                                        \
    g2p_strip_impl(s, q, mode, gimp, fr, d, dw, acc);                                                  \
  }
G2P_FN(g2p_lin_usl, G2P_USL, 0, frac)
G2P_FN(g2p_lin_musl, G2P_MUSL, 0, 1.0)
G2P_FN(g2p_lin_strain, G2P_STRAIN_F, 0, frac)
G2P_FN(g2p_lin_move, G2P_MOVE, 0, 1.0)
G2P_FN(g2p_gimp_usl, G2P_USL, 1, frac)
G2P_FN(g2p_gimp_musl, G2P_MUSL, 1, 1.0)
G2P_FN(g2p_gimp_strain, G2P_STRAIN_F, 1, frac)
G2P_FN(g2p_gimp_move, G2P_MOVE, 1, 1.0)
#undef G2P_FN
/* The two-field loops take the shape at run time, once per strip: a constant shape
 * there lets the compiler contract the sums otherwise (FMA), and a45's load.csv moved
 * in the last digit. */
#define G2P_FN2(name, mode, fr)                                                                        \
  static void name(mpm_sim *s, int q, double frac, mpm_defer *d, mpm_dwork *dw, g2p_acc *acc)          \
  {                                                                                                    \
    (void)frac;                                                                                        \
    g2p_strip_impl(s, q, mode, s->sc.shape == MPM_SHAPE_GIMP, fr, d, dw, acc);                         \
  }
G2P_FN2(g2p_two_usl, G2P_USL | G2P_TWO, frac)
G2P_FN2(g2p_two_musl, G2P_MUSL | G2P_TWO, 1.0)
G2P_FN2(g2p_two_strain, G2P_STRAIN_F | G2P_TWO, frac)
G2P_FN2(g2p_two_move, G2P_MOVE | G2P_TWO, 1.0)
#undef G2P_FN2

/* [two fields][shape][pass] */
static const mpm_g2p_fn G2P_TAB[2][2][MPM_G2P_N] = {
  {{g2p_lin_usl, g2p_lin_musl, g2p_lin_strain, g2p_lin_move},
   {g2p_gimp_usl, g2p_gimp_musl, g2p_gimp_strain, g2p_gimp_move}},
  {{g2p_two_usl, g2p_two_musl, g2p_two_strain, g2p_two_move},
   {g2p_two_usl, g2p_two_musl, g2p_two_strain, g2p_two_move}},
};

/* A gather pass over all strips (pass: MPM_G2P_*). */
static mpm_status g2p(mpm_sim *s, int pass, double frac, char *err, size_t errlen)
{
  g2p_acc tot = {0, 0, 0, 0.0, 0, 0, 0};
  const mpm_g2p_fn fn = s->ph->g2p[s->ph->split][pass];
#ifdef _OPENMP
#pragma omp parallel num_threads(s->nthreads)
#endif
  {
    g2p_acc acc = {0, 0, 0, 0.0, 0, 0, 0};
    mpm_dwork *dw = s->dws[thread_id()];
    mpm_defer *d = &s->defer[thread_id()];
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for (int q = 0; q < s->nstrip; q++)
      fn(s, q, frac, d, dw, &acc);
#ifdef _OPENMP
#pragma omp critical
#endif
    {
      /* integer counters: order-free; tconst: a timing only */
      tot.soften += acc.soften;
      tot.separate += acc.separate;
      tot.bracketed += acc.bracketed;
      tot.tconst = acc.tconst > tot.tconst ? acc.tconst : tot.tconst;
      tot.resort |= acc.resort;
      if (acc.bad && (!tot.bad || acc.bad_k < tot.bad_k)) {
        tot.bad = 1;
        tot.bad_k = acc.bad_k;
      }
    }
  }
  s->n_soften += tot.soften;
  s->n_separate += tot.separate;
  s->n_bracketed += tot.bracketed;
  s->time_split[MPM_T_CONST] += tot.tconst;
  s->resort |= tot.resort;
  if (tot.bad) {
    const mpm_particles *p = s->p;
    if (!name_nonfinite(s, err, errlen))
      snprintf(err, errlen, "step %ld: particle at X = %g, Y = %g: decohesion update not finite", s->step,
               p->x0[tot.bad_k], p->y0[tot.bad_k]);
    return MPM_ENOTFINITE;
  }
  return MPM_OK;
}

/* The step's ledger (see "Energy" above), from the per-strip partial sums, in strip
 * order, and the serial held-node sums: the same bits for any thread count.  The same
 * sums carry the step's dissipation into sim.D_run (mpm_control.c). */
static void ledger_step(mpm_sim *s)
{
  double t[MPM_LED_N] = {0.0};
  for (int q = 0; q < s->nstrip; q++)
    for (int i = 0; i < MPM_LED_N; i++)
      t[i] += s->led_part[q][i];
  mpm_ledger *L = &s->led;
  const double A = t[MPM_LED_A] + L->s_A, K = 0.5 * (t[MPM_LED_K] + L->s_K);
  const double B = t[MPM_LED_B] + L->s_B + L->s_Bstart, Kp = 0.5 * t[MPM_LED_KP];
  /* Q = sum V dsigma : deps / 2 = (sum V sigma_new : deps - B) / 2: B is the particles'
   * sum V sigma : deps at the old stress (the strain is linear in the nodal velocity
   * u_i, the force in the stress), formed on the nodes.  V = m / rho, one rho for all
   * materials (mpm_sim_alloc). */
  assert(s->mat[MPM_MAT_IMP].irho == s->mat[MPM_MAT_BAR].irho && s->mat[MPM_MAT_HEAD].irho == s->mat[MPM_MAT_BAR].irho);
  /* B holds the viscous stress's share (time.damping_beta), Bv: work it took, booked in
   * L_damp; the stored energy's change is the rest */
  const double Bv = s->mat[MPM_MAT_BAR].irho * t[MPM_LED_BV];
  const double Q = 0.5 * (s->mat[MPM_MAT_BAR].irho * t[MPM_LED_QS] - (B - Bv));
  L->L_flip += K - Kp;
  L->L_bc += -L->s_H + (L->s_Wbook - L->s_Wtrue);
  L->L_scheme += L->s_Wtrue - A - K - B - Q + L->s_H - L->s_C - L->s_Dmp - L->s_I;
  L->W_iface += L->s_I;
  L->L_contact += L->s_C;
  L->L_damp += L->s_Dmp + Bv;
  s->D_run += t[MPM_LED_D];
}

/* grid.weights = laid, when a step ends (mpm_sim_step, failed or not): the step moved
 * each particle from its laid place; it is where it was plus that move (the next
 * lay_grid writes the offsets afresh) */
static void unlay(mpm_sim *s)
{
  if (!s->laid)
    return;
  mpm_particles *p = s->p;
  for (size_t k = 0; k < p->n; k++) {
    p->x[k] += p->wdx[k];
    p->y[k] += p->wdy[k];
  }
  s->laid = 0;
}

static int particle_inside(const mpm_sim *s, size_t k)
{
  mpm_shape sh;
  const mpm_particles *p = s->p;
  return s->sc.shape == MPM_SHAPE_GIMP ? mpm_gimp_inside(s->g, p->x[k], p->y[k])
                                       : mpm_shape_at(s->g, p->x[k], p->y[k], &sh);
}

/* Debris.  After the cut a snapback scene's release can fling a block of separated
 * particles off the bar (docs/findings.md).  A separated particle (sep) of the bar
 * found outside the grid leaves the computation: its kinetic and elastic energy are
 * booked in L_debris, its mass, velocity and stress become 0 and its material
 * MPM_MAT_DEBRIS (no stiffness, no strength), and it is parked at the nearest point one
 * cell inside the grid's edge; it keeps its lambda, dis and wcoh (D and W_coh are
 * unchanged).  Any other particle outside the grid is an error.  Returns the particles
 * parked. */
static long debris(mpm_sim *s)
{
  mpm_particles *p = s->p;
  const mpm_grid *g = s->g;
  const double xlo = g->ox + g->hx, xhi = g->ox + (g->ncx - 1) * g->hx;
  const double ylo = g->oy + g->h, yhi = g->oy + (g->ncy - 1) * g->h;
  long n = 0, moved = 0;
  for (size_t k = 0; k < p->n; k++) {
    if (particle_inside(s, k) || !isfinite(p->x[k]) || !isfinite(p->y[k]))
      continue;
    if (p->mat[k] != MPM_MAT_DEBRIS) {
      if (!p->sep[k] || p->mat[k] == MPM_MAT_HEAD)
        continue; /* not debris: the caller names it */
      double ke, se;
      mpm_particle_energy(s, k, &ke, &se);
      s->led.L_debris += ke + se;
      p->m[k] = 0.0;
      p->sxx[k] = p->syy[k] = p->sxy[k] = 0.0;
      p->str2[k] = 1.0; /* the elastic trial's bound: fn = ft = 0 pass it */
      p->mat[k] = MPM_MAT_DEBRIS;
      n++;
    }
    /* parked; a massless particle still follows the nodes' velocity, so debris that other
     * debris carried out again is parked again (it has no energy to book) */
    p->vx[k] = p->vy[k] = 0.0;
    p->x[k] = fmin(fmax(p->x[k], xlo), xhi);
    p->y[k] = fmin(fmax(p->y[k], ylo), yhi);
    moved++;
  }
  s->n_debris += n;
  return moved;
}

/* eqs. 2-3 into a zeroed grid; 1 if a particle is outside it. */
static int scatter_zeroed(mpm_sim *s)
{
  mpm_grid *g = s->g;
  memset(g->nd, 0, (size_t)g->nnx * (size_t)g->nny * sizeof(mpm_node));
  mpm_phase_hooks(s, MPM_PH_MARK);
  return mpm_scatter(s, 0);
}

/* eqs. 2-3; MPM_EDOMAIN or MPM_ENOTFINITE, with the particle named, if one is outside
 * the grid and is not debris. */
static mpm_status p2g(mpm_sim *s, char *err, size_t errlen)
{
  mpm_grid *g = s->g;
  g->body_k = MPM_PI / s->sc.L;
  g->body_now = s->sc.body_amp != 0.0 ? s->sc.body_amp * sin(s->sc.body_omega * s->t) : 0.0;
  if (!scatter_zeroed(s))
    return MPM_OK;
  if (debris(s) > 0) {
    mpm_sim_sort(s); /* the parked particles moved: their strips again */
    if (!scatter_zeroed(s))
      return MPM_OK;
  }
  const mpm_particles *p = s->p;
  mpm_status st = MPM_EDOMAIN;
  for (size_t k = 0; k < p->n; k++) {
    if (!particle_inside(s, k)) {
      st = isfinite(p->x[k]) && isfinite(p->y[k]) ? MPM_EDOMAIN : MPM_ENOTFINITE;
      snprintf(err, errlen, "step %ld: particle at X = %g, Y = %g %s at (%g, %g)%s", s->step, p->x0[k],
               p->y0[k], st == MPM_EDOMAIN ? "left the grid" : "has a non-finite position", p->x[k],
               p->y[k], st == MPM_EDOMAIN ? "; raise grid.margin" : "");
      break;
    }
  }
  return st;
}

void mpm_phase_time(mpm_sim *s, int which)
{
  const double t = mpm_wall();
  s->time_split[which] += t - s->ph->tmark;
  s->ph->tmark = t;
}

mpm_status mpm_phase_none(mpm_sim *s, char *err, size_t errlen)
{
  (void)s;
  (void)err;
  (void)errlen;
  return MPM_OK;
}

mpm_status mpm_phase_p2g(mpm_sim *s, char *err, size_t errlen)
{
  const mpm_status st = p2g(s, err, errlen);
  mpm_phase_time(s, MPM_T_P2G);
  return st;
}

/* A gather pass, timed apart from the constitutive updates inside it. */
mpm_status mpm_phase_g2p(mpm_sim *s, int pass, double frac, char *err, size_t errlen)
{
  const double c0 = s->time_split[MPM_T_CONST];
  const mpm_status st = g2p(s, pass, frac, err, errlen);
  mpm_phase_time(s, MPM_T_G2P);
  s->time_split[MPM_T_G2P] -= s->time_split[MPM_T_CONST] - c0;
  return st;
}

mpm_status mpm_phase_strain_first(mpm_sim *s, char *err, size_t errlen)
{
  const double frac = s->scheme->start_frac;
  mpm_nodes_start_velocity(s, frac);
  mpm_phase_hooks(s, MPM_PH_START);
  mpm_phase_time(s, MPM_T_GRID);
  mpm_status st = mpm_phase_g2p(s, MPM_G2P_STRAIN_F, frac, err, errlen);
  if (st == MPM_OK)
    st = mpm_phase_p2g(s, err, errlen);
  return st;
}

/* The step's start: the thread count, the grip's speed, the cut, the grid laid, the
 * particles sorted (every MPM_SORT_EVERY steps, or when one left its strip's range),
 * the ledger's step sums zeroed. */
static void begin(mpm_sim *s)
{
  mpm_threads_tick(s);
  mpm_control_step(s);
  mpm_sim_cut(s);
  mpm_phase_hooks(s, MPM_PH_LAY);
  s->ph->tmark = mpm_wall();
  if (s->resort || s->step % MPM_SORT_EVERY == 0) {
    mpm_sim_sort(s);
    mpm_phase_time(s, MPM_T_SORT);
  }
  memset(s->led_part, 0, (size_t)s->nstrip * sizeof *s->led_part);
  mpm_ledger *L = &s->led;
  L->s_A = L->s_K = L->s_B = L->s_Bheld = L->s_Bstart = L->s_H = L->s_Wtrue = L->s_Wbook = L->s_C = L->s_Dmp = L->s_I = 0.0;
}

/* eq. 4 with the constraints, and what the optional physics does to the nodes. */
static void nodes(mpm_sim *s)
{
  mpm_nodes_update(s);
  mpm_phase_hooks(s, MPM_PH_GRID);
  mpm_phase_time(s, MPM_T_GRID);
}

/* The step's end: the specimen's loading machine (the bar's rigid head), the ledger,
 * the grip and the clock. */
static void finish(mpm_sim *s)
{
  mpm_phase_hooks(s, MPM_PH_GATHER);
  if (s->spec->step_end)
    s->spec->step_end(s);
  mpm_phase_hooks(s, MPM_PH_END);
  ledger_step(s);
  s->ugrip += s->vgrip * s->sc.dt;
  s->P_peak = fmax(s->P_peak, s->P_grip);
  s->step++;
  s->t = s->step * s->sc.dt;
}

static mpm_status step(mpm_sim *s, char *err, size_t errlen)
{
  const mpm_scheme_type *sch = s->scheme;
  mpm_status st;
  begin(s);
  if ((st = mpm_phase_p2g(s, err, errlen)) != MPM_OK || (st = sch->before_nodes(s, err, errlen)) != MPM_OK)
    return st;
  nodes(s);
  if ((st = sch->gather(s, err, errlen)) != MPM_OK)
    return st;
  finish(s);
  return MPM_OK;
}

mpm_status mpm_sim_step(mpm_sim *s, char *err, size_t errlen)
{
  const mpm_status st = step(s, err, errlen);
  unlay(s); /* here, so that a step that failed half-way puts its particles back too */
  return st;
}

/* The band's rows after the gather (decohesion.Le = row or zone). */
static void band_gather(mpm_sim *s)
{
  mpm_band_step(s->band);
}

const mpm_hook mpm_hook_band = {"band", {[MPM_PH_GATHER] = band_gather}};

static void add_hook(struct mpm_phases *P, const mpm_hook *h)
{
  for (int ph = 0; ph < MPM_PH_N; ph++)
    if (h->at[ph]) {
      assert(P->n[ph] < MPM_HOOK_MAX);
      P->fn[ph][P->n[ph]++] = h->at[ph];
    }
}

mpm_status mpm_step_setup(mpm_sim *s)
{
  struct mpm_phases *P = calloc(1, sizeof *P);
  if (!P)
    return MPM_ENOMEM;
  const mpm_scene *sc = &s->sc;
  s->scheme = mpm_schemes[sc->scheme];
  /* in the order they act at a phase they share */
  if (sc->grid_motion == MPM_GRID_STRETCH)
    add_hook(P, &mpm_hook_stretch);
  if (sc->weights == MPM_WEIGHTS_LAID)
    add_hook(P, &mpm_hook_laid);
  if (s->g->fld)
    add_hook(P, s->g->fld->ifc ? &mpm_hook_iface : &mpm_hook_fields);
  if (s->damp)
    add_hook(P, &mpm_hook_damping);
  if (s->band)
    add_hook(P, &mpm_hook_band);
  const int gimp = sc->shape == MPM_SHAPE_GIMP;
  for (int i = 0; i < MPM_G2P_N; i++) {
    P->g2p[0][i] = G2P_TAB[0][gimp][i];
    P->g2p[1][i] = G2P_TAB[1][gimp][i];
  }
  P->flush = s->band ? flush_rows : flush_plain;
  s->ph = P;
  return MPM_OK;
}
