/* kea_solve.c -- Kea's front door: default parameters, the choice between the direct and the
 * iterative path, the workspace size query, input validation and the dispatch.
 *
 * The workspace: each path lays its arrays out with one function that runs either on a counting
 * arena (KeaMemoryRequired) or on the caller's buffer (KeaSolve), so the two can never disagree.
 * The caller's buffer may have any alignment: KeaMemoryRequired includes KEA_ALIGN - 1 bytes so that
 * KeaSolve can align the base itself. */
#include <stdatomic.h>
#include <string.h>

#include "kea_internal.h"
#include "kea_iterative.h"

void KeaParametersDefault(KeaParameters *params)
{
    params->path = KeaPathAuto;
    params->maxDirectRows = 128;
    params->maxIterations = 10;
    params->tolerance = ME_R(1e-6);
    params->sor = ME_R(1.0);
    params->subspaceIterations = 4;
    params->maxBlockRows = 12;
    params->maxPivots = 0;
    params->maxFrictionPasses = 8;
    params->effortResidual = ME_R(0.0);
    params->effortRestSpeed = ME_R(0.0);
    params->autoPivotsPerRow = ME_R(0.0);
    params->splitRows = 0;
    params->tasks.run = NULL;
    params->tasks.user = NULL;
    params->tasks.workers = 1;
    params->tasks.perStage = 0;
    params->nonsmoothCg = 0;
    params->subspaceEvery = 1;
    params->subspaceStop = ME_R(0.0);
    params->subspaceJointShare = ME_R(0.0);
    params->subspaceJointEvery = 0;
    params->deflation = 0;
}

KeaPath KeaSelectPath(int nRows, const KeaParameters *params)
{
    if (params->path == KeaPathDirect || params->path == KeaPathIterative)
        return params->path;
    if (nRows <= params->maxDirectRows) /* with a pivot budget, the iterative path may finish it */
        return params->autoPivotsPerRow > ME_R(0.0) ? KeaPathAuto : KeaPathDirect;
    if ((long long)nRows <= KEA_SPARSE_DIRECT_FACTOR * (long long)params->maxDirectRows)
        return KeaPathAuto; /* direct if the factor is sparse enough: decided by KeaSolve */
    return KeaPathIterative;
}

static size_t KeaVelocityBytes(int nBodies)
{
    return (sizeof(KeaBodyVelocity) * (size_t)nBodies + (KEA_ALIGN - 1)) & ~(size_t)(KEA_ALIGN - 1);
}

size_t KeaMemoryRequired(int nRows, int nBodies, KeaPath path)
{
    size_t bytes;
    if (nRows < 0 || nBodies < 0)
        return 0;
    switch (path) {
    case KeaPathDirect:
        bytes = KeaDirectWorkspaceBytes(nRows, nBodies);
        break;
    case KeaPathIterative:
        bytes = KeaIterativeWorkspaceBytes(nRows, nBodies);
        break;
    default: {
        const size_t direct = KeaDirectWorkspaceBytes(nRows, nBodies);
        const size_t iterative = KeaIterativeWorkspaceBytes(nRows, nBodies);
        bytes = direct > iterative ? direct : iterative;
        break;
    }
    }
    /* + room for dv when the caller does not want it, + the alignment of the caller's base. */
    return bytes + KeaVelocityBytes(nBodies) + (KEA_ALIGN - 1);
}

/* KeaIsFinite as one comparison, |v| < MEINFINITY (false for a NaN), so that many of them can be
 * combined with & without a branch each. */
static int KeaIsFiniteFlag(MeReal v) { return KeaFabs(v) < MEINFINITY; }

/* The declared contacts keep KeaContact's promise (kea.h): in row order, not overlapping, each one's
 * three rows on the same two distinct bodies (the first not the world), the normal row [0, inf)
 * without a link, the friction rows linked to it without bounds of their own. */
static int KeaContactsAreValid(const KeaProblem *p)
{
    int c, k, next = 0;
    if (p->nContacts < 0 || (p->nContacts > 0 && (!p->contacts || !p->link)))
        return 0;
    for (c = 0; c < p->nContacts; ++c) {
        const int s = p->contacts[c].row;
        const int *b;
        int ok;
        if (s < next || s + 2 >= p->nRows) /* next >= 0, so s too */
            return 0;
        b = p->rowBodies[s];
        /* combined with & into one flag, one branch per contact, as a row's (KeaProblemIsValid) */
        const int normalUnbounded = !KeaIsFiniteFlag(p->hi[s]);
        ok = (b[0] >= 0) & (b[0] != b[1]) & (p->link[s] == -1) & (p->lo[s] == ME_R(0.0)) & normalUnbounded;
        for (k = 1; k < 3; ++k) {
            const int frictionUnbounded = (KeaIsFiniteFlag(p->lo[s + k]) | KeaIsFiniteFlag(p->hi[s + k])) == 0;
            ok &= (p->rowBodies[s + k][0] == b[0]) & (p->rowBodies[s + k][1] == b[1]) & (p->link[s + k] == s) &
                  frictionUnbounded;
        }
        if (!ok)
            return 0;
        next = s + 3;
    }
    return 1;
}

/* Rows [i0, i1) of KeaProblemIsValid: indices in range, bounds ordered, softness non-negative,
 * numbers where numbers are needed (finite in Karma's sense: within +-MEINFINITY). Every step's every
 * row goes through here, and bad input is rare: the tests are combined with & into one flag over all
 * the rows (a comparison with a NaN is false), array by array, so the loops have no branch to take;
 * only the friction links, whose test reads another row, return at the first bad one. */
static int KeaRowsAreValid(const KeaProblem *p, int i0, int i1)
{
    int ok = 1, i;
    for (i = i0; i < i1; ++i) {
        const KeaJacobianRow *J = &p->J[i];
        ok &= (p->rowBodies[i][0] >= KEA_WORLD) & (p->rowBodies[i][0] < p->nBodies) &
              (p->rowBodies[i][1] >= KEA_WORLD) & (p->rowBodies[i][1] < p->nBodies) & (p->lo[i] <= p->hi[i]) &
              KeaIsFiniteFlag(p->rhs[i]) &
              KeaLanesFinite3x4(J->lin0, J->ang0, J->lin1, J->ang1); /* the pads are not read as numbers */
    }
    if (p->epsilon)
        for (i = i0; i < i1; ++i)
            ok &= (p->epsilon[i] >= ME_R(0.0)) & KeaIsFiniteFlag(p->epsilon[i]);
    if (p->x0)
        for (i = i0; i < i1; ++i)
            ok &= KeaIsFiniteFlag(p->x0[i]);
    if (!ok)
        return 0;
    if (p->link)
        for (i = i0; i < i1; ++i) {
            const int l = p->link[i];
            if (l < -1)
                return 0;
            if (l >= 0 && (l >= p->nRows || l == i || p->link[l] >= 0 ||
                           !((p->mu[i] >= ME_R(0.0)) & KeaIsFiniteFlag(p->mu[i]))))
                return 0;
        }
    return 1;
}

/* A partition that will be split checks its rows in chunks over the caller's workers (one task
 * before the solve's own): a chunk that finds a bad row says so; the answer does not depend on which
 * chunks ran where. A task system that leaves chunks out (or runs one twice) has the rows checked
 * here instead. */
typedef struct KeaRowsCheck {
    const KeaProblem *problem;
    atomic_int invalid, chunksRun;
} KeaRowsCheck;

static void KeaRowsCheckChunks(int start, int end, int worker, void *data)
{
    KeaRowsCheck *t = data;
    const int n = t->problem->nRows;
    int j;
    (void)worker;
    for (j = start; j < end; ++j) {
        if (!KeaRowsAreValid(t->problem, j * KEA_SPLIT_ROWS, KeaRowChunkEnd(j, n)))
            atomic_store_explicit(&t->invalid, 1, memory_order_relaxed);
        atomic_fetch_add_explicit(&t->chunksRun, 1, memory_order_relaxed);
    }
}

/* The rows keep kea.h's promises (KeaRowsAreValid): in chunks over params' workers when the
 * partition will be split (on one worker the same chunks, here). */
static int KeaProblemRowsAreValid(const KeaProblem *p, const KeaParameters *params)
{
    if (KeaSplits(p->nRows, params)) {
        const int chunks = KeaRowChunkCount(p->nRows);
        KeaRowsCheck check;
        check.problem = p;
        atomic_init(&check.invalid, 0);
        atomic_init(&check.chunksRun, 0);
        if (params->tasks.run && params->tasks.workers > 1)
            params->tasks.run(KeaRowsCheckChunks, chunks, 1, &check, params->tasks.user);
        else
            KeaRowsCheckChunks(0, chunks, 0, &check);
        if (atomic_load_explicit(&check.chunksRun, memory_order_relaxed) != chunks)
            return KeaRowsAreValid(p, 0, p->nRows);
        return !atomic_load_explicit(&check.invalid, memory_order_relaxed);
    }
    return KeaRowsAreValid(p, 0, p->nRows);
}

/* The problem keeps kea.h's promises (the bodies, the rows, the declared contacts); the rows not
 * checked when the caller proved them (KeaSolveRowsProved). */
static int KeaProblemIsValid(const KeaProblem *p, const KeaParameters *params, int rowsProved)
{
    int b, k;
    if (p->nRows < 0 || p->nBodies < 0)
        return 0;
    if (p->nRows > 0 && (!p->J || !p->rowBodies || !p->rhs || !p->lo || !p->hi))
        return 0;
    if (p->nBodies > 0 && !p->bodies)
        return 0;
    if (p->link && !p->mu)
        return 0;
    for (b = 0; b < p->nBodies; ++b) {
        const KeaBody *body = &p->bodies[b];
        int ok = (body->invMass >= ME_R(0.0)) & KeaIsFiniteFlag(body->invMass);
        for (k = 0; k < 9; ++k)
            ok &= KeaIsFiniteFlag(body->invInertia[k / 3][k % 3]);
        if (!ok)
            return 0;
    }
    if (!rowsProved && !KeaProblemRowsAreValid(p, params))
        return 0;
    return KeaContactsAreValid(p);
}

/* What the caller did already (KeaSolveIn's `done`): sized the workspace for this problem
 * (KeaSolveSized), proved the rows valid (KeaSolveRowsProved). */
#define KEA_DONE_SIZED 1
#define KEA_DONE_ROWS_PROVED 2

/* Size: KeaSolve's arguments (the problem, its parameters, the caller's workspace and the three
 * outputs), and what the caller did already (KEA_DONE_*). */
static KeaStatus KeaSolveIn(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                            size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *statsOut, int done)
{
    KeaStats localStats, *stats = statsOut ? statsOut : &localStats;
    KeaArena arena;
    KeaPath path;
    KeaBodyVelocity *velocity = dv;
    size_t need = 0, skew;
    int i;

    memset(stats, 0, sizeof *stats);
    if (!params) {
        stats->status = KeaStatusBadInput;
        return stats->status;
    }
    path = KeaSelectPath(problem ? problem->nRows : 0, params);
    stats->path = path;
    if (!problem || (!x && problem->nRows > 0) ||
        !KeaProblemIsValid(problem, params, (done & KEA_DONE_ROWS_PROVED) != 0)) {
        stats->status = KeaStatusBadInput;
        return stats->status;
    }
    stats->rows = problem->nRows;
    stats->bodies = problem->nBodies;

    /* Align the workspace base; the velocity output gets workspace room when the caller has none. */
    if (!(done & KEA_DONE_SIZED)) /* a layout pass over the workspace's allocations: hundreds of instructions */
        need = KeaMemoryRequired(problem->nRows, problem->nBodies, path) +
               KeaSplitMemoryRequired(problem->nRows, problem->nBodies, params);
    skew = workspace ? (size_t)((KEA_ALIGN - ((uintptr_t)workspace & (KEA_ALIGN - 1))) & (KEA_ALIGN - 1)) : 0;
    if (!workspace || workspaceSize < need) {
        stats->status = KeaStatusWorkspaceTooSmall;
        return stats->status;
    }
    arena.base = (unsigned char *)workspace + skew;
    arena.size = workspaceSize - skew;
    arena.used = 0;
    if (!velocity) /* Kea needs dv internally: without an output array it lives in the workspace */
        velocity = KEA_ALLOC(&arena, KeaBodyVelocity, problem->nBodies);
    else
        (void)KeaArenaAlloc(&arena, KeaVelocityBytes(problem->nBodies)); /* same layout either way */

    if (problem->x0) {
        if (x != problem->x0)
            for (i = 0; i < problem->nRows; ++i)
                x[i] = problem->x0[i];
    } else {
        for (i = 0; i < problem->nRows; ++i)
            x[i] = ME_R(0.0);
    }

    if (path == KeaPathAuto) { /* direct unless the factor is not sparse enough (above maxDirectRows) or
                                * the pivots run over their budget: then iterative, from x as left */
        KeaArena tryArena = arena;
        stats->status = KeaSolveDirect(problem, params, &tryArena, problem->nRows > params->maxDirectRows, x,
                                       velocity, stats);
        path = stats->status == KeaStatusDeclined || stats->status == KeaStatusOverBudget ? KeaPathIterative
                                                                                         : KeaPathDirect;
        stats->handedOver = stats->status == KeaStatusOverBudget;
        stats->path = path;
    } else if (path == KeaPathDirect) {
        stats->status = KeaSolveDirect(problem, params, &arena, 0, x, velocity, stats);
    }
    if (path == KeaPathIterative)
        stats->status = KeaSolveIterative(problem, params, &arena, x, velocity, stats,
                                          (done & KEA_DONE_ROWS_PROVED) != 0);
    return stats->status;
}

/* Size: the problem, its parameters, the caller's workspace (pointer and size) and the three
 * outputs, each its own argument so that the caller owns every buffer (kea.h). */
KeaStatus KeaSolve(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                   size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats)
{
    return KeaSolveIn(problem, params, workspace, workspaceSize, x, dv, stats, 0);
}

/* Size: KeaSolve's. */
KeaStatus KeaSolveSized(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                        size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats)
{
    return KeaSolveIn(problem, params, workspace, workspaceSize, x, dv, stats, KEA_DONE_SIZED);
}

/* Size: KeaSolve's. */
KeaStatus KeaSolveRowsProved(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                             size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats)
{
    return KeaSolveIn(problem, params, workspace, workspaceSize, x, dv, stats, KEA_DONE_SIZED | KEA_DONE_ROWS_PROVED);
}
