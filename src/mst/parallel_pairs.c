/* parallel_pairs.c -- the bridge's pair tests on several workers (issue 17, point 5).
 *
 * With a task system on the world (MdtTaskSystem.h), the nearfield tests of a chunk of pairs run as
 * one task over the pairs (MdtWorldRunTask): each pair's test writes only its own record and its own
 * slice of contacts (and its own pair cache). The conversion into contact groups then runs in pair
 * order, exactly as the serial update runs it, so the contacts, and every trajectory, are the serial
 * ones bit for bit. Karma's per-model intersect callbacks (McdModelSetIntersectCallback) are called
 * inside the test: with a task system they run on the workers.
 *
 * The whole update (MstBridgeReadPairsPipelined) overlaps the conversion with the tests: chunk k's
 * conversion is one item of the task that tests chunk k + 1 (two sets of records, two pair
 * containers), so the serial part of the bridge runs beside the next chunk's tests. What orders the
 * world's pools is kept: chunk k's conversion (which makes and removes contacts) still comes before
 * chunk k + 1's goodbyes (which destroy contact groups), so every contact and group takes the slot it
 * takes in the serial update. Only the Hellos of chunk k + 1 (McdHello: a pair's test and cache
 * cleared) move before chunk k's conversion, which does not read them. A model with an intersect
 * callback (which runs in the test, and could read what the conversion writes) or a material with a
 * callback keeps the chunk-by-chunk update: a material's callbacks run on the stepping thread, in pair
 * order, and a model's run only while no conversion does. */
#include <string.h>

#include <karma/McdFrame.h>
#include <karma/McdSpace.h>
#include <karma/MdtTaskSystem.h>
#include <karma/MdtWorld.h>
#include <karma/MeMemory.h>

#include "bridge.h"

/* Pairs per range of the test task: one convex pair test is a few thousand operations. */
#define PAIR_MIN_RANGE 8

/* Test one pair into record `r`, whose contacts are its own slice of the scratch. */
static void testPair(MstBridgeData *b, McdModelPairID pair, MstTestedPair *r, McdContact *contacts)
{
    memset(&r->result, 0, sizeof r->result);
    r->result.contacts = contacts;
    r->result.contactMaxCount = b->testedContactsPerPair;
    r->tested = McdIntersectForResponse(pair, &r->info, &r->result);
}

/* The records of set `set` (0 or 1) and the contacts of its pair i. */
static MstTestedPair *recordsOf(MstBridgeData *b, int set) { return b->tested + (size_t)set * (size_t)b->testedPairs; }

static McdContact *contactsOf(MstBridgeData *b, int set, int i)
{
    return b->testedContacts + ((size_t)set * (size_t)b->testedPairs + (size_t)i) * (size_t)b->testedContactsPerPair;
}

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
        testPair(b, pair, &b->tested[i], contactsOf(b, 0, i));
    }
}

void MstBridgeFreeParallel(MstBridgeData *b)
{
    MeMemoryDestroy(b->tested);
    MeMemoryDestroy(b->testedContacts);
    if (b->nextPairs)
        McdModelPairContainerDestroy(b->nextPairs);
    b->tested = NULL;
    b->testedContacts = NULL;
    b->nextPairs = NULL;
    b->testedPairs = b->testedContactsPerPair = 0;
}

/* Size the world's task marks for a chunk's tasks: its pairs' tests and the conversion beside them. A
 * failure is reported by the world's chunk; the tasks then run serially, as MdtWorldRunTask does
 * without memory for its marks, so it is not tried again for this world. */
static void markWorld(MstBridgeData *b, MdtWorldID world)
{
    if (!world && b->markedWorld && MdtWorldIsValid(b->markedWorld))
        world = b->markedWorld;
    if (!world)
        return;
    (void)MdtWorldReserveTaskItems(world, b->pairBufferSize + 1);
    b->markedWorld = world;
}

MeBool MstBridgeReserveParallel(MstBridgeData *b, MdtWorldID world)
{
    if (b->tested && b->testedPairs == b->pairBufferSize && b->testedContactsPerPair == b->contactBufferSize) {
        if (world && world != b->markedWorld)
            markWorld(b, world);
        return METRUE;
    }
    if (b->failedPairs == b->pairBufferSize && b->failedContactsPerPair == b->contactBufferSize)
        return MEFALSE; /* failed for these sizes (reported then): not again at every update */
    MstBridgeFreeParallel(b);
    b->tested = MeMemoryCreate(sizeof *b->tested * 2 * (size_t)b->pairBufferSize);
    b->testedContacts = MeMemoryCreate(sizeof *b->testedContacts * 2 * (size_t)b->pairBufferSize *
                                       (size_t)b->contactBufferSize);
    b->nextPairs = McdModelPairContainerCreate(b->pairBufferSize);
    if (!b->tested || !b->testedContacts || !b->nextPairs) {
        MstBridgeFreeParallel(b); /* reported by MeMemory; the pairs are tested serially */
        b->failedPairs = b->pairBufferSize;
        b->failedContactsPerPair = b->contactBufferSize;
        return MEFALSE;
    }
    b->failedPairs = b->failedContactsPerPair = 0;
    b->testedPairs = b->pairBufferSize;
    b->testedContactsPerPair = b->contactBufferSize;
    markWorld(b, world);
    return METRUE;
}

MeBool MstBridgeCollideInParallel(MstBridgeData *b, MdtWorldID world, McdModelPairID *hello, int helloCount,
                                  McdModelPairID *staying, int stayingCount)
{
    const int count = helloCount + stayingCount;
    if (MdtWorldGetWorkerCount(world) <= 1 || count <= PAIR_MIN_RANGE || count > b->pairBufferSize)
        return MEFALSE;
    if (!MstBridgeReserveParallel(b, world))
        return MEFALSE;
    PairTask task = {b, hello, staying, helloCount};
    MdtWorldRunTask(world, testPairs, count, PAIR_MIN_RANGE, &task);
    return METRUE;
}

/* ---- the pipelined update ---------------------------------------------------------------------- */

/* A chunk read from the space: its container and the set of records its tests write. */
typedef struct Chunk {
    McdModelPairContainer *pairs;
    int set;
    McdModelPairID *hello, *staying;
    int helloCount, count;
} Chunk;

static void readChunk(Chunk *c)
{
    int staying;
    c->hello = McdModelPairContainerGetHelloArray(c->pairs, &c->helloCount);
    c->staying = McdModelPairContainerGetStayingArray(c->pairs, &staying);
    c->count = c->helloCount + staying;
}

static McdModelPairID pairOf(const Chunk *c, int i)
{
    return i < c->helloCount ? c->hello[i] : c->staying[i - c->helloCount];
}

/* Chunk `convert`'s conversion (item 0, in pair order) and chunk `test`'s pair tests (items 1..). */
typedef struct PipelineTask {
    MstBridgeData *b;
    MdtWorldID world;
    const Chunk *convert, *test; /* either may be NULL */
    int contacts;                /* made by the conversion */
} PipelineTask;

static void convertChunk(PipelineTask *t)
{
    MstBridgeData *b = t->b;
    const Chunk *c = t->convert;
    MstTestedPair *records = recordsOf(b, c->set);
    for (int i = 0; i < c->count; i++)
        t->contacts += MstBridgeConvertPair(b, pairOf(c, i), t->world, records[i].tested, &records[i].info,
                                            &records[i].result);
}

static void pipelineItems(int start, int end, int worker, void *data)
{
    (void)worker;
    PipelineTask *t = data;
    MstBridgeData *b = t->b;
    for (int i = start; i < end; i++) {
        if (i == 0) {
            if (t->convert)
                convertChunk(t);
            continue;
        }
        const int k = i - 1, set = t->test->set;
        testPair(b, pairOf(t->test, k), &recordsOf(b, set)[k], contactsOf(b, set, k));
    }
}

/* Whether the pair tests or the conversion call the application: a material's callback (which runs
 * in the conversion) or a model's intersect callback (which runs in the pair test, and so would run
 * beside the previous chunk's conversion). Then the update stays chunk by chunk. */
static MeBool callsTheApplication(const MstBridgeData *b)
{
    return b->materialCallbackCount > 0 || (b->framework && McdFrameworkGetIntersectCallbackCount(b->framework) > 0);
}

MeBool MstBridgeReadPairsPipelined(MstBridgeData *b, McdSpaceID space, MdtWorldID world)
{
    if (MdtWorldGetWorkerCount(world) <= 1 || callsTheApplication(b) || !MstBridgeReserveParallel(b, world))
        return MEFALSE;
    /* The conversion's messages name the call the application made (MstUniverseStep or
     * MstBridgeUpdateContacts, which name themselves first). */
    const char *caller = MdtWorldGetCallerName(world);
    b->converting = caller ? caller : "MstBridgeUpdateContacts";
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    Chunk chunks[2] = {{b->pairs, 0, NULL, NULL, 0, 0}, {b->nextPairs, 1, NULL, NULL, 0, 0}};
    Chunk *converted = NULL, *read = &chunks[0];
    PipelineTask task = {b, world, NULL, NULL, 0};
    MeBool more = METRUE;
    /* Each pass reads the next chunk (if any), then tests it beside the conversion of the chunk before:
     * the first pass converts nothing, the last reads and tests nothing. */
    while (more || converted) {
        task.test = NULL;
        if (more) {
            McdModelPairContainerReset(read->pairs);
            more = McdSpaceGetPairs(space, &it, read->pairs);
            if (!converted) /* the first chunk: its goodbyes come first, as in the serial update */
                MstBridgeSayGoodbye(read->pairs);
            MstBridgeSayHello(read->pairs);
            readChunk(read);
            task.test = read;
        }
        task.convert = converted;
        task.contacts = 0;
        MdtWorldRunTask(world, pipelineItems, 1 + (task.test ? task.test->count : 0), PAIR_MIN_RANGE, &task);
        b->lastContactCount += task.contacts;
        if (task.test) {
            b->lastPairCount += task.test->count;
            if (converted) /* after the conversion before it, as in the serial update */
                MstBridgeSayGoodbye(read->pairs);
        }
        Chunk *const spare = converted ? converted : &chunks[1];
        converted = task.test ? read : NULL;
        read = spare;
    }
    return METRUE;
}
