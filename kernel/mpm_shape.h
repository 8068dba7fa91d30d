/*
 * mpm_shape.h - bilinear shape functions on the regular grid (sec. 2), shared by the
 * step's passes and the tests.  With r = (x - x_i) / h in [0, 1) the 1-D weights are
 * (1 - r, r) and the 1-D derivatives (-1/h, 1/h); N and grad N of the four nodes of a
 * cell are their products.  Nodes are stored column by column (mpm_grid_node), so the
 * cell's nodes (i,j), (i,j+1), (i+1,j), (i+1,j+1) sit at n00, n00 + 1, n00 + nny, n00 + nny + 1.
 */
#ifndef DELAM_MPM_SHAPE_H
#define DELAM_MPM_SHAPE_H

#include <math.h>
#include <stddef.h>

#include "mpm_kernel.h"

typedef struct {
  size_t n00;                 /* index of node (i, j)                                  */
  double wx0, wx1, wy0, wy1;  /* 1-D weights                                           */
} mpm_shape;

/* Cell and weights of point (x, y); returns 0 (and the first cell) if it lies outside
 * the grid. */
static inline int mpm_shape_at(const mpm_grid *g, double x, double y, mpm_shape *s)
{
  const double fx = (x - g->ox) * g->ihx, fy = (y - g->oy) * g->ihy;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < (double)g->ncx && fy < (double)g->ncy)) {
    s->n00 = 0;
    s->wx0 = s->wy0 = 1.0;
    s->wx1 = s->wy1 = 0.0;
    return 0;
  }
  const int i = (int)fx, j = (int)fy;
  const double rx = fx - i, ry = fy - j;
  s->n00 = (size_t)i * (size_t)g->nny + (size_t)j;
  s->wx0 = 1.0 - rx;
  s->wx1 = rx;
  s->wy0 = 1.0 - ry;
  s->wy1 = ry;
  return 1;
}

/* The same for a point known to lie inside the grid (the gather passes, after the
 * scatter has checked every particle). */
static inline void mpm_shape_inside(const mpm_grid *g, double x, double y, mpm_shape *s)
{
  const double fx = (x - g->ox) * g->ihx, fy = (y - g->oy) * g->ihy;
  const int i = (int)fx, j = (int)fy;
  s->n00 = (size_t)i * (size_t)g->nny + (size_t)j;
  s->wx1 = fx - i;
  s->wx0 = 1.0 - s->wx1;
  s->wy1 = fy - j;
  s->wy0 = 1.0 - s->wy1;
}

/* The four N and grad N on square cells of side h, in the order (i,j), (i+1,j),
 * (i,j+1), (i+1,j+1).  (The step's loops write the same with hx and hy.) */
static inline void mpm_shape_eval(const mpm_shape *s, double h, double N[4], double Gx[4], double Gy[4])
{
  const double ih = 1.0 / h;
  N[0] = s->wx0 * s->wy0; N[1] = s->wx1 * s->wy0; N[2] = s->wx0 * s->wy1; N[3] = s->wx1 * s->wy1;
  Gx[0] = -ih * s->wy0;   Gx[1] = ih * s->wy0;    Gx[2] = -ih * s->wy1;   Gx[3] = ih * s->wy1;
  Gy[0] = -ih * s->wx0;   Gy[1] = -ih * s->wx1;   Gy[2] = ih * s->wx0;    Gy[3] = ih * s->wx1;
}

/* ---- uGIMP (Bardenhagen and Kober 2004, undeformed particle domains) ----
 * A particle is a square of half-side l = h / (2 sqrt ppc) whose weight at node i is
 * the hat N_i averaged over that square.  In 1-D, with d = x_p - x_i in cells and
 * lc = l / h (0 < lc <= 1/2):
 *   |d| < lc             S = 1 - (d^2 + lc^2) / (2 lc)       dS/dx = -d / (lc h)
 *   lc <= |d| < 1 - lc   S = 1 - |d|                         dS/dx = -sgn(d) / h
 *   1 - lc <= |d| < 1+lc S = (1 + lc - |d|)^2 / (4 lc)       dS/dx = -sgn(d) (1 + lc - |d|) / (2 lc h)
 * and 0 beyond.  Weights and gradients are continuous as the particle crosses a cell
 * edge, which removes the cell-crossing force error of the bilinear hats; with one
 * particle per cell (lc = 1/2) S is the quadratic B-spline.  The support is 3 nodes:
 * the nearest node i0 and its two neighbours (|d| < 1 + lc <= 3/2). */
typedef struct {
  int i0;          /* first of the three nodes (the nearest node minus one)            */
  double S[3];     /* weights of nodes i0, i0 + 1, i0 + 2                               */
  double dS[3];    /* their derivatives d/dx_p, times h (so in 1 / cells)              */
} mpm_gimp1;

/* The weights above, evaluated without branches (the three regions of the table
 * become clamps).  With c the nearest node, d0 = f - c in [-1/2, 1/2], and the
 * particle's overlaps into the cells of the outer nodes rl = lc - d0, rr = lc + d0:
 *   S_right = w(rr), S_left = w(rl),  w(r) = min(max(r, 0), 2 lc)^2 / (4 lc) + max(r - 2 lc, 0),
 *   dS_right = w'(rr), dS_left = -w'(rl),  w'(r) = min(max(r, 0), 2 lc) / (2 lc),
 * and the centre node takes the rest (partition of unity: S_c = 1 - S_l - S_r,
 * dS_c = -(dS_l + dS_r)), which is the table's 1 - (d^2 + lc^2) / (2 lc) for |d0| < lc
 * and 1 - |d0| beyond.  test_mpm_gimp.c checks them against the definition. */
static inline void mpm_gimp_1d(double f, double lc, mpm_gimp1 *o)
{
  const double c = floor(f + 0.5), d0 = f - c, w2 = 2.0 * lc, i2 = 0.5 / lc;
  const double rl = lc - d0, rr = lc + d0;
  /* clamps as comparisons, not fmin / fmax: those are library calls where NaN rules apply */
  const double cl = rl < 0.0 ? 0.0 : (rl > w2 ? w2 : rl), cr = rr < 0.0 ? 0.0 : (rr > w2 ? w2 : rr);
  const double el = rl > w2 ? rl - w2 : 0.0, er = rr > w2 ? rr - w2 : 0.0;
  const double sl = 0.5 * i2 * cl * cl + el, sr = 0.5 * i2 * cr * cr + er;
  const double gl = -cl * i2, gr = cr * i2;
  o->i0 = (int)c - 1;
  o->S[0] = sl;
  o->S[1] = 1.0 - sl - sr;
  o->S[2] = sr;
  o->dS[0] = gl;
  o->dS[1] = -(gl + gr);
  o->dS[2] = gr;
}

/* 1 if the particle at (x, y) has its 3 x 3 nodes inside the grid. */
static inline int mpm_gimp_inside(const mpm_grid *g, double x, double y)
{
  const double fx = (x - g->ox) * g->ihx, fy = (y - g->oy) * g->ihy;
  return fx >= 0.5 && fy >= 0.5 && fx < (double)g->ncx - 0.5 && fy < (double)g->ncy - 0.5;
}

#endif
