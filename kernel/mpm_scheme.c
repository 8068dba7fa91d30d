/*
 * mpm_scheme.c - the time schemes, one row each (time.scheme; mpm_phase.h).  A scheme
 * is a file with its const mpm_scheme_type and a row here: the step is not edited.
 */
#include <string.h>

#include "mpm_kernel.h"
#include "mpm_phase.h"

extern const mpm_scheme_type mpm_scheme_usl, mpm_scheme_musl, mpm_scheme_usf, mpm_scheme_usavg;

const mpm_scheme_type *const mpm_schemes[] = {
  [MPM_SCHEME_USL] = &mpm_scheme_usl,
  [MPM_SCHEME_MUSL] = &mpm_scheme_musl,
  [MPM_SCHEME_USF] = &mpm_scheme_usf,
  [MPM_SCHEME_USAVG] = &mpm_scheme_usavg,
};
const int mpm_nschemes = (int)(sizeof mpm_schemes / sizeof mpm_schemes[0]);

int mpm_scheme_find(const char *name)
{
  for (int i = 0; i < mpm_nschemes; i++)
    if (!strcmp(mpm_schemes[i]->name, name))
      return i;
  return -1;
}

const char *mpm_scheme_name(int i)
{
  return mpm_schemes[i >= 0 && i < mpm_nschemes ? i : MPM_SCHEME_USL]->name;
}
