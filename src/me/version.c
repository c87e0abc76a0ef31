/* version.c -- build facts (see MeVersion.h). */
#include <karma/MeVersion.h>

MeBool MeIsDoublePrecision(void) { return KARMA_DOUBLE ? METRUE : MEFALSE; }

const char *MeToolkitVersionString(void)
{
    return KARMA_DOUBLE ? "Karma " KARMA_VERSION_STRING " (double precision)"
                        : "Karma " KARMA_VERSION_STRING " (single precision)";
}
