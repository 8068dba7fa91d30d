/*
 * mpm_nodes.h - the node pass of the step (mpm_nodes.c), called by mpm_step.c.  Private
 * to kernel/.
 */
#ifndef DELAM_MPM_NODES_H
#define DELAM_MPM_NODES_H

#include "mpm_kernel.h"

/* 1 where grid.node_mass = limited acts (usl, usavg; bilinear shapes): the scatter then
 * sums each node's sum_p V_p (|Gx_ip| + |Gy_ip|) into lane qx. */
int mpm_nodes_limit_on(const mpm_sim *s);
/* eq. 4 and the reactions: after it lanes (px, py) hold v^L and (fx, fy) the FLIP
 * increment; the ledger takes the scheme's share bfac of the strain from v^L. */
void mpm_nodes_update(mpm_sim *s);
/* USF, USAVG: the projected v_i with the constraints into (fx, fy), before the forces. */
void mpm_nodes_start_velocity(mpm_sim *s, double frac);
/* MUSL: v' = q / m with the constraints into (fx, fy). */
void mpm_nodes_musl_velocity(mpm_sim *s);

#endif
