/*
 * cmd_analytic_spec.c - `delam analytic --specimen dcb|els`: the specimens' references of
 * analytic/ana_spec.h (docs/specimens-reference.md): the law's Gc and separation openings,
 * the compliance at a0 by each beam theory, the LEFM propagation branches, and for the DCB
 * the cohesive reference's peak on three meshes with Richardson's extrapolation, and its
 * curve (--curve: delta, P, crack_tip).
 *
 * Options as `delam analytic`'s: `--name value` or `--name=value`; a bad one gives one line
 * on stderr and exit status 2.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ana_spec.h"
#include "cmd.h"

#define PROG "delam analytic --specimen"

enum { S_SPEC, S_A0, S_L, S_H, S_E, S_NU, S_SNF, S_STF, S_U0, S_S0, S_Q, S_CELLS, S_TIP, S_BEAM, S_CURVE, S_HELP, S_COUNT };

static const struct {
  const char *name, *arg, *help, *allowed;
} sopt[S_COUNT] = {
    [S_SPEC] = {"specimen", "dcb|els", "the specimen: DCB (mode I) or ELS (mode II)", "dcb or els"},
    [S_A0] = {"a0", "X", "pre-crack length from the loaded end (default 64)", "(0, L)"},
    [S_L] = {"L", "X", "bar length (default 192)", "finite, > 0"},
    [S_H] = {"H", "X", "bar height; arms t = H / 2 (default 32)", "finite, > 0"},
    [S_E] = {"E", "X", "Young's modulus (default 1024)", "finite, > 0"},
    [S_NU] = {"nu", "X", "Poisson's ratio (default 0.25)", "(-1, 0.5]"},
    [S_SNF] = {"snf", "X", "law's strength in opening (default DCB 1, ELS 10)", "finite, > 0"},
    [S_STF] = {"stf", "X", "law's strength in shear (default DCB 10, ELS 1)", "finite, > 0"},
    [S_U0] = {"U0", "X", "law's U0; Gc = q U0 / (q + 1) (default 0.375)", "finite, > 0"},
    [S_S0] = {"s0", "X", "law's reference traction, no effect in a pure mode (default 1)", "finite, > 0"},
    [S_Q] = {"q", "X", "softening exponent (default 1; the cohesive reference needs q >= 1)", "finite, > 0"},
    [S_CELLS] = {"cells", "N", "cohesive reference: cells of the coarsest of 3 meshes (default 192)",
                 "integer in [16, 250000]"},
    [S_TIP] = {"tip-end", "X", "cohesive reference: trace until the crack tip passes X (default (a0 + L) / 2)",
               "(a0, L)"},
    [S_BEAM] = {"beam", "euler|timoshenko", "the arm of the --curve (default timoshenko)", "euler or timoshenko"},
    [S_CURVE] = {"curve", "FILE", "write the cohesive curve (finest mesh) as delta,P,crack_tip CSV", "a writable path"},
    [S_HELP] = {"help", "", "this text", ""},
};

static void help(void)
{
  printf("usage: " PROG " dcb|els [OPTIONS]\n"
         "The DCB and ELS specimens' references (docs/specimens-reference.md): compliances,\n"
         "LEFM branches and, for the DCB, the cohesive beam reference.\n\n");
  for (int i = 0; i < S_COUNT; i++) {
    char lhs[48];
    snprintf(lhs, sizeof lhs, "--%s%s%s", sopt[i].name, *sopt[i].arg ? " " : "", sopt[i].arg);
    printf("  %-26s %s\n", lhs, sopt[i].help);
  }
  printf("\nexit status: 0 ok, 1 the reference failed or the curve could not be written, 2 bad option\n");
}

typedef struct {
  ana_spec_params p;
  ana_czm_opts o;
  const char *curve;
} sp_opts;

static int bad(int k, const char *what, const char *val)
{
  fprintf(stderr, PROG ": --%s: %s%s%s%s (allowed: %s)\n", sopt[k].name, what, val ? " '" : "", val ? val : "",
          val ? "'" : "", sopt[k].allowed);
  return 2;
}

/* One option's value into o; 0 or 2. */
static int set(sp_opts *o, int k, const char *val)
{
  if (k == S_SPEC || k == S_BEAM) {
    const char *a = k == S_SPEC ? "dcb" : "euler", *b = k == S_SPEC ? "els" : "timoshenko";
    if (!strcmp(val, a) || !strcmp(val, b)) {
      if (k == S_SPEC)
        ana_spec_default(strcmp(val, a) ? ANA_SPEC_ELS : ANA_SPEC_DCB, &o->p);
      else
        o->o.beam = strcmp(val, a) ? ANA_CZM_TIMOSHENKO : ANA_CZM_EULER;
      return 0;
    }
    return bad(k, "not one of the choices:", val);
  }
  if (k == S_CURVE) {
    o->curve = val;
    return 0;
  }
  char *end = NULL;
  errno = 0;
  const double v = strtod(val, &end);
  if (end == val || *end || errno == ERANGE || !isfinite(v))
    return bad(k, "not a finite number:", val);
  if (k == S_CELLS) {
    if (v != floor(v) || v < 16 || v > 250000)
      return bad(k, "out of range:", val);
    o->o.cells = (int)v;
    return 0;
  }
  double *dst[] = {[S_A0] = &o->p.a0, [S_L] = &o->p.L, [S_H] = &o->p.H, [S_E] = &o->p.E, [S_NU] = &o->p.nu,
                   [S_SNF] = &o->p.snf, [S_STF] = &o->p.stf, [S_U0] = &o->p.U0, [S_S0] = &o->p.s0, [S_Q] = &o->p.q,
                   [S_TIP] = &o->o.tip_end};
  *dst[k] = v; /* ranges: ana_spec_init and the solver check them, with their message */
  return 0;
}

/* argv into o: -1 go on, 0 help printed, 2 bad.  --specimen is read first, so that its
 * defaults come before the other options whatever their order. */
static int parse(int argc, char **argv, sp_opts *o)
{
  *o = (sp_opts){.o = {.beam = ANA_CZM_TIMOSHENKO, .cells = 192, .tip_end = NAN}};
  ana_spec_default(ANA_SPEC_DCB, &o->p);
  for (int pass = 0; pass < 2; pass++)
    for (int i = 1; i < argc; i++) {
      const char *a = argv[i];
      if (strncmp(a, "--", 2) || !a[2]) {
        fprintf(stderr, PROG ": unexpected argument '%s' (allowed: the options of --help)\n", a);
        return 2;
      }
      const char *name = a + 2, *eq = strchr(name, '=');
      const size_t nl = eq ? (size_t)(eq - name) : strlen(name);
      int k = -1;
      for (int j = 0; j < S_COUNT; j++)
        if (strlen(sopt[j].name) == nl && !strncmp(sopt[j].name, name, nl))
          k = j;
      if (k < 0) {
        fprintf(stderr, PROG ": unknown option '%.*s' (allowed: the options of --help)\n", (int)(nl + 2), a);
        return 2;
      }
      if (k == S_HELP) {
        if (pass == 1)
          continue;
        help();
        return 0;
      }
      const char *val = eq ? eq + 1 : (i + 1 < argc && strncmp(argv[i + 1], "--", 2) ? argv[++i] : NULL);
      if (!val || !*val)
        return bad(k, "missing value", NULL);
      if ((k == S_SPEC) == (pass == 0) && set(o, k, val))
        return 2;
    }
  if (isnan(o->o.tip_end))
    o->o.tip_end = 0.5 * (o->p.a0 + o->p.L);
  return -1;
}

static const char *const theory_name[ANA_BEAM_COUNT] = {"simple", "corrected", "shear", "Kanninen",
                                                        "Kanninen+shear"};

static void print_lefm(const ana_spec *s)
{
  const int dcb = s->p.kind == ANA_SPEC_DCB, nth = dcb ? ANA_BEAM_COUNT : ANA_BEAM_KANNINEN;
  const double a0 = s->p.a0, as[3] = {a0, 1.5 * a0, 2.0 * a0};
  printf("  C(a0)      ");
  for (int th = 0; th < nth; th++) {
    double C;
    if (ana_spec_compliance(s, th, a0, &C, NULL) == ANA_OK)
      printf("%s%s %.6g", th ? ", " : "", theory_name[th], C);
  }
  printf("\n             (corrected: a + chi t, chi %.4g%s)\n", dcb ? s->chi : s->chi_II,
         dcb ? ", Williams" : " = 0.42 chi, ISO 15114");
  printf("  LEFM       P (delta) on the branch G = Gc at a = %g, %g, %g:\n", as[0], as[1], as[2]);
  for (int th = 0; th < nth; th++) {
    printf("    %-15s", theory_name[th]);
    for (int i = 0; i < 3; i++) {
      double P, d;
      if (as[i] < s->p.L && ana_spec_lefm_branch(s, th, as[i], &P, &d) == ANA_OK)
        printf("  %.6g (%.6g)", P, d);
      else
        printf("  -");
    }
    printf("\n");
  }
  if (!dcb)
    for (int th = 0; th < nth; th++) {
      double at;
      if (ana_els_snapback_end(s, th, &at) == ANA_OK)
        printf("  snap-back  %-15s growth unstable under displacement control for a < %.6g (%.4g L)\n",
               theory_name[th], at, at / s->p.L);
    }
}

/* The cohesive curve on the finest mesh, written to path.tmp and renamed. */
static int write_curve(const ana_spec *s, const sp_opts *o)
{
  ana_czm_opts fine = o->o;
  fine.cells = 4 * o->o.cells;
  ana_czm_path c;
  char err[200];
  if (ana_dcb_czm_solve(s, &fine, &c, err, sizeof err) != ANA_OK) {
    fprintf(stderr, PROG ": --curve: %s\n", err);
    return 1;
  }
  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp", o->curve);
  FILE *f = fopen(tmp, "w");
  int rc = 1;
  if (f) {
    fprintf(f, "delta,P,crack_tip\n");
    for (int i = 0; i < c.n; i++)
      fprintf(f, "%.17g,%.17g,%.17g\n", c.pt[i].delta, c.pt[i].P, c.pt[i].tip);
    rc = (ferror(f) | fclose(f)) ? 1 : rename(tmp, o->curve) ? 1 : 0;
  }
  if (rc) {
    fprintf(stderr, PROG ": --curve: cannot write '%s': %s\n", o->curve, strerror(errno));
    remove(tmp);
  } else
    printf("  curve      %d points (%s arm, %d cells) written to %s\n", c.n,
           fine.beam == ANA_CZM_EULER ? "Euler" : "Timoshenko", fine.cells, o->curve);
  ana_czm_path_free(&c);
  return rc;
}

int ver_cmd_analytic_specimen(int argc, char **argv)
{
  sp_opts o;
  const int pa = parse(argc, argv, &o);
  if (pa >= 0)
    return pa;
  ana_spec s;
  char err[200];
  if (ana_spec_init(&o.p, &s, err, sizeof err) != ANA_OK) {
    fprintf(stderr, PROG ": %s\n", err);
    return 2;
  }
  const ana_spec_params *p = &s.p;
  const int dcb = p->kind == ANA_SPEC_DCB;
  printf("%s specimen (mode %s), plane stress, unit width\n", dcb ? "DCB" : "ELS", dcb ? "I" : "II");
  printf("  inputs     L %g, H %g (arms t %g), a0 %g, E %g, nu %g, snf %g, stf %g, U0 %g, s0 %g, q %g\n", p->L, p->H,
         s.t, p->a0, p->E, p->nu, p->snf, p->stf, p->U0, p->s0, p->q);
  printf("  law        Gc = q U0 / (q + 1) = %.6g; separation at opening U0 / snf = %.6g, sliding U0 / stf = %.6g\n",
         s.Gc, s.wc_I, s.wc_II);
  printf("             zone length scale (E Gc / s^2)^(1/4) t^(3/4) = %.4g (s = %s)\n", s.lcz, dcb ? "snf" : "stf");
  print_lefm(&s);
  if (!dcb) {
    printf("  cohesive   not provided for the ELS (mode II): the LEFM branches above are its references\n");
    return 0;
  }
  for (int beam = 0; beam < 2; beam++) {
    ana_czm_opts bo = o.o;
    bo.beam = beam;
    ana_czm_conv cv;
    const int rc = ana_dcb_czm_converge(&s, &bo, &cv, err, sizeof err);
    if (rc != ANA_OK) {
      fprintf(stderr, PROG ": cohesive reference: %s\n", err);
      return rc == ANA_EINVAL ? 2 : 1;
    }
    printf("  cohesive   %s arm: peak P = %.9g at delta = %.9g (Richardson, order %.3f)\n",
           beam ? "Timoshenko" : "Euler", cv.P_ext, cv.delta_ext, cv.order);
    printf("             meshes %d, %d, %d cells: P %.9g, %.9g, %.9g; finest within %.1e (P), %.1e (delta);\n"
           "             the extrapolation's own spread %.1e, %.1e\n",
           bo.cells, 2 * bo.cells, 4 * bo.cells, cv.P[0], cv.P[1], cv.P[2], cv.P_err, cv.delta_err, cv.P_ext_err,
           cv.delta_ext_err);
  }
  return o.curve ? write_curve(&s, &o) : 0;
}
