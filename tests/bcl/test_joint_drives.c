/* Joints in motion against closed-form answers: RPRO reaching and tracking a target (and a finite
 * strength capping its torque), a pendulum on a fixed path, a Cardan shaft, a point in a plane, a
 * pendulum on a cart on a rail (Linear2), and a pendulum made by a user-written distance row. */
#include "karma_test.h"

#include <karma/Mdt.h>

#define PI 3.14159265358979323846
#define G 9.81

static MdtWorldID newWorld(double gravity)
{
    MdtWorldID w = MdtWorldCreate(4, 8, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-gravity);
    MdtWorldSetAutoDisable(w, MEFALSE);
    return w;
}

static MdtBodyID newBody(MdtWorldID w, double mass, double inertia, double x, double y, double z)
{
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetMass(b, (MeReal)mass);
    MdtBodySetSphericalInertiaTensor(b, (MeReal)inertia);
    MdtBodySetPosition(b, (MeReal)x, (MeReal)y, (MeReal)z);
    MdtBodyEnable(b);
    return b;
}

/* Angle of the rotation between two orientations: 2 asin |vec(conj(p) q)| (precise near 0). */
static double angleBetween(const MeVector4 p, const MeVector4 q)
{
    double x = (double)p[0] * q[1] - (double)p[1] * q[0] - (double)p[2] * q[3] + (double)p[3] * q[2];
    double y = (double)p[0] * q[2] - (double)p[2] * q[0] - (double)p[3] * q[1] + (double)p[1] * q[3];
    double z = (double)p[0] * q[3] - (double)p[3] * q[0] - (double)p[1] * q[2] + (double)p[2] * q[1];
    return 2 * asin(fmin(1.0, sqrt(x * x + y * y + z * z)));
}

static void rpro_reaches_and_tracks_its_target(void **s)
{
    (void)s;
    MdtWorldID w = newWorld(G);
    MdtBodyID b = newBody(w, 1, 0.1, 0, 0, 0);
    MdtRPROJointID j = MdtRPROJointCreate(w);
    MdtRPROJointSetBodies(j, b, NULL);
    MeVector3 axis = {1, 1, 0};
    MeVector4 target, q;
    MeQuaternionMake(target, axis, (MeReal)(PI / 3));
    MdtRPROJointSetRelativeQuaternion(j, target);
    MdtRPROJointEnable(j);
    int steps = 0;
    double err = 0;
    for (; steps < 120; steps++) {
        MdtWorldStep(w, ME_R(1.0) / 60);
        MdtBodyGetQuaternion(b, q);
        err = angleBetween(q, target);
        if (err < 1e-3)
            break;
    }
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    print_message("RPRO: 60 deg target reached within 1e-3 rad after %d steps (gamma 0.2); position held at %.1e m\n",
                  steps + 1, sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    assert_true(steps < 60);
    assert_true(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) < 1e-3);

    /* Tracking: the target turns at 2 rad/s about z (body 1's frame: the world). */
    MeVector3 omega = {0, 0, 2};
    MdtRPROJointSetAngularVelocity(j, omega);
    double worst = 0;
    for (int i = 0; i < 120; i++) {
        MdtRPROJointSetRelativeQuaternion(j, target);
        MdtWorldStep(w, ME_R(1.0) / 60);
        MeQuaternionFiniteRotation(target, omega, ME_R(1.0) / 60);
        MdtBodyGetQuaternion(b, q);
        if (i >= 60) /* after the 1e-3 left from above has decayed */
            worst = fmax(worst, angleBetween(q, target));
    }
    MeVector3 wb;
    MdtBodyGetAngularVelocity(b, wb);
    /* The lag left is the integrator's: a first-order quaternion update turns by 2 atan(ω h / 2), short
     * of ω h by (ω h)³/12 per step, which γ = 0.2 holds at about 5 times that. */
    double h = 1.0 / 60, predicted = pow(2 * h, 3) / 12 / 0.2;
    print_message("RPRO tracking 2 rad/s: body turns at (%.4f, %.4f, %.4f) rad/s, largest lag %.2e rad (predicted "
                  "%.2e)\n",
                  wb[0], wb[1], wb[2], worst, predicted);
    assert_near(wb[2], 2, 1e-3);
    assert_true(worst < 2 * predicted);
    MdtWorldDestroy(w);
}

static void rpro_strength_caps_the_torque(void **s)
{
    (void)s;
    const double I = 0.1, cap = 0.5;
    MdtWorldID w = newWorld(0);
    MdtBodyID b = newBody(w, 1, I, 0, 0, 0);
    MdtRPROJointID j = MdtRPROJointCreate(w);
    MdtRPROJointSetBodies(j, b, NULL);
    MdtRPROJointSetAngularStrength(j, (MeReal)cap, (MeReal)cap, (MeReal)cap);
    MeVector3 z = {0, 0, 1};
    MeVector4 target, q;
    MeQuaternionMake(target, z, (MeReal)(PI / 2));
    MdtRPROJointSetRelativeQuaternion(j, target);
    MdtRPROJointEnable(j);
    double largest = 0, first = 0, firstRate = 0;
    for (int i = 0; i < 600; i++) {
        MdtWorldStep(w, ME_R(1.0) / 60);
        MeVector3 t, wb;
        MdtRPROJointGetTorque(j, 0, t);
        largest = fmax(largest, sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
        if (i == 0) {
            first = t[2];
            MdtBodyGetAngularVelocity(b, wb);
            firstRate = wb[2];
        }
    }
    MdtBodyGetQuaternion(b, q);
    print_message("RPRO angular strength %.2f N m: first torque %.4f N m (spin-up %.4f rad/s vs cap h / I = %.4f), "
                  "largest %.4f N m; after 10 s %.2e rad from the target\n",
                  cap, first, firstRate, cap / 60 / I, largest, angleBetween(q, target));
    assert_near(first, cap, cap * 1e-3);
    assert_near(firstRate, cap / 60 / I, 1e-4);
    assert_true(largest <= cap * (1 + 1e-3));
    assert_true(angleBetween(q, target) < 1e-3);
    MdtWorldDestroy(w);
}

/* Distance of the bob from the pivot that moves on a circle of radius 0.3 m at 2 rad/s. */
static double fixedPathDrift(MeBool giveVelocity)
{
    const double R = 0.3, wp = 2, h = 1.0 / 60;
    MdtWorldID w = newWorld(G);
    MdtBodyID bob = newBody(w, 1, 1e-3, R, 0, -1);
    MdtFixedPathID j = MdtFixedPathCreate(w);
    MdtFixedPathSetBodies(j, bob, NULL);
    MdtFixedPathSetPosition(j, 0, (MeReal)R, 0, 0); /* the point of the bob 1 m above it */
    MdtFixedPathEnable(j);
    double worst = 0, t = 0;
    for (int i = 0; i < 300; i++) {
        MdtFixedPathSetPosition(j, 1, (MeReal)(R * cos(wp * t)), (MeReal)(R * sin(wp * t)), 0);
        if (giveVelocity)
            MdtFixedPathSetVelocity(j, 1, (MeReal)(-R * wp * sin(wp * t)), (MeReal)(R * wp * cos(wp * t)), 0);
        MdtWorldStep(w, (MeReal)h);
        t += h;
        MeVector3 p;
        MdtBodyGetPosition(bob, p);
        double dx = p[0] - R * cos(wp * t), dy = p[1] - R * sin(wp * t), dz = p[2];
        worst = fmax(worst, fabs(sqrt(dx * dx + dy * dy + dz * dz) - 1));
    }
    MdtWorldDestroy(w);
    return worst;
}

static void fixed_path_pendulum_keeps_its_length(void **s)
{
    (void)s;
    double with = fixedPathDrift(METRUE), without = fixedPathDrift(MEFALSE);
    print_message("FixedPath pivot on a circle (0.3 m, 0.6 m/s): largest length error %.2e m with the path velocity, "
                  "%.2e m with positions only\n",
                  with, without);
    assert_true(with < 2e-3);
    assert_true(without > 5 * with);
}

static void universal_joint_drives_a_shaft(void **s)
{
    (void)s;
    const double beta = PI / 6, omega = 2 * PI, h = 1.0 / 240;
    const double dx = cos(beta), dy = sin(beta);
    MdtWorldID w = newWorld(0);
    /* A, heavy and kept turning at 2π rad/s, drives B through the joint. */
    MdtBodyID A = newBody(w, 1, 10, -1, 0, 0), B = newBody(w, 1, 0.1, dx, dy, 0);
    /* Each shaft turns about its own axis through its centre: ball and socket + Angular2. */
    MdtBodyID shafts[2] = {A, B};
    const double axes[2][3] = {{1, 0, 0}, {dx, dy, 0}};
    for (int i = 0; i < 2; i++) {
        MeVector3 c;
        MdtBodyGetPosition(shafts[i], c);
        MdtBSJointID bs = MdtBSJointCreate(w);
        MdtBSJointSetBodies(bs, shafts[i], NULL);
        MdtBSJointSetPosition(bs, c[0], c[1], c[2]);
        MdtBSJointEnable(bs);
        MdtAngular3ID a3 = MdtAngular3Create(w);
        MdtAngular3SetBodies(a3, shafts[i], NULL);
        MdtAngular3SetAxis(a3, (MeReal)axes[i][0], (MeReal)axes[i][1], (MeReal)axes[i][2]);
        MdtAngular3EnableRotation(a3, METRUE);
        MdtAngular3Enable(a3);
    }
    MdtUniversalID u = MdtUniversalCreate(w);
    MdtUniversalSetBodies(u, A, B);
    MdtUniversalSetPosition(u, 0, 0, 0);
    MdtUniversalSetAxis(u, 0, 0, 0, 1);
    MdtUniversalSetAxis(u, 1, (MeReal)-dy, (MeReal)dx, 0);
    MdtUniversalEnable(u);
    double angleA = 0, angleB = 0, lo = 10, hi = 0, perp = 0;
    int n = (int)(2 / h); /* two turns of A */
    for (int i = 0; i < n; i++) {
        MdtBodySetAngularVelocity(A, (MeReal)omega, 0, 0);
        MdtWorldStep(w, (MeReal)h);
        MeVector3 wb, a0, a1;
        MdtBodyGetAngularVelocity(B, wb);
        double rate = wb[0] * dx + wb[1] * dy;
        angleB += rate * h;
        MeVector3 wa;
        MdtBodyGetAngularVelocity(A, wa);
        angleA += wa[0] * h;
        lo = fmin(lo, rate / wa[0]);
        hi = fmax(hi, rate / wa[0]);
        MdtUniversalGetAxis(u, 0, a0);
        MdtUniversalGetAxis(u, 1, a1);
        perp = fmax(perp, fabs(a0[0] * a1[0] + a0[1] * a1[1] + a0[2] * a1[2]));
    }
    print_message("Universal, shafts at 30 deg: B turned %.4f turns for A's %.4f; speed ratio %.4f ... %.4f vs cos b = "
                  "%.4f ... 1/cos b = %.4f; largest |a0.a1| %.1e\n",
                  angleB / (2 * PI), angleA / (2 * PI), lo, hi, cos(beta), 1 / cos(beta), perp);
    assert_near(angleB / angleA, 1, 0.005);
    assert_near(lo, cos(beta), 0.01);
    assert_near(hi, 1 / cos(beta), 0.01);
    assert_true(perp < 2e-3);
    MdtWorldDestroy(w);
}

static void linear1_keeps_a_point_in_the_plane(void **s)
{
    (void)s;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtWorldSetGravity(w, 2, 1, 0); /* in the plane */
    MdtBodyID b = newBody(w, 1, 0.1, 0, 0, 0.3);
    MdtBodySetAngularVelocity(b, 1, 2, 3);
    MdtLinear1ID j = MdtLinear1Create(w);
    MdtLinear1SetBodies(j, b, NULL);
    MdtLinear1SetPosition(j, 0, 0, 0); /* body's point 0.3 m below its centre, in the plane z = 0 */
    MdtLinear1SetAxis(j, 0, 0, 1);
    MdtLinear1Enable(j);
    double worst = 0;
    for (int i = 0; i < 120; i++) {
        MdtWorldStep(w, ME_R(1.0) / 60);
        MeVector3 p;
        MdtConstraintBodyGetPosition(MdtLinear1QuaConstraint(j), 0, p);
        worst = fmax(worst, fabs(p[2]));
    }
    /* In the plane the centre falls freely: after n steps, g h² n(n+1)/2 along (2, 1). */
    MeVector3 c;
    MdtBodyGetPosition(b, c);
    double expected = 2 * (1.0 / 3600) * 120 * 121 / 2;
    /* Off the plane: the second-order drift of a point turning at |ω| about the centre, ≈ ω² r h² / 2 per
     * step, held at about that over γ. */
    print_message("Linear1: point off the plane at most %.1e m while spinning at 3.7 rad/s; centre moved %.5f m along "
                  "x vs free fall %.5f m\n",
                  worst, c[0], expected);
    assert_true(worst < 2e-3);
    assert_near(c[0], expected, 2e-3 * expected);
    MdtWorldDestroy(w);
}

static void linear2_cart_pendulum(void **s)
{
    (void)s;
    const double M = 2, m = 1, L = 1, Ib = 1e-3, theta0 = 0.05, h = 1.0 / 240;
    MdtWorldID w = newWorld(G);
    MdtBodyID cart = newBody(w, M, 0.01, 0, 0, 0);
    MdtBodyID bob = newBody(w, m, Ib, L * sin(theta0), 0, -L * cos(theta0));
    MdtLinear2ID rail = MdtLinear2Create(w);
    MdtLinear2SetBodies(rail, cart, NULL);
    MdtLinear2SetPosition(rail, 0, 0, 0);
    MdtLinear2SetDirection(rail, 1, 0, 0);
    MdtLinear2Enable(rail);
    MdtBSJointID bs = MdtBSJointCreate(w);
    MdtBSJointSetBodies(bs, bob, cart);
    MdtBSJointSetPosition(bs, 0, 0, 0);
    MdtBSJointEnable(bs);
    double crossings[8], last = 1, off = 0, momentum = 0, t = 0;
    int n = 0;
    while (n < 8 && t < 30) {
        MdtWorldStep(w, (MeReal)h);
        t += h;
        MeVector3 pc, pb, vc, vb;
        MdtBodyGetPosition(cart, pc);
        MdtBodyGetPosition(bob, pb);
        MdtBodyGetLinearVelocity(cart, vc);
        MdtBodyGetLinearVelocity(bob, vb);
        off = fmax(off, sqrt(pc[1] * pc[1] + pc[2] * pc[2]));
        momentum = fmax(momentum, fabs(M * vc[0] + m * vb[0]));
        double x = pb[0] - pc[0];
        if ((last > 0) != (x > 0))
            crossings[n++] = t - h * x / (x - last);
        last = x;
    }
    assert_int_equal(n, 8);
    double T = (crossings[7] - crossings[1]) / 3;
    /* Linearised Lagrangian with the cart free along x: ω² = m g L / (m L² + I − m² L² / (M + m)). */
    double expected = 2 * PI / sqrt(m * G * L / (m * L * L + Ib - m * m * L * L / (M + m)));
    print_message("Linear2 cart pendulum: period %.5f s vs %.5f s (%.3f %%); cart off its rail %.1e m; horizontal "
                  "momentum %.1e kg m/s\n",
                  T, expected, 100 * fabs(T - expected) / expected, off, momentum);
    assert_rel(T, expected, 0.01);
    assert_true(off < 1e-3);
    assert_true(momentum < 1e-3);
    MdtWorldDestroy(w);
}

/* The user constraint: |p − pivot| = L, one row, pivot at the world origin, the body's centre as p. */
static int pendulumRow(MdtUserConstraintID j, MdtUserConstraintRow *rows, int maxRows,
                       const MdtBclSolverParameters *params, void *data)
{
    (void)maxRows;
    (void)params;
    const double *L = data;
    MeVector3 p;
    MdtBodyGetPosition(MdtConstraintGetBody(MdtUserConstraintQuaConstraint(j), 0), p);
    MeReal len = MeVector3Normalize(p);
    MeVector3Copy(rows[0].linear0, p); /* d|p|/dt = n·v */
    rows[0].error = len - (MeReal)*L;
    return 1;
}

static void user_constraint_pendulum(void **s)
{
    (void)s;
    const double L = 1, theta0 = 0.05, Ib = 1e-3, h = 1.0 / 60;
    MdtWorldID w = newWorld(G);
    MdtBodyID bob = newBody(w, 1, Ib, L * sin(theta0), 0, -L * cos(theta0));
    MdtUserConstraintID u = MdtUserConstraintCreate(w);
    MdtUserConstraintSetBodies(u, bob, NULL);
    MdtUserConstraintSetAddConstraintFunction(u, pendulumRow);
    MdtUserConstraintSetConstraintStruct(u, (void *)&L);
    MdtUserConstraintSetMaxRows(u, 1);
    MdtUserConstraintEnable(u);
    double crossings[8], last = 1, t = 0, drift = 0, tension = 0;
    int n = 0;
    while (n < 8 && t < 30) {
        MdtWorldStep(w, (MeReal)h);
        t += h;
        MeVector3 p;
        MdtBodyGetPosition(bob, p);
        drift = fmax(drift, fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - L));
        tension = MdtUserConstraintGetRowForce(u, 0);
        if ((last > 0) != (p[0] > 0))
            crossings[n++] = t - h * p[0] / (p[0] - last);
        last = p[0];
    }
    assert_int_equal(n, 8);
    double T = (crossings[7] - crossings[1]) / 3;
    double expected = 2 * PI * sqrt((L * L + Ib) / (G * L)) * (1 + theta0 * theta0 / 16);
    print_message("UserConstraint pendulum: period %.5f s vs %.5f s (%.3f %%), length drift %.1e m, row force %.3f N "
                  "(m g = %.3f), rows %d\n",
                  T, expected, 100 * fabs(T - expected) / expected, drift, -tension, G,
                  MdtUserConstraintGetRowCount(u));
    assert_rel(T, expected, 0.01);
    assert_true(drift < 1e-3);
    assert_near(-tension, G, 0.05 * G); /* ≈ m g (1 + θ²) near the bottom */
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rpro_reaches_and_tracks_its_target),
        cmocka_unit_test(rpro_strength_caps_the_torque),
        cmocka_unit_test(fixed_path_pendulum_keeps_its_length),
        cmocka_unit_test(universal_joint_drives_a_shaft),
        cmocka_unit_test(linear1_keeps_a_point_in_the_plane),
        cmocka_unit_test(linear2_cart_pendulum),
        cmocka_unit_test(user_constraint_pendulum),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
