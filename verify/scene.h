/*
 * scene.h - scene files (INI, read with Debian's libinih) and their validation.
 *
 * Every key is checked where it enters: unknown, missing, not a number, or out of
 * its physical range gives one line  file:line: section.key: what is wrong (what is allowed).
 * A value set on the command line (--set, --h, ...) is reported as  file: command line: ...
 */
#ifndef DELAM_SCENE_H
#define DELAM_SCENE_H

#include <stddef.h>
#include <stdio.h>

#include "ana.h"
#include "mpm.h"

#define VER_MAX_SNAP 16
#define VER_NKEYS 57
#define VER_NSECT 15
#define VER_MAX_OVER 32

typedef struct {
  char name[64];              /* scene name: the file's base name without .ini          */
  char path[512];             /* the file it came from                                  */
  mpm_scene sc;               /* the kernel's description                               */
  double snap[VER_MAX_SNAP];  /* end displacements at which particles are written       */
  int nsnap;
  double interval;            /* load/energy rows every this much end displacement      */
  double stop_margin;         /* run: stop this far in delta past detected separation (0: never early) */
  double sep_load_frac;       /* run: separation detected when |P| < this fraction of the peak */
  int allow_unstable;         /* accept dt above the CFL bound                           */
  int damping_beta_cell;      /* time.damping_beta = cell: h / sqrt(E / rho), likewise      */
  int preset;                 /* method.preset: a preset of scene_method.c (-1: none)      */
  int damping_critical;       /* time.damping = critical: the rate is set from the bar, to
                                 2 pi sqrt(E / rho) / L, after the file and each override */
  int line[VER_NKEYS];        /* line each key was set on (0: default, -1: command line) */
  int seen[VER_NKEYS];
  int sect_line[VER_NSECT];   /* line of each section's first [header] (0: absent)       */
  int nlines;                 /* lines in the file                                      */
  char over[VER_MAX_OVER][128]; /* the overrides set after the file (ver_scene_set), in order */
  int nover;
  double file_h, file_dt;     /* grid.h and time.dt as the file gave them               */
} ver_scene;

/* Method presets (scene_method.c): each a list of "section.key=value" rows of method
 * keys; a method key a preset does not name takes its default.  A file's
 * [method] preset gives the keys the file does not set (ver_method_apply_file, with
 * line, the preset's line, for messages); the override method.preset=NAME (delam run
 * --method NAME) makes every method key NAME's, dropping the file's and the earlier
 * overrides of method keys (ver_method_apply_cmd).  Both use vs->preset. */
int ver_method_find(const char *name);        /* index of a preset, or -1            */
const char *ver_method_name(int preset);      /* its name; "none" for -1             */
int ver_method_rows(int preset, const char *const **sets); /* its rows: how many     */
int ver_method_key(int ki);                   /* 1 if key ki of the table is a method key */
int ver_method_held(int ki);                  /* 1: a method key the presets hold, listed apart */
const char *ver_method_where(const ver_scene *vs); /* "scene file", "command line" or "none" */
void ver_method_list(char *buf, size_t len);  /* "paper, band or interface"         */
int ver_method_apply_file(ver_scene *vs, int line, char *msg, size_t len);
int ver_method_apply_cmd(ver_scene *vs, char *msg, size_t len);
/* The method keys whose values differ from the preset's (or, without one, from their
 * defaults), as "section.key=value" into out: how many (at most max). */
int ver_method_overrides(const ver_scene *vs, char out[][64], int max);

/* The paper preset's rows: the overrides that turn any scene file's method into the
 * paper's (the report's and the bench's paper runs). */
#define VER_PAPER_NSETS 13
extern const char *const ver_paper_sets[VER_PAPER_NSETS];

/* The overrides that turn an inclined paper scene file (fig7, fig8) back to the band
 * method it ran until it took the cohesive interface (scene_bar.c; docs/methods.md).
 * Returns how many (at most VER_BAND_NSETS) and points *sets at them; 0 for a scene
 * without one. */
#define VER_BAND_NSETS 6
int ver_band_sets(const char *scene, const char *const **sets);

/* Reads and validates a scene file.  Returns 0, or 2 with one line in err. */
int ver_scene_load(const char *path, ver_scene *vs, char *err, size_t errlen);
/* Parses it without the final validation, so that overrides can follow.  Files
 * larger than VER_SCENE_MAX bytes or holding a NUL byte are refused. */
#define VER_SCENE_MAX (1 << 20)
int ver_scene_parse(const char *path, ver_scene *vs, char *err, size_t errlen);
/* The same for a scene held in memory; name stands for the file in messages. */
int ver_scene_parse_string(const char *text, const char *name, ver_scene *vs, char *err, size_t errlen);
/* Sets one key ("section.key=value" style override, as from --set).  grid.h=H also
 * scales time.dt with it, keeping the file's Courant number as --h does, unless time.dt
 * was set on the command line before it. */
int ver_scene_set(ver_scene *vs, const char *assignment, char *err, size_t errlen);
/* Checks presence, ranges, the rules between keys (h divides L and H, ppc a square,
 * the CFL bound, sizes the kernel can allocate) and fills the defaults.  Returns 0 or 2. */
int ver_scene_validate(ver_scene *vs, char *err, size_t errlen);
/* The grip speed against the wave speed: (speed / c) / (min(snf, stf) / E), the strain
 * the grip adds in one wave transit L / c over the strain at initiation; 0 without
 * decohesion or in a free vibration.  Fig. 6 at speed 0.001: 0.031.  Measured there
 * (METHODS: h 1, 4 ppc) the curve error is first order in the speed, about 0.6 times
 * this ratio; a scene above VER_RATE_REFUSE (the peak within one transit: a wave problem,
 * not a quasi-static one) is refused, one above VER_RATE_WARN runs with a warning. */
#define VER_RATE_REFUSE 1.0
#define VER_RATE_WARN 0.1
double ver_scene_rate_ratio(const mpm_scene *sc);
/* The period of the scene's axial mode m (vibration.mode) of the bar held in x at both
 * ends: 2 L / (m c), c = sqrt(E / rho) (uniaxial stress: plane stress with free lateral
 * faces), times Love's correction for the lateral inertia of the Poisson contraction,
 * sqrt(1 + nu^2 k^2 r^2), k = m pi / L, r^2 = H^2 / 12 (the strip's lateral radius of
 * gyration).  For the default bar, mode 1, the correction is +0.07 %. */
double ver_scene_vib_period(const mpm_scene *sc);
/* Case id: scene, h and ppc, then every override but grid.h, grid.ppc and a time.dt
 * that only keeps the file's Courant number, each as ver_scene_id_part writes it, e.g.
 * "fig6-h4-ppc4", "fig6-h8-ppc1-E2048", "fig6-h8-ppc4-static" (the last value of each
 * key).  Two runs of different scenes never get the same id. */
void ver_scene_case_id(const ver_scene *vs, char *buf, size_t len);
/* One override "section.key=value" as a part of a folder name a person can type: the
 * key and its number without exponent ("E2048", "separation0.98", "a0_100" after a
 * digit), the word alone for a type or preset ("static", "els", "paper"), else the key
 * and its word ("scheme_musl", "Le_zone"). */
void ver_scene_id_part(const char *set, char *buf, size_t len);
/* v as ver_scene_fmt_num writes it, without exponent (a folder name). */
void ver_scene_id_num(double v, char *buf, size_t len);
/* v in the shortest form that reads back as v exactly (at most 17 digits), without an
 * exponent from 1e-9 to 1e15. */
void ver_scene_fmt_num(double v, char *buf, size_t len);
/* Scene, h and ppc only, e.g. "fig6-h4-ppc4" (verify adds its own variant names). */
void ver_scene_base_id(const ver_scene *vs, char *buf, size_t len);
/* The effective scene as an INI file: every key with the value the run uses (defaults
 * filled in; numbers to 17 digits), so that reading it back gives the same scene.  The
 * header comments name the source file and the overrides.  0 or -1 (write error). */
int ver_scene_write_ini(const ver_scene *vs, FILE *f);
#define VER_SCHEMA_SCENE 1     /* its first line: "; delam scene.ini schema 1, ..." */
/* The key table as a Markdown table (section, key, type, required, allowed, default),
 * for docs/scene-keys.md, which a test holds to it. */
void ver_scene_keys_markdown(FILE *f);
/* The word of an enumerated key's current value ("musl", "gimp", ...); "" if the key
 * is not one (scene_ini.c). */
const char *ver_scene_word(const ver_scene *vs, const char *section, const char *key);
/* The closed-form bar of the scene (analytic/ana.h; alpha > 90 folded to 180 - alpha,
 * the same line).  0, or 2 with the reason in err (scene_bar.c). */
int ver_scene_bar(const mpm_scene *sc, ana_bar *bar, char *err, size_t len);
/* What the static solver refuses before a run: the kernel's rules (mpm_static_refusal) and
 * a softening band on a bar whose closed form snaps back (g < 1; docs/static.md, "Where it
 * stops").  0, or 2 with the reason in err (scene_bar.c). */
int ver_static_refusal(const mpm_scene *sc, char *err, size_t len);

#endif
