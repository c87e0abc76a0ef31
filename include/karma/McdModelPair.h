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
/** The pair's two models. */
ME_API void McdModelPairGetModels(McdModelPairID pair, McdModelID *model1, McdModelID *model2);
/** Type names of the two models' geometries (for messages). */
ME_API void McdModelPairGetGeometryNames(McdModelPairID pair, const char **name1, const char **name2);
/** The request the pair's tests use: the one set, else the framework's default request. */
ME_API McdRequest *McdModelPairGetRequestPtr(const McdModelPairID pair);
/** Use `request` (the caller's; NULL: the framework's default) for this pair. */
ME_API void McdModelPairSetRequestPtr(McdModelPairID pair, McdRequest *request);
/** What a collision-response layer (a bridge) reads of a pair's two models each step before testing
 *  it, in the order model1, model2 (McdModelPairGetModelInfo). */
typedef struct McdModelPairModelInfo {
    void *bodyData[2];  /**< each model's McdModelGetBodyData (the bridge's MdtBodyID), or NULL */
    int material[2];    /**< each model's McdModelGetMaterial */
    MeBool frozen[2];   /**< each model's McdSpaceModelIsFrozen */
} McdModelPairModelInfo;
/** Fill `info` from the pair's two models with one handle check each (the per-field getters would
 *  take three); MEFALSE with `info` zeroed when a model ID is invalid (reported) or an argument NULL. */
ME_API MeBool McdModelPairGetModelInfo(McdModelPairID pair, McdModelPairModelInfo *info);
/** A dynamics bridge's per-pair step with one handle check per model: McdModelPairGetModelInfo, then
 *  McdIntersect (result->contacts and contactMaxCount set by the caller) unless both models are frozen
 *  or neither has body data (two pieces of the world); returns whether the pair was tested (an
 *  untested pair's result holds no contacts). Invalid models or NULL arguments: reported, MEFALSE,
 *  `info` zeroed. */
ME_API MeBool McdIntersectForResponse(McdModelPairID pair, McdModelPairModelInfo *info, McdIntersectResult *result);
/** The application's pointer for the pair (the bridge keeps its contact group here). */
ME_API void *McdModelPairGetUserData(McdModelPairID pair);
/** Attach an application pointer to the pair (not owned by Mcd); NULL pair refused. */
ME_API void McdModelPairSetUserData(McdModelPairID pair, void *data);

ME_EXTERN_C_END

#endif /* MCD_MODEL_PAIR_H */
