/* Hinge: pendulum period, the axis kept, motors (reach and stall), hard stops (hold, bounce with the
 * set restitution, multi-turn), soft stops as springs, MdtLimitController. */
#include "karma_test.h"

#include <karma/Mdt.h>

#include "karma_pendulum.h"
#include "mdt/bcl/limit_internal.h"
#include "karma_rotor.h"

#define PI 3.14159265358979323846

static double angle(const KarmaRotor *r) { return MdtLimitGetPosition(r->l); }
static double rate(const KarmaRotor *r) { return MdtLimitGetVelocity(r->l); }

static void spin(const KarmaRotor *r, double w) { MdtBodySetAngularVelocity(r->b, 0, 0, (MeReal)w); }

/* ---- pendulum ---- */
static void hinge_pendulum_period(void **state)
{
    (void)state;
    const double L = 1, theta0 = 0.05;
    const double expected = karma_pendulum_expected_period(L, theta0);
    const double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++) {
        KarmaPendulum swing = karma_pendulum_swing(KARMA_PENDULUM_HINGE, steps[i], L, theta0);
        print_message("hinge pendulum h=%.5f: period %.5f s vs %.5f s (%.3f %%), axis drift %.1e\n", steps[i],
                      swing.period, expected, 100 * fabs(swing.period - expected) / expected, swing.axisDrift);
        assert_rel(swing.period, expected, 0.01);
        assert_true(swing.axisDrift < 1e-3);
    }
}

/* ---- motors ---- */
static void hinge_motor_reaches_target_speed(void **state)
{
    (void)state;
    KarmaRotor r = karma_rotor_make(0.5);
    MdtLimitSetLimitedForceMotor(r.l, 3, 100);
    assert_true(MdtLimitIsMotorized(r.l));
    for (int i = 0; i < 30; i++)
        MdtWorldStep(r.w, 1.0f / 60);
    print_message("hinge motor: rate %.6f rad/s for a target of 3\n", rate(&r));
    assert_near(rate(&r), 3, ME_TOL(1e-6, 1e-4));
    /* Against a load the cap allows, the motor keeps the speed and supplies the load's torque. */
    double drift = 0;
    for (int i = 0; i < 30; i++) {
        MdtBodyAddTorque(r.b, 4, -3, -1); /* the hinge carries the torque across its axis */
        MdtBodyAddForce(r.b, 2, 5, -1);
        MdtWorldStep(r.w, 1.0f / 60);
        MeVector3 p;
        MeMatrix3 R;
        MdtBodyGetPosition(r.b, p);
        MdtBodyGetOrientation(r.b, R); /* row 2: the rotor's z axis, which must stay the hinge axis */
        drift = fmax(drift, fmax(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), fmax(fabs(R[2][0]), fabs(R[2][1]))));
    }
    MeVector3 t;
    MdtHingeGetTorque(r.j, 0, t);
    /* The row's softness ε lets the motor slip by ε·(its impulse): the speed is 3 − ε τ h. */
    const double expected = 3 - MdtWorldGetEpsilon(r.w) * 1.0 / 60;
    print_message("hinge motor under a 1 N m load: rate %.7f (3 - eps tau h = %.7f), motor torque %.6f N m\n",
                  rate(&r), expected, t[2]);
    assert_near(rate(&r), expected, ME_TOL(1e-9, 1e-5));
    print_message("hinge under torque and force across its axis: axis and point kept within %.1e\n", drift);
    assert_true(drift < 1e-3);
    assert_near(t[2], 1, ME_TOL(1e-6, 1e-4));
    MdtWorldDestroy(r.w);
}

static void hinge_motor_stalls_at_its_cap(void **state)
{
    (void)state;
    const double I = 0.5, cap = 2, load = 5, h = 1.0 / 60;
    KarmaRotor r = karma_rotor_make(I);
    spin(&r, 3);
    MdtLimitSetLimitedForceMotor(r.l, 3, (MeReal)cap);
    double w0 = 0;
    for (int i = 0; i < 60; i++) {
        if (i == 30)
            w0 = rate(&r);
        MdtBodyAddTorque(r.b, 0, 0, (MeReal)-load);
        MdtWorldStep(r.w, (MeReal)h);
    }
    double accel = (rate(&r) - w0) / (30 * h), expected = (cap - load) / I;
    MeVector3 t;
    MdtHingeGetTorque(r.j, 0, t);
    print_message("stalled hinge motor: torque %.6f N m (cap %.1f), acceleration %.5f vs %.5f rad/s^2\n", t[2], cap,
                  accel, expected);
    assert_near(t[2], cap, ME_TOL(1e-6, 1e-4));
    assert_rel(accel, expected, 1e-3);
    MdtWorldDestroy(r.w);
}

/* ---- hard stops ---- */
static void setStops(MdtLimitID l, double lo, double hi, double e)
{
    MdtLimitActivateLimits(l, METRUE);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(l), (MeReal)lo);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(l), (MeReal)hi);
    MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(l), (MeReal)e);
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(l), (MeReal)e);
}

/* A 1 kg bob at (x, 0, z) under gravity −z, hinged to the world at the origin about (0, ay, 0). */
static MdtHingeID makeArm(MdtWorldID *w, double x, double z, double ay, MdtBodyID *bob)
{
    *w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetGravity(*w, 0, 0, -9.81f);
    MdtWorldSetAutoDisable(*w, MEFALSE);
    *bob = MdtBodyCreate(*w);
    MdtBodySetPosition(*bob, (MeReal)x, 0, (MeReal)z);
    MdtBodyEnable(*bob);
    MdtHingeID j = MdtHingeCreate(*w);
    MdtHingeSetBodies(j, *bob, NULL);
    MdtHingeSetPosition(j, 0, 0, 0);
    MdtHingeSetAxis(j, 0, (MeReal)ay, 0);
    MdtHingeEnable(j);
    return j;
}

static void hinge_hard_stops_hold(void **state)
{
    (void)state;
    /* A pendulum swinging hard into stops at ±0.3 rad, without bounce. */
    MdtWorldID w;
    MdtBodyID bob;
    MdtHingeID j = makeArm(&w, 0, -1, 1, &bob);
    MdtBodySetLinearVelocity(bob, 4, 0, 0);
    MdtLimitID l = MdtHingeGetLimit(j);
    setStops(l, -0.3, 0.3, 0);
    double worst = 0;
    int hitsLo = 0, hitsHi = 0;
    for (int i = 0; i < 600; i++) {
        MdtWorldStep(w, 1.0f / 60);
        double a = MdtLimitGetPosition(l);
        worst = fmax(worst, fabs(a) - 0.3);
        hitsLo += a < -0.299;
        hitsHi += a > 0.299;
    }
    print_message("hinge hard stops at +-0.3 rad: worst overshoot %.2e rad (steps at the stops: %d low, %d high)\n",
                  worst, hitsLo, hitsHi);
    assert_true(worst < 1e-3);
    assert_true(hitsLo > 0 && hitsHi > 0);
    MdtWorldDestroy(w);

    /* Multi-turn: a motor winds the rotor up to a stop at 3π. */
    KarmaRotor r = karma_rotor_make(0.5);
    setStops(r.l, -1, 3 * PI, 0);
    MdtLimitSetLimitedForceMotor(r.l, 4, 10);
    for (int i = 0; i < 600; i++)
        MdtWorldStep(r.w, 1.0f / 60);
    print_message("multi-turn stop at 3 pi: angle %.5f rad (%.5f), rate %.2e\n", angle(&r), 3 * PI, rate(&r));
    assert_near(angle(&r), 3 * PI, 2e-3);
    assert_near(rate(&r), 0, 1e-3);
    MdtWorldDestroy(r.w);
}

static void hinge_hard_stop_restitution(void **state)
{
    (void)state;
    const double es[3] = {0.25, 0.5, 1};
    for (int k = 0; k < 3; k++) {
        KarmaRotor r = karma_rotor_make(0.5);
        setStops(r.l, -10, 0.5, es[k]);
        spin(&r, 2);
        double after = 0;
        for (int i = 0; i < 60 && after == 0; i++) {
            MdtWorldStep(r.w, 1.0f / 60);
            if (rate(&r) < 0)
                after = -rate(&r);
        }
        print_message("hinge stop restitution %.2f: rebound/arrival speed %.5f\n", es[k], after / 2);
        assert_rel(after / 2, es[k], 1e-2);
        MdtWorldDestroy(r.w);
    }
}

/* ---- soft stops ---- */
static void hinge_soft_stops_are_springs(void **state)
{
    (void)state;
    const double I = 0.5, k = 20, h = 1.0 / 60;
    const double expected = 2 * PI * sqrt(I / k);
    /* Two soft stops at 0: a torsion spring. */
    KarmaRotor r = karma_rotor_make(I);
    MdtLimitActivateLimits(r.l, METRUE);
    MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(r.l), (MeReal)k);
    MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(r.l), (MeReal)k);
    spin(&r, 1);
    double last = 0, t = 0, crossings[6];
    int n = 0;
    while (n < 6 && t < 20) {
        MdtWorldStep(r.w, (MeReal)h);
        t += h;
        double a = angle(&r);
        if (t > h && (last > 0) != (a > 0))
            crossings[n++] = t - h * a / (a - last);
        last = a;
    }
    assert_int_equal(n, 6);
    double T = (crossings[5] - crossings[1]) / 2;
    print_message("soft hinge stops k=%.0f: period %.5f s vs 2 pi sqrt(I/k) = %.5f s (%.3f %%)\n", k, T, expected,
                  100 * fabs(T - expected) / expected);
    assert_rel(T, expected, 0.02);
    MdtWorldDestroy(r.w);

    /* One soft stop at 0.2 rad: the rotor spends half a period past it and leaves as fast as it came. */
    r = karma_rotor_make(I);
    setStops(r.l, -10, 0.2, 1);
    MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(r.l), (MeReal)k);
    spin(&r, 1);
    double inside = 0;
    for (int i = 0; i < 120; i++) {
        double before = angle(&r);
        MdtWorldStep(r.w, (MeReal)h);
        double a = angle(&r);
        /* time past the stop, with the crossings interpolated */
        if (before > 0.2 && a > 0.2)
            inside += h;
        else if (before <= 0.2 && a > 0.2)
            inside += h * (a - 0.2) / (a - before);
        else if (before > 0.2 && a <= 0.2)
            inside += h * (before - 0.2) / (before - a);
    }
    print_message("one soft stop: %.5f s past it vs half a period %.5f s; leaves at %.5f rad/s (came at 1)\n",
                  inside, expected / 2, -rate(&r));
    assert_rel(inside, expected / 2, 0.02);
    assert_rel(-rate(&r), 1, 0.02);
    MdtWorldDestroy(r.w);
}

/* ---- controller ---- */
static void hinge_limit_controller(void **state)
{
    (void)state;
    KarmaRotor r = karma_rotor_make(0.5);
    double err = 0;
    for (int i = 0; i < 240; i++) {
        MdtLimitController(r.l, 1.2f, 0.5f, 2, 50);
        MdtWorldStep(r.w, 1.0f / 60);
        err = angle(&r) - 1.2;
    }
    print_message("MdtLimitController to 1.2 rad: error after 4 s %.2e rad, rate %.2e\n", err, rate(&r));
    assert_near(err, 0, 1e-4);
    MdtWorldDestroy(r.w);
}

/* A motor lifting a pendulum off its stop: it stays on the stop while gravity's torque exceeds the
 * cap, and lifts off once the cap allows. */
static void hinge_motor_lifts_off_stop_only_when_strong_enough(void **state)
{
    (void)state;
    /* A horizontal arm of 1 m (gravity's torque 9.81 N m); a positive angle lifts it. */
    MdtWorldID w;
    MdtBodyID bob;
    MdtHingeID j = makeArm(&w, 1, 0, -1, &bob);
    MdtLimitID l = MdtHingeGetLimit(j);
    setStops(l, 0, 1, 0);
    MdtLimitSetLimitedForceMotor(l, 1, 8);
    double worst = 0;
    for (int i = 0; i < 120; i++) {
        MdtWorldStep(w, 1.0f / 60);
        worst = fmax(worst, fabs(MdtLimitGetPosition(l)));
    }
    print_message("motor of 8 N m against 9.81 N m: stays on the stop within %.2e rad (stalled: %d)\n", worst,
                  MDT_LIMIT_STALLED(l));
    assert_true(worst < 1e-3);
    assert_true(MDT_LIMIT_STALLED(l)); /* the stop row carries the motor's 8 N m (limit.c) */
    MdtLimitSetLimitedForceMotor(l, 1, 20);
    for (int i = 0; i < 20; i++)
        MdtWorldStep(w, 1.0f / 60);
    print_message("motor of 20 N m: lifted to %.4f rad at %.5f rad/s (target 1)\n", MdtLimitGetPosition(l),
                  MdtLimitGetVelocity(l));
    assert_true(MdtLimitGetPosition(l) > 0.2);
    /* the motor slips by ε × its impulse (about 9.5 N m × h) */
    assert_near(MdtLimitGetVelocity(l), 1, 2e-3);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hinge_pendulum_period),
        cmocka_unit_test(hinge_motor_reaches_target_speed),
        cmocka_unit_test(hinge_motor_stalls_at_its_cap),
        cmocka_unit_test(hinge_hard_stops_hold),
        cmocka_unit_test(hinge_hard_stop_restitution),
        cmocka_unit_test(hinge_soft_stops_are_springs),
        cmocka_unit_test(hinge_limit_controller),
        cmocka_unit_test(hinge_motor_lifts_off_stop_only_when_strong_enough),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
