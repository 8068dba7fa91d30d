/*
 * report_cases.c - the cases behind the figures of `delam report` (report.h): the
 * pictures (each paper scene from its own file), the h x ppc sweep (joined by the runs
 * of the verify folder), the time-step sweep, the snapback scenes, the separation
 * threshold and the USL/MUSL pair; and finding them again.
 */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "scene.h"
#include "summary.h"

#define PROG "delam report"

const char *const rep_sweep_scene[REP_NSWEEP] = {"fig6", "fig7", "fig8"};
const double rep_sweep_until[REP_NSWEEP] = {0.6, 1.2, 1.2};
static const double stab_ratio[] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.72, 0.74, 0.76, 0.78, 0.8, 0.9, 1.0, 1.1};
#define NSTAB (int)(sizeof stab_ratio / sizeof stab_ratio[0])

/* h / c, the 1-D bound: the unit of the time-step sweep, so that the figure
 * shows where the step really fails (1/sqrt(2) of it).  The kernel validates the 2-D
 * bound mpm_scene_dt_crit() = h / (c sqrt 2). */
double ver_report_dt_crit(const rep_ctx *r, const char *scene, double h)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0)
    return NAN;
  vs.sc.h = h;
  return sqrt(2.0) * mpm_scene_dt_crit(&vs.sc);
}

/* Does the scene table know time.scheme=musl (the modified-USL option)? */
static int knows_musl(const rep_ctx *r)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%s/fig6.ini", r->scenes);
  if (ver_scene_parse(path, &vs, err, sizeof err) != 0)
    return 0;
  return ver_scene_set(&vs, "time.scheme=musl", err, sizeof err) == 0;
}

/* The sweep case of (scene, h, ppc), or -1. */
int ver_report_find_sweep(const rep_ctx *r, const char *scene, double h, int ppc)
{
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if ((c->role & REP_SWEEP) && !strcmp(c->scene, scene) && c->h == h && c->ppc == ppc)
      return i;
  }
  return -1;
}

/* 1 if the run used its scene file's own method (scheme, shape, fields, Le, path, grid
 * motion, separation threshold, damping, grip speed): only such runs join the sweep, not
 * verify's variants (the rate study's slower grip would join the work-precision line
 * otherwise). */
static int same_method(const rep_ctx *r, const ver_summary_doc *sd)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, sd->scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0)
    return 0;
  const struct {
    const char *run, *sect, *key;
  } m[7] = {{sd->scheme, "time", "scheme"},   {sd->shape, "grid", "shape"},
            {sd->fields, "grid", "fields"},   {sd->le, "decohesion", "Le"},
            {sd->damping_from, "time", "damping_from"}, {sd->path, "decohesion", "path"},
            {sd->motion, "grid", "motion"}};
  for (int i = 0; i < 7; i++)
    if (m[i].run[0] && strcmp(m[i].run, ver_scene_word(&vs, m[i].sect, m[i].key)))
      return 0;
  const double damping = isfinite(sd->damping) ? sd->damping : 0.0;
  if (isfinite(sd->path_reach) && !strcmp(sd->path, "line") && sd->path_reach != vs.sc.path_reach)
    return 0;
  return (!isfinite(sd->sep_threshold) || sd->sep_threshold == vs.sc.sep_threshold) && damping == vs.sc.damping &&
         (!isfinite(sd->speed) || sd->speed == vs.sc.speed);
}

/* --from DIR: every DIR/<case>/summary.json run with the scene's defaults joins the sweep;
 * of two at one h and ppc the shorter run (verify's "-whole" variant runs on to the
 * scene's end_delta, and its CPU time put fig6's h 8 point right of h 4 in the
 * work-precision chart). */
static int scan_from(report *R)
{
  rep_ctx *r = &R->r;
  DIR *d = opendir(r->from);
  int n = 0;
  if (!d)
    return 0;
  const struct dirent *e;
  while ((e = readdir(d)) && r->n < REP_MAX_CASES) {
    if (e->d_name[0] == '.')
      continue;
    rep_case tmp;
    memset(&tmp, 0, sizeof tmp);
    snprintf(tmp.dir, sizeof tmp.dir, "%.800s/%.200s", r->from, e->d_name);
    if (ver_report_read_summary(&tmp) != 0 || !tmp.complete)
      continue;
    ver_summary_doc sd;
    if (ver_summary_read(tmp.dir, &sd) != 0)
      continue;
    /* the quasi-static solver's runs are no points of the explicit sweep */
    int ok = !sd.u.static_run && sd.scene[0] && isfinite(sd.h) && sd.ppc > 0 && isfinite(sd.dt) && same_method(r, &sd);
    /* the paper's time step only: dt / h as in the scene file */
    if (ok) {
      const double crit = ver_report_dt_crit(r, sd.scene, sd.h);
      const double ref = ver_report_dt_crit(r, sd.scene, 8.0);
      ok = isfinite(crit) && fabs(sd.dt / crit - 0.1 / ref) < 1e-6;
    }
    const int old = ok ? ver_report_find_sweep(r, sd.scene, sd.h, sd.ppc) : -1;
    if (old >= 0 && !(r->c[old].reused && tmp.delta_end < r->c[old].delta_end))
      ok = 0;
    if (ok) {
      rep_case *c = old >= 0 ? &r->c[old] : &r->c[r->n++];
      *c = tmp;
      snprintf(c->id, sizeof c->id, "%.80s", e->d_name);
      if (ver_report_find(r, c->id) != c - r->c)
        snprintf(c->id, sizeof c->id, "%.80s@verify", e->d_name);
      snprintf(c->scene, sizeof c->scene, "%.31s", sd.scene);
      c->h = sd.h;
      c->ppc = sd.ppc;
      c->speed = sd.speed;
      c->role = REP_SWEEP;
      c->have = c->reused = 1;
      c->exit_status = 0;
      c->last_snap = -1;
      c->curve_err = c->max_dev = c->diss_err = c->k_soft = c->drop_width = NAN;
      n += old < 0;
    }
  }
  closedir(d);
  return n;
}

/* 1 if the scene file's own method is not the paper's (and the keys exist to say so). */
static int needs_paper_run(const rep_ctx *r, const char *scene)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0)
    return 0;
  const mpm_scene own = vs.sc;
  for (int i = 0; i < VER_PAPER_NSETS; i++)
    if (ver_scene_set(&vs, ver_paper_sets[i], err, sizeof err) != 0)
      return 0;
  /* whatever the paper's overrides change (a field list here missed each key they gained) */
  return memcmp(&own, &vs.sc, sizeof own) != 0;
}

/* 1 if the scene file is inclined and its own path is not the interface, and the
 * interface takes the file as it is but for the path (docs/methods.md). */
static int needs_iface_run(const rep_ctx *r, const char *scene)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0 || vs.sc.alpha_deg == 90.0 || vs.sc.path == MPM_PATH_IFACE)
    return 0;
  return ver_scene_set(&vs, "decohesion.path=interface", err, sizeof err) == 0 &&
         ver_scene_validate(&vs, err, sizeof err) == 0;
}

/* The band method's overrides (ver_band_sets) of a scene file whose own path is the
 * interface, into sets; returns how many, 0 where the file does not run the interface,
 * the scene has no band method or it does not validate. */
static int band_sets(const rep_ctx *r, const char *scene, const char *sets[VER_BAND_NSETS])
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0 || vs.sc.path != MPM_PATH_IFACE)
    return 0;
  const char *const *bs;
  const int n = ver_band_sets(scene, &bs);
  for (int i = 0; i < n; i++)
    if (ver_scene_set(&vs, sets[i] = bs[i], err, sizeof err) != 0)
      return 0;
  return n > 0 && ver_scene_validate(&vs, err, sizeof err) == 0 ? n : 0;
}

/* 1 if the scene file loads. */
static int has_scene(const rep_ctx *r, const char *scene)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  return ver_scene_load(path, &vs, err, sizeof err) == 0;
}

/* The grid of a scene file (h 8, 1 ppc if it does not load). */
static void scene_grid(const rep_ctx *r, const char *scene, double *h, int *ppc)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%.900s/%.60s.ini", r->scenes, scene);
  const int ok = ver_scene_load(path, &vs, err, sizeof err) == 0;
  *h = ok ? vs.sc.h : 8;
  *ppc = ok ? vs.sc.ppc : 1;
}

void ver_report_build_cases(report *R)
{
  rep_ctx *r = &R->r;
  /* pictures: each paper scene as its file says (its grid, scheme, all its snapshots),
   * so that every picture shows the scene file it names */
  static const char *const pics[3] = {"fig6", "fig7", "fig8"};
  for (int i = 0; i < 3; i++) {
    double h = 0;
    int ppc = 0;
    scene_grid(r, pics[i], &h, &ppc);
    ver_report_add(r, pics[i], h, ppc, 0, 0, NULL, NULL, i == 2 ? REP_PIC | REP_SNAP : REP_PIC, 0);
    /* Figs. 7(d) and 8(c) also with the paper's method where the scene file chooses
     * another (the same run otherwise, so it is not repeated) */
    if (i > 0 && needs_paper_run(r, pics[i]))
      ver_report_add_sets(r, pics[i], h, ppc, 0, 0, ver_paper_sets, VER_PAPER_NSETS, REP_PAPER, 0);
    /* and with the crack as a cohesive interface, the method beyond the paper that meets
     * the inclined-crack bounds most often (docs/methods.md) */
    if (i > 0 && needs_iface_run(r, pics[i]))
      ver_report_add(r, pics[i], h, ppc, 0, 0, "decohesion.path=interface", NULL, REP_IFACE, 0);
  }
  /* sweep over h and particles per cell, to a little past separation */
  const int from_n = r->from[0] ? scan_from(R) : 0;
  R->sweep_from = from_n;
  if (from_n)
    fprintf(stderr, PROG ": %d runs of %s join the h x ppc sweep\n", from_n, r->from);
  /* the sweep's points that --from does not have are run here */
  for (int s = 0; s < REP_NSWEEP; s++)
      for (int ppc = 1; ppc <= 9; ppc += ppc == 1 ? 3 : 5)
        /* 9 ppc at h = 2 only where it is cheap (fig6 stops at 0.6): inclined runs to 1.2
         * at h = 2 with 9 ppc cost ~28 CPU-s each, a fifth of the report's budget */
        for (double h = 8; h >= (ppc == 1 ? 1 : ppc == 9 && s > 0 ? 4 : 2); h /= 2)
          if (ver_report_find_sweep(r, rep_sweep_scene[s], h, ppc) < 0)
            ver_report_add(r, rep_sweep_scene[s], h, ppc, 0, rep_sweep_until[s], NULL, NULL, REP_SWEEP, 0);
  /* the inclined scenes' 1-ppc sweep also with the paper's method, where the scene file
   * chooses another (work-precision: one line per method; tag 1 tells them from the
   * pictures' paper-method runs) */
  for (int s = 1; s < REP_NSWEEP; s++)
    if (needs_paper_run(r, rep_sweep_scene[s]))
      for (double h = 8; h >= 2; h /= 2)
        ver_report_add_sets(r, rep_sweep_scene[s], h, 1, 0, rep_sweep_until[s], ver_paper_sets, VER_PAPER_NSETS, REP_PAPER, 1);
  /* and with the interface (tag 1: the work-precision line) */
  for (int s = 1; s < REP_NSWEEP; s++)
    if (needs_iface_run(r, rep_sweep_scene[s]))
      for (double h = 8; h >= 2; h /= 2)
        ver_report_add(r, rep_sweep_scene[s], h, 1, 0, rep_sweep_until[s], "decohesion.path=interface", NULL, REP_IFACE, 1);
  /* and, where the file runs the interface, with the band method (tag 1: its line) */
  for (int s = 1; s < REP_NSWEEP; s++) {
    const char *bs[VER_BAND_NSETS];
    const int nb = band_sets(r, rep_sweep_scene[s], bs);
    if (nb > 0)
      for (double h = 8; h >= 2; h /= 2)
        ver_report_add_sets(r, rep_sweep_scene[s], h, 1, 0, rep_sweep_until[s], bs, nb, REP_BAND, 1);
  }
  /* Fig. 6's bar on the interface (iface90.ini), the model with an exact solution at the
   * grip speed, beside fig6.ini's 1-ppc sweep (report_text.c, figure "rate") */
  if (has_scene(r, "iface90"))
    for (double h = 8; h >= 1; h /= 2)
      ver_report_add(r, "iface90", h, 1, 0, rep_sweep_until[0], NULL, NULL, REP_WAVE, 0);
  /* time-step sweep: fig6, h = 8, 1 ppc, to delta 0.5 */
  const double crit = ver_report_dt_crit(r, "fig6", 8);
  for (int i = 0; i < NSTAB; i++)
    ver_report_add(r, "fig6", 8, 1, stab_ratio[i] * crit, 0.5, NULL, NULL, REP_STAB, stab_ratio[i]);
  /* snapback scenes (g < 1) on two grids */
  for (double h = 4; h >= 2; h /= 2) {
    ver_report_add(r, "a45", h, 1, 0, 0, NULL, NULL, REP_SNAP, 0);
    ver_report_add(r, "a30", h, 1, 0, 0, NULL, NULL, REP_SNAP, 0);
  }
  /* separation threshold */
  ver_report_add(r, "fig6", 8, 4, 0, 0.6, "decohesion.separation=0.98", NULL, REP_SEP, 0.98);
  ver_report_add(r, "fig6", 8, 4, 0, 0.6, "decohesion.separation=0.8", NULL, REP_SEP, 0.8);
  /* usl vs musl on an inclined scene, if the option exists.  The interface is MUSL's
   * only (mpm_iface.c): where a scene file runs it, the pair is the band method's
   * (band_sets).  time.damping_beta needs MUSL (mpm_sim.c): USL runs the file's damping
   * without it. */
  r->have_musl = knows_musl(r);
  if (r->have_musl) {
    static const char *const pair[2] = {"fig7", "fig8"}; /* at h 4, 1 ppc, to delta 1 */
    for (int i = 0; i < 2; i++) {
      const char *sc = pair[i], *usl[2 + VER_BAND_NSETS] = {"time.scheme=usl", "time.damping_beta=0"}, *musl[1 + VER_BAND_NSETS] = {"time.scheme=musl"};
      const char *bs[VER_BAND_NSETS];
      const int nb = band_sets(r, sc, bs);
      for (int k = 0; k < nb; k++)
        usl[2 + k] = musl[1 + k] = bs[k];
      ver_report_add_sets(r, sc, 4, 1, 0, 1.0, usl, 2 + nb, REP_SCHEME, 0);
      ver_report_add_sets(r, sc, 4, 1, 0, 1.0, musl, 1 + nb, REP_SCHEME, 1);
    }
  }
  /* the quasi-static solver: the snapback scenes and Fig. 3's bars (report_qs.c) */
  ver_report_qs_cases(r);
  /* the split beams, static by their file (report_spec.c) */
  ver_report_spec_cases(r);
}

const rep_case *ver_report_first(const rep_ctx *r, int role, const char *scene)
{
  for (int i = 0; i < r->n; i++)
    if ((r->c[i].role & role) && !strcmp(r->c[i].scene, scene))
      return &r->c[i];
  return NULL;
}

const rep_case *ver_report_case(const rep_ctx *r, const char *id)
{
  const int k = ver_report_find(r, id);
  return k >= 0 && r->c[k].have ? &r->c[k] : NULL;
}

const rep_case *ver_report_role_at(const rep_ctx *r, int mask, double h, int ppc)
{
  const rep_case *q = NULL;
  for (int i = 0; i < r->n; i++)
    if ((r->c[i].role & mask) && r->c[i].have && r->c[i].h == h && r->c[i].ppc == ppc)
      q = &r->c[i];
  return q;
}

const rep_case *ver_report_sweep(const rep_ctx *r, const char *scene, double h, int ppc)
{
  const int k = ver_report_find_sweep(r, scene, h, ppc);
  return k >= 0 && r->c[k].have ? &r->c[k] : NULL;
}

