/*
 * build_info.c - the strings of build_info.h, from two generated headers:
 * delam_vcs.h (meson's vcs_tag, remade at every build) and delam_config.h.
 */
#include "build_info.h"
#include "delam_config.h"
#include "delam_vcs.h"

const char *ver_build_version(void)
{
  /* git describe of the source tree, or empty when it is not a checkout */
  return DELAM_VCS[0] ? DELAM_RELEASE "+" DELAM_VCS : DELAM_RELEASE;
}

const char *ver_build_compiler(void)
{
  return DELAM_COMPILER;
}

const char *ver_build_flags(void)
{
  return DELAM_FLAGS;
}
