/*
 * report.h - private to `delam report`: the cases the figures need (report_cases.c),
 * how they are run (report_run.c), what is measured from them (report_data.c), the
 * plot data and gnuplot (report_plot.c), the checks and the paper's numbers
 * (report_judge.c), the quasi-static solver's runs (report_qs.c, report_static.c), the split
 * beams (report_spec.c), the text (report_text.c, templates in reports/text/) and the one
 * document model rendered to REPORT.md and index.html (report_doc.c).
 */
#ifndef DELAM_REPORT_H
#define DELAM_REPORT_H

/* --set overrides a case may carry (the paper's method has six). */
#define REP_NSET 13 /* at least VER_PAPER_NSETS (checked in report_run.c) */

#include <stddef.h>
#include <stdio.h>

#include "ana.h"
#include "report_doc.h"

#define REP_PATH 1024
#define REP_MAX_CASES 160

/* Which figure a case feeds (bit mask). */
enum {
  REP_PIC = 1,      /* particle pictures (full scene run, all snapshots)       */
  REP_SWEEP = 2,    /* h x ppc sweep: convergence and work-precision          */
  REP_STAB = 4,     /* time-step sweep                                        */
  REP_SNAP = 8,     /* snapback scenes                                        */
  REP_SEP = 16,     /* separation threshold                                   */
  REP_SCHEME = 32,  /* usl vs musl                                            */
  REP_PAPER = 64,   /* a paper scene with the paper's method (bilinear, one field, Le = cell) */
  REP_IFACE = 128,  /* an inclined paper scene with decohesion.path = interface (docs/methods.md) */
  REP_BAND = 256,   /* an inclined paper scene whose file runs the interface, with the band method */
  REP_WAVE = 512,   /* iface90.ini: Fig. 6's bar on the interface, against the exact solution at the grip speed */
  REP_STATIC = 1024, /* the sweep scenes with the quasi-static solver (report_static.c)          */
  REP_QS = 4096,    /* a snapback scene on the quasi-static solver (report_qs.c)                  */
  REP_QS3 = 8192,   /* one of Fig. 3's nine bars on the quasi-static solver (report_qs.c; tag 3 i + j) */
  REP_SPEC = 16384, /* a split beam on its file's static solver (report_spec.c; tag 0 DCB, 1 ELS)      */
};

/* Outcome of a time-step sweep point. */
enum { REP_STABLE = 0, REP_NOISY = 1, REP_BLOWN = 2 };

typedef struct {
  /* what to run */
  char id[128];         /* case id: <scene>-h<h>-ppc<n>[-u<until>][-dt<dt>][-<tag>]          */
  char scene[32];       /* scene name, data/scenes/<scene>.ini                               */
  double h;             /* grid spacing                                                      */
  int ppc;              /* particles per cell                                                */
  double dt;            /* time step; 0: the scene's, scaled with h                          */
  double until;         /* --until; 0: the scene's stop rule                                  */
  char set[REP_NSET][64]; /* --set overrides                                                  */
  int nset;
  int allow_unstable;   /* pass --allow-unstable; a failed run is then a result, not an error */
  int role;             /* REP_* mask                                                         */
  double tag;           /* role-specific: dt / dt_crit, separation threshold, ...            */
  double cost;          /* estimated particle-updates, to start the longest runs first       */
  double speed;         /* the scene's grip speed (energy.csv's t to delta)                  */
  double last_snap;     /* the scene's last snapshot (REP_PIC results must hold it); -1 none  */
  /* where its results are and how the run ended */
  char dir[REP_PATH];   /* folder with summary.json, load.csv, snapshots                      */
  int have;             /* 1 if dir holds a summary.json                                     */
  int reused;           /* 1 if taken from the cache or --from                               */
  int exit_status;      /* of `delam run` (0 complete, 1 failed, 2 bad input); -1 unknown    */
  /* from summary.json */
  int complete;
  double peak_P, delta_peak, delta_sep, k_elastic, D_final, W_ext_final, energy_residual;
  double delta_end, cpu_s, wall_s, updates_per_s, dt_used;
  long steps;
  double particles;
  char error[256];      /* summary.json "error", if any                                       */
  char scheme[16];      /* "usl" or "musl" (summary.json)                                     */
  char shape[16], fields[16], le[16]; /* "linear"/"gimp", "one"/"two", "cell"/... (summary.json) */
  char damping_from[16];                /* "start" or "cut" (summary.json; "" if absent)        */
  char damping_about[16];               /* "drift" or "parts" (summary.json; "" if absent)      */
  char path[16];                        /* decohesion.path, "free" or "line" ("" if absent)    */
  char reversed_shear[16];              /* decohesion.reversed_shear ("" if absent)            */
  double path_reach;                    /* decohesion.path_reach                               */
  double sep_threshold; /* the run's separation threshold (summary.json)                     */
  double damping;       /* the run's time.damping (summary.json; 0 if absent)                 */
  double damping_beta;  /* the run's time.damping_beta (summary.json; 0 if absent)            */
  /* measured here against the analytic bar */
  ana_bar bar;          /* the scene's analytic bar                                          */
  int bar_ok;
  double curve_err;     /* RMS (P - P_ana) / Pmax over (0, cmp_end] (ver_curve_l2; NaN if no rows) */
  double max_dev;       /* max |P - P_ana| / Pmax over the same range                         */
  double curve_wave;    /* RMS (P - P_wave) / Pmax over the same range, against the exact solution at
                           the grip speed (ver_curve_err_wave; NaN where it does not apply)    */
  double wave_peak;     /* that solution's peak load (NaN where it does not apply)            */
  double rho, imp_x;    /* the scene file's density and flaw x (the exact solution's plane)   */
  double cmp_end;       /* the range of the comparison: ver_sep_ref at the run's threshold    */
  double diss_err;      /* D_final / D_sep(analytic) - 1                                      */
  double k_soft;        /* softening slope (ver_softening_slope, 0.8 to 0.2 of the peak)      */
  double drop_width;    /* delta interval in which P fell from 0.9 to 0.1 of its peak; NaN    */
  double max_absP;      /* largest |P| in load.csv (blow-up test)                             */
  int rows;             /* rows of load.csv read                                              */
  /* the quasi-static solver (solver.type = static: rows are equilibrium states) */
  int static_run;       /* 1 if summary.json says the run was static                          */
  double curve_path;    /* static: RMS distance from the analytic path (ver_curve_path); NaN  */
} rep_case;

typedef struct {
  rep_case c[REP_MAX_CASES];
  int n;
  char exe[REP_PATH];      /* the delam binary (/proc/self/exe)                 */
  char scenes[REP_PATH];   /* folder of the scene files                         */
  char cache[REP_PATH];    /* out/report                                        */
  char from[REP_PATH];     /* --from folder or ""                               */
  char out[REP_PATH];      /* reports/out                                       */
  char gpdir[REP_PATH];    /* reports (the .gp scripts)                         */
  int jobs;                /* children at once                                  */
  int rerun;               /* ignore cached results                             */
  int have_musl;           /* the scene files accept time.scheme=musl           */
  int *io_bad;             /* counts the data files that could not be written (NULL: none) */
} rep_ctx;


/* The sweep over h and ppc: its scenes and how far the runs made here go. */
#define REP_NSWEEP 3
extern const char *const rep_sweep_scene[REP_NSWEEP];
extern const double rep_sweep_until[REP_NSWEEP];

/* err = exp(c) h^p over the complete 1-ppc runs of a sweep scene; a dissipation error
 * at rounding (below REP_ROUNDING: the interface's D is U0 area by construction) is
 * counted in n_diss_exact and left out of its fit, whose p is then NaN if fewer than two
 * runs are left */
#define REP_ROUNDING 1e-12
typedef struct {
  double p_curve, c_curve, p_diss, c_diss;
  int n, n_diss_exact;
} rep_fit;

#define REP_MAX_FIGS 24
typedef struct {
  char name[32];           /* reports/<name>.gp -> OUT/<name>.png, .svg; reports/text/<name>.md */
  int status;              /* gnuplot's exit status for the PNG (-1: not run)   */
} rep_fig;

struct cJSON;
typedef struct {
  rep_ctx r;
  struct cJSON *verify;    /* verify.json of the checks (--from, or the report's own) */
  char verify_dir[REP_PATH]; /* where it came from                               */
  int verify_rc;           /* exit status of the report's own delam verify; -1 none */
  int sweep_from;          /* sweep points taken from the verify folder         */
  rep_fit fits[REP_NSWEEP];
  rep_fit sfits[REP_NSWEEP]; /* the static sweep (REP_STATIC, 4 ppc): p_curve of curve_path */
  char sverdict[REP_NSWEEP][48]; /* its verdict per scene (report_static.c)           */
  rep_fig fig[REP_MAX_FIGS];
  int nfig;
  double t_runs, t0;
  rep_vars vars;           /* the placeholders of the templates                 */
  rep_doc doc;
  int data_bad;            /* data files that could not be written (r.io_bad)   */
} report;

/* report_cases.c */
double ver_report_dt_crit(const rep_ctx *r, const char *scene, double h);
int ver_report_find_sweep(const rep_ctx *r, const char *scene, double h, int ppc);
const rep_case *ver_report_first(const rep_ctx *r, int role, const char *scene);
const rep_case *ver_report_sweep(const rep_ctx *r, const char *scene, double h, int ppc); /* with results */
/* report_data.c: the exact solution at case c's grip speed (its scene's density, flaw x
 * and the run's separation threshold, 0.98 if the summary has none). */
ana_wave_params ver_report_wave_params(const rep_case *c);
/* The case with a role in mask at (h, ppc) that has a result (the last added), or NULL. */
const rep_case *ver_report_role_at(const rep_ctx *r, int mask, double h, int ppc);
const rep_case *ver_report_case(const rep_ctx *r, const char *id);                     /* with results */
void ver_report_build_cases(report *R);

/* report_plot.c */
/* Fig. 3's bars: q = rep_fig3_q[i], g = rep_fig3_g[j] (alpha 90, r0 1, L = E U0 / g). */
extern const double rep_fig3_q[3], rep_fig3_g[3];
int ver_report_fig3_bar(int i, int j, ana_bar *b);
/* OUT/data/NAME for writing (NULL, said and counted in r->io_bad, if it cannot be); its
 * close removes a file not written whole and counts it. */
FILE *ver_report_open_data(const rep_ctx *r, const char *name);
void ver_report_close_data(const rep_ctx *r, FILE *f, const char *name);
/* OUT/data/: plot data, vars.gp, and a copy of each run's files (nothing links out). */
void ver_report_write_data(report *R);
/* Time-step sweep: REP_STABLE, REP_NOISY or REP_BLOWN against the smallest-dt error. */
int ver_report_stab_outcome(const rep_case *c, double base);
double ver_report_stab_base(const rep_ctx *r);
#define REP_STAB_NOISY 0.02 /* curve error (RMS / Pmax) above the smallest dt's by this: noisy */
void ver_report_gnuplot(report *R);
/* Where data files could not be written: no figure is drawn (nor an older one kept). */
void ver_report_no_figures(report *R);

/* report_judge.c */
/* Without --from: runs `delam verify --quick` into CACHE/verify, which then serves as
 * --from.  0, or 2 if it could not be started. */
int ver_report_run_verify(report *R);
/* Reads FROM/verify.json (NULL if missing). */
struct cJSON *ver_report_read_verify(const char *from);
/* Adds the verdict sections (per case, counts, every check) to the document. */
/* The verdict counts in one paragraph (reports/text/verdicts.md), for the top of the page. */
void ver_report_verdict_summary(report *R);
/* The verdicts: per case, across cases, and every check. */
void ver_report_verdicts(report *R);
/* Adds the table of the paper's numbers beside the measured ones. */
void ver_report_paper_table(report *R);

/* report_static.c: the sweep scenes with the quasi-static solver at REP_STATIC_PPC,
 * h = 8, 4, 2 (and 1 for fig6), beside the explicit sweep */
#define REP_STATIC_PPC 4
void ver_report_static_cases(report *R);
/* OUT/data/sweep-<scene>-static.dat (h, curve_path, RMS load error, |D error|, CPU s,
 * complete, particles, and the explicit run's distance from the static one at the same h
 * and ppc); fits R->sfits and verdicts R->sverdict; their vars in vars.gp. */
void ver_report_write_static(report *R, FILE *vars);
/* The template placeholders static:<scene>:p, :verdict, :n and rate:<scene>:h<h>. */
void ver_report_static_vars(report *R);
/* Their table in the document (the convergence figure's section). */
void ver_report_static_table(report *R);

/* report_text.c */
/* The figures, in the report's order (sets R->fig). */
void ver_report_plan_figs(report *R);
/* Sets the template placeholders from the runs. */
void ver_report_set_vars(report *R);
/* The whole document: introduction, verdicts, paper table, figures, all runs. */
void ver_report_compose(report *R);

/* path made absolute against the working folder (not resolved further). */
void ver_report_abs(const char *path, char *out, size_t len);
/* Adds a case (id made from the parameters); returns its index or -1 if full. */
int ver_report_add(rep_ctx *r, const char *scene, double h, int ppc, double dt, double until,
                   const char *set1, const char *set2, int role, double tag);
/* The same with up to 4 overrides. */
int ver_report_add_sets(rep_ctx *r, const char *scene, double h, int ppc, double dt, double until,
                        const char *const *sets, int nset, int role, double tag);
int ver_report_find(const rep_ctx *r, const char *id);
/* The method of a run in words: "MUSL, bilinear, one field, Le = cell" (report_data.c). */
void ver_report_method(const rep_case *c, char *buf, size_t len);
/* Looks for results (from, then cache), runs the missing cases jobs at a time with
 * progress on stderr.  Returns the number of cases that could not be run at all. */
int ver_report_run_cases(rep_ctx *r);
/* Runs the n commands argvs[i] in folder cwd (NULL: here) with output to logs[i], up to
 * jobs at once, one progress line per finished command on stderr; status[i] gets the
 * exit status (-1 if it could not start).  meant_to_fail (NULL: none) marks the commands
 * whose failure is their result (the time-step sweep above the stable bound): their
 * progress line says so instead of "failed". */
void ver_report_spawn_all(char ***argvs, const char *cwd, char **logs, char **names, int n, int jobs,
                          int *status, const char *what, const int *meant_to_fail);

/* report_qs.c: the quasi-static solver's runs, the snapback scenes (REP_QS) and Fig. 3's
 * nine bars (REP_QS3, q = rep_fig3_q[i], g = rep_fig3_g[j]). */
void ver_report_qs_cases(rep_ctx *r);
/* Their vars (qs_<scene>, f3k_*) and OUT/data/fig3-kernel-q<q>-g<g>.csv. */
void ver_report_qs_write(const rep_ctx *r, FILE *vars);
/* Their placeholders (qs_<scene>:para, fig3k:*). */
void ver_report_qs_vars(report *R);

/* report_spec.c: the split beams (docs/specimens.md), the DCB and the ELS at h 4 and 2,
 * 4 ppc, static (REP_SPEC), against data/fe, beam theory and the DCB's cohesive beam. */
void ver_report_spec_cases(rep_ctx *r);
/* OUT/data/spec-*.csv (the references' curves) and their vars (spec_*). */
void ver_report_spec_write(const rep_ctx *r, FILE *vars);
/* The placeholders spec:<dcb|els>_h<h>:<check> (delam check's numbers) and spec:<dcb|els>:*. */
void ver_report_spec_vars(report *R);
/* Their table in the document (the figure's section). */
void ver_report_spec_table(report *R);

/* report_data.c */
/* Reads summary.json of c->dir into *c; 0 if read. */
int ver_report_read_summary(rep_case *c);
/* Sets up the analytic bar of the case's scene and measures the load curve. */
void ver_report_measure(const rep_ctx *r, rep_case *c);
/* Load rows of a case: delta and P (malloc'd, caller frees); returns the count. */
int ver_report_load(const rep_case *c, double **delta, double **P);
#endif
