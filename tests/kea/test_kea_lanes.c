/* test_kea_lanes.c -- the four-lane kernels (kea_lanes.h, and M^-1 J^T of a row from them) and the
 * scalar helpers the solver's results rest on compute exactly what their comments say, bit for bit: each lane the scalar IEEE
 * operations in the stated order, whatever the lanes are made of (SSE in a single-precision x86
 * build, an array elsewhere). The solver's "same trajectory" claims for these kernels depend on it. */
#include "karma_test.h"

#include <string.h>

#include "kea_test_problems.h"
#include "mdt/kea/kea_block_kernels.h"

/* Random values of mixed sign and magnitude (including exact zeros), as solver data has. */
static MeReal random_value(KtRng *r)
{
    const double u = kt_uniform(r);
    if (u < 0.05)
        return ME_R(0.0);
    return (MeReal)(kt_range(r, -1.0, 1.0) * (u < 0.5 ? 1.0 : 1e3 * kt_uniform(r)));
}

static int same_bits(MeReal a, MeReal b) { return memcmp(&a, &b, sizeof a) == 0; }

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
 * KeaRowApply4 in row order, the inverse's padded columns KeaBlockSymmetricApply for m = 3; and
 * KeaLanesStore3 writes three lanes and leaves the fourth place alone. */
static void contact_kernels_are_the_row_kernels(void **state)
{
    KtRng rng = {4242};
    int trial, r, k;
    (void)state;
    for (trial = 0; trial < 500; ++trial) {
        KeaJacobianRow J[3];
        KeaVel4 v0, v1, a0, a1, b0, b1;
        MeReal inv[9], columns[12], in[3], out[3], got[4], gathered[3], d[3];
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
            in[k] = random_value(&rng);
            d[k] = random_value(&rng);
        }
        KeaContactGather(J, &v0, &v1, gathered);
        for (r = 0; r < 3; ++r)
            assert_true(same_bits(gathered[r], KeaRowVel4(&J[r], &v0, &v1)));
        KeaContactGather(J, &v0, NULL, gathered);
        for (r = 0; r < 3; ++r)
            assert_true(same_bits(gathered[r], KeaRowVel4World(&J[r], &v0)));

        a0 = b0 = v0;
        a1 = b1 = v1;
        KeaContactScatter(J, d, &a0, &a1);
        for (r = 0; r < 3; ++r)
            KeaRowApply4(&J[r], d[r], &b0, &b1);
        assert_memory_equal(&a0, &b0, sizeof a0);
        assert_memory_equal(&a1, &b1, sizeof a1);

        for (r = 0; r < 3; ++r) /* a symmetric 3 x 3 and its padded columns */
            for (k = 0; k <= r; ++k)
                inv[3 * r + k] = inv[3 * k + r] = random_value(&rng);
        for (k = 0; k < 3; ++k) {
            for (r = 0; r < 3; ++r)
                columns[4 * k + r] = inv[3 * k + r];
            columns[4 * k + 3] = ME_R(0.0);
        }
        KeaBlockSymmetricApply(3, inv, in, out);
        got[3] = ME_R(-7.0);
        KeaLanesStore3(got, KeaContactInverseApply(columns, in[0], in[1], in[2]));
        for (r = 0; r < 3; ++r)
            assert_true(same_bits(got[r], out[r]));
        assert_true(same_bits(got[3], ME_R(-7.0)));
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
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
