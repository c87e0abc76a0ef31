/* simerror.c -- the simulation check: containing a partition that produced NaN or infinity.
 *
 * The solver (solve_partitions.c) and the integrator (integrate_bodies.c) mark a partition failed when its solve or
 * its new state is not finite. Here each failed partition is reported (ME_ERR_NONFINITE_STATE, once
 * per partition and step), handed to the application's callback while its bodies still hold the bad
 * values, and then put back to its pose at the start of the step, stopped and disabled. Its
 * constraints' forces and warm starts are cleared by the unpack stage, so nothing non-finite survives
 * into the next step. Partitions share no data, so the others simulate exactly as they would without
 * the failed one (decision K5). */
#include "../me/check.h"
#include "constraint.h"
#include "world.h"

static void stopAndDisable(MdtBodyData *b)
{
    MeVector4Copy(b->q, b->stepStartQ);
    MdtBodyUpdateTransforms(b, b->stepStartCom);
    MeVector3Set(b->vel, 0, 0, 0);
    MeVector3Set(b->velrot, 0, 0, 0);
    MeVector3Set(b->accel, 0, 0, 0);
    MeVector3Set(b->accelrot, 0, 0, 0);
    MdtBodySetEnabledInternal(b, MEFALSE);
}

void MdtSimErrorHandlePartitions(MdtWorldData *w)
{
    MdtPartitionLists *out = &w->partitions;
    for (int p = 0; p < out->partitionCount; p++) {
        if (!out->simError[p])
            continue;
        int start = out->partitionStart[p], end = out->partitionStart[p + 1];
        MdtSimError e;
        e.kind = (MdtSimErrorKind)out->simError[p];
        e.partition = p;
        e.bodyCount = end - start;
        e.bodies = out->ids + start;
        e.constraintCount = out->constraintStart[p + 1] - out->constraintStart[p];
        e.rows = w->rowsPacked ? w->rows.partitionRowStart[p + 1] - w->rows.partitionRowStart[p] : 0;
        e.solverStatus = out->solverStatus[p];
        w->simErrors++;
        ME_REPORT_IN("MdtWorldStep", ME_ERR_NONFINITE_STATE,
                     "partition %d (%d bodies, %d rows) produced a NaN or infinite %s; its bodies were put back to "
                     "their pose at the start of the step, stopped and disabled",
                     p, e.bodyCount, e.rows, e.kind == MdtSimErrorSolver ? "solver result" : "state");
        if (w->simErrorCB)
            w->simErrorCB((MdtWorldID)w->id, &e, w->simErrorData);
        for (int i = start; i < end; i++)
            stopAndDisable(out->bodies[i]);
    }
}

/* ---- API ---------------------------------------------------------------------------------- */
void MdtWorldSetCheckSim(MdtWorldID id, MeBool check)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (w)
        w->checkSim = check ? METRUE : MEFALSE;
}

MeBool MdtWorldGetCheckSim(MdtWorldID id)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    return w ? w->checkSim : MEFALSE;
}

void MdtWorldSetSimErrorHandler(MdtWorldID id, MdtSimErrorHandlerPtr cb, void *userData)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    w->simErrorCB = cb;
    w->simErrorData = userData;
}

MdtSimErrorHandlerPtr MdtWorldGetSimErrorHandler(MdtWorldID id, void **userData)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (userData)
        *userData = w ? w->simErrorData : NULL;
    return w ? w->simErrorCB : NULL;
}

void MdtDefaultSimErrorHandler(MdtWorldID id, const MdtSimError *error, void *userData)
{
    (void)userData;
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    ME_CHECK_NOT_NULL(error, ME_NOTHING);
    MeInfo(0, "simulation error in partition %d (%s): %d bodies, %d constraints, %d rows, solver status %d",
           error->partition, error->kind == MdtSimErrorSolver ? "solver result" : "state", error->bodyCount,
           error->constraintCount, error->rows, error->solverStatus);
    for (int i = 0; i < error->bodyCount; i++)
        MdtBodyLog(error->bodies[i]);
}
