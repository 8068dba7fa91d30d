/*
 * mpm_law.h - the paper's decohesion law on a plane, written once (Schreyer, Sulsky and
 * Zhou 2002, sec. 3; docs/model.md sec. 3), private to kernel/: the particle update
 * (mpm_decohesion.c) and both cohesive interfaces (mpm_iface.c, mpm_static_iface.c).
 * For a traction (tn, tt) on the plane, strengths snf, stf and lambda in [0, 1]:
 *
 *   traction  se = sqrt(<tn / snf>^2 + (tt / stf)^2)                 eq. 23
 *   surface   F = se - S(lambda), S = 1 - lambda^q                    eq. 23
 *   flow      m* = (s0 / se) (gn, gt), (gn, gt) = (<tn> / snf^2, tt / stf^2);
 *             Model 2 opens along n only                              eqs. 19, 24, 26
 *   update    Model 1's power s . d up = U0 se d lambda; on the surface with q = 1 the
 *             work per unit area W = U0 (lambda - lambda^2 / 2)         eqs. 19, 25
 *   tangent   d se / d t = (gn, gt) / se,  dS / d lambda = -q lambda^(q-1)
 * <tn>: compression neither starts nor drives decohesion (docs/model.md sec. 6).
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

#endif
