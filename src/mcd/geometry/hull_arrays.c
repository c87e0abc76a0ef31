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
 * view shares h's normals; freed by freeCorners. MEFALSE when out of memory or a polygon would be
 * left with fewer than three corners. */
static MeBool cornersOnly(const McdHull *h, McdHull *view)
{
    const int nv = h->vertexCount, nf = h->polygonCount, ne = h->polygonStart[nf];
    memset(view, 0, sizeof *view);
    int *uses = MeMemoryCreateZeroed((size_t)(nv > 0 ? nv : 1) * sizeof(int));
    view->vertices = MeMemoryCreate((size_t)(nv > 0 ? nv : 1) * sizeof(MeVector3));
    view->polygonStart = MeMemoryCreate((size_t)(nf + 1) * sizeof(int));
    view->polygonVertices = MeMemoryCreate((size_t)(ne > 0 ? ne : 1) * sizeof(int));
    view->normals = h->normals;
    MeBool ok = uses && view->vertices && view->polygonStart && view->polygonVertices;
    for (int k = 0; ok && k < ne; k++)
        uses[h->polygonVertices[k]]++;
    for (int v = 0; ok && v < nv; v++) { /* uses[v] becomes v's new index, or -1 */
        if (uses[v] >= 2) {
            MeVector3Copy(view->vertices[view->vertexCount], h->vertices[v]);
            uses[v] = view->vertexCount++;
        } else {
            uses[v] = -1;
        }
    }
    int kept = 0;
    for (int p = 0; ok && p < nf; p++) {
        view->polygonStart[p] = kept;
        for (int k = h->polygonStart[p]; k < h->polygonStart[p + 1]; k++)
            if (uses[h->polygonVertices[k]] >= 0)
                view->polygonVertices[kept++] = uses[h->polygonVertices[k]];
        ok = kept - view->polygonStart[p] >= 3;
    }
    if (ok) {
        view->polygonStart[nf] = kept;
        view->polygonCount = nf;
    }
    MeMemoryDestroy(uses);
    return ok;
}

static void freeCorners(McdHull *view)
{
    MeMemoryDestroy(view->vertices);
    MeMemoryDestroy(view->polygonStart);
    MeMemoryDestroy(view->polygonVertices);
    memset(view, 0, sizeof *view);
}

/* cnv's counts for h's corners; MEFALSE (counts zero) when cornersOnly fails. */
static MeBool countsOf(const McdHull *h, McdConvexHull *cnv)
{
    McdHull view;
    const MeBool ok = cornersOnly(h, &view);
    cnv->numVertex = ok ? view.vertexCount : 0;
    cnv->numFace = ok ? view.polygonCount : 0;
    cnv->numEdge = ok ? view.polygonStart[view.polygonCount] : 0;
    freeCorners(&view);
    return ok;
}

/* Fill cnv's arrays (sized by countsOf) from h's corners. */
static MeBool fillCorners(const McdHull *h, McdConvexHull *cnv)
{
    McdHull view;
    const MeBool ok = cornersOnly(h, &view) && fillFromHull(&view, cnv);
    freeCorners(&view);
    return ok;
}

MeBool McdConvexHullFromHull(const McdHull *h, McdConvexHull *cnv, const char *function)
{
    if (countsOf(h, cnv) && allocateArrays(cnv)) {
        if (fillCorners(h, cnv))
            return METRUE;
        McdDeallocateHull(cnv);
    }
    ME_REPORT_IN(function, ME_ERR_MCD_HULL_INCONSISTENT, "the hull of these points has a polygon 1.2's arrays "
                 "cannot hold (its corners do not close around a vertex), or memory ran out; call ignored");
    return MEFALSE;
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

/* The hull the last McdComputeHullSizes built, until McdGetHullData takes it: one slot for the process,
 * as 1.2's qhull state (no thread-local storage: the core needs libc and libm only). Swapped atomically,
 * so threads never share or leak a hull; threads building hulls at once use McdComputeHull. */
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
    McdHull *h = MeMemoryCreate(sizeof *h);
    if (!h)
        return 0;
    if (!buildHull(points, numpoints, h, __func__)) {
        MeMemoryDestroy(h);
        return 0;
    }
    if (!countsOf(h, cnv)) {
        ME_REPORT(ME_ERR_MCD_HULL_INCONSISTENT, "the hull of these points has a polygon 1.2's arrays cannot hold, "
                  "or memory ran out; call ignored");
        freeHull(h);
        return 0;
    }
    freeHull(atomic_exchange(&pendingHull, h));
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
    MeBool ok = fillCorners(h, cnv);
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

static MeBool faceEdgeInRange(const McdConvexHull *cnv, int face, int i, MeBool anyEdge, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, cnv, MEFALSE);
    if (face < 0 || face >= cnv->numFace) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "face (%d) must lie in 0 ... %d", face, cnv->numFace - 1);
        return MEFALSE;
    }
    int n = cnv->face[face + 1].firstEdge - cnv->face[face].firstEdge;
    if (!anyEdge && (i < 0 || i >= n)) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "i (%d) must lie in 0 ... %d", i, n - 1);
        return MEFALSE;
    }
    return METRUE;
}

static MeBool vertexEdgeInRange(const McdConvexHull *cnv, int vertex, int i, MeBool anyEdge, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, cnv, MEFALSE);
    if (vertex < 0 || vertex >= cnv->numVertex) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "vertex (%d) must lie in 0 ... %d", vertex, cnv->numVertex - 1);
        return MEFALSE;
    }
    int n = cnv->vertex[vertex + 1].firstEdgeIndex - cnv->vertex[vertex].firstEdgeIndex;
    if (!anyEdge && (i < 0 || i >= n)) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "i (%d) must lie in 0 ... %d", i, n - 1);
        return MEFALSE;
    }
    return METRUE;
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
