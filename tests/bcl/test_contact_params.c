/* Every contact parameter of docs/karma12.md §5.6 on hand-made contacts, each against its closed-form answer:
 * Friction1D and an explicit primary direction (anisotropic Box friction), the restitution velocity
 * threshold, softness (rest penetration and contact forces), adhesion, slip, slide, and the world
 * velocity (a moving surface). A unit box (1 kg) rests on the plane z = 0 on four corner contacts
 * (karma_box_on_plane), gravity −z. */
#include "karma_test.h"
#include "karma_contacts.h"

#include <karma/Mdt.h>

static const double G = 9.81, H = 1.0 / 60;
static const MeVector3 HALF = {0.5f, 0.5f, 0.5f}, UP = {0, 0, 1};

typedef struct Scene {
    MdtWorldID w;
    MdtBodyID box;
    MdtContactGroupID g;
    MdtContactParams params;
    MeVector3 up;     /* the plane's normal (towards the box) */
    MeReal offset;    /* the plane: x·up = offset */
    MeReal dir[3];    /* primary direction given to every contact, when set */
    int useDir;
    MeReal worldVel[3]; /* velocity of the plane's surface, when set */
    int useWorldVel;
    double h;           /* the step */
} Scene;

static void makeScene(Scene *s, double z)
{
    s->w = MdtWorldCreate(4, 16, 1, 1);
    MdtWorldSetGravity(s->w, 0, 0, (MeReal)-G);
    MdtWorldSetAutoDisable(s->w, MEFALSE);
    s->box = MdtBodyCreate(s->w);
    MeMatrix3 I;
    MdtMakeInertiaTensorBox(1, 1, 1, 1, I);
    MdtBodySetInertiaTensor(s->box, I);
    MdtBodySetPosition(s->box, 0, 0, (MeReal)z);
    MdtBodyEnable(s->box);
    s->g = MdtContactGroupCreate(s->w);
    MdtContactGroupSetBodies(s->g, s->box, NULL);
    MdtContactGroupEnable(s->g);
    MdtContactParamsReset(&s->params);
    MeVector3Copy(s->up, UP);
    s->offset = 0;
    s->useDir = s->useWorldVel = 0;
    s->h = H;
}

/* Refresh the four contacts (parameters, geometry, direction, world velocity), then step. */
static void stepScene(Scene *s)
{
    karma_box_on_plane(s->g, s->box, HALF, s->up, s->offset, &s->params);
    for (MdtContactID c = MdtContactGroupGetFirstContact(s->g); c; c = MdtContactGroupGetNextContact(s->g, c)) {
        if (s->useDir)
            MdtContactSetDirection(c, s->dir[0], s->dir[1], s->dir[2]);
        if (s->useWorldVel)
            MdtContactSetWorldVelocity(c, s->worldVel[0], s->worldVel[1], s->worldVel[2]);
    }
    MdtWorldStep(s->w, (MeReal)s->h);
}

static void steps(Scene *s, int n)
{
    for (int i = 0; i < n; i++)
        stepScene(s);
}

/* Push the box with (fx, fy) N at the centre of its bottom face (the line of the contact forces: no
 * tipping torque) for n steps. */
static void pushSteps(Scene *s, double fx, double fy, int n)
{
    for (int i = 0; i < n; i++) {
        MeVector3 p;
        MdtBodyGetPosition(s->box, p);
        MdtBodyAddForceAtPosition(s->box, (MeReal)fx, (MeReal)fy, 0, p[0], p[1], p[2] - 0.5f);
        stepScene(s);
    }
}

static void velocity(const Scene *s, MeVector3 v) { MdtBodyGetLinearVelocity(s->box, v); }

/* ---- Friction1D, primary direction, anisotropic Box friction ---- */
static void friction_1d_and_primary_direction(void **state)
{
    (void)state;
    /* Friction1D along x (unbounded Box friction): pushed along x and y, the box holds along x and
     * slides freely along y (a = F / m exactly); each contact writes 2 rows. */
    Scene s;
    makeScene(&s, 0.5);
    MdtContactParamsSetType(&s.params, MdtContactTypeFriction1D);
    s.useDir = 1;
    s.dir[0] = 1, s.dir[1] = 0, s.dir[2] = 0;
    steps(&s, 10);
    pushSteps(&s, 3, 3, 60);
    MeVector3 v;
    velocity(&s, v);
    int rows = MdtConstraintGetRowCount(MdtContactGroupQuaConstraint(s.g));
    print_message("Friction1D along x, push (3, 3) N for 1 s: v = (%.2e, %.5f) m/s (0, 3), %d rows\n", v[0], v[1],
                  rows);
    assert_int_equal(rows, 8);
    assert_near(v[0], 0, 1e-3);
    assert_rel(v[1], 3, 1e-3);
    MdtWorldDestroy(s.w);

    /* Anisotropic Box friction (2D): bound 2 N along the primary direction, 1 N along the secondary
     * (a quarter per contact). With the primary along x, a 5 N push along x slides at 3 m/s², along y
     * at 4 m/s²; with the primary turned to y, the two swap. */
    const double expect[2][2] = {{3, 4}, {4, 3}};
    for (int turned = 0; turned < 2; turned++)
        for (int axis = 0; axis < 2; axis++) {
            makeScene(&s, 0.5);
            MdtContactParamsSetType(&s.params, MdtContactTypeFriction2D);
            MdtContactParamsSetPrimaryFriction(&s.params, 0.5f);
            MdtContactParamsSetSecondaryFriction(&s.params, 0.25f);
            s.useDir = 1;
            s.dir[0] = turned ? 0 : 1, s.dir[1] = turned ? 1 : 0, s.dir[2] = 0;
            steps(&s, 10);
            pushSteps(&s, axis == 0 ? 5 : 0, axis == 1 ? 5 : 0, 30);
            velocity(&s, v);
            double v0 = v[axis];
            pushSteps(&s, axis == 0 ? 5 : 0, axis == 1 ? 5 : 0, 60);
            velocity(&s, v);
            double a = (v[axis] - v0) / (60 * H);
            print_message("Box friction (2 N primary, 1 N secondary), primary along %c, push 5 N along %c: a = %.5f "
                          "(%.0f)\n",
                          turned ? 'y' : 'x', axis ? 'y' : 'x', a, expect[turned][axis]);
            assert_rel(a, expect[turned][axis], 1e-3);
            assert_near(v[1 - axis], 0, 1e-4);
            MdtWorldDestroy(s.w);
        }
}

/* ---- restitution threshold ---- */
/* A 1 kg ball of radius 0.25 dropped from `drop` m onto one contact (kept with the true separation);
 * returns the rebound speed over the impact speed. */
static double bounceRatio(double drop, double e, double threshold)
{
    const double r = 0.25;
    MdtWorldID w = MdtWorldCreate(2, 4, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-G);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID ball = MdtBodyCreate(w);
    MdtBodySetPosition(ball, 0, 0, (MeReal)(r + drop));
    MdtBodyEnable(ball);
    MdtContactID c = MdtContactCreate(w);
    MdtContactSetBodies(c, ball, NULL);
    MdtContactEnable(c);
    MdtContactParamsSetRestitution(MdtContactGetParams(c), (MeReal)e);
    MdtContactParamsSetRestitutionThreshold(MdtContactGetParams(c), (MeReal)threshold);
    double impact = 0, rebound = 0;
    for (int i = 0; i < (int)(2.0 / H); i++) {
        MeVector3 p, v;
        MdtBodyGetPosition(ball, p);
        MdtBodyGetLinearVelocity(ball, v);
        if (rebound == 0)
            impact = fmax(impact, -v[2]);
        MdtContactSetPosition(c, p[0], p[1], 0);
        MdtContactSetNormal(c, 0, 0, 1); /* the ground pushes the ball (body 0) up */
        MdtContactSetPenetration(c, (MeReal)(r - p[2]));
        MdtWorldStep(w, (MeReal)H);
        MdtBodyGetLinearVelocity(ball, v);
        rebound = fmax(rebound, v[2]);
    }
    MdtWorldDestroy(w);
    return rebound / impact;
}

static void restitution_velocity_threshold(void **state)
{
    (void)state;
    /* A drop of 2 cm arrives at 0.63 m/s: below a threshold of 1 m/s it does not bounce, above one of
     * 0.1 m/s it does, with e = 0.5. A 2 m drop (6.3 m/s) bounces past the 1 m/s threshold. */
    double low = bounceRatio(0.02, 0.5, 1), high = bounceRatio(0.02, 0.5, 0.1), far = bounceRatio(2, 0.5, 1);
    MdtContactParams p;
    MdtContactParamsReset(&p);
    print_message("restitution 0.5: 0.63 m/s impact, threshold 1 m/s: ratio %.4f (0); threshold 0.1: %.4f (0.5); "
                  "6.3 m/s impact, threshold 1: %.4f (0.5); default threshold %.4f\n",
                  low, high, far, MdtContactParamsGetRestitutionThreshold(&p));
    assert_near(MdtContactParamsGetRestitutionThreshold(&p), 0.001, 1e-9);
    assert_near(low, 0, 0.02);
    assert_rel(high, 0.5, 0.01);
    assert_rel(far, 0.5, 0.01);
}

/* ---- softness, contact forces ---- */
static void softness_and_contact_forces(void **state)
{
    (void)state;
    /* At rest each contact row satisfies (ε + softness) x = γ p / h with x = (m g / 4) h, so the box
     * sinks to p = (ε + softness) (m g / 4) h² / γ. */
    const double softs[2] = {0, 1};
    for (int k = 0; k < 2; k++) {
        Scene s;
        makeScene(&s, 0.5);
        MdtContactParamsSetType(&s.params, MdtContactTypeFriction2D);
        MdtContactParamsSetFrictionModel(&s.params, MdtFrictionModelNormalForce);
        MdtContactParamsSetFrictionCoeffecient(&s.params, 0.5f);
        if (softs[k] > 0) {
            MdtContactParamsSetSoftness(&s.params, (MeReal)softs[k]);
            assert_true(s.params.options & MdtBclContactOptionSoft);
        }
        steps(&s, 600);
        MeVector3 p;
        MdtBodyGetPosition(s.box, p);
        const double eps = MdtWorldGetEpsilon(s.w) + softs[k], gamma = MdtWorldGetGamma(s.w);
        const double predicted = eps * (G / 4) * H * H / gamma, sink = 0.5 - p[2];
        double sum = 0, least = 1e9, most = 0;
        for (MdtContactID c = MdtContactGroupGetFirstContact(s.g); c; c = MdtContactGroupGetNextContact(s.g, c)) {
            double f = MdtContactGetNormalForce(c);
            sum += f;
            least = fmin(least, f);
            most = fmax(most, f);
        }
        MeVector3 f, t;
        MdtConstraintGetForce(MdtContactGroupQuaConstraint(s.g), 0, f);
        MdtConstraintGetTorque(MdtContactGroupQuaConstraint(s.g), 0, t);
        print_message("softness %.1f: sinks %.4e m (predicted %.4e); contact normal forces %.4f..%.4f N, sum %.4f, "
                      "group %.4f, force on the box (%.1e, %.1e, %.5f), torque %.1e\n",
                      softs[k], sink, predicted, least, most, sum, MdtContactGroupGetNormalForce(s.g), f[0], f[1],
                      f[2], sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
        assert_rel(sink, predicted, ME_TOL(1e-3, 0.02));
        assert_rel(least, G / 4, 1e-3);
        assert_rel(most, G / 4, 1e-3);
        assert_rel(MdtContactGroupGetNormalForce(s.g), G, 1e-3);
        assert_rel(f[2], G, 1e-3);
        assert_near(f[0], 0, 1e-4);
        assert_near(t[0], 0, 1e-4);
        assert_near(t[1], 0, 1e-4);
        MdtWorldDestroy(s.w);
    }
}

/* ---- adhesion ---- */
static void adhesion_holds_up_to_its_force(void **state)
{
    (void)state;
    /* The box hangs under a ceiling z = 1 (its top face on four contacts). An adhesive force of 5 N per
     * contact (20 N) holds its 9.81 N weight, the contacts pulling m g / 4 each; 1 N per contact lets
     * it fall at g − 4 N / m while the contacts keep pulling; without adhesion it falls at g. */
    const double adhesion[3] = {5, 1, 0};
    for (int k = 0; k < 3; k++) {
        Scene s;
        makeScene(&s, 0.5);
        MeVector3Set(s.up, 0, 0, -1);
        s.offset = -1; /* −z = −1 */
        if (adhesion[k] > 0) {
            MdtContactParamsSetMaxAdhesiveForce(&s.params, (MeReal)adhesion[k]);
            assert_true(s.params.options & MdtBclContactOptionAdhesive);
        }
        steps(&s, 30);
        MeVector3 v, p;
        velocity(&s, v);
        MdtBodyGetPosition(s.box, p);
        double pull = -MdtContactGroupGetNormalForce(s.g);
        if (k == 0) {
            print_message("adhesion 4 x 5 N: hangs at z = %.5f, v %.1e m/s, contacts pull %.4f N (m g)\n", p[2], v[2],
                          pull);
            assert_near(p[2], 0.5, 1e-3);
            assert_near(v[2], 0, 1e-4);
            assert_rel(pull, G, 1e-3);
        } else {
            double expected = -(G - 4 * adhesion[k]) * 30 * H;
            print_message("adhesion 4 x %.0f N: after 0.5 s v = %.5f m/s (%.5f), contacts pull %.4f N\n", adhesion[k],
                          v[2], expected, pull);
            assert_rel(v[2], expected, 1e-3);
            assert_near(pull, 4 * adhesion[k], 1e-3);
        }
        MdtWorldDestroy(s.w);
    }
}

/* ---- slip ---- */
static void slip_gives_velocity_proportional_to_force(void **state)
{
    (void)state;
    /* Unbounded friction with slip s (User Guide: slip speed = slip × friction force, not scaled by
     * the step): a steady push F shared by the four contacts slides the box at s F / 4, with no static
     * phase; twice the force, twice the speed; the same at two step sizes. The slipping rows keep a
     * trace of the world's ε (10⁻³ ε₀ per impulse), which adds 10⁻³ ε₀ h F / 4. */
    const double slip = 0.02, forces[2] = {4, 8}, stepSizes[2] = {H, H / 4};
    double speeds[2][2];
    for (int k = 0; k < 2; k++)
        for (int j = 0; j < 2; j++) {
            Scene s;
            makeScene(&s, 0.5);
            s.h = stepSizes[j];
            MdtContactParamsSetType(&s.params, MdtContactTypeFriction2D);
            MdtContactParamsSetSlip(&s.params, (MeReal)slip);
            assert_true((s.params.options & (MdtBclContactOptionSlip1 | MdtBclContactOptionSlip2)) ==
                        (MdtBclContactOptionSlip1 | MdtBclContactOptionSlip2));
            steps(&s, (int)(0.2 / s.h));
            pushSteps(&s, forces[k], 0, (int)(2.0 / s.h));
            MeVector3 v;
            velocity(&s, v);
            speeds[k][j] = v[0];
            double expected = slip * forces[k] / 4, trace = 1e-3 * MdtWorldGetEpsilon(s.w) * s.h * forces[k] / 4;
            print_message("slip %.2f s/kg, push %.0f N, step 1/%.0f s: slides at %.7f m/s (s F / 4 = %.7f, + trace "
                          "%.1e)\n",
                          slip, forces[k], 1 / s.h, v[0], expected, trace);
            assert_rel(v[0], expected + trace, 1e-4);
            assert_near(v[1], 0, 1e-6);
            MdtWorldDestroy(s.w);
        }
    assert_rel(speeds[1][0], 2 * speeds[0][0], 1e-4);
    assert_rel(speeds[0][1], speeds[0][0], 1e-4); /* independent of the step */
    assert_rel(speeds[1][1], speeds[1][0], 1e-4);
}

/* ---- slide ---- */
static void slide_sets_the_relative_tangential_velocity(void **state)
{
    (void)state;
    /* Slide 0.5 m/s along the primary direction t1 = x and 0.2 along the secondary t2 = t1 × normal =
     * x × (0, 0, 1) = −y (as Karma; the normal points from body 1, the world, to body 0, the box): the
     * contacts drive the velocity of body 0 relative to body 1 at the contact to 0.5 t1 + 0.2 t2 =
     * (0.5, −0.2, 0), so the box moves at (0.5, −0.2, 0). */
    Scene s;
    makeScene(&s, 0.5);
    MdtContactParamsSetType(&s.params, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(&s.params, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(&s.params, 1);
    MdtContactParamsSetPrimarySlide(&s.params, 0.5f);
    MdtContactParamsSetSecondarySlide(&s.params, 0.2f);
    assert_true((s.params.options & (MdtBclContactOptionSlide1 | MdtBclContactOptionSlide2)) ==
                (MdtBclContactOptionSlide1 | MdtBclContactOptionSlide2));
    s.useDir = 1;
    s.dir[0] = 1, s.dir[1] = 0, s.dir[2] = 0;
    steps(&s, 60);
    MeVector3 v, rel, q;
    velocity(&s, v);
    MdtContactGetRelativeVelocity(MdtContactGroupGetFirstContact(s.g), rel);
    MdtBodyGetAngularVelocity(s.box, q);
    print_message("slide (0.5 along x, 0.2 along -y): box v = (%.5f, %.5f, %.1e), contact relative velocity (%.5f, %.5f, %.1e), "
                  "spin %.1e\n",
                  v[0], v[1], v[2], rel[0], rel[1], rel[2], sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
    assert_near(v[0], 0.5, 1e-4);
    assert_near(v[1], -0.2, 1e-4);
    assert_near(rel[0], 0.5, 1e-4);
    assert_near(rel[1], -0.2, 1e-4);
    assert_near(rel[2], 0, 1e-4);
    MdtWorldDestroy(s.w);
}

/* ---- world velocity ---- */
static void world_velocity_carries_the_box(void **state)
{
    (void)state;
    /* The plane's surface moves at 1 m/s along x (a conveyor): Coulomb friction (μ 0.6) accelerates
     * the box at μ g until it moves with the surface, then the contact's relative velocity is 0. */
    const double mu = 0.6;
    Scene s;
    makeScene(&s, 0.5);
    karma_contact_params_friction(&s.params, (MeReal)mu);
    s.useWorldVel = 1;
    s.worldVel[0] = 1, s.worldVel[1] = 0, s.worldVel[2] = 0;
    steps(&s, 6);
    MeVector3 v, rel, wv;
    velocity(&s, v);
    double early = v[0];
    steps(&s, 54);
    velocity(&s, v);
    MdtContactID c = MdtContactGroupGetFirstContact(s.g);
    MdtContactGetRelativeVelocity(c, rel);
    MdtContactGetWorldVelocity(c, wv);
    print_message("conveyor at 1 m/s, mu %.1f: after 0.1 s v = %.5f (mu g t = %.5f); after 1 s v = %.6f, relative "
                  "velocity %.1e\n",
                  mu, early, mu * G * 6 * H, v[0], rel[0]);
    assert_true(MdtContactGetParams(c)->options & MdtBclContactOptionUseWorldVelocity);
    assert_true(wv[0] == 1 && wv[1] == 0 && wv[2] == 0);
    assert_rel(early, mu * G * 6 * H, 0.01);
    assert_near(v[0], 1, 1e-4);
    assert_near(rel[0], 0, 1e-4);
    MdtWorldDestroy(s.w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(friction_1d_and_primary_direction),
        cmocka_unit_test(restitution_velocity_threshold),
        cmocka_unit_test(softness_and_contact_forces),
        cmocka_unit_test(adhesion_holds_up_to_its_force),
        cmocka_unit_test(slip_gives_velocity_proportional_to_force),
        cmocka_unit_test(slide_sets_the_relative_tangential_velocity),
        cmocka_unit_test(world_velocity_carries_the_box),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
