/*
 * cmd_analytic.c - `delam analytic`: the closed-form uniaxial bar of analytic/ana.h
 * (paper sec. 3.2, eqs. 28-37): r0, g, slopes, snapback, energies, and optionally
 * the load-deflection curve as CSV.  With --speed, the same bar at that grip speed
 * (analytic/ana_wave.c: the exact 1-D wave solution, alpha 90 only) for the peak and the
 * curve.  With --specimen dcb|els, the specimens' references instead (cmd_analytic_spec.c).
 *
 * Options are parsed by hand (no getopt state): `--name value` or `--name=value`.
 * Every bad option gives one line on stderr naming it and its allowed range, and
 * exit status 2.  The ranges here are the ones ana_bar_init enforces; it is still
 * called and its message printed should the two ever disagree.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "ana.h"
#include "cmd.h"

#define PROG "delam analytic"

enum { OPT_DBL, OPT_INT, OPT_STR, OPT_FLAG };
enum { R_POS, R_ALPHA, R_NU, R_MODEL, R_POINTS, R_NONNEG, R_NONE };

typedef struct {
  const char *name;  /* without the leading "--" */
  int kind;          /* OPT_* */
  int range;         /* R_*: which check, see in_range() */
  const char *allowed;
  const char *help;
} opt_spec;

/* Order matches the slots of the values[] array in ver_cmd_analytic. */
enum {
  O_ALPHA, O_SNF, O_STF, O_U0, O_S0, O_Q, O_E, O_NU, O_L, O_H, O_MODEL,
  O_JSON, O_CURVE, O_POINTS, O_DEND, O_SPEED, O_RHO, O_HELP, O_COUNT
};

static const opt_spec specs[O_COUNT] = {
    [O_ALPHA] = {"alpha", OPT_DBL, R_ALPHA, "(0, 90] deg", "laminate angle from the x-axis"},
    [O_SNF] = {"snf", OPT_DBL, R_POS, "finite, > 0", "normal traction at failure initiation"},
    [O_STF] = {"stf", OPT_DBL, R_POS, "finite, > 0", "shear traction at failure initiation"},
    [O_U0] = {"U0", OPT_DBL, R_POS, "finite, > 0", "energy dissipated per unit area at separation"},
    [O_S0] = {"s0", OPT_DBL, R_POS, "finite, > 0", "reference traction, ubar0 = U0 / s0"},
    [O_Q] = {"q", OPT_DBL, R_POS, "finite, > 0", "softening exponent, sbar = lambda^q"},
    [O_E] = {"E", OPT_DBL, R_POS, "finite, > 0", "Young's modulus"},
    [O_NU] = {"nu", OPT_DBL, R_NU, "(-1, 0.5]", "Poisson's ratio (recorded only; uniaxial stress)"},
    [O_L] = {"L", OPT_DBL, R_POS, "finite, > 0", "bar length"},
    [O_H] = {"H", OPT_DBL, R_POS, "finite, > 0", "bar height"},
    [O_MODEL] = {"model", OPT_INT, R_MODEL, "1 or 2", "1 associated, 2 opening only (eq. 37)"},
    [O_JSON] = {"json", OPT_FLAG, R_NONE, "", "print one JSON object instead of the summary"},
    [O_CURVE] = {"curve", OPT_STR, R_NONE, "a writable path", "write the load-deflection curve as delta,P CSV"},
    [O_POINTS] = {"points", OPT_INT, R_POINTS, "integer in [4, 10000000]", "number of curve points"},
    [O_DEND] = {"delta-end", OPT_DBL, R_NONNEG, "finite, >= 0",
                "end displacement of the curve"},
    [O_SPEED] = {"speed", OPT_DBL, R_POS, "finite, > 0",
                 "grip speed: the bar's wave solution at this speed (alpha 90, q 1, s0 = snf)"},
    [O_RHO] = {"rho", OPT_DBL, R_POS, "finite, > 0", "density, for --speed (wave speed sqrt(E / rho))"},
    [O_HELP] = {"help", OPT_FLAG, R_NONE, "", "this text"},
};

static int in_range(int range, double v)
{
  switch (range) {
  case R_POS:
    return isfinite(v) && v > 0.0;
  case R_ALPHA:
    return isfinite(v) && v > 0.0 && v <= 90.0;
  case R_NU:
    return isfinite(v) && v > -1.0 && v <= 0.5;
  case R_MODEL:
    return v == 1.0 || v == 2.0;
  case R_POINTS:
    return v >= 4.0 && v <= 1e7;
  case R_NONNEG:
    return isfinite(v) && v >= 0.0;
  default:
    return 1;
  }
}

static void print_help(FILE *f)
{
  ana_params dp;
  ana_params_default(&dp);
  const ana_params *d = &dp;
  const double defs[] = {d->alpha_deg, d->snf, d->stf, d->U0, d->s0, d->q, d->E, d->nu, d->L, d->H};
  fprintf(f, "usage: " PROG " [OPTIONS]\n"
             "Closed-form uniaxial bar with decohesion (paper sec. 3.2, eqs. 28-37).\n"
             "Defaults are the Fig. 6 case.  Options take `--name value` or `--name=value`.\n\n");
  for (int i = 0; i < O_COUNT; i++) {
    const opt_spec *s = &specs[i];
    char lhs[40], def[48] = "";
    snprintf(lhs, sizeof lhs, "--%s%s", s->name,
             s->kind == OPT_FLAG ? "" : s->kind == OPT_STR ? " FILE" : s->kind == OPT_INT ? " N" : " X");
    if (i < O_MODEL)
      snprintf(def, sizeof def, "default %g", defs[i]);
    else if (i == O_MODEL)
      snprintf(def, sizeof def, "default %d", d->model);
    else if (i == O_POINTS)
      snprintf(def, sizeof def, "default 401");
    else if (i == O_CURVE)
      snprintf(def, sizeof def, "default none");
    else if (i == O_DEND)
      snprintf(def, sizeof def, "default 1.5 x the largest delta of the curve");
    else if (i == O_SPEED)
      snprintf(def, sizeof def, "default none: the quasi-static bar");
    else if (i == O_RHO)
      snprintf(def, sizeof def, "default 1");
    fprintf(f, "  %-16s %s\n", lhs, s->help);
    if (s->kind != OPT_FLAG)
      fprintf(f, "  %-16s   %s; allowed %s\n", "", def, s->allowed);
  }
  fprintf(f, "  %-16s %s\n", "--specimen S", "dcb or els: the specimens' references instead of the bar");
  fprintf(f, "  %-16s   see `delam analytic --specimen dcb --help`\n", "");
  fprintf(f, "\nexit status: 0 ok, 1 the curve file could not be written, 2 bad option\n");
}

static int bad(const opt_spec *s, const char *what, const char *val)
{
  if (val)
    fprintf(stderr, PROG ": --%s: %s '%s' (allowed: %s)\n", s->name, what, val, s->allowed);
  else
    fprintf(stderr, PROG ": --%s: %s (allowed: %s)\n", s->name, what, s->allowed);
  return 2;
}

/* Parses one numeric value with strtod; integers must also be whole. */
static int parse_value(const opt_spec *s, const char *val, double *out)
{
  if (!val || !*val)
    return bad(s, "missing value", NULL);
  char *end = NULL;
  errno = 0;
  const double v = strtod(val, &end);
  if (end == val || *end != '\0' || errno == ERANGE || !isfinite(v))
    return bad(s, "not a finite number:", val);
  if (s->kind == OPT_INT && (v != floor(v) || fabs(v) > (double)INT_MAX))
    return bad(s, "not an integer:", val);
  if (!in_range(s->range, v))
    return bad(s, "out of range:", val);
  *out = v;
  return 0;
}

static cJSON *to_json(const ana_bar *b)
{
  cJSON *o = cJSON_CreateObject();
  if (!o)
    return NULL;
  const ana_params *p = &b->p;
  const struct {
    const char *k;
    double v;
  } num[] = {
      {"alpha", p->alpha_deg}, {"snf", p->snf}, {"stf", p->stf}, {"U0", p->U0}, {"s0", p->s0},
      {"q", p->q}, {"E", p->E}, {"nu", p->nu}, {"L", p->L}, {"H", p->H}, {"model", p->model},
      {"r0", b->r0}, {"mec_n", b->mec[0]}, {"mec_t", b->mec[1]}, {"upx_sep", b->upx_sep},
      {"g", b->g}, {"Pmax", b->Pmax}, {"k_elastic", b->k_elastic}, {"k_soft_peak", b->k_soft_peak},
      {"delta_peak", b->delta_peak}, {"delta_sep", b->delta_sep}, {"sstar_turn", b->sstar_turn},
      {"UD", b->UD}, {"UU", b->UU}, {"UF", b->UF}, {"area", b->area}, {"W_sep", b->W_sep},
      {"D_sep", b->D_sep},
  };
  for (size_t i = 0; i < sizeof num / sizeof num[0]; i++) {
    /* JSON has no infinity (k_soft_peak is infinite for q = 1, g = 1): null */
    cJSON *item = isfinite(num[i].v) ? cJSON_CreateNumber(num[i].v) : cJSON_CreateNull();
    if (!item) {
      cJSON_Delete(o);
      return NULL;
    }
    cJSON_AddItemToObject(o, num[i].k, item);
  }
  if (!cJSON_AddBoolToObject(o, "snapback", b->snapback)) {
    cJSON_Delete(o);
    return NULL;
  }
  return o;
}

static void print_summary(const ana_bar *b)
{
  const ana_params *p = &b->p;
  printf("uniaxial bar, model %d (%s)\n", p->model, p->model == 1 ? "associated" : "opening only");
  printf("  inputs     alpha %g deg, snf %g, stf %g, U0 %g, s0 %g, q %g, E %g, nu %g, L %g, H %g\n",
         p->alpha_deg, p->snf, p->stf, p->U0, p->s0, p->q, p->E, p->nu, p->L, p->H);
  printf("  peak       r0 = %.6g, Pmax = %.6g at delta_peak = %.6g\n", b->r0, b->Pmax, b->delta_peak);
  printf("  g          %.6g (eq. %s)\n", b->g, p->model == 1 ? "35" : "37");
  printf("  slopes     elastic %.6g, softening just after the peak %.6g (eq. 36)\n", b->k_elastic,
         b->k_soft_peak);
  if (b->snapback)
    printf("  snapback   yes, the softening branch turns at sigma* = %.6g\n", b->sstar_turn);
  else
    printf("  snapback   no\n");
  printf("  separation delta_sep = %.6g, mec = (%.6g n, %.6g t)\n", b->delta_sep, b->mec[0], b->mec[1]);
  printf("  energies   per unit area UD %.6g, UU %.6g, UF %.6g; area %.6g\n", b->UD, b->UU, b->UF, b->area);
  printf("             W_sep = %.6g, D_sep = %.6g\n", b->W_sep, b->D_sep);
}

/* Writes the curve to path.tmp and renames it over path, so a reader never sees a
 * half-written file. */
static int write_curve(const ana_bar *b, const ana_wave *w, const char *path, int n, double delta_end, int *written)
{
  double *d = malloc((size_t)n * sizeof *d), *P = malloc((size_t)n * sizeof *P);
  const size_t len = strlen(path) + 5;
  char *tmp = malloc(len);
  int rc = 1;
  if (!d || !P || !tmp) {
    fprintf(stderr, PROG ": out of memory for %d curve points\n", n);
    goto out;
  }
  int k = n;
  if (w) /* evenly in delta, from 0 */
    for (int i = 0; i < n; i++) {
      d[i] = delta_end * i / (n - 1);
      P[i] = ana_wave_load_at(w, d[i]);
    }
  else
    k = ana_bar_curve(b, delta_end, n, d, P);
  if (k <= 0) {
    fprintf(stderr, PROG ": no curve for delta_end %g with %d points\n", delta_end, n);
    goto out;
  }
  snprintf(tmp, len, "%s.tmp", path);
  FILE *f = fopen(tmp, "w");
  if (!f) {
    fprintf(stderr, PROG ": --curve: cannot write '%s': %s\n", tmp, strerror(errno));
    goto out;
  }
  fprintf(f, "delta,P\n");
  for (int i = 0; i < k; i++)
    fprintf(f, "%.17g,%.17g\n", d[i], P[i]);
  const int werr = ferror(f);
  if (fclose(f) != 0 || werr) {
    fprintf(stderr, PROG ": --curve: error writing '%s'\n", tmp);
    remove(tmp);
    goto out;
  }
  if (rename(tmp, path) != 0) {
    fprintf(stderr, PROG ": --curve: cannot rename '%s' to '%s': %s\n", tmp, path, strerror(errno));
    remove(tmp);
    goto out;
  }
  *written = k;
  rc = 0;
out:
  free(d);
  free(P);
  free(tmp);
  return rc;
}

/* The command's options: the bar's parameters and what to print. */
typedef struct {
  ana_params p;
  int json, points;
  const char *curve;  /* --curve FILE, or NULL                                  */
  double delta_end;   /* < 0: the default, set once the bar is known            */
  double speed, rho;  /* the bar at the grip speed (0: none), its density       */
} an_opts;

/* Parses argv into o: -1 on to the bar, 0 help printed, 2 a bad option (said on stderr). */
static int parse_args(int argc, char **argv, an_opts *o)
{
  ana_params p;
  ana_params_default(&p);
  *o = (an_opts){.p = p, .points = 401, .delta_end = -1.0, .rho = 1.0};
  double *dst[O_MODEL] = {&o->p.alpha_deg, &o->p.snf, &o->p.stf, &o->p.U0, &o->p.s0, &o->p.q, &o->p.E, &o->p.nu,
                          &o->p.L, &o->p.H};
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (strncmp(a, "--", 2) != 0 || !a[2]) {
      fprintf(stderr, PROG ": unexpected argument '%s' (allowed: the options of --help)\n", a);
      return 2;
    }
    const char *name = a + 2, *eq = strchr(name, '=');
    const size_t nlen = eq ? (size_t)(eq - name) : strlen(name);
    int k = -1;
    for (int j = 0; j < O_COUNT; j++)
      if (strlen(specs[j].name) == nlen && !strncmp(specs[j].name, name, nlen))
        k = j;
    if (k < 0) {
      fprintf(stderr, PROG ": unknown option '%.*s' (allowed: the options of --help)\n", (int)(nlen + 2), a);
      return 2;
    }
    const opt_spec *s = &specs[k];
    if (s->kind == OPT_FLAG) {
      if (eq) {
        fprintf(stderr, PROG ": --%s takes no value (allowed: --%s alone)\n", s->name, s->name);
        return 2;
      }
      if (k == O_HELP) {
        print_help(stdout);
        return 0;
      }
      o->json = 1;
      continue;
    }
    /* a following option is a missing value, never the value itself */
    const char *val = eq ? eq + 1 : (i + 1 < argc && strncmp(argv[i + 1], "--", 2) ? argv[++i] : NULL);
    if (s->kind == OPT_STR) {
      if (!val || !*val)
        return bad(s, "missing value", NULL);
      o->curve = val;
      continue;
    }
    double v;
    if (parse_value(s, val, &v))
      return 2;
    if (k < O_MODEL)
      *dst[k] = v;
    else if (k == O_MODEL)
      o->p.model = (int)v;
    else if (k == O_POINTS)
      o->points = (int)v;
    else if (k == O_SPEED)
      o->speed = v;
    else if (k == O_RHO)
      o->rho = v;
    else
      o->delta_end = v;
  }

  return -1;
}

/* The default end: past the farthest point of the curve, so that it ends separated; on
 * a q > 1 snapback that is the turning point, beyond both peak and separation. */
static double default_end(const ana_bar *bar)
{
  double end = fmax(bar->delta_peak, bar->delta_sep);
  if (bar->sstar_turn > 0.0 && bar->sstar_turn < 1.0) {
    double dt, Pt;
    ana_bar_softening_point(bar, bar->sstar_turn, &dt, &Pt);
    end = fmax(end, dt);
  }
  return 1.5 * end;
}

/* The bar's numbers (and the wave's peak at the grip speed) as JSON or text; 0, or 1 out
 * of memory. */
static int print_bar(const an_opts *o, const ana_bar *bar, const ana_wave *wave, double wpeak, double wdpeak)
{
  if (o->json) {
    cJSON *j = to_json(bar);
    if (j && o->speed > 0.0) {
      cJSON_AddNumberToObject(j, "speed", o->speed);
      cJSON_AddNumberToObject(j, "rho", o->rho);
      cJSON_AddNumberToObject(j, "wave_Pmax", wpeak);
      cJSON_AddNumberToObject(j, "wave_delta_peak", wdpeak);
      cJSON_AddNumberToObject(j, "wave_transit", wave->Tg);
    }
    char *txt = j ? cJSON_Print(j) : NULL;
    cJSON_Delete(j);
    if (!txt) {
      fprintf(stderr, PROG ": out of memory building the JSON\n");
      return 1;
    }
    printf("%s\n", txt);
    cJSON_free(txt);
  } else {
    print_summary(bar);
    if (o->speed > 0.0)
      printf("  at speed   %g (rho %g, plane at L / 2, wave transit to the grip %.6g): peak %.6g at delta %.6g,\n"
             "             %+.3g %% of Pmax: the grip's load rises until the plane's unloading reaches it\n",
             o->speed, o->rho, wave->Tg, wpeak, wdpeak, 100.0 * (wpeak / bar->Pmax - 1.0));
  }
  return 0;
}

int ver_cmd_analytic(int argc, char **argv)
{
  for (int i = 1; i < argc; i++) /* the specimens are their own command */
    if (!strncmp(argv[i], "--specimen", 10) && (argv[i][10] == '\0' || argv[i][10] == '='))
      return ver_cmd_analytic_specimen(argc, argv);
  an_opts o;
  const int pa = parse_args(argc, argv, &o);
  if (pa >= 0)
    return pa;
  ana_bar bar;
  char err[200];
  if (ana_bar_init(&o.p, &bar, err, sizeof err) != ANA_OK) {
    fprintf(stderr, PROG ": %s\n", err);
    return 2;
  }
  const double delta_end = o.delta_end < 0.0 ? default_end(&bar) : o.delta_end;
  /* the bar at the grip speed: the plane at L / 2, as the scene files' flaw */
  ana_wave wave = {0};
  double wpeak = -INFINITY, wdpeak = 0.0;
  if (o.speed > 0.0) {
    const ana_wave_params wp = {o.speed, o.rho, 0.5 * o.p.L, 0.98};
    const int rc = ana_wave_init(&bar, &wp, delta_end, &wave, err, sizeof err);
    if (rc != ANA_OK) {
      fprintf(stderr, PROG ": --speed: %s\n", err);
      return rc == ANA_EINVAL ? 2 : 1;
    }
    wpeak = ana_wave_peak(&wave, &wdpeak);
  }
  if (print_bar(&o, &bar, &wave, wpeak, wdpeak))
    return 1;
  if (o.curve) {
    int k = 0;
    if (write_curve(&bar, o.speed > 0.0 ? &wave : NULL, o.curve, o.points, delta_end, &k)) {
      ana_wave_free(&wave);
      return 1;
    }
    if (!o.json)
      printf("  curve      %d points to delta %.6g written to %s%s\n", k, delta_end, o.curve,
             o.speed > 0.0 ? " (the wave solution)" : "");
  }
  ana_wave_free(&wave);
  return 0;
}
