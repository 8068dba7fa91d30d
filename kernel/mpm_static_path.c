/*
 * mpm_static_path.c - the quasi-static solver's path control around Newton's solve of
 * one increment (mpm_static.c): a state machine (path_state) over
 *  - linear: the grip leads in equal increments to the first initiation (F = 0, eq. 23),
 *    or stops at a uniform state's tie;
 *  - kick: a small grip increment starts the softening where nothing dissipated yet;
 *  - dissipation: C = sum U0 lambda V / Le (eq. 10 uncapped) leads, delta an unknown,
 *    through the peak and any snapback;
 *  - grip: the grip leads along an elastic stretch until C can grow again (resume);
 *  - severing, a passage: below MPM_QS_SEP of the peak the line's last segments let go;
 *  - cut: the part's vertical rigid motion held (pin); the grip leads to the end.
 * Each committed state is judged (path_sound: the ledger, the push-back) and its
 * stability measured (det K's sign, the critical points crossed).
 */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "mpm_kernel.h"
#include "mpm_static.h"

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
#define MPM_QS_PUSH 0.01  /* of the peak: an interface's load below minus this stops the run */
#define MPM_QS_LEDGER 1e-4 /* of the largest W_ext: W_ext - SE - W_coh beyond this stops the run */
#define MPM_QS_KICK 1e-4  /* of delta: the first grip increment that starts the softening     */
#define MPM_QS_DEEPCUT 0.125  /* a failed kick, or a dissipation increment whose Newton ran to its
                                 limit without cycling, is retried at this share of its size:
                                 at a snapback's peak a kick passes only near 1e-8 of delta, at
                                 a band's onset the dissipation step near 1e-6 of Dref         */

/* The path's states, from the control's flags (a kick is always under the dissipation's
 * mode; the first increment, before the linear branch is scaled, is linear). */
enum { PATH_LINEAR, PATH_KICK, PATH_DISSIPATION, PATH_GRIP, PATH_CUT };

static int path_state(const mpm_static *q)
{
  assert(!q->kick || q->mode == MPM_QS_DISSIPATION);
  if (q->kick)
    return PATH_KICK;
  if (q->mode == MPM_QS_DISSIPATION)
    return PATH_DISSIPATION;
  if (q->pinned)
    return PATH_CUT;
  return q->nel > 0 || q->s->step == 0 ? PATH_LINEAR : PATH_GRIP;
}

/* The softening particles that reach their strength within MPM_QS_KICK of the first
 * (scale k: the linear increment times k meets F = 0, eq. 23): the first grip increment
 * past the initiation, MPM_QS_KICK of delta, starts them all. */
static long tied_at_initiation(const mpm_static *q, double k)
{
  const mpm_sim *s = q->s;
  long n = 0;
  for (size_t c = 0; c < q->np; c++) {
    const mpm_material *m = &s->mat[s->p->mat[q->pid[c]]];
    if (m->model == MPM_DCOH_NONE)
      continue;
    const double se = mpm_dcoh_F(m, q->tst[c].sxx, q->tst[c].syy, q->tst[c].sxy, 0.0) + 1.0;
    n += se > 0.0 && 1.0 / se <= k * (1.0 + MPM_QS_KICK);
  }
  return n;
}

/* The linear first increment scaled to 1 / MPM_QS_NEL of the first initiation (F = 0,
 * eq. 23); the grip's step is set to the rest's share.  Where more particles than a cell
 * holds reach their strength together (a uniform stress without a flaw) the uniform state
 * bifurcates there, every band is a branch and the uniform softening one is unstable (fig6
 * without its flaw followed it to D = 13 U0 H): q->tie counts them, the linear branch is
 * run to the tie and the run stops there (tie_stop). */
static void scale_to_initiation(mpm_static *q)
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
  q->tie = tied > s->sc.ppc ? tied : 0;
  for (int pi = 0; pi < q->npair; pi++) { /* the interface's ties */
    const mpm_dstate *o = &q->ptr[pi];
    const double se = mpm_dcoh_F(&q->imat, o->sxx, o->syy, o->sxy, 0.0) + 1.0;
    if (se > 0.0)
      kmin = fmin(kmin, 1.0 / se);
  }
  if (!(kmin > 1.0) || !isfinite(kmin)) {
    q->tie = 0; /* no equal steps to a tie */
    return;
  }
  double k = kmin * (1.0 - 1e-12) / MPM_QS_NEL;
  if (q->dt * k > s->sc.end_delta) { /* the run ends first: the linear state at its end */
    k = s->sc.end_delta / q->dt;
    q->tie = 0;
  }
  for (size_t i = 0; i < 2 * q->nslot; i++)
    if (q->eq[i] >= 0)
      q->Ut[i] *= k;
  q->dt *= k;
  q->step_d = q->dt;
  q->nel = MPM_QS_NEL - 1;
  mpm_static_eval(q, 1);
}

/* The uniform state's tie met (scale_to_initiation): MPM_ESTALL and how to choose the
 * branch, after the linear branch's rows up to it. */
static mpm_status tie_stop(const mpm_static *q, char *err, size_t errlen)
{
  snprintf(err, errlen, "static solver: %ld softening particles reach their strength together at delta = %.9g, "
           "increment %ld: the uniform state bifurcates there (each band is a branch, the uniform softening is "
           "unstable); give the bar a flaw to choose the branch (imperfection.snf_factor below 1) or use "
           "decohesion.path = interface", q->tie, q->dn, q->s->step);
  return MPM_ESTALL;
}

/* The committed state's stability: the sign of det K (the tangent with the grip held, the
 * stiffness under displacement control; its factors are the predictor's), 0 where it is
 * not the state's: on a cut bar before its part is pinned (K holds no vertical rigid
 * motion) and at a tie, points on the softening path that dissipated only rounding (C at
 * most MPM_QS_CMIN, C answering delta: which of them K softens is rounding's).  Where the
 * sign changed since the last state that had one, the critical point crossed: across a
 * tie a bifurcation (every tied point's opening is a branch); else a limit point of delta
 * where the sign of det K pden did not change (pden = d C / d delta along the path turns
 * with delta; det K pden is the bordered system's), or, where C does not answer delta on
 * either side (pden 0), where delta's way turned; else a bifurcation. */
static void stability(mpm_static *q)
{
  const int tie = !(q->Cn > MPM_QS_CMIN * q->Dref) && q->pden != 0.0;
  const int sign = q->have_pred && !(q->s->cut && !q->pinned) && !tie ? mpm_lin_det_sign(q->lin) : 0;
  const int x = sign * ((q->pden > 0.0) - (q->pden < 0.0)), dir = q->dlast > 0.0 ? 1 : -1;
  q->st.det_sign = sign;
  q->st.crit = 0;
  q->wtie |= tie;
  if (sign == 0)
    return;
  if (q->wsign == -sign) {
    const int limit = q->wtie ? 0 : q->xsign != 0 && x != 0 ? x == q->xsign : dir != q->wdir;
    q->st.crit = limit ? MPM_QS_LIMIT : MPM_QS_BIFURCATION;
  }
  q->wsign = sign;
  q->xsign = x;
  q->wdir = dir;
  q->wtie = 0;
}

/* 1 if the trial increment's chord turns more than MPM_QS_TURN from the last one's and
 * the step can still be halved. */
static int turns(const mpm_static *q)
{
  const mpm_sim *s = q->s;
  if (s->step < MPM_QS_NEL || !(q->pk_d > 0.0) || !(s->P_peak > 0.0))
    return 0;
  const double ax = q->ch_d, ay = q->ch_P, bx = (q->dt - q->dn) / q->pk_d, by = (q->Pg - s->P_grip) / s->P_peak;
  /* past the peak with the load below 1 % of it on both ends: no corner a curve shows
   * (the load curve's judgement ends there, ver_curve_path) */
  if (fabs(s->P_grip) < 0.01 * s->P_peak && fabs(q->Pg) < 0.01 * s->P_peak)
    return 0;
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

/* A failed increment after iters Newton iterations: the current control's step halved,
 * or cut deeper (MPM_QS_DEEPCUT). */
static void shrink(mpm_static *q, int iters)
{
  q->st.cuts++;
  const int st = path_state(q);
  if (st == PATH_KICK) {
    q->kick_d *= MPM_QS_DEEPCUT;
  } else if (st == PATH_DISSIPATION) {
    q->step_D *= iters >= MPM_QS_MAXIT ? MPM_QS_DEEPCUT : 0.5;
    /* the grip leads where the step falls below 1e-9 of Dref, or below MPM_QS_RESUME of it
     * with the load under 1 % of the peak (the line's last dissipation, past the curve's
     * judged part: there Newton cycles on the smaller steps) */
    const double low = fabs(q->s->P_grip) < 0.01 * q->s->P_peak ? MPM_QS_RESUME : 1e-9;
    if (q->step_D < low * q->Dref)
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

/* One try of the current control's increment: 1 if its trial state converged and is to be
 * committed, 0 if the control changed or its step was halved (a kick starts the
 * softening, a corner is resolved, Newton failed). */
static int attempt(mpm_static *q, int *iters)
{
  const mpm_sim *s = q->s;
  int r = mpm_static_increment(q, iters);
  /* a kick starts the softening; one whose equilibrium lost half the load crossed a
   * snap (at a snapback's peak the only states past delta are the separated ones):
   * it is retried smaller */
  if (r == 1 && path_state(q) == PATH_KICK && q->Pg < 0.5 * s->P_grip)
    r = 0;
  if (r == -2) {
    /* C does not answer delta: nothing softens at the committed state (the initiation,
     * or a particle that stopped): a small grip increment starts it again; if that
     * does not, the grip leads to the end */
    if (q->nkick < 3) {
      q->kick = 1;
      /* a kick after a kick starts from the size that passed (at a snapback's peak
       * the first is cut from 1e-4 of delta to about 1e-8 before Newton finds a state) */
      q->kick_d = q->nkick > 0 ? q->kick_d : MPM_QS_KICK * q->dn;
    } else
      set_mode(q, MPM_QS_GRIP);
    return 0;
  }
  /* the kick and the linear branch are taken as they are */
  const int st = path_state(q), dis = st == PATH_DISSIPATION, grip = st == PATH_GRIP || st == PATH_CUT;
  if (r == 1 && (dis ? q->step_D > 1e-6 * q->Dref : grip && q->step_d > 1e-9 * s->sc.L) && turns(q)) {
    q->st.turns++;
    if (dis)
      q->step_D *= 0.5;
    else
      q->step_d *= 0.5;
    return 0;
  }
  if (r != 1)
    shrink(q, r == -3 ? MPM_QS_MAXIT : *iters); /* an untried predictor: cut as Newton's failure */
  return r == 1;
}

/* After a committed increment: a control that advances no more either hands over (the
 * grip to the dissipation, the line's last segments letting go, the bar separated) or
 * stops the run (MPM_ESTALL and the reason); *gone: segments let go. */
static mpm_status settle(mpm_static *q, int *gone, char *err, size_t errlen)
{
  mpm_sim *s = q->s;
  const int st = path_state(q);
  const int grip_stalls = ((st == PATH_GRIP || st == PATH_CUT) && q->step_d < 1e-9 * fmax(q->dn, 1e-300)) ||
                          q->st.increments >= MPM_QS_MAXINC;
  const int diss_stalls = (st == PATH_DISSIPATION || st == PATH_KICK) && stalls(q);
  *gone = 0;
  if (grip_stalls && q->st.increments < MPM_QS_MAXINC && resume(q)) {
    /* the grip could not pass a limit point */
  } else if ((diss_stalls || grip_stalls) && q->st.increments < MPM_QS_MAXINC && (*gone = let_go(q)) > 0) {
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
  return MPM_OK;
}

/* Commits the converged trial state and sets up the next increment: its control, its
 * predictor from this state's tangent, its size; the state's stability. */
static mpm_status accept(mpm_static *q, int iters, char *err, size_t errlen)
{
  mpm_sim *s = q->s;
  const int first = s->step == 0;
  if (first && q->mode == MPM_QS_GRIP)
    scale_to_initiation(q);
  const double Cprev = q->Cn;
  mpm_static_commit(q);
  int gone = 0;
  mpm_status ps = settle(q, &gone, err, errlen);
  if (ps == MPM_OK)
    ps = path_sound(q, err, errlen);
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
  if (mpm_static_predict(q) != MPM_OK)
    q->have_eval = 0;
  stability(q);
  q->st.increments++;
  q->st.mode = q->mode;
  next_step(q, iters, first);
  if (q->tie > 0 && q->nel == 0)
    q->st.crit = MPM_QS_TIE;
  return s->cut && !q->pinned ? pin(q, err, errlen) : MPM_OK;
}

mpm_status mpm_static_step(mpm_static *q, char *err, size_t errlen)
{
  if (q->tie > 0 && q->nel == 0)
    return tie_stop(q, err, errlen);
  for (;;) {
    for (int cut = 0; cut <= MPM_QS_MAXCUT; cut++) {
      int iters = 0;
      if (attempt(q, &iters))
        return accept(q, iters, err, errlen);
    }
    /* severing: no increment found near separation: the line's last segments let go,
     * the cut part is pinned, and the increment is tried again */
    if (!let_go(q))
      break;
    const mpm_status st = q->pinned ? MPM_OK : pin(q, err, errlen);
    if (st != MPM_OK)
      return st;
  }
  snprintf(err, errlen, "static solver: no equilibrium found after %d smaller increments at delta = %.9g (increment "
           "%ld, %s control)", MPM_QS_MAXCUT, q->dn, q->s->step + 1, q->mode == MPM_QS_GRIP ? "grip" : "dissipation");
  return MPM_ESTALL;
}
