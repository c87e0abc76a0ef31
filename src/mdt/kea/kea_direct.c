/* kea_direct.c -- Kea's direct path: one partition solved exactly.
 *
 * Forms the dense A = J M^-1 J^T + diag(eps) (kea_dense.c; each row touches at most two bodies, so
 * only rows sharing a body interact) and hands it with the rows' rhs, bounds and friction links to
 * the dense box-LCP solver (kea_dense_lcp.c: primal active set with an updatable Cholesky factor,
 * friction passes and a Woodbury polish of the coupled friction). Then Delta v = M^-1 J^T x.
 *
 * Cost: forming A is O(n^2) to clear plus O(sum over bodies of degree^2) dot products; the solve is
 * about one Cholesky factorisation, O(n^3 / 3), plus O(n^2) per pivot; memory is about 2.75 n^2 reals
 * (A, the factor, the polish's Woodbury columns). */
#include "kea_internal.h"

typedef struct KeaDirectWork {
    KeaJacobianRow *B;  /**< M^-1 J^T per row */
    MeReal *A;          /**< n x n */
    int *incidence;     /**< 2n: body -> row incidence for forming A */
    int *start;         /**< nb + 1 */
    KeaDenseWork *lcp;  /**< the dense solver's workspace */
} KeaDirectWork;

static void KeaDirectLayout(KeaArena *arena, int n, int nb, KeaDirectWork *w)
{
    w->B = KEA_ALLOC(arena, KeaJacobianRow, n);
    w->A = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)n);
    w->incidence = KEA_ALLOC(arena, int, 2 * n);
    w->start = KEA_ALLOC(arena, int, nb + 1);
    w->lcp = KeaDenseWorkCreate(arena, n);
}

size_t KeaDirectWorkspaceBytes(int nRows, int nBodies)
{
    KeaArena counter = {NULL, 0, 0};
    KeaDirectWork w;
    KeaDirectLayout(&counter, nRows, nBodies, &w);
    return counter.used;
}

KeaStatus KeaSolveDirect(const KeaProblem *problem, const KeaParameters *params, KeaArena *arena,
                         MeReal *x, KeaBodyVelocity *dv, KeaStats *stats)
{
    const int n = problem->nRows;
    KeaDirectWork w;
    KeaDenseLcp lcp;
    KeaStatus status;
    int i;

    KeaDirectLayout(arena, n, problem->nBodies, &w);
    for (i = 0; i < n; ++i)
        (void)KeaRowInvMassJT(problem, i, &w.B[i]);
    KeaFormDenseMatrix(problem, w.B, w.A, w.incidence, w.start);

    lcp.n = n;
    lcp.A = w.A;
    lcp.r = problem->rhs;
    lcp.lo = problem->lo;
    lcp.hi = problem->hi;
    lcp.link = problem->link;
    lcp.mu = problem->mu;
    status = KeaDenseLcpSolve(&lcp, params->maxPivots, params->maxFrictionPasses, w.lcp, x, stats);
    KeaBodyVelocityFromImpulses(problem, x, dv);
    return status;
}
