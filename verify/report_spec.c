/*
 * report_spec.c - the split beams in `delam report` (report.h; docs/specimens.md): the
 * double cantilever beam (dcb.ini) and the end-loaded split (the same file with
 * specimen.type = els, snf 10, stf 1) at h 8, 4 and 2, 4 ppc, on their file's static
 * solver (REP_SPEC, tag 0 the DCB, 1 the ELS).  The figure "specimens" draws them over the
 * references `delam check` holds them to (verify/check_spec.c): data/fe's 2-D
 * finite-element compliance C(a), as the elastic line P = delta / C(a0) and the LEFM
 * branch P = sqrt(2 G_c / C'(a)), delta = C P; corrected beam theory's branch; and the
 * DCB's cohesive beam, a Timoshenko arm on the law and the ligament's foundation (the
 * curve of `delam analytic --specimen dcb --curve`, traced further); its bottom row their
 * errors against h (spec-conv.csv).  The text's numbers are ver_spec_judge's: the checks
 * of `delam check` on the same folders.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ana_spec.h"
#include "check_spec.h"
#include "io.h"
#include "report.h"
#include "scene.h"

#define SPEC_SCENE "dcb"
#define SPEC_PPC 4
#define SPEC_NH 3
static const double spec_h[SPEC_NH] = {8.0, 4.0, 2.0}; /* the P-delta panels draw 4 and 2 */
/* the ELS's law: docs/specimens-reference.md's defaults (mode II, shear the weaker) */
static const char *const els_sets[3] = {"specimen.type=els", "decohesion.snf=10", "decohesion.stf=1"};
static const char *const spec_name[2] = {"dcb", "els"};

/* The scene of specimen s (0 DCB, 1 ELS) as the report runs it, but for its grid; 0 if it
 * loads. */
static int spec_scene(const rep_ctx *r, int s, ver_scene *vs)
{
  char path[REP_PATH + 64], err[256];
  snprintf(path, sizeof path, "%.900s/%s.ini", r->scenes, SPEC_SCENE);
  if (ver_scene_parse(path, vs, err, sizeof err) != 0)
    return -1;
  for (int j = 0; s == 1 && j < 3; j++)
    if (ver_scene_set(vs, els_sets[j], err, sizeof err) != 0)
      return -1;
  return ver_scene_validate(vs, err, sizeof err) == 0 && vs->sc.specimen != MPM_SPEC_BAR ? 0 : -1;
}

void ver_report_spec_cases(rep_ctx *r)
{
  static ver_scene vs; /* large */
  if (spec_scene(r, 0, &vs) != 0) /* a scene folder without the split beams */
    return;
  for (int k = 0; k < SPEC_NH; k++) {
    const int i[2] = {ver_report_add(r, SPEC_SCENE, spec_h[k], SPEC_PPC, 0, 0, NULL, NULL, REP_SPEC, 0),
                      ver_report_add_sets(r, SPEC_SCENE, spec_h[k], SPEC_PPC, 0, 0, els_sets, 3, REP_SPEC, 1)};
    /* the cost as particles x increments (a few hundred; 0.2 to 1.5 s each), not the
     * explicit steps ver_report_add counts: they start among the short runs */
    for (int j = 0; j < 2; j++)
      if (i[j] >= 0)
        r->c[i[j]].cost = 500.0 * vs.sc.L * vs.sc.H / (spec_h[k] * spec_h[k]) * SPEC_PPC;
  }
}

/* The run of specimen s at h, with a result, or NULL. */
static const rep_case *spec_case(const rep_ctx *r, int s, double h)
{
  for (int i = 0; i < r->n; i++) {
    const rep_case *c = &r->c[i];
    if ((c->role & REP_SPEC) && c->tag == s && c->h == h && c->have)
      return c;
  }
  return NULL;
}

/* The references of specimen s: its scene, data/fe's table (have_fe) and the beam
 * theories (have_sp). */
typedef struct {
  ver_scene vs;
  ver_fe_table fe;
  int have_fe, have_sp;
  char why[600];
  ana_spec sp;
  double Gc, t;  /* G_c = q U0 / (q + 1); the arms' thickness                          */
  double a_end;   /* the curves' last a: L - 2 t (nearer the end the DCB's branch turns
                     back, the ligament too short), or the table's end if that comes first */
  double a_turn;  /* where the 2-D LEFM branch's delta is least (a0 where it only grows)  */
} spec_ref;

/* The 2-D LEFM branch at a from data/fe: P = sqrt(2 G_c / C'(a)), delta = C(a) P. */
static double fe_branch(const spec_ref *f, double a, double *delta)
{
  const double P = sqrt(2.0 * f->Gc / ver_spec_fe_at(&f->fe, f->fe.dC, a));
  *delta = ver_spec_fe_at(&f->fe, f->fe.C, a) * P;
  return P;
}

static int spec_ref_init(const rep_ctx *r, int s, spec_ref *f)
{
  memset(f, 0, sizeof *f);
  if (spec_scene(r, s, &f->vs) != 0)
    return -1;
  const mpm_scene *sc = &f->vs.sc;
  f->have_fe = ver_spec_fe_read(sc, &f->fe, f->why, sizeof f->why) == 0;
  ana_spec_params p;
  ver_spec_params(sc, &p);
  f->have_sp = ana_spec_init(&p, &f->sp, NULL, 0) == ANA_OK;
  f->Gc = sc->q * sc->U0 / (sc->q + 1.0);
  f->t = 0.5 * sc->H;
  f->a_end = sc->L - 2.0 * f->t;
  if (f->have_fe)
    f->a_end = fmin(f->a_end, f->fe.a[f->fe.n - 1]);
  f->a_turn = sc->a0;
  double dmin = INFINITY;
  for (double a = sc->a0; f->have_fe && a <= f->a_end; a += 0.25) {
    double d;
    fe_branch(f, a, &d);
    if (d < dmin) {
      dmin = d;
      f->a_turn = a;
    }
  }
  return 0;
}

/* The 2-D LEFM branch's crack length at opening delta, on its stretch where delta grows
 * with a (a_turn to a_end), by bisection; NAN off it. */
static double fe_crack_at(const spec_ref *f, double delta)
{
  double lo = f->a_turn, hi = f->a_end, dlo, dhi;
  fe_branch(f, lo, &dlo);
  fe_branch(f, hi, &dhi);
  if (!f->have_fe || !(delta >= dlo && delta <= dhi))
    return NAN;
  for (int it = 0; it < 60; it++) {
    double d;
    const double m = 0.5 * (lo + hi);
    fe_branch(f, m, &d);
    if (d < delta)
      lo = m;
    else
      hi = m;
  }
  return 0.5 * (lo + hi);
}

/* spec-<s>-fe.csv (a, delta, P: the 2-D LEFM branch from a0 on), spec-<s>-elastic.csv
 * (delta, P: the line P = delta / C(a0) up to the branch) and spec-<s>-beam.csv (a,
 * delta, P: corrected beam theory's branch); the header alone where a reference is
 * missing (gnuplot then draws nothing). */
static void write_refs(const rep_ctx *r, int s, const spec_ref *f, FILE *vars)
{
  char name[3][48];
  FILE *o[3];
  static const char *const what[3] = {"fe", "elastic", "beam"}, *const head[3] = {"a,delta,P", "delta,P", "a,delta,P"};
  for (int k = 0; k < 3; k++) {
    snprintf(name[k], sizeof name[k], "spec-%s-%s.csv", spec_name[s], what[k]);
    if ((o[k] = ver_report_open_data(r, name[k])))
      fprintf(o[k], "%s\n", head[k]);
  }
  const double a0 = f->vs.sc.a0, C0 = f->have_fe ? ver_spec_fe_at(&f->fe, f->fe.C, a0) : NAN;
  for (double a = a0; f->have_fe && o[0] && a <= f->a_end + 1e-9; a += 0.5) {
    double d;
    const double P = fe_branch(f, a, &d);
    fprintf(o[0], "%.10g,%.10g,%.10g\n", a, d, P);
  }
  double d0 = NAN;
  const double P0 = f->have_fe ? fe_branch(f, a0, &d0) : NAN;
  if (f->have_fe && o[1])
    fprintf(o[1], "0,0\n%.10g,%.10g\n", d0, P0);
  for (double a = a0; f->have_sp && o[2] && a <= f->a_end + 1e-9; a += 0.5) {
    double P, d;
    if (ana_spec_lefm_branch(&f->sp, ANA_BEAM_CORRECTED, a, &P, &d) == ANA_OK)
      fprintf(o[2], "%.10g,%.10g,%.10g\n", a, d, P);
  }
  for (int k = 0; k < 3; k++)
    if (o[k])
      ver_report_close_data(r, o[k], name[k]);
  fprintf(vars, "spec_%s_C0 = %.10g\nspec_%s_have_fe = %d\nspec_%s_a0 = %g\n", spec_name[s], f->have_fe ? C0 : 0.0,
          spec_name[s], f->have_fe, spec_name[s], a0);
}

/* spec-dcb-czm.csv (delta, P, crack_tip): the cohesive beam with a Timoshenko arm on
 * 768 cells (as ver_spec_judge's peak), traced until its tip passes L - 2.5 t, past
 * where dcb.ini's runs end (its delta 14: the front near L - 3 t); nearer the end the
 * short ligament stops the path. */
static void write_czm(const rep_ctx *r, const spec_ref *f, FILE *vars)
{
  const mpm_scene *sc = &f->vs.sc;
  const ana_czm_opts o = {.beam = ANA_CZM_TIMOSHENKO, .cells = 768, .tip_end = sc->L - 2.5 * f->t};
  ana_czm_path cz = {0};
  const int ok = f->have_sp && ana_dcb_czm_solve(&f->sp, &o, &cz, NULL, 0) == ANA_OK;
  FILE *o1 = ver_report_open_data(r, "spec-dcb-czm.csv");
  if (o1) {
    fprintf(o1, "delta,P,crack_tip\n");
    for (int i = 0; ok && i < cz.n; i++)
      fprintf(o1, "%.10g,%.10g,%.10g\n", cz.pt[i].delta, cz.pt[i].P, cz.pt[i].tip);
    ver_report_close_data(r, o1, "spec-dcb-czm.csv");
  }
  fprintf(vars, "spec_dcb_have_czm = %d\n", ok);
  if (ok)
    ana_czm_path_free(&cz);
}

/* `delam check DIR` on case c: its checks into chk (n of them), from the run's own
 * scene.ini as check_folder.c reads it; 0, or -1 with why in err. */
static int judge_case(const rep_case *c, ver_check *chk, int *n, char *err, size_t errlen)
{
  static ver_scene vs; /* large */
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/scene.ini", c->dir);
  *n = 0;
  if (ver_scene_parse(p, &vs, err, errlen) != 0)
    return -1;
  vs.allow_unstable = 1;
  return ver_scene_validate(&vs, err, errlen) == 0 && ver_spec_judge(c->dir, &vs, chk, VER_NCHECK, n, err, errlen) == 0
             ? 0
             : -1;
}

/* spec-conv.csv (spec, h, compliance, peak, branch): each run's |error| against the 2-D
 * FE compliance, the cohesive beam's peak (the DCB) and the 2-D LEFM branch (RMS), as
 * `delam check` measures them; empty fields where a check was skipped or the run is
 * missing. */
static void write_conv(const rep_ctx *r)
{
  FILE *o = ver_report_open_data(r, "spec-conv.csv");
  if (!o)
    return;
  fprintf(o, "spec,h,compliance,peak,branch\n");
  static const char *const want[3] = {"compliance", "peak_P", "branch"};
  for (int s = 0; s < 2; s++)
    for (int k = 0; k < SPEC_NH; k++) {
      const rep_case *c = spec_case(r, s, spec_h[k]);
      ver_check chk[VER_NCHECK];
      char err[600];
      int n = 0;
      if (!c || judge_case(c, chk, &n, err, sizeof err) != 0)
        continue;
      fprintf(o, "%d,%g", s, spec_h[k]);
      for (int w = 0; w < 3; w++) {
        double e = NAN;
        for (int j = 0; j < n; j++)
          if (!strcmp(chk[j].name, want[w]))
            e = fabs(chk[j].error);
        fprintf(o, isnan(e) ? "," : ",%.6g", e);
      }
      fprintf(o, "\n");
    }
  ver_report_close_data(r, o, "spec-conv.csv");
}

/* The runs' ids (spec_<s>_h<h>) and their keys' notes: " (stopped at delta = X)" for a
 * run that ended early, else "". */
static void write_ids(const rep_ctx *r, FILE *vars)
{
  for (int s = 0; s < 2; s++)
    for (int k = 0; k < SPEC_NH; k++) {
      const rep_case *c = spec_case(r, s, spec_h[k]);
      fprintf(vars, "spec_%s_h%g = \"%s\"\nspec_%s_h%g_note = \"", spec_name[s], spec_h[k], c ? c->id : "",
              spec_name[s], spec_h[k]);
      if (c && !c->complete)
        fprintf(vars, " (stopped at {/Symbol d} = %.3g)", c->delta_end);
      fprintf(vars, "\"\n");
    }
  fprintf(vars, "spec_ppc = %d\n", SPEC_PPC);
}

void ver_report_spec_write(const rep_ctx *r, FILE *vars)
{
  static spec_ref f; /* large */
  int any = 0;
  for (int i = 0; i < r->n; i++)
    any |= (r->c[i].role & REP_SPEC) != 0;
  fprintf(vars, "have_spec = %d\n", any);
  if (!any)
    return;
  for (int s = 0; s < 2; s++) {
    if (spec_ref_init(r, s, &f) != 0)
      continue;
    write_refs(r, s, &f, vars);
    if (s == 0)
      write_czm(r, &f, vars);
  }
  write_conv(r);
  write_ids(r, vars);
}

/* ---- the text: delam check's numbers ---- */

/* One check's error as words: a signed percentage, the RMS as a plain one, or "n/a"
 * with the reason where it was skipped. */
static void check_words(const ver_check *k, char *buf, size_t len)
{
  if (isnan(k->error))
    snprintf(buf, len, "n/a (%.150s)", k->note);
  else if (!strcmp(k->name, "branch"))
    snprintf(buf, len, "%.2f %%", 100.0 * k->error);
  else if (!strcmp(k->name, "ledger") || !strcmp(k->name, "gap") || !strcmp(k->name, "crack_tip"))
    snprintf(buf, len, "%.2g", k->measured);
  else if (!strcmp(k->name, "delta_fall"))
    snprintf(buf, len, "%.2f %%", 100.0 * k->measured);
  else /* no "-0.00 %" for an error at rounding */
    snprintf(buf, len, "%+.2f %%", fabs(k->error) < 5e-5 ? 0.0 : 100.0 * k->error);
}

/* From case c's load.csv: where delta falls back after the peak, from the row of its
 * largest value to the least after it (the check delta_fall's), the crack tip then
 * ("from x = X to Y while delta fell from D1 to D2", or "none"); and how far the
 * separated tip trails the 2-D LEFM branch's crack length at the same delta where the
 * front first reaches the middle of the branch check's window (a0 + 2 t to L - 3 t),
 * NAN where that is off the branch. */
static double tip_stats(const rep_case *c, const spec_ref *f, char *snap, size_t len)
{
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/load.csv", c->dir);
  static const char *const cols[3] = {"delta", "P_grip", "crack_tip"};
  double *v[3];
  const long n = ver_csv_read(p, cols, 3, v);
  const double *d = v[0], *P = v[1], *tip = v[2];
  const double mid = 0.5 * (f->vs.sc.a0 + 2.0 * f->t + f->vs.sc.L - 3.0 * f->t);
  long ipk = 0, im = -1, i0 = -1, i1 = -1, imid = -1;
  for (long i = 1; i < n; i++)
    ipk = P[i] > P[ipk] ? i : ipk;
  double fall = 0.0;
  for (long i = ipk; i < n; i++) {
    im = im < 0 || d[i] > d[im] ? i : im;
    if (d[im] - d[i] > fall) {
      fall = d[im] - d[i];
      i0 = im;
      i1 = i;
    }
  }
  for (long i = 0; i < n && imid < 0; i++)
    imid = tip[i] >= mid ? i : -1;
  if (i1 > 0)
    snprintf(snap, len, "from x = %g to %g while delta fell from %.4g to %.4g", tip[i0], tip[i1], d[i0], d[i1]);
  else
    snprintf(snap, len, "none");
  const double lag = imid >= 0 ? fe_crack_at(f, d[imid]) - tip[imid] : NAN;
  for (int k = 0; k < 3; k++)
    free(v[k]);
  return lag;
}

/* The checks of `delam check DIR` on case c, under spec:<key>:<check> (and _tol), with
 * the verdict; 0, or -1 (the verdict says why) where the folder could not be judged. */
static int check_vars(report *R, const char *key, const rep_case *c)
{
  char k[96], buf[400], err[600] = "";
  ver_check chk[VER_NCHECK];
  int n = 0;
  const int ok = judge_case(c, chk, &n, err, sizeof err) == 0;
  int fail = 0;
  char failed[200] = "";
  for (int i = 0; ok && i < n; i++) {
    snprintf(k, sizeof k, "spec:%s:%s", key, chk[i].name);
    check_words(&chk[i], buf, sizeof buf);
    rep_vars_set(&R->vars, k, "%s", buf);
    snprintf(k, sizeof k, "spec:%s:%s_tol", key, chk[i].name);
    rep_vars_set(&R->vars, k, "%.3g %%", 100.0 * chk[i].tol);
    if (chk[i].verdict == VER_FAIL) {
      const size_t l = strlen(failed);
      snprintf(failed + l, sizeof failed - l, "%s%s", fail++ ? ", " : "", chk[i].name);
    }
  }
  snprintf(k, sizeof k, "spec:%s:verdict", key);
  if (!ok)
    rep_vars_set(&R->vars, k, "not judged (%.300s)", err);
  else if (fail)
    rep_vars_set(&R->vars, k, "FAIL (%s; %d checks)", failed, n);
  else
    rep_vars_set(&R->vars, k, "pass (%d checks)", n);
  return ok ? 0 : -1;
}

/* Case c under spec:<key>:*: its checks, its peak (and against the 2-D LEFM branch's
 * start), the crack tip in the snapback and its lag behind the LEFM crack length. */
static void run_vars(report *R, const char *key, const rep_case *c, const spec_ref *f)
{
  char k[96], buf[400];
  check_vars(R, key, c);
  snprintf(k, sizeof k, "spec:%s:id", key);
  rep_vars_set(&R->vars, k, "%s", c->id);
  snprintf(k, sizeof k, "spec:%s:peak", key);
  rep_vars_set(&R->vars, k, "%.4g at delta = %.3g", c->peak_P, c->delta_peak);
  double d0;
  const double P0 = f->have_fe ? fe_branch(f, f->vs.sc.a0, &d0) : NAN;
  snprintf(k, sizeof k, "spec:%s:peak_vs_lefm", key);
  rep_vars_set(&R->vars, k, "%+.1f %%", 100.0 * (c->peak_P / P0 - 1.0));
  snprintf(k, sizeof k, "spec:%s:cpu_s", key);
  rep_vars_num(&R->vars, k, c->cpu_s);
  const double lag = tip_stats(c, f, buf, sizeof buf);
  snprintf(k, sizeof k, "spec:%s:snap", key);
  rep_vars_set(&R->vars, k, "%s", buf);
  snprintf(k, sizeof k, "spec:%s:lag", key);
  rep_vars_num(&R->vars, k, lag);
  snprintf(k, sizeof k, "spec:%s:ended", key);
  rep_vars_set(&R->vars, k, c->complete ? "complete at delta = %.3g" : "STOPPED at delta = %.3g", c->delta_end);
}

/* The references' numbers of specimen s under spec:<s>:*: from data/fe C(a0), the LEFM
 * branch's start and where its delta is least (the ELS: growth from a0 snaps back up to
 * there); corrected beam theory's turn and its branch's largest departure from the 2-D
 * one; the zone's length scale and the curves' end. */
static void ref_vars(report *R, int s, const spec_ref *f)
{
  char k[64];
  const int ok = f->have_fe;
  const double a0 = f->vs.sc.a0;
  double d0 = NAN, dt = NAN; /* delta at a0 and at the branch's turn */
  const double P0 = ok ? fe_branch(f, a0, &d0) : NAN;
  if (ok)
    fe_branch(f, f->a_turn, &dt);
  const char *const sn = spec_name[s];
  const struct {
    const char *name;
    double v;
  } num[6] = {{"C0", ok ? ver_spec_fe_at(&f->fe, f->fe.C, a0) : NAN},
              {"P0", P0},
              {"d0", d0},
              {"a_turn", ok ? f->a_turn : NAN},
              {"d_turn", dt},
              {"lcz", f->have_sp ? f->sp.lcz : NAN}};
  for (int i = 0; i < 6; i++) {
    snprintf(k, sizeof k, "spec:%s:%s", sn, num[i].name);
    rep_vars_num(&R->vars, k, num[i].v);
  }
  double at = NAN, dev = 0.0;
  if (s == 1 && f->have_sp && ana_els_snapback_end(&f->sp, ANA_BEAM_CORRECTED, &at) != ANA_OK)
    at = NAN;
  snprintf(k, sizeof k, "spec:%s:a_turn_beam", sn);
  rep_vars_num(&R->vars, k, at);
  for (double a = a0; ok && f->have_sp && a <= f->a_end; a += 0.5) {
    double P, d;
    if (ana_spec_lefm_branch(&f->sp, ANA_BEAM_CORRECTED, a, &P, &d) == ANA_OK)
      dev = fmax(dev, fabs(P / fe_branch(f, a, &d) - 1.0));
  }
  snprintf(k, sizeof k, "spec:%s:beam_dev", sn);
  rep_vars_set(&R->vars, k, ok && f->have_sp ? "%.1f %%" : "n/a", 100.0 * dev);
  snprintf(k, sizeof k, "spec:%s:a_end", sn);
  rep_vars_num(&R->vars, k, f->a_end);
  snprintf(k, sizeof k, "spec:%s:lefm_fall", sn);
  rep_vars_set(&R->vars, k, "%.1f %%", 100.0 * (1.0 - dt / d0));
}

void ver_report_spec_vars(report *R)
{
  static spec_ref f; /* large */
  for (int s = 0; s < 2; s++) {
    if (spec_ref_init(&R->r, s, &f) != 0)
      continue;
    ref_vars(R, s, &f);
    for (int k = 0; k < SPEC_NH; k++) {
      char key[32], v[64];
      snprintf(key, sizeof key, "%s_h%g", spec_name[s], spec_h[k]);
      const rep_case *c = spec_case(&R->r, s, spec_h[k]);
      if (c) {
        run_vars(R, key, c, &f);
        continue;
      }
      static const char *const names[] = {"compliance", "peak_P", "branch", "D_growth", "delta_fall", "verdict",
                                          "peak", "peak_vs_lefm", "snap", "lag"};
      for (size_t j = 0; j < sizeof names / sizeof names[0]; j++) {
        snprintf(v, sizeof v, "spec:%s:%s", key, names[j]);
        rep_vars_set(&R->vars, v, "n/a (the run is missing)");
      }
    }
  }
}

void ver_report_spec_table(report *R)
{
  static const char *const head[9] = {"case",       "h",         "compliance vs 2-D FE", "peak P",
                                      "peak vs cohesive beam", "branch RMS vs 2-D LEFM", "D growth vs U0",
                                      "delam check", "CPU s"};
  rep_table *t = rep_doc_table(&R->doc, 9, head);
  for (int s = 0; s < 2; s++)
    for (int k = 0; k < SPEC_NH; k++) {
      const rep_case *c = spec_case(&R->r, s, spec_h[k]);
      if (!c) {
        rep_table_row(t, REP_ROW_FAIL, "%s h = %g (no run)\t%g\t\t\t\t\t\t\t", spec_name[s], spec_h[k], spec_h[k]);
        continue;
      }
      char key[32], f[7][96];
      static const char *const field[7] = {"compliance", "peak_P", "branch", "D_growth", "verdict", "cpu_s", "peak"};
      snprintf(key, sizeof key, "%s_h%g", spec_name[s], spec_h[k]);
      for (int j = 0; j < 7; j++) {
        char v[96];
        snprintf(v, sizeof v, "spec:%s:%s", key, field[j]);
        const char *w = rep_vars_get(&R->vars, v);
        snprintf(f[j], sizeof f[j], "%.95s", w ? w : s == 1 && j == 1 ? "no reference (mode II)" : "n/a");
      }
      const int bad = !c->complete || strncmp(f[4], "pass", 4);
      rep_table_row(t, bad ? REP_ROW_FAIL : REP_ROW_PASS, "%s\t%g\t%s\t%s\t%s\t%s\t%s\t%s\t%s", c->id, c->h, f[0], f[6],
                    f[1], f[2], f[3], f[4], f[5]);
    }
}
