/*
 * mpm_gimp.c - the particle-to-grid scatters (eqs. 2, 3, and MUSL's second projection)
 * with uGIMP weights (grid.shape = gimp; mpm_shape.h has the weights and why).
 *
 * A particle adds to its 3 x 3 nodes.  With P = (m, m vx, m vy) and the force lanes
 * FX = (V / hx)(sxx, sxy), FY = (V / hy)(sxy, syy), node (a, b) receives
 *   Sx_a Sy_b P - dSx_a Sy_b FX - Sx_a dSy_b FY  =  Sx_a T_b - dSx_a R_b,
 *   T_b = Sy_b P - dSy_b FY,  R_b = Sy_b FX,
 * i.e. N_i (m, m v) and f_i = -V sigma . grad N_i (eq. 3).  Threads: the particles of a
 * strip stay within half a cell of it between sorts (mpm_step.c sets the resort flag
 * beyond), so with the nearest node's neighbours they write the same node columns as a
 * bilinear particle drifting a whole cell, and the strips' colouring holds (mpm_sort.c).
 */
#include <math.h>

#include "mpm_gimp.h"

int mpm_gimp_p2g_range(const mpm_grid *gg, const mpm_particles *p, size_t a, size_t b, double lcx, double lcy)
{
  const mpm_grid geo = *gg, *g = &geo;
  const size_t nny = (size_t)g->nny;
  const double ihx = g->ihx, ihy = g->ihy;
  mpm_node *restrict nd = g->nd;
  int out = 0;
  for (size_t k = a; k < b; k++) {
    if (!mpm_gimp_inside(g, p->x[k], p->y[k])) {
      out = 1;
      continue;
    }
    mpm_gimp1 sx, sy;
    mpm_gimp_1d((p->x[k] - g->ox) * ihx, lcx, &sx);
    mpm_gimp_1d((p->y[k] - g->oy) * ihy, lcy, &sy);
    const double mm = p->m[k], Vx = p->V[k] * ihx, Vy = p->V[k] * ihy;
    const mpm_v8 P = {mm, mm * p->vx[k], mm * p->vy[k], 0.0, 0.0, 0.0, 0.0, 0.0};
    const mpm_v8 FX = {0.0, 0.0, 0.0, Vx * p->sxx[k], Vx * p->sxy[k], 0.0, 0.0, 0.0};
    const mpm_v8 FY = {0.0, 0.0, 0.0, Vy * p->sxy[k], Vy * p->syy[k], 0.0, 0.0, 0.0};
    mpm_v8 T[3], R[3];
    for (int j = 0; j < 3; j++) {
      T[j] = sy.S[j] * P - sy.dS[j] * FY;
      R[j] = sy.S[j] * FX;
    }
    for (int i = 0; i < 3; i++) {
      mpm_node *col = nd + (size_t)(sx.i0 + i) * nny + (size_t)sy.i0;
      for (int j = 0; j < 3; j++)
        node_add(col + j, sx.S[i] * T[j] - sx.dS[i] * R[j]);
    }
  }
  return out;
}

void mpm_gimp_musl_range(const mpm_grid *gg, mpm_particles *p, size_t a, size_t b, double lcx, double lcy)
{
  const mpm_grid geo = *gg, *g = &geo;
  const size_t nny = (size_t)g->nny;
  mpm_node *restrict nd = g->nd;
  double *restrict vx = p->vx, *restrict vy = p->vy;
  for (size_t k = a; k < b; k++) {
    mpm_gimp1 sx, sy;
    mpm_gimp_1d((p->x[k] - g->ox) * g->ihx, lcx, &sx);
    mpm_gimp_1d((p->y[k] - g->oy) * g->ihy, lcy, &sy);
    mpm_v4 S, DX, DY;
    mpm_gimp_gather(nd, nny, &sx, &sy, &S, &DX, &DY);
    const double vxn = vx[k] + S[GFX], vyn = vy[k] + S[GFY];
    vx[k] = vxn;
    vy[k] = vyn;
    const mpm_v8 Q = {0.0, 0.0, 0.0, 0.0, 0.0, p->m[k] * vxn, p->m[k] * vyn, 0.0};
    for (int i = 0; i < 3; i++) {
      mpm_node *col = nd + (size_t)(sx.i0 + i) * nny + (size_t)sy.i0;
      for (int j = 0; j < 3; j++)
        node_add(col + j, (sx.S[i] * sy.S[j]) * Q);
    }
  }
}
