/*
 * scene_keys.c - the table of scene keys (section, key, type, range, default and the
 * allowed text of messages), the words of the enumerated keys, and setting one key's
 * value with its checks (scene_keys.h).  The parser (scene.c), the validation
 * (scene_check.c) and the writer (scene_ini.c) all read this one table.
 */
#include <assert.h>
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "scene_keys.h"

#define OFF(f) offsetof(ver_scene, sc.f) /* the kernel's description */
#define VOFF(f) offsetof(ver_scene, f)  /* run control, not the kernel's */
const keydef ver_scene_keys[] = {
  {"method", "preset", K_PRESET, VOFF(preset), 0, 0, 0, 0, -1, "paper (the paper's method), band (a band along the line through the flaw) or interface (a cohesive interface on that line): the method keys' values, each key the file sets overriding its preset's (docs/methods.md)"},
  {"specimen", "type", K_SPECIMEN, OFF(specimen), 0, 0, 0, 0, MPM_SPEC_BAR, "bar (the paper's: pulled along x at x = 0, held at x = L), dcb (double cantilever beam, mode I) or els (end-loaded split, mode II; needs solver.type = static): a pre-crack along y = H / 2 from x = 0 to a0 (docs/specimens.md)"},
  {"specimen", "grips", K_GRIPS, OFF(grips), 0, 0, 0, 0, MPM_GRIPS_ROLLERS, "rollers (the paper's: the bar's ends held in x, one node in y) or held (the ends held in x and y, as wedge grips hold them; specimen.type = bar)"},
  {"specimen", "a0", K_DBL, OFF(a0), 0, 0, 0, LO_OPEN, -1, "> 0 and below L: the pre-crack's length along y = H / 2 from x = 0 (dcb, els; default L / 3)"},
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
  {"decohesion", "path", K_PATH, OFF(path), 0, 0, 0, 0, MPM_PATH_FREE, "free (the paper: any particle may soften), line (only near the line through the imperfection) or interface (a cohesive interface on that line between two velocity fields; needs grid.fields = two, grid.shape = gimp, time.scheme = musl, Model 1, q = 1 unless solver.type = static)"},
  {"decohesion", "share", K_SHARE, OFF(share), 0, 0, 0, 0, MPM_SHARE_STICK, "stick (path = interface: each node of a softening segment keeps its own stick impulse, scaled by the segment's factor) or line (each node takes the segment's traction times its length of line; needs path = interface, alpha = 90, grid.motion = stretch and the crack on a node column)"},
  {"decohesion", "reversed_shear", K_SHEAR, OFF(reversed_shear), 0, 0, 0, 0, MPM_SHEAR_EVEN, "even (the paper: shear either way softens) or closing (shear against a particle's slip closes it elastically, as compression closes an opening)"},
  {"decohesion", "path_reach", K_DBL, OFF(path_reach), 0, 0, 100, LO_CLOSED | HI_CLOSED, 1.0, "in [0, 100] cells: path = line's band beyond the cells the line crosses (0 locks; docs/findings.md)"},
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
  {K_SPECIMEN, "bar", MPM_SPEC_BAR}, {K_SPECIMEN, "dcb", MPM_SPEC_DCB}, {K_SPECIMEN, "els", MPM_SPEC_ELS},
  {K_GRIPS, "rollers", MPM_GRIPS_ROLLERS}, {K_GRIPS, "held", MPM_GRIPS_HELD},
};
#define NENUMS (sizeof ENUMS / sizeof ENUMS[0])

int ver_scene_enum_type(ktype t)
{
  if (t == K_PRESET || t == K_SCHEME) /* the presets' own table (scene_method.c), the kernel's schemes */
    return 1;
  for (size_t i = 0; i < NENUMS; i++)
    if (ENUMS[i].type == t)
      return 1;
  return 0;
}

int ver_scene_enum_value(ktype t, const char *word, int *value)
{
  if (t == K_PRESET)
    return (*value = ver_method_find(word)) >= 0 ? 0 : -1;
  if (t == K_SCHEME)
    return (*value = mpm_scheme_find(word)) >= 0 ? 0 : -1;
  for (size_t i = 0; i < NENUMS; i++)
    if (ENUMS[i].type == t && !strcmp(ENUMS[i].word, word)) {
      *value = ENUMS[i].value;
      return 0;
    }
  return -1;
}

const char *ver_scene_enum_word(ktype t, int value)
{
  if (t == K_PRESET)
    return ver_method_name(value);
  if (t == K_SCHEME)
    return mpm_scheme_name(value);
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
const char *ver_scene_shown(const char *s, char *buf, size_t len)
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
int ver_scene_key_set(ver_scene *vs, int ki, const char *value, char *msg, size_t len)
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
      snprintf(msg, len, "%s.%s: '%s' is not allowed (%s)", k->section, k->key, ver_scene_shown(value, sv, sizeof sv),
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
        snprintf(msg, len, "%s.%s: '%s' is %s (%s)", k->section, k->key, ver_scene_shown(t, sv, sizeof sv),
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
      snprintf(msg, len, "%s.%s: '%s' is %s (%s)", k->section, k->key, ver_scene_shown(value, sv, sizeof sv),
               r == 1 ? "not a number" : "not a finite number", k->allowed);
      return 2;
    }
    if (k->type == K_INT && v != floor(v)) {
      snprintf(msg, len, "%s.%s: '%s' is not an integer (%s)", k->section, k->key, ver_scene_shown(value, sv, sizeof sv),
               k->allowed);
      return 2;
    }
    if (!ver_scene_key_in_range(k, v)) {
      snprintf(msg, len, "%s.%s: %s is out of range (%s)", k->section, k->key, ver_scene_shown(value, sv, sizeof sv),
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
