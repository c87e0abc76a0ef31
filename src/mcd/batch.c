/* batch.c -- Karma 1.2's batched intersection (McdBatch.h): McdIntersect over a container's hello and
 * staying pairs, resumable when the caller's arrays fill up. */
#include <karma/McdBatch.h>
#include <karma/McdInteraction.h>
#include <karma/McdModelPair.h>
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "framework.h"

struct McdBatchContext {
    McdFrameworkID framework;
    const McdModelPairContainer *pairs; /* the container of the pass under way, or NULL */
    int next;                           /* its next entry */
};

McdBatchContext *MEAPI McdBatchContextCreate(McdFramework *frame)
{
    if (!McdFrameworkFromID(frame, __func__))
        return NULL;
    McdBatchContext *context = MeMemoryCreateZeroed(sizeof *context);
    if (!context) {
        ME_REPORT(ME_ERR_OUT_OF_MEMORY, "no memory for a batch context");
        return NULL;
    }
    context->framework = frame;
    return context;
}

void MEAPI McdBatchContextReset(McdBatchContext *context)
{
    ME_CHECK_NOT_NULL(context, ME_NOTHING);
    context->pairs = NULL;
    context->next = 0;
}

void MEAPI McdBatchContextRelease(McdBatchContext *context)
{
    ME_CHECK_NOT_NULL(context, ME_NOTHING);
    McdBatchContextReset(context);
}

void MEAPI McdBatchContextDestroy(McdBatchContext *context)
{
    ME_CHECK_NOT_NULL(context, ME_NOTHING);
    MeMemoryDestroy(context);
}

/* Both models frozen (a pair of sleeping models): 1.2's batch does not test it. */
static MeBool bothFrozen(const McdModelPair *pair)
{
    McdModelData *m1 = McdModelFromID(pair->model1, "McdBatchIntersectEach");
    McdModelData *m2 = McdModelFromID(pair->model2, "McdBatchIntersectEach");
    return m1 && m2 && m1->frozen && m2->frozen;
}

/* Size: Karma 1.2's signature. */
MeBool MEAPI McdBatchIntersectEach(McdBatchContext *context, McdModelPairContainer *pairs,
                                   McdIntersectResult *resultArray, int *resultCount, int resultMaxCount,
                                   McdContact *contactArray, int *contactCount, int contactMaxCount)
{
    ME_CHECK_NOT_NULL(context, 1);
    ME_CHECK_NOT_NULL(pairs, 1);
    ME_CHECK_NOT_NULL(resultCount, 1);
    ME_CHECK_NOT_NULL(contactCount, 1);
    *resultCount = *contactCount = 0;
    if ((resultMaxCount > 0 && !resultArray) || (contactMaxCount > 0 && !contactArray)) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "a result or contact array is NULL for a size above 0; call ignored");
        return 1;
    }
    if (context->pairs != pairs) { /* a new pass */
        context->pairs = pairs;
        context->next = pairs->helloFirst;
    }
    while (context->next < pairs->stayingEnd) {
        McdModelPair *pair = pairs->array[context->next];
        if (bothFrozen(pair)) {
            context->next++;
            continue;
        }
        const McdRequest *request = McdModelPairGetRequestPtr(pair);
        int want = request ? request->contactMaxCount : 0;
        if (*resultCount == resultMaxCount || *contactCount + want > contactMaxCount) {
            if (*resultCount > 0)
                return 0; /* call again with emptied arrays */
            ME_REPORT(ME_ERR_ARGUMENT_RANGE,
                      "the arrays (%d results, %d contacts) cannot hold one pair wanting %d contacts; the pass is "
                      "abandoned",
                      resultMaxCount, contactMaxCount, want);
            McdBatchContextReset(context);
            return 1;
        }
        McdIntersectResult *r = &resultArray[*resultCount];
        r->contacts = contactArray + *contactCount;
        r->contactMaxCount = want;
        McdIntersect(pair, r);
        *contactCount += r->contactCount;
        (*resultCount)++;
        context->next++;
    }
    McdBatchContextReset(context); /* done: the next call starts a new pass */
    return 1;
}
