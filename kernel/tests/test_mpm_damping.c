/*
 * test_mpm_damping.c - the damping of the nodal velocities about their slow drift
 * (time.damping = c, mpm_damping.c) against values that do not come from the code:
 *  - free vibration of vibration.ini's bar (h 8, 1 ppc, MUSL, first mode) with c = 0.05
 *    and a low-pass too slow to follow it: mass-proportional damping, so the energy kept
 *    over two periods is the undamped run's times exp(-c t) within 2 %;
 *  - the ledger closes with L_damp to 1e-9 of E0, and L_damp > 0;
 *  - a quasi-static pull feels no damping: the grip load at delta 0.2 is E H delta / L
 *    within 1 % with and without c = 0.1, the two within 0.1 %;
 *  - a damped decohesion run gives the same bits on 1 and 2 threads, and up to the cut
 *    the undamped run's bits (damping_from = cut); damped about the parts the same;
 *  - damping about the parts (test_damping_parts): a part's rigid motion with its held
 *    end is kept, a stretch and a rotation keep (1 - c dt), L_damp gains what they lose.
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

#define PI 3.14159265358979323846

/* vibration.ini's bar under MUSL with consistent boundaries (test_util.h). */
static mpm_scene bar_scene(double h)
{
  return tu_vib_scene(h, MPM_SCHEME_MUSL, MPM_BC_CONSISTENT);
}

/* Energy kept over `periods` of 2 L / c (the time run into *t); the ledger's gap over E0
 * into *gap. */
static double run_vib(double c, double beta, double periods, double *t, double *gap, double *ldamp)
{
  mpm_scene sc = bar_scene(8.0);
  sc.damping = c;
  sc.damping_beta = beta;
  sc.damping_from = MPM_DAMP_START; /* no band: from the first step */
  sc.damping_tau = 1e6;
  mpm_sim *s = NULL;
  char err[256] = "";
  if (mpm_sim_alloc(&sc, 1, &s, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  mpm_energy e0, e;
  mpm_sim_energy(s, &e0);
  const double E0 = e0.KE + e0.SE, T = 2.0 * sc.L / sqrt(sc.E / sc.rho);
  const long n = lround(periods * T / sc.dt);
  for (long k = 0; k < n; k++)
    if (mpm_sim_step(s, err, sizeof err) != MPM_OK)
      fail_msg("step %ld: %s", k, err);
  mpm_sim_energy(s, &e);
  *t = s->t;
  *gap = fabs(e.W_ext + E0 - e.KE - e.SE - e.W_coh - tu_booked(&e)) / E0;
  *ldamp = e.L_damp / E0;
  mpm_sim_free(s);
  return (e.KE + e.SE) / E0;
}

static void test_damping_decay(void **state)
{
  (void)state;
  const double c = 0.05;
  double t0, t, gap0, gap, ld0, ld;
  const double k0 = run_vib(0.0, 0.0, 2.0, &t0, &gap0, &ld0), k = run_vib(c, 0.0, 2.0, &t, &gap, &ld);
  print_message("# kept: undamped %.5f, damped %.5f; (kept / undamped) / exp(-c t) = %.4f; L_damp / E0 %.4f\n", k0, k,
                k / k0 / exp(-c * t), ld);
  assert_rel(k / k0, exp(-c * t), 0.02, "damped energy kept / undamped against exp(-c t)");
  assert_abs(gap0, 0.0, 1e-9, "ledger, undamped");
  assert_abs(gap, 0.0, 1e-9, "ledger with L_damp");
  assert_abs(ld0, 0.0, 0.0, "L_damp without damping");
  assert_true(ld > 0.0);
}

/* time.damping_beta: the viscous stress beta C : grad v is stiffness-proportional damping,
 * under which a mode of frequency w obeys u'' + beta w^2 u' + w^2 u = 0 and its energy
 * decays as exp(-beta w^2 t) (light damping: beta w / 2 = 0.026 here).  w is the first
 * axial mode's, pi c / L with c = sqrt(E / rho) (the vibration scene measures the
 * kernel's period within 0.4 % of 2 L / c at h 8).  Over two periods the energy kept is
 * the undamped run's times exp(-beta w^2 t) within 2 % (measured: 1 % more kept, and 2 %
 * at twice this beta, a shortfall of the discrete step that grows with beta), and the
 * ledger closes with the viscous work in L_damp, to 1e-9 of E0. */
static void test_damping_beta_decay(void **state)
{
  (void)state;
  const double beta = 0.1;
  double t0, t, gap0, gap, ld0, ld;
  const double k0 = run_vib(0.0, 0.0, 2.0, &t0, &gap0, &ld0), k = run_vib(0.0, beta, 2.0, &t, &gap, &ld);
  const double w = PI * 32.0 / 192.0; /* vibration.ini: E 1024, rho 1, L 192 */
  print_message("# beta: kept undamped %.5f, damped %.5f; (kept / undamped) / exp(-beta w^2 t) = %.4f; L_damp / E0 %.4f\n",
                k0, k, k / k0 / exp(-beta * w * w * t), ld);
  assert_rel(k / k0, exp(-beta * w * w * t), 0.02, "energy kept / undamped against exp(-beta w^2 t)");
  assert_abs(gap, 0.0, 1e-9, "ledger with the viscous work in L_damp");
  assert_true(ld > 0.0);
}

/* Grip load at delta 0.2 of a slow pull (no vibration). */
static double pull_load(double c)
{
  mpm_scene sc = bar_scene(8.0);
  sc.vib_mode = 0;
  sc.speed = 1e-3;
  sc.end_delta = 0.25;
  sc.damping = c;
  sc.damping_from = MPM_DAMP_START;
  mpm_sim *s = NULL;
  char err[256] = "";
  if (mpm_sim_alloc(&sc, 1, &s, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  while (mpm_sim_delta(s) < 0.2)
    if (mpm_sim_step(s, err, sizeof err) != MPM_OK)
      fail_msg("%s", err);
  const double P = s->P_grip / mpm_sim_delta(s);
  mpm_sim_free(s);
  return P;
}

static void test_damping_quasistatic(void **state)
{
  (void)state;
  const double k = 1024.0 * 32.0 / 192.0, k0 = pull_load(0.0), k1 = pull_load(0.1);
  print_message("# P / delta: analytic %.4f, undamped %.4f, damped %.4f\n", k, k0, k1);
  assert_rel(k0, k, 0.01, "undamped slope against E H / L");
  assert_rel(k1, k, 0.01, "damped slope against E H / L");
  assert_rel(k1, k0, 1e-3, "damped slope against undamped");
}

static void test_damping_threads(void **state)
{
  (void)state;
  mpm_scene sc = bar_scene(4.0);
  sc.vib_mode = 0;
  sc.head = MPM_HEAD_RIGID;
  sc.model = MPM_DCOH_MODEL1;
  sc.alpha_deg = 60.0;
  sc.snf = 10.0;
  sc.stf = 1.0;
  sc.s0 = 10.0;
  sc.U0 = 0.375;
  sc.imp_factor = 0.9;
  sc.imp_stf_factor = 0.9;
  sc.imp_x = 96.0;
  sc.imp_y = 16.0;
  sc.shape = MPM_SHAPE_GIMP;
  sc.fields = MPM_FIELDS_TWO;
  sc.speed = 0.01;
  sc.end_delta = 1.1;
  sc.margin = 16.0;
  sc.damping = 0.1;
  sc.damping_from = MPM_DAMP_CUT;
  mpm_sim *a = NULL, *b = NULL;
  char err[256] = "";
  if (mpm_sim_alloc(&sc, 1, &a, err, sizeof err) != MPM_OK || mpm_sim_alloc(&sc, 2, &b, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  /* c: the same scene undamped, which up to the cut must be the damped run bit for bit
   * (time.damping_from = cut) */
  mpm_scene su = sc;
  su.damping = 0.0;
  mpm_sim *c = NULL;
  if (mpm_sim_alloc(&su, 1, &c, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  const long n = lround(1.0 / (sc.speed * sc.dt));
  long precut = 0;
  for (long k = 0; k < n; k++) {
    if (mpm_sim_step(a, err, sizeof err) != MPM_OK || mpm_sim_step(b, err, sizeof err) != MPM_OK)
      fail_msg("step %ld: %s", k, err);
    if (!a->cut) {
      if (mpm_sim_step(c, err, sizeof err) != MPM_OK)
        fail_msg("undamped step %ld: %s", k, err);
      if (memcmp(a->p->x, c->p->x, a->p->n * sizeof(double)) || memcmp(a->p->vx, c->p->vx, a->p->n * sizeof(double)))
        fail_msg("step %ld, before the cut: the damped run differs from the undamped one", k);
      precut++;
    }
  }
  mpm_sim_free(c);
  assert_true(precut > 100);
  print_message("# cut %d, softened %ld, separated %ld, peak %.4g, L_damp %.4g\n", a->cut, a->n_soften, a->n_separate, a->P_peak, a->led.L_damp);
  assert_true(a->cut && a->led.L_damp > 0.0);
  tu_assert_same_bits(a, b, "damped, two fields");
  mpm_sim_free(a);
  mpm_sim_free(b);
  /* about the parts */
  sc.damping_about = MPM_DAMP_PARTS;
  if (mpm_sim_alloc(&sc, 1, &a, err, sizeof err) != MPM_OK || mpm_sim_alloc(&sc, 2, &b, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  mpm_energy e0, e;
  mpm_sim_energy(a, &e0);
  for (long k = 0; k < n; k++)
    if (mpm_sim_step(a, err, sizeof err) != MPM_OK || mpm_sim_step(b, err, sizeof err) != MPM_OK)
      fail_msg("parts, step %ld: %s", k, err);
  mpm_sim_energy(a, &e);
  const double gap = fabs(tu_ledger_gap(&e0, &e)) / e.W_ext;
  print_message("# parts: cut %d, L_damp %.4g, ledger gap / W_ext %.2e\n", a->cut, e.L_damp, gap);
  assert_true(a->cut && e.L_damp > 0.0);
  assert_abs(gap, 0.0, 1e-6, "ledger, damped about the parts");
  tu_assert_same_bits(a, b, "damped about the parts, two fields");
  mpm_sim_free(a);
  mpm_sim_free(b);
}

static void test_damping_parts(void **state)
{
  (void)state;
  mpm_scene sc = bar_scene(8.0);
  sc.vib_mode = 0;
  sc.damping = 1.0;
  sc.damping_from = MPM_DAMP_CUT;
  sc.damping_about = MPM_DAMP_PARTS;
  mpm_sim *s = NULL;
  char err[256] = "";
  if (mpm_sim_alloc(&sc, 1, &s, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  assert_true(s->nbc > 0); /* held at both ends */
  mpm_particles *p = s->p;
  const double a = sc.damping * sc.dt, eps = 1e-3, vy0 = -0.02, w1 = -0.001, px1 = 150.0, py1 = 30.0;
  double *vx0 = malloc(p->n * sizeof(double)), *vy = malloc(p->n * sizeof(double)), ke = 0.0;
  assert_non_null(vx0);
  assert_non_null(vy);
  size_t nsep = 0, n0 = 0, n1 = 0;
  for (size_t k = 0; k < p->n; k++) {
    vx0[k] = vy[k] = 0.0;
    if (p->mat[k] == MPM_MAT_HEAD)
      continue;
    if (p->x0[k] == 92.0) {
      p->sep[k] = 1;
      nsep++;
      vx0[k] = 0.02; /* a row's lone separated particle: left alone */
    } else if (p->x0[k] < 92.0) { /* the grip's part: the grip's x velocity, a slide in y, a stretch */
      vx0[k] = -s->vgrip + eps * (p->x0[k] - 44.0);
      vy[k] = vy0;
      ke += 0.5 * p->m[k] * (pow(eps * (p->x0[k] - 44.0), 2) + vy0 * vy0);
      n0++;
    } else { /* the fixed end's part, held: a rotation is not its rigid motion */
      vx0[k] = -w1 * (p->y[k] - py1);
      vy[k] = w1 * (p->x[k] - px1);
      ke += 0.5 * p->m[k] * (vx0[k] * vx0[k] + vy[k] * vy[k]);
      n1++;
    }
    p->vx[k] = vx0[k];
    p->vy[k] = vy[k];
  }
  assert_int_equal(nsep, 4); /* h 8: four particle rows */
  assert_true(n0 == 44 && n1 == 48);
  s->cut = 1; /* the column has cut the bar */
  mpm_damping_parts(s);
  double e1 = 0.0, e2 = 0.0;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD || p->sep[k]) {
      e1 = fmax(e1, fabs(p->vx[k] - vx0[k]) + fabs(p->vy[k] - vy[k]));
      continue;
    }
    if (p->x0[k] < 92.0)
      e2 = fmax(e2, fabs(p->vx[k] - (-s->vgrip + (1.0 - a) * eps * (p->x0[k] - 44.0))) + fabs(p->vy[k] - (1.0 - a) * vy0));
    else
      e2 = fmax(e2, fabs(p->vx[k] - (1.0 - a) * vx0[k]) + fabs(p->vy[k] - (1.0 - a) * vy[k]));
  }
  print_message("# parts: untouched %.2e, kept and scaled %.2e; L_damp %.6e against %.6e\n", e1, e2, s->led.L_damp,
                ke * (1.0 - (1.0 - a) * (1.0 - a)));
  assert_abs(e1, 0.0, 0.0, "separated and head particles");
  assert_abs(e2, 0.0, 1e-14, "the grip's part's slide and stretch about the grip, the held part's rotation, scaled by 1 - c dt");
  assert_rel(s->led.L_damp, ke * (1.0 - (1.0 - a) * (1.0 - a)), 1e-9, "L_damp: the kinetic energy lost");
  free(vx0);
  free(vy);
  mpm_sim_free(s);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_damping_decay),
    cmocka_unit_test(test_damping_beta_decay),
    cmocka_unit_test(test_damping_quasistatic),
    cmocka_unit_test(test_damping_threads),
    cmocka_unit_test(test_damping_parts),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
