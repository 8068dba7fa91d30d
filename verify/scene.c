/*
 * scene.c - scene files: a table of keys, each with its type, range and default,
 * read by inih into a ver_scene and validated once where it enters.
 *
 * Every error is one line  file:line: section.key: what is wrong (what is allowed).
 * inih gives a line number only when parsing fails, counts a line longer than its
 * buffer as two, and takes an indented line as the continuation of the previous
 * value; so it reads through our own line reader, which counts the lines, strips
 * the indentation, checks each line's shape ([section], key = value, comment or
 * blank) and stops at the first error.  The handler therefore always knows its line.
 */
#include <ctype.h>
#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ini.h>

#include "build_info.h"
#include "datadir.h"
#include "scene.h"
#include "scene_keys.h"

#define OFF(f) offsetof(ver_scene, sc.f) /* the kernel's description */
#define VOFF(f) offsetof(ver_scene, f)  /* run control, not the kernel's */
const keydef ver_scene_keys[] = {
  {"bar", "L", K_DBL, OFF(L), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"bar", "H", K_DBL, OFF(H), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"material", "E", K_DBL, OFF(E), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"material", "nu", K_DBL, OFF(nu), 1, -1, 0.5, LO_OPEN | HI_OPEN, 0, "in (-1, 0.5)"},
  {"material", "rho", K_DBL, OFF(rho), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"decohesion", "model", K_INT, OFF(model), 1, 0, 2, LO_CLOSED | HI_CLOSED, 0, "0 (none), 1 (associated) or 2 (opening only)"},
  {"decohesion", "alpha", K_DBL, OFF(alpha_deg), 2, 0, 180, LO_CLOSED | HI_OPEN, 0, "in [0, 180) deg"},
  {"decohesion", "snf", K_DBL, OFF(snf), 2, 0, 0, LO_OPEN, 0, "> 0"},
  {"decohesion", "stf", K_DBL, OFF(stf), 2, 0, 0, LO_OPEN, 0, "> 0"},
  {"decohesion", "U0", K_DBL, OFF(U0), 2, 0, 0, LO_OPEN, 0, "> 0"},
  {"decohesion", "s0", K_DBL, OFF(s0), 0, 0, 0, LO_OPEN, -1, "> 0 (default: snf)"},
  {"decohesion", "q", K_DBL, OFF(q), 2, 0, 0, LO_OPEN, 0, "> 0"},
  {"decohesion", "separation", K_DBL, OFF(sep_threshold), 0, 0, 1, LO_OPEN | HI_CLOSED, 0.98, "in (0, 1] (default 0.98; 1 with solver.type = static)"},
  {"decohesion", "eta", K_DBL, OFF(eta), 0, 0, 1e6, LO_CLOSED | HI_CLOSED, 0, "in [0, 1e6]: viscosity, a time (0: the paper's rate-independent law)"},
  {"decohesion", "Le", K_LE, OFF(le_mode), 0, 0, 0, 0, MPM_LE_CELL, "cell, particle, staircase, row or zone"},
  {"decohesion", "Le_factor", K_DBL, OFF(le_factor), 0, 0, 100, LO_OPEN | HI_CLOSED, 1.0, "in (0, 100]: Le times this"},
  {"decohesion", "path", K_PATH, OFF(path), 0, 0, 0, 0, MPM_PATH_FREE, "free (the paper: any particle may soften), line (only near the failure line through the imperfection) or interface (no particle softens: the line is a cohesive interface between two velocity fields; needs grid.fields = two, grid.shape = gimp, time.scheme = musl, Model 1 with q = 1)"},
  {"decohesion", "share", K_SHARE, OFF(share), 0, 0, 0, 0, MPM_SHARE_STICK, "stick (path = interface: each node of a softening segment keeps its own stick impulse, scaled by the segment's factor) or line (each node takes the segment's traction times its length of line; needs path = interface, alpha = 90, grid.motion = stretch and the crack on a node column)"},
  {"decohesion", "reversed_shear", K_SHEAR, OFF(reversed_shear), 0, 0, 0, 0, MPM_SHEAR_EVEN, "even (the paper: shear either way softens) or closing (shear against a particle's slip closes it elastically, as compression closes an opening)"},
  {"decohesion", "path_reach", K_DBL, OFF(path_reach), 0, 0, 100, LO_CLOSED | HI_CLOSED, 1.0, "in [0, 100] cells: path = line's band beyond the cells the line crosses (0 locks; docs/bands.md sec. 3c)"},
  {"imperfection", "snf_factor", K_DBL, OFF(imp_factor), 0, 0, 1, LO_OPEN | HI_CLOSED, 1.0, "in (0, 1]"},
  {"imperfection", "stf_factor", K_DBL, OFF(imp_stf_factor), 0, 0, 1, LO_OPEN | HI_CLOSED, 1.0, "in (0, 1]"},
  {"imperfection", "x", K_DBL, OFF(imp_x), 0, 0, 0, 0, -1, "a number (default: L / 2)"},
  {"imperfection", "y", K_DBL, OFF(imp_y), 0, 0, 0, 0, -1, "a number (default: H / 2)"},
  {"imperfection", "size", K_IMPSIZE, OFF(imp_size), 0, 0, 0, 0, MPM_IMP_PARTICLE, "particle (the paper's: the particle nearest x, y) or cell (every particle of its cell)"},
  {"grid", "h", K_DBL, OFF(h), 1, 0, 0, LO_OPEN, 0, "> 0, dividing L and H"},
  {"grid", "ppc", K_INT, OFF(ppc), 1, 1, 1024, LO_CLOSED | HI_CLOSED, 0, "a perfect square from 1 to 1024: 1, 4, 9, ..., 1024"},
  {"grid", "margin", K_DBL, OFF(margin), 0, 0, 0, LO_CLOSED, 0, ">= 0: empty space around the bar, a length (one cell is always added)"},
  {"time", "dt", K_DBL, OFF(dt), 1, 0, 0, LO_OPEN, 0, "> 0 and below the CFL bound h / (c sqrt 2)"},
  {"time", "damping", K_DBL, OFF(damping), 0, 0, 0, LO_CLOSED, 0, ">= 0 and below 1 / dt: a rate, the damping of each node's velocity about its slow drift (0: none, the paper), or critical: 2 pi sqrt(E / rho) / L, twice the bar's first axial frequency"},
  {"time", "damping_from", K_DAMPFROM, OFF(damping_from), 0, 0, 0, 0, MPM_DAMP_START, "start (from the first step) or cut (once the band has cut the bar)"},
  {"time", "damping_about", K_DAMPABOUT, OFF(damping_about), 0, 0, 0, 0, MPM_DAMP_DRIFT, "drift (each node's slow drift, a low-pass) or parts (after the cut, the motion of the end holding each part)"},
  {"time", "damping_beta", K_DBL, OFF(damping_beta), 0, 0, 0, LO_CLOSED, 0, ">= 0, a time: a viscous stress beta C : grad v on the particles not separated, from damping_from on (0: none), or cell: h / sqrt(E / rho), critical for the grid's fastest axial mode; needs time.scheme = musl"},
  {"time", "damping_tau", K_DBL, OFF(damping_tau), 0, 0, 0, LO_CLOSED, 0, ">= 0: the damping's low-pass time (0: 2 L / c)"},
  {"time", "scheme", K_SCHEME, OFF(scheme), 0, 0, 0, 0, MPM_SCHEME_USL, "usl (the paper), musl, usf or usavg"},
  {"grid", "motion", K_MOTION, OFF(grid_motion), 0, 0, 0, 0, MPM_GRID_FIXED, "fixed (the paper) or stretch (follows the bar's mean stretch)"},
  {"grid", "weights", K_WEIGHTS, OFF(weights), 0, 0, 0, 0, MPM_WEIGHTS_CURRENT, "current (the paper: shape functions at the particles' positions) or laid (at the places the grid was laid at, carried by its stretch, until the bar is cut; needs grid.motion = stretch)"},
  {"grid", "fields", K_FIELDS, OFF(fields), 0, 0, 0, 0, MPM_FIELDS_ONE, "one (the paper) or two (one per side of a band once it has cut the bar)"},
  {"grid", "shape", K_SHAPE, OFF(shape), 0, 0, 0, 0, MPM_SHAPE_LINEAR, "linear (the paper's bilinear hats) or gimp (uGIMP)"},
  {"grid", "node_mass", K_NODEMASS, OFF(node_mass), 0, 0, 0, 0, MPM_NODEMASS_LUMPED, "lumped (the paper) or limited (a mass floor in v^L where a node is stiffer than the step can integrate; usl and usavg, linear shapes)"},
  {"grid", "bc", K_BC, OFF(bc), 0, 0, 0, 0, MPM_BC_LAGRANGIAN, "lagrangian (on v^L only), both (on v and v^L) or consistent"},
  {"loading", "head", K_HEAD, OFF(head), 0, 0, 0, 0, MPM_HEAD_RIGID, "rigid (the paper's rigid head) or none (the node column x = 0 alone)"},
  {"vibration", "mode", K_INT, OFF(vib_mode), 0, 0, 1000, LO_CLOSED | HI_CLOSED, 0, "0 (none) or the axial mode m, 1 to 1000, to start from"},
  {"vibration", "amplitude", K_DBL, OFF(vib_amp), 0, 0, 0, LO_OPEN, 0.03, "> 0: the mode's velocity amplitude"},
  {"vibration", "periods", K_DBL, OFF(vib_periods), 0, 0, 1e6, LO_OPEN | HI_CLOSED, 25, "in (0, 1e6]: the run's length in periods 2 L / (m c)"},
  {"loading", "control", K_CONTROL, OFF(control), 0, 0, 0, 0, MPM_CONTROL_GRIP,
   "grip or dissipation"},
  {"loading", "speed", K_DBL, OFF(speed), 1, 0, 0, LO_OPEN, 0, "> 0 and quasi-static: speed / c <= min(snf, stf) / E (warning above a tenth of that)"},
  {"run", "end_delta", K_DBL, OFF(end_delta), 3, 0, 0, LO_OPEN, 0, "> 0 (default with vibration.mode > 0: vibration.periods periods)"},
  {"run", "stop_margin", K_DBL, VOFF(stop_margin), 0, 0, 0, LO_CLOSED, 0.1, ">= 0 (0: run to end_delta)"},
  {"run", "sep_load", K_DBL, VOFF(sep_load_frac), 0, 0, 1, LO_OPEN | HI_OPEN, 0.02, "in (0, 1)"},
  {"solver", "type", K_SOLVER, OFF(solver), 0, 0, 0, 0, MPM_SOLVER_EXPLICIT, "explicit (the paper's dynamic step at loading.speed) or static (load increments in equilibrium, path-following through a snapback; time.* and loading.speed unused)"},
  {"output", "snapshots", K_LIST, 0, 0, 0, 0, LO_CLOSED, 0, "a comma-separated list of end displacements >= 0"},
  {"output", "interval", K_DBL, 0, 0, 0, 0, LO_OPEN, -1, "> 0 (default: 0.0005)"},
};
const int ver_scene_nkeys = (int)(sizeof ver_scene_keys / sizeof ver_scene_keys[0]);

/* The words of the enumerated keys, one row per allowed word: read by the parser, written
 * back by ver_scene_write_ini (scene_ini.c).  The first word of a type is its fallback. */
static const struct {
  ktype type;
  const char *word;
  int value;
} ENUMS[] = {
  {K_LE, "cell", MPM_LE_CELL}, {K_LE, "particle", MPM_LE_PARTICLE}, {K_LE, "staircase", MPM_LE_STAIRCASE}, {K_LE, "row", MPM_LE_ROW}, {K_LE, "zone", MPM_LE_ZONE},
  {K_SCHEME, "usl", MPM_SCHEME_USL}, {K_SCHEME, "musl", MPM_SCHEME_MUSL}, {K_SCHEME, "usf", MPM_SCHEME_USF},
  {K_SCHEME, "usavg", MPM_SCHEME_USAVG},
  {K_BC, "lagrangian", MPM_BC_LAGRANGIAN}, {K_BC, "both", MPM_BC_BOTH}, {K_BC, "consistent", MPM_BC_CONSISTENT},
  {K_HEAD, "rigid", MPM_HEAD_RIGID}, {K_HEAD, "none", MPM_HEAD_NONE},
  {K_CONTROL, "grip", MPM_CONTROL_GRIP}, {K_CONTROL, "dissipation", MPM_CONTROL_DISSIPATION},
  {K_IMPSIZE, "particle", MPM_IMP_PARTICLE}, {K_IMPSIZE, "cell", MPM_IMP_CELL},
  {K_DAMPFROM, "start", MPM_DAMP_START}, {K_DAMPFROM, "cut", MPM_DAMP_CUT},
  {K_DAMPABOUT, "drift", MPM_DAMP_DRIFT}, {K_DAMPABOUT, "parts", MPM_DAMP_PARTS},
  {K_PATH, "free", MPM_PATH_FREE}, {K_PATH, "line", MPM_PATH_LINE}, {K_PATH, "interface", MPM_PATH_IFACE},
  {K_SHEAR, "even", MPM_SHEAR_EVEN}, {K_SHEAR, "closing", MPM_SHEAR_CLOSING},
  {K_SHARE, "stick", MPM_SHARE_STICK}, {K_SHARE, "line", MPM_SHARE_LINE},
  {K_MOTION, "fixed", MPM_GRID_FIXED}, {K_MOTION, "stretch", MPM_GRID_STRETCH},
  {K_WEIGHTS, "current", MPM_WEIGHTS_CURRENT}, {K_WEIGHTS, "laid", MPM_WEIGHTS_LAID},
  {K_SHAPE, "linear", MPM_SHAPE_LINEAR}, {K_SHAPE, "gimp", MPM_SHAPE_GIMP},
  {K_FIELDS, "one", MPM_FIELDS_ONE}, {K_FIELDS, "two", MPM_FIELDS_TWO},
  {K_NODEMASS, "lumped", MPM_NODEMASS_LUMPED}, {K_NODEMASS, "limited", MPM_NODEMASS_LIMITED},
  {K_SOLVER, "explicit", MPM_SOLVER_EXPLICIT}, {K_SOLVER, "static", MPM_SOLVER_STATIC},
};
#define NENUMS (sizeof ENUMS / sizeof ENUMS[0])

int ver_scene_enum_type(ktype t)
{
  for (size_t i = 0; i < NENUMS; i++)
    if (ENUMS[i].type == t)
      return 1;
  return 0;
}

int ver_scene_enum_value(ktype t, const char *word, int *value)
{
  for (size_t i = 0; i < NENUMS; i++)
    if (ENUMS[i].type == t && !strcmp(ENUMS[i].word, word)) {
      *value = ENUMS[i].value;
      return 0;
    }
  return -1;
}

const char *ver_scene_enum_word(ktype t, int value)
{
  const char *first = "";
  for (size_t i = 0; i < NENUMS; i++)
    if (ENUMS[i].type == t) {
      if (!*first)
        first = ENUMS[i].word;
      if (ENUMS[i].value == value)
        return ENUMS[i].word;
    }
  return first;
}

_Static_assert(sizeof ver_scene_keys / sizeof ver_scene_keys[0] <= VER_NKEYS, "VER_NKEYS too small for the key table");

typedef struct {
  ver_scene *vs;
  const char *text; /* the scene, NUL-terminated                               */
  size_t pos;       /* where the reader is in text                             */
  int line;         /* lines handed to inih so far: the line the handler is on */
  int errline;      /* line of the first error found by reader or handler      */
  char msg[640];    /* that error, without "file:line: "                       */
} parse_ctx;

/* 1 if key i is the first of its section in the table. */
int ver_scene_key_first(int i)
{
  for (int j = 0; j < i; j++)
    if (!strcmp(ver_scene_keys[j].section, ver_scene_keys[i].section))
      return 0;
  return 1;
}

/* Index of a section among the distinct sections of the table, or -1. */
int ver_scene_key_section(const char *section)
{
  for (int i = 0, n = 0; i < ver_scene_nkeys; i++)
    if (ver_scene_key_first(i)) {
      assert(n < VER_NSECT);
      if (!strcmp(ver_scene_keys[i].section, section))
        return n;
      n++;
    }
  return -1;
}

int ver_scene_key_find(const char *section, const char *key)
{
  for (int i = 0; i < ver_scene_nkeys; i++)
    if (!strcmp(ver_scene_keys[i].section, section) && !strcmp(ver_scene_keys[i].key, key))
      return i;
  return -1;
}

/* User text fit for a one-line message: at most 40 characters, control characters
 * shown as '?'. */
static const char *shown(const char *s, char *buf, size_t len)
{
  size_t i = 0;
  for (; s[i] && i < 40 && i + 4 < len; i++)
    buf[i] = (unsigned char)s[i] < 0x20 || s[i] == 0x7f ? '?' : s[i];
  if (s[i] && i + 4 <= len) {
    memcpy(buf + i, "...", 3);
    i += 3;
  }
  buf[i] = '\0';
  return buf;
}

/* The keys of a section, or with section NULL all sections: "a, b, c" into buf. */
static void list_names(const char *section, char *buf, size_t len)
{
  buf[0] = '\0';
  size_t n = 0;
  for (int i = 0; i < ver_scene_nkeys && n < len; i++) {
    if (section ? strcmp(ver_scene_keys[i].section, section) != 0 : !ver_scene_key_first(i))
      continue;
    n += (size_t)snprintf(buf + n, len - n, "%s%s", n ? ", " : "", section ? ver_scene_keys[i].key : ver_scene_keys[i].section);
  }
}

int ver_scene_key_in_range(const keydef *k, double v)
{
  if ((k->range & LO_OPEN) && !(v > k->lo)) return 0;
  if ((k->range & LO_CLOSED) && !(v >= k->lo)) return 0;
  if ((k->range & HI_OPEN) && !(v < k->hi)) return 0;
  if ((k->range & HI_CLOSED) && !(v <= k->hi)) return 0;
  return 1;
}

/* A finite number with nothing but blanks after it: 0; 1 not a number; 2 not finite. */
int ver_scene_key_num(const char *s, double *v)
{
  char *end;
  errno = 0;
  *v = strtod(s, &end);
  if (end == s)
    return 1;
  while (*end == ' ' || *end == '\t')
    end++;
  if (*end)
    return 1;
  if (!isfinite(*v) || (errno == ERANGE && fabs(*v) > 1.0))
    return 2;
  return 0;
}

/* Number keys that also take one word, for a value the scene itself gives: the word sets
 * the flag, and resolve_damping derives the number after the file and every override. */
static const struct {
  const char *section, *key, *word;
  size_t flag;
} derived_words[] = {
  {"time", "damping", "critical", VOFF(damping_critical)},
  {"time", "damping_beta", "cell", VOFF(damping_beta_cell)},
};

/* The flag of key k's word (NULL: none), and the word into *word. */
static int *derived_flag(ver_scene *vs, const keydef *k, const char **word)
{
  for (size_t i = 0; i < sizeof derived_words / sizeof derived_words[0]; i++)
    if (!strcmp(k->section, derived_words[i].section) && !strcmp(k->key, derived_words[i].key)) {
      *word = derived_words[i].word;
      return (int *)((char *)vs + derived_words[i].flag);
    }
  return NULL;
}

/* Checks value for key ki and stores it; 0, or 2 with a message (no location) in msg. */
static int set_key(ver_scene *vs, int ki, const char *value, char *msg, size_t len)
{
  const keydef *k = &ver_scene_keys[ki];
  char sv[48];
  char *base = (char *)vs;
  int *flag = NULL;         /* derived_words: the key's word flag, if it has one */
  const char *word = NULL;
  while (*value == ' ' || *value == '\t')
    value++;
  if (!*value) {
    snprintf(msg, len, "%s.%s: empty value (%s)", k->section, k->key, k->allowed);
    return 2;
  }
  if (ver_scene_enum_type(k->type)) {
    int mode;
    if (ver_scene_enum_value(k->type, value, &mode) != 0) {
      snprintf(msg, len, "%s.%s: '%s' is not allowed (%s)", k->section, k->key, shown(value, sv, sizeof sv),
               k->allowed);
      return 2;
    }
    *(int *)(base + k->off) = mode;
  } else if (k->type == K_LIST) {
    double v[VER_MAX_SNAP];
    int n = 0;
    for (const char *p = value;;) {
      const char *e = strchr(p, ',');
      char item[64];
      const size_t il = e ? (size_t)(e - p) : strlen(p);
      if (il >= sizeof item) {
        snprintf(msg, len, "%s.%s: an item is too long (%s)", k->section, k->key, k->allowed);
        return 2;
      }
      memcpy(item, p, il);
      item[il] = '\0';
      const char *t = item;
      while (*t == ' ' || *t == '\t') t++;
      if (!*t) {
        snprintf(msg, len, "%s.%s: an empty item in the list (%s)", k->section, k->key, k->allowed);
        return 2;
      }
      if (n == VER_MAX_SNAP) {
        snprintf(msg, len, "%s.%s: more than %d snapshots (%s)", k->section, k->key, VER_MAX_SNAP, k->allowed);
        return 2;
      }
      const int r = ver_scene_key_num(t, &v[n]);
      if (r || v[n] < 0.0) {
        snprintf(msg, len, "%s.%s: '%s' is %s (%s)", k->section, k->key, shown(t, sv, sizeof sv),
                 r == 1 ? "not a number" : r == 2 ? "not a finite number" : "negative", k->allowed);
        return 2;
      }
      n++;
      if (!e)
        break;
      p = e + 1;
    }
    memcpy(vs->snap, v, sizeof(double) * (size_t)n);
    vs->nsnap = n;
  } else if ((flag = derived_flag(vs, k, &word)) && !strcmp(value, word)) {
    *flag = 1; /* the number is the scene's: resolve_damping */
  } else {
    double v;
    const int r = ver_scene_key_num(value, &v);
    if (r) {
      snprintf(msg, len, "%s.%s: '%s' is %s (%s)", k->section, k->key, shown(value, sv, sizeof sv),
               r == 1 ? "not a number" : "not a finite number", k->allowed);
      return 2;
    }
    if (k->type == K_INT && v != floor(v)) {
      snprintf(msg, len, "%s.%s: '%s' is not an integer (%s)", k->section, k->key, shown(value, sv, sizeof sv),
               k->allowed);
      return 2;
    }
    if (!ver_scene_key_in_range(k, v)) {
      snprintf(msg, len, "%s.%s: %s is out of range (%s)", k->section, k->key, shown(value, sv, sizeof sv),
               k->allowed);
      return 2;
    }
    if (flag)
      *flag = 0; /* a number given after the word replaces it */
    if (!strcmp(k->section, "output"))
      vs->interval = v;
    else if (k->type == K_INT)
      *(int *)(base + k->off) = (int)v; /* in range, so it fits */
    else
      *(double *)(base + k->off) = v;
  }
  return 0;
}

/* Records the first error at the current line; returns 1. */
__attribute__((format(printf, 2, 3))) static int fail(parse_ctx *c, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(c->msg, sizeof c->msg, fmt, ap);
  va_end(ap);
  c->errline = c->line;
  return 1;
}

/* The shape of one line (indentation already stripped): 0 fine, 1 error recorded. */
static int check_line(parse_ctx *c, const char *s, size_t n)
{
  char b[MAX_LINE + 1], sv[48];
  memcpy(b, s, n);
  b[n] = '\0';
  char *p = b;
  if (c->line == 1 && !strncmp(p, "\xEF\xBB\xBF", 3))
    p += 3; /* UTF-8 byte order mark: inih skips it too */
  for (char *e = p + strlen(p); e > p && isspace((unsigned char)e[-1]);)
    *--e = '\0';
  if (!*p || *p == ';' || *p == '#')
    return 0;
  if (*p == '[') {
    char *e = strchr(p, ']');
    if (!e)
      return fail(c, "'%s': a [section] header without ']'", shown(p, sv, sizeof sv));
    *e = '\0';
    const char *rest = e + 1;
    while (*rest == ' ' || *rest == '\t') rest++;
    if (*rest && *rest != ';')
    {
      char sr[48];
      return fail(c, "[%s]: text after the section header ('%s')", shown(p + 1, sv, sizeof sv),
                  shown(rest, sr, sizeof sr));
    }
    const int si = ver_scene_key_section(p + 1);
    if (si < 0) {
      char all[256];
      list_names(NULL, all, sizeof all);
      return fail(c, "[%s]: unknown section (allowed: %s)", shown(p + 1, sv, sizeof sv), all);
    }
    if (!c->vs->sect_line[si])
      c->vs->sect_line[si] = c->line;
    return 0;
  }
  /* key = value: the first of '=', ':' (inih's other separator) and an inline
   * comment must be '=', with a key before it. */
  char *q = p;
  for (int blank = 0; *q && *q != '=' && *q != ':' && !(blank && *q == ';'); q++)
    blank = isspace((unsigned char)*q);
  if (*q != '=') {
    if (*q == ';') /* show the line without its comment */
      for (char *e = q; e > p && isspace((unsigned char)e[-1]);)
        *--e = '\0';
    return fail(c, "'%s' is not a 'key = value' line, a [section] header or a comment",
                shown(p, sv, sizeof sv));
  }
  if (q == p)
    return fail(c, "'%s': no key before '='", shown(p, sv, sizeof sv));
  return 0;
}

/* inih's line source: one line of the text per call, indentation stripped. */
static char *reader(char *str, int num, void *stream)
{
  parse_ctx *c = stream;
  if (c->errline || !c->text[c->pos])
    return NULL;
  const char *s = c->text + c->pos;
  const char *nl = strchr(s, '\n');
  size_t n = nl ? (size_t)(nl - s) : strlen(s);
  c->pos += n + (nl != NULL);
  c->line++;
  while (n && (*s == ' ' || *s == '\t')) {
    s++;
    n--;
  }
  const size_t most = num - 3 < MAX_LINE ? (size_t)(num - 3) : MAX_LINE;
  if (num < 4 || n > most) {
    fail(c, "a line of %zu characters (allowed: at most %zu)", n, num < 4 ? 0 : most);
    return NULL;
  }
  if (check_line(c, s, n))
    return NULL;
  memcpy(str, s, n);
  str[n] = '\n';
  str[n + 1] = '\0';
  return str;
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
  parse_ctx *c = user;
  char sv[48];
  if (c->errline)
    return 0;
  if (!section[0])
    return !fail(c, "%s: a key before any [section] header", shown(name, sv, sizeof sv));
  const int ki = ver_scene_key_find(section, name);
  if (ki < 0) {
    char all[256];
    list_names(section, all, sizeof all);
    return !fail(c, "%s.%s: unknown key (allowed in [%s]: %s)", section, shown(name, sv, sizeof sv), section, all);
  }
  ver_scene *vs = c->vs;
  if (vs->seen[ki])
    return !fail(c, "%s.%s: set twice, first on line %d (each key once)", section, name, vs->line[ki]);
  if (set_key(vs, ki, value, c->msg, sizeof c->msg)) {
    c->errline = c->line;
    return 0;
  }
  vs->seen[ki] = 1;
  vs->line[ki] = c->line;
  return 1;
}

static void scene_defaults(ver_scene *vs, const char *path)
{
  memset(vs, 0, sizeof *vs);
  snprintf(vs->path, sizeof vs->path, "%s", path);
  const char *b = strrchr(path, '/');
  b = b ? b + 1 : path;
  snprintf(vs->name, sizeof vs->name, "%s", b);
  char *dot = strrchr(vs->name, '.');
  if (dot && !strcmp(dot, ".ini"))
    *dot = '\0';
  char *base = (char *)vs;
  for (int i = 0; i < ver_scene_nkeys; i++) {
    if (ver_scene_keys[i].required || ver_scene_keys[i].type == K_LIST || !strcmp(ver_scene_keys[i].section, "output"))
      continue;
    if (ver_scene_keys[i].type == K_DBL)
      *(double *)(base + ver_scene_keys[i].off) = ver_scene_keys[i].def;
    else
      *(int *)(base + ver_scene_keys[i].off) = (int)ver_scene_keys[i].def;
  }
  vs->interval = -1;
}

/* time.damping = critical: twice the first axial angular frequency of the bar held at
 * both ends, omega_1 = pi c / L with c = sqrt(E / rho), the rate that damps that mode
 * critically (x'' + 2 omega_1 x' + omega_1^2 x = 0), the slowest ring of the release
 * (docs/bands.md sec. 5h).  Set after the file and after every override, so that a
 * changed bar changes it wherever the scene is read. */
static void resolve_damping(ver_scene *vs)
{
  if (vs->damping_critical && vs->sc.L > 0.0 && vs->sc.rho > 0.0 && vs->sc.E > 0.0)
    vs->sc.damping = 2.0 * 3.14159265358979323846 * sqrt(vs->sc.E / vs->sc.rho) / vs->sc.L;
  /* time.damping_beta = cell: h / c, the beta that damps the grid's fastest axial mode,
   * omega = 2 c / h on a lumped 1-D lattice, critically (beta omega / 2 = 1) */
  if (vs->damping_beta_cell && vs->sc.h > 0.0 && vs->sc.rho > 0.0 && vs->sc.E > 0.0)
    vs->sc.damping_beta = vs->sc.h / sqrt(vs->sc.E / vs->sc.rho);
}

int ver_scene_parse_string(const char *text, const char *name, ver_scene *vs, char *err, size_t errlen)
{
  scene_defaults(vs, name);
  parse_ctx c;
  memset(&c, 0, sizeof c);
  c.vs = vs;
  c.text = text;
  const int r = ini_parse_stream(reader, &c, handler, &c);
  /* inih's own complaint (a line it would not take that the reader let through) is
   * the error only if it comes first. */
  if (r > 0 && (!c.errline || r < c.errline)) {
    snprintf(err, errlen, "%s:%d: not a 'key = value' line, a [section] header or a comment", vs->path, r);
    return 2;
  }
  if (c.errline) {
    snprintf(err, errlen, "%s:%d: %s", vs->path, c.errline, c.msg);
    return 2;
  }
  if (r < 0) {
    snprintf(err, errlen, "%s: cannot parse: out of memory", vs->path);
    return 2;
  }
  vs->nlines = c.line;
  resolve_damping(vs);
  vs->file_h = vs->sc.h;
  vs->file_dt = vs->sc.dt;
  return 0;
}

int ver_scene_parse(const char *path, ver_scene *vs, char *err, size_t errlen)
{
  scene_defaults(vs, path);
  const char *what;
  FILE *f = ver_open_regular(path, &what);
  if (!f) {
    if (what)
      snprintf(err, errlen, "%s: %s, not a scene file (a regular file is needed)", path, what);
    else
      snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    return 2;
  }
  char *text = malloc(VER_SCENE_MAX + 1);
  if (!text) {
    fclose(f);
    snprintf(err, errlen, "%s: cannot read: out of memory", path);
    return 2;
  }
  const size_t n = fread(text, 1, VER_SCENE_MAX + 1, f);
  const int bad = ferror(f), e = errno;
  fclose(f);
  int rc = 2;
  if (bad)
    snprintf(err, errlen, "%s: cannot read: %s", path, strerror(e));
  else if (n > VER_SCENE_MAX)
    snprintf(err, errlen, "%s: larger than %d bytes: not a scene file", path, VER_SCENE_MAX);
  else if (memchr(text, '\0', n)) {
    int line = 1;
    for (const char *p = text; *p; p++)
      line += *p == '\n';
    snprintf(err, errlen, "%s:%d: a NUL byte: not a text file", path, line);
  } else {
    text[n] = '\0';
    rc = ver_scene_parse_string(text, path, vs, err, errlen);
  }
  free(text);
  return rc;
}

int ver_scene_set(ver_scene *vs, const char *assignment, char *err, size_t errlen)
{
  char buf[256], sv[48], msg[640];
  for (const char *p = assignment; *p; p++)
    if ((unsigned char)*p < 0x20 || *p == 0x7f) {
      snprintf(err, errlen, "%s: command line: '%s': a control character (expected section.key=value)", vs->path,
               shown(assignment, sv, sizeof sv));
      return 2;
    }
  if (strlen(assignment) >= sizeof buf) {
    snprintf(err, errlen, "%s: command line: '%s': too long (expected section.key=value)", vs->path,
             shown(assignment, sv, sizeof sv));
    return 2;
  }
  snprintf(buf, sizeof buf, "%s", assignment);
  char *eq = strchr(buf, '='), *dot = strchr(buf, '.');
  if (!eq || !dot || dot > eq) {
    snprintf(err, errlen, "%s: command line: '%s': expected section.key=value", vs->path,
             shown(assignment, sv, sizeof sv));
    return 2;
  }
  *eq = '\0';
  *dot = '\0';
  char *key = dot + 1;
  for (char *e = eq; e > key && isspace((unsigned char)e[-1]);)
    *--e = '\0';
  const int ki = ver_scene_key_find(buf, key);
  if (ki < 0) {
    char all[256];
    if (ver_scene_key_section(buf) >= 0)
      list_names(buf, all, sizeof all);
    else
      list_names(NULL, all, sizeof all);
    snprintf(err, errlen, "%s: command line: %s: unknown key (allowed%s%s%s: %s)", vs->path,
             shown(assignment, sv, sizeof sv), ver_scene_key_section(buf) >= 0 ? " in [" : " sections",
             ver_scene_key_section(buf) >= 0 ? buf : "", ver_scene_key_section(buf) >= 0 ? "]" : "", all);
    return 2;
  }
  if (set_key(vs, ki, eq + 1, msg, sizeof msg)) {
    snprintf(err, errlen, "%s: command line: %s", vs->path, msg);
    return 2;
  }
  vs->seen[ki] = 1;
  vs->line[ki] = -1;
  resolve_damping(vs);
  if (vs->nover == VER_MAX_OVER) {
    snprintf(err, errlen, "%s: command line: %s: more than %d overrides", vs->path, shown(assignment, sv, sizeof sv),
             VER_MAX_OVER);
    return 2;
  }
  const char *val = eq + 1;
  while (*val == ' ' || *val == '\t')
    val++;
  snprintf(vs->over[vs->nover++], sizeof vs->over[0], "%s.%s=%s", ver_scene_keys[ki].section, ver_scene_keys[ki].key, val);
  return 0;
}

double ver_scene_vib_period(const mpm_scene *sc)
{
  const double c = sqrt(sc->E / sc->rho), k = sc->vib_mode * 3.14159265358979323846 / sc->L;
  return 2.0 * sc->L / (sc->vib_mode * c) * sqrt(1.0 + sc->nu * sc->nu * k * k * sc->H * sc->H / 12.0);
}

