/*
 * datadir.h - where the scene files are (and opening only regular files as input), so that `delam run fig6`, verify, report and
 * bench work from any folder, in the build tree and once installed.
 */
#ifndef DELAM_DATADIR_H
#define DELAM_DATADIR_H

#include <stddef.h>
#include <stdio.h>

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

/* fopen(path, "rb") of a regular file only: a FIFO, device, socket or directory is not
 * opened (a FIFO would block until a writer came).  NULL with errno set; for a file that
 * is not regular errno is EINVAL and *what (if not NULL) names its kind ("a FIFO"). */
FILE *ver_open_regular(const char *path, const char **what);
/* "a FIFO", "a directory", ... for a st_mode. */
const char *ver_file_kind(unsigned mode);

#endif
