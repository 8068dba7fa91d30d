/*
 * mpm_grid.c - the background grid: nodal arrays of a regular lattice (sec. 2).
 * The grid carries no state between steps; it is zeroed at the start of each one.
 */
#include <stdlib.h>
#include <string.h>

#include "mpm.h"
#include "mpm_kernel.h"

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
  g->nd = aligned_alloc(_Alignof(mpm_node), nn * sizeof(mpm_node));
  if (!g->nd) {
    mpm_grid_free(g);
    return NULL;
  }
  memset(g->nd, 0, nn * sizeof(mpm_node));
  return g;
}

void mpm_grid_free(mpm_grid *g)
{
  if (!g)
    return;
  free(g->nd);
  free(g);
}
