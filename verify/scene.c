/*
 * scene.c - scene files: a table of keys, each with its type, range and default,
 * read by inih into a ver_scene and validated once where it enters.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ini.h>

#include "scene.h"

typedef enum { K_DBL, K_INT, K_LE, K_SCHEME, K_LIST } ktype;

/* Range kinds: (lo, hi) open, [lo, hi) half open, etc. encoded by flags. */
enum { LO_OPEN = 1, LO_CLOSED = 2, HI_OPEN = 4, HI_CLOSED = 8 };

typedef struct {
  const char *section, *key;
  ktype type;
  size_t off;          /* offset in mpm_scene (K_DBL, K_INT, K_LE) */
  int required;        /* 1 always, 2 only when decohesion.model > 0, 0 optional */
  double lo, hi;
  int range;           /* LO_* | HI_* */
  double def;          /* default when optional */
  const char *allowed; /* human text of the range */
} keydef;

#define OFF(f) offsetof(mpm_scene, f)
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
  {"decohesion", "Le", K_LE, OFF(le_mode), 0, 0, 0, 0, MPM_LE_CELL, "cell or particle"},
  {"imperfection", "snf_factor", K_DBL, OFF(imp_factor), 0, 0, 1, LO_OPEN | HI_CLOSED, 1.0, "in (0, 1]"},
  {"imperfection", "x", K_DBL, OFF(imp_x), 0, 0, 0, 0, -1, "a number (default: L / 2)"},
  {"imperfection", "y", K_DBL, OFF(imp_y), 0, 0, 0, 0, -1, "a number (default: H / 2)"},
  {"grid", "h", K_DBL, OFF(h), 1, 0, 0, LO_OPEN, 0, "> 0, dividing L and H"},
  {"grid", "ppc", K_INT, OFF(ppc), 1, 1, 1024, LO_CLOSED | HI_CLOSED, 0, "a perfect square: 1, 4, 9, ..."},
  {"grid", "margin", K_DBL, OFF(margin), 0, 0, 0, LO_CLOSED, 0, ">= 0: empty space around the bar, a length (one cell is always added)"},
  {"time", "dt", K_DBL, OFF(dt), 1, 0, 0, LO_OPEN, 0, "> 0 and below the CFL bound h / c"},
  {"time", "scheme", K_SCHEME, OFF(scheme), 0, 0, 0, 0, MPM_SCHEME_USL, "usl (the paper) or musl"},
  {"loading", "speed", K_DBL, OFF(speed), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"run", "end_delta", K_DBL, OFF(end_delta), 1, 0, 0, LO_OPEN, 0, "> 0"},
  {"run", "stop_margin", K_DBL, OFF(stop_margin), 0, 0, 0, LO_CLOSED, 0.1, ">= 0 (0: run to end_delta)"},
  {"run", "sep_load", K_DBL, OFF(sep_load_frac), 0, 0, 1, LO_OPEN | HI_OPEN, 0.02, "in (0, 1)"},
  {"output", "snapshots", K_LIST, 0, 0, 0, 0, LO_CLOSED, 0, "a comma-separated list of end displacements >= 0"},
  {"output", "interval", K_DBL, 0, 0, 0, 0, LO_OPEN, -1, "> 0 (default: 0.0005)"},
};
#define NKEYS (int)(sizeof keys / sizeof keys[0])

typedef struct {
  ver_scene *vs;
  char *err;
  size_t errlen;
  int line; /* the line inih is on (counted by the handler: inih reports it only on error) */
} parse_ctx;

static int find_key(const char *section, const char *key)
{
  for (int i = 0; i < NKEYS; i++)
    if (!strcmp(keys[i].section, section) && !strcmp(keys[i].key, key))
      return i;
  return -1;
}

static int in_range(const keydef *k, double v)
{
  if ((k->range & LO_OPEN) && !(v > k->lo)) return 0;
  if ((k->range & LO_CLOSED) && !(v >= k->lo)) return 0;
  if ((k->range & HI_OPEN) && !(v < k->hi)) return 0;
  if ((k->range & HI_CLOSED) && !(v <= k->hi)) return 0;
  return 1;
}

static int parse_num(const char *s, double *v)
{
  char *end;
  errno = 0;
  *v = strtod(s, &end);
  while (*end == ' ' || *end == '\t')
    end++;
  return end != s && *end == '\0' && errno == 0 && isfinite(*v);
}

static void where(const ver_scene *vs, int line, char *buf, size_t len)
{
  if (line > 0)
    snprintf(buf, len, "%s:%d", vs->path, line);
  else if (line < 0)
    snprintf(buf, len, "%s: command line", vs->path);
  else
    snprintf(buf, len, "%s", vs->path);
}

/* Sets key index ki from text; 0 or 2 with the message in err. */
static int set_key(ver_scene *vs, int ki, const char *value, int line, char *err, size_t errlen)
{
  const keydef *k = &keys[ki];
  char at[600];
  where(vs, line, at, sizeof at);
  char *base = (char *)&vs->sc;
  if (k->type == K_LE || k->type == K_SCHEME) {
    int mode;
    if (k->type == K_LE && !strcmp(value, "cell")) mode = MPM_LE_CELL;
    else if (k->type == K_LE && !strcmp(value, "particle")) mode = MPM_LE_PARTICLE;
    else if (k->type == K_SCHEME && !strcmp(value, "usl")) mode = MPM_SCHEME_USL;
    else if (k->type == K_SCHEME && !strcmp(value, "musl")) mode = MPM_SCHEME_MUSL;
    else {
      snprintf(err, errlen, "%s: %s.%s: '%s' is not allowed (%s)", at, k->section, k->key, value, k->allowed);
      return 2;
    }
    *(int *)(base + k->off) = mode;
  } else if (k->type == K_LIST) {
    vs->nsnap = 0;
    char buf[512];
    snprintf(buf, sizeof buf, "%s", value);
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
      while (*tok == ' ') tok++;
      double v;
      if (!parse_num(tok, &v) || v < 0.0) {
        snprintf(err, errlen, "%s: %s.%s: '%s' is not an end displacement (%s)", at, k->section, k->key, tok, k->allowed);
        return 2;
      }
      if (vs->nsnap == VER_MAX_SNAP) {
        snprintf(err, errlen, "%s: %s.%s: more than %d snapshots", at, k->section, k->key, VER_MAX_SNAP);
        return 2;
      }
      vs->snap[vs->nsnap++] = v;
    }
  } else {
    double v;
    if (!parse_num(value, &v)) {
      snprintf(err, errlen, "%s: %s.%s: '%s' is not a number (%s)", at, k->section, k->key, value, k->allowed);
      return 2;
    }
    if (k->type == K_INT && v != floor(v)) {
      snprintf(err, errlen, "%s: %s.%s: '%s' is not an integer (%s)", at, k->section, k->key, value, k->allowed);
      return 2;
    }
    if (!in_range(k, v)) {
      snprintf(err, errlen, "%s: %s.%s: %s is out of range (%s)", at, k->section, k->key, value, k->allowed);
      return 2;
    }
    if (!strcmp(k->section, "output"))
      vs->interval = v;
    else if (k->type == K_INT)
      *(int *)(base + k->off) = (int)v;
    else
      *(double *)(base + k->off) = v;
  }
  vs->seen[ki] = 1;
  vs->line[ki] = line;
  return 0;
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
  parse_ctx *c = user;
  const int ki = find_key(section, name);
  if (ki < 0) {
    /* inih returns this line number from ini_parse; the message is completed there. */
    snprintf(c->err, c->errlen, "%s.%s: unknown key", section, name);
    return 0;
  }
  if (c->vs->seen[ki] && c->vs->line[ki] > 0) {
    snprintf(c->err, c->errlen, "%s.%s: set twice (each key once)", section, name);
    return 0;
  }
  /* The line is not known inside the handler; mark it and let ini_parse's caller fill it
   * by re-scanning the file (cheap; scene files are small). */
  char msg[700];
  if (set_key(c->vs, ki, value, 1, msg, sizeof msg) != 0) {
    /* strip the "file:1: " prefix: the caller prints file:line */
    const char *p = strstr(msg, ": ");
    snprintf(c->err, c->errlen, "%s", p ? p + 2 : msg);
    return 0;
  }
  return 1;
}

/* The line on which section.key is set (first match), for messages; 0 if not found. */
static int key_line(const char *path, const char *section, const char *key)
{
  FILE *f = fopen(path, "r");
  if (!f)
    return 0;
  char buf[1024], cur[128] = "";
  int ln = 0, found = 0;
  while (fgets(buf, sizeof buf, f)) {
    ln++;
    char *s = buf;
    while (*s == ' ' || *s == '\t') s++;
    if (*s == '[') {
      char *e = strchr(s, ']');
      if (e) {
        size_t n = (size_t)(e - s - 1);
        if (n >= sizeof cur) n = sizeof cur - 1;
        memcpy(cur, s + 1, n);
        cur[n] = '\0';
      }
      continue;
    }
    if (*s == ';' || *s == '#' || *s == '\0' || *s == '\n')
      continue;
    size_t kl = strlen(key);
    if (!strcmp(cur, section) && !strncmp(s, key, kl) && (s[kl] == ' ' || s[kl] == '=' || s[kl] == '\t' || s[kl] == ':')) {
      found = ln;
      break;
    }
  }
  fclose(f);
  return found;
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
  char *base = (char *)&vs->sc;
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

int ver_scene_parse(const char *path, ver_scene *vs, char *err, size_t errlen)
{
  scene_defaults(vs, path);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    return 2;
  }
  char msg[800] = "";
  parse_ctx c = {vs, msg, sizeof msg, 0};
  const int r = ini_parse_file(f, handler, &c);
  fclose(f);
  if (r != 0) {
    if (msg[0])
      snprintf(err, errlen, "%s:%d: %s", path, r, msg);
    else
      snprintf(err, errlen, "%s:%d: not a 'key = value' line or a [section] header", path, r);
    return 2;
  }
  /* Record the real line of each key for later messages. */
  for (int i = 0; i < NKEYS; i++)
    if (vs->seen[i])
      vs->line[i] = key_line(path, keys[i].section, keys[i].key);
  return 0;
}

int ver_scene_set(ver_scene *vs, const char *assignment, char *err, size_t errlen)
{
  char buf[256];
  snprintf(buf, sizeof buf, "%s", assignment);
  char *eq = strchr(buf, '='), *dot = strchr(buf, '.');
  if (!eq || !dot || dot > eq) {
    snprintf(err, errlen, "%s: command line: '%s': expected section.key=value", vs->path, assignment);
    return 2;
  }
  *eq = '\0';
  *dot = '\0';
  const int ki = find_key(buf, dot + 1);
  if (ki < 0) {
    snprintf(err, errlen, "%s: command line: %s.%s: unknown key", vs->path, buf, dot + 1);
    return 2;
  }
  return set_key(vs, ki, eq + 1, -1, err, errlen);
}

static int kidx(const char *section, const char *key)
{
  const int i = find_key(section, key);
  return i;
}

int ver_scene_validate(ver_scene *vs, char *err, size_t errlen)
{
  mpm_scene *sc = &vs->sc;
  char at[600];
  for (int i = 0; i < NKEYS; i++) {
    const int need = keys[i].required == 1 || (keys[i].required == 2 && sc->model > 0);
    if (need && !vs->seen[i]) {
      snprintf(err, errlen, "%s: %s.%s: missing (%s)", vs->path, keys[i].section, keys[i].key, keys[i].allowed);
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
  /* Rules that involve two keys: h divides L and H, ppc is a square, CFL. */
  const int hi = kidx("grid", "h");
  where(vs, vs->line[hi], at, sizeof at);
  for (int d = 0; d < 2; d++) {
    const double len = d ? sc->H : sc->L, r = len / sc->h;
    if (fabs(r - round(r)) > 1e-9 * r || r < 1) {
      snprintf(err, errlen, "%s: grid.h: %g does not divide bar.%s = %g (allowed: h = %s / n for a whole n)",
               at, sc->h, d ? "H" : "L", len, d ? "H" : "L");
      return 2;
    }
  }
  const int pi = kidx("grid", "ppc"), n = (int)lround(sqrt((double)sc->ppc));
  if (n * n != sc->ppc) {
    where(vs, vs->line[pi], at, sizeof at);
    snprintf(err, errlen, "%s: grid.ppc: %d is not a perfect square (allowed: 1, 4, 9, 16, ...)", at, sc->ppc);
    return 2;
  }
  const double dtc = mpm_scene_dt_crit(sc);
  if (sc->dt >= dtc && !vs->allow_unstable) {
    where(vs, vs->line[kidx("time", "dt")], at, sizeof at);
    snprintf(err, errlen, "%s: time.dt: %g is at or above the CFL bound h / c = %.4g (allowed: dt < %.4g, or --allow-unstable)",
             at, sc->dt, dtc, dtc);
    return 2;
  }
  char e2[256];
  if (mpm_scene_check(sc, e2, sizeof e2) != MPM_OK) {
    snprintf(err, errlen, "%s: %s", vs->path, e2);
    return 2;
  }
  return 0;
}

int ver_scene_load(const char *path, ver_scene *vs, char *err, size_t errlen)
{
  const int r = ver_scene_parse(path, vs, err, errlen);
  return r ? r : ver_scene_validate(vs, err, errlen);
}

void ver_scene_case_id(const ver_scene *vs, char *buf, size_t len)
{
  snprintf(buf, len, "%s-h%g-ppc%d", vs->name, vs->sc.h, vs->sc.ppc);
}
