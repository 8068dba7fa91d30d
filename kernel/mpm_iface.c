/*
 * mpm_iface.c - the crack as a cohesive interface between two velocity fields
 * (decohesion.path = interface; docs/findings.md derives and measures it).
 *
 * A band of softening particles on an inclined line dissipates more than U0 per unit
 * area and carries load after it separates (docs/findings.md): the cell staircase makes
 * more material strain with the opening than the line holds.  Here no particle softens.
 * The paper's decohesion law (Model 1 with q = 1, eqs. 8-10) acts on the line itself:
 *  - the two fields (mpm_fields.c) exist from the first step.  Every node within
 *    MPM_IFACE_REACH h (|sin a| + |cos a|) of the line at alpha through the flaw is split,
 *    and a particle's side is fixed by its reference centre (mpm_iface_side; a centre
 *    on the line takes the first side, so at alpha 90 the crack runs along the edge of
 *    the flaw's particle column);
 *  - the line is cut into segments of MPM_IFACE_SEG h.  A node belongs to the segment of
 *    its projection on the line and carries An, the line's length weighted by the node's
 *    uGIMP weight for a particle centred on it, so a segment's nodes share its length;
 *  - STUCK: until a segment's mean traction on the line, from the particles' stresses
 *    through the nodes it weighs (onset()), reaches se = sqrt(<tn>^2 / snf^2 +
 *    tt^2 / stf^2) >= 1 (eq. 8 at lambda = 0), both fields at its nodes take their centre-of-mass velocity (the
 *    impulse J = m1 (vc - v1) on field 1, -J on field 2) and, under MUSL, share v':
 *    the bar is one body there;
 *  - SOFT: the segment's mean stick traction, sum J / (dt A), is held to the failure
 *    surface se <= 1 - lambda (eq. 8, q = 1): every node's impulse is scaled by the same
 *    factor (tension and shear; compression is never capped), and a segment whose mean
 *    traction is inside the surface sticks whole this step.  (Holding each node's own
 *    traction J / (dt An) to the surface released the bar at 1 ppc: the stick traction
 *    scatters from node to node there, every node above the surface was cut at once, and
 *    the load fell from the peak to a quarter within half a wave transit: fig7 h 4,
 *    k_soft -5346 against the analytic -563; docs/findings.md.)
 *    decohesion.share = line instead gives each node the segment's traction times its
 *    length of line An (of the length at the nodes holding both fields), capped at its
 *    stick impulse: with a line along a node column (alpha 90, the grid following the
 *    bar) the scaled stick impulses leave the traction's spread among a segment's rows
 *    free, and a mode grew in it (iface90 h 1, 4 ppc: L_flip 2.5; docs/findings.md).
 *    lambda grows by the traction's work on the opening,
 *    dW per unit area (the impulse times the fields' relative velocity v'2 - v'1,
 *    MUSL's re-projected velocities that the particles' strain takes, summed over the
 *    segment's nodes; mpm_iface_musl): Model 1's power s . d up = U0 se dlambda with
 *    se = 1 - lambda on the surface, integrated in closed form, lambda = 1 - sqrt(1 -
 *    2 W / U0) of the work W taken so far, so a segment that opens to lambda = 1 has
 *    taken UF = U0 / 2 per unit area whatever the mode.
 *    (lambda from an effective opening, sqrt((snf un)^2 + (stf ut)^2) / U0, counts the
 *    slip that Mode I's inclined opening makes ten times over with stf = 10 snf, and
 *    separated fig7 early: h 4, 4 ppc, W_ext 0.75 UF area; docs/findings.md);
 *    (The fields' velocity after the impulse, v^L, instead: that opening rate runs ahead
 *    of the one the particles take, lambda outran the work, and at 1 ppc the softening
 *    was steep and short of UF: fig7 h 2, k_soft -716 against -563 and W_ext -3.2 %.)
 *  - OPEN: at lambda >= the separation threshold, frictionless contact only
 *    (mpm_fields.c), and lambda = 1: no traction is left.  The bar is cut when every
 *    segment is open (s->cut).
 * The flaw: the segment holding the flaw's square (its particle, or its cell with
 * imperfection.size = cell) loses strength in proportion to the share of its length that
 * lies in the square.  A segment with less than a quarter of the segment length of line
 * (the bar's edges) joins its larger neighbour.
 * Energy: the impulse's work on the fields over the step, -m c . (v + v^L) / 2 per record
 * (as the contact's, docs/verification.md), is the cohesive work and goes to W_coh; D is eq. 10
 * on the segments, U0 A min(lambda, 1).
 * Serial, in node and particle order: the same sums whatever the threads.
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
#include "mpm_static.h"

/* quadrature of the line for An and the flaw: points per cell of line */
#define IFACE_QUAD 200

static int seg_of(const mpm_iface *f, double x, double y)
{
  const int b = (int)floor((f->tx * (x - f->lx) + f->ty * (y - f->ly) - f->smin) / f->sw);
  return b < 0 ? 0 : b >= f->nseg ? f->nseg - 1 : b;
}

void mpm_iface_free(mpm_iface *f)
{
  if (!f)
    return;
  free(f->seg);
  free(f->owner);
  free(f->node);
  double *d[] = {f->Ab, f->r, f->An, f->jx, f->jy, f->A, f->snf, f->stf, f->lam, f->sn, f->st, f->sv,
                 f->wn, f->Tn, f->Tt, f->md, f->ns};
  for (size_t i = 0; i < sizeof d / sizeof *d; i++)
    free(d[i]);
  free(f->state);
  free(f->stuck);
  free(f);
}

/* The line's length in each segment that lies in the flaw's square, into lf. */
static void flaw_lengths(const mpm_sim *s, const mpm_iface *f, double s0, double s1, double *lf)
{
  const mpm_scene *sc = &s->sc;
  const double h = sc->h, dx = h / sqrt((double)sc->ppc);
  double x0 = f->lx - 0.5 * dx, x1 = f->lx + 0.5 * dx, y0 = f->ly - 0.5 * dx, y1 = f->ly + 0.5 * dx;
  if (sc->imp_size == MPM_IMP_CELL) {
    x0 = floor(f->lx / h) * h;
    y0 = floor(f->ly / h) * h;
    x1 = x0 + h;
    y1 = y0 + h;
  }
  const int ns = (int)ceil((s1 - s0) / h * IFACE_QUAD);
  const double ds = (s1 - s0) / ns;
  for (int i = 0; i < ns; i++) {
    const double sl = s0 + (i + 0.5) * ds, x = f->lx + sl * f->tx, y = f->ly + sl * f->ty;
    if (x >= x0 && x <= x1 && y >= y0 && y <= y1)
      lf[seg_of(f, x, y)] += ds;
  }
}

/* An: the line integral of each node's uGIMP weight for a particle of the run's size
 * centred on the line from s0 to s1 (midpoint rule). */
static void line_weights(const mpm_sim *s, mpm_iface *f, double s0, double s1)
{
  const mpm_grid *g = s->g;
  const size_t nny = (size_t)g->nny;
  const double h = s->sc.h, lx = f->lx, ly = f->ly, ca = f->tx, sa = f->ty;
  double lcx = 0.0, lcy = 0.0;
  mpm_gimp_lc(s, &lcx, &lcy);
  const int nq = (int)ceil((s1 - s0) / h * IFACE_QUAD);
  const double ds = (s1 - s0) / nq;
  for (int i = 0; i < nq; i++) {
    const double sl = s0 + (i + 0.5) * ds, x = lx + sl * ca, y = ly + sl * sa;
    mpm_gimp1 gx, gy;
    mpm_gimp_1d((x - g->ox) * g->ihx, lcx, &gx);
    mpm_gimp_1d((y - g->oy) * g->ihy, lcy, &gy);
    size_t n[9];
    double w[9];
    mpm_gimp_stencil((size_t)gx.i0 * nny + (size_t)gy.i0, nny, &gx, &gy, n, w);
    for (int q = 0; q < 9; q++)
      f->An[n[q]] += w[q] * ds;
  }
}

/* The split nodes, their list in node order and each node's segment; 0 if out of memory. */
static int split_nodes(const mpm_sim *s, mpm_iface *f)
{
  const mpm_grid *g = s->g;
  mpm_fields *fl = g->fld;
  const size_t nn = (size_t)g->nnx * (size_t)g->nny, nny = (size_t)g->nny;
  const double h = s->sc.h, lx = f->lx, ly = f->ly, ca = f->tx, sa = f->ty;
  /* the split nodes (never a held one: its reaction stays that of one field), and the
   * segment of each node */
  const double reach = MPM_IFACE_REACH * h * (fabs(sa) + fabs(ca));
  for (size_t n = 0; n < nn; n++) {
    const double X = g->ox + (double)(n / nny) * g->hx, Y = g->oy + (double)(n % nny) * g->h;
    fl->split[n] = fabs(f->nx * (X - lx) + f->ny * (Y - ly)) <= reach;
    f->seg[n] = seg_of(f, X, Y);
  }
  for (int q = 0; q < s->nbc; q++)
    fl->split[s->bc[q].node] = 0;
  fl->nsplit = 0;
  for (size_t n = 0; n < nn; n++)
    fl->nsplit += fl->split[n];
  /* the split nodes in node order: fixed for the run, so each step walks this list */
  if (!(f->node = malloc((size_t)(fl->nsplit > 0 ? fl->nsplit : 1) * sizeof(size_t))))
    return 0;
  for (size_t n = 0; n < nn; n++)
    if (fl->split[n]) {
      f->node[f->nnode++] = n;
      f->A[f->seg[n]] += f->An[n];
    }
  return 1;
}

/* Slivers into their neighbours (see below); amin: a quarter of a segment's length. */
static void merge_slivers(const mpm_sim *s, mpm_iface *f, double amin)
{
  const size_t nn = (size_t)s->g->nnx * (size_t)s->g->nny;
  /* a segment with under a quarter of its length of line joins its larger neighbour,
   * if that one is a whole segment (the bar's edges: the line ends inside it); the
   * slivers left, the uGIMP tails beyond the bar, hold no line */
  for (int b = 0; b < f->nseg; b++)
    f->owner[b] = b;
  /* a segment a node (the split beams): no neighbour's share to join; the node behind the
   * crack tip, whose uGIMP weight reaches the bonded line by a particle's half-width,
   * stays on the pre-crack (joined to the tip's, it bonded the crack h shorter) */
  for (int b = 0; !f->stick_onset && b < f->nseg; b++)
    if (f->A[b] > 0.0 && f->A[b] < amin) {
      const int lo = b > 0 ? b - 1 : b + 1, hi = b + 1 < f->nseg ? b + 1 : b - 1;
      const int to = f->A[lo] > f->A[hi] ? lo : hi;
      if (!(f->A[to] >= amin))
        continue;
      for (size_t n = 0; n < nn; n++)
        if (f->seg[n] == b)
          f->seg[n] = to;
      f->A[to] += f->A[b];
      f->A[b] = 0.0;
      f->owner[b] = to;
    }
}

/* Each segment's strengths, the flaw's by its length lf on the line, and its state. */
static void strengths(const mpm_scene *sc, mpm_iface *f, const double *lf, double amin)
{
  for (int b = 0; b < f->nseg; b++) {
    const double share = f->A[b] > 0.0 ? fmin(lf[b] / f->A[b], 1.0) : 0.0;
    f->snf[b] = sc->snf * (1.0 - (1.0 - sc->imp_factor) * share);
    f->stf[b] = sc->stf * (1.0 - (1.0 - sc->imp_stf_factor) * share);
    /* a segment with no line in it (beyond the bar's edges) is open from the start */
    f->state[b] = f->A[b] >= amin ? MPM_SEG_STUCK : MPM_SEG_OPEN;
  }
}

/* A split beam's pre-crack (mpm_specimen.h): the segments whose centre lies on it are
 * open from the start, lambda 0 (they spend nothing: faces in contact only). */
static void precrack(const mpm_sim *s, mpm_iface *f)
{
  const mpm_specimen_type *spec = mpm_specimen_of(&s->sc);
  for (int b = 0; spec->precrack && b < f->nseg; b++) {
    const double sc = f->smin + (b + 0.5) * f->sw;
    if (spec->precrack(&s->sc, f->lx + sc * f->tx, f->ly + sc * f->ty))
      f->state[b] = MPM_SEG_OPEN;
  }
}

mpm_iface *mpm_iface_alloc(mpm_sim *s, double lx, double ly)
{
  const mpm_scene *sc = &s->sc;
  mpm_grid *g = s->g;
  mpm_fields *fl = g->fld;
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  mpm_iface *f = calloc(1, sizeof *f);
  if (!f)
    return NULL;
  const double a = sc->alpha_deg * (3.14159265358979323846 / 180.0), sa = sin(a), ca = cos(a), h = sc->h;
  f->lx = lx;
  f->ly = ly;
  f->on = 1e-9 * h;
  f->share = sc->share;
  f->nx = fl->nx;
  f->ny = fl->ny;
  f->tx = ca;
  f->ty = sa;
  /* the line on the bar: y from 0 to H (mpm_scene_check: sin a > 0 and it stays in x);
   * a split beam's along x, from x = 0 to L (the pre-crack included: its nodes split),
   * one segment a node (centred on it), whose stick traction starts its softening */
  const int along_x = sc->specimen != MPM_SPEC_BAR;
  const double s0 = along_x ? -lx / ca : -ly / sa, s1 = along_x ? (sc->L - lx) / ca : (sc->H - ly) / sa;
  f->s0 = s0;
  f->s1 = s1;
  f->sw = along_x ? h : MPM_IFACE_SEG * h;
  f->smin = along_x ? s0 - 4.5 * h : s0 - 4.0 * h;
  f->stick_onset = along_x;
  f->nseg = (int)ceil((s1 - s0 + 8.0 * h) / f->sw) + 1;
  const size_t ns = (size_t)f->nseg;
  f->seg = malloc(nn * sizeof(int));
  double **nodal[] = {&f->An, &f->jx, &f->jy};
  for (size_t i = 0; i < 3; i++)
    *nodal[i] = calloc(nn, sizeof(double));
  f->md = calloc(4 * nn, sizeof(double));
  f->ns = calloc(3 * nn, sizeof(double));
  double **segs[] = {&f->Ab, &f->r, &f->A, &f->snf, &f->stf, &f->lam, &f->sn, &f->st, &f->sv, &f->wn, &f->Tn, &f->Tt};
  int ok = f->seg && f->An && f->jx && f->jy && f->md && f->ns;
  for (size_t i = 0; i < sizeof segs / sizeof *segs; i++)
    ok &= (*segs[i] = calloc(ns, sizeof(double))) != NULL;
  f->state = calloc(ns, 1);
  f->owner = malloc(ns * sizeof(int));
  f->stuck = calloc(ns, 1);
  double *lf = calloc(ns, sizeof(double));
  if (!ok || !f->state || !f->stuck || !f->owner || !lf) {
    free(lf);
    mpm_iface_free(f);
    return NULL;
  }
  line_weights(s, f, along_x ? fmax(s0, 0.0) : s0, s1); /* a beam's bonded line: from a0 */
  if (!split_nodes(s, f)) {
    free(lf);
    mpm_iface_free(f);
    return NULL;
  }
  /* a segment with under a quarter of its length of line joins its larger neighbour,
   * if that one is a whole segment (the bar's edges: the line ends inside it); the
   * slivers left, the uGIMP tails beyond the bar, hold no line */
  const double amin = 0.25 * f->sw;
  merge_slivers(s, f, amin);
  flaw_lengths(s, f, s0, s1, lf);
  strengths(sc, f, lf, amin);
  free(lf);
  precrack(s, f);
  return f;
}

double mpm_iface_x_at(const mpm_iface *f, double y)
{
  return f->lx + (y - f->ly) * f->tx / f->ty;
}

double mpm_iface_D(const mpm_sim *s)
{
  const mpm_iface *f = s->g->fld->ifc;
  double d = 0.0;
  for (int b = 0; b < f->nseg; b++)
    d += s->sc.U0 * f->A[b] * fmin(f->lam[b], 1.0); /* eq. 10 */
  return d;
}

/* se of a traction (eq. 8's effective stress, compression not counted) */
static double eff(double tn, double tt, double snf, double stf)
{
  const double a = fmax(tn, 0.0) / snf, b = tt / stf;
  return sqrt(a * a + b * b);
}

/* Onset: each stuck segment's mean traction on the line, sum An t_k / A, with t_k the
 * traction sigma . n of the node's volume-weighted mean particle stress (the particles'
 * stress at the end of the last step, with their uGIMP weights): every node the line
 * weighs has particles in its support, whatever the ppc. */
static void onset(mpm_sim *s, mpm_iface *f)
{
  int any = 0;
  for (int b = 0; b < f->nseg; b++) {
    f->sn[b] = f->st[b] = f->sv[b] = 0.0;
    any |= f->state[b] == MPM_SEG_STUCK;
  }
  if (!any)
    return;
  const mpm_grid *g = s->g;
  const mpm_fields *fl = g->fld;
  const mpm_particles *p = s->p;
  const size_t nny = (size_t)g->nny;
  for (int i = 0; i < f->nnode; i++) { /* only split nodes are summed into */
    double *ns = f->ns + 3 * f->node[i];
    ns[0] = ns[1] = ns[2] = 0.0;
  }
  double lcx = 0.0, lcy = 0.0;
  mpm_gimp_lc(s, &lcx, &lcy);
  const double nx = f->nx, ny = f->ny, far = MPM_IFACE_REACH * s->sc.h * (fabs(nx) + fabs(ny)) + 2.0 * s->sc.h;
  for (size_t k = 0; k < p->n; k++) {
    if (p->mat[k] == MPM_MAT_HEAD || p->mat[k] == MPM_MAT_DEBRIS ||
        fabs(nx * (p->x0[k] - f->lx) + ny * (p->y0[k] - f->ly)) > far || !mpm_gimp_inside(g, p->x[k], p->y[k]))
      continue;
    mpm_gimp1 gx, gy;
    mpm_gimp_1d((p->x[k] - g->ox) * g->ihx, lcx, &gx);
    mpm_gimp_1d((p->y[k] - g->oy) * g->ihy, lcy, &gy);
    size_t n[9];
    double w[9];
    mpm_gimp_stencil((size_t)gx.i0 * nny + (size_t)gy.i0, nny, &gx, &gy, n, w);
    const double sx = p->sxx[k] * nx + p->sxy[k] * ny, sy = p->sxy[k] * nx + p->syy[k] * ny; /* sigma . n */
    const double tn = sx * nx + sy * ny, tt = sx * f->tx + sy * f->ty;
    for (int q = 0; q < 9; q++)
      if (fl->split[n[q]] && f->An[n[q]] > 0.0) {
        const double wv = w[q] * p->V[k];
        f->ns[3 * n[q]] += wv * tn;
        f->ns[3 * n[q] + 1] += wv * tt;
        f->ns[3 * n[q] + 2] += wv;
      }
  }
  for (int i = 0; i < f->nnode; i++) {
    const size_t k = f->node[i];
    if (f->ns[3 * k + 2] > 0.0) {
      const int b = f->seg[k];
      f->sn[b] += f->An[k] * f->ns[3 * k] / f->ns[3 * k + 2];
      f->st[b] += f->An[k] * f->ns[3 * k + 1] / f->ns[3 * k + 2];
      f->sv[b] += f->An[k];
    }
  }
  for (int b = 0; b < f->nseg; b++)
    if (f->state[b] == MPM_SEG_STUCK && f->sv[b] > 0.0 &&
        eff(f->sn[b] / f->sv[b], f->st[b] / f->sv[b], f->snf[b], f->stf[b]) >= 1.0)
      f->state[b] = MPM_SEG_SOFT;
}

/* The ledger at one record that the interface's impulse changes by c (a velocity): with
 * v its projected velocity and dv its free increment, as the contact's (mpm_fields.c)
 * with c a vector.  The impulse's work on the record, m c . (v + v + dv + c) / 2, is not
 * booked here: the interface's work is taken at the opening the particles take
 * (mpm_iface_musl), and the ledger's L_scheme holds what the nodal fields did beyond it. */
static void record_ledger(mpm_ledger *L, double m, const double v[2], const double dv[2], const double c[2],
                          double bfac)
{
  const double cv = c[0] * v[0] + c[1] * v[1], cd = c[0] * dv[0] + c[1] * dv[1], cc = c[0] * c[0] + c[1] * c[1];
  L->s_A += m * cv;
  L->s_K += m * (2.0 * cd + cc);
  L->s_B -= bfac * m * cd;
}

/* lambda from the work, and the segments that open.  On the surface se = 1 - lambda,
 * Model 1's power U0 se dlambda = dW integrates in closed form: W = U0 (lambda -
 * lambda^2 / 2) per unit area, so lambda = 1 - sqrt(1 - 2 W / U0) of the work taken so
 * far (steps that took work; the traction's work never lowers lambda), and a step's dW
 * takes (1 - lambda)^2 to (1 - lambda)^2 - 2 dW / U0.  (The explicit
 * update dlambda = dW / (U0 (1 - lambda)) overcounts the work of a large step: a release
 * at the snapback of Mode II took 1.036 UF area by the cut, h 8, 4 ppc.) */
static void advance(mpm_sim *s, mpm_iface *f)
{
  int open = 1;
  for (int b = 0; b < f->nseg; b++) {
    if (f->state[b] == MPM_SEG_SOFT) {
      const double dw = f->wn[b] / f->A[b], r = 1.0 - f->lam[b];
      if (dw > 0.0)
        f->lam[b] = 1.0 - sqrt(fmax(0.0, r * r - 2.0 * dw / s->sc.U0));
      if (f->lam[b] > 0.0 && isfinite(s->zone_end)) /* the process zone's far end */
        s->zone_end = fmax(s->zone_end, f->lx + (f->smin + (b + 1) * f->sw) * f->tx);
      if (f->lam[b] >= s->sc.sep_threshold) { /* open: no traction is left, the surface
                                                * se <= 1 - lambda of lambda = 1 (the band's
                                                * separated particle reaches it by its opening) */
        f->state[b] = MPM_SEG_OPEN;
        f->lam[b] = 1.0;
        /* the crack's front: the farthest end of an opened segment (NAN on the bar) */
        if (isfinite(s->crack_tip))
          s->crack_tip = fmax(s->crack_tip, f->lx + (f->smin + (b + 1) * f->sw) * f->tx);
      }
    }
    open &= f->state[b] == MPM_SEG_OPEN;
  }
  if (open)
    s->cut = 1;
}

/* stick_onset (the split beams): a stuck segment whose stick traction reaches the
 * strength (eq. 23 at lambda 0) softens from this step: the impulse the line carries at a
 * crack tip, where the particles' stresses about a node average the tip's field with the
 * free faces behind it (docs/findings.md, "The DCB explicitly") */
static void stick_onset(mpm_iface *f, double dt)
{
  for (int b = 0; f->stick_onset && b < f->nseg; b++)
    if (f->state[b] == MPM_SEG_STUCK && f->A[b] > 0.0 &&
        eff(f->Tn[b] / (dt * f->A[b]), f->Tt[b] / (dt * f->A[b]), f->snf[b], f->stf[b]) >= 1.0)
      f->state[b] = MPM_SEG_SOFT;
}

void mpm_iface_grid(mpm_sim *s)
{
  const double bfac = s->scheme->bfac;
  mpm_grid *g = s->g;
  mpm_fields *fl = g->fld;
  mpm_iface *f = fl->ifc;
  mpm_ledger *L = &s->led;
  const double dt = s->sc.dt, mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  const double nx = f->nx, ny = f->ny, tx = f->tx, ty = f->ty;
  onset(s, f);
  /* the stick impulses J = m1 (vc - v1), vc the pair's centre-of-mass velocity (p holds
   * v^L after the node update), and their sums per segment */
  for (int b = 0; b < f->nseg; b++)
    f->Tn[b] = f->Tt[b] = f->Ab[b] = 0.0;
  for (int i = 0; i < f->nnode; i++) {
    const size_t k = f->node[i];
    f->jx[k] = f->jy[k] = 0.0;
    if (f->state[f->seg[k]] == MPM_SEG_OPEN)
      continue;
    const mpm_node *a = &g->nd[k], *b = &fl->nd2[k];
    if (!(a->m > mmin) || !(b->m > mmin))
      continue;
    const double mt = a->m + b->m;
    f->jx[k] = a->m * b->m * (b->px - a->px) / mt;
    f->jy[k] = a->m * b->m * (b->py - a->py) / mt;
    f->Tn[f->seg[k]] += f->jx[k] * nx + f->jy[k] * ny;
    f->Tt[f->seg[k]] += f->jx[k] * tx + f->jy[k] * ty;
    f->Ab[f->seg[k]] += f->An[k];
  }
  stick_onset(f, dt);
  /* a softening segment sticks whole this step when its mean traction is inside the
   * surface se <= 1 - lambda */
  for (int b = 0; b < f->nseg; b++) {
    const double se = f->state[b] == MPM_SEG_SOFT
                          ? eff(f->Tn[b] / (dt * f->A[b]), f->Tt[b] / (dt * f->A[b]), f->snf[b], f->stf[b])
                          : 0.0;
    f->stuck[b] = f->state[b] == MPM_SEG_STUCK || (f->state[b] == MPM_SEG_SOFT && se <= 1.0 - f->lam[b]);
    f->r[b] = f->stuck[b] ? 1.0 : (1.0 - f->lam[b]) / se;
  }
  for (int i = 0; i < f->nnode; i++) {
    const size_t k = f->node[i];
    if (f->state[f->seg[k]] == MPM_SEG_OPEN)
      continue;
    mpm_node *a = &g->nd[k], *b = &fl->nd2[k];
    double *md = f->md + 4 * k;
    md[0] = md[1] = md[2] = md[3] = 0.0;
    if (!(a->m > mmin) || !(b->m > mmin))
      continue;
    const int q = f->seg[k];
    double jn = f->jx[k] * nx + f->jy[k] * ny, jt = f->jx[k] * tx + f->jy[k] * ty;
    if (!f->stuck[q] && f->share == MPM_SHARE_LINE) {
      /* SOFT, share = line: the segment's normal traction on the surface times the node's
       * length of line, of the length at nodes holding both fields; never more than sticks
       * the node (between 0 and its stick impulse), compression never capped.  No shear:
       * the line this share is built for (alpha 90 across a bar in tension) carries none
       * in the model, and what the fields' lateral breathing asks of it jumps between the
       * stuck and the capped steps; MUSL keeps what that puts into the bar's waves (with
       * the node's share of the segment's shear: iface90 h 4, 4 ppc at a sixteenth of the
       * grip speed, kinetic energy 4.5e-4 against the steady 4e-6; with none 1.6e-5;
       * docs/findings.md) */
      const double w = f->Ab[q] > 0.0 ? f->r[q] * f->An[k] / f->Ab[q] : 0.0;
      if (jn > 0.0)
        jn = f->Tn[q] > 0.0 ? fmin(jn, w * f->Tn[q]) : 0.0;
      jt = 0.0;
    } else if (!f->stuck[q]) {
      /* SOFT, share = stick: the segment's mean traction held to the surface, every
       * node's impulse scaled alike (tension and shear) */
      if (jn > 0.0)
        jn *= f->r[q];
      jt *= f->r[q];
    }
    const double ex = jn * nx + jt * tx, ey = jn * ny + jt * ty; /* the impulse on field 1 */
    const double ca[2] = {ex / a->m, ey / a->m}, cb[2] = {-ex / b->m, -ey / b->m};
    const double dva[2] = {a->fx, a->fy}, dvb[2] = {b->fx, b->fy};
    const double va[2] = {a->px - a->fx, a->py - a->fy}, vb[2] = {b->px - b->fx, b->py - b->fy};
    record_ledger(L, a->m, va, dva, ca, bfac);
    record_ledger(L, b->m, vb, dvb, cb, bfac);
    /* MUSL's B needs each record's m dv (mpm_iface_musl) */
    md[0] = a->m * dva[0];
    md[1] = a->m * dva[1];
    md[2] = b->m * dvb[0];
    md[3] = b->m * dvb[1];
    double *dc = fl->dc + 4 * k;
    dc[0] = ca[0];
    dc[1] = ca[1];
    dc[2] = cb[0];
    dc[3] = cb[1];
    a->px += ca[0];
    a->py += ca[1];
    a->fx += ca[0];
    a->fy += ca[1];
    b->px += cb[0];
    b->py += cb[1];
    b->fx += cb[0];
    b->fy += cb[1];
  }
}

void mpm_iface_musl(mpm_sim *s)
{
  mpm_grid *g = s->g;
  mpm_fields *fl = g->fld;
  mpm_iface *f = fl->ifc;
  const double mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  /* the traction's work on the opening this step, at the softening segments' nodes: the
   * impulse on field 1 (m1 c1) times the fields' relative velocity v'2 - v'1, the
   * opening rate the particles' strain takes (mpm_fields_musl has just set both v') */
  for (int b = 0; b < f->nseg; b++)
    f->wn[b] = 0.0;
  for (int i = 0; i < f->nnode; i++) {
    const size_t k = f->node[i];
    const int q = f->seg[k];
    if (f->state[q] != MPM_SEG_SOFT || f->stuck[q])
      continue;
    const mpm_node *a = &g->nd[k], *b = &fl->nd2[k];
    if (!(a->m > mmin) || !(b->m > mmin))
      continue;
    const double *dc = fl->dc + 4 * k;
    f->wn[q] += a->m * (dc[0] * (b->fx - a->fx) + dc[1] * (b->fy - a->fy));
  }
  double work = 0.0;
  for (int b = 0; b < f->nseg; b++)
    work += f->wn[b];
  s->led.s_I += work; /* W_coh; what the impulse did to the nodal fields beyond it is the
                       * scheme's (L_scheme, mpm_step.c's ledger_step) */
  advance(s, f);
  double B = 0.0;
  for (int i = 0; i < f->nnode; i++) {
    const size_t k = f->node[i];
    if (!f->stuck[f->seg[k]])
      continue;
    mpm_node *a = &g->nd[k], *b = &fl->nd2[k];
    if (!(a->m > mmin) || !(b->m > mmin))
      continue;
    /* stuck: one body, one v' (fx, fy hold v'); B = -m dv . v' of both records again */
    const double mt = a->m + b->m;
    const double vx = (a->m * a->fx + b->m * b->fx) / mt, vy = (a->m * a->fy + b->m * b->fy) / mt;
    const double *md = f->md + 4 * k;
    B -= md[0] * (vx - a->fx) + md[1] * (vy - a->fy) + md[2] * (vx - b->fx) + md[3] * (vy - b->fy);
    a->fx = b->fx = vx;
    a->fy = b->fy = vy;
  }
  s->led.s_B += B;
}

int mpm_iface_pieces(const mpm_sim *s)
{
  if (s->g && s->g->fld && s->g->fld->ifc)
    return s->g->fld->ifc->nseg;
  return s->qs ? mpm_static_iface_npieces(s->qs) : 0; /* the static solver's line alone */
}

int mpm_iface_piece(const mpm_sim *s, int i, double xy[4], double *lam, int *state)
{
  if (!(s->g && s->g->fld && s->g->fld->ifc))
    return s->qs ? mpm_static_iface_piece(s->qs, i, xy, lam, state) : 0;
  const mpm_iface *f = s->g->fld->ifc;
  const double a = fmax(f->smin + i * f->sw, f->s0), b = fmin(f->smin + (i + 1) * f->sw, f->s1);
  if (!(b > a))
    return 0;
  xy[0] = f->lx + a * f->tx;
  xy[1] = f->ly + a * f->ty;
  xy[2] = f->lx + b * f->tx;
  xy[3] = f->ly + b * f->ty;
  const int o = f->owner[i];
  *lam = f->lam[o];
  *state = f->state[o];
  return 1;
}

/* The interface's split nodes are fixed (mpm_iface_alloc): before each scatter only the
 * second field's records are zeroed. */
static void iface_mark(mpm_sim *s)
{
  const mpm_grid *g = s->g;
  memset(g->fld->nd2, 0, (size_t)g->nnx * (size_t)g->nny * sizeof(mpm_node));
  s->ph->split = g->fld->nsplit != 0;
}

/* The second field's eq. 4 and contact where open (mpm_fields_grid), then the law. */
static void iface_grid(mpm_sim *s)
{
  if (s->g->fld->nsplit == 0)
    return;
  mpm_fields_grid(s);
  mpm_iface_grid(s);
}

static void iface_musl(mpm_sim *s)
{
  if (s->g->fld->nsplit == 0)
    return;
  mpm_fields_musl(s);
  mpm_iface_musl(s);
}

/* decohesion.path = interface: two fields split along the line, which carries the law. */
const mpm_hook mpm_hook_iface = {"interface",
                                 {[MPM_PH_MARK] = iface_mark,
                                  [MPM_PH_START] = mpm_fields_start,
                                  [MPM_PH_GRID] = iface_grid,
                                  [MPM_PH_MUSL] = iface_musl}};
