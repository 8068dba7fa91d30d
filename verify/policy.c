/*
 * policy.c - the checks of `delam verify` (sweep.h) for each case (those across
 * cases: policy_cross.c): every check's class and tolerance, next to the reason for
 * it.  Pure: the input is the case's measured numbers and analytic bar, the output its
 * ver_check list and verdict; tests/test_ver_policy.c drives it with made-up cases.
 */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "metrics.h"
#include "sweep.h"

/* Analytic end displacement where lambda reaches the separation threshold. */
static double sep_ref(const ver_case *c)
{
  return ver_sep_ref(&c->ana, c->vs.sc.sep_threshold);
}

static ver_check *add_check(ver_case *c, const char *name, double measured, double reference, int rel)
{
  assert(c->nchk < VER_NCHECK);
  ver_check *k = &c->chk[c->nchk++];
  memset(k, 0, sizeof *k);
  k->name = name;
  k->measured = measured;
  k->reference = reference;
  k->rel = rel;
  k->cls = VER_CLASS_PASS;
  k->lim_lo = -INFINITY;
  k->lim_hi = INFINITY;
  return k;
}

static void known(ver_check *k, double lo, double hi)
{
  k->cls = VER_CLASS_KNOWN;
  k->lim_lo = lo;
  k->lim_hi = hi;
}

/*
 * The checks of one case, each with its class and tolerance, and why.
 *
 * Classes come from the physics of the scene, decided before looking at a run:
 *  - alpha = 90 (Fig. 6): the band lies along a grid line, one cell wide; the
 *    paper's curves agree with the analytic ones.  Every check is pass-class.
 *  - alpha != 90 (Figs. 7, 8, a45, a30): the band spreads over about two cells
 *    (paper, Fig. 7 discussion), so it dissipates more than U0 per area, softens more
 *    gently, separates later and takes more external work: D, W_ext, delta_sep, the
 *    softening slope and the curve error are known-limit, bounded by what a band up to
 *    ~3 cells wide can do (D <= 4 D_sep, separation before 4 x delta_sep, ...).  Band
 *    width is known-limit (reference: 1 cell; the paper sees ~2).
 *  - analytic snapback (g below its limit: fig8, a45, a30): the explicit method cannot
 *    follow the load reversal; the softening slope is then negative where the
 *    analytic one is positive (known-limit).
 *  - Le = particle with several particles per cell (docs/model.md sec. 6): the strain is
 *    uniform along x inside a cell, so all sqrt(ppc) sub-columns of the band cell soften
 *    together, each with Le = h / sqrt(ppc): the band dissipates sqrt(ppc) x U0 per area.
 *    This case measures that choice; D, W_ext, delta_sep, softening and curve error are
 *    known-limit, bounded by sqrt(ppc) x the analytic value (+10 %).
 *  - an inclined band run with the band method (two velocity fields once the band has
 *    cut the bar, Le = staircase: the narrowest band that can open on the grid) must
 *    dissipate U0 x area: D_final is pass-class within 10 % at one particle per cell.
 *    With several particles per cell, particles beside the band soften part-way before
 *    the cut and add 0.2-0.5 U0 x area (measured, docs/methods.md): known-limit up to
 *    +60 %.  With Le = row (the zone's Le measured per particle row, docs/methods.md)
 *    that partial softening is charged within the zone's width: D is pass-class within
 *    10 % at every ppc.  Its other inclined checks keep their classes.
 *  - the crack angle is the principal axis of the separated particles (lambda at or
 *    past the separation threshold), within 5 deg of alpha.  Known-limit to
 *    30 deg with four cells or fewer across the bar, and to 20 deg with several
 *    particles per cell, where the band turns toward the cell columns (fig7 h 4, 4 ppc:
 *    70.5 deg against 60).
 *  - decohesion.path = interface: no particle softens, the line dissipates U0 per unit
 *    area at every angle: D_final is pass-class inclined too.
 *  - peak load, elastic slope and energy balance are pass-class everywhere.
 */

/* What decides a case's classes (see above). */
typedef struct {
  int a90;      /* plane along a grid line (alpha = 90)             */
  int snap;     /* analytic snapback                                */
  int lep;      /* Le = particle with several particles per cell    */
  int ppc1;     /* one particle per cell                            */
  double nside; /* sqrt(ppc)                                        */
  int band;     /* inclined, with two fields and Le = staircase, row or zone */
  int row;      /* ... Le = row: the zone measured, at every ppc      */
  int iface;    /* decohesion.path = interface: no particle softens   */
} case_class;

/* the run itself */
static void check_run(ver_case *c)
{
  ver_check *k;
  k = add_check(c, "run", c->complete ? 1.0 : 0.0, 1.0, 0);
  k->tol = 0;
  snprintf(k->note, sizeof k->note, "the run reached its stop rule with finite state%s%.150s",
           c->error[0] ? ": " : "", c->error[0] ? c->error : "");
}

/* peak load and elastic slope */
static void check_peak_elastic(ver_case *c, const case_class *q)
{
  const ana_bar *a = &c->ana;
  const mpm_scene *sc = &c->vs.sc;
  const int ppc1 = q->ppc1;
  ver_check *k;
  /* one particle per cell samples the stress at the cell centre only; the peak is
   * reached a little early (paper, Fig. 6c: 4 per cell clearly better than 1) */
  /* the interface at 90 deg: its model's exact peak at the run's grip speed, which is
   * the quasi-static one plus the load the grip adds while the plane's unloading travels
   * to it (+1.6 % at the paper's 0.001; ana_wave.c) */
  /* (the static solver has no grip speed: its reference is the quasi-static bar) */
  const int wave = sc->path == MPM_PATH_IFACE && isfinite(c->wave_peak) && sc->solver != MPM_SOLVER_STATIC;
  k = add_check(c, "peak_P", c->peak_P, wave ? c->wave_peak : a->Pmax, 1);
  k->tol = ppc1 ? 0.03 : 0.01;
  if (wave)
    snprintf(k->note, sizeof k->note, "peak grip load vs the exact solution's at grip speed %g (Pmax = r0 H %g, "
             "eq. 30, plus the grip's load during the unloading wave's transit); tol %g %% (ppc %d)", sc->speed,
             a->Pmax, 100 * k->tol, sc->ppc);
  else
    snprintf(k->note, sizeof k->note, "peak grip load vs Pmax = r0 H (eq. 30); tol %g %% (ppc %d)", 100 * k->tol,
             sc->ppc);

  k = add_check(c, "k_elastic", c->k_elastic, a->k_elastic, 1);
  k->tol = 0.01;
  snprintf(k->note, sizeof k->note, "least-squares dP/ddelta for 0.1-0.6 peak vs E H / L");
}

/* softening slope */
static void check_softening(ver_case *c, const case_class *q)
{
  const ana_bar *a = &c->ana;
  const int a90 = q->a90;
  const int snap = q->snap;
  const int lep = q->lep;
  const int ppc1 = q->ppc1;
  ver_check *k;
  /* eq. 36 is the slope of q = 1's straight branch; for q other than 1 the branch is
   * curved and a straight fit over 0.8-0.2 of the peak has no closed-form partner (the
   * curve itself is judged by curve_path) */
  if (a->p.q != 1.0)
    return;
  k = add_check(c, "k_soft", c->k_soft, a->k_soft_peak, 1);
  k->tol = ppc1 ? 0.10 : 0.05;
  if (snap) {
    known(k, -INFINITY, -1.0); /* measured slope negative where the analytic one is positive */
    snprintf(k->note, sizeof k->note, "fit over 0.8-0.2 peak after the peak vs eq. 36; analytic snapback "
             "(g = %.3g): explicit runs cannot follow it, so known-limit if negative", a->g);
  } else if (!a90 || lep) {
    known(k, 0.0, 1.0); /* softer (less steep) but still softening */
    snprintf(k->note, sizeof k->note, "fit over 0.8-0.2 peak after the peak vs eq. 36; %s: known-limit if "
             "softer but negative", lep ? "Le = particle doubles the band's compliance" : "inclined band is wider");
  } else
    snprintf(k->note, sizeof k->note, "fit over 0.8-0.2 peak after the peak vs eq. 36");
}

/* where the bar separated */
static void check_separation(ver_case *c, const case_class *q)
{
  const mpm_scene *sc = &c->vs.sc;
  const int a90 = q->a90;
  const int lep = q->lep;
  const int ppc1 = q->ppc1;
  const double nside = q->nside;
  ver_check *k;
  /* The run detects separation when the load averaged over 4 L / c falls below
   * sep_load x peak and reports the window's centre: about half a window (0.011 in
   * delta at the paper's speed, 3 % of fig6's 0.375) after the drop.  The analytic
   * reference is where lambda reaches the separation threshold (eqs. 31, 34), which is
   * delta_sep itself for a threshold of 1. */
  /* Where the bar snaps back (g < 1) that delta lies on the branch behind the peak,
   * which a grip that only moves forward cannot reach: the reference is then the
   * peak's delta (ver_curve_end), where such a bar lets go. */
  /* (the static solver follows the branch back: its reference is the branch's own end) */
  const double dref = sc->solver == MPM_SOLVER_STATIC ? sep_ref(c) : ver_curve_end(&c->ana, sc->sep_threshold);
  k = add_check(c, "delta_sep", c->delta_sep, dref, 1);
  k->tol = ppc1 ? 0.06 : 0.04;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 3.0);
  snprintf(k->note, sizeof k->note, "detected separation vs analytic delta at lambda = %g%s (%.4g)",
           sc->sep_threshold, dref > sep_ref(c) ? " or, snapback, at the peak" : "", dref);
}

/* dissipation, external work, energy balance */
static void check_energy(ver_case *c, const case_class *q)
{
  const ana_bar *a = &c->ana;
  const int a90 = q->a90;
  const int lep = q->lep;
  const double nside = q->nside;
  ver_check *k;
  /* the interface (no particle softens) dissipates U0 per unit area of its line once
   * every segment has opened, at every angle (fig7, fig8, a45, a30: D / U0 area 1.000,
   * docs/methods.md): pass-class like alpha = 90, so a law off by a few % fails there too */
  k = add_check(c, "D_final", c->D_final, a->D_sep, 1);
  k->tol = q->band ? 0.10 : 0.02;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90 && !q->band && !q->iface)
    known(k, -k->tol, 3.0);
  else if (q->band && !q->ppc1 && !q->row)
    known(k, -k->tol, 0.6); /* measured: partial softening beside the band, docs/methods.md */
  snprintf(k->note, sizeof k->note, "dissipation at the end vs UD x area = %.4g%s", a->D_sep,
           !a90 && !lep && !q->iface ? " (inclined band: more, paper Fig. 7)" : "");

  /* W_ext also holds the kinetic and elastic energy still in the bar at the end, and
   * what the ledger booked on the way (W_booked: the scheme's own loss, the damper's,
   * the head's, ...; docs/verification.md): the work is compared with UF x area plus
   * that, so this check judges where the model put the work; the scheme's own share is
   * judged below (scheme_loss).  The inclined bound is the dissipation bound (4 D_sep):
   * the work ends up dissipated, and where the traction is dropped at separation (or an
   * unfollowed snapback releases stored energy) it is not the analytic UF per area that
   * the work is compared with. */
  k = add_check(c, "W_ext_final", c->W_ext_final, a->W_sep + c->W_booked, 1);
  k->tol = 0.03;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 4.0 * a->D_sep / a->W_sep - 1.0);
  snprintf(k->note, sizeof k->note, "external work at the end vs UF x area = %.4g plus the booked losses %.4g",
           a->W_sep, c->W_booked);

  /* What the discretisation itself took by the end (L_bc + L_flip + L_scheme, booked by
   * the ledger), over W_ext: the part of W_booked the W_ext check above lets pass, judged
   * here on its own, with the energy tolerance.  The damper's (L_damp: a file's damped
   * release), the loading head's (W_head), the contact's and the debris' are the scene's
   * own and not counted.
   * USL at one particle per cell with softening particles at 90 deg (fig6.ini, the
   * paper's method; inclined, its one field couples the cut parts, docs/methods.md):
   * the crack's velocity jump lies inside one cell's stencil, where one particle a side
   * cannot carry it; the nodes there hold what the particles do not, and each step loses
   * it, half in the projection (L_flip), half in the integration (L_scheme).  The steps
   * grow as 1 / h, and the loss with them: of W_ext, 0.0008, 0.0027, 0.0115, 0.0206 by
   * separation at h 8, 4, 2, 1, and after it the grip pulls the loose part through those
   * nodes (under 2 % of the peak: load_after_sep) at the same cost: 0.0009, 0.0042,
   * 0.018, 0.031 at the end (0.2 past separation).  At 4 and 9 ppc at most 0.0008.
   * Known-limit to 0.05, above h 1's 0.031: it grows as h falls, so a finer grid, a
   * longer run past separation or a lossier step can pass that bound and fail. */
  if (isfinite(c->W_scheme) && c->W_ext_final > 0.0) {
    k = add_check(c, "scheme_loss", c->W_scheme / c->W_ext_final, 0.0, 0);
    k->tol = VER_ENERGY_TOL;
    const int usl1 = a90 && q->ppc1 && c->vs.sc.scheme == MPM_SCHEME_USL && c->vs.sc.path != MPM_PATH_IFACE;
    if (usl1)
      known(k, 0.0, 0.05);
    snprintf(k->note, sizeof k->note, "the discretisation's own loss at the end (L_bc + L_flip + L_scheme = %.4g) "
             "over W_ext%s", c->W_scheme, usl1 ? "; USL, 1 ppc, a band: the crack's jump inside one cell's stencil "
             "is lost each step, growing as h falls: known-limit to 0.05" : "");
  }

  /* Inclined scenes: after the band has failed, the single-valued velocity of a cell
   * still couples the two parts (the paper, Fig. 8 discussion: separation "not as clean",
   * stresses built up until the separation is a cell wide); a load of a few % of the peak
   * persists and its work is not all accounted for.  Known-limit up to 15 %. */
  k = add_check(c, "energy_residual", c->energy_residual, 0.0, 0);
  k->tol = VER_ENERGY_TOL;
  if (!a90)
    known(k, 0.0, 0.15);
  snprintf(k->note, sizeof k->note, "max |W_ext + E0 - KE - SE - W_coh - booked| / max W_ext over the rows%s%s",
           c->var.whole ? ", the whole run to the scene's end_delta" : "",
           a90 ? "" : " (inclined: residual load after the band fails, known-limit to 0.15)");
  /* The whole run (V_WHOLE): also the plain balance, no losses booked.  With the USL
   * ledger the booked residual closes to rounding by construction; what the run lost to
   * the boundary treatment and the FLIP projection is only seen here. */
  if (c->var.whole) {
    /* grid.bc = lagrangian (fig6.ini's, docs/findings.md): the held nodes' treatment lets
     * the grip keep working after separation; the work is booked (L_flip, L_scheme) but
     * not in the bar: measured fig6 h 8, 1 ppc to delta 5, unbooked 0.033 and W_ext
     * +3.5 % (consistent: 0.00097 and +0.3 %).  Known-limit to 5 % with that bc. */
    const int lag = c->vs.sc.bc == MPM_BC_LAGRANGIAN;
    k = add_check(c, "energy_unbooked", c->energy_unbooked, 0.0, 0);
    k->tol = VER_ENERGY_TOL;
    if (lag)
      known(k, 0.0, 0.05);
    snprintf(k->note, sizeof k->note, "max |W_ext + E0 - KE - SE - W_coh| / max W_ext over the whole run to "
             "end_delta %.4g (nothing booked)%s", c->end_delta, lag ? "; grid.bc = lagrangian: known-limit to 0.05" : "");
    k = NULL;
    for (int i = 0; i < c->nchk; i++)
      if (!strcmp(c->chk[i].name, "W_ext_final"))
        k = &c->chk[i];
    if (k && lag && a90)
      known(k, -k->tol, 0.05);
  }
}

/* band width and crack angle: the separated particles */
static void check_band_angle(ver_case *c, const case_class *q)
{
  const mpm_scene *sc = &c->vs.sc;
  const int a90 = q->a90;
  const int ppc1 = q->ppc1;
  ver_check *k;
  k = add_check(c, "band_width", c->band_width, 1.0, 0);
  k->tol = 0.5;
  if (!a90)
    known(k, -0.5, 2.0);
  snprintf(k->note, sizeof k->note, "cells: (particles with lambda > 0.5) x h^2/ppc / (H / sin a) / h; "
           "projected extent %.3g cells, %zu particles", c->band_extent, c->band_count);

  /* the separated particles (lambda >= the separation threshold) along a line within
   * 5 deg of alpha (1 deg at 90).  A staircase of cells through a fixed grid
   * approximates the line; the coarser the grid the larger the deviation it can show */
  k = add_check(c, "crack_angle", c->angle, sc->alpha_deg, 0);
  k->measured = c->angle;
  k->tol = a90 ? 1.0 : 5.0;
  /* four cells or fewer across the bar (fig7 at h 8: the GCI's coarse grid): a band of
   * whole cells through four rows resolves its angle to about atan(1/4) = 14 deg, more
   * than the tolerance (measured: fig7 h 8 ppc 1, 70.7 against 60) */
  const int coarse = !a90 && sc->H / sc->h <= 4.0 + 1e-9;
  /* several particles per cell: the band turns toward the cell columns (fig7 h 4,
   * 4 ppc: 70.5 against 60; rows' centroids 68.7 at h 2, docs/findings.md) */
  const int turns = !a90 && !ppc1;
  if (coarse)
    known(k, -30.0, 30.0);
  else if (turns)
    known(k, -20.0, 20.0);
  /* decohesion.path = line holds the band within w of the line at alpha: the check then
   * measures the band's tilt inside that strip, not where the crack chose to run */
  char strip[96] = "";
  if (sc->path == MPM_PATH_LINE)
    snprintf(strip, sizeof strip, "; path = line: held within %.3g of the line, its tilt inside",
             mpm_scene_path_halfwidth(sc));
  snprintf(k->note, sizeof k->note, "principal axis of the separated particles' x0, y0 (lambda >= %g) vs alpha (deg)%s%s",
           sc->sep_threshold,
           coarse ? "; <= 4 cells across the bar: known-limit to 30 deg"
                  : turns ? "; several particles per cell: the band turns toward the cell columns, known-limit to 20 deg"
                          : "", strip);
}

/* band width, crack angle, curve error */
static void check_band(ver_case *c, const case_class *q)
{
  const ana_bar *a = &c->ana;
  const mpm_scene *sc = &c->vs.sc;
  const int a90 = q->a90;
  const int snap = q->snap;
  const int lep = q->lep;
  const int ppc1 = q->ppc1;
  ver_check *k;
  /* decohesion.path = interface: no particle softens, the crack is the line at alpha
   * through the flaw by construction; band width and angle have nothing to measure */
  if (sc->path != MPM_PATH_IFACE)
    check_band_angle(c, q);
  if (sc->solver == MPM_SOLVER_STATIC && isfinite(c->curve_path)) {
    /* the static solver's curve is a sequence of equilibrium states: judged as a path in
     * (delta / delta_peak, P / Pmax), which a snapback's reversal does not break */
    k = add_check(c, "curve_path", c->curve_path, 0.0, 0);
    k->tol = a90 ? VER_PATH_TOL_90 : VER_PATH_TOL_INCLINED;
    snprintf(k->note, sizeof k->note, "RMS distance of the curve from the analytic path in (delta / delta_peak, "
             "P / Pmax), to the load's fall below 1 %% of Pmax");
    k = add_check(c, "delta_5", c->delta5, 0.0, 0);
    k->tol = 0.05;
    snprintf(k->note, sizeof k->note, "where the load falls to 5 %% of Pmax after the peak, less the analytic "
             "branch's delta there, over delta_peak (a snapback moves back to it)");
  }
  if (sc->solver == MPM_SOLVER_STATIC && snap)
    return; /* P(delta) has two values on a snapback: curve_path judges the path */
  k = add_check(c, "curve_l2", c->curve_l2, 0.0, 0);
  k->tol = ppc1 ? VER_CURVE_TOL_PPC1 : VER_CURVE_TOL;
  if (!a90 || lep || snap)
    known(k, 0.0, 0.35);
  snprintf(k->note, sizeof k->note, "RMS of P - P_ana(delta) / Pmax over rows up to lambda = %g or the peak "
           "(delta %.4g)", sc->sep_threshold, ver_curve_end(a, sc->sep_threshold));
  /* the interface at 90 deg is the model the exact solution at the grip speed solves
   * (ana_wave: a cohesive plane in an elastic bar): the run must follow it, ringing and
   * all, within 1 % of the peak (RMS).  The band method is another model there (every
   * particle may soften, and the overshoot softens the whole bar a little), so it is
   * not judged by it.  Measured: 0.0040-0.0073 (iface90.ini, h 8-1, 1, 4 and 9 ppc); the
   * quasi-static curve itself is 0.0157 from it at the paper's speed 0.001. */
  if (sc->path == MPM_PATH_IFACE && isfinite(c->curve_wave) && sc->solver != MPM_SOLVER_STATIC) {
    k = add_check(c, "curve_wave", c->curve_wave, 0.0, 0);
    k->tol = VER_WAVE_TOL;
    snprintf(k->note, sizeof k->note, "RMS of P - P_wave(delta) / Pmax, the exact 1-D solution at grip speed %g "
             "(the plane at x %g), over the same rows", sc->speed, sc->imp_x);
  }

  /* once separated the grip carries under 2 % of the peak, at every load
   * row from VER_LOAD_SETTLE past separation on (the release's ringing has that long
   * to pass): the mean is not enough, a separated part ringing at +-40 % averages to
   * nothing.  One velocity field on an inclined band couples the parts after the cut
   * (the paper's method: a plateau near a third of the peak at fig8 h 8,
   * docs/methods.md): known-limit to 60 %.  A
   * separation threshold below 1 drops the traction still left, 1 - threshold of the
   * strength, at once: the bar rings with up to that share of the peak (fig6 h 8, 4 ppc,
   * threshold 0.8: 19 %; at the paper's 0.98, fig6 h 2, 4 ppc: 1.97 %): known-limit to
   * the tolerance plus 1 - threshold. */
  if (isfinite(c->delta_sep)) {
    k = add_check(c, "load_after_sep", c->P_after, 0.0, 0);
    k->tol = 0.02;
    const int one = !a90 && sc->fields != MPM_FIELDS_TWO;
    const double drop = 1.0 - sc->sep_threshold;
    if (one || drop > 0.0)
      known(k, 0.0, fmax(one ? 0.6 : 0.0, k->tol + drop));
    /* the sign says which: tension is a band still carrying, compression the separated
     * parts pushed together (fig8: the sliding part meets the other, docs/findings.md) */
    snprintf(k->note, sizeof k->note, "largest |P| / peak from delta_sep + %g to the end (tension %.2g, compression %.2g)%s%s",
             VER_LOAD_SETTLE, c->P_after_t, c->P_after_c, one ? "; one field: known-limit to 0.6" : "",
             drop > 0.0 ? "; traction left at separation dropped: known-limit to tol + 1 - threshold" : "");
  }
}

/* Judges every check (angles mod 180) and sets the case's verdict. */
static void judge_all(ver_case *c)
{
  /* the angle of a line is defined mod 180: judge the wrapped difference */
  for (int i = 0; i < c->nchk; i++) {
    ver_check *q = &c->chk[i];
    if (!c->have_ana && strcmp(q->name, "run")) {
      q->measured = NAN;
      snprintf(q->note, sizeof q->note, "no analytic reference for this scene");
    }
    ver_check_judge(q);
    if (!strcmp(q->name, "crack_angle") && isfinite(q->measured)) {
      q->error = ver_angle_diff(q->measured, q->reference);
      q->verdict = fabs(q->error) <= q->tol ? VER_PASS
                   : q->cls == VER_CLASS_KNOWN && q->error >= q->lim_lo && q->error <= q->lim_hi ? VER_KNOWN
                                                                                               : VER_FAIL;
    }
  }
  c->verdict = VER_PASS;
  for (int i = 0; i < c->nchk; i++) {
    if (c->chk[i].verdict == VER_FAIL)
      c->verdict = VER_FAIL;
    else if (c->chk[i].verdict == VER_KNOWN && c->verdict == VER_PASS)
      c->verdict = VER_KNOWN;
  }
}

void ver_policy_case(ver_case *c)
{
  const mpm_scene *sc = &c->vs.sc;
  const int a90 = ver_case_a90(c);
  const case_class q = {a90, c->ana.snapback, sc->le_mode == MPM_LE_PARTICLE && sc->ppc > 1, sc->ppc == 1,
                        sqrt((double)sc->ppc),
                        !a90 && sc->fields == MPM_FIELDS_TWO &&
                            (sc->le_mode == MPM_LE_STAIRCASE || sc->le_mode == MPM_LE_ROW ||
                             sc->le_mode == MPM_LE_ZONE),
                        sc->le_mode == MPM_LE_ROW || sc->le_mode == MPM_LE_ZONE, sc->path == MPM_PATH_IFACE};
  c->nchk = 0;
  if (c->refused[0]) {
    /* a case the static solver refuses by design (docs/static.md, "What it refuses") is
     * not run: one known-limit check saying so, not a failure */
    ver_check *k = add_check(c, "static_refused", 1.0, 0.0, 0);
    known(k, 1.0, 1.0);
    snprintf(k->note, sizeof k->note, "%.250s", c->refused);
    ver_check_judge(k);
    c->verdict = k->verdict;
    return;
  }
  check_run(c);
  check_peak_elastic(c, &q);
  check_softening(c, &q);
  check_separation(c, &q);
  check_energy(c, &q);
  check_band(c, &q);
  judge_all(c);
}

void ver_policy_drop(ver_case *c, const char *name)
{
  int m = 0;
  for (int i = 0; i < c->nchk; i++)
    if (strcmp(c->chk[i].name, name))
      c->chk[m++] = c->chk[i];
  c->nchk = m;
  judge_all(c);
}
