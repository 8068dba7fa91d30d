/*
 * summary.h - summary.json, the one record a run leaves of itself: what was run (scene,
 * h, ppc, dt, Le, scheme, shape, separation threshold) and what it measured (ver_summary).
 * Written by `delam run` (run.c) and read by verify, report and the --from scan through
 * the same two functions, so the schema has one definition.
 */
#ifndef DELAM_VER_SUMMARY_H
#define DELAM_VER_SUMMARY_H

#include <stddef.h>

#include "scene.h"

#define VER_CRIT_MAX 16 /* critical points summary.json lists */
/* A critical point of the static path, at the first increment past it. */
typedef struct {
  long increment;
  double delta, P;  /* that increment's state                                    */
  int kind;         /* MPM_QS_TIE, MPM_QS_LIMIT, MPM_QS_BIFURCATION (mpm.h)      */
} ver_crit;

typedef struct {
  double peak_P, delta_peak;     /* largest (interval-averaged) grip load and where  */
  double delta_sep;              /* separation: the first of delta_sep_cut and delta_sep_load; -1 if none */
  double delta_sep_cut;          /* first delta at which separated particles cut every particle row */
  double delta_sep_load;         /* first delta after the peak with the windowed |P| < sep_load * peak */
  double k_elastic;              /* least-squares slope of P(delta) for 0.1-0.6 peak before the peak */
  double D_final, W_ext_final, W_coh_final, KE_final, SE_final;
  double D_cut;                  /* D of the output row at delta_sep (NaN, null in the file, if none) */
  double D_after_cut;            /* D_final - D_cut: what decohered after the detected separation */
  double energy_residual;        /* max |W_ext + E0 - KE - SE - W_coh - booked| / max(max W_ext, E0) over
                                    the rows: what the energy ledger does not explain */
  double energy_unbooked;        /* the same without the booked terms                */
  double energy_created;         /* max (KE + SE + W_coh - W_ext - E0) / max(max W_ext, E0) over the
                                    rows: energy the run made (an unstable step), >= 0 */
  int unstable;                  /* 1: energy_created passed VER_CREATED_TOL (--allow-unstable) */
  double L_bc_final, L_flip_final, L_scheme_final, W_head_final, L_contact_final; /* the ledger (mpm.h) */
  double L_damp_final;           /* ... and what the local damping took (time.damping)           */
  double L_debris_final;         /* ... and what debris carried off the grid (mpm_step.c)        */
  long n_debris;                 /* separated particles that left the grid as debris     */
  double crack_tip_final;        /* dcb, els: the crack front's x at the end (NaN: the bar) */
  double gap_min;                /* the static interface's least normal opening (NaN: none) */
  double energy_start;           /* E0 = KE + SE at the start                        */
  double energy_kept;            /* free vibration: (KE + SE) at the end over E0; NaN otherwise */
  double period, period_exact, period_error; /* vibration: measured, 2 L / (m c) corrected, error */
  double delta_end;              /* where the run stopped                            */
  long steps;
  size_t particles;
  long n_soften, n_separate, n_bracketed;
  double wall_s, cpu_s, updates_per_s;
  int complete;                  /* 1 if the run reached its stop rule               */
  int status;                    /* mpm_status of the run                            */
  int threads_req;               /* --threads (0: chosen per step by the kernel)     */
  int threads_max;               /* the most threads a step could use                */
  long steps_multi;              /* steps that ran on more than one thread           */
  long probes, probes_busy;      /* thread probes made; skipped for want of an idle core */
  /* solver.type = static (kernel/mpm_static.c): its work; 0 for an explicit run */
  int static_run;                /* 1 for the static solver                           */
  long increments, newton, factorizations, cuts; /* load increments, Newton iterations,
                                    LU factorizations, increments retried smaller   */
  long updates;                  /* low-rank updates in a factorization's place      */
  long severed;                  /* interface segments the static solver let go at the end */
  int unknowns;                  /* free degrees of freedom                          */
  double t_eval, t_factor, t_solve; /* seconds: laws and assembly, factorization, solves */
  long ncrit;                    /* static: critical points the path crossed (mpm.h MPM_QS_TIE ...) */
  ver_crit crit[VER_CRIT_MAX];   /* the first VER_CRIT_MAX of them                   */
} ver_summary;

/* The ledger's booked losses at the end (the seven columns after D in energy.csv); a
 * term the summary lacks (a file from before it was booked) counts 0. */
double ver_summary_booked(const ver_summary *u);
/* Of those, the discretisation's own (L_bc + L_flip + L_scheme); NaN if the summary lacks
 * one of them. */
double ver_summary_scheme_loss(const ver_summary *u);

/* Schema versions of the files a run writes (docs/output-formats.md); each file says
 * its own: summary.json "schema", a first comment line in the CSV files and scene.ini,
 * a comment before the root element of the VTK files and snapshots.pvd.  Raised when a column or key changes meaning or
 * goes away (new keys and columns may join without a raise). */
#define VER_SCHEMA_SUMMARY 1
#define VER_SCHEMA_LOAD 1
#define VER_SCHEMA_ENERGY 3 /* 2: the ledger columns L_bc, L_flip, L_scheme, W_head; 3: L_contact,
                               taken out of L_scheme (two velocity fields) */
#define VER_SCHEMA_PARTICLES 1
#define VER_SCHEMA_LINE 1 /* <snapshot>-line.csv: decohesion.path = interface */
#define VER_SCHEMA_PVD 2 /* snapshots.pvd; 2: its DataSets are .vtp (1: legacy .vtk) */
#define VER_SCHEMA_VERIFY 3     /* verify.json and verify.csv                       */
#define VER_SCHEMA_CHECK 1      /* check.json                                        */
/* scene.ini: VER_SCHEMA_SCENE in scene.h */

/* What summary.json says: the run's description and its ver_summary. */
typedef struct {
  char case_id[128];
  char scene[64];
  char scene_file[512];
  double h, dt, sep_threshold;
  double damping;                /* time.damping (NaN if the file predates it: 0)   */
  double damping_beta;           /* time.damping_beta (NaN if the file predates it: 0) */
  double speed;                  /* loading.speed (NaN if the file predates it)      */
  int ppc;
  char le[16];                   /* "cell" or "particle"                             */
  char scheme[16];               /* "usl", "musl", "usf" or "usavg"                  */
  char shape[16];                /* "linear" or "gimp"                               */
  char fields[16];               /* "one" or "two" velocity fields                   */
  char damping_from[16];         /* "start" or "cut" ("" if the file predates it)   */
  char damping_about[16];        /* "drift" or "parts" ("" if the file predates it) */
  char path[16];                 /* decohesion.path: "free" or "line" ("" if absent) */
  char reversed_shear[16];       /* decohesion.reversed_shear: "even" or "closing" ("" if absent) */
  char motion[16];               /* grid.motion: "fixed" or "stretch" ("" if absent) */
  double path_reach;             /* decohesion.path_reach (NaN if absent)           */
  char error[512];               /* "" if none                                       */
  ver_summary u;                 /* numbers missing from the file read as NaN        */
} ver_summary_doc;

/* Writes dir/summary.json (through a temporary name).  0 or -1. */
int ver_summary_write(const char *dir, const ver_scene *vs, const ver_summary *u, const char *errmsg);
/* Reads dir/summary.json.  0, or -1 if it is missing or not JSON. */
int ver_summary_read(const char *dir, ver_summary_doc *d);

#endif
