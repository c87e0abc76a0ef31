/* RReport.c -- the checks and allocations the viewer's object functions share, each reporting in the
 * name of the public call that made it. */
#include <stdlib.h>

#include "RInternal.h"

int RBothGiven(const RRender *rc, const void *object, const char *fn, const char *what)
{
    if (rc && object)
        return 1;
    R_REPORT(ME_ERR_NULL_ARGUMENT, fn, "NULL render context or %s", what);
    return 0;
}

void *RZeroedOrReport(size_t size, const char *fn, const char *what)
{
    void *p = calloc(1, size);
    if (!p)
        R_REPORT(ME_ERR_OUT_OF_MEMORY, fn, "no memory for %s", what);
    return p;
}
