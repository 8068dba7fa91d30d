/*
 * mpm_static_iface.c - the quasi-static solver's crack as a cohesive interface
 * (decohesion.path = interface): the line at alpha through the flaw's particle splits the
 * bar's particles into two sides (mpm_iface_side, the explicit interface's rule); a node
 * whose stencil holds particles of both sides gets a second displacement slot for the far
 * side's particles, and between its two slots acts the paper's law (secs. 3-4, Model 1 or 2)
 * on the jump w = u_far - u_near, per unit of the node's share of the line A.
 *
 * The law is the particle update itself (mpm_dcoh_update, with its algorithmic tangent),
 * driven by the jump instead of a strain: a material whose "strain" e_nn = w . n,
 * e_nt = w . t / 2 meets a stiffness k0 (E1 = G = k0, E2 = 0) and Le = 1, so that the
 * decohesion "strain" is the opening itself, d ud = d lambda ubar0 m* (eqs. 19, 24).
 * Before the traction reaches the strength (eq. 23) the tie is elastic with k0 =
 * MPM_QS_TIE E / L per unit area: it adds 1 / MPM_QS_TIE of the bar's own compliance to
 * the curve (the explicit interface sticks rigidly; a rigid tie would need the pairs'
 * unknowns merged and split again at the onset).  After the onset the traction softens
 * with the opening to zero at lambda 1, where the line separates (eqs. 56-58; compression
 * closes it first and is carried, shear is released).
 *
 * A: a uniform stress sigma puts the force sigma a_0 on a split node's near slot, a_0 =
 * sum over the near side's particles of V grad N; its share of the line is A = a_0 . n,
 * so that a uniform traction on the line balances the particles exactly where a_0 lies
 * along n (at 90 deg, on a node column).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_iface.h"
#include "mpm_static.h"

#define MPM_QS_TIE 1e6 /* the tie's stiffness before the onset, k0 L / E per unit area */

void mpm_static_iface_free(mpm_static *q)
{
  free(q->pnode);
  free(q->pA);
  free(q->pst);
  free(q->ptr);
  free(q->pw);
  free(q->pf);
}

mpm_status mpm_static_iface_setup(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  const mpm_particles *p = s->p;
  const mpm_iface *f = s->g && s->g->fld ? s->g->fld->ifc : NULL;
  const size_t M = MPM_ST_MAX, nn = q->nn;
  uint8_t *mask = calloc(nn, 1);
  double *ax = calloc(nn, sizeof(double)), *ay = calloc(nn, sizeof(double));
  if (!f || !mask || !ax || !ay) {
    free(mask);
    free(ax);
    free(ay);
    snprintf(err, errlen, "out of memory for the static interface (or no interface line)");
    return MPM_ENOMEM;
  }
  /* which sides touch each node; the near side's sum of V grad N */
  for (size_t c = 0; c < q->np; c++) {
    const size_t k = q->pid[c];
    const int side = mpm_iface_side(f, p->x0[k], p->y0[k]);
    for (int a = 0; a < q->cnt[c]; a++) {
      const size_t nd = (size_t)q->node[c * M + (size_t)a];
      mask[nd] |= (uint8_t)(1u << side);
      if (!side) {
        ax[nd] += p->V[k] * q->Gx[c * M + (size_t)a];
        ay[nd] += p->V[k] * q->Gy[c * M + (size_t)a];
      }
    }
  }
  int np = 0;
  for (size_t nd = 0; nd < nn; nd++)
    np += mask[nd] == 3;
  q->npair = np;
  q->pnode = malloc((size_t)(np ? np : 1) * sizeof *q->pnode);
  q->pA = malloc((size_t)(np ? np : 1) * sizeof(double));
  q->pst = calloc((size_t)(np ? np : 1), sizeof *q->pst);
  q->ptr = calloc((size_t)(np ? np : 1), sizeof *q->ptr);
  q->pw = calloc((size_t)(np ? np : 1), sizeof(double));
  q->pf = calloc(4 * (size_t)(np ? np : 1), sizeof(double));
  int ok = q->pnode && q->pA && q->pst && q->ptr && q->pw && q->pf;
  for (size_t nd = 0, i = 0; ok && nd < nn; nd++)
    if (mask[nd] == 3) {
      q->pnode[i] = (int)nd;
      q->pA[i] = fmax(f->nx * ax[nd] + f->ny * ay[nd], 0.0);
      i++;
    }
  /* the far side's particles use the second slot of a split node */
  for (size_t c = 0; ok && c < q->np; c++) {
    const size_t k = q->pid[c];
    if (!mpm_iface_side(f, p->x0[k], p->y0[k]))
      continue;
    for (int a = 0; a < q->cnt[c]; a++) {
      int *nd = &q->node[c * M + (size_t)a];
      if (mask[*nd] == 3)
        *nd += (int)nn;
    }
  }
  free(mask);
  free(ax);
  free(ay);
  if (!ok) {
    snprintf(err, errlen, "out of memory for the static interface's %d split nodes", np);
    return MPM_ENOMEM;
  }
  /* the law as a material of the update: the bar's strengths and U0, stiffness k0 */
  mpm_material *m = &q->imat;
  *m = s->mat[MPM_MAT_BAR];
  m->model = s->sc.model;
  m->E1 = m->G = MPM_QS_TIE * s->sc.E / s->sc.L;
  m->E2 = 0.0;
  m->Le = 1.0;
  m->visc = 0.0;
  m->snf = s->sc.snf * s->sc.imp_factor; /* the line's strength: the flaw's, if any */
  m->stf = s->sc.stf * s->sc.imp_stf_factor;
  mpm_material_derive(m);
  return MPM_OK;
}

/* The strain the update sees for a jump (wx, wy): e_nn = w . n, e_nt = w . t / 2, e_tt = 0. */
static void jump_strain(const mpm_material *m, double wx, double wy, double de[3])
{
  const double en = m->nx * wx + m->ny * wy, et = 0.5 * (m->tx * wx + m->ty * wy);
  de[0] = en * m->nx * m->nx + 2.0 * et * m->nx * m->tx;
  de[1] = en * m->ny * m->ny + 2.0 * et * m->ny * m->ty;
  de[2] = en * m->nx * m->ny + et * (m->nx * m->ty + m->ny * m->tx);
}

void mpm_static_iface_eval(mpm_static *q, int tangent, double *Ax, double *D, double *C)
{
  const mpm_material *m = &q->imat;
  const size_t nn = q->nn;
  double Dl = 0.0, Cl = 0.0;
  /* d de / d w, columns for wx and wy */
  double J[3][2];
  {
    double a[3], b[3];
    jump_strain(m, 1.0, 0.0, a);
    jump_strain(m, 0.0, 1.0, b);
    for (int i = 0; i < 3; i++) {
      J[i][0] = a[i];
      J[i][1] = b[i];
    }
  }
  for (int pi = 0; pi < q->npair; pi++) {
    const size_t s0 = (size_t)q->pnode[pi], s1 = nn + s0;
    const double A = q->pA[pi];
    const double wx = (q->Ut[2 * s1] - q->Ut[2 * s0]) - (q->Un[2 * s1] - q->Un[2 * s0]);
    const double wy = (q->Ut[2 * s1 + 1] - q->Ut[2 * s0 + 1]) - (q->Un[2 * s1 + 1] - q->Un[2 * s0 + 1]);
    double de[3];
    jump_strain(m, wx, wy, de);
    mpm_dinfo info;
    mpm_dcoh_update(m, &q->pst[pi], de, &q->ptr[pi], &info, q->dw);
    const mpm_dstate *o = &q->ptr[pi];
    q->pw[pi] = info.w * A;
    Dl += m->U0 * fmin(o->lam, 1.0) * A;
    Cl += m->U0 * o->lam * A;
    /* the traction sigma . n on the near side, pulling it toward the far one */
    const double tx = o->sxx * m->nx + o->sxy * m->ny, ty = o->sxy * m->nx + o->syy * m->ny;
    const double f[4] = {-A * tx, -A * ty, A * tx, A * ty}; /* residual: f_int - the law's pull */
    for (int a = 0; a < 4; a++) {
      const int e = q->eq[2 * (a < 2 ? s0 : s1) + (size_t)(a % 2)];
      if (e >= 0)
        q->R[e] += f[a];
      q->pf[4 * pi + a] = f[a];
    }
    if (!tangent)
      continue;
    double Dm[3][3], dl[3];
    mpm_dcoh_tangent(m, &q->pst[pi], de, Dm, dl, q->dw);
    /* S = d t / d w (2 x 2), g = d lambda / d w */
    double S[2][2], g[2];
    for (int c = 0; c < 2; c++) {
      double ds[3];
      for (int i = 0; i < 3; i++)
        ds[i] = Dm[i][0] * J[0][c] + Dm[i][1] * J[1][c] + Dm[i][2] * J[2][c];
      S[0][c] = ds[0] * m->nx + ds[2] * m->ny;
      S[1][c] = ds[2] * m->nx + ds[1] * m->ny;
      g[c] = dl[0] * J[0][c] + dl[1] * J[1][c] + dl[2] * J[2][c];
    }
    /* R_near = ... - A t(w), R_far = ... + A t(w), w = u_far - u_near */
    const size_t k = q->kpair + 16 * (size_t)pi;
    for (int a = 0; a < 4; a++)
      for (int b = 0; b < 4; b++) {
        const double sa = a < 2 ? -1.0 : 1.0, sb = b < 2 ? -1.0 : 1.0;
        const double kab = sa * sb * A * S[a % 2][b % 2];
        const int at = q->map[k + (size_t)(4 * a + b)];
        const int ea = q->eq[2 * (a < 2 ? s0 : s1) + (size_t)(a % 2)];
        const int eb = q->eq[2 * (b < 2 ? s0 : s1) + (size_t)(b % 2)];
        if (at >= 0)
          Ax[at] += kab;
        else if (ea >= 0 && eb == MPM_DOF_GRIP)
          q->kfd[ea] -= kab;
      }
    for (int b = 0; b < 4; b++) { /* the control's gradient */
      const double gd = m->U0 * A * (b < 2 ? -1.0 : 1.0) * g[b % 2];
      const int eb = q->eq[2 * (b < 2 ? s0 : s1) + (size_t)(b % 2)];
      if (eb >= 0)
        q->ga[eb] += gd;
      else if (eb == MPM_DOF_GRIP)
        q->gb -= gd;
    }
  }
  *D = Dl;
  *C = Cl;
}

void mpm_static_iface_commit(mpm_static *q)
{
  mpm_sim *s = q->s;
  int open = 0, on = 0;
  double w = 0.0, d = 0.0;
  for (int pi = 0; pi < q->npair; pi++) {
    q->pst[pi] = q->ptr[pi];
    w += q->pw[pi];
    d += q->imat.U0 * fmin(q->pst[pi].lam, 1.0) * q->pA[pi];
    if (q->pA[pi] > 0.0) {
      on++;
      open += q->pst[pi].sep;
    }
  }
  s->led.W_iface += w;
  s->led.D_static = d;
  if (on > 0 && open == on) /* every pair of the line has separated: the bar is cut */
    s->cut = 1;
}
