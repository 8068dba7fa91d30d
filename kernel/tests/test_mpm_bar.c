/*
 * test_mpm_bar.c - the MPM step (sec. 2, eqs. 2-7) on whole bars, against laws and
 * closed forms that do not come from the code:
 *  - total momentum is conserved without boundary conditions (sum_i f_i = 0 because
 *    sum_i grad N_i = 0), in both USL and MUSL;
 *  - an elastic bar pulled at its end has the static stiffness E H / L (uniaxial
 *    stress, plane stress: the lateral faces are free), and the reaction at the fixed
 *    end equals the pull (equilibrium);
 *  - energy balance W_ext + KE(0) = KE + SE, and SE = k delta^2 / 2;
 *  - the Fig. 6 bar with decohesion: peak snf H, work to separation UF H (eq. 25),
 *    dissipation U0 H, and the balance with the traction work;
 *  - results do not depend on the number of threads (bit for bit: mpm.h promises it);
 *  - the error paths: each rule of mpm_scene_check, a particle that leaves the grid,
 *    a non-finite position.
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

/* The Fig. 6 bar (L 192, H 32, E 1024, nu 0.25, rho 1), elastic, h 8, dt 0.1. */
static mpm_scene fig6_scene(void)
{
  mpm_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.le_factor = 1.0;
  sc.L = 192.0;
  sc.H = 32.0;
  sc.E = 1024.0;
  sc.nu = 0.25;
  sc.rho = 1.0;
  sc.model = MPM_DCOH_NONE;
  sc.alpha_deg = 90.0;
  sc.snf = 1.0;
  sc.stf = 10.0;
  sc.U0 = 0.375;
  sc.s0 = 1.0;
  sc.q = 1.0;
  sc.sep_threshold = 0.98;
  sc.le_mode = MPM_LE_CELL;
  sc.imp_factor = 1.0;
  sc.imp_stf_factor = 1.0;
  sc.imp_x = 96.0;
  sc.imp_y = 16.0;
  sc.h = 8.0;
  sc.ppc = 4;
  sc.margin = 8.0;
  sc.scheme = MPM_SCHEME_USL;
  sc.dt = 0.1;
  sc.speed = 0.001;
  sc.end_delta = 0.1;
  return sc;
}

/* (a) Without boundary conditions the grid forces sum to zero, so the particles' total
 * momentum is that of the start, to rounding (scale: sum m |v|), under a translating,
 * rotating and random velocity field that also shears and stresses the bar. */
/* A free 16 x 8 block on an h 2 grid (the Fig. 6 material), for the free-body tests. */
static mpm_scene block_scene(int ppc, double margin)
{
  mpm_scene sc = fig6_scene();
  sc.L = 16.0;
  sc.H = 8.0;
  sc.h = 2.0;
  sc.ppc = ppc;
  sc.margin = margin;
  return sc;
}

/* No grip, no fixed end: the fixed-y node is moved to a corner of the padding, which
 * never carries mass. */
static void release_block(mpm_sim *s)
{
  s->nbc = 0;
}

static void momentum_case(int scheme, int shape)
{
  mpm_scene sc = block_scene(4, 6.0);
  sc.scheme = scheme;
  sc.shape = shape;
  sc.dt = 0.2 * sqrt(2.0) * mpm_scene_dt_crit(&sc); /* 0.2 h / c, as written for */
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_particles *p = s->p;
  uint64_t seed = 2024 + (uint64_t)scheme;
  const double cx = 8.0, cy = 4.0, om = 0.002; /* slow: a momentum test, not a cell-crossing one */
  for (size_t k = 0; k < p->n; k++) {
    p->vx[k] = 0.03 - om * (p->y[k] - cy) + 0.005 * (urand(&seed) - 0.5);
    p->vy[k] = -0.02 + om * (p->x[k] - cx) + 0.005 * (urand(&seed) - 0.5);
  }
  release_block(s); /* checked below: the corner never carries mass */
  double px0, py0, scale = 0.0;
  mpm_particles_momentum(p, &px0, &py0);
  for (size_t k = 0; k < p->n; k++)
    scale += p->m[k] * hypot(p->vx[k], p->vy[k]);
  double smax = 0.0;
  for (int k = 0; k < 200; k++) {
    tu_run_steps(s, 1);
    assert_true(s->g->nd[0].m == 0.0);
    double px, py;
    mpm_particles_momentum(s->p, &px, &py);
    assert_abs(px, px0, 1e-12 * scale, scheme ? "MUSL: x momentum" : "USL: x momentum");
    assert_abs(py, py0, 1e-12 * scale, scheme ? "MUSL: y momentum" : "USL: y momentum");
  }
  for (size_t k = 0; k < s->p->n; k++)
    smax = fmax(smax, fabs(s->p->sxx[k]) + fabs(s->p->syy[k]) + fabs(s->p->sxy[k]));
  /* the random field did load the bar, so the forces were not trivially zero */
  assert_true(smax > 1e-3);
  /* the centre of mass moved with the constant momentum: x_c(t) = x_c(0) + P t / M */
  double M = 0.0, xc = 0.0, yc = 0.0;
  for (size_t k = 0; k < s->p->n; k++) {
    M += s->p->m[k];
    xc += s->p->m[k] * (s->p->x[k] - s->p->x0[k]);
    yc += s->p->m[k] * (s->p->y[k] - s->p->y0[k]);
  }
  assert_rel(xc / M, px0 / M * s->t, 1e-9, "centre of mass drift x");
  assert_rel(yc / M, py0 / M * s->t, 1e-9, "centre of mass drift y");
  mpm_sim_free(s);
}

static void test_mpm_bar_momentum_usl(void **state)
{
  (void)state;
  momentum_case(MPM_SCHEME_USL, MPM_SHAPE_LINEAR);
  momentum_case(MPM_SCHEME_USL, MPM_SHAPE_GIMP);
}

static void test_mpm_bar_momentum_musl(void **state)
{
  (void)state;
  momentum_case(MPM_SCHEME_MUSL, MPM_SHAPE_LINEAR);
  momentum_case(MPM_SCHEME_MUSL, MPM_SHAPE_GIMP);
}

/* Shared by (b), (c), (d): the elastic Fig. 6 bar pulled to delta = 0.1 (1000 steps),
 * windowed averages of the loads. */
#define NWIN 20
typedef struct {
  double delta[NWIN], Pg[NWIN], Pf[NWIN];
  mpm_energy e;
  double KE0;
} elastic_run;

static void run_elastic(int scheme, int ppc, int shape, elastic_run *r)
{
  mpm_scene sc = fig6_scene();
  sc.scheme = scheme;
  sc.shape = shape;
  sc.ppc = ppc;
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_energy e0;
  mpm_sim_energy(s, &e0);
  r->KE0 = e0.KE;
  const long nsteps = lround(sc.end_delta / (sc.speed * sc.dt)), per = nsteps / NWIN;
  for (int w = 0; w < NWIN; w++) {
    double sg = 0.0, sf = 0.0, sd = 0.0;
    for (long k = 0; k < per; k++) {
      tu_run_steps(s, 1);
      sg += s->P_grip;
      sf += s->P_fixed;
      sd += mpm_sim_delta(s);
    }
    r->Pg[w] = sg / per;
    r->Pf[w] = sf / per;
    r->delta[w] = sd / per;
  }
  assert_rel(mpm_sim_delta(s), sc.end_delta, 1e-9, "end delta");
  mpm_sim_energy(s, &r->e);
  mpm_sim_free(s);
}

/* least-squares slope and intercept of y on x */
static void lsq(const double *x, const double *y, int n, double *slope, double *icpt)
{
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (int i = 0; i < n; i++) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  *slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  *icpt = (sy - *slope * sx) / n;
}

/* (b) stiffness E H / L = 1024 * 32 / 192 = 170.67 within 1 % (grip and fixed end),
 * and (d) energy: W_ext + KE(0) = KE + SE within 1 %, SE = k delta^2 / 2 within 2 %. */
static void elastic_case(int scheme, int ppc, int shape)
{
  const double k_exact = 1024.0 * 32.0 / 192.0, d_end = 0.1;
  elastic_run r;
  run_elastic(scheme, ppc, shape, &r);
  double kg, ig, kf, iff;
  lsq(r.delta, r.Pg, NWIN, &kg, &ig);
  lsq(r.delta, r.Pf, NWIN, &kf, &iff);
  char what[96];
  snprintf(what, sizeof what, "scheme %d ppc %d shape %d: grip stiffness vs E H / L", scheme, ppc, shape);
  assert_rel(kg, k_exact, 0.01, what);
  snprintf(what, sizeof what, "scheme %d ppc %d: fixed-end stiffness vs E H / L", scheme, ppc);
  assert_rel(kf, k_exact, 0.01, what);
  /* the line goes through the origin: |intercept| small against the final load */
  assert_abs(ig, 0.0, 0.01 * k_exact * d_end, "grip load intercept");
  const double lhs = r.e.W_ext + r.KE0, rhs = r.e.KE + r.e.SE;
  snprintf(what, sizeof what, "scheme %d ppc %d: W_ext + KE0 vs KE + SE", scheme, ppc);
  assert_rel(lhs, rhs, 0.01, what);
  assert_rel(r.e.SE, 0.5 * k_exact * d_end * d_end, 0.02, "SE vs k delta^2 / 2");
  assert_true(r.e.W_coh == 0.0 && r.e.D == 0.0); /* model 0: nothing on a failure plane */
}

static void test_mpm_bar_elastic_stiffness_energy(void **state)
{
  (void)state;
  elastic_case(MPM_SCHEME_USL, 4, MPM_SHAPE_LINEAR);
  elastic_case(MPM_SCHEME_USL, 1, MPM_SHAPE_LINEAR);
  elastic_case(MPM_SCHEME_MUSL, 4, MPM_SHAPE_LINEAR);
  elastic_case(MPM_SCHEME_USL, 1, MPM_SHAPE_GIMP);
  elastic_case(MPM_SCHEME_MUSL, 4, MPM_SHAPE_GIMP);
}

/* Fig. 6 with decohesion (Model 1, alpha 90, q 1, imperfection 0.9 at the centre),
 * pulled to delta 0.45, past separation (analytic: peak at 0.1875, separation at
 * 0.375, docs/model.md sec. 5).  Against eq. 25 and the closed-form bar:
 *   peak load Pmax = snf H = 32 (the imperfection is one particle: within 3 %);
 *   external work to separation = UF x failure area = (q U0 / (q + 1)) H = 6;
 *   traction work on the failure plane W_coh = 6 as well (sec. 3: UF);
 *   dissipation D = U0 H = 12 (lambda ~ 1 over one band of cells, Le = h);
 *   energy balance W_ext + KE(0) = KE + SE + W_coh, to 1 % of W_ext;
 *   the separated bar carries (almost) nothing: |P| < 3 % of the peak at the end. */
static void fig6_decohesion_case(int scheme, int shape, int le_mode)
{
  mpm_scene sc = fig6_scene();
  sc.le_mode = le_mode;
  sc.model = MPM_DCOH_MODEL1;
  sc.imp_factor = 0.9;
  sc.end_delta = 0.45;
  sc.scheme = scheme;
  sc.shape = shape;
  mpm_sim *s = tu_make_sim(&sc, 1);
  mpm_energy e0, e;
  mpm_sim_energy(s, &e0);
  const long nsteps = lround(sc.end_delta / (sc.speed * sc.dt));
  double Pmax = 0.0, Pend = 0.0;
  for (long k = 0; k < nsteps; k++) {
    tu_run_steps(s, 1);
    Pmax = fmax(Pmax, s->P_grip);
    if (k >= nsteps - 100)
      Pend += s->P_grip / 100.0; /* averaged over the last 100 steps */
  }
  mpm_sim_energy(s, &e);
  const double H = sc.H, UF = sc.q * sc.U0 / (sc.q + 1.0);
  char what[96];
  snprintf(what, sizeof what, "scheme %d shape %d: peak load vs snf H", scheme, shape);
  assert_rel(Pmax, sc.snf * H, 0.03, what);
  /* Le = row counts the neighbour columns' slight softening past the peak into the
   * zone's width, so the band's own particles are charged a little less (measured
   * h 8 4 ppc: W_ext -2.1 %, D -1.1 %): 3 % for the works there */
  const double tolw = le_mode == MPM_LE_ROW ? 0.03 : 0.02;
  snprintf(what, sizeof what, "scheme %d shape %d: W_ext vs UF H", scheme, shape);
  assert_rel(e.W_ext, UF * H, tolw, what);
  snprintf(what, sizeof what, "scheme %d shape %d: W_coh vs UF H", scheme, shape);
  assert_rel(e.W_coh, UF * H, tolw, what);
  snprintf(what, sizeof what, "scheme %d shape %d: dissipation vs U0 H", scheme, shape);
  assert_rel(e.D, sc.U0 * H, 0.02, what);
  snprintf(what, sizeof what, "scheme %d shape %d: W_ext + KE0 - (KE + SE + W_coh)", scheme, shape);
  assert_abs(e.W_ext + e0.KE - (e.KE + e.SE + e.W_coh), 0.0, 0.01 * e.W_ext, what);
  snprintf(what, sizeof what, "scheme %d shape %d: load after separation", scheme, shape);
  assert_abs(Pend, 0.0, 0.03 * Pmax, what);
  assert_true(s->n_separate >= (long)(H / sc.h)); /* at least one band across the bar */
  mpm_sim_free(s);
}

static void test_mpm_bar_fig6_decohesion_energy(void **state)
{
  (void)state;
  fig6_decohesion_case(MPM_SCHEME_USL, MPM_SHAPE_LINEAR, MPM_LE_CELL);
  fig6_decohesion_case(MPM_SCHEME_MUSL, MPM_SHAPE_LINEAR, MPM_LE_CELL);
  fig6_decohesion_case(MPM_SCHEME_USL, MPM_SHAPE_GIMP, MPM_LE_CELL);
  fig6_decohesion_case(MPM_SCHEME_MUSL, MPM_SHAPE_GIMP, MPM_LE_CELL);
  /* Le measured per row (mpm_band.c): at 90 deg with bilinear shapes the band is the
   * one cell column, both particle columns soften alike, so the rows measure Le = h and
   * every analytic number above holds as with the cell's Le */
  fig6_decohesion_case(MPM_SCHEME_USL, MPM_SHAPE_LINEAR, MPM_LE_ROW);
}

/* (b'') The nodal mass limit (grid.node_mass = limited; mpm_step.c "Nodal mass limit").
 * A free elastic block, one particle per cell, translating across the grid with a small
 * random velocity on top: with no constraint and no decohesion, KE + SE can only stay
 * or fall (USL dissipates a little); it must never grow.  As the block's end column
 * nears a node, the node beyond it holds a sliver of mass N m with the full gradient
 * 1 / h, and v^L = v + dt f / m there drives the particle's strain with gain growing as
 * 1 / N: the lumped step (the paper's) amplifies the seed until KE + SE is many times
 * its start (or throws a particle off the grid); with the limit it stays at its start.
 * Both are asserted, so that the case is known to exercise what the limit is for. */
static double node_mass_case(int node_mass)
{
  mpm_scene sc = block_scene(1, 8.0);
  sc.dt = 0.025; /* fig6.ini's dt at h 2: c dt / h = 0.41 */
  sc.node_mass = node_mass;
  mpm_sim *s = tu_make_sim(&sc, 1);
  release_block(s);
  mpm_particles *p = s->p;
  uint64_t seed = 77;
  for (size_t k = 0; k < p->n; k++) {
    p->vx[k] = -0.01 + 1e-4 * (urand(&seed) - 0.5);
    p->vy[k] = 1e-4 * (urand(&seed) - 0.5);
  }
  mpm_energy e0, e;
  mpm_sim_energy(s, &e0);
  double emax = 0.0;
  char err[256] = "";
  for (int k = 0; k < 16000 && emax < INFINITY; k++) { /* 4 cells of travel */
    if (mpm_sim_step(s, err, sizeof err) != MPM_OK)
      emax = INFINITY; /* blown up: a particle thrown off the grid */
    mpm_sim_energy(s, &e);
    emax = fmax(emax, e.KE + e.SE);
  }
  mpm_sim_free(s);
  return emax / (e0.KE + e0.SE);
}

static void test_mpm_bar_node_mass_limit(void **state)
{
  (void)state;
  const double lim = node_mass_case(MPM_NODEMASS_LIMITED), lum = node_mass_case(MPM_NODEMASS_LUMPED);
  print_message("# node mass: KE + SE max over start: limited %.6g, lumped %.6g\n", lim, lum);
  /* USL keeps KE + SE only on the whole, not step by step (a step's L_scheme can be
   * negative: measured up to 1e-5 of the start here): 1e-3 */
  assert_true(lim <= 1.001);
  assert_true(lum > 2.0);
}

/* The Fig. 7 bar at 60 deg (Model 1, snf 1, stf 10, U0 0.375, h 8, 1 ppc) with the
 * inclined scene files' band method: uGIMP, two fields, Le = row, MUSL. */
static mpm_scene band_scene(void)
{
  mpm_scene sc = fig6_scene();
  sc.model = MPM_DCOH_MODEL1;
  sc.alpha_deg = 60.0;
  sc.imp_factor = 0.9;
  sc.ppc = 1;
  sc.margin = 16.0;
  sc.scheme = MPM_SCHEME_MUSL;
  sc.shape = MPM_SHAPE_GIMP;
  sc.fields = MPM_FIELDS_TWO;
  sc.le_mode = MPM_LE_ROW;
  return sc;
}

/* (b') An inclined band at 60 deg (the paper's Fig. 7 scene: Model 1, snf 1, stf 10,
 * U0 0.375) with the band method and Le measured per row: the dissipation is
 * U0 x crack area = U0 H / sin a (eq. 10 over the crack, sec. 3) within 10 %, and
 * the separated bar carries under 3 % of the peak.  h 8, 1 ppc: 4 particle rows. */
static void test_mpm_bar_inclined_row_energy(void **state)
{
  (void)state;
  mpm_scene sc = band_scene();
  sc.end_delta = 0.6;
  mpm_sim *s = tu_make_sim(&sc, 1);
  const long nsteps = lround(sc.end_delta / (sc.speed * sc.dt));
  double Pmax = 0.0, Pend = 0.0;
  for (long k = 0; k < nsteps; k++) {
    tu_run_steps(s, 1);
    Pmax = fmax(Pmax, s->P_grip);
    if (k >= nsteps - 500)
      Pend += s->P_grip / 500.0;
  }
  mpm_energy e;
  mpm_sim_energy(s, &e);
  const double a = sc.alpha_deg * (3.14159265358979323846 / 180.0);
  assert_rel(e.D, sc.U0 * sc.H / sin(a), 0.10, "60 deg, Le = row: dissipation vs U0 H / sin a");
  /* peak: r0 H with 1 / r0 = sin a sqrt(sin^2 a / snf^2 + cos^2 a / stf^2) (eq. 30) */
  const double r0 = 1.0 / (sin(a) * sqrt(sin(a) * sin(a) / (sc.snf * sc.snf) + cos(a) * cos(a) / (sc.stf * sc.stf)));
  assert_rel(Pmax, r0 * sc.H, 0.03, "60 deg, Le = row: peak vs r0 H");
  assert_abs(Pend, 0.0, 0.03 * Pmax, "60 deg, Le = row: load after separation");
  mpm_sim_free(s);
}

/* The a45 file's method at h 4 with ppc particles per cell: uGIMP, two fields, MUSL,
 * Le = zone, the release damped from the cut. */
static mpm_scene a45_scene(int ppc)
{
  mpm_scene sc = band_scene();
  sc.alpha_deg = 45.0;
  sc.h = 4.0;
  sc.dt = 0.05;
  sc.ppc = ppc;
  sc.le_mode = MPM_LE_ZONE;
  sc.damping = 0.1;
  sc.damping_from = MPM_DAMP_CUT;
  return sc;
}

/* (b'') The 45 deg bar (Model 1, snf 1, stf 10, U0 0.375) at h 4 with 9 ppc, the a45 file's
 * method (uGIMP, two fields, MUSL, the release damped from the cut) with Le = zone: the
 * dissipation is U0 H / sin a within 10 %.  Le = row charges this band 0.84 of that:
 * the particles far along the rows soften a little before the band localizes, count in
 * its measured width and leave the band's own particles under-charged; zone counts only
 * the particles whose supports touch the row's lead (docs/findings.md). */
static void test_mpm_bar_inclined_zone_energy(void **state)
{
  (void)state;
  mpm_scene sc = a45_scene(9);
  sc.end_delta = 0.5;
  mpm_sim *s = tu_make_sim(&sc, 1);
  tu_run_steps(s, lround(sc.end_delta / (sc.speed * sc.dt)));
  mpm_energy e;
  mpm_sim_energy(s, &e);
  const double a = sc.alpha_deg * (3.14159265358979323846 / 180.0);
  assert_rel(e.D, sc.U0 * sc.H / sin(a), 0.10, "45 deg, h 4, 9 ppc, Le = zone: dissipation vs U0 H / sin a");
  mpm_sim_free(s);
}

/* (b3) decohesion.path = line (the a45 geometry, h 4, 4 ppc, Le = zone, damped from the
 * cut, one cell of reach): (i) no particle farther than h (|sin a| + |cos a|) / 2 + h
 * from the line at alpha through the imperfection softens at all, and particles nearer
 * it are the bar's own material; (ii) D within 10 % of U0 H / sin a; (iii) the
 * separated particles' principal axis lies within 5 deg of alpha (the inclined-crack bound). */
static void test_mpm_bar_path_line(void **state)
{
  (void)state;
  mpm_scene sc = a45_scene(4);
  sc.path = MPM_PATH_LINE;
  sc.path_reach = 1.0;
  sc.end_delta = 0.55;
  mpm_sim *s = tu_make_sim(&sc, 1);
  tu_run_steps(s, lround(sc.end_delta / (sc.speed * sc.dt)));
  assert_true(s->cut);
  const mpm_particles *p = s->p;
  const double a = sc.alpha_deg * (3.14159265358979323846 / 180.0);
  const double w = 0.5 * sc.h * (fabs(sin(a)) + fabs(cos(a))) + sc.path_reach * sc.h;
  size_t imp = p->n;
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] == MPM_MAT_IMP)
      imp = k;
  assert_true(imp < p->n);
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, ns = 0;
  long outside = 0, inside_bar = 0;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD)
      continue;
    const double dist = fabs(sin(a) * (p->x0[k] - p->x0[imp]) - cos(a) * (p->y0[k] - p->y0[imp]));
    if (dist > w) {
      outside++;
      if (p->lam[k] != 0.0 || p->mat[k] != MPM_MAT_ELASTIC)
        fail_msg("particle %zu at %g from the line (band %g): lambda %g, material %d", k, dist, w, p->lam[k],
                 (int)p->mat[k]);
    } else {
      inside_bar += p->mat[k] == MPM_MAT_BAR;
    }
    if (p->lam[k] >= 0.98) {
      ns++;
      sx += p->x0[k];
      sy += p->y0[k];
      sxx += p->x0[k] * p->x0[k];
      syy += p->y0[k] * p->y0[k];
      sxy += p->x0[k] * p->y0[k];
    }
  }
  assert_true(outside > 0 && inside_bar > 0);
  assert_true(ns > 2);
  const double cxx = sxx / ns - (sx / ns) * (sx / ns), cyy = syy / ns - (sy / ns) * (sy / ns);
  const double cxy = sxy / ns - (sx / ns) * (sy / ns);
  const double ang = fmod(0.5 * atan2(2.0 * cxy, cxx - cyy) * (180.0 / 3.14159265358979323846) + 180.0, 180.0);
  assert_abs(ang, sc.alpha_deg, 5.0, "45 deg, path = line: angle of the separated particles");
  mpm_energy e;
  mpm_sim_energy(s, &e);
  assert_rel(e.D, sc.U0 * sc.H / sin(a), 0.10, "45 deg, h 4, 4 ppc, path = line: dissipation vs U0 H / sin a");
  mpm_sim_free(s);
}

/* (b'') The paper's Fig. 8 bar (Mode II by strengths: snf 10, stf 1, 60 deg; g = 0.446,
 * eq. 35: the analytic curve snaps back from delta 0.427 at the peak to 0.19 at
 * separation, where the bar has taken UF x area = 6.93 of work) under
 * loading.control = dissipation with decohesion.eta = 4 (mpm_control.c): the grip moves
 * back by at least 0.15 after the peak, and the work it has done when the band has cut
 * the bar is under 1.5 UF x area (pulled at constant speed the run takes 2.3 times that,
 * released into waves).  h 4, 1 ppc, the fig8 file's band method. */
static void test_mpm_bar_snapback_control(void **state)
{
  (void)state;
  mpm_scene sc = band_scene();
  sc.snf = 10.0;
  sc.stf = 1.0;
  sc.s0 = 10.0;
  sc.imp_stf_factor = 0.9;
  sc.h = 4.0;
  sc.dt = 0.05;
  sc.end_delta = 1.0;
  sc.control = MPM_CONTROL_DISSIPATION;
  sc.eta = 4.0;
  mpm_sim *s = tu_make_sim(&sc, 1);
  double Pmax = 0.0, dpeak = 0.0, dmin = 1e9;
  for (long k = 0; k < 40000 && !s->cut; k++) {
    tu_run_steps(s, 1);
    const double d = mpm_sim_delta(s);
    if (s->P_grip > Pmax) {
      Pmax = s->P_grip;
      dpeak = d;
      dmin = d;
    }
    dmin = fmin(dmin, d);
  }
  assert_true(s->cut);
  const double a = sc.alpha_deg * (3.14159265358979323846 / 180.0);
  const double UFA = 0.5 * sc.U0 * sc.H / sin(a); /* q = 1: UF = U0 / 2 (eq. 25) */
  if (!(dmin <= dpeak - 0.15))
    fail_msg("the grip moved back from delta %g to %g only (analytic: 0.427 to 0.19)", dpeak, dmin);
  if (!(s->W_ext < 1.5 * UFA))
    fail_msg("W_ext at the cut %g against UF x area %g: over 1.5 times", s->W_ext, UFA);
  mpm_sim_free(s);
}

/* (c) nthreads 1 and 2 give bit-identical particle states: the elastic bar, and a
 * Model 1 bar with an imperfection pulled past its peak (softening, separation and
 * the bracketed solver run inside the threaded pass). */
static void threads_case(const mpm_scene *sc, long nsteps, const char *what, long *n_soften, long *n_separate)
{
  mpm_sim *a = tu_make_sim(sc, 1), *b = tu_make_sim(sc, 2);
  assert_int_equal(a->nthreads, 1);
#ifdef _OPENMP
  assert_int_equal(b->nthreads, 2);
#endif
  tu_run_steps(a, nsteps);
  tu_run_steps(b, nsteps);
  assert_int_equal(a->p->n, b->p->n);
  const size_t nb = a->p->n * sizeof(double);
  if (memcmp(a->p->x, b->p->x, nb) || memcmp(a->p->y, b->p->y, nb))
    fail_msg("%s: positions differ between 1 and 2 threads", what);
  if (memcmp(a->p->vx, b->p->vx, nb) || memcmp(a->p->sxx, b->p->sxx, nb) || memcmp(a->p->lam, b->p->lam, nb))
    fail_msg("%s: velocities, stresses or lambda differ between 1 and 2 threads", what);
  if (memcmp(&a->P_grip, &b->P_grip, sizeof a->P_grip) || memcmp(&a->W_ext, &b->W_ext, sizeof a->W_ext))
    fail_msg("%s: loads or work differ between 1 and 2 threads", what);
  assert_int_equal(a->n_soften, b->n_soften);
  assert_int_equal(a->n_separate, b->n_separate);
  *n_soften = a->n_soften;
  *n_separate = a->n_separate;
  mpm_sim_free(a);
  mpm_sim_free(b);
}

static void test_mpm_bar_threads_bit_identical(void **state)
{
  (void)state;
  long nsoft, nsep;
  mpm_scene sc = fig6_scene();
  /* Few steps: on an oversubscribed machine each OpenMP barrier of the 2-thread run
   * can cost a time slice (libgomp spins, and its wait policy is fixed at load). */
  threads_case(&sc, 300, "elastic bar, USL", &nsoft, &nsep);
  sc.scheme = MPM_SCHEME_MUSL;
  threads_case(&sc, 300, "elastic bar, MUSL", &nsoft, &nsep);
  /* Fig. 6 with the decohesion on (peak at delta 0.1875, separation near 0.375),
   * pulled 4 times faster to get there in 1125 steps */
  sc = fig6_scene();
  sc.model = MPM_DCOH_MODEL1;
  sc.imp_factor = 0.9;
  sc.end_delta = 0.45;
  sc.speed = 0.004;
  sc.scheme = MPM_SCHEME_MUSL;
  threads_case(&sc, 1125, "Model 1 bar, softening and separation", &nsoft, &nsep);
  if (!(nsoft > 0 && nsep > 0))
    fail_msg("Model 1 bar: %ld softening and %ld separation updates; expected both", nsoft, nsep);
  sc.shape = MPM_SHAPE_GIMP; /* uGIMP: 3 x 3 nodes a particle, half-cell drift between sorts */
  threads_case(&sc, 1125, "Model 1 bar, uGIMP, softening and separation", &nsoft, &nsep);
  sc.fields = MPM_FIELDS_TWO; /* and the second velocity field once the band separates */
  threads_case(&sc, 1125, "Model 1 bar, uGIMP, two fields", &nsoft, &nsep);
  if (!(nsep > 0))
    fail_msg("two fields: no separation, so the second field was never used");
  sc.le_mode = MPM_LE_ROW; /* the rows' Le: per-strip sums reduced in strip order */
  threads_case(&sc, 1125, "Model 1 bar, uGIMP, two fields, Le = row", &nsoft, &nsep);
  /* the case did reach decohesion, else the comparison proves little */
  if (!(nsoft > 0 && nsep > 0))
    fail_msg("Model 1 bar: %ld softening and %ld separation updates; expected both", nsoft, nsep);
}

/* (c') the thread count may change between any two steps (mpm_threads.c): a run whose
 * count flips every step matches the one-thread run bit for bit; and the automatic
 * choice keeps small problems on one thread without measuring. */
static void test_mpm_bar_threads_switch(void **state)
{
  (void)state;
  mpm_scene sc = fig6_scene();
  sc.model = MPM_DCOH_MODEL1;
  sc.imp_factor = 0.9;
  sc.end_delta = 0.45;
  sc.speed = 0.004;
  mpm_sim *a = tu_make_sim(&sc, 1), *b = tu_make_sim(&sc, 2);
  b->thr.automatic = 0;
  char err[256] = "";
  for (long k = 0; k < 1125; k++) {
    b->thr.use = k % 2 ? b->thr.nmax : 1;
    if (mpm_sim_step(a, err, sizeof err) != MPM_OK || mpm_sim_step(b, err, sizeof err) != MPM_OK)
      fail_msg("step %ld: %s", k, err);
  }
  assert_true(b->thr.steps_multi == (b->thr.nmax > 1 ? 562 : 0));
  const size_t nb = a->p->n * sizeof(double);
  if (memcmp(a->p->x, b->p->x, nb) || memcmp(a->p->sxx, b->p->sxx, nb) || memcmp(a->p->lam, b->p->lam, nb) ||
      memcmp(&a->W_ext, &b->W_ext, sizeof a->W_ext))
    fail_msg("a run switching between 1 and %d threads differs from the one-thread run", b->thr.nmax);
  assert_true(a->n_separate > 0);
  mpm_sim_free(a);
  mpm_sim_free(b);
  mpm_threads t;
  mpm_threads_init(&t, 0, MPM_THREADS_MIN_PARTICLES - 1);
  assert_int_equal(t.automatic, 0);
  assert_int_equal(t.use, 1);
  mpm_threads_init(&t, 3, 10);
  assert_int_equal(t.automatic, 0);
#ifdef _OPENMP
  assert_int_equal(t.use, 3);
#endif
}

/* (e) each rule of mpm_scene_check once, with the key in the message. */
static void expect_einval(const mpm_scene *sc, const char *key)
{
  char err[256] = "";
  if (mpm_scene_check(sc, err, sizeof err) != MPM_EINVAL)
    fail_msg("scene with bad %s accepted", key);
  if (!strstr(err, key))
    fail_msg("message for bad %s does not name it: \"%s\"", key, err);
  mpm_sim *s = (mpm_sim *)&err; /* must be reset to NULL */
  assert_int_equal(mpm_sim_alloc(sc, 1, &s, err, sizeof err), MPM_EINVAL);
  assert_null(s);
}

static void test_mpm_bar_scene_check(void **state)
{
  (void)state;
  const mpm_scene ok = fig6_scene();
  char err[256];
  assert_int_equal(mpm_scene_check(&ok, err, sizeof err), MPM_OK);
  mpm_scene d1 = ok;
  d1.model = MPM_DCOH_MODEL1;
  assert_int_equal(mpm_scene_check(&d1, err, sizeof err), MPM_OK);
  mpm_scene sc;
  sc = ok; sc.L = 0.0; expect_einval(&sc, "L");
  sc = ok; sc.H = NAN; expect_einval(&sc, "H");
  sc = ok; sc.E = -1.0; expect_einval(&sc, "E");
  sc = ok; sc.nu = 0.5; expect_einval(&sc, "nu");
  sc = ok; sc.nu = -1.0; expect_einval(&sc, "nu");
  sc = ok; sc.rho = 0.0; expect_einval(&sc, "rho");
  sc = ok; sc.model = 3; expect_einval(&sc, "model");
  sc = ok; sc.model = -1; expect_einval(&sc, "model");
  sc = d1; sc.alpha_deg = 180.0; expect_einval(&sc, "alpha");
  sc = d1; sc.alpha_deg = -1.0; expect_einval(&sc, "alpha");
  sc = d1; sc.snf = 0.0; expect_einval(&sc, "snf");
  sc = d1; sc.stf = -2.0; expect_einval(&sc, "stf");
  sc = d1; sc.U0 = 0.0; expect_einval(&sc, "U0");
  sc = d1; sc.s0 = NAN; expect_einval(&sc, "s0");
  sc = d1; sc.q = 0.0; expect_einval(&sc, "q");
  sc = d1; sc.sep_threshold = 1.01; expect_einval(&sc, "separation");
  sc = d1; sc.sep_threshold = 0.0; expect_einval(&sc, "separation");
  sc = d1; sc.imp_factor = 0.0; expect_einval(&sc, "snf_factor");
  sc = d1; sc.imp_factor = 1.5; expect_einval(&sc, "snf_factor");
  sc = d1; sc.imp_stf_factor = 0.0; expect_einval(&sc, "stf_factor");
  sc = d1; sc.imp_stf_factor = 1.5; expect_einval(&sc, "stf_factor");
  sc = ok; sc.h = 0.0; expect_einval(&sc, "h");
  sc = ok; sc.h = 5.0; expect_einval(&sc, "h"); /* 5 divides neither 192 nor 32 */
  sc = ok; sc.h = 24.0; expect_einval(&sc, "h"); /* divides L = 192, not H = 32 */
  sc = ok; sc.ppc = 3; expect_einval(&sc, "ppc");
  sc = ok; sc.ppc = 0; expect_einval(&sc, "ppc");
  sc = ok; sc.margin = -1.0; expect_einval(&sc, "margin");
  sc = ok; sc.scheme = 4; expect_einval(&sc, "scheme");
  sc = ok; sc.shape = 2; expect_einval(&sc, "shape");
  sc = ok; sc.dt = 0.0; expect_einval(&sc, "dt");
  sc = ok; sc.speed = 0.0; expect_einval(&sc, "speed");
  sc = ok; sc.end_delta = -0.1; expect_einval(&sc, "end_delta");
  /* the edges of the allowed ranges are accepted */
  sc = d1; sc.alpha_deg = 0.0; sc.sep_threshold = 1.0; sc.imp_factor = 1.0; sc.margin = 0.0; sc.ppc = 9;
  assert_int_equal(mpm_scene_check(&sc, err, sizeof err), MPM_OK);
  /* decohesion keys are not checked when decohesion is off */
  sc = ok; sc.q = -1.0; sc.snf = 0.0;
  assert_int_equal(mpm_scene_check(&sc, err, sizeof err), MPM_OK);
  /* the rules between options are one function, which mpm_scene_check ends with: the
   * key at fault first in the message, and the allowed values named */
  const char *key = NULL;
  char msg[512];
  sc = ok; sc.damping_beta = 0.1; /* USL */
  assert_int_equal(mpm_scene_rules(&sc, &key, msg, sizeof msg), MPM_EINVAL);
  assert_string_equal(key, "time.damping_beta");
  assert_non_null(strstr(msg, "time.damping_beta: 0.1 needs time.scheme = musl (here: usl"));
  assert_int_equal(mpm_scene_check(&sc, err, sizeof err), MPM_EINVAL);
  assert_int_equal(strncmp(err, msg, strlen(err)), 0);
  sc = ok; sc.weights = MPM_WEIGHTS_LAID; sc.grid_motion = MPM_GRID_FIXED;
  assert_int_equal(mpm_scene_rules(&sc, &key, msg, sizeof msg), MPM_EINVAL);
  assert_string_equal(key, "grid.weights");
  sc.grid_motion = MPM_GRID_STRETCH;
  assert_int_equal(mpm_scene_rules(&sc, &key, msg, sizeof msg), MPM_OK);
  assert_null(key);
  mpm_sim_free(NULL);
}

/* (f) a particle thrown out of the grid: MPM_EDOMAIN from the step that finds it, with
 * a message that says so; a non-finite position: MPM_ENOTFINITE. */
/* imperfection.size: the paper's single particle, or every particle of its cell: at
 * ppc n the flaw is n particles, all in the h x h cell that holds the particle nearest
 * (imp_x, imp_y), whose union is that cell (n particles of area h^2 / n). */
static void test_mpm_bar_imperfection_size(void **state)
{
  (void)state;
  for (int size = MPM_IMP_PARTICLE; size <= MPM_IMP_CELL; size++)
    for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5) {
      mpm_scene sc = fig6_scene();
      sc.model = MPM_DCOH_MODEL1;
      sc.imp_factor = 0.9;
      sc.imp_x = 97.0; /* inside the cell [96, 104] x [16, 24] */
      sc.imp_y = 17.0;
      sc.imp_size = size;
      sc.ppc = ppc;
      mpm_sim *s = tu_make_sim(&sc, 1);
      const mpm_particles *p = s->p;
      int n = 0;
      double area = 0.0;
      for (size_t k = 0; k < p->n; k++)
        if (p->mat[k] == MPM_MAT_IMP) {
          n++;
          area += p->V[k];
          assert_true(p->x0[k] > 96.0 && p->x0[k] < 104.0 && p->y0[k] > 16.0 && p->y0[k] < 24.0);
        }
      assert_int_equal(n, size == MPM_IMP_CELL ? ppc : 1);
      assert_abs(area, size == MPM_IMP_CELL ? 64.0 : 64.0 / ppc, 1e-9, "the flaw's area");
      mpm_sim_free(s);
    }
}

static void test_mpm_bar_leaves_grid(void **state)
{
  (void)state;
  const mpm_scene sc = fig6_scene();
  mpm_sim *s = tu_make_sim(&sc, 1);
  s->p->vx[s->p->n / 2] = 1e6;
  char err[256] = "";
  mpm_status st = MPM_OK;
  for (int k = 0; k < 3 && st == MPM_OK; k++)
    st = mpm_sim_step(s, err, sizeof err);
  assert_int_equal(st, MPM_EDOMAIN);
  assert_non_null(strstr(err, "left the grid"));
  mpm_sim_free(s);

  s = tu_make_sim(&sc, 1);
  s->p->y[3] = NAN;
  assert_int_equal(mpm_sim_step(s, err, sizeof err), MPM_ENOTFINITE);
  mpm_sim_free(s);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_bar_momentum_usl),
      cmocka_unit_test(test_mpm_bar_momentum_musl),
      cmocka_unit_test(test_mpm_bar_elastic_stiffness_energy),
      cmocka_unit_test(test_mpm_bar_fig6_decohesion_energy),
      cmocka_unit_test(test_mpm_bar_node_mass_limit),
      cmocka_unit_test(test_mpm_bar_inclined_row_energy),
      cmocka_unit_test(test_mpm_bar_inclined_zone_energy),
      cmocka_unit_test(test_mpm_bar_path_line),
      cmocka_unit_test(test_mpm_bar_snapback_control),
      cmocka_unit_test(test_mpm_bar_threads_bit_identical),
      cmocka_unit_test(test_mpm_bar_threads_switch),
      cmocka_unit_test(test_mpm_bar_scene_check),
      cmocka_unit_test(test_mpm_bar_imperfection_size),
      cmocka_unit_test(test_mpm_bar_leaves_grid),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
