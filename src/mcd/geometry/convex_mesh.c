/* convex_mesh.c -- the convex mesh: a hull (convex_hull.c) rounded by a fatness radius; its API and
 * protocol. The vertices stay in the frame they were given in (Karma 1.2): the centre of mass is
 * reported by the mass properties, not moved to the origin. Built from points (McdConvexMeshCreateHull)
 * or from 1.2's McdConvexHull arrays (McdConvexMeshCreate, checked by hull_check.c); either way the pair
 * tests use the hull rebuilt from the vertices and the accessors read the McdConvexHull. */
#include <math.h>
#include <string.h>

#include <karma/McdConvexMesh.h>
#include <karma/McdPrimitives.h>
#include <karma/MeDebugDraw.h>
#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "convex_hull.h"
#include "convex_mass.h"
#include "geometry.h"
#include "hull_arrays.h"

/* Hulls with more vertices than this climb the vertex graph instead of reading every vertex. */
#define CLIMB_MIN_VERTICES 48

/* Index of the vertex farthest along dir (local). Small hulls: every vertex (ties: the first). Large
 * ones: climbed to from vertex 0 (McdHullClimb). */
static int supportIndex(const McdHull *h, const MeVector3 dir)
{
    int i, best = 0;
    MeReal bestD = MeVector3Dot(h->vertices[0], dir);
    if (h->vertexCount < CLIMB_MIN_VERTICES) {
        for (i = 1; i < h->vertexCount; i++) {
            MeReal d = MeVector3Dot(h->vertices[i], dir);
            if (d > bestD) {
                bestD = d;
                best = i;
            }
        }
        return best;
    }
    return McdHullClimb(h, dir, 0);
}

int McdHullClimb(const McdHull *h, const MeVector3 dir, int start)
{
    int best = start >= 0 && start < h->vertexCount ? start : 0;
    MeReal bestD = MeVector3Dot(h->vertices[best], dir);
    for (int steps = 0; steps < h->vertexCount; steps++) {
        int from = best;
        for (int i = h->neighbourStart[from]; i < h->neighbourStart[from + 1]; i++) {
            int w = h->neighbours[i];
            MeReal d = MeVector3Dot(h->vertices[w], dir);
            if (d > bestD) {
                bestD = d;
                best = w;
            }
        }
        if (best == from)
            break;
    }
    return best;
}

int McdConvexMeshSupportIndex(const McdConvexMeshData *c, const MeVector3 dir) { return supportIndex(c->hull, dir); }

static void convexAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdConvexMeshData *c = data;
    for (int j = 0; j < 3; j++) {
        MeVector3 axis = {tm[0][j], tm[1][j], tm[2][j]}, neg = {-tm[0][j], -tm[1][j], -tm[2][j]};
        MeReal hi = MeVector3Dot(c->hull->vertices[supportIndex(c->hull, axis)], axis);
        MeReal lo = MeVector3Dot(c->hull->vertices[supportIndex(c->hull, neg)], axis);
        maxCorner[j] = tm[3][j] + hi + c->fatness;
        minCorner[j] = tm[3][j] + lo - c->fatness;
    }
}

static void convexBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    const McdConvexMeshData *c = data;
    MeVector3Copy(centre, c->hull->centre);
    *radius = c->hull->radius + c->fatness;
}

static void convexSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdConvexMeshData *c = data;
    MeVector3 u;
    MeVector3Copy(point, c->hull->vertices[supportIndex(c->hull, dir)]);
    MeVector3Copy(u, dir);
    if (c->fatness > 0 && MeVector3NormalizeSafe(u))
        MeVector3MultiplyAdd(point, c->fatness, u);
}

static void convexMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g;
    const McdHull *h = ((const McdConvexMeshData *)data)->hull;
    MeMatrix4TMMakeIdentity(relTM);
    MeVector3Copy(relTM[3], h->centreOfMass);
    memcpy(inertia, h->inertia, sizeof(MeMatrix3));
    *volume = h->volume;
}

/* The polyhedron is the intersection of its polygons' half-spaces; a rounded one is met exactly by
 * McdRoundedHullSegment (a segment of no length: the half-spaces moved out by the fatness). */
static int convexSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                         MeVector3 normal)
{
    (void)g;
    const McdConvexMeshData *c = data;
    const McdHull *h = c->hull;
    McdLineInterval iv;
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    if (c->fatness > 0 && MeVector3MagnitudeSqr(d) > 0)
        return McdRoundedHullSegment(h, c->fatness, p0, p1, t, normal);
    McdLineIntervalAll(&iv);
    for (int p = 0; p < h->polygonCount && iv.tIn <= iv.tOut; p++) {
        MeReal den = MeVector3Dot(h->normals[p], d);
        MeReal num = h->offsets[p] + c->fatness - MeVector3Dot(h->normals[p], p0);
        if (den == 0) {
            if (num < 0)
                iv.tIn = MEINFINITY; /* parallel and outside: empty */
            continue;
        }
        MeReal tp = num / den;
        if (den < 0) {
            if (tp > iv.tIn) {
                iv.tIn = tp;
                MeVector3Copy(iv.nIn, h->normals[p]);
            }
        } else if (tp < iv.tOut)
            iv.tOut = tp;
    }
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}

static void convexDestroy(McdGeometryID g, void *data)
{
    (void)g;
    McdConvexMeshData *c = data;
    if (c->hull) {
        McdHullFree(c->hull);
        MeMemoryDestroy(c->hull);
        c->hull = NULL;
    }
    if (c->poly) {
        McdDeallocateHull(c->poly);
        MeMemoryDestroy(c->poly);
        c->poly = NULL;
    }
}

/* Wire-frame: every edge once. */
static void convexDraw(McdGeometryID g, void *data, MeMatrix4 tm, const float colour[3])
{
    (void)g;
    const McdHull *h = ((const McdConvexMeshData *)data)->hull;
    for (int e = 0; e < h->edgeCount; e++) {
        MeVector3 a, b;
        MeMatrix4TMTransform(a, tm, h->vertices[h->edges[2 * e]]);
        MeMatrix4TMTransform(b, tm, h->vertices[h->edges[2 * e + 1]]);
        MeDebugDrawAPI.line(a, b, colour[0], colour[1], colour[2]);
    }
}

const McdGeometryTypeDesc McdConvexMeshTypeDesc = {"ConvexMesh", convexDestroy, convexAABB, convexBSphere,
                                                   convexSupport, convexMass, convexSegment, convexDraw};

/* The convex mesh of `vertexCount` points (reported in `function`'s name), its McdConvexHull not yet set. */
static McdGeometryData *createFromPoints(McdFrameworkData *fw, const MeVector3 *vertices, int vertexCount,
                                         MeReal fatnessRadius, const char *function)
{
    if (!McdCheckDimension(fw, fatnessRadius, "fatnessRadius", METRUE, function) ||
        !McdHullCheckPoints(vertices, vertexCount, function))
        return NULL;
    MeReal far = 0;
    for (int i = 0; i < vertexCount; i++)
        far = MeMAX(far, MeMAX3(MeFabs(vertices[i][0]), MeFabs(vertices[i][1]), MeFabs(vertices[i][2])));
    if (far > MCD_SIZE_MAX * fw->lengthScale) {
        ME_REPORT_IN(function, ME_ERR_MCD_SIZE_RANGE, "a vertex lies %g from the origin, beyond %g (1e6 times the "
                     "framework's lengthScale); call ignored", (double)far, (double)(MCD_SIZE_MAX * fw->lengthScale));
        return NULL;
    }
    McdHull *hull = MeMemoryCreate(sizeof *hull);
    if (!hull)
        return NULL;
    McdHullStatus status = McdHullBuild(vertices, vertexCount, hull);
    if (status != MCD_HULL_OK) {
        MeMemoryDestroy(hull);
        if (status == MCD_HULL_FLAT)
            ME_REPORT_IN(function, ME_ERR_MCD_HULL_FLAT, "the %d points span no volume: they lie within %g of a line "
                         "or a plane (the hull tolerance); call ignored", vertexCount,
                         McdHullTolerance(vertices, vertexCount));
        return NULL;
    }
    /* the hull's smallest extent (its thickness along some polygon normal) must be a valid size */
    MeReal thin = MEINFINITY;
    for (int p = 0; p < hull->polygonCount; p++) {
        MeVector3 neg;
        MeVector3MultiplyScalar(neg, hull->normals[p], -1);
        thin = MeMIN(thin, hull->offsets[p] + MeVector3Dot(hull->vertices[supportIndex(hull, neg)], neg));
    }
    if (!(thin >= MCD_SIZE_MIN * fw->lengthScale)) {
        ME_REPORT_IN(function, ME_ERR_MCD_SIZE_RANGE, "the hull is %g thick, below %g (1e-6 times the framework's "
                     "lengthScale); call ignored", (double)thin, (double)(MCD_SIZE_MIN * fw->lengthScale));
        McdHullFree(hull);
        MeMemoryDestroy(hull);
        return NULL;
    }
    McdGeometryData *g = McdHullComputeMass(hull, fatnessRadius) ? McdGeometryNew(fw, kMcdGeometryTypeConvexMesh, function)
                                                           : NULL;
    if (!g) {
        McdHullFree(hull);
        MeMemoryDestroy(hull);
        return NULL;
    }
    g->u.convex.hull = hull;
    g->u.convex.poly = NULL;
    g->u.convex.fatness = fatnessRadius;
    return g;
}

McdConvexMeshID McdConvexMeshCreateHull(McdFrameworkID fwId, const MeVector3 *vertices, int vertexCount,
                                        MeReal fatnessRadius)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    McdGeometryData *g = fw ? createFromPoints(fw, vertices, vertexCount, fatnessRadius, __func__) : NULL;
    if (!g)
        return NULL;
    McdConvexMeshID id = McdGeometryToID(g);
    McdConvexHull *poly = MeMemoryCreateZeroed(sizeof *poly);
    if (!poly || !McdConvexHullFromHull(g->u.convex.hull, poly, __func__)) {
        MeMemoryDestroy(poly);
        McdGeometryDestroy(id);
        return NULL;
    }
    g->u.convex.poly = poly;
    return id;
}

McdConvexMeshID McdConvexMeshCreate(McdFrameworkID fwId, McdConvexHull *poly, MeReal fatness)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !McdConvexHullCheck(poly, __func__))
        return NULL;
    MeVector3 *points = McdConvexHullPositions(poly);
    if (!points)
        return NULL;
    McdGeometryData *g = createFromPoints(fw, (const MeVector3 *)points, poly->numVertex, fatness, __func__);
    MeMemoryDestroy(points);
    McdConvexHull *kept = g ? MeMemoryCreate(sizeof *kept) : NULL;
    if (!kept) {
        if (g)
            McdGeometryDestroy(McdGeometryToID(g));
        return NULL;
    }
    *kept = *poly; /* 1.2's shallow copy: the geometry now owns the arrays */
    g->u.convex.poly = kept;
    return McdGeometryToID(g);
}

/* The sphyl as a rounded polyhedron: the core is the box [-d, d]^2 x [-h/2, h/2] (a segment made thick
 * enough for the hull tolerance: d = 1e-3 r + 1e-5 h), the fatness r - d; the solid then lies
 * between the sphyl shrunk by d and grown by d (sqrt 2 - 1). Its mass properties are the sphyl's
 * closed form (radius r, cylinder part h). */
McdConvexMeshID McdConvexMeshCreateSphyl(McdFrameworkID fwId, MeReal radius, MeReal height)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !McdCheckDimension(fw, radius, "radius", MEFALSE, __func__) ||
        !McdCheckDimension(fw, height, "height", METRUE, __func__))
        return NULL;
    MeReal d = ME_R(1e-3) * radius + ME_R(1e-5) * height, hh = ME_R(0.5) * height;
    MeVector3 corners[8];
    for (int k = 0; k < 8; k++)
        MeVector3Set(corners[k], (k & 1) ? d : -d, (k & 2) ? d : -d, (k & 4) ? hh + d : -hh - d);
    McdConvexMeshID id = McdConvexMeshCreateHull(fwId, (const MeVector3 *)corners, 8, radius - d);
    McdGeometryData *g = id ? McdGeometryFromID(id, __func__) : NULL;
    if (!g)
        return NULL;
    {
        McdHull *h = g->u.convex.hull;
        MeReal r = radius, r2 = r * r, vCyl = ME_PI * r2 * height, vBall = ME_R(4.0) / 3 * ME_PI * r2 * r;
        /* a cylinder and two hemispheres (centroids 3r/8 beyond their flat faces at z = +-h/2) */
        MeReal ixx = vCyl * (3 * r2 + height * height) / 12 + vBall * (ME_R(0.4) * r2 + hh * hh + ME_R(0.75) * hh * r);
        h->volume = vCyl + vBall;
        MeVector3Set(h->centreOfMass, 0, 0, 0);
        McdDiagonalInertia(h->inertia, ixx, ixx, vCyl * r2 / 2 + ME_R(0.4) * vBall * r2);
    }
    return id;
}

#define CONVEX_OR_RETURN(c, id, ret)                                                                 \
    McdGeometryData *c##G = McdGeometryOfType((id), kMcdGeometryTypeConvexMesh, __func__);           \
    if (!c##G)                                                                                       \
        return ret;                                                                                  \
    const McdConvexHull *c = c##G->u.convex.poly

void McdConvexMeshDestroy(McdConvexMeshID id)
{
    if (McdGeometryOfType(id, kMcdGeometryTypeConvexMesh, __func__))
        McdGeometryDestroy(id);
}

int McdConvexMeshGetPolygonCount(McdConvexMeshID id)
{
    CONVEX_OR_RETURN(h, id, 0);
    return h->numFace;
}

static MeBool polygonInRange(const McdConvexHull *h, int polyID, const char *function)
{
    if (polyID < 0 || polyID >= h->numFace) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "polyID (%d) must lie in 0 ... %d; call ignored", polyID,
                     h->numFace - 1);
        return MEFALSE;
    }
    return METRUE;
}

static const MeReal *polygonVertex(const McdConvexHull *h, int polyID, int vertexID, const char *function)
{
    if (!polygonInRange(h, polyID, function))
        return NULL;
    int n = h->face[polyID + 1].firstEdge - h->face[polyID].firstEdge;
    if (vertexID < 0 || vertexID >= n) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "vertexID (%d) must lie in 0 ... %d; call ignored", vertexID,
                     n - 1);
        return NULL;
    }
    return h->vertex[h->edge[h->face[polyID].firstEdge + vertexID].fromVert].position;
}

int McdConvexMeshGetPolygonVertexCount(McdConvexMeshID id, int polyID)
{
    CONVEX_OR_RETURN(h, id, 0);
    if (!polygonInRange(h, polyID, __func__))
        return 0;
    return h->face[polyID + 1].firstEdge - h->face[polyID].firstEdge;
}

void McdConvexMeshGetPolygonVertex(McdConvexMeshID id, int polyID, int vertexID, MeVector3 coords)
{
    CONVEX_OR_RETURN(h, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(coords, ME_NOTHING);
    const MeReal *v = polygonVertex(h, polyID, vertexID, __func__);
    if (v)
        MeVector3Copy(coords, v);
}

const MeReal *McdConvexMeshGetPolygonVertexPtr(McdConvexMeshID id, int polyID, int vertexID)
{
    CONVEX_OR_RETURN(h, id, NULL);
    return polygonVertex(h, polyID, vertexID, __func__);
}

void McdConvexMeshGetPolygonNormal(McdConvexMeshID id, int polyID, MeVector3 normal)
{
    CONVEX_OR_RETURN(h, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(normal, ME_NOTHING);
    if (polygonInRange(h, polyID, __func__))
        MeVector3Copy(normal, h->face[polyID].normal);
}

int McdConvexMeshGetVertexCount(McdConvexMeshID id)
{
    CONVEX_OR_RETURN(h, id, 0);
    return h->numVertex;
}

void McdConvexMeshGetVertex(McdConvexMeshID id, int index, MeVector3 position)
{
    CONVEX_OR_RETURN(h, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(position, ME_NOTHING);
    if (index < 0 || index >= h->numVertex) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "index (%d) must lie in 0 ... %d; call ignored", index, h->numVertex - 1);
        return;
    }
    MeVector3Copy(position, h->vertex[index].position);
}

const McdConvexHull *McdConvexMeshGetPolyhedron(McdConvexMeshID id)
{
    CONVEX_OR_RETURN(h, id, NULL);
    return h;
}

MeReal McdConvexMeshGetFatness(McdConvexMeshID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeConvexMesh, __func__);
    return g ? g->u.convex.fatness : 0;
}

MeI16 McdConvexMeshGetMassProperties(McdConvexMeshID id, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    if (!McdGeometryOfType(id, kMcdGeometryTypeConvexMesh, __func__))
        return 1;
    return McdGeometryGetMassProperties(id, relTM, inertia, volume);
}

MeI16 McdConvexMeshGetTypeId(void) { return (MeI16)kMcdGeometryTypeConvexMesh; }

void McdConvexMeshRegisterType(McdFramework *frame) { (void)McdFrameworkFromID(frame, __func__); }

MeBool McdConvexMeshPrimitivesRegisterInteractions(McdFramework *frame)
{
    return McdPrimitivesRegisterInteractions(frame);
}
