/*
 * report_data.c - what `delam report` reads back from a run (summary.json, load.csv,
 * snapshots) and what it measures against the analytic bar (MODEL.md sec. 5):
 * curve error, softening slope, width of the load drop, dissipation error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "report.h"
#include "scene.h"

static char *slurp(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f)
    return NULL;
  char *buf = NULL;
  size_t len = 0, cap = 0;
  for (;;) {
    if (len + 4096 + 1 > cap) {
      cap = 2 * cap + 8192;
      char *nb = realloc(buf, cap);
      if (!nb) {
        free(buf);
        fclose(f);
        return NULL;
      }
      buf = nb;
    }
    const size_t k = fread(buf + len, 1, 4096, f);
    len += k;
    if (k < 4096)
      break;
  }
  fclose(f);
  buf[len] = '\0';
  return buf;
}

static double num(const cJSON *o, const char *k)
{
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
  return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

int ver_report_read_summary(rep_case *c)
{
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/summary.json", c->dir);
  char *txt = slurp(p);
  if (!txt)
    return -1;
  cJSON *o = cJSON_Parse(txt);
  free(txt);
  if (!o)
    return -1;
  c->complete = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(o, "complete"));
  c->peak_P = num(o, "peak_P");
  c->delta_peak = num(o, "delta_peak");
  c->delta_sep = num(o, "delta_sep");
  c->k_elastic = num(o, "k_elastic");
  c->D_final = num(o, "D_final");
  c->W_ext_final = num(o, "W_ext_final");
  c->energy_residual = num(o, "energy_residual");
  c->delta_end = num(o, "delta_end");
  c->cpu_s = num(o, "cpu_s");
  c->wall_s = num(o, "wall_s");
  c->updates_per_s = num(o, "updates_per_s");
  c->dt_used = num(o, "dt");
  const double st = num(o, "steps");
  c->steps = isfinite(st) ? (long)st : 0;
  c->particles = num(o, "particles");
  const cJSON *e = cJSON_GetObjectItemCaseSensitive(o, "error");
  c->error[0] = '\0';
  if (cJSON_IsString(e))
    snprintf(c->error, sizeof c->error, "%s", e->valuestring);
  cJSON_Delete(o);
  return 0;
}

/* Index of the header field name in a CSV header line, or -1. */
static int column(const char *header, const char *name)
{
  int k = 0;
  const size_t n = strlen(name);
  for (const char *s = header; *s; k++) {
    const char *e = s + strcspn(s, ",\r\n");
    if ((size_t)(e - s) == n && !strncmp(s, name, n))
      return k;
    if (*e != ',')
      break;
    s = e + 1;
  }
  return -1;
}

int ver_report_snapshot(const char *path, const char *const *cols, int ncol, double **out)
{
  FILE *f = fopen(path, "r");
  for (int j = 0; j < ncol; j++)
    out[j] = NULL;
  if (!f)
    return 0;
  char line[4096];
  int idx[16], n = 0, cap = 0;
  if (ncol > 16 || !fgets(line, sizeof line, f)) {
    fclose(f);
    return 0;
  }
  for (int j = 0; j < ncol; j++)
    if ((idx[j] = column(line, cols[j])) < 0) {
      fclose(f);
      return 0;
    }
  while (fgets(line, sizeof line, f)) {
    if (n == cap) {
      cap = cap ? 2 * cap : 1024;
      for (int j = 0; j < ncol; j++) {
        double *nb = realloc(out[j], (size_t)cap * sizeof *nb);
        if (!nb) {
          fclose(f);
          return n;
        }
        out[j] = nb;
      }
    }
    double v[64];
    int k = 0;
    for (char *s = line; k < 64;) {
      char *end;
      v[k++] = strtod(s, &end);
      s = end + strcspn(end, ",");
      if (*s != ',')
        break;
      s++;
    }
    for (int j = 0; j < ncol; j++)
      out[j][n] = idx[j] < k ? v[idx[j]] : NAN;
    n++;
  }
  fclose(f);
  return n;
}

int ver_report_load(const rep_case *c, double **delta, double **P)
{
  char p[REP_PATH + 32];
  snprintf(p, sizeof p, "%s/load.csv", c->dir);
  const char *cols[2] = {"delta", "P_grip"};
  double *o[2];
  const int n = ver_report_snapshot(p, cols, 2, o);
  *delta = o[0];
  *P = o[1];
  return n;
}

double ver_report_order(const double *x, const double *y, int n, double *logc)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int k = 0;
  for (int i = 0; i < n; i++) {
    if (!(x[i] > 0 && y[i] > 0 && isfinite(x[i]) && isfinite(y[i])))
      continue;
    const double a = log(x[i]), b = log(y[i]);
    sx += a;
    sy += b;
    sxx += a * a;
    sxy += a * b;
    k++;
  }
  if (k < 2 || sxx * k - sx * sx <= 0) {
    if (logc)
      *logc = NAN;
    return NAN;
  }
  const double p = (k * sxy - sx * sy) / (k * sxx - sx * sx);
  if (logc)
    *logc = (sy - p * sx) / k;
  return p;
}

/* The analytic bar of a scene file (overrides do not change it). */
static int scene_bar(const rep_ctx *r, const char *scene, ana_bar *bar)
{
  char path[REP_PATH + 64], err[256];
  ver_scene vs;
  snprintf(path, sizeof path, "%s/%s.ini", r->scenes, scene);
  if (ver_scene_load(path, &vs, err, sizeof err) != 0)
    return -1;
  const mpm_scene *s = &vs.sc;
  ana_params p = {s->alpha_deg, s->snf, s->stf, s->U0, s->s0 > 0 ? s->s0 : s->snf, s->q, s->E, s->nu,
                  s->L, s->H, s->model};
  return ana_bar_init(&p, bar, err, (int)sizeof err) == ANA_OK ? 0 : -1;
}

void ver_report_measure(const rep_ctx *r, rep_case *c)
{
  c->bar_ok = scene_bar(r, c->scene, &c->bar) == 0;
  if (!c->have || !c->bar_ok)
    return;
  const ana_bar *b = &c->bar;
  c->diss_err = c->D_final / b->D_sep - 1.0;
  double *d, *P;
  const int n = ver_report_load(c, &d, &P);
  c->rows = n;
  c->cmp_end = 1.5 * fmax(b->delta_peak, b->delta_sep);
  double s2 = 0, mx = 0, mabs = 0;
  int k = 0, ipk = -1;
  for (int i = 0; i < n; i++) {
    if (!isfinite(P[i])) {
      mabs = INFINITY;
      continue;
    }
    mabs = fmax(mabs, fabs(P[i]));
    if (ipk < 0 || P[i] > P[ipk])
      ipk = i;
    if (d[i] > c->cmp_end)
      continue;
    const double e = (P[i] - ana_bar_load_at(b, d[i])) / b->Pmax;
    s2 += e * e;
    mx = fmax(mx, fabs(e));
    k++;
  }
  c->max_absP = mabs;
  if (k > 0) {
    c->curve_err = sqrt(s2 / k);
    c->max_dev = mx;
  }
  if (ipk >= 0) {
    /* softening slope: least squares over the first stretch after the peak with
     * 0.3 Ppk <= P <= 0.8 Ppk; drop width: from 0.9 to 0.1 of the peak */
    const double Ppk = P[ipk];
    double sx = 0, sy = 0, sxx = 0, sxy = 0, d90 = NAN, d10 = NAN;
    int m = 0;
    for (int i = ipk; i < n; i++) {
      if (isnan(d90) && P[i] < 0.9 * Ppk)
        d90 = d[i];
      if (P[i] < 0.1 * Ppk) {
        d10 = d[i];
        break;
      }
      if (P[i] <= 0.8 * Ppk && P[i] >= 0.3 * Ppk) {
        sx += d[i];
        sy += P[i];
        sxx += d[i] * d[i];
        sxy += d[i] * P[i];
        m++;
      }
    }
    if (m >= 3 && m * sxx - sx * sx > 0)
      c->k_soft = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    c->drop_width = d10 - d90;
  }
  free(d);
  free(P);
}
