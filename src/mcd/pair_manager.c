/* pair_manager.c -- Karma 1.2's model pair manager (McdModelPairManager.h): a fixed table of pair
 * records with a hash from the (unordered) pair of model IDs to its record. Records are handed out
 * in slot order, so the same calls always give the same order. */
#include <karma/McdInteraction.h>
#include <karma/McdModel.h>
#include <karma/McdModelPair.h>
#include <karma/McdModelPairManager.h>
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "framework.h"

enum { kFree = 0, kHello, kStaying, kGoodbye };

typedef struct PairRecord {
    McdModelPair pair;
    int state;
    int next; /* next record of the same hash bucket, or -1 */
} PairRecord;

struct McdModelPairManager {
    PairRecord *records;
    int *buckets; /* first record of each bucket, or -1 */
    int size, bucketCount, used;
    int freeHint; /* where to start looking for a free record */
    McdSpacePoolErrorFnPtr poolFullHandler;
};

McdModelPairManagerID MEAPI McdModelPairManagerCreate(int size)
{
    if (size <= 0 || size > (1 << 24)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "size is %d; it must be in 1..%d; call ignored", size, 1 << 24);
        return NULL;
    }
    McdModelPairManager *m = MeMemoryCreateZeroed(sizeof *m);
    if (m) {
        m->size = size;
        m->bucketCount = 2 * size;
        m->records = MeMemoryCreateZeroed((size_t)size * sizeof *m->records);
        m->buckets = MeMemoryCreate((size_t)m->bucketCount * sizeof *m->buckets);
    }
    if (!m || !m->records || !m->buckets) {
        ME_REPORT(ME_ERR_OUT_OF_MEMORY, "no memory for a pair manager of %d pairs", size);
        McdModelPairManagerDestroy(m);
        return NULL;
    }
    for (int i = 0; i < m->bucketCount; i++)
        m->buckets[i] = -1;
    return m;
}

void MEAPI McdModelPairManagerDestroy(McdModelPairManager *manager)
{
    if (!manager)
        return;
    MeMemoryDestroy(manager->records);
    MeMemoryDestroy(manager->buckets);
    MeMemoryDestroy(manager);
}

/* The bucket of the unordered pair (IDs are handles: their bits, not addresses). */
static int bucketOf(const McdModelPairManager *m, McdModelID a, McdModelID b)
{
    uintptr_t x = (uintptr_t)a, y = (uintptr_t)b;
    if (x > y) {
        uintptr_t t = x;
        x = y;
        y = t;
    }
    uint64_t h = ((uint64_t)x * 0x9E3779B97F4A7C15ull) ^ ((uint64_t)y * 0xC2B2AE3D27D4EB4Full);
    return (int)((h ^ (h >> 29)) % (uint64_t)m->bucketCount);
}

/* The record of the pair, or -1. */
static int findRecord(const McdModelPairManager *m, McdModelID a, McdModelID b)
{
    for (int i = m->buckets[bucketOf(m, a, b)]; i >= 0; i = m->records[i].next) {
        const McdModelPair *p = &m->records[i].pair;
        if ((p->model1 == a && p->model2 == b) || (p->model1 == b && p->model2 == a))
            return i;
    }
    return -1;
}

/* Forget record i: undo its McdHello if the application did not say Goodbye, unlink it. */
static void freeRecord(McdModelPairManager *m, int i)
{
    PairRecord *r = &m->records[i];
    if (r->pair.testIndex >= 0 && McdModelIsValid(r->pair.model1)) {
        McdModelData *m1 = McdModelFromID(r->pair.model1, "McdModelPairManagerFlush");
        if (m1)
            McdGoodbyeInternal(&r->pair, m1);
    }
    int *link = &m->buckets[bucketOf(m, r->pair.model1, r->pair.model2)];
    while (*link != i)
        link = &m->records[*link].next;
    *link = r->next;
    r->state = kFree;
    m->used--;
    if (i < m->freeHint)
        m->freeHint = i;
}

/* Both models live and distinct (reported in `function` otherwise). */
static MeBool modelsOk(McdModelID a, McdModelID b, const char *function)
{
    if (!McdModelFromID(a, function) || !McdModelFromID(b, function))
        return MEFALSE;
    if (a == b) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "the two models are the same; call ignored");
        return MEFALSE;
    }
    return METRUE;
}

MeBool MEAPI McdModelPairManagerActivate(McdModelPairManagerID manager, McdModelID model1, McdModelID model2)
{
    ME_CHECK_NOT_NULL(manager, MEFALSE);
    if (!modelsOk(model1, model2, __func__))
        return MEFALSE;
    int i = findRecord(manager, model1, model2);
    if (i >= 0) {
        if (manager->records[i].state == kGoodbye)
            manager->records[i].state = kStaying; /* back before the flush: it never left */
        return METRUE;
    }
    if (manager->used == manager->size) {
        ME_REPORT(ME_ERR_POOL_FULL, "all %d pairs of the manager are in use (McdModelPairManagerCreate); pair lost",
                  manager->size);
        if (manager->poolFullHandler)
            manager->poolFullHandler(model1, model2);
        return MEFALSE;
    }
    while (manager->records[manager->freeHint].state != kFree)
        manager->freeHint++;
    i = manager->freeHint;
    PairRecord *r = &manager->records[i];
    McdModelPairReset(&r->pair, model1, model2);
    r->pair.id = (MeU32)i;
    r->state = kHello;
    int b = bucketOf(manager, model1, model2);
    r->next = manager->buckets[b];
    manager->buckets[b] = i;
    manager->used++;
    return MEFALSE;
}

MeBool MEAPI McdModelPairManagerDeactivate(McdModelPairManagerID manager, McdModelID model1, McdModelID model2)
{
    ME_CHECK_NOT_NULL(manager, MEFALSE);
    int i = findRecord(manager, model1, model2);
    if (i < 0 || manager->records[i].state == kGoodbye)
        return MEFALSE;
    if (manager->records[i].state == kHello)
        freeRecord(manager, i);
    else
        manager->records[i].state = kGoodbye;
    return METRUE;
}

McdModelPairID MEAPI McdModelPairManagerGetPair(McdModelPairManagerID manager, McdModelID m1, McdModelID m2)
{
    ME_CHECK_NOT_NULL(manager, NULL);
    int i = findRecord(manager, m1, m2);
    return i >= 0 ? &manager->records[i].pair : NULL;
}

void MEAPI McdModelPairManagerFlush(McdModelPairManagerID manager)
{
    ME_CHECK_NOT_NULL(manager, ME_NOTHING);
    for (int i = 0; i < manager->size; i++) {
        if (manager->records[i].state == kHello)
            manager->records[i].state = kStaying;
        else if (manager->records[i].state == kGoodbye)
            freeRecord(manager, i);
    }
}

void MEAPI McdModelPairManagerResetIterator(McdModelPairManagerID manager, McdSpacePairIterator *iterator)
{
    ME_CHECK_NOT_NULL(manager, ME_NOTHING);
    ME_CHECK_NOT_NULL(iterator, ME_NOTHING);
    iterator->report = 0;
    iterator->index = 0;
    iterator->space = 0;
}

/* Fill the container from the iterator's place: goodbyes, hellos, then (withStaying) stayings; the
 * iterator walks phase * size + slot. Returns METRUE when the container filled up first. */
static MeBool fill(McdModelPairManager *m, McdSpacePairIterator *it, McdModelPairContainer *c, MeBool withStaying)
{
    static const int phaseState[3] = {kGoodbye, kHello, kStaying};
    int end = (withStaying ? 3 : 2) * m->size;
    McdModelPairContainerReset(c);
    for (; it->index < end; it->index++) {
        int phase = it->index / m->size;
        PairRecord *r = &m->records[it->index % m->size];
        if (r->state != phaseState[phase])
            continue;
        if (c->stayingEnd >= c->size)
            return METRUE;
        if (phase == 0)
            McdModelPairContainerInsertGoodbyePair(c, &r->pair);
        else if (phase == 1)
            McdModelPairContainerInsertHelloPair(c, &r->pair);
        else
            McdModelPairContainerInsertStayingPair(c, &r->pair);
    }
    return MEFALSE;
}

MeBool MEAPI McdModelPairManagerGetTransitions(McdModelPairManagerID manager, McdSpacePairIterator *iterator,
                                               McdModelPairContainer *container)
{
    ME_CHECK_NOT_NULL(manager, MEFALSE);
    ME_CHECK_NOT_NULL(iterator, MEFALSE);
    ME_CHECK_NOT_NULL(container, MEFALSE);
    return fill(manager, iterator, container, MEFALSE);
}

MeBool MEAPI McdModelPairManagerGetPairs(McdModelPairManagerID manager, McdSpacePairIterator *iterator,
                                         McdModelPairContainer *container)
{
    ME_CHECK_NOT_NULL(manager, MEFALSE);
    ME_CHECK_NOT_NULL(iterator, MEFALSE);
    ME_CHECK_NOT_NULL(container, MEFALSE);
    return fill(manager, iterator, container, METRUE);
}

int MEAPI McdModelPairManagerGetSize(McdModelPairManagerID manager)
{
    ME_CHECK_NOT_NULL(manager, 0);
    return manager->used;
}

void MEAPI McdModelPairManagerSetPoolFullHandler(McdModelPairManagerID manager, McdSpacePoolErrorFnPtr handler)
{
    ME_CHECK_NOT_NULL(manager, ME_NOTHING);
    manager->poolFullHandler = handler;
}

McdSpacePoolErrorFnPtr MEAPI McdModelPairManagerGetPoolFullHandler(McdModelPairManagerID manager)
{
    ME_CHECK_NOT_NULL(manager, NULL);
    return manager->poolFullHandler;
}
