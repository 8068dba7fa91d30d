/*
 * check_spec.h - `delam check` on a split beam's folder (check_spec.c).
 */
#ifndef DELAM_VER_CHECK_SPEC_H
#define DELAM_VER_CHECK_SPEC_H

#include "ana_spec.h"
#include "check.h"
#include "foreign.h"
#include "sweep.h"
#include "scene.h"

/* One table of data/fe: the 2-D finite-element compliance C(a) and C'(a) (by the J
 * integral), ascending a, scaled to the scene's E (the tables' is 1024). */
typedef struct {
  int n;
  double a[64], C[64], dC[64];
} ver_fe_table;
/* data/fe/<dcb|els>[_H<H>][_nu045].dat for the scene's specimen, L, H and nu; 0, or -1
 * with the reason in why. */
int ver_spec_fe_read(const mpm_scene *sc, ver_fe_table *t, char *why, size_t wl);
/* y (t->C or t->dC) at a, by the cubic through the 4 table points nearest a (C is smooth
 * in a); NAN outside the table. */
double ver_spec_fe_at(const ver_fe_table *t, const double *y, double a);

/* The checks of DIR, a run of the DCB or ELS (vs its scene), into chk (at most max, *n
 * of them; a check that cannot be made is a pass with error NaN and the reason in its
 * note).  0, or 2 with the reason in err when the folder's files cannot be read. */
int ver_spec_judge(const char *dir, const ver_scene *vs, ver_check *chk, int max, int *n, char *err, size_t errlen);
/* Judges DIR, a run of the DCB or ELS (vs its scene), against data/fe's 2-D finite
 * elements and the cohesive beam; prints a line per check and writes check.json (or
 * out).  0 pass, 1 a check failed, 2 the folder's files cannot be read. */
int ver_check_spec(const char *dir, const ver_scene *vs, const char *out);

/* The 2-D LEFM branch the check holds the run to (docs/specimens.md), for a plot: at a0
 * and at data/fe's crack lengths past it, a, delta = C(a) P and P = sqrt(2 G_c / C'(a))
 * with G_c = q U0 / (q + 1) and the table's C scaled by 1024 / E; at most max points.
 * The count, or -1 with why (no table for the scene's L, H, nu, or a0 outside it). */
int ver_spec_branch(const mpm_scene *sc, double *a, double *d, double *P, int max, char *why, size_t wl);

/* verify's case of a split beam (c->vs.sc.specimen dcb or els), run into dir: its
 * checks (a failed run is one failed check, "run") and verdict. */
void ver_spec_case(const char *dir, ver_case *c);

/* --full's classes for a split beam at one particle per cell: a static run that finds no
 * equilibrium on its way to the peak and a branch up to 5 % off are known limits (their
 * causes: docs/specimens.md, "Where it stops"); every other check stays pass-class. */
void ver_spec_policy(ver_case *c);

/* verify's cross-case checks of the split beams in cs (3 grids in ratio 2 at one ppc):
 * the compliance's order, the DCB's peak's Richardson limit against the cohesive beam;
 * at most room into x, returns how many. */
int ver_spec_cross(const ver_case *cs, int n, ver_cross *x, int room);

/* energy.csv's columns the specimens' checks read: W_ext, SE, W_coh, then KE and the
 * booked losses (absent in another code's file: 0), D last; the ledger's largest
 * |W_ext - SE - W_coh - KE - booked| over the largest W_ext of such a table. */
#define VER_SPEC_NEN 12
extern const char *const ver_spec_enames[VER_SPEC_NEN];
double ver_spec_ledger(const ver_table *en);
/* The analytic references' inputs (analytic/ana_spec.h) from a split beam's scene. */
void ver_spec_params(const mpm_scene *sc, ana_spec_params *p);
/* The bar held by wedge grips (check_held.c): its stiffness against data/fe's and the
 * ledger, as ver_spec_judge. */
int ver_held_judge(const char *dir, const ver_scene *vs, ver_check *chk, int max, int *n, char *err, size_t errlen);

#endif
