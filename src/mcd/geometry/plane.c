/* plane.c -- the plane: the half-space z <= 0 of its frame, normal +z; static models only. */
#include <karma/McdPlane.h>

#include "../../me/check.h"
#include "geometry.h"

/* How far a support point goes in an unbounded direction: large, yet finite after a transform
 * (three such terms must not overflow), so that callers never see inf or NaN. */
#define PLANE_FAR ME_R(1e15)
/* A plane normal within this of a world axis bounds the AABB on that axis. */
#define AXIS_ALIGNED ME_R(1e-6)

static void planeAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g, (void)data;
    /* Along world axis j the half-space is bounded only when its normal is parallel to the axis. */
    for (int j = 0; j < 3; j++) {
        MeReal n = tm[2][j];
        minCorner[j] = -MEINFINITY;
        maxCorner[j] = MEINFINITY;
        if (n >= 1 - AXIS_ALIGNED)
            maxCorner[j] = tm[3][j];
        else if (n <= -(1 - AXIS_ALIGNED))
            minCorner[j] = tm[3][j];
    }
}

static void planeBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g, (void)data;
    MeVector3Set(centre, 0, 0, 0);
    *radius = MEINFINITY;
}

static void planeSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g, (void)data;
    point[0] = dir[0] > 0 ? PLANE_FAR : dir[0] < 0 ? -PLANE_FAR : 0;
    point[1] = dir[1] > 0 ? PLANE_FAR : dir[1] < 0 ? -PLANE_FAR : 0;
    point[2] = dir[2] < 0 ? -PLANE_FAR : 0;
}

static void planeMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g, (void)data;
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, 0, 0, 0);
    *volume = 0; /* infinite: no mass properties */
}

static int planeSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                        MeVector3 normal)
{
    (void)g, (void)data;
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    McdLineInterval iv;
    McdLineIntervalAll(&iv);
    McdLineIntervalSlab(&iv, p0, d, 2, -MEINFINITY, 0);
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}

const McdGeometryTypeDesc McdPlaneTypeDesc = {"Plane", NULL, planeAABB, planeBSphere, planeSupport,
                                              planeMass, planeSegment, NULL};

McdPlaneID McdPlaneCreate(McdFrameworkID fwId)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw)
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypePlane, __func__);
    return g ? McdGeometryToID(g) : NULL;
}

void McdPlaneGetNormal(McdPlaneID id, MeMatrix4 tm, MeVector3 normal)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypePlane, __func__);
    ME_CHECK_NOT_NULL(normal, ME_NOTHING);
    if (!g || !tm)
        MeVector3Set(normal, 0, 0, 1);
    else
        MeVector3Copy(normal, tm[2]);
}

MeReal McdPlaneGetDistanceToPoint(McdPlaneID id, MeMatrix4 tm, const MeVector3 point)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypePlane, __func__);
    ME_CHECK_NOT_NULL(point, 0);
    if (!g)
        return 0;
    if (!tm)
        return point[2];
    MeVector3 rel;
    MeVector3Subtract(rel, point, tm[3]);
    return MeVector3Dot(rel, tm[2]);
}
