/* McdBatch.h -- Karma 1.2's batched intersection of a pair container (what 1.2's bridge used).
 *
 * McdBatchIntersectEach tests the container's hello and staying pairs in order, one result per pair
 * (pairs of two frozen models are skipped, as in 1.2), each pair's contacts packed into contactArray
 * up to its request's contactMaxCount. Each call first sets *resultCount and *contactCount to 0, fills
 * the arrays as far as they go and returns 1 when every pair is done, 0 when pairs remain: handle the
 * results and call again with the same context and container. McdBatchContextReset starts the next
 * container from its first pair. (1.2 also flattened aggregates and grouped tests by type; here an
 * aggregate's pair test recurses itself, and the results come in the container's order either way.) */
#ifndef MCD_BATCH_H
#define MCD_BATCH_H

#include "McdCTypes.h"
#include "McdSpace.h"

ME_EXTERN_C_BEGIN

/** A batch context (opaque here; 1.2 published its internals). */
typedef struct McdBatchContext McdBatchContext;

/** A context for the framework's pairs; NULL (reported) for a bad framework or no memory. */
ME_API McdBatchContext *MEAPI McdBatchContextCreate(McdFramework *frame);
/** Forget any pass under way: the next McdBatchIntersectEach starts at the container's first pair. */
ME_API void MEAPI McdBatchContextReset(McdBatchContext *context);
/** Free a context made by McdBatchContextCreate; NULL refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MEAPI McdBatchContextDestroy(McdBatchContext *context);
/** Test the pairs (see above). Returns 1 when done, 0 when called again is needed. */
ME_API MeBool MEAPI McdBatchIntersectEach(McdBatchContext *context, McdModelPairContainer *pairs,
                                          McdIntersectResult *resultArray, int *resultCount, int resultMaxCount,
                                          McdContact *contactArray, int *contactCount, int contactMaxCount);
/** Declared by 1.2 and never defined there: here, as McdBatchContextReset. */
ME_API void MEAPI McdBatchContextRelease(McdBatchContext *context);

ME_EXTERN_C_END

#endif /* MCD_BATCH_H */
