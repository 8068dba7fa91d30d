/*
 * mpm.h - the public contract of the kernel: an explicit 2-D material point method
 * (Schreyer, Sulsky and Zhou 2002, sec. 2, eqs. 2-7) with the decohesion
 * constitutive update of secs. 3-4 (eqs. 19-26, 39-58), and a quasi-static solver on
 * the same particles and laws.  Plane stress, small strain, unit thickness,
 * dimensionless units.
 *
 * A program fills an mpm_scene (a run's plain description; verify/scene.h reads one
 * from a scene file), makes an opaque mpm_sim from it, steps it, and reads the loads,
 * energies and particles back through the calls below.  The kernel's own structs are
 * private (kernel/mpm_kernel.h); the scene keys: docs/scene-keys.md.
 */
#ifndef DELAM_MPM_H
#define DELAM_MPM_H

#include <stddef.h>
#include <stdint.h>

typedef enum {
  MPM_OK = 0,
  MPM_EINVAL,     /* bad input a user can cause                          */
  MPM_ENOMEM,     /* allocation failed                                   */
  MPM_ENOTFINITE, /* a NaN or infinity appeared in the state              */
  MPM_EDOMAIN,    /* a particle left the grid                            */
  MPM_EIO,        /* a file could not be written                         */
  MPM_EINTR,      /* stopped by a signal                                 */
  MPM_ESTALL      /* the static solver found no equilibrium path onward   */
} mpm_status;

const char *mpm_strerror(mpm_status s);

/* The values of the scene's method words (docs/scene-keys.md; what each does in the
 * kernel: kernel/mpm_kernel.h, "The method options"). The first of each is the paper's. */
enum { MPM_LE_CELL = 0, MPM_LE_PARTICLE = 1, MPM_LE_STAIRCASE = 2, MPM_LE_ROW = 3, MPM_LE_ZONE = 4 };
enum { MPM_DCOH_NONE = 0, MPM_DCOH_MODEL1 = 1, MPM_DCOH_MODEL2 = 2 }; /* decohesion.model */
enum { MPM_SCHEME_USL = 0, MPM_SCHEME_MUSL = 1, MPM_SCHEME_USF = 2, MPM_SCHEME_USAVG = 3 };
enum { MPM_BC_LAGRANGIAN = 0, MPM_BC_BOTH = 1, MPM_BC_CONSISTENT = 2 };  /* grid.bc */
enum { MPM_HEAD_RIGID = 0, MPM_HEAD_NONE = 1 };                         /* loading.head */
enum { MPM_CONTROL_GRIP = 0, MPM_CONTROL_DISSIPATION = 1 };              /* loading.control */
enum { MPM_GRID_FIXED = 0, MPM_GRID_STRETCH = 1 };                      /* grid.motion */
enum { MPM_WEIGHTS_CURRENT = 0, MPM_WEIGHTS_LAID = 1 };                 /* grid.weights */
enum { MPM_SHAPE_LINEAR = 0, MPM_SHAPE_GIMP = 1 };                      /* grid.shape */
enum { MPM_FIELDS_ONE = 0, MPM_FIELDS_TWO = 1 };                        /* grid.fields */
enum { MPM_NODEMASS_LUMPED = 0, MPM_NODEMASS_LIMITED = 1 };             /* grid.node_mass */
enum { MPM_IMP_PARTICLE = 0, MPM_IMP_CELL = 1 };                        /* imperfection.size */
enum { MPM_DAMP_START = 0, MPM_DAMP_CUT = 1 };                          /* time.damping_from */
enum { MPM_DAMP_DRIFT = 0, MPM_DAMP_PARTS = 1 };                        /* time.damping_about */
enum { MPM_PATH_FREE = 0, MPM_PATH_LINE = 1, MPM_PATH_IFACE = 2 };      /* decohesion.path */
enum { MPM_SHEAR_EVEN = 0, MPM_SHEAR_CLOSING = 1 };                     /* decohesion.reversed_shear */
enum { MPM_SHARE_STICK = 0, MPM_SHARE_LINE = 1 };                       /* decohesion.share */
enum { MPM_SOLVER_EXPLICIT = 0, MPM_SOLVER_STATIC = 1 };                /* solver.type */
enum { MPM_SPEC_BAR = 0, MPM_SPEC_DCB = 1, MPM_SPEC_ELS = 2, MPM_GRIPS_ROLLERS = 0, MPM_GRIPS_HELD = 1 };

/* ---- scene: everything a run needs, as plain numbers (filled by verify/scene.c) ---- */
typedef struct {
  int specimen, grips;   /* MPM_SPEC_* (the body, its supports and load), MPM_GRIPS_*  */
  double a0;             /* dcb, els: the pre-crack's length from x = 0 along y = H / 2 */
  double L, H;           /* bar length and height; the bar is [0,L] x [0,H]           */
  double E, nu, rho;     /* Young's modulus, Poisson's ratio, density                  */
  int model;             /* MPM_DCOH_*                                                 */
  double alpha_deg;      /* laminate angle from the x-axis, deg                        */
  double snf, stf;       /* failure tractions in opening and in shear                  */
  double U0, s0, q;      /* dissipation per area at separation, reference traction, softening exponent */
  double sep_threshold;  /* lambda above which the separation algorithm is used (paper 0.98) */
  double eta;            /* decohesion viscosity, a time (0: the paper's rate-independent law) */
  int le_mode;           /* MPM_LE_*: the effective length Le of eq. 41                */
  double le_factor;      /* Le is le_factor times the mode's length (1)                */
  double imp_factor;     /* snf multiplier at the imperfection particle (paper 0.9); 1 = none */
  double imp_stf_factor; /* stf multiplier there (1: the paper's imperfection, snf only) */
  double imp_x, imp_y;   /* the imperfection sits at the particle nearest this point   */
  int imp_size;          /* MPM_IMP_*                                                  */
  int path;              /* MPM_PATH_*: where the bar may soften                       */
  int reversed_shear;    /* MPM_SHEAR_*                                                */
  int share;             /* path = interface: MPM_SHARE_*                              */
  double path_reach;     /* LINE: the band's half-width beyond the crossed cells, in cells */
  double h;              /* grid spacing                                               */
  int ppc;               /* particles per cell, a perfect square (1, 4, 9, ...)        */
  double margin;         /* empty space around the bar (the left side adds the grip's travel) */
  int scheme;            /* MPM_SCHEME_*                                               */
  int grid_motion;       /* MPM_GRID_*                                                 */
  int weights;           /* MPM_WEIGHTS_*                                              */
  int shape;             /* MPM_SHAPE_*                                                */
  int fields;            /* MPM_FIELDS_*                                               */
  int bc;                /* MPM_BC_* (how a held node enters eq. 6)                    */
  int node_mass;         /* MPM_NODEMASS_*                                             */
  int head;              /* MPM_HEAD_*                                                 */
  int vib_mode;          /* > 0: start from axial mode m, vx += vib_amp sin(m pi X / L) */
  double vib_amp;        /* its velocity amplitude                                    */
  double vib_periods;    /* the run's length in periods (the driver sets end_delta from it) */
  double body_amp;       /* a body force per unit mass in x, b_x = body_amp sin(pi X / L) */
  double body_omega;     /*   sin(body_omega t) (0: none; manufactured solutions)     */
  double dt;             /* time step                                                  */
  double speed;          /* grip speed (pulls the left end in -x)                      */
  int control;           /* MPM_CONTROL_*                                              */
  double damping;        /* c: nodal velocities relax at the rate c, 0 <= c dt < 1 (0: none) */
  double damping_tau;    /* its low-pass time constant (0: 2 L / c)                    */
  double damping_beta;   /* beta, a time: viscous stress beta C : grad v (0: none)     */
  int damping_from;      /* MPM_DAMP_START or MPM_DAMP_CUT                             */
  int damping_about;     /* MPM_DAMP_DRIFT or MPM_DAMP_PARTS                           */
  double end_delta;      /* the run never goes past this end displacement              */
  int solver;            /* MPM_SOLVER_*                                               */
} mpm_scene;

/* Starting velocity (no wave): -speed (L - x) / L on the bar, -speed left, 0 right; beams 0. */
static inline double mpm_scene_start_vx(const mpm_scene *sc, double x)
{
  return sc->specimen != MPM_SPEC_BAR ? 0.0 : x <= 0.0 ? -sc->speed : x >= sc->L ? 0.0 : -sc->speed * (sc->L - x) / sc->L;
}
/* decohesion.path = line: the half-width of the strip that may soften, h (|sin a| +
 * |cos a|) / 2 (the cells the line at alpha crosses) + path_reach h. */
double mpm_scene_path_halfwidth(const mpm_scene *sc);
/* Checks a scene for physical sense; MPM_EINVAL and a message naming the key. */
mpm_status mpm_scene_check(const mpm_scene *sc, char *err, size_t errlen);
/* Critical time step h / (c sqrt 2), c = sqrt(E1 / rho) (measured: mpm_sim.c). */
double mpm_scene_dt_crit(const mpm_scene *sc);
/* The rules between the method options (mpm_rules.c; mpm_scene_check ends with them):
 * MPM_OK, or MPM_EINVAL with the first one broken in err, which starts with the key at
 * fault and names the allowed values; *key (if not NULL) is that key, "section.key". */
mpm_status mpm_scene_rules(const mpm_scene *sc, const char **key, char *err, size_t errlen);
/* The time schemes: the index of the one named `name` (-1: none); the name of index i. */
int mpm_scheme_find(const char *name);
const char *mpm_scheme_name(int i);

/* ---- the simulation: opaque; made from a scene, stepped, read, freed ---- */
typedef struct mpm_sim mpm_sim;

/* nthreads > 0: that many threads; <= 0: chosen per step by measurement, up to OpenMP's
 * default.  Results do not depend on it (fixed summation order). */
mpm_status mpm_sim_alloc(const mpm_scene *sc, int nthreads, mpm_sim **out, char *err, size_t errlen);
void mpm_sim_free(mpm_sim *s);
/* One explicit step (eqs. 2-7); on failure err names the step, particle and field. */
mpm_status mpm_sim_step(mpm_sim *s, char *err, size_t errlen);
/* The grip's displacement delta. */
double mpm_sim_delta(const mpm_sim *s);
/* The scene the sim was made from (its copy). */
const mpm_scene *mpm_sim_scene(const mpm_sim *s);

/* Where a run is, after a step (mpm_sim_info_get). */
enum { MPM_T_SORT = 0, MPM_T_P2G, MPM_T_GRID, MPM_T_G2P, MPM_T_CONST, MPM_T_N };
typedef struct {
  long step;               /* steps taken (static solver: increments)                  */
  double t;                /* time                                                     */
  double P_grip, P_fixed;  /* loads of the last step at the grip and the fixed end (tension > 0) */
  int cut;                 /* 1 once the band has cut the bar (a separated particle in every row) */
  double crack_tip, zone_end; /* dcb, els: the front's x (a0 before growth), the process zone's far end; bar: NAN */
  double gap_min;          /* the static interface's least normal opening (< 0: overlap) */
  long n_soften, n_separate, n_bracketed; /* decohesion updates by path; bracketed solves */
  long n_debris;           /* separated particles that left the grid                  */
  double time_split[MPM_T_N]; /* seconds in sort, p2g, grid, g2p, constitutive update */
} mpm_sim_info;
void mpm_sim_info_get(const mpm_sim *s, mpm_sim_info *out);

/* ---- energies (sec. 3 eq. 25 for the surface terms) ---- */
typedef struct {
  double W_ext;  /* work of the reactions at the constrained nodes                    */
  double KE;     /* kinetic energy of the particles                                   */
  double SE;     /* elastic strain energy                                             */
  double W_coh;  /* work of the traction on the decohesion surfaces, int s . d up dA   */
  double D;      /* dissipation, U0 min(lambda, 1) per unit failure area (eq. 10)      */
  /* The ledger: what the step itself removes, so that W_ext + KE(0) = KE + SE + W_coh +
   * L_bc + L_flip + L_scheme + W_head + L_contact + L_debris + L_damp up to the
   * constitutive update's own integration error (docs/model.md). */
  double L_bc;     /* removed at held nodes by the constraint's velocity jump          */
  double L_flip;   /* lost interpolating the nodal velocity increments to the particles */
  double L_scheme; /* the time integration's own loss (negative: gain)                */
  double W_head;   /* taken by the rigid head (its KE change and its projection)      */
  double L_contact; /* taken by the contact between two velocity fields               */
  double L_debris; /* carried off the grid by separated particles that left it        */
  double L_damp;   /* taken by the local damping (time.damping)                       */
} mpm_energy;
void mpm_sim_energy(const mpm_sim *s, mpm_energy *e);

/* ---- particles, read-only: structure of arrays, valid until the next step or free ----
 * A particle's material: the bar, the imperfection, the rigid head (the loading machine,
 * left out of energies and snapshots), debris (separated, off the grid), the bar off the
 * crack's path (elastic). */
enum { MPM_MAT_BAR = 0, MPM_MAT_IMP = 1, MPM_MAT_HEAD = 2, MPM_MAT_DEBRIS = 3, MPM_MAT_ELASTIC = 4 };
typedef struct {
  size_t n;                     /* particles                                           */
  size_t nhead;                 /* of them the head's (mat MPM_MAT_HEAD)               */
  const double *x, *y;          /* position                                            */
  const double *x0, *y0;        /* reference position                                  */
  const double *vx, *vy;        /* velocity                                            */
  const double *m, *V;          /* mass, volume                                        */
  const double *sxx, *syy, *sxy; /* stress                                             */
  const double *lam;            /* decohesion parameter lambda                         */
  const double *upn, *upt;      /* displacement jump across the failure plane, n and t */
  const double *wcoh, *dis;     /* traction work and dissipation so far               */
  const uint8_t *mat, *sep;     /* MPM_MAT_*; 1 once separated                         */
} mpm_particle_view;
void mpm_sim_particles(const mpm_sim *s, mpm_particle_view *v);

/* Setting up a start other than the scene's (the bench): the bar at the uniform uniaxial
 * stress sigma along x, at the time and step the grip reaches it; particle i separated.
 * MPM_EINVAL for a sigma not finite or an i past the particles. */
mpm_status mpm_sim_prestress(mpm_sim *s, double sigma);
mpm_status mpm_sim_separate(mpm_sim *s, size_t i);

/* decohesion.path = interface, for pictures: the places on the line (0: none), and place
 * i's piece, (xy[0], xy[1]) to (xy[2], xy[3]) in reference coordinates, its segment's
 * lambda and state (0 stuck, 1 softening, 2 open); 0 when place i is off the bar. */
int mpm_iface_pieces(const mpm_sim *s);
int mpm_iface_piece(const mpm_sim *s, int i, double xy[4], double *lam, int *state);

/* The kernel's bookkeeping (summary.json and the bench): threads, memory per particle. */
typedef struct {
  int nmax;                /* threads allocated for                                    */
  long steps_multi;        /* steps run on more than one thread                        */
  long nprobe, nbusy;      /* probes of the thread count done; skipped (no idle core)  */
} mpm_threads_info;
void mpm_sim_threads(const mpm_sim *s, mpm_threads_info *out);
size_t mpm_sim_bytes_per_particle(const mpm_sim *s);

/* ---- the quasi-static solver (mpm_static.c) ----
 * Load increments on the same grid, particles, shapes and laws, each solved by Newton's
 * method on the nodal force balance; the grip's displacement leads to the first
 * softening, then the dissipation does (the grip may move back: snapback).  An
 * increment is one "step" of the sim: delta, loads, particles, step and t advance. */
enum { MPM_QS_GRIP = 0, MPM_QS_DISSIPATION = 1 };
/* the path's critical points (docs/static.md): a uniform state's tie, a limit point of delta, a bifurcation */
enum { MPM_QS_TIE = 1, MPM_QS_LIMIT = 2, MPM_QS_BIFURCATION = 3 };
typedef struct {
  long increments, newton; /* load increments taken; Newton iterations, all increments */
  long cuts, factorizations, updates; /* increments retried smaller; sparse LUs; low-rank updates */
  long switches, turns;    /* changes of control; increments retried smaller at a corner */
  int det_sign;            /* the last state's tangent K (grip held): sign of det K, 0 singular */
  int crit;                /* MPM_QS_TIE, _LIMIT, _BIFURCATION the last increment crossed (0: none) */
  long backtracks;         /* Newton steps halved by the line search                   */
  long severed;            /* interface segments let go below 2 % of the peak load     */
  int nres;                /* the last increment's Newton iterations, and each one's   */
  double res[32];          /* largest residual force over the largest load (first 32) */
  int mode;                /* MPM_QS_* of the last increment                           */
  int unknowns; size_t nnz; /* free degrees of freedom; entries of the tangent         */
  double t_eval, t_factor, t_solve; /* seconds: laws and assembly, factorization, solves */
} mpm_static_stats;
typedef struct mpm_static mpm_static;
/* On a sim of a scene with solver = static, which must outlive q; MPM_EINVAL and why. */
mpm_status mpm_static_alloc(mpm_sim *s, mpm_static **out, char *err, size_t errlen);
/* MPM_EINVAL and the reason if the static solver refuses the scene (before a sim). */
mpm_status mpm_static_refusal(const mpm_scene *sc, char *err, size_t errlen);
void mpm_static_free(mpm_static *q);
mpm_status mpm_static_step(mpm_static *q, char *err, size_t errlen);
void mpm_static_stats_get(const mpm_static *q, mpm_static_stats *out);

/* Manufactured solutions, the RMS particle displacement error over the amplitude on grid h (*e): the step's forced
 * axial vibration (mpm_mms.c), the static solver's 2-D field (mpm_static_mms.c; *e_node the nodes', unless NULL). */
mpm_status mpm_mms_error(double h, int scheme, int bc, double *e, char *err, size_t errlen);
mpm_status mpm_static_mms_error(double h, int shape, int ppc, double *e, double *e_node, char *err, size_t errlen);

#endif
