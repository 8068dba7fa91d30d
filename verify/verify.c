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
#include "verify.h"

typedef struct {
  const ver_verify_opts *o;
  ver_case *cs;
  int n;
  int threads;   /* OpenMP threads a child */
} run_ctx;

/* In the child: one run, its error text (if any) to DIR/<id>/error.txt. */
static void child_run(const ver_verify_opts *o, const ver_case *c, int threads)
{
  char dir[800], path[900], err[1024] = "";
  ver_case_dir(o, c, dir, sizeof dir);
  snprintf(path, sizeof path, "%s/error.txt", dir);
  remove(path);
  ver_run_opts ro = {dir, 0, 1, NULL, 0, threads};
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
  const pid_t pid = fork();
  if (pid == 0)
    child_run(r->o, &r->cs[i], r->threads);
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

/* Runs every case, at most o->jobs at a time, costliest first. */
static int run_cases(const ver_verify_opts *o, ver_case *cs, int n)
{
  int *order = malloc(sizeof(int) * (size_t)(n + 1));
  if (!order)
    return 2;
  for (int i = 0; i < n; i++)
    order[i] = i;
  /* insertion sort by cost, descending (n is small) */
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && cs[order[j]].cost > cs[order[j - 1]].cost; j--) {
      const int t = order[j];
      order[j] = order[j - 1];
      order[j - 1] = t;
    }
  const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
  /* as many jobs as cores: one thread each; fewer: the kernel chooses (mpm_threads.c) */
  run_ctx ctx = {o, cs, n, o->jobs >= (ncpu > 0 ? ncpu : 1) ? 1 : 0};
  const ver_pool p = {n, o->jobs, order, start_case, show_running, case_done, &ctx};
  const int rc = ver_pool_run(&p);
  free(order);
  return rc ? 2 : 0;
}

/* One `delam run` line per case. */
static void list_cases(const ver_verify_opts *o, const ver_case *cs, int n)
{
  for (int i = 0; i < n; i++) {
    const ver_case *c = &cs[i];
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
static int check_all(ver_case *cs, int n, ver_cross *x, int *nx)
{
  int rc = 0;
  for (int i = 0; i < n; i++) {
    ver_policy_case(&cs[i]);
    for (int j = 0; j < cs[i].nchk; j++)
      ver_sweep_print_check(cs[i].id, &cs[i].chk[j]);
    rc |= cs[i].verdict == VER_FAIL;
  }
  *nx = ver_policy_cross(cs, n, x);
  *nx += ver_mms_cross(x + *nx, VER_MAXCROSS - *nx);
  for (int i = 0; i < *nx; i++) {
    char id[160];
    snprintf(id, sizeof id, "%s/%s%g", x[i].scene, strcmp(x[i].over, "h") ? "h" : "ppc", x[i].fixed);
    ver_sweep_print_check(id, &x[i].chk);
    rc |= x[i].chk.verdict == VER_FAIL;
  }
  return rc;
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
  if (ver_mkdir_p(o->outdir) != 0) {
    fprintf(stderr, "delam verify: %s: cannot create: %s\n", o->outdir, strerror(errno));
    free(cs);
    return 2;
  }
  const double w0 = ver_now_wall();
  if (!o->merge) {
    fprintf(stderr, "verify: %d cases, %d at a time, into %s/\n", n, o->jobs, o->outdir);
    if (run_cases(o, cs, n)) {
      free(cs);
      return 2;
    }
  }
  for (int i = 0; i < n; i++)
    ver_case_read(o, &cs[i]);
  static ver_cross x[VER_MAXCROSS];
  int nx;
  int rc = check_all(cs, n, x, &nx);
  ver_sweep_print_table(cs, n, x, nx);
  const double wall = ver_now_wall() - w0;
  if (ver_sweep_write_json(o, cs, n, x, nx, wall, rc) || ver_sweep_write_csv(o, cs, n) ||
      ver_sweep_write_cross_csv(o, x, nx)) {
    fprintf(stderr, "delam verify: %s: cannot write verify.json / verify.csv: %s\n", o->outdir, strerror(errno));
    rc = rc ? rc : 2;
  }
  printf("\nverify: %d cases in %.1f s -> %s/verify.json, verify.csv: %s\n", n, wall, o->outdir,
         rc ? "FAIL (a check failed)" : "no failed check");
  free(cs);
  return rc;
}
