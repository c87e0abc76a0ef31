/* hull_arrays.c -- Karma 1.2's McdConvexHull: made from a built hull's polygons (McdComputeHull and
 * its two-step form), freed, and read through 1.2's accessors. */
#include <stdatomic.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "hull_arrays.h"

MeBool McdHullCheckPoints(const MeVector3 *points, int n, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, points, MEFALSE);
    if (n < 4) {
        ME_REPORT_IN(function, ME_ERR_MCD_HULL_FLAT, "%d points (at least 4 needed); call ignored", n);
        return MEFALSE;
    }
    for (int i = 0; i < n; i++)
        if (!MeVector3IsValid(points[i])) {
            ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "point %d holds NaN or infinity; call ignored", i);
            return MEFALSE;
        }
    return METRUE;
}

MeVector3 *McdConvexHullPositions(const McdConvexHull *cnv)
{
    MeVector3 *points = MeMemoryCreate((size_t)cnv->numVertex * sizeof(MeVector3));
    for (int v = 0; points && v < cnv->numVertex; v++)
        MeVector3Copy(points[v], cnv->vertex[v].position);
    return points;
}

static MeBool allocateArrays(McdConvexHull *cnv)
{
    cnv->vertex = MeMemoryCreate((size_t)(cnv->numVertex + 1) * sizeof *cnv->vertex);
    cnv->face = MeMemoryCreate((size_t)(cnv->numFace + 1) * sizeof *cnv->face);
    cnv->edge = MeMemoryCreate((size_t)(cnv->numEdge > 0 ? cnv->numEdge : 1) * sizeof *cnv->edge);
    cnv->edgeIndex = MeMemoryCreate((size_t)(cnv->numEdge > 0 ? cnv->numEdge : 1) * sizeof(int));
    if (cnv->vertex && cnv->face && cnv->edge && cnv->edgeIndex)
        return METRUE;
    McdDeallocateHull(cnv);
    return MEFALSE;
}

/* Fill cnv's arrays (sized for h) from h's polygons: the edges of polygon p in its vertex order, each
 * with leftFace p; the face across an edge is the left face of its reverse. Around a vertex, the edge
 * after e (counter-clockwise seen from outside) is the reverse of the edge before e in e's face. */
static MeBool fillFromHull(const McdHull *h, McdConvexHull *cnv)
{
    int nv = h->vertexCount, nf = h->polygonCount, ne = h->polygonStart[nf];
    int *outStart = MeMemoryCreateZeroed((size_t)(nv + 1) * sizeof(int));
    int *outList = MeMemoryCreate((size_t)ne * sizeof(int));
    int *reverse = MeMemoryCreate((size_t)ne * sizeof(int));
    MeBool ok = outStart && outList && reverse;
    for (int v = 0; ok && v < nv; v++) {
        MeVector3Copy(cnv->vertex[v].position, h->vertices[v]);
    }
    for (int p = 0; ok && p < nf; p++) {
        int s = h->polygonStart[p], e = h->polygonStart[p + 1];
        MeVector3Copy(cnv->face[p].normal, h->normals[p]);
        cnv->face[p].firstEdge = s;
        for (int k = s; k < e; k++) {
            McdCnvEdge *edge = &cnv->edge[k];
            MeVector3 d;
            edge->fromVert = h->polygonVertices[k];
            edge->toVert = h->polygonVertices[k + 1 < e ? k + 1 : s];
            edge->leftFace = p;
            edge->rightFace = -1;
            MeVector3Subtract(d, h->vertices[edge->toVert], h->vertices[edge->fromVert]);
            edge->invLength = 1 / MeVector3Magnitude(d);
            outStart[edge->fromVert + 1]++;
        }
    }
    if (ok) {
        MeVector3Set(cnv->face[nf].normal, 0, 0, 0);
        cnv->face[nf].firstEdge = ne;
        for (int v = 0; v < nv; v++)
            outStart[v + 1] += outStart[v];
        for (int k = 0; k < ne; k++)
            outList[outStart[cnv->edge[k].fromVert]++] = k;
        for (int v = nv; v > 0; v--) /* the fill moved each start to the next vertex's */
            outStart[v] = outStart[v - 1];
        outStart[0] = 0;
    }
    for (int k = 0; ok && k < ne; k++) {
        const McdCnvEdge *e = &cnv->edge[k];
        reverse[k] = -1;
        for (int i = outStart[e->toVert]; i < outStart[e->toVert + 1]; i++)
            if (cnv->edge[outList[i]].toVert == e->fromVert)
                reverse[k] = outList[i];
        ok = reverse[k] >= 0;
        if (ok)
            cnv->edge[k].rightFace = cnv->edge[reverse[k]].leftFace;
    }
    for (int v = 0; ok && v < nv; v++) {
        int first = outList[outStart[v]], e = first, n = 0, degree = outStart[v + 1] - outStart[v];
        cnv->vertex[v].firstEdgeIndex = outStart[v];
        do {
            int f = cnv->edge[e].leftFace;
            int before = e == cnv->face[f].firstEdge ? cnv->face[f + 1].firstEdge - 1 : e - 1;
            cnv->edgeIndex[outStart[v] + n++] = e;
            e = reverse[before];
        } while (e != first && n < degree);
        ok = e == first && n == degree;
    }
    if (ok) {
        MeVector3Set(cnv->vertex[nv].position, 0, 0, 0);
        cnv->vertex[nv].firstEdgeIndex = ne;
    }
    MeMemoryDestroy(outStart);
    MeMemoryDestroy(outList);
    MeMemoryDestroy(reverse);
    return ok;
}

/* The hull as 1.2's arrays hold it: only its corners. A vertex in fewer than two of h's polygons is
 * not one: the build merges coplanar faces, and a point within the tolerance of a neighbour's edge
 * stays in one polygon only (a T-junction), where no edge of the neighbour returns along it. Such
 * points are dropped from the polygons and the vertices renumbered; the polygons keep their shape.
 * corners gets the vertices, polygons and normals only, its own (McdHullFree frees them). MEFALSE,
 * corners emptied, when out of memory or a polygon would be left with fewer than three corners. */
static MeBool cornersOnly(const McdHull *h, McdHull *corners)
{
    const int nv = h->vertexCount, nf = h->polygonCount, ne = h->polygonStart[nf];
    memset(corners, 0, sizeof *corners);
    int *uses = MeMemoryCreateZeroed((size_t)(nv > 0 ? nv : 1) * sizeof(int));
    corners->vertices = MeMemoryCreate((size_t)(nv > 0 ? nv : 1) * sizeof(MeVector3));
    corners->polygonStart = MeMemoryCreate((size_t)(nf + 1) * sizeof(int));
    corners->polygonVertices = MeMemoryCreate((size_t)(ne > 0 ? ne : 1) * sizeof(int));
    corners->normals = MeMemoryCreate((size_t)(nf > 0 ? nf : 1) * sizeof(MeVector3));
    MeBool ok = uses && corners->vertices && corners->polygonStart && corners->polygonVertices && corners->normals;
    for (int k = 0; ok && k < ne; k++)
        uses[h->polygonVertices[k]]++;
    for (int v = 0; ok && v < nv; v++) { /* uses[v] becomes v's new index, or -1 */
        if (uses[v] >= 2) {
            MeVector3Copy(corners->vertices[corners->vertexCount], h->vertices[v]);
            uses[v] = corners->vertexCount++;
        } else {
            uses[v] = -1;
        }
    }
    int kept = 0;
    for (int p = 0; ok && p < nf; p++) {
        corners->polygonStart[p] = kept;
        MeVector3Copy(corners->normals[p], h->normals[p]);
        for (int k = h->polygonStart[p]; k < h->polygonStart[p + 1]; k++)
            if (uses[h->polygonVertices[k]] >= 0)
                corners->polygonVertices[kept++] = uses[h->polygonVertices[k]];
        ok = kept - corners->polygonStart[p] >= 3;
    }
    MeMemoryDestroy(uses);
    if (!ok) {
        McdHullFree(corners);
        return MEFALSE;
    }
    corners->polygonStart[nf] = kept;
    corners->polygonCount = nf;
    return METRUE;
}

/* cnv's counts for the hull `corners` (made by cornersOnly). */
static void countsOf(const McdHull *corners, McdConvexHull *cnv)
{
    cnv->numVertex = corners->vertexCount;
    cnv->numFace = corners->polygonCount;
    cnv->numEdge = corners->polygonStart[corners->polygonCount];
}

MeBool McdConvexHullFromHull(const McdHull *h, McdConvexHull *cnv, const char *function)
{
    McdHull corners;
    MeBool ok = cornersOnly(h, &corners);
    if (ok) {
        countsOf(&corners, cnv);
        ok = allocateArrays(cnv);
        if (ok && !fillFromHull(&corners, cnv)) {
            McdDeallocateHull(cnv);
            ok = MEFALSE;
        }
        McdHullFree(&corners);
    }
    if (!ok)
        ME_REPORT_IN(function, ME_ERR_MCD_HULL_INCONSISTENT, "the hull of these points has a polygon 1.2's arrays "
                     "cannot hold (its corners do not close around a vertex), or memory ran out; call ignored");
    return ok;
}

/* Build the hull of checked points; MEFALSE (reported in `function`'s name) when flat. */
static MeBool buildHull(const MeVector3 *points, int n, McdHull *h, const char *function)
{
    if (!McdHullCheckPoints(points, n, function))
        return MEFALSE;
    McdHullStatus status = McdHullBuild(points, n, h);
    if (status == MCD_HULL_FLAT)
        ME_REPORT_IN(function, ME_ERR_MCD_HULL_FLAT, "the %d points lie within %g of a line or a plane (the hull "
                     "tolerance); call ignored", n, McdHullTolerance(points, n));
    return status == MCD_HULL_OK;
}

int McdComputeHull(McdConvexHull *cnv, int numpoints, const MeVector3 *points)
{
    ME_CHECK_NOT_NULL(cnv, 0);
    McdHull h;
    if (!buildHull(points, numpoints, &h, __func__))
        return 0;
    McdConvexHull built;
    MeBool ok = McdConvexHullFromHull(&h, &built, __func__);
    McdHullFree(&h);
    if (ok)
        *cnv = built;
    return ok ? 1 : 0;
}

/* The corners (cornersOnly) of the hull the last McdComputeHullSizes built, until McdGetHullData takes
 * them: one slot for the process, as 1.2's qhull state (no thread-local storage: the core needs libc
 * and libm only). Swapped atomically, so threads never share or leak a hull; threads building hulls
 * at once use McdComputeHull. */
static _Atomic(McdHull *) pendingHull = NULL;

static void freeHull(McdHull *h)
{
    if (h) {
        McdHullFree(h);
        MeMemoryDestroy(h);
    }
}

int McdComputeHullSizes(McdConvexHull *cnv, int numpoints, const MeVector3 *points)
{
    ME_CHECK_NOT_NULL(cnv, 0);
    McdHull built, *corners = MeMemoryCreate(sizeof *corners);
    if (!corners)
        return 0;
    if (!buildHull(points, numpoints, &built, __func__)) {
        MeMemoryDestroy(corners);
        return 0;
    }
    const MeBool ok = cornersOnly(&built, corners);
    McdHullFree(&built);
    if (!ok) {
        ME_REPORT(ME_ERR_MCD_HULL_INCONSISTENT, "the hull of these points has a polygon 1.2's arrays cannot hold, "
                  "or memory ran out; call ignored");
        MeMemoryDestroy(corners);
        return 0;
    }
    countsOf(corners, cnv);
    freeHull(atomic_exchange(&pendingHull, corners));
    return 1;
}

void McdAllocateHull(McdConvexHull *cnv)
{
    ME_CHECK_NOT_NULL(cnv, ME_NOTHING);
    if (cnv->numVertex < 0 || cnv->numFace < 0 || cnv->numEdge < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "a count is negative (numVertex %d, numFace %d, numEdge %d); nothing "
                  "allocated", cnv->numVertex, cnv->numFace, cnv->numEdge);
        cnv->vertex = NULL;
        cnv->face = NULL;
        cnv->edge = NULL;
        cnv->edgeIndex = NULL;
        return;
    }
    int nv = cnv->numVertex, nf = cnv->numFace, ne = cnv->numEdge;
    if (!allocateArrays(cnv)) { /* it cleared the counts with the pointers: keep the caller's */
        cnv->numVertex = nv;
        cnv->numFace = nf;
        cnv->numEdge = ne;
    }
}

int McdGetHullData(McdConvexHull *cnv)
{
    ME_CHECK_NOT_NULL(cnv, 0);
    if (!cnv->vertex || !cnv->face || !cnv->edge || !cnv->edgeIndex) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "an array of cnv is NULL (allocate them, e.g. McdAllocateHull); call ignored");
        return 0;
    }
    McdHull *h = atomic_exchange(&pendingHull, NULL);
    if (!h) {
        ME_REPORT(ME_ERR_BAD_STATE, "no hull waits: call McdComputeHullSizes first; call ignored");
        return 0;
    }
    McdConvexHull sizes;
    countsOf(h, &sizes);
    if (cnv->numVertex != sizes.numVertex || cnv->numFace != sizes.numFace || cnv->numEdge != sizes.numEdge) {
        ME_REPORT(ME_ERR_MCD_HULL_INCONSISTENT, "cnv's counts (%d vertices, %d faces, %d edges) are not the hull's "
                  "(%d, %d, %d); call ignored", cnv->numVertex, cnv->numFace, cnv->numEdge, sizes.numVertex,
                  sizes.numFace, sizes.numEdge);
        McdHull *none = NULL; /* put it back for a corrected call, unless a newer one came meanwhile */
        if (!atomic_compare_exchange_strong(&pendingHull, &none, h))
            freeHull(h);
        return 0;
    }
    MeBool ok = fillFromHull(h, cnv);
    if (!ok)
        ME_REPORT(ME_ERR_MCD_HULL_INCONSISTENT, "the hull's corners do not close around a vertex, or memory ran "
                  "out; call ignored");
    freeHull(h);
    return ok ? 1 : 0;
}

void McdDeallocateHull(McdConvexHull *cnv)
{
    if (!cnv)
        return;
    MeMemoryDestroy(cnv->vertex);
    MeMemoryDestroy(cnv->face);
    MeMemoryDestroy(cnv->edge);
    MeMemoryDestroy(cnv->edgeIndex);
    memset(cnv, 0, sizeof *cnv);
}

void McdGetTriangleHull(McdConvexHull *cnv, const MeVector3 p1, const MeVector3 p2, const MeVector3 p3)
{
    ME_CHECK_NOT_NULL(cnv, ME_NOTHING);
    ME_CHECK_NOT_NULL(p1, ME_NOTHING);
    ME_CHECK_NOT_NULL(p2, ME_NOTHING);
    ME_CHECK_NOT_NULL(p3, ME_NOTHING);
    if (!cnv->vertex || !cnv->face || !cnv->edge || !cnv->edgeIndex) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "an array of cnv is NULL (allocate 3 vertices, 1 face, 3 edges); call ignored");
        return;
    }
    const MeReal *p[3] = {p1, p2, p3};
    MeVector3 a, b;
    cnv->numVertex = 3;
    cnv->numFace = 1;
    cnv->numEdge = 3;
    for (int i = 0; i < 3; i++) {
        McdCnvEdge *e = &cnv->edge[i];
        MeVector3 d;
        MeVector3Copy(cnv->vertex[i].position, p[i]);
        cnv->vertex[i].firstEdgeIndex = i;
        cnv->edgeIndex[i] = i;
        e->fromVert = i;
        e->toVert = (i + 1) % 3;
        e->leftFace = 0;
        e->rightFace = 0; /* one face: it lies on both sides */
        MeVector3Subtract(d, p[e->toVert], p[i]);
        e->invLength = 1 / MeVector3Magnitude(d);
    }
    MeVector3Set(cnv->vertex[3].position, 0, 0, 0);
    cnv->vertex[3].firstEdgeIndex = 3;
    MeVector3Subtract(a, p2, p1);
    MeVector3Subtract(b, p3, p1);
    MeVector3Cross(cnv->face[0].normal, a, b);
    if (!MeVector3NormalizeSafe(cnv->face[0].normal))
        MeVector3Set(cnv->face[0].normal, 0, 0, 1);
    cnv->face[0].firstEdge = 0;
    MeVector3Set(cnv->face[1].normal, 0, 0, 0);
    cnv->face[1].firstEdge = 3;
}

/* ---- accessors ------------------------------------------------------------------------------ */

/* Whether 0 <= index < count, reported in `function`'s name as `name` otherwise. */
static MeBool indexInRange(const char *name, int index, int count, const char *function)
{
    if (index >= 0 && index < count)
        return METRUE;
    ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "%s (%d) must lie in 0 ... %d", name, index, count - 1);
    return MEFALSE;
}

static MeBool faceEdgeInRange(const McdConvexHull *cnv, int face, int i, MeBool anyEdge, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, cnv, MEFALSE);
    if (!indexInRange("face", face, cnv->numFace, function))
        return MEFALSE;
    return anyEdge || indexInRange("i", i, cnv->face[face + 1].firstEdge - cnv->face[face].firstEdge, function);
}

static MeBool vertexEdgeInRange(const McdConvexHull *cnv, int vertex, int i, MeBool anyEdge, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, cnv, MEFALSE);
    if (!indexInRange("vertex", vertex, cnv->numVertex, function))
        return MEFALSE;
    return anyEdge ||
           indexInRange("i", i, cnv->vertex[vertex + 1].firstEdgeIndex - cnv->vertex[vertex].firstEdgeIndex, function);
}

int McdCnvFaceGetCount(const McdConvexHull *cnv, int face)
{
    if (!faceEdgeInRange(cnv, face, 0, METRUE, __func__))
        return 0;
    return cnv->face[face + 1].firstEdge - cnv->face[face].firstEdge;
}

const McdCnvEdge *McdCnvFaceGetEdge(const McdConvexHull *cnv, int face, int i)
{
    if (!faceEdgeInRange(cnv, face, i, MEFALSE, __func__))
        return NULL;
    return &cnv->edge[cnv->face[face].firstEdge + i];
}

int McdCnvFaceGetVertexId(const McdConvexHull *cnv, int face, int i)
{
    if (!faceEdgeInRange(cnv, face, i, MEFALSE, __func__))
        return -1;
    return cnv->edge[cnv->face[face].firstEdge + i].fromVert;
}

const McdCnvVertex *McdCnvFaceGetVertex(const McdConvexHull *cnv, int face, int i)
{
    if (!faceEdgeInRange(cnv, face, i, MEFALSE, __func__))
        return NULL;
    return &cnv->vertex[cnv->edge[cnv->face[face].firstEdge + i].fromVert];
}

const MeReal *McdCnvFaceGetVertexPosition(const McdConvexHull *cnv, int face, int i)
{
    if (!faceEdgeInRange(cnv, face, i, MEFALSE, __func__))
        return NULL;
    return cnv->vertex[cnv->edge[cnv->face[face].firstEdge + i].fromVert].position;
}

int McdCnvVertexGetCount(const McdConvexHull *cnv, int vertex)
{
    if (!vertexEdgeInRange(cnv, vertex, 0, METRUE, __func__))
        return 0;
    return cnv->vertex[vertex + 1].firstEdgeIndex - cnv->vertex[vertex].firstEdgeIndex;
}

int McdCnvVertexGetEdgeId(const McdConvexHull *cnv, int vertex, int i)
{
    if (!vertexEdgeInRange(cnv, vertex, i, MEFALSE, __func__))
        return -1;
    return cnv->edgeIndex[cnv->vertex[vertex].firstEdgeIndex + i];
}

const McdCnvEdge *McdCnvVertexGetEdge(const McdConvexHull *cnv, int vertex, int i)
{
    if (!vertexEdgeInRange(cnv, vertex, i, MEFALSE, __func__))
        return NULL;
    return &cnv->edge[cnv->edgeIndex[cnv->vertex[vertex].firstEdgeIndex + i]];
}

int McdCnvVertexGetNeighbor(const McdConvexHull *cnv, int vertex, int i)
{
    if (!vertexEdgeInRange(cnv, vertex, i, MEFALSE, __func__))
        return -1;
    return cnv->edge[cnv->edgeIndex[cnv->vertex[vertex].firstEdgeIndex + i]].toVert;
}
