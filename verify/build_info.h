/*
 * build_info.h - what built this program: the version (`git describe` of the source
 * tree at build time, or the release version when the tree is not a git checkout),
 * the compiler, and the options that change the results' bits.
 */
#ifndef DELAM_BUILD_INFO_H
#define DELAM_BUILD_INFO_H

const char *ver_build_version(void);   /* e.g. "0.1.0-00aa46f-dirty" or "0.1.0"         */
const char *ver_build_compiler(void);  /* e.g. "gcc 12.2.0"                             */
const char *ver_build_flags(void);     /* build type, -march=native or not, c_args      */

#endif
