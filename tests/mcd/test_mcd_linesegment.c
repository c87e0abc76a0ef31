/* McdLineSegIntersect against every primitive: analytic hits (position, normal, distance), Karma's
 * start-inside rule, and random segments at random placements checked against an independent signed
 * distance function: the hit lies on the surface, its normal is an outward surface normal there,
 * and dense sampling finds no earlier point inside; misses have no point inside. */
#include "karma_test.h"
#include "karma_mcd_fixture.h"

#include <string.h>

#include <karma/Mcd.h>

#include "mcd_shapes.h"

static McdFrameworkID fw;

static int setup(void **state)
{
    (void)state;
    MeRealRandomSeed(99);
    return karma_mcd_open(&fw, 32, 1);
}

static McdModelID modelAt(McdGeometryID g, MeMatrix4 tm)
{
    McdModelID m = McdModelCreate(g);
    MeMatrix4Copy(McdModelGetTransformPtr(m), tm);
    McdModelUpdate(m);
    return m;
}

static void expectHit(McdModelID m, MeReal x0, MeReal y0, MeReal z0, MeReal x1, MeReal y1, MeReal z1, double px,
                      double py, double pz, double nx, double ny, double nz, double distance)
{
    MeVector3 a = {x0, y0, z0}, b = {x1, y1, z1};
    McdLineSegIntersectResult r;
    memset(&r, 0, sizeof r);
    assert_int_equal(McdLineSegIntersect(m, a, b, &r), 1);
    double tol = ME_TOL(1e-9, 2e-5);
    assert_ptr_equal(r.model, m);
    assert_near(r.position[0], px, tol);
    assert_near(r.position[1], py, tol);
    assert_near(r.position[2], pz, tol);
    assert_near(r.normal[0], nx, tol);
    assert_near(r.normal[1], ny, tol);
    assert_near(r.normal[2], nz, tol);
    assert_near(r.distance, distance, tol);
}

static void expectMiss(McdModelID m, MeReal x0, MeReal y0, MeReal z0, MeReal x1, MeReal y1, MeReal z1)
{
    MeVector3 a = {x0, y0, z0}, b = {x1, y1, z1};
    McdLineSegIntersectResult r;
    assert_int_equal(McdLineSegIntersect(m, a, b, &r), 0);
}

static void analytic_hits(void **state)
{
    (void)state;
    MeMatrix4 tm;
    /* Sphere r 1 at (1, 2, 3), turned (turning a sphere changes nothing). */
    MeMatrix4TMFromEulerAnglesAndPosition(tm, ME_R(0.4), ME_R(0.5), ME_R(0.6), 1, 2, 3);
    McdModelID sphere = modelAt(McdSphereCreate(fw, 1), tm);
    expectHit(sphere, -2, 2, 3, 4, 2, 3, 0, 2, 3, -1, 0, 0, 2);
    expectHit(sphere, 1, 2, 10, 1, 2, 3, 1, 2, 4, 0, 0, 1, 6);
    expectMiss(sphere, -2, 2, 3, -1.5, 2, 3);     /* stops short */
    expectMiss(sphere, -2, ME_R(3.01), 3, 4, ME_R(3.01), 3); /* passes by */
    /* Start inside: distance 0 at p0, normal = -direction. */
    expectHit(sphere, 1, 2, ME_R(3.5), 1, 2, 10, 1, 2, 3.5, 0, 0, -1, 0);

    /* Box 2 x 4 x 6 turned +90 deg about z: local x is world y, local y is world -x. */
    MeMatrix4TMFromEulerAnglesAndPosition(tm, 0, 0, ME_PI_2, 0, 0, 0);
    McdModelID box = modelAt(McdBoxCreate(fw, 2, 4, 6), tm);
    expectHit(box, -5, 0, 0, 5, 0, 0, -2, 0, 0, -1, 0, 0, 3);
    expectHit(box, 0, 5, 0, 0, -5, 0, 0, 1, 0, 0, 1, 0, 4);
    expectHit(box, ME_R(0.5), ME_R(0.5), 10, ME_R(0.5), ME_R(0.5), 0, 0.5, 0.5, 3, 0, 0, 1, 7);
    expectMiss(box, ME_R(-2.1), 5, 0, ME_R(-2.1), -5, 0);

    /* Plane, y up at y = 1 (rotated -pi/2 about x). */
    MeMatrix4TMFromEulerAnglesAndPosition(tm, -ME_PI_2, 0, 0, 0, 1, 0);
    McdModelID plane = modelAt(McdPlaneCreate(fw), tm);
    expectHit(plane, 3, 5, -2, 3, -5, -2, 3, 1, -2, 0, 1, 0, 4);
    expectHit(plane, 0, 3, 0, 4, -1, 0, 2, 1, 0, 0, 1, 0, 2 * sqrt(2.0));
    expectMiss(plane, -5, 2, 0, 5, 2, 0);         /* parallel above */
    expectHit(plane, 0, 0, 0, 0, 5, 0, 0, 0, 0, 0, -1, 0, 0); /* starts below: inside */

    /* Cylinder r 0.5, height 2 along z at the origin. */
    MeMatrix4TMMakeIdentity(tm);
    McdModelID cyl = modelAt(McdCylinderCreate(fw, ME_R(0.5), 2), tm);
    expectHit(cyl, -3, 0, ME_R(0.2), 3, 0, ME_R(0.2), -0.5, 0, 0.2, -1, 0, 0, 2.5);
    expectHit(cyl, ME_R(0.3), 0, 5, ME_R(0.3), 0, -5, 0.3, 0, 1, 0, 0, 1, 4);
    expectHit(cyl, 0, ME_R(0.1), -5, 0, ME_R(0.1), 5, 0, 0.1, -1, 0, 0, -1, 4);
    expectMiss(cyl, ME_R(0.6), 0, 5, ME_R(0.6), 0, -5);
    expectMiss(cyl, -3, 0, ME_R(1.1), 3, 0, ME_R(1.1));

    /* Sphyl r 0.5, cylinder part 1 (caps' centres at z = +-0.5), moved to x = 10. */
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetPosition(tm, 10, 0, 0);
    McdModelID sphyl = modelAt(McdSphylCreate(fw, ME_R(0.5), 1), tm);
    expectHit(sphyl, 10, 0, 5, 10, 0, -5, 10, 0, 1, 0, 0, 1, 4);
    expectHit(sphyl, 7, 0, 0, 13, 0, 0, 9.5, 0, 0, -1, 0, 0, 2.5);
    double x = sqrt(0.25 - 0.04);
    expectHit(sphyl, 7, 0, ME_R(0.7), 13, 0, ME_R(0.7), 10 - x, 0, 0.7, -x / 0.5, 0, 0.2 / 0.5, 3 - x);
    expectMiss(sphyl, 7, 0, ME_R(1.01), 13, 0, ME_R(1.01));

    /* Pointed cone, length 2, base radius 0.5: base at z = -0.5, apex at z = 1.5. */
    MeMatrix4TMMakeIdentity(tm);
    McdModelID cone = modelAt(McdConeCreate(fw, 2, ME_R(0.5)), tm);
    double k = sqrt(4.25); /* side of the meridian from (0.5, -0.5) to (0, 1.5): outward normal (2, 0.5)/k */
    expectHit(cone, -3, 0, ME_R(0.5), 3, 0, ME_R(0.5), -0.25, 0, 0.5, -2 / k, 0, 0.5 / k, 2.75);
    expectHit(cone, ME_R(0.1), 0, -5, ME_R(0.1), 0, 5, 0.1, 0, -0.5, 0, 0, -1, 4.5);
    expectMiss(cone, -3, 0, ME_R(1.6), 3, 0, ME_R(1.6));
    /* A truncated cone: the upper disc (radius 0.2) at z = zUpper. */
    McdGeometryID frustum = McdConeCreate(fw, 2, ME_R(0.5));
    McdConeSetGeometricalParameters(frustum, 2, ME_R(0.5), ME_R(0.2));
    McdModelID fm = modelAt(frustum, tm);
    double zUp = McdConeGetUpperZ(frustum);
    expectHit(fm, ME_R(0.1), 0, 5, ME_R(0.1), 0, -5, 0.1, 0, zUp, 0, 0, 1, 5 - zUp);

    /* Null geometries are never hit. */
    McdModelID null = modelAt(McdNullCreate(fw), tm);
    expectMiss(null, -1, 0, 0, 1, 0, 0);
}

/* ---- random segments against the independent distance functions ------------------------------ */
typedef struct Stats {
    int hits, misses, inside;
    double surface, normal, earlier, missInside, distance;
} Stats;

static void worst(double *w, double e)
{
    if (e > *w)
        *w = e;
}

static void randomSegments(McdGeometryID g, const char *name)
{
    TestShape s = test_shape_of(g);
    Stats st = {0};
    const int samples = 600;
    for (int trial = 0; trial < 1500; trial++) {
        MeMatrix4 tm;
        test_random_tm(tm, 1);
        McdModelID m = modelAt(g, tm);
        MeVector3 a, b;
        for (int i = 0; i < 3; i++) {
            a[i] = MeRealRandomInRange(-2, 2);
            b[i] = MeRealRandomInRange(-2, 2);
        }
        McdLineSegIntersectResult r;
        int hit = McdLineSegIntersect(m, a, b, &r);
        double pa[3] = {a[0], a[1], a[2]}, d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        if (!hit) {
            st.misses++;
            for (int k = 0; k <= samples; k++) {
                double t = (double)k / samples, p[3] = {pa[0] + t * d[0], pa[1] + t * d[1], pa[2] + t * d[2]};
                worst(&st.missInside, -test_sdf_world(&s, tm, p));
            }
        } else if (r.distance == 0) {
            st.inside++;
            worst(&st.surface, test_sdf_world(&s, tm, pa)); /* p0 must be inside (sdf <= 0) */
        } else {
            st.hits++;
            double p[3] = {r.position[0], r.position[1], r.position[2]}, delta = 0.1;
            worst(&st.surface, fabs(test_sdf_world(&s, tm, p)));
            double q[3] = {p[0] + delta * r.normal[0], p[1] + delta * r.normal[1], p[2] + delta * r.normal[2]};
            worst(&st.normal, fabs(test_sdf_world(&s, tm, q) - delta));
            worst(&st.normal, fabs(MeVector3Magnitude(r.normal) - 1));
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), th = r.distance / len;
            worst(&st.distance, fabs(MeVector3Distance(r.position, a) - r.distance));
            for (int k = 0; k < samples; k++) {
                double t = th * k / samples, e[3] = {pa[0] + t * d[0], pa[1] + t * d[1], pa[2] + t * d[2]};
                worst(&st.earlier, -test_sdf_world(&s, tm, e));
            }
        }
        McdModelDestroy(m);
    }
    printf("%-8s hits %4d, starts inside %4d, misses %4d | hit off surface %.1e, normal %.1e, distance %.1e; "
           "inside before the hit %.1e; inside on a miss %.1e\n",
           name, st.hits, st.inside, st.misses, st.surface, st.normal, st.distance, st.earlier, st.missInside);
    /* float: a cone hit grazing near the apex solves a nearly degenerate quadratic (~1e-5 seen). */
    double tol = ME_TOL(1e-9, 3e-5), surfaceTol = ME_TOL(1e-9, 1e-4);
    assert_true(st.hits > 100 && st.misses > 100);
    assert_true(st.surface < surfaceTol);
    assert_true(st.normal < surfaceTol);
    assert_true(st.distance < tol);
    assert_true(st.earlier < tol);
    assert_true(st.missInside < tol);
}

static void random_segments(void **state)
{
    (void)state;
    randomSegments(McdSphereCreate(fw, ME_R(0.9)), "sphere");
    randomSegments(McdBoxCreate(fw, ME_R(1.2), ME_R(0.6), ME_R(1.8)), "box");
    randomSegments(McdPlaneCreate(fw), "plane");
    randomSegments(McdCylinderCreate(fw, ME_R(0.7), ME_R(1.6)), "cylinder");
    randomSegments(McdSphylCreate(fw, ME_R(0.5), ME_R(1.4)), "sphyl");
    randomSegments(McdConeCreate(fw, ME_R(1.8), ME_R(0.9)), "cone");
    McdGeometryID frustum = McdConeCreate(fw, 1, 1);
    McdConeSetGeometricalParameters(frustum, ME_R(1.4), ME_R(1.0), ME_R(0.4));
    randomSegments(frustum, "frustum");
}

static void bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    McdModelID m = modelAt(McdSphereCreate(fw, 1), tm);
    MeVector3 a = {NAN, 0, 0}, b = {1, 0, 0};
    McdLineSegIntersectResult r;
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, assert_int_equal(McdLineSegIntersect(m, a, b, &r), 0));
    a[0] = -2;
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdLineSegIntersect(m, a, b, NULL), 0));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdLineSegIntersect(NULL, a, b, &r), 0));
    /* A zero-length segment hits only when it is inside. */
    MeVector3 c = {ME_R(0.5), 0, 0};
    assert_int_equal(McdLineSegIntersect(m, c, c, &r), 1);
    assert_near(r.distance, 0, 0);
    assert_int_equal(McdLineSegIntersect(m, a, a, &r), 0);
    McdModelDestroy(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(analytic_hits),
        cmocka_unit_test(random_segments),
        cmocka_unit_test(bad_input),
    };
    return cmocka_run_group_tests(tests, setup, karma_mcd_close);
}
