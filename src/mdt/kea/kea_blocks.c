/* kea_blocks.c -- block set-up of Kea's iterative path (kea_iterative.h): the workspace layout, the
 * split of the rows into blocks (a constraint's rows on one body pair, a contact point with its
 * friction rows), each block's matrix A_bb = J_b M^-1 J_b^T + diag(eps), its factor and inverse, and
 * which blocks are declared contacts (KeaContact; the sweep's contact step). */
#include "kea_block_kernels.h"
#include "kea_contact_packs.h"
#include "kea_joint_packs.h"

void KeaIterativeLayout(KeaArena *arena, int n, int nb, int maxBlockRows, KeaIterativeWork *w)
{
    const int cap = KeaBlockCap(n, maxBlockRows), positions = KeaFreePositions(n);
    w->B = KEA_ALLOC(arena, KeaJacobianRow, n);
    w->invDiag = KEA_ALLOC(arena, MeReal, n);
    w->diag = KEA_ALLOC(arena, MeReal, n);
    w->blockStart = KEA_ALLOC(arena, int, n + 1);
    w->blockMatrix = KEA_ALLOC(arena, int, n);
    w->blockA = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)cap);
    w->blockInv = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)cap);
    w->blockFactored = KEA_ALLOC(arena, unsigned char, n);
    w->blockContact = KEA_ALLOC(arena, unsigned char, n);
    w->wasFree = KEA_ALLOC(arena, unsigned char, n);
    w->localW = KEA_ALLOC(arena, MeReal, cap);
    w->rowBlock = KEA_ALLOC(arena, int, n);
    w->pieces = KEA_ALLOC(arena, KeaFreePiece, n);
    w->loosePieces = KEA_ALLOC(arena, int, n);
    w->packs = KEA_ALLOC(arena, KeaContactPack, n / 12 + 1);
    w->packed = KEA_ALLOC(arena, unsigned char, n);
    w->jointPacks = KEA_ALLOC(arena, KeaJointPack, KeaJointPacksMax(n));
    w->jointPackOf = KEA_ALLOC(arena, int, n);
    w->localR = KEA_ALLOC(arena, MeReal, cap);
    w->localLo = KEA_ALLOC(arena, MeReal, cap);
    w->localHi = KEA_ALLOC(arena, MeReal, cap);
    w->localX = KEA_ALLOC(arena, MeReal, cap);
    w->localLink = KEA_ALLOC(arena, int, cap);
    w->dense = KeaDenseWorkCreate(arena, cap);
    w->freeRows = KEA_ALLOC(arena, int, positions);
    w->lo = KEA_ALLOC(arena, MeReal, positions);
    w->hi = KEA_ALLOC(arena, MeReal, positions);
    w->xFree = KEA_ALLOC(arena, MeReal, positions);
    w->grad = KEA_ALLOC(arena, MeReal, positions);
    w->epsFree = KEA_ALLOC(arena, MeReal, positions);
    w->step = KEA_ALLOC(arena, MeReal, positions);
    w->res = KEA_ALLOC(arena, MeReal, positions);
    w->z = KEA_ALLOC(arena, MeReal, positions);
    w->dir = KEA_ALLOC(arena, MeReal, positions);
    w->q = KEA_ALLOC(arena, MeReal, positions);
    w->paddedJ = KEA_ALLOC(arena, KeaJacobianRow, n);
    w->J = w->paddedJ;
    w->JT = KEA_ALLOC(arena, MeReal, (size_t)n * 12);
    w->localD = KEA_ALLOC(arena, MeReal, cap);
    w->body = (int(*)[2])KeaArenaAlloc(arena, sizeof(int[2]) * (size_t)n);
    w->eps = KEA_ALLOC(arena, MeReal, n);
    w->dv = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->dvTmp = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->dvStep = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->clamped = KEA_ALLOC(arena, int, positions);
    w->xPrev = KEA_ALLOC(arena, MeReal, n);
    w->nncgDir = KEA_ALLOC(arena, MeReal, n);
    w->dvPrev = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->dvDir = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->xStart = KEA_ALLOC(arena, MeReal, n);
    w->dvStart = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->bodyColumns = KEA_ALLOC(arena, KeaBodyColumns, nb);
    w->nb = nb;
    w->split = NULL;
}

size_t KeaIterativeWorkspaceBytes(int nRows, int nBodies)
{
    KeaArena counter = {NULL, 0, 0};
    KeaIterativeWork w;
    KeaIterativeLayout(&counter, nRows, nBodies, KEA_MAX_BLOCK_ROWS, &w);
    return counter.used;
}

/* inv = (L L^T)^-1 = L^-T L^-1 (about m^3 / 3 multiply-adds, once per block and step): first
 * R = L^-1 (lower triangular) row by row, row r = -(sum_{j<r} L_rj R_j) / L_rr over its columns
 * c < r, then the upper triangle of R^T R, inv_rc = sum_{k>=c} R_kr R_kc, mirrored. Every sum runs
 * over its index in increasing order; the inner loops are contiguous rows of R. */
static inline void KeaBlockInvert(int m, const MeReal *L, MeReal *inv)
{
    MeReal R[KEA_MAX_BLOCK_ROWS * KEA_MAX_BLOCK_ROWS], acc[KEA_MAX_BLOCK_ROWS];
    int r, c, j, k;
    for (r = 0; r < m; ++r) {
        const MeReal invDiag = ME_R(1.0) / L[r * m + r];
        MeReal *Rr = R + r * m;
        for (c = 0; c < r; ++c)
            acc[c] = ME_R(0.0);
        for (j = 0; j < r; ++j) { /* R_jc = 0 for c > j */
            const MeReal l = L[r * m + j];
            const MeReal *Rj = R + j * m;
            for (c = 0; c <= j; ++c)
                acc[c] += l * Rj[c];
        }
        for (c = 0; c < r; ++c)
            Rr[c] = -acc[c] * invDiag;
        Rr[r] = invDiag;
    }
    for (r = 0; r < m; ++r) {
        for (c = r; c < m; ++c)
            acc[c] = ME_R(0.0);
        for (k = r; k < m; ++k) { /* R_kc = 0 for c > k */
            const MeReal a = R[k * m + r];
            const MeReal *Rk = R + k * m;
            for (c = r; c <= k; ++c)
                acc[c] += a * Rk[c];
        }
        for (c = r; c < m; ++c)
            inv[r * m + c] = inv[c * m + r] = acc[c];
    }
}

/* Generic rows: row i heads a link group, the rows that follow it linked to it (a normal row and
 * its friction rows written as generic rows, e.g. an adhesive contact's). Such a group is a block
 * of its own, never part of a longer run: a friction link then stays inside its block. */
static int KeaLinkGroupStart(const KeaProblem *problem, int i)
{
    return problem->link && problem->link[i] < 0 && i + 1 < problem->nRows && problem->link[i + 1] == i;
}

/* Rows in the generic block that starts at row i (not a declared contact): a link group (above),
 * or a run of unlinked rows on the body pair of row i (a constraint's rows), at most cap rows and
 * stopping before the next declared contact's row `stop`. */
static int KeaGenericBlockRows(const KeaProblem *problem, int i, int cap, int stop)
{
    const int *b = problem->rowBodies[i];
    const int group = KeaLinkGroupStart(problem, i);
    int m = 1;
    while (i + m < stop && m < cap && problem->rowBodies[i + m][0] == b[0] && problem->rowBodies[i + m][1] == b[1]) {
        if (group ? problem->link[i + m] != i
                  : KeaLinkGroupStart(problem, i + m) || (problem->link && problem->link[i + m] >= 0))
            break;
        ++m;
    }
    return m;
}

/* The block of m rows from i on the body pair b: its transpose J_b^T when KeaBlockGather reads it
 * (more than KEA_GATHER_ROW_BY_ROW rows), and its matrix A_bb = J_b M^-1 J_b^T + diag(eps) at A
 * from the rows' B = M^-1 J^T (a 1-row block needs none: its d_i serves). */
KEA_ALWAYS_INLINE void KeaFormBlockMatrix(const KeaProblem *problem, KeaIterativeWork *w, int i, int m, const int *b,
                                          MeReal *A)
{
    int r, c, h, g;
    for (r = 0; r < m && m > KEA_GATHER_ROW_BY_ROW; ++r) { /* only KeaBlockGather's large blocks read JT */
        MeReal *JT = w->JT + 12 * i + r;
        for (c = 0; c < 3; ++c) {
            JT[c * m] = w->J[i + r].lin0[c];
            JT[(3 + c) * m] = w->J[i + r].ang0[c];
            JT[(6 + c) * m] = w->J[i + r].lin1[c];
            JT[(9 + c) * m] = w->J[i + r].ang1[c];
        }
    }
    if (m > 1 && b[0] != b[1]) { /* column c of A_bb = J_b B_c, from the transpose */
        MeReal column[KEA_MAX_BLOCK_ROWS];
        for (c = 0; c < m; ++c) {
            const KeaJacobianRow *Bc = &w->B[i + c];
            if (m <= KEA_GATHER_ROW_BY_ROW) { /* KeaBlockGatherSmall's sums, reading B_c's halves in place */
                for (r = 0; r < m; ++r)
                    A[r * m + c] = KeaRowDot4(&w->J[i + r], Bc);
            } else {
                KeaVel4 v0, v1;
                for (h = 0; h < 4; ++h) {
                    v0.lin[h] = Bc->lin0[h];
                    v0.ang[h] = Bc->ang0[h];
                    v1.lin[h] = Bc->lin1[h];
                    v1.ang[h] = Bc->ang1[h];
                }
                KeaBlockGather(w, i, m, &v0, &v1, column);
                for (r = 0; r < m; ++r)
                    A[r * m + c] = column[r];
            }
            if (problem->epsilon)
                A[c * m + c] += problem->epsilon[i + c];
        }
    } else if (m > 1) { /* both halves on one body: the cross terms count too */
        for (r = 0; r < m; ++r)
            for (c = 0; c < m; ++c) {
                const KeaJacobianRow *Jr = &problem->J[i + r], *Bc = &w->B[i + c];
                MeReal v = ME_R(0.0);
                for (h = 0; h < 2; ++h)
                    for (g = 0; g < 2; ++g) {
                        if (b[h] < 0 || b[h] != b[g])
                            continue;
                        v += KeaDot3(h ? Jr->lin1 : Jr->lin0, g ? Bc->lin1 : Bc->lin0) +
                             KeaDot3(h ? Jr->ang1 : Jr->ang0, g ? Bc->ang1 : Bc->ang0);
                    }
                if (r == c && problem->epsilon)
                    v += problem->epsilon[i + r];
                A[r * m + c] = v;
            }
    }
}

/* KeaFormBlockMatrix's A_bb for a 3-row block on two bodies (a contact, a ball joint) with its trip
 * counts constant: the same sums in the same order, without the general path's per-entry tests. */
static inline void KeaFormBlockMatrix3(const KeaProblem *problem, const KeaIterativeWork *w, int i, MeReal *A)
{
    const KeaJacobianRow *J = w->J + i, *B = w->B + i;
    int r, c;
    for (c = 0; c < 3; ++c)
        for (r = 0; r < 3; ++r)
            A[r * 3 + c] = KeaRowDot4(&J[r], &B[c]);
    if (problem->epsilon)
        for (c = 0; c < 3; ++c)
            A[c * 3 + c] += problem->epsilon[i + c];
}

/* The blocks' boundaries, kinds and matrix offsets (a few operations per block, in row order): a
 * declared contact (KeaContact) is a block of its own, solved by the contact step (blockContact set);
 * the generic rows between contacts are split by KeaGenericBlockRows. With cap < 3 (scalar PGS asked
 * for) contacts are generic rows too. */
static void KeaFindBlocks(const KeaProblem *problem, KeaIterativeWork *w, int cap)
{
    const int n = problem->nRows, nContacts = cap >= 3 ? problem->nContacts : 0;
    int i = 0, offset = 0, c = 0;
    w->nBlocks = 0;
    w->nContactBlocks = 0;
    while (i < n) {
        const int contact = c < nContacts && problem->contacts[c].row == i;
        const int m = contact ? 3 : KeaGenericBlockRows(problem, i, cap, c < nContacts ? problem->contacts[c].row : n);
        int r;
        w->blockStart[w->nBlocks] = i;
        w->blockMatrix[w->nBlocks] = offset;
        for (r = 0; r < m; ++r)
            w->rowBlock[i + r] = w->nBlocks;
        w->blockContact[w->nBlocks] = 0;
        if (contact) {
            w->blockContact[w->nBlocks] = problem->rowBodies[i][1] < 0 ? KEA_CONTACT_WORLD : KEA_CONTACT_BODIES;
            ++w->nContactBlocks;
            ++c;
        }
        offset += m == 3 ? 9 : (m > 1 ? m * m : 0);
        ++w->nBlocks;
        i += m;
    }
    w->blockStart[w->nBlocks] = n;
    w->nPacks = -1; /* SM builds them when it first runs (kea_contact_packs.h) */
    w->nJointPacks = -1; /* and these (kea_joint_packs.h) */
}

/* Block b of m rows: its matrix A_bb = J_b M^-1 J_b^T + diag(eps) from the rows' B = M^-1 J^T, its
 * factor and its inverse. Always inlined with m a constant for the usual sizes (KeaFactorBlocks), so
 * that its loops unroll: the same arithmetic as with m a variable. */
KEA_ALWAYS_INLINE void KeaFactorBlock(const int m, const KeaProblem *problem, KeaIterativeWork *w, int b)
{
    MeReal L[KEA_MAX_BLOCK_ROWS * KEA_MAX_BLOCK_ROWS]; /* the block's Cholesky factor */
    const int i = w->blockStart[b], offset = w->blockMatrix[b];
    const int *bodies = problem->rowBodies[i];
    w->blockFactored[b] = 0;
    if (m == 3 && bodies[0] != bodies[1])
        KeaFormBlockMatrix3(problem, w, i, w->blockA + offset);
    else
        KeaFormBlockMatrix(problem, w, i, m, bodies, w->blockA + offset);
    if (m > 1) {
        w->blockFactored[b] = (unsigned char)KeaCholeskyDenseInline(m, w->blockA + offset, L);
        if (w->blockFactored[b])
            KeaBlockInvert(m, L, w->blockInv + offset);
    }
}

/* Blocks [b0, b1), each by KeaFactorBlock. Each block writes only its own entries, so blocks may be
 * set up in any order, on any worker. */
static void KeaFactorBlocks(const KeaProblem *problem, KeaIterativeWork *w, int b0, int b1)
{
    int b;
    for (b = b0; b < b1; ++b) {
        const int m = w->blockStart[b + 1] - w->blockStart[b];
        switch (m) { /* a contact or a ball joint, a hinge, a fixed joint (or a hinge with a limit) */
        case 3: KeaFactorBlock(3, problem, w, b); break;
        case 5: KeaFactorBlock(5, problem, w, b); break;
        case 6: KeaFactorBlock(6, problem, w, b); break;
        default: KeaFactorBlock(m, problem, w, b); break;
        }
    }
}

typedef struct KeaBlocksTask {
    const KeaProblem *problem;
    KeaIterativeWork *w;
} KeaBlocksTask;

static void KeaFactorBlockChunks(int start, int end, int worker, void *data)
{
    const KeaBlocksTask *t = data;
    const int last = t->w->nBlocks;
    (void)worker;
    KeaFactorBlocks(t->problem, t->w, start * KEA_SPLIT_BLOCKS,
                    end * KEA_SPLIT_BLOCKS < last ? end * KEA_SPLIT_BLOCKS : last);
}

/* Split the rows into blocks (KeaFindBlocks), then set up each block (KeaFactorBlocks): in a split
 * solve in chunks of KEA_SPLIT_BLOCKS blocks over the workers. */
void KeaSetUpBlocks(const KeaProblem *problem, KeaIterativeWork *w, int cap)
{
    KeaBlocksTask t;
    KeaFindBlocks(problem, w, cap);
    if (!w->split) {
        KeaFactorBlocks(problem, w, 0, w->nBlocks);
        return;
    }
    t.problem = problem;
    t.w = w;
    KeaSplitRun(w->split, KeaFactorBlockChunks, (w->nBlocks + KEA_SPLIT_BLOCKS - 1) / KEA_SPLIT_BLOCKS, &t);
}
