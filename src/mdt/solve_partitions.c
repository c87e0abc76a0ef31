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
 * disables it instead of integrating it. Other partitions are not touched.
 *
 * On several cores (MdtTaskSystem.h). The partitions are solved as one task over the partition
 * indices, each on a workspace of its worker's (the Kea chunk holds one per worker). A partition's
 * solve reads only its own slice of the rows and writes only its own impulses, velocity changes and
 * result record, so it does not matter which worker solves it or when: the result is the serial one,
 * bit for bit, for any worker count. Statistics and messages are gathered afterwards, on the stepping
 * thread, in partition order, as the serial loop gave them. A partition the task system did not solve
 * (a range left out, a worker index out of range) is solved then on the stepping thread, and reported
 * (ME_ERR_TASK_WORKER, task_system.c). */
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

/* One partition's outcome, written by whichever worker solved it. */
typedef struct PartitionResult {
    KeaStats stats;
} PartitionResult;

/* What the solve task shares: read-only during the task but for the partitions' own slices. */
typedef struct SolveTask {
    MdtWorldData *w;
    const KeaParameters *kea;  /* the world's, with the step's rest speed for the extra effort and the
                                  world's task system as Kea's task hook (a split partition's) */
    unsigned char *workspaces; /* workerCount workspaces of `need` bytes each */
    size_t need;
    int workers;
    PartitionResult *results;
} SolveTask;

/* Solve partition p on `workspace`: its slice of the rows, its impulses and velocity changes. */
static void solvePartition(MdtWorldData *w, const KeaParameters *kea, int p, void *workspace, size_t need,
                           PartitionResult *res)
{
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    int row0 = r->partitionRowStart[p], rows = r->partitionRowStart[p + 1] - row0;
    int body0 = out->partitionStart[p], bodies = out->partitionStart[p + 1] - body0;
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
    /* Rows the writer proved valid (pack.c) are not checked again. */
    KeaStatus status = (r->partitionUnproven[p] ? KeaSolveSized : KeaSolveRowsProved)(&problem, kea, workspace, need,
                                                                                     r->x + row0, r->dv + body0,
                                                                                     &res->stats);
    res->stats.status = status;
    MeBool failed = status == KeaStatusBadInput;
    if (!failed && w->checkSim && status != KeaStatusWorkspaceTooSmall)
        failed = !allFinite(r->x + row0, (size_t)rows) || !allFinite((const MeReal *)(r->dv + body0), 6 * (size_t)bodies);
    if (failed) {
        /* Handled (reported, restored, disabled) by the integrator, before it would integrate. */
        out->simError[p] = MdtSimErrorSolver;
    }
    if (failed || status == KeaStatusWorkspaceTooSmall) {
        memset(r->x + row0, 0, sizeof(MeReal) * (size_t)rows);
        memset(r->dv + body0, 0, sizeof(KeaBodyVelocity) * (size_t)bodies);
    }
}

/* Whether Kea splits partition p over the workers (MdtWorldSetPartitionSplitRows): it is then solved
 * on its own after the other partitions, on the stepping thread, handing its sweeps' chunks to the
 * task system. */
static MeBool splitPartition(const MdtWorldData *w, const KeaParameters *kea, int p)
{
    int rows = w->rows.partitionRowStart[p + 1] - w->rows.partitionRowStart[p];
    return rows > 0 && KeaSplits(rows, kea);
}

/* The task: partitions [start, end) on worker `worker`'s workspace (MdtRunStepTask checks the
 * range and the worker index); split partitions wait for the stepping thread. */
static void solveTask(int start, int end, int worker, void *data)
{
    SolveTask *t = data;
    const MdtStepRows *r = &t->w->rows;
    void *workspace = t->workspaces + (size_t)worker * t->need;
    for (int p = start; p < end; p++)
        if (r->partitionRowStart[p + 1] > r->partitionRowStart[p] && !splitPartition(t->w, t->kea, p))
            solvePartition(t->w, t->kea, p, workspace, t->need, &t->results[p]);
}

/* Kea's task hook (KeaTaskHook): a split partition's chunks as a step task over the world's workers. */
static void runKeaTask(KeaTaskFn task, int itemCount, int minRange, void *data, void *user)
{
    MdtRunStepTask(user, task, itemCount, minRange, data);
}

/* A partition's statistics into the step's, and its messages, in partition order. */
static void gatherPartition(MdtWorldData *w, int p, const KeaStats *ks)
{
    MdtSolverStats *stats = &w->solverStats;
    const MdtStepRows *r = &w->rows;
    int rows = r->partitionRowStart[p + 1] - r->partitionRowStart[p];
    KeaStatus status = ks->status;
    stats->partitions++;
    stats->rows += rows;
    if (rows > stats->maxPartitionRows)
        stats->maxPartitionRows = rows;
    if (ks->path == KeaPathDirect)
        stats->directPartitions++;
    else
        stats->iterativePartitions++;
    stats->iterations += ks->iterations;
    stats->pivots += ks->pivots;
    if (ks->colours > 0)
        stats->splitPartitions++;
    if (ks->colours > stats->maxColours)
        stats->maxColours = ks->colours;
    if (status != KeaStatusOk)
        stats->unconverged++;
    if (ks->residual > stats->maxResidual)
        stats->maxResidual = ks->residual;
    w->partitions.solverStatus[p] = (int)status;
    if (w->partitions.simError[p] == MdtSimErrorSolver)
        return;
    if (status == KeaStatusWorkspaceTooSmall)
        ME_REPORT_IN("MdtWorldStep", ME_ERR_KEA_WORKSPACE,
                     "the solver could not solve partition %d (%d rows): workspace too small; its constraints "
                     "were ignored this step",
                     p, rows);
    else if (status != KeaStatusOk)
        ME_REPORT_IN("MdtWorldStep", ME_ERR_KEA_MAX_ITERATIONS,
                     "partition %d (%d rows) stopped at the solver's cap (status %d, residual %g m/s)", p, rows,
                     (int)status, (double)ks->residual);
}

/* Bytes of `n` rounded up to a cache line, so that workers' workspaces do not share lines. */
static size_t cacheLines(size_t n) { return (n + 63) & ~(size_t)63; }

/* KeaMemoryRequired through the world's kept sizes (a direct-mapped memo: a layout pass costs hundreds
 * of instructions, a scene's partitions repeat a few shapes). */
static size_t workspaceBytes(MdtWorldData *w, int rows, int bodies, KeaPath path)
{
    const unsigned hash = (unsigned)rows + 7u * (unsigned)bodies + 31u * (unsigned)path;
    MdtWorkspaceSize *m = &w->workspaceSizes[hash % MDT_WORKSPACE_SIZES];
    if (m->rows != rows || m->bodies != bodies || m->path != path) {
        m->rows = rows;
        m->bodies = bodies;
        m->path = path;
        m->bytes = KeaMemoryRequired(rows, bodies, path);
    }
    return m->bytes;
}

void MdtSolveStage(MdtWorldData *w)
{
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    memset(&w->solverStats, 0, sizeof w->solverStats);
    if (!w->rowsPacked)
        return; /* pack could not lay out its rows: the integrator uses no velocity change */
    for (int i = 0; i < out->bodyCount; i++)
        memset(&r->dv[i], 0, sizeof r->dv[i]);
    if (r->count == 0)
        return;

    /* The extra effort's rest speed is above what gravity adds in this step (kea_tuning.h); a split
     * partition's sweeps go to the world's workers. */
    KeaParameters kea = w->kea;
    if (kea.effortRestSpeed > 0)
        kea.effortRestSpeed += MeVector3Magnitude(w->gravity) * w->stepSize;
    kea.tasks.run = runKeaTask;
    kea.tasks.user = w;
    kea.tasks.workers = w->enqueueTask ? w->workerCount : 1;
    kea.tasks.perStage = 0;

    /* One workspace per worker, for the largest partition (each partition's size is asked here, so
     * the solves need not size it again: KeaSolveSized); then one result per partition. */
    size_t need = 0;
    int splits = 0;
    for (int p = 0; p < out->partitionCount; p++) {
        int rows = r->partitionRowStart[p + 1] - r->partitionRowStart[p];
        int bodies = out->partitionStart[p + 1] - out->partitionStart[p];
        if (rows == 0)
            continue;
        const size_t bytes = workspaceBytes(w, rows, bodies, KeaSelectPath(rows, &kea)) +
                             KeaSplitMemoryRequired(rows, bodies, &kea);
        splits += splitPartition(w, &kea, p);
        if (bytes > need)
            need = bytes;
    }
    SolveTask task;
    task.w = w;
    task.workers = w->workerCount;
    task.need = task.workers > 1 ? cacheLines(need) : need;
    size_t workspaceBytes = task.need * (size_t)task.workers;
    size_t resultBytes = sizeof(PartitionResult) * (size_t)out->partitionCount;
    unsigned char *mem = MeChunkGetMem(&w->keaChunk, cacheLines(workspaceBytes) + resultBytes);
    if (!mem)
        return; /* reported by the chunk; the constraints act as if absent this step */
    task.workspaces = mem;
    task.results = (PartitionResult *)(mem + cacheLines(workspaceBytes));
    memset(task.results, 0, resultBytes);
    task.kea = &kea;

    MdtRunStepTask(w, solveTask, out->partitionCount, 1, &task);
    /* Split partitions, one after the other, on worker 0's workspace (no task runs any more), each
     * handing its sweeps to the workers. */
    for (int p = 0; p < out->partitionCount && splits > 0; p++)
        if (splitPartition(w, &kea, p))
            solvePartition(w, &kea, p, task.workspaces, task.need, &task.results[p]);

    for (int p = 0; p < out->partitionCount; p++)
        if (r->partitionRowStart[p + 1] > r->partitionRowStart[p])
            gatherPartition(w, p, &task.results[p].stats);
    MeChunkPutMem(&w->keaChunk, mem);
}
