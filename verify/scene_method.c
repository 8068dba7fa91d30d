/*
 * scene_method.c - the method presets (scene.h): each a named list of the method keys'
 * values, defined here once.  A scene file names one in [method] preset and sets only
 * what differs (its own keys win); `--method NAME` (the override method.preset=NAME)
 * makes NAME the run's method: every method key back to its default, then NAME's rows,
 * then the --set overrides that follow.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene.h"
#include "scene_keys.h"

/* The keys that choose the numerical method rather than the problem (bar, material,
 * law, flaw position, loading, run length): a preset sets every one of them. */
static const char *const method_keys[] = {
    "decohesion.Le",        "decohesion.Le_factor",    "decohesion.path",    "decohesion.share",
    "decohesion.reversed_shear", "decohesion.path_reach", "imperfection.snf_factor", "imperfection.stf_factor",
    "imperfection.size",    "grid.shape",              "grid.fields",        "grid.motion",
    "grid.weights",         "grid.node_mass",          "grid.bc",            "time.scheme",
    "time.damping",         "time.damping_from",       "time.damping_about", "time.damping_beta",
    "time.damping_tau"};
#define NMETHOD_KEYS (int)(sizeof method_keys / sizeof method_keys[0])

/* The method keys a user does not choose: the presets hold them, the keys page lists them
 * apart (advanced), and a scene or --set may still set them. */
static const char *const held_keys[] = {
    "decohesion.Le_factor", "decohesion.share", "decohesion.reversed_shear", "decohesion.path_reach",
    "imperfection.size",    "grid.motion",      "grid.weights",              "grid.node_mass",
    "time.damping",         "time.damping_from", "time.damping_about",       "time.damping_beta",
    "time.damping_tau"};

/* The paper's method: its bilinear shapes, one field, Le of the cell, the snf-only
 * imperfection (0.9) at one particle, every particle free to soften, a fixed grid, no
 * damping and USL, with the nodal mass limit, which changes nothing until a node passes
 * its stable stiffness-to-mass ratio (the paper's lumped USL blows up in 14 of 24
 * inclined runs at h 8-2, 1 and 4 ppc; docs/findings.md). */
const char *const ver_paper_sets[VER_PAPER_NSETS] = {
    "grid.shape=linear",         "grid.fields=one", "decohesion.Le=cell",
    "imperfection.stf_factor=1", "time.scheme=usl", "grid.node_mass=limited", "time.damping=0", "time.damping_beta=0",
    "imperfection.size=particle", "decohesion.path=free", "grid.motion=fixed", "decohesion.reversed_shear=even",
    "imperfection.snf_factor=0.9"};

/* The band method (docs/methods.md): only the particles near the line through the flaw
 * soften, Le measured per row over the zone, the flaw's whole cell at 0.9, uGIMP with
 * two fields once the band has cut the bar, the grid following the bar's stretch, MUSL,
 * and the release after the cut damped toward each part's end (fig7.ini's band runs). */
static const char *const band_sets[] = {
    "decohesion.path=line", "decohesion.Le=zone", "decohesion.path_reach=1", "decohesion.reversed_shear=closing",
    "imperfection.snf_factor=0.9", "imperfection.size=cell", "grid.shape=gimp", "grid.fields=two",
    "grid.motion=stretch", "time.scheme=musl", "time.damping=0.1", "time.damping_from=cut",
    "time.damping_about=parts"};

/* The cohesive interface (docs/methods.md): the paper's Model 1 on the line through
 * the flaw's point between two velocity fields, uGIMP and MUSL (what mpm_iface.c
 * implements), no flaw, the fixed grid, the release after the cut damped as the band's. */
static const char *const iface_sets[] = {
    "decohesion.path=interface", "grid.shape=gimp", "grid.fields=two", "time.scheme=musl",
    "imperfection.snf_factor=1", "time.damping=0.1", "time.damping_from=cut", "time.damping_about=parts"};

typedef struct {
  const char *name;
  const char *const *sets; /* "section.key=value", each a method key */
  int nsets;
} preset;

#define PRESET(n, s) {n, s, (int)(sizeof s / sizeof s[0])}
static const preset presets[] = {PRESET("paper", ver_paper_sets), PRESET("band", band_sets),
                                 PRESET("interface", iface_sets)};
#define NPRESETS (int)(sizeof presets / sizeof presets[0])

int ver_method_find(const char *name)
{
  for (int i = 0; i < NPRESETS; i++)
    if (!strcmp(presets[i].name, name))
      return i;
  return -1;
}

const char *ver_method_name(int i)
{
  return i >= 0 && i < NPRESETS ? presets[i].name : "none";
}

int ver_method_rows(int i, const char *const **sets)
{
  *sets = i >= 0 && i < NPRESETS ? presets[i].sets : NULL;
  return i >= 0 && i < NPRESETS ? presets[i].nsets : 0;
}

const char *ver_method_where(const ver_scene *vs)
{
  const int line = vs->line[ver_scene_key_idx("method", "preset")];
  return vs->preset < 0 ? "none" : line < 0 ? "command line" : "scene file";
}

int ver_method_key(int ki)
{
  char name[64];
  snprintf(name, sizeof name, "%s.%s", ver_scene_keys[ki].section, ver_scene_keys[ki].key);
  for (int i = 0; i < NMETHOD_KEYS; i++)
    if (!strcmp(method_keys[i], name))
      return 1;
  return 0;
}

int ver_method_held(int ki)
{
  char name[64];
  snprintf(name, sizeof name, "%s.%s", ver_scene_keys[ki].section, ver_scene_keys[ki].key);
  for (size_t i = 0; i < sizeof held_keys / sizeof held_keys[0]; i++)
    if (!strcmp(held_keys[i], name))
      return 1;
  return 0;
}

/* Index of the key of a "section.key=value" row; the value into *value. */
static int row_key(const char *row, const char **value)
{
  char sec[32], key[32];
  const char *dot = strchr(row, '.'), *eq = strchr(row, '=');
  snprintf(sec, sizeof sec, "%.*s", (int)(dot - row), row);
  snprintf(key, sizeof key, "%.*s", (int)(eq - dot - 1), dot + 1);
  *value = eq + 1;
  return ver_scene_key_idx(sec, key);
}

int ver_method_apply_file(ver_scene *vs, int line, char *msg, size_t len)
{
  const char *const *sets;
  const int n = ver_method_rows(vs->preset, &sets);
  for (int i = 0; i < n; i++) {
    const char *value;
    const int ki = row_key(sets[i], &value);
    if (vs->seen[ki])
      continue; /* the file's own key wins */
    if (ver_scene_key_set(vs, ki, value, msg, len))
      return 2;
    vs->line[ki] = line;
  }
  return 0;
}

/* Every method key back to its default (and without its word: damping = critical). */
static void reset_method(ver_scene *vs)
{
  char *base = (char *)vs;
  for (int ki = 0; ki < ver_scene_nkeys; ki++) {
    const keydef *k = &ver_scene_keys[ki];
    if (!ver_method_key(ki))
      continue;
    if (k->type == K_DBL)
      *(double *)(base + k->off) = k->def;
    else
      *(int *)(base + k->off) = (int)k->def;
    vs->seen[ki] = 0;
    vs->line[ki] = 0;
  }
  vs->damping_critical = vs->damping_beta_cell = 0;
}

int ver_method_apply_cmd(ver_scene *vs, char *msg, size_t len)
{
  reset_method(vs);
  const char *const *sets;
  const int n = ver_method_rows(vs->preset, &sets);
  for (int i = 0; i < n; i++) {
    const char *value;
    const int ki = row_key(sets[i], &value);
    if (ver_scene_key_set(vs, ki, value, msg, len))
      return 2;
    vs->seen[ki] = 1;
    vs->line[ki] = -1;
  }
  /* the overrides of method keys before it no longer hold */
  int m = 0;
  for (int i = 0; i < vs->nover; i++) {
    const char *o = vs->over[i], *eq = strchr(o, '='), *dot = strchr(o, '.');
    char sec[32], key[32];
    snprintf(sec, sizeof sec, "%.*s", dot && dot < eq ? (int)(dot - o) : 0, o);
    snprintf(key, sizeof key, "%.*s", dot && dot < eq ? (int)(eq - dot - 1) : 0, dot ? dot + 1 : o);
    const int ki = ver_scene_key_find(sec, key);
    if (ki >= 0 && ver_method_key(ki))
      continue;
    if (m != i)
      memcpy(vs->over[m], vs->over[i], sizeof vs->over[0]);
    m++;
  }
  vs->nover = m;
  return 0;
}

/* The value of method key ki in vs as a scene file writes it. */
static void key_value(const ver_scene *vs, int ki, char *buf, size_t len)
{
  const keydef *k = &ver_scene_keys[ki];
  const char *base = (const char *)vs;
  if (ver_scene_enum_type(k->type)) {
    snprintf(buf, len, "%s", ver_scene_word(vs, k->section, k->key));
    return;
  }
  if ((!strcmp(k->key, "damping") && vs->damping_critical) || (!strcmp(k->key, "damping_beta") && vs->damping_beta_cell)) {
    snprintf(buf, len, "%s", !strcmp(k->key, "damping") ? "critical" : "cell");
    return;
  }
  double v;
  memcpy(&v, base + k->off, sizeof v);
  ver_scene_fmt_num(v, buf, len);
}

int ver_method_overrides(const ver_scene *vs, char out[][64], int max)
{
  ver_scene ref = *vs;
  char msg[256], val[48];
  ver_method_apply_cmd(&ref, msg, sizeof msg);
  int n = 0;
  for (int ki = 0; ki < ver_scene_nkeys && n < max; ki++) {
    if (!ver_method_key(ki))
      continue;
    const size_t sz = ver_scene_keys[ki].type == K_DBL ? sizeof(double) : sizeof(int);
    const int word_differs = (!strcmp(ver_scene_keys[ki].key, "damping") && vs->damping_critical) ||
                             (!strcmp(ver_scene_keys[ki].key, "damping_beta") && vs->damping_beta_cell);
    if (!word_differs && !memcmp((const char *)vs + ver_scene_keys[ki].off, (const char *)&ref + ver_scene_keys[ki].off, sz))
      continue;
    key_value(vs, ki, val, sizeof val);
    snprintf(out[n++], 64, "%s.%s=%s", ver_scene_keys[ki].section, ver_scene_keys[ki].key, val);
  }
  return n;
}

void ver_method_list(char *buf, size_t len)
{
  size_t n = 0;
  buf[0] = '\0';
  for (int i = 0; i < NPRESETS && n < len; i++)
    n += (size_t)snprintf(buf + n, len - n, "%s%s", i == 0 ? "" : i + 1 < NPRESETS ? ", " : " or ", presets[i].name);
}
