/* solve_partitions.c -- MdtKeaSolve (MdtSolveStage): run Kea on each partition of the step and
 * collect its statistics.
 *
 * Each partition is an independent LCP over its slice of the step's rows. The world's KeaParameters
 * choose the path (exact up to maxDirectRows rows, iterative beyond, or forced), and the workspace
 * comes from the world's Kea chunk, sized once for the largest partition. The result per partition:
 * the row impulses (in place of the warm start) and each body's velocity change, which the
 * integrator adds to the predicted velocities.
 *
 * Simulation check. A partition whose rows are not finite (the solver refuses them as bad input) or,
 * with MdtWorldSetCheckSim on, whose impulses or velocity changes come out NaN or infinite, is marked
 * failed (MdtSimErrorSolver): its velocity changes are zeroed and the integrator restores, stops and
 * disables it instead of integrating it. Other partitions are not touched. */
#include <string.h>

#include "../me/check.h"
#include "world.h"

static MeBool allFinite(const MeReal *v, size_t n)
{
    MeBool ok = METRUE;
    for (size_t i = 0; i < n; i++)
        ok &= ME_IS_FINITE(v[i]) ? METRUE : MEFALSE;
    return ok;
}

void MdtSolveStage(MdtWorldData *w)
{
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    MdtSolverStats *stats = &w->solverStats;
    memset(stats, 0, sizeof *stats);
    if (!w->rowsPacked)
        return; /* pack could not lay out its rows: the integrator uses no velocity change */
    for (int i = 0; i < out->bodyCount; i++)
        memset(&r->dv[i], 0, sizeof r->dv[i]);
    if (r->count == 0)
        return;

    /* One workspace for the largest partition. */
    size_t need = 0;
    for (int p = 0; p < out->partitionCount; p++) {
        int rows = r->partitionRowStart[p + 1] - r->partitionRowStart[p];
        int bodies = out->partitionStart[p + 1] - out->partitionStart[p];
        if (rows == 0)
            continue;
        size_t bytes = KeaMemoryRequired(rows, bodies, KeaSelectPath(rows, &w->kea));
        if (bytes > need)
            need = bytes;
    }
    void *workspace = MeChunkGetMem(&w->keaChunk, need);
    if (!workspace)
        return; /* reported by the chunk; the constraints act as if absent this step */
    /* The extra effort's rest speed is above what gravity adds in this step (kea_tuning.h). */
    KeaParameters kea = w->kea;
    if (kea.effortRestSpeed > 0)
        kea.effortRestSpeed += MeVector3Magnitude(w->gravity) * w->stepSize;

    for (int p = 0; p < out->partitionCount; p++) {
        int row0 = r->partitionRowStart[p], rows = r->partitionRowStart[p + 1] - row0;
        int body0 = out->partitionStart[p], bodies = out->partitionStart[p + 1] - body0;
        if (rows == 0)
            continue;
        KeaProblem problem;
        problem.nRows = rows;
        problem.nBodies = bodies;
        problem.bodies = r->bodies + body0;
        problem.J = r->J + row0;
        problem.rowBodies = (const int(*)[2])(r->rowBodies + row0);
        problem.epsilon = r->epsilon + row0;
        problem.rhs = r->rhs + row0;
        problem.lo = r->lo + row0;
        problem.hi = r->hi + row0;
        problem.link = r->link + row0;
        problem.mu = r->mu + row0;
        problem.x0 = r->x + row0;
        /* Links were written as step-global row indices: make them partition-local. */
        for (int i = 0; i < rows; i++)
            if (r->link[row0 + i] >= 0)
                r->link[row0 + i] -= row0;
        /* So were the declared contacts. */
        int contact0 = r->partitionContactStart[p];
        problem.nContacts = r->partitionContactStart[p + 1] - contact0;
        problem.contacts = r->contacts + contact0;
        for (int i = 0; i < problem.nContacts; i++)
            r->contacts[contact0 + i].row -= row0;
        KeaStats ks;
        KeaStatus status = KeaSolve(&problem, &kea, workspace, need, r->x + row0, r->dv + body0, &ks);
        stats->partitions++;
        stats->rows += rows;
        if (rows > stats->maxPartitionRows)
            stats->maxPartitionRows = rows;
        if (ks.path == KeaPathDirect)
            stats->directPartitions++;
        else
            stats->iterativePartitions++;
        stats->iterations += ks.iterations;
        stats->pivots += ks.pivots;
        if (status != KeaStatusOk)
            stats->unconverged++;
        if (ks.residual > stats->maxResidual)
            stats->maxResidual = ks.residual;
        out->solverStatus[p] = (int)status;
        MeBool failed = status == KeaStatusBadInput;
        if (!failed && w->checkSim && status != KeaStatusWorkspaceTooSmall)
            failed = !allFinite(r->x + row0, (size_t)rows) ||
                     !allFinite((const MeReal *)(r->dv + body0), 6 * (size_t)bodies);
        if (failed) {
            /* Handled (reported, restored, disabled) by the integrator, before it would integrate. */
            out->simError[p] = MdtSimErrorSolver;
            memset(r->x + row0, 0, sizeof(MeReal) * (size_t)rows);
            memset(r->dv + body0, 0, sizeof(KeaBodyVelocity) * (size_t)bodies);
        } else if (status == KeaStatusWorkspaceTooSmall) {
            ME_REPORT_IN("MdtWorldStep", ME_ERR_KEA_WORKSPACE,
                         "the solver could not solve partition %d (%d rows): workspace too small; its constraints "
                         "were ignored this step",
                         p, rows);
            memset(r->x + row0, 0, sizeof(MeReal) * (size_t)rows);
            memset(r->dv + body0, 0, sizeof(KeaBodyVelocity) * (size_t)bodies);
        } else if (status != KeaStatusOk) {
            ME_REPORT_IN("MdtWorldStep", ME_ERR_KEA_MAX_ITERATIONS,
                         "partition %d (%d rows) stopped at the solver's cap (status %d, residual %g m/s)", p, rows,
                         (int)status, (double)ks.residual);
        }
    }
    MeChunkPutMem(&w->keaChunk, workspace);
}
