/*
 * mpm_gimp.c - the particle-to-grid scatters (eqs. 2, 3, and MUSL's second projection)
 * with uGIMP weights (grid.shape = gimp; mpm_shape.h has the weights and why).
 *
 * A particle adds to its 3 x 3 nodes.  With P = (m, m vx, m vy) and the force lanes
 * FX = (V / hx)(sxx, sxy), FY = (V / hy)(sxy, syy), node (a, b) receives
 *   Sx_a Sy_b P - dSx_a Sy_b FX - Sx_a dSy_b FY  =  Sx_a T_b - dSx_a R_b,
 *   T_b = Sy_b P - dSy_b FY,  R_b = Sy_b FX,
 * i.e. N_i (m, m v) and f_i = -V sigma . grad N_i (eq. 3).  Threads: particles are
 * sorted by the dual cell around their nearest node and may drift half a dual column
 * beyond their strip before a sort (mpm_sort.c, mpm_step.c), so the strips' colouring
 * holds for the 3 x 3 stencil.
 */
#include <math.h>
#include <stdint.h>

#include "mpm_kernel.h"
#include "mpm_fields.h"
#include "mpm_gimp.h"

/* The 3 x 3 node shares of the particles that have the same nearest node (they are
 * consecutive: mpm_sort.c sorts by the dual cell) are summed in registers and added to
 * the nodes when the next particle has another. */
static inline void stencil_flush(mpm_node *nd, size_t n0, size_t nny, const mpm_v8 c[9])
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      node_add(nd + n0 + (size_t)i * nny + (size_t)j, c[3 * i + j]);
}

static inline void stencil_clear(mpm_v8 c[9])
{
  const mpm_v8 zero = {0.0};
  for (int q = 0; q < 9; q++)
    c[q] = zero;
}

/* The next particle's stencil starts at n0: flush the sums when it differs from cur. */
static inline void stencil_move(mpm_node *nd, size_t nny, size_t *cur, size_t n0, mpm_v8 c[9])
{
  if (n0 == *cur)
    return;
  if (*cur != SIZE_MAX)
    stencil_flush(nd, *cur, nny, c);
  stencil_clear(c);
  *cur = n0;
}

int mpm_gimp_p2g_range(const mpm_grid *gg, const mpm_particles *p, size_t a, size_t b, double lcx, double lcy)
{
  const mpm_grid geo = *gg, *g = &geo;
  const size_t nny = (size_t)g->nny;
  const double ihx = g->ihx, ihy = g->ihy, ox = g->ox, oy = g->oy;
  mpm_node *restrict nd = g->nd;
  const double *restrict x = p->x, *restrict y = p->y, *restrict vx = p->vx, *restrict vy = p->vy;
  const double *restrict x0 = p->x0, *restrict y0 = p->y0;
  const double *restrict pm = p->m, *restrict V = p->V;
  const double *restrict sxx = p->sxx, *restrict syy = p->syy, *restrict sxy = p->sxy;
  const int vis = p->vxx != NULL;
  const mpm_fields *fld = g->fld;
  mpm_v8 c[9];
  stencil_clear(c);
  size_t cur = SIZE_MAX;
  int out = 0;
  for (size_t k = a; k < b; k++) {
    if (!mpm_gimp_inside(g, x[k], y[k])) {
      out = 1;
      continue;
    }
    mpm_gimp1 sx, sy;
    mpm_gimp_1d((x[k] - ox) * ihx, lcx, &sx);
    mpm_gimp_1d((y[k] - oy) * ihy, lcy, &sy);
    const size_t n0 = (size_t)sx.i0 * nny + (size_t)sy.i0;
    const double mm = pm[k], Vx = V[k] * ihx, Vy = V[k] * ihy;
    /* time.damping_beta: the viscous stress rides with sigma */
    const double txx = vis ? sxx[k] + p->vxx[k] : sxx[k], tyy = vis ? syy[k] + p->vyy[k] : syy[k];
    const double txy = vis ? sxy[k] + p->vxy[k] : sxy[k];
    const mpm_v8 FX = {0.0, 0.0, 0.0, Vx * txx, Vx * txy, 0.0, 0.0, 0.0};
    const mpm_v8 FY = {0.0, 0.0, 0.0, Vy * txy, Vy * tyy, 0.0, 0.0, 0.0};
    if (mpm_fields_any(fld, n0, nny)) { /* near a separated band: the field per node */
      /* lane 7: the displacement along the failure normal, for the contact's gap (only
       * split nodes read it, and only particles of this path reach them) */
      const double un = fld->nx * (x[k] - x0[k]) + fld->ny * (y[k] - y0[k]);
      const mpm_v8 P = {mm, mm * vx[k], mm * vy[k], 0.0, 0.0, 0.0, 0.0, mm * un};
      const int side = mpm_fields_pside(fld, n0, nny, &sx, &sy, x[k], y[k], x0[k], y0[k], g->h);
      for (int j = 0; j < 3; j++) {
        const mpm_v8 T = sy.S[j] * P - sy.dS[j] * FY, R = sy.S[j] * FX;
        for (int i = 0; i < 3; i++)
          node_add(mpm_fields_node(fld, nd, n0 + (size_t)i * nny + (size_t)j, side), sx.S[i] * T - sx.dS[i] * R);
      }
      continue;
    }
    const mpm_v8 P = {mm, mm * vx[k], mm * vy[k], 0.0, 0.0, 0.0, 0.0, 0.0};
    stencil_move(nd, nny, &cur, n0, c);
    for (int j = 0; j < 3; j++) {
      const mpm_v8 T = sy.S[j] * P - sy.dS[j] * FY, R = sy.S[j] * FX;
      for (int i = 0; i < 3; i++)
        c[3 * i + j] += sx.S[i] * T - sx.dS[i] * R;
    }
  }
  if (cur != SIZE_MAX)
    stencil_flush(nd, cur, nny, c);
  return out;
}

double mpm_gimp_musl_range(const mpm_grid *gg, mpm_particles *p, size_t a, size_t b, double lcx, double lcy)
{
  double kp = 0.0; /* the ledger's sum m |dv_p|^2 (mpm_step.c) */
  const mpm_grid geo = *gg, *g = &geo;
  const size_t nny = (size_t)g->nny;
  const double ihx = g->ihx, ihy = g->ihy, ox = g->ox, oy = g->oy;
  mpm_node *restrict nd = g->nd;
  const double *restrict x = p->x, *restrict y = p->y, *restrict pm = p->m;
  double *restrict vx = p->vx, *restrict vy = p->vy;
  const mpm_fields *fld = g->fld;
  mpm_v8 c[9];
  stencil_clear(c);
  size_t cur = SIZE_MAX;
  for (size_t k = a; k < b; k++) {
    mpm_gimp1 sx, sy;
    mpm_gimp_1d((x[k] - ox) * ihx, lcx, &sx);
    mpm_gimp_1d((y[k] - oy) * ihy, lcy, &sy);
    const size_t n0 = (size_t)sx.i0 * nny + (size_t)sy.i0;
    const int two = mpm_fields_any(fld, n0, nny);
    const int side = two ? mpm_fields_pside(fld, n0, nny, &sx, &sy, x[k], y[k], p->x0[k], p->y0[k], g->h) : 0;
    mpm_v4 S, DX, DY;
    if (two)
      mpm_fields_gather(fld, nd, nny, &sx, &sy, side, &S, &DX, &DY);
    else
      mpm_gimp_gather(nd, nny, &sx, &sy, &S, &DX, &DY);
    const double vxn = vx[k] + S[GFX], vyn = vy[k] + S[GFY];
    kp += p->m[k] * (S[GFX] * S[GFX] + S[GFY] * S[GFY]);
    vx[k] = vxn;
    vy[k] = vyn;
    const mpm_v8 Q = {0.0, 0.0, 0.0, 0.0, 0.0, pm[k] * vxn, pm[k] * vyn, 0.0};
    if (two) {
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
          node_add(mpm_fields_node(fld, nd, n0 + (size_t)i * nny + (size_t)j, side), (sx.S[i] * sy.S[j]) * Q);
      continue;
    }
    stencil_move(nd, nny, &cur, n0, c);
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        c[3 * i + j] += (sx.S[i] * sy.S[j]) * Q;
  }
  if (cur != SIZE_MAX)
    stencil_flush(nd, cur, nny, c);
  return kp;
}
