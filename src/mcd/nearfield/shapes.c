/* shapes.c -- the primitives as a core swept by a radius: support points and facing features
 * (internal). Sphere = point + r, sphyl = segment + r; box, cylinder and cone are their own cores. */
#include "../geometry/convex_hull.h"
#include "../geometry/geometry.h"
#include "nearfield.h"

void McdNfShapeInit(McdNfShape *s, const McdGeometryData *g, MeMatrix4 tm)
{
    s->g = g;
    s->tm = tm;
    s->type = g->type;
    s->radius = ME_R(0.0);
    switch (g->type) {
    case kMcdGeometryTypeSphere:
        s->radius = g->u.sphere.radius;
        s->size = g->u.sphere.radius;
        break;
    case kMcdGeometryTypeSphyl:
        s->radius = g->u.sphyl.radius;
        s->size = g->u.sphyl.radius + g->u.sphyl.halfHeight;
        break;
    case kMcdGeometryTypeBox:
        s->size = MeVector3Magnitude(g->u.box.radii);
        break;
    case kMcdGeometryTypeCylinder:
        s->size = MeMAX(g->u.cylinder.radius, g->u.cylinder.halfHeight);
        break;
    case kMcdGeometryTypeCone:
        s->size = MeMAX3(g->u.cone.lowerRadius, g->u.cone.upperRadius, g->u.cone.zUpper - g->u.cone.zLower);
        break;
    case kMcdGeometryTypeConvexMesh: /* the polyhedron is the core, the fatness its radius */
        s->radius = g->u.convex.fatness;
        s->size = g->u.convex.hull->radius + g->u.convex.fatness;
        break;
    case MCD_NF_TRIANGLE_TYPE: {
        const McdTriangleCoreData *t = &g->u.triangle;
        s->size = MeMAX3(MeVector3Distance(t->v[0], t->v[1]), MeVector3Distance(t->v[1], t->v[2]),
                         MeVector3Distance(t->v[2], t->v[0]));
        break;
    }
    default:
        s->size = ME_R(1.0);
        break;
    }
}

static MeReal signOf(MeReal x) { return x >= ME_R(0.0) ? ME_R(1.0) : -ME_R(1.0); }

/* Support of a disc of radius r at height z, in local direction d. */
static void discSupport(MeReal r, MeReal z, const MeVector3 d, MeVector3 out)
{
    MeReal rho = MeSqrt(d[0] * d[0] + d[1] * d[1]);
    if (rho > ME_MIN_EPSILON) {
        out[0] = r * d[0] / rho;
        out[1] = r * d[1] / rho;
    } else {
        out[0] = out[1] = ME_R(0.0);
    }
    out[2] = z;
}

static void localCoreSupport(const McdGeometryData *g, const MeVector3 d, MeVector3 out)
{
    switch (g->type) {
    case kMcdGeometryTypeSphyl:
        MeVector3Set(out, ME_R(0.0), ME_R(0.0), signOf(d[2]) * g->u.sphyl.halfHeight);
        break;
    case kMcdGeometryTypeBox:
        MeVector3Set(out, signOf(d[0]) * g->u.box.radii[0], signOf(d[1]) * g->u.box.radii[1],
                     signOf(d[2]) * g->u.box.radii[2]);
        break;
    case kMcdGeometryTypeCylinder:
        discSupport(g->u.cylinder.radius, signOf(d[2]) * g->u.cylinder.halfHeight, d, out);
        break;
    case kMcdGeometryTypeConvexMesh:
        MeVector3Copy(out, g->u.convex.hull->vertices[McdConvexMeshSupportIndex(&g->u.convex, d)]);
        break;
    case kMcdGeometryTypeCone: {
        MeVector3 lo, hi;
        discSupport(g->u.cone.lowerRadius, g->u.cone.zLower, d, lo);
        discSupport(g->u.cone.upperRadius, g->u.cone.zUpper, d, hi);
        if (MeVector3Dot(hi, d) > MeVector3Dot(lo, d))
            MeVector3Copy(out, hi);
        else
            MeVector3Copy(out, lo);
        break;
    }
    case MCD_NF_TRIANGLE_TYPE: {
        const McdTriangleCoreData *t = &g->u.triangle;
        int k, best = 0;
        for (k = 1; k < 3; k++)
            if (MeVector3Dot(t->v[k], d) > MeVector3Dot(t->v[best], d))
                best = k;
        MeVector3Copy(out, t->v[best]);
        break;
    }
    default: /* sphere and anything else: the centre */
        MeVector3Set(out, ME_R(0.0), ME_R(0.0), ME_R(0.0));
        break;
    }
}

void McdNfCoreSupport(const McdNfShape *s, const MeVector3 d, MeVector3 out)
{
    MeVector3 dl, pl;
    MeMatrix4TMInverseRotate(dl, s->tm, d);
    localCoreSupport(s->g, dl, pl);
    MeMatrix4TMTransform(out, s->tm, pl);
}

/* A disc of radius r at height z as a polygon, one vertex towards the local radial direction
 * (dx, dy) (so that the deepest rim point is a vertex), counter-clockwise seen from +z. */
static int discPolygon(MeReal r, MeReal z, MeReal dx, MeReal dy, MeVector3 *pts)
{
    /* cos and sin of 2 pi k / 8 */
    static const MeReal c8[MCD_NF_DISC_SIDES] = {ME_R(1.0), ME_R(0.70710678118654752), ME_R(0.0),
                                                 -ME_R(0.70710678118654752), -ME_R(1.0),
                                                 -ME_R(0.70710678118654752), ME_R(0.0),
                                                 ME_R(0.70710678118654752)};
    static const MeReal s8[MCD_NF_DISC_SIDES] = {ME_R(0.0), ME_R(0.70710678118654752), ME_R(1.0),
                                                 ME_R(0.70710678118654752), ME_R(0.0),
                                                 -ME_R(0.70710678118654752), -ME_R(1.0),
                                                 -ME_R(0.70710678118654752)};
    MeReal rho = MeSqrt(dx * dx + dy * dy), c0 = ME_R(1.0), s0 = ME_R(0.0);
    int k;
    if (rho > ME_MIN_EPSILON) {
        c0 = dx / rho;
        s0 = dy / rho;
    }
    for (k = 0; k < MCD_NF_DISC_SIDES; k++)
        MeVector3Set(pts[k], r * (c0 * c8[k] - s0 * s8[k]), r * (s0 * c8[k] + c0 * s8[k]), z);
    return MCD_NF_DISC_SIDES;
}

/* A convex mesh's feature facing the local unit direction n: of the polygons around the support
 * vertex, the one whose normal is within MCD_NF_FEATURE_COS of n (at most MCD_NF_MAX_FEATURE of its
 * vertices, evenly spaced), else the edge at the support vertex within MCD_NF_FEATURE_SIN of
 * perpendicular to n, else the support vertex. */
static int convexFeature(const McdConvexMeshData *c, const MeVector3 n, MeVector3 *pts)
{
    const McdHull *h = c->hull;
    int p, best = 0, v = McdConvexMeshSupportIndex(c, n), k, w = -1;
    MeReal bestCos = -MEINFINITY, bestSin = MCD_NF_FEATURE_SIN;
    for (k = h->vertexPolygonStart[v]; k < h->vertexPolygonStart[v + 1]; k++) {
        MeReal cs;
        p = h->vertexPolygons[k];
        cs = MeVector3Dot(h->normals[p], n);
        if (cs > bestCos) {
            bestCos = cs;
            best = p;
        }
    }
    if (bestCos >= MCD_NF_FEATURE_COS) {
        int first = h->polygonStart[best], count = h->polygonStart[best + 1] - first;
        int m = count < MCD_NF_MAX_FEATURE ? count : MCD_NF_MAX_FEATURE;
        for (k = 0; k < m; k++)
            MeVector3Copy(pts[k], h->vertices[h->polygonVertices[first + (k * count) / m]]);
        return m;
    }
    MeVector3Copy(pts[0], h->vertices[v]);
    for (k = h->neighbourStart[v]; k < h->neighbourStart[v + 1]; k++) {
        MeVector3 e;
        MeReal len, sn;
        MeVector3Subtract(e, h->vertices[h->neighbours[k]], h->vertices[v]);
        len = MeVector3Magnitude(e);
        sn = len > ME_R(0.0) ? MeFabs(MeVector3Dot(e, n)) / len : MEINFINITY;
        if (sn <= bestSin) {
            bestSin = sn;
            w = h->neighbours[k];
        }
    }
    if (w < 0)
        return 1;
    MeVector3Copy(pts[1], h->vertices[w]);
    return 2;
}

/* A sphyl's feature facing n: its axis when n is across it, else 0 (a point). */
static int sphylFeature(const McdSphylData *c, const MeVector3 n, MeVector3 *pts)
{
    if (MeFabs(n[2]) <= MCD_NF_FEATURE_SIN) {
        MeVector3Set(pts[0], ME_R(0.0), ME_R(0.0), -c->halfHeight);
        MeVector3Set(pts[1], ME_R(0.0), ME_R(0.0), c->halfHeight);
        return 2;
    }
    return 0;
}

/* A box's (half-extents r) feature facing n: a face, an edge, or 0 (a vertex). */
static int boxFeature(const MeReal *r, const MeVector3 n, MeVector3 *pts)
{
    int small[3], nSmall = 0, i;
    for (i = 0; i < 3; i++) {
        small[i] = MeFabs(n[i]) <= MCD_NF_FEATURE_SIN;
        nSmall += small[i];
    }
    if (nSmall == 2) { /* a face: the axis that is not small */
        int a = small[0] ? (small[1] ? 2 : 1) : 0, b = (a + 1) % 3, c = (a + 2) % 3;
        MeReal sa = signOf(n[a]);
        static const MeReal u[4] = {ME_R(1.0), -ME_R(1.0), -ME_R(1.0), ME_R(1.0)};
        static const MeReal v[4] = {ME_R(1.0), ME_R(1.0), -ME_R(1.0), -ME_R(1.0)};
        for (i = 0; i < 4; i++) {
            pts[i][a] = sa * r[a];
            pts[i][b] = u[i] * r[b];
            pts[i][c] = v[i] * r[c];
        }
        return 4;
    }
    if (nSmall == 1) { /* an edge along the small axis */
        int a = small[0] ? 0 : (small[1] ? 1 : 2);
        for (i = 0; i < 3; i++)
            pts[0][i] = pts[1][i] = signOf(n[i]) * r[i];
        pts[0][a] = -r[a];
        pts[1][a] = r[a];
        return 2;
    }
    return 0;
}

/* A cylinder's feature facing n (radial part rho; (dx, dy) orients a disc): an end disc, a side line,
 * or 0 (a point of a rim). */
static int cylinderFeature(const McdCylinderData *cy, const MeVector3 n, MeReal rho, MeReal dx, MeReal dy,
                           MeVector3 *pts)
{
    const MeReal sinTol = MCD_NF_FEATURE_SIN;
    MeReal r = cy->radius, hh = cy->halfHeight;
    if (rho <= sinTol)
        return discPolygon(r, signOf(n[2]) * hh, dx, dy, pts);
    if (MeFabs(n[2]) <= sinTol) {
        MeVector3Set(pts[0], r * n[0] / rho, r * n[1] / rho, -hh);
        MeVector3Set(pts[1], r * n[0] / rho, r * n[1] / rho, hh);
        return 2;
    }
    return 0;
}

/* A cone's feature facing n (radial part rho; (dx, dy) orients a disc): an end disc, a side line, or 0
 * (a point). */
static int coneFeature(const McdConeData *c, const MeVector3 n, MeReal rho, MeReal dx, MeReal dy, MeVector3 *pts)
{
    const MeReal sinTol = MCD_NF_FEATURE_SIN;
    MeReal gr, gz, gl;
    if (rho <= sinTol && n[2] < ME_R(0.0))
        return discPolygon(c->lowerRadius, c->zLower, dx, dy, pts);
    if (rho <= sinTol && c->upperRadius > ME_R(1e-3) * c->lowerRadius)
        return discPolygon(c->upperRadius, c->zUpper, dx, dy, pts);
    /* the side line at the azimuth of n: generator (gr, gz) from the lower to the upper rim */
    gr = c->upperRadius - c->lowerRadius;
    gz = c->zUpper - c->zLower;
    gl = MeSqrt(gr * gr + gz * gz);
    if (rho > sinTol && MeFabs(rho * gr + n[2] * gz) <= sinTol * gl) {
        MeVector3Set(pts[0], c->lowerRadius * n[0] / rho, c->lowerRadius * n[1] / rho, c->zLower);
        MeVector3Set(pts[1], c->upperRadius * n[0] / rho, c->upperRadius * n[1] / rho, c->zUpper);
        return 2;
    }
    return 0;
}

/* A triangle's feature facing n: the vertices within the feature angle of the deepest, in order. */
static int triangleFeature(const McdTriangleCoreData *t, const MeVector3 n, MeVector3 *pts)
{
    MeReal top = MeMAX3(MeVector3Dot(t->v[0], n), MeVector3Dot(t->v[1], n), MeVector3Dot(t->v[2], n));
    int k, best = 0, count = 0;
    for (k = 1; k < 3; k++)
        if (MeVector3Dot(t->v[k], n) > MeVector3Dot(t->v[best], n))
            best = k;
    for (k = 0; k < 3; k++)
        if (top - MeVector3Dot(t->v[k], n) <= MCD_NF_FEATURE_SIN * MeVector3Distance(t->v[k], t->v[best]))
            MeVector3Copy(pts[count++], t->v[k]);
    return count;
}

/* The local feature of a core facing the local unit direction n; h orients discs when n has no
 * radial part. */
static int localFeature(const McdGeometryData *g, const MeVector3 n, const MeVector3 h, MeVector3 *pts)
{
    MeReal rho = MeSqrt(n[0] * n[0] + n[1] * n[1]);
    MeReal dx = rho > ME_R(1e-3) ? n[0] : h[0], dy = rho > ME_R(1e-3) ? n[1] : h[1];
    int count = 0;
    switch (g->type) {
    case kMcdGeometryTypeConvexMesh:
        return convexFeature(&g->u.convex, n, pts);
    case kMcdGeometryTypeSphyl:
        count = sphylFeature(&g->u.sphyl, n, pts);
        break;
    case kMcdGeometryTypeBox:
        count = boxFeature(g->u.box.radii, n, pts);
        break;
    case kMcdGeometryTypeCylinder:
        count = cylinderFeature(&g->u.cylinder, n, rho, dx, dy, pts);
        break;
    case kMcdGeometryTypeCone:
        count = coneFeature(&g->u.cone, n, rho, dx, dy, pts);
        break;
    case MCD_NF_TRIANGLE_TYPE:
        return triangleFeature(&g->u.triangle, n, pts);
    default:
        break;
    }
    if (count > 0)
        return count;
    localCoreSupport(g, n, pts[0]);
    return 1;
}

int McdNfCoreFeature(const McdNfShape *s, const MeVector3 n, const MeVector3 hint, MeVector3 *pts)
{
    MeVector3 nl, hl, p;
    int k, count;
    MeMatrix4TMInverseRotate(nl, s->tm, n);
    MeMatrix4TMInverseRotate(hl, s->tm, hint);
    count = localFeature(s->g, nl, hl, pts);
    for (k = 0; k < count; k++) {
        MeMatrix4TMTransform(p, s->tm, pts[k]);
        MeVector3Copy(pts[k], p);
    }
    return count;
}
