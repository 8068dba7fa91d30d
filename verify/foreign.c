/*
 * foreign.c - a run folder that another code wrote (foreign.h): its CSV files read
 * strictly, and the measurements `delam verify` takes from delam's own runs (metrics.h,
 * separation.h) taken from them.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "datadir.h"
#include "foreign.h"
#include "separation.h"
#include "io.h"
#include "metrics.h"

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

/* The first byte of line `line`, [s, e), that is not text (NUL, a control byte other
 * than tab and CR, or DEL), named by line and byte in err; 0 if there is none. */
static int line_text(const char *path, int line, const char *s, const char *e, char *err, size_t errlen)
{
  for (const char *p = s; p < e; p++) {
    const unsigned char c = (unsigned char)*p;
    if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
      snprintf(err, errlen, "%s:%d: byte %zu of the line is %s (0x%02x): not a text file", path, line,
               (size_t)(p - s) + 1, c ? "a control byte" : "a NUL byte", c);
      return 2;
    }
  }
  return 0;
}

/* The header line s: want[k] = j where field k is names[j] (ncol fields, want malloc'd);
 * 0, or 2 with err. */
static int table_header(const char *path, int line, char *s, const char *const *names, int nname, int nreq,
                        int **want, int *ncol, char *err, size_t errlen)
{
  int found[VER_TABLE_MAXCOL] = {0};
  *ncol = 1;
  for (const char *p = s; *p; p++)
    *ncol += *p == ',';
  if (!(*want = malloc(sizeof(int) * (size_t)*ncol))) {
    snprintf(err, errlen, "%s: out of memory", path);
    return 2;
  }
  char *f = s; /* field k of the header is column k of every row, empty ones too */
  for (int k = 0; k < *ncol; k++) {
    char *c = strchr(f, ',');
    if (c)
      *c = '\0';
    const char *name = trim(f);
    (*want)[k] = -1;
    for (int j = 0; j < nname; j++)
      if (!found[j] && !strcmp(name, names[j])) {
        (*want)[k] = j;
        found[j] = 1;
        break;
      }
    f = c ? c + 1 : f + strlen(f);
  }
  for (int j = 0; j < nreq; j++)
    if (!found[j]) {
      snprintf(err, errlen, "%s:%d: the header has no column '%s' (needed: ", path, line, names[j]);
      for (int q = 0; q < nreq; q++)
        snprintf(err + strlen(err), errlen - strlen(err), "%s%s", q ? ", " : "", names[q]);
      snprintf(err + strlen(err), errlen - strlen(err), ")");
      return 2;
    }
  return 0;
}

/* strtod(s, end) of a whole field, with a fast path where the field is a plain decimal
 * ([-+]digits[.digits][e[-+]digits] and nothing after it):
 * at most 19 significant digits whose integer fits 2^53 and a power of ten up to 22
 * are two exact doubles, so one multiplication or division rounds correctly (Clinger
 * 1990), the same double as strtod; anything else goes to strtod. */
static double parse_num(const char *s, char **end)
{
  static const double p10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                               1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const char *p = s;
  const int neg = *p == '-';
  p += *p == '-' || *p == '+';
  uint64_t m = 0;
  int nd = 0, e = 0;
  for (; *p >= '0' && *p <= '9'; p++, nd++)
    m = m * 10 + (uint64_t)(*p - '0');
  if (*p == '.')
    for (p++; *p >= '0' && *p <= '9'; p++, nd++, e--)
      m = m * 10 + (uint64_t)(*p - '0');
  if (nd > 0 && nd <= 19 && (*p == 'e' || *p == 'E')) {
    const char *q = p + 1;
    const int eneg = *q == '-';
    q += *q == '-' || *q == '+';
    int x = 0, nx = 0;
    for (; *q >= '0' && *q <= '9' && nx < 4; q++, nx++)
      x = x * 10 + (*q - '0');
    e += eneg ? -x : x;
    p = nx && !(*q >= '0' && *q <= '9') ? q : s; /* s: not plain, strtod decides */
  }
  if (nd == 0 || nd > 19 || p == s || *p || m > (1ull << 53) || e < -22 || e > 22)
    return strtod(s, end);
  *end = (char *)(uintptr_t)p; /* as strtod: end points into the caller's string */
  const double v = e < 0 ? (double)m / p10[-e] : (double)m * p10[e];
  return neg ? -v : v;
}

/* One data row s (line `line`) into row t->n of the wanted columns; 0, or 2 with err. */
static int table_row(const char *path, int line, char *s, const int *want, int ncol, const char *const *names,
                     ver_table *t, char *err, size_t errlen)
{
  int nf = 0, got = 0, nwant = 0;
  for (int k = 0; k < ncol; k++)
    nwant += want[k] >= 0;
  for (char *p = s; p; nf++) {
    char *c = strchr(p, ',');
    if (c)
      *c = '\0';
    const int j = nf < ncol ? want[nf] : -1;
    if (j >= 0) {
      char *f = trim(p), *end;
      const double v = parse_num(f, &end);
      if (end == f || *end || !isfinite(v)) {
        snprintf(err, errlen, "%s:%d:%d: column '%s': '%.40s' is not a finite number", path, line, nf + 1,
                 names[j], f);
        return 2;
      }
      t->col[j][t->n] = v;
      got++;
    }
    p = c ? c + 1 : NULL;
  }
  if (got < nwant)
    for (int k = nf; k < ncol; k++)
      if (want[k] >= 0) {
        snprintf(err, errlen, "%s:%d:%d: no field for column '%s' (the row has %d fields, the header %d)", path,
                 line, k + 1, names[want[k]], nf, ncol);
        return 2;
      }
  t->n++;
  return 0;
}

/* The file's text, NUL-terminated, or NULL: 1 (no such file) or 2 (err) in *rc. */
static char *table_text(const char *path, size_t *len, int *rc, char *err, size_t errlen)
{
  char *txt = ver_io_slurp(path, len, VER_TABLE_MAXBYTES);
  *rc = 0;
  if (!txt) {
    const int e = errno;
    struct stat st;
    *rc = 2;
    if (e == ENOENT)
      *rc = 1;
    else if (e == EINVAL && stat(path, &st) == 0)
      snprintf(err, errlen, "%s: %s, not a CSV file (a regular file is needed)", path, ver_file_kind(st.st_mode));
    else if (e == EFBIG)
      snprintf(err, errlen, "%s: larger than %d MiB: refused", path, VER_TABLE_MAXBYTES >> 20);
    else
      snprintf(err, errlen, "%s: cannot read: %s", path, strerror(e));
  }
  return txt;
}

int ver_table_read(const char *path, const char *const *names, int nname, int nreq, ver_table *t, char *err,
                   size_t errlen)
{
  memset(t, 0, sizeof *t);
  size_t len = 0;
  int rc;
  char *txt = table_text(path, &len, &rc, err, errlen);
  if (!txt)
    return rc;
  const unsigned char *u = (const unsigned char *)txt;
  if (len >= 2 && ((u[0] == 0xff && u[1] == 0xfe) || (u[0] == 0xfe && u[1] == 0xff))) {
    snprintf(err, errlen, "%s:1: UTF-16 text (it starts with the byte-order mark 0x%02x 0x%02x): save it as UTF-8 "
             "or ASCII", path, u[0], u[1]);
    free(txt);
    return 2;
  }
  /* a UTF-8 byte-order mark (spreadsheets write one) is no part of the header's first name */
  const size_t bom = len >= 3 && u[0] == 0xef && u[1] == 0xbb && u[2] == 0xbf ? 3 : 0;
  if (bom) {
    memmove(txt, txt + bom, len - bom + 1);
    len -= bom;
  }
  long rows = 1;
  for (const char *s = txt; (s = memchr(s, '\n', len - (size_t)(s - txt))); s++)
    rows++;
  int line = 0, ncol = 0, *want = NULL;
  for (char *ln = txt, *end = txt + len, *next; ln < end && !rc; ln = next) {
    char *nl = memchr(ln, '\n', (size_t)(end - ln)), *le = nl ? nl : end;
    next = nl ? nl + 1 : end;
    if ((rc = line_text(path, ++line, ln, le, err, errlen)))
      break;
    *le = '\0'; /* the newline, or the NUL after the text */
    while (le > ln && (le[-1] == ' ' || le[-1] == '\t' || le[-1] == '\r' || le[-1] == '"'))
      *--le = '\0';
    char *s = trim(ln);
    if (!*s || (*s == '#' && !want))
      continue;
    if (!want) {
      rc = table_header(path, line, s, names, nname, nreq, &want, &ncol, err, errlen);
      for (int k = 0; k < ncol && !rc; k++)
        if (want[k] >= 0 && !(t->col[want[k]] = malloc(sizeof(double) * (size_t)rows))) {
          snprintf(err, errlen, "%s: out of memory", path);
          rc = 2;
        }
    } else
      rc = table_row(path, line, s, want, ncol, names, t, err, errlen);
  }
  free(txt);
  if (!rc && !want) {
    snprintf(err, errlen, "%s:1: no header line (expected at least: %s%s%s)", path, names[0], nreq > 1 ? ", " : "",
             nreq > 1 ? names[1] : "");
    rc = 2;
  } else if (!rc && t->n < 3) {
    snprintf(err, errlen, "%s:%d: %ld data rows; at least 3 are needed", path, line, t->n);
    rc = 2;
  }
  free(want);
  if (rc)
    ver_table_free(t);
  return rc;
}

/* The load each row stands for over its interval (delta[i - 1], delta[i]] (delam's rows
 * are interval averages), summed from the first row: the integral of P d delta; NULL if
 * out of memory. */
static double *load_integral(const double *d, const double *P, size_t n)
{
  double *I = malloc(sizeof(double) * (n ? n : 1));
  if (!I)
    return NULL;
  for (size_t i = 0; i < n; i++)
    I[i] = i ? I[i - 1] + P[i] * (d[i] - d[i - 1]) : 0.0;
  return I;
}

/* The integral from the first row to x, d[0] <= x <= d[n - 1]; *j (a cursor kept between
 * calls, so that a sweep in x is linear) becomes the row whose interval holds x. */
static double integral_at(const double *d, const double *P, const double *I, size_t n, size_t *j, double x)
{
  while (*j + 1 < n && d[*j] < x)
    (*j)++;
  while (*j > 0 && d[*j - 1] >= x) /* a delta that went back (dissipation control) */
    (*j)--;
  return I[*j] - P[*j] * (d[*j] - x);
}

/* The window's means of both loads when it ends at x, the larger of the two over the
 * threshold in *over (signed: below 0 both are under it). */
typedef struct {
  const double *d, *P, *Pf, *Ig, *If;
  size_t n, jg, jf, kg, kf; /* cursors: the window's end and start, each load */
  double span, thr;
} sep_win;

static double win_over(sep_win *w, double x)
{
  const double g = integral_at(w->d, w->P, w->Ig, w->n, &w->jg, x) -
                   integral_at(w->d, w->P, w->Ig, w->n, &w->kg, x - w->span);
  const double f = integral_at(w->d, w->Pf, w->If, w->n, &w->jf, x) -
                   integral_at(w->d, w->Pf, w->If, w->n, &w->kf, x - w->span);
  return fmax(fabs(g), fabs(f)) / w->span - w->thr;
}

double ver_sep_window(const double *d, const double *P, const double *Pf, size_t n, double span, double frac)
{
  double *Ig = load_integral(d, P, n), *If = load_integral(d, Pf, n), peak = -INFINITY, dpk = 0.0, sep = NAN;
  if (!Ig || !If || !(span > 0.0) || n < 2) {
    free(Ig);
    free(If);
    return NAN;
  }
  /* The means are piecewise linear in the window's end x, with corners where x or x -
   * span meets a row: x runs over those corners in order (rows and rows + span merged),
   * and the first crossing under the threshold is found on the line between two. */
  sep_win w = {d, P, Pf, Ig, If, n, 0, 0, 0, 0, span, 0.0};
  double xp = NAN, op = NAN; /* the last corner whose window was past the peak, its excess */
  for (size_t i = 0, k = 0; (i < n || k < n) && isnan(sep);) {
    const int row = k >= n || (i < n && d[i] <= d[k] + span);
    const double x = row ? d[i] : d[k] + span;
    if (row) {
      if (P[i] > peak) {
        peak = P[i];
        dpk = d[i];
        xp = NAN; /* a new peak: the windows before it do not count */
      }
      i++;
    } else
      k++;
    if (x > d[n - 1] || !(peak > 0.0) || !(x - span > dpk) || x - span < d[0])
      continue;
    w.thr = frac * peak;
    const double o = win_over(&w, x);
    if (o < 0.0)
      sep = isfinite(xp) && op > 0.0 ? xp + (x - xp) * op / (op - o) : x; /* on the line between the corners */
    xp = x;
    op = o;
  }
  free(Ig);
  free(If);
  return isfinite(sep) ? sep - 0.5 * span : NAN; /* the window's centre */
}

/* A static run: where its rows' load falls to the closed form's load at the separation
 * threshold (0 at lambda = 1), on the line through the first row past the peak at or
 * under sep_load of the peak and the row before it (extrapolated where the rows stop
 * short of it: near separation the branch is straight, eq. 34 at q 1).  The rows are
 * exact states, so the detection's margin (a fraction of the peak, there for a ringing
 * explicit run) is not the separation: at a strong snapback it lies 10-17 % of delta_sep
 * away from it.  NaN if the load never falls that far. */
static double static_sep(const ver_case *c, const double *d, const double *P, size_t n)
{
  double Ps = 0.0, ds;
  if (c->have_ana && c->vs.sc.sep_threshold < 1.0)
    ana_bar_softening_point(&c->ana, 1.0 - pow(c->vs.sc.sep_threshold, c->ana.p.q), &ds, &Ps);
  int past = 0;
  for (size_t i = 0; i < n; i++) {
    past = past || P[i] >= c->peak_P;
    if (past && P[i] <= c->vs.sep_load_frac * c->peak_P) {
      return i == 0 ? d[i] : ver_sep_static(d[i - 1], P[i - 1], d[i], P[i], Ps);
    }
  }
  return NAN;
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
  {
    const int pts = sc->solver == MPM_SOLVER_STATIC;
    c->curve_l2 = ver_curve_err_bar(&c->ana, d, P, n, ver_curve_end(&c->ana, sc->sep_threshold), NULL, pts);
    c->curve_path = pts ? ver_curve_path(&c->ana, d, P, n, &c->delta5) : NAN;
  }
  ver_case_wave(c, d, P, n);
  /* separation by the load, over the run's window of 4 L / c in delta, whatever the
   * rows' spacing; a static run's rows are states along its path (no window) */
  const double cw = sqrt(sc->E / (1.0 - sc->nu * sc->nu) / sc->rho);
  c->delta_sep = sc->solver == MPM_SOLVER_STATIC
                     ? static_sep(c, d, P, n)
                     : ver_sep_window(d, P, Pf, n, 4.0 * sc->L / cw * sc->speed, c->vs.sep_load_frac);
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


long ver_foreign_backstep(const double *d, long n)
{
  for (long i = 1; i < n; i++)
    if (d[i] < d[i - 1])
      return i;
  return -1;
}

/* The area under P(delta) from the start to each row (the first row's from delta 0). */
static double *work_curve(const double *d, const double *P, long n)
{
  double *w = malloc(sizeof(double) * (size_t)n);
  if (!w)
    return NULL;
  w[0] = 0.5 * P[0] * d[0];
  for (long i = 1; i < n; i++)
    w[i] = w[i - 1] + 0.5 * (P[i] + P[i - 1]) * (d[i] - d[i - 1]);
  return w;
}

/* The largest |W[k] - w(row k)| over the rows, where w is the load curve's work at the
 * energy row's time (lt, et) or at the same row (lt or et NULL); its row in *row. */
static double work_gap(const double *w, const double *lt, long n, const double *W, const double *et, long m,
                       long *row, double *area)
{
  double gap = -1.0;
  for (long k = 0, i = 1; k < m; k++) {
    double wk;
    if (!lt || !et)
      wk = w[k];
    else {
      if (et[k] < lt[0] || et[k] > lt[n - 1])
        continue; /* before the first load row: nothing to compare with */
      while (i < n - 1 && lt[i] < et[k])
        i++;
      const double a = lt[i] > lt[i - 1] ? (et[k] - lt[i - 1]) / (lt[i] - lt[i - 1]) : 1.0;
      wk = w[i - 1] + a * (w[i] - w[i - 1]);
    }
    if (fabs(W[k] - wk) > gap) {
      gap = fabs(W[k] - wk);
      *row = k + 1;
      *area = wk;
    }
  }
  return gap;
}

int ver_foreign_work(const double *lt, const double *d, const double *P, long n, const double *et, const double *W,
                     long m, double *rel, long *row, double *area, char *why, size_t len)
{
  *rel = *area = NAN;
  *row = 0;
  if (!(lt && et) && m != n) {
    snprintf(why, len, "energy.csv has %ld rows and load.csv %ld, and not both have a t column: their rows "
             "cannot be matched", m, n);
    return 2;
  }
  if (lt && et) {
    const long bl = ver_foreign_backstep(lt, n), be = ver_foreign_backstep(et, m);
    if (bl >= 0 || be >= 0) {
      snprintf(why, len, "%s: t goes back at data row %ld", bl >= 0 ? "load.csv" : "energy.csv",
               (bl >= 0 ? bl : be) + 1);
      return 2;
    }
    /* both end at the same time, within the longer of their last intervals */
    const double span = fmax(lt[n - 1] - lt[n - 2], et[m - 1] - et[m - 2]);
    if (fabs(et[m - 1] - lt[n - 1]) > span * (1.0 + 1e-9)) {
      snprintf(why, len, "energy.csv ends at t %.9g, load.csv at t %.9g: they do not cover the same run",
               et[m - 1], lt[n - 1]);
      return 2;
    }
  }
  double *w = work_curve(d, P, n), scale = 0.0;
  if (!w) {
    snprintf(why, len, "out of memory");
    return 2;
  }
  for (long k = 0; k < m; k++)
    scale = fmax(scale, fabs(W[k]));
  for (long i = 0; i < n; i++)
    scale = fmax(scale, fabs(w[i]));
  const double gap = work_gap(w, lt, n, W, et, m, row, area);
  free(w);
  *rel = scale > 0.0 ? fmax(gap, 0.0) / scale : 0.0;
  return 0;
}
