/*
 * mpm_spec_beam.c - the split beams of delamination testing: the bar [0, L] x [0, H]
 * as two arms H / 2 thick, bonded along y = H / 2 by the interface's law from x = a0 to
 * L, the part x < a0 a pre-crack (faces free, in frictionless contact where they press).
 * - dcb, the double cantilever beam (mode I; ASTM D5528): each arm's end face x = 0
 *   held at u_y = +-delta / 2 with u_x free (no moment), the far end free; the point
 *   (L, H / 2) held in x and y, which removes the rigid motion without a reaction
 *   (symmetry and equilibrium).  P is the force on one arm (work-conjugate to delta,
 *   the arms' opening).
 * - els, the end-loaded split (mode II; ISO 15114): the far end x = L clamped, both arm
 *   ends moved by the same u_y = delta, u_x free.  P is the force on both arms.
 * Static only (solver.type = static; mpm_rules.c): the line lies on a node row, one
 * segment of the interface per node.
 */
#include <math.h>

#include "mpm_specimen.h"

static void beam_left_cells(const mpm_scene *sc, int *left, int *head)
{
  (void)sc;
  *left = *head = 0;
}

/* The node columns an end face's particles reach: x = 0, and with uGIMP the column
 * before it. */
static int face_cols(const mpm_scene *sc)
{
  return sc->shape == MPM_SHAPE_GIMP ? 2 : 1;
}

/* The arms' end faces at c_lo (lower arm) and c_hi (upper arm) times delta in y; the
 * node on the line belongs to both, one slot each (the lower arm is on the far side of
 * the line, whose normal is (0, -1) at alpha 0). */
static int arm_faces(const mpm_sim *s, const mpm_layout *l, double c_lo, double c_hi, mpm_bc *out, int n)
{
  const mpm_grid *g = s->g;
  const int mid = l->cy / 2;
  for (int c = face_cols(&s->sc) - 1; c >= 0; c--)
    for (int j = 0; j <= l->cy; j++) {
      const int node = (int)mpm_grid_node(g, l->padl - c, j + l->padv);
      if (j <= mid) {
        if (out)
          out[n] = (mpm_bc){node, 1, 0, j == mid ? MPM_BC_FAR : MPM_BC_ANY, c_lo};
        n++;
      }
      if (j >= mid) {
        if (out)
          out[n] = (mpm_bc){node, 1, 0, j == mid ? MPM_BC_NEAR : MPM_BC_ANY, c_hi};
        n++;
      }
    }
  return n;
}

static int dcb_bcs(const mpm_sim *s, const mpm_layout *l, mpm_bc *out)
{
  int n = arm_faces(s, l, -0.5, 0.5, out, 0);
  const int pin = (int)mpm_grid_node(s->g, l->padl + l->cx, l->cy / 2 + l->padv);
  for (int cmp = 0; cmp < 2; cmp++) {
    if (out)
      out[n] = (mpm_bc){pin, (uint8_t)cmp, (uint8_t)(cmp == 0), MPM_BC_ANY, 0.0};
    n++;
  }
  return n;
}

static int els_bcs(const mpm_sim *s, const mpm_layout *l, mpm_bc *out)
{
  int n = arm_faces(s, l, 1.0, 1.0, out, 0);
  for (int c = 0; c < face_cols(&s->sc); c++)
    for (int j = 0; j <= l->cy; j++)
      for (int cmp = 0; cmp < 2; cmp++) {
        if (out)
          out[n] = (mpm_bc){(int)mpm_grid_node(s->g, l->padl + l->cx + c, j + l->padv), (uint8_t)cmp,
                            (uint8_t)(cmp == 0), MPM_BC_ANY, 0.0};
        n++;
      }
  return n;
}

static void beam_line_point(const mpm_sim *s, size_t imp, double *lx, double *ly)
{
  (void)imp;
  *lx = s->sc.a0;
  *ly = 0.5 * s->sc.H;
}

static double beam_dis_full(const mpm_scene *sc)
{
  return sc->U0 * (sc->L - sc->a0);
}

static double beam_dis_step_max(const mpm_scene *sc)
{
  return sc->U0 * sc->h;
}

/* The DCB's arms as cantilevers clamped at the pre-crack's tip, each end moving at
 * +-speed / 2: v_y = +-(speed / 2) (1 - x / a0)^2 (2 + x / a0) / 2 for x < a0 (the
 * deflection of an end-loaded cantilever over its end's), 0 beyond; the ELS's both arms
 * the same way at +speed (explicit runs: the DCB's) */
static void beam_start_velocity(const mpm_scene *sc, double x, double y, double *vx, double *vy)
{
  const double r = x < sc->a0 ? 1.0 - x / sc->a0 : 0.0, shape = 0.5 * r * r * (3.0 - r);
  const double c = sc->specimen == MPM_SPEC_DCB ? (y < 0.5 * sc->H ? -0.5 : 0.5) : 1.0;
  *vx = 0.0;
  *vy = c * sc->speed * shape;
}

/* the arms' ends travel delta / 2 (DCB) or delta (ELS) in y, to end_delta */
static int beam_rise_cells(const mpm_scene *sc)
{
  const double rise = sc->specimen == MPM_SPEC_DCB ? 0.5 * sc->end_delta : sc->end_delta;
  return (int)ceil(rise / sc->h - 1e-9);
}

static int beam_precrack(const mpm_scene *sc, double x, double y)
{
  (void)y;
  return x < sc->a0;
}

static int beam_pin_node(const mpm_sim *s, const int *eq)
{
  (void)s;
  (void)eq;
  return -1;
}

const mpm_specimen_type mpm_spec_dcb = {
  .name = "dcb",
  .left_cells = beam_left_cells,
  .bcs = dcb_bcs,
  .line_point = beam_line_point,
  .dis_full = beam_dis_full,
  .dis_step_max = beam_dis_step_max,
  .start_velocity = beam_start_velocity,
  .rise_cells = beam_rise_cells,
  .precrack = beam_precrack,
  .explicit_iface = 0,
  .seg_cells = 0.0,
  .pin_node = beam_pin_node,
};

const mpm_specimen_type mpm_spec_els = {
  .name = "els",
  .left_cells = beam_left_cells,
  .bcs = els_bcs,
  .line_point = beam_line_point,
  .dis_full = beam_dis_full,
  .dis_step_max = beam_dis_step_max,
  .start_velocity = beam_start_velocity,
  .rise_cells = beam_rise_cells,
  .precrack = beam_precrack,
  .explicit_iface = 0,
  .seg_cells = 0.0,
  .pin_node = beam_pin_node,
};
