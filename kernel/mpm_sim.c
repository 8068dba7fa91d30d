/*
 * mpm_sim.c - setting up a run from a scene: the grid (only as large as the motion
 * needs), particles on a regular n x n subdivision of each cell, the materials with
 * the imperfection, and the specimen's constrained node components (its row of the
 * table, mpm_specimen.h: the paper's bar and its rigid head in mpm_spec_bar.c, the
 * split beams in mpm_spec_beam.c; the loads they give are read back in mpm_view.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_fields.h"
#include "mpm.h"
#include "mpm_kernel.h"
#include "mpm_gimp.h"
#include "mpm_iface.h"
#include "mpm_phase.h"
#include "mpm_specimen.h"

const char *mpm_strerror(mpm_status s)
{
  switch (s) {
  case MPM_OK: return "ok";
  case MPM_EINVAL: return "invalid input";
  case MPM_ENOMEM: return "out of memory";
  case MPM_ENOTFINITE: return "non-finite value";
  case MPM_EDOMAIN: return "particle left the grid";
  case MPM_EIO: return "i/o error";
  case MPM_EINTR: return "interrupted";
  case MPM_ESTALL: return "no equilibrium path onward";
  }
  return "unknown status";
}

/* The 2-D bound h / (c sqrt 2), not the 1-D h / c: measured on Fig. 6 (h 8,
 * 1 ppc, report's time-step sweep) the step is stable at 0.70 h/c and blows up from
 * 0.72 h/c, i.e. at 1/sqrt(2), as for bilinear elements with lumped mass. */
double mpm_scene_dt_crit(const mpm_scene *sc)
{
  const double E1 = sc->E / (1.0 - sc->nu * sc->nu);
  return sc->h / (sqrt(E1 / sc->rho) * sqrt(2.0));
}

/* n such that v / h = n within rounding, or -1. */
static long whole_cells(double v, double h)
{
  const double r = v / h;
  const long n = lround(r);
  return (n >= 1 && fabs(r - (double)n) < 1e-9 * r) ? n : -1;
}

mpm_status mpm_scene_check(const mpm_scene *sc, char *err, size_t errlen)
{
#define BAD(...) do { snprintf(err, errlen, __VA_ARGS__); return MPM_EINVAL; } while (0)
  if (!(sc->L > 0.0) || !(sc->H > 0.0)) BAD("bar: L and H must be > 0");
  if (!(sc->E > 0.0)) BAD("material.E must be > 0");
  if (!(sc->nu > -1.0 && sc->nu < 0.5)) BAD("material.nu must be in (-1, 0.5)");
  if (!(sc->rho > 0.0)) BAD("material.rho must be > 0");
  if (sc->model < 0 || sc->model > 2) BAD("decohesion.model must be 0, 1 or 2");
  if (sc->le_mode < MPM_LE_CELL || sc->le_mode > MPM_LE_ZONE) BAD("decohesion.Le must be cell, particle, staircase, row or zone");
  if (!(sc->le_factor > 0.0 && sc->le_factor <= 100.0)) BAD("decohesion.Le_factor must be in (0, 100]");
  if (sc->model) {
    if (!(sc->alpha_deg >= 0.0 && sc->alpha_deg < 180.0)) BAD("decohesion.alpha must be in [0, 180)");
    if (!(sc->snf > 0.0) || !(sc->stf > 0.0)) BAD("decohesion: snf and stf must be > 0");
    if (!(sc->U0 > 0.0) || !(sc->s0 > 0.0)) BAD("decohesion: U0 and s0 must be > 0");
    if (!(sc->q > 0.0)) BAD("decohesion.q must be > 0");
    if (!(sc->eta >= 0.0 && sc->eta <= 1e6)) BAD("decohesion.eta must be in [0, 1e6]");
    if (!(sc->sep_threshold > 0.0 && sc->sep_threshold <= 1.0)) BAD("decohesion.separation must be in (0, 1]");
    if (!(sc->imp_factor > 0.0 && sc->imp_factor <= 1.0)) BAD("imperfection.snf_factor must be in (0, 1]");
    if (!(sc->imp_stf_factor > 0.0 && sc->imp_stf_factor <= 1.0)) BAD("imperfection.stf_factor must be in (0, 1]");
    if (sc->imp_size != MPM_IMP_PARTICLE && sc->imp_size != MPM_IMP_CELL) BAD("imperfection.size must be particle or cell");
    if (sc->path < MPM_PATH_FREE || sc->path > MPM_PATH_IFACE) BAD("decohesion.path must be free, line or interface");
    if (sc->share != MPM_SHARE_STICK && sc->share != MPM_SHARE_LINE) BAD("decohesion.share must be stick or line");
  }
  if (!(sc->h > 0.0)) BAD("grid.h must be > 0");
  if (whole_cells(sc->L, sc->h) < 0 || whole_cells(sc->H, sc->h) < 0)
    BAD("grid.h = %g must divide L = %g and H = %g", sc->h, sc->L, sc->H);
  const int n = (int)lround(sqrt((double)sc->ppc));
  if (sc->ppc < 1 || n * n != sc->ppc) BAD("grid.ppc must be a perfect square (1, 4, 9, ...)");
  if (!(sc->margin >= 0.0)) BAD("grid.margin must be >= 0");
  if (sc->scheme < 0 || sc->scheme >= mpm_nschemes) BAD("time.scheme must be usl, musl, usf or usavg");
  if (sc->bc < MPM_BC_LAGRANGIAN || sc->bc > MPM_BC_CONSISTENT) BAD("grid.bc must be lagrangian, both or consistent");
  if (sc->node_mass != MPM_NODEMASS_LUMPED && sc->node_mass != MPM_NODEMASS_LIMITED) BAD("grid.node_mass must be lumped or limited");
  if (sc->head != MPM_HEAD_RIGID && sc->head != MPM_HEAD_NONE) BAD("loading.head must be rigid or none");
  if (sc->vib_mode < 0) BAD("vibration.mode must be >= 0");
  if (sc->vib_mode > 0 && !isfinite(sc->vib_amp)) BAD("vibration.amplitude must be finite");
  if (!isfinite(sc->body_amp) || !isfinite(sc->body_omega)) BAD("the body force must be finite");
  if (sc->body_amp != 0.0 && (sc->shape != MPM_SHAPE_LINEAR || sc->fields != MPM_FIELDS_ONE))
    BAD("a body force needs grid.shape = linear and grid.fields = one");
  if (sc->grid_motion != MPM_GRID_STRETCH && sc->grid_motion != MPM_GRID_FIXED) BAD("grid.motion must be stretch or fixed");
  if (sc->weights != MPM_WEIGHTS_CURRENT && sc->weights != MPM_WEIGHTS_LAID) BAD("grid.weights must be current or laid");
  if (sc->shape != MPM_SHAPE_LINEAR && sc->shape != MPM_SHAPE_GIMP) BAD("grid.shape must be linear or gimp");
  if (sc->fields != MPM_FIELDS_ONE && sc->fields != MPM_FIELDS_TWO) BAD("grid.fields must be one or two");
  if (!(sc->dt > 0.0)) BAD("time.dt must be > 0");
  if (!(sc->speed > 0.0)) BAD("loading.speed must be > 0");
  if (sc->control != MPM_CONTROL_GRIP && sc->control != MPM_CONTROL_DISSIPATION)
    BAD("loading.control must be grip or dissipation");
  if (!(sc->damping >= 0.0 && sc->damping * sc->dt < 1.0))
    BAD("time.damping must be >= 0 and below 1 / time.dt = %g", 1.0 / sc->dt);
  if (!(sc->damping_tau >= 0.0 && isfinite(sc->damping_tau))) BAD("time.damping_tau must be >= 0 (0: 2 L / c)");
  if (!(sc->damping_beta >= 0.0 && isfinite(sc->damping_beta))) BAD("time.damping_beta must be >= 0");
  if (sc->damping_from != MPM_DAMP_CUT && sc->damping_from != MPM_DAMP_START) BAD("time.damping_from must be cut or start");
  if (sc->damping_about != MPM_DAMP_DRIFT && sc->damping_about != MPM_DAMP_PARTS) BAD("time.damping_about must be drift or parts");
  if (!(sc->end_delta > 0.0)) BAD("run.end_delta must be > 0");
  return mpm_scene_rules(sc, NULL, err, errlen); /* the rules between options, last */
#undef BAD
}

void mpm_sim_free(mpm_sim *s)
{
  if (!s)
    return;
  mpm_particles_free(s->p);
  if (s->g)
    mpm_fields_free(s->g->fld);
  mpm_damping_free(s->damp);
  mpm_grid_free(s->g);
  if (s->dws)
    for (int t = 0; t < s->thr.nmax; t++)
      mpm_dwork_free(s->dws[t]);
  free(s->dws);
  free(s->defer);
  free(s->head);
  free(s->strip_start);
  free(s->key);
  free(s->perm);
  free(s->count);
  free(s->scratch);
  free(s->scratch8);
  free(s->bc);
  free(s->rowsep);
  free(s->led_part);
  mpm_band_free(s->band);
  free(s->ph);
  free(s);
}

/* The run's layout: the body's cells, the grid's padding, the particle counts. */
static mpm_layout layout_of(const mpm_scene *sc)
{
  mpm_layout l;
  const double h = l.h = sc->h;
  l.cx = (int)whole_cells(sc->L, h);
  l.cy = (int)whole_cells(sc->H, h);
  /* The grid is only as large as the motion needs: margin all round (at least one
   * cell), and on the left the grip's travel to end_delta besides. */
  l.pad = 1 + (int)ceil(sc->margin / h - 1e-9);
  int left;
  mpm_specimen_of(sc)->left_cells(sc, &left, &l.headc);
  l.padl = l.pad + left;
  l.padv = l.pad + mpm_specimen_of(sc)->rise_cells(sc);
  l.n1 = (int)lround(sqrt((double)sc->ppc));
  l.nbar = (size_t)l.cx * (size_t)l.cy * (size_t)sc->ppc;
  l.nhead = (size_t)l.headc * (size_t)l.cy * (size_t)sc->ppc;
  l.np = l.nbar + l.nhead;
  return l;
}

/* The grid and the arrays; 0 if one could not be made (mpm_sim_free frees the rest). */
static int alloc_arrays(mpm_sim *s, const mpm_scene *sc, const mpm_layout *l, int nthreads)
{
  const int cy = l->cy;
  const size_t nhead = l->nhead, np = l->np;
  s->g = mpm_grid_alloc(l->padl + l->cx + l->pad, cy + 2 * l->padv, -l->padl * l->h, -l->padv * l->h, l->h);
  s->nbc = s->g ? mpm_specimen_of(sc)->bcs(s, l, NULL) : 0;
  mpm_threads_init(&s->thr, nthreads, np);
  s->nthreads = s->thr.use;
  s->p = mpm_particles_alloc(np);
  if (s->p && ((sc->damping_beta > 0.0 && mpm_particles_alloc_viscous(s->p) != 0) ||
               (sc->weights == MPM_WEIGHTS_LAID && mpm_particles_alloc_laid(s->p) != 0))) {
    mpm_particles_free(s->p);
    s->p = NULL;
  }
  s->dws = calloc((size_t)s->thr.nmax, sizeof *s->dws);
  s->defer = calloc((size_t)s->thr.nmax, sizeof *s->defer);
  s->head = malloc((nhead ? nhead : 1) * sizeof *s->head);
  s->bc = s->g ? malloc(sizeof *s->bc * (size_t)(s->nbc ? s->nbc : 1)) : NULL;
  s->nrow = cy * (int)lround(sqrt((double)sc->ppc));
  s->rowsep = malloc((size_t)s->nrow);
  s->cut_seen = -1; /* count at the first step: a scene may start with separated particles */
  int ok = s->g && s->p && s->dws && s->defer && s->head && s->bc && s->rowsep;
  if (ok) {
    const size_t ncell = (size_t)s->g->ncx * (size_t)s->g->ncy;
    s->nstrip = (s->g->ncx + MPM_STRIP - 1) / MPM_STRIP;
    s->strip_start = calloc((size_t)s->nstrip + 1, sizeof(size_t));
    s->key = malloc(np * sizeof(uint32_t));
    s->perm = malloc(np * sizeof(uint32_t));
    s->count = malloc((ncell + 1) * sizeof(size_t));
    s->scratch = malloc(np * sizeof(double));
    s->scratch8 = malloc(np);
    s->led_part = calloc((size_t)s->nstrip, sizeof *s->led_part);
    ok = s->strip_start && s->key && s->perm && s->count && s->scratch && s->scratch8 && s->led_part;
    for (int t = 0; ok && t < s->thr.nmax; t++)
      ok = (s->dws[t] = mpm_dwork_alloc()) != NULL;
    if (ok && sc->fields == MPM_FIELDS_TWO) {
      ok = (s->g->fld = mpm_fields_alloc((size_t)s->g->nnx * (size_t)s->g->nny, s->plane.nx, s->plane.ny)) != NULL;
    }
  }
  return ok;
}

/* Le (decohesion.Le); ROW and ZONE: the band's rows as well.  0 if out of memory. */
static int le_setup(mpm_sim *s, const mpm_scene *sc, const mpm_layout *l, double *Le_out)
{
  const double h = l->h;
  const int n1 = l->n1;
  /* Le = V_e / A_d (eq. 41): for a square of side a crossed by a line at alpha,
   * a * max(|sin a|, |cos a|).  a = h (cell) or h / n (particle), docs/model.md sec. 6. */
  const double sa = s->plane.nx, ca = s->plane.tx;
  const double side = sc->le_mode == MPM_LE_PARTICLE ? h / n1 : h;
  /* STAIRCASE: on a grid of square cells a band along a line at angle a steps sideways
   * by one cell every cot a rows (a > 45 deg; tan a columns below), and the cell at each
   * step's corner has to strain with the band for it to open (a node there belongs to
   * both sides), so the narrowest band that can separate is 1 + |cot a| cells wide per
   * row: the band's volume per unit crack length is h (|sin a| + |cos a|). */
  const int rows = sc->le_mode == MPM_LE_ROW || sc->le_mode == MPM_LE_ZONE;
  const int stair = sc->le_mode == MPM_LE_STAIRCASE || rows;
  const double Le = sc->le_factor * (stair ? h * (fabs(sa) + fabs(ca)) : side * fmax(fabs(sa), fabs(ca)));
  /* ROW: each row starts from the staircase length and then measures its own
   * (mpm_band.c); a row is dy = h / n high and its particles dx = h / n wide.  ZONE: the
   * same, counting only the particles within 2 h + dx of the row's lead. */
  *Le_out = Le;
  return !rows || (s->band = mpm_band_alloc(s->nrow, s->nstrip, h / n1, sc->le_factor * (h / n1) * fabs(sa), Le,
                                         sc->le_mode == MPM_LE_ZONE ? 2.0 * h + h / n1 : 0.0)) != NULL;
}

/* The bar, its imperfection, the head (the loading machine), debris and the bar off the
 * crack's path. */
static void materials(mpm_sim *s, const mpm_scene *sc, double Le)
{
  mpm_material_init(&s->mat[MPM_MAT_BAR], sc, sc->snf, Le);
  mpm_material_init(&s->mat[MPM_MAT_IMP], sc, sc->snf * sc->imp_factor, Le);
  s->mat[MPM_MAT_IMP].stf *= sc->imp_stf_factor; /* a shear-governed scene's imperfection */
  mpm_material_derive(&s->mat[MPM_MAT_IMP]);
  mpm_material_init(&s->mat[MPM_MAT_HEAD], sc, sc->snf, Le);
  s->mat[MPM_MAT_HEAD].model = MPM_DCOH_NONE;            /* stress-free: it only carries mass */
  s->mat[MPM_MAT_HEAD].E1 = s->mat[MPM_MAT_HEAD].E2 = s->mat[MPM_MAT_HEAD].G = 0.0;
  mpm_material_derive(&s->mat[MPM_MAT_HEAD]);
  /* debris: the bar's constants (U0, Le: its D stays as it was), no stiffness, no
   * strength test (fn = ft = 0: the elastic trial always holds), no mass */
  s->mat[MPM_MAT_DEBRIS] = s->mat[MPM_MAT_BAR];
  s->mat[MPM_MAT_DEBRIS].model = MPM_DCOH_NONE; /* as the head: derive sets fn = ft = 0 */
  s->mat[MPM_MAT_DEBRIS].E1 = s->mat[MPM_MAT_DEBRIS].E2 = s->mat[MPM_MAT_DEBRIS].G = 0.0;
  mpm_material_derive(&s->mat[MPM_MAT_DEBRIS]);
  s->mat[MPM_MAT_ELASTIC] = s->mat[MPM_MAT_BAR];
  s->mat[MPM_MAT_ELASTIC].model = MPM_DCOH_NONE; /* fn = ft = 0: the elastic trial always holds */
  mpm_material_derive(&s->mat[MPM_MAT_ELASTIC]);
}

/* The bar's particles; returns the imperfection's (the particle nearest imp_x, imp_y). */
static size_t place_bar(mpm_sim *s, const mpm_scene *sc, const mpm_layout *l)
{
  const double h = l->h;
  const int n1 = l->n1, cx = l->cx, cy = l->cy;
  mpm_particles *p = s->p;
  const double d = h / n1, mp = sc->rho * d * d;
  for (int i = 0; i < 3; i++)
    s->mat[i].mp = mp; /* the head has the bar's density */
  s->mat[MPM_MAT_ELASTIC].mp = mp;
  s->mat[MPM_MAT_DEBRIS].mp = 0.0;
  size_t k = 0;
  double best = INFINITY;
  size_t imp = 0;
  for (int j = 0; j < cy * n1; j++)
    for (int i = 0; i < cx * n1; i++, k++) {
      p->x[k] = p->x0[k] = (i + 0.5) * d;
      p->y[k] = p->y0[k] = (j + 0.5) * d;
      mpm_specimen_of(sc)->start_velocity(sc, p->x[k], p->y[k], &p->vx[k], &p->vy[k]);
      if (sc->vib_mode > 0) /* free vibration: mode m of the bar held at both ends */
        p->vx[k] += sc->vib_amp * sin(sc->vib_mode * MPM_PI * p->x[k] / sc->L);
      p->m[k] = mp;
      p->V[k] = d * d;
      const double r2 = (p->x[k] - sc->imp_x) * (p->x[k] - sc->imp_x) +
                        (p->y[k] - sc->imp_y) * (p->y[k] - sc->imp_y);
      if (r2 < best - 1e-12) { /* ties go to the lowest index: deterministic */
        best = r2;
        imp = k;
      }
    }
  return imp;
}

/* The imperfection's material and the crack's path (decohesion.path); MPM_EINVAL when
 * share = line cannot be laid on a node column. */
static mpm_status mark_paths(mpm_sim *s, const mpm_scene *sc, const mpm_layout *l, size_t imp, char *err, size_t errlen)
{
  mpm_particles *p = s->p;
  const double h = l->h, d = h / l->n1;
  const size_t nbar = l->nbar;
  if (sc->model && (sc->imp_factor < 1.0 || sc->imp_stf_factor < 1.0)) {
    p->mat[imp] = MPM_MAT_IMP;
    /* imperfection.size = cell: the whole cell of that particle (the same lattice cell
     * index, so no rounding decides membership) */
    const long ci = (long)(p->x0[imp] / h), cj = (long)(p->y0[imp] / h);
    for (size_t q = 0; sc->imp_size == MPM_IMP_CELL && q < nbar; q++)
      if ((long)(p->x0[q] / h) == ci && (long)(p->y0[q] / h) == cj)
        p->mat[q] = MPM_MAT_IMP;
  }
  /* decohesion.path = line: the bar softens only within h (|sin a| + |cos a|) / 2 +
   * path_reach h of the line at alpha through the imperfection's particle (n . (X - X_imp),
   * n the failure plane's normal); at 1 ppc and path_reach 0, the cells the line crosses. */
  if (sc->model && sc->path == MPM_PATH_LINE) {
    const double sa = s->plane.ty, ca = s->plane.tx, w = mpm_scene_path_halfwidth(sc);
    for (size_t q = 0; q < nbar; q++)
      if (p->mat[q] == MPM_MAT_BAR && fabs(sa * (p->x0[q] - p->x0[imp]) - ca * (p->y0[q] - p->y0[imp])) > w)
        p->mat[q] = MPM_MAT_ELASTIC;
  }
  /* decohesion.path = interface: every particle elastic; the line through the
   * imperfection's particle carries the law (mpm_iface.c) */
  if (sc->model && sc->path == MPM_PATH_IFACE) {
    for (size_t q = 0; q < nbar; q++)
      p->mat[q] = MPM_MAT_ELASTIC;
    const double ifx = p->x0[imp];
    /* share = line: the crack, the edge between the two sides' particles, must lie on a
     * node column.  At alpha 90 the flaw's particle column lies on the line and joins the
     * first side (mpm_iface_side), so the crack runs along that column's far edge. */
    const double xc = ifx + 0.5 * d, col = xc / h;
    if (sc->share == MPM_SHARE_LINE && fabs(col - round(col)) > 1e-9) {
      snprintf(err, errlen,
               "decohesion.share = line: the interface's crack at x = %g (the edge of the flaw's particle column at x = %g) is "
               "not on a node column of h = %g; move imperfection.x (now %g) so that it is, or use share = stick",
               xc, ifx, h, sc->imp_x);
      return MPM_EINVAL;
    }
  }
  return MPM_OK;
}


/* Fails with MPM_ENOMEM and a message. */
static mpm_status nomem(mpm_sim *s, const char *what, char *err, size_t errlen)
{
  mpm_sim_free(s);
  snprintf(err, errlen, "out of memory for %s", what);
  return MPM_ENOMEM;
}

mpm_status mpm_sim_alloc(const mpm_scene *sc, int nthreads, mpm_sim **out, char *err, size_t errlen)
{
  *out = NULL;
  mpm_status st = mpm_scene_check(sc, err, errlen);
  if (st != MPM_OK)
    return st;
  mpm_sim *s = calloc(1, sizeof *s);
  if (!s)
    return MPM_ENOMEM;
  s->sc = *sc;
  s->plane = mpm_plane_of(sc);
  s->vgrip = sc->speed;
  s->ctl_D0 = INFINITY; /* dissipation control: the target starts at D (mpm_control.c) */
  const mpm_layout l = layout_of(sc);
  const mpm_specimen_type *spec = s->spec = mpm_specimen_of(sc);
  if (!alloc_arrays(s, sc, &l, nthreads)) {
    mpm_sim_free(s);
    snprintf(err, errlen, "out of memory for %zu particles", l.np);
    return MPM_ENOMEM;
  }
  double Le;
  if (!le_setup(s, sc, &l, &Le))
    return nomem(s, "the rows' Le", err, errlen);
  materials(s, sc, Le);
  s->nhead = l.nhead;
  const size_t imp = place_bar(s, sc, &l);
  if ((st = mark_paths(s, sc, &l, imp, err, errlen)) != MPM_OK) {
    mpm_sim_free(s);
    return st;
  }
  if (spec->place_head)
    spec->place_head(s, &l);
  s->grid_ox0 = s->g->ox;
  s->nbc = spec->bcs(s, &l, s->bc);
  /* the explicit step holds a node's one velocity: a condition on one side of the line
   * (the split beams' node on the line at an arm's end) is left out, the node is free */
  if (sc->solver == MPM_SOLVER_EXPLICIT) {
    int j = 0;
    for (int i = 0; i < s->nbc; i++)
      if (s->bc[i].side == MPM_BC_ANY)
        s->bc[j++] = s->bc[i];
    s->nbc = j;
  }
  s->crack_tip = s->zone_end = spec->precrack ? sc->a0 : NAN;
  s->gap_min = INFINITY;
  spec->line_point(s, imp, &s->line_x, &s->line_y);
  if (sc->model && sc->path == MPM_PATH_IFACE && (spec->explicit_iface || sc->solver == MPM_SOLVER_EXPLICIT) &&
      !(s->g->fld->ifc = mpm_iface_alloc(s, s->line_x, s->line_y)))
    return nomem(s, "the interface's arrays", err, errlen);
  if (sc->damping > 0.0 && !(s->damp = mpm_damping_alloc(s)))
    return nomem(s, "the damping's node arrays", err, errlen);
  if (mpm_step_setup(s) != MPM_OK)
    return nomem(s, "the step's phases", err, errlen);
  for (size_t i = l.nbar; i < l.np; i++)
    s->led.KE_head0 += 0.5 * s->p->m[i] * (s->p->vx[i] * s->p->vx[i] + s->p->vy[i] * s->p->vy[i]);
  mpm_sim_sort(s);
  *out = s;
  return MPM_OK;
}

double mpm_scene_path_halfwidth(const mpm_scene *sc)
{
  const mpm_plane pl = mpm_plane_of(sc);
  return 0.5 * sc->h * (fabs(pl.nx) + fabs(pl.tx)) + sc->path_reach * sc->h;
}

mpm_plane mpm_plane_of(const mpm_scene *sc)
{
  const double a = sc->alpha_deg * (MPM_PI / 180.0);
  return (mpm_plane){a, sin(a), -cos(a), cos(a), sin(a)};
}
