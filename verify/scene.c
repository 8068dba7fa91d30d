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
#include "scene.h"

typedef enum { K_DBL, K_INT, K_LE, K_SCHEME, K_MOTION, K_SHAPE, K_FIELDS, K_LIST } ktype;

/* Range kinds: (lo, hi) open, [lo, hi) half open, etc. encoded by flags. */
enum { LO_OPEN = 1, LO_CLOSED = 2, HI_OPEN = 4, HI_CLOSED = 8 };

typedef struct {
  const char *section, *key;
  ktype type;
  size_t off;          /* offset in ver_scene (K_DBL, K_INT, K_LE, ...) */
  int required;        /* 1 always, 2 only when decohesion.model > 0, 0 optional */
  double lo, hi;
  int range;           /* LO_* | HI_* */
  double def;          /* default when optional */
  const char *allowed; /* human text of the range */
} keydef;

#define OFF(f) offsetof(ver_scene, sc.f) /* the kernel's description */
#define VOFF(f) offsetof(ver_scene, f)  /* run control, not the kernel's */
static const keydef keys[] = {
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
  {"decohesion", "separation", K_DBL, OFF(sep_threshold), 0, 0, 1, LO_OPEN | HI_CLOSED, 0.98, "in (0, 1]"},
  {"decohesion", "Le", K_LE, OFF(le_mode), 0, 0, 0, 0, MPM_LE_CELL, "cell, particle or staircase"},
  {"decohesion", "Le_factor", K_DBL, OFF(le_factor), 0, 0, 100, LO_OPEN | HI_CLOSED, 1.0, "in (0, 100]: Le times this"},
  {"imperfection", "snf_factor", K_DBL, OFF(imp_factor), 0, 0, 1, LO_OPEN | HI_CLOSED, 1.0, "in (0, 1]"},
  {"imperfection", "x", K_DBL, OFF(imp_x), 0, 0, 0, 0, -1, "a number (default: L / 2)"},
  {"imperfection", "y", K_DBL, OFF(imp_y), 0, 0, 0, 0, -1, "a number (default: H / 2)"},
  {"grid", "h", K_DBL, OFF(h), 1, 0, 0, LO_OPEN, 0, "> 0, dividing L and H"},
  {"grid", "ppc", K_INT, OFF(ppc), 1, 1, 1024, LO_CLOSED | HI_CLOSED, 0, "a perfect square: 1, 4, 9, ..."},
  {"grid", "margin", K_DBL, OFF(margin), 0, 0, 0, LO_CLOSED, 0, ">= 0: empty space around the bar, a length (one cell is always added)"},
  {"time", "dt", K_DBL, OFF(dt), 1, 0, 0, LO_OPEN, 0, "> 0 and below the CFL bound h / (c sqrt 2)"},
  {"time", "scheme", K_SCHEME, OFF(scheme), 0, 0, 0, 0, MPM_SCHEME_USL, "usl (the paper) or musl"},
  {"grid", "motion", K_MOTION, OFF(grid_motion), 0, 0, 0, 0, MPM_GRID_FIXED, "fixed (the paper) or stretch (follows the bar's mean stretch)"},
  {"grid", "fields", K_FIELDS, OFF(fields), 0, 0, 0, 0, MPM_FIELDS_ONE, "one (the paper) or two (one per side of a separated band; needs shape = gimp)"},
  {"grid", "shape", K_SHAPE, OFF(shape), 0, 0, 0, 0, MPM_SHAPE_LINEAR, "linear (the paper's bilinear hats) or gimp (uGIMP)"},
  {"loading", "speed", K_DBL, OFF(speed), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"run", "end_delta", K_DBL, OFF(end_delta), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"run", "stop_margin", K_DBL, VOFF(stop_margin), 0, 0, 0, LO_CLOSED, 0.1, ">= 0 (0: run to end_delta)"},
  {"run", "sep_load", K_DBL, VOFF(sep_load_frac), 0, 0, 1, LO_OPEN | HI_OPEN, 0.02, "in (0, 1)"},
  {"output", "snapshots", K_LIST, 0, 0, 0, 0, LO_CLOSED, 0, "a comma-separated list of end displacements >= 0"},
  {"output", "interval", K_DBL, 0, 0, 0, 0, LO_OPEN, -1, "> 0 (default: 0.0005)"},
};
#define NKEYS (int)(sizeof keys / sizeof keys[0])

_Static_assert(NKEYS <= VER_NKEYS, "VER_NKEYS too small for the key table");

/* Size limits: far above any sensible scene, low enough that every count fits in an
 * int and every allocation in memory (and that no double-to-integer cast overflows). */
#define MAX_NODES 1e8     /* grid nodes                        */
#define MAX_PARTICLES 1e8 /* particles                         */
#define MAX_STEPS 1e12    /* time steps to run.end_delta       */
#define MAX_ROWS 1e7      /* rows of load.csv and energy.csv   */
#define MAX_LINE 500      /* characters on a line of the file  */

typedef struct {
  ver_scene *vs;
  const char *text; /* the scene, NUL-terminated                               */
  size_t pos;       /* where the reader is in text                             */
  int line;         /* lines handed to inih so far: the line the handler is on */
  int errline;      /* line of the first error found by reader or handler      */
  char msg[640];    /* that error, without "file:line: "                       */
} parse_ctx;

/* 1 if key i is the first of its section in the table. */
static int first_of_section(int i)
{
  for (int j = 0; j < i; j++)
    if (!strcmp(keys[j].section, keys[i].section))
      return 0;
  return 1;
}

/* Index of a section among the distinct sections of the table, or -1. */
static int section_index(const char *section)
{
  for (int i = 0, n = 0; i < NKEYS; i++)
    if (first_of_section(i)) {
      assert(n < VER_NSECT);
      if (!strcmp(keys[i].section, section))
        return n;
      n++;
    }
  return -1;
}

static int find_key(const char *section, const char *key)
{
  for (int i = 0; i < NKEYS; i++)
    if (!strcmp(keys[i].section, section) && !strcmp(keys[i].key, key))
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
  for (int i = 0; i < NKEYS && n < len; i++) {
    if (section ? strcmp(keys[i].section, section) != 0 : !first_of_section(i))
      continue;
    n += (size_t)snprintf(buf + n, len - n, "%s%s", n ? ", " : "", section ? keys[i].key : keys[i].section);
  }
}

static int in_range(const keydef *k, double v)
{
  if ((k->range & LO_OPEN) && !(v > k->lo)) return 0;
  if ((k->range & LO_CLOSED) && !(v >= k->lo)) return 0;
  if ((k->range & HI_OPEN) && !(v < k->hi)) return 0;
  if ((k->range & HI_CLOSED) && !(v <= k->hi)) return 0;
  return 1;
}

/* A finite number with nothing but blanks after it: 0; 1 not a number; 2 not finite. */
static int parse_num(const char *s, double *v)
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

/* Checks value for key ki and stores it; 0, or 2 with a message (no location) in msg. */
static int set_key(ver_scene *vs, int ki, const char *value, char *msg, size_t len)
{
  const keydef *k = &keys[ki];
  char sv[48];
  char *base = (char *)vs;
  while (*value == ' ' || *value == '\t')
    value++;
  if (!*value) {
    snprintf(msg, len, "%s.%s: empty value (%s)", k->section, k->key, k->allowed);
    return 2;
  }
  if (k->type == K_LE || k->type == K_SCHEME || k->type == K_MOTION || k->type == K_SHAPE ||
      k->type == K_FIELDS) {
    int mode;
    if (k->type == K_LE && !strcmp(value, "cell")) mode = MPM_LE_CELL;
    else if (k->type == K_LE && !strcmp(value, "particle")) mode = MPM_LE_PARTICLE;
    else if (k->type == K_LE && !strcmp(value, "staircase")) mode = MPM_LE_STAIRCASE;
    else if (k->type == K_SCHEME && !strcmp(value, "usl")) mode = MPM_SCHEME_USL;
    else if (k->type == K_SCHEME && !strcmp(value, "musl")) mode = MPM_SCHEME_MUSL;
    else if (k->type == K_MOTION && !strcmp(value, "stretch")) mode = MPM_GRID_STRETCH;
    else if (k->type == K_MOTION && !strcmp(value, "fixed")) mode = MPM_GRID_FIXED;
    else if (k->type == K_SHAPE && !strcmp(value, "linear")) mode = MPM_SHAPE_LINEAR;
    else if (k->type == K_SHAPE && !strcmp(value, "gimp")) mode = MPM_SHAPE_GIMP;
    else if (k->type == K_FIELDS && !strcmp(value, "one")) mode = MPM_FIELDS_ONE;
    else if (k->type == K_FIELDS && !strcmp(value, "two")) mode = MPM_FIELDS_TWO;
    else {
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
      const int r = parse_num(t, &v[n]);
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
  } else {
    double v;
    const int r = parse_num(value, &v);
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
    if (!in_range(k, v)) {
      snprintf(msg, len, "%s.%s: %s is out of range (%s)", k->section, k->key, shown(value, sv, sizeof sv),
               k->allowed);
      return 2;
    }
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
    const int si = section_index(p + 1);
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
  const int ki = find_key(section, name);
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
  for (int i = 0; i < NKEYS; i++) {
    if (keys[i].required || keys[i].type == K_LIST || !strcmp(keys[i].section, "output"))
      continue;
    if (keys[i].type == K_DBL)
      *(double *)(base + keys[i].off) = keys[i].def;
    else
      *(int *)(base + keys[i].off) = (int)keys[i].def;
  }
  vs->interval = -1;
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
  vs->file_h = vs->sc.h;
  vs->file_dt = vs->sc.dt;
  return 0;
}

int ver_scene_parse(const char *path, ver_scene *vs, char *err, size_t errlen)
{
  scene_defaults(vs, path);
  FILE *f = fopen(path, "rb");
  if (!f) {
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
  const int ki = find_key(buf, key);
  if (ki < 0) {
    char all[256];
    if (section_index(buf) >= 0)
      list_names(buf, all, sizeof all);
    else
      list_names(NULL, all, sizeof all);
    snprintf(err, errlen, "%s: command line: %s: unknown key (allowed%s%s%s: %s)", vs->path,
             shown(assignment, sv, sizeof sv), section_index(buf) >= 0 ? " in [" : " sections",
             section_index(buf) >= 0 ? buf : "", section_index(buf) >= 0 ? "]" : "", all);
    return 2;
  }
  if (set_key(vs, ki, eq + 1, msg, sizeof msg)) {
    snprintf(err, errlen, "%s: command line: %s", vs->path, msg);
    return 2;
  }
  vs->seen[ki] = 1;
  vs->line[ki] = -1;
  if (vs->nover == VER_MAX_OVER) {
    snprintf(err, errlen, "%s: command line: %s: more than %d overrides", vs->path, shown(assignment, sv, sizeof sv),
             VER_MAX_OVER);
    return 2;
  }
  const char *val = eq + 1;
  while (*val == ' ' || *val == '\t')
    val++;
  snprintf(vs->over[vs->nover++], sizeof vs->over[0], "%s.%s=%s", keys[ki].section, keys[ki].key, val);
  return 0;
}

/* "file:line" of key ki: its line, else its section's header, else the file's end. */
static const char *key_at(const ver_scene *vs, int ki, char *buf, size_t len)
{
  int line = vs->line[ki];
  if (line < 0) {
    snprintf(buf, len, "%s: command line", vs->path);
    return buf;
  }
  if (!line)
    line = vs->sect_line[section_index(keys[ki].section)];
  if (!line)
    line = vs->nlines > 0 ? vs->nlines : 1;
  snprintf(buf, len, "%s:%d", vs->path, line);
  return buf;
}

static int kidx(const char *section, const char *key)
{
  const int i = find_key(section, key);
  assert(i >= 0);
  return i;
}

int ver_scene_validate(ver_scene *vs, char *err, size_t errlen)
{
  mpm_scene *sc = &vs->sc;
  char at[600];
  for (int i = 0; i < NKEYS; i++) {
    const int need = keys[i].required == 1 || (keys[i].required == 2 && sc->model > 0);
    if (need && !vs->seen[i]) {
      const int si = section_index(keys[i].section);
      snprintf(err, errlen, "%s: %s.%s: missing%s%s%s (%s)", key_at(vs, i, at, sizeof at), keys[i].section,
               keys[i].key, vs->sect_line[si] ? "" : ", and there is no [", vs->sect_line[si] ? "" : keys[i].section,
               vs->sect_line[si] ? "" : "] section", keys[i].allowed);
      return 2;
    }
  }
  if (!vs->seen[kidx("decohesion", "s0")])
    sc->s0 = sc->snf;
  if (!vs->seen[kidx("imperfection", "x")])
    sc->imp_x = 0.5 * sc->L;
  if (!vs->seen[kidx("imperfection", "y")])
    sc->imp_y = 0.5 * sc->H;
  if (vs->interval <= 0)
    vs->interval = 0.0005;
  /* Sizes first: the checks after them round L / h and H / h to integers. */
  const int hi = kidx("grid", "h");
  key_at(vs, hi, at, sizeof at);
  const double nx = (sc->L + 2.0 * sc->margin) / sc->h + 4.0, ny = (sc->H + 2.0 * sc->margin) / sc->h + 4.0;
  if (!(nx * ny <= MAX_NODES)) {
    snprintf(err, errlen, "%s: grid.h: %g gives a grid of %.3g x %.3g nodes for bar.L, bar.H and grid.margin "
             "(allowed: at most %.0e nodes)", at, sc->h, nx, ny, MAX_NODES);
    return 2;
  }
  /* The grid also spans the grip's travel, to the left of the bar. */
  const double nt = sc->end_delta / sc->h;
  if (!((nx + nt) * ny <= MAX_NODES)) {
    snprintf(err, errlen, "%s: run.end_delta: %g is %.3g cells of grip travel at grid.h = %g, a grid of %.3g x %.3g "
             "nodes (allowed: at most %.0e nodes)", key_at(vs, kidx("run", "end_delta"), at, sizeof at),
             sc->end_delta, nt, sc->h, nx + nt, ny, MAX_NODES);
    return 2;
  }
  /* h divides L and H (as the kernel rounds it), ppc is a square. */
  for (int d = 0; d < 2; d++) {
    const double len = d ? sc->H : sc->L, r = len / sc->h, n = round(r);
    if (!(n >= 1 && fabs(r - n) < 1e-9 * r)) {
      snprintf(err, errlen, "%s: grid.h: %g does not divide bar.%s = %g (allowed: h = %s / n for a whole n)", at,
               sc->h, d ? "H" : "L", len, d ? "H" : "L");
      return 2;
    }
  }
  const int n1 = (int)lround(sqrt((double)sc->ppc));
  if (n1 * n1 != sc->ppc) {
    snprintf(err, errlen, "%s: grid.ppc: %d is not a perfect square (allowed: 1, 4, 9, 16, ...)",
             key_at(vs, kidx("grid", "ppc"), at, sizeof at), sc->ppc);
    return 2;
  }
  const double np = round(sc->L / sc->h) * round(sc->H / sc->h) * sc->ppc;
  if (np > MAX_PARTICLES) {
    snprintf(err, errlen, "%s: grid.h: %g with grid.ppc = %d gives %.3g particles (allowed: at most %.0e)",
             key_at(vs, hi, at, sizeof at), sc->h, sc->ppc, np, MAX_PARTICLES);
    return 2;
  }
  /* The imperfection is at the particle nearest (x, y): a point of the bar. */
  if (!(sc->imp_x >= 0 && sc->imp_x <= sc->L) || !(sc->imp_y >= 0 && sc->imp_y <= sc->H)) {
    const int x = !(sc->imp_x >= 0 && sc->imp_x <= sc->L);
    snprintf(err, errlen, "%s: imperfection.%s: %g is outside the bar (allowed: 0 <= %s <= bar.%s = %g)",
             key_at(vs, kidx("imperfection", x ? "x" : "y"), at, sizeof at), x ? "x" : "y", x ? sc->imp_x : sc->imp_y,
             x ? "x" : "y", x ? "L" : "H", x ? sc->L : sc->H);
    return 2;
  }
  const double dtc = mpm_scene_dt_crit(sc);
  if (!(sc->dt < dtc) && !vs->allow_unstable) {
    snprintf(err, errlen, "%s: time.dt: %g is at or above the CFL bound h / (c sqrt 2) = %.4g (allowed: dt < %.4g, or --allow-unstable)",
             key_at(vs, kidx("time", "dt"), at, sizeof at), sc->dt, dtc, dtc);
    return 2;
  }
  const double vdt = sc->speed * sc->dt;
  if (!(sc->end_delta / vdt <= MAX_STEPS)) {
    snprintf(err, errlen, "%s: run.end_delta: %g at loading.speed = %g and time.dt = %g takes %.3g time steps "
             "(allowed: at most %.0e)", key_at(vs, kidx("run", "end_delta"), at, sizeof at), sc->end_delta,
             sc->speed, sc->dt, sc->end_delta / vdt, MAX_STEPS);
    return 2;
  }
  /* A row every max(interval, one step): the rows are held in memory until the end. */
  const int ii = kidx("output", "interval");
  const double rows = sc->end_delta / fmax(vs->interval, vdt);
  if (!(rows <= MAX_ROWS)) {
    snprintf(err, errlen, "%s: output.interval: %g gives %.3g rows of load.csv to run.end_delta = %g "
             "(allowed: at most %.0e rows)", key_at(vs, ii, at, sizeof at), vs->interval, rows, sc->end_delta, MAX_ROWS);
    return 2;
  }
  if (!(vs->interval / vdt <= MAX_STEPS)) {
    snprintf(err, errlen, "%s: output.interval: %g is %.3g time steps (allowed: at most %.0e)",
             key_at(vs, ii, at, sizeof at), vs->interval, vs->interval / vdt, MAX_STEPS);
    return 2;
  }
  /* The kernel's own check: every rule it has is above, so this is a backstop. */
  char e2[256];
  if (mpm_scene_check(sc, e2, sizeof e2) != MPM_OK) {
    snprintf(err, errlen, "%s:%d: %s", vs->path, vs->nlines > 0 ? vs->nlines : 1, e2);
    return 2;
  }
  return 0;
}

int ver_scene_load(const char *path, ver_scene *vs, char *err, size_t errlen)
{
  const int r = ver_scene_parse(path, vs, err, errlen);
  return r ? r : ver_scene_validate(vs, err, errlen);
}

void ver_scene_base_id(const ver_scene *vs, char *buf, size_t len)
{
  snprintf(buf, len, "%s-h%g-ppc%d", vs->name, vs->sc.h, vs->sc.ppc);
}

void ver_scene_fmt_num(double v, char *buf, size_t len)
{
  for (int prec = 1; prec <= 17; prec++) {
    snprintf(buf, len, "%.*g", prec, v);
    if (strtod(buf, NULL) == v)
      return;
  }
}

void ver_scene_case_id(const ver_scene *vs, char *buf, size_t len)
{
  ver_scene_base_id(vs, buf, len);
  size_t n = strlen(buf);
  for (int i = 0; i < vs->nover; i++) {
    const char *o = vs->over[i], *eq = strchr(o, '=');
    const size_t klen = (size_t)(eq - o);
    int later = 0; /* a later override of the same key wins */
    for (int j = i + 1; j < vs->nover && !later; j++)
      later = !strncmp(vs->over[j], o, klen + 1);
    if (later || !strncmp(o, "grid.h=", 7) || !strncmp(o, "grid.ppc=", 9))
      continue;
    if (!strncmp(o, "time.dt=", 8) && vs->file_h > 0 &&
        fabs(vs->sc.dt - vs->file_dt * vs->sc.h / vs->file_h) <= 1e-12 * vs->sc.dt)
      continue; /* the dt --h scales to: no choice of the user's */
    char val[64];
    double v;
    if (parse_num(eq + 1, &v) == 0)
      ver_scene_fmt_num(v, val, sizeof val);
    else
      snprintf(val, sizeof val, "%s", eq + 1);
    for (char *c = val; *c; c++)
      if (*c == '/' || *c == ' ' || *c == ',')
        *c = '_'; /* a folder name */
    if (n < len)
      n += (size_t)snprintf(buf + n, len - n, "-%.*s=%s", (int)klen, o, val);
  }
}

static const char *enum_word(ktype t, int v)
{
  switch (t) {
  case K_LE: return v == MPM_LE_PARTICLE ? "particle" : v == MPM_LE_STAIRCASE ? "staircase" : "cell";
  case K_SCHEME: return v == MPM_SCHEME_MUSL ? "musl" : "usl";
  case K_MOTION: return v == MPM_GRID_STRETCH ? "stretch" : "fixed";
  case K_SHAPE: return v == MPM_SHAPE_GIMP ? "gimp" : "linear";
  case K_FIELDS: return v == MPM_FIELDS_TWO ? "two" : "one";
  default: return "";
  }
}

static int is_enum(ktype t)
{
  return t == K_LE || t == K_SCHEME || t == K_MOTION || t == K_SHAPE || t == K_FIELDS;
}

int ver_scene_write_ini(const ver_scene *vs, FILE *f)
{
  const char *base = (const char *)vs;
  char id[512];
  ver_scene_case_id(vs, id, sizeof id);
  fprintf(f, "; delam scene.ini schema %d, written by delam %s\n", VER_SCHEMA_SCENE, ver_build_version());
  fprintf(f, "; effective scene of case %s: every key as the run used it\n; from %s", id, vs->path);
  for (int i = 0; i < vs->nover; i++)
    fprintf(f, "%s%s", i ? ", " : " with ", vs->over[i]);
  fprintf(f, "\n");
  char num[40];
  for (int si = 0; si < NKEYS; si++) {
    if (!first_of_section(si))
      continue;
    fprintf(f, "\n[%s]\n", keys[si].section);
  for (int i = si; i < NKEYS; i++) {
    const keydef *k = &keys[i];
    if (strcmp(k->section, keys[si].section))
      continue;
    if (k->type == K_LIST) {
      if (vs->nsnap == 0)
        continue;
      fprintf(f, "%s = ", k->key);
      for (int j = 0; j < vs->nsnap; j++) {
        ver_scene_fmt_num(vs->snap[j], num, sizeof num);
        fprintf(f, "%s%s", j ? ", " : "", num);
      }
      fprintf(f, "\n");
      continue;
    }
    if (is_enum(k->type)) {
      int v;
      memcpy(&v, base + k->off, sizeof v);
      fprintf(f, "%s = %s\n", k->key, enum_word(k->type, v));
      continue;
    }
    double v;
    if (!strcmp(k->section, "output"))
      v = vs->interval;
    else if (k->type == K_INT) {
      int iv;
      memcpy(&iv, base + k->off, sizeof iv);
      v = iv;
    } else
      memcpy(&v, base + k->off, sizeof v);
    /* a key the scene does not use (decohesion keys of model 0) stays out */
    if (!vs->seen[i] && (k->required || !in_range(k, v)))
      continue;
    ver_scene_fmt_num(v, num, sizeof num);
    fprintf(f, "%s = %s\n", k->key, num);
  }
  }
  return ferror(f) ? -1 : 0;
}

static const char *type_name(ktype t)
{
  switch (t) {
  case K_DBL: return "number";
  case K_INT: return "integer";
  case K_LIST: return "list of numbers";
  default: return "word";
  }
}

void ver_scene_keys_markdown(FILE *f)
{
  fprintf(f, "| section | key | type | required | allowed | default |\n|---|---|---|---|---|---|\n");
  for (int i = 0; i < NKEYS; i++) {
    const keydef *k = &keys[i];
    char def[64];
    if (k->required)
      snprintf(def, sizeof def, "-");
    else if (is_enum(k->type))
      snprintf(def, sizeof def, "%s", enum_word(k->type, (int)k->def));
    else if (k->type == K_LIST)
      snprintf(def, sizeof def, "none");
    else if (k->def < 0)
      snprintf(def, sizeof def, "derived");
    else
      snprintf(def, sizeof def, "%g", k->def);
    fprintf(f, "| %s | %s | %s | %s | %s | %s |\n", k->section, k->key, type_name(k->type),
            k->required == 1 ? "yes" : k->required == 2 ? "when decohesion.model > 0" : "no", k->allowed, def);
  }
}
