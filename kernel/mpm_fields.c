/*
 * mpm_fields.c - two velocity fields across a separated band (grid.fields = 2), after
 * CRAMP (Nairn 2003) and DFG (Homel and Herbold 2017), the side taken from the failure
 * plane's normal n.  One field until the band has cut the bar (mpm_sim_cut); then each
 * step:
 *  1. every node a separated particle's support covers is split, its band centre the
 *     N-weighted mean of those particles' positions;
 *  2. a particle with n . (x_p - c_p) > 0 uses the second field (nd2) at its split
 *     nodes (mpm_fields_side), the others the first;
 *  3. the fields at a split node meet only in frictionless contact: when the gap is
 *     closed and they approach along n, both take their centre-of-mass normal velocity;
 *     the impulse's work is booked in L_contact.
 * Constrained nodes are never split.  Before the cut the step is the one-field step, bit
 * for bit (why not split earlier: docs/findings.md).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_kernel.h"
#include "mpm_specimen.h"
#include "mpm_fields.h"
#include "mpm_gimp.h"
#include "mpm_iface.h"
#include "mpm_phase.h"

mpm_fields *mpm_fields_alloc(size_t nn, double nx, double ny)
{
  mpm_fields *f = calloc(1, sizeof *f);
  if (!f)
    return NULL;
  f->nd2 = aligned_alloc(_Alignof(mpm_node), nn * sizeof(mpm_node));
  f->split = calloc(nn, 1);
  f->crk = calloc(2 * nn, sizeof(double));
  f->cw = calloc(nn, sizeof(double));
  f->dc = calloc(4 * nn, sizeof(double));
  if (!f->nd2 || !f->split || !f->crk || !f->cw || !f->dc) {
    mpm_fields_free(f);
    return NULL;
  }
  memset(f->nd2, 0, nn * sizeof(mpm_node));
  f->nx = nx;
  f->ny = ny;
  return f;
}

void mpm_fields_free(mpm_fields *f)
{
  if (!f)
    return;
  free(f->nd2);
  free(f->split);
  free(f->crk);
  free(f->cw);
  free(f->dc);
  mpm_iface_free(f->ifc);
  free(f);
}

/* Step 1: the split nodes and their band centres, from the separated particles.
 * Serial, in particle order: the same sums whatever the threads. */
void mpm_fields_mark(mpm_sim *s)
{
  mpm_fields *f = s->g->fld;
  const mpm_particles *p = s->p;
  const mpm_grid *g = s->g;
  if (!s->cut)
    return; /* a cut band has its separated particles (separation is never undone) */
  const size_t nn = (size_t)g->nnx * (size_t)g->nny, nny = (size_t)g->nny;
  memset(f->split, 0, nn);
  memset(f->crk, 0, 2 * nn * sizeof(double));
  memset(f->cw, 0, nn * sizeof(double));
  memset(f->nd2, 0, nn * sizeof(mpm_node));
  f->nsplit = 0;
  const int gimp = s->sc.shape == MPM_SHAPE_GIMP;
  double lcx = 0.0, lcy = 0.0;
  if (gimp)
    mpm_gimp_lc(s, &lcx, &lcy);
  for (size_t k = 0; k < p->n; k++) {
    if (!p->sep[k])
      continue;
    size_t n[9];
    double w[9];
    int nw;
    if (gimp) {
      if (!mpm_gimp_inside(g, p->x[k], p->y[k]))
        continue; /* outside: the scatter reports it */
      mpm_gimp1 sx, sy;
      mpm_gimp_1d((p->x[k] - g->ox) * g->ihx, lcx, &sx);
      mpm_gimp_1d((p->y[k] - g->oy) * g->ihy, lcy, &sy);
      mpm_gimp_stencil((size_t)sx.i0 * nny + (size_t)sy.i0, nny, &sx, &sy, n, w);
      nw = 9;
    } else {
      mpm_shape sh;
      if (!mpm_shape_at(g, p->x[k], p->y[k], &sh))
        continue;
      mpm_shape_stencil(&sh, nny, n, w);
      nw = 4;
    }
    for (int q = 0; q < nw; q++) {
      if (!(w[q] > 0.0))
        continue;
      f->split[n[q]] = 1;
      f->cw[n[q]] += w[q];
      f->crk[2 * n[q]] += w[q] * p->x[k];
      f->crk[2 * n[q] + 1] += w[q] * p->y[k];
    }
  }
  for (int q = 0; q < s->nbc; q++)
    f->split[s->bc[q].node] = 0;
  for (size_t n = 0; n < nn; n++)
    if (f->split[n]) {
      f->crk[2 * n] /= f->cw[n];
      f->crk[2 * n + 1] /= f->cw[n];
      f->nsplit++;
    }
  s->ph->split = f->nsplit != 0;
}

/* The ledger's change at one record (field 1 or 2 of a split node) when the contact
 * adds c = dr n to its increment: with v its projected velocity and dv its free
 * increment (d = dv + c, v^L = v + dv + c), A = m v . d gains m dr v . n, the sum
 * m |d|^2 gains 2 m dr dv . n + m dr^2, the share bfac of B = -m dv . v^L gains
 * -bfac m dr dv . n.  The contact's loss is the work its impulse m c takes from the
 * record over the step, at the mean of the start and end velocities (the trapezoid, as
 * the stress work is taken): -m c . (v + v^L) / 2.  Both records end with the same normal
 * velocity and m1 c1 = -m2 c2, so the pair's end terms cancel and -m dr (v . n) / 2 of
 * each record is left. */
static void contact_ledger(mpm_ledger *L, double m, double vn, double dvn, double dr, double bfac)
{
  L->s_A += m * dr * vn;
  L->s_K += m * dr * (2.0 * dvn + dr);
  L->s_B -= bfac * m * dr * dvn;
  L->s_C -= 0.5 * m * dr * vn;
}

/* Step 3 and the second field's eq. 4: after mpm_nodes_update has done the first field.
 * bfac: the scheme's share of the strain taken from v^L after it (mpm_phase.h).  The ledger
 * (mpm_step.c, "Energy"): the second field's node terms A, K and B, as grid_nodes sums
 * the first field's, and what the contact changes in both (contact_ledger).  Summed
 * per pair, the contact's loss is mu (w2L - w1L)(w2 - w1) / 2, mu = m1 m2 / (m1 + m2),
 * with wL the normal velocities it equalises and w those at the start of the step:
 * mu (w2 - w1)^2 / 2 in a free impact (a perfectly inelastic, frictionless one), 0 for
 * fields resting against each other however hard the stress presses them, negative
 * only where they were parting at the start and the stress brought them together
 * (mpm_energy.L_contact).  Serial in node order: the same sums whatever the threads. */
void mpm_fields_grid(mpm_sim *s)
{
  mpm_fields *f = s->g->fld;
  const double bfac = s->scheme->bfac;
  if (f->nsplit == 0)
    return;
  mpm_grid *g = s->g;
  mpm_ledger *L = &s->led;
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  const double dt = s->sc.dt, mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp, nx = f->nx, ny = f->ny;
  for (size_t k = 0; k < nn; k++) {
    if (!f->split[k])
      continue;
    double *dc = f->dc + 4 * k;
    dc[0] = dc[1] = dc[2] = dc[3] = 0.0;
    mpm_node *b = &f->nd2[k], *a = &g->nd[k];
    if (b->m > mmin) {
      const double im = 1.0 / b->m;
      const double dvx = dt * b->fx * im, dvy = dt * b->fy * im;
      L->s_A += b->px * dvx + b->py * dvy; /* m v . dv, m v = p */
      b->px = b->px * im + dvx;
      b->py = b->py * im + dvy;
      b->fx = dvx;
      b->fy = dvy;
      /* m |dv|^2 and the share bfac of -m dv . v^L */
      const double mdx = b->m * dvx, mdy = b->m * dvy;
      L->s_K += mdx * dvx + mdy * dvy;
      L->s_B -= bfac * (mdx * b->px + mdy * b->py);
    } else {
      b->px = b->py = b->fx = b->fy = 0.0;
      continue;
    }
    if (!(a->m > mmin))
      continue;
    if (f->ifc && f->ifc->state[f->ifc->seg[k]] != MPM_SEG_OPEN)
      continue; /* still bonded: the interface's law (mpm_iface_grid) */
    const double wa = a->px * nx + a->py * ny, wb = b->px * nx + b->py * ny;
    /* the gap along n: the mean normal displacement of the far field's particles less
     * that of the near field's (lane 7 holds m u_n); contact only when it is closed */
    const double gap = b->pad / b->m - a->pad / a->m;
    if (wb - wa < 0.0 && gap <= 0.0) { /* approaching: contact, the normal velocity of the centre of mass */
      const double wc = (a->m * wa + b->m * wb) / (a->m + b->m), da = wc - wa, db = wc - wb;
      const double dva = a->fx * nx + a->fy * ny, dvb = b->fx * nx + b->fy * ny;
      contact_ledger(L, a->m, wa - dva, dva, da, bfac);
      contact_ledger(L, b->m, wb - dvb, dvb, db, bfac);
      dc[0] = da * nx;
      dc[1] = da * ny;
      dc[2] = db * nx;
      dc[3] = db * ny;
      a->px += da * nx;
      a->py += da * ny;
      a->fx += da * nx;
      a->fy += da * ny;
      b->px += db * nx;
      b->py += db * ny;
      b->fx += db * nx;
      b->fy += db * ny;
    }
  }
}

/* USF and USAVG: the second field's projected velocity v = p / m into (fx, fy), as
 * mpm_nodes_start_velocity does for the first, and the ledger's stress power of that share
 * (frac) of the strain increment, -frac dt f . v, from the forces still in the lanes. */
void mpm_fields_start(mpm_sim *s)
{
  mpm_fields *f = s->g->fld;
  const double frac = s->scheme->start_frac;
  if (f->nsplit == 0)
    return;
  const size_t nn = (size_t)s->g->nnx * (size_t)s->g->nny;
  const double c = frac * s->sc.dt, mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  double B = 0.0;
  for (size_t k = 0; k < nn; k++) {
    if (!f->split[k])
      continue;
    mpm_node *b = &f->nd2[k];
    const double im = b->m > mmin ? 1.0 / b->m : 0.0, vx = b->px * im, vy = b->py * im;
    B -= c * (b->fx * vx + b->fy * vy);
    b->fx = vx;
    b->fy = vy;
  }
  s->led.s_B += B;
}

/* MUSL: the second field's v' = q / m into (fx, fy), as mpm_nodes_musl_velocity does for
 * the first, and the ledger's stress power B = -dt f . v' = -m dv . v' (q = m v') at the
 * split nodes: the second field's, and, where the contact acted, the first field's
 * correction (mpm_nodes_musl_velocity summed -m d . v' with d = dv + c). */
void mpm_fields_musl(mpm_sim *s)
{
  mpm_fields *f = s->g->fld;
  if (f->nsplit == 0)
    return;
  const size_t nn = (size_t)s->g->nnx * (size_t)s->g->nny;
  const double mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  double B = 0.0;
  for (size_t k = 0; k < nn; k++) {
    if (!f->split[k])
      continue;
    const mpm_node *a = &s->g->nd[k];
    mpm_node *b = &f->nd2[k];
    const double *dc = f->dc + 4 * k;
    B += dc[0] * a->qx + dc[1] * a->qy;
    B -= (b->fx - dc[2]) * b->qx + (b->fy - dc[3]) * b->qy;
    const double im = b->m > mmin ? 1.0 / b->m : 0.0;
    b->fx = b->qx * im;
    b->fy = b->qy * im;
  }
  s->led.s_B += B;
}

/* Two fields across the cut band (grid.fields = two, no interface). */
const mpm_hook mpm_hook_fields = {"fields",
                                  {[MPM_PH_MARK] = mpm_fields_mark,
                                   [MPM_PH_START] = mpm_fields_start,
                                   [MPM_PH_GRID] = mpm_fields_grid,
                                   [MPM_PH_MUSL] = mpm_fields_musl}};
