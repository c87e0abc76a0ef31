/* step.c -- MdtWorldStep and its stages as public functions (MdtMainLoop.h, docs/step.md).
 *
 *   MdtWorldStepBegin         check h, lock the world, start the profile frame
 *   MdtUpdatePartitions       islands of enabled bodies joined by constraints
 *   MdtAutoDisablePartitions  islands at rest go to sleep                           (optional)
 *   MdtLODPartitions          matrix capping                                        (optional)
 *   MdtPackAllPartitions      external forces → predicted velocities; constraints → solver rows
 *   MdtKeaAddConstraintForces the LCP for the constraint impulses, per island
 *   MdtKeaIntegrateSystem     velocities, then positions and orientations; state check
 *   MdtUnpackForces           constraint forces back into the constraints; accumulators cleared
 *   MdtWorldStepEnd           count the step, unlock
 *
 * MdtWorldStep runs exactly these, so a step written by the application from the public stages is
 * bit-identical to MdtWorldStep. A stage called out of order is refused: the partition lists hold
 * pointers that are only valid within the step that built them. */
#include <karma/MdtMainLoop.h>

#include "../me/check.h"
#include "world.h"

/* The stage a call needs the world to be in: at least `after`, and before `stage` itself. */
static MdtWorld *enterStage(MdtWorldID id, MdtStage stage, MdtStage after, const char *function)
{
    MdtWorld *w = MdtWorldFromID(id, function);
    if (!w)
        return NULL;
    if (w->stage < after || w->stage >= stage) {
        static const char *const names[] = {"MdtWorldStepBegin",        "MdtWorldStepBegin",
                                            "MdtUpdatePartitions",      "MdtAutoDisablePartitions",
                                            "MdtLODPartitions",         "MdtPackAllPartitions",
                                            "MdtKeaAddConstraintForces", "MdtKeaIntegrateSystem",
                                            "MdtUnpackForces"};
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "stage called out of order: it must follow %s%s in the same step; call ignored",
                     names[after], w->stage == MdtStageIdle ? " (no step has begun)" : "");
        return NULL;
    }
    return w;
}

static MeBool beginStep(MdtWorld *w, MeReal stepSize, const char *function)
{
    if (!(ME_IS_FINITE(stepSize) && stepSize > 0)) {
        ME_REPORT_IN(function, ME_ERR_STEP_SIZE, "argument 'stepSize' (%g) must be positive and finite; step skipped",
                     (double)stepSize);
        return MEFALSE;
    }
    if (w->locked) {
        ME_REPORT_IN(function, ME_ERR_WORLD_LOCKED, "the world is already stepping; %s refused", function);
        return MEFALSE;
    }
    w->locked = METRUE;
    w->stage = MdtStageBegun;
    w->stepSize = stepSize;
    w->droppedRows = w->cappedPartitions = w->simErrors = 0;
    MeProfileFrameStart(&w->profile);
    MeProfileStartSection(&w->profile, MDT_SECTION_STEP);
    return METRUE;
}

static void endStep(MdtWorld *w)
{
    MeProfileEndSection(&w->profile, MDT_SECTION_STEP);
    MeProfileFrameEnd(&w->profile);
    w->steps++;
    w->time += w->stepSize;
    w->stage = MdtStageIdle;
    w->locked = MEFALSE;
}

/* One stage, timed in its profile section. */
static void runStage(MdtWorld *w, void (*stage)(MdtWorld *), const char *section, MdtStage done)
{
    MeProfileStartSection(&w->profile, section);
    stage(w);
    MeProfileEndSection(&w->profile, section);
    w->stage = done;
}

void MdtWorldStepBegin(MdtWorldID id, MeReal stepSize)
{
    MdtWorld *w = MdtWorldFromID(id, __func__);
    if (w)
        beginStep(w, stepSize, __func__);
}

void MdtUpdatePartitions(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStagePartitioned, MdtStageBegun, __func__);
    if (w)
        runStage(w, MdtPartitionStage, MDT_SECTION_PARTITION, MdtStagePartitioned);
}

void MdtAutoDisablePartitions(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStageAutoDisabled, MdtStagePartitioned, __func__);
    if (w)
        runStage(w, MdtAutoDisableStage, MDT_SECTION_AUTODISABLE, MdtStageAutoDisabled);
}

void MdtLODPartitions(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStageCapped, MdtStagePartitioned, __func__);
    if (w)
        runStage(w, MdtLODStage, MDT_SECTION_LOD, MdtStageCapped);
}

void MdtPackAllPartitions(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStagePacked, MdtStagePartitioned, __func__);
    if (w)
        runStage(w, MdtPackStage, MDT_SECTION_PACK, MdtStagePacked);
}

void MdtKeaAddConstraintForces(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStageSolved, MdtStagePacked, __func__);
    if (w)
        runStage(w, MdtSolveStage, MDT_SECTION_SOLVE, MdtStageSolved);
}

void MdtKeaIntegrateSystem(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStageIntegrated, MdtStageSolved, __func__);
    if (w)
        runStage(w, MdtIntegrateStage, MDT_SECTION_INTEGRATE, MdtStageIntegrated);
}

void MdtUnpackForces(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, MdtStageUnpacked, MdtStageIntegrated, __func__);
    if (w)
        runStage(w, MdtUnpackStage, MDT_SECTION_UNPACK, MdtStageUnpacked);
}

void MdtWorldStepEnd(MdtWorldID id)
{
    MdtWorld *w = enterStage(id, (MdtStage)(MdtStageUnpacked + 1), MdtStageUnpacked, __func__);
    if (w)
        endStep(w);
}

void MdtWorldStep(MdtWorldID id, MeReal stepSize)
{
    MdtWorld *w = MdtWorldFromID(id, __func__);
    if (!w || !beginStep(w, stepSize, __func__))
        return;
    runStage(w, MdtPartitionStage, MDT_SECTION_PARTITION, MdtStagePartitioned);
    runStage(w, MdtAutoDisableStage, MDT_SECTION_AUTODISABLE, MdtStageAutoDisabled);
    runStage(w, MdtLODStage, MDT_SECTION_LOD, MdtStageCapped);
    runStage(w, MdtPackStage, MDT_SECTION_PACK, MdtStagePacked);
    runStage(w, MdtSolveStage, MDT_SECTION_SOLVE, MdtStageSolved);
    runStage(w, MdtIntegrateStage, MDT_SECTION_INTEGRATE, MdtStageIntegrated);
    runStage(w, MdtUnpackStage, MDT_SECTION_UNPACK, MdtStageUnpacked);
    endStep(w);
}

/* ---- partition queries -------------------------------------------------------------------- */
static MdtWorld *partitionWorld(MdtWorldID id, int partition, const char *function)
{
    MdtWorld *w = MdtWorldFromID(id, function);
    if (!w)
        return NULL;
    if (partition < 0 || partition >= w->partitions.partitionCount) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "argument 'partition' (%d) must lie in [0, %d)", partition,
                     w->partitions.partitionCount);
        return NULL;
    }
    return w;
}

int MdtWorldGetPartitionCount(MdtWorldID id)
{
    MdtWorld *w = MdtWorldFromID(id, __func__);
    return w ? w->partitions.partitionCount : 0;
}

void MdtWorldGetPartitionInfo(MdtWorldID id, int partition, MdtPartitionInfo *info)
{
    ME_CHECK_NOT_NULL(info, ME_NOTHING);
    info->bodies = info->constraints = info->rows = info->droppedRows = 0;
    MdtWorld *w = partitionWorld(id, partition, __func__);
    if (!w)
        return;
    const MdtPartitionOutput *out = &w->partitions;
    info->bodies = out->partitionStart[partition + 1] - out->partitionStart[partition];
    info->constraints = out->constraintStart[partition + 1] - out->constraintStart[partition];
    info->droppedRows = out->droppedRows[partition];
    if (w->rowsPacked)
        info->rows = w->rows.partitionRowStart[partition + 1] - w->rows.partitionRowStart[partition];
}

MdtBodyID MdtWorldGetPartitionBody(MdtWorldID id, int partition, int index)
{
    MdtWorld *w = partitionWorld(id, partition, __func__);
    if (!w)
        return NULL;
    const MdtPartitionOutput *out = &w->partitions;
    int count = out->partitionStart[partition + 1] - out->partitionStart[partition];
    if (index < 0 || index >= count) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'index' (%d) must lie in [0, %d)", index, count);
        return NULL;
    }
    return (MdtBodyID)out->bodies[out->partitionStart[partition] + index]->id;
}
