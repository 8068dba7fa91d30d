/*
 * check_spec_cross.c - verify's cross-case checks of the specimens (check_spec.h): over
 * three grids in ratio 2 at one ppc, the order of the compliance's (the held bar's
 * stiffness's) error against data/fe, and the DCB's peak's Richardson limit against the
 * cohesive beam.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check_spec.h"

/* The measured number of check name in case c (NAN if it is not there or skipped). */
static double case_measure(const ver_case *c, const char *name)
{
  for (int j = 0; j < c->nchk; j++)
    if (!strcmp(c->chk[j].name, name) && !isnan(c->chk[j].error))
      return c->chk[j].measured;
  return NAN;
}

int ver_spec_cross(const ver_case *cs, int n, ver_cross *x, int room)
{
  int m = 0;
  for (int i = 0; i < n && m + 2 <= room; i++) {
    const ver_case *a = &cs[i], *b = NULL, *c = NULL;
    const int held = a->vs.sc.grips == MPM_GRIPS_HELD;
    const char *cn = held ? "stiffness" : "compliance";
    if ((a->vs.sc.specimen == MPM_SPEC_BAR && !held) || !a->complete)
      continue;
    for (int j = 0; j < n; j++) { /* 2 h and 4 h of the same scene, variant and ppc */
      const ver_case *o = &cs[j];
      if (o->vs.sc.specimen != a->vs.sc.specimen || o->vs.sc.grips != a->vs.sc.grips || !o->complete ||
          strcmp(o->scene, a->scene) || o->ppc != a->ppc ||
          strcmp(o->var.suffix, a->var.suffix))
        continue;
      b = fabs(o->h - 2.0 * a->h) < 1e-9 * a->h ? o : b;
      c = fabs(o->h - 4.0 * a->h) < 1e-9 * a->h ? o : c;
    }
    if (!b || !c)
      continue;
    const ver_case *g3[3] = {a, b, c};
    /* the compliance's order of convergence to the FE value (at least about 1: the tip's
     * field; one-sided, as 1 ppc's error, softer, is second order and leads at h 4-1) */
    ver_cross *q = &x[m++];
    memset(q, 0, sizeof *q);
    snprintf(q->name, sizeof q->name, "%s_order", cn);
    snprintf(q->scene, sizeof q->scene, "%s%s%s", a->scene, a->var.suffix[0] ? "-" : "", a->var.suffix);
    snprintf(q->over, sizeof q->over, "h");
    q->fixed = a->ppc;
    double e[3];
    for (int k = 0; k < 3; k++) {
      q->x[k] = g3[k]->h;
      const double C = case_measure(g3[k], cn);
      double Cfe = NAN;
      for (int j = 0; j < g3[k]->nchk; j++)
        if (!strcmp(g3[k]->chk[j].name, cn))
          Cfe = g3[k]->chk[j].reference;
      q->y[k] = e[k] = fabs(C / Cfe - 1.0);
      snprintf(q->ids[k], sizeof q->ids[0], "%s", g3[k]->id);
    }
    q->n = 3;
    ver_check *k = &q->chk;
    k->name = held ? "stiffness_order" : "compliance_order";
    k->measured = log2(e[1] / e[0]);
    k->reference = 1.0;
    k->error = k->measured - 1.0;
    k->tol = 0.5;
    k->verdict = k->error >= -k->tol ? VER_PASS : VER_FAIL; /* at least: 1 ppc's quadrature error goes as h^2 */
    snprintf(k->note, sizeof k->note, "log2 of the %s's error against data/fe at h %g over h %g (%.3g, %.3g; at 4 h "
             "%.3g): pass from 0.5, the %s field's first order (1 ppc's softer cells: h^2)", cn, b->h, a->h, e[1],
             e[0], e[2], held ? "corners'" : "tip's");
    if (a->vs.sc.specimen != MPM_SPEC_DCB)
      continue;
    /* the peak's Richardson limit (first order, the nodes' release) against the beam */
    const double Pa = case_measure(a, "peak_P"), Pb = case_measure(b, "peak_P");
    double ref = NAN;
    for (int j = 0; j < a->nchk; j++)
      if (!strcmp(a->chk[j].name, "peak_P"))
        ref = a->chk[j].reference;
    ver_cross *r = &x[m++];
    *r = *q;
    snprintf(r->name, sizeof r->name, "peak_limit");
    for (int t = 0; t < 3; t++)
      r->y[t] = case_measure(g3[t], "peak_P");
    k = &r->chk;
    memset(k, 0, sizeof *k);
    k->name = "peak_limit";
    k->measured = 2.0 * Pa - Pb;
    k->reference = ref;
    k->error = k->measured / ref - 1.0;
    k->rel = 1;
    k->tol = 0.03;
    k->verdict = fabs(k->error) <= k->tol ? VER_PASS : VER_FAIL;
    snprintf(k->note, sizeof k->note, "Richardson limit 2 P(h %g) - P(h %g) of the peak load against the cohesive "
             "Timoshenko beam (the 2-D continuum against the beam: a modelling difference)", a->h, b->h);
  }
  return m;
}

void ver_spec_policy(ver_case *c)
{
  if (c->ppc != 1 || c->vs.sc.specimen == MPM_SPEC_BAR)
    return;
  for (int j = 0; j < c->nchk; j++) {
    ver_check *k = &c->chk[j];
    const int stall = !strcmp(k->name, "run") && strstr(k->note, "no equilibrium");
    if (!(stall || !strcmp(k->name, "branch")) || k->verdict != VER_FAIL)
      continue;
    k->cls = VER_CLASS_KNOWN;
    k->lim_lo = stall ? 1.0 : 0.0;
    k->lim_hi = stall ? 1.0 : 0.05;
    if (k->error >= k->lim_lo && k->error <= k->lim_hi)
      k->verdict = VER_KNOWN;
    const size_t u = strlen(k->note);
    snprintf(k->note + u, sizeof k->note - u, "%s",
             stall ? "; 1 ppc: the static path stalls before the peak (known-limit)"
                   : "; 1 ppc: the arms' one point a cell, known-limit to 0.05");
  }
}
