/*
 * mpm_view.c - what a caller reads of a sim, and the two starts other than the scene's
 * that the bench sets up (mpm.h): the sim itself stays opaque outside kernel/.
 */
#include <math.h>

#include "mpm_kernel.h"

const mpm_scene *mpm_sim_scene(const mpm_sim *s)
{
  return &s->sc;
}

void mpm_sim_info_get(const mpm_sim *s, mpm_sim_info *out)
{
  *out = (mpm_sim_info){.step = s->step, .t = s->t, .P_grip = s->P_grip, .P_fixed = s->P_fixed, .cut = s->cut,
                        .n_soften = s->n_soften, .n_separate = s->n_separate, .n_bracketed = s->n_bracketed,
                        .n_debris = s->n_debris};
  for (int q = 0; q < MPM_T_N; q++)
    out->time_split[q] = s->time_split[q];
}

void mpm_sim_particles(const mpm_sim *s, mpm_particle_view *v)
{
  const mpm_particles *p = s->p;
  *v = (mpm_particle_view){.n = p->n, .nhead = s->nhead, .x = p->x, .y = p->y, .x0 = p->x0, .y0 = p->y0,
                           .vx = p->vx, .vy = p->vy, .m = p->m, .V = p->V, .sxx = p->sxx, .syy = p->syy,
                           .sxy = p->sxy, .lam = p->lam, .upn = p->upn, .upt = p->upt, .wcoh = p->wcoh,
                           .dis = p->dis, .mat = p->mat, .sep = p->sep};
}

/* Uniform uniaxial stress sigma along x: strains sigma/E and -nu sigma/E, the left end
 * at -delta, the right end fixed, mid-height fixed in y; the head moves with the grip,
 * stress-free.  Time and step are those at which the grip reaches delta. */
mpm_status mpm_sim_prestress(mpm_sim *s, double sigma)
{
  if (!isfinite(sigma))
    return MPM_EINVAL;
  const mpm_scene *sc = &s->sc;
  mpm_particles *p = s->p;
  const double exx = sigma / sc->E, eyy = -sc->nu * sigma / sc->E;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD) {
      p->x[k] = p->x0[k] - sc->L * exx;
      continue;
    }
    p->x[k] = p->x0[k] - (sc->L - p->x0[k]) * exx;
    p->y[k] = p->y0[k] + (p->y0[k] - 0.5 * sc->H) * eyy;
    p->sxx[k] = sigma;
  }
  s->t = sc->L * exx / sc->speed;
  s->step = (long)floor(s->t / sc->dt);
  s->t = s->step * sc->dt;
  return MPM_OK;
}

mpm_status mpm_sim_separate(mpm_sim *s, size_t i)
{
  mpm_particles *p = s->p;
  if (i >= p->n)
    return MPM_EINVAL;
  p->sep[i] = 1;
  p->lam[i] = 1.0;
  p->str2[i] = -1.0;
  return MPM_OK;
}
