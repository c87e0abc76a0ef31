/* Contacts made by hand (as an application with its own collision would): friction on an incline,
 * Box friction as a force cap, restitution, a resting box, a column of 20 boxes. */
#include "karma_test.h"
#include "karma_contacts.h"

#include <karma/Mdt.h>

static const double G = 9.81;

typedef struct Scene {
    MdtWorldID world;
    MdtBodyID box;
    MdtContactGroupID ground;
    MdtContactParams params;
} Scene;

/* A unit box resting on the plane z = 0 under gravity tilted by theta about y: the same physics as a
 * box on an incline of angle theta (the plane's "downhill" is +x). */
static void makeIncline(Scene *s, double theta, double mu)
{
    s->world = MdtWorldCreate(4, 16, 1, 1);
    MdtWorldSetGravity(s->world, (MeReal)(G * sin(theta)), 0, (MeReal)(-G * cos(theta)));
    MdtWorldSetAutoDisable(s->world, MEFALSE);
    s->box = MdtBodyCreate(s->world);
    MdtBodySetPosition(s->box, 0, 0, 0.5f);
    MeMatrix3 I;
    MdtMakeInertiaTensorBox(1, 1, 1, 1, I);
    MdtBodySetInertiaTensor(s->box, I);
    MdtBodyEnable(s->box);
    s->ground = MdtContactGroupCreate(s->world);
    MdtContactGroupSetBodies(s->ground, s->box, NULL);
    MdtContactGroupEnable(s->ground);
    karma_contact_params_friction(&s->params, (MeReal)mu);
}

static void stepScene(Scene *s, double h)
{
    const MeVector3 half = {0.5f, 0.5f, 0.5f}, up = {0, 0, 1};
    karma_box_on_plane(s->ground, s->box, half, up, 0, &s->params);
    MdtWorldStep(s->world, (MeReal)h);
}

static double boxX(const Scene *s)
{
    MeVector3 p;
    MdtBodyGetPosition(s->box, p);
    return p[0];
}

static double boxVx(const Scene *s)
{
    MeVector3 v;
    MdtBodyGetLinearVelocity(s->box, v);
    return v[0];
}

static void incline_sticks_below_tan_mu(void **state)
{
    (void)state;
    const double mu = 0.5, theta = atan(mu) - 0.05; /* tan θ = 0.44 < μ */
    Scene s;
    makeIncline(&s, theta, mu);
    for (int i = 0; i < 120; i++)
        stepScene(&s, 1.0 / 60);
    double x = boxX(&s);
    print_message("incline tan=%.3f mu=%.2f: moved %.2e m in 2 s\n", tan(theta), mu, x);
    assert_true(fabs(x) < 1e-3);
    /* The friction force holds the tangential weight: F = m g sin θ along -x, summed over contacts. */
    MeVector3 f;
    MdtContactGroupGetForce(s.ground, 0, f);
    assert_near(f[0], -G * sin(theta), 0.02 * G);
    assert_near(f[2], G * cos(theta), 0.02 * G);
    MdtWorldDestroy(s.world);
}

static void incline_slides_above_tan_mu(void **state)
{
    (void)state;
    const double mu = 0.3, theta = 0.5; /* tan θ = 0.55 > μ */
    const double expected = G * (sin(theta) - mu * cos(theta));
    double steps[2] = {1.0 / 60, 1.0 / 240};
    for (int k = 0; k < 2; k++) {
        Scene s;
        makeIncline(&s, theta, mu);
        double h = steps[k];
        int n1 = (int)(0.5 / h), n2 = (int)(1.5 / h);
        double v1 = 0;
        for (int i = 1; i <= n2; i++) {
            stepScene(&s, h);
            if (i == n1)
                v1 = boxVx(&s);
        }
        double a = (boxVx(&s) - v1) / ((n2 - n1) * h);
        print_message("incline slide h=%.5f: a = %.4f vs g(sin - mu cos) = %.4f (%.2f %%)\n", h, a, expected,
                      100 * fabs(a - expected) / expected);
        assert_rel(a, expected, 0.02);
        MdtWorldDestroy(s.world);
    }
}

/* Box friction bounds the force, whatever the load: a box pushed by a force above the bound slides
 * with (F - bound)/m; below it, it stays. */
static void box_friction_is_a_force_cap(void **state)
{
    (void)state;
    const double bound = 2.0;
    for (int pass = 0; pass < 2; pass++) {
        double push = pass == 0 ? 1.5 : 5.0;
        Scene s;
        makeIncline(&s, 0, 0);
        MdtContactParamsSetFrictionModel(&s.params, MdtFrictionModelBox);
        /* Four contacts share the load: each is bounded by a quarter of the total. */
        MdtContactParamsSetFriction(&s.params, (MeReal)(bound / 4));
        double v1 = 0;
        for (int i = 1; i <= 120; i++) {
            MdtBodyAddForceAtPosition(s.box, (MeReal)push, 0, 0, 0, 0, 0.5f);
            stepScene(&s, 1.0 / 60);
            if (i == 60)
                v1 = boxVx(&s);
        }
        double a = (boxVx(&s) - v1) / 1.0;
        double expected = push > bound ? push - bound : 0;
        print_message("Box friction bound %.1f N, push %.1f N: a = %.4f (expected %.4f)\n", bound, push, a, expected);
        assert_near(a, expected, 0.02 * bound);
        MdtWorldDestroy(s.world);
    }
}

/* A ball dropped on a hand-made ground contact rebounds to e² of its drop height. The contact is
 * there all the time, with the ball's true separation (negative penetration) while it falls, as a
 * collision system with a generous contact tolerance would report it. */
static double dropBall(double H, double e, double h, double *velocityRatio)
{
    const double r = 0.25;
    MdtWorldID w = MdtWorldCreate(2, 8, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-G);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID ball = MdtBodyCreate(w);
    MdtBodySetPosition(ball, 0, 0, (MeReal)(r + H));
    MdtBodyEnable(ball);
    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(g, ball, NULL);
    MdtContactGroupEnable(g);
    MdtContactID c = MdtContactGroupCreateContact(g);
    MdtContactParamsSetRestitution(MdtContactGetParams(c), (MeReal)e);
    double apex = 0, vBefore = 0;
    int bounced = 0;
    *velocityRatio = 0;
    for (int i = 0; i < (int)(3.0 / h) && apex == 0; i++) {
        MeVector3 p, v;
        MdtBodyGetPosition(ball, p);
        MdtBodyGetLinearVelocity(ball, v);
        if (!bounced && v[2] < vBefore)
            vBefore = v[2]; /* the impact speed: the fastest approach */
        MdtContactSetPosition(c, p[0], p[1], 0);
        MdtContactSetNormal(c, 0, 0, 1); /* the ground pushes the ball (body 0) up */
        MdtContactSetPenetration(c, (MeReal)(r - p[2]));
        MdtWorldStep(w, (MeReal)h);
        MdtBodyGetPosition(ball, p);
        MdtBodyGetLinearVelocity(ball, v);
        if (v[2] > 0 && !bounced) {
            bounced = 1;
            *velocityRatio = -v[2] / vBefore;
        }
        if (bounced && v[2] <= 0)
            apex = p[2] - r;
    }
    MdtWorldDestroy(w);
    return apex;
}

static void restitution_height(void **state)
{
    (void)state;
    const double H = 2.0;
    const double es[2] = {0.6, 0.9}, hs[2] = {1.0 / 60, 1.0 / 240};
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 2; k++) {
            double ratio;
            double apex = dropBall(H, es[i], hs[k], &ratio);
            double expected = es[i] * es[i] * H;
            print_message("restitution e=%.2f h=%.5f from %.2f m: speed ratio %.4f, apex %.4f m vs e^2 H = %.4f "
                          "(%.2f %%)\n",
                          es[i], hs[k], H, ratio, apex, expected, 100 * fabs(apex - expected) / expected);
            /* The contact law itself, at any step: the rebound speed is e times the impact speed. */
            assert_rel(ratio, es[i], 0.005);
            /* The height, where the integrator's own first-order error (about (e²+e) v h / 2, 7 % at
             * 60 Hz here) is small against the 2 % asked: at 240 Hz. */
            if (hs[k] < 0.005)
                assert_rel(apex, expected, 0.02);
        }
}

/* A box resting on four contacts stays put: drift below 1e-4 lengthScale in 10 s. */
static void resting_box_does_not_drift(void **state)
{
    (void)state;
    Scene s;
    makeIncline(&s, 0, 0.6);
    for (int i = 0; i < 60; i++)
        stepScene(&s, 1.0 / 60); /* settle into its equilibrium penetration */
    MeVector3 p0, p;
    MeVector4 q0, q;
    MdtBodyGetPosition(s.box, p0);
    MdtBodyGetQuaternion(s.box, q0);
    for (int i = 0; i < 600; i++)
        stepScene(&s, 1.0 / 60);
    MdtBodyGetPosition(s.box, p);
    MdtBodyGetQuaternion(s.box, q);
    double drift = sqrt((p[0] - p0[0]) * (p[0] - p0[0]) + (p[1] - p0[1]) * (p[1] - p0[1]) +
                        (p[2] - p0[2]) * (p[2] - p0[2]));
    print_message("resting box: drift %.2e m in 10 s, rest penetration %.2e m\n", drift, -(p[2] - 0.5));
    assert_true(drift < 1e-4);
    assert_near(q[0], q0[0], 1e-5);
    MdtWorldDestroy(s.world);
}

/* A column of 20 unit boxes on hand-made contacts (mu 0.6, h 1/60) stands for 20 s with the top box
 * within 0.02 m of where it started, on each path at its default settings: Auto (the partition's
 * 240 rows are beyond the dense limit, but a column's ordered factor is sparse, so it is solved
 * exactly) and the iterative path forced. */
static void column_of_twenty_stands_on(MdtLCPSolver solver)
{
    enum { N = 20 };
    const MeVector3 half = {0.5f, 0.5f, 0.5f}, up = {0, 0, 1};
    MdtWorldID w = MdtWorldCreate(N, 5 * N, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-G);
    MdtWorldSetLCPSolver(w, solver);
    MdtBodyID box[N];
    MdtContactGroupID group[N];
    MdtContactParams params;
    karma_contact_params_friction(&params, 0.6f);
    MeMatrix3 I;
    MdtMakeInertiaTensorBox(1, 1, 1, 1, I);
    for (int i = 0; i < N; i++) {
        box[i] = MdtBodyCreate(w);
        MdtBodySetInertiaTensor(box[i], I);
        MdtBodySetPosition(box[i], 0, 0, 0.5f + i);
        MdtBodyEnable(box[i]);
        group[i] = MdtContactGroupCreate(w);
        MdtContactGroupSetBodies(group[i], box[i], i ? box[i - 1] : NULL);
        MdtContactGroupEnable(group[i]);
    }
    MeVector3 top0, top;
    MdtBodyGetPosition(box[N - 1], top0);
    double worst = 0;
    MdtSolverStats stats;
    for (int step = 0; step < 20 * 60; step++) {
        for (int i = 0; i < N; i++) {
            if (i == 0)
                karma_box_on_plane(group[0], box[0], half, up, 0, &params);
            else
                karma_box_on_box(group[i], box[i], box[i - 1], half, &params);
        }
        MdtWorldStep(w, ME_R(1.0) / 60);
        MdtBodyGetPosition(box[N - 1], top);
        double d = sqrt((top[0] - top0[0]) * (top[0] - top0[0]) + (top[1] - top0[1]) * (top[1] - top0[1]) +
                        (top[2] - top0[2]) * (top[2] - top0[2]));
        worst = fmax(worst, d);
        if (step == 0)
            MdtWorldGetSolverStats(w, &stats);
    }
    print_message("column of %d: top box moved at most %.4f m in 20 s (%d rows, %s path, %d iterations)\n", N, worst,
                  stats.rows, stats.iterativePartitions ? "iterative" : "direct", stats.iterations);
    assert_int_equal(stats.iterativePartitions, solver == MdtLCPSolverIterative ? 1 : 0);
    assert_int_equal(stats.directPartitions, solver == MdtLCPSolverIterative ? 0 : 1);
    assert_true(worst < 0.02);
    MdtWorldDestroy(w);
}

static void column_of_twenty_stands(void **state)
{
    (void)state;
    column_of_twenty_stands_on(MdtLCPSolverAuto);
    column_of_twenty_stands_on(MdtLCPSolverIterative);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(incline_sticks_below_tan_mu),  cmocka_unit_test(incline_slides_above_tan_mu),
        cmocka_unit_test(box_friction_is_a_force_cap),  cmocka_unit_test(restitution_height),
        cmocka_unit_test(resting_box_does_not_drift),   cmocka_unit_test(column_of_twenty_stands),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
