/* test_kea_memory.c -- Kea's workspace contract, path selection, input checks and determinism.
 *
 * The solve must run in exactly KeaMemoryRequired bytes, whatever the buffer's alignment: the
 * buffers here are heap blocks of exactly that size (or offset by one byte inside a block one byte
 * larger), so the sanitizer build catches any access past the reported size. */
#include "karma_test.h"

#include "kea_test_problems.h"

static void solve_in_exact_workspace(const KeaProblem *p, KeaPath path, size_t misalign)
{
    KeaParameters prm = kt_params(path);
    const size_t bytes = KeaMemoryRequired(p->nRows, p->nBodies, path);
    unsigned char *block = (unsigned char *)malloc(bytes + misalign);
    MeReal *x = (MeReal *)malloc(sizeof(MeReal) * (size_t)(p->nRows + 1));
    KeaBodyVelocity *dv = (KeaBodyVelocity *)malloc(sizeof(KeaBodyVelocity) * (size_t)(p->nBodies + 1));
    KeaStats st;
    KeaStatus status;
    assert_true(bytes > 0);
    status = KeaSolve(p, &prm, block + misalign, bytes, x, dv, &st);
    assert_true(status == KeaStatusOk || status == KeaStatusMaxIterations);
    assert_int_equal(st.path, path);
    /* and without a velocity output (Kea keeps dv in the workspace) */
    status = KeaSolve(p, &prm, block + misalign, bytes, x, NULL, &st);
    assert_true(status == KeaStatusOk || status == KeaStatusMaxIterations);
    free(block);
    free(x);
    free(dv);
}

static void exact_workspace_is_enough(void **state)
{
    const int sizes[][2] = {{1, 1}, {3, 1}, {8, 3}, {30, 8}, {37, 12}};
    int s, seed = 0;
    (void)state;
    for (s = 0; s < 5; ++s) {
        KtRng rng = kt_rng((uint64_t)(31 + s));
        KtProblem t, c;
        kt_random_problem(&t, &rng, sizes[s][0], sizes[s][1], 1e-3, 1e-1);
        kt_random_contacts(&c, &rng, 1 + sizes[s][0] / 3, sizes[s][0] % 3, sizes[s][1], 0.4, 1e-2);
        for (seed = 0; seed < 2; ++seed) {
            solve_in_exact_workspace(&t.p, KeaPathDirect, (size_t)seed);
            solve_in_exact_workspace(&t.p, KeaPathIterative, (size_t)seed);
            solve_in_exact_workspace(&c.p, KeaPathDirect, (size_t)seed);
            solve_in_exact_workspace(&c.p, KeaPathIterative, (size_t)seed);
        }
        kt_free(&t);
        kt_free(&c);
    }
}

static void short_workspace_is_refused(void **state)
{
    KtRng rng = kt_rng(5);
    KtProblem t;
    KeaParameters prm = kt_params(KeaPathDirect);
    size_t bytes;
    unsigned char *block;
    MeReal x[10];
    KeaStats st;
    int i;
    (void)state;
    kt_random_problem(&t, &rng, 10, 3, 1e-3, 1e-1);
    bytes = KeaMemoryRequired(10, 3, KeaPathDirect);
    block = (unsigned char *)malloc(bytes);
    for (i = 0; i < 10; ++i)
        x[i] = ME_R(7.0);
    assert_int_equal(KeaSolve(&t.p, &prm, block, bytes - 1, x, NULL, &st), KeaStatusWorkspaceTooSmall);
    assert_int_equal(st.status, KeaStatusWorkspaceTooSmall);
    for (i = 0; i < 10; ++i) /* nothing was touched */
        assert_true(x[i] == ME_R(7.0));
    assert_int_equal(KeaSolve(&t.p, &prm, NULL, bytes, x, NULL, &st), KeaStatusWorkspaceTooSmall);
    /* Auto asks for enough for either path */
    assert_true(KeaMemoryRequired(10, 3, KeaPathAuto) >= KeaMemoryRequired(10, 3, KeaPathDirect));
    assert_true(KeaMemoryRequired(10, 3, KeaPathAuto) >= KeaMemoryRequired(10, 3, KeaPathIterative));
    /* the direct path's workspace grows with n^2, the iterative path's with n */
    assert_true(KeaMemoryRequired(400, 100, KeaPathDirect) > 3 * KeaMemoryRequired(200, 100, KeaPathDirect));
    assert_true(KeaMemoryRequired(400, 100, KeaPathIterative) < 3 * KeaMemoryRequired(200, 100, KeaPathIterative));
    free(block);
    kt_free(&t);
}

static void path_selection(void **state)
{
    KeaParameters prm;
    (void)state;
    KeaParametersDefault(&prm);
    assert_int_equal(prm.path, KeaPathAuto);
    assert_int_equal(prm.maxIterations, 10);
    assert_int_equal(KeaSelectPath(prm.maxDirectRows, &prm), KeaPathDirect);
    /* Between maxDirectRows and 4 maxDirectRows rows the structure decides (KeaSolve): Auto. */
    assert_int_equal(KeaSelectPath(prm.maxDirectRows + 1, &prm), KeaPathAuto);
    assert_int_equal(KeaSelectPath(4 * prm.maxDirectRows, &prm), KeaPathAuto);
    assert_int_equal(KeaSelectPath(4 * prm.maxDirectRows + 1, &prm), KeaPathIterative);
    assert_int_equal(KeaSelectPath(0, &prm), KeaPathDirect);
    prm.path = KeaPathIterative;
    assert_int_equal(KeaSelectPath(1, &prm), KeaPathIterative);
    prm.path = KeaPathDirect;
    assert_int_equal(KeaSelectPath(100000, &prm), KeaPathDirect);
    prm.path = KeaPathAuto;
    prm.maxDirectRows = 0;
    assert_int_equal(KeaSelectPath(1, &prm), KeaPathIterative);
}

static void bad_input_is_refused(void **state)
{
    KtRng rng = kt_rng(6);
    KtProblem t;
    KeaParameters prm = kt_params(KeaPathAuto);
    MeReal x[6];
    KeaStats st;
    MeReal keep;
    (void)state;
    kt_random_contacts(&t, &rng, 2, 0, 2, 0.5, 1e-2);
    assert_true(kt_solve(&t.p, &prm, x, NULL, &st) == KeaStatusOk);
    keep = t.lo[0];
    t.lo[0] = ME_R(1.0);
    t.hi[0] = ME_R(0.5); /* lo > hi */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.lo[0] = keep;
    t.hi[0] = MEINFINITY;
    t.rowBodies[2][0] = 2; /* body out of range */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.rowBodies[2][0] = t.rowBodies[0][0];
    t.link[1] = 1; /* linked to itself */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.link[1] = 2; /* linked to a friction row */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.link[1] = 0;
    t.eps[3] = ME_R(-1.0);
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.eps[3] = ME_R(0.01);
    t.rhs[4] = (MeReal)NAN;
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.rhs[4] = MEINFINITY; /* Karma's infinity is not a number a row may hold */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.rhs[4] = ME_R(0.5);
    keep = t.J[5].ang1[2];
    t.J[5].ang1[2] = (MeReal)NAN; /* every Jacobian entry is checked, the last one too */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.J[5].ang1[2] = -MEINFINITY;
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.J[5].ang1[2] = keep;
    t.J[5].ang1[3] = (MeReal)NAN; /* a pad is not a number the solver reads */
    assert_true(kt_solve(&t.p, &prm, x, NULL, &st) == KeaStatusOk);
    t.J[5].ang1[3] = ME_R(0.0);
    assert_true(kt_solve(&t.p, &prm, x, NULL, &st) == KeaStatusOk);
    keep = t.bodies[1].invInertia[2][2];
    t.bodies[1].invInertia[2][2] = (MeReal)NAN; /* every body's every number, the last one too */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.bodies[1].invInertia[2][2] = keep;
    keep = t.bodies[1].invMass;
    t.bodies[1].invMass = ME_R(-1.0);
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.bodies[1].invMass = MEINFINITY;
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.bodies[1].invMass = keep;
    keep = t.mu[1];
    t.mu[1] = (MeReal)NAN; /* a linked row's friction coefficient */
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.mu[1] = ME_R(-0.5);
    assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
    t.mu[1] = keep;
    assert_true(kt_solve(&t.p, &prm, x, NULL, &st) == KeaStatusOk);
    assert_int_equal(KeaSolve(&t.p, NULL, NULL, 0, x, NULL, &st), KeaStatusBadInput);
    kt_free(&t);
}

static void empty_partition(void **state)
{
    KtProblem t;
    KeaParameters prm = kt_params(KeaPathAuto);
    KeaBodyVelocity dv[2];
    KeaStats st;
    MeReal x[1];
    (void)state;
    kt_alloc(&t, 0, 2, 0);
    t.bodies[0].invMass = t.bodies[1].invMass = ME_R(1.0);
    dv[0].lin[0] = dv[1].ang[2] = ME_R(3.0);
    assert_int_equal(kt_solve(&t.p, &prm, x, dv, &st), KeaStatusOk);
    assert_true(dv[0].lin[0] == ME_R(0.0) && dv[1].ang[2] == ME_R(0.0));
    assert_true(st.residual == ME_R(0.0));
    kt_free(&t);
}

/* Same input, same bits; the warm start may alias the output. */
static void deterministic_and_in_place(void **state)
{
    int p;
    (void)state;
    for (p = 0; p < 2; ++p) {
        KtRng rng = kt_rng(99);
        KtProblem t;
        KeaParameters prm = kt_params(p ? KeaPathIterative : KeaPathDirect);
        MeReal x1[30], x2[30];
        KeaBodyVelocity dv1[6], dv2[6];
        KeaStats st;
        int i;
        kt_random_contacts(&t, &rng, 8, 6, 6, 0.5, 1e-2);
        for (i = 0; i < 30; ++i)
            t.x0[i] = (MeReal)kt_range(&rng, 0, 0.2);
        t.p.x0 = t.x0;
        kt_solve(&t.p, &prm, x1, dv1, &st);
        kt_solve(&t.p, &prm, x2, dv2, &st);
        assert_memory_equal(x1, x2, sizeof x1);
        assert_memory_equal(dv1, dv2, sizeof dv1);
        kt_solve(&t.p, &prm, t.x0, dv2, &st); /* x0 aliases x */
        assert_memory_equal(x1, t.x0, sizeof x1);
        kt_free(&t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(exact_workspace_is_enough),
        cmocka_unit_test(short_workspace_is_refused),
        cmocka_unit_test(path_selection),
        cmocka_unit_test(bad_input_is_refused),
        cmocka_unit_test(empty_partition),
        cmocka_unit_test(deterministic_and_in_place),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
