/*
 * pool.c - the process pool (pool.h).
 *
 * Children are started with fork (+ exec) rather than posix_spawn because gnuplot has
 * to run inside the output folder (chdir between the two) and verify's cases run in a
 * forked copy of the program itself.
 */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif
#include <time.h>
#include <unistd.h>

#include "io.h"
#include "pool.h"

/* The signal (SIGINT, SIGTERM, SIGHUP) that stopped the command (0: none), set by the handler
 * ver_pool_catch installs.  Global because a signal handler can reach nothing else; a
 * forked child keeps its own copy, which its ver_run polls (ver_pool_stop_flag). */
static volatile sig_atomic_t caught;

static void on_signal(int sig)
{
  caught = sig;
}

void ver_pool_catch(void)
{
  struct sigaction sa, old;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);
  /* a closed terminal too, unless nohup asked for it to be ignored */
  if (sigaction(SIGHUP, NULL, &old) == 0 && old.sa_handler != SIG_IGN)
    sigaction(SIGHUP, &sa, NULL);
}

void ver_pool_child(pid_t parent)
{
#ifdef __linux__
  /* SIGTERM when the parent dies, even by SIGKILL, so that no child outlives it; it
   * may have died before this call */
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent)
    _exit(130);
#else
  (void)parent;
#endif
}

int ver_pool_caught(void)
{
  return caught;
}

volatile sig_atomic_t *ver_pool_stop_flag(void)
{
  return &caught;
}

pid_t ver_pool_spawn(char *const argv[], const char *cwd, const char *log)
{
  fflush(NULL);
  const pid_t parent = getpid(), pid = fork();
  if (pid != 0)
    return pid; /* parent (or -1) */
  ver_pool_child(parent);
  if (cwd && chdir(cwd) != 0)
    _exit(126);
  const int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (fd >= 0) {
    dup2(fd, 1);
    dup2(fd, 2);
    close(fd);
  }
  execvp(argv[0], argv);
  _exit(127);
}

typedef struct {
  pid_t pid;
  int job;     /* -1: free */
  double t0;
} slot;

/* Starts jobs into free slots; returns 1 if any started. */
static int fill(const ver_pool *p, slot *s, int *next, int *running, int *done)
{
  int started = 0;
  while (*running < p->jobs && *next < p->n) {
    const int i = p->order ? p->order[*next] : *next;
    (*next)++;
    int j = 0;
    while (s[j].job >= 0)
      j++;
    const double t0 = ver_now_wall();
    const pid_t pid = p->start(i, p->ctx);
    if (pid < 0) {
      (*done)++;
      if (p->finished)
        p->finished(i, -1, 0, 0.0, *done, p->ctx);
      continue;
    }
    s[j] = (slot){pid, i, t0};
    (*running)++;
    started = 1;
  }
  return started;
}

/* After a signal: SIGTERM once to every running child (each stops as the command does:
 * a run writes what it has and exits 130), SIGKILL to those still there 30 s later. */
static void stop_children(const slot *s, int jobs, double *t_sig, int *killed)
{
  const int first = *t_sig < 0.0;
  if (first)
    *t_sig = ver_now_wall();
  else if (*killed || ver_now_wall() - *t_sig < 30.0)
    return;
  else
    *killed = 1;
  for (int j = 0; j < jobs; j++)
    if (s[j].job >= 0)
      kill(s[j].pid, first ? SIGTERM : SIGKILL);
}

/* The child pid ended with wait status ws: its slot freed, the caller told. */
static void finish_one(const ver_pool *p, slot *s, pid_t pid, int ws, int *running, int *done)
{
  int j = 0;
  while (j < p->jobs && !(s[j].job >= 0 && s[j].pid == pid))
    j++;
  if (j == p->jobs)
    return;
  const int sig = WIFSIGNALED(ws) ? WTERMSIG(ws) : 0;
  const int st = WIFEXITED(ws) ? WEXITSTATUS(ws) : sig ? 128 + sig : -1;
  const int i = s[j].job;
  const double wall = ver_now_wall() - s[j].t0;
  s[j].job = -1;
  (*running)--;
  (*done)++;
  if (p->finished)
    p->finished(i, st, sig, wall, *done, p->ctx);
}

int ver_pool_run(const ver_pool *p)
{
  slot *s = malloc(sizeof *s * (size_t)(p->jobs > 0 ? p->jobs : 1));
  int *run = malloc(sizeof *run * (size_t)(p->jobs > 0 ? p->jobs : 1));
  if (!s || !run || p->jobs < 1) {
    free(s);
    free(run);
    return -1;
  }
  for (int j = 0; j < p->jobs; j++)
    s[j].job = -1;
  int next = 0, running = 0, done = 0, killed = 0;
  double t_sig = -1.0;
  /* polled every 20 ms rather than a blocking wait, which would sleep through a signal
   * until some child ended */
  const struct timespec tick = {0, 20000000};
  while (done < p->n && (running > 0 || !caught)) {
    if (!caught && fill(p, s, &next, &running, &done) && p->started) {
      int k = 0;
      for (int j = 0; j < p->jobs; j++)
        if (s[j].job >= 0)
          run[k++] = s[j].job;
      p->started(run, k, done, p->ctx);
    }
    if (running == 0)
      continue;
    if (caught)
      stop_children(s, p->jobs, &t_sig, &killed);
    int ws;
    const pid_t pid = waitpid(-1, &ws, WNOHANG);
    if (pid == 0)
      nanosleep(&tick, NULL);
    else if (pid > 0)
      finish_one(p, s, pid, ws, &running, &done);
    else if (errno != EINTR)
      break;
  }
  free(s);
  free(run);
  return caught ? (int)caught : 0;
}
