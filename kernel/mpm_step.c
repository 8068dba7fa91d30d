/*
 * mpm_step.c - one explicit MPM step, update-stress-last as in the paper
 * (sec. 2, eqs. 2-7), with the boundary conditions and their reactions.
 *
 *   p2g   m_i, (m v)_i, f_i = -sum_p V_p sigma_p . G_ip            eqs. 2, 3
 *   grid  v_i = (m v)_i / m_i,  v^L_i = v_i + dt f_i / m_i; BCs      eq. 4
 *   g2p   x_p += dt sum v^L_i N_ip,  v_p += sum (v^L_i - v_i) N_ip    eqs. 5, 6
 *         de_p = dt sym(sum v^L_i (x) G_ip), then the decohesion update  eq. 7
 *
 * MUSL (time.scheme = musl) differs only in the strain: the updated particle
 * velocities are projected to the grid again, v'_i = sum m_p v_p N_ip / m_i (BCs
 * applied), and de_p = dt sym(sum v'_i (x) G_ip).  v'_i is a weighted mean of particle
 * velocities, so a node that a particle barely touches (tiny m_i, finite f_i) cannot
 * inject a huge strain: the cell-crossing instability of USL.
 *
 * N and G are taken at the start of the step in every pass (mpm_shape.h).
 *
 * Boundary conditions are applied to v^L only.  Applying them to v_i as well (as
 * MODEL.md sec. 2 reads) would make v^L - v_i = 0 at a gripped node, so the FLIP
 * update (eq. 6) could never bring the particles there to the grip's speed.
 *
 * Threads: the scatters run strip by strip, even strips then odd (mpm_sort.c); the
 * gathers are independent per particle.  Results are bit-for-bit the same for any
 * number of threads.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "mpm.h"
#include "mpm_shape.h"

/* Nodes with less mass than this fraction of a particle's are treated as empty. */
#define MPM_MASS_EPS 1e-12

static double wall(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int thread_id(void)
{
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

/* eqs. 2, 3 for the particles [a, b); 1 if one of them is outside the grid.  The array
 * pointers are hoisted into restrict locals: through g-> and p-> every store would make
 * the compiler reload every pointer. */
static int p2g_range(const mpm_grid *gg, const mpm_particles *p, size_t a, size_t b)
{
  const mpm_grid geo = *gg, *g = &geo; /* a local copy: no store below can alias it */
  const size_t nny = (size_t)g->nny;
  const double ihx = g->ihx, ihy = g->ihy;
  double *restrict gm = g->m, *restrict gpx = g->px, *restrict gpy = g->py;
  double *restrict gfx = g->fx, *restrict gfy = g->fy;
  const double *restrict x = p->x, *restrict y = p->y, *restrict vx = p->vx, *restrict vy = p->vy;
  const double *restrict pm = p->m, *restrict V = p->V;
  const double *restrict sxx = p->sxx, *restrict syy = p->syy, *restrict sxy = p->sxy;
  int out = 0;
  for (size_t k = a; k < b; k++) {
    mpm_shape sh;
    if (!mpm_shape_at(g, x[k], y[k], &sh)) {
      out = 1;
      continue;
    }
    const double wx0 = sh.wx0, wx1 = sh.wx1, wy0 = sh.wy0, wy1 = sh.wy1;
    const double mm = pm[k], mvx = mm * vx[k], mvy = mm * vy[k];
    const double Vx = V[k] * ihx, Vy = V[k] * ihy;
    const double A = Vx * sxx[k], Bx = Vx * sxy[k], By = Vy * sxy[k], C = Vy * syy[k];
    const size_t n00 = sh.n00, n01 = n00 + 1, n10 = n00 + nny, n11 = n10 + 1;
    const double N00 = wx0 * wy0, N10 = wx1 * wy0, N01 = wx0 * wy1, N11 = wx1 * wy1;
    gm[n00] += mm * N00;   gm[n01] += mm * N01;   gm[n10] += mm * N10;   gm[n11] += mm * N11;
    gpx[n00] += mvx * N00; gpx[n01] += mvx * N01; gpx[n10] += mvx * N10; gpx[n11] += mvx * N11;
    gpy[n00] += mvy * N00; gpy[n01] += mvy * N01; gpy[n10] += mvy * N10; gpy[n11] += mvy * N11;
    /* f_i = -V sigma . G_i with G_i = (+-wy/hx, +-wx/hy), eq. 3 */
    gfx[n00] += A * wy0 + By * wx0;   gfy[n00] += Bx * wy0 + C * wx0;
    gfx[n10] += -A * wy0 + By * wx1;  gfy[n10] += -Bx * wy0 + C * wx1;
    gfx[n01] += A * wy1 - By * wx0;   gfy[n01] += Bx * wy1 - C * wx0;
    gfx[n11] += -A * wy1 - By * wx1;  gfy[n11] += -Bx * wy1 - C * wx1;
  }
  return out;
}

/* MUSL: momentum of the updated particle velocities into (vx, vy) for [a, b). */
static void p2g_momentum_range(const mpm_grid *restrict g, const mpm_particles *restrict p,
                               double *restrict qx, double *restrict qy, size_t a, size_t b)
{
  const size_t nny = (size_t)g->nny;
  for (size_t k = a; k < b; k++) {
    mpm_shape sh;
    if (!mpm_shape_at(g, p->x[k], p->y[k], &sh))
      continue;
    const double mvx = p->m[k] * p->vx[k], mvy = p->m[k] * p->vy[k];
    const size_t n00 = sh.n00, n01 = n00 + 1, n10 = n00 + nny, n11 = n10 + 1;
    const double N00 = sh.wx0 * sh.wy0, N10 = sh.wx1 * sh.wy0, N01 = sh.wx0 * sh.wy1, N11 = sh.wx1 * sh.wy1;
    qx[n00] += mvx * N00; qx[n01] += mvx * N01; qx[n10] += mvx * N10; qx[n11] += mvx * N11;
    qy[n00] += mvy * N00; qy[n01] += mvy * N01; qy[n10] += mvy * N10; qy[n11] += mvy * N11;
  }
}

/* Scatter over the strips, colour by colour (deterministic, no atomics).  which = 0:
 * eqs. 2-3; which = 1: MUSL momentum into (fx, fy). */
static int scatter(mpm_sim *s, int which)
{
  mpm_grid *g = s->g;
  const mpm_particles *p = s->p;
  int out = 0;
  for (int colour = 0; colour < 2; colour++) {
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) reduction(| : out) num_threads(s->nthreads)
#endif
    for (int q = colour; q < s->nstrip; q += 2) {
      if (which == 0)
        out |= p2g_range(g, p, s->strip_start[q], s->strip_start[q + 1]);
      else
        p2g_momentum_range(g, p, g->fx, g->fy, s->strip_start[q], s->strip_start[q + 1]);
    }
  }
  return out;
}

/* eq. 4 and the reactions.  After this px, py hold v^L and fx, fy hold v^L - v. */
static void grid_update(mpm_sim *s)
{
  mpm_grid *g = s->g;
  const double dt = s->sc.dt, mmin = MPM_MASS_EPS * s->p->m[0];
  const long nn = (long)g->nnx * (long)g->nny;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(s->nthreads)
#endif
  for (long k = 0; k < nn; k++) {
    if (g->m[k] > mmin) {
      const double im = 1.0 / g->m[k];
      const double dvx = dt * g->fx[k] * im, dvy = dt * g->fy[k] * im;
      g->px[k] = g->px[k] * im + dvx;
      g->py[k] = g->py[k] * im + dvy;
      g->fx[k] = dvx;
      g->fy[k] = dvy;
    } else {
      g->px[k] = g->py[k] = g->fx[k] = g->fy[k] = 0.0;
    }
  }
  /* Reaction of a constraint: the force that turns the free v^L into the prescribed one,
   * R = m (v_bc - v^L_free) / dt.  Tension is positive in both loads. */
  const double vg = -s->sc.speed;
  double Rg = 0.0, Rf = 0.0;
  for (int q = 0; q < s->ngrip; q++) {
    const int k = s->grip[q];
    const double jump = vg - g->px[k];
    Rg += g->m[k] * jump;
    g->px[k] = vg;
    g->fx[k] += jump;
  }
  for (int q = 0; q < s->nfixx; q++) {
    const int k = s->fixx[q];
    const double jump = -g->px[k];
    Rf += g->m[k] * jump;
    g->px[k] = 0.0;
    g->fx[k] += jump;
  }
  g->fy[s->fixy] -= g->py[s->fixy];
  g->py[s->fixy] = 0.0;
  s->P_grip = -Rg / dt;
  s->P_fixed = Rf / dt;
  s->W_ext += (Rg / dt) * vg * dt; /* power of the grip's force; the fixed nodes do no work */
}

/* MUSL: v' = q / m with the same boundary conditions, in place in (fx, fy). */
static void grid_musl_velocity(mpm_sim *s)
{
  mpm_grid *g = s->g;
  const double mmin = MPM_MASS_EPS * s->p->m[0];
  const long nn = (long)g->nnx * (long)g->nny;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(s->nthreads)
#endif
  for (long k = 0; k < nn; k++) {
    const double im = g->m[k] > mmin ? 1.0 / g->m[k] : 0.0;
    g->fx[k] *= im;
    g->fy[k] *= im;
  }
  for (int q = 0; q < s->ngrip; q++)
    g->fx[s->grip[q]] = -s->sc.speed;
  for (int q = 0; q < s->nfixx; q++)
    g->fx[s->fixx[q]] = 0.0;
  g->fy[s->fixy] = 0.0;
}

/* Names the first particle whose state is not finite. */
static void name_nonfinite(const mpm_sim *s, char *err, size_t errlen)
{
  const mpm_particles *p = s->p;
  const char *names[] = {"x", "y", "vx", "vy", "sxx", "syy", "sxy", "lambda"};
  for (size_t k = 0; k < p->n; k++) {
    const double v[] = {p->x[k], p->y[k], p->vx[k], p->vy[k], p->sxx[k], p->syy[k], p->sxy[k], p->lam[k]};
    for (int f = 0; f < 8; f++)
      if (!isfinite(v[f])) {
        snprintf(err, errlen, "step %ld: particle at X = %g, Y = %g: %s is not finite", s->step, p->x0[k],
                 p->y0[k], names[f]);
        return;
      }
  }
  snprintf(err, errlen, "step %ld: non-finite value", s->step);
}

typedef struct {
  long soften, separate, bracketed;
  double tconst;   /* seconds in the full constitutive update */
  int bad;         /* the update returned non-finite */
  int resort;      /* a particle drifted out of its strip's safe range */
  size_t bad_k;
  double check;    /* sum of the new state: NaN if anything is not finite */
} g2p_acc;

/* The full decohesion update of particle k (sec. 4), off the hot path. */
static __attribute__((noinline)) void constitutive_full(const mpm_material *m, mpm_particles *restrict p,
                                                         size_t k, const double de[3], mpm_dwork *dw,
                                                         g2p_acc *acc)
{
  const double t0 = wall();
  const mpm_dstate in = {p->sxx[k], p->syy[k], p->sxy[k], p->lam[k], p->upn[k], p->upt[k], p->sep[k]};
  mpm_dstate o;
  mpm_dinfo info;
  if (mpm_dcoh_update(m, &in, de, &o, &info, dw) != MPM_OK && !acc->bad) {
    acc->bad = 1;
    acc->bad_k = k;
  }
  p->sxx[k] = o.sxx;
  p->syy[k] = o.syy;
  p->sxy[k] = o.sxy;
  p->lam[k] = o.lam;
  p->upn[k] = o.upn;
  p->upt[k] = o.upt;
  p->sep[k] = (uint8_t)o.sep;
  p->str[k] = o.sep ? 0.0 : 1.0 - (m->q == 1.0 ? o.lam : pow(o.lam, m->q));
  p->wcoh[k] += info.w * p->V[k] / m->Le;
  acc->soften += info.path == MPM_DPATH_SOFTEN;
  acc->separate += info.path == MPM_DPATH_SEPARATE;
  acc->bracketed += info.bracketed;
  acc->tconst += wall() - t0;
}

/* The constitutive update of particle k with strain increment de (eq. 7 -> sec. 4):
 * the elastic trial inline, the full update only where F > 0 may hold. */
static inline void constitutive(const mpm_sim *s, mpm_particles *restrict p, size_t k, const double de[3],
                                mpm_dwork *dw, g2p_acc *acc)
{
  const mpm_material *m = &s->mat[p->mat[k]];
  double *restrict psxx = p->sxx, *restrict psyy = p->syy, *restrict psxy = p->sxy;
  const double sxx = psxx[k] + m->E1 * de[0] + m->E2 * de[1];
  const double syy = psyy[k] + m->E2 * de[0] + m->E1 * de[1];
  const double sxy = psxy[k] + 2.0 * m->G * de[2];
  if (m->model != MPM_DCOH_NONE) {
    /* F <= 0 (eq. 23) as se^2 <= (1 - lambda^q)^2, with the strength cached */
    const double tx = sxx * m->nx + sxy * m->ny, ty = sxy * m->nx + syy * m->ny;
    const double sn = tx * m->nx + ty * m->ny, st = tx * m->tx + ty * m->ty;
    const double a = sn > 0.0 ? sn / m->snf : 0.0, b = st / m->stf;
    if (p->sep[k] || a * a + b * b > p->str[k] * p->str[k]) {
      constitutive_full(m, p, k, de, dw, acc);
      return;
    }
  }
  psxx[k] = sxx;
  psyy[k] = syy;
  psxy[k] = sxy;
}

/* eqs. 5-7 and the constitutive update for the particles of strip q.  USL: strain from
 * v^L (px, py).  MUSL: velocities were already updated; strain from v' (fx, fy). */
static inline __attribute__((always_inline)) void g2p_strip_impl(mpm_sim *s, int q, const int musl,
                                                                  mpm_dwork *dw, g2p_acc *acc)
{
  const mpm_grid geo = *s->g, *g = &geo; /* a local copy: no store below can alias it */
  mpm_particles *p = s->p;
  const double ihx = g->ihx, ihy = g->ihy, dt = s->sc.dt, ox = g->ox;
  const size_t nny = (size_t)g->nny;
  const double *restrict ux = g->px, *restrict uy = g->py;                 /* v^L      */
  const double *restrict dvx = g->fx, *restrict dvy = g->fy;               /* v^L - v  */
  const double *restrict sx = musl ? g->fx : g->px, *restrict sy = musl ? g->fy : g->py; /* strain velocity */
  double *restrict x = p->x, *restrict y = p->y, *restrict vx = p->vx, *restrict vy = p->vy;
  const int lo = q * MPM_STRIP - 1, hi = (q + 1) * MPM_STRIP; /* safe columns (mpm_sort.c) */
  double check = 0.0;
  int resort = 0;
  for (size_t k = s->strip_start[q]; k < s->strip_start[q + 1]; k++) {
    mpm_shape sh;
    mpm_shape_inside(g, x[k], y[k], &sh); /* inside: checked by the scatter */
    const double wx0 = sh.wx0, wx1 = sh.wx1, wy0 = sh.wy0, wy1 = sh.wy1;
    const size_t n00 = sh.n00, n01 = n00 + 1, n10 = n00 + nny, n11 = n10 + 1;
    const double N00 = wx0 * wy0, N10 = wx1 * wy0, N01 = wx0 * wy1, N11 = wx1 * wy1;
    /* eq. 5 (and eq. 6 for USL) */
    x[k] += dt * (N00 * ux[n00] + N10 * ux[n10] + N01 * ux[n01] + N11 * ux[n11]);
    y[k] += dt * (N00 * uy[n00] + N10 * uy[n10] + N01 * uy[n01] + N11 * uy[n11]);
    if (!musl) {
      vx[k] += N00 * dvx[n00] + N10 * dvx[n10] + N01 * dvx[n01] + N11 * dvx[n11];
      vy[k] += N00 * dvy[n00] + N10 * dvy[n10] + N01 * dvy[n01] + N11 * dvy[n11];
    }
    /* eq. 7: gradient of the bilinear velocity field */
    const double a00 = sx[n00], a10 = sx[n10], a01 = sx[n01], a11 = sx[n11];
    const double b00 = sy[n00], b10 = sy[n10], b01 = sy[n01], b11 = sy[n11];
    const double dxux = ihx * (wy0 * (a10 - a00) + wy1 * (a11 - a01));
    const double dyuy = ihy * (wx0 * (b01 - b00) + wx1 * (b11 - b10));
    const double dyux = ihy * (wx0 * (a01 - a00) + wx1 * (a11 - a10));
    const double dxuy = ihx * (wy0 * (b10 - b00) + wy1 * (b11 - b01));
    const double de[3] = {dt * dxux, dt * dyuy, 0.5 * dt * (dyux + dxuy)};
    constitutive(s, p, k, de, dw, acc);
    const double col = (x[k] - ox) * ihx;
    resort |= col < lo || col >= hi + 1;
    check += vx[k] + vy[k] + p->sxx[k] + p->syy[k] + p->sxy[k];
  }
  acc->resort |= resort;
  acc->check += check;
}

/* One copy of the loop per scheme, so that the USL copy reads v^L once for eq. 5 and
 * eq. 7 (the compiler cannot know at run time that the two pointers agree). */
static void g2p_strip(mpm_sim *s, int q, int musl, mpm_dwork *dw, g2p_acc *acc)
{
  if (musl)
    g2p_strip_impl(s, q, 1, dw, acc);
  else
    g2p_strip_impl(s, q, 0, dw, acc);
}

/* MUSL first half: eq. 6 only, for the particles of strip q. */
static void g2p_velocity_strip(mpm_sim *s, int q)
{
  const mpm_grid *g = s->g;
  mpm_particles *restrict p = s->p;
  const size_t nny = (size_t)g->nny;
  for (size_t k = s->strip_start[q]; k < s->strip_start[q + 1]; k++) {
    mpm_shape sh;
    mpm_shape_inside(g, p->x[k], p->y[k], &sh);
    const size_t n00 = sh.n00, n01 = n00 + 1, n10 = n00 + nny, n11 = n10 + 1;
    const double N00 = sh.wx0 * sh.wy0, N10 = sh.wx1 * sh.wy0, N01 = sh.wx0 * sh.wy1, N11 = sh.wx1 * sh.wy1;
    p->vx[k] += N00 * g->fx[n00] + N10 * g->fx[n10] + N01 * g->fx[n01] + N11 * g->fx[n11];
    p->vy[k] += N00 * g->fy[n00] + N10 * g->fy[n10] + N01 * g->fy[n01] + N11 * g->fy[n11];
  }
}

static mpm_status g2p(mpm_sim *s, char *err, size_t errlen)
{
  const int musl = s->sc.scheme == MPM_SCHEME_MUSL;
  if (musl) {
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(s->nthreads)
#endif
    for (int q = 0; q < s->nstrip; q++)
      g2p_velocity_strip(s, q);
    mpm_grid *g = s->g;
    const size_t nn = (size_t)g->nnx * (size_t)g->nny;
    memset(g->fx, 0, nn * sizeof(double));
    memset(g->fy, 0, nn * sizeof(double));
    scatter(s, 1);
    grid_musl_velocity(s);
  }
  g2p_acc tot = {0, 0, 0, 0.0, 0, 0, 0, 0.0};
#ifdef _OPENMP
#pragma omp parallel num_threads(s->nthreads)
#endif
  {
    g2p_acc acc = {0, 0, 0, 0.0, 0, 0, 0, 0.0};
    mpm_dwork *dw = s->dws[thread_id()];
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for (int q = 0; q < s->nstrip; q++)
      g2p_strip(s, q, musl, dw, &acc);
#ifdef _OPENMP
#pragma omp critical
#endif
    {
      /* integer counters: order-free; tconst: a timing only */
      tot.soften += acc.soften;
      tot.separate += acc.separate;
      tot.bracketed += acc.bracketed;
      tot.tconst = acc.tconst > tot.tconst ? acc.tconst : tot.tconst;
      tot.resort |= acc.resort;
      tot.check += acc.check; /* only tested for finiteness: order does not matter */
      if (acc.bad && (!tot.bad || acc.bad_k < tot.bad_k)) {
        tot.bad = 1;
        tot.bad_k = acc.bad_k;
      }
    }
  }
  s->n_soften += tot.soften;
  s->n_separate += tot.separate;
  s->n_bracketed += tot.bracketed;
  s->time_split[MPM_T_CONST] += tot.tconst;
  s->resort |= tot.resort;
  if (tot.bad) {
    const mpm_particles *p = s->p;
    snprintf(err, errlen, "step %ld: particle at X = %g, Y = %g: decohesion update not finite", s->step,
             p->x0[tot.bad_k], p->y0[tot.bad_k]);
    return MPM_ENOTFINITE;
  }
  /* A NaN anywhere in the state makes the sum NaN. */
  if (!isfinite(tot.check)) {
    name_nonfinite(s, err, errlen);
    return MPM_ENOTFINITE;
  }
  return MPM_OK;
}

/* The head is rigid: in x it moves with the grip; in y it is free, as one body whose
 * momentum is the sum its particles received this step (no y constraint, so the bar's
 * end may rise, as the paper's Fig. 8 shows).  Serial, in particle order: the same sums
 * whatever the threads. */
static void head_rigid(mpm_sim *s)
{
  if (s->ngrip == 0)
    return; /* the head is the grip: without one (tests of the bare step) it is left alone */
  mpm_particles *p = s->p;
  double m = 0.0, my = 0.0;
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] == MPM_MAT_HEAD) {
      m += p->m[k];
      my += p->m[k] * p->vy[k];
    }
  if (!(m > 0.0))
    return;
  const double vy = my / m, dx = -s->sc.speed * (s->step + 1) * s->sc.dt;
  s->head_dy += vy * s->sc.dt;
  for (size_t k = 0; k < p->n; k++)
    if (p->mat[k] == MPM_MAT_HEAD) {
      p->vx[k] = -s->sc.speed;
      p->vy[k] = vy;
      p->x[k] = p->x0[k] + dx;
      p->y[k] = p->y0[k] + s->head_dy;
    }
}

/* Lays the background grid for this step (MPM_GRID_STRETCH: along the bar's mean
 * stretch, so that the gripped column stays on the bar's left end, the fixed one on its
 * right end). */
static void lay_grid(mpm_sim *s)
{
  if (s->sc.grid_motion != MPM_GRID_STRETCH)
    return;
  mpm_grid *g = s->g;
  const double L = s->sc.L, stretch = 1.0 + mpm_sim_delta(s) / L;
  g->hx = s->sc.h * stretch;
  g->ihx = 1.0 / g->hx;
  g->ox = L + (s->grid_ox0 - L) * stretch;
}

mpm_status mpm_sim_step(mpm_sim *s, char *err, size_t errlen)
{
  lay_grid(s);
  double t0 = wall(), t1;
  if (s->resort || s->step % MPM_SORT_EVERY == 0) {
    mpm_sim_sort(s);
    t1 = wall();
    s->time_split[MPM_T_SORT] += t1 - t0;
    t0 = t1;
  }
  mpm_grid *g = s->g;
  const size_t nn = (size_t)g->nnx * (size_t)g->nny;
  memset(g->m, 0, nn * sizeof(double));
  memset(g->px, 0, nn * sizeof(double));
  memset(g->py, 0, nn * sizeof(double));
  memset(g->fx, 0, nn * sizeof(double));
  memset(g->fy, 0, nn * sizeof(double));
  if (scatter(s, 0)) {
    const mpm_particles *p = s->p;
    mpm_status st = MPM_EDOMAIN;
    for (size_t k = 0; k < p->n; k++) {
      mpm_shape sh;
      if (!mpm_shape_at(g, p->x[k], p->y[k], &sh)) {
        st = isfinite(p->x[k]) && isfinite(p->y[k]) ? MPM_EDOMAIN : MPM_ENOTFINITE;
        snprintf(err, errlen, "step %ld: particle at X = %g, Y = %g %s at (%g, %g)%s", s->step, p->x0[k],
                 p->y0[k], st == MPM_EDOMAIN ? "left the grid" : "has a non-finite position", p->x[k],
                 p->y[k], st == MPM_EDOMAIN ? "; raise grid.margin" : "");
        break;
      }
    }
    return st;
  }
  t1 = wall();
  s->time_split[MPM_T_P2G] += t1 - t0;
  grid_update(s);
  t0 = wall();
  s->time_split[MPM_T_GRID] += t0 - t1;
  const double c0 = s->time_split[MPM_T_CONST];
  const mpm_status st = g2p(s, err, errlen);
  t1 = wall();
  /* g2p's own share excludes the constitutive time measured inside it */
  s->time_split[MPM_T_G2P] += (t1 - t0) - (s->time_split[MPM_T_CONST] - c0);
  if (st != MPM_OK)
    return st;
  head_rigid(s);
  s->step++;
  s->t = s->step * s->sc.dt;
  return MPM_OK;
}
