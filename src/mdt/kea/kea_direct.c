/* kea_direct.c -- Kea's direct path: one partition solved exactly.
 *
 * Forms A = J M^-1 J^T + diag(eps) (kea_dense.c; each row touches at most two bodies, so only rows
 * sharing a body interact: that is A's pattern), orders the rows so that the Cholesky factor stays
 * sparse (kea_order.c), and hands A with the rows' rhs, bounds, friction links, order, pattern and
 * the rows themselves to the box-LCP solver (kea_dense_lcp.c: primal active set with an updatable
 * Cholesky factor, friction passes and a Woodbury polish of the coupled friction). Then
 * Delta v = M^-1 J^T x and the residual, unless the polish's acceptance test has just computed both
 * for the very x it returns (KeaDenseLcpFinalVelocity).
 *
 * Cost: the factor works on envelopes (kea_dense.c): about linear in the rows for a chain or a tree
 * of bodies, O(n^3 / 6) at worst (every row coupled to every other); a product with A goes through
 * the bodies, O(n). Storage is still dense, about 3.75 n^2 reals and ints (A, the factor, the polish's
 * Woodbury columns, the pattern), which is why KeaPathAuto takes this path only up to
 * 4 maxDirectRows rows.
 *
 * Auto's choice above maxDirectRows rows (mayDecline): after ordering, the factor's envelope is
 * counted; if it exceeds maxDirectRows (maxDirectRows + 1) / 2 entries, a dense factor of
 * maxDirectRows rows, the path declines (KeaStatusDeclined) before forming A and the iterative
 * path solves the partition instead. Auto's pivot budget (KeaParameters.autoPivotsPerRow), for
 * partitions of at most maxDirectRows rows: a solve that needs more pivots stops there
 * (KeaStatusOverBudget) and the iterative path finishes it from the feasible iterate it left
 * (docs/kea.md, "Worst frames"). */
#include <string.h>

#include "kea_internal.h"

typedef struct KeaDirectWork {
    KeaJacobianRow *B;  /**< M^-1 J^T per row */
    KeaBodyColumns *bodyColumns; /**< nb: inverse masses and inertia columns, for B */
    MeReal *A;          /**< n x n */
    int *incidence;     /**< 2n: body -> row incidence for forming A */
    int *start;         /**< nb + 1 */
    int *order;         /**< n: factoring order (kea_order.c) */
    int *patternStart;  /**< n + 1: A's structural non-zeros by row (rows sharing a body) */
    int *pattern;       /**< at most n^2 */
    int *mark;          /**< n: scratch for building the pattern */
    int *orderScratch;  /**< KeaEliminationOrderScratch ints */
    MeReal *formColumns; /**< KeaFormScratchReals: one body's rows while forming A */
    int *formInts;      /**< KeaFormScratchInts */
    KeaDenseWork *lcp;  /**< the dense solver's workspace */
    KeaBodyFactor *body; /**< the free rows in body coordinates (kea_body_factor.c), when it fits */
} KeaDirectWork;

static void KeaDirectLayout(KeaArena *arena, int n, int nb, KeaDirectWork *w)
{
    w->B = KEA_ALLOC(arena, KeaJacobianRow, n);
    w->A = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)n);
    w->incidence = KEA_ALLOC(arena, int, 2 * n);
    w->start = KEA_ALLOC(arena, int, nb + 1);
    w->order = KEA_ALLOC(arena, int, n);
    w->patternStart = KEA_ALLOC(arena, int, n + 1);
    w->pattern = KEA_ALLOC(arena, int, (size_t)n * (size_t)n);
    w->mark = KEA_ALLOC(arena, int, n);
    w->orderScratch = KEA_ALLOC(arena, int, KeaEliminationOrderScratch(n, nb));
    w->formColumns = KEA_ALLOC(arena, MeReal, KeaFormScratchReals(n));
    w->formInts = KEA_ALLOC(arena, int, KeaFormScratchInts(n));
    w->lcp = KeaDenseWorkCreate(arena, n);
    w->bodyColumns = KEA_ALLOC(arena, KeaBodyColumns, nb);
    w->body = KeaBodyFactorCreate(arena, n, nb);
}

/* Row i's structural non-zeros: every row on one of its bodies (itself included), once each. */
static void KeaDirectPattern(const KeaProblem *problem, const int *incidence, const int *start, KeaDirectWork *w)
{
    const int n = problem->nRows;
    int i, h, p, count = 0;
    for (i = 0; i < n; ++i)
        w->mark[i] = -1;
    for (i = 0; i < n; ++i) {
        w->patternStart[i] = count;
        if (i > 0 && (problem->rowBodies[i][0] >= 0 || problem->rowBodies[i][1] >= 0) &&
            problem->rowBodies[i][0] == problem->rowBodies[i - 1][0] &&
            problem->rowBodies[i][1] == problem->rowBodies[i - 1][1]) {
            /* the next row of the same constraint (same bodies): the same rows, in the same order */
            const int prev = w->patternStart[i - 1], len = count - prev;
            memcpy(w->pattern + count, w->pattern + prev, sizeof(int) * (size_t)len);
            count += len;
            continue;
        }
        for (h = 0; h < 2; ++h) {
            const int b = problem->rowBodies[i][h];
            if (b < 0)
                continue;
            for (p = start[b]; p < start[b + 1]; ++p) {
                const int col = incidence[p] >> 1;
                if (w->mark[col] != i) {
                    w->mark[col] = i;
                    w->pattern[count++] = col;
                }
            }
        }
        if (w->mark[i] != i) /* a row on no body still has its diagonal */
            w->pattern[count++] = i;
    }
    w->patternStart[n] = count;
}

size_t KeaDirectWorkspaceBytes(int nRows, int nBodies)
{
    KeaArena counter = {NULL, 0, 0};
    KeaDirectWork w;
    KeaDirectLayout(&counter, nRows, nBodies, &w);
    return counter.used;
}

/* Entries of the factor's envelope, sum over k of (k - first_k), if every row were free: an upper
 * bound of the factor's and a solve's work in the rows' factoring order. */
static long long KeaDirectEnvelope(int n, const KeaDirectWork *w)
{
    long long envelope = 0;
    int k, j;
    for (k = 0; k < n; ++k) /* position of each row in the order (mark is free scratch again) */
        w->mark[w->order[k]] = k;
    for (k = 0; k < n; ++k) {
        const int i = w->order[k];
        int first = k;
        for (j = w->patternStart[i]; j < w->patternStart[i + 1]; ++j)
            if (w->mark[w->pattern[j]] < first)
                first = w->mark[w->pattern[j]];
        envelope += k - first;
    }
    return envelope;
}

/* The row factor's structures: A's pattern, M^-1 J^T of every row and A itself. Returns 0 when Auto
 * may decline the partition and its factor's envelope is over the budget (then nothing is formed). */
static int KeaDirectRowSetUp(const KeaProblem *problem, const KeaParameters *params, int mayDecline,
                             KeaDirectWork *w)
{
    const int n = problem->nRows;
    int i;
    KeaDirectPattern(problem, w->incidence, w->start, w);
    if (mayDecline) {
        const long long budget = (long long)params->maxDirectRows * ((long long)params->maxDirectRows + 1) / 2;
        if (KeaDirectEnvelope(n, w) > budget)
            return 0;
    }
    for (i = 0; i < n; ++i)
        (void)KeaRowInvMassJT4(problem, w->bodyColumns, i, &w->B[i]);
    KeaFormDenseMatrix(problem, w->B, w->A, w->incidence, w->start, w->patternStart, w->pattern, w->formColumns,
                       w->formInts);
    return 1;
}

/* Whether the partition's free rows go through its bodies' coordinates first (kea_body_factor.c:
 * a partition of two or more bodies with more than 18 rows, at least 1.5 a body coordinate, enough
 * softness): then only A's diagonal is formed (into A, for the solver and the residual). */
static int KeaDirectBodySetUp(const KeaProblem *problem, int mayDecline, KeaDirectWork *w)
{
    const int n = problem->nRows;
    int i;
    if (!w->body || mayDecline)
        return 0;
    for (i = 0; i < n; ++i)
        w->A[(size_t)i * (size_t)n + (size_t)i] = KeaRowInvMassJT4(problem, w->bodyColumns, i, &w->B[i]);
    return KeaBodyFactorBegin(w->body, problem, w->bodyColumns, w->orderScratch, w->A, (size_t)n + 1);
}

/* The dense solver's view of the partition: A (or its diagonal), the rows, the order, and the
 * pattern when the row factor is used. */
static void KeaDirectLcp(const KeaProblem *problem, const KeaDirectWork *w, int bodySpace, KeaBodyVelocity *dv,
                         KeaDenseLcp *lcp)
{
    lcp->n = problem->nRows;
    lcp->A = w->A;
    lcp->r = problem->rhs;
    lcp->lo = problem->lo;
    lcp->hi = problem->hi;
    lcp->link = problem->link;
    lcp->mu = problem->mu;
    lcp->order = w->order;
    lcp->patternStart = bodySpace ? NULL : w->patternStart;
    lcp->pattern = bodySpace ? NULL : w->pattern;
    lcp->rows = problem;
    lcp->velocity = dv; /* scratch until the final velocity change */
}

/* The pivot cap of the solve, and whether it is Auto's budget (past it, the iterative path). */
static int KeaDirectPivotCap(const KeaParameters *params, int n, int *budgeted)
{
    int maxPivots = params->maxPivots;
    /* Only a partition of at most maxDirectRows rows: a larger one is on this path because its bodies
     * form a tree (a chain, a column), where the iterative path's answer is far from the exact one */
    *budgeted = params->path == KeaPathAuto && params->autoPivotsPerRow > ME_R(0.0) && n <= params->maxDirectRows;
    if (*budgeted) { /* Auto's pivot budget (the worst frames, docs/kea.md) */
        const MeReal budget = params->autoPivotsPerRow * (MeReal)n + (MeReal)KEA_AUTO_PIVOTS_EXTRA;
        maxPivots = (int)budget;
        if (params->maxPivots > 0 && params->maxPivots < maxPivots) {
            maxPivots = params->maxPivots;
            *budgeted = 0; /* the caller's own cap is the tighter one and keeps its meaning */
        }
    }
    return maxPivots;
}

/* Size: KeaSolve's contract (problem, parameters, workspace, the three outputs) and whether it may
 * decline the partition to the iterative path. The body factor (kea_body_factor.c) is tried first
 * where it fits, for a solve without pivots (a resting stack: one factorisation, no A formed); at
 * the first pivot the solve starts again from the warm start with the row factor, whose pivots
 * cost less than the body factor's refactorisations, and gives the row factor's bits. */
KeaStatus KeaSolveDirect(const KeaProblem *problem, const KeaParameters *params, KeaArena *arena,
                         int mayDecline, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats)
{
    const int n = problem->nRows;
    KeaDirectWork w;
    KeaDenseLcp lcp;
    KeaStatus status;
    int i, budgeted, maxPivots;

    KeaDirectLayout(arena, n, problem->nBodies, &w);
    KeaBodyIncidence(problem, w.incidence, w.start);
    KeaEliminationOrder(problem, w.incidence, w.start, w.orderScratch, w.order);
    KeaBodyColumnsFill(problem, w.bodyColumns);
    maxPivots = KeaDirectPivotCap(params, n, &budgeted);
    status = KeaStatusMaxPivots;
    if (KeaDirectBodySetUp(problem, mayDecline, &w)) {
        const KeaStats before = *stats;
        for (i = 0; i < n; ++i) /* the warm start, for the row factor if a pivot comes */
            w.formColumns[i] = x[i];
        KeaDenseWorkUseBodyFactor(w.lcp, w.body);
        KeaDirectLcp(problem, &w, 1, dv, &lcp);
        status = KeaDenseLcpSolve(&lcp, 1, params->maxFrictionPasses, w.lcp, x, stats);
        if (status == KeaStatusMaxPivots) {
            for (i = 0; i < n; ++i)
                x[i] = w.formColumns[i];
            *stats = before;
        } else {
            stats->bodyFactor = 1;
        }
    }
    if (status == KeaStatusMaxPivots) {
        KeaDenseWorkUseBodyFactor(w.lcp, NULL);
        if (!KeaDirectRowSetUp(problem, params, mayDecline, &w))
            return KeaStatusDeclined;
        KeaDirectLcp(problem, &w, 0, dv, &lcp);
        status = KeaDenseLcpSolve(&lcp, maxPivots, params->maxFrictionPasses, w.lcp, x, stats);
        if (budgeted && status == KeaStatusMaxPivots)
            return KeaStatusOverBudget;
    }
    if (!KeaDenseLcpFinalVelocity(w.lcp, &stats->residual)) { /* else dv and the residual are x's */
        KeaBodyVelocityFromImpulses(problem, x, dv);
        stats->residual = KeaResidualWithDiagonal(problem, x, dv, w.A, (size_t)n + 1);
    }
    return status;
}
