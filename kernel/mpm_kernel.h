/*
 * mpm_kernel.h - what the kernel's files share and no caller needs (private to kernel/;
 * the kernel's tests include it to drive its parts alone): the method options' meaning,
 * materials, the pure constitutive update, particles, grid, the energy ledger, the
 * thread count, struct mpm_sim; the band's rows, damping, the grip's control, the sort
 * and the cut.
 */
#ifndef DELAM_MPM_KERNEL_H
#define DELAM_MPM_KERNEL_H

#include <time.h>

#include "mpm.h"

#define MPM_PI 3.14159265358979323846

/* The failure plane at the scene's angle (decohesion.alpha; eq. 28): a in radians, the
 * normal n = (sin a, -cos a) and the direction t = (cos a, sin a).  The one conversion of
 * alpha (mpm_sim.c); a sim keeps its plane (mpm_sim.plane). */
typedef struct {
  double a, nx, ny, tx, ty;
} mpm_plane;
mpm_plane mpm_plane_of(const mpm_scene *sc);

/* ---- The method options, as the kernel reads them (the enums: mpm.h; the keys:
 * docs/scene-keys.md) ---- */
/* decohesion.Le, the effective length V_e / A_d of eq. 41 (docs/model.md sec. 6): CELL,
 * the paper's h max(|sin a|, |cos a|), exact for a band one cell wide per row; PARTICLE,
 * the same for the particle's square; STAIRCASE, h (|sin a| + |cos a|), the width of the
 * narrowest band of cells that can open along an inclined line (mpm_sim.c). */

/* time.scheme. USL: strain from v^L (the paper, eq. 7). MUSL: strain from the nodal
 * velocity re-projected from the updated particle velocities, which keeps nearly empty
 * nodes (tiny m_i, finite f_i) from injecting huge strain increments. USF: the stress is
 * updated first, from the projected nodal velocity v_i, and the nodal forces come from
 * the new stress (Bardenhagen 2002). USAVG: half the strain increment as USF before the
 * forces, half as USL after them (Nairn 2003). mpm_step.c has the energy of each. */

/* grid.bc: how a held node enters the FLIP update (eq. 6), mpm_nodes.c mpm_nodes_update.
 * LAGRANGIAN: the constraint is set on v^L only, so the increment at a held node is
 *   v_bc - v_i, with v_i the projected velocity: it pulls the particles there toward the
 *   held velocity every step (a damper: mpm_ledger.L_bc).
 * BOTH: set on v_i and v^L, increment 0, but the reaction still the one of the jump
 *   from the projected v_i: the particles do not receive the impulse the load reports.
 * CONSISTENT: the increment at a held node is the change of the held velocity (0 at a
 *   constant grip speed) and the reaction is what the particles then receive,
 *   R = m dv_bc / dt - f_i: no energy leaves through the constraint but its work. */

/* loading.head: RIGID is the paper's rigid head (MPM_MAT_HEAD); NONE grips the node
 * column x = 0 alone (no head particles: the free-vibration scene). */

/* loading.control, what the grip follows (mpm_control.c): GRIP, the paper's constant
 * speed; DISSIPATION, from the first softening until the band has cut the bar, a
 * dissipation that grows at speed x (the peak load so far), the grip moving back where
 * the bar's curve snaps back (as a test machine under crack-opening control follows a
 * snapback). */

/* grid.motion. The background grid is discarded every step (sec. 2), so it may be laid
 * anywhere. STRETCH lays it along the bar's mean stretch, x_i = L + (X_i - L)(1 + delta
 * / L): the gripped and fixed node columns stay on the bar's ends and no particle
 * crosses them while the bar is loaded. FIXED (default) is the paper's fixed grid, where
 * the first particle column crossing the gripped node line (delta = h / (2 sqrt ppc))
 * meets MPM's cell-crossing force error and, before separation, fails the gripped end.
 * Measured cost of STRETCH with one particle per cell: fig6 h 1 energy residual 2.6 %
 * (USL; fixed 0.02 %), D doubled under MUSL; so only fig6.ini, run at 4 and 9 ppc on
 * fine grids, uses it. */

/* grid.weights: where a particle's shape functions are taken. CURRENT (default, the
 * paper's) at its position. LAID (grid.motion = stretch only, until the bar is cut) at
 * the place the grid was laid at, carried by the grid's stretch: x = L + (X - L)(1 +
 * delta / L), y = Y, so a particle keeps its place among the nodes while the bar is one
 * body and its motion relative to the grid (the halves unloading in the softening, some
 * 0.04 h) never moves a uGIMP box across a node. Such a move, under a stress, changes
 * the nodal forces the way no strain energy does, and MUSL, which damps no wave, grows a
 * grid-scale wave from it (analytic/ana_stab.c; docs/findings.md). The particles still
 * move: the step adds each one's offset from its laid place back when it ends, so
 * output, energies and the next step see where it is. */

/* grid.shape: LINEAR, the paper's bilinear hats (2 x 2 nodes a particle); GIMP,
 * uGIMP (Bardenhagen and Kober 2004; 3 x 3 nodes), continuous as a particle crosses a
 * cell edge (mpm_shape.h). */

/* grid.fields, velocity fields per node: ONE, the paper's; TWO, a second field at the
 * nodes next to a separated band, one per side of it (mpm_fields.c). */

/* grid.node_mass: how a node's v^L takes its acceleration (eq. 4) where the strain is
 * taken from v^L (usl, usavg) on bilinear shapes.  LUMPED (the paper): v^L = v + dt f / m
 * at every node.  LIMITED: a node whose stiffness-to-mass bound exceeds what the step
 * can integrate takes the acceleration with a mass floor in v^L (mpm_step.c, "Nodal
 * mass limit"); the particles' velocity increment keeps the lumped mass. */

/* imperfection.size: PARTICLE, the paper's particle nearest (imp_x, imp_y); CELL, every
 * particle of that particle's cell, so that the flaw is one cell at any ppc (the paper's
 * flaw at its one particle per cell). */

/* time.damping_from (mpm_damping.c): the damping acts from the first step (START) or once
 * the band has cut the bar (CUT). */

/* time.damping_about (mpm_damping.c): after the cut the damping takes each velocity about
 * its node's slow drift (DRIFT, a low-pass) or about the motion of the end that holds the
 * part of the bar its particle belongs to (PARTS: the parts the cut made). */

/* decohesion.path: where the bar may soften.  FREE (the paper): every particle.  LINE:
 * only the particles whose reference centre lies within h (|sin a| + |cos a|) / 2 +
 * path_reach h of the failure line through the imperfection (the cells that line
 * crosses, widened by path_reach cells); the others are elastic (MPM_MAT_ELASTIC).  A
 * laminate delaminates along its ply interface: the crack's path is the plane at alpha
 * through where it starts (docs/findings.md).  IFACE: no particle softens; the
 * line is a cohesive interface between two velocity fields (mpm_iface.c,
 * docs/findings.md). */

/* decohesion.reversed_shear: shear on the failure plane against a particle's accumulated
 * tangential jump (s_nt upt < 0). EVEN (the paper): eq. 23 is even in s_nt, so it
 * softens the particle as shear the other way does. CLOSING: it closes the slip
 * elastically and neither starts nor drives decohesion, as <sn> keeps normal compression
 * out of eq. 23 (mpm_decohesion.c; docs/findings.md). */

/* decohesion.share (path = interface): how a softening segment's traction is shared
 * among its nodes (mpm_iface.c). STICK: each node's own stick impulse, scaled by the
 * segment's factor. LINE: the segment's traction times the node's length of line An (the
 * consistent nodal force of a traction on the line), never more than sticks the node;
 * built for a line along a node column that the grid follows (alpha 90, grid.motion =
 * stretch; the crack on a node column, mpm_sim.c), docs/findings.md. */

/* ---- material ---- */
typedef struct {
  double E, nu, rho;     /* elastic constants                                          */
  double E1, E2, G;      /* plane stress: E/(1-nu^2), nu E/(1-nu^2), E/(2(1+nu))       */
  int model;             /* MPM_DCOH_*                                                 */
  double nx, ny, tx, ty; /* failure-plane normal n = (sin a, -cos a), tangent t = (cos a, sin a) */
  double snf, stf;       /* failure tractions (eq. 23)                                 */
  double U0, s0, q;      /* eq. 19-20                                                  */
  double ubar0;          /* U0 / s0                                                    */
  double irho;           /* 1 / rho (the ledger's V = m / rho)                         */
  double mp;             /* the mass of each of its particles (mpm_sim.c: one lattice),
                            so that the gather's ledger sums need not read p->m         */
  double Le;             /* effective length V_e / A_d (eq. 41), fixed for the run     */
  double sep_threshold;  /* eqs. 56-58 take over when lambda would pass this           */
  double visc;           /* decohesion.eta / dt: overstress per unit dlambda in a step (0: none) */
  int shear_closing;     /* decohesion.reversed_shear = closing: shear against the particle's
                            slip upt leaves eq. 23 (mpm_decohesion.c)                  */
  /* derived (mpm_material_derive), so that the hot paths multiply instead of divide */
  double isnf, istf;     /* 1 / snf, 1 / stf                                            */
  double isnf2, istf2;   /* 1 / snf^2, 1 / stf^2                                        */
  double kL;             /* ubar0 / Le                                                 */
  double Lopen;          /* the length eqs. 57-58 turn a separated particle's strain into its
                            opening with: Le, except under decohesion.Le = row (mpm_band.c),
                            where the softening's Le is the row's and this the staircase's */
  double rnn[3], rtt[3], rnt[3]; /* (s_nn, s_tt, s_nt) = r . (sxx, syy, sxy)             */
  double fn[3], ft[3];   /* s_nn / snf and s_nt / stf as dot products with (sxx, syy, sxy):
                            the step's elastic test (all 0 when model = NONE)          */
} mpm_material;

void mpm_material_init(mpm_material *m, const mpm_scene *sc, double snf, double Le);
/* Recomputes the derived constants after model, snf, stf, ubar0 or Le changed. */
void mpm_material_derive(mpm_material *m);

/* ---- the pure constitutive update (secs. 4.1-4.3) ---- */
typedef struct {
  double sxx, syy, sxy;  /* Cauchy stress                                              */
  double lam;            /* decohesion parameter lambda (monotone; 1 at separation, may pass 1 after) */
  double upn, upt;       /* displacement jump across the failure plane, n and t components */
  int sep;               /* 1 once separated: no traction across the plane             */
} mpm_dstate;

/* How a step went, for tests and counters. */
enum { MPM_DPATH_ELASTIC = 0, MPM_DPATH_SOFTEN = 1, MPM_DPATH_SEPARATE = 2, MPM_DPATH_OPEN = 3 };

typedef struct {
  int path;              /* MPM_DPATH_*                                                */
  int iters;             /* root-solver iterations (0 on an elastic step)              */
  int bracketed;         /* 1 if the bracketed (GSL Brent) solve was needed            */
  double w;              /* traction work per unit failure area in this step, int s . d up */
} mpm_dinfo;

typedef struct mpm_dwork mpm_dwork;   /* scratch for the bracketed solve (GSL)          */
mpm_dwork *mpm_dwork_alloc(void);
void mpm_dwork_free(mpm_dwork *w);

/* Strain increment de = (dexx, deyy, dexy), tensor shear.  Pure: output depends only
 * on the arguments; w is scratch.  MPM_ENOTFINITE if the result is not finite. */
mpm_status mpm_dcoh_update(const mpm_material *m, const mpm_dstate *in, const double de[3],
                           mpm_dstate *out, mpm_dinfo *info, mpm_dwork *w);

/* The algorithmic (consistent) tangent of that update: D[i][j] = d sigma_out[i] / d de[j]
 * at the same (in, de), sigma = (sxx, syy, sxy), de = (dexx, deyy, dexy) with tensor shear
 * (elastic: D = [[E1, E2, 0], [E2, E1, 0], [0, 0, 2G]]).  Analytic, on the path the update
 * takes (a one-sided value exactly on a switch between paths); runs the update itself.
 * Pure like it; D is NaN and the update's status returned when that is not MPM_OK.
 * dlam (if not NULL) gets d lambda_out / d de on the same path (0 on an elastic step). */
mpm_status mpm_dcoh_tangent(const mpm_material *m, const mpm_dstate *in, const double de[3], double D[3][3],
                            double dlam[3], mpm_dwork *w);
/* Both in one: the update (out, info: mpm_dcoh_update's) and its tangent (D, dlam:
 * mpm_dcoh_tangent's) from one run of the update. */
mpm_status mpm_dcoh_update_tangent(const mpm_material *m, const mpm_dstate *in, const double de[3], mpm_dstate *out,
                                   mpm_dinfo *info, double D[3][3], double dlam[3], mpm_dwork *w);

/* The elastic trial of a step (eq. 7's increment through plane-stress C): the stress
 * (sxx, syy, sxy) plus C de, de = (de0, de1, de2) with tensor shear, into (txx, tyy,
 * txy); the first thing mpm_dcoh_update does, and the callers' before their test
 * (mpm_dcoh_trial_inside). */
static inline void mpm_dcoh_trial(const mpm_material *m, double sxx, double syy, double sxy, double de0, double de1,
                                  double de2, double *txx, double *tyy, double *txy)
{
  *txx = sxx + m->E1 * de0 + m->E2 * de1;
  *tyy = syy + m->E2 * de0 + m->E1 * de1;
  *txy = sxy + 2.0 * m->G * de2;
}

/* Plane-stress C (eq. 7's increment, tensor shear doubled): the tangent of an elastic
 * step, and the part of the algorithmic tangent every particle shares. */
static inline void mpm_dcoh_elastic(const mpm_material *m, double C[3][3])
{
  C[0][0] = C[1][1] = m->E1;
  C[0][1] = C[1][0] = m->E2;
  C[0][2] = C[1][2] = C[2][0] = C[2][1] = 0.0;
  C[2][2] = 2.0 * m->G;
}

/* The inline elastic test sends a particle to the full update from this fraction of
 * its remaining strength squared on (a rounding margin, far above 1 ulp). */
#define MPM_TRIAL_SAFE (1.0 - 1e-9)

/* 1 where the trial t stays inside eq. 23's surface by the margin, so that
 * mpm_dcoh_update would keep it (path ELASTIC, the trial's bits): <s_nn / snf>^2 +
 * (s_nt / stf)^2 < MPM_TRIAL_SAFE str2, str2 the particle's cached (1 - lambda^q)^2
 * (mpm_particles.str2; < 0 once separated: never).  A non-finite trial fails it (NaN * 0
 * is NaN); the state's own finiteness is the committed update's. */
static inline int mpm_dcoh_trial_inside(const mpm_material *m, const double t[3], double str2)
{
  const double sn = m->fn[0] * t[0] + m->fn[1] * t[1] + m->fn[2] * t[2], a = sn > 0.0 ? sn : 0.0;
  const double b = m->ft[0] * t[0] + m->ft[1] * t[1] + m->ft[2] * t[2];
  return a * a + b * b < MPM_TRIAL_SAFE * str2;
}

/* mpm_dcoh_update's softening step (eqs. 39-50) for n particles of one material with
 * q = 1, in one loop without branches on the data (the particles' chains of square roots
 * and divisions overlap): st[0..5] their sxx, syy, sxy, lambda, upn, upt, sep their flags,
 * de[0..2] their strain increments.  Where ok[i] = 1 particle i softened, its first Newton
 * iterate within tolerance and every output finite: st holds its new state and w[i] its
 * traction work, the same bits as mpm_dcoh_update's.  Elsewhere (ok[i] = 0, st untouched)
 * it needs mpm_dcoh_update. */
void mpm_dcoh_soften_batch(const mpm_material *m, size_t n, double *const st[6], const unsigned char *sep,
                           const double *const de[3], double *w, unsigned char *ok);

/* Remaining strength squared, (1 - lambda^q)^2 (eq. 23); -1 once separated
 * (mpm_particles.str2). */
double mpm_dcoh_str2(const mpm_material *m, double lam, int sep);

/* Decohesion function F = se - (1 - lambda^q) (eq. 23) at a stress state. */
double mpm_dcoh_F(const mpm_material *m, double sxx, double syy, double sxy, double lam);

/* ---- particles: structure of arrays ---- */
typedef struct {
  size_t n;                /* number of particles                                      */
  double *x, *y;           /* position                                                 */
  double *x0, *y0;         /* reference position (for displacements)                   */
  double *vx, *vy;         /* velocity                                                 */
  double *m, *V;           /* mass (constant) and volume (V = m / rho, small strain)   */
  double *sxx, *syy, *sxy; /* stress                                                   */
  double *lam;             /* decohesion parameter                                     */
  double *upn, *upt;       /* displacement jump, n and t components                    */
  double *wcoh;            /* traction work on the failure plane so far (energy)       */
  double *dis;             /* dissipation so far, U0 dlambda V / Le summed while lambda <= 1 */
  double *str2;            /* remaining strength squared, (1 - lambda^q)^2 (eq. 23), and -1
                              once separated: lets the step test F <= 0 without a pow
                              or a branch per particle                                 */
  uint8_t *mat;            /* index into the material table                            */
  uint8_t *sep;            /* 1 once separated                                         */
  double *vxx, *vyy, *vxy; /* time.damping_beta > 0: the viscous stress beta C : grad v of
                              the last strain pass, scattered with sigma (NULL otherwise) */
  double *wdx, *wdy;       /* grid.weights = laid: during a step, the particle's offset from
                              its laid place, added back when the step ends (NULL otherwise) */
} mpm_particles;

mpm_particles *mpm_particles_alloc(size_t n);
/* The viscous stress arrays of time.damping_beta, zeroed; 0, or -1 out of memory. */
int mpm_particles_alloc_viscous(mpm_particles *p);
/* The offsets of grid.weights = laid, zeroed; 0, or -1 out of memory. */
int mpm_particles_alloc_laid(mpm_particles *p);
void mpm_particles_free(mpm_particles *p);

/* ---- grid: a regular lattice of (ncx+1) x (ncy+1) nodes, origin (ox, oy), spacing h.
 * Nodes are stored column by column: node (i, j) is at i * nny + j, so the particles,
 * sorted by cell in the same order, walk the nodes forward.  A node is one 64-byte
 * record (a cache line): the scatter adds a particle's share of all five values with
 * one vector operation per node, and a gather reads them back the same way. ---- */
typedef struct {
  _Alignas(64) double m;   /* nodal mass                                               */
  double px, py;           /* momentum, then Lagrangian velocity v^L after the update  */
  double fx, fy;           /* internal force, then v^L - v after the update (MUSL: then v') */
  double qx, qy;           /* MUSL: momentum of the updated particle velocities        */
  double pad;              /* to 64 bytes; 0, except under two fields (mpm_fields.c):
                              mass times the displacement along the failure normal    */
} mpm_node;

typedef struct mpm_iface mpm_iface; /* decohesion.path = interface (mpm_iface.h) */

/* The second velocity field across a separated band (grid.fields = two): mpm_fields.h. */
typedef struct mpm_fields mpm_fields;

typedef struct {
  int ncx, ncy;            /* cells in x and y                                         */
  int nnx, nny;            /* nodes in x and y (ncx+1, ncy+1)                          */
  double ox, oy, h;        /* origin, and the spacing in y (and in x at t = 0)          */
  double hx;               /* spacing in x now (the grid may follow the bar's stretch) */
  double ihx, ihy;         /* 1 / hx, 1 / h                                            */
  mpm_node *nd;            /* the nodes, nnx * nny                                     */
  mpm_fields *fld;         /* the second velocity field, or NULL (grid.fields = 1)      */
  double body_now;         /* this step's body_amp sin(body_omega t), 0: no body force  */
  double body_k;           /* pi / L                                                   */
} mpm_grid;

mpm_grid *mpm_grid_alloc(int ncx, int ncy, double ox, double oy, double h);
static inline size_t mpm_grid_node(const mpm_grid *g, int i, int j)
{
  return (size_t)i * (size_t)g->nny + (size_t)j;
}
void mpm_grid_free(mpm_grid *g);

/* decohesion.Le = row: the rows' measured Le (mpm_kernel.h). */
typedef struct mpm_band mpm_band;

/* ---- threads: the count a step uses (mpm_threads.c) ---- */
#define MPM_THREADS_MIN_PARTICLES 16384 /* below: one thread, no measuring            */
#define MPM_PROBE_SHARE 0.02       /* most time a lost probe may cost                    */
#define MPM_PROBE_STEPS 16         /* steps timed on each count per probe              */
#define MPM_PERIOD_MIN 256         /* steps on the chosen count after a changed choice */
#define MPM_PERIOD_MAX 8192        /* ... doubled while it holds, up to this           */
enum { MPM_TPH_PROBE1 = 0, MPM_TPH_PROBEN, MPM_TPH_RUN };
typedef struct {
  int nmax;                /* threads allocated for (the most a step may use)           */
  int automatic;           /* 1: measure and choose between 1 and nmax                  */
  int use;                 /* threads of the next step                                 */
  int phase, np, last_pick, run_n, losses;
  long left, period;       /* steps left in the phase; length of the running stretch   */
  double last, mean1;      /* clock at the last tick; mean step on one thread (probe)  */
  double run_sum;          /* time of the current window of a stretch on many threads  */
  double probe_time;       /* time of the probe on many threads so far, and its steps  */
  long probe_n;
  double tp[MPM_PROBE_STEPS];
  long steps_multi;        /* steps run on more than one thread                        */
  long nprobe;             /* probes done                                              */
  long nfall;              /* falls back to one thread in a stretch                    */
  long nbusy;              /* probes skipped: no idle core (load average)              */
} mpm_threads;

/* The ledger's sums (mpm_step.c), accumulated step by step in a fixed order. */
typedef struct {
  double L_bc, L_flip, L_scheme, W_head, L_contact, L_debris, L_damp;
  double W_iface;          /* the interface's cohesive work so far (mpm_iface.c): in W_coh */
  double D_static;         /* the static solver's interface dissipation (mpm_static_iface.c): in D */
  double KE_head0;         /* the head's kinetic energy at the start                   */
  double head_reset;       /* kinetic energy the head's rigid projection removed so far */
  /* this step's held-node and serial sums (mpm_nodes.c, mpm_step.c; reset every step) */
  double s_A, s_K, s_B, s_Bheld, s_Bstart, s_H, s_Wtrue, s_Wbook;
  double s_C;              /* the contact's loss this step (mpm_fields.c)               */
  double s_I;              /* the interface's work this step (mpm_iface.c)             */
  double s_Dmp;            /* the damper's work this step (mpm_damping.c)               */
} mpm_ledger;

/* Per-strip partial sums of one step (fixed partition: the same sums for any thread
 * count).  Node terms: A = sum m v . d, K = sum m |d|^2, B = -dt sum f . u;
 * particle terms: KP = sum m |dv_p|^2, QS = sum m sigma_new : deps (mpm_step.c,
 * ledger_step); and D, the step's dissipation (sim.D_run, for mpm_control.c). */
enum { MPM_LED_A = 0, MPM_LED_K, MPM_LED_B, MPM_LED_KP, MPM_LED_QS, MPM_LED_D, MPM_LED_BV, MPM_LED_N };

/* ---- the simulation ---- */
/* Particles whose elastic trial left the elastic domain, waiting for the full
 * decohesion update (mpm_step.c): one list per thread, of at most MPM_DEFER particles
 * (a chunk of the gather), with each one's strain increment. */
#define MPM_DEFER 256
typedef struct {
  size_t n;
  size_t k[MPM_DEFER];
  double de[MPM_DEFER][3];
  /* the list as structure of arrays for mpm_dcoh_soften_batch */
  double bst[6][MPM_DEFER], bde[3][MPM_DEFER], bw[MPM_DEFER];
  unsigned char bsep[MPM_DEFER], bok[MPM_DEFER];
  /* a chunk's strain increments (de0, de1, g2), for the gather's elastic trial eight
   * particles at a time (mpm_step.c) */
  double tde[3][MPM_DEFER];
} mpm_defer;

struct mpm_sim {
  mpm_scene sc;            /* copy of the scene                                        */
  mpm_plane plane;         /* its failure plane (mpm_plane_of)                          */
  mpm_material mat[5];     /* MPM_MAT_BAR, MPM_MAT_IMP (the imperfection), MPM_MAT_HEAD,
                              MPM_MAT_DEBRIS, MPM_MAT_ELASTIC */
  size_t nhead;            /* particles of the rigid head (p->n - nhead are the bar's)  */
  uint32_t *head;          /* their indices, ascending (rebuilt by each sort)          */
  double head_dy;          /* the head's vertical displacement (it moves as one body)   */
  double grid_ox0;         /* the grid's x-origin at t = 0                              */
  mpm_particles *p;
  mpm_grid *g;
  const struct mpm_specimen_type *spec; /* the specimen's row (mpm_specimen.h), chosen once */
  struct mpm_bc *bc;       /* the constrained node components (mpm_specimen.h), in the   */
  int nbc;                 /*   order the step takes them                               */
  double crack_tip;        /* x of the interface's farthest separated point (NAN: none)  */
  double zone_end;         /* x of its farthest softened point (>= crack_tip; NAN: none) */
  double gap_min;          /* the static interface's least normal opening so far         */
  double line_x, line_y;   /* a point of the interface's line (the specimen's)           */
  struct mpm_static *qs;   /* the static solver on this sim, or NULL (its line's pieces)  */
  double t;                /* time                                                     */
  long step;               /* steps taken                                              */
  double P_grip, P_fixed;  /* loads (tension positive) of the last step                 */
  /* the grip (mpm_control.c): its speed this step (pulling, > 0), the change of that speed
   * from the last step, its displacement so far (delta) */
  double vgrip, dvgrip, ugrip;
  double D_run;            /* dissipation so far, summed from the steps' increments       */
  double P_peak;           /* the largest grip load so far                                */
  double ctl_D0;           /* dissipation control: the D held to (infinite: not yet)     */
  double ctl_int;          /* ... its integral term (a speed; 0 until it takes over)      */
  double W_ext;            /* accumulated external work                                */
  long n_soften, n_separate, n_bracketed; /* counters of constitutive paths           */
  long n_debris;           /* separated particles that left the grid (MPM_MAT_DEBRIS)    */
  /* sorting and threads (mpm_sort.c): particles sorted by cell, column by column;
   * strips of MPM_STRIP columns of cells are coloured even/odd for the scatter */
  int nthreads;            /* threads of the current step (set by mpm_threads_tick)     */
  mpm_threads thr;         /* thr.nmax threads' worth of scratch is allocated           */
  mpm_dwork **dws;         /* one scratch per thread                                   */
  mpm_defer *defer;        /* one list per thread                                      */
  int nstrip;              /* strips of columns                                        */
  size_t *strip_start;     /* first particle of each strip (nstrip + 1 entries)        */
  uint32_t *key, *perm;    /* per-particle cell key and sort permutation               */
  size_t *count;           /* per-cell counters                                        */
  double *scratch;         /* one particle array's worth, for permuting                 */
  uint8_t *scratch8;
  int resort;              /* 1: a particle left its strip's safe range; sort before the next step */
  int laid;                /* grid.weights = laid: 1 while this step's particles sit at their
                              laid places (mpm_step.c lay_grid), their offsets in wdx, wdy */
  int laid_done;           /* 1 once the bar is cut and the laid places are given up     */
  double time_split[MPM_T_N];    /* seconds in: sort, p2g, grid, g2p, constitutive            */
  int cut;                 /* 1 once the band has cut the bar: a separated particle in every
                              particle row of the reference lattice (mpm_sim_cut); latched */
  long cut_seen;           /* n_separate when the rows were last counted                */
  int nrow;                /* particle rows of the bar                                  */
  uint8_t *rowsep;         /* scratch: the rows holding a separated particle            */
  mpm_ledger led;          /* the energy ledger                                        */
  mpm_band *band;          /* decohesion.Le = row: the rows' measured Le, or NULL       */
  double (*led_part)[MPM_LED_N]; /* per-strip partial sums of the step (nstrip rows)  */
  struct mpm_damping *damp; /* time.damping > 0: its state (mpm_damping.c), else NULL   */
  const struct mpm_scheme_type *scheme; /* time.scheme's phases (mpm_phase.h)          */
  struct mpm_phases *ph;   /* the hooks and loops the step walks, chosen at setup       */
};

/* Local damping (time.damping): its state (mpm_kernel.h). */
typedef struct mpm_damping mpm_damping;

/* Materials.  The head is the loading machine (paper, sec. 4.4: "a rigid head with
 * large mass"): stress-free particles MPM_HEAD_CELLS cells wide beyond the bar's left
 * end, whose nodes are all gripped in x.  It keeps the nodes beyond the bar's end from
 * ever being nearly empty, which under USL tore the gripped end off once a particle
 * crossed the gripped node line (Fig. 6 at h 4 past delta 2, at h 2 with 9 ppc before
 * separation).  Head particles are left out of the energies and the snapshots. */
/* MPM_MAT_DEBRIS: a separated particle that left the grid (mpm_step.c, "Debris"): no
 * mass, no stiffness, no strength; it keeps its lambda, dis and wcoh. */
/* MPM_MAT_ELASTIC: the bar off the crack's path (decohesion.path = line): the bar's
 * stiffness and mass, no strength test. */
#define MPM_HEAD_CELLS 2
#define MPM_STRIP 4        /* columns of cells per strip (>= 3: see mpm_sort.c)           */
#define MPM_SORT_EVERY 64  /* steps between sorts (quasi-static: particles move ~1e-5 h a
                              step; 16 cost 0.45 ns per particle-step more, measured)  */

/* Total momentum (for conservation tests). */
void mpm_particles_momentum(const mpm_particles *p, double *px, double *py);

/* Seconds on the monotonic clock: the kernel's timings (time split, thread probes, the
 * static solver's phases). */
static inline double mpm_wall(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* decohesion.Le = row (mpm_band.c): Le per particle row of the bar, measured from the
 * particles softening in it, k dx |sin a| with k = sum / lam (mpm_band_le). */
struct mpm_band {
  int nrow, nstrip;        /* particle rows of the bar; strips of the gather            */
  double idy;              /* 1 / the row height h / sqrt(ppc)                           */
  double wlen;             /* Le per participating particle, dx |sin a| Le_factor        */
  double le0;              /* a row's Le before any of its particles has softened        */
  double *acc;             /* per strip and row: sum of this step's dlambda (softening), and
                              the largest min(lambda, 1) reached                        */
  double *lam;             /* each row's crack state: the largest min(lambda, 1) in it   */
  double *sum;             /* each row's softening so far, the sum of its particles' dlambda */
  double *xl;              /* each row's lead: the x0 of its particle with the largest lambda */
  double reach;            /* Le = zone: only the particles within this x0 distance of the
                              row's lead count in sum (2 h + dx: their supports touch the
                              lead's); 0 for Le = row, every particle of the row counts  */
};

mpm_band *mpm_band_alloc(int nrow, int nstrip, double dy, double wlen, double le0, double reach);
void mpm_band_free(mpm_band *b);
void mpm_band_step(mpm_band *b);
static inline int mpm_band_row(const mpm_band *b, double y0)
{
  const int j = (int)(y0 * b->idy);
  return j < 0 ? 0 : j >= b->nrow ? b->nrow - 1 : j;
}
/* Row j's Le for this step: k wlen, k = sum / lam (at least 1), once it has softened. */
static inline double mpm_band_le(const mpm_band *b, int j)
{
  const double lam = b->lam[j], sum = b->sum[j];
  if (!(lam > 0.0 && sum > 0.0))
    return b->le0;
  const double k = sum / lam;
  return (k > 1.0 ? k : 1.0) * b->wlen;
}

/* The grip's displacement after `ahead` more steps at its current speed (0: delta). */
double mpm_sim_grip_u(const mpm_sim *s, int ahead);
/* Particle i's kinetic and elastic energy (plane-stress compliance of its material). */
void mpm_particle_energy(const mpm_sim *s, size_t i, double *ke, double *se);
/* The manufactured solution's scene at grid h (mpm_mms.c; mpm.h mpm_mms_error). */
mpm_scene mpm_mms_scene(double h, int scheme, int bc);

/* Sets up t for `requested` threads (<= 0: automatic, up to OpenMP's default). */
void mpm_threads_init(mpm_threads *t, int requested, size_t particles);

/* Local damping (time.damping, mpm_damping.c): after the node update (and the second
 * field's), on every free velocity component; under MUSL, its share of the stress power
 * after the re-projection. */
mpm_damping *mpm_damping_alloc(const mpm_sim *s);
void mpm_damping_free(mpm_damping *d);
void mpm_damping_apply(mpm_sim *s);
void mpm_damping_musl(mpm_sim *s);
/* time.damping_about = parts, once the band has cut the bar: each bar particle's velocity
 * relaxes toward the motion of its part's held end (mpm_damping.c); books L_damp. */
void mpm_damping_parts(mpm_sim *s);

/* Sorts the particles by cell (stable counting sort) and rebuilds the strips. */
void mpm_sim_sort(mpm_sim *s);

/* Called at the top of each step: picks the step's thread count (s->nthreads). */
void mpm_threads_tick(mpm_sim *s);

/* The grip's speed for the next step (mpm_control.c), at the top of each step. */
void mpm_control_step(mpm_sim *s);

/* Updates s->cut after new separations (cheap when there are none). */
void mpm_sim_cut(mpm_sim *s);

/* Stress in a material's n-t frame, (s_nn, s_tt, s_nt), and back, with its rotation
 * coefficients (the decohesion update's frame, and the static interface's). */
typedef struct {
  double nn, tt, nt;
} nt_stress;

static inline nt_stress mpm_to_nt(const mpm_material *m, double sxx, double syy, double sxy)
{
  nt_stress s;
  s.nn = m->rnn[0] * sxx + m->rnn[1] * syy + m->rnn[2] * sxy;
  s.tt = m->rtt[0] * sxx + m->rtt[1] * syy + m->rtt[2] * sxy;
  s.nt = m->rnt[0] * sxx + m->rnt[1] * syy + m->rnt[2] * sxy;
  return s;
}

/* The inverse rotation, with the same coefficients: sxx = nx^2 s_nn + tx^2 s_tt +
 * 2 nx tx s_nt, ... (the factors 2 and 1/2 are exact). */
static inline void mpm_from_nt(const mpm_material *m, nt_stress s, mpm_dstate *out)
{
  out->sxx = m->rnn[0] * s.nn + m->rtt[0] * s.tt + (2.0 * m->rnt[0]) * s.nt;
  out->syy = m->rnn[1] * s.nn + m->rtt[1] * s.tt + (2.0 * m->rnt[1]) * s.nt;
  out->sxy = (0.5 * m->rnn[2]) * s.nn + (0.5 * m->rtt[2]) * s.tt + m->rnt[2] * s.nt;
}

#endif
