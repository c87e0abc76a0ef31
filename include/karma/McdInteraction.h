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

#include "McdSafeTimeResult.h"
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
/** Conservative time of impact (Karma 1.2): result->time is the largest time in [0, maxTime] (s) up to
 *  which the models, moving from the transforms they follow now at their velocities (as
 *  McdIntersectAt; a NULL velocity pointer is at rest), provably do not touch; 0 when they touch now,
 *  maxTime when they do not meet. Never later than the true time of impact; at the time returned the
 *  models are at most MCD_SAFE_TIME_GAP times the framework's lengthScale apart (unless 256 advances
 *  do not get there, as a fast spin grazing past may need: the time is then earlier, still safe). Closed forms for
 *  sphere-sphere and sphere-plane, conservative advancement on GJK distances for every other pair of
 *  convex shapes (primitives, convex meshes), shape-plane and shape-terrain (triangle lists, meshes,
 *  height fields). Returns METRUE when the pair's types have a method; MEFALSE (time = maxTime) for
 *  the others (aggregates, user types, two static shapes). NULL pair or result: ME_ERR_NULL_ARGUMENT;
 *  maxTime negative or not finite: ME_ERR_MCD_SAFE_TIME_RANGE; a velocity not finite:
 *  ME_ERR_MCD_SAFE_TIME_VELOCITY; both return MEFALSE and leave result unchanged. */
ME_API MeBool McdSafeTime(McdModelPairID pair, MeReal maxTime, McdSafeTimeResult *result);
/** Distance (times lengthScale) the models may still be apart at the time McdSafeTime returns. */
#define MCD_SAFE_TIME_GAP ME_R(1e-4)
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
