/*
 * mpm_shape.h - bilinear shape functions on the regular grid (sec. 2), shared by the
 * step's passes and the tests.  With r = (x - x_i) / h in [0, 1) the 1-D weights are
 * (1 - r, r) and the 1-D derivatives (-1/h, 1/h); N and grad N of the four nodes of a
 * cell are their products.  Nodes are stored column by column (mpm_grid_node), so the
 * cell's nodes (i,j), (i,j+1), (i+1,j), (i+1,j+1) sit at n00, n00 + 1, n00 + nny, n00 + nny + 1.
 */
#ifndef DELAM_MPM_SHAPE_H
#define DELAM_MPM_SHAPE_H

#include <stddef.h>

#include "mpm.h"

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

#endif
