/*
 * cmd_run.c - `delam run SCENE`: one scene file through the kernel, with overrides.
 */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cmd.h"
#include "run.h"
#include "datadir.h"
#include "metrics.h"
#include "scene.h"

static volatile sig_atomic_t stop_flag = 0;

static void on_signal(int sig)
{
  (void)sig;
  stop_flag = 1;
}

static void usage(FILE *f)
{
  fprintf(f,
    "usage: delam run SCENE [options]\n"
    "Runs one scene, a file or the name of one in the scene folder (fig6, fig7, ...:\n"
    "$DELAM_SCENES, ./data/scenes, or the installed or source tree's), and writes\n"
    "load.csv, energy.csv, particle\n"
    "snapshots (CSV and VTK XML .vtp, with snapshots.pvd for ParaView), final.csv/.vtp\n"
    "and summary.json; `delam plot DIR` draws the folder.\n\n"
    "options:\n"
    "  --out DIR         output folder (default out/<scene>-h<h>-ppc<n>)\n"
    "  --h H             grid spacing; dt is scaled with it unless --dt is given\n"
    "  --ppc N           particles per cell, a perfect square (1, 4, 9, ..., 1024)\n"
    "  --dt DT           time step (must be below the CFL bound h / (c sqrt 2))\n"
    "  --until DELTA     run to this end displacement exactly (no early stop)\n"
    "  --method NAME     the run's method is the preset NAME (paper, band or\n"
    "                    interface) instead of the file's: every method key takes\n"
    "                    NAME's value or its default; --set still applies after it\n"
    "  --set S.K=V       set key K of section S, as in the file (repeatable; grid.h\n"
    "                    scales dt as --h does unless time.dt was set before it)\n"
    "  --solver NAME     explicit (the paper's dynamic step) or static (load\n"
    "                    increments in equilibrium; the same as --set solver.type=NAME)\n"
    "  --allow-unstable  accept a time step at or above the CFL bound\n"
    "  --threads N       OpenMP threads (default: chosen while it runs, one thread\n"
    "                    for small scenes, up to OMP_NUM_THREADS or all cores when\n"
    "                    that measures faster; see docs/library.md)\n"
    "  --quiet           no progress line\n"
    "  --keys            print every scene key (type, range, default) and stop\n"
    "  --help            this text\n"
    "exit status: 0 complete, 1 the run failed, 2 bad input, 130 stopped by a signal\n");
}

/* Parses a positive number for option opt; 0 on success. */
static int num_arg(const char *opt, const char *v, double *out)
{
  char *end;
  *out = v ? strtod(v, &end) : NAN;
  if (!v || end == v || *end || !isfinite(*out) || *out <= 0) {
    fprintf(stderr, "delam run: %s: '%s' is not a number > 0\n", opt, v ? v : "");
    return 2;
  }
  return 0;
}

/* The command line's overrides, as --set assignments (dt scaled with h unless given:
 * the file's Courant number is kept); 0, or 2 with err. */
static int apply_overrides(ver_scene *vs, const char *method, double h, double ppc, double dt, double until,
                           const char *const *sets, int nset, char *err, size_t len)
{
  char buf[128], num[40];
  if (method) { /* first: the --set overrides after it hold */
    snprintf(buf, sizeof buf, "method.preset=%s", method);
    if (ver_scene_set(vs, buf, err, len))
      return 2;
  }
  if (h > 0 && dt <= 0 && vs->sc.h > 0)
    dt = vs->sc.dt * h / vs->sc.h;
  const char *key[4] = {"grid.h", "grid.ppc", "time.dt", "run.end_delta"};
  const double val[4] = {h, ppc, dt, until};
  for (int k = 0; k < 3; k++)
    if (val[k] > 0) {
      ver_scene_fmt_num(val[k], num, sizeof num);
      snprintf(buf, sizeof buf, "%s=%s", key[k], num);
      if (ver_scene_set(vs, buf, err, len))
        return 2;
    }
  for (int i = 0; i < nset; i++)
    if (ver_scene_set(vs, sets[i], err, len))
      return 2;
  if (until > 0) {
    ver_scene_fmt_num(until, num, sizeof num);
    snprintf(buf, sizeof buf, "%s=%s", key[3], num);
    if (ver_scene_set(vs, buf, err, len) || ver_scene_set(vs, "run.stop_margin=0", err, len))
      return 2;
  }
  return 0;
}

/* What a finished run says: the energy warnings on stderr and its numbers on stdout. */
static void print_result(const ver_scene *vs, const char *id, const ver_summary *uu, const char *outdir)
{
  const ver_summary u = *uu;
  if (!(u.energy_residual <= VER_ENERGY_TOL)) /* the balance over every row, to the run's end */
    fprintf(stderr, "delam run: warning: energy residual %.3g over the whole run (to delta %.4g) is above the tolerance "
            "%g (W_ext + E0 - KE - SE - W_coh - booked losses, over max W_ext; unbooked %.3g; energy.csv)\n",
            u.energy_residual, u.delta_end, VER_ENERGY_TOL, u.energy_unbooked);
  else if (vs->sc.vib_mode == 0 && !(u.energy_unbooked <= VER_ENERGY_TOL)) {
    char damp[96] = ""; /* the damper is work the scene asked to remove: say how much */
    if (u.L_damp_final > 0.0)
      snprintf(damp, sizeof damp, "; of it the damper the scene asks for (time.damping) took %.3g (L_damp)",
               u.L_damp_final);
    fprintf(stderr, "delam run: warning: energy not accounted for %.3g over the whole run (to delta %.4g) is above the "
            "tolerance %g (W_ext + E0 - KE - SE - W_coh over max W_ext, nothing booked; booked residual %.3g; "
            "energy.csv L_bc, L_flip, L_scheme, W_head, L_contact, L_debris, L_damp)%s\n", u.energy_unbooked, u.delta_end,
            VER_ENERGY_TOL, u.energy_residual, damp);
  }
  if (vs->sc.vib_mode > 0) /* free vibration: what it kept and its period */
    printf("%s: energy kept %.4f (booked: L_bc %.3g, L_flip %.3g, L_scheme %.3g of %.4g), period %.6g against "
           "%.6g (error %+.3f %%), energy residual %.2e\n",
           id, u.energy_kept, u.L_bc_final, u.L_flip_final, u.L_scheme_final, u.energy_start, u.period,
           u.period_exact, 100.0 * u.period_error, u.energy_residual);
  else
    printf("%s: peak P %.4g at delta %.4g, separation at delta %.4g, D %.4g (%.4g at separation), W_ext %.4g, "
           "elastic slope %.4g, energy residual %.2e (unbooked %.2e) to delta %.4g\n",
           id, u.peak_P, u.delta_peak, u.delta_sep, u.D_final, u.D_cut, u.W_ext_final, u.k_elastic,
           u.energy_residual, u.energy_unbooked, u.delta_end);
  if (u.n_debris > 0) /* not an error, but the user should know (docs/findings.md) */
    printf("%s: %ld separated particles left the grid as debris, carrying %.4g (energy.csv L_debris)\n", id,
           u.n_debris, u.L_debris_final);
  printf("%s: %zu particles, %ld steps, %.2f s, %.3g particle-updates/s -> %s/\n", id, u.particles, u.steps,
         u.wall_s, u.updates_per_s, outdir);
}

/* After a failed or stopped run: what its folder holds, as it is. */
static void say_folder(const char *dir)
{
  ver_summary_doc d;
  struct stat st;
  const int have = ver_summary_read(dir, &d) == 0;
  if (have && !d.u.complete)
    fprintf(stderr, "delam run: partial results in %s (summary.json says complete: false)\n", dir);
  else if (have) /* the run failed before it cleared the folder */
    fprintf(stderr, "delam run: %s is as an earlier run left it: none of it is this run's\n", dir);
  else if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode))
    fprintf(stderr, "delam run: no summary.json in %s: nothing there is a result of this run\n", dir);
}

/* SIGINT, SIGTERM and SIGHUP (unless nohup ignores it) stop the run cleanly. */
static void catch_signals(void)
{
  struct sigaction sa, old;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);
  if (sigaction(SIGHUP, NULL, &old) == 0 && old.sa_handler != SIG_IGN)
    sigaction(SIGHUP, &sa, NULL);
}

int ver_cmd_run(int argc, char **argv)
{
  const char *path = NULL, *outdir = NULL, *method = NULL;
  const char *sets[64];
  char solver_set[80];
  int nset = 0, quiet = 0, allow = 0, threads = 0;
  double h = 0, ppc = 0, dt = 0, until = 0;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    const char *v = i + 1 < argc ? argv[i + 1] : NULL;
    int r = 0;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(a, "--keys")) {
      ver_scene_keys_markdown(stdout);
      return 0;
    } else if (!strcmp(a, "--out")) {
      if (!v) { fprintf(stderr, "delam run: --out needs a folder\n"); return 2; }
      outdir = v; i++;
    } else if (!strcmp(a, "--method")) {
      if (!v || v[0] == '-') { fprintf(stderr, "delam run: --method needs a preset (paper, band or interface)\n"); return 2; }
      method = v; i++;
    } else if (!strcmp(a, "--h")) { r = num_arg(a, v, &h); i++; }
    else if (!strcmp(a, "--ppc")) { r = num_arg(a, v, &ppc); i++; }
    else if (!strcmp(a, "--dt")) { r = num_arg(a, v, &dt); i++; }
    else if (!strcmp(a, "--until")) { r = num_arg(a, v, &until); i++; }
    else if (!strcmp(a, "--threads")) {
      double t;
      r = num_arg(a, v, &t);
      if (!r && (t != floor(t) || t > 256)) {
        fprintf(stderr, "delam run: --threads: '%s' is not a whole number in 1..256\n", v);
        return 2;
      }
      threads = (int)t;
      i++;
    }
    else if (!strcmp(a, "--solver")) {
      if (!v || nset == 64) { fprintf(stderr, "delam run: --solver needs explicit or static\n"); return 2; }
      snprintf(solver_set, sizeof solver_set, "solver.type=%s", v);
      sets[nset++] = solver_set; i++;
    } else if (!strcmp(a, "--set")) {
      if (!v || nset == 64) { fprintf(stderr, "delam run: --set needs section.key=value\n"); return 2; }
      sets[nset++] = v; i++;
    } else if (!strcmp(a, "--allow-unstable")) allow = 1;
    else if (!strcmp(a, "--quiet")) quiet = 1;
    else if (a[0] == '-' && a[1]) {
      fprintf(stderr, "delam run: unknown option '%s' (see delam run --help)\n", a);
      return 2;
    } else if (!path) path = a;
    else { fprintf(stderr, "delam run: one scene file only ('%s' is extra)\n", a); return 2; }
    if (r) return r;
  }
  if (!path) {
    fprintf(stderr, "delam run: no scene file (usage: delam run SCENE.ini [options])\n");
    return 2;
  }
  ver_scene vs;
  char err[4800], found[4400];
  if (ver_scene_resolve(path, found, sizeof found, err, sizeof err)) {
    fprintf(stderr, "delam run: %s\n", err);
    return 2;
  }
  path = found;
  if (ver_scene_parse(path, &vs, err, sizeof err)) {
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  if (apply_overrides(&vs, method, h, ppc, dt, until, sets, nset, err, sizeof err)) {
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  vs.allow_unstable = allow;
  if (ver_scene_validate(&vs, err, sizeof err)) {
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  if (ver_scene_rate_ratio(&vs.sc) > VER_RATE_WARN)
    fprintf(stderr, "delam run: warning: loading.speed = %g moves a strain %.2g times the strain at initiation in one "
            "wave transit (quasi-static below %g; expect a load error of about %.0f %% of the peak)\n", vs.sc.speed,
            ver_scene_rate_ratio(&vs.sc), VER_RATE_WARN, 60.0 * ver_scene_rate_ratio(&vs.sc));
  char id[600], defdir[700];
  ver_scene_case_id(&vs, id, sizeof id);
  snprintf(defdir, sizeof defdir, "out/%s", id);
  catch_signals();
  ver_run_opts o = {outdir ? outdir : defdir, !quiet, 1, &stop_flag, 0, threads};
  ver_summary u;
  const int rc = ver_run(&vs, &o, &u, err, sizeof err);
  if (rc) {
    fprintf(stderr, "delam run: %s\n", err);
    if (rc != 2)
      say_folder(o.outdir);
    return rc;
  }
  print_result(&vs, id, &u, o.outdir);
  return 0;
}
