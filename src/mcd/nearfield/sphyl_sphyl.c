/* sphyl_sphyl.c -- sphyl against sphyl: closest points of the two segments; parallel capsules get
 * the two ends of their common part (internal). */
#include "nearfield.h"

/* Size: McdNearfieldFn's signature. */
int McdNfSphylSphyl(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                    MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdNfShape s1, s2;
    McdNfDistance d;
    MeVector3 p0, p1, q0, q1, e;
    MeReal s, t;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    McdNfShapeInit(&s1, g1, tm1);
    McdNfShapeInit(&s2, g2, tm2);
    MeVector3ScaleAndAdd(p0, tm1[3], -g1->u.sphyl.halfHeight, tm1[2]);
    MeVector3ScaleAndAdd(p1, tm1[3], g1->u.sphyl.halfHeight, tm1[2]);
    MeVector3ScaleAndAdd(q0, tm2[3], -g2->u.sphyl.halfHeight, tm2[2]);
    MeVector3ScaleAndAdd(q1, tm2[3], g2->u.sphyl.halfHeight, tm2[2]);
    McdNfSegmentSegment(p0, p1, q0, q1, &s, &t);
    MeVector3Lerp(d.p1, p0, p1, s);
    MeVector3Lerp(d.p2, q0, q1, t);
    MeVector3Subtract(d.normal, d.p2, d.p1);
    d.distance = MeVector3Magnitude(d.normal);
    if (d.distance - s1.radius - s2.radius > tolerance)
        return 0;
    if (d.distance > MCD_NF_REL_EPS * (s1.size + s2.size))
        MeVector3Scale(d.normal, ME_R(1.0) / d.distance);
    else {
        /* the segments meet: leave across the plane they span (or across a common line) */
        MeVector3Subtract(e, tm2[3], tm1[3]);
        MeVector3Cross(d.normal, tm1[2], tm2[2]);
        if (MeVector3Magnitude(d.normal) > ME_R(1e-3))
            MeVector3Normalize(d.normal);
        else { /* on one line: across it, towards the second centre if it is off the line */
            MeVector3ScaleAndAdd(d.normal, e, -MeVector3Dot(e, tm1[2]), tm1[2]);
            if (!MeVector3NormalizeSafe(d.normal) || MeVector3Magnitude(d.normal) < ME_R(0.5))
                McdNfPerpendicular(d.normal, tm1[2]);
        }
        if (MeVector3Dot(e, d.normal) < ME_R(0.0))
            MeVector3Scale(d.normal, -ME_R(1.0));
        d.distance = ME_R(0.0);
    }
    return McdNfManifold(&s1, &s2, &d, tolerance, contacts, maxContacts);
}
