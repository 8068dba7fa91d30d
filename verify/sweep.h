/*
 * sweep.h - the parts of `delam verify` (private to verify/): a case of the sweep
 * (ver_case) and a cross-case group (ver_cross), and the steps the driver (verify.c)
 * strings together:
 *   sweep_cases.c  which cases (the quick list, or every scene x h x ppc), their
 *                  scenes and analytic bars; reading back what a run left
 *   policy.c       the checks of a case and across cases, with their classes and
 *                  tolerances: pure functions of the measured numbers (unit-tested)
 *   sweep_out.c    verify.json, verify.csv, the printed lines and table
 */
#ifndef DELAM_VER_SWEEP_H
#define DELAM_VER_SWEEP_H

#include <stddef.h>

#include "ana.h"
#include "check.h"
#include "scene.h"
#include "verify.h"

#define VER_MAXSET 7
#define VER_NCHECK 16
/* room for the cross-case checks: --full needs about 120 (invariance 42, orders 24,
 * GCI 36, rate 3, MMS 4); ver_policy_cross_room fails a sweep that comes near it */
#define VER_MAXCROSS 256

/* A variant of a scene: a suffix for the case id and the override it stands for. */
typedef struct {
  const char *suffix; /* "" for the scene as written */
  const char *set;    /* "section.key=value" or NULL */
  int whole;          /* 1: to the scene's own end_delta, not the verify stop       */
  int slow;           /* k: set makes loading.speed the file's / 2^k (rate studies)  */
  int swap;           /* 1: the file's snf and stf exchanged (the other mode, --angles) */
} ver_variant;


typedef struct {
  /* what to run */
  char id[128];
  char scene[64];
  char path[600];
  ver_variant var;
  double h;
  int ppc;
  char sets[VER_MAXSET][128];      /* the --set overrides, as `delam run` gets them     */
  int nset;
  ver_scene vs;                /* the scene as the run sees it                      */
  int have_ana;
  ana_bar ana;
  double end_delta;
  double cost;                 /* particles x steps to the end, for scheduling       */
  char refused[240];           /* non-empty: the static solver refuses this case (its
                                  reason, as the solver gives it); the case is listed
                                  and judged as refused, never run                  */
  /* how the run went */
  int exit_code;               /* child's exit status; -1 not run (merge)            */
  int term_sig;                /* signal that killed the child, 0 if none            */
  double wall_s;               /* wall time of the child (or summary wall_s on merge) */
  int have_summary, complete;
  char error[600];
  /* measured */
  double peak_P, delta_peak, delta_sep, k_elastic, D_final, W_ext_final, energy_residual, delta_end;
  double energy_unbooked;      /* the balance without the booked losses (summary.json) */
  double W_booked;             /* the booked losses at the end (the ledger's L_bc, L_flip,
                                  L_scheme, W_head, L_contact, L_debris, L_damp); 0 without
                                  a ledger */
  double W_scheme;             /* of those, the discretisation's own: L_bc + L_flip + L_scheme;
                                  NaN without those columns */
  double k_soft, curve_l2, band_width, band_extent, angle;
  double curve_path, delta5; /* static runs: distance from the analytic path and where the
                                load falls to 5 % of the peak (ver_curve_path); NaN otherwise */
  double curve_wave; /* the curve error against the bar at the run's grip speed (ver_case_wave) */
  double wave_peak;  /* that solution's peak load (ver_case_wave; NaN where it does not apply) */
  double rate_floor; /* that solution's own curve error against the quasi-static bar over the
                        same rows (the rate's error at this speed; ver_case_wave)      */
  double D_diffuse;  /* dissipation outside the band, over U0 x area (ver_diffuse_share) */
  double P_after;    /* largest |P| past separation, over the peak (ver_load_after)       */
  double P_after_t, P_after_c; /* its largest tension and compression, over the peak   */
  size_t band_count;
  ver_check chk[VER_NCHECK];
  int nchk;
  int verdict;
} ver_case;

typedef struct {
  char name[64];          /* "D_invariance_h", "D_invariance_ppc", "order_h"          */
  char scene[64];
  char over[8];           /* "h" or "ppc": what varies                               */
  double fixed;           /* the ppc (or h) held fixed                                */
  int n;
  double x[8], y[8];      /* the varying parameter and the number per case            */
  char ids[8][128];
  char yname[24];         /* the points' value key ("" : D_final or curve_l2 by name) */
  ver_check chk;
} ver_cross;

/* sweep_cases.c */
/* 1 if the case's plane is at 90 deg (along a grid line). */
int ver_case_a90(const ver_case *c);

/* The exact solution at the case's own grip speed (ver_curve_err_wave, the plane at
 * imperfection.x from the grip): c->curve_wave, the load-curve error against it over the
 * same rows as curve_l2, c->wave_peak, its peak, and c->rate_floor, its own distance from
 * the quasi-static curve over those rows; NaN where that solution does not
 * apply (not alpha 90, q 1, s0 = snf) or without an analytic bar. */
void ver_case_wave(ver_case *c, const double *delta, const double *P, size_t n);

/* The case's check of that name, or NULL if it has none. */
const ver_check *ver_case_check(const ver_case *c, const char *name);
/* Sets up case c of scene file path (name scene) at h, ppc with variant v, and with
 * method a preset (as --method; NULL: the file's): id, overrides, analytic bar, end
 * displacement.  0, or 2 with err. */
int ver_case_init(ver_case *c, const char *path, const char *scene, const char *method, double h, int ppc,
                  ver_variant v, char *err, size_t len);
/* The case list of o (quick or full); 0, or 2 with a message on stderr. */
int ver_sweep_cases(const ver_verify_opts *o, ver_case **out, int *nout);
/* With o->merge_found: the cases of both lists whose folders DIR holds; 0 or 2. */
int ver_sweep_found(const ver_verify_opts *o, ver_case **cs, int *n);
/* DIR/<id>. */
void ver_case_dir(const ver_verify_opts *o, const ver_case *c, char *buf, size_t len);
/* Reads what the run left in DIR/<id>/ and measures from it (metrics.h). */
void ver_case_read(const ver_verify_opts *o, ver_case *c);

/* mms.c: the manufactured solution's order checks (USL, MUSL) into x; how many. */
int ver_mms_cross(ver_cross *x, int room);

/* policy.c */
/* The checks of one case (c->chk, c->verdict) from its measured numbers. */
void ver_policy_case(ver_case *c);
/* Removes check `name` from c (an input the case does not have) and judges c again. */
void ver_policy_drop(ver_case *c, const char *name);
/* The cross-case checks over cs into x (at most VER_MAXCROSS); their number. */
int ver_policy_cross(ver_case *cs, int n, ver_cross *x);
/* If the cross checks x[0..*nx) came within 4 of VER_MAXCROSS, where a group may have
 * found no room and been left out, a failing check saying so is added (in the last
 * slot if x is full). */
void ver_policy_cross_room(ver_cross *x, int *nx);
/* Sets g's check to the observed order p of y ~ x^p over its points, one-sided: pass
 * when p >= lo (policy_cross.c; the MMS checks use it too). */
void ver_policy_order_check(ver_cross *g, const char *name, double lo, const char *what);

/* sweep_out.c */
int ver_sweep_write_json(const ver_verify_opts *o, const ver_case *cs, int n, const ver_cross *x, int nx,
                         double wall, int rc);
int ver_sweep_write_csv(const ver_verify_opts *o, const ver_case *cs, int n);
/* DIR/verify_cross.csv: one row per cross-case check (order, gci, mms, invariance). */
int ver_sweep_write_cross_csv(const ver_verify_opts *o, const ver_cross *x, int nx);
void ver_sweep_print_check(const char *id, const ver_check *k);
/* One check as a JSON object (name, class, measured, reference, error, tolerance,
 * bounds, verdict, note), for verify.json and check.json. */
struct cJSON;
struct cJSON *ver_check_json(const ver_check *k);
void ver_sweep_print_table(const ver_case *cs, int n, const ver_cross *x, int nx);

#endif
