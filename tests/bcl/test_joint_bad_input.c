/* Bad input to the limits and to the hinge, prismatic, spring and car wheel joints: each rejection
 * has its code and leaves the settings unchanged; defaults; casts. */
#include "karma_test.h"

#include <string.h>

#include <karma/Mdt.h>

static void limit_defaults_and_bad_values(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtLimit limit;
    MdtLimitReset(&limit);
    MdtSingleLimitID lo = MdtLimitGetLowerLimit(&limit);
    /* Karma's defaults (docs/karma12.md §5.5, decision D4: motor off). */
    assert_true(MdtSingleLimitGetStop(lo) == 0 && MdtSingleLimitGetRestitution(lo) == 1);
    assert_true(MdtSingleLimitGetStiffness(lo) == MEINFINITY && MdtSingleLimitGetDamping(lo) == 0);
    assert_false(MdtLimitIsActive(&limit));
    assert_false(MdtLimitIsMotorized(&limit));
    assert_false(MdtLimitIsLocked(&limit));
    assert_true(MdtLimitGetMotorDesiredVelocity(&limit) == 0 && MdtLimitGetMotorMaxForce(&limit) == 0);
    assert_true(MdtLimitGetStiffnessThreshold(&limit) == MEINFINITY);

    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtSingleLimitSetStop(lo, (MeReal)NAN));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtSingleLimitSetStiffness(lo, -1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtSingleLimitSetStiffness(lo, (MeReal)NAN));
    assert_reports(ME_ERR_NEGATIVE_DAMPING, MdtSingleLimitSetDamping(lo, -1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtSingleLimitSetRestitution(lo, 1.5f));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtLimitSetLimitedForceMotor(&limit, 1, -2));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtLimitSetLimitedForceMotor(&limit, (MeReal)INFINITY, 2));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtLimitController(&limit, 1, 0, 1, 1));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtLimitController(&limit, 1, 1, -1, 1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtLimitController(&limit, 1, 1, MEINFINITY, 1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtLimitSetStiffnessThreshold(&limit, 0));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtLimitSetLock(&limit, 0, -1));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtLimitIsActive(NULL));
    MdtSingleLimit bad = {0, -5, 0, 1};
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtLimitSetUpperLimit(&limit, &bad));
    /* Nothing changed. */
    assert_true(MdtSingleLimitGetStop(lo) == 0 && MdtSingleLimitGetStiffness(lo) == MEINFINITY);
    assert_true(MdtSingleLimitGetDamping(lo) == 0 && MdtSingleLimitGetRestitution(lo) == 1);
    assert_true(MdtSingleLimitGetStiffness(MdtLimitGetUpperLimit(&limit)) == MEINFINITY);
    assert_false(MdtLimitIsMotorized(&limit));
    /* The motor and the lock exclude each other. */
    MdtLimitSetLimitedForceMotor(&limit, 1, 2);
    assert_true(MdtLimitIsMotorized(&limit));
    MdtLimitActivateLock(&limit, METRUE);
    assert_true(MdtLimitIsLocked(&limit) && !MdtLimitIsMotorized(&limit));
    MdtLimitActivateMotor(&limit, METRUE);
    assert_true(!MdtLimitIsLocked(&limit) && MdtLimitIsMotorized(&limit));
    /* A limit that MdtLimitReset never saw is refused. */
    MdtLimit raw;
    memset(&raw, 0, sizeof raw);
    assert_reports(ME_ERR_BAD_STATE, MdtLimitActivateLimits(&raw, METRUE));
    print_message("limit: %lu rejections reported, settings unchanged\n", karma_warning_count());
}

static void joints_bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(8, 8, 1, 1);
    MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
    MdtHingeID hinge = MdtHingeCreate(w);
    MdtPrismaticID slider = MdtPrismaticCreate(w);
    MdtSpringID spring = MdtSpringCreate(w);
    MdtCarWheelID wheel = MdtCarWheelCreate(w);
    MdtBSJointID ball = MdtBSJointCreate(w);
    MdtHingeSetBodies(hinge, a, b);
    MdtPrismaticSetBodies(slider, a, b);
    MdtSpringSetBodies(spring, a, b);
    MdtCarWheelSetBodies(wheel, a, b);
    /* created disabled */
    assert_false(MdtHingeIsEnabled(hinge) || MdtPrismaticIsEnabled(slider) || MdtSpringIsEnabled(spring) ||
                 MdtCarWheelIsEnabled(wheel));

    assert_reports(ME_ERR_ZERO_AXIS, MdtHingeSetAxis(hinge, 0, 0, 0));
    assert_reports(ME_ERR_ZERO_AXIS, MdtPrismaticSetAxis(slider, 0, 0, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtPrismaticSetAxis(slider, (MeReal)NAN, 0, 1));
    MeVector3 axis;
    MdtPrismaticGetAxis(slider, axis);
    assert_true(axis[0] == 1 && axis[1] == 0 && axis[2] == 0); /* default (1,0,0), decision D2 */

    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtSpringSetStiffness(spring, -1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtSpringSetDamping(spring, (MeReal)NAN));
    assert_reports(ME_ERR_NEGATIVE_DAMPING, MdtSpringSetDamping(spring, -2));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtSpringSetNaturalLength(spring, (MeReal)INFINITY));
    assert_reports(ME_ERR_BODY_INDEX, MdtSpringSetPosition(spring, 2, 0, 0, 0));
    assert_true(MdtSpringGetStiffness(spring) == 100 && MdtSpringGetDamping(spring) == 1);

    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtCarWheelSetSuspension(wheel, 1, 1, 0, 1, -1, 0));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtCarWheelSetSuspension(wheel, -1, 1, 0, -1, 1, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtCarWheelSetSuspension(wheel, MEINFINITY, 1, 0, -1, 1, 0));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtCarWheelSetHingeLimitedForceMotor(wheel, 1, -1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtCarWheelSetSteeringLimitedForceMotor(wheel, (MeReal)NAN, 1));
    assert_true(MdtCarWheelGetSuspensionKp(wheel) == 0 && MdtCarWheelGetHingeMotorMaxForce(wheel) == 0);

    /* Casts, and functions given another joint type. */
    assert_true(MdtConstraintDCastHinge(MdtHingeQuaConstraint(hinge)) == hinge);
    assert_null(MdtConstraintDCastHinge(MdtPrismaticQuaConstraint(slider)));
    assert_true(MdtConstraintDCastPrismatic(MdtPrismaticQuaConstraint(slider)) == slider);
    assert_true(MdtConstraintDCastSpring(MdtSpringQuaConstraint(spring)) == spring);
    assert_true(MdtConstraintDCastCarWheel(MdtCarWheelQuaConstraint(wheel)) == wheel);
    assert_null(MdtConstraintDCastCarWheel(MdtBSJointQuaConstraint(ball)));
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, MdtHingeGetLimit((MdtHingeID)ball));
    assert_string_equal(MdtConstraintGetTypeName(MdtCarWheelQuaConstraint(wheel)), "CarWheel");

    /* A destroyed joint's limit is refused, not used. */
    MdtLimitID l = MdtHingeGetLimit(hinge);
    MdtHingeDestroy(hinge);
    assert_reports(ME_ERR_BAD_STATE, MdtLimitActivateLimits(l, METRUE));
    /* Copying an uninitialised limit into a joint is refused. */
    MdtLimit raw;
    memset(&raw, 0, sizeof raw);
    assert_reports(ME_ERR_BAD_STATE, MdtPrismaticSetLimit(slider, &raw));
    print_message("joints: %lu rejections reported\n", karma_warning_count());
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(limit_defaults_and_bad_values),
        cmocka_unit_test(joints_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
