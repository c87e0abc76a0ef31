/* The sense of a hand-made contact, as Karma 1.2's tutorials write it: the normal points from body 1
 * towards body 0, the direction in which body 0 is pushed. A ball (body 0) bounces on the world (body 1
 * NULL) with the normal (0, 1, 0), y up, as in the tutorial Bounce; two spheres with the normal
 * p0 − p1 are pushed apart with their momentum kept; the relative velocity is body 0's minus body 1's. */
#include "karma_test.h"

#include <karma/Mdt.h>

static const double G = 9.81, R = 0.5;

/* The tutorial's ball: dropped from `top`, its one contact refreshed every step (kept even when the
 * ball is in the air: a negative penetration is a gap). Returns the lowest centre height seen and
 * writes the highest point after the first bounce. */
static double bounce(double top, double e, double h, int steps, double *rebound, double *impact)
{
    MdtWorldID w = MdtWorldCreate(2, 4, 1, 1);
    MdtWorldSetGravity(w, 0, (MeReal)-G, 0);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID ball = MdtBodyCreate(w);
    MdtBodySetPosition(ball, 0, (MeReal)top, 0);
    MdtBodyEnable(ball);
    MdtContactID c = MdtContactCreate(w);
    MdtContactSetBodies(c, ball, NULL);
    MdtContactParamsID p = MdtContactGetParams(c);
    MdtContactParamsSetType(p, MdtContactTypeFrictionZero);
    MdtContactParamsSetRestitution(p, (MeReal)e);
    MdtContactEnable(c);
    double lowest = top, highest = 0, fastest = 0;
    int bounced = 0;
    for (int i = 0; i < steps; i++) {
        MeVector3 x, v;
        MdtBodyGetPosition(ball, x);
        MdtContactSetPosition(c, x[0], 0, x[2]);
        MdtContactSetNormal(c, 0, 1, 0);
        MdtContactSetPenetration(c, (MeReal)(R - x[1]));
        MdtWorldStep(w, (MeReal)h);
        MdtBodyGetPosition(ball, x);
        MdtBodyGetLinearVelocity(ball, v);
        assert_true(isfinite(x[1]) && isfinite(v[1]));
        lowest = fmin(lowest, x[1]);
        if (!bounced) {
            fastest = fmax(fastest, -v[1]);
            bounced = v[1] > 0;
        } else
            highest = fmax(highest, x[1]);
    }
    MdtWorldDestroy(w);
    *rebound = highest;
    *impact = fastest;
    return lowest;
}

static void bounce_as_the_tutorial(void **state)
{
    (void)state;
    /* Dropped from 3 m (the ball's bottom 2.5 m up), restitution 0.6: it stops at the plane and rises
     * again to e² × 2.5 = 0.9 m above it (within the step's error); it never sinks into the plane. */
    const double top = 3, e = 0.6, h = 1.0 / 240;
    double rebound, impact;
    double lowest = bounce(top, e, h, (int)(2.0 / h), &rebound, &impact);
    double expected = R + e * e * (top - R);
    print_message("Bounce (y up, normal (0, 1, 0), body 1 NULL): impact %.4f m/s, lowest centre %.5f (radius %.2f), "
                  "rebound apex %.4f (e^2 drop + r = %.4f)\n",
                  impact, lowest, R, rebound, expected);
    assert_rel(impact, sqrt(2 * G * (top - R)), 0.01);
    assert_true(lowest > R - 0.005);
    assert_rel(rebound, expected, 0.02);
    /* Inelastic: it comes to rest on the plane and stays there. */
    lowest = bounce(top, 0, h, (int)(3.0 / h), &rebound, &impact);
    print_message("Bounce, restitution 0: lowest centre %.5f, no rebound (apex %.4f)\n", lowest, rebound);
    assert_true(lowest > R - 0.005);
    assert_true(rebound < R + 0.005);
}

static void two_spheres_pushed_apart(void **state)
{
    (void)state;
    /* Two spheres (1 kg and 3 kg, radius 0.5, no gravity) approach along x at 1 m/s each, overlapping
     * by 0.02. One contact at the middle, normal p0 − p1 (from body 1 towards body 0), penetration
     * from the distance, refreshed every step. Restitution 0.5: the approach speed 2 m/s reverses to
     * 1 m/s; the momentum (−2 kg m/s) is kept; they end apart. */
    const double m[2] = {1, 3}, h = 1.0 / 120;
    MdtWorldID w = MdtWorldCreate(2, 4, 1, 1);
    MdtWorldSetGravity(w, 0, 0, 0);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b[2];
    for (int i = 0; i < 2; i++) {
        b[i] = MdtBodyCreate(w);
        MdtBodySetMass(b[i], (MeReal)m[i]);
        MdtBodySetPosition(b[i], i ? ME_R(0.49) : ME_R(-0.49), 0, 0);
        MdtBodySetLinearVelocity(b[i], i ? -1 : 1, 0, 0);
        MdtBodyEnable(b[i]);
    }
    MdtContactID c = MdtContactCreate(w);
    MdtContactSetBodies(c, b[0], b[1]);
    MdtContactParamsSetRestitution(MdtContactGetParams(c), ME_R(0.5));
    MdtContactEnable(c);
    double closest = 1e9;
    for (int i = 0; i < 60; i++) {
        MeVector3 p0, p1, n, rel;
        MdtBodyGetPosition(b[0], p0);
        MdtBodyGetPosition(b[1], p1);
        MeVector3Subtract(n, p0, p1);
        MeReal d = MeVector3Normalize(n);
        closest = fmin(closest, d);
        MdtContactSetPosition(c, (p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2, (p0[2] + p1[2]) / 2);
        MdtContactSetNormal(c, n[0], n[1], n[2]);
        MdtContactSetPenetration(c, (MeReal)(2 * R) - d);
        if (i == 0) {
            /* body 0's velocity relative to body 1's: (1 − (−1), 0, 0) */
            MdtContactGetRelativeVelocity(c, rel);
            assert_near(rel[0], 2, 1e-6);
            assert_near(rel[1], 0, 1e-6);
        }
        MdtWorldStep(w, (MeReal)h);
    }
    MeVector3 v0, v1, p0, p1;
    MdtBodyGetLinearVelocity(b[0], v0);
    MdtBodyGetLinearVelocity(b[1], v1);
    MdtBodyGetPosition(b[0], p0);
    MdtBodyGetPosition(b[1], p1);
    double momentum = m[0] * v0[0] + m[1] * v1[0], separating = v1[0] - v0[0];
    print_message("two spheres, normal p0 - p1: v0 %.5f, v1 %.5f m/s (momentum %.6f, -2), separating at %.5f (1), "
                  "closest %.4f, now %.4f apart\n",
                  v0[0], v1[0], momentum, separating, closest, p1[0] - p0[0]);
    assert_near(momentum, -2, 1e-4);
    assert_rel(separating, 1, 0.01);
    /* body 0 pushed back along the normal, body 1 the other way: v0 = -1.25, v1 = -0.25 */
    assert_rel(v0[0], -1.25, 0.01);
    assert_rel(v1[0], -0.25, 0.04);
    assert_true(closest > 2 * R - 0.03);
    assert_true(p1[0] - p0[0] > 2 * R + 0.3);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bounce_as_the_tutorial),
        cmocka_unit_test(two_spheres_pushed_apart),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
