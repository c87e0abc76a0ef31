/* Bad input to the world and body API: each rejection has its own code, names the function and the
 * argument, and leaves the state unchanged; full pools; stale, foreign and made-up IDs. */
#include "karma_test.h"

#include <float.h>
#include <string.h>

#include <karma/MeMemory.h>
#include <karma/Mdt.h>

static MdtWorldID world;
static MdtBodyID body;

static int setup(void **state)
{
    (void)state;
    karma_capture_messages();
    world = MdtWorldCreate(4, 4, 1, 1);
    body = MdtBodyCreate(world);
    MdtBodyEnable(body);
    MdtBodySetPosition(body, 1, 2, 3);
    MdtBodySetMass(body, 2);
    MdtBodySetLinearVelocity(body, 0.5f, 0, 0);
    return world && body ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    MdtWorldDestroy(world);
    return 0;
}

/* The body as the test set it up. */
static void assertUnchanged(void)
{
    MeVector3 p, v;
    MeVector4 q;
    MdtBodyGetPosition(body, p);
    MdtBodyGetLinearVelocity(body, v);
    MdtBodyGetQuaternion(body, q);
    assert_near(p[0], 1, 0);
    assert_near(p[1], 2, 0);
    assert_near(p[2], 3, 0);
    assert_near(v[0], 0.5, 0);
    assert_near(q[0], 1, 0);
    assert_near(MdtBodyGetMass(body), 2, 0);
    assert_near(MdtBodyGetLinearVelocityDamping(body), 0, 0);
}

static void nonfinite_values_are_rejected(void **state)
{
    (void)state;
    const MeReal nan = (MeReal)NAN, inf = (MeReal)INFINITY;
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodySetPosition(body, nan, 0, 0));
    assert_string_equal(karma_last_function(), "MdtBodySetPosition");
    assert_non_null(strstr(karma_last_text(), "'x'"));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodySetLinearVelocity(body, 0, inf, 0));
    assert_non_null(strstr(karma_last_text(), "'dy'"));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodySetAngularVelocity(body, 0, 0, -inf));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodyAddForce(body, nan, 0, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodyAddTorque(body, 0, nan, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodyAddImpulse(body, 0, 0, inf));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodyAddForceAtPosition(body, 1, 0, 0, 0, nan, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodySetMass(body, nan));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtBodySetQuaternion(body, nan, 0, 0, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtWorldSetGravity(world, 0, nan, 0));
    MeVector3 g;
    MdtWorldGetGravity(world, g);
    assert_near(g[1], 0, 0);
    assertUnchanged();
    MeVector3 f;
    MdtBodyGetForce(body, f);
    assert_near(MeVector3Magnitude(f), 0, 0);
}

static void masses_and_inertia(void **state)
{
    (void)state;
    assert_reports(ME_ERR_MASS_NOT_POSITIVE, MdtBodySetMass(body, 0));
    assert_string_equal(karma_last_function(), "MdtBodySetMass");
    assert_non_null(strstr(karma_last_text(), "'mass'"));
    assert_reports(ME_ERR_MASS_NOT_POSITIVE, MdtBodySetMass(body, -1));
    assert_reports(ME_ERR_INERTIA_INVALID, MdtBodySetSphericalInertiaTensor(body, 0));
    MeMatrix3 notSymmetric = {{1, 0.5f, 0}, {0, 1, 0}, {0, 0, 1}};
    MeMatrix3 indefinite = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
    MeMatrix3 fine = {{1, 0.1f, 0}, {0.1f, 2, 0}, {0, 0, 3}};
    MeMatrix3 before, after;
    MdtBodyGetInertiaTensor(body, before);
    assert_reports(ME_ERR_INERTIA_INVALID, MdtBodySetInertiaTensor(body, notSymmetric));
    assert_reports(ME_ERR_INERTIA_INVALID, MdtBodySetInertiaTensor(body, indefinite));
    MdtBodyGetInertiaTensor(body, after);
    assert_memory_equal(before, after, sizeof before);
    unsigned long warnings = karma_warning_count();
    MdtBodySetInertiaTensor(body, fine);
    assert_int_equal(karma_warning_count(), warnings);
    MdtBodyGetInertiaTensor(body, after);
    assert_near(after[1][0], 0.1, 1e-6);
    /* A mass 1000 times the world's massScale is accepted with a warning saying what to set, once. */
    assert_reports(ME_ERR_MASS_SCALE, MdtBodySetMass(body, 2000));
    assert_non_null(strstr(karma_last_text(), "set massScale (MdtWorldCreate's fourth argument)"));
    assert_near(MdtBodyGetMass(body), 2000, 0);
    MdtBodySetMass(body, 2);
    assertUnchanged();
}

static void damping_axes_quaternions_rotations(void **state)
{
    (void)state;
    assert_reports(ME_ERR_NEGATIVE_DAMPING, MdtBodySetLinearVelocityDamping(body, -0.1f));
    assert_string_equal(karma_last_function(), "MdtBodySetLinearVelocityDamping");
    assert_reports(ME_ERR_NEGATIVE_DAMPING, MdtBodySetAngularVelocityDamping(body, -2));
    assert_reports(ME_ERR_ZERO_AXIS, MdtBodySetFastSpinAxis(body, 0, 0, 0));
    assert_false(MdtBodyFastSpinAxisIsEnabled(body));
    assert_reports(ME_ERR_QUATERNION_NOT_UNIT, MdtBodySetQuaternion(body, 1, 0.5f, 0, 0));
    assert_string_equal(karma_last_function(), "MdtBodySetQuaternion");
    /* Within tolerance: accepted and renormalised. */
    MdtBodySetQuaternion(body, 1.0005f, 0, 0, 0);
    MeVector4 q;
    MdtBodyGetQuaternion(body, q);
    assert_near(q[0], 1, 1e-6);
    MeMatrix3 sheared = {{1, 0.2f, 0}, {0, 1, 0}, {0, 0, 1}};
    MeMatrix3 mirrored = {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    assert_reports(ME_ERR_NOT_ROTATION, MdtBodySetOrientation(body, sheared));
    assert_reports(ME_ERR_NOT_ROTATION, MdtBodySetOrientation(body, mirrored));
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 1, 0}, {5, 5, 5, 1}};
    assert_reports(ME_ERR_NOT_ROTATION, MdtBodySetTransform(body, tm));
    assertUnchanged();
}

static void world_settings(void **state)
{
    (void)state;
    assert_reports(ME_ERR_SCALE_NOT_POSITIVE, assert_null(MdtWorldCreate(10, 10, 0, 1)));
    assert_reports(ME_ERR_SCALE_NOT_POSITIVE, assert_null(MdtWorldCreate(10, 10, 1, (MeReal)NAN)));
    assert_reports(ME_ERR_STEP_SIZE, MdtWorldStep(world, 0));
    assert_reports(ME_ERR_STEP_SIZE, MdtWorldStep(world, -0.01f));
    assert_reports(ME_ERR_STEP_SIZE, MdtWorldStep(world, (MeReal)NAN));
    assertUnchanged(); /* a rejected step does not move anything */
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetEpsilon(world, 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetGamma(world, 1.5f));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetMaxLCPIterations(world, 0));
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtWorldSetAutoDisableVelocityThreshold(world, -1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtWorldSetAutoDisableAliveTime(world, (MeReal)INFINITY));
    assert_near(MdtWorldGetEpsilon(world), 0.01, 1e-9);
    assert_near(MdtWorldGetGamma(world), 0.2, 1e-7);
    assert_int_equal(MdtWorldGetMaxLCPIterations(world), 10);
    assert_near(MdtWorldGetAutoDisableAliveTime(world), 0.2, 1e-7);
}

static void full_pool_returns_null_and_recovers(void **state)
{
    (void)state;
    MdtBodyID more[3];
    for (int i = 0; i < 3; i++)
        assert_non_null(more[i] = MdtBodyCreate(world)); /* 1 + 3 = maxBodies */
    assert_reports(ME_ERR_POOL_FULL, assert_null(MdtBodyCreate(world)));
    assert_string_equal(karma_last_function(), "MdtBodyCreate");
    assert_non_null(strstr(karma_last_text(), "maxBodies"));
    assert_int_equal(MdtWorldGetTotalBodies(world), 4);
    /* Still usable: steps, and a destroyed slot can be reused. */
    MdtWorldStep(world, ME_R(1.0) / 60);
    MdtBodyDestroy(more[1]);
    MdtBodyID again = MdtBodyCreate(world);
    assert_non_null(again);
    assert_true(again != more[1]); /* same slot, new generation: a different ID */
    MdtWorldCounters c;
    MdtWorldGetCounters(world, &c);
    assert_int_equal(c.bodyPoolHighWater, 4);
}

static void stale_foreign_and_made_up_ids(void **state)
{
    (void)state;
    MdtBodyID victim = MdtBodyCreate(world);
    MdtBodySetPosition(victim, 7, 7, 7);
    MdtBodyDestroy(victim);
    assert_false(MdtBodyIsValid(victim));
    assert_reports(ME_ERR_INVALID_HANDLE, MdtBodySetPosition(victim, 0, 0, 0));
    assert_string_equal(karma_last_function(), "MdtBodySetPosition");
    assert_reports(ME_ERR_INVALID_HANDLE, MdtBodyDestroy(victim));
    assert_reports(ME_ERR_INVALID_HANDLE, assert_near(MdtBodyGetMass(victim), 0, 0));
    /* The slot is reused: the old ID still does not reach the new body. */
    MdtBodyID reuse = MdtBodyCreate(world);
    MdtBodySetPosition(reuse, 9, 9, 9);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtBodySetPosition(victim, 1, 1, 1));
    MeVector3 p;
    MdtBodyGetPosition(reuse, p);
    assert_near(p[0], 9, 0);
    /* A world ID passed as a body ID, a made-up value, NULL. */
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, MdtBodyEnable((MdtBodyID)(void *)world));
    assert_reports(ME_ERR_INVALID_HANDLE, MdtBodyEnable((MdtBodyID)(uintptr_t)0x12345));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtBodyEnable(NULL));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtWorldStep(NULL, 0.01f));
    /* Bodies of a destroyed world, and the world itself. */
    MdtWorldID other = MdtWorldCreate(2, 2, 1, 1);
    MdtBodyID foreign = MdtBodyCreate(other);
    assert_true(MdtBodyIsValid(foreign));
    MdtWorldDestroy(other);
    assert_false(MdtWorldIsValid(other));
    assert_reports(ME_ERR_INVALID_HANDLE, MdtBodySetPosition(foreign, 0, 0, 0));
    assert_reports(ME_ERR_INVALID_HANDLE, MdtWorldStep(other, 0.01f));
    assert_reports(ME_ERR_INVALID_HANDLE, MdtWorldDestroy(other));
    assertUnchanged();
}

static void nonfinite_state_is_contained(void **state)
{
    (void)state;
    /* Two forces near FLT_MAX overflow the accumulator: the body's step fails. */
    MdtBodyID bystander = MdtBodyCreate(world);
    MdtBodyEnable(bystander);
    MdtBodySetLinearVelocity(bystander, 1, 0, 0);
    MdtWorldSetAutoDisable(world, MEFALSE);
    MdtBodyAddForce(body, (MeReal)(0.9 * MEINFINITY), 0, 0);
    MdtBodyAddForce(body, (MeReal)(0.9 * MEINFINITY), 0, 0);
    assert_reports(ME_ERR_NONFINITE_STATE, MdtWorldStep(world, ME_R(1.0) / 60));
    assert_false(MdtBodyIsEnabled(body));
    MeVector3 p, v;
    MdtBodyGetPosition(body, p);
    MdtBodyGetLinearVelocity(body, v);
    assert_near(p[0], 1, 0); /* back where the step started, stopped */
    assert_near(MeVector3Magnitude(v), 0, 0);
    /* The other partition went on. */
    MdtBodyGetPosition(bystander, p);
    assert_near(p[0], 1.0 / 60, 1e-6);
    assert_true(MdtBodyIsEnabled(bystander));
}

static void step_allocates_nothing_after_warm_up(void **state)
{
    (void)state;
    MdtWorldSetGravity(world, 0, 0, -9.81f);
    MdtWorldStep(world, ME_R(1.0) / 60);
    MeMemoryStats before, after;
    MeMemoryGetStats(&before);
    for (int i = 0; i < 100; i++)
        MdtWorldStep(world, ME_R(1.0) / 60);
    MeMemoryGetStats(&after);
    assert_int_equal(after.allocations, before.allocations);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(nonfinite_values_are_rejected, setup, teardown),
        cmocka_unit_test_setup_teardown(masses_and_inertia, setup, teardown),
        cmocka_unit_test_setup_teardown(damping_axes_quaternions_rotations, setup, teardown),
        cmocka_unit_test_setup_teardown(world_settings, setup, teardown),
        cmocka_unit_test_setup_teardown(full_pool_returns_null_and_recovers, setup, teardown),
        cmocka_unit_test_setup_teardown(stale_foreign_and_made_up_ids, setup, teardown),
        cmocka_unit_test_setup_teardown(nonfinite_state_is_contained, setup, teardown),
        cmocka_unit_test_setup_teardown(step_allocates_nothing_after_warm_up, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
