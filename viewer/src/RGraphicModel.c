/* RGraphicModel.c -- graphics from collision geometry: what the model collides with is what is drawn.
 * An aggregate model is drawn element by element, each element's graphic following its geometry
 * instance's world transform (so it is where the collision sees it, nested aggregates included). */
#include <stdlib.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/McdAggregate.h>
#include <karma/McdConvexMesh.h>
#include <karma/McdGeometryInstance.h>
#include <karma/McdRGHeightField.h>
#include <karma/McdTriangleList.h>
#include <karma/McdTriangleMesh.h>

#include "RConvex.h"
#include "RInternal.h"

/** Side of the square drawn for an infinite plane (m). */
#define R_PLANE_SIDE 60
/** Its checkerboard cells (m): metres can be counted on the ground. */
#define R_PLANE_CELL 1.0f

/* The graphic of geometry g following matrix; fn names the caller in messages. */
static RGraphic *geometryGraphic(RRender *rc, McdGeometryID g, float color[4], MeMatrix4Ptr matrix, const char *fn)
{
    if (!rc || !g) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, fn, "NULL %s", rc ? "geometry" : "render context");
        return NULL;
    }
    int type = McdGeometryGetTypeId(g);
    if (type == McdSphereGetTypeId())
        return RGraphicSphereCreate(rc, McdSphereGetRadius(g), color, matrix);
    if (type == McdBoxGetTypeId()) {
        MeReal x, y, z;
        McdBoxGetDimensions(g, &x, &y, &z);
        return RGraphicBoxCreate(rc, x, y, z, color, matrix);
    }
    if (type == McdCylinderGetTypeId())
        return RGraphicCylinderCreate(rc, McdCylinderGetRadius(g), McdCylinderGetHeight(g), color, matrix);
    if (type == McdSphylGetTypeId())
        return RGraphicSphylCreate(rc, McdSphylGetRadius(g), McdSphylGetHeight(g), color, matrix);
    if (type == McdConeGetTypeId())
        return RGraphicFrustumCreate(rc, McdConeGetLowerRadius(g), McdConeGetUpperRadius(g), McdConeGetLowerZ(g),
                                     McdConeGetUpperZ(g), rc->m_sphereRes, color, matrix);
    if (type == McdPlaneGetTypeId()) {
        RGraphic *rg = RGraphicSquareCreate(rc, R_PLANE_SIDE, color, matrix);
        if (rg)
            rg->m_private->checkerCell = R_PLANE_CELL;
        return rg;
    }
    if (type == McdConvexMeshGetTypeId())
        return RGraphicConvexCreate(rc, g, color, matrix);
    if (type == McdAggregateGetTypeId())
        return RGraphicAggregateCreate(rc, g, color, matrix);
    if (type == McdTriangleMeshGetTypeId())
        return RGraphicTriangleMeshCreate(rc, g, color, matrix);
    if (type == McdRGHeightFieldGetTypeId())
        return RGraphicHeightFieldCreate(rc, g, color, matrix);
    R_REPORT(ME_ERR_WRONG_HANDLE_KIND, fn, "cannot draw a geometry of type %s%s", McdGeometryGetTypeName(g),
             type == McdTriangleListGetTypeId() ? " (its triangles exist only inside its generator's queries)" : "");
    return NULL;
}

RGraphic *MEAPI RGraphicCreateFromGeometry(RRender *rc, McdGeometryID g, float color[4])
{
    return geometryGraphic(rc, g, color, NULL, "RGraphicCreateFromGeometry");
}

/* Row-vector transforms (Karma's): out = a then b, i.e. p·a·b. out may not alias a or b. */
static void compose(MeReal out[4][4], const MeReal a[4][4], const MeReal b[4][4])
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            MeReal s = 0;
            for (int k = 0; k < 4; k++)
                s += a[i][k] * b[k][j];
            out[i][j] = s;
        }
}

/* Growing vertex array of RGraphicAggregateCreate. */
typedef struct Vertices {
    RObjectVertex *v;
    int n, capacity;
} Vertices;

/* Append the elements of aggregate ag placed by rel (element to the aggregate's frame). Returns 0
 * when out of memory. */
static int appendElements(RRender *rc, McdGeometryID ag, const MeReal rel[4][4], Vertices *out)
{
    int slots = McdAggregateGetElementCountMax(ag);
    for (int i = 0; i < slots; i++) {
        McdGeometryID g = McdAggregateGetElementGeometry(ag, i);
        if (!g)
            continue;
        MeReal placed[4][4];
        compose(placed, (const MeReal(*)[4])McdAggregateGetElementTransformPtr(ag, i), rel);
        if (McdGeometryGetTypeId(g) == McdAggregateGetTypeId()) {
            if (!appendElements(rc, g, (const MeReal(*)[4])placed, out))
                return 0;
            continue;
        }
        RGraphic *e = geometryGraphic(rc, g, NULL, NULL, "RGraphicAggregateCreate");
        if (!e)
            continue; /* reported: an element it cannot draw is left out */
        int n = e->m_pObject->m_nNumVertices;
        if (out->n + n > out->capacity) {
            int capacity = 2 * (out->n + n);
            RObjectVertex *v = realloc(out->v, sizeof *v * (size_t)capacity);
            if (!v) {
                RGraphicDelete(rc, e, 0);
                return 0;
            }
            out->v = v, out->capacity = capacity;
        }
        for (int k = 0; k < n; k++) {
            const RObjectVertex *s = &e->m_pVertices[k];
            RObjectVertex *d = &out->v[out->n + k];
            double p[3] = {s->m_X, s->m_Y, s->m_Z}, q[3] = {s->m_NX, s->m_NY, s->m_NZ};
            AcmeReal *dp[3] = {&d->m_X, &d->m_Y, &d->m_Z}, *dq[3] = {&d->m_NX, &d->m_NY, &d->m_NZ};
            for (int j = 0; j < 3; j++) {
                *dp[j] = (AcmeReal)(p[0] * placed[0][j] + p[1] * placed[1][j] + p[2] * placed[2][j] + placed[3][j]);
                *dq[j] = (AcmeReal)(q[0] * placed[0][j] + q[1] * placed[1][j] + q[2] * placed[2][j]);
            }
            d->m_U = s->m_U, d->m_V = s->m_V;
        }
        out->n += n;
        RGraphicDelete(rc, e, 0);
    }
    return 1;
}

RGraphic *MEAPI RGraphicAggregateCreate(RRender *rc, McdAggregateID ag, float color[4], MeMatrix4Ptr tm)
{
    if (!rc || !ag) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicAggregateCreate", "NULL %s", rc ? "aggregate" : "render context");
        return NULL;
    }
    if (McdGeometryGetTypeId(ag) != McdAggregateGetTypeId()) {
        R_REPORT(ME_ERR_WRONG_HANDLE_KIND, "RGraphicAggregateCreate", "a %s is not an aggregate",
                 McdGeometryGetTypeName(ag));
        return NULL;
    }
    static const MeReal identity[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    Vertices all = {NULL, 0, 0};
    RGraphic *rg = NULL;
    if (appendElements(rc, ag, identity, &all)) {
        rg = RGraphicNew(rc, kRKindTriangles, all.n, color, tm);
        if (rg && all.n > 0)
            memcpy(rg->m_pVertices, all.v, sizeof *all.v * (size_t)all.n);
    }
    free(all.v);
    return rg;
}

/* Chain a graphic for each element under instance `ins` (an aggregate's) after *last, each following
 * its child instance's world transform. */
static void addElementGraphics(RRender *rc, McdGeometryInstanceID ins, float color[4], RGraphic **last)
{
    int slots = McdAggregateGetElementCountMax(McdGeometryInstanceGetGeometry(ins));
    for (int i = 0; i < slots; i++) {
        McdGeometryInstanceID child = McdGeometryInstanceGetChild(ins, i);
        McdGeometryID g = child ? McdGeometryInstanceGetGeometry(child) : NULL;
        if (!g)
            continue;
        if (McdGeometryGetTypeId(g) == McdAggregateGetTypeId()) {
            addElementGraphics(rc, child, color, last);
            continue;
        }
        RGraphic *e = geometryGraphic(rc, g, color, McdGeometryInstanceGetTransformPtr(child), "RGraphicCreateFromModel");
        if (e) {
            (*last)->m_private->part = e;
            *last = e;
        }
    }
}

RGraphic *MEAPI RGraphicCreateFromModel(RRender *rc, McdModelID m, float color[4])
{
    if (!m) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicCreateFromModel", "NULL model");
        return NULL;
    }
    McdGeometryID g = McdModelGetGeometry(m);
    if (!rc || !g || McdGeometryGetTypeId(g) != McdAggregateGetTypeId())
        return geometryGraphic(rc, g, color, McdModelGetTransformPtr(m), "RGraphicCreateFromModel");
    /* The model's graphic holds no vertices: it follows the model and carries the elements. */
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 0, color, McdModelGetTransformPtr(m)), *last = rg;
    if (rg)
        addElementGraphics(rc, McdModelGetGeometryInstance(m), color, &last);
    return rg;
}
