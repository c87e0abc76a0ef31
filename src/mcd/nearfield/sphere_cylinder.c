/* sphere_cylinder.c -- sphere against cylinder: the nearest point of the solid cylinder, or, for a
 * centre inside it, the nearest of the side and the caps (internal). */
#include "nearfield.h"

/* Size: McdNearfieldFn's signature. */
int McdNfSphereCylinder(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                        MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const MeReal r = g1->u.sphere.radius, R = g2->u.cylinder.radius, hh = g2->u.cylinder.halfHeight;
    MeVector3 p, q, ul, n, on1, on2;
    MeReal rho, ux = ME_R(1.0), uy = ME_R(0.0);
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    MeMatrix4TMInverseTransform(p, tm2, tm1[3]);
    rho = MeSqrt(p[0] * p[0] + p[1] * p[1]);
    if (rho > ME_MIN_EPSILON * R) {
        ux = p[0] / rho;
        uy = p[1] / rho;
    }
    if (rho <= R && MeFabs(p[2]) <= hh) { /* centre inside: leave by the nearer surface */
        if (hh - MeFabs(p[2]) <= R - rho) {
            MeVector3Set(ul, ME_R(0.0), ME_R(0.0), p[2] >= ME_R(0.0) ? ME_R(1.0) : -ME_R(1.0));
            MeVector3Set(q, p[0], p[1], ul[2] * hh);
        } else {
            MeVector3Set(ul, ux, uy, ME_R(0.0));
            MeVector3Set(q, R * ux, R * uy, p[2]);
        }
    } else {
        MeReal rc = MeMIN(rho, R), dist;
        MeVector3Set(q, rc * ux, rc * uy, MeCLAMP(p[2], -hh, hh));
        MeVector3Subtract(ul, p, q);
        dist = MeVector3Normalize(ul);
        if (dist - r > tolerance)
            return 0;
    }
    MeMatrix4TMRotate(n, tm2, ul); /* cylinder towards sphere */
    MeVector3ScaleAndAdd(on1, tm1[3], -r, n);
    McdNfToWorld(on2, tm2, q);
    return McdNfAddPair(contacts, 0, maxContacts, on1, on2, n, tolerance, 0);
}
