/*
 * datadir.h - where the scene files are, so that `delam run fig6`, verify, report and
 * bench work from any folder, in the build tree and once installed.
 */
#ifndef DELAM_DATADIR_H
#define DELAM_DATADIR_H

#include <stddef.h>

/* The scene folder, the first that exists of: $DELAM_SCENES; data/scenes in the
 * current folder; <program>/../share/delam/scenes (an installed program, also under
 * DESTDIR); the installed data folder; the source tree's data/scenes.  NULL if none. */
const char *ver_scene_dir(void);

/* The gnuplot scripts and text templates of `delam report`, the first that exists of:
 * $DELAM_REPORTS; ./reports (holding common.gp); <program>/../share/delam/reports; the
 * installed one; the source tree's reports/.  NULL if none. */
const char *ver_report_dir(void);

/* A scene argument: an existing file as given; otherwise a name ("fig6" or
 * "fig6.ini") in ver_scene_dir().  Writes the path to out; 0, or 2 with a message in
 * err naming the folders tried. */
int ver_scene_resolve(const char *arg, char *out, size_t len, char *err, size_t errlen);

#endif
