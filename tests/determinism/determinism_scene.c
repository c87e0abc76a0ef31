/* determinism_scene.c -- the golden-hash test: a scene that uses every body feature gives
 * bit-identical states run after run, at -O0 and at -O2, equal to a hash recorded in this file.
 *
 * tests/cmake/determinism.cmake builds this file twice, each time with its own copy of the core
 * library compiled at -O0 or at -O2 (both with -ffp-contract=off and no fast-math). Each program runs
 * the scene twice and compares the FNV-1a hash of every body's state (position, quaternion, linear
 * and angular velocity, enabled flag) after every step with the golden value of its precision.
 * (This file is not named test_*.c, so the ordinary test glob leaves it to determinism.cmake.)
 *
 * The scene: no world gravity; a thrown body pulled down by a force applied every step with an offset
 * centre of mass; an asymmetric box with a full inertia tensor and the gyroscopic term; a wheel with a
 * fast-spin axis; a damped body that slows down until auto-disable puts it to sleep; impulses at a
 * point and torques at scripted steps. When the constraint, collision and bridge layers land, extend
 * the scene (joints of every family, contacts with friction and restitution, partitions) and record
 * new golden values.
 *
 * If the hash changes on purpose, run the program with KARMA_DETERMINISM_PRINT=1 to print the new
 * value; to find where two builds diverge, KARMA_DETERMINISM_TRACE=1 prints the hash after each step
 * (diff the outputs of the -O0 and -O2 programs). */
#include <stdlib.h>
#include <string.h>

#include "karma_test.h"

#include <karma/karma.h>

#define STEPS 300
#define STEP_SIZE (ME_R(1.0) / 60)

/* Golden values: the hash after STEPS steps, per precision. */
#if KARMA_DOUBLE
#  define GOLDEN_HASH 0xaa559e7ec3927a6aull
#else
#  define GOLDEN_HASH 0x0456161e7e0f5c42ull
#endif

typedef struct Scene {
    MdtWorldID world;
    MdtBodyID thrown, tumbler, wheel, damped;
} Scene;

static void buildScene(Scene *s)
{
    MeMatrix3 I, Q, box;
    s->world = MdtWorldCreate(8, 8, ME_R(1.0), ME_R(1.0));
    assert_non_null(s->world);

    s->thrown = MdtBodyCreate(s->world);
    MdtBodySetMass(s->thrown, ME_R(2.0));
    MdtBodySetSphericalInertiaTensor(s->thrown, ME_R(0.3));
    MeVector3 com = {ME_R(0.1), ME_R(-0.05), ME_R(0.02)};
    MdtBodySetCenterOfMassRelativePosition(s->thrown, com);
    MdtBodySetPosition(s->thrown, 0, ME_R(1.0), 0);
    MdtBodySetLinearVelocity(s->thrown, ME_R(3.0), ME_R(7.0), ME_R(-1.0));
    MdtBodySetAngularVelocity(s->thrown, ME_R(0.5), ME_R(-2.0), ME_R(1.0));

    s->tumbler = MdtBodyCreate(s->world);
    MdtMakeInertiaTensorBox(ME_R(3.0), ME_R(0.4), ME_R(1.5), ME_R(0.8), box);
    MeMatrix3FromEulerAngles(Q, ME_R(0.3), ME_R(-0.2), ME_R(0.7));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            I[i][j] = 0;
            for (int k = 0; k < 3; k++)
                I[i][j] += Q[k][i] * box[k][k] * Q[k][j];
        }
    MdtBodySetMass(s->tumbler, ME_R(3.0));
    MdtBodySetInertiaTensor(s->tumbler, I);
    MdtBodyEnableNonSphericalInertia(s->tumbler);
    MdtBodyEnableCoriolisForce(s->tumbler);
    MdtBodySetQuaternion(s->tumbler, ME_R(0.8), ME_R(0.6), 0, 0);
    MdtBodySetAngularVelocity(s->tumbler, ME_R(0.05), ME_R(3.0), ME_R(-1.0));

    s->wheel = MdtBodyCreate(s->world);
    MeMatrix3MakeIdentity(I);
    I[0][0] = I[2][2] = ME_R(0.12);
    I[1][1] = ME_R(0.22);
    MdtBodySetMass(s->wheel, ME_R(5.0));
    MdtBodySetInertiaTensor(s->wheel, I);
    MdtBodyEnableNonSphericalInertia(s->wheel);
    MdtBodyEnableCoriolisForce(s->wheel);
    MdtBodySetPosition(s->wheel, ME_R(2.0), 0, 0);
    MdtBodySetAngularVelocity(s->wheel, 0, ME_R(120.0), 0);

    s->damped = MdtBodyCreate(s->world);
    MdtBodySetMass(s->damped, ME_R(1.0));
    MdtBodySetLinearVelocityDamping(s->damped, ME_R(2.0));
    MdtBodySetAngularVelocityDamping(s->damped, ME_R(1.0));
    MdtBodySetPosition(s->damped, ME_R(-2.0), 0, 0);
    MdtBodySetLinearVelocity(s->damped, ME_R(4.0), ME_R(-1.0), ME_R(0.5));
    MdtBodySetAngularVelocity(s->damped, ME_R(1.0), ME_R(2.0), ME_R(-0.5));

    MdtBodyEnable(s->thrown);
    MdtBodyEnable(s->tumbler);
    MdtBodyEnable(s->wheel);
    MdtBodyEnable(s->damped);
}

static void scriptStep(const Scene *s, int step)
{
    MdtBodyAddForce(s->thrown, 0, ME_R(-9.81) * ME_R(2.0), 0); /* gravity on this body only */
    MdtBodySetFastSpinAxis(s->wheel, 0, 1, 0);
    if (step == 40)
        MdtBodyAddImpulseAtPosition(s->thrown, ME_R(0.5), 0, ME_R(-0.25), ME_R(0.2), ME_R(1.5), ME_R(0.1));
    if (step >= 60 && step < 90)
        MdtBodyAddTorque(s->tumbler, ME_R(0.2), 0, ME_R(-0.1));
    if (step == 100)
        MdtBodyAddForceAtPosition(s->wheel, ME_R(3.0), 0, 0, ME_R(2.0), ME_R(0.3), 0);
}

/* Run the scene; returns the hash chained over every step's state. */
static uint64_t runScene(MeBool *dampedSlept, MeBool trace)
{
    Scene s;
    buildScene(&s);
    uint64_t hash = KARMA_HASH_INIT;
    for (int step = 0; step < STEPS; step++) {
        scriptStep(&s, step);
        MdtWorldStep(s.world, STEP_SIZE);
        hash = karma_hash_world(hash, s.world);
        if (trace)
            printf("step %3d hash 0x%016llx\n", step, (unsigned long long)hash);
    }
    *dampedSlept = !MdtBodyIsEnabled(s.damped);
    assert_true(MdtBodyIsEnabled(s.thrown)); /* still moving: never at rest */
    MdtWorldDestroy(s.world);
    return hash;
}

static void test_same_hash_twice_and_golden(void **state)
{
    (void)state;
    karma_capture_messages();
    MeBool trace = getenv("KARMA_DETERMINISM_TRACE") != NULL;
    MeBool slept1 = MEFALSE, slept2 = MEFALSE;
    uint64_t first = runScene(&slept1, trace);
    uint64_t second = runScene(&slept2, MEFALSE);
    print_message("state hash after %d steps: 0x%016llx (run 1), 0x%016llx (run 2), golden 0x%016llx (%s)\n",
                  STEPS, (unsigned long long)first, (unsigned long long)second, (unsigned long long)GOLDEN_HASH,
                  KARMA_DOUBLE ? "double" : "float");
    if (getenv("KARMA_DETERMINISM_PRINT"))
        printf("#  define GOLDEN_HASH 0x%016llxull\n", (unsigned long long)first);
    assert_int_equal(karma_warning_count(), 0);
    /* the scene really exercises auto-disable */
    assert_true(slept1);
    assert_true(slept2);
    assert_true(first == second);
    assert_true(first == GOLDEN_HASH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_hash_twice_and_golden),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
