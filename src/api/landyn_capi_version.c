/* landyn_version() of include/landyn.h: one line with the library's version, git revision and
 * compiler, fixed at build time (CMake defines LANDYN_VERSION_LINE); static storage, no state. */
#include "landyn.h"

#ifndef LANDYN_VERSION_LINE
#define LANDYN_VERSION_LINE "LANDYN (version unknown)"
#endif

const char *landyn_version(void) { return LANDYN_VERSION_LINE; }
