/* kea_iterative.c -- Kea's iterative path: projected Gauss-Seidel (PGS) on the sparse rows, with
 * subspace minimisation (SM) steps between sweeps, for partitions too large for the direct path.
 *
 * Data: per row B_i = M^-1 J_i^T (a padded row, like J_i) and the diagonal d_i = J_i B_i + eps_i;
 * per body the velocity change dv = M^-1 J^T x, kept up to date, so that a row needs only its own
 * two bodies: w_i = J_i . dv + eps_i x_i - r_i is O(1) and so is the update dv += B_i delta_i.
 *
 * PGS sweep (rows in index order on odd sweeps, in reverse order on even ones: a one-way sweep moves
 * information quickly one way along a chain of bodies and slowly the other, and an alternating
 * (symmetric) order lets a 20-high pyramid of boxes stand at the default 10 sweeps where the one-way
 * order let it creep apart within seconds, tests/mst/test_stacking.c):
 *   x_i <- mid(lo_i, x_i - omega w_i / d_i, hi_i), with lo_i, hi_i
 * the effective bounds at that moment (a friction row reads the current impulse of its normal row),
 * omega the SOR factor. A sweep costs O(n). The sweep also measures the natural-map residual of
 * each row just before its update; the largest is the sweep's residual, compared with the
 * tolerance. PGS converges for A positive definite (0 < omega < 2) but slowly when information must
 * travel along a chain of bodies (a stack of k boxes needs of the order of k^2 sweeps) and on the
 * near-null directions that redundant contacts create (eps small).
 *
 * Subspace minimisation (after the idea of Silcowitz, Niebe and Erleben, "Interactive rigid body
 * dynamics using a projected Gauss-Seidel subspace minimization method", 2010): a PGS sweep is good
 * at finding which rows sit at a bound, poor at solving the linear system on the rows that do not.
 * So between two sweeps, with the bounds frozen at their current values, the free rows F (strictly
 * inside their bounds) take a few conjugate-gradient steps on A_FF delta = -w_F (Jacobi
 * preconditioned, matrix-free: A_FF p = J_F M^-1 J_F^T p + eps p costs two passes over F through the
 * per-body scratch), then a projected backtracking line search x_F <- mid(lo, x_F + a delta, hi),
 * a = 1, 1/2, 1/4, 1/8, accepts the first step that lowers the QP objective
 *   f(x) = 1/2 x^T A x - r^T x;   f(x + s) - f(x) = s . (w + 1/2 (J M^-1 J^T s + eps s))
 * (computed from the step alone, free of cancellation). A rejected step leaves x as PGS made it, so
 * SM never makes the QP worse; the next sweep re-applies the friction links and the active set.
 * Each CG step costs about half a sweep (an SM step of 4, with its line search, two to three:
 * measured on the pile, 2026-11-27); KeaStats.subspaceSteps counts them.
 *
 * SM pays when the sweeps have (nearly) settled which rows sit at a bound: CG on a free set that
 * the next sweep changes again is mostly thrown away. So the SM step after a sweep is skipped when
 * more than 1/20 of the rows (and more than 16: a small problem's CG is cheap, and a lone box's
 * corners need it to share their load) went from free to bound or back since the last SM step (or
 * the warm start) -- but never twice in a row, so that SM runs at least every other sweep whatever the
 * motion (measured on bench/ scenes: the 1,000-body pile, whose contacts keep opening, closing
 * and slipping, saves 17 % of its instructions at the same penetration; every pyramid at rest
 * keeps its SM steps; skipping at any change without the "never twice" rule let the pyramids
 * fall). And SM must pay for itself: a step costs about two sweeps, so when the sweep after an SM
 * step lowers the QP objective more than that step did (the sweep's decrease estimated as
 * 1/2 delta . w per updated row, exact for an unclamped block step, low for a clamped one, so the
 * estimate favours SM), the next SM step waits until at most 1/100 of the rows (or 16) changed
 * since the last chance. A settling or resting stack's SM steps lower the objective 1.6 to 100
 * times more than the next sweep and all run; in the pile they lower it less than the sweep after
 * them from the second on, while 2-8 % of the rows keep changing per sweep (pile: 17.8e9 ->
 * 15.4e9 instructions over 300 steps, same penetration). Once the active set settles, SM runs
 * again, so a solve run to convergence keeps it. KeaStats.subspaceSkipped counts the skips.
 *
 * Block solves: a block of m rows (a constraint's rows on one body pair, or one contact point with
 * its friction rows) is solved exactly with the rest of x fixed. Most blocks at rest have every row
 * strictly inside its bounds: one product with the block's inverse (KeaBlockAllFree). Each contact
 * point with its friction rows is a block of its own (not its whole contact group: docs/kea.md),
 * which otherwise tries its few active sets in closed form (opening, or one or both friction rows
 * sliding: KeaContactSolve); anything else (a constraint's rows at a limit) goes to the dense
 * box-LCP solver (kea_dense_lcp.c). A plain contact block (a normal row and its two friction rows,
 * the pile's every block) has its own step with the same arithmetic and its rows in locals, and on
 * the world it skips the world's half (exact zeros): the same trajectories, a quarter fewer
 * instructions on the pile with the four-lane kernels (docs/kea.md).
 *
 * Warm start: x0 is clamped to its bounds and dv computed from it before the first sweep.
 *
 * Data layout (for the cost per row; the arithmetic is the above): dv lives in a padded per-body
 * copy (KeaVel4, 3-vectors padded to 4, plus an all-zero body standing for the world), rows read it
 * through a copy of J with zero pads and zero world halves, so a row kernel has no branch per body
 * half. A block of m > 4 rows (a joint's: a fixed joint has 6) computes its w_b = J_b dv from a 12 x m
 * transpose of its J (KeaColumnsApply, one vectorised column kernel for all block products: w_b
 * through KeaColumnsApplyPair, which reads the two bodies in place,
 * A_bb^-1 w_b, the preconditioner, forming A_bb) and applies its deltas to local copies of its two
 * bodies; SM's matrix-free products go through the free list a piece (a free row on its own, or a
 * block whose rows are all free) at a time the same way, each piece's rows and bodies listed once
 * per SM step (KeaFreePiece). */
#include <string.h>

#include "kea_internal.h"
#include "kea_lanes.h"

/** A body's velocity change with each 3-vector padded to 4 (pad 0). */
typedef struct KeaVel4 {
    MeReal lin[4];
    MeReal ang[4];
} KeaVel4;

/** J . (v0, v1) on padded rows: lane k sums component k of the four parts, then the three lanes
 *  are added in a fixed order (kea_lanes.h: the same bits with or without SSE). No branch per body
 *  half. */
static inline MeReal KeaRowVel4(const KeaJacobianRow *J, const KeaVel4 *v0, const KeaVel4 *v1)
{
    return KeaLanesSum3(KeaLanesAdd(KeaLanesDot2(J->lin0, v0->lin, J->ang0, v0->ang),
                                    KeaLanesDot2(J->lin1, v1->lin, J->ang1, v1->ang)));
}

/* J . (v0, world) on padded rows: KeaRowVel4 without the world's half, which adds exact zeros. */
static inline MeReal KeaRowVel4World(const KeaJacobianRow *J, const KeaVel4 *v0)
{
    return KeaLanesSum3(KeaLanesDot2(J->lin0, v0->lin, J->ang0, v0->ang));
}

/** J_r . B_c of two padded rows: KeaRowVel4 with B_c's halves as the two bodies' velocities. */
static inline MeReal KeaRowDot4(const KeaJacobianRow *J, const KeaJacobianRow *B)
{
    return KeaLanesSum3(KeaLanesAdd(KeaLanesDot2(J->lin0, B->lin0, J->ang0, B->ang0),
                                    KeaLanesDot2(J->lin1, B->lin1, J->ang1, B->ang1)));
}

/** v += B s for one body half (padded; the pads stay 0). */
static inline void KeaHalfApply4(const MeReal *lin, const MeReal *ang, MeReal s, KeaVel4 *v)
{
    const KeaLanes scale = KeaLanesSplat(s);
    KeaLanesAddScaled(v->lin, lin, scale);
    KeaLanesAddScaled(v->ang, ang, scale);
}

/** (v0, v1) += B s (v0 first, then v1, so that v0 == v1 is handled as two updates). */
static inline void KeaRowApply4(const KeaJacobianRow *B, MeReal s, KeaVel4 *v0, KeaVel4 *v1)
{
    KeaHalfApply4(B->lin0, B->ang0, s, v0);
    KeaHalfApply4(B->lin1, B->ang1, s, v1);
}

/** SM: one piece of the free list for its matrix-free products, everything they read about it in
 *  one place: a free row on its own, or a segment (a block whose rows are all free). */
typedef struct KeaFreePiece {
    int pos;      /**< its first position in the free list */
    int row;      /**< its first row */
    int rows;     /**< 1 for a row on its own, else the block's size */
    int kind;     /**< 0, or the segment's KEA_CONTACT_* kind when it is a plain contact */
    int body[2];  /**< the row halves' bodies (the world: nb) */
} KeaFreePiece;

typedef struct KeaIterativeWork {
    KeaBodyColumns *bodyColumns; /**< nb: inverse masses and inertia columns, for B */
    KeaJacobianRow *B;     /**< M^-1 J^T per row */
    MeReal *invDiag;       /**< 1 / d_i (0 for a row that touches nothing and has eps 0) */
    MeReal *diag;          /**< d_i */
    /* Blocks: runs of consecutive rows on the same two bodies, solved together exactly. */
    int nBlocks;
    int *blockStart;       /**< nBlocks + 1 row offsets */
    int *blockMatrix;      /**< offset of each block's m x m matrix in blockA */
    MeReal *blockA;        /**< the blocks' A_bb, at most n * maxBlockRows reals */
    MeReal *blockL;        /**< scratch: one block's Cholesky factor, read only to form its inverse */
    MeReal *blockInv;      /**< their inverses A_bb^-1 (same offsets): a block solve in a sweep or
                                a preconditioner step is then one small matrix-vector product,
                                no divisions (each block is solved ~50 times a step, factored once) */
    unsigned char *blockFactored; /**< the factor exists (A_bb safely positive definite) */
    unsigned char *blockContact;  /**< KEA_CONTACT_* kind of a plain contact block (KeaIsPlainContact), else 0 */
    unsigned char *wasFree;       /**< SM: the row was free at the last SM step (or the warm start) */
    int skippedLast;              /**< SM: the last SM step was skipped */
    MeReal sweepDecrease;         /**< estimated decrease of the QP objective by the current sweep
                                       (its contacts tallied only in a sweep after an SM step, the
                                       one whose figure is read) */
    MeReal smDecrease;            /**< decrease of the objective by that SM step (0 if rejected) */
    int smRan;                    /**< an SM step ran since the last sweep */
    int smUnpaid;                 /**< SM: the last SM step did less than the sweep after it */
    int nContactBlocks;           /**< blocks that are plain contacts (blockContact) */
    int sweepChanged;             /**< plain contacts' rows that went between free and a bound in
                                       the last sweep (tallied by its steps) */
    MeReal *localW;        /**< a block's w */
    int *rowBlock;         /**< block of each row */
    int *segmentPos, *segmentBlock, nSegments; /**< SM: free blocks preconditioned by their factor */
    KeaFreePiece *pieces;  /**< SM: the free list as rows on their own and segments, in order */
    int nPieces;
    MeReal *localR, *localLo, *localHi, *localX; /**< a block's LCP (maxBlockRows each) */
    int *localLink;
    KeaDenseWork *dense;   /**< the dense solver, sized for maxBlockRows */
    /* Subspace minimisation: */
    int *freeRows;         /**< rows strictly inside their bounds */
    MeReal *lo, *hi;       /**< bounds frozen for the SM step (by row) */
    MeReal *grad;          /**< w on the free rows (by position) */
    MeReal *epsFree;       /**< eps of the free rows (by position) */
    MeReal *step;          /**< CG solution delta */
    MeReal *res, *z, *dir, *q; /**< CG vectors */
    /* Row kernels on padded data: J_i . dv and dv += B_i s as four-wide operations with no branch
     * per body half. Bodies are KeaVel4 (4-padded 3-vectors, pads 0) with one extra all-zero body
     * at index nb that stands for the world; the rows' copies of J have zero pads and zero halves
     * on the world, so that the extra body contributes exact zeros. */
    KeaJacobianRow *J;     /**< J_i with pads and world halves zeroed */
    MeReal *JT;            /**< per block of m rows from s, its 12 x m transpose J_b^T (pads
                                dropped) at JT + 12 s: J_b v is then a sum of 12 columns */
    MeReal *localD;        /**< a block's impulse changes */
    int (*body)[2];        /**< row halves' bodies, KEA_WORLD mapped to nb */
    MeReal *eps;           /**< eps_i (0 when the problem has none) */
    KeaVel4 *dv;           /**< the solve's dv (nb + 1), copied out at the end */
    KeaVel4 *dvTmp;        /**< per-body scratch for A_FF p and for the trial step (nb + 1) */
} KeaIterativeWork;

static int KeaBlockCap(int n, int maxBlockRows)
{
    const int cap = maxBlockRows < KEA_MAX_BLOCK_ROWS ? maxBlockRows : KEA_MAX_BLOCK_ROWS;
    return cap < 1 ? 1 : (cap < n ? cap : (n > 0 ? n : 1));
}

static void KeaIterativeLayout(KeaArena *arena, int n, int nb, int maxBlockRows, KeaIterativeWork *w)
{
    const int cap = KeaBlockCap(n, maxBlockRows);
    w->B = KEA_ALLOC(arena, KeaJacobianRow, n);
    w->invDiag = KEA_ALLOC(arena, MeReal, n);
    w->diag = KEA_ALLOC(arena, MeReal, n);
    w->blockStart = KEA_ALLOC(arena, int, n + 1);
    w->blockMatrix = KEA_ALLOC(arena, int, n);
    w->blockA = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)cap);
    w->blockL = KEA_ALLOC(arena, MeReal, (size_t)cap * (size_t)cap);
    w->blockInv = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)cap);
    w->blockFactored = KEA_ALLOC(arena, unsigned char, n);
    w->blockContact = KEA_ALLOC(arena, unsigned char, n);
    w->wasFree = KEA_ALLOC(arena, unsigned char, n);
    w->localW = KEA_ALLOC(arena, MeReal, cap);
    w->rowBlock = KEA_ALLOC(arena, int, n);
    w->segmentPos = KEA_ALLOC(arena, int, n);
    w->segmentBlock = KEA_ALLOC(arena, int, n);
    w->pieces = KEA_ALLOC(arena, KeaFreePiece, n);
    w->localR = KEA_ALLOC(arena, MeReal, cap);
    w->localLo = KEA_ALLOC(arena, MeReal, cap);
    w->localHi = KEA_ALLOC(arena, MeReal, cap);
    w->localX = KEA_ALLOC(arena, MeReal, cap);
    w->localLink = KEA_ALLOC(arena, int, cap);
    w->dense = KeaDenseWorkCreate(arena, cap);
    w->freeRows = KEA_ALLOC(arena, int, n);
    w->lo = KEA_ALLOC(arena, MeReal, n);
    w->hi = KEA_ALLOC(arena, MeReal, n);
    w->grad = KEA_ALLOC(arena, MeReal, n);
    w->epsFree = KEA_ALLOC(arena, MeReal, n);
    w->step = KEA_ALLOC(arena, MeReal, n);
    w->res = KEA_ALLOC(arena, MeReal, n);
    w->z = KEA_ALLOC(arena, MeReal, n);
    w->dir = KEA_ALLOC(arena, MeReal, n);
    w->q = KEA_ALLOC(arena, MeReal, n);
    w->J = KEA_ALLOC(arena, KeaJacobianRow, n);
    w->JT = KEA_ALLOC(arena, MeReal, (size_t)n * 12);
    w->localD = KEA_ALLOC(arena, MeReal, cap);
    w->body = (int(*)[2])KeaArenaAlloc(arena, sizeof(int[2]) * (size_t)n);
    w->eps = KEA_ALLOC(arena, MeReal, n);
    w->dv = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->dvTmp = KEA_ALLOC(arena, KeaVel4, nb + 1);
    w->bodyColumns = KEA_ALLOC(arena, KeaBodyColumns, nb);
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

/* out = M in for a symmetric m x m block M (out and in distinct): KeaColumnsApply (kea_rows.c); a
 * contact's 3 x 3, the most common block, inline with the same sums. */
static inline void KeaBlockSymmetricApply(int m, const MeReal *M, const MeReal *in, MeReal *out)
{
    int r;
    if (m != 3) {
        KeaColumnsApply(m, m, M, in, out);
        return;
    }
    for (r = 0; r < 3; ++r)
        out[r] = (M[r] * in[0] + M[3 + r] * in[1]) + M[6 + r] * in[2];
}

/* out = J_b (v0, v1) for the block of m rows from s (all on the same two bodies): a block of more
 * than 4 rows from its transpose JT (12 x m), column by column, each out[r] its own running sum
 * over the 12 components in order; a smaller one row by row. */
static void KeaBlockGatherSmall(const KeaIterativeWork *w, int s, int m, const KeaVel4 *v0, const KeaVel4 *v1,
                                MeReal *out)
{
    /* written out: a loop over so few rows is "vectorised" across them, at a high price */
    out[0] = KeaRowVel4(&w->J[s], v0, v1);
    if (m > 1)
        out[1] = KeaRowVel4(&w->J[s + 1], v0, v1);
    if (m > 2)
        out[2] = KeaRowVel4(&w->J[s + 2], v0, v1);
    if (m > 3)
        out[3] = KeaRowVel4(&w->J[s + 3], v0, v1);
}

static inline void KeaBlockGather(const KeaIterativeWork *w, int s, int m, const KeaVel4 *v0, const KeaVel4 *v1,
                                  MeReal *out)
{
    if (m <= 4) { /* a ball joint, a one-point contact: row by row */
        KeaBlockGatherSmall(w, s, m, v0, v1, out);
        return;
    }
    KeaColumnsApplyPair(m, w->JT + 12 * s, v0->lin, v0->ang, v1->lin, v1->ang, out);
}

/* (v0, v1) += sum_r B_r d_r over a block's m rows (rows with d_r = 0 skipped), in row order: the
 * same operations as row-by-row updates, on local copies of the two bodies (v0 != v1). v1 NULL: the
 * second half is the world's (all zero: nothing to add). */
static inline void KeaBlockScatterSized(const int m, const KeaJacobianRow *B, const MeReal *d, KeaVel4 *v0, KeaVel4 *v1)
{
    KeaLanes aLin = KeaLanesLoad(v0->lin), aAng = KeaLanesLoad(v0->ang), bLin = aLin, bAng = aAng;
    int r;
    if (v1) {
        bLin = KeaLanesLoad(v1->lin);
        bAng = KeaLanesLoad(v1->ang);
    }
    for (r = 0; r < m; ++r) {
        KeaLanes dr;
        if (d[r] == ME_R(0.0))
            continue;
        dr = KeaLanesSplat(d[r]);
        aLin = KeaLanesAdd(aLin, KeaLanesMul(KeaLanesLoad(B[r].lin0), dr));
        aAng = KeaLanesAdd(aAng, KeaLanesMul(KeaLanesLoad(B[r].ang0), dr));
        if (v1) {
            bLin = KeaLanesAdd(bLin, KeaLanesMul(KeaLanesLoad(B[r].lin1), dr));
            bAng = KeaLanesAdd(bAng, KeaLanesMul(KeaLanesLoad(B[r].ang1), dr));
        }
    }
    KeaLanesStore(v0->lin, aLin);
    KeaLanesStore(v0->ang, aAng);
    if (v1) {
        KeaLanesStore(v1->lin, bLin);
        KeaLanesStore(v1->ang, bAng);
    }
}

/* v += sum_r B_r d_r over a contact's three rows, on body half `half` of B. */
static inline void KeaContactScatterHalf(const KeaJacobianRow *B, const MeReal *d, int half, KeaVel4 *v)
{
    KeaLanes lin = KeaLanesLoad(v->lin), ang = KeaLanesLoad(v->ang);
    int r;
    for (r = 0; r < 3; ++r) {
        const KeaLanes dr = KeaLanesSplat(d[r]);
        lin = KeaLanesAdd(lin, KeaLanesMul(KeaLanesLoad(half ? B[r].lin1 : B[r].lin0), dr));
        ang = KeaLanesAdd(ang, KeaLanesMul(KeaLanesLoad(half ? B[r].ang1 : B[r].ang0), dr));
    }
    KeaLanesStore(v->lin, lin);
    KeaLanesStore(v->ang, ang);
}

/* KeaBlockScatterSized for a contact's three rows (v0 != v1; v1 NULL on the world) without its
 * test per row: a row with d_r = 0 adds B_r 0, zeros (the same values; only a -0 in dv may become
 * +0, which no later comparison or product tells apart). */
static inline void KeaContactScatter(const KeaJacobianRow *B, const MeReal *d, KeaVel4 *v0, KeaVel4 *v1)
{
    KeaContactScatterHalf(B, d, 0, v0);
    if (v1)
        KeaContactScatterHalf(B, d, 1, v1);
}

static void KeaBlockScatter(int m, const KeaJacobianRow *B, const MeReal *d, KeaVel4 *v0, KeaVel4 *v1)
{
    int r;
    if (v0 == v1) { /* a block whose halves are the same body: one update after the other */
        for (r = 0; r < m; ++r)
            if (d[r] != ME_R(0.0))
                KeaRowApply4(&B[r], d[r], v0, v1);
    } else if (m == 3) { /* a contact */
        KeaBlockScatterSized(3, B, d, v0, v1);
    } else if (m == 12) {
        KeaBlockScatterSized(12, B, d, v0, v1);
    } else {
        KeaBlockScatterSized(m, B, d, v0, v1);
    }
}

/* Row i begins a contact with friction: it has no link and the next row is linked to it. */
static int KeaContactStart(const KeaProblem *problem, int i)
{
    return problem->link && problem->link[i] < 0 && i + 1 < problem->nRows && problem->link[i + 1] == i;
}

enum { KEA_CONTACT_BODIES = 1, KEA_CONTACT_WORLD = 2 }; /* a plain contact between two bodies, or on the world */

/* A plain contact block, the pile's every block: three rows on two different bodies (the second
 * may be the world), a normal row with bounds [0, inf) and no link, two friction rows linked to it
 * with no bounds of their own (KeaContactSolve's case), each touching something, and the block's
 * inverse exists. The sweep solves it with that layout known (KeaContactBlockStep). Returns its
 * KEA_CONTACT_* kind, or 0. */
static unsigned char KeaIsPlainContact(const KeaProblem *problem, const KeaIterativeWork *w, int s, int m)
{
    const int block = w->rowBlock[s];
    int k;
    if (m != 3 || !problem->mu || !w->blockFactored[block] || w->body[s][0] == w->body[s][1] ||
        !KeaContactStart(problem, s) || problem->link[s + 2] != s)
        return 0;
    if (problem->lo[s] != ME_R(0.0) || KeaIsFinite(problem->hi[s]))
        return 0;
    for (k = 0; k < 3; ++k)
        if (w->invDiag[s + k] == ME_R(0.0) || (k > 0 && (KeaIsFinite(problem->lo[s + k]) || KeaIsFinite(problem->hi[s + k]))))
            return 0;
    if (w->body[s][0] == problem->nBodies)
        return 0;
    return w->body[s][1] == problem->nBodies ? KEA_CONTACT_WORLD : KEA_CONTACT_BODIES;
}

/* Split the rows into blocks and form each block's matrix A_bb = J_b M^-1 J_b^T + diag(eps) from the
 * rows' B = M^-1 J^T. A block is a run of rows on the same body pair, at most cap rows, except that a
 * contact with friction (its normal row and the rows linked to it) is a block of its own. */
static void KeaSetUpBlocks(const KeaProblem *problem, KeaIterativeWork *w, int cap)
{
    const int n = problem->nRows;
    int i = 0, offset = 0;
    w->nBlocks = 0;
    w->nContactBlocks = 0;
    while (i < n) {
        const int *b = problem->rowBodies[i];
        const int contact = KeaContactStart(problem, i);
        int m = 1, r, c, h, g;
        while (i + m < n && m < cap && problem->rowBodies[i + m][0] == b[0] && problem->rowBodies[i + m][1] == b[1]) {
            if (contact ? problem->link[i + m] != i
                        : KeaContactStart(problem, i + m) || (problem->link && problem->link[i + m] >= 0))
                break; /* a contact is a block of its own */
            ++m;
        }
        w->blockStart[w->nBlocks] = i;
        w->blockMatrix[w->nBlocks] = offset;
        for (r = 0; r < m; ++r)
            w->rowBlock[i + r] = w->nBlocks;
        for (r = 0; r < m && m > 4; ++r) { /* only KeaBlockGather's large blocks read JT */
            MeReal *JT = w->JT + 12 * i + r;
            for (c = 0; c < 3; ++c) {
                JT[c * m] = w->J[i + r].lin0[c];
                JT[(3 + c) * m] = w->J[i + r].ang0[c];
                JT[(6 + c) * m] = w->J[i + r].lin1[c];
                JT[(9 + c) * m] = w->J[i + r].ang1[c];
            }
        }
        if (m > 1 && b[0] != b[1]) { /* column c of A_bb = J_b B_c, from the transpose */
            MeReal *A = w->blockA + offset, column[KEA_MAX_BLOCK_ROWS];
            for (c = 0; c < m; ++c) {
                const KeaJacobianRow *Bc = &w->B[i + c];
                if (m <= 4) { /* KeaBlockGatherSmall's sums, reading B_c's halves in place */
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
            MeReal *A = w->blockA + offset;
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
        w->blockFactored[w->nBlocks] = 0;
        if (m == 3) { /* a contact or a ball joint: the same arithmetic, unrolled */
            w->blockFactored[w->nBlocks] = (unsigned char)KeaCholeskyDenseInline(3, w->blockA + offset, w->blockL);
            if (w->blockFactored[w->nBlocks])
                KeaBlockInvert(3, w->blockL, w->blockInv + offset);
            offset += 9;
        } else if (m > 1) {
            w->blockFactored[w->nBlocks] = (unsigned char)KeaCholeskyDense(m, w->blockA + offset, w->blockL);
            if (w->blockFactored[w->nBlocks])
                KeaBlockInvert(m, w->blockL, w->blockInv + offset);
            offset += m * m;
        }
        w->blockContact[w->nBlocks] = KeaIsPlainContact(problem, w, i, m);
        w->nContactBlocks += w->blockContact[w->nBlocks] != 0;
        ++w->nBlocks;
        i += m;
    }
    w->blockStart[w->nBlocks] = n;
}

static MeReal KeaRowW(const KeaProblem *problem, const KeaIterativeWork *w, int i, const MeReal *x,
                      const KeaVel4 *v0, const KeaVel4 *v1)
{
    return KeaRowVel4(&w->J[i], v0, v1) + w->eps[i] * x[i] - problem->rhs[i];
}

/* Apply the deltas localX - x of the block's m rows from s (all on the same two bodies) to dv and
 * x, in row order; localW holds the block's w before the step. */
static void KeaBlockApplyDeltas(KeaIterativeWork *w, int s, int m, MeReal *x)
{
    int r;
    for (r = 0; r < m; ++r) {
        w->localD[r] = w->localX[r] - x[s + r];
        w->sweepDecrease -= ME_R(0.5) * w->localD[r] * w->localW[r];
    }
    KeaBlockScatter(m, &w->B[s], w->localD, &w->dv[w->body[s][0]], &w->dv[w->body[s][1]]);
    for (r = 0; r < m; ++r)
        if (w->localD[r] != ME_R(0.0))
            x[s + r] = w->localX[r];
}

/* The common case of a block at rest: all its rows free. Try x_b - A_bb^-1 w_b with the block's
 * precomputed factor; if it lies within every row's bounds (friction links inside the block read
 * the new normal values), w_b = 0 there and it is the block's exact solution. Returns 1 if taken. */
static int KeaBlockAllFree(const KeaProblem *problem, KeaIterativeWork *w, int block, MeReal *x)
{
    const int s = w->blockStart[block], m = w->blockStart[block + 1] - s;
    int r;
    if (!w->blockFactored[block])
        return 0;
    KeaBlockSymmetricApply(m, w->blockInv + w->blockMatrix[block], w->localW, w->localX);
    for (r = 0; r < m; ++r)
        w->localX[r] = x[s + r] - w->localX[r];
    for (r = 0; r < m; ++r) {
        MeReal lo = w->localLo[r], hi = w->localHi[r];
        if (w->localLink[r] >= 0)
            KeaFrictionBounds(lo, hi, problem->mu[s + r], w->localX[w->localLink[r]], &lo, &hi);
        if (!(w->localX[r] >= lo && w->localX[r] <= hi))
            return 0;
    }
    KeaBlockApplyDeltas(w, s, m, x);
    return 1;
}

/* One active set of KeaContactActiveSets (below): friction row k free (sigk 0) or sliding at
 * sigk mu_k n. Returns 1, with the solution in out, if it is valid. */
static inline int KeaContactTry(const MeReal *A, const MeReal *r, const MeReal *mu, const int sig1, const int sig2,
                                MeReal *out)
{
    const int sig[3] = {0, sig1, sig2};
    const int free = sig1 == 0 ? 1 : (sig2 == 0 ? 2 : -1);
    MeReal an[3], x[3], wv;
    int k;
    for (k = 0; k < 3; ++k) /* the column of n with the sliding rows substituted */
        an[k] = A[k * 3 + 0] + (MeReal)sig[1] * mu[1] * A[k * 3 + 1] + (MeReal)sig[2] * mu[2] * A[k * 3 + 2];
    if (free < 0) {
        if (!(an[0] > ME_R(0.0)))
            return 0;
        x[0] = r[0] / an[0];
    } else {
        const MeReal det = an[0] * A[free * 3 + free] - A[0 * 3 + free] * an[free];
        if (!(det > ME_R(0.0)))
            return 0;
        x[0] = (r[0] * A[free * 3 + free] - A[0 * 3 + free] * r[free]) / det;
        x[free] = (an[0] * r[free] - an[free] * r[0]) / det;
        if (!(KeaFabs(x[free]) <= mu[free] * x[0]))
            return 0;
    }
    if (!(x[0] > ME_R(0.0)))
        return 0;
    for (k = 1; k < 3; ++k)
        if (sig[k] != 0)
            x[k] = (MeReal)sig[k] * mu[k] * x[0];
    for (k = 1; k < 3; ++k) {
        if (sig[k] == 0)
            continue;
        wv = A[k * 3 + 0] * x[0] + A[k * 3 + 1] * x[1] + A[k * 3 + 2] * x[2] - r[k];
        if (sig[k] > 0 ? wv > ME_R(0.0) : wv < ME_R(0.0))
            return 0; /* the row would rather slide less */
    }
    out[0] = x[0];
    out[1] = x[1];
    out[2] = x[2];
    return 1;
}

/* One contact with friction (a normal row with bounds [0, inf) and two rows linked to it with no
 * bounds of their own), solved exactly by trying its few active sets, x = (n, f1, f2):
 *   n = 0 (the contact opens; the friction rows are pinned at 0): valid if w_n >= 0;
 *   n > 0 with each friction row free or sliding at +-mu n, not both free: the rows that are free
 *   (and the normal) have w = 0, a 1x1 or 2x2 system in n and the free friction impulse; valid if
 *   n > 0, a free friction row stays within +-mu n, and a sliding one's w pushes against its bound.
 * A is the contact's 3 x 3 matrix, r its r_loc = A x - w, mu its rows' friction coefficients.
 * The all-free case is KeaBlockAllFree's (with the block's precomputed inverse).
 * The first valid set in that fixed order is taken (with mu small enough the solution is unique).
 * Exact comparisons: a set valid only within rounding is left to the general solver. Returns 1 if
 * solved (out holds the solution). */
static int KeaContactActiveSets(const MeReal *A, const MeReal *r, const MeReal *mu, MeReal *out)
{
    if (-r[0] >= ME_R(0.0)) { /* n = 0: w = A 0 - r */
        out[0] = out[1] = out[2] = ME_R(0.0);
        return 1;
    }
    /* Each friction row free (0) or sliding (+1, -1), not both free, in this order; one call per set
     * (constants: each test its own branch, which predicts better than one loop's). */
    return KeaContactTry(A, r, mu, 0, 1, out) || KeaContactTry(A, r, mu, 0, -1, out) ||
           KeaContactTry(A, r, mu, 1, 0, out) || KeaContactTry(A, r, mu, 1, 1, out) ||
           KeaContactTry(A, r, mu, 1, -1, out) || KeaContactTry(A, r, mu, -1, 0, out) ||
           KeaContactTry(A, r, mu, -1, 1, out) || KeaContactTry(A, r, mu, -1, -1, out);
}

/* KeaContactActiveSets for a block given by its local bounds and links: 0 unless it is a contact
 * (normal row with bounds [0, inf) and no link, two rows linked to it with no bounds of their own). */
static int KeaContactSolve(const MeReal *A, const MeReal *r, const MeReal *lo, const MeReal *hi, const int *link,
                           const MeReal *mu, MeReal *out)
{
    int k;
    if (link[0] >= 0 || lo[0] != ME_R(0.0) || KeaIsFinite(hi[0]))
        return 0;
    for (k = 1; k < 3; ++k)
        if (link[k] != 0 || KeaIsFinite(lo[k]) || KeaIsFinite(hi[k]))
            return 0;
    return KeaContactActiveSets(A, r, mu, out);
}

/* The box-LCP of n rows (matrix A, r, own bounds lo/hi, links local to these rows or -1) with the
 * dense solver; x is the warm start on entry and the solution on return. */
static void KeaSmallLcp(const KeaProblem *problem, KeaIterativeWork *w, int n, const MeReal *A, const MeReal *r,
                        const MeReal *lo, const MeReal *hi, const int *link, const MeReal *mu, int maxPasses,
                        MeReal *x, KeaStats *stats)
{
    KeaDenseLcp lcp;
    KeaStats local;
    lcp.n = n;
    lcp.A = A;
    lcp.r = r;
    lcp.lo = lo;
    lcp.hi = hi;
    lcp.link = problem->mu ? link : NULL;
    lcp.mu = problem->mu ? mu : NULL;
    lcp.order = NULL;
    lcp.patternStart = lcp.pattern = NULL;
    lcp.rows = NULL;
    lcp.velocity = NULL;
    memset(&local, 0, sizeof local);
    (void)KeaDenseLcpSolve(&lcp, 0, maxPasses, w->dense, x, &local);
    stats->pivots += local.pivots;
    stats->regularised += local.regularised;
}

/* Solve the block of m rows from s exactly with the rest of x fixed: its local LCP has the matrix
 * A_bb and r_loc = A_bb x_b - w_b, so that its w is the true w of these rows. A friction link to a
 * row outside the block becomes a fixed bound. Returns the block's largest row residual before
 * (when measure is set; else 0). */
static MeReal KeaBlockStep(const KeaProblem *problem, KeaIterativeWork *w, int block, int maxPasses,
                           MeReal *x, KeaStats *stats, int measure)
{
    const int s = w->blockStart[block], m = w->blockStart[block + 1] - s;
    const MeReal *A = w->blockA + w->blockMatrix[block];
    MeReal worst = ME_R(0.0);
    int r;
    KeaBlockGather(w, s, m, &w->dv[w->body[s][0]], &w->dv[w->body[s][1]], w->localW);
    for (r = 0; r < m; ++r) {
        const int i = s + r;
        const MeReal wi = w->localW[r] + w->eps[i] * x[i] - problem->rhs[i];
        MeReal lo, hi;
        KeaRowBoundsInline(problem, x, i, &lo, &hi);
        if (measure && w->invDiag[i] != ME_R(0.0))
            worst = KeaMax(worst, w->diag[i] * KeaFabs(x[i] - KeaClamp(x[i] - wi * w->invDiag[i], lo, hi)));
        w->localW[r] = wi;
        w->localLink[r] = -1;
        if (problem->link && problem->link[i] >= s && problem->link[i] < s + m) {
            w->localLink[r] = problem->link[i] - s;
            w->localLo[r] = problem->lo[i];
            w->localHi[r] = problem->hi[i];
        } else {
            w->localLo[r] = lo;
            w->localHi[r] = hi;
        }
    }
    if (KeaBlockAllFree(problem, w, block, x))
        return worst;
    KeaBlockSymmetricApply(m, A, x + s, w->localR); /* r_loc = A_bb x_b - w_b */
    for (r = 0; r < m; ++r) {
        w->localR[r] -= w->localW[r];
        w->localX[r] = x[s + r];
    }
    if (m == 3 && problem->mu &&
        KeaContactSolve(A, w->localR, w->localLo, w->localHi, w->localLink, problem->mu + s, w->localX)) {
        KeaBlockApplyDeltas(w, s, m, x);
        return worst;
    }
    KeaSmallLcp(problem, w, m, A, w->localR, w->localLo, w->localHi, w->localLink, problem->mu ? problem->mu + s : NULL,
                maxPasses, w->localX, stats);
    KeaBlockApplyDeltas(w, s, m, x);
    return worst;
}

/* A plain contact's rows free now (KeaRowIsFree: its normal row's bounds [0, hi), its friction
 * rows' +-mu n) into was, from its impulses xb; returns how many of the three changed. The sweep
 * calls it after each contact's step, which is that block's last change before the next SM
 * chance (a contact's bounds depend on its own rows only). */
static inline int KeaContactFreeRows(const MeReal *mu, MeReal hi, const MeReal *xb, unsigned char *was)
{
    const MeReal n = xb[0], bound1 = KeaFrictionBound(mu[1], n), bound2 = KeaFrictionBound(mu[2], n);
    const unsigned char f0 = (unsigned char)(ME_R(0.0) < n && n < hi);
    const unsigned char f1 = (unsigned char)(-bound1 < xb[1] && xb[1] < bound1);
    const unsigned char f2 = (unsigned char)(-bound2 < xb[2] && xb[2] < bound2);
    const int changed = (f0 != was[0]) + (f1 != was[1]) + (f2 != was[2]);
    was[0] = f0;
    was[1] = f1;
    was[2] = f2;
    return changed;
}

/* KeaBlockStep for a plain contact block (KeaIsPlainContact), with the same arithmetic in the same
 * order (so the same values; on the world the exact zeros of its half are not computed), its three
 * rows held in locals: the normal row's bounds are [0, inf), the friction rows' [-mu n, mu n] for
 * the normal impulse n. */
static MeReal KeaContactBlockStep(const KeaProblem *problem, KeaIterativeWork *w, int block, int maxPasses, MeReal *x,
                                  KeaStats *stats, int onWorld, int measure, int tally, MeReal *decrease,
                                  int *changed)
{
    const int s = w->blockStart[block];
    KeaVel4 *v0 = &w->dv[w->body[s][0]], *v1 = &w->dv[w->body[s][1]];
    const MeReal *mu = problem->mu + s, *inv = w->blockInv + w->blockMatrix[block];
    MeReal wb[3], xb[3], xn[3], d[3], t[3], bound, bound2, worst;
    int r;
    for (r = 0; r < 3; ++r)
        wb[r] = onWorld ? KeaRowVel4World(&w->J[s + r], v0) : KeaRowVel4(&w->J[s + r], v0, v1);
    for (r = 0; r < 3; ++r) {
        xb[r] = x[s + r];
        wb[r] = wb[r] + w->eps[s + r] * xb[r] - problem->rhs[s + r];
    }
    /* the residual before the step (when the sweep still measures): normal row in [0, inf), friction
     * rows in [-mu n, mu n] */
    worst = ME_R(0.0);
    if (measure) {
        worst = KeaMax(worst, w->diag[s] * KeaFabs(xb[0] - KeaClamp(xb[0] - wb[0] * w->invDiag[s], ME_R(0.0),
                                                                     problem->hi[s])));
        for (r = 1; r < 3; ++r) {
            bound = KeaFrictionBound(mu[r], xb[0]);
            worst = KeaMax(worst, w->diag[s + r] *
                                      KeaFabs(xb[r] - KeaClamp(xb[r] - wb[r] * w->invDiag[s + r], -bound, bound)));
        }
    }
    /* every row free: x_b - A_bb^-1 w_b, if it keeps within the bounds its own normal gives */
    for (r = 0; r < 3; ++r)
        t[r] = (inv[r] * wb[0] + inv[3 + r] * wb[1]) + inv[6 + r] * wb[2];
    for (r = 0; r < 3; ++r)
        xn[r] = xb[r] - t[r];
    bound = KeaFrictionBound(mu[1], xn[0]);
    bound2 = KeaFrictionBound(mu[2], xn[0]);
    if (!(xn[0] >= ME_R(0.0) && xn[0] <= problem->hi[s] && xn[1] >= -bound && xn[1] <= bound && xn[2] >= -bound2 &&
          xn[2] <= bound2)) {
        const MeReal *A = w->blockA + w->blockMatrix[block];
        MeReal rl[3];
        for (r = 0; r < 3; ++r) /* r_loc = A_bb x_b - w_b */
            rl[r] = ((A[r] * xb[0] + A[3 + r] * xb[1]) + A[6 + r] * xb[2]) - wb[r];
        /* the set the contact was in, tried first: a sliding contact usually keeps sliding the same
         * way (the solution, when unique, is the same whichever valid set is found first) */
        const MeReal was1Bound = KeaFrictionBound(mu[1], xb[0]), was2Bound = KeaFrictionBound(mu[2], xb[0]);
        const int was1 = xb[1] >= was1Bound ? 1 : (xb[1] <= -was1Bound ? -1 : 0);
        const int was2 = xb[2] >= was2Bound ? 1 : (xb[2] <= -was2Bound ? -1 : 0);
        if (!((was1 | was2) != 0 && xb[0] > ME_R(0.0) && KeaContactTry(A, rl, mu, was1, was2, xn)) &&
            !KeaContactActiveSets(A, rl, mu, xn)) { /* within rounding: the general solver */
            for (r = 0; r < 3; ++r) {
                w->localW[r] = wb[r];
                w->localX[r] = xb[r];
                w->localLo[r] = problem->lo[s + r];
                w->localHi[r] = problem->hi[s + r];
                w->localLink[r] = r == 0 ? -1 : 0;
            }
            KeaSmallLcp(problem, w, 3, A, rl, w->localLo, w->localHi, w->localLink, mu, maxPasses, w->localX, stats);
            w->sweepDecrease = *decrease;
            KeaBlockApplyDeltas(w, s, 3, x);
            *decrease = w->sweepDecrease;
            *changed += KeaContactFreeRows(mu, problem->hi[s], x + s, w->wasFree + s);
            return worst;
        }
    }
    for (r = 0; r < 3; ++r)
        d[r] = xn[r] - xb[r];
    if (tally) /* only the sweep after an SM step is asked how much it lowered the objective */
        for (r = 0; r < 3; ++r)
            *decrease -= ME_R(0.5) * d[r] * wb[r];
    if (d[0] != ME_R(0.0) || d[1] != ME_R(0.0) || d[2] != ME_R(0.0))
        KeaContactScatter(&w->B[s], d, v0, onWorld ? NULL : v1);
    for (r = 0; r < 3; ++r) /* d_r = 0: xn_r is x_r */
        x[s + r] = xn[r];
    *changed += KeaContactFreeRows(mu, problem->hi[s], xn, w->wasFree + s);
    return worst;
}

/* One PGS sweep over the blocks, forwards or backwards; returns the largest residual met (the rows'
 * residuals before their steps). Only whether that is within the tolerance matters, so once a row is
 * above it the block steps stop measuring (a sixth of a contact step's work, on a pile that does not
 * converge in ten sweeps); the steps themselves are the same either way. */
static MeReal KeaSweep(const KeaProblem *problem, KeaIterativeWork *w, const KeaParameters *params,
                       MeReal omega, MeReal *x, KeaStats *stats, int backward)
{
    /* decrease: the sweep's running sweepDecrease, in a local so that it can live in a register (in w
     * it chained every block to the last one through a store and a load) */
    MeReal worst = ME_R(0.0), decrease = ME_R(0.0);
    int k, changed = 0;
    for (k = 0; k < w->nBlocks; ++k) {
        const int block = backward ? w->nBlocks - 1 - k : k;
        const int i = w->blockStart[block];
        MeReal lo, hi, wi, xNew, r;
        if (w->blockContact[block]) { /* one call site: the step is inlined into the sweep */
            worst = KeaMax(worst, KeaContactBlockStep(problem, w, block, params->maxFrictionPasses, x, stats,
                                                      w->blockContact[block] == KEA_CONTACT_WORLD,
                                                      worst <= params->tolerance, w->smRan, &decrease, &changed));
            continue;
        }
        if (w->blockStart[block + 1] - i > 1) {
            w->sweepDecrease = decrease;
            worst = KeaMax(worst, KeaBlockStep(problem, w, block, params->maxFrictionPasses, x, stats,
                                               worst <= params->tolerance));
            decrease = w->sweepDecrease;
            continue;
        }
        if (w->invDiag[i] == ME_R(0.0))
            continue;
        KeaRowBoundsInline(problem, x, i, &lo, &hi);
        wi = KeaRowW(problem, w, i, x, &w->dv[w->body[i][0]], &w->dv[w->body[i][1]]);
        r = w->diag[i] * KeaFabs(x[i] - KeaClamp(x[i] - wi * w->invDiag[i], lo, hi));
        worst = KeaMax(worst, r);
        xNew = KeaClamp(x[i] - omega * wi * w->invDiag[i], lo, hi);
        if (xNew != x[i]) {
            decrease -= ME_R(0.5) * (xNew - x[i]) * wi;
            KeaRowApply4(&w->B[i], xNew - x[i], &w->dv[w->body[i][0]], &w->dv[w->body[i][1]]);
            x[i] = xNew;
        }
    }
    w->sweepDecrease = decrease;
    w->sweepChanged = changed;
    return worst;
}

/* dvTmp = M^-1 J_F^T v (v by position in the free list), a piece (KeaFindSegments) at a time in
 * free-list order: a segment through the sweep's block kernels (a contact's world half not
 * written), a row on its own by itself. */
static void KeaScatter(const KeaProblem *problem, const KeaIterativeWork *w, const MeReal *v)
{
    int k;
    memset(w->dvTmp, 0, sizeof(KeaVel4) * (size_t)(problem->nBodies + 1));
    for (k = 0; k < w->nPieces; ++k) {
        const KeaFreePiece *piece = &w->pieces[k];
        KeaVel4 *v0 = &w->dvTmp[piece->body[0]], *v1 = &w->dvTmp[piece->body[1]];
        const MeReal *vp = v + piece->pos;
        if (piece->rows == 1) {
            if (vp[0] != ME_R(0.0))
                KeaRowApply4(&w->B[piece->row], vp[0], v0, v1);
        } else if (piece->kind) {
            KeaContactScatter(&w->B[piece->row], vp, v0, piece->kind == KEA_CONTACT_WORLD ? NULL : v1);
        } else {
            KeaBlockScatter(piece->rows, &w->B[piece->row], vp, v0, v1);
        }
    }
}

/* out[p] = J_i . dv of the free rows (a piece at a time, as KeaScatter). */
static void KeaGather(const KeaIterativeWork *w, const KeaVel4 *dv, MeReal *out)
{
    int k;
    for (k = 0; k < w->nPieces; ++k) {
        const KeaFreePiece *piece = &w->pieces[k];
        const KeaVel4 *v0 = &dv[piece->body[0]], *v1 = &dv[piece->body[1]];
        const KeaJacobianRow *J = &w->J[piece->row];
        MeReal *o = out + piece->pos;
        if (piece->rows == 1) {
            o[0] = KeaRowVel4(J, v0, v1);
        } else if (piece->kind == KEA_CONTACT_WORLD) { /* as the sweep's contact step gathers */
            o[0] = KeaRowVel4World(&J[0], v0);
            o[1] = KeaRowVel4World(&J[1], v0);
            o[2] = KeaRowVel4World(&J[2], v0);
        } else if (piece->kind) {
            o[0] = KeaRowVel4(&J[0], v0, v1);
            o[1] = KeaRowVel4(&J[1], v0, v1);
            o[2] = KeaRowVel4(&J[2], v0, v1);
        } else {
            KeaBlockGather(w, piece->row, piece->rows, v0, v1, o);
        }
    }
}

/* The blocks whose rows are all free (and whose factor exists) become segments of the free list,
 * preconditioned by their exact inverse A_bb^-1; the other free rows by 1 / d_i. */
static void KeaFindSegments(KeaIterativeWork *w, int nFree)
{
    int p = 0;
    w->nSegments = 0;
    w->nPieces = 0;
    while (p < nFree) {
        const int i = w->freeRows[p], b = w->rowBlock[i];
        const int m = w->blockStart[b + 1] - w->blockStart[b];
        KeaFreePiece *piece = &w->pieces[w->nPieces++];
        piece->pos = p;
        piece->row = i;
        piece->body[0] = w->body[i][0];
        piece->body[1] = w->body[i][1];
        if (m > 1 && i == w->blockStart[b] && w->blockFactored[b] && p + m <= nFree &&
            w->freeRows[p + m - 1] == i + m - 1) {
            w->segmentPos[w->nSegments] = p;
            w->segmentBlock[w->nSegments++] = b;
            piece->rows = m;
            piece->kind = w->blockContact[b];
            p += m;
        } else {
            piece->rows = 1;
            piece->kind = 0;
            ++p;
        }
    }
}

/* z = P^-1 res (block-Jacobi preconditioner of the free rows). */
static void KeaPrecondition(const KeaIterativeWork *w, int nFree, const MeReal *res, MeReal *z)
{
    int p = 0, k;
    for (k = 0; k < w->nSegments; ++k) { /* Jacobi up to the segment, then the segment's block */
        const int b = w->segmentBlock[k], m = w->blockStart[b + 1] - w->blockStart[b], start = w->segmentPos[k];
        for (; p < start; ++p)
            z[p] = res[p] * w->invDiag[w->freeRows[p]];
        KeaBlockSymmetricApply(m, w->blockInv + w->blockMatrix[b], res + start, z + start);
        p = start + m;
    }
    for (; p < nFree; ++p)
        z[p] = res[p] * w->invDiag[w->freeRows[p]];
}

/* q += eps p, returning p . q (the new q) in one pass: the sums of KeaDotN4, in its order. */
static MeReal KeaAddEpsDot(MeReal *q, const MeReal *eps, const MeReal *p, int n)
{
    MeReal s0 = ME_R(0.0), s1 = ME_R(0.0), s2 = ME_R(0.0), s3 = ME_R(0.0);
    int m = 0;
    for (; m + 4 <= n; m += 4) {
        const MeReal q0 = q[m] + eps[m] * p[m], q1 = q[m + 1] + eps[m + 1] * p[m + 1];
        const MeReal q2 = q[m + 2] + eps[m + 2] * p[m + 2], q3 = q[m + 3] + eps[m + 3] * p[m + 3];
        q[m] = q0;
        q[m + 1] = q1;
        q[m + 2] = q2;
        q[m + 3] = q3;
        s0 += p[m] * q0;
        s1 += p[m + 1] * q1;
        s2 += p[m + 2] * q2;
        s3 += p[m + 3] * q3;
    }
    for (; m < n; ++m) {
        q[m] = q[m] + eps[m] * p[m];
        s0 += p[m] * q[m];
    }
    return (s0 + s1) + (s2 + s3);
}

/* Row i is free: strictly inside its bounds lo, hi (and not a row that touches nothing). */
static unsigned char KeaRowIsFree(const KeaIterativeWork *w, int i, MeReal xi, MeReal lo, MeReal hi)
{
    return (unsigned char)(w->invDiag[i] != ME_R(0.0) && lo < xi && xi < hi);
}

/* Set wasFree to which rows are free now (KeaRowIsFree); returns how many rows changed. Every
 * chance of an SM step does this, skipped or not, so it is kept cheaper than the bounds and the
 * free list, which only a step that runs needs: the plain contacts, a pile's every block, were
 * tallied by the sweep just before (KeaContactFreeRows), only the other blocks are visited here
 * (their friction bounds can follow a row that a later block of the sweep changed). */
static int KeaUpdateFreeRows(const KeaProblem *problem, KeaIterativeWork *w, const MeReal *x)
{
    unsigned char *was = w->wasFree;
    int b, i, changed = w->sweepChanged;
    if (w->nContactBlocks == w->nBlocks)
        return changed;
    for (b = 0; b < w->nBlocks; ++b) {
        const int s = w->blockStart[b];
        if (w->blockContact[b])
            continue; /* the sweep has tallied it (KeaContactFreeRows) */
        for (i = s; i < w->blockStart[b + 1]; ++i) {
            MeReal lo, hi;
            unsigned char isFree;
            KeaRowBoundsInline(problem, x, i, &lo, &hi);
            isFree = KeaRowIsFree(w, i, x[i], lo, hi);
            changed += isFree != was[i];
            was[i] = isFree;
        }
    }
    return changed;
}

/* Subspace minimisation on the rows strictly inside their bounds; returns the CG steps taken, -1 if
 * skipped because the active set is still moving (top comment). */
static int KeaSubspaceMinimise(const KeaProblem *problem, KeaIterativeWork *w, int maxSteps, MeReal *x)
{
    const int n = problem->nRows, nb = problem->nBodies;
    MeReal rz, rz0, scale;
    int i, p, b, k, nFree = 0, changed = 0, steps = 0, tries;

    changed = KeaUpdateFreeRows(problem, w, x);
    if (changed > 16 && (long)changed * 20 > (long)n && !w->skippedLast) {
        w->skippedLast = 1;
        return -1;
    }
    w->skippedLast = 0;
    if (w->smUnpaid && changed > 16 && (long)changed * 100 > (long)n)
        return -1; /* it did not pay: wait until the active set has settled */
    for (i = 0; i < n; ++i) /* the step runs: list the free rows, freeze their bounds */
        if (w->wasFree[i]) {
            KeaRowBoundsInline(problem, x, i, &w->lo[i], &w->hi[i]);
            w->freeRows[nFree++] = i;
        }
    if (nFree == 0)
        return 0;

    /* Preconditioned CG on A_FF step = -w_F from step = 0. */
    KeaFindSegments(w, nFree);
    KeaGather(w, w->dv, w->grad);
    for (p = 0; p < nFree; ++p) {
        i = w->freeRows[p];
        w->epsFree[p] = w->eps[i];
        w->grad[p] = w->grad[p] + w->eps[i] * x[i] - problem->rhs[i];
        w->step[p] = ME_R(0.0);
        w->res[p] = -w->grad[p];
    }
    KeaPrecondition(w, nFree, w->res, w->z);
    for (p = 0; p < nFree; ++p)
        w->dir[p] = w->z[p];
    rz = rz0 = KeaDotN4(w->res, w->z, nFree);
    if (!(rz0 > ME_R(0.0)))
        return 0;
    w->smRan = 1;
    w->smDecrease = ME_R(0.0);
    while (steps < maxSteps) {
        MeReal pq, a, rzNew, beta;
        KeaScatter(problem, w, w->dir);
        KeaGather(w, w->dvTmp, w->q);
        pq = KeaAddEpsDot(w->q, w->epsFree, w->dir, nFree);
        if (!(pq > ME_R(0.0)))
            break;
        a = rz / pq;
        for (p = 0; p < nFree; ++p) {
            w->step[p] += a * w->dir[p];
            w->res[p] -= a * w->q[p];
        }
        KeaPrecondition(w, nFree, w->res, w->z);
        ++steps;
        rzNew = KeaDotN4(w->res, w->z, nFree);
        if (!(rzNew > ME_SMALL_EPSILON * ME_SMALL_EPSILON * rz0))
            break;
        beta = rzNew / rz;
        for (p = 0; p < nFree; ++p)
            w->dir[p] = w->z[p] + beta * w->dir[p];
        rz = rzNew;
    }
    if (steps == 0)
        return 0;

    /* Projected backtracking line search on the QP objective (bounds frozen). */
    for (tries = 0, scale = ME_R(1.0); tries < 4; ++tries, scale *= ME_R(0.5)) {
        MeReal df = ME_R(0.0);
        for (p = 0; p < nFree; ++p) { /* z holds the trial step s */
            i = w->freeRows[p];
            w->z[p] = KeaClamp(x[i] + scale * w->step[p], w->lo[i], w->hi[i]) - x[i];
        }
        KeaScatter(problem, w, w->z);
        KeaGather(w, w->dvTmp, w->q); /* q is free after CG */
        for (p = 0; p < nFree; ++p) {
            const MeReal As = w->q[p] + w->epsFree[p] * w->z[p];
            df += w->z[p] * (w->grad[p] + ME_R(0.5) * As);
        }
        if (df < ME_R(0.0)) {
            w->smDecrease = -df;
            for (p = 0; p < nFree; ++p)
                x[w->freeRows[p]] += w->z[p];
            for (b = 0; b < nb; ++b)
                for (k = 0; k < 4; ++k) {
                    w->dv[b].lin[k] += w->dvTmp[b].lin[k];
                    w->dv[b].ang[k] += w->dvTmp[b].ang[k];
                }
            break;
        }
    }
    return steps;
}

/* KeaResidual (kea_rows.c) of the final x and dv from the work's diagonal and padded rows (no
 * M^-1 J^T recomputed per row): the same measure, J_i dv summed in the padded kernel's order. */
static MeReal KeaIterativeResidual(const KeaProblem *problem, const KeaIterativeWork *w, const MeReal *x)
{
    MeReal worst = ME_R(0.0);
    int i;
    for (i = 0; i < problem->nRows; ++i) {
        const MeReal d = w->diag[i];
        const MeReal wi = KeaRowW(problem, w, i, x, &w->dv[w->body[i][0]], &w->dv[w->body[i][1]]);
        MeReal lo, hi, r;
        KeaRowBoundsInline(problem, x, i, &lo, &hi);
        r = KeaRowResidual(d, x[i], wi, lo, hi);
        if (r > worst || r != r)
            worst = r;
    }
    return worst;
}

KeaStatus KeaSolveIterative(const KeaProblem *problem, const KeaParameters *params, KeaArena *arena,
                            MeReal *x, KeaBodyVelocity *dv, KeaStats *stats)
{
    const int n = problem->nRows;
    const MeReal omega = params->sor > ME_R(0.0) && params->sor < ME_R(2.0) ? params->sor : ME_R(1.0);
    KeaIterativeWork w;
    KeaStatus status = KeaStatusMaxIterations;
    const int nb = problem->nBodies;
    int i, it, b, k;

    KeaIterativeLayout(arena, n, nb, KEA_MAX_BLOCK_ROWS, &w);
    KeaBodyColumnsFill(problem, w.bodyColumns);
    for (i = 0; i < n; ++i) {
        const int *rb = problem->rowBodies[i];
        const KeaJacobianRow *J = &problem->J[i];
        w.diag[i] = KeaRowInvMassJT4(problem, w.bodyColumns, i, &w.B[i]);
        w.invDiag[i] = w.diag[i] > ME_R(0.0) ? ME_R(1.0) / w.diag[i] : ME_R(0.0);
        w.eps[i] = problem->epsilon ? problem->epsilon[i] : ME_R(0.0);
        w.J[i] = *J; /* then the pads and the world's halves zeroed */
        w.J[i].lin0[3] = w.J[i].ang0[3] = w.J[i].lin1[3] = w.J[i].ang1[3] = ME_R(0.0);
        if (rb[0] < 0) {
            memset(w.J[i].lin0, 0, sizeof w.J[i].lin0);
            memset(w.J[i].ang0, 0, sizeof w.J[i].ang0);
        }
        if (rb[1] < 0) {
            memset(w.J[i].lin1, 0, sizeof w.J[i].lin1);
            memset(w.J[i].ang1, 0, sizeof w.J[i].ang1);
        }
        w.body[i][0] = rb[0] >= 0 ? rb[0] : nb;
        w.body[i][1] = rb[1] >= 0 ? rb[1] : nb;
    }
    KeaSetUpBlocks(problem, &w, KeaBlockCap(n, params->maxBlockRows));
    /* Warm start: clamp (bounds read from the unclamped x, as the direct path does), then dv. */
    for (i = 0; i < n; ++i)
        KeaRowBoundsInline(problem, x, i, &w.lo[i], &w.hi[i]);
    for (i = 0; i < n; ++i)
        x[i] = KeaClamp(x[i], w.lo[i], w.hi[i]);
    KeaBodyVelocityFromImpulses(problem, x, dv);
    for (i = 0; i < n; ++i)
        w.wasFree[i] = KeaRowIsFree(&w, i, x[i], w.lo[i], w.hi[i]);
    w.skippedLast = 0;
    w.smRan = 0;
    w.smUnpaid = 0;
    memset(w.dv, 0, sizeof(KeaVel4) * (size_t)(nb + 1));
    for (b = 0; b < nb; ++b)
        for (k = 0; k < 3; ++k) {
            w.dv[b].lin[k] = dv[b].lin[k];
            w.dv[b].ang[k] = dv[b].ang[k];
        }

    for (it = 1; it <= params->maxIterations; ++it) {
        const MeReal sweepResidual = KeaSweep(problem, &w, params, omega, x, stats, (it & 1) == 0);
        stats->iterations = it;
        if (sweepResidual <= params->tolerance) {
            status = KeaStatusOk;
            break;
        }
        if (w.smRan) /* did the last SM step lower the objective more than this sweep? */
            w.smUnpaid = w.sweepDecrease > w.smDecrease;
        w.smRan = 0;
        if (params->subspaceIterations > 0 && it < params->maxIterations) {
            const int steps = KeaSubspaceMinimise(problem, &w, params->subspaceIterations, x);
            if (steps < 0)
                ++stats->subspaceSkipped;
            else
                stats->subspaceSteps += steps;
        }
    }
    for (b = 0; b < nb; ++b)
        for (k = 0; k < 3; ++k) {
            dv[b].lin[k] = w.dv[b].lin[k];
            dv[b].ang[k] = w.dv[b].ang[k];
        }
    stats->residual = KeaIterativeResidual(problem, &w, x);
    return status;
}
