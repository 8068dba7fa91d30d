/*
 * cmd_plot.c - `delam plot DIR [--out FILE.png]`: one figure of one run folder, drawn by
 * gnuplot (docs/guide.md, "Looking at a run"):
 *   - the load curve (load.csv's P_grip against delta) with its reference: the scene's
 *     closed-form bar (analytic/, as `delam analytic --curve`), or on the split beams the
 *     2-D LEFM branch that `delam check` holds them to (data/fe, check_spec.c);
 *   - the crack front against delta where load.csv has crack_tip, with the branch's a;
 *   - energy.csv's ledger: W_ext, KE, SE, W_coh, D, the booked losses, and the balance;
 *   - in the title, delam check's verdict: check.json's where the folder has one, else
 *     the check run now into a temporary file (the folder keeps only the PNG).
 * Any folder delam check reads: DIR/scene.ini gives the scene, else --scene; without
 * either the curves are drawn without a reference.  The script goes to gnuplot whole,
 * its data inline, so that --script prints a file that redraws the figure anywhere.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "ana.h"
#include "check_folder.h"
#include "check_spec.h"
#include "cmd.h"
#include "foreign.h"
#include "io.h"
#include "summary.h"

#define PROG "delam plot"
#define NREF 2001 /* points of the reference curve */

static void usage(FILE *f)
{
  fprintf(f,
    "usage: delam plot DIR [--out FILE.png] [--scene SCENE] [--script]\n"
    "Draws one run folder with gnuplot into one PNG (default DIR/plot.png):\n"
    "  - the load curve, P_grip against delta (load.csv), with its reference where there\n"
    "    is one: the scene's closed-form bar (as delam analytic --curve), or on the split\n"
    "    beams (specimen.type = dcb or els) the 2-D LEFM branch of data/fe that delam\n"
    "    check holds them to; a static run's rows with det_sign -1 (a state a held grip\n"
    "    cannot keep) marked;\n"
    "  - the crack front against delta where load.csv has crack_tip, with the branch's a;\n"
    "  - the energy ledger of energy.csv: W_ext, KE, SE, W_coh, D, the booked losses (the\n"
    "    L_* columns and W_head) and the balance KE + SE + W_coh + booked - E0 (E0 the\n"
    "    first row's KE + SE + W_coh less its W_ext: the start's energy),\n"
    "    which lies on W_ext;\n"
    "  - in the title the folder, the scene, and delam check's verdict: DIR/check.json's\n"
    "    when it is there, else the check made now (into a temporary file: the folder is\n"
    "    not changed but for the PNG).\n"
    "Units are the scene's: any consistent set, dimensionless in the paper's scenes;\n"
    "forces and energies per unit depth (docs/output-formats.md).  Where the load stays\n"
    "under 1 %% of its peak for the last part of the run, delta is drawn to 1.5 times the\n"
    "last delta above it, and the panel says so.\n\n"
    "DIR is any folder delam check reads: load.csv (header with delta and P_grip) is\n"
    "required, energy.csv optional; the scene is DIR/scene.ini (delam's runs) or --scene.\n\n"
    "options:\n"
    "  --out FILE.png   where the figure goes (default DIR/plot.png)\n"
    "  --scene SCENE    the scene of another code's folder (a file or a name: fig6), for\n"
    "                   the reference and the check\n"
    "  --script         print the gnuplot script (data inline) instead of drawing\n"
    "  --help           this text\n\n"
    "exit status: 0 the figure is written, 1 gnuplot failed or is missing (Debian:\n"
    "gnuplot-nox) or the PNG could not be written, 2 bad usage or a folder that cannot\n"
    "be drawn (no load.csv, a bad CSV, a run writing it now)\n");
}

typedef struct {
  const char *dir, *out, *scene;
  int script;
} plot_opts;

/* What the figure is drawn from. */
typedef struct {
  ver_table ld, en;     /* load.csv: delta, P_grip, crack_tip, t; energy.csv as delam check reads it */
  int have_en;
  int spec;             /* 1 DCB, 2 ELS (the reference is the LEFM branch, with a), 0 the bar    */
  int nref;             /* reference points (0: none, ref_why says why)                          */
  double rd[NREF], rP[NREF], ra[NREF];
  char ref_label[160], ref_why[400];
  char scene[200];      /* "fig6 h 8 ppc 1 explicit", or why there is no scene                    */
  char verdict[600];    /* delam check's verdict and where it comes from                          */
  char state[600];      /* summary.json: incomplete and why ("" if complete or absent)            */
  double xmax;          /* the delta drawn to (NAN: all)                                          */
  char xnote[200];
} plot_run;

enum { L_D, L_P, L_TIP, L_T, L_DET };
enum { E_W, E_KE, E_SE, E_WCOH, E_D, E_BOOK0, E_NBOOK = 7, E_T = E_BOOK0 + E_NBOOK }; /* booked: L_bc .. L_damp */

static int plot_args(int argc, char **argv, plot_opts *o)
{
  memset(o, 0, sizeof *o);
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 1;
    } else if (!strcmp(a, "--out") || !strcmp(a, "--scene")) {
      if (!v || !v[0]) {
        fprintf(stderr, PROG ": %s needs a value (see delam plot --help)\n", a);
        return 2;
      }
      *(!strcmp(a, "--out") ? &o->out : &o->scene) = v;
      i++;
    } else if (!strcmp(a, "--script"))
      o->script = 1;
    else if (a[0] == '-' && a[1]) {
      fprintf(stderr, PROG ": unknown option '%s' (see delam plot --help)\n", a);
      return 2;
    } else if (!o->dir)
      o->dir = a;
    else {
      fprintf(stderr, PROG ": one folder only ('%s' is extra)\n", a);
      return 2;
    }
  }
  if (!o->dir) {
    fprintf(stderr, PROG ": needs a run folder (usage: delam plot DIR [--out FILE.png])\n");
    return 2;
  }
  return 0;
}

/* check.json's verdict into out ("pass", "fail: peak_P, branch"); 0, or -1 if it is not
 * there or does not read. */
static int verdict_json(const char *path, char *out, size_t len)
{
  char *txt = ver_io_slurp(path, NULL, 1 << 20);
  cJSON *j = txt ? cJSON_Parse(txt) : NULL;
  free(txt);
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "verdict");
  if (!cJSON_IsString(v)) {
    cJSON_Delete(j);
    return -1;
  }
  size_t k = (size_t)snprintf(out, len, "%s", v->valuestring);
  const cJSON *c, *cs = cJSON_GetObjectItemCaseSensitive(j, "checks");
  int nf = 0;
  cJSON_ArrayForEach(c, cs) {
    const cJSON *cv = cJSON_GetObjectItemCaseSensitive(c, "verdict"), *cn = cJSON_GetObjectItemCaseSensitive(c, "name");
    if (k < len && cJSON_IsString(cv) && cJSON_IsString(cn) && !strcmp(cv->valuestring, "fail"))
      k += (size_t)snprintf(out + k, len - k, "%s%s", nf++ ? ", " : " (failed: ", cn->valuestring);
  }
  if (nf && k < len)
    snprintf(out + k, len - k, ")");
  cJSON_Delete(j);
  return 0;
}

/* The check made now: `delam check DIR [--scene S] --out TMP` in a child process (its
 * output to a temporary file), the verdict from TMP, or why it judged nothing. */
static void verdict_now(const plot_opts *o, char *out, size_t len)
{
  const char *td = getenv("TMPDIR") && getenv("TMPDIR")[0] ? getenv("TMPDIR") : "/tmp";
  char js[600], lg[600];
  snprintf(js, sizeof js, "%.500s/delam-plot-check.XXXXXX", td);
  snprintf(lg, sizeof lg, "%.500s/delam-plot-log.XXXXXX", td);
  const int fj = mkstemp(js), fl = fj >= 0 ? mkstemp(lg) : -1;
  if (fj < 0 || fl < 0) {
    snprintf(out, len, "not judged (no temporary file in %s: %s)", td, strerror(errno));
    if (fj >= 0)
      close(fj), remove(js);
    return;
  }
  close(fj);
  fflush(NULL);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fl, 1);
    dup2(fl, 2);
    char a0[] = "check", a2[] = "--out", a4[] = "--scene";
    char *av[] = {a0, (char *)o->dir, a2, js, o->scene ? a4 : NULL, (char *)o->scene, NULL};
    _exit(ver_cmd_check(o->scene ? 6 : 4, av));
  }
  int st = 0;
  while (pid > 0 && waitpid(pid, &st, 0) < 0 && errno == EINTR) {
  }
  close(fl);
  const int rc = pid > 0 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  if (rc == 2) { /* the reason: check's last "delam check: " line */
    char *log = ver_io_slurp(lg, NULL, 1 << 20), *why = NULL;
    for (char *p = log ? strstr(log, "delam check: ") : NULL; p; p = strstr(p + 1, "delam check: "))
      why = p + 13;
    if (why)
      why[strcspn(why, "\n")] = '\0';
    snprintf(out, len, "not judged: %.300s", why ? why : "delam check exited 2");
    free(log);
  } else if (rc < 0 || verdict_json(js, out, len))
    snprintf(out, len, "not judged (delam check did not finish: status %d)", rc);
  remove(js);
  remove(lg);
}

/* The reference of the scene vs into p: the closed-form bar to dmax, or the split beam's
 * LEFM branch; p->nref 0 with ref_why when there is none. */
static void reference(const ver_scene *vs, double dmax, plot_run *p)
{
  char err[400] = "";
  if (vs->sc.specimen != MPM_SPEC_BAR) {
    p->spec = vs->sc.specimen == MPM_SPEC_DCB ? 1 : 2;
    int n = ver_spec_branch(&vs->sc, p->ra, p->rd + 1, p->rP + 1, NREF - 1, err, sizeof err);
    while (n > 0 && p->ra[n - 1] > vs->sc.L - 1.5 * vs->sc.H) /* the check's window ends at L - 3 t */
      n--;
    if (n > 0) { /* from the origin along C(a0), then the branch */
      p->nref = n + 1;
      p->rd[0] = p->rP[0] = 0.0;
      memmove(p->ra + 1, p->ra, (size_t)n * sizeof *p->ra);
      p->ra[0] = vs->sc.a0;
      snprintf(p->ref_label, sizeof p->ref_label, "2-D LEFM (data/fe): C(a0), then P = sqrt(2 Gc / C'(a)) to a = L - 3 t");
    }
  } else {
    ana_bar bar;
    if (ver_scene_bar(&vs->sc, &bar, err, sizeof err) == 0) {
      p->nref = ana_bar_curve(&bar, dmax, NREF, p->rd, p->rP);
      snprintf(p->ref_label, sizeof p->ref_label, "closed form (delam analytic --curve), Pmax %.4g", bar.Pmax);
      if (p->nref <= 0)
        snprintf(err, sizeof err, "no closed-form curve to delta %g", dmax);
    }
  }
  if (p->nref <= 0) {
    p->nref = 0;
    snprintf(p->ref_why, sizeof p->ref_why, "no reference: %s", err);
  }
}

/* The scene (DIR/scene.ini, else --scene) and its reference, and summary.json's word on
 * the run; a folder without a scene is drawn without a reference. */
static void scene_and_state(const plot_opts *o, plot_run *p)
{
  static ver_scene vs; /* large */
  char err[4800];
  struct stat st;
  char own[1400];
  snprintf(own, sizeof own, "%s/scene.ini", o->dir);
  const ver_check_opts so = {o->scene, o->dir, NULL, NULL, 0, 0.0, 0.0};
  double dmax = 0.0;
  for (long i = 0; i < p->ld.n; i++)
    dmax = fmax(dmax, p->ld.col[L_D][i]);
  ver_summary_doc d;
  const int have_sum = ver_summary_read(o->dir, &d) == 0;
  if (have_sum && !d.u.complete)
    snprintf(p->state, sizeof p->state, "the run did not finish (summary.json says complete: false)%s%.400s",
             d.error[0] ? ": " : "", d.error);
  if (!o->scene && lstat(own, &st) != 0)
    snprintf(p->ref_why, sizeof p->ref_why, "no reference: no scene.ini (give --scene SCENE)");
  else if (ver_check_scene(&so, have_sum ? d.scene : "", &vs, err, sizeof err))
    snprintf(p->ref_why, sizeof p->ref_why, "no reference: %.380s", err);
  else {
    snprintf(p->scene, sizeof p->scene, "%.120s, %s, %s solver", have_sum && d.case_id[0] ? d.case_id : vs.name,
             vs.sc.specimen == MPM_SPEC_DCB ? "DCB" : vs.sc.specimen == MPM_SPEC_ELS ? "ELS" : "bar",
             vs.sc.solver == MPM_SOLVER_STATIC ? "static" : "explicit");
    reference(&vs, dmax, p);
  }
}

/* Where the load has died out for good (below 1 % of its peak from some row on, over a
 * third of the run), delta is drawn to 1.5 times the largest delta of the rows up to the
 * last one above it (a snapback's peak lies beyond its foot). */
static void crop(plot_run *p)
{
  const double *d = p->ld.col[L_D], *P = p->ld.col[L_P];
  double pk = 0.0, dmax = d[0], dlive = 0.0;
  long last = 0;
  for (long i = 0; i < p->ld.n; i++) {
    pk = fmax(pk, fabs(P[i]));
    dmax = fmax(dmax, d[i]);
  }
  for (long i = 0; i < p->ld.n; i++)
    if (fabs(P[i]) > 0.01 * pk)
      last = i;
  for (long i = 0; i <= last; i++)
    dlive = fmax(dlive, d[i]);
  p->xmax = NAN;
  if (pk > 0.0 && dlive > 0.0 && 1.5 * dlive < 0.67 * dmax) {
    p->xmax = 1.5 * dlive;
    snprintf(p->xnote, sizeof p->xnote, " - delta to %.4g of the run's %.4g: the load stays under 1 %% of its peak "
             "after delta %.4g", p->xmax, dmax, dlive);
  }
}

/* s as a gnuplot string in double quotes: \ and " escaped, newlines kept, other
 * control bytes shown as '?'. */
static void gp_str(FILE *f, const char *s)
{
  fputc('"', f);
  for (; *s; s++) {
    const unsigned char c = (unsigned char)*s;
    if (c == '"' || c == '\\')
      fprintf(f, "\\%c", c);
    else if (c == '\n')
      fputs("\\n", f);
    else
      fputc(c < 0x20 || c == 0x7f ? '?' : c, f);
  }
  fputc('"', f);
}

/* Breaks s's lines at spaces so that none is much over width characters (a title wider
 * than the figure is cut off at its edges). */
static void wrap(char *s, int width)
{
  char *line = s, *space = NULL;
  for (char *c = s; *c; c++) {
    if (*c == '\n') {
      line = c + 1;
      space = NULL;
    } else if (*c == ' ')
      space = c;
    if (c - line >= width && space) {
      *space = '\n';
      line = space + 1;
      space = NULL;
    }
  }
}

/* The inline data: $load (delta, P_grip[, crack_tip][, det_sign]), $ref (delta, P[, a]) and $en (x,
 * W_ext, KE, SE, W_coh, D, booked, balance) with x delta where energy.csv has load.csv's
 * rows, else t, else the row number; returns which (0, 1, 2). */
static int gp_data(FILE *f, const plot_run *p)
{
  const ver_table *ld = &p->ld, *en = &p->en;
  fputs("$load << EOD\n", f);
  for (long i = 0; i < ld->n; i++) {
    fprintf(f, "%.9g %.9g", ld->col[L_D][i], ld->col[L_P][i]);
    if (ld->col[L_TIP])
      fprintf(f, " %.9g", ld->col[L_TIP][i]);
    if (ld->col[L_DET])
      fprintf(f, " %.9g", ld->col[L_DET][i]);
    fputc('\n', f);
  }
  fputs("EOD\n$ref << EOD\n", f);
  for (int i = 0; i < p->nref; i++)
    fprintf(f, p->spec ? "%.9g %.9g %.9g\n" : "%.9g %.9g\n", p->rd[i], p->rP[i], p->ra[i]);
  fputs("EOD\n", f);
  if (!p->have_en)
    return 0;
  const int xk = en->n == ld->n ? 0 : en->col[E_T] ? 1 : 2;
  fputs("$en << EOD\n", f);
  /* the start's energy: the first row's less the work done to it (a static run's first
   * row is its first increment's state, not the start) */
  const double E0 = en->col[E_KE][0] + en->col[E_SE][0] + en->col[E_WCOH][0] - en->col[E_W][0];
  for (long i = 0; i < en->n; i++) {
    double book = 0.0;
    for (int k = E_BOOK0; k < E_BOOK0 + E_NBOOK; k++)
      book += en->col[k] ? en->col[k][i] : 0.0;
    const double x = xk == 0 ? ld->col[L_D][i] : xk == 1 ? en->col[E_T][i] : (double)(i + 1);
    fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", x, en->col[E_W][i], en->col[E_KE][i], en->col[E_SE][i],
            en->col[E_WCOH][i], en->col[E_D][i], book,
            en->col[E_KE][i] + en->col[E_SE][i] + en->col[E_WCOH][i] + book - E0);
  }
  fputs("EOD\n", f);
  return xk;
}

/* The figure's script: terminal and output, the data, the multiplot of 2 or 3 panels. */
static void gp_script(FILE *f, const plot_opts *o, const plot_run *p, const char *png)
{
  const int tip = p->ld.col[L_TIP] != NULL, np = 1 + tip + p->have_en;
  fprintf(f, "# delam plot %s: gnuplot script, data inline\nset terminal pngcairo size 1000,%d noenhanced "
          "font 'Helvetica,11' background rgb 'white'\nset output ", o->dir, 120 + 400 * np);
  gp_str(f, png);
  fputc('\n', f);
  const int xk = gp_data(f, p);
  char title[2400], xr[80] = "set xrange [*:*]";
  snprintf(title, sizeof title, "delam plot %s%s%s\ndelam check: %s%s%s\nunits: the scene's (dimensionless in "
           "the paper's scenes); forces and energies per unit depth", o->dir, p->scene[0] ? " - " : "", p->scene,
           p->verdict, p->state[0] ? "\n" : "", p->state);
  wrap(title, 120);
  if (isfinite(p->xmax))
    snprintf(xr, sizeof xr, "set xrange [*:%.9g]", p->xmax);
  fprintf(f, "set grid lc rgb '#dddddd'\nset key top right Left reverse box opaque\nset lmargin at screen 0.08\n"
          "set rmargin at screen 0.97\nset multiplot layout %d,1 title ", np);
  gp_str(f, title);
  fprintf(f, "\n%s\nset xlabel ", xr);
  gp_str(f, p->spec == 1 ? "delta: the arms' opening" : p->spec ? "delta: the end deflection" : "delta: end displacement of the grip");
  fputs("\nset ylabel 'P_grip'\nset title ", f);
  char t1[700];
  snprintf(t1, sizeof t1, "load against delta%s%s%s", p->xnote, p->nref ? "" : "\n", p->ref_why);
  wrap(t1, 120);
  gp_str(f, t1);
  /* headroom for the key above the curves */
  fputs("\nset offsets 0, 0, graph 0.3, 0\nplot $load using 1:2 with lines lw 2 lc rgb '#1f4e9a' title 'this run (load.csv)'", f);
  if (p->ld.col[L_DET]) /* the static solver's stability (docs/static.md, "Stability") */
    fprintf(f, ", $load using 1:($%d < 0 ? $2 : 1/0) with points pt 7 ps 0.6 lc rgb '#e67e22' title "
            "'det K < 0 (det_sign): a state a held grip cannot keep'", 3 + tip);
  if (p->nref) {
    fputs(", $ref using 1:2 with lines dt 2 lw 2 lc rgb '#c0392b' title ", f);
    gp_str(f, p->ref_label);
  }
  if (tip) {
    fputs("\nset offsets 0, 0, 0, 0\nset key top left\nset title 'crack front against delta'\nset ylabel 'crack_tip: x of the front'\n"
          "plot $load using 1:3 with linespoints pt 7 ps 0.4 lw 2 lc rgb '#1f4e9a' title 'this run (load.csv)'", f);
    if (p->nref && p->spec)
      fputs(", $ref using 1:3 with lines dt 2 lw 2 lc rgb '#c0392b' title 'LEFM branch: a (a sharp crack; crack_tip is the last separated node)'", f);
  }
  if (p->have_en) {
    fprintf(f, "\n%s\nset xlabel '%s'\nset offsets 0, 0, graph 0.05, 0\nset key top left\nset title 'energy ledger (energy.csv)'\nset ylabel 'energy'\n",
            xk ? "set xrange [*:*]" : xr, xk == 0 ? "delta" : xk == 1 ? "t (energy.csv has other rows than "
            "load.csv)" : "energy.csv row");
    fputs("plot $en using 1:2 with lines lw 3 lc rgb '#222222' title 'W_ext', "
          "'' using 1:8 with lines dt 2 lw 2 lc rgb '#e0a000' title 'KE+SE+W_coh+booked-E0 (on W_ext)', "
          "'' using 1:3 with lines lw 1.5 lc rgb '#2ca02c' title 'KE', "
          "'' using 1:4 with lines lw 1.5 lc rgb '#1f77b4' title 'SE', "
          "'' using 1:5 with lines lw 1.5 lc rgb '#9467bd' title 'W_coh', "
          "'' using 1:6 with lines lw 2 lc rgb '#c0392b' title 'D', "
          "'' using 1:7 with lines lw 1.5 lc rgb '#7f7f7f' title 'booked (L_* + W_head)'", f);
  }
  fputs("\nunset multiplot\n", f);
}

/* The folder's tables into p; 0, or 2 with the reason on stderr. */
static int read_run(const char *dir, plot_run *p)
{
  static const char *const lnames[] = {"delta", "P_grip", "crack_tip", "t", "det_sign"};
  static const char *const enames[] = {"W_ext",  "KE",        "SE",       "W_coh",  "D", "L_bc", "L_flip",
                                       "L_scheme", "W_head", "L_contact", "L_debris", "L_damp", "t"};
  char path[1400], err[1600] = "";
  struct stat st;
  if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
    fprintf(stderr, PROG ": %s: %s\n", dir, errno == ENOENT ? "no such folder" : "not a folder");
    return 2;
  }
  const long pid = ver_io_lock_holder(dir);
  if (pid > 0) {
    fprintf(stderr, PROG ": %s: a delam process (pid %ld) is writing this folder now; plot it when it is done\n",
            dir, pid);
    return 2;
  }
  snprintf(path, sizeof path, "%s/load.csv", dir);
  int r = ver_table_read(path, lnames, 5, 2, &p->ld, err, sizeof err);
  if (r == 1)
    snprintf(err, sizeof err, "%s: no such file (delam plot draws a run folder; its load.csv, with delta and P_grip, "
             "is required)", path);
  if (r == 0) {
    snprintf(path, sizeof path, "%s/energy.csv", dir);
    r = ver_table_read(path, enames, 13, 5, &p->en, err, sizeof err);
    p->have_en = r == 0;
    r = r == 1 ? 0 : r;
  }
  if (r) {
    fprintf(stderr, PROG ": %s\n", err);
    ver_table_free(&p->ld);
    ver_table_free(&p->en);
    return 2;
  }
  return 0;
}

/* 1 if the PNG at path ends in its IEND chunk (gnuplot may exit 0 leaving a cut file). */
static int png_whole(const char *path)
{
  FILE *f = fopen(path, "rb");
  unsigned char tail[12] = {0};
  const int ok = f && fseek(f, -12, SEEK_END) == 0 && fread(tail, 1, 12, f) == 12 && !memcmp(tail + 4, "IEND", 4);
  if (f)
    fclose(f);
  return ok;
}

/* gnuplot on the script at gp; its exit status (127: not found), -1 if it did not run. */
static int run_gnuplot(const char *gp)
{
  fflush(NULL);
  const pid_t pid = fork();
  if (pid == 0) {
    execlp("gnuplot", "gnuplot", gp, (char *)NULL);
    _exit(127);
  }
  int st = 0;
  while (pid > 0 && waitpid(pid, &st, 0) < 0 && errno == EINTR) {
  }
  return pid > 0 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* The script into a temporary file, gnuplot on it into png.<pid>.tmp, renamed to png
 * when whole.  0, or 1 with the reason on stderr. */
static int draw(const plot_opts *o, const plot_run *p, const char *png)
{
  const char *td = getenv("TMPDIR") && getenv("TMPDIR")[0] ? getenv("TMPDIR") : "/tmp";
  char gp[600], tmp[1500];
  snprintf(gp, sizeof gp, "%.500s/delam-plot.XXXXXX", td);
  snprintf(tmp, sizeof tmp, "%s.%ld.tmp", png, (long)getpid());
  const int fd = mkstemp(gp);
  FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
  if (!f) {
    fprintf(stderr, PROG ": cannot write the script in %s: %s\n", td, strerror(errno));
    return 1;
  }
  gp_script(f, o, p, tmp);
  const int werr = ferror(f) | fclose(f);
  const int rc = werr ? -1 : run_gnuplot(gp);
  remove(gp);
  if (rc != 0 || !png_whole(tmp) || rename(tmp, png) != 0) {
    const int e = errno;
    if (werr)
      fprintf(stderr, PROG ": cannot write the script %s\n", gp);
    else if (rc == 127)
      fprintf(stderr, PROG ": gnuplot not found (Debian: apt-get install gnuplot-nox)\n");
    else if (rc != 0)
      fprintf(stderr, PROG ": gnuplot failed (exit status %d)\n", rc);
    else
      fprintf(stderr, PROG ": %s: cannot write: %s\n", png, png_whole(tmp) ? strerror(e) : "the PNG is not whole");
    remove(tmp);
    return 1;
  }
  return 0;
}

int ver_cmd_plot(int argc, char **argv)
{
  plot_opts o;
  const int pa = plot_args(argc, argv, &o);
  if (pa)
    return pa == 1 ? 0 : 2;
  static plot_run p; /* large */
  memset(&p, 0, sizeof p);
  if (read_run(o.dir, &p))
    return 2;
  scene_and_state(&o, &p);
  crop(&p);
  char js[1400], png[1400];
  snprintf(js, sizeof js, "%s/check.json", o.dir);
  if (verdict_json(js, p.verdict, sizeof p.verdict) == 0) {
    const size_t k = strlen(p.verdict);
    snprintf(p.verdict + k, sizeof p.verdict - k, " (check.json)");
  } else
    verdict_now(&o, p.verdict, sizeof p.verdict);
  snprintf(png, sizeof png, "%s", o.out ? o.out : "");
  if (!o.out)
    snprintf(png, sizeof png, "%s/plot.png", o.dir);
  int rc = 0;
  if (o.script)
    gp_script(stdout, &o, &p, png);
  else if (!(rc = draw(&o, &p, png)))
    printf("plot: %s -> %s (delam check: %s)\n", o.dir, png, p.verdict);
  ver_table_free(&p.ld);
  ver_table_free(&p.en);
  return rc;
}
