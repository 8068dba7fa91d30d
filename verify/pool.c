/*
 * pool.c - the process pool (pool.h).
 *
 * Children are started with fork (+ exec) rather than posix_spawn because gnuplot has
 * to run inside the output folder (chdir between the two) and verify's cases run in a
 * forked copy of the program itself.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io.h"
#include "pool.h"

pid_t ver_pool_spawn(char *const argv[], const char *cwd, const char *log)
{
  fflush(NULL);
  const pid_t pid = fork();
  if (pid != 0)
    return pid; /* parent (or -1) */
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
  int next = 0, running = 0, done = 0;
  while (done < p->n) {
    if (fill(p, s, &next, &running, &done) && p->started) {
      int k = 0;
      for (int j = 0; j < p->jobs; j++)
        if (s[j].job >= 0)
          run[k++] = s[j].job;
      p->started(run, k, done, p->ctx);
    }
    if (running == 0)
      continue;
    int ws;
    const pid_t pid = waitpid(-1, &ws, 0);
    if (pid < 0) {
      if (errno == EINTR)
        continue;
      break;
    }
    int j = 0;
    while (j < p->jobs && !(s[j].job >= 0 && s[j].pid == pid))
      j++;
    if (j == p->jobs)
      continue;
    const int sig = WIFSIGNALED(ws) ? WTERMSIG(ws) : 0;
    const int st = WIFEXITED(ws) ? WEXITSTATUS(ws) : sig ? 128 + sig : -1;
    const int i = s[j].job;
    const double wall = ver_now_wall() - s[j].t0;
    s[j].job = -1;
    running--;
    done++;
    if (p->finished)
      p->finished(i, st, sig, wall, done, p->ctx);
  }
  free(s);
  free(run);
  return 0;
}
