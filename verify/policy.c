/*
 * policy.c - the checks of `delam verify` (sweep.h): for each case and across cases,
 * every check's class and tolerance, next to the reason for it.  Pure: the input is
 * the case's measured numbers and analytic bar, the output its ver_check list and
 * verdict; tests/test_ver_policy.c drives it with made-up cases.
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
 *    the cut and add 0.2-0.5 U0 x area (measured, docs/bands.md): known-limit up to
 *    +60 %.  The crack angle keeps the inclined 10 deg: on h 4 the staircase of a 60 deg
 *    band over 8 cell rows measures 69-71 deg with every method.  Its other inclined
 *    checks keep their classes.
 *  - peak load, elastic slope, energy balance and crack angle are pass-class everywhere.
 */
/* Curve errors below this fraction of Pmax are at the loading-rate floor. */
#define VER_CURVE_FLOOR 0.02
/* |D - UD area| / UD area below this at every h (a quarter of D_final's 2 % tolerance):
 * the order of D is not measurable (fig6 at 1 ppc: 0.04 to 0.1 %). */
#define VER_D_FLOOR 0.005

/* What decides a case's classes (see above). */
typedef struct {
  int a90;      /* plane along a grid line (alpha = 90)             */
  int snap;     /* analytic snapback                                */
  int lep;      /* Le = particle with several particles per cell    */
  int ppc1;     /* one particle per cell                            */
  double nside; /* sqrt(ppc)                                        */
  int band;     /* inclined, with two fields and Le = staircase      */
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
  k = add_check(c, "peak_P", c->peak_P, a->Pmax, 1);
  k->tol = ppc1 ? 0.03 : 0.01;
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
  const double dref = sep_ref(c);
  k = add_check(c, "delta_sep", c->delta_sep, dref, 1);
  k->tol = ppc1 ? 0.06 : 0.04;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 3.0);
  snprintf(k->note, sizeof k->note, "detected separation vs analytic delta at lambda = %g (%.4g)",
           sc->sep_threshold, dref);
}

/* dissipation, external work, energy balance */
static void check_energy(ver_case *c, const case_class *q)
{
  const ana_bar *a = &c->ana;
  const int a90 = q->a90;
  const int lep = q->lep;
  const double nside = q->nside;
  ver_check *k;
  k = add_check(c, "D_final", c->D_final, a->D_sep, 1);
  k->tol = q->band ? 0.10 : 0.02;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90 && !q->band)
    known(k, -k->tol, 3.0);
  else if (q->band && !q->ppc1)
    known(k, -k->tol, 0.6); /* measured: partial softening beside the band, docs/bands.md */
  snprintf(k->note, sizeof k->note, "dissipation at the end vs UD x area = %.4g%s", a->D_sep,
           !a90 && !lep ? " (inclined band: more, paper Fig. 7)" : "");

  /* W_ext also holds the kinetic and elastic energy still in the bar at the end.  The
   * inclined bound is the dissipation bound (4 D_sep): the work ends up dissipated, and
   * where the traction is dropped at separation (or an unfollowed snapback releases
   * stored energy) it is not the analytic UF per area that the work is compared with. */
  k = add_check(c, "W_ext_final", c->W_ext_final, a->W_sep, 1);
  k->tol = 0.03;
  if (lep)
    known(k, -k->tol, 1.1 * nside - 1.0);
  else if (!a90)
    known(k, -k->tol, 4.0 * a->D_sep / a->W_sep - 1.0);
  snprintf(k->note, sizeof k->note, "external work at the end vs UF x area = %.4g", a->W_sep);

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
    /* grid.bc = lagrangian (fig6.ini's, docs/energy.md): the held nodes' treatment lets
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
  k = add_check(c, "band_width", c->band_width, 1.0, 0);
  k->tol = 0.5;
  if (!a90)
    known(k, -0.5, 2.0);
  snprintf(k->note, sizeof k->note, "cells: (particles with lambda > 0.5) x h^2/ppc / (H / sin a) / h; "
           "projected extent %.3g cells, %zu particles", c->band_extent, c->band_count);

  /* a staircase of cells through a fixed grid approximates the line; the coarser the
   * grid the larger the deviation it can show */
  k = add_check(c, "crack_angle", c->angle, sc->alpha_deg, 0);
  k->measured = c->angle;
  k->tol = a90 ? 1.0 : 10.0;
  /* four cells or fewer across the bar (fig7 at h 8: the GCI's coarse grid): a band of
   * whole cells through four rows resolves its angle to about atan(1/4) = 14 deg, more
   * than the tolerance (measured: fig7 h 8 ppc 1, 70.7 against 60) */
  const int coarse = !a90 && sc->H / sc->h <= 4.0 + 1e-9;
  if (coarse)
    known(k, -30.0, 30.0);
  snprintf(k->note, sizeof k->note, "principal axis of the decohered particles' x0, y0 vs alpha (deg)%s",
           coarse ? "; <= 4 cells across the bar: known-limit to 30 deg" : "");

  k = add_check(c, "curve_l2", c->curve_l2, 0.0, 0);
  k->tol = ppc1 ? 0.04 : 0.03;
  if (!a90 || lep || snap)
    known(k, 0.0, 0.35);
  snprintf(k->note, sizeof k->note, "RMS of P - P_ana(delta) / Pmax over rows up to lambda = %g or the peak "
           "(delta %.4g)", sc->sep_threshold, ver_curve_end(a, sc->sep_threshold));
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
                        !a90 && sc->fields == MPM_FIELDS_TWO && sc->le_mode == MPM_LE_STAIRCASE};
  c->nchk = 0;
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

/* ------------------------------------------------------------------ across cases */

static int cross_add(ver_cross *x, int *nx, const char *name, const char *scene, const char *over, double fixed)
{
  for (int i = 0; i < *nx; i++)
    if (!strcmp(x[i].name, name) && !strcmp(x[i].scene, scene) && x[i].fixed == fixed)
      return i;
  if (*nx == VER_MAXCROSS)
    return -1;
  ver_cross *g = &x[(*nx)++];
  memset(g, 0, sizeof *g);
  snprintf(g->name, sizeof g->name, "%s", name);
  snprintf(g->scene, sizeof g->scene, "%s", scene);
  snprintf(g->over, sizeof g->over, "%s", over);
  g->fixed = fixed;
  return *nx - 1;
}

/*
 * Energy invariance: the spread (max - min) / mean of D_final over h (ppc fixed) and
 * over ppc (h fixed), per scene, scene-as-written cases only.  alpha = 90: pass-class,
 * 2 %.  Inclined: known-limit up to 50 % (the band's width in cells, hence its
 * dissipation, changes with the grid).
 *
 * Order of convergence: least-squares slope p of log(curve_l2) against log(h), per
 * scene and ppc.  Only the elastic branch is plain discretisation error; on the
 * softening branch the model is regularised by Le = h (the band is one cell whatever
 * h), and the error has a floor set by the ringing of a dynamic run at a finite
 * loading rate (its amplitude depends on the speed, not on h).  So no positive rate
 * is claimed: alpha = 90 is pass-class one-sided, p >= 0 (the error must not grow
 * under refinement).  Inclined: the band never becomes a sharp line, known-limit for
 * p >= -1 (the error not growing faster than 1/h).
 */
/*
 * Grid Convergence Index (Roache; metrics.h ver_gci) of the inclined scenes, which have
 * no closed form in 2-D: per scene and ppc, the finest three scene-as-written cases at
 * h, 2 h, 4 h, on peak_P, D_final and delta_sep.  Sensible p: in [0.5, 2] (2: uGIMP's
 * order on smooth fields, the most a grid can be credited with; below 0.5 the three
 * values do not show convergence) with monotone convergence, then Fs 1.25, else Fs 3.
 * Pass: monotone convergence and GCI_12 <= 2 % (the tolerance of the alpha = 90 checks
 * against the closed form).  Known-limit class (the band's dissipation and its
 * separation change with the grid: Le = one cell; docs/bands.md): GCI up to 1.
 */
static int policy_gci(const ver_case *cs, int n, ver_cross *x, int room)
{
  static const char *qname[3] = {"gci_peak_P", "gci_D_final", "gci_delta_sep"};
  static const char *yname[3] = {"peak_P", "D_final", "delta_sep"};
  int m = 0;
  for (int i = 0; i < n; i++) {
    const ver_case *a = &cs[i], *b = NULL, *c = NULL;
    if (a->var.set || !a->complete || ver_case_a90(a))
      continue;
    int finest = 1; /* a is the finest h of its scene and ppc with 2 h and 4 h present */
    for (int j = 0; j < n; j++) {
      const ver_case *o = &cs[j];
      if (o->var.set || !o->complete || strcmp(o->scene, a->scene) || o->ppc != a->ppc)
        continue;
      if (fabs(o->h - 2.0 * a->h) < 1e-9 * a->h)
        b = o;
      else if (fabs(o->h - 4.0 * a->h) < 1e-9 * a->h)
        c = o;
      else if (o->h < a->h && fabs(2.0 * o->h - a->h) < 1e-9 * a->h)
        finest = 0;
    }
    if (!b || !c || !finest)
      continue;
    for (int t = 0; t < 3 && m < room; t++) {
      ver_cross *g = &x[m++];
      memset(g, 0, sizeof *g);
      snprintf(g->name, sizeof g->name, "%s", qname[t]);
      snprintf(g->scene, sizeof g->scene, "%s", a->scene);
      snprintf(g->over, sizeof g->over, "h");
      snprintf(g->yname, sizeof g->yname, "%s", yname[t]);
      g->fixed = a->ppc;
      const ver_case *abc[3] = {a, b, c};
      for (int j = 0; j < 3; j++) {
        g->x[j] = abc[j]->h;
        g->y[j] = t == 0 ? abc[j]->peak_P : t == 1 ? abc[j]->D_final : abc[j]->delta_sep;
        snprintf(g->ids[j], sizeof g->ids[0], "%s", abc[j]->id);
      }
      g->n = 3;
      ver_gci_result r;
      ver_gci(g->y[0], g->y[1], g->y[2], 2.0, 0.5, 2.0, &r);
      ver_check *k = &g->chk;
      k->name = qname[t];
      k->measured = r.gci12;
      k->reference = 0.0;
      k->tol = 0.02;
      k->cls = VER_CLASS_KNOWN;
      k->lim_lo = 0.0;
      k->lim_hi = 1.0;
      snprintf(k->note, sizeof k->note, "GCI_12 of %s at h %g (ratio 2, ppc %d): conv %.3g, p %.3g (%s, used %.3g), "
               "Fs %g, GCI_23 %.3g, GCI_23 / (2^p GCI_12) %.3g", yname[t], a->h, a->ppc, r.conv, r.p,
               r.sensible ? "sensible" : "not sensible", r.p_used, r.fs, r.gci23, r.asym);
      ver_check_judge(k);
      if (k->verdict == VER_PASS && !(r.conv > 0.0 && r.conv < 1.0))
        k->verdict = VER_KNOWN; /* small but not converging: no estimate */
    }
  }
  return m;
}

/* One order check: p of y ~ x^p over the group's points, pass when p >= lo. */
static void order_check(ver_cross *g, const char *name, double lo, const char *what)
{
  ver_check *k = &g->chk;
  memset(k, 0, sizeof *k);
  k->name = name;
  k->measured = ver_conv_order(g->x, g->y, (size_t)g->n, NULL);
  k->reference = lo;
  k->tol = 0.0;
  k->cls = VER_CLASS_PASS;
  k->lim_lo = -INFINITY;
  k->lim_hi = INFINITY;
  ver_check_judge(k);
  if (isfinite(k->error) && k->error >= 0.0)
    k->verdict = VER_PASS; /* one-sided: p >= lo */
  snprintf(k->note, sizeof k->note, "observed order p of %.140s; one-sided: pass if p >= %g", what, lo);
}

/*
 * The loading rate as a discretisation parameter (docs/verification.md).  The closed form
 * is the limit v -> 0; at a fixed grip speed the rate error does not fall with h and the
 * fixed-speed order_h mixes both.  Per alpha = 90 scene and ppc:
 *  - order_rate_h_curve_l2, order_rate_h_D: curve_l2 and |D - UD area| / UD area against h
 *    with the speed refined with h (v = v_file h / h_file: the cases whose variant has
 *    halved the speed k times at h = h_file / 2^k), three h or more;
 *  - order_rate_v_curve_l2: curve_l2 against v at the finest h with three speeds.
 * Pass: p >= 0.7 (first order expected in both, METHODS: 0.8 and 1 measured at 4 ppc;
 * 0.7 leaves room for the oscillation whose phase moves with v).
 */
static int policy_rate(const ver_case *cs, int n, ver_cross *x, int room)
{
  int m = 0;
  for (int i = 0; i < n && m + 3 <= room; i++) {
    const ver_case *a = &cs[i];
    if (!a->complete || !a->have_ana || !ver_case_a90(a) || a->var.set || a->h != a->vs.file_h)
      continue; /* a: the scene file's own h and speed */
    ver_cross hc, hd, vc;
    memset(&hc, 0, sizeof hc);
    memset(&vc, 0, sizeof vc);
    for (int j = 0; j < n; j++) {
      const ver_case *o = &cs[j];
      if (!o->complete || !o->have_ana || strcmp(o->scene, a->scene) || o->ppc != a->ppc ||
          (o->var.set && !o->var.slow))
        continue;
      if (fabs(o->h * (double)(1 << o->var.slow) - a->h) < 1e-9 * a->h && hc.n < 8) {
        hc.x[hc.n] = o->h;
        hc.y[hc.n] = o->curve_l2;
        snprintf(hc.ids[hc.n++], sizeof hc.ids[0], "%s", o->id);
      }
    }
    /* the speed study at the finest h that has three speeds */
    double hv = INFINITY;
    for (int j = 0; j < n; j++) {
      const ver_case *o = &cs[j];
      if (!o->complete || strcmp(o->scene, a->scene) || o->ppc != a->ppc || (o->var.set && !o->var.slow))
        continue;
      int ns = 0;
      for (int l = 0; l < n; l++)
        ns += cs[l].complete && !strcmp(cs[l].scene, a->scene) && cs[l].ppc == a->ppc && cs[l].h == o->h &&
              (!cs[l].var.set || cs[l].var.slow);
      if (ns >= 3 && o->h < hv)
        hv = o->h;
    }
    for (int j = 0; j < n && isfinite(hv); j++) {
      const ver_case *o = &cs[j];
      if (o->complete && !strcmp(o->scene, a->scene) && o->ppc == a->ppc && o->h == hv &&
          (!o->var.set || o->var.slow) && vc.n < 8) {
        vc.x[vc.n] = o->vs.sc.speed;
        vc.y[vc.n] = o->curve_l2;
        snprintf(vc.ids[vc.n++], sizeof vc.ids[0], "%s", o->id);
      }
    }
    hd = hc;
    for (int j = 0; j < hd.n; j++)
      for (int l = 0; l < n; l++)
        if (!strcmp(cs[l].id, hd.ids[j]))
          hd.y[j] = fabs(cs[l].D_final - cs[l].ana.D_sep) / cs[l].ana.D_sep;
    ver_cross *gs[3] = {&hc, &hd, &vc};
    static const char *names[3] = {"order_rate_h_curve_l2", "order_rate_h_D", "order_rate_v_curve_l2"};
    static const char *ynames[3] = {"curve_l2", "D_err", "curve_l2"};
    for (int t = 0; t < 3; t++) {
      if (gs[t]->n < 3)
        continue;
      ver_cross *g = &x[m++];
      *g = *gs[t];
      snprintf(g->name, sizeof g->name, "%s", names[t]);
      snprintf(g->scene, sizeof g->scene, "%s", a->scene);
      snprintf(g->over, sizeof g->over, "%s", t == 2 ? "speed" : "h");
      snprintf(g->yname, sizeof g->yname, "%s", ynames[t]);
      g->fixed = t == 2 ? hv : a->ppc;
      char what[160];
      if (t == 2)
        snprintf(what, sizeof what, "curve_l2 ~ v^p at h %g, ppc %d (the rate study)", hv, a->ppc);
      else
        snprintf(what, sizeof what, "%s ~ h^p, ppc %d, grip speed refined with h (v = %g h / %g)",
                 t ? "|D - UD area| / UD area" : "curve_l2", a->ppc, a->vs.sc.speed, a->h);
      order_check(g, names[t], 0.7, what);
      ver_check *k = &g->chk;
      double emax = 0.0, emin = INFINITY;
      for (int j = 0; j < g->n; j++) {
        emax = fmax(emax, g->y[j]);
        emin = fmin(emin, g->y[j]);
      }
      if (k->verdict == VER_FAIL && t == 1 && emax < VER_D_FLOOR) {
        /* D within VER_D_FLOOR of UD x area at every h: no order to measure */
        k->verdict = VER_KNOWN;
        snprintf(k->note, sizeof k->note, "observed order p of |D - UD area| / UD area ~ h^p, ppc %d, speed refined "
                 "with h; every error below %g (largest %.3g): not an order, known-limit", a->ppc, VER_D_FLOOR, emax);
      } else if (k->verdict == VER_FAIL && t == 2) {
        /* the slowest speed's error is the grid's floor at this h: the rate error is not
         * separable here (first order in v measured at h 1, 4 ppc: docs/verification.md) */
        k->verdict = VER_KNOWN;
        snprintf(k->note, sizeof k->note, "observed order p of curve_l2 ~ v^p at h %g, ppc %d (rate study): the "
                 "grid's error (%.3g at the slowest speed) dominates at this h; known-limit", hv, a->ppc, emin);
      }
    }
  }
  return m;
}

int ver_policy_cross(ver_case *cs, int n, ver_cross *x)
{
  int nx = 0;
  for (int i = 0; i < n; i++) {
    ver_case *c = &cs[i];
    if (c->var.set || !c->complete || !c->have_ana)
      continue;
    const char *names[3] = {"D_invariance_h", "D_invariance_ppc", "order_h"};
    const char *over[3] = {"h", "ppc", "h"};
    const double fixed[3] = {c->ppc, c->h, c->ppc};
    const double xv[3] = {c->h, c->ppc, c->h};
    const double yv[3] = {c->D_final, c->D_final, c->curve_l2};
    for (int t = 0; t < 3; t++) {
      const int gi = cross_add(x, &nx, names[t], c->scene, over[t], fixed[t]);
      if (gi < 0 || x[gi].n == 8)
        continue;
      ver_cross *g = &x[gi];
      g->x[g->n] = xv[t];
      g->y[g->n] = yv[t];
      snprintf(g->ids[g->n], sizeof g->ids[0], "%s", c->id);
      g->n++;
    }
    /* remember alpha = 90 in the group through the check's class below */
  }
  int m = 0;
  for (int i = 0; i < nx; i++) {
    ver_cross *g = &x[i];
    if (g->n < 2)
      continue;
    int a90 = 1;
    for (int j = 0; j < n; j++)
      if (!strcmp(cs[j].scene, g->scene))
        a90 = ver_case_a90(&cs[j]);
    ver_check *k = &g->chk;
    memset(k, 0, sizeof *k);
    k->lim_lo = -INFINITY;
    k->lim_hi = INFINITY;
    if (!strcmp(g->name, "order_h")) {
      k->name = "order_h";
      k->measured = ver_conv_order(g->x, g->y, (size_t)g->n, NULL);
      k->reference = 0.0;
      k->tol = 0.0;
      snprintf(k->note, sizeof k->note, "observed order p of curve_l2 ~ h^p (ppc %g) at the fixed grip speed "
               "(rate error not removed: see order_rate_*); one-sided: pass if p >= 0", g->fixed);
      ver_check_judge(k);
      if (isfinite(k->error) && k->error >= 0.0)
        k->verdict = VER_PASS; /* one-sided: any order >= 0 passes */
      /* An order is only meaningful while the discretisation error dominates.  Where
       * every error is already below VER_CURVE_FLOOR of Pmax (fig6 at 4 and 9 per cell:
       * about 1 %, the ringing of the quasi-static loading, which h does not reduce) the
       * check passes and says so, with the measured order kept. */
      double emax = 0.0;
      for (int j = 0; j < g->n; j++)
        emax = fmax(emax, g->y[j]);
      if (k->verdict != VER_PASS && emax < VER_CURVE_FLOOR) {
        k->verdict = VER_PASS;
        snprintf(k->note, sizeof k->note, "observed order p of curve_l2 ~ h^p (ppc %g, fixed grip speed); every error is below "
                 "the %g floor (largest %.3g), where the order is not meaningful", g->fixed, VER_CURVE_FLOOR, emax);
      }
      if (!a90) {
        k->cls = VER_CLASS_KNOWN;
        k->lim_lo = -1.0;
        if (isfinite(k->error) && k->verdict == VER_FAIL && k->error >= k->lim_lo)
          k->verdict = VER_KNOWN;
      }
    } else {
      k->name = strcmp(g->name, "D_invariance_h") ? "D_invariance_ppc" : "D_invariance_h";
      k->measured = ver_spread(g->y, (size_t)g->n);
      k->reference = 0.0;
      k->tol = 0.02;
      if (!a90) {
        k->cls = VER_CLASS_KNOWN;
        k->lim_lo = 0.0;
        k->lim_hi = 0.5;
      }
      snprintf(k->note, sizeof k->note, "(max - min) / mean of D_final over %s at %s %g", g->over,
               strcmp(g->over, "h") ? "h" : "ppc", g->fixed);
      ver_check_judge(k);
    }
    x[m++] = *g;
  }
  m += policy_gci(cs, n, x + m, VER_MAXCROSS - m);
  return m + policy_rate(cs, n, x + m, VER_MAXCROSS - m);
}

