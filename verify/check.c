/*
 * check.c - the verdict of one check (check.h).
 */
#include <math.h>

#include "check.h"

const char *ver_verdict_name(int verdict)
{
  switch (verdict) {
  case VER_PASS: return "pass";
  case VER_KNOWN: return "known-limit";
  default: return "fail";
  }
}

void ver_check_judge(ver_check *c)
{
  if (c->rel)
    c->error = c->reference != 0.0 ? (c->measured - c->reference) / fabs(c->reference) : NAN;
  else
    c->error = c->measured - c->reference;
  if (!isfinite(c->error))
    c->verdict = VER_FAIL;
  else if (fabs(c->error) <= c->tol)
    c->verdict = VER_PASS;
  else if (c->cls == VER_CLASS_KNOWN && c->error >= c->lim_lo && c->error <= c->lim_hi)
    c->verdict = VER_KNOWN;
  else
    c->verdict = VER_FAIL;
}
