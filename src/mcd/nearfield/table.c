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

/* A bound on a built-in primitive's distance from its origin (0 for the plane, which has no size, and
 * for types this file does not know). */
static inline MeReal reachOf(const McdGeometryData *g)
{
    switch (g->type) {
    case kMcdGeometryTypeSphere: return g->u.sphere.radius;
    case kMcdGeometryTypeBox: return MeFabs(g->u.box.radii[0]) + MeFabs(g->u.box.radii[1]) + MeFabs(g->u.box.radii[2]);
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

/* Keep the contacts a pair test could have meant: finite, unit normal, not beyond the tolerance, and
 * (built-in types, whose reach `reach` is the sum of the two shapes' reachOf) no deeper and no farther
 * from geometry 1 than the two shapes reach. Others are dropped and counted: they come from arithmetic
 * beyond the precision (an aspect ratio of 1e11 in float, say). */
static int keepPlausible(MeBool builtIn, MeReal reach, MeMatrix4 tm1, MeMatrix4 tm2, MeReal tolerance,
                         McdContact *contacts, int n)
{
    MeReal bound = MEINFINITY, boundSqr = MEINFINITY;
    int k, kept = 0;
    if (n == 0)
        return 0; /* most pairs of a scene: boxes that overlap, shapes that do not touch */
    if (builtIn) {
        bound = MeVector3Distance(tm1[3], tm2[3]) + ME_R(2.0) * reach + tolerance;
        boundSqr = bound * bound;
    }
    const MeReal deepest = -bound;
    const MeReal shallowest = tolerance * ME_R(1.01) + MCD_NF_REL_EPS * (builtIn ? bound : ME_R(0.0));
    for (k = 0; k < n; k++) {
        const McdContact *c = &contacts[k];
        if (McdNfContactIsValid(c) && c->separation >= deepest && c->separation <= shallowest &&
            (!builtIn || withinDistance(c->position, tm1[3], bound, boundSqr))) {
            if (kept != k)
                contacts[kept] = *c;
            kept++;
        } else {
            McdNfCountFallback();
        }
    }
    return kept;
}

int McdNfCallCentred(McdNearfieldFn fn, const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2,
                     MeMatrix4 tm2, MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    const MeBool builtIn = g1->type < kMcdGeometryBuiltInTypes && g2->type < kMcdGeometryBuiltInTypes;
    const MeReal reach = builtIn ? reachOf(g1) + reachOf(g2) : ME_R(0.0);
    int n, k;
    /* Near the origin (within MCD_NF_CENTRE_RATIO sizes of the pair) rounding of the world coordinates
     * costs nothing worth the copies: the test sees the models' own transforms. User types too. */
    if (!builtIn ||
        !(MeMAX3(MeFabs(tm1[3][0]), MeFabs(tm1[3][1]), MeFabs(tm1[3][2])) > MCD_NF_CENTRE_RATIO * reach)) {
        n = fn(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, cache);
        if (n < 0 || n > maxContacts)
            return n; /* the dispatcher reports it */
        return keepPlausible(builtIn, reach, tm1, tm2, tolerance, contacts, n);
    }
    MeMatrix4 a, b;
    MeVector3 origin;
    MeVector3Copy(origin, tm1[3]);
    MeMatrix4Copy(a, tm1);
    MeMatrix4Copy(b, tm2);
    MeVector3Set(a[3], ME_R(0.0), ME_R(0.0), ME_R(0.0));
    MeVector3Subtract(b[3], tm2[3], origin);
    n = fn(g1, a, g2, b, tolerance, contacts, maxContacts, cache);
    if (n < 0 || n > maxContacts)
        return n;
    n = keepPlausible(builtIn, reach, a, b, tolerance, contacts, n);
    for (k = 0; k < n; k++)
        MeVector3Add(contacts[k].position, contacts[k].position, origin);
    return n;
}

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
