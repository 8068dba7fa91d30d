/*
 * verify_checks.c - the pure measuring helpers of `delam verify` (verify.h): line
 * fits, the softening slope, band width and angle of the decohered particles, the
 * observed order of convergence, spreads, the load-deflection error norm, and the
 * verdict of one check.  No I/O and no state: tests drive them with synthetic data.
 */
#include <math.h>
#include <stddef.h>

#include "verify.h"

#define PI 3.14159265358979323846

const char *ver_verdict_name(int verdict)
{
  switch (verdict) {
  case VER_PASS: return "pass";
  case VER_KNOWN: return "known-limit";
  default: return "fail";
  }
}

void ver_check_judge(ver_check *c)
{
  if (c->rel)
    c->error = c->reference != 0.0 ? (c->measured - c->reference) / fabs(c->reference) : NAN;
  else
    c->error = c->measured - c->reference;
  if (!isfinite(c->error))
    c->verdict = VER_FAIL;
  else if (fabs(c->error) <= c->tol)
    c->verdict = VER_PASS;
  else if (c->cls == VER_CLASS_KNOWN && c->error >= c->lim_lo && c->error <= c->lim_hi)
    c->verdict = VER_KNOWN;
  else
    c->verdict = VER_FAIL;
}

int ver_fit_line(const double *x, const double *y, size_t n, double *slope, double *icpt)
{
  if (n < 2)
    return -1;
  /* centred sums: better conditioned than the raw normal equations */
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; i++) {
    mx += x[i];
    my += y[i];
  }
  mx /= (double)n;
  my /= (double)n;
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; i++) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 0))
    return -1;
  *slope = sxy / sxx;
  if (icpt)
    *icpt = my - *slope * mx;
  return 0;
}

double ver_softening_slope(const double *delta, const double *P, size_t n, double hi_frac, double lo_frac)
{
  size_t ipk = 0;
  for (size_t i = 1; i < n; i++)
    if (P[i] > P[ipk])
      ipk = i;
  if (n == 0 || !(P[ipk] > 0))
    return NAN;
  const double peak = P[ipk];
  /* accumulate the centred fit in one pass over the qualifying rows */
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  size_t m = 0;
  for (size_t i = ipk + 1; i < n; i++) {
    if (P[i] < lo_frac * peak)
      break;
    if (P[i] > hi_frac * peak)
      continue;
    sx += delta[i];
    sy += P[i];
    sxx += delta[i] * delta[i];
    sxy += delta[i] * P[i];
    m++;
  }
  if (m < 3)
    return NAN;
  const double dm = (double)m, den = dm * sxx - sx * sx;
  return den > 0 ? (dm * sxy - sx * sy) / den : NAN;
}

double ver_band_width(const double *x0, const double *y0, const double *lam, size_t n, double thr,
                      double alpha_deg, double h, int ppc, double H, double *extent, size_t *count)
{
  const double a = alpha_deg * PI / 180.0, nx = sin(a), ny = -cos(a);
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

double ver_crack_angle(const double *x0, const double *y0, const double *lam, size_t n, double thr)
{
  double mx = 0, my = 0;
  size_t c = 0;
  for (size_t i = 0; i < n; i++)
    if (lam[i] > thr) {
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
    if (lam[i] > thr) {
      const double dx = x0[i] - mx, dy = y0[i] - my;
      sxx += dx * dx;
      syy += dy * dy;
      sxy += dx * dy;
    }
  /* principal axis of the scatter matrix: tan 2 theta = 2 sxy / (sxx - syy) */
  if (sxy == 0.0 && sxx == syy)
    return NAN;
  double th = 0.5 * atan2(2.0 * sxy, sxx - syy) * 180.0 / PI;
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

double ver_conv_order(const double *h, const double *e, size_t n)
{
  double lx[64], ly[64];
  if (n < 2 || n > 64)
    return NAN;
  for (size_t i = 0; i < n; i++) {
    if (!(h[i] > 0) || !(e[i] > 0) || !isfinite(e[i]))
      return NAN;
    lx[i] = log(h[i]);
    ly[i] = log(e[i]);
  }
  double p;
  return ver_fit_line(lx, ly, n, &p, NULL) == 0 ? p : NAN;
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

double ver_curve_l2(const double *delta, const double *P, size_t n, double delta_end, double scale,
                    double (*ref)(const void *ctx, double delta), const void *ctx)
{
  double s = 0;
  size_t m = 0;
  for (size_t i = 0; i < n; i++) {
    if (!(delta[i] > 0) || delta[i] > delta_end)
      continue;
    const double prev = i > 0 ? delta[i - 1] : 0.0, mid = 0.5 * (prev + delta[i]);
    const double d = P[i] - ref(ctx, mid);
    s += d * d;
    m++;
  }
  return m ? sqrt(s / (double)m) / scale : NAN;
}
