/* Joints with finite stiffness are harmonic oscillators: Angular3 and Spring6 (linear and angular
 * axes) oscillate with period 2π√(I/k) (or 2π√(m/k)) within 2 %, at two steps, and a damper makes
 * the amplitude decay as exp(−d t / 2I). The SPOOK rows (docs/step.md) are exact in the limit h → 0
 * and, undamped, keep the amplitude (trapezoidal phase error only: 2 atan(hω/2) per step). */
#include "karma_test.h"

#include <karma/Mdt.h>

#define PI 3.14159265358979323846

typedef enum { ANGULAR3, SPRING6_LINEAR, SPRING6_ANGULAR } Rig;

typedef struct Result {
    double period, firstPeak, lastPeak, lastPeakTime, firstPeakTime;
} Result;

/* Coordinate of the oscillation: rotation about z (2 q_z ≈ angle) or the x position. */
static double coordinate(MdtBodyID b, Rig rig)
{
    if (rig == SPRING6_LINEAR) {
        MeVector3 p;
        MdtBodyGetPosition(b, p);
        return p[0];
    }
    MeVector4 q;
    MdtBodyGetQuaternion(b, q);
    return 2 * q[3] * (q[0] < 0 ? -1 : 1);
}

/* Oscillator with stiffness k (N·m/rad or N/m), damping d, inertia I (or mass), started at rate v0. */
static Result run(Rig rig, double h, double k, double d, double I, double v0)
{
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetMass(b, rig == SPRING6_LINEAR ? (MeReal)I : 1);
    MdtBodySetSphericalInertiaTensor(b, rig == SPRING6_LINEAR ? 1 : (MeReal)I);
    MdtBodyEnable(b);
    if (rig == SPRING6_LINEAR)
        MdtBodySetLinearVelocity(b, (MeReal)v0, 0, 0);
    else
        MdtBodySetAngularVelocity(b, 0, 0, (MeReal)v0);
    if (rig == ANGULAR3) {
        MdtAngular3ID j = MdtAngular3Create(w);
        MdtAngular3SetBodies(j, b, NULL);
        MdtAngular3SetStiffness(j, (MeReal)k);
        MdtAngular3SetDamping(j, (MeReal)d);
        MdtAngular3Enable(j);
    } else {
        MdtSpring6ID j = MdtSpring6Create(w);
        MdtSpring6SetBodies(j, b, NULL);
        if (rig == SPRING6_LINEAR) {
            MdtSpring6SetLinearStiffness(j, 0, (MeReal)k);
            MdtSpring6SetLinearDamping(j, 0, (MeReal)d);
        } else {
            MdtSpring6SetAngularStiffness(j, 2, (MeReal)k);
            MdtSpring6SetAngularDamping(j, 2, (MeReal)d);
        }
        MdtSpring6Enable(j);
    }
    Result r = {0, 0, 0, 0, 0};
    double crossings[16], last = 0, prev = 0, t = 0;
    int n = 0, peaks = 0;
    while (t < 12) {
        MdtWorldStep(w, (MeReal)h);
        t += h;
        double x = coordinate(b, rig);
        if (n < 16 && t > h && (last > 0) != (x > 0))
            crossings[n++] = t - h * x / (x - last);
        /* Peaks of |x| (a sample beside its neighbours). */
        if (t > 2 * h && fabs(last) > fabs(prev) && fabs(last) >= fabs(x)) {
            if (peaks == 0) {
                r.firstPeak = fabs(last);
                r.firstPeakTime = t - h;
            }
            r.lastPeak = fabs(last);
            r.lastPeakTime = t - h;
            peaks++;
        }
        prev = last;
        last = x;
    }
    MdtWorldDestroy(w);
    assert_true(n >= 11);
    r.period = (crossings[10] - crossings[0]) / 5; /* five full periods */
    return r;
}

static void period(Rig rig, const char *name, double k, double I)
{
    const double expected = 2 * PI * sqrt(I / k);
    const double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++) {
        Result r = run(rig, steps[i], k, 0, I, 0.05);
        double err = fabs(r.period - expected) / expected;
        double keep = r.lastPeak / r.firstPeak;
        /* The discrete prediction: a phase of 2 atan(h ω / 2) per step. */
        const double h = steps[i], discrete = 2 * PI * h / (2 * atan(h * sqrt(k / I) / 2));
        print_message("%s h=%.5f: period %.5f s vs 2 pi sqrt(I/k) = %.5f s (%.3f %%), discrete prediction %.5f s; "
                      "amplitude kept %.4f\n",
                      name, h, r.period, expected, 100 * err, discrete, keep);
        assert_true(err < 0.02);
        assert_rel(r.period, discrete, 0.002);
        assert_true(fabs(keep - 1) < 0.02); /* undamped: no numerical damping */
    }
}

static void damping(Rig rig, const char *name, double k, double d, double I)
{
    Result r = run(rig, 1.0 / 60, k, d, I, 0.05);
    double measured = r.lastPeak / r.firstPeak;
    double expected = exp(-d / (2 * I) * (r.lastPeakTime - r.firstPeakTime));
    print_message("%s damped: amplitude ratio %.4f vs exp(-d t / 2I) = %.4f (%.2f %%)\n", name, measured, expected,
                  100 * fabs(measured - expected) / expected);
    assert_rel(measured, expected, 0.03);
}

static void angular3_period(void **s)
{
    (void)s;
    period(ANGULAR3, "Angular3", 4, 0.1);
    damping(ANGULAR3, "Angular3", 4, 0.02, 0.1);
}

static void spring6_linear_period(void **s)
{
    (void)s;
    period(SPRING6_LINEAR, "Spring6 linear x", 40, 1);
    damping(SPRING6_LINEAR, "Spring6 linear x", 40, 0.2, 1);
}

static void spring6_angular_period(void **s)
{
    (void)s;
    period(SPRING6_ANGULAR, "Spring6 angular z", 2, 0.1);
    damping(SPRING6_ANGULAR, "Spring6 angular z", 2, 0.02, 0.1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(angular3_period),
        cmocka_unit_test(spring6_linear_period),
        cmocka_unit_test(spring6_angular_period),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
