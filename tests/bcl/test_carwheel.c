/* Car wheel joint: the angles and the height it reports, suspension spring period and stops, wheel
 * motor, steering motor and lock, defaults. */
#include "karma_test.h"

#include <karma/Mdt.h>

#define PI 3.14159265358979323846

typedef struct Car {
    MdtWorldID w;
    MdtBodyID chassis, wheel;
    MdtCarWheelID j;
} Car;

/* A 4 kg chassis at the origin and a 1 kg wheel 0.5 m below it (z up), hinge axis y. */
static Car makeCar(void)
{
    Car c;
    c.w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetAutoDisable(c.w, MEFALSE);
    c.chassis = MdtBodyCreate(c.w);
    MdtBodySetMass(c.chassis, 4);
    MdtBodyEnable(c.chassis);
    c.wheel = MdtBodyCreate(c.w);
    MdtBodySetPosition(c.wheel, 0, 0, -0.5f);
    MdtBodyEnable(c.wheel);
    c.j = MdtCarWheelCreate(c.w);
    MdtCarWheelSetBodies(c.j, c.chassis, c.wheel);
    MdtCarWheelSetPosition(c.j, 0, 0, -0.5f);
    MdtCarWheelSetSteeringAndHingeAxes(c.j, 0, 0, 1, 0, 1, 0);
    MdtCarWheelEnable(c.j);
    return c;
}

static void step(MdtWorldID w, int n)
{
    for (int i = 0; i < n; i++)
        MdtWorldStep(w, 1.0f / 60);
}

static void carwheel_defaults_and_readings(void **state)
{
    (void)state;
    Car c = makeCar();
    assert_true(MdtCarWheelGetSteeringMotorMaxForce(c.j) == (MeReal)1e9);
    assert_true(MdtCarWheelGetSteeringMotorDesiredVelocity(c.j) == 0);
    assert_false(MdtCarWheelIsSteeringLocked(c.j));
    assert_true(MdtCarWheelGetHingeMotorMaxForce(c.j) == 0);
    assert_true(MdtCarWheelGetSuspensionHighLimit(c.j) == (MeReal)1e9);
    assert_true(MdtCarWheelGetSuspensionLowLimit(c.j) == (MeReal)-1e9);
    assert_true(MdtCarWheelGetSuspensionKp(c.j) == 0 && MdtCarWheelGetSuspensionKd(c.j) == 0);
    assert_true(MdtCarWheelGetSuspensionReference(c.j) == 0 && MdtCarWheelGetSuspensionLimitSoftness(c.j) == 0);
    assert_near(MdtCarWheelGetSuspensionHeight(c.j), 0, 1e-6);
    /* Turn the wheel by known angles and read them back. */
    MeVector4 q;
    MeVector3 z = {0, 0, 1}, y = {0, 1, 0};
    MeQuaternionMake(q, z, 0.3f);
    MdtBodySetQuaternion(c.wheel, q[0], q[1], q[2], q[3]);
    double steer = MdtCarWheelGetSteeringAngle(c.j);
    MeQuaternionMake(q, y, -0.4f);
    MdtBodySetQuaternion(c.wheel, q[0], q[1], q[2], q[3]);
    double hinge = MdtCarWheelGetHingeAngle(c.j);
    MdtBodySetPosition(c.wheel, 0, 0, -0.6f);
    MdtBodySetAngularVelocity(c.wheel, 0, 2, 0.7f);
    MdtBodySetLinearVelocity(c.wheel, 0, 0, -0.25f);
    print_message("car wheel readings: steering %.5f (0.3), hinge %.5f (2 pi - 0.4 = %.5f), height %.5f (0.1), rates "
                  "%.3f %.3f %.3f (2, 0.7, 0.25)\n",
                  steer, hinge, 2 * PI - 0.4, MdtCarWheelGetSuspensionHeight(c.j), MdtCarWheelGetHingeAngleRate(c.j),
                  MdtCarWheelGetSteeringAngleRate(c.j), MdtCarWheelGetSuspensionRate(c.j));
    assert_near(steer, 0.3, 1e-5);
    assert_near(hinge, 2 * PI - 0.4, 1e-5);
    assert_near(MdtCarWheelGetSuspensionHeight(c.j), 0.1, 1e-5);
    assert_near(MdtCarWheelGetHingeAngleRate(c.j), 2, 1e-5);
    assert_near(MdtCarWheelGetSteeringAngleRate(c.j), 0.7, 1e-5);
    assert_near(MdtCarWheelGetSuspensionRate(c.j), 0.25, 1e-5);
    MdtWorldDestroy(c.w);
}

static void carwheel_suspension_period(void **state)
{
    (void)state;
    const double k = 100, mu = 4.0 * 1.0 / 5.0; /* the chassis and the wheel oscillate against each other */
    Car c = makeCar();
    MdtCarWheelSetSuspension(c.j, (MeReal)k, 0, 0, -1, 1, 0);
    MdtBodySetLinearVelocity(c.wheel, 0, 0, -0.2f);
    MdtBodySetLinearVelocity(c.chassis, 0, 0, 0.05f);
    double last = 0, t = 0, h = 1.0 / 60, crossings[6];
    int n = 0;
    while (n < 6 && t < 20) {
        MdtWorldStep(c.w, (MeReal)h);
        t += h;
        double x = MdtCarWheelGetSuspensionHeight(c.j);
        if (t > h && (last > 0) != (x > 0))
            crossings[n++] = t - h * x / (x - last);
        last = x;
    }
    assert_int_equal(n, 6);
    double T = (crossings[5] - crossings[1]) / 2, expected = 2 * PI * sqrt(mu / k);
    print_message("car wheel suspension k=%.0f: period %.5f s vs 2 pi sqrt(mu/k) = %.5f s (%.3f %%)\n", k, T,
                  expected, 100 * fabs(T - expected) / expected);
    assert_rel(T, expected, 0.02);
    MdtWorldDestroy(c.w);
}

/* Damping Kd: successive peaks of the suspension height shrink by exp(−2π ζ / sqrt(1 − ζ²)), ζ = Kd /
 * (2 sqrt(Kp μ)); the spring's rest height is the reference. */
static void carwheel_suspension_damping_and_reference(void **state)
{
    (void)state;
    const double k = 100, d = 1, mu = 4.0 * 1.0 / 5.0, zeta = d / (2 * sqrt(k * mu));
    const double expected = exp(-2 * PI * zeta / sqrt(1 - zeta * zeta));
    Car c = makeCar();
    MdtCarWheelSetSuspension(c.j, (MeReal)k, (MeReal)d, 0, -1, 1, 0);
    MdtBodySetLinearVelocity(c.wheel, 0, 0, -0.2f);
    MdtBodySetLinearVelocity(c.chassis, 0, 0, 0.05f);
    double prev2 = 0, prev = 0, peaks[2];
    int n = 0;
    for (int i = 0; i < 2400 && n < 2; i++) {
        MdtWorldStep(c.w, 1.0f / 240);
        double x = MdtCarWheelGetSuspensionHeight(c.j);
        if (i > 1 && prev > prev2 && prev >= x && prev > 0)
            peaks[n++] = prev;
        prev2 = prev;
        prev = x;
    }
    assert_int_equal(n, 2);
    print_message("car wheel suspension Kp %.0f Kd %.0f (zeta %.3f): peak ratio %.5f vs %.5f (%.2f %%)\n", k, d, zeta,
                  peaks[1] / peaks[0], expected, 100 * fabs(peaks[1] / peaks[0] - expected) / expected);
    assert_rel(peaks[1] / peaks[0], expected, 0.02);
    MdtWorldDestroy(c.w);

    c = makeCar();
    MdtCarWheelSetSuspension(c.j, (MeReal)k, 10, 0, -1, 1, 0.1f);
    step(c.w, 600);
    print_message("car wheel suspension with reference 0.1 m: settles at %.6f m\n", MdtCarWheelGetSuspensionHeight(c.j));
    assert_near(MdtCarWheelGetSuspensionHeight(c.j), 0.1, 1e-4);
    MdtWorldDestroy(c.w);
}

static void carwheel_suspension_stops(void **state)
{
    (void)state;
    /* The wheel flies off down at 1 m/s: the stop at 0.05 m catches it, and the spring pulls it back. */
    Car c = makeCar();
    MdtCarWheelSetSuspension(c.j, 100, 0, 0, -0.05f, 0.05f, 0);
    MdtBodySetLinearVelocity(c.wheel, 0, 0, -1);
    double highest = -1, lowest = 1;
    int atStop = 0;
    for (int i = 0; i < 120; i++) {
        MdtWorldStep(c.w, 1.0f / 60);
        double x = MdtCarWheelGetSuspensionHeight(c.j);
        highest = fmax(highest, x);
        lowest = fmin(lowest, x);
        atStop += x > 0.0499;
    }
    print_message("car wheel suspension stops +-0.05 m: height within [%.5f, %.5f], %d steps at the stop\n", lowest,
                  highest, atStop);
    assert_true(highest < 0.05 + 1e-3 && lowest > -0.05 - 1e-3);
    assert_true(atStop > 0);
    assert_true(lowest < -0.04); /* left the stop and swung through to the other */
    MdtWorldDestroy(c.w);
}

static void carwheel_motors_and_lock(void **state)
{
    (void)state;
    Car c = makeCar();
    /* The motor's reaction spins the chassis: a free suspension would let the wheel fly out along it. */
    MdtCarWheelSetSuspension(c.j, 0, 0, 0, 0, 0, 0);
    MdtCarWheelSetHingeLimitedForceMotor(c.j, 10, 50);
    step(c.w, 30);
    double spin = MdtCarWheelGetHingeAngleRate(c.j);
    MdtWorldDestroy(c.w);
    /* Steering, on a wheel that does not spin. The default steering motor (v 0, 1e9) holds the
     * steering against a torque. */
    c = makeCar();
    for (int i = 0; i < 30; i++) {
        MdtBodyAddTorque(c.wheel, 0, 0, 2);
        MdtWorldStep(c.w, 1.0f / 60);
    }
    double held = MdtCarWheelGetSteeringAngle(c.j);
    MdtCarWheelSetSteeringLimitedForceMotor(c.j, 0.5f, 100);
    step(c.w, 30);
    double steerRate = MdtCarWheelGetSteeringAngleRate(c.j), steered = MdtCarWheelGetSteeringAngle(c.j);
    /* The lock brings the steering back to 0 and holds it there. */
    MdtCarWheelSetSteeringLock(c.j, METRUE);
    for (int i = 0; i < 120; i++) {
        MdtBodyAddTorque(c.wheel, 0, 0, 2);
        MdtWorldStep(c.w, 1.0f / 60);
    }
    double locked = MdtCarWheelGetSteeringAngle(c.j);
    print_message("car wheel: spin %.5f rad/s (10); steering held at %.2e under 2 N m; steering motor %.5f rad/s "
                  "(0.5) to %.4f rad; locked at %.2e\n",
                  spin, held, steerRate, steered, locked);
    assert_near(spin, 10, ME_TOL(1e-6, 1e-4));
    assert_near(held, 0, 1e-3);
    assert_near(steerRate, 0.5, 1e-3);
    assert_true(steered > 0.2);
    assert_near(locked, 0, 1e-3);
    MdtWorldDestroy(c.w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(carwheel_defaults_and_readings),
        cmocka_unit_test(carwheel_suspension_period),
        cmocka_unit_test(carwheel_suspension_damping_and_reference),
        cmocka_unit_test(carwheel_suspension_stops),
        cmocka_unit_test(carwheel_motors_and_lock),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
