/* material.c -- the bridge's material table: contact parameters and callbacks per material pair.
 *
 * The table is symmetric: (m1, m2) and (m2, m1) name one entry, stored at (min, max). Parameters are
 * copied by value into each new dynamics contact, so the application may change a contact's own
 * copy in a per-contact callback without touching the table. */
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "bridge.h"

MstMaterialPairData *MstBridgeMaterialPair(MstBridgeData *b, MstMaterialID m1, MstMaterialID m2, const char *function)
{
    /* Unsigned: a negative index a program computed arrives as a huge one and is refused here. */
    unsigned int count = (unsigned int)b->materialCount;
    if (m1 >= count || m2 >= count) {
        ME_REPORT_IN(function, ME_ERR_MST_MATERIAL,
                     "material pair (%u, %u) is out of range: the bridge has %u material(s)", m1, m2, count);
        return NULL;
    }
    size_t lo = m1 < m2 ? m1 : m2, hi = m1 < m2 ? m2 : m1;
    return &b->table[lo * (size_t)b->maxMaterials + hi];
}

MstMaterialID MstBridgeGetDefaultMaterial(void) { return 0; }

MstMaterialID MstBridgeGetNewMaterial(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return MST_MATERIAL_INVALID;
    if (b->materialCount >= b->maxMaterials) {
        ME_REPORT(ME_ERR_POOL_FULL, "the material table is full (%d materials): raise %s", b->maxMaterials,
                  b->materialsSizeName);
        return MST_MATERIAL_INVALID;
    }
    return (MstMaterialID)b->materialCount++;
}

int MstBridgeGetMaterialCount(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->materialCount : 0;
}

int MstBridgeGetMaxMaterials(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->maxMaterials : 0;
}

MdtContactParamsID MstBridgeGetContactParams(MstBridgeID id, MstMaterialID m1, MstMaterialID m2)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    MstMaterialPairData *e = b ? MstBridgeMaterialPair(b, m1, m2, __func__) : NULL;
    return e ? &e->params : NULL;
}

static MeBool hasCallback(const MstMaterialPairData *e) { return e->intersectCB || e->perContactCB || e->perPairCB; }

/* Setter and getter of one callback field of the table; the setter keeps the bridge's count of entries
 * with a callback, which decides whether its update may run on several workers. */
#define MATERIAL_CALLBACK(Name, Type, field)                                                         \
    void MstBridgeSet##Name(MstBridgeID id, MstMaterialID m1, MstMaterialID m2, Type cb)             \
    {                                                                                                \
        MstBridgeData *b = MstBridgeFromID(id, __func__);                                                \
        MstMaterialPairData *e = b ? MstBridgeMaterialPair(b, m1, m2, __func__) : NULL;                  \
        if (!e)                                                                                      \
            return;                                                                                  \
        const MeBool had = hasCallback(e);                                                           \
        e->field = cb;                                                                               \
        b->materialCallbackCount += hasCallback(e) - had;                                            \
    }                                                                                                \
    Type MstBridgeGet##Name(MstBridgeID id, MstMaterialID m1, MstMaterialID m2)                      \
    {                                                                                                \
        MstBridgeData *b = MstBridgeFromID(id, __func__);                                                \
        MstMaterialPairData *e = b ? MstBridgeMaterialPair(b, m1, m2, __func__) : NULL;                  \
        return e ? e->field : NULL;                                                                  \
    }

MATERIAL_CALLBACK(IntersectCB, MstIntersectCBPtr, intersectCB)
MATERIAL_CALLBACK(PerContactCB, MstPerContactCBPtr, perContactCB)
MATERIAL_CALLBACK(PerPairCB, MstPerPairCBPtr, perPairCB)
