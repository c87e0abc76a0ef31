/* culling.c -- culling tables: which models of one group never pair (see McdSpace.h). */
#include <string.h>

#include <karma/MeMemory.h>

#include "../me/check.h"
#include "space.h"

McdCullingTableID McdCullingTableCreate(int size)
{
    if (size < 1 || size > 65536) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "size (%d) must be between 1 and 65536; no table made", size);
        return NULL;
    }
    McdCullingTable *t = MeMemoryCreateZeroed(sizeof *t);
    if (!t)
        return NULL;
    t->size = size;
    t->bits = MeMemoryCreateZeroed(((size_t)size * (size_t)size + 7) / 8);
    if (!t->bits) {
        MeMemoryDestroy(t);
        return NULL;
    }
    return (McdCullingTableID)t;
}

void McdCullingTableDestroy(McdCullingTableID table)
{
    McdCullingTable *t = (McdCullingTable *)table;
    ME_CHECK_NOT_NULL(t, ME_NOTHING);
    if (t->users > 0) {
        ME_REPORT(ME_ERR_MCD_IN_USE, "%d models in spaces still use the culling table; remove them first", t->users);
        return;
    }
    MeMemoryDestroy(t->bits);
    MeMemoryDestroy(t);
}

static MeBool inRange(const McdCullingTable *t, int i, int j, const char *function)
{
    if (!t) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument 'table' is NULL; call ignored");
        return MEFALSE;
    }
    if (i < 0 || j < 0 || i >= t->size || j >= t->size) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "indices (%d, %d) must be in [0, %d); call ignored", i, j,
                     t->size);
        return MEFALSE;
    }
    return METRUE;
}

static void setBit(McdCullingTable *t, int i, int j, MeBool on)
{
    int bit = i * t->size + j;
    if (on)
        t->bits[bit >> 3] |= (unsigned char)(1u << (bit & 7));
    else
        t->bits[bit >> 3] &= (unsigned char)~(1u << (bit & 7));
}

void McdCullingTableSet(McdCullingTableID table, int i, int j, MeBool cull)
{
    McdCullingTable *t = (McdCullingTable *)table;
    if (!inRange(t, i, j, __func__))
        return;
    setBit(t, i, j, cull);
    setBit(t, j, i, cull);
}

MeBool McdCullingTableGet(McdCullingTableID table, int i, int j)
{
    const McdCullingTable *t = (const McdCullingTable *)table;
    if (!inRange(t, i, j, __func__))
        return MEFALSE;
    int bit = i * t->size + j;
    return (t->bits[bit >> 3] >> (bit & 7)) & 1;
}
