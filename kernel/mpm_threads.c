/*
 * mpm_threads.c - how many threads a step uses when the caller leaves it open
 * (mpm_sim_alloc with nthreads <= 0).  Results do not depend on the count (mpm_sort.c),
 * so it may change between any two steps.  On a machine whose other cores are busy,
 * OpenMP's threads wait at every barrier for a descheduled partner, so the count is
 * measured, not guessed (docs/findings.md, "Threads and speed"):
 *  - below MPM_THREADS_MIN_PARTICLES particles, or with no idle core (load average at
 *    least the cores less one half), one thread;
 *  - otherwise a probe (MPM_PROBE_STEPS steps on one thread, as many on all) alternates
 *    with a stretch on the faster count, doubling while the choice holds (up to
 *    MPM_PERIOD_MAX steps); a many-thread probe or stretch slower than one thread falls
 *    back early, and a lost probe costs at most MPM_PROBE_SHARE of the next stretch.
 * The clock is read once per step (mpm_threads_tick).
 */
#include <stdio.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "mpm.h"
#include "mpm_kernel.h"

/* 1 if the machine has no idle core for a second thread: the 1-minute load average
 * (runnable tasks, this run's own thread among them) above the cores less one half.
 * Linux's /proc/loadavg; where it cannot be read, 0 (the probes decide alone). */
static int machine_busy(void)
{
#ifdef _OPENMP
  const int ncpu = omp_get_num_procs();
#else
  const int ncpu = 1;
#endif
  FILE *f = fopen("/proc/loadavg", "r");
  double load = 0.0;
  const int ok = f && fscanf(f, "%lf", &load) == 1;
  if (f)
    fclose(f);
  return ok && load > (double)ncpu - 0.5;
}

/* The next probe, unless the machine is busy: then another stretch on one thread,
 * twice as long as the last (a busy machine is asked ever less often). */
static void start_probe(mpm_threads *t)
{
  t->use = 1;
  t->np = 0;
  if (machine_busy()) {
    t->phase = MPM_TPH_RUN;
    t->period = t->period < MPM_PERIOD_MAX ? 2 * t->period : MPM_PERIOD_MAX;
    t->left = t->period;
    t->nbusy++;
    return;
  }
  t->phase = MPM_TPH_PROBE1;
  t->left = MPM_PROBE_STEPS + 1;
}

void mpm_threads_init(mpm_threads *t, int requested, size_t particles)
{
  *t = (mpm_threads){0};
#ifdef _OPENMP
  t->nmax = requested > 0 ? requested : omp_get_max_threads();
#else
  (void)requested;
  t->nmax = 1;
#endif
  if (t->nmax < 1)
    t->nmax = 1;
  t->automatic = requested <= 0 && t->nmax > 1 && particles >= MPM_THREADS_MIN_PARTICLES;
  t->use = requested > 0 || t->automatic ? t->nmax : 1;
  if (t->automatic) {
    t->period = MPM_PERIOD_MIN / 2; /* start_probe doubles it if it waits */
    start_probe(t);
  }
}

static double sum(const double *v, int n)
{
  double a = 0.0;
  for (int i = 0; i < n; i++)
    a += v[i];
  return a;
}

static void decide(mpm_threads *t)
{
  if (!t->automatic)
    return;
  if (t->phase == MPM_TPH_RUN && t->use == 1 && t->left > 1) {
    t->left--; /* a stretch on one thread needs no clock */
    return;
  }
  const double now = mpm_wall(), dt = now - t->last;
  const int have = t->last > 0.0;
  t->last = now;
  if (t->phase == MPM_TPH_RUN) {
    /* On many threads, a window of MPM_PROBE_STEPS steps slower in total than one
     * thread's means the machine got busy: back to one thread now, not at the next probe. */
    if (t->use > 1 && have) {
      t->run_sum += dt;
      if (++t->run_n == MPM_PROBE_STEPS) {
        if (t->run_sum > (double)t->run_n * t->mean1) {
          t->use = t->last_pick = 1;
          t->period = MPM_PERIOD_MIN;
          t->left = t->period;
          t->nfall++;
        }
        t->run_sum = 0.0;
        t->run_n = 0;
      }
    }
    if (--t->left > 0)
      return;
    start_probe(t);
    return;
  }
  /* A probe.  The first step on a new count (wake-up, cache) is not counted.  Means,
   * not medians: on a busy machine a few steps in a window lose a scheduler time slice
   * each, and those are the cost. */
  if (have && t->left <= MPM_PROBE_STEPS && t->np < MPM_PROBE_STEPS)
    t->tp[t->np++] = dt;
  if (t->phase == MPM_TPH_PROBEN && have) {
    t->probe_time += dt;
    t->probe_n++;
  }
  /* many threads already twice as slow as one thread, wake-up step included: end the
   * probe (on a busy machine each such step costs a few scheduler time slices) */
  const int hopeless = t->phase == MPM_TPH_PROBEN && t->probe_n > 0 &&
                       t->probe_time > 2.0 * t->mean1 * (double)t->probe_n;
  if (--t->left > 0 && !hopeless)
    return;
  if (t->phase == MPM_TPH_PROBE1) {
    t->mean1 = t->np ? sum(t->tp, t->np) / t->np : 0.0;
    t->phase = MPM_TPH_PROBEN;
    t->left = MPM_PROBE_STEPS + 1;
    t->np = 0;
    t->probe_time = 0.0;
    t->probe_n = 0;
    t->use = t->nmax;
    return;
  }
  /* many threads only when clearly faster: a tie goes to one thread */
  const int pick = !hopeless && sum(t->tp, t->np) < 0.9 * t->mean1 * t->np ? t->nmax : 1;
  t->period = pick == t->last_pick && t->period < MPM_PERIOD_MAX ? 2 * t->period : MPM_PERIOD_MIN;
  t->last_pick = pick;
  t->use = pick;
  t->phase = MPM_TPH_RUN;
  t->left = t->period;
  /* a probe that lost costs at most MPM_PROBE_SHARE of the time on one thread */
  if (pick == 1 && t->mean1 > 0.0) {
    const double lost = t->probe_time - t->mean1 * (double)t->probe_n;
    t->losses++;
    /* doubled for each loss in a row: a machine that stays busy is probed ever less */
    const double need = lost / (MPM_PROBE_SHARE * t->mean1) * (double)(1L << (t->losses < 10 ? t->losses - 1 : 9));
    if (need > (double)t->left)
      t->left = need < 1e9 ? (long)need : 1000000000L;
  }
  if (pick > 1)
    t->losses = 0;
  t->run_sum = 0.0;
  t->run_n = 0;
  t->nprobe++;
}

void mpm_threads_tick(mpm_sim *s)
{
  decide(&s->thr);
  s->nthreads = s->thr.use;
  if (s->thr.use > 1)
    s->thr.steps_multi++;
}
