/*
 * mpm_scheme_usthird.c - an experimental scheme: a third of the strain increment as USF
 * before the forces, two thirds as USL after them (USAVG with unequal shares).
 */
#include "mpm_phase.h"

static mpm_status usthird_gather(mpm_sim *s, char *err, size_t errlen)
{
  return mpm_phase_g2p(s, MPM_G2P_USL, 2.0 / 3.0, err, errlen);
}

const mpm_scheme_type mpm_scheme_usthird = {"usthird", 2.0 / 3.0, 1.0 / 3.0, mpm_phase_strain_first, usthird_gather};
