/* triangle_mesh.c -- a static triangle mesh that owns its triangles: the copies, the triangle
 * normals, the edges in use (from adjacency) and an AABB tree built once (McdTriangleMesh.h). */
#include <float.h>
#include <stdint.h>
#include <stdlib.h>

#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "../geometry/geometry.h"
#include "../nearfield/nearfield.h"
#include "terrain.h"

/* A triangle whose area is below this times its longest edge squared has no usable normal. */
#if KARMA_DOUBLE
#  define DEGENERATE_AREA ME_R(1e-12)
#else
#  define DEGENERATE_AREA ME_R(1e-6)
#endif
#define STACK_DEPTH 64

static const McdTriangleMeshShape *meshOf(void *data) { return &(*(McdTerrainData **)data)->s.mesh; }

static void meshAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdTriangleMeshShape *s = meshOf(data);
    McdAABBOfLocalBox(tm, s->nodes[0].lo, s->nodes[0].hi, minCorner, maxCorner);
}

static void meshBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    const McdTriangleMeshShape *s = meshOf(data);
    MeVector3Lerp(centre, s->nodes[0].lo, s->nodes[0].hi, ME_R(0.5));
    *radius = ME_R(0.5) * MeVector3Distance(s->nodes[0].lo, s->nodes[0].hi);
}

static void meshSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdTriangleMeshShape *s = meshOf(data);
    int best = 0;
    for (int i = 1; i < s->vertexCount; i++)
        if (MeVector3Dot(s->vertices[i], dir) > MeVector3Dot(s->vertices[best], dir))
            best = i;
    MeVector3Copy(point, s->vertices[best]);
}

static void freeMesh(McdTerrainData *t)
{
    if (!t)
        return;
    MeMemoryDestroy(t->s.mesh.vertices);
    MeMemoryDestroy(t->s.mesh.indices);
    MeMemoryDestroy(t->s.mesh.normals);
    MeMemoryDestroy(t->s.mesh.flags);
    MeMemoryDestroy(t->s.mesh.nodes);
    MeMemoryDestroy(t->s.mesh.order);
    MeMemoryDestroy(t);
}

static void meshDestroy(McdGeometryID g, void *data)
{
    (void)g;
    freeMesh(*(McdTerrainData **)data);
}

static void triangleOf(const McdTriangleMeshShape *s, int i, McdTerrainTriangle *t)
{
    for (int k = 0; k < 3; k++)
        MeVector3Copy(t->v[k], s->vertices[s->indices[3 * i + k]]);
    MeVector3Copy(t->normal, s->normals[i]);
    t->flags = s->flags[i];
    t->element = (void *)(intptr_t)i;
}

static MeBool boxesOverlap(const MeVector3 alo, const MeVector3 ahi, const MeVector3 blo, const MeVector3 bhi)
{
    return alo[0] <= bhi[0] && blo[0] <= ahi[0] && alo[1] <= bhi[1] && blo[1] <= ahi[1] && alo[2] <= bhi[2] &&
           blo[2] <= ahi[2];
}

void McdTriangleMeshForEach(const McdTriangleMeshShape *s, const MeVector3 lo, const MeVector3 hi,
                            McdTerrainVisitFn visit, void *ctx)
{
    int stack[STACK_DEPTH], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const McdBvhNode *node = &s->nodes[stack[--top]];
        if (!boxesOverlap(node->lo, node->hi, lo, hi))
            continue;
        if (node->count > 0) {
            for (int k = 0; k < node->count; k++) {
                McdTerrainTriangle t;
                triangleOf(s, s->order[node->first + k], &t);
                MeVector3 tlo, thi;
                for (int j = 0; j < 3; j++) {
                    tlo[j] = MeMIN3(t.v[0][j], t.v[1][j], t.v[2][j]);
                    thi[j] = MeMAX3(t.v[0][j], t.v[1][j], t.v[2][j]);
                }
                if (boxesOverlap(tlo, thi, lo, hi) && !visit(ctx, &t))
                    return;
            }
        } else if (top + 2 <= STACK_DEPTH) {
            stack[top++] = node->first + 1;
            stack[top++] = node->first;
        }
    }
}

/* Segment query: the tree walked by slab tests of the segment against each node's box. */
static MeBool segmentHitsBox(const MeVector3 p0, const MeVector3 d, MeReal tMax, const MeVector3 lo, const MeVector3 hi)
{
    MeReal t0 = ME_R(0.0), t1 = tMax;
    for (int j = 0; j < 3; j++) {
        if (d[j] == ME_R(0.0)) {
            if (p0[j] < lo[j] || p0[j] > hi[j])
                return MEFALSE;
            continue;
        }
        MeReal a = (lo[j] - p0[j]) / d[j], b = (hi[j] - p0[j]) / d[j];
        if (a > b) {
            MeReal x = a;
            a = b;
            b = x;
        }
        t0 = MeMAX(t0, a);
        t1 = MeMIN(t1, b);
        if (t0 > t1)
            return MEFALSE;
    }
    return METRUE;
}

static int meshSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t, MeVector3 normal)
{
    (void)g;
    const McdTriangleMeshShape *s = meshOf(data);
    MeVector3 d;
    MeReal best = ME_R(1.0);
    MeBool hit = MEFALSE;
    int stack[STACK_DEPTH], top = 0;
    MeVector3Subtract(d, p1, p0);
    stack[top++] = 0;
    while (top > 0) {
        const McdBvhNode *node = &s->nodes[stack[--top]];
        if (!segmentHitsBox(p0, d, best, node->lo, node->hi))
            continue;
        if (node->count > 0) {
            for (int k = 0; k < node->count; k++) {
                McdTerrainTriangle tri;
                MeReal tt;
                triangleOf(s, s->order[node->first + k], &tri);
                if (McdTerrainSegmentTriangle(&tri, p0, d, hit ? best : best + MCD_TERRAIN_SEGMENT_SLACK, &tt) &&
                    tt <= ME_R(1.0)) {
                    best = tt;
                    hit = METRUE;
                    MeVector3Copy(normal, tri.normal);
                }
            }
        } else if (top + 2 <= STACK_DEPTH) {
            stack[top++] = node->first + 1;
            stack[top++] = node->first;
        }
    }
    if (!hit)
        return 0;
    if (MeVector3Dot(normal, d) > ME_R(0.0))
        MeVector3Scale(normal, -ME_R(1.0));
    *t = best;
    return 1;
}

const McdGeometryTypeDesc McdTriangleMeshTypeDesc = {"TriangleMesh", meshDestroy, meshAABB, meshBSphere,
                                                     meshSupport, McdTerrainMass, meshSegment, NULL};

/* ---- building ---------------------------------------------------------------------------------- */

typedef struct Builder {
    McdTriangleMeshShape *s;
    MeVector3 *centroids;
} Builder;

/* The box [lo, hi] of the triangles order[first .. first + count - 1]. */
static void boundsOf(const Builder *b, int first, int count, MeVector3 lo, MeVector3 hi)
{
    MeVector3Set(lo, MEINFINITY, MEINFINITY, MEINFINITY);
    MeVector3Set(hi, -MEINFINITY, -MEINFINITY, -MEINFINITY);
    for (int i = first; i < first + count; i++) {
        int tri = b->s->order[i];
        for (int k = 0; k < 3; k++) {
            const MeReal *v = b->s->vertices[b->s->indices[3 * tri + k]];
            for (int j = 0; j < 3; j++) {
                lo[j] = MeMIN(lo[j], v[j]);
                hi[j] = MeMAX(hi[j], v[j]);
            }
        }
    }
}

/* The box [clo, chi] of those triangles' centroids (where the split is chosen). */
static void centroidBoundsOf(const Builder *b, int first, int count, MeVector3 clo, MeVector3 chi)
{
    MeVector3Set(clo, MEINFINITY, MEINFINITY, MEINFINITY);
    MeVector3Set(chi, -MEINFINITY, -MEINFINITY, -MEINFINITY);
    for (int i = first; i < first + count; i++) {
        int tri = b->s->order[i];
        for (int j = 0; j < 3; j++) {
            clo[j] = MeMIN(clo[j], b->centroids[tri][j]);
            chi[j] = MeMAX(chi[j], b->centroids[tri][j]);
        }
    }
}

/* Put the triangle of median centroid (along axis) at order[mid], smaller ones before it. */
static void selectMedian(const Builder *b, int lo, int hi, int mid, int axis)
{
    int *o = b->s->order;
    while (hi > lo) {
        MeReal pivot = b->centroids[o[(lo + hi) / 2]][axis];
        int i = lo, j = hi;
        while (i <= j) {
            while (b->centroids[o[i]][axis] < pivot)
                i++;
            while (b->centroids[o[j]][axis] > pivot)
                j--;
            if (i <= j) {
                int x = o[i];
                o[i] = o[j];
                o[j] = x;
                i++;
                j--;
            }
        }
        if (mid <= j)
            hi = j;
        else if (mid >= i)
            lo = i;
        else
            return;
    }
}

static void buildNode(Builder *b, int nodeIndex, int first, int count)
{
    McdBvhNode *node = &b->s->nodes[nodeIndex];
    MeVector3 clo, chi;
    boundsOf(b, first, count, node->lo, node->hi);
    centroidBoundsOf(b, first, count, clo, chi);
    if (count <= MCD_TERRAIN_LEAF_SIZE) {
        node->first = first;
        node->count = count;
        return;
    }
    int axis = 0;
    for (int j = 1; j < 3; j++)
        if (chi[j] - clo[j] > chi[axis] - clo[axis])
            axis = j;
    int half = count / 2;
    selectMedian(b, first, first + count - 1, first + half, axis);
    int children = b->s->nodeCount;
    b->s->nodeCount += 2;
    node->first = children;
    node->count = 0;
    buildNode(b, children, first, half);
    buildNode(b, children + 1, first + half, count - half);
}

typedef struct EdgeRef {
    int a, b;   /* vertex numbers, a < b */
    int tri, k; /* triangle and its edge number */
} EdgeRef;

static int compareEdges(const void *x, const void *y)
{
    const EdgeRef *p = x, *q = y;
    if (p->a != q->a)
        return p->a < q->a ? -1 : 1;
    if (p->b != q->b)
        return p->b < q->b ? -1 : 1;
    return (p->tri > q->tri) - (p->tri < q->tri);
}

/* Whether edge (tri, k) stays in use next to triangle `other`: only at a convex angle of more than
 * the threshold, seen from tri's front. */
static MeBool edgeInUse(const McdTriangleMeshShape *s, int tri, int other)
{
    const int *o = &s->indices[3 * other];
    const int *t = &s->indices[3 * tri];
    int w = o[0];
    for (int k = 0; k < 3; k++)
        if (o[k] != t[0] && o[k] != t[1] && o[k] != t[2])
            w = o[k];
    MeVector3 dv;
    MeVector3Subtract(dv, s->vertices[w], s->vertices[t[0]]);
    MeReal size = MeVector3Distance(s->vertices[t[0]], s->vertices[t[1]]) + MeVector3Magnitude(dv);
    MeReal below = -MeVector3Dot(dv, s->normals[tri]);
    MeVector3 x;
    MeVector3Cross(x, s->normals[tri], s->normals[other]);
    MeBool bent = MeVector3Magnitude(x) > MCD_TERRAIN_ACTIVE_EDGE_SIN ||
                  MeVector3Dot(s->normals[tri], s->normals[other]) < ME_R(0.0);
    return below > MCD_NF_REL_EPS * size && bent;
}

static MeBool computeEdgeFlags(McdTriangleMeshShape *s)
{
    int n = 3 * s->triangleCount;
    EdgeRef *edges = MeMemoryCreate((size_t)n * sizeof *edges);
    if (!edges)
        return MEFALSE;
    for (int i = 0; i < s->triangleCount; i++)
        for (int k = 0; k < 3; k++) {
            int a = s->indices[3 * i + k], b = s->indices[3 * i + (k + 1) % 3];
            EdgeRef *e = &edges[3 * i + k];
            e->a = a < b ? a : b;
            e->b = a < b ? b : a;
            e->tri = i;
            e->k = k;
        }
    qsort(edges, (size_t)n, sizeof *edges, compareEdges);
    for (int i = 0; i < s->triangleCount; i++)
        s->flags[i] = kMcdTriangleTwoSided | kMcdTriangleUseSmallestPenetration;
    for (int start = 0; start < n;) {
        int end = start + 1;
        while (end < n && edges[end].a == edges[start].a && edges[end].b == edges[start].b)
            end++;
        for (int e = start; e < end; e++) {
            /* a boundary (one triangle) or a non-manifold edge (three or more) is always in use */
            MeBool use = end - start != 2 || edgeInUse(s, edges[e].tri, edges[e == start ? start + 1 : start].tri);
            if (use)
                s->flags[edges[e].tri] |= (unsigned char)(kMcdTriangleUseEdge0 << edges[e].k);
        }
        start = end;
    }
    MeMemoryDestroy(edges);
    return METRUE;
}

static MeBool checkMesh(const McdFrameworkData *fw, const MeVector3 *vertices, int vertexCount, const int *indices,
                        int triangleCount, const char *function)
{
    if (!vertices || !indices) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "vertices and indices must not be NULL; call ignored");
        return MEFALSE;
    }
    if (vertexCount < 3 || triangleCount < 1 || triangleCount > INT32_MAX / 3) {
        ME_REPORT_IN(function, ME_ERR_MCD_BAD_MESH, "a mesh needs at least 3 vertices and 1 triangle (%d and %d given); "
                     "call ignored", vertexCount, triangleCount);
        return MEFALSE;
    }
    for (int i = 0; i < vertexCount; i++)
        if (!McdPositionInRange(fw, vertices[i])) {
            ME_REPORT_IN(function, ME_ERR_MCD_BAD_MESH, "vertex %d is not finite or lies beyond 1e7 times lengthScale "
                         "from the origin; call ignored", i);
            return MEFALSE;
        }
    for (int i = 0; i < triangleCount; i++) {
        MeVector3 e1, e2, x;
        for (int k = 0; k < 3; k++)
            if (indices[3 * i + k] < 0 || indices[3 * i + k] >= vertexCount) {
                ME_REPORT_IN(function, ME_ERR_MCD_BAD_MESH, "triangle %d has vertex index %d, outside 0 to %d; call "
                             "ignored", i, indices[3 * i + k], vertexCount - 1);
                return MEFALSE;
            }
        const MeReal *a = vertices[indices[3 * i]], *b = vertices[indices[3 * i + 1]], *c = vertices[indices[3 * i + 2]];
        MeVector3Subtract(e1, b, a);
        MeVector3Subtract(e2, c, a);
        MeVector3Cross(x, e1, e2);
        MeReal longest = MeMAX3(MeVector3MagnitudeSqr(e1), MeVector3MagnitudeSqr(e2), MeVector3DistanceSqr(b, c));
        if (!(MeVector3Magnitude(x) > DEGENERATE_AREA * longest)) {
            ME_REPORT_IN(function, ME_ERR_MCD_DEGENERATE_TRIANGLE, "triangle %d (vertices %d, %d, %d) has no area; "
                         "call ignored", i, indices[3 * i], indices[3 * i + 1], indices[3 * i + 2]);
            return MEFALSE;
        }
    }
    return METRUE;
}

McdTriangleMeshID McdTriangleMeshCreate(McdFrameworkID fwId, const MeVector3 *vertices, int vertexCount,
                                        const int *indices, int triangleCount)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !checkMesh(fw, vertices, vertexCount, indices, triangleCount, __func__))
        return NULL;
    McdTerrainData *t = MeMemoryCreateZeroed(sizeof *t);
    if (!t)
        return NULL;
    McdTriangleMeshShape *s = &t->s.mesh;
    size_t nt = (size_t)triangleCount;
    s->vertexCount = vertexCount;
    s->triangleCount = triangleCount;
    s->vertices = MeMemoryCreate((size_t)vertexCount * sizeof *s->vertices);
    s->indices = MeMemoryCreate(3 * nt * sizeof *s->indices);
    s->normals = MeMemoryCreate(nt * sizeof *s->normals);
    s->flags = MeMemoryCreate(nt);
    s->nodes = MeMemoryCreate(2 * nt * sizeof *s->nodes);
    s->order = MeMemoryCreate(nt * sizeof *s->order);
    MeVector3 *centroids = MeMemoryCreate(nt * sizeof *centroids);
    if (!s->vertices || !s->indices || !s->normals || !s->flags || !s->nodes || !s->order || !centroids) {
        MeMemoryDestroy(centroids);
        freeMesh(t);
        return NULL;
    }
    for (int i = 0; i < vertexCount; i++)
        MeVector3Copy(s->vertices[i], vertices[i]);
    for (size_t i = 0; i < 3 * nt; i++)
        s->indices[i] = indices[i];
    for (int i = 0; i < triangleCount; i++) {
        const MeReal *a = s->vertices[s->indices[3 * i]], *b = s->vertices[s->indices[3 * i + 1]],
                     *c = s->vertices[s->indices[3 * i + 2]];
        MeVector3 e1, e2;
        MeVector3Subtract(e1, b, a);
        MeVector3Subtract(e2, c, a);
        MeVector3Cross(s->normals[i], e1, e2);
        MeVector3Normalize(s->normals[i]);
        for (int j = 0; j < 3; j++)
            centroids[i][j] = (a[j] + b[j] + c[j]) / ME_R(3.0);
        s->order[i] = i;
    }
    if (!computeEdgeFlags(s)) {
        MeMemoryDestroy(centroids);
        freeMesh(t);
        return NULL;
    }
    Builder b = {s, centroids};
    s->nodeCount = 1;
    buildNode(&b, 0, 0, triangleCount);
    MeMemoryDestroy(centroids);
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeTriangleMesh, __func__);
    if (!g) {
        freeMesh(t);
        return NULL;
    }
    g->u.terrain = t;
    return McdGeometryToID(g);
}

int McdTriangleMeshGetTriangleCount(McdTriangleMeshID g)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleMesh, __func__);
    return t ? t->s.mesh.triangleCount : 0;
}

int McdTriangleMeshGetTriangle(McdTriangleMeshID g, int index, MeVector3 v0, MeVector3 v1, MeVector3 v2, int *flags)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleMesh, __func__);
    if (!t)
        return 0;
    ME_CHECK_NOT_NULL(v0, 0);
    ME_CHECK_NOT_NULL(v1, 0);
    ME_CHECK_NOT_NULL(v2, 0);
    if (index < 0 || index >= t->s.mesh.triangleCount) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "index %d is outside 0 to %d; call ignored", index, t->s.mesh.triangleCount - 1);
        return 0;
    }
    McdTerrainTriangle tri;
    triangleOf(&t->s.mesh, index, &tri);
    MeVector3Copy(v0, tri.v[0]);
    MeVector3Copy(v1, tri.v[1]);
    MeVector3Copy(v2, tri.v[2]);
    if (flags)
        *flags = tri.flags;
    return 1;
}

typedef struct BoxQuery {
    int *out;
    int maxCount, count;
} BoxQuery;

static MeBool collectIndex(void *ctx, const McdTerrainTriangle *t)
{
    BoxQuery *q = ctx;
    if (q->count < q->maxCount)
        q->out[q->count] = (int)(intptr_t)t->element;
    q->count++;
    return METRUE;
}

int McdTriangleMeshQueryBox(McdTriangleMeshID g, const MeVector3 min, const MeVector3 max, int *out, int maxCount)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleMesh, __func__);
    if (!t)
        return 0;
    ME_CHECK_NOT_NULL(min, 0);
    ME_CHECK_NOT_NULL(max, 0);
    if (maxCount > 0)
        ME_CHECK_NOT_NULL(out, 0);
    BoxQuery q = {out, maxCount, 0};
    McdTriangleMeshForEach(&t->s.mesh, min, max, collectIndex, &q);
    return q.count;
}

MeI16 McdTriangleMeshGetTypeId(void) { return (MeI16)kMcdGeometryTypeTriangleMesh; }
