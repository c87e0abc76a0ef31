/* Prismatic joint (line and orientation held, motor, hard and soft stops) and spring joint (period,
 * natural length, static deflection, rod, string). */
#include "karma_test.h"

#include <karma/Mdt.h>

#define PI 3.14159265358979323846

typedef struct Slider {
    MdtWorldID w;
    MdtBodyID b;
    MdtPrismaticID j;
    MdtLimitID l;
} Slider;

/* A 2 kg body sliding along x on the world. */
static Slider makeSlider(void)
{
    Slider s;
    s.w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetAutoDisable(s.w, MEFALSE);
    s.b = MdtBodyCreate(s.w);
    MdtBodySetMass(s.b, 2);
    MdtBodySetPosition(s.b, 0.3f, 0.2f, -0.1f);
    MdtBodyEnable(s.b);
    s.j = MdtPrismaticCreate(s.w);
    MdtPrismaticSetBodies(s.j, s.b, NULL);
    MdtPrismaticSetAxis(s.j, 1, 0, 0);
    MdtPrismaticEnable(s.j);
    s.l = MdtPrismaticGetLimit(s.j);
    return s;
}

static void step(MdtWorldID w, int n)
{
    for (int i = 0; i < n; i++)
        MdtWorldStep(w, 1.0f / 60);
}

static void prismatic_holds_line_and_orientation(void **state)
{
    (void)state;
    Slider s = makeSlider();
    MdtBodySetLinearVelocity(s.b, 1, 0, 0);
    double worst = 0;
    for (int i = 0; i < 120; i++) {
        MdtBodyAddForce(s.b, 0, 30, -20);
        MdtBodyAddTorque(s.b, 5, -3, 4);
        MdtWorldStep(s.w, 1.0f / 60);
        MeVector3 p;
        MeVector4 q;
        MdtBodyGetPosition(s.b, p);
        MdtBodyGetQuaternion(s.b, q);
        worst = fmax(worst, fmax(fabs(p[1] - 0.2), fabs(p[2] + 0.1)));
        worst = fmax(worst, fmax(fabs(q[1]), fmax(fabs(q[2]), fabs(q[3]))));
    }
    MeVector3 p;
    MdtBodyGetPosition(s.b, p);
    print_message("prismatic under sideways force and torque: off the line / turned by at most %.2e; travel %.5f m "
                  "(reported %.5f)\n",
                  worst, p[0] - 0.3, MdtLimitGetPosition(s.l));
    assert_true(worst < 1e-3);
    assert_near(p[0] - 0.3, 2, 1e-4);
    assert_near(MdtLimitGetPosition(s.l), p[0] - 0.3, 1e-5);
    MdtWorldDestroy(s.w);
}

static void prismatic_motor(void **state)
{
    (void)state;
    Slider s = makeSlider();
    MdtLimitSetLimitedForceMotor(s.l, 1.5f, 100);
    step(s.w, 10);
    double reached = MdtLimitGetVelocity(s.l);
    /* A load of 5 N against a cap of 2 N: it decelerates at (2 − 5)/m and the joint pushes with 2 N. */
    MdtLimitSetLimitedForceMotor(s.l, 1.5f, 2);
    double v0 = 0;
    for (int i = 0; i < 60; i++) {
        if (i == 30)
            v0 = MdtLimitGetVelocity(s.l);
        MdtBodyAddForce(s.b, -5, 0, 0);
        MdtWorldStep(s.w, 1.0f / 60);
    }
    double accel = (MdtLimitGetVelocity(s.l) - v0) / 0.5;
    MeVector3 f;
    MdtPrismaticGetForce(s.j, 0, f);
    print_message("prismatic motor: reached %.6f m/s (1.5); stalled: force %.6f N (cap 2), acceleration %.5f (-1.5)\n",
                  reached, f[0], accel);
    assert_near(reached, 1.5, ME_TOL(1e-6, 1e-4));
    assert_near(f[0], 2, ME_TOL(1e-6, 1e-4));
    assert_rel(accel, -1.5, 1e-3);
    MdtWorldDestroy(s.w);
}

static void prismatic_hard_stops(void **state)
{
    (void)state;
    /* A motor drives the slider into a stop at 0.5 m: it stops there and stays. */
    Slider s = makeSlider();
    MdtLimitActivateLimits(s.l, METRUE);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(s.l), -0.5f);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(s.l), 0.5f);
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(s.l), 0);
    MdtLimitSetLimitedForceMotor(s.l, 2, 50);
    double worst = 0;
    for (int i = 0; i < 120; i++) {
        MdtWorldStep(s.w, 1.0f / 60);
        worst = fmax(worst, MdtLimitGetPosition(s.l) - 0.5);
    }
    MeVector3 f;
    MdtPrismaticGetForce(s.j, 0, f);
    print_message("prismatic pushed into its stop by a 50 N motor: at %.6f m (stop 0.5), overshoot %.1e, net force "
                  "%.2e N\n",
                  MdtLimitGetPosition(s.l), worst, f[0]);
    assert_near(MdtLimitGetPosition(s.l), 0.5, 1e-4);
    assert_true(worst < 1e-3);
    assert_near(f[0], 0, 1e-3); /* the motor's push and the stop's reaction cancel */
    MdtWorldDestroy(s.w);

    /* Bounce off the lower stop with restitution 0.5. */
    s = makeSlider();
    MdtLimitActivateLimits(s.l, METRUE);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(s.l), -0.5f);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(s.l), 10);
    MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(s.l), 0.5f);
    MdtBodySetLinearVelocity(s.b, -2, 0, 0);
    double after = 0;
    for (int i = 0; i < 60 && after == 0; i++) {
        MdtWorldStep(s.w, 1.0f / 60);
        if (MdtLimitGetVelocity(s.l) > 0)
            after = MdtLimitGetVelocity(s.l);
    }
    print_message("prismatic stop restitution 0.5: rebound/arrival %.5f\n", after / 2);
    assert_rel(after / 2, 0.5, 1e-2);
    MdtWorldDestroy(s.w);
}

/* Period of x(t) from its zero crossings (x measured by `coordinate`), after n half periods. */
static double period(MdtWorldID w, double (*coordinate)(void *), void *data, double h, double x0)
{
    double last = x0, t = 0, crossings[6];
    int n = 0;
    while (n < 6 && t < 30) {
        MdtWorldStep(w, (MeReal)h);
        t += h;
        double x = coordinate(data);
        if ((last > 0) != (x > 0))
            crossings[n++] = t - h * x / (x - last);
        last = x;
    }
    assert_int_equal(n, 6);
    return (crossings[5] - crossings[1]) / 2;
}

static double limitPosition(void *l) { return MdtLimitGetPosition((MdtLimitID)l); }

static void prismatic_soft_stops_are_springs(void **state)
{
    (void)state;
    const double m = 2, k = 50;
    Slider s = makeSlider();
    MdtLimitActivateLimits(s.l, METRUE);
    MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(s.l), (MeReal)k);
    MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(s.l), (MeReal)k);
    MdtBodySetLinearVelocity(s.b, 0.4f, 0, 0);
    double T = period(s.w, limitPosition, s.l, 1.0 / 60, 1e-9), expected = 2 * PI * sqrt(m / k);
    print_message("prismatic soft stops k=%.0f: period %.5f s vs 2 pi sqrt(m/k) = %.5f s (%.3f %%)\n", k, T, expected,
                  100 * fabs(T - expected) / expected);
    assert_rel(T, expected, 0.02);
    MdtWorldDestroy(s.w);
}

/* ---- spring ---- */
typedef struct SpringScene {
    MdtWorldID w;
    MdtBodyID b;
    MdtSpringID j;
} SpringScene;

/* A 1 kg body at (1, 0, 0) on a spring to the world anchor at the origin. */
static SpringScene makeSpring(double k, double d)
{
    SpringScene s;
    s.w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetAutoDisable(s.w, MEFALSE);
    s.b = MdtBodyCreate(s.w);
    MdtBodySetPosition(s.b, 1, 0, 0);
    MdtBodyEnable(s.b);
    s.j = MdtSpringCreate(s.w);
    MdtSpringSetBodies(s.j, s.b, NULL);
    MdtSpringSetPosition(s.j, 0, 1, 0, 0);
    MdtSpringSetPosition(s.j, 1, 0, 0, 0);
    MdtSpringSetStiffness(s.j, (MeReal)k);
    MdtSpringSetDamping(s.j, (MeReal)d);
    MdtSpringEnable(s.j);
    return s;
}

static double springExtension(void *j) { return MdtSpringGetLength((MdtSpringID)j) - 1; }

static void spring_period_and_length(void **state)
{
    (void)state;
    const double k = 40;
    const double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++) {
        SpringScene s = makeSpring(k, 0);
        MdtBodySetLinearVelocity(s.b, 0.3f, 0, 0);
        double T = period(s.w, springExtension, s.j, steps[i], 1e-9), expected = 2 * PI * sqrt(1 / k);
        print_message("spring k=%.0f h=%.5f: period %.5f s vs 2 pi sqrt(m/k) = %.5f s (%.3f %%)\n", k, steps[i], T,
                      expected, 100 * fabs(T - expected) / expected);
        assert_rel(T, expected, 0.02);
        MdtWorldDestroy(s.w);
    }
    /* Damped: successive peaks shrink by exp(−π ζ / sqrt(1 − ζ²)) with ζ = d / (2 sqrt(k m)). */
    {
        const double d = 2, zeta = d / (2 * sqrt(k)), expected = exp(-2 * PI * zeta / sqrt(1 - zeta * zeta));
        SpringScene s = makeSpring(k, d);
        MdtBodySetLinearVelocity(s.b, 0.3f, 0, 0);
        double prev2 = 0, prev = 0, peaks[2];
        int n = 0;
        for (int i = 0; i < 600 && n < 2; i++) {
            MdtWorldStep(s.w, 1.0f / 240);
            double x = MdtSpringGetLength(s.j) - 1;
            if (i > 1 && prev > prev2 && prev >= x && prev > 0)
                peaks[n++] = prev;
            prev2 = prev;
            prev = x;
        }
        assert_int_equal(n, 2);
        print_message("damped spring zeta=%.3f: peak ratio %.5f vs %.5f (%.2f %%)\n", zeta, peaks[1] / peaks[0], expected,
                      100 * fabs(peaks[1] / peaks[0] - expected) / expected);
        assert_rel(peaks[1] / peaks[0], expected, 0.02);
        MdtWorldDestroy(s.w);
    }
    /* The natural length adds to the initial separation (1 m); a damped spring settles there. */
    SpringScene s = makeSpring(k, 5);
    MdtSpringSetNaturalLength(s.j, 0.5f);
    step(s.w, 600);
    print_message("spring natural length 0.5 added to 1 m: settles at %.6f m\n", MdtSpringGetLength(s.j));
    assert_near(MdtSpringGetLength(s.j), 1.5, 1e-4);
    /* Hanging under gravity (along +x, away from the anchor): static extension m g / k exactly. */
    MdtWorldSetGravity(s.w, 9.81f, 0, 0);
    MdtSpringSetNaturalLength(s.j, 0);
    step(s.w, 900);
    double stretch = MdtSpringGetLength(s.j) - 1;
    print_message("spring under gravity: extension %.6f m vs m g / k = %.6f m\n", stretch, 9.81 / k);
    assert_near(stretch, 9.81 / k, ME_TOL(1e-6, 1e-4));
    MdtWorldDestroy(s.w);
}

static void spring_rod_and_string(void **state)
{
    (void)state;
    /* A rod (infinite stiffness): a pendulum whose length holds. A velocity-level step moves the bob
     * along its tangent, lengthening the rod by (h v)²/(2L) per step, which the world's γ removes at
     * its rate: the rod stays within (h v)²/(2 L γ) of its length, as a ball joint would. */
    SpringScene s = makeSpring(MEINFINITY, 0);
    MdtWorldSetGravity(s.w, 0, -9.81f, 0);
    double worst = 0, vmax = 0, h = 1.0 / 60, gamma = MdtWorldGetGamma(s.w);
    for (int i = 0; i < 300; i++) {
        MdtWorldStep(s.w, (MeReal)h);
        MeVector3 v;
        MdtBodyGetLinearVelocity(s.b, v);
        vmax = fmax(vmax, sqrt(v[0] * v[0] + v[1] * v[1]));
        worst = fmax(worst, fabs(MdtSpringGetLength(s.j) - 1));
    }
    double bound = (h * vmax) * (h * vmax) / (2 * gamma);
    MeVector3 p;
    MdtBodyGetPosition(s.b, p);
    print_message("rod spring pendulum from horizontal: length within %.2e m of 1 over 5 s (bound (h v)^2/(2 L gamma) "
                  "= %.2e at v = %.2f m/s)\n",
                  worst, bound, vmax);
    assert_true(worst < 1.05 * bound);
    assert_true(vmax > 4); /* it did swing down: sqrt(2 g L) = 4.43 */
    MdtWorldDestroy(s.w);

    /* A string: no lower stop. Compressed, it exerts nothing; stretched, it pulls. */
    s = makeSpring(40, 0);
    MdtLimitID l = MdtSpringGetLimit(s.j);
    MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(l), 0);
    MdtSingleLimitSetDamping(MdtLimitGetLowerLimit(l), 0);
    MdtBodySetLinearVelocity(s.b, -1, 0, 0);
    step(s.w, 30);
    MeVector3 v, f;
    MdtBodyGetLinearVelocity(s.b, v);
    MdtSpringGetForce(s.j, 0, f);
    print_message("slack string: length %.4f m, velocity %.6f m/s (was -1), force %.2e N\n", MdtSpringGetLength(s.j),
                  v[0], f[0]);
    assert_near(MdtSpringGetLength(s.j), 0.5, 1e-4);
    assert_near(v[0], -1, 1e-6);
    assert_near(f[0], 0, 1e-6);
    MdtBodySetPosition(s.b, 1.1f, 0, 0);
    MdtBodySetLinearVelocity(s.b, 0, 0, 0);
    step(s.w, 1);
    MdtSpringGetForce(s.j, 0, f);
    print_message("taut string stretched 0.1 m: force %.4f N (k x = -4)\n", f[0]);
    assert_true(f[0] < -3.5 && f[0] > -4.5);
    MdtWorldDestroy(s.w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(prismatic_holds_line_and_orientation),
        cmocka_unit_test(prismatic_motor),
        cmocka_unit_test(prismatic_hard_stops),
        cmocka_unit_test(prismatic_soft_stops_are_springs),
        cmocka_unit_test(spring_period_and_length),
        cmocka_unit_test(spring_rod_and_string),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
