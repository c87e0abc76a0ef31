/* MdtLOD.h -- matrix capping: a bound on the rows of each partition's LCP.
 *
 * The solver's cost grows with the rows of a partition (about rows³ on the direct path), so Karma
 * lets an application cap them: MdtWorldSetMaxMatrixSize(w, n). In every partition with more than n
 * rows, contact rows are dropped for this step, least important first, in three phases:
 *
 *   1. friction rows (the contact stays, frictionless),
 *   2. whole contacts,
 *   3. nothing more: joint rows are never dropped, and every contact group (and stand-alone contact)
 *      keeps at least one contact, so a partition may stay above the cap.
 *
 * Importance orders the contacts. By default it is computed from MdtLODParams:
 *
 *   importance = penetrationBias · penetration / lengthScale
 *              + normVelBias · approach speed / lengthScale   (per second; 0 when separating)
 *              + toWorldBonus    if the contact is with the world (body 1 NULL)
 *              + nonAutoBonus    if neither body was woken by the partitioner in this step
 *              − rowCountBias · (rows of the contact's group) / (rows of the partition)
 *              + the contact's own MdtContactSetImportance value
 *              + zeroRowBonus    for each group's most important contact (the one never dropped)
 *
 * With the defaults this drops friction first, then body–body contacts, then body–world contacts,
 * shallowest first (Karma's order) for any penetration below ~6 lengthScales and approach speed below
 * ~15 lengthScales per second. MdtWorldSetContactImportanceCB replaces the whole formula (decision D8).
 * Ties are broken by the constraint pool slot, so capping is deterministic. Capping is off by default
 * (MDT_MATRIX_SIZE_UNCAPPED). MdtWorldGetCounters and MdtWorldGetPartitionInfo report what was dropped;
 * MdtConstraintGetRowCount of a dropped contact is 0 for that step. */
#ifndef MDT_LOD_H
#define MDT_LOD_H

#include <limits.h>

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** MdtWorldGetMaxMatrixSize when capping is off (the default): no partition is ever capped. */
#define MDT_MATRIX_SIZE_UNCAPPED INT_MAX

/** Weights of the default contact importance (see the top of this file). */
typedef struct MdtLODParams {
    MeReal frictionRatio;   /**< share (0...1) of a capped partition's friction contacts, the most
                                 important, whose friction is dropped only with the contact; default 0 */
    MeReal zeroRowBonus;    /**< bonus of each group's most important contact; default 150 */
    MeReal toWorldBonus;    /**< bonus of contacts with the world; default 100 */
    MeReal rowCountBias;    /**< penalty per share of the partition's rows in the contact's group; default 40 */
    MeReal penetrationBias; /**< per lengthScale of penetration; default 15 */
    MeReal normVelBias;     /**< per lengthScale/s of approach speed; default 6.5 */
    MeReal nonAutoBonus;    /**< bonus when no body of the contact was woken by the partitioner; default 40 */
} MdtLODParams;

/** Importance of one contact (larger is kept longer). Called in the LOD stage for each contact of each
 *  partition that exceeds the cap; the world is locked (no creation or destruction). */
typedef MeReal (*MdtContactImportanceCBPtr)(MdtContactID contact, void *userData);

/** Cap the rows of each partition's LCP at `size` (≥ 1), or MDT_MATRIX_SIZE_UNCAPPED for no cap. */
ME_API void MdtWorldSetMaxMatrixSize(MdtWorldID w, int size);
/** The row cap of each partition's LCP, or MDT_MATRIX_SIZE_UNCAPPED (also for a bad ID). */
ME_API int MdtWorldGetMaxMatrixSize(MdtWorldID w);
/** Copy the world's LOD weights out / in (all finite; frictionRatio in [0, 1]). */
ME_API void MdtWorldGetLODParams(MdtWorldID w, MdtLODParams *params);
/** Copy LOD weights into the world; NULL, NaN or infinite weights, frictionRatio outside [0, 1] refused. */
ME_API void MdtWorldSetLODParams(MdtWorldID w, const MdtLODParams *params);
/** Karma's default weights. */
ME_API void MdtLODParamsSetDefaults(MdtLODParams *params);
/** Replace the importance formula by `cb` (NULL restores the formula). */
ME_API void MdtWorldSetContactImportanceCB(MdtWorldID w, MdtContactImportanceCBPtr cb, void *userData);

ME_EXTERN_C_END

#endif /* MDT_LOD_H */
