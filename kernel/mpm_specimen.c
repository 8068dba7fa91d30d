/*
 * mpm_specimen.c - the table of specimens (mpm_specimen.h), in the order of the
 * specimen.type words (mpm.h MPM_SPEC_*).  A new specimen is one file with its row and
 * one entry here.
 */
#include "mpm_specimen.h"

static const mpm_specimen_type *const table[] = {&mpm_spec_bar, &mpm_spec_dcb, &mpm_spec_els};

const mpm_specimen_type *mpm_specimen_of(const mpm_scene *sc)
{
  const int i = sc->specimen;
  return i >= 0 && i < (int)(sizeof table / sizeof table[0]) ? table[i] : table[0];
}
