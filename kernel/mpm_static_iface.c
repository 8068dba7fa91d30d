/*
 * mpm_static_iface.c - the quasi-static solver's crack as a cohesive interface
 * (decohesion.path = interface): the line at alpha through the flaw's particle splits the
 * bar's particles into two sides (mpm_iface_side); a node whose stencil holds both sides
 * gets a second displacement slot for the far side, and the jump W_I between its slots
 * carries the line's law.  On an inclined line the sides meet in a staircase, so the law
 * acts on segments of a few cells (the specimen's seg_cells; docs/static.md), on their
 * nodes' mean jump weighted by the staircase's share A_I (facet_areas); node I carries
 * A_I t(W_seg) + T_I k0 (W_I - W_seg), a stiff tie on its departure from the mean.
 * The law (mpm_law.h; eqs. 19, 23-24, 56-58): an elastic tie of k0 = MPM_QS_TIE E / L per
 * unit area before the onset; then the traction softens with the opening to zero at
 * lambda 1, returned along the flow at the step's end (mpm_law_return); a segment that
 * separates releases its traction into the opening (mpm_law_separate).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_kernel.h"
#include "mpm_fields.h"
#include "mpm_iface.h"
#include "mpm_law.h"
#include "mpm_specimen.h"
#include "mpm_static.h"

#define MPM_QS_TIE 1e6    /* the tie's stiffness, k0 L / E per unit area                  */

void mpm_static_iface_free(mpm_static *q)
{
  void *f[] = {q->split, q->snode, q->sA, q->sT, q->sseg, q->segstart, q->sorder, q->pA, q->pT, q->pst, q->ptr, q->pw,
               q->kseg, q->segx, q->pD, q->spre};
  for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
    free(f[i]);
}

/* A line along x (the split beams, mpm_spec_beam.c): the y-facing facets between the
 * sides' particle squares, each of length d, into A_I by the nodes' bilinear weights at
 * the facet's midpoint.  Where the line starts open (a pre-crack) its nodes take every
 * facet (their contact's area), and the bonded nodes only the bonded facets, so that
 * the bonded shares sum to the bonded length (the crack tip's node carries the half of
 * its share that lies ahead of the tip). */
static int column_facets(const mpm_static *q, const mpm_iface *f, const signed char *side, int nx, int ny, double d,
                         double *A)
{
  const mpm_sim *s = q->s;
  const mpm_grid *g = s->g;
  const double h = s->sc.h;
  const mpm_specimen_type *spec = mpm_specimen_of(&s->sc);
  double *Ab = calloc(q->nn, sizeof(double));
  if (!Ab || !(fabs(f->ny) > 1e-12)) {
    free(Ab);
    return -1;
  }
  for (int j = 0; j + 1 < ny; j++)
    for (int i = 0; i < nx; i++) {
      const signed char s0 = side[(size_t)j * (size_t)nx + (size_t)i], s1 = side[(size_t)(j + 1) * (size_t)nx + (size_t)i];
      if (s0 < 0 || s1 < 0 || s1 == s0) /* the +y neighbour */
        continue;
      const double w = d * (s0 == 0 ? 1.0 : -1.0) / f->ny, xm = (i + 0.5) * d, ym = (j + 1.0) * d;
      const int open = spec->precrack && spec->precrack(&s->sc, xm, ym);
      const double fx = (xm - s->grid_ox0) / h, fy = (ym - g->oy) / h;
      const int ci = (int)floor(fx), cj = (int)floor(fy);
      const double rx = fx - ci, ry = fy - cj;
      for (int b = 0; b < 2; b++)
        for (int a = 0; a < 2; a++) {
          const size_t nd = mpm_grid_node(g, ci + a, cj + b);
          const double wn = w * (a ? rx : 1.0 - rx) * (b ? ry : 1.0 - ry);
          A[nd] += wn;
          if (!open)
            Ab[nd] += wn;
        }
    }
  for (size_t nd = 0; nd < q->nn; nd++) {
    const double x = s->grid_ox0 + h * (double)(nd / (size_t)g->nny), y = g->oy + h * (double)(nd % (size_t)g->nny);
    if (!(spec->precrack && spec->precrack(&s->sc, x, y)))
      A[nd] = Ab[nd];
  }
  free(Ab);
  return 0;
}

/* The split nodes' shares of the line, A_I = sum over the staircase's x-facing facets (an
 * edge between a near and a far particle's squares side by side, length d) of
 * N_I(facet midpoint) d / |n_x|: the bar's cross-section that crosses the line at node I,
 * over n_x.  The bar is pulled along x, so a uniform stress s_xx crosses the staircase
 * through those facets only, with the force s_xx d each, and the line's traction
 * t = s . n = s_xx n_x e_x on A_I carries exactly that: the uniform state is a discrete
 * solution on every segment (projecting both facet families on n, a segment whose run of
 * the staircase held more x-facing facets than the line's average carried more than its
 * share: tractions 0.85-1.0 along a30's line at the first initiation, the crack opening
 * from one end).  Every row of particles has one x-facing facet, so the shares sum to
 * H / |n_x|, the line's length. */
static int facet_areas(const mpm_static *q, const mpm_iface *f, double *A)
{
  const mpm_sim *s = q->s;
  const mpm_particles *p = s->p;
  const mpm_grid *g = s->g;
  const double h = s->sc.h, d = h / sqrt((double)s->sc.ppc);
  const int nx = (int)lround(s->sc.L / d), ny = (int)lround(s->sc.H / d);
  signed char *side = malloc((size_t)nx * (size_t)ny);
  if (!side)
    return -1;
  const int along_x = !(fabs(f->nx) > 1e-12); /* a line along x crosses no row: columns */
  memset(side, -1, (size_t)nx * (size_t)ny);
  for (size_t c = 0; c < q->np; c++) {
    const size_t k = q->pid[c];
    const int i = (int)floor(p->x0[k] / d), j = (int)floor(p->y0[k] / d);
    if (i >= 0 && i < nx && j >= 0 && j < ny)
      side[(size_t)j * (size_t)nx + (size_t)i] = (signed char)mpm_iface_side(f, p->x0[k], p->y0[k]);
  }
  if (along_x) {
    const int r = column_facets(q, f, side, nx, ny, d, A);
    free(side);
    return r;
  }
  for (int j = 0; j < ny; j++)
    for (int i = 0; i < nx; i++) {
      const signed char s0 = side[(size_t)j * (size_t)nx + (size_t)i];
      if (s0 < 0 || i + 1 >= nx) /* the +x neighbour */
        continue;
      const signed char s1 = side[(size_t)j * (size_t)nx + (size_t)i + 1];
      if (s1 < 0 || s1 == s0)
        continue;
      /* positive where the facet's normal from the near particle to the far one, +-x,
       * goes the way of n */
      const double w = d * (s0 == 0 ? 1.0 : -1.0) / f->nx;
      const double fx = ((i + 1.0) * d - s->grid_ox0) / h, fy = ((j + 0.5) * d - g->oy) / h;
      const int ci = (int)floor(fx), cj = (int)floor(fy);
      const double rx = fx - ci, ry = fy - cj;
      for (int b = 0; b < 2; b++)
        for (int a = 0; a < 2; a++)
          A[mpm_grid_node(g, ci + a, cj + b)] += w * (a ? rx : 1.0 - rx) * (b ? ry : 1.0 - ry);
    }
  free(side);
  /* scaled to the line's length in the bar, the crack's area (D is U0 times it, eq. 10):
   * a guard, as the rows' facets already sum to it where the line crosses y = 0 to H */
  double sum = 0.0;
  for (size_t nd = 0; nd < q->nn; nd++)
    sum += A[nd];
  const double ty = fabs(f->ty) > 1e-12 ? fabs(f->ty) : 1.0;
  double len = s->sc.H / ty; /* y = 0 to H, within x = 0 to L */
  if (fabs(f->tx) > 1e-12)
    len = fmin(len, s->sc.L / fabs(f->tx));
  for (size_t nd = 0; sum > 0.0 && nd < q->nn; nd++)
    A[nd] *= len / sum;
  return 0;
}

/* The split nodes, their shares of the line (facet_areas) and their segments along it
 * (CSR by segment). */
static int segments(mpm_static *q, const mpm_iface *f, const double *An)
{
  const mpm_sim *s = q->s;
  const mpm_grid *g = s->g;
  const size_t nn = q->nn;
  int n = 0;
  for (size_t nd = 0; nd < nn; nd++)
    n += q->split[nd];
  q->snode = malloc((size_t)(n ? n : 1) * sizeof *q->snode);
  q->sA = malloc((size_t)(n ? n : 1) * sizeof(double));
  q->sseg = malloc((size_t)(n ? n : 1) * sizeof *q->sseg);
  q->sorder = malloc((size_t)(n ? n : 1) * sizeof *q->sorder);
  if (!q->snode || !q->sA || !q->sseg || !q->sorder)
    return -1;
  double smin = INFINITY, smax = -INFINITY, *sp = malloc((size_t)(n ? n : 1) * sizeof(double));
  if (!sp)
    return -1;
  for (size_t nd = 0, i = 0; nd < nn; nd++)
    if (q->split[nd]) {
      const double x = s->grid_ox0 + s->sc.h * (double)(nd / (size_t)g->nny);
      const double y = g->oy + s->sc.h * (double)(nd % (size_t)g->nny);
      q->snode[i] = (int)nd;
      q->sA[i] = fmax(An[nd], 0.0);
      sp[i] = f->tx * (x - f->lx) + f->ty * (y - f->ly);
      smin = fmin(smin, sp[i]);
      smax = fmax(smax, sp[i]);
      i++;
    }
  /* the segments span the nodes that share the line; a node off it joins the nearest */
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < n; i++)
    if (q->sA[i] > 0.0) {
      lo = fmin(lo, sp[i]);
      hi = fmax(hi, sp[i]);
    }
  if (isfinite(lo)) {
    smin = lo;
    smax = hi;
  }
  /* equal segments of about the specimen's length in cells (a short remainder at the
   * line's end would carry a few facets' share and initiate first); 0: one per node
   * place along the line (a line along a node row: the nodes' own quadrature) */
  const double cells = mpm_specimen_of(&s->sc)->seg_cells;
  const int bynode = !(cells > 0.0);
  const int nfit = bynode ? (int)lround((smax - smin) / s->sc.h) + 1 : (int)lround((smax - smin) / (cells * s->sc.h));
  q->nseg = n ? (nfit > 1 ? nfit : 1) : 0;
  const double len = bynode ? s->sc.h : q->nseg > 0 && smax > smin ? (smax - smin) / q->nseg : 1.0;
  q->segstart = calloc((size_t)q->nseg + 1, sizeof *q->segstart);
  q->pA = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof(double));
  q->pst = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof *q->pst);
  q->ptr = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof *q->ptr);
  q->pw = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof(double));
  q->kseg = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof *q->kseg);
  if (!q->segstart || !q->pA || !q->pst || !q->ptr || !q->pw || !q->kseg) {
    free(sp);
    return -1;
  }
  for (int i = 0; i < n; i++) {
    const int gi = bynode ? (int)lround((sp[i] - smin) / len) : (int)floor((sp[i] - smin) / len);
    q->sseg[i] = gi < 0 ? 0 : gi >= q->nseg ? q->nseg - 1 : gi;
    q->segstart[q->sseg[i] + 1]++;
    q->pA[q->sseg[i]] += q->sA[i];
  }
  for (int k = 0; k < q->nseg; k++)
    q->segstart[k + 1] += q->segstart[k];
  int *fill = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof *fill);
  if (!fill) {
    free(sp);
    return -1;
  }
  for (int i = 0; i < n; i++)
    q->sorder[q->segstart[q->sseg[i]] + fill[q->sseg[i]]++] = i;
  free(fill);
  free(sp);
  q->npair = q->nseg;
  return 0;
}

/* The ties' weights: a split node off the staircase (A_I 0: uGIMP's reach, the corners
 * beyond the faces) is still tied to its segment's mean, with the weight of half a
 * particle's side; per segment their sum. */
static int ties(mpm_static *q)
{
  const double tfloor = 0.5 * q->s->sc.h / sqrt((double)q->s->sc.ppc);
  int n = q->nseg > 0 ? q->segstart[q->nseg] : 0;
  q->sT = malloc((size_t)(n ? n : 1) * sizeof(double));
  q->pT = calloc((size_t)(q->nseg ? q->nseg : 1), sizeof(double));
  if (!q->sT || !q->pT)
    return -1;
  for (int i = 0; i < n; i++)
    q->sT[i] = fmax(q->sA[i], tfloor);
  for (int g = 0; g < q->nseg; g++)
    for (int a = q->segstart[g]; a < q->segstart[g + 1]; a++)
      q->pT[g] += q->sT[q->sorder[a]];
  return 0;
}

/* Each segment's place along the line (its first node's x), and where the line starts
 * open (a pre-crack), that segment separated from the start with nothing dissipated:
 * its faces carry contact only (eqs. 56-58). */
static int precrack(mpm_static *q)
{
  const mpm_sim *s = q->s;
  const mpm_specimen_type *spec = mpm_specimen_of(&s->sc);
  q->segx = malloc((size_t)(q->nseg ? q->nseg : 1) * sizeof(double));
  q->pD = malloc((size_t)(q->nseg ? q->nseg : 1) * sizeof(double));
  q->spre = calloc((size_t)(q->nseg ? q->nseg : 1), 1);
  if (!q->segx || !q->pD || !q->spre)
    return -1;
  for (int g = 0; g < q->nseg; g++) {
    q->segx[g] = NAN;
    q->pD[g] = q->pA[g];
    if (q->segstart[g + 1] == q->segstart[g])
      continue;
    const size_t nd = (size_t)q->snode[q->sorder[q->segstart[g]]];
    const double x = s->grid_ox0 + s->sc.h * (double)(nd / (size_t)s->g->nny);
    const double y = s->g->oy + s->sc.h * (double)(nd % (size_t)s->g->nny);
    q->segx[g] = x;
    if (spec->precrack && spec->precrack(&s->sc, x, y)) {
      q->spre[g] = 1;
      q->pD[g] = 0.0; /* a pre-crack's lambda grows with its opening, which spends nothing */
      q->pst[g].sep = q->ptr[g].sep = 1;
    }
  }
  return 0;
}

mpm_status mpm_static_iface_setup(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  const mpm_particles *p = s->p;
  /* the line: the specimen's point at alpha, with the explicit interface's side rule */
  const mpm_plane *pl = &s->plane;
  const mpm_iface line = {.lx = s->line_x, .ly = s->line_y, .nx = pl->nx, .ny = pl->ny, .tx = pl->tx, .ty = pl->ty,
                          .on = 1e-9 * s->sc.h};
  const mpm_iface *f = &line;
  const size_t M = MPM_ST_MAX, nn = q->nn;
  q->split = calloc(nn, 1);
  double *An = calloc(nn, sizeof(double));
  int ok = q->split && An && facet_areas(q, f, An) == 0;
  /* which sides touch each node (bit 0 near, 1 far): both, and it is split */
  for (size_t c = 0; ok && c < q->np; c++) {
    const size_t k = q->pid[c];
    const int side = mpm_iface_side(f, p->x0[k], p->y0[k]);
    for (int a = 0; a < q->cnt[c]; a++)
      q->split[q->node[c * M + (size_t)a]] |= (uint8_t)(1u << side);
  }
  for (size_t nd = 0; ok && nd < nn; nd++)
    q->split[nd] = q->split[nd] == 3;
  ok = ok && segments(q, f, An) == 0 && ties(q) == 0 && precrack(q) == 0;
  free(An);
  if (!ok) {
    snprintf(err, errlen, "out of memory for the static interface (or no interface line)");
    return MPM_ENOMEM;
  }
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
  /* the line's parameters for the law (mpm_law.h) and the path's control
   * (mpm_dcoh_F): the frame, the bar's strengths and U0, the tie k0 = E1 = G (s_nn =
   * k0 w_n, s_nt = k0 w_t), an opening Le of 1 (the "strain" is the jump) */
  mpm_material *m = &q->imat;
  *m = s->mat[MPM_MAT_BAR];
  m->model = s->sc.model;
  m->E1 = m->G = MPM_QS_TIE * s->sc.E / s->sc.L;
  m->E2 = m->E1 - 2.0 * m->G;
  m->Le = 1.0;
  m->visc = 0.0;
  m->snf = s->sc.snf * s->sc.imp_factor; /* the line's strength: the flaw's, if any */
  m->stf = s->sc.stf * s->sc.imp_stf_factor;
  mpm_material_derive(m);
  return MPM_OK;
}

/* The unknown of component c (0-3: near x, near y, far x, far y) of node nd. */
static int comp_eq(const mpm_static *q, int nd, int c)
{
  const size_t sl = c < 2 ? (size_t)nd : q->nn + (size_t)nd;
  return q->eq[2 * sl + (size_t)(c % 2)];
}

size_t mpm_static_iface_nz(const mpm_static *q)
{
  size_t nz = 0;
  for (int g = 0; g < q->nseg; g++) {
    const size_t k = (size_t)(q->segstart[g + 1] - q->segstart[g]);
    nz += 16 * k * k;
  }
  return nz;
}

size_t mpm_static_iface_pattern(mpm_static *q, int *ti, int *tj, size_t k, size_t *m)
{
  for (int g = 0; g < q->nseg; g++) {
    q->kseg[g] = k;
    for (int a = q->segstart[g]; a < q->segstart[g + 1]; a++)
      for (int b = q->segstart[g]; b < q->segstart[g + 1]; b++)
        for (int ca = 0; ca < 4; ca++)
          for (int cb = 0; cb < 4; cb++, k++) {
            const int ea = comp_eq(q, q->snode[q->sorder[a]], ca), eb = comp_eq(q, q->snode[q->sorder[b]], cb);
            q->map[k] = -1;
            if (ea >= 0 && eb >= 0) {
              ti[*m] = ea;
              tj[*m] = eb;
              q->map[k] = (int)(*m)++;
            }
          }
  }
  return k;
}

/* node nd's jump: total (now), and this increment's */
static void jump(const mpm_static *q, int nd, double W[2], double w[2])
{
  const size_t s0 = (size_t)nd, s1 = q->nn + s0;
  for (int c = 0; c < 2; c++) {
    W[c] = q->Ut[2 * s1 + (size_t)c] - q->Ut[2 * s0 + (size_t)c];
    w[c] = W[c] - (q->Un[2 * s1 + (size_t)c] - q->Un[2 * s0 + (size_t)c]);
  }
}


/* The law's step on a segment (mpm_law.h), with the flow at the end of the step
 * (mpm_law_return, closest point): the particle update freezes the flow direction m* at
 * its elastic trial (secs. 3-4), first order in the trial's excess over the strength; the
 * tie's stiffness k0 puts a segment's trial k0 |w| thousands of times past it, where the
 * frozen direction is almost the larger component's alone (fig8's normal opening came out
 * 1e-4 of eq. 19's).  A segment separated, or opening past separation in the step, with
 * sep set, takes the law's separation (eqs. 56-58, mpm_law_separate); without, 0 there.
 * Out: the state, the work, the tangent d t / d w (x-y) and d lambda / d w. */
static int seg_step(const mpm_material *m, const mpm_dstate *in, const double w[2], int sep, mpm_dstate *out,
                    double *work, double Sx[2][2], double glx[2])
{
  const double nx = m->nx, ny = m->ny, tx = m->tx, ty = m->ty, k0 = m->E1;
  nt_stress s0;
  s0.nn = in->sxx * nx * nx + 2.0 * in->sxy * nx * ny + in->syy * ny * ny;
  s0.nt = in->sxx * nx * tx + in->sxy * (nx * ty + ny * tx) + in->syy * ny * ty;
  s0.tt = in->sxx * tx * tx + 2.0 * in->sxy * tx * ty + in->syy * ty * ty;
  const double wn = w[0] * nx + w[1] * ny, wt = w[0] * tx + w[1] * ty;
  const double an = s0.nn + k0 * wn, at = s0.nt + k0 * wt; /* the elastic trial, eq. 7 */
  double sn = an, st = at, dl = 0.0, dun = 0.0, dut = 0.0, gl[2] = {0.0, 0.0};
  double dsn[2] = {1.0, 0.0}, dst[2] = {0.0, 1.0};
  int open = in->sep;
  if (!open && mpm_law_se(an > 0.0 ? an / m->snf : 0.0, at / m->stf) > mpm_law_S(in->lam, m->q)) /* eq. 23 */
    open = !mpm_law_return(in->lam, m->q, an, at, m->snf, m->stf, k0 * m->ubar0 * m->s0, &dl, &sn, &st, dsn, dst, gl);
  if (open && !sep)
    return 0;
  if (open) { /* eqs. 56-58 */
    double de_nn;
    const int contact = mpm_law_separate(an, at, k0, m->G, m->Lopen, in->upn, &de_nn, &dun, &dut);
    sn = an - k0 * de_nn;
    st = 0.0;
    dsn[0] = contact;
    dst[1] = 0.0;
    mpm_law_separate_dlam(dun, dut, contact, k0, m->G, m->Lopen, m->ubar0, &gl[0], &gl[1]);
    dl = mpm_law_open_dlam(dun, dut, m->ubar0);
  } else {
    dun = (an - sn) / k0; /* t = t_tr - k0 d ud */
    dut = (at - st) / k0;
  }
  const nt_stress s1 = {sn, s0.tt + m->E2 * (wn - dun), st}; /* s_tt: the frame's, unused by the law */
  *out = *in;
  out->sep = open;
  out->lam = in->lam + dl;
  out->upn = in->upn + dun;
  out->upt = in->upt + dut;
  out->sxx = s1.nn * nx * nx + s1.tt * tx * tx + 2.0 * s1.nt * nx * tx;
  out->syy = s1.nn * ny * ny + s1.tt * ty * ty + 2.0 * s1.nt * ny * ty;
  out->sxy = s1.nn * nx * ny + s1.tt * tx * ty + s1.nt * (nx * ty + ny * tx);
  *work = 0.5 * ((s0.nn + sn) * dun + (s0.nt + st) * dut);
  /* x-y: t = sn n + st t, (an, at) = (s0.nn, s0.nt) + k0 (w . n, w . t) */
  const double dnw[2] = {k0 * nx, k0 * ny}, dtw[2] = {k0 * tx, k0 * ty};
  for (int c = 0; c < 2; c++) {
    const double dsnw = dsn[0] * dnw[c] + dsn[1] * dtw[c], dstw = dst[0] * dnw[c] + dst[1] * dtw[c];
    Sx[0][c] = dsnw * nx + dstw * tx;
    Sx[1][c] = dsnw * ny + dstw * ty;
    glx[c] = gl[0] * dnw[c] + gl[1] * dtw[c];
  }
  return 1;
}

/* Elastic and softening steps (seg_step); 0 where the segment is separated or separates
 * in the step. */
int mpm_static_seg_law(const mpm_material *m, const mpm_dstate *in, const double w[2], mpm_dstate *out, double *work,
                       double Sx[2][2], double glx[2])
{
  return seg_step(m, in, w, 0, out, work, Sx, glx);
}

/* One segment's law and its nodes' forces; with the tangent, its entries. */
static void segment_eval(mpm_static *q, int g, int tangent, double *Ax)
{
  const mpm_material *m = &q->imat;
  const double Ag = q->pA[g], Tg = q->pT[g], k0 = m->E1;
  const int a0 = q->segstart[g], a1 = q->segstart[g + 1];
  if (!(Ag > 0.0))
    return;
  /* the segment's jump: the A-weighted mean the law takes, and the T-weighted mean the
   * ties pull toward, so that the ties' forces sum to zero over the segment (tied to the
   * A-weighted mean, the nodes off the staircase, T_I > A_I, would put a net force on it
   * that the law does not carry) */
  double Ws[2] = {0.0, 0.0}, ws[2] = {0.0, 0.0}, Wt[2] = {0.0, 0.0};
  for (int a = a0; a < a1; a++) {
    const int i = q->sorder[a];
    const double Ti = q->sT[i];
    double W[2], w[2];
    jump(q, q->snode[i], W, w);
    for (int c = 0; c < 2; c++) {
      Ws[c] += q->sA[i] / Ag * W[c];
      ws[c] += q->sA[i] / Ag * w[c];
      Wt[c] += Ti / Tg * W[c];
    }
  }
  double S[2][2], gl[2], wk = 0.0;
  seg_step(m, &q->pst[g], ws, 1, &q->ptr[g], &wk, S, gl);
  const mpm_dstate *o = &q->ptr[g];
  q->pw[g] = wk * Ag;
  /* node I: A_I (t + k0 (W_I - W_seg)): the law on the segment's mean, a tie on the rest */
  const double t[2] = {o->sxx * m->nx + o->sxy * m->ny, o->sxy * m->nx + o->syy * m->ny};
  for (int a = a0; a < a1; a++) {
    const int i = q->sorder[a], nd = q->snode[i];
    double W[2], w[2];
    jump(q, nd, W, w);
    for (int c = 0; c < 4; c++) {
      const int e = comp_eq(q, nd, c);
      if (e >= 0)
        q->R[e] += (c < 2 ? -1.0 : 1.0) * (q->sA[i] * t[c % 2] + q->sT[i] * k0 * (W[c % 2] - Wt[c % 2]));
    }
  }
  if (!tangent)
    return;
  size_t k = q->kseg[g];
  for (int a = a0; a < a1; a++)
    for (int b = a0; b < a1; b++) {
      const int ia = q->sorder[a], ib = q->sorder[b];
      const double Ai = q->sA[ia], Ti = q->sT[ia], r = q->sA[ib] / Ag, rt = q->sT[ib] / Tg;
      for (int ca = 0; ca < 4; ca++)
        for (int cb = 0; cb < 4; cb++, k++) {
          /* d f_I / d W_J = A_I S A_J / A_g + T_I k0 (delta_IJ - T_J / T_g) */
          const double bij = Ai * S[ca % 2][cb % 2] * r + ((ca % 2) == (cb % 2) ? Ti * k0 * ((a == b) - rt) : 0.0);
          const double kab = (ca < 2 ? -1.0 : 1.0) * (cb < 2 ? -1.0 : 1.0) * bij;
          const int at = q->map[k];
          const int ea = comp_eq(q, q->snode[ia], ca), eb = comp_eq(q, q->snode[ib], cb);
          if (at >= 0)
            Ax[at] += kab;
          else if (ea >= 0 && eb == MPM_DOF_GRIP)
            q->kfd[ea] -= kab;
          else if (ea >= 0 && eb == MPM_DOF_PUSH)
            q->kfd[ea] += kab;
        }
    }
  /* the control's gradient, d C / d W_J = U0 A_J gl; none once the segment has spent U0
   * (C counts min(lambda, 1): after separation lambda grows with |d ud| whichever way the
   * jump goes, closing included, so an uncapped C could grow along spurious directions) */
  const int capped = o->sep || o->lam >= 1.0;
  for (int b = a0; b < a1 && !capped; b++) {
    const int ib = q->sorder[b];
    for (int cb = 0; cb < 4; cb++) {
      const double gd = m->U0 * q->sA[ib] * (cb < 2 ? -1.0 : 1.0) * gl[cb % 2];
      const int eb = comp_eq(q, q->snode[ib], cb);
      if (eb >= 0)
        q->ga[eb] += gd;
      else if (eb == MPM_DOF_GRIP)
        q->gb -= gd;
      else if (eb == MPM_DOF_PUSH)
        q->gb += gd;
    }
  }
}

/* U0 times the line's area opened so far: each segment's min(lambda, 1) (eq. 10; past
 * separation lambda grows with the jump, which spends nothing more) over states st. */
static double line_dissipation(const mpm_static *q, const mpm_dstate *st)
{
  double d = 0.0;
  for (int g = 0; g < q->nseg; g++)
    d += q->imat.U0 * fmin(st[g].lam, 1.0) * q->pD[g];
  return d;
}

void mpm_static_iface_eval(mpm_static *q, int tangent, double *Ax, double *D, double *C)
{
  for (int g = 0; g < q->nseg; g++)
    segment_eval(q, g, tangent, Ax);
  *D = *C = line_dissipation(q, q->ptr); /* the control counts what D does */
}

void mpm_static_iface_commit(mpm_static *q)
{
  mpm_sim *s = q->s;
  int open = 0, on = 0;
  double w = 0.0;
  double tip = s->crack_tip, zone = s->zone_end;
  for (int g = 0; g < q->nseg; g++) {
    q->pst[g] = q->ptr[g];
    w += q->pw[g];
    on += q->pA[g] > 0.0;
    open += q->pA[g] > 0.0 && q->pst[g].sep;
    if (q->pst[g].sep && !q->spre[g] && q->pA[g] > 0.0 && q->segx[g] > tip) /* the crack's front */
      tip = q->segx[g];
    if (q->pst[g].lam > 0.0 && !q->spre[g] && q->pA[g] > 0.0 && q->segx[g] > zone) /* the zone's far end */
      zone = q->segx[g];
  }
  s->crack_tip = tip;
  s->zone_end = fmax(zone, tip);
  /* the least normal opening at a node of the line (contact keeps it near 0 from below) */
  for (int a = 0; a < (q->nseg > 0 ? q->segstart[q->nseg] : 0); a++) {
    const int i = q->sorder[a];
    double W[2], dw[2];
    jump(q, q->snode[i], W, dw);
    if (q->sA[i] > 0.0)
      s->gap_min = fmin(s->gap_min, W[0] * q->imat.nx + W[1] * q->imat.ny);
  }
  s->led.W_iface += w;
  s->led.D_static = line_dissipation(q, q->pst);
  if (on > 0 && open == on) /* every segment of the line has separated: the bar is cut */
    s->cut = 1;
}

/* Below MPM_QS_SEP of the peak, where no increment is found: each segment not yet
 * separated lets go in place, its traction turned into opening by the law's separation
 * with no jump increment (eqs. 56-58: ud += t / k0) and its lambda set to 1, so that D is
 * U0 times the crack's area; the work its remaining traction would have done (at most that share of U0 for
 * the segment) is not booked.  The number of segments that let go; the bar is cut if
 * any did. */
int mpm_static_iface_sever(mpm_static *q)
{
  const mpm_material *m = &q->imat;
  int n = 0;
  for (int g = 0; g < q->nseg; g++) {
    mpm_dstate *o = &q->pst[g];
    if (o->sep || !(q->pA[g] > 0.0))
      continue;
    nt_stress t = mpm_to_nt(m, o->sxx, o->syy, o->sxy);
    double de_nn, dun, dut;
    mpm_law_separate(t.nn, t.nt, m->E1, m->G, m->Lopen, o->upn, &de_nn, &dun, &dut);
    o->upn += dun;
    o->upt += dut;
    t.nn -= m->E1 * de_nn;
    t.tt -= m->E2 * de_nn;
    t.nt = 0.0;
    mpm_from_nt(m, t, o);
    o->lam = fmax(o->lam, 1.0);
    o->sep = 1;
    n++;
  }
  if (n == 0)
    return 0;
  memcpy(q->ptr, q->pst, sizeof *q->ptr * (size_t)q->nseg); /* not the failed increment's trial */
  q->s->led.D_static = line_dissipation(q, q->pst);
  q->s->cut = 1;
  return n;
}

int mpm_static_iface_npieces(const mpm_static *q)
{
  return q->iface && !(fabs(q->imat.nx) > 1e-12) ? q->nseg : 0;
}

int mpm_static_iface_piece(const mpm_static *q, int i, double xy[4], double *lam, int *state)
{
  const mpm_sim *s = q->s;
  if (i < 0 || i >= mpm_static_iface_npieces(q) || isnan(q->segx[i]) || !(q->pA[i] > 0.0))
    return 0;
  const double h = s->sc.h, x = q->segx[i];
  xy[0] = fmax(x - 0.5 * h, 0.0);
  xy[2] = fmin(x + 0.5 * h, s->sc.L);
  xy[1] = xy[3] = s->line_y;
  *lam = q->spre[i] ? 0.0 : q->pst[i].lam;
  *state = q->spre[i] || q->pst[i].sep ? 2 : q->pst[i].lam > 0.0 ? 1 : 0;
  return 1;
}
