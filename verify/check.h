/*
 * check.h - one check of a run (prefix ver_check_): a measured number against its
 * reference, a tolerance, and a class decided up front from the physics of the scene.
 *
 * Verdicts.  pass-class checks pass within their tolerance or fail; known-limit checks
 * are the deviations the paper itself reports (inclined bands dissipating more than U0
 * per area, the softer softening slope, load reversal an explicit method cannot follow).
 * A known-limit check still passes inside its tolerance, is `known-limit` inside its
 * outer bounds (the direction and size the physics allows), and fails outside them.
 */
#ifndef DELAM_VER_CHECK_H
#define DELAM_VER_CHECK_H

enum { VER_CLASS_PASS = 0, VER_CLASS_KNOWN = 1 };
enum { VER_PASS = 0, VER_FAIL = 1, VER_KNOWN = 2 };

typedef struct {
  const char *name;      /* stable check id: "peak_P", "D_final", ...                   */
  double measured;       /* the run's number                                             */
  double reference;      /* the analytic (or expected) number                            */
  double error;          /* relative (measured - reference) / |reference| if rel, else measured - reference */
  int rel;               /* 1: error is relative                                         */
  double tol;            /* pass when |error| <= tol                                     */
  double lim_lo, lim_hi; /* known-limit class: error in [lim_lo, lim_hi] is known-limit  */
  int cls;               /* VER_CLASS_*                                                  */
  int verdict;           /* VER_PASS, VER_FAIL, VER_KNOWN                                */
  char note[256];        /* what is compared and why this class                          */
} ver_check;

/* Fills error from measured/reference and sets the verdict; a non-finite error fails. */
void ver_check_judge(ver_check *c);
const char *ver_verdict_name(int verdict);

#endif
