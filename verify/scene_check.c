/*
 * scene_check.c - validation of a parsed scene (scene.h: ver_scene_validate): every
 * key present that must be, the rules between keys (h divides L and H, ppc a square,
 * the CFL bound), sizes the kernel can allocate, and the kernel's own check; one line
 * file:line: section.key: what is wrong (what is allowed); the rules between the method
 * options are the kernel's (mpm_scene_rules).  And ver_scene_load: parse,
 * then validate.
 */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene.h"
#include "scene_keys.h"

/* "file:line" of key ki: its line, else its section's header, else the file's end. */
const char *ver_scene_key_at(const ver_scene *vs, int ki, char *buf, size_t len)
{
  int line = vs->line[ki];
  if (line < 0) {
    snprintf(buf, len, "%s: command line", vs->path);
    return buf;
  }
  if (!line)
    line = vs->sect_line[ver_scene_key_section(ver_scene_keys[ki].section)];
  if (!line)
    line = vs->nlines > 0 ? vs->nlines : 1;
  snprintf(buf, len, "%s:%d", vs->path, line);
  return buf;
}

int ver_scene_key_idx(const char *section, const char *key)
{
  const int i = ver_scene_key_find(section, key);
  assert(i >= 0);
  return i;
}

/* Every key that must be there is, and the defaults that depend on other keys. */
static int check_present(ver_scene *vs, char *err, size_t errlen)
{
  mpm_scene *sc = &vs->sc;
  char at[600];
  for (int i = 0; i < ver_scene_nkeys; i++) {
    const int need = ver_scene_keys[i].required == 1 || (ver_scene_keys[i].required == 2 && sc->model > 0) ||
                     (ver_scene_keys[i].required == 3 && sc->vib_mode == 0);
    if (need && !vs->seen[i]) {
      const int si = ver_scene_key_section(ver_scene_keys[i].section);
      snprintf(err, errlen, "%s: %s.%s: missing%s%s%s (%s)", ver_scene_key_at(vs, i, at, sizeof at), ver_scene_keys[i].section,
               ver_scene_keys[i].key, vs->sect_line[si] ? "" : ", and there is no [", vs->sect_line[si] ? "" : ver_scene_keys[i].section,
               vs->sect_line[si] ? "" : "] section", ver_scene_keys[i].allowed);
      return 2;
    }
  }
  if (!vs->seen[ver_scene_key_idx("decohesion", "s0")])
    sc->s0 = sc->snf;
  /* The static solver separates where the traction has gone (lambda 1): an equilibrium
   * path cannot cross the jump that dropping the last 2 % of it at 0.98 makes (the
   * explicit step's default; docs/static.md) */
  if (sc->solver == MPM_SOLVER_STATIC && !vs->seen[ver_scene_key_idx("decohesion", "separation")])
    sc->sep_threshold = 1.0;
  if (!vs->seen[ver_scene_key_idx("specimen", "a0")])
    sc->a0 = sc->specimen == MPM_SPEC_BAR ? 0.0 : sc->L / 3.0;
  if (!vs->seen[ver_scene_key_idx("imperfection", "x")])
    sc->imp_x = 0.5 * sc->L;
  if (!vs->seen[ver_scene_key_idx("imperfection", "y")])
    sc->imp_y = 0.5 * sc->H;
  if (sc->vib_mode > 0) {
    /* free vibration: the run lasts vibration.periods periods of the mode (unless
     * run.end_delta, e.g. --until, says otherwise), with 64 rows a period unless
     * output.interval says otherwise */
    const double T = ver_scene_vib_period(sc);
    if (!vs->seen[ver_scene_key_idx("run", "end_delta")])
      sc->end_delta = sc->speed * sc->vib_periods * T;
    if (vs->interval <= 0)
      vs->interval = sc->speed * T / 64.0;
  }
  if (vs->interval <= 0)
    vs->interval = 0.0005;
  return 0;
}

/* Grid and particle counts the kernel can allocate. */
static int check_sizes(const ver_scene *vs, char *err, size_t errlen)
{
  const mpm_scene *sc = &vs->sc;
  char at[600];
  /* Sizes first: the checks after them round L / h and H / h to integers. */
  const int hi = ver_scene_key_idx("grid", "h");
  ver_scene_key_at(vs, hi, at, sizeof at);
  const double nx = (sc->L + 2.0 * sc->margin) / sc->h + 4.0, ny = (sc->H + 2.0 * sc->margin) / sc->h + 4.0;
  if (!(nx * ny <= MAX_NODES)) {
    snprintf(err, errlen, "%s: grid.h: %g gives a grid of %.3g x %.3g nodes for bar.L, bar.H and grid.margin "
             "(allowed: at most %.0e nodes)", at, sc->h, nx, ny, MAX_NODES);
    return 2;
  }
  /* The grid also spans the grip's travel, to the left of the bar. */
  const double nt = sc->end_delta / sc->h;
  if (!((nx + nt) * ny <= MAX_NODES)) {
    snprintf(err, errlen, "%s: run.end_delta: %g is %.3g cells of grip travel at grid.h = %g, a grid of %.3g x %.3g "
             "nodes (allowed: at most %.0e nodes)", ver_scene_key_at(vs, ver_scene_key_idx("run", "end_delta"), at, sizeof at),
             sc->end_delta, nt, sc->h, nx + nt, ny, MAX_NODES);
    return 2;
  }
  return 0;
}

/* Time steps and output rows within bounds. */
static int check_steps(const ver_scene *vs, char *err, size_t errlen)
{
  const mpm_scene *sc = &vs->sc;
  char at[600];
  const double vdt = sc->speed * sc->dt;
  if (!(sc->end_delta / vdt <= MAX_STEPS)) {
    snprintf(err, errlen, "%s: run.end_delta: %g at loading.speed = %g and time.dt = %g takes %.3g time steps "
             "(allowed: at most %.0e)", ver_scene_key_at(vs, ver_scene_key_idx("run", "end_delta"), at, sizeof at), sc->end_delta,
             sc->speed, sc->dt, sc->end_delta / vdt, MAX_STEPS);
    return 2;
  }
  /* A row every max(interval, one step): the rows are held in memory until the end. */
  const int ii = ver_scene_key_idx("output", "interval");
  const double rows = sc->end_delta / fmax(vs->interval, vdt);
  if (!(rows <= MAX_ROWS)) {
    snprintf(err, errlen, "%s: output.interval: %g gives %.3g rows of load.csv to run.end_delta = %g "
             "(allowed: at most %.0e rows)", ver_scene_key_at(vs, ii, at, sizeof at), vs->interval, rows, sc->end_delta, MAX_ROWS);
    return 2;
  }
  if (!(vs->interval / vdt <= MAX_STEPS)) {
    snprintf(err, errlen, "%s: output.interval: %g is %.3g time steps (allowed: at most %.0e)",
             ver_scene_key_at(vs, ii, at, sizeof at), vs->interval, vs->interval / vdt, MAX_STEPS);
    return 2;
  }
  return 0;
}

double ver_scene_rate_ratio(const mpm_scene *sc)
{
  /* The bar takes L / c to feel the grip; in that time the grip adds the mean strain
   * speed / L * L / c = speed / c.  The load is quasi-static when that is small against
   * the strain at which the answer changes, the strain at initiation min(snf, stf) / E
   * (the smaller traction: the peak of any angle is at or above it).  Without decohesion
   * (model 0) nothing is peaked, and a free vibration uses speed as a time unit only. */
  if (sc->model == 0 || sc->vib_mode > 0)
    return 0.0;
  const double c = sqrt(sc->E / sc->rho), ep = fmin(sc->snf, sc->stf) / sc->E;
  return sc->speed / c / ep;
}

int ver_scene_validate(ver_scene *vs, char *err, size_t errlen)
{
  mpm_scene *sc = &vs->sc;
  char at[600];
  if (check_present(vs, err, errlen) || check_sizes(vs, err, errlen))
    return 2;
  const int hi = ver_scene_key_idx("grid", "h");
  ver_scene_key_at(vs, hi, at, sizeof at);
  /* h divides L and H (as the kernel rounds it), ppc is a square. */
  for (int d = 0; d < 2; d++) {
    const double len = d ? sc->H : sc->L, r = len / sc->h, n = round(r);
    if (!(n >= 1 && fabs(r - n) < 1e-9 * r)) {
      snprintf(err, errlen, "%s: grid.h: %g does not divide bar.%s = %g (allowed: h = %s / n for a whole n)", at,
               sc->h, d ? "H" : "L", len, d ? "H" : "L");
      return 2;
    }
  }
  const int n1 = (int)lround(sqrt((double)sc->ppc));
  if (n1 * n1 != sc->ppc) {
    snprintf(err, errlen, "%s: grid.ppc: %d is not a perfect square (allowed: 1, 4, 9, 16, ..., 1024)",
             ver_scene_key_at(vs, ver_scene_key_idx("grid", "ppc"), at, sizeof at), sc->ppc);
    return 2;
  }
  const double np = round(sc->L / sc->h) * round(sc->H / sc->h) * sc->ppc;
  if (np > MAX_PARTICLES) {
    snprintf(err, errlen, "%s: grid.h: %g with grid.ppc = %d gives %.3g particles (allowed: at most %.0e)",
             ver_scene_key_at(vs, hi, at, sizeof at), sc->h, sc->ppc, np, MAX_PARTICLES);
    return 2;
  }
  /* The imperfection is at the particle nearest (x, y): a point of the bar. */
  if (!(sc->imp_x >= 0 && sc->imp_x <= sc->L) || !(sc->imp_y >= 0 && sc->imp_y <= sc->H)) {
    const int x = !(sc->imp_x >= 0 && sc->imp_x <= sc->L);
    snprintf(err, errlen, "%s: imperfection.%s: %g is outside the bar (allowed: 0 <= %s <= bar.%s = %g)",
             ver_scene_key_at(vs, ver_scene_key_idx("imperfection", x ? "x" : "y"), at, sizeof at), x ? "x" : "y", x ? sc->imp_x : sc->imp_y,
             x ? "x" : "y", x ? "L" : "H", x ? sc->L : sc->H);
    return 2;
  }
  const double dtc = mpm_scene_dt_crit(sc);
  if (!(sc->dt < dtc) && !vs->allow_unstable) {
    snprintf(err, errlen, "%s: time.dt: %g is at or above the CFL bound h / (c sqrt 2) = %.4g (allowed: dt < %.4g, or --allow-unstable)",
             ver_scene_key_at(vs, ver_scene_key_idx("time", "dt"), at, sizeof at), sc->dt, dtc, dtc);
    return 2;
  }
  if (check_steps(vs, err, errlen))
    return 2;
  /* time.damping takes the share c dt of v - vbar out a step (mpm_damping.c): below 1, or
   * it would overshoot; and the nodal mass limit's v^L is not the node's velocity. */
  if (!(sc->damping * sc->dt < 1.0)) {
    snprintf(err, errlen, "%s: time.damping: %g with time.dt = %g takes %g of the velocity about its drift a step "
             "(allowed: below 1 / dt = %g)", ver_scene_key_at(vs, ver_scene_key_idx("time", "damping"), at, sizeof at),
             sc->damping, sc->dt, sc->damping * sc->dt, 1.0 / sc->dt);
    return 2;
  }
  /* the rules between the method options: the kernel's one function (kernel/mpm_rules.c) */
  const char *key;
  char why[700];
  if (mpm_scene_rules(sc, &key, why, sizeof why) != MPM_OK) {
    char sec[32];
    const char *dot = strchr(key, '.');
    snprintf(sec, sizeof sec, "%.*s", (int)(dot - key), key);
    snprintf(err, errlen, "%s: %s", ver_scene_key_at(vs, ver_scene_key_idx(sec, dot + 1), at, sizeof at), why);
    return 2;
  }
  /* Quasi-static: the grip must be slow against the wave speed (ver_scene_rate_ratio). */
  const double rr = ver_scene_rate_ratio(sc);
  if (!(rr <= VER_RATE_REFUSE)) {
    const double c = sqrt(sc->E / sc->rho), ep = rr > 0 ? sc->speed / c / rr : 0;
    snprintf(err, errlen, "%s: loading.speed: %g is not quasi-static: the grip moves a strain of speed / c = %.3g in one "
             "wave transit, %.3g times the strain at initiation %.3g (allowed: speed <= %.3g, that is speed / c at most %g "
             "times that strain)", ver_scene_key_at(vs, ver_scene_key_idx("loading", "speed"), at, sizeof at), sc->speed,
             sc->speed / c, rr, ep, VER_RATE_REFUSE * ep * c, VER_RATE_REFUSE);
    return 2;
  }
  /* The kernel's own check: every rule it has is above, so this is a backstop. */
  char e2[256];
  if (mpm_scene_check(sc, e2, sizeof e2) != MPM_OK) {
    snprintf(err, errlen, "%s:%d: %s", vs->path, vs->nlines > 0 ? vs->nlines : 1, e2);
    return 2;
  }
  return 0;
}

int ver_scene_load(const char *path, ver_scene *vs, char *err, size_t errlen)
{
  const int r = ver_scene_parse(path, vs, err, errlen);
  return r ? r : ver_scene_validate(vs, err, errlen);
}
