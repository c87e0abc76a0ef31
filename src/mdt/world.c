/* world.c -- creating, configuring and destroying a dynamics world (see MdtWorld.h). */
#include <karma/MdtDefaults.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "../me/check.h"
#include "../me/handle.h"
#include "constraint.h"
#include "kea/kea_tuning.h"
#include "world.h"

/* Karma's defaults (docs/karma12.md §5.1, decision D1 for auto-disable). */
#define DEFAULT_EPSILON MDTWORLD_DEFAULT_EPSILON
#define DEFAULT_GAMMA MDTWORLD_DEFAULT_GAMMA
#define DEFAULT_LCP_ITERATIONS 10
#define DEFAULT_AD_VELOCITY MDTWORLD_DEFAULT_VEL_THRESH
#define DEFAULT_AD_ANGULAR_VELOCITY MDTWORLD_DEFAULT_VELROT_THRESH
#define DEFAULT_AD_ACCELERATION MDTWORLD_DEFAULT_ACC_THRESH
#define DEFAULT_AD_ANGULAR_ACCELERATION MDTWORLD_DEFAULT_ACCROT_THRESH
#define DEFAULT_AD_ALIVE_TIME MDTWORLD_DEFAULT_ALIVE_TIME_THRESH

/* A constraint slot holds the common header and the largest type's data (constraint.h). */
#define CONSTRAINT_SLOT_BYTES sizeof(MdtConstraintData)

MdtWorldData *MdtWorldFromID(MdtWorldID id, const char *function)
{
    return MeHandleResolveOwner((uintptr_t)id, ME_HANDLE_WORLD, function, "w");
}

#define WORLD_OR_RETURN(w, id, ret)                                                                  \
    MdtWorldData *w = MdtWorldFromID((id), __func__);                                                    \
    if (!w)                                                                                          \
    return ret

void MdtWorldSetDefaults(MdtWorldData *w)
{
    MeReal l2 = w->lengthScale * w->lengthScale;
    MeVector3Set(w->gravity, MDTWORLD_DEFAULT_GRAVITY_X, MDTWORLD_DEFAULT_GRAVITY_Y, MDTWORLD_DEFAULT_GRAVITY_Z);
    w->epsilon = DEFAULT_EPSILON / w->massScale;
    w->gamma = DEFAULT_GAMMA;
    w->maxLCPIterations = DEFAULT_LCP_ITERATIONS;
    KeaParametersDefault(&w->kea);
    w->kea.maxIterations = DEFAULT_LCP_ITERATIONS;
    /* the iterative path's extra effort where the residual stays high (docs/kea.md, decision K36) */
    w->kea.effortResidual = KEA_EFFORT_RESIDUAL * w->lengthScale;
    w->kea.effortRestSpeed = KEA_EFFORT_REST_SPEED * w->lengthScale;
    w->kea.tolerance = KEA_WORLD_TOLERANCE * w->lengthScale;
    /* Auto hands a partition whose pivots run over their budget to the iterative path (docs/kea.md) */
    w->kea.autoPivotsPerRow = KEA_AUTO_PIVOTS_PER_ROW;
    /* NNCG's momentum on the iterative path's sweeps: the same LCP in fewer sweeps (decision K47) */
    w->kea.nonsmoothCg = 1;
    /* SM at the first chance and every second one after, longer CG runs (decision K55) */
    w->kea.subspaceEvery = KEA_WORLD_SM_EVERY;
    w->kea.subspaceIterations = KEA_WORLD_SM_STEPS;
    w->kea.subspaceStop = KEA_WORLD_SM_STOP;
    w->kea.subspaceJointShare = KEA_WORLD_SM_JOINT_SHARE; /* joint-heavy partitions: fewer SM steps (K58) */
    w->kea.subspaceJointEvery = KEA_WORLD_SM_JOINT_EVERY;
    w->autoDisable.enabled = METRUE;
    w->autoDisable.velocity = DEFAULT_AD_VELOCITY * l2;
    w->autoDisable.angularVelocity = DEFAULT_AD_ANGULAR_VELOCITY;
    w->autoDisable.acceleration = DEFAULT_AD_ACCELERATION * l2;
    w->autoDisable.angularAcceleration = DEFAULT_AD_ANGULAR_ACCELERATION;
    w->autoDisable.aliveTime = DEFAULT_AD_ALIVE_TIME;
    w->autoDisable.averagingTime = MDTWORLD_DEFAULT_AVERAGING_TIME;
    w->checkSim = METRUE;
    w->speedLimit = MDTWORLD_DEFAULT_SPEED_LIMIT * w->lengthScale;
    w->angularSpeedLimit = MDTWORLD_DEFAULT_ANGULAR_SPEED_LIMIT;
    w->maxCorrectingVelocity = MDTWORLD_DEFAULT_MAX_CORRECTING_VEL * w->lengthScale;
    w->maxMatrixSize = MDT_MATRIX_SIZE_UNCAPPED;
    MdtLODParamsSetDefaults(&w->lod);
    MdtWorldDebugDefaults(w);
}

MdtWorldID MdtWorldCreate(unsigned int maxBodies, unsigned int maxConstraints, MeReal lengthScale, MeReal massScale)
{
    if (!(ME_IS_FINITE(lengthScale) && lengthScale > 0) || !(ME_IS_FINITE(massScale) && massScale > 0)) {
        ME_REPORT(ME_ERR_SCALE_NOT_POSITIVE, "lengthScale (%g) and massScale (%g) must be positive and finite",
                  (double)lengthScale, (double)massScale);
        return NULL;
    }
    if (maxBodies > (unsigned int)ME_HANDLE_MAX_INDEX || maxConstraints > (unsigned int)ME_HANDLE_MAX_INDEX) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "maxBodies (%u) and maxConstraints (%u) may be at most %ld", maxBodies,
                  maxConstraints, (long)ME_HANDLE_MAX_INDEX);
        return NULL;
    }
    MdtWorldData *w = MeMemoryCreateZeroed(sizeof *w);
    if (!w)
        return NULL;
    w->maxBodies = maxBodies;
    w->maxConstraints = maxConstraints;
    w->lengthScale = lengthScale;
    w->massScale = massScale;
    w->massScaleName = "massScale (MdtWorldCreate's fourth argument)";
    if (!MePoolInit(&w->bodyPool, (int)maxBodies, sizeof(MdtBodyData), 16, "maxBodies in MdtWorldCreate", 0) ||
        !MePoolInit(&w->constraintPool, (int)maxConstraints, CONSTRAINT_SLOT_BYTES, 16, "maxConstraints in MdtWorldCreate", 0)) {
        MePoolDestroy(&w->bodyPool);
        MeMemoryDestroy(w);
        return NULL;
    }
    w->ownerSlot = MeHandleRegisterOwner(w, ME_HANDLE_WORLD, __func__);
    if (!w->ownerSlot) {
        MePoolDestroy(&w->bodyPool);
        MePoolDestroy(&w->constraintPool);
        MeMemoryDestroy(w);
        return NULL;
    }
    MeHandleSetOwnerPool(w->ownerSlot, ME_HANDLE_BODY, &w->bodyPool);
    MeHandleSetOwnerPool(w->ownerSlot, ME_HANDLE_CONSTRAINT, &w->constraintPool);
    w->id = MeHandleOfOwner(w->ownerSlot);
    MeChunkInitNamed(&w->partitionChunk, "partition output");
    MeChunkInitNamed(&w->keaChunk, "Kea workspace");
    MeChunkInitNamed(&w->rowChunk, "constraint rows");
    MeChunkInitNamed(&w->lodChunk, "matrix capping");
    MeChunkInitNamed(&w->taskChunk, "task marks");
    MeProfileInit(&w->profile);
    w->workerCount = 1; /* no task system: the step runs on the calling thread */
    MdtWorldSetDefaults(w);
    return (MdtWorldID)w->id;
}

void MdtWorldDestroy(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (w->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "a world cannot be destroyed from inside its own step");
        return;
    }
    MeHandleUnregisterOwner(w->ownerSlot);
    MeChunkTerm(&w->partitionChunk);
    MeChunkTerm(&w->keaChunk);
    MeChunkTerm(&w->rowChunk);
    MeChunkTerm(&w->lodChunk);
    MeChunkTerm(&w->taskChunk);
    MePoolDestroy(&w->bodyPool);
    MePoolDestroy(&w->constraintPool);
    MeMemoryDestroy(w);
}

void MdtWorldReset(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (w->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "a world cannot be reset from inside its own step");
        return;
    }
    MePoolDeset(&w->bodyPool);
    MePoolDeset(&w->constraintPool);
    w->enabledBodyCount = 0;
    w->enabledConstraintCount = 0;
    w->partitions.bodyCount = 0;
    w->partitions.partitionCount = 0;
    w->partitions.constraintCount = 0;
    w->rowsPacked = MEFALSE;
}

void MdtWorldReCreate(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    MdtWorldSetDefaults(w);
}

MeBool MdtWorldIsValid(MdtWorldID id) { return MeHandleIsValid((uintptr_t)id, ME_HANDLE_WORLD); }

void MdtWorldSetCallerName(MdtWorldID id, const char *function)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->callerName = function;
}

const char *MdtWorldGetCallerName(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, NULL);
    return w->callerName;
}

void MdtWorldSetSizeNames(MdtWorldID id, const char *bodies, const char *constraints, const char *massScale)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (bodies)
        w->bodyPool.sizeName = bodies;
    if (constraints)
        w->constraintPool.sizeName = constraints;
    if (massScale)
        w->massScaleName = massScale;
}

/* ---- accessors ---------------------------------------------------------------------------- */
int MdtWorldGetTotalBodies(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return MePoolGetUsed(&w->bodyPool);
}

int MdtWorldGetEnabledBodies(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->enabledBodyCount;
}

int MdtWorldGetTotalConstraints(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return MePoolGetUsed(&w->constraintPool);
}

int MdtWorldGetEnabledConstraints(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->enabledConstraintCount;
}

int MdtWorldGetMaxBodies(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return (int)w->maxBodies;
}

int MdtWorldGetMaxConstraints(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return (int)w->maxConstraints;
}

MeReal MdtWorldGetEpsilon(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->epsilon;
}

MeReal MdtWorldGetGamma(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->gamma;
}

void MdtWorldGetGravity(MdtWorldID id, MeVector3 g)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(g, ME_NOTHING);
    MeVector3Copy(g, w->gravity);
}

MeBool MdtWorldGetAutoDisable(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, MEFALSE);
    return w->autoDisable.enabled;
}

MeReal MdtWorldGetAutoDisableVelocityThreshold(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->autoDisable.velocity;
}

MeReal MdtWorldGetAutoDisableAngularVelocityThreshold(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->autoDisable.angularVelocity;
}

MeReal MdtWorldGetAutoDisableAccelerationThreshold(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->autoDisable.acceleration;
}

MeReal MdtWorldGetAutoDisableAngularAccelerationThreshold(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->autoDisable.angularAcceleration;
}

MeReal MdtWorldGetAutoDisableAliveTime(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->autoDisable.aliveTime;
}

int MdtWorldGetMaxLCPIterations(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->maxLCPIterations;
}

MeReal MdtWorldGetDefaultDensity(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->massScale / (w->lengthScale * w->lengthScale * w->lengthScale);
}

MeReal MdtWorldGetLengthScale(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->lengthScale;
}

MeReal MdtWorldGetMassScale(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->massScale;
}

const MeProfile *MdtWorldGetProfile(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, NULL);
    return &w->profile;
}

MeProfile *MdtWorldGetProfilePtr(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, NULL);
    return &w->profile;
}

void MdtWorldGetCounters(MdtWorldID id, MdtWorldCounters *c)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(c, ME_NOTHING);
    memset(c, 0, sizeof *c);
    c->bodies = MePoolGetUsed(&w->bodyPool);
    c->enabledBodies = w->enabledBodyCount;
    c->constraints = MePoolGetUsed(&w->constraintPool);
    c->enabledConstraints = w->enabledConstraintCount;
    c->partitions = w->partitions.partitionCount;
    c->rows = w->lastRowCount;
    c->droppedRows = w->droppedRows;
    c->cappedPartitions = w->cappedPartitions;
    c->simErrors = w->simErrors;
    c->speedWarnings = w->speedWarnings;
    c->energyWarnings = w->energyWarnings;
    c->bodyPoolHighWater = MePoolGetHighWater(&w->bodyPool);
    c->constraintPoolHighWater = MePoolGetHighWater(&w->constraintPool);
    c->steps = w->steps;
    c->time = w->time;
}

/* ---- mutators ----------------------------------------------------------------------------- */
void MdtWorldSetGravity(MdtWorldID id, MeReal gx, MeReal gy, MeReal gz)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_FINITE3(gx, gy, gz, ME_NOTHING);
    MeVector3Set(w->gravity, gx, gy, gz);
}

void MdtWorldSetEpsilon(MdtWorldID id, MeReal e)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_FINITE(e, ME_NOTHING);
    if (!(e > 0)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'e' (%g) must be positive (typical 1e-5 ... 0.1)", (double)e);
        return;
    }
    w->epsilon = e;
}

void MdtWorldSetGamma(MdtWorldID id, MeReal g)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_FINITE(g, ME_NOTHING);
    if (!(g >= 0 && g <= 1)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'g' (%g) must lie in [0, 1] (typical 0.1 ... 0.8)", (double)g);
        return;
    }
    w->gamma = g;
}

void MdtWorldSetGammaWithRefTimeStep(MdtWorldID id, MeReal aGamma, MeReal aRefStep, MeReal aTimeStep)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_FINITE3(aGamma, aRefStep, aTimeStep, ME_NOTHING);
    if (!(aRefStep > 0 && aTimeStep > 0)) {
        ME_REPORT(ME_ERR_STEP_SIZE, "aRefStep (%g) and aTimeStep (%g) must be positive", (double)aRefStep,
                  (double)aTimeStep);
        return;
    }
    MeReal g = aGamma * aTimeStep / aRefStep;
    if (!(g >= 0 && g <= 1)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "the resulting gamma (%g) must lie in [0, 1]", (double)g);
        return;
    }
    w->gamma = g;
}

void MdtWorldResetForces(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    for (int i = 0; i < w->bodyPool.capacity; i++) {
        if (!MePoolSlotIsLive(&w->bodyPool, i))
            continue;
        MdtBodyData *b = MePoolSlot(&w->bodyPool, i);
        MeVector3Set(b->force, 0, 0, 0);
        MeVector3Set(b->torque, 0, 0, 0);
        MeVector3Set(b->impulse, 0, 0, 0);
        MeVector3Set(b->angularImpulse, 0, 0, 0);
    }
}

void MdtWorldSetAutoDisable(MdtWorldID id, MeBool d)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    const MeBool enable = d ? METRUE : MEFALSE;
    if (enable && !w->autoDisable.enabled) {
        /* The rest windows were not kept while auto-disable was off: each starts afresh. */
        for (int i = 0; i < w->bodyPool.capacity; i++)
            if (MePoolSlotIsLive(&w->bodyPool, i))
                MdtBodyRestWindowRestart(MePoolSlot(&w->bodyPool, i));
    }
    w->autoDisable.enabled = enable;
}

MeReal MdtWorldGetAutoDisableAveragingTime(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->autoDisable.averagingTime;
}

/* All auto-disable thresholds share one check: finite and not negative. */
static void setThreshold(MdtWorldID id, MeReal value, size_t offset, const char *function)
{
    MdtWorldData *w = MdtWorldFromID(id, function);
    if (!w)
        return;
    if (!ME_IS_FINITE(value)) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "the threshold is %g (not finite); call ignored",
                     (double)value);
        return;
    }
    if (value < 0) {
        ME_REPORT_IN(function, ME_ERR_NEGATIVE_VALUE, "the threshold (%g) must not be negative", (double)value);
        return;
    }
    *(MeReal *)((unsigned char *)&w->autoDisable + offset) = value;
}

void MdtWorldSetAutoDisableVelocityThreshold(MdtWorldID id, MeReal vt)
{
    setThreshold(id, vt, offsetof(MdtAutoDisableParams, velocity), __func__);
}

void MdtWorldSetAutoDisableAngularVelocityThreshold(MdtWorldID id, MeReal avt)
{
    setThreshold(id, avt, offsetof(MdtAutoDisableParams, angularVelocity), __func__);
}

void MdtWorldSetAutoDisableAccelerationThreshold(MdtWorldID id, MeReal at)
{
    setThreshold(id, at, offsetof(MdtAutoDisableParams, acceleration), __func__);
}

void MdtWorldSetAutoDisableAngularAccelerationThreshold(MdtWorldID id, MeReal aat)
{
    setThreshold(id, aat, offsetof(MdtAutoDisableParams, angularAcceleration), __func__);
}

void MdtWorldSetAutoDisableAliveTime(MdtWorldID id, MeReal aw)
{
    setThreshold(id, aw, offsetof(MdtAutoDisableParams, aliveTime), __func__);
}

void MdtWorldSetAutoDisableAveragingTime(MdtWorldID id, MeReal t)
{
    setThreshold(id, t, offsetof(MdtAutoDisableParams, averagingTime), __func__);
}

void MdtWorldSetMaxLCPIterations(MdtWorldID id, int mi)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (mi < 1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'mi' (%d) must be at least 1", mi);
        return;
    }
    w->maxLCPIterations = mi;
    w->kea.maxIterations = mi;
}

void MdtWorldSetBodyEnableCallback(MdtWorldID id, MdtBodyEnableCBPtr cb, void *userData)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->bodyEnableCB = cb;
    w->bodyEnableData = userData;
}

void MdtWorldSetBodyDisableCallback(MdtWorldID id, MdtBodyEnableCBPtr cb, void *userData)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->bodyDisableCB = cb;
    w->bodyDisableData = userData;
}

void MdtWorldSetContactGroupDestroyCallback(MdtWorldID id, MdtContactGroupDestroyCBPtr cb, void *userData)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->contactGroupDestroyCB = cb;
    w->contactGroupDestroyData = userData;
}

/* ---- solver settings ---------------------------------------------------------------------- */
void MdtWorldGetSolverStats(MdtWorldID id, MdtSolverStats *stats)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(stats, ME_NOTHING);
    *stats = w->solverStats;
}

MdtLCPSolver MdtWorldGetLCPSolver(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, MdtLCPSolverAuto);
    return (MdtLCPSolver)w->kea.path;
}

int MdtWorldGetMaxDirectRows(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->kea.maxDirectRows;
}

int MdtWorldGetPartitionSplitRows(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->kea.splitRows;
}

void MdtWorldSetPartitionSplitRows(MdtWorldID id, int rows)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (rows < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'rows' (%d) must not be negative", rows);
        return;
    }
    w->kea.splitRows = rows;
}

MeBool MdtWorldGetNonsmoothCG(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, MEFALSE);
    return w->kea.nonsmoothCg ? METRUE : MEFALSE;
}

void MdtWorldSetNonsmoothCG(MdtWorldID id, MeBool on)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->kea.nonsmoothCg = on ? 1 : 0;
}

MeBool MdtWorldGetDeflation(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, MEFALSE);
    return w->kea.deflation ? METRUE : MEFALSE;
}

void MdtWorldSetDeflation(MdtWorldID id, MeBool on)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->kea.deflation = on ? 1 : 0;
}

MeReal MdtWorldGetLCPTolerance(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    return w->kea.tolerance;
}

void MdtWorldSetLCPSolver(MdtWorldID id, MdtLCPSolver solver)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (solver != MdtLCPSolverAuto && solver != MdtLCPSolverDirect && solver != MdtLCPSolverIterative) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'solver' (%d) is not an MdtLCPSolver", (int)solver);
        return;
    }
    w->kea.path = (KeaPath)solver;
}

void MdtWorldSetMaxDirectRows(MdtWorldID id, int rows)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (rows < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'rows' (%d) must not be negative", rows);
        return;
    }
    w->kea.maxDirectRows = rows;
}

void MdtWorldSetLCPTolerance(MdtWorldID id, MeReal tolerance)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_FINITE(tolerance, ME_NOTHING);
    if (!(tolerance > 0)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'tolerance' (%g) must be positive", (double)tolerance);
        return;
    }
    w->kea.tolerance = tolerance;
}

/* ---- runaway reports and the contacts' correction speed (docs/step.md) ---------------------- */

/* A positive speed, MEINFINITY allowed (it turns the setting off); NaN, zero and negatives refused. */
static MeBool checkSpeedSetting(MeReal v, const char *name, const char *function)
{
    if (!(v > 0)) {
        ME_REPORT_IN(function, v != v ? ME_ERR_NONFINITE_ARGUMENT : ME_ERR_ARGUMENT_RANGE,
                     "argument '%s' (%g) must be positive (MEINFINITY: no limit); call ignored", name, (double)v);
        return MEFALSE;
    }
    return METRUE;
}

#define SPEED_SETTING(Name, field, arg)                                                              \
    void MdtWorldSet##Name(MdtWorldID id, MeReal arg)                                                \
    {                                                                                                \
        WORLD_OR_RETURN(w, id, ME_NOTHING);                                                          \
        if (checkSpeedSetting(arg, #arg, __func__))                                                  \
            w->field = arg;                                                                          \
    }                                                                                                \
    MeReal MdtWorldGet##Name(MdtWorldID id)                                                          \
    {                                                                                                \
        WORLD_OR_RETURN(w, id, 0);                                                                   \
        return w->field;                                                                             \
    }
SPEED_SETTING(SpeedLimit, speedLimit, speed)
SPEED_SETTING(AngularSpeedLimit, angularSpeedLimit, angularSpeed)
SPEED_SETTING(MaxCorrectingVelocity, maxCorrectingVelocity, speed)
