/* pairs.c -- model pairs and the nearfield entry points: McdHello, McdIntersect, McdGoodbye.
 *
 * Pair tests are registered one way round (framework.c); McdHello looks the pair's geometry types up
 * both ways and remembers in `swapped` that the test takes model 2 first. McdIntersect then calls
 * the test in its own order and turns the answer back: normals negated, elements exchanged, so the
 * caller always sees normals from model 2 towards model 1. */
#include <string.h>

#include <karma/McdInteraction.h>
#include <karma/McdModel.h>
#include <karma/McdModelPair.h>
#include <karma/McdSpace.h>
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "framework.h"
#include "nearfield/nearfield.h"
#include "aggregate/aggregate.h"

McdModelPairID McdModelPairCreate(McdModelID model1, McdModelID model2)
{
    McdModelData *m1 = McdModelFromID(model1, __func__), *m2 = McdModelFromID(model2, __func__);
    if (!m1 || !m2)
        return NULL;
    if (m1->framework != m2->framework) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "the two models belong to different frameworks; call ignored");
        return NULL;
    }
    McdModelPair *pair = MeMemoryCreateZeroed(sizeof *pair);
    if (!pair)
        return NULL;
    McdModelPairReset(pair, model1, model2);
    pair->id = m1->framework->nextPairId++;
    return pair;
}

void McdModelPairDestroy(McdModelPairID pair)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    MeMemoryDestroy(pair);
}

void McdModelPairReset(McdModelPairID pair, McdModelID model1, McdModelID model2)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    MeU32 id = pair->id;
    memset(pair, 0, sizeof *pair);
    pair->model1 = model1;
    pair->model2 = model2;
    pair->testIndex = -1;
    pair->id = id;
}

/* Resolve both models of a pair in the caller's name. */
static MeBool pairModels(const McdModelPair *pair, McdModelData **m1, McdModelData **m2, const char *function)
{
    if (!pair) {
        MeReport(ME_ERR_NULL_ARGUMENT, function, __FILE__, __LINE__, "argument 'pair' is NULL; call ignored");
        return MEFALSE;
    }
    *m1 = McdModelFromID(pair->model1, function);
    *m2 = McdModelFromID(pair->model2, function);
    return *m1 && *m2;
}

void McdHelloInternal(McdModelPair *pair, McdModelData *m1, McdModelData *m2, const char *function)
{
    McdFrameworkData *fw = m1->framework;
    int t1 = m1->geometry->type, t2 = m2->geometry->type;
    pair->framework = McdFrameworkToID(fw);
    pair->cache = NULL;
    pair->swapped = 0;
    pair->testIndex = -1;
    if (McdFrameworkGetInteraction(fw, t1, t2)) {
        pair->testIndex = t1 * fw->typeCapacity + t2;
    } else if (McdFrameworkGetInteraction(fw, t2, t1)) {
        pair->testIndex = t2 * fw->typeCapacity + t1;
        pair->swapped = 1;
    } else if (t1 != kMcdGeometryTypeNull && t2 != kMcdGeometryTypeNull) {
        /* Null geometries touch nothing by design; any other missing test is worth one message. */
        int lo = t1 < t2 ? t1 : t2, hi = t1 < t2 ? t2 : t1;
        unsigned char *warned = &fw->warnedPairs[lo * fw->typeCapacity + hi];
        if (!*warned) {
            *warned = 1;
            MeReport(ME_ERR_MCD_NO_INTERACTION, function, __FILE__, __LINE__,
                     "no pair test is registered for %s and %s (McdPrimitivesRegisterInteractions?); such pairs "
                     "give no contacts",
                     fw->types[t1].typeName, fw->types[t2].typeName);
        }
    }
}

void McdHello(McdModelPairID pair)
{
    McdModelData *m1, *m2;
    if (!pairModels(pair, &m1, &m2, __func__))
        return;
    if (m1->framework != m2->framework) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "the pair's models belong to different frameworks; call ignored");
        return;
    }
    McdHelloInternal(pair, m1, m2, __func__);
    if (m1->framework->helloCallback) /* Karma's hook, e.g. McduHelloRequestTableCB */
        m1->framework->helloCallback(pair);
}

void McdGoodbyeInternal(McdModelPair *pair, McdModelData *m1)
{
    McdFrameworkData *fw = m1->framework;
    if (pair->cache && pair->testIndex >= 0 && fw->interactions[pair->testIndex].releaseCache)
        fw->interactions[pair->testIndex].releaseCache(pair->cache);
    pair->cache = NULL;
    pair->testIndex = -1;
    pair->swapped = 0;
}

void McdGoodbye(McdModelPairID pair)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    /* A goodbye pair may name models destroyed since they left their space (MstModelAndBodyDestroy
     * removes and destroys at once): legal, so not reported. The cache goes back through the
     * framework McdHello recorded; with that gone too (McdTerm freed it), only the fields are cleared. */
    McdFrameworkData *fw = McdFrameworkIsValid(pair->framework)
                               ? McdFrameworkFromID(pair->framework, __func__)
                               : NULL;
    if (fw && pair->cache && pair->testIndex >= 0 && fw->interactions[pair->testIndex].releaseCache)
        fw->interactions[pair->testIndex].releaseCache(pair->cache);
    pair->cache = NULL;
    pair->testIndex = -1;
    pair->swapped = 0;
}

/* The representative normal: the mean of the contact normals, or the deepest contact's normal when
 * they cancel out. */
static inline void representativeNormal(const McdContact *c, int count, MeVector3 normal)
{
    MeVector3 sum = {0, 0, 0};
    int deepest = 0;
    for (int i = 0; i < count; i++) {
        MeVector3Add(sum, sum, c[i].normal);
        if (c[i].separation < c[deepest].separation)
            deepest = i;
    }
    if (MeVector3NormalizeSafe(sum))
        MeVector3Copy(normal, sum);
    else
        MeVector3Copy(normal, c[deepest].normal);
}

/* For a pair test that overran its room: McdNfCallCentred checks the contacts of a count in range
 * (McdNfKeepPlausible), not these, so a contact with a non-finite value or a normal that is not of unit
 * length is dropped (and counted) here, and none reaches the bridge. */
static int dropInvalidContacts(McdFrameworkData *fw, McdContact *c, int n)
{
    int kept = 0;
    for (int i = 0; i < n; i++)
        if (McdNfContactIsValid(&c[i]))
            c[kept++] = c[i];
    if (kept < n)
        atomic_fetch_add(&fw->droppedContacts, (unsigned long)(n - kept));
    return kept;
}

static void clearResult(McdModelPair *pair, McdIntersectResult *result)
{
    result->pair = pair;
    result->contactCount = 0;
    result->touch = 0;
    result->data = NULL;
    MeVector3Set(result->normal, 0, 0, 0);
}

int McdIntersect(McdModelPairID pair, McdIntersectResult *result)
{
    ME_CHECK_NOT_NULL(result, 0);
    McdModelData *m1, *m2;
    if (!pairModels(pair, &m1, &m2, __func__)) {
        clearResult(pair, result);
        return 0;
    }
    return McdIntersectModels(pair, m1, m2, result, __func__); /* which clears the result first */
}

/* Resolve the pair's models and fill `info` from them, in `function`'s name; `info` zeroed when a
 * model is invalid. */
static MeBool modelInfo(const McdModelPair *pair, McdModelData **m, McdModelPairModelInfo *info, const char *function)
{
    if (!pairModels(pair, &m[0], &m[1], function)) {
        memset(info, 0, sizeof *info);
        return MEFALSE;
    }
    for (int i = 0; i < 2; i++) {
        info->bodyData[i] = m[i]->body;
        info->material[i] = m[i]->material;
        info->frozen[i] = m[i]->frozen;
    }
    return METRUE;
}

MeBool McdModelPairGetModelInfo(McdModelPairID pair, McdModelPairModelInfo *info)
{
    ME_CHECK_NOT_NULL(info, MEFALSE);
    McdModelData *m[2];
    return modelInfo(pair, m, info, __func__);
}

/* McdIntersectModels. Inlined into McdIntersectForResponse, which a bridge calls for every pair of
 * every step; gcc's heuristics decline it (it is long and has two callers), so it is asked by
 * attribute where the compiler has one. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int intersectModels(McdModelPair *pair, McdModelData *m1, McdModelData *m2, McdIntersectResult *result,
                                  const char *function)
{
    clearResult(pair, result);
    if (result->contactMaxCount > 0 && !result->contacts) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT,
                     "result->contacts is NULL but result->contactMaxCount is %d; call ignored",
                  result->contactMaxCount);
        return 0;
    }
    McdFrameworkData *fw = m1->framework;
    if (pair->testIndex < 0)
        return 0;
    const McdRequest *request = pair->request ? pair->request : &fw->defaultRequest;
    int maxCount = result->contactMaxCount;
    if (request->contactMaxCount < maxCount)
        maxCount = request->contactMaxCount;
    if (maxCount <= 0)
        return 0;
    McdNearfieldFn fn = fw->interactions[pair->testIndex].fn;
    if (!fn) /* unregistered since McdHello */
        return 0;
    MeReal tolerance = m1->contactTolerance + m2->contactTolerance;
    McdContact *c = result->contacts;
    McdNfTakeFallbacks(); /* the thread's fallbacks so far are not this test's (pair tests without a framework) */
    McdModelData *first = pair->swapped ? m2 : m1, *second = pair->swapped ? m1 : m2; /* the test's order */
    int n = McdNfCallCentred(fn, first->geometry, first->worldTransform, second->geometry, second->worldTransform,
                             tolerance, c, maxCount, &pair->cache);
    if (n < 0 || n > maxCount) {
        ME_REPORT_IN(function, ME_ERR_INTERNAL, "a pair test returned %d contacts for room for %d", n, maxCount);
        n = n < 0 ? 0 : dropInvalidContacts(fw, c, maxCount);
    }
    const unsigned long fallbacks = McdNfTakeFallbacks(); /* this thread's: this test's */
    if (fallbacks)
        atomic_fetch_add(&fw->pairFallbacks, fallbacks);
    if (pair->swapped)
        for (int i = 0; i < n; i++) {
            void *e = c[i].element1;
            MeVector3Scale(c[i].normal, -1);
            c[i].element1 = c[i].element2;
            c[i].element2 = e;
        }
    if (m1->geometry->type == kMcdGeometryTypeAggregate || m2->geometry->type == kMcdGeometryTypeAggregate)
        McdInstanceResolveTags(m1, m2, c, n); /* element path codes -> the models' child instances */
    result->contactCount = n;
    result->touch = n > 0;
    if (n > 0)
        representativeNormal(c, n, result->normal);
    /* Karma's per-model intersect callbacks see the finished result. */
    if (m1->intersectFn)
        m1->intersectFn((McdModel *)McdModelToID(m1), result);
    if (m2->intersectFn)
        m2->intersectFn((McdModel *)McdModelToID(m2), result);
    return result->touch;
}

int McdIntersectModels(McdModelPair *pair, McdModelData *m1, McdModelData *m2, McdIntersectResult *result,
                       const char *function)
{
    return intersectModels(pair, m1, m2, result, function);
}

MeBool McdIntersectForResponse(McdModelPairID pair, McdModelPairModelInfo *info, McdIntersectResult *result)
{
    ME_CHECK_NOT_NULL(info, MEFALSE);
    ME_CHECK_NOT_NULL(result, MEFALSE);
    McdModelData *m[2];
    if (!modelInfo(pair, m, info, __func__) || (info->frozen[0] && info->frozen[1]) ||
        (!info->bodyData[0] && !info->bodyData[1])) {
        clearResult(pair, result);
        return MEFALSE;
    }
    intersectModels(pair, m[0], m[1], result, __func__);
    return METRUE;
}

MeBool McdNearby(McdModelPairID pair)
{
    McdModelData *m1, *m2;
    if (!pairModels(pair, &m1, &m2, __func__))
        return MEFALSE;
    for (int j = 0; j < 3; j++)
        if (m1->aabbMax[j] < m2->aabbMin[j] || m2->aabbMax[j] < m1->aabbMin[j])
            return MEFALSE;
    return METRUE;
}

/* ---- Karma's pair accessors ------------------------------------------------------------------- */

void McdModelPairGetModels(McdModelPairID pair, McdModelID *model1, McdModelID *model2)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    if (model1)
        *model1 = pair->model1;
    if (model2)
        *model2 = pair->model2;
}

void McdModelPairGetGeometryNames(McdModelPairID pair, const char **name1, const char **name2)
{
    McdModelData *m1, *m2;
    ME_CHECK_NOT_NULL(name1, ME_NOTHING);
    ME_CHECK_NOT_NULL(name2, ME_NOTHING);
    *name1 = *name2 = NULL;
    if (!pairModels(pair, &m1, &m2, __func__))
        return;
    *name1 = McdGeometryTypeOf(m1->geometry)->typeName;
    *name2 = McdGeometryTypeOf(m2->geometry)->typeName;
}

McdRequest *McdModelPairGetRequestPtr(const McdModelPairID pair)
{
    ME_CHECK_NOT_NULL(pair, NULL);
    if (pair->request)
        return (McdRequest *)pair->request;
    McdModelData *m1 = McdModelFromID(pair->model1, __func__);
    return m1 ? m1->framework->defaultRequestPtr : NULL;
}

void McdModelPairSetRequestPtr(McdModelPairID pair, McdRequest *request)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    pair->request = request;
}

void *McdModelPairGetUserData(McdModelPairID pair)
{
    ME_CHECK_NOT_NULL(pair, NULL);
    return pair->userData;
}

void McdModelPairSetUserData(McdModelPairID pair, void *data)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    pair->userData = data;
}

/* ---- the ...Each helpers over a container ------------------------------------------------------ */

void McdHelloEach(McdModelPairContainer *pairs)
{
    ME_CHECK_NOT_NULL(pairs, ME_NOTHING);
    for (int i = pairs->helloFirst; i < pairs->helloEndStayingFirst; i++)
        McdHello(pairs->array[i]);
}

void McdGoodbyeEach(McdModelPairContainer *pairs)
{
    ME_CHECK_NOT_NULL(pairs, ME_NOTHING);
    for (int i = pairs->goodbyeFirst; i < pairs->goodbyeEnd; i++)
        McdGoodbye(pairs->array[i]);
}

/* Size: Karma 1.2's signature. */
MeBool McdIntersectEach(McdModelPairContainer *pairs, McdModelPairContainerIterator *iter,
                        McdIntersectResult *resultArray, int resultArraySize, int *resultCount,
                        McdContact *contactArray, int contactArraySize, int *contactCount)
{
    ME_CHECK_NOT_NULL(pairs, MEFALSE);
    ME_CHECK_NOT_NULL(iter, MEFALSE);
    ME_CHECK_NOT_NULL(resultCount, MEFALSE);
    ME_CHECK_NOT_NULL(contactCount, MEFALSE);
    *resultCount = *contactCount = 0;
    if ((resultArraySize > 0 && !resultArray) || (contactArraySize > 0 && !contactArray)) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "a result or contact array is NULL for a size above 0; call ignored");
        return MEFALSE;
    }
    if (iter->container != pairs) {
        ME_REPORT(ME_ERR_BAD_STATE, "the iterator was not initialised on this container "
                                    "(McdModelPairContainerIteratorInit); call ignored");
        return MEFALSE;
    }
    /* Hellos and stayings in container order; a pair is taken only when its request's contacts fit. */
    if (iter->count < pairs->helloFirst)
        iter->count = pairs->helloFirst;
    while (iter->count < pairs->stayingEnd) {
        McdModelPair *pair = pairs->array[iter->count];
        const McdRequest *request = McdModelPairGetRequestPtr(pair);
        int want = request ? request->contactMaxCount : 0;
        if (*resultCount == resultArraySize || *contactCount + want > contactArraySize)
            return METRUE; /* more pairs remain: call again */
        McdIntersectResult *r = &resultArray[*resultCount];
        r->contacts = contactArray + *contactCount;
        r->contactMaxCount = want;
        McdIntersect(pair, r);
        *contactCount += r->contactCount;
        (*resultCount)++;
        iter->count++;
    }
    return MEFALSE;
}
