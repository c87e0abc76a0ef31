/* MeVersion.h -- what this copy of Karma is. */
#ifndef ME_VERSION_H
#define ME_VERSION_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** METRUE when the library was built with MeReal = double. */
ME_API MeBool MeIsDoublePrecision(void);
/** "Karma <version> (single|double precision)". */
ME_API const char *MeToolkitVersionString(void);

ME_EXTERN_C_END

#endif /* ME_VERSION_H */
