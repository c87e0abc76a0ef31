/* Free bodies against analytic answers and against the integrator's own discrete recurrence.
 *
 * Karma integrates velocities, then positions (symplectic Euler): v_{n+1} = v_n + h g,
 * x_{n+1} = x_n + h v_{n+1}. So after n steps x_n = x_0 + n h v_0 + h² g n(n+1)/2, which differs
 * from the continuous x(t) = x_0 + v_0 t + ½ g t² by exactly ½ g h t: first order in h. */
#include "karma_test.h"

#include <karma/Mdt.h>

static MdtWorldID makeWorld(void)
{
    MdtWorldID w = MdtWorldCreate(16, 16, 1, 1);
    assert_non_null(w);
    MdtWorldSetAutoDisable(w, MEFALSE);
    return w;
}

static MdtBodyID makeBody(MdtWorldID w)
{
    MdtBodyID b = MdtBodyCreate(w);
    assert_non_null(b);
    MdtBodyEnable(b);
    return b;
}

static void freeFallAt(double h, int steps)
{
    const double g = -9.81, z0 = 100, vz0 = 3;
    MdtWorldID w = makeWorld();
    MdtWorldSetGravity(w, 0, 0, (MeReal)g);
    MdtBodyID b = makeBody(w);
    MdtBodySetPosition(b, 0, 0, (MeReal)z0);
    MdtBodySetLinearVelocity(b, 0, 0, (MeReal)vz0);
    /* The discrete recurrence computed in double, step by step, as the engine does it. */
    double z = z0, v = vz0;
    for (int n = 1; n <= steps; n++) {
        MdtWorldStep(w, (MeReal)h);
        v += h * g;
        z += h * v;
    }
    MeVector3 p, vel;
    MdtBodyGetPosition(b, p);
    MdtBodyGetLinearVelocity(b, vel);
    double t = h * steps;
    double closed = z0 + steps * h * vz0 + h * h * g * steps * (steps + 1) / 2.0;
    assert_near(z, closed, 1e-9);
    /* Matches its own recurrence to rounding... */
    assert_near(p[2], z, ME_TOL(1e-9, 2e-6 * steps * fabs(z)));
    assert_near(vel[2], v, ME_TOL(1e-11, 2e-7 * steps * fabs(v)));
    assert_near(p[0], 0, 0);
    /* ...and the continuous answer to first order: the error is ½ g h t, as predicted. */
    double continuous = z0 + vz0 * t + 0.5 * g * t * t;
    assert_near(p[2] - continuous, 0.5 * g * h * t, ME_TOL(1e-8, 3e-4));
    print_message("free fall h=%.5f t=%.2f: |z - z(t)| = %.3e (predicted %.3e)\n", h, t, fabs(p[2] - continuous),
                  fabs(0.5 * g * h * t));
    MdtWorldDestroy(w);
}

static void free_fall_60(void **state)
{
    (void)state;
    freeFallAt(1.0 / 60, 120);
}

static void free_fall_240(void **state)
{
    (void)state;
    freeFallAt(1.0 / 240, 480);
}

/* Range of a projectile over flat ground (z = 0), found where the path crosses z = 0. */
static double projectileRange(double h, double speed, double angle, double *discrete)
{
    const double g = 9.81;
    MdtWorldID w = makeWorld();
    MdtWorldSetGravity(w, 0, 0, (MeReal)-g);
    MdtBodyID b = makeBody(w);
    MdtBodySetLinearVelocity(b, (MeReal)(speed * cos(angle)), 0, (MeReal)(speed * sin(angle)));
    MeVector3 prev = {0, 0, 0}, p;
    double x = 0, z = 0, vz = speed * sin(angle), px = 0, pz = 0;
    for (int n = 0; n < 100000; n++) {
        MdtWorldStep(w, (MeReal)h);
        MdtBodyGetPosition(b, p);
        px = x;
        pz = z;
        vz -= h * g;
        x += h * speed * cos(angle);
        z += h * vz;
        if (p[2] < 0)
            break;
        MeVector3Copy(prev, p);
    }
    double range = prev[0] + (p[0] - prev[0]) * prev[2] / (prev[2] - p[2]);
    *discrete = px + (x - px) * pz / (pz - z);
    MdtWorldDestroy(w);
    return range;
}

static void projectile_range(void **state)
{
    (void)state;
    const double speed = 20, angle = 0.6, g = 9.81;
    const double exact = speed * speed * sin(2 * angle) / g;
    double errors[2];
    double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++) {
        double discrete;
        double range = projectileRange(steps[i], speed, angle, &discrete);
        assert_near(range, discrete, ME_TOL(1e-9, 2e-3));
        errors[i] = fabs(range - exact);
        /* First order: the error is about v_x·h/2 (the path leads by half a step of fall). */
        assert_true(errors[i] < speed * steps[i]);
        print_message("range h=%.5f: %.6f vs %.6f (error %.2e)\n", steps[i], range, exact, errors[i]);
    }
    /* Four times smaller step, about four times smaller error. */
    assert_true(errors[1] < errors[0] / 3);
}

static void impulse_equals_force_over_one_step(void **state)
{
    (void)state;
    const MeReal h = ME_R(1.0) / 60;
    MdtWorldID w = makeWorld();
    MdtBodyID a = makeBody(w), b = makeBody(w);
    MdtBodySetMass(a, 2);
    MdtBodySetMass(b, 2);
    MdtBodyAddImpulseAtPosition(a, 3, -1, 2, 0.5f, 0.2f, -0.1f);
    MdtBodyAddForceAtPosition(b, 3 / h, -1 / h, 2 / h, 0.5f, 0.2f, -0.1f);
    MdtWorldStep(w, h);
    MeVector3 va, vb, wa, wb, pa, pb;
    MdtBodyGetLinearVelocity(a, va);
    MdtBodyGetLinearVelocity(b, vb);
    MdtBodyGetAngularVelocity(a, wa);
    MdtBodyGetAngularVelocity(b, wb);
    MdtBodyGetPosition(a, pa);
    MdtBodyGetPosition(b, pb);
    for (int k = 0; k < 3; k++) {
        assert_near(va[k], vb[k], ME_TOL(1e-12, 1e-5));
        assert_near(wa[k], wb[k], ME_TOL(1e-12, 1e-5));
        assert_near(pa[k], pb[k], ME_TOL(1e-12, 1e-6));
    }
    assert_near(va[0], 1.5, ME_TOL(1e-12, 1e-6)); /* Δv = J/m */
    /* Accumulators are cleared by the step: a second step changes nothing. */
    MdtWorldStep(w, h);
    MdtBodyGetLinearVelocity(a, vb);
    assert_near(vb[0], va[0], 0);
    MdtWorldDestroy(w);
}

static void damping_decays_at_the_stated_rate(void **state)
{
    (void)state;
    const double h = 1.0 / 60, m = 2, c = 0.8, i = 0.5, ca = 0.3;
    const int steps = 120;
    MdtWorldID w = makeWorld();
    MdtBodyID b = makeBody(w);
    MdtBodySetMass(b, (MeReal)m);
    MdtBodySetSphericalInertiaTensor(b, (MeReal)i);
    MdtBodySetLinearVelocityDamping(b, (MeReal)c);
    MdtBodySetAngularVelocityDamping(b, (MeReal)ca);
    MdtBodySetLinearVelocity(b, 4, 0, 0);
    MdtBodySetAngularVelocity(b, 0, 0, 10);
    for (int n = 0; n < steps; n++)
        MdtWorldStep(w, (MeReal)h);
    MeVector3 v, om;
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, om);
    double t = h * steps;
    /* Implicit drag: exactly 1/(1 + h c/m) per step... */
    assert_rel(v[0], 4 * pow(1 + h * c / m, -steps), ME_TOL(1e-10, 1e-5));
    assert_rel(om[2], 10 * pow(1 + h * ca / i, -steps), ME_TOL(1e-10, 1e-5));
    /* ...which is exp(-c t/m) to first order in h. */
    assert_rel(v[0], 4 * exp(-c * t / m), 0.5 * h * c / m * (c * t / m) + 1e-3);
    assert_rel(om[2], 10 * exp(-ca * t / i), 0.5 * h * ca / i * (ca * t / i) + 1e-3);
    MdtWorldDestroy(w);
}

/* Body-frame components of a world vector. */
static void toBody(MdtBodyID b, const MeVector3 world, MeVector3 local)
{
    MeMatrix3 R;
    MdtBodyGetOrientation(b, R);
    MeMatrix3TransposeMultiplyVector(local, R, world);
}

static void torque_free_asymmetric_body(void **state)
{
    (void)state;
    const MeReal h = ME_R(1.0) / 60;
    const double I[3] = {1, 2, 3};
    MdtWorldID w = makeWorld();
    MdtBodyID b = makeBody(w);
    MeMatrix3 tensor = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
    MdtBodySetInertiaTensor(b, tensor);
    MdtBodyEnableNonSphericalInertia(b);
    MdtBodyEnableCoriolisForce(b);
    MdtBodySetQuaternion(b, 0.9238795f, 0.3826834f, 0, 0); /* tilted 45° about x */
    /* Spin mostly about the intermediate (y) body axis: unstable, it must flip. */
    MeVector3 wb0 = {0.1f, 5, 0.1f}, w0;
    MeMatrix3 R;
    MdtBodyGetOrientation(b, R);
    MeMatrix3MultiplyVector(w0, R, wb0);
    MdtBodySetAngularVelocity(b, w0[0], w0[1], w0[2]);

    double L0[3], E0 = 0.5 * (I[0] * 0.01 + I[1] * 25 + I[2] * 0.01);
    MeVector3 Lw;
    MeVector3 Ib = {(MeReal)(I[0] * wb0[0]), (MeReal)(I[1] * wb0[1]), (MeReal)(I[2] * wb0[2])};
    MeMatrix3MultiplyVector(Lw, R, Ib);
    for (int k = 0; k < 3; k++)
        L0[k] = Lw[k];
    double L0mag = sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
    double worstL = 0, worstE = 0, worstDir = 0;
    int flips = 0;
    MeReal lastSign = 1;
    for (int n = 0; n < 600; n++) {
        MdtWorldStep(w, h);
        MeVector3 om, wb;
        MdtBodyGetAngularVelocity(b, om);
        toBody(b, om, wb);
        double Lb[3] = {I[0] * wb[0], I[1] * wb[1], I[2] * wb[2]};
        double Lmag = sqrt(Lb[0] * Lb[0] + Lb[1] * Lb[1] + Lb[2] * Lb[2]);
        double E = 0.5 * (I[0] * wb[0] * wb[0] + I[1] * wb[1] * wb[1] + I[2] * wb[2] * wb[2]);
        assert_near(MdtBodyGetKineticEnergy(b), E, 1e-3 * E0);
        worstL = fmax(worstL, fabs(Lmag - L0mag) / L0mag);
        worstE = fmax(worstE, fabs(E - E0) / E0);
        /* The world-frame angular momentum keeps its direction too. */
        MeVector3 LbR = {(MeReal)Lb[0], (MeReal)Lb[1], (MeReal)Lb[2]}, LwNow;
        MdtBodyGetOrientation(b, R);
        MeMatrix3MultiplyVector(LwNow, R, LbR);
        double cosang = (LwNow[0] * L0[0] + LwNow[1] * L0[1] + LwNow[2] * L0[2]) / (Lmag * L0mag);
        worstDir = fmax(worstDir, acos(fmin(1.0, cosang)));
        if (wb[1] * lastSign < 0) {
            flips++;
            lastSign = -lastSign;
        }
    }
    print_message("asymmetric body, 10 s at h=1/60: |L| error %.3f%%, energy error %.3f%%, L direction %.3f rad, "
                  "%d flips\n",
                  100 * worstL, 100 * worstE, worstDir, flips);
    assert_true(worstL < 0.01);
    assert_true(worstE < 0.02);
    assert_true(flips >= 2);
    MdtWorldDestroy(w);
}

static void force_through_com_does_not_rotate(void **state)
{
    (void)state;
    MdtWorldID w = makeWorld();
    MdtBodyID b = makeBody(w);
    MeVector3 offset = {0.5f, -0.25f, 0.1f}, com;
    MdtBodySetPosition(b, 1, 2, 3);
    MdtBodySetQuaternion(b, 0.8f, 0, 0.6f, 0);
    MdtBodySetCenterOfMassRelativePosition(b, offset);
    MdtBodyGetCenterOfMassPosition(b, com);
    /* The body frame did not move when the COM was placed. */
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    assert_near(p[0], 1, ME_TOL(1e-12, 1e-6));
    MeVector3 comExpected;
    MdtConvertPositionVector(b, offset, NULL, comExpected);
    for (int k = 0; k < 3; k++)
        assert_near(com[k], comExpected[k], ME_TOL(1e-12, 1e-5));
    for (int n = 0; n < 60; n++) {
        MdtBodyAddForceAtPosition(b, 0, 5, 2, com[0], com[1], com[2]);
        MdtWorldStep(w, ME_R(1.0) / 60);
        MdtBodyGetCenterOfMassPosition(b, com);
    }
    MeVector3 om;
    MdtBodyGetAngularVelocity(b, om);
    assert_near(MeVector3Magnitude(om), 0, ME_TOL(1e-12, 1e-5));
    /* The same force at the body origin (not the COM) does turn it: the test can fail. */
    MdtBodyGetPosition(b, p);
    MdtBodyAddForceAtPosition(b, 0, 5, 2, p[0], p[1], p[2]);
    MdtWorldStep(w, ME_R(1.0) / 60);
    MdtBodyGetAngularVelocity(b, om);
    assert_true(MeVector3Magnitude(om) > 0.01f);
    MdtWorldDestroy(w);
}

/* A wheel spinning at 100 rad/s about its axle (body y): with the fast-spin axis it turns at its
 * true rate and keeps its axis; the plain first-order update turns it too slowly. */
static double spinWheel(MeBool fastSpin, double *axisError)
{
    const MeReal h = ME_R(1.0) / 60;
    MdtWorldID w = makeWorld();
    MdtBodyID b = makeBody(w);
    MeMatrix3 I = {{0.25f, 0, 0}, {0, 0.5f, 0}, {0, 0, 0.25f}};
    MdtBodySetInertiaTensor(b, I);
    MdtBodyEnableNonSphericalInertia(b);
    MdtBodyEnableCoriolisForce(b);
    MdtBodySetAngularVelocity(b, 0, 100, 0);
    double angle = 0;
    *axisError = 0;
    MeVector4 prev;
    MdtBodyGetQuaternion(b, prev);
    for (int n = 0; n < 60; n++) {
        MeMatrix3 R;
        MdtBodyGetOrientation(b, R);
        if (fastSpin)
            MdtBodySetFastSpinAxis(b, R[1][0], R[1][1], R[1][2]);
        MdtWorldStep(w, h);
        MeVector4 q, conj, rel;
        MdtBodyGetQuaternion(b, q);
        MeVector4Set(conj, prev[0], -prev[1], -prev[2], -prev[3]);
        MeQuaternionProduct(rel, q, conj);
        angle += 2 * atan2(sqrt(rel[1] * rel[1] + rel[2] * rel[2] + rel[3] * rel[3]), fabs(rel[0]));
        MeVector4Copy(prev, q);
        MdtBodyGetOrientation(b, R);
        *axisError = fmax(*axisError, sqrt(R[1][0] * R[1][0] + R[1][2] * R[1][2]));
    }
    MdtWorldDestroy(w);
    return angle;
}

static void fast_spin_wheel_keeps_axis_and_rate(void **state)
{
    (void)state;
    double axisFast, axisPlain;
    double fast = spinWheel(METRUE, &axisFast);
    double plain = spinWheel(MEFALSE, &axisPlain);
    print_message("wheel at 100 rad/s for 1 s: turned %.4f rad with fast spin, %.4f without (true 100)\n", fast,
                  plain);
    assert_near(fast, 100, ME_TOL(1e-6, 2e-2));
    assert_true(axisFast < ME_TOL(1e-9, 1e-5));
    assert_true(axisPlain < ME_TOL(1e-9, 1e-5));
    assert_true(plain < 95); /* first order lags at ω h = 1.7 rad per step: why fast spin exists */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(free_fall_60),
        cmocka_unit_test(free_fall_240),
        cmocka_unit_test(projectile_range),
        cmocka_unit_test(impulse_equals_force_over_one_step),
        cmocka_unit_test(damping_decays_at_the_stated_rate),
        cmocka_unit_test(torque_free_asymmetric_body),
        cmocka_unit_test(force_through_com_does_not_rotate),
        cmocka_unit_test(fast_spin_wheel_keeps_axis_and_rate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
