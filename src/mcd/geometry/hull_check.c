/* hull_check.c -- is a handed-in McdConvexHull a closed, consistently wound, convex polyhedron?
 * (McdConvexMeshCreate trusts nothing it is given: 1.2 took the arrays as they came.)
 *
 * First the combinatorics (counts, sentinels, indices, rings, reverse edges, vertex order), so the
 * geometry checks after them can follow every index; then the numbers (finite, inverse lengths),
 * then convexity within MCD_HULL_CHECK_REL_TOL. A closed surface whose faces all support the set of
 * its vertices and agree with their winding is the boundary of their hull. */
#include <math.h>

#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "hull_arrays.h"

#define INCONSISTENT(...)                                                                           \
    do {                                                                                            \
        ME_REPORT_IN(function, ME_ERR_MCD_HULL_INCONSISTENT, __VA_ARGS__);                          \
        return MEFALSE;                                                                             \
    } while (0)

#define NOT_CONVEX(...)                                                                             \
    do {                                                                                            \
        ME_REPORT_IN(function, ME_ERR_MCD_HULL_NOT_CONVEX, __VA_ARGS__);                            \
        return MEFALSE;                                                                             \
    } while (0)

static MeBool checkCounts(const McdConvexHull *c, const char *function)
{
    int nv = c->numVertex, nf = c->numFace, ne = c->numEdge;
    if (nv < 4 || nf < 4 || ne < 12 || ne % 2 != 0)
        INCONSISTENT("numVertex %d, numFace %d, numEdge %d: a polyhedron has at least 4 vertices, 4 faces and 12 "
                     "directed edges (an even number); call ignored", nv, nf, ne);
    if (nv - ne / 2 + nf != 2)
        INCONSISTENT("numVertex - numEdge / 2 + numFace is %d, not 2 (Euler): not a closed convex polyhedron; "
                     "call ignored", nv - ne / 2 + nf);
    if (c->face[0].firstEdge != 0 || c->face[nf].firstEdge != ne || c->vertex[0].firstEdgeIndex != 0 ||
        c->vertex[nv].firstEdgeIndex != ne)
        INCONSISTENT("face[0].firstEdge and vertex[0].firstEdgeIndex must be 0, the sentinels face[numFace] and "
                     "vertex[numVertex] numEdge (%d); call ignored", ne);
    for (int f = 0; f < nf; f++)
        if (c->face[f + 1].firstEdge - c->face[f].firstEdge < 3)
            INCONSISTENT("face %d has %d edges (firstEdge must rise by at least 3 a face); call ignored", f,
                         c->face[f + 1].firstEdge - c->face[f].firstEdge);
    for (int v = 0; v < nv; v++)
        if (c->vertex[v + 1].firstEdgeIndex - c->vertex[v].firstEdgeIndex < 3)
            INCONSISTENT("vertex %d has %d edges (firstEdgeIndex must rise by at least 3 a vertex); call ignored",
                         v, c->vertex[v + 1].firstEdgeIndex - c->vertex[v].firstEdgeIndex);
    return METRUE;
}

/* Each face's edges: in range, left face the face, a closed ring. */
static MeBool checkRings(const McdConvexHull *c, const char *function)
{
    for (int f = 0; f < c->numFace; f++) {
        int s = c->face[f].firstEdge, e = c->face[f + 1].firstEdge;
        for (int k = s; k < e; k++) {
            const McdCnvEdge *a = &c->edge[k], *b = &c->edge[k + 1 < e ? k + 1 : s];
            if (a->fromVert < 0 || a->fromVert >= c->numVertex || a->toVert < 0 || a->toVert >= c->numVertex ||
                a->fromVert == a->toVert || a->rightFace < 0 || a->rightFace >= c->numFace || a->rightFace == f)
                INCONSISTENT("edge %d (vertices %d -> %d, right face %d) has an index out of range or repeated; "
                             "call ignored", k, a->fromVert, a->toVert, a->rightFace);
            if (a->leftFace != f)
                INCONSISTENT("edge %d lies in face %d's range but its leftFace is %d; call ignored", k, f, a->leftFace);
            if (a->toVert != b->fromVert)
                INCONSISTENT("face %d's ring breaks after edge %d (it ends at vertex %d, the next starts at %d); "
                             "call ignored", f, k, a->toVert, b->fromVert);
        }
    }
    return METRUE;
}

/* edgeIndex: each edge once, under its start vertex; every edge has exactly one reverse, naming the
 * same two faces swapped; around a vertex each edge's right face is the previous edge's left face. */
static MeBool checkVertexEdges(const McdConvexHull *c, int *seen, const char *function)
{
    for (int k = 0; k < c->numEdge; k++)
        seen[k] = 0;
    for (int v = 0; v < c->numVertex; v++) {
        int s = c->vertex[v].firstEdgeIndex, e = c->vertex[v + 1].firstEdgeIndex;
        for (int i = s; i < e; i++) {
            int id = c->edgeIndex[i];
            if (id < 0 || id >= c->numEdge || seen[id]++ || c->edge[id].fromVert != v)
                INCONSISTENT("edgeIndex[%d] (%d) is out of range, listed twice or does not start at vertex %d; "
                             "call ignored", i, id, v);
            int next = c->edgeIndex[i + 1 < e ? i + 1 : s];
            if (next >= 0 && next < c->numEdge && c->edge[next].rightFace != c->edge[id].leftFace)
                INCONSISTENT("around vertex %d, edge %d follows edge %d but its right face (%d) is not the left "
                             "face of the one before (%d): not counter-clockwise; call ignored", v, next, id,
                             c->edge[next].rightFace, c->edge[id].leftFace);
        }
    }
    for (int k = 0; k < c->numEdge; k++) {
        const McdCnvEdge *a = &c->edge[k];
        int reverses = 0, back = -1, to = a->toVert;
        for (int i = c->vertex[to].firstEdgeIndex; i < c->vertex[to + 1].firstEdgeIndex; i++)
            if (c->edge[c->edgeIndex[i]].toVert == a->fromVert) {
                reverses++;
                back = c->edgeIndex[i];
            }
        if (reverses != 1)
            INCONSISTENT("edge %d (%d -> %d) has %d reverse edges, not 1; call ignored", k, a->fromVert, to, reverses);
        if (c->edge[back].leftFace != a->rightFace || c->edge[back].rightFace != a->leftFace)
            INCONSISTENT("edge %d and its reverse %d do not name the same two faces swapped; call ignored", k, back);
    }
    return METRUE;
}

static MeBool checkNumbers(const McdConvexHull *c, const char *function)
{
    for (int v = 0; v < c->numVertex; v++)
        if (!MeVector3IsValid(c->vertex[v].position)) {
            ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "vertex %d's position holds NaN or infinity; call "
                         "ignored", v);
            return MEFALSE;
        }
    for (int f = 0; f < c->numFace; f++)
        if (!MeVector3IsValid(c->face[f].normal)) {
            ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "face %d's normal holds NaN or infinity; call ignored", f);
            return MEFALSE;
        }
    for (int k = 0; k < c->numEdge; k++) {
        const McdCnvEdge *a = &c->edge[k];
        MeVector3 d;
        MeVector3Subtract(d, c->vertex[a->toVert].position, c->vertex[a->fromVert].position);
        double want = 1 / (double)MeVector3Magnitude(d);
        if (!isfinite((double)a->invLength)) {
            ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "edge %d's invLength is NaN or infinite; call ignored", k);
            return MEFALSE;
        }
        if (!(fabs((double)a->invLength - want) <= 1e-3 * want))
            INCONSISTENT("edge %d's invLength is %g, not 1 / its length (%g); call ignored", k, (double)a->invLength,
                         want);
    }
    return METRUE;
}

static void toDouble(double out[3], const MeReal *v)
{
    for (int j = 0; j < 3; j++)
        out[j] = (double)v[j];
}

static double dotD(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Each face: unit normal agreeing with its winding (Newell), its vertices within tol of its plane and
 * turning left (seen from outside), no vertex more than tol in front of it. */
static MeBool checkConvex(const McdConvexHull *c, double tol, const char *function)
{
    for (int f = 0; f < c->numFace; f++) {
        int s = c->face[f].firstEdge, e = c->face[f + 1].firstEdge;
        double n[3], newell[3] = {0, 0, 0}, offset = 0;
        toDouble(n, c->face[f].normal);
        double len = sqrt(dotD(n, n));
        if (!(fabs(len - 1) <= 1e-3))
            NOT_CONVEX("face %d's normal has length %g, not 1; call ignored", f, len);
        for (int k = s; k < e; k++) {
            double a[3], b[3];
            toDouble(a, c->vertex[c->edge[k].fromVert].position);
            toDouble(b, c->vertex[c->edge[k].toVert].position);
            newell[0] += (a[1] - b[1]) * (a[2] + b[2]);
            newell[1] += (a[2] - b[2]) * (a[0] + b[0]);
            newell[2] += (a[0] - b[0]) * (a[1] + b[1]);
            offset += dotD(n, a) / (e - s);
        }
        if (!(dotD(newell, n) > 0))
            NOT_CONVEX("face %d's normal points against its winding (its edges must run counter-clockwise seen from "
                       "outside); call ignored", f);
        for (int k = s; k < e; k++) {
            const McdCnvEdge *a = &c->edge[k], *b = &c->edge[k + 1 < e ? k + 1 : s];
            double p[3], q[3], r[3], u[3], w[3], x[3];
            toDouble(p, c->vertex[a->fromVert].position);
            toDouble(q, c->vertex[a->toVert].position);
            toDouble(r, c->vertex[b->toVert].position);
            for (int j = 0; j < 3; j++) {
                u[j] = q[j] - p[j];
                w[j] = r[j] - q[j];
            }
            x[0] = u[1] * w[2] - u[2] * w[1];
            x[1] = u[2] * w[0] - u[0] * w[2];
            x[2] = u[0] * w[1] - u[1] * w[0];
            if (fabs(dotD(n, p) - offset) > tol)
                NOT_CONVEX("vertex %d lies %g off face %d's plane (tolerance %g); call ignored", a->fromVert,
                           dotD(n, p) - offset, f, tol);
            if (dotD(x, n) < -tol * sqrt(dotD(u, u)))
                NOT_CONVEX("face %d turns clockwise at vertex %d: a reflex corner; call ignored", f, a->toVert);
        }
        for (int v = 0; v < c->numVertex; v++) {
            double p[3];
            toDouble(p, c->vertex[v].position);
            if (dotD(n, p) - offset > tol)
                NOT_CONVEX("vertex %d lies %g in front of face %d (tolerance %g): not convex; call ignored", v,
                           dotD(n, p) - offset, f, tol);
        }
    }
    return METRUE;
}

MeBool McdConvexHullCheck(const McdConvexHull *c, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, c, MEFALSE);
    if (!c->vertex || !c->face || !c->edge || !c->edgeIndex) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "an array of the hull (vertex, face, edge or edgeIndex) is NULL; "
                     "call ignored");
        return MEFALSE;
    }
    if (c->numVertex < 0 || c->numFace < 0 || c->numEdge < 0)
        INCONSISTENT("a count is negative; call ignored");
    if (!checkCounts(c, function) || !checkRings(c, function))
        return MEFALSE;
    int *seen = MeMemoryCreate((size_t)c->numEdge * sizeof(int));
    MeBool ok = seen && checkVertexEdges(c, seen, function);
    MeMemoryDestroy(seen);
    if (!ok || !checkNumbers(c, function))
        return MEFALSE;
    MeVector3 *points = McdConvexHullPositions(c);
    if (!points)
        return MEFALSE;
    double tol = McdHullTolerance((const MeVector3 *)points, c->numVertex) / MCD_HULL_REL_TOL * MCD_HULL_CHECK_REL_TOL;
    MeMemoryDestroy(points);
    return checkConvex(c, tol, function);
}
