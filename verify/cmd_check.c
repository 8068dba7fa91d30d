/*
 * cmd_check.c - `delam check [--scene SCENE] DIR`: judges a run folder that any code
 * wrote, with the checks `delam verify` applies to delam's own runs (policy.c, metrics.h;
 * nothing here decides a tolerance).  A delam folder is judged against its own scene.ini
 * (SCENE and the options must agree with it: ver_check_scene); another code's folder
 * against SCENE with the options.
 *
 * Input (docs/output-formats.md, "Checking a run of another code"): DIR/load.csv
 * (required: delta and P_grip, P_fixed if present), DIR/energy.csv (optional: W_ext, KE,
 * SE, W_coh, D and delam's ledger; without it the external work is the curve's area)
 * and DIR/final.csv or --particles FILE (optional: x0, y0, lambda).  Output: one line
 * per check, the verdict, DIR/check.json.  Exit status 0 every check passed (or within a
 * known limit), 1 a check failed or check.json could not be written, 2 unusable input.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "build_info.h"
#include "check_folder.h"
#include "check_spec.h"
#include "cmd.h"
#include "datadir.h"
#include "foreign.h"
#include "io.h"
#include "metrics.h"
#include "summary.h"

#define PROG "delam check"

static void usage(FILE *f)
{
  fprintf(f,
    "usage: delam check [--scene SCENE] DIR [options]\n"
    "Judges a run folder written by any code against the closed-form bar of its scene, with\n"
    "the checks of `delam verify` (peak load, elastic and softening slopes, separation,\n"
    "load-curve error, external work; dissipation and energy balance when energy.csv is\n"
    "there; band width and crack angle when final particles are).  At alpha 90 (q 1,\n"
    "s0 = snf) also the load-curve error against the exact solution at the scene's grip\n"
    "speed (curve_wave, docs/model.md sec. 5a): judged, with its peak, where the scene's\n"
    "decohesion.path is interface (a crack as one cohesive line: iface90), else printed.\n"
    "A folder of the static solver (its scene.ini says solver.type = static, or --set\n"
    "solver.type=static) holds equilibrium states, not interval averages: its curve is\n"
    "judged as a path too (curve_path: RMS distance from the analytic path in\n"
    "(delta / delta_peak, P / Pmax), snapback included; delta_5: where the load falls to\n"
    "5 %% of Pmax after the peak), and nothing against a grip speed.\n\n"
    "DIR holds load.csv (header with at least delta and P_grip, or delta and P as\n"
    "delam analytic --curve writes it), optionally energy.csv\n"
    "(W_ext, KE, SE, W_coh, D) and final.csv (x0, y0, lambda); see docs/output-formats.md.\n\n"
    "A folder delam wrote is judged against DIR/scene.ini, the effective scene the run\n"
    "computed; --scene and the options below then say what the run was meant to be, and a\n"
    "folder whose scene.ini differs from them on a key a check reads (the bar, the\n"
    "material, the law, h, ppc, the method's Le, path and fields, the grip speed and\n"
    "control, the solver) is refused, naming the keys.  Another code's folder (no\n"
    "scene.ini) needs --scene.\n\n"
    "options:\n"
    "  --scene SCENE     the scene the run was meant to compute (a file, or a name: fig6)\n"
    "  --h H, --ppc N    the run's grid spacing and particles per cell (default: from\n"
    "                    DIR/scene.ini when delam wrote the folder, else the scene's)\n"
    "  --method NAME     the method preset the run used (paper, band or interface),\n"
    "                    as for delam run (default: DIR/scene.ini's when delam wrote\n"
    "                    the folder, else the scene's)\n"
    "  --set S.K=V       set a key of the scene, as for delam run (repeatable)\n"
    "  --particles FILE  the final particle CSV (default DIR/final.csv when present)\n"
    "  --columns MAP     another code's load.csv header: delta=NAME,P_grip=NAME (either or\n"
    "                    both; the other keeps its own name)\n"
    "  --sign S          1 (default) or -1: the load is read times S (a file with\n"
    "                    compression positive)\n"
    "  --out FILE        where check.json goes (default DIR/check.json)\n"
    "  --help            this text\n"
    "Not judged (exit 2): a folder of delam's (a scene.ini, or energy.csv or final.csv\n"
    "with delam's schema line) without a summary.json; a summary.json that is not a\n"
    "regular file holding one whole JSON object, or whose \"complete\" is there and not\n"
    "true (delam's must have it); a file that is not a regular text file;\n"
    "a delta that goes back where the grip only pulls (solver.type = explicit and\n"
    "loading.control = grip); an energy.csv whose W_ext is more than 1%% of the work\n"
    "from the area under load.csv's P_grip-delta curve, or that does not cover the\n"
    "same times; a folder a delam process is writing now.\n\n"
    "exit status: 0 all checks pass (or are within a known limit), 1 a check failed or\n"
    "check.json could not be written, 2 bad usage or unusable input (file, line and\n"
    "column named)\n");
}

/* Informational, never judged (not a ver_check: the checks' classes and verdicts stay as
 * policy.c makes them): the dissipation at the separation this check detected and after
 * it.  A snapback run (fig8, a30) can decohere after the band has cut the bar (docs/methods.md
 * sec. 5c); D_final alone does not say when.  Needs energy.csv with the same rows as
 * load.csv (as delam writes them), whose deltas then date its D column. */
typedef struct {
  int have;          /* 1: computed                                         */
  double delta_sep;  /* the check's separation (the load test)              */
  double D_cut, D_after_cut, D_ref; /* D at delta_sep, D_final - D_cut, U0 x area */
  char why[120];     /* why it is left out, when it is                      */
} check_info;

/* Checks left out because the closed form gives them no finite reference (a relative
 * error needs one that is not 0), each with why: never a verdict on NaN or inf. */
typedef struct {
  int n;
  char name[VER_NCHECK][24];
  char why[VER_NCHECK][200];
} check_skips;

/* Why a check's reference is degenerate, into why. */
static void skip_reason(const ver_case *c, const ver_check *k, char *why, size_t len)
{
  if (!strcmp(k->name, "k_soft") && c->have_ana && !isfinite(k->reference))
    snprintf(why, len, "the closed form's softening branch is vertical at the peak (g = %.4g: the load drops at "
             "one delta, eq. 36 gives dP/ddelta = %g): no finite slope to compare with", c->ana.g, k->reference);
  else
    snprintf(why, len, "the closed form gives reference %g%s: no %s error to judge", k->reference,
             k->rel && k->reference == 0.0 ? " (a relative error needs one that is not 0)" : "",
             k->rel ? "relative" : "finite");
}

/* The checks whose reference is not finite (or 0 where the error is relative) are taken
 * out of c into sk, with why; the verdict is then that of the rest. */
static void skip_degenerate(ver_case *c, check_skips *sk)
{
  sk->n = 0;
  for (int j = 0; j < c->nchk;) {
    const ver_check *k = &c->chk[j];
    if (isfinite(k->reference) && !(k->rel && k->reference == 0.0)) {
      j++;
      continue;
    }
    snprintf(sk->name[sk->n], sizeof sk->name[0], "%s", k->name);
    skip_reason(c, k, sk->why[sk->n], sizeof sk->why[0]);
    sk->n++;
    ver_policy_drop(c, sk->name[sk->n - 1]);
  }
}

/* Why a measured number is NaN (the check fails on it): what the rows lack. */
static const char *unmeasured(const ver_case *c, const char *name)
{
  const int st = c->vs.sc.solver == MPM_SOLVER_STATIC;
  if (!strcmp(name, "k_elastic"))
    return "fewer than 3 rows between 0.1 and 0.6 of the peak before it, and no row under that band followed by "
           "one over it";
  if (!strcmp(name, "k_soft"))
    return "the load never falls under 0.2 of the peak after it";
  if (!strcmp(name, "delta_sep"))
    return st ? "the load never falls to run.sep_load of the peak after it"
              : "the load's mean over a window of 4 L / c never stays under run.sep_load of the peak after it";
  if (!strcmp(name, "load_after_sep"))
    return "no separation detected (delta_sep)";
  if (!strcmp(name, "crack_angle"))
    return "fewer than 2 particles at or past the separation threshold, or no preferred direction among them";
  if (!strncmp(name, "curve", 5))
    return "no row inside the compared window";
  if (!strcmp(name, "peak_P"))
    return "no row with a finite load";
  return "the rows give no finite value";
}

static int write_json(const char *out, const ver_case *c, const check_skips *sk, const check_info *info,
                      const char *dir, const char *scene_path, int have_en, const char *pfile, int rc)
{
  cJSON *o = cJSON_CreateObject();
  cJSON_AddNumberToObject(o, "schema", VER_SCHEMA_CHECK);
  cJSON_AddStringToObject(o, "dir", dir);
  cJSON_AddStringToObject(o, "scene", c->vs.name);
  cJSON_AddStringToObject(o, "scene_file", scene_path);
  cJSON_AddNumberToObject(o, "h", c->vs.sc.h);
  cJSON_AddNumberToObject(o, "ppc", c->vs.sc.ppc);
  cJSON *ov = cJSON_AddArrayToObject(o, "overrides");
  for (int i = 0; i < c->vs.nover; i++)
    cJSON_AddItemToArray(ov, cJSON_CreateString(c->vs.over[i]));
  cJSON *in = cJSON_AddObjectToObject(o, "inputs");
  cJSON_AddStringToObject(in, "load", "load.csv");
  if (have_en)
    cJSON_AddStringToObject(in, "energy", "energy.csv");
  if (pfile)
    cJSON_AddStringToObject(in, "particles", pfile);
  cJSON_AddStringToObject(o, "checked_by", ver_build_version());
  cJSON *ck = cJSON_AddArrayToObject(o, "checks");
  for (int j = 0; j < c->nchk; j++) {
    cJSON *kj = ver_check_json(&c->chk[j]);
    if (isnan(c->chk[j].measured)) /* null in the file: why */
      cJSON_AddStringToObject(kj, "not_measured", unmeasured(c, c->chk[j].name));
    cJSON_AddItemToArray(ck, kj);
  }
  cJSON *sj = cJSON_AddArrayToObject(o, "skipped");
  for (int j = 0; j < sk->n; j++) {
    cJSON *e = cJSON_CreateObject();
    cJSON_AddStringToObject(e, "name", sk->name[j]);
    cJSON_AddStringToObject(e, "reason", sk->why[j]);
    cJSON_AddItemToArray(sj, e);
  }
  if (have_en) { /* informational: not a check, never part of the verdict */
    cJSON *io = cJSON_AddObjectToObject(o, "info");
    cJSON_AddNumberToObject(io, "delta_sep", info->delta_sep);
    cJSON_AddNumberToObject(io, "D_cut", info->have ? info->D_cut : NAN);
    cJSON_AddNumberToObject(io, "D_after_cut", info->have ? info->D_after_cut : NAN);
    cJSON_AddNumberToObject(io, "D_reference", info->D_ref);
    cJSON_AddNumberToObject(io, "W_booked", c->W_booked);
    if (!info->have)
      cJSON_AddStringToObject(io, "note", info->why);
  }
  cJSON_AddStringToObject(o, "verdict", ver_verdict_name(c->verdict));
  cJSON_AddNumberToObject(o, "exit_status", rc);
  char *txt = cJSON_Print(o);
  cJSON_Delete(o);
  if (!txt)
    return -1;
  const size_t len = strlen(txt);
  char *t2 = realloc(txt, len + 2);
  if (!t2) {
    free(txt);
    return -1;
  }
  t2[len] = '\n';
  t2[len + 1] = '\0';
  const int r = ver_io_write_atomic(out, t2);
  free(t2);
  return r;
}

static int num_opt(const char *opt, const char *v, double *out)
{
  char *end;
  *out = v ? strtod(v, &end) : NAN;
  if (!v || end == v || *end || !isfinite(*out) || *out <= 0) {
    fprintf(stderr, PROG ": %s: '%s' is not a number > 0\n", opt, v ? v : "");
    return 2;
  }
  return 0;
}

/* The command line of delam check. */
typedef struct {
  const char *scene, *dir, *out, *pfile, *method, *sets[VER_MAX_OVER];
  int nset;
  double h, ppc;
  char col_delta[64], col_P[64]; /* --columns: the header's names of delta and P_grip */
  double sign;                   /* --sign: the load is read times this             */
} check_opts;

/* --columns delta=NAME,P_grip=NAME into o; 0, or 2 with a message. */
static int columns_opt(const char *v, check_opts *o)
{
  char buf[200];
  snprintf(buf, sizeof buf, "%s", v);
  for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
    char *eq = strchr(tok, '=');
    char *dst = eq && !strncmp(tok, "delta=", 6) ? o->col_delta : eq && !strncmp(tok, "P_grip=", 7) ? o->col_P : NULL;
    if (!dst || !eq[1] || strlen(eq + 1) >= 64) {
      fprintf(stderr, PROG ": --columns '%s': each item is delta=NAME or P_grip=NAME (a header name, under 64 "
              "characters)\n", v);
      return 2;
    }
    snprintf(dst, 64, "%s", eq + 1);
  }
  return 0;
}

/* Reads the options into o; 0, 1 (--help given) or 2 (bad usage). */
static int check_args(int argc, char **argv, check_opts *o)
{
  memset(o, 0, sizeof *o);
  o->sign = 1.0;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    int r = 0;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 1;
    } else if (!strcmp(a, "--scene") || !strcmp(a, "--out") || !strcmp(a, "--particles") || !strcmp(a, "--set") ||
               !strcmp(a, "--method")) {
      if (!v) {
        fprintf(stderr, PROG ": %s needs a value (see delam check --help)\n", a);
        return 2;
      }
      if (!strcmp(a, "--scene")) o->scene = v;
      else if (!strcmp(a, "--out")) o->out = v;
      else if (!strcmp(a, "--particles")) o->pfile = v;
      else if (!strcmp(a, "--method")) o->method = v;
      else if (o->nset < VER_MAX_OVER) o->sets[o->nset++] = v;
      else { fprintf(stderr, PROG ": more than %d --set\n", VER_MAX_OVER); return 2; }
      i++;
    } else if (!strcmp(a, "--columns") || !strcmp(a, "--sign")) {
      if (!v) {
        fprintf(stderr, PROG ": %s needs a value (see delam check --help)\n", a);
        return 2;
      }
      if (!strcmp(a, "--columns"))
        r = columns_opt(v, o);
      else if (!strcmp(v, "1") || !strcmp(v, "-1"))
        o->sign = atof(v);
      else {
        fprintf(stderr, PROG ": --sign '%s': 1 or -1\n", v);
        return 2;
      }
      i++;
    } else if (!strcmp(a, "--h")) { r = num_opt(a, v, &o->h); i++; }
    else if (!strcmp(a, "--ppc")) { r = num_opt(a, v, &o->ppc); i++; }
    else if (a[0] == '-' && a[1]) {
      fprintf(stderr, PROG ": unknown option '%s' (see delam check --help)\n", a);
      return 2;
    } else if (!o->dir) o->dir = a;
    else { fprintf(stderr, PROG ": one folder only ('%s' is extra)\n", a); return 2; }
    if (r) return r;
  }
  return 0;
}

static void info_measure(const ver_case *c, const ver_table *ld, const ver_table *en, check_info *in)
{
  memset(in, 0, sizeof *in);
  in->delta_sep = c->delta_sep;
  in->D_ref = c->have_ana ? c->ana.D_sep : NAN;
  if (!en)
    snprintf(in->why, sizeof in->why, "no energy.csv");
  else if (en->n != ld->n && !(ld->col[3] && en->col[12]))
    snprintf(in->why, sizeof in->why, "energy.csv has %ld rows, load.csv %ld, and not both a t column: its rows "
             "are not dated", en->n, ld->n);
  else if (!(c->delta_sep >= 0))
    snprintf(in->why, sizeof in->why, "no separation detected");
  else {
    /* by time where both files have it (the first energy row at or past the load row
     * of delta_sep), else row by row */
    const int by_t = ld->col[3] && en->col[12]; /* else the row counts are equal */
    const double ts = by_t ? ver_value_at(ld->col[0], ld->col[3], (size_t)ld->n, c->delta_sep) : NAN;
    in->D_cut = !by_t        ? ver_value_at(ld->col[0], en->col[4], (size_t)ld->n, c->delta_sep)
                : isfinite(ts) ? ver_value_at(en->col[12], en->col[4], (size_t)en->n, ts)
                               : NAN;
    in->D_after_cut = en->col[4][en->n - 1] - in->D_cut;
    in->have = isfinite(in->D_cut);
    if (!in->have)
      snprintf(in->why, sizeof in->why, "no row at delta_sep %.4g", c->delta_sep);
  }
}

/* The verdict lines: every check, the informational line, then the case's verdict and
 * what was left out. */
static void print_verdict(const char *label, const ver_case *c, const check_skips *sk, const check_info *in,
                          int have_en, int have_pt)
{
  for (int j = 0; j < c->nchk; j++) {
    const ver_check *k = &c->chk[j];
    if (!isnan(k->measured)) /* inf is a value: as far as can be, and it fails */
      ver_sweep_print_check(label, k);
    else
      printf("%-11s %s %s: not measured: %s (reference %.6g) -- %s\n", ver_verdict_name(k->verdict)[0] == 'f' ?
             "FAIL" : ver_verdict_name(k->verdict), label, k->name, unmeasured(c, k->name), k->reference, k->note);
  }
  for (int j = 0; j < sk->n; j++)
    printf("%-11s %s %s: not judged: %s\n", "skip", label, sk->name[j], sk->why[j]);
  if (in->have)
    printf("%-11s %s D_cut: %.6g at the detected separation (delta %.4g), %.6g after it; over U0 x area %.4g: "
           "%.4g and %.4g -- informational, never judged\n", "info", label, in->D_cut, in->delta_sep,
           in->D_after_cut, in->D_ref, in->D_cut / in->D_ref, in->D_after_cut / in->D_ref);
  else if (have_en)
    printf("%-11s %s D_cut: left out (%s)\n", "info", label, in->why);
  if (have_en && c->W_booked != 0.0)
    printf("%-11s %s W_booked: %.6g, %.3g of W_ext: the ledger's booked losses at the end (energy.csv's L_bc, "
           "L_flip, L_scheme, W_head, L_contact, L_debris, L_damp), the scheme's own and the loading machine's; "
           "W_ext_final is judged against UF x area plus them -- informational, never judged\n",
           "info", label, c->W_booked, c->W_booked / c->W_ext_final);
  if (!ver_case_check(c, "curve_wave") && isfinite(c->curve_wave))
    printf("%-11s %s curve_wave: %.4g, RMS of P - P_wave / Pmax against the exact solution at grip speed %g of a "
           "bar whose only weak plane is at x %g (a cohesive line; this run's path is another model there) -- "
           "informational, never judged\n",
           "info", label, c->curve_wave, c->vs.sc.speed, c->vs.sc.imp_x);
  printf("check: %s", ver_verdict_name(c->verdict));
  if (c->verdict == VER_FAIL) {
    printf(", failed:");
    for (int j = 0; j < c->nchk; j++)
      if (c->chk[j].verdict == VER_FAIL)
        printf(" %s", c->chk[j].name);
  }
  if (sk->n)
    printf(" (%d checks, %d skipped; %s%s)\n", c->nchk, sk->n, have_en ? "with energy.csv" : "no energy.csv: D and energy balance left out",
           have_pt ? ", with particles" : ", no particles: band width and angle left out");
  else
  printf(" (%d checks; %s%s)\n", c->nchk, have_en ? "with energy.csv" : "no energy.csv: D and energy balance left out",
         have_pt ? ", with particles" : ", no particles: band width and angle left out");
}

/* Whether the run's grip only pulls: the explicit solver under loading.control = grip
 * (the static solver follows a snapback, the dissipation control may too), in the scene
 * it is judged against (its own scene.ini where delam wrote it, ver_check_scene). */
static int grip_pulls(const ver_scene *vs)
{
  return vs->sc.control == MPM_CONTROL_GRIP && vs->sc.solver == MPM_SOLVER_EXPLICIT;
}

/* load.csv (delta, P_grip, P_fixed, t) and energy.csv (W_ext first, t at 12; or NULL) say
 * the same run: delta never goes back where the grip only pulls, and W_ext is the area
 * under P_grip(delta) within VER_WORK_AGREE.  0, or 2 with the reason in err. */
static int inputs_agree(const char *dir, int pulls, const ver_table *ld, const ver_table *en, char *err,
                        size_t errlen)
{
  const long b = pulls ? ver_foreign_backstep(ld->col[0], ld->n) : -1;
  if (b >= 0) {
    snprintf(err, errlen, "%s/load.csv: data row %ld: delta %.9g is below the row before's %.9g, but the grip only "
             "pulls (solver.type = explicit, loading.control = grip): not one run's curve", dir, b + 1, ld->col[0][b], ld->col[0][b - 1]);
    return 2;
  }
  if (!en)
    return 0;
  double rel, area;
  long row;
  char why[300];
  if (ver_foreign_work(ld->col[3], ld->col[0], ld->col[1], ld->n, en->col[12], en->col[0], en->n, &rel, &row, &area,
                       why, sizeof why)) {
    snprintf(err, errlen, "%s: load.csv and energy.csv disagree: %s", dir, why);
    return 2;
  }
  if (!(rel <= VER_WORK_AGREE)) {
    snprintf(err, errlen, "%s: load.csv and energy.csv disagree: energy.csv's W_ext %.6g (data row %ld) against "
             "%.6g, the area under load.csv's P_grip-delta curve then: %.3g of the work apart (allowed: %g)", dir,
             en->col[0][row - 1], row, area, rel, VER_WORK_AGREE);
    return 2;
  }
  return 0;
}

/* What a folder gives delam check: the load table, and energy and particles if there. */
typedef struct {
  ver_table ld, en, pt;
  int have_en, have_pt;
  char ppath[1400];   /* the particle file */
} check_inputs;

static void free_inputs(check_inputs *in)
{
  ver_table_free(&in->ld);
  ver_table_free(&in->en);
  ver_table_free(&in->pt);
}

/* Reads DIR's files (after ver_check_finished) and checks that they agree (inputs_agree).  0,
 * or 2 with the file and the reason in err (nothing left allocated). */
static int read_inputs(const char *dir, const check_opts *o, const ver_scene *vs, check_inputs *in, char *err,
                       size_t errlen)
{
  const char *pfile = o->pfile;
  const char *const lnames[] = {o->col_delta[0] ? o->col_delta : "delta", o->col_P[0] ? o->col_P : "P_grip", "P_fixed",
                                "t"};
  static const char *const enames[] = {"W_ext", "KE",       "SE",     "W_coh",    "D",
                                       "L_bc",  "L_flip",   "L_scheme", "W_head", "L_contact", "L_debris", "L_damp", "t"};
  static const char *const pnames[] = {"x0", "y0", "lambda"};
  char path[1400];
  memset(in, 0, sizeof *in);
  snprintf(path, sizeof path, "%s/load.csv", dir);
  int r = ver_table_read(path, lnames, 4, 2, &in->ld, err, errlen);
  if (r == 2 && !o->col_P[0] && strstr(err, "no column 'P_grip'")) { /* delam analytic --curve's delta,P */
    const char *const an[] = {lnames[0], "P", "P_fixed", "t"};
    char e2[256];
    if (ver_table_read(path, an, 4, 2, &in->ld, e2, sizeof e2) == 0)
      r = 0;
  }
  if (r == 1)
    snprintf(err, errlen, "%s: no such file (the load-deflection curve is required)", path);
  if (r == 2 && strstr(err, "has no column")) /* another code's names: say how to map them */
    snprintf(err + strlen(err), errlen - strlen(err), "; another code's columns: --columns delta=NAME,P_grip=NAME");
  if (r)
    return 2;
  for (long i = 0; i < in->ld.n; i++) /* --sign: a file with compression positive */
    for (int c = 1; c < 3; c++)
      if (in->ld.col[c])
        in->ld.col[c][i] *= o->sign;
  snprintf(path, sizeof path, "%s/energy.csv", dir);
  r = ver_table_read(path, enames, 13, 5, &in->en, err, errlen);
  in->have_en = r == 0;
  if (r == 2 || inputs_agree(dir, grip_pulls(vs), &in->ld, in->have_en ? &in->en : NULL, err, errlen)) {
    free_inputs(in);
    return 2;
  }
  snprintf(in->ppath, sizeof in->ppath, "%s", pfile ? pfile : "");
  if (!pfile)
    snprintf(in->ppath, sizeof in->ppath, "%s/final.csv", dir);
  r = ver_table_read(in->ppath, pnames, 3, 3, &in->pt, err, errlen);
  in->have_pt = r == 0;
  if (r == 2 || (r == 1 && pfile)) {
    if (r == 1)
      snprintf(err, errlen, "%s: no such file", in->ppath);
    free_inputs(in);
    return 2;
  }
  return 0;
}

int ver_cmd_check(int argc, char **argv)
{
  check_opts o;
  const int pa = check_args(argc, argv, &o);
  if (pa)
    return pa == 1 ? 0 : 2;
  const char *dir = o.dir, *out = o.out;
  if (!dir) {
    fprintf(stderr, PROG ": needs a run folder (usage: delam check [--scene SCENE] DIR)\n");
    return 2;
  }
  static ver_case c; /* large; one per process */
  memset(&c, 0, sizeof c);
  char err[4800], sname[64];
  const ver_check_opts so = {o.scene, dir, o.method, o.sets, o.nset, o.h, o.ppc};
  if (ver_check_finished(dir, ver_check_ours(dir), sname, sizeof sname, err, sizeof err) ||
      ver_check_scene(&so, sname, &c.vs, err, sizeof err)) {
    fprintf(stderr, PROG ": %s\n", err);
    return 2;
  }
  if (c.vs.sc.specimen != MPM_SPEC_BAR || c.vs.sc.grips == MPM_GRIPS_HELD) /* its own references */
    return ver_check_spec(dir, &c.vs, out);
  char aerr[256];
  c.have_ana = ver_scene_bar(&c.vs.sc, &c.ana, aerr, sizeof aerr) == 0;
  const mpm_scene *sc = &c.vs.sc;
  /* where curve_wave is judged (policy.c: the interface, the explicit solver), a solution
   * too large to build is no verdict; elsewhere it is informational and left out */
  if (c.have_ana && sc->path == MPM_PATH_IFACE && sc->solver != MPM_SOLVER_STATIC && ver_curve_wave_size(&c.ana, sc->speed, sc->rho, sc->imp_x, sc->sep_threshold,
                                        ver_curve_end(&c.ana, sc->sep_threshold), aerr, sizeof aerr)) {
    fprintf(stderr, PROG ": %s: curve_wave needs the exact solution at the grip speed, and %s: not judged\n", dir,
            aerr);
    return 2;
  }
  snprintf(c.scene, sizeof c.scene, "%s", c.vs.name);
  snprintf(c.id, sizeof c.id, "%.100s", dir);

  check_inputs in;
  if (read_inputs(dir, &o, &c.vs, &in, err, sizeof err)) {
    fprintf(stderr, PROG ": %s\n", err);
    return 2;
  }
  const ver_table *ld = &in.ld;
  const int have_en = in.have_en, have_pt = in.have_pt;
  ver_foreign_measure(&c, ld, have_en ? &in.en : NULL, have_pt ? &in.pt : NULL);
  ver_policy_case(&c);
  /* the checks whose input is not there are left out, not failed; "run" (delam's own
   * stop rule) says nothing of another code's folder */
  ver_policy_drop(&c, "run");
  if (!have_en) {
    ver_policy_drop(&c, "D_final");
    ver_policy_drop(&c, "energy_residual");
  }
  if (!have_pt) {
    ver_policy_drop(&c, "band_width");
    ver_policy_drop(&c, "crack_angle");
  }
  char label[160];
  snprintf(label, sizeof label, "%s vs %s-h%g-ppc%d", dir, c.vs.name, c.vs.sc.h, c.vs.sc.ppc);
  check_info info;
  info_measure(&c, ld, have_en ? &in.en : NULL, &info);
  check_skips sk;
  skip_degenerate(&c, &sk);
  print_verdict(label, &c, &sk, &info, have_en, have_pt);
  double pmin = 0.0, pmax = 0.0;
  for (long i = 0; i < ld->n; i++) {
    pmin = fmin(pmin, ld->col[1][i]);
    pmax = fmax(pmax, ld->col[1][i]);
  }
  if (-pmin > pmax) /* tension is positive here */
    printf("check: the load is mostly negative (least %g, largest %g): a file with compression positive? "
           "--sign -1 reads it the other way\n", pmin, pmax);
  const int rc = c.verdict == VER_FAIL ? 1 : 0;
  char jpath[1400];
  snprintf(jpath, sizeof jpath, "%s", out ? out : "");
  if (!out)
    snprintf(jpath, sizeof jpath, "%s/check.json", dir);
  const int wrc = write_json(jpath, &c, &sk, &info, dir, c.vs.path, have_en, have_pt ? in.ppath : NULL, rc);
  const int werr = errno;
  free_inputs(&in);
  if (wrc) {
    fprintf(stderr, PROG ": %s: cannot write: %s\n", jpath, strerror(werr));
    return 1;
  }
  printf("check: -> %s\n", jpath);
  return rc;
}
