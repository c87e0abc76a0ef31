/* collide.c -- a convex primitive or a convex mesh against the triangles of a terrain (triangle
 * list, mesh, height field): one triangle at a time through the nearfield's GJK/EPA and clipped manifold, with the
 * internal edges suppressed, then the deepest and best spread four of all (internal).
 *
 * Everything runs in the terrain's frame (the convex is placed there), so a small body on a large
 * terrain keeps its own precision. Internal edges: a triangle's contact normal comes from GJK/EPA on
 * that triangle alone; where the triangle's point of contact lies on an edge or a vertex that is not
 * "in use" (an internal flat or concave edge, or Karma's flags), that normal would snag a body
 * sliding across the edge, so the face normal is used instead, and only the contacts over the
 * triangle itself are kept (its neighbour gives the others). One-sided triangles push along +normal
 * only; two-sided ones along the face normal on the convex's side. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "../geometry/geometry.h"
#include "../nearfield/nearfield.h"
#include "terrain.h"

/* Contacts gathered before the reduction to four. */
#define GATHER_MAX 64
/* A triangle point counts as on an edge within this fraction of the triangle's size. */
#define ON_EDGE_FRACTION ME_R(1e-3)

static MeMatrix4 identityTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

typedef struct Gather {
    McdNfShape convex;
    MeVector3 centre; /* the convex's centre (terrain frame) */
    MeReal tolerance;
    McdContact buf[GATHER_MAX];
    int count;
} Gather;

/* Barycentric weights of p (projected on the triangle's plane). */
static void barycentric(const McdTerrainTriangle *t, const MeVector3 p, MeReal w[3])
{
    MeVector3 e0, e1, dp;
    MeVector3Subtract(e0, t->v[1], t->v[0]);
    MeVector3Subtract(e1, t->v[2], t->v[0]);
    MeVector3Subtract(dp, p, t->v[0]);
    MeReal d00 = MeVector3Dot(e0, e0), d01 = MeVector3Dot(e0, e1), d11 = MeVector3Dot(e1, e1);
    MeReal d20 = MeVector3Dot(dp, e0), d21 = MeVector3Dot(dp, e1);
    MeReal den = d00 * d11 - d01 * d01;
    if (!(den > ME_R(0.0))) {
        w[0] = w[1] = w[2] = ME_R(1.0) / ME_R(3.0);
        return;
    }
    w[1] = (d11 * d20 - d01 * d21) / den;
    w[2] = (d00 * d21 - d01 * d20) / den;
    w[0] = ME_R(1.0) - w[1] - w[2];
}

/* Whether the triangle's contact point p may carry a normal other than the face's: it lies on an
 * edge in use (edge k runs from v[k] to v[k+1]; its flag is kMcdTriangleUseEdge0 << k); at a
 * vertex, one of its two edges in use will do (as Jolt's active edges: the vertex of a ridge is on
 * the ridge even where the cell's flat diagonal meets it). An interior point never does. */
static MeBool edgesAllowOtherNormal(const McdTerrainTriangle *t, const MeVector3 p)
{
    MeReal w[3];
    int k;
    barycentric(t, p, w);
    for (k = 0; k < 3; k++)
        if (w[(k + 2) % 3] <= ON_EDGE_FRACTION && (t->flags & (kMcdTriangleUseEdge0 << k))) /* opposite vertex k+2 */
            return METRUE;
    return MEFALSE;
}

static MeBool insideTriangle(const McdTerrainTriangle *t, const MeVector3 p)
{
    MeReal w[3];
    barycentric(t, p, w);
    return w[0] >= -ON_EDGE_FRACTION && w[1] >= -ON_EDGE_FRACTION && w[2] >= -ON_EDGE_FRACTION;
}

/* Closest point of the triangle to p (Ericson, Real-Time Collision Detection 5.1.5) and the feature
 * it lies on: -1 the face, 0..2 edge k (v[k] to v[k+1]), 3..5 vertex k - 3. */
static int closestOnTriangle(const McdTerrainTriangle *t, const MeVector3 p, MeVector3 q)
{
    MeVector3 ab, ac, ap, bp, cp;
    MeVector3Subtract(ab, t->v[1], t->v[0]);
    MeVector3Subtract(ac, t->v[2], t->v[0]);
    MeVector3Subtract(ap, p, t->v[0]);
    MeVector3Subtract(bp, p, t->v[1]);
    MeVector3Subtract(cp, p, t->v[2]);
    MeReal d1 = MeVector3Dot(ab, ap), d2 = MeVector3Dot(ac, ap), d3 = MeVector3Dot(ab, bp);
    MeReal d4 = MeVector3Dot(ac, bp), d5 = MeVector3Dot(ab, cp), d6 = MeVector3Dot(ac, cp);
    MeReal va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
    if (d1 <= 0 && d2 <= 0) {
        MeVector3Copy(q, t->v[0]);
        return 3;
    }
    if (d3 >= 0 && d4 <= d3) {
        MeVector3Copy(q, t->v[1]);
        return 4;
    }
    if (d6 >= 0 && d5 <= d6) {
        MeVector3Copy(q, t->v[2]);
        return 5;
    }
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        MeVector3ScaleAndAdd(q, t->v[0], d1 / (d1 - d3), ab);
        return 0;
    }
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        MeVector3ScaleAndAdd(q, t->v[0], d2 / (d2 - d6), ac);
        return 2;
    }
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        MeVector3 bc;
        MeVector3Subtract(bc, t->v[2], t->v[1]);
        MeVector3ScaleAndAdd(q, t->v[1], (d4 - d3) / ((d4 - d3) + (d5 - d6)), bc);
        return 1;
    }
    MeReal den = ME_R(1.0) / (va + vb + vc);
    MeVector3ScaleAndAdd(q, t->v[0], vb * den, ab);
    MeVector3ScaleAndAdd(q, q, vc * den, ac);
    return -1;
}

/* Whether the feature (as closestOnTriangle) may give a normal of its own: an edge in use, or a
 * vertex with one of its two edges in use (as edgesAllowOtherNormal). */
static MeBool featureInUse(const McdTerrainTriangle *t, int feature)
{
    if (feature < 0)
        return MEFALSE;
    if (feature < 3)
        return (t->flags & (kMcdTriangleUseEdge0 << feature)) != 0;
    feature -= 3; /* vertex k: edges k and k - 1 */
    return (t->flags & (kMcdTriangleUseEdge0 << feature)) || (t->flags & (kMcdTriangleUseEdge0 << ((feature + 2) % 3)));
}

/* Reduce n contacts to keep. Contacts of a flat floor come from many triangles at one depth up to
 * rounding; the reduction starts from the deepest, which would then be a point picked by rounding
 * (often inside the footprint, losing a corner). Depths within `tie` of the deepest count as equal
 * and the one farthest from their centre starts: the footprint's corners are kept. */
static int reduce(McdContact *c, int n, int keep, MeReal tie)
{
    McdContact work[GATHER_MAX], original[GATHER_MAX];
    MeVector3 centre = {0, 0, 0};
    MeReal deepest = MEINFINITY, far = -ME_R(1.0);
    int k, start = 0, tied = 0, m;
    if (n <= keep)
        return n;
    for (k = 0; k < n; k++)
        deepest = MeMIN(deepest, c[k].separation);
    for (k = 0; k < n; k++)
        if (c[k].separation <= deepest + tie) {
            MeVector3Add(centre, centre, c[k].position);
            tied++;
        }
    MeVector3Scale(centre, ME_R(1.0) / (MeReal)tied);
    for (k = 0; k < n; k++)
        if (c[k].separation <= deepest + tie && MeVector3DistanceSqr(c[k].position, centre) > far) {
            far = MeVector3DistanceSqr(c[k].position, centre);
            start = k;
        }
    for (k = 0; k < n; k++) {
        int from = k == 0 ? start : (k == start ? 0 : k);
        original[k] = c[from];
        work[k] = c[from];
        work[k].element1 = (void *)(intptr_t)k; /* which original it is */
        if (work[k].separation <= deepest + tie)
            work[k].separation = deepest; /* ties: the first, the farthest, starts */
    }
    m = McdNfReduce(work, n, keep);
    for (k = 0; k < m; k++)
        c[k] = original[(intptr_t)work[k].element1];
    return m;
}

static void keepBest(Gather *g)
{
    if (g->count > MCD_NF_MAX_CONTACTS)
        g->count = reduce(g->buf, g->count, MCD_NF_MAX_CONTACTS, MCD_TERRAIN_DEPTH_TIE * g->convex.size);
}

static void add(Gather *g, const McdContact *c)
{
    if (g->count == GATHER_MAX)
        keepBest(g);
    g->buf[g->count++] = *c;
}

/* A sphere, in closed form: the closest point of the triangle to the centre; the normal from it to
 * the centre where that point is on the face or on a feature in use, else the face normal (and
 * then only when the centre lies over the triangle: the neighbour gives the rest). */
static void sphereTriangle(Gather *g, const McdTerrainTriangle *t, const MeVector3 faceN)
{
    const MeReal r = g->convex.radius;
    const MeReal *c = g->convex.tm[3];
    MeVector3 q, n, on1, on2;
    McdContact contact;
    int feature = closestOnTriangle(t, c, q);
    MeReal dist = MeVector3Distance(c, q);
    if (dist - r > g->tolerance)
        return;
    MeVector3Subtract(n, c, q);
    MeBool useOwn = dist > MCD_NF_REL_EPS * g->convex.size && MeVector3Dot(n, faceN) >= ME_R(0.0) &&
                    (feature < 0 || featureInUse(t, feature));
    if (useOwn) {
        MeVector3Scale(n, ME_R(1.0) / dist);
        MeVector3ScaleAndAdd(on1, c, -r, n);
        MeVector3Copy(on2, q);
    } else {
        MeReal h = MeVector3Dot(faceN, c) - MeVector3Dot(faceN, t->v[0]);
        MeVector3Copy(n, faceN);
        MeVector3ScaleAndAdd(on1, c, -r, n);
        MeVector3ScaleAndAdd(on2, c, -h, n);
        if (!insideTriangle(t, on2))
            return;
    }
    if (McdNfAddPair(&contact, 0, 1, on1, on2, n, g->tolerance, 0)) {
        contact.element2 = t->element;
        add(g, &contact);
    }
}

/* A face contact: the manifold kept four points of this triangle's part of the footprint, which
 * need not be the convex feature's own corners; those over the triangle are added, so that the
 * reduction over all triangles finds the footprint's corners. */
static void addFeatureCorners(Gather *g, const McdTerrainTriangle *t, const MeVector3 faceN)
{
    MeVector3 pts[MCD_NF_MAX_FEATURE], down, hint;
    int k, count;
    MeVector3MultiplyScalar(down, faceN, -ME_R(1.0));
    McdNfPerpendicular(hint, faceN);
    count = McdNfCoreFeature(&g->convex, down, hint, pts);
    if (count < 3)
        return;
    for (k = 0; k < count; k++) {
        MeVector3 on1, on2;
        McdContact c;
        MeReal h = MeVector3Dot(faceN, pts[k]) - MeVector3Dot(faceN, t->v[0]);
        MeVector3ScaleAndAdd(on2, pts[k], -h, faceN);
        if (!insideTriangle(t, on2))
            continue;
        MeVector3ScaleAndAdd(on1, pts[k], -g->convex.radius, faceN);
        if (McdNfAddPair(&c, 0, 1, on1, on2, faceN, g->tolerance, 2)) {
            c.element2 = t->element;
            add(g, &c);
        }
    }
}

static MeBool visitTriangle(void *ctx, const McdTerrainTriangle *t)
{
    Gather *g = ctx;
    McdGeometryData core;
    McdNfShape tri;
    McdNfDistance d;
    McdContact local[MCD_NF_MAX_CONTACTS];
    MeVector3 faceN, toCentre, nc;
    MeBool forced = MEFALSE;
    int n, k;
    memset(&core, 0, sizeof core);
    core.type = MCD_NF_TRIANGLE_TYPE;
    for (k = 0; k < 3; k++)
        MeVector3Copy(core.u.triangle.v[k], t->v[k]);
    McdNfShapeInit(&tri, &core, identityTM);

    MeVector3Copy(faceN, t->normal);
    MeVector3Subtract(toCentre, g->centre, t->v[0]);
    if ((t->flags & kMcdTriangleTwoSided) && MeVector3Dot(toCentre, faceN) < ME_R(0.0))
        MeVector3Scale(faceN, -ME_R(1.0));
    if (g->convex.type == kMcdGeometryTypeSphere) {
        sphereTriangle(g, t, faceN);
        return METRUE;
    }

    McdNfCoreDistance(&g->convex, &tri, &d);
    if (d.distance - g->convex.radius > g->tolerance)
        return METRUE;
    MeVector3MultiplyScalar(nc, d.normal, -ME_R(1.0)); /* from the triangle towards the convex */
    if (!(t->flags & kMcdTriangleTwoSided) && MeVector3Dot(nc, faceN) < ME_R(0.0))
        forced = METRUE; /* one-sided: the solid is behind the face */
    else if (!(t->flags & kMcdTriangleUseSmallestPenetration) && insideTriangle(t, g->centre))
        forced = METRUE; /* Karma: face normals first */
    else if (MeVector3Dot(nc, faceN) < ME_R(1.0) - MCD_NF_REL_EPS && !edgesAllowOtherNormal(t, d.p2))
        forced = METRUE; /* through the face, or off an edge or vertex not in use */
    if (forced) {
        MeVector3 p1;
        MeVector3MultiplyScalar(d.normal, faceN, -ME_R(1.0));
        McdNfCoreSupport(&g->convex, d.normal, p1);
        d.distance = MeVector3Dot(faceN, p1) - MeVector3Dot(faceN, t->v[0]);
        if (d.distance - g->convex.radius > g->tolerance)
            return METRUE;
        MeVector3Copy(d.p1, p1);
        MeVector3ScaleAndAdd(d.p2, p1, -d.distance, faceN);
    } else if (d.distance > ME_R(0.0)) {
        McdNfRefineSeparated(&g->convex, &tri, &d);
    }
    n = McdNfManifold(&g->convex, &tri, &d, g->tolerance, local, MCD_NF_MAX_CONTACTS);
    if (forced || -MeVector3Dot(d.normal, faceN) >= ME_R(1.0) - MCD_NF_REL_EPS)
        addFeatureCorners(g, t, faceN);
    for (k = 0; k < n; k++) {
        if (forced && !insideTriangle(t, local[k].position))
            continue; /* over the neighbour, which gives it */
        local[k].element2 = t->element;
        add(g, &local[k]);
    }
    return METRUE;
}

void McdTerrainForEach(const McdGeometryData *g, const McdTerrainRegion *region, McdModelPair *pair,
                       McdTerrainVisitFn visit, void *ctx)
{
    const McdTerrainData *t = g->u.terrain;
    switch (g->type) {
    case kMcdGeometryTypeTriangleList:
        McdTriangleListForEach(&t->s.list, region->centre, region->radius, pair, visit, ctx);
        break;
    case kMcdGeometryTypeTriangleMesh: McdTriangleMeshForEach(&t->s.mesh, region->lo, region->hi, visit, ctx); break;
    case kMcdGeometryTypeRGHeightField: McdHeightFieldForEach(&t->s.field, region->lo, region->hi, visit, ctx); break;
    default: break;
    }
}

/* Size: McdNearfieldFn's signature, the pair-test table's type. */
int McdNfConvexTerrain(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                       MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    /* The pair test's cache argument is its pair's cache slot (mcd_internal.h): the generator of a
     * triangle list is given the pair, as Karma's. NULL outside McdIntersect (tests, benchmarks). */
    McdModelPair *pair = cache ? (McdModelPair *)(void *)((char *)cache - offsetof(McdModelPair, cache)) : NULL;
    Gather g;
    MeMatrix4 rel;
    McdTerrainRegion region;
    MeVector3 bsCentre;
    MeReal bsRadius;
    int k, n;
    if (maxContacts <= 0)
        return 0;
    /* the convex in the terrain's frame */
    for (k = 0; k < 3; k++) {
        MeMatrix4TMInverseRotate(rel[k], tm2, tm1[k]);
        rel[k][3] = ME_R(0.0);
    }
    MeMatrix4TMInverseTransform(rel[3], tm2, tm1[3]);
    rel[3][3] = ME_R(1.0);
    McdGeometryAABBInternal(g1, rel, region.lo, region.hi);
    for (k = 0; k < 3; k++) {
        region.lo[k] -= tolerance;
        region.hi[k] += tolerance;
    }
    McdGeometryTypeOf(g1)->getBSphere(McdGeometryToID(g1), McdGeometryShapeData(g1), bsCentre, &bsRadius);
    McdNfShapeInit(&g.convex, g1, rel);
    MeMatrix4TMTransform(g.centre, rel, bsCentre);
    g.tolerance = tolerance;
    g.count = 0;
    MeVector3Copy(region.centre, g.centre);
    region.radius = bsRadius + tolerance;
    McdTerrainForEach(g2, &region, pair, visitTriangle, &g);
    if (g.count == 0)
        return 0;
    if (maxContacts > MCD_NF_MAX_CONTACTS)
        maxContacts = MCD_NF_MAX_CONTACTS;
    n = reduce(g.buf, g.count, maxContacts, MCD_TERRAIN_DEPTH_TIE * g.convex.size);
    for (k = 0; k < n; k++) {
        MeVector3 p, nn;
        MeMatrix4TMTransform(p, tm2, g.buf[k].position);
        MeMatrix4TMRotate(nn, tm2, g.buf[k].normal);
        contacts[k] = g.buf[k];
        MeVector3Copy(contacts[k].position, p);
        MeVector3Copy(contacts[k].normal, nn);
    }
    return n;
}

MeBool McdTerrainSegmentTriangle(const McdTerrainTriangle *tri, const MeVector3 p0, const MeVector3 d, MeReal tMax,
                                 MeReal *t)
{
    /* Moller-Trumbore, with the edge tests on the barycentric weights */
    MeVector3 e1, e2, pv, tv, qv;
    MeReal det, inv, u, v, tt;
    MeVector3Subtract(e1, tri->v[1], tri->v[0]);
    MeVector3Subtract(e2, tri->v[2], tri->v[0]);
    MeVector3Cross(pv, d, e2);
    det = MeVector3Dot(e1, pv);
    if (det == ME_R(0.0) || !isfinite(det))
        return MEFALSE;
    if (!(tri->flags & kMcdTriangleTwoSided) && MeVector3Dot(d, tri->normal) >= ME_R(0.0))
        return MEFALSE; /* one-sided: hit from the front only */
    inv = ME_R(1.0) / det;
    MeVector3Subtract(tv, p0, tri->v[0]);
    u = MeVector3Dot(tv, pv) * inv;
    if (u < ME_R(0.0) || u > ME_R(1.0))
        return MEFALSE;
    MeVector3Cross(qv, tv, e1);
    v = MeVector3Dot(d, qv) * inv;
    if (v < ME_R(0.0) || u + v > ME_R(1.0))
        return MEFALSE;
    tt = MeVector3Dot(e2, qv) * inv;
    if (!(tt >= ME_R(0.0) && tt < tMax))
        return MEFALSE;
    *t = tt;
    return METRUE;
}

typedef struct SegmentSearch {
    MeVector3 p0, d;
    MeReal t;
    MeVector3 normal;
    MeBool hit;
} SegmentSearch;

static MeBool visitSegment(void *ctx, const McdTerrainTriangle *tri)
{
    SegmentSearch *s = ctx;
    MeReal t;
    if (McdTerrainSegmentTriangle(tri, s->p0, s->d, s->hit ? s->t : ME_R(1.0) + MCD_TERRAIN_SEGMENT_SLACK, &t) && t <= ME_R(1.0)) {
        s->t = t;
        s->hit = METRUE;
        MeVector3Copy(s->normal, tri->normal);
        if (MeVector3Dot(s->normal, s->d) > ME_R(0.0))
            MeVector3Scale(s->normal, -ME_R(1.0));
    }
    return METRUE;
}

MeBool McdTerrainSegment(const McdGeometryData *g, const MeVector3 p0, const MeVector3 p1, McdModelPair *pair,
                         MeReal *t, MeVector3 normal)
{
    SegmentSearch s;
    McdTerrainRegion region;
    int k;
    MeVector3Copy(s.p0, p0);
    MeVector3Subtract(s.d, p1, p0);
    s.hit = MEFALSE;
    s.t = ME_R(1.0);
    for (k = 0; k < 3; k++) {
        region.lo[k] = MeMIN(p0[k], p1[k]);
        region.hi[k] = MeMAX(p0[k], p1[k]);
    }
    MeVector3Lerp(region.centre, p0, p1, ME_R(0.5));
    region.radius = ME_R(0.5) * MeVector3Magnitude(s.d);
    McdTerrainForEach(g, &region, pair, visitSegment, &s);
    if (!s.hit)
        return MEFALSE;
    *t = s.t;
    MeVector3Copy(normal, s.normal);
    return METRUE;
}

/* Every convex primitive and the convex mesh against each static triangle geometry; the terrain is
 * geometry 2 (normals from it towards the convex, decision K29). Kept out of the primitives' table
 * (nearfield/table.c), whose entries the primitive tests and benchmarks run on geometries of their
 * own making. */
static const McdNfPairEntry terrainPairs[] = {
    {kMcdGeometryTypeSphere, kMcdGeometryTypeTriangleList, McdNfConvexTerrain, "sphere-trianglelist"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeTriangleList, McdNfConvexTerrain, "box-trianglelist"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeTriangleList, McdNfConvexTerrain, "cylinder-trianglelist"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeTriangleList, McdNfConvexTerrain, "sphyl-trianglelist"},
    {kMcdGeometryTypeCone, kMcdGeometryTypeTriangleList, McdNfConvexTerrain, "cone-trianglelist"},
    {kMcdGeometryTypeConvexMesh, kMcdGeometryTypeTriangleList, McdNfConvexTerrain, "convex-trianglelist"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeTriangleMesh, McdNfConvexTerrain, "sphere-trianglemesh"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeTriangleMesh, McdNfConvexTerrain, "box-trianglemesh"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeTriangleMesh, McdNfConvexTerrain, "cylinder-trianglemesh"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeTriangleMesh, McdNfConvexTerrain, "sphyl-trianglemesh"},
    {kMcdGeometryTypeCone, kMcdGeometryTypeTriangleMesh, McdNfConvexTerrain, "cone-trianglemesh"},
    {kMcdGeometryTypeConvexMesh, kMcdGeometryTypeTriangleMesh, McdNfConvexTerrain, "convex-trianglemesh"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeRGHeightField, McdNfConvexTerrain, "sphere-heightfield"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeRGHeightField, McdNfConvexTerrain, "box-heightfield"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeRGHeightField, McdNfConvexTerrain, "cylinder-heightfield"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeRGHeightField, McdNfConvexTerrain, "sphyl-heightfield"},
    {kMcdGeometryTypeCone, kMcdGeometryTypeRGHeightField, McdNfConvexTerrain, "cone-heightfield"},
    {kMcdGeometryTypeConvexMesh, kMcdGeometryTypeRGHeightField, McdNfConvexTerrain, "convex-heightfield"},
};

const McdNfPairEntry *McdTerrainPairTable(int *count)
{
    *count = (int)(sizeof terrainPairs / sizeof terrainPairs[0]);
    return terrainPairs;
}
