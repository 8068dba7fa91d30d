/*
 * separation.c - the separation detector of a run (separation.h).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "separation.h"

int ver_sep_init(ver_sep *d, double H, double h, int ppc, long win, double frac)
{
  memset(d, 0, sizeof *d);
  const int n1 = (int)lround(sqrt((double)ppc));
  d->dy = h / n1;
  d->nrow = (int)lround(H / d->dy);
  d->win = win > 0 ? win : 1;
  d->frac = frac;
  d->delta_cut = d->delta_load = d->delta_sep = -1;
  d->cut = calloc((size_t)(d->nrow > 0 ? d->nrow : 1), 1);
  d->ring = malloc(3 * sizeof(double) * (size_t)d->win);
  if (!d->cut || !d->ring) {
    ver_sep_free(d);
    return -1;
  }
  return 0;
}

void ver_sep_free(ver_sep *d)
{
  free(d->cut);
  free(d->ring);
  d->cut = NULL;
  d->ring = NULL;
}

static void settle(ver_sep *d)
{
  if (d->delta_sep < 0 && (d->delta_cut >= 0 || d->delta_load >= 0))
    d->delta_sep = d->delta_cut >= 0 && (d->delta_load < 0 || d->delta_cut < d->delta_load) ? d->delta_cut
                                                                                             : d->delta_load;
}

void ver_sep_cut(ver_sep *d, const double *y0, const uint8_t *sep, const uint8_t *mat, int skip_mat, size_t n,
                 double delta)
{
  if (d->delta_cut >= 0)
    return;
  int ncut = 0;
  memset(d->cut, 0, (size_t)d->nrow);
  for (size_t k = 0; k < n; k++)
    if (sep[k] && !(mat && mat[k] == skip_mat)) {
      const int j = (int)(y0[k] / d->dy);
      if (j >= 0 && j < d->nrow && !d->cut[j]) {
        d->cut[j] = 1;
        ncut++;
      }
    }
  if (ncut == d->nrow)
    d->delta_cut = delta;
}

void ver_sep_through(ver_sep *d, double delta)
{
  if (d->delta_cut < 0)
    d->delta_cut = delta;
}

void ver_sep_load(ver_sep *d, double delta, double Pg, double Pf, double peak, double delta_peak)
{
  const long w = d->win, slot = d->nseen % w;
  if (d->nseen >= w) { /* the row leaving the window */
    d->sum_g -= d->ring[3 * slot + 1];
    d->sum_f -= d->ring[3 * slot + 2];
  }
  d->sum_g += Pg;
  d->sum_f += Pf;
  d->amax = fmax(d->amax, fmax(fabs(Pg), fabs(Pf)));
  d->ring[3 * slot] = delta;
  d->ring[3 * slot + 1] = Pg;
  d->ring[3 * slot + 2] = Pf;
  d->nseen++;
  const long first = d->nseen % w; /* the oldest row of the window */
  if (d->delta_load < 0 && peak > 0 && d->nseen >= w && d->ring[3 * first] > delta_peak) {
    /* The running sums decide only where they are clearly above the threshold: each of
     * their 2 nseen additions rounds a sum of at most w amax by eps / 2 of it, so 4 nseen
     * eps w amax bounds their error.  Elsewhere the window is summed afresh, which keeps
     * the verdict exactly that of the plain sum and the cost linear in rows. */
    const double slack = 4.0 * DBL_EPSILON * (double)d->nseen * (double)w * d->amax;
    if (fmax(fabs(d->sum_g), fabs(d->sum_f)) - slack >= d->frac * peak * (double)w) {
      settle(d);
      return;
    }
    double mg = 0.0, mf = 0.0;
    for (long i = 0; i < w; i++) {
      const long j = (first + i) % w;
      mg += d->ring[3 * j + 1];
      mf += d->ring[3 * j + 2];
    }
    if (fmax(fabs(mg), fabs(mf)) / (double)w < d->frac * peak)
      d->delta_load = 0.5 * (d->ring[3 * first] + delta);
  }
  settle(d); /* after both tests of the row: the earlier of the two counts */
}

double ver_sep_static(double d0, double P0, double d1, double P1, double Ps)
{
  return P0 > P1 ? d1 + (Ps - P1) * (d1 - d0) / (P1 - P0) : d1;
}
