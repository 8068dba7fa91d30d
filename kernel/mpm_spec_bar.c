/*
 * mpm_spec_bar.c - the paper's specimen (sec. 4.4, Fig. 5): the bar [0, L] x [0, H]
 * pulled at its left end x = 0 by a rigid head moving at -speed in x (stress-free
 * particles beyond the end, MPM_MAT_HEAD, whose node columns are all gripped), and held
 * at its right end x = L in x, its mid-height node in y as well (specimen.grips =
 * rollers).  specimen.grips = held holds both ends in y too, as a test machine's wedge
 * grips do.  The crack runs along the line at alpha through the flaw's particle.
 */
#include <math.h>

#include "mpm_specimen.h"
#include "mpm_static.h"

/* the head and the grip's travel to end_delta (the columns are laid with or without
 * the head's particles) */
static void bar_left_cells(const mpm_scene *sc, int *left, int *head)
{
  *left = MPM_HEAD_CELLS + (int)ceil(sc->end_delta / sc->h - 1e-9);
  *head = sc->head == MPM_HEAD_NONE ? 0 : MPM_HEAD_CELLS;
}

static int bar_rise_cells(const mpm_scene *sc)
{
  (void)sc;
  return 0;
}

/* -speed (L - x) / L along the bar (mpm.h) */
static void bar_start_velocity(const mpm_scene *sc, double x, double y, double *vx, double *vy)
{
  (void)y;
  *vx = mpm_scene_start_vx(sc, x);
  *vy = 0.0;
}

/* The explicit step's end: the head is rigid; in x it moves with the grip; in y it is free, as one body whose
 * momentum is the sum its particles received this step (no y constraint, so the bar's
 * end may rise, as the paper's Fig. 8 shows).  Serial, in particle order: the same sums
 * whatever the threads. */
static void bar_step_end(mpm_sim *s)
{
  mpm_particles *p = s->p;
  double m = 0.0, my = 0.0, ke0 = 0.0;
  for (size_t i = 0; i < s->nhead; i++) {
    const size_t k = s->head[i];
    m += p->m[k];
    my += p->m[k] * p->vy[k];
    ke0 += 0.5 * p->m[k] * (p->vx[k] * p->vx[k] + p->vy[k] * p->vy[k]);
  }
  mpm_ledger *L = &s->led;
  /* the ledger: what the head (the machine) took, its KE change and what its
   * projection below removes */
  L->W_head = ke0 - L->KE_head0 + L->head_reset;
  if (s->nbc == 0)
    return; /* the head is the grip: without one (tests of the bare step) it is left alone */
  if (!(m > 0.0))
    return;
  const double vy = my / m, dx = -mpm_sim_grip_u(s, 1);
  s->head_dy += vy * s->sc.dt;
  double ke1 = 0.0;
  for (size_t i = 0; i < s->nhead; i++) {
    const size_t k = s->head[i];
    p->vx[k] = -s->vgrip;
    p->vy[k] = vy;
    p->x[k] = p->x0[k] + dx;
    p->y[k] = p->y0[k] + s->head_dy;
    ke1 += 0.5 * p->m[k] * (p->vx[k] * p->vx[k] + vy * vy);
  }
  L->head_reset += ke0 - ke1;
  L->W_head = ke1 - L->KE_head0 + L->head_reset;
}

/* The head: stress-free particles of the bar's density beyond x = 0 (MPM_MAT_HEAD). */
static void bar_place_head(mpm_sim *s, const mpm_layout *l)
{
  const mpm_scene *sc = &s->sc;
  mpm_particles *p = s->p;
  const double d = l->h / l->n1, mp = s->mat[MPM_MAT_BAR].mp;
  const int n1 = l->n1, cy = l->cy;
  const size_t nbar = l->nbar, nhead = l->nhead;
  /* the same lattice continued over the head's cells beyond x = 0, moving with the grip */
  size_t k = nbar;
  for (int j = 0; nhead && j < cy * n1; j++)
    for (int i = -l->headc * n1; i < 0; i++, k++) {
      p->x[k] = p->x0[k] = (i + 0.5) * d;
      p->y[k] = p->y0[k] = (j + 0.5) * d;
      p->vx[k] = mpm_scene_start_vx(sc, p->x[k]); /* the head: the grip's speed */
      p->m[k] = mp;
      p->V[k] = d * d;
      p->mat[k] = MPM_MAT_HEAD;
    }
}

/* Every node column from the head's travel to x = 0 is gripped in x (rows 0..H); the
 * column x = L is held in x (uGIMP: the column beyond it too, which the bar's last
 * particles reach: the support is a wall, like the head on the left), its mid-height
 * node in y; held grips hold every one of those nodes in y as well. */
static int bar_bcs(const mpm_sim *s, const mpm_layout *l, mpm_bc *out)
{
  const mpm_grid *g = s->g;
  const int grip0 = l->nhead ? l->pad : l->padl, nfixcol = s->sc.shape == MPM_SHAPE_GIMP ? 2 : 1;
  const int held = s->sc.grips == MPM_GRIPS_HELD;
  int n = 0;
#define PUT(i, j, cmp, cc, fx)                                                                         \
  do {                                                                                             \
    if (out)                                                                                       \
      out[n] = (mpm_bc){(int)mpm_grid_node(g, (i), (j) + l->padv), (cmp), (fx), MPM_BC_ANY, (cc)};  \
    n++;                                                                                           \
  } while (0)
  for (int i = grip0; i <= l->padl; i++)
    for (int j = 0; j <= l->cy; j++)
      PUT(i, j, 0, -1.0, 0);
  for (int c = 0; c < nfixcol; c++)
    for (int j = 0; j <= l->cy; j++)
      PUT(l->padl + l->cx + c, j, 0, 0.0, 1);
  if (!held) {
    PUT(l->padl + l->cx, l->cy / 2, 1, 0.0, 0);
    return n;
  }
  for (int i = grip0; i <= l->padl; i++)
    for (int j = 0; j <= l->cy; j++)
      PUT(i, j, 1, 0.0, 0);
  for (int c = 0; c < nfixcol; c++)
    for (int j = 0; j <= l->cy; j++)
      PUT(l->padl + l->cx + c, j, 1, 0.0, 0);
#undef PUT
  return n;
}

static void bar_line_point(const mpm_sim *s, size_t imp, double *lx, double *ly)
{
  *lx = s->p->x0[imp];
  *ly = s->p->y0[imp];
}

/* U0 H / sin a: the line crosses the bar from y = 0 to y = H */
static double bar_dis_full(const mpm_scene *sc)
{
  const double sa = fabs(sin(sc->alpha_deg * (3.14159265358979323846 / 180.0)));
  return sc->U0 * sc->H / fmax(sa, 1e-3);
}

static double bar_dis_step_max(const mpm_scene *sc)
{
  return 0.1 * bar_dis_full(sc);
}

/* Once cut, the gripped part's vertical rigid motion: held at the gripped node nearest
 * mid-height (no force: the part is unloaded). */
static int bar_pin_node(const mpm_sim *s, const int *eq)
{
  int best = -1;
  double bd = INFINITY;
  for (int i = 0; i < s->nbc; i++) {
    const mpm_bc *b = &s->bc[i];
    if (b->comp != 0 || b->c == 0.0)
      continue;
    const size_t n = (size_t)b->node;
    const double y = s->g->oy + s->sc.h * (double)(n % (size_t)s->g->nny), d = fabs(y - 0.5 * s->sc.H);
    if (eq[2 * n] == MPM_DOF_GRIP && d < bd) {
      bd = d;
      best = (int)n;
    }
  }
  return best;
}

const mpm_specimen_type mpm_spec_bar = {
  .name = "bar",
  .left_cells = bar_left_cells,
  .place_head = bar_place_head,
  .step_end = bar_step_end,
  .start_velocity = bar_start_velocity,
  .rise_cells = bar_rise_cells,
  .bcs = bar_bcs,
  .line_point = bar_line_point,
  .dis_full = bar_dis_full,
  .dis_step_max = bar_dis_step_max,
  .precrack = NULL,
  .explicit_iface = 1,
  .seg_cells = 3.0,
  .pin_node = bar_pin_node,
};
