/*
 * mpm_damping.c - damping of the nodal velocities about their slow drift (time.damping
 * = c > 0), for scenes that ask a quasi-static question through a dynamic release (a
 * snapback, eq. 35); c = 0 is the paper's undamped step, bit for bit.
 *
 * DRIFT (time.damping_about, the default): each free velocity component of each node
 * gets after the node update (eq. 4) delta = -c dt (v - vbar), vbar the node's low-pass
 * of v (time constant time.damping_tau): Rayleigh damping about the drift, not about rest.
 * PARTS: once the band has cut the bar, each bar particle's velocity relaxes instead
 * toward its held end's motion, v <- v - c dt (v - V_end) (mpm_damping_parts).
 * time.damping_from = start or cut: from the first step, or from the cut on.
 * Held components are not damped; the kinetic energy taken is booked in L_damp (the
 * ledger's terms: damp_record).  Serial, in node and particle order.  What the other
 * forms gave: docs/findings.md, "Snapback and the release after the cut".
 */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_fields.h"
#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_specimen.h"
#include "mpm_phase.h"
#include "mpm_node.h"
#include "mpm_iface.h"

struct mpm_damping {
  double alpha;   /* c dt (time.damping times dt): the share of v - vbar taken out a step */
  double w;       /* dt / tau: the low-pass's weight per step                       */
  double *vbar;   /* the first field's low-pass velocity per node (x, y pairs)       */
  double *vbar2;  /* the second field's (mpm_fields.c), kept where a node is split   */
  double *del;    /* this step's delta per node, first field (x, y pairs)            */
  double *del2;   /* ... second field                                                */
  uint8_t *held;  /* bit 0: x held, bit 1: y held                                     */
  double *rowmid, *rowhi; /* PARTS: per particle row, the midpoint between the reference
                              x0 of its first and last separated particle at the cut,
                              which divides the row between the parts (set once:
                              rows_set; rowhi is the last's x0 while it is built)     */
  int rows_set;
  size_t nn;
  int on;         /* 1 if this step's delta may be nonzero (time.damping_from)      */
};

mpm_damping *mpm_damping_alloc(const mpm_sim *s)
{
  const mpm_scene *sc = &s->sc;
  const size_t nn = (size_t)s->g->nnx * (size_t)s->g->nny;
  mpm_damping *d = calloc(1, sizeof *d);
  if (!d)
    return NULL;
  d->nn = nn;
  d->vbar = calloc(2 * nn, sizeof(double));
  d->vbar2 = calloc(2 * nn, sizeof(double));
  d->del = calloc(2 * nn, sizeof(double));
  d->del2 = calloc(2 * nn, sizeof(double));
  d->held = calloc(nn, 1);
  d->rowmid = malloc((size_t)(s->nrow > 0 ? s->nrow : 1) * sizeof(double));
  d->rowhi = malloc((size_t)(s->nrow > 0 ? s->nrow : 1) * sizeof(double));
  if (!d->vbar || !d->vbar2 || !d->del || !d->del2 || !d->held || !d->rowmid || !d->rowhi) {
    mpm_damping_free(d);
    return NULL;
  }
  d->alpha = sc->damping * sc->dt;
  const double c = sqrt(s->mat[MPM_MAT_BAR].E1 / sc->rho);
  const double tau = sc->damping_tau > 0.0 ? sc->damping_tau : 2.0 * sc->L / c;
  d->w = fmin(1.0, sc->dt / tau);
  /* the low-pass starts from the loading's own steady field, the one the particles start
   * with (mpm_scene_start_vx) */
  const mpm_grid *g = s->g;
  for (int i = 0; i < g->nnx; i++) {
    const double vx = mpm_scene_start_vx(sc, g->ox + i * g->hx);
    for (int j = 0; j < g->nny; j++)
      d->vbar[2 * mpm_grid_node(g, i, j)] = d->vbar2[2 * mpm_grid_node(g, i, j)] = vx;
  }
  for (int q = 0; q < s->nbc; q++)
    d->held[s->bc[q].node] |= (uint8_t)(1u << s->bc[q].comp);
  return d;
}

void mpm_damping_free(mpm_damping *d)
{
  if (!d)
    return;
  free(d->vbar);
  free(d->vbar2);
  free(d->del);
  free(d->del2);
  free(d->held);
  free(d->rowmid);
  free(d->rowhi);
  free(d);
}

/* The sums one damped record adds to the ledger. */
typedef struct {
  double A, K, B, W;
} damp_sums;

/* One velocity component: lanes p (v^L) and f (d), the contact's part c of d (0 if
 * none), its low-pass vb; returns delta and books its ledger terms: with delta added to
 * d and to v^L, A = sum m v . d gains m v delta, K = sum m d^2 gains m (2 d + delta)
 * delta, bfac's share of B = -dt f . v^L gains -bfac m dv delta (dv = d less the
 * contact's part), and the damper's work L_damp = -m delta (v^L + delta). */
static inline double damp_component(double *lp, double *lf, double c, double *vb, double alpha, double w,
                                    double m, double bfac, damp_sums *t)
{
  const double d = *lf, v = *lp - d;
  *vb += w * (v - *vb);
  if (alpha == 0.0)
    return 0.0; /* not yet on (time.damping_from = cut): the low-pass runs all the same */
  const double del = -alpha * (v - *vb); /* alpha = c dt < 1 (mpm_scene_check) */
  if (del == 0.0)
    return 0.0;
  t->A += m * v * del;
  t->K += m * (2.0 * d + del) * del;
  t->B -= bfac * m * (d - c) * del;
  *lp += del;
  *lf += del;
  t->W -= m * del * *lp;
  return del;
}

static void damp_record(mpm_node *n, const double c[2], double *vb, double *del, uint8_t held, double alpha,
                        double w, double bfac, damp_sums *t)
{
  del[0] = del[1] = 0.0;
  if (!(held & 1))
    del[0] = damp_component(&n->px, &n->fx, c[0], &vb[0], alpha, w, n->m, bfac, t);
  if (!(held & 2))
    del[1] = damp_component(&n->py, &n->fy, c[1], &vb[1], alpha, w, n->m, bfac, t);
}

/* After mpm_nodes_update and mpm_fields_grid: delta on every free component of both
 * fields; bfac as theirs. */
void mpm_damping_apply(mpm_sim *s)
{
  const double bfac = s->scheme->bfac;
  mpm_damping *d = s->damp;
  const mpm_grid *g = s->g;
  const mpm_fields *f = g->fld;
  const double mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  const int off = (s->sc.damping_from == MPM_DAMP_CUT && !s->cut) || (s->sc.damping_about == MPM_DAMP_PARTS && s->cut);
  const double alpha = off ? 0.0 : d->alpha;
  d->on = alpha != 0.0;
  damp_sums t = {0.0, 0.0, 0.0, 0.0};
  for (size_t k = 0; k < d->nn; k++) {
    mpm_node *n = &g->nd[k];
    const int split = f && f->nsplit && f->split[k];
    double ca[2] = {0.0, 0.0}, cb[2] = {0.0, 0.0};
    if (split) { /* the contact's (or interface's) velocity change is in d too (mpm_fields_grid) */
      ca[0] = f->dc[4 * k];
      ca[1] = f->dc[4 * k + 1];
      cb[0] = f->dc[4 * k + 2];
      cb[1] = f->dc[4 * k + 3];
    }
    if (n->m > mmin)
      damp_record(n, ca, &d->vbar[2 * k], &d->del[2 * k], d->held[k], alpha, d->w, bfac, &t);
    else
      d->del[2 * k] = d->del[2 * k + 1] = 0.0;
    d->del2[2 * k] = d->del2[2 * k + 1] = 0.0;
    if (split && f->nd2[k].m > mmin) /* split nodes are never held (mpm_fields.c) */
      damp_record(&f->nd2[k], cb, &d->vbar2[2 * k], &d->del2[2 * k], 0, alpha, d->w, bfac, &t);
  }
  mpm_ledger *L = &s->led;
  L->s_A += t.A;
  L->s_K += t.K;
  L->s_B += t.B;
  L->s_Dmp += t.W;
}

/* MUSL, after mpm_nodes_musl_velocity and mpm_fields_musl (lanes q still hold
 * q = m v'): their B = -m d . v' took delta in d; the stress power is -m dv . v'. */
void mpm_damping_musl(mpm_sim *s)
{
  const mpm_damping *d = s->damp;
  if (!d->on)
    return; /* every delta of this step is 0 */
  const mpm_grid *g = s->g;
  const mpm_fields *f = g->fld;
  double B = 0.0;
  for (size_t k = 0; k < d->nn; k++) {
    const mpm_node *n = &g->nd[k];
    B += d->del[2 * k] * n->qx + d->del[2 * k + 1] * n->qy;
    if (f && f->nsplit && f->split[k])
      B += d->del2[2 * k] * f->nd2[k].qx + d->del2[2 * k + 1] * f->nd2[k].qy;
  }
  s->led.s_B += B;
}

/* PARTS: the part of particle k: in its particle row, left of the midpoint between the
 * row's first and last separated particle at the cut (reference x0) the grip's (0), right
 * of it the fixed end's (1), the band's own particles each by its side; -1 (left alone)
 * on the midpoint, for the head and for debris. */
static int part_of(const mpm_sim *s, const mpm_damping *d, size_t k, double dy)
{
  const mpm_particles *p = s->p;
  const int mat = p->mat[k];
  if (mat == MPM_MAT_HEAD || mat == MPM_MAT_DEBRIS)
    return -1;
  const int j = (int)(p->y0[k] / dy); /* the row, as mpm_sim_cut counts it */
  if (j < 0 || j >= s->nrow)
    return -1;
  const double mid = d->rowmid[j];
  return p->x0[k] < mid ? 0 : p->x0[k] > mid ? 1 : -1;
}

void mpm_damping_parts(mpm_sim *s)
{
  mpm_damping *d = s->damp;
  if (s->sc.damping_about != MPM_DAMP_PARTS || !s->cut || d->alpha == 0.0)
    return;
  assert(s->nbc > 0); /* every scene holds its ends (mpm_sim_alloc) */
  mpm_particles *p = s->p;
  const double dy = s->sc.h / sqrt((double)s->sc.ppc);
  if (!d->rows_set) { /* the parts the cut made: every row holds a separated particle */
    for (int j = 0; j < s->nrow; j++) {
      d->rowmid[j] = INFINITY; /* the first separated x0, until the loop below ends */
      d->rowhi[j] = -INFINITY;
    }
    for (size_t k = 0; k < p->n; k++) {
      const int j = (int)(p->y0[k] / dy);
      if (!p->sep[k] || p->mat[k] == MPM_MAT_HEAD || j < 0 || j >= s->nrow)
        continue;
      d->rowmid[j] = fmin(d->rowmid[j], p->x0[k]);
      d->rowhi[j] = fmax(d->rowhi[j], p->x0[k]);
    }
    for (int j = 0; j < s->nrow; j++) /* the interface: the line's x at the row's centre */
      d->rowmid[j] = s->g->fld && s->g->fld->ifc ? mpm_iface_x_at(s->g->fld->ifc, (j + 0.5) * dy)
                                                   : 0.5 * (d->rowmid[j] + d->rowhi[j]);
    d->rows_set = 1;
  }
  const double a = d->alpha, vend[2] = {-s->vgrip, 0.0};
  double dke = 0.0;
  for (size_t k = 0; k < p->n; k++) {
    const int q = part_of(s, d, k, dy);
    if (q < 0)
      continue;
    const double ux = p->vx[k], uy = p->vy[k];
    const double nx = ux - a * (ux - vend[q]), ny = uy - a * uy;
    dke += 0.5 * p->m[k] * ((ux * ux - nx * nx) + (uy * uy - ny * ny));
    p->vx[k] = nx;
    p->vy[k] = ny;
  }
  s->led.L_damp += dke;
}

/* time.damping > 0: after the node update (and the fields'), after MUSL's re-projection,
 * and on the parts once the band has cut the bar. */
const mpm_hook mpm_hook_damping = {"damping",
                                   {[MPM_PH_GRID] = mpm_damping_apply,
                                    [MPM_PH_MUSL] = mpm_damping_musl,
                                    [MPM_PH_END] = mpm_damping_parts}};
