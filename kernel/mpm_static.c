/*
 * mpm_static.c - the quasi-static solver: load increments solved by Newton's method on
 * the nodal force balance f_int(u) = 0 at the free degrees of freedom (eq. 3 without the
 * inertia of eq. 4), with the constitutive update of secs. 3-4 at every particle and its
 * algorithmic tangent (mpm_static_asm.c), and a path-following control:
 *
 *  - up to the first softening the grip's displacement delta leads.  The bar is linear
 *    there and starts unstressed, so the first increment is solved at a small delta and
 *    scaled to an eighth of the first particle's initiation (F = 0, eq. 23); seven more
 *    equal ones meet it exactly;
 *  - from then on the dissipation leads: C = sum U0 lambda V / Le, the dissipation of
 *    eq. 10 without its cap at lambda = 1 (a separated particle's lambda grows on with its
 *    opening, eq. 58, so C has no flat end where delta would be undetermined; the
 *    cohesive interface's segments count min(lambda, 1), mpm_static_iface.c).  Each
 *    increment adds tau to it, with delta an unknown (the constraint C(u, delta) = C_n +
 *    tau borders the system; two solves with one factorization).  C never decreases, so
 *    the control passes the peak and any snapback, where delta moves back as a test
 *    machine under crack-opening control does;
 *  - where C cannot grow (a segment of the interface's line separated and the rest
 *    unload: the load climbs back elastically) the grip leads, and hands back to the
 *    dissipation when an increment of it dissipates or it meets a limit point (resume);
 *  - below MPM_QS_SEP of the peak, where no increment is found, the interface's last
 *    segments let go in place (let_go);
 *  - once the bar is cut (or C stops answering delta) the grip leads again, and the cut
 *    part's vertical rigid motion is held.
 * Increments adapt to Newton's work: larger after an easy one, smaller after a hard one,
 * halved and retried when an increment fails.
 *
 * Convergence: the largest residual force below MPM_QS_FTOL times the largest load so far
 * (the curve is judged to 1e-3 of the peak load: nine orders below it), and D within
 * MPM_QS_DTOL of its target per unit of the full dissipation U0 H / sin a.
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
#define MPM_QS_MAXIT 25   /* Newton iterations an increment may take                */
#define MPM_QS_CYCLE 1e-3 /* relative: merits this close two iterations apart are a cycle */
#define MPM_QS_LS 8       /* halvings of a Newton step that raises the residual      */
#define MPM_QS_MAXCUT 40  /* halvings of one increment before the run gives up       */
#define MPM_QS_EASY 4     /* iterations at or below which the next increment grows   */
#define MPM_QS_HARD 10    /* ... at or above which it shrinks                        */
#define MPM_QS_TURN 0.15  /* radians: an increment whose chord turns more than this from the last
                             one's, in (delta / delta at the peak, P / the peak), is retried at
                             half its size, so that rows resolve the curve's corners (the peak,
                             the separation) and stay few along its straight pieces            */
#define MPM_QS_STALL 100  /* increments over which the control must advance by MPM_QS_STALL_C */
#define MPM_QS_STALL_C 1e-3 /* ... of U0 H / sin a, or the run stops with an error: it stalls */
#define MPM_QS_SEP 0.02   /* a load below this share of the peak, after it, is separation   */
#define MPM_QS_MAXINC 5000 /* increments a run may take (Fig. 6 at h 2 takes under 100)      */
#define MPM_QS_RESUME 1e-6 /* of U0 H / sin a: a grip increment after the peak that dissipates
                              more hands the lead back to the dissipation                    */
#define MPM_QS_GRIPMIN 1e-6 /* of delta: a grip step cut below this has met a limit point      */
#define MPM_QS_MAXSW 60   /* changes of control a run may make (each resumed softening takes two) */
#define MPM_QS_CMIN 1e-12 /* of U0 H / sin a: less dissipated is nothing (rounding)     */
#define MPM_QS_NEL 8      /* equal increments of the linear branch up to the first initiation */
#define MPM_QS_PUSH 0.01  /* of the peak: an interface's load below minus this stops the run */
#define MPM_QS_LEDGER 1e-4 /* of the largest W_ext: W_ext - SE - W_coh beyond this stops the run */

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

static mpm_status factor(mpm_static *q)
{
  const double t0 = mpm_wall();
  const mpm_status st = mpm_lin_factor(q->lin);
  q->st.t_factor += mpm_wall() - t0;
  q->st.factorizations++;
  return st;
}

static mpm_status solve(mpm_static *q, const double *b, double *x)
{
  const double t0 = mpm_wall();
  const mpm_status st = mpm_lin_solve(q->lin, b, x);
  q->st.t_solve += mpm_wall() - t0;
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

/* One increment from the committed state under the current control; 1 if it converged
 * (the trial state is then the increment's), 0 if not, or a negative status. */
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
  if (!grip) {
    /* q < 1 and nothing dissipated beyond rounding (a line at its strength everywhere
     * can have one segment at lambda 4e-16 after the linear branch's last increment): a
     * grip increment starts the softening, not a predictor from that one segment's
     * tangent, which has the law's infinite slope and sent Newton after it alone (a45,
     * a30 at q 0.8 stopped at the peak); for q >= 1 that tangent is finite and the
     * predictor is cheaper (a grip increment here triples Newton's work on a30) */
    if (q->s->sc.q < 1.0 && !(q->Cn > MPM_QS_CMIN * q->Dref) && q->nkick < 3)
      return -2;
    /* pden < 0: C grows as delta falls, the snapback branch */
    if (fabs(q->pden) * fmax(q->dn, 1e-300) > 1e-9 * q->Dref)
      dd = q->step_D / q->pden;
    else if (q->Cn > 0.0)
      dd = (q->dlast < 0.0 ? -1e-4 : 1e-4) * q->dn; /* the way the last increment went; Newton
                                                       finds the control's target from there */
    else
      return -2; /* nothing softens yet: a grip increment starts it */
  }
  add_free(q, q->pdir, dd);
  q->dt += dd;
  const double Dtarget = q->Cn + q->step_D;
  double mh[MPM_QS_MAXIT]; /* each iteration's merit */
  if (mpm_static_eval(q, 1) != MPM_OK)
    return 0;
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
    if (it + 1 >= MPM_QS_MAXIT || cycles(mh, it) || factor(q) != MPM_OK)
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

/* The softening particles that reach their strength within 1e-9 of the first (scale k:
 * the linear increment times k meets F = 0, eq. 23). */
static long tied_at_initiation(const mpm_static *q, double k)
{
  const mpm_sim *s = q->s;
  long n = 0;
  for (size_t c = 0; c < q->np; c++) {
    const mpm_material *m = &s->mat[s->p->mat[q->pid[c]]];
    if (m->model == MPM_DCOH_NONE)
      continue;
    const double se = mpm_dcoh_F(m, q->tst[c].sxx, q->tst[c].syy, q->tst[c].sxy, 0.0) + 1.0;
    n += se > 0.0 && 1.0 / se <= k * (1.0 + 1e-9);
  }
  return n;
}

/* The linear first increment scaled to 1 / MPM_QS_NEL of the first initiation (F = 0,
 * eq. 23); the grip's step is set to the rest's share.  MPM_ESTALL where more particles
 * than a cell holds reach their strength together (a uniform stress without a flaw): the
 * uniform state bifurcates there, every band is a branch and the uniform softening one is
 * unstable (fig6 without its flaw followed it to D = 13 U0 H); the run stops and says how
 * to choose the branch. */
static mpm_status scale_to_initiation(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  double kmin = INFINITY;
  for (size_t c = 0; c < q->np; c++) {
    const mpm_material *m = &s->mat[s->p->mat[q->pid[c]]];
    if (m->model == MPM_DCOH_NONE)
      continue;
    const double F = mpm_dcoh_F(m, q->tst[c].sxx, q->tst[c].syy, q->tst[c].sxy, 0.0), se = F + 1.0;
    if (se > 0.0)
      kmin = fmin(kmin, 1.0 / se);
  }
  const long tied = isfinite(kmin) ? tied_at_initiation(q, kmin) : 0;
  if (tied > s->sc.ppc) {
    snprintf(err, errlen, "static solver: %ld softening particles reach their strength together at delta = %.9g: "
             "the uniform state bifurcates there (each band is a branch, the uniform softening is unstable); give "
             "the bar a flaw to choose the branch (imperfection.snf_factor below 1) or use decohesion.path = "
             "interface", tied, q->dt * kmin);
    return MPM_ESTALL;
  }
  for (int pi = 0; pi < q->npair; pi++) { /* the interface's ties */
    const mpm_dstate *o = &q->ptr[pi];
    const double se = mpm_dcoh_F(&q->imat, o->sxx, o->syy, o->sxy, 0.0) + 1.0;
    if (se > 0.0)
      kmin = fmin(kmin, 1.0 / se);
  }
  if (!(kmin > 1.0) || !isfinite(kmin))
    return MPM_OK;
  const double k = kmin * (1.0 - 1e-12) / MPM_QS_NEL;
  for (size_t i = 0; i < 2 * q->nslot; i++)
    if (q->eq[i] >= 0)
      q->Ut[i] *= k;
  q->dt *= k;
  q->step_d = q->dt;
  q->nel = MPM_QS_NEL - 1;
  mpm_static_eval(q, 1);
  return MPM_OK;
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

/* 1 if the trial increment's chord turns more than MPM_QS_TURN from the last one's and
 * the step can still be halved. */
static int turns(const mpm_static *q)
{
  const mpm_sim *s = q->s;
  if (s->step < MPM_QS_NEL || !(q->pk_d > 0.0) || !(s->P_peak > 0.0))
    return 0;
  const double ax = q->ch_d, ay = q->ch_P, bx = (q->dt - q->dn) / q->pk_d, by = (q->Pg - s->P_grip) / s->P_peak;
  const double la = hypot(ax, ay), lb = hypot(bx, by);
  if (!(la > 0.0) || !(lb > 1e-4)) /* a short chord: no corner to resolve */
    return 0;
  const double c = (ax * bx + ay * by) / (la * lb);
  /* the separation's corner: the load falling from above 3 % of the peak to below 1 % in
   * one increment cuts it whatever the chords' angle */
  const int lands = q->Pg < 0.01 * s->P_peak && s->P_grip > 0.03 * s->P_peak;
  return c < cos(MPM_QS_TURN) || lands;
}

/* 1 if the control's measure moved by less than MPM_QS_STALL_C Dref over the last
 * MPM_QS_STALL increments (a ring of their values). */
static int stalls(mpm_static *q)
{
  const int k = (int)(q->st.increments % MPM_QS_STALL);
  const double old = q->cring[k];
  q->cring[k] = q->Cn;
  return q->st.increments >= MPM_QS_STALL && q->Cn - old < MPM_QS_STALL_C * q->Dref;
}

static void set_mode(mpm_static *q, int mode)
{
  if (q->mode == mode)
    return;
  q->mode = mode;
  q->st.switches++;
  if (mode == MPM_QS_GRIP) /* after the softening: a fiftieth of delta, growing */
    q->step_d = 0.02 * fabs(q->dn) + 1e-6 * q->s->sc.L * fmin(q->s->sc.snf, q->s->sc.stf) / q->s->sc.E;
}

/* After the peak and before the cut the grip leads only along an elastic stretch (a
 * segment of the line separated and the rest unloaded: the load climbs back to their
 * strength).  When the grip cannot pass a limit point, or an increment of it dissipated,
 * the dissipation leads again; 1 if it does. */
static int resume(mpm_static *q)
{
  if (q->mode != MPM_QS_GRIP || q->nel > 0 || !(q->Cn > 0.0) || q->s->cut || q->st.switches >= MPM_QS_MAXSW)
    return 0;
  set_mode(q, MPM_QS_DISSIPATION);
  q->step_D = fmax(q->step_D, MPM_QS_RESUME * q->Dref);
  return 1;
}

/* The load gone below MPM_QS_SEP of the peak and no increment found: the interface's
 * last segments let go in place (as the explicit run's separation at 0.98 drops the last
 * 2 % of a traction at once; the bar is then cut) and the grip pulls the parts apart.
 * How many let go; 0 where none was left or the rule does not apply. */
static int let_go(mpm_static *q)
{
  const mpm_sim *s = q->s;
  if (!q->iface || !(q->Cn > 0.0) || !(fabs(s->P_grip) < MPM_QS_SEP * s->P_peak))
    return 0;
  const int n = mpm_static_iface_sever(q);
  q->st.severed += n;
  if (n > 0)
    q->have_eval = q->have_pred = 0;
  return n;
}

/* The bar is cut: the cut part's vertical rigid motion is held and the grip leads. */
static mpm_status pin(mpm_static *q, char *err, size_t errlen)
{
  q->pinned = 1;
  set_mode(q, MPM_QS_GRIP);
  q->step_d = fmax(q->step_d, 0.02 * fabs(q->dn));
  return mpm_static_number(q, err, errlen);
}

/* A failed increment: the current control's step halved. */
static void shrink(mpm_static *q)
{
  q->st.cuts++;
  if (q->kick) {
    q->kick_d *= 0.5;
  } else if (q->mode == MPM_QS_DISSIPATION) {
    q->step_D *= 0.5;
    if (q->step_D < 1e-9 * q->Dref)
      set_mode(q, MPM_QS_GRIP);
  } else {
    q->step_d *= 0.5;
    if (q->step_d < MPM_QS_GRIPMIN * fabs(q->dn)) /* the grip cannot pass a limit point */
      resume(q);
  }
}

/* The next increment's size after one that took iters Newton iterations. */
static void next_step(mpm_static *q, int iters, int first)
{
  const mpm_sim *s = q->s;
  const double grow = iters <= MPM_QS_EASY ? 1.5 : iters >= MPM_QS_HARD ? 0.6 : 1.0;
  if (q->mode == MPM_QS_DISSIPATION)
    q->step_D = fmin(q->step_D * grow, q->Dmax);
  else if (q->nel > 0 && !first) {
    /* the linear branch: equal steps to the initiation, then the dissipation leads */
    if (--q->nel == 0 && s->sc.model != MPM_DCOH_NONE)
      set_mode(q, MPM_QS_DISSIPATION);
  } else if (!first)
    q->step_d *= grow;
  /* the grip never passes the run's end */
  if (q->mode == MPM_QS_GRIP && q->dn + q->step_d > s->sc.end_delta)
    q->step_d = fmax(s->sc.end_delta - q->dn, 1e-12 * s->sc.end_delta);
}

/* After an increment is committed: its path still one of equilibria (the ledger) and not
 * one a test would leave by a snap (the push-back); MPM_ESTALL and the reason if not. */
static mpm_status path_sound(mpm_static *q, char *err, size_t errlen)
{
  const mpm_sim *s = q->s;
  /* the ledger at every increment: W_ext (the trapezoid of P d delta) against SE +
   * W_coh, within MPM_QS_LEDGER of the largest W_ext so far (every bar scene's static
   * run keeps it below 1e-6): a path that leaves it is not one of equilibria */
  mpm_energy e;
  mpm_sim_energy(s, &e);
  q->Wmax = fmax(q->Wmax, fabs(e.W_ext));
  if (fabs(e.W_ext - e.SE - e.W_coh) > MPM_QS_LEDGER * q->Wmax && q->Wmax > 0.0) {
    snprintf(err, errlen, "static solver: the work done, %.9g, and the energy stored and spent, SE %.9g + W_coh "
             "%.9g, part by %.3g of the largest work at delta = %.9g, increment %ld (allowed %g)", e.W_ext, e.SE,
             e.W_coh, fabs(e.W_ext - e.SE - e.W_coh) / q->Wmax, q->dn, s->step, MPM_QS_LEDGER);
    return MPM_ESTALL;
  }
  /* an interface's equilibrium path along which the specimen pushes back on its
   * loading, P below -MPM_QS_PUSH of the peak (held grips on an inclined crack:
   * segments unload with their opening kept while the control moves delta back):
   * every state is in equilibrium, but a test under displacement control leaves such
   * a path by a dynamic snap, which no quasi-static path shows; the run stops and
   * says so.  (A free band's last particles take the load to -3 % of the peak near
   * separation, test_mpm_static: the band's own error, not a snap; not judged here.) */
  if (q->iface && s->P_grip < -MPM_QS_PUSH * s->P_peak) {
    snprintf(err, errlen, "static solver: the equilibrium path takes the load to %.6g (%.3g of the peak %.6g) at "
             "delta = %.9g, increment %ld: a test under displacement control would snap dynamically before this "
             "point, which a quasi-static path cannot follow (docs/static.md, \"Where it stops\"); the explicit "
             "solver runs it", s->P_grip, s->P_grip / s->P_peak, s->P_peak, q->dn, s->step);
    return MPM_ESTALL;
  }
  return MPM_OK;
}

mpm_status mpm_static_step(mpm_static *q, char *err, size_t errlen)
{
  mpm_sim *s = q->s;
  for (int cut = 0; cut <= MPM_QS_MAXCUT; cut++) {
    int iters = 0;
    int r = increment(q, &iters);
    /* a kick starts the softening; one whose equilibrium lost half the load crossed a
     * snap (at a snapback's peak the only states past delta are the separated ones):
     * it is retried smaller */
    if (r == 1 && q->kick && q->Pg < 0.5 * s->P_grip)
      r = 0;
    if (r == -2) {
      /* C does not answer delta: nothing softens at the committed state (the initiation,
       * or a particle that stopped): a small grip increment starts it again; if that
       * does not, the grip leads to the end */
      if (q->nkick < 3) {
        q->kick = 1;
        q->kick_d = 1e-4 * q->dn;
      } else
        set_mode(q, MPM_QS_GRIP);
      continue;
    }
    /* the kick and the linear branch are taken as they are */
    const int dis = q->mode == MPM_QS_DISSIPATION && !q->kick, grip = q->mode == MPM_QS_GRIP && q->nel == 0;
    if (r == 1 && (dis ? q->step_D > 1e-6 * q->Dref : grip && q->step_d > 1e-9 * s->sc.L) && turns(q)) {
      q->st.turns++;
      if (dis)
        q->step_D *= 0.5;
      else
        q->step_d *= 0.5;
      continue;
    }
    if (r == 1) {
      const int first = s->step == 0;
      const mpm_status si = first && q->mode == MPM_QS_GRIP ? scale_to_initiation(q, err, errlen) : MPM_OK;
      if (si != MPM_OK)
        return si;
      const double Cprev = q->Cn;
      commit(q);
      const int grip_stalls = (q->mode == MPM_QS_GRIP && q->nel == 0 && q->step_d < 1e-9 * fmax(q->dn, 1e-300)) ||
                              q->st.increments >= MPM_QS_MAXINC;
      const int diss_stalls = q->mode == MPM_QS_DISSIPATION && stalls(q);
      int gone = 0;
      if (grip_stalls && q->st.increments < MPM_QS_MAXINC && resume(q)) {
        /* the grip could not pass a limit point */
      } else if ((diss_stalls || grip_stalls) && q->st.increments < MPM_QS_MAXINC && (gone = let_go(q)) > 0) {
        /* the line's last segments let go */
      } else if (diss_stalls && s->P_grip < MPM_QS_SEP * s->P_peak && !grip_stalls) {
        /* the control creeps with the load almost gone (the line's last points opening one
         * by one): the bar has separated; the grip pulls the rest open */
        s->cut = 1;
      } else if (diss_stalls || grip_stalls) {
        snprintf(err, errlen, "static solver: the path stalls at delta = %.9g, P = %.6g: the %s control "
                 "advanced by less than %g of its scale over the last %d increments (docs/static.md, \"Where it "
                 "stops\")", q->dn, s->P_grip, grip_stalls ? "grip" : "dissipation",
                 grip_stalls ? 1e-9 : MPM_QS_STALL_C, grip_stalls ? 1 : MPM_QS_STALL);
        return MPM_ESTALL;
      }
      const mpm_status ps = path_sound(q, err, errlen);
      if (ps != MPM_OK)
        return ps;
      /* a grip increment that dissipated, before the cut: softening resumed after an
       * elastic stretch (a segment of the line separated and the rest unloaded; the load
       * climbs back to their strength): the dissipation leads again through the next
       * snapback, which the grip cannot pass */
      if (!first && !q->kick && q->Cn - Cprev > MPM_QS_RESUME * q->Dref)
        resume(q);
      q->nkick = q->kick ? q->nkick + 1 : 0;
      q->kick = 0;
      /* the next increment's predictor from this state's tangent (the trial's last
       * evaluation is at the committed state) */
      q->have_eval = !gone; /* letting go changed the state since that evaluation */
      q->have_pred = 0;
      if (predictor(q) != MPM_OK)
        q->have_eval = 0;
      q->st.increments++;
      q->st.mode = q->mode;
      next_step(q, iters, first);
      return s->cut && !q->pinned ? pin(q, err, errlen) : MPM_OK;
    }
    shrink(q);
  }
  if (let_go(q)) {
    const mpm_status st = q->pinned ? MPM_OK : pin(q, err, errlen);
    return st != MPM_OK ? st : mpm_static_step(q, err, errlen);
  }
  snprintf(err, errlen, "static solver: no equilibrium found after %d smaller increments at delta = %.9g (increment "
           "%ld, %s control)", MPM_QS_MAXCUT, q->dn, s->step + 1, q->mode == MPM_QS_GRIP ? "grip" : "dissipation");
  return MPM_ESTALL;
}
