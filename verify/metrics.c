/*
 * metrics.c - the measured quantities of verify/ (metrics.h), each defined once.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_fit.h>

#include "metrics.h"


int ver_fit_line(const double *x, const double *y, size_t n, double *slope, double *icpt)
{
  if (n < 2)
    return -1;
  double sxx = 0, mx = 0;
  for (size_t i = 0; i < n; i++)
    mx += x[i];
  mx /= (double)n;
  for (size_t i = 0; i < n; i++)
    sxx += (x[i] - mx) * (x[i] - mx);
  if (!(sxx > 0))
    return -1;
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(x, 1, y, 1, n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  *slope = c1;
  if (icpt)
    *icpt = c0;
  return 0;
}

/* Fits the rows idx[0..m-1]; NaN if fewer than 3. */
static double fit_rows(const double *x, const double *y, const size_t *idx, size_t m)
{
  if (m < 3)
    return NAN;
  double *bx = malloc(2 * m * sizeof *bx), s = NAN;
  if (!bx)
    return NAN;
  for (size_t i = 0; i < m; i++) {
    bx[i] = x[idx[i]];
    bx[m + i] = y[idx[i]];
  }
  if (ver_fit_line(bx, bx + m, m, &s, NULL) != 0)
    s = NAN;
  free(bx);
  return s;
}

double ver_elastic_slope(const double *delta, const double *P, size_t n, double peak, double delta_peak,
                         double lo, double hi)
{
  size_t *idx = calloc(n + 1, sizeof *idx), m = 0;
  if (!idx)
    return NAN;
  for (size_t i = 0; i < n && delta[i] < delta_peak; i++)
    if (P[i] <= hi * peak && P[i] >= lo * peak)
      idx[m++] = i;
  double s = fit_rows(delta, P, idx, m);
  free(idx);
  /* a rise that crosses the band within too few rows to fit (a curve given at its
   * corners, the closed form's own): the secant from the last row under the band to the
   * first over it, the peak's row included */
  size_t under = n;
  for (size_t i = 0; !isfinite(s) && i < n && delta[i] <= delta_peak; i++)
    if (P[i] < lo * peak)
      under = i;
    else if (P[i] > hi * peak && under < n && delta[i] > delta[under])
      s = (P[i] - P[under]) / (delta[i] - delta[under]);
  return s;
}

/* Index of the first largest P; n if none is positive. */
static size_t peak_index(const double *P, size_t n)
{
  size_t ipk = 0;
  for (size_t i = 1; i < n; i++)
    if (P[i] > P[ipk])
      ipk = i;
  return n > 0 && P[ipk] > 0 ? ipk : n;
}

double ver_softening_slope(const double *delta, const double *P, size_t n, double hi_frac, double lo_frac)
{
  const size_t ipk = peak_index(P, n);
  if (ipk == n)
    return NAN;
  const double peak = P[ipk];
  size_t *idx = malloc((n + 1) * sizeof *idx), m = 0;
  if (!idx)
    return NAN;
  size_t above = ipk, below = n; /* the last row over the window, the first under it */
  for (size_t i = ipk + 1; i < n; i++) {
    if (P[i] < lo_frac * peak) {
      below = i;
      break;
    }
    if (P[i] <= hi_frac * peak)
      idx[m++] = i;
    else
      above = i;
  }
  double s = fit_rows(delta, P, idx, m);
  free(idx);
  /* a drop that crosses the window within too few rows to fit (a snapback's release): the
   * secant from the last row over the window to the first under it, the shallowest slope
   * the rows allow */
  if (!isfinite(s) && below < n && delta[below] > delta[above])
    s = (P[below] - P[above]) / (delta[below] - delta[above]);
  return s;
}

double ver_drop_width(const double *delta, const double *P, size_t n)
{
  const size_t ipk = peak_index(P, n);
  if (ipk == n)
    return NAN;
  double d90 = NAN;
  for (size_t i = ipk; i < n; i++) {
    if (isnan(d90) && P[i] < 0.9 * P[ipk])
      d90 = delta[i];
    if (P[i] < 0.1 * P[ipk])
      return delta[i] - d90;
  }
  return NAN;
}

double ver_band_width(const double *x0, const double *y0, const double *lam, size_t n, double thr,
                      double alpha_deg, double h, int ppc, double H, double *extent, size_t *count)
{
  const double a = alpha_deg * ANA_PI / 180.0, nx = sin(a), ny = -cos(a);
  double lo = INFINITY, hi = -INFINITY;
  size_t c = 0;
  for (size_t i = 0; i < n; i++) {
    if (!(lam[i] > thr))
      continue;
    const double s = x0[i] * nx + y0[i] * ny;
    lo = fmin(lo, s);
    hi = fmax(hi, s);
    c++;
  }
  if (count)
    *count = c;
  if (c == 0) {
    if (extent)
      *extent = 0;
    return 0;
  }
  if (extent)
    *extent = (hi - lo) / h + 1.0 / sqrt((double)ppc);
  const double area = (double)c * h * h / (double)ppc, len = H / fabs(sin(a));
  return area / (len * h);
}

double ver_diffuse_share(const double *lam, size_t n, double thr)
{
  double out = 0.0, all = 0.0;
  for (size_t i = 0; i < n; i++) {
    const double l = fmin(fmax(lam[i], 0.0), 1.0);
    all += l;
    if (!(lam[i] > thr))
      out += l;
  }
  return all > 0.0 ? out / all : 0.0;
}

double ver_load_after(const double *delta, const double *P, size_t n, double delta_sep, double peak, double *tens,
                      double *comp)
{
  if (tens)
    *tens = NAN;
  if (comp)
    *comp = NAN;
  if (!isfinite(delta_sep) || !isfinite(peak) || !(peak > 0.0) || n == 0)
    return NAN;
  const double from = delta_sep + VER_LOAD_SETTLE;
  double m = -1.0, t = 0.0, c = 0.0;
  for (size_t i = 0; i < n; i++)
    if (delta[i] >= from && isfinite(P[i])) {
      m = fmax(m, fabs(P[i]));
      t = fmax(t, P[i]);
      c = fmax(c, -P[i]);
    }
  if (m < 0.0) {
    m = fabs(P[n - 1]);
    t = fmax(P[n - 1], 0.0);
    c = fmax(-P[n - 1], 0.0);
  }
  if (tens)
    *tens = t / peak;
  if (comp)
    *comp = c / peak;
  return m / peak;
}

double ver_crack_angle(const double *x0, const double *y0, const double *lam, size_t n, double thr)
{
  double mx = 0, my = 0;
  size_t c = 0;
  for (size_t i = 0; i < n; i++)
    if (lam[i] >= thr) {
      mx += x0[i];
      my += y0[i];
      c++;
    }
  if (c < 2)
    return NAN;
  mx /= (double)c;
  my /= (double)c;
  double sxx = 0, syy = 0, sxy = 0;
  for (size_t i = 0; i < n; i++)
    if (lam[i] >= thr) {
      const double dx = x0[i] - mx, dy = y0[i] - my;
      sxx += dx * dx;
      syy += dy * dy;
      sxy += dx * dy;
    }
  /* principal axis of the scatter matrix: tan 2 theta = 2 sxy / (sxx - syy) */
  if (sxy == 0.0 && sxx == syy)
    return NAN;
  double th = 0.5 * atan2(2.0 * sxy, sxx - syy) * 180.0 / ANA_PI;
  if (th < 0)
    th += 180.0;
  if (th >= 180.0)
    th -= 180.0;
  return th;
}

double ver_angle_diff(double a_deg, double b_deg)
{
  double d = fmod(a_deg - b_deg, 180.0);
  if (d <= -90.0)
    d += 180.0;
  else if (d > 90.0)
    d -= 180.0;
  return d;
}

double ver_energy_residual(const double *const e[VER_ENERGY_COLS], size_t n, double E0, double *raw)
{
  double wmax = E0, res = 0.0, r0 = 0.0;
  for (size_t i = 0; i < n; i++)
    wmax = fmax(wmax, fabs(e[0][i]));
  for (size_t i = 0; i < n && wmax > 0; i++) {
    const double miss = e[0][i] + E0 - e[1][i] - e[2][i] - e[3][i];
    double left = miss; /* less each booked term in turn */
    for (int j = 4; j < VER_ENERGY_COLS; j++)
      left -= e[j] ? e[j][i] : 0.0;
    r0 = fmax(r0, fabs(miss) / wmax);
    res = fmax(res, fabs(left) / wmax);
  }
  if (raw)
    *raw = r0;
  return res;
}

int ver_gci(double f1, double f2, double f3, double r, double p_lo, double p_hi, ver_gci_result *g)
{
  g->conv = g->p = g->p_used = g->fs = g->gci12 = g->gci23 = g->asym = NAN;
  g->sensible = 0;
  if (!(r > 1.0) || !(p_lo > 0.0) || !(p_lo <= p_hi) || f1 == 0.0 || f2 == 0.0 || !isfinite(f1 + f2 + f3))
    return -1;
  /* the two finest agree to rounding (a quantity the method fixes exactly, such as the
   * interface's D = U0 area): nothing to estimate, and no order to read from noise */
  const double tie = 64.0 * DBL_EPSILON * fmax(fabs(f1), fmax(fabs(f2), fabs(f3)));
  if (fabs(f2 - f1) <= tie) {
    g->gci12 = 0.0;
    if (fabs(f3 - f2) <= tie)
      g->gci23 = 0.0;
    return -1;
  }
  g->conv = (f3 != f2) ? (f2 - f1) / (f3 - f2) : INFINITY;
  if (g->conv > 0.0 && isfinite(g->conv))
    g->p = log(1.0 / g->conv) / log(r);
  g->sensible = g->conv > 0.0 && g->conv < 1.0 && g->p >= p_lo && g->p <= p_hi;
  g->fs = g->sensible ? 1.25 : 3.0;
  g->p_used = isfinite(g->p) ? fmin(fmax(g->p, p_lo), p_hi) : p_lo;
  const double rp = pow(r, g->p_used);
  g->gci12 = g->fs * fabs((f2 - f1) / f1) / (rp - 1.0);
  g->gci23 = g->fs * fabs((f3 - f2) / f2) / (rp - 1.0);
  g->asym = g->gci12 > 0.0 ? g->gci23 / (rp * g->gci12) : NAN;
  return 0;
}

double ver_spread(const double *v, size_t n)
{
  if (n == 0)
    return NAN;
  double lo = v[0], hi = v[0], s = 0;
  for (size_t i = 0; i < n; i++) {
    lo = fmin(lo, v[i]);
    hi = fmax(hi, v[i]);
    s += v[i];
  }
  const double mean = s / (double)n;
  return mean != 0.0 ? (hi - lo) / fabs(mean) : NAN;
}

double ver_conv_order(const double *h, const double *e, size_t n, double *logc)
{
  double lx[64], ly[64], p, c;
  if (logc)
    *logc = NAN;
  if (n < 2 || n > 64)
    return NAN;
  for (size_t i = 0; i < n; i++) {
    if (!(h[i] > 0) || !(e[i] > 0) || !isfinite(e[i]))
      return NAN;
    lx[i] = log(h[i]);
    ly[i] = log(e[i]);
  }
  if (ver_fit_line(lx, ly, n, &p, &c) != 0)
    return NAN;
  if (logc)
    *logc = c;
  return p;
}

double ver_curve_l2(const double *delta, const double *P, size_t n, double delta_end, double scale,
                    double (*ref)(const void *ctx, double delta), const void *ctx, double *maxdev, int points)
{
  double s = 0, mx = 0;
  size_t m = 0;
  for (size_t i = 0; i < n; i++) {
    if (!(delta[i] > 0) || delta[i] > delta_end)
      continue;
    const double prev = i > 0 ? delta[i - 1] : 0.0, mid = points ? delta[i] : 0.5 * (prev + delta[i]);
    const double d = P[i] - ref(ctx, mid);
    s += d * d;
    mx = fmax(mx, fabs(d));
    m++;
  }
  if (maxdev)
    *maxdev = m ? mx / scale : NAN;
  return m ? sqrt(s / (double)m) / scale : NAN;
}

static double bar_load(const void *ctx, double delta)
{
  return ana_bar_load_at(ctx, delta);
}

double ver_curve_err_bar(const ana_bar *b, const double *delta, const double *P, size_t n, double delta_end,
                         double *maxdev, int points)
{
  return ver_curve_l2(delta, P, n, delta_end, b->Pmax, bar_load, b, maxdev, points);
}

typedef struct {
  const double *d, *P;
  size_t n;
} ref_rows;

/* The reference rows' load at delta: linear between rows, from (0, 0) to the first.  The
 * rows' delta never falls (ver_curve_err_curve stops them at a snapback), so the row is
 * found by bisection: the curve error stays linear in the rows (times their log). */
static double rows_load(const void *ctx, double delta)
{
  const ref_rows *q = ctx;
  if (q->n == 0)
    return 0.0;
  if (delta <= q->d[0]) {
    const double w = q->d[0] > 0.0 ? delta / q->d[0] : 1.0;
    return w * q->P[0];
  }
  if (!(delta <= q->d[q->n - 1]))
    return q->P[q->n - 1];
  size_t lo = 0, hi = q->n - 1; /* d[lo] < delta <= d[hi] */
  while (hi - lo > 1) {
    const size_t mid = lo + (hi - lo) / 2;
    if (delta <= q->d[mid])
      hi = mid;
    else
      lo = mid;
  }
  const double w = q->d[hi] > q->d[lo] ? (delta - q->d[lo]) / (q->d[hi] - q->d[lo]) : 1.0;
  return q->P[lo] + w * (q->P[hi] - q->P[lo]);
}

double ver_curve_err_curve(const double *rd, const double *rP, size_t rn, const double *delta, const double *P,
                           size_t n, double delta_end, double scale)
{
  if (rn == 0)
    return NAN;
  size_t m = 1;
  while (m < rn && rd[m] >= rd[m - 1])
    m++;
  const ref_rows q = {rd, rP, m};
  return ver_curve_l2(delta, P, n, fmin(delta_end, rd[m - 1]), scale, rows_load, &q, NULL, 0);
}

static double wave_load(const void *ctx, double delta)
{
  return ana_wave_load_at(ctx, delta);
}

/* The wave solution is built a percent past the window, so that its last row has a
 * sample beyond it. */
#define WAVE_PAST 1.01

int ver_curve_wave_size(const ana_bar *b, double speed, double rho, double xg, double thr, double delta_end,
                        char *why, size_t len)
{
  const ana_wave_params wp = {speed, rho, xg, thr};
  long n;
  char e[300];
  if (ana_wave_size(b, &wp, delta_end * WAVE_PAST, &n, e, sizeof e) != ANA_ERANGE)
    return 0;
  snprintf(why, len, "%s", e);
  return 2;
}

/* The exact solution's own RMS distance from the quasi-static bar over Pmax, taken at
 * the rows' midpoints as ver_curve_l2 takes a run's rows: the rate's error, the least a
 * run converging on that solution can show against the quasi-static curve. */
static double wave_rate(const ana_bar *b, const ana_wave *w, const double *delta, size_t n, double delta_end)
{
  double s = 0.0;
  size_t m = 0;
  for (size_t i = 0; i < n; i++) {
    if (!(delta[i] > 0) || delta[i] > delta_end)
      continue;
    const double mid = 0.5 * ((i > 0 ? delta[i - 1] : 0.0) + delta[i]);
    const double d = ana_wave_load_at(w, mid) - ana_bar_load_at(b, mid);
    s += d * d;
    m++;
  }
  return m ? sqrt(s / (double)m) / b->Pmax : NAN;
}

double ver_curve_err_wave(const ana_bar *b, double speed, double rho, double xg, double thr, const double *delta,
                          const double *P, size_t n, double delta_end, double *maxdev, double *peak, double *rate)
{
  const ana_wave_params wp = {speed, rho, xg, thr};
  ana_wave w;
  if (maxdev)
    *maxdev = NAN;
  if (peak)
    *peak = NAN;
  if (rate)
    *rate = NAN;
  if (ana_wave_init(b, &wp, delta_end * WAVE_PAST, &w, NULL, 0) != ANA_OK)
    return NAN;
  if (peak)
    *peak = ana_wave_peak(&w, NULL);
  if (rate)
    *rate = wave_rate(b, &w, delta, n, delta_end);
  const double e = ver_curve_l2(delta, P, n, delta_end, b->Pmax, wave_load, &w, maxdev, 0);
  ana_wave_free(&w);
  return e;
}

double ver_sep_ref(const ana_bar *b, double thr)
{
  double d = b->delta_sep, P;
  if (thr < 1.0)
    ana_bar_softening_point(b, 1.0 - pow(thr, b->p.q), &d, &P);
  return d;
}

double ver_curve_end(const ana_bar *b, double thr)
{
  return fmax(ver_sep_ref(b, thr), b->delta_peak);
}

double ver_value_at(const double *delta, const double *v, size_t n, double at)
{
  if (!isfinite(at) || at < 0.0)
    return NAN;
  const double tol = 1e-9 * fmax(1.0, fabs(at));
  for (size_t i = 0; i < n; i++)
    if (delta[i] >= at - tol)
      return v[i];
  return NAN;
}
