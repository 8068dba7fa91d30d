/*
 * check_spec.h - `delam check` on a split beam's folder (check_spec.c).
 */
#ifndef DELAM_VER_CHECK_SPEC_H
#define DELAM_VER_CHECK_SPEC_H

#include "check.h"
#include "sweep.h"
#include "scene.h"

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

#endif
