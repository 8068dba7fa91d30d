/*
 * mpm_scatter.c - the step's particle-to-grid passes (eqs. 2, 3) with bilinear shapes,
 * and MUSL's second projection; the uGIMP ones are mpm_gimp.c's.  Called by mpm_step.c.
 *
 * Speed: a node is one 64-byte record (mpm_node.h), so a particle's share of all its
 * nodal sums is one vector add per node; the particles are sorted by cell, so the
 * shares are summed per cell in registers and touch memory once per cell.  The strips
 * scatter even then odd, so no two threads write a node at once and any thread count
 * gives the same bits.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "mpm_fields.h"
#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_gimp.h"
#include "mpm_node.h"
#include "mpm_nodes.h"
#include "mpm_scatter.h"
#include "mpm_shape.h"

/* A cell's four node shares, summed in registers while the sorted particles stay in
 * the cell (cur: its n00, SIZE_MAX before the first) and added to the nodes when they
 * leave it (cell_sums_move) or at the end of the range (cell_sums_flush). */
typedef struct {
  size_t cur;
  mpm_v8 c00, c10, c01, c11;
} cell_sums;

static inline void cell_sums_flush(const cell_sums *c, mpm_node *nd, size_t nny)
{
  if (c->cur == SIZE_MAX)
    return;
  node_add(nd + c->cur, c->c00);
  node_add(nd + c->cur + nny, c->c10);
  node_add(nd + c->cur + 1, c->c01);
  node_add(nd + c->cur + nny + 1, c->c11);
}

/* grid.node_mass = limited: the cell's sums sv = sum V, sx = sum V wx1, sy = sum V wy1
 * of its particles, added at the flush to lane qx of its corners as their shares of
 * sum_p V_p (|Gx_ip| + |Gy_ip|) = sum V (wy / hx + wx / hy) ("Nodal mass limit"). */
typedef struct {
  double sv, sx, sy;
} cell_vols;

static inline void cell_vols_flush(cell_vols *c, size_t cur, mpm_node *nd, size_t nny, double ihx, double ihy)
{
  if (cur == SIZE_MAX)
    return;
  const double x0 = ihy * (c->sv - c->sx), x1 = ihy * c->sx, y0 = ihx * (c->sv - c->sy), y1 = ihx * c->sy;
  nd[cur].qx += x0 + y0;
  nd[cur + nny].qx += x1 + y0;
  nd[cur + 1].qx += x0 + y1;
  nd[cur + nny + 1].qx += x1 + y1;
  c->sv = c->sx = c->sy = 0.0;
}

static inline void cell_sums_move(cell_sums *c, mpm_node *nd, size_t nny, size_t n00)
{
  if (n00 == c->cur)
    return;
  cell_sums_flush(c, nd, nny);
  const mpm_v8 zero = {0.0};
  c->c00 = c->c10 = c->c01 = c->c11 = zero;
  c->cur = n00;
}

/* eqs. 2, 3 for the particles [a, b); 1 if one of them is outside the grid.  A
 * particle adds to each of its four nodes N_i (m, m vx, m vy) and the force
 * f_i = -V sigma . G_i, G_i = (+-wy / hx, +-wx / hy).  With FX = (V / hx)(sxx, sxy) and
 * FY = (V / hy)(sxy, syy) in the force lanes, the four shares factor as
 *   c00 = wx0 T0 + R0,  c10 = wx1 T0 - R0,  T0 = wy0 P + FY,  R0 = wy0 FX,
 *   c01 = wx0 T1 + R1,  c11 = wx1 T1 - R1,  T1 = wy1 P - FY,  R1 = wy1 FX.
 * The particles are sorted by cell, so the shares are summed per cell (cell_sums). */
static inline __attribute__((always_inline)) int p2g_range_impl(const mpm_grid *gg, const mpm_particles *p,
                                                                 size_t a, size_t b, const int two, const int body,
                                                                 const int lim)
{
  const mpm_grid geo = *gg, *g = &geo; /* a local copy: no store below can alias it */
  const size_t nny = (size_t)g->nny;
  const double ihx = g->ihx, ihy = g->ihy;
  mpm_node *restrict nd = g->nd;
  const double *restrict x = p->x, *restrict y = p->y, *restrict vx = p->vx, *restrict vy = p->vy;
  const double *restrict pm = p->m, *restrict V = p->V;
  const double *restrict sxx = p->sxx, *restrict syy = p->syy, *restrict sxy = p->sxy;
  const int vis = p->vxx != NULL;
  const mpm_fields *fld = g->fld;
  cell_sums cs = {.cur = SIZE_MAX};
  cell_vols cv = {0.0, 0.0, 0.0};
  int out = 0;
  for (size_t k = a; k < b; k++) {
    mpm_shape sh;
    if (!mpm_shape_at(g, x[k], y[k], &sh)) {
      out = 1;
      continue;
    }
    const double mm = pm[k], Vx = V[k] * ihx, Vy = V[k] * ihy;
    /* time.damping_beta: the viscous stress rides with sigma */
    const double txx = vis ? sxx[k] + p->vxx[k] : sxx[k], tyy = vis ? syy[k] + p->vyy[k] : syy[k];
    const double txy = vis ? sxy[k] + p->vxy[k] : sxy[k];
    const mpm_v8 FX = {0.0, 0.0, 0.0, Vx * txx, Vx * txy, 0.0, 0.0, 0.0};
    const mpm_v8 FY = {0.0, 0.0, 0.0, Vy * txy, Vy * tyy, 0.0, 0.0, 0.0};
    if (two && mpm_fields_any4(fld, sh.n00, nny)) { /* near a separated band: the field per node */
      /* lane 7: the displacement along the failure normal, for the contact's gap (only
       * split nodes read it, and only particles of this path reach them) */
      const double un = fld->nx * (x[k] - p->x0[k]) + fld->ny * (y[k] - p->y0[k]);
      const mpm_v8 P = {mm, mm * vx[k], mm * vy[k], 0.0, 0.0, 0.0, 0.0, mm * un};
      const mpm_v8 T0 = sh.wy0 * P + FY, R0 = sh.wy0 * FX;
      const mpm_v8 T1 = sh.wy1 * P - FY, R1 = sh.wy1 * FX;
      size_t n[4];
      double w[4];
      mpm_shape_stencil(&sh, nny, n, w);
      const int side = mpm_fields_side_w(fld, n, w, 4, x[k], y[k], g->h);
      mpm_v8 e0 = {0.0}, e1 = {0.0}, e2 = {0.0}, e3 = {0.0}; /* lane 5, per corner */
      if (lim) {
        const double Vk = V[k];
        e0[5] = Vk * (sh.wy0 * ihx + sh.wx0 * ihy);
        e1[5] = Vk * (sh.wy0 * ihx + sh.wx1 * ihy);
        e2[5] = Vk * (sh.wy1 * ihx + sh.wx0 * ihy);
        e3[5] = Vk * (sh.wy1 * ihx + sh.wx1 * ihy);
      }
      node_add(mpm_fields_node(fld, nd, n[0], side), sh.wx0 * T0 + R0 + e0);
      node_add(mpm_fields_node(fld, nd, n[1], side), sh.wx1 * T0 - R0 + e1);
      node_add(mpm_fields_node(fld, nd, n[2], side), sh.wx0 * T1 + R1 + e2);
      node_add(mpm_fields_node(fld, nd, n[3], side), sh.wx1 * T1 - R1 + e3);
      continue;
    }
    /* body (manufactured solutions only): f_i += m_p b(X_p, t) N_ip in the fx lane */
    const double fb = body ? mm * g->body_now * sin(g->body_k * p->x0[k]) : 0.0;
    const mpm_v8 P = {mm, mm * vx[k], mm * vy[k], fb, 0.0, 0.0, 0.0, 0.0};
    const mpm_v8 T0 = sh.wy0 * P + FY, R0 = sh.wy0 * FX;
    const mpm_v8 T1 = sh.wy1 * P - FY, R1 = sh.wy1 * FX;
    if (sh.n00 != cs.cur) {
      const size_t old = cs.cur;
      cell_sums_move(&cs, nd, nny, sh.n00);
      if (lim) /* after the cell's vector flush: a narrower load than the store forwards */
        cell_vols_flush(&cv, old, nd, nny, ihx, ihy);
    }
    if (lim) {
      cv.sv += V[k];
      cv.sx += V[k] * sh.wx1;
      cv.sy += V[k] * sh.wy1;
    }
    cs.c00 += sh.wx0 * T0 + R0;
    cs.c10 += sh.wx1 * T0 - R0;
    cs.c01 += sh.wx0 * T1 + R1;
    cs.c11 += sh.wx1 * T1 - R1;
  }
  cell_sums_flush(&cs, nd, nny);
  if (lim)
    cell_vols_flush(&cv, cs.cur, nd, nny, ihx, ihy);
  return out;
}

/* MUSL first half, for the particles [a, b): eq. 6 from v^L - v (lanes fx, fy), and
 * the new momentum m_p v_p N_ip summed into lanes qx, qy.  The pass reads lanes that
 * it never writes, so one pass does both; as it scatters, it runs by colour.  Returns
 * the ledger's sum m |dv_p|^2 over the range. */
static int p2g_range(const mpm_grid *g, const mpm_particles *p, size_t a, size_t b, int lim)
{
  /* one loop without the two-field test, for every step before a band is cut */
  if (g->fld && g->fld->nsplit)
    return lim ? p2g_range_impl(g, p, a, b, 1, 0, 1) : p2g_range_impl(g, p, a, b, 1, 0, 0);
  if (g->body_now != 0.0) /* a manufactured solution's body force: its own loop */
    return p2g_range_impl(g, p, a, b, 0, 1, 0);
  return lim ? p2g_range_impl(g, p, a, b, 0, 0, 1) : p2g_range_impl(g, p, a, b, 0, 0, 0);
}

static inline __attribute__((always_inline)) double musl_velocity_range_impl(const mpm_grid *gg, mpm_particles *p,
                                                                             size_t a, size_t b, const int twof)
{
  const mpm_grid geo = *gg, *g = &geo;
  const size_t nny = (size_t)g->nny;
  mpm_node *restrict nd = g->nd;
  const double *restrict x = p->x, *restrict y = p->y, *restrict pm = p->m;
  double *restrict vx = p->vx, *restrict vy = p->vy;
  const mpm_fields *fld = g->fld;
  cell_sums cs = {.cur = SIZE_MAX};
  double kp = 0.0;
  for (size_t k = a; k < b; k++) {
    mpm_shape sh;
    mpm_shape_inside(g, x[k], y[k], &sh); /* inside: checked by the first scatter */
    const double rx = sh.wx1, ry = sh.wy1;
    const size_t n00 = sh.n00, n01 = n00 + 1, n10 = n00 + nny, n11 = n10 + 1;
    const int two = twof && mpm_fields_any4(fld, n00, nny);
    mpm_node *r00 = nd + n00, *r10 = nd + n10, *r01 = nd + n01, *r11 = nd + n11;
    if (two) { /* near a separated band: the particle's own side's records */
      size_t n[4];
      double w[4];
      mpm_shape_stencil(&sh, nny, n, w);
      const int side = mpm_fields_side_w(fld, n, w, 4, x[k], y[k], g->h);
      r00 = mpm_fields_node(fld, nd, n00, side);
      r10 = mpm_fields_node(fld, nd, n10, side);
      r01 = mpm_fields_node(fld, nd, n01, side);
      r11 = mpm_fields_node(fld, nd, n11, side);
    }
    const mpm_v4 a00 = node_load4(r00), a10 = node_load4(r10);
    const mpm_v4 a01 = node_load4(r01), a11 = node_load4(r11);
    const mpm_v4 b0 = a00 + rx * (a10 - a00), b1 = a01 + rx * (a11 - a01);
    const mpm_v4 S = b0 + ry * (b1 - b0);
    const double vxn = vx[k] + S[GFX], vyn = vy[k] + S[GFY];
    kp += pm[k] * (S[GFX] * S[GFX] + S[GFY] * S[GFY]);
    vx[k] = vxn;
    vy[k] = vyn;
    const mpm_v8 Q = {0.0, 0.0, 0.0, 0.0, 0.0, pm[k] * vxn, pm[k] * vyn, 0.0};
    const mpm_v8 Q0 = sh.wy0 * Q, Q1 = sh.wy1 * Q;
    if (two) {
      node_add(r00, sh.wx0 * Q0);
      node_add(r10, sh.wx1 * Q0);
      node_add(r01, sh.wx0 * Q1);
      node_add(r11, sh.wx1 * Q1);
      continue;
    }
    cell_sums_move(&cs, nd, nny, sh.n00);
    cs.c00 += sh.wx0 * Q0;
    cs.c10 += sh.wx1 * Q0;
    cs.c01 += sh.wx0 * Q1;
    cs.c11 += sh.wx1 * Q1;
  }
  cell_sums_flush(&cs, nd, nny);
  return kp;
}

static double musl_velocity_range(const mpm_grid *g, mpm_particles *p, size_t a, size_t b)
{
  if (g->fld && g->fld->nsplit)
    return musl_velocity_range_impl(g, p, a, b, 1);
  return musl_velocity_range_impl(g, p, a, b, 0);
}

/* Scatter over the strips, colour by colour (deterministic, no atomics).  which = 0:
 * eqs. 2-3; which = 1: MUSL velocities and their momentum into lanes (qx, qy). */
int mpm_scatter(mpm_sim *s, int which)
{
  mpm_grid *g = s->g;
  mpm_particles *p = s->p;
  const int gimp = s->sc.shape == MPM_SHAPE_GIMP, lim = mpm_nodes_limit_on(s);
  double lcx = 0.0, lcy = 0.0;
  if (gimp)
    mpm_gimp_lc(s, &lcx, &lcy);
  int out = 0;
  for (int colour = 0; colour < 2; colour++) {
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) reduction(| : out) num_threads(s->nthreads)
#endif
    for (int q = colour; q < s->nstrip; q += 2) {
      const size_t a = s->strip_start[q], b = s->strip_start[q + 1];
      if (which == 0)
        out |= gimp ? mpm_gimp_p2g_range(g, p, a, b, lcx, lcy) : p2g_range(g, p, a, b, lim);
      else if (gimp)
        s->led_part[q][MPM_LED_KP] = mpm_gimp_musl_range(g, p, a, b, lcx, lcy);
      else
        s->led_part[q][MPM_LED_KP] = musl_velocity_range(g, p, a, b);
    }
  }
  return out;
}
