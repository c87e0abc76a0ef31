/* McdModelPairManager.h -- Karma 1.2's pair manager: the life cycle of model pairs kept apart from a
 * space, for an application's own farfield.
 *
 * The application activates the pairs it finds overlapping and deactivates those that stop; the
 * manager keeps each pair (McdModelPair, stable while it lives) in one state: Hello (activated since
 * the last flush), Staying, Goodbye (deactivated since the last flush). McdModelPairManagerGetPairs
 * and ...GetTransitions hand them out in a container as the space does (goodbyes, hellos, stayings,
 * each in the manager's slot order); McdModelPairManagerFlush then makes hellos staying and forgets
 * goodbyes. A pair deactivated while still Hello is forgotten at once (its McdHello, if any, is
 * undone); a Goodbye pair activated again before the flush stays. (a, b) and (b, a) are one pair. */
#ifndef MCD_MODEL_PAIR_MANAGER_H
#define MCD_MODEL_PAIR_MANAGER_H

#include "McdCTypes.h"
#include "McdSpace.h"

ME_EXTERN_C_BEGIN

/** A pair manager (opaque here; 1.2 published its internals). */
typedef struct McdModelPairManager McdModelPairManager;
typedef McdModelPairManager *McdModelPairManagerID;

/** A manager with room for `size` (> 0) pairs; NULL (reported) on a bad size or no memory. */
ME_API McdModelPairManagerID MEAPI McdModelPairManagerCreate(int size);
/** Free the manager and its tables (NULL: nothing done); the pairs' models are not touched. */
ME_API void MEAPI McdModelPairManagerDestroy(McdModelPairManager *manager);
/** Activate the pair of two live models. Returns non-zero when it was active already. When the
 *  manager is full the pool-full handler is called for the models and ME_ERR_POOL_FULL reported. */
ME_API MeBool MEAPI McdModelPairManagerActivate(McdModelPairManagerID manager, McdModelID model1, McdModelID model2);
/** Deactivate the pair. Returns zero when it was not active. */
ME_API MeBool MEAPI McdModelPairManagerDeactivate(McdModelPairManagerID manager, McdModelID model1,
                                                  McdModelID model2);
/** The pair of two models (either order) while the manager holds it, else NULL. */
ME_API McdModelPairID MEAPI McdModelPairManagerGetPair(McdModelPairManagerID manager, McdModelID m1, McdModelID m2);
/** Hello pairs become staying; goodbye pairs are forgotten. */
ME_API void MEAPI McdModelPairManagerFlush(McdModelPairManagerID manager);
/** Start `iterator` at the first pair. */
ME_API void MEAPI McdModelPairManagerResetIterator(McdModelPairManagerID manager, McdSpacePairIterator *iterator);
/** Reset `container` and fill it with the next goodbye and hello pairs. Returns non-zero when more
 *  remain (call again once the container's pairs are handled). */
ME_API MeBool MEAPI McdModelPairManagerGetTransitions(McdModelPairManagerID manager, McdSpacePairIterator *iterator,
                                                      McdModelPairContainer *container);
/** As McdModelPairManagerGetTransitions, with the staying pairs too. */
ME_API MeBool MEAPI McdModelPairManagerGetPairs(McdModelPairManagerID manager, McdSpacePairIterator *iterator,
                                                McdModelPairContainer *container);
/** Pairs held now (hello, staying and goodbye). */
ME_API int MEAPI McdModelPairManagerGetSize(McdModelPairManagerID manager);
/** Called for each pair that a full manager could not activate (NULL: none). */
ME_API void MEAPI McdModelPairManagerSetPoolFullHandler(McdModelPairManagerID manager, McdSpacePoolErrorFnPtr handler);
/** The handler of McdModelPairManagerSetPoolFullHandler, or NULL; NULL manager refused. */
ME_API McdSpacePoolErrorFnPtr MEAPI McdModelPairManagerGetPoolFullHandler(McdModelPairManagerID manager);

ME_EXTERN_C_END

#endif /* MCD_MODEL_PAIR_MANAGER_H */
