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

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

ME_API void McdHello(McdModelPairID pair);
/** Fill `result` (its contacts array and contactMaxCount set by the caller). Returns `touch`. */
ME_API int McdIntersect(McdModelPairID pair, McdIntersectResult *result);
ME_API void McdGoodbye(McdModelPairID pair);
/** Whether the two models' AABBs (of their last update) overlap. */
ME_API MeBool McdNearby(McdModelPairID pair);

ME_EXTERN_C_END

#endif /* MCD_INTERACTION_H */
