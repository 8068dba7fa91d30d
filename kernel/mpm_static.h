/*
 * mpm_static.h - private to kernel/: the parts of the quasi-static solver: the control
 * and the increments (mpm_static.c), the particles' stencils, trial state and the
 * tangent's assembly (mpm_static_asm.c), the sparse linear solve (mpm_static_lin.c), the
 * cohesive interface's line (mpm_static_iface.c) and the manufactured solution
 * (mpm_static_mms.c).
 */
#ifndef DELAM_MPM_STATIC_H
#define DELAM_MPM_STATIC_H

#include "mpm_kernel.h"

/* ---- the sparse system over the free degrees of freedom (GSL's band or KLU) ---- */
typedef struct mpm_lin mpm_lin;
/* The pattern from triplets (ti, tj) of n x n; map[k] receives the position of triplet k
 * in the compressed values (duplicates share one).  NULL when out of memory. */
mpm_lin *mpm_lin_alloc(int n, size_t nz, const int *ti, const int *tj, int *map);
void mpm_lin_free(mpm_lin *l);
double *mpm_lin_values(mpm_lin *l); /* the values to assemble into, nnz of them */
size_t mpm_lin_nnz(const mpm_lin *l);
/* LU of the values (the pattern's ordering is computed once); MPM_ENOTFINITE when the
 * matrix is singular or not finite. */
mpm_status mpm_lin_factor(mpm_lin *l);
/* 1 if the last factorization was a low-rank update of the held base's factors. */
int mpm_lin_updated(const mpm_lin *l);
/* Adds the factorizations and low-rank updates done since the last call to *fact, *upd. */
void mpm_lin_counts(mpm_lin *l, long *fact, long *upd);
/* 1 if the factors held are of the values as they are now (bit for bit). */
int mpm_lin_same(const mpm_lin *l);
/* x = A^-1 b with the last factors; x and b may not alias. */
mpm_status mpm_lin_solve(mpm_lin *l, const double *b, double *x);
/* The sign of the last factors' determinant (+1, -1; 0: none held). */
int mpm_lin_det_sign(const mpm_lin *l);

/* ---- a bar particle's stencil at its reference place (total Lagrangian) ---- */
#define MPM_ST_MAX 9 /* uGIMP: 3 x 3 nodes */

/* Degrees of freedom: each node's x and y; eq >= 0 is the unknown's row, else the
 * component is held (MPM_DOF_*) or the node carries no particle. */
/* GRIP: held at c delta with c < 0 (the bar's grip pulls back), PUSH: c > 0; every
 * driven component of a specimen has the same |c| (mpm_static_number checks it), so
 * the sums of the load and of d R / d delta take +-f and are scaled by |c| once. */
enum { MPM_DOF_OFF = -1, MPM_DOF_GRIP = -2, MPM_DOF_HELD = -3, MPM_DOF_PUSH = -4 };

struct mpm_static {
  mpm_sim *s;             /* borrowed: scene, materials, particles, grid, loads, energies */
  size_t np;              /* bar particles (the head is the explicit run's machine)      */
  size_t *pid;            /* their indices in s->p                                      */
  int *cnt;               /* stencil nodes per particle (those with a weight or gradient) */
  int *node;              /* np x MPM_ST_MAX node indices                                */
  double *N, *Gx, *Gy;    /* np x MPM_ST_MAX weights and gradients at the reference place */
  size_t nn;              /* grid nodes                                                 */
  size_t nslot;           /* displacement slots: a node's, and with the interface a second
                             one (nn + node) for the particles on the line's far side where
                             the node is split; node[] holds slots                      */
  int *eq;                /* 2 nslot: the unknown of each component, or MPM_DOF_*         */
  double *held;           /* 2 nslot: the value of a held component (MPM_DOF_HELD)        */
  double *coef;           /* 2 nslot: a driven component's value per unit delta, c       */
  double *fext;           /* 2 nslot: an external force on each component, in R as -fext
                             (NULL: none; the manufactured solution's body force)       */
  double cmag;            /* |c| of every driven component                               */
  int drv2;               /* 1: a driven component other than x at c < 0 (driven_load)   */
  int nfree;              /* unknowns                                                   */
  int pinned;             /* 1 once the cut part's vertical rigid motion is held          */
  int *map;               /* per particle, (2 MPM_ST_MAX)^2 positions in the values, -1 off */
  mpm_lin *lin;
  double *Kel, *kfdel;    /* the tangent's elastic part and its d R / d delta (every particle's C) */
  int kel_ok;             /* 1: Kel and kfdel are of the current numbering              */
  /* displacements: committed (Un) and trial (Ut), 2 nslot each; the grip's delta */
  double *Un, *Ut;
  double dn, dt;
  double dlast;           /* the last increment's change of delta                       */
  /* vectors over the unknowns */
  double *R, *kfd, *ga, *x1, *x2, *du;
  double gb;              /* d Ct / d delta through the driven components                */
  /* the particles' trial state (np each) and what the increment booked */
  mpm_dstate *tst;        /* each particle's state after the update                      */
  double *tw;             /* ... the traction work it booked                             */
  uint8_t *tpath;         /* ... and the update's path (MPM_DPATH_*)                    */
  mpm_dwork *dw;
  /* loads and dissipation of the trial state */
  double Pg, Pf, Dt, Dn;
  double Ct, Cn;          /* the control's measure: sum U0 lambda V / Le, lambda uncapped  */
  /* the control: MPM_QS_* mode, the grip step or the dissipation step */
  int mode;
  double step_d, step_D, Dref, Fref;
  double Dmax;            /* the largest dissipation increment (the specimen's)         */
  double Wmax;            /* the largest external work so far (the ledger's scale)       */
  int kick;               /* 1: one small grip increment starts the softening            */
  double cring[100];      /* the control's measure over the last increments (stalls)     */
  int nkick;              /* such increments in a row                                   */
  double kick_d;          /* its grip step                                              */
  double pk_d;             /* delta at the largest load so far                          */
  double ch_d, ch_P;      /* the last increment's chord over (pk_d, the peak load)       */
  int nel;                /* equal grip increments left before the first initiation      */
  int have_eval;          /* the last evaluation is of the committed state               */
  int have_pred;          /* pdir, pden are the committed state's                        */
  double *pdir;           /* d u / d delta at the committed state (unknowns)             */
  double pden;            /* d C / d delta along pdir                                    */
  int wsign, xsign, wdir; /* at the last state with det K's sign: it, det K pden's, delta's way */
  int wtie;               /* a tie's states since it (their sign is rounding's)            */
  long tie;               /* particles tied at the first initiation (> ppc: a uniform state) */
  mpm_static_stats st;
  /* decohesion.path = interface (mpm_static_iface.c): the line's law between the two
   * copies of each split node, as a stiff elastic tie until it initiates */
  int iface;
  uint8_t *split;         /* nn: 1 where a node has the far side's second slot            */
  int *snode;             /* their node indices                                        */
  double *sA;             /* their weights A = max(a_0 . n, 0), a_0 the near side's sum of
                             V grad N (the force of a uniform stress: sigma a_0)        */
  int *sseg;              /* their segment                                             */
  int nseg, npair;        /* segments of the line (npair: the same, for the law's loops) */
  int *segstart, *sorder; /* split nodes of segment g: sorder[segstart[g] .. segstart[g+1]) */
  double *sT;             /* the split nodes' tie weights T = max(A, half a particle's side) */
  double *pA;             /* per segment: sum of its nodes' A                           */
  double *pT;             /* ... and of their T                                         */
  mpm_dstate *pst, *ptr;  /* the law's committed and trial state per segment            */
  double *pw;             /* trial: the law's work this increment, times pA             */
  size_t *kseg;           /* where each segment's entries start in map                   */
  double *segx;           /* per segment: x of its first node                           */
  double *pD;             /* ... the area its dissipation counts (pA; 0 on a pre-crack)   */
  uint8_t *spre;          /* per segment: 1 on the pre-crack (open from the start)       */
  mpm_material imat;      /* the line's law parameters (mpm_law.h): E1 = G = k0, Le 1, frame */
};

/* mpm_static_iface.c */
mpm_status mpm_static_iface_setup(mpm_static *q, char *err, size_t errlen);
void mpm_static_iface_eval(mpm_static *q, int tangent, double *Ax, double *D, double *C);
void mpm_static_iface_commit(mpm_static *q);
int mpm_static_iface_sever(mpm_static *q); /* the unseparated segments let go in place */
/* One segment's step of the line's law returned along the flow at the step's end, for a
 * jump increment w (x, y); the tangent S = d t / d w and gl = d lambda / d w; 0 where the
 * segment is separated or separates in the step (the law's separation takes those). */
int mpm_static_seg_law(const mpm_material *m, const mpm_dstate *in, const double w[2], mpm_dstate *out, double *work,
                       double S[2][2], double gl[2]);
/* the segments' entries of the tangent's pattern from map position k; returns the next */
size_t mpm_static_iface_pattern(mpm_static *q, int *ti, int *tj, size_t k, size_t *m);
size_t mpm_static_iface_nz(const mpm_static *q); /* how many entries that is            */
void mpm_static_iface_free(mpm_static *q);
/* The line's pieces for pictures (mpm.h mpm_iface_pieces): one per segment of a line
 * along x (the split beams), the segment's node share, its lambda and state (0 stuck,
 * 1 softening, 2 open: separated or a pre-crack); 0 pieces on an inclined line. */
int mpm_static_iface_npieces(const mpm_static *q);
int mpm_static_iface_piece(const mpm_static *q, int i, double xy[4], double *lam, int *state);

/* mpm_static.c: Newton's method on one increment under the current control (1 converged,
 * the trial state the increment's; 0 not; -2 the dissipation cannot lead: nothing
 * softens), the committed state's tangent and predictor, the trial state committed.  The
 * path control that calls them: mpm_static_path.c (mpm_static_step). */
#define MPM_QS_CMIN 1e-12 /* of U0 H / sin a: less dissipated is nothing (rounding)     */
#define MPM_QS_NEL 8      /* equal increments of the linear branch up to the first initiation */
#define MPM_QS_MAXIT 25   /* Newton iterations an increment may take                */
int mpm_static_increment(mpm_static *q, int *iters);
mpm_status mpm_static_predict(mpm_static *q);
void mpm_static_commit(mpm_static *q);

/* mpm_static_asm.c: the stencils and unknowns (setup), the trial state of every particle
 * from Ut with the residual, tangent and the dissipation's gradient (eval). */
mpm_status mpm_static_setup(mpm_static *q, char *err, size_t errlen);
mpm_status mpm_static_number(mpm_static *q, char *err, size_t errlen);
mpm_status mpm_static_eval(mpm_static *q, int tangent);

#endif
