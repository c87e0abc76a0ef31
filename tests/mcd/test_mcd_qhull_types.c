/* Karma 1.2's McdConvexHull (McdQHullTypes.h) and McdConvexMeshCreate: a 1.2 program that computes
 * the arrays (McdComputeHull, or McdComputeHullSizes + McdAllocateHull + McdGetHullData) or fills them
 * by hand and calls McdConvexMeshCreate gets the hull McdConvexMeshCreateHull makes of the same points
 * (same faces as sets of vertices with the same normals, same mass properties). The arrays are
 * checked against every invariant 1.2's header states (sentinels, Euler, closed counter-clockwise
 * rings, reverse edges naming the faces swapped, 1 / length, vertex edges counter-clockwise seen from
 * outside, outward normals agreeing with the winding, every input point inside), and bad arrays are
 * refused with a code and left to the caller. */
#include "karma_test.h"
#include "karma_mcd_fixture.h"

#include <math.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/McdQHullTypes.h>
#include <karma/MeMemory.h>

static McdFrameworkID fw;

static int setup(void **state)
{
    (void)state;
    return karma_mcd_open(&fw, 64, 1);
}

static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void vec(double *o, const MeReal *v)
{
    o[0] = (double)v[0];
    o[1] = (double)v[1];
    o[2] = (double)v[2];
}

static void cross(double *o, const double *a, const double *b)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Every claim of 1.2's McdQHullTypes.h, and every point of pts[n] inside or on the hull (tol, m). */
static void checkInvariants(const McdConvexHull *h, const MeVector3 *pts, int n, double tol)
{
    const int nv = h->numVertex, nf = h->numFace, ne = h->numEdge;
    assert_int_equal(nv - ne / 2 + nf, 2);
    assert_int_equal(h->face[0].firstEdge, 0);
    assert_int_equal(h->face[nf].firstEdge, ne);
    assert_int_equal(h->vertex[0].firstEdgeIndex, 0);
    assert_int_equal(h->vertex[nv].firstEdgeIndex, ne);
    for (int f = 0; f < nf; f++) {
        int s = h->face[f].firstEdge, e = h->face[f + 1].firstEdge;
        double nrm[3], newell[3] = {0, 0, 0}, p0[3];
        vec(nrm, h->face[f].normal);
        vec(p0, h->vertex[h->edge[s].fromVert].position);
        assert_true(e - s >= 3);
        assert_near(sqrt(dot(nrm, nrm)), 1, 1e-5);
        assert_int_equal(McdCnvFaceGetCount(h, f), e - s);
        for (int k = s; k < e; k++) {
            const McdCnvEdge *a = &h->edge[k], *b = &h->edge[k + 1 < e ? k + 1 : s];
            double pa[3], pb[3], d[3];
            assert_int_equal(a->leftFace, f);
            assert_int_equal(a->toVert, b->fromVert);
            assert_ptr_equal(McdCnvFaceGetEdge(h, f, k - s), a);
            assert_int_equal(McdCnvFaceGetVertexId(h, f, k - s), a->fromVert);
            assert_ptr_equal(McdCnvFaceGetVertex(h, f, k - s), &h->vertex[a->fromVert]);
            assert_ptr_equal(McdCnvFaceGetVertexPosition(h, f, k - s), h->vertex[a->fromVert].position);
            vec(pa, h->vertex[a->fromVert].position);
            vec(pb, h->vertex[a->toVert].position);
            for (int j = 0; j < 3; j++)
                d[j] = pb[j] - pa[j];
            assert_rel(a->invLength, 1 / sqrt(dot(d, d)), 1e-5);
            assert_near(dot(nrm, pa), dot(nrm, p0), tol); /* the face is planar */
            newell[0] += (pa[1] - pb[1]) * (pa[2] + pb[2]);
            newell[1] += (pa[2] - pb[2]) * (pa[0] + pb[0]);
            newell[2] += (pa[0] - pb[0]) * (pa[1] + pb[1]);
            /* its reverse exists once and names the faces swapped */
            int reverses = 0;
            for (int i = 0; i < ne; i++)
                if (h->edge[i].fromVert == a->toVert && h->edge[i].toVert == a->fromVert) {
                    reverses++;
                    assert_int_equal(h->edge[i].leftFace, a->rightFace);
                    assert_int_equal(h->edge[i].rightFace, f);
                }
            assert_int_equal(reverses, 1);
        }
        assert_true(dot(newell, nrm) > 0); /* counter-clockwise seen from outside */
        for (int v = 0; v < nv; v++) {     /* outward: no vertex in front */
            double p[3];
            vec(p, h->vertex[v].position);
            assert_true(dot(nrm, p) - dot(nrm, p0) <= tol);
        }
        for (int i = 0; i < n; i++) { /* every input point inside or on */
            double p[3];
            vec(p, pts[i]);
            assert_true(dot(nrm, p) - dot(nrm, p0) <= tol);
        }
    }
    for (int v = 0; v < nv; v++) {
        int s = h->vertex[v].firstEdgeIndex, e = h->vertex[v + 1].firstEdgeIndex;
        double pv[3];
        vec(pv, h->vertex[v].position);
        assert_true(e - s >= 3);
        assert_int_equal(McdCnvVertexGetCount(h, v), e - s);
        for (int i = s; i < e; i++) {
            const McdCnvEdge *a = &h->edge[h->edgeIndex[i]], *b = &h->edge[h->edgeIndex[i + 1 < e ? i + 1 : s]];
            double da[3], db[3], x[3], nrm[3], pa[3], pb[3];
            assert_int_equal(a->fromVert, v);
            assert_int_equal(McdCnvVertexGetEdgeId(h, v, i - s), h->edgeIndex[i]);
            assert_ptr_equal(McdCnvVertexGetEdge(h, v, i - s), a);
            assert_int_equal(McdCnvVertexGetNeighbor(h, v, i - s), a->toVert);
            /* the next edge turns counter-clockwise about the outward normal of the face between them */
            vec(pa, h->vertex[a->toVert].position);
            vec(pb, h->vertex[b->toVert].position);
            for (int j = 0; j < 3; j++) {
                da[j] = pa[j] - pv[j];
                db[j] = pb[j] - pv[j];
            }
            cross(x, da, db);
            vec(nrm, h->face[a->leftFace].normal);
            assert_int_equal(b->rightFace, a->leftFace);
            assert_true(dot(x, nrm) > 0);
        }
    }
}

/* The two meshes have the same faces: each polygon of a has one in b with the same normal and the
 * same vertices (positions within tol), and the same mass properties (relative 1e-5 of the scale). */
static void assertSameMesh(McdConvexMeshID a, McdConvexMeshID b, double tol)
{
    int nf = McdConvexMeshGetPolygonCount(a);
    assert_int_equal(McdConvexMeshGetPolygonCount(b), nf);
    for (int p = 0; p < nf; p++) {
        MeVector3 na, nb;
        int found = 0;
        McdConvexMeshGetPolygonNormal(a, p, na);
        for (int q = 0; q < nf && !found; q++) {
            McdConvexMeshGetPolygonNormal(b, q, nb);
            int m = McdConvexMeshGetPolygonVertexCount(a, p);
            if (fabs((double)MeVector3Dot(na, nb) - 1) > 1e-6 || McdConvexMeshGetPolygonVertexCount(b, q) != m)
                continue;
            int matched = 0;
            for (int i = 0; i < m; i++)
                for (int j = 0; j < m; j++) {
                    MeVector3 d;
                    MeVector3Subtract(d, McdConvexMeshGetPolygonVertexPtr(a, p, i),
                                      McdConvexMeshGetPolygonVertexPtr(b, q, j));
                    matched += MeVector3Magnitude(d) <= tol;
                }
            found = matched == m;
        }
        assert_true(found);
    }
    MeMatrix4 ra, rb;
    MeMatrix3 ia, ib;
    MeReal va, vb;
    assert_int_equal(McdGeometryGetMassProperties(a, ra, ia, &va), 0);
    assert_int_equal(McdGeometryGetMassProperties(b, rb, ib, &vb), 0);
    assert_rel(va, vb, 1e-5);
    for (int i = 0; i < 3; i++) {
        assert_near(ra[3][i], rb[3][i], 1e-5);
        for (int j = 0; j < 3; j++)
            assert_near(ia[i][j], ib[i][j], 1e-5 * fabs((double)ib[0][0]));
    }
}

/* 1.2's tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) filled by hand: faces z=0 (0 2 1), y=0 (0 1 3),
 * x=0 (0 3 2), slanted (1 2 3), each counter-clockwise from outside; edges in that order with the face
 * across each; the edges leaving each vertex counter-clockwise seen from outside. */
static void fillTetrahedron(McdConvexHull *h)
{
    static const int edges[12][4] = {/* from, to, left, right */
                                     {0, 2, 0, 2}, {2, 1, 0, 3}, {1, 0, 0, 1}, {0, 1, 1, 0}, {1, 3, 1, 3}, {3, 0, 1, 2},
                                     {0, 3, 2, 1}, {3, 2, 2, 3}, {2, 0, 2, 0}, {1, 2, 3, 0}, {2, 3, 3, 2}, {3, 1, 3, 1}};
    static const int edgeIndex[12] = {0, 3, 6, 2, 9, 4, 1, 8, 10, 5, 11, 7};
    static const MeReal pos[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const MeReal s = (MeReal)(1 / sqrt(3.0));
    const MeReal normals[4][3] = {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {s, s, s}};
    h->numVertex = 4;
    h->numFace = 4;
    h->numEdge = 12;
    McdAllocateHull(h);
    assert_non_null(h->vertex);
    for (int v = 0; v <= 4; v++) {
        MeVector3Set(h->vertex[v].position, v < 4 ? pos[v][0] : 0, v < 4 ? pos[v][1] : 0, v < 4 ? pos[v][2] : 0);
        h->vertex[v].firstEdgeIndex = 3 * v;
        h->face[v].firstEdge = 3 * v;
        MeVector3Set(h->face[v].normal, v < 4 ? normals[v][0] : 0, v < 4 ? normals[v][1] : 0,
                     v < 4 ? normals[v][2] : 0);
    }
    for (int k = 0; k < 12; k++) {
        McdCnvEdge *e = &h->edge[k];
        MeVector3 d;
        e->fromVert = edges[k][0];
        e->toVert = edges[k][1];
        e->leftFace = edges[k][2];
        e->rightFace = edges[k][3];
        MeVector3Subtract(d, pos[e->toVert], pos[e->fromVert]);
        e->invLength = 1 / MeVector3Magnitude(d);
        h->edgeIndex[k] = edgeIndex[k];
    }
}

/* A polyhedron given as faces (vertex lists, counter-clockwise from outside, -1 ends each) filled in
 * by brute force: normals from the winding (Newell), reverse edges by search, the edges leaving a
 * vertex chained by "the next leaves the left face of the one before". */
static void fillFromFaces(McdConvexHull *h, const MeVector3 *pos, int nv, const int *faces, int nf)
{
    int ne = 0;
    for (int i = 0, f = 0; f < nf; i++)
        ne += faces[i] >= 0, f += faces[i] < 0;
    h->numVertex = nv;
    h->numFace = nf;
    h->numEdge = ne;
    McdAllocateHull(h);
    assert_non_null(h->edge);
    for (int v = 0; v <= nv; v++)
        MeVector3Set(h->vertex[v].position, v < nv ? pos[v][0] : 0, v < nv ? pos[v][1] : 0, v < nv ? pos[v][2] : 0);
    int k = 0, i = 0;
    for (int f = 0; f < nf; f++, i++) {
        int s = i;
        h->face[f].firstEdge = k;
        double newell[3] = {0, 0, 0};
        for (; faces[i] >= 0; i++, k++) {
            int a = faces[i], b = faces[i + 1] >= 0 ? faces[i + 1] : faces[s];
            MeVector3 d;
            h->edge[k].fromVert = a;
            h->edge[k].toVert = b;
            h->edge[k].leftFace = f;
            MeVector3Subtract(d, pos[b], pos[a]);
            h->edge[k].invLength = 1 / MeVector3Magnitude(d);
            newell[0] += ((double)pos[a][1] - pos[b][1]) * ((double)pos[a][2] + pos[b][2]);
            newell[1] += ((double)pos[a][2] - pos[b][2]) * ((double)pos[a][0] + pos[b][0]);
            newell[2] += ((double)pos[a][0] - pos[b][0]) * ((double)pos[a][1] + pos[b][1]);
        }
        double len = sqrt(dot(newell, newell));
        MeVector3Set(h->face[f].normal, (MeReal)(newell[0] / len), (MeReal)(newell[1] / len), (MeReal)(newell[2] / len));
    }
    h->face[nf].firstEdge = ne;
    for (int e = 0; e < ne; e++)
        for (int r = 0; r < ne; r++)
            if (h->edge[r].fromVert == h->edge[e].toVert && h->edge[r].toVert == h->edge[e].fromVert)
                h->edge[e].rightFace = h->edge[r].leftFace;
    int slot = 0;
    for (int v = 0; v < nv; v++) {
        int first = -1;
        h->vertex[v].firstEdgeIndex = slot;
        for (int e = 0; e < ne && first < 0; e++)
            if (h->edge[e].fromVert == v)
                first = e;
        int e = first;
        do {
            h->edgeIndex[slot++] = e;
            int next = -1;
            for (int r = 0; r < ne; r++)
                if (h->edge[r].fromVert == v && h->edge[r].rightFace == h->edge[e].leftFace)
                    next = r;
            e = next;
        } while (e != first && e >= 0);
    }
    h->vertex[nv].firstEdgeIndex = slot;
    assert_int_equal(slot, ne);
}

static void literal_tetrahedron_is_the_hull_of_its_points(void **state)
{
    (void)state;
    McdConvexHull h;
    const MeVector3 pts[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    fillTetrahedron(&h);
    checkInvariants(&h, pts, 4, 1e-6);
    McdCnvEdge *edgeArray = h.edge;
    McdConvexMeshID byArrays = McdConvexMeshCreate(fw, &h, 0);
    McdConvexMeshID byPoints = McdConvexMeshCreateHull(fw, pts, 4, 0);
    assert_non_null(byArrays);
    assert_non_null(byPoints);
    /* the mesh kept the arrays (1.2's shallow copy) and gives them back */
    const McdConvexHull *kept = McdConvexMeshGetPolyhedron(byArrays);
    assert_non_null(kept);
    assert_ptr_equal(kept->edge, edgeArray);
    assert_int_equal(McdConvexMeshGetPolygonCount(byArrays), 4);
    assert_int_equal(McdConvexMeshGetPolygonVertexCount(byArrays, 3), 3);
    MeVector3 v;
    McdConvexMeshGetPolygonVertex(byArrays, 0, 1, v); /* face 0's second vertex: vertex 2 */
    assert_true(v[0] == 0 && v[1] == 1 && v[2] == 0);
    assertSameMesh(byArrays, byPoints, 1e-6);
    /* closed forms: volume 1/6, centre of mass (1/4, 1/4, 1/4) */
    MeMatrix4 rel;
    MeMatrix3 inertia;
    MeReal volume;
    McdGeometryGetMassProperties(byArrays, rel, inertia, &volume);
    assert_near(volume, 1.0 / 6, 1e-6);
    for (int i = 0; i < 3; i++)
        assert_near(rel[3][i], 0.25, 1e-6);
    /* McdComputeHull of the same points: the same arrays up to numbering */
    McdConvexHull computed;
    assert_int_equal(McdComputeHull(&computed, 4, pts), 1);
    checkInvariants(&computed, pts, 4, 1e-6);
    McdConvexMeshID byComputed = McdConvexMeshCreate(fw, &computed, 0);
    assert_non_null(byComputed);
    assertSameMesh(byComputed, byPoints, 1e-6);
    McdConvexMeshDestroy(byArrays); /* frees the arrays: asan sees a leak or a double free otherwise */
    McdConvexMeshDestroy(byPoints);
    McdConvexMeshDestroy(byComputed);
}

static unsigned rngState = 12345u;
static double rnd(void)
{
    rngState = rngState * 1103515245u + 12345u;
    return (double)((rngState >> 8) & 0xffffff) / 16777216.0;
}

/* A cloud: n points on the unit sphere plus n / 2 inside, or a cube with its face centres, edge
 * midpoints and interior points (coplanar points that must merge away). */
static int makeCloud(MeVector3 *p, int n, int kind)
{
    int m = 0;
    if (kind == 0) {
        for (int i = 0; i < n; i++) {
            double u = 2 * rnd() - 1, t = 2 * 3.14159265358979 * rnd(), r = sqrt(1 - u * u);
            MeVector3Set(p[m++], (MeReal)(r * cos(t)), (MeReal)(r * sin(t)), (MeReal)u);
        }
        for (int i = 0; i < n / 2; i++)
            MeVector3Set(p[m++], (MeReal)(0.5 * rnd() - 0.25), (MeReal)(0.5 * rnd() - 0.25), (MeReal)(0.5 * rnd() - 0.25));
        return m;
    }
    for (int x = 0; x < 3; x++)
        for (int y = 0; y < 3; y++)
            for (int z = 0; z < 3; z++)
                MeVector3Set(p[m++], (MeReal)(0.5 * x - 0.5), (MeReal)(y - 1), (MeReal)(2 * z - 2));
    return m;
}

/* Field by field (the structs' padding is not part of the data). */
static void assertSameArrays(const McdConvexHull *a, const McdConvexHull *b)
{
    for (int v = 0; v <= b->numVertex; v++) {
        assert_memory_equal(a->vertex[v].position, b->vertex[v].position, sizeof(MeVector3));
        assert_int_equal(a->vertex[v].firstEdgeIndex, b->vertex[v].firstEdgeIndex);
    }
    for (int f = 0; f <= b->numFace; f++) {
        assert_memory_equal(a->face[f].normal, b->face[f].normal, sizeof(MeVector3));
        assert_int_equal(a->face[f].firstEdge, b->face[f].firstEdge);
    }
    for (int k = 0; k < b->numEdge; k++) {
        assert_true(a->edge[k].invLength == b->edge[k].invLength);
        assert_int_equal(a->edge[k].fromVert, b->edge[k].fromVert);
        assert_int_equal(a->edge[k].toVert, b->edge[k].toVert);
        assert_int_equal(a->edge[k].leftFace, b->edge[k].leftFace);
        assert_int_equal(a->edge[k].rightFace, b->edge[k].rightFace);
        assert_int_equal(a->edgeIndex[k], b->edgeIndex[k]);
    }
}

static void computed_hulls_give_the_mesh_of_their_points(void **state)
{
    (void)state;
    static MeVector3 pts[600];
    for (int trial = 0; trial < 8; trial++) {
        int kind = trial % 2, n = makeCloud(pts, 40 + 50 * trial, kind);
        MeReal fat = trial % 3 == 0 ? ME_R(0.05) : 0;
        /* one step */
        McdConvexHull one;
        assert_int_equal(McdComputeHull(&one, n, (const MeVector3 *)pts), 1);
        checkInvariants(&one, (const MeVector3 *)pts, n, 1e-4); /* the build merges within 1e-5 of 3.5 m */
        if (kind == 1) { /* the box merged: 8 corners, 6 quadrilaterals */
            assert_int_equal(one.numVertex, 8);
            assert_int_equal(one.numFace, 6);
            assert_int_equal(one.numEdge, 24);
        }
        /* two steps, into arrays of the caller's */
        McdConvexHull two;
        memset(&two, 0, sizeof two);
        assert_int_equal(McdComputeHullSizes(&two, n, (const MeVector3 *)pts), 1);
        assert_int_equal(two.numVertex, one.numVertex);
        assert_int_equal(two.numFace, one.numFace);
        assert_int_equal(two.numEdge, one.numEdge);
        McdAllocateHull(&two);
        assert_int_equal(McdGetHullData(&two), 1);
        assertSameArrays(&two, &one);
        McdDeallocateHull(&two);
        assert_null(two.vertex);
        McdConvexMeshID byArrays = McdConvexMeshCreate(fw, &one, fat);
        McdConvexMeshID byPoints = McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, n, fat);
        assert_non_null(byArrays);
        assert_non_null(byPoints);
        assert_rel(McdConvexMeshGetFatness(byArrays), fat, 0);
        assertSameMesh(byArrays, byPoints, 1e-6);
        /* the points mesh's own arrays pass the same checks, numbered as its accessors */
        const McdConvexHull *own = McdConvexMeshGetPolyhedron(byPoints);
        checkInvariants(own, (const MeVector3 *)pts, n, 1e-4);
        assert_int_equal(own->numFace, McdConvexMeshGetPolygonCount(byPoints));
        for (int f = 0; f < own->numFace; f++)
            for (int i = 0; i < McdCnvFaceGetCount(own, f); i++)
                assert_ptr_equal(McdCnvFaceGetVertexPosition(own, f, i), McdConvexMeshGetPolygonVertexPtr(byPoints, f, i));
        /* the same AABB at a pose */
        MeMatrix4 tm;
        MeVector3 lo1, hi1, lo2, hi2;
        MeMatrix3 r;
        MeMatrix3FromEulerAngles(r, ME_R(0.3), ME_R(-0.2), ME_R(0.7));
        MeMatrix4TMMakeFromRotationAndPosition(tm, r, 1, 2, 3);
        McdGeometryGetAABB(byArrays, tm, lo1, hi1);
        McdGeometryGetAABB(byPoints, tm, lo2, hi2);
        for (int j = 0; j < 3; j++) {
            assert_near(lo1[j], lo2[j], 1e-5);
            assert_near(hi1[j], hi2[j], 1e-5);
        }
        McdConvexMeshDestroy(byArrays);
        McdConvexMeshDestroy(byPoints);
    }
}

/* A cloud whose hull has a T-junction (found by fuzz_pairs): point 4 lies within the build's tolerance
 * of the edge between points 5 and 1, so the merged face holds it and the face across that edge does
 * not. 1.2's arrays hold the corners only (point 4 dropped, six corners): both paths build them, they
 * satisfy 1.2's claims, and the mesh from them is the mesh from the points. */
static void a_point_on_a_neighbours_edge_is_not_a_corner(void **state)
{
    (void)state;
    static const MeVector3 pts[7] = {
        {ME_R(0.872898188), ME_R(0.875652938), ME_R(-0.89042875)},
        {ME_R(-0.641021312), ME_R(-0.911771562), ME_R(-0.911799375)},
        {ME_R(-0.911799375), ME_R(-0.064097957), ME_R(-0.282785125)},
        {ME_R(0.187980797), ME_R(0.18951125), ME_R(0.876042562)},
        {ME_R(-0.89042875), ME_R(-0.911799375), ME_R(-0.911799375)},
        {ME_R(-0.911799375), ME_R(-0.911799375), ME_R(-0.911799375)},
        {ME_R(-0.907096750), ME_R(0.370438062), ME_R(-0.911799375)}};
    McdConvexHull one;
    assert_int_equal(McdComputeHull(&one, 7, pts), 1);
    checkInvariants(&one, pts, 7, 1e-4);
    assert_int_equal(one.numVertex, 6); /* point 4 is not a corner */
    McdConvexHull two;
    memset(&two, 0, sizeof two);
    assert_int_equal(McdComputeHullSizes(&two, 7, pts), 1);
    McdAllocateHull(&two);
    assert_int_equal(McdGetHullData(&two), 1);
    assertSameArrays(&two, &one);
    McdDeallocateHull(&two);
    McdConvexMeshID byPoints = McdConvexMeshCreateHull(fw, pts, 7, 0);
    McdConvexMeshID byArrays = McdConvexMeshCreate(fw, &one, 0);
    assert_non_null(byPoints);
    assert_non_null(byArrays);
    checkInvariants(McdConvexMeshGetPolyhedron(byPoints), pts, 7, 1e-4);
    assertSameMesh(byArrays, byPoints, 1e-6);
    McdConvexMeshDestroy(byArrays);
    McdConvexMeshDestroy(byPoints);
}

static void hand_filled_bipyramid_and_its_dented_twin(void **state)
{
    (void)state;
    const double c = cos(2 * 3.14159265358979 / 3), s = sin(2 * 3.14159265358979 / 3);
    MeVector3 pos[5] = {{1, 0, 0}, {(MeReal)c, (MeReal)s, 0}, {(MeReal)c, (MeReal)-s, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int faces[] = {0, 1, 3, -1, 1, 2, 3, -1, 2, 0, 3, -1, 1, 0, 4, -1, 2, 1, 4, -1, 0, 2, 4, -1};
    McdConvexHull h;
    fillFromFaces(&h, (const MeVector3 *)pos, 5, faces, 6);
    checkInvariants(&h, (const MeVector3 *)pos, 5, 1e-6);
    McdConvexMeshID byArrays = McdConvexMeshCreate(fw, &h, 0);
    McdConvexMeshID byPoints = McdConvexMeshCreateHull(fw, (const MeVector3 *)pos, 5, 0);
    assert_non_null(byArrays);
    assertSameMesh(byArrays, byPoints, 1e-6);
    MeMatrix4 rel;
    MeMatrix3 inertia;
    MeReal volume;
    McdGeometryGetMassProperties(byArrays, rel, inertia, &volume);
    assert_near(volume, 2.0 / 3 * (3 * sqrt(3.0) / 4), 1e-6); /* two pyramids on the unit triangle */
    McdConvexMeshDestroy(byArrays);
    McdConvexMeshDestroy(byPoints);
    /* the lower apex pushed up inside: a consistent closed surface, wound right, but dented */
    karma_capture_messages();
    MeVector3Set(pos[4], 0, 0, ME_R(0.3));
    fillFromFaces(&h, (const MeVector3 *)pos, 5, faces, 6);
    assert_reports(ME_ERR_MCD_HULL_NOT_CONVEX, assert_null(McdConvexMeshCreate(fw, &h, 0)));
    McdDeallocateHull(&h); /* refused: the arrays are still the caller's */
}

/* Corrupt a fresh tetrahedron by `how` and expect `code`. */
typedef void (*Corrupt)(McdConvexHull *h);
static void oddEdgeCount(McdConvexHull *h) { h->numEdge = 11; }
static void eulerBroken(McdConvexHull *h) { h->numFace = 5; }
static void sentinelWrong(McdConvexHull *h) { h->face[4].firstEdge = 11; }
static void vertexOutOfRange(McdConvexHull *h) { h->edge[4].toVert = 7; }
static void ringBroken(McdConvexHull *h) { h->edge[0].toVert = 3; }
static void leftFaceWrong(McdConvexHull *h) { h->edge[5].leftFace = 2; }
static void rightFaceWrong(McdConvexHull *h) { h->edge[1].rightFace = 2; }
static void vertexEdgesClockwise(McdConvexHull *h)
{
    h->edgeIndex[1] = 6;
    h->edgeIndex[2] = 3;
}
static void edgeIndexWrongVertex(McdConvexHull *h) { h->edgeIndex[0] = 2; }
static void invLengthWrong(McdConvexHull *h) { h->edge[9].invLength = 1; }
static void positionNaN(McdConvexHull *h) { h->vertex[2].position[1] = (MeReal)NAN; }
static void normalNaN(McdConvexHull *h) { h->face[1].normal[0] = (MeReal)NAN; }
static void invLengthInfinite(McdConvexHull *h) { h->edge[3].invLength = (MeReal)INFINITY; }
static void normalFlipped(McdConvexHull *h) { MeVector3Scale(h->face[3].normal, -1); }
static void normalNotUnit(McdConvexHull *h) { MeVector3Scale(h->face[0].normal, 2); }
static void normalTilted(McdConvexHull *h) { MeVector3Set(h->face[0].normal, ME_R(0.6), 0, ME_R(-0.8)); }
static void vertexOffItsFace(McdConvexHull *h) { h->face[3].normal[0] = -h->face[3].normal[0]; }
static void edgeArrayNull(McdConvexHull *h)
{
    MeMemoryDestroy(h->edge);
    h->edge = NULL;
}

static void bad_arrays_are_refused_and_left_to_the_caller(void **state)
{
    (void)state;
    static const struct {
        Corrupt how;
        MeErrorCode code;
    } cases[] = {
        {oddEdgeCount, ME_ERR_MCD_HULL_INCONSISTENT},   {eulerBroken, ME_ERR_MCD_HULL_INCONSISTENT},
        {sentinelWrong, ME_ERR_MCD_HULL_INCONSISTENT},  {vertexOutOfRange, ME_ERR_MCD_HULL_INCONSISTENT},
        {ringBroken, ME_ERR_MCD_HULL_INCONSISTENT},     {leftFaceWrong, ME_ERR_MCD_HULL_INCONSISTENT},
        {rightFaceWrong, ME_ERR_MCD_HULL_INCONSISTENT}, {vertexEdgesClockwise, ME_ERR_MCD_HULL_INCONSISTENT},
        {edgeIndexWrongVertex, ME_ERR_MCD_HULL_INCONSISTENT}, {invLengthWrong, ME_ERR_MCD_HULL_INCONSISTENT},
        {positionNaN, ME_ERR_NONFINITE_ARGUMENT},       {normalNaN, ME_ERR_NONFINITE_ARGUMENT},
        {invLengthInfinite, ME_ERR_NONFINITE_ARGUMENT}, {normalFlipped, ME_ERR_MCD_HULL_NOT_CONVEX},
        {normalNotUnit, ME_ERR_MCD_HULL_NOT_CONVEX},    {normalTilted, ME_ERR_MCD_HULL_NOT_CONVEX},
        {vertexOffItsFace, ME_ERR_MCD_HULL_NOT_CONVEX}, {edgeArrayNull, ME_ERR_NULL_ARGUMENT},
    };
    karma_capture_messages();
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        McdConvexHull h, before;
        fillTetrahedron(&h);
        /* the fill is accepted as it is: each case's one change is what is refused */
        cases[i].how(&h);
        before = h;
        assert_reports(cases[i].code, assert_null(McdConvexMeshCreate(fw, &h, 0)));
        assert_memory_equal(&h, &before, sizeof h);
        McdDeallocateHull(&h);
    }
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(McdConvexMeshCreate(fw, NULL, 0)));
    /* a negative fatness, a hull too small for the framework: refused, arrays kept */
    McdConvexHull h;
    fillTetrahedron(&h);
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdConvexMeshCreate(fw, &h, -1)));
    for (int v = 0; v < 4; v++)
        MeVector3Scale(h.vertex[v].position, ME_R(1e-7));
    for (int k = 0; k < 12; k++)
        h.edge[k].invLength *= ME_R(1e7);
    assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(McdConvexMeshCreate(fw, &h, 0)));
    McdDeallocateHull(&h);
    /* a flat set: every point in z = 0 cannot be wound both ways, the upper face is against its winding */
    fillTetrahedron(&h);
    h.vertex[3].position[2] = 0;
    h.vertex[3].position[0] = ME_R(0.3);
    h.vertex[3].position[1] = ME_R(0.3);
    for (int k = 0; k < 12; k++) {
        MeVector3 d;
        MeVector3Subtract(d, h.vertex[h.edge[k].toVert].position, h.vertex[h.edge[k].fromVert].position);
        h.edge[k].invLength = 1 / MeVector3Magnitude(d);
    }
    assert_reports(ME_ERR_MCD_HULL_NOT_CONVEX, assert_null(McdConvexMeshCreate(fw, &h, 0)));
    McdDeallocateHull(&h);
    /* the tetrahedron unchanged is accepted (so the cases above fail for their change alone) */
    fillTetrahedron(&h);
    McdConvexMeshID g = McdConvexMeshCreate(fw, &h, 0);
    assert_non_null(g);
    McdConvexMeshDestroy(g);
}

static void computing_and_accessors_refuse_bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    McdConvexHull h;
    memset(&h, 0, sizeof h);
    const MeVector3 pts[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {(MeReal)NAN, 0, 0}};
    const MeVector3 flat[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdComputeHull(NULL, 4, pts), 0));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdComputeHull(&h, 4, NULL), 0));
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_int_equal(McdComputeHull(&h, 3, pts), 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, assert_int_equal(McdComputeHull(&h, 5, pts), 0));
    assert_reports(ME_ERR_MCD_HULL_FLAT, assert_int_equal(McdComputeHull(&h, 4, flat), 0));
    assert_null(h.vertex); /* untouched */
    /* the two steps out of order or with the wrong counts */
    McdConvexHull t;
    t.numVertex = 4;
    t.numFace = 4;
    t.numEdge = 12;
    McdAllocateHull(&t);
    assert_reports(ME_ERR_BAD_STATE, assert_int_equal(McdGetHullData(&t), 0)); /* nothing waits */
    assert_int_equal(McdComputeHullSizes(&h, 4, pts), 1);
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdGetHullData(&h), 0));
    h.numFace = 3;
    McdAllocateHull(&h);
    assert_reports(ME_ERR_MCD_HULL_INCONSISTENT, assert_int_equal(McdGetHullData(&h), 0));
    McdDeallocateHull(&h);
    assert_int_equal(McdGetHullData(&t), 1); /* the refusals left the hull waiting */
    assert_reports(ME_ERR_BAD_STATE, assert_int_equal(McdGetHullData(&t), 0)); /* taken once */
    h = t;
    /* accessors out of range */
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(McdCnvFaceGetCount(&h, 4), 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdCnvFaceGetEdge(&h, 0, 3)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(McdCnvFaceGetVertexId(&h, -1, 0), -1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdCnvFaceGetVertex(&h, 0, -1)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdCnvFaceGetVertexPosition(&h, 9, 0)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(McdCnvVertexGetCount(&h, 4), 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(McdCnvVertexGetEdgeId(&h, 0, 3), -1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdCnvVertexGetEdge(&h, 0, 5)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(McdCnvVertexGetNeighbor(&h, -2, 0), -1));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdCnvFaceGetCount(NULL, 0), 0));
    McdDeallocateHull(&h);
    McdDeallocateHull(NULL);
    h.numVertex = -1;
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdAllocateHull(&h));
    assert_null(h.vertex);
    /* GetPolyhedron of another type */
    McdGeometryID sphere = McdSphereCreate(fw, 1);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, assert_null(McdConvexMeshGetPolyhedron(sphere)));
    McdGeometryDestroy(sphere);
}

static void triangle_hull(void **state)
{
    (void)state;
    McdConvexHull h;
    h.numVertex = 3;
    h.numFace = 1;
    h.numEdge = 3;
    McdAllocateHull(&h);
    const MeVector3 p[3] = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    McdGetTriangleHull(&h, p[0], p[1], p[2]);
    assert_true(h.face[0].normal[2] == 1);
    assert_int_equal(h.face[1].firstEdge, 3);
    assert_int_equal(h.vertex[3].firstEdgeIndex, 3);
    for (int k = 0; k < 3; k++) {
        assert_int_equal(h.edge[k].toVert, h.edge[(k + 1) % 3].fromVert);
        assert_int_equal(McdCnvVertexGetNeighbor(&h, k, 0), (k + 1) % 3);
    }
    assert_rel(h.edge[0].invLength, 0.5, 1e-6);
    assert_rel(h.edge[1].invLength, 1 / sqrt(5.0), 1e-6);
    /* no volume: not a convex mesh */
    karma_capture_messages();
    assert_reports(ME_ERR_MCD_HULL_INCONSISTENT, assert_null(McdConvexMeshCreate(fw, &h, ME_R(0.1))));
    McdDeallocateHull(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(literal_tetrahedron_is_the_hull_of_its_points),
        cmocka_unit_test(computed_hulls_give_the_mesh_of_their_points),
        cmocka_unit_test(a_point_on_a_neighbours_edge_is_not_a_corner),
        cmocka_unit_test(hand_filled_bipyramid_and_its_dented_twin),
        cmocka_unit_test(bad_arrays_are_refused_and_left_to_the_caller),
        cmocka_unit_test(computing_and_accessors_refuse_bad_input),
        cmocka_unit_test(triangle_hull),
    };
    return cmocka_run_group_tests(tests, setup, karma_mcd_close);
}
