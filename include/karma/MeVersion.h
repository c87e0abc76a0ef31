/* MeVersion.h -- what this copy of Karma is. */
#ifndef ME_VERSION_H
#define ME_VERSION_H

#include "MePrecision.h"

/* Karma 1.2's version macros describe the release whose API this library offers (1.2.1, build 631);
 * KARMA_VERSION_STRING (karma/config.h) and MeToolkitVersionString() give this library's own. */
#define ME_PRODUCT_NAME "MathEngine Karma"
#define ME_PRODUCTVERSION_MAJOR 1
#define ME_PRODUCTVERSION_MINOR 2
#define ME_PRODUCTVERSION_REV 1
#define ME_PRODUCTVERSION_QUALIFIER
#define ME_PRODUCTVERSION_BUILDNUMBER 631

/** Copyright lines shown by Karma's samples (this library's; its code is not MathEngine's). */
#define ME_COPYRIGHT_LINE1 "Karma: an open reimplementation of the MathEngine Karma 1.2 API."
#define ME_COPYRIGHT_LINE2 ""
#define ME_COPYRIGHT_LINE3 ""

/* Building version strings from the numbers above. */
#define STRINGIZE(value) #value
#define CONSTRUCT_VER2(maj, min) STRINGIZE(maj.min)
#define CONSTRUCT_VER2QUALIFIED(maj, min, qual) STRINGIZE(maj.min qual)
#define CONSTRUCT_VER3(maj, min, rev) STRINGIZE(maj.min.rev)
#define CONSTRUCT_VER3QUALIFIED(maj, min, rev, qual) STRINGIZE(maj.min.rev qual)

/** "1.2.1 " and "1.2.1 (build 631)". */
#define ME_VERSION_STRING                                                                            \
    CONSTRUCT_VER3QUALIFIED(ME_PRODUCTVERSION_MAJOR, ME_PRODUCTVERSION_MINOR, ME_PRODUCTVERSION_REV,   \
                            ME_PRODUCTVERSION_QUALIFIER)
#define ME_BUILD_VERSION_STRING                                                                      \
    CONSTRUCT_VER3QUALIFIED(ME_PRODUCTVERSION_MAJOR, ME_PRODUCTVERSION_MINOR, ME_PRODUCTVERSION_REV,   \
                            ME_PRODUCTVERSION_QUALIFIER(build ME_PRODUCTVERSION_BUILDNUMBER))

ME_EXTERN_C_BEGIN

/** METRUE when the library was built with MeReal = double. */
ME_API MeBool MeIsDoublePrecision(void);
/** "Karma <version> (single|double precision)". */
ME_API const char *MeToolkitVersionString(void);

ME_EXTERN_C_END

#endif /* ME_VERSION_H */
