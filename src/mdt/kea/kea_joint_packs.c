/* kea_joint_packs.c -- the joint packs of a solve and SM's passes over them (kea_joint_packs.h). */
#include "kea_joint_packs.h"

/* Lane l of pack k: block b's transpose, inverse and bodies. */
static void KeaJointPackSetLane(KeaIterativeWork *w, KeaJointPack *pack, int l, int b)
{
    const int s = w->blockStart[b], m = pack->rows;
    const MeReal *JT = w->JT + 12 * s, *inv = w->blockInv + w->blockMatrix[b];
    int r, c;
    for (r = 0; r < m; ++r)
        for (c = 0; c < 12; ++c)
            pack->J[r][c][l] = JT[c * m + r];
    for (c = 0; c < m; ++c)
        for (r = 0; r < m; ++r)
            pack->inv[c][r][l] = inv[c * m + r];
    pack->body[0][l] = w->body[s][0];
    pack->body[1][l] = w->body[s][1];
}

/* A lane with no block: zeros on the world (never free, but read by the four-lane products). */
static void KeaJointPackClearLane(KeaJointPack *pack, int l, int nb)
{
    int r, c;
    for (r = 0; r < KEA_JOINT_PACK_ROWS; ++r) {
        for (c = 0; c < 12; ++c)
            pack->J[r][c][l] = ME_R(0.0);
        for (c = 0; c < KEA_JOINT_PACK_ROWS; ++c)
            pack->inv[c][r][l] = ME_R(0.0);
    }
    pack->body[0][l] = pack->body[1][l] = nb;
    pack->pos[l] = 0;
}

void KeaJointPacksFill(KeaIterativeWork *w)
{
    int open[2] = {-1, -1}; /* the pack being filled, of 5 and of 6 rows */
    int b, k, l;
    w->nJointPacks = 0;
    for (b = 0; b < w->nBlocks; ++b) {
        const int m = w->blockStart[b + 1] - w->blockStart[b];
        KeaJointPack *pack;
        w->jointPackOf[b] = -1;
        if (w->split || (m != 5 && m != 6) || w->blockContact[b] || !w->blockFactored[b])
            continue;
        k = open[m - 5];
        if (k < 0 || w->jointPacks[k].lanes == KEA_JOINT_PACK_LANES) {
            k = open[m - 5] = w->nJointPacks++;
            w->jointPacks[k].rows = m;
            w->jointPacks[k].lanes = 0;
            w->jointPacks[k].active = 0;
        }
        pack = &w->jointPacks[k];
        KeaJointPackSetLane(w, pack, pack->lanes, b);
        w->jointPackOf[b] = KEA_JOINT_PACK_LANES * k + pack->lanes++;
    }
    for (k = 0; k < 2; ++k)
        if (open[k] >= 0)
            for (l = w->jointPacks[open[k]].lanes; l < KEA_JOINT_PACK_LANES; ++l)
                KeaJointPackClearLane(&w->jointPacks[open[k]], l, w->nb);
}

void KeaJointPacksClear(KeaIterativeWork *w)
{
    int k;
    for (k = 0; k < w->nJointPacks; ++k)
        w->jointPacks[k].active = 0;
}

void KeaJointPacksMark(KeaIterativeWork *w, int b, int p)
{
    const int at = w->jointPackOf[b];
    KeaJointPack *pack = &w->jointPacks[at / KEA_JOINT_PACK_LANES];
    pack->active |= 1 << (at % KEA_JOINT_PACK_LANES);
    pack->pos[at % KEA_JOINT_PACK_LANES] = p;
}

void KeaJointPacksFinish(KeaIterativeWork *w)
{
    int k, l;
    for (k = 0; k < w->nJointPacks; ++k) {
        KeaJointPack *pack = &w->jointPacks[k];
        int first = 0;
        if (pack->active == 0 || pack->active == (1 << KEA_JOINT_PACK_LANES) - 1)
            continue;
        while (!(pack->active & (1 << first)))
            ++first;
        for (l = 0; l < KEA_JOINT_PACK_LANES; ++l)
            if (!(pack->active & (1 << l)))
                pack->pos[l] = pack->pos[first];
    }
}

/* Over the packs with a free lane: the gather of dv (res NULL) or the preconditioner of res, to out. */
static void KeaJointPacksRun(const KeaIterativeWork *w, const KeaVel4 *dv, const MeReal *res, MeReal *out)
{
    const KeaJointPack *packs = w->jointPacks;
    int k;
    for (k = 0; k < w->nJointPacks; ++k) {
        const int six = packs[k].rows == 6;
        if (!packs[k].active)
            continue;
        if (res && six) /* m a constant in each call, so that the kernel unrolls */
            KeaJointPackPrecondition(6, &packs[k], res, out);
        else if (res)
            KeaJointPackPrecondition(5, &packs[k], res, out);
        else if (six)
            KeaJointPackGather(6, &packs[k], dv, out);
        else
            KeaJointPackGather(5, &packs[k], dv, out);
    }
}

void KeaJointPacksGather(const KeaIterativeWork *w, const KeaVel4 *dv, MeReal *out)
{
    KeaJointPacksRun(w, dv, NULL, out);
}

void KeaJointPacksPrecondition(const KeaIterativeWork *w, const MeReal *res, MeReal *z)
{
    KeaJointPacksRun(w, NULL, res, z);
}
