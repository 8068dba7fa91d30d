/*
 * mpm_kernel.h - what the kernel's files share of the explicit run's machinery and no
 * caller needs (private to kernel/): the band's rows, damping, the thread count, the
 * grip's control, the sort and the cut.
 */
#ifndef DELAM_MPM_KERNEL_H
#define DELAM_MPM_KERNEL_H

#include <time.h>

#include "mpm.h"

/* Seconds on the monotonic clock: the kernel's timings (time split, thread probes, the
 * static solver's phases). */
static inline double mpm_wall(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* decohesion.Le = row (mpm_band.c): Le per particle row of the bar, measured from the
 * particles softening in it, k dx |sin a| with k = sum / lam (mpm_band_le). */
struct mpm_band {
  int nrow, nstrip;        /* particle rows of the bar; strips of the gather            */
  double idy;              /* 1 / the row height h / sqrt(ppc)                           */
  double wlen;             /* Le per participating particle, dx |sin a| Le_factor        */
  double le0;              /* a row's Le before any of its particles has softened        */
  double *acc;             /* per strip and row: sum of this step's dlambda (softening), and
                              the largest min(lambda, 1) reached                        */
  double *lam;             /* each row's crack state: the largest min(lambda, 1) in it   */
  double *sum;             /* each row's softening so far, the sum of its particles' dlambda */
  double *xl;              /* each row's lead: the x0 of its particle with the largest lambda */
  double reach;            /* Le = zone: only the particles within this x0 distance of the
                              row's lead count in sum (2 h + dx: their supports touch the
                              lead's); 0 for Le = row, every particle of the row counts  */
};

mpm_band *mpm_band_alloc(int nrow, int nstrip, double dy, double wlen, double le0, double reach);
void mpm_band_free(mpm_band *b);
void mpm_band_step(mpm_band *b);
static inline int mpm_band_row(const mpm_band *b, double y0)
{
  const int j = (int)(y0 * b->idy);
  return j < 0 ? 0 : j >= b->nrow ? b->nrow - 1 : j;
}
/* Row j's Le for this step: k wlen, k = sum / lam (at least 1), once it has softened. */
static inline double mpm_band_le(const mpm_band *b, int j)
{
  const double lam = b->lam[j], sum = b->sum[j];
  if (!(lam > 0.0 && sum > 0.0))
    return b->le0;
  const double k = sum / lam;
  return (k > 1.0 ? k : 1.0) * b->wlen;
}

/* Sets up t for `requested` threads (<= 0: automatic, up to OpenMP's default). */
void mpm_threads_init(mpm_threads *t, int requested, size_t particles);

/* Local damping (time.damping, mpm_damping.c): after the node update (and the second
 * field's), on every free velocity component; under MUSL, its share of the stress power
 * after the re-projection. */
mpm_damping *mpm_damping_alloc(const mpm_sim *s);
void mpm_damping_free(mpm_damping *d);
void mpm_damping_apply(mpm_sim *s);
void mpm_damping_musl(mpm_sim *s);
/* time.damping_about = parts, once the band has cut the bar: each bar particle's velocity
 * relaxes toward the motion of its part's held end (mpm_damping.c); books L_damp. */
void mpm_damping_parts(mpm_sim *s);

/* Sorts the particles by cell (stable counting sort) and rebuilds the strips. */
void mpm_sim_sort(mpm_sim *s);

/* Called at the top of each step: picks the step's thread count (s->nthreads). */
void mpm_threads_tick(mpm_sim *s);

/* The grip's speed for the next step (mpm_control.c), at the top of each step. */
void mpm_control_step(mpm_sim *s);

/* Updates s->cut after new separations (cheap when there are none). */
void mpm_sim_cut(mpm_sim *s);

#endif
