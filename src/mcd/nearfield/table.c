/* table.c -- the built-in pair tests, one entry per unordered pair of primitive types (internal).
 * The framework's interaction table is filled from this list; McdNfCollide runs an entry in either
 * order for the tests and the benchmark. */
#include "../geometry/convex_hull.h"
#include "nearfield.h"
#include "../aggregate/aggregate.h"

static const McdNfPairEntry pairTable[] = {
    {kMcdGeometryTypeSphere, kMcdGeometryTypeSphere, McdNfSphereSphere, "sphere-sphere"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeBox, McdNfSphereBox, "sphere-box"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeCylinder, McdNfSphereCylinder, "sphere-cylinder"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeSphyl, McdNfSphereSphyl, "sphere-sphyl"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeCone, McdNfConvexConvex, "sphere-cone"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeBox, McdNfBoxBox, "box-box"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeCylinder, McdNfConvexConvex, "box-cylinder"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeSphyl, McdNfConvexConvex, "box-sphyl"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeCone, McdNfConvexConvex, "box-cone"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeCylinder, McdNfConvexConvex, "cylinder-cylinder"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeSphyl, McdNfConvexConvex, "cylinder-sphyl"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeCone, McdNfConvexConvex, "cylinder-cone"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeSphyl, McdNfSphylSphyl, "sphyl-sphyl"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeCone, McdNfConvexConvex, "sphyl-cone"},
    {kMcdGeometryTypeCone, kMcdGeometryTypeCone, McdNfConvexConvex, "cone-cone"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypePlane, McdNfSpherePlane, "sphere-plane"},
    {kMcdGeometryTypeBox, kMcdGeometryTypePlane, McdNfBoxPlane, "box-plane"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypePlane, McdNfCylinderPlane, "cylinder-plane"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypePlane, McdNfSphylPlane, "sphyl-plane"},
    {kMcdGeometryTypeCone, kMcdGeometryTypePlane, McdNfConePlane, "cone-plane"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeConvexMesh, McdNfConvexMeshConvex, "sphere-convex"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeConvexMesh, McdNfConvexMeshConvex, "box-convex"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeConvexMesh, McdNfConvexMeshConvex, "cylinder-convex"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeConvexMesh, McdNfConvexMeshConvex, "sphyl-convex"},
    {kMcdGeometryTypeCone, kMcdGeometryTypeConvexMesh, McdNfConvexMeshConvex, "cone-convex"},
    {kMcdGeometryTypeConvexMesh, kMcdGeometryTypeConvexMesh, McdNfConvexMeshConvex, "convex-convex"},
    {kMcdGeometryTypeConvexMesh, kMcdGeometryTypePlane, McdNfConvexMeshPlaneCached, "convex-plane"},
};

const McdNfPairEntry *McdNfPairTable(int *count)
{
    *count = (int)(sizeof pairTable / sizeof pairTable[0]);
    return pairTable;
}

McdNearfieldFn McdNfFind(int type1, int type2, int *swapped)
{
    size_t k;
    for (k = 0; k < sizeof pairTable / sizeof pairTable[0]; k++) {
        if (pairTable[k].type1 == type1 && pairTable[k].type2 == type2) {
            *swapped = 0;
            return pairTable[k].fn;
        }
        if (pairTable[k].type1 == type2 && pairTable[k].type2 == type1) {
            *swapped = 1;
            return pairTable[k].fn;
        }
    }
    *swapped = 0;
    return NULL;
}

MeReal McdNfReachOther(const McdGeometryData *g)
{
    switch (g->type) {
    case kMcdGeometryTypeCylinder: return g->u.cylinder.radius + g->u.cylinder.halfHeight;
    case kMcdGeometryTypeSphyl: return g->u.sphyl.radius + g->u.sphyl.halfHeight;
    case kMcdGeometryTypeCone:
        return g->u.cone.lowerRadius + MeFabs(g->u.cone.zLower) + MeFabs(g->u.cone.zUpper);
    case kMcdGeometryTypeConvexMesh:
        return MeVector3Magnitude(g->u.convex.hull->centre) + g->u.convex.hull->radius + g->u.convex.fatness;
    case kMcdGeometryTypeAggregate: return McdAggregateReach(g);
    default: return ME_R(0.0);
    }
}

/* Whether MeVector3Distance(p, origin) <= bound, decided the same way but without the square root
 * unless |p - origin|² lies within a relative ME_SMALL_EPSILON (several rounding errors) of bound², or
 * is not a number. */
static MeBool withinDistance(const MeVector3 p, const MeVector3 origin, MeReal bound, MeReal boundSqr)
{
    const MeReal d2 = MeVector3DistanceSqr(p, origin);
    if (boundSqr > ME_R(1e-30)) { /* clear of underflow: the margins below are relative */
        if (d2 < boundSqr * (1 - ME_SMALL_EPSILON))
            return METRUE;
        if (d2 > boundSqr * (1 + ME_SMALL_EPSILON))
            return MEFALSE;
    }
    return MeSqrt(d2) <= bound;
}

/* McdNfKeepPlausible's loop, for constant `finiteTests` and `distanceTest` (inlined into each use and
 * specialised): the contacts within [deepest, shallowest] of separation, with a unit normal, finite
 * (`finiteTests`) and within `bound` of `origin` (`distanceTest`), kept in place and the others
 * counted. */
/* Size: the flags and bounds stay separate parameters so that each use, inlined, is specialised. */
static inline int keepIf(McdContact *contacts, int n, MeBool finiteTests, MeBool distanceTest, MeReal deepest,
                         MeReal shallowest, const MeVector3 origin, MeReal bound, MeReal boundSqr)
{
    int kept = 0;
    for (int k = 0; k < n; k++) {
        const McdContact *c = &contacts[k];
        if ((finiteTests ? McdNfContactIsValid(c) : McdNfNormalIsUnit(c)) && c->separation >= deepest &&
            c->separation <= shallowest && (!distanceTest || withinDistance(c->position, origin, bound, boundSqr))) {
            if (kept != k)
                contacts[kept] = *c;
            kept++;
        } else {
            McdNfCountFallback();
        }
    }
    return kept;
}

int McdNfKeepValid(MeReal tolerance, McdContact *contacts, int n)
{
    return keepIf(contacts, n, METRUE, MEFALSE, -MEINFINITY, tolerance * ME_R(1.01), NULL, MEINFINITY, MEINFINITY);
}

int McdNfKeepPlausible(MeReal reach, MeMatrix4 tm1, MeMatrix4 tm2, MeReal tolerance, McdContact *contacts, int n)
{
    const MeReal bound = MeVector3Distance(tm1[3], tm2[3]) + ME_R(2.0) * reach + tolerance;
    const MeReal shallowest = tolerance * ME_R(1.01) + MCD_NF_REL_EPS * bound;
    /* Finite bounds reject by themselves what McdNfContactIsValid's finiteness tests would: a NaN or
     * infinite separation fails the depth range, a NaN or infinite position withinDistance, and a NaN
     * or infinite normal is not of unit length. So with them only the normal's length is tested. */
    const MeBool finiteTests = !(isfinite(bound) && isfinite(shallowest));
    return finiteTests ? keepIf(contacts, n, METRUE, METRUE, -bound, shallowest, tm1[3], bound, bound * bound)
                       : keepIf(contacts, n, MEFALSE, METRUE, -bound, shallowest, tm1[3], bound, bound * bound);
}

/* Size: McdNearfieldFn's arguments, the test to call and the pair's reach. */
int McdNfCallInPairFrame(McdNearfieldFn fn, const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2,
                         MeMatrix4 tm2, MeReal reach, MeReal tolerance, McdContact *contacts, int maxContacts,
                         void **cache)
{
    MeMatrix4 a, b;
    MeVector3 origin;
    int n, k;
    MeVector3Copy(origin, tm1[3]);
    MeMatrix4Copy(a, tm1);
    MeMatrix4Copy(b, tm2);
    MeVector3Set(a[3], ME_R(0.0), ME_R(0.0), ME_R(0.0));
    MeVector3Subtract(b[3], tm2[3], origin);
    n = fn(g1, a, g2, b, tolerance, contacts, maxContacts, cache);
    if (n <= 0 || n > maxContacts)
        return n; /* none, or the dispatcher reports it */
    n = McdNfKeepPlausible(reach, a, b, tolerance, contacts, n);
    for (k = 0; k < n; k++)
        MeVector3Add(contacts[k].position, contacts[k].position, origin);
    return n;
}

/* Size: McdNearfieldFn's arguments without the cache. */
int McdNfCollide(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, MeReal tolerance,
                 McdContact *contacts, int maxContacts)
{
    int swapped, n, k;
    McdNearfieldFn fn = McdNfFind(g1->type, g2->type, &swapped);
    if (!fn)
        return 0;
    if (!swapped)
        return McdNfCallCentred(fn, g1, tm1, g2, tm2, tolerance, contacts, maxContacts, NULL);
    n = McdNfCallCentred(fn, g2, tm2, g1, tm1, tolerance, contacts, maxContacts, NULL);
    for (k = 0; k < n; k++) {
        void *e = contacts[k].element1;
        MeVector3Scale(contacts[k].normal, -ME_R(1.0));
        contacts[k].element1 = contacts[k].element2;
        contacts[k].element2 = e;
    }
    return n;
}
