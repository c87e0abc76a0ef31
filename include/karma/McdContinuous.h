/* McdContinuous.h -- continuous collision for fast models (additions to Karma 1.2).
 *
 * A model flagged with McdModelEnableContinuous is swept after each MstUniverseStep: when its body
 * went through another model of the space during the step, the body is put back where it first
 * came within half its contact tolerance of it (its velocity kept), and the contacts of the next
 * step stop or bounce it. Other models are taken at rest where they are after the step. Models
 * without the flag cost nothing. See docs/decisions.md (continuous collision) for the design. */
#ifndef MCD_CONTINUOUS_H
#define MCD_CONTINUOUS_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Sweep this model's body after each universe step (convex primitives and convex meshes only:
 *  others refused with ME_ERR_MCD_CONTINUOUS_GEOMETRY, no change). */
ME_API void McdModelEnableContinuous(McdModelID m);
/** Stop sweeping the model (the default). */
ME_API void McdModelDisableContinuous(McdModelID m);
/** Whether McdModelEnableContinuous is in force for the model (MEFALSE for an invalid ID, reported). */
ME_API MeBool McdModelIsContinuous(McdModelID m);
/** Models of the framework with the continuous flag (0 for an invalid ID, reported). */
ME_API int McdFrameworkGetContinuousModelCount(McdFrameworkID fw);
/** The first maxCount of them into models (in the order they were flagged, a model unflagged
 *  replaced by the last); returns how many there are. models may be NULL when maxCount is 0. */
ME_API int McdFrameworkGetContinuousModels(McdFrameworkID fw, McdModelID *models, int maxCount);
/** What McdSpaceSweepModel found. */
typedef struct McdSweepResult {
    MeReal time;      /**< s from the start: the first time of impact, or the duration when none */
    McdModelID model; /**< the model hit first, or NULL */
    MeVector3 normal; /**< unit, from the swept model towards the one hit, at the time */
    MeVector3 position; /**< the swept model's point nearest the one hit (deepest in it), world, m */
    MeBool touching;  /**< the two were within gap of each other already at the start */
} McdSweepResult;

/** Sweep `m` (in a space, convex) from its followed transform `start` at constant velocities v (m/s,
 *  of start's origin) and w (rad/s, about it) for `duration` s against the other models of its
 *  space (each at rest where it is; those whose AABB of the last update misses the path skipped, as
 *  are disabled pairs and models of the same body). Returns METRUE when m comes within `gap` (m) of
 *  another before the duration: result->time (s) is the conservative first such time. A model
 *  already within gap of another at the start hits it only when their signed distance (depth when
 *  overlapping) falls below -2 gap; a triangle of a terrain only when m's centre also approaches its
 *  plane by a quarter of m's inner radius (rolling and sliding across a mesh are not stopped).
 *  A model whose points all move less than half its inner radius in the duration is not swept (the
 *  contacts catch it). MEFALSE: result->time = duration, model NULL. Duration or gap negative or not finite:
 *  ME_ERR_MCD_SAFE_TIME_RANGE; start or velocities not finite: ME_ERR_MCD_SAFE_TIME_VELOCITY; both
 *  return MEFALSE and leave result unchanged. */
ME_API MeBool McdSpaceSweepModel(McdModelID m, MeMatrix4 start, const MeVector3 v, const MeVector3 w, MeReal duration,
                                 MeReal gap, McdSweepResult *result);

ME_EXTERN_C_END

#endif /* MCD_CONTINUOUS_H */
