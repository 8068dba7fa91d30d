/*
 * verify.h - `delam verify`: sweeps of the scenes over h and particles per cell,
 * each run checked against the closed-form bar (analytic/ana.h, MODEL.md sec. 5),
 * then cross-case checks (energy invariance over h and ppc, observed order of
 * convergence of the load-deflection curve).
 *
 * Two layers: pure helpers on arrays (verify_checks.c; unit-tested on synthetic data
 * with known answers) and the sweep itself (verify.c: case list, runs in child
 * processes, reading the per-case output files, verdicts, verify.json/verify.csv).
 *
 * Verdicts.  Every check has a class decided up front from the physics of its scene:
 * pass-class checks pass within their tolerance or fail; known-limit checks are the
 * deviations the paper itself reports (inclined bands dissipating more than U0 per
 * area, the softer softening slope, load reversal an explicit method cannot follow).
 * A known-limit check still passes inside its tolerance, is `known-limit` inside its
 * outer bounds (the direction and size the physics allows), and fails outside them.
 */
#ifndef DELAM_VERIFY_H
#define DELAM_VERIFY_H

#include <stddef.h>

enum { VER_CLASS_PASS = 0, VER_CLASS_KNOWN = 1 };
enum { VER_PASS = 0, VER_FAIL = 1, VER_KNOWN = 2 };

typedef struct {
  const char *name;      /* stable check id: "peak_P", "D_final", ...                   */
  double measured;       /* the run's number                                             */
  double reference;      /* the analytic (or expected) number                            */
  double error;          /* relative (measured - reference) / |reference| if rel, else measured - reference */
  int rel;               /* 1: error is relative                                         */
  double tol;            /* pass when |error| <= tol                                     */
  double lim_lo, lim_hi; /* known-limit class: error in [lim_lo, lim_hi] is known-limit  */
  int cls;               /* VER_CLASS_*                                                  */
  int verdict;           /* VER_PASS, VER_FAIL, VER_KNOWN                                */
  char note[200];        /* what is compared and why this class                          */
} ver_check;

/* Fills error from measured/reference and sets the verdict; a non-finite error fails. */
void ver_check_judge(ver_check *c);
const char *ver_verdict_name(int verdict);

/* ---- pure helpers (verify_checks.c) ---- */

/* Least-squares line y = slope x + icpt; 0, or -1 if n < 2 or all x equal. */
int ver_fit_line(const double *x, const double *y, size_t n, double *slope, double *icpt);

/* Softening slope dP/ddelta: least-squares line through the rows after the (first)
 * largest P whose P lies in [lo_frac, hi_frac] * peak, up to the first row below
 * lo_frac * peak.  NaN if fewer than 3 rows qualify. */
double ver_softening_slope(const double *delta, const double *P, size_t n, double hi_frac, double lo_frac);

/* Band of particles with lambda > thr (reference positions x0, y0).  Returns its mean
 * width in cells: band area / (crack length * h), band area = count * h^2 / ppc,
 * crack length = H / sin(alpha) (the failure plane across a bar of height H).
 * *extent (if not NULL) gets the projected width in cells: (max - min of x0 . n) / h
 * + 1 / sqrt(ppc), n = (sin a, -cos a) (one cell's worth of particles counts as 1).
 * *count gets the number of particles in the band.  0 if no particle is past thr. */
double ver_band_width(const double *x0, const double *y0, const double *lam, size_t n, double thr,
                      double alpha_deg, double h, int ppc, double H, double *extent, size_t *count);

/* Angle in [0, 180) deg from the x-axis of the principal axis (total least squares
 * line) through the points with lambda > thr.  NaN if fewer than 2 points or if the
 * points have no preferred direction. */
double ver_crack_angle(const double *x0, const double *y0, const double *lam, size_t n, double thr);

/* Share of the dissipation that lies outside the band: sum of min(lambda, 1) over the
 * particles with lambda <= thr, over the sum for all (particles of equal V and Le, as in
 * every scene).  The diffuse decohesion a peak's overshoot leaves in every particle
 * column (README, Fig. 6).  0 if nothing decohered. */
double ver_diffuse_share(const double *lam, size_t n, double thr);

/* a - b for angles of lines (mod 180), in (-90, 90]. */
double ver_angle_diff(double a_deg, double b_deg);

/* Observed order p of e = C h^p: least-squares slope of log e against log h.  NaN if
 * fewer than 2 distinct h or any e <= 0. */
double ver_conv_order(const double *h, const double *e, size_t n);

/* (max - min) / mean; NaN if n == 0 or the mean is 0. */
double ver_spread(const double *v, size_t n);

/* Root-mean-square of P_i - ref(delta_i) over rows with 0 < delta_i <= delta_end,
 * divided by scale.  Each row's P is the average over the interval that ends at
 * delta_i, so it is compared at the interval's midpoint.  NaN if no row qualifies. */
double ver_curve_l2(const double *delta, const double *P, size_t n, double delta_end, double scale,
                    double (*ref)(const void *ctx, double delta), const void *ctx);

/* ---- the sweep (verify.c) ---- */
typedef struct {
  int full;              /* 0: the --quick subset, 1: every scene x h x ppc               */
  int jobs;              /* parallel cases                                                */
  const char *outdir;    /* DIR: DIR/<case-id>/, DIR/verify.json, DIR/verify.csv         */
  const char *scenes;    /* folder of the scene files (data/scenes)                      */
  const char *self;      /* path of the delam program, for --list                        */
  int list;              /* 1: print one `delam run` line per case and stop               */
  int merge;             /* 1: do not run; check what DIR already holds                  */
  int merge_found;       /* with merge: the cases of either list whose folders DIR holds
                            (neither --quick nor --full given)                           */
} ver_verify_opts;

/* Runs (or lists, or merges) the sweep.  Returns 0 when no pass-class check failed,
 * 1 when one did, 2 on bad input (a scene that does not load, an unwritable DIR). */
int ver_verify(const ver_verify_opts *o);

#endif
