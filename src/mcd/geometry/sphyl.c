/* sphyl.c -- the sphyl (capsule) along local z: McdSphyl API and its protocol.
 *
 * The set of points within `radius` of the segment z in [-halfHeight, halfHeight]; Karma's `height`
 * is the segment's length (the cylindrical part). */
#include <karma/McdSphyl.h>

#include "../../me/check.h"
#include "geometry.h"

static void sphylAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdSphylData *s = data;
    const McdAxialShape shape = {-s->halfHeight, 0, s->halfHeight, 0, s->radius};
    McdAABBOfAxialShape(tm, &shape, minCorner, maxCorner);
}

static void sphylBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    const McdSphylData *s = data;
    MeVector3Set(centre, 0, 0, 0);
    *radius = s->halfHeight + s->radius;
}

static void sphylSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdSphylData *s = data;
    MeVector3 u;
    MeVector3Copy(u, dir);
    if (!MeVector3NormalizeSafe(u))
        MeVector3Set(u, 0, 0, 1);
    MeVector3Scale(u, s->radius);
    MeVector3Set(point, u[0], u[1], u[2] + (dir[2] < 0 ? -s->halfHeight : s->halfHeight));
}

static void sphylMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g;
    const McdSphylData *s = data;
    MeReal r = s->radius, r2 = r * r, h = s->halfHeight, len = 2 * h;
    MeReal vCyl = ME_PI * r2 * len, vBall = ME_R(4.0) / 3 * ME_PI * r2 * r;
    /* Each hemisphere (mass vBall/2) has its centroid 3r/8 beyond its flat face at z = +-h; the
     * parallel-axis theorem about the sphyl's centre gives vBall (2r^2/5 + h^2 + 3hr/4) for both. */
    MeReal ixx = vCyl * (3 * r2 + len * len) / 12 + vBall * (ME_R(0.4) * r2 + h * h + ME_R(0.75) * h * r);
    MeReal izz = vCyl * r2 / 2 + ME_R(0.4) * vBall * r2;
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, ixx, ixx, izz);
    *volume = vCyl + vBall;
}

static int sphylSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                        MeVector3 normal)
{
    (void)g;
    const McdSphylData *s = data;
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    /* A union of a cylinder and two balls: the first entry into any of them. */
    McdLineInterval parts[3];
    MeVector3 top = {0, 0, s->halfHeight}, bottom = {0, 0, -s->halfHeight};
    for (int i = 0; i < 3; i++)
        McdLineIntervalAll(&parts[i]);
    McdLineIntervalSlab(&parts[0], p0, d, 2, -s->halfHeight, s->halfHeight);
    McdLineIntervalCone(&parts[0], p0, d, s->radius, 0);
    McdLineIntervalBall(&parts[1], p0, d, top, s->radius);
    McdLineIntervalBall(&parts[2], p0, d, bottom, s->radius);
    MeBool hit = MEFALSE;
    for (int i = 0; i < 3; i++) {
        MeReal ti;
        MeVector3 ni;
        if (McdLineIntervalToSegmentHit(&parts[i], d, &ti, ni) && (!hit || ti < *t)) {
            hit = METRUE;
            *t = ti;
            MeVector3Copy(normal, ni);
        }
    }
    return hit;
}

const McdGeometryTypeDesc McdSphylTypeDesc = {"Sphyl", NULL, sphylAABB, sphylBSphere, sphylSupport,
                                              sphylMass, sphylSegment, NULL};

McdSphylID McdSphylCreate(McdFrameworkID fwId, MeReal radius, MeReal height)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !McdCheckDimension(fw, radius, "radius", MEFALSE, __func__) ||
        !McdCheckDimension(fw, height, "height", METRUE, __func__))
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeSphyl, __func__);
    if (!g)
        return NULL;
    g->u.sphyl.radius = radius;
    g->u.sphyl.halfHeight = ME_R(0.5) * height;
    return McdGeometryToID(g);
}

MeReal McdSphylGetRadius(McdSphylID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphyl, __func__);
    return g ? g->u.sphyl.radius : 0;
}

void McdSphylSetRadius(McdSphylID id, MeReal radius)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphyl, __func__);
    if (g && McdCheckDimension(g->framework, radius, "radius", MEFALSE, __func__))
        g->u.sphyl.radius = radius;
}

MeReal McdSphylGetHeight(McdSphylID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphyl, __func__);
    return g ? 2 * g->u.sphyl.halfHeight : 0;
}

void McdSphylSetHeight(McdSphylID id, MeReal height)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphyl, __func__);
    if (g && McdCheckDimension(g->framework, height, "height", METRUE, __func__))
        g->u.sphyl.halfHeight = ME_R(0.5) * height;
}

MeReal McdSphylGetHalfHeight(McdSphylID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeSphyl, __func__);
    return g ? g->u.sphyl.halfHeight : 0;
}
