/*
 * scene_ini.c - what a scene says about itself (scene.h): the case id, numbers as the
 * scene files write them, the effective scene as an INI file that reruns bit for bit,
 * and the key table as Markdown (docs/scene-keys.md).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "build_info.h"
#include "scene.h"
#include "scene_keys.h"

void ver_scene_base_id(const ver_scene *vs, char *buf, size_t len)
{
  char h[64];
  ver_scene_id_num(vs->sc.h, h, sizeof h);
  snprintf(buf, len, "%s-h%s-ppc%d", vs->name, h, vs->sc.ppc);
}

void ver_scene_fmt_num(double v, char *buf, size_t len)
{
  for (int prec = 1; prec <= 17; prec++) {
    snprintf(buf, len, "%.*g", prec, v);
    if (strtod(buf, NULL) == v)
      break;
  }
  /* as a person writes it: no exponent between 1e-9 and 1e15 (90, not 9e+01; 0.00001,
   * not 1e-05) */
  const double a = fabs(v);
  if (!strchr(buf, 'e') || !(a >= 1e-9 && a < 1e15))
    return;
  for (int dec = 0; dec <= 26; dec++) {
    snprintf(buf, len, "%.*f", dec, v);
    if (strtod(buf, NULL) == v)
      return;
  }
}

void ver_scene_id_num(double v, char *buf, size_t len)
{
  ver_scene_fmt_num(v, buf, len);
  if (!strchr(buf, 'e'))
    return;
  char t[64];
  for (int dec = 0; dec <= 40; dec++) { /* a folder name has no exponent: 0.00001, not 1e-05 */
    snprintf(t, sizeof t, "%.*f", dec, v);
    if (strtod(t, NULL) == v || dec == 40) {
      snprintf(buf, len, "%s", t);
      return;
    }
  }
}

void ver_scene_id_part(const char *set, char *buf, size_t len)
{
  const char *eq = strchr(set, '='), *dot = strchr(set, '.');
  const char *key = dot && dot < eq ? dot + 1 : set;
  const int klen = (int)(eq - key);
  char val[64];
  double v;
  if (ver_scene_key_num(eq + 1, &v) == 0) {
    ver_scene_id_num(v, val, sizeof val);
    const int digit_end = klen > 0 && key[klen - 1] >= '0' && key[klen - 1] <= '9';
    snprintf(buf, len, "%.*s%s%s", klen, key, digit_end ? "_" : "", val); /* E2048, a0_100 */
  } else if ((klen == 4 && !strncmp(key, "type", 4)) || (klen == 6 && !strncmp(key, "preset", 6)))
    snprintf(buf, len, "%.60s", eq + 1); /* static, els, paper: the word alone */
  else
    snprintf(buf, len, "%.*s_%.60s", klen, key, eq + 1); /* scheme_musl, Le_zone */
  for (char *c = buf; *c; c++)
    if (*c == '/' || *c == ' ' || *c == ',' || *c == '=')
      *c = '_'; /* a folder name */
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
    char part[128];
    ver_scene_id_part(o, part, sizeof part);
    if (n < len)
      n += (size_t)snprintf(buf + n, len - n, "-%s", part);
  }
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
  for (int si = 0; si < ver_scene_nkeys; si++) {
    if (!ver_scene_key_first(si))
      continue;
    fprintf(f, "\n[%s]\n", ver_scene_keys[si].section);
  for (int i = si; i < ver_scene_nkeys; i++) {
    const keydef *k = &ver_scene_keys[i];
    if (strcmp(k->section, ver_scene_keys[si].section))
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
    if (ver_scene_enum_type(k->type)) {
      int v;
      memcpy(&v, base + k->off, sizeof v);
      if (k->type == K_PRESET && v < 0)
        continue; /* no preset: every key below says the method */
      fprintf(f, "%s = %s\n", k->key, ver_scene_enum_word(k->type, v));
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
    if (!vs->seen[i] && (k->required || !ver_scene_key_in_range(k, v)))
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

/* One row of the key table; held: the presets' knobs, without the required column. */
static void key_row(FILE *f, const keydef *k, int held)
{
  char def[64];
  if (k->required)
    snprintf(def, sizeof def, "-");
  else if (ver_scene_enum_type(k->type))
    snprintf(def, sizeof def, "%s", ver_scene_enum_word(k->type, (int)k->def));
  else if (k->type == K_LIST)
    snprintf(def, sizeof def, "none");
  else if (k->def < 0)
    snprintf(def, sizeof def, "derived");
  else
    snprintf(def, sizeof def, "%g", k->def);
  if (held) {
    fprintf(f, "| %s.%s | %s | %s | %s |\n", k->section, k->key, type_name(k->type), k->allowed, def);
    return;
  }
  fprintf(f, "| %s | %s | %s | %s | %s | %s |\n", k->section, k->key, type_name(k->type),
          k->required == 1   ? "yes"
          : k->required == 2 ? "when decohesion.model > 0"
          : k->required == 3 ? "unless vibration.mode > 0"
                             : "no",
          k->allowed, def);
}

void ver_scene_keys_markdown(FILE *f)
{
  fprintf(f, "| section | key | type | required | allowed | default |\n|---|---|---|---|---|---|\n");
  for (int i = 0; i < ver_scene_nkeys; i++)
    if (!ver_method_held(i))
      key_row(f, &ver_scene_keys[i], 0);
  fprintf(f, "\nHeld by the presets (advanced: a scene file or --set may still set them):\n\n"
             "| key | type | allowed | default |\n|---|---|---|---|\n");
  for (int i = 0; i < ver_scene_nkeys; i++)
    if (ver_method_held(i))
      key_row(f, &ver_scene_keys[i], 1);
}

const char *ver_scene_word(const ver_scene *vs, const char *section, const char *key)
{
  const int i = ver_scene_key_find(section, key);
  if (i < 0 || !ver_scene_enum_type(ver_scene_keys[i].type))
    return "";
  int v;
  memcpy(&v, (const char *)vs + ver_scene_keys[i].off, sizeof v);
  return ver_scene_enum_word(ver_scene_keys[i].type, v);
}
