/*
 * test_ana_stab.c - the linearised 1-D step (analytic/ana_stab.c) against what a step
 * must do whatever its scheme: a rest state without a force is neutral (the largest
 * eigenvalue modulus is 1: the rigid drift and the transfer's null space), and the rate
 * of a mode fed by the prestress scales with it.  Then the finding docs/methods.md
 * rests on: MUSL with uGIMP grows once the boxes straddle a node under a prestress, and
 * neither USL nor bilinear shapes do.
 *
 * "Neutral" is |rate| < 1e-5 per unit time (1.25e-7 a step at dt 0.0125): the defective
 * eigenvalue 1 of the drift modes is found to about sqrt(machine epsilon), 1e-8 a step.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ana.h"

#define NEUTRAL 1e-5

/* the Fig. 6 bar's material at h 1 with the scene's time step there (dt 0.1 at h 8, so
 * c dt / h = 0.4), 2 particles a cell along the bar (the 2-D 4 ppc) */
static ana_stab_rates rates_of(int scheme, int shape, int per_cell, double sigma0, double drift)
{
  const ana_stab c = {scheme, shape, per_cell, 12, 1.0, 1024.0, 1.0, sigma0, drift, 0.0125};
  ana_stab_rates r = {NAN, NAN};
  char err[200];
  if (ana_stab_rate(&c, &r, err, sizeof err) != ANA_OK)
    fail_msg("ana_stab_rate: %s", err);
  return r;
}

static double rate_of(int scheme, int shape, int per_cell, double sigma0, double drift)
{
  return rates_of(scheme, shape, per_cell, sigma0, drift).rate;
}

/* ana_stab-1: no stress, no force, whatever moves: every scheme and shape is neutral */
static void test_ana_stab_unstressed_neutral(void **state)
{
  (void)state;
  for (int sch = ANA_STAB_USL; sch <= ANA_STAB_MUSL; sch++)
    for (int sh = ANA_STAB_LINEAR; sh <= ANA_STAB_GIMP; sh++)
      for (int n = 1; n <= 2; n++) {
        const double r = rate_of(sch, sh, n, 0.0, 0.05);
        print_message("# ana_stab-1 scheme %d shape %d per_cell %d: rate %.3e\n", sch, sh, n, r);
        assert_true(fabs(r) < NEUTRAL);
      }
}

/* ana_stab-2: the particles where the grid was laid (the stretched grid before the peak:
 * every uGIMP box ends on a node), under the peak stress: neutral for both schemes */
static void test_ana_stab_laid_neutral(void **state)
{
  (void)state;
  for (int sch = ANA_STAB_USL; sch <= ANA_STAB_MUSL; sch++)
    for (int n = 1; n <= 2; n++) {
      const double r = rate_of(sch, ANA_STAB_GIMP, n, 1.0, 0.0);
      print_message("# ana_stab-2 scheme %d per_cell %d: rate %.3e\n", sch, n, r);
      assert_true(fabs(r) < NEUTRAL);
    }
}

/* ana_stab-3: drifted under the stress, bilinear shapes (H = 0 inside a cell) and USL
 * with uGIMP stay neutral */
static void test_ana_stab_drift_usl_bilinear_neutral(void **state)
{
  (void)state;
  const double drifts[] = {0.02, 0.05, 0.1};
  for (size_t k = 0; k < sizeof drifts / sizeof *drifts; k++)
    for (int n = 1; n <= 2; n++) {
      const double rl = rate_of(ANA_STAB_MUSL, ANA_STAB_LINEAR, n, 0.8, drifts[k]);
      const double ru = rate_of(ANA_STAB_USL, ANA_STAB_GIMP, n, 0.8, drifts[k]);
      print_message("# ana_stab-3 drift %.2f per_cell %d: MUSL bilinear %.3e, USL uGIMP %.3e\n", drifts[k], n, rl, ru);
      assert_true(fabs(rl) < NEUTRAL);
      assert_true(fabs(ru) < NEUTRAL);
    }
}

/* ana_stab-4: MUSL with uGIMP, drifted under the stress, grows; its rate is the
 * prestress's: linear in sigma0 (twice the stress, twice the rate within 10 %) */
static void test_ana_stab_musl_gimp_grows(void **state)
{
  (void)state;
  for (int n = 1; n <= 2; n++) {
    const double r1 = rate_of(ANA_STAB_MUSL, ANA_STAB_GIMP, n, 0.8, 0.05);
    const double r2 = rate_of(ANA_STAB_MUSL, ANA_STAB_GIMP, n, 1.6, 0.05);
    print_message("# ana_stab-4 per_cell %d: rate %.3e at sigma0 0.8, %.3e at 1.6\n", n, r1, r2);
    assert_true(r1 > 100.0 * NEUTRAL);
    assert_in_range((long)lround(100.0 * r2 / r1), 180, 220);
  }
}

/* ana_stab-5: why one scheme grows and the other not.  Without a prestress MUSL keeps
 * every wave's modulus at 1 (no loss, so no margin against a feed), USL damps them all;
 * with the prestress USL's least damped wave still decays */
static void test_ana_stab_waves(void **state)
{
  (void)state;
  for (int n = 1; n <= 2; n++) {
    const ana_stab_rates m0 = rates_of(ANA_STAB_MUSL, ANA_STAB_GIMP, n, 0.0, 0.05);
    const ana_stab_rates u0 = rates_of(ANA_STAB_USL, ANA_STAB_GIMP, n, 0.0, 0.05);
    const ana_stab_rates u1 = rates_of(ANA_STAB_USL, ANA_STAB_GIMP, n, 0.8, 0.05);
    print_message("# ana_stab-5 per_cell %d: waves MUSL %.3e, USL %.3e, USL at sigma0 0.8 %.3e\n", n, m0.wave,
                  u0.wave, u1.wave);
    assert_true(fabs(m0.wave) < NEUTRAL);
    assert_true(u0.wave < -100.0 * NEUTRAL);
    assert_true(u1.wave < -100.0 * NEUTRAL);
  }
}

/* ana_stab-6: bad input is named, not computed */
static void test_ana_stab_bad_input(void **state)
{
  (void)state;
  ana_stab c = {ANA_STAB_MUSL, ANA_STAB_GIMP, 0, 12, 1.0, 1024.0, 1.0, 0.8, 0.05, 0.0125};
  ana_stab_rates r = {42.0, 42.0};
  char err[200] = "";
  assert_int_equal(ana_stab_rate(&c, &r, err, sizeof err), ANA_EINVAL);
  assert_true(r.rate == 42.0);
  assert_non_null(strstr(err, "per_cell"));
  c.per_cell = 2;
  c.dt = 0.0;
  assert_int_equal(ana_stab_rate(&c, &r, err, sizeof err), ANA_EINVAL);
  c.dt = 0.0125;
  c.scheme = 7;
  assert_int_equal(ana_stab_rate(&c, &r, NULL, 0), ANA_EINVAL);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ana_stab_unstressed_neutral),
      cmocka_unit_test(test_ana_stab_laid_neutral),
      cmocka_unit_test(test_ana_stab_drift_usl_bilinear_neutral),
      cmocka_unit_test(test_ana_stab_musl_gimp_grows),
      cmocka_unit_test(test_ana_stab_waves),
      cmocka_unit_test(test_ana_stab_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
