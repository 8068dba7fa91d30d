/*
 * report_run.c - the runs behind `delam report`: the case table, the result cache
 * (out/report/<case-id>/: reused when its summary.json says "complete": true and the
 * scene file is unchanged; a failed run only while the delam binary is also the same),
 * and the runs of `delam run` (or gnuplot) children a few at a time through the process
 * pool (pool.c); each child writes to its own log file so that the parent's stderr
 * carries only the progress lines.
 */
#include <assert.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "io.h"
#include "pool.h"
#include "report.h"
#include "run.h"
#include "scene.h"

void ver_report_abs(const char *path, char *out, size_t len)
{
  char cwd[REP_PATH];
  if (path[0] == '/' || !getcwd(cwd, sizeof cwd))
    snprintf(out, len, "%s", path);
  else
    snprintf(out, len, "%.1000s/%.1000s", cwd, path);
}


/* "decohesion.separation=0.8" -> "-separation0.8" appended to id (ver_scene_id_part). */
static void id_suffix(char *id, size_t len, const char *set)
{
  if (!strchr(set, '='))
    return;
  char part[128];
  ver_scene_id_part(set, part, sizeof part);
  const size_t n = strlen(id), m = strlen(part);
  if (n + m + 2 <= len) {
    id[n] = '-';
    memcpy(id + n + 1, part, m + 1);
  }
}

int ver_report_add(rep_ctx *r, const char *scene, double h, int ppc, double dt, double until,
                   const char *set1, const char *set2, int role, double tag)
{
  const char *sets[2] = {set1, set2};
  return ver_report_add_sets(r, scene, h, ppc, dt, until, sets, set2 ? 2 : set1 ? 1 : 0, role, tag);
}

int ver_report_add_sets(rep_ctx *r, const char *scene, double h, int ppc, double dt, double until,
                        const char *const *sets, int nset, int role, double tag)
{
  char id[128];
  snprintf(id, sizeof id, "%s-h%g-ppc%d", scene, h, ppc);
  if (until > 0)
    snprintf(id + strlen(id), sizeof id - strlen(id), "-u%g", until);
  if (dt > 0)
    snprintf(id + strlen(id), sizeof id - strlen(id), "-dt%.4g", dt);
  /* the paper's method is one word in the id: its eleven overrides would not fit */
  if (sets == ver_paper_sets)
    snprintf(id + strlen(id), sizeof id - strlen(id), "-paper");
  else
    for (int j = 0; j < nset && j < REP_NSET; j++)
      id_suffix(id, sizeof id, sets[j]);
  const int k = ver_report_find(r, id);
  if (k >= 0) {
    r->c[k].role |= role;
    return k;
  }
  if (r->n >= REP_MAX_CASES)
    return -1;
  rep_case *c = &r->c[r->n];
  memset(c, 0, sizeof *c);
  snprintf(c->id, sizeof c->id, "%s", id);
  snprintf(c->scene, sizeof c->scene, "%s", scene);
  c->h = h;
  c->ppc = ppc;
  c->dt = dt;
  c->until = until;
  assert(nset <= REP_NSET); /* a case runs every override it is given */
  for (int j = 0; j < nset && j < REP_NSET; j++)
    snprintf(c->set[c->nset++], sizeof c->set[0], "%s", sets[j]);
  c->allow_unstable = (role & REP_STAB) != 0;
  c->role = role;
  c->tag = tag;
  c->exit_status = -1;
  c->curve_err = c->max_dev = c->diss_err = c->k_soft = c->drop_width = NAN;
  /* cost: particles x steps, from the scene file (L, H, its dt scaled with h, its end) */
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%s/%s.ini", r->scenes, scene);
  double L = 192, H = 32, dts = 0.0125 * h, end = 2, speed = 0.001;
  c->last_snap = -1;
  if (ver_scene_load(path, &vs, err, sizeof err) == 0) {
    for (int j = 0; j < vs.nsnap; j++)
      c->last_snap = fmax(c->last_snap, vs.snap[j]);
    L = vs.sc.L;
    H = vs.sc.H;
    dts = vs.sc.dt * h / vs.sc.h;
    end = vs.sc.end_delta;
    speed = vs.sc.speed;
  }
  c->speed = speed;
  if (dt > 0)
    dts = dt;
  if (until > 0)
    end = until;
  c->cost = L * H / (h * h) * ppc * end / (speed * dts);
  return r->n++;
}

int ver_report_find(const rep_ctx *r, const char *id)
{
  for (int i = 0; i < r->n; i++)
    if (!strcmp(r->c[i].id, id))
      return i;
  return -1;
}

/* The exit status of a run is kept in DIR/exit-status with the size and mtime of the
 * delam program that made it: a failed run is reused only while that program is
 * unchanged (a complete one always). */
static void exe_stamp(const char *exe, long long *size, long long *mtime)
{
  struct stat st;
  *size = *mtime = -1;
  if (stat(exe, &st) == 0) {
    *size = (long long)st.st_size;
    *mtime = (long long)st.st_mtime;
  }
}

static int read_exit_status(const rep_ctx *r, const char *dir, int *same_exe)
{
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/exit-status", dir);
  FILE *f = fopen(p, "r");
  int s = -1;
  long long sz = -2, mt = -2, esz, emt;
  *same_exe = 0;
  if (f) {
    if (fscanf(f, "%d %lld %lld", &s, &sz, &mt) < 1)
      s = -1;
    fclose(f);
  }
  exe_stamp(r->exe, &esz, &emt);
  *same_exe = sz == esz && mt == emt && esz >= 0;
  return s;
}

static void write_exit_status(const rep_ctx *r, const char *dir, int s)
{
  char p[REP_PATH + 32];
  long long sz, mt;
  exe_stamp(r->exe, &sz, &mt);
  snprintf(p, sizeof p, "%s/exit-status", dir);
  FILE *f = fopen(p, "w");
  if (f) {
    fprintf(f, "%d %lld %lld\n", s, sz, mt);
    fclose(f);
  }
}

/* 1 if the two files have the same bytes (scene files are small). */
static int same_file(const char *a, const char *b)
{
  size_t la = 0, lb = 0;
  char *x = ver_io_slurp(a, &la, VER_SCENE_MAX), *y = ver_io_slurp(b, &lb, VER_SCENE_MAX);
  const int same = x && y && la == lb && !memcmp(x, y, la);
  free(x);
  free(y);
  return same;
}

/* Keeps a copy of the scene file beside the results, so that a cached result is
 * reused only while the scene file is unchanged. */
static void keep_scene(const rep_ctx *r, const rep_case *c)
{
  char src[REP_PATH + 64], dst[REP_PATH + 32];
  snprintf(src, sizeof src, "%s/%s.ini", r->scenes, c->scene);
  snprintf(dst, sizeof dst, "%s/source.ini", c->dir);
  ver_io_copy(src, dst);
}

/* Uses the results in dir if they are complete, or (check_scene: our own cache) if the
 * same binary on the same scene file failed before.  1 if taken. */
static int try_reuse(const rep_ctx *r, rep_case *c, const char *dir, int check_scene)
{
  char p[REP_PATH + 64], q[REP_PATH + 64];
  snprintf(p, sizeof p, "%s/source.ini", dir);
  snprintf(q, sizeof q, "%s/%s.ini", r->scenes, c->scene);
  if (check_scene && !same_file(p, q))
    return 0; /* made with another version of the scene file */
  snprintf(p, sizeof p, "%s/snap-d%.3f.csv", dir, c->last_snap);
  if ((c->role & REP_PIC) && c->last_snap >= 0 && access(p, R_OK) != 0)
    return 0; /* a shorter run under the same case id: no pictures */
  char save[REP_PATH];
  snprintf(save, sizeof save, "%s", c->dir);
  snprintf(c->dir, sizeof c->dir, "%s", dir);
  if (ver_report_read_summary(c) == 0) {
    int same_exe;
    const int st = read_exit_status(r, dir, &same_exe);
    /* a run stopped by a signal (130) or killed (128 + n) is run again, not reused */
    if (c->complete || (check_scene && st > 0 && st < 128 && same_exe)) {
      c->have = 1;
      c->reused = 1;
      c->exit_status = c->complete ? 0 : st;
      return 1;
    }
  }
  snprintf(c->dir, sizeof c->dir, "%s", save);
  return 0;
}

typedef struct {
  char ***argvs;
  const char *cwd;
  char **logs, **names;
  int n, *status;
  const char *what;
  const int *meant_to_fail; /* per job, or NULL: a failure is then the result it is run for */
} spawn_ctx;

static pid_t spawn_one(int i, void *ctx)
{
  const spawn_ctx *c = ctx;
  return ver_pool_spawn(c->argvs[i], c->cwd, c->logs[i]);
}

static void spawn_done(int i, int status, int sig, double wall, int done, void *ctx)
{
  const spawn_ctx *c = ctx;
  (void)sig;
  c->status[i] = status;
  if (status >= 0)
    fprintf(stderr, "delam report: [%2d/%d] %s %s: %s (%.1f s)\n", done, c->n, c->what, c->names[i],
            status == 0                              ? "ok"
            : status == 130                          ? "stopped by a signal"
            : c->meant_to_fail && c->meant_to_fail[i] ? "blew up, as a time step above the stable bound should"
                                                      : "failed",
            wall);
}

void ver_report_spawn_all(char ***argvs, const char *cwd, char **logs, char **names, int n, int jobs,
                          int *status, const char *what, const int *meant_to_fail)
{
  for (int i = 0; i < n; i++)
    status[i] = -1;
  spawn_ctx c = {argvs, cwd, logs, names, n, status, what, meant_to_fail};
  const ver_pool p = {n, jobs, NULL, spawn_one, NULL, spawn_done, &c};
  ver_pool_run(&p);
}

static int by_cost_desc(const void *a, const void *b)
{
  const double x = (*(rep_case *const *)a)->cost, y = (*(rep_case *const *)b)->cost;
  return (x < y) - (x > y);
}

/* The cases without results: reused from --from or the cache where possible, the rest
 * into todo; returns how many are to run. */
static int plan_runs(rep_ctx *r, rep_case **todo, int *reused)
{
  int ntodo = 0;
  *reused = 0;
  for (int i = 0; i < r->n; i++) {
    rep_case *c = &r->c[i];
    if (c->have)
      continue;
    char d[REP_PATH];
    if (r->from[0]) {
      snprintf(d, sizeof d, "%.800s/%.150s", r->from, c->id);
      if (try_reuse(r, c, d, 0)) {
        (*reused)++;
        continue;
      }
    }
    snprintf(d, sizeof d, "%.800s/%.150s", r->cache, c->id);
    if (!r->rerun && try_reuse(r, c, d, 1)) {
      (*reused)++;
      continue;
    }
    snprintf(c->dir, sizeof c->dir, "%s", d);
    todo[ntodo++] = c;
  }
  return ntodo;
}

enum { NARG = 40, ALEN = REP_PATH + 64 };

/* The `delam run` command line of case c in av (strings in s, NARG x ALEN). */
static void run_argv(const rep_ctx *r, const rep_case *c, char **av, char *s)
{
  int k = 0;
#define ARG(...) (snprintf(s + (size_t)k * ALEN, ALEN, __VA_ARGS__), av[k] = s + (size_t)k * ALEN, k++)
  av[k++] = (char *)r->exe;
  ARG("run");
  ARG("%.900s/%.40s.ini", r->scenes, c->scene);
  ARG("--h");
  ARG("%.17g", c->h);
  ARG("--ppc");
  ARG("%d", c->ppc);
  if (c->dt > 0) {
    ARG("--dt");
    ARG("%.17g", c->dt);
  }
  if (c->until > 0) {
    ARG("--until");
    ARG("%.17g", c->until);
  }
  for (int j = 0; j < c->nset; j++) {
    ARG("--set");
    ARG("%s", c->set[j]);
  }
  if (c->allow_unstable)
    ARG("--allow-unstable");
  ARG("--threads");
  ARG("1");
  ARG("--quiet");
  ARG("--out");
  ARG("%.1000s", c->dir);
#undef ARG
  av[k] = NULL;
}

int ver_report_run_cases(rep_ctx *r)
{
  rep_case *todo[REP_MAX_CASES];
  int reused;
  int ntodo = plan_runs(r, todo, &reused);
  double total = 0;
  for (int i = 0; i < ntodo; i++)
    total += todo[i]->cost;
  fprintf(stderr, "delam report: %d cases, %d reused, %d to run (%.2g particle-updates) with %d at a time\n",
          r->n, reused, ntodo, total, r->jobs);
  if (!ntodo)
    return 0;
  /* longest first, so that the last ones to finish are short */
  qsort(todo, (size_t)ntodo, sizeof todo[0], by_cost_desc);
  /* argument vectors: every string lives in one block per case */
  char *store = calloc((size_t)ntodo, NARG * ALEN);
  char ***argvs = calloc((size_t)ntodo, sizeof *argvs);
  char **argvbuf = calloc((size_t)ntodo * (NARG + 1), sizeof *argvbuf);
  char **logs = calloc((size_t)ntodo, sizeof *logs), **names = calloc((size_t)ntodo, sizeof *names);
  char *logstore = calloc((size_t)ntodo, REP_PATH + 16);
  int *status = calloc((size_t)ntodo, sizeof *status);
  int *meant = calloc((size_t)ntodo, sizeof *meant);
  int failed = 0;
  if (!store || !argvs || !argvbuf || !logs || !names || !logstore || !status || !meant) {
    fprintf(stderr, "delam report: out of memory\n");
    failed = ntodo;
    ntodo = 0;
  }
  for (int i = 0; i < ntodo; i++) {
    rep_case *c = todo[i];
    argvs[i] = argvbuf + (size_t)i * (NARG + 1);
    run_argv(r, c, argvs[i], store + (size_t)i * NARG * ALEN);
    /* the log sits beside the run's files; the folder must exist before the child opens it */
    ver_mkdir_p(c->dir);
    logs[i] = logstore + (size_t)i * (REP_PATH + 16);
    snprintf(logs[i], REP_PATH + 16, "%s/run.log", c->dir);
    names[i] = c->id;
    meant[i] = c->allow_unstable; /* the time-step sweep: above the bound a blow-up is its result */
  }
  ver_report_spawn_all(argvs, NULL, logs, names, ntodo, r->jobs, status, "run", meant);
  for (int i = 0; i < ntodo; i++) {
    rep_case *c = todo[i];
    c->exit_status = status[i];
    write_exit_status(r, c->dir, status[i]);
    keep_scene(r, c);
    if (ver_report_read_summary(c) == 0)
      c->have = 1;
    else
      failed++;
    if (status[i] != 0 && !c->allow_unstable)
      fprintf(stderr, "delam report: %s: delam run exit status %d (see %s)\n", c->id, status[i], logs[i]);
  }
  free(store);
  free(argvs);
  free(argvbuf);
  free(logs);
  free(names);
  free(logstore);
  free(status);
  free(meant);
  return failed;
}
