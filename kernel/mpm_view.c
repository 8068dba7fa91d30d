/*
 * mpm_view.c - what a caller reads of a sim (mpm.h; the sim itself stays opaque outside
 * kernel/): its scene, progress, particles, the grip's displacement, the energy sums
 * (eq. 10 for the dissipation) and the kernel's bookkeeping; the cut's latch, which the
 * step updates; and the two starts other than the scene's that the bench sets up.
 */
#include <math.h>
#include <string.h>

#include "mpm_fields.h"
#include "mpm_iface.h"
#include "mpm_kernel.h"
#include "mpm_specimen.h"

const mpm_scene *mpm_sim_scene(const mpm_sim *s)
{
  return &s->sc;
}

void mpm_sim_info_get(const mpm_sim *s, mpm_sim_info *out)
{
  *out = (mpm_sim_info){.step = s->step, .t = s->t, .P_grip = s->P_grip, .P_fixed = s->P_fixed, .cut = s->cut, .crack_tip = s->crack_tip, .zone_end = s->zone_end, .gap_min = s->gap_min,
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

/* The band has cut the bar once every particle row of the reference lattice holds a
 * separated particle: the bar is then in two parts (the scenes' bands run from the
 * bottom face to the top one).  Counted again only after new separations. */
void mpm_sim_cut(mpm_sim *s)
{
  if (s->cut || s->n_separate == s->cut_seen)
    return;
  s->cut_seen = s->n_separate;
  const mpm_particles *p = s->p;
  const double d = s->sc.h / sqrt((double)s->sc.ppc);
  memset(s->rowsep, 0, (size_t)s->nrow);
  int rows = 0;
  for (size_t k = 0; k < p->n; k++)
    if (p->sep[k]) {
      const int j = (int)(p->y0[k] / d);
      if (j >= 0 && j < s->nrow && !s->rowsep[j]) {
        s->rowsep[j] = 1;
        rows++;
      }
    }
  s->cut = rows == s->nrow;
}

double mpm_sim_grip_u(const mpm_sim *s, int ahead)
{
  if (s->sc.control == MPM_CONTROL_GRIP) /* the paper's: delta = speed t exactly */
    return s->sc.speed * (double)(s->step + ahead) * s->sc.dt;
  return s->ugrip + ahead * s->vgrip * s->sc.dt;
}

double mpm_sim_delta(const mpm_sim *s)
{
  if (s->sc.solver == MPM_SOLVER_STATIC)
    return s->ugrip;
  return s->sc.control == MPM_CONTROL_GRIP ? s->sc.speed * s->t : s->ugrip;
}

void mpm_particle_energy(const mpm_sim *s, size_t i, double *ke, double *se)
{
  const mpm_particles *p = s->p;
  const mpm_material *m = &s->mat[p->mat[i]];
  *ke = 0.5 * p->m[i] * (p->vx[i] * p->vx[i] + p->vy[i] * p->vy[i]);
  /* plane-stress compliance: exx = (sxx - nu syy)/E, eyy = (syy - nu sxx)/E, gxy = sxy/G */
  const double exx = (p->sxx[i] - m->nu * p->syy[i]) / m->E;
  const double eyy = (p->syy[i] - m->nu * p->sxx[i]) / m->E;
  *se = 0.5 * p->V[i] * (p->sxx[i] * exx + p->syy[i] * eyy + p->sxy[i] * p->sxy[i] / m->G);
}

void mpm_sim_energy(const mpm_sim *s, mpm_energy *e)
{
  const mpm_particles *p = s->p;
  double ke = 0.0, se = 0.0, wc = 0.0, dd = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->mat[i] == MPM_MAT_HEAD)
      continue; /* the machine, not the specimen */
    const mpm_material *m = &s->mat[p->mat[i]];
    if (p->mat[i] != MPM_MAT_DEBRIS) { /* debris: its KE and SE went into L_debris */
      double k1, s1;
      mpm_particle_energy(s, i, &k1, &s1);
      ke += k1;
      se += s1;
    }
    wc += p->wcoh[i];
    if (s->band) /* Le changes in time: the sum of U0 dlambda V / Le, step by step */
      dd += p->dis[i];
    else if (p->lam[i] > 0.0) /* eq. 10: U0 min(lambda, 1) per unit failure area V / Le */
      dd += m->U0 * fmin(p->lam[i], 1.0) * p->V[i] / m->Le;
  }
  e->W_ext = s->W_ext;
  e->KE = ke;
  e->SE = se;
  if (s->g && s->g->fld && s->g->fld->ifc) { /* the interface's (mpm_iface.c) */
    wc += s->led.W_iface;
    dd += mpm_iface_D(s) + s->led.D_static;
  } else if (s->sc.model && s->sc.path == MPM_PATH_IFACE) { /* the static solver's line alone */
    wc += s->led.W_iface;
    dd += s->led.D_static;
  }
  e->W_coh = wc;
  e->D = dd;
  e->L_bc = s->led.L_bc;
  e->L_flip = s->led.L_flip;
  e->L_scheme = s->led.L_scheme;
  e->W_head = s->led.W_head;
  e->L_contact = s->led.L_contact;
  e->L_debris = s->led.L_debris;
  e->L_damp = s->led.L_damp;
}

void mpm_sim_threads(const mpm_sim *s, mpm_threads_info *out)
{
  out->nmax = s->thr.nmax;
  out->steps_multi = s->thr.steps_multi;
  out->nprobe = s->thr.nprobe;
  out->nbusy = s->thr.nbusy;
}

size_t mpm_sim_bytes_per_particle(const mpm_sim *s)
{
  const size_t np = s->p->n, nn = (size_t)s->g->nnx * (size_t)s->g->nny;
  const size_t ncell = (size_t)s->g->ncx * (size_t)s->g->ncy;
  const size_t particles = np * (16 * sizeof(double) + 2);         /* mpm_particles  */
  const size_t sorting = np * (sizeof(double) + 1 + 2 * sizeof(uint32_t)) + (ncell + 1) * sizeof(size_t) +
                         ((size_t)s->nstrip + 1) * sizeof(size_t);
  const size_t fields = s->g->fld ? nn * (sizeof(mpm_node) + 1 + 3 * sizeof(double)) : 0;
  const size_t grid = nn * sizeof(mpm_node) + fields;
  const size_t other = s->nhead * sizeof(uint32_t) + (size_t)s->thr.nmax * sizeof(mpm_defer) +
                       (size_t)s->nbc * sizeof(mpm_bc);
  return (particles + sorting + grid + other + np / 2) / np;
}
