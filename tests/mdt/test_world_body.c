/* World and body API: Karma's defaults, accessors, iteration, callbacks, auto-disable, profile. */
#include "karma_test.h"

#include <string.h>

#include <karma/Mdt.h>

static void defaults_follow_karma(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(10, 20, 2, 5); /* lengthScale 2, massScale 5 */
    MeVector3 g;
    MdtWorldGetGravity(w, g);
    assert_near(MeVector3Magnitude(g), 0, 0);
    assert_near(MdtWorldGetEpsilon(w), 0.01 / 5, 1e-9);
    assert_near(MdtWorldGetGamma(w), 0.2, 1e-7);
    assert_int_equal(MdtWorldGetMaxLCPIterations(w), 10);
    assert_true(MdtWorldGetAutoDisable(w));
    assert_near(MdtWorldGetAutoDisableVelocityThreshold(w), 0.02 * 4, 1e-7);
    assert_near(MdtWorldGetAutoDisableAngularVelocityThreshold(w), 0.001, 1e-9);
    assert_near(MdtWorldGetAutoDisableAccelerationThreshold(w), 0.05 * 4, 1e-7);
    assert_near(MdtWorldGetAutoDisableAngularAccelerationThreshold(w), 0.05, 1e-7);
    assert_near(MdtWorldGetAutoDisableAliveTime(w), 0.2, 1e-7);
    assert_near(MdtWorldGetDefaultDensity(w), 5.0 / 8, 1e-7);
    assert_int_equal(MdtWorldGetMaxBodies(w), 10);
    assert_int_equal(MdtWorldGetMaxConstraints(w), 20);

    MdtBodyID b = MdtBodyCreate(w);
    assert_false(MdtBodyIsEnabled(b)); /* created disabled */
    assert_near(MdtBodyGetMass(b), 5, 0);
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(b, I);
    assert_near(I[0][0], 0.4 * 5 * 4, 1e-6);
    assert_near(I[0][1], 0, 0);
    MeVector4 q;
    MdtBodyGetQuaternion(b, q);
    assert_near(q[0], 1, 0);
    MeVector3 axis;
    MdtBodyGetFastSpinAxis(b, axis);
    assert_near(axis[1], 1, 0);
    assert_false(MdtBodyFastSpinAxisIsEnabled(b));
    assert_false(MdtBodyNonSphericalInertiaIsEnabled(b));
    assert_false(MdtBodyCoriolisForceIsEnabled(b));
    assert_near(MdtBodyGetLinearVelocityDamping(b), 0, 0);
    assert_int_equal(MdtBodyGetPartition(b), -1);
    assert_int_equal(MdtWorldGetEnabledBodies(w), 0);
    MdtBodyEnable(b);
    assert_int_equal(MdtWorldGetEnabledBodies(w), 1);
    MdtWorldDestroy(w);
}

static void state_accessors_agree(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MeMatrix4Ptr tm = MdtBodyGetTransformPtr(b);
    MdtBodySetPosition(b, 1, -2, 3);
    MdtBodySetQuaternion(b, 0.5f, 0.5f, 0.5f, 0.5f); /* 120° about (1,1,1): x→y→z→x */
    /* The stable pointer sees every change; rows are the body axes in the world. */
    assert_near(tm[3][0], 1, 0);
    assert_near(tm[0][1], 1, 1e-6); /* body x axis = world y */
    assert_near(tm[1][2], 1, 1e-6); /* body y axis = world z */
    MeMatrix3 R;
    MdtBodyGetOrientation(b, R);
    assert_near(R[2][0], 1, 1e-6);
    MeMatrix4 copy;
    MdtBodyGetTransform(b, copy);
    assert_memory_equal(copy, tm, sizeof copy);
    MdtBodySetTransform(b, copy); /* round trip */
    assert_near(tm[3][1], -2, 1e-6);

    MdtBodySetLinearVelocity(b, 1, 0, 0);
    MdtBodySetAngularVelocity(b, 0, 0, 2);
    MeVector3 p = {1, 0, 3}, v; /* 2 m along -y... the point (1,0,3) is +2 y from the COM at (1,-2,3) */
    MdtBodyGetVelocityAtPoint(b, p, v);
    assert_near(v[0], 1 - 2 * 2, 1e-6); /* v + ω × r = (1,0,0) + (0,0,2)×(0,2,0) = (1-4, 0, 0) */
    assert_near(v[1], 0, 1e-6);
    assert_near(MdtBodyGetKineticEnergy(b), 0.5 * 1 * 1 + 0.5 * 0.4 * 4, 1e-6);

    /* Directions and points between frames. */
    MeVector3 ex = {1, 0, 0}, out;
    MdtConvertVector(b, ex, NULL, out);
    assert_near(out[1], 1, 1e-6);
    MdtConvertVector(NULL, out, b, out);
    assert_near(out[0], 1, 1e-6);
    MdtConvertPositionVector(b, ex, NULL, out);
    assert_near(out[0], 1, 1e-6);
    assert_near(out[1], -1, 1e-6);

    /* Copy: same state, disabled, in another world. */
    MdtWorldID w2 = MdtWorldCreate(2, 2, 1, 1);
    MdtBodyEnable(b);
    MdtBodyID c = MdtBodyCopy(b, w2);
    assert_non_null(c);
    assert_false(MdtBodyIsEnabled(c));
    assert_true(MdtBodyGetWorld(c) == w2);
    MeVector3 pc;
    MdtBodyGetPosition(c, pc);
    assert_near(pc[1], -2, 1e-6);
    MdtWorldDestroy(w2);
    MdtWorldDestroy(w);
}

static void iteration_in_slot_order(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(5, 1, 1, 1);
    MdtBodyID b[5];
    for (int i = 0; i < 5; i++)
        b[i] = MdtBodyCreate(w);
    MdtBodyDestroy(b[2]);
    int n = 0;
    for (MdtBodyID it = MdtBodyGetFirst(w); it; it = MdtBodyGetNext(it))
        assert_true(it == b[n++ == 2 ? n++ : n - 1]);
    assert_int_equal(n, 5);
    assert_int_equal(MdtWorldGetTotalBodies(w), 4);
    MdtWorldReset(w);
    assert_int_equal(MdtWorldGetTotalBodies(w), 0);
    assert_false(MdtBodyIsValid(b[0]));
    assert_null(MdtBodyGetFirst(w));
    MdtWorldDestroy(w);
}

static int enables, disables;
static void onEnable(MdtBodyID b, void *data)
{
    (void)b;
    (*(int *)data)++;
    enables++;
}
static void onDisable(MdtBodyID b, void *data)
{
    (void)b;
    (void)data;
    disables++;
}

/* A body at rest sleeps after the alive window; a falling one never does. Karma 1.2's last-step test
 * (averaging time 0); the averaged test waits for its averaging time too (test_auto_disable.c). */
static void auto_disable_after_alive_time(void **state)
{
    (void)state;
    int tag = 0;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetAutoDisableAveragingTime(w, 0);
    MdtWorldSetBodyEnableCallback(w, onEnable, &tag);
    MdtWorldSetBodyDisableCallback(w, onDisable, NULL);
    MdtBodyID still = MdtBodyCreate(w), moving = MdtBodyCreate(w);
    MdtBodyEnable(still);
    MdtBodyEnable(moving);
    assert_int_equal(enables, 2);
    assert_int_equal(tag, 2);
    MdtBodySetLinearVelocity(moving, 0, 0.5f, 0); /* 0.25 m²/s² > 0.02 */
    const MeReal h = ME_R(1.0) / 60;
    int stepsAwake = 0;
    while (MdtBodyIsEnabled(still) && stepsAwake < 100) {
        MdtWorldStep(w, h);
        stepsAwake++;
    }
    /* Disabled at the first step whose start finds it enabled for longer than 0.2 s. */
    assert_int_equal(stepsAwake, 14);
    assert_near(MdtBodyGetEnabledTime(still), 13 * h, 1e-5);
    assert_int_equal(disables, 1);
    for (int i = 0; i < 60; i++)
        MdtWorldStep(w, h);
    assert_true(MdtBodyIsEnabled(moving));
    assert_int_equal(MdtWorldGetEnabledBodies(w), 1);
    /* A force does not wake a disabled body; it is kept until the body is enabled. */
    MdtBodyAddForce(still, 60, 0, 0);
    MdtWorldStep(w, h);
    assert_false(MdtBodyIsEnabled(still));
    MeVector3 f;
    MdtBodyGetForce(still, f);
    assert_near(f[0], 60, 0);
    MdtBodyEnable(still);
    MdtWorldStep(w, h);
    MeVector3 v;
    MdtBodyGetLinearVelocity(still, v);
    assert_near(v[0], 1, 1e-6);
    MdtWorldDestroy(w);
}

/* A clock that advances one tick each time it is read: a step reads it where the step begins and at
 * the end of each stage (one reading ends a stage and starts the next, and the last one ends the
 * step), so a section's time counts the clock reads from its start to its end, exactly. */
#define TICK (1.0 / 1024)
static double tickClockNow;
static double tickClock(void)
{
    tickClockNow += TICK;
    return tickClockNow;
}

static void profile_has_every_stage(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyEnable(MdtBodyCreate(w));
    MeProfileSetTimer(MdtWorldGetProfilePtr(w), tickClock);
    MdtWorldStep(w, 0.01f);
    MdtWorldStep(w, 0.01f);
    const MeProfile *p = MdtWorldGetProfile(w);
    const char *stages[] = {"Partition", "AutoDisable", "Pack", "Solve", "Integrate", "Unpack"};
    double stagesTotal = 0;
    for (unsigned i = 0; i < sizeof stages / sizeof stages[0]; i++) {
        const MeProfileSection *s = MeProfileGetSection(p, stages[i]);
        assert_non_null(s);
        assert_int_equal(s->calls, 2);
        /* each call is timed: at least the one tick between its own start and end */
        assert_true(s->totalTime >= 2 * TICK);
        stagesTotal += s->totalTime;
    }
    /* Dynamics is timed around the stages: from the first stage's start to the last one's end. */
    const MeProfileSection *dynamics = MeProfileGetSection(p, "Dynamics");
    assert_non_null(dynamics);
    assert_int_equal(dynamics->calls, 2);
    assert_true(dynamics->totalTime >= stagesTotal - 1e-12);
    MdtWorldCounters c;
    MdtWorldGetCounters(w, &c);
    assert_int_equal(c.steps, 2);
    assert_int_equal(c.partitions, 1);
    assert_near(c.time, 0.02, 1e-7);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults_follow_karma),
        cmocka_unit_test(state_accessors_agree),
        cmocka_unit_test(iteration_in_slot_order),
        cmocka_unit_test(auto_disable_after_alive_time),
        cmocka_unit_test(profile_has_every_stage),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
