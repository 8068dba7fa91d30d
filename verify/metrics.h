/*
 * metrics.h - every quantity verify/ measures from a run, defined once (prefix ver_):
 * `delam verify`, `delam report` and `delam bench` all call these, so the same case
 * gives the same number wherever it is printed.  Pure functions on arrays: no I/O,
 * no state; tests/test_ver_metrics.c drives them with hand-computed data.
 *
 * Line fits go through GSL (gsl_fit_linear).
 */
#ifndef DELAM_VER_METRICS_H
#define DELAM_VER_METRICS_H

#include <stddef.h>

#include "ana.h"

/* The fraction bands of the fits (one definition, see metrics.c). */
#define VER_ELASTIC_LO 0.1   /* elastic slope: rows with 0.1 .. 0.6 of the peak, before it */
#define VER_ELASTIC_HI 0.6
#define VER_SOFT_HI 0.8      /* softening slope: 0.8 .. 0.2 of the peak, after it */
#define VER_SOFT_LO 0.2
#define VER_BAND_LAMBDA 0.5  /* a particle belongs to the failed band past this lambda */

/* Least-squares line y = slope x + icpt (gsl_fit_linear); 0, or -1 if n < 2 or all x
 * are equal.  icpt may be NULL. */
int ver_fit_line(const double *x, const double *y, size_t n, double *slope, double *icpt);

/* Elastic slope dP/ddelta: least-squares line through the rows before delta_peak with
 * lo * peak <= P <= hi * peak.  Where fewer than 3 rows qualify, the secant from the last
 * row under lo * peak to the first over hi * peak (up to the peak's row): a rise that
 * crosses the band within a row or two; NaN if the rows do not cross it. */
double ver_elastic_slope(const double *delta, const double *P, size_t n, double peak, double delta_peak,
                         double lo, double hi);

/* Softening slope dP/ddelta: least-squares line through the rows after the (first)
 * largest P whose P lies in [lo_frac, hi_frac] * peak, up to the first row below
 * lo_frac * peak.  Where fewer than 3 rows qualify but the load does fall under the
 * window (a drop within a row or two), the secant from the last row above the window to
 * the first under it; NaN if the load never falls under it. */
double ver_softening_slope(const double *delta, const double *P, size_t n, double hi_frac, double lo_frac);

/* How far past the detected separation ver_load_after starts: 0.1 of delta, the scene
 * files' stop margin (100 time units at their grip speed 0.001, eight transits of the
 * bar's wave, 2 L / c = 12): time for the release after the cut to pass.
 * `delam verify` runs its cases 0.2 past separation so that the window holds rows. */
#define VER_LOAD_SETTLE 0.1

/* The load the grip still carries once the bar has separated at delta_sep: the largest
 * |P| over the rows with delta >= delta_sep + VER_LOAD_SETTLE, over peak; if no row
 * reaches it, the last row's |P| (what the run ended with).  NaN if delta_sep or peak is
 * not finite and positive, or n is 0.  tens and comp (either may be NULL) get the
 * largest tension (P > 0, a band still carrying) and the largest compression (-P, the
 * parts pushed together: a contact) over the same rows, each over peak, 0 if the load
 * never has that sign there, NaN where the return is. */
double ver_load_after(const double *delta, const double *P, size_t n, double delta_sep, double peak, double *tens,
                      double *comp);

/* Width in delta of the load drop: from the first row after the (first) largest P
 * below 0.9 of it to the first row below 0.1 of it.  NaN if the load never falls
 * below 0.1 of its peak. */
double ver_drop_width(const double *delta, const double *P, size_t n);

/* Band of particles with lambda > thr (reference positions x0, y0).  Returns its mean
 * width in cells: band area / (crack length * h), band area = count * h^2 / ppc,
 * crack length = H / sin(alpha) (the failure plane across a bar of height H).
 * *extent (if not NULL) gets the projected width in cells: (max - min of x0 . n) / h
 * + 1 / sqrt(ppc), n = (sin a, -cos a) (one cell's worth of particles counts as 1).
 * *count gets the number of particles in the band.  0 if no particle is past thr. */
double ver_band_width(const double *x0, const double *y0, const double *lam, size_t n, double thr,
                      double alpha_deg, double h, int ppc, double H, double *extent, size_t *count);

/* Angle in [0, 180) deg from the x-axis of the principal axis (total least squares
 * line) through the points with lambda >= thr.  NaN if fewer than 2 points or if the
 * points have no preferred direction. */
double ver_crack_angle(const double *x0, const double *y0, const double *lam, size_t n, double thr);

/* Share of the dissipation that lies outside the band: sum of min(lambda, 1) over the
 * particles with lambda <= thr, over the sum for all (particles of equal V and Le, as in
 * every scene).  0 if nothing decohered. */
double ver_diffuse_share(const double *lam, size_t n, double thr);

/* a - b for angles of lines (mod 180), in (-90, 90]. */
double ver_angle_diff(double a_deg, double b_deg);

/* Observed order p of e = C h^p: least-squares slope of log e against log h; *logc
 * (if not NULL) gets log C.  NaN if fewer than 2 distinct h or any e <= 0. */
double ver_conv_order(const double *h, const double *e, size_t n, double *logc);

/* Roache's Grid Convergence Index from three grids h, r h, r^2 h (r > 1) with values
 * f1 (finest), f2, f3.  conv = (f2 - f1) / (f3 - f2): in (0, 1) the values converge
 * monotonically, < 0 they oscillate, > 1 they diverge.  p = ln((f3 - f2) / (f2 - f1)) / ln r
 * (NaN unless conv > 0).  The p is sensible when 0 < conv < 1 and p_lo <= p <= p_hi:
 * then Fs = 1.25 and p is used; otherwise Fs = 3 and p is clamped to [p_lo, p_hi]
 * (p_lo when it is NaN).  gci12 = Fs |(f2 - f1) / f1| / (r^p - 1), gci23 the same on f2,
 * f3; asym = gci23 / (r^p gci12), about 1 in the asymptotic range. */
typedef struct {
  double conv, p, p_used, fs, gci12, gci23, asym;
  int sensible;
} ver_gci_result;
/* 0, or -1 (the result all NaN) if r <= 1, p_lo > p_hi, p_lo <= 0, f1 == 0 or f2 == 0,
 * or f2 == f1 to rounding (64 eps of the largest value: nothing to estimate; gci12 = 0 is
 * then set, and gci23 = 0 too when f3 ties as well; conv and p stay NaN). */
int ver_gci(double f1, double f2, double f3, double r, double p_lo, double p_hi, ver_gci_result *g);

/* The energy balance W_ext + E0 = KE + SE + W_coh + booked over n rows, E0 the energy
 * at the start (KE + SE) and booked the ledger's terms L_bc + L_flip + L_scheme + W_head
 * + L_contact + L_debris + L_damp (mpm.h): its largest miss over the larger of max |W_ext|
 * and E0.  The columns are e[0..10] = W_ext, KE, SE, W_coh, L_bc, L_flip, L_scheme,
 * W_head, L_contact, L_debris, L_damp; a
 * NULL ledger column counts as 0.  *raw (if not NULL) gets the miss without the booked terms.  0 if there is
 * no energy at all. */
/* The tolerance on it: verify's check and delam run's warning (over the whole run). */
#define VER_ENERGY_TOL 0.02
/* energy a run may make, KE + SE + W_coh above W_ext + E0, over the largest work: above it
 * the run stopped as unstable (legitimate runs stay below 1e-9: their booked losses sum
 * to >= 0) */
#define VER_CREATED_TOL 0.1
#define VER_ENERGY_COLS 11
double ver_energy_residual(const double *const e[VER_ENERGY_COLS], size_t n, double E0, double *raw);

/* The value of a column at an output row: v of the first row with delta >= at (up to a
 * relative 1e-9, so a delta taken from a row finds that row).  The dissipation at the
 * detected separation (summary.json's D_cut, `delam check`'s info line) is this with
 * at = delta_sep.  NaN if at is negative (no separation: delta_sep -1) or not finite,
 * or if no row reaches it. */
double ver_value_at(const double *delta, const double *v, size_t n, double at);

/* (max - min) / mean; NaN if n == 0 or the mean is 0. */
double ver_spread(const double *v, size_t n);

/* The load-curve error: root-mean-square of P_i - ref(delta_i) over rows with
 * 0 < delta_i <= delta_end, divided by scale.  Each row's P is the average over the
 * interval that ends at delta_i, so it is compared at the interval's midpoint; with
 * points (the static solver's rows, each an equilibrium state) at delta_i itself.
 * *maxdev (if not NULL) gets the largest |P_i - ref| / scale over the same rows.
 * NaN if no row qualifies. */
double ver_curve_l2(const double *delta, const double *P, size_t n, double delta_end, double scale,
                    double (*ref)(const void *ctx, double delta), const void *ctx, double *maxdev, int points);

/* The same against the analytic bar's load (ana_bar_load_at), to delta_end. */
double ver_curve_err_bar(const ana_bar *b, const double *delta, const double *P, size_t n, double delta_end,
                         double *maxdev, int points);

/* The distance of a run's curve from the analytic path, snapback included: in the plane
 * (delta / delta_peak, P / Pmax), the root-mean-square distance to the analytic curve
 * (elastic line, softening branch of eq. 34, then P = 0) of points spaced evenly along
 * the run's polyline from the origin to its first row past the peak with P <= 1 % of
 * Pmax.  *d5 (if not NULL) gets where the run's load first falls to 5 % of Pmax after
 * its peak, less the analytic branch's delta there, over delta_peak (NaN if it never
 * does).  NaN without rows; DBL_MAX where the distance is beyond the doubles.  Linear in
 * the rows whatever their values: a row longer than 4096 points is sampled at 4096, each
 * weighing for the points it stands for. */
double ver_curve_path(const ana_bar *b, const double *delta, const double *P, size_t n, double *d5);
/* The distance of a run's curve from another run's (the rate's error of an explicit run:
 * its distance from the static run at the same h and ppc): ver_curve_l2 of (delta, P)
 * against the reference rows (rd, rP) up to the first where rd moves back (a snapback),
 * linearly interpolated and from (0, 0) to their first row, to the smaller of delta_end
 * and the last of those rows' delta.  NaN without reference rows or rows to compare. */
double ver_curve_err_curve(const double *rd, const double *rP, size_t rn, const double *delta, const double *P,
                           size_t n, double delta_end, double scale);
/* curve_l2's bound in verify's check (policy.c) at one and at several particles per
 * cell (the grip speed's own error at the paper's speed is 0.0157 of them), and
 * curve_wave's, against the exact solution at the grip speed, which has no rate error. */
#define VER_CURVE_TOL_PPC1 0.04
#define VER_CURVE_TOL 0.03
#define VER_WAVE_TOL 0.01
/* ver_curve_path's bound in verify's check (policy.c), at alpha 90 and inclined. */
#define VER_PATH_TOL_90 0.005
#define VER_PATH_TOL_INCLINED 0.01

/* The same against the bar at the run's own grip speed (ana_wave: the 1-D wave solution
 * with the plane as a cohesive line xg from the grip; docs/verification.md "The exact
 * solution at the grip speed"), to delta_end.  NaN where that solution does not apply
 * (alpha other than 90, q other than 1, s0 other than snf) or cannot be built (larger than
 * its cap: ver_curve_wave_size says so).  *peak (if
 * not NULL) gets that solution's peak load, *rate (if not NULL) its own RMS distance
 * from the quasi-static bar over Pmax at the same rows: the rate's error at this speed,
 * the floor a run converging on it tends to against the quasi-static curve (NaN where it
 * does not apply). */
double ver_curve_err_wave(const ana_bar *b, double speed, double rho, double xg, double thr, const double *delta,
                          const double *P, size_t n, double delta_end, double *maxdev, double *peak, double *rate);

/* 2 with why where that solution applies but would be larger than analytic/ana.h's cap
 * (ANA_WAVE_MAX_SAMPLES: a large U0 or a slow grip puts its end far out), else 0. */
int ver_curve_wave_size(const ana_bar *b, double speed, double rho, double xg, double thr, double delta_end,
                        char *why, size_t len);

/* Where the curve error stops: the analytic end displacement at which lambda reaches the
 * separation threshold thr (eqs. 31, 34) - where the model is told to separate;
 * delta_sep itself for a threshold of 1. */
double ver_sep_ref(const ana_bar *b, double thr);

/* The end of the curve-error window: ver_sep_ref, or the analytic peak where that comes
 * first (a snapback bar, g below its limit, reaches lambda = 1 at a smaller delta than
 * its peak: the window then still holds the whole rising branch). */
double ver_curve_end(const ana_bar *b, double thr);

#endif
