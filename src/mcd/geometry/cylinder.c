/* cylinder.c -- the cylinder along local z, origin at half height: McdCylinder API and protocol. */
#include <karma/McdCylinder.h>

#include "../../me/check.h"
#include "geometry.h"

static void cylinderAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdCylinderData *c = data;
    const McdAxialShape shape = {-c->halfHeight, c->radius, c->halfHeight, c->radius, 0};
    McdAABBOfAxialShape(tm, &shape, minCorner, maxCorner);
}

static void cylinderBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    const McdCylinderData *c = data;
    MeVector3Set(centre, 0, 0, 0);
    *radius = MeSqrt(c->radius * c->radius + c->halfHeight * c->halfHeight);
}

static void cylinderSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdCylinderData *c = data;
    McdDiscSupport(dir, c->radius, dir[2] < 0 ? -c->halfHeight : c->halfHeight, point);
}

static void cylinderMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g;
    const McdCylinderData *c = data;
    MeReal r2 = c->radius * c->radius, h = 2 * c->halfHeight;
    MeReal v = ME_PI * r2 * h;
    MeReal ixx = v * (3 * r2 + h * h) / 12;
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, ixx, ixx, v * r2 / 2);
    *volume = v;
}

static int cylinderSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                           MeVector3 normal)
{
    (void)g;
    const McdCylinderData *c = data;
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    McdLineInterval iv;
    McdLineIntervalAll(&iv);
    McdLineIntervalSlab(&iv, p0, d, 2, -c->halfHeight, c->halfHeight);
    McdLineIntervalCone(&iv, p0, d, c->radius, 0);
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}

const McdGeometryTypeDesc McdCylinderTypeDesc = {"Cylinder", NULL, cylinderAABB, cylinderBSphere, cylinderSupport,
                                                 cylinderMass, cylinderSegment, NULL};

McdCylinderID McdCylinderCreate(McdFrameworkID fwId, MeReal radius, MeReal height)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !McdCheckDimension(fw, radius, "radius", MEFALSE, __func__) ||
        !McdCheckDimension(fw, height, "height", MEFALSE, __func__))
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeCylinder, __func__);
    if (!g)
        return NULL;
    g->u.cylinder.radius = radius;
    g->u.cylinder.halfHeight = ME_R(0.5) * height;
    return McdGeometryToID(g);
}

MeReal McdCylinderGetRadius(McdCylinderID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    return g ? g->u.cylinder.radius : 0;
}

void McdCylinderSetRadius(McdCylinderID id, MeReal radius)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    if (g && McdCheckDimension(g->framework, radius, "radius", MEFALSE, __func__))
        g->u.cylinder.radius = radius;
}

MeReal McdCylinderGetHeight(McdCylinderID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    return g ? 2 * g->u.cylinder.halfHeight : 0;
}

void McdCylinderSetHeight(McdCylinderID id, MeReal height)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    if (g && McdCheckDimension(g->framework, height, "height", MEFALSE, __func__))
        g->u.cylinder.halfHeight = ME_R(0.5) * height;
}

MeReal McdCylinderGetHalfHeight(McdCylinderID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    return g ? g->u.cylinder.halfHeight : 0;
}

void McdCylinderSetGeometricalParameters(McdCylinderID id, MeReal inRadius, MeReal inHeight)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    if (g && McdCheckDimension(g->framework, inRadius, "inRadius", MEFALSE, __func__) &&
        McdCheckDimension(g->framework, inHeight, "inHeight", MEFALSE, __func__)) {
        g->u.cylinder.radius = inRadius;
        g->u.cylinder.halfHeight = ME_R(0.5) * inHeight;
    }
}

void McdCylinderGetXYAABB(McdCylinderID id, MeMatrix4 tm, MeReal bounds[4])
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    if (g)
        McdGeometryXYAABB(g, tm, bounds, __func__);
}

void McdCylinderMaximumPointLocal(McdCylinderID id, MeReal *inDir, MeReal *outPoint)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCylinder, __func__);
    if (g)
        McdGeometryMaximumPointLocalChecked(g, inDir, outPoint, __func__);
}
