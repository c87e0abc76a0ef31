/* kea_contact_packs.c -- the packs of four declared contacts (kea_contact_packs.h): built once per
 * solve (at its first SM step), masked per SM step, and SM's passes over them. */
#include <string.h>

#include "kea_contact_packs.h"

/* Row r of the four lanes' contacts (rows[l], padded, 16-byte aligned) into the pack's places
 * out[k][l] (a 4 x 4 transpose per body half; the pads dropped). */
static void KeaPackSetRows(const KeaJacobianRow *const rows[KEA_PACK_LANES], MeReal (*out)[KEA_PACK_LANES])
{
    KeaLanes v[12];
    int k;
    KeaPackTranspose3(rows[0]->lin0, rows[1]->lin0, rows[2]->lin0, rows[3]->lin0, v);
    KeaPackTranspose3(rows[0]->ang0, rows[1]->ang0, rows[2]->ang0, rows[3]->ang0, v + 3);
    KeaPackTranspose3(rows[0]->lin1, rows[1]->lin1, rows[2]->lin1, rows[3]->lin1, v + 6);
    KeaPackTranspose3(rows[0]->ang1, rows[1]->ang1, rows[2]->ang1, rows[3]->ang1, v + 9);
    for (k = 0; k < 12; ++k)
        KeaLanesStoreA(out[k], v[k]);
}

/* Lane l of the pack from contact block b (its rows s, s + 1, s + 2), the SM step's fields cleared. */
static void KeaPackSetLane(const KeaProblem *problem, const KeaIterativeWork *w, KeaContactPack *pack, int l, int b)
{
    const int s = w->blockStart[b], factored = w->blockFactored[b] != 0;
    const MeReal *inv = w->blockInv + w->blockMatrix[b];
    int r, c;
    for (r = 0; r < 3; ++r) /* KeaBlockSymmetricApply's out[r] reads entry 3 c + r for in[c] */
        for (c = 0; c < 3; ++c)
            pack->inv[3 * r + c][l] = factored ? inv[3 * c + r] : ME_R(0.0);
    for (r = 0; r < 3; ++r) {
        pack->invDiag[r][l] = w->invDiag[s + r];
        pack->rhs[r][l] = problem->rhs[s + r];
        pack->mask[r][l] = pack->keep[r][l] = ME_R(0.0);
    }
    pack->full[l] = ME_R(0.0);
    pack->mu[0][l] = problem->mu[s + 1];
    pack->mu[1][l] = problem->mu[s + 2];
    pack->normalHi[l] = problem->hi[s];
    pack->body[0][l] = w->body[s][0];
    pack->body[1][l] = w->body[s][1];
    pack->row[l] = s;
    pack->live[l] = factored;
}

/* Lane l of the pack holding no contact: zeros on the world body nb, its rows lane 0's (masked). */
static void KeaPackClearLane(KeaContactPack *pack, int l, int nb)
{
    int r;
    for (r = 0; r < 9; ++r)
        pack->inv[r][l] = ME_R(0.0);
    for (r = 0; r < 3; ++r)
        pack->invDiag[r][l] = pack->rhs[r][l] = pack->mask[r][l] = pack->keep[r][l] = ME_R(0.0);
    pack->full[l] = pack->mu[0][l] = pack->mu[1][l] = pack->normalHi[l] = ME_R(0.0);
    pack->body[0][l] = pack->body[1][l] = nb;
    pack->row[l] = pack->row[0];
    pack->live[l] = 0;
}

/* Pack k from the contact blocks block[0 .. lanes - 1] (1 <= lanes <= 4; the others hold no
 * contact: zero rows on the world body nb). */
static void KeaPackSet(const KeaProblem *problem, KeaIterativeWork *w, KeaContactPack *pack, const int *block,
                       int lanes)
{
    static _Alignas(16) const KeaJacobianRow zero;
    const KeaJacobianRow *J[KEA_PACK_LANES], *B[KEA_PACK_LANES];
    int l, r;
    for (r = 0; r < 3; ++r) {
        for (l = 0; l < KEA_PACK_LANES; ++l) {
            const int s = l < lanes ? w->blockStart[block[l]] : 0;
            J[l] = l < lanes ? &w->J[s + r] : &zero;
            B[l] = l < lanes ? &w->B[s + r] : &zero;
        }
        KeaPackSetRows(J, pack->J[r]);
        KeaPackSetRows(B, pack->B[r]);
    }
    for (l = 0; l < lanes; ++l)
        KeaPackSetLane(problem, w, pack, l, block[l]);
    for (; l < KEA_PACK_LANES; ++l)
        KeaPackClearLane(pack, l, problem->nBodies);
    pack->lanes = lanes;
    pack->pair = lanes == KEA_PACK_LANES;
    for (l = 1; l < KEA_PACK_LANES; ++l)
        pack->pair &= pack->body[0][l] == pack->body[0][0] && pack->body[1][l] == pack->body[1][0];
}

/* Assign pack k's rows and eps in the free list's pack region, the same for every SM step of the
 * solve (a lane with no contact: lane 0's rows, masked); as for the generic rows listed after it per
 * SM step, a position's eps is written where its row is assigned. */
static void KeaPackAssignPositions(KeaIterativeWork *w, int k)
{
    int l, r;
    for (r = 0; r < 3; ++r)
        for (l = 0; l < KEA_PACK_LANES; ++l) {
            const int p = KEA_PACK_POSITIONS * k + KEA_PACK_LANES * r + l, i = w->packs[k].row[l] + r;
            w->freeRows[p] = i;
            w->epsFree[p] = w->eps[i];
        }
}

/* Pack k planned: its blocks, kept in its row[] until KeaPacksSet fills it. */
static void KeaPackPlan(KeaContactPack *pack, const int *block, int lanes)
{
    int l;
    for (l = 0; l < lanes; ++l)
        pack->row[l] = block[l];
    pack->lanes = lanes;
}

/* The contacts in block order, four to a pack; a run of contacts on one body pair (a box on a box
 * touches at four corners) fills packs of its own (KeaContactPack.pair), and what is left of each
 * run shares packs with the other remainders. */
void KeaPacksPlan(const KeaProblem *problem, KeaIterativeWork *w)
{
    int b, run = 0, mixed = 0, runBlock[KEA_PACK_LANES], mixedBlock[KEA_PACK_LANES];
    w->nPacks = 0;
    memset(w->packed, 0, (size_t)problem->nRows);
    for (b = 0; b <= w->nBlocks; ++b) {
        const int contact = b < w->nBlocks && w->blockContact[b];
        const int *pair = contact ? w->body[w->blockStart[b]] : NULL;
        const int *runPair = run ? w->body[w->blockStart[runBlock[0]]] : NULL;
        int k;
        if (contact)
            memset(w->packed + w->blockStart[b], 1, 3);
        if (run && (!contact || pair[0] != runPair[0] || pair[1] != runPair[1])) { /* the run ends */
            for (k = 0; k < run; ++k) {
                mixedBlock[mixed++] = runBlock[k];
                if (mixed == KEA_PACK_LANES) {
                    KeaPackPlan(&w->packs[w->nPacks++], mixedBlock, mixed);
                    mixed = 0;
                }
            }
            run = 0;
        }
        if (!contact)
            continue;
        runBlock[run++] = b;
        if (run == KEA_PACK_LANES) {
            KeaPackPlan(&w->packs[w->nPacks++], runBlock, run);
            run = 0;
        }
    }
    if (mixed > 0)
        KeaPackPlan(&w->packs[w->nPacks++], mixedBlock, mixed);
}

void KeaPacksSet(const KeaProblem *problem, KeaIterativeWork *w, int first, int last)
{
    int k, l;
    for (k = first; k < last; ++k) {
        KeaContactPack *pack = &w->packs[k];
        int block[KEA_PACK_LANES];
        for (l = 0; l < pack->lanes; ++l)
            block[l] = pack->row[l];
        KeaPackSet(problem, w, pack, block, pack->lanes);
        KeaPackAssignPositions(w, k);
    }
}

void KeaPacksFill(const KeaProblem *problem, KeaIterativeWork *w)
{
    KeaPacksPlan(problem, w);
    KeaPacksSet(problem, w, 0, w->nPacks);
}

/* A contact's masks in lanes, by its free rows (bit r: row r) and whether its block is factored
 * (bit 3): (row 0 free, row 1 free, row 2 free, all three free and factored), 1 or 0 each; four
 * contacts' transposed are a pack's masks and full (KeaPacksListFree). */
#define KEA_FREE_LANES(m) {(MeReal)((m) & 1), (MeReal)((m) >> 1 & 1), (MeReal)((m) >> 2 & 1), (MeReal)((m) == 15)}
static _Alignas(16) const MeReal keaFreeLanes[16][KEA_PACK_LANES] = {
    KEA_FREE_LANES(0),  KEA_FREE_LANES(1),  KEA_FREE_LANES(2),  KEA_FREE_LANES(3),
    KEA_FREE_LANES(4),  KEA_FREE_LANES(5),  KEA_FREE_LANES(6),  KEA_FREE_LANES(7),
    KEA_FREE_LANES(8),  KEA_FREE_LANES(9),  KEA_FREE_LANES(10), KEA_FREE_LANES(11),
    KEA_FREE_LANES(12), KEA_FREE_LANES(13), KEA_FREE_LANES(14), KEA_FREE_LANES(15)};
static const unsigned char keaBitsSet[8] = {0, 1, 1, 2, 1, 2, 2, 3};

/* A contact's bounds as the contact step reads them (kea_contact_kernel.h: the normal row [0, hi],
 * the friction rows +-mu max(n, 0)), in lanes: each a row's value where its mask is 1, +0 where it
 * is 0 (KeaLanesKeep, a select: a free row's the same bits, a masked row's +0 whatever its value,
 * even a NaN or mu max(n, 0) with mu = MEINFINITY and n = 0). The masks and x come a contact per
 * lane, transposed into rows (a lane with no contact: lane 0's x, masked). */
int KeaPacksListFree(KeaIterativeWork *w, const MeReal *x)
{
    MeReal *const JT = w->JT; /* the contacts' records: their rows' free masks */
    KeaContactPack *const packs = w->packs;
    MeReal *const los = w->lo, *const his = w->hi, *const xFs = w->xFree; /* read once: KeaPackVectors */
    const int nPacks = w->nPacks;
    const KeaLanes minusOne = KeaLanesSplat(ME_R(-1.0)), zero = KeaLanesSplat(ME_R(0.0));
    int k, l, r, listed = 0;
    for (k = 0; k < nPacks; ++k) {
        KeaContactPack *pack = &packs[k];
        const int base = KEA_PACK_POSITIONS * k;
        MeReal *lo = los + base, *hi = his + base, *xF = xFs + base;
        KeaLanes m[KEA_PACK_LANES], xs[KEA_PACK_LANES], nPos, bound;
        int allFull = 1, anyFree = 0;
        for (l = 0; l < KEA_PACK_LANES; ++l) {
            const int s = pack->row[l], free = l < pack->lanes ? KeaContactConstsOf(JT, s)->freeRows : 0;
            m[l] = KeaLanesLoadA(keaFreeLanes[free | pack->live[l] << 3]);
            xs[l] = KeaLanesLoad3(x + s);
            allFull &= pack->live[l] & (free == 7);
            anyFree |= free;
            listed += keaBitsSet[free];
        }
        pack->idle = anyFree == 0;
        KeaLanesTranspose4(&m[0], &m[1], &m[2], &m[3]);
        KeaLanesTranspose4(&xs[0], &xs[1], &xs[2], &xs[3]);
        KeaLanesStoreA(pack->full, m[3]);
        pack->allFull = allFull;
        for (r = 0; r < 3; ++r) {
            KeaLanesStoreA(pack->mask[r], m[r]);
            m[r] = KeaLanesSelectOf(m[r]);
            KeaLanesStoreA(pack->keep[r], m[r]);
            KeaLanesStoreA(xF + KEA_PACK_LANES * r, KeaLanesKeep(xs[r], m[r]));
        }
        nPos = KeaLanesMax(xs[0], zero);
        KeaLanesStoreA(lo, zero);
        KeaLanesStoreA(hi, KeaLanesKeep(KeaLanesLoadA(pack->normalHi), m[0]));
        for (r = 1; r < 3; ++r) { /* KeaFrictionBound in lanes */
            bound = KeaLanesKeep(KeaLanesMul(KeaLanesLoadA(pack->mu[r - 1]), nPos), m[r]);
            KeaLanesStoreA(hi + KEA_PACK_LANES * r, bound);
            KeaLanesStoreA(lo + KEA_PACK_LANES * r, KeaLanesMul(bound, minusOne));
        }
    }
    return listed;
}

void KeaPacksScatter(const KeaIterativeWork *w, const MeReal *v, KeaVel4 *dv, int first, int last)
{
    const KeaContactPack *packs = w->packs;
    int k;
    for (k = first; k < last; ++k)
        if (!packs[k].idle)
            KeaPackScatter(&packs[k], v + KEA_PACK_POSITIONS * k, dv, -1);
}

void KeaPacksScatterDirection(const KeaIterativeWork *w, MeReal beta, int first, int last)
{
    const KeaContactPack *packs = w->packs;
    MeReal *const dirs = w->dir;
    const MeReal *const zs = w->z;
    KeaVel4 *const dvTmp = w->dvTmp;
    const KeaLanes b = KeaLanesSplat(beta);
    int k, r;
    for (k = first; k < last; ++k) {
        MeReal *dir = dirs + KEA_PACK_POSITIONS * k;
        const MeReal *z = zs + KEA_PACK_POSITIONS * k;
        if (packs[k].idle)
            continue;
        for (r = 0; r < 3; ++r) {
            const int o = KEA_PACK_LANES * r;
            KeaLanesStoreA(dir + o, KeaLanesAdd(KeaLanesLoadA(z + o), KeaLanesMul(b, KeaLanesLoadA(dir + o))));
        }
        KeaPackScatter(&packs[k], dir, dvTmp, -1);
    }
}

void KeaPacksScatterSplit(const KeaIterativeWork *w, const MeReal *v, KeaVel4 *dv, const int *order, int first,
                          int last)
{
    const KeaContactPack *packs = w->packs;
    const int nb = w->nb;
    int j;
    for (j = first; j < last; ++j)
        if (!packs[order[j]].idle)
            KeaPackScatter(&packs[order[j]], v + KEA_PACK_POSITIONS * order[j], dv, nb);
}

/* The SM arrays of the pack passes read into locals once (a four-lane store may alias anything for
 * the compiler, which would reload every array pointer of the work after each one). */
typedef struct KeaPackVectors {
    MeReal *grad, *res, *z, *dir, *step, *q;
    const MeReal *eps, *xFree;
    const KeaContactPack *packs;
} KeaPackVectors;

static KeaPackVectors KeaPackVectorsOf(const KeaIterativeWork *w)
{
    KeaPackVectors v;
    v.grad = w->grad;
    v.res = w->res;
    v.z = w->z;
    v.dir = w->dir;
    v.step = w->step;
    v.q = w->q;
    v.eps = w->epsFree;
    v.xFree = w->xFree;
    v.packs = w->packs;
    return v;
}

/* Every SM vector +0 at a pack's positions from base (an idle pack's, written once an SM step). */
static void KeaPackZero(const KeaPackVectors *v, int base)
{
    MeReal *const vectors[6] = {v->grad, v->res, v->z, v->dir, v->step, v->q};
    const KeaLanes zero = KeaLanesSplat(ME_R(0.0));
    int j, o;
    for (j = 0; j < 6; ++j)
        for (o = 0; o < KEA_PACK_POSITIONS; o += KEA_PACK_LANES)
            KeaLanesStoreA(vectors[j] + base + o, zero);
}

void KeaPacksCgStart(const KeaIterativeWork *w, int first, int last, KeaLanes *acc)
{
    const KeaPackVectors v = KeaPackVectorsOf(w);
    const KeaVel4 *dv = w->dv;
    const KeaLanes minusOne = KeaLanesSplat(ME_R(-1.0)), zero = KeaLanesSplat(ME_R(0.0));
    KeaLanes sum = *acc;
    int k, r;
    for (k = first; k < last; ++k) {
        const KeaContactPack *pack = &v.packs[k];
        const int base = KEA_PACK_POSITIONS * k;
        MeReal *res = v.res + base, *z = v.z + base;
        KeaLanes g[3];
        if (pack->idle) { /* its positions 0, as a masked row's, and left so by the passes that skip it */
            KeaPackZero(&v, base);
            continue;
        }
        KeaPackGatherLanes(pack, dv, g);
        for (r = 0; r < 3; ++r) {
            const int o = base + KEA_PACK_LANES * r;
            const KeaLanes m = KeaLanesLoadA(pack->keep[r]);
            g[r] = KeaLanesSub(KeaLanesAdd(g[r], KeaLanesMul(KeaLanesLoadA(v.eps + o), KeaLanesLoadA(v.xFree + o))),
                               KeaLanesLoadA(pack->rhs[r]));
            g[r] = KeaLanesKeep(g[r], m);
            KeaLanesStoreA(v.grad + o, g[r]);
            KeaLanesStoreA(v.res + o, KeaLanesMul(g[r], minusOne));
            KeaLanesStoreA(v.step + o, zero);
        }
        KeaPackPrecondition(pack, res, z);
        for (r = 0; r < 3; ++r) {
            const KeaLanes zr = KeaLanesLoadA(z + KEA_PACK_LANES * r);
            sum = KeaLanesAdd(sum, KeaLanesMul(KeaLanesLoadA(res + KEA_PACK_LANES * r), zr));
            KeaLanesStoreA(v.dir + base + KEA_PACK_LANES * r, zr);
        }
    }
    *acc = sum;
}

/* (A_FF u) at pack k's positions, in lanes: q[r] = J_r dvTmp + eps_r u_r (dvTmp: the scatter of u). */
static inline void KeaPackProduct(const KeaPackVectors *v, const KeaVel4 *dvTmp, int k, const MeReal *u,
                                  KeaLanes q[3])
{
    const int base = KEA_PACK_POSITIONS * k;
    int r;
    KeaPackGatherLanes(&v->packs[k], dvTmp, q);
    for (r = 0; r < 3; ++r) {
        const int o = base + KEA_PACK_LANES * r;
        q[r] = KeaLanesAdd(q[r], KeaLanesMul(KeaLanesLoadA(v->eps + o), KeaLanesLoadA(u + o)));
    }
}

void KeaPacksCgProduct(const KeaIterativeWork *w, int first, int last, KeaLanes *acc)
{
    const KeaPackVectors v = KeaPackVectorsOf(w);
    const KeaVel4 *dvTmp = w->dvTmp;
    KeaLanes sum = *acc;
    int k, r;
    for (k = first; k < last; ++k) {
        KeaLanes q[3];
        if (v.packs[k].idle)
            continue;
        KeaPackProduct(&v, dvTmp, k, v.dir, q);
        for (r = 0; r < 3; ++r) {
            const int o = KEA_PACK_POSITIONS * k + KEA_PACK_LANES * r;
            KeaLanesStoreA(v.q + o, q[r]);
            sum = KeaLanesAdd(sum, KeaLanesMul(KeaLanesLoadA(v.dir + o), q[r]));
        }
    }
    *acc = sum;
}

void KeaPacksCgUpdate(const KeaIterativeWork *w, MeReal a, int first, int last, KeaLanes *acc)
{
    const KeaPackVectors v = KeaPackVectorsOf(w);
    const KeaLanes av = KeaLanesSplat(a);
    KeaLanes sum = *acc;
    int k, r;
    for (k = first; k < last; ++k) {
        const int base = KEA_PACK_POSITIONS * k;
        MeReal *res = v.res + base, *z = v.z + base, *step = v.step + base;
        const MeReal *dir = v.dir + base, *q = v.q + base;
        if (v.packs[k].idle)
            continue;
        for (r = 0; r < 3; ++r) {
            const int o = KEA_PACK_LANES * r;
            KeaLanesStoreA(step + o, KeaLanesAdd(KeaLanesLoadA(step + o), KeaLanesMul(av, KeaLanesLoadA(dir + o))));
            KeaLanesStoreA(res + o, KeaLanesSub(KeaLanesLoadA(res + o), KeaLanesMul(av, KeaLanesLoadA(q + o))));
        }
        KeaPackPrecondition(&v.packs[k], res, z);
        for (r = 0; r < 3; ++r) {
            const int o = KEA_PACK_LANES * r;
            sum = KeaLanesAdd(sum, KeaLanesMul(KeaLanesLoadA(res + o), KeaLanesLoadA(z + o)));
        }
    }
    *acc = sum;
}

void KeaPacksApply(const KeaIterativeWork *w, MeReal *x)
{
    const MeReal *z = w->z;
    int k, l, r;
    for (k = 0; k < w->nPacks; ++k) {
        const KeaContactPack *pack = &w->packs[k];
        if (pack->idle)
            continue;
        for (l = 0; l < pack->lanes; ++l) { /* a contact's three rows are consecutive in x */
            MeReal *xc = x + pack->row[l];
            for (r = 0; r < 3; ++r) {
                const MeReal s = z[KEA_PACK_POSITIONS * k + KEA_PACK_LANES * r + l];
                if (s != ME_R(0.0))
                    xc[r] += s;
            }
        }
    }
}
