/*
 * ana_wave.c - the uniaxial bar at a finite grip speed V: the exact 1-D wave solution
 * with the 90 deg failure plane as a cohesive line (docs/model.md sec. 5a derives it).
 *
 * Before the onset the bar is in the homogeneous state sigma_h = E V t / L, v_h = V x / L
 * (the kernel starts the particles on it).  The perturbation travels in the Riemann
 * invariants R+ = v' - sigma' / Z, R- = v' + sigma' / Z (c = sqrt(E / rho), Z = rho c),
 * reflected with a sign change at the held ends.  The plane's law is the interface's
 * (Model 1, q = 1, eqs. 8-10): stuck while the traction Ts that keeps the faces together
 * is at most snf (1 - lambda); above it the opening obeys dw/dt = alpha w + f,
 * alpha = 2 snf^2 / (U0 Z), integrated exactly over the step; open (T = 0) at the
 * separation threshold, then contact only.  The histories are read by linear
 * interpolation: second order in the step min(Tg, Tf) / ANA_WAVE_SUB
 * (analytic/tests/test_ana_wave.c checks it).
 */
#include "ana.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* time steps per plane-to-nearer-end transit */
#define ANA_WAVE_SUB 400

static int bad(char *err, int errlen, const char *msg)
{
  if (err && errlen > 0)
    snprintf(err, (size_t)errlen, "%s", msg);
  return ANA_EINVAL;
}

/* history value at (fractional) step s; zero up to the onset (s <= 0, where h[0] = 0) */
static double hist(const double *h, long n, double s)
{
  if (s <= 0.0 || n == 0)
    return 0.0;
  const long i = (long)s;
  if (i + 1 >= n)
    return h[n - 1];
  const double f = s - (double)i;
  return (1.0 - f) * h[i] + f * h[i + 1];
}

void ana_wave_free(ana_wave *w)
{
  if (!w)
    return;
  free(w->P);
  w->P = NULL;
  w->n = 0;
}

int ana_wave_size(const ana_bar *bar, const ana_wave_params *wp, double delta_end, long *n, char *err, int errlen)
{
  const ana_params *p = &bar->p;
  *n = 0;
  if (fabs(p->alpha_deg - 90.0) > 1e-9)
    return bad(err, errlen, "the wave solution is 1-D: alpha must be 90 deg");
  if (fabs(p->q - 1.0) > 1e-12 || fabs(p->s0 - p->snf) > 1e-12 * p->snf)
    return bad(err, errlen, "the wave solution takes the interface's law: q = 1 and s0 = snf");
  if (!(isfinite(wp->speed) && wp->speed > 0.0) || !(isfinite(wp->rho) && wp->rho > 0.0))
    return bad(err, errlen, "the wave solution needs speed > 0 and rho > 0");
  if (!(wp->xg > 0.0 && wp->xg < p->L))
    return bad(err, errlen, "the plane's distance from the grip must lie in (0, L)");
  if (!(wp->thr > 0.0 && wp->thr <= 1.0))
    return bad(err, errlen, "the separation threshold must lie in (0, 1]");
  if (!(isfinite(delta_end) && delta_end > 0.0))
    return bad(err, errlen, "the wave solution needs delta_end > 0");
  const double c = sqrt(p->E / wp->rho), dt = fmin(wp->xg / c, (p->L - wp->xg) / c) / ANA_WAVE_SUB; /* as init's */
  /* counted in double first: a slow grip or a large U0 (which puts the separation far
   * out) asks for more samples than memory, or a long, holds */
  const double t_end = delta_end / wp->speed, want = ceil(t_end / dt) + 1.0;
  if (!(want <= ANA_WAVE_MAX_SAMPLES)) {
    if (err && errlen > 0)
      snprintf(err, (size_t)errlen, "the wave solution to delta %.6g would take %.3g time samples (delta / (speed "
               "dt), dt = %.3g, a %d-th of the shorter transit), above its cap of %g", delta_end, want, dt,
               ANA_WAVE_SUB, (double)ANA_WAVE_MAX_SAMPLES);
    return ANA_ERANGE;
  }
  *n = (long)want;
  return ANA_OK;
}

int ana_wave_init(const ana_bar *bar, const ana_wave_params *wp, double delta_end, ana_wave *out, char *err,
                  int errlen)
{
  const ana_params *p = &bar->p;
  out->P = NULL;
  out->n = 0;
  long n;
  const int rc = ana_wave_size(bar, wp, delta_end, &n, err, errlen);
  if (rc != ANA_OK)
    return rc;

  const double V = wp->speed, c = sqrt(p->E / wp->rho), Z = wp->rho * c, snf = p->snf, U0 = p->U0;
  const double Tg = wp->xg / c, Tf = (p->L - wp->xg) / c;
  const double dt = fmin(Tg, Tf) / ANA_WAVE_SUB, t0 = snf * p->L / (p->E * V);
  const double kh = p->E * V / p->L; /* d sigma_h / dt */
  const double alpha = 2.0 * snf * snf / (U0 * Z), ea = exp(alpha * dt);
  const double wthr = wp->thr * U0 / snf;
  /* load samples every dt to delta_end (n of them); the plane's histories from the onset
   * (compared in double: t0 / dt may be past what a long holds) */
  const long nw = (double)n > t0 / dt ? n - (long)(t0 / dt) + 2 : 2;
  double *P = malloc((size_t)n * sizeof *P), *A = malloc((size_t)nw * sizeof *A),
         *B = malloc((size_t)nw * sizeof *B);
  if (!P || !A || !B) {
    free(P);
    free(A);
    free(B);
    if (err && errlen > 0)
      snprintf(err, (size_t)errlen, "out of memory for the wave solution (%ld steps)", n);
    return ANA_EFAIL;
  }
  /* plane time tau = t - t0, history index k at tau = k dt (A[0] = B[0] = 0) */
  A[0] = B[0] = 0.0;
  double wo = 0.0; /* opening */
  int open = 0;
  long k = 0;
  const double sg = Tg / dt, sf = Tf / dt;
  for (long i = 0; i < n; i++) {
    const double t = (double)i * dt, tau = t - t0;
    /* advance the plane to tau (k dt <= tau) */
    while ((double)(k + 1) * dt <= tau + 1e-12 && k + 1 < nw) {
      const double tm = t0 + ((double)k + 0.5) * dt, t1 = t0 + (double)(k + 1) * dt;
      const double Rm = -hist(A, k + 1, (double)k + 0.5 - 2.0 * sg), Rp = -hist(B, k + 1, (double)k + 0.5 - 2.0 * sf);
      const double sh = kh * tm, Ts = sh + 0.5 * Z * (Rm - Rp);
      const double cap = open ? 0.0 : snf * (1.0 - snf * wo / U0);
      double T1;
      const double Rm1 = -hist(A, k + 1, (double)(k + 1) - 2.0 * sg), Rp1 = -hist(B, k + 1, (double)(k + 1) - 2.0 * sf);
      const double sh1 = kh * t1, Ts1 = sh1 + 0.5 * Z * (Rm1 - Rp1);
      if (Ts <= cap && !(open && wo > 0.0)) {
        T1 = fmin(Ts1, cap); /* stuck (or in contact): the faces move together */
      } else if (!open) {
        const double f = Rm - Rp - 2.0 * (snf - sh) / Z;
        wo = wo * ea + f * (ea - 1.0) / alpha;
        if (wo >= wthr)
          open = 1;
        T1 = open ? 0.0 : snf * (1.0 - snf * wo / U0);
      } else {
        wo = fmax(0.0, wo + dt * (Rm - Rp + 2.0 * sh / Z));
        T1 = 0.0;
      }
      A[k + 1] = Rm1 - 2.0 * (T1 - sh1) / Z;
      B[k + 1] = Rp1 + 2.0 * (T1 - sh1) / Z;
      k++;
    }
    P[i] = p->H * (kh * t - Z * hist(A, k + 1, (tau - Tg) / dt)); /* 0 until the unloading reaches the grip */
  }
  free(A);
  free(B);
  out->P = P;
  out->n = n;
  out->ddelta = V * dt;
  out->t_onset = t0;
  out->Tg = Tg;
  out->Tf = Tf;
  return ANA_OK;
}

double ana_wave_peak(const ana_wave *w, double *delta_at)
{
  double pk = -INFINITY, dpk = NAN;
  for (long i = 0; i < w->n; i++)
    if (w->P[i] > pk) {
      pk = w->P[i];
      dpk = (double)i * w->ddelta;
    }
  if (delta_at)
    *delta_at = dpk;
  return pk;
}

double ana_wave_load_at(const ana_wave *w, double delta)
{
  if (!w->n || !(delta >= 0.0))
    return NAN;
  const double s = delta / w->ddelta;
  const long i = (long)s;
  if (i + 1 >= w->n)
    return i + 1 == w->n && s == (double)i ? w->P[i] : NAN;
  const double f = s - (double)i;
  return (1.0 - f) * w->P[i] + f * w->P[i + 1];
}
