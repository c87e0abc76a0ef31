/* world.h -- the dynamics world record (internal).
 *
 * The world owns the body and constraint pools (fixed size, generational slots behind the IDs), the
 * solver settings, the auto-disable settings, the profile and the scratch chunks the step uses. */
#ifndef MDT_WORLD_INTERNAL_H
#define MDT_WORLD_INTERNAL_H

#include <karma/MeChunk.h>
#include <karma/MePool.h>
#include <karma/MeProfile.h>
#include <karma/MdtKea.h>
#include <karma/MdtLOD.h>
#include <karma/MdtTaskSystem.h>
#include <karma/MdtWorld.h>

#include "body.h"
#include "kea/kea.h"

/* Names of the step's profile sections (docs/step.md). */
#define MDT_SECTION_STEP "Dynamics"
#define MDT_SECTION_PARTITION "Partition"
#define MDT_SECTION_AUTODISABLE "AutoDisable"
#define MDT_SECTION_LOD "LOD"
#define MDT_SECTION_PACK "Pack"
#define MDT_SECTION_SOLVE "Solve"
#define MDT_SECTION_INTEGRATE "Integrate"
#define MDT_SECTION_UNPACK "Unpack"

typedef struct MdtAutoDisableParams {
    MeBool enabled;
    MeReal velocity, angularVelocity, acceleration, angularAcceleration; /* squared magnitudes */
    MeReal aliveTime;                                                    /* seconds */
    MeReal averagingTime; /* seconds the motion is averaged over (rest_window.c); 0: the last step alone */
} MdtAutoDisableParams;

struct MdtConstraintData;

/* The step's view of the enabled bodies and constraints, grouped into partitions (islands). */
typedef struct MdtPartitionLists {
    int bodyCount;
    MdtBodyData **bodies;        /* enabled bodies, grouped by partition */
    int partitionCount;
    int *partitionStart;     /* partitionCount + 1 offsets into bodies */
    int constraintCount;
    struct MdtConstraintData **constraints; /* enabled constraints, grouped by partition */
    int *constraintStart;    /* partitionCount + 1 offsets into constraints */
    int *droppedRows;        /* per partition: rows removed by matrix capping */
    int *simError;           /* per partition: 0, or the MdtSimErrorKind that failed it */
    int *solverStatus;       /* per partition: the KeaStatus of its solve */
    int *runawayReports;     /* per partition: what the integrator's runaway check left to report */
    MeReal *energies;        /* per partition: kinetic energy predicted and after integration (2 each) */
    MdtBodyID *ids;          /* scratch for the sim-error callback's body list (maxBodies) */
} MdtPartitionLists;

/* Where an application-driven step is (MdtMainLoop.h): each stage requires the previous one. */
typedef enum MdtStage {
    MdtStageIdle = 0,   /* no step in progress */
    MdtStageBegun,      /* MdtWorldStepBegin */
    MdtStagePartitioned,
    MdtStageAutoDisabled,
    MdtStageCapped,
    MdtStagePacked,
    MdtStageSolved,
    MdtStageIntegrated,
    MdtStageUnpacked
} MdtStage;

/* The solver rows of the step, all partitions one after the other (written by MdtPack). */
typedef struct MdtStepRows {
    int count;
    KeaJacobianRow *J;
    int (*rowBodies)[2];
    MeReal *epsilon, *rhs, *lo, *hi, *mu, *x;
    int *link;
    int *partitionRowStart;  /* partitionCount + 1 offsets */
    KeaContact *contacts;    /* declared contacts (MdtRowWriterDeclareContact), partition after partition */
    int *partitionContactStart; /* partitionCount + 1 offsets into contacts */
    int *packRowRoom, *packContactRoom; /* per piece of a partition (pack.c): where pack wrote its rows and contacts */
    int *packRows, *packContacts;       /* per piece: how many it wrote */
    int *pieceConstraintStart, *pieceBodyStart; /* pieces + 1 offsets into the partitions' lists */
    int *piecePartition;                /* per piece: its partition */
    int *pieceUnproven;                 /* per piece: some row its writer could not prove valid */
    int *partitionUnproven;             /* per partition: the same, for its pieces together: Kea checks
                                           its rows (KeaSolveSized), else trusts them (KeaSolveRowsProved) */
    KeaBody *bodies;         /* per step body (partition order) */
    KeaBodyVelocity *dv;     /* per step body: velocity change from the constraints */
    size_t workspaceBytes;   /* Kea workspace for the largest partition */
} MdtStepRows;

/* A workspace size Kea gave (KeaMemoryRequired: a function of its arguments, so a kept answer stays
 * right); rows = 0 marks an empty entry. A scene's partitions repeat a few shapes step after step. */
#define MDT_WORKSPACE_SIZES 16
typedef struct MdtWorkspaceSize {
    int rows, bodies;
    KeaPath path;
    size_t bytes;
} MdtWorkspaceSize;

typedef struct MdtWorldData {
    int ownerSlot;           /* registry slot behind the MdtWorldID */
    uintptr_t id;
    MePool bodyPool;
    MePool constraintPool;
    unsigned int maxBodies, maxConstraints;
    MeReal lengthScale, massScale;

    /* settings */
    MeVector3 gravity;
    MeReal epsilon, gamma;
    int maxLCPIterations;
    MdtAutoDisableParams autoDisable;
    MeReal speedLimit, angularSpeedLimit;  /* runaway reports (runaway.c) */
    MeReal maxCorrectingVelocity;          /* contact penetration correction bound, m/s */

    /* callbacks */
    MdtBodyEnableCBPtr bodyEnableCB, bodyDisableCB;
    void *bodyEnableData, *bodyDisableData;
    MdtContactGroupDestroyCBPtr contactGroupDestroyCB;
    void *contactGroupDestroyData;
    MdtSimErrorHandlerPtr simErrorCB;
    void *simErrorData;
    MeBool checkSim;
    MdtContactImportanceCBPtr importanceCB;
    void *importanceData;

    /* matrix capping (lod.c) */
    int maxMatrixSize;
    MdtLODParams lod;
    MeChunk lodChunk;        /* the capped partition's contact list */
    int droppedRows, cappedPartitions, simErrors; /* of the last step */
    unsigned long speedWarnings, energyWarnings;  /* since creation (runaway.c) */

    /* messages reported once per world (the rest are counted) */
    MeBool contactPoolFullReported;     /* the bridge could not make a contact */
    MeBool massRangeReported;           /* a mass far from massScale */
    MeBool inertiaRangeReported;        /* an inertia far from its scale */
    MeBool hintsDisabled;               /* MdtWorldSetHints(world, MEFALSE) */
    MeBool nothingMovesHinted;          /* the one-time "nothing will move" hint was given */
    MeBool hasMoved;                    /* a step had something acting: no more hints to look for */
    const char *massScaleName;          /* what sets massScale, for the mass-range warning */
    const char *callerName;             /* MdtWorldSetCallerName: the API function running the world on
                                           the application's behalf (MstUniverseStep), named by the step's
                                           messages, its contacts' and the mass warning; else NULL */

    /* debugging (world_debug.c) */
    MdtDebugDrawOptions debugOptions;   /* MdtWorldSetDebugDrawing */
    MdtKeaDebugDataRequest keaDebug;    /* MdtWorldSetKeaDebugRequest: kept, not acted on */
    int *matrixSizeLog;                 /* MdtWorldSetMatrixSizeLog: counts of partitions by rows */
    int matrixSizeLogSize;

    /* step state */
    MeBool locked;           /* inside MdtWorldStep, or between MdtWorldStepBegin and End */
    MdtStage stage;
    MeReal stepSize;         /* of the step in progress or the last one */
    int enabledBodyCount;
    int enabledConstraintCount;
    MdtPartitionLists partitions;
    MdtStepRows rows;
    MeBool rowsPacked;       /* rows describe the current partitions (pack ran after partitioning) */
    unsigned long partitionStamp;
    MeChunk partitionChunk;  /* body and constraint lists, partition offsets */
    MeChunk rowChunk;        /* the step's solver rows */
    MeChunk keaChunk;        /* solver workspace */
    MdtWorkspaceSize workspaceSizes[MDT_WORKSPACE_SIZES]; /* Kea's sizes, kept (solve_partitions.c) */
    MeChunk taskChunk;       /* marks of the items a task system ran (task_system.c) */
    KeaParameters kea;       /* solver settings (path, iterations, tolerance...) */
    /* the application's task system (MdtTaskSystem.h, task_system.c); workerCount 1 and no
       callbacks: the step runs on the calling thread */
    int workerCount;
    MdtEnqueueTaskCBPtr enqueueTask;
    MdtFinishTaskCBPtr finishTask;
    void *taskUser;
    MdtSolverStats solverStats;
    MeProfile profile;
    unsigned long steps;
    MeReal time;
    int lastRowCount;
} MdtWorldData;

/* Resolve an ID or report in the caller's name; NULL when invalid. */
MdtWorldData *MdtWorldFromID(MdtWorldID id, const char *function);
/** hints.c: at the start of a step, the one-time hint when nothing can move (MdtWorldSetHints). */
void MdtWorldHintIfNothingMoves(MdtWorldData *w, const char *function);
/* Set every setting to its default for the world's scales. */
void MdtWorldSetDefaults(MdtWorldData *w);

/* Run `task` over [0, itemCount) on the world's task system (task_system.c): on the calling thread
 * as worker 0 without one (or for a single range), else enqueued and finished before returning; items
 * the task system left out are run afterwards on the calling thread (reported, ME_ERR_TASK_WORKER). */
void MdtRunStepTask(MdtWorldData *w, MdtTaskFnPtr task, int itemCount, int minRange, void *taskData);

/* The stages of the step (docs/step.md, MdtMainLoop.h); step.c wraps each in its public function. */
void MdtPartitionStage(MdtWorldData *w);
void MdtAutoDisableStage(MdtWorldData *w);
void MdtLODStage(MdtWorldData *w);
void MdtPackStage(MdtWorldData *w);
void MdtSolveStage(MdtWorldData *w);
void MdtIntegrateStage(MdtWorldData *w);
void MdtUnpackStage(MdtWorldData *w);
/* Debugging settings to their defaults (none), and their per-step work (world_debug.c). */
void MdtWorldDebugDefaults(MdtWorldData *w);
/* Count a solved partition of `rows` rows in the matrix-size log, if one is set. */
void MdtWorldLogMatrixSize(MdtWorldData *w, int rows);
/* Draw what MdtWorldSetDebugDrawing asked for, after the unpack stage. */
void MdtWorldDebugDraw(MdtWorldData *w);
/* Add one constraint to Karma 1.2's counts of a partition (partition_info.c). */
void MdtPartitionInfoAdd(MdtPartitionInfo *info, const struct MdtConstraintData *c);
/* Whether a body counts as at rest for auto-disable under `p` and step size h (autodisable.c). */
MeBool MdtBodyAtRest(const MdtBodyData *b, const MdtAutoDisableParams *p, MeReal h);
/* Rest window (rest_window.c): forget the body's motion (it was enabled or its velocity set). */
void MdtBodyRestWindowRestart(MdtBodyData *b);
/* Rest window: add the body's velocities after a step, in blocks of blockSteps steps. */
void MdtBodyRestWindowRecord(MdtBodyData *b, int blockSteps);
/* Rest window: the steps per block for an averaging time (s) and step size h (s). */
int MdtRestWindowBlockSteps(MeReal averagingTime, MeReal h);
/* Rest window: mean velocity and angular velocity and fitted acceleration and angular acceleration
 * over the window, for steps of size h; MEFALSE while the window is not yet complete. */
MeBool MdtBodyRestWindowMeans(const MdtBodyData *b, MeReal h, MeVector3 vel, MeVector3 velrot, MeVector3 accel,
                              MeVector3 accelrot);
/* Kinetic energy of a body for velocities v, w (world frame), with its inertia in use (runaway.c). */
MeReal MdtBodyKineticEnergy(const MdtBodyData *b, const MeVector3 v, const MeVector3 w);
/* After integrating partition p, on any worker: judge its bodies against the speed limits and its
 * energy from `predicted` (kinetic energy with the applied forces, before constraints) to `after`,
 * updating the bodies' warning flags; returns what MdtRunawayReportPartition must report (runaway.c). */
int MdtRunawayJudgePartition(MdtWorldData *w, int p, MeReal predicted, MeReal after);
/* On the stepping thread, in partition order: the reports MdtRunawayJudgePartition returned for p
 * (messages and the world's warning counters). */
void MdtRunawayReportPartition(MdtWorldData *w, int p, int reports, MeReal predicted, MeReal after);
/* Whether partition p's kinetic energy after integration (velocities v* + Δv from `deltaVelocities`,
 * 6 per body, or NULL for none) is certainly at most the energy check's floor, so that the check
 * finds no jump whatever the energy before: the integration then need not sum the energies
 * (runaway.c). */
MeBool MdtRunawayEnergyBelowFloor(const MdtWorldData *w, int p, const MeReal *deltaVelocities);
/* Restore, stop and disable the partitions marked in simError; report each and call the callback. */
void MdtSimErrorHandlePartitions(MdtWorldData *w);

#endif /* MDT_WORLD_INTERNAL_H */
