/*
 * check_spec.h - `delam check` on a split beam's folder (check_spec.c).
 */
#ifndef DELAM_VER_CHECK_SPEC_H
#define DELAM_VER_CHECK_SPEC_H

#include "scene.h"

/* Judges DIR, a run of the DCB or ELS (vs its scene), against data/fe's 2-D finite
 * elements and the cohesive beam; prints a line per check and writes check.json (or
 * out).  0 pass, 1 a check failed, 2 the folder's files cannot be read. */
int ver_check_spec(const char *dir, const ver_scene *vs, const char *out);

#endif
