/*
 * mpm_fields.h - two velocity fields across a separated band or the interface
 * (grid.fields = two, mpm_fields.c), private to kernel/: the fields' state, their
 * passes, and the per-particle side and record choice the scatters and gathers inline.
 */
#ifndef DELAM_MPM_FIELDS_H
#define DELAM_MPM_FIELDS_H

#include "mpm_kernel.h"
#include "mpm_gimp.h"
#include "mpm_iface.h"

/* The second velocity field (grid.fields = 2, mpm_fields.c): at a node that a separated
 * particle's support covers ("split"), the particles on the far side of the band, as
 * seen from the band's local centre (crk), sum into nd2 instead of nd. */
struct mpm_fields {
  mpm_node *nd2;           /* the second field's records, nnx * nny (used where split)   */
  uint8_t *split;          /* 1 where a node holds two fields this step                 */
  double *crk;             /* the band's local centre at a split node (x, y pairs)      */
  double *cw;              /* the weights summed into crk (scratch)                     */
  double *dc;              /* the velocity change the contact (or the interface) made in
                              field 1 and 2 at a split node this step (x, y of field 1,
                              then of field 2; 0 without contact): the ledger           */
  double nx, ny;           /* the failure plane's normal: side 2 is n . (x - crk) > 0   */
  int nsplit;              /* split nodes this step (0: one field everywhere)           */
  mpm_iface *ifc;          /* decohesion.path = interface: the split nodes are its, from
                              the first step; NULL otherwise                            */
};

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

#endif
