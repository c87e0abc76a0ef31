/* Contact mechanics through the whole pipeline (MstUniverse: space → nearfield → bridge → dynamics):
 * collisions of two spheres conserve momentum and reproduce the material's restitution; a ball rolls
 * down an incline at 5/7 g sin θ; a box on the incline sticks below the friction angle and slides at
 * g (sin θ − μ cos θ) above it. */
#include "karma_test.h"

#include <math.h>

#include <karma/karma.h>

#define G 9.81
#define PI 3.14159265358979323846

static MstUniverseID universeNew(MeReal massScale, MeReal g)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = massScale; /* the typical body mass: the world's ε scales with 1/massScale */
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, -g);
    return u;
}

static McdModelID bodyModel(MstUniverseID u, McdGeometryID geo, MeReal density, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = MstModelAndBodyCreate(u, geo, density);
    assert_non_null(m);
    MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
}

/* ---- two spheres ------------------------------------------------------------------------------ */

/* Linear momentum and angular momentum about the origin (spheres: spherical inertia, centred mass),
 * and each body's velocity. */
static void momenta(MdtBodyID b[2], double p[3], double L[3], double vel[2][3])
{
    for (int k = 0; k < 3; k++)
        p[k] = L[k] = 0;
    for (int i = 0; i < 2; i++) {
        MeVector3 x, v, w;
        MeMatrix3 I;
        MdtBodyGetPosition(b[i], x);
        MdtBodyGetLinearVelocity(b[i], v);
        MdtBodyGetAngularVelocity(b[i], w);
        MdtBodyGetInertiaTensor(b[i], I);
        double m = MdtBodyGetMass(b[i]);
        for (int k = 0; k < 3; k++) {
            p[k] += m * v[k];
            vel[i][k] = v[k];
        }
        L[0] += m * ((double)x[1] * v[2] - (double)x[2] * v[1]) + (double)I[0][0] * w[0];
        L[1] += m * ((double)x[2] * v[0] - (double)x[0] * v[2]) + (double)I[1][1] * w[1];
        L[2] += m * ((double)x[0] * v[1] - (double)x[1] * v[0]) + (double)I[2][2] * w[2];
    }
}

static double norm3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* Sphere A (r 0.5, 1000 kg/m³, 524 kg) at 3 m/s meets sphere B (r 0.3, 3000 kg/m³, 339 kg) coming
 * at 1.5 m/s, with B's centre `offset` off A's line of motion. Without gravity the total momentum
 * is constant; the relative velocity along the contact normal reverses with factor e. */
static void collideSpheres(double offset, MeBool friction, const char *label)
{
    const double e = 0.6;
    MstUniverseID u = universeNew(400, 0);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetRestitution(p, (MeReal)e);
    if (friction) {
        MdtContactParamsSetType(p, MdtContactTypeFriction2D);
        MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
        MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.3));
    }
    MdtBodyID b[2];
    b[0] = McdModelGetBody(bodyModel(u, McdSphereCreate(fw, ME_R(0.5)), 1000, -1, 0, 0));
    b[1] = McdModelGetBody(bodyModel(u, McdSphereCreate(fw, ME_R(0.3)), 3000, 1, (MeReal)offset, 0));
    MdtBodySetLinearVelocity(b[0], 3, 0, 0);
    MdtBodySetLinearVelocity(b[1], ME_R(-1.5), 0, 0);
    MdtWorldSetAutoDisable(MstUniverseGetWorld(u), MEFALSE);
    double p0[3], L0[3], v0[2][3];
    momenta(b, p0, L0, v0);
    /* The normal of the first contact: the line of centres when the bridge first made contacts. */
    double n[3] = {0, 0, 0};
    int contactSteps = 0;
    const MeReal h = ME_R(1.0) / 240;
    for (int step = 0; step < 240; step++) {
        MeVector3 xa, xb;
        MdtBodyGetPosition(b[0], xa);
        MdtBodyGetPosition(b[1], xb);
        MstUniverseStep(u, h);
        if (MstBridgeGetLastContactCount(MstUniverseGetBridge(u)) > 0) {
            if (contactSteps++ == 0) {
                for (int k = 0; k < 3; k++)
                    n[k] = (double)xb[k] - xa[k];
                double len = norm3(n);
                for (int k = 0; k < 3; k++)
                    n[k] /= len;
            }
        }
    }
    assert_true(contactSteps > 0);
    double p1[3], L1[3], v1[2][3];
    momenta(b, p1, L1, v1);
    /* Scales for relative errors: the sum of the bodies' momentum magnitudes, and of |r × m v|. */
    double pScale = 0, LScale = 0;
    for (int i = 0; i < 2; i++) {
        double m = MdtBodyGetMass(b[i]);
        pScale += m * norm3(v0[i]);
        LScale += m * norm3(v0[i]) * 1.0; /* both start 1 m from the origin */
    }
    double dp[3], dL[3];
    for (int k = 0; k < 3; k++) {
        dp[k] = p1[k] - p0[k];
        dL[k] = L1[k] - L0[k];
    }
    double approach = 0, separation = 0;
    for (int k = 0; k < 3; k++) {
        approach += (v0[0][k] - v0[1][k]) * n[k];
        separation += (v1[1][k] - v1[0][k]) * n[k];
    }
    double eMeasured = separation / approach;
    double spin = 0;
    MeVector3 w;
    MdtBodyGetAngularVelocity(b[1], w);
    spin = sqrt((double)w[0] * w[0] + (double)w[1] * w[1] + (double)w[2] * w[2]);
    printf("%s: %d contact steps, |dp|/p = %.3e, |dL|/L = %.3e, restitution %.5f (material %.2f, error %.3f %%), "
           "spin of B %.4f rad/s\n",
           label, contactSteps, norm3(dp) / pScale, norm3(dL) / LScale, eMeasured, e, 100 * fabs(eMeasured / e - 1),
           spin);
    const double tol = ME_TOL(1e-6, 2e-5); /* float: a few ulps of each step's impulses */
    assert_true(norm3(dp) / pScale < tol);
    assert_true(norm3(dL) / LScale < tol);
    assert_rel(eMeasured, e, 0.02);
    if (friction)
        assert_true(spin > 0.1); /* the tangential impulse spun B: angular momentum had to move */
    MstUniverseDestroy(u);
}

static void spheres_head_on(void **state)
{
    (void)state;
    collideSpheres(0, MEFALSE, "head-on");
}

static void spheres_off_centre(void **state)
{
    (void)state;
    collideSpheres(0.4, METRUE, "off-centre (b = 0.4 m, mu 0.3)");
}

/* ---- incline ---------------------------------------------------------------------------------- */

typedef struct Incline {
    MstUniverseID u;
    MeMatrix4 tm;       /* the fixed box's transform (outlives its model) */
    MeVector4 q;        /* its rotation */
    double down[3];     /* unit vector down the slope */
    double normal[3];   /* unit outward normal of the top face */
    MstMaterialID object;
} Incline;

/* A fixed 30 × 4 × 1 m box rotated by θ about y, its top face through the origin; material 1 (the
 * object's) against the incline's default material has 2D NormalForce friction μ. */
static void inclineInit(Incline *s, double theta, double mu, MeReal massScale)
{
    s->u = universeNew(massScale, (MeReal)G);
    MdtWorldSetAutoDisable(MstUniverseGetWorld(s->u), MEFALSE); /* measure the contact, not sleep */
    MeVector3 axis = {0, 1, 0};
    MeQuaternionMake(s->q, axis, (MeReal)theta);
    MeMatrix4TMMakeIdentity(s->tm);
    MeQuaternionToTM(s->tm, s->q);
    for (int k = 0; k < 3; k++) {
        s->down[k] = s->tm[0][k];
        s->normal[k] = s->tm[2][k];
        s->tm[3][k] = (MeReal)(-0.5 * s->normal[k]);
    }
    /* Rotating x about +y by θ tips it downwards: (cos θ, 0, −sin θ). */
    assert_true(s->down[2] < 0);
    McdFrameworkID fw = MstUniverseGetFramework(s->u);
    assert_non_null(MstFixedModelCreate(s->u, McdBoxCreate(fw, 30, 4, 1), s->tm));
    MstBridgeID b = MstUniverseGetBridge(s->u);
    s->object = MstBridgeGetNewMaterial(b);
    MdtContactParamsID p = MstBridgeGetContactParams(b, 0, s->object);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, (MeReal)mu);
}

/* Put `m`'s body at distance `height` above the slope, `back` metres up the slope from the origin. */
static void placeOnIncline(Incline *s, McdModelID m, double height, double back)
{
    MeReal pos[3];
    for (int k = 0; k < 3; k++)
        pos[k] = (MeReal)(height * s->normal[k] - back * s->down[k]);
    MdtBodySetPosition(McdModelGetBody(m), pos[0], pos[1], pos[2]);
    McdModelSetMaterial(m, s->object);
}

/* Distance travelled down the slope after each step, steps 0..n. */
static void runDownSlope(Incline *s, MdtBodyID body, MeReal h, int n, double *along)
{
    MeVector3 x0;
    MdtBodyGetPosition(body, x0);
    for (int i = 0; i <= n; i++) {
        MeVector3 x;
        MdtBodyGetPosition(body, x);
        along[i] = 0;
        for (int k = 0; k < 3; k++)
            along[i] += ((double)x[k] - x0[k]) * s->down[k];
        if (i < n)
            MstUniverseStep(s->u, h);
    }
}

/* The acceleration over steps [c − k, c + k]: for a constant acceleration a, symplectic Euler gives
 * x_n = x_0 + v_0 h n + a h² n(n+1)/2, whose second difference x_{c+k} − 2 x_c + x_{c−k} is a h² k²
 * exactly. */
static double windowAcceleration(const double *x, int c, int k, double h)
{
    return (x[c + k] - 2 * x[c] + x[c - k]) / ((double)k * k * h * h);
}

static void ball_rolls_down_incline(void **state)
{
    (void)state;
    const double theta = 20 * PI / 180, mu = 0.5, r = 0.3;
    Incline s;
    inclineInit(&s, theta, mu, 100);
    McdModelID ball = MstModelAndBodyCreate(s.u, McdSphereCreate(MstUniverseGetFramework(s.u), (MeReal)r), 1000);
    assert_non_null(ball);
    placeOnIncline(&s, ball, r, 8);
    MdtBodyID body = McdModelGetBody(ball);
    const MeReal h = ME_R(1.0) / 60;
    double along[181];
    runDownSlope(&s, body, h, 180, along);
    double a = windowAcceleration(along, 105, 75, h);
    double expected = 5.0 / 7.0 * G * sin(theta);
    /* Rolling without slipping: v = ω r at the end. */
    MeVector3 v, w;
    MdtBodyGetLinearVelocity(body, v);
    MdtBodyGetAngularVelocity(body, w);
    double speed = 0, wn = sqrt((double)w[0] * w[0] + (double)w[1] * w[1] + (double)w[2] * w[2]);
    for (int k = 0; k < 3; k++)
        speed += v[k] * s.down[k];
    printf("ball on %.0f deg incline: a = %.5f m/s^2 (5/7 g sin = %.5f, error %.3f %%), v = %.4f, w r = %.4f, "
           "travelled %.3f m\n",
           theta * 180 / PI, a, expected, 100 * fabs(a / expected - 1), speed, wn * r, along[180]);
    assert_rel(a, expected, 0.02);
    assert_rel(wn * r, speed, 0.02);
    MstUniverseDestroy(s.u);
}

/* A 0.4 m cube (64 kg) resting on the incline, released at rest. */
static void boxOnIncline(double thetaDeg, double mu, double *accel, double *travelled)
{
    const double theta = thetaDeg * PI / 180, half = 0.2;
    Incline s;
    inclineInit(&s, theta, mu, 64);
    McdModelID box = MstModelAndBodyCreate(s.u, McdBoxCreate(MstUniverseGetFramework(s.u), 0.4f, 0.4f, 0.4f), 1000);
    assert_non_null(box);
    placeOnIncline(&s, box, half, 8);
    MdtBodyID body = McdModelGetBody(box);
    MdtBodySetQuaternion(body, s.q[0], s.q[1], s.q[2], s.q[3]);
    const MeReal h = ME_R(1.0) / 60;
    double along[181];
    runDownSlope(&s, body, h, 180, along);
    *accel = windowAcceleration(along, 105, 75, h);
    *travelled = along[180];
    MeVector4 q;
    MdtBodyGetQuaternion(body, q);
    double dot = fabs((double)q[0] * s.q[0] + (double)q[1] * s.q[1] + (double)q[2] * s.q[2] + (double)q[3] * s.q[3]);
    assert_true(dot > 0.9999); /* slid flat, did not tip */
    MstUniverseDestroy(s.u);
}

static void box_sticks_below_friction_angle(void **state)
{
    (void)state;
    const double mu = 0.5, thetaDeg = 20; /* tan 20° = 0.364 < μ */
    double a, x;
    boxOnIncline(thetaDeg, mu, &a, &x);
    printf("box on %.0f deg incline, mu %.2f (tan = %.3f): moved %.3e m in 3 s, a = %.3e m/s^2\n", thetaDeg, mu,
           tan(thetaDeg * PI / 180), x, a);
    assert_true(fabs(x) < 1e-3);
    assert_true(fabs(a) < 1e-3);
}

static void box_slides_above_friction_angle(void **state)
{
    (void)state;
    const double mu = 0.5, thetaDeg = 35; /* tan 35° = 0.700 > μ */
    const double theta = thetaDeg * PI / 180;
    double a, x;
    boxOnIncline(thetaDeg, mu, &a, &x);
    double expected = G * (sin(theta) - mu * cos(theta));
    printf("box on %.0f deg incline, mu %.2f: a = %.5f m/s^2 (g (sin - mu cos) = %.5f, error %.3f %%), travelled "
           "%.3f m\n",
           thetaDeg, mu, a, expected, 100 * fabs(a / expected - 1), x);
    assert_rel(a, expected, 0.02);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spheres_head_on),
        cmocka_unit_test(spheres_off_centre),
        cmocka_unit_test(ball_rolls_down_incline),
        cmocka_unit_test(box_sticks_below_friction_angle),
        cmocka_unit_test(box_slides_above_friction_angle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
