/* space.c -- the space record, its ID, change blocks, reading the pairs, pair containers (see
 * McdSpace.h). Models enter and leave in space_model.c; the engine is space_sort.c + space_pairs.c. */
#include <string.h>

#include <karma/McdInteraction.h>
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "../me/handle.h"
#include "space.h"

McdSpaceData *McdSpaceFromID(McdSpaceID id, const char *function)
{
    return MeHandleResolveOwner((uintptr_t)id, ME_HANDLE_SPACE, function, "space");
}

#define SPACE_OR_RETURN(s, id, ret)                                                                  \
    McdSpaceData *s = McdSpaceFromID((id), __func__);                                                    \
    if (!s)                                                                                          \
    return ret

McdSpaceData *McdSpaceCreateInternal(struct McdFrameworkData *fw, int axes, int objectCount, int pairCount, const char *function)
{
    if (axes <= 0 || axes > McdAllAxes) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE,
                     "axes (%d) must combine McdXAxis, McdYAxis and McdZAxis (1 to 7); no space made", axes);
        return NULL;
    }
    if (objectCount < 1 || objectCount > (int)ME_HANDLE_MAX_INDEX || pairCount < 1 ||
        pairCount > (int)ME_HANDLE_MAX_INDEX) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE,
                     "objectCount (%d) and pairCount (%d) must be between 1 and %ld; no space made", objectCount,
                     pairCount, (long)ME_HANDLE_MAX_INDEX);
        return NULL;
    }
    McdSpaceData *s = MeMemoryCreateZeroed(sizeof *s);
    if (!s)
        return NULL;
    s->framework = fw;
    if (!McdSpaceEngineInit(s, axes, objectCount, pairCount)) {
        ME_REPORT_IN(function, ME_ERR_OUT_OF_MEMORY, "no memory for a space of %d models and %d pairs", objectCount,
                     pairCount);
        McdSpaceEngineTerm(s);
        MeMemoryDestroy(s);
        return NULL;
    }
    s->ownerSlot = MeHandleRegisterOwner(s, ME_HANDLE_SPACE, function);
    if (!s->ownerSlot) {
        McdSpaceEngineTerm(s);
        MeMemoryDestroy(s);
        return NULL;
    }
    s->id = MeHandleOfOwner(s->ownerSlot);
    s->changing = METRUE; /* a new space starts inside a change block */
    return s;
}

void McdSpaceDestroyInternal(McdSpaceData *s)
{
    for (int p = 0; p < s->maxPairs; p++) /* pairs still holding a pair test's cache: their goodbye */
        if (s->pairs[p].pair.cache)
            McdGoodbye(&s->pairs[p].pair);
    for (int slot = 0; slot < s->maxObjects; slot++) /* release the culling tables */
        if (s->obj[slot].flags & MCD_OBJ_LIVE)
            McdSpaceObjectSetCulling(s, slot, NULL, 0, 0);
    MeHandleUnregisterOwner(s->ownerSlot);
    McdSpaceEngineTerm(s);
    MeMemoryDestroy(s);
}

MeBool McdSpaceIsValid(McdSpaceID space) { return MeHandleIsValid((uintptr_t)space, ME_HANDLE_SPACE); }

void McdSpaceSetSizeNames(McdSpaceID id, const char *models, const char *pairs)
{
    SPACE_OR_RETURN(s, id, ME_NOTHING);
    if (models)
        s->objectsSizeName = models;
    if (pairs)
        s->pairsSizeName = pairs;
}

void McdSpaceSetCallerName(McdSpaceID id, const char *function)
{
    SPACE_OR_RETURN(s, id, ME_NOTHING);
    s->caller = function;
}

/* ---- change blocks ------------------------------------------------------------------------ */

void McdSpaceBeginChanges(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    if (s->changing) {
        ME_REPORT(ME_ERR_BAD_STATE, "the space is already inside a change block; call ignored");
        return;
    }
    McdSpacePairReleaseGoodbyes(s);
    s->changing = METRUE;
}

void McdSpaceEndChanges(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    if (!s->changing) {
        ME_REPORT(ME_ERR_BAD_STATE, "the space is not inside a change block (McdSpaceBeginChanges); call ignored");
        return;
    }
    McdSpaceSort(s, MEFALSE, __func__); /* models inserted or removed since the last update */
    McdSpacePairReport(s);
    s->changing = MEFALSE;
}

MeBool McdSpaceIsChanging(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, MEFALSE);
    return s->changing;
}

void McdSpaceBuild(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    if (McdSpaceCheckChanging(s, METRUE, __func__))
        McdSpaceRebuild(s, __func__);
}

MeBool McdSpaceCheckChanging(const McdSpaceData *s, MeBool wanted, const char *function)
{
    if (s->changing == wanted)
        return METRUE;
    if (wanted)
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "allowed only inside a change block (McdSpaceBeginChanges ... EndChanges); call ignored");
    else
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "not allowed inside a change block: call McdSpaceEndChanges first; call ignored");
    return MEFALSE;
}

void McdSpaceSetPoolFullHandler(McdSpaceID space, McdSpacePoolErrorFnPtr handler)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    s->poolFull = handler;
}

McdSpacePoolErrorFnPtr McdSpaceGetPoolFullHandler(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, NULL);
    return s->poolFull;
}

void McdSpaceSetUserData(McdSpaceID space, void *data)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    s->userData = data;
}

void *McdSpaceGetUserData(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, NULL);
    return s->userData;
}

void McdSpaceSetAABBFn(McdSpaceID space, McdSpaceUpdateAABBFnPtr updateAABBFn)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    s->updateAABBFn = updateAABBFn;
}

int McdSpaceGetPairCount(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, 0);
    return s->maxPairs - s->freePairCount;
}

int McdSpaceGetPairCapacity(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, 0);
    return s->maxPairs;
}

int McdSpaceGetLostPairCount(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, 0);
    return s->lostTotal;
}

/* ---- reading the pairs -------------------------------------------------------------------- */

void McdSpacePairIteratorBegin(McdSpaceID space, McdSpacePairIterator *iter)
{
    ME_CHECK_NOT_NULL(iter, ME_NOTHING);
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    iter->report = s->reportNumber;
    iter->index = 0;
    iter->space = (MeU32)s->id;
}

/* Shared by GetPairs and GetTransitions: fills from the report entries [iter->index, end). */
static MeBool fill(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *c, MeBool all,
                   const char *function)
{
    McdSpaceData *s = McdSpaceFromID(space, function);
    if (!s)
        return MEFALSE;
    if (!iter || !c) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument '%s' is NULL; call ignored", iter ? "container" : "iter");
        return MEFALSE;
    }
    McdModelPairContainerReset(c);
    if (!McdSpaceCheckChanging(s, MEFALSE, function))
        return MEFALSE;
    if (iter->report != s->reportNumber || iter->space != (MeU32)s->id) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "the iterator was not started with McdSpacePairIteratorBegin on this space since its last "
                     "McdSpaceEndChanges; call ignored");
        return MEFALSE;
    }
    int g = s->goodbyeCount, h = s->helloCount;
    int end = all ? g + h + s->stayingCount : g + h;
    int i = iter->index < 0 ? 0 : iter->index;
    int n = 0;
    c->goodbyeFirst = 0;
    for (; i < g && n < c->size; i++)
        c->array[n++] = &s->pairs[s->report[i]].pair;
    c->goodbyeEnd = c->helloFirst = n;
    for (; i < g + h && n < c->size; i++)
        c->array[n++] = &s->pairs[s->report[i]].pair;
    c->helloEndStayingFirst = n;
    for (; i < end && n < c->size; i++)
        c->array[n++] = &s->pairs[s->report[i]].pair;
    c->stayingEnd = n;
    iter->index = i;
    return i < end;
}

MeBool McdSpaceGetPairs(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *container)
{
    return fill(space, iter, container, METRUE, __func__);
}

MeBool McdSpaceGetTransitions(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *container)
{
    return fill(space, iter, container, MEFALSE, __func__);
}

/* ---- containers --------------------------------------------------------------------------- */

McdModelPairContainer *McdModelPairContainerCreate(int size)
{
    if (size < 1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "size (%d) must be at least 1", size);
        return NULL;
    }
    McdModelPairContainer *c = MeMemoryCreateZeroed(sizeof *c);
    if (!c)
        return NULL;
    c->array = MeMemoryCreateZeroed((size_t)size * sizeof *c->array);
    if (!c->array) {
        MeMemoryDestroy(c);
        return NULL;
    }
    c->size = size;
    return c;
}

void McdModelPairContainerDestroy(McdModelPairContainer *c)
{
    if (!c)
        return;
    MeMemoryDestroy(c->array);
    MeMemoryDestroy(c);
}

void McdModelPairContainerReset(McdModelPairContainer *c)
{
    ME_CHECK_NOT_NULL(c, ME_NOTHING);
    c->goodbyeFirst = c->goodbyeEnd = c->helloFirst = c->helloEndStayingFirst = c->stayingEnd = 0;
}

#define CONTAINER_RANGE(name, first, end)                                                            \
    McdModelPairID *McdModelPairContainerGet##name##Array(McdModelPairContainer *c, int *count)      \
    {                                                                                                \
        ME_CHECK_NOT_NULL(c, NULL);                                                                  \
        if (count)                                                                                   \
            *count = c->end - c->first;                                                              \
        return c->array + c->first;                                                                  \
    }                                                                                                \
    int McdModelPairContainerGet##name##Count(const McdModelPairContainer *c)                        \
    {                                                                                                \
        ME_CHECK_NOT_NULL(c, 0);                                                                     \
        return c->end - c->first;                                                                    \
    }
CONTAINER_RANGE(Goodbye, goodbyeFirst, goodbyeEnd)
CONTAINER_RANGE(Hello, helloFirst, helloEndStayingFirst)
CONTAINER_RANGE(Staying, helloEndStayingFirst, stayingEnd)

/* Opens a gap at `at` by moving the later ranges up one place. */
static MeBool insertAt(McdModelPairContainer *c, int at, McdModelPairID pair, const char *function)
{
    if (!c || !pair) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument '%s' is NULL; call ignored", c ? "pair" : "container");
        return MEFALSE;
    }
    if (c->stayingEnd >= c->size) {
        ME_REPORT_IN(function, ME_ERR_POOL_FULL,
                     "the container is full (%d pairs); pair not added: raise size in McdModelPairContainerCreate",
                     c->size);
        return MEFALSE;
    }
    memmove(c->array + at + 1, c->array + at, (size_t)(c->stayingEnd - at) * sizeof *c->array);
    c->array[at] = pair;
    return METRUE;
}

MeBool McdModelPairContainerInsertGoodbyePair(McdModelPairContainer *c, McdModelPairID pair)
{
    if (!insertAt(c, c ? c->goodbyeEnd : 0, pair, __func__))
        return MEFALSE;
    c->goodbyeEnd++;
    c->helloFirst++;
    c->helloEndStayingFirst++;
    c->stayingEnd++;
    return METRUE;
}

MeBool McdModelPairContainerInsertHelloPair(McdModelPairContainer *c, McdModelPairID pair)
{
    if (!insertAt(c, c ? c->helloEndStayingFirst : 0, pair, __func__))
        return MEFALSE;
    c->helloEndStayingFirst++;
    c->stayingEnd++;
    return METRUE;
}

MeBool McdModelPairContainerInsertStayingPair(McdModelPairContainer *c, McdModelPairID pair)
{
    if (!insertAt(c, c ? c->stayingEnd : 0, pair, __func__))
        return MEFALSE;
    c->stayingEnd++;
    return METRUE;
}

void McdModelPairContainerInit(McdModelPairContainer *c, McdModelPair **array, int size)
{
    ME_CHECK_NOT_NULL(c, ME_NOTHING);
    if (size < 0 || (size > 0 && !array)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "size (%d) must be >= 0 with an array of that many entries; call ignored",
                  size);
        return;
    }
    c->array = array;
    c->size = size;
    McdModelPairContainerReset(c);
}

void McdModelPairContainerRemovePair(McdModelPairContainer *c, McdModelPairID *entry)
{
    ME_CHECK_NOT_NULL(c, ME_NOTHING);
    ME_CHECK_NOT_NULL(entry, ME_NOTHING);
    ptrdiff_t at = entry - c->array;
    if (at < c->goodbyeFirst || at >= c->stayingEnd) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "the entry is not one of the container's pairs; call ignored");
        return;
    }
    /* Close the gap, keeping the order of every range; the ranges after it move down by one. */
    memmove(&c->array[at], &c->array[at + 1], (size_t)(c->stayingEnd - at - 1) * sizeof *c->array);
    if (at < c->goodbyeEnd)
        c->goodbyeEnd--;
    if (at < c->helloFirst)
        c->helloFirst--;
    if (at < c->helloEndStayingFirst)
        c->helloEndStayingFirst--;
    c->stayingEnd--;
}

void McdModelPairContainerPrintStats(McdModelPairContainer *c)
{
    ME_CHECK_NOT_NULL(c, ME_NOTHING);
    MeInfo(0, "McdModelPairContainer (size %d): %d hello, %d staying, %d goodbye", c->size,
           McdModelPairContainerGetHelloCount(c), McdModelPairContainerGetStayingCount(c),
           McdModelPairContainerGetGoodbyeCount(c));
}

void McdPairContainerPrintStats(McdModelPairContainer *c) { McdModelPairContainerPrintStats(c); }

void McdModelPairContainerIteratorInit(McdModelPairContainerIterator *iter, McdModelPairContainer *c)
{
    ME_CHECK_NOT_NULL(iter, ME_NOTHING);
    ME_CHECK_NOT_NULL(c, ME_NOTHING);
    iter->container = c;
    iter->count = c->helloFirst;
}
