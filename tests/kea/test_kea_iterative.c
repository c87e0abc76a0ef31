/* test_kea_iterative.c -- Kea's iterative path against its direct path.
 *
 * The iterates of the iterative path for caps 1, 5, 20, 100, 1000 are prefixes of one deterministic
 * sequence, and every operation in it (a projected Gauss-Seidel row or block update, an accepted
 * subspace step) lowers the QP objective f(x) = 1/2 x^T A x - r^T x. So on box LCPs the objective gap
 * f(x_k) - f(x*) must not increase with the cap, and it bounds the error: 1/2 |x_k - x*|_A^2 <= gap.
 * f is evaluated in double from the test's own dense A. The max-norm error to the direct solution is
 * printed (a convergence table per problem) and must reach rounding level at the largest cap. */
#include "karma_test.h"

#include "kea_test_problems.h"

typedef struct Variant {
    const char *name;
    int blockRows, subspace;
} Variant;

static const Variant variants[] = {{"PGS", 1, 0}, {"block PGS", 12, 0}, {"block PGS + SM (default)", 12, 4}};
static const int caps[] = {1, 5, 20, 100, 1000};
#define NCAPS 5

/* Random box LCPs of 36 rows in blocks of 3 rows on the same bodies, over 8 bodies. */
static void make_problem(KtProblem *t, int seed)
{
    KtRng rng = kt_rng((uint64_t)(9000 + seed));
    int i;
    kt_random_problem(t, &rng, 36, 8, 1e-3, 1e-2);
    for (i = 0; i < 36; ++i)
        if (i % 3) { /* rows of a block share their bodies */
            t->rowBodies[i][0] = t->rowBodies[i - i % 3][0];
            t->rowBodies[i][1] = t->rowBodies[i - i % 3][1];
        }
}

static void error_does_not_grow_with_iteration_cap(void **state)
{
    double table[3][NCAPS] = {{0}};
    int v, k, seed;
    (void)state;
    for (seed = 0; seed < 10; ++seed) {
        KtProblem t;
        MeReal xd[36], xi[36];
        double A[36 * 36], fStar, gapPrev = INFINITY, scale;
        KeaParameters direct = kt_params(KeaPathDirect);
        KeaStats st;
        make_problem(&t, seed);
        kt_dense_matrix(&t.p, A);
        assert_int_equal(kt_solve(&t.p, &direct, xd, NULL, &st), KeaStatusOk);
        fStar = kt_objective(36, A, t.rhs, xd);
        scale = 1.0;
        for (k = 0; k < 36; ++k)
            scale = fmax(scale, fabs((double)xd[k]));
        for (v = 0; v < 3; ++v) {
            gapPrev = INFINITY;
            for (k = 0; k < NCAPS; ++k) {
                KeaParameters prm = kt_params(KeaPathIterative);
                double gap, err = 0.0;
                int i;
                prm.maxIterations = caps[k];
                prm.tolerance = ME_R(0.0);
                prm.maxBlockRows = variants[v].blockRows;
                prm.subspaceIterations = variants[v].subspace;
                /* tolerance 0: stops early only at an exact fixed point */
                if (kt_solve(&t.p, &prm, xi, NULL, &st) == KeaStatusMaxIterations)
                    assert_int_equal(st.iterations, caps[k]);
                else
                    assert_true(st.iterations <= caps[k]);
                gap = kt_objective(36, A, t.rhs, xi) - fStar;
                /* non-increasing, up to the rounding of f itself */
                assert_true(gap <= gapPrev + ME_TOL(1e-12, 1e-5) * (1.0 + fabs(fStar)));
                gapPrev = gap;
                for (i = 0; i < 36; ++i)
                    err = fmax(err, fabs((double)xi[i] - (double)xd[i]) / scale);
                table[v][k] = fmax(table[v][k], err);
            }
        }
        kt_free(&t);
    }
    print_message("max relative error to the direct solution over 10 random 36-row box LCPs:\n");
    print_message("%-26s %10s %10s %10s %10s %10s\n", "iterations", "1", "5", "20", "100", "1000");
    for (v = 0; v < 3; ++v)
        print_message("%-26s %10.2e %10.2e %10.2e %10.2e %10.2e\n", variants[v].name, table[v][0], table[v][1],
                      table[v][2], table[v][3], table[v][4]);
    /* Sweeps alternate direction (symmetric Gauss-Seidel, which lets tall stacks converge): on these
     * random, densely coupled problems plain and block PGS reach about 1e-6 after 1000 sweeps instead
     * of 1e-8; the default (with subspace minimisation) is exact to rounding. */
    for (v = 0; v < 3; ++v)
        assert_near(table[v][NCAPS - 1], 0.0, v == 2 ? ME_TOL(1e-8, 2e-3) : ME_TOL(1e-5, 2e-3));
    /* the improvements pay: at 20 iterations the default is far closer than plain PGS */
    assert_true(table[2][2] < 0.1 * table[0][2]);
}

/* The largest difference between a and b relative to max(1, |b|). */
static double relative_difference(const MeReal *a, const MeReal *b, int n)
{
    double err = 0.0, scale = 1.0;
    int i;
    for (i = 0; i < n; ++i)
        scale = fmax(scale, fabs((double)b[i]));
    for (i = 0; i < n; ++i)
        err = fmax(err, fabs((double)a[i] - (double)b[i]) / scale);
    return err;
}

/* Solve t with the direct path (friction passes to convergence) into xd and with the iterative
 * path at `iterations` sweeps and no tolerance into xi (its stats in st); returns the largest
 * difference relative to max(1, |xd|). */
static double iterative_vs_direct(const KtProblem *t, int iterations, MeReal *xd, MeReal *xi, KeaStats *st)
{
    KeaParameters direct = kt_params(KeaPathDirect), iter = kt_params(KeaPathIterative);
    direct.maxFrictionPasses = 50;
    assert_int_equal(kt_solve(&t->p, &direct, xd, NULL, st), KeaStatusOk);
    iter.maxIterations = iterations;
    iter.tolerance = ME_R(0.0);
    kt_solve(&t->p, &iter, xi, NULL, st);
    return relative_difference(xi, xd, t->p.nRows);
}

/* With friction links the iterative path converges to the direct path's coupled solution. */
static void friction_links_converge_to_direct(void **state)
{
    double worst = 0.0;
    int seed;
    (void)state;
    for (seed = 0; seed < 20; ++seed) {
        KtRng rng = kt_rng((uint64_t)(700 + seed));
        KtProblem t;
        MeReal xd[40], xi[40];
        KeaStats st;
        double err;
        kt_random_contacts(&t, &rng, 10, 6, 6, 0.2, 1e-2);
        err = iterative_vs_direct(&t, 2000, xd, xi, &st);
        worst = fmax(worst, err);
        assert_near(err, 0.0, ME_TOL(1e-7, 2e-3));
        assert_near(st.residual, 0.0, ME_TOL(1e-7, 1e-3));
        kt_free(&t);
    }
    print_message("friction links: iterative (2000 iterations) vs direct, max relative error %.3g\n", worst);
}

/* A partition that is one contact (a normal row and two friction rows linked to it, on the same
 * bodies) is one block: a single sweep of the iterative path solves it exactly (the block's all-free
 * shortcut, its few-active-set contact solve, or the general block solver), so it must agree with
 * the direct path's coupled solution, sticking, sliding or opening. */
static void one_contact_block_is_exact_in_one_sweep(void **state)
{
    static const double mus[3] = {0.2, 0.6, 1.0};
    double worst = 0.0;
    int seed, opened = 0, sliding = 0;
    (void)state;
    for (seed = 0; seed < 300; ++seed) {
        KtRng rng = kt_rng((uint64_t)(3100 + seed));
        KtProblem t;
        MeReal xd[3], xi[3];
        KeaStats st;
        double err;
        kt_random_contacts(&t, &rng, 1, 0, 1 + seed % 2, mus[seed % 3], 1e-2);
        if (seed % 4 == 0)
            t.rhs[0] = (MeReal)-kt_range(&rng, 0.1, 1.0); /* some contacts pull apart */
        err = iterative_vs_direct(&t, 1, xd, xi, &st);
        worst = fmax(worst, err);
        opened += xd[0] == ME_R(0.0);
        sliding += xd[0] > ME_R(0.0) && (fabs((double)xd[1]) >= (double)(t.mu[1] * xd[0]) * (1 - 1e-5) ||
                                         fabs((double)xd[2]) >= (double)(t.mu[2] * xd[0]) * (1 - 1e-5));
        assert_near(err, 0.0, ME_TOL(1e-9, 1e-4));
        kt_free(&t);
    }
    print_message("one contact, one sweep vs direct: 300 contacts (%d opening, %d sliding), max relative error %.3g\n",
                  opened, sliding, worst);
    assert_true(opened > 10 && sliding > 10);
}

/* The contact's LCP conditions at x, in double from the test's own A: n >= 0 and w_n >= 0 with
 * n w_n = 0; each friction impulse within +-mu n, with w_f = 0 when strictly inside and w_f pushing
 * against the bound it sits at. Returns the largest violation, relative to max(1, |r|). */
static double contact_lcp_violation(const KtProblem *t, const MeReal *x)
{
    double A[9], w[3], scale = 1.0, worst = 0.0;
    int r, c;
    kt_dense_matrix(&t->p, A);
    for (r = 0; r < 3; ++r) {
        w[r] = -(double)t->rhs[r];
        for (c = 0; c < 3; ++c)
            w[r] += A[r * 3 + c] * (double)x[c];
        scale = fmax(scale, fabs((double)t->rhs[r]));
    }
    worst = fmax(worst, fmax(-(double)x[0], -w[0]));
    worst = fmax(worst, fabs((double)x[0] * w[0]));
    for (r = 1; r < 3; ++r) {
        const double bound = (double)t->mu[r] * (double)x[0], f = (double)x[r];
        worst = fmax(worst, fabs(f) - bound);
        if (fabs(f) < bound * (1 - 1e-4))
            worst = fmax(worst, fabs(w[r]));
        else if (bound > 0)
            worst = fmax(worst, f > 0 ? w[r] : -w[r]); /* sliding: w_f opposes the impulse */
    }
    return worst / scale;
}

/* The generic rows path: a contact not declared (here with the world as its first body, which a
 * declared contact may not have) is three generic rows, a normal row with the two rows linked to
 * it, which the sweep solves as one block with the generic block step (KeaBlockStep: the all-free
 * shortcut, or the dense solver). One sweep must give the exact LCP solution (the block is the
 * whole problem), equal to the direct path's, opening, sticking and sliding. */
static void generic_contact_path_is_exact_in_one_sweep(void **state)
{
    static const double mus[3] = {0.2, 0.6, 1.0};
    double worst = 0.0, worstLcp = 0.0;
    int seed, opened = 0, sliding = 0, sticking = 0;
    (void)state;
    for (seed = 0; seed < 300; ++seed) {
        KtRng rng = kt_rng((uint64_t)(5100 + seed));
        KtProblem t;
        MeReal xd[3], xi[3];
        KeaStats st;
        double err, lcp;
        int i, k;
        kt_random_contacts(&t, &rng, 1, 0, 1, mus[seed % 3], 1e-2);
        t.p.nContacts = 0; /* generic rows */
        for (i = 0; i < 3; ++i) { /* the world first: the body's half moves to the second slot */
            t.rowBodies[i][1] = t.rowBodies[i][0];
            t.rowBodies[i][0] = KEA_WORLD;
            for (k = 0; k < 3; ++k) {
                t.J[i].lin1[k] = t.J[i].lin0[k];
                t.J[i].ang1[k] = t.J[i].ang0[k];
                t.J[i].lin0[k] = t.J[i].ang0[k] = ME_R(0.0);
            }
        }
        if (seed % 4 == 0)
            t.rhs[0] = (MeReal)-kt_range(&rng, 0.1, 1.0); /* some contacts pull apart */
        err = iterative_vs_direct(&t, 1, xd, xi, &st);
        lcp = contact_lcp_violation(&t, xi);
        worst = fmax(worst, err);
        worstLcp = fmax(worstLcp, lcp);
        if (xd[0] == ME_R(0.0))
            opened++;
        else if (fabs((double)xd[1]) >= (double)(t.mu[1] * xd[0]) * (1 - 1e-5) ||
                 fabs((double)xd[2]) >= (double)(t.mu[2] * xd[0]) * (1 - 1e-5))
            sliding++;
        else
            sticking++;
        assert_near(err, 0.0, ME_TOL(1e-9, 1e-4));
        assert_near(lcp, 0.0, ME_TOL(1e-9, 1e-4));
        kt_free(&t);
    }
    print_message("generic contact path, one sweep vs direct: 300 contacts (%d opening, %d sticking, %d sliding), "
                  "max relative error %.3g, largest LCP violation %.3g\n",
                  opened, sticking, sliding, worst, worstLcp);
    assert_true(opened > 10 && sliding > 10 && sticking > 10);
}

/* A joint's block whose limit the step reaches: five unbounded rows and a limit row (bounded on one
 * side) on one body pair, or on one body and the world. One sweep solves the block exactly, with the
 * limit row clamped in closed form (KeaBlockClampOneRow) and no pivot of the dense solver; it agrees
 * with the direct path to rounding amplified by the block's conditioning (as the contact blocks'
 * tests). The limit is reached in most of the cases (its all-free value beyond the bound). */
static void joint_limit_block_is_exact_in_one_sweep(void **state)
{
    double worst = 0.0;
    int seed, atLimit = 0;
    (void)state;
    for (seed = 0; seed < 200; ++seed) {
        KtRng rng = kt_rng((uint64_t)(6100 + seed));
        KtProblem t;
        MeReal xd[6], xi[6];
        KeaStats st;
        double err;
        int i, k;
        kt_alloc(&t, 6, 2, 0);
        kt_random_body(&rng, &t.bodies[0]);
        kt_random_body(&rng, &t.bodies[1]);
        for (i = 0; i < 6; ++i) {
            t.rowBodies[i][0] = 0;
            t.rowBodies[i][1] = seed % 2 ? 1 : KEA_WORLD;
            for (k = 0; k < 3; ++k) {
                t.J[i].lin0[k] = (MeReal)kt_range(&rng, -1, 1);
                t.J[i].ang0[k] = (MeReal)kt_range(&rng, -1, 1);
                t.J[i].lin1[k] = seed % 2 ? (MeReal)kt_range(&rng, -1, 1) : ME_R(0.0);
                t.J[i].ang1[k] = seed % 2 ? (MeReal)kt_range(&rng, -1, 1) : ME_R(0.0);
            }
            t.eps[i] = (MeReal)kt_range(&rng, 1e-3, 1e-2);
            t.rhs[i] = (MeReal)kt_range(&rng, -1, 1);
            t.lo[i] = -MEINFINITY;
            t.hi[i] = MEINFINITY;
        }
        if (seed % 4 < 2)
            t.lo[5] = ME_R(0.0); /* a lower limit */
        else
            t.hi[5] = (MeReal)kt_range(&rng, -0.2, 0.2); /* an upper limit, at a force of either sign */
        err = iterative_vs_direct(&t, 1, xd, xi, &st);
        worst = fmax(worst, err);
        atLimit += xd[5] == t.lo[5] || xd[5] == t.hi[5];
        assert_near(err, 0.0, ME_TOL(1e-9, 1e-4));
        assert_int_equal(st.pivots, 0);
        assert_true(xi[5] >= t.lo[5] && xi[5] <= t.hi[5]);
        kt_free(&t);
    }
    print_message("joint limit blocks, one sweep vs direct: 200 blocks (%d at the limit), max relative error %.3g\n",
                  atLimit, worst);
    assert_true(atLimit > 50);
}

/* Contacts whose exact solution sits on the edge of the friction cone (the primary friction
 * impulse at exactly mu n, the secondary inside): the plain contact step's closed forms (all rows
 * free, or the primary sliding) then hold only within rounding, about half the time neither passes
 * its exact test, and the step falls back to the dense box-LCP solver. Whichever way each contact
 * goes, one sweep must meet the contact's LCP conditions. (Not compared with the direct path: with
 * friction, such a contact's LCP may have more than one solution, and the two paths may find
 * different ones.) */
static void contacts_on_the_cone_edge_meet_the_lcp_conditions(void **state)
{
    static const double mus[3] = {0.3, 0.6, 1.0};
    double worstLcp = 0.0;
    int seed;
    (void)state;
    for (seed = 0; seed < 400; ++seed) {
        KtRng rng = kt_rng((uint64_t)(7100 + seed));
        KtProblem t;
        MeReal xd[3], xi[3];
        KeaStats st;
        double A[9], x[3], lcp; /* x: a solution (with friction there may be others) */
        int r, c;
        kt_random_contacts(&t, &rng, 1, 0, 2, mus[seed % 3], 1e-2);
        /* the solution chosen: n > 0, f1 = mu n on the edge, |f2| < mu n; r = A x */
        kt_dense_matrix(&t.p, A);
        x[0] = kt_range(&rng, 0.2, 1.0);
        x[1] = (double)t.mu[1] * x[0];
        x[2] = kt_range(&rng, -0.5, 0.5) * (double)t.mu[2] * x[0];
        for (r = 0; r < 3; ++r) {
            double sum = 0.0;
            for (c = 0; c < 3; ++c)
                sum += A[r * 3 + c] * x[c];
            t.rhs[r] = (MeReal)sum;
        }
        (void)iterative_vs_direct(&t, 1, xd, xi, &st);
        lcp = contact_lcp_violation(&t, xi);
        worstLcp = fmax(worstLcp, lcp);
        assert_near(lcp, 0.0, ME_TOL(1e-9, 1e-4));
        kt_free(&t);
    }
    print_message("400 contacts on the friction cone's edge, one sweep: largest LCP violation %.3g\n", worstLcp);
}

/* Random contacts with the rarer options, as BCL writes them: anisotropic friction (mu_1 != mu_2),
 * a soft normal row and slipping friction rows (their own eps), restitution and surface or world
 * velocities (the normal and friction rows' rhs), among bilateral joint rows. */
static void random_contacts_with_options(KtProblem *t, KtRng *rng, int nContacts, int nJoint, int nb)
{
    int c, k;
    kt_random_contacts(t, rng, nContacts, nJoint, nb, 0.3, 1e-2);
    for (c = 0; c < nContacts; ++c) {
        const int s = 3 * c;
        t->eps[s] = (MeReal)(kt_int(rng, 2) ? kt_range(rng, 1e-3, 1e-1) : 1e-2);    /* soft */
        for (k = 1; k < 3; ++k) {
            t->mu[s + k] = (MeReal)kt_range(rng, 0.05, 0.5);                       /* anisotropic */
            t->eps[s + k] = (MeReal)(kt_int(rng, 2) ? kt_range(rng, 1e-2, 0.5) : 1e-2); /* slip */
            t->rhs[s + k] += (MeReal)kt_range(rng, -0.5, 0.5);                     /* surface velocity */
        }
        t->rhs[s] += (MeReal)kt_range(rng, -0.3, 0.6); /* a bounce, or a contact pulling apart */
    }
}

/* The one contact step (declared contacts) and the generic rows path (the same rows, not declared)
 * solve the same LCP, on cases both solve exactly:
 *  - one contact with the rarer options, one sweep: each path's block step is exact (the contact
 *    step's closed forms or dense fallback, the generic step's all-free shortcut or dense solver),
 *    and with mu <= 0.5 on these random blocks the contact's LCP has one solution, so the two agree
 *    to rounding amplified by the block's conditioning: 1e-4 in float (rounding 6e-8 times
 *    condition numbers up to ~1e3), 1e-9 in double;
 *  - ten such contacts among joint rows, run to convergence (tolerance 0, 2000 sweeps): each path
 *    converges to the partition's solution, so they agree to the iterative path's own accuracy on
 *    these problems (friction_links_converge_to_direct's bound, 2e-3 in float, 1e-7 in double). */
static void contact_step_and_generic_rows_agree(void **state)
{
    double worstOne = 0.0, worstMany = 0.0;
    int seed;
    (void)state;
    for (seed = 0; seed < 300; ++seed) {
        KtRng rng = kt_rng((uint64_t)(11000 + seed));
        KtProblem t;
        MeReal xt[3], xg[3];
        KeaParameters iter = kt_params(KeaPathIterative);
        KeaStats st;
        double err;
        random_contacts_with_options(&t, &rng, 1, 0, 1 + seed % 2);
        iter.maxIterations = 1;
        iter.tolerance = ME_R(0.0);
        assert_int_not_equal(kt_solve(&t.p, &iter, xt, NULL, &st), KeaStatusBadInput);
        t.p.nContacts = 0;
        kt_solve(&t.p, &iter, xg, NULL, &st);
        err = relative_difference(xt, xg, 3);
        worstOne = fmax(worstOne, err);
        assert_near(err, 0.0, ME_TOL(1e-9, 1e-4));
        kt_free(&t);
    }
    for (seed = 0; seed < 20; ++seed) {
        KtRng rng = kt_rng((uint64_t)(12000 + seed));
        KtProblem t;
        MeReal xt[36], xg[36];
        KeaParameters iter = kt_params(KeaPathIterative);
        KeaStats st;
        double err;
        random_contacts_with_options(&t, &rng, 10, 6, 6);
        iter.maxIterations = 2000;
        iter.tolerance = ME_R(0.0);
        kt_solve(&t.p, &iter, xt, NULL, &st);
        assert_near(st.residual, 0.0, ME_TOL(1e-7, 1e-3));
        t.p.nContacts = 0;
        kt_solve(&t.p, &iter, xg, NULL, &st);
        assert_near(st.residual, 0.0, ME_TOL(1e-7, 1e-3));
        err = relative_difference(xt, xg, 36);
        worstMany = fmax(worstMany, err);
        assert_near(err, 0.0, ME_TOL(1e-7, 2e-3));
        kt_free(&t);
    }
    print_message("contact step vs generic rows: one contact, one sweep, max relative difference %.3g; "
                  "ten contacts to convergence %.3g\n", worstOne, worstMany);
}

/* A declared contact whose block has no factor (its two friction rows the same direction, so its
 * 3 x 3 matrix is singular without softness) skips the all-free try and goes to the active sets or
 * the dense solver; one sweep must still meet the contact's LCP conditions. */
static void contact_without_a_factor_meets_the_lcp_conditions(void **state)
{
    double worst = 0.0;
    int seed;
    (void)state;
    for (seed = 0; seed < 100; ++seed) {
        KtRng rng = kt_rng((uint64_t)(13000 + seed));
        KtProblem t;
        MeReal xd[3], xi[3];
        KeaStats st;
        double lcp;
        int r;
        kt_random_contacts(&t, &rng, 1, 0, 1 + seed % 2, 0.4, 1e-2);
        t.J[2] = t.J[1];
        for (r = 0; r < 3; ++r)
            t.eps[r] = ME_R(0.0);
        if (seed % 3 == 0)
            t.rhs[0] = (MeReal)-kt_range(&rng, 0.1, 1.0);
        (void)iterative_vs_direct(&t, 1, xd, xi, &st);
        lcp = contact_lcp_violation(&t, xi);
        worst = fmax(worst, lcp);
        assert_near(lcp, 0.0, ME_TOL(1e-8, 1e-3));
        kt_free(&t);
    }
    print_message("100 contacts without a factor, one sweep: largest LCP violation %.3g\n", worst);
}

/* A contact declaration that breaks KeaContact's promise is bad input, whatever the path: Kea does
 * not second-guess the rows, it checks what it was told. */
static void broken_contact_declarations_are_bad_input(void **state)
{
    int bad;
    (void)state;
    for (bad = 0; bad < 9; ++bad) {
        KtRng rng = kt_rng(77);
        KtProblem t;
        MeReal x[9];
        KeaContact two[2] = {{0}, {2}};
        KeaParameters prm = kt_params(bad % 2 ? KeaPathDirect : KeaPathIterative);
        KeaStats st;
        kt_random_contacts(&t, &rng, 3, 0, 3, 0.4, 1e-2);
        kt_declare_contacts(&t, 3);
        assert_int_not_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
        switch (bad) {
        case 0: t.contacts[1].row = 7; break;                 /* past the last row */
        case 1: t.p.contacts = two; t.p.nContacts = 2; break; /* overlapping */
        case 2: t.lo[3] = ME_R(-1.0); break;                  /* adhesive normal row */
        case 3: t.hi[3] = ME_R(5.0); break;                   /* capped normal row */
        case 4: t.link[4] = -1; break;                        /* friction row not linked */
        case 5: t.hi[5] = ME_R(1.0); break;                   /* box-bounded friction row */
        case 6: t.rowBodies[4][1] = t.rowBodies[3][0] == 0 ? 1 : 0; break; /* another body pair */
        case 7: t.rowBodies[3][0] = t.rowBodies[4][0] = t.rowBodies[5][0] = KEA_WORLD; break;
        default: t.p.link = NULL; break;                      /* contacts need links */
        }
        assert_int_equal(kt_solve(&t.p, &prm, x, NULL, &st), KeaStatusBadInput);
        kt_free(&t);
    }
}

/* Over-relaxation changes the path, not the limit. */
static void sor_converges_to_the_same_solution(void **state)
{
    KtProblem t;
    MeReal xd[36], xi[36];
    KeaParameters direct = kt_params(KeaPathDirect), iter = kt_params(KeaPathIterative);
    KeaStats st;
    int i;
    (void)state;
    make_problem(&t, 3);
    assert_int_equal(kt_solve(&t.p, &direct, xd, NULL, &st), KeaStatusOk);
    iter.sor = ME_R(1.3);
    iter.maxBlockRows = 1;
    iter.subspaceIterations = 0;
    iter.maxIterations = 3000;
    iter.tolerance = ME_R(0.0);
    kt_solve(&t.p, &iter, xi, NULL, &st);
    for (i = 0; i < 36; ++i)
        assert_near(xi[i], xd[i], ME_TOL(1e-8, 2e-3) * (1.0 + fabs((double)xd[i])));
    kt_free(&t);
}

/* A loose tolerance stops the sweeps early and says so. */
static void tolerance_stops_early(void **state)
{
    KtProblem t;
    MeReal x[36];
    KeaParameters iter = kt_params(KeaPathIterative);
    KeaStats st;
    (void)state;
    make_problem(&t, 5);
    iter.maxIterations = 1000;
    iter.tolerance = ME_R(1e-3);
    assert_int_equal(kt_solve(&t.p, &iter, x, NULL, &st), KeaStatusOk);
    assert_true(st.iterations > 1 && st.iterations < 1000);
    iter.tolerance = ME_R(0.0);
    iter.maxIterations = 3;
    assert_int_equal(kt_solve(&t.p, &iter, x, NULL, &st), KeaStatusMaxIterations);
    assert_int_equal(st.iterations, 3);
    assert_int_equal(st.subspaceSteps > 0, 1);
    kt_free(&t);
}

/* The extra effort (KeaParameters.effortResidual): a threshold no sweep reaches adds two sweeps at a
 * time, SM between, up to KEA_EFFORT_FACTOR times the cap, which is the same sequence as a cap that
 * many sweeps higher, bit for bit; a threshold every sweep is within adds none; one in between stops
 * at the first round whose last sweep is within it, with a smaller residual than the cap alone. */
static void extra_effort_sweeps_on_while_the_residual_is_high(void **state)
{
    KtProblem t;
    MeReal plain[36], longer[36], effort[36];
    KeaParameters iter = kt_params(KeaPathIterative);
    KeaStats st, stLonger, stPlain;
    int i;
    (void)state;
    make_problem(&t, 11);
    iter.tolerance = ME_R(0.0);
    iter.maxIterations = 3;
    assert_true(iter.effortResidual == ME_R(0.0)); /* Kea's own default: none */
    kt_solve(&t.p, &iter, plain, NULL, &stPlain);
    assert_int_equal(stPlain.iterations, 3);
    assert_int_equal(stPlain.effortRounds, 0);
    iter.maxIterations = 3 * (1 + KEA_EFFORT_FACTOR);
    kt_solve(&t.p, &iter, longer, NULL, &stLonger);
    iter.maxIterations = 3;
    iter.effortResidual = ME_R(1e-30);
    kt_solve(&t.p, &iter, effort, NULL, &st);
    assert_int_equal(st.iterations, 3 * (1 + KEA_EFFORT_FACTOR));
    assert_int_equal(st.effortRounds, 3 * KEA_EFFORT_FACTOR / 2);
    for (i = 0; i < 36; ++i)
        assert_true(effort[i] == longer[i]);
    iter.effortResidual = ME_R(1e30);
    kt_solve(&t.p, &iter, effort, NULL, &st);
    assert_int_equal(st.iterations, 3);
    for (i = 0; i < 36; ++i)
        assert_true(effort[i] == plain[i]);
    iter.effortResidual = ME_R(0.5) * (stPlain.residual + stLonger.residual);
    kt_solve(&t.p, &iter, effort, NULL, &st);
    print_message("effort at %g: %d sweeps, residual %g (cap alone %g, three times the cap %g)\n",
                  (double)iter.effortResidual, st.iterations, (double)st.residual, (double)stPlain.residual,
                  (double)stLonger.residual);
    assert_true(st.iterations > 3 && st.iterations <= 3 * (1 + KEA_EFFORT_FACTOR) && st.iterations % 2 == 1);
    assert_true(st.residual < stPlain.residual);
    kt_free(&t);
}

/* make_problem(seed)'s 36 rows among n more blocks that one sweep solves for good: a row of its own
 * on a body of its own, against the world. */
static void make_problem_among_converged(KtProblem *t, int seed, int n)
{
    KtProblem base;
    KtRng rng = kt_rng(77);
    int i, k;
    make_problem(&base, seed);
    kt_alloc(t, 36 + n, 8 + n, 0);
    memcpy(t->bodies, base.bodies, 8 * sizeof(KeaBody));
    memcpy(t->J, base.J, 36 * sizeof(KeaJacobianRow));
    memcpy(t->rowBodies, base.rowBodies, 36 * sizeof(int[2]));
    memcpy(t->eps, base.eps, 36 * sizeof(MeReal));
    memcpy(t->rhs, base.rhs, 36 * sizeof(MeReal));
    memcpy(t->lo, base.lo, 36 * sizeof(MeReal));
    memcpy(t->hi, base.hi, 36 * sizeof(MeReal));
    for (k = 0; k < n; ++k) {
        i = 36 + k;
        kt_random_body(&rng, &t->bodies[8 + k]);
        t->rowBodies[i][0] = 8 + k;
        t->rowBodies[i][1] = KEA_WORLD;
        t->J[i].lin0[k % 3] = ME_R(1.0);
        t->eps[i] = ME_R(1e-3);
        t->rhs[i] = (MeReal)kt_range(&rng, -1, 1);
        t->lo[i] = -MEINFINITY;
        t->hi[i] = MEINFINITY;
    }
    kt_free(&base);
}

/* The extra effort adds a round only while more than KEA_EFFORT_FRACTION of the blocks are above its
 * threshold (a settled pile's few wandering rows do not converge under it): make_problem's 12 blocks,
 * unconverged after 3 sweeps, among 600 converged ones are at most 2 % of the blocks, and the solve
 * stops at the cap, bit for bit as without the effort; among 40 they are more, and it sweeps on. */
static void extra_effort_only_while_many_blocks_are_unconverged(void **state)
{
    const int sizes[2] = {600, 40};
    int s, i;
    (void)state;
    for (s = 0; s < 2; ++s) {
        KtProblem t;
        KeaParameters iter = kt_params(KeaPathIterative);
        KeaStats st, stPlain;
        MeReal *plain, *effort;
        make_problem_among_converged(&t, 11, sizes[s]);
        plain = malloc(sizeof(MeReal) * (size_t)t.p.nRows);
        effort = malloc(sizeof(MeReal) * (size_t)t.p.nRows);
        assert_non_null(plain);
        assert_non_null(effort);
        iter.tolerance = ME_R(0.0);
        iter.subspaceIterations = 0;
        iter.maxIterations = 3;
        kt_solve(&t.p, &iter, plain, NULL, &stPlain);
        iter.effortResidual = ME_R(1e-3) * stPlain.residual; /* far above a converged row's rounding */
        kt_solve(&t.p, &iter, effort, NULL, &st);
        print_message("%d rows: cap alone residual %g; with the effort %d sweeps, residual %g\n", t.p.nRows,
                      (double)stPlain.residual, st.iterations, (double)st.residual);
        if (s == 0) {
            assert_int_equal(st.iterations, 3);
            assert_int_equal(st.effortRounds, 0);
            for (i = 0; i < t.p.nRows; ++i)
                assert_true(kt_same_bits(effort[i], plain[i]));
        } else {
            assert_true(st.effortRounds > 0);
            assert_true(st.residual < stPlain.residual);
        }
        free(plain);
        free(effort);
        kt_free(&t);
    }
}

/* The extra effort only for a partition at rest (KeaParameters.effortRestSpeed): with a rest speed
 * below the problem's largest |rhs| (a row that must change its velocity fast: bodies colliding or
 * sliding) the solve stops at the cap, bit for bit as without the effort; with one at that largest
 * |rhs| (every row within it) it sweeps on as before. */
static void extra_effort_only_where_the_partition_rests(void **state)
{
    KtProblem t;
    MeReal plain[36], longer[36], effort[36];
    KeaParameters iter = kt_params(KeaPathIterative);
    KeaStats st;
    MeReal largest = ME_R(0.0);
    int i;
    (void)state;
    make_problem(&t, 11);
    for (i = 0; i < t.p.nRows; ++i)
        if ((MeReal)fabs((double)t.p.rhs[i]) > largest)
            largest = (MeReal)fabs((double)t.p.rhs[i]);
    assert_true(largest > ME_R(0.0));
    assert_true(iter.effortRestSpeed == ME_R(0.0)); /* Kea's own default: no limit */
    iter.tolerance = ME_R(0.0);
    iter.maxIterations = 3;
    kt_solve(&t.p, &iter, plain, NULL, &st);
    iter.maxIterations = 3 * (1 + KEA_EFFORT_FACTOR);
    kt_solve(&t.p, &iter, longer, NULL, &st);
    iter.maxIterations = 3;
    iter.effortResidual = ME_R(1e-30);
    iter.effortRestSpeed = ME_R(0.999) * largest;
    kt_solve(&t.p, &iter, effort, NULL, &st);
    assert_int_equal(st.iterations, 3);
    assert_int_equal(st.effortRounds, 0);
    for (i = 0; i < 36; ++i)
        assert_true(effort[i] == plain[i]);
    iter.effortRestSpeed = largest;
    kt_solve(&t.p, &iter, effort, NULL, &st);
    assert_int_equal(st.iterations, 3 * (1 + KEA_EFFORT_FACTOR));
    for (i = 0; i < 36; ++i)
        assert_true(effort[i] == longer[i]);
    kt_free(&t);
}

/* Warm-started from the exact solution, one sweep changes nothing and reports convergence. */
static void warm_start_at_solution_stays(void **state)
{
    KtProblem t;
    MeReal xd[36], xi[36];
    KeaParameters direct = kt_params(KeaPathDirect), iter = kt_params(KeaPathIterative);
    KeaStats st;
    int i;
    (void)state;
    make_problem(&t, 8);
    assert_int_equal(kt_solve(&t.p, &direct, xd, NULL, &st), KeaStatusOk);
    for (i = 0; i < 36; ++i)
        t.x0[i] = xd[i];
    t.p.x0 = t.x0;
    iter.tolerance = ME_TOL(1e-9, 1e-4);
    assert_int_equal(kt_solve(&t.p, &iter, xi, NULL, &st), KeaStatusOk);
    assert_int_equal(st.iterations, 1);
    for (i = 0; i < 36; ++i)
        assert_near(xi[i], xd[i], ME_TOL(1e-9, 1e-4) * (1.0 + fabs((double)xd[i])));
    kt_free(&t);
}

/* Subspace minimisation waits for the active set: a column of 20 boxes started cold (every normal
 * row at its bound, most of them freed by the first sweeps) skips some SM steps, never two in a
 * row; the same column warm-started at its solution skips none, and both reach the same x. */
static void subspace_steps_wait_for_the_active_set(void **state)
{
    enum { BOXES = 20, N = 12 * BOXES };
    static const double gravity[3] = {0, 0, -9.81};
    const double v[6 * BOXES] = {0};
    KtProblem t;
    MeReal xd[N], xi[N];
    KeaParameters direct = kt_params(KeaPathDirect), iter = kt_params(KeaPathIterative);
    KeaStats st;
    int i;
    (void)state;
    kt_column(&t, BOXES, 1.0, 0.6, 1e-2);
    kt_set_rhs_from_velocities(&t, v, 1.0 / 60, gravity);
    assert_int_equal(kt_solve(&t.p, &direct, xd, NULL, &st), KeaStatusOk);
    iter.maxIterations = 3000;
    iter.tolerance = ME_TOL(1e-9, 1e-5);
    kt_solve(&t.p, &iter, xi, NULL, &st); /* cold: x0 = 0 */
    print_message("column of %d, cold start: %d sweeps, %d SM steps, %d skipped\n", BOXES, st.iterations,
                  st.subspaceSteps, st.subspaceSkipped);
    assert_true(st.subspaceSkipped >= 1);
    assert_true(st.subspaceSkipped <= (st.iterations + 1) / 2); /* SM paid: never twice in a row */
    for (i = 0; i < N; ++i)
        assert_near(xi[i], xd[i], ME_TOL(1e-5, 2e-2) * (1.0 + fabs((double)xd[i])));
    for (i = 0; i < N; ++i)
        t.x0[i] = xd[i];
    t.p.x0 = t.x0;
    iter.maxIterations = 10;
    kt_solve(&t.p, &iter, xi, NULL, &st);
    print_message("column of %d, warm start at the solution: %d sweeps, %d skipped\n", BOXES, st.iterations,
                  st.subspaceSkipped);
    assert_int_equal(st.subspaceSkipped, 0);
    kt_free(&t);
}

/* An SM step must pay for itself: on random contact partitions (300 contacts on 150 bodies, cold),
 * whose active set keeps changing, an SM step that lowers the objective less than the sweep after
 * it makes the next ones wait for the active set to settle, so that at the default 10 sweeps more
 * than half of the chances are skipped (the "active set still moving" rule alone skips at most
 * every other one); given 1000 sweeps, the active set settles, SM runs again and the residual
 * falls to about the default tolerance, as it did without the rule (seed 3 of this generator stays
 * far from it after 1000 sweeps with or without the rule and is left out). */
static void subspace_steps_that_do_not_pay_wait(void **state)
{
    static const int seeds[3] = {1, 2, 4};
    int k;
    (void)state;
    for (k = 0; k < 3; ++k) {
        KtRng r = kt_rng((uint64_t)seeds[k]);
        KtProblem t;
        MeReal *xi;
        KeaParameters iter = kt_params(KeaPathIterative);
        KeaStats st;
        kt_random_contacts(&t, &r, 300, 0, 150, 0.6, 1e-2);
        xi = malloc(sizeof(MeReal) * (size_t)t.p.nRows);
        assert_non_null(xi);
        kt_solve(&t.p, &iter, xi, NULL, &st);
        print_message("random contacts, seed %d, 10 sweeps: %d SM steps, %d of %d chances skipped\n", seeds[k],
                      st.subspaceSteps, st.subspaceSkipped, st.iterations - 1);
        assert_true(2 * st.subspaceSkipped > st.iterations - 1);
        iter.maxIterations = 1000;
        kt_solve(&t.p, &iter, xi, NULL, &st);
        print_message("  to convergence: %d sweeps, %d SM steps, residual %.2g\n", st.iterations,
                      st.subspaceSteps, (double)st.residual);
        assert_near(st.residual, 0.0, 1e-5); /* the default tolerance is 1e-6 */
        free(xi);
        kt_free(&t);
    }
}


/* NNCG (KeaParameters.nonsmoothCg, kea_nncg.c): its momentum steps change the path, not the limit.
 * A column of 20 boxes started cold (the chain along which plain sweeps carry the load one box a
 * sweep) reaches the direct path's solution with NNCG alone and with NNCG and SM at every second
 * chance; at a budget of 40 sweeps without SM, NNCG's objective gap to the solution is well below
 * plain PGS's (the acceleration it is for); and the impulses returned are within their bounds (the
 * solve ends on a sweep), with the velocity change they imply (dv kept beside the momentum). The
 * coarse correction (KeaParameters.deflation, kea_deflation.c) in NNCG's place reaches the same
 * solution and, at 40 sweeps without SM, a smaller gap than NNCG's. */
static void nncg_converges_faster_to_the_same_solution(void **state)
{
    enum { BOXES = 20, N = 12 * BOXES };
    static const double gravity[3] = {0, 0, -9.81};
    const double v[6 * BOXES] = {0};
    KtProblem t;
    MeReal xd[N], xi[N];
    static double A[N * N];
    KeaParameters direct = kt_params(KeaPathDirect), iter = kt_params(KeaPathIterative);
    KeaStats st;
    double fStar, gap[3];
    int i, k;
    (void)state;
    kt_column(&t, BOXES, 1.0, 0.6, 1e-2);
    kt_set_rhs_from_velocities(&t, v, 1.0 / 60, gravity);
    kt_dense_matrix(&t.p, A);
    assert_int_equal(kt_solve(&t.p, &direct, xd, NULL, &st), KeaStatusOk);
    fStar = kt_objective(N, A, t.rhs, xd);
    for (k = 0; k < 3; ++k) { /* the third: deflation (kea_deflation.c) in NNCG's place, SM every 2nd */
        iter.nonsmoothCg = 1;
        iter.deflation = k == 2;
        iter.subspaceIterations = k == 0 ? 0 : 4;
        iter.subspaceEvery = 2;
        iter.maxIterations = 3000;
        iter.tolerance = ME_TOL(1e-9, 1e-5);
        kt_solve(&t.p, &iter, xi, NULL, &st);
        print_message("column of %d, cold, %s: %d sweeps, residual %.2g\n", BOXES,
                      k == 0 ? "NNCG" : (k == 1 ? "NNCG + SM every 2nd" : "deflation + SM every 2nd"),
                      st.iterations, (double)st.residual);
        assert_true(st.residual <= 10 * iter.tolerance); /* the stop measures rows before their step */
        for (i = 0; i < N; ++i)
            assert_near(xi[i], xd[i], ME_TOL(1e-5, 2e-2) * (1.0 + fabs((double)xd[i])));
    }
    for (k = 0; k < 3; ++k) {
        iter = kt_params(KeaPathIterative);
        iter.nonsmoothCg = k > 0;
        iter.deflation = k == 2;
        iter.subspaceIterations = 0;
        iter.maxIterations = 40;
        iter.tolerance = ME_R(0.0);
        kt_solve(&t.p, &iter, xi, NULL, &st);
        gap[k] = kt_objective(N, A, t.rhs, xi) - fStar;
        assert_true(st.residual < ME_R(1.0)); /* measured on x and dv as returned: bounded, finite */
        for (i = 0; i < N; ++i) {
            MeReal lo, hi;
            KeaRowBounds(&t.p, xi, i, &lo, &hi);
            assert_true(xi[i] >= lo && xi[i] <= hi);
        }
    }
    print_message("column of %d, 40 sweeps without SM: objective gap PGS %.3g, NNCG %.3g, deflation %.3g\n", BOXES,
                  gap[0], gap[1], gap[2]);
    assert_true(gap[1] < 0.5 * gap[0]);
    assert_true(gap[2] < gap[1]);
    kt_free(&t);
}


/* The largest gap between the solve's dv and M^-1 J^T x recomputed from the returned x, in double,
 * as a fraction of the largest |dv| component. */
static double dv_gap_to_impulses(const KtProblem *t, const MeReal *x, const KeaBodyVelocity *dv)
{
    double *want = calloc((size_t)(6 * t->p.nBodies), sizeof(double)), gap = 0.0, size = 0.0;
    int i, h, b, r, c;
    assert_non_null(want);
    for (i = 0; i < t->p.nRows; ++i)
        for (h = 0; h < 2; ++h) {
            const KeaBody *body;
            const MeReal *lin = h ? t->J[i].lin1 : t->J[i].lin0, *ang = h ? t->J[i].ang1 : t->J[i].ang0;
            if ((b = t->rowBodies[i][h]) < 0)
                continue;
            body = &t->bodies[b];
            for (r = 0; r < 3; ++r) {
                want[6 * b + r] += (double)body->invMass * (double)lin[r] * (double)x[i];
                for (c = 0; c < 3; ++c)
                    want[6 * b + 3 + r] += (double)body->invInertia[r][c] * (double)ang[c] * (double)x[i];
            }
        }
    for (b = 0; b < t->p.nBodies; ++b)
        for (r = 0; r < 3; ++r) {
            gap = fmax(gap, fabs((double)dv[b].lin[r] - want[6 * b + r]));
            gap = fmax(gap, fabs((double)dv[b].ang[r] - want[6 * b + 3 + r]));
            size = fmax(size, fmax(fabs(want[6 * b + r]), fabs(want[6 * b + 3 + r])));
        }
    free(want);
    return gap / size;
}

/* The velocity change a solve returns is the one its impulses make, dv = M^-1 J^T x, however long it
 * runs: SM's accepted steps move dv by CG's step scattered a direction at a time plus the rows a
 * bound clamped (kea_subspace.c, KeaTrialStep), and the coarse correction by a scatter of the rows it
 * moved, not by its directions' images, whose rounding added up over a long solve. Random contacts
 * (friction clamps rows in SM's line search) run to convergence with SM at every chance, and the
 * cold column with deflation and SM at every second chance, for 3000 sweeps without a stop. */
static void solves_keep_dv_the_impulses_velocity_change(void **state)
{
    enum { COLUMN_BOXES = 20 };
    static const double gravity[3] = {0, 0, -9.81};
    const double still[6 * COLUMN_BOXES] = {0};
    int seed;
    (void)state;
    for (seed = 1; seed <= 3; ++seed) {
        KtRng r = kt_rng((uint64_t)seed);
        KtProblem t;
        MeReal *x;
        KeaBodyVelocity *dv;
        KeaParameters iter = kt_params(KeaPathIterative);
        KeaStats st;
        double gap;
        if (seed < 3) {
            kt_random_contacts(&t, &r, 300, 0, 150, 0.6, 1e-2);
            iter.maxIterations = 1000;
            iter.subspaceEvery = 1;
        } else {
            kt_column(&t, COLUMN_BOXES, 1.0, 0.6, 1e-2);
            kt_set_rhs_from_velocities(&t, still, 1.0 / 60, gravity);
            iter.nonsmoothCg = 1;
            iter.deflation = 1;
            iter.subspaceIterations = 4;
            iter.subspaceEvery = 2;
            iter.maxIterations = 3000;
            iter.tolerance = ME_R(0.0);
        }
        x = malloc(sizeof(MeReal) * (size_t)t.p.nRows);
        dv = malloc(sizeof(KeaBodyVelocity) * (size_t)t.p.nBodies);
        assert_non_null(x);
        assert_non_null(dv);
        kt_solve(&t.p, &iter, x, dv, &st);
        gap = dv_gap_to_impulses(&t, x, dv);
        print_message("%s: %d sweeps, %d SM steps, dv's gap to M^-1 J^T x %.2g of its size\n",
                      seed < 3 ? "random contacts" : "cold column, deflation", st.iterations, st.subspaceSteps, gap);
        assert_true(st.subspaceSteps > 0);
        assert_true(gap < ME_TOL(1e-10, 1e-4));
        free(x);
        free(dv);
        kt_free(&t);
    }
}

enum { SM_BOXES = 20, SM_ROWS = 12 * SM_BOXES };

/* The cold column of SM_BOXES boxes at rest under gravity, and its direct solution xd. */
static void cold_column_solved(KtProblem *t, MeReal *xd)
{
    static const double g[3] = {0, 0, -9.81}, still[6 * SM_BOXES];
    KeaParameters exact = kt_params(KeaPathDirect);
    KeaStats stats;
    kt_column(t, SM_BOXES, 1.0, 0.6, 1e-2);
    kt_set_rhs_from_velocities(t, still, 1.0 / 60, g);
    assert_int_equal(kt_solve(&t->p, &exact, xd, NULL, &stats), KeaStatusOk);
}

/* SM's schedule (KeaParameters.subspaceEvery, subspaceStop; the world's, decision K55): SM after the
 * first sweep and every second one, CG stopped once r.z has fallen tenfold. On the cold column of 20
 * boxes the first chance comes (after sweep 1, before sweep 2: run or skipped) and, run to
 * convergence with or without the stop, the schedule reaches the direct path's solution: the stop
 * changes the path, not the limit. On random contact partitions at 10 sweeps the stop ends CG runs
 * before their 7 steps. */
static void sm_first_chance_and_early_stop_keep_the_limit(void **state)
{
    MeReal xd[SM_ROWS], xi[SM_ROWS];
    KtProblem t;
    KeaParameters iter;
    KeaStats st;
    int i, k, steps[2];
    (void)state;
    cold_column_solved(&t, xd);
    for (k = 0; k < 2; ++k) { /* without and with the stop */
        iter = kt_params(KeaPathIterative);
        iter.nonsmoothCg = 1;
        iter.subspaceEvery = 2;
        iter.subspaceIterations = 7;
        iter.subspaceStop = k ? ME_R(0.1) : ME_R(0.0);
        iter.maxIterations = 2;
        iter.tolerance = ME_R(0.0);
        kt_solve(&t.p, &iter, xi, NULL, &st);
        assert_true(st.subspaceSteps + st.subspaceSkipped > 0); /* the first chance came (ran or skipped) */
        iter.maxIterations = 3000;
        iter.tolerance = ME_TOL(1e-9, 1e-5);
        kt_solve(&t.p, &iter, xi, NULL, &st);
        assert_true(st.residual <= 10 * iter.tolerance);
        for (i = 0; i < SM_ROWS; ++i)
            assert_near(xi[i], xd[i], ME_TOL(1e-5, 2e-2) * (1.0 + fabs((double)xd[i])));
    }
    kt_free(&t);
    steps[0] = steps[1] = 0;
    for (i = 0; i < 10; ++i) /* random contact partitions, 10 sweeps: the stop saves CG steps */
        for (k = 0; k < 2; ++k) {
            KtRng rng = kt_rng((uint64_t)(900 + i));
            kt_random_contacts(&t, &rng, 30, 0, 12, 0.5, 1e-2);
            iter = kt_params(KeaPathIterative);
            iter.subspaceEvery = 2;
            iter.subspaceIterations = 7;
            iter.subspaceStop = k ? ME_R(0.1) : ME_R(0.0);
            iter.tolerance = ME_R(0.0);
            kt_solve(&t.p, &iter, xi, NULL, &st);
            steps[k] += st.subspaceSteps;
            kt_free(&t);
        }
    print_message("random contacts, 10 sweeps: %d CG steps without the stop, %d with\n", steps[0], steps[1]);
    assert_true(steps[1] < steps[0]);
}

/* The world's schedule with subspaceJointShare and subspaceJointEvery (decision K58): a partition whose
 * generic rows (joints) are at least that share of its rows gets SM at the first chance and every eighth
 * sweep (two chances in 10 sweeps), and run to convergence still reaches the full schedule's solution; a
 * partition of contacts alone keeps the full schedule,
 * bit for bit. */
static MeReal joint_heavy_solve(const KtProblem *t, MeReal share, int maxIterations, MeReal *x, KeaStats *st)
{
    KeaParameters iter = kt_params(KeaPathIterative);
    iter.nonsmoothCg = 1;
    iter.subspaceEvery = 2;
    iter.subspaceIterations = 7;
    iter.subspaceJointShare = share;
    iter.subspaceJointEvery = 8;
    iter.maxIterations = maxIterations;
    iter.tolerance = maxIterations > 10 ? ME_TOL(1e-9, 1e-5) : ME_R(0.0);
    kt_solve(&t->p, &iter, x, NULL, st);
    return iter.tolerance;
}

static void joint_heavy_partitions_get_sm_once(void **state)
{
    enum { CONTACTS = 10, JOINT_ROWS = 30, N = 3 * CONTACTS + JOINT_ROWS };
    MeReal x[N], xFull[N], xd[N];
    KtProblem t;
    KeaStats st;
    int seed, i, steps[2] = {0, 0};
    (void)state;
    for (seed = 0; seed < 10; ++seed) {
        KtRng rng = kt_rng((uint64_t)(950 + seed));
        MeReal tolerance;
        kt_random_contacts(&t, &rng, CONTACTS, JOINT_ROWS, 8, 0.5, 1e-2);
        joint_heavy_solve(&t, ME_R(0.0), 10, xFull, &st);
        steps[0] += st.subspaceSteps;
        joint_heavy_solve(&t, ME_R(0.6), 10, x, &st); /* half the rows generic: below the share */
        assert_memory_equal(x, xFull, sizeof x);
        joint_heavy_solve(&t, ME_R(0.25), 10, x, &st);
        assert_true(st.subspaceSteps <= 2 * 7 && st.subspaceSkipped <= 2); /* after sweeps 1 and 8 */
        steps[1] += st.subspaceSteps;
        tolerance = joint_heavy_solve(&t, ME_R(0.0), 3000, xd, &st);
        assert_true(st.residual <= 10 * tolerance);
        tolerance = joint_heavy_solve(&t, ME_R(0.25), 3000, x, &st);
        assert_true(st.residual <= 10 * tolerance);
        for (i = 0; i < N; ++i)
            assert_near(x[i], xd[i], ME_TOL(1e-5, 2e-2) * (1.0 + fabs((double)xd[i])));
        kt_free(&t);
        kt_random_contacts(&t, &rng, CONTACTS, 0, 8, 0.5, 1e-2); /* contacts only: the same bits */
        joint_heavy_solve(&t, ME_R(0.0), 10, xFull, &st);
        joint_heavy_solve(&t, ME_R(0.25), 10, x, &st);
        assert_memory_equal(x, xFull, sizeof(MeReal) * 3 * CONTACTS);
        kt_free(&t);
    }
    print_message("joint-heavy partitions, 10 sweeps: %d CG steps with the full schedule, %d after sweeps 1 and 8\n",
                  steps[0], steps[1]);
    assert_true(steps[1] > 0 && steps[1] < steps[0]);
}

/* A caller that proved its rows (KeaSolveRowsProved: J's pads and world halves zero, as the column's
 * are) gets the solve of KeaSolveSized bit for bit, J read in place instead of copied; a row it would
 * have had to check (a NaN rhs) is then the caller's to catch: the same problem through
 * KeaSolveSized is bad input. */
static void proved_rows_solve_as_checked_rows(void **state)
{
    (void)state;
    const double v[6 * 12] = {0}, gravity[3] = {0, 0, -9.81};
    KtProblem t;
    KeaParameters params = kt_params(KeaPathIterative);
    kt_column(&t, 12, 1.0, 0.5, 1e-3);
    kt_set_rhs_from_velocities(&t, v, 0.01, gravity);
    const int n = t.p.nRows, nb = t.p.nBodies;
    const size_t bytes = KeaMemoryRequired(n, nb, KeaPathIterative);
    void *work = malloc(bytes);
    MeReal *x[2] = {calloc((size_t)n, sizeof(MeReal)), calloc((size_t)n, sizeof(MeReal))};
    KeaBodyVelocity *dv[2] = {calloc((size_t)nb, sizeof(KeaBodyVelocity)), calloc((size_t)nb, sizeof(KeaBodyVelocity))};
    KeaStats stats[2];
    const KeaStatus checked = KeaSolveSized(&t.p, &params, work, bytes, x[0], dv[0], &stats[0]);
    assert_true(checked == KeaStatusOk || checked == KeaStatusMaxIterations);
    assert_int_equal(KeaSolveRowsProved(&t.p, &params, work, bytes, x[1], dv[1], &stats[1]), checked);
    for (int i = 0; i < n; ++i)
        assert_true(kt_same_bits(x[0][i], x[1][i]));
    for (int b = 0; b < nb; ++b)
        for (int k = 0; k < 3; ++k)
            assert_true(kt_same_bits(dv[0][b].lin[k], dv[1][b].lin[k]) &&
                        kt_same_bits(dv[0][b].ang[k], dv[1][b].ang[k]));
    assert_true(kt_same_bits(stats[0].residual, stats[1].residual));
    assert_true(stats[0].residual > ME_R(0.0));
    t.rhs[7] = (MeReal)NAN;
    assert_int_equal(KeaSolveSized(&t.p, &params, work, bytes, x[0], dv[0], &stats[0]), KeaStatusBadInput);
    free(work);
    for (int k = 0; k < 2; ++k) {
        free(x[k]);
        free(dv[k]);
    }
    kt_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(error_does_not_grow_with_iteration_cap),
        cmocka_unit_test(sm_first_chance_and_early_stop_keep_the_limit),
        cmocka_unit_test(joint_heavy_partitions_get_sm_once),
        cmocka_unit_test(friction_links_converge_to_direct),
        cmocka_unit_test(one_contact_block_is_exact_in_one_sweep),
        cmocka_unit_test(generic_contact_path_is_exact_in_one_sweep),
        cmocka_unit_test(joint_limit_block_is_exact_in_one_sweep),
        cmocka_unit_test(contacts_on_the_cone_edge_meet_the_lcp_conditions),
        cmocka_unit_test(contact_step_and_generic_rows_agree),
        cmocka_unit_test(contact_without_a_factor_meets_the_lcp_conditions),
        cmocka_unit_test(broken_contact_declarations_are_bad_input),
        cmocka_unit_test(sor_converges_to_the_same_solution),
        cmocka_unit_test(tolerance_stops_early),
        cmocka_unit_test(extra_effort_sweeps_on_while_the_residual_is_high),
        cmocka_unit_test(extra_effort_only_while_many_blocks_are_unconverged),
        cmocka_unit_test(extra_effort_only_where_the_partition_rests),
        cmocka_unit_test(warm_start_at_solution_stays),
        cmocka_unit_test(subspace_steps_wait_for_the_active_set),
        cmocka_unit_test(subspace_steps_that_do_not_pay_wait),
        cmocka_unit_test(nncg_converges_faster_to_the_same_solution),
        cmocka_unit_test(solves_keep_dv_the_impulses_velocity_change),
        cmocka_unit_test(proved_rows_solve_as_checked_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
