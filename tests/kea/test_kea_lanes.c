/* test_kea_lanes.c -- the four-lane kernels (kea_lanes.h, and M^-1 J^T of a row from them) and the
 * scalar helpers the solver's results rest on compute exactly what their comments say, bit for bit: each lane the scalar IEEE
 * operations in the stated order, whatever the lanes are made of (SSE in a single-precision x86
 * build, an array elsewhere). The solver's "same trajectory" claims for these kernels depend on it. */
#include "karma_test.h"

#include <float.h>
#include <string.h>

#include "kea_test_problems.h"
#include "mdt/kea/kea_block_kernels.h"
#include "mdt/kea/kea_contact_packs.h"

static MeReal random_value(KtRng *r) { return kt_mixed_value(r); } /* kea_test_problems.h */
static int same_bits(MeReal a, MeReal b) { return kt_same_bits(a, b); }

static void lanes_do_the_scalar_operations(void **state)
{
    KtRng rng = {12345};
    int trial, k;
    (void)state;
    for (trial = 0; trial < 2000; ++trial) {
        MeReal a[4], b[4], c[4], d[4], v[4], out[4], s = random_value(&rng);
        for (k = 0; k < 4; ++k) {
            a[k] = k < 3 ? random_value(&rng) : ME_R(0.0); /* padded 3-vectors: pad 0 */
            b[k] = k < 3 ? random_value(&rng) : ME_R(0.0);
            c[k] = k < 3 ? random_value(&rng) : ME_R(0.0);
            d[k] = k < 3 ? random_value(&rng) : ME_R(0.0);
            v[k] = k < 3 ? random_value(&rng) : ME_R(0.0);
        }
        { /* a.b + c.d over three components: lane k is a_k b_k + c_k d_k, then (l0 + l1) + l2 */
            MeReal lane[3], expect;
            for (k = 0; k < 3; ++k)
                lane[k] = a[k] * b[k] + c[k] * d[k];
            expect = (lane[0] + lane[1]) + lane[2];
            assert_true(same_bits(KeaLanesSum3(KeaLanesDot2(a, b, c, d)), expect));
        }
        { /* v += u s */
            MeReal w[4];
            memcpy(w, v, sizeof w);
            KeaLanesAddScaled(w, a, KeaLanesSplat(s));
            for (k = 0; k < 4; ++k)
                assert_true(same_bits(w[k], v[k] + a[k] * s));
        }
        { /* (a - b) * c + d, lane by lane */
            KeaLanesStore(out, KeaLanesAdd(KeaLanesMul(KeaLanesSub(KeaLanesLoad(a), KeaLanesLoad(b)), KeaLanesLoad(c)),
                                           KeaLanesLoad(d)));
            for (k = 0; k < 4; ++k)
                assert_true(same_bits(out[k], (a[k] - b[k]) * c[k] + d[k]));
        }
    }
}

/* The contact step's lane helpers (kea_lanes.h) are the scalar operations: the three sums at once,
 * a lane out, |a|, the larger of two (KeaMax), and the compare masks (NaN and -0 among the values). */
static void contact_step_lanes_are_the_scalars(void **state)
{
    KtRng rng = {2468};
    int trial, k;
    (void)state;
    for (trial = 0; trial < 2000; ++trial) {
        MeReal a[4], b[4], c[4], out[4];
        int le = 0, lt = 0, nz = 0;
        KeaLanes la, lb;
        for (k = 0; k < 4; ++k) {
            a[k] = random_value(&rng);
            b[k] = k == 1 && trial % 7 == 0 ? -a[k] : random_value(&rng);
            c[k] = random_value(&rng);
        }
        if (trial % 11 == 0)
            a[trial % 3] = (MeReal)NAN;
        if (trial % 13 == 0)
            b[trial % 3] = ME_R(-0.0);
        la = KeaLanesLoad(a);
        lb = KeaLanesLoad(b);
        KeaLanesStore(out, KeaLanesSum3Each(la, lb, KeaLanesLoad(c)));
        assert_true(same_bits(out[0], (a[0] + a[1]) + a[2]));
        assert_true(same_bits(out[1], (b[0] + b[1]) + b[2]));
        assert_true(same_bits(out[2], (c[0] + c[1]) + c[2]));
        assert_true(same_bits(out[3], ME_R(0.0)));
        KeaLanesStore(out, KeaLanesLoad3(a));
        for (k = 0; k < 3; ++k)
            assert_true(same_bits(out[k], a[k]));
        assert_true(same_bits(out[3], ME_R(0.0)));
        KeaLanesStore(out, KeaLanesAbs(la));
        for (k = 0; k < 4; ++k) {
            assert_true(same_bits(KeaLanesAt(la, k), a[k]));
            assert_true(same_bits(out[k], MeFabs(a[k])));
        }
        KeaLanesStore(out, KeaLanesMax(la, lb)); /* KeaMax: b for a NaN and for two zeros */
        for (k = 0; k < 4; ++k)
            assert_true(same_bits(out[k], a[k] > b[k] ? a[k] : b[k]));
        KeaLanesStore(out, KeaLanesMax(lb, KeaLanesSplat(ME_R(0.0))));
        for (k = 0; k < 4; ++k)
            assert_true(same_bits(out[k], b[k] > ME_R(0.0) ? b[k] : ME_R(0.0)));
        for (k = 0; k < 3; ++k) {
            le |= (a[k] <= b[k]) << k;
            lt |= (a[k] < b[k]) << k;
            nz |= (a[k] != ME_R(0.0)) << k;
        }
        assert_int_equal(KeaLanesLe3(la, lb), le);
        assert_int_equal(KeaLanesLt3(la, lb), lt);
        assert_int_equal(KeaLanesNonZero3(la), nz);
    }
}

/* KeaDotN4: four running sums over entries k, k + 4, ..., the tail added to the first, then
 * (s0 + s1) + (s2 + s3) -- the order the direct path's factor has always used. */
static MeReal dot_reference(const MeReal *a, const MeReal *b, int n)
{
    MeReal s[4] = {ME_R(0.0), ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    int m = 0, k;
    for (; m + 4 <= n; m += 4)
        for (k = 0; k < 4; ++k)
            s[k] += a[m + k] * b[m + k];
    for (; m < n; ++m)
        s[0] += a[m] * b[m];
    return (s[0] + s[1]) + (s[2] + s[3]);
}

static void dot_keeps_its_four_sums(void **state)
{
    KtRng rng = {777};
    MeReal a[40], b[40];
    int trial, n, k;
    (void)state;
    for (trial = 0; trial < 200; ++trial) {
        for (k = 0; k < 40; ++k) {
            a[k] = random_value(&rng);
            b[k] = random_value(&rng);
        }
        for (n = 0; n <= 37; ++n) {
            const int offset = trial % 3; /* any alignment */
            assert_true(same_bits(KeaDotN4(a + offset, b + offset, n), dot_reference(a + offset, b + offset, n)));
        }
    }
}

/* KeaClamp(v, lo, hi) for lo <= hi: lo below, hi above, v between, NaN stays NaN; the same value as
 * v < lo ? lo : (v > hi ? hi : v), signed zeros included. */
static void clamp_is_the_middle_value(void **state)
{
    KtRng rng = {4242};
    const MeReal special[] = {ME_R(0.0), -ME_R(0.0), ME_R(1.0), -ME_R(1.0), MEINFINITY, -MEINFINITY, ME_R(1e-30)};
    const int ns = (int)(sizeof special / sizeof special[0]);
    int i, j, k, trial;
    (void)state;
    for (i = 0; i < ns; ++i) /* every ordered pair of bounds from the special values, every v */
        for (j = 0; j < ns; ++j)
            for (k = 0; k < ns; ++k) {
                const MeReal lo = special[i], hi = special[j], v = special[k];
                if (!(lo <= hi))
                    continue;
                assert_true(same_bits(KeaClamp(v, lo, hi), v < lo ? lo : (v > hi ? hi : v)));
            }
    for (trial = 0; trial < 10000; ++trial) {
        MeReal lo = random_value(&rng), hi = random_value(&rng), v = random_value(&rng), t;
        if (hi < lo) {
            t = lo;
            lo = hi;
            hi = t;
        }
        t = KeaClamp(v, lo, hi);
        assert_true(same_bits(t, v < lo ? lo : (v > hi ? hi : v)));
        assert_true(t >= lo && t <= hi);
    }
    {
        volatile MeReal zero = ME_R(0.0);
        const MeReal nan = zero / zero;
        const MeReal t = KeaClamp(nan, -ME_R(1.0), ME_R(1.0));
        assert_true(t != t);
    }
}

/* M^-1 J^T of one half, scalar, in the order the solver's results rest on: B_lin = m^-1 J_lin,
 * B_ang[k] = (I[k][0] a0 + I[k][1] a1) + I[k][2] a2, and J.B = ((l.b)) + ((a.c)), each dot
 * (x0 y0 + x1 y1) + x2 y2; pads 0. */
static MeReal half_reference(const KeaBody *body, const MeReal *jl, const MeReal *ja, MeReal *bl, MeReal *ba)
{
    int k;
    for (k = 0; k < 3; ++k) {
        bl[k] = body->invMass * jl[k];
        ba[k] = (body->invInertia[k][0] * ja[0] + body->invInertia[k][1] * ja[1]) + body->invInertia[k][2] * ja[2];
    }
    bl[3] = ba[3] = ME_R(0.0);
    return ((jl[0] * bl[0] + jl[1] * bl[1]) + jl[2] * bl[2]) + ((ja[0] * ba[0] + ja[1] * ba[1]) + ja[2] * ba[2]);
}

/* A row's M^-1 J^T from the lanes, with the bodies' columns made once (KeaRowInvMassJT4) or per row
 * (KeaRowInvMassJT), gives the scalar reference's B and diagonal bit for bit: rows on two bodies,
 * on one and the world (either half), with eps or without; inverse inertias not exactly symmetric
 * (a world-frame product R I R^T in floating point is not), and J's pads holding junk (the
 * KeaProblem does not promise zero pads; B's pads must come out 0). */
static void inverse_mass_rows_match_the_scalar_ones(void **state)
{
    enum { NB = 4, NR = 64 };
    KtRng rng = {2026};
    KeaBody bodies[NB];
    KeaBodyColumns columns[NB];
    KeaJacobianRow J[NR];
    int rowBodies[NR][2], trial, i, b, j, k;
    MeReal eps[NR];
    (void)state;
    for (trial = 0; trial < 50; ++trial) {
        KeaProblem problem;
        memset(&problem, 0, sizeof problem);
        for (b = 0; b < NB; ++b) {
            bodies[b].invMass = b == NB - 1 ? ME_R(0.0) : (MeReal)kt_range(&rng, 0.01, 10.0);
            for (j = 0; j < 3; ++j)
                for (k = 0; k < 3; ++k)
                    bodies[b].invInertia[j][k] = random_value(&rng);
        }
        for (i = 0; i < NR; ++i) {
            MeReal *halves[4] = {J[i].lin0, J[i].ang0, J[i].lin1, J[i].ang1};
            for (j = 0; j < 4; ++j)
                for (k = 0; k < 4; ++k)
                    halves[j][k] = k < 3 ? random_value(&rng) : (MeReal)kt_range(&rng, -1e6, 1e6);
            rowBodies[i][0] = i % 5 == 0 ? -1 : (int)(kt_uniform(&rng) * NB) % NB;
            rowBodies[i][1] = i % 3 == 0 ? -1 : (rowBodies[i][0] + 1 + i % (NB - 1)) % NB;
            eps[i] = random_value(&rng);
        }
        problem.nRows = NR;
        problem.nBodies = NB;
        problem.bodies = bodies;
        problem.J = J;
        problem.rowBodies = (const int(*)[2])rowBodies;
        problem.epsilon = trial % 2 ? eps : NULL;
        KeaBodyColumnsFill(&problem, columns);
        for (i = 0; i < NR; ++i) {
            KeaJacobianRow expect, got, alone;
            MeReal d = problem.epsilon ? eps[i] : ME_R(0.0), d4, d1;
            memset(&expect, 0, sizeof expect);
            if (rowBodies[i][0] >= 0)
                d += half_reference(&bodies[rowBodies[i][0]], J[i].lin0, J[i].ang0, expect.lin0, expect.ang0);
            if (rowBodies[i][1] >= 0)
                d += half_reference(&bodies[rowBodies[i][1]], J[i].lin1, J[i].ang1, expect.lin1, expect.ang1);
            d4 = KeaRowInvMassJT4(&problem, columns, i, &got);
            d1 = KeaRowInvMassJT(&problem, i, &alone);
            assert_true(same_bits(d4, d));
            assert_true(same_bits(d1, d));
            assert_memory_equal(&expect, &got, sizeof expect);
            assert_memory_equal(&expect, &alone, sizeof expect);
        }
    }
}

/* KeaLanesFinite3x4 (KeaSolve's test of a Jacobian row) is |v| < MEINFINITY of each of the twelve
 * components, whatever the pads hold: every special value in every place, the pads not numbers. */
static void finite_lanes_are_the_scalar_test(void **state)
{
    const MeReal special[] = {ME_R(0.0), -ME_R(0.0), ME_R(1.0), -ME_R(3.5e3), MEINFINITY, -MEINFINITY,
                              (MeReal)INFINITY, -(MeReal)INFINITY, (MeReal)NAN, ME_R(0.5) * MEINFINITY,
                              -ME_R(0.5) * MEINFINITY};
    const int nSpecial = (int)(sizeof special / sizeof special[0]);
    MeReal v[4][4];
    int place, value, k;
    (void)state;
    for (place = 0; place < 16; ++place)
        for (value = 0; value < nSpecial; ++value) {
            int expect = 1;
            for (k = 0; k < 16; ++k) /* pads NaN: not read as numbers */
                v[k / 4][k % 4] = k % 4 == 3 ? (MeReal)NAN : ME_R(0.5) * (MeReal)(k + 1);
            v[place / 4][place % 4] = special[value];
            if (place % 4 != 3)
                expect = MeFabs(special[value]) < MEINFINITY;
            assert_int_equal(KeaLanesFinite3x4(v[0], v[1], v[2], v[3]), expect);
        }
}

/* The iterative path's contact kernels (kea_iterative.h, kea_block_kernels.h), which load a
 * contact's bodies, impulses and inverse once for its three rows, give the bits of the row kernels
 * they stand for: the gather KeaRowVel4 (KeaRowVel4World on the world) per row, the scatter three
 * KeaRowApply4 in row order. */
static void contact_kernels_are_the_row_kernels(void **state)
{
    KtRng rng = {4242};
    int trial, r, k;
    (void)state;
    for (trial = 0; trial < 500; ++trial) {
        _Alignas(16) KeaJacobianRow J[3]; /* as the work's rows: the contact kernels load them aligned */
        KeaVel4 v0, v1, a0, a1, b0, b1;
        MeReal gathered[4], d[3];
        memset(J, 0, sizeof J);
        memset(&v0, 0, sizeof v0);
        memset(&v1, 0, sizeof v1);
        for (r = 0; r < 3; ++r)
            for (k = 0; k < 3; ++k) {
                J[r].lin0[k] = random_value(&rng);
                J[r].ang0[k] = random_value(&rng);
                J[r].lin1[k] = random_value(&rng);
                J[r].ang1[k] = random_value(&rng);
            }
        for (k = 0; k < 3; ++k) {
            v0.lin[k] = random_value(&rng);
            v0.ang[k] = random_value(&rng);
            v1.lin[k] = random_value(&rng);
            v1.ang[k] = random_value(&rng);
            d[k] = random_value(&rng);
        }
        KeaLanesStore(gathered, KeaContactGather(J, &v0, &v1));
        for (r = 0; r < 3; ++r)
            assert_true(same_bits(gathered[r], KeaRowVel4(&J[r], &v0, &v1)));
        KeaLanesStore(gathered, KeaContactGather(J, &v0, NULL));
        for (r = 0; r < 3; ++r)
            assert_true(same_bits(gathered[r], KeaRowVel4World(&J[r], &v0)));

        a0 = b0 = v0;
        a1 = b1 = v1;
        KeaContactScatter(J, KeaLanesLoad3(d), &a0, &a1);
        for (r = 0; r < 3; ++r)
            KeaRowApply4(&J[r], d[r], &b0, &b1);
        assert_memory_equal(&a0, &b0, sizeof a0);
        assert_memory_equal(&a1, &b1, sizeof a1);

    }
}

/* KeaLanesTranspose4 moves entry (i, j) of the four rows to (j, i), every bit (NaN and -0 too). */
static void transpose_moves_every_entry(void **state)
{
    KtRng rng = {777};
    MeReal m[4][4], t[4][4];
    KeaLanes a, b, c, d;
    int i, j, trial;
    (void)state;
    for (trial = 0; trial < 50; ++trial) {
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 4; ++j)
                m[i][j] = random_value(&rng);
        m[trial % 4][(trial / 4) % 4] = trial % 2 ? (MeReal)NAN : -ME_R(0.0);
        a = KeaLanesLoad(m[0]);
        b = KeaLanesLoad(m[1]);
        c = KeaLanesLoad(m[2]);
        d = KeaLanesLoad(m[3]);
        KeaLanesTranspose4(&a, &b, &c, &d);
        KeaLanesStore(t[0], a);
        KeaLanesStore(t[1], b);
        KeaLanesStore(t[2], c);
        KeaLanesStore(t[3], d);
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 4; ++j)
                assert_memory_equal(&t[i][j], &m[j][i], sizeof(MeReal));
    }
}


/* The pack's selects from its masks, as KeaPacksListFree makes them (KeaLanesKeep reads them). */
static void set_keep(KeaContactPack *pack)
{
    int r;
    for (r = 0; r < 3; ++r)
        KeaLanesStoreA(pack->keep[r], KeaLanesSelectOf(KeaLanesLoadA(pack->mask[r])));
}

/* A pack (kea_contact_packs.h) against the row kernels it stands for, on NB bodies and the world
 * (body NB, all zero): lanes 0 and 1 share their body 0 (the scatter's write conflict), lane 2 is
 * on the world, and with `lanes` < 4 the last lanes hold no contact (zeros on the world, mask 0),
 * as in a solve's last pack. Or (`pair`) four contacts on one body pair, bodies 0 and 1 or body 0
 * and the world. */
enum { PACK_NB = 3 };
#define UNIT_ROUND ((MeReal)(sizeof(MeReal) == sizeof(float) ? FLT_EPSILON : DBL_EPSILON))

static void make_pack(KtRng *rng, int lanes, int pair, KeaContactPack *pack, KeaJacobianRow J[4][3],
                      KeaJacobianRow B[4][3], MeReal inv[4][9])
{
    int l, r, k;
    memset(pack, 0, sizeof *pack);
    memset(J, 0, sizeof(KeaJacobianRow) * 12);
    memset(B, 0, sizeof(KeaJacobianRow) * 12);
    pack->pair = pair != 0;
    if (pair)
        lanes = 4;
    pack->lanes = lanes;
    pack->allFull = lanes == 4;
    for (l = 0; l < 4; ++l) {
        const int used = l < lanes, world = pair ? pair == 2 : l == 2;
        pack->body[0][l] = pair ? 0 : (!used ? PACK_NB : (l < 2 ? 0 : l % PACK_NB));
        pack->body[1][l] = !used || world ? PACK_NB : (pair || l == 0 ? 1 : 2);
        pack->full[l] = used ? ME_R(1.0) : ME_R(0.0);
        for (r = 0; r < 3; ++r) {
            for (k = 0; k < 3; ++k) {
                MeReal *half[8] = {J[l][r].lin0, J[l][r].ang0, J[l][r].lin1, J[l][r].ang1,
                                   B[l][r].lin0, B[l][r].ang0, B[l][r].lin1, B[l][r].ang1};
                int h;
                for (h = 0; h < 8; ++h) /* the world's half and an empty lane: exact zeros */
                    half[h][k] = !used || (world && (h % 4) >= 2) ? ME_R(0.0) : random_value(rng);
                for (h = 0; h < 4; ++h) {
                    pack->J[r][3 * h + k][l] = half[h][k];
                    pack->B[r][3 * h + k][l] = half[4 + h][k];
                }
            }
            for (k = 0; k <= r; ++k) /* a symmetric 3 x 3 */
                inv[l][3 * r + k] = inv[l][3 * k + r] = used ? random_value(rng) : ME_R(0.0);
            pack->mask[r][l] = used ? ME_R(1.0) : ME_R(0.0);
            pack->invDiag[r][l] = used ? (MeReal)kt_range(rng, 0.01, 10.0) : ME_R(0.0);
        }
        for (r = 0; r < 3; ++r)
            for (k = 0; k < 3; ++k)
                pack->inv[3 * r + k][l] = inv[l][3 * k + r];
    }
    set_keep(pack);
}

static void random_bodies(KtRng *rng, KeaVel4 *v)
{
    int b, k;
    memset(v, 0, sizeof(KeaVel4) * (PACK_NB + 1));
    for (b = 0; b < PACK_NB; ++b)
        for (k = 0; k < 3; ++k) {
            v[b].lin[k] = random_value(rng);
            v[b].ang[k] = random_value(rng);
        }
}

/* The gather and the preconditioner give each used lane the bits of KeaRowVel4 and of
 * KeaBlockSymmetricApply (m = 3), or of res_r / d_r for a lane not preconditioned by its inverse (up
 * to the sign of a zero); a masked row's gather and an empty lane's give 0. */
static void pack_gather_and_inverse_are_the_row_kernels(void **state)
{
    KtRng rng = {9191};
    int trial, l, r;
    (void)state;
    for (trial = 0; trial < 400; ++trial) {
        const int lanes = 1 + trial % 4;
        KeaContactPack pack;
        KeaJacobianRow J[4][3], B[4][3];
        MeReal inv[4][9], out[12], res[12], z[12];
        KeaVel4 dv[PACK_NB + 1];
        make_pack(&rng, lanes, trial % 7 < 2 ? 1 + trial % 7 : 0, &pack, J, B, inv);
        random_bodies(&rng, dv);
        if (trial % 5 == 4) { /* an SM step where lane 0's friction row 1 is at a bound */
            pack.mask[1][0] = ME_R(0.0);
            pack.full[0] = ME_R(0.0);
            pack.allFull = 0;
        }
        set_keep(&pack);
        for (r = 0; r < 12; ++r)
            res[r] = (r % 4) < lanes ? random_value(&rng) : ME_R(0.0);
        KeaPackGather(&pack, dv, out);
        KeaPackPrecondition(&pack, res, z);
        for (l = 0; l < 4; ++l) {
            MeReal in[3], expect[3];
            for (r = 0; r < 3; ++r)
                in[r] = res[4 * r + l];
            KeaBlockSymmetricApply(3, inv[l], in, expect);
            for (r = 0; r < 3; ++r) {
                const MeReal row = KeaRowVel4(&J[l][r], &dv[pack.body[0][l]], &dv[pack.body[1][l]]);
                if (pack.mask[r][l] != ME_R(0.0))
                    assert_true(same_bits(out[4 * r + l], row));
                else
                    assert_true(out[4 * r + l] == ME_R(0.0));
                if (pack.full[l] != ME_R(0.0))
                    assert_true(same_bits(z[4 * r + l], expect[r]) || (z[4 * r + l] == ME_R(0.0) && expect[r] == ME_R(0.0)));
                else
                    assert_true(same_bits(z[4 * r + l], in[r] * pack.invDiag[r][l]) ||
                                (z[4 * r + l] == ME_R(0.0) && in[r] * pack.invDiag[r][l] == ME_R(0.0)));
            }
        }
    }
}

/* The scatter adds what three KeaRowApply4 per lane, lane after lane, add, within rounding (each
 * lane sums its three rows before adding them to a body): a body two lanes share gets both, the
 * world and the pads stay exactly 0, an empty lane adds nothing; a pair pack gives the bits of the
 * same pack scattered lane by lane. The bound, 10 eps (|v| + sum |B d|), covers both orders'
 * roundings: at most 13 and 8 rounded operations of half an eps on a component. */
static void pack_scatter_is_the_row_kernels_within_rounding(void **state)
{
    KtRng rng = {5150};
    int trial, l, r, b, k;
    (void)state;
    for (trial = 0; trial < 400; ++trial) {
        const int lanes = 1 + trial % 4;
        KeaContactPack pack;
        KeaJacobianRow J[4][3], B[4][3];
        MeReal inv[4][9], d[12], scale[PACK_NB + 1][2][3];
        KeaVel4 got[PACK_NB + 1], expect[PACK_NB + 1], byLane[PACK_NB + 1];
        make_pack(&rng, lanes, trial % 7 < 2 ? 1 + trial % 7 : 0, &pack, J, B, inv);
        random_bodies(&rng, got);
        memcpy(expect, got, sizeof got);
        for (r = 0; r < 12; ++r)
            d[r] = (r % 4) < lanes ? random_value(&rng) : ME_R(0.0);
        for (b = 0; b <= PACK_NB; ++b) /* |v| + sum |B d|: the size of the rounding */
            for (k = 0; k < 3; ++k) {
                scale[b][0][k] = MeFabs(got[b].lin[k]);
                scale[b][1][k] = MeFabs(got[b].ang[k]);
            }
        for (l = 0; l < 4; ++l)
            for (r = 0; r < 3; ++r) {
                KeaRowApply4(&B[l][r], d[4 * r + l], &expect[pack.body[0][l]], &expect[pack.body[1][l]]);
                for (k = 0; k < 3; ++k) {
                    scale[pack.body[0][l]][0][k] += MeFabs(B[l][r].lin0[k] * d[4 * r + l]);
                    scale[pack.body[0][l]][1][k] += MeFabs(B[l][r].ang0[k] * d[4 * r + l]);
                    scale[pack.body[1][l]][0][k] += MeFabs(B[l][r].lin1[k] * d[4 * r + l]);
                    scale[pack.body[1][l]][1][k] += MeFabs(B[l][r].ang1[k] * d[4 * r + l]);
                }
            }
        memcpy(byLane, got, sizeof got);
        KeaPackScatter(&pack, d, got, -1);
        if (pack.pair) { /* the same pack scattered lane by lane */
            KeaContactPack lanePack = pack;
            lanePack.pair = 0;
            KeaPackScatter(&lanePack, d, byLane, -1);
            assert_memory_equal(byLane, got, sizeof got);
        }
        for (b = 0; b <= PACK_NB; ++b) {
            for (k = 0; k < 3; ++k) {
                assert_true(MeFabs(got[b].lin[k] - expect[b].lin[k]) <= ME_R(10.0) * UNIT_ROUND * scale[b][0][k]);
                assert_true(MeFabs(got[b].ang[k] - expect[b].ang[k]) <= ME_R(10.0) * UNIT_ROUND * scale[b][1][k]);
            }
            assert_true(got[b].lin[3] == ME_R(0.0) && got[b].ang[3] == ME_R(0.0));
        }
        for (k = 0; k < 4; ++k)
            assert_true(got[PACK_NB].lin[k] == ME_R(0.0) && got[PACK_NB].ang[k] == ME_R(0.0));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lanes_do_the_scalar_operations),
        cmocka_unit_test(dot_keeps_its_four_sums),
        cmocka_unit_test(clamp_is_the_middle_value),
        cmocka_unit_test(inverse_mass_rows_match_the_scalar_ones),
        cmocka_unit_test(finite_lanes_are_the_scalar_test),
        cmocka_unit_test(contact_kernels_are_the_row_kernels),
        cmocka_unit_test(contact_step_lanes_are_the_scalars),
        cmocka_unit_test(transpose_moves_every_entry),
        cmocka_unit_test(pack_gather_and_inverse_are_the_row_kernels),
        cmocka_unit_test(pack_scatter_is_the_row_kernels_within_rounding),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
