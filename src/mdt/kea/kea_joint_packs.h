/* kea_joint_packs.h -- SM's gather and preconditioner on joint blocks four at a time (kea_iterative.h):
 * a pack holds four generic blocks of the same size, 5 rows (a hinge) or 6 (a fixed joint, a hinge
 * with its limit or motor row), as structure of arrays: each entry of their 12 x m transposes J_b^T
 * and of their m x m inverses A_bb^-1 as four lanes, one block per lane. Each row's product is then
 * a four-lane running sum over the columns in order, from +0: in every lane the sums of KeaJointApply
 * and KeaJointApplyPair (kea_block_kernels.h), so the same bits as the piece-by-piece kernels, with
 * no splat of the input per column and no scalar tail for rows 4 and 5.
 *
 * Only the two products whose rows are independent go through the packs; SM's vectors stay in the
 * free list's positions (a pack reads and writes each lane's segment there, through 4 x 4
 * transposes), so its dot products and updates keep their order. The scatter (M^-1 J^T v) stays
 * segment by segment in free-list order: neighbouring joints share bodies, and each body's sum must
 * take their rows in that order.
 *
 * The packs are built once per solve, at its first SM step that runs (KeaJointPacksFill: every
 * factored generic block of 5 or 6 rows, in block order, four of one size to a pack); each SM step
 * marks which lanes are free segments of the free list and where (KeaJointPacksMark, from
 * KeaFindSegments). A split solve does not use them (its gathers run over chunks of pieces). */
#ifndef KEA_JOINT_PACKS_H
#define KEA_JOINT_PACKS_H

#include "kea_contact_packs.h"

enum {
    KEA_JOINT_PACK_LANES = 4, /* blocks per pack */
    KEA_JOINT_PACK_ROWS = 6   /* rows per block at most (at least 5) */
};

struct KeaJointPack {
    _Alignas(16) MeReal J[KEA_JOINT_PACK_ROWS][12][KEA_JOINT_PACK_LANES]; /**< J_b of row r, component c
                                                   (0-2 lin, 3-5 ang on body 0, 6-11 on body 1), lane l */
    MeReal inv[KEA_JOINT_PACK_ROWS][KEA_JOINT_PACK_ROWS][KEA_JOINT_PACK_LANES]; /**< A_bb^-1 column c, row r */
    int body[2][KEA_JOINT_PACK_LANES]; /**< the halves' bodies (the world, and a lane with no block: nb) */
    int pos[KEA_JOINT_PACK_LANES];     /**< SM: each free lane's first position; a lane not free: a free one's */
    int rows;                          /**< 5 or 6 */
    int lanes;                         /**< lanes that hold a block: 0 ... lanes - 1 */
    int active;                        /**< SM: bit l set where lane l's block is a free segment */
};

/* Packs at most for n rows: blocks of at least 5 rows, four to a pack, a part-filled pack per size. */
static inline int KeaJointPacksMax(int n) { return n / (5 * KEA_JOINT_PACK_LANES) + 2; }

/* The pack's free lanes' rows (o[r]: row r, a lane each) to out at each lane's position. */
static inline void KeaJointPackStore(const int m, const KeaJointPack *pack, KeaLanes *o, MeReal *out)
{
    _Alignas(16) MeReal tail[KEA_JOINT_PACK_ROWS - 4][KEA_JOINT_PACK_LANES];
    int l, r;
    for (r = 4; r < m; ++r)
        KeaLanesStoreA(tail[r - 4], o[r]);
    KeaLanesTranspose4(&o[0], &o[1], &o[2], &o[3]); /* o[l]: lane l's rows 0-3 */
    for (l = 0; l < KEA_JOINT_PACK_LANES; ++l)
        if (pack->active & (1 << l)) {
            MeReal *seg = out + pack->pos[l];
            KeaLanesStore(seg, o[l]);
            for (r = 4; r < m; ++r)
                seg[r] = tail[r - 4][l];
        }
}

/* out = J_b (dv of its two bodies) of each free lane's block, at its positions (KeaJointApplyPair's
 * sums in each lane). */
static inline void KeaJointPackGather(const int m, const KeaJointPack *pack, const KeaVel4 *dv, MeReal *out)
{
    KeaLanes v[12], o[KEA_JOINT_PACK_ROWS];
    int r, c;
    KeaPackBodies(dv, pack->body[0], v);
    KeaPackBodies(dv, pack->body[1], v + 6);
    for (r = 0; r < m; ++r) {
        KeaLanes acc = KeaLanesSplat(ME_R(0.0));
        for (c = 0; c < 12; ++c)
            acc = KeaLanesAdd(acc, KeaLanesMul(KeaLanesLoadA(pack->J[r][c]), v[c]));
        o[r] = acc;
    }
    KeaJointPackStore(m, pack, o, out);
}

/* z = A_bb^-1 res of each free lane's block, at its positions (KeaJointApply's sums in each lane). */
static inline void KeaJointPackPrecondition(const int m, const KeaJointPack *pack, const MeReal *res, MeReal *z)
{
    _Alignas(16) MeReal tail[KEA_JOINT_PACK_ROWS - 4][KEA_JOINT_PACK_LANES];
    KeaLanes in[KEA_JOINT_PACK_ROWS], o[KEA_JOINT_PACK_ROWS];
    int l, r, c;
    for (l = 0; l < KEA_JOINT_PACK_LANES; ++l) {
        const MeReal *seg = res + pack->pos[l];
        in[l] = KeaLanesLoad(seg);
        for (r = 4; r < m; ++r)
            tail[r - 4][l] = seg[r];
    }
    KeaLanesTranspose4(&in[0], &in[1], &in[2], &in[3]); /* in[c]: entry c of each lane's segment */
    for (r = 4; r < m; ++r)
        in[r] = KeaLanesLoadA(tail[r - 4]);
    for (r = 0; r < m; ++r) {
        KeaLanes acc = KeaLanesSplat(ME_R(0.0));
        for (c = 0; c < m; ++c)
            acc = KeaLanesAdd(acc, KeaLanesMul(KeaLanesLoadA(pack->inv[c][r]), in[c]));
        o[r] = acc;
    }
    KeaJointPackStore(m, pack, o, z);
}

/* kea_joint_packs.c. Fill: the solve's packs (after KeaSetUpBlocks and the factors; none in a split
 * solve). Clear, Mark, Finish: a step's free lanes (before, for each segment of block b at position
 * p, after KeaFindSegments's pieces). Gather, Precondition: the products over the packs' free lanes. */
void KeaJointPacksFill(KeaIterativeWork *w);
void KeaJointPacksClear(KeaIterativeWork *w);
void KeaJointPacksMark(KeaIterativeWork *w, int b, int p);
void KeaJointPacksFinish(KeaIterativeWork *w);
void KeaJointPacksGather(const KeaIterativeWork *w, const KeaVel4 *dv, MeReal *out);
void KeaJointPacksPrecondition(const KeaIterativeWork *w, const MeReal *res, MeReal *z);

#endif
