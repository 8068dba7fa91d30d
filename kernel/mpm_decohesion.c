/*
 * mpm_decohesion.c - the decohesion update at one particle and its algorithmic tangent
 * (Schreyer, Sulsky and Zhou 2002, secs. 3-4; docs/model.md secs. 3-4, choices sec. 6),
 * in the n-t frame of the failure plane (plane-stress elasticity keeps its form there).
 * The law (se, F, the flow: eqs. 19, 23-26) is mpm_law.h's; here:
 *
 *   weak compatibility  de_d = (d ud / Le) sym(n (x) m)                  eqs. 39-41
 *   first-order step    d lambda = -c / 2b, then Newton (or Brent)      eqs. 46, 49
 *   separation          eqs. 56-58, d ud_t = 2 Le de_nt; lambda grows on with |d ud|
 *
 * The flow is frozen at the trial state; no root in (0, 1 - lambda] is separation,
 * where compression closes the opening first.  mpm_dcoh_tangent differentiates the
 * converged step (phi(dl; s_tr) = 0).
 */
#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_law.h"

#define MPM_DCOH_FTOL 1e-12  /* |F| after a softening step               */
#define MPM_DCOH_MAXIT 60

struct mpm_dwork {
  gsl_root_fsolver *brent;
};

mpm_dwork *mpm_dwork_alloc(void)
{
  mpm_dwork *w = malloc(sizeof *w);
  if (!w)
    return NULL;
  w->brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (!w->brent) {
    free(w);
    return NULL;
  }
  return w;
}

void mpm_dwork_free(mpm_dwork *w)
{
  if (!w)
    return;
  gsl_root_fsolver_free(w->brent);
  free(w);
}

void mpm_material_init(mpm_material *m, const mpm_scene *sc, double snf, double Le)
{
  const mpm_plane pl = mpm_plane_of(sc);
  m->E = sc->E;
  m->nu = sc->nu;
  m->rho = sc->rho;
  m->E1 = sc->E / (1.0 - sc->nu * sc->nu);
  m->E2 = sc->nu * m->E1;
  m->G = sc->E / (2.0 * (1.0 + sc->nu));
  m->model = sc->model;
  m->nx = pl.nx;
  m->ny = pl.ny;
  m->tx = pl.tx;
  m->ty = pl.ty;
  m->snf = snf;
  m->stf = sc->stf;
  m->U0 = sc->U0;
  m->s0 = sc->s0;
  m->q = sc->q;
  m->ubar0 = sc->U0 / sc->s0;
  m->Le = Le;
  m->sep_threshold = sc->sep_threshold;
  m->visc = sc->dt > 0.0 ? sc->eta / sc->dt : 0.0;
  m->shear_closing = sc->reversed_shear == MPM_SHEAR_CLOSING;
  mpm_material_derive(m);
}

void mpm_material_derive(mpm_material *m)
{
  const int on = m->model != MPM_DCOH_NONE;
  const double nx = m->nx, ny = m->ny, tx = m->tx, ty = m->ty;
  m->irho = 1.0 / m->rho;
  m->isnf = 1.0 / m->snf;
  m->istf = 1.0 / m->stf;
  m->isnf2 = m->isnf * m->isnf;
  m->istf2 = m->istf * m->istf;
  m->kL = m->ubar0 / m->Le;
  m->Lopen = m->Le;
  /* (s_nn, s_tt, s_nt) from (sxx, syy, sxy); from_nt uses the same numbers back */
  m->rnn[0] = nx * nx; m->rnn[1] = ny * ny; m->rnn[2] = 2.0 * nx * ny;
  m->rtt[0] = tx * tx; m->rtt[1] = ty * ty; m->rtt[2] = 2.0 * tx * ty;
  m->rnt[0] = nx * tx; m->rnt[1] = ny * ty; m->rnt[2] = nx * ty + ny * tx;
  for (int i = 0; i < 3; i++) {
    m->fn[i] = on ? m->rnn[i] / m->snf : 0.0;
    m->ft[i] = on ? m->rnt[i] / m->stf : 0.0;
  }
}

double mpm_dcoh_str2(const mpm_material *m, double lam, int sep)
{
  const double str = mpm_law_S(lam, m->q);
  return sep ? -1.0 : str * str;
}

/* The effective traction of eq. 23 (mpm_law.h) with the material's strengths (<sn> taken
 * before the product: the bits the runs are measured with). */
static inline double eff_traction(const mpm_material *m, double sn, double st)
{
  return mpm_law_se(sn > 0.0 ? sn * m->isnf : 0.0, st * m->istf);
}

double mpm_dcoh_F(const mpm_material *m, double sxx, double syy, double sxy, double lam)
{
  const nt_stress s = mpm_to_nt(m, sxx, syy, sxy);
  return eff_traction(m, s.nn, s.nt) - mpm_law_S(lam, m->q);
}

/* The consistency function along the frozen flow direction:
 * phi(dl) = se(s_tr - dl s_m) - 1 + (lam + dl)^q - visc dl, with s_m the traction per unit
 * dl and visc = eta / dt: the viscous overstress eta dlambda/dt of decohesion.eta (0: the
 * paper's rate-independent law, eq. 23). */
typedef struct {
  const mpm_material *m;
  double sn, st;     /* trial traction        */
  double smn, smt;   /* traction per unit dl  */
  double lam;
} phi_ctx;

/* The traction (sn, st) at dl and its effective traction se (eq. 23), which phi and
 * its slope share. */
static inline double phi_se(const phi_ctx *c, double dl, double *sn, double *st)
{
  *sn = c->sn - dl * c->smn;
  *st = c->st - dl * c->smt;
  return eff_traction(c->m, *sn, *st);
}

/* phi at dl from se there. */
static inline double phi_of(const phi_ctx *c, double dl, double se)
{
  return se - 1.0 + mpm_law_powq(c->lam + dl, c->m->q) - c->m->visc * dl;
}

static double phi(double dl, void *vp)
{
  const phi_ctx *c = vp;
  double sn, st;
  return phi_of(c, dl, phi_se(c, dl, &sn, &st));
}

/* d phi / d dl at dl from the traction (sn, st) there and its se, for Newton and the
 * tangent (se is smooth away from sn = 0 and se = 0). */
static inline double dphi_of(const phi_ctx *c, double dl, double sn, double st, double se)
{
  double gn, gt;
  mpm_law_flow(sn, st, c->m->isnf2, c->m->istf2, &gn, &gt);
  const double lq = c->lam + dl;
  return -(gn * c->smn + gt * c->smt) / se + mpm_law_dpowq(lq, c->m->q) - c->m->visc;
}

/* Root of phi in (0, dlmax]: 0 and *dl on success, -1 when none exists
 * (traction reversal at the element level, or full decohesion within the step). */
static int solve_dl(const phi_ctx *c, double dlmax, double guess, mpm_dwork *w, mpm_dinfo *info,
                    double *dl_out)
{
  /* Newton from the paper's first-order step (eq. 46).  For q >= 1 phi is convex in
   * dl, so from dl = 0 with phi'(0) < 0 the iterates rise monotonically to the first root. */
  if (guess > 0.0 && c->m->q >= 1.0) {
    double dl = guess;
    for (int k = 0; k < MPM_DCOH_MAXIT && dl > 0.0 && dl <= dlmax; k++) {
      info->iters++;
      double sn, st;
      const double se = phi_se(c, dl, &sn, &st), f = phi_of(c, dl, se);
      if (fabs(f) < MPM_DCOH_FTOL) {
        *dl_out = dl;
        return 0;
      }
      const double d = dphi_of(c, dl, sn, st, se);
      if (!(d < 0.0))
        break; /* past the minimum of phi: let the bracket decide */
      dl -= f / d;
    }
  }
  /* Bracket by doubling from a small step, then refine with GSL's Brent solver. */
  info->bracketed = 1;
  double lo = 0.0, hi = guess > 0.0 ? fmin(guess, dlmax) : 1e-9 * dlmax;
  double fhi = phi(hi, (void *)c);
  while (fhi > 0.0) {
    if (hi >= dlmax)
      return -1;
    lo = hi;
    hi = fmin(2.0 * hi, dlmax);
    fhi = phi(hi, (void *)c);
    info->iters++;
  }
  if (fhi == 0.0) {
    *dl_out = hi;
    return 0;
  }
  gsl_function F = {phi, (void *)c};
  if (gsl_root_fsolver_set(w->brent, &F, lo, hi) != GSL_SUCCESS)
    return -1;
  double r = hi;
  for (int k = 0; k < 200; k++) {
    info->iters++;
    if (gsl_root_fsolver_iterate(w->brent) != GSL_SUCCESS)
      break;
    r = gsl_root_fsolver_root(w->brent);
    if (fabs(phi(r, (void *)c)) < MPM_DCOH_FTOL ||
        gsl_root_test_interval(gsl_root_fsolver_x_lower(w->brent),
                               gsl_root_fsolver_x_upper(w->brent), 0.0, 1e-15) == GSL_SUCCESS)
      break;
  }
  *dl_out = r;
  return 0;
}

/* Separation (eqs. 56-58, mpm_law_separate), and every later step of a separated particle:
 * release the traction of the trial stress by a decohesion strain in the n-t frame.  In
 * normal compression the opening closes first (never below zero) and compression is carried. */
static int separate(const mpm_material *m, nt_stress tr, double upn, nt_stress *s, double *dun, double *dut)
{
  double de_nn;
  const int contact = mpm_law_separate(tr.nn, tr.nt, m->E1, m->G, m->Lopen, upn, &de_nn, dun, dut);
  s->nn = tr.nn - m->E1 * de_nn;
  s->tt = tr.tt - m->E2 * de_nn;                     /* eq. 57 */
  s->nt = 0.0;
  return contact;
}

/* What one update decided and the frozen quantities it used, for the tangent
 * (mpm_dcoh_tangent): the trial traction, the flow direction at the trial state and the
 * root dl.  Written by dcoh_step; mpm_dcoh_update ignores it. */
typedef struct {
  int path;          /* MPM_DPATH_* (ELASTIC also for model NONE)                  */
  int contact;       /* separate(): the closing stopped at shut (s_nn follows the trial) */
  double dun;        /* ... and its normal opening increment                               */
  int st_on;         /* 1: st = trial s_nt; 0: reversed_shear = closing zeroed it   */
  nt_stress tr;      /* trial stress in the n-t frame                              */
  double st, se, r, gn, gt, mn, mt, dl;
  phi_ctx ctx;       /* the consistency function the root solved                   */
} dcoh_trace;

/* An unseparated particle's step from its elastic trial tr: nothing when eq. 23 holds (0);
 * otherwise (1) the softening step of eqs. 39-50, or the separation of eqs. 56-58 when
 * lambda would pass the threshold or no root is found: s, the jump increments, out's
 * lambda or sep, info's path. */
static inline __attribute__((always_inline)) int dcoh_soften(const mpm_material *m, const mpm_dstate *in,
                                                             const nt_stress tr, nt_stress *s, double *dun,
                                                             double *dut, mpm_dstate *out, mpm_dinfo *info,
                                                             mpm_dwork *w, dcoh_trace *t)
{
  /* decohesion.reversed_shear = closing: shear against the slip the particle has
   * accumulated (s_nt upt < 0) closes that slip elastically and leaves eq. 23, as <sn>
   * leaves normal compression out of it; only the opening part may soften.  The paper's
   * eq. 23 is even in s_nt (EVEN): after a release the rebound's reversed shear fails
   * the band's part-softened neighbours (docs/methods.md secs. 5h, 5j). */
  const int st_on = !(m->shear_closing && tr.nt * in->upt < 0.0);
  const double st = st_on ? tr.nt : 0.0;
  const double se = eff_traction(m, tr.nn, st);
  const double c = se - mpm_law_S(in->lam, m->q);            /* eq. 23 */
  if (c <= 0.0)
    return 0;
  /* Flow direction at the trial state (eqs. 24, 26). */
  const double ise = 1.0 / se, r = m->s0 * ise;
  double gn, gt;
  mpm_law_flow(tr.nn, st, m->isnf2, m->istf2, &gn, &gt);
  const double mn = r * gn;
  const double mt = m->model == MPM_DCOH_MODEL2 ? 0.0 : r * gt;
  /* Traction (and s_tt) per unit dlambda: C : (ubar0/Le) sym(n (x) m), eqs. 39-41. */
  const double k = m->kL;
  phi_ctx ctx = {m, tr.nn, st, m->E1 * k * mn, m->G * k * mt, in->lam};
  t->st_on = st_on;
  t->st = st;
  t->se = se;
  t->r = r;
  t->gn = gn;
  t->gt = gt;
  t->mn = mn;
  t->mt = mt;
  t->ctx = ctx;
  const double smtt = m->E2 * k * mn;
  /* 2b of eq. 49, -(m* : s_m) / s0 + q lambda^(q-1) with m* = (s0 / se)(gn, gt),
   * is dpow - Q / se^2 with Q = s0 (ubar0 / Le)(E1 gn^2 + G gt^2); the first-order
   * step of eq. 46, -c / 2b, where 2b < 0, is then c se^2 / (Q - dpow se^2): one
   * division, not two in a row. */
  const double Q = m->s0 * k * (m->E1 * gn * gn + (m->model == MPM_DCOH_MODEL2 ? 0.0 : m->G * gt * gt));
  const double se2 = se * se, den = Q + (m->visc - mpm_law_dpowq(in->lam, m->q)) * se2;
  const double guess = (den > 0.0 && isfinite(den)) ? c * se2 / den : 0.0;
  const double dlmax = 1.0 - in->lam;
  double dl = 0.0;
  const int ok = dlmax > 0.0 ? solve_dl(&ctx, dlmax, guess, w, info, &dl) : -1;
  if (ok == 0 && in->lam + dl <= m->sep_threshold) {
    s->nn = tr.nn - dl * ctx.smn;
    s->nt = tr.nt - dl * ctx.smt;
    s->tt = tr.tt - dl * smtt;
    *dun = dl * m->ubar0 * mn;
    *dut = dl * m->ubar0 * mt;
    out->lam = in->lam + dl;
    info->path = MPM_DPATH_SOFTEN;
    t->dl = dl;
  } else {
    /* Separation imminent (lambda past the threshold) or no solution. */
    t->contact = separate(m, tr, in->upn, s, dun, dut);
    t->dun = *dun;
    out->sep = 1;
    info->path = MPM_DPATH_SEPARATE;
  }
  return 1;
}

/* The update (mpm_dcoh_update), recording in *t what the tangent needs. */
static inline mpm_status dcoh_step(const mpm_material *m, const mpm_dstate *in, const double de[3],
                                   mpm_dstate *out, mpm_dinfo *info, mpm_dwork *w, dcoh_trace *t)
{
  assert(m && in && de && out && info);
  t->path = MPM_DPATH_ELASTIC;
  info->path = MPM_DPATH_ELASTIC;
  info->iters = 0;
  info->bracketed = 0;
  info->w = 0.0;
  *out = *in;

  /* Elastic trial (eq. 7 increment through plane-stress C). */
  mpm_dcoh_trial(m, in->sxx, in->syy, in->sxy, de[0], de[1], de[2], &out->sxx, &out->syy, &out->sxy);
  if (m->model == MPM_DCOH_NONE)
    goto done;
  /* Non-finite input never reaches the root solver (GSL's default handler aborts). */
  if (!isfinite(out->sxx) || !isfinite(out->syy) || !isfinite(out->sxy) || !isfinite(in->lam) ||
      !isfinite(in->upn) || !isfinite(in->upt))
    return MPM_ENOTFINITE;

  const nt_stress s_in = mpm_to_nt(m, in->sxx, in->syy, in->sxy);
  const nt_stress tr = mpm_to_nt(m, out->sxx, out->syy, out->sxy);
  double dun = 0.0, dut = 0.0;
  nt_stress s = tr;

  t->tr = tr;
  if (in->sep) {
    t->contact = separate(m, tr, in->upn, &s, &dun, &dut);
    t->dun = dun;
    info->path = MPM_DPATH_OPEN;
  } else if (!dcoh_soften(m, in, tr, &s, &dun, &dut, out, info, w, t)) {
    goto done;
  }
  if (info->path != MPM_DPATH_SOFTEN)
    out->lam = in->lam + mpm_law_open_dlam(dun, dut, m->ubar0); /* eq. 58 */
  out->upn = in->upn + dun;
  out->upt = in->upt + dut;
  /* Traction work, trapezoidal in the step: int s . d ud. */
  info->w = 0.5 * ((s_in.nn + s.nn) * dun + (s_in.nt + s.nt) * dut);
  mpm_from_nt(m, s, out);
  t->path = info->path;

done:
  if (!isfinite(out->sxx) || !isfinite(out->syy) || !isfinite(out->sxy) || !isfinite(out->lam) ||
      !isfinite(out->upn) || !isfinite(out->upt))
    return MPM_ENOTFINITE;
  return MPM_OK;
}

mpm_status mpm_dcoh_update(const mpm_material *m, const mpm_dstate *in, const double de[3],
                           mpm_dstate *out, mpm_dinfo *info, mpm_dwork *w)
{
  dcoh_trace t;
  return dcoh_step(m, in, de, out, info, w, &t);
}

/* Eight particles at once (GCC's vector extension; one AVX-512 register with
 * -march=native, pairs of SSE2 registers without): elementwise IEEE arithmetic, so a lane
 * rounds as the scalar code does.  Comparisons give lane masks (all ones or zero). */
typedef double dcoh_v8 __attribute__((vector_size(64)));
typedef long long dcoh_m8 __attribute__((vector_size(64)));

static inline dcoh_v8 v8_load(const double *x)
{
  dcoh_v8 v;
  memcpy(&v, x, sizeof v);
  return v;
}

static inline dcoh_v8 v8_sel(dcoh_m8 m, dcoh_v8 a, dcoh_v8 b) /* m ? a : b, lane by lane */
{
  return (dcoh_v8)((m & (dcoh_m8)a) | (~m & (dcoh_m8)b));
}

static inline dcoh_v8 v8_abs(dcoh_v8 x)
{
  const dcoh_m8 mag = (dcoh_m8){0} + 0x7fffffffffffffffLL; /* every bit but the sign */
  return (dcoh_v8)((dcoh_m8)x & mag);
}

static inline dcoh_m8 v8_finite(dcoh_v8 x)
{
  return (dcoh_m8)(v8_abs(x) <= DBL_MAX);
}

/* x as rounded, out of the compiler's sight: a product passed through it is not fused
 * into a later sum (-ffp-contract=fast), where the scalar code, which computes it in a
 * branch of its own, does not fuse it either. */
static inline dcoh_v8 v8_round(dcoh_v8 x)
{
  __asm__("" : "+m"(x));
  return x;
}

static inline dcoh_v8 v8_sqrt(dcoh_v8 x)
{
  dcoh_v8 r;
  for (int j = 0; j < 8; j++)
    r[j] = sqrt(x[j]);
  return r;
}

/* The arithmetic is dcoh_step's, dcoh_soften's and phi's for q = 1 (powq(lam) = lam,
 * dpowq = 1), expression for expression, so that each lane rounds (and contracts) as
 * they do; their branches become lane masks.  Lanes past n read the arrays' unused
 * (zeroed) tail, capacity a multiple of 8, and are ignored.  test_mpm_decohesion.c
 * compares the batch with mpm_dcoh_update bit for bit. */
void mpm_dcoh_soften_batch(const mpm_material *m, size_t n, double *const st[6], const unsigned char *sep,
                           const double *const de[3], double *w, unsigned char *ok)
{
  assert(m->q == 1.0 && m->model != MPM_DCOH_NONE);
  const int m2 = m->model == MPM_DCOH_MODEL2;
  const double E1 = m->E1, E2 = m->E2, G = m->G, k = m->kL, s0 = m->s0, visc = m->visc, ub = m->ubar0;
  const double isnf = m->isnf, istf = m->istf, isnf2 = m->isnf2, istf2 = m->istf2, thr = m->sep_threshold;
  const dcoh_v8 zero = {0.0};
  for (size_t i = 0; i < n; i += 8) {
    const dcoh_v8 xx = v8_load(st[0] + i), yy = v8_load(st[1] + i), xy = v8_load(st[2] + i);
    const dcoh_v8 lam = v8_load(st[3] + i), upn = v8_load(st[4] + i), upt = v8_load(st[5] + i);
    const dcoh_v8 e0 = v8_load(de[0] + i), e1 = v8_load(de[1] + i), e2 = v8_load(de[2] + i);
    dcoh_m8 sp;
    for (int j = 0; j < 8; j++)
      sp[j] = sep[i + j] ? -1 : 0;
    const dcoh_v8 txx = xx + E1 * e0 + E2 * e1;
    const dcoh_v8 tyy = yy + E2 * e0 + E1 * e1;
    const dcoh_v8 txy = xy + 2.0 * G * e2;
    const dcoh_m8 fin = v8_finite(txx) & v8_finite(tyy) & v8_finite(txy) & v8_finite(lam) & v8_finite(upn) &
                        v8_finite(upt);
    /* mpm_to_nt of the old and the trial stress */
    const dcoh_v8 inn = m->rnn[0] * xx + v8_round(m->rnn[1] * yy) + m->rnn[2] * xy;
    const dcoh_v8 int_ = m->rnt[0] * xx + v8_round(m->rnt[1] * yy) + m->rnt[2] * xy;
    const dcoh_v8 tnn = m->rnn[0] * txx + v8_round(m->rnn[1] * tyy) + m->rnn[2] * txy;
    const dcoh_v8 ttt = m->rtt[0] * txx + v8_round(m->rtt[1] * tyy) + m->rtt[2] * txy;
    const dcoh_v8 tnt = m->rnt[0] * txx + v8_round(m->rnt[1] * tyy) + m->rnt[2] * txy;
    const dcoh_m8 closed = m->shear_closing ? (dcoh_m8)(tnt * upt < 0.0) : (dcoh_m8){0};
    const dcoh_v8 stv = v8_sel(closed, zero, tnt);
    const dcoh_m8 pos = (dcoh_m8)(tnn > 0.0);
    const dcoh_v8 an = tnn * isnf, a = v8_sel(pos, an, zero), b = stv * istf; /* eff_traction */
    const dcoh_v8 se = v8_sqrt(v8_round(a * a) + b * b);
    const dcoh_v8 c = se - (1.0 - lam); /* eq. 23 */
    const dcoh_v8 ise = 1.0 / se, r = s0 * ise;
    const dcoh_v8 gnv = tnn * isnf2, gn = v8_sel(pos, gnv, zero);
    const dcoh_v8 gt = stv * istf2;
    const dcoh_v8 mn = r * gn;
    const dcoh_v8 mt = m2 ? zero : r * gt;
    const dcoh_v8 smn = E1 * k * mn, smt = G * k * mt;
    const dcoh_v8 smtt = E2 * k * mn;
    const dcoh_v8 q1 = v8_round(E1 * gn * gn), q2 = m2 ? zero : v8_round(G * gt * gt);
    const dcoh_v8 Q = v8_round(s0 * k * (q1 + q2));
    const dcoh_v8 se2 = se * se, den = Q + (visc - 1.0) * se2;
    const dcoh_v8 gs = c * se2 / den;
    const dcoh_v8 dl = v8_sel((dcoh_m8)(den > 0.0) & v8_finite(den), gs, zero); /* eq. 46 */
    const dcoh_v8 dlmax = 1.0 - lam;
    const dcoh_v8 fsn = tnn - dl * smn, fst = stv - dl * smt; /* phi(dl) */
    const dcoh_v8 fan = fsn * isnf, fa = v8_sel((dcoh_m8)(fsn > 0.0), fan, zero), fb = fst * istf;
    const dcoh_v8 f = v8_sqrt(v8_round(fa * fa) + fb * fb) - 1.0 + (lam + dl) - visc * dl;
    const dcoh_v8 snn = tnn - dl * smn, snt = tnt - dl * smt, stt = ttt - dl * smtt;
    const dcoh_v8 dun = dl * ub * mn, dut = dl * ub * mt;
    const dcoh_v8 olam = lam + dl, oupn = upn + dun, oupt = upt + dut;
    const dcoh_v8 wi = 0.5 * ((inn + snn) * dun + v8_round((int_ + snt) * dut));
    /* mpm_from_nt */
    const dcoh_v8 oxx = m->rnn[0] * snn + v8_round(m->rtt[0] * stt) + (2.0 * m->rnt[0]) * snt;
    const dcoh_v8 oyy = m->rnn[1] * snn + v8_round(m->rtt[1] * stt) + (2.0 * m->rnt[1]) * snt;
    const dcoh_v8 oxy = (0.5 * m->rnn[2]) * snn + v8_round((0.5 * m->rtt[2]) * stt) + m->rnt[2] * snt;
    const dcoh_m8 good = fin & ~sp & (dcoh_m8)(c > 0.0) & (dcoh_m8)(dlmax > 0.0) & (dcoh_m8)(dl > 0.0) &
                         (dcoh_m8)(dl <= dlmax) & (dcoh_m8)(v8_abs(f) < MPM_DCOH_FTOL) &
                         (dcoh_m8)(lam + dl <= thr) & v8_finite(oxx) & v8_finite(oyy) & v8_finite(oxy) &
                         v8_finite(olam) & v8_finite(oupn) & v8_finite(oupt);
    const dcoh_v8 out[6] = {v8_sel(good, oxx, xx),   v8_sel(good, oyy, yy),     v8_sel(good, oxy, xy),
                            v8_sel(good, olam, lam), v8_sel(good, oupn, upn), v8_sel(good, oupt, upt)};
    for (int q = 0; q < 6; q++)
      memcpy(st[q] + i, &out[q], sizeof out[q]);
    const dcoh_v8 wv = v8_sel(good, wi, zero);
    memcpy(w + i, &wv, sizeof wv);
    for (int j = 0; j < 8; j++)
      ok[i + j] = good[j] != 0;
  }
}

/* d s / d s_tr in the n-t frame, rows and columns (nn, tt, nt), of the path t took. */
static void tangent_nt(const mpm_material *m, const dcoh_trace *t, double A[3][3], double L[3])
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      A[i][j] = i == j ? 1.0 : 0.0;
  L[0] = L[1] = L[2] = 0.0;
  if (t->path == MPM_DPATH_OPEN || t->path == MPM_DPATH_SEPARATE) {
    /* lambda = lambda_in + |d ud| / ubar0, d ud = Lopen (s_nn_tr / E1, s_nt_tr / G) (eq. 58;
     * in contact d ud_n is -ud_n, fixed) */
    const double dun = t->contact ? t->dun : m->Lopen * t->tr.nn / m->E1, dut = m->Lopen * t->tr.nt / m->G;
    mpm_law_separate_dlam(dun, dut, t->contact, m->E1, m->G, m->Lopen, m->ubar0, &L[0], &L[2]);
    /* eqs. 56-58: s_nt = 0; open, s_nn = 0 and s_tt = s_tt_tr - (E2/E1) s_nn_tr (eq. 57);
     * in contact de_nn is fixed by the opening, so s_nn and s_tt follow the trial. */
    A[2][2] = 0.0;
    if (!t->contact) {
      A[0][0] = 0.0;
      A[1][0] = -m->E2 / m->E1;
    }
    return;
  }
  if (t->path != MPM_DPATH_SOFTEN)
    return;
  /* Softening: s = s_tr - dl s_m(s_tr), s_m = C : (ubar0/Le) sym(n (x) m) (eqs. 39-41) with
   * m = r (gn, gt), r = s0/se, frozen at the trial (eqs. 24, 26).  Derivatives with respect
   * to x = (s_nn_tr, s_nt_tr); s_tt_tr enters neither phi nor m.  <sn> makes gn and its
   * slope vanish in compression; closing (st_on = 0) makes st, gt, mt constant (0). */
  const double k = m->kL, se = t->se, r = t->r, gn = t->gn, gt = t->gt;
  const double hn = t->tr.nn > 0.0 ? m->isnf2 : 0.0;          /* d gn / d sn_tr */
  const double ht = t->st_on ? m->istf2 : 0.0;                 /* d gt / d st_tr */
  const double dse[2] = {gn / se, t->st_on ? gt / se : 0.0};   /* eq. 23 */
  double dmn[2], dmt[2];
  for (int j = 0; j < 2; j++) {
    const double dr = -r / se * dse[j];
    dmn[j] = dr * gn + (j == 0 ? r * hn : 0.0);
    dmt[j] = m->model == MPM_DCOH_MODEL2 ? 0.0 : dr * gt + (j == 1 ? r * ht : 0.0); /* eq. 26: none */
  }
  /* Implicit function theorem on phi(dl; x) = 0 (the consistency of eq. 23 with the
   * overstress): d dl / d x = -(d phi / d x) / (d phi / d dl), at the converged dl. */
  const double dl = t->dl;
  double sn, st;
  const double se_o = phi_se(&t->ctx, dl, &sn, &st);
  double gn_o, gt_o;
  mpm_law_flow(sn, st, m->isnf2, m->istf2, &gn_o, &gt_o);
  const double phil = dphi_of(&t->ctx, dl, sn, st, se_o);
  const double dsn[2] = {1.0, 0.0}, dst[2] = {0.0, t->st_on ? 1.0 : 0.0};
  double ddl[2];
  for (int j = 0; j < 2; j++) {
    const double phix = (gn_o * (dsn[j] - dl * m->E1 * k * dmn[j]) +
                         gt_o * (dst[j] - dl * m->G * k * dmt[j])) / se_o;
    ddl[j] = -phix / phil;
  }
  L[0] = ddl[0]; /* lambda = lambda_in + dl */
  L[2] = ddl[1];
  /* s_nn = sn_tr - dl E1 k mn, s_tt = stt_tr - dl E2 k mn, s_nt = st_tr - dl G k mt
   * (the trial s_nt, not st: closing keeps it elastic). */
  const int col[2] = {0, 2};
  for (int j = 0; j < 2; j++) {
    const double dn = ddl[j] * t->mn + dl * dmn[j], dt = ddl[j] * t->mt + dl * dmt[j];
    A[0][col[j]] -= m->E1 * k * dn;
    A[1][col[j]] -= m->E2 * k * dn;
    A[2][col[j]] -= m->G * k * dt;
  }
}

mpm_status mpm_dcoh_tangent(const mpm_material *m, const mpm_dstate *in, const double de[3], double D[3][3],
                            double dlam[3], mpm_dwork *w)
{
  mpm_dstate out;
  mpm_dinfo info;
  return mpm_dcoh_update_tangent(m, in, de, &out, &info, D, dlam, w);
}

mpm_status mpm_dcoh_update_tangent(const mpm_material *m, const mpm_dstate *in, const double de[3], mpm_dstate *out,
                                   mpm_dinfo *info, double D[3][3], double dlam[3], mpm_dwork *w)
{
  assert(m && in && de && D);
  dcoh_trace t;
  const mpm_status rc = dcoh_step(m, in, de, out, info, w, &t);
  double C[3][3];
  mpm_dcoh_elastic(m, C);
  if (dlam)
    dlam[0] = dlam[1] = dlam[2] = rc == MPM_OK ? 0.0 : NAN;
  if (rc != MPM_OK) {
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        D[i][j] = NAN;
    return rc;
  }
  if (t.path == MPM_DPATH_ELASTIC) { /* exactly C (and so exactly symmetric) */
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        D[i][j] = C[i][j];
    return MPM_OK;
  }
  /* D = P A R C: C the trial's d sigma_tr / d de, R = to_nt, A = d s / d s_tr in the n-t
   * frame, P = from_nt (its sxx, syy columns carry 2 rnt on s_nt, its sxy row halves
   * rnn[2], rtt[2]: the same numbers as from_nt). */
  const double R[3][3] = {{m->rnn[0], m->rnn[1], m->rnn[2]},
                          {m->rtt[0], m->rtt[1], m->rtt[2]},
                          {m->rnt[0], m->rnt[1], m->rnt[2]}};
  const double P[3][3] = {{m->rnn[0], m->rtt[0], 2.0 * m->rnt[0]},
                          {m->rnn[1], m->rtt[1], 2.0 * m->rnt[1]},
                          {0.5 * m->rnn[2], 0.5 * m->rtt[2], m->rnt[2]}};
  double A[3][3], RC[3][3], ARC[3][3];
  double L[3];
  tangent_nt(m, &t, A, L);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      RC[i][j] = R[i][0] * C[0][j] + R[i][1] * C[1][j] + R[i][2] * C[2][j];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      ARC[i][j] = A[i][0] * RC[0][j] + A[i][1] * RC[1][j] + A[i][2] * RC[2][j];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      D[i][j] = P[i][0] * ARC[0][j] + P[i][1] * ARC[1][j] + P[i][2] * ARC[2][j];
  if (dlam) /* L is d lambda / d (s_nn_tr, s_tt_tr, s_nt_tr) */
    for (int j = 0; j < 3; j++)
      dlam[j] = L[0] * RC[0][j] + L[1] * RC[1][j] + L[2] * RC[2][j];
  return MPM_OK;
}
