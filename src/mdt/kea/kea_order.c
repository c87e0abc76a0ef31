/* kea_order.c -- the order in which the direct path factors a partition's rows.
 *
 * A = J M^-1 J^T couples two rows only when they share a body, so the factor's fill is decided by
 * the order in which bodies are "eliminated": factoring the rows of body b first couples every
 * remaining row on b's neighbours, as eliminating b from the body graph joins its neighbours. In a
 * tree of bodies (a chain, a ragdoll, anything resting on the world), eliminating leaves before
 * their parents joins nothing: the factor has no fill at all. The order used here: a depth-first
 * search from the body with the most rows, reversed, so that every body comes after the bodies
 * below it and each subtree's rows stay together (narrow envelopes, kea_dense.c). A row goes with
 * whichever of its bodies comes first; rows of one body keep their index order, so a constraint's
 * rows stay together. Graphs with loops get some fill, never more than the dense factor.
 *
 * Cost O(rows + bodies); no allocation (the scratch comes from the direct path's workspace). */
#include "kea_internal.h"

/* Rank of a row: that of its first-eliminated body; -1 for a row on no body. */
static int KeaRowRank(const KeaProblem *problem, const int *rank, int i)
{
    const int b0 = problem->rowBodies[i][0], b1 = problem->rowBodies[i][1];
    int r = b0 >= 0 ? rank[b0] : -1;
    if (b1 >= 0 && (r < 0 || rank[b1] < r))
        r = rank[b1];
    return r;
}

size_t KeaEliminationOrderScratch(int nRows, int nBodies) { return (size_t)(2 * nRows + 3 * nBodies + 2); }

void KeaEliminationOrder(const KeaProblem *problem, const int *incidence, const int *start, int *scratch,
                         int *order)
{
    const int n = problem->nRows, nb = problem->nBodies;
    int *rank = scratch;            /* nb: elimination rank of each body, -1 = not reached yet */
    int *stack = rank + nb;         /* 2n + nb: bodies waiting to be visited (with repeats) */
    int *count = stack + 2 * n + nb; /* nb + 2: rows per rank, then where each rank's rows start */
    int visited = 0, b, i, root;

    if (nb == 1) { /* a block or a ball on the world: the same order without the search */
        int k = 0;
        rank[0] = 0;
        for (i = 0; i < n; ++i)
            if (problem->rowBodies[i][0] < 0 && problem->rowBodies[i][1] < 0)
                order[k++] = i;
        for (i = 0; i < n; ++i)
            if (problem->rowBodies[i][0] >= 0 || problem->rowBodies[i][1] >= 0)
                order[k++] = i;
        return;
    }
    for (b = 0; b < nb; ++b)
        rank[b] = -1;
    /* Depth-first preorder from the busiest body (a ragdoll's torso: its limbs become subtrees);
     * further components, if any, from their first body. */
    root = 0;
    for (b = 1; b < nb; ++b)
        if (start[b + 1] - start[b] > start[root + 1] - start[root])
            root = b;
    while (visited < nb) {
        int top = 0;
        while (rank[root] >= 0)
            root = (root + 1) % nb;
        stack[top++] = root;
        while (top > 0) {
            const int v = stack[--top];
            int p;
            if (rank[v] >= 0)
                continue;
            rank[v] = nb - 1 - visited++; /* reversed preorder: descendants before ancestors */
            for (p = start[v]; p < start[v + 1]; ++p) {
                const int e = incidence[p], row = e >> 1, other = problem->rowBodies[row][1 - (e & 1)];
                if (other >= 0 && rank[other] < 0)
                    stack[top++] = other;
            }
        }
    }

    /* Rows by the rank of their first-eliminated body (a counting sort, stable in row index). */
    for (b = 0; b <= nb + 1; ++b)
        count[b] = 0;
    for (i = 0; i < n; ++i) /* a row on no body couples to nothing: rank -1, first */
        ++count[KeaRowRank(problem, rank, i) + 2];
    for (b = 0; b <= nb; ++b)
        count[b + 1] += count[b];
    for (i = 0; i < n; ++i)
        order[count[KeaRowRank(problem, rank, i) + 1]++] = i;
}
