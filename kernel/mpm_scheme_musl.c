/*
 * mpm_scheme_musl.c - modified USL: after the node update the particles' velocities are
 * updated and projected to the grid again, v'_i = sum m_p v_p N_ip / m_i (constraints
 * applied), and the strain is taken from v'.  v'_i is a weighted mean of particle
 * velocities, so a node that a particle barely touches (tiny m_i, finite f_i) cannot
 * inject a huge strain: the cell-crossing instability of USL.
 */
#include "mpm_kernel.h"
#include "mpm_nodes.h"
#include "mpm_phase.h"
#include "mpm_scatter.h"

static mpm_status musl_gather(mpm_sim *s, char *err, size_t errlen)
{
  mpm_scatter(s, 1); /* timed with the gather, as its first half */
  mpm_nodes_musl_velocity(s);
  mpm_phase_hooks(s, MPM_PH_MUSL);
  mpm_phase_time(s, MPM_T_G2P);
  return mpm_phase_g2p(s, MPM_G2P_MUSL, 1.0, err, errlen);
}

const mpm_scheme_type mpm_scheme_musl = {"musl", 0.0, 0.0, mpm_phase_none, musl_gather};
