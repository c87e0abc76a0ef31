/* Pendulums on a ball and socket joint: the small-angle period 2π√(L/g) within 1 %, at two steps. */
#include "karma_test.h"
#include "karma_jacobian.h"
#include "karma_pendulum.h"

#include <karma/MdtBSJoint.h>
#include <karma/Mdt.h>

static void bsjoint_pendulum_period(void **state)
{
    (void)state;
    const double L = 1, theta0 = 0.05;
    const double expected = karma_pendulum_expected_period(L, theta0);
    double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++) {
        KarmaPendulum swing = karma_pendulum_swing(KARMA_PENDULUM_BALL, steps[i], L, theta0);
        print_message("BS pendulum h=%.5f: period %.5f s vs %.5f s (%.3f %%), length drift %.2e m\n", steps[i],
                      swing.period, expected, 100 * fabs(swing.period - expected) / expected, swing.lengthDrift);
        assert_rel(swing.period, expected, 0.01);
        assert_true(swing.lengthDrift < 1e-3);
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
