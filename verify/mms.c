/*
 * mms.c - the manufactured solutions' orders of accuracy as cross checks of verify
 * (sweep.h ver_mms_cross), in-process: the explicit step's (the kernel's mpm_mms_error on
 * h = 8, 4, 2, dt with h, per scheme; six short runs, about a second; derivation and
 * bound: kernel/tests/test_mpm_mms.c, docs/verification.md) and the static solver's
 * (mpm_static_mms_error on h = 8, 4, 2 at 4 ppc, per shape; six linear solves, a tenth
 * of a second; kernel/tests/test_mpm_static_mms.c, docs/static.md).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "metrics.h"
#include "sweep.h"

/* Pass: the observed order of the RMS particle displacement error >= 1.8 (second order
 * expected: bilinear shapes with no particle leaving its cell, midpoint quadrature,
 * symplectic time step; 0.2 margin for a three-point fit). */
#define VER_MMS_ORDER 1.8

int ver_mms_cross(ver_cross *x, int room)
{
  static const struct {
    const char *name, *what;
    int scheme;
  } sch[] = {{"mms_order_usl", "USL", MPM_SCHEME_USL}, {"mms_order_musl", "MUSL", MPM_SCHEME_MUSL}};
  int m = 0;
  for (int t = 0; t < 2 && m < room; t++) {
    ver_cross *g = &x[m++];
    memset(g, 0, sizeof *g);
    snprintf(g->name, sizeof g->name, "%s", sch[t].name);
    snprintf(g->scene, sizeof g->scene, "mms");
    snprintf(g->over, sizeof g->over, "h");
    snprintf(g->yname, sizeof g->yname, "displacement_error");
    g->fixed = 1;
    char err[256] = "";
    for (int i = 0; i < 3; i++) {
      g->x[i] = 8.0 / (double)(1 << i);
      if (mpm_mms_error(g->x[i], sch[t].scheme, MPM_BC_CONSISTENT, &g->y[i], err, sizeof err) != MPM_OK)
        g->y[i] = NAN;
      snprintf(g->ids[i], sizeof g->ids[0], "mms-h%g-%s", g->x[i], sch[t].what);
    }
    g->n = 3;
    ver_check *k = &g->chk;
    ver_policy_order_check(g, sch[t].name, VER_MMS_ORDER, "");
    snprintf(k->note, sizeof k->note, "manufactured solution (forced axial vibration, nu 0, body force), %s, "
             "grid.bc consistent, 1 ppc: order of the RMS particle displacement error in h (dt with h); "
             "pass if p >= %g", sch[t].what, VER_MMS_ORDER);
  }
  /* the static solver: second order expected (the bilinear element with the particles'
   * composite midpoint quadrature, exact for its bilinear terms; uGIMP's weights are the
   * bilinear ones at the laid places) */
  static const struct {
    const char *name, *what;
    int shape;
  } shp[] = {{"static_mms_order_linear", "linear", MPM_SHAPE_LINEAR}, {"static_mms_order_gimp", "gimp", MPM_SHAPE_GIMP}};
  for (int t = 0; t < 2 && m < room; t++) {
    ver_cross *g = &x[m++];
    memset(g, 0, sizeof *g);
    snprintf(g->name, sizeof g->name, "%s", shp[t].name);
    snprintf(g->scene, sizeof g->scene, "static-mms");
    snprintf(g->over, sizeof g->over, "h");
    snprintf(g->yname, sizeof g->yname, "displacement_error");
    g->fixed = 4;
    char err[256] = "";
    for (int i = 0; i < 3; i++) {
      g->x[i] = 8.0 / (double)(1 << i);
      if (mpm_static_mms_error(g->x[i], shp[t].shape, 4, &g->y[i], NULL, err, sizeof err) != MPM_OK)
        g->y[i] = NAN;
      snprintf(g->ids[i], sizeof g->ids[0], "static-mms-h%g-ppc4-%s", g->x[i], shp[t].what);
    }
    g->n = 3;
    ver_check *k = &g->chk;
    ver_policy_order_check(g, shp[t].name, VER_MMS_ORDER, "");
    snprintf(k->note, sizeof k->note, "static solver's manufactured solution (2-D field, plane stress, nu 0.25, body "
             "force, exact u on the perimeter nodes), grid.shape %s, 4 ppc: order of the RMS particle displacement "
             "error in h; pass if p >= %g", shp[t].what, VER_MMS_ORDER);
  }
  return m;
}
