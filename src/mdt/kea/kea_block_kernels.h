/* kea_block_kernels.h -- the block kernels the iterative path's parts share (kea_iterative.h): a
 * block's product with a symmetric matrix, J_b dv (gather), dv += B_b d (scatter), applying a
 * block's impulse changes, and the dense solver on a block's small LCP. Static inline: each part
 * that includes this gets its own inlined copy, the same arithmetic everywhere. */
#ifndef KEA_BLOCK_KERNELS_H
#define KEA_BLOCK_KERNELS_H

#include <string.h>

#include "kea_iterative.h"

/* A joint's block (more than 4 rows, at most 8: a hinge has 5, a fixed joint 6) times a vector,
 * column by column with the sums of KeaColumnsApply (kea_rows.c: each out[r] a running sum over the
 * columns in order, from +0), rows 0-3 in lanes and the others one by one. Inlined where m and the
 * column count are constants, so that it unrolls: in the general kernel its call, the copy of its
 * input and its loops cost more than the products. */
enum { KEA_JOINT_ROWS_MAX = 8 };

/* acc (rows 0-3) and tail (rows 4 ... m - 1) += column (m rows) times v. */
static inline void KeaJointColumn(const int m, const MeReal *column, MeReal v, KeaLanes *acc, MeReal *tail)
{
    int r;
    *acc = KeaLanesAdd(*acc, KeaLanesMul(KeaLanesLoad(column), KeaLanesSplat(v)));
    for (r = 4; r < m; ++r)
        tail[r - 4] += column[r] * v;
}

static inline void KeaJointColumnsOut(const int m, KeaLanes acc, const MeReal *tail, MeReal *out)
{
    int r;
    KeaLanesStore(out, acc);
    for (r = 4; r < m; ++r)
        out[r] = tail[r - 4];
}

/* out = M in for the m x nc column-major M. */
static inline void KeaJointApply(const int m, const int nc, const MeReal *M, const MeReal *in, MeReal *out)
{
    KeaLanes acc = KeaLanesSplat(ME_R(0.0));
    MeReal tail[KEA_JOINT_ROWS_MAX - 4] = {ME_R(0.0), ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    int c;
    for (c = 0; c < nc; ++c)
        KeaJointColumn(m, M + c * m, in[c], &acc, tail);
    KeaJointColumnsOut(m, acc, tail, out);
}

/* out = M (v0, v1) for the m x 12 column-major M of a block's J_b^T (KeaColumnsApplyPair's sums):
 * component c of the bodies is half c / 3 of (v0 lin, v0 ang, v1 lin, v1 ang), entry c % 3. */
static inline void KeaJointApplyPair(const int m, const MeReal *M, const KeaVel4 *v0, const KeaVel4 *v1, MeReal *out)
{
    const MeReal *const half[4] = {v0->lin, v0->ang, v1->lin, v1->ang};
    KeaLanes acc = KeaLanesSplat(ME_R(0.0));
    MeReal tail[KEA_JOINT_ROWS_MAX - 4] = {ME_R(0.0), ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    int c;
    for (c = 0; c < 12; ++c)
        KeaJointColumn(m, M + c * m, half[c / 3][c % 3], &acc, tail);
    KeaJointColumnsOut(m, acc, tail, out);
}

/* out = M in for a symmetric m x m block M (out and in distinct): KeaColumnsApply (kea_rows.c); a
 * contact's 3 x 3, the most common block, inline with the same sums, and a hinge's and a fixed
 * joint's by KeaJointApply. */
static inline void KeaBlockSymmetricApply(int m, const MeReal *M, const MeReal *in, MeReal *out)
{
    int r;
    switch (m) {
    case 3:
        for (r = 0; r < 3; ++r)
            out[r] = (M[r] * in[0] + M[3 + r] * in[1]) + M[6 + r] * in[2];
        break;
    case 5: KeaJointApply(5, 5, M, in, out); break;
    case 6: KeaJointApply(6, 6, M, in, out); break;
    default: KeaColumnsApply(m, m, M, in, out); break;
    }
}

/* out = J_b (v0, v1) for the block of m rows from s (all on the same two bodies): a block of more
 * than KEA_GATHER_ROW_BY_ROW rows from its transpose JT (12 x m), column by column, each out[r] its own running sum
 * over the 12 components in order (a hinge's and a fixed joint's by KeaJointApplyPair); a smaller one row by row. */
_Static_assert(KEA_GATHER_ROW_BY_ROW == 4, "KeaBlockGatherSmall is written out for 4 rows");

static inline void KeaBlockGatherSmall(const KeaIterativeWork *w, int s, int m, const KeaVel4 *v0, const KeaVel4 *v1,
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

/* KeaBlockGatherSmall of three rows (a ball joint) with the bodies' lanes loaded once and the three
 * horizontal sums done at once (KeaContactGather: KeaRowVel4's sums, the world's half included). */
static inline void KeaBlockGather3(const KeaIterativeWork *w, int s, const KeaVel4 *v0, const KeaVel4 *v1, MeReal *out)
{
    _Alignas(16) MeReal rows[4];
    KeaLanesStoreA(rows, KeaContactGather(&w->J[s], v0, v1));
    out[0] = rows[0];
    out[1] = rows[1];
    out[2] = rows[2];
}

static inline void KeaBlockGather(const KeaIterativeWork *w, int s, int m, const KeaVel4 *v0, const KeaVel4 *v1,
                                  MeReal *out)
{
    const MeReal *JT = w->JT + 12 * s;
    switch (m) {
    case 3: KeaBlockGather3(w, s, v0, v1, out); break;
    case 5: KeaJointApplyPair(5, JT, v0, v1, out); break;
    case 6: KeaJointApplyPair(6, JT, v0, v1, out); break;
    default:
        if (m <= KEA_GATHER_ROW_BY_ROW) /* a ball joint, a contact point: row by row */
            KeaBlockGatherSmall(w, s, m, v0, v1, out);
        else
            KeaColumnsApplyPair(m, JT, v0->lin, v0->ang, v1->lin, v1->ang, out);
        break;
    }
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

/* v += sum_r B_r d_r over a contact's three rows, on body half `half` of B (16-byte aligned, as the
 * work's rows are: the loads fold into the products), d splatted. */
static inline void KeaContactScatterHalf(const KeaJacobianRow *B, const KeaLanes *d, int half, KeaVel4 *v)
{
    KeaLanes lin = KeaLanesLoadA(v->lin), ang = KeaLanesLoadA(v->ang);
    int r;
    for (r = 0; r < 3; ++r) {
        lin = KeaLanesAdd(lin, KeaLanesMul(KeaLanesLoadA(half ? B[r].lin1 : B[r].lin0), d[r]));
        ang = KeaLanesAdd(ang, KeaLanesMul(KeaLanesLoadA(half ? B[r].ang1 : B[r].ang0), d[r]));
    }
    KeaLanesStoreA(v->lin, lin);
    KeaLanesStoreA(v->ang, ang);
}

/* KeaBlockScatterSized for a contact's three rows (v0 != v1; v1 NULL on the world), d in lanes 0-2,
 * without its test per row: a row with d_r = 0 adds B_r 0, zeros (the same values; only a -0 in dv
 * may become +0, which no later comparison or product tells apart). */
static inline void KeaContactScatter(const KeaJacobianRow *B, KeaLanes d, KeaVel4 *v0, KeaVel4 *v1)
{
    const KeaLanes ds[3] = {KeaLanesSplat(KeaLanesAt(d, 0)), KeaLanesSplat(KeaLanesAt(d, 1)),
                            KeaLanesSplat(KeaLanesAt(d, 2))};
    KeaContactScatterHalf(B, ds, 0, v0);
    if (v1)
        KeaContactScatterHalf(B, ds, 1, v1);
}

static inline void KeaBlockScatter(int m, const KeaJacobianRow *B, const MeReal *d, KeaVel4 *v0, KeaVel4 *v1)
{
    int r;
    if (v0 == v1) { /* a block whose halves are the same body: one update after the other */
        for (r = 0; r < m; ++r)
            if (d[r] != ME_R(0.0))
                KeaRowApply4(&B[r], d[r], v0, v1);
    } else if (m == 3) { /* a contact */
        KeaBlockScatterSized(3, B, d, v0, v1);
    } else if (m == 5) { /* a hinge */
        KeaBlockScatterSized(5, B, d, v0, v1);
    } else if (m == 6) { /* a fixed joint */
        KeaBlockScatterSized(6, B, d, v0, v1);
    } else {
        KeaBlockScatterSized(m, B, d, v0, v1);
    }
}

/* Apply the deltas xNew - x of the block's m rows from s (all on the same two bodies) to dv and x,
 * in row order, lowering *decrease by the objective's estimated decrease; wb holds the block's w
 * before the step, d (m entries) takes the deltas. Size: the step's block, its new values and its w,
 * as the block steps hold them (in their locals, or in the work's block scratch). */
static inline void KeaBlockApplyNew(KeaIterativeWork *w, int s, int m, const MeReal *xNew, const MeReal *wb, MeReal *d,
                                    MeReal *x, MeReal *decrease)
{
    MeReal decreased = *decrease; /* a local: *decrease may be the sweep's, in memory */
    int r;
    for (r = 0; r < m; ++r) {
        d[r] = xNew[r] - x[s + r];
        decreased -= ME_R(0.5) * d[r] * wb[r];
    }
    *decrease = decreased;
    /* the world's half (dv[nb], all zero) is not written: a split sweep's blocks on the world run at once */
    if (w->body[s][0] != w->nb)
        KeaBlockScatter(m, &w->B[s], d, &w->dv[w->body[s][0]], w->body[s][1] == w->nb ? NULL : &w->dv[w->body[s][1]]);
    else if (w->body[s][1] != w->nb)
        KeaBlockScatterHalf1(m, &w->B[s], d, &w->dv[w->body[s][1]]);
    for (r = 0; r < m; ++r)
        if (d[r] != ME_R(0.0))
            x[s + r] = xNew[r];
}

/* KeaBlockApplyNew of the work's block scratch: localX the new x, localW the block's w. */
static inline void KeaBlockApplyDeltas(KeaIterativeWork *w, int s, int m, MeReal *x, MeReal *decrease)
{
    KeaBlockApplyNew(w, s, m, w->localX, w->localW, w->localD, x, decrease);
}

/* The block's local box-LCP with the dense solver: its matrix A_bb, r_loc in localR, own bounds in
 * localLo and localHi, links local to the block (or -1) in localLink, and localX the warm start on
 * entry and the solution on return. */
static inline void KeaSmallLcp(const KeaProblem *problem, KeaIterativeWork *w, int block, int maxPasses,
                               KeaStats *stats)
{
    const int s = w->blockStart[block];
    KeaDenseLcp lcp;
    KeaStats local;
    lcp.n = w->blockStart[block + 1] - s;
    lcp.A = w->blockA + w->blockMatrix[block];
    lcp.r = w->localR;
    lcp.lo = w->localLo;
    lcp.hi = w->localHi;
    lcp.link = problem->mu ? w->localLink : NULL;
    lcp.mu = problem->mu ? problem->mu + s : NULL;
    lcp.order = NULL;
    lcp.patternStart = lcp.pattern = NULL;
    lcp.rows = NULL;
    lcp.velocity = NULL;
    memset(&local, 0, sizeof local);
    (void)KeaDenseLcpSolve(&lcp, 0, maxPasses, w->dense, w->localX, &local);
    stats->pivots += local.pivots;
    stats->regularised += local.regularised;
}

#endif
