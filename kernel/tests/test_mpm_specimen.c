/*
 * test_mpm_specimen.c - the specimen table (mpm_specimen.h): each specimen's list of
 * constrained node components against a count by hand of the nodes its drawing holds,
 * with their components, sides and loading coefficients, and the dissipation scale.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_specimen.h"
#include "test_util.h"

/* The paper's bar at h 8 (24 x 4 cells), 4 ppc, an interface scene for the beams. */
static mpm_scene scene(int specimen, int shape, int grips)
{
  mpm_scene sc = tu_scene(MPM_DCOH_MODEL1, specimen == MPM_SPEC_BAR ? 90.0 : 0.0, 1.0, 10.0, 1.0, 1.0);
  sc.specimen = specimen;
  sc.grips = grips;
  sc.a0 = 64.0;
  sc.L = 192.0;
  sc.H = 32.0;
  sc.h = 8.0;
  sc.ppc = 4;
  sc.shape = shape;
  sc.imp_factor = sc.imp_stf_factor = 1.0;
  sc.imp_x = 96.0;
  sc.imp_y = 16.0;
  sc.dt = 0.1;
  sc.speed = 0.001;
  sc.end_delta = 0.6;
  sc.sep_threshold = 1.0;
  if (specimen != MPM_SPEC_BAR) {
    sc.solver = MPM_SOLVER_STATIC;
    sc.path = MPM_PATH_IFACE;
    sc.fields = MPM_FIELDS_TWO;
    sc.shape = MPM_SHAPE_GIMP;
    sc.scheme = MPM_SCHEME_MUSL;
  }
  return sc;
}

/* x and y of node n */
static void node_xy(const mpm_sim *s, int n, double *x, double *y)
{
  *x = s->g->ox + s->sc.h * (double)(n / s->g->nny);
  *y = s->g->oy + s->sc.h * (double)(n % s->g->nny);
}

/* The bar with rollers: the grip's node columns from the head's far end to x = 0
 * (2 head cells and ceil(0.6 / 8) = 1 cell of travel: 4 columns of 5 nodes) in x at
 * c = -1; the column x = L in x at rest (5, counted in P_fixed); its mid-height node in
 * y.  26 components; held grips add the 20 + 5 in y and drop that one: 50. */
static void bar_lists(void **state)
{
  (void)state;
  for (int held = 0; held < 2; held++) {
    mpm_scene sc = scene(MPM_SPEC_BAR, MPM_SHAPE_LINEAR, held ? MPM_GRIPS_HELD : MPM_GRIPS_ROLLERS);
    mpm_sim *s = tu_make_sim(&sc, 1);
    assert_int_equal(s->nbc, held ? 50 : 26);
    int grip = 0, fixx = 0, ys = 0, fixed = 0;
    for (int i = 0; i < s->nbc; i++) {
      const mpm_bc *b = &s->bc[i];
      double x, y;
      node_xy(s, b->node, &x, &y);
      assert_true(y >= -1e-9 && y <= 32.0 + 1e-9);
      if (b->comp == 0 && b->c == -1.0) {
        assert_true(x <= 1e-9 && x >= -4.0 * 8.0 - 1e-9); /* the head's columns and x = 0 */
        grip++;
      } else if (b->comp == 0) {
        assert_true(b->c == 0.0 && fabs(x - 192.0) < 1e-9);
        fixx++;
      } else {
        assert_true(b->c == 0.0);
        ys++;
      }
      fixed += b->fixed;
      assert_int_equal(b->side, MPM_BC_ANY);
    }
    assert_int_equal(grip, 20);
    assert_int_equal(fixx, 5);
    assert_int_equal(fixed, 5);
    assert_int_equal(ys, held ? 25 : 1);
    mpm_sim_free(s);
  }
}

/* The DCB on uGIMP: the node columns x = -8 and 0, rows y = 0..32; below the line c =
 * -1/2, above +1/2, the line's node twice (its far slot with the lower arm, its near
 * slot with the upper): 2 x (5 + 1) = 12, and the pin (192, 16) in x (fixed) and y: 14.
 * The ELS: the same faces at c = 1 (12) and the columns x = 192, 200 clamped in x and y
 * (2 x 5 x 2 = 20): 32. */
static void beam_lists(void **state)
{
  (void)state;
  for (int els = 0; els < 2; els++) {
    mpm_scene sc = scene(els ? MPM_SPEC_ELS : MPM_SPEC_DCB, MPM_SHAPE_GIMP, MPM_GRIPS_ROLLERS);
    mpm_sim *s = tu_make_sim(&sc, 1);
    assert_int_equal(s->nbc, els ? 32 : 14);
    int face = 0, near = 0, far = 0, rest = 0;
    double csum = 0.0;
    for (int i = 0; i < s->nbc; i++) {
      const mpm_bc *b = &s->bc[i];
      double x, y;
      node_xy(s, b->node, &x, &y);
      if (b->c != 0.0) {
        assert_int_equal(b->comp, 1);
        assert_true(fabs(x) < 1e-9 || fabs(x + 8.0) < 1e-9);
        const double want = els ? 1.0 : (y < 16.0 || b->side == MPM_BC_FAR ? -0.5 : 0.5);
        assert_true(b->c == want);
        near += b->side == MPM_BC_NEAR;
        far += b->side == MPM_BC_FAR;
        if (b->side != MPM_BC_ANY)
          assert_true(fabs(y - 16.0) < 1e-9);
        csum += b->c;
        face++;
      } else {
        assert_true(fabs(x - 192.0) < 1e-9 || (els && fabs(x - 200.0) < 1e-9));
        assert_int_equal(b->fixed, b->comp == 0);
        rest++;
      }
    }
    assert_int_equal(face, 12);
    assert_int_equal(near, 2);
    assert_int_equal(far, 2);
    assert_int_equal(rest, els ? 20 : 2);
    assert_true(fabs(csum - (els ? 12.0 : 0.0)) < 1e-12); /* the DCB's arms pull apart evenly */
    mpm_sim_free(s);
  }
}

/* D's full value: U0 H / sin a on the bar, U0 (L - a0) on a split beam; the crack tip
 * starts at a0 (NAN on the bar). */
static void dissipation_scale(void **state)
{
  (void)state;
  mpm_scene sc = scene(MPM_SPEC_BAR, MPM_SHAPE_LINEAR, MPM_GRIPS_ROLLERS);
  sc.alpha_deg = 30.0;
  assert_rel(mpm_spec_bar.dis_full(&sc), 0.375 * 32.0 / 0.5, 1e-14, "bar at 30 deg");
  sc = scene(MPM_SPEC_DCB, MPM_SHAPE_GIMP, MPM_GRIPS_ROLLERS);
  assert_rel(mpm_specimen_of(&sc)->dis_full(&sc), 0.375 * 128.0, 1e-14, "dcb");
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  assert_true(in.crack_tip == 64.0);
  mpm_sim_free(s);
}

/* What the table refuses: held grips off the bar, the ELS solved explicitly, a beam with
 * its line off a node row, a pre-crack outside the bar. */
static void refusals(void **state)
{
  (void)state;
  char err[512];
  mpm_scene sc = scene(MPM_SPEC_DCB, MPM_SHAPE_GIMP, MPM_GRIPS_HELD);
  assert_int_equal(mpm_scene_rules(&sc, NULL, err, sizeof err), MPM_EINVAL);
  sc = scene(MPM_SPEC_ELS, MPM_SHAPE_GIMP, MPM_GRIPS_ROLLERS);
  sc.solver = MPM_SOLVER_EXPLICIT; /* the ELS is static only; the DCB runs explicitly */
  assert_int_equal(mpm_scene_rules(&sc, NULL, err, sizeof err), MPM_EINVAL);
  sc.specimen = MPM_SPEC_DCB;
  assert_int_equal(mpm_scene_rules(&sc, NULL, err, sizeof err), MPM_OK);
  sc = scene(MPM_SPEC_ELS, MPM_SHAPE_GIMP, MPM_GRIPS_ROLLERS);
  sc.H = 24.0; /* H / 2 = 12: not a node row of h 8 */
  assert_int_equal(mpm_scene_rules(&sc, NULL, err, sizeof err), MPM_EINVAL);
  sc = scene(MPM_SPEC_ELS, MPM_SHAPE_GIMP, MPM_GRIPS_ROLLERS);
  sc.a0 = 192.0;
  assert_int_equal(mpm_scene_rules(&sc, NULL, err, sizeof err), MPM_EINVAL);
  sc.a0 = 64.0;
  assert_int_equal(mpm_scene_rules(&sc, NULL, err, sizeof err), MPM_OK);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(bar_lists),
    cmocka_unit_test(beam_lists),
    cmocka_unit_test(dissipation_scale),
    cmocka_unit_test(refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
