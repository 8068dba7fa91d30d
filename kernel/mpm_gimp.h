/*
 * mpm_gimp.h - the step's passes with uGIMP shape functions (mpm_shape.h), private to
 * kernel/: the two scatters (mpm_gimp.c) and the gather that the grid-to-particle pass
 * of mpm_step.c shares with its bilinear twin.
 */
#ifndef DELAM_MPM_GIMP_H
#define DELAM_MPM_GIMP_H

#include "mpm.h"
#include "mpm_node.h"
#include "mpm_shape.h"
#include "mpm_iface.h"

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

/* ---- two velocity fields (mpm_fields.c) ---- */
mpm_fields *mpm_fields_alloc(size_t nn, double nx, double ny);
void mpm_fields_free(mpm_fields *f);
void mpm_fields_mark(mpm_sim *s);  /* before the scatter: split nodes and band centres   */
void mpm_fields_grid(mpm_sim *s); /* after mpm_nodes_update: the second field's eq. 4, contact */
void mpm_fields_start(mpm_sim *s); /* after mpm_nodes_start_velocity (USF, USAVG)        */
void mpm_fields_musl(mpm_sim *s);  /* after mpm_nodes_musl_velocity                           */

/* The side of a particle near a separated band, from its stencil's nodes n[0..cnt)
 * and weights w: 1 (the second field) when n . (x_p - c_p) > 0, with c_p the band
 * centre seen from the particle, the mean of crk over its split nodes weighted by
 * N_ip.  One side a particle, at all its nodes: a particle in two fields at once would
 * couple them again.  A tie (the separated particles of a one-particle-wide band sit
 * on c_p) goes to the first field, with a margin far above rounding (1e-9 cells). */
static inline int mpm_fields_side_w(const mpm_fields *f, const size_t *n, const double *w, int cnt, double x,
                                    double y, double h)
{
  double ws = 0.0, cx = 0.0, cy = 0.0;
  for (int q = 0; q < cnt; q++)
    if (f->split[n[q]]) {
      ws += w[q];
      cx += w[q] * f->crk[2 * n[q]];
      cy += w[q] * f->crk[2 * n[q] + 1];
    }
  if (!(ws > 0.0))
    return 0;
  return f->nx * (x - cx / ws) + f->ny * (y - cy / ws) > 1e-9 * h;
}

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

/* The side rule on the uGIMP stencil. */
static inline int mpm_fields_side(const mpm_fields *f, size_t n0, size_t nny, const mpm_gimp1 *gx,
                                  const mpm_gimp1 *gy, double x, double y, double h)
{
  size_t n[9];
  double w[9];
  mpm_gimp_stencil(n0, nny, gx, gy, n, w);
  return mpm_fields_side_w(f, n, w, 9, x, y, h);
}

/* The side of particle at (x, y), reference centre (x0, y0): the interface's by the
 * reference centre (decohesion.path = interface), else the band's rule above. */
static inline int mpm_fields_pside(const mpm_fields *f, size_t n0, size_t nny, const mpm_gimp1 *gx,
                                   const mpm_gimp1 *gy, double x, double y, double x0, double y0, double h)
{
  return f->ifc ? mpm_iface_side(f->ifc, x0, y0) : mpm_fields_side(f, n0, nny, gx, gy, x, y, h);
}

/* 1 if any of the bilinear stencil's nodes is split. */
static inline int mpm_fields_any4(const mpm_fields *f, size_t n00, size_t nny)
{
  if (!f || f->nsplit == 0)
    return 0;
  const uint8_t *s = f->split + n00;
  return (s[0] | s[1] | s[nny] | s[nny + 1]) != 0;
}

/* The record a particle on side `side` uses at node n. */
static inline mpm_node *mpm_fields_node(const mpm_fields *f, mpm_node *nd, size_t n, int side)
{
  return (side && f->split[n]) ? f->nd2 + n : nd + n;
}

/* 1 if any node of the 3 x 3 stencil from n0 is split. */
static inline int mpm_fields_any(const mpm_fields *f, size_t n0, size_t nny)
{
  if (!f || f->nsplit == 0)
    return 0;
  const uint8_t *s = f->split + n0;
  return (s[0] | s[1] | s[2] | s[nny] | s[nny + 1] | s[nny + 2] | s[2 * nny] | s[2 * nny + 1] | s[2 * nny + 2]) != 0;
}

/* mpm_gimp_gather with the field chosen per node. */
static inline void mpm_fields_gather(const mpm_fields *f, mpm_node *nd, size_t nny, const mpm_gimp1 *gx,
                                     const mpm_gimp1 *gy, int side, mpm_v4 *S, mpm_v4 *DX, mpm_v4 *DY)
{
  const mpm_v4 zero = {0.0};
  mpm_v4 s = zero, dx = zero, dy = zero;
  for (int a = 0; a < 3; a++) {
    mpm_v4 c = zero, d = zero;
    for (int b = 0; b < 3; b++) {
      const size_t n = (size_t)(gx->i0 + a) * nny + (size_t)(gy->i0 + b);
      const mpm_v4 v = node_load4(mpm_fields_node(f, nd, n, side));
      c += gy->S[b] * v;
      d += gy->dS[b] * v;
    }
    s += gx->S[a] * c;
    dx += gx->dS[a] * c;
    dy += gx->S[a] * d;
  }
  *S = s;
  *DX = dx;
  *DY = dy;
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
