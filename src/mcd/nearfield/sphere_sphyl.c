/* sphere_sphyl.c -- sphere against sphyl (capsule): the centre against the capsule's segment. */
#include "nearfield.h"

/* Size: McdNearfieldFn's signature. */
int McdNfSphereSphyl(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                     MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const MeReal r1 = g1->u.sphere.radius, r2 = g2->u.sphyl.radius, hh = g2->u.sphyl.halfHeight;
    MeVector3 p, q, n, on1, on2;
    MeReal dist;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    MeMatrix4TMInverseTransform(p, tm2, tm1[3]);
    MeVector3Set(q, ME_R(0.0), ME_R(0.0), MeCLAMP(p[2], -hh, hh)); /* nearest segment point */
    McdNfToWorld(q, tm2, q);
    MeVector3Subtract(n, tm1[3], q); /* sphyl's segment towards the centre */
    dist = MeVector3Magnitude(n);
    if (dist - r1 - r2 > tolerance)
        return 0;
    if (dist > ME_MIN_EPSILON * (r1 + r2))
        MeVector3Scale(n, ME_R(1.0) / dist);
    else /* centre on the segment: any direction across the axis */
        McdNfPerpendicular(n, tm2[2]);
    MeVector3ScaleAndAdd(on1, tm1[3], -r1, n);
    MeVector3ScaleAndAdd(on2, q, r2, n);
    return McdNfAddPair(contacts, 0, maxContacts, on1, on2, n, tolerance, 0);
}
