/*
 * mpm_gimp.h - the step's passes with uGIMP shape functions (mpm_shape.h), private to
 * kernel/: the two scatters (mpm_gimp.c) and the gather that the grid-to-particle pass
 * of mpm_step.c shares with its bilinear twin.
 */
#ifndef DELAM_MPM_GIMP_H
#define DELAM_MPM_GIMP_H

#include "mpm_kernel.h"
#include "mpm_node.h"
#include "mpm_shape.h"

/* The particle's half-side in cells of the current grid, along x and y. */
static inline void mpm_gimp_lc(const mpm_sim *s, double *lcx, double *lcy)
{
  const double l = 0.5 * s->sc.h / sqrt((double)s->sc.ppc);
  *lcx = l * s->g->ihx;
  *lcy = l * s->g->ihy;
}

/* eqs. 2, 3 for the particles [a, b); 1 if one of them is outside the grid. */
int mpm_gimp_p2g_range(const mpm_grid *g, const mpm_particles *p, size_t a, size_t b, double lcx, double lcy);
/* MUSL: eq. 6 from lanes (fx, fy), the new momentum into lanes (qx, qy); returns the
 * energy ledger's sum m |dv_p|^2 over the range (mpm_step.c). */
double mpm_gimp_musl_range(const mpm_grid *g, mpm_particles *p, size_t a, size_t b, double lcx, double lcy);

/* The uGIMP stencil from its first node n0: 3 x 3 nodes, weights Sx Sy. */
static inline void mpm_gimp_stencil(size_t n0, size_t nny, const mpm_gimp1 *gx, const mpm_gimp1 *gy, size_t n[9],
                                    double w[9])
{
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      n[3 * a + b] = n0 + (size_t)a * nny + (size_t)b;
      w[3 * a + b] = gx->S[a] * gy->S[b];
    }
}

/* The bilinear stencil of sh: nodes (i,j), (i+1,j), (i,j+1), (i+1,j+1), weights N. */
static inline void mpm_shape_stencil(const mpm_shape *sh, size_t nny, size_t n[4], double w[4])
{
  n[0] = sh->n00;
  n[1] = sh->n00 + nny;
  n[2] = sh->n00 + 1;
  n[3] = sh->n00 + nny + 1;
  w[0] = sh->wx0 * sh->wy0;
  w[1] = sh->wx1 * sh->wy0;
  w[2] = sh->wx0 * sh->wy1;
  w[3] = sh->wx1 * sh->wy1;
}

/* The field S = sum N_i a_i of the lanes (px, py, fx, fy) at a particle and its
 * derivatives DX = sum dN_i/dx a_i, DY = sum dN_i/dy a_i, in 1 / cells (the caller
 * scales by 1 / hx and 1 / hy).  Column sums first: N_i is a product Sx Sy. */
static inline __attribute__((always_inline)) void mpm_gimp_gather(const mpm_node *nd, size_t nny,
                                                                  const mpm_gimp1 *gx, const mpm_gimp1 *gy,
                                                                  mpm_v4 *S, mpm_v4 *DX, mpm_v4 *DY)
{
  const mpm_v4 zero = {0.0};
  mpm_v4 s = zero, dx = zero, dy = zero;
  for (int a = 0; a < 3; a++) {
    const mpm_node *col = nd + (size_t)(gx->i0 + a) * nny + (size_t)gy->i0;
    const mpm_v4 n0 = node_load4(col), n1 = node_load4(col + 1), n2 = node_load4(col + 2);
    const mpm_v4 c = gy->S[0] * n0 + gy->S[1] * n1 + gy->S[2] * n2;
    const mpm_v4 d = gy->dS[0] * n0 + gy->dS[1] * n1 + gy->dS[2] * n2;
    s += gx->S[a] * c;
    dx += gx->dS[a] * c;
    dy += gx->S[a] * d;
  }
  *S = s;
  *DX = dx;
  *DY = dy;
}

#endif
