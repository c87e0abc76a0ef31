/* parallel_pairs.c -- the bridge's pair tests on several workers (issue 17, point 5).
 *
 * With a task system on the world (MdtTaskSystem.h), the nearfield tests of a chunk of pairs run as
 * one task over the pairs (MdtWorldRunTask): each pair's test writes only its own record and its own
 * slice of contacts (and its own pair cache). The conversion into contact groups, the material
 * callbacks and the world's contacts then run on the stepping thread in pair order, exactly as the
 * serial update runs them, so the contacts, and every trajectory, are the serial ones bit for bit.
 * Karma's per-model intersect callbacks (McdModelSetIntersectCallback) are called inside the test:
 * with a task system they run on the workers. */
#include <string.h>

#include <karma/MdtTaskSystem.h>
#include <karma/MeMemory.h>

#include "bridge.h"

/* Pairs per range of the test task: one convex pair test is a few thousand operations. */
#define PAIR_MIN_RANGE 8

typedef struct PairTask {
    MstBridgeData *b;
    McdModelPairID *hello, *staying;
    int helloCount;
} PairTask;

static void testPairs(int start, int end, int worker, void *data)
{
    (void)worker;
    const PairTask *t = data;
    MstBridgeData *b = t->b;
    for (int i = start; i < end; i++) {
        McdModelPairID pair = i < t->helloCount ? t->hello[i] : t->staying[i - t->helloCount];
        MstTestedPair *r = &b->tested[i];
        memset(&r->result, 0, sizeof r->result);
        r->result.contacts = b->testedContacts + (size_t)i * (size_t)b->testedContactsPerPair;
        r->result.contactMaxCount = b->testedContactsPerPair;
        r->tested = McdIntersectForResponse(pair, &r->info, &r->result);
    }
}

void MstBridgeFreeParallel(MstBridgeData *b)
{
    MeMemoryDestroy(b->tested);
    MeMemoryDestroy(b->testedContacts);
    b->tested = NULL;
    b->testedContacts = NULL;
    b->testedPairs = b->testedContactsPerPair = 0;
}

MeBool MstBridgeReserveParallel(MstBridgeData *b)
{
    if (b->tested && b->testedPairs == b->pairBufferSize && b->testedContactsPerPair == b->contactBufferSize)
        return METRUE;
    MstBridgeFreeParallel(b);
    b->tested = MeMemoryCreate(sizeof *b->tested * (size_t)b->pairBufferSize);
    b->testedContacts = MeMemoryCreate(sizeof *b->testedContacts * (size_t)b->pairBufferSize *
                                       (size_t)b->contactBufferSize);
    if (!b->tested || !b->testedContacts) {
        MstBridgeFreeParallel(b); /* reported by MeMemory; the pairs are tested serially */
        return MEFALSE;
    }
    b->testedPairs = b->pairBufferSize;
    b->testedContactsPerPair = b->contactBufferSize;
    return METRUE;
}

MeBool MstBridgeCollideInParallel(MstBridgeData *b, MdtWorldID world, McdModelPairID *hello, int helloCount,
                                  McdModelPairID *staying, int stayingCount)
{
    const int count = helloCount + stayingCount;
    if (MdtWorldGetWorkerCount(world) <= 1 || count <= PAIR_MIN_RANGE || count > b->pairBufferSize)
        return MEFALSE;
    if (!MstBridgeReserveParallel(b))
        return MEFALSE;
    PairTask task = {b, hello, staying, helloCount};
    MdtWorldRunTask(world, testPairs, count, PAIR_MIN_RANGE, &task);
    return METRUE;
}
