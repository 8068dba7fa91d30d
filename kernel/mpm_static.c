/*
 * mpm_static.c - the quasi-static solver: load increments solved by Newton's method on
 * the nodal force balance f_int(u) = 0 at the free degrees of freedom (eq. 3 without the
 * inertia of eq. 4), with the update of secs. 3-4 and its algorithmic tangent at every
 * particle (mpm_static_asm.c).  This file solves one increment; the path-following
 * control that chooses each (the grip's delta up to the first softening, then the
 * dissipation C = sum U0 lambda V / Le of eq. 10 uncapped, through the peak and any
 * snapback, the grip again where C cannot grow or after the cut) is mpm_static_path.c.
 * Convergence: residual below MPM_QS_FTOL times the largest load so far, and D within
 * MPM_QS_DTOL of its target per unit of U0 H / sin a.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mpm_kernel.h"
#include "mpm_specimen.h"
#include "mpm_static.h"

#define MPM_QS_FTOL 1e-9
#define MPM_QS_DTOL 1e-10
#define MPM_QS_CYCLE 1e-3 /* relative: merits this close two iterations apart are a cycle */
#define MPM_QS_LS 8       /* halvings of a Newton step that raises the residual      */
#define MPM_QS_PREDMAX 0.05 /* the largest predictor change of delta after a kick, of delta */
#define MPM_QS_MISS 100    /* of the step: a predictor missing the dissipation target by more
                               is not tried (Newton from there: 18 to 25 iterations, measured) */
#define MPM_QS_FIRST 1e-6   /* of Dref: less dissipated, the softening has just begun     */

void mpm_static_free(mpm_static *q)
{
  if (!q)
    return;
  if (q->s && q->s->qs == q)
    q->s->qs = NULL;
  void *f[] = {q->pid, q->cnt, q->node, q->N, q->Gx, q->Gy, q->eq, q->held, q->coef, q->map, q->Un, q->Ut, q->Kel, q->kfdel, q->R, q->kfd,
               q->ga, q->x1, q->x2, q->du, q->pdir, q->tst, q->tw, q->tpath, q->fext};
  for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
    free(f[i]);
  mpm_static_iface_free(q);
  mpm_lin_free(q->lin);
  mpm_dwork_free(q->dw);
  free(q);
}

void mpm_static_stats_get(const mpm_static *q, mpm_static_stats *out)
{
  *out = q->st;
}

/* What the static solver cannot solve, refused before anything is built. */
mpm_status mpm_static_refusal(const mpm_scene *sc, char *err, size_t errlen)
{
  if (sc->le_mode == MPM_LE_ROW || sc->le_mode == MPM_LE_ZONE) {
    snprintf(err, errlen, "solver.type = static: decohesion.Le = %s is measured as an explicit run goes; use cell, "
             "particle or staircase", sc->le_mode == MPM_LE_ROW ? "row" : "zone");
    return MPM_EINVAL;
  }
  if (sc->ppc == 1 && sc->model != MPM_DCOH_NONE && sc->path != MPM_PATH_IFACE) {
    /* measured: fig6 on uGIMP at 1 ppc, h 8, stalls in the softening (D 0.19 of 12) */
    snprintf(err, errlen, "solver.type = static: grid.ppc = 1 with softening particles (decohesion.path = %s) "
             "stalls: one particle a cell cannot open its band in equilibrium (docs/static.md); use ppc 4 or 9, or "
             "decohesion.path = interface", sc->path == MPM_PATH_LINE ? "line" : "free");
    return MPM_EINVAL;
  }
  if (sc->shape == MPM_SHAPE_LINEAR && sc->ppc == 1) {
    /* one quadrature point per cell: the bilinear cell's two hourglass modes carry no
     * strain at it, so the tangent is singular (docs/static.md) */
    snprintf(err, errlen, "solver.type = static: grid.ppc = 1 with grid.shape = linear leaves one quadrature point per "
             "cell, whose stiffness has zero-energy (hourglass) modes; use ppc 4 or 9, or shape = gimp");
    return MPM_EINVAL;
  }
  return MPM_OK;
}

mpm_status mpm_static_alloc(mpm_sim *s, mpm_static **out, char *err, size_t errlen)
{
  *out = NULL;
  mpm_status st = mpm_static_refusal(&s->sc, err, errlen);
  if (st != MPM_OK)
    return st;
  mpm_static *q = calloc(1, sizeof *q);
  if (!q)
    return MPM_ENOMEM;
  q->s = s;
  if ((st = mpm_static_setup(q, err, errlen)) != MPM_OK || (st = mpm_static_number(q, err, errlen)) != MPM_OK) {
    mpm_static_free(q);
    return st;
  }
  const mpm_scene *sc = &s->sc;
  q->Dref = sc->model != MPM_DCOH_NONE ? mpm_specimen_of(sc)->dis_full(sc) : 1.0;
  q->Dmax = sc->model != MPM_DCOH_NONE ? mpm_specimen_of(sc)->dis_step_max(sc) : 0.1;
  q->Fref = 1e-3 * fmin(sc->snf, sc->stf) * sc->H;
  q->step_d = 1e-3 * sc->L * fmin(sc->snf, sc->stf) / sc->E; /* the first, elastic, increment */
  if (sc->model == MPM_DCOH_NONE) { /* no strength to scale by: the run's own stretch */
    q->Fref = 1e-3 * sc->E * sc->H * sc->end_delta / sc->L;
    q->step_d = sc->end_delta / MPM_QS_NEL;
  }
  q->step_D = 1e-3 * q->Dref;
  q->mode = MPM_QS_GRIP;
  s->qs = q;
  /* a static bar has no velocity: the explicit run's starting field is not its */
  for (size_t k = 0; k < s->p->n; k++)
    s->p->vx[k] = s->p->vy[k] = 0.0;
  *out = q;
  return MPM_OK;
}

static double dot(const double *a, const double *b, int n)
{
  double d = 0.0;
  for (int i = 0; i < n; i++)
    d += a[i] * b[i];
  return d;
}

static double norm_inf(const double *a, int n)
{
  double d = 0.0;
  for (int i = 0; i < n; i++)
    d = fmax(d, fabs(a[i]));
  return d;
}

/* The tangent's LU; the factors held are kept where the values did not change (the
 * linear branch, an elastic stretch, the parts after the cut): the same bits. */
static mpm_status factor(mpm_static *q)
{
  if (mpm_lin_same(q->lin))
    return MPM_OK;
  const double t0 = mpm_wall();
  const mpm_status st = mpm_lin_factor(q->lin);
  q->st.t_factor += mpm_wall() - t0;
  mpm_lin_counts(q->lin, &q->st.factorizations, &q->st.updates);
  return st;
}

static mpm_status solve(mpm_static *q, const double *b, double *x)
{
  const double t0 = mpm_wall();
  const mpm_status st = mpm_lin_solve(q->lin, b, x);
  q->st.t_solve += mpm_wall() - t0;
  mpm_lin_counts(q->lin, &q->st.factorizations, &q->st.updates); /* a correction may fall back */
  return st;
}

/* Adds du (unknowns) to the trial displacement. */
static void add_free(mpm_static *q, const double *du, double a)
{
  for (size_t i = 0; i < 2 * q->nslot; i++)
    if (q->eq[i] >= 0)
      q->Ut[i] += a * du[q->eq[i]];
}

/* The predictor of the next increment: the tangent at the committed state (its last
 * evaluation, at the converged trial) factorized, d u / d delta = -K^-1 d R / d delta, and
 * the control's answer to delta along it. */
static mpm_status predictor(mpm_static *q)
{
  const int n = q->nfree;
  if (!q->have_eval && mpm_static_eval(q, 1) != MPM_OK)
    return MPM_ENOTFINITE;
  mpm_status st = factor(q);
  for (int i = 0; st == MPM_OK && i < n; i++)
    q->x1[i] = -q->kfd[i];
  if (st == MPM_OK)
    st = solve(q, q->x1, q->pdir);
  q->pden = st == MPM_OK ? dot(q->ga, q->pdir, n) + q->gb : NAN;
  q->have_pred = st == MPM_OK;
  return st;
}

/* The residual over its tolerance: the largest force over MPM_QS_FTOL Fref and, under
 * the dissipation control, the constraint's miss over MPM_QS_DTOL Dref; <= 1 converged. */
static double merit(const mpm_static *q, double Fref, double g, int grip)
{
  const double r = norm_inf(q->R, q->nfree) / (MPM_QS_FTOL * Fref);
  return grip ? r : fmax(r, fabs(g) / (MPM_QS_DTOL * q->Dref));
}

/* 1 if Newton's merits m[0 .. it] end in a cycle: each of the last two within
 * MPM_QS_CYCLE of the one two before it, above the tolerance (near the peak a segment
 * flips between elastic and softening across a step, and the iterates alternate between
 * two states to the last digits until MPM_QS_MAXIT). */
static int cycles(const double *m, int it)
{
  return it >= 3 && fabs(m[it] - m[it - 2]) <= MPM_QS_CYCLE * m[it] &&
         fabs(m[it - 1] - m[it - 3]) <= MPM_QS_CYCLE * m[it - 1];
}

/* The dissipation control's predicted change of delta, *dd; -2 where a grip increment
 * is to start the softening instead. */
static int dissipation_step(mpm_static *q, double *dd)
{
  /* nothing dissipated beyond rounding: a grip increment starts the softening, not a
   * predictor from the committed state's tangent.  The linear branch ends just short of
   * the first initiation, but where a line is at its strength everywhere rounding can
   * leave some of its segments at lambda 4e-16 and the rest at 0, and the predictor then
   * sends Newton after those alone: which branch the path took depended on the build
   * (iface90 with U0 0.01875, h 4: one side opening, curve_path 0.030, with -O3; the
   * uniform opening, 4e-7, with -O0; a45, a30 at q 0.8 stopped at the peak).  A grip
   * increment loads every tied point past its strength alike: the same branch on every
   * build (docs/static.md, "Stability") */
  if (!(q->Cn > MPM_QS_CMIN * q->Dref) && q->nkick < 3)
    return -2;
  /* pden < 0: C grows as delta falls, the snapback branch */
  if (fabs(q->pden) * fmax(q->dn, 1e-300) > 1e-9 * q->Dref) {
    /* the run's first dissipation step, after the kick, where particles soften: the
     * kick's softening set is the flaw alone, whose tangent answers a step of 1e-3 U0 H
     * with a delta hundreds of times the bar's (fig6, h 1, 9 ppc: 33.7 at 0.169) and
     * Newton fails from there four times before the step is small enough; so the step
     * is one that moves delta by at most MPM_QS_PREDMAX of itself (docs/static.md) */
    if (q->nkick > 0 && !q->iface && q->Cn < MPM_QS_FIRST * q->Dref)
      q->step_D = fmin(q->step_D, MPM_QS_PREDMAX * fabs(q->pden) * q->dn);
    *dd = q->step_D / q->pden;
  } else if (q->Cn > 0.0)
    *dd = (q->dlast < 0.0 ? -1e-4 : 1e-4) * q->dn; /* the way the last increment went; Newton
                                                      finds the control's target from there */
  else
    return -2; /* nothing softens yet: a grip increment starts it */
  return 0;
}

/* One increment from the committed state under the current control; 1 if it converged
 * (the trial state is then the increment's), 0 if not, -2 if nothing softens (a grip
 * increment starts it), -3 if its predictor was not tried (MPM_QS_MISS). */
static int increment(mpm_static *q, int *iters)
{
  const int n = q->nfree;
  memcpy(q->Ut, q->Un, sizeof(double) * 2 * q->nslot);
  q->dt = q->dn;
  if (!q->have_pred && predictor(q) != MPM_OK)
    return 0;
  /* predictor: the committed state's tangent response to delta, scaled to the step */
  const int grip = q->mode == MPM_QS_GRIP || q->kick;
  double dd = q->kick ? q->kick_d : q->step_d;
  if (!grip && dissipation_step(q, &dd) != 0)
    return -2;
  add_free(q, q->pdir, dd);
  q->dt += dd;
  const double Dtarget = q->Cn + q->step_D;
  double mh[MPM_QS_MAXIT]; /* each iteration's merit */
  if (mpm_static_eval(q, 1) != MPM_OK)
    return 0;
  /* a predictor that misses the dissipation target by MPM_QS_MISS steps has passed a
   * limit of the tangent's reach (Fig. 6's bar past its strength, where every particle
   * softens at once: C 1e4 steps off at h 1); Newton from there ran to MPM_QS_MAXIT at
   * h 2 and 1 and took 18 at h 4, where the same step cut as deep passes at once */
  if (!grip && fabs(q->Ct - Dtarget) > MPM_QS_MISS * q->step_D)
    return -3;
  for (int it = 0;; it++) {
    *iters = it + 1;
    q->st.newton++;
    const double Fref = fmax(fmax(q->s->P_peak, fabs(q->Pg)), q->Fref);
    const double g = q->Ct - Dtarget, m0 = merit(q, Fref, g, grip);
    mh[it] = m0;
    if (it < 32) {
      q->st.res[it] = norm_inf(q->R, n) / Fref;
      q->st.nres = it + 1;
    }
    if (m0 <= 1.0)
      return 1;
    /* C answers nothing at the trial (no point softens: ga and gb 0): the constraint's
     * denominator below is 0 whatever the factors, so the increment fails unfactorized */
    if (it + 1 >= MPM_QS_MAXIT || cycles(mh, it) || (!grip && q->gb == 0.0 && norm_inf(q->ga, n) == 0.0) ||
        factor(q) != MPM_OK)
      return 0;
    for (int i = 0; i < n; i++)
      q->x1[i] = -q->R[i];
    if (solve(q, q->x1, q->du) != MPM_OK)
      return 0;
    double ddl = 0.0;
    if (!grip) {
      for (int i = 0; i < n; i++)
        q->x1[i] = -q->kfd[i];
      if (solve(q, q->x1, q->x2) != MPM_OK)
        return 0;
      const double den = dot(q->ga, q->x2, n) + q->gb;
      if (!(fabs(den) > 0.0))
        return 0;
      ddl = (-g - dot(q->ga, q->du, n)) / den;
      for (int i = 0; i < n; i++)
        q->du[i] += ddl * q->x2[i];
    }
    if (!isfinite(norm_inf(q->du, n)) || !isfinite(ddl))
      return 0;
    /* backtracking: a full step that raises the residual is halved, up to MPM_QS_LS
     * times (near the peak particles flip between elastic and softening across a full
     * step and Newton cycles) */
    double a = 1.0;
    add_free(q, q->du, a);
    q->dt += a * ddl;
    for (int ls = 0;; ls++) {
      if (mpm_static_eval(q, 1) != MPM_OK)
        return 0;
      if (ls == MPM_QS_LS || merit(q, fmax(fmax(q->s->P_peak, fabs(q->Pg)), q->Fref), q->Ct - Dtarget, grip) < m0)
        break;
      a *= 0.5;
      add_free(q, q->du, -a);
      q->dt -= a * ddl;
      q->st.backtracks++;
    }
  }
  return 0;
}

/* Makes the trial state the committed one: particles, displacements, loads, energies. */
static void commit(mpm_static *q)
{
  mpm_sim *s = q->s;
  mpm_particles *p = s->p;
  const size_t M = MPM_ST_MAX;
  for (size_t c = 0; c < q->np; c++) {
    const size_t i = q->pid[c];
    const mpm_material *m = &s->mat[p->mat[i]];
    const mpm_dstate *o = &q->tst[c];
    if (m->model != MPM_DCOH_NONE)
      p->dis[i] += m->U0 * (fmin(o->lam, 1.0) - fmin(p->lam[i], 1.0)) * p->V[i] / m->Le;
    p->sxx[i] = o->sxx;
    p->syy[i] = o->syy;
    p->sxy[i] = o->sxy;
    p->lam[i] = o->lam;
    p->upn[i] = o->upn;
    p->upt[i] = o->upt;
    p->sep[i] = (uint8_t)o->sep;
    p->str2[i] = mpm_dcoh_str2(m, o->lam, o->sep);
    p->wcoh[i] += q->tw[c];
    s->n_soften += q->tpath[c] == MPM_DPATH_SOFTEN;
    s->n_separate += q->tpath[c] == MPM_DPATH_SEPARATE;
    double ux = 0.0, uy = 0.0;
    for (int a = 0; a < q->cnt[c]; a++) {
      ux += q->N[c * M + (size_t)a] * q->Ut[2 * (size_t)q->node[c * M + (size_t)a]];
      uy += q->N[c * M + (size_t)a] * q->Ut[2 * (size_t)q->node[c * M + (size_t)a] + 1];
    }
    p->x[i] = p->x0[i] + ux;
    p->y[i] = p->y0[i] + uy;
  }
  s->W_ext += 0.5 * (s->P_grip + q->Pg) * (q->dt - q->dn); /* trapezoid: exact on straight pieces */
  q->dlast = q->dt - q->dn;
  if (q->Pg >= s->P_peak)
    q->pk_d = q->dt;
  if (q->pk_d > 0.0 && s->P_peak > 0.0) { /* this chord, for the next one's turn */
    q->ch_d = (q->dt - q->dn) / q->pk_d;
    q->ch_P = (q->Pg - s->P_grip) / fmax(s->P_peak, q->Pg);
  }
  memcpy(q->Un, q->Ut, sizeof(double) * 2 * q->nslot);
  q->dn = q->dt;
  q->Dn = q->Dt;
  q->Cn = q->Ct;
  s->P_grip = q->Pg;
  s->P_fixed = q->Pf;
  s->P_peak = fmax(s->P_peak, q->Pg);
  s->D_run = q->Dt;
  s->ugrip = q->dt;
  s->step++;
  s->t = (double)s->step;
  if (q->iface)
    mpm_static_iface_commit(q);
  mpm_sim_cut(s);
}

/* The Newton side as the path control (mpm_static_path.c) calls it. */
int mpm_static_increment(mpm_static *q, int *iters)
{
  return increment(q, iters);
}

mpm_status mpm_static_predict(mpm_static *q)
{
  return predictor(q);
}

void mpm_static_commit(mpm_static *q)
{
  commit(q);
}
