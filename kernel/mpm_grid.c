/*
 * mpm_grid.c - the background grid: nodal arrays of a regular lattice (sec. 2).
 * The grid carries no state between steps; it is zeroed at the start of each one.
 */
#include <stdlib.h>

#include "mpm.h"

mpm_grid *mpm_grid_alloc(int ncx, int ncy, double ox, double oy, double h)
{
  if (ncx < 1 || ncy < 1 || !(h > 0.0))
    return NULL;
  mpm_grid *g = calloc(1, sizeof *g);
  if (!g)
    return NULL;
  g->ncx = ncx;
  g->ncy = ncy;
  g->nnx = ncx + 1;
  g->nny = ncy + 1;
  g->ox = ox;
  g->oy = oy;
  g->h = g->hx = h;
  g->ihx = g->ihy = 1.0 / h;
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  g->m = calloc(nn, sizeof(double));
  g->px = calloc(nn, sizeof(double));
  g->py = calloc(nn, sizeof(double));
  g->fx = calloc(nn, sizeof(double));
  g->fy = calloc(nn, sizeof(double));
  if (!g->m || !g->px || !g->py || !g->fx || !g->fy) {
    mpm_grid_free(g);
    return NULL;
  }
  return g;
}

void mpm_grid_free(mpm_grid *g)
{
  if (!g)
    return;
  free(g->m);
  free(g->px);
  free(g->py);
  free(g->fx);
  free(g->fy);
  free(g);
}
