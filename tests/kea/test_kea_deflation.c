/* test_kea_deflation.c -- the coarse correction of Kea's iterative path (kea_deflation.c,
 * KeaParameters.deflation): its k x k solve drops a direction that adds nothing new; each step on a
 * random contact LCP, between real sweeps, never raises the QP objective f(x) = 1/2 x^T A x - r^T x,
 * keeps x within the bounds as they stood and keeps dv = M^-1 J^T x (a cold column of boxes solved
 * with it: test_kea_iterative, NNCG's test). f in double from the test's dense A. */
#include "karma_test.h"

#include <string.h>

#include "kea_test_problems.h"
#include "mdt/kea/kea_iterative.h"

/* G alpha = -g on an SPD 3 x 3 is solved; with the third direction the first again, it is dropped
 * (alpha_2 = 0) and the first two solved alone. */
/* alpha solves G alpha = -g (G row-major, 3 x 3) over its first k rows and columns. */
static void assertSolves(const MeReal G[9], const MeReal g[3], const MeReal alpha[3], int k)
{
    for (int i = 0; i < k; ++i) {
        double s = (double)g[i];
        for (int j = 0; j < k; ++j)
            s += (double)G[3 * i + j] * (double)alpha[j];
        assert_near(s, 0.0, ME_TOL(1e-12, 1e-5));
    }
}

static void deflation_solve_drops_dependent_directions(void **state)
{
    const MeReal G[9] = {4, 1, 0.5, 1, 3, 0.25, 0.5, 0.25, 2}, g[3] = {1, -2, 0.5};
    const MeReal Gd[9] = {4, 1, 4, 1, 3, 1, 4, 1, 4};
    MeReal alpha[3];
    (void)state;
    assert_int_equal(KeaDeflationSolve(3, G, g, alpha), 3);
    assertSolves(G, g, alpha, 3);
    assert_int_equal(KeaDeflationSolve(3, Gd, g, alpha), 2);
    assert_true(alpha[2] == ME_R(0.0));
    assertSolves(Gd, g, alpha, 2);
    assert_int_equal(KeaDeflationSolve(1, Gd, g, alpha), 1);
    assert_near(alpha[0], -0.25, 1e-6);
}

/* The work's fields the correction reads, from the problem: J with the world's halves zeroed, B =
 * M^-1 J^T, the bodies (the world nb), eps, invDiag (not 0: a row may be free), SM's scratch z, q, lo, hi. */
static void make_work(const KeaProblem *p, KeaIterativeWork *w)
{
    const int n = p->nRows, nb = p->nBodies;
    int i, h, k, c;
    memset(w, 0, sizeof *w);
    w->nb = nb;
    w->paddedJ = calloc((size_t)n, sizeof(KeaJacobianRow));
    w->J = w->paddedJ;
    w->B = calloc((size_t)n, sizeof(KeaJacobianRow));
    w->body = calloc((size_t)n, sizeof(int[2]));
    w->eps = calloc((size_t)n, sizeof(MeReal));
    w->invDiag = calloc((size_t)n, sizeof(MeReal));
    w->xPrev = calloc((size_t)n, sizeof(MeReal));
    w->nncgDir = calloc((size_t)n, sizeof(MeReal));
    w->xStart = calloc((size_t)n, sizeof(MeReal));
    w->z = calloc((size_t)n, sizeof(MeReal));
    w->q = calloc((size_t)n, sizeof(MeReal));
    w->lo = calloc((size_t)n, sizeof(MeReal));
    w->hi = calloc((size_t)n, sizeof(MeReal));
    w->dv = aligned_alloc(16, sizeof(KeaVel4) * (size_t)(nb + 1) * 6);
    assert_non_null(w->dv);
    memset(w->dv, 0, sizeof(KeaVel4) * (size_t)(nb + 1) * 6);
    w->dvTmp = w->dv + (nb + 1);
    w->dvPrev = w->dv + 2 * (nb + 1);
    w->dvDir = w->dv + 3 * (nb + 1);
    w->dvStart = w->dv + 4 * (nb + 1);
    for (i = 0; i < n; ++i) {
        w->eps[i] = p->epsilon ? p->epsilon[i] : ME_R(0.0);
        w->invDiag[i] = ME_R(1.0); /* every row may be free */
        for (h = 0; h < 2; ++h) {
            const int b = p->rowBodies[i][h];
            const MeReal *lin = h ? p->J[i].lin1 : p->J[i].lin0, *ang = h ? p->J[i].ang1 : p->J[i].ang0;
            MeReal *jl = h ? w->paddedJ[i].lin1 : w->paddedJ[i].lin0, *ja = h ? w->paddedJ[i].ang1 : w->paddedJ[i].ang0;
            MeReal *bl = h ? w->B[i].lin1 : w->B[i].lin0, *ba = h ? w->B[i].ang1 : w->B[i].ang0;
            w->body[i][h] = b == KEA_WORLD ? nb : b;
            if (b == KEA_WORLD)
                continue;
            for (k = 0; k < 3; ++k) {
                jl[k] = lin[k];
                ja[k] = ang[k];
                bl[k] = p->bodies[b].invMass * lin[k];
                ba[k] = ME_R(0.0);
                for (c = 0; c < 3; ++c)
                    ba[k] += p->bodies[b].invInertia[k][c] * ang[c];
            }
        }
    }
}

static void free_work(KeaIterativeWork *w)
{
    free(w->paddedJ);
    free(w->B);
    free(w->body);
    free(w->eps);
    free(w->invDiag);
    free(w->xPrev);
    free(w->nncgDir);
    free(w->xStart);
    free(w->z);
    free(w->q);
    free(w->lo);
    free(w->hi);
    free(w->dv);
}

/* w->dv = M^-1 J^T x (KeaBodyVelocityFromImpulses, padded). */
static void set_dv(const KeaProblem *p, KeaIterativeWork *w, const MeReal *x, KeaBodyVelocity *dv)
{
    int b, k;
    KeaBodyVelocityFromImpulses(p, x, dv);
    for (b = 0; b < p->nBodies; ++b)
        for (k = 0; k < 3; ++k) {
            w->dv[b].lin[k] = dv[b].lin[k];
            w->dv[b].ang[k] = dv[b].ang[k];
        }
}

/* A projected Jacobi pass standing in for a pair of sweeps: x_i <- mid(lo, x_i - (A x - r)_i / (2
 * A_ii), hi), the bounds from the x before, then friction projected on the new normals' bounds. */
static void jacobi_pass(const KeaProblem *p, const double *A, MeReal *x, MeReal *tmp)
{
    const int n = p->nRows;
    int i, j;
    for (i = 0; i < n; ++i) {
        double wi = -(double)p->rhs[i];
        MeReal lo, hi;
        for (j = 0; j < n; ++j)
            wi += A[i * n + j] * (double)x[j];
        KeaRowBounds(p, x, i, &lo, &hi);
        tmp[i] = KeaClamp((MeReal)((double)x[i] - wi / (2.0 * A[i * n + i])), lo, hi);
    }
    memcpy(x, tmp, sizeof(MeReal) * (size_t)n);
    for (i = 0; i < n; ++i) { /* friction within the new normals' bounds (the normals stay) */
        MeReal lo, hi;
        KeaRowBounds(p, x, i, &lo, &hi);
        x[i] = KeaClamp(x[i], lo, hi);
    }
}

/* Random contact LCPs (some joint rows) from random impulses: passes, each followed by the
 * correction. Every step leaves f no higher (as it reports, and as the dense A has it), x within the
 * bounds of the x before it (friction's from the normals' x then), x as it was when no step is
 * taken, dv the velocity change of x; and half the steps or more lower f. */
static void deflation_step_never_raises_the_objective(void **state)
{
    static const int seeds[] = {11, 12, 13, 14};
    int s, lowered = 0, steps = 0;
    (void)state;
    for (s = 0; s < 4; ++s) {
        KtRng r = kt_rng((uint64_t)seeds[s]);
        KtProblem t;
        KeaIterativeWork w;
        MeReal *x, *xBefore, *lo, *hi;
        KeaBodyVelocity *dv;
        double *A;
        int n, nb, i, b, k, pass;
        kt_random_contacts(&t, &r, 40, 6, 20, 0.5, 1e-2);
        n = t.p.nRows;
        nb = t.p.nBodies;
        x = malloc(sizeof(MeReal) * (size_t)n);
        xBefore = malloc(sizeof(MeReal) * (size_t)n);
        lo = malloc(sizeof(MeReal) * (size_t)n);
        hi = malloc(sizeof(MeReal) * (size_t)n);
        dv = malloc(sizeof(KeaBodyVelocity) * (size_t)nb);
        A = malloc(sizeof(double) * (size_t)n * (size_t)n);
        assert_non_null(x);
        assert_non_null(A);
        kt_dense_matrix(&t.p, A);
        make_work(&t.p, &w);
        for (i = 0; i < n; ++i)
            x[i] = i % 3 == 0 && i < 120 ? (MeReal)kt_range(&r, 0.0, 1.0) : ME_R(0.0);
        set_dv(&t.p, &w, x, dv);
        KeaDeflationStart(&w, x, n);
        for (pass = 0; pass < 8; ++pass) {
            double f0, f1;
            MeReal df;
            jacobi_pass(&t.p, A, x, xBefore);
            set_dv(&t.p, &w, x, dv);
            for (i = 0; i < n; ++i) {
                KeaRowBounds(&t.p, x, i, &lo[i], &hi[i]);
                xBefore[i] = x[i];
            }
            f0 = kt_objective(n, A, t.p.rhs, x);
            df = KeaDeflationStep(&t.p, &w, x);
            f1 = kt_objective(n, A, t.p.rhs, x);
            ++steps;
            lowered += df < ME_R(0.0);
            assert_true(df <= ME_R(0.0));
            assert_true(f1 <= f0 + ME_TOL(1e-9, 1e-4) * (1.0 + fabs(f0)));
            if (df < ME_R(0.0)) /* the change it reports is the objective's */
                assert_near(f1 - f0, (double)df, ME_TOL(1e-6, 1e-2) * (1.0 + fabs(f0)));
            for (i = 0; i < n; ++i) {
                assert_true(x[i] >= lo[i] && x[i] <= hi[i]);
                if (df == ME_R(0.0))
                    assert_true(x[i] == xBefore[i]);
            }
            KeaBodyVelocityFromImpulses(&t.p, x, dv);
            for (b = 0; b < nb; ++b)
                for (k = 0; k < 3; ++k) {
                    assert_near(w.dv[b].lin[k], dv[b].lin[k], ME_TOL(1e-9, 1e-3) * (1.0 + fabs(dv[b].lin[k])));
                    assert_near(w.dv[b].ang[k], dv[b].ang[k], ME_TOL(1e-9, 1e-3) * (1.0 + fabs(dv[b].ang[k])));
                }
        }
        free_work(&w);
        free(A);
        free(dv);
        free(hi);
        free(lo);
        free(xBefore);
        free(x);
        kt_free(&t);
    }
    print_message("deflation on random contacts: %d of %d steps lowered the objective\n", lowered, steps);
    assert_true(2 * lowered >= steps);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(deflation_solve_drops_dependent_directions),
        cmocka_unit_test(deflation_step_never_raises_the_objective),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
