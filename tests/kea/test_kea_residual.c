/* test_kea_residual.c -- KeaResidual, the natural-map residual of any impulses x, as an independent
 * check of both of Kea's paths.
 *
 * KeaResidual takes each row's d_i = A_ii from the row's own M^-1 J^T, not from a formed A (the
 * direct path's KeaStats.residual uses the factor's diagonal), so it checks an answer without the
 * solver's own arithmetic. First it is checked itself against the residual made in double from the
 * dense A of kea_test_problems.h; then: the direct path's answers on random problems have residual
 * ~0 (and a nudged answer has not: the check can fail), and the iterative path's residual falls as
 * it is given more sweeps. */
#include "karma_test.h"

#include "kea_test_problems.h"

/* max_i d_i |x_i - mid(lo_i, x_i - w_i / d_i, hi_i)| with w = A x - r, all in double from the dense
 * A; rows without friction links (their bounds are their own). */
static double dense_residual(const KeaProblem *p, const MeReal *x)
{
    const int n = p->nRows;
    double *A = malloc(sizeof(double) * (size_t)(n * n + 1));
    double worst = 0.0;
    kt_dense_matrix(p, A);
    for (int i = 0; i < n; ++i) {
        double w = -(double)p->rhs[i], d = A[i * n + i];
        for (int j = 0; j < n; ++j)
            w += A[i * n + j] * (double)x[j];
        const double lo = (double)p->lo[i], hi = (double)p->hi[i], xi = (double)x[i];
        const double mid = fmin(fmax(xi - w / d, lo), hi);
        worst = fmax(worst, d * fabs(xi - mid));
    }
    free(A);
    return worst;
}

static void residual_matches_the_dense_reference(void **state)
{
    (void)state;
    double worstRel = 0.0;
    MeReal x[12];
    KeaBodyVelocity dv[5];
    for (int seed = 0; seed < 50; ++seed) {
        KtRng rng = kt_rng((uint64_t)(4200 + seed));
        KtProblem t;
        kt_random_problem(&t, &rng, 12, 5, 1e-3, 1e-1);
        for (int i = 0; i < 12; ++i) /* any impulses, inside or outside the bounds */
            x[i] = (MeReal)kt_range(&rng, -1, 1);
        KeaBodyVelocityFromImpulses(&t.p, x, dv);
        const double ours = (double)KeaResidual(&t.p, x, dv), ref = dense_residual(&t.p, x);
        assert_true(ref > 0.0);
        worstRel = fmax(worstRel, fabs(ours - ref) / ref);
        assert_rel(ours, ref, ME_TOL(1e-10, 1e-4));
        kt_free(&t);
    }
    print_message("KeaResidual vs the dense double residual: max relative difference %.3g\n", worstRel);
}

/* Direct answers, without and with friction links, have residual ~0 by KeaResidual; the same answer
 * with one row's impulse moved by 0.1 has not. */
static void direct_answers_have_zero_residual(void **state)
{
    (void)state;
    KeaParameters prm = kt_params(KeaPathDirect);
    prm.maxFrictionPasses = 50;
    double worst = 0.0;
    for (int seed = 0; seed < 40; ++seed) {
        KtRng rng = kt_rng((uint64_t)(5100 + seed));
        KtProblem t;
        MeReal x[24];
        KeaBodyVelocity dv[6];
        KeaStats st;
        if (seed % 2)
            kt_random_contacts(&t, &rng, 6, 4, 6, 0.5, 1e-2); /* 22 rows, friction linked */
        else
            kt_random_problem(&t, &rng, 20, 6, 1e-3, 1e-1);
        assert_int_equal(kt_solve(&t.p, &prm, x, dv, &st), KeaStatusOk);
        const MeReal res = KeaResidual(&t.p, x, dv);
        worst = fmax(worst, (double)res);
        assert_near(res, 0.0, ME_TOL(1e-9, 1e-4));
        assert_near(res, st.residual, ME_TOL(1e-9, 1e-4)); /* the path's own measure agrees */
        x[0] += ME_R(0.1);
        KeaBodyVelocityFromImpulses(&t.p, x, dv);
        assert_true(KeaResidual(&t.p, x, dv) > ME_R(1e-3));
        kt_free(&t);
    }
    print_message("direct path: worst KeaResidual %.3g over 40 random problems\n", worst);
}

/* The iterative path's residual (KeaResidual of what it returns) falls as the sweeps grow: each
 * fourfold more sweeps leave it no larger, and 256 sweeps leave at most a hundredth of one. */
static void iterative_residual_falls_with_sweeps(void **state)
{
    (void)state;
    static const int sweeps[] = {1, 4, 16, 64, 256};
    enum { STEPS = sizeof sweeps / sizeof sweeps[0] };
    for (int seed = 0; seed < 10; ++seed) {
        KtRng rng = kt_rng((uint64_t)(6300 + seed));
        KtProblem t;
        MeReal x[30];
        KeaBodyVelocity dv[8];
        MeReal res[STEPS];
        kt_random_contacts(&t, &rng, 8, 6, 8, 0.5, 1e-2);
        for (int s = 0; s < STEPS; ++s) {
            KeaParameters prm = kt_params(KeaPathIterative);
            prm.maxIterations = sweeps[s];
            prm.tolerance = ME_R(0.0);
            kt_solve(&t.p, &prm, x, dv, NULL);
            res[s] = KeaResidual(&t.p, x, dv);
            if (s > 0)
                assert_true(res[s] <= res[s - 1] * ME_R(1.0001) + ME_TOL(1e-12, 1e-6));
        }
        assert_true(res[STEPS - 1] <= ME_R(0.01) * res[0]);
        if (seed == 0)
            print_message("iterative path, seed 0: residual %.3g, %.3g, %.3g, %.3g, %.3g after 1, 4, 16, 64, 256 "
                          "sweeps\n", (double)res[0], (double)res[1], (double)res[2], (double)res[3],
                          (double)res[4]);
        kt_free(&t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(residual_matches_the_dense_reference),
        cmocka_unit_test(direct_answers_have_zero_residual),
        cmocka_unit_test(iterative_residual_falls_with_sweeps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
