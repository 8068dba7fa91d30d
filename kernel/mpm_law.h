/*
 * mpm_law.h - the paper's decohesion law on a plane, written once (Schreyer, Sulsky and
 * Zhou 2002, sec. 3; docs/model.md sec. 3), private to kernel/: the particle update
 * (mpm_decohesion.c) and both cohesive interfaces (mpm_iface.c, mpm_static_iface.c).
 * For a traction (tn, tt) on the plane, strengths snf, stf and lambda in [0, 1]:
 *   traction  se = sqrt(<tn / snf>^2 + (tt / stf)^2), <tn>: compression does not count  eq. 23
 *   surface   F = se - S(lambda), S = 1 - lambda^q                                      eq. 23
 *   flow      m* = (s0 / se) (gn, gt), (gn, gt) = (<tn> / snf^2, tt / stf^2);
 *             Model 2 opens along n only                                          eqs. 19, 24, 26
 *   update    Model 1's s . d up = U0 se d lambda, with q = 1 W = U0 (lambda - lambda^2 / 2)
 *             (eqs. 19, 25); the static interface's return at the step's end (eqs. 19, 23-24)
 *   separate  the traction released into the opening                             eqs. 56-58
 *   tangent   d se / d t = (gn, gt) / se, dS / d lambda = -q lambda^(q-1), and each step's
 */
#ifndef DELAM_MPM_LAW_H
#define DELAM_MPM_LAW_H

#include <math.h>

/* lambda^q, exact and cheap for the paper's q = 1. */
static inline double mpm_law_powq(double lam, double q)
{
  return q == 1.0 ? lam : pow(lam, q);
}

/* d(lambda^q)/d lambda = q lambda^(q-1): 1 without a pow for q = 1; at lambda = 0 the
 * limit (infinite for q < 1, 0 for q > 1). */
static inline double mpm_law_dpowq(double lam, double q)
{
  if (q == 1.0)
    return 1.0;
  if (lam > 0.0)
    return q * pow(lam, q - 1.0);
  return q < 1.0 ? INFINITY : 0.0;
}

/* The strength left, S = 1 - lambda^q (eq. 23). */
static inline double mpm_law_S(double lam, double q)
{
  return 1.0 - mpm_law_powq(lam, q);
}

/* The effective traction se of eq. 23 of a traction normalised by the strengths,
 * (un, ut) = (tn / snf, tt / stf), with the Macaulay bracket on un.  The callers form the
 * quotients (the particle update as products with 1 / snf), and may bracket un first. */
static inline double mpm_law_se(double un, double ut)
{
  const double a = fmax(un, 0.0);
  return sqrt(a * a + ut * ut);
}

/* The flow's components per unit s0 / se (eqs. 24, 26): gn = <tn> / snf^2, gt = tt / stf^2
 * (the gradient of se^2 / 2), from the inverse squared strengths; Model 2's flow takes
 * only gn. */
static inline void mpm_law_flow(double tn, double tt, double isnf2, double istf2, double *gn, double *gt)
{
  *gn = tn > 0.0 ? tn * isnf2 : 0.0;
  *gt = tt * istf2;
}

/* Model 1 with q = 1 on the surface: the work dw per unit area taken from lambda (the
 * power U0 se d lambda with se = 1 - lambda, integrated in closed form, W = U0 (lambda -
 * lambda^2 / 2)); the work never lowers lambda. */
static inline double mpm_law_lambda_after(double lam, double dw, double U0)
{
  const double r = 1.0 - lam;
  return dw > 0.0 ? 1.0 - sqrt(fmax(0.0, r * r - 2.0 * dw / U0)) : lam;
}

/* Separation (eqs. 56-58), and every later step once separated: the trial traction (tn, tt)
 * released by the decohesion strain de_nn = tn / E1, de_nt = tt / 2G (eq. 57), the opening
 * (dun, dut) = Le (de_nn, 2 de_nt) (eq. 58).  In normal compression the opening closes
 * first, no further than shut (upn + dun >= 0), and the compression is carried: s_nn =
 * tn - E1 de_nn, s_nt = 0.  1 in contact. */
static inline int mpm_law_separate(double tn, double tt, double E1, double G, double Le, double upn, double *de_nn,
                                   double *dun, double *dut)
{
  double e = tn / E1;                        /* eq. 57 */
  const int contact = tn < 0.0 && Le * e < -upn;
  if (contact)
    e = -upn / Le;                           /* contact: close no further than shut */
  const double de_nt = tt / (2.0 * G);       /* eq. 57 */
  *de_nn = e;
  *dun = Le * e;                             /* eq. 58 */
  *dut = 2.0 * Le * de_nt;                   /* eq. 58, tensor shear: 2 Le de_nt */
  return contact;
}

/* The separation's tangent: lambda = lambda_in + |d ud| / ubar0 (eq. 58) differentiated in
 * the trial (tn, tt), d ud = Le (tn / E1, tt / G); in contact d ud_n is -upn, fixed. */
static inline void mpm_law_separate_dlam(double dun, double dut, int contact, double E1, double G, double Le,
                                         double ubar0, double *ln, double *lt)
{
  const double du = sqrt(dun * dun + dut * dut);
  *ln = *lt = 0.0;
  if (du > 0.0) {
    *ln = contact ? 0.0 : dun * Le / (E1 * du * ubar0);
    *lt = dut * Le / (G * du * ubar0);
  }
}

/* Once separated, lambda grows with the opening: d lambda = |d ud| / ubar0 (eq. 58). */
static inline double mpm_law_open_dlam(double dun, double dut, double ubar0)
{
  return sqrt(dun * dun + dut * dut) / ubar0;
}

/* The closest-point return of Model 1 with an isotropic stiffness k on the plane (the
 * static interface's segments): the flow taken at the step's end, t = t_tr - k ubar0 dl
 * m*(t), m* = (s0 / se)(<tn> / snf^2, tt / stf^2) (eqs. 19, 24), gives each component its
 * trial over 1 + c dl / S, c = k ubar0 s0 / s_f^2 (cn = 0 in compression), S = 1 -
 * (lambda + dl)^q; eq. 23 at the end is psi(dl) = se / S - 1 = 0, psi decreasing in dl. */
static inline double mpm_law_return_psi(double lam, double q, double an, double at, double snf, double stf,
                                        double cn, double ct, double dl)
{
  const double S = mpm_law_S(lam + dl, q);
  return mpm_law_se(an / (snf * (S + cn * dl)), at / (stf * (S + ct * dl))) - 1.0;
}

/* The return's root dl (bisection on psi), the traction (sn, st) at the end, and the
 * tangent: dsn, dst = d (sn, st) / d (an, at), dl_dt = d dl / d (an, at), by implicit
 * differentiation of psi = 0.  The trial (an, at) lies past the surface; K = k ubar0 s0.
 * 0 where the step opens past separation (no root in (0, 1 - lambda]). */
static inline int mpm_law_return(double lam, double q, double an, double at, double snf, double stf, double K,
                                 double *dl_out, double *sn, double *st, double dsn[2], double dst[2],
                                 double dl_dt[2])
{
  const double cn = an > 0.0 ? K / (snf * snf) : 0.0, ct = K / (stf * stf); /* eq. 24 */
  const double hi0 = 1.0 - lam;
  if (!(hi0 > 0.0) || mpm_law_return_psi(lam, q, an, at, snf, stf, cn, ct, hi0) >= 0.0)
    return 0;
  double lo = 0.0, hi = hi0;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi0; it++) {
    const double mid = 0.5 * (lo + hi);
    if (mpm_law_return_psi(lam, q, an, at, snf, stf, cn, ct, mid) > 0.0)
      lo = mid;
    else
      hi = mid;
  }
  const double dl = 0.5 * (lo + hi), S = mpm_law_S(lam + dl, q), Sp = -mpm_law_dpowq(lam + dl, q);
  const double Dn = S + cn * dl, Dt = S + ct * dl;
  *dl_out = dl;
  *sn = an * S / Dn;
  *st = at * S / Dt;
  const double un = an > 0.0 ? an / (snf * Dn) : 0.0, ut = at / (stf * Dt);
  const double pn = an > 0.0 ? un / (snf * Dn) : 0.0, pt = ut / (stf * Dt);
  const double pd = -un * un * (Sp + cn) / Dn - ut * ut * (Sp + ct) / Dt;
  dl_dt[0] = -pn / pd;
  dl_dt[1] = -pt / pd;
  const double gn = S / Dn, gnp = cn * (Sp * dl - S) / (Dn * Dn);
  const double gt = S / Dt, gtp = ct * (Sp * dl - S) / (Dt * Dt);
  dsn[0] = an > 0.0 ? gn + an * gnp * dl_dt[0] : 1.0;
  dsn[1] = an > 0.0 ? an * gnp * dl_dt[1] : 0.0;
  dst[0] = at * gtp * dl_dt[0];
  dst[1] = gt + at * gtp * dl_dt[1];
  return 1;
}

#endif
