/*
 * mpm_scheme_usl.c - update-stress-last, the paper's (sec. 2, eqs. 2-7): the node update,
 * then one gather that moves the particles, adds the FLIP increment to their velocities
 * and takes the strain from v^L.
 */
#include "mpm_kernel.h"
#include "mpm_phase.h"

static mpm_status usl_gather(mpm_sim *s, char *err, size_t errlen)
{
  return mpm_phase_g2p(s, MPM_G2P_USL, 1.0, err, errlen);
}

const mpm_scheme_type mpm_scheme_usl = {"usl", 1.0, 0.0, mpm_phase_none, usl_gather};
