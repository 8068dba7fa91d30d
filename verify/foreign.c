/*
 * foreign.c - a run folder that another code wrote (foreign.h): its CSV files read
 * strictly, and the measurements `delam verify` takes from delam's own runs (metrics.h,
 * separation.h) taken from them.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "datadir.h"
#include "foreign.h"
#include "io.h"
#include "metrics.h"
#include "separation.h"

void ver_table_free(ver_table *t)
{
  for (int j = 0; j < VER_TABLE_MAXCOL; j++)
    free(t->col[j]);
  memset(t, 0, sizeof *t);
}

static char *trim(char *s)
{
  while (*s == ' ' || *s == '\t' || *s == '"')
    s++;
  char *e = s + strlen(s);
  while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '"'))
    *--e = '\0';
  return s;
}

int ver_table_read(const char *path, const char *const *names, int nname, int nreq, ver_table *t, char *err,
                   size_t errlen)
{
  memset(t, 0, sizeof *t);
  char *txt = ver_io_slurp(path, NULL, VER_TABLE_MAXBYTES);
  if (!txt) {
    const int e = errno;
    struct stat st;
    if (e == ENOENT)
      return 1;
    if (e == EINVAL && stat(path, &st) == 0)
      snprintf(err, errlen, "%s: %s, not a CSV file (a regular file is needed)", path, ver_file_kind(st.st_mode));
    else if (e == EFBIG)
      snprintf(err, errlen, "%s: larger than %d MiB: refused", path, VER_TABLE_MAXBYTES >> 20);
    else
      snprintf(err, errlen, "%s: cannot read: %s", path, strerror(e));
    return 2;
  }
  long rows = 0;
  for (const char *s = txt; *s; s++)
    rows += *s == '\n';
  int idx[VER_TABLE_MAXCOL];
  for (int j = 0; j < nname; j++)
    idx[j] = -1;
  int line = 0, have_header = 0, rc = 0, ncol = 0;
  for (char *ln = txt, *next; *ln && !rc; ln = next) {
    char *nl = strchr(ln, '\n');
    next = nl ? nl + 1 : ln + strlen(ln);
    if (nl)
      *nl = '\0';
    line++;
    char *s = trim(ln);
    if (!*s || (*s == '#' && !have_header))
      continue;
    if (!have_header) {
      have_header = 1;
      char *hs = NULL;
      ncol = 0;
      for (char *f = strtok_r(s, ",", &hs); f; f = strtok_r(NULL, ",", &hs), ncol++)
        for (int j = 0; j < nname; j++)
          if (!strcmp(trim(f), names[j]))
            idx[j] = ncol;
      for (int j = 0; j < nreq; j++)
        if (idx[j] < 0) {
          snprintf(err, errlen, "%s:%d: the header has no column '%s' (needed: ", path, line, names[j]);
          for (int q = 0; q < nreq; q++)
            snprintf(err + strlen(err), errlen - strlen(err), "%s%s", q ? ", " : "", names[q]);
          snprintf(err + strlen(err), errlen - strlen(err), ")");
          rc = 2;
        }
      for (int j = 0; j < nname && !rc; j++)
        if (idx[j] >= 0 && !(t->col[j] = malloc(sizeof(double) * (size_t)(rows + 1)))) {
          snprintf(err, errlen, "%s: out of memory", path);
          rc = 2;
        }
      continue;
    }
    /* a data row: split it once, then take the wanted fields */
    char *fields[256];
    int nf = 0;
    for (char *p = s;;) {
      if (nf == 256)
        break;
      fields[nf++] = p;
      char *c = strchr(p, ',');
      if (!c)
        break;
      *c = '\0';
      p = c + 1;
    }
    for (int j = 0; j < nname && !rc; j++) {
      if (idx[j] < 0)
        continue;
      if (idx[j] >= nf) {
        snprintf(err, errlen, "%s:%d:%d: no field for column '%s' (the row has %d fields, the header %d)", path,
                 line, idx[j] + 1, names[j], nf, ncol);
        rc = 2;
        break;
      }
      char *f = trim(fields[idx[j]]), *end;
      errno = 0;
      const double v = strtod(f, &end);
      if (end == f || *end || !isfinite(v)) {
        snprintf(err, errlen, "%s:%d:%d: column '%s': '%.40s' is not a finite number", path, line, idx[j] + 1,
                 names[j], f);
        rc = 2;
        break;
      }
      t->col[j][t->n] = v;
    }
    t->n++;
  }
  free(txt);
  if (!rc && !have_header) {
    snprintf(err, errlen, "%s:1: no header line (expected at least: %s%s%s)", path, names[0], nreq > 1 ? ", " : "",
             nreq > 1 ? names[1] : "");
    rc = 2;
  } else if (!rc && t->n < 3) {
    snprintf(err, errlen, "%s:%d: %ld data rows; at least 3 are needed", path, line, t->n);
    rc = 2;
  }
  if (rc)
    ver_table_free(t);
  return rc;
}

void ver_foreign_measure(ver_case *c, const ver_table *ld, const ver_table *en, const ver_table *pt)
{
  const mpm_scene *sc = &c->vs.sc;
  const double *d = ld->col[0], *P = ld->col[1], *Pf = ld->col[2] ? ld->col[2] : ld->col[1];
  const size_t n = (size_t)ld->n;
  c->complete = 1;
  c->exit_code = 0;
  c->peak_P = -INFINITY;
  for (size_t i = 0; i < n; i++)
    if (P[i] > c->peak_P) {
      c->peak_P = P[i];
      c->delta_peak = d[i];
    }
  c->delta_end = d[n - 1];
  c->k_elastic = ver_elastic_slope(d, P, n, c->peak_P, c->delta_peak, VER_ELASTIC_LO, VER_ELASTIC_HI);
  c->k_soft = ver_softening_slope(d, P, n, VER_SOFT_HI, VER_SOFT_LO);
  if (c->have_ana)
    c->curve_l2 = ver_curve_err_bar(&c->ana, d, P, n, ver_curve_end(&c->ana, sc->sep_threshold), NULL);
  ver_case_wave(c, d, P, n);
  /* separation by the load, with the run's window of 4 L / c in delta */
  const double cw = sqrt(sc->E / (1.0 - sc->nu * sc->nu) / sc->rho);
  const double step = (d[n - 1] - d[0]) / (double)(n - 1);
  const long win = step > 0 ? (long)fmax(1.0, ceil(4.0 * sc->L / cw * sc->speed / step)) : 1;
  ver_sep sep;
  c->delta_sep = NAN;
  if (ver_sep_init(&sep, sc->H, sc->h, sc->ppc, win, c->vs.sep_load_frac) == 0) {
    double peak = -INFINITY, dpk = 0.0;
    for (size_t i = 0; i < n; i++) {
      if (P[i] > peak) {
        peak = P[i];
        dpk = d[i];
      }
      ver_sep_load(&sep, d[i], P[i], Pf[i], peak, dpk);
    }
    if (sep.delta_sep >= 0)
      c->delta_sep = sep.delta_sep;
    ver_sep_free(&sep);
  }
  c->P_after = ver_load_after(d, P, n, c->delta_sep, c->peak_P, &c->P_after_t, &c->P_after_c);
  if (en) { /* W_ext, KE, SE, W_coh, D */
    const size_t m = (size_t)en->n;
    c->W_ext_final = en->col[0][m - 1];
    c->D_final = en->col[4][m - 1];
    /* delam's own definition; the ledger columns count where the file has them, and
     * the energy at the start is that of the first row less the work done by then */
    const double *e[VER_ENERGY_COLS] = {en->col[0], en->col[1], en->col[2], en->col[3], en->col[5],
                                        en->col[6], en->col[7], en->col[8], en->col[9], en->col[10], en->col[11]};
    const double E0 = fmax(0.0, en->col[1][0] + en->col[2][0] - en->col[0][0]);
    c->energy_residual = ver_energy_residual(e, m, E0, NULL);
    c->W_booked = 0.0; /* the ledger's columns the file has */
    for (int j = 4; j < VER_ENERGY_COLS; j++)
      c->W_booked += e[j] ? e[j][m - 1] : 0.0;
    /* the discretisation's own loss: L_bc, L_flip, L_scheme, all three or not judged */
    c->W_scheme = e[4] && e[5] && e[6] ? e[4][m - 1] + e[5][m - 1] + e[6][m - 1] : NAN;
  } else { /* the external work is the area under the load-deflection curve */
    double w = 0.5 * P[0] * d[0];
    for (size_t i = 1; i < n; i++)
      w += 0.5 * (P[i] + P[i - 1]) * (d[i] - d[i - 1]);
    c->W_ext_final = w;
    c->W_booked = 0.0;
    c->W_scheme = NAN;
    c->D_final = c->energy_residual = NAN;
  }
  c->band_width = c->angle = c->D_diffuse = NAN;
  if (pt) {
    const size_t m = (size_t)pt->n;
    c->band_width = ver_band_width(pt->col[0], pt->col[1], pt->col[2], m, VER_BAND_LAMBDA, sc->alpha_deg, sc->h,
                                   sc->ppc, sc->H, &c->band_extent, &c->band_count);
    c->angle = ver_crack_angle(pt->col[0], pt->col[1], pt->col[2], m, sc->sep_threshold);
    if (c->have_ana && c->ana.D_sep > 0.0 && isfinite(c->D_final))
      c->D_diffuse = ver_diffuse_share(pt->col[2], m, VER_BAND_LAMBDA) * c->D_final / c->ana.D_sep;
  }
}

