/*
 * cmd_bench.c - `delam bench`: kernel speed on fixed cases.
 *
 * Each case starts from the exact quasi-static uniaxial state at 99 % of the analytic
 * peak stress r0 (uniform sxx, the matching displacements and velocity field), so that
 * the timed steps cross the peak and decohesion is active in them, with no untimed
 * warm-up of tens of thousands of steps.  Reported: particles, steps, wall and CPU
 * seconds, particle-updates per second (particles x steps / wall), the time split
 * (sort, particle-to-grid, grid update, grid-to-particle, constitutive update) and the
 * bytes per particle.  Reproduce a single case outside the bench with, e.g.,
 *   /usr/bin/time -v build/delam run data/scenes/fig6.ini --h 1 --ppc 4 --until 0.1 --threads 1
 * (its "Maximum resident set size" and "Elapsed" lines; that run includes output rows).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cjson/cJSON.h>

#include "ana.h"
#include "cmd.h"
#include "io.h"
#include "mpm.h"
#include "datadir.h"
#include "scene.h"

/* Each case names its method in full (the scene files' defaults may change). */
typedef struct {
  const char *scene;
  double h;
  int ppc;
  long steps;
  const char *method; /* label in the case id                                   */
  const char *sets;   /* the method: overrides, separated by spaces              */
  int cut;            /* 1: start with a separated band across the bar (cut_band) */
  int base;           /* what goes before sets: BENCH_FILE, BENCH_PAPER
                         (ver_paper_sets) or BENCH_BAND (ver_band_sets)          */
} bench_case;

enum { BENCH_FILE = 0, BENCH_PAPER = 1, BENCH_BAND = 2 };

static const bench_case cases[] = {
  /* the paper's step (lumped v^L); fig6.ini's nodal mass limit in a case of its own */
  {"fig6", 2.0, 4, 4000, "linear", "grid.shape=linear grid.fields=one grid.node_mass=lumped", 0, 0},
  {"fig6", 1.0, 4, 2000, "linear", "grid.shape=linear grid.fields=one grid.node_mass=lumped", 0, 0},
  {"fig6", 2.0, 4, 4000, "limited", "grid.shape=linear grid.fields=one grid.node_mass=limited", 0, 0},
  {"fig7", 2.0, 4, 4000, "paper", "", 0, BENCH_PAPER},
  {"fig6", 2.0, 4, 4000, "gimp", "grid.shape=gimp grid.fields=one", 0, 0},
  {"fig7", 2.0, 4, 4000, "gimp", "grid.shape=gimp grid.fields=one decohesion.Le=cell", 0, BENCH_BAND},
  {"fig7", 2.0, 4, 4000, "gimp-two", "grid.shape=gimp grid.fields=two decohesion.Le=staircase", 1, BENCH_BAND},
  /* the fig7 file's method, timed through the softening, where the rows measure Le */
  {"fig7", 2.0, 4, 4000, "gimp-row", "grid.shape=gimp grid.fields=two decohesion.Le=row decohesion.path=free", 0,
   BENCH_BAND},
  /* fig7.ini's band method (a method tried and not kept): the lead's zone, the band held to its line */
  {"fig7", 2.0, 4, 4000, "gimp-zone-line", "grid.shape=gimp grid.fields=two decohesion.Le=zone", 0, BENCH_BAND},
  /* the crack as a cohesive interface (docs/methods.md; fig7.ini's method):
   * every particle elastic, the split nodes' two fields from the first step, the law on
   * the line's segments */
  {"fig7", 2.0, 4, 4000, "interface", "", 0, BENCH_FILE},
  /* fig8's file (uGIMP, two fields, Rayleigh damping from the cut), after the cut: the
   * viscous stress in the gather and the scatter, with the mass half about each part's
   * held end (the file's: a serial particle pass) or about each node's
   * drift (a serial node pass) */
  {"fig8", 2.0, 4, 4000, "damped-parts", "time.damping_about=parts", 1, 0},
  {"fig8", 2.0, 4, 4000, "damped-drift", "time.damping_about=drift", 1, 0},
  {"fig8", 2.0, 4, 4000, "undamped", "time.damping=0 time.damping_beta=0", 1, 0},
};

/* A separated band along the failure plane through the bar's centre: in each particle
 * row the particle nearest the line, so that the two-field path is the one timed. */
static void cut_band(mpm_sim *s)
{
  const mpm_scene *sc = mpm_sim_scene(s);
  mpm_particle_view v;
  mpm_sim_particles(s, &v);
  const mpm_particle_view *p = &v;
  const double a = sc->alpha_deg * (ANA_PI / 180.0), d = sc->h / sqrt((double)sc->ppc);
  const int nrow = (int)lround(sc->H / d);
  for (int j = 0; j < nrow; j++) {
    const double y = (j + 0.5) * d, xl = 0.5 * sc->L + (y - 0.5 * sc->H) * cos(a) / sin(a);
    size_t best = SIZE_MAX;
    for (size_t k = 0; k < p->n; k++)
      if (p->mat[k] != MPM_MAT_HEAD && fabs(p->y0[k] - y) < 0.25 * d &&
          (best == SIZE_MAX || fabs(p->x0[k] - xl) < fabs(p->x0[best] - xl)))
        best = k;
    if (best != SIZE_MAX)
      (void)mpm_sim_separate(s, best); /* best < p->n */
  }
}

/* Applies the space-separated overrides of a case. */
static int apply_sets(ver_scene *vs, const char *sets, char *err, size_t errlen)
{
  char buf[256];
  snprintf(buf, sizeof buf, "%s", sets);
  for (char *save = NULL, *tok = strtok_r(buf, " ", &save); tok; tok = strtok_r(NULL, " ", &save))
    if (ver_scene_set(vs, tok, err, errlen))
      return 1;
  return 0;
}

static void usage(FILE *f)
{
  fprintf(f,
    "usage: delam bench [--threads N] [--repeat N] [--json] [--steps-scale X] [--case TEXT]\n"
    "Times fixed cases, 4 particles per cell, from 99 %% of the peak stress so decohesion is\n"
    "active, with 1 and 2 threads, or with N: Fig. 6 at h = 2 and 1 and Fig. 7 at h = 2 with\n"
    "the paper's bilinear shapes and step; Fig. 6 at h = 2 with the nodal mass limit\n"
    "(fig6.ini's); Fig. 6 and Fig. 7 at h = 2 with uGIMP; Fig. 7 at h = 2 with\n"
    "uGIMP and two velocity fields, from a band already cut, and through the softening\n"
    "with Le measured per row, with the band method (Le\n"
    "over the lead's zone, the band held to its line) and as its file runs it, the\n"
    "crack as a cohesive interface (decohesion.path = interface); every Fig. 7 case but\n"
    "the last with the paper's flaw; Fig. 8 at h = 2 as its file runs it (uGIMP, two\n"
    "fields, Rayleigh damping) from a band already cut, damped about each part's held\n"
    "end (the file's) or about each node's drift, and undamped (the case id ends in\n"
    "the method).\n"
    "Then the quasi-static solver (--solver static) on whole runs at 4 ppc, one thread:\n"
    "Fig. 6 (the band) and iface90 (the interface) at h 8, 4, 2 and 1, a30 (the inclined\n"
    "interface) at h 2 (h 2 and 1 only with --steps-scale 1 or more), with its increments,\n"
    "Newton iterations, LU factorizations, low-rank updates in their place (upd) and\n"
    "the time per increment in assembly, factorization (with the updates) and solves,\n"
    "and per scene the exponent of CPU s against unknowns\n"
    "(a least-squares line through its rows, log-log).\n"
    "Each case runs --repeat times from the same start and the fastest run is reported\n"
    "(the others differ only by what else the machine did meanwhile).\n"
    "  --threads N      only N threads (default: 1 and 2)\n"
    "  --repeat N       runs per case, the fastest reported (default 3)\n"
    "  --json           one JSON object per line instead of the table\n"
    "  --steps-scale X  multiply the number of steps (default 1)\n"
    "  --case TEXT      only the cases whose id contains TEXT (e.g. fig6-h1)\n"
    "Reproduce outside the bench: /usr/bin/time -v build/delam run data/scenes/fig6.ini \\\n"
    "  --h 1 --ppc 4 --until 0.1 --threads 1\n");
}

/* The scene of a bench case: its file at the case's h and ppc (dt scaled with h), its
 * overrides, to delta 1; and its analytic bar.  0, or 2 with a message on stderr. */
static int bench_scene(const bench_case *bc, ver_scene *vs, ana_bar *bar)
{
  char err[1024], set[64];
  char path[4400];
  if (ver_scene_resolve(bc->scene, path, sizeof path, err, sizeof err) ||
      ver_scene_parse(path, vs, err, sizeof err)) {
    fprintf(stderr, "delam bench: %s (run from the source folder)\n", err);
    return 2;
  }
  vs->sc.dt *= bc->h / vs->sc.h;
  snprintf(set, sizeof set, "grid.h=%g", bc->h);
  ver_scene_set(vs, set, err, sizeof err);
  snprintf(set, sizeof set, "grid.ppc=%d", bc->ppc);
  ver_scene_set(vs, set, err, sizeof err);
  const char *const *band = NULL;
  const int nband = bc->base == BENCH_BAND ? ver_band_sets(bc->scene, &band) : 0;
  for (int i = 0; bc->base == BENCH_PAPER && i < VER_PAPER_NSETS; i++)
    ver_scene_set(vs, ver_paper_sets[i], err, sizeof err);
  for (int i = 0; i < nband; i++)
    ver_scene_set(vs, band[i], err, sizeof err);
  if (apply_sets(vs, bc->sets, err, sizeof err)) {
    fprintf(stderr, "delam bench: %s\n", err);
    return 2;
  }
  vs->sc.end_delta = 1.0;
  if (ver_scene_validate(vs, err, sizeof err)) {
    fprintf(stderr, "delam bench: %s\n", err);
    return 2;
  }
  if (ver_scene_bar(&vs->sc, bar, err, sizeof err) != 0) {
    fprintf(stderr, "delam bench: %s\n", err);
    return 2;
  }
  return 0;
}

/* The options; 0, 1 (--help: done) or 2 (bad usage). */
static int bench_args(int argc, char **argv, int *threads, int *json, int *repeat, double *scale,
                      const char **only)
{
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      usage(stdout);
      return 1;
    } else if (!strcmp(argv[i], "--json")) {
      *json = 1;
    } else if (!strcmp(argv[i], "--case") && i + 1 < argc) {
      *only = argv[++i];
    } else if (!strcmp(argv[i], "--threads") || !strcmp(argv[i], "--repeat") ||
               !strcmp(argv[i], "--steps-scale")) {
      char *end;
      const double v = i + 1 < argc ? strtod(argv[i + 1], &end) : NAN;
      const int whole = argv[i][2] != 's';
      if (!(i + 1 < argc) || *end || !(v > 0) || v > (whole ? 256 : 1024) || (whole && v != floor(v))) {
        fprintf(stderr, "delam bench: %s needs %s\n", argv[i],
                whole ? "a whole number in [1, 256]" : "a number in (0, 1024]");
        return 2;
      }
      if (argv[i][2] == 't')
        *threads = (int)v;
      else if (argv[i][2] == 'r')
        *repeat = (int)v;
      else
        *scale = v;
      i++;
    } else {
      fprintf(stderr, "delam bench: unknown option '%s' (see delam bench --help)\n", argv[i]);
      return 2;
    }
  }
  return 0;
}

/* The quasi-static solver (docs/static.md) on whole runs, to the cut and a margin: the
 * band (fig6.ini), the interface (iface90.ini) and the inclined interface (a30.ini) at 4
 * ppc; h 2 and 1 with --steps-scale 1 or more. */
static const struct {
  const char *scene;
  double h;
} static_cases[] = {{"fig6", 8},    {"fig6", 4},    {"fig6", 2},    {"fig6", 1}, {"iface90", 8},
                    {"iface90", 4}, {"iface90", 2}, {"iface90", 1}, {"a30", 2}};

/* One static case, the fastest of `repeat` runs (its CPU seconds and unknowns in *cpu_out,
 * *nu); 0, 1 when it fails, 2 on bad input. */
static int bench_static_case(int c, int repeat, int json, double *cpu_out, int *nu)
{
  const bench_case bc = {static_cases[c].scene, static_cases[c].h, 4, 0, "static", "solver.type=static", 0, 0};
  ver_scene vs;
  ana_bar bar;
  char err[1024];
  if (bench_scene(&bc, &vs, &bar))
    return 2;
  mpm_static_stats best = {0};
  double wall = INFINITY, cpu = 0.0;
  size_t np = 0;
  for (int r = 0; r < repeat; r++) {
    mpm_sim *s = NULL;
    mpm_static *q = NULL;
    if (mpm_sim_alloc(&vs.sc, 1, &s, err, sizeof err) != MPM_OK || mpm_static_alloc(s, &q, err, sizeof err) != MPM_OK) {
      fprintf(stderr, "delam bench: %s\n", err);
      mpm_sim_free(s);
      return 1;
    }
    const double w0 = ver_now_wall(), c0 = ver_now_cpu();
    int after = 0; /* increments past the cut */
    while (after < 3 && mpm_sim_delta(s) < vs.sc.end_delta) {
      if (mpm_static_step(q, err, sizeof err) != MPM_OK) {
        fprintf(stderr, "delam bench: %s\n", err);
        mpm_static_free(q);
        mpm_sim_free(s);
        return 1;
      }
      mpm_sim_info in;
      mpm_sim_info_get(s, &in);
      after += in.cut;
    }
    const double w = ver_now_wall() - w0;
    if (w < wall) {
      wall = w;
      cpu = ver_now_cpu() - c0;
      mpm_static_stats_get(q, &best);
      mpm_particle_view p;
      mpm_sim_particles(s, &p);
      np = p.n;
    }
    mpm_static_free(q);
    mpm_sim_free(s);
  }
  *cpu_out = cpu;
  *nu = best.unknowns;
  char id[96];
  snprintf(id, sizeof id, "%s-h%g-ppc4-static", vs.name, bc.h);
  const double ni = best.increments > 0 ? (double)best.increments : 1.0;
  if (json) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "case", id);
    cJSON_AddNumberToObject(o, "threads", 1);
    cJSON_AddNumberToObject(o, "repeat", repeat);
    cJSON_AddNumberToObject(o, "particles", (double)np);
    cJSON_AddNumberToObject(o, "unknowns", best.unknowns);
    cJSON_AddNumberToObject(o, "increments", (double)best.increments);
    cJSON_AddNumberToObject(o, "newton", (double)best.newton);
    cJSON_AddNumberToObject(o, "factorizations", (double)best.factorizations);
    cJSON_AddNumberToObject(o, "updates", (double)best.updates);
    cJSON_AddNumberToObject(o, "wall_s", wall);
    cJSON_AddNumberToObject(o, "cpu_s", cpu);
    cJSON_AddNumberToObject(o, "assembly_s_per_increment", best.t_eval / ni);
    cJSON_AddNumberToObject(o, "factor_s_per_increment", best.t_factor / ni);
    cJSON_AddNumberToObject(o, "solve_s_per_increment", best.t_solve / ni);
    char *txt = cJSON_PrintUnformatted(o);
    printf("%s\n", txt);
    free(txt);
    cJSON_Delete(o);
  } else {
    printf("%-28s %8zu %8d %5ld %6ld %5ld %5ld %7.3f %7.3f  %8.3f %8.3f %8.3f\n", id, np, best.unknowns,
           best.increments, best.newton, best.factorizations, best.updates, wall, cpu, 1e3 * best.t_eval / ni,
           1e3 * best.t_factor / ni, 1e3 * best.t_solve / ni);
  }
  fflush(stdout);
  return 0;
}

/* One explicit case's row: its fastest run's time, rate, time split and memory. */
static void print_case(const char *id, int threads, int repeat, const mpm_sim *s, long steps, double wall, double cpu,
                       int json)
{
  mpm_sim_info in;
  mpm_sim_info_get(s, &in);
  mpm_particle_view p;
  mpm_sim_particles(s, &p);
  const double ups = (double)p.n * (double)steps / wall;
  double split = 0.0;
  for (int q = 0; q < MPM_T_N; q++)
    split += in.time_split[q];
  const size_t bpp = mpm_sim_bytes_per_particle(s);
  if (json) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "case", id);
    cJSON_AddNumberToObject(o, "threads", threads);
    cJSON_AddNumberToObject(o, "repeat", repeat);
    cJSON_AddNumberToObject(o, "particles", (double)p.n);
    cJSON_AddNumberToObject(o, "steps", (double)steps);
    cJSON_AddNumberToObject(o, "wall_s", wall);
    cJSON_AddNumberToObject(o, "cpu_s", cpu);
    cJSON_AddNumberToObject(o, "updates_per_s", ups);
    const char *names[MPM_T_N] = {"sort_s", "p2g_s", "grid_s", "g2p_s", "constitutive_s"};
    for (int q = 0; q < MPM_T_N; q++)
      cJSON_AddNumberToObject(o, names[q], in.time_split[q]);
    cJSON_AddNumberToObject(o, "decohesion_updates", (double)(in.n_soften + in.n_separate));
    cJSON_AddNumberToObject(o, "bytes_per_particle", (double)bpp);
    char *txt = cJSON_PrintUnformatted(o);
    printf("%s\n", txt);
    free(txt);
    cJSON_Delete(o);
  } else {
    printf("%-28s %3d %8zu %6ld %7.2f %7.2f %9.1f  %5.1f %5.1f %5.1f %5.1f %5.1f  %4zu\n", id, threads,
           p.n, steps, wall, cpu, ups / 1e6, 100 * in.time_split[0] / split,
           100 * in.time_split[1] / split, 100 * in.time_split[2] / split, 100 * in.time_split[3] / split,
           100 * in.time_split[4] / split, bpp);
  }
}

int ver_cmd_bench(int argc, char **argv)
{
  int threads = 0, json = 0, repeat = 3;
  double scale = 1.0;
  const char *only = "";
  const int pa = bench_args(argc, argv, &threads, &json, &repeat, &scale, &only);
  if (pa)
    return pa == 1 ? 0 : 2;
  const int tlist[2] = {threads ? threads : 1, 2};
  const int ntl = threads ? 1 : 2;
  if (!json)
    printf("%-28s %3s %8s %6s %7s %7s %9s  %5s %5s %5s %5s %5s  %4s\n", "case", "thr", "particles", "steps",
           "wall_s", "cpu_s", "Mupd/s", "sort%", "p2g%", "grid%", "g2p%", "cons%", "B/p");
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
    for (int ti = 0; ti < ntl; ti++) {
      char want[96];
      snprintf(want, sizeof want, "%s-h%g-ppc%d-%s", cases[c].scene, cases[c].h, cases[c].ppc, cases[c].method);
      if (!strstr(want, only))
        continue;
      ver_scene vs;
      ana_bar bar;
      char err[1024];
      if (bench_scene(&cases[c], &vs, &bar))
        return 2;
      mpm_sim *s = NULL;
      const long steps = (long)(cases[c].steps * scale);
      double wall = INFINITY, cpu = 0.0;
      for (int r = 0; r < repeat; r++) {
        mpm_sim *t = NULL;
        if (mpm_sim_alloc(&vs.sc, tlist[ti], &t, err, sizeof err) != MPM_OK ||
            mpm_sim_prestress(t, 0.99 * bar.r0) != MPM_OK) {
          fprintf(stderr, "delam bench: %s\n", t ? "the bar's peak stress is not finite" : err);
          mpm_sim_free(t);
          mpm_sim_free(s);
          return 1;
        }
        if (cases[c].cut)
          cut_band(t);
        const double w0 = ver_now_wall(), c0 = ver_now_cpu();
        for (long k = 0; k < steps; k++)
          if (mpm_sim_step(t, err, sizeof err) != MPM_OK) {
            fprintf(stderr, "delam bench: %s\n", err);
            mpm_sim_free(t);
            mpm_sim_free(s);
            return 1;
          }
        const double w = ver_now_wall() - w0, cu = ver_now_cpu() - c0;
        if (w < wall) { /* keep the fastest run, with its own time split */
          wall = w;
          cpu = cu;
          mpm_sim_free(s);
          s = t;
        } else {
          mpm_sim_free(t);
        }
      }
      char id[96];
      snprintf(id, sizeof id, "%s-h%g-ppc%d-%s", vs.name, cases[c].h, cases[c].ppc, cases[c].method);
      print_case(id, tlist[ti], repeat, s, steps, wall, cpu, json);
      fflush(stdout);
      mpm_sim_free(s);
    }
  int nstatic = 0; /* the static cases --case leaves */
  for (int c = 0; c < (int)(sizeof static_cases / sizeof static_cases[0]); c++) {
    char want[96];
    snprintf(want, sizeof want, "%s-h%g-ppc4-static", static_cases[c].scene, static_cases[c].h);
    nstatic += strstr(want, only) != NULL;
  }
  if (!json && nstatic)
    printf("\n%-28s %8s %8s %5s %6s %5s %5s %7s %7s  %8s %8s %8s\n", "static case (1 thread)", "particles", "unknowns",
           "incr", "newton", "LU", "upd", "wall_s", "cpu_s", "asm ms/i", "LU ms/i", "sol ms/i");
  /* per scene, a least-squares line through (log unknowns, log CPU s) of its h rows */
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int m = 0;
  const int nc = (int)(sizeof static_cases / sizeof static_cases[0]);
  for (int c = 0; c < nc; c++) {
    char want[96];
    snprintf(want, sizeof want, "%s-h%g-ppc4-static", static_cases[c].scene, static_cases[c].h);
    /* h 2 and 1 are whole runs of seconds: not for a shortened bench */
    const int run = !(static_cases[c].h < 4 && scale < 1.0) && strstr(want, only);
    double cpu = 0.0;
    int nu = 0;
    const int rc = run ? bench_static_case(c, repeat, json, &cpu, &nu) : 0;
    if (rc)
      return rc;
    if (cpu > 0.0 && nu > 0) {
      const double x = log((double)nu), y = log(cpu);
      sx += x, sy += y, sxx += x * x, sxy += x * y, m++;
    }
    if (c + 1 == nc || strcmp(static_cases[c + 1].scene, static_cases[c].scene) != 0) {
      if (m >= 2 && !json && m * sxx - sx * sx > 0.0)
        printf("%-28s CPU s ~ unknowns^%.2f over its %d rows\n", static_cases[c].scene,
               (m * sxy - sx * sy) / (m * sxx - sx * sx), m);
      sx = sy = sxx = sxy = 0.0;
      m = 0;
    }
  }
  return 0;
}