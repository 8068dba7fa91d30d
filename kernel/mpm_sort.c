/*
 * mpm_sort.c - particles sorted by cell, and the strips that let the particle-to-grid
 * scatter run on several threads with no atomics and a summation order independent of
 * the thread count.
 *
 * Cells are numbered column by column (key = i * ncy + j), like the nodes.  Columns are
 * grouped into strips of MPM_STRIP; a strip's particles write to its node columns plus
 * one on each side, so strips of one colour (even or odd) never share a node and run in
 * parallel; each node receives its sums in a fixed order (its even strip, then its odd
 * one, each in particle order).  A particle that drifts further is caught by the gather
 * (resort flag).  uGIMP sorts by the dual cell (the unit square centred on the nearest
 * node, key from floor(x / h + 1/2)), whose particles share their 3 x 3 nodes, and may
 * drift only half a cell between sorts.
 */
#include <assert.h>
#include <string.h>

#include "mpm.h"
#include "mpm_kernel.h"

_Static_assert(MPM_STRIP >= 3, "strips must be 3 columns or wider for the colouring to be safe");

static void permute_d(double **a, double **scratch, const uint32_t *perm, size_t n)
{
  double *src = *a, *dst = *scratch;
  for (size_t k = 0; k < n; k++)
    dst[k] = src[perm[k]];
  *a = dst;
  *scratch = src;
}

static void permute_u8(uint8_t **a, uint8_t **scratch, const uint32_t *perm, size_t n)
{
  uint8_t *src = *a, *dst = *scratch;
  for (size_t k = 0; k < n; k++)
    dst[k] = src[perm[k]];
  *a = dst;
  *scratch = src;
}

void mpm_sim_sort(mpm_sim *s)
{
  mpm_particles *p = s->p;
  const mpm_grid *g = s->g;
  const size_t n = p->n, ncell = (size_t)g->ncx * (size_t)g->ncy;
  const double ihx = g->ihx, ihy = g->ihy, shift = s->sc.shape == MPM_SHAPE_GIMP ? 0.5 : 0.0;
  memset(s->count, 0, (ncell + 1) * sizeof(size_t));
  for (size_t k = 0; k < n; k++) {
    /* Outside the grid (caught by the step) or not finite: clamp, only to sort. */
    double fx = (p->x[k] - g->ox) * ihx + shift, fy = (p->y[k] - g->oy) * ihy + shift;
    fx = fx >= 0.0 ? (fx < g->ncx ? fx : g->ncx - 1) : 0.0;
    fy = fy >= 0.0 ? (fy < g->ncy ? fy : g->ncy - 1) : 0.0;
    const uint32_t key = (uint32_t)((size_t)fx * (size_t)g->ncy + (size_t)fy);
    s->key[k] = key;
    s->count[key + 1]++;
  }
  for (size_t c = 0; c < ncell; c++)
    s->count[c + 1] += s->count[c];
  /* count[c] is now the first slot of cell c */
  for (int q = 0; q <= s->nstrip; q++) {
    const size_t col = (size_t)q * MPM_STRIP;
    s->strip_start[q] = col >= (size_t)g->ncx ? n : s->count[col * (size_t)g->ncy];
  }
  for (size_t k = 0; k < n; k++)
    s->perm[s->count[s->key[k]]++] = (uint32_t)k;
  double **dbl[] = {&p->x, &p->y, &p->x0, &p->y0, &p->vx, &p->vy, &p->m, &p->V, &p->sxx,
                    &p->syy, &p->sxy, &p->lam, &p->upn, &p->upt, &p->wcoh, &p->str2, &p->dis};
  for (size_t f = 0; f < sizeof dbl / sizeof dbl[0]; f++)
    permute_d(dbl[f], &s->scratch, s->perm, n);
  permute_u8(&p->mat, &s->scratch8, s->perm, n);
  permute_u8(&p->sep, &s->scratch8, s->perm, n);
  if (p->wdx) { /* grid.weights = laid */
    permute_d(&p->wdx, &s->scratch, s->perm, n);
    permute_d(&p->wdy, &s->scratch, s->perm, n);
  }
  if (p->vxx) { /* time.damping_beta */
    permute_d(&p->vxx, &s->scratch, s->perm, n);
    permute_d(&p->vyy, &s->scratch, s->perm, n);
    permute_d(&p->vxy, &s->scratch, s->perm, n);
  }
  size_t nh = 0;
  for (size_t k = 0; k < n; k++)
    if (p->mat[k] == MPM_MAT_HEAD)
      s->head[nh++] = (uint32_t)k;
  assert(nh == s->nhead);
  s->resort = 0;
}
