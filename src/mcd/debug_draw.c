/* debug_draw.c -- Karma 1.2's wireframes of geometries, models and spaces (McduDebugDraw.h), drawn
 * line by line through MeDebugDrawAPI.line. Every shape is drawn in its local frame and carried to
 * the world by the geometry-to-world transform. */
#include <karma/McduDebugDraw.h>
#include <karma/MeMath.h>

#include "../me/check.h"
#include "framework.h"
#include "geometry/geometry.h"

/* A drawing in progress: where the local frame is and in which colour. */
typedef struct Pen {
    MeReal (*tm)[4];
    MeReal r, g, b;
} Pen;

static void penInit(Pen *pen, MeMatrix4 tm, const MeReal colour[3])
{
    pen->tm = tm;
    pen->r = colour[0];
    pen->g = colour[1];
    pen->b = colour[2];
}

/* One line between two local points. */
static void penLine(const Pen *pen, const MeVector3 a, const MeVector3 b)
{
    MeVector3 wa, wb;
    MeMatrix4TMTransform(wa, pen->tm, a);
    MeMatrix4TMTransform(wb, pen->tm, b);
    MeDebugDrawAPI.line(wa, wb, pen->r, pen->g, pen->b);
}

/* An arc in the local frame: the points centre + radius (cos t e1 + sin t e2), t from t0 to t1. */
typedef struct Arc {
    const MeReal *centre, *e1, *e2;
    MeReal radius, t0, t1;
} Arc;

/* The arc in `segments` lines. */
static void penArc(const Pen *pen, const Arc *arc, int segments)
{
    MeVector3 prev, next;
    for (int i = 0; i <= segments; i++) {
        MeReal t = arc->t0 + (arc->t1 - arc->t0) * (MeReal)i / (MeReal)segments;
        MeReal c = arc->radius * MeCos(t), s = arc->radius * MeSin(t);
        for (int k = 0; k < 3; k++)
            next[k] = arc->centre[k] + c * arc->e1[k] + s * arc->e2[k];
        if (i > 0)
            penLine(pen, prev, next);
        MeVector3Copy(prev, next);
    }
}

static const MeVector3 axisX = {1, 0, 0}, axisY = {0, 1, 0}, axisZ = {0, 0, 1};

/* A full circle of `radius` in the local xy plane at height z. */
static void penCircleZ(const Pen *pen, MeReal z, MeReal radius)
{
    MeVector3 centre = {0, 0, z};
    penArc(pen, &(Arc){centre, axisX, axisY, radius, 0, 2 * ME_PI}, MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS);
}

/* Four lines joining the circle of rLo at zLo to the circle of rHi at zHi (at 0, 90, 180, 270 deg). */
static void penSides(const Pen *pen, MeReal zLo, MeReal rLo, MeReal zHi, MeReal rHi)
{
    static const MeReal dirs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int i = 0; i < 4; i++) {
        MeVector3 a = {rLo * dirs[i][0], rLo * dirs[i][1], zLo}, b = {rHi * dirs[i][0], rHi * dirs[i][1], zHi};
        penLine(pen, a, b);
    }
}

/* The 12 edges of the local box [lo, hi]. */
static void penBox(const Pen *pen, const MeVector3 lo, const MeVector3 hi)
{
    for (int axis = 0; axis < 3; axis++) {
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int corner = 0; corner < 4; corner++) {
            MeVector3 a, b;
            a[u] = b[u] = (corner & 1) ? hi[u] : lo[u];
            a[v] = b[v] = (corner & 2) ? hi[v] : lo[v];
            a[axis] = lo[axis];
            b[axis] = hi[axis];
            penLine(pen, a, b);
        }
    }
}

/* The built-in shapes; returns MEFALSE for a type drawn otherwise. */
static MeBool drawBuiltIn(const McdGeometryData *g, const Pen *pen)
{
    switch (g->type) {
    case kMcdGeometryTypeNull:
        return METRUE;
    case kMcdGeometryTypeSphere: {
        MeVector3 o = {0, 0, 0};
        MeReal r = g->u.sphere.radius;
        int n = MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS;
        penArc(pen, &(Arc){o, axisX, axisY, r, 0, 2 * ME_PI}, n);
        penArc(pen, &(Arc){o, axisY, axisZ, r, 0, 2 * ME_PI}, n);
        penArc(pen, &(Arc){o, axisZ, axisX, r, 0, 2 * ME_PI}, n);
        return METRUE;
    }
    case kMcdGeometryTypeBox: {
        MeVector3 lo;
        MeVector3Copy(lo, g->u.box.radii);
        MeVector3Scale(lo, -1);
        penBox(pen, lo, g->u.box.radii);
        return METRUE;
    }
    case kMcdGeometryTypeCylinder: {
        MeReal r = g->u.cylinder.radius, h = g->u.cylinder.halfHeight;
        penCircleZ(pen, -h, r);
        penCircleZ(pen, h, r);
        penSides(pen, -h, r, h, r);
        return METRUE;
    }
    case kMcdGeometryTypeSphyl: {
        MeReal r = g->u.sphyl.radius, h = g->u.sphyl.halfHeight;
        MeVector3 top = {0, 0, h}, bottom = {0, 0, -h};
        int n = MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS / 2;
        penCircleZ(pen, -h, r);
        penCircleZ(pen, h, r);
        penSides(pen, -h, r, h, r);
        penArc(pen, &(Arc){top, axisX, axisZ, r, 0, ME_PI}, n); /* the caps' half circles */
        penArc(pen, &(Arc){top, axisY, axisZ, r, 0, ME_PI}, n);
        penArc(pen, &(Arc){bottom, axisX, axisZ, r, ME_PI, 2 * ME_PI}, n);
        penArc(pen, &(Arc){bottom, axisY, axisZ, r, ME_PI, 2 * ME_PI}, n);
        return METRUE;
    }
    case kMcdGeometryTypeCone: {
        const McdConeData *c = &g->u.cone;
        penCircleZ(pen, c->zLower, c->lowerRadius);
        if (c->upperRadius > 0)
            penCircleZ(pen, c->zUpper, c->upperRadius);
        penSides(pen, c->zLower, c->lowerRadius, c->zUpper, c->upperRadius);
        return METRUE;
    }
    case kMcdGeometryTypePlane: {
        MeReal s = g->framework->lengthScale;
        MeVector3 lo = {-s, -s, 0}, hi = {s, s, 0}, o = {0, 0, 0}, n = {0, 0, s};
        MeVector3 c1 = {s, -s, 0}, c3 = {-s, s, 0};
        penLine(pen, lo, c1);
        penLine(pen, c1, hi);
        penLine(pen, hi, c3);
        penLine(pen, c3, lo);
        penLine(pen, o, n);
        return METRUE;
    }
    default:
        return MEFALSE;
    }
}

/* Any geometry: built-in shapes, else the type's debugDraw, else its AABB. */
static void drawGeometry(const McdGeometryData *g, MeMatrix4 tm, const MeReal colour[3])
{
    Pen pen;
    penInit(&pen, tm, colour);
    if (drawBuiltIn(g, &pen))
        return;
    const McdGeometryTypeDesc *t = McdGeometryTypeOf(g);
    if (t->debugDraw) {
        const float c[3] = {(float)colour[0], (float)colour[1], (float)colour[2]};
        t->debugDraw(McdGeometryToID(g), McdGeometryShapeData(g), tm, c);
        return;
    }
    MeVector3 lo, hi;
    McdGeometryAABBInternal(g, tm, lo, hi);
    McduDebugDrawAABB(lo, hi, colour);
}

/* Draw a geometry that must be of `type` (reported in `function` otherwise). */
static void drawOfType(McdGeometryID id, int type, MeMatrix4 tm, const MeReal colour[3], const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, tm, ME_NOTHING);
    ME_CHECK_NOT_NULL_IN(function, colour, ME_NOTHING);
    McdGeometryData *g = McdGeometryFromID(id, function);
    if (!g)
        return;
    if (g->type != type) {
        ME_REPORT_IN(function, ME_ERR_WRONG_HANDLE_KIND, "argument is a %s geometry, not a %s; call ignored",
                     McdGeometryTypeOf(g)->typeName,
                     type < g->framework->typeCount && g->framework->types[type].typeName
                         ? g->framework->types[type].typeName
                         : "geometry of this function's type");
        return;
    }
    drawGeometry(g, tm, colour);
}

void MEAPI McduDebugDrawSphere(const McdSphereID sphere, MeMatrix4 tm, const MeReal colour[3])
{
    drawOfType(sphere, kMcdGeometryTypeSphere, tm, colour, __func__);
}

void MEAPI McduDebugDrawBox(const McdBoxID box, MeMatrix4 tm, const MeReal colour[3])
{
    drawOfType(box, kMcdGeometryTypeBox, tm, colour, __func__);
}

void MEAPI McduDebugDrawCylinder(const McdCylinderID cyl, MeMatrix4 tm, const MeReal colour[3])
{
    drawOfType(cyl, kMcdGeometryTypeCylinder, tm, colour, __func__);
}

void MEAPI McduDebugDrawConvex(const McdConvexMeshID convex, MeMatrix4 tm, const MeReal colour[3])
{
    drawOfType(convex, kMcdGeometryTypeConvexMesh, tm, colour, __func__);
}

void MEAPI McduDebugDrawAggregate(const McdAggregateID agg, MeMatrix4 tm, const MeReal colour[3])
{
    drawOfType(agg, kMcdGeometryTypeAggregate, tm, colour, __func__);
}

void MEAPI McduDebugDrawAABB(const MeVector3 min, const MeVector3 max, const MeReal colour[3])
{
    ME_CHECK_NOT_NULL(min, ME_NOTHING);
    ME_CHECK_NOT_NULL(max, ME_NOTHING);
    ME_CHECK_NOT_NULL(colour, ME_NOTHING);
    MeMatrix4 identity;
    Pen pen;
    MeMatrix4TMMakeIdentity(identity);
    penInit(&pen, identity, colour);
    penBox(&pen, min, max);
}

void MEAPI McduDebugDrawGeometry(const McdGeometryID geometry, MeMatrix4Ptr tm, const MeReal colour[3])
{
    ME_CHECK_NOT_NULL(tm, ME_NOTHING);
    ME_CHECK_NOT_NULL(colour, ME_NOTHING);
    McdGeometryData *g = McdGeometryFromID(geometry, __func__);
    if (g)
        drawGeometry(g, tm, colour);
}

/* One model, reported in `function`'s name. */
static void drawModel(McdModelID model, McduDebugDrawFlags flags, const MeReal colour[3], const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, colour, ME_NOTHING);
    McdModelData *m = McdModelFromID(model, function);
    if (!m || !m->geometry)
        return;
    if ((flags & kMcduDebugDrawEnabledOnly) && m->frozen)
        return;
    drawGeometry(m->geometry, m->worldTransform, colour);
    if (flags & kMcduDebugDrawAABB)
        McduDebugDrawAABB(m->aabbMin, m->aabbMax, colour);
}

void MEAPI McduDebugDrawModel(const McdModelID model, McduDebugDrawFlags flags, const MeReal colour[3])
{
    drawModel(model, flags, colour, __func__);
}

void MEAPI McduDebugDrawSpace(const McdSpaceID space, McduDebugDrawFlags flags, const MeReal colour[3])
{
    ME_CHECK_NOT_NULL(colour, ME_NOTHING);
    if (!McdSpaceIsValid(space)) {
        ME_REPORT(ME_ERR_INVALID_HANDLE, "argument 'space' is not a live McdSpaceID; call ignored");
        return;
    }
    McdSpaceModelIterator it;
    McdModelID m;
    McdSpaceModelIteratorBegin(space, &it);
    while (McdSpaceGetModel(space, &it, &m))
        drawModel(m, flags, colour, __func__);
}
