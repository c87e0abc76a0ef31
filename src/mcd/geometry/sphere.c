/* sphere.c -- the sphere: McdSphere API and its geometry protocol. */
#include <karma/McdSphere.h>

#include "../../me/check.h"
#include "geometry.h"

static void sphereAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdSphereData *s = data;
    for (int j = 0; j < 3; j++) {
        minCorner[j] = tm[3][j] - s->radius;
        maxCorner[j] = tm[3][j] + s->radius;
    }
}

static void sphereBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    MeVector3Set(centre, 0, 0, 0);
    *radius = ((const McdSphereData *)data)->radius;
}

static void sphereSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    MeVector3Copy(point, dir);
    if (!MeVector3NormalizeSafe(point))
        MeVector3Set(point, 0, 0, 1);
    MeVector3Scale(point, ((const McdSphereData *)data)->radius);
}

static void sphereMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g;
    MeReal r = ((const McdSphereData *)data)->radius;
    MeReal v = ME_R(4.0) / 3 * ME_PI * r * r * r;
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, ME_R(0.4) * v * r * r, ME_R(0.4) * v * r * r, ME_R(0.4) * v * r * r);
    *volume = v;
}

static int sphereSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                         MeVector3 normal)
{
    (void)g;
    MeVector3 d, origin = {0, 0, 0};
    MeVector3Subtract(d, p1, p0);
    McdLineInterval iv;
    McdLineIntervalAll(&iv);
    McdLineIntervalBall(&iv, p0, d, origin, ((const McdSphereData *)data)->radius);
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}

const McdGeometryTypeDesc McdSphereTypeDesc = {"Sphere", NULL, sphereAABB, sphereBSphere, sphereSupport,
                                               sphereMass, sphereSegment, NULL};

McdSphereID McdSphereCreate(McdFrameworkID fwId, MeReal radius)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !McdCheckDimension(fw, radius, "radius", MEFALSE, __func__))
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeSphere, __func__);
    if (!g)
        return NULL;
    g->u.sphere.radius = radius;
    return McdGeometryToID(g);
}

MeReal McdSphereGetRadius(McdSphereID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphere, __func__);
    return g ? g->u.sphere.radius : 0;
}

void McdSphereSetRadius(McdSphereID id, MeReal radius)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphere, __func__);
    if (g && McdCheckDimension(g->framework, radius, "radius", MEFALSE, __func__))
        g->u.sphere.radius = radius;
}
