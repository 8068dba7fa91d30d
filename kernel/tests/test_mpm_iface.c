/*
 * test_mpm_iface.c - the crack as a cohesive interface (decohesion.path = interface,
 * mpm_iface.c) on the paper's inclined bar (L 192, H 32, alpha 60), against closed forms
 * and conservation laws:
 *  - Mode I and Mode II (bar_case): elastic slope E H / L, peak r0 H (eq. 8's surface),
 *    D = U0 x area and W_coh = U0 / 2 x area (eqs. 10, 24) by the cut, the cut bar under
 *    2 % of the peak, the ledger to 1e-6 of W_ext; no particle softens;
 *  - the same bits on 1 and 2 threads; the scene check refuses what is not implemented;
 *  - at alpha 90 (iface90.ini) the flaw's column goes to one part whole, D = U0 H;
 *  - share = line: the traction even along the crack within 5 % of its mean;
 *  - grid.weights = laid: the particles still move, D = U0 H, a slow softening stays
 *    quasi-static (kinetic energy under 1 % of the strain energy); refused off the
 *    stretched grid; share = line carries no shear on capped steps.
 * The two slow runs (a sixteenth of the speed) are the IFACE_SLOW build, mpm_iface_slow.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "test_util.h"

/* built twice (kernel/meson.build): IFACE_SLOW runs the long tests, the other build the
 * rest, so each build leaves the other's test functions unused */
#pragma GCC diagnostic ignored "-Wunused-function"

static const double PI = 3.14159265358979323846;

/* The inclined bar of fig7.ini / fig8.ini with the interface: Model 1, q 1, 60 deg,
 * the flaw (0.9 of the strengths that govern) on the centre's cell, uGIMP, two fields,
 * MUSL, the release damped from the cut about the parts. */
static mpm_scene iface_scene(double snf, double stf, double h, int ppc)
{
  mpm_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.L = 192.0;
  sc.H = 32.0;
  sc.E = 1024.0;
  sc.nu = 0.25;
  sc.rho = 1.0;
  sc.model = MPM_DCOH_MODEL1;
  sc.alpha_deg = 60.0;
  sc.snf = snf;
  sc.stf = stf;
  sc.U0 = 0.375;
  sc.s0 = snf;
  sc.q = 1.0;
  sc.sep_threshold = 0.98;
  sc.le_mode = MPM_LE_CELL;
  sc.le_factor = 1.0;
  sc.imp_factor = snf < stf ? 0.9 : 1.0;
  sc.imp_stf_factor = stf < snf ? 0.9 : 1.0;
  sc.imp_x = 96.0;
  sc.imp_y = 16.0;
  sc.imp_size = MPM_IMP_CELL;
  sc.path = MPM_PATH_IFACE;
  sc.h = h;
  sc.ppc = ppc;
  sc.margin = 16.0;
  sc.scheme = MPM_SCHEME_MUSL;
  sc.shape = MPM_SHAPE_GIMP;
  sc.fields = MPM_FIELDS_TWO;
  sc.dt = 0.0125 * h; /* the paper's 0.025 at h 2 */
  sc.speed = 0.001;
  sc.damping = 0.1;
  sc.damping_from = MPM_DAMP_CUT;
  sc.damping_about = MPM_DAMP_PARTS;
  sc.end_delta = 1.0;
  return sc;
}

/* Runs to the cut plus `after` of grip travel, and checks every closed form above. */
static void bar_case(double snf, double stf, const char *mode)
{
  const mpm_scene sc = iface_scene(snf, stf, 8.0, 4);
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_energy e0, e;
  mpm_sim_energy(s, &e0);
  const double a = sc.alpha_deg * (PI / 180.0), sa = sin(a), ca = cos(a);
  const double sn = sa * sa / snf, st = sa * ca / stf, r0 = 1.0 / sqrt(sn * sn + st * st);
  const double Pmax = r0 * sc.H, area = sc.H / sa;
  /* the elastic slope: least squares over the rows with 0.1 to 0.6 of the peak, before it */
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0, peak = 0.0, dcut = -1.0, after = 0.0;
  double Wcut = NAN;
  const long nmax = lround(sc.end_delta / (sc.speed * sc.dt));
  for (long k = 0; k < nmax; k++) {
    tu_run_steps(s, 1);
    const double d = mpm_sim_delta(s), P = s->P_grip;
    peak = fmax(peak, P);
    if (peak < 0.6 * Pmax && P > 0.1 * Pmax && P == peak) {
      sx += d;
      sy += P;
      sxx += d * d;
      sxy += d * P;
      n++;
    }
    if (s->cut && dcut < 0.0) {
      dcut = d;
      mpm_sim_energy(s, &e);
      Wcut = e.W_coh;
    }
    /* the load a settle of 0.1 past the cut (the release's ringing has that long to
     * pass), over 0.05 of travel */
    if (dcut >= 0.0 && d >= dcut + 0.1)
      after = fmax(after, fabs(P));
    if (dcut >= 0.0 && d >= dcut + 0.15)
      break;
  }
  char what[128];
  snprintf(what, sizeof what, "%s: the bar is cut", mode);
  if (dcut < 0.0)
    fail_msg("%s (never, to delta %g; peak %g against r0 H %g)", what, mpm_sim_delta(s), peak, Pmax);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  snprintf(what, sizeof what, "%s: elastic slope vs E H / L", mode);
  assert_rel(slope, sc.E * sc.H / sc.L, 0.01, what);
  snprintf(what, sizeof what, "%s: peak vs r0 H", mode);
  assert_rel(peak, Pmax, 0.03, what);
  mpm_sim_energy(s, &e);
  snprintf(what, sizeof what, "%s: dissipation vs U0 area", mode);
  /* every segment is open, lambda 1, and the segments' lengths (the line integrals of
   * the nodes' uGIMP weights, a partition of unity) sum to the crack's length */
  assert_rel(e.D, sc.U0 * area, 1e-3, what);
  /* the law's work to lambda = 0.98 is UF x area x (1 - 0.02^2), lambda taken in closed
   * form from the work (mpm_iface.c advance) */
  snprintf(what, sizeof what, "%s: cohesive work at the cut vs UF area", mode);
  assert_rel(Wcut, 0.5 * sc.U0 * area, 0.01, what);
  snprintf(what, sizeof what, "%s: load after the cut vs the peak", mode);
  assert_abs(after / peak, 0.0, 0.02, what);
  const double booked = e.L_bc + e.L_flip + e.L_scheme + e.W_head + e.L_contact + e.L_debris + e.L_damp;
  snprintf(what, sizeof what, "%s: W_ext + E0 - (KE + SE + W_coh + booked)", mode);
  assert_abs(e.W_ext + e0.KE + e0.SE - (e.KE + e.SE + e.W_coh + booked), 0.0, 1e-6 * e.W_ext, what);
  const mpm_particles *p = s->p;
  for (size_t k = 0; k < p->n; k++)
    if (p->lam[k] != 0.0 || p->sep[k])
      fail_msg("%s: particle %zu softened (lambda %g)", mode, k, p->lam[k]);
  mpm_sim_free(s);
}

static void test_mpm_iface_mode_one(void **state)
{
  (void)state;
  bar_case(1.0, 10.0, "Mode I (snf 1, stf 10)");
}

static void test_mpm_iface_mode_two(void **state)
{
  (void)state;
  bar_case(10.0, 1.0, "Mode II (snf 10, stf 1)");
}

/* 1 and 2 threads through the onset, the softening and the cut: the same bits. */
static void test_mpm_iface_threads(void **state)
{
  (void)state;
  mpm_scene sc = iface_scene(1.0, 10.0, 8.0, 4);
  mpm_sim *a = tu_make_sim(&sc, 1), *b = tu_make_sim(&sc, 2);
  const long nmax = lround(0.45 / (sc.speed * sc.dt));
  for (long k = 0; k < nmax; k++) {
    tu_run_steps(a, 1);
    tu_run_steps(b, 1);
  }
  assert_true(a->cut); /* the run went through every phase */
  tu_assert_same_bits(a, b, "interface, h 8, 4 ppc");
  mpm_sim_free(a);
  mpm_sim_free(b);
}

/* Fig. 6's bar with the interface at alpha 90 (iface90.ini): the line through the flaw's
 * particle, no flaw, the grid following the bar's stretch. */
static mpm_scene iface90_scene(double h, int ppc, int share)
{
  mpm_scene sc = iface_scene(1.0, 10.0, h, ppc);
  sc.alpha_deg = 90.0;
  sc.imp_factor = 1.0;
  sc.imp_size = MPM_IMP_PARTICLE;
  sc.grid_motion = MPM_GRID_STRETCH;
  sc.share = share;
  sc.dt = 0.0125 * h;
  sc.end_delta = 0.5;
  return sc;
}

/* The flaw's column (x0 = lx, on the line) against its neighbours at lx -+ d, by the mean
 * and the spread of their x displacements after the cut: the column must move whole with
 * one of them (the two parts are apart by the opening, about U0 / snf = 0.375). */
static void column_case(double h, int ppc, int share, const char *what)
{
  const mpm_scene sc = iface90_scene(h, ppc, share);
  mpm_sim *s = tu_make_sim(&sc, 1);
  const long nmax = lround(sc.end_delta / (sc.speed * sc.dt));
  for (long k = 0; k < nmax && !(s->cut && mpm_sim_delta(s) > 0.45); k++)
    tu_run_steps(s, 1);
  if (!s->cut)
    fail_msg("%s: the bar is not cut by delta %g", what, mpm_sim_delta(s));
  const mpm_particles *p = s->p;
  /* the flaw's particle: the one nearest (96, 16), ties to the lowest index, as laid */
  size_t imp = 0;
  double best = INFINITY;
  for (size_t k = 0; k < p->n; k++) {
    const double r2 = (p->x0[k] - 96.0) * (p->x0[k] - 96.0) + (p->y0[k] - 16.0) * (p->y0[k] - 16.0);
    if (p->mat[k] != MPM_MAT_HEAD && r2 < best - 1e-12) {
      best = r2;
      imp = k;
    }
  }
  const double lx = p->x0[imp], d = h / sqrt((double)ppc);
  double lo[3], hi[3], sum[3] = {0, 0, 0};
  int n[3] = {0, 0, 0};
  for (int c = 0; c < 3; c++) {
    lo[c] = INFINITY;
    hi[c] = -INFINITY;
  }
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD)
      continue;
    for (int c = 0; c < 3; c++)
      if (fabs(p->x0[k] - (lx + (c - 1) * d)) < 1e-9 * h) {
        const double u = p->x[k] - p->x0[k];
        lo[c] = fmin(lo[c], u);
        hi[c] = fmax(hi[c], u);
        sum[c] += u;
        n[c]++;
      }
  }
  const double gap = sum[2] / n[2] - sum[0] / n[0], mid = sum[1] / n[1];
  if (!(gap > 0.3))
    fail_msg("%s: the parts are not apart at the line (%g)", what, gap);
  /* the column whole: its spread is far below the opening */
  if (!(hi[1] - lo[1] < 0.05 * gap))
    fail_msg("%s: the column on the line is split: x displacements %g to %g, the opening %g", what, lo[1], hi[1], gap);
  /* and with one part: its mean within a tenth of the opening of one neighbour's */
  if (!(fmin(fabs(mid - sum[0] / n[0]), fabs(mid - sum[2] / n[2])) < 0.1 * gap))
    fail_msg("%s: the column on the line (mean u %g) moves with neither part (%g, %g)", what, mid, sum[0] / n[0],
             sum[2] / n[2]);
  mpm_energy e;
  mpm_sim_energy(s, &e);
  assert_rel(e.D, sc.U0 * sc.H, 1e-6, what);
  mpm_sim_free(s);
}

/* iface90.ini's method on a short L x H bar at h 1, 4 ppc, the crack at its centre (on a
 * node column) */
static mpm_scene short_bar(double L, double H)
{
  mpm_scene sc = iface90_scene(1.0, 4, MPM_SHARE_LINE);
  sc.L = L;
  sc.H = H;
  sc.imp_x = 0.5 * L;
  sc.imp_y = 0.5 * H;
  sc.bc = MPM_BC_CONSISTENT; /* iface90.ini's */
  return sc;
}

/* share = line: the traction even along the crack, late in the softening (delta 0.3 of the
 * opening's 0.375): a 48 x 16 bar at h 1, 4 ppc, the crack on the node column x = 24. */
static void test_mpm_iface_share_line_even(void **state)
{
  (void)state;
  const mpm_scene sc = short_bar(48.0, 16.0);
  mpm_sim *s = tu_make_sim(&sc, 1);
  while (mpm_sim_delta(s) < 0.3 && !s->cut)
    tu_run_steps(s, 1);
  if (s->cut)
    fail_msg("share line: the bar is cut by delta %g, before the softening's end", mpm_sim_delta(s));
  const mpm_particles *p = s->p;
  double lo[4], hi[4], sum[4];
  int n[4] = {0, 0, 0, 0};
  const double xs[4] = {23.25, 23.75, 24.25, 24.75}; /* the columns within one cell of x = 24 */
  for (int c = 0; c < 4; c++) {
    lo[c] = INFINITY;
    hi[c] = -INFINITY;
    sum[c] = 0.0;
  }
  for (size_t k = 0; k < p->n; k++)
    for (int c = 0; c < 4; c++)
      if (p->mat[k] != MPM_MAT_HEAD && fabs(p->x0[k] - xs[c]) < 1e-9 && p->y0[k] > 2.0 && p->y0[k] < sc.H - 2.0) {
        lo[c] = fmin(lo[c], p->sxx[k]);
        hi[c] = fmax(hi[c], p->sxx[k]);
        sum[c] += p->sxx[k];
        n[c]++;
      }
  for (int c = 0; c < 4; c++) {
    const double mean = sum[c] / n[c];
    if (!(n[c] == 24 && mean > 0.1 && (hi[c] - lo[c]) < 0.05 * mean))
      fail_msg("share line: sigma_xx at x0 %g varies along the crack from %g to %g (mean %g over %d particles; "
               "at most 5 %% of the mean)", xs[c], lo[c], hi[c], mean, n[c]);
  }
  mpm_sim_free(s);
}

static void test_mpm_iface_column_on_line(void **state)
{
  (void)state;
  column_case(8.0, 1, MPM_SHARE_LINE, "alpha 90, h 8, 1 ppc, share line");
  column_case(8.0, 4, MPM_SHARE_LINE, "alpha 90, h 8, 4 ppc, share line");
  column_case(8.0, 4, MPM_SHARE_STICK, "alpha 90, h 8, 4 ppc, share stick");
  column_case(4.0, 4, MPM_SHARE_LINE, "alpha 90, h 4, 4 ppc, share line");
}

static void expect_einval(const mpm_scene *sc, const char *what)
{
  mpm_sim *s = NULL;
  char err[256] = "";
  if (mpm_sim_alloc(sc, 1, &s, err, sizeof err) != MPM_EINVAL || s)
    fail_msg("%s: accepted", what);
  if (!strstr(err, "interface"))
    fail_msg("%s: the message does not name the interface: %s", what, err);
}

/* What the interface does not implement is refused, each rule on its own. */
static void test_mpm_iface_scene_check(void **state)
{
  (void)state;
  mpm_scene sc = iface_scene(1.0, 10.0, 8.0, 1);
  mpm_sim *s = tu_make_sim(&sc, 1); /* the base is accepted */
  mpm_sim_free(s);
  sc.shape = MPM_SHAPE_LINEAR;
  expect_einval(&sc, "linear shapes");
  sc = iface_scene(1.0, 10.0, 8.0, 1);
  sc.fields = MPM_FIELDS_ONE;
  expect_einval(&sc, "one field");
  sc = iface_scene(1.0, 10.0, 8.0, 1);
  sc.scheme = MPM_SCHEME_USL;
  expect_einval(&sc, "USL");
  sc = iface_scene(1.0, 10.0, 8.0, 1);
  sc.q = 2.0;
  expect_einval(&sc, "q = 2");
  sc = iface_scene(1.0, 10.0, 8.0, 1);
  sc.alpha_deg = 5.0; /* the line leaves the bar through its ends */
  expect_einval(&sc, "alpha 5");
  /* share = line: a line along a node column that the grid follows, no other */
  sc = iface90_scene(8.0, 4, MPM_SHARE_LINE);
  s = tu_make_sim(&sc, 1); /* accepted: the crack at x 96 */
  mpm_sim_free(s);
  sc.alpha_deg = 60.0;
  expect_einval(&sc, "share line at alpha 60");
  sc = iface90_scene(8.0, 4, MPM_SHARE_LINE);
  sc.grid_motion = MPM_GRID_FIXED;
  expect_einval(&sc, "share line on the fixed grid");
  sc = iface90_scene(8.0, 4, MPM_SHARE_LINE);
  sc.imp_x = 99.0; /* the flaw's column at x 98, its edge at 100: a cell's centre */
  expect_einval(&sc, "share line, the crack inside a cell");
}

/* Runs s to delta `end` (or the cut), `every` steps at a time, and returns the largest
 * kinetic energy past the peak (the softening), over the strain energy if per_se, and
 * where it was (*at). */
static double softening_worst_ke(mpm_sim *s, double end, int every, int per_se, double *at)
{
  double worst = 0.0;
  *at = 0.0;
  mpm_energy e;
  while (mpm_sim_delta(s) < end && !s->cut) {
    tu_run_steps(s, every);
    if (s->P_grip < s->P_peak) {
      mpm_sim_energy(s, &e);
      const double v = per_se ? e.KE / e.SE : e.KE;
      if (v > worst) {
        worst = v;
        *at = mpm_sim_delta(s);
      }
    }
  }
  return worst;
}

/* grid.weights = laid under long softening.  MUSL with uGIMP grows a grid-scale wave once
 * the particles drift from where the grid was laid under a stress (analytic/ana_stab.c):
 * at a sixteenth of the paper's grip speed a 24 x 8 bar at h 1, 4 ppc holds 2.4e-4 of
 * kinetic energy by delta 0.2 with the weights at the particles' positions, rising
 * e-fold every 0.013 of delta, against 3.5e-6 with the weights at the laid places.  The
 * loading is quasi-static (the grip at 6e-5 of the wave speed): the kinetic energy must
 * stay a small part of the strain energy, here under 1 % of it from the peak to delta
 * 0.25 (measured: 1.7e-5 with laid; 0.10 by delta 0.25 with the weights at the
 * particles' positions, which fails).  The ledger closes as ever. */
static void test_mpm_iface_laid_quiet(void **state)
{
  (void)state;
  mpm_scene sc = short_bar(24.0, 8.0);
  sc.speed = 0.0000625;
  sc.weights = MPM_WEIGHTS_LAID;
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_energy e0, e;
  mpm_sim_energy(s, &e0);
  double at;
  const double worst = softening_worst_ke(s, 0.25, 80, 1, &at);
  print_message("# laid: KE / SE at most %.3e (delta %.3f)\n", worst, at);
  if (s->cut)
    fail_msg("laid: the bar is cut by delta %g, before the softening's end", mpm_sim_delta(s));
  if (!(worst < 0.01))
    fail_msg("laid: the kinetic energy reaches %g of the strain energy at delta %g (at most 0.01)", worst, at);
  mpm_sim_energy(s, &e);
  assert_abs(tu_ledger_gap(&e0, &e), 0.0, 1e-9 * e.W_ext, "laid: W_ext + E0 - (KE + SE + W_coh + booked)");
  mpm_sim_free(s);
}

/* share = line carries no shear on a softening segment's capped steps.  Fig. 6's bar
 * (iface90.ini: laid weights) at h 4, 4 ppc and a sixteenth of the paper's grip speed,
 * from the peak to delta 0.34: the kinetic energy stays within 20 times that of the steady
 * loading, rho H L v^2 / 6 (the bar stretching at the grip speed v: 4.0e-6), an allowance
 * for the softening's own change of the velocity field.  Measured: 1.8e-5.  With the
 * node's share of the segment's shear on those steps (a rule tried and not kept) a
 * wave grows there: 2.4e-3 (4.5e-4 with the weights at the particles' positions);
 * docs/findings.md. */
static void test_mpm_iface_line_no_shear_quiet(void **state)
{
  (void)state;
  mpm_scene sc = iface90_scene(4.0, 4, MPM_SHARE_LINE);
  sc.bc = MPM_BC_CONSISTENT;
  sc.speed = 0.0000625;
  sc.weights = MPM_WEIGHTS_LAID;
  mpm_sim *s = tu_make_sim(&sc, 1);
  const double steady = sc.rho * sc.H * sc.L * sc.speed * sc.speed / 6.0;
  double at;
  const double worst = softening_worst_ke(s, 0.34, 40, 0, &at);
  print_message("# line, no shear: KE at most %.3e (delta %.3f), the steady loading's %.3e\n", worst, at, steady);
  if (s->cut)
    fail_msg("line: the bar is cut by delta %g, before the softening's end", mpm_sim_delta(s));
  if (!(worst < 20.0 * steady))
    fail_msg("line: the kinetic energy reaches %g at delta %g (at most 20 x the steady %g)", worst, at, steady);
  mpm_sim_free(s);
}

/* grid.weights = laid is refused off the stretched grid (the places follow its stretch) */
static void test_mpm_iface_laid_refused(void **state)
{
  (void)state;
  mpm_scene sc = iface_scene(1.0, 10.0, 8.0, 1);
  sc.weights = MPM_WEIGHTS_LAID;
  mpm_sim *s = NULL;
  char err[256] = "";
  assert_int_equal(mpm_sim_alloc(&sc, 1, &s, err, sizeof err), MPM_EINVAL);
  assert_null(s);
  assert_non_null(strstr(err, "grid.weights"));
}

/* grid.weights = laid through a whole run of Fig. 6's bar (h 8, 4 ppc, the paper's speed):
 * the particles still move (before the cut every particle is within 0.01 of where the
 * usual weights put it: the two differ only by the 0.04 h drift the laid weights do not
 * see), the bar is cut with D = U0 H (eq. 10 on the open line), and the ledger closes
 * past the cut, where the laid places are given up. */
static void test_mpm_iface_laid_run(void **state)
{
  (void)state;
  mpm_scene sc = iface90_scene(8.0, 4, MPM_SHARE_LINE);
  sc.bc = MPM_BC_CONSISTENT;
  mpm_sim *cur = tu_make_sim(&sc, 1);
  sc.weights = MPM_WEIGHTS_LAID;
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_energy e0, e;
  mpm_sim_energy(s, &e0);
  while (mpm_sim_delta(s) < 0.3) {
    tu_run_steps(s, 1);
    tu_run_steps(cur, 1);
  }
  const mpm_particles *p = s->p, *q = cur->p;
  double worst = 0.0;
  size_t found = 0;
  for (size_t k = 0; k < p->n; k++)
    for (size_t m = 0; m < q->n; m++)
      if (q->x0[m] == p->x0[k] && q->y0[m] == p->y0[k]) {
        worst = fmax(worst, fmax(fabs(p->x[k] - q->x[m]), fabs(p->y[k] - q->y[m])));
        found++;
        break;
      }
  print_message("# laid run: at delta 0.3 the positions within %.2e of the usual weights'\n", worst);
  assert_int_equal(found, p->n);
  if (!(worst < 0.01))
    fail_msg("laid: a particle is %g from where the usual weights put it at delta 0.3", worst);
  mpm_sim_free(cur);
  double dcut = -1.0;
  while (mpm_sim_delta(s) < 0.6 && (dcut < 0.0 || mpm_sim_delta(s) < dcut + 0.1)) {
    tu_run_steps(s, 1);
    if (s->cut && dcut < 0.0)
      dcut = mpm_sim_delta(s);
  }
  if (dcut < 0.0)
    fail_msg("laid: the bar is not cut by delta %g", mpm_sim_delta(s));
  mpm_sim_energy(s, &e);
  assert_rel(e.D, sc.U0 * sc.H, 1e-9, "laid: D vs U0 H");
  assert_abs(tu_ledger_gap(&e0, &e), 0.0, 1e-9 * e.W_ext, "laid: W_ext + E0 - (KE + SE + W_coh + booked)");
  mpm_sim_free(s);
}

int main(void)
{
#ifdef IFACE_SLOW /* the long runs (kernel/meson.build: test mpm_iface_slow) */
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_iface_laid_quiet),
      cmocka_unit_test(test_mpm_iface_line_no_shear_quiet),
  };
#else
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_iface_scene_check),
      cmocka_unit_test(test_mpm_iface_mode_one),
      cmocka_unit_test(test_mpm_iface_mode_two),
      cmocka_unit_test(test_mpm_iface_threads),
      cmocka_unit_test(test_mpm_iface_column_on_line),
      cmocka_unit_test(test_mpm_iface_share_line_even),
      cmocka_unit_test(test_mpm_iface_laid_run),
      cmocka_unit_test(test_mpm_iface_laid_refused),
  };
#endif
  return cmocka_run_group_tests(tests, NULL, NULL);
}
