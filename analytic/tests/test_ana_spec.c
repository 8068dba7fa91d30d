/*
 * test_ana_spec.c - the specimens' references (analytic/ana_spec.c, ana_spec_czm.c)
 * against values that do not come from the code under test: the law integrated from its
 * flow rule, hand-computed beam values, dC/da by finite differences, Kanninen's classic
 * semi-infinite form, the elastic BVP against the closed forms, the cohesive reference's
 * brittle limit, its energy balance and its convergence under mesh halving.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "ana_spec.h"

static int near(double got, double want, double rel)
{
  return fabs(got - want) <= rel * fabs(want);
}

#define CHECK_REL(got, want, rel, what)                                                                          \
  do {                                                                                                       \
    const double g_ = (got), w_ = (want);                                                                    \
    if (!near(g_, w_, (rel)))                                                                                \
      fail_msg("%s: %.12g, want %.12g (rel %.2e > %.1e)", what, g_, w_, fabs(g_ / w_ - 1.0), (double)(rel)); \
  } while (0)

static ana_spec spec(int kind, double snf)
{
  ana_spec_params p;
  ana_spec_default(kind, &p);
  if (snf > 0.0)
    p.snf = snf;
  ana_spec s;
  char err[200];
  if (ana_spec_init(&p, &s, err, sizeof err) != ANA_OK)
    fail_msg("ana_spec_init: %s", err);
  return s;
}

static ana_czm_path trace(const ana_spec *s, int beam, int cells, double tip_end)
{
  const ana_czm_opts o = {.beam = beam, .cells = cells, .tip_end = tip_end};
  ana_czm_path c;
  char err[200];
  if (ana_dcb_czm_solve(s, &o, &c, err, sizeof err) != ANA_OK)
    fail_msg("ana_dcb_czm_solve: %s", err);
  return c;
}

/* The law in pure opening from its flow rule (docs/model.md sec. 3: d up = d lambda
 * (U0 / s0) m*, m* = (s0 / se)(sn / snf^2) n, sn = snf (1 - lambda)), integrated by the
 * midpoint rule with s0 away from snf: the opening at separation is U0 / snf and the
 * traction's work U0 / 2, whatever s0. */
static void test_ana_spec_law_pure_modes(void **state)
{
  (void)state;
  for (int s0i = 0; s0i < 3; s0i++) {
    ana_spec_params p;
    ana_spec_default(ANA_SPEC_DCB, &p);
    p.s0 = (double[]){0.3, 1.0, 7.0}[s0i];
    p.snf = 1.7;
    p.stf = 0.6;
    ana_spec s;
    assert_int_equal(ana_spec_init(&p, &s, NULL, 0), ANA_OK);
    for (int mode = 0; mode < 2; mode++) {
      const double str = mode == 0 ? p.snf : p.stf;
      double up = 0.0, work = 0.0;
      const int n = 20000;
      for (int k = 0; k < n; k++) {
        const double lam = (k + 0.5) / n, t = str * (1.0 - lam), se = t / str;
        const double m = p.s0 / se * t / (str * str); /* |m*| in the pure mode */
        const double dup = (1.0 / n) * p.U0 / p.s0 * m;
        up += dup;
        work += t * dup;
      }
      CHECK_REL(mode == 0 ? s.wc_I : s.wc_II, up, 1e-12, "opening at separation");
      CHECK_REL(s.Gc, work, 1e-8, "work of the traction");
      CHECK_REL(s.Gc, 0.5 * p.U0, 1e-15, "Gc at q = 1");
    }
  }
}

/* Hand values of the default DCB (E 1024, t 16, a 64, Gc 0.1875): C = 8 64^3 / (1024 16^3)
 * = 0.5, P = sqrt(1024 16^3 0.1875 / 12) / a = 256 / a; with shear 2 a / (5/6 G t),
 * G = 409.6.  ELS: C = (3 64^3 + 192^3) / (2 1024 16^3) = 0.9375. */
static void test_ana_spec_hand_values(void **state)
{
  (void)state;
  const ana_spec d = spec(ANA_SPEC_DCB, 0), e = spec(ANA_SPEC_ELS, 0);
  double C, P, delta;
  assert_int_equal(ana_spec_compliance(&d, ANA_BEAM_SIMPLE, 64.0, &C, NULL), ANA_OK);
  CHECK_REL(C, 0.5, 1e-15, "DCB C(64)");
  for (double a = 64.0; a <= 128.0; a += 32.0) {
    assert_int_equal(ana_spec_lefm_branch(&d, ANA_BEAM_SIMPLE, a, &P, &delta), ANA_OK);
    CHECK_REL(P, 256.0 / a, 1e-14, "DCB branch P");
    CHECK_REL(delta, 0.5 * pow(a / 64.0, 3) * 256.0 / a, 1e-14, "DCB branch delta");
  }
  assert_int_equal(ana_spec_compliance(&d, ANA_BEAM_SHEAR, 64.0, &C, NULL), ANA_OK);
  CHECK_REL(C, 0.5 + 128.0 / (5.0 / 6.0 * 409.6 * 16.0), 1e-14, "DCB C(64) with shear");
  CHECK_REL(d.chi, 0.6544, 2e-4, "Williams' chi at E / G = 2.5");
  assert_int_equal(ana_spec_compliance(&e, ANA_BEAM_SIMPLE, 64.0, &C, NULL), ANA_OK);
  CHECK_REL(C, 0.9375, 1e-15, "ELS C(64)");
  assert_int_equal(ana_spec_lefm_branch(&e, ANA_BEAM_SIMPLE, 128.0, &P, &delta), ANA_OK);
  CHECK_REL(P, 2.0 / 3.0 * sqrt(1024.0 * 4096.0 * 0.1875) / 128.0, 1e-14, "ELS branch P(128)");
}

/* G = P^2 / 2 dC/da against a central difference of C(a), for every theory. */
static void test_ana_spec_G_from_dCda(void **state)
{
  (void)state;
  for (int kind = 0; kind < 2; kind++) {
    const ana_spec s = spec(kind, 0);
    for (int th = 0; th < ANA_BEAM_COUNT; th++) {
      if (kind == ANA_SPEC_ELS && (th == ANA_BEAM_KANNINEN || th == ANA_BEAM_KANNINEN_SHEAR))
        continue;
      for (double a = 40.0; a < 180.0; a += 23.0) {
        const double h = 1e-3, P = 1.7;
        double Cp, Cm, C2p, C2m, G;
        assert_int_equal(ana_spec_compliance(&s, th, a + h, &Cp, NULL), ANA_OK);
        assert_int_equal(ana_spec_compliance(&s, th, a - h, &Cm, NULL), ANA_OK);
        assert_int_equal(ana_spec_compliance(&s, th, a + 2 * h, &C2p, NULL), ANA_OK);
        assert_int_equal(ana_spec_compliance(&s, th, a - 2 * h, &C2m, NULL), ANA_OK);
        const double dC = (8.0 * (Cp - Cm) - (C2p - C2m)) / (12.0 * h);
        assert_int_equal(ana_spec_G(&s, th, a, P, &G), ANA_OK);
        if (!near(G, 0.5 * P * P * dC, 1e-8))
          fail_msg("kind %d theory %d a %g: G %.12g, from dC/da %.12g", kind, th, a, G, 0.5 * P * P * dC);
      }
    }
  }
}

/* Kanninen's (1973) semi-infinite form C = 8 / (E t^3) (a^3 + 3 a^2 / l + 3 a / l^2 +
 * 3 / (2 l^3)), l^4 = 6 / t^4: the finite ligament's form tends to it (a long bar), and at
 * the default bar (beta (L - a) = 12.5) differs by less than 1e-9. */
static void test_ana_spec_kanninen_semi_infinite(void **state)
{
  (void)state;
  for (int longbar = 0; longbar < 2; longbar++) {
    ana_spec_params p;
    ana_spec_default(ANA_SPEC_DCB, &p);
    if (longbar)
      p.L = 2000.0;
    ana_spec s;
    assert_int_equal(ana_spec_init(&p, &s, NULL, 0), ANA_OK);
    const double t = s.t, l = pow(6.0, 0.25) / t, a = 64.0;
    const double want = 8.0 / (p.E * t * t * t) * (a * a * a + 3 * a * a / l + 3 * a / (l * l) + 1.5 / (l * l * l));
    double C;
    assert_int_equal(ana_spec_compliance(&s, ANA_BEAM_KANNINEN, a, &C, NULL), ANA_OK);
    CHECK_REL(C, want, longbar ? 1e-14 : 1e-9, "Kanninen against the semi-infinite form");
  }
  /* a short ligament is softer than the semi-infinite one */
  const ana_spec s = spec(ANA_SPEC_DCB, 0);
  double Cs, Cl;
  assert_int_equal(ana_spec_compliance(&s, ANA_BEAM_KANNINEN, 185.0, &Cs, NULL), ANA_OK);
  const double t = s.t, l = pow(6.0, 0.25) / t, a = 185.0;
  Cl = 8.0 / (1024.0 * t * t * t) * (a * a * a + 3 * a * a / l + 3 * a / (l * l) + 1.5 / (l * l * l));
  assert_true(Cs > Cl * (1.0 + 1e-4));
}

/* The elastic problem (the law never opens) solved as the BVP on meshes of 192 and 384
 * cells: second order, and extrapolated onto Kanninen's closed forms (Euler arm: Hetenyi's
 * finite beam; Timoshenko arm: the two decaying roots of the semi-infinite ligament). */
static void test_ana_spec_kanninen_bvp(void **state)
{
  (void)state;
  const ana_spec s = spec(ANA_SPEC_DCB, 0);
  for (int beam = 0; beam < 2; beam++) {
    double C[2], want;
    for (int m = 0; m < 2; m++) {
      const ana_czm_opts o = {.beam = beam, .cells = 192 << m, .rigid = 1};
      ana_czm_path c;
      assert_int_equal(ana_dcb_czm_solve(&s, &o, &c, NULL, 0), ANA_OK);
      C[m] = c.pt[1].delta / c.pt[1].P;
      ana_czm_path_free(&c);
    }
    assert_int_equal(ana_spec_compliance(&s, beam ? ANA_BEAM_KANNINEN_SHEAR : ANA_BEAM_KANNINEN, s.p.a0, &want, NULL),
                     ANA_OK);
    const double ratio = (C[0] - want) / (C[1] - want), ext = C[1] + (C[1] - C[0]) / 3.0;
    if (!(ratio > 3.9 && ratio < 4.1))
      fail_msg("beam %d: error ratio %.4f under halving, want 4", beam, ratio);
    CHECK_REL(ext, want, 1e-9, beam ? "Timoshenko BVP, extrapolated" : "Euler BVP, extrapolated");
  }
}

/* ELS: delta = C P on the branch is smallest at a = L / 6^(1/3) (simple theory): growth
 * from a shorter crack snaps back under displacement control. */
static void test_ana_spec_els_snapback(void **state)
{
  (void)state;
  const ana_spec s = spec(ANA_SPEC_ELS, 0);
  for (int th = 0; th < 3; th++) {
    double at, P, d0, dm, dp;
    assert_int_equal(ana_els_snapback_end(&s, th, &at), ANA_OK);
    if (th == ANA_BEAM_SIMPLE)
      CHECK_REL(at, 192.0 / cbrt(6.0), 1e-14, "L / 6^(1/3)");
    assert_int_equal(ana_spec_lefm_branch(&s, th, at, &P, &d0), ANA_OK);
    assert_int_equal(ana_spec_lefm_branch(&s, th, at - 1.0, &P, &dm), ANA_OK);
    assert_int_equal(ana_spec_lefm_branch(&s, th, at + 1.0, &P, &dp), ANA_OK);
    if (!(dm > d0 && dp > d0))
      fail_msg("theory %d: delta %.9g %.9g %.9g around a %.4f is not a minimum", th, dm, d0, dp, at);
  }
}

/* A strong, brittle law (snf 1, 2, 4 at the same Gc) tends to Kanninen's LEFM branch:
 * the load at the branch's opening for a = 110 approaches it, the gap falling each time. */
static void test_ana_spec_czm_brittle_limit(void **state)
{
  (void)state;
  for (int beam = 0; beam < 2; beam++) {
    double gap_prev = INFINITY;
    for (double snf = 1.0; snf <= 4.0; snf *= 2.0) {
      const ana_spec s = spec(ANA_SPEC_DCB, snf);
      double P, delta;
      assert_int_equal(
          ana_spec_lefm_branch(&s, beam ? ANA_BEAM_KANNINEN_SHEAR : ANA_BEAM_KANNINEN, 110.0, &P, &delta), ANA_OK);
      ana_czm_path c = trace(&s, beam, 256, 115.0);
      const double gap = fabs(ana_czm_load_at(&c, delta, NULL) / P - 1.0);
      ana_czm_path_free(&c);
      if (!(gap < 0.5 * gap_prev))
        fail_msg("beam %d snf %g: gap to LEFM %.3g, the previous %.3g", beam, snf, gap, gap_prev);
      gap_prev = gap;
    }
    if (!(gap_prev < 1e-4))
      fail_msg("beam %d: at snf 4 the load is %.3g from Kanninen's branch", beam, gap_prev);
  }
}

/* Energy: the work of the load (trapezoid of P d delta along the path) equals the elastic
 * energy plus the law's work at every point; past the peak, the law's work grows by Gc per
 * unit of crack growth (to the zone's slow change: 1e-3 at snf 4). */
static void test_ana_spec_czm_energy(void **state)
{
  (void)state;
  const ana_spec s = spec(ANA_SPEC_DCB, 4.0);
  ana_czm_path c = trace(&s, ANA_CZM_TIMOSHENKO, 256, 150.0);
  double W = 0.0;
  for (int i = 1; i < c.n; i++) {
    W += 0.5 * (c.pt[i].P + c.pt[i - 1].P) * (c.pt[i].delta - c.pt[i - 1].delta);
    const double E = c.pt[i].U_el + c.pt[i].W_law;
    if (c.pt[i].delta > 0.1 * c.peak.delta && !near(W, E, 1e-3))
      fail_msg("delta %.5g: work of the load %.9g, energies %.9g", c.pt[i].delta, W, E);
  }
  int i1 = -1, i2 = -1;
  for (int i = 0; i < c.n; i++) {
    if (i1 < 0 && c.pt[i].tip >= 100.0)
      i1 = i;
    if (i2 < 0 && c.pt[i].tip >= 140.0)
      i2 = i;
  }
  assert_true(i1 > 0 && i2 > i1);
  const double dA = c.pt[i2].tip - c.pt[i1].tip, dW = c.pt[i2].W_law - c.pt[i1].W_law;
  CHECK_REL(dW, s.Gc * dA, 1e-3, "the law's work over the crack growth");
  const double dU = c.pt[i2].U_el - c.pt[i1].U_el;
  double Wseg = 0.0;
  for (int i = i1 + 1; i <= i2; i++)
    Wseg += 0.5 * (c.pt[i].P + c.pt[i - 1].P) * (c.pt[i].delta - c.pt[i - 1].delta);
  CHECK_REL(Wseg, s.Gc * dA + dU, 2e-3, "work past the peak = Gc growth + elastic change");
  ana_czm_path_free(&c);
}

/* The DCB's path: delta rises, the tip never recedes, no node's law closes again (so the
 * law's elastic form is the history's); the peak lies before the tip leaves a0. */
static void test_ana_spec_czm_path(void **state)
{
  (void)state;
  const ana_spec s = spec(ANA_SPEC_DCB, 0);
  ana_czm_path c = trace(&s, ANA_CZM_EULER, 192, 128.0);
  for (int i = 1; i < c.n; i++) {
    if (!(c.pt[i].delta > c.pt[i - 1].delta) || c.pt[i].tip < c.pt[i - 1].tip)
      fail_msg("point %d: delta %.9g after %.9g, tip %.6g after %.6g", i, c.pt[i].delta, c.pt[i - 1].delta,
               c.pt[i].tip, c.pt[i - 1].tip);
    assert_true(c.pt[i].P <= c.peak.P * (1.0 + 1e-12));
  }
  assert_true(c.unload == 0.0);
  assert_true(c.peak.tip == s.p.a0 && c.peak.front > s.p.a0);
  assert_true(c.pt[c.n - 1].tip >= 128.0);
  ana_czm_path_free(&c);
}

/* Halving the mesh (128, 256, 512 cells): the peak load converges at second order, the
 * finest mesh is within 1e-5 of Richardson's value, and that value within 1e-6 of the
 * value extrapolated from 256, 512 and 1024 cells. */
static void test_ana_spec_czm_converges(void **state)
{
  (void)state;
  const ana_spec s = spec(ANA_SPEC_DCB, 0);
  ana_czm_opts o = {.beam = ANA_CZM_EULER, .cells = 128, .tip_end = 90.0};
  ana_czm_conv cv, fine;
  char err[200];
  if (ana_dcb_czm_converge(&s, &o, &cv, err, sizeof err) != ANA_OK)
    fail_msg("converge: %s", err);
  if (!(cv.order > 1.8 && cv.order < 2.2))
    fail_msg("observed order %.3f (peaks %.10g %.10g %.10g)", cv.order, cv.P[0], cv.P[1], cv.P[2]);
  assert_true(cv.P_err < 1e-5 && cv.delta_err < 1e-4);
  o.cells = 256;
  if (ana_dcb_czm_converge(&s, &o, &fine, err, sizeof err) != ANA_OK)
    fail_msg("converge: %s", err);
  CHECK_REL(cv.P_ext, fine.P_ext, 1e-6, "extrapolated peak load, coarse against fine");
  CHECK_REL(cv.delta_ext, fine.delta_ext, 1e-5, "extrapolated delta at the peak, coarse against fine");
  /* below the LEFM branch at a0 and above it where the zone's length is added */
  double P, delta;
  assert_int_equal(ana_spec_lefm_branch(&s, ANA_BEAM_KANNINEN_SHEAR, s.p.a0, &P, &delta), ANA_OK);
  assert_true(cv.P_ext < P);
}

static void test_ana_spec_refuses(void **state)
{
  (void)state;
  ana_spec_params p;
  ana_spec s;
  char err[200];
  ana_spec_default(ANA_SPEC_DCB, &p);
  const double bad[][3] = {{0, -1.0, 0}, {1, 0.6, 0}, {2, 192.0, 0}, {3, NAN, 0}, {4, 0.0, 0}};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    ana_spec_params b = p;
    const int k = (int)bad[i][0];
    if (k == 0)
      b.E = bad[i][1];
    else if (k == 1)
      b.nu = bad[i][1];
    else if (k == 2)
      b.a0 = bad[i][1];
    else if (k == 3)
      b.U0 = bad[i][1];
    else
      b.q = bad[i][1];
    assert_int_equal(ana_spec_init(&b, &s, err, sizeof err), ANA_EINVAL);
  }
  p.kind = 7;
  assert_int_equal(ana_spec_init(&p, &s, err, sizeof err), ANA_EINVAL);
  const ana_spec d = spec(ANA_SPEC_DCB, 0), e = spec(ANA_SPEC_ELS, 0);
  double C, at;
  assert_int_equal(ana_spec_compliance(&d, ANA_BEAM_SIMPLE, 0.0, &C, NULL), ANA_EINVAL);
  assert_int_equal(ana_spec_compliance(&d, ANA_BEAM_SIMPLE, 192.0, &C, NULL), ANA_EINVAL);
  assert_int_equal(ana_spec_compliance(&d, ANA_BEAM_COUNT, 64.0, &C, NULL), ANA_EINVAL);
  assert_int_equal(ana_spec_compliance(&e, ANA_BEAM_KANNINEN, 64.0, &C, NULL), ANA_EINVAL);
  assert_int_equal(ana_els_snapback_end(&d, ANA_BEAM_SIMPLE, &at), ANA_EINVAL);
  ana_czm_path c;
  const ana_czm_opts ok = {.beam = ANA_CZM_EULER, .cells = 64, .tip_end = 100.0};
  assert_int_equal(ana_dcb_czm_solve(&e, &ok, &c, err, sizeof err), ANA_EINVAL);
  ana_czm_opts o = ok;
  o.cells = 8;
  assert_int_equal(ana_dcb_czm_solve(&d, &o, &c, err, sizeof err), ANA_EINVAL);
  o = ok;
  o.tip_end = 200.0;
  assert_int_equal(ana_dcb_czm_solve(&d, &o, &c, err, sizeof err), ANA_EINVAL);
  o = ok;
  o.beam = 5;
  assert_int_equal(ana_dcb_czm_solve(&d, &o, &c, err, sizeof err), ANA_EINVAL);
  const ana_spec steep = spec(ANA_SPEC_DCB, 8.0); /* kf U0 / snf = 6 < 2 snf */
  assert_int_equal(ana_dcb_czm_solve(&steep, &ok, &c, err, sizeof err), ANA_EINVAL);
  ana_spec_default(ANA_SPEC_DCB, &p);
  p.q = 0.8;
  assert_int_equal(ana_spec_init(&p, &s, err, sizeof err), ANA_OK);
  assert_int_equal(ana_dcb_czm_solve(&s, &ok, &c, err, sizeof err), ANA_EINVAL);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ana_spec_law_pure_modes),
      cmocka_unit_test(test_ana_spec_hand_values),
      cmocka_unit_test(test_ana_spec_G_from_dCda),
      cmocka_unit_test(test_ana_spec_kanninen_semi_infinite),
      cmocka_unit_test(test_ana_spec_kanninen_bvp),
      cmocka_unit_test(test_ana_spec_els_snapback),
      cmocka_unit_test(test_ana_spec_czm_brittle_limit),
      cmocka_unit_test(test_ana_spec_czm_energy),
      cmocka_unit_test(test_ana_spec_czm_path),
      cmocka_unit_test(test_ana_spec_czm_converges),
      cmocka_unit_test(test_ana_spec_refuses),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
