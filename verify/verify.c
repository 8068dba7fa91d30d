/*
 * verify.c - the driver of `delam verify` (verify.h): the case list (sweep_cases.c),
 * the runs in child processes through the process pool (pool.c; a crashing case cannot
 * take the sweep with it), reading back and checking each case (sweep_cases.c,
 * policy.c), the cross-case checks, and verify.json / verify.csv / the closing table
 * (sweep_out.c).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io.h"
#include "pool.h"
#include "run.h"
#include "sweep.h"
#include "check_spec.h"
#include "verify.h"

typedef struct {
  const ver_verify_opts *o;
  ver_case *cs;
  int n;
  int threads;   /* OpenMP threads a child */
  char *started; /* per case: 1 once its child was started */
} run_ctx;

/* In the child: one run, its error text (if any) to DIR/<id>/error.txt. */
static void child_run(const ver_verify_opts *o, const ver_case *c, int threads)
{
  char dir[800], path[900], err[1024] = "";
  ver_case_dir(o, c, dir, sizeof dir);
  snprintf(path, sizeof path, "%s/error.txt", dir);
  remove(path);
  /* a signal to this child (from the parent's pool or the terminal) stops the run as
   * delam run stops: the rows so far, summary.json with complete: false, status 130 */
  ver_run_opts ro = {dir, 0, 1, ver_pool_stop_flag(), 0, threads};
  ver_summary u;
  const int rc = ver_run(&c->vs, &ro, &u, err, sizeof err);
  if (rc) {
    FILE *f = fopen(path, "w");
    if (f) {
      fprintf(f, "%s\n", err);
      fclose(f);
    }
  }
  fflush(NULL);
  _exit(rc & 0xff);
}

static pid_t start_case(int i, void *ctx)
{
  run_ctx *r = ctx;
  fflush(NULL);
  r->started[i] = 1;
  const pid_t parent = getpid(), pid = fork();
  if (pid == 0) {
    ver_pool_child(parent);
    child_run(r->o, &r->cs[i], r->threads);
  }
  if (pid < 0)
    snprintf(r->cs[i].error, sizeof r->cs[i].error, "fork failed: %s", strerror(errno));
  return pid;
}

static void show_running(const int *running, int nrunning, int done, void *ctx)
{
  const run_ctx *r = ctx;
  fprintf(stderr, "verify: [%d/%d done] running:", done, r->n);
  for (int j = 0; j < nrunning; j++)
    fprintf(stderr, " %s", r->cs[running[j]].id);
  fprintf(stderr, "\n");
}

static void case_done(int i, int status, int sig, double wall, int done, void *ctx)
{
  run_ctx *r = ctx;
  ver_case *c = &r->cs[i];
  c->wall_s = wall;
  c->exit_code = status < 0 ? 1 : status;
  c->term_sig = sig;
  fprintf(stderr, "verify: [%d/%d done] %s finished in %.1f s (exit %d%s)\n", done, r->n, c->id, c->wall_s,
          c->exit_code, c->term_sig ? ", killed by a signal" : "");
}

/* Runs every case, at most o->jobs at a time, costliest first; started[i] says which
 * were started.  0, 2 (out of memory) or 130 (stopped by a signal: the running cases
 * stopped and waited for, no other started). */
static int run_cases(const ver_verify_opts *o, ver_case *cs, int n, char *started)
{
  int *order = malloc(sizeof(int) * (size_t)(n + 1));
  if (!order)
    return 2;
  int m = 0;
  for (int i = 0; i < n; i++)
    if (!cs[i].refused[0]) /* refused: never run, judged as such */
      order[m++] = i;
  n = m;
  /* insertion sort by cost, descending (n is small) */
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && cs[order[j]].cost > cs[order[j - 1]].cost; j--) {
      const int t = order[j];
      order[j] = order[j - 1];
      order[j - 1] = t;
    }
  const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
  /* as many jobs as cores: one thread each; fewer: the kernel chooses (mpm_threads.c) */
  run_ctx ctx = {o, cs, n, o->jobs >= (ncpu > 0 ? ncpu : 1) ? 1 : 0, started};
  const ver_pool p = {n, o->jobs, order, start_case, show_running, case_done, &ctx};
  const int rc = ver_pool_run(&p);
  free(order);
  return rc < 0 ? 2 : rc > 0 ? 130 : 0;
}

/* One `delam run` line per case. */
static void list_cases(const ver_verify_opts *o, const ver_case *cs, int n)
{
  for (int i = 0; i < n; i++) {
    const ver_case *c = &cs[i];
    if (c->refused[0]) { /* a shell comment: a runner skips it, the merge judges it */
      printf("# %s: %s\n", c->id, c->refused);
      continue;
    }
    printf("%s run %s --h %g --ppc %d", o->self, c->path, c->h, c->ppc);
    for (int s = 0; s < c->nset; s++)
      printf(" --set %s", c->sets[s]);
    /* one thread per case: a dispatcher runs many at once, and OpenMP teams that
     * outnumber the cores spin against each other (9 cases at once, 2 threads each,
     * on 2 cores: minutes instead of seconds) */
    printf(" --threads 1 --quiet --out %s/%s\n", o->outdir, c->id);
  }
}

/* Reads and checks every case and the groups across them; 1 if a check failed. */
static int check_all(const ver_verify_opts *o, ver_case *cs, int n, ver_cross *x, int *nx)
{
  int rc = 0;
  for (int i = 0; i < n; i++) {
    if (cs[i].vs.sc.specimen != MPM_SPEC_BAR || cs[i].vs.sc.grips == MPM_GRIPS_HELD) { /* its own references */
      char dir[800];
      ver_case_dir(o, &cs[i], dir, sizeof dir);
      ver_spec_case(dir, &cs[i]);
    } else
      ver_policy_case(&cs[i]);
    for (int j = 0; j < cs[i].nchk; j++)
      ver_sweep_print_check(cs[i].id, &cs[i].chk[j]);
    rc |= cs[i].verdict == VER_FAIL;
  }
  *nx = ver_policy_cross(cs, n, x);
  *nx += ver_spec_cross(cs, n, x + *nx, VER_MAXCROSS - *nx);
  *nx += ver_mms_cross(x + *nx, VER_MAXCROSS - *nx);
  ver_policy_cross_room(x, nx);
  for (int i = 0; i < *nx; i++) {
    char id[160];
    snprintf(id, sizeof id, "%s/%s%g", x[i].scene, strcmp(x[i].over, "h") ? "h" : "ppc", x[i].fixed);
    ver_sweep_print_check(id, &x[i].chk);
    rc |= x[i].chk.verdict == VER_FAIL;
  }
  return rc;
}

/* Reads back every case; after a stop, the cases never started are not read (their
 * folders may hold an earlier sweep's results) but marked as not run. */
static void read_cases(const ver_verify_opts *o, ver_case *cs, int n, const char *started, int stopped)
{
  for (int i = 0; i < n; i++)
    if (!stopped || started[i])
      ver_case_read(o, &cs[i]);
    else {
      cs[i].have_summary = cs[i].complete = 0;
      snprintf(cs[i].error, sizeof cs[i].error, "not run: verify was stopped by a signal before this case");
    }
}

int ver_verify(const ver_verify_opts *o)
{
  ver_case *cs;
  int n;
  int mk = ver_sweep_cases(o, &cs, &n);
  if (!mk && o->merge_found)
    mk = ver_sweep_found(o, &cs, &n);
  if (mk)
    return mk;
  if (o->list) {
    list_cases(o, cs, n);
    free(cs);
    return 0;
  }
  char err[1400];
  const int e = ver_mkdir_p(o->outdir) != 0 ? errno : 0;
  if (e) {
    fprintf(stderr, "delam verify: %s: cannot create the folder: %s\n", o->outdir, strerror(e));
    free(cs);
    return e == ENOTDIR || e == ELOOP || e == ENAMETOOLONG ? 2 : 1;
  }
  const int lock = ver_io_lock_dir(o->outdir, err, sizeof err); /* one sweep per folder */
  const int held = lock < 0 && errno == EAGAIN;
  char *started = calloc((size_t)n + 1, 1);
  if (lock < 0 || !started) {
    fprintf(stderr, "delam verify: %s\n", lock < 0 ? err : "out of memory");
    free(cs);
    free(started);
    if (lock >= 0)
      close(lock);
    return held ? 2 : 1;
  }
  ver_pool_catch();
  const double w0 = ver_now_wall();
  int stopped = 0;
  if (!o->merge) {
    fprintf(stderr, "verify: %d cases, %d at a time, into %s/\n", n, o->jobs, o->outdir);
    const int rr = run_cases(o, cs, n, started);
    stopped = rr == 130;
    if (rr == 2) {
      free(cs);
      free(started);
      close(lock);
      return 2;
    }
  }
  read_cases(o, cs, n, started, stopped);
  static ver_cross x[VER_MAXCROSS];
  int nx;
  int rc = check_all(o, cs, n, x, &nx);
  ver_sweep_print_table(cs, n, x, nx);
  const double wall = ver_now_wall() - w0;
  stopped = stopped || ver_pool_caught();
  const char *bad = ver_sweep_write_json(o, cs, n, x, nx, wall, stopped ? 130 : rc) ? "verify.json"
                    : ver_sweep_write_csv(o, cs, n)                                    ? "verify.csv"
                    : ver_sweep_write_cross_csv(o, x, nx)                              ? "verify_cross.csv"
                                                                                       : NULL;
  if (bad) {
    fprintf(stderr, "delam verify: %s/%s: cannot write: %s\n", o->outdir, bad, strerror(errno));
    rc = 1;
  }
  int nrun = 0;
  for (int i = 0; i < n; i++)
    nrun += started[i];
  if (stopped)
    printf("\nverify: stopped by a signal after %.1f s: %d of %d cases started, each stopped or finished; "
           "%s/verify.json and verify.csv judge what there is (the rest: not run)\n", wall, nrun, n, o->outdir);
  else
    printf("\nverify: %d cases in %.1f s -> %s/verify.json, verify.csv: %s\n", n, wall, o->outdir,
           rc ? "FAIL (a check failed)" : "no failed check");
  free(cs);
  free(started);
  close(lock);
  return stopped ? 130 : rc;
}
