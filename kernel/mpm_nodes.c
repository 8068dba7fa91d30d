/*
 * mpm_nodes.c - the node pass of the step (mpm_step.c): the free update of eq. 4,
 *   v_i = (m v)_i / m_i,  v^L_i = v_i + dt f_i / m_i,
 * the constraints and their reactions (grid.bc: lagrangian, both or consistent; see
 * hold), the ledger's node sums, the nodal velocities the other schemes take their
 * strain from (USF, USAVG: v_i; MUSL: v'), and the nodal mass limit (grid.node_mass =
 * limited: a node whose stiffness-to-mass bound k_i / m_i exceeds 4 / dt^2 takes its
 * acceleration with the mass k_i / rmax, node_limit_consts).  What the other conditions
 * and the lumped mass gave: docs/findings.md, "Time schemes, boundaries, energy".
 */
#include <math.h>
#include <stddef.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_node.h"
#include "mpm_nodes.h"
#include "mpm_phase.h"
#include "mpm_specimen.h"

/* grid.node_mass = limited applies where the strain is taken from v^L (usl, usavg) on
 * bilinear shapes (uGIMP's gradient vanishes with its weight at the support's edge, so
 * a node that a particle barely touches is no stiffer than any other). */
int mpm_nodes_limit_on(const mpm_sim *s)
{
  return s->sc.node_mass == MPM_NODEMASS_LIMITED && s->sc.shape == MPM_SHAPE_LINEAR &&
         mpm_schemes[s->sc.scheme]->bfac > 0.0;
}

/* The nodal mass limit's constants ("Nodal mass limit"): k_i = ck sum_p V_p a_ip bounds
 * the row sum of node i's stiffness (Gershgorin), with a_ip = |Gx_ip| + |Gy_ip|,
 * ck = E1 sum_j a_jp = E1 (2 / hx + 2 / hy) for bilinear hats (E1 = E / (1 - nu^2), the
 * largest entry of the plane-stress stiffness, over the materials).  The step integrates
 * a node stably while k_i / m_i <= 4 / dt^2; a node inside a uniformly filled lattice has
 * k / m = ck 2 (hx + hy) / (rho hx hy), and the limit never binds below that, so the
 * bar's interior keeps the lumped mass at any dt the CFL bound allows.  1 / rmax out. */
static void node_limit_consts(const mpm_sim *s, double *ck, double *irmax)
{
  const mpm_grid *g = s->g;
  double e1 = 0.0;
  for (int i = 0; i < 3; i++) /* MPM_MAT_BAR, _IMP, _HEAD */
    e1 = fmax(e1, s->mat[i].E1);
  *ck = e1 * 2.0 * (g->ihx + g->ihy);
  const double dt = s->sc.dt, hx = 1.0 / g->ihx, hy = 1.0 / g->ihy;
  const double rref = *ck * 2.0 * (hx + hy) * s->mat[MPM_MAT_BAR].irho * g->ihx * g->ihy;
  *irmax = 1.0 / fmax(4.0 / (dt * dt), rref);
}

/* The excess of v^L over the lumped one at a node, as a multiple of the FLIP increment:
 * m / m* - 1 with m* = ck sum V a / rmax (lane qx: sum V a) past the limit, else 0. */
static inline double node_limit_excess(const mpm_node *n, double ck, double irmax)
{
  const double mstar = ck * n->qx * irmax;
  return mstar > n->m ? n->m / mstar - 1.0 : 0.0;
}

/* The node index range [k0, k1) of strip q's node columns (the last strip takes the
 * last node column too): the fixed partition of the grid passes' ledger sums. */
static inline void strip_nodes(const mpm_sim *s, int q, long *k0, long *k1)
{
  const long nny = s->g->nny, nn = (long)s->g->nnx * nny;
  *k0 = (long)q * MPM_STRIP * nny;
  *k1 = q == s->nstrip - 1 ? nn : *k0 + MPM_STRIP * nny;
}

/* The held-node sums of one mpm_nodes_update, in registers while its loops run. */
typedef struct {
  double A, K, B, Bheld, H, Wtrue;
} hold_sums;

/* One held velocity component of node n (lane y: 0 for x, 1 for y) at v_bc, after the
 * free update left v^L (lane p) and dv = v^L - v (lane f) in it.  Sets the lanes to the
 * treatment's v^L = v_bc and increment d, books the ledger's held-node terms (replacing
 * the free-node ones mpm_nodes_update summed for it), and returns the reaction's impulse,
 * R dt = m (v_bc - v^L_free) for LAGRANGIAN and BOTH, m d - dt f for CONSISTENT. */
static inline double hold(int bc, mpm_node *n, int y, double vbc, double dvbc, double bfac, const double lim[2],
                          hold_sums *h)
{
  double *lp = y ? &n->py : &n->px, *lf = y ? &n->fy : &n->fx;
  /* lim (grid.node_mass = limited: ck, 1 / rmax; else NULL): v^L's excess over the
   * lumped one, (m / m* - 1) dv, is not the node's velocity */
  const double m = n->m, vL = *lp, dv = *lf;
  const double v = vL - dv - (lim && m > 0.0 ? node_limit_excess(n, lim[0], lim[1]) * dv : 0.0);
  double d, R;
  if (bc == MPM_BC_LAGRANGIAN) {
    d = dv + (vbc - vL); /* = v_bc - v: the FLIP increment pulls toward v_bc */
    R = m * (vbc - vL);
  } else {
    d = dvbc; /* the change of v_bc over the step (0 at a constant grip speed) */
    R = bc == MPM_BC_BOTH ? m * (vbc - vL) : m * (d - dv);
  }
  *lp = vbc;
  *lf = d;
  /* the free-node terms mpm_nodes_update added for this component, replaced by the held ones */
  h->A += m * v * (d - dv);
  h->K += m * (d * d - dv * dv);
  h->B += bfac * (m * dv * vL - m * dv * vbc);
  h->Bheld -= m * dv * vbc;
  h->H += m * (d * (v - vbc) + 0.5 * d * d);
  h->Wtrue += m * (d - dv) * vbc;
  return R;
}

/* The free update of every node (eq. 4) and the ledger's node sums, strip by strip:
 * A, K and bfac B (B the stress power of the share bfac of the strain taken from v^L).
 * usl (bfac = 1): B = -(A + K) exactly, and dt f . dv = m |dv|^2.  A scalar loop: with
 * AVX-512 a vectorised one gathers and scatters the 64-byte records, which was slower. */
static inline __attribute__((always_inline)) void grid_nodes(mpm_sim *s, double bfac, const int usl,
                                                             const int lim)
{
  mpm_grid *g = s->g;
  const double dt = s->sc.dt, mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  /* Nodal mass limit: the floor is m* = ck sum V a / rmax (lane qx holds sum V a) */
  double ck = 0.0, irmax = 0.0;
  if (lim)
    node_limit_consts(s, &ck, &irmax);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(s->nthreads)
#endif
  for (int q = 0; q < s->nstrip; q++) {
    long k0, k1;
    strip_nodes(s, q, &k0, &k1);
    double A = 0.0, K = 0.0, B = 0.0, Bc = 0.0;
    for (long k = k0; k < k1; k++) {
      mpm_node *n = &g->nd[k];
      if (n->m > mmin) {
        const double im = 1.0 / n->m;
        const double dvx = dt * n->fx * im, dvy = dt * n->fy * im;
        /* lim: v^L takes the acceleration with the floor m* past the limit; the excess
         * e over the lumped v^L (node_limit_excess: hold() finds it again) */
        double ex = 0.0, ey = 0.0;
        const double r = lim ? node_limit_excess(n, ck, irmax) : 0.0;
        if (__builtin_expect(r != 0.0, 0)) {
          ex = r * dvx;
          ey = r * dvy;
          Bc -= n->m * (dvx * ex + dvy * ey); /* the strain's extra stress power -dt f . e */
        }
        if (usl) { /* A = m v . dv = p . dv; K = m |dv|^2 = dt f . dv */
          A += n->px * dvx + n->py * dvy;
          K += dt * (n->fx * dvx + n->fy * dvy);
        } else {
          const double vx = n->px * im, vy = n->py * im, mdx = n->m * dvx, mdy = n->m * dvy;
          A += mdx * vx + mdy * vy;
          K += mdx * dvx + mdy * dvy;
          B -= mdx * (vx + dvx) + mdy * (vy + dvy);
        }
        n->px = n->px * im + dvx + ex;
        n->py = n->py * im + dvy + ey;
        n->fx = dvx;
        n->fy = dvy;
      } else {
        n->px = n->py = n->fx = n->fy = 0.0;
      }
    }
    s->led_part[q][MPM_LED_A] += A;
    s->led_part[q][MPM_LED_K] += K;
    s->led_part[q][MPM_LED_B] += usl ? -(A + K) + Bc : bfac * (B + Bc);
  }
}

/* eq. 4 and the reactions.  After this px, py hold v^L and fx, fy hold the FLIP
 * increment (v^L - v at a free node; at a held node what sc.bc says).  bfac: the share
 * of the strain increment taken from v^L after this update (USL 1, USAVG 1/2, MUSL and
 * USF 0), for the ledger's stress power B.  The GIMP path calls this too. */
void mpm_nodes_update(mpm_sim *s)
{
  const double bfac = s->scheme->bfac;
  mpm_grid *g = s->g;
  const double dt = s->sc.dt;
  const int lim = mpm_nodes_limit_on(s);
  double lc[2] = {0.0, 0.0};
  if (lim)
    node_limit_consts(s, &lc[0], &lc[1]);
  if (bfac == 1.0)
    lim ? grid_nodes(s, 1.0, 1, 1) : grid_nodes(s, 1.0, 1, 0);
  else
    lim ? grid_nodes(s, bfac, 0, 1) : grid_nodes(s, bfac, 0, 0);
  /* The constraints (sc.bc; mpm.h), serial in node order.  Tension is positive in both
   * loads. */
  const int bc = s->sc.bc;
  double Rg = 0.0, Rf = 0.0; /* sum c R (the load's), sum R where fixed */
  hold_sums h = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int q = 0; q < s->nbc; q++) {
    const mpm_bc *b = &s->bc[q];
    const int moves = b->c != 0.0;
    const double R = hold(bc, &g->nd[b->node], b->comp, moves ? b->c * s->vgrip : 0.0, moves ? b->c * s->dvgrip : 0.0,
                          bfac, lim ? lc : NULL, &h);
    if (moves)
      Rg += b->c * R;
    if (b->fixed)
      Rf += R;
  }
  mpm_ledger *L = &s->led;
  L->s_A += h.A;
  L->s_K += h.K;
  L->s_B += h.B;
  L->s_Bheld += h.Bheld;
  L->s_H += h.H;
  L->s_Wtrue += h.Wtrue;
  s->P_grip = Rg / dt;
  s->P_fixed = Rf / dt;
  const double W = (Rg / dt) * s->vgrip * dt; /* power of the load; the nodes held at rest do no work */
  s->W_ext += W;
  s->led.s_Wbook += W;
}

/* The held velocities into the strain lanes (fx, fy) of the constrained nodes: the
 * grip's -speed and the fixed end's 0 in x, the fixed node's 0 in y. */
static void held_velocity_lanes(mpm_sim *s)
{
  mpm_grid *g = s->g;
  for (int q = 0; q < s->nbc; q++) {
    const mpm_bc *b = &s->bc[q];
    const double v = b->c != 0.0 ? b->c * s->vgrip : 0.0;
    if (b->comp)
      g->nd[b->node].fy = v;
    else
      g->nd[b->node].fx = v;
  }
}

/* USF and USAVG: the projected nodal velocity v_i = p_i / m_i with the constraints
 * (v_bc at a held node), into lanes (fx, fy), for the strain increment taken before
 * the forces; the ledger's stress power of that share (frac) of the increment,
 * B = -frac dt sum f . v_i, from the forces still in the lanes. */
void mpm_nodes_start_velocity(mpm_sim *s, double frac)
{
  mpm_grid *g = s->g;
  const double c = frac * s->sc.dt, mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  /* held components first, while the lanes hold the forces: the loop below sums
   * -c f . p / m for them; B wants -c f . v_bc */
  double Bh = 0.0;
  for (int q = 0; q < s->nbc; q++) {
    const mpm_bc *b = &s->bc[q];
    const int y = b->comp;
    const mpm_node *n = &g->nd[b->node];
    const double im = n->m > mmin ? 1.0 / n->m : 0.0, vbc = b->c != 0.0 ? b->c * s->vgrip : 0.0;
    const double f = y ? n->fy : n->fx, v = (y ? n->py : n->px) * im;
    Bh += c * f * v - c * f * vbc;
  }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(s->nthreads)
#endif
  for (int q = 0; q < s->nstrip; q++) {
    long k0, k1;
    strip_nodes(s, q, &k0, &k1);
    double B = 0.0;
    for (long k = k0; k < k1; k++) {
      mpm_node *n = &g->nd[k];
      const double im = n->m > mmin ? 1.0 / n->m : 0.0;
      const double vx = n->px * im, vy = n->py * im;
      B -= c * (n->fx * vx + n->fy * vy);
      n->fx = vx;
      n->fy = vy;
    }
    s->led_part[q][MPM_LED_B] += B;
  }
  held_velocity_lanes(s);
  s->led.s_Bstart += Bh;
}

/* MUSL: v' = q / m with the same boundary conditions, into (fx, fy); the ledger's
 * stress power B = -dt sum f . v' (dt f = m dv at a free component, and the held
 * components' dt f . v_bc booked by hold()). */
void mpm_nodes_musl_velocity(mpm_sim *s)
{
  mpm_grid *g = s->g;
  const double mmin = MPM_MASS_EPS * s->mat[MPM_MAT_BAR].mp;
  /* held components, before their v' is set: -m dv . v' was summed with the
   * increment d in place of dv; take it out (d q = m d v') */
  double corr = 0.0;
  for (int q = 0; q < s->nbc; q++) {
    const mpm_node *n = &g->nd[s->bc[q].node];
    corr += s->bc[q].comp ? n->fy * n->qy : n->fx * n->qx;
  }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(s->nthreads)
#endif
  for (int q = 0; q < s->nstrip; q++) {
    long k0, k1;
    strip_nodes(s, q, &k0, &k1);
    double B = 0.0;
#ifdef _OPENMP
#pragma omp simd reduction(+ : B)
#endif
    for (long k = k0; k < k1; k++) {
      mpm_node *n = &g->nd[k];
      const double im = n->m > mmin ? 1.0 / n->m : 0.0;
      B -= n->fx * n->qx + n->fy * n->qy; /* -m dv . v' */
      n->fx = n->qx * im;
      n->fy = n->qy * im;
    }
    s->led_part[q][MPM_LED_B] += B;
  }
  held_velocity_lanes(s);
  s->led.s_Bstart += corr + s->led.s_Bheld;
}
