/* kea_contact_packs.h -- declared contacts four at a time (kea_iterative.h): a pack holds four
 * contacts' rows as structure of arrays, each of their 3 x 12 Jacobian components (and of B = M^-1
 * J^T, and the 3 x 3 block inverse) as four lanes, one contact per lane. A pass over the packs then
 * does the arithmetic of four contacts per four-lane operation with no horizontal sums; only the
 * bodies are moved between a body per vector and a body per lane (a 4 x 4 transpose per half).
 *
 * Subspace minimisation's products run through the packs (kea_subspace.c): the free list starts
 * with a region of 12 positions per pack, position 12 k + 4 r + l holding row r of lane l's contact
 * of pack k, so that SM's vectors are read and written as whole lanes. The packs are built once per
 * solve, at its first SM step that runs (KeaPacksFill: every declared contact, four to a pack; a
 * solve whose SM never runs does not pay for them); each SM step only sets the rows' masks
 * (KeaPacksListFree: 1 for a free row, else 0) and which lanes have all three rows free and a
 * factored block (preconditioned by the block's inverse, as a segment of the free list; a lane
 * with only some rows free, by 1 / d_i per row, as rows on their own). A masked row's position
 * holds 0 in every SM vector (its gather is multiplied by 0, its bounds and x are 0), so it adds
 * nothing to any product, sum or step. Each of CG's stages is one pass over the packs that does its
 * vector work beside its product (KeaPacksCgStart, KeaPacksCgProduct, KeaPacksCgUpdate,
 * KeaPacksScatterDirection), its sums in SM's position order (docs/kea.md, "SM's
 * passes, one per product"). A pack none of whose rows is free (KeaContactPack.idle) is skipped by
 * every pass of that SM step, its positions set to 0 by KeaPacksCgStart: it would add only zeros, and a
 * body's sum, starting at +0, is never -0, so the bits are the same. Masking by a product assumes finite x, rhs and dv (a NaN in a masked
 * row would reach the sums; SM stops on a non-positive or NaN res . z).
 *
 * The scatter adds a lane's contribution to its bodies lane by lane, in lane order: the four
 * contacts of a pack may share a body (neighbouring contacts usually do: the four corners of one
 * face), and one read-modify-write after the other needs no pack to be built from distinct bodies
 * (there is no four-lane scatter to memory to gain from such packs anyway: each lane's body is
 * written as its own padded 3-vectors either way).
 *
 * Every four lanes a pass reads are 16-byte aligned (the packs' and SM's vectors from the arena,
 * KEA_ALIGN, a pack's position region a multiple of 12 reals; KeaVel4 aligned), so that the loads
 * are folded into the arithmetic (KeaLanesLoadA). */
#ifndef KEA_CONTACT_PACKS_H
#define KEA_CONTACT_PACKS_H

#include "kea_iterative.h"

enum {
    KEA_PACK_LANES = 4,      /* contacts per pack */
    KEA_PACK_POSITIONS = 12  /* free-list positions per pack: 3 rows x 4 lanes */
};

/* Four declared contacts, a lane each. Component k of a row: 0-2 linear and 3-5 angular on body 0,
 * 6-8 and 9-11 on body 1 (the world's half exact zeros, as in KeaIterativeWork.J). A lane with no
 * contact (the last pack of a solve) is all zeros on the world body (nb) and never unmasked. The
 * per-SM-step fields are written by KeaPacksListFree. */
struct KeaContactPack {
    _Alignas(16) MeReal J[3][12][KEA_PACK_LANES]; /**< J of row r, component k, lane l (every
                                                        four lanes 16-byte aligned: KeaLanesLoadA) */
    MeReal B[3][12][KEA_PACK_LANES];   /**< B = M^-1 J^T, the same places */
    MeReal inv[9][KEA_PACK_LANES];     /**< the block's A_bb^-1, entry (r, c) at 3 r + c (0 unfactored) */
    MeReal invDiag[3][KEA_PACK_LANES]; /**< the rows' 1 / d_i */
    MeReal mask[3][KEA_PACK_LANES];    /**< SM: 1 for a free row, else 0 */
    MeReal keep[3][KEA_PACK_LANES];    /**< SM: the masks as selects (KeaLanesSelectOf, for KeaLanesKeep) */
    MeReal full[KEA_PACK_LANES];       /**< SM: 1 for a lane preconditioned by its inverse, else 0 */
    MeReal mu[2][KEA_PACK_LANES];      /**< the friction rows' coefficients */
    MeReal normalHi[KEA_PACK_LANES];   /**< the normal row's upper bound (its lower is 0) */
    MeReal rhs[3][KEA_PACK_LANES];     /**< the rows' r (0 in a lane with no contact) */
    int body[2][KEA_PACK_LANES];       /**< the halves' bodies (the world, and a lane with no contact: nb) */
    int row[KEA_PACK_LANES];           /**< the contact's first row (a lane with no contact: lane 0's) */
    int live[KEA_PACK_LANES];          /**< 1 for a contact whose block is factored, else 0 */
    int lanes;                         /**< the lanes that hold a contact: 0 ... lanes - 1 */
    int pair;                          /**< 1: all four lanes are contacts on the same two bodies */
    int allFull;                       /**< SM: every lane's full is 1 */
    int idle;                          /**< SM: no row of the pack is free (every pass skips it) */
};

/* Lanes 0-2 of four bodies' padded 3-vectors: v[0..2] hold the x, y, z of a, b, c, d a lane each. */
static inline void KeaPackTranspose3(const MeReal *a, const MeReal *b, const MeReal *c, const MeReal *d, KeaLanes *v)
{
    KeaLanes x = KeaLanesLoadA(a), y = KeaLanesLoadA(b), z = KeaLanesLoadA(c), t = KeaLanesLoadA(d);
    KeaLanesTranspose4(&x, &y, &z, &t);
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

/* The four lanes' bodies `body` of dv as components: v[0..2] linear, v[3..5] angular. */
static inline void KeaPackBodies(const KeaVel4 *dv, const int *body, KeaLanes *v)
{
    const KeaVel4 *b0 = &dv[body[0]], *b1 = &dv[body[1]], *b2 = &dv[body[2]], *b3 = &dv[body[3]];
    KeaPackTranspose3(b0->lin, b1->lin, b2->lin, b3->lin, v);
    KeaPackTranspose3(b0->ang, b1->ang, b2->ang, b3->ang, v + 3);
}

/* The one body of all four lanes as components, each splatted: v[0..2] linear, v[3..5] angular. */
static inline void KeaPackBody(const KeaVel4 *b, KeaLanes *v)
{
    int k;
    for (k = 0; k < 3; ++k) {
        v[k] = KeaLanesSplat(b->lin[k]);
        v[3 + k] = KeaLanesSplat(b->ang[k]);
    }
}

/* out[r] = mask_rl J_r (v0, v1) of lane l's contact, in lanes: in each lane the sums of KeaRowVel4, in
 * its order (component k's two halves, then the three components), so a lane with mask 1 gives its
 * bits (on the world too, up to the sign of a zero). A pack on one body pair splats its two
 * bodies instead of transposing eight. */
static inline void KeaPackGatherLanes(const KeaContactPack *pack, const KeaVel4 *dv, KeaLanes out[3])
{
    KeaLanes v[12], s[3];
    int r, k;
    if (pack->pair) {
        KeaPackBody(&dv[pack->body[0][0]], v);
        KeaPackBody(&dv[pack->body[1][0]], v + 6);
    } else {
        KeaPackBodies(dv, pack->body[0], v);
        KeaPackBodies(dv, pack->body[1], v + 6);
    }
    for (r = 0; r < 3; ++r) {
        const MeReal(*J)[KEA_PACK_LANES] = pack->J[r];
        for (k = 0; k < 3; ++k)
            s[k] = KeaLanesAdd(KeaLanesDot2L(J[k], v[k], J[3 + k], v[3 + k]),
                               KeaLanesDot2L(J[6 + k], v[6 + k], J[9 + k], v[9 + k]));
        out[r] = KeaLanesKeep(KeaLanesAdd(KeaLanesAdd(s[0], s[1]), s[2]), KeaLanesLoadA(pack->keep[r]));
    }
}

/* out[4 r + l] = mask_rl J_r (v0, v1) of lane l's contact (KeaPackGatherLanes, stored). */
static inline void KeaPackGather(const KeaContactPack *pack, const KeaVel4 *dv, MeReal *out)
{
    KeaLanes g[3];
    int r;
    KeaPackGatherLanes(pack, dv, g);
    for (r = 0; r < 3; ++r)
        KeaLanesStoreA(out + 4 * r, g[r]);
}

/* Lane l's bodies += sum_r B_r d[4 r + l], lane by lane in lane order (lanes may share a body);
 * each lane's sum over its three rows made first, ((B_0 d_0 + B_1 d_1) + B_2 d_2), then added. A
 * pack on one body pair makes the same additions with each body loaded and stored once. Body
 * `skip` is not written (a split solve's: the world, nb, whose half adds exact zeros and which other
 * packs of the colour may hold too; -1: every body written). */
static inline void KeaPackScatter(const KeaContactPack *pack, const MeReal *d, KeaVel4 *dv, int skip)
{
    const KeaLanes d0 = KeaLanesLoadA(d), d1 = KeaLanesLoadA(d + 4), d2 = KeaLanesLoadA(d + 8);
    KeaLanes add[16]; /* after the transposes: add[4 h + l], half h (lin0, ang0, lin1, ang1) of lane l */
    int h, c, l;
    for (h = 0; h < 4; ++h) {
        for (c = 0; c < 3; ++c) {
            const int k = 3 * h + c;
            add[4 * h + c] = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoadA(pack->B[0][k]), d0),
                                                     KeaLanesMul(KeaLanesLoadA(pack->B[1][k]), d1)),
                                         KeaLanesMul(KeaLanesLoadA(pack->B[2][k]), d2));
        }
        add[4 * h + 3] = KeaLanesSplat(ME_R(0.0)); /* the pads stay 0 */
        KeaLanesTranspose4(&add[4 * h], &add[4 * h + 1], &add[4 * h + 2], &add[4 * h + 3]);
    }
    if (pack->pair) { /* the same additions, in the same order, on the two bodies held in lanes */
        KeaVel4 *v0 = &dv[pack->body[0][0]], *v1 = &dv[pack->body[1][0]];
        for (h = 0; h < 4; ++h) {
            MeReal *half = h == 0 ? v0->lin : (h == 1 ? v0->ang : (h == 2 ? v1->lin : v1->ang));
            KeaLanes sum;
            if (pack->body[h / 2][0] == skip)
                continue;
            sum = KeaLanesLoadA(half);
            for (l = 0; l < KEA_PACK_LANES; ++l)
                sum = KeaLanesAdd(sum, add[4 * h + l]);
            KeaLanesStoreA(half, sum);
        }
        return;
    }
    for (l = 0; l < KEA_PACK_LANES; ++l) {
        KeaVel4 *v0 = &dv[pack->body[0][l]];
        if (pack->body[0][l] != skip) {
            KeaLanesStoreA(v0->lin, KeaLanesAdd(KeaLanesLoadA(v0->lin), add[l]));
            KeaLanesStoreA(v0->ang, KeaLanesAdd(KeaLanesLoadA(v0->ang), add[4 + l]));
        }
        if (pack->body[1][l] != skip) {
            KeaVel4 *v1 = &dv[pack->body[1][l]]; /* after v0's store: v0 may be v1 */
            KeaLanesStoreA(v1->lin, KeaLanesAdd(KeaLanesLoadA(v1->lin), add[8 + l]));
            KeaLanesStoreA(v1->ang, KeaLanesAdd(KeaLanesLoadA(v1->ang), add[12 + l]));
        }
    }
}

/* z[4 r + l] = (A_bb^-1 res)_r of lane l's contact where its full is 1 (KeaBlockSymmetricApply's
 * sums for m = 3, in its order), else res_r / d_r (a row on its own): the two products weighted by
 * full and 1 - full, 0 and 1, which gives either one's value (up to the sign of a zero). */
static inline void KeaPackPrecondition(const KeaContactPack *pack, const MeReal *res, MeReal *z)
{
    const KeaLanes r0 = KeaLanesLoadA(res), r1 = KeaLanesLoadA(res + 4), r2 = KeaLanesLoadA(res + 8);
    const KeaLanes full = KeaLanesLoadA(pack->full), diag = KeaLanesSub(KeaLanesSplat(ME_R(1.0)), full);
    const KeaLanes in[3] = {r0, r1, r2};
    int r;
    for (r = 0; r < 3; ++r) {
        KeaLanes zr = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoadA(pack->inv[3 * r]), r0),
                                              KeaLanesMul(KeaLanesLoadA(pack->inv[3 * r + 1]), r1)),
                                  KeaLanesMul(KeaLanesLoadA(pack->inv[3 * r + 2]), r2));
        if (!pack->allFull)
            zr = KeaLanesAdd(KeaLanesMul(zr, full), KeaLanesMul(KeaLanesMul(in[r], KeaLanesLoadA(pack->invDiag[r])), diag));
        KeaLanesStoreA(z + 4 * r, zr);
    }
}

/* kea_contact_packs.c: the packs of a solve and SM's passes over packs first ... last - 1. */

/* Build the packs from the declared contacts' blocks (after KeaSetUpBlocks: J, B, the inverses) and
 * mark their rows (KeaIterativeWork.packed). */
void KeaPacksFill(const KeaProblem *problem, KeaIterativeWork *w);
/* KeaPacksFill in two parts: which blocks go in which pack, and their rows marked (serial: the packs
 * follow the blocks' order), then packs first ... last - 1 filled with them (each writes only its own
 * pack and pack region, so ranges of packs may be filled in any order; the split solve fills them
 * in chunks over its workers). */
void KeaPacksPlan(const KeaProblem *problem, KeaIterativeWork *w);
void KeaPacksSet(const KeaProblem *problem, KeaIterativeWork *w, int first, int last);
/* SM: set the rows' masks and the lanes' preconditioner from the contacts' free rows
 * (KeaContactConsts.freeRows), and the free list's pack region's bounds and x (lo, hi, xFree at its
 * positions; 0 for a masked row, up to the sign of a zero); returns the free rows. (freeRows and
 * epsFree of the region: KeaPacksFill, once.) */
int KeaPacksListFree(KeaIterativeWork *w, const MeReal *x);
/* dv += M^-1 J^T v over the packs' positions. */
void KeaPacksScatter(const KeaIterativeWork *w, const MeReal *v, KeaVel4 *dv, int first, int last);
/* CG's next direction and its scatter in one pass: dir = z + beta dir, then dvTmp += M^-1 J^T dir,
 * over the packs' positions (the same bits as the two passes). */
void KeaPacksScatterDirection(const KeaIterativeWork *w, MeReal beta, int first, int last);
/* The same for packs order[j], j in [first, last), the world's dv (nb) not written: a split solve's
 * colour of packs sharing no body but the world (KeaSplitPacks), on several workers at once. */
void KeaPacksScatterSplit(const KeaIterativeWork *w, const MeReal *v, KeaVel4 *dv, const int *order, int first,
                          int last);

/* SM's CG passes over packs first ... last - 1 in one pass each (kea_subspace.c), on the work's SM
 * vectors at the packs' positions, a masked row's position 0 in each (up to the sign of a zero);
 * *acc += the pass's dot product lane-wise, position 12 k + 4 r + l into lane l, in position order
 * (KeaDotN4's sums). CG's start: grad = J dv + eps xFree - r, res = -grad, z = P^-1 res, dir = z,
 * step = 0; acc: res . z. */
void KeaPacksCgStart(const KeaIterativeWork *w, int first, int last, KeaLanes *acc);
/* A_FF dir: q = J dvTmp + eps dir (dvTmp: the scatter of dir); acc: dir . q. */
void KeaPacksCgProduct(const KeaIterativeWork *w, int first, int last, KeaLanes *acc);
/* CG's update: step += a dir, res -= a q, z = P^-1 res; acc: res . z. */
void KeaPacksCgUpdate(const KeaIterativeWork *w, MeReal a, int first, int last, KeaLanes *acc);
/* The accepted step: x += z at every pack position whose z is not 0 (a masked row's is 0: x is left
 * alone), with no list of rows. */
void KeaPacksApply(const KeaIterativeWork *w, MeReal *x);

#endif
