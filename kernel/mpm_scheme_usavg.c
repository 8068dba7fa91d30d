/*
 * mpm_scheme_usavg.c - update-stress-average (Nairn 2003): half the strain increment as
 * USF before the forces, half as USL after them.
 */
#include "mpm_kernel.h"
#include "mpm_phase.h"

static mpm_status usavg_gather(mpm_sim *s, char *err, size_t errlen)
{
  return mpm_phase_g2p(s, MPM_G2P_USL, 0.5, err, errlen);
}

const mpm_scheme_type mpm_scheme_usavg = {"usavg", 0.5, 0.5, mpm_phase_strain_first, usavg_gather};
