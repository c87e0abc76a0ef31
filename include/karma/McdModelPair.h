/* McdModelPair.h -- model pairs made by the application (the space makes its own).
 *
 * A pair made here can be tested without a space: McdHello, McdIntersect, McdGoodbye
 * (McdInteraction.h). A McdModelPair may also live in the application's memory: McdModelPairReset
 * initialises it. */
#ifndef MCD_MODEL_PAIR_H
#define MCD_MODEL_PAIR_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** A pair of two models of the same framework (allocated through MeMemory), reset. */
ME_API McdModelPairID McdModelPairCreate(McdModelID model1, McdModelID model2);
/** Free a pair made by McdModelPairCreate (call McdGoodbye first if McdHello was called). */
ME_API void McdModelPairDestroy(McdModelPairID pair);
/** Set the models and clear everything else (request NULL, user data NULL, no test chosen). */
ME_API void McdModelPairReset(McdModelPairID pair, McdModelID model1, McdModelID model2);

ME_EXTERN_C_END

#endif /* MCD_MODEL_PAIR_H */
