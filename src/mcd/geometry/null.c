/* null.c -- the null geometry: no extent, no mass, touches nothing. */
#include <karma/McdNull.h>

#include "geometry.h"

static void nullAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g, (void)data;
    MeVector3Copy(minCorner, tm[3]);
    MeVector3Copy(maxCorner, tm[3]);
}

static void nullBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g, (void)data;
    MeVector3Set(centre, 0, 0, 0);
    *radius = 0;
}

static void nullSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g, (void)data, (void)dir;
    MeVector3Set(point, 0, 0, 0);
}

static void nullMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g, (void)data;
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, 0, 0, 0);
    *volume = 0;
}

const McdGeometryTypeDesc McdNullTypeDesc = {"Null", NULL, nullAABB, nullBSphere, nullSupport, nullMass, NULL, NULL};

McdNullID McdNullCreate(McdFrameworkID fwId)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw)
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeNull, __func__);
    return g ? McdGeometryToID(g) : NULL;
}
