/*
 * scene_keys.h - private to the scene module (scene_keys.c: the key table; scene.c: the
 * parser; scene_check.c: validation; scene_ini.c: case ids and writing a scene back;
 * scene_method.c: the method presets): the table of keys, each with its type, range and
 * default, and the helpers on it.
 */
#ifndef DELAM_VER_SCENE_KEYS_H
#define DELAM_VER_SCENE_KEYS_H

#include <stddef.h>

#include "scene.h"

typedef enum { K_DBL, K_INT, K_LE, K_SCHEME, K_MOTION, K_SHAPE, K_FIELDS, K_NODEMASS, K_BC, K_HEAD, K_CONTROL, K_IMPSIZE, K_DAMPFROM, K_DAMPABOUT, K_PATH, K_SHEAR, K_SHARE, K_WEIGHTS, K_PRESET, K_SOLVER, K_SPECIMEN, K_GRIPS, K_LIST } ktype;

/* Range kinds: (lo, hi) open, [lo, hi) half open, etc. encoded by flags. */
enum { LO_OPEN = 1, LO_CLOSED = 2, HI_OPEN = 4, HI_CLOSED = 8 };

typedef struct {
  const char *section, *key;
  ktype type;
  size_t off;          /* offset in ver_scene (K_DBL, K_INT, K_LE, ...) */
  int required;        /* 1 always, 2 only when decohesion.model > 0, 3 unless
                          vibration.mode > 0, 0 optional */
  double lo, hi;
  int range;           /* LO_* | HI_* */
  double def;          /* default when optional */
  const char *allowed; /* human text of the range */
} keydef;

extern const keydef ver_scene_keys[];
extern const int ver_scene_nkeys;

/* Size limits: far above any sensible scene, low enough that every count fits in an
 * int and every allocation in memory (and that no double-to-integer cast overflows). */
#define MAX_NODES 1e8     /* grid nodes                        */
#define MAX_PARTICLES 1e8 /* particles                         */
#define MAX_STEPS 1e12    /* time steps to run.end_delta       */
#define MAX_ROWS 1e7      /* rows of load.csv and energy.csv   */
#define MAX_LINE 500      /* characters on a line of the file  */

/* 1 if key i is the first of its section in the table. */
int ver_scene_key_first(int i);
/* Index of a section among the distinct sections of the table, or -1. */
int ver_scene_key_section(const char *section);
/* Index of section.key in the table, or -1; ver_scene_key_idx asserts it exists. */
int ver_scene_key_find(const char *section, const char *key);
int ver_scene_key_idx(const char *section, const char *key);
/* 1 if v is inside key k's range. */
int ver_scene_key_in_range(const keydef *k, double v);
/* A finite number: 0, 1 (not a number) or 2 (not finite). */
int ver_scene_key_num(const char *s, double *v);
/* Enumerated keys: 1 if type t is one; the value of a word (0, or -1 if it is not
 * allowed); the word of a value (the type's first word if none matches). */
int ver_scene_enum_type(ktype t);
int ver_scene_enum_value(ktype t, const char *word, int *value);
const char *ver_scene_enum_word(ktype t, int value);
/* Checks value for key ki and stores it; 0, or 2 with a message (no location) in msg. */
int ver_scene_key_set(ver_scene *vs, int ki, const char *value, char *msg, size_t len);
/* User text fit for a one-line message: at most 40 characters, control characters
 * shown as '?'. */
const char *ver_scene_shown(const char *s, char *buf, size_t len);
/* "file:line" of key ki: its line, else its section's header, else the file's end. */
const char *ver_scene_key_at(const ver_scene *vs, int ki, char *buf, size_t len);

#endif
