/* Pendulums on a ball and socket joint: the small-angle period 2π√(L/g) within 1 %, at two steps. */
#include "karma_test.h"
#include "karma_jacobian.h"

#include <karma/MdtBSJoint.h>
#include <karma/Mdt.h>

/* Period from the times the bob crosses the vertical (linear interpolation between steps). */
static double measurePeriod(double h, double L, double theta0, double *drift)
{
    const double g = 9.81;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-g);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID bob = MdtBodyCreate(w);
    MdtBodySetSphericalInertiaTensor(bob, 1e-3f);
    MdtBodySetPosition(bob, (MeReal)(L * sin(theta0)), 0, (MeReal)(-L * cos(theta0)));
    MdtBodyEnable(bob);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, bob, NULL);
    MdtBSJointSetPosition(j, 0, 0, 0);
    MdtBSJointEnable(j);
    double lastX = L * sin(theta0), t = 0, crossings[8];
    int n = 0;
    *drift = 0;
    while (n < 8 && t < 60) {
        MdtWorldStep(w, (MeReal)h);
        t += h;
        MeVector3 p;
        MdtBodyGetPosition(bob, p);
        double r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        *drift = fmax(*drift, fabs(r - L));
        if ((lastX > 0) != (p[0] > 0))
            crossings[n++] = t - h * p[0] / (p[0] - lastX);
        lastX = p[0];
    }
    MdtWorldDestroy(w);
    assert_int_equal(n, 8);
    return (crossings[7] - crossings[1]) / 3; /* three full periods */
}

static void bsjoint_pendulum_period(void **state)
{
    (void)state;
    const double L = 1, g = 9.81, theta0 = 0.05;
    /* The small-angle period, corrected for the bob's own inertia (1e-3, 0.1 %) and the amplitude. */
    const double expected = 2 * 3.14159265358979323846 * sqrt((L * L + 1e-3) / (g * L)) * (1 + theta0 * theta0 / 16);
    double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++) {
        double drift;
        double T = measurePeriod(steps[i], L, theta0, &drift);
        print_message("BS pendulum h=%.5f: period %.5f s vs %.5f s (%.3f %%), length drift %.2e m\n", steps[i], T,
                      expected, 100 * fabs(T - expected) / expected, drift);
        assert_rel(T, expected, 0.01);
        assert_true(drift < 1e-3);
    }
}

static void bsjoint_jacobian_matches_finite_differences(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
    MdtBSJointID j = MdtBSJointCreate(w);
    MeRealRandomSeed(7);
    double worst = 0;
    for (int trial = 0; trial < 200; trial++) {
        karma_random_pose(a, 1);
        karma_random_pose(b, 1);
        MdtBSJointSetBodies(j, a, trial % 4 == 0 ? NULL : b);
        MdtConstraintBodySetPositionRel(MdtBSJointQuaConstraint(j), 0, 0.3f, -0.2f, 0.5f);
        MdtConstraintBodySetPositionRel(MdtBSJointQuaConstraint(j), 1, -0.4f, 0.1f, 0.2f);
        int rows;
        worst = fmax(worst, karma_jacobian_error(MdtBSJointQuaConstraint(j), &rows));
        assert_int_equal(rows, 3);
    }
    print_message("BSJoint: worst |J v - dphi/dt| / (1 + |J v|) = %.2e\n", worst);
    assert_true(worst < ME_TOL(1e-6, 2e-2));
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bsjoint_jacobian_matches_finite_differences),
        cmocka_unit_test(bsjoint_pendulum_period),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
