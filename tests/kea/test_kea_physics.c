/* test_kea_physics.c -- Kea on small problems with closed-form answers, on both paths.
 *
 * - a unit cube resting on four corner contacts under gravity: the total normal impulse is
 *   m g h / (1 + eps m / 4) (the symmetric solution with softness eps per contact), each contact a
 *   quarter, and the cube's velocity change cancels gravity's, less the soft sink;
 * - a pendulum: a body held by a ball joint (three bilateral rows) at an anchor L above its centre,
 *   swinging at speed V: the vertical row carries m g h (its row decouples), the swing direction
 *   -V / (1/m + L^2 / I), and the anchor's velocity after the step is zero;
 * - friction: the cube sliding at V over the ground with coefficient mu: when V > mu g h the friction
 *   rows sit at their bounds -mu N_i and the cube slows by exactly mu (sum N) / m; when V < mu g h
 *   it stops and every friction row is strictly inside its bounds. Soft rows give at eps x (velocity),
 *   which bounds what "stops" and "holds" mean here. */
#include "karma_test.h"

#include "kea_test_problems.h"

static const double g = 9.81, h = 1.0 / 60.0;

static const KeaPath paths[] = {KeaPathDirect, KeaPathIterative};

/* A cube of mass m on four corner contacts on the ground, moving at v (linear, angular), rows: each
 * contact's normal, then (withFriction) its x and y friction rows linked to it. */
static void cube_on_ground(KtProblem *t, double m, double eps, int withFriction, double mu, const double v[6])
{
    const double corners[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    const double dirs[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    const double centre[3] = {0, 0, 0.5}, gravity[3] = {0, 0, -g};
    const int perContact = withFriction ? 3 : 1;
    int c, d, k, row = 0;
    kt_alloc(t, 4 * perContact, 1, withFriction);
    t->bodies[0].invMass = (MeReal)(1.0 / m);
    for (k = 0; k < 3; ++k)
        t->bodies[0].invInertia[k][k] = (MeReal)(6.0 / m);
    for (c = 0; c < 4; ++c) {
        const double p[3] = {corners[c][0], corners[c][1], 0.0};
        const int normal = row;
        for (d = 0; d < perContact; ++d, ++row) {
            kt_contact_row(&t->J[row], p, centre, NULL, dirs[d]);
            t->rowBodies[row][0] = 0;
            t->rowBodies[row][1] = KEA_WORLD;
            t->eps[row] = (MeReal)eps;
            t->lo[row] = d ? -MEINFINITY : ME_R(0.0);
            t->hi[row] = MEINFINITY;
            if (d) {
                t->link[row] = normal;
                t->mu[row] = (MeReal)mu;
            }
        }
    }
    if (withFriction)
        kt_declare_contacts(t, 4);
    kt_set_rhs_from_velocities(t, v, h, gravity);
}

static void resting_cube_carries_its_weight(void **state)
{
    const double m = 2.0, eps = 1e-4, v[6] = {0};
    int p;
    (void)state;
    for (p = 0; p < 2; ++p) {
        KtProblem t;
        MeReal x[4];
        KeaBodyVelocity dv[1];
        KeaParameters prm = kt_params(paths[p]);
        KeaStats st;
        const double total = m * g * h / (1.0 + eps * m / 4.0);
        int i;
        cube_on_ground(&t, m, eps, 0, 0.0, v);
        kt_solve(&t.p, &prm, x, dv, &st);
        assert_int_equal(st.path, paths[p]);
        /* The total is well conditioned; its split over the four (redundant) contacts is fixed only by
         * eps, so float resolves it to about 1e-7 / (eps m): see docs/kea.md. */
        assert_rel((double)x[0] + (double)x[1] + (double)x[2] + (double)x[3], total, ME_TOL(1e-10, 1e-5));
        for (i = 0; i < 4; ++i)
            assert_rel(x[i], total / 4.0, ME_TOL(1e-10, 2e-3));
        /* velocity change: up by the impulse over the mass, no rotation */
        assert_rel(dv[0].lin[2], total / m, ME_TOL(1e-10, 1e-5));
        for (i = 0; i < 3; ++i)
            assert_near(dv[0].ang[i], 0.0, ME_TOL(1e-12, 1e-6));
        assert_near(st.residual, 0.0, ME_TOL(1e-12, 1e-6));
        kt_free(&t);
    }
}

static void pendulum_rows(void **state)
{
    const double m = 3.0, L = 0.8, V = 1.5, Ix = 0.2, Iy = 0.3, Iz = 0.25;
    int p;
    (void)state;
    for (p = 0; p < 2; ++p) {
        KtProblem t;
        MeReal x[3];
        KeaBodyVelocity dv[1];
        KeaParameters prm = kt_params(paths[p]);
        KeaStats st;
        const double anchor[3] = {0, L, 0}, centre[3] = {0, 0, 0}, gravity[3] = {0, -g, 0};
        const double v[6] = {V, 0, 0, 0, 0, 0};
        double post[3], wxr[3], omega[3];
        int k;
        kt_alloc(&t, 3, 1, 0);
        t.bodies[0].invMass = (MeReal)(1.0 / m);
        t.bodies[0].invInertia[0][0] = (MeReal)(1.0 / Ix);
        t.bodies[0].invInertia[1][1] = (MeReal)(1.0 / Iy);
        t.bodies[0].invInertia[2][2] = (MeReal)(1.0 / Iz);
        for (k = 0; k < 3; ++k) {
            double e[3] = {0, 0, 0};
            e[k] = 1.0;
            kt_contact_row(&t.J[k], anchor, centre, NULL, e); /* J = (e, r x e): the anchor's velocity */
            t.rowBodies[k][0] = 0;
            t.rowBodies[k][1] = KEA_WORLD;
            t.eps[k] = ME_R(0.0);
            t.lo[k] = -MEINFINITY;
            t.hi[k] = MEINFINITY;
        }
        kt_set_rhs_from_velocities(&t, v, h, gravity);
        kt_solve(&t.p, &prm, x, dv, &st);
        assert_rel(x[1], m * g * h, ME_TOL(1e-10, 1e-5));
        assert_rel(x[0], -V / (1.0 / m + L * L / Iz), ME_TOL(1e-10, 1e-5));
        assert_near(x[2], 0.0, ME_TOL(1e-12, 1e-6));
        /* anchor velocity after the step: v + h g + dv_lin + (w + dw) x r = 0 */
        for (k = 0; k < 3; ++k)
            omega[k] = (double)dv[0].ang[k];
        kt_cross(omega, anchor, wxr);
        for (k = 0; k < 3; ++k) {
            post[k] = v[k] + h * gravity[k] + (double)dv[0].lin[k] + wxr[k];
            assert_near(post[k], 0.0, ME_TOL(1e-12, 1e-5));
        }
        kt_free(&t);
    }
}

static void friction_at_bound_when_sliding_inside_when_sticking(void **state)
{
    const double m = 1.5, mu = 0.5, eps = 1e-3;
    const double speeds[2] = {0.2, 0.03}; /* mu g h = 0.0818 */
    int p, s;
    (void)state;
    for (p = 0; p < 2; ++p)
        for (s = 0; s < 2; ++s) {
            KtProblem t;
            MeReal x[12];
            KeaBodyVelocity dv[1];
            KeaParameters prm = kt_params(paths[p]);
            KeaStats st;
            const double V = speeds[s], v[6] = {V, 0, 0, 0, 0, 0};
            const double tight = paths[p] == KeaPathIterative ? 1e-8 : 1e-10;
            double normalSum = 0.0, vx;
            int c, k;
            (void)tight; /* used by the double build's tolerances */
            cube_on_ground(&t, m, eps, 1, mu, v);
            /* The iterative path solves each contact as its own block: the four corners share
             * the load through the sweeps (about 40 sticking, 80 sliding to the float tolerance),
             * not in one; run it to convergence, and in double to 1e-8 where the direct path is
             * exact to 1e-10. */
            if (paths[p] == KeaPathIterative) {
                prm.maxIterations = 1000;
                prm.tolerance = ME_TOL(1e-13, 1e-6);
            }
            kt_solve(&t.p, &prm, x, dv, &st);
            assert_int_equal(st.status, KeaStatusOk);
            assert_near(st.residual, 0.0, ME_TOL(tight, 1e-5));
            for (c = 0; c < 4; ++c)
                normalSum += (double)x[3 * c];
            /* vertical: the ground stops the fall (up to the soft sink eps x) */
            assert_near(-g * h + (double)dv[0].lin[2], 0.0, 1e-3 * g * h);
            vx = V + (double)dv[0].lin[0];
            if (V > mu * g * h) { /* sliding: each x-friction row at -mu N_i, speed drops by mu N / m */
                double sideways = 0.0;
                for (c = 0; c < 4; ++c) {
                    assert_near(x[3 * c + 1], -mu * (double)x[3 * c], ME_TOL(tight, 1e-6));
                    sideways += (double)x[3 * c + 2];
                    /* The corners' y rows can carry a stress that neither moves nor turns the cube
                     * (pairs of equal and opposite impulses), resisted by eps alone: the iterative
                     * path leaves it up to its tolerance / eps, so that path is held to the sum. */
                    if (paths[p] != KeaPathIterative)
                        assert_near(x[3 * c + 2], 0.0, ME_TOL(tight, 1e-3) * mu * (double)x[3 * c]);
                }
                assert_near(sideways, 0.0, ME_TOL(tight, 1e-3) * mu * normalSum);
                assert_rel(vx, V - mu * normalSum / m, ME_TOL(tight, 1e-5));
                assert_true(vx > 0.0);
            } else { /* sticking: stops, friction strictly inside */
                assert_near(vx, 0.0, eps * m * g * h); /* soft: rows give at eps x */
                for (c = 0; c < 4; ++c)
                    assert_true(fabs((double)x[3 * c + 1]) < 0.99 * mu * (double)x[3 * c]);
            }
            for (k = 0; k < 3; ++k) /* the contacts hold the cube's rotation (up to the soft give) */
                assert_near(dv[0].ang[k], 0.0, 2.0 * eps * m * g * h);
            kt_free(&t);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(resting_cube_carries_its_weight),
        cmocka_unit_test(pendulum_rows),
        cmocka_unit_test(friction_at_bound_when_sliding_inside_when_sticking),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
