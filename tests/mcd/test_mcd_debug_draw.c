/* McduDebugDraw: a recording line hook checks that each shape draws the right number of lines at the
 * right places (a box's 12 edges joining its 8 corners, a sphere's points at its radius, ...), where
 * the transform or the model's last update puts it, in the given colour. */
#include "karma_test.h"

#include <karma/Mcd.h>
#include <karma/McduDebugDraw.h>
#include <karma/MeMath.h>

#define MAX_LINES 512
static MeVector3 starts[MAX_LINES], ends[MAX_LINES];
static MeReal colours[MAX_LINES][3];
static int lineCount;

static void MEAPI record(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    if (lineCount < MAX_LINES) {
        MeVector3Copy(starts[lineCount], start);
        MeVector3Copy(ends[lineCount], end);
        colours[lineCount][0] = r;
        colours[lineCount][1] = g;
        colours[lineCount][2] = b;
    }
    lineCount++;
}

static int setup(void **state)
{
    (void)state;
    MeDebugDrawAPI.line = record;
    return 0;
}

static const MeReal red[3] = {1, 0, 0};
static const MeReal tol = ME_TOL(1e-12, 1e-5);

/* Every recorded end point p satisfies |p - c| == radius (within tol). */
static void assert_all_on_sphere(const MeVector3 c, MeReal radius)
{
    for (int i = 0; i < lineCount; i++) {
        assert_near(MeVector3Distance(starts[i], c), radius, tol);
        assert_near(MeVector3Distance(ends[i], c), radius, tol);
    }
}

/* The 12 edges of the box [lo, hi]: each line joins two corners that differ along one axis by the
 * full edge, and each of the 12 (corner pair) edges appears once. */
static void assert_box_edges(const MeVector3 lo, const MeVector3 hi)
{
    int seen[8][8] = {{0}};
    assert_int_equal(lineCount, 12);
    for (int i = 0; i < 12; i++) {
        int ca = 0, cb = 0;
        for (int k = 0; k < 3; k++) {
            MeReal a = starts[i][k], b = ends[i][k];
            assert_true(MeFabs(a - lo[k]) < tol || MeFabs(a - hi[k]) < tol);
            assert_true(MeFabs(b - lo[k]) < tol || MeFabs(b - hi[k]) < tol);
            ca |= (MeFabs(a - hi[k]) < tol) << k;
            cb |= (MeFabs(b - hi[k]) < tol) << k;
        }
        int diff = ca ^ cb;
        assert_true(diff == 1 || diff == 2 || diff == 4); /* an edge, not a diagonal */
        seen[ca][cb]++;
        seen[cb][ca]++;
    }
    for (int a = 0; a < 8; a++)
        for (int b = a + 1; b < 8; b++) {
            int diff = a ^ b;
            assert_int_equal(seen[a][b], diff == 1 || diff == 2 || diff == 4 ? 1 : 0);
        }
}

static void aabb_and_box(void **state)
{
    (void)state;
    karma_capture_messages();
    MeVector3 lo = {-1, 2, 3}, hi = {4, 5, 7};
    lineCount = 0;
    McduDebugDrawAABB(lo, hi, red);
    assert_box_edges(lo, hi);
    assert_true(colours[0][0] == 1 && colours[0][1] == 0 && colours[0][2] == 0);

    McdFrameworkID fw = McdInit(0, 8, 0, 1);
    McdGeometryID box = McdBoxCreate(fw, 2, 4, 6);
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetPosition(tm, 10, 20, 30);
    lineCount = 0;
    McduDebugDrawBox(box, tm, red);
    MeVector3 blo = {9, 18, 27}, bhi = {11, 22, 33};
    assert_box_edges(blo, bhi);
    /* turned 90 degrees about z: the x and y extents swap */
    MeMatrix3 r;
    MeMatrix3MakeRotationZ(r, ME_PI / 2);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            tm[i][j] = r[i][j];
    lineCount = 0;
    McduDebugDrawGeometry(box, tm, red);
    MeVector3 rlo = {8, 19, 27}, rhi = {12, 21, 33};
    assert_box_edges(rlo, rhi);
    /* wrong type: reported, nothing drawn */
    McdGeometryID ball = McdSphereCreate(fw, 1);
    lineCount = 0;
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, McduDebugDrawBox(ball, tm, red));
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, McduDebugDrawConvex(ball, tm, red));
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, McduDebugDrawAggregate(box, tm, red));
    assert_int_equal(lineCount, 0);
    McdGeometryDestroy(ball);
    McdGeometryDestroy(box);
    McdTerm(fw);
}

static void round_shapes(void **state)
{
    (void)state;
    karma_capture_messages();
    const int n = MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS;
    McdFrameworkID fw = McdInit(0, 8, 0, 1);
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetPosition(tm, 1, 2, 3);
    MeVector3 c = {1, 2, 3};

    McdGeometryID ball = McdSphereCreate(fw, 0.5);
    lineCount = 0;
    McduDebugDrawSphere(ball, tm, red);
    assert_int_equal(lineCount, 3 * n); /* three great circles */
    assert_all_on_sphere(c, 0.5);

    /* cylinder radius 1, height 4: 2 circles + 4 sides; every point at radius 1 from the axis, on z = 3 +- 2 */
    McdGeometryID cyl = McdCylinderCreate(fw, 1, 4);
    lineCount = 0;
    McduDebugDrawCylinder(cyl, tm, red);
    assert_int_equal(lineCount, 2 * n + 4);
    for (int i = 0; i < lineCount; i++) {
        const MeReal *p[2] = {starts[i], ends[i]};
        for (int k = 0; k < 2; k++) {
            assert_near(MeSqrt((p[k][0] - 1) * (p[k][0] - 1) + (p[k][1] - 2) * (p[k][1] - 2)), 1, tol);
            assert_near(MeFabs(p[k][2] - 3), 2, tol);
        }
    }
    /* sphyl: every point within the capsule's surface distance of the axis segment */
    McdGeometryID sphyl = McdSphylCreate(fw, 0.5, 2);
    lineCount = 0;
    McduDebugDrawGeometry(sphyl, tm, red);
    assert_int_equal(lineCount, 2 * n + 4 + 4 * (n / 2));
    for (int i = 0; i < lineCount; i++) {
        MeReal z = ends[i][2] - 3, zc = z > 1 ? 1 : (z < -1 ? -1 : z);
        MeVector3 axis = {1, 2, 3 + zc};
        assert_near(MeVector3Distance(ends[i], axis), 0.5, tol);
    }
    /* null draws nothing; a plane its square and normal (5 lines) */
    McdGeometryID nothing = McdNullCreate(fw), plane = McdPlaneCreate(fw);
    lineCount = 0;
    McduDebugDrawGeometry(nothing, tm, red);
    assert_int_equal(lineCount, 0);
    McduDebugDrawGeometry(plane, tm, red);
    assert_int_equal(lineCount, 5);
    McdGeometryDestroy(ball);
    McdGeometryDestroy(cyl);
    McdGeometryDestroy(sphyl);
    McdGeometryDestroy(nothing);
    McdGeometryDestroy(plane);
    McdTerm(fw);
}

/* Models are drawn where their last update put them; the space draws each model; frozen models are
 * skipped with kMcduDebugDrawEnabledOnly; kMcduDebugDrawAABB adds the 12 AABB edges. */
static void models_and_space(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 8, 0, 1);
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 4, 4);
    McdGeometryID box = McdBoxCreate(fw, 2, 2, 2);
    McdModelID a = McdModelCreate(box), b = McdModelCreate(box);
    McdModelSetContactTolerance(a, 0);
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(a), 5, 0, 0);
    McdModelUpdate(a);
    lineCount = 0;
    McduDebugDrawModel(a, (McduDebugDrawFlags)0, red);
    MeVector3 lo = {4, -1, -1}, hi = {6, 1, 1};
    assert_box_edges(lo, hi);
    lineCount = 0;
    McduDebugDrawModel(a, kMcduDebugDrawAABB, red);
    assert_int_equal(lineCount, 24);
    McdSpaceInsertModel(space, a);
    McdSpaceInsertModel(space, b);
    McdSpaceEndChanges(space);
    lineCount = 0;
    McduDebugDrawSpace(space, (McduDebugDrawFlags)0, red);
    assert_int_equal(lineCount, 24);
    McdSpaceFreezeModel(b);
    lineCount = 0;
    McduDebugDrawSpace(space, kMcduDebugDrawEnabledOnly, red);
    assert_int_equal(lineCount, 12);
    assert_reports(ME_ERR_INVALID_HANDLE, McduDebugDrawSpace(NULL, (McduDebugDrawFlags)0, red));
    McdSpaceBeginChanges(space);
    McdSpaceRemoveModel(a);
    McdSpaceRemoveModel(b);
    McdSpaceDestroy(space);
    McdModelDestroy(a);
    McdModelDestroy(b);
    McdGeometryDestroy(box);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(aabb_and_box),
        cmocka_unit_test(round_shapes),
        cmocka_unit_test(models_and_space),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
