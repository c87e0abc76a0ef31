/* MeAssert.h -- MEASSERT, Karma's assertion: compiled in only when the program defines _MECHECK, as
 * Karma's checking builds did; it reports a failed assertion as a fatal message (MeFatalError, so a
 * program's handler sees it) when MEASSERT_IS_FATAL_ERROR is defined too, else through assert(). */
#ifndef ME_ASSERT_H
#define ME_ASSERT_H

#include "MePrecision.h"

#ifndef _MECHECK
#  define MEASSERT(P) ((void)0)
#elif defined(MEASSERT_IS_FATAL_ERROR)
#  include "MeMessage.h"
#  define MEASSERT(P)                                                                                \
      do {                                                                                           \
          if (!(P))                                                                                  \
              MeFatalError(1, "assertion failed: %s", #P);                                           \
      } while (0)
#else
#  include <assert.h>
#  define MEASSERT(P) assert(P)
#endif

/** Assert that pointer P is aligned to A bytes (A a power of two). */
#define MEASSERTALIGNED(P, A) MEASSERT((((MeUintPtr)(P)) & ((MeUintPtr)(A) - 1)) == 0)

#endif /* ME_ASSERT_H */
