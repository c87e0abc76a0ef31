/* McdSafeTimeResult.h -- the result of McdSafeTime (Karma 1.2's struct: the pair and the time). */
#ifndef MCD_SAFE_TIME_RESULT_H
#define MCD_SAFE_TIME_RESULT_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** McdSafeTime's answer: until `time` (seconds from now, 0 ... maxTime) the pair's models, moving at
 *  their velocities, do not touch; maxTime when they do not meet within it. */
struct McdSafeTimeResult {
    McdModelPair *pair; /**< the pair asked about */
    MeReal time;        /**< conservative time of impact, s */
};

ME_EXTERN_C_END

#endif /* MCD_SAFE_TIME_RESULT_H */
