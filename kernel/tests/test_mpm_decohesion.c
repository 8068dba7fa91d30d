/*
 * test_mpm_decohesion.c - the pure constitutive update mpm_dcoh_update (secs. 3-4;
 * docs/model.md secs. 1, 3, 4) at a single particle, against values that do not come
 * from the update itself:
 *  - plane-stress elasticity C computed here from E and nu;
 *  - the softening branch of a strain-driven particle, solved here by bisection from
 *    F = 0 (eq. 23) and the weak compatibility of eqs. 39-41 (softening_root);
 *  - the traction work at separation UF = q U0 / (q + 1) (eq. 25), dissipation -> U0;
 *  - the flow directions of eqs. 24 (Model 1) and 26 (Model 2) evaluated here;
 *  - the Macaulay bracket, contact of a separated particle, purity, reversed shear;
 *  - the algorithmic tangent against central differences on every path.
 * Material (the paper's Fig. 6 data): E 1024, nu 0.25, rho 1, U0 0.375, s0 1,
 * separation threshold 0.98, Le 8 (one cell of the Fig. 6 grid).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>
#include <gsl/gsl_errno.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "test_util.h"

#define PI 3.14159265358979323846
#define LE 8.0

static mpm_material make_mat(int model, double alpha, double snf, double stf, double s0, double q)
{
  const mpm_scene sc = tu_scene(model, alpha, snf, stf, s0, q);
  mpm_material m;
  mpm_material_init(&m, &sc, snf, LE);
  return m;
}

/* Plane-stress C (docs/model.md sec. 1), from E and nu only; e[2] is tensor shear. */
static void C_apply(double E, double nu, const double e[3], double s[3])
{
  const double E1 = E / (1.0 - nu * nu), E2 = nu * E / (1.0 - nu * nu), G = E / (2.0 * (1.0 + nu));
  s[0] = E1 * e[0] + E2 * e[1];
  s[1] = E2 * e[0] + E1 * e[1];
  s[2] = 2.0 * G * e[2];
}

/* Traction components on the plane of normal n = (sin a, -cos a), t = (cos a, sin a). */
static void traction(double alpha_deg, double sxx, double syy, double sxy, double *sn, double *st)
{
  const double a = alpha_deg * PI / 180.0;
  const double nx = sin(a), ny = -cos(a), tx = cos(a), ty = sin(a);
  const double px = sxx * nx + sxy * ny, py = sxy * nx + syy * ny;
  *sn = px * nx + py * ny;
  *st = px * tx + py * ty;
}

static mpm_dstate zero_state(void)
{
  mpm_dstate s;
  memset(&s, 0, sizeof s);
  return s;
}

/* One update in place. */
static void step(const mpm_material *m, mpm_dstate *st, const double de[3], mpm_dinfo *info, mpm_dwork *w)
{
  const mpm_dstate in = *st;
  const mpm_status rc = mpm_dcoh_update(m, &in, de, st, info, w);
  if (rc != MPM_OK)
    fail_msg("mpm_dcoh_update: %s", mpm_strerror(rc));
}

/*
 * The softening branch of a strain-driven particle whose decohesion runs in a fixed
 * direction: the traction component s = A - B lambda (elastic part minus the relaxation
 * C : (ubar0/Le) sym(n (x) m) per unit lambda) must equal f (1 - lambda^q) (F = 0 with
 * one traction component).  Returns lambda in (0, 1) by bisection; the residual is
 * monotone-crossing for every q > 0 as long as A > f (past initiation) and A < B.
 */
static double softening_root(double A, double B, double f, double q)
{
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; k++) {
    const double mid = 0.5 * (lo + hi);
    const double r = f * (1.0 - pow(mid, q)) - (A - B * mid);
    if (r < 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

/* Small increments in any direction below initiation: lambda stays 0, the path is
 * elastic, the stress is C : e (total) with C from E, nu. */
static void test_mpm_decohesion_elastic_below_initiation(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const double alphas[] = {90.0, 60.0, 30.0, 0.0};
  for (size_t ia = 0; ia < sizeof alphas / sizeof alphas[0]; ia++) {
    const mpm_material m = make_mat(MPM_DCOH_MODEL1, alphas[ia], 1.0, 10.0, 1.0, 1.0);
    mpm_dstate s = zero_state();
    double e[3] = {0.0, 0.0, 0.0};
    /* a wandering path: strain components oscillating with amplitude 2e-4 (|s| < 0.5) */
    for (int k = 1; k <= 200; k++) {
      const double target[3] = {2e-4 * sin(0.07 * k), -1.5e-4 * cos(0.05 * k) + 1e-4, 1e-4 * sin(0.11 * k + 1.0)};
      const double de[3] = {target[0] - e[0], target[1] - e[1], target[2] - e[2]};
      mpm_dinfo info;
      step(&m, &s, de, &info, w);
      e[0] += de[0];
      e[1] += de[1];
      e[2] += de[2];
      double want[3];
      C_apply(1024.0, 0.25, e, want);
      assert_int_equal(info.path, MPM_DPATH_ELASTIC);
      assert_true(s.lam == 0.0 && s.upn == 0.0 && s.upt == 0.0 && s.sep == 0);
      assert_true(info.w == 0.0);
      assert_abs(s.sxx, want[0], 1e-12, "sxx = C:e");
      assert_abs(s.syy, want[1], 1e-12, "syy = C:e");
      assert_abs(s.sxy, want[2], 1e-12, "sxy = C:e");
      assert_true(mpm_dcoh_F(&m, s.sxx, s.syy, s.sxy, 0.0) < 0.0);
    }
  }
  /* model 0: no decohesion however large the stress */
  const mpm_material m0 = make_mat(MPM_DCOH_NONE, 90.0, 1.0, 10.0, 1.0, 1.0);
  mpm_dstate s = zero_state();
  const double de[3] = {0.01, -0.0025, 0.0};
  mpm_dinfo info;
  step(&m0, &s, de, &info, w);
  assert_int_equal(info.path, MPM_DPATH_ELASTIC);
  assert_rel(s.sxx, 1024.0 * 0.01, 1e-12, "model 0: sxx = E e (uniaxial stress)");
  assert_abs(s.syy, 0.0, 1e-12, "model 0: syy = 0 (uniaxial stress)");
  mpm_dwork_free(w);
}

/*
 * Opening, alpha = 90 (n = x), driven in uniaxial stress: de = (d, -nu d, 0) keeps the
 * elastic syy at 0, so sxx = E exx - E1 upn / Le.  With mstar = (s0/snf) n the
 * softening branch is s = E exx - E1 (ubar0 s0/snf / Le) lambda = snf (1 - lambda^q).
 * Returns the traction work per unit area to separation and the lambda there.
 */
static void drive_opening(double q, int model, double *work, double *lam_sep, int *bracketed_at_init)
{
  const double snf = 1.0, nu = 0.25, E = 1024.0, E1 = E / (1.0 - nu * nu);
  const mpm_material m = make_mat(model, 90.0, snf, 10.0, 1.0, q);
  const double B = E1 * (0.375 / 1.0) * (1.0 / snf) / LE; /* 51.2 */
  mpm_dwork *w = mpm_dwork_alloc();
  mpm_dstate s = zero_state();
  const double d = 1e-4;
  double exx = 0.0, W = 0.0, lam_prev = 0.0, sn_prev = 0.0;
  int nsoft = 0, sep_step = -1;
  *bracketed_at_init = -1;
  for (int k = 1; k <= 800; k++) {
    const double de[3] = {d, -nu * d, 0.0};
    mpm_dinfo info;
    const mpm_dstate before = s;
    step(&m, &s, de, &info, w);
    exx += d;
    double sn, st;
    traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
    if (sep_step < 0)
      W += info.w;
    assert_true(s.lam >= lam_prev); /* monotone */
    assert_abs(s.upt, 0.0, 1e-12 * 0.375, "pure opening: upt (cos 90 deg rounds to 6e-17)");
    if (E * exx <= snf * (1.0 - 1e-12)) {
      assert_int_equal(info.path, MPM_DPATH_ELASTIC);
      assert_rel(s.sxx, E * exx, 1e-12, "elastic sxx = E exx");
    } else if (info.path == MPM_DPATH_SOFTEN) {
      nsoft++;
      if (before.lam == 0.0)
        *bracketed_at_init = info.bracketed;
      assert_abs(mpm_dcoh_F(&m, s.sxx, s.syy, s.sxy, s.lam), 0.0, 1e-10, "F after softening");
      const double lam_want = softening_root(E * exx, B, snf, q);
      assert_abs(s.lam, lam_want, 1e-9, "lambda on the softening branch");
      assert_abs(sn, snf * (1.0 - pow(lam_want, q)), 1e-8, "traction on the softening branch");
      assert_rel(s.upn, 0.375 * s.lam, 1e-12, "upn = ubar0 (mstar.n) lambda");
      /* syy = C:(e - e_d) with e_d = (upn/Le) n n: E2 (exx - upn/Le) - E1 nu exx = -E2 upn/Le */
      assert_rel(s.syy, -nu * E1 * s.upn / LE, 1e-9, "syy on the softening branch");
      assert_true(s.lam > lam_prev); /* softening: lambda up, traction down */
      if (before.lam > 0.0)
        assert_true(sn < sn_prev);
      else
        assert_true(sn <= snf);
      assert_true(s.lam <= 0.98);
    } else if (info.path == MPM_DPATH_SEPARATE) {
      assert_int_equal(sep_step, -1);
      sep_step = k;
      *lam_sep = s.lam;
      assert_int_equal(s.sep, 1);
    } else {
      assert_int_equal(info.path, MPM_DPATH_OPEN);
      assert_true(sep_step > 0);
    }
    if (s.sep) { /* no traction across the plane once separated */
      assert_abs(sn, 0.0, 1e-12 * snf, "s.n after separation");
      assert_abs(st, 0.0, 1e-12 * snf, "s.t after separation");
      if (info.path == MPM_DPATH_OPEN) /* free in n: uniaxial stress along t, d syy = E d eyy */
        assert_rel(s.syy - before.syy, E * de[1], 1e-9, "d syy after separation");
    }
    lam_prev = s.lam;
    sn_prev = sn;
  }
  if (sep_step < 0)
    fail_msg("q = %g: no separation by exx = %g", q, exx);
  if (nsoft < 50)
    fail_msg("q = %g: only %d softening steps", q, nsoft);
  /* the opening goes on after separation: lambda grows with |d ud| / ubar0 (paper) */
  assert_true(s.lam > 1.0);
  *work = W;
  mpm_dwork_free(w);
}

/* Model 1, q = 1: the branch, F = 0, zero traction after separation, and the energies:
 * traction work to separation UF = q U0 / (q + 1) = 0.1875 (eq. 25), dissipation
 * U0 lambda -> U0 (lambda reaches the threshold 0.98 ~ 1). */
static void test_mpm_decohesion_opening_q1(void **state)
{
  (void)state;
  double W, lam, UF = 1.0 * 0.375 / 2.0;
  int br;
  drive_opening(1.0, MPM_DCOH_MODEL1, &W, &lam, &br);
  assert_rel(W, UF, 0.01, "traction work to separation vs UF = q U0/(q+1)");
  assert_rel(0.375 * lam, 0.375, 0.03, "dissipation U0 lambda at separation vs U0");
  assert_true(lam >= 0.98);
}

/* decohesion.eta: a softening step ends on F = eta dlambda / dt (the viscous overstress),
 * not on F = 0, and softens less than the rate-independent step from the same trial. */
static void test_mpm_decohesion_viscous_overstress(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  mpm_material m = make_mat(MPM_DCOH_MODEL1, 90.0, 1.0, 10.0, 1.0, 1.0);
  const double e0 = 1.0 / m.E1;         /* at 90 deg n = (1, 0): sxx reaches snf */
  const double de[3] = {1.02 * e0, 0.0, 0.0};
  mpm_dstate a = zero_state(), b;
  mpm_dinfo info;
  step(&m, &a, de, &info, w);          /* rate-independent: on F = 0 */
  assert_int_equal(info.path, MPM_DPATH_SOFTEN);
  assert_abs(mpm_dcoh_F(&m, a.sxx, a.syy, a.sxy, a.lam), 0.0, 1e-10, "eta 0: F after softening");
  m.visc = 5.0; /* eta / dt */
  b = zero_state();
  step(&m, &b, de, &info, w);
  assert_int_equal(info.path, MPM_DPATH_SOFTEN);
  assert_abs(mpm_dcoh_F(&m, b.sxx, b.syy, b.sxy, b.lam), m.visc * b.lam, 1e-10,
             "eta > 0: F after softening vs eta dlambda / dt");
  assert_true(b.lam > 0.0 && b.lam < a.lam);
  mpm_dwork_free(w);
}

/* q = 0.8 and 1.2 (and Model 2 in pure opening, which must agree with Model 1):
 * monotone softening onto the bisected branch, separation, work UF(q);
 * q < 1 must start with the bracketed solver (lambda^(q-1) infinite at 0). */
static void test_mpm_decohesion_opening_q_range(void **state)
{
  (void)state;
  const double qs[] = {0.8, 1.2, 0.5, 2.0};
  for (size_t i = 0; i < sizeof qs / sizeof qs[0]; i++) {
    const double q = qs[i];
    double W, lam;
    int br;
    drive_opening(q, MPM_DCOH_MODEL1, &W, &lam, &br);
    char what[80];
    snprintf(what, sizeof what, "q = %g: work vs UF = q U0/(q+1)", q);
    assert_rel(W, q * 0.375 / (q + 1.0), 0.02, what);
    snprintf(what, sizeof what, "q = %g: U0 lambda at separation vs U0", q);
    assert_rel(0.375 * lam, 0.375, 0.03, what);
    if (q < 1.0 && br != 1)
      fail_msg("q = %g: the first softening step did not use the bracketed solver (bracketed = %d)", q, br);
  }
  double W, lam;
  int br;
  drive_opening(1.0, MPM_DCOH_MODEL2, &W, &lam, &br);
  assert_rel(W, 0.375 / 2.0, 0.01, "Model 2, pure opening: work vs UF");
}

/* Pure shear, alpha = 90 (t = y), Mode II data of Fig. 8 (snf 10, stf 1, s0 10):
 * de = (0, 0, d) gives st = 2G (exy - upt / (2 Le)) with upt = ubar0 (s0/stf) lambda,
 * i.e. st = 2G exy - G ubar0 (s0/stf) / Le lambda = stf (1 - lambda).  Model 1 is
 * associated, so s . mstar = s0 se and the work to separation is UF again, whichever
 * mode; both signs of shear. */
static void test_mpm_decohesion_shear(void **state)
{
  (void)state;
  const double E = 1024.0, nu = 0.25, G = E / (2.0 * (1.0 + nu)), stf = 1.0, s0 = 10.0;
  const mpm_material m = make_mat(MPM_DCOH_MODEL1, 90.0, 10.0, stf, s0, 1.0);
  const double B = G * (0.375 / s0) * (s0 / stf) / LE; /* 19.2 */
  mpm_dwork *w = mpm_dwork_alloc();
  for (int sign = -1; sign <= 1; sign += 2) {
    mpm_dstate s = zero_state();
    const double d = sign * 2e-5;
    double exy = 0.0, W = 0.0, lam_sep = -1.0;
    int nsoft = 0;
    for (int k = 1; k <= 1500 && !s.sep; k++) {
      const double de[3] = {0.0, 0.0, d};
      mpm_dinfo info;
      step(&m, &s, de, &info, w);
      exy += d;
      W += info.w;
      double sn, st;
      traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
      assert_abs(s.upn, 0.0, 1e-12 * 0.375, "pure shear: upn (cos 90 deg rounds to 6e-17)");
      assert_abs(sn, 0.0, 1e-12, "pure shear: sn");
      if (info.path == MPM_DPATH_SOFTEN) {
        nsoft++;
        assert_abs(mpm_dcoh_F(&m, s.sxx, s.syy, s.sxy, s.lam), 0.0, 1e-10, "F after softening (shear)");
        const double lam_want = softening_root(2.0 * G * fabs(exy), B, stf, 1.0);
        assert_abs(s.lam, lam_want, 1e-9, "lambda on the shear branch");
        assert_abs(st, sign * stf * (1.0 - lam_want), 1e-8, "st on the shear branch");
        assert_rel(s.upt, sign * (0.375 / s0) * (s0 / stf) * s.lam, 1e-12, "upt = ubar0 (s0/stf) lambda");
      } else if (info.path == MPM_DPATH_SEPARATE) {
        lam_sep = s.lam;
        assert_abs(st, 0.0, 1e-12, "st after separation");
      } else {
        assert_int_equal(info.path, MPM_DPATH_ELASTIC);
        assert_rel(st, 2.0 * G * exy, 1e-12, "elastic st = 2G exy");
      }
    }
    assert_int_equal(s.sep, 1);
    assert_true(nsoft > 50);
    assert_rel(W, 0.375 / 2.0, 0.01, "shear: traction work vs UF");
    assert_rel(lam_sep, 1.0, 0.03, "shear: lambda at separation");
  }
  mpm_dwork_free(w);
}

/*
 * decohesion.reversed_shear (docs/findings.md): a particle softened in shear to
 * lambda about 0.5, then sheared back past its strength the other way, then forward again.
 * EVEN (the paper's eq. 23, even in st): the reversed shear softens it once |st| reaches
 * stf (1 - lambda), and the slip upt runs back.  CLOSING: every reversed step is elastic,
 * st = st_rev + 2G d(exy) with G from E and nu, lambda and upt unchanged, even at 1.5 times
 * the strength; forward again it stays elastic up to stf (1 - lambda) and then softens
 * on F = 0 from the lambda it kept.
 */
static void test_mpm_decohesion_reversed_shear(void **state)
{
  (void)state;
  const double E = 1024.0, nu = 0.25, G = E / (2.0 * (1.0 + nu)), stf = 1.0, s0 = 10.0;
  mpm_dwork *w = mpm_dwork_alloc();
  for (int rule = MPM_SHEAR_EVEN; rule <= MPM_SHEAR_CLOSING; rule++) {
    mpm_scene sc = tu_scene(MPM_DCOH_MODEL1, 90.0, 10.0, stf, s0, 1.0);
    sc.reversed_shear = rule;
    mpm_material m;
    mpm_material_init(&m, &sc, 10.0, LE);
    const double d = 2e-5;
    mpm_dstate s = zero_state();
    mpm_dinfo info;
    double sn, st;
    for (int k = 0; k < 2000 && s.lam < 0.5; k++) {
      const double de[3] = {0.0, 0.0, d};
      step(&m, &s, de, &info, w);
    }
    assert_true(s.lam >= 0.5 && s.lam < 0.6 && !s.sep);
    const double lam1 = s.lam, upt1 = s.upt;
    traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
    const double st1 = st;
    assert_rel(st1, stf * (1.0 - lam1), 1e-8, "on the forward branch");
    /* back: 2G n d = 2.5 times the strength, so st ends at -1.5 stf (1 - lambda) */
    const int nback = (int)ceil(2.5 * stf * (1.0 - lam1) / (2.0 * G * d));
    int nsoft = 0;
    for (int k = 1; k <= nback; k++) {
      const double de[3] = {0.0, 0.0, -d};
      step(&m, &s, de, &info, w);
      traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
      if (rule == MPM_SHEAR_CLOSING) {
        assert_int_equal(info.path, MPM_DPATH_ELASTIC);
        assert_abs(st, st1 - 2.0 * G * d * k, 1e-10, "closing: reversed shear is elastic");
        assert_true(s.lam == lam1 && s.upt == upt1);
      } else if (info.path == MPM_DPATH_SOFTEN) {
        nsoft++;
        assert_abs(st, -stf * (1.0 - s.lam), 1e-8, "even: the reversed branch, |st| = stf (1 - lambda)");
      }
    }
    if (rule == MPM_SHEAR_EVEN) {
      assert_true(nsoft > 10);
      assert_true(s.lam > lam1 + 0.01); /* 0.25 of stress past the strength over B - stf = 18.2 */
      assert_true(s.upt < upt1); /* the slip runs back */
      continue;
    }
    assert_true(st < -1.4 * stf * (1.0 - lam1));
    /* forward again: elastic up to the kept strength, then the branch from lam1 */
    int first_soft = -1;
    const double st_back = st;
    for (int k = 1; k <= 2 * nback && first_soft < 0; k++) {
      const double de[3] = {0.0, 0.0, d};
      step(&m, &s, de, &info, w);
      traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
      if (info.path == MPM_DPATH_SOFTEN) {
        first_soft = k;
        assert_abs(mpm_dcoh_F(&m, s.sxx, s.syy, s.sxy, s.lam), 0.0, 1e-10, "F after softening");
        assert_true(s.lam > lam1 && s.lam < lam1 + 0.01);
      } else {
        assert_int_equal(info.path, MPM_DPATH_ELASTIC);
        assert_abs(st, st_back + 2.0 * G * d * k, 1e-10, "forward again: elastic");
        assert_true(st <= stf * (1.0 - lam1) + 1e-12);
      }
    }
    assert_true(first_soft > 0);
  }
  mpm_dwork_free(w);
}

/*
 * Mixed loading: alpha = 60 with uniaxial-stress increments in x (sn and st both
 * nonzero), stf = 2 so that both terms of se matter.  Checks at every softening step:
 * F = 0; the increment of up is along the flow direction evaluated here at the trial
 * state (eq. 24 for Model 1, (mstar . n) n of eq. 26 for Model 2) with length
 * d lambda ubar0 |m|.  Model 1 work to separation is UF (associated flow:
 * s . mstar = s0 se, so int s . d up = U0 int (1 - lambda^q) d lambda).
 */
static void drive_mixed(int model, double q)
{
  const double E = 1024.0, nu = 0.25, snf = 1.0, stf = 2.0, s0 = 1.0, alpha = 60.0, ubar0 = 0.375;
  const mpm_material m = make_mat(model, alpha, snf, stf, s0, q);
  mpm_dwork *w = mpm_dwork_alloc();
  mpm_dstate s = zero_state();
  const double d = 2e-5;
  double W = 0.0, lam_prev = 0.0;
  int nsoft = 0, sep = 0;
  for (int k = 1; k <= 20000 && !sep; k++) {
    const double de[3] = {d, -nu * d, 0.0};
    double dsig[3], sn_tr, st_tr;
    C_apply(E, nu, de, dsig);
    traction(alpha, s.sxx + dsig[0], s.syy + dsig[1], s.sxy + dsig[2], &sn_tr, &st_tr);
    const mpm_dstate in = s;
    mpm_dinfo info;
    step(&m, &s, de, &info, w);
    W += info.w;
    assert_true(s.lam >= lam_prev);
    lam_prev = s.lam;
    if (info.path == MPM_DPATH_SOFTEN) {
      nsoft++;
      assert_abs(mpm_dcoh_F(&m, s.sxx, s.syy, s.sxy, s.lam), 0.0, 1e-10, "F after softening (mixed)");
      const double se = sqrt(sn_tr * sn_tr / (snf * snf) + st_tr * st_tr / (stf * stf));
      const double mn = s0 / se * sn_tr / (snf * snf);
      const double mt = model == MPM_DCOH_MODEL2 ? 0.0 : s0 / se * st_tr / (stf * stf);
      const double dl = s.lam - in.lam;
      assert_true(dl > 0.0);
      assert_rel(s.upn - in.upn, dl * ubar0 * mn, 1e-9, "d upn along the flow direction");
      if (model == MPM_DCOH_MODEL2)
        assert_true(s.upt == 0.0); /* eq. 26: up grows along n only */
      else
        assert_rel(s.upt - in.upt, dl * ubar0 * mt, 1e-9, "d upt along the flow direction");
    } else if (info.path == MPM_DPATH_SEPARATE) {
      sep = 1;
      double sn, st;
      traction(alpha, s.sxx, s.syy, s.sxy, &sn, &st);
      assert_abs(sn, 0.0, 1e-12, "sn after separation (mixed)");
      assert_abs(st, 0.0, 1e-12, "st after separation (mixed)");
      /* Separation is legitimate only if the consistency condition (docs/model.md sec. 4,
       * flow frozen at the trial state) has no root with lambda below the threshold. */
      const double se = sqrt(sn_tr * sn_tr / (snf * snf) + st_tr * st_tr / (stf * stf));
      const double kk = ubar0 / LE, E1 = E / (1.0 - nu * nu), G = E / (2.0 * (1.0 + nu));
      const double smn = E1 * kk * (s0 / se) * sn_tr / (snf * snf);
      const double smt = model == MPM_DCOH_MODEL2 ? 0.0 : G * kk * (s0 / se) * st_tr / (stf * stf);
      const double dlmax = 1.0 - in.lam;
      for (int j = 1; j <= 20000; j++) {
        const double dl = dlmax * j / 20000.0, a = fmax(sn_tr - dl * smn, 0.0) / snf, b = (st_tr - dl * smt) / stf;
        if (sqrt(a * a + b * b) - 1.0 + pow(in.lam + dl, q) <= 0.0 && in.lam + dl < 0.98 - 1e-4)
          fail_msg("model %d q %g: separated at lambda %g although F = 0 has a root at lambda %g", model, q,
                   in.lam, in.lam + dl);
      }
      if (model == MPM_DCOH_MODEL1)
        assert_rel(s.lam, 1.0, 0.03, "lambda at separation (mixed, Model 1)");
    } else {
      assert_int_equal(info.path, MPM_DPATH_ELASTIC);
      assert_true(s.upt == 0.0 && s.upn == 0.0);
    }
  }
  if (!sep)
    fail_msg("model %d q %g: mixed loading never separated", model, q);
  assert_true(nsoft > 50);
  if (model == MPM_DCOH_MODEL1)
    assert_rel(W, q * 0.375 / (q + 1.0), 0.03, "mixed, Model 1: traction work vs UF");
  mpm_dwork_free(w);
}

static void test_mpm_decohesion_mixed_model1(void **state)
{
  (void)state;
  drive_mixed(MPM_DCOH_MODEL1, 1.0);
  drive_mixed(MPM_DCOH_MODEL1, 0.8);
  drive_mixed(MPM_DCOH_MODEL1, 1.2);
}

static void test_mpm_decohesion_model2_normal_only(void **state)
{
  (void)state;
  drive_mixed(MPM_DCOH_MODEL2, 1.0);
  drive_mixed(MPM_DCOH_MODEL2, 0.8);
}

/*
 * Macaulay bracket: a stress that is pure normal compression on the plane (sigma =
 * -p n (x) n, p up to 100 snf) plus a shear traction of 0.9 stf never initiates.
 * Without the bracket se = sqrt(p^2/snf^2 + 0.81) would pass 1 at once.
 */
static void test_mpm_decohesion_compression_never_initiates(void **state)
{
  (void)state;
  const double E = 1024.0, nu = 0.25, G = E / (2.0 * (1.0 + nu));
  const double alphas[] = {90.0, 60.0, 30.0};
  mpm_dwork *w = mpm_dwork_alloc();
  for (size_t ia = 0; ia < 3; ia++) {
    const double alpha = alphas[ia], a = alpha * PI / 180.0;
    const double nx = sin(a), ny = -cos(a), tx = cos(a), ty = sin(a);
    const mpm_material m = make_mat(MPM_DCOH_MODEL1, alpha, 1.0, 10.0, 1.0, 1.0);
    mpm_dstate s = zero_state();
    double e[3] = {0.0, 0.0, 0.0};
    for (int k = 1; k <= 100; k++) {
      /* target stress -p n n + tau (n t + t n), strain by the plane-stress compliance */
      const double p = 1.0 * k, tau = 9.0 * k / 100.0;
      const double sig[3] = {-p * nx * nx + 2.0 * tau * nx * tx, -p * ny * ny + 2.0 * tau * ny * ty,
                             -p * nx * ny + tau * (nx * ty + ny * tx)};
      const double et[3] = {(sig[0] - nu * sig[1]) / E, (sig[1] - nu * sig[0]) / E, sig[2] / (2.0 * G)};
      const double de[3] = {et[0] - e[0], et[1] - e[1], et[2] - e[2]};
      mpm_dinfo info;
      step(&m, &s, de, &info, w);
      memcpy(e, et, sizeof e);
      assert_int_equal(info.path, MPM_DPATH_ELASTIC);
      assert_true(s.lam == 0.0 && s.sep == 0);
      double sn, st;
      traction(alpha, s.sxx, s.syy, s.sxy, &sn, &st);
      assert_rel(sn, -p, 1e-10, "sn = -p");
      assert_rel(st, tau, 1e-10, "st = tau");
    }
  }
  mpm_dwork_free(w);
}

/*
 * Contact of a separated particle (decision in mpm_decohesion.c): alpha = 90, opened
 * past separation, then compressed with a shear increment in every step.  While the
 * opening closes the particle carries nothing across the plane; once shut (upn = 0,
 * never below) it carries normal compression with the elastic stiffness,
 * d sxx = E1 d exx + E2 d eyy (C from E, nu), and never any shear.
 */
static void test_mpm_decohesion_separated_contact(void **state)
{
  (void)state;
  const double E = 1024.0, nu = 0.25, E1 = E / (1.0 - nu * nu), E2 = nu * E1;
  const mpm_material m = make_mat(MPM_DCOH_MODEL1, 90.0, 1.0, 10.0, 1.0, 1.0);
  mpm_dwork *w = mpm_dwork_alloc();
  mpm_dstate s = zero_state();
  mpm_dinfo info;
  for (int k = 0; k < 700; k++) {
    const double de[3] = {1e-4, -nu * 1e-4, 0.0};
    step(&m, &s, de, &info, w);
  }
  assert_int_equal(s.sep, 1);
  assert_true(s.upn > 0.3);
  const double lam_open = s.lam;
  int closed_steps = 0, open_steps = 0;
  for (int k = 0; k < 1200; k++) {
    const double de[3] = {-1e-4, 0.2e-4, 0.5e-4};
    const mpm_dstate in = s;
    step(&m, &s, de, &info, w);
    double sn, st;
    traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
    assert_int_equal(info.path, MPM_DPATH_OPEN);
    assert_int_equal(s.sep, 1);
    assert_abs(st, 0.0, 1e-12, "no shear across a separated plane");
    assert_true(sn <= 1e-12);
    assert_true(s.upn >= 0.0); /* no interpenetration */
    assert_true(s.lam >= in.lam);
    if (in.upn == 0.0) { /* shut before and after: elastic in the normal direction */
      closed_steps++;
      assert_abs(s.upn, 0.0, 0.0, "stays shut under compression");
      assert_rel(s.sxx - in.sxx, E1 * de[0] + E2 * de[1], 1e-9, "closed: d sxx = E1 dexx + E2 deyy");
    } else if (s.upn > 0.0) {
      open_steps++;
      assert_abs(sn, 0.0, 1e-12, "closing: no normal traction while open");
    }
  }
  assert_true(open_steps > 100 && closed_steps > 100);
  double sn, st;
  traction(90.0, s.sxx, s.syy, s.sxy, &sn, &st);
  assert_true(sn < -1.0); /* real compression carried at the end */
  assert_true(s.lam >= lam_open);
  mpm_dwork_free(w);
}

static void assert_same_state(const mpm_dstate *a, const mpm_dstate *b, const char *what)
{
  const double fa[] = {a->sxx, a->syy, a->sxy, a->lam, a->upn, a->upt};
  const double fb[] = {b->sxx, b->syy, b->sxy, b->lam, b->upn, b->upt};
  if (memcmp(fa, fb, sizeof fa) != 0 || a->sep != b->sep)
    fail_msg("%s: states differ", what);
}

/* Purity: the same arguments give bit-identical results, whatever the scratch went
 * through in between, and the inputs are not touched. */
static void test_mpm_decohesion_pure_function(void **state)
{
  (void)state;
  const mpm_material m = make_mat(MPM_DCOH_MODEL1, 60.0, 1.0, 2.0, 1.0, 0.8);
  const mpm_material mcopy = m;
  mpm_dwork *w1 = mpm_dwork_alloc(), *w2 = mpm_dwork_alloc();
  mpm_dstate s = zero_state();
  mpm_dinfo info;
  /* bring the particle onto the softening branch */
  for (int k = 0; k < 300 && !(info.path == MPM_DPATH_SOFTEN && s.lam > 0.2); k++) {
    const double de[3] = {2e-5, -0.25 * 2e-5, 0.0};
    step(&m, &s, de, &info, w1);
  }
  assert_true(s.lam > 0.0 && !s.sep);
  const mpm_dstate in = s, in_copy = s;
  const double de[3] = {3e-5, -1e-5, 1e-5}, de_copy[3] = {3e-5, -1e-5, 1e-5};
  mpm_dstate o1, o2, o3;
  mpm_dinfo i1, i2, i3;
  assert_int_equal(mpm_dcoh_update(&m, &in, de, &o1, &i1, w1), MPM_OK);
  /* dirty the scratch with an unrelated bracketed solve */
  mpm_dstate junk;
  const mpm_dstate z = zero_state();
  const double big[3] = {0.01, 0.0, 0.0};
  mpm_dcoh_update(&m, &z, big, &junk, &info, w1);
  assert_int_equal(mpm_dcoh_update(&m, &in, de, &o2, &i2, w1), MPM_OK);
  assert_int_equal(mpm_dcoh_update(&m, &in, de, &o3, &i3, w2), MPM_OK);
  assert_same_state(&o1, &o2, "same inputs, same scratch");
  assert_same_state(&o1, &o3, "same inputs, other scratch");
  assert_true(i1.path == i2.path && i1.iters == i2.iters && i1.bracketed == i2.bracketed &&
              memcmp(&i1.w, &i2.w, sizeof i1.w) == 0);
  assert_true(i1.path == i3.path && memcmp(&i1.w, &i3.w, sizeof i1.w) == 0);
  assert_same_state(&in, &in_copy, "input state untouched");
  assert_memory_equal(de, de_copy, sizeof de);
  assert_memory_equal(&m, &mcopy, sizeof m);
  assert_int_equal(i1.path, MPM_DPATH_SOFTEN); /* the case exercised the solver */
  mpm_dwork_free(w1);
  mpm_dwork_free(w2);
}

/* One non-finite increment through each model; 0 when every call returned
 * MPM_ENOTFINITE. */
static int nonfinite_all_reported(void)
{
  mpm_dwork *w = mpm_dwork_alloc();
  const double bad[][3] = {{NAN, 0.0, 0.0}, {0.0, INFINITY, 0.0}, {0.0, 0.0, -INFINITY}};
  const int models[] = {MPM_DCOH_NONE, MPM_DCOH_MODEL1, MPM_DCOH_MODEL2};
  int nbad = 0;
  for (int im = 0; im < 3; im++) {
    const mpm_material m = make_mat(models[im], 90.0, 1.0, 10.0, 1.0, 1.0);
    for (int b = 0; b < 3; b++) {
      const mpm_dstate in = zero_state();
      mpm_dstate out;
      mpm_dinfo info;
      if (mpm_dcoh_update(&m, &in, bad[b], &out, &info, w) != MPM_ENOTFINITE) {
        fprintf(stderr, "model %d, increment %d: non-finite input not reported\n", models[im], b);
        nbad++;
      }
    }
  }
  mpm_dwork_free(w);
  return nbad;
}

/* MPM_ENOTFINITE when the increment is not finite (the error path), with GSL's error
 * handler off as the delam program runs it (verify/main.c). */
static void test_mpm_decohesion_not_finite(void **state)
{
  (void)state;
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  const int nbad = nonfinite_all_reported();
  gsl_set_error_handler(old);
  assert_int_equal(nbad, 0);
}

/* The same with GSL's default error handler, as any other caller of the library gets
 * it: mpm.h promises MPM_ENOTFINITE, and a NaN must never reach gsl_root_fsolver_set,
 * whose default handler aborts.  Run in a child process so that an abort is observed,
 * not suffered. */
static void test_mpm_decohesion_not_finite_default_gsl_handler(void **state)
{
  (void)state;
  fflush(NULL);
  const pid_t pid = fork();
  assert_true(pid >= 0);
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stderr)) /* the abort message would look like a failure */
      _exit(2);
    _exit(nonfinite_all_reported() == 0 ? 0 : 1);
  }
  int status = 0;
  assert_int_equal(waitpid(pid, &status, 0), pid);
  assert_false(WIFSIGNALED(status)); /* no abort from GSL's default handler */
  assert_true(WIFEXITED(status));
  assert_int_equal(WEXITSTATUS(status), 0);
}

/* ---- the algorithmic tangent mpm_dcoh_tangent ---- */

/* A stress given in the n-t frame of plane alpha, as (sxx, syy, sxy):
 * sigma = snn n n + stt t t + snt (n t + t n). */
static mpm_dstate nt_state(double alpha_deg, double snn, double stt, double snt, double lam, double upn,
                           double upt, int sep)
{
  const double a = alpha_deg * PI / 180.0;
  const double nx = sin(a), ny = -cos(a), tx = cos(a), ty = sin(a);
  mpm_dstate s = zero_state();
  s.sxx = snn * nx * nx + stt * tx * tx + 2.0 * snt * nx * tx;
  s.syy = snn * ny * ny + stt * ty * ty + 2.0 * snt * ny * ty;
  s.sxy = snn * nx * ny + stt * tx * ty + snt * (nx * ty + ny * tx);
  s.lam = lam;
  s.upn = upn;
  s.upt = upt;
  s.sep = sep;
  return s;
}

/* Drives a particle from rest by increments de0 until lambda reaches lam_min, or to its
 * last softening step before separation; fails unless it softened in that last step. */
static mpm_dstate soften_to(const mpm_material *m, const double de0[3], double lam_min, mpm_dwork *w)
{
  mpm_dstate s = zero_state();
  mpm_dinfo info = {.path = MPM_DPATH_ELASTIC};
  for (int k = 0; k < 100000 && s.lam < lam_min; k++) {
    mpm_dstate next = s;
    mpm_dinfo ni;
    step(m, &next, de0, &ni, w);
    if (next.sep)
      break;
    s = next;
    info = ni;
  }
  if (s.lam == 0.0 || info.path != MPM_DPATH_SOFTEN)
    fail_msg("soften_to: lambda %g, path %d", s.lam, info.path);
  return s;
}

/*
 * D of mpm_dcoh_tangent against central differences of mpm_dcoh_update at (in, de):
 * step h = 1e-7 x the strain scale (the largest of |de| and |sigma_in| / E1); every
 * evaluation must take the path `path`.  Fails when the largest error passes 1e-5 of the
 * largest entry of D; returns that relative error (reported as a TAP comment).
 */
static double fd_check(const mpm_material *m, const mpm_dstate *in, const double de[3], int path,
                       const char *what, mpm_dwork *w)
{
  double D[3][3], L[3];
  assert_int_equal(mpm_dcoh_tangent(m, in, de, D, L, w), MPM_OK);
  mpm_dstate o;
  mpm_dinfo info;
  assert_int_equal(mpm_dcoh_update(m, in, de, &o, &info, w), MPM_OK);
  if (info.path != path)
    fail_msg("%s: path %d, want %d", what, info.path, path);
  double scale = fmax(fmax(fabs(de[0]), fabs(de[1])), fabs(de[2]));
  scale = fmax(scale, fmax(fmax(fabs(in->sxx), fabs(in->syy)), fabs(in->sxy)) / m->E1);
  const double h = 1e-7 * scale;
  double err = 0.0, dmax = 0.0, lerr = 0.0, lmax = 0.0;
  for (int j = 0; j < 3; j++) {
    double dp[3] = {de[0], de[1], de[2]}, dm[3] = {de[0], de[1], de[2]};
    dp[j] += h;
    dm[j] -= h;
    mpm_dstate op, om;
    mpm_dinfo ip, im;
    assert_int_equal(mpm_dcoh_update(m, in, dp, &op, &ip, w), MPM_OK);
    assert_int_equal(mpm_dcoh_update(m, in, dm, &om, &im, w), MPM_OK);
    if (ip.path != path || im.path != path)
      fail_msg("%s: de[%d] +- h changes the path (%d, %d; want %d)", what, j, ip.path, im.path, path);
    const double fd[3] = {(op.sxx - om.sxx) / (2.0 * h), (op.syy - om.syy) / (2.0 * h),
                          (op.sxy - om.sxy) / (2.0 * h)};
    for (int i = 0; i < 3; i++) {
      err = fmax(err, fabs(D[i][j] - fd[i]));
      dmax = fmax(dmax, fabs(D[i][j]));
    }
    /* d lambda / d de, the static solver's dissipation control, on the same differences */
    const double fl = (op.lam - om.lam) / (2.0 * h);
    lerr = fmax(lerr, fabs(L[j] - fl));
    lmax = fmax(lmax, fabs(fl));
  }
  if (lmax > 0.0 && !(lerr < 1e-5 * lmax))
    fail_msg("%s: d lambda / d de vs central differences: abs err %.3g (max %g)", what, lerr, lmax);
  if (lmax == 0.0 && !(lerr == 0.0))
    fail_msg("%s: d lambda / d de is %g where lambda does not move", what, lerr);
  const double rel = err / dmax;
  print_message("# tangent vs FD, %s: rel err %.2e (max |D| %.4g)\n", what, rel, dmax);
  if (!(rel < 1e-5))
    fail_msg("%s: tangent vs central differences: rel err %.3g (max |D| %g)", what, rel, dmax);
  return rel;
}

/* Elastic: D = C (from E and nu) exactly, symmetric, and FD agrees; also model NONE. */
static void test_mpm_decohesion_tangent_elastic(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const double E = 1024.0, nu = 0.25;
  const double alphas[] = {90.0, 60.0, 0.0};
  for (size_t ia = 0; ia < 3; ia++) {
    const mpm_material m = make_mat(MPM_DCOH_MODEL1, alphas[ia], 1.0, 2.0, 1.0, 1.0);
    const mpm_dstate in = nt_state(alphas[ia], 0.3, -0.5, 0.2, 0.1, 0.01, 0.0, 0);
    const double de[3] = {1e-4, -2e-4, 5e-5};
    fd_check(&m, &in, de, MPM_DPATH_ELASTIC, "elastic", w);
    double D[3][3];
    assert_int_equal(mpm_dcoh_tangent(&m, &in, de, D, NULL, w), MPM_OK);
    for (int j = 0; j < 3; j++) {
      double e[3] = {0.0, 0.0, 0.0}, c[3];
      e[j] = 1.0;
      C_apply(E, nu, e, c);
      for (int i = 0; i < 3; i++)
        assert_rel(D[i][j], c[i], 1e-14, "elastic D = C");
    }
  }
  const mpm_material m0 = make_mat(MPM_DCOH_NONE, 60.0, 1.0, 2.0, 1.0, 1.0);
  const mpm_dstate z = zero_state();
  const double big[3] = {0.01, 0.0, 0.003};
  fd_check(&m0, &z, big, MPM_DPATH_ELASTIC, "model NONE", w);
  mpm_dwork_free(w);
}

/* Sanity: the elastic D is symmetric (plane-stress C with tensor shear). */
static void test_mpm_decohesion_tangent_elastic_symmetric(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const mpm_material m = make_mat(MPM_DCOH_MODEL2, 30.0, 1.0, 2.0, 1.0, 0.8);
  const mpm_dstate in = zero_state();
  const double de[3] = {2e-4, 1e-4, -1e-4};
  double D[3][3];
  assert_int_equal(mpm_dcoh_tangent(&m, &in, de, D, NULL, w), MPM_OK);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < i; j++)
      assert_true(D[i][j] == D[j][i]);
  mpm_dwork_free(w);
}

/*
 * Softening (mixed loading, alpha 60, snf 1, stf 2): Model 1 and Model 2, q = 1, 0.8, 1.2,
 * eta/dt = 0 and 5, from a particle on the softening branch (lambda about 0.3; 0.04 for
 * Model 2) with a
 * mixed increment, and from a particle at rest with one large increment that crosses
 * from elastic into softening (a static load step).
 */
static void test_mpm_decohesion_tangent_softening(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const int models[] = {MPM_DCOH_MODEL1, MPM_DCOH_MODEL2};
  const double qs[] = {1.0, 0.8, 1.2}, viscs[] = {0.0, 5.0};
  for (int im = 0; im < 2; im++)
    for (int iq = 0; iq < 3; iq++)
      for (int iv = 0; iv < 2; iv++) {
        mpm_material m = make_mat(models[im], 60.0, 1.0, 2.0, 1.0, qs[iq]);
        m.visc = viscs[iv];
        char what[120];
        /* on the branch: small mixed increment */
        const double de0[3] = {2e-5, -0.25 * 2e-5, 0.0};
        /* Model 2 keeps the shear (eq. 26): on this path no root exists past lambda
         * about 0.09 and it separates there */
        const double lam_at = models[im] == MPM_DCOH_MODEL2 ? 0.04 : 0.3;
        const mpm_dstate in = soften_to(&m, de0, lam_at, w);
        assert_true(in.lam >= lam_at);
        const double de[3] = {3e-5, -1e-5, 1e-5};
        snprintf(what, sizeof what, "softening, model %d q %g visc %g", models[im], qs[iq], viscs[iv]);
        fd_check(&m, &in, de, MPM_DPATH_SOFTEN, what, w);
        /* from rest, one large step: the trial is 1.3 x past initiation (se = 1 at
         * de = 1.3^-1 of it), the start elastic */
        const mpm_dstate z = zero_state();
        const double a = 60.0 * PI / 180.0, nx = sin(a), ny = -cos(a), tx = cos(a), ty = sin(a);
        /* target traction se = 1.3 at lambda 0: sn/snf = 1.3 x 0.8, st/stf = 1.3 x 0.6; for
         * Model 2, whose shear never relaxes (no root once st/stf > 1 - lambda), st/stf = 0.3 */
        const double sn = models[im] == MPM_DCOH_MODEL2 ? sqrt(1.3 * 1.3 - 0.09) : 1.3 * 0.8;
        const double st = models[im] == MPM_DCOH_MODEL2 ? 0.3 * 2.0 : 1.3 * 0.6 * 2.0;
        const double sig[3] = {sn * nx * nx + 2.0 * st * nx * tx, sn * ny * ny + 2.0 * st * ny * ty,
                               sn * nx * ny + st * (nx * ty + ny * tx)};
        const double E = 1024.0, nu = 0.25, G = E / (2.0 * (1.0 + nu));
        const double big[3] = {(sig[0] - nu * sig[1]) / E, (sig[1] - nu * sig[0]) / E, sig[2] / (2.0 * G)};
        assert_true(mpm_dcoh_F(&m, z.sxx, z.syy, z.sxy, z.lam) < 0.0);
        snprintf(what, sizeof what, "large step from rest, model %d q %g visc %g", models[im], qs[iq], viscs[iv]);
        fd_check(&m, &z, big, MPM_DPATH_SOFTEN, what, w);
        /* from an elastic state on the unloaded branch (lambda 0.3, F < 0) */
        const mpm_dstate un = nt_state(60.0, 0.2, 0.1, 0.3, 0.3, 0.05, 0.02, 0);
        assert_true(mpm_dcoh_F(&m, un.sxx, un.syy, un.sxy, un.lam) < 0.0);
        snprintf(what, sizeof what, "large step from unloaded, model %d q %g visc %g", models[im], qs[iq],
                 viscs[iv]);
        fd_check(&m, &un, big, MPM_DPATH_SOFTEN, what, w);
        /* Model 1 without overstress: the step along the direction frozen at the trial
         * carries s_nn past 0 (a tensile trial ends in compression), where <sn> leaves se
         * to the shear alone; the tangent there reaches 5 E1 in size */
        mpm_dstate o;
        mpm_dinfo info;
        assert_int_equal(mpm_dcoh_update(&m, &un, big, &o, &info, w), MPM_OK);
        double sn_o, st_o;
        traction(60.0, o.sxx, o.syy, o.sxy, &sn_o, &st_o);
        print_message("#   s_nn after it: %.4g\n", sn_o);
        if (models[im] == MPM_DCOH_MODEL1 && viscs[iv] == 0.0)
          assert_true(sn_o < 0.0);
      }
  mpm_dwork_free(w);
}

/*
 * Mode I closed form, alpha 90 (n = x, t = y), Model 1, q 1, eta 0, no shear.  With one
 * traction component the flow direction is constant, m* = (s0/snf) n, so the step is
 * linear: s_nn = sn_tr - B dl with B = E1 (ubar0/Le)(s0/snf) (eqs. 39-41), and F = 0
 * (eq. 23) gives (sn_tr - B dl)/snf = 1 - lambda - dl, i.e. dl = (sn_tr - snf(1 - lambda))
 * / (B - snf).  With sn_tr = sxx_in + E1 dexx + E2 deyy and s_tt = s_tt_tr - (E2/E1) B dl:
 *   d sxx/d dexx = -E1 snf/(B - snf)   (uniaxial strain in n: the band's softening slope)
 *   d sxx/d deyy = d syy/d dexx = -E2 snf/(B - snf)
 *   d syy/d deyy = E1 - (E2^2/E1) B/(B - snf)
 * and along de = (1, -nu, 0) (drive_opening's path) d sxx = -E snf/(B - snf) per unit dexx.
 */
static void test_mpm_decohesion_tangent_mode1_closed_form(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const double E = 1024.0, nu = 0.25, E1 = E / (1.0 - nu * nu), E2 = nu * E1, snf = 1.0;
  const mpm_material m = make_mat(MPM_DCOH_MODEL1, 90.0, snf, 10.0, 1.0, 1.0);
  const double B = E1 * (0.375 / LE) * (1.0 / snf); /* 51.2 */
  const double de0[3] = {1e-4, -nu * 1e-4, 0.0};
  const mpm_dstate in = soften_to(&m, de0, 0.3, w);
  const double de[3] = {1e-5, 0.0, 0.0};
  fd_check(&m, &in, de, MPM_DPATH_SOFTEN, "Mode I, alpha 90", w);
  double D[3][3];
  assert_int_equal(mpm_dcoh_tangent(&m, &in, de, D, NULL, w), MPM_OK);
  assert_rel(D[0][0], -E1 * snf / (B - snf), 1e-10, "Mode I: d sxx / d dexx = -E1 snf / (B - snf)");
  assert_rel(D[0][1], -E2 * snf / (B - snf), 1e-10, "Mode I: d sxx / d deyy");
  assert_rel(D[1][0], -E2 * snf / (B - snf), 1e-10, "Mode I: d syy / d dexx");
  assert_rel(D[1][1], E1 - E2 * E2 / E1 * B / (B - snf), 1e-10, "Mode I: d syy / d deyy");
  assert_rel(D[0][0] - nu * D[0][1], -E * snf / (B - snf), 1e-10, "Mode I: slope along (1, -nu, 0)");
  mpm_dwork_free(w);
}

/*
 * Separation (eqs. 56-58): the separating step (lambda about 0.9 on the branch, then
 * an increment that takes it past the threshold), a separated particle opening further,
 * and a separated particle in compression both while its opening closes and once
 * contact engages (the closing stops at shut and s_nn follows the trial).
 */
static void test_mpm_decohesion_tangent_separation(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const double alphas[] = {60.0, 90.0};
  for (int ia = 0; ia < 2; ia++) {
    const double alpha = alphas[ia];
    const mpm_material m = make_mat(MPM_DCOH_MODEL1, alpha, 1.0, 2.0, 1.0, 1.0);
    char what[120];
    const double de0[3] = {2e-5, -0.25 * 2e-5, 0.0};
    const mpm_dstate in = soften_to(&m, de0, 0.9, w);
    const double de[3] = {2e-3, -5e-4, 4e-4};
    snprintf(what, sizeof what, "separating step, alpha %g", alpha);
    fd_check(&m, &in, de, MPM_DPATH_SEPARATE, what, w);
    /* separated, opening */
    const mpm_dstate open = nt_state(alpha, 0.0, 0.4, 0.0, 1.1, 0.3, 0.05, 1);
    const double dt[3] = {1e-4, -2e-5, 3e-5};
    snprintf(what, sizeof what, "separated, opening, alpha %g", alpha);
    fd_check(&m, &open, dt, MPM_DPATH_OPEN, what, w);
    /* separated, compressed, the opening not yet shut: s_nn stays 0 */
    const double dc[3] = {-1e-4, 2e-5, 5e-5};
    mpm_dstate o;
    mpm_dinfo info;
    snprintf(what, sizeof what, "separated, closing, alpha %g", alpha);
    fd_check(&m, &open, dc, MPM_DPATH_OPEN, what, w);
    assert_int_equal(mpm_dcoh_update(&m, &open, dc, &o, &info, w), MPM_OK);
    assert_true(o.upn > 0.0 && o.upn < open.upn);
    /* separated and shut (upn 0), compressed: contact */
    const mpm_dstate shut = nt_state(alpha, -0.5, 0.4, 0.0, 1.1, 0.0, 0.05, 1);
    snprintf(what, sizeof what, "separated, contact, alpha %g", alpha);
    fd_check(&m, &shut, dc, MPM_DPATH_OPEN, what, w);
    assert_int_equal(mpm_dcoh_update(&m, &shut, dc, &o, &info, w), MPM_OK);
    assert_true(o.upn == 0.0);
    /* a nearly shut opening that a large compressive step closes: contact too */
    const mpm_dstate near = nt_state(alpha, 0.0, 0.4, 0.0, 1.1, 1e-3, 0.05, 1);
    const double dbig[3] = {-2e-3, 4e-4, 1e-3};
    snprintf(what, sizeof what, "separated, closes into contact, alpha %g", alpha);
    fd_check(&m, &near, dbig, MPM_DPATH_OPEN, what, w);
    assert_int_equal(mpm_dcoh_update(&m, &near, dbig, &o, &info, w), MPM_OK);
    assert_true(o.upn == 0.0);
  }
  mpm_dwork_free(w);
}

/*
 * decohesion.reversed_shear = closing: a part-softened particle with slip upt > 0 under
 * normal tension and reversed shear (s_nt < 0): the shear leaves eq. 23 and stays
 * elastic while the normal traction softens.  The same state under the paper's rule
 * (even) softens in both components.
 */
static void test_mpm_decohesion_tangent_closing(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const double E = 1024.0, nu = 0.25, G = E / (2.0 * (1.0 + nu));
  const int models[] = {MPM_DCOH_MODEL1, MPM_DCOH_MODEL2};
  for (int im = 0; im < 2; im++)
    for (int rule = MPM_SHEAR_EVEN; rule <= MPM_SHEAR_CLOSING; rule++) {
      mpm_scene sc = tu_scene(models[im], 60.0, 1.0, 2.0, 1.0, 1.0);
      sc.reversed_shear = rule;
      mpm_material m;
      mpm_material_init(&m, &sc, 1.0, LE);
      const mpm_dstate in = nt_state(60.0, 0.6, 0.2, -0.5, 0.3, 0.05, 0.04, 0);
      /* push s_nn past the strength 0.7, keep s_nt < 0 */
      const double de[3] = {2e-4, -5e-5, 1e-5};
      char what[120];
      snprintf(what, sizeof what, "reversed shear %s, model %d", rule == MPM_SHEAR_CLOSING ? "closing" : "even",
               models[im]);
      fd_check(&m, &in, de, MPM_DPATH_SOFTEN, what, w);
      mpm_dstate o;
      mpm_dinfo info;
      assert_int_equal(mpm_dcoh_update(&m, &in, de, &o, &info, w), MPM_OK);
      double sn, st, sn0, st0;
      traction(60.0, o.sxx, o.syy, o.sxy, &sn, &st);
      traction(60.0, in.sxx, in.syy, in.sxy, &sn0, &st0);
      const double a = 60.0 * PI / 180.0, dent = de[0] * sin(a) * cos(a) + de[1] * (-cos(a)) * sin(a) +
                                                 de[2] * (sin(a) * sin(a) - cos(a) * cos(a));
      assert_true(st < 0.0);
      if (rule == MPM_SHEAR_CLOSING) {
        assert_abs(st, st0 + 2.0 * G * dent, 1e-10, "closing: s_nt elastic");
        assert_true(o.upt == in.upt);
      } else if (models[im] == MPM_DCOH_MODEL1) {
        assert_true(o.upt < in.upt); /* even: the slip runs back */
      }
    }
  mpm_dwork_free(w);
}

/*
 * Shear under normal compression (alpha 60, stf 2, lambda 0.3): the Macaulay bracket
 * (eq. 23 with <sn>) leaves s_nn out of se and of the flow direction, so Model 1 softens
 * in shear alone and s_nn follows the trial; Model 2 (eq. 26, flow along n only) has no
 * root and separates in its step, in contact (the small opening shuts).
 */
static void test_mpm_decohesion_tangent_compression(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  const double a = 60.0 * PI / 180.0, nx = sin(a), ny = -cos(a), tx = cos(a), ty = sin(a);
  /* e_nt = 2e-4 (s_nt 1.3 -> 1.46, past stf (1 - lambda) = 1.4) and e_nn = -5e-5 */
  const double ent = 2e-4, enn = -5e-5;
  const double de[3] = {enn * nx * nx + 2.0 * ent * nx * tx, enn * ny * ny + 2.0 * ent * ny * ty,
                        enn * nx * ny + ent * (nx * ty + ny * tx)};
  const mpm_dstate in = nt_state(60.0, -0.3, 0.1, 1.3, 0.3, 1e-3, 0.1, 0);
  const mpm_material m1 = make_mat(MPM_DCOH_MODEL1, 60.0, 1.0, 2.0, 1.0, 1.0);
  fd_check(&m1, &in, de, MPM_DPATH_SOFTEN, "shear softening under compression, model 1", w);
  mpm_dstate o;
  mpm_dinfo info;
  assert_int_equal(mpm_dcoh_update(&m1, &in, de, &o, &info, w), MPM_OK);
  double sn, st, sn_tr, st_tr;
  double dsig[3];
  C_apply(1024.0, 0.25, de, dsig);
  traction(60.0, o.sxx, o.syy, o.sxy, &sn, &st);
  traction(60.0, in.sxx + dsig[0], in.syy + dsig[1], in.sxy + dsig[2], &sn_tr, &st_tr);
  assert_true(sn_tr < 0.0 && o.lam > in.lam);
  assert_abs(sn, sn_tr, 1e-12, "<sn> = 0: s_nn follows the trial");
  const mpm_material m2 = make_mat(MPM_DCOH_MODEL2, 60.0, 1.0, 2.0, 1.0, 1.0);
  fd_check(&m2, &in, de, MPM_DPATH_SEPARATE, "separating step in contact, model 2", w);
  assert_int_equal(mpm_dcoh_update(&m2, &in, de, &o, &info, w), MPM_OK);
  assert_true(o.upn == 0.0);
  mpm_dwork_free(w);
}

/* The batch softening step (mpm_dcoh_soften_batch, the explicit gather's) against the
 * scalar update, on states on their strength surface pushed outward (softening), pulled
 * back (elastic), separated and non-finite, for both models, three planes, with and
 * without reversed-shear closing: where the batch takes a particle its state and
 * traction work equal mpm_dcoh_update's bit for bit on a softening path of one Newton
 * iterate; elsewhere the state is untouched, and the batch takes most softening ones. */
static void test_mpm_decohesion_soften_batch(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  assert_non_null(w);
  static double st[6][MPM_DEFER], de[3][MPM_DEFER], wb[MPM_DEFER];
  static unsigned char sep[MPM_DEFER], ok[MPM_DEFER];
  static mpm_dstate in[MPM_DEFER];
  const int models[] = {MPM_DCOH_MODEL1, MPM_DCOH_MODEL2};
  const double alphas[] = {90.0, 60.0, 30.0};
  long taken = 0, soft = 0;
  unsigned seed = 12345u;
  for (int im = 0; im < 2; im++)
    for (int ia = 0; ia < 3; ia++)
      for (int closing = 0; closing < 2; closing++) {
        mpm_scene sc = tu_scene(models[im], alphas[ia], 1.0, 2.0, 1.0, 1.0);
        sc.reversed_shear = closing ? MPM_SHEAR_CLOSING : MPM_SHEAR_EVEN;
        mpm_material m;
        mpm_material_init(&m, &sc, 1.0, LE);
        const size_t n = MPM_DEFER - 3; /* not a multiple of 8: the last lanes unused */
        for (size_t i = 0; i < n; i++) {
          seed = seed * 1103515245u + 12345u;
          const double u1 = (double)(seed >> 8) / 16777216.0;
          seed = seed * 1103515245u + 12345u;
          const double u2 = (double)(seed >> 8) / 16777216.0;
          const double lam = 0.9 * u1, th = PI * (u2 - 0.5) / 2.0, r = 1.0 - lam;
          const double snn = r * cos(th), snt = 2.0 * r * sin(th);
          in[i] = nt_state(alphas[ia], snn, 0.3 * snn, snt, lam, 0.01 * u2, -0.01 * u1, i % 17 == 5);
          const double g = (i % 5 == 3 ? -1e-10 : 1e-10) * (0.5 + u1); /* i % 5 == 3: unloading */
          const double nx = sin(alphas[ia] * PI / 180.0), ny = -cos(alphas[ia] * PI / 180.0);
          const double d3[3] = {g * nx * nx + 0.3 * g * u2, g * ny * ny, g * nx * ny - 0.2 * g * u1};
          if (i % 31 == 7)
            in[i].upn = NAN;
          const double v[6] = {in[i].sxx, in[i].syy, in[i].sxy, in[i].lam, in[i].upn, in[i].upt};
          for (int c = 0; c < 6; c++)
            st[c][i] = v[c];
          for (int c = 0; c < 3; c++)
            de[c][i] = d3[c];
          sep[i] = (unsigned char)in[i].sep;
        }
        double *const sp[6] = {st[0], st[1], st[2], st[3], st[4], st[5]};
        const double *const dp[3] = {de[0], de[1], de[2]};
        mpm_dcoh_soften_batch(&m, n, sp, sep, dp, wb, ok);
        for (size_t i = 0; i < n; i++) {
          const double d3[3] = {de[0][i], de[1][i], de[2][i]};
          mpm_dstate o;
          mpm_dinfo info;
          const mpm_status rc = mpm_dcoh_update(&m, &in[i], d3, &o, &info, w);
          const int one = rc == MPM_OK && info.path == MPM_DPATH_SOFTEN && info.iters == 1 && !info.bracketed;
          soft += one;
          mpm_dstate b = in[i];
          b.sxx = st[0][i], b.syy = st[1][i], b.sxy = st[2][i], b.lam = st[3][i], b.upn = st[4][i];
          b.upt = st[5][i];
          if (ok[i]) {
            taken++;
            assert_true(one);
            assert_same_state(&b, &o, "batch against mpm_dcoh_update");
            assert_memory_equal(&wb[i], &info.w, sizeof(double));
          } else {
            const double fa[6] = {b.sxx, b.syy, b.sxy, b.lam, b.upn, b.upt};
            const double fi[6] = {in[i].sxx, in[i].syy, in[i].sxy, in[i].lam, in[i].upn, in[i].upt};
            assert_memory_equal(fa, fi, sizeof fa); /* untouched */
          }
        }
      }
  print_message("# batch: %ld of %ld softening one-iterate updates taken\n", taken, soft);
  assert_true(soft > 1000);
  assert_true(taken > soft * 9 / 10);
  mpm_dwork_free(w);
}

/* The callers' elastic test (mpm_dcoh_trial_inside: the explicit gather's and the
 * static evaluation's) and the update with its tangent in one run
 * (mpm_dcoh_update_tangent), against mpm_dcoh_update and mpm_dcoh_tangent, on states
 * at their strength surface (lambda 0 to 0.9, q 1 and 2, both models, three planes,
 * closing shear, separated) moved by increments from 1e-12 to 1e-6 out and in: where
 * the test passes the update is elastic, and it passes on the states pulled back by
 * more than its margin; the joint run gives both functions' bits.  (The trial here
 * rounds as this file is compiled, without the kernel's FMA contraction: the runs'
 * byte-identical outputs hold the kernel's callers to the update's bits.) */
static void test_mpm_decohesion_trial_and_joint_tangent(void **state)
{
  (void)state;
  mpm_dwork *w = mpm_dwork_alloc();
  assert_non_null(w);
  const int models[] = {MPM_DCOH_MODEL1, MPM_DCOH_MODEL2};
  const double alphas[] = {90.0, 60.0, 30.0}, qs[] = {1.0, 2.0};
  long inside = 0, back = 0, missed = 0, soft = 0;
  unsigned seed = 4242u;
  for (int im = 0; im < 2; im++)
    for (int ia = 0; ia < 3; ia++)
      for (int iq = 0; iq < 2; iq++)
        for (int closing = 0; closing < 2; closing++) {
          mpm_scene sc = tu_scene(models[im], alphas[ia], 1.0, 2.0, 1.0, qs[iq]);
          sc.reversed_shear = closing ? MPM_SHEAR_CLOSING : MPM_SHEAR_EVEN;
          mpm_material m;
          mpm_material_init(&m, &sc, 1.0, LE);
          for (int i = 0; i < 400; i++) {
            seed = seed * 1103515245u + 12345u;
            const double u1 = (double)(seed >> 8) / 16777216.0;
            seed = seed * 1103515245u + 12345u;
            const double u2 = (double)(seed >> 8) / 16777216.0;
            const double lam = 0.9 * u1, th = PI * (u2 - 0.5) / 2.0, r = 1.0 - pow(lam, qs[iq]);
            const double snn = r * cos(th), snt = 2.0 * r * sin(th);
            const mpm_dstate in = nt_state(alphas[ia], snn, 0.3 * snn, snt, lam, 0.01 * u2, -0.01 * u1, i % 23 == 5);
            const double g = (i % 2 ? -1.0 : 1.0) * pow(10.0, -12.0 + 6.0 * u2) * (0.5 + u1);
            const double nx = sin(alphas[ia] * PI / 180.0), ny = -cos(alphas[ia] * PI / 180.0);
            const double de[3] = {g * nx * nx + 0.3 * g * u2, g * ny * ny, g * nx * ny - 0.2 * g * u1};
            mpm_dstate o, oj;
            mpm_dinfo info, ij;
            double D[3][3], L[3], Dj[3][3], Lj[3], t[3];
            const mpm_status rc = mpm_dcoh_update(&m, &in, de, &o, &info, w);
            assert_int_equal(rc, MPM_OK);
            mpm_dcoh_trial(&m, in.sxx, in.syy, in.sxy, de[0], de[1], de[2], &t[0], &t[1], &t[2]);
            const int pass = mpm_dcoh_trial_inside(&m, t, mpm_dcoh_str2(&m, in.lam, in.sep));
            if (pass) {
              inside++;
              assert_int_equal(info.path, MPM_DPATH_ELASTIC);
            }
            if (info.path == MPM_DPATH_ELASTIC && g < -1e-9) {
              back++;
              missed += !pass;
            }
            soft += info.path == MPM_DPATH_SOFTEN;
            assert_int_equal(mpm_dcoh_tangent(&m, &in, de, D, L, w), rc);
            assert_int_equal(mpm_dcoh_update_tangent(&m, &in, de, &oj, &ij, Dj, Lj, w), rc);
            assert_same_state(&oj, &o, "joint update against mpm_dcoh_update");
            assert_int_equal(ij.path, info.path);
            assert_memory_equal(&ij.w, &info.w, sizeof(double));
            assert_memory_equal(Dj, D, sizeof D);
            assert_memory_equal(Lj, L, sizeof L);
          }
        }
  print_message("# trial: %ld inside, %ld pulled back by more than 1e-9 (%ld of them not inside), %ld softening\n",
                inside, back, missed, soft);
  assert_true(soft > 1000);
  assert_true(back > 1000);
  assert_true(missed * 20 < back);
  mpm_dwork_free(w);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_decohesion_elastic_below_initiation),
      cmocka_unit_test(test_mpm_decohesion_opening_q1),
      cmocka_unit_test(test_mpm_decohesion_viscous_overstress),
      cmocka_unit_test(test_mpm_decohesion_opening_q_range),
      cmocka_unit_test(test_mpm_decohesion_shear),
      cmocka_unit_test(test_mpm_decohesion_reversed_shear),
      cmocka_unit_test(test_mpm_decohesion_mixed_model1),
      cmocka_unit_test(test_mpm_decohesion_model2_normal_only),
      cmocka_unit_test(test_mpm_decohesion_compression_never_initiates),
      cmocka_unit_test(test_mpm_decohesion_separated_contact),
      cmocka_unit_test(test_mpm_decohesion_pure_function),
      cmocka_unit_test(test_mpm_decohesion_not_finite),
      cmocka_unit_test(test_mpm_decohesion_not_finite_default_gsl_handler),
      cmocka_unit_test(test_mpm_decohesion_tangent_elastic),
      cmocka_unit_test(test_mpm_decohesion_tangent_elastic_symmetric),
      cmocka_unit_test(test_mpm_decohesion_tangent_softening),
      cmocka_unit_test(test_mpm_decohesion_tangent_mode1_closed_form),
      cmocka_unit_test(test_mpm_decohesion_tangent_separation),
      cmocka_unit_test(test_mpm_decohesion_tangent_closing),
      cmocka_unit_test(test_mpm_decohesion_tangent_compression),
      cmocka_unit_test(test_mpm_decohesion_soften_batch),
      cmocka_unit_test(test_mpm_decohesion_trial_and_joint_tangent),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
