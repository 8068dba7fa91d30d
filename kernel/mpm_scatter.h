/*
 * mpm_scatter.h - the step's particle-to-grid passes (mpm_scatter.c).  Private to
 * kernel/.
 */
#ifndef DELAM_MPM_SCATTER_H
#define DELAM_MPM_SCATTER_H

#include "mpm_kernel.h"

/* Scatter over the strips, colour by colour.  which = 0: eqs. 2-3 into the zeroed grid
 * (1 if a particle is outside it); which = 1: MUSL's updated velocities (eq. 6 from the
 * FLIP increment) and their momentum into lanes (qx, qy). */
int mpm_scatter(mpm_sim *s, int which);

#endif
