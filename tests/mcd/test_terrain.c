/* The static triangle geometries (triangle list, triangle mesh, height field) and their pair tests
 * against every convex primitive and the convex mesh, asserted on geometry:
 *  - creation and its coded errors (empty, out-of-range index, NaN, degenerate triangle, bad grid);
 *  - the mesh's tree: a box query equals the brute-force answer on random boxes and triangle soups;
 *  - analytic contacts: face, edge and vertex of a triangle against a sphere, a box and its hull;
 *  - random poses against one triangle: unit normals, points on both surfaces, depth equal to an
 *    independent computation (sphere and sphyl by closest points, box by the 13 separating axes),
 *    the swapped pair's normal negated; a convex box hull's depth also against the box primitive's;
 *  - a sphere, box, cylinder, sphyl and cone resting on each flat tessellated floor give the
 *    contacts of a plane (normal +z, the same depth), with internal edges suppressed;
 *  - a convex box hull face, edge and vertex down on each floor gives the box primitive's contacts
 *    and its own on a plane; a rounded hull its own depth and normal on a plane;
 *  - internal edges: the adjacency marks flat and concave edges unused, convex and boundary ones used;
 *  - line segments: first hit on each floor, on a hole, from behind a one-sided height field;
 *  - a height field's valley and ridge; heights from a BMP image (Karma's utilities). */
#include "karma_test.h"
#include "karma_pairs.h"
#include "karma_terrain.h"
#include "mcd_shapes.h"
#include "karma_mcd_reference.h"

#include <stdint.h>
#include <stdlib.h>

#include <karma/karma.h>

#define TOL_CONTACT ME_R(0.01)

static McdFrameworkID fwNew(void) { return karma_pairs_framework(0); }

static McdModelID modelAt(McdGeometryID g, MeMatrix4 tm) { return karma_model_at(g, tm, TOL_CONTACT / 2); }

/* Contacts of the pair (m1, m2), at most max, with the pair's default request. */
static int intersect(McdModelID m1, McdModelID m2, McdContact *c, int max)
{
    return karma_intersect(m1, m2, NULL, c, max);
}

static void translation(MeMatrix4 tm, double x, double y, double z)
{
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetPosition(tm, (MeReal)x, (MeReal)y, (MeReal)z);
}

/* ---- creation and errors ---------------------------------------------------------------------- */

static int dummyGenerator(McdModelPair *p, McdUserTriangle *t, MeVector3 pos, MeReal r, int max)
{
    (void)p, (void)t, (void)pos, (void)r, (void)max;
    return 0;
}

static void creation_and_errors(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = fwNew();
    MeVector3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    int ok[3] = {0, 1, 2}, bad[3] = {0, 1, 4}, line[3] = {0, 1, 3};
    McdTriangleMeshID m = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, ok, 1);
    assert_non_null(m);
    assert_int_equal(McdGeometryGetTypeId(m), kMcdGeometryTypeTriangleMesh);
    assert_string_equal(McdGeometryGetTypeName(m), "TriangleMesh");
    assert_int_equal(McdTriangleMeshGetTriangleCount(m), 1);
    McdTriangleMeshID r;
    assert_reports(ME_ERR_MCD_BAD_MESH, r = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, ok, 0));
    assert_null(r);
    assert_reports(ME_ERR_MCD_BAD_MESH, r = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, bad, 1));
    assert_null(r);
    assert_reports(ME_ERR_MCD_DEGENERATE_TRIANGLE, r = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, line, 1));
    assert_null(r);
    v[2][1] = (MeReal)NAN;
    assert_reports(ME_ERR_MCD_BAD_MESH, r = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, ok, 1));
    assert_null(r);
    assert_reports(ME_ERR_NULL_ARGUMENT, r = McdTriangleMeshCreate(fw, NULL, 4, ok, 1));

    MeReal h[6] = {0, 1, 2, 3, 4, 5};
    McdRGHeightFieldID f = McdRGHeightFieldCreate(fw, h, 3, 2, 1, ME_R(0.5), -1, -2);
    assert_non_null(f);
    MeReal *hp, dx, dy, x0, y0;
    int nx, ny;
    McdRGHeightFieldGetParameters(f, &hp, &nx, &ny, &dx, &dy, &x0, &y0);
    assert_true(hp != h && hp[5] == 5 && nx == 3 && ny == 2 && dx == 1 && dy == ME_R(0.5) && x0 == -1 && y0 == -2);
    MeVector3 lo, hi;
    McdModelID fm = McdModelCreate(f);
    McdModelUpdate(fm);
    McdModelGetAABB(fm, lo, hi);
    assert_true(lo[0] <= -1 && hi[0] >= 1 && lo[1] <= -2 && hi[1] >= ME_R(-1.5) && lo[2] <= 0 && hi[2] >= 5);
    assert_reports(ME_ERR_MCD_BAD_MESH, r = McdRGHeightFieldCreate(fw, h, 1, 6, 1, 1, 0, 0));
    assert_null(r);
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, r = McdRGHeightFieldCreate(fw, h, 3, 2, 0, 1, 0, 0));
    assert_reports(ME_ERR_MCD_SIZE_RANGE, r = McdRGHeightFieldCreate(fw, h, 3, 2, ME_R(1e-9), 1, 0, 0));
    h[3] = (MeReal)NAN;
    assert_reports(ME_ERR_MCD_BAD_MESH, r = McdRGHeightFieldCreate(fw, h, 3, 2, 1, 1, 0, 0));
    assert_null(r);

    MeVector3 bmin = {-1, -1, -1}, bmax = {1, 1, 1}, flat = {1, 1, -1};
    McdTriangleListID l = McdTriangleListCreate(fw, bmin, bmax, 16, dummyGenerator);
    assert_non_null(l);
    assert_int_equal(McdGeometryGetTypeId(l), kMcdGeometryTypeTriangleList);
    assert_int_equal(McdTriangleListGetMaxTriangles(l), 16);
    assert_true(McdTriangleListGetGenerator(l) == dummyGenerator);
    McdTriangleListSetUserData(l, &nx);
    assert_true(McdTriangleListGetUserData(l) == &nx);
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, r = McdTriangleListCreate(fw, bmin, flat, 16, dummyGenerator));
    assert_null(r);
    assert_reports(ME_ERR_ARGUMENT_RANGE, r = McdTriangleListCreate(fw, bmin, bmax, 0, dummyGenerator));
    assert_reports(ME_ERR_NULL_ARGUMENT, r = McdTriangleListCreate(fw, bmin, bmax, 4, NULL));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdTriangleListSetMaxTriangles(l, -3));
    assert_int_equal(McdTriangleListGetMaxTriangles(l), 16);
    /* static geometries: no mass */
    MeMatrix4 rel;
    MeMatrix3 I;
    MeReal vol = 1;
    McdGeometryGetMassProperties(m, rel, I, &vol);
    assert_true(vol == 0);
    McdModelDestroy(fm);
    McdTerm(fw);
}

/* ---- the tree against brute force --------------------------------------------------------------- */

static double rnd(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (double)((*s >> 8) & 0xffffff) / 16777216.0;
}

static void bvh_query_equals_brute_force(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    unsigned seed = 7;
    const int nt = 3000;
    MeVector3 *v = malloc(3 * (size_t)nt * sizeof *v);
    int *idx = malloc(3 * (size_t)nt * sizeof *idx);
    for (int i = 0; i < nt; i++) {
        double c[3] = {20 * rnd(&seed) - 10, 20 * rnd(&seed) - 10, 4 * rnd(&seed) - 2};
        for (int k = 0; k < 3; k++) {
            for (int j = 0; j < 3; j++)
                v[3 * i + k][j] = (MeReal)(c[j] + rnd(&seed) - 0.5);
            idx[3 * i + k] = 3 * i + k;
        }
    }
    McdTriangleMeshID m = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 3 * nt, idx, nt);
    assert_non_null(m);
    int *got = malloc((size_t)nt * sizeof *got);
    char *seen = malloc((size_t)nt);
    long visitedTotal = 0;
    for (int q = 0; q < 500; q++) {
        MeVector3 lo, hi;
        for (int j = 0; j < 3; j++) {
            double a = 24 * rnd(&seed) - 12, w = 3 * rnd(&seed);
            lo[j] = (MeReal)a;
            hi[j] = (MeReal)(a + w);
        }
        int n = McdTriangleMeshQueryBox(m, lo, hi, got, nt);
        for (int i = 0; i < nt; i++)
            seen[i] = 0;
        for (int i = 0; i < n; i++)
            seen[got[i]]++;
        int brute = 0;
        for (int i = 0; i < nt; i++) {
            int overlap = 1;
            for (int j = 0; j < 3; j++) {
                MeReal a = MeMIN3(v[3 * i][j], v[3 * i + 1][j], v[3 * i + 2][j]);
                MeReal b = MeMAX3(v[3 * i][j], v[3 * i + 1][j], v[3 * i + 2][j]);
                overlap &= a <= hi[j] && b >= lo[j];
            }
            brute += overlap;
            assert_int_equal(seen[i], overlap); /* each exactly once, exactly the overlapping ones */
        }
        assert_int_equal(n, brute);
        visitedTotal += n;
    }
    assert_true(visitedTotal > 500); /* the boxes did hit triangles */
    free(got);
    free(seen);
    free(v);
    free(idx);
    McdTerm(fw);
}

/* ---- adjacency: which edges are in use -------------------------------------------------------- */

static void adjacency_marks_internal_edges(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    /* a roof: two triangles meeting at a ridge along y (convex seen from above), and a valley */
    for (int valley = 0; valley < 2; valley++) {
        MeReal zr = valley ? -1 : 1;
        MeVector3 v[4] = {{-1, 0, 0}, {0, -1, zr}, {0, 1, zr}, {1, 0, 0}};
        /* ridge edge 1-2 shared; both triangles counter-clockwise seen from +z */
        int idx[6] = {0, 1, 2, 2, 1, 3};
        McdTriangleMeshID m = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, idx, 2);
        assert_non_null(m);
        MeVector3 a, b, c;
        int flags0, flags1;
        McdTriangleMeshGetTriangle(m, 0, a, b, c, &flags0);
        McdTriangleMeshGetTriangle(m, 1, a, b, c, &flags1);
        /* triangle 0's edge 1 (v1 -> v2) and triangle 1's edge 0 (v2 -> v1) are the shared edge */
        assert_int_equal(!!(flags0 & kMcdTriangleUseEdge1), !valley);
        assert_int_equal(!!(flags1 & kMcdTriangleUseEdge0), !valley);
        /* the boundary edges are in use */
        assert_true((flags0 & kMcdTriangleUseEdge0) && (flags0 & kMcdTriangleUseEdge2));
        assert_true((flags1 & kMcdTriangleUseEdge1) && (flags1 & kMcdTriangleUseEdge2));
        McdGeometryDestroy(m);
    }
    /* a flat floor: every internal edge unused, every border edge used */
    McdTriangleMeshID floor = karma_floor_mesh(fw, 2, 4, 0.3, 3);
    int used = 0, total = 0;
    for (int i = 0; i < McdTriangleMeshGetTriangleCount(floor); i++) {
        MeVector3 t[3];
        int flags;
        McdTriangleMeshGetTriangle(floor, i, t[0], t[1], t[2], &flags);
        for (int k = 0; k < 3; k++) {
            const MeReal *p = t[k], *q = t[(k + 1) % 3];
            int border = (MeFabs(p[0]) > ME_R(1.999) && MeFabs(q[0]) > ME_R(1.999) && p[0] == q[0]) ||
                         (MeFabs(p[1]) > ME_R(1.999) && MeFabs(q[1]) > ME_R(1.999) && p[1] == q[1]);
            assert_int_equal(!!(flags & (kMcdTriangleUseEdge0 << k)), border);
            used += border;
            total++;
        }
    }
    assert_int_equal(used, 16);
    assert_int_equal(total, 3 * 32);
    McdTerm(fw);
}

/* The convex hull of the corners of a box of half-sizes (hx, hy, hz) about the origin, rounded by fat. */
static McdConvexMeshID boxHull(McdFrameworkID fw, double hx, double hy, double hz, double fat)
{
    MeVector3 c[8];
    for (int k = 0; k < 8; k++)
        MeVector3Set(c[k], (MeReal)(k & 1 ? hx : -hx), (MeReal)(k & 2 ? hy : -hy), (MeReal)(k & 4 ? hz : -hz));
    McdConvexMeshID g = McdConvexMeshCreateHull(fw, (const MeVector3 *)c, 8, (MeReal)fat);
    assert_non_null(g);
    return g;
}

/* ---- analytic contacts on one triangle ---------------------------------------------------------- */

static McdTriangleMeshID oneTriangle(McdFrameworkID fw)
{
    MeVector3 v[3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    int idx[3] = {0, 1, 2};
    return McdTriangleMeshCreate(fw, (const MeVector3 *)v, 3, idx, 1);
}

static void sphere_face_edge_vertex(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    McdModelID tri = modelAt(oneTriangle(fw), (MeMatrix4){{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
    McdGeometryID sphere = McdSphereCreate(fw, ME_R(0.5));
    struct {
        double c[3], n[3], sep;
    } cases[] = {
        {{0.5, 0.5, 0.45}, {0, 0, 1}, -0.05},                       /* face, from above */
        {{0.5, 0.5, -0.4}, {0, 0, -1}, -0.1},                       /* face, from below (two-sided) */
        {{1, -0.3, 0.4}, {0, -0.6, 0.8}, 0.0},                      /* edge v0-v1 */
        {{-0.3, -0.4, 0}, {-0.6, -0.8, 0}, 0.0},                    /* vertex v0 */
        {{1.5, 1.5, 0}, {0.70710678, 0.70710678, 0}, 0.70710678 - 0.5}, /* edge v1-v2: too far */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        MeMatrix4 tm;
        translation(tm, cases[k].c[0], cases[k].c[1], cases[k].c[2]);
        McdModelID s = modelAt(sphere, tm);
        McdContact c[4];
        int n = intersect(s, tri, c, 4);
        if (cases[k].sep > TOL_CONTACT) {
            assert_int_equal(n, 0);
        } else {
            assert_int_equal(n, 1);
            assert_near(c[0].separation, cases[k].sep, ME_TOL(1e-9, 2e-5));
            for (int j = 0; j < 3; j++)
                assert_near(c[0].normal[j], cases[k].n[j], ME_TOL(1e-9, 2e-5));
            assert_true(c[0].element2 == (void *)(intptr_t)0);
        }
        McdModelDestroy(s);
    }
    McdTerm(fw);
}

/* The box primitive and its convex hull give the same contacts on a triangle's face, edge and vertex. */
static void boxOnTriangle(int hull)
{
    McdFrameworkID fw = fwNew();
    McdModelID tri = modelAt(oneTriangle(fw), (MeMatrix4){{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
    McdGeometryID box = hull ? boxHull(fw, 0.2, 0.2, 0.2, 0) : McdBoxCreate(fw, ME_R(0.4), ME_R(0.4), ME_R(0.4));
    McdContact c[4];
    /* face on face: the box's four bottom corners, 1 cm deep, normal +z */
    MeMatrix4 tm;
    translation(tm, 0.5, 0.5, 0.19);
    McdModelID b = modelAt(box, tm);
    int n = intersect(b, tri, c, 4);
    assert_int_equal(n, 4);
    for (int i = 0; i < n; i++) {
        assert_near(c[i].separation, -0.01, ME_TOL(1e-9, 2e-5));
        assert_near(c[i].normal[2], 1, ME_TOL(1e-9, 1e-6));
        assert_near(fabs(c[i].position[0] - 0.5), 0.2, ME_TOL(1e-9, 2e-5));
        assert_near(fabs(c[i].position[1] - 0.5), 0.2, ME_TOL(1e-9, 2e-5));
    }
    McdModelDestroy(b);
    /* the box's vertex down on the face: turned so that a corner points down (diagonal along z) */
    MeMatrix4 rot;
    double half = 0.2 * sqrt(3.0);
    ref_tm_axis_angle(rot, 1 / sqrt(2.0), -1 / sqrt(2.0), 0, acos(1 / sqrt(3.0)), 0.6, 0.6, half - 0.02);
    b = modelAt(box, rot);
    n = intersect(b, tri, c, 4);
    assert_int_equal(n, 1);
    assert_near(c[0].separation, -0.02, ME_TOL(1e-9, 5e-5));
    assert_near(c[0].normal[2], 1, ME_TOL(1e-9, 1e-5));
    assert_near(c[0].position[0], 0.6, ME_TOL(1e-9, 5e-5));
    McdModelDestroy(b);
    /* the box's face against the triangle's boundary edge v0-v1 (y = 0) from the side: normal -y */
    translation(tm, 1, -0.19, 0);
    b = modelAt(box, tm);
    n = intersect(b, tri, c, 4);
    assert_true(n >= 1 && n <= 2);
    for (int i = 0; i < n; i++) {
        assert_near(c[i].separation, -0.01, ME_TOL(1e-9, 5e-5));
        assert_near(c[i].normal[1], -1, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].position[1], 0.005, ME_TOL(1e-9, 5e-5));
    }
    McdModelDestroy(b);
    McdTerm(fw);
}

static void box_face_edge_vertex(void **state)
{
    (void)state;
    boxOnTriangle(0);
}

static void convex_box_face_edge_vertex(void **state)
{
    (void)state;
    boxOnTriangle(1);
}

/* ---- random poses against one triangle ---------------------------------------------------------- */

/* Closest point of the triangle to p (Ericson 5.1.5), in double. */
static void closestOnTriangle(const double a[3], const double b[3], const double c[3], const double p[3], double q[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    for (int j = 0; j < 3; j++) {
        ab[j] = b[j] - a[j], ac[j] = c[j] - a[j], ap[j] = p[j] - a[j], bp[j] = p[j] - b[j], cp[j] = p[j] - c[j];
    }
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
    double d1 = DOT(ab, ap), d2 = DOT(ac, ap), d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
#undef DOT
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2, s, t;
    if (d1 <= 0 && d2 <= 0) s = 0, t = 0;
    else if (d3 >= 0 && d4 <= d3) s = 1, t = 0;
    else if (d6 >= 0 && d5 <= d6) s = 0, t = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) s = d1 / (d1 - d3), t = 0;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) s = 0, t = d2 / (d2 - d6);
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        s = 1 - w, t = w;
    } else {
        double den = 1 / (va + vb + vc);
        s = vb * den, t = vc * den;
    }
    for (int j = 0; j < 3; j++)
        q[j] = a[j] + s * ab[j] + t * ac[j];
}

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from the segment to the triangle (dense sampling of the segment, refined): a reference
 * independent of GJK, good to 1e-9 of the sizes here. */
static double segmentTriangleDistance(double tri[3][3], const double p0[3], const double p1[3])
{
    double lo = 0, hi = 1;
    double best = 1e300, bestT = 0;
    for (int i = 0; i <= 200; i++) {
        double t = i / 200.0, p[3], q[3];
        for (int j = 0; j < 3; j++)
            p[j] = p0[j] + t * (p1[j] - p0[j]);
        closestOnTriangle(tri[0], tri[1], tri[2], p, q);
        double d = dist3(p, q);
        if (d < best)
            best = d, bestT = t;
    }
    lo = bestT - 0.005, hi = bestT + 0.005;
    for (int it = 0; it < 100; it++) { /* ternary search: the distance is convex in t */
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3, d[2];
        double ts[2] = {m1, m2};
        for (int k = 0; k < 2; k++) {
            double t = ts[k] < 0 ? 0 : ts[k] > 1 ? 1 : ts[k], p[3], q[3];
            for (int j = 0; j < 3; j++)
                p[j] = p0[j] + t * (p1[j] - p0[j]);
            closestOnTriangle(tri[0], tri[1], tri[2], p, q);
            d[k] = dist3(p, q);
        }
        if (d[0] < d[1])
            hi = m2;
        else
            lo = m1;
        best = d[0] < best ? d[0] : best;
        best = d[1] < best ? d[1] : best;
    }
    return best;
}

/* Penetration depth of a box and a triangle by the 13 separating axes (positive when they
 * overlap on every axis: the least overlap), in double. */
static double boxTriangleSat(const double radii[3], MeMatrix4 tm, double tri[3][3])
{
    double axes[13][3], ax[3][3], e[3][3];
    int na = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            ax[i][j] = tm[i][j];
            e[i][j] = tri[(i + 1) % 3][j] - tri[i][j];
        }
    double nrm[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                     e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    for (int j = 0; j < 3; j++)
        axes[na][j] = nrm[j];
    na++;
    for (int i = 0; i < 3; i++, na++)
        for (int j = 0; j < 3; j++)
            axes[na][j] = ax[i][j];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++, na++) {
            axes[na][0] = e[k][1] * ax[i][2] - e[k][2] * ax[i][1];
            axes[na][1] = e[k][2] * ax[i][0] - e[k][0] * ax[i][2];
            axes[na][2] = e[k][0] * ax[i][1] - e[k][1] * ax[i][0];
        }
    double depth = 1e300;
    for (int a = 0; a < na; a++) {
        double len = sqrt(axes[a][0] * axes[a][0] + axes[a][1] * axes[a][1] + axes[a][2] * axes[a][2]);
        if (len < 1e-9)
            continue;
        double L[3] = {axes[a][0] / len, axes[a][1] / len, axes[a][2] / len};
        double c = tm[3][0] * L[0] + tm[3][1] * L[1] + tm[3][2] * L[2], r = 0;
        for (int i = 0; i < 3; i++)
            r += radii[i] * fabs(ax[i][0] * L[0] + ax[i][1] * L[1] + ax[i][2] * L[2]);
        double tmin = 1e300, tmax = -1e300;
        for (int v = 0; v < 3; v++) {
            double p = tri[v][0] * L[0] + tri[v][1] * L[1] + tri[v][2] * L[2];
            tmin = p < tmin ? p : tmin;
            tmax = p > tmax ? p : tmax;
        }
        double overlap = fmin(c + r - tmin, tmax - (c - r));
        depth = overlap < depth ? overlap : depth;
    }
    return depth;
}

typedef struct RandomStats {
    int touching, depthChecked;
    double worstNormal, worstSurface1, worstSurface2, worstDepth, worstSwap;
    double worstTwin; /* a convex box hull's deepest against the box primitive's */
} RandomStats;

static void randomAgainstTriangle(int type, RandomStats *st)
{
    McdFrameworkID fw = fwNew();
    MeRealRandomSeed(11u + (unsigned)type);
    double tri[3][3] = {{-0.8, -0.6, 0.1}, {0.9, -0.4, -0.2}, {0.1, 0.9, 0.05}};
    MeVector3 v[3];
    for (int i = 0; i < 3; i++)
        MeVector3Set(v[i], (MeReal)tri[i][0], (MeReal)tri[i][1], (MeReal)tri[i][2]);
    int idx[3] = {0, 1, 2};
    McdTriangleMeshID mesh = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 3, idx, 1);
    MeMatrix4 meshTM;
    MeMatrix4TMMakeIdentity(meshTM);
    McdModelID mm = modelAt(mesh, meshTM);
    McdGeometryID g = NULL;
    switch (type) {
    case kMcdGeometryTypeSphere: g = McdSphereCreate(fw, ME_R(0.4)); break;
    case kMcdGeometryTypeBox: g = McdBoxCreate(fw, ME_R(0.6), ME_R(0.4), ME_R(0.3)); break;
    case kMcdGeometryTypeCylinder: g = McdCylinderCreate(fw, ME_R(0.3), ME_R(0.6)); break;
    case kMcdGeometryTypeSphyl: g = McdSphylCreate(fw, ME_R(0.25), ME_R(0.5)); break;
    case kMcdGeometryTypeConvexMesh: g = boxHull(fw, 0.3, 0.2, 0.15, 0); break;
    default: g = McdConeCreate(fw, ME_R(0.7), ME_R(0.35)); break;
    }
    TestShape shape = test_shape_of(g);
    /* the convex box hull: its surface is the box's, and the box primitive at the same pose gives an
     * independent depth (box-triangle through the box's own core and features) */
    McdGeometryID twin = NULL;
    if (type == kMcdGeometryTypeConvexMesh) {
        twin = McdBoxCreate(fw, ME_R(0.6), ME_R(0.4), ME_R(0.3));
        shape = test_shape_of(twin);
    }
    for (int pose = 0; pose < 2000; pose++) {
        MeMatrix4 tm;
        test_random_tm(tm, ME_R(0.7));
        McdModelID m = modelAt(g, tm);
        McdContact c[4], cs[4];
        int n = intersect(m, mm, c, 4);
        int ns = intersect(mm, m, cs, 4);
        assert_int_equal(n, ns);
        if (n > 0)
            st->touching++;
        double deepest = 1e300;
        for (int i = 0; i < n; i++) {
            double len = sqrt((double)MeVector3MagnitudeSqr(c[i].normal));
            st->worstNormal = fmax(st->worstNormal, fabs(len - 1));
            assert_true(c[i].separation <= TOL_CONTACT * 1.01);
            double on1[3], on2[3], q[3];
            for (int j = 0; j < 3; j++) {
                on1[j] = c[i].position[j] + 0.5 * c[i].separation * c[i].normal[j];
                on2[j] = c[i].position[j] - 0.5 * c[i].separation * c[i].normal[j];
            }
            st->worstSurface1 = fmax(st->worstSurface1, fabs(test_sdf_world(&shape, tm, on1)));
            closestOnTriangle(tri[0], tri[1], tri[2], on2, q);
            st->worstSurface2 = fmax(st->worstSurface2, dist3(on2, q));
            if (getenv("TERRAIN_DEBUG") && dist3(on2, q) > 1e-4)
                printf("pose %d type %d contact %d/%d sep %g n %g %g %g pos %g %g %g centre %g %g %g off %g\n", pose, type, i, n,
                       (double)c[i].separation, (double)c[i].normal[0], (double)c[i].normal[1], (double)c[i].normal[2],
                       (double)c[i].position[0], (double)c[i].position[1], (double)c[i].position[2], (double)tm[3][0],
                       (double)tm[3][1], (double)tm[3][2], dist3(on2, q));
            deepest = fmin(deepest, c[i].separation);
            /* the swapped pair: same contacts, normal negated */
            for (int j = 0; j < 3; j++)
                st->worstSwap = fmax(st->worstSwap, fabs(c[i].normal[j] + cs[i].normal[j]));
            st->worstSwap = fmax(st->worstSwap, fabs(c[i].separation - cs[i].separation));
        }
        /* the depth against an independent computation */
        double ref = 1e300;
        if (type == kMcdGeometryTypeSphere) {
            double p[3] = {tm[3][0], tm[3][1], tm[3][2]}, q[3];
            closestOnTriangle(tri[0], tri[1], tri[2], p, q);
            ref = dist3(p, q) - shape.radius;
        } else if (type == kMcdGeometryTypeSphyl) {
            double p0[3], p1[3];
            for (int j = 0; j < 3; j++) {
                p0[j] = tm[3][j] - shape.halfHeight * tm[2][j];
                p1[j] = tm[3][j] + shape.halfHeight * tm[2][j];
            }
            ref = segmentTriangleDistance(tri, p0, p1) - shape.radius;
        } else if (shape.type == kMcdGeometryTypeBox) {
            double d = boxTriangleSat(shape.radii, tm, tri);
            ref = d > 0 ? -d : 1e300; /* SAT gives the depth of overlapping pairs only */
        }
        if (twin) {
            McdModelID b = modelAt(twin, tm);
            McdContact cb[4];
            int nb = intersect(b, mm, cb, 4);
            assert_int_equal(n > 0, nb > 0);
            double deepB = 1e300;
            for (int i = 0; i < nb; i++)
                deepB = fmin(deepB, cb[i].separation);
            if (n > 0)
                st->worstTwin = fmax(st->worstTwin, fabs(deepest - deepB));
            McdModelDestroy(b);
        }
        if (ref < 1e299) {
            /* a core that crosses the triangle's plane: the depth is the face's (two-sided triangles
             * push out on the centre's side), not the minimum translation: not compared */
            double nrm[3] = {0, 0, 1};
            (void)nrm;
            if (ref <= TOL_CONTACT - 1e-3 && ref > -0.2) {
                if (n == 0 && getenv("TERRAIN_DEBUG"))
                    printf("missed pose %d type %d ref %g centre %g %g %g\n", pose, type, ref, (double)tm[3][0],
                           (double)tm[3][1], (double)tm[3][2]);
                assert_true(n > 0);
                st->depthChecked++;
                st->worstDepth = fmax(st->worstDepth, fabs(deepest - ref));
            } else if (ref > TOL_CONTACT + 1e-3) {
                assert_int_equal(n, 0);
            }
        }
        McdModelDestroy(m);
    }
    McdModelDestroy(mm);
    McdTerm(fw);
}

static void random_poses_one_triangle(void **state)
{
    (void)state;
    static const int types[] = {kMcdGeometryTypeSphere, kMcdGeometryTypeBox, kMcdGeometryTypeCylinder,
                                kMcdGeometryTypeSphyl, kMcdGeometryTypeCone, kMcdGeometryTypeConvexMesh};
    for (size_t k = 0; k < sizeof types / sizeof types[0]; k++) {
        RandomStats st = {0};
        randomAgainstTriangle(types[k], &st);
        printf("%-8s vs triangle: %4d touching of 2000, depth checked %4d: |n|-1 %.1e, on shape %.1e, on triangle "
               "%.1e, depth %.1e, swap %.1e",
               ref_type_name(types[k]), st.touching, st.depthChecked, st.worstNormal,
               st.worstSurface1, st.worstSurface2, st.worstDepth, st.worstSwap);
        if (types[k] == kMcdGeometryTypeConvexMesh)
            printf(", deepest off the box primitive's by %.1e", st.worstTwin);
        printf("\n");
        assert_true(st.touching > 200);
        assert_true(st.worstNormal < ME_TOL(1e-9, 1e-5));
        /* curved rims (cylinder, cone) go through GJK/EPA with the normal refined on the supports: as
         * the primitives' general path (test_nearfield_random), their points are good to ~2e-3 of
         * the size in float, 1e-4 in double (the general path promises 1e-3 of the size in either);
         * the closed forms and flat features to the precision */
        const int curved = types[k] == kMcdGeometryTypeCylinder || types[k] == kMcdGeometryTypeCone;
        const double surfaceTol = curved ? ME_TOL(1e-4, 3e-3) : ME_TOL(1e-6, 1e-3);
        assert_true(st.worstSurface1 < surfaceTol);
        assert_true(st.worstSurface2 < surfaceTol);
        assert_true(st.worstSwap < ME_TOL(1e-9, 1e-5));
        if (types[k] != kMcdGeometryTypeCylinder && types[k] != kMcdGeometryTypeCone) {
            assert_true(st.depthChecked > 100);
            assert_true(st.worstDepth < ME_TOL(1e-6, 1e-3));
        }
        assert_true(st.worstTwin < ME_TOL(1e-6, 1e-3));
    }
}

/* ---- resting on a flat tessellated floor: the contacts of a plane ----------------------------------- */

enum { FLOOR_MESH, FLOOR_FIELD, FLOOR_LIST, FLOORS };
static const char *const floorNames[FLOORS] = {"mesh", "height field", "triangle list"};

static McdGeometryID makeFloor(McdFrameworkID fw, int kind, McdTriangleMeshID *meshOut)
{
    McdTriangleMeshID mesh = karma_floor_mesh(fw, 2, 8, 0.3, 5);
    if (meshOut)
        *meshOut = mesh;
    switch (kind) {
    case FLOOR_MESH: return mesh;
    case FLOOR_FIELD: return karma_floor_field(fw, 2, 8);
    default: return karma_floor_list(fw, mesh);
    }
}

/* The y-up placement of a z-up floor (as a plane's, McdPlane.h) or the identity. */
static void floorTM(MeMatrix4 tm, int yUp)
{
    MeMatrix4TMMakeIdentity(tm);
    if (yUp) {
        MeVector3Set(tm[1], 0, 0, -1);
        MeVector3Set(tm[2], 0, 1, 0);
    }
}

/* The plane z-up and y-up (as floorTM), as models. */
static void planeModels(McdFrameworkID fw, McdModelID plane[2])
{
    for (int yUp = 0; yUp < 2; yUp++) {
        MeMatrix4 tm;
        floorTM(tm, yUp);
        plane[yUp] = modelAt(McdPlaneCreate(fw), tm);
    }
}

static void rests_as_on_a_plane(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    McdGeometryID shapes[5] = {McdSphereCreate(fw, ME_R(0.3)), McdBoxCreate(fw, ME_R(0.4), ME_R(0.5), ME_R(0.3)),
                               McdCylinderCreate(fw, ME_R(0.25), ME_R(0.5)), McdSphylCreate(fw, ME_R(0.2), ME_R(0.5)),
                               McdConeCreate(fw, ME_R(0.6), ME_R(0.3))};
    /* the lowest point of each shape in its resting pose (sphyl lying along x, others upright) */
    const double bottom[5] = {0.3, 0.15, 0.25, 0.2, 0.15};
    const int lying[5] = {0, 0, 1, 1, 0};
    McdModelID plane[2];
    planeModels(fw, plane);
    for (int kind = 0; kind < FLOORS; kind++) {
        McdTriangleMeshID mesh = NULL;
        McdGeometryID floorGeo = makeFloor(fw, kind, &mesh);
        assert_non_null(floorGeo);
        double worstNormal = 0, worstDepth = 0, worstCorner = 0, worstSurface = 0;
        int cases = 0;
        for (int yUp = 0; yUp < 2; yUp++) {
            MeMatrix4 ftm;
            floorTM(ftm, yUp);
            McdModelID floor = modelAt(floorGeo, ftm);
            MeRealRandomSeed(3);
            for (int s = 0; s < 5; s++)
                for (int pose = 0; pose < 60; pose++) {
                    /* local pose on the floor: a yaw, a place, 5 mm deep */
                    double yaw = MeRealRandomInRange(0, ME_R(6.283)), x = MeRealRandomInRange(-1.5, 1.5),
                           y = MeRealRandomInRange(-1.5, 1.5);
                    MeMatrix4 local, world;
                    if (lying[s])
                        ref_tm_axis_angle(local, 0, 1, 0, 3.14159265358979 / 2, x, y, bottom[s] - 0.005);
                    else
                        MeMatrix4TMMakeIdentity(local), MeMatrix4TMSetPosition(local, (MeReal)x, (MeReal)y,
                                                                               (MeReal)(bottom[s] - 0.005));
                    MeMatrix4 yawTM;
                    ref_tm_axis_angle(yawTM, 0, 0, 1, yaw, 0, 0, 0);
                    MeMatrix4 tmp;
                    MeMatrix4MultiplyMatrix(tmp, local, yawTM); /* turned about the floor's normal */
                    MeVector3Copy(tmp[3], local[3]);
                    MeMatrix4MultiplyMatrix(world, tmp, ftm);
                    McdModelID m = modelAt(shapes[s], world);
                    McdContact cf[4], cp[4];
                    int nf = intersect(m, floor, cf, 4), np = intersect(m, plane[yUp], cp, 4);
                    assert_true(np >= 1);
                    assert_true(nf >= 1);
                    double deepF = 1e9, deepP = 1e9;
                    TestShape shape = test_shape_of(shapes[s]);
                    for (int i = 0; i < nf; i++) {
                        double on1[3];
                        for (int j = 0; j < 3; j++) {
                            worstNormal = fmax(worstNormal, fabs(cf[i].normal[j] - ftm[2][j]));
                            on1[j] = cf[i].position[j] + 0.5 * cf[i].separation * cf[i].normal[j];
                        }
                        worstSurface = fmax(worstSurface, fabs(test_sdf_world(&shape, world, on1)));
                        deepF = fmin(deepF, cf[i].separation);
                    }
                    if (np >= 3)
                        assert_true(nf >= 3); /* a face down stands on three points or more */
                    for (int i = 0; i < np; i++)
                        deepP = fmin(deepP, cp[i].separation);
                    worstDepth = fmax(worstDepth, fabs(deepF - deepP));
                    /* the support: each of the plane's contacts has a floor contact there (a box's
                     * corners, a sphyl's ends, a sphere's point); a lying sphyl may get more points
                     * along its line, all at the same depth */
                    const int polygonal = s != 2 && s != 4; /* discs: other rim points, as valid */
                    for (int i = 0; i < np && polygonal; i++) {
                        double best = 1e9;
                        for (int k = 0; k < nf; k++)
                            best = fmin(best, MeVector3Distance(cp[i].position, cf[k].position));
                        if (best > 1e-4 && getenv("TERRAIN_DEBUG"))
                            printf("shape %d pose %d: plane contact %d of %d unmatched by %g (%d floor contacts)\n", s,
                                   pose, i, np, best, nf);
                        worstCorner = fmax(worstCorner, best);
                    }
                    cases++;
                    McdModelDestroy(m);
                }
            McdModelDestroy(floor);
        }
        printf("%-13s: %d rests: normal off by %.1e, depth off by %.1e, plane's contacts matched to %.1e m, "
               "points on the shape to %.1e m\n", floorNames[kind], cases, worstNormal, worstDepth, worstCorner,
               worstSurface);
        assert_true(worstSurface < ME_TOL(1e-9, 1e-5));
        assert_true(worstNormal < ME_TOL(1e-9, 1e-5));
        assert_true(worstDepth < ME_TOL(1e-9, 1e-5));
        assert_true(worstCorner < ME_TOL(1e-6, 1e-4));
        if (kind != FLOOR_MESH)
            McdGeometryDestroy(floorGeo);
        if (kind != FLOOR_MESH || mesh != floorGeo)
            McdGeometryDestroy(mesh);
        else
            McdGeometryDestroy(mesh);
    }
    McdTerm(fw);
}

/* The pose `local` (a rotation) turned by yaw about the floor's normal, at (x, y, height) on the floor. */
static void placeOnFloor(MeMatrix4 world, MeMatrix4 local, double yaw, double x, double y, double height, MeMatrix4 ftm)
{
    MeMatrix4 yawTM, tmp;
    ref_tm_axis_angle(yawTM, 0, 0, 1, yaw, 0, 0, 0);
    MeMatrix4MultiplyMatrix(tmp, local, yawTM);
    MeVector3Set(tmp[3], (MeReal)x, (MeReal)y, (MeReal)height);
    MeMatrix4MultiplyMatrix(world, tmp, ftm);
}

/* A convex box hull on each floor, face, edge and vertex down, gives the box primitive's contacts on
 * that floor (same points, normal and depth) and the hull's own depth and support on a plane; a
 * rounded hull (fatness 3 cm) gives its own depth and normal on a plane. */
static void convex_hull_rests_as_the_box(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    const double r[3] = {0.2, 0.25, 0.15};
    const double fat = 0.03;
    McdGeometryID hull = boxHull(fw, r[0], r[1], r[2], 0), box = McdBoxCreate(fw, ME_R(0.4), ME_R(0.5), ME_R(0.3));
    McdGeometryID rounded = boxHull(fw, r[0] - fat, r[1] - fat, r[2] - fat, fat);
    TestShape shape = test_shape_of(box);
    /* face down; edge down (45 degrees about x); vertex down (tilted about x, then about y) */
    static const char *const poseNames[3] = {"face", "edge", "vertex"};
    const int plainCount[3] = {4, 2, 1};
    McdModelID plane[2];
    planeModels(fw, plane);
    for (int kind = 0; kind < FLOORS; kind++) {
        McdTriangleMeshID mesh = NULL;
        McdGeometryID floorGeo = makeFloor(fw, kind, &mesh);
        for (int down = 0; down < 3; down++) {
            double worstBox = 0, worstPlane = 0, worstNormal = 0, worstSurface = 0, worstCorner = 0, worstRounded = 0;
            int cases = 0;
            for (int yUp = 0; yUp < 2; yUp++) {
                MeMatrix4 ftm;
                floorTM(ftm, yUp);
                McdModelID floor = modelAt(floorGeo, ftm);
                MeRealRandomSeed(5 + (unsigned)down);
                for (int pose = 0; pose < 50; pose++) {
                    double yaw = MeRealRandomInRange(0, ME_R(6.283)), x = MeRealRandomInRange(-1.5, 1.5),
                           y = MeRealRandomInRange(-1.5, 1.5);
                    MeMatrix4 tilt, tilt2, local, world, worldR;
                    ref_tm_axis_angle(tilt, 1, 0, 0, down >= 1 ? 3.14159265358979 / 4 : 0, 0, 0, 0);
                    ref_tm_axis_angle(tilt2, 0, 1, 0, down == 2 ? 0.5 : 0, 0, 0, 0);
                    MeMatrix4MultiplyMatrix(local, tilt, tilt2);
                    /* the lowest point of the turned box, 5 mm into the floor */
                    double bottom = 0, bottomR = fat;
                    for (int i = 0; i < 3; i++) {
                        bottom += r[i] * fabs((double)local[i][2]);
                        bottomR += (r[i] - fat) * fabs((double)local[i][2]);
                    }
                    placeOnFloor(world, local, yaw, x, y, bottom - 0.005, ftm);
                    placeOnFloor(worldR, local, yaw, x, y, bottomR - 0.005, ftm);
                    McdModelID mh = modelAt(hull, world), mb = modelAt(box, world);
                    McdContact ch[4], cb[4], cp[4];
                    int nh = intersect(mh, floor, ch, 4), nb = intersect(mb, floor, cb, 4);
                    int np = intersect(mh, plane[yUp], cp, 4);
                    assert_int_equal(np, plainCount[down]);
                    assert_int_equal(nh, nb);
                    double deepH = 1e9, deepP = 1e9;
                    for (int i = 0; i < nh; i++) {
                        /* the box primitive's contact at the same place, with the same normal and depth */
                        double best = 1e9, on1[3];
                        int match = 0;
                        for (int k = 0; k < nb; k++)
                            if (MeVector3Distance(ch[i].position, cb[k].position) < best)
                                best = MeVector3Distance(ch[i].position, cb[k].position), match = k;
                        worstBox = fmax(worstBox, best);
                        worstBox = fmax(worstBox, fabs(ch[i].separation - cb[match].separation));
                        for (int j = 0; j < 3; j++) {
                            worstBox = fmax(worstBox, fabs(ch[i].normal[j] - cb[match].normal[j]));
                            worstNormal = fmax(worstNormal, fabs(ch[i].normal[j] - ftm[2][j]));
                            on1[j] = ch[i].position[j] + 0.5 * ch[i].separation * ch[i].normal[j];
                        }
                        worstSurface = fmax(worstSurface, fabs(test_sdf_world(&shape, world, on1)));
                        deepH = fmin(deepH, ch[i].separation);
                    }
                    for (int i = 0; i < np; i++) {
                        double best = 1e9;
                        deepP = fmin(deepP, cp[i].separation);
                        for (int k = 0; k < nh; k++)
                            best = fmin(best, MeVector3Distance(cp[i].position, ch[k].position));
                        worstCorner = fmax(worstCorner, best);
                    }
                    assert_true(nh >= np);
                    worstPlane = fmax(worstPlane, fabs(deepH - deepP));
                    assert_near(deepH, -0.005, ME_TOL(1e-9, 2e-5));
                    /* the rounded hull: the plane's depth and normal, a face down on three points or more */
                    McdModelID mr = modelAt(rounded, worldR);
                    McdContact cr[4], crp[4];
                    int nr = intersect(mr, floor, cr, 4), nrp = intersect(mr, plane[yUp], crp, 4);
                    assert_true(nr >= 1 && nrp >= 1);
                    if (nrp >= 3)
                        assert_true(nr >= 3);
                    double deepR = 1e9, deepRP = 1e9;
                    for (int i = 0; i < nr; i++) {
                        deepR = fmin(deepR, cr[i].separation);
                        for (int j = 0; j < 3; j++)
                            worstRounded = fmax(worstRounded, fabs(cr[i].normal[j] - ftm[2][j]));
                    }
                    for (int i = 0; i < nrp; i++)
                        deepRP = fmin(deepRP, crp[i].separation);
                    worstRounded = fmax(worstRounded, fabs(deepR - deepRP));
                    assert_near(deepR, -0.005, ME_TOL(1e-9, 2e-5));
                    McdModelDestroy(mr);
                    cases++;
                    McdModelDestroy(mh);
                    McdModelDestroy(mb);
                }
                McdModelDestroy(floor);
            }
            printf("convex box %-6s down on the %-13s: %d rests: off the box primitive's contacts by %.1e, normal "
                   "off by %.1e, depth off the plane's by %.1e, plane's contacts matched to %.1e m, points on the "
                   "box to %.1e m; rounded hull off the plane's normal and depth by %.1e\n",
                   poseNames[down], floorNames[kind], cases, worstBox, worstNormal, worstPlane, worstCorner,
                   worstSurface, worstRounded);
            assert_true(worstBox < ME_TOL(1e-6, 1e-4));
            assert_true(worstNormal < ME_TOL(1e-9, 1e-5));
            assert_true(worstPlane < ME_TOL(1e-9, 1e-5));
            assert_true(worstCorner < ME_TOL(1e-6, 1e-4));
            assert_true(worstSurface < ME_TOL(1e-9, 1e-5));
            assert_true(worstRounded < ME_TOL(1e-9, 1e-5));
        }
        if (floorGeo != mesh)
            McdGeometryDestroy(floorGeo);
        McdGeometryDestroy(mesh);
    }
    McdTerm(fw);
}

/* ---- line segments ------------------------------------------------------------------------------ */

static void segments_first_hit(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    MeMatrix4 id;
    MeMatrix4TMMakeIdentity(id);
    for (int kind = 0; kind < FLOORS; kind++) {
        McdTriangleMeshID mesh = NULL;
        McdModelID floor = modelAt(makeFloor(fw, kind, &mesh), id);
        McdLineSegIntersectResult r;
        MeRealRandomSeed(9);
        for (int i = 0; i < 200; i++) {
            MeReal x = MeRealRandomInRange(-1.7, 1.7), y = MeRealRandomInRange(-1.7, 1.7);
            MeReal dx = MeRealRandomInRange(-0.5, 0.5), dy = MeRealRandomInRange(-0.5, 0.5);
            MeVector3 p0 = {x, y, 1}, p1 = {x + dx, y + dy, -1};
            int hit0 = McdLineSegIntersect(floor, p0, p1, &r);
            if (!hit0 && getenv("TERRAIN_DEBUG"))
                printf("kind %d segment %d at %g %g missed\n", kind, i, (double)x, (double)y);
            assert_true(hit0);
            assert_true(r.model == floor);
            assert_near(r.position[0], x + dx / 2, ME_TOL(1e-9, 1e-5));
            assert_near(r.position[1], y + dy / 2, ME_TOL(1e-9, 1e-5));
            assert_near(r.position[2], 0, ME_TOL(1e-9, 1e-5));
            assert_near(r.normal[2], 1, ME_TOL(1e-9, 1e-6));
            assert_near(r.distance, MeVector3Distance(p0, p1) / 2, ME_TOL(1e-9, 1e-5));
            /* from below: the two-sided mesh and list hit with the normal down, the height field is
             * one-sided (solid below): no entry from inside */
            int hit = McdLineSegIntersect(floor, p1, p0, &r);
            assert_int_equal(hit, kind != FLOOR_FIELD);
            if (hit)
                assert_near(r.normal[2], -1, ME_TOL(1e-9, 1e-6));
            /* a segment that stops short, or passes beside */
            MeVector3 p2 = {x, y, ME_R(0.01)}, p3 = {3, y, 1}, p4 = {3, y, -1};
            assert_false(McdLineSegIntersect(floor, p0, p2, &r));
            assert_false(McdLineSegIntersect(floor, p3, p4, &r));
        }
        if (kind == FLOOR_LIST) /* the generator was given a pair of the list's model */
            assert_true(karma_floor_list_last_pair()->model1 == floor);
        McdGeometryID g = McdModelGetGeometry(floor);
        McdModelDestroy(floor);
        McdGeometryDestroy(g);
        if (mesh != g)
            McdGeometryDestroy(mesh);
    }
    /* a hole in a height field: no hit through it, and a sphere falls through it */
    McdRGHeightFieldID f = karma_floor_field(fw, 2, 8);
    unsigned char holes[64] = {0};
    holes[3 * 8 + 4] = 1; /* cell (4, 3): x in [0, 0.5], y in [-0.5, 0] */
    McdRGHeightFieldSetHoles(f, holes);
    McdModelID fm = modelAt(f, id);
    McdLineSegIntersectResult r;
    MeVector3 a = {ME_R(0.25), ME_R(-0.25), 1}, b = {ME_R(0.25), ME_R(-0.25), -1};
    assert_false(McdLineSegIntersect(fm, a, b, &r));
    MeVector3 c = {ME_R(0.75), ME_R(-0.25), 1}, d = {ME_R(0.75), ME_R(-0.25), -1};
    assert_true(McdLineSegIntersect(fm, c, d, &r));
    MeMatrix4 st;
    translation(st, 0.25, -0.25, 0.05);
    McdModelID small = modelAt(McdSphereCreate(fw, ME_R(0.1)), st);
    McdContact k[4];
    int n = intersect(small, fm, k, 4);
    /* over the hole the sphere touches only the hole's rim, sideways, never a floor under it */
    for (int i = 0; i < n; i++)
        assert_true(k[i].normal[2] < ME_R(0.99));
    translation(st, 0.25, -0.25, -0.3);
    McdModelSetTransformPtr(small, NULL);
    MeMatrix4Copy(McdModelGetTransformPtr(small), st);
    McdModelUpdate(small);
    assert_int_equal(intersect(small, fm, k, 4), 0);
    McdTerm(fw);
}

/* ---- triangle lists: Karma's flags and the generator's pair --------------------------------------- */

static MeVector3 flagVerts[2][3] = {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}}, {{-1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}};
static MeVector3 flagNormal = {0, 0, 1};
static int flagSet;

static int flagGenerator(McdModelPair *pair, McdUserTriangle *t, MeVector3 pos, MeReal radius, int max)
{
    (void)pos, (void)radius;
    assert_non_null(pair);
    assert_true(max >= 2);
    for (int i = 0; i < 2; i++) {
        for (int k = 0; k < 3; k++)
            t[i].vertices[k] = &flagVerts[i][k];
        t[i].normal = &flagNormal;
        t[i].triangleData.ptr = (void *)(intptr_t)(10 + i);
        t[i].flags = (McdTriangleFlags)flagSet;
    }
    return 2;
}

static void triangle_list_flags(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    MeVector3 lo = {-1, -1, -1}, hi = {1, 1, 1};
    MeMatrix4 id, tm;
    MeMatrix4TMMakeIdentity(id);
    McdModelID list = modelAt(McdTriangleListCreate(fw, lo, hi, 8, flagGenerator), id);
    McdGeometryID sphere = McdSphereCreate(fw, ME_R(0.2));
    McdContact c[4];
    /* a sphere on the shared diagonal, 2 cm deep: with its edges unused the normal is the face's */
    translation(tm, 0.1, 0.1, 0.18);
    McdModelID s = modelAt(sphere, tm);
    flagSet = kMcdTriangleUseSmallestPenetration | kMcdTriangleTwoSided;
    int n = intersect(s, list, c, 4);
    assert_true(n >= 1);
    for (int i = 0; i < n; i++) {
        assert_near(c[i].normal[2], 1, ME_TOL(1e-9, 1e-6));
        assert_near(c[i].separation, -0.02, ME_TOL(1e-9, 1e-5));
        assert_true(c[i].element2 == (void *)(intptr_t)10 || c[i].element2 == (void *)(intptr_t)11);
    }
    McdModelDestroy(s);
    /* beside the outer edge x = 1, below the plane's level: an edge in use pushes sideways (+x); not
     * in use, the sphere (its centre beside the triangle) gets no contact from the face */
    translation(tm, 1.15, 0, -0.05);
    s = modelAt(sphere, tm);
    flagSet = kMcdTriangleStandard;
    n = intersect(s, list, c, 4);
    assert_int_equal(n, 1);
    const double reach = sqrt(0.15 * 0.15 + 0.05 * 0.05); /* to the edge's point (1, 0, 0) */
    assert_near(c[0].normal[0], 0.15 / reach, ME_TOL(1e-9, 1e-5));
    assert_near(c[0].normal[2], -0.05 / reach, ME_TOL(1e-9, 1e-5));
    assert_near(c[0].separation, reach - 0.2, ME_TOL(1e-9, 1e-5));
    flagSet = kMcdTriangleUseSmallestPenetration | kMcdTriangleTwoSided;
    assert_int_equal(intersect(s, list, c, 4), 0);
    McdModelDestroy(s);
    /* one-sided: a sphere whose centre is 5 cm below the face is pushed up through it */
    translation(tm, 0.3, -0.3, -0.05);
    s = modelAt(sphere, tm);
    flagSet = kMcdTriangleUseSmallestPenetration | kMcdTriangleUseEdges;
    n = intersect(s, list, c, 4);
    assert_int_equal(n, 1);
    assert_near(c[0].normal[2], 1, ME_TOL(1e-9, 1e-6));
    assert_near(c[0].separation, -0.25, ME_TOL(1e-9, 1e-5));
    /* two-sided: pushed down, out of the near side */
    flagSet = kMcdTriangleStandard;
    n = intersect(s, list, c, 4);
    assert_int_equal(n, 1);
    assert_near(c[0].normal[2], -1, ME_TOL(1e-9, 1e-6));
    assert_near(c[0].separation, -0.15, ME_TOL(1e-9, 1e-5));
    McdModelDestroy(s);
    McdTerm(fw);
}

/* ---- a height field's valley and ridge --------------------------------------------------------- */

/* A 5 x 3 grid, 1 m apart, whose heights fall (valley) or rise (ridge) by 0.5 m per metre away
 * from x = 2: two slopes of 26.6 degrees meeting along the line x = 2. */
static McdModelID vee(McdFrameworkID fw, double sign)
{
    MeReal h[15];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 5; i++)
            h[j * 5 + i] = (MeReal)(sign * 0.5 * fabs(i - 2.0));
    MeMatrix4 id;
    MeMatrix4TMMakeIdentity(id);
    return modelAt(McdRGHeightFieldCreate(fw, h, 5, 3, 1, 1, 0, 0), id);
}

/* Vertical rays on a random height field hit the surface of the cell's right triangle (lower: x' >= y',
 * upper: y' >= x' in the cell's unit coordinates), at random points and at points exactly on the
 * cells' diagonals and edges, where the triangle filter of the field's walk must keep both sides. */
static void height_field_rays_hit_the_right_triangle(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    enum { NX = 9, NY = 7 };
    static MeReal h[NX * NY];
    const double dx = 0.5, dy = 0.75, x0 = -2, y0 = -2.25;
    unsigned seed = 11;
    for (int i = 0; i < NX * NY; i++)
        h[i] = (MeReal)(rnd(&seed) - 0.5);
    McdRGHeightFieldID f = McdRGHeightFieldCreate(fw, h, NX, NY, (MeReal)dx, (MeReal)dy, (MeReal)x0, (MeReal)y0);
    assert_non_null(f);
    MeMatrix4 id;
    MeMatrix4TMMakeIdentity(id);
    McdModelID m = modelAt(f, id);
    for (int i = 0; i < 3000; i++) {
        const int ix = (int)(rnd(&seed) * (NX - 1)), iy = (int)(rnd(&seed) * (NY - 1));
        double u = rnd(&seed), v = rnd(&seed);
        if (i % 3 == 1)
            v = u; /* on the diagonal */
        else if (i % 3 == 2 && i % 2)
            u = 0; /* on a cell edge */
        else if (i % 3 == 2)
            v = 0;
        const MeReal *c = &h[iy * NX + ix];
        const double h00 = c[0], h10 = c[1], h01 = c[NX], h11 = c[NX + 1];
        const double z = u >= v ? h00 + u * (h10 - h00) + v * (h11 - h10) : h00 + v * (h01 - h00) + u * (h11 - h01);
        const MeReal x = (MeReal)(x0 + (ix + u) * dx), y = (MeReal)(y0 + (iy + v) * dy);
        MeVector3 p0 = {x, y, 2}, p1 = {x, y, -2};
        McdLineSegIntersectResult r;
        assert_true(McdLineSegIntersect(m, p0, p1, &r));
        assert_near(r.position[2], z, ME_TOL(1e-9, 1e-5));
    }
    McdModelDestroy(m);
    McdGeometryDestroy(f);
    McdTerm(fw);
}

static void height_field_valley_and_ridge(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew();
    McdGeometryID sphere = McdSphereCreate(fw, ME_R(0.5));
    const double slope = sqrt(1.25); /* |(0.5, 0, 1)| */
    McdContact c[4];
    MeMatrix4 tm;
    /* valley: the sphere rests on both slopes, 1 cm deep into each, with each slope's normal; the
     * concave edge at the bottom gives nothing of its own */
    McdModelID valley = vee(fw, 1);
    translation(tm, 2, 1, (0.5 - 0.01) * slope);
    McdModelID s = modelAt(sphere, tm);
    int n = intersect(s, valley, c, 4), left = 0, right = 0;
    assert_true(n >= 2);
    for (int i = 0; i < n; i++) {
        assert_near(c[i].separation, -0.01, ME_TOL(1e-9, 1e-5));
        assert_near(fabs(c[i].normal[0]), 0.5 / slope, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].normal[1], 0, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].normal[2], 1 / slope, ME_TOL(1e-9, 1e-5));
        left += c[i].normal[0] > 0;
        right += c[i].normal[0] < 0;
    }
    assert_true(left >= 1 && right >= 1);
    McdModelDestroy(s);
    /* ridge: the edge at the top is convex (53 degrees), in use: a sphere above it touches the edge
     * straight up; a box lying across it rests on the edge's line */
    McdModelID ridge = vee(fw, -1);
    translation(tm, 2, 1, 0.49);
    s = modelAt(sphere, tm);
    n = intersect(s, ridge, c, 4);
    assert_true(n >= 1);
    for (int i = 0; i < n; i++) {
        assert_near(c[i].separation, -0.01, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].normal[2], 1, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].position[0], 2, ME_TOL(1e-9, 1e-5));
    }
    McdModelDestroy(s);
    translation(tm, 2, 1, 0.09);
    s = modelAt(McdBoxCreate(fw, ME_R(0.4), ME_R(0.6), ME_R(0.2)), tm);
    n = intersect(s, ridge, c, 4);
    if (getenv("TERRAIN_DEBUG"))
        for (int i = 0; i < n; i++)
            printf("ridge box %d: sep %g n %g %g %g at %g %g %g\n", i, (double)c[i].separation, (double)c[i].normal[0],
                   (double)c[i].normal[1], (double)c[i].normal[2], (double)c[i].position[0], (double)c[i].position[1],
                   (double)c[i].position[2]);
    assert_true(n >= 2); /* on the line along the ridge, its two ends among them */
    double yMin = 9, yMax = -9;
    for (int i = 0; i < n; i++) {
        assert_near(c[i].separation, -0.01, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].normal[2], 1, ME_TOL(1e-9, 1e-5));
        assert_near(c[i].position[0], 2, ME_TOL(1e-9, 1e-5));
        yMin = fmin(yMin, c[i].position[1]);
        yMax = fmax(yMax, c[i].position[1]);
    }
    assert_near(yMin, 0.7, ME_TOL(1e-9, 1e-5));
    assert_near(yMax, 1.3, ME_TOL(1e-9, 1e-5));
    McdModelDestroy(s);
    McdTerm(fw);
}

/* ---- a height field from an image (Karma's McduRGHeighField... utilities) ------------------------ */

/* Write a 24-bit BMP of 3 x 2 pixels: pixel (ix, iy) (iy = 0 the bottom row) has red 50 ix, green
 * 100 iy, blue 7; bottom-up rows as most BMPs, or top-down (negative height). */
static void writeBmp(const char *path, int topDown)
{
    unsigned char file[54 + 2 * 12] = {'B', 'M'};
    const int w = 3, h = 2, stride = 12;
    unsigned size = (unsigned)sizeof file;
    int32_t height = topDown ? -h : h;
    for (int k = 0; k < 4; k++) {
        file[2 + k] = (unsigned char)(size >> (8 * k));
        file[10 + k] = (unsigned char)(54u >> (8 * k));
        file[14 + k] = (unsigned char)(40u >> (8 * k));
        file[18 + k] = (unsigned char)((uint32_t)w >> (8 * k));
        file[22 + k] = (unsigned char)((uint32_t)height >> (8 * k));
    }
    file[26] = 1;
    file[28] = 24;
    for (int r = 0; r < h; r++) {
        int iy = topDown ? h - 1 - r : r;
        for (int ix = 0; ix < w; ix++) {
            unsigned char *px = file + 54 + r * stride + 3 * ix;
            px[0] = 7, px[1] = (unsigned char)(100 * iy), px[2] = (unsigned char)(50 * ix);
        }
    }
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(file, 1, sizeof file, f), sizeof file);
    fclose(f);
}

static void height_field_from_bmp(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = fwNew();
    char path[] = "test_terrain_heights.bmp";
    for (int topDown = 0; topDown < 2; topDown++) {
        writeBmp(path, topDown);
        MeReal *h = NULL;
        int nx = 0, ny = 0;
        assert_true(McduRGHeighFieldCreateHeightMatrixFromBmp(path, 2, 1, 0, ME_R(-0.5), &h, &nx, &ny));
        assert_int_equal(nx, 3);
        assert_int_equal(ny, 2);
        for (int iy = 0; iy < 2; iy++)
            for (int ix = 0; ix < 3; ix++)
                assert_near(h[iy * 3 + ix], 2 * 50 * ix / 255.0 + 100 * iy / 255.0 - 0.5, ME_TOL(1e-12, 1e-6));
        MeMemoryDestroy(h);
    }
    /* 4 m by 1 m from (-2, 3): vertex (ix, iy) at (-2 + 2 ix, 3 + iy), height (100 ix + 100 iy) / 255 */
    McdRGHeightFieldID f = McduRGHeighFieldCreateFromBmp(fw, path, -2, 3, 4, 1, 2, 1, 0, 0);
    assert_non_null(f);
    MeReal *hp, dx, dy, x0, y0;
    int nx, ny;
    McdRGHeightFieldGetParameters(f, &hp, &nx, &ny, &dx, &dy, &x0, &y0);
    assert_true(nx == 3 && ny == 2 && dx == 2 && dy == 1 && x0 == -2 && y0 == 3);
    MeMatrix4 id;
    MeMatrix4TMMakeIdentity(id);
    McdModelID m = modelAt(f, id);
    McdLineSegIntersectResult r;
    MeVector3 a = {ME_R(1.999), ME_R(3.999), 5}, b = {ME_R(1.999), ME_R(3.999), -5};
    assert_true(McdLineSegIntersect(m, a, b, &r));
    /* cell (1, 0) at (0.9995, 0.999) of its sides: its lower triangle, 100 + 0.9995 100 + 0.999 100 */
    assert_near(r.position[2], 299.85 / 255.0, ME_TOL(1e-9, 1e-5));
    /* refused: a missing file, a file that is not a BMP */
    MeReal *h;
    int ok;
    assert_reports(ME_ERR_MCD_BAD_IMAGE, ok = McduRGHeighFieldCreateHeightMatrixFromBmp("no-such-file.bmp", 1, 1, 1, 0,
                                                                                           &h, &nx, &ny));
    assert_false(ok);
    FILE *bad = fopen(path, "wb");
    fputs("P6 not a bitmap, and long enough to fill the fifty-four bytes of a BMP header.", bad);
    fclose(bad);
    McdRGHeightFieldID g;
    assert_reports(ME_ERR_MCD_BAD_IMAGE, g = McduRGHeighFieldCreateFromBmp(fw, path, 0, 0, 1, 1, 1, 1, 1, 0));
    assert_null(g);
    remove(path);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(creation_and_errors),
        cmocka_unit_test(bvh_query_equals_brute_force),
        cmocka_unit_test(height_field_rays_hit_the_right_triangle),
        cmocka_unit_test(adjacency_marks_internal_edges),
        cmocka_unit_test(sphere_face_edge_vertex),
        cmocka_unit_test(box_face_edge_vertex),
        cmocka_unit_test(convex_box_face_edge_vertex),
        cmocka_unit_test(random_poses_one_triangle),
        cmocka_unit_test(rests_as_on_a_plane),
        cmocka_unit_test(convex_hull_rests_as_the_box),
        cmocka_unit_test(segments_first_hit),
        cmocka_unit_test(triangle_list_flags),
        cmocka_unit_test(height_field_valley_and_ridge),
        cmocka_unit_test(height_field_from_bmp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
