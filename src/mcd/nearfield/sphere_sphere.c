/* sphere_sphere.c -- sphere against sphere: the line of centres (internal). */
#include "nearfield.h"

/* Size: McdNearfieldFn's signature. */
int McdNfSphereSphere(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                      MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const MeReal r1 = g1->u.sphere.radius, r2 = g2->u.sphere.radius;
    MeVector3 n, on1, on2;
    MeReal dist;
    (void)cache;
    MeVector3Subtract(n, tm1[3], tm2[3]); /* sphere 2 towards sphere 1 */
    dist = MeVector3Magnitude(n);
    if (dist - r1 - r2 > tolerance || maxContacts <= 0)
        return 0;
    if (dist > ME_MIN_EPSILON * (r1 + r2))
        MeVector3Scale(n, ME_R(1.0) / dist);
    else /* coincident centres: every direction is as good; sphere 1 leaves along +z (stated in docs) */
        MeVector3Set(n, ME_R(0.0), ME_R(0.0), ME_R(1.0));
    MeVector3ScaleAndAdd(on1, tm1[3], -r1, n);
    MeVector3ScaleAndAdd(on2, tm2[3], r2, n);
    return McdNfAddPair(contacts, 0, maxContacts, on1, on2, n, tolerance, 0);
}
