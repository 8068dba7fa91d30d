/*
 * mpm_static_mms.c - code verification of the quasi-static solver by a manufactured
 * solution whose stress varies (mpm.h mpm_static_mms_error; the order asserted in
 * kernel/tests/test_mpm_static_mms.c, measured in docs/static.md):
 *
 *   u_x = A sin(kx X) cos(ky Y),  u_y = A cos(kx X) sin(ky Y / 2),  kx = pi / L, ky = pi / H
 *
 * on the elastic bar [0, L] x [0, H] (192 x 32, plane stress, E 1024, nu 0.25), with the
 * body force b = -div sigma(u) in closed form (mms_exact) as the particles' quadrature
 * f_a = sum_p V_p N_a(X_p) b(X_p), and the exact u held at every perimeter node (the
 * finite element's Dirichlet condition).  One Newton step solves it.  Error: the RMS over
 * the particles of the interpolated displacement's error, and over the free nodes of the
 * nodal one, both over A.  MPM_EINVAL for an h, shape or ppc the solver refuses.
 */
#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_specimen.h"
#include "mpm_static.h"

#define MMS_A 0.03
#define MMS_RTOL 1e-9 /* the residual after the step, of the largest body force on a node */

/* The exact displacement u and body force b = -div sigma(u) at (X, Y): with
 * D = E / (1 - nu^2), G = E / (2 (1 + nu)),
 *   b_x = -(D u_x,XX + G u_x,YY + (nu D + G) u_y,XY),
 *   b_y = -(D u_y,YY + G u_y,XX + (nu D + G) u_x,XY). */
static void mms_exact(const mpm_scene *sc, double X, double Y, double u[2], double b[2])
{
  const double kx = MPM_PI / sc->L, ky = MPM_PI / sc->H, A = MMS_A;
  const double D = sc->E / (1.0 - sc->nu * sc->nu), G = sc->E / (2.0 * (1.0 + sc->nu)), C = sc->nu * D + G;
  const double sx = sin(kx * X), cx = cos(kx * X), sy = sin(ky * Y), cy = cos(ky * Y);
  const double sh = sin(0.5 * ky * Y), ch = cos(0.5 * ky * Y);
  u[0] = A * sx * cy;
  u[1] = A * cx * sh;
  const double uxXX = -kx * kx * u[0], uxYY = -ky * ky * u[0], uxXY = -A * kx * ky * cx * sy;
  const double uyXX = -kx * kx * u[1], uyYY = -0.25 * ky * ky * u[1], uyXY = -A * kx * 0.5 * ky * sx * ch;
  b[0] = -(D * uxXX + G * uxYY + C * uyXY);
  b[1] = -(D * uyYY + G * uyXX + C * uxXY);
}

static mpm_scene mms_scene(double h, int shape, int ppc)
{
  mpm_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.L = 192.0;
  sc.H = 32.0;
  sc.E = 1024.0;
  sc.nu = 0.25;
  sc.rho = 1.0;
  sc.model = MPM_DCOH_NONE;
  sc.snf = sc.stf = sc.U0 = sc.s0 = sc.q = 1.0;
  sc.sep_threshold = 1.0;
  sc.imp_factor = sc.imp_stf_factor = sc.le_factor = 1.0;
  sc.h = h;
  sc.ppc = ppc;
  sc.shape = shape;
  sc.head = MPM_HEAD_NONE;
  sc.solver = MPM_SOLVER_STATIC;
  sc.dt = 1.0;         /* no time: only checked */
  sc.speed = 1e-12;    /* no grip */
  sc.end_delta = 1e-9; /* only sizes the grid */
  return sc;
}

/* The body's perimeter nodes, both components held at rest (c = 0: MPM_DOF_HELD), in
 * place of the bar's grips; the sim owns the list.  0 when out of memory. */
static int hold_perimeter(mpm_sim *s)
{
  const mpm_grid *g = s->g;
  const double h = s->sc.h;
  const int i0 = (int)lround(-s->grid_ox0 / h), j0 = (int)lround(-g->oy / h);
  const int cx = (int)lround(s->sc.L / h), cy = (int)lround(s->sc.H / h);
  const int n = 2 * (2 * (cx + 1) + 2 * (cy - 1));
  mpm_bc *bc = realloc(s->bc, sizeof *bc * (size_t)n);
  if (!bc)
    return 0;
  s->bc = bc;
  int k = 0;
  for (int i = 0; i <= cx; i++)
    for (int j = 0; j <= cy; j++)
      if (i == 0 || i == cx || j == 0 || j == cy)
        for (uint8_t c = 0; c < 2; c++)
          bc[k++] = (mpm_bc){(int)mpm_grid_node(g, i0 + i, j0 + j), c, 0, MPM_BC_ANY, 0.0};
  assert(k == n);
  s->nbc = n;
  return 1;
}

/* Holds the exact u on the held components, sets the body force, solves; the relative
 * residual after the step into *res. */
static mpm_status solve(mpm_static *q, double *res, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  const mpm_grid *g = s->g;
  const size_t M = MPM_ST_MAX;
  double u[2], b[2];
  for (size_t k = 0; k < 2 * q->nslot; k++)
    if (q->eq[k] == MPM_DOF_HELD) {
      const size_t nd = k / 2;
      const double X = s->grid_ox0 + s->sc.h * (double)(nd / (size_t)g->nny);
      const double Y = g->oy + s->sc.h * (double)(nd % (size_t)g->nny);
      mms_exact(&s->sc, X, Y, u, b);
      q->held[k] = u[k % 2];
    }
  for (size_t c = 0; c < q->np; c++) {
    const size_t i = q->pid[c];
    mms_exact(&s->sc, s->p->x0[i], s->p->y0[i], u, b);
    for (int a = 0; a < q->cnt[c]; a++) {
      const size_t nd = (size_t)q->node[c * M + (size_t)a];
      /* the perimeter is the boundary: no particle reaches past it (file header) */
      assert(q->eq[2 * nd] != MPM_DOF_OFF && q->eq[2 * nd + 1] != MPM_DOF_OFF);
      q->fext[2 * nd] += s->p->V[i] * q->N[c * M + (size_t)a] * b[0];
      q->fext[2 * nd + 1] += s->p->V[i] * q->N[c * M + (size_t)a] * b[1];
    }
  }
  double fbig = 0.0;
  for (size_t k = 0; k < 2 * q->nslot; k++)
    fbig = fmax(fbig, fabs(q->fext[k]));
  mpm_status st = mpm_static_eval(q, 1);
  if (st == MPM_OK)
    st = mpm_lin_factor(q->lin);
  if (st == MPM_OK)
    st = mpm_lin_solve(q->lin, q->R, q->du);
  if (st != MPM_OK) {
    snprintf(err, errlen, "static manufactured solution: the linear solve failed (%s)", mpm_strerror(st));
    return st;
  }
  for (size_t k = 0; k < 2 * q->nslot; k++) /* K du = -R */
    if (q->eq[k] >= 0)
      q->Ut[k] -= q->du[q->eq[k]];
  if ((st = mpm_static_eval(q, 0)) != MPM_OK)
    return st;
  double r = 0.0;
  for (int k = 0; k < q->nfree; k++)
    r = fmax(r, fabs(q->R[k]));
  *res = r / fbig;
  return MPM_OK;
}

/* The errors over A: at the particles, the displacement interpolated with the
 * stiffness's weights against u at the reference place (*e); at the free nodes (*e_node,
 * unless NULL; the held ones are exact). */
static void measure(const mpm_static *q, double *e, double *e_node)
{
  const mpm_sim *s = q->s;
  const size_t M = MPM_ST_MAX, nny = (size_t)s->g->nny;
  const double h = s->sc.h;
  double e2 = 0.0, u[2], b[2];
  for (size_t c = 0; c < q->np; c++) {
    const size_t i = q->pid[c];
    double uh[2] = {0.0, 0.0};
    for (int a = 0; a < q->cnt[c]; a++) {
      const size_t nd = (size_t)q->node[c * M + (size_t)a];
      uh[0] += q->N[c * M + (size_t)a] * q->Ut[2 * nd];
      uh[1] += q->N[c * M + (size_t)a] * q->Ut[2 * nd + 1];
    }
    mms_exact(&s->sc, s->p->x0[i], s->p->y0[i], u, b);
    e2 += (uh[0] - u[0]) * (uh[0] - u[0]) + (uh[1] - u[1]) * (uh[1] - u[1]);
  }
  *e = sqrt(e2 / (double)q->np) / MMS_A;
  double n2 = 0.0;
  for (size_t k = 0; k < 2 * q->nslot; k++)
    if (q->eq[k] >= 0) {
      const size_t nd = k / 2;
      mms_exact(&s->sc, s->grid_ox0 + h * (double)(nd / nny), s->g->oy + h * (double)(nd % nny), u, b);
      n2 += (q->Ut[k] - u[k % 2]) * (q->Ut[k] - u[k % 2]);
    }
  if (e_node)
    *e_node = sqrt(2.0 * n2 / (double)q->nfree) / MMS_A; /* per node, both components */
}

mpm_status mpm_static_mms_error(double h, int shape, int ppc, double *e, double *e_node, char *err, size_t errlen)
{
  *e = NAN;
  if (e_node)
    *e_node = NAN;
  if (shape != MPM_SHAPE_LINEAR && shape != MPM_SHAPE_GIMP) {
    snprintf(err, errlen, "static manufactured solution: shape %d is neither linear nor gimp", shape);
    return MPM_EINVAL;
  }
  const mpm_scene sc = mms_scene(h, shape, ppc);
  mpm_sim *s = NULL;
  mpm_static *q = NULL;
  mpm_status st = mpm_sim_alloc(&sc, 1, &s, err, errlen); /* checks h and ppc */
  if (st != MPM_OK)
    return st;
  if (!hold_perimeter(s)) {
    mpm_sim_free(s);
    snprintf(err, errlen, "out of memory for the manufactured solution's boundary");
    return MPM_ENOMEM;
  }
  if ((st = mpm_static_alloc(s, &q, err, errlen)) != MPM_OK) {
    mpm_sim_free(s);
    return st;
  }
  double res = NAN;
  if (!(q->fext = calloc(2 * q->nslot, sizeof(double)))) {
    snprintf(err, errlen, "out of memory for the manufactured solution's body force");
    st = MPM_ENOMEM;
  } else if ((st = solve(q, &res, err, errlen)) == MPM_OK && !(res <= MMS_RTOL)) {
    snprintf(err, errlen, "static manufactured solution at h %g: residual %.3g of the body force after the solve",
             h, res);
    st = MPM_ENOTFINITE;
  }
  if (st == MPM_OK)
    measure(q, e, e_node);
  mpm_static_free(q);
  mpm_sim_free(s);
  return st;
}
