/*
 * scene.c - reading scene files: inih through our own line reader into a ver_scene,
 * each key set and checked by the key table (scene_keys.c) where it enters.
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

typedef struct {
  ver_scene *vs;
  const char *text; /* the scene, NUL-terminated                               */
  size_t pos;       /* where the reader is in text                             */
  int line;         /* lines handed to inih so far: the line the handler is on */
  int errline;      /* line of the first error found by reader or handler      */
  char msg[640];    /* that error, without "file:line: "                       */
} parse_ctx;

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
  if (c->line == 1 && n >= 2 && (!memcmp(p, "\xFF\xFE", 2) || !memcmp(p, "\xFE\xFF", 2)))
    return fail(c, "the file is UTF-16 text (its byte-order mark %s): save it as UTF-8 or ASCII",
                p[0] == '\xFF' ? "FF FE" : "FE FF");
  for (char *e = p + strlen(p); e > p && isspace((unsigned char)e[-1]);)
    *--e = '\0';
  if (!*p || *p == ';' || *p == '#')
    return 0;
  if (*p == '[') {
    char *e = strchr(p, ']');
    if (!e)
      return fail(c, "'%s': a [section] header without ']'", ver_scene_shown(p, sv, sizeof sv));
    *e = '\0';
    const char *rest = e + 1;
    while (*rest == ' ' || *rest == '\t') rest++;
    if (*rest && *rest != ';')
    {
      char sr[48];
      return fail(c, "[%s]: text after the section header ('%s')", ver_scene_shown(p + 1, sv, sizeof sv),
                  ver_scene_shown(rest, sr, sizeof sr));
    }
    const int si = ver_scene_key_section(p + 1);
    if (si < 0) {
      char all[256];
      list_names(NULL, all, sizeof all);
      return fail(c, "[%s]: unknown section (allowed: %s)", ver_scene_shown(p + 1, sv, sizeof sv), all);
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
                ver_scene_shown(p, sv, sizeof sv));
  }
  if (q == p)
    return fail(c, "'%s': no key before '='", ver_scene_shown(p, sv, sizeof sv));
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
    return !fail(c, "%s: a key before any [section] header", ver_scene_shown(name, sv, sizeof sv));
  const int ki = ver_scene_key_find(section, name);
  if (ki < 0) {
    char all[256];
    list_names(section, all, sizeof all);
    return !fail(c, "%s.%s: unknown key (allowed in [%s]: %s)", section, ver_scene_shown(name, sv, sizeof sv), section, all);
  }
  ver_scene *vs = c->vs;
  if (vs->seen[ki])
    return !fail(c, "%s.%s: set twice, first on line %d (each key once)", section, name, vs->line[ki]);
  if (ver_scene_key_set(vs, ki, value, c->msg, sizeof c->msg)) {
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
 * (docs/findings.md).  Set after the file and after every override, so that a
 * changed bar changes it wherever the scene is read. */
static void resolve_damping(ver_scene *vs)
{
  if (vs->damping_critical && vs->sc.L > 0.0 && vs->sc.rho > 0.0 && vs->sc.E > 0.0)
    vs->sc.damping = 2.0 * ANA_PI * sqrt(vs->sc.E / vs->sc.rho) / vs->sc.L;
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
  const int pi = ver_scene_key_idx("method", "preset");
  if (ver_method_apply_file(vs, vs->line[pi], c.msg, sizeof c.msg)) {
    snprintf(err, errlen, "%s:%d: %s", vs->path, vs->line[pi], c.msg);
    return 2;
  }
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
               ver_scene_shown(assignment, sv, sizeof sv));
      return 2;
    }
  if (strlen(assignment) >= sizeof buf) {
    snprintf(err, errlen, "%s: command line: '%s': too long (expected section.key=value)", vs->path,
             ver_scene_shown(assignment, sv, sizeof sv));
    return 2;
  }
  snprintf(buf, sizeof buf, "%s", assignment);
  char *eq = strchr(buf, '='), *dot = strchr(buf, '.');
  if (!eq || !dot || dot > eq) {
    snprintf(err, errlen, "%s: command line: '%s': expected section.key=value", vs->path,
             ver_scene_shown(assignment, sv, sizeof sv));
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
             ver_scene_shown(assignment, sv, sizeof sv), ver_scene_key_section(buf) >= 0 ? " in [" : " sections",
             ver_scene_key_section(buf) >= 0 ? buf : "", ver_scene_key_section(buf) >= 0 ? "]" : "", all);
    return 2;
  }
  if (ver_scene_key_set(vs, ki, eq + 1, msg, sizeof msg)) {
    snprintf(err, errlen, "%s: command line: %s", vs->path, msg);
    return 2;
  }
  const int dti = ver_scene_key_idx("time", "dt");
  if (ki == ver_scene_key_idx("grid", "h") && vs->line[dti] >= 0 && vs->file_h > 0)
    vs->sc.dt = vs->file_dt * vs->sc.h / vs->file_h; /* the file's Courant number, as --h */
  vs->seen[ki] = 1;
  vs->line[ki] = -1;
  if (ver_scene_keys[ki].type == K_PRESET && ver_method_apply_cmd(vs, msg, sizeof msg)) {
    snprintf(err, errlen, "%s: command line: %s", vs->path, msg);
    return 2;
  }
  resolve_damping(vs);
  if (vs->nover == VER_MAX_OVER) {
    snprintf(err, errlen, "%s: command line: %s: more than %d overrides", vs->path, ver_scene_shown(assignment, sv, sizeof sv),
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
  const double c = sqrt(sc->E / sc->rho), k = sc->vib_mode * ANA_PI / sc->L;
  return 2.0 * sc->L / (sc->vib_mode * c) * sqrt(1.0 + sc->nu * sc->nu * k * k * sc->H * sc->H / 12.0);
}

