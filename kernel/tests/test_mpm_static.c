/*
 * test_mpm_static.c - the quasi-static solver (kernel/mpm_static.c) against closed forms:
 * a short bar at alpha 90 whose softening snaps back (g = 0.5, eq. 35) traced through
 * the reversal, its dissipation U0 H, its energy ledger, Newton's quadratic convergence
 * near the solution, and the refusal of a one-point quadrature.
 *
 * The closed form at alpha 90, q 1, Model 1 (docs/model.md sec. 5): peak Pmax = snf H,
 * elastic branch P = E H delta / L, softening branch delta(P) = P L / (E H) + (1 - P / Pmax)
 * U0 / snf, which turns back (d delta / d P > 0) when g = E U0 / (L snf^2) < 1.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_static.h"
#include "test_util.h"

/* A 48 x 8 bar on h 4 at 4 ppc, g = 0.5 (U0 = 0.5 L snf^2 / E), the paper's flaw.  (On
 * h 2 the free band's separation sequence stalls: docs/static.md, "Where it stops".) */
static mpm_scene snap_scene(void)
{
  mpm_scene sc = tu_scene(MPM_DCOH_MODEL1, 90.0, 1.0, 10.0, 1.0, 1.0);
  sc.L = 48.0;
  sc.H = 8.0;
  sc.U0 = 0.5 * 48.0 / 1024.0;
  sc.sep_threshold = 1.0;
  sc.le_mode = MPM_LE_CELL;
  sc.imp_factor = 0.9;
  sc.imp_stf_factor = 1.0;
  sc.imp_x = 24.0;
  sc.imp_y = 4.0;
  sc.h = 4.0;
  sc.ppc = 4;
  sc.margin = 4.0;
  sc.dt = 0.01;
  sc.speed = 0.001;
  sc.end_delta = 0.2;
  sc.solver = MPM_SOLVER_STATIC;
  return sc;
}

/* The same bar with the crack as a cohesive interface (decohesion.path = interface) on
 * the line at alpha through the bar's centre. */
static mpm_scene iface_scene(double alpha)
{
  mpm_scene sc = snap_scene();
  sc.path = MPM_PATH_IFACE;
  sc.shape = MPM_SHAPE_GIMP;
  sc.fields = MPM_FIELDS_TWO;
  sc.scheme = MPM_SCHEME_MUSL;
  sc.imp_factor = 1.0; /* the line through the bar's centre places the crack */
  sc.alpha_deg = alpha;
  return sc;
}

static int cmp_dbl(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

typedef struct {
  double d[4096], P[4096];
  int det[4096];      /* each state's det_sign (mpm_static_stats)                    */
  int crit[4096];     /* the critical point crossed to it (MPM_QS_*, 0 none)         */
  int n;
  double ratio[8192]; /* r_{k+1} / r_k^2 over Newton pairs near a solution             */
  int nquad;          /* how many                                                   */
} trace;

/* Runs the scene's static solver to the cut (or n_max increments), recording the curve
 * and, per increment, Newton's residual ratios r_{k+1} / r_k^2. */
static void run_static(const mpm_scene *sc, trace *t, mpm_energy *e, int n_max)
{
  mpm_sim *s = tu_make_sim(sc, 1);
  mpm_static *q = NULL;
  char err[256] = "";
  if (mpm_static_alloc(s, &q, err, sizeof err) != MPM_OK)
    fail_msg("mpm_static_alloc: %s", err);
  t->n = 0;
  t->nquad = 0;
  t->d[t->n] = 0.0;
  t->P[t->n++] = 0.0;
  /* past the cut to end_delta, for the last particles to open to lambda 1 */
  for (int k = 0; k < n_max && mpm_sim_delta(s) < sc->end_delta && t->n < 4096; k++) {
    if (mpm_static_step(q, err, sizeof err) != MPM_OK)
      fail_msg("increment %d: %s", k, err);
    mpm_static_stats st;
    mpm_static_stats_get(q, &st);
    t->det[t->n] = st.det_sign;
    t->crit[t->n] = st.crit;
    t->d[t->n] = mpm_sim_delta(s);
    t->P[t->n++] = s->P_grip;
    /* pairs from below 1e-3 (near the solution) to above 1e-11 (clear of the rounding
     * of the nodal force sums, about 1e-13 of the load) */
    for (int i = 0; i + 1 < st.nres && t->nquad < 8192; i++)
      if (st.res[i] < 1e-3 && st.res[i + 1] > 1e-11)
        t->ratio[t->nquad++] = st.res[i + 1] / (st.res[i] * st.res[i]);
  }
  mpm_sim_energy(s, e);
  mpm_static_free(q);
  mpm_sim_free(s);
}

/* static-1: the snapback traced: the load falls back to 5 % of Pmax at the closed form's
 * delta (which is below the peak's), the grip moving back by more than a third of the
 * peak's delta on the way; D = U0 H; the ledger W_ext = SE + W_coh to the solver's
 * tolerance; Newton converges quadratically near each solution. */
static void test_mpm_static_snapback(void **state)
{
  (void)state;
  const mpm_scene sc = snap_scene();
  static trace t;
  mpm_energy e;
  run_static(&sc, &t, &e, 2000);
  const double Pmax = sc.snf * sc.H, k = sc.E * sc.H / sc.L, dpk = Pmax / k;
  double peak = 0.0, dmin_after = INFINITY, d5 = NAN;
  int ipk = 0;
  for (int i = 0; i < t.n; i++)
    if (t.P[i] > peak) {
      peak = t.P[i];
      ipk = i;
    }
  for (int i = ipk + 1; i < t.n; i++) {
    dmin_after = fmin(dmin_after, t.d[i]);
    if (isnan(d5) && t.P[i] <= 0.05 * Pmax && t.P[i - 1] > 0.05 * Pmax)
      d5 = t.d[i - 1] + (t.d[i] - t.d[i - 1]) * (t.P[i - 1] - 0.05 * Pmax) / (t.P[i - 1] - t.P[i]);
  }
  const double d5_ana = 0.05 * Pmax / k + 0.95 * sc.U0 / sc.snf;
  print_message("# snapback: peak %.5g (Pmax %g), delta at 5 %% %.6g (closed form %.6g, delta_peak %.6g), least "
                "delta after the peak %.6g, D %.6g (U0 H %.6g), W_ext %.6g SE %.3g W_coh %.6g, %d increments\n",
                peak, Pmax, d5, d5_ana, dpk, dmin_after, e.D, sc.U0 * sc.H, e.W_ext, e.SE, e.W_coh, t.n - 1);
  assert_rel(peak, Pmax, 0.05, "peak load"); /* the flaw is a quarter of a cell of the two across */
  assert_true(dmin_after < 0.65 * dpk); /* the grip moved back: a snapback, not a drop */
  assert_abs(d5, d5_ana, 0.05 * dpk, "delta where the load falls to 5 % of Pmax");
  assert_rel(e.D, sc.U0 * sc.H, 0.01, "dissipation U0 H");
  assert_abs(e.W_ext - e.SE - e.W_coh, 0.0, 1e-6 * e.W_ext, "ledger W_ext = SE + W_coh");
  /* quadratic where the laws are smooth; an iteration that moves a particle across a
   * path switch (elastic to softening, the separation) converges only linearly, so the
   * bound is on the bulk of the pairs: the median, and three quarters below 1e4 */
  qsort(t.ratio, (size_t)t.nquad, sizeof(double), cmp_dbl);
  int below = 0;
  for (int i = 0; i < t.nquad; i++)
    below += t.ratio[i] < 1e4;
  print_message("# Newton: r_{k+1} / r_k^2 median %.3g, %d of %d pairs below 1e4 (largest %.3g)\n",
                t.nquad ? t.ratio[t.nquad / 2] : NAN, below, t.nquad, t.nquad ? t.ratio[t.nquad - 1] : NAN);
  assert_true(t.nquad >= 20);
  assert_true(t.ratio[t.nquad / 2] < 100.0);
  assert_true(4 * below >= 3 * t.nquad);
}

/* static-4: the crack as a cohesive interface at 90 deg (decohesion.path = interface):
 * the uniform state is an exact solution of the discrete problem, so every row lies on
 * the closed form, elastic line and snapback branch, up to where the line's last points
 * separate: the uniform opening is one of the equilibrium branches there, and the
 * factorization's rounding decides whether a point runs a little ahead (measured: 1e-6
 * delta_peak with UMFPACK, 0.0036 with the banded LU); D = U0 H. */
static void test_mpm_static_interface_exact(void **state)
{
  (void)state;
  const mpm_scene sc = iface_scene(90.0);
  static trace t;
  mpm_energy e;
  run_static(&sc, &t, &e, 500);
  const double Pmax = sc.snf * sc.H, k = sc.E * sc.H / sc.L, dpk = Pmax / k;
  double worst = 0.0, dmin = INFINITY, peak = 0.0;
  for (int i = 1; i < t.n; i++) {
    peak = fmax(peak, t.P[i]);
    /* the closed form's delta at this load: on the elastic line before the peak, on the
     * softening branch after it (eq. 34, q 1, alpha 90) */
    const double P = fmax(t.P[i], 0.0);
    const double d_ana = peak < Pmax * (1.0 - 1e-9) ? P / k : P / k + (1.0 - P / Pmax) * sc.U0 / sc.snf;
    if (t.P[i] > 1e-6 * Pmax)
      worst = fmax(worst, fabs(t.d[i] - d_ana) / dpk);
    if (peak >= Pmax * (1.0 - 1e-9))
      dmin = fmin(dmin, t.d[i]);
  }
  print_message("# interface at 90 deg: peak %.9g (Pmax %g), largest delta error %.3g delta_peak, least delta %.6g "
                "(U0 / snf %.6g), D %.9g (U0 H %.9g)\n", peak, Pmax, worst, dmin, sc.U0 / sc.snf, e.D, sc.U0 * sc.H);
  assert_rel(peak, Pmax, 1e-8, "peak");
  assert_true(worst < 5e-3);
  assert_true(dmin < sc.U0 / sc.snf + 0.01 * dpk); /* back to the branch's end, the opening alone */
  assert_rel(e.D, sc.U0 * sc.H, 1e-9, "dissipation U0 H");
}

/* static-5: the interface inclined on the same bar: a uniform stress is a discrete
 * solution there too, so the peak is eq. 30's r0 H, where (r0 sin^2 a / snf)^2 +
 * (r0 sin a cos a / stf)^2 = 1, and D is U0 times the line's length H / sin a.  At 60 deg
 * on h 4 (one segment) this needs the split nodes' ties to sum to zero over the segment
 * (tied to the share-weighted mean: peak 10.577 against 10.649); at 30 deg on h 2 (three
 * segments) it needs each segment's share of the line to be the cross-section that
 * crosses it (both facet families projected on n: peak 29.533 against 31.531, -6.3 %). */
static void run_inclined(double alpha, double h)
{
  mpm_scene sc = iface_scene(alpha);
  sc.h = h;
  sc.end_delta = 0.4;
  static trace t;
  mpm_energy e;
  run_static(&sc, &t, &e, 500);
  const double a = sc.alpha_deg * (3.14159265358979323846 / 180.0), sa = sin(a), ca = cos(a);
  const double r0 = 1.0 / hypot(sa * sa / sc.snf, sa * ca / sc.stf), Pmax = r0 * sc.H;
  double peak = 0.0;
  for (int i = 0; i < t.n; i++)
    peak = fmax(peak, t.P[i]);
  print_message("# interface at %g deg, h %g: peak %.9g (r0 H %.9g), D %.9g (U0 H / sin a %.9g)\n", alpha, h, peak,
                Pmax, e.D, sc.U0 * sc.H / sa);
  assert_rel(peak, Pmax, 1e-6, "peak r0 H");
  assert_rel(e.D, sc.U0 * sc.H / sa, 1e-9, "dissipation U0 H / sin a");
}

static void test_mpm_static_interface_inclined(void **state)
{
  (void)state;
  run_inclined(60.0, 4.0);
  run_inclined(30.0, 2.0);
}

/* The sign of a tridiagonal matrix's determinant (diagonal a, both off-diagonals b) from
 * its three-term recurrence f_k = a_k f_{k-1} - b^2 f_{k-2}, rescaled as it goes. */
static int tridiag_det_sign(const double *a, int n, double b)
{
  double f0 = 1.0, f1 = a[0];
  for (int k = 1; k < n; k++) {
    const double f2 = a[k] * f1 - b * b * f0, m = fmax(fabs(f2), fabs(f1));
    f0 = f1 / m;
    f1 = f2 / m;
  }
  return (f1 > 0.0) - (f1 < 0.0);
}

/* mpm_lin_det_sign on tridiagonal matrices whose off-diagonal outweighs the diagonal (the
 * LU exchanges rows), against the recurrence: banded (n 12) and UMFPACK (n 400 with a
 * zero in the far corners, bandwidth 399 > the band's limit). */
static void det_case(int n, int corner, unsigned seed)
{
  int ti[2000], tj[2000], map[2000];
  double a[400];
  size_t nz = 0;
  for (int i = 0; i < n; i++)
    for (int j = i - 1; j <= i + 1; j++)
      if (j >= 0 && j < n) {
        ti[nz] = i;
        tj[nz++] = j;
      }
  if (corner) {
    ti[nz] = 0, tj[nz++] = n - 1;
    ti[nz] = n - 1, tj[nz++] = 0;
  }
  for (int trial = 0; trial < 20; trial++) {
    mpm_lin *l = mpm_lin_alloc(n, nz, ti, tj, map);
    assert_non_null(l);
    double *x = mpm_lin_values(l);
    for (int i = 0; i < n; i++) {
      seed = seed * 1103515245u + 12345u;
      a[i] = ((double)(seed >> 8 & 0xffff) / 65536.0 - 0.5) * 3.0; /* in (-1.5, 1.5), b = 1 */
    }
    for (size_t k = 0; k < nz; k++)
      x[map[k]] = ti[k] == tj[k] ? a[ti[k]] : abs(ti[k] - tj[k]) == 1 ? 1.0 : 0.0;
    assert_int_equal(mpm_lin_factor(l), MPM_OK);
    assert_int_equal(mpm_lin_det_sign(l), tridiag_det_sign(a, n, 1.0));
    mpm_lin_free(l);
  }
}

/* static-6: stability.  The determinant's sign on matrices of known sign; then along
 * the interface at 90 deg, where the closed form is a 1-D chain, the bar's stiffness
 * k = E H / L in series with the line's softening slope -k_s: under the grip held the
 * state's stiffness is k - k_s, negative on a snapback branch (g < 1: delta falls with the
 * load) and positive on a branch with g > 1.  So det_sign is +1 on the elastic rows,
 * -1 on every row of the snapback between 5 % and 95 % of Pmax (g 0.5) and +1 on every
 * row at g 2; the first critical point is at the peak. */
static void stab_case(double g)
{
  mpm_scene sc = iface_scene(90.0);
  sc.U0 = g * sc.L * sc.snf * sc.snf / sc.E;
  sc.end_delta = 0.2 + sc.U0 / sc.snf;
  static trace t;
  mpm_energy e;
  run_static(&sc, &t, &e, 500);
  const double Pmax = sc.snf * sc.H;
  int ipk = 0, first = 0, on = 0, wrong = 0;
  for (int i = 1; i < t.n; i++) {
    ipk = t.P[i] > t.P[ipk] ? i : ipk;
    first = first ? first : t.crit[i] ? i : 0;
  }
  for (int i = 1; i < t.n; i++) {
    /* (the rows at the peak, the tie at initiation, not judged) */
    const int band = t.P[i] > 0.05 * Pmax && t.P[i] < 0.95 * Pmax;
    const int want = i < ipk && t.P[i] < 0.95 * Pmax ? 1 : i > ipk && band ? (g < 1.0 ? -1 : 1) : 0;
    on += want != 0;
    wrong += want != 0 && t.det[i] != want;
  }
  print_message("# stability at g %g: %d rows judged, %d with the wrong sign; peak at row %d, first critical point "
                "at row %d (kind %d)\n", g, on, wrong, ipk, first, first ? t.crit[first] : 0);
  assert_true(on >= 10);
  assert_int_equal(wrong, 0);
  if (g < 1.0) /* the sign changes at the peak's row or within the 3 grip increments that
                  start the softening from the tie (det_sign 0 on them) */
    assert_true(first >= ipk && first <= ipk + 4);
  else
    assert_int_equal(first, 0);
}

static void test_mpm_static_stability(void **state)
{
  (void)state;
  det_case(12, 0, 7u);
  det_case(400, 1, 11u);
  stab_case(0.5);
  stab_case(2.0);
}

/* The low-rank update (mpm_static_lin.c) on a 100 x 100 grid's five-point matrix, whose
 * factorization costs enough to keep a base: each system solved after a change is judged
 * against a fresh factorization of the same values, and the determinant's sign against
 * what the change must give.  1 x 1: one diagonal entry sent to -1000 (the rest, reduced
 * by the entry's small Schur term, stays positive definite: det < 0); a stiff tie (1e5 on
 * a pair of neighbours, the interface's tie before it lets go) removed from the base;
 * a change on every unknown (no update: a factorization on its own); a base near singular
 * (no update on it). */
#define LR_N 100
static int lr_pattern(int *ti, int *tj)
{
  int nz = 0;
  for (int y = 0; y < LR_N; y++)
    for (int x = 0; x < LR_N; x++) {
      const int i = y * LR_N + x;
      const int nb[5][2] = {{x, y}, {x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (int k = 0; k < 5; k++)
        if (nb[k][0] >= 0 && nb[k][0] < LR_N && nb[k][1] >= 0 && nb[k][1] < LR_N) {
          ti[nz] = i;
          tj[nz++] = nb[k][1] * LR_N + nb[k][0];
        }
    }
  return nz;
}

/* values: 4.01 on the diagonal, -1 off it, plus `tie` between unknowns t0 and t0 + 1 */
static void lr_values(mpm_lin *l, const int *ti, const int *tj, const int *map, int nz, int t0, double tie)
{
  double *x = mpm_lin_values(l);
  memset(x, 0, sizeof(double) * mpm_lin_nnz(l));
  for (int k = 0; k < nz; k++) {
    const int pair = (ti[k] == t0 || ti[k] == t0 + 1) && (tj[k] == t0 || tj[k] == t0 + 1);
    x[map[k]] += (ti[k] == tj[k] ? 4.01 : -1.0) + (pair ? (ti[k] == tj[k] ? tie : -tie) : 0.0);
  }
}

/* max |x - x_fresh| / max |x_fresh| for the values held by l, x_fresh from a new LU */
static double lr_err(mpm_lin *l, const int *ti, const int *tj, int nz, const double *b, double *x, double *y)
{
  static int map2[5 * LR_N * LR_N];
  mpm_lin *f = mpm_lin_alloc(LR_N * LR_N, (size_t)nz, ti, tj, map2);
  assert_non_null(f);
  memcpy(mpm_lin_values(f), mpm_lin_values(l), sizeof(double) * mpm_lin_nnz(l));
  assert_int_equal(mpm_lin_factor(f), MPM_OK);
  assert_int_equal(mpm_lin_solve(f, b, y), MPM_OK);
  assert_int_equal(mpm_lin_solve(l, b, x), MPM_OK);
  double e = 0.0, m = 0.0;
  for (int i = 0; i < LR_N * LR_N; i++) {
    e = fmax(e, fabs(x[i] - y[i]));
    m = fmax(m, fabs(y[i]));
  }
  mpm_lin_free(f);
  return e / m;
}

static void test_mpm_static_lowrank(void **state)
{
  (void)state;
  static int ti[5 * LR_N * LR_N], tj[5 * LR_N * LR_N], map[5 * LR_N * LR_N];
  static double b[LR_N * LR_N], x[LR_N * LR_N], y[LR_N * LR_N];
  const int nz = lr_pattern(ti, tj), n = LR_N * LR_N, i0 = 50 * LR_N + 50;
  for (int i = 0; i < n; i++)
    b[i] = sin(0.37 * i) + 0.1;
  for (int tie = 0; tie < 2; tie++) {
    mpm_lin *l = mpm_lin_alloc(n, (size_t)nz, ti, tj, map);
    assert_non_null(l);
    lr_values(l, ti, tj, map, nz, i0, tie ? 1e5 : 0.0);
    assert_int_equal(mpm_lin_factor(l), MPM_OK); /* the base */
    assert_int_equal(mpm_lin_updated(l), 0);
    assert_int_equal(mpm_lin_det_sign(l), 1);
    double *v = mpm_lin_values(l);
    if (tie) /* the tie lets go */
      lr_values(l, ti, tj, map, nz, i0, 0.0);
    else
      for (int k = 0; k < nz; k++)
        if (ti[k] == i0 && tj[k] == i0)
          v[map[k]] = -1000.0;
    assert_int_equal(mpm_lin_factor(l), MPM_OK);
    assert_int_equal(mpm_lin_updated(l), 1);
    assert_int_equal(mpm_lin_det_sign(l), tie ? 1 : -1);
    const double e = lr_err(l, ti, tj, nz, b, x, y);
    print_message("# low-rank update (%s): solution within %.2e of a fresh LU's\n", tie ? "a tie of 1e5 let go" : "one entry -1000", e);
    assert_true(e < 1e-9);
    for (int k = 0; k < nz; k++) /* every unknown: a factorization on its own */
      if (ti[k] == tj[k])
        v[map[k]] = 5.0;
    assert_int_equal(mpm_lin_factor(l), MPM_OK);
    assert_int_equal(mpm_lin_updated(l), 0);
    assert_int_equal(mpm_lin_det_sign(l), 1);
    assert_true(lr_err(l, ti, tj, nz, b, x, y) < 1e-12);
    mpm_lin_free(l);
  }
  /* a base whose pivots spread past 1e-9 (one particle a cell's hourglass modes): no
   * update on it, each change factorized and solved as a fresh LU would */
  mpm_lin *l = mpm_lin_alloc(n, (size_t)nz, ti, tj, map);
  assert_non_null(l);
  lr_values(l, ti, tj, map, nz, i0, 0.0);
  double *v = mpm_lin_values(l);
  for (int k = 0; k < nz; k++) { /* unknowns 0, 1 cut loose: [[1, -1], [-1, 1 + 1e-12]] */
    const int in_i = ti[k] < 2, in_j = tj[k] < 2;
    if (in_i != in_j)
      v[map[k]] = 0.0;
    else if (in_i)
      v[map[k]] = ti[k] != tj[k] ? -1.0 : ti[k] == 0 ? 1.0 : 1.0 + 1e-12;
  }
  assert_int_equal(mpm_lin_factor(l), MPM_OK);
  for (int k = 0; k < nz; k++)
    if (ti[k] == i0 && tj[k] == i0)
      v[map[k]] = 5.0;
  assert_int_equal(mpm_lin_factor(l), MPM_OK);
  assert_int_equal(mpm_lin_updated(l), 0);
  assert_true(lr_err(l, ti, tj, nz, b, x, y) < 1e-12);
  mpm_lin_free(l);
}

/* static-2: the elastic bar: the first increments lie on P = E H delta / L (a linear
 * problem, exact to the solver's tolerance), whatever the flaw. */
static void test_mpm_static_elastic(void **state)
{
  (void)state;
  mpm_scene sc = snap_scene();
  static trace t;
  mpm_energy e;
  run_static(&sc, &t, &e, 4);
  const double k = sc.E * sc.H / sc.L;
  for (int i = 1; i < t.n; i++)
    assert_rel(t.P[i], k * t.d[i], 1e-8, "elastic load");
}

/* static-3: one particle per cell is refused with MPM_EINVAL and why: on bilinear shapes
 * (hourglass modes), and with softening particles on any shape (the band stalls). */
static void refuse_case(int shape, int model, const char *why)
{
  mpm_scene sc = snap_scene();
  sc.ppc = 1;
  sc.shape = shape;
  sc.model = model;
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_static *q = NULL;
  char err[400] = "";
  assert_int_equal(mpm_static_alloc(s, &q, err, sizeof err), MPM_EINVAL);
  assert_null(q);
  if (!strstr(err, why))
    fail_msg("message lacks '%s': %s", why, err);
  mpm_sim_free(s);
}

static void test_mpm_static_refuses_one_point(void **state)
{
  (void)state;
  refuse_case(MPM_SHAPE_LINEAR, MPM_DCOH_NONE, "hourglass");
  refuse_case(MPM_SHAPE_GIMP, MPM_DCOH_MODEL1, "stalls");
}


/* The interface's law (mpm_static_seg_law) on its own: after a softening step the traction
 * lies on the strength (eq. 23, F = 0), the opening increment is along the flow at the
 * step's end (eqs. 19, 24: d ud parallel to (<sn> / snf^2, st / stf^2)), and the tangent
 * d t / d w, d lambda / d w matches central differences.  Angles, strengths, states and
 * jumps (opening, sliding, closing) spread over the scenes' range; k0 as the solver's. */
static void test_mpm_static_seg_law(void **state)
{
  (void)state;
  const double angles[] = {30.0, 45.0, 60.0, 90.0}, lams[] = {0.0, 0.3, 0.7};
  const double dirs[][2] = {{1.0, 0.0}, {0.6, 0.8}, {-0.3, 1.0}, {1.0, -0.5}};
  const double str[][2] = {{1.0, 10.0}, {10.0, 1.0}};
  int cases = 0;
  double worst_F = 0.0, worst_par = 0.0, worst_fd = 0.0;
  for (size_t ia = 0; ia < sizeof angles / sizeof angles[0]; ia++)
    for (size_t is = 0; is < 2; is++)
      for (size_t il = 0; il < sizeof lams / sizeof lams[0]; il++)
        for (size_t id = 0; id < sizeof dirs / sizeof dirs[0]; id++) {
          mpm_scene sc = tu_scene(MPM_DCOH_MODEL1, angles[ia], str[is][0], str[is][1], str[is][0], 1.0);
          sc.sep_threshold = 1.0;
          mpm_material m;
          mpm_material_init(&m, &sc, sc.snf, 1.0);
          m.E1 = m.G = 1e6 * 1024.0 / 192.0; /* the solver's tie */
          m.E2 = m.E1 - 2.0 * m.G;
          m.Le = 1.0;
          mpm_material_derive(&m);
          /* a state on its strength: traction (sn, st) with se = 1 - lambda, along the flow
           * direction of this jump's (n, t) components */
          const double lam = lams[il], dn = dirs[id][0], dt = dirs[id][1];
          const double an = dn > 0.0 ? dn * sc.snf : dn, at = dt * sc.stf;
          const double se = hypot(an > 0.0 ? an / sc.snf : 0.0, at / sc.stf), S0 = 1.0 - lam;
          const double sn0 = an * S0 / se, st0 = at * S0 / se;
          mpm_dstate in = {0};
          in.lam = lam;
          in.sxx = sn0 * m.nx * m.nx + 2.0 * st0 * m.nx * m.tx;
          in.syy = sn0 * m.ny * m.ny + 2.0 * st0 * m.ny * m.ty;
          in.sxy = sn0 * m.nx * m.ny + st0 * (m.nx * m.ty + m.ny * m.tx);
          /* a jump increment that opens it by a tenth of ubar0 along (dn, dt) */
          const double a = 0.1 * m.ubar0 / hypot(dn, dt);
          const double w[2] = {a * (dn * m.nx + dt * m.tx), a * (dn * m.ny + dt * m.ty)};
          mpm_dstate out;
          double wk, S[2][2], gl[2];
          if (!mpm_static_seg_law(&m, &in, w, &out, &wk, S, gl))
            continue; /* past separation: the law's separation */
          if (!(out.lam > lam))
            continue; /* elastic (closing) */
          cases++;
          worst_F = fmax(worst_F, fabs(mpm_dcoh_F(&m, out.sxx, out.syy, out.sxy, out.lam)));
          const double sn = out.sxx * m.nx * m.nx + 2.0 * out.sxy * m.nx * m.ny + out.syy * m.ny * m.ny;
          const double st = out.sxx * m.nx * m.tx + out.sxy * (m.nx * m.ty + m.ny * m.tx) + out.syy * m.ny * m.ty;
          const double gn = sn > 0.0 ? sn / (sc.snf * sc.snf) : 0.0, gt = st / (sc.stf * sc.stf);
          const double un = out.upn - in.upn, ut = out.upt - in.upt;
          worst_par = fmax(worst_par, fabs(un * gt - ut * gn) / (hypot(un, ut) * hypot(gn, gt)));
          for (int c = 0; c < 2; c++) {
            const double hstep = 1e-7 * m.ubar0;
            double wp[2] = {w[0], w[1]}, wm[2] = {w[0], w[1]};
            wp[c] += hstep;
            wm[c] -= hstep;
            mpm_dstate op, om;
            double S2[2][2], g2[2];
            assert_true(mpm_static_seg_law(&m, &in, wp, &op, &wk, S2, g2));
            assert_true(mpm_static_seg_law(&m, &in, wm, &om, &wk, S2, g2));
            const double tp[2] = {op.sxx * m.nx + op.sxy * m.ny, op.sxy * m.nx + op.syy * m.ny};
            const double tm[2] = {om.sxx * m.nx + om.sxy * m.ny, om.sxy * m.nx + om.syy * m.ny};
            for (int r = 0; r < 2; r++) {
              const double fd = (tp[r] - tm[r]) / (2.0 * hstep);
              worst_fd = fmax(worst_fd, fabs(fd - S[r][c]) / (fabs(fd) + 1e-3 * m.E1 * 1e-6 + 1.0));
            }
            const double fl = (op.lam - om.lam) / (2.0 * hstep);
            worst_fd = fmax(worst_fd, fabs(fl - gl[c]) / (fabs(fl) + 1.0));
          }
        }
  print_message("# seg_law: %d softening cases, |F| <= %.2g, flow misalignment <= %.2g, tangent vs FD <= %.2g\n",
                cases, worst_F, worst_par, worst_fd);
  assert_true(cases >= 40);
  assert_true(worst_F < 1e-9);
  assert_true(worst_par < 1e-6);
  assert_true(worst_fd < 1e-4);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_mpm_static_elastic),
    cmocka_unit_test(test_mpm_static_seg_law),
    cmocka_unit_test(test_mpm_static_snapback),
    cmocka_unit_test(test_mpm_static_interface_exact),
    cmocka_unit_test(test_mpm_static_interface_inclined),
    cmocka_unit_test(test_mpm_static_refuses_one_point),
    cmocka_unit_test(test_mpm_static_stability),
    cmocka_unit_test(test_mpm_static_lowrank),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
