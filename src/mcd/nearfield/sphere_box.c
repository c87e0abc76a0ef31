/* sphere_box.c -- sphere against box: the box point nearest to the centre, or, for a centre inside
 * the box, the nearest face (internal). */
#include "nearfield.h"

/* Size: McdNearfieldFn's signature. */
int McdNfSphereBox(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                   MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const MeReal r = g1->u.sphere.radius;
    const MeReal *h = g2->u.box.radii;
    MeVector3 p, q, ul, on1, on2, n;
    MeBool inside = METRUE;
    int i;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    MeMatrix4TMInverseTransform(p, tm2, tm1[3]); /* centre in the box frame */
    for (i = 0; i < 3; i++) {
        q[i] = MeCLAMP(p[i], -h[i], h[i]);
        if (q[i] != p[i])
            inside = MEFALSE;
    }
    if (!inside) {
        MeReal dist;
        MeVector3Subtract(ul, p, q); /* box -> sphere */
        dist = MeVector3Normalize(ul);
        if (dist - r > tolerance)
            return 0;
    } else {
        /* the face the centre is nearest to (ties: the lower axis) */
        int k = 0;
        MeReal best = h[0] - MeFabs(p[0]);
        for (i = 1; i < 3; i++)
            if (h[i] - MeFabs(p[i]) < best) {
                best = h[i] - MeFabs(p[i]);
                k = i;
            }
        MeVector3Set(ul, ME_R(0.0), ME_R(0.0), ME_R(0.0));
        ul[k] = p[k] >= ME_R(0.0) ? ME_R(1.0) : -ME_R(1.0);
        q[k] = ul[k] * h[k];
    }
    MeMatrix4TMRotate(n, tm2, ul); /* box towards sphere */
    MeVector3ScaleAndAdd(on1, tm1[3], -r, n);
    McdNfToWorld(on2, tm2, q);
    return McdNfAddPair(contacts, 0, maxContacts, on1, on2, n, tolerance, 0);
}
