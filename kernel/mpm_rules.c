/*
 * mpm_rules.c - the rules between method options, in one place: what each option needs
 * of the others (the interface, share = line, laid weights, the viscous stress, damping
 * with the nodal mass limit).  The kernel's mpm_scene_check and the scene checker
 * (verify/scene_check.c, which puts the file and line of the key in front) both call
 * mpm_scene_rules; each message starts with the key at fault and names the allowed values.
 */
#include <math.h>
#include <stdio.h>

#include "mpm.h"
#include "mpm_kernel.h"

/* The scene files' words of the enumerated options, for messages. */
static const char *word(int v, const char *const *w, int n)
{
  return v >= 0 && v < n ? w[v] : "?";
}
static const char *const SHAPE[] = {"linear", "gimp"};
static const char *const FIELDS[] = {"one", "two"};
static const char *const MOTION[] = {"fixed", "stretch"};
static const char *const PATH[] = {"free", "line", "interface"};
#define W(v, t) word(v, t, (int)(sizeof t / sizeof t[0]))

/* path = interface: what mpm_iface.c implements, no more. */
static const char *iface_rules(const mpm_scene *sc, char *err, size_t len)
{
  if (sc->fields != MPM_FIELDS_TWO || sc->shape != MPM_SHAPE_GIMP || sc->scheme != MPM_SCHEME_MUSL ||
      sc->model != MPM_DCOH_MODEL1 || (sc->q != 1.0 && sc->solver != MPM_SOLVER_STATIC) || sc->s0 != sc->snf ||
      sc->eta != 0.0) {
    snprintf(err, len, "decohesion.path: interface needs grid.fields = two, grid.shape = gimp, time.scheme = musl and "
             "Model 1 with q = 1 (any q with solver.type = static), s0 = snf, eta = 0 (here: fields %s, shape %s, scheme %s, model %d, q %g, s0 %g, "
             "snf %g, eta %g; allowed otherwise: path = free or line)", W(sc->fields, FIELDS), W(sc->shape, SHAPE),
             mpm_scheme_name(sc->scheme), sc->model, sc->q, sc->s0, sc->snf, sc->eta);
    return "decohesion.path";
  }
  if (sc->specimen != MPM_SPEC_BAR) /* the split beams' line: specimen_rules */
    return NULL;
  const mpm_plane pl = mpm_plane_of(sc);
  const double c = pl.tx / pl.nx;
  if (!(pl.nx > 0.0) || !(sc->imp_x - sc->imp_y * c > 0.0 && sc->imp_x - sc->imp_y * c < sc->L &&
                           sc->imp_x + (sc->H - sc->imp_y) * c > 0.0 && sc->imp_x + (sc->H - sc->imp_y) * c < sc->L)) {
    snprintf(err, len, "decohesion.alpha: %g with path = interface: the line at alpha through the imperfection's "
             "point (%g, %g) must cross the bar from y = 0 to y = H inside 0 < x < L (allowed: an angle and point "
             "that do, or path = free or line)", sc->alpha_deg, sc->imp_x, sc->imp_y);
    return "decohesion.alpha";
  }
  return NULL;
}

/* The specimens' own needs (kernel/mpm_specimen.h). */
static const char *const SPEC[] = {"bar", "dcb", "els"};
static const char *specimen_rules(const mpm_scene *sc, char *err, size_t len)
{
  if (sc->specimen < MPM_SPEC_BAR || sc->specimen > MPM_SPEC_ELS) {
    snprintf(err, len, "specimen.type must be bar, dcb or els");
    return "specimen.type";
  }
  if (sc->grips != MPM_GRIPS_ROLLERS && (sc->grips != MPM_GRIPS_HELD || sc->specimen != MPM_SPEC_BAR)) {
    snprintf(err, len, "specimen.grips: held is the bar's (here: type %s; allowed: rollers)", W(sc->specimen, SPEC));
    return "specimen.grips";
  }
  if (sc->specimen == MPM_SPEC_BAR)
    return NULL;
  /* the split beams: the interface along y = H / 2 on a node row */
  const double rows = 0.5 * sc->H / sc->h;
  if (!sc->model || sc->path != MPM_PATH_IFACE || sc->alpha_deg != 0.0 || fabs(rows - round(rows)) > 1e-9 * rows ||
      (sc->solver == MPM_SOLVER_EXPLICIT && sc->specimen != MPM_SPEC_DCB)) {
    snprintf(err, len, "specimen.type: %s needs decohesion.path = interface with model 1, alpha = 0, H / 2 on a node "
             "row, and solver.type = static unless it is the dcb (here: solver %s, path %s, model %d, alpha %g, H / 2 / "
             "h = %g)", W(sc->specimen, SPEC), sc->solver == MPM_SOLVER_STATIC ? "static" : "explicit",
             W(sc->path, PATH), sc->model, sc->alpha_deg, rows);
    return "specimen.type";
  }
  if (!(sc->a0 > 0.0 && sc->a0 < sc->L)) {
    snprintf(err, len, "specimen.a0: %g must be in (0, L = %g): the pre-crack's length", sc->a0, sc->L);
    return "specimen.a0";
  }
  return NULL;
}

mpm_status mpm_scene_rules(const mpm_scene *sc, const char **key, char *err, size_t len)
{
  const char *k = specimen_rules(sc, err, len);
  /* the viscous stress is measured stable with MUSL only (usl: fig8.ini's beta = h / c
   * throws a particle off the grid after the cut at h 4, 1 ppc; usf, usavg: two strain
   * passes) */
  if (!k && sc->damping_beta > 0.0 && sc->scheme != MPM_SCHEME_MUSL) {
    snprintf(err, len, "time.damping_beta: %g needs time.scheme = musl (here: %s; allowed: 0 with %s)", sc->damping_beta,
             mpm_scheme_name(sc->scheme), mpm_scheme_name(sc->scheme));
    k = "time.damping_beta";
  }
  if (!k && sc->model && sc->path == MPM_PATH_IFACE)
    k = iface_rules(sc, err, len);
  /* share = line is built for a line along a node column that the grid follows (the
   * crack's column is checked when the particles are laid) */
  if (!k && sc->model && sc->share == MPM_SHARE_LINE &&
      (sc->path != MPM_PATH_IFACE || sc->alpha_deg != 90.0 || sc->grid_motion != MPM_GRID_STRETCH)) {
    snprintf(err, len, "decohesion.share: line needs decohesion.path = interface, alpha = 90 and grid.motion = stretch "
             "(here: path %s, alpha %g, motion %s; allowed otherwise: share = stick)", W(sc->path, PATH), sc->alpha_deg,
             W(sc->grid_motion, MOTION));
    k = "decohesion.share";
  }
  /* the laid places are carried by the grid's stretch */
  if (!k && sc->weights == MPM_WEIGHTS_LAID && sc->grid_motion != MPM_GRID_STRETCH) {
    snprintf(err, len, "grid.weights: laid needs grid.motion = stretch (here: motion %s; allowed otherwise: weights = "
             "current)", W(sc->grid_motion, MOTION));
    k = "grid.weights";
  }
  /* the nodal mass limit's v^L is not the node's velocity, which the damping relaxes */
  if (!k && sc->damping > 0.0 && sc->node_mass == MPM_NODEMASS_LIMITED && sc->shape == MPM_SHAPE_LINEAR &&
      (sc->scheme == MPM_SCHEME_USL || sc->scheme == MPM_SCHEME_USAVG)) {
    snprintf(err, len, "time.damping: %g needs grid.node_mass = lumped with usl or usavg on linear shapes (allowed: 0 "
             "here, or another node_mass, scheme or shape)", sc->damping);
    k = "time.damping";
  }
  if (key)
    *key = k;
  return k ? MPM_EINVAL : MPM_OK;
}
