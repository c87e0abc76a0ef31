/* Continuous collision (McdModelEnableContinuous) through MstUniverseStep at world defaults and
 * 1/60 s: a 0.05 m sphere at 100 m/s and a 0.02 x 1 x 1 m plate at 50 m/s (face first, and tilted
 * and spinning) against a 2 cm wall (a static box) and a triangle-mesh wall.
 *  - without the flag each passes through (the test shows the tunnelling it prevents);
 *  - with it the body stays on the near side at every step (its centre never past the wall's near
 *    face, its penetration below 1 cm: the contacts' softness at a 100 m/s impact; the plate spinning
 *    at 20 rad/s below 2 cm, its centre before the wall's middle);
 *  - restitution 0: it stops at the wall (speed below 0.2 m/s after 1 s; the turning plate, whose
 *    spin its impacts turn into motion, ends moving away) and never gains momentum or energy;
 *    restitution 0.5 (frictionless): it leaves at half its speed (within 2 %);
 *  - a sphere rolling fast on a tessellated mesh floor is not snagged: its trajectory with the flag is
 *    the one without it, bit for bit (the sweep finds nothing to stop);
 *  - a flagged body that hits nothing moves bit for bit as an unflagged one;
 *  - thirty random fast convex bodies (random shapes, sizes, poses and spins) stay in front. */
#include "karma_test.h"
#include "karma_terrain.h"

#include <math.h>
#include <string.h>

#include <karma/karma.h>

#define STEP (1.0 / 60)

enum { SPHERE, PLATE, PLATE_TURNING };
enum { WALL_BOX, WALL_MESH };

typedef struct Outcome {
    double maxX;            /* largest centre x over the run */
    double maxPenetration;  /* deepest contact reported against the wall over the run */
    double maxMomentum;     /* largest |m v| after the first step */
    double maxEnergy;       /* largest kinetic energy (linear + angular) */
    double startMomentum, startEnergy;
    MeVector3 x, v;         /* at the end */
} Outcome;

static double energyOf(MdtBodyID b)
{
    MeVector3 v, w;
    MeMatrix3 I;
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, w);
    MdtBodyGetInertiaTensor(b, I); /* world frame is the body frame rotated: |w|^2 bound via the tensor */
    MeMatrix4Ptr tm = MdtBodyGetTransformPtr(b);
    double wl[3]; /* w in body axes (rows of tm) */
    for (int i = 0; i < 3; i++)
        wl[i] = (double)(w[0] * tm[i][0] + w[1] * tm[i][1] + w[2] * tm[i][2]);
    double rot = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            rot += wl[i] * (double)I[i][j] * wl[j];
    return 0.5 * (double)MdtBodyGetMass(b) * (double)MeVector3MagnitudeSqr(v) + 0.5 * rot;
}

/* A universe at the defaults with a wall in the plane x = 0: a 2 cm static box (2 half x 2 half) or
 * the tessellated floor (half-width half, jitter 0.3, seed) stood up with its front (+z) facing -x.
 * The wall's transform is static: one universe at a time. */
static McdModelID universeWithWall(MstUniverseID *u, int wall, double half, unsigned seed)
{
    static MeMatrix4 wallTM;
    *u = MstUniverseCreate(&MstUniverseDefaultSizes);
    assert_non_null(*u);
    McdFrameworkID fw = MstUniverseGetFramework(*u);
    MeMatrix4TMMakeIdentity(wallTM);
    McdGeometryID wallGeo;
    if (wall == WALL_BOX) {
        wallGeo = McdBoxCreate(fw, ME_R(0.02), (MeReal)(2 * half), (MeReal)(2 * half));
    } else {
        wallGeo = karma_floor_mesh(fw, half, 6, 0.3, seed);
        MeVector3Set(wallTM[0], 0, 0, 1);
        MeVector3Set(wallTM[1], 0, 1, 0);
        MeVector3Set(wallTM[2], -1, 0, 0);
    }
    McdModelID wallModel = MstFixedModelCreate(*u, wallGeo, wallTM);
    assert_non_null(wallModel);
    return wallModel;
}

/* How deep the body of model m is in the wall now: the pair test (m, wall) at the current poses. */
static double depthInWall(McdModelPairID pair, McdModelID m)
{
    McdModelUpdate(m);
    McdContact c[8];
    McdIntersectResult r;
    memset(&r, 0, sizeof r);
    r.contacts = c;
    r.contactMaxCount = 8;
    McdIntersect(pair, &r);
    double deep = 0;
    for (int k = 0; k < r.contactCount; k++)
        deep = fmax(deep, -(double)c[k].separation);
    return deep;
}

static void run(int shape, int wall, MeBool continuous, double restitution, Outcome *o)
{
    MstUniverseID u;
    McdModelID wallModel = universeWithWall(&u, wall, 1, 5);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    if (restitution > 0) {
        MdtContactParamsSetType(p, MdtContactTypeFrictionZero);
        MdtContactParamsSetRestitution(p, (MeReal)restitution);
    }
    McdGeometryID g = shape == SPHERE ? McdSphereCreate(fw, ME_R(0.05)) : McdBoxCreate(fw, ME_R(0.02), 1, 1);
    McdModelID m = MstModelAndBodyCreate(u, g, 1000);
    assert_non_null(m);
    if (continuous)
        McdModelEnableContinuous(m);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, -1, ME_R(0.1), ME_R(-0.05));
    const double speed = shape == SPHERE ? 100 : 50;
    MdtBodySetLinearVelocity(b, (MeReal)speed, 0, 0);
    if (shape == PLATE_TURNING) {
        MeVector4 q;
        const MeVector3 axis = {ME_R(0.3), ME_R(0.4), ME_R(0.866)};
        MeVector3 unit;
        MeVector3Copy(unit, axis);
        MeVector3Normalize(unit);
        MeQuaternionMake(q, unit, ME_R(0.6));
        MdtBodySetQuaternion(b, q[0], q[1], q[2], q[3]);
        MdtBodySetAngularVelocity(b, 0, 0, 20);
    }
    o->startMomentum = (double)MdtBodyGetMass(b) * speed;
    o->startEnergy = energyOf(b);
    o->maxX = -1e9;
    o->maxPenetration = 0;
    o->maxMomentum = 0;
    o->maxEnergy = 0;
    McdModelPairID pair = McdModelPairCreate(m, wallModel);
    McdHello(pair);
    for (int i = 0; i < 60; i++) {
        MstUniverseStep(u, (MeReal)STEP);
        MeVector3 x, v;
        MdtBodyGetPosition(b, x);
        MdtBodyGetLinearVelocity(b, v);
        o->maxX = fmax(o->maxX, (double)x[0]);
        o->maxMomentum = fmax(o->maxMomentum, (double)MdtBodyGetMass(b) * (double)MeVector3Magnitude(v));
        o->maxEnergy = fmax(o->maxEnergy, energyOf(b));
        o->maxPenetration = fmax(o->maxPenetration, depthInWall(pair, m));
    }
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    MdtBodyGetPosition(b, o->x);
    MdtBodyGetLinearVelocity(b, o->v);
    MstUniverseDestroy(u);
}

static const char *const shapeNames[] = {"sphere", "plate", "turning plate"};
static const char *const wallNames[] = {"box wall", "mesh wall"};

static void tunnels_without_flag(void **state)
{
    (void)state;
    for (int shape = SPHERE; shape <= PLATE_TURNING; shape++)
        for (int wall = WALL_BOX; wall <= WALL_MESH; wall++) {
            Outcome o;
            run(shape, wall, MEFALSE, 0, &o);
            if (!(o.x[0] > 5))
                fail_msg("%s, %s: expected to pass through without the flag, ends at x = %g", shapeNames[shape],
                         wallNames[wall], (double)o.x[0]);
        }
}

static void stops_with_flag(void **state)
{
    (void)state;
    for (int shape = SPHERE; shape <= PLATE_TURNING; shape++)
        for (int wall = WALL_BOX; wall <= WALL_MESH; wall++) {
            Outcome o;
            run(shape, wall, METRUE, 0, &o);
            print_message("%s, %s: max x %.4f, deepest %.4f m, final x %.4f v %.3f, |p|max/p0 %.4f, Emax/E0 %.4f\n",
                          shapeNames[shape], wallNames[wall], o.maxX, o.maxPenetration, (double)o.x[0],
                          (double)o.v[0], o.maxMomentum / o.startMomentum, o.maxEnergy / o.startEnergy);
            const double nearFace = wall == WALL_BOX ? -0.01 : 0.0;
            if (shape == PLATE_TURNING) {
                /* a spin of a third of a turn a step, which the step's contacts linearise: it sinks
                 * deeper before they hold it, but never to the far side */
                assert_true(o.maxX < 0);
                assert_true(o.maxPenetration < 0.02);
            } else {
                assert_true(o.maxX < nearFace);
                assert_true(o.maxPenetration < 0.01);
            }
            if (shape == PLATE_TURNING)
                assert_true(o.v[0] < 0.2); /* the spin may throw it back: not into the wall */
            else
                assert_true(fabs((double)o.v[0]) < 0.2);
            assert_true(o.maxMomentum <= o.startMomentum * (1 + 1e-4));
            assert_true(o.maxEnergy <= o.startEnergy * (1 + 1e-4));
        }
}

static void bounces_with_flag(void **state)
{
    (void)state;
    for (int shape = SPHERE; shape <= PLATE; shape++)
        for (int wall = WALL_BOX; wall <= WALL_MESH; wall++) {
            Outcome o;
            run(shape, wall, METRUE, 0.5, &o);
            const double speed = shape == SPHERE ? 100 : 50;
            print_message("%s, %s, e 0.5: max x %.4f, final v %.3f\n", shapeNames[shape], wallNames[wall], o.maxX,
                          (double)o.v[0]);
            assert_true(o.maxX < (wall == WALL_BOX ? -0.01 : 0.0));
            assert_rel(o.v[0], -0.5 * speed, 0.02);
            assert_true(o.maxEnergy <= o.startEnergy * (1 + 1e-4));
        }
}

/* A 0.25 m sphere rolling at 20 m/s (a third of a metre a step) under gravity across a jittered,
 * tessellated mesh floor, with and without the flag. */
static void rollRun(MeBool continuous, double path[40][3])
{
    static MeMatrix4 floorTM;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(w, MEFALSE);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MeMatrix4TMMakeIdentity(floorTM);
    assert_non_null(MstFixedModelCreate(u, karma_floor_mesh(fw, 8, 32, 0.3, 21), floorTM));
    McdModelID m = MstModelAndBodyCreate(u, McdSphereCreate(fw, ME_R(0.25)), 1000);
    if (continuous)
        McdModelEnableContinuous(m);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, -6, ME_R(-0.3), ME_R(0.25));
    MdtBodySetLinearVelocity(b, 20, ME_R(2.0), 0);
    MdtBodySetAngularVelocity(b, ME_R(-2.0 / 0.25), ME_R(20 / 0.25), 0);
    for (int i = 0; i < 40; i++) {
        MstUniverseStep(u, (MeReal)STEP);
        MeVector3 x;
        MdtBodyGetPosition(b, x);
        for (int k = 0; k < 3; k++)
            path[i][k] = (double)x[k];
    }
    MstUniverseDestroy(u);
}

static void rolling_does_not_snag(void **state)
{
    (void)state;
    double with[40][3], without[40][3];
    rollRun(MEFALSE, without);
    rollRun(METRUE, with);
    assert_true(without[39][0] > 6); /* it rolled across the floor */
    for (int i = 0; i < 40; i++)
        for (int k = 0; k < 3; k++)
            if (with[i][k] != without[i][k])
                fail_msg("step %d axis %d: %.9g with the flag, %.9g without", i, k, with[i][k], without[i][k]);
}

/* A flagged sphere flying past a wall and a flagged body resting: the same as without the flag. */
static void flag_without_impact_changes_nothing(void **state)
{
    (void)state;
    double x[2][3];
    for (int flagged = 0; flagged < 2; flagged++) {
        MstUniverseID u;
        universeWithWall(&u, WALL_BOX, 1, 0);
        McdFrameworkID fw = MstUniverseGetFramework(u);
        McdModelID m = MstModelAndBodyCreate(u, McdBoxCreate(fw, ME_R(0.3), ME_R(0.2), ME_R(0.1)), 1000);
        if (flagged)
            McdModelEnableContinuous(m);
        MdtBodyID b = McdModelGetBody(m);
        MdtBodySetPosition(b, -1, ME_R(1.3), 0); /* passes beside the wall (its AABB meets the path) */
        MdtBodySetLinearVelocity(b, 90, 0, ME_R(0.5));
        MdtBodySetAngularVelocity(b, 3, -2, 7);
        for (int i = 0; i < 30; i++)
            MstUniverseStep(u, (MeReal)STEP);
        MeVector3 p;
        MdtBodyGetPosition(b, p);
        for (int k = 0; k < 3; k++)
            x[flagged][k] = (double)p[k];
        MstUniverseDestroy(u);
    }
    assert_true(x[0][0] > 40);
    assert_memory_equal(x[0], x[1], sizeof x[0]);
}

/* Random fast convex bodies (sphere, box, cylinder, sphyl, convex hull; random sizes down to 2 cm,
 * random orientations, spins up to 10 rad/s, 30 to 120 m/s) thrown at the box wall and the mesh
 * wall: with the flag every one stays on the near side (its centre before the wall's middle, never
 * deeper in it than 2 cm) and none gains energy. */
static double uniform(unsigned long long *state, double lo, double hi)
{
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(*state >> 11) / 9007199254740992.0;
}

static void random_fast_bodies_stay_in_front(void **state)
{
    (void)state;
    unsigned long long rng = 0xcc11d5ull;
    for (int iter = 0; iter < 30; iter++) {
        const int wall = iter % 2, kind = (iter / 2) % 5;
        MstUniverseID u;
        McdModelID wallModel = universeWithWall(&u, wall, 1.5, 9);
        McdFrameworkID fw = MstUniverseGetFramework(u);
        McdGeometryID g;
        const MeReal a = (MeReal)uniform(&rng, 0.02, 0.3), b = (MeReal)uniform(&rng, 0.02, 0.5);
        switch (kind) {
        case 0: g = McdSphereCreate(fw, a); break;
        case 1: g = McdBoxCreate(fw, a, b, (MeReal)uniform(&rng, 0.02, 0.5)); break;
        case 2: g = McdCylinderCreate(fw, a, b); break;
        case 3: g = McdSphylCreate(fw, a, b); break;
        default: {
            MeVector3 pts[12];
            for (int k = 0; k < 12; k++)
                MeVector3Set(pts[k], (MeReal)uniform(&rng, -a, a), (MeReal)uniform(&rng, -b, b), (MeReal)uniform(&rng, -0.2, 0.2));
            g = McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, 12, 0);
            break;
        }
        }
        assert_non_null(g);
        McdModelID m = MstModelAndBodyCreate(u, g, 1000);
        assert_non_null(m);
        McdModelEnableContinuous(m);
        MdtBodyID body = McdModelGetBody(m);
        MeVector3 axis = {(MeReal)uniform(&rng, -1, 1), (MeReal)uniform(&rng, -1, 1), (MeReal)uniform(&rng, -1, 1)};
        MeVector3Normalize(axis);
        MeVector4 q;
        MeQuaternionMake(q, axis, (MeReal)uniform(&rng, 0, 3.14));
        MdtBodySetQuaternion(body, q[0], q[1], q[2], q[3]);
        MdtBodySetPosition(body, -2, (MeReal)uniform(&rng, -0.5, 0.5), (MeReal)uniform(&rng, -0.5, 0.5));
        MdtBodySetLinearVelocity(body, (MeReal)uniform(&rng, 30, 120), (MeReal)uniform(&rng, -5, 5), 0);
        MdtBodySetAngularVelocity(body, (MeReal)uniform(&rng, -6, 6), (MeReal)uniform(&rng, -6, 6), (MeReal)uniform(&rng, -6, 6));
        const double e0 = energyOf(body);
        McdModelPairID pair = McdModelPairCreate(m, wallModel);
        McdHello(pair);
        for (int i = 0; i < 45; i++) {
            MstUniverseStep(u, (MeReal)STEP);
            MeVector3 x;
            MdtBodyGetPosition(body, x);
            const double deep = depthInWall(pair, m);
            if (!(x[0] < 0) || deep > 0.02 || energyOf(body) > e0 * (1 + 1e-4))
                fail_msg("body %d (kind %d, %s) step %d: x %g, %g m deep, energy %g of %g", iter, kind, wallNames[wall], i,
                         (double)x[0], deep, energyOf(body), e0);
        }
        McdGoodbye(pair);
        McdModelPairDestroy(pair);
        MstUniverseDestroy(u);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tunnels_without_flag),  cmocka_unit_test(stops_with_flag),
        cmocka_unit_test(bounces_with_flag),     cmocka_unit_test(rolling_does_not_snag),
        cmocka_unit_test(flag_without_impact_changes_nothing), cmocka_unit_test(random_fast_bodies_stay_in_front),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
