/*
 * ana.c - closed-form uniaxial bar with decohesion (Schreyer, Sulsky, Zhou 2002,
 * sec. 3.2, eqs. 28-37; docs/model.md sec. 5).
 *
 * Geometry (eq. 28): n = (sin a, -cos a), t = (cos a, sin a), uniaxial stress
 * sigma = P / H along x, so sn = sigma sin^2 a, st = sigma sin a cos a and se = sigma / r0
 * (eqs. 29, 30).  The softening branch is written in lambda in [0, 1] (eq. 31:
 * sigma* = 1 - lambda^q), in which load and opening are smooth: P = Pmax (1 - lambda^q),
 * delta = (r0 L / E) (sigma* + lambda g) (eq. 34); the public functions speak sigma*
 * (lambda = (1 - sigma*)^(1/q), exact).  Model 2's energies (not in the paper): the
 * Model 1 ones times kappa (ana_bar_init).
 * GSL: qags for ana_bar_work, brent where a displacement is inverted to sigma*; GSL's
 * error handler is switched off around the calls (not thread-safe against other GSL
 * users in the process).
 */
#include "ana.h"

#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

/* Fine lambda grid used to place curve points at equal (normalised) arc length. */
#define ANA_ARC_GRID 4096

enum { HIT_ELASTIC = 0, HIT_SOFT = 1, HIT_SEPARATED = 2 };

void ana_params_default(ana_params *p)
{
  p->alpha_deg = 90.0;
  p->snf = 1.0;
  p->stf = 10.0;
  p->U0 = 0.375;
  p->s0 = 1.0;
  p->q = 1.0;
  p->E = 1024.0;
  p->nu = 0.25;
  p->L = 192.0;
  p->H = 32.0;
  p->model = 1;
}

static int pos_ok(double v) { return isfinite(v) && v > 0.0; }

static int fail(char *err, int errlen, const char *msg, const char *name, double v)
{
  if (err && errlen > 0)
    snprintf(err, (size_t)errlen, msg, name, v);
  return ANA_EINVAL;
}

static int check_params(const ana_params *p, char *err, int errlen)
{
  if (!(isfinite(p->alpha_deg) && p->alpha_deg > 0.0 && p->alpha_deg <= 90.0))
    return fail(err, errlen, "%s = %g is out of range: allowed (0, 90] deg", "alpha", p->alpha_deg);
  const struct {
    const char *name;
    double v;
  } pos[] = {{"snf", p->snf}, {"stf", p->stf}, {"U0", p->U0}, {"s0", p->s0},
             {"q", p->q},     {"E", p->E},     {"L", p->L},   {"H", p->H}};
  for (size_t i = 0; i < sizeof pos / sizeof pos[0]; i++)
    if (!pos_ok(pos[i].v))
      return fail(err, errlen, "%s = %g is out of range: allowed finite and > 0", pos[i].name, pos[i].v);
  if (!(isfinite(p->nu) && p->nu > -1.0 && p->nu <= 0.5))
    return fail(err, errlen, "%s = %g is out of range: allowed (-1, 0.5]", "nu", p->nu);
  if (p->model != 1 && p->model != 2)
    return fail(err, errlen, "%s = %g is out of range: allowed 1 (associated) or 2 (opening only)",
                "model", (double)p->model);
  return ANA_OK;
}

/* sigma* where the softening branch reverses direction in delta (d delta / d sigma* = 0,
 * i.e. Phat = g in eq. 36), if that happens strictly inside (0, 1).  Phat(sigma*) =
 * q (1 - sigma*)^(1 - 1/q) = g  <=>  sigma* = 1 - (g/q)^(q/(q-1)). */
static int interior_turn(double q, double g, double *st)
{
  if (q == 1.0)
    return 0;
  const double s = 1.0 - pow(g / q, q / (q - 1.0));
  if (!(s > 0.0 && s < 1.0))
    return 0;
  *st = s;
  return 1;
}

int ana_bar_init(const ana_params *p, ana_bar *bar, char *err, int errlen)
{
  const int rc = check_params(p, err, errlen);
  if (rc != ANA_OK)
    return rc;
  if (err && errlen > 0)
    err[0] = '\0';

  bar->p = *p;
  const double a = p->alpha_deg * ANA_PI / 180.0;
  /* exact at 90 deg so that Model 2 coincides with Model 1 to the last bit */
  const double sa = p->alpha_deg == 90.0 ? 1.0 : sin(a);
  const double ca = p->alpha_deg == 90.0 ? 0.0 : cos(a);
  const double snf2 = p->snf * p->snf, stf2 = p->stf * p->stf;

  /* eq. 29/30: 1/r0 = sin a sqrt(sin^2 a / snf^2 + cos^2 a / stf^2) */
  bar->r0 = 1.0 / (sa * sqrt(sa * sa / snf2 + ca * ca / stf2));
  const double r0 = bar->r0;

  /* kappa: opening share of the traction power, 1 for Model 1.  Model 2's flow (eq. 26),
   * d up = d lambda ubar0 (m* . n) n, has the power s . d up = kappa d lambda U0 se with
   * kappa = (sn^2 / snf^2) / se^2 = r0^2 sin^4 a / snf^2, constant in the bar: its work
   * to separation is kappa q U0 / (q + 1), split as eq. 25 splits Model 1's. */
  double kappa = 1.0;
  if (p->model == 1) {
    /* eq. 29: mec = U0 r0 sin a ((sin a / snf^2) n + (cos a / stf^2) t) */
    bar->mec[0] = p->U0 * r0 * sa * sa / snf2;
    bar->mec[1] = p->U0 * r0 * sa * ca / stf2;
    /* eq. 32: upx = lambda U0 / (r0 sin a) */
    bar->upx_sep = p->U0 / (r0 * sa);
    /* eq. 35: g = E U0 / (L r0^2 sin a) */
    bar->g = p->E * p->U0 / (p->L * r0 * r0 * sa);
  } else {
    /* eq. 37: men = U0 r0 sin^2 a / snf^2, opening only */
    bar->mec[0] = p->U0 * r0 * sa * sa / snf2;
    bar->mec[1] = 0.0;
    /* eq. 37: upx = lambda U0 r0 sin^3 a / snf^2, g2 = E U0 sin^3 a / (L snf^2) */
    bar->upx_sep = p->U0 * r0 * sa * sa * sa / snf2;
    bar->g = p->E * p->U0 * sa * sa * sa / (p->L * snf2);
    kappa = r0 * r0 * sa * sa * sa * sa / snf2;
  }

  bar->Pmax = r0 * p->H;
  bar->k_elastic = p->E * p->H / p->L; /* eq. 36, elastic */
  bar->delta_peak = r0 * p->L / p->E;
  bar->delta_sep = bar->upx_sep; /* sigma = 0 at separation: no elastic part */
  /* just after the peak: Phat -> 1 (q = 1), +inf (q < 1), 0 (q > 1) */
  bar->k_soft_peak = ana_bar_softening_slope(bar, 1.0);

  /* Snapback: Phat > g somewhere on the softening branch (eq. 36).
   *   q = 1: Phat = 1 everywhere, so iff g < 1, on the whole branch;
   *   q > 1: Phat rises from 0 to q, so iff g < q, for sigma* < sstar_turn;
   *   q < 1: Phat falls from +inf to q, so always, for sigma* > sstar_turn
   *          (the whole branch when g <= q).
   * sstar_turn is the interior reversal point; where the reversal covers the
   * whole branch it starts at the peak and sstar_turn = 1. */
  double st = -1.0;
  if (p->q == 1.0) {
    bar->snapback = bar->g < 1.0;
    bar->sstar_turn = bar->snapback ? 1.0 : -1.0;
  } else if (p->q > 1.0) {
    bar->snapback = bar->g < p->q;
    bar->sstar_turn = bar->snapback && interior_turn(p->q, bar->g, &st) ? st : -1.0;
    if (bar->snapback && bar->sstar_turn < 0.0) /* g so small that the turn is at the peak */
      bar->sstar_turn = 1.0;
  } else {
    bar->snapback = 1;
    bar->sstar_turn = interior_turn(p->q, bar->g, &st) ? st : 1.0;
  }

  /* eq. 25 (Model 1), scaled by kappa for Model 2 (above) */
  bar->area = p->H / sa;
  bar->UD = kappa * p->U0;
  bar->UU = -kappa * p->U0 / (p->q + 1.0);
  bar->UF = kappa * p->q * p->U0 / (p->q + 1.0);
  bar->W_sep = bar->UF * bar->area;
  bar->D_sep = bar->UD * bar->area;
  return ANA_OK;
}

/* delta on the softening branch at lambda (eqs. 31, 34) */
static double delta_of_lambda(const ana_bar *bar, double lambda)
{
  const double sstar = 1.0 - pow(lambda, bar->p.q);
  return bar->delta_peak * (sstar + lambda * bar->g);
}

static double delta_of_sstar(const ana_bar *bar, double sstar)
{
  return bar->delta_peak * (sstar + pow(1.0 - sstar, 1.0 / bar->p.q) * bar->g);
}

void ana_bar_softening_point(const ana_bar *bar, double sstar, double *delta, double *P)
{
  if (!(sstar >= 0.0 && sstar <= 1.0)) {
    *delta = NAN;
    *P = NAN;
    return;
  }
  *delta = delta_of_sstar(bar, sstar); /* eq. 34: delta = L e_ave */
  *P = sstar * bar->Pmax;
}

double ana_bar_softening_slope(const ana_bar *bar, double sstar)
{
  if (!(sstar >= 0.0 && sstar <= 1.0))
    return NAN;
  /* eq. 36: Phat = q (1 - P/Pmax)^(1 - 1/q); IEEE pow gives the limits at sigma* = 1 */
  const double phat = bar->p.q * pow(1.0 - sstar, 1.0 - 1.0 / bar->p.q);
  const double den = 1.0 - bar->g / phat;
  if (den == 0.0)
    return INFINITY;
  return bar->k_elastic / den;
}

typedef struct {
  const ana_bar *bar;
  double target;
} root_ctx;

static double root_fn(double sstar, void *vp)
{
  const root_ctx *c = vp;
  return delta_of_sstar(c->bar, sstar) - c->target;
}

/* sigma* in [lo, hi] with delta(sigma*) = target; the caller has bracketed it. */
static int solve_sstar(const ana_bar *bar, double target, double lo, double hi, double *out)
{
  root_ctx ctx = {bar, target};
  const double flo = root_fn(lo, &ctx), fhi = root_fn(hi, &ctx);
  if (flo == 0.0) {
    *out = lo;
    return ANA_OK;
  }
  if (fhi == 0.0) {
    *out = hi;
    return ANA_OK;
  }
  gsl_function F = {root_fn, &ctx};
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (!s)
    return ANA_EFAIL;
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  int status = gsl_root_fsolver_set(s, &F, lo, hi);
  for (int it = 0; status == GSL_SUCCESS && it < 200; it++) {
    status = gsl_root_fsolver_iterate(s);
    if (status != GSL_SUCCESS)
      break;
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 1e-15, 1e-13);
    if (status == GSL_SUCCESS)
      break;
    status = GSL_SUCCESS; /* GSL_CONTINUE */
    if (it == 199)
      status = GSL_EMAXITER;
  }
  *out = gsl_root_fsolver_root(s);
  gsl_set_error_handler(old);
  gsl_root_fsolver_free(s);
  return status == GSL_SUCCESS ? ANA_OK : ANA_EFAIL;
}

/* Where end displacement d is first reached walking the curve: the elastic branch
 * (d <= delta_peak), the softening branch in decreasing sigma* (returns *sstar), or
 * only after separation (P = 0).  The branch is cut into pieces monotone in delta at
 * the interior reversal point, so each piece brackets at most one root. */
static int first_hit(const ana_bar *bar, double d, double *sstar)
{
  if (!(d > bar->delta_peak))
    return HIT_ELASTIC;
  double b[3] = {1.0, 0.0, 0.0};
  int npieces = 1;
  double st;
  if (interior_turn(bar->p.q, bar->g, &st)) {
    b[1] = st;
    npieces = 2;
  }
  for (int i = 0; i < npieces; i++) {
    const double hi = b[i], lo = b[i + 1];
    const double dhi = delta_of_sstar(bar, hi), dlo = delta_of_sstar(bar, lo);
    if (d >= fmin(dhi, dlo) && d <= fmax(dhi, dlo)) {
      if (solve_sstar(bar, d, lo, hi, sstar) != ANA_OK)
        *sstar = NAN;
      return HIT_SOFT;
    }
  }
  return HIT_SEPARATED;
}

double ana_bar_load_at(const ana_bar *bar, double delta)
{
  if (!isfinite(delta))
    return NAN;
  double s = 0.0;
  switch (first_hit(bar, delta, &s)) {
  case HIT_ELASTIC:
    return bar->k_elastic * delta;
  case HIT_SOFT:
    return s * bar->Pmax;
  default:
    return 0.0;
  }
}

/* P d delta / d lambda on the softening branch (eqs. 31, 34); lambda^(q-1) is an
 * integrable singularity at lambda = 0 when q < 1, which qags handles. */
static double work_integrand(double lambda, void *vp)
{
  const ana_bar *bar = vp;
  const double q = bar->p.q;
  const double P = bar->Pmax * (1.0 - pow(lambda, q));
  const double dd = bar->delta_peak * (bar->g - q * pow(lambda, q - 1.0));
  return P * dd;
}

double ana_bar_work(const ana_bar *bar, double delta_end)
{
  if (!isfinite(delta_end))
    return NAN;
  double s = 0.0;
  double lambda_end = 1.0;
  switch (first_hit(bar, delta_end, &s)) {
  case HIT_ELASTIC:
    return 0.5 * bar->k_elastic * delta_end * delta_end;
  case HIT_SOFT:
    if (!isfinite(s))
      return NAN;
    lambda_end = pow(1.0 - s, 1.0 / bar->p.q);
    break;
  default:
    break;
  }
  const double w_el = 0.5 * bar->Pmax * bar->delta_peak;
  if (lambda_end <= 0.0)
    return w_el;

  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
  if (!ws)
    return NAN;
  gsl_function F = {work_integrand, (void *)bar}; /* read only in work_integrand */
  double res = 0.0, abserr = 0.0;
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  const int status = gsl_integration_qags(&F, 0.0, lambda_end, 1e-12 * w_el, 1e-10, 1000, ws, &res, &abserr);
  gsl_set_error_handler(old);
  gsl_integration_workspace_free(ws);
  /* a roundoff warning with a tiny error estimate is still a good answer */
  if (status != GSL_SUCCESS && !(abserr <= 1e-8 * fabs(w_el)))
    return NAN;
  return w_el + res;
}

/* Normalised arc-length element of the softening branch between two lambdas. */
static double arc(const ana_bar *bar, double l0, double l1, double dscale)
{
  const double dd = (delta_of_lambda(bar, l1) - delta_of_lambda(bar, l0)) / dscale;
  const double dp = pow(l0, bar->p.q) - pow(l1, bar->p.q); /* (P1 - P0) / Pmax */
  return hypot(dd, dp);
}

/* m >= 2 points of the softening branch lambda in [0, lambda_end], equally spaced in
 * arc length (delta scaled by dscale, P by Pmax) so that both the steep and the flat
 * parts are resolved for any q; every point lies exactly on the curve. */
static int sample_softening(const ana_bar *bar, double lambda_end, int m, double *delta, double *P)
{
  const double dscale = fmax(bar->delta_peak, bar->delta_sep);
  double total = 0.0;
  for (int j = 0; j < ANA_ARC_GRID; j++)
    total += arc(bar, lambda_end * j / ANA_ARC_GRID, lambda_end * (j + 1) / ANA_ARC_GRID, dscale);

  int k = 0;
  delta[k] = bar->delta_peak;
  P[k] = bar->Pmax;
  k++;
  double cum = 0.0;
  for (int j = 0; j < ANA_ARC_GRID && k < m - 1; j++) {
    const double l0 = lambda_end * j / ANA_ARC_GRID, l1 = lambda_end * (j + 1) / ANA_ARC_GRID;
    const double seg = arc(bar, l0, l1, dscale);
    while (k < m - 1 && total * k / (m - 1) <= cum + seg) {
      const double f = seg > 0.0 ? (total * k / (m - 1) - cum) / seg : 0.0;
      const double l = l0 + f * (l1 - l0);
      delta[k] = delta_of_lambda(bar, l);
      P[k] = bar->Pmax * (1.0 - pow(l, bar->p.q));
      k++;
    }
    cum += seg;
  }
  /* rounding may leave the last targets unplaced: put them at the end */
  while (k < m) {
    delta[k] = delta_of_lambda(bar, lambda_end);
    P[k] = bar->Pmax * (1.0 - pow(lambda_end, bar->p.q));
    k++;
  }
  return k;
}

/* Needs n >= 4 (origin, peak, separation, end); returns 0 otherwise or for a
 * non-finite or negative delta_end.  The softening branch is cut where delta_end is
 * first reached (as in ana_bar_load_at); a P = 0 point at delta_end follows the
 * separation point when delta_end lies beyond it. */
int ana_bar_curve(const ana_bar *bar, double delta_end, int n, double *delta, double *P)
{
  if (n < 4 || !isfinite(delta_end) || delta_end < 0.0)
    return 0;
  delta[0] = 0.0;
  P[0] = 0.0;
  double s = 0.0;
  const int hit = first_hit(bar, delta_end, &s);
  if (hit == HIT_ELASTIC) {
    delta[1] = delta_end;
    P[1] = bar->k_elastic * delta_end;
    return 2;
  }
  double lambda_end = 1.0;
  int tail = 0;
  if (hit == HIT_SOFT) {
    if (!isfinite(s))
      return 0;
    lambda_end = pow(1.0 - s, 1.0 / bar->p.q);
  } else {
    tail = delta_end > bar->delta_sep;
  }
  int k = 1 + sample_softening(bar, lambda_end, n - 1 - tail, delta + 1, P + 1);
  if (tail) {
    delta[k] = delta_end;
    P[k] = 0.0;
    k++;
  }
  return k;
}
