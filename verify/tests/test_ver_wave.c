/*
 * test_ver_wave.c - data/scenes/iface90.ini (Fig. 6's bar with the crack as a cohesive
 * interface, MUSL) against the exact solution at its own grip speed (analytic/ana_wave.c):
 *  - the peak grip load is that solution's (r0 H plus the load the grip adds while the
 *    plane's unloading wave travels to it, +1.6 % at speed 0.001) within 1 %, and above
 *    r0 H by more than half that overshoot;
 *  - the RMS of P - P_wave over Pmax, up to lambda 0.98, is under 1 % at h 8 and h 4
 *    (1 ppc), and smaller at h 4 than at h 8;
 *  - the dissipation is U0 H (eq. 10 on the open line) within 1e-6.
 * The bounds and their measurements: docs/verification.md, "The exact solution at the
 * grip speed".
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

#include "metrics.h"
#include "mpm.h"
#include "sweep.h"

/* Runs iface90.ini at h, 1 ppc to the end of the curve window; returns the RMS error
 * against the wave solution and the peak, and the dissipation at the end of the run. */
static double run_case(double h, double *peak, double *wave_peak, double *D, double *D_ref)
{
  ver_case c;
  char err[1024];
  if (ver_case_init(&c, DELAM_SRC "/data/scenes/iface90.ini", "iface90", NULL, h, 1, (ver_variant){"", NULL, 0, 0, 0}, err,
                    sizeof err))
    fail_msg("iface90.ini: %s", err);
  const mpm_scene *sc = &c.vs.sc;
  const double dend = ver_curve_end(&c.ana, sc->sep_threshold);
  const ana_wave_params wp = {sc->speed, sc->rho, sc->imp_x, sc->sep_threshold};
  ana_wave w;
  if (ana_wave_init(&c.ana, &wp, dend + 0.2, &w, err, sizeof err) != ANA_OK)
    fail_msg("ana_wave_init: %s", err);
  *wave_peak = ana_wave_peak(&w, NULL);
  mpm_sim *s = NULL;
  if (mpm_sim_alloc(sc, 1, &s, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  double sq = 0.0;
  long m = 0;
  *peak = 0.0;
  /* to the window's end, then on to 0.1 past it for the open line's dissipation */
  while (mpm_sim_delta(s) < dend + 0.1) {
    const mpm_status st = mpm_sim_step(s, err, sizeof err);
    mpm_sim_info in;
    mpm_sim_info_get(s, &in);
    if (st != MPM_OK)
      fail_msg("step %ld: %s", in.step, err);
    const double d = mpm_sim_delta(s), P = in.P_grip;
    *peak = fmax(*peak, P);
    if (d <= dend) {
      const double e = P - ana_wave_load_at(&w, d);
      sq += e * e;
      m++;
    }
  }
  mpm_energy e;
  mpm_sim_energy(s, &e);
  *D = e.D;
  *D_ref = sc->U0 * sc->H;
  mpm_sim_free(s);
  ana_wave_free(&w);
  return sqrt(sq / (double)m) / c.ana.Pmax;
}

static void test_ver_wave_iface90(void **state)
{
  (void)state;
  double e[2], pk, wpk, D, Dref;
  const double hs[2] = {8.0, 4.0};
  for (int i = 0; i < 2; i++) {
    e[i] = run_case(hs[i], &pk, &wpk, &D, &Dref);
    print_message("# h %g: RMS (P - P_wave) / Pmax %.5f, peak %.4f against the exact %.4f, D %.6f\n", hs[i], e[i], pk,
                  wpk, D);
    if (!(e[i] < 0.01))
      fail_msg("h %g: RMS (P - P_wave) / Pmax %.5f, want < 0.01", hs[i], e[i]);
    if (!(fabs(pk / wpk - 1.0) < 0.01))
      fail_msg("h %g: peak %.5f, want the exact solution's %.5f within 1 %%", hs[i], pk, wpk);
    if (!(pk - 32.0 > 0.5 * (wpk - 32.0)))
      fail_msg("h %g: peak %.5f carries less than half the exact overshoot over r0 H (%.5f)", hs[i], pk, wpk);
    if (!(fabs(D - Dref) < 1e-6 * Dref))
      fail_msg("h %g: D %.9g, want U0 H = %g", hs[i], D, Dref);
  }
  if (!(e[1] < e[0]))
    fail_msg("no convergence to the exact solution: h 8 %.5f, h 4 %.5f", e[0], e[1]);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ver_wave_iface90),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
