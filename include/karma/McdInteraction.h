/* McdInteraction.h -- the nearfield entry points: hello, intersect, goodbye.
 *
 * McdHello chooses the pair test from the framework's interaction table (tests are registered one
 * way round; the pair remembers whether its models must be swapped). McdIntersect runs it on the
 * models' transforms of their last update and fills the caller's contact array: normals point from
 * model 2 towards model 1, separation < 0 means overlap, contacts up to the sum of the two contact
 * tolerances are reported. A pair of types with no test gives no contacts (reported once per type
 * pair). McdGoodbye releases the pair's cached data. */
#ifndef MCD_INTERACTION_H
#define MCD_INTERACTION_H

#include "McdSpace.h"
#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Prepare a new pair for McdIntersect (orders its models for the registered pair test); McdGoodbye
 *  releases what the test cached for the pair. */
ME_API void McdHello(McdModelPairID pair);
/** Fill `result` (its contacts array and contactMaxCount set by the caller). Returns `touch`. */
ME_API int McdIntersect(McdModelPairID pair, McdIntersectResult *result);
/** Release what McdHello set up for the pair (its test's cache); NULL refused (ME_ERR_NULL_ARGUMENT). */
ME_API void McdGoodbye(McdModelPairID pair);
/** McdIntersect with both models moved on by `time` at their velocities (McdModelSetLinearVelocityPtr,
 *  McdModelSetAngularVelocityPtr; a NULL pointer is at rest) from the transforms they follow now;
 *  their relative transforms apply. The models themselves are not moved. Returns `touch`. */
ME_API MeBool McdIntersectAt(McdModelPairID pair, McdIntersectResult *result, MeReal time);
/** Whether the two models' AABBs (of their last update) overlap. */
ME_API MeBool McdNearby(McdModelPairID pair);

/** Called by McdHello after the test is chosen (e.g. McduHelloRequestTableCB); NULL: none. */
ME_API void McdSetHelloCallback(McdFramework *fw, McdHelloCallbackFnPtr fn);
/** The callback set by McdSetHelloCallback, or NULL (also for an invalid framework, reported). */
ME_API McdHelloCallbackFnPtr McdGetHelloCallback(McdFramework *fw);
/** McdHello on each hello pair of the container, McdGoodbye on each goodbye pair. */
ME_API void McdHelloEach(McdModelPairContainer *pairs);
/** McdGoodbye on each goodbye pair of the container; NULL refused (ME_ERR_NULL_ARGUMENT). */
ME_API void McdGoodbyeEach(McdModelPairContainer *pairs);
/** McdIntersect on the container's hello and staying pairs from `pairsIter` on, one result each,
 *  their contacts packed into contactArray (each pair is given its request's contactMaxCount).
 *  Stops when either array is full: returns METRUE ("call again") when pairs remain. */
ME_API MeBool McdIntersectEach(McdModelPairContainer *pairs, McdModelPairContainerIterator *pairsIter,
                               McdIntersectResult *resultArray, int resultArraySize, int *resultCount,
                               McdContact *contactArray, int contactArraySize, int *contactCount);

ME_EXTERN_C_END

#endif /* MCD_INTERACTION_H */
