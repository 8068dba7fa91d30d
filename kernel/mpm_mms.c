/*
 * mpm_mms.c - the manufactured solution of the step's code verification (mpm.h
 * mpm_mms_error; derivation in tests/test_mpm_mms.c and docs/verification.md):
 *   u = A sin(pi X / L) sin(w t), v = 0, plane stress, nu = 0, the bar held in x at
 *   X = 0 and L, body force b_x = A ((pi c / L)^2 - w^2) sin(pi X / L) sin(w t),
 *   A = 0.03, w = 1.5 pi c / L, 1 particle per cell, dt = 0.1 h / 8, error at t = 10
 *   (the RMS particle displacement error over A); MPM_OK or the failing step's status.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mpm.h"
#include "mpm_kernel.h"

#define MMS_A 0.03
#define MMS_T 10.0

mpm_scene mpm_mms_scene(double h, int scheme, int bc)
{
  mpm_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.L = 192.0;
  sc.H = 32.0;
  sc.E = 1024.0;
  sc.nu = 0.0;
  sc.rho = 1.0;
  sc.model = MPM_DCOH_NONE;
  sc.snf = sc.stf = sc.U0 = sc.s0 = sc.q = 1.0;
  sc.sep_threshold = 0.98;
  sc.imp_factor = 1.0;
  sc.imp_stf_factor = 1.0;
  sc.le_factor = 1.0;
  sc.h = h;
  sc.ppc = 1;
  sc.scheme = scheme;
  sc.bc = bc;
  sc.head = MPM_HEAD_NONE;
  const double wn = MPM_PI * sqrt(sc.E / sc.rho) / sc.L, w = 1.5 * wn;
  sc.vib_mode = 1;
  sc.vib_amp = MMS_A * w; /* vx(0) = A w sin(pi X / L) */
  sc.body_amp = MMS_A * (wn * wn - w * w);
  sc.body_omega = w;
  sc.dt = 0.1 * h / 8.0;
  sc.speed = 1e-12;    /* the grip does not move */
  sc.end_delta = 1e-9; /* only sizes the grid */
  return sc;
}

mpm_status mpm_mms_error(double h, int scheme, int bc, double *err_out, char *err, size_t errlen)
{
  mpm_scene sc = mpm_mms_scene(h, scheme, bc);
  mpm_sim *s = NULL;
  *err_out = NAN;
  mpm_status st = mpm_sim_alloc(&sc, 1, &s, err, errlen);
  if (st != MPM_OK)
    return st;
  const long n = lround(MMS_T / sc.dt);
  for (long k = 0; k < n && st == MPM_OK; k++)
    st = mpm_sim_step(s, err, errlen);
  if (st == MPM_OK) {
    double e2 = 0.0;
    for (size_t i = 0; i < s->p->n; i++) {
      const double X = s->p->x0[i];
      const double ue = MMS_A * sin(MPM_PI * X / sc.L) * sin(sc.body_omega * s->t);
      const double dx = s->p->x[i] - X - ue, dy = s->p->y[i] - s->p->y0[i];
      e2 += dx * dx + dy * dy;
    }
    *err_out = sqrt(e2 / (double)s->p->n) / MMS_A;
  }
  mpm_sim_free(s);
  return st;
}
