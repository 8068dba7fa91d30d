/*
 * mpm_static_iface.c - the quasi-static solver's crack as a cohesive interface
 * (decohesion.path = interface): the line at alpha through the flaw's particle splits the
 * bar's particles into two sides (mpm_iface_side, the explicit interface's rule); a node
 * whose stencil holds particles of both sides gets a second displacement slot for the far
 * side's particles.  The jump w = u_far - u_near along the line is interpolated from the
 * split nodes' two slots with the grid's hats, and the paper's law (secs. 3-4, Model 1 or
 * 2) acts on it at quadrature points along the line, MPM_QS_LINE_PTS per cell crossed, each
 * with its length ds: nodal forces -+ N_I t ds, the traction t from the law.
 *
 * The law is the particle update itself (mpm_dcoh_update, with its algorithmic tangent),
 * driven by the jump instead of a strain: a material whose "strain" e_nn = w . n,
 * e_nt = w . t / 2 meets a stiffness k0 (E1 = G = k0, E2 = -k0: isotropic, as the
 * update's rotation into the n-t frame needs) and Le = 1, so that the
 * decohesion "strain" is the opening itself, d ud = d lambda ubar0 m* (eqs. 19, 24).
 * Before the traction reaches the strength (eq. 23) the tie is elastic with k0 =
 * MPM_QS_TIE E / L per unit area: it adds 1 / MPM_QS_TIE of the bar's own compliance to
 * the curve (the explicit interface sticks rigidly; a rigid tie would need the unknowns
 * merged and split again at the onset).  Stiffer ties make the inclined line's tractions
 * oscillate from point to point (fig8 at 1e6: a point initiates at 19 % of the peak;
 * docs/static.md), as stiff cohesive ties do under line quadrature.  After the onset the traction softens with the
 * opening to zero at lambda 1, where the line separates (eqs. 56-58; compression closes
 * it first and is carried, shear is released).
 *
 * At 90 deg the line lies on a node column and midpoint quadrature integrates the hats
 * exactly, so a uniform state is an exact discrete solution; inclined, the line crosses
 * cells and the particles' forces at the split nodes match the line's only on average.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_kernel.h"
#include "mpm_fields.h"
#include "mpm_iface.h"
#include "mpm_static.h"

#define MPM_QS_TIE 1e3 /* the tie's stiffness before the onset, k0 L / E per unit area */

#define MPM_QS_LINE_PTS 2 /* quadrature points per cell length of line */

void mpm_static_iface_free(mpm_static *q)
{
  free(q->qnode);
  free(q->qN);
  free(q->pA);
  free(q->pst);
  free(q->ptr);
  free(q->pw);
  free(q->split);
}

/* The points along the crack within the bar, their hats' nodes and weights.  The crack
 * is where the sides meet: the line through the flaw's particle, moved along n by half
 * the gap to the nearest far-side particle (the particles on the line join the near
 * side: at 90 deg the crack is the flaw column's far edge, a node column). */
static int line_points(mpm_static *q, const mpm_iface *f)
{
  const mpm_sim *s = q->s;
  const mpm_particles *p = s->p;
  const mpm_grid *g = s->g;
  const double h = s->sc.h;
  double gmin = INFINITY;
  for (size_t c = 0; c < q->np; c++) {
    const size_t k = q->pid[c];
    const double gn = f->nx * (p->x0[k] - f->lx) + f->ny * (p->y0[k] - f->ly);
    if (gn > f->on)
      gmin = fmin(gmin, gn);
  }
  const double off = isfinite(gmin) ? 0.5 * gmin : 0.0;
  const double lx = f->lx + off * f->nx, ly = f->ly + off * f->ny;
  /* from y = 0 to y = H (t_y = sin a > 0), within 0 <= x <= L */
  double s0 = -ly / f->ty, s1 = (s->sc.H - ly) / f->ty;
  for (int e = 0; e < 2 && fabs(f->tx) > 1e-12; e++) {
    const double se = ((e ? s->sc.L : 0.0) - lx) / f->tx;
    if ((f->tx > 0.0) == (e == 0))
      s0 = fmax(s0, se);
    else
      s1 = fmin(s1, se);
  }
  const int n = (int)ceil((s1 - s0) / h * MPM_QS_LINE_PTS - 1e-9);
  const double ds = (s1 - s0) / n;
  q->npair = n;
  q->qnode = malloc(4 * (size_t)n * sizeof *q->qnode);
  q->qN = malloc(4 * (size_t)n * sizeof(double));
  q->pA = malloc((size_t)n * sizeof(double));
  q->pst = calloc((size_t)n, sizeof *q->pst);
  q->ptr = calloc((size_t)n, sizeof *q->ptr);
  q->pw = calloc((size_t)n, sizeof(double));
  if (!q->qnode || !q->qN || !q->pA || !q->pst || !q->ptr || !q->pw)
    return -1;
  for (int i = 0; i < n; i++) {
    const double sl = s0 + (i + 0.5) * ds, x = lx + sl * f->tx, y = ly + sl * f->ty;
    const double fx = (x - s->grid_ox0) / h, fy = (y - g->oy) / h;
    const int ci = (int)floor(fx), cj = (int)floor(fy);
    const double rx = fx - ci, ry = fy - cj;
    for (int b = 0; b < 2; b++)
      for (int a = 0; a < 2; a++) {
        q->qnode[4 * i + 2 * b + a] = (int)mpm_grid_node(g, ci + a, cj + b);
        q->qN[4 * i + 2 * b + a] = (a ? rx : 1.0 - rx) * (b ? ry : 1.0 - ry);
      }
    q->pA[i] = ds;
  }
  return 0;
}

mpm_status mpm_static_iface_setup(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  const mpm_particles *p = s->p;
  const mpm_iface *f = s->g && s->g->fld ? s->g->fld->ifc : NULL;
  const size_t M = MPM_ST_MAX, nn = q->nn;
  q->split = calloc(nn, 1);
  if (!f || !q->split || line_points(q, f) != 0) {
    snprintf(err, errlen, "out of memory for the static interface (or no interface line)");
    return MPM_ENOMEM;
  }
  /* which sides touch each node (bit 0 near, 1 far): both, and the node is split */
  for (size_t c = 0; c < q->np; c++) {
    const size_t k = q->pid[c];
    const int side = mpm_iface_side(f, p->x0[k], p->y0[k]);
    for (int a = 0; a < q->cnt[c]; a++)
      q->split[q->node[c * M + (size_t)a]] |= (uint8_t)(1u << side);
  }
  for (size_t nd = 0; nd < nn; nd++)
    q->split[nd] = q->split[nd] == 3;
  /* the far side's particles use the second slot of a split node */
  for (size_t c = 0; c < q->np; c++) {
    const size_t k = q->pid[c];
    if (!mpm_iface_side(f, p->x0[k], p->y0[k]))
      continue;
    for (int a = 0; a < q->cnt[c]; a++) {
      int *nd = &q->node[c * M + (size_t)a];
      if (q->split[*nd])
        *nd += (int)nn;
    }
  }
  /* the law as a material of the update: the bar's strengths and U0, stiffness k0 */
  mpm_material *m = &q->imat;
  *m = s->mat[MPM_MAT_BAR];
  m->model = s->sc.model;
  /* isotropic (E1 - E2 = 2 G), as the update's n-t frame needs: s_nn = k0 w_n and
   * s_nt = k0 w_t on the jumps (e_tt = 0) */
  m->E1 = m->G = MPM_QS_TIE * s->sc.E / s->sc.L;
  m->E2 = m->E1 - 2.0 * m->G;
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

/* The unknown of component c (0-3: near x, near y, far x, far y) of point node a. */
static int comp_eq(const mpm_static *q, int node, int c)
{
  const size_t sl = c < 2 ? (size_t)node : q->nn + (size_t)node;
  return q->eq[2 * sl + (size_t)(c % 2)];
}

size_t mpm_static_iface_pattern(mpm_static *q, int *ti, int *tj, size_t k, size_t *m)
{
  q->kpair = k;
  for (int pi = 0; pi < q->npair; pi++)
    for (int a = 0; a < 4; a++)
      for (int b = 0; b < 4; b++)
        for (int ca = 0; ca < 4; ca++)
          for (int cb = 0; cb < 4; cb++, k++) {
            const int na = q->qnode[4 * pi + a], nb = q->qnode[4 * pi + b];
            const int ea = q->split[na] ? comp_eq(q, na, ca) : -1, eb = q->split[nb] ? comp_eq(q, nb, cb) : -1;
            q->map[k] = -1;
            if (ea >= 0 && eb >= 0) {
              ti[*m] = ea;
              tj[*m] = eb;
              q->map[k] = (int)(*m)++;
            }
          }
  return k;
}

void mpm_static_iface_eval(mpm_static *q, int tangent, double *Ax, double *D, double *C)
{
  const mpm_material *m = &q->imat;
  const size_t nn = q->nn;
  double Dl = 0.0, Cl = 0.0;
  double J[3][2]; /* d de / d w, columns for wx and wy */
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
    const int *nd = q->qnode + 4 * pi;
    const double *N = q->qN + 4 * pi, ds = q->pA[pi];
    double wx = 0.0, wy = 0.0; /* this increment's jump at the point */
    for (int a = 0; a < 4; a++)
      if (q->split[nd[a]]) {
        const size_t s0 = (size_t)nd[a], s1 = nn + s0;
        wx += N[a] * ((q->Ut[2 * s1] - q->Ut[2 * s0]) - (q->Un[2 * s1] - q->Un[2 * s0]));
        wy += N[a] * ((q->Ut[2 * s1 + 1] - q->Ut[2 * s0 + 1]) - (q->Un[2 * s1 + 1] - q->Un[2 * s0 + 1]));
      }
    double de[3];
    jump_strain(m, wx, wy, de);
    mpm_dinfo info;
    mpm_dcoh_update(m, &q->pst[pi], de, &q->ptr[pi], &info, q->dw);
    const mpm_dstate *o = &q->ptr[pi];
    q->pw[pi] = info.w * ds;
    Dl += m->U0 * fmin(o->lam, 1.0) * ds;
    Cl += m->U0 * o->lam * ds;
    /* the traction sigma . n pulls the near side toward the far one: residual -N t ds on
     * the near slot, +N t ds on the far one */
    const double t[2] = {o->sxx * m->nx + o->sxy * m->ny, o->sxy * m->nx + o->syy * m->ny};
    for (int a = 0; a < 4; a++)
      for (int c = 0; q->split[nd[a]] && c < 4; c++) {
        const int e = comp_eq(q, nd[a], c);
        if (e >= 0)
          q->R[e] += (c < 2 ? -1.0 : 1.0) * N[a] * ds * t[c % 2];
      }
    if (!tangent)
      continue;
    double Dm[3][3], dl[3], S[2][2], g[2];
    mpm_dcoh_tangent(m, &q->pst[pi], de, Dm, dl, q->dw);
    for (int c = 0; c < 2; c++) { /* S = d t / d w, g = d lambda / d w */
      double dsg[3];
      for (int i = 0; i < 3; i++)
        dsg[i] = Dm[i][0] * J[0][c] + Dm[i][1] * J[1][c] + Dm[i][2] * J[2][c];
      S[0][c] = dsg[0] * m->nx + dsg[2] * m->ny;
      S[1][c] = dsg[2] * m->nx + dsg[1] * m->ny;
      g[c] = dl[0] * J[0][c] + dl[1] * J[1][c] + dl[2] * J[2][c];
    }
    const size_t k0 = q->kpair + 256 * (size_t)pi;
    for (int a = 0; a < 4; a++)
      for (int b = 0; b < 4; b++) {
        if (!q->split[nd[a]] || !q->split[nd[b]])
          continue;
        for (int ca = 0; ca < 4; ca++)
          for (int cb = 0; cb < 4; cb++) {
            const double sa = ca < 2 ? -1.0 : 1.0, sb = cb < 2 ? -1.0 : 1.0;
            const double kab = sa * sb * N[a] * N[b] * ds * S[ca % 2][cb % 2];
            const int at = q->map[k0 + (size_t)(64 * a + 16 * b + 4 * ca + cb)];
            const int ea = comp_eq(q, nd[a], ca), eb = comp_eq(q, nd[b], cb);
            if (at >= 0)
              Ax[at] += kab;
            else if (ea >= 0 && eb == MPM_DOF_GRIP)
              q->kfd[ea] -= kab;
          }
      }
    for (int b = 0; b < 4; b++) /* the control's gradient */
      for (int cb = 0; q->split[nd[b]] && cb < 4; cb++) {
        const double gd = m->U0 * ds * (cb < 2 ? -1.0 : 1.0) * N[b] * g[cb % 2];
        const int eb = comp_eq(q, nd[b], cb);
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
  int open = 0;
  double w = 0.0, d = 0.0;
  for (int pi = 0; pi < q->npair; pi++) {
    q->pst[pi] = q->ptr[pi];
    w += q->pw[pi];
    d += q->imat.U0 * fmin(q->pst[pi].lam, 1.0) * q->pA[pi];
    open += q->pst[pi].sep;
  }
  s->led.W_iface += w;
  s->led.D_static = d;
  if (q->npair > 0 && open == q->npair) /* the whole line has separated: the bar is cut */
    s->cut = 1;
}
