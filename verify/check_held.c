/*
 * check_held.c - `delam check` and verify on the bar held by wedge grips (specimen.grips =
 * held, data/scenes/held.ini): its stiffness P / delta on the elastic line against the
 * 2-D finite-element stiffness of data/fe/held_bar.dat (FreeFEM), and the ledger.  The
 * grips' corners make the stress vary (singular there): the error falls with h at about
 * first order, 0.024 % at h 4 and 0.0093 % at h 2 (L 192, H 32, nu 0.25, 4 ppc).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_spec.h"
#include "datadir.h"
#include "foreign.h"

/* data/fe/held_bar.dat's K for the scene's L, H, nu (NAN, and why, when not there). */
static double fe_stiffness(const mpm_scene *sc, char *why, size_t wl)
{
  const char *sd = ver_scene_dir();
  char path[600];
  snprintf(path, sizeof path, "%.500s/../fe/held_bar.dat", sd ? sd : ".");
  FILE *f = ver_open_regular(path, NULL);
  if (!f) {
    snprintf(why, wl, "%s: cannot read", path);
    return NAN;
  }
  char line[1024], bc[16];
  double K = NAN, L, H, nu, k;
  while (fgets(line, sizeof line, f))
    if (line[0] != '#' && sscanf(line, "%lf %lf %lf %15s %lf", &L, &H, &nu, bc, &k) == 5 && !strcmp(bc, "held") &&
        fabs(L - sc->L) < 1e-9 && fabs(H - sc->H) < 1e-9 && fabs(nu - sc->nu) < 1e-12)
      K = k * sc->E / 1024.0; /* the table's E is 1024 */
  fclose(f);
  if (isnan(K))
    snprintf(why, wl, "%s has no held bar of L %g, H %g, nu %g", path, sc->L, sc->H, sc->nu);
  return K;
}

int ver_held_judge(const char *dir, const ver_scene *vs, ver_check *chk, int max, int *nchk, char *err, size_t errlen)
{
  const mpm_scene *sc = &vs->sc;
  static const char *const lnames[] = {"delta", "P_grip"};
  ver_table ld = {0}, en = {0};
  char path[1200];
  err[0] = '\0';
  snprintf(path, sizeof path, "%s/load.csv", dir);
  if (ver_table_read(path, lnames, 2, 2, &ld, err, errlen)) {
    if (!err[0])
      snprintf(err, errlen, "%s: cannot read", path);
    return 2;
  }
  snprintf(path, sizeof path, "%s/energy.csv", dir);
  if (ver_table_read(path, ver_spec_enames, VER_SPEC_NEN, 3, &en, err, errlen) || en.n != ld.n) {
    if (!err[0])
      snprintf(err, errlen, "%s: its rows are not load.csv's", path);
    ver_table_free(&ld);
    ver_table_free(&en);
    return 2;
  }
  int n = 0;
  char why[700] = "";
  const double K = fe_stiffness(sc, why, sizeof why), k = ld.col[1][0] / ld.col[0][0];
  if (n < max) {
    ver_check *c = &chk[n++];
    memset(c, 0, sizeof *c);
    c->name = "stiffness";
    c->measured = k;
    c->reference = K;
    c->error = k / K - 1.0;
    c->rel = 1;
    c->tol = 7.5e-4 * sc->h; /* 0.3 % at h 4, 0.15 % at h 2 */
    c->verdict = isnan(c->error) || fabs(c->error) <= c->tol ? VER_PASS : VER_FAIL;
    snprintf(c->note, sizeof c->note, "%s%.200s", isnan(K) ? "skipped: " : "",
             isnan(K) ? why : "P / delta on the elastic line against FreeFEM's held bar (data/fe)");
  }
  if (n < max) {
    ver_check *c = &chk[n++];
    memset(c, 0, sizeof *c);
    c->name = "ledger";
    c->measured = c->error = ver_spec_ledger(&en);
    c->tol = 1e-4;
    c->verdict = c->error <= c->tol ? VER_PASS : VER_FAIL;
    snprintf(c->note, sizeof c->note, "max |W_ext - KE - SE - W_coh - booked| over max W_ext");
  }
  ver_table_free(&ld);
  ver_table_free(&en);
  *nchk = n;
  return 0;
}
