/* test_kea_joint_packs.c -- SM's gather and preconditioner over the joint packs (kea_joint_packs.c:
 * KeaJointPacksFill, KeaJointPacksMark, KeaJointPacksGather, KeaJointPacksPrecondition) give every
 * free segment of a hinge's or fixed joint's block the bits of the block kernels they replace
 * (KeaBlockGather, KeaBlockSymmetricApply), write nothing else, and take no other block: the "same
 * bits" claim of docs/kea.md ("SM's gather and preconditioner, four joints at a time") rests on it. */
#include "karma_test.h"

#include <string.h>

#include "kea_test_problems.h"
#include "mdt/kea/kea_block_kernels.h"
#include "mdt/kea/kea_joint_packs.h"

enum {
    NBLK = 16, /* blocks */
    NB = 6,    /* bodies; body NB is the world */
    NROWS = 6 * NBLK,
    NPOS = NROWS + 8 /* SM's positions (a gap at the start, as after a contact pack region) */
};

/* Block sizes: hinges (5) and fixed joints (6) mixed with a contact (3), a ball joint (3), a lone
 * row and a block of 7 rows, which the packs must leave alone; 7 hinges make a full pack and a part
 * one. */
static const int kSizes[NBLK] = {5, 5, 6, 3, 5, 1, 6, 5, 7, 5, 6, 5, 3, 6, 5, 6};

typedef struct Fixture {
    int blockStart[NBLK + 1], blockMatrix[NBLK], jointPackOf[NBLK], body[NROWS][2];
    unsigned char blockFactored[NBLK], blockContact[NBLK];
    MeReal JT[12 * NROWS], blockInv[NROWS * 7];
    KeaJointPack packs[NROWS / 20 + 2];
    KeaVel4 dv[NB + 1];
    MeReal res[NPOS], got[NPOS], expect[NPOS];
    int pos[NBLK], isFree[NBLK];
    KeaIterativeWork w;
} Fixture;

static Fixture fx;

/* Random blocks (J, inverses, bodies, some on the world, some unfactored), velocities and free
 * segments at increasing positions; the work points at the fixture's arrays. */
static void make_fixture(KtRng *rng)
{
    int b, i, c, s = 0, offset = 0, p = 8;
    memset(&fx, 0, sizeof fx);
    for (b = 0; b < NBLK; ++b) {
        const int m = kSizes[b], b0 = kt_int(rng, NB), b1 = kt_uniform(rng) < 0.2 ? NB : kt_int(rng, NB);
        fx.blockStart[b] = s;
        fx.blockMatrix[b] = offset;
        fx.blockFactored[b] = kt_uniform(rng) < 0.9;
        fx.blockContact[b] = m == 3 && b == 3 ? KEA_CONTACT_BODIES : 0;
        for (i = s; i < s + m; ++i) {
            fx.body[i][0] = b0;
            fx.body[i][1] = b1;
        }
        for (c = 0; c < 12 * m; ++c)
            fx.JT[12 * s + c] = c >= 6 * m && b1 == NB ? ME_R(0.0) : kt_mixed_value(rng);
        for (c = 0; c < m * m; ++c)
            fx.blockInv[offset + c] = kt_mixed_value(rng);
        fx.isFree[b] = kt_uniform(rng) < 0.75;
        fx.pos[b] = p;
        if (fx.isFree[b])
            p += m;
        offset += m * m;
        s += m;
    }
    fx.blockStart[NBLK] = s;
    for (b = 0; b < NB; ++b)
        for (c = 0; c < 3; ++c) {
            fx.dv[b].lin[c] = kt_mixed_value(rng);
            fx.dv[b].ang[c] = kt_mixed_value(rng);
        }
    for (p = 0; p < NPOS; ++p)
        fx.res[p] = kt_mixed_value(rng);
    fx.w.nBlocks = NBLK;
    fx.w.blockStart = fx.blockStart;
    fx.w.blockMatrix = fx.blockMatrix;
    fx.w.blockFactored = fx.blockFactored;
    fx.w.blockContact = fx.blockContact;
    fx.w.blockInv = fx.blockInv;
    fx.w.JT = fx.JT;
    fx.w.body = fx.body;
    fx.w.nb = NB;
    fx.w.dv = fx.dv;
    fx.w.jointPacks = fx.packs;
    fx.w.jointPackOf = fx.jointPackOf;
    fx.w.split = NULL;
    fx.w.nJointPacks = -1;
}

static int in_a_pack(int b)
{
    const int m = kSizes[b];
    return (m == 5 || m == 6) && !fx.blockContact[b] && fx.blockFactored[b];
}

/* The packs take exactly the factored 5- and 6-row generic blocks; mark this fixture's free ones. */
static void fill_and_mark(void)
{
    int b, packed = 0;
    KeaJointPacksFill(&fx.w);
    KeaJointPacksClear(&fx.w);
    for (b = 0; b < NBLK; ++b) {
        assert_int_equal(fx.jointPackOf[b] >= 0, in_a_pack(b));
        packed += in_a_pack(b);
        if (fx.jointPackOf[b] >= 0) {
            const KeaJointPack *pack = &fx.packs[fx.jointPackOf[b] / KEA_JOINT_PACK_LANES];
            assert_int_equal(pack->rows, kSizes[b]);
            if (fx.isFree[b])
                KeaJointPacksMark(&fx.w, b, fx.pos[b]);
        }
    }
    assert_true(packed > KEA_JOINT_PACK_LANES);
    assert_true(fx.w.nJointPacks >= 2);
    KeaJointPacksFinish(&fx.w);
}

/* got equals expect everywhere (the same bits: a free packed segment computed, the rest untouched). */
static void assert_same(void)
{
    int p;
    for (p = 0; p < NPOS; ++p)
        assert_true(kt_same_bits(fx.got[p], fx.expect[p]));
}

/* The packs' gather (gather 1) or preconditioner against the block kernels, over random fixtures. */
static void assert_passes_are_the_block_kernels(uint64_t seed, int gather)
{
    KtRng rng = kt_rng(seed);
    int round, b, p;
    for (round = 0; round < 50; ++round) {
        make_fixture(&rng);
        fill_and_mark();
        for (p = 0; p < NPOS; ++p)
            fx.got[p] = fx.expect[p] = (MeReal)p; /* untouched positions keep these */
        if (gather)
            KeaJointPacksGather(&fx.w, fx.dv, fx.got);
        else
            KeaJointPacksPrecondition(&fx.w, fx.res, fx.got);
        for (b = 0; b < NBLK; ++b) {
            const int s = fx.blockStart[b];
            if (!in_a_pack(b) || !fx.isFree[b])
                continue;
            if (gather)
                KeaBlockGather(&fx.w, s, kSizes[b], &fx.dv[fx.body[s][0]], &fx.dv[fx.body[s][1]], fx.expect + fx.pos[b]);
            else
                KeaBlockSymmetricApply(kSizes[b], fx.blockInv + fx.blockMatrix[b], fx.res + fx.pos[b],
                                       fx.expect + fx.pos[b]);
        }
        assert_same();
    }
}

static void gather_is_the_block_kernels(void **state)
{
    (void)state;
    assert_passes_are_the_block_kernels(1717, 1);
}

static void preconditioner_is_the_block_kernels(void **state)
{
    (void)state;
    assert_passes_are_the_block_kernels(2323, 0);
}

/* A split solve has no joint packs (its gathers run over chunks of pieces). */
static void split_solve_has_no_joint_packs(void **state)
{
    KtRng rng = kt_rng(99);
    KeaSplit split;
    int b;
    (void)state;
    make_fixture(&rng);
    fx.w.split = &split;
    KeaJointPacksFill(&fx.w);
    assert_int_equal(fx.w.nJointPacks, 0);
    for (b = 0; b < NBLK; ++b)
        assert_int_equal(fx.jointPackOf[b], -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gather_is_the_block_kernels),
        cmocka_unit_test(preconditioner_is_the_block_kernels),
        cmocka_unit_test(split_solve_has_no_joint_packs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
