/*
 * ana_spec.h - references for the two delamination specimens with a moving crack front
 * (docs/specimens-reference.md), plane stress, unit width: the double cantilever beam
 * (DCB, mode I) and the end-loaded split (ELS, mode II).  ana_spec.c: the interface law's
 * pure-mode numbers (docs/model.md sec. 3, eqs. 23-25) and the LEFM beam references
 * (simple, corrected, Timoshenko, Kanninen); ana_spec_czm.c: the DCB's cohesive beam
 * reference (a beam on the law and a Winkler foundation, by finite differences).
 *
 * Geometry: a bar L x H; two arms t = H / 2 about y = H / 2, cracked from x = 0 to a.
 *   DCB: the arms' ends held at u_y = +-delta / 2 (moment-free), x = L free; P is the
 *        force on one arm, C = delta / P.
 *   ELS: x = L clamped, both arms' ends moved together by delta; P is the total force.
 */
#ifndef DELAM_ANA_SPEC_H
#define DELAM_ANA_SPEC_H

#include "ana.h" /* ANA_OK, ANA_EINVAL, ANA_EFAIL */

enum { ANA_SPEC_DCB = 0, ANA_SPEC_ELS = 1 };

/* The beam theories of the LEFM references. */
enum {
  ANA_BEAM_SIMPLE = 0,    /* Euler arms built in at the crack tip                         */
  ANA_BEAM_CORRECTED = 1, /* a -> a + chi t (Williams 1989; ELS: chi_II = 0.42 chi)       */
  ANA_BEAM_SHEAR = 2,     /* simple beam theory plus the arms' Timoshenko shear (k = 5/6) */
  ANA_BEAM_KANNINEN = 3,  /* DCB only: Euler arm on a Winkler foundation 2E/t over L - a  */
  ANA_BEAM_KANNINEN_SHEAR = 4, /* DCB only: Timoshenko arm on that foundation, the ligament
                                  taken semi-infinite (its end's effect ~ exp(-2 beta (L - a))) */
  ANA_BEAM_COUNT = 5
};

typedef struct {
  int kind;      /* ANA_SPEC_DCB or ANA_SPEC_ELS                                        */
  double L, H;   /* bar length and height (> 0); arm thickness t = H / 2                 */
  double a0;     /* pre-crack length from the loaded end, (0, L)                         */
  double E, nu;  /* Young's modulus (> 0), Poisson's ratio (-1, 0.5]                     */
  double snf;    /* law's strength in opening (> 0)                                      */
  double stf;    /* law's strength in shear (> 0)                                        */
  double U0;     /* law's U0, the dissipation per unit area at separation (> 0)          */
  double s0;     /* law's reference traction (> 0); the pure modes do not depend on it   */
  double q;      /* softening exponent (> 0), traction = strength (1 - lambda^q)         */
} ana_spec_params;

typedef struct {
  ana_spec_params p;
  double t;       /* arm thickness H / 2                                                    */
  double EI;      /* one arm's bending stiffness E t^3 / 12 (unit width)                    */
  double kGA;     /* one arm's shear stiffness (5/6) G t, G = E / (2 (1 + nu))               */
  double kf;      /* Winkler modulus of the bonded ligament per arm, 2 E / t                */
  double beta;    /* (kf / (4 EI))^(1/4), the foundation's inverse length                   */
  double chi;     /* Williams' crack length correction for the DCB (isotropic arm)          */
  double chi_II;  /* ELS correction 0.42 chi (Hashemi, Kinloch and Williams 1990)           */
  double wc_I;    /* law's opening at separation in pure opening, U0 / snf                  */
  double wc_II;   /* law's sliding at separation in pure shear, U0 / stf                    */
  double Gc;      /* work of the law's traction to separation per unit area, q U0 / (q + 1) */
  double lcz;     /* slender-arm zone length (E Gc / s^2)^(1/4) t^(3/4), s the mode's strength */
} ana_spec;

/* Defaults of the scenes: L 192, H 32, a0 64, E 1024, nu 0.25, U0 0.375, s0 1, q 1;
 * DCB snf 1, stf 10; ELS snf 10, stf 1.  kind outside the two: the DCB's. */
void ana_spec_default(int kind, ana_spec_params *p);

/* Fills *s from *p; ANA_EINVAL (and a message in err, if given) on bad input. */
int ana_spec_init(const ana_spec_params *p, ana_spec *s, char *err, int errlen);

/* Compliance C(a) = delta / P and its derivative dC/da at crack length a in (0, L) by
 * theory (ANA_BEAM_*); dCda may be NULL.  ANA_EINVAL for a out of range or a theory the
 * specimen lacks (Kanninen for the ELS). */
int ana_spec_compliance(const ana_spec *s, int theory, double a, double *C, double *dCda);

/* Energy release rate at load P and crack length a, G = (P^2 / 2) dC/da (unit width). */
int ana_spec_G(const ana_spec *s, int theory, double a, double P, double *G);

/* The LEFM propagation branch at crack length a: the load with G = Gc, and delta = C P. */
int ana_spec_lefm_branch(const ana_spec *s, int theory, double a, double *P, double *delta);

/* ELS only: the crack length below which the branch's delta falls as a grows (growth
 * unstable under displacement control: a snap-back), the root of d(C P)/da = 0.  Simple
 * theory: L / 6^(1/3); corrected: solved with the corrected compliance. */
int ana_els_snapback_end(const ana_spec *s, int theory, double *a_turn);

/* ---- the cohesive reference of the DCB (ana_spec_czm.c) ---- */

enum { ANA_CZM_EULER = 0, ANA_CZM_TIMOSHENKO = 1 };

typedef struct {
  int beam;       /* ANA_CZM_EULER or ANA_CZM_TIMOSHENKO                                   */
  int cells;      /* mesh cells over L, [16, 1000000]; the node at a0 is kept exact          */
  double tip_end; /* the path stops once the crack tip passes here, (a0, L)                 */
  double kf;      /* foundation modulus per arm; <= 0: the specimen's 2 E / t               */
  int rigid;      /* 1: the law never opens (the elastic Kanninen problem, for checks)       */
} ana_czm_opts;

typedef struct {
  double delta; /* opening between the arms' ends                                          */
  double P;     /* force on one arm                                                        */
  double tip;   /* crack tip: the largest x where the law has separated (a0 before)         */
  double front; /* process zone front: the largest x where the law has started to open      */
  double U_el;  /* elastic energy of both arms (bending, shear, foundation)                 */
  double W_law; /* work of the law's traction on both arms' openings                       */
} ana_czm_point;

typedef struct {
  ana_czm_point *pt; /* the path, in order (delta rises monotonically for the DCB)          */
  int n, cap;
  ana_czm_point peak; /* the largest P, located between path points to 1e-10 in the parameter */
  double h;          /* mesh size of the ligament                                          */
  double unload;     /* the largest fall of any node's law opening along the path (0: the law
                        only opened, so the law's elastic form used here was exact)           */
  int newton;        /* Newton iterations summed over the path                              */
} ana_czm_path;

/* Traces the DCB's cohesive reference from delta = 0 until the crack tip passes
 * o->tip_end.  ANA_EINVAL for a non-DCB specimen, q < 1 (infinite slope at onset) or bad
 * options; ANA_EFAIL if out of memory or a step fails to converge.  *out owns its
 * points: ana_czm_path_free. */
int ana_dcb_czm_solve(const ana_spec *s, const ana_czm_opts *o, ana_czm_path *out, char *err, int errlen);
void ana_czm_path_free(ana_czm_path *c);

/* Load and crack tip at opening delta (linear between path points); NaN outside. */
double ana_czm_load_at(const ana_czm_path *c, double delta, double *tip);

/* The peak on meshes of o->cells, 2x and 4x cells with Richardson extrapolation. */
typedef struct {
  double P[3], delta[3]; /* peak load and its delta on the three meshes                     */
  double order;          /* observed order of the peak load, log2 of the ratio of differences */
  double P_ext, delta_ext; /* extrapolated with the observed order (2 if not measurable)     */
  double P_err, delta_err; /* |finest - extrapolated| / extrapolated: the finest mesh's error */
  double P_ext_err, delta_ext_err; /* |extrapolated with the observed order - with order 2| /
                                      extrapolated: how far the extrapolation itself is sure */
} ana_czm_conv;
int ana_dcb_czm_converge(const ana_spec *s, const ana_czm_opts *o, ana_czm_conv *out, char *err, int errlen);

#endif
