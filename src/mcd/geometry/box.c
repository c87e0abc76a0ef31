/* box.c -- the box (full edge lengths in, half extents stored): McdBox API and its protocol. */
#include <karma/McdBox.h>

#include "../../me/check.h"
#include "geometry.h"

static void boxAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdBoxData *b = data;
    MeVector3 lo = {-b->radii[0], -b->radii[1], -b->radii[2]};
    McdAABBOfLocalBox(tm, lo, b->radii, minCorner, maxCorner);
}

static void boxBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    MeVector3Set(centre, 0, 0, 0);
    *radius = MeVector3Magnitude(((const McdBoxData *)data)->radii);
}

static void boxSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdBoxData *b = data;
    for (int i = 0; i < 3; i++)
        point[i] = dir[i] < 0 ? -b->radii[i] : b->radii[i];
}

static void boxMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g;
    const McdBoxData *b = data;
    MeReal x2 = 4 * b->radii[0] * b->radii[0], y2 = 4 * b->radii[1] * b->radii[1], z2 = 4 * b->radii[2] * b->radii[2];
    MeReal v = 8 * b->radii[0] * b->radii[1] * b->radii[2];
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, v * (y2 + z2) / 12, v * (x2 + z2) / 12, v * (x2 + y2) / 12);
    *volume = v;
}

static int boxSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                      MeVector3 normal)
{
    (void)g;
    const McdBoxData *b = data;
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    McdLineInterval iv;
    McdLineIntervalAll(&iv);
    for (int i = 0; i < 3; i++)
        McdLineIntervalSlab(&iv, p0, d, i, -b->radii[i], b->radii[i]);
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}

const McdGeometryTypeDesc McdBoxTypeDesc = {"Box", NULL, boxAABB, boxBSphere, boxSupport, boxMass, boxSegment, NULL};

static MeBool checkDimensions(const McdFrameworkData *fw, MeReal dx, MeReal dy, MeReal dz, const char *function)
{
    return McdCheckDimension(fw, dx, "dx", MEFALSE, function) && McdCheckDimension(fw, dy, "dy", MEFALSE, function) &&
           McdCheckDimension(fw, dz, "dz", MEFALSE, function);
}

McdBoxID McdBoxCreate(McdFrameworkID fwId, MeReal dx, MeReal dy, MeReal dz)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !checkDimensions(fw, dx, dy, dz, __func__))
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeBox, __func__);
    if (!g)
        return NULL;
    MeVector3Set(g->u.box.radii, ME_R(0.5) * dx, ME_R(0.5) * dy, ME_R(0.5) * dz);
    return McdGeometryToID(g);
}

MeReal *McdBoxGetRadii(McdBoxID id)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeBox, __func__);
    return g ? g->u.box.radii : NULL; /* geometries live in a pool slot: the pointer stays valid */
}

void McdBoxGetXYAABB(McdBoxID id, MeMatrix4 tm, MeReal bounds[4])
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeBox, __func__);
    if (g)
        McdGeometryXYAABB(g, tm, bounds, __func__);
}

void McdBoxMaximumPointLocal(McdBoxID id, MeReal *inDir, MeReal *outPoint)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeBox, __func__);
    if (g)
        McdGeometryMaximumPointLocalChecked(g, inDir, outPoint, __func__);
}

void McdBoxGetDimensions(McdBoxID id, MeReal *dx, MeReal *dy, MeReal *dz)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeBox, __func__);
    ME_CHECK_NOT_NULL(dx, ME_NOTHING);
    ME_CHECK_NOT_NULL(dy, ME_NOTHING);
    ME_CHECK_NOT_NULL(dz, ME_NOTHING);
    *dx = g ? 2 * g->u.box.radii[0] : 0;
    *dy = g ? 2 * g->u.box.radii[1] : 0;
    *dz = g ? 2 * g->u.box.radii[2] : 0;
}

void McdBoxSetDimensions(McdBoxID id, MeReal dx, MeReal dy, MeReal dz)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeBox, __func__);
    if (g && checkDimensions(g->framework, dx, dy, dz, __func__))
        MeVector3Set(g->u.box.radii, ME_R(0.5) * dx, ME_R(0.5) * dy, ME_R(0.5) * dz);
}
