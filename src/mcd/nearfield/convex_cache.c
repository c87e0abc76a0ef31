/* convex_cache.c -- the pair cache of convex meshes' pair tests: coherence from frame to frame.
 *
 * A pair that has a convex mesh keeps, in its McdModelPair cache slot, the last direction between
 * the cores (in geometry 1's frame), the side whose polygon was the manifold's reference and, against
 * a plane, the hull's lowest vertex. They serve three ways, none of which changes what a test on a
 * pose reports compared with the uncached test, except where the two sides' faces tie:
 *  - a pair still separated along the cached direction by more than the tolerance has no contact
 *    (a separating axis bounds the distance from below): answered by two support points;
 *  - the reference polygon stays on the side it was on while that side's face is within
 *    MCD_NF_FEATURE_COS of the other's alignment (two resting faces are parallel to rounding, and
 *    the bare comparison would swap them from frame to frame);
 *  - against a plane, the climb to the lowest vertex starts from last frame's. */
#include <karma/MeMemory.h>

#include "../geometry/convex_hull.h"
#include "nearfield.h"

typedef struct McdNfConvexCache {
    MeVector3 axis; /* last core 1 -> core 2 direction, in geometry 1's frame */
    int valid;      /* axis set */
    int refSide;    /* 1 or 2: the reference polygon's side in the last manifold; 0: none yet */
    int vertex;     /* against a plane: the hull's lowest vertex last time */
    int apart;      /* the last test found the pair beyond the tolerance (only then is the axis tried first:
                       a touching pair's axis seldom separates, and trying it would cost two supports) */
} McdNfConvexCache;

void McdNfConvexCacheRelease(void *cache) { MeMemoryDestroy(cache); }

/* The cache in the slot, made on first use; NULL without a slot (aggregates' leaves, terrains) or
 * without memory (the test then runs uncached). */
static McdNfConvexCache *cacheOf(void **slot)
{
    McdNfConvexCache *c;
    if (!slot)
        return NULL;
    if (*slot)
        return *slot;
    c = MeMemoryCreate(sizeof *c);
    if (c) {
        MeVector3Set(c->axis, ME_R(0.0), ME_R(0.0), ME_R(0.0));
        c->valid = 0;
        c->refSide = 0;
        c->vertex = 0;
        c->apart = 0;
    }
    *slot = c;
    return c;
}

/* World direction of a direction in tm's frame, and back. */
static void toWorldDir(MeVector3 out, MeMatrix4 tm, const MeVector3 d)
{
    for (int k = 0; k < 3; k++)
        out[k] = d[0] * tm[0][k] + d[1] * tm[1][k] + d[2] * tm[2][k];
}
static void toLocalDir(MeVector3 out, MeMatrix4 tm, const MeVector3 d)
{
    for (int k = 0; k < 3; k++)
        out[k] = MeVector3Dot(tm[k], d);
}

/* Size: McdNearfieldFn's signature. */
int McdNfConvexMeshConvex(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                          MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdNfConvexCache *c = cacheOf(cache);
    McdNfShape s1, s2;
    McdNfDistance d;
    if (!c)
        return McdNfConvexConvex(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, NULL);
    if (maxContacts <= 0)
        return 0;
    McdNfShapeInit(&s1, g1, tm1);
    McdNfShapeInit(&s2, g2, tm2);
    if (c->valid && c->apart) {
        MeVector3 n, m, a, b;
        toWorldDir(n, tm1, c->axis);
        MeVector3MultiplyScalar(m, n, -ME_R(1.0));
        McdNfCoreSupport(&s1, n, a);
        McdNfCoreSupport(&s2, m, b);
        if (MeVector3Dot(b, n) - MeVector3Dot(a, n) - s1.radius - s2.radius > tolerance)
            return 0;
    }
    McdNfCoreDistance(&s1, &s2, &d);
    if (d.distance > ME_R(0.0) && d.distance - s1.radius - s2.radius <= tolerance)
        McdNfRefineSeparated(&s1, &s2, &d);
    if (MeVector3IsValid(d.normal)) {
        toLocalDir(c->axis, tm1, d.normal);
        c->valid = 1;
    }
    c->apart = d.distance - s1.radius - s2.radius > tolerance;
    if (c->apart)
        return 0;
    return McdNfManifoldCoherent(&s1, &s2, &d, tolerance, contacts, maxContacts, &c->refSide);
}

/* Size: McdNearfieldFn's signature. */
int McdNfConvexMeshPlaneCached(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                               MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdNfConvexCache *c = cacheOf(cache);
    if (c && c->apart && maxContacts > 0) {
        const McdHull *h = g1->u.convex.hull;
        MeVector3 down, local, p, dp;
        MeVector3MultiplyScalar(down, tm2[2], -ME_R(1.0));
        toLocalDir(local, tm1, down);
        c->vertex = McdHullClimb(h, local, c->vertex); /* the lowest vertex */
        McdNfToWorld(p, tm1, h->vertices[c->vertex]);
        MeVector3Subtract(dp, p, tm2[3]);
        if (MeVector3Dot(dp, tm2[2]) - g1->u.convex.fatness > tolerance)
            return 0;
    }
    {
        int n = McdNfConvexMeshPlane(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, NULL);
        if (c)
            c->apart = n == 0;
        return n;
    }
}

McdNfCacheReleaseFn McdNfCacheReleaseFor(McdNearfieldFn fn)
{
    return fn == McdNfConvexMeshConvex || fn == McdNfConvexMeshPlaneCached ? McdNfConvexCacheRelease : NULL;
}
