/*
 * mpm_phase.h - the explicit step as named phases (mpm_step.c), private to kernel/.
 *
 * A scheme (time.scheme) is a const mpm_scheme_type in its own file (mpm_scheme_*.c),
 * one row of mpm_schemes[] (mpm_scheme.c): what it does between the scatter and the
 * node update, how it gathers, and its ledger weight.  Optional physics (two fields, the
 * interface, damping, the band's Le, the stretched grid and laid weights) is an
 * mpm_hook: what it does at each phase, NULL where it does nothing.  mpm_step_setup
 * picks the scheme, the hooks and the gather's loops once, in mpm_sim_alloc; the step
 * then walks them with no test of a method option.
 */
#ifndef DELAM_MPM_PHASE_H
#define DELAM_MPM_PHASE_H

#include "mpm_kernel.h"

typedef struct mpm_scheme_type {
  const char *name;  /* the scene's time.scheme word                                    */
  double bfac;       /* share of the strain taken from v^L after the node update: the
                        ledger's B (mpm_nodes.c; USL 1, USAVG 1/2, MUSL and USF 0)     */
  double start_frac; /* share taken from the projected v_i before the forces (USF 1,
                        USAVG 1/2; 0: none)                                           */
  /* between the first scatter and the node update (mpm_phase_none: nothing) */
  mpm_status (*before_nodes)(mpm_sim *s, char *err, size_t errlen);
  /* after the node update: the gather (eqs. 5-7 and the constitutive update) */
  mpm_status (*gather)(mpm_sim *s, char *err, size_t errlen);
} mpm_scheme_type;

/* The schemes, indexed by mpm_scene.scheme. */
extern const mpm_scheme_type *const mpm_schemes[];
extern const int mpm_nschemes;

/* Where optional physics acts in a step, in the step's order. */
enum {
  MPM_PH_LAY = 0, /* the grid laid for the step (before the sort)                        */
  MPM_PH_MARK,    /* the grid zeroed, before each scatter                                */
  MPM_PH_START,   /* after the projected velocities (schemes with start_frac > 0)        */
  MPM_PH_GRID,    /* after the node update (eq. 4), in field, interface, damping order   */
  MPM_PH_MUSL,    /* after MUSL's re-projection                                          */
  MPM_PH_GATHER,  /* after the gather, before the rigid head                             */
  MPM_PH_END,     /* after the rigid head, before the ledger                             */
  MPM_PH_N
};
typedef void (*mpm_hook_fn)(mpm_sim *s);
typedef struct {
  const char *name;
  mpm_hook_fn at[MPM_PH_N];
} mpm_hook;

/* The hooks of the physics modules (each in its own file). */
extern const mpm_hook mpm_hook_fields, mpm_hook_iface, mpm_hook_damping, mpm_hook_band, mpm_hook_stretch,
    mpm_hook_laid;

/* The gather passes (mpm_step.c): move the particles and take v += d (MOVE), the
 * strain from v^L as well (USL), the strain alone from lanes fx, fy (STRAIN_F), both
 * moves and the strain from lanes fx, fy with v already updated (MUSL). */
enum { MPM_G2P_USL = 0, MPM_G2P_MUSL, MPM_G2P_STRAIN_F, MPM_G2P_MOVE, MPM_G2P_N };
typedef struct g2p_acc g2p_acc;
typedef void (*mpm_g2p_fn)(mpm_sim *s, int q, double frac, mpm_defer *d, mpm_dwork *dw, g2p_acc *acc);
typedef double (*mpm_flush_fn)(const mpm_sim *s, int q, mpm_particles *p, mpm_defer *d, mpm_dwork *dw,
                               g2p_acc *acc);

#define MPM_HOOK_MAX 4
/* What mpm_step_setup chose. */
struct mpm_phases {
  mpm_hook_fn fn[MPM_PH_N][MPM_HOOK_MAX];
  int n[MPM_PH_N];
  mpm_g2p_fn g2p[2][MPM_G2P_N]; /* [1]: the loops with the two-field test, once nodes are split */
  int split;                    /* 1 while the fields have split nodes (set by their MARK hook) */
  mpm_flush_fn flush;           /* the full constitutive update of a chunk's deferred particles */
  double tmark;                 /* the clock at the last phase's end (time_split)                */
};

/* Picks the scheme, the hooks and the gather's loops for s (mpm_sim_alloc). */
mpm_status mpm_step_setup(mpm_sim *s);

/* Runs the hooks of phase ph. */
static inline void mpm_phase_hooks(mpm_sim *s, int ph)
{
  const struct mpm_phases *P = s->ph;
  for (int i = 0; i < P->n[ph]; i++)
    P->fn[ph][i](s);
}

/* The phases a scheme is made of (mpm_step.c).  Each adds its time to time_split. */
mpm_status mpm_phase_none(mpm_sim *s, char *err, size_t errlen);
/* the scatter of eqs. 2-3 (into a zeroed grid, the MARK hooks first) */
mpm_status mpm_phase_p2g(mpm_sim *s, char *err, size_t errlen);
/* a gather pass over all strips; frac: the share of the step's strain increment */
mpm_status mpm_phase_g2p(mpm_sim *s, int pass, double frac, char *err, size_t errlen);
/* the strain first, start_frac of it from the projected v_i, then the forces of the new
 * stress (USF, USAVG) */
mpm_status mpm_phase_strain_first(mpm_sim *s, char *err, size_t errlen);
/* adds the time since the last phase ended to time_split[which] */
void mpm_phase_time(mpm_sim *s, int which);

#endif
