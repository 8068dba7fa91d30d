/*
 * ana_stab.c - the growth rate of the kernel's explicit step, linearised on a 1-D periodic
 * bar of Nc cells, n particles a cell, about a rest state of uniform stress sigma0 whose
 * particles have drifted by d cells (docs/findings.md, "The cohesive interface").  The
 * perturbation (u_p, v_p, s_p) goes through the step as kernel/mpm_step.c takes it:
 *   m_i = sum_p S_ip m_p,  v_i = sum_p S_ip m_p v_p / m_i                  eqs. 2, 3
 *   f_i = -sum_p V (G_ip s_p + sigma0 H_ip u_p)                             eq. 3
 *   vL_i = v_i + dt f_i / m_i;  v_p += sum_i S_ip (vL_i - v_i)             eqs. 4, 6
 *   w_i = vL_i (USL) or the re-projected v (MUSL);  s_p += E dt sum_i G_ip w_i   eq. 7
 *   u_p += dt sum_i S_ip vL_i                                               eq. 5
 * S is the node's weight, G = dS/dx and H = dG/dx_p (zero inside a cell for bilinear
 * shapes; nonzero for uGIMP once a particle's box straddles a node).  The step's matrix
 * (3 n Nc square) has largest eigenvalue modulus r: the rate is ln(r) / dt (0 neutral);
 * the same over the complex eigenvalues (the waves) says how the scheme treats them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>

#include "ana.h"

/* uGIMP weight, gradient and its second derivative for a node at distance xi (cells) from
 * a particle whose box has half length lp (cells); bilinear when gimp is 0 */
static void shape(double xi, double lp, int gimp, double *s, double *g, double *hh)
{
  const double a = fabs(xi), sg = xi >= 0.0 ? 1.0 : -1.0;
  *s = *g = *hh = 0.0;
  if (!gimp) {
    if (a < 1.0) {
      *s = 1.0 - a;
      *g = -sg;
    }
    return;
  }
  if (a < lp) {
    *s = 1.0 - (xi * xi + lp * lp) / (2.0 * lp);
    *g = -xi / lp;
    *hh = -1.0 / lp;
  } else if (a <= 1.0 - lp) {
    *s = 1.0 - a;
    *g = -sg;
  } else if (a < 1.0 + lp) {
    *s = (1.0 + lp - a) * (1.0 + lp - a) / (4.0 * lp);
    *g = -sg * (1.0 + lp - a) / (2.0 * lp);
    *hh = 1.0 / (2.0 * lp);
  }
}

/* The periodic lattice's shape values S, gradients G and second derivatives Hh (node i,
 * particle p at i * np + p; Hh carries the initial stress's geometric stiffness) and the
 * nodal masses m. */
static void stab_weights(const ana_stab *c, double *S, double *G, double *Hh, double *m)
{
  const int nc = c->ncell, n = c->per_cell, np = nc * n;
  const double h = c->h, lp = 0.5 / n, mp = c->rho * h / n;
  for (int p = 0; p < np; p++) {
    const double xp = (p / n) + ((p % n) + 0.5) / n + c->drift; /* cells */
    for (int i = 0; i < nc; i++)
      for (int wrap = -1; wrap <= 1; wrap++) { /* periodic images */
        double s, g, hh;
        shape(xp - (i + wrap * nc), lp, c->shape == ANA_STAB_GIMP, &s, &g, &hh);
        S[i * np + p] += s;
        G[i * np + p] += g / h;
        Hh[i * np + p] += hh / (h * h);
      }
  }
  for (int i = 0; i < nc; i++)
    for (int p = 0; p < np; p++)
      m[i] += S[i * np + p] * mp;
}

/* One step of the linearised scheme on the state z = w + 4 nc = (u, v, s) per particle,
 * in place; w's first 4 nc entries are the nodal scratch. */
static void stab_step(const ana_stab *c, const double *S, const double *G, const double *Hh, const double *m, double *w)
{
  const int nc = c->ncell, n = c->per_cell, np = nc * n;
  const double mp = c->rho * c->h / n, V = c->h / n, dt = c->dt;
  double *vg = w, *vL = w + nc, *wg = w + 2 * nc, *f = w + 3 * nc, *z = w + 4 * nc;
  double *u = z, *v = z + np, *s = z + 2 * np;
  for (int i = 0; i < nc; i++) {
    double pm = 0.0, fi = 0.0;
    for (int p = 0; p < np; p++) {
      pm += S[i * np + p] * mp * v[p];
      fi -= V * (G[i * np + p] * s[p] + c->sigma0 * Hh[i * np + p] * u[p]);
    }
    vg[i] = pm / m[i];
    f[i] = fi;
    vL[i] = vg[i] + dt * fi / m[i];
  }
  for (int p = 0; p < np; p++) {
    double dv = 0.0, du = 0.0;
    for (int i = 0; i < nc; i++) {
      dv += S[i * np + p] * (vL[i] - vg[i]);
      du += S[i * np + p] * vL[i];
    }
    v[p] += dv;
    u[p] += dt * du;
  }
  for (int i = 0; i < nc; i++) {
    double q = 0.0;
    for (int p = 0; p < np; p++)
      q += S[i * np + p] * mp * v[p];
    wg[i] = c->scheme == ANA_STAB_MUSL ? q / m[i] : vL[i];
  }
  for (int p = 0; p < np; p++) {
    double de = 0.0;
    for (int i = 0; i < nc; i++)
      de += G[i * np + p] * wg[i];
    s[p] += c->E * dt * de;
  }
}

int ana_stab_rate(const ana_stab *c, ana_stab_rates *out, char *err, int errlen)
{
  if (!(c->h > 0.0 && isfinite(c->h)) || !(c->E > 0.0 && isfinite(c->E)) || !(c->rho > 0.0 && isfinite(c->rho)) ||
      !isfinite(c->sigma0) || !isfinite(c->drift) || !(c->dt > 0.0 && isfinite(c->dt)) || c->per_cell < 1 ||
      c->per_cell > 8 || c->ncell < 3 || c->ncell > 64 || (c->scheme != ANA_STAB_USL && c->scheme != ANA_STAB_MUSL)) {
    if (err)
      snprintf(err, (size_t)errlen, "ana_stab_rate: h, E, rho, dt > 0 and finite, sigma0 and drift finite, per_cell in "
                                    "[1, 8], ncell in [3, 64], scheme usl or musl");
    return ANA_EINVAL;
  }
  const int nc = c->ncell, n = c->per_cell, np = nc * n, nz = 3 * np;
  const double dt = c->dt;
  double *S = calloc((size_t)nc * np, sizeof *S), *G = calloc((size_t)nc * np, sizeof *G),
         *Hh = calloc((size_t)nc * np, sizeof *Hh), *m = calloc((size_t)nc, sizeof *m),
         *w = malloc(sizeof(double) * (size_t)(4 * nc + 3 * np));
  gsl_matrix *A = gsl_matrix_alloc((size_t)nz, (size_t)nz);
  gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t)nz);
  gsl_eigen_nonsymm_workspace *ws = gsl_eigen_nonsymm_alloc((size_t)nz);
  int st = ANA_OK;
  if (!S || !G || !Hh || !m || !w || !A || !ev || !ws) {
    st = ANA_EFAIL;
    if (err)
      snprintf(err, (size_t)errlen, "ana_stab_rate: out of memory");
    goto done;
  }
  stab_weights(c, S, G, Hh, m);
  double *z = w + 4 * nc;
  for (int col = 0; col < nz; col++) {
    for (int k = 0; k < nz; k++)
      z[k] = k == col;
    stab_step(c, S, G, Hh, m, w);
    for (int k = 0; k < nz; k++)
      gsl_matrix_set(A, (size_t)k, (size_t)col, z[k]);
  }
  if (gsl_eigen_nonsymm(A, ev, ws) != 0) {
    st = ANA_EFAIL;
    if (err)
      snprintf(err, (size_t)errlen, "ana_stab_rate: the eigenvalues did not converge");
    goto done;
  }
  double r = 0.0, ro = 0.0;
  for (int k = 0; k < nz; k++) {
    const gsl_complex e = gsl_vector_complex_get(ev, (size_t)k);
    const double a = hypot(GSL_REAL(e), GSL_IMAG(e));
    r = fmax(r, a);
    if (fabs(GSL_IMAG(e)) > 1e-9 * a) /* oscillates: a wave, not the drift or the null space */
      ro = fmax(ro, a);
  }
  out->rate = log(r) / dt;
  out->wave = ro > 0.0 ? log(ro) / dt : -INFINITY;
done:
  gsl_eigen_nonsymm_free(ws);
  gsl_vector_complex_free(ev);
  gsl_matrix_free(A);
  free(S);
  free(G);
  free(Hh);
  free(m);
  free(w);
  return st;
}
