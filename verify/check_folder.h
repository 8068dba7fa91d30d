/*
 * check_folder.h - what `delam check` (cmd_check.c) settles about a folder before it
 * measures anything: whether delam wrote it, whether the run finished (summary.json),
 * and the scene it is judged against.
 */
#ifndef DELAM_VER_CHECK_FOLDER_H
#define DELAM_VER_CHECK_FOLDER_H

#include <stddef.h>

#include "scene.h"

/* The scene options of delam check: SCENE (or NULL), --method, --h, --ppc (0: not
 * given) and the --set assignments, and the folder. */
typedef struct {
  const char *scene, *dir, *method;
  const char *const *sets;
  int nset;
  double h, ppc;
} ver_check_opts;

/* 1 if delam wrote DIR: a scene.ini there, or an energy.csv or final.csv with delam's
 * schema line (a load.csv alone does not say so: a curve cut out of a delam run keeps
 * its comment line).  */
int ver_check_ours(const char *dir);

/* Whether the run in DIR finished, so that its files can be believed: not while a
 * delam process holds its lock; a summary.json that is there must be a regular file
 * holding one whole JSON object whose "complete", where it has one, is literally true
 * (a string "true", 1 or null is not); a folder of delam's (ours) needs that summary.json
 * and its "complete".  Another code's folder without a summary.json, or with one that has
 * no "complete", is judged on its files.  The summary's "scene" (its name) goes to scene
 * ("" if none).  0, or 2 with the file, what was found and why in err. */
int ver_check_finished(const char *dir, int ours, char *scene, size_t slen, char *err, size_t errlen);

/* The scene DIR is judged against, into vs (validated, allow_unstable set).  A folder
 * delam wrote is judged against its scene.ini, the effective scene the run computed;
 * SCENE and the options then only say what the run was meant to be: where they differ
 * from it on a key a check reads (REF_KEYS in check_folder.c) the folder is refused, naming the
 * keys and both values.  Another code's folder is judged against SCENE with the
 * options.  summary_scene (from ver_check_finished) names the scene in the labels when
 * no SCENE is given.  0, or 2 with err. */
int ver_check_scene(const ver_check_opts *o, const char *summary_scene, ver_scene *vs, char *err, size_t errlen);

#endif
