/*
 * mpm_band.c - Le measured from the band itself (decohesion.Le = row or zone): the
 * effective length of eq. 41, Le = V_e / A_d, per particle row of the bar from the
 * particles that soften in it, instead of from the cell.
 *
 * A straight crack crosses each particle row (height dy) over dy / |sin a|; k particles
 * of width dx softening together in the row make a zone of volume k dx |sin a| per unit
 * crack length: the row's Le.  k = S / lam_r, S the sum of every dlambda the row's
 * particles have softened and lam_r the row's largest lambda.  zone counts in S only the
 * particles within 2 h + dx (in x0) of the row's lead (largest lambda), whose uGIMP
 * supports touch the lead's.  What row and zone gave: docs/findings.md, "The band method".
 * Threads: per strip sums in particle order, rows reduced in strip order (a later
 * strip's lead wins only with a strictly larger lambda): the same bits for any count.
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
