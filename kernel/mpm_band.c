/*
 * mpm_band.c - Le measured from the band itself (decohesion.Le = row): the effective
 * length of eq. 41, Le = V_e / A_d, taken per particle row of the bar from the particles
 * that soften in it, instead of from the cell (docs/findings.md).
 *
 * Why.  Eq. 41 makes a band of volume V dissipate U0 A when every particle in it
 * separates and Le = V / A.  The cell and staircase lengths assume a band shape; on an
 * inclined line with several particles per cell the band that forms is 3 to 6 particles
 * wide per row at first and localizes later, so a fixed Le over- or under-charges it.
 * A straight crack crosses each particle row of the bar (height dy) once, over a length
 * dy / |sin a|.  If k particles of width dx soften together in a row, the zone's volume
 * per unit crack length is k dx |sin a|: that is the row's Le.  k is measured as
 * S / lam_r, S the sum of every dlambda the row's particles have softened so far and
 * lam_r the row's largest lambda, so a particle that softens a little beside the band
 * counts a little (mpm_band_step has what that charges).
 *
 * Le = zone counts in S only the particles near the row's lead (the particle with the
 * row's largest lambda, as of the last step): those within 2 h + dx of it in x0, whose
 * uGIMP supports (half-width h + dx / 2) touch the lead's.  Before the band localizes
 * the whole bar is near its strength and particles far along the row soften by
 * 0.001-0.03 and stop; with `row` they count in S and the band's own particles are
 * charged less (the low bias, docs/findings.md); a particle that cannot
 * share a node with the lead cannot be part of the lead's zone.  No constant: h, dx and
 * the shape's support.
 *
 * Threads: each strip sums its particles' dlambda per row in particle order and keeps
 * its row's largest lambda with the first particle (in list order) that reached it;
 * the rows are reduced in strip order after the gather, a later strip's lead taking
 * over only with a strictly larger lambda, so any thread count gives the same bits.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpm.h"
#include "mpm_kernel.h"

mpm_band *mpm_band_alloc(int nrow, int nstrip, double dy, double wlen, double le0, double reach)
{
  mpm_band *b = calloc(1, sizeof *b);
  if (!b)
    return NULL;
  b->nrow = nrow;
  b->nstrip = nstrip;
  b->idy = 1.0 / dy;
  b->wlen = wlen;
  b->le0 = le0;
  b->acc = calloc((size_t)nrow * (size_t)nstrip * 3, sizeof *b->acc);
  b->xl = calloc((size_t)nrow, sizeof *b->xl);
  b->reach = reach;
  b->lam = calloc((size_t)nrow, sizeof *b->lam);
  b->sum = calloc((size_t)nrow, sizeof *b->sum);
  if (!b->acc || !b->lam || !b->sum || !b->xl) {
    mpm_band_free(b);
    return NULL;
  }
  return b;
}

void mpm_band_free(mpm_band *b)
{
  if (!b)
    return;
  free(b->acc);
  free(b->lam);
  free(b->sum);
  free(b->xl);
  free(b);
}

/* After the step's gather (strips reduced in order): the row's lead moves to the particle
 * that passed the row's largest lambda so far; the row's crack state lam_r is the
 * largest min(lambda, 1) of its particles (1 once one has separated), S the sum of
 * every dlambda its particles have softened, and the next step's Le (mpm_band_le) is
 * k wlen with k = S / lam_r, the number of particles the zone holds, each counted by its share of
 * the leader's lambda.  The row then dissipates U0 (dy / |sin a|) lam_r dS / S: its
 * crack's increment while the zone keeps its shape; a particle that stops softening
 * beside the band still widens the measured zone, so the band's own particles are then
 * charged less (fig7 h 2, 1 ppc: 0.77-1.00 of a row's crack, 0.92 over the bar). */
void mpm_band_step(mpm_band *b)
{
  const size_t nr = (size_t)b->nrow;
  for (size_t j = 0; j < nr; j++) {
    double sum = 0.0, mx = 0.0, xm = 0.0;
    for (int q = 0; q < b->nstrip; q++) {
      const double *a = b->acc + 3 * ((size_t)q * nr + j);
      sum += a[0];
      if (a[1] > mx) {
        mx = a[1];
        xm = a[2];
      }
    }
    if (mx > b->lam[j])
      b->xl[j] = xm;
    b->lam[j] = fmax(b->lam[j], mx);
    b->sum[j] += sum;
  }
  memset(b->acc, 0, 3 * nr * (size_t)b->nstrip * sizeof *b->acc);
}
