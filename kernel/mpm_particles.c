/*
 * mpm_particles.c - material points as a structure of arrays (sec. 2).
 */
#include <stdlib.h>

#include "mpm.h"
#include "mpm_kernel.h"

mpm_particles *mpm_particles_alloc(size_t n)
{
  if (n == 0)
    return NULL;
  mpm_particles *p = calloc(1, sizeof *p);
  if (!p)
    return NULL;
  p->n = n;
  double **dbl[] = {&p->x, &p->y, &p->x0, &p->y0, &p->vx, &p->vy, &p->m, &p->V, &p->sxx,
                    &p->syy, &p->sxy, &p->lam, &p->upn, &p->upt, &p->wcoh, &p->str2, &p->dis};
  for (size_t k = 0; k < sizeof dbl / sizeof dbl[0]; k++)
    if (!(*dbl[k] = calloc(n, sizeof(double)))) {
      mpm_particles_free(p);
      return NULL;
    }
  for (size_t k = 0; k < n; k++)
    p->str2[k] = 1.0;
  p->mat = calloc(n, 1);
  p->sep = calloc(n, 1);
  if (!p->mat || !p->sep) {
    mpm_particles_free(p);
    return NULL;
  }
  return p;
}

int mpm_particles_alloc_laid(mpm_particles *p)
{
  p->wdx = calloc(p->n, sizeof(double));
  p->wdy = calloc(p->n, sizeof(double));
  return p->wdx && p->wdy ? 0 : -1;
}

int mpm_particles_alloc_viscous(mpm_particles *p)
{
  p->vxx = calloc(p->n, sizeof(double));
  p->vyy = calloc(p->n, sizeof(double));
  p->vxy = calloc(p->n, sizeof(double));
  return p->vxx && p->vyy && p->vxy ? 0 : -1;
}

void mpm_particles_free(mpm_particles *p)
{
  if (!p)
    return;
  double *dbl[] = {p->x, p->y, p->x0, p->y0, p->vx, p->vy, p->m, p->V, p->sxx,
                   p->syy, p->sxy, p->lam, p->upn, p->upt, p->wcoh, p->str2, p->dis};
  for (size_t k = 0; k < sizeof dbl / sizeof dbl[0]; k++)
    free(dbl[k]);
  free(p->mat);
  free(p->sep);
  free(p->vxx);
  free(p->vyy);
  free(p->vxy);
  free(p->wdx);
  free(p->wdy);
  free(p);
}

void mpm_particles_momentum(const mpm_particles *p, double *px, double *py)
{
  double sx = 0.0, sy = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    sx += p->m[i] * p->vx[i];
    sy += p->m[i] * p->vy[i];
  }
  *px = sx;
  *py = sy;
}
