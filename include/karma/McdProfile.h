/* McdProfile.h -- Karma 1.2's collision profiling macros, onto Me's global profiler (MeProfile.h).
 *
 * McdProfileStart(name) starts the global profiler's section `name` (not auto-stopping) and
 * McdProfileEnd(name) ends it; read the time with MeProfileGetSectionTime(name). They are on unless
 * PROFILE_MCD is defined as 0 before this header (1.2 had them off unless PROFILE_MCD was 1), or
 * _ME_NOPROFILING compiles the global profiler out. */
#ifndef MCD_PROFILE_H
#define MCD_PROFILE_H

#include "MeProfile.h"

#ifndef PROFILE_MCD
#  define PROFILE_MCD 1
#endif

#if PROFILE_MCD
#  define McdProfileStart(s) MeProfileStartSection((s), 0)
#  define McdProfileEnd(s) MeProfileEndSection(s)
#else
#  define McdProfileStart(s) ((void)0)
#  define McdProfileEnd(s) ((void)0)
#endif

#endif /* MCD_PROFILE_H */
