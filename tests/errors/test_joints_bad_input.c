/* The joints of issue 3 (Universal, Angular3, Linear1/2, FixedPath, RPRO, Skeletal, Spring6, ConeLimit,
 * UserConstraint): created disabled with Karma's defaults, Reset restores them, casts check the type,
 * and bad input is rejected with its code, naming the function, changing nothing. */
#include "karma_test.h"

#include <string.h>

#include <karma/Mdt.h>

static MdtWorldID world;
static MdtBodyID body;
static const MeReal nan_ = (MeReal)NAN;

static int setup(void **state)
{
    (void)state;
    karma_capture_messages();
    world = MdtWorldCreate(4, 16, 1, 1);
    body = MdtBodyCreate(world);
    MdtBodyEnable(body);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    MdtWorldDestroy(world);
    return 0;
}

static void assertVector(const MeVector3 v, double x, double y, double z)
{
    assert_near(v[0], x, 1e-6);
    assert_near(v[1], y, 1e-6);
    assert_near(v[2], z, 1e-6);
}

static void created_disabled_with_karma_defaults(void **s)
{
    (void)s;
    MeVector3 v;
    MeVector4 q;
    MdtUniversalID u = MdtUniversalCreate(world);
    MdtUniversalSetBodies(u, body, NULL);
    assert_false(MdtUniversalIsEnabled(u));
    MdtUniversalGetAxis(u, 0, v);
    assertVector(v, 1, 0, 0);
    MdtUniversalGetAxis(u, 1, v);
    assertVector(v, 0, 1, 0);

    MdtAngular3ID a = MdtAngular3Create(world);
    assert_false(MdtAngular3IsEnabled(a));
    assert_true(MdtAngular3GetStiffness(a) == MEINFINITY);
    assert_near(MdtAngular3GetDamping(a), 0, 0); /* decision D3 */
    assert_false(MdtAngular3RotationIsEnabled(a));

    MdtLinear2ID l2 = MdtLinear2Create(world);
    MdtLinear2SetBodies(l2, body, NULL);
    MdtLinear2GetDirection(l2, v);
    assertVector(v, 1, 0, 0);

    MdtConeLimitID c = MdtConeLimitCreate(world);
    assert_near(MdtConeLimitGetConeHalfAngle(c), ME_PI, 0);
    assert_true(MdtConeLimitGetStiffness(c) == MEINFINITY);
    assert_true(MdtConeLimitGetDamping(c) == MEINFINITY);

    MdtSkeletalID k = MdtSkeletalCreate(world);
    assert_near(MdtSkeletalGetConePrimaryLimitAngle(k), ME_PI / 4, 0); /* decision D6 */
    assert_near(MdtSkeletalGetConeSecondaryLimitAngle(k), ME_PI / 4, 0);
    assert_near(MdtSkeletalGetTwistLimitAngle(k), ME_PI / 4, 0);
    assert_int_equal(MdtSkeletalGetConeLimitOption(k), MdtSkeletalConeOptionCone);
    assert_int_equal(MdtSkeletalGetTwistLimitOption(k), MdtSkeletalTwistOptionLimited);
    assert_false(MdtSkeletalCombinedLimitsAreEnabled(k));

    MdtSpring6ID sp = MdtSpring6Create(world);
    for (unsigned int i = 0; i < 3; i++) {
        assert_true(MdtSpring6GetLinearStiffness(sp, i) == MEINFINITY);
        assert_true(MdtSpring6GetAngularStiffness(sp, i) == MEINFINITY);
        assert_near(MdtSpring6GetLinearDamping(sp, i), 0, 0);
    }

    MdtRPROJointID r = MdtRPROJointCreate(world);
    MdtRPROJointGetRelativeQuaternion(r, q);
    assert_near(q[0], 1, 0);
    MdtRPROJointGetLinearStrength(r, v);
    assert_true(v[0] == MEINFINITY && v[2] == MEINFINITY);
    MdtRPROJointGetAngularStrength(r, v);
    assert_true(v[1] == MEINFINITY);

    MdtFixedPathID f = MdtFixedPathCreate(world);
    MdtFixedPathSetBodies(f, body, NULL);
    MdtFixedPathGetVelocity(f, 1, v);
    assertVector(v, 0, 0, 0);

    MdtUserConstraintID us = MdtUserConstraintCreate(world);
    assert_int_equal(MdtUserConstraintGetMaxRows(us), 6);
    assert_null(MdtUserConstraintGetAddConstraintFunction(us));

    MdtLinear1ID l1 = MdtLinear1Create(world);
    assert_string_equal(MdtConstraintGetTypeName(MdtLinear1QuaConstraint(l1)), "Linear1");
    assert_int_equal(MdtConstraintGetType(MdtSkeletalQuaConstraint(k)), MdtBclSKELETAL);

    /* Casts: back to the type, or NULL for another type. */
    assert_true(MdtConstraintDCastSkeletal(MdtSkeletalQuaConstraint(k)) == k);
    assert_null(MdtConstraintDCastSkeletal(MdtConeLimitQuaConstraint(c)));
    assert_null(MdtConstraintDCastUniversal(MdtLinear1QuaConstraint(l1)));

    /* Reset restores the defaults. */
    MdtSkeletalSetTwistLimitAngle(k, 1);
    MdtSkeletalSetConeLimitOption(k, MdtSkeletalConeOptionFixed);
    MdtSkeletalReset(k);
    assert_near(MdtSkeletalGetTwistLimitAngle(k), ME_PI / 4, 0);
    assert_int_equal(MdtSkeletalGetConeLimitOption(k), MdtSkeletalConeOptionCone);
    MdtAngular3SetStiffness(a, 3);
    MdtAngular3EnableRotation(a, METRUE);
    MdtAngular3Reset(a);
    assert_true(MdtAngular3GetStiffness(a) == MEINFINITY);
    assert_false(MdtAngular3RotationIsEnabled(a));
    assert_int_equal(karma_warning_count(), 0);
}

static void bad_axes_and_indices(void **s)
{
    (void)s;
    MeVector3 v;
    MdtUniversalID u = MdtUniversalCreate(world);
    MdtUniversalSetBodies(u, body, NULL);
    assert_reports(ME_ERR_ZERO_AXIS, MdtUniversalSetAxis(u, 0, 0, 0, 0));
    assert_string_equal(karma_last_function(), "MdtUniversalSetAxis");
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtUniversalSetAxis(u, 1, nan_, 0, 0));
    assert_reports(ME_ERR_BODY_INDEX, MdtUniversalSetAxis(u, 2, 1, 0, 0));
    MdtUniversalGetAxis(u, 1, v);
    assertVector(v, 0, 1, 0); /* unchanged */

    MdtLinear2ID l2 = MdtLinear2Create(world);
    assert_reports(ME_ERR_ZERO_AXIS, MdtLinear2SetDirection(l2, 0, 0, 0));
    assert_string_equal(karma_last_function(), "MdtLinear2SetDirection");

    MdtFixedPathID f = MdtFixedPathCreate(world);
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtFixedPathSetVelocity(f, 1, 0, nan_, 0));
    assert_reports(ME_ERR_BODY_INDEX, MdtFixedPathSetPosition(f, 3, 0, 0, 0));

    MdtSpring6ID sp = MdtSpring6Create(world);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtSpring6SetLinearStiffness(sp, 3, 1));
    assert_string_equal(karma_last_function(), "MdtSpring6SetLinearStiffness");
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtSpring6GetAngularDamping(sp, 7));
}

static void bad_gains_and_angles(void **s)
{
    (void)s;
    MdtAngular3ID a = MdtAngular3Create(world);
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtAngular3SetStiffness(a, -1));
    assert_non_null(strstr(karma_last_text(), "'stiffness'"));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtAngular3SetDamping(a, nan_));
    assert_true(MdtAngular3GetStiffness(a) == MEINFINITY);
    assert_near(MdtAngular3GetDamping(a), 0, 0);
    MdtAngular3SetStiffness(a, (MeReal)INFINITY); /* +inf means rigid: stored as MEINFINITY */
    assert_true(MdtAngular3GetStiffness(a) == MEINFINITY);

    MdtConeLimitID c = MdtConeLimitCreate(world);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtConeLimitSetConeHalfAngle(c, -0.1f));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtConeLimitSetConeHalfAngle(c, 4));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtConeLimitSetConeHalfAngle(c, nan_));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtConeLimitSetDamping(c, -3));
    assert_near(MdtConeLimitGetConeHalfAngle(c), ME_PI, 0);

    MdtSkeletalID k = MdtSkeletalCreate(world);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtSkeletalSetConeLimitOption(k, (MdtSkeletalConeOption)7));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtSkeletalSetTwistLimitOption(k, (MdtSkeletalTwistOption)-1));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtSkeletalSetTwistStiffness(k, -2));
    assert_string_equal(karma_last_function(), "MdtSkeletalSetTwistStiffness");
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtSkeletalSetConePrimaryLimitAngle(k, 5));
    assert_int_equal(MdtSkeletalGetConeLimitOption(k), MdtSkeletalConeOptionCone);

    MdtSpring6ID sp = MdtSpring6Create(world);
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtSpring6SetAngularDamping(sp, 1, -1));
    assert_near(MdtSpring6GetAngularDamping(sp, 1), 0, 0);

    MdtRPROJointID r = MdtRPROJointCreate(world);
    MeVector4 notUnit = {2, 0, 0, 0}, q;
    MeVector3 v;
    assert_reports(ME_ERR_QUATERNION_NOT_UNIT, MdtRPROJointSetRelativeQuaternion(r, notUnit));
    assert_reports(ME_ERR_QUATERNION_NOT_UNIT, MdtRPROJointSetAttachmentQuaternion(r, 0, 0, 0, 0, 0));
    assert_reports(ME_ERR_BODY_INDEX, MdtRPROJointSetAttachmentQuaternion(r, 1, 0, 0, 0, 5));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtRPROJointSetAngularStrength(r, 1, -1, 1));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtRPROJointSetAngularVelocity(r, NULL));
    MdtRPROJointGetRelativeQuaternion(r, q);
    assert_near(q[0], 1, 0);
    MdtRPROJointGetAngularStrength(r, v);
    assert_true(v[0] == MEINFINITY); /* the whole call was refused */
}

static void wrong_and_stale_handles(void **s)
{
    (void)s;
    MdtConeLimitID c = MdtConeLimitCreate(world);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, MdtAngular3SetStiffness((MdtAngular3ID)c, 1));
    MdtSkeletalID k = MdtSkeletalCreate(world);
    MdtSkeletalDestroy(k);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtSkeletalSetTwistLimitAngle(k, 0.5f));
    MdtLinear1ID l1 = MdtLinear1Create(world);
    assert_reports(ME_ERR_BAD_STATE, MdtLinear1Enable(l1)); /* no body yet */
}

static int tooMany(MdtUserConstraintID j, MdtUserConstraintRow *rows, int maxRows,
                   const MdtBclSolverParameters *params, void *data)
{
    (void)j;
    (void)rows;
    (void)params;
    (void)data;
    return maxRows + 5;
}

static int nanRow(MdtUserConstraintID j, MdtUserConstraintRow *rows, int maxRows,
                  const MdtBclSolverParameters *params, void *data)
{
    (void)j;
    (void)maxRows;
    (void)params;
    (void)data;
    rows[0].linear0[0] = 1;
    rows[0].error = (MeReal)NAN;
    rows[1].linear0[1] = 1;
    rows[1].lo = 1;
    rows[1].hi = -1;
    return 2;
}

static void user_constraint_bad_input(void **s)
{
    (void)s;
    MdtUserConstraintID u = MdtUserConstraintCreate(world);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtUserConstraintSetMaxRows(u, 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtUserConstraintSetMaxRows(u, MDT_USER_CONSTRAINT_MAX_ROWS + 1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtUserConstraintGetRowForce(u, -1));
    assert_int_equal(MdtUserConstraintGetMaxRows(u), 6);

    /* During the step: a bad row count is clamped and reported; bad rows are left out; no NaN. */
    MdtUserConstraintSetBodies(u, body, NULL);
    MdtUserConstraintSetAddConstraintFunction(u, tooMany);
    MdtUserConstraintEnable(u);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldStep(world, ME_R(1.0) / 60));
    MdtUserConstraintSetAddConstraintFunction(u, nanRow);
    unsigned long nonfinite = MeMessageGetCount(ME_ERR_NONFINITE_ARGUMENT);
    unsigned long range = MeMessageGetCount(ME_ERR_ARGUMENT_RANGE);
    MdtWorldStep(world, ME_R(1.0) / 60);
    assert_int_equal(MeMessageGetCount(ME_ERR_NONFINITE_ARGUMENT) - nonfinite, 1);
    assert_int_equal(MeMessageGetCount(ME_ERR_ARGUMENT_RANGE) - range, 1);
    assert_int_equal(MdtUserConstraintGetRowCount(u), 0);
    MeVector3 p;
    MdtBodyGetPosition(body, p);
    assert_true(MeVector3IsValid(p));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(created_disabled_with_karma_defaults, setup, teardown),
        cmocka_unit_test_setup_teardown(bad_axes_and_indices, setup, teardown),
        cmocka_unit_test_setup_teardown(bad_gains_and_angles, setup, teardown),
        cmocka_unit_test_setup_teardown(wrong_and_stale_handles, setup, teardown),
        cmocka_unit_test_setup_teardown(user_constraint_bad_input, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
