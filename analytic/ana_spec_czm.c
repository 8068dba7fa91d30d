/*
 * ana_spec_czm.c - the DCB's semi-analytic cohesive reference (docs/specimens-reference.md
 * sec. 3): each arm a beam on the interface law in series with the bonded ligament's
 * Winkler foundation (stiffness kf), the other arm its mirror image.
 *
 * At x >= a0 the deflection is w = sigma / kf + g / 2, sigma the law's traction in pure
 * opening (docs/model.md sec. 3, Model 1: rigid below snf, then snf (1 - (g / gc)^q),
 * gc = U0 / snf).  Each node carries a path parameter u (u = w while closed, w0 + g once
 * open, w0 = snf / kf); the solver refuses a local snap-back (kf gc < 2 q snf).
 * The arm: Euler-Bernoulli or Timoshenko (w = wb + ws, energy EI / 2 wb''^2 +
 * kGA / 2 ws'^2), free at x = L, held at w = delta / 2 moment-free at x = 0, discretised
 * by the energy (three-point curvature, shear per cell, trapezoid weights for the law
 * and foundation).  Each path point is a Newton solve with u at a0 prescribed; the
 * systems are banded (GSL's banded LU).  P is the reaction on one arm at x = 0.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_min.h>

#include "ana_spec.h"

/* The discrete problem and its workspace (all allocated once per mesh).  Per node the
 * unknowns (u, theta, M, Q): the law's path parameter, the section's rotation, the
 * bending moment M = EI theta' and the shear force Q = -M'.  Per arm (energy
 * EI / 2 theta'^2 + kGA / 2 (w' - theta)^2 + the law and foundation, minus P w(0)):
 *     w' = theta + Q / kGA (Euler: theta),  theta' = M / EI,  M' = -Q,  Q' = sigma(w) on [a0, L]
 * with M(0) = 0, M(L) = Q(L) = 0, the load P = -Q(0) and delta = 2 w(0).  The box scheme
 * (trapezoid per cell) is second order and well conditioned (the displacement form, one
 * fourth-order equation in w, has a matrix growing as h^-4 and lost six digits at h = 1/4);
 * a0 is a node, so the foundation's jump there falls between cells. */
typedef struct {
  int timo;       /* 1: Timoshenko, 0: Euler-Bernoulli                        */
  int N, ia;      /* cells; the node at a0                                    */
  int n, lb, ub;  /* unknowns 4 (N + 1); the system's lower and upper bands   */
  double kf, w0, gc, snf, q, EI, kGA;
  int rigid;
  double *x;      /* node positions                                           */
  double *y;      /* (u, theta, M, Q) by node                                 */
  double *w, *dw; /* deflection and dw/du by node                             */
  double *sg, *dsg; /* law traction and d sigma / du by node                  */
  double *R;      /* residual, rows: M(0), the cells (the path's row after cell ia - 1), M(L), Q(L) */
  gsl_matrix *AB;
  gsl_vector_uint *piv;
  gsl_vector *rhs, *sol;
} czm_ws;

static void ws_free(czm_ws *w)
{
  free(w->x);
  free(w->y);
  free(w->w);
  free(w->dw);
  free(w->sg);
  free(w->dsg);
  free(w->R);
  if (w->AB)
    gsl_matrix_free(w->AB);
  if (w->piv)
    gsl_vector_uint_free(w->piv);
  if (w->rhs)
    gsl_vector_free(w->rhs);
  if (w->sol)
    gsl_vector_free(w->sol);
}

/* The mesh: n1 cells on the pre-crack, n2 on the ligament. */
static int ws_init(czm_ws *w, const ana_spec *s, const ana_czm_opts *o, int n1, int n2)
{
  memset(w, 0, sizeof *w);
  const double a0 = s->p.a0, L = s->p.L;
  w->timo = o->beam == ANA_CZM_TIMOSHENKO;
  w->N = n1 + n2;
  w->ia = n1;
  w->n = 4 * (w->N + 1);
  w->lb = 6; /* a cell's rows reach 5 below and 6 above its first node's columns */
  w->ub = 7;
  w->kf = o->kf > 0.0 ? o->kf : s->kf;
  w->snf = s->p.snf;
  w->q = s->p.q;
  w->gc = s->wc_I;
  w->w0 = w->snf / w->kf;
  w->EI = s->EI;
  w->kGA = s->kGA;
  w->rigid = o->rigid;
  const size_t np = (size_t)w->N + 1, n = (size_t)w->n;
  w->x = calloc(np, sizeof *w->x);
  w->y = calloc(n, sizeof *w->y);
  w->w = calloc(np, sizeof *w->w);
  w->dw = calloc(np, sizeof *w->dw);
  w->sg = calloc(np, sizeof *w->sg);
  w->dsg = calloc(np, sizeof *w->dsg);
  w->R = calloc(n, sizeof *w->R);
  w->AB = gsl_matrix_calloc(n, (size_t)(2 * w->lb + w->ub + 1));
  w->piv = gsl_vector_uint_alloc(n);
  w->rhs = gsl_vector_alloc(n);
  w->sol = gsl_vector_alloc(n);
  if (!w->x || !w->y || !w->w || !w->dw || !w->sg || !w->dsg || !w->R || !w->AB || !w->piv || !w->rhs || !w->sol) {
    ws_free(w);
    return ANA_EFAIL;
  }
  for (int i = 0; i <= w->N; i++)
    w->x[i] = i <= n1 ? a0 * i / n1 : a0 + (L - a0) * (i - n1) / n2;
  return ANA_OK;
}

/* The local law from u: traction, its slope, deflection and its slope. */
static void law(const czm_ws *w, double u, double *sg, double *dsg, double *W, double *dW)
{
  if (w->rigid || u <= w->w0) {
    *sg = w->kf * u;
    *dsg = w->kf;
    *W = u;
    *dW = 1.0;
    return;
  }
  const double g = u - w->w0, r = g / w->gc;
  if (r >= 1.0) {
    *sg = *dsg = 0.0;
  } else {
    const double rq = pow(r, w->q);
    *sg = w->snf * (1.0 - rq);
    *dsg = -w->snf * w->q * (r > 0.0 ? rq / r : (w->q == 1.0 ? 1.0 : 0.0)) / w->gc;
  }
  *W = *sg / w->kf + 0.5 * g;
  *dW = *dsg / w->kf + 0.5;
}

/* The law's opening g and the work of its traction per unit length of one opening. */
static double opening(const czm_ws *w, double u)
{
  return w->rigid ? 0.0 : fmax(0.0, u - w->w0);
}
static double law_work(const czm_ws *w, double g)
{
  if (g >= w->gc)
    return w->snf * w->gc * w->q / (w->q + 1.0);
  return w->snf * (g - w->gc * pow(g / w->gc, w->q + 1.0) / (w->q + 1.0));
}

/* The law's regime at u: 0 closed, 1 softening, 2 separated. */
static int regime(const czm_ws *w, double u)
{
  return w->rigid || u <= w->w0 ? 0 : u < w->w0 + w->gc ? 1 : 2;
}

/* The mean of f over u running linearly from ui to uj (3-point Gauss-Legendre, exact for
 * the polynomial pieces of q = 1 and 2; the range split where it crosses a kink). */
static double mean_u(const czm_ws *w, double ui, double uj, double (*f)(const czm_ws *, double))
{
  static const double xg[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
  static const double wg[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double lo = fmin(ui, uj), hi = fmax(ui, uj), d = hi - lo;
  if (d <= 1e-14 * (fabs(lo) + w->w0))
    return f(w, 0.5 * (ui + uj));
  double b[4] = {lo, 0.0, 0.0, hi};
  int nb = 1;
  if (!w->rigid)
    for (int k = 0; k < 2; k++) {
      const double br = w->w0 + k * w->gc;
      if (br > lo && br < hi)
        b[nb++] = br;
    }
  b[nb] = hi;
  double acc = 0.0;
  for (int k = 0; k < nb; k++) {
    const double m = 0.5 * (b[k] + b[k + 1]), r = 0.5 * (b[k + 1] - b[k]);
    for (int g = 0; g < 3; g++)
      acc += r * wg[g] * f(w, m + r * xg[g]);
  }
  return acc / d;
}

/* The mean of f(u(x)) over a cell whose nodes hold ui and uj.  Within one regime u is
 * taken linear in x.  Where the law changes regime inside the cell, the deflection w (smooth
 * in x) is taken linear instead: the kink sits where w crosses its value there (w0 at the
 * onset, gc / 2 at separation), and u is linear on each side (exact for q = 1, where u is
 * linear in w in each regime).  Integrating the kink where it is, not by the nodes'
 * trapezoid, keeps the discrete load smooth as the zone's ends cross the cells (with the
 * trapezoid the peak load jittered by 1e-4 from one mesh to the next).  w grows with u
 * (check_opts refuses a law softening faster than the foundation), so the place is one. */
static double cell_mean(const czm_ws *w, double ui, double uj, double (*f)(const czm_ws *, double))
{
  const int ri = regime(w, ui), rj = regime(w, uj);
  if (ri == rj)
    return mean_u(w, ui, uj, f);
  double s, ds, wi, wj, dW;
  law(w, ui, &s, &ds, &wi, &dW);
  law(w, uj, &s, &ds, &wj, &dW);
  const int step = rj > ri ? 1 : -1;
  double t0 = 0.0, u0 = ui, acc = 0.0;
  for (int b = (step > 0 ? ri + 1 : ri); b != (step > 0 ? rj + 1 : rj); b += step) {
    const double B = b == 1 ? w->w0 : 0.5 * w->gc, Ub = b == 1 ? w->w0 : w->w0 + w->gc;
    double t = (B - wi) / (wj - wi);
    t = fmin(1.0, fmax(t0, t));
    acc += (t - t0) * mean_u(w, u0, Ub, f);
    t0 = t;
    u0 = Ub;
  }
  return acc + (1.0 - t0) * mean_u(w, u0, uj, f);
}

static double f_sigma(const czm_ws *w, double u)
{
  double sg, dsg, W, dW;
  law(w, u, &sg, &dsg, &W, &dW);
  return sg;
}
static double f_found(const czm_ws *w, double u)
{
  const double sg = f_sigma(w, u);
  return sg * sg / (2.0 * w->kf);
}
static double f_work(const czm_ws *w, double u)
{
  return law_work(w, opening(w, u));
}

/* The cell's mean traction and its derivatives in ui and uj: within one regime
 * (sigma(uj) - mean) / (uj - ui) and (mean - sigma(ui)) / (uj - ui) (each half the slope
 * where the two are close); across a kink by central differences. */
static double cell_sigma(const czm_ws *w, double ui, double uj, double *di, double *dj)
{
  const double m = cell_mean(w, ui, uj, f_sigma), d = uj - ui;
  if (regime(w, ui) != regime(w, uj)) {
    const double e = 1e-7 * (fabs(ui) + fabs(uj) + w->w0);
    *di = (cell_mean(w, ui + e, uj, f_sigma) - cell_mean(w, ui - e, uj, f_sigma)) / (2.0 * e);
    *dj = (cell_mean(w, ui, uj + e, f_sigma) - cell_mean(w, ui, uj - e, f_sigma)) / (2.0 * e);
    return m;
  }
  double si, dsi, sj, dsj, W, dW;
  law(w, ui, &si, &dsi, &W, &dW);
  law(w, uj, &sj, &dsj, &W, &dW);
  if (fabs(d) <= 1e-9 * (fabs(ui) + w->w0)) {
    *di = *dj = 0.25 * (dsi + dsj);
  } else {
    *dj = (sj - m) / d;
    *di = (m - si) / d;
  }
  return m;
}

#define U_(i) (4 * (i))
#define TH_(i) (4 * (i) + 1)
#define M_(i) (4 * (i) + 2)
#define Q_(i) (4 * (i) + 3)

/* The first row of cell i's four equations. */
static int cell_row(const czm_ws *w, int i)
{
  return 1 + 4 * i + (i >= w->ia);
}

/* The law at the nodes and the residual at u(a0) = tau; returns P = -Q(0). */
static double residual(czm_ws *w, double tau)
{
  const double *y = w->y;
  for (int i = 0; i <= w->N; i++) {
    if (i < w->ia) {
      w->w[i] = y[U_(i)];
      w->dw[i] = 1.0;
      w->sg[i] = w->dsg[i] = 0.0;
    } else
      law(w, y[U_(i)], &w->sg[i], &w->dsg[i], &w->w[i], &w->dw[i]);
  }
  const double cs = w->timo ? 1.0 / w->kGA : 0.0;
  w->R[0] = y[M_(0)];
  for (int i = 0; i < w->N; i++) {
    const int j = i + 1, r = cell_row(w, i);
    const double h2 = 0.5 * (w->x[j] - w->x[i]), chi = i >= w->ia ? 1.0 : 0.0;
    w->R[r] = w->w[j] - w->w[i] - h2 * (y[TH_(i)] + y[TH_(j)] + cs * (y[Q_(i)] + y[Q_(j)]));
    w->R[r + 1] = y[TH_(j)] - y[TH_(i)] - h2 * (y[M_(i)] + y[M_(j)]) / w->EI;
    w->R[r + 2] = y[M_(j)] - y[M_(i)] + h2 * (y[Q_(i)] + y[Q_(j)]);
    double di, dj;
    w->R[r + 3] = y[Q_(j)] - y[Q_(i)] - (chi > 0.0 ? 2.0 * h2 * cell_sigma(w, y[U_(i)], y[U_(j)], &di, &dj) : 0.0);
  }
  w->R[1 + 4 * w->ia] = y[U_(w->ia)] - tau;
  w->R[w->n - 2] = y[M_(w->N)];
  w->R[w->n - 1] = y[Q_(w->N)];
  return -y[Q_(0)];
}

static void put(czm_ws *w, int r, int c, double v)
{
  gsl_matrix_set(w->AB, (size_t)c, (size_t)(w->lb + w->ub + r - c), v);
}

/* The Jacobian of the residual (after residual()) into AB, GSL's banded layout. */
static void jacobian(czm_ws *w)
{
  gsl_matrix_set_zero(w->AB);
  const double cs = w->timo ? 1.0 / w->kGA : 0.0;
  put(w, 0, M_(0), 1.0);
  for (int i = 0; i < w->N; i++) {
    const int j = i + 1, r = cell_row(w, i);
    const double h2 = 0.5 * (w->x[j] - w->x[i]), chi = i >= w->ia ? 1.0 : 0.0;
    put(w, r, U_(j), w->dw[j]);
    put(w, r, U_(i), -w->dw[i]);
    put(w, r, TH_(i), -h2);
    put(w, r, TH_(j), -h2);
    put(w, r, Q_(i), -h2 * cs);
    put(w, r, Q_(j), -h2 * cs);
    put(w, r + 1, TH_(j), 1.0);
    put(w, r + 1, TH_(i), -1.0);
    put(w, r + 1, M_(i), -h2 / w->EI);
    put(w, r + 1, M_(j), -h2 / w->EI);
    put(w, r + 2, M_(j), 1.0);
    put(w, r + 2, M_(i), -1.0);
    put(w, r + 2, Q_(i), h2);
    put(w, r + 2, Q_(j), h2);
    put(w, r + 3, Q_(j), 1.0);
    put(w, r + 3, Q_(i), -1.0);
    if (chi > 0.0) {
      double di, dj;
      cell_sigma(w, w->y[U_(i)], w->y[U_(j)], &di, &dj);
      put(w, r + 3, U_(i), -2.0 * h2 * di);
      put(w, r + 3, U_(j), -2.0 * h2 * dj);
    }
  }
  put(w, 1 + 4 * w->ia, U_(w->ia), 1.0);
  put(w, w->n - 2, M_(w->N), 1.0);
  put(w, w->n - 1, Q_(w->N), 1.0);
}

/* One Newton solve at u(a0) = tau from the current y; ANA_OK or ANA_EFAIL.  Converged
 * when every kind of unknown moves by less than 1e-12 of its largest value. */
static int newton(czm_ws *w, double tau, int *iters)
{
  const size_t n = (size_t)w->n;
  for (int it = 0; it < 40; it++) {
    residual(w, tau);
    jacobian(w);
    for (size_t r = 0; r < n; r++)
      gsl_vector_set(w->rhs, r, -w->R[r]);
    if (gsl_linalg_LU_band_decomp(n, (size_t)w->lb, (size_t)w->ub, w->AB, w->piv) != GSL_SUCCESS ||
        gsl_linalg_LU_band_solve((size_t)w->lb, (size_t)w->ub, w->AB, w->piv, w->rhs, w->sol) != GSL_SUCCESS)
      return ANA_EFAIL;
    double dmax[4] = {0}, ymax[4] = {w->w0, 0, 0, 0};
    for (size_t c = 0; c < n; c++) {
      const double d = gsl_vector_get(w->sol, c);
      if (!isfinite(d))
        return ANA_EFAIL;
      w->y[c] += d;
      dmax[c % 4] = fmax(dmax[c % 4], fabs(d));
      ymax[c % 4] = fmax(ymax[c % 4], fabs(w->y[c]));
    }
    ++*iters;
    int done = 1;
    for (int k = 0; k < 4; k++)
      done &= dmax[k] <= 1e-12 * ymax[k];
    if (done) {
      residual(w, tau);
      return ANA_OK;
    }
  }
  return ANA_EFAIL;
}

/* The point of the current (solved) state: delta, P, tip, front and the energies. */
static ana_czm_point state_point(czm_ws *w, const ana_spec *s)
{
  const double *y = w->y;
  ana_czm_point p = {.P = 0.0 - y[Q_(0)], .delta = 2.0 * w->w[0], .tip = s->p.a0, .front = s->p.a0};
  double U = 0.0, Wl = 0.0; /* one arm's elastic energy; the law's work on both */
  for (int i = 0; i < w->N; i++) {
    const int j = i + 1;
    const double h2 = 0.5 * (w->x[j] - w->x[i]);
    U += h2 * (y[M_(i)] * y[M_(i)] + y[M_(j)] * y[M_(j)]) / (2.0 * w->EI);
    if (w->timo)
      U += h2 * (y[Q_(i)] * y[Q_(i)] + y[Q_(j)] * y[Q_(j)]) / (2.0 * w->kGA);
    if (i >= w->ia) {
      U += 2.0 * h2 * cell_mean(w, y[U_(i)], y[U_(j)], f_found);
      Wl += 2.0 * h2 * cell_mean(w, y[U_(i)], y[U_(j)], f_work);
    }
  }
  p.U_el = 2.0 * U;
  p.W_law = Wl;
  /* the separated and the opened stretch grow from a0; their ends between nodes where w
   * crosses its value at the kink (gc / 2, w0), w linear in the cell */
  double *end[2] = {&p.tip, &p.front};
  for (int k = 0; k < 2 && !w->rigid; k++) {
    const int reg = k == 0 ? 2 : 1;
    int i = w->ia;
    if (regime(w, y[U_(i)]) < reg)
      continue;
    while (i < w->N && regime(w, y[U_(i + 1)]) >= reg)
      i++;
    if (i == w->N) {
      *end[k] = w->x[w->N];
      continue;
    }
    const double B = k == 0 ? 0.5 * w->gc : w->w0, fi = w->w[i] - B, fn = w->w[i + 1] - B;
    *end[k] = w->x[i] + fmin(1.0, fmax(0.0, fi / (fi - fn))) * (w->x[i + 1] - w->x[i]);
  }
  return p;
}

static int push(ana_czm_path *c, ana_czm_point p)
{
  if (c->n == c->cap) {
    const int cap = c->cap ? 2 * c->cap : 256;
    ana_czm_point *q = realloc(c->pt, (size_t)cap * sizeof *q);
    if (!q)
      return ANA_EFAIL;
    c->pt = q;
    c->cap = cap;
  }
  c->pt[c->n++] = p;
  return ANA_OK;
}

/* The peak between the path's parameters lo < mid < hi (P(mid) above both): P(tau)
 * maximised by GSL's Brent minimiser, each value a Newton solve from ystart. */
typedef struct {
  czm_ws *w;
  const ana_spec *s;
  const double *ystart;
  int *iters;
  int failed;
} peak_ctx;

static double neg_load(double tau, void *v)
{
  peak_ctx *c = v;
  memcpy(c->w->y, c->ystart, (size_t)c->w->n * sizeof *c->w->y);
  if (newton(c->w, tau, c->iters) != ANA_OK) {
    c->failed = 1;
    return GSL_NAN;
  }
  return -residual(c->w, tau);
}

static int refine_peak(peak_ctx *c, double lo, double mid, double hi, double *tau_peak)
{
  gsl_function F = {neg_load, c};
  gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  if (!m)
    return ANA_EFAIL;
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  int rc = gsl_min_fminimizer_set(m, &F, mid, lo, hi) == GSL_SUCCESS ? ANA_OK : ANA_EFAIL;
  for (int it = 0; rc == ANA_OK && it < 200; it++) {
    if (gsl_min_fminimizer_iterate(m) != GSL_SUCCESS || c->failed) {
      rc = ANA_EFAIL;
      break;
    }
    const double a = gsl_min_fminimizer_x_lower(m), b = gsl_min_fminimizer_x_upper(m);
    if (gsl_min_test_interval(a, b, 0.0, 1e-10) == GSL_SUCCESS)
      break;
  }
  gsl_set_error_handler(old);
  *tau_peak = gsl_min_fminimizer_x_minimum(m);
  gsl_min_fminimizer_free(m);
  return rc;
}

/* Inserts p into the path before index k (the peak between two path points). */
static int insert(ana_czm_path *c, int k, ana_czm_point p)
{
  if (push(c, p) != ANA_OK)
    return ANA_EFAIL;
  memmove(&c->pt[k + 1], &c->pt[k], (size_t)(c->n - 1 - k) * sizeof p);
  c->pt[k] = p;
  return ANA_OK;
}

/* The path's step: the parameter's increment is adapted so that each step moves delta, P
 * and the tip by about 1 / STEPS of their scales (the LEFM opening at tip_end, the LEFM
 * load at a0, the growth tip_end - a0). */
#define STEPS 400.0

typedef struct {
  double *ysave, *yprev, *ykeep, *gmax;
  double tau[3], P[3]; /* the last three path points' parameter and load */
  double best;         /* the largest load located so far                */
} trace_buf;

static void buf_free(trace_buf *b)
{
  free(b->ysave);
  free(b->yprev);
  free(b->ykeep);
  free(b->gmax);
}

/* After a step: the law's largest fall of opening so far, and the peak if the last
 * three points bracket it. */
static int after_step(czm_ws *w, const ana_spec *s, trace_buf *b, ana_czm_path *out, int *iters)
{
  for (int i = w->ia; i <= w->N; i++) {
    const double g = opening(w, w->y[U_(i)]);
    if (g > b->gmax[i])
      b->gmax[i] = g;
    else
      out->unload = fmax(out->unload, b->gmax[i] - g);
  }
  if (!(b->P[1] > b->P[2] && b->P[1] >= b->P[0] && b->P[1] > b->best && b->tau[0] < b->tau[1]))
    return ANA_OK;
  /* the state at tau[1] is yprev: start every solve there, keep the current state */
  memcpy(b->ykeep, w->y, (size_t)w->n * sizeof *w->y);
  peak_ctx c = {w, s, b->yprev, iters, 0};
  double tp = b->tau[1];
  ana_czm_point pk = out->pt[out->n - 2];
  if (b->P[1] > b->P[0] && refine_peak(&c, b->tau[0], b->tau[1], b->tau[2], &tp) == ANA_OK &&
      !isnan(neg_load(tp, &c)) && !c.failed) {
    pk = state_point(w, s);
    if (insert(out, tp > b->tau[1] ? out->n - 1 : out->n - 2, pk) != ANA_OK)
      return ANA_EFAIL;
  }
  out->peak = pk;
  b->best = pk.P;
  memcpy(w->y, b->ykeep, (size_t)w->n * sizeof *w->y);
  residual(w, b->tau[2]);
  return ANA_OK;
}

/* The path on the mesh of n1 + n2 cells. */
static int trace(const ana_spec *s, const ana_czm_opts *o, int n1, int n2, ana_czm_path *out, char *err, int errlen)
{
  czm_ws w;
  memset(out, 0, sizeof *out);
  if (ws_init(&w, s, o, n1, n2) != ANA_OK)
    goto nomem;
  out->h = (s->p.L - s->p.a0) / n2;
  const size_t bytes = (size_t)w.n * sizeof(double);
  trace_buf b = {malloc(bytes), calloc((size_t)w.n, sizeof(double)), malloc(bytes),
                 calloc((size_t)w.N + 1, sizeof(double)), {0}, {0}, -INFINITY};
  if (!b.ysave || !b.yprev || !b.ykeep || !b.gmax || push(out, state_point(&w, s)) != ANA_OK)
    goto nomem_b;
  int rc = ANA_OK;
  if (w.rigid) { /* linear: one solve gives the compliance */
    rc = newton(&w, w.w0, &out->newton);
    if (rc == ANA_OK && push(out, state_point(&w, s)) != ANA_OK)
      goto nomem_b;
    out->peak = out->pt[out->n - 1];
    goto done;
  }
  double C, dC, Pref, dref;
  ana_spec_compliance(s, ANA_BEAM_SIMPLE, s->p.a0, &C, &dC);
  Pref = sqrt(2.0 * s->Gc / dC);
  ana_spec_lefm_branch(s, ANA_BEAM_SIMPLE, o->tip_end, &dC, &dref);
  const double aref = o->tip_end - s->p.a0;
  double tau = 0.0, dtau = 0.5 * w.w0;
  int k = 0;
  while (out->pt[out->n - 1].tip < o->tip_end) {
    if (dtau < 1e-13 * (tau + w.w0) || k > 1000000) {
      rc = ANA_EFAIL;
      if (err && errlen > 0)
        snprintf(err, (size_t)errlen, "the path stopped at delta %g: no converged step", out->pt[out->n - 1].delta);
      goto done;
    }
    memcpy(b.ysave, w.y, bytes);
    if (k > 0) /* secant predictor */
      for (int i = 0; i < w.n; i++)
        w.y[i] += dtau / (tau - b.tau[1]) * (w.y[i] - b.yprev[i]);
    if (newton(&w, tau + dtau, &out->newton) != ANA_OK) {
      memcpy(w.y, b.ysave, bytes);
      dtau *= 0.5;
      continue;
    }
    const ana_czm_point p = state_point(&w, s), *q = &out->pt[out->n - 1];
    const double r = STEPS * fmax(fmax(fabs(p.delta - q->delta) / dref, fabs(p.P - q->P) / Pref),
                                  fabs(p.tip - q->tip) / aref);
    if (r > 4.0) {
      memcpy(w.y, b.ysave, bytes);
      dtau *= 0.5;
      continue;
    }
    memcpy(b.yprev, b.ysave, bytes);
    b.tau[0] = b.tau[1];
    b.P[0] = b.P[1];
    b.tau[1] = tau;
    b.P[1] = q->P;
    tau += dtau;
    b.tau[2] = tau;
    b.P[2] = p.P;
    k++;
    if (push(out, p) != ANA_OK)
      goto nomem_b;
    if (k >= 2 && after_step(&w, s, &b, out, &out->newton) != ANA_OK)
      goto nomem_b;
    dtau *= fmin(2.0, fmax(0.5, r > 0.0 ? 1.0 / r : 2.0));
  }
  if (!(b.best > -INFINITY)) { /* no interior maximum: the largest point */
    out->peak = out->pt[0];
    for (int i = 1; i < out->n; i++)
      if (out->pt[i].P > out->peak.P)
        out->peak = out->pt[i];
  }
done:
  buf_free(&b);
  ws_free(&w);
  if (rc != ANA_OK)
    ana_czm_path_free(out);
  return rc;
nomem_b:
  buf_free(&b);
  ws_free(&w);
nomem:
  ana_czm_path_free(out);
  if (err && errlen > 0)
    snprintf(err, (size_t)errlen, "out of memory for the cohesive reference");
  return ANA_EFAIL;
}

void ana_czm_path_free(ana_czm_path *c)
{
  if (!c)
    return;
  free(c->pt);
  c->pt = NULL;
  c->n = c->cap = 0;
}

static int check_opts(const ana_spec *s, const ana_czm_opts *o, char *err, int errlen)
{
  const char *why = NULL;
  if (s->p.kind != ANA_SPEC_DCB)
    why = "the cohesive reference is the DCB's";
  else if (s->p.q < 1.0)
    why = "q < 1: the law's slope is infinite at its onset";
  else if (o->beam != ANA_CZM_EULER && o->beam != ANA_CZM_TIMOSHENKO)
    why = "beam must be Euler (0) or Timoshenko (1)";
  else if (o->cells < 16 || o->cells > 1000000)
    why = "cells must be in [16, 1000000]";
  else if (!o->rigid && !(o->tip_end > s->p.a0 && o->tip_end < s->p.L))
    why = "tip_end must be in (a0, L)";
  else if (!isfinite(o->kf))
    why = "kf must be finite";
  else if (!o->rigid && (o->kf > 0.0 ? o->kf : s->kf) * s->wc_I <= 2.0 * s->p.q * s->p.snf)
    why = "the law softens faster than the foundation stiffens (kf U0 / snf <= 2 q snf): the "
          "opening at a0 no longer orders the path";
  if (why && err && errlen > 0)
    snprintf(err, (size_t)errlen, "%s", why);
  return why ? ANA_EINVAL : ANA_OK;
}

/* The mesh's split: the node at a0 kept exact. */
static void split(const ana_spec *s, int cells, int *n1, int *n2)
{
  long m = lround(cells * s->p.a0 / s->p.L);
  *n1 = (int)(m < 1 ? 1 : m > cells - 1 ? cells - 1 : m);
  *n2 = cells - *n1;
}

int ana_dcb_czm_solve(const ana_spec *s, const ana_czm_opts *o, ana_czm_path *out, char *err, int errlen)
{
  memset(out, 0, sizeof *out);
  const int rc = check_opts(s, o, err, errlen);
  if (rc != ANA_OK)
    return rc;
  int n1, n2;
  split(s, o->cells, &n1, &n2);
  return trace(s, o, n1, n2, out, err, errlen);
}

double ana_czm_load_at(const ana_czm_path *c, double delta, double *tip)
{
  for (int i = 1; i < c->n; i++) {
    const ana_czm_point *a = &c->pt[i - 1], *b = &c->pt[i];
    if ((delta - a->delta) * (delta - b->delta) <= 0.0 && a->delta != b->delta) {
      const double f = (delta - a->delta) / (b->delta - a->delta);
      if (tip)
        *tip = a->tip + f * (b->tip - a->tip);
      return a->P + f * (b->P - a->P);
    }
  }
  if (tip)
    *tip = NAN;
  return NAN;
}

/* Richardson's extrapolation of v[0..2] on meshes h, h / 2, h / 4 with the observed
 * order (2 where the differences do not give one in [0.5, 8]); *spread is its distance
 * from the extrapolation with order 2. */
static double richardson(const double v[3], double *order, double *spread)
{
  const double d1 = v[1] - v[0], d2 = v[2] - v[1];
  double p = 2.0;
  if (d1 != 0.0 && d2 != 0.0 && d1 / d2 > 0.0) {
    const double po = log2(d1 / d2);
    if (po >= 0.5 && po <= 8.0)
      p = po;
  }
  if (order)
    *order = p;
  const double ext = v[2] + d2 / (pow(2.0, p) - 1.0);
  *spread = fabs(ext - (v[2] + d2 / 3.0));
  return ext;
}

int ana_dcb_czm_converge(const ana_spec *s, const ana_czm_opts *o, ana_czm_conv *out, char *err, int errlen)
{
  memset(out, 0, sizeof *out);
  int rc = check_opts(s, o, err, errlen);
  if (rc != ANA_OK)
    return rc;
  int n1, n2;
  split(s, o->cells, &n1, &n2);
  for (int m = 0; m < 3; m++) {
    ana_czm_path c;
    rc = trace(s, o, n1 << m, n2 << m, &c, err, errlen);
    if (rc != ANA_OK)
      return rc;
    out->P[m] = c.peak.P;
    out->delta[m] = c.peak.delta;
    ana_czm_path_free(&c);
  }
  double sp, sd;
  out->P_ext = richardson(out->P, &out->order, &sp);
  out->delta_ext = richardson(out->delta, NULL, &sd);
  out->P_ext_err = sp / fabs(out->P_ext);
  out->delta_ext_err = sd / fabs(out->delta_ext);
  out->P_err = fabs(out->P[2] - out->P_ext) / fabs(out->P_ext);
  out->delta_err = fabs(out->delta[2] - out->delta_ext) / fabs(out->delta_ext);
  return ANA_OK;
}
