/* test_kea_packs.c -- subspace minimisation's passes over the packs of four contacts
 * (kea_contact_packs.c: KeaPacksListFree, KeaPacksCgStart, KeaPacksCgProduct, KeaPacksCgUpdate,
 * KeaPacksScatterDirection, KeaPacksApply) give every free row the bits of the
 * element-by-element loops they replaced (a pack kernel, then the vector arithmetic position by
 * position), every dot product the bits of KeaDotN4's four sums, and every masked row 0: the "same
 * trajectories" claim of docs/kea.md ("SM's passes, one per product") rests on it. */
#include "karma_test.h"

#include <float.h>
#include <string.h>

#include "kea_test_problems.h"
#include "mdt/kea/kea_contact_packs.h"

enum {
    NP = 3,                        /* packs; the last holds three contacts */
    NB = 5,                        /* bodies; body NB is the world */
    NPOS = KEA_PACK_POSITIONS * NP /* SM's positions */
};

typedef struct Fixture {
    KeaContactPack packs[NP];
    _Alignas(16) MeReal lo[NPOS], hi[NPOS], xFree[NPOS], grad[NPOS], epsFree[NPOS], step[NPOS];
    _Alignas(16) MeReal res[NPOS], z[NPOS], dir[NPOS], q[NPOS];
    KeaVel4 dv[NB + 1], dvTmp[NB + 1];
    unsigned char was[NPOS]; /* by row; the contacts' records hold them as masks */
    _Alignas(16) MeReal JT[12 * NPOS]; /* the contacts' records (KeaContactConsts at JT + 12 s) */
    MeReal x[NPOS];
    KeaIterativeWork w;
} Fixture;

static Fixture fx;

static int lanes_of(int k) { return k == NP - 1 ? 3 : KEA_PACK_LANES; }

static int used(int k, int l) { return l < lanes_of(k); }

/* Random packs (contact rows 3 (4 k + l)), bodies, velocities, x (some normals negative, some
 * friction coefficients MEINFINITY) and free rows; the work points at the fixture's arrays. */
static void make_fixture(KtRng *rng)
{
    int k, l, r, c, b;
    memset(&fx, 0, sizeof fx);
    for (k = 0; k < NP; ++k) {
        KeaContactPack *pack = &fx.packs[k];
        pack->lanes = lanes_of(k);
        for (l = 0; l < KEA_PACK_LANES; ++l) {
            const int u = used(k, l);
            pack->row[l] = 3 * (4 * k + (u ? l : 0));
            pack->body[0][l] = u ? (int)kt_range(rng, 0.0, NB - 0.01) : NB;
            pack->body[1][l] = u && kt_uniform(rng) < 0.7 ? (int)kt_range(rng, 0.0, NB - 0.01) : NB;
            pack->live[l] = u && kt_uniform(rng) < 0.9;
            pack->normalHi[l] = u ? (kt_uniform(rng) < 0.5 ? MEINFINITY : (MeReal)kt_range(rng, 0.1, 5.0)) : ME_R(0.0);
            for (r = 0; r < 2; ++r)
                pack->mu[r][l] = u ? (kt_uniform(rng) < 0.2 ? MEINFINITY : (MeReal)kt_range(rng, 0.0, 1.0)) : ME_R(0.0);
            for (r = 0; r < 3; ++r) {
                pack->rhs[r][l] = u ? kt_mixed_value(rng) : ME_R(0.0);
                pack->invDiag[r][l] = u ? (MeReal)kt_range(rng, 0.01, 10.0) : ME_R(0.0);
                for (c = 0; c < 12; ++c) {
                    const int world = c >= 6 && pack->body[1][l] == NB;
                    pack->J[r][c][l] = u && !world ? kt_mixed_value(rng) : ME_R(0.0);
                    pack->B[r][c][l] = u && !world ? kt_mixed_value(rng) : ME_R(0.0);
                }
                for (c = 0; c <= r; ++c)
                    pack->inv[3 * r + c][l] = pack->inv[3 * c + r][l] = pack->live[l] ? kt_mixed_value(rng) : ME_R(0.0);
            }
        }
    }
    for (b = 0; b < NB; ++b)
        for (c = 0; c < 3; ++c) {
            fx.dv[b].lin[c] = kt_mixed_value(rng);
            fx.dv[b].ang[c] = kt_mixed_value(rng);
            fx.dvTmp[b].lin[c] = kt_mixed_value(rng);
            fx.dvTmp[b].ang[c] = kt_mixed_value(rng);
        }
    for (r = 0; r < NPOS; ++r) {
        fx.was[r] = kt_uniform(rng) < 0.7;
        fx.x[r] = kt_mixed_value(rng); /* a normal impulse negative at times (the friction bound's max) */
        if (r % 3 == 0 && kt_uniform(rng) < 0.3)
            fx.x[r] = (MeReal)kt_range(rng, 2.0, 10.0); /* with mu = MEINFINITY: an infinite bound */
        fx.epsFree[r] = kt_uniform(rng) < 0.3 ? ME_R(0.0) : (MeReal)kt_range(rng, 1e-6, 1e-2);
    }
    for (k = 0; k < NP; ++k) /* a pack with no free row at times: every pass skips it (idle) */
        if (kt_uniform(rng) < 0.2)
            memset(&fx.was[KEA_PACK_POSITIONS * k], 0, KEA_PACK_POSITIONS);
    for (r = 0; r < NPOS; r += 3)
        KeaContactConstsOf(fx.JT, r)->freeRows = fx.was[r] | fx.was[r + 1] << 1 | fx.was[r + 2] << 2;
    fx.w.packs = fx.packs;
    fx.w.JT = fx.JT;
    fx.w.nPacks = NP;
    fx.w.nb = NB;
    fx.w.lo = fx.lo;
    fx.w.hi = fx.hi;
    fx.w.xFree = fx.xFree;
    fx.w.grad = fx.grad;
    fx.w.epsFree = fx.epsFree;
    fx.w.step = fx.step;
    fx.w.res = fx.res;
    fx.w.z = fx.z;
    fx.w.dir = fx.dir;
    fx.w.q = fx.q;
    fx.w.dv = fx.dv;
    fx.w.dvTmp = fx.dvTmp;
}

static int masked(int p)
{
    return fx.packs[p / KEA_PACK_POSITIONS].mask[(p % KEA_PACK_POSITIONS) / KEA_PACK_LANES][p % KEA_PACK_LANES] ==
           ME_R(0.0);
}

/* A free row holds the reference's bits, a masked row 0 (of either sign). */
static void assert_rows(const MeReal *got, const MeReal *expect)
{
    int p;
    for (p = 0; p < NPOS; ++p)
        if (masked(p))
            assert_true(got[p] == ME_R(0.0));
        else
            assert_true(kt_same_bits(got[p], expect[p]));
}

/* KeaDotN4's value from the lanes a pass left. */
static MeReal lanes_sum(KeaLanes acc)
{
    MeReal s[4];
    KeaLanesStore(s, acc);
    return (s[0] + s[1]) + (s[2] + s[3]);
}

/* Random SM vectors, masked rows 0 (as SM keeps them). */
static void random_vector(KtRng *rng, MeReal *v)
{
    int p;
    for (p = 0; p < NPOS; ++p)
        v[p] = masked(p) ? ME_R(0.0) : kt_mixed_value(rng);
}

/* The bounds are the contact step's (normal [0, hi], friction +-mu max(n, 0)) at a free row, and
 * a masked row's are 0, never NaN, even where mu is MEINFINITY and the normal impulse above 1. */
static void listed_bounds_are_the_contact_steps(void **state)
{
    KtRng rng = {4242};
    int trial, k, l, r;
    (void)state;
    for (trial = 0; trial < 300; ++trial) {
        int listed, expectListed = 0;
        make_fixture(&rng);
        listed = KeaPacksListFree(&fx.w, fx.x);
        for (k = 0; k < NP; ++k) {
            const KeaContactPack *pack = &fx.packs[k];
            int allFull = 1, anyOn = 0;
            for (l = 0; l < KEA_PACK_LANES; ++l) {
                const int s = pack->row[l];
                int full = used(k, l) && pack->live[l];
                for (r = 0; r < 3; ++r) {
                    const int p = KEA_PACK_POSITIONS * k + KEA_PACK_LANES * r + l;
                    const int on = used(k, l) && fx.was[s + r];
                    const MeReal bound = r == 0 ? pack->normalHi[l] : KeaFrictionBound(pack->mu[r - 1][l], fx.x[s]);
                    full &= on;
                    anyOn |= on;
                    expectListed += on;
                    assert_true(pack->mask[r][l] == (on ? ME_R(1.0) : ME_R(0.0)));
                    if (on) {
                        assert_true(kt_same_bits(fx.lo[p], r == 0 ? ME_R(0.0) : -bound));
                        assert_true(kt_same_bits(fx.hi[p], bound));
                        assert_true(kt_same_bits(fx.xFree[p], fx.x[s + r]));
                    } else {
                        assert_true(fx.lo[p] == ME_R(0.0) && fx.hi[p] == ME_R(0.0) && fx.xFree[p] == ME_R(0.0));
                    }
                }
                assert_true(pack->full[l] == (full ? ME_R(1.0) : ME_R(0.0)));
                allFull &= full;
            }
            assert_int_equal(pack->allFull, allFull);
            assert_int_equal(pack->idle, !anyOn);
        }
        assert_int_equal(listed, expectListed);
    }
}


/* A masked row is +0 in SM's vectors whatever its numbers: a NaN in a masked row's impulse or
 * right-hand side (a row SM must not touch) stays out of the bounds, the gradient and CG's first
 * sum (the masks select, they do not multiply: NaN times 0 is NaN). */
static void masked_rows_keep_a_nan_out(void **state)
{
    KtRng rng = {99};
    int trial, k, l, r, p;
    (void)state;
    for (trial = 0; trial < 50; ++trial) {
        KeaLanes acc = KeaLanesSplat(ME_R(0.0));
        make_fixture(&rng);
        for (k = 0; k < NP; ++k)
            for (l = 0; l < lanes_of(k); ++l)
                for (r = 0; r < 3; ++r) {
                    const int s = fx.packs[k].row[l];
                    if (!fx.was[s + r]) {
                        fx.x[s + r] = (MeReal)NAN;
                        fx.packs[k].rhs[r][l] = (MeReal)NAN;
                    }
                }
        KeaPacksListFree(&fx.w, fx.x);
        KeaPacksCgStart(&fx.w, 0, NP, &acc);
        for (p = 0; p < NPOS; ++p)
            if (masked(p))
                assert_true(fx.lo[p] == ME_R(0.0) && fx.hi[p] == ME_R(0.0) && fx.xFree[p] == ME_R(0.0) &&
                            fx.grad[p] == ME_R(0.0) && fx.res[p] == ME_R(0.0));
        assert_false(isnan((double)lanes_sum(acc)));
    }
}

/* CG's start, product, update and the direction's scatter against the pack kernels followed by
 * the element-by-element loops of before, the line search's trial against its one sum, and the
 * accepted step against the loop over positions. */
static void cg_passes_are_the_element_loops(void **state)
{
    KtRng rng = {777};
    int trial, k, p;
    (void)state;
    for (trial = 0; trial < 300; ++trial) {
        _Alignas(16) MeReal g[NPOS], grad[NPOS], res[NPOS], z[NPOS], q[NPOS], step[NPOS], dir[NPOS];
        KeaVel4 dvExpect[NB + 1];
        MeReal xExpect[NPOS];
        KeaLanes acc;
        MeReal expect, a, beta;
        make_fixture(&rng);
        KeaPacksListFree(&fx.w, fx.x);

        /* the start: grad = J dv + eps x - r, res = -grad, z = P^-1 res, dir = z, step = 0 */
        for (k = 0; k < NP; ++k)
            KeaPackGather(&fx.packs[k], fx.dv, g + KEA_PACK_POSITIONS * k);
        for (p = 0; p < NPOS; ++p) {
            const MeReal r = fx.packs[p / 12].rhs[(p % 12) / 4][p % 4];
            grad[p] = masked(p) ? ME_R(0.0) : g[p] + fx.epsFree[p] * fx.xFree[p] - r;
            res[p] = masked(p) ? ME_R(0.0) : -grad[p];
        }
        for (k = 0; k < NP; ++k)
            KeaPackPrecondition(&fx.packs[k], res + KEA_PACK_POSITIONS * k, z + KEA_PACK_POSITIONS * k);
        expect = KeaDotN4(res, z, NPOS);
        acc = KeaLanesSplat(ME_R(0.0));
        KeaPacksCgStart(&fx.w, 0, NP, &acc);
        assert_rows(fx.grad, grad);
        assert_rows(fx.res, res);
        assert_rows(fx.z, z);
        assert_rows(fx.dir, z);
        for (p = 0; p < NPOS; ++p)
            assert_true(fx.step[p] == ME_R(0.0));
        assert_true(kt_same_bits(lanes_sum(acc), expect));

        /* the product: q = J dvTmp + eps dir, dir . q */
        random_vector(&rng, fx.dir);
        for (k = 0; k < NP; ++k)
            KeaPackGather(&fx.packs[k], fx.dvTmp, q + KEA_PACK_POSITIONS * k);
        for (p = 0; p < NPOS; ++p)
            q[p] = q[p] + fx.epsFree[p] * fx.dir[p];
        expect = KeaDotN4(fx.dir, q, NPOS);
        acc = KeaLanesSplat(ME_R(0.0));
        KeaPacksCgProduct(&fx.w, 0, NP, &acc);
        assert_rows(fx.q, q);
        assert_true(kt_same_bits(lanes_sum(acc), expect));

        /* the update: step += a dir, res -= a q, z = P^-1 res, res . z */
        a = kt_mixed_value(&rng);
        random_vector(&rng, fx.step);
        random_vector(&rng, fx.res);
        for (p = 0; p < NPOS; ++p) {
            step[p] = fx.step[p] + a * fx.dir[p];
            res[p] = fx.res[p] - a * fx.q[p];
        }
        for (k = 0; k < NP; ++k)
            KeaPackPrecondition(&fx.packs[k], res + KEA_PACK_POSITIONS * k, z + KEA_PACK_POSITIONS * k);
        expect = KeaDotN4(res, z, NPOS);
        acc = KeaLanesSplat(ME_R(0.0));
        KeaPacksCgUpdate(&fx.w, a, 0, NP, &acc);
        assert_rows(fx.step, step);
        assert_rows(fx.res, res);
        assert_rows(fx.z, z);
        assert_true(kt_same_bits(lanes_sum(acc), expect));

        /* the next direction and its scatter in one pass: dir = z + beta dir, dvTmp += M^-1 J^T dir */
        beta = kt_mixed_value(&rng);
        for (p = 0; p < NPOS; ++p)
            dir[p] = fx.z[p] + beta * fx.dir[p];
        memcpy(dvExpect, fx.dvTmp, sizeof dvExpect);
        KeaPacksScatter(&fx.w, dir, dvExpect, 0, NP);
        KeaPacksScatterDirection(&fx.w, beta, 0, NP);
        assert_rows(fx.dir, dir);
        assert_memory_equal(fx.dvTmp, dvExpect, sizeof dvExpect);

        random_vector(&rng, fx.z);
        /* the accepted step: x += s at every position whose s is not 0 (a masked row's x untouched) */
        memcpy(xExpect, fx.x, sizeof xExpect);
        for (p = 0; p < NPOS; ++p) {
            const KeaContactPack *pack = &fx.packs[p / KEA_PACK_POSITIONS];
            if (fx.z[p] != ME_R(0.0))
                xExpect[pack->row[p % KEA_PACK_LANES] + (p % KEA_PACK_POSITIONS) / KEA_PACK_LANES] += fx.z[p];
        }
        KeaPacksApply(&fx.w, fx.x);
        assert_memory_equal(fx.x, xExpect, sizeof xExpect);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(listed_bounds_are_the_contact_steps),
        cmocka_unit_test(cg_passes_are_the_element_loops),
        cmocka_unit_test(masked_rows_keep_a_nan_out),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
