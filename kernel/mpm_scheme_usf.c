/*
 * mpm_scheme_usf.c - update-stress-first (Bardenhagen 2002): the strain from the
 * projected v_i, the stress updated, the forces of the new stress scattered, then the
 * node update and a gather that only moves the particles.
 */
#include "mpm_kernel.h"
#include "mpm_phase.h"

static mpm_status usf_gather(mpm_sim *s, char *err, size_t errlen)
{
  return mpm_phase_g2p(s, MPM_G2P_MOVE, 1.0, err, errlen);
}

const mpm_scheme_type mpm_scheme_usf = {"usf", 0.0, 1.0, mpm_phase_strain_first, usf_gather};
