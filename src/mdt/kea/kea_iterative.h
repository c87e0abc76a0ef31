/* kea_iterative.h -- Kea's iterative path (internal to it): projected Gauss-Seidel (PGS) on the
 * sparse rows, with subspace minimisation (SM) steps between sweeps, for partitions too large for
 * the direct path. Its files, one job each:
 *   kea_blocks.c          block set-up: the workspace layout, the blocks and their inverses
 *   kea_block_kernels.h   the block kernels every part shares (gather, scatter, a block's deltas)
 *   kea_contact_kernel.h  the contact step: one declared contact's exact step (KeaContactBlockStep)
 *   kea_contact_consts.c  the contact step's constants, laid out once a solve (KeaContactConsts)
 *   kea_iterative.c       the sweep, the generic block step and the driver (KeaSolveIterative)
 *   kea_subspace.c        subspace minimisation and its schedule (KeaSubspaceMinimise)
 *   kea_nncg.c            NNCG: a momentum step after each pair of sweeps (KeaNncgStep)
 *   kea_contact_packs.*   declared contacts four to a pack, a lane each (SM's products on them)
 *   kea_joint_packs.*     joint blocks (hinges, fixed joints) four to a pack (SM's gather and
 *                         preconditioner on them)
 * This header holds the padded data, the work struct and the row kernels; the tuning constants
 * (KEA_SM_*, KEA_GATHER_ROW_BY_ROW) are in kea_tuning.h.
 *
 * Data: per row B_i = M^-1 J_i^T (a padded row, like J_i) and the diagonal d_i = J_i B_i + eps_i;
 * per body the velocity change dv = M^-1 J^T x, kept up to date, so that a row needs only its own
 * two bodies: w_i = J_i . dv + eps_i x_i - r_i is O(1) and so is the update dv += B_i delta_i.
 *
 * PGS sweep (rows in index order on odd sweeps, in reverse order on even ones: a one-way sweep moves
 * information quickly one way along a chain of bodies and slowly the other, and the alternating
 * (symmetric) order is what lets a tall pyramid of boxes stand at the default 10 sweeps,
 * tests/mst/test_stacking.c):
 *   x_i <- mid(lo_i, x_i - omega w_i / d_i, hi_i), with lo_i, hi_i
 * the effective bounds at that moment (a friction row reads the current impulse of its normal row),
 * omega the SOR factor. A sweep costs O(n). The sweep also measures the natural-map residual of
 * each row just before its update; the largest is the sweep's residual, compared with the
 * tolerance. PGS converges for A positive definite (0 < omega < 2) but slowly when information must
 * travel along a chain of bodies (a stack of k boxes needs of the order of k^2 sweeps) and on the
 * near-null directions that redundant contacts create (eps small).
 *
 * Block solves: a block of rows is solved exactly with the rest of x fixed. Two kinds of block:
 *  - a declared contact (KeaContact, kea.h: the problem says which rows are contacts; Kea does not
 *    guess it from the rows' shape) is a block of its own (not its whole contact group: decision
 *    K27), solved by the one contact step (KeaContactBlockStep, kea_contact_kernel.h): all rows
 *    free with the block's inverse, else its few active sets in closed form (opening, or one or
 *    both friction rows sliding), else the dense box-LCP solver; its rows are held in locals, and
 *    on the world the world's half (exact zeros) is skipped;
 *  - generic rows: a constraint's rows on one body pair (or a normal row with the rows linked to
 *    it, as a contact with rarer options is written) solved by the generic block step
 *    (KeaBlockStep): all rows free (KeaBlockAllFree, most blocks at rest), else the dense box-LCP
 *    solver (kea_dense_lcp.c); a lone row by a scalar PGS update.
 *
 * Subspace minimisation (after the idea of Silcowitz, Niebe and Erleben, "Interactive rigid body
 * dynamics using a projected Gauss-Seidel subspace minimization method", 2010): see kea_subspace.c.
 *
 * Warm start: x0 is clamped to its bounds and dv computed from it before the first sweep.
 *
 * Data layout (for the cost per row; the arithmetic is the above): dv lives in a padded per-body
 * copy (KeaVel4, 3-vectors padded to 4, plus an all-zero body standing for the world), rows read it
 * through a copy of J with zero pads and zero world halves, so a row kernel has no branch per body
 * half. A block of m > 4 rows (a joint's: a fixed joint has 6) computes its w_b = J_b dv from a 12 x m
 * transpose of its J (KeaColumnsApply, one vectorised column kernel for all block products: w_b
 * through KeaColumnsApplyPair, which reads the two bodies in place,
 * A_bb^-1 w_b, the preconditioner, forming A_bb; a hinge's 5 rows and a fixed joint's 6 through its
 * inlined twins with the row count constant, KeaJointApply, kea_block_kernels.h) and applies its
 * deltas to local copies of its two bodies; SM's matrix-free products go through the declared contacts four at a time, a lane each
 * (kea_contact_packs.h), then through the generic rows' free list a piece (a free row on its own,
 * or a block whose rows are all free) at a time the same way, each piece's rows and bodies listed
 * once per SM step (KeaFreePiece); the free hinges' and fixed joints' gather and preconditioner four
 * blocks at a time (kea_joint_packs.h). */
#ifndef KEA_ITERATIVE_H
#define KEA_ITERATIVE_H

#include <stdatomic.h>
#include <stdint.h>

#include "kea_colour.h"
#include "kea_internal.h"
#include "kea_lanes.h"

/* A stage of the solve that runs a few times a step (the set-up, a sweep) and is kept out of line,
 * so that a profile (callgrind) shows it as a function of its own; a call per sweep costs nothing
 * measurable. */
#if defined(__GNUC__)
#  define KEA_NOINLINE static __attribute__((noinline))
#  define KEA_ALWAYS_INLINE static inline __attribute__((always_inline))
#else
#  define KEA_NOINLINE static
#  define KEA_ALWAYS_INLINE static inline
#endif

typedef struct KeaContactPack KeaContactPack; /* kea_contact_packs.h */
typedef struct KeaJointPack KeaJointPack;     /* kea_joint_packs.h */

/** A body's velocity change with each 3-vector padded to 4 (pad 0). */
typedef struct KeaVel4 {
    _Alignas(16) MeReal lin[4]; /* 16-byte aligned: four-lane loads of it may be aligned ones */
    MeReal ang[4];
} KeaVel4;

/* v[0 .. count - 1] = 0 by two aligned four-lane stores a body: a loop rather than memset, whose
 * glibc version clears a few kilobytes and more by rep stosb, one counted instruction a byte (the
 * instruction counts that measure the solver, bench/README.md). */
static inline void KeaVel4Clear(KeaVel4 *v, int count)
{
    const KeaLanes zero = KeaLanesSplat(ME_R(0.0));
    int b;
    for (b = 0; b < count; ++b) {
        KeaLanesStoreA(v[b].lin, zero);
        KeaLanesStoreA(v[b].ang, zero);
    }
}

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

/** KeaLanesDot2L of a row half read with aligned loads (a 16-byte aligned row, as the work's are:
 *  the loads then fold into the products). */
static inline KeaLanes KeaLanesDot2LA(const MeReal *a, KeaLanes b, const MeReal *c, KeaLanes d)
{
    return KeaLanesAdd(KeaLanesMul(KeaLanesLoadA(a), b), KeaLanesMul(KeaLanesLoadA(c), d));
}

/** A contact's three rows J_r . (v0, v1) in lanes 0-2 (v1 NULL: on the world, whose half adds exact
 *  zeros; J 16-byte aligned, as the work's rows are), the bodies' lanes loaded once for the three:
 *  the sums of KeaRowVel4 / KeaRowVel4World, in their order, the three horizontal sums done at once
 *  (KeaLanesSum3Each). */
static inline KeaLanes KeaContactGather(const KeaJacobianRow *J, const KeaVel4 *v0, const KeaVel4 *v1)
{
    const KeaLanes l0 = KeaLanesLoadA(v0->lin), a0 = KeaLanesLoadA(v0->ang);
    KeaLanes s0 = KeaLanesDot2LA(J[0].lin0, l0, J[0].ang0, a0), s1 = KeaLanesDot2LA(J[1].lin0, l0, J[1].ang0, a0),
             s2 = KeaLanesDot2LA(J[2].lin0, l0, J[2].ang0, a0);
    if (v1) {
        const KeaLanes l1 = KeaLanesLoadA(v1->lin), a1 = KeaLanesLoadA(v1->ang);
        s0 = KeaLanesAdd(s0, KeaLanesDot2LA(J[0].lin1, l1, J[0].ang1, a1));
        s1 = KeaLanesAdd(s1, KeaLanesDot2LA(J[1].lin1, l1, J[1].ang1, a1));
        s2 = KeaLanesAdd(s2, KeaLanesDot2LA(J[2].lin1, l1, J[2].ang1, a1));
    }
    return KeaLanesSum3Each(s0, s1, s2);
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

/** v1 += sum_r B_r d_r over the second halves of m rows (rows with d_r = 0 skipped), row after row:
 *  a block whose first half is the world's, which is not written (its dv stays zero; a split sweep's
 *  blocks on the world read it at once). The same sums as KeaBlockScatterSized's second half. */
static inline void KeaBlockScatterHalf1(int m, const KeaJacobianRow *B, const MeReal *d, KeaVel4 *v1)
{
    int r;
    for (r = 0; r < m; ++r)
        if (d[r] != ME_R(0.0))
            KeaHalfApply4(B[r].lin1, B[r].ang1, d[r], v1);
}

enum { KEA_CONTACT_BODIES = 1, KEA_CONTACT_WORLD = 2 }; /* a declared contact between two bodies, or on the world */

/** SM: one piece of the free list after its pack region (kea_contact_packs.h) for its matrix-free
 *  products, everything they read about it in one place: a free row on its own, or a segment (a
 *  generic block whose rows are all free). */
typedef struct KeaFreePiece {
    int pos;      /**< its first position in the free list */
    int row;      /**< its first row */
    int rows;     /**< 1 for a row on its own, else the block's size */
    int body[2];  /**< the row halves' bodies (the world: nb) */
    int matrix;   /**< a segment: its block's offset in blockInv (the preconditioner); else -1 */
} KeaFreePiece;

/** A declared contact's constants for the contact step (kea_contact_kernel.h), laid out once a
 *  solve (KeaContactConstsFill) as the step reads them, padded to lanes (pads 0): at JT + 12 s, the
 *  room its block's transpose would take, which a contact (gathered row by row) does not use; and
 *  which of its rows are free, the one field the sweep writes. */
typedef struct KeaContactConsts {
    _Alignas(16) MeReal inv[3][4]; /**< the columns of its block's inverse A_bb^-1 (when factored) */
    MeReal eps[4];                 /**< its rows' eps_i */
    MeReal rhs[4];                 /**< its rows' r_i */
    MeReal mu[4];                  /**< its friction rows' mu (lanes 1, 2; lane 0 is 0) */
    int freeRows;                  /**< SM: bit r set where row r is free (wasFree of the other rows):
                                        from the warm start, then kept by the sweep (KeaContactFreeRows);
                                        an int, not bytes: a byte store may alias anything for the
                                        compiler, which then reloads the work's arrays after each */
} KeaContactConsts;

/** The contact step's record of the declared contact whose rows start at s. */
static inline KeaContactConsts *KeaContactConstsOf(MeReal *JT, int s)
{
    return (KeaContactConsts *)(void *)(JT + 12 * s);
}

/** What one sweep carries from block to block and hands to each block step: a local of KeaSweep
 *  (the steps are inlined into it, so its fields live in registers, where in the work struct each
 *  block's tally would wait for the last one's store). */
typedef struct KeaSweepState {
    MeReal decrease;   /**< the sweep's running estimate of the QP objective's decrease */
    int changed;       /**< declared contacts' rows that went between free and a bound so far */
    int measure;       /**< the residual is still within the tolerance: measure this block's */
    int tally;         /**< an SM step ran before this sweep: the contacts tally the decrease */
    int maxPasses;     /**< the dense solver's friction passes (KeaParameters.maxFrictionPasses) */
    KeaStats *stats;   /**< the solve's statistics (the dense solver's pivots) */
} KeaSweepState;

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
    MeReal *blockInv;      /**< their inverses A_bb^-1 (same offsets): a block solve in a sweep or
                                a preconditioner step is then one small matrix-vector product,
                                no divisions (each block is solved once a sweep, and
                                again per SM step when free, but factored once a step) */
    unsigned char *blockFactored; /**< the factor exists (A_bb safely positive definite) */
    unsigned char *blockContact;  /**< KEA_CONTACT_* kind of a declared contact's block (KeaContact), else 0 */
    unsigned char *wasFree;       /**< SM: the row was free at the last SM step (or the warm start); a
                                       declared contact's rows: its KeaContactConsts.freeRows after the set-up */
    int skippedLast;              /**< SM: the last SM step was skipped */
    MeReal sweepDecrease;         /**< estimated decrease of the QP objective by the last sweep
                                       (KeaSweepState.decrease at its end; its contacts tallied only
                                       in a sweep after an SM step, the one whose figure is read) */
    MeReal smDecrease;            /**< decrease of the objective by that SM step (0 if rejected) */
    int smRan;                    /**< an SM step ran since the last sweep */
    int smUnpaid;                 /**< SM: the last SM step did less than the sweep after it */
    MeReal smStop;                /**< SM: CG stops once r.z is at most this times its first value
                                       (KeaParameters.subspaceStop, at least KEA_SM_CG_STOP) */
    int nContactBlocks;           /**< blocks that are declared contacts (blockContact) */
    int sweepChanged;             /**< declared contacts' rows that went between free and a bound in
                                       the last sweep (tallied by its steps) */
    int sweepAbove;               /**< blocks of the last sweep whose residual was above its measureUpTo,
                                       when it counted them (a round's last sweep under the extra effort) */
    MeReal *localW;        /**< a block's w */
    int *rowBlock;         /**< block of each row */
    KeaFreePiece *pieces;  /**< SM: the free list after its pack region as rows on their own and
                                segments (free blocks, preconditioned by their inverse), in order */
    int nPieces;
    int *loosePieces;      /**< SM, a solve not split: the pieces not in a joint pack (kea_joint_packs.h), in order */
    int nLoosePieces;
    KeaContactPack *packs; /**< the declared contacts four to a pack (kea_contact_packs.h) */
    int nPacks;            /**< -1 until the solve's first SM step builds them */
    unsigned char *packed; /**< a declared contact's row: its place in SM's free list is in the packs */
    KeaJointPack *jointPacks; /**< SM: joint blocks of 5 or 6 rows four to a pack (kea_joint_packs.h) */
    int nJointPacks;       /**< -1 until the solve's first SM step builds them (0 in a split solve) */
    int *jointPackOf;      /**< each block's pack and lane in it, 4 pack + lane, or -1 */
    MeReal *localR, *localLo, *localHi, *localX; /**< a block's LCP (maxBlockRows each) */
    int *localLink;
    KeaDenseWork *dense;   /**< the dense solver, sized for maxBlockRows */
    /* Subspace minimisation: */
    int *freeRows;         /**< rows strictly inside their bounds (the pack region: every pack's
                                rows, masked or not; then the generic rows that are free) */
    MeReal *lo, *hi;       /**< the warm start's bounds (by row); then SM's, frozen for its step
                                (by position in the free list) */
    MeReal *xFree;         /**< SM: x on the free rows (by position), as the step found it */
    MeReal *grad;          /**< w on the free rows (by position) */
    MeReal *epsFree;       /**< eps of the free rows (by position) */
    MeReal *step;          /**< CG solution delta */
    MeReal *res, *z, *dir, *q; /**< CG vectors */
    /* Row kernels on padded data: J_i . dv and dv += B_i s as four-wide operations with no branch
     * per body half. Bodies are KeaVel4 (4-padded 3-vectors, pads 0) with one extra all-zero body
     * at index nb that stands for the world; the rows' copies of J have zero pads and zero halves
     * on the world, so that the extra body contributes exact zeros. */
    const KeaJacobianRow *J; /**< J_i with pads and world halves zeroed: paddedJ, or the problem's own
                                  J when its caller proved it so (KeaSolveRowsProved) */
    KeaJacobianRow *paddedJ; /**< the work's copy of J, pads and world halves zeroed */
    MeReal *JT;            /**< per block of m rows from s, its 12 x m transpose J_b^T (pads
                                dropped) at JT + 12 s: J_b v is then a sum of 12 columns; a
                                declared contact's (gathered row by row) holds its
                                KeaContactConsts instead */
    MeReal *localD;        /**< a block's impulse changes */
    int (*body)[2];        /**< row halves' bodies, KEA_WORLD mapped to nb */
    MeReal *eps;           /**< eps_i (0 when the problem has none) */
    KeaVel4 *dv;           /**< the solve's dv (nb + 1), copied out at the end */
    KeaVel4 *dvTmp;        /**< per-body scratch for A_FF p and for the trial step (nb + 1) */
    KeaVel4 *dvStep;       /**< SM: M^-1 J_F^T step, summed over CG's steps (nb + 1) */
    int *clamped;          /**< SM: the trial step's positions that a bound clamps */
    /* NNCG (kea_nncg.c): */
    MeReal *xPrev;         /**< x before the last sweep (after its momentum step) */
    MeReal *nncgDir;       /**< the momentum direction p (by row) */
    KeaVel4 *dvPrev;       /**< dv before the last sweep (nb + 1) */
    KeaVel4 *dvDir;        /**< M^-1 J^T p (nb + 1) */
    MeReal nncgLast;       /**< |x change|^2 of the sweep before (0: none yet) */
    /* Deflation (kea_deflation.c), beside NNCG's arrays above: */
    MeReal *xStart;        /**< x at the warm start */
    KeaVel4 *dvStart;      /**< dv at the warm start (nb + 1) */
    int nb;                /**< bodies: dv[nb] is the world's, all zero, never written by a sweep */
    struct KeaSplit *split; /**< a split solve's colouring and workers (kea_split.c); NULL: not split */
} KeaIterativeWork;

/* ---- the split solve (kea_split.c) ------------------------------------------------------------
 * One large partition over several workers, bit-identical for any worker count (docs/kea.md,
 * "One partition on several cores"): the blocks are coloured (kea_colour.c) so that no two blocks
 * of a colour share a body, and a sweep takes the colours one after the other, each colour's blocks
 * in fixed chunks of KEA_SPLIT_CHUNK blocks handed to the workers (a barrier between colours: the
 * hook returns when the colour is done). Every chunk keeps its own tallies (the objective's decrease,
 * the residual, the rows that changed, the dense solver's pivots), added afterwards in chunk order;
 * SM's loops run over fixed chunks of KEA_SPLIT_PACKS packs, then of KEA_SPLIT_PIECES pieces of its
 * free list, their dot products as one partial sum per chunk, added in chunk order; its scatter
 * takes the packs colour by colour (KeaSplitPacks), then the pieces colour by colour; the set-up's
 * loops over rows and blocks (each item writing only its own entries) in chunks too. The chunks depend on the problem only, never
 * on the workers, so neither does any bit of the result. */

/** Blocks per chunk of a colour in a split sweep, at least (whole units: a pair's blocks stay in one
 *  chunk; a contact is one block, three rows). */
#define KEA_SPLIT_CHUNK 16
/** Pieces of SM's free list (KeaFreePiece) per chunk of its loops in a split solve (at least, for
 *  its scatter: whole units). */
#define KEA_SPLIT_PIECES 128
/** Packs of four contacts (kea_contact_packs.h) per chunk of SM's loops in a split solve (their
 *  scatter: per chunk of a colour's packs, KeaSplitPacks). */
#define KEA_SPLIT_PACKS 32
/** Rows per chunk of the set-up's row loops, and blocks per chunk of its block set-up, in a split solve. */
#define KEA_SPLIT_ROWS 256
#define KEA_SPLIT_BLOCKS 64

/** Row chunks of KEA_SPLIT_ROWS rows covering n rows (the last may be shorter). */
static inline int KeaRowChunkCount(int n) { return (n + KEA_SPLIT_ROWS - 1) / KEA_SPLIT_ROWS; }

/** One past the last row of row chunk j of n rows. */
static inline int KeaRowChunkEnd(int j, int n) { return (j + 1) * KEA_SPLIT_ROWS < n ? (j + 1) * KEA_SPLIT_ROWS : n; }

/** A chunk's tallies in one split sweep, added afterwards in chunk order. */
typedef struct KeaSplitChunk {
    MeReal decrease;  /**< KeaSweepState.decrease over the chunk's blocks */
    MeReal worst;     /**< the largest residual measured */
    int changed;      /**< KeaSweepState.changed */
    int above;        /**< blocks above measureUpTo, when counted (KeaIterativeWork.sweepAbove) */
    int pivots;       /**< the dense solver's pivots (KeaStats.pivots) */
    int regularised;  /**< and its raised pivots (KeaStats.regularised) */
} KeaSplitChunk;

/** One worker's block scratch (KeaIterativeWork's local* arrays and dense solver). */
typedef struct KeaBlockScratch {
    MeReal *localW, *localR, *localLo, *localHi, *localX, *localD;
    int *localLink;
    KeaDenseWork *dense;
} KeaBlockScratch;

/** The workers' team of a split solve (kea_split.c, KeaSplitDrive): the driver and the stage it has
 *  published for the helpers. */
typedef struct KeaTeamStage {
    atomic_int items;           /**< the stage's items */
    _Atomic(KeaTaskFn) task;    /**< its task */
    _Atomic(void *) data;       /**< and its data */
} KeaTeamStage;

typedef struct KeaTeam {
    _Atomic(uint64_t) cursor;   /**< the stage's generation (high half) and its next item (low half) */
    atomic_int completed;       /**< items of the stage that have run */
    KeaTeamStage stage[2];      /**< stage g in stage[g & 1]: the next one is written while a helper
                                     late on this one may still read it (its claim then fails) */
    atomic_int driving;         /**< an item has become the driver */
    atomic_int done;            /**< the driver has finished the solve */
    unsigned generation;        /**< the driver's: stages published */
    int driverWorker;           /**< the driver's worker index */
    void (*drive)(void *);      /**< the solve */
    void *driveData;
} KeaTeam;

typedef struct KeaSplit {
    KeaTaskHook hook;      /**< the caller's workers (hook.workers >= 1; run NULL: inline) */
    KeaTeam *team;         /**< the team while the solve runs on it (KeaSplitDrive), else NULL */
    int *order;            /**< the blocks sorted by colour, each colour in block order (nBlocks) */
    int *colour;           /**< each unit's colour (a unit: consecutive blocks on one body pair) */
    int (*pairs)[2];       /**< each unit's bodies for the colouring */
    int *unitStart;        /**< unit u is blocks unitStart[u] .. unitStart[u + 1] - 1 */
    int *unitOrder;        /**< the units sorted by colour */
    int *blockUnit;        /**< each block's unit */
    int *pieceOrder;       /**< SM's scatter: the free list's pieces by colour, each colour's in order */
    int *pieceChunk;       /**< its chunks: pieceOrder[pieceChunk[k] .. pieceChunk[k + 1]) (whole units) */
    int pieceColourChunk[KEA_COLOUR_COUNT + 2]; /**< colour c's scatter chunks */
    int *packBodies;       /**< SM's scatter: each pack's eight halves' bodies for its colouring (world: none) */
    int *packColour;       /**< each pack's colour (no two packs of a colour share a body) */
    int *packOrder;        /**< the packs by colour, each colour's in pack order */
    int *packChunk;        /**< the packs' scatter chunks: packOrder[packChunk[k] .. packChunk[k + 1]) */
    int packColourChunk[KEA_COLOUR_COUNT + 2]; /**< colour c's pack scatter chunks */
    void *colourWork;      /**< the colouring's workspace (a mask of colours per body) */
    size_t colourBytes;
    int colourStart[KEA_COLOUR_COUNT + 2]; /**< colour c is order[colourStart[c] .. colourStart[c + 1]) (the
                                                 colouring's units at first) */
    int colourChunk[KEA_COLOUR_COUNT + 2]; /**< colour c's chunks are colourChunk[c] .. colourChunk[c + 1] - 1 */
    int *chunkStart;       /**< chunk k is order[chunkStart[k] .. chunkStart[k + 1]) */
    int nChunks;
    int colours;           /**< colours in use (the overflow colour not counted) */
    KeaSplitChunk *chunks; /**< one per chunk */
    MeReal *partial;       /**< SM: one partial sum per chunk (of KEA_SPLIT_PACKS packs or KEA_SPLIT_PIECES pieces) */
    KeaBlockScratch *scratch; /**< per worker; worker 0's are the work's own */
    KeaIterativeWork *works;  /**< per worker: a copy of the work with its scratch (made per sweep) */
} KeaSplit;

/* kea_split.c: its workspace (counting mode with arena->base NULL), the workers a hook gives, the
 * colouring of the blocks after KeaSetUpBlocks (0: the split cannot apply, a friction link leaves its
 * block: the solve is then not split), running items over the workers, and SM's scatter order for
 * the current free list (pieces: nPieces of them). */
void KeaSplitLayout(KeaArena *arena, int n, int nb, int workers, KeaSplit *split);
int KeaSplitWorkers(const KeaTaskHook *hook);
int KeaSplitColour(const KeaProblem *problem, KeaIterativeWork *w, KeaSplit *split);
void KeaSplitRun(const KeaSplit *split, KeaTaskFn task, int items, void *data);
void KeaSplitDrive(KeaSplit *split, void (*drive)(void *), void *data);
void KeaSplitWorks(const KeaIterativeWork *w, KeaSplit *split);
void KeaSplitPieces(const KeaIterativeWork *w, KeaSplit *split);
/* SM's pack scatter order, once the packs are built (KeaPacksFill): the packs coloured by their
 * bodies (the world in no colour), each colour's in chunks of KEA_SPLIT_PACKS packs. */
void KeaSplitPacks(const KeaIterativeWork *w, KeaSplit *split);

/* SM's free-list positions for n rows at most: the pack region (12 per pack of up to four of the at
 * most n / 3 contacts, masked lanes included) and every row again after it. */
static inline int KeaFreePositions(int n) { return n + 12 * (n / 12 + 1); }

/* Rows per block at most: maxBlockRows within 1 ... KEA_MAX_BLOCK_ROWS and the problem size. */
static inline int KeaBlockCap(int n, int maxBlockRows)
{
    const int cap = maxBlockRows < KEA_MAX_BLOCK_ROWS ? maxBlockRows : KEA_MAX_BLOCK_ROWS;
    return cap < 1 ? 1 : (cap < n ? cap : (n > 0 ? n : 1));
}

/* Row i is free: strictly inside its bounds lo, hi (and not a row that touches nothing). */
static inline unsigned char KeaRowIsFree(const KeaIterativeWork *w, int i, MeReal xi, MeReal lo, MeReal hi)
{
    return (unsigned char)(w->invDiag[i] != ME_R(0.0) && lo < xi && xi < hi);
}

/* kea_blocks.c: lay the work struct out in the arena (n rows, nb bodies, blocks of at most
 * maxBlockRows rows), then split the rows into blocks and form and invert each block's matrix. */
void KeaIterativeLayout(KeaArena *arena, int n, int nb, int maxBlockRows, KeaIterativeWork *w);
void KeaSetUpBlocks(const KeaProblem *problem, KeaIterativeWork *w, int cap);

/* kea_contact_consts.c: every declared contact's KeaContactConsts, after KeaSetUpBlocks and the warm
 * start (wasFree). */
void KeaContactConstsFill(const KeaProblem *problem, KeaIterativeWork *w);

/* kea_nncg.c: NNCG's momentum step (KeaParameters.nonsmoothCg): KeaNncgStart before the first sweep,
 * KeaNncgStep after each sweep but the last (returns beta, 0 at a restart). */
void KeaNncgStart(KeaIterativeWork *w, const MeReal *x, int n);
MeReal KeaNncgStep(KeaIterativeWork *w, MeReal *restrict x, int n);

/* kea_deflation.c: the coarse correction (KeaParameters.deflation): KeaDeflationStart before the
 * first sweep, KeaDeflationStep after each pair of sweeps but the last (returns the objective's
 * change, 0 when no step lowered it); KeaDeflationSolve, its k x k system (k <= 3, tests). */
void KeaDeflationStart(KeaIterativeWork *w, const MeReal *x, int n);
MeReal KeaDeflationStep(const KeaProblem *problem, KeaIterativeWork *w, MeReal *x);
int KeaDeflationSolve(int k, const MeReal G[9], const MeReal g[3], MeReal alpha[3]);

/* kea_subspace.c: one SM chance after a sweep; returns the CG steps taken, -1 if skipped. */
int KeaSubspaceMinimise(const KeaProblem *problem, KeaIterativeWork *w, int maxSteps, MeReal *x);

#endif
