/* plane.c -- every primitive against the plane (internal). The plane is z = 0 of its transform, solid
 * below, normal +z; geometry 1 is the primitive, geometry 2 the plane, so the contact normal (from
 * geometry 2 towards geometry 1) is the plane's normal. Each test lists the primitive's candidate
 * lowest points (a vertex, a sphere's lowest point, a few points of each rim) and keeps those within
 * the tolerance: a face or a cap standing on the plane gets several points, a body on an edge two, on
 * a corner one. */
#include "../geometry/convex_hull.h"
#include "nearfield.h"

/* Contact of a point of the primitive's surface with the plane. */
static int planePoint(McdContact *c, int count, int maxc, MeMatrix4 plane, const MeVector3 p, MeReal tol)
{
    MeVector3 d, on2;
    MeReal h;
    MeVector3Subtract(d, p, plane[3]);
    h = MeVector3Dot(d, plane[2]);
    MeVector3ScaleAndAdd(on2, p, -h, plane[2]);
    return McdNfAddPair(c, count, maxc, p, on2, plane[2], tol, 0);
}

static int finish(McdContact *c, int count, int maxContacts)
{
    int k, dims;
    if (maxContacts > MCD_NF_MAX_CONTACTS)
        maxContacts = MCD_NF_MAX_CONTACTS;
    if (count == 0)
        return 0;
    dims = count >= 3 ? 2 : count - 1;
    count = McdNfReduce(c, count, maxContacts);
    for (k = 0; k < count; k++)
        c[k].dims = (MeI16)dims;
    return count;
}

/* Size: McdNearfieldFn's signature. */
int McdNfSpherePlane(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                     MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    MeVector3 p;
    (void)g2;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    MeVector3ScaleAndAdd(p, tm1[3], -g1->u.sphere.radius, tm2[2]);
    return planePoint(contacts, 0, maxContacts, tm2, p, tolerance);
}

/* Size: McdNearfieldFn's signature. */
int McdNfBoxPlane(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                  MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdContact buf[8];
    const MeReal *h = g1->u.box.radii;
    int k, count = 0;
    (void)g2;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    for (k = 0; k < 8; k++) {
        MeVector3 l, p;
        MeVector3Set(l, (k & 1) ? h[0] : -h[0], (k & 2) ? h[1] : -h[1], (k & 4) ? h[2] : -h[2]);
        McdNfToWorld(p, tm1, l);
        count += planePoint(buf, count, 8, tm2, p, tolerance);
    }
    count = finish(buf, count, maxContacts);
    for (k = 0; k < count; k++)
        contacts[k] = buf[k];
    return count;
}

/* Below this sine of a rim's tilt, the rim direction is made perpendicular to the axis again. */
#define MCD_NF_RIM_SIN ME_R(0.01)

/* Four points of a rim (centre c, unit axis a, radius r), the first the lowest towards the plane. */
/* Size: the contact array being filled, the plane, the rim (centre, axis, radius) and tolerance. */
static int rimPoints(McdContact *c, int count, int maxc, MeMatrix4 plane, const MeVector3 centre,
                     const MeVector3 a, MeReal r, MeReal tol)
{
    MeVector3 u, v, p;
    MeReal mag;
    int k;
    MeVector3ScaleAndAdd(u, plane[2], -MeVector3Dot(plane[2], a), a);
    MeVector3Scale(u, -ME_R(1.0));
    /* u's length is the sine of the tilt. When it is small its direction is partly rounding noise,
     * which need not lie across the axis: take the axial part out again (any direction across the
     * axis is then a rim direction, the lowest one to rounding). */
    mag = MeVector3Magnitude(u);
    if (!MeVector3NormalizeSafe(u))
        McdNfPerpendicular(u, a); /* axis along the plane normal: any rim direction */
    else if (mag < MCD_NF_RIM_SIN) {
        MeVector3MultiplyAdd(u, -MeVector3Dot(u, a), a);
        if (!MeVector3NormalizeSafe(u) || MeVector3Magnitude(u) < ME_R(0.5))
            McdNfPerpendicular(u, a);
    }
    MeVector3Cross(v, a, u);
    for (k = 0; k < 4; k++) {
        MeReal cu = k == 0 ? ME_R(1.0) : (k == 2 ? -ME_R(1.0) : ME_R(0.0));
        MeReal cv = k == 1 ? ME_R(1.0) : (k == 3 ? -ME_R(1.0) : ME_R(0.0));
        MeVector3Copy(p, centre);
        MeVector3MultiplyAdd(p, r * cu, u);
        MeVector3MultiplyAdd(p, r * cv, v);
        count += planePoint(c, count, maxc, plane, p, tol);
    }
    return count;
}

/* Size: McdNearfieldFn's signature. */
int McdNfCylinderPlane(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                       MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdContact buf[8];
    MeVector3 c;
    int k, count = 0;
    (void)g2;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    for (k = 0; k < 2; k++) {
        MeVector3ScaleAndAdd(c, tm1[3], k ? g1->u.cylinder.halfHeight : -g1->u.cylinder.halfHeight, tm1[2]);
        count = rimPoints(buf, count, 8, tm2, c, tm1[2], g1->u.cylinder.radius, tolerance);
    }
    count = finish(buf, count, maxContacts);
    for (k = 0; k < count; k++)
        contacts[k] = buf[k];
    return count;
}

/* Size: McdNearfieldFn's signature. */
int McdNfConePlane(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                   MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const McdConeData *cd = &g1->u.cone;
    McdContact buf[8];
    MeVector3 c;
    int k, count = 0;
    (void)g2;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    MeVector3ScaleAndAdd(c, tm1[3], cd->zLower, tm1[2]);
    count = rimPoints(buf, count, 8, tm2, c, tm1[2], cd->lowerRadius, tolerance);
    MeVector3ScaleAndAdd(c, tm1[3], cd->zUpper, tm1[2]);
    if (cd->upperRadius > ME_R(0.0))
        count = rimPoints(buf, count, 8, tm2, c, tm1[2], cd->upperRadius, tolerance);
    else
        count += planePoint(buf, count, 8, tm2, c, tolerance);
    count = finish(buf, count, maxContacts);
    for (k = 0; k < count; k++)
        contacts[k] = buf[k];
    return count;
}

/* Size: McdNearfieldFn's signature. */
int McdNfSphylPlane(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                    MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdContact buf[2];
    int k, count = 0;
    (void)g2;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    /* The lower end's sphere touches at its lowest point. The upper end's ring (the circle across the
     * axis) gives a second point, on the surface, when the sphyl lies nearly flat. */
    {
        MeReal up = MeVector3Dot(tm1[2], tm2[2]);
        MeReal lowEnd = up > ME_R(0.0) ? -g1->u.sphyl.halfHeight : g1->u.sphyl.halfHeight;
        MeVector3 p, down;
        MeVector3ScaleAndAdd(p, tm1[3], lowEnd, tm1[2]);
        MeVector3MultiplyAdd(p, -g1->u.sphyl.radius, tm2[2]);
        count += planePoint(buf, count, 2, tm2, p, tolerance);
        if (MeFabs(up) <= MCD_NF_FEATURE_SIN) {
            MeVector3ScaleAndAdd(down, tm2[2], -up, tm1[2]); /* plane normal across the axis */
            MeVector3Normalize(down);
            MeVector3ScaleAndAdd(p, tm1[3], -lowEnd, tm1[2]);
            MeVector3MultiplyAdd(p, -g1->u.sphyl.radius, down);
            count += planePoint(buf, count, 2, tm2, p, tolerance);
        }
    }
    count = finish(buf, count, maxContacts);
    for (k = 0; k < count; k++)
        contacts[k] = buf[k];
    return count;
}

/* Height of a hull vertex (local) above the plane. */
static MeReal hullHeight(MeMatrix4 tm1, MeMatrix4 plane, const MeVector3 local)
{
    MeVector3 p, d;
    McdNfToWorld(p, tm1, local);
    MeVector3Subtract(d, p, plane[3]);
    return MeVector3Dot(d, plane[2]);
}

/* Every hull vertex within the tolerance is a candidate; the set is reduced to the deepest and best
 * spread four, whenever 64 are waiting and at the end (so the room needed does not grow with the
 * hull). A rounded hull (fatness r) offers only the vertices of its lowest feature -- those no
 * neighbour lies below by more than MCD_NF_FEATURE_SIN of the edge -- each moved down by r: the
 * lowest points of their balls, on the surface exactly when the feature is level and within
 * r (1 - cos 3 deg) = 1.3e-3 r of it otherwise (another vertex's ball point lies inside the solid). */
/* Size: McdNearfieldFn's signature. */
int McdNfConvexMeshPlane(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                         MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const McdHull *h = g1->u.convex.hull;
    const MeReal fat = g1->u.convex.fatness;
    McdContact buf[64];
    MeVector3 down;
    int k, j, count = 0;
    (void)g2;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    MeVector3MultiplyScalar(down, tm2[2], -fat);
    for (k = 0; k < h->vertexCount; k++) {
        MeVector3 p;
        MeReal hk = hullHeight(tm1, tm2, h->vertices[k]);
        if (hk - fat > tolerance)
            continue;
        if (fat > ME_R(0.0)) {
            MeBool lowest = METRUE;
            for (j = h->neighbourStart[k]; j < h->neighbourStart[k + 1] && lowest; j++) {
                const MeReal *w = h->vertices[h->neighbours[j]];
                lowest = hullHeight(tm1, tm2, w) >=
                         hk - MCD_NF_FEATURE_SIN * MeVector3Distance(w, h->vertices[k]);
            }
            if (!lowest)
                continue;
        }
        McdNfToWorld(p, tm1, h->vertices[k]);
        MeVector3Add(p, p, down);
        if (count == 64)
            count = McdNfReduce(buf, count, MCD_NF_MAX_CONTACTS);
        count += planePoint(buf, count, 64, tm2, p, tolerance);
    }
    count = finish(buf, count, maxContacts);
    for (k = 0; k < count; k++)
        contacts[k] = buf[k];
    return count;
}
