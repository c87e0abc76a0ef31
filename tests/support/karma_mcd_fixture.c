/* karma_mcd_fixture.c -- the shared Mcd framework of a group of collision tests. */
#include "karma_mcd_fixture.h"

#include <stddef.h>

static McdFrameworkID *opened; /* the file's handle, cleared at close */

int karma_mcd_open(McdFrameworkID *fw, int models, MeReal lengthScale)
{
    *fw = McdInit(0, models, 0, lengthScale);
    opened = fw;
    return *fw ? 0 : -1;
}

int karma_mcd_close(void **state)
{
    (void)state;
    if (opened) {
        McdTerm(*opened);
        *opened = NULL;
        opened = NULL;
    }
    return 0;
}
