/* bridge.h -- the bridge record (internal): the material table and the buffers of the update. */
#ifndef MST_BRIDGE_INTERNAL_H
#define MST_BRIDGE_INTERNAL_H

#include <stdint.h>

#include <karma/MstBridge.h>

/** One entry of the symmetric material table. */
typedef struct MstMaterialPair {
    MdtContactParams params;
    MstIntersectCBPtr intersectCB;
    MstPerContactCBPtr perContactCB;
    MstPerPairCBPtr perPairCB;
} MstMaterialPair;

typedef struct MstBridge {
    int ownerSlot;
    uintptr_t id;
    McdFrameworkID framework;
    int maxMaterials, materialCount;
    MstMaterialPair *table;            /* maxMaterials², entry (i, j) with i <= j used */
    McdModelPairContainer *pairs;      /* chunk read from the space */
    int pairBufferSize;
    McdContact *contacts;              /* buffer for one pair test */
    int contactBufferSize;
    int lastPairCount, lastContactCount;
} MstBridge;

MstBridge *MstBridgeFromID(MstBridgeID id, const char *function);
/** The table entry for a material pair, or NULL (reported in `function`'s name) for a bad index. */
MstMaterialPair *MstBridgeMaterialPair(MstBridge *b, MstMaterialID m1, MstMaterialID m2, const char *function);

#endif /* MST_BRIDGE_INTERNAL_H */
