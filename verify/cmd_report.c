/*
 * cmd_report.c - `delam report [--from DIR] [--out DIR]`: the paper's figures and the
 * report around them, the checks' verdicts and the paper's numbers beside the measured
 * ones.  The steps are in report_*.c (report.h); this file reads the options and runs
 * them in order.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "cmd.h"
#include "datadir.h"
#include "io.h"
#include "pool.h"
#include "report.h"

#define PROG "delam report"

static void usage(FILE *f)
{
  fprintf(f, "usage: " PROG " [--from DIR] [--out DIR] [options]\n"
             "Runs the checks (delam verify --quick, unless --from gives a verify folder), the\n"
             "cases the paper's figures need (or reuses them), plots them with gnuplot\n"
             "(reports/*.gp; PNG and SVG) and writes OUT/index.html and OUT/REPORT.md: the\n"
             "verdict of every checked case, the paper's numbers beside the measured ones,\n"
             "the figures with their text (reports/text/). OUT holds copies of the data\n"
             "it shows; no link points out of it.\n\n"
             "options:\n"
             "  --from DIR     a `delam verify` output folder (DIR/verify.json, DIR/<case-id>/)\n"
             "                 to judge and to take runs from; default: run the quick checks\n"
             "                 into CACHE/verify\n"
             "  --out DIR      where the report goes (default reports/out)\n"
             "  --cache DIR    where runs are kept and reused (default out/report)\n"
             "  --scenes DIR   scene files (default: $DELAM_SCENES, ./data/scenes, or the\n"
             "                 installed or source tree's scenes)\n"
             "  --gp DIR       gnuplot scripts and text/ templates (default: $DELAM_REPORTS,\n"
             "                 ./reports, or the installed or source tree's)\n"
             "  --jobs N       runs at once (default 2)\n"
             "  --rerun        ignore cached runs\n"
             "  --help         this text\n"
             "exit status: 0 report written and no check failed, 1 a check failed or some\n"
             "figure or run is missing, 2 bad usage\n");
}

/* Reads the options into R; 0, 1 (--help given) or 2 (bad usage). */
static int parse_args(int argc, char **argv, report *R)
{
  rep_ctx *r = &R->r;
  snprintf(r->out, sizeof r->out, "reports/out");
  snprintf(r->cache, sizeof r->cache, "out/report");
  const char *scenes = ver_scene_dir();
  snprintf(r->scenes, sizeof r->scenes, "%s", scenes ? scenes : "data/scenes");
  const char *gp = ver_report_dir();
  snprintf(r->gpdir, sizeof r->gpdir, "%s", gp ? gp : "reports");
  r->jobs = 2;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    char *dst = NULL;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 1;
    } else if (!strcmp(a, "--rerun")) {
      r->rerun = 1;
      continue;
    } else if (!strcmp(a, "--from"))
      dst = r->from;
    else if (!strcmp(a, "--out"))
      dst = r->out;
    else if (!strcmp(a, "--cache"))
      dst = r->cache;
    else if (!strcmp(a, "--scenes"))
      dst = r->scenes;
    else if (!strcmp(a, "--gp"))
      dst = r->gpdir;
    else if (!strcmp(a, "--jobs")) {
      char *end;
      const long j = v ? strtol(v, &end, 10) : 0;
      if (!v || *end || j < 1 || j > 64) {
        fprintf(stderr, PROG ": --jobs: '%s' is not an integer in [1, 64]\n", v ? v : "");
        return 2;
      }
      r->jobs = (int)j;
      i++;
      continue;
    } else {
      fprintf(stderr, PROG ": unknown argument '%s' (see " PROG " --help)\n", a);
      return 2;
    }
    if (!v || !*v) {
      fprintf(stderr, PROG ": %s needs a folder\n", a);
      return 2;
    }
    snprintf(dst, REP_PATH, "%s", v);
    i++;
  }
  return 0;
}

/* Where the program is, and that the folders exist or can be made; 0 or 2. */
static int check_paths(report *R)
{
  rep_ctx *r = &R->r;
  if (r->from[0]) {
    struct stat st;
    if (stat(r->from, &st) != 0 || !S_ISDIR(st.st_mode)) {
      fprintf(stderr, PROG ": --from: '%s' is not a folder\n", r->from);
      return 2;
    }
  }
  const ssize_t k = readlink("/proc/self/exe", r->exe, sizeof r->exe - 1);
  if (k <= 0) {
    fprintf(stderr, PROG ": cannot find the delam program (/proc/self/exe)\n");
    return 2;
  }
  r->exe[k] = '\0';
  char probe[REP_PATH + 32];
  snprintf(probe, sizeof probe, "%s/fig6.ini", r->scenes);
  if (access(probe, R_OK) != 0) {
    fprintf(stderr, PROG ": no scene files in '%s' (run from the repository, or give --scenes)\n", r->scenes);
    return 2;
  }
  if (ver_mkdir_p(r->out) != 0 || ver_mkdir_p(r->cache) != 0) {
    fprintf(stderr, PROG ": cannot create %s or %s\n", r->out, r->cache);
    return 2;
  }
  return 0;
}

/* OUT/REPORT.md and OUT/index.html from the document, each through a temporary name. */
static int write_report(report *R)
{
  static const char *const names[2] = {"REPORT.md", "index.html"};
  int bad = 0;
  for (int i = 0; i < 2; i++) {
    char path[REP_PATH + 32], tmp[REP_PATH + 64];
    snprintf(path, sizeof path, "%s/%s", R->r.out, names[i]);
    FILE *f = ver_io_open_tmp(path, tmp, sizeof tmp);
    if (!f) {
      fprintf(stderr, PROG ": %s: cannot write: %s\n", path, strerror(errno));
      bad = 1;
      continue;
    }
    if (i == 0)
      rep_doc_markdown(&R->doc, f);
    else
      rep_doc_html(&R->doc, f, "delam: verification report");
    if (ver_io_commit(f, tmp) != 0) {
      fprintf(stderr, PROG ": %s: cannot write: %s\n", path, strerror(errno));
      bad = 1;
    }
  }
  return bad;
}

/* After SIGINT or SIGTERM: the children have been stopped and waited for (pool.c); the
 * runs that finished stay where they are, for the next report to reuse; no REPORT.md or
 * index.html is written from a part of the data.  Exit status 130. */
static int stopped(report *R)
{
  fprintf(stderr, PROG ": stopped by a signal after %.1f s: its runs and gnuplot stopped and waited for; the "
          "finished runs are kept in %s for the next report; REPORT.md and index.html not written\n",
          ver_now_wall() - R->t0, R->r.cache);
  rep_doc_free(&R->doc);
  rep_vars_free(&R->vars);
  cJSON_Delete(R->verify);
  return 130;
}

int ver_cmd_report(int argc, char **argv)
{
  static report R;
  memset(&R, 0, sizeof R);
  R.verify_rc = -1;
  rep_ctx *r = &R.r;
  r->io_bad = &R.data_bad;
  const int pa = parse_args(argc, argv, &R);
  if (pa)
    return pa == 1 ? 0 : 2;
  if (check_paths(&R))
    return 2;
  char lerr[REP_PATH + 200];
  /* one report per folder; the lock holds until the process ends */
  if (ver_io_lock_dir(r->out, lerr, sizeof lerr) < 0) {
    const int held = errno == EAGAIN;
    fprintf(stderr, PROG ": %s\n", lerr);
    return held ? 2 : 1;
  }
  R.t0 = ver_now_wall();
  ver_pool_catch(); /* a signal stops the children (pool.c) and the stages below */
  if (!r->from[0] && ver_report_run_verify(&R) != 0 && !ver_pool_caught())
    fprintf(stderr, PROG ": delam verify --quick could not run; the report has no verdicts\n");
  if (r->from[0]) {
    R.verify = ver_report_read_verify(r->from);
    if (!R.verify_dir[0])
      snprintf(R.verify_dir, sizeof R.verify_dir, "%s", r->from);
  }
  ver_report_build_cases(&R);
  ver_report_static_cases(&R);
  const int missing = ver_pool_caught() ? 0 : ver_report_run_cases(r);
  if (ver_pool_caught())
    return stopped(&R);
  R.t_runs = ver_now_wall() - R.t0;
  for (int i = 0; i < r->n; i++)
    ver_report_measure(r, &r->c[i]);
  ver_report_plan_figs(&R);
  ver_report_write_data(&R);
  if (R.data_bad)
    ver_report_no_figures(&R);
  else
    ver_report_gnuplot(&R);
  if (ver_pool_caught())
    return stopped(&R);
  ver_report_set_vars(&R);
  ver_report_compose(&R);
  int bad = missing;
  for (int i = 0; i < R.nfig; i++)
    bad += R.fig[i].status != 0;
  if (R.vars.missing)
    fprintf(stderr, PROG ": %d placeholders of reports/text/ were not set (shown as {name?})\n", R.vars.missing);
  const int rc = write_report(&R);
  const cJSON *s = R.verify ? cJSON_GetObjectItemCaseSensitive(R.verify, "summary") : NULL;
  const cJSON *nf = s ? cJSON_GetObjectItemCaseSensitive(s, "checks_fail") : NULL;
  const int failed = cJSON_IsNumber(nf) && nf->valuedouble > 0;
  rep_doc_free(&R.doc);
  rep_vars_free(&R.vars);
  cJSON_Delete(R.verify);
  if (rc)
    fprintf(stderr, PROG ": %s: the report is not complete: REPORT.md or index.html could not be written (see above)"
            "%s\n", r->out, bad ? ", and parts are missing" : "");
  else
    fprintf(stderr, PROG ": %s/index.html and %s/REPORT.md written in %.1f s%s%s\n", r->out, r->out,
            ver_now_wall() - R.t0, failed ? "; a check FAILED" : "", bad ? " (with missing parts, see above)" : "");
  if (ver_pool_caught()) /* a signal during the last stage: the report is written, as said */
    return 130;
  return rc || bad || failed ? 1 : 0;
}
