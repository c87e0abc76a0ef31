/* Convex meshes: the hull against brute force on random clouds (every input point inside or on it
 * within the stated tolerance, every polygon a supporting plane through hull vertices, convex and
 * counter-clockwise, Euler's formula, the support function of the cloud), degenerate clouds
 * (duplicates, coplanar points on faces, a cube jittered by 1e-7, flat and collinear sets), bad input
 * refused with codes, mass properties against closed forms (a box hull against the box, a prism of
 * many points against its exact formula and the cylinder within the discretisation error), AABB and
 * segments against the box primitive, and pair tests: analytic cases (face, edge, vertex, parallel
 * faces) and a convex box against the box-box test on random poses. */
#include "karma_test.h"
#include "karma_mcd_fixture.h"

#include <math.h>
#include <string.h>
#include <time.h>

#include <karma/Mcd.h>
#include <karma/karma.h>

#include "karma_mcd_reference.h"
#include "mcd/geometry/convex_hull.h"
#include "mcd/nearfield/nearfield.h"

#define PI 3.14159265358979323846

static McdFrameworkID fw;

static int setup(void **state)
{
    (void)state;
    return karma_mcd_open(&fw, 64, 1);
}

static McdConvexMeshID hullOf(MeVector3 *pts, int n, MeReal fat)
{
    return McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, n, fat);
}

static void boxCorners(MeVector3 *c, double hx, double hy, double hz, double ox, double oy, double oz)
{
    for (int k = 0; k < 8; k++)
        MeVector3Set(c[k], (MeReal)(ox + ((k & 1) ? hx : -hx)), (MeReal)(oy + ((k & 2) ? hy : -hy)),
                     (MeReal)(oz + ((k & 4) ? hz : -hz)));
}

/* Everything a hull of the cloud pts[n] must satisfy, checked through the public accessors. */
static void checkHull(McdConvexMeshID g, MeVector3 *pts, int n)
{
    const double tol = McdHullTolerance((const MeVector3 *)pts, n) * 1.01;
    const int nf = McdConvexMeshGetPolygonCount(g), nv = McdConvexMeshGetVertexCount(g);
    int edgeUses = 0;
    assert_true(nf >= 4);
    assert_true(nv >= 4);
    for (int p = 0; p < nf; p++) {
        MeVector3 nrm, v0;
        int m = McdConvexMeshGetPolygonVertexCount(g, p);
        double off = -1e300;
        assert_true(m >= 3);
        edgeUses += m;
        McdConvexMeshGetPolygonNormal(g, p, nrm);
        assert_near(MeVector3Magnitude(nrm), 1, ME_TOL(1e-12, 1e-6));
        McdConvexMeshGetPolygonVertex(g, p, 0, v0);
        for (int k = 0; k < m; k++) {
            const MeReal *a = McdConvexMeshGetPolygonVertexPtr(g, p, k);
            const MeReal *b = McdConvexMeshGetPolygonVertexPtr(g, p, (k + 1) % m);
            const MeReal *c = McdConvexMeshGetPolygonVertexPtr(g, p, (k + 2) % m);
            MeVector3 e1, e2, x;
            double o = MeVector3Dot(nrm, a);
            off = o > off ? o : off;
            /* every polygon vertex is an input point */
            int found = 0;
            for (int i = 0; i < n && !found; i++)
                found = a[0] == pts[i][0] && a[1] == pts[i][1] && a[2] == pts[i][2];
            assert_true(found);
            /* convex and counter-clockwise about the outward normal */
            MeVector3Subtract(e1, b, a);
            MeVector3Subtract(e2, c, b);
            MeVector3Cross(x, e1, e2);
            assert_true(MeVector3Dot(x, nrm) > 0);
        }
        /* planar within the tolerance: every vertex on the plane */
        for (int k = 0; k < m; k++)
            assert_true(off - MeVector3Dot(nrm, McdConvexMeshGetPolygonVertexPtr(g, p, k)) <= 2 * tol);
        /* supporting: every input point on the inner side (within the tolerance) */
        for (int i = 0; i < n; i++)
            assert_true(MeVector3Dot(nrm, pts[i]) - off <= tol);
    }
    /* a closed polyhedron: each edge in two polygons, V - E + F = 2 */
    assert_int_equal(nv - edgeUses / 2 + nf, 2);
    /* the support function of the hull is the cloud's: no extreme point lost */
    MeRealRandomSeed(7);
    for (int t = 0; t < 200; t++) {
        MeVector3 d = {MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1)}, s;
        double cloud = -1e300;
        if (!MeVector3NormalizeSafe(d))
            continue;
        for (int i = 0; i < n; i++)
            cloud = fmax(cloud, MeVector3Dot(d, pts[i]));
        McdGeometryMaximumPoint(g, NULL, d, s);
        assert_true(fabs(cloud - MeVector3Dot(d, s)) <= tol);
    }
}

static void randomCloud(MeVector3 *pts, int n, int kind, unsigned seed)
{
    MeRealRandomSeed(seed);
    for (int i = 0; i < n; i++) {
        MeVector3 d;
        do
            MeVector3Set(d, MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1));
        while (MeVector3Magnitude(d) > 1 || MeVector3Magnitude(d) < 1e-3);
        if (kind == 1) /* on the unit sphere: every point a vertex */
            MeVector3Normalize(d);
        if (kind == 2) /* in a cube far from the origin, stretched */
            MeVector3Set(d, 3 * d[0] + 40, d[1] - 7, ME_R(0.2) * d[2] + 3);
        MeVector3Copy(pts[i], d);
    }
}

static void hull_of_random_clouds_against_brute_force(void **state)
{
    (void)state;
    static MeVector3 pts[2000];
    const int sizes[] = {4, 10, 50, 300, 2000};
    for (int kind = 0; kind < 3; kind++)
        for (int s = 0; s < 5; s++) {
            int n = sizes[s];
            randomCloud(pts, n, kind, 100u * (unsigned)kind + (unsigned)s);
            McdConvexMeshID g = hullOf(pts, n, 0);
            assert_non_null(g);
            checkHull(g, pts, n);
            if (s == 4)
                printf("cloud kind %d, %d points: %d vertices, %d polygons, tolerance %.2e\n", kind, n,
                       McdConvexMeshGetVertexCount(g), McdConvexMeshGetPolygonCount(g), McdHullTolerance((const MeVector3 *)pts, n));
            McdGeometryDestroy(g);
        }
}

static void hull_build_time(void **state)
{
    (void)state;
    static MeVector3 pts[10000];
    for (int kind = 0; kind < 2; kind++) {
        McdHull h;
        randomCloud(pts, 10000, kind, 5);
        clock_t t0 = clock();
        assert_int_equal(McdHullBuild((const MeVector3 *)pts, 10000, &h), MCD_HULL_OK);
        double ms = 1e3 * (double)(clock() - t0) / CLOCKS_PER_SEC;
        printf("hull of 1e4 points %s: %.1f ms, %d vertices, %d polygons\n", kind ? "on a sphere" : "in a ball", ms,
               h.vertexCount, h.polygonCount);
        McdHullFree(&h);
    }
}

/* The hull of a unit cube given with extra points must be the cube: 8 vertices, 6 quadrilaterals
 * with the axis normals. */
static void expectCube(McdConvexMeshID g)
{
    assert_non_null(g);
    assert_int_equal(McdConvexMeshGetVertexCount(g), 8);
    assert_int_equal(McdConvexMeshGetPolygonCount(g), 6);
    for (int p = 0; p < 6; p++) {
        MeVector3 n;
        assert_int_equal(McdConvexMeshGetPolygonVertexCount(g, p), 4);
        McdConvexMeshGetPolygonNormal(g, p, n);
        assert_near(MeMAX3(MeFabs(n[0]), MeFabs(n[1]), MeFabs(n[2])), 1, 1e-6);
    }
}

static void degenerate_clouds(void **state)
{
    (void)state;
    static MeVector3 pts[400];
    int n = 0;
    /* duplicates: every corner five times, and interior points */
    for (int r = 0; r < 5; r++, n += 8)
        boxCorners(&pts[n], 1, 1, 1, 0, 0, 0);
    for (int i = 0; i < 20; i++, n++)
        MeVector3Set(pts[n], ME_R(0.9) * MeRealRandomInRange(-1, 1), ME_R(0.9) * MeRealRandomInRange(-1, 1), 0);
    McdConvexMeshID g = hullOf(pts, n, 0);
    expectCube(g);
    checkHull(g, pts, n);
    McdGeometryDestroy(g);
    /* coplanar: a 5 x 5 grid on each face of the cube (edges and face interiors included) */
    n = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2)
            for (int i = 0; i < 5; i++)
                for (int j = 0; j < 5; j++, n++) {
                    pts[n][axis] = (MeReal)side;
                    pts[n][(axis + 1) % 3] = ME_R(-1.0) + ME_R(0.5) * (MeReal)i;
                    pts[n][(axis + 2) % 3] = ME_R(-1.0) + ME_R(0.5) * (MeReal)j;
                }
    g = hullOf(pts, n, 0);
    expectCube(g);
    checkHull(g, pts, n);
    McdGeometryDestroy(g);
    /* nearly coplanar: the grid jittered by 1e-7 of its size, far below the tolerance (2e-5 here) */
    MeRealRandomSeed(3);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            pts[i][k] += ME_R(1e-7) * MeRealRandomInRange(-1, 1);
    g = hullOf(pts, n, 0);
    assert_non_null(g);
    assert_int_equal(McdConvexMeshGetPolygonCount(g), 6);
    checkHull(g, pts, n);
    McdGeometryDestroy(g);
    /* a face bulged by 10 tolerances is no longer flat: more polygons */
    boxCorners(pts, 1, 1, 1, 0, 0, 0);
    MeVector3Set(pts[8], 0, 0, ME_R(1.0) + ME_R(10.0) * (MeReal)McdHullTolerance((const MeVector3 *)pts, 8));
    g = hullOf(pts, 9, 0);
    assert_non_null(g);
    assert_int_equal(McdConvexMeshGetPolygonCount(g), 9);
    checkHull(g, pts, 9);
    McdGeometryDestroy(g);
    /* the same point within the tolerance is dropped */
    MeVector3Set(pts[8], 0, 0, ME_R(1.0) + ME_R(0.3) * (MeReal)McdHullTolerance((const MeVector3 *)pts, 8));
    g = hullOf(pts, 9, 0);
    expectCube(g);
    McdGeometryDestroy(g);
}

static void bad_input_is_refused(void **state)
{
    (void)state;
    MeVector3 pts[40];
    karma_capture_messages();
    boxCorners(pts, 1, 1, 1, 0, 0, 0);
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_null(hullOf(pts, 3, 0)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(McdConvexMeshCreateHull(fw, NULL, 8, 0)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(hullOf(pts, 8, -1)));
    assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(hullOf(pts, 8, ME_R(1e7))));
    /* all coplanar (a square grid, z jittered well inside the tolerance), all collinear, all equal */
    for (int i = 0; i < 36; i++)
        MeVector3Set(pts[i], (MeReal)(i % 6), (MeReal)(i / 6), (i % 2) ? ME_R(1e-7) : 0);
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_null(hullOf(pts, 36, 0)));
    for (int i = 0; i < 10; i++)
        MeVector3Set(pts[i], (MeReal)i, 2 * (MeReal)i, 0);
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_null(hullOf(pts, 10, 0)));
    for (int i = 0; i < 10; i++)
        MeVector3Set(pts[i], 1, 2, 3);
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_null(hullOf(pts, 10, 0)));
    /* not finite, too far, too small */
    boxCorners(pts, 1, 1, 1, 0, 0, 0);
    pts[5][1] = (MeReal)NAN;
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, assert_null(hullOf(pts, 8, 0)));
    boxCorners(pts, 1, 1, 1, ME_R(2e6), 0, 0);
    assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(hullOf(pts, 8, 0)));
    boxCorners(pts, ME_R(1e-7), ME_R(1e-7), ME_R(1e-7), 0, 0, 0); /* a hull, but below the size range */
    assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(hullOf(pts, 8, 0)));
    boxCorners(pts, ME_R(1e-7), 1, 1, 0, 0, 0); /* thinner than the tolerance for its size: flat */
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_null(hullOf(pts, 8, 0)));
    /* accessors: indices out of range and other types are refused, nothing written */
    boxCorners(pts, 1, 1, 1, 0, 0, 0);
    McdConvexMeshID g = hullOf(pts, 8, ME_R(0.1));
    MeVector3 v = {7, 7, 7};
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdConvexMeshGetPolygonVertex(g, 6, 0, v));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdConvexMeshGetPolygonVertex(g, 0, 4, v));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdConvexMeshGetPolygonNormal(g, -1, v));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdConvexMeshGetVertex(g, 8, v));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdConvexMeshGetPolygonVertexPtr(g, 0, -1)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(McdConvexMeshGetPolygonVertexCount(g, 99), 0));
    assert_true(v[0] == 7 && v[1] == 7 && v[2] == 7);
    McdGeometryID box = McdBoxCreate(fw, 1, 1, 1);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, assert_int_equal(McdConvexMeshGetPolygonCount(box), 0));
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, McdConvexMeshDestroy(box));
    assert_true(McdGeometryIsValid(box));
    assert_near(McdConvexMeshGetFatness(g), 0.1, 1e-7);
    assert_int_equal(McdGeometryGetTypeId(g), kMcdGeometryTypeConvexMesh);
    assert_int_equal(McdConvexMeshGetTypeId(), kMcdGeometryTypeConvexMesh);
    assert_string_equal(McdGeometryGetTypeName(g), "ConvexMesh");
    McdConvexMeshDestroy(g);
    assert_false(McdGeometryIsValid(g));
    McdGeometryDestroy(box);
}

static void box_hull_mass_properties_are_the_box_s(void **state)
{
    (void)state;
    MeVector3 pts[8];
    MeMatrix4 relH, relB;
    MeMatrix3 iH, iB;
    MeReal vH, vB;
    boxCorners(pts, 0.5, 1, 1.5, 5, -2, 1); /* a 1 x 2 x 3 box centred at (5, -2, 1) */
    McdConvexMeshID h = hullOf(pts, 8, 0);
    McdGeometryID b = McdBoxCreate(fw, 1, 2, 3);
    assert_int_equal(McdConvexMeshGetMassProperties(h, relH, iH, &vH), 0);
    assert_int_equal(McdGeometryGetMassProperties(b, relB, iB, &vB), 0);
    assert_rel(vH, vB, ME_TOL(1e-12, 1e-6));
    assert_near(relH[3][0], 5, ME_TOL(1e-12, 1e-5));
    assert_near(relH[3][1], -2, ME_TOL(1e-12, 1e-5));
    assert_near(relH[3][2], 1, ME_TOL(1e-12, 1e-5));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            assert_near(relH[i][j], i == j, 0);
            assert_near(iH[i][j], iB[i][j], ME_TOL(1e-10, 2e-5) * iB[2][2]);
        }
    /* rotated hull: the tensor rotates (R I R^T), the volume stays */
    MeMatrix4 rot;
    MeVector3 r[8];
    MeMatrix3 iR;
    MeReal vR;
    ref_tm_axis_angle(rot, 0, 0.6, 0.8, 0.7, 0, 0, 0);
    for (int k = 0; k < 8; k++) {
        MeVector3 local = {pts[k][0] - 5, pts[k][1] + 2, pts[k][2] - 1};
        MeMatrix4TMTransform(r[k], rot, local);
    }
    McdConvexMeshID hr = hullOf(r, 8, 0);
    assert_int_equal(McdGeometryGetMassProperties(hr, relH, iR, &vR), 0);
    assert_rel(vR, vB, ME_TOL(1e-12, 1e-5));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0; /* rows of rot are the box axes in the world: I_world = R^T I_box R */
            for (int a = 0; a < 3; a++)
                s += rot[a][i] * iB[a][a] * rot[a][j];
            assert_near(iR[i][j], s, ME_TOL(1e-10, 3e-5) * iB[2][2]);
        }
    McdGeometryDestroy(h);
    McdGeometryDestroy(hr);
    McdGeometryDestroy(b);
}

static void prism_mass_properties_and_the_cylinder(void **state)
{
    (void)state;
    static MeVector3 pts[2 * 64];
    const int n = 64;
    const double R = 0.7, H = 1.6, a = 2 * PI / n;
    for (int k = 0; k < n; k++)
        for (int s = 0; s < 2; s++)
            MeVector3Set(pts[2 * k + s], (MeReal)(R * cos(k * a)), (MeReal)(R * sin(k * a)),
                         (MeReal)(s ? H / 2 : -H / 2));
    McdConvexMeshID g = hullOf(pts, 2 * n, 0);
    assert_non_null(g);
    assert_int_equal(McdConvexMeshGetPolygonCount(g), n + 2);
    MeMatrix4 rel;
    MeMatrix3 I;
    MeReal V;
    assert_int_equal(McdGeometryGetMassProperties(g, rel, I, &V), 0);
    /* the regular n-gon prism exactly: area n R^2 sin(a) / 2, polar moment n R^4 sin(a) (2 + cos a) / 12 */
    const double area = n * R * R * sin(a) / 2, J = n * R * R * R * R * sin(a) * (2 + cos(a)) / 12;
    const double Vx = area * H, Izz = J * H, Ixx = J / 2 * H + area * H * H * H / 12;
    assert_rel(V, Vx, ME_TOL(1e-10, 1e-5));
    assert_rel(I[2][2], Izz, ME_TOL(1e-10, 1e-5));
    assert_rel(I[0][0], Ixx, ME_TOL(1e-10, 1e-5));
    assert_rel(I[1][1], Ixx, ME_TOL(1e-10, 1e-5));
    assert_near(I[0][1], 0, ME_TOL(1e-12, 1e-6));
    assert_near(rel[3][2], 0, ME_TOL(1e-12, 1e-6));
    /* against the cylinder: the prism lacks the circular segments, a relative area of
     * 1 - sin(a) / a = a^2 / 6 to first order (1.6e-3 at n = 64); the moments lose about twice that */
    McdGeometryID cyl = McdCylinderCreate(fw, (MeReal)R, (MeReal)H);
    MeMatrix3 Ic;
    MeReal Vc;
    McdGeometryGetMassProperties(cyl, rel, Ic, &Vc);
    const double disc = a * a / 6;
    printf("prism of %d sides: volume %.6f, cylinder %.6f (%.2e off, discretisation %.2e); Izz off %.2e\n", n,
           (double)V, (double)Vc, 1 - V / Vc, disc, 1 - I[2][2] / Ic[2][2]);
    assert_true(1 - V / Vc > 0 && 1 - V / Vc < 1.05 * disc);
    assert_true(1 - I[2][2] / Ic[2][2] > 0 && 1 - I[2][2] / Ic[2][2] < 2.1 * disc);
    assert_true(fabs(1 - I[0][0] / Ic[0][0]) < 2.1 * disc);
    McdGeometryDestroy(g);
    McdGeometryDestroy(cyl);
}

/* The rounded box (half-extents h, radius r) in closed form: its second moment along x, int x^2 dV,
 * from its cross-sections at x (a rectangle 2hy x 2hz rounded by r for |x| <= hx, by sqrt(r^2 - d^2)
 * at d = |x| - hx beyond), integrated by hand. */
static double roundedBoxSecondMoment(double hx, double hy, double hz, double r)
{
    const double rect = 4 * hy * hz, perim = 4 * (hy + hz);
    const double core = 2 * hx * hx * hx / 3 * (rect + perim * r + PI * r * r);
    const double cap = rect * (pow(hx + r, 3) - pow(hx, 3)) / 3 +
                       perim * (PI * r * r / 4 * hx * hx + 2 * hx * r * r * r / 3 + PI * pow(r, 4) / 16) +
                       PI * (2.0 / 3 * hx * hx * r * r * r + hx * pow(r, 4) / 2 + 2.0 / 15 * pow(r, 5));
    return core + 2 * cap;
}

/* A rounded box (1 x 2 x 3, fatness 0.3, off the origin and rotated) against the analytic rounded box:
 * Steiner's volume abc + 2r(ab + bc + ca) + pi r^2 (a + b + c) + 4/3 pi r^3, the centre, and the
 * inertia from the second moments above, rotated. */
static void rounded_box_mass_properties_are_exact(void **state)
{
    (void)state;
    const double hx = 0.5, hy = 1, hz = 1.5, r = 0.3, a = 2 * hx, b = 2 * hy, c = 2 * hz;
    const double exact = a * b * c + 2 * r * (a * b + b * c + c * a) + PI * r * r * (a + b + c) + 4.0 / 3 * PI * r * r * r;
    const double sx = roundedBoxSecondMoment(hx, hy, hz, r), sy = roundedBoxSecondMoment(hy, hz, hx, r),
                 sz = roundedBoxSecondMoment(hz, hx, hy, r);
    const double Ibox[3] = {sy + sz, sz + sx, sx + sy};
    MeMatrix4 rot, rel;
    MeMatrix3 I;
    MeReal V;
    MeVector3 pts[8];
    ref_tm_axis_angle(rot, 0.3, -0.5, 0.8, 1.1, 4, -1, 2);
    boxCorners(pts, hx, hy, hz, 0, 0, 0);
    for (int k = 0; k < 8; k++) {
        MeVector3 local;
        MeVector3Copy(local, pts[k]);
        MeMatrix4TMTransform(pts[k], rot, local);
    }
    McdConvexMeshID g = hullOf(pts, 8, (MeReal)r);
    assert_int_equal(McdGeometryGetMassProperties(g, rel, I, &V), 0);
    printf("rounded box 1 x 2 x 3, r 0.3: volume %.9f, Steiner %.9f (%.1e)\n", (double)V, exact, V / exact - 1);
    assert_rel(V, exact, ME_TOL(1e-12, 2e-6));
    for (int k = 0; k < 3; k++)
        assert_near(rel[3][k], rot[3][k], ME_TOL(1e-12, 2e-6));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0; /* I_world = R^T I_box R, rows of rot the box axes */
            for (int m = 0; m < 3; m++)
                s += rot[m][i] * Ibox[m] * rot[m][j];
            assert_near(I[i][j], s, ME_TOL(1e-11, 3e-6) * Ibox[0]);
        }
    McdGeometryDestroy(g);
}

/* Distance from x to the triangle t (Ericson's closest point by Voronoi regions). */
static double triangleDistance(const double x[3], double t[3][3])
{
    double ab[3], ac[3], ap[3], q[3], d = 0;
    for (int k = 0; k < 3; k++) {
        ab[k] = t[1][k] - t[0][k];
        ac[k] = t[2][k] - t[0][k];
        ap[k] = x[k] - t[0][k];
    }
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
    double d1 = DOT(ab, ap), d2 = DOT(ac, ap), bp[3], cp[3];
    for (int k = 0; k < 3; k++) {
        bp[k] = x[k] - t[1][k];
        cp[k] = x[k] - t[2][k];
    }
    double d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2, s, w;
#undef DOT
    if (d1 <= 0 && d2 <= 0)
        s = 0, w = 0;
    else if (d3 >= 0 && d4 <= d3)
        s = 1, w = 0;
    else if (d6 >= 0 && d5 <= d6)
        s = 0, w = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
        s = d1 / (d1 - d3), w = 0;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
        s = 0, w = d2 / (d2 - d6);
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6)), s = 1 - w;
    else {
        double den = 1 / (va + vb + vc);
        s = vb * den, w = vc * den;
    }
    for (int k = 0; k < 3; k++) {
        q[k] = t[0][k] + s * ab[k] + w * ac[k] - x[k];
        d += q[k] * q[k];
    }
    return sqrt(d);
}

/* Distance from x to the solid tetrahedron v[4] (0 inside). */
static double tetraDistance(const double x[3], const double v[4][3])
{
    static const int face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    double best = INFINITY;
    int outside = 0;
    for (int f = 0; f < 4; f++) {
        double t[3][3], e1[3], e2[3], n[3], opp = 0, here = 0;
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                t[j][k] = v[face[f][j]][k];
        for (int k = 0; k < 3; k++) {
            e1[k] = t[1][k] - t[0][k];
            e2[k] = t[2][k] - t[0][k];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        for (int k = 0; k < 3; k++) { /* the side of the face the fourth vertex is not on */
            opp += n[k] * (v[f][k] - t[0][k]);
            here += n[k] * (x[k] - t[0][k]);
        }
        if (here * opp < 0)
            outside = 1;
        best = fmin(best, triangleDistance(x, t));
    }
    return outside ? best : 0;
}

/* A rounded tetrahedron against an independent numerical integration: the solid {x : distance to the
 * tetrahedron <= r} is convex, so each vertical line (a 240 x 240 grid of columns, midpoints) meets it
 * in one interval, found by bisection on the distance; the interval's moments in z are exact. The
 * columns' error is of the order of the silhouette's (1e-4 relative). */
static void rounded_tetrahedron_mass_properties_against_integration(void **state)
{
    (void)state;
    const double v[4][3] = {{0.1, -0.2, 0.05}, {1.3, 0.1, -0.1}, {0.2, 0.9, 0.2}, {0.4, 0.3, 1.1}}, r = 0.25;
    MeVector3 pts[4];
    for (int i = 0; i < 4; i++)
        MeVector3Set(pts[i], (MeReal)v[i][0], (MeReal)v[i][1], (MeReal)v[i][2]);
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = fmin(fmin(v[0][k], v[1][k]), fmin(v[2][k], v[3][k])) - r;
        hi[k] = fmax(fmax(v[0][k], v[1][k]), fmax(v[2][k], v[3][k])) + r;
    }
    const int N = 240;
    const double hx = (hi[0] - lo[0]) / N, hy = (hi[1] - lo[1]) / N;
    double vol = 0, m1[3] = {0, 0, 0}, m2[3][3] = {{0}};
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            double x[3] = {lo[0] + (i + 0.5) * hx, lo[1] + (j + 0.5) * hy, 0}, best = INFINITY, zb = 0;
            /* the lowest point of the distance along the column: golden-free ternary search (convex) */
            double a = lo[2], b = hi[2];
            for (int it = 0; it < 60; it++) {
                double z1 = a + (b - a) / 3, z2 = b - (b - a) / 3, p1[3] = {x[0], x[1], z1}, p2[3] = {x[0], x[1], z2};
                if (tetraDistance(p1, v) < tetraDistance(p2, v))
                    b = z2;
                else
                    a = z1;
            }
            zb = (a + b) / 2;
            x[2] = zb;
            best = tetraDistance(x, v);
            if (best > r)
                continue;
            double ends[2];
            for (int side = 0; side < 2; side++) { /* bisection for distance = r on each side of zb */
                double in = zb, out = side ? hi[2] : lo[2];
                for (int it = 0; it < 50; it++) {
                    double mid = (in + out) / 2, p[3] = {x[0], x[1], mid};
                    if (tetraDistance(p, v) <= r)
                        in = mid;
                    else
                        out = mid;
                }
                ends[side] = (in + out) / 2;
            }
            const double z0 = ends[0], z1 = ends[1], L = (z1 - z0) * hx * hy;
            const double mz = (z1 * z1 - z0 * z0) / 2 * hx * hy, mzz = (z1 * z1 * z1 - z0 * z0 * z0) / 3 * hx * hy;
            vol += L;
            m1[0] += x[0] * L, m1[1] += x[1] * L, m1[2] += mz;
            m2[0][0] += x[0] * x[0] * L, m2[1][1] += x[1] * x[1] * L, m2[0][1] += x[0] * x[1] * L;
            m2[0][2] += x[0] * mz, m2[1][2] += x[1] * mz, m2[2][2] += mzz;
        }
    m2[1][0] = m2[0][1], m2[2][0] = m2[0][2], m2[2][1] = m2[1][2];
    double g[3], C[3][3], Inum[3][3];
    for (int k = 0; k < 3; k++)
        g[k] = m1[k] / vol;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = m2[i][j] - vol * g[i] * g[j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Inum[i][j] = (i == j ? C[0][0] + C[1][1] + C[2][2] : 0) - C[i][j];
    McdConvexMeshID h = hullOf(pts, 4, (MeReal)r);
    MeMatrix4 rel;
    MeMatrix3 I;
    MeReal V;
    assert_int_equal(McdGeometryGetMassProperties(h, rel, I, &V), 0);
    printf("rounded tetrahedron: volume %.6f, integrated %.6f (%.1e); Ixx %.6f, integrated %.6f (%.1e)\n", (double)V,
           vol, V / vol - 1, (double)I[0][0], Inum[0][0], I[0][0] / Inum[0][0] - 1);
    assert_rel(V, vol, 1e-4);
    for (int k = 0; k < 3; k++)
        assert_near(rel[3][k], g[k], 3e-4);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            assert_near(I[i][j], Inum[i][j], 1e-3 * Inum[0][0]);
    /* and a rounding of 0 is the polyhedron: the tetrahedron's volume |det| / 6 */
    McdConvexMeshID h0 = hullOf(pts, 4, 0);
    double e[3][3];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            e[i][k] = v[i + 1][k] - v[0][k];
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    assert_int_equal(McdGeometryGetMassProperties(h0, rel, I, &V), 0);
    assert_rel(V, fabs(det) / 6, ME_TOL(1e-12, 1e-6));
    McdGeometryDestroy(h);
    McdGeometryDestroy(h0);
}

/* McdConvexMeshCreateSphyl against the sphyl primitive: the same mass properties, support points
 * within the stated 1e-3 r + 1e-5 h (so GJK/EPA see the sphyl to that), bad sizes refused. */
static void convex_sphyl_is_the_sphyl(void **state)
{
    (void)state;
    const MeReal r = ME_R(0.3), h = ME_R(1.2);
    McdConvexMeshID c = McdConvexMeshCreateSphyl(fw, r, h);
    McdGeometryID s = McdSphylCreate(fw, r, h);
    MeMatrix4 rel1, rel2;
    MeMatrix3 I1, I2;
    MeReal v1, v2;
    assert_non_null(c);
    McdGeometryGetMassProperties(c, rel1, I1, &v1);
    McdGeometryGetMassProperties(s, rel2, I2, &v2);
    assert_rel(v1, v2, 1e-6);
    for (int i = 0; i < 3; i++)
        assert_rel(I1[i][i], I2[i][i], 1e-6);
    MeRealRandomSeed(5);
    for (int t = 0; t < 300; t++) {
        MeVector3 d = {MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1)}, p1, p2;
        if (!MeVector3NormalizeSafe(d))
            continue;
        McdGeometryMaximumPoint(c, NULL, d, p1);
        McdGeometryMaximumPoint(s, NULL, d, p2);
        assert_near(MeVector3Dot(p1, d), MeVector3Dot(p2, d), 1e-3 * r + 1e-5 * h + 1e-6);
    }
    karma_capture_messages();
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdConvexMeshCreateSphyl(fw, 0, 1)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdConvexMeshCreateSphyl(fw, 1, -1)));
    McdConvexMeshID ball = McdConvexMeshCreateSphyl(fw, 1, 0); /* a sphere */
    assert_non_null(ball);
    McdGeometryDestroy(ball);
    McdGeometryDestroy(c);
    McdGeometryDestroy(s);
}

static void aabb_bsphere_and_segments_match_the_box(void **state)
{
    (void)state;
    MeVector3 pts[8];
    boxCorners(pts, 0.5, 0.25, 1, 0, 0, 0);
    McdConvexMeshID h = hullOf(pts, 8, 0);
    McdGeometryID b = McdBoxCreate(fw, 1, 0.5, 2);
    McdModelID mh = McdModelCreate(h), mb = McdModelCreate(b);
    MeRealRandomSeed(11);
    int hits = 0;
    for (int t = 0; t < 500; t++) {
        MeMatrix4 tm;
        MeVector3 lo1, hi1, lo2, hi2, c, p0, p1;
        MeReal r;
        MeVector3 axis = {MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1), ME_R(0.5)};
        MeVector3Normalize(axis);
        ref_tm_axis_angle(tm, axis[0], axis[1], axis[2], MeRealRandomInRange(-3, 3), MeRealRandomInRange(-2, 2),
                          MeRealRandomInRange(-2, 2), MeRealRandomInRange(-2, 2));
        McdGeometryGetAABB(h, tm, lo1, hi1);
        McdGeometryGetAABB(b, tm, lo2, hi2);
        for (int k = 0; k < 3; k++) {
            assert_near(lo1[k], lo2[k], 1e-5);
            assert_near(hi1[k], hi2[k], 1e-5);
        }
        McdGeometryGetBSphere(h, c, &r);
        for (int k = 0; k < 8; k++)
            assert_true(MeVector3Distance(pts[k], c) <= r * (1 + 1e-6));
        MeMatrix4Copy(McdModelGetTransformPtr(mh), tm);
        MeMatrix4Copy(McdModelGetTransformPtr(mb), tm);
        McdModelUpdate(mh);
        McdModelUpdate(mb);
        MeVector3Set(p0, MeRealRandomInRange(-4, 4), MeRealRandomInRange(-4, 4), MeRealRandomInRange(-4, 4));
        MeVector3Set(p1, tm[3][0] + MeRealRandomInRange(-1, 1), tm[3][1] + MeRealRandomInRange(-1, 1),
                     tm[3][2] + MeRealRandomInRange(-1, 1)); /* towards the box */
        McdLineSegIntersectResult rh, rb;
        int a1 = McdLineSegIntersect(mh, p0, p1, &rh), a2 = McdLineSegIntersect(mb, p0, p1, &rb);
        assert_int_equal(a1, a2);
        if (a1) {
            hits++;
            assert_near(rh.distance, rb.distance, 1e-5);
            for (int k = 0; k < 3; k++) {
                assert_near(rh.position[k], rb.position[k], 1e-5);
                if (rb.distance > 0)
                    assert_near(rh.normal[k], rb.normal[k], 1e-5);
            }
        }
    }
    printf("segments: %d of 500 hit, each as the box primitive\n", hits);
    assert_true(hits > 150);
    McdModelDestroy(mh);
    McdModelDestroy(mb);
    McdGeometryDestroy(h);
    McdGeometryDestroy(b);
}

/* ---- pair tests ----------------------------------------------------------------------------- */

static McdGeometryData cubeHull(double half, double fat)
{
    MeVector3 pts[8];
    McdGeometryData g;
    boxCorners(pts, half, half, half, 0, 0, 0);
    ref_make_convex(&g, pts, 8, fat);
    return g;
}

static void identityAt(MeMatrix4 tm, double x, double y, double z) { ref_tm_axis_angle(tm, 0, 0, 1, 0, x, y, z); }

/* Distance from p to the box |x| <= h (closed form). */
static double boxDistance(const double p[3], const double h[3])
{
    double s = 0;
    for (int k = 0; k < 3; k++) {
        double e = fabs(p[k]) - h[k];
        s += e > 0 ? e * e : 0;
    }
    return sqrt(s);
}

/* A box hull rounded by r is the set within r of the box: segments at its face, edge and corner meet
 * it where that set begins (the faces' half-spaces moved out by r would meet it up to r (sqrt 3 - 1)
 * early at a corner), and 500 random segments against the first point within r of the box found by
 * bisection on the closed-form distance. */
static void rounded_hull_segments_are_exact(void **state)
{
    (void)state;
    const double h[3] = {0.5, 0.3, 0.2}, r = 0.1;
    MeVector3 pts[8];
    boxCorners(pts, h[0], h[1], h[2], 0, 0, 0);
    McdConvexMeshID g = hullOf(pts, 8, (MeReal)r);
    McdModelID m = McdModelCreate(g);
    MeMatrix4TMMakeIdentity(McdModelGetTransformPtr(m));
    McdModelUpdate(m);
    McdLineSegIntersectResult res;
    const double s2 = sqrt(0.5), s3 = sqrt(1.0 / 3);
    struct {
        double from[3], dir[3], hit[3];
    } cases[] = {
        {{2, 0.1, 0.05}, {-1, 0, 0}, {0.6, 0.1, 0.05}},                                      /* face */
        {{0.5 + 2 * s2, 0.3 + 2 * s2, 0}, {-s2, -s2, 0}, {0.5 + 0.1 * s2, 0.3 + 0.1 * s2, 0}}, /* edge */
        {{0.5 + 2 * s3, 0.3 + 2 * s3, 0.2 + 2 * s3},
         {-s3, -s3, -s3},
         {0.5 + 0.1 * s3, 0.3 + 0.1 * s3, 0.2 + 0.1 * s3}}, /* corner */
    };
    for (int i = 0; i < 3; i++) {
        MeVector3 p0, p1;
        for (int k = 0; k < 3; k++) {
            p0[k] = (MeReal)cases[i].from[k];
            p1[k] = (MeReal)(cases[i].from[k] + 4 * cases[i].dir[k]);
        }
        assert_true(McdLineSegIntersect(m, p0, p1, &res));
        for (int k = 0; k < 3; k++) {
            assert_near(res.position[k], cases[i].hit[k], 1e-5);
            assert_near(res.normal[k], -cases[i].dir[k], 1e-5);
        }
    }
    MeRealRandomSeed(5);
    int hits = 0;
    for (int trial = 0; trial < 500; trial++) {
        MeVector3 p0, p1;
        double a[3], b[3];
        for (int k = 0; k < 3; k++) {
            p0[k] = MeRealRandomInRange(-1.5, 1.5);
            p1[k] = MeRealRandomInRange(-0.8, 0.8);
            a[k] = (double)p0[k];
            b[k] = (double)p1[k];
        }
        if (boxDistance(a, h) <= r)
            continue; /* starts inside: distance 0, tested elsewhere */
        /* the first t where the distance reaches r: a sample below it, then bisection */
        double lo = 0, hi = -1;
        for (int k = 1; k <= 2000 && hi < 0; k++) {
            double q[3], t = k / 2000.0;
            for (int j = 0; j < 3; j++)
                q[j] = a[j] + t * (b[j] - a[j]);
            if (boxDistance(q, h) <= r)
                hi = t;
            else
                lo = t;
        }
        int hit = McdLineSegIntersect(m, p0, p1, &res);
        assert_int_equal(hit, hi >= 0);
        if (!hit)
            continue;
        hits++;
        for (int it = 0; it < 60; it++) {
            double q[3], t = (lo + hi) / 2;
            for (int j = 0; j < 3; j++)
                q[j] = a[j] + t * (b[j] - a[j]);
            *(boxDistance(q, h) <= r ? &hi : &lo) = t;
        }
        double len = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
        assert_near(res.distance, hi * len, 2e-5);
        /* the normal: from the closest box point to the hit point */
        double q[3], c[3], n[3], nl = 0;
        for (int j = 0; j < 3; j++) {
            q[j] = (double)res.position[j];
            c[j] = fmax(-h[j], fmin(h[j], q[j]));
            n[j] = q[j] - c[j];
            nl += n[j] * n[j];
        }
        for (int j = 0; j < 3; j++)
            assert_near(res.normal[j], n[j] / sqrt(nl), 1e-3);
    }
    printf("rounded hull: %d of 500 random segments hit, each where the box's r-neighbourhood begins\n", hits);
    assert_true(hits > 100);
    McdModelDestroy(m);
    McdConvexMeshDestroy(g);
}

static void analytic_face_edge_vertex(void **state)
{
    (void)state;
    McdGeometryData a = cubeHull(0.5, 0), b = cubeHull(0.5, 0), plane;
    MeMatrix4 ta, tb;
    McdContact c[4];
    int n;
    ref_make_plane(&plane);
    /* face on face, 0.01 deep, offset sideways by 0.3: four points on the overlap square's corners */
    identityAt(tb, 0, 0, 0);
    identityAt(ta, 0.3, 0.2, 0.99);
    n = McdNfCollide(&a, ta, &b, tb, ME_R(0.005), c, 4);
    assert_int_equal(n, 4);
    for (int k = 0; k < n; k++) {
        assert_near(c[k].normal[2], 1, 1e-6); /* from b (below) towards a */
        assert_near(c[k].separation, -0.01, 1e-5);
        assert_near(c[k].position[2], 0.495, 1e-5);
        assert_true(c[k].position[0] >= -0.2 - 1e-5 && c[k].position[0] <= 0.5 + 1e-5);
        assert_true(c[k].position[1] >= -0.3 - 1e-5 && c[k].position[1] <= 0.5 + 1e-5);
    }
    /* swapped: the same points, the normal negated */
    {
        McdContact s[4];
        assert_int_equal(McdNfCollide(&b, tb, &a, ta, ME_R(0.005), s, 4), 4);
        for (int k = 0; k < 4; k++)
            assert_near(s[k].normal[2], -1, 1e-6);
    }
    /* parallel faces apart by 0.003, within the tolerance 0.005: four points, separation +0.003 */
    identityAt(ta, 0, 0, 1.003);
    n = McdNfCollide(&a, ta, &b, tb, ME_R(0.005), c, 4);
    assert_int_equal(n, 4);
    for (int k = 0; k < n; k++)
        assert_near(c[k].separation, 0.003, 1e-5);
    /* ...and beyond it: none */
    identityAt(ta, 0, 0, 1.01);
    assert_int_equal(McdNfCollide(&a, ta, &b, tb, ME_R(0.005), c, 4), 0);
    /* an edge down (45 degrees about x): a line contact of two points at the edge's ends */
    ref_tm_axis_angle(ta, 1, 0, 0, PI / 4, 0, 0, 0.5 + sqrt(0.5) - 0.02);
    n = McdNfCollide(&a, ta, &b, tb, ME_R(0.005), c, 4);
    assert_int_equal(n, 2);
    for (int k = 0; k < n; k++) {
        assert_near(c[k].normal[2], 1, 1e-5);
        assert_near(c[k].separation, -0.02, 1e-5);
        assert_near(fabs(c[k].position[0]), 0.5, 1e-5);
        assert_near(c[k].position[1], 0, 1e-5);
    }
    /* a vertex down (a cube diagonal near z): one point under the lowest vertex, on the cube and on
     * the plane */
    {
        MeMatrix4 t;
        MeVector3 low = {0, 0, (MeReal)1e30}, corner, p;
        double second = 1e30;
        ref_tm_axis_angle(t, 1 / sqrt(2.0), -1 / sqrt(2.0), 0, acos(1 / sqrt(3.0)), 0, 0, 0);
        for (int k = 0; k < 8; k++) {
            MeVector3Set(corner, (k & 1) ? 0.5f : -0.5f, (k & 2) ? 0.5f : -0.5f, (k & 4) ? 0.5f : -0.5f);
            MeMatrix4TMTransform(p, t, corner);
            if (p[2] < low[2]) {
                second = low[2];
                MeVector3Copy(low, p);
            } else if (p[2] < second)
                second = p[2];
        }
        assert_true(second - low[2] > 0.3); /* a single lowest vertex */
        t[3][2] = (MeReal)(0.5 - low[2] - 0.01);
        n = McdNfCollide(&a, t, &b, tb, ME_R(0.005), c, 4);
        assert_int_equal(n, 1);
        assert_near(c[0].normal[2], 1, 1e-5);
        assert_near(c[0].separation, -0.01, 1e-5);
        assert_near(c[0].position[0], low[0], 1e-5);
        assert_near(c[0].position[1], low[1], 1e-5);
        t[3][2] = (MeReal)(-low[2] - 0.01);
        n = McdNfCollide(&a, t, &plane, tb, ME_R(0.005), c, 4);
        assert_int_equal(n, 1);
        assert_near(c[0].separation, -0.01, 1e-5);
        assert_near(c[0].normal[2], 1, 1e-6);
    }
    ref_free_convex(&a);
    ref_free_convex(&b);
}

static void rounded_hull_on_a_plane(void **state)
{
    (void)state;
    McdGeometryData a = cubeHull(0.5, 0.05), plane;
    MeMatrix4 ta, tp;
    McdContact c[4];
    ref_make_plane(&plane);
    identityAt(tp, 0, 0, 0);
    identityAt(ta, 0, 0, 0.54); /* the rounded bottom at -0.01 */
    int n = McdNfCollide(&a, ta, &plane, tp, ME_R(0.005), c, 4);
    assert_int_equal(n, 4);
    for (int k = 0; k < n; k++) {
        assert_near(c[k].separation, -0.01, 1e-6);
        assert_near(fabs(c[k].position[0]), 0.5, 1e-6); /* the flat bottom's corners, not the rounded rim's */
    }
    ref_free_convex(&a);
}

/* A sphere against a convex cube: over a face, beyond an edge, beyond a vertex, each at a distance
 * known in closed form (the nearest feature's); the normal points from the cube to the sphere. */
static void sphere_on_face_edge_vertex(void **state)
{
    (void)state;
    McdGeometryData cube = cubeHull(0.5, 0), ball;
    MeMatrix4 tc, ts;
    McdContact c[4];
    const double r = 0.3, s3 = 1 / sqrt(3.0), s2 = 1 / sqrt(2.0);
    /* centre directions (unit) and where the nearest point of the cube is */
    const double dir[3][3] = {{0, 0, 1}, {s2, 0, s2}, {s3, s3, s3}};
    const double near[3][3] = {{0.1, -0.2, 0.5}, {0.5, 0.1, 0.5}, {0.5, 0.5, 0.5}};
    ref_make_sphere(&ball, r);
    identityAt(tc, 0, 0, 0);
    for (int f = 0; f < 3; f++) {
        const double gap = -0.02; /* overlapping by 0.02 */
        identityAt(ts, near[f][0] + (r + gap) * dir[f][0], near[f][1] + (r + gap) * dir[f][1],
                   near[f][2] + (r + gap) * dir[f][2]);
        if (f > 0) /* edge: y anywhere along it; vertex: exactly on the diagonal */
            ts[3][1] = (MeReal)(f == 1 ? 0.1 : near[f][1] + (r + gap) * dir[f][1]);
        int n = McdNfCollide(&ball, ts, &cube, tc, ME_R(0.005), c, 4);
        assert_int_equal(n, 1);
        assert_near(c[0].separation, gap, ME_TOL(1e-9, 1e-5));
        for (int k = 0; k < 3; k++)
            assert_near(c[0].normal[k], dir[f][k], ME_TOL(1e-9, 1e-5));
    }
    ref_free_convex(&cube);
}

/* A hull whose points sit 1 m beside their origin rests on its face through MstUniverse: the body's
 * centre of mass is the hull's (relTM), so the box stands still instead of toppling about its edge. */
static void off_centre_hull_rests(void **state)
{
    (void)state;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    MeVector3 pts[8], p0, p1, com;
    static MeMatrix4 ground = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    MstFixedModelCreate(u, McdPlaneCreate(MstUniverseGetFramework(u)), ground);
    boxCorners(pts, 0.25, 0.25, 0.25, 1, 0, 0);
    McdGeometryID g = McdConvexMeshCreateHull(MstUniverseGetFramework(u), (const MeVector3 *)pts, 8, 0);
    McdModelID m = MstModelAndBodyCreate(u, g, 1000);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodyGetCenterOfMassRelativePosition(b, com);
    assert_near(com[0], 1, 1e-5);
    assert_near(com[1], 0, 1e-5);
    assert_near(MdtBodyGetMass(b), 125, 1e-2);
    MdtBodySetPosition(b, 0, 0, ME_R(0.25));
    MdtBodyEnable(b);
    MdtBodyGetCenterOfMassPosition(b, p0);
    for (int i = 0; i < 120; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    MdtBodyGetCenterOfMassPosition(b, p1);
    MeVector4 q;
    MdtBodyGetQuaternion(b, q);
    printf("off-centre hull after 2 s: centre of mass moved (%.2e %.2e %.2e) m, rotation angle %.2e rad\n",
           (double)(p1[0] - p0[0]), (double)(p1[1] - p0[1]), (double)(p1[2] - p0[2]),
           2 * acos(fmin(1.0, fabs((double)q[0]))));
    /* it sinks into the soft default contacts (a 125 kg body at massScale 1), but neither slides nor tilts
     * (toppling about the edge 0.75 m from a wrong centre of mass would turn it by radians) */
    assert_true(fabs(p1[0] - p0[0]) < 1e-4 && fabs(p1[1] - p0[1]) < 1e-4);
    assert_true(p1[2] - p0[2] < 0 && p1[2] - p0[2] > -0.01);
    assert_true(2 * acos(fmin(1.0, fabs((double)q[0]))) < 1e-3);
    MstUniverseDestroy(u);
}

/* A convex box against the box primitive, on random poses: the same depth and a normal along which
 * the box-box pair overlaps by that depth; the swapped pair gives the negated normal. */
static void convex_box_against_box_box(void **state)
{
    (void)state;
    RefRng rng = {0x5eedull};
    double worstDepth = 0, worstSwap = 0;
    int touching = 0;
    for (int pose = 0; pose < 2000; pose++) {
        double hx = ref_uniform(&rng, 0.2, 0.8), hy = ref_uniform(&rng, 0.2, 0.8), hz = ref_uniform(&rng, 0.2, 0.8);
        MeVector3 pts[8];
        McdGeometryData cvx, box, other;
        MeMatrix4 t1, t2;
        McdContact cc[4], cb[4], cs[4];
        boxCorners(pts, hx, hy, hz, 0, 0, 0);
        ref_make_convex(&cvx, pts, 8, 0);
        ref_make_box(&box, 2 * hx, 2 * hy, 2 * hz);
        ref_make_box(&other, ref_uniform(&rng, 0.4, 1.6), ref_uniform(&rng, 0.4, 1.6), ref_uniform(&rng, 0.4, 1.6));
        ref_random_tm(&rng, t1, 0, 0, 0);
        ref_random_tm(&rng, t2, ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1));
        int nc = McdNfCollide(&cvx, t1, &other, t2, ME_R(0.01), cc, 4);
        int nb = McdNfCollide(&box, t1, &other, t2, ME_R(0.01), cb, 4);
        int ns = McdNfCollide(&other, t2, &cvx, t1, ME_R(0.01), cs, 4);
        double size = ref_size(&box) + ref_size(&other);
        if (nc > 0 && nb > 0) {
            double dc = 1e300, db = 1e300, ds = 1e300, n[3] = {0, 0, 0}, m[3];
            for (int k = 0; k < nc; k++)
                if (cc[k].separation < dc) {
                    dc = cc[k].separation;
                    for (int i = 0; i < 3; i++)
                        n[i] = cc[k].normal[i];
                }
            for (int k = 0; k < nb; k++)
                db = fmin(db, cb[k].separation);
            for (int k = 0; k < ns; k++)
                ds = fmin(ds, cs[k].separation);
            touching++;
            /* box-box prefers face axes by 0.1 % of the depth */
            worstDepth = fmax(worstDepth, fabs(dc - db) / size);
            worstSwap = fmax(worstSwap, fabs(ds - dc) / size);
            for (int i = 0; i < 3; i++)
                m[i] = -n[i];
            if (dc < 0) /* the overlap along the convex pair's normal is its depth */
                assert_near(-ref_overlap(&cvx, t1, &other, t2, m), dc, 1e-3 * size);
            assert_true(ns > 0);
        } else if (nc != nb) {
            /* only at the tolerance's edge may one see a contact the other does not */
            double sep = nc ? cc[0].separation : cb[0].separation;
            assert_true(fabs(sep - 0.01) < 1e-3 * size);
        }
        ref_free_convex(&cvx);
    }
    printf("convex box vs box-box: %d touching poses, depth off by %.2e of the size at most, swapped %.2e\n", touching,
           worstDepth, worstSwap);
    assert_true(touching > 400);
    assert_true(worstDepth < 1.5e-3);
    assert_true(worstSwap < ME_TOL(1e-6, 2e-4));
}

/* Pair tests per second of two hulls of n points on a sphere, at random overlapping poses. */
static void measurePairs(int n)
{
    static MeVector3 pts[1000];
    McdGeometryData a, b;
    MeMatrix4 ta, tb;
    McdContact c[4];
    randomCloud(pts, n, 1, 9);
    ref_make_convex(&a, pts, n, 0);
    ref_make_convex(&b, pts, n, 0);
    identityAt(tb, 0, 0, 0);
    long calls = 0, touching = 0;
    clock_t t0 = clock();
    RefRng rng = {99};
    while (clock() - t0 < CLOCKS_PER_SEC / 4) {
        for (int k = 0; k < 100; k++, calls++) {
            ref_random_tm(&rng, ta, ref_uniform(&rng, -1.2, 1.2), ref_uniform(&rng, -1.2, 1.2), ref_uniform(&rng, -1.2, 1.2));
            touching += McdNfCollide(&a, ta, &b, tb, ME_R(0.01), c, 4) > 0;
        }
    }
    double s = (double)(clock() - t0) / CLOCKS_PER_SEC;
    printf("convex-convex (%d-point sphere hulls, %d vertices): %.0f pair tests/s (%ld calls, %ld touching)\n", n,
           a.u.convex.hull->vertexCount, (double)calls / s, calls, touching);
    assert_true(touching > 0);
    ref_free_convex(&a);
    ref_free_convex(&b);
}

static void pair_tests_per_second(void **state)
{
    (void)state;
    measurePairs(16);
    measurePairs(64);
    measurePairs(1000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hull_of_random_clouds_against_brute_force),
        cmocka_unit_test(hull_build_time),
        cmocka_unit_test(degenerate_clouds),
        cmocka_unit_test(bad_input_is_refused),
        cmocka_unit_test(box_hull_mass_properties_are_the_box_s),
        cmocka_unit_test(prism_mass_properties_and_the_cylinder),
        cmocka_unit_test(rounded_box_mass_properties_are_exact),
        cmocka_unit_test(rounded_tetrahedron_mass_properties_against_integration),
        cmocka_unit_test(convex_sphyl_is_the_sphyl),
        cmocka_unit_test(aabb_bsphere_and_segments_match_the_box),
        cmocka_unit_test(rounded_hull_segments_are_exact),
        cmocka_unit_test(analytic_face_edge_vertex),
        cmocka_unit_test(rounded_hull_on_a_plane),
        cmocka_unit_test(sphere_on_face_edge_vertex),
        cmocka_unit_test(off_centre_hull_rests),
        cmocka_unit_test(convex_box_against_box_box),
        cmocka_unit_test(pair_tests_per_second),
    };
    return cmocka_run_group_tests(tests, setup, karma_mcd_close);
}
