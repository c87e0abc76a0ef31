/* MdtPartition.h -- Karma 1.2's header for the partitions of a step (islands of bodies joined by
 * constraints). Here they are read through the world between the stages of MdtMainLoop.h
 * (MdtWorldGetPartitionCount, MdtWorldGetPartitionInfo, MdtWorldGetPartitionBody); the world owns
 * its partition lists, so 1.2's MdtPartitionOutput and its functions do not exist (decision K16). */
#ifndef MDT_PARTITION_H
#define MDT_PARTITION_H

#include "MdtLOD.h"
#include "MdtMainLoop.h"
#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** The settings the partitioner's end-of-partition test uses, in Karma 1.2's layout: auto-disable
 *  thresholds (squared magnitudes, as MdtWorldSetAutoDisable...Threshold), the alive window, matrix
 *  capping and debug drawing. MdtWorldGetPartitionParams fills one from a world; MdtBodyIsMovingTest
 *  reads the thresholds. */
struct MdtPartitionParams {
    MeBool autoDisable;          /**< whether partitions at rest are disabled */
    MeReal vel_thresh;           /**< squared speed, m²/s² */
    MeReal velrot_thresh;        /**< squared angular speed, rad²/s² */
    MeReal acc_thresh;           /**< squared acceleration, m²/s⁴ */
    MeReal accrot_thresh;        /**< squared angular acceleration, rad²/s⁴ */
    MeReal alive_time_thresh;    /**< seconds a body stays enabled before it may be disabled */
    int maxMatrixSize;           /**< MdtWorldGetMaxMatrixSize */
    MdtLODParams lodParams;      /**< MdtWorldGetLODParams */
    MdtDebugDrawOptions debugOptions; /**< MdtWorldSetDebugDrawing */
};

/** Copy a world's partition settings into `params` (this library's addition: 1.2 kept them inside
 *  its world struct). */
ME_API void MdtWorldGetPartitionParams(MdtWorldID w, MdtPartitionParams *params);

/** Zero every count of `info`. */
ME_API void MdtPartInfoReset(MdtPartitionInfo *info);
/** Add constraint `c` to the counts of `info`: its rows this step (upper bound) to rowCount, its
 *  contacts (a group's count, or 1 for a stand-alone contact) to contactCount, or 1 to jointCount;
 *  and 1 to constraints. The other fields are left alone. */
ME_API void MdtPartInfoAddConstraint(MdtPartitionInfo *info, MdtConstraintID c);

ME_EXTERN_C_END

#endif /* MDT_PARTITION_H */
