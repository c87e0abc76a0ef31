/* transitions.c -- reading the space's pairs chunk by chunk, for the bridge's whole update and for
 * MstBridgeUpdateTransitions, the Hello and Goodbye half on its own (Karma 1.2's form, for programs
 * that remove models between steps). */
#include <karma/McdSpace.h>
#include <karma/MstBridge.h>

#include "bridge.h"

void MstBridgeReadPairs(MstBridgeData *b, McdSpaceID space, MdtWorldID world, MeBool collisions)
{
    if (McdSpaceIsChanging(space))
        McdSpaceEndChanges(space);
    if (collisions && MstBridgeReadPairsPipelined(b, space, world)) {
        McdSpaceBeginChanges(space);
        return;
    }
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    MeBool more;
    do {
        McdModelPairContainerReset(b->pairs);
        more = McdSpaceGetPairs(space, &it, b->pairs);
        MstHandleTransitions(b->pairs, space, world, (MstBridgeID)b->id);
        if (collisions)
            MstHandleCollisions(b->pairs, space, world, (MstBridgeID)b->id);
    } while (more);
    McdSpaceBeginChanges(space);
}

void MstBridgeUpdateTransitions(MstBridgeID id, McdSpaceID space, MdtWorldID world)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (b)
        MstBridgeReadPairs(b, space, world, MEFALSE);
}
