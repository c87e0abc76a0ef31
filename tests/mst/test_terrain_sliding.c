/* Internal edges do not snag: a box and a convex box hull sliding and a sphere rolling across a flat
 * tessellated floor (a jittered triangle mesh, a height field, a triangle list with Karma's edge
 * flags) move as on a plane. Each run goes through the whole pipeline (MstUniverse: space,
 * nearfield, bridge, Kea) and is compared step by step with the same run on McdPlane, z-up and y-up:
 *  - the box (0.4 m cube, mu 0.3) slides at 3.2 m/s across ~40 internal edges until friction stops
 *    it: its path stays within 0.1 mm of the plane run's, its height within 0.1 mm of it, its
 *    angular velocity below 0.01 rad/s (a snag tips it);
 *  - the convex hull of the same box's corners slides the same way, compared with its own run on the
 *    plane (convex-plane) within the same 0.1 mm;
 *  - the sphere (r 0.25 m) rolls at 2 m/s for 2 s: within 0.1 mm of the plane run, its height within
 *    0.1 mm, and it keeps rolling (speed within 0.1 %). */
#include "karma_test.h"
#include "karma_terrain.h"

#include <math.h>

#include <karma/karma.h>

#define G 9.81

enum { PLANE, MESH, FIELD, LIST, KINDS };
enum { BOX, SPHERE, HULL };
static const char *const bodyNames[3] = {"box sliding", "sphere rolling", "convex box sliding"};
static const char *const kindNames[KINDS] = {"plane", "mesh", "height field", "triangle list"};

typedef struct Run {
    double pos[200][3];
    double maxW, maxLift, minLift;
    int steps;
} Run;

static void floorTM(MeMatrix4 tm, int yUp)
{
    MeMatrix4TMMakeIdentity(tm);
    if (yUp) {
        MeVector3Set(tm[1], 0, 0, -1);
        MeVector3Set(tm[2], 0, 1, 0);
    }
}

/* Floor coordinates (x, y along the floor, z up from it) of a world point. */
static void toFloor(MeMatrix4 ftm, const MeReal *w, double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = (double)w[0] * ftm[k][0] + (double)w[1] * ftm[k][1] + (double)w[2] * ftm[k][2];
}

/* The body: a 0.4 m cube, a 0.25 m sphere or the convex hull of the cube's corners. */
static McdGeometryID bodyGeometry(McdFrameworkID fw, int body)
{
    MeVector3 c[8];
    if (body == SPHERE)
        return McdSphereCreate(fw, ME_R(0.25));
    if (body == BOX)
        return McdBoxCreate(fw, ME_R(0.4), ME_R(0.4), ME_R(0.4));
    for (int k = 0; k < 8; k++)
        MeVector3Set(c[k], k & 1 ? ME_R(0.2) : -ME_R(0.2), k & 2 ? ME_R(0.2) : -ME_R(0.2), k & 4 ? ME_R(0.2) : -ME_R(0.2));
    return McdConvexMeshCreateHull(fw, (const MeVector3 *)c, 8, 0);
}

static void simulate(int kind, int shape, int yUp, Run *run)
{
    const int sphere = shape == SPHERE;
    static MeMatrix4 ftm; /* outlives the fixed model */
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 60;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldID world = MstUniverseGetWorld(u);
    MdtWorldSetAutoDisable(world, MEFALSE);
    floorTM(ftm, yUp);
    MdtWorldSetGravity(world, (MeReal)(-G * ftm[2][0]), (MeReal)(-G * ftm[2][1]), (MeReal)(-G * ftm[2][2]));
    McdFrameworkID fw = MstUniverseGetFramework(u);
    McdGeometryID floorGeo = NULL;
    McdTriangleMeshID mesh = kind == MESH || kind == LIST ? karma_floor_mesh(fw, 4, 16, 0.3, 21) : NULL;
    switch (kind) {
    case PLANE: floorGeo = McdPlaneCreate(fw); break;
    case MESH: floorGeo = mesh; break;
    case FIELD: floorGeo = karma_floor_field(fw, 4, 16); break;
    default: floorGeo = karma_floor_list(fw, mesh); break;
    }
    assert_non_null(floorGeo);
    assert_non_null(MstFixedModelCreate(u, floorGeo, ftm));
    MstBridgeID b = MstUniverseGetBridge(u);
    MdtContactParamsID p = MstBridgeGetContactParams(b, 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.3));
    const double r = sphere ? 0.25 : 0.2;
    McdModelID m = MstModelAndBodyCreate(u, bodyGeometry(fw, shape), 1000);
    assert_non_null(m);
    MdtBodyID body = McdModelGetBody(m);
    /* start on the floor at (-2.5, -0.7), moving along (3, 1) (box) or (2, 0.5) (sphere), in floor axes */
    double start[3] = {-2.5, -0.7, r}, v[3] = {sphere ? 2.0 : 3.0, sphere ? 0.5 : 1.0, 0};
    MeReal pw[3], vw[3], ww[3];
    for (int k = 0; k < 3; k++) {
        pw[k] = (MeReal)(start[0] * ftm[0][k] + start[1] * ftm[1][k] + start[2] * ftm[2][k]);
        vw[k] = (MeReal)(v[0] * ftm[0][k] + v[1] * ftm[1][k]);
        /* rolling: w = z x v / r */
        ww[k] = sphere ? (MeReal)((-v[1] * ftm[0][k] + v[0] * ftm[1][k]) / r) : 0;
    }
    MdtBodySetPosition(body, pw[0], pw[1], pw[2]);
    MdtBodySetLinearVelocity(body, vw[0], vw[1], vw[2]);
    MdtBodySetAngularVelocity(body, ww[0], ww[1], ww[2]);
    run->maxW = 0;
    run->maxLift = -1e9;
    run->minLift = 1e9;
    run->steps = sphere ? 120 : 90;
    for (int step = 0; step < run->steps; step++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        MeVector3 x, w;
        MdtBodyGetPosition(body, x);
        MdtBodyGetAngularVelocity(body, w);
        toFloor(ftm, x, run->pos[step]);
        run->maxLift = fmax(run->maxLift, run->pos[step][2] - r);
        run->minLift = fmin(run->minLift, run->pos[step][2] - r);
        if (!sphere)
            run->maxW = fmax(run->maxW, sqrt((double)MeVector3MagnitudeSqr(w)));
    }
    if (sphere) {
        MeVector3 vv;
        MdtBodyGetLinearVelocity(body, vv);
        run->maxW = sqrt((double)MeVector3MagnitudeSqr(vv)); /* the final speed */
    }
    MstUniverseDestroy(u);
}

static void compare(int shape)
{
    const int sphere = shape == SPHERE;
    for (int yUp = 0; yUp < 2; yUp++) {
        Run ref, run;
        simulate(PLANE, shape, yUp, &ref);
        double travelled = hypot(ref.pos[ref.steps - 1][0] - ref.pos[0][0], ref.pos[ref.steps - 1][1] - ref.pos[0][1]);
        assert_true(travelled > (sphere ? 3.5 : 1.4));
        for (int kind = MESH; kind < KINDS; kind++) {
            simulate(kind, shape, yUp, &run);
            double worst = 0;
            for (int s = 0; s < run.steps; s++)
                for (int k = 0; k < 3; k++)
                    worst = fmax(worst, fabs(run.pos[s][k] - ref.pos[s][k]));
            printf("%s %s (%s): path off the plane run's by %.2e m over %.2f m, height %+.2e..%+.2e m (plane "
                   "%+.2e..%+.2e), %s %.4f (plane %.4f)\n",
                   bodyNames[shape], kindNames[kind], yUp ? "y-up" : "z-up", worst, travelled,
                   run.minLift, run.maxLift, ref.minLift, ref.maxLift, sphere ? "final speed" : "max |w|", run.maxW,
                   ref.maxW);
            assert_true(worst < 1e-4);
            assert_true(run.maxLift < 1e-4 && run.minLift > -0.01);
            assert_true(fabs(run.maxLift - ref.maxLift) < 1e-4 && fabs(run.minLift - ref.minLift) < 1e-4);
            if (sphere)
                assert_true(fabs(run.maxW - ref.maxW) < 1e-3 * ref.maxW);
            else
                assert_true(run.maxW < 0.01);
        }
    }
}

static void box_slides_as_on_a_plane(void **state)
{
    (void)state;
    compare(BOX);
}

static void convex_box_slides_as_on_a_plane(void **state)
{
    (void)state;
    compare(HULL);
}

static void sphere_rolls_as_on_a_plane(void **state)
{
    (void)state;
    compare(SPHERE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_slides_as_on_a_plane),
        cmocka_unit_test(convex_box_slides_as_on_a_plane),
        cmocka_unit_test(sphere_rolls_as_on_a_plane),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
