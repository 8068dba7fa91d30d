/*
 * mpm_static_asm.c - the quasi-static solver's discrete equations (total Lagrangian):
 * each bar particle's stencil at its reference place, the unknowns, and at a trial
 * displacement the particles' constitutive state (secs. 3-4, the same update as the
 * explicit step), the nodal force residual f_int = sum_p V_p B_p^T sigma_p (eq. 3) less
 * an external force where one is set (fext: the manufactured solution's body force), its
 * tangent K = sum_p V_p B_p^T C_p B_p with C_p the update's algorithmic tangent, and the
 * dissipation D = sum_p U0 min(lambda_p, 1) V_p / Le (eq. 10), and the control's measure,
 * the same sum without the cap (lambda grows on with the opening once separated, eq. 58),
 * with its gradient.
 *
 * Total Lagrangian: shape functions and gradients are taken once, where the particles
 * were laid (small strain; the paper's displacements stay below a cell until the
 * separation: docs/static.md measures the updated-Lagrangian alternative).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mpm_kernel.h"
#include "mpm_shape.h"
#include "mpm_specimen.h"
#include "mpm_static.h"

/* One particle's stencil: nodes with a weight or a gradient, at reference (x0, y0). */
static int stencil(const mpm_sim *s, double x0, double y0, int *node, double *N, double *Gx, double *Gy)
{
  const mpm_grid *g = s->g;
  const double h = s->sc.h, fx = (x0 - s->grid_ox0) / h, fy = (y0 - g->oy) / h;
  int c = 0;
  if (s->sc.shape == MPM_SHAPE_GIMP) {
    const double lc = 0.5 / sqrt((double)s->sc.ppc);
    mpm_gimp1 gx, gy;
    mpm_gimp_1d(fx, lc, &gx);
    mpm_gimp_1d(fy, lc, &gy);
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        const double n = gx.S[a] * gy.S[b], dx = gx.dS[a] * gy.S[b] / h, dy = gx.S[a] * gy.dS[b] / h;
        /* at the edge of a particle's support uGIMP's weight is rounding (1e-30 at 9 ppc):
         * such a node would be an unknown with no stiffness, so the tangent is singular */
        if (fabs(n) < 1e-14 && fabs(dx) * h < 1e-12 && fabs(dy) * h < 1e-12)
          continue;
        node[c] = (int)mpm_grid_node(g, gx.i0 + a, gy.i0 + b);
        N[c] = n;
        Gx[c] = dx;
        Gy[c] = dy;
        c++;
      }
    return c;
  }
  const int i = (int)floor(fx), j = (int)floor(fy);
  const double rx = fx - i, ry = fy - j, wx[2] = {1.0 - rx, rx}, wy[2] = {1.0 - ry, ry};
  const double dxs[2] = {-1.0 / h, 1.0 / h};
  for (int b = 0; b < 2; b++)
    for (int a = 0; a < 2; a++) {
      node[c] = (int)mpm_grid_node(g, i + a, j + b);
      N[c] = wx[a] * wy[b];
      Gx[c] = dxs[a] * wy[b];
      Gy[c] = wx[a] * dxs[b];
      c++;
    }
  return c;
}

mpm_status mpm_static_setup(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  const mpm_particles *p = s->p;
  size_t np = 0;
  for (size_t k = 0; k < p->n; k++)
    np += p->mat[k] != MPM_MAT_HEAD && p->mat[k] != MPM_MAT_DEBRIS;
  q->np = np;
  q->nn = (size_t)s->g->nnx * (size_t)s->g->nny;
  q->iface = s->sc.model != MPM_DCOH_NONE && s->sc.path == MPM_PATH_IFACE;
  q->nslot = q->iface ? 2 * q->nn : q->nn;
  const size_t M = MPM_ST_MAX;
  q->pid = malloc(np * sizeof *q->pid);
  q->cnt = malloc(np * sizeof *q->cnt);
  q->node = malloc(np * M * sizeof *q->node);
  q->N = malloc(np * M * sizeof(double));
  q->Gx = malloc(np * M * sizeof(double));
  q->Gy = malloc(np * M * sizeof(double));
  q->eq = malloc(2 * q->nslot * sizeof *q->eq);
  q->held = calloc(2 * q->nslot, sizeof(double));
  q->coef = calloc(2 * q->nslot, sizeof(double));
  q->Un = calloc(2 * q->nslot, sizeof(double));
  q->Ut = calloc(2 * q->nslot, sizeof(double));
  q->tst = malloc((np ? np : 1) * sizeof *q->tst);
  double **t[] = {&q->tw};
  int ok = q->pid && q->cnt && q->node && q->N && q->Gx && q->Gy && q->eq && q->held && q->coef && q->Un && q->Ut;
  for (size_t i = 0; ok && i < sizeof t / sizeof t[0]; i++)
    ok = (*t[i] = malloc((np ? np : 1) * sizeof(double))) != NULL;
  ok = ok && q->tst && (q->tpath = malloc(np ? np : 1)) && (q->dw = mpm_dwork_alloc());
  if (!ok) {
    snprintf(err, errlen, "out of memory for the static solver's %zu particles", np);
    return MPM_ENOMEM;
  }
  size_t c = 0;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD || p->mat[k] == MPM_MAT_DEBRIS)
      continue;
    q->pid[c] = k;
    q->cnt[c] = stencil(s, p->x0[k], p->y0[k], q->node + c * M, q->N + c * M, q->Gx + c * M, q->Gy + c * M);
    c++;
  }
  return q->iface ? mpm_static_iface_setup(q, err, errlen) : MPM_OK;
}

/* Numbers the unknowns (active components that are not held) and builds the tangent's
 * pattern; again after a hold is added (the cut). */
/* Room for the tangent's elastic part of a new numbering (elastic_part fills it); 0 when
 * out of memory. */
static int elastic_alloc(mpm_static *q)
{
  free(q->Kel);
  free(q->kfdel);
  q->Kel = malloc(sizeof(double) * (mpm_lin_nnz(q->lin) ? mpm_lin_nnz(q->lin) : 1));
  q->kfdel = malloc(sizeof(double) * (size_t)(q->nfree ? q->nfree : 1));
  q->kel_ok = 0;
  return q->Kel && q->kfdel;
}

mpm_status mpm_static_number(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  const size_t M = MPM_ST_MAX, nn = q->nn, ns = q->nslot;
  for (size_t i = 0; i < 2 * ns; i++)
    q->eq[i] = MPM_DOF_OFF;
  for (size_t c = 0; c < q->np; c++)
    for (int a = 0; a < q->cnt[c]; a++)
      q->eq[2 * (size_t)q->node[c * M + (size_t)a]] = q->eq[2 * (size_t)q->node[c * M + (size_t)a] + 1] = 0;
  /* the specimen's constrained components: a node's both slots, or where the node is
   * split and the condition is one side's, that side's slot */
  for (int i = 0; i < s->nbc; i++) {
    const mpm_bc *b = &s->bc[i];
    for (size_t o = 0; o < ns; o += nn) {
      if (b->side != MPM_BC_ANY && ns > nn && (o == 0) != (b->side == MPM_BC_NEAR))
        continue;
      const size_t k = 2 * (o + (size_t)b->node) + b->comp;
      if (q->eq[k] == MPM_DOF_OFF)
        continue;
      q->eq[k] = b->c < 0.0 ? MPM_DOF_GRIP : b->c > 0.0 ? MPM_DOF_PUSH : MPM_DOF_HELD;
      q->coef[k] = b->c;
      if (b->c != 0.0 && q->cmag != 0.0 && fabs(b->c) != q->cmag) {
        snprintf(err, errlen, "static solver: the specimen drives its components by %g and %g times delta; it must "
                 "drive them all by the same magnitude", q->cmag, fabs(b->c));
        return MPM_EINVAL;
      }
      if (b->c != 0.0)
        q->cmag = fabs(b->c);
      q->drv2 |= b->c > 0.0 || (b->c < 0.0 && b->comp == 1);
    }
  }
  if (q->pinned) {
    /* the cut part's vertical rigid motion, free once the body is cut: held where it is
     * now (no force: the part is unloaded) */
    const int best = mpm_specimen_of(&s->sc)->pin_node(s, q->eq);
    for (size_t o = 0; best >= 0 && o < ns; o += nn)
      if (q->eq[2 * (o + (size_t)best) + 1] != MPM_DOF_OFF) {
        q->eq[2 * (o + (size_t)best) + 1] = MPM_DOF_HELD;
        q->held[2 * (o + (size_t)best) + 1] = q->Un[2 * (o + (size_t)best) + 1];
      }
  }
  /* node by node along the grid's columns, a split node's two slots together: the
   * tangent's bandwidth is then about twice a column of nodes (mpm_static_lin.c) */
  int n = 0;
  for (size_t nd = 0; nd < nn; nd++)
    for (size_t o = 0; o < ns; o += nn)
      for (size_t c = 0; c < 2; c++)
        if (q->eq[2 * (o + nd) + c] == 0)
          q->eq[2 * (o + nd) + c] = n++;
  q->nfree = n;
  /* the pattern: every pair of free components of a particle's stencil */
  size_t nz = q->iface ? mpm_static_iface_nz(q) : 0;
  for (size_t c = 0; c < q->np; c++)
    nz += 4 * (size_t)q->cnt[c] * (size_t)q->cnt[c];
  int *ti = malloc((nz ? nz : 1) * sizeof *ti), *tj = malloc((nz ? nz : 1) * sizeof *tj);
  free(q->map);
  q->map = malloc((nz ? nz : 1) * sizeof *q->map);
  double **v[] = {&q->R, &q->kfd, &q->ga, &q->x1, &q->x2, &q->du, &q->pdir};
  int ok = ti && tj && q->map;
  for (size_t i = 0; ok && i < sizeof v / sizeof v[0]; i++) {
    free(*v[i]);
    ok = (*v[i] = calloc((size_t)(n ? n : 1), sizeof(double))) != NULL;
  }
  size_t k = 0, m = 0;
  for (size_t c = 0; ok && c < q->np; c++) {
    const int cn = q->cnt[c];
    for (int a = 0; a < 2 * cn; a++)
      for (int b = 0; b < 2 * cn; b++, k++) {
        const int ea = q->eq[2 * (size_t)q->node[c * M + (size_t)(a / 2)] + (size_t)(a % 2)];
        const int eb = q->eq[2 * (size_t)q->node[c * M + (size_t)(b / 2)] + (size_t)(b % 2)];
        q->map[k] = -1;
        if (ea >= 0 && eb >= 0) {
          ti[m] = ea;
          tj[m] = eb;
          q->map[k] = (int)m++; /* the triplet's number until the map is filled below */
        }
      }
  }
  if (ok && q->iface)
    k = mpm_static_iface_pattern(q, ti, tj, k, &m);
  int *tmap = ok ? malloc((m ? m : 1) * sizeof *tmap) : NULL;
  mpm_lin_free(q->lin);
  q->lin = tmap ? mpm_lin_alloc(n, m, ti, tj, tmap) : NULL;
  if (q->lin)
    for (size_t i = 0; i < k; i++)
      if (q->map[i] >= 0)
        q->map[i] = tmap[q->map[i]];
  free(ti);
  free(tj);
  free(tmap);
  if (!q->lin || !elastic_alloc(q)) {
    snprintf(err, errlen, "out of memory for the tangent of %d unknowns", n);
    return MPM_ENOMEM;
  }
  q->st.unknowns = n;
  q->st.nnz = mpm_lin_nnz(q->lin);
  q->have_eval = q->have_pred = 0;
  return MPM_OK;
}

/* Particle c's entries of the tangent (V B^T Cp B), of d R / d delta (kfd) and, where
 * it softens (wD > 0), of the control's gradient (ga, gb, from dl = d lambda / d de); k
 * is its first place in the map.  Cp is C for the elastic part every particle adds
 * (Kel), else the update's algorithmic tangent less C. */
static void particle_tangent(mpm_static *q, size_t c, double Cp[3][3], const double dl[3], double wD, size_t k,
                             double *restrict Ax)
{
  const size_t M = MPM_ST_MAX;
  const int cn = q->cnt[c];
  const size_t rs = 2 * (size_t)cn; /* the block's row length */
  const int *restrict nd = q->node + c * M, *restrict eq = q->eq, *restrict map = q->map + k;
  const double *restrict Gx = q->Gx + c * M, *restrict Gy = q->Gy + c * M, V = q->s->p->V[q->pid[c]];
  double *restrict ga = q->ga, *restrict kfd = q->kfd;
  double gb = q->gb;
  for (int b = 0; b < 2 * cn; b++) {
    /* d de / d u_b: (Gx, 0, Gy / 2) for an x component, (0, Gy, Gx / 2) for y */
    const int bn = nd[b / 2], bc = b % 2;
    const double d0 = bc ? 0.0 : Gx[b / 2], d1 = bc ? Gy[b / 2] : 0.0, d2 = 0.5 * (bc ? Gx[b / 2] : Gy[b / 2]);
    const double sx = Cp[0][0] * d0 + Cp[0][1] * d1 + Cp[0][2] * d2;
    const double sy = Cp[1][0] * d0 + Cp[1][1] * d1 + Cp[1][2] * d2;
    const double sxy = Cp[2][0] * d0 + Cp[2][1] * d1 + Cp[2][2] * d2;
    const int eb = eq[2 * bn + bc];
    if (wD > 0.0) {
      const double gd = wD * (dl[0] * d0 + dl[1] * d1 + dl[2] * d2);
      if (eb >= 0)
        ga[eb] += gd;
      else if (eb == MPM_DOF_GRIP)
        gb -= gd; /* u = c delta there, the sum scaled by |c| in eval */
      else if (eb == MPM_DOF_PUSH)
        gb += gd;
    }
    if (eb < 0 && eb != MPM_DOF_GRIP && eb != MPM_DOF_PUSH)
      continue; /* held or off: no entry */
    const int *restrict mb = map + b; /* column b: row 2a at mb[2a rs], row 2a + 1 a row on */
    for (int a = 0; a < cn; a++) {
      const double kx = V * (Gx[a] * sx + Gy[a] * sxy), ky = V * (Gy[a] * sy + Gx[a] * sxy);
      if (eb >= 0) {
        const int kx_at = mb[(size_t)(2 * a) * rs], ky_at = mb[(size_t)(2 * a + 1) * rs];
        if (kx_at >= 0)
          Ax[kx_at] += kx;
        if (ky_at >= 0)
          Ax[ky_at] += ky;
        continue;
      }
      const int ex = eq[2 * nd[a]], ey = eq[2 * nd[a] + 1];
      if (eb == MPM_DOF_GRIP) { /* d R / d delta = c K_{f,driven} */
        if (ex >= 0)
          kfd[ex] -= kx;
        if (ey >= 0)
          kfd[ey] -= ky;
      } else {
        if (ex >= 0)
          kfd[ex] += kx;
        if (ey >= 0)
          kfd[ey] += ky;
      }
    }
  }
  q->gb = gb;
}

/* The load's share of the driven components other than the x ones pulled back (the
 * bar's grip, summed in mpm_static_eval's loop): +-f at each, from the trial stresses.
 * A pass of its own, so that the particle loop keeps the arithmetic it had before. */
static double driven_load(const mpm_static *q)
{
  const size_t M = MPM_ST_MAX;
  double P = 0.0;
  for (size_t c = 0; c < q->np; c++) {
    const int *nd = q->node + c * M;
    const double *Gx = q->Gx + c * M, *Gy = q->Gy + c * M, V = q->s->p->V[q->pid[c]];
    const mpm_dstate *o = &q->tst[c];
    for (int a = 0; a < q->cnt[c]; a++) {
      const int ex = q->eq[2 * nd[a]], ey = q->eq[2 * nd[a] + 1];
      if (ex == MPM_DOF_PUSH)
        P += V * (Gx[a] * o->sxx + Gy[a] * o->sxy);
      if (ey == MPM_DOF_PUSH)
        P += V * (Gy[a] * o->syy + Gx[a] * o->sxy);
      else if (ey == MPM_DOF_GRIP)
        P -= V * (Gy[a] * o->syy + Gx[a] * o->sxy);
    }
  }
  return P;
}

/* The tangent's elastic part, sum_p V_p B_p^T C B_p over every particle, and its d R /
 * d delta: the same for the whole run (total Lagrangian: B_p and V_p fixed), so that
 * each evaluation adds only the particles off the elastic path, (C_p - C). */
static void elastic_part(mpm_static *q)
{
  const mpm_sim *s = q->s;
  memset(q->Kel, 0, sizeof(double) * mpm_lin_nnz(q->lin));
  memset(q->kfd, 0, sizeof(double) * (size_t)q->nfree);
  size_t k = 0;
  const double dl[3] = {0.0, 0.0, 0.0};
  for (size_t c = 0; c < q->np; c++) {
    const mpm_material *m = &s->mat[s->p->mat[q->pid[c]]];
    double C[3][3];
    mpm_dcoh_elastic(m, C);
    particle_tangent(q, c, C, dl, 0.0, k, q->Kel);
    k += 4 * (size_t)q->cnt[c] * (size_t)q->cnt[c];
  }
  memcpy(q->kfdel, q->kfd, sizeof(double) * (size_t)q->nfree);
  q->kel_ok = 1;
}

/* Particle i's dissipation per unit lambda, U0 V / Le (eq. 10; 0 without decohesion). */
static inline double dis_rate(const mpm_sim *s, size_t i)
{
  const mpm_material *m = &s->mat[s->p->mat[i]];
  return m->model != MPM_DCOH_NONE ? m->U0 * s->p->V[i] / m->Le : 0.0;
}

/* Particle c's trial state (tst, tpath, tw) from its strain increment de and, with the
 * tangent, its entries off the elastic part (k its first place in the map).  The elastic
 * trial clear inside eq. 23 (most particles) is the update's own result, without the
 * update (mpm_dcoh_trial_inside); the rest take the full update, and with the tangent
 * its algorithmic tangent from the same run. */
static mpm_status particle_update(mpm_static *q, size_t c, const double de[3], int tangent, size_t k, double *Ax)
{
  const mpm_particles *p = q->s->p;
  const size_t i = q->pid[c];
  const mpm_material *m = &q->s->mat[p->mat[i]];
  mpm_dstate *o = &q->tst[c];
  double t[3];
  mpm_dcoh_trial(m, p->sxx[i], p->syy[i], p->sxy[i], de[0], de[1], de[2], &t[0], &t[1], &t[2]);
  if (mpm_dcoh_trial_inside(m, t, p->str2[i])) {
    *o = (mpm_dstate){t[0], t[1], t[2], p->lam[i], p->upn[i], p->upt[i], p->sep[i]};
    q->tpath[c] = MPM_DPATH_ELASTIC;
    q->tw[c] = 0.0;
    return MPM_OK;
  }
  const mpm_dstate in = {p->sxx[i], p->syy[i], p->sxy[i], p->lam[i], p->upn[i], p->upt[i], p->sep[i]};
  mpm_dinfo info;
  double Cp[3][3], dl[3];
  const mpm_status st =
      tangent ? mpm_dcoh_update_tangent(m, &in, de, o, &info, Cp, dl, q->dw) : mpm_dcoh_update(m, &in, de, o, &info, q->dw);
  q->tpath[c] = (uint8_t)info.path;
  q->tw[c] = info.w * p->V[i] / (info.path == MPM_DPATH_SOFTEN ? m->Le : m->Lopen);
  if (tangent && !(st == MPM_OK && info.path == MPM_DPATH_ELASTIC)) {
    double C[3][3];
    mpm_dcoh_elastic(m, C);
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++)
        Cp[a][b] -= C[a][b];
    const double wD = dis_rate(q->s, i);
    particle_tangent(q, c, Cp, dl, wD > 0.0 && info.path != MPM_DPATH_ELASTIC ? wD : 0.0, k, Ax);
  }
  return st;
}

mpm_status mpm_static_eval(mpm_static *q, int tangent)
{
  const double t0 = mpm_wall();
  mpm_sim *s = q->s;
  mpm_particles *p = s->p;
  const size_t M = MPM_ST_MAX, ns = q->nslot;
  double *Ut = q->Ut, *Ax = tangent ? mpm_lin_values(q->lin) : NULL;
  for (size_t i = 0; i < 2 * ns; i++)
    if (q->eq[i] == MPM_DOF_GRIP || q->eq[i] == MPM_DOF_PUSH)
      Ut[i] = q->coef[i] * q->dt;
    else if (q->eq[i] == MPM_DOF_HELD)
      Ut[i] = q->held[i];
  memset(q->R, 0, sizeof(double) * (size_t)q->nfree);
  if (tangent) {
    if (!q->kel_ok)
      elastic_part(q);
    memcpy(Ax, q->Kel, sizeof(double) * mpm_lin_nnz(q->lin));
    memcpy(q->kfd, q->kfdel, sizeof(double) * (size_t)q->nfree);
    memset(q->ga, 0, sizeof(double) * (size_t)q->nfree);
    q->gb = 0.0;
  }
  double Pg = 0.0, Pf = 0.0, D = 0.0, C = 0.0;
  size_t k = 0; /* position in the map */
  mpm_status bad = MPM_OK;
  for (size_t c = 0; c < q->np; c++) {
    const size_t i = q->pid[c];
    const int cn = q->cnt[c];
    const int *nd = q->node + c * M;
    const double *Gx = q->Gx + c * M, *Gy = q->Gy + c * M;
    double de[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < cn; a++) {
      const double ux = Ut[2 * nd[a]] - q->Un[2 * nd[a]], uy = Ut[2 * nd[a] + 1] - q->Un[2 * nd[a] + 1];
      de[0] += Gx[a] * ux;
      de[1] += Gy[a] * uy;
      de[2] += 0.5 * (Gy[a] * ux + Gx[a] * uy);
    }
    const mpm_status st = particle_update(q, c, de, tangent, k, Ax);
    if (st != MPM_OK && bad == MPM_OK)
      bad = st;
    const mpm_dstate o = q->tst[c];
    if (o.lam != 0.0) { /* eq. 10; lambda = 0 adds +0 to the sums, which leaves them as they are */
      const double wD = dis_rate(s, i);
      D += wD * fmin(o.lam, 1.0);
      C += wD * o.lam;
    }
    const double V = p->V[i];
    for (int a = 0; a < cn; a++) { /* eq. 3: f_a = V B_a^T sigma */
      const double fx = V * (Gx[a] * o.sxx + Gy[a] * o.sxy), fy = V * (Gy[a] * o.syy + Gx[a] * o.sxy);
      const int ex = q->eq[2 * nd[a]], ey = q->eq[2 * nd[a] + 1];
      if (ex >= 0)
        q->R[ex] += fx;
      else if (ex == MPM_DOF_GRIP)
        Pg -= fx;
      else if (ex == MPM_DOF_HELD)
        Pf += fx;
      if (ey >= 0)
        q->R[ey] += fy;
    }
    k += 4 * (size_t)cn * (size_t)cn;
  }
  for (size_t i = 0; q->fext && i < 2 * ns; i++) /* R = f_int - f_ext */
    if (q->eq[i] >= 0)
      q->R[q->eq[i]] -= q->fext[i];
  if (q->iface) { /* the line's law between the split nodes' two slots */
    double Dl = 0.0, Cl = 0.0;
    mpm_static_iface_eval(q, tangent, Ax, &Dl, &Cl);
    D += Dl;
    C += Cl;
  }
  if (q->drv2) /* the driven components other than x pulled back */
    Pg += driven_load(q);
  if (q->cmag != 1.0 && q->cmag != 0.0) { /* the sums of c f: +-f above, times |c| */
    Pg *= q->cmag;
    for (int i = 0; tangent && i < q->nfree; i++)
      q->kfd[i] *= q->cmag;
    if (tangent)
      q->gb *= q->cmag;
  }
  q->Pg = Pg;
  q->Pf = Pf;
  q->Dt = D;
  q->Ct = C;
  q->st.t_eval += mpm_wall() - t0;
  return bad;
}
