/*
 * ana_spec.c - the specimens' closed forms (docs/specimens-reference.md): the interface
 * law's pure modes and the LEFM beam references of the DCB and the ELS.
 *
 * The law (docs/model.md sec. 3, Model 1): in pure opening m* = (s0 / snf) n (eq. 24), so
 * the opening at separation is U0 / snf and the traction falls as snf (1 - (w snf / U0)^q);
 * pure shear likewise with stf.  The work to separation, Gc, is q U0 / (q + 1) (eq. 25's
 * UF) in any mode mix, as s . m* = s0 se.
 * Beam references, unit width, arm thickness t, EI = E t^3 / 12 per arm:
 *   DCB simple  C = 8 a^3 / (E t^3); corrected a -> a + chi t (Williams 1989); with
 *               shear + 2 a / (k G t); Kanninen (1973) an arm on a Winkler foundation
 *               2 E / t (Hetenyi 1946), and with a Timoshenko arm
 *   ELS simple  C = (3 a^3 + L^3) / (2 E t^3), G_II = 9 P^2 a^2 / (4 E t^3); corrected
 *               a -> a + 0.42 chi t (ISO 15114); shear + L / (2 k G t)
 */
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "ana_spec.h"

#define KAPPA (5.0 / 6.0) /* Timoshenko's shear factor of a rectangle */

static int fail(char *err, int errlen, const char *msg, double v)
{
  if (err && errlen > 0)
    snprintf(err, (size_t)errlen, msg, v);
  return ANA_EINVAL;
}

void ana_spec_default(int kind, ana_spec_params *p)
{
  const int els = kind == ANA_SPEC_ELS;
  *p = (ana_spec_params){.kind = els ? ANA_SPEC_ELS : ANA_SPEC_DCB, .L = 192.0, .H = 32.0, .a0 = 64.0,
                         .E = 1024.0, .nu = 0.25, .snf = els ? 10.0 : 1.0, .stf = els ? 1.0 : 10.0,
                         .U0 = 0.375, .s0 = 1.0, .q = 1.0};
}

int ana_spec_init(const ana_spec_params *p, ana_spec *s, char *err, int errlen)
{
  if (p->kind != ANA_SPEC_DCB && p->kind != ANA_SPEC_ELS)
    return fail(err, errlen, "specimen kind %g is neither DCB (0) nor ELS (1)", p->kind);
  const struct {
    const char *name;
    double v;
  } pos[] = {{"L", p->L}, {"H", p->H}, {"E", p->E}, {"snf", p->snf}, {"stf", p->stf},
             {"U0", p->U0}, {"s0", p->s0}, {"q", p->q}};
  for (size_t i = 0; i < sizeof pos / sizeof pos[0]; i++)
    if (!(isfinite(pos[i].v) && pos[i].v > 0.0)) {
      if (err && errlen > 0)
        snprintf(err, (size_t)errlen, "%s = %g: must be finite and > 0", pos[i].name, pos[i].v);
      return ANA_EINVAL;
    }
  if (!(isfinite(p->nu) && p->nu > -1.0 && p->nu <= 0.5))
    return fail(err, errlen, "nu = %g: must be in (-1, 0.5]", p->nu);
  if (!(isfinite(p->a0) && p->a0 > 0.0 && p->a0 < p->L))
    return fail(err, errlen, "a0 = %g: must be in (0, L)", p->a0);
  *s = (ana_spec){.p = *p};
  const double t = 0.5 * p->H, G = p->E / (2.0 * (1.0 + p->nu)), g = 1.18 * p->E / G;
  s->t = t;
  s->EI = p->E * t * t * t / 12.0;
  s->kGA = KAPPA * G * t;
  s->kf = 2.0 * p->E / t;
  s->beta = pow(s->kf / (4.0 * s->EI), 0.25);
  /* Williams 1989, isotropic (E11 = E22 = E, G13 = G): chi = sqrt(E / (11 G) (3 - 2
   * (g / (1 + g))^2)), g = 1.18 E / G; the ELS's 0.42 chi (Hashemi, Kinloch, Williams 1990) */
  s->chi = sqrt(p->E / (11.0 * G) * (3.0 - 2.0 * (g / (1.0 + g)) * (g / (1.0 + g))));
  s->chi_II = 0.42 * s->chi;
  s->wc_I = p->U0 / p->snf;
  s->wc_II = p->U0 / p->stf;
  s->Gc = p->q * p->U0 / (p->q + 1.0);
  const double str = p->kind == ANA_SPEC_DCB ? p->snf : p->stf;
  s->lcz = pow(p->E * s->Gc / (str * str), 0.25) * pow(t, 0.75);
  return ANA_OK;
}

/* Hetenyi's end flexibilities of a free-free beam on a Winkler foundation, length l, as
 * multiples of their semi-infinite values: f1 (force to deflection), f2 (force to rotation
 * and moment to deflection), f3 (moment to rotation), and their derivatives in z = beta l.
 * Past z = 20 they differ from 1 by less than e^-40. */
static void hetenyi(double z, double f[3], double df[3])
{
  if (z > 20.0) {
    f[0] = f[1] = f[2] = 1.0;
    df[0] = df[1] = df[2] = 0.0;
    return;
  }
  const double S = sinh(z), Ch = cosh(z), s = sin(z), c = cos(z);
  const double D = S * S - s * s, dD = 2.0 * (S * Ch - s * c);
  const double n[3] = {S * Ch - s * c, S * S + s * s, S * Ch + s * c};
  const double dn[3] = {Ch * Ch + S * S - c * c + s * s, 2.0 * (S * Ch + s * c), Ch * Ch + S * S + c * c - s * s};
  for (int i = 0; i < 3; i++) {
    f[i] = n[i] / D;
    df[i] = (dn[i] * D - n[i] * dD) / (D * D);
  }
}

/* Kanninen's DCB: per arm delta / 2 = P (a^3 / (3 EI) + fww + 2 a fwm + a^2 fmm), with
 * fww = 2 beta f1 / k, fwm = 2 beta^2 f2 / k, fmm = 4 beta^3 f3 / k at l = L - a. */
static void kanninen(const ana_spec *s, double a, double *C, double *dC)
{
  const double b = s->beta, k = s->kf, EI = s->EI;
  double f[3], df[3];
  hetenyi(b * (s->p.L - a), f, df);
  const double c1 = 2.0 * b / k, c2 = 2.0 * b * b / k, c3 = 4.0 * b * b * b / k;
  *C = 2.0 * (a * a * a / (3.0 * EI) + c1 * f[0] + 2.0 * a * c2 * f[1] + a * a * c3 * f[2]);
  /* d/da through a and through l = L - a (dz/da = -beta) */
  *dC = 2.0 * (a * a / EI + 2.0 * c2 * f[1] + 2.0 * a * c3 * f[2] -
               b * (c1 * df[0] + 2.0 * a * c2 * df[1] + a * a * c3 * df[2]));
}

/* Kanninen's DCB with a Timoshenko arm: per arm delta / 2 = w(0) - a theta(0) +
 * P (a^3 / (3 EI) + a / kGA), with w(0) and theta(0) at the crack tip from the decaying
 * solution theta = A e^(l1 x) + B e^(l2 x) on the ligament (x into it), w = -EI theta''' / kf,
 * M = EI theta', Q = -EI theta''. */
static int kanninen_shear(const ana_spec *s, double a, double *C, double *dC)
{
  const double EI = s->EI, k = s->kf, sc = k / s->kGA, c = k / EI;
  const double complex disc = csqrt((double complex)(sc * sc - 4.0 * c));
  const double complex l1 = -csqrt(0.5 * (sc + disc)), l2 = -csqrt(0.5 * (sc - disc));
  if (cabs(l1 - l2) < 1e-12 * cabs(l1))
    return ANA_EINVAL; /* a double root: the two-exponential form does not hold */
  /* unit tip loads: (M, Q) = (1, 0) and (0, -1); A, B from EI (l1 A + l2 B) = M and
   * -EI (l1^2 A + l2^2 B) = Q */
  double w0[2], th0[2];
  for (int m = 0; m < 2; m++) {
    const double M = m == 0 ? 1.0 : 0.0, Q = m == 0 ? 0.0 : -1.0;
    const double complex det = EI * EI * (-l1 * l2 * l2 + l2 * l1 * l1);
    const double complex A = (M * (-EI * l2 * l2) - EI * l2 * Q) / det;
    const double complex B = (EI * l1 * Q + EI * l1 * l1 * M) / det;
    w0[m] = creal(-EI * (l1 * l1 * l1 * A + l2 * l2 * l2 * B) / k);
    th0[m] = creal(A + B);
  }
  /* per unit P: w(0) = a w0[0] + w0[1], theta(0) = a th0[0] + th0[1] */
  *C = 2.0 * (a * w0[0] + w0[1] - a * (a * th0[0] + th0[1]) + a * a * a / (3.0 * EI) + a / s->kGA);
  *dC = 2.0 * (w0[0] - 2.0 * a * th0[0] - th0[1] + a * a / EI + 1.0 / s->kGA);
  return ANA_OK;
}

int ana_spec_compliance(const ana_spec *s, int theory, double a, double *C, double *dCda)
{
  const ana_spec_params *p = &s->p;
  if (!(isfinite(a) && a > 0.0 && a < p->L) || theory < 0 || theory >= ANA_BEAM_COUNT)
    return ANA_EINVAL;
  const double Et3 = p->E * s->t * s->t * s->t;
  double c = 0.0, dc = 0.0;
  if (p->kind == ANA_SPEC_DCB) {
    const double ae = theory == ANA_BEAM_CORRECTED ? a + s->chi * s->t : a;
    c = 8.0 * ae * ae * ae / Et3;
    dc = 24.0 * ae * ae / Et3;
    if (theory == ANA_BEAM_SHEAR) {
      c += 2.0 * a / s->kGA;
      dc += 2.0 / s->kGA;
    } else if (theory == ANA_BEAM_KANNINEN)
      kanninen(s, a, &c, &dc);
    else if (theory == ANA_BEAM_KANNINEN_SHEAR && kanninen_shear(s, a, &c, &dc) != ANA_OK)
      return ANA_EINVAL;
  } else {
    if (theory == ANA_BEAM_KANNINEN || theory == ANA_BEAM_KANNINEN_SHEAR)
      return ANA_EINVAL;
    const double ae = theory == ANA_BEAM_CORRECTED ? a + s->chi_II * s->t : a, L = p->L;
    c = (3.0 * ae * ae * ae + L * L * L) / (2.0 * Et3);
    dc = 9.0 * ae * ae / (2.0 * Et3);
    if (theory == ANA_BEAM_SHEAR)
      c += L / (2.0 * s->kGA);
  }
  *C = c;
  if (dCda)
    *dCda = dc;
  return ANA_OK;
}

int ana_spec_G(const ana_spec *s, int theory, double a, double P, double *G)
{
  double C, dC;
  const int rc = ana_spec_compliance(s, theory, a, &C, &dC);
  if (rc != ANA_OK || !isfinite(P))
    return ANA_EINVAL;
  *G = 0.5 * P * P * dC;
  return ANA_OK;
}

int ana_spec_lefm_branch(const ana_spec *s, int theory, double a, double *P, double *delta)
{
  double C, dC;
  const int rc = ana_spec_compliance(s, theory, a, &C, &dC);
  if (rc != ANA_OK || !(dC > 0.0))
    return ANA_EINVAL;
  *P = sqrt(2.0 * s->Gc / dC);
  *delta = C * *P;
  return ANA_OK;
}

/* delta = C sqrt(2 Gc / C') with C = (3 ae^3 + Leff^3) / (2 E t^3), C' ~ ae^2: delta ~
 * (3 ae^3 + Leff^3) / ae, stationary at ae^3 = Leff^3 / 6. */
int ana_els_snapback_end(const ana_spec *s, int theory, double *a_turn)
{
  if (s->p.kind != ANA_SPEC_ELS || theory < 0 || theory >= ANA_BEAM_COUNT || theory == ANA_BEAM_KANNINEN ||
      theory == ANA_BEAM_KANNINEN_SHEAR)
    return ANA_EINVAL;
  const double L = s->p.L, t = s->t;
  double L3 = L * L * L;
  if (theory == ANA_BEAM_SHEAR) /* the shear term L E t^3 / kGA joins L^3 */
    L3 += L * s->p.E * t * t * t / s->kGA;
  const double off = theory == ANA_BEAM_CORRECTED ? s->chi_II * t : 0.0;
  *a_turn = cbrt(L3 / 6.0) - off;
  return ANA_OK;
}
