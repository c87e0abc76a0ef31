/* step.c -- MdtWorldStep and its stages as public functions (MdtMainLoop.h, docs/step.md).
 *
 *   MdtWorldStepBegin         check h, lock the world, start the profile frame
 *   MdtWorldUpdatePartitions  islands of enabled bodies joined by constraints
 *   MdtAutoDisablePartitions  islands at rest go to sleep                           (optional)
 *   MdtLODPartitions          matrix capping                                        (optional)
 *   MdtPack                   external forces → predicted velocities; constraints → solver rows
 *   MdtKeaSolve               the LCP for the constraint impulses, per island
 *   MdtKeaIntegrate           velocities, then positions and orientations; state check
 *   MdtUnpack                 constraint forces back into the constraints; accumulators cleared
 *   MdtWorldStepEnd           count the step, unlock
 *
 * MdtWorldStep runs exactly these, so a step written by the application from the public stages is
 * bit-identical to MdtWorldStep. A stage called out of order is refused: the partition lists hold
 * pointers that are only valid within the step that built them. */
#include <karma/MdtMainLoop.h>

#include <string.h>

#include "../me/check.h"
#include "../me/profile_at.h"
#include "world.h"

/* The stage a call needs the world to be in: at least `after`, and before `stage` itself. */
static MdtWorldData *enterStage(MdtWorldID id, MdtStage stage, MdtStage after, const char *function)
{
    MdtWorldData *w = MdtWorldFromID(id, function);
    if (!w)
        return NULL;
    if (w->stage < after || w->stage >= stage) {
        static const char *const names[] = {"MdtWorldStepBegin",        "MdtWorldStepBegin",
                                            "MdtWorldUpdatePartitions", "MdtAutoDisablePartitions",
                                            "MdtLODPartitions",         "MdtPack",
                                            "MdtKeaSolve",              "MdtKeaIntegrate",
                                            "MdtUnpack"};
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "stage called out of order: it must follow %s%s in the same step; call ignored",
                     names[after], w->stage == MdtStageIdle ? " (no step has begun)" : "");
        return NULL;
    }
    return w;
}

/* Begins the step (refused: MEFALSE); *start is the clock reading its profile section starts at. */
static MeBool beginStep(MdtWorldData *w, MeReal stepSize, const char *function, double *start)
{
    if (!(ME_IS_FINITE(stepSize) && stepSize >= MDT_MIN_STEP_SIZE)) {
        ME_REPORT_IN(function, ME_ERR_STEP_SIZE,
                     "argument 'stepSize' (%g) must be finite and at least MDT_MIN_STEP_SIZE (%g s); step skipped",
                     (double)stepSize, (double)MDT_MIN_STEP_SIZE);
        return MEFALSE;
    }
    if (w->locked) {
        ME_REPORT_IN(function, ME_ERR_WORLD_LOCKED, "the world is already stepping; %s refused", function);
        return MEFALSE;
    }
    MdtWorldHintIfNothingMoves(w, function);
    w->locked = METRUE;
    w->stage = MdtStageBegun;
    w->stepSize = stepSize;
    w->droppedRows = w->cappedPartitions = w->simErrors = 0;
    MeProfileFrameStart(&w->profile);
    *start = MeProfileNow(&w->profile);
    MeProfileSectionStartAt(&w->profile, MDT_SECTION_STEP, *start);
    return METRUE;
}

/* Ends the step; `end` is the clock reading its profile section ends at. */
static void endStep(MdtWorldData *w, double end)
{
    MeProfileSectionEndAt(&w->profile, MDT_SECTION_STEP, end);
    MeProfileFrameEnd(&w->profile);
    w->steps++;
    w->time += w->stepSize;
    w->stage = MdtStageIdle;
    w->locked = MEFALSE;
}

/* The stages in order: what each runs, its profile section, the stage it completes and the earliest
 * stage it may follow (the optional auto-disable and LOD stages may be skipped). */
typedef struct StageDef {
    void (*run)(MdtWorldData *w);
    const char *section;
    MdtStage done, after;
} StageDef;

static const StageDef stages[] = {
    {MdtPartitionStage, MDT_SECTION_PARTITION, MdtStagePartitioned, MdtStageBegun},
    {MdtAutoDisableStage, MDT_SECTION_AUTODISABLE, MdtStageAutoDisabled, MdtStagePartitioned},
    {MdtLODStage, MDT_SECTION_LOD, MdtStageCapped, MdtStagePartitioned},
    {MdtPackStage, MDT_SECTION_PACK, MdtStagePacked, MdtStagePartitioned},
    {MdtSolveStage, MDT_SECTION_SOLVE, MdtStageSolved, MdtStagePacked},
    {MdtIntegrateStage, MDT_SECTION_INTEGRATE, MdtStageIntegrated, MdtStageSolved},
    {MdtUnpackStage, MDT_SECTION_UNPACK, MdtStageUnpacked, MdtStageIntegrated},
};

/* One stage, timed in its profile section from the clock reading `start`; returns the reading at its
 * end (the next stage's start). */
static double runStage(MdtWorldData *w, const StageDef *stage, double start)
{
    MeProfileSectionStartAt(&w->profile, stage->section, start);
    stage->run(w);
    const double end = MeProfileNow(&w->profile);
    MeProfileSectionEndAt(&w->profile, stage->section, end);
    w->stage = stage->done;
    return end;
}

/* A stage called by the application: checked against the step's progress, then run. */
static void publicStage(MdtWorldID id, int index, const char *function)
{
    MdtWorldData *w = enterStage(id, stages[index].done, stages[index].after, function);
    if (w)
        (void)runStage(w, &stages[index], MeProfileNow(&w->profile));
}

void MdtWorldStepBegin(MdtWorldID id, MeReal stepSize)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    double start;
    if (w)
        beginStep(w, stepSize, __func__, &start);
}

void MdtWorldUpdatePartitions(MdtWorldID id) { publicStage(id, 0, __func__); }
void MdtAutoDisablePartitions(MdtWorldID id) { publicStage(id, 1, __func__); }
void MdtLODPartitions(MdtWorldID id) { publicStage(id, 2, __func__); }
void MdtPack(MdtWorldID id) { publicStage(id, 3, __func__); }
void MdtKeaSolve(MdtWorldID id) { publicStage(id, 4, __func__); }
void MdtKeaIntegrate(MdtWorldID id) { publicStage(id, 5, __func__); }
void MdtUnpack(MdtWorldID id) { publicStage(id, 6, __func__); }

void MdtWorldStepEnd(MdtWorldID id)
{
    MdtWorldData *w = enterStage(id, (MdtStage)(MdtStageUnpacked + 1), MdtStageUnpacked, __func__);
    if (w)
        endStep(w, MeProfileNow(&w->profile));
}

void MdtWorldStep(MdtWorldID id, MeReal stepSize)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    double now;
    if (!w || !beginStep(w, stepSize, w->callerName ? w->callerName : __func__, &now))
        return;
    for (size_t i = 0; i < sizeof stages / sizeof stages[0]; i++)
        now = runStage(w, &stages[i], now);
    endStep(w, now);
}

/* ---- partition queries -------------------------------------------------------------------- */
static MdtWorldData *partitionWorld(MdtWorldID id, int partition, const char *function)
{
    MdtWorldData *w = MdtWorldFromID(id, function);
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
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    return w ? w->partitions.partitionCount : 0;
}

void MdtWorldGetPartitionInfo(MdtWorldID id, int partition, MdtPartitionInfo *info)
{
    ME_CHECK_NOT_NULL(info, ME_NOTHING);
    memset(info, 0, sizeof *info);
    MdtWorldData *w = partitionWorld(id, partition, __func__);
    if (!w)
        return;
    const MdtPartitionLists *out = &w->partitions;
    info->bodies = out->partitionStart[partition + 1] - out->partitionStart[partition];
    for (int i = out->constraintStart[partition]; i < out->constraintStart[partition + 1]; i++)
        MdtPartitionInfoAdd(info, out->constraints[i]);
    info->droppedRows = out->droppedRows[partition];
    if (w->rowsPacked)
        info->rows = w->rows.partitionRowStart[partition + 1] - w->rows.partitionRowStart[partition];
}

MdtBodyID MdtWorldGetPartitionBody(MdtWorldID id, int partition, int index)
{
    MdtWorldData *w = partitionWorld(id, partition, __func__);
    if (!w)
        return NULL;
    const MdtPartitionLists *out = &w->partitions;
    int count = out->partitionStart[partition + 1] - out->partitionStart[partition];
    if (index < 0 || index >= count) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'index' (%d) must lie in [0, %d)", index, count);
        return NULL;
    }
    return (MdtBodyID)out->bodies[out->partitionStart[partition] + index]->id;
}
