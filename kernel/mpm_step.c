/*
 * mpm_step.c - one explicit MPM step, update-stress-last as in the paper
 * (sec. 2, eqs. 2-7), with the boundary conditions and their reactions.
 *
 *   p2g   m_i, (m v)_i, f_i = -sum_p V_p sigma_p . G_ip            eqs. 2, 3
 *   grid  v_i = (m v)_i / m_i,  v^L_i = v_i + dt f_i / m_i; BCs      eq. 4
 *   g2p   x_p += dt sum v^L_i N_ip,  v_p += sum (v^L_i - v_i) N_ip    eqs. 5, 6
 *         de_p = dt sym(sum v^L_i (x) G_ip), then the decohesion update  eq. 7
 *
 * Bilinear shape functions are products of 1-D hats; with r = (x - x_i)/h in [0,1)
 * the weights are (1-r, r) in each direction and the gradients (-1/h, 1/h) times the
 * other direction's weight.  N and G are taken at the start of the step in both passes.
 *
 * Boundary conditions are applied to v^L only.  Applying them to v_i as well (as
 * MODEL.md sec. 2 reads) would make v^L - v_i = 0 at a gripped node, so the FLIP
 * update (eq. 6) could never bring the particles there to the grip's speed.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mpm.h"

/* Nodes with less mass than this fraction of a particle's are treated as empty. */
#define MPM_MASS_EPS 1e-12

static void p2g(mpm_sim *s, int *bad)
{
  mpm_grid *g = s->g;
  const mpm_particles *p = s->p;
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  memset(g->m, 0, nn * sizeof(double));
  memset(g->px, 0, nn * sizeof(double));
  memset(g->py, 0, nn * sizeof(double));
  memset(g->fx, 0, nn * sizeof(double));
  memset(g->fy, 0, nn * sizeof(double));
  const double ih = 1.0 / g->h, ox = g->ox, oy = g->oy;
  const int nnx = g->nnx, ncx = g->ncx, ncy = g->ncy;
  int out = 0;
  for (size_t k = 0; k < p->n; k++) {
    const double fx = (p->x[k] - ox) * ih, fy = (p->y[k] - oy) * ih;
    const int i = (int)fx, j = (int)fy;
    if (!(fx >= 0.0 && fy >= 0.0 && i < ncx && j < ncy)) {
      out = 1;
      continue;
    }
    const double rx = fx - i, ry = fy - j;
    const double wx0 = 1.0 - rx, wx1 = rx, wy0 = 1.0 - ry, wy1 = ry;
    const double mm = p->m[k], mvx = mm * p->vx[k], mvy = mm * p->vy[k];
    const double Vi = p->V[k] * ih;
    const double A = Vi * p->sxx[k], B = Vi * p->sxy[k], C = Vi * p->syy[k];
    const size_t n00 = (size_t)j * nnx + i, n10 = n00 + 1, n01 = n00 + nnx, n11 = n01 + 1;
    const double N00 = wx0 * wy0, N10 = wx1 * wy0, N01 = wx0 * wy1, N11 = wx1 * wy1;
    g->m[n00] += mm * N00;  g->m[n10] += mm * N10;  g->m[n01] += mm * N01;  g->m[n11] += mm * N11;
    g->px[n00] += mvx * N00; g->px[n10] += mvx * N10; g->px[n01] += mvx * N01; g->px[n11] += mvx * N11;
    g->py[n00] += mvy * N00; g->py[n10] += mvy * N10; g->py[n01] += mvy * N01; g->py[n11] += mvy * N11;
    /* f_i = -V sigma . G_i with G_i = (+-wy/h, +-wx/h), eq. 3 */
    g->fx[n00] += A * wy0 + B * wx0;   g->fy[n00] += B * wy0 + C * wx0;
    g->fx[n10] += -A * wy0 + B * wx1;  g->fy[n10] += -B * wy0 + C * wx1;
    g->fx[n01] += A * wy1 - B * wx0;   g->fy[n01] += B * wy1 - C * wx0;
    g->fx[n11] += -A * wy1 - B * wx1;  g->fy[n11] += -B * wy1 - C * wx1;
  }
  *bad = out;
}

/* eq. 4 and the reactions.  After this px, py hold v^L and fx, fy hold v^L - v. */
static void grid_update(mpm_sim *s)
{
  mpm_grid *g = s->g;
  const double dt = s->sc.dt, mmin = MPM_MASS_EPS * s->p->m[0];
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  for (size_t k = 0; k < nn; k++) {
    if (g->m[k] > mmin) {
      const double im = 1.0 / g->m[k];
      const double dvx = dt * g->fx[k] * im, dvy = dt * g->fy[k] * im;
      g->px[k] = g->px[k] * im + dvx;
      g->py[k] = g->py[k] * im + dvy;
      g->fx[k] = dvx;
      g->fy[k] = dvy;
    } else {
      g->px[k] = g->py[k] = g->fx[k] = g->fy[k] = 0.0;
    }
  }
  /* Reaction of a constraint: the force that turns the free v^L into the prescribed one,
   * R = m (v_bc - v^L_free) / dt.  Tension is positive in both loads. */
  const double vg = -s->sc.speed;
  double Rg = 0.0, Rf = 0.0;
  for (int q = 0; q < s->ngrip; q++) {
    const int k = s->grip[q];
    const double jump = vg - g->px[k];
    Rg += g->m[k] * jump;
    g->px[k] = vg;
    g->fx[k] += jump;
  }
  for (int q = 0; q < s->nfixx; q++) {
    const int k = s->fixx[q];
    const double jump = -g->px[k];
    Rf += g->m[k] * jump;
    g->px[k] = 0.0;
    g->fx[k] += jump;
  }
  g->fy[s->fixy] -= g->py[s->fixy];
  g->py[s->fixy] = 0.0;
  s->P_grip = -Rg / dt;
  s->P_fixed = Rf / dt;
  s->W_ext += (Rg / dt) * vg * dt; /* power of the grip's force; the fixed nodes do no work */
}

/* Names the first particle whose state is not finite. */
static void name_nonfinite(const mpm_sim *s, char *err, size_t errlen)
{
  const mpm_particles *p = s->p;
  const char *names[] = {"x", "y", "vx", "vy", "sxx", "syy", "sxy", "lambda"};
  for (size_t k = 0; k < p->n; k++) {
    const double v[] = {p->x[k], p->y[k], p->vx[k], p->vy[k], p->sxx[k], p->syy[k], p->sxy[k], p->lam[k]};
    for (int f = 0; f < 8; f++)
      if (!isfinite(v[f])) {
        snprintf(err, errlen, "step %ld: particle %zu (X = %g, Y = %g): %s is not finite",
                 s->step, k, p->x0[k], p->y0[k], names[f]);
        return;
      }
  }
  snprintf(err, errlen, "step %ld: non-finite value", s->step);
}

static mpm_status g2p(mpm_sim *s, char *err, size_t errlen)
{
  const mpm_grid *g = s->g;
  mpm_particles *p = s->p;
  const double ih = 1.0 / g->h, ox = g->ox, oy = g->oy, dt = s->sc.dt;
  const int nnx = g->nnx;
  double check = 0.0;
  for (size_t k = 0; k < p->n; k++) {
    const double fx = (p->x[k] - ox) * ih, fy = (p->y[k] - oy) * ih;
    const int i = (int)fx, j = (int)fy;
    const double rx = fx - i, ry = fy - j;
    const double wx0 = 1.0 - rx, wx1 = rx, wy0 = 1.0 - ry, wy1 = ry;
    const size_t n00 = (size_t)j * nnx + i, n10 = n00 + 1, n01 = n00 + nnx, n11 = n01 + 1;
    const double N00 = wx0 * wy0, N10 = wx1 * wy0, N01 = wx0 * wy1, N11 = wx1 * wy1;
    const double ux00 = g->px[n00], ux10 = g->px[n10], ux01 = g->px[n01], ux11 = g->px[n11];
    const double uy00 = g->py[n00], uy10 = g->py[n10], uy01 = g->py[n01], uy11 = g->py[n11];
    /* eqs. 5, 6 */
    p->x[k] += dt * (N00 * ux00 + N10 * ux10 + N01 * ux01 + N11 * ux11);
    p->y[k] += dt * (N00 * uy00 + N10 * uy10 + N01 * uy01 + N11 * uy11);
    p->vx[k] += N00 * g->fx[n00] + N10 * g->fx[n10] + N01 * g->fx[n01] + N11 * g->fx[n11];
    p->vy[k] += N00 * g->fy[n00] + N10 * g->fy[n10] + N01 * g->fy[n01] + N11 * g->fy[n11];
    /* eq. 7: velocity gradient from the bilinear field */
    const double dxux = ih * (wy0 * (ux10 - ux00) + wy1 * (ux11 - ux01));
    const double dyuy = ih * (wx0 * (uy01 - uy00) + wx1 * (uy11 - uy10));
    const double dyux = ih * (wx0 * (ux01 - ux00) + wx1 * (ux11 - ux10));
    const double dxuy = ih * (wy0 * (uy10 - uy00) + wy1 * (uy11 - uy01));
    const double de[3] = {dt * dxux, dt * dyuy, 0.5 * dt * (dyux + dxuy)};
    const mpm_material *m = &s->mat[p->mat[k]];
    /* Elastic trial; the full update only where decohesion may act. */
    const double sxx = p->sxx[k] + m->E1 * de[0] + m->E2 * de[1];
    const double syy = p->syy[k] + m->E2 * de[0] + m->E1 * de[1];
    const double sxy = p->sxy[k] + 2.0 * m->G * de[2];
    int full = 0;
    if (m->model != MPM_DCOH_NONE) {
      if (p->lam[k] > 0.0 || p->sep[k]) {
        full = 1;
      } else {
        const double tx = sxx * m->nx + sxy * m->ny, ty = sxy * m->nx + syy * m->ny;
        const double sn = tx * m->nx + ty * m->ny, st = tx * m->tx + ty * m->ty;
        const double a = sn > 0.0 ? sn / m->snf : 0.0, b = st / m->stf;
        full = a * a + b * b > 1.0;
      }
    }
    if (!full) {
      p->sxx[k] = sxx;
      p->syy[k] = syy;
      p->sxy[k] = sxy;
    } else {
      const mpm_dstate in = {p->sxx[k], p->syy[k], p->sxy[k], p->lam[k], p->upn[k], p->upt[k], p->sep[k]};
      mpm_dstate o;
      mpm_dinfo info;
      if (mpm_dcoh_update(m, &in, de, &o, &info, s->dw) != MPM_OK) {
        snprintf(err, errlen, "step %ld: particle %zu (X = %g, Y = %g): decohesion update not finite",
                 s->step, k, p->x0[k], p->y0[k]);
        return MPM_ENOTFINITE;
      }
      p->sxx[k] = o.sxx;
      p->syy[k] = o.syy;
      p->sxy[k] = o.sxy;
      p->lam[k] = o.lam;
      p->upn[k] = o.upn;
      p->upt[k] = o.upt;
      p->sep[k] = (uint8_t)o.sep;
      p->wcoh[k] += info.w * p->V[k] / m->Le;
      s->n_soften += info.path == MPM_DPATH_SOFTEN;
      s->n_separate += info.path == MPM_DPATH_SEPARATE;
      s->n_bracketed += info.bracketed;
    }
    check += p->x[k] + p->y[k] + p->vx[k] + p->vy[k] + p->sxx[k] + p->syy[k] + p->sxy[k];
  }
  if (!isfinite(check)) {
    name_nonfinite(s, err, errlen);
    return MPM_ENOTFINITE;
  }
  return MPM_OK;
}

mpm_status mpm_sim_step(mpm_sim *s, char *err, size_t errlen)
{
  int bad = 0;
  p2g(s, &bad);
  if (bad) {
    const mpm_particles *p = s->p;
    mpm_status st = MPM_EDOMAIN;
    for (size_t k = 0; k < p->n; k++) {
      const double fx = (p->x[k] - s->g->ox) / s->g->h, fy = (p->y[k] - s->g->oy) / s->g->h;
      if (!(fx >= 0.0 && fy >= 0.0 && fx < s->g->ncx && fy < s->g->ncy)) {
        st = isfinite(p->x[k]) && isfinite(p->y[k]) ? MPM_EDOMAIN : MPM_ENOTFINITE;
        snprintf(err, errlen, "step %ld: particle %zu (X = %g, Y = %g) %s at (%g, %g)%s", s->step, k,
                 p->x0[k], p->y0[k], st == MPM_EDOMAIN ? "left the grid" : "has a non-finite position",
                 p->x[k], p->y[k], st == MPM_EDOMAIN ? "; raise grid.pad" : "");
        break;
      }
    }
    return st;
  }
  grid_update(s);
  const mpm_status st = g2p(s, err, errlen);
  if (st != MPM_OK)
    return st;
  s->step++;
  s->t = s->step * s->sc.dt;
  return MPM_OK;
}
