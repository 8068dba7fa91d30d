/*
 * ana.h - closed-form uniaxial bar with decohesion (Schreyer, Sulsky, Zhou 2002,
 * sec. 3.2, eqs. 28-37; docs/model.md sec. 5).  The independent oracle for every MPM result.
 *
 * A bar of length L, height H, unit depth, loaded in uniaxial stress sigma = P / H,
 * with one failure plane at angle alpha to the x-axis.  Model 1 (associated) and
 * Model 2 (opening only, eq. 37), any q > 0.
 */
#ifndef DELAM_ANA_H
#define DELAM_ANA_H

#define ANA_PI 3.14159265358979323846 /* pi, for analytic/ and verify/ */

enum { ANA_OK = 0, ANA_EINVAL = 1, ANA_EFAIL = 2, ANA_ERANGE = 3 /* a table too large to hold */ };

typedef struct {
  double alpha_deg; /* laminate angle from the x-axis, (0, 90] deg            */
  double snf;       /* normal traction at failure initiation (> 0)           */
  double stf;       /* shear traction at failure initiation (> 0)            */
  double U0;        /* energy dissipated per unit area at separation (> 0)   */
  double s0;        /* reference traction; ubar0 = U0 / s0 (> 0)              */
  double q;         /* softening exponent, sbar = lambda^q (> 0)             */
  double E;         /* Young's modulus (uniaxial stress) (> 0)               */
  double nu;        /* Poisson's ratio (kept for the record; uniaxial)       */
  double L;         /* bar length (> 0)                                      */
  double H;         /* bar height (> 0)                                      */
  int model;        /* 1: associated, 2: opening only                        */
} ana_params;

typedef struct {
  ana_params p;
  double r0;          /* peak stress (eq. 30)                                  */
  double mec[2];      /* decohesion at separation, n-t components (eq. 30)     */
  double upx_sep;     /* x-component of the opening at separation              */
  double g;           /* dimensionless snapback parameter (eq. 35 / eq. 37)    */
  double Pmax;        /* peak load r0 H                                        */
  double k_elastic;   /* E H / L                                               */
  double k_soft_peak; /* softening slope dP/ddelta just after the peak (eq. 36)*/
  double delta_peak;  /* r0 L / E                                              */
  double delta_sep;   /* end displacement at separation = upx_sep              */
  int snapback;       /* 1 if the softening slope turns positive somewhere     */
  double sstar_turn;  /* sigma* where dP/ddelta changes sign (snapback), else -1 */
  double area;        /* failure area H / sin(alpha)                           */
  double UD, UU, UF;  /* energies per unit failure area at separation (eq. 25) */
  double W_sep;       /* external work to separation, UF * area                */
  double D_sep;       /* dissipation at separation, UD * area                  */
} ana_bar;

/* Fills *bar from *p; ANA_EINVAL (and a message in err, if given) on bad input. */
int ana_bar_init(const ana_params *p, ana_bar *bar, char *err, int errlen);

/* Default parameters: the Fig. 6 case (alpha 90, snf 1, stf 10, U0 0.375, s0 1,
 * q 1, E 1024, nu 0.25, L 192, H 32, model 1). */
void ana_params_default(ana_params *p);

/* Point on the softening branch parametrised by sigma* = sigma / r0 in [0, 1]:
 * end displacement and load (eq. 34). */
void ana_bar_softening_point(const ana_bar *bar, double sstar, double *delta, double *P);

/* Slope dP/ddelta on the softening branch at sigma* (eq. 36); +inf where vertical. */
double ana_bar_softening_slope(const ana_bar *bar, double sstar);

/* Load-deflection curve: elastic branch 0..delta_peak, then the softening branch
 * sampled in sigma* (single-valued in that parameter), then P = 0 to delta_end.
 * Writes up to n points into delta[], P[]; returns the number written. */
int ana_bar_curve(const ana_bar *bar, double delta_end, int n, double *delta, double *P);

/* Load at end displacement delta on the first branch that reaches it (for error
 * norms; on a snapback the branch is the one met first along sigma*). */
double ana_bar_load_at(const ana_bar *bar, double delta);

/* External work to end displacement delta_end (quadrature of the curve, GSL). */
double ana_bar_work(const ana_bar *bar, double delta_end);

/* The same bar at a finite grip speed (ana_wave.c, docs/model.md sec. 5a): the exact
 * 1-D wave solution from the kernel's start (the steady velocity field), with the plane
 * as the interface's cohesive line.  90 deg only (uniaxial waves), q = 1, s0 = snf. */
typedef struct {
  double speed; /* grip speed (> 0)                                              */
  double rho;   /* density (> 0); c = sqrt(E / rho)                              */
  double xg;    /* distance of the plane from the grip, (0, L)                   */
  double thr;   /* separation threshold on lambda, (0, 1]: the plane opens there */
} ana_wave_params;

typedef struct {
  double *P;      /* grip load at delta = i ddelta, i < n                         */
  long n;
  double ddelta;  /* sample spacing in delta                                     */
  double t_onset; /* when the plane starts to soften (snf L / (E speed))         */
  double Tg, Tf;  /* transit times plane-grip and plane-fixed end                */
} ana_wave;

/* Solves to delta_end; ANA_EINVAL (message in err) for a bar or parameters outside the
 * above, ANA_ERANGE (message in err) where it would take more than ANA_WAVE_MAX_SAMPLES
 * time samples (3 arrays of doubles that long: 96 MiB; iface90.ini takes 5e4),
 * ANA_EFAIL if out of memory.  *out owns its samples: ana_wave_free. */
#define ANA_WAVE_MAX_SAMPLES 4000000
/* ana_wave_init's checks alone, and the samples it would take in *n: ANA_OK, ANA_EINVAL
 * or ANA_ERANGE, with the message in err. */
int ana_wave_size(const ana_bar *bar, const ana_wave_params *wp, double delta_end, long *n, char *err, int errlen);
int ana_wave_init(const ana_bar *bar, const ana_wave_params *wp, double delta_end, ana_wave *out, char *err,
                  int errlen);
void ana_wave_free(ana_wave *w);

/* Grip load at delta (linear between samples); NaN outside [0, delta_end]. */
double ana_wave_load_at(const ana_wave *w, double delta);

/* The largest grip load of the samples, and (if delta_at) its delta. */
double ana_wave_peak(const ana_wave *w, double *delta_at);

/* The growth rate of the kernel's explicit step on a 1-D periodic bar, linearised about
 * a uniform stress sigma0 carried by particles that drifted by `drift` cells from where
 * the grid was laid (ana_stab.c derives the map; docs/methods.md uses it).  Which
 * ingredients make the step grow: MUSL against USL, uGIMP against bilinear shapes, the
 * drift and the prestress. */
enum { ANA_STAB_USL = 0, ANA_STAB_MUSL = 1 };
enum { ANA_STAB_LINEAR = 0, ANA_STAB_GIMP = 1 };
typedef struct {
  int scheme;    /* ANA_STAB_USL or ANA_STAB_MUSL (strain from vL, or from the re-projection) */
  int shape;     /* ANA_STAB_LINEAR or ANA_STAB_GIMP (uGIMP, box half length 1 / (2 per_cell))*/
  int per_cell;  /* particles per cell along the bar, [1, 8] (2 for the 2-D grid's 4 ppc)      */
  int ncell;     /* cells of the periodic bar, [3, 64]                                     */
  double h;      /* cell size (> 0)                                                        */
  double E, rho; /* Young's modulus and density (> 0)                                      */
  double sigma0; /* the uniform stress of the rest state                                   */
  double drift;  /* the particles' offset from their laid positions, in cells             */
  double dt;     /* time step (> 0)                                                        */
} ana_stab;

typedef struct {
  double rate; /* ln(r) / dt per unit time, r the largest eigenvalue modulus of the step     */
  double wave; /* the same over the eigenvalues off the real axis (the waves); -inf if none */
} ana_stab_rates;

/* The rates of the linearised step into *out; ANA_EINVAL on bad input, ANA_EFAIL out of
 * memory or when the eigenvalues fail (*out untouched then). */
int ana_stab_rate(const ana_stab *c, ana_stab_rates *out, char *err, int errlen);

#endif
