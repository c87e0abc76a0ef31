/* McdLineSegment.h -- line segment queries against one model.
 *
 * The first entry point of the segment p0 -> p1 into the model's geometry (placed by the model's last
 * update). When p0 is already inside, the hit is p0 itself at distance 0 (Karma's rule) and the
 * normal is minus the segment's direction. Planes are solid below (z <= 0 locally). The space's
 * queries (McdSpaceGetLineSegFirstIntersection...) build on this. */
#ifndef MCD_LINE_SEGMENT_H
#define MCD_LINE_SEGMENT_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef struct McdLineSegIntersectResult {
    McdModelID model;  /**< the model hit */
    MeVector3 position; /**< world point of entry */
    MeVector3 normal;   /**< outward unit surface normal there (world) */
    MeReal distance;    /**< from p0 to position */
} McdLineSegIntersectResult;

/** A per-type segment test (Karma's McdFrameworkSetLineSegInteraction): non-zero and `outOverlap`
 *  filled when the world segment inOrig -> inDest meets the model. */
typedef int (*McdLineSegIntersectFnPtr)(const McdModelID cm, MeReal *const inOrig, MeReal *const inDest,
                                        McdLineSegIntersectResult *outOverlap);

/** Returns 1 and fills `result` when the segment meets the model, else 0. */
ME_API int McdLineSegIntersect(McdModelID m, const MeVector3 p0, const MeVector3 p1, McdLineSegIntersectResult *result);

ME_EXTERN_C_END

#endif /* MCD_LINE_SEGMENT_H */
