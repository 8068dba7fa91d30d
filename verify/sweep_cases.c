/*
 * sweep_cases.c - the cases of `delam verify` (sweep.h): the quick list or every
 * scene x h x ppc, each case's scene with the overrides `delam run` gets, its analytic
 * bar (ver_scene_bar) and end displacement; and reading back what a run left.
 */
#include <assert.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io.h"
#include "metrics.h"
#include "summary.h"
#include "sweep.h"

static const ver_variant V_BASE = {"", NULL, 0, 0, 0};
static const ver_variant V_LEP = {"Leparticle", "decohesion.Le=particle", 0, 0, 0};
static const ver_variant V_SEP8 = {"sep0.8", "decohesion.separation=0.8", 0, 0, 0};
/* the scene's whole run (its end_delta, no early stop) for the energy balance to the end */
static const ver_variant V_WHOLE = {"whole", "run.stop_margin=0", 1, 0, 0};
/* fig6.ini's grip speed 0.001 halved and quartered: the speed refined with h
 * (v = 0.001 h / 8) and the rate study at fixed h (policy.c policy_rate) */
static const ver_variant V_V2 = {"v0.0005", "loading.speed=0.0005", 0, 1, 0};
static const ver_variant V_V4 = {"v0.00025", "loading.speed=0.00025", 0, 2, 0};
/* the quasi-static solver (docs/static.md): equilibrium increments, no grip speed */
static const ver_variant V_STATIC = {"static", "solver.type=static", 0, 0, 0};
/* --angles: an inclined file with only its laminate angle changed, and with its two
 * failure tractions snf and stf exchanged as well (the other mode: Mode I by strengths
 * becomes Mode II and back): the method must hold for the bands and modes the
 * files were not written for.  A file's own angle in its own mode is --full's case and is
 * left out; in the other mode it is kept (its alpha restated). */
#define V_NANGLE 4
static const double V_ANGLE_DEG[V_NANGLE] = {30, 45, 60, 75};
static const ver_variant V_ANGLES[2 * V_NANGLE] = {
  {"a30", "decohesion.alpha=30", 0, 0, 0},       {"a45", "decohesion.alpha=45", 0, 0, 0},
  {"a60", "decohesion.alpha=60", 0, 0, 0},       {"a75", "decohesion.alpha=75", 0, 0, 0},
  {"a30-swap", "decohesion.alpha=30", 0, 0, 1}, {"a45-swap", "decohesion.alpha=45", 0, 0, 1},
  {"a60-swap", "decohesion.alpha=60", 0, 0, 1}, {"a75-swap", "decohesion.alpha=75", 0, 0, 1},
};

/* The scene file with the same overrides `delam run --h H --ppc N --set ...` applies
 * (cmd_run.c: dt scaled with h to keep the file's Courant number). */
static int build_scene(const char *path, double h, int ppc, char sets[][128], int nset, ver_scene *vs,
                       char *err, size_t len)
{
  if (ver_scene_parse(path, vs, err, len))
    return 2;
  char buf[128];
  if (h > 0) {
    const double dt = vs->sc.dt * h / vs->sc.h;
    snprintf(buf, sizeof buf, "grid.h=%.17g", h);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
    snprintf(buf, sizeof buf, "time.dt=%.17g", dt);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
  }
  if (ppc > 0) {
    snprintf(buf, sizeof buf, "grid.ppc=%d", ppc);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
  }
  for (int i = 0; i < nset; i++)
    if (ver_scene_set(vs, sets[i], err, len))
      return 2;
  return ver_scene_validate(vs, err, len);
}

/* The static solver's refusal (ver_static_refusal, delam run's own), so that the sweep lists
 * such a case as refused instead of running it into a failure.  0, or 1 with the reason. */
static int static_refusal(const mpm_scene *sc, char *buf, size_t len)
{
  return ver_static_refusal(sc, buf, len) != 0;
}

int ver_case_a90(const ver_case *c)
{
  return fabs(c->vs.sc.alpha_deg - 90.0) < 1e-9;
}

void ver_case_wave(ver_case *c, const double *delta, const double *P, size_t n)
{
  const mpm_scene *sc = &c->vs.sc;
  c->curve_wave = c->wave_peak = c->rate_floor = NAN;
  if (c->have_ana)
    c->curve_wave = ver_curve_err_wave(&c->ana, sc->speed, sc->rho, sc->imp_x, sc->sep_threshold, delta, P, n,
                                       ver_curve_end(&c->ana, sc->sep_threshold), NULL, &c->wave_peak,
                                       &c->rate_floor);
}

/* Sets up case c: id, overrides, the analytic bar and the end displacement.
 * end_delta covers separation with margin (the run stops itself stop_margin past
 * separation, and the grid is sized to end_delta, so it is kept as small as is safe):
 * 4 x the analytic delta_sep, at least 1, for alpha = 90; inclined bands dissipate
 * several times U0 per area (paper, Fig. 7) and separate later: at least 1.2, past
 * every separation measured (0.61 to 0.87 on h = 2 and 4); a band that has not cut the
 * bar by then is reported as not separating. */
int ver_case_init(ver_case *c, const char *path, const char *scene, const char *method, double h, int ppc,
                  ver_variant v, char *err, size_t len)
{
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  snprintf(c->scene, sizeof c->scene, "%s", scene);
  c->var = v;
  c->h = h;
  c->ppc = ppc;
  c->exit_code = -1;
  c->delta_sep = NAN;
  if (method) /* first: the variant's own key holds over it */
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "method.preset=%s", method);
  if (v.set)
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "%s", v.set);
  if (build_scene(path, h, ppc, c->sets, c->nset, &c->vs, err, len))
    return 2;
  char swap[2][sizeof c->sets[0]]; /* the file's own tractions exchanged: the other mode */
  if (v.swap) {
    snprintf(swap[0], sizeof swap[0], "decohesion.snf=%.17g", c->vs.sc.stf);
    snprintf(swap[1], sizeof swap[1], "decohesion.stf=%.17g", c->vs.sc.snf);
    for (int i = 0; i < 2; i++)
      memcpy(c->sets[c->nset++], swap[i], sizeof swap[i]);
    if (build_scene(path, h, ppc, c->sets, c->nset, &c->vs, err, len))
      return 2;
  }
  char aerr[256];
  double mult = 4.0, least = 1.0;
  if (c->vs.sc.model > 0 && ver_scene_bar(&c->vs.sc, &c->ana, aerr, sizeof aerr) == 0) {
    c->have_ana = 1;
    if (!ver_case_a90(c))
      least = 1.2;
    c->end_delta = v.whole ? c->vs.sc.end_delta : fmax(least, mult * c->ana.delta_sep);
  } else {
    c->end_delta = c->vs.sc.end_delta;
  }
  c->nset = 0;
  if (method)
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "method.preset=%s", method);
  /* one snapshot at delta 0 stands for none: an empty list is refused by the scene
   * reader, and snapshots later than separation would keep the run going */
  snprintf(c->sets[c->nset++], sizeof c->sets[0], "output.snapshots=0");
  snprintf(c->sets[c->nset++], sizeof c->sets[0], "run.end_delta=%.6g", c->end_delta);
  /* twice the load check's settling past separation, so that load_after_sep reads
   * rows from VER_LOAD_SETTLE to 2 VER_LOAD_SETTLE (policy.c) */
  if (c->vs.stop_margin > 0.0 && c->vs.stop_margin < 2.0 * VER_LOAD_SETTLE)
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "run.stop_margin=%.6g", 2.0 * VER_LOAD_SETTLE);
  if (v.set)
    snprintf(c->sets[c->nset++], sizeof c->sets[0], "%s", v.set);
  for (int i = 0; v.swap && i < 2; i++)
    memcpy(c->sets[c->nset++], swap[i], sizeof swap[i]);
  assert(c->nset <= VER_MAXSET);
  if (build_scene(path, h, ppc, c->sets, c->nset, &c->vs, err, len))
    return 2;
  char base[100];
  ver_scene_base_id(&c->vs, base, sizeof base);
  snprintf(c->id, sizeof c->id, "%s%s%s%s%s", base, method ? "-" : "", method ? method : "",
           v.suffix[0] ? "-" : "", v.suffix);
  const mpm_scene *sc = &c->vs.sc;
  static_refusal(sc, c->refused, sizeof c->refused);
  /* the nodes a particle reaches (4 bilinear, 9 uGIMP) times the velocity fields: the
   * interface's explicit step costs 4.4 times the paper's per particle and step
   * (iface90 against fig6 at h 1, 9 ppc: 339 and 77 s), so that the sweep, costliest
   * first, starts the long runs first and ends on short ones */
  const double stencil = (sc->shape == MPM_SHAPE_GIMP ? 9.0 : 4.0) / 4.0 * (sc->fields == MPM_FIELDS_TWO ? 2.0 : 1.0);
  c->cost = (sc->L / sc->h) * (sc->H / sc->h) * sc->ppc * (c->end_delta / (sc->speed * sc->dt)) * stencil;
  return 0;
}

static int cmp_str(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The *.ini files of folder dir, sorted, into names (at most room, each malloc'd);
 * their number, or -1 with a message on stderr. */
static int scene_files(const char *dir, char **names, int room)
{
  DIR *d = opendir(dir);
  if (!d) {
    fprintf(stderr, "delam verify: %s: cannot open the scene folder: %s\n", dir, strerror(errno));
    return -1;
  }
  int nn = 0;
  struct dirent *e;
  while ((e = readdir(d)) && nn < room) {
    const size_t l = strlen(e->d_name);
    if (l > 4 && !strcmp(e->d_name + l - 4, ".ini") && e->d_name[0] != '.')
      names[nn++] = strdup(e->d_name);
  }
  closedir(d);
  qsort(names, (size_t)nn, sizeof names[0], cmp_str);
  return nn;
}

/* --full's split beam (specimen.type dcb in its file, static): the file and the ELS
 * (specimen.type els, its tractions exchanged: mode II) at h 4, 2, 1 and 4 and 1 ppc,
 * judged by the specimen checks (check_spec.c, 1 ppc's known limits ver_spec_policy);
 * the held bar's file (held 1) at 4 ppc alone (the static solver refuses its band at 1
 * ppc: a cell's one point leaves hourglass modes). */
static const ver_variant V_ELS = {"els", "specimen.type=els", 0, 0, 1};
static int beam_cases(const ver_verify_opts *o, const char *path, const char *scene, int held, ver_case *cs, int *n,
                      char *err, size_t errlen)
{
  static const double hs[] = {4, 2, 1};
  for (int k = 0; k < (held ? 1 : 2); k++)
    for (int a = 0; a < 6; a++) {
      if (held && a >= 3) /* the static solver refuses the held bar's band at 1 ppc (hourglass modes) */
        break;
      if (ver_case_init(&cs[*n], path, scene, o->method, hs[a % 3], a < 3 ? 4 : 1, k ? V_ELS : V_BASE, err, errlen)) {
        fprintf(stderr, "delam verify: %s\n", err);
        return 2;
      }
      (*n)++;
    }
  return 0;
}

/* --full's rate-refined sequence of Fig. 6's bar (the quick list's, policy_cross.c
 * policy_rate): 1 ppc at h 4 with the speed halved and quartered, and at h 2 quartered,
 * beside the file's h 8 (v = 0.001 h / 8).  The paper's band model has no exact solution
 * at a finite grip speed, so this is the sequence its convergence is judged on (about
 * 20 CPU s). */
static int rate_cases(const ver_verify_opts *o, const char *path, const char *scene, ver_case *cs, int *n)
{
  static const struct {
    double h;
    const ver_variant *v;
  } r[] = {{4, &V_V2}, {2, &V_V4}, {4, &V_V4}};
  char err[1024];
  for (int i = 0; i < 3; i++) {
    if (ver_case_init(&cs[*n], path, scene, o->method, r[i].h, 1, *r[i].v, err, sizeof err)) {
      fprintf(stderr, "delam verify: %s\n", err);
      return 2;
    }
    (*n)++;
  }
  return 0;
}

/* 1 if the file at path is not a bar's to sweep (sf its scene): a free-vibration scene
 * (vibration.mode > 0) is not a bar pulled to separation, nor a split beam (specimen.type
 * dcb, els; docs/specimens.md): the analytic bar's checks do not apply to them (the
 * vibration's own: kernel tests; the beams' cases under --full: beam_cases); --angles
 * takes the inclined files only (alpha 90 is the grid's own direction). */
static int other_file(const ver_verify_opts *o, const char *path, const char *scene, ver_case *cs, int *n,
                      ver_scene *sf, int *rc)
{
  char err[1024];
  if (ver_scene_parse(path, sf, err, sizeof err) != 0)
    return 0;
  if ((sf->sc.specimen != MPM_SPEC_BAR || sf->sc.grips == MPM_GRIPS_HELD) && !o->angles) {
    *rc = beam_cases(o, path, scene, sf->sc.grips == MPM_GRIPS_HELD, cs, n, err, sizeof err);
    return 1;
  }
  return sf->sc.vib_mode > 0 || sf->sc.specimen != MPM_SPEC_BAR || sf->sc.grips == MPM_GRIPS_HELD ||
         (o->angles && (sf->sc.model == 0 || fabs(sf->sc.alpha_deg - 90.0) < 1e-9));
}

/* 1 if --full leaves case c out because cheaper cases imply its verdicts: the explicit
 * interface (uGIMP, two fields, MUSL) at h 1 with 9 ppc, 300-460 s a run, a third of
 * the sweep's time.  There 9 ppc gives what 4 ppc gives at h 1 and 9 ppc at h 2 (iface90:
 * curve_wave 0.0040 at h 1 with 4 and 9 ppc, peak -0.11 and -0.10 %; fig7 and a45: the
 * same known-limit k_soft; docs/sweeps.md).  The static solver keeps h 1 at 9 ppc (30-
 * 100 s), and so does fig6 (the paper's method, 80 s). */
static int implied_case(const ver_verify_opts *o, const ver_case *c)
{
  const mpm_scene *sc = &c->vs.sc;
  return o->full && !c->var.set && c->h == 1.0 && c->ppc == 9 && sc->path == MPM_PATH_IFACE &&
         sc->solver != MPM_SOLVER_STATIC;
}

/* The case list: the quick subset, every scene of the folder x h x ppc, or the
 * inclined scenes at other angles. */
int ver_sweep_cases(const ver_verify_opts *o, ver_case **out, int *nout)
{
  char err[1024];
  ver_case *cs = NULL;
  int n = 0;
  if (!o->full && !o->angles) {
    static const struct {
      const char *scene;
      double h;
      int ppc;
      const ver_variant *v;
    } q[] = {
      {"fig6", 8, 1, &V_BASE}, {"fig6", 8, 4, &V_BASE}, {"fig6", 4, 4, &V_BASE},
      {"fig6", 4, 1, &V_BASE}, {"fig6", 2, 4, &V_BASE},
      {"fig6", 8, 4, &V_LEP},  {"fig6", 8, 4, &V_SEP8},
      {"fig7", 4, 4, &V_BASE}, {"fig6", 8, 1, &V_WHOLE},
      /* one inclined GCI (policy.c): three grids in ratio 2 at 1 ppc, about 10 s */
      {"fig7", 8, 1, &V_BASE}, {"fig7", 4, 1, &V_BASE}, {"fig7", 2, 1, &V_BASE},
      /* the rate: h 8, 4, 2 at v = 0.001 h / 8, and h 4 at v 0.001, 0.0005, 0.00025 (1 ppc) */
      {"fig6", 4, 1, &V_V2}, {"fig6", 2, 1, &V_V4}, {"fig6", 4, 1, &V_V4},
      /* Fig. 6's bar on the interface against the exact solution at its grip speed */
      {"iface90", 4, 1, &V_BASE},
      /* the quasi-static solver on the band and on the interface (a second each) */
      {"fig6", 8, 4, &V_STATIC}, {"fig6", 4, 4, &V_STATIC}, {"iface90", 8, 4, &V_STATIC},
      {"fig8", 8, 4, &V_STATIC}, /* a snapback traced back (g 0.45), about a second */
      /* the double cantilever beam (static by its file): a moving front against data/fe */
      {"dcb", 4, 4, &V_BASE},
    };
    const int nq = (int)(sizeof q / sizeof q[0]);
    cs = calloc((size_t)nq, sizeof *cs);
    if (!cs)
      return 2;
    for (int i = 0; i < nq; i++) {
      char path[600];
      if (!strcmp(q[i].scene, "dcb") && o->method && strcmp(o->method, "interface")) /* interface alone */
        continue;
      snprintf(path, sizeof path, "%s/%s.ini", o->scenes, q[i].scene);
      if (ver_case_init(&cs[n], path, q[i].scene, o->method, q[i].h, q[i].ppc, *q[i].v, err, sizeof err)) {
        fprintf(stderr, "delam verify: %s\n", err);
        free(cs);
        return 2;
      }
      n++;
    }
  } else {
    char *names[256];
    int nn = scene_files(o->scenes, names, 256);
    if (nn < 0)
      return 2;
    static const double hs[] = {8, 4, 2, 1}, hs_angles[] = {4, 2};
    static const int ps[] = {1, 4, 9}, ps_angles[] = {1, 4};
    const double *hv = o->angles ? hs_angles : hs;
    const int *pv = o->angles ? ps_angles : ps;
    const int nh = o->angles ? 2 : 4, np = o->angles ? 2 : 3, na = o->angles ? 2 * V_NANGLE : 2;
    cs = calloc((size_t)(nn * nh * np * na + 4), sizeof *cs);
    int rc = cs ? 0 : 2;
    for (int i = 0; i < nn && !rc; i++) {
      char path[600], scene[64];
      snprintf(path, sizeof path, "%s/%s", o->scenes, names[i]);
      snprintf(scene, sizeof scene, "%.*s", (int)strlen(names[i]) - 4, names[i]);
      ver_scene sf;
      if (other_file(o, path, scene, cs, &n, &sf, &rc))
        continue;
      if (o->full && !strcmp(scene, "fig6"))
        rc = rate_cases(o, path, scene, cs, &n);
      for (int k = 0; k < na && !rc; k++) {
        const ver_variant *v = o->angles ? &V_ANGLES[k] : k ? &V_STATIC : &V_BASE;
        if (o->angles && !v->swap && fabs(sf.sc.alpha_deg - V_ANGLE_DEG[k % V_NANGLE]) < 1e-9)
          continue; /* the file's own angle and mode: --full's case */
        for (int a = 0; a < nh && !rc; a++)
          for (int b = 0; b < np && !rc; b++) {
            if (ver_case_init(&cs[n], path, scene, o->method, hv[a], pv[b], *v, err, sizeof err)) {
              fprintf(stderr, "delam verify: %s\n", err);
              rc = 2;
            } else if (!implied_case(o, &cs[n]))
              n++;
          }
      }
    }
    for (int i = 0; i < nn; i++)
      free(names[i]);
    if (rc) {
      free(cs);
      return rc;
    }
    if (n == 0) {
      if (!o->merge_found) /* merging what a folder holds: no angles list is no error */
        fprintf(stderr, "delam verify: %s: no %sscene files (*.ini)\n", o->scenes, o->angles ? "inclined " : "");
      free(cs);
      return 2;
    }
  }
  *out = cs;
  *nout = n;
  return 0;
}

void ver_case_dir(const ver_verify_opts *o, const ver_case *c, char *buf, size_t len)
{
  snprintf(buf, len, "%s/%s", o->outdir, c->id);
}

/* Reads what the run left in DIR/<id>/ and measures from it. */
void ver_case_read(const ver_verify_opts *o, ver_case *c)
{
  char dir[800], path[900];
  ver_case_dir(o, c, dir, sizeof dir);
  c->peak_P = c->delta_peak = c->delta_sep = c->k_elastic = NAN;
  c->D_final = c->W_ext_final = c->energy_residual = c->energy_unbooked = c->delta_end = NAN;
  c->W_booked = 0.0;
  c->W_scheme = NAN;
  c->curve_path = c->delta5 = NAN;
  c->k_soft = c->curve_l2 = c->curve_wave = c->wave_peak = c->rate_floor = c->band_width = c->band_extent = c->angle = c->D_diffuse = c->P_after = c->P_after_t = c->P_after_c = NAN;
  if (c->refused[0]) { /* never run: nothing to read */
    snprintf(c->error, sizeof c->error, "refused: %s", c->refused);
    return;
  }
  ver_summary_doc sd;
  if (ver_summary_read(dir, &sd) == 0) {
    const ver_summary *u = &sd.u;
    c->have_summary = 1;
    c->complete = u->complete;
    if (sd.error[0] && !c->error[0])
      snprintf(c->error, sizeof c->error, "%s", sd.error);
    c->peak_P = u->peak_P;
    c->delta_peak = u->delta_peak;
    c->delta_sep = u->delta_sep;
    if (c->delta_sep < 0)
      c->delta_sep = NAN; /* -1: no separation detected before end_delta */
    c->k_elastic = u->k_elastic;
    c->D_final = u->D_final;
    c->W_ext_final = u->W_ext_final;
    c->energy_residual = u->energy_residual;
    c->energy_unbooked = u->energy_unbooked;
    c->W_booked = ver_summary_booked(u);
    c->W_scheme = ver_summary_scheme_loss(u);
    c->delta_end = u->delta_end;
    if (c->exit_code < 0)
      c->wall_s = u->wall_s;
  }
  if (!c->error[0]) {
    snprintf(path, sizeof path, "%s/error.txt", dir);
    char *et = ver_io_slurp(path, NULL, 1 << 16);
    if (et) {
      char *nl = strchr(et, '\n');
      if (nl)
        *nl = '\0';
      snprintf(c->error, sizeof c->error, "%s", et);
      free(et);
    }
  }
  if (!c->have_summary && !c->error[0]) {
    if (c->term_sig)
      snprintf(c->error, sizeof c->error, "killed by signal %d (%s); no summary.json", c->term_sig,
               strsignal(c->term_sig));
    else
      snprintf(c->error, sizeof c->error, "no summary.json in %.400s (not run, or the run crashed)", dir);
  }
  if (c->term_sig && c->have_summary)
    c->complete = 0;
  static const char *const lcols[] = {"delta", "P_grip"};
  double *lc[2];
  snprintf(path, sizeof path, "%s/load.csv", dir);
  const long nl = ver_csv_read(path, lcols, 2, lc);
  if (nl > 0 && c->have_ana) {
    c->k_soft = ver_softening_slope(lc[0], lc[1], (size_t)nl, VER_SOFT_HI, VER_SOFT_LO);
    const int pts = c->vs.sc.solver == MPM_SOLVER_STATIC;
    c->curve_l2 = ver_curve_err_bar(&c->ana, lc[0], lc[1], (size_t)nl, ver_curve_end(&c->ana, c->vs.sc.sep_threshold), NULL, pts);
    c->curve_path = pts ? ver_curve_path(&c->ana, lc[0], lc[1], (size_t)nl, &c->delta5) : NAN;
    ver_case_wave(c, lc[0], lc[1], (size_t)nl);
  }
  if (nl > 0)
    c->P_after = ver_load_after(lc[0], lc[1], (size_t)nl, c->delta_sep, c->peak_P, &c->P_after_t, &c->P_after_c);
  for (int k = 0; k < 2; k++)
    free(lc[k]);
  static const char *const fcols[] = {"x0", "y0", "lambda"};
  double *fc[3];
  snprintf(path, sizeof path, "%s/final.csv", dir);
  const long nf = ver_csv_read(path, fcols, 3, fc);
  if (nf > 0) {
    const mpm_scene *sc = &c->vs.sc;
    const double thr = VER_BAND_LAMBDA;
    c->band_width = ver_band_width(fc[0], fc[1], fc[2], (size_t)nf, thr, sc->alpha_deg, sc->h, sc->ppc, sc->H,
                                   &c->band_extent, &c->band_count);
    c->angle = ver_crack_angle(fc[0], fc[1], fc[2], (size_t)nf, sc->sep_threshold);
    if (c->have_ana && c->ana.D_sep > 0.0)
      c->D_diffuse = ver_diffuse_share(fc[2], (size_t)nf, thr) * c->D_final / c->ana.D_sep;
  }
  for (int k = 0; k < 3; k++)
    free(fc[k]);
}

/* Keeps the cases whose folder DIR holds; their number. */
static int keep_found(const ver_verify_opts *o, ver_case *cs, int n)
{
  int m = 0;
  for (int i = 0; i < n; i++) {
    char dir[1200];
    struct stat st;
    ver_case_dir(o, &cs[i], dir, sizeof dir);
    if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode))
      cs[m++] = cs[i];
  }
  return m;
}


/* With o->merge_found: the cases of every list (quick, then full, then angles) whose
 * folders DIR holds.  Frees *out on failure. */
int ver_sweep_found(const ver_verify_opts *o, ver_case **out, int *nout)
{
  ver_case *cs = *out;
  int n = *nout;
  for (int list = 0; list < 2; list++) {
    ver_case *cq;
    int nq;
    ver_verify_opts q = *o;
    q.full = list == 0;
    q.angles = list == 1;
    const int mk = ver_sweep_cases(&q, &cq, &nq);
    if (mk && list == 1) /* a folder without inclined scenes has no angles list */
      continue;
    if (mk) {
      free(cs);
      return mk;
    }
    ver_case *all = realloc(cs, (size_t)(n + nq) * sizeof *cs);
    if (!all) {
      free(cs);
      free(cq);
      return 2;
    }
    cs = all;
    for (int i = 0; i < nq; i++) {
      int dup = 0;
      for (int j = 0; j < n && !dup; j++)
        dup = !strcmp(cs[j].id, cq[i].id);
      if (!dup)
        cs[n++] = cq[i];
    }
    free(cq);
  }
  n = keep_found(o, cs, n);
  if (n == 0) {
    fprintf(stderr, "delam verify: %s holds no case folder of the quick, full or angles list\n", o->outdir);
    free(cs);
    return 2;
  }
  *out = cs;
  *nout = n;
  return 0;
}
