/* Body and world accessors of docs/karma12.md §5.1–5.2 that the other tests do not reach: user data, sort key,
 * accelerations over the last step, clearing forces and impulses (per body and for the world), reset
 * to the creation defaults, γ from a reference step, the auto-disable thresholds stored. */
#include "karma_test.h"

#include <karma/Mdt.h>

static const double G = 9.81, H = 1.0 / 60;

static void body_accessors(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-G);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodyEnable(b);

    int tag = 3;
    assert_null(MdtBodyGetUserData(b));
    MdtBodySetUserData(b, &tag);
    assert_ptr_equal(MdtBodyGetUserData(b), &tag);
    assert_int_equal(MdtBodyGetSortKey(b), 0);
    MdtBodySetSortKey(b, 9);
    assert_int_equal(MdtBodyGetSortKey(b), 9);

    /* Accelerations over the last step: gravity plus 2 N along x on 1 kg; 0.5 N m about z on the
     * default inertia 0.4. */
    MdtBodyAddForce(b, 2, 0, 0);
    MdtBodyAddTorque(b, 0, 0, 0.5f);
    MeVector3 f, t;
    MdtBodyGetForce(b, f);
    MdtBodyGetTorque(b, t);
    assert_true(f[0] == 2 && t[2] == (MeReal)0.5);
    MdtWorldStep(w, (MeReal)H);
    MeVector3 a, alpha;
    MdtBodyGetLinearAcceleration(b, a);
    MdtBodyGetAngularAcceleration(b, alpha);
    print_message("accelerations: (%.5f, %.5f, %.5f) m/s^2, (%.5f, %.5f, %.5f) rad/s^2\n", a[0], a[1], a[2], alpha[0],
                  alpha[1], alpha[2]);
    assert_near(a[0], 2, ME_TOL(1e-9, 1e-4));
    assert_near(a[2], -G, ME_TOL(1e-9, 1e-4));
    assert_near(alpha[2], 0.5 / 0.4, ME_TOL(1e-9, 1e-4));
    MdtBodyGetForce(b, f);
    assert_true(f[0] == 0 && f[1] == 0 && f[2] == 0); /* cleared by the step */

    /* ResetForces / ResetImpulses / MdtWorldResetForces drop what was accumulated. */
    MeVector3 v0, v;
    MdtBodyGetLinearVelocity(b, v0);
    MdtBodyAddForce(b, 100, 0, 0);
    MdtBodyAddTorque(b, 0, 100, 0);
    MdtBodyResetForces(b);
    MdtBodyAddImpulse(b, 0, 50, 0);
    MdtBodyResetImpulses(b);
    MdtBodyID other = MdtBodyCreate(w);
    MdtBodyEnable(other);
    MdtBodyAddForce(other, 0, 100, 0);
    MdtWorldResetForces(w);
    MdtWorldStep(w, (MeReal)H);
    MdtBodyGetLinearVelocity(b, v);
    assert_near(v[0] - v0[0], 0, 1e-6);
    assert_near(v[1] - v0[1], 0, 1e-6);
    MdtBodyGetLinearVelocity(other, v);
    assert_near(v[1], 0, 1e-6);

    /* Reset restores the creation defaults, keeping user data and the enabled state. */
    MdtBodySetMass(b, 3);
    MdtBodySetLinearVelocityDamping(b, 0.5f);
    MdtBodySetPosition(b, 1, 2, 3);
    MdtBodyReset(b);
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    MdtBodyGetLinearVelocity(b, v);
    assert_true(MdtBodyGetMass(b) == 1);
    assert_true(MdtBodyGetLinearVelocityDamping(b) == 0);
    assert_true(p[0] == 0 && p[1] == 0 && p[2] == 0);
    assert_true(v[0] == 0 && v[1] == 0 && v[2] == 0);
    assert_ptr_equal(MdtBodyGetUserData(b), &tag);
    assert_true(MdtBodyIsEnabled(b));
    assert_int_equal(karma_warning_count(), 0);
    MdtWorldDestroy(w);
}

static void world_settings_stored(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    /* Karma's auto-disable defaults (docs/karma12.md §5.1, D1), then each setter stores its value. */
    assert_true(MdtWorldGetAutoDisable(w));
    assert_near(MdtWorldGetAutoDisableVelocityThreshold(w), 0.02, 1e-7);
    assert_near(MdtWorldGetAutoDisableAngularVelocityThreshold(w), 0.001, 1e-9);
    assert_near(MdtWorldGetAutoDisableAccelerationThreshold(w), 0.05, 1e-7);
    assert_near(MdtWorldGetAutoDisableAngularAccelerationThreshold(w), 0.05, 1e-7);
    assert_near(MdtWorldGetAutoDisableAliveTime(w), 0.2, 1e-7);
    MdtWorldSetAutoDisableAngularVelocityThreshold(w, 0.01f);
    MdtWorldSetAutoDisableAccelerationThreshold(w, 0.3f);
    MdtWorldSetAutoDisableAngularAccelerationThreshold(w, 0.4f);
    assert_near(MdtWorldGetAutoDisableAngularVelocityThreshold(w), 0.01, 1e-7);
    assert_near(MdtWorldGetAutoDisableAccelerationThreshold(w), 0.3, 1e-7);
    assert_near(MdtWorldGetAutoDisableAngularAccelerationThreshold(w), 0.4, 1e-7);
    /* γ chosen for a reference step, rescaled to the step used: γ = 0.2 × (1/120) / (1/60). */
    MdtWorldSetGammaWithRefTimeStep(w, 0.2f, 1.0f / 60, 1.0f / 120);
    assert_near(MdtWorldGetGamma(w), 0.1, 1e-6);
    assert_near(MdtWorldGetLengthScale(w), 1, 0);
    assert_near(MdtWorldGetMassScale(w), 1, 0);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(body_accessors),
        cmocka_unit_test(world_settings_stored),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
