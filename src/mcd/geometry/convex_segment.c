/* convex_segment.c -- where a line meets a hull rounded by a radius r: exactly, not through the
 * half-spaces moved out by r (those reach up to r (sqrt 3 - 1) beyond the rounded corners).
 *
 * The rounded solid is the set of points within r of the polyhedron; its surface is made of the
 * faces moved out by r (where the foot of the point lies on the face), cylinders of radius r about
 * the edges (the foot on the edge) and spheres about the vertices. The line's first point in the
 * solid lies on one of these pieces with its foot there, and every such point is in the solid, so
 * the entry is the least valid entry over the pieces and the exit the greatest valid exit. */
#include "convex_hull.h"
#include "geometry.h"

typedef struct Span {
    MeReal tIn, tOut;
    MeVector3 nIn;
} Span;

static void entry(Span *s, MeReal t, const MeVector3 n)
{
    if (t < s->tIn) {
        s->tIn = t;
        MeVector3Copy(s->nIn, n);
    }
}

static void exitAt(Span *s, MeReal t)
{
    if (t > s->tOut)
        s->tOut = t;
}

/* Is q (on polygon p's plane, within the tolerance) inside the polygon? */
static MeBool insidePolygon(const McdHull *h, int p, const MeVector3 q)
{
    int s = h->polygonStart[p], e = h->polygonStart[p + 1];
    for (int k = s; k < e; k++) {
        const MeReal *a = h->vertices[h->polygonVertices[k]];
        const MeReal *b = h->vertices[h->polygonVertices[k + 1 < e ? k + 1 : s]];
        MeVector3 ab, aq, x;
        MeVector3Subtract(ab, b, a);
        MeVector3Subtract(aq, q, a);
        MeVector3Cross(x, ab, aq);
        if (MeVector3Dot(x, h->normals[p]) < -h->tolerance * MeVector3Magnitude(ab))
            return MEFALSE;
    }
    return METRUE;
}

/* Faces moved out by r: one crossing each, valid where its foot lies on the face. */
static void faces(const McdHull *h, MeReal r, const MeVector3 p0, const MeVector3 d, Span *s)
{
    for (int p = 0; p < h->polygonCount; p++) {
        MeReal den = MeVector3Dot(h->normals[p], d);
        if (den == 0)
            continue;
        MeReal t = (h->offsets[p] + r - MeVector3Dot(h->normals[p], p0)) / den;
        MeVector3 foot;
        MeVector3ScaleAndAdd(foot, p0, t, d);
        MeVector3MultiplyAdd(foot, -r, h->normals[p]);
        if (!insidePolygon(h, p, foot))
            continue;
        if (den < 0)
            entry(s, t, h->normals[p]);
        else
            exitAt(s, t);
    }
}

/* Cylinders of radius r about the edges: two crossings each, valid where the foot is on the edge. */
static void edges(const McdHull *h, MeReal r, const MeVector3 p0, const MeVector3 d, Span *s)
{
    for (int e = 0; e < h->edgeCount; e++) {
        const MeReal *a = h->vertices[h->edges[2 * e]], *b = h->vertices[h->edges[2 * e + 1]];
        MeVector3 u, m, dp, mp;
        MeVector3Subtract(u, b, a);
        MeReal len = MeVector3Magnitude(u);
        if (!(len > 0))
            continue;
        MeVector3Scale(u, 1 / len);
        MeVector3Subtract(m, p0, a);
        /* the parts of m and d across the edge */
        MeVector3ScaleAndAdd(dp, d, -MeVector3Dot(d, u), u);
        MeVector3ScaleAndAdd(mp, m, -MeVector3Dot(m, u), u);
        MeReal qa = MeVector3Dot(dp, dp), qb = 2 * MeVector3Dot(mp, dp), qc = MeVector3Dot(mp, mp) - r * r;
        MeReal disc = qb * qb - 4 * qa * qc;
        if (qa == 0 || disc < 0)
            continue;
        MeReal root = MeSqrt(disc), ts[2] = {(-qb - root) / (2 * qa), (-qb + root) / (2 * qa)};
        for (int k = 0; k < 2; k++) {
            MeVector3 x, n;
            MeVector3ScaleAndAdd(x, m, ts[k], d); /* relative to a */
            MeReal along = MeVector3Dot(x, u);
            if (along < 0 || along > len)
                continue;
            if (k == 1) {
                exitAt(s, ts[k]);
                continue;
            }
            MeVector3ScaleAndAdd(n, x, -along, u);
            if (!MeVector3NormalizeSafe(n))
                continue;
            entry(s, ts[k], n);
        }
    }
}

/* Spheres of radius r about the vertices. */
static void corners(const McdHull *h, MeReal r, const MeVector3 p0, const MeVector3 d, Span *s)
{
    for (int v = 0; v < h->vertexCount; v++) {
        McdLineInterval iv;
        McdLineIntervalAll(&iv);
        McdLineIntervalBall(&iv, p0, d, h->vertices[v], r);
        if (iv.tIn > iv.tOut)
            continue;
        entry(s, iv.tIn, iv.nIn);
        exitAt(s, iv.tOut);
    }
}

int McdRoundedHullSegment(const McdHull *h, MeReal r, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                          MeVector3 normal)
{
    McdLineInterval iv;
    Span s = {MEINFINITY, -MEINFINITY, {0, 0, 0}};
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    faces(h, r, p0, d, &s);
    edges(h, r, p0, d, &s);
    corners(h, r, p0, d, &s);
    iv.tIn = s.tIn;
    iv.tOut = s.tOut;
    MeVector3Copy(iv.nIn, s.nIn);
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}
