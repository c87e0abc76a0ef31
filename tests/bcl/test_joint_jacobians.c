/* Every row of the hinge, prismatic, spring and car wheel joints (limit, spring and motor rows
 * included) against central finite differences of its constraint function, at random poses. */
#include "karma_test.h"
#include "karma_jacobian.h"

#include <karma/Mdt.h>

typedef struct Scene {
    MdtWorldID w;
    MdtBodyID a, b;
} Scene;

static Scene makeScene(void)
{
    Scene s;
    s.w = MdtWorldCreate(4, 4, 1, 1);
    s.a = MdtBodyCreate(s.w);
    s.b = MdtBodyCreate(s.w);
    MeVector3 com = {0.1f, 0, -0.05f};
    MdtBodySetCenterOfMassRelativePosition(s.a, com); /* COM away from the body origin */
    return s;
}

/* Random frames in each body (the joint need not be satisfied: the Jacobians are exact anyway). */
static void randomFrames(MdtConstraintID c)
{
    for (unsigned i = 0; i < 2; i++) {
        MdtConstraintBodySetPositionRel(c, i, MeRealRandomInRange(-0.5f, 0.5f), MeRealRandomInRange(-0.5f, 0.5f),
                                        MeRealRandomInRange(-0.5f, 0.5f));
        MdtConstraintBodySetAxesRel(c, i, MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1),
                                    MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1),
                                    MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1));
    }
}

/* Worst error over 200 random poses; each trial must write `rows` rows. */
static double check(Scene *s, MdtConstraintID c, int rows, const char *name)
{
    double worst = 0;
    for (int trial = 0; trial < 200; trial++) {
        karma_random_pose(s->a, 1);
        karma_random_pose(s->b, 1);
        MdtConstraintSetBodies(c, s->a, trial % 4 == 0 ? NULL : s->b);
        randomFrames(c);
        int n;
        worst = fmax(worst, karma_jacobian_error(c, &n));
        assert_int_equal(n, rows);
    }
    print_message("%-10s %d rows: worst |J v - dphi/dt| / (1 + |J v|) = %.2e\n", name, rows, worst);
    assert_true(worst < ME_TOL(1e-6, 2e-2));
    return worst;
}

/* A soft lower stop far above every reachable value keeps the limit row written. */
static void activeSoftLimit(MdtLimitID l)
{
    MdtLimitActivateLimits(l, METRUE);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(l), 100);
    MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(l), 50);
    MdtSingleLimitSetDamping(MdtLimitGetLowerLimit(l), 2);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(l), 200);
}

static void hinge_rows(void **state)
{
    (void)state;
    MeRealRandomSeed(11);
    Scene s = makeScene();
    MdtHingeID j = MdtHingeCreate(s.w);
    activeSoftLimit(MdtHingeGetLimit(j));
    check(&s, MdtHingeQuaConstraint(j), 6, "Hinge");
    MdtWorldDestroy(s.w);
}

static void prismatic_rows(void **state)
{
    (void)state;
    MeRealRandomSeed(12);
    Scene s = makeScene();
    MdtPrismaticID j = MdtPrismaticCreate(s.w);
    activeSoftLimit(MdtPrismaticGetLimit(j));
    check(&s, MdtPrismaticQuaConstraint(j), 6, "Prismatic");
    MdtWorldDestroy(s.w);
}

static void spring_rows(void **state)
{
    (void)state;
    MeRealRandomSeed(13);
    Scene s = makeScene();
    MdtSpringID j = MdtSpringCreate(s.w); /* default: two soft stops at one place, one two-sided row */
    check(&s, MdtSpringQuaConstraint(j), 1, "Spring");
    MdtWorldDestroy(s.w);
}

static void carwheel_rows(void **state)
{
    (void)state;
    MeRealRandomSeed(14);
    Scene s = makeScene();
    MdtCarWheelID j = MdtCarWheelCreate(s.w);
    MdtCarWheelSetSuspension(j, 1000, 20, 0, -1e6f, 1e6f, 0.1f);
    MdtCarWheelSetHingeLimitedForceMotor(j, 3, 50); /* the steering motor is on by default */
    check(&s, MdtCarWheelQuaConstraint(j), 6, "CarWheel");
    MdtWorldDestroy(s.w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hinge_rows),
        cmocka_unit_test(prismatic_rows),
        cmocka_unit_test(spring_rows),
        cmocka_unit_test(carwheel_rows),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
