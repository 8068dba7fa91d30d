/*
 * test_mpm_fields.c - two velocity fields across a separated band (grid.fields = two,
 * mpm_fields.c), against mechanics, not against the code's own output:
 *  - two blocks on either side of a separated particle column, moving apart, keep their
 *    velocities (nothing couples them: no force across a separated band), while with one
 *    field the shared nodes drag them together (the test can fail);
 *  - the same blocks moving towards each other stop at the band (contact: no
 *    interpenetration), and total momentum is kept in both cases to rounding;
 *  - without a separated particle the two-field step is the one-field step, bit for bit;
 *  - the energy ledger closes with two fields (the conservation law W_ext + E0 = KE + SE
 *    + W_coh + the booked terms, here with W_ext = 0), for every scheme and both shapes,
 *    and the contact's loss L_contact is positive when the blocks meet and 0 when they
 *    part.
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

#include "mpm_fields.h"
#include "mpm.h"
#include "mpm_kernel.h"
#include "test_util.h"

/* A short bar, 48 x 16, h 2, 1 ppc, decohesion across x (alpha 90), uGIMP, no grip or
 * fixed end; the particle column at x = 23 (the middle) separated. */
static mpm_sim *blocks_shape(int fields, double v, int shape)
{
  mpm_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.le_factor = 1.0;
  sc.L = 48.0;
  sc.H = 16.0;
  sc.E = 1024.0;
  sc.nu = 0.25;
  sc.rho = 1.0;
  sc.model = MPM_DCOH_MODEL1;
  sc.alpha_deg = 90.0;
  sc.snf = 1e6; /* strong: nothing else decoheres */
  sc.stf = 1e6;
  sc.U0 = 0.375;
  sc.s0 = 1.0;
  sc.q = 1.0;
  sc.sep_threshold = 0.98;
  sc.imp_factor = 1.0;
  sc.imp_stf_factor = 1.0;
  sc.imp_x = 24.0;
  sc.imp_y = 8.0;
  sc.h = 2.0;
  sc.ppc = 1;
  sc.margin = 8.0;
  sc.shape = shape;
  sc.fields = fields;
  sc.scheme = MPM_SCHEME_MUSL;
  sc.dt = 0.02;
  sc.speed = 0.001;
  sc.end_delta = 1.0;
  mpm_sim *s = NULL;
  char err[256] = "";
  if (mpm_sim_alloc(&sc, 1, &s, err, sizeof err) != MPM_OK)
    fail_msg("mpm_sim_alloc: %s", err);
  s->nbc = 0;
  mpm_particles *p = s->p;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD) { /* park the head far from the blocks, at rest */
      p->m[k] = 0.0;
      continue;
    }
    p->vx[k] = p->x0[k] < 24.0 ? -v : v;
    p->vy[k] = 0.0;
    if (fabs(p->x0[k] - 23.0) < 1e-9) {
      p->sep[k] = 1;
      p->lam[k] = 1.0;
      p->str2[k] = -1.0;
    }
  }
  s->mat[MPM_MAT_HEAD].mp = 0.0; /* the mass the gather's ledger sums take for it */
  s->led.KE_head0 = 0.0; /* the ledger's start energy of the head: it was parked massless */
  return s;
}

static mpm_sim *blocks_scheme(int fields, double v, int shape, int scheme)
{
  mpm_sim *s = blocks_shape(fields, v, shape);
  s->sc.scheme = scheme;
  return s;
}

static mpm_sim *blocks(int fields, double v)
{
  return blocks_shape(fields, v, MPM_SHAPE_GIMP);
}

static void run(mpm_sim *s, long n)
{
  char err[256] = "";
  for (long k = 0; k < n; k++)
    if (mpm_sim_step(s, err, sizeof err) != MPM_OK)
      fail_msg("step %ld: %s", k, err);
}

/* mean x velocity of the bar's particles left of 22 and right of 24 (the band aside) */
static void halves(const mpm_sim *s, double *vl, double *vr, double *xl, double *xr)
{
  const mpm_particles *p = s->p;
  double ml = 0.0, mr = 0.0, pl = 0.0, pr = 0.0;
  *xl = -INFINITY;
  *xr = INFINITY;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD)
      continue;
    if (p->x0[k] < 22.0) {
      ml += p->m[k];
      pl += p->m[k] * p->vx[k];
      *xl = fmax(*xl, p->x[k]);
    } else if (p->x0[k] > 24.0) {
      mr += p->m[k];
      pr += p->m[k] * p->vx[k];
      *xr = fmin(*xr, p->x[k]);
    }
  }
  *vl = pl / ml;
  *vr = pr / mr;
}

static void test_mpm_fields_separated_blocks_move_apart(void **state)
{
  (void)state;
  const double v = 0.01;
  double vl, vr, xl, xr, px0, py0, px, py;
  mpm_sim *s = blocks(MPM_FIELDS_TWO, v);
  mpm_particles_momentum(s->p, &px0, &py0);
  run(s, 200);
  halves(s, &vl, &vr, &xl, &xr);
  mpm_particles_momentum(s->p, &px, &py);
  assert_abs(px, px0, 1e-12, "x momentum, two fields");
  assert_abs(py, py0, 1e-12, "y momentum, two fields");
  /* free rigid motion: each block keeps its speed (to the elastic ringing of the start) */
  assert_rel(vl, -v, 1e-3, "left block speed, two fields");
  assert_rel(vr, v, 1e-3, "right block speed, two fields");
  assert_true(s->g->fld->nsplit > 0);
  mpm_sim_free(s);
  /* the same with the paper's bilinear shapes */
  s = blocks_shape(MPM_FIELDS_TWO, v, MPM_SHAPE_LINEAR);
  run(s, 200);
  halves(s, &vl, &vr, &xl, &xr);
  assert_rel(vl, -v, 1e-3, "left block speed, two fields, bilinear");
  assert_rel(vr, v, 1e-3, "right block speed, two fields, bilinear");
  mpm_sim_free(s);
  /* one field: the nodes under the band average both blocks, so they drag each other */
  s = blocks(MPM_FIELDS_ONE, v);
  run(s, 200);
  halves(s, &vl, &vr, &xl, &xr);
  if (!(fabs(vl + v) > 0.05 * v && fabs(vr - v) > 0.05 * v))
    fail_msg("one field: blocks kept %g and %g of +-%g: the coupling this test relies on is gone", vl, vr, v);
  mpm_sim_free(s);
}

/* Towards each other at +-v: without contact the blocks would overlap the band by
 * v t = 0.4 at t = 40; with it they meet at the band and bounce (elastic blocks, so
 * their mean velocities reverse rather than vanish), momentum kept. */
static void test_mpm_fields_contact_stops_blocks(void **state)
{
  (void)state;
  const double v = 0.01;
  double vl, vr, xl, xr, px0, py0, px, py, xl0, xr0, vl0, vr0;
  mpm_sim *s = blocks(MPM_FIELDS_TWO, -v); /* left block moves right, right block left */
  halves(s, &vl0, &vr0, &xl0, &xr0);
  mpm_particles_momentum(s->p, &px0, &py0);
  double gap_min = INFINITY;
  for (int k = 0; k < 20; k++) {
    run(s, 100);
    halves(s, &vl, &vr, &xl, &xr);
    gap_min = fmin(gap_min, xr - xl);
  }
  mpm_particles_momentum(s->p, &px, &py);
  /* nodes with less than MPM_MASS_EPS of a particle's mass are empty (mpm_node.h):
   * the force on those at the supports' very edges is dropped, 1.6e-8 here against
   * the blocks' momenta of 7.7 */
  double pscale = 0.0; /* the blocks' momenta, each one's alone */
  for (size_t k = 0; k < s->p->n; k++)
    pscale += s->p->m[k] * v;
  assert_abs(px, px0, 1e-6 * pscale, "x momentum with contact");
  /* free flight would close the gap of 4 between the blocks' edge particles by 0.8 at
   * t = 40; contact stops them at the band: they close it by less than half of that */
  if (!(gap_min > (xr0 - xl0) - 0.4))
    fail_msg("contact: the gap between the blocks fell from %g to %g", xr0 - xl0, gap_min);
  /* the approach was stopped: neither block still moves inwards at the start speed */
  if (!(vl < 0.5 * v && vr > -0.5 * v))
    fail_msg("contact: blocks still approaching at %g and %g (start +-%g)", vl, vr, v);
  mpm_sim_free(s);
}

/* The energy of the blocks, no external work (no grip, no fixed end): KE + SE (start)
 * = KE + SE + W_coh + L_bc + L_flip + L_scheme + W_head + L_contact at every step, to
 * rounding, for each scheme and shape, parting (v > 0) and meeting (v < 0), each block
 * with a shear wave in it.  The second
 * field's node sums and the contact's change are what this needs beyond one field:
 * without them the booked terms miss the contact's loss and the far block's share. */
static void test_mpm_fields_ledger_closes(void **state)
{
  (void)state;
  static const char *const sname[] = {"usl", "musl", "usf", "usavg"};
  char err[256] = "", what[160];
  for (int shape = MPM_SHAPE_LINEAR; shape <= MPM_SHAPE_GIMP; shape++)
    for (int scheme = MPM_SCHEME_USL; scheme <= MPM_SCHEME_USAVG; scheme++)
      for (int dir = 1; dir >= -1; dir -= 2) {
        const double v = 0.01 * dir;
        mpm_sim *s = blocks_scheme(MPM_FIELDS_TWO, v, shape, scheme);
        /* a shear wave in each block besides the rigid motion, so that both fields are
         * strained (in rigid motion every node term is 0) */
        for (size_t k = 0; k < s->p->n; k++)
          s->p->vy[k] = 0.5 * fabs(v) * sin(6.283185307179586 * s->p->x0[k] / 24.0);
        mpm_energy e;
        mpm_sim_energy(s, &e);
        const double E0 = e.KE + e.SE;
        double worst = 0.0;
        long split_steps = 0;
        for (long k = 0; k < 1000; k++) {
          if (mpm_sim_step(s, err, sizeof err) != MPM_OK)
            fail_msg("step %ld: %s", k, err);
          split_steps += s->g->fld->nsplit > 0;
          mpm_sim_energy(s, &e);
          const double booked = e.L_bc + e.L_flip + e.L_scheme + e.W_head + e.L_contact;
          worst = fmax(worst, fabs(e.W_ext + E0 - e.KE - e.SE - e.W_coh - booked) / E0);
        }
        snprintf(what, sizeof what, "%s, %s, blocks %s: ledger closure / E0", shape ? "gimp" : "linear",
                 sname[scheme], dir > 0 ? "parting" : "meeting");
        assert_true(split_steps == 1000); /* two fields throughout */
        assert_abs(worst, 0.0, 1e-12, what);
        /* the contact's work (the trapezoid: mpm_fields.c) on blocks that start the step
         * approaching is an inelastic impact's, never a gain: a real loss when the blocks
         * meet, next to nothing when they part (only while the gap is still closed at the
         * start, where the shear wave's Poisson motion brings a few nodes together) */
        snprintf(what, sizeof what, "%s, %s, blocks %s: L_contact / E0", shape ? "gimp" : "linear", sname[scheme],
                 dir > 0 ? "parting" : "meeting");
        if (!(e.L_contact >= 0.0) || (dir > 0 && !(e.L_contact < 1e-4 * E0)) ||
            (dir < 0 && !(e.L_contact > 1e-3 * E0)))
          fail_msg("%s: got %g, want %s", what, e.L_contact / E0, dir > 0 ? "[0, 1e-4)" : "above 1e-3");
        mpm_sim_free(s);
      }
}

/* Debris (mpm_step.c): a particle of the separated column between the blocks, put
 * outside the grid as if flung there, leaves the computation at the next step: the step
 * goes on (MPM_OK), the particle is parked inside the grid with no mass, and L_debris
 * takes its kinetic and elastic energy, 1/2 m |v|^2 + 1/2 V sigma : C^-1 sigma (plane
 * stress), computed here from its state before the step; the ledger then closes at
 * every step to rounding.  A particle of a block (not separated) outside the grid is
 * still an error. */
static void test_mpm_fields_debris_leaves(void **state)
{
  (void)state;
  char err[256] = "";
  for (int shape = MPM_SHAPE_LINEAR; shape <= MPM_SHAPE_GIMP; shape++) {
    mpm_sim *s = blocks_shape(MPM_FIELDS_TWO, 0.01, shape);
    mpm_particles *p = s->p;
    for (size_t k = 0; k < p->n; k++) /* a shear wave, so that the column is strained */
      p->vy[k] = 0.005 * sin(6.283185307179586 * p->x0[k] / 24.0);
    mpm_energy e;
    mpm_sim_energy(s, &e);
    const double E0 = e.KE + e.SE;
    double worst = 0.0, want = -1.0;
    size_t fly = p->n, block = p->n;
    double fx0 = 0.0, fy0 = 0.0; /* the flung particle's reference position (the sort moves it) */
    for (long k = 0; k < 400; k++) {
      if (k == 200) { /* fling the column's lowest particle and note a block's */
        for (size_t i = 0; i < p->n; i++) {
          if (p->mat[i] == MPM_MAT_HEAD)
            continue;
          if (p->sep[i] && (fly == p->n || p->y0[i] < p->y0[fly]))
            fly = i;
        }
        fx0 = p->x0[fly];
        fy0 = p->y0[fly];
        const double E = s->mat[MPM_MAT_BAR].E, nu = s->mat[MPM_MAT_BAR].nu;
        const double sx = p->sxx[fly], sy = p->syy[fly], t = p->sxy[fly];
        want = 0.5 * p->m[fly] * (p->vx[fly] * p->vx[fly] + p->vy[fly] * p->vy[fly]) +
               0.5 * p->V[fly] * (sx * sx + sy * sy - 2.0 * nu * sx * sy + 2.0 * (1.0 + nu) * t * t) / E;
        p->y[fly] = -1e3;
      }
      if (mpm_sim_step(s, err, sizeof err) != MPM_OK)
        fail_msg("%s, step %ld: %s", shape ? "gimp" : "linear", k, err);
      mpm_sim_energy(s, &e);
      const double booked = e.L_bc + e.L_flip + e.L_scheme + e.W_head + e.L_contact + e.L_debris;
      worst = fmax(worst, fabs(e.W_ext + E0 - e.KE - e.SE - e.W_coh - booked) / E0);
    }
    assert_int_equal(s->n_debris, 1);
    for (size_t i = 0; i < p->n; i++) {
      if (p->x0[i] == fx0 && p->y0[i] == fy0 && p->mat[i] != MPM_MAT_HEAD)
        fly = i;
      else if (!p->sep[i] && p->mat[i] != MPM_MAT_HEAD)
        block = i;
    }
    assert_int_equal(p->mat[fly], MPM_MAT_DEBRIS);
    assert_true(p->m[fly] == 0.0 && p->y[fly] > s->g->oy);
    assert_true(want > 0.0);
    assert_abs(e.L_debris / want, 1.0, 1e-12, "L_debris / the flung particle's KE + SE");
    assert_abs(worst, 0.0, 1e-12, "ledger closure with debris / E0");
    p->y[block] = -1e3; /* not separated: not debris */
    assert_int_equal(mpm_sim_step(s, err, sizeof err), MPM_EDOMAIN);
    mpm_sim_free(s);
  }
}

/* No separated particle: nothing is split, the step is the one-field step bit for bit. */
static void test_mpm_fields_inactive_is_one_field(void **state)
{
  (void)state;
  mpm_sim *a = blocks(MPM_FIELDS_ONE, 0.01), *b = blocks(MPM_FIELDS_TWO, 0.01);
  for (size_t k = 0; k < a->p->n; k++) {
    a->p->sep[k] = b->p->sep[k] = 0;
    a->p->lam[k] = b->p->lam[k] = 0.0;
    a->p->str2[k] = b->p->str2[k] = 1.0;
  }
  run(a, 100);
  run(b, 100);
  const size_t nb = a->p->n * sizeof(double);
  assert_true(memcmp(a->p->x, b->p->x, nb) == 0 && memcmp(a->p->vx, b->p->vx, nb) == 0);
  assert_true(memcmp(a->p->sxx, b->p->sxx, nb) == 0);
  assert_int_equal(b->g->fld->nsplit, 0);
  mpm_sim_free(a);
  mpm_sim_free(b);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mpm_fields_separated_blocks_move_apart),
      cmocka_unit_test(test_mpm_fields_contact_stops_blocks),
      cmocka_unit_test(test_mpm_fields_inactive_is_one_field),
      cmocka_unit_test(test_mpm_fields_ledger_closes),
      cmocka_unit_test(test_mpm_fields_debris_leaves),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
