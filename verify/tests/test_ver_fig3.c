/*
 * test_ver_fig3.c - two of Fig. 3's bars computed by the kernel against eq. 34, as the
 * report draws them (report_qs.c): iface90.ini on the quasi-static solver at h 8, 4 ppc
 * with g = 0.75 (eq. 35) and q = 1.2 (a snapback with q other than 1) or q = 0.8 (a
 * branch that leaves the peak with an infinite slope).
 *  - fig3-1: every softening row (0.05 < sigma* < 0.95) lies on eq. 34,
 *    E e_ave / r0 = s* + (1 - s*)^(1/q) g, within 1e-4;
 *  - fig3-2: the grip moved back on the way (least E e / r0 after the peak below 0.85):
 *    a snapback traced, not a drop;
 *  - fig3-3: the distance from the analytic path under 0.005 (delam check's static bound);
 *  - fig3-4: the dissipation is U0 H (eq. 10 with the line open) within 1e-6.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>
#include <dirent.h>

#include "io.h"
#include "metrics.h"
#include "run.h"
#include "scene.h"

#define G 0.75

static void run_bar(double Q)
{
  ver_scene vs;
  char err[1024], dir[] = "/tmp/test_ver_fig3.XXXXXX", num[40], set[96], qset[64];
  if (ver_scene_parse(DELAM_SRC "/data/scenes/iface90.ini", &vs, err, sizeof err))
    fail_msg("iface90.ini: %s", err);
  const double E = vs.sc.E, L = vs.sc.L, H = vs.sc.H, r0 = vs.sc.snf; /* alpha 90: r0 = snf */
  assert_true(vs.sc.alpha_deg == 90.0);
  ver_scene_fmt_num(G * L * r0 * r0 / E, num, sizeof num); /* eq. 35 */
  snprintf(set, sizeof set, "decohesion.U0=%s", num);
  snprintf(qset, sizeof qset, "decohesion.q=%g", Q);
  const char *sets[] = {"solver.type=static", qset, set, "grid.h=8", "grid.ppc=4"};
  for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++)
    if (ver_scene_set(&vs, sets[i], err, sizeof err))
      fail_msg("%s: %s", sets[i], err);
  if (ver_scene_validate(&vs, err, sizeof err))
    fail_msg("validate: %s", err);
  assert_non_null(mkdtemp(dir));
  const ver_run_opts o = {dir, 0, 1, NULL, 0, 1};
  ver_summary u;
  if (ver_run(&vs, &o, &u, err, sizeof err) != 0)
    fail_msg("run: %s", err);
  char p[512];
  snprintf(p, sizeof p, "%s/load.csv", dir);
  static const char *const cols[2] = {"delta", "P_grip"};
  double *v[2];
  const long n = ver_csv_read(p, cols, 2, v);
  assert_true(n > 10);
  long ipk = 0;
  for (long i = 0; i < n; i++)
    if (v[1][i] > v[1][ipk])
      ipk = i;
  double worst = 0, least = INFINITY;
  int rows = 0;
  for (long i = ipk + 1; i < n; i++) {
    const double s = v[1][i] / (H * r0), e = v[0][i] / L * E / r0;
    least = fmin(least, e);
    if (s > 0.05 && s < 0.95) {
      worst = fmax(worst, fabs(e - (s + pow(1 - s, 1 / Q) * G))); /* eq. 34 */
      rows++;
    }
  }
  ana_bar b;
  if (ver_scene_bar(&vs.sc, &b, err, sizeof err))
    fail_msg("bar: %s", err);
  double d5;
  const double path = ver_curve_path(&b, v[0], v[1], (size_t)n, &d5);
  print_message("# fig3 q %g g %g: %d softening rows, largest |E e / r0 - eq. 34| %.4g, least E e / r0 after the "
                "peak %.4g, curve_path %.4g, delta_5 %+.4g, D %.8g (U0 H %.8g), %ld increments\n",
                Q, G, rows, worst, least, path, d5, u.D_final, vs.sc.U0 * H, u.steps);
  assert_true(rows >= 5);
  assert_true(worst < 1e-4);                              /* fig3-1 */
  assert_true(least < 0.85);                              /* fig3-2 */
  assert_true(path < 0.005);                              /* fig3-3 */
  assert_true(fabs(u.D_final / (vs.sc.U0 * H) - 1) < 1e-6); /* fig3-4 */
  free(v[0]);
  free(v[1]);
  /* the run's files (load, energy, snapshots, summary), then its folder */
  DIR *d = opendir(dir);
  for (const struct dirent *f = d ? readdir(d) : NULL; f; f = readdir(d))
    if (strcmp(f->d_name, ".") && strcmp(f->d_name, "..")) { /* .delam.lock too */
      snprintf(p, sizeof p, "%s/%s", dir, f->d_name);
      unlink(p);
    }
  if (d)
    closedir(d);
  rmdir(dir);
}

static void test_ver_fig3_q12_g075(void **state)
{
  (void)state;
  run_bar(1.2);
}

static void test_ver_fig3_q08_g075(void **state)
{
  (void)state;
  run_bar(0.8);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ver_fig3_q12_g075),
      cmocka_unit_test(test_ver_fig3_q08_g075),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
