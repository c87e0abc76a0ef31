/* MdtMainLoop.h -- the stages of MdtWorldStep, callable one by one (Karma's "main-loop pieces").
 *
 * MdtWorldStep(w, h) is exactly
 *
 *     MdtWorldStepBegin(w, h);
 *     MdtWorldUpdatePartitions(w);    islands of enabled bodies joined by constraints
 *     MdtAutoDisablePartitions(w);    islands at rest go to sleep                    (optional)
 *     MdtLODPartitions(w);            matrix capping (MdtWorldSetMaxMatrixSize)      (optional)
 *     MdtPack(w);                     external forces -> predicted velocities; constraints -> rows
 *     MdtKeaSolve(w);                 the LCP of each partition (Kea)
 *     MdtKeaIntegrate(w);             velocities, then positions; NaN/inf containment
 *     MdtUnpack(w);                   constraint forces for the application; accumulators cleared
 *     MdtWorldStepEnd(w);
 *
 * so an application can write its own step: inspect the partitions between stages
 * (MdtWorldGetPartitionCount / MdtWorldGetPartitionInfo), skip the optional ones, time them its own
 * way. The stages must come in this order (the two optional ones may be left out); a stage called
 * out of order is refused with ME_ERR_BAD_STATE and does nothing. Between Begin and End the world is
 * locked as during MdtWorldStep: bodies and constraints cannot be created or destroyed. Each stage is
 * a section of the world's profile, as in MdtWorldStep.
 *
 * Karma 1.2's headers declared per-partition stages on Kea's arrays (MdtUpdatePartitions,
 * MdtPackAllPartitions(po, ...), MdtKeaAddConstraintForces(constraints, ...), MdtUnpackForces(force,
 * partition, po)...); here each stage runs over all partitions of the step (decisions D7, K16), so the
 * stages take the User Guide's names (MdtWorldUpdatePartitions, MdtPack, MdtKeaSolve, MdtKeaIntegrate)
 * and a 1.2 call to the header names fails to compile instead of misbehaving (docs/api_changes.md). */
#ifndef MDT_MAIN_LOOP_H
#define MDT_MAIN_LOOP_H

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** Start a step of `stepSize` seconds (> 0, finite): checks it, locks the world, starts the
 *  profile's frame. Refused (ME_ERR_STEP_SIZE, ME_ERR_WORLD_LOCKED) like MdtWorldStep. */
ME_API void MdtWorldStepBegin(MdtWorldID w, MeReal stepSize);
/** Find the partitions: enabled bodies joined by enabled constraints; disabled bodies reached
 *  through a constraint are enabled ("enabled by partitioner"). */
ME_API void MdtWorldUpdatePartitions(MdtWorldID w);
/** Disable the partitions whose bodies are all at rest (auto-disable thresholds, alive window). */
ME_API void MdtAutoDisablePartitions(MdtWorldID w);
/** Matrix capping: in each partition with more rows than MdtWorldGetMaxMatrixSize, drop contact rows
 *  (see MdtLOD.h). Does nothing when capping is off. */
ME_API void MdtLODPartitions(MdtWorldID w);
/** Predict the velocities under external forces and write every constraint's solver rows. */
ME_API void MdtPack(MdtWorldID w);
/** Solve each partition's LCP for the constraint impulses (the world's solver settings). */
ME_API void MdtKeaSolve(MdtWorldID w);
/** Integrate velocities and positions; a partition whose solve or state is not finite is restored,
 *  stopped, disabled and reported (MdtWorldSetSimErrorHandler). */
ME_API void MdtKeaIntegrate(MdtWorldID w);
/** Write each constraint's force and torque (MdtConstraintGetForce) and keep its impulses for warm
 *  starting; clear the accumulators of the simulated bodies. */
ME_API void MdtUnpack(MdtWorldID w);
/** End the step: counts it, adds its time, unlocks the world. */
ME_API void MdtWorldStepEnd(MdtWorldID w);

/** What the last MdtWorldUpdatePartitions found, as later stages left it. The first three fields are
 *  Karma 1.2's (also filled by MdtPartInfoReset / MdtPartInfoAddConstraint, MdtPartition.h); the
 *  others are this library's. */
struct MdtPartitionInfo {
    int rowCount;     /**< rows the partition's constraints may write this step (an upper bound: a
                           contact group counts its contacts' rows) */
    int contactCount; /**< contacts: those of its contact groups and its stand-alone contacts */
    int jointCount;   /**< the other constraints */
    int bodies;       /**< bodies in the partition */
    int constraints;  /**< enabled constraints (a contact group counts once) */
    int rows;         /**< solver rows (after MdtPack; 0 before) */
    int droppedRows;  /**< rows removed by matrix capping (MdtLODPartitions) */
};
/** Partitions of the current or last step (after auto-disable has removed the sleeping ones). */
ME_API int MdtWorldGetPartitionCount(MdtWorldID w);
/** Counts of partition `partition` (0 ... count−1); zeros and ME_ERR_ARGUMENT_RANGE otherwise. */
ME_API void MdtWorldGetPartitionInfo(MdtWorldID w, int partition, MdtPartitionInfo *info);
/** Body `index` of a partition, in solver order; NULL (reported) when out of range. */
ME_API MdtBodyID MdtWorldGetPartitionBody(MdtWorldID w, int partition, int index);

/* The User Guide's name for the auto-disable stage (decision D7). */
#define MdtAutoDisable(w) MdtAutoDisablePartitions(w)

ME_EXTERN_C_END

#endif /* MDT_MAIN_LOOP_H */
