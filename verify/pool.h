/*
 * pool.h - the one process pool of verify/ (prefix ver_pool_): n jobs, at most `jobs`
 * children at once, in a given order.  `delam verify` forks a child per case (a
 * crashing case cannot take the sweep with it); `delam report` forks + execs `delam
 * run` and gnuplot.  The caller says how to start job i and hears when it ends.
 */
#ifndef DELAM_VER_POOL_H
#define DELAM_VER_POOL_H

#include <signal.h>
#include <sys/types.h>

typedef struct {
  int n;                 /* jobs                                                      */
  int jobs;              /* children at once (>= 1)                                   */
  const int *order;      /* the order to start them in; NULL: 0 .. n-1                */
  /* starts job i in a child and returns its pid (-1: it could not start) */
  pid_t (*start)(int i, void *ctx);
  /* optional: after a round of starts, the jobs running now */
  void (*started)(const int *running, int nrunning, int done, void *ctx);
  /* job i ended: exit status (128 + signal if killed, -1 if it never started), the
   * signal that killed it (0 if none), its wall time, jobs done so far */
  void (*finished)(int i, int status, int sig, double wall_s, int done, void *ctx);
  void *ctx;
} ver_pool;

/* Runs every job; 0, -1 if out of memory (nothing started), or the signal (SIGINT,
 * SIGTERM) that stopped it, caught by ver_pool_catch: then no job is started, every
 * running child gets SIGTERM (SIGKILL 30 s later if still there) and is waited for, and
 * the jobs never started are not reported to finished. */
int ver_pool_run(const ver_pool *p);

/* For a command that runs a pool: SIGINT, SIGTERM and SIGHUP are caught from now on, for the
 * pool to stop its children and the command to stop between its stages; caught says
 * which came (0: none).  A forked child that does not exec stops its run on the same
 * flag (its own copy): ver_pool_stop_flag is ver_run_opts.stop for it. */
void ver_pool_catch(void);
int ver_pool_caught(void);
volatile sig_atomic_t *ver_pool_stop_flag(void);
/* In a child just forked by parent: it gets SIGTERM when parent dies, however (Linux). */
void ver_pool_child(pid_t parent);

/* A start helper: fork + exec argv (PATH search) in folder cwd (NULL: here) with stdout
 * and stderr to the file log (opened after the chdir). */
pid_t ver_pool_spawn(char *const argv[], const char *cwd, const char *log);

#endif
