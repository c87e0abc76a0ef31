/* manifold.c -- the general convex pair test and its contact set (internal).
 *
 * Once GJK/EPA has given the direction n (core 1 -> core 2), each core's feature facing the other
 * (vertex, edge, face; a disc as a polygon) is taken, and the features are clipped against each other
 * in projection along n: every clipped point pairs a point of one feature with the point of the other
 * straight along n, so both lie on their surfaces and their distance along n is the separation there.
 * Points beyond the tolerance are dropped and the rest reduced to four (Ericson ch. 5; Gregorius).
 * The contacts' normal is -n (from core 2 towards core 1, the contact convention). */
#include "nearfield.h"

/* Write a contact of the pair (on1, on2) found along the query's direction n12 (core 1 -> core 2). */
/* Size: McdNfAddPair's parameters, with the query direction in place of the contact normal. */
static int addAlong(McdContact *c, int count, int maxc, const MeVector3 on1, const MeVector3 on2,
                    const MeVector3 n12, MeReal tol, int dims)
{
    MeVector3 normal;
    MeVector3MultiplyScalar(normal, n12, -ME_R(1.0));
    return McdNfAddPair(c, count, maxc, on1, on2, normal, tol, dims);
}

#define CLIP_MAX (2 * MCD_NF_MAX_FEATURE) /* a polygon clipped by another keeps at most both counts */

typedef struct Side {
    const McdNfShape *s;
    MeVector3 pts[MCD_NF_MAX_FEATURE];
    int n;
    MeVector3 facing; /* unit direction the feature faces (towards the other shape) */
} Side;

/* Unit Newell normal of a polygon (its sign follows the vertex order); returns |normal . facing|. */
static MeReal polygonNormal(const Side *f, MeVector3 m)
{
    int i;
    MeVector3Set(m, ME_R(0.0), ME_R(0.0), ME_R(0.0));
    /* relative to the first vertex: the sums then carry the polygon's size, not its distance from the
     * origin (a small face far away lost every bit of its normal) */
    for (i = 0; i < f->n; i++) {
        MeVector3 p, q;
        MeVector3Subtract(p, f->pts[i], f->pts[0]);
        MeVector3Subtract(q, f->pts[(i + 1) % f->n], f->pts[0]);
        m[0] += (p[1] - q[1]) * (p[2] + q[2]);
        m[1] += (p[2] - q[2]) * (p[0] + q[0]);
        m[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    MeVector3Normalize(m);
    return MeFabs(MeVector3Dot(m, f->facing));
}

/* A face clipping under way: the reference and incident features, the reference plane's unit normal m
 * (facing the incident feature), the query's direction n (core 1 -> core 2) and nm, n oriented with the
 * reference polygon's vertex order, which shape is the reference, and the tolerance. */
typedef struct Clip {
    const Side *ref, *inc;
    MeVector3 m, nm;
    const MeReal *n;
    MeBool refIsFirst;
    MeReal tol;
} Clip;

/* Emit a contact from a point `p` of the incident feature and its partner on the reference plane. */
static int emit(const Clip *k, McdContact *c, int count, const MeVector3 p, int dims)
{
    const Side *ref = k->ref;
    const MeReal *q0 = ref->pts[0], *m = k->m, *n = k->n;
    MeVector3 a, d, on1, on2;
    MeReal t, mn = MeVector3Dot(m, n);
    MeVector3Subtract(d, p, q0);
    t = MeVector3Dot(d, m) / mn;
    MeVector3ScaleAndAdd(a, p, -t, n); /* p moved along n onto the reference plane */
    if (k->refIsFirst) {
        MeVector3ScaleAndAdd(on1, a, ref->s->radius, n);
        MeVector3Copy(on2, p);
    } else {
        MeVector3Copy(on1, p);
        MeVector3ScaleAndAdd(on2, a, -ref->s->radius, n);
    }
    return addAlong(c, count, CLIP_MAX, on1, on2, n, k->tol, dims);
}

/* The reference plane of a clipping: its unit normal m, turned to face the incident feature, and nm. */
static void clipPlane(Clip *k)
{
    MeReal orient;
    polygonNormal(k->ref, k->m);
    /* orientation of the reference polygon's vertex order about n */
    orient = MeVector3Dot(k->m, k->n) >= ME_R(0.0) ? ME_R(1.0) : -ME_R(1.0);
    MeVector3MultiplyScalar(k->nm, k->n, orient);
    if (MeVector3Dot(k->m, k->ref->facing) < ME_R(0.0))
        MeVector3Scale(k->m, -ME_R(1.0));
}

/* The incident feature's surface points facing the reference, into out; returns their count. */
static int incidentSurface(const Side *inc, MeVector3 out[CLIP_MAX])
{
    MeVector3 across;
    int i;
    const MeReal incRadius = inc->s->radius;
    /* A rounded incident segment (sphyl): its surface points facing the reference lie across the axis,
     * along the facing direction made perpendicular to the segment. They are clipped themselves (not
     * the axis), so that every clipped point stays over the reference feature. */
    MeVector3Copy(across, inc->facing);
    if (incRadius > ME_R(0.0) && inc->n == 2) {
        MeVector3 ax;
        MeVector3Subtract(ax, inc->pts[1], inc->pts[0]);
        MeVector3Normalize(ax);
        MeVector3MultiplyAdd(across, -MeVector3Dot(across, ax), ax);
        MeVector3Normalize(across);
    }
    for (i = 0; i < inc->n; i++)
        MeVector3ScaleAndAdd(out[i], inc->pts[i], incRadius, across);
    return inc->n;
}

/* Clip the cnt points of buf[*cur] (a segment or polygon) against the reference polygon's side planes,
 * alternating between the two buffers; *cur ends on the result, whose count is returned. */
static int clipBySides(const Clip *k, MeVector3 buf[2][CLIP_MAX], int cnt, int *cur)
{
    const Side *ref = k->ref;
    int i, e;
    for (e = 0; e < ref->n && cnt > 0; e++) {
        const MeReal *q = ref->pts[e], *q1 = ref->pts[(e + 1) % ref->n];
        MeVector3 edge, o;
        int nxt = 1 - *cur, out = 0, loops = cnt == 2 ? 1 : cnt;
        MeVector3Subtract(edge, q1, q);
        MeVector3Cross(o, edge, k->nm); /* outward side normal for a counter-clockwise polygon about nm */
        for (i = 0; i < loops; i++) {
            const MeReal *p = buf[*cur][i], *p1 = buf[*cur][(i + 1) % cnt];
            MeVector3 dp, dp1;
            MeReal s0, s1;
            MeVector3Subtract(dp, p, q);
            MeVector3Subtract(dp1, p1, q);
            s0 = MeVector3Dot(o, dp);
            s1 = MeVector3Dot(o, dp1);
            if (s0 <= ME_R(0.0) && out < CLIP_MAX)
                MeVector3Copy(buf[nxt][out++], p);
            if (((s0 < ME_R(0.0) && s1 > ME_R(0.0)) || (s0 > ME_R(0.0) && s1 < ME_R(0.0))) && out < CLIP_MAX) {
                MeVector3Lerp(buf[nxt][out++], p, p1, s0 / (s0 - s1));
            }
            if (cnt == 2 && s1 <= ME_R(0.0) && out < CLIP_MAX)
                MeVector3Copy(buf[nxt][out++], p1);
        }
        cnt = out;
        *cur = nxt;
    }
    return cnt;
}

/* Whether p lies over the reference polygon (inside all its side planes, in projection along n). */
static MeBool overReference(const Clip *k, const MeVector3 p)
{
    const Side *ref = k->ref;
    MeBool inside = METRUE;
    int e;
    for (e = 0; e < ref->n && inside; e++) {
        MeVector3 edge, o, dp;
        MeVector3Subtract(edge, ref->pts[(e + 1) % ref->n], ref->pts[e]);
        MeVector3Cross(o, edge, k->nm);
        MeVector3Subtract(dp, p, ref->pts[e]);
        inside = MeVector3Dot(o, dp) <= ME_R(0.0);
    }
    return inside;
}

/* The incident shape's deepest point (its support along the facing direction, e.g. a sphyl's end cap)
 * is the minimum-translation witness; the clipped points of a rounded or tilted feature may all be
 * shallower: add it to the count contacts (of a clipped feature of cnt points) when it lies over the
 * reference feature and is deeper. Returns the new count. */
static int addDeepest(const Clip *k, McdContact *c, int count, int cnt, int dims)
{
    const Side *ref = k->ref, *inc = k->inc;
    MeVector3 p;
    MeReal deepest = c[0].separation;
    int i;
    McdNfCoreSupport(inc->s, inc->facing, p);
    MeVector3ScaleAndAdd(p, p, inc->s->radius, inc->facing);
    for (i = 1; i < count; i++)
        deepest = MeMIN(deepest, c[i].separation);
    if (overReference(k, p) && emit(k, c, count, p, dims)) {
        if (c[count].separation < deepest - MCD_NF_REL_EPS * (ref->s->size + inc->s->size)) {
            if (cnt == 2) { /* a line contact stays two points: the nearer end gives way */
                int near = MeVector3DistanceSqr(c[0].position, c[count].position) <=
                                   MeVector3DistanceSqr(c[count - 1].position, c[count].position)
                               ? 0
                               : count - 1;
                c[near] = c[count];
            } else
                count++;
        }
    }
    return count;
}

/* Clip the incident feature (segment or polygon) against the side planes of the reference polygon;
 * the side planes contain n, so this is clipping in projection along n. Writes at most CLIP_MAX
 * contacts to c. */
static int clipFaces(const Side *ref, const Side *inc, const MeVector3 n, MeBool refIsFirst, MeReal tol,
                     McdContact *c)
{
    MeVector3 buf[2][CLIP_MAX];
    int cnt, i, cur = 0, count = 0, dims;
    Clip k;
    k.ref = ref;
    k.inc = inc;
    k.n = n;
    k.refIsFirst = refIsFirst;
    k.tol = tol;
    clipPlane(&k);
    cnt = clipBySides(&k, buf, incidentSurface(inc, buf[0]), &cur);
    dims = cnt >= 3 ? 2 : (cnt == 2 ? 1 : 0);
    for (i = 0; i < cnt; i++)
        count += emit(&k, c, count, buf[cur][i], dims);
    if (count > 0 && count < CLIP_MAX)
        count = addDeepest(&k, c, count, cnt, dims);
    return count;
}

/* Two segments facing each other: the common part when they are parallel in projection along n. */
static int clipSegments(const Side *f1, const Side *f2, const MeVector3 n, MeReal tol, MeReal size,
                        McdContact *c)
{
    MeVector3 e1, e2, x;
    MeReal l1, t[2], lo, hi;
    int k, count = 0;
    MeVector3Subtract(e1, f1->pts[1], f1->pts[0]);
    MeVector3Subtract(e2, f2->pts[1], f2->pts[0]);
    MeVector3Cross(x, e1, e2);
    l1 = MeVector3Dot(e1, e1);
    if (MeFabs(MeVector3Dot(x, n)) > MCD_NF_FEATURE_SIN * MeVector3Magnitude(e1) * MeVector3Magnitude(e2) ||
        l1 <= ME_MIN_EPSILON)
        return 0;
    /* parameters of segment 2's ends along segment 1 */
    for (k = 0; k < 2; k++) {
        MeVector3 d;
        MeVector3Subtract(d, f2->pts[k], f1->pts[0]);
        t[k] = MeVector3Dot(d, e1) / l1;
    }
    lo = MeMAX(ME_R(0.0), MeMIN(t[0], t[1]));
    hi = MeMIN(ME_R(1.0), MeMAX(t[0], t[1]));
    if (lo > hi)
        return 0;
    for (k = 0; k < 2; k++) {
        MeReal u = k == 0 ? lo : hi, v, len;
        MeVector3 a, b, lat, on1, on2, ab, nk, d;
        /* the point b of segment 2 over parameter u of segment 1, and a: the point of segment 1's
         * line nearest to b, so that b - a is across segment 1 */
        v = (t[1] != t[0]) ? (u - t[0]) / (t[1] - t[0]) : ME_R(0.0);
        v = MeCLAMP(v, ME_R(0.0), ME_R(1.0));
        MeVector3ScaleAndAdd(b, f2->pts[0], v, e2);
        MeVector3Subtract(d, b, f1->pts[0]);
        u = MeCLAMP(MeVector3Dot(d, e1) / l1, ME_R(0.0), ME_R(1.0));
        MeVector3ScaleAndAdd(a, f1->pts[0], u, e1);
        MeVector3Subtract(ab, b, a);
        MeVector3ScaleAndAdd(lat, ab, -MeVector3Dot(ab, n), n);
        /* nearly parallel segments: each end of the common part is its own pair, along its own line
         * (so exact on rounded surfaces); far apart across n, the segments only cross: one point */
        if (MeVector3Magnitude(lat) > ME_R(2e-3) * size)
            return 0;
        /* each pair along its own line (the shapes may be rounded): exact surface points */
        MeVector3Copy(nk, ab);
        len = MeVector3Magnitude(nk);
        if (len > ME_R(1e-3) * size && MeVector3Dot(nk, n) > ME_R(0.0))
            MeVector3Scale(nk, ME_R(1.0) / len);
        else
            MeVector3Copy(nk, n);
        MeVector3ScaleAndAdd(on1, a, f1->s->radius, nk);
        MeVector3ScaleAndAdd(on2, b, -f2->s->radius, nk);
        count += addAlong(c, count, 2, on1, on2, nk, tol, 1);
        if (hi - lo <= ME_R(1e-4))
            break;
    }
    return count;
}

/* One contact where at least one feature is a vertex (or two edges cross). The vertex is exact (a
 * support point); its partner lies straight along n on the other feature, at the depth the
 * distance query measured. Two crossing edges: their closest points. */
static int singlePoint(const Side *f1, const Side *f2, const McdNfDistance *d, MeReal tol, McdContact *c)
{
    const MeReal *n = d->normal;
    MeReal sep = d->distance - f1->s->radius - f2->s->radius;
    MeVector3 on1, on2;
    if (f1->n == 1 && f2->n == 1) {
        MeVector3ScaleAndAdd(on1, f1->pts[0], f1->s->radius, n);
        MeVector3ScaleAndAdd(on2, f2->pts[0], -f2->s->radius, n);
        return addAlong(c, 0, 1, on1, on2, n, tol, 0);
    }
    if (f1->n == 1) {
        MeVector3ScaleAndAdd(on1, f1->pts[0], f1->s->radius, n);
        MeVector3ScaleAndAdd(on2, on1, sep, n);
    } else if (f2->n == 1) {
        MeVector3ScaleAndAdd(on2, f2->pts[0], -f2->s->radius, n);
        MeVector3ScaleAndAdd(on1, on2, -sep, n);
    } else if (f1->n == 2 && f2->n == 2) {
        /* The witnesses are where the segments cross seen along n (not their closest points in
         * space, which for deep overlaps lie along the segments' common perpendicular instead). */
        MeReal s, t;
        MeVector3 p, q, e[4];
        int k;
        for (k = 0; k < 4; k++) {
            const MeReal *x = k < 2 ? f1->pts[k] : f2->pts[k - 2];
            MeVector3ScaleAndAdd(e[k], x, -MeVector3Dot(x, n), n);
        }
        McdNfSegmentSegment(e[0], e[1], e[2], e[3], &s, &t);
        MeVector3Lerp(p, f1->pts[0], f1->pts[1], s);
        MeVector3Lerp(q, f2->pts[0], f2->pts[1], t);
        MeVector3ScaleAndAdd(on1, p, f1->s->radius, n);
        MeVector3ScaleAndAdd(on2, q, -f2->s->radius, n);
    } else {
        MeVector3ScaleAndAdd(on1, d->p1, f1->s->radius, n);
        MeVector3ScaleAndAdd(on2, d->p2, -f2->s->radius, n);
        if (addAlong(c, 0, 1, on1, on2, n, tol, 0) == 0)
            return 0;
        c[0].separation = sep;
        return 1;
    }
    return addAlong(c, 0, 1, on1, on2, n, tol, 0);
}

int McdNfManifold(const McdNfShape *s1, const McdNfShape *s2, const McdNfDistance *d, MeReal tolerance,
                  McdContact *contacts, int maxContacts)
{
    return McdNfManifoldCoherent(s1, s2, d, tolerance, contacts, maxContacts, NULL);
}

/* Size: McdNfManifold's parameters and the reference side kept from the last step. */
int McdNfManifoldCoherent(const McdNfShape *s1, const McdNfShape *s2, const McdNfDistance *d, MeReal tolerance,
                          McdContact *contacts, int maxContacts, int *refSide)
{
    McdContact buf[CLIP_MAX];
    Side f1, f2;
    MeVector3 hint1, hint2;
    int count = 0, k;
    f1.s = s1;
    f2.s = s2;
    MeVector3Copy(f1.facing, d->normal);
    MeVector3MultiplyScalar(f2.facing, d->normal, -ME_R(1.0));
    MeVector3Subtract(hint1, s2->tm[3], s1->tm[3]);
    MeVector3MultiplyScalar(hint2, hint1, -ME_R(1.0));
    f1.n = McdNfCoreFeature(s1, f1.facing, hint1, f1.pts);
    f2.n = McdNfCoreFeature(s2, f2.facing, hint2, f2.pts);
    if (f1.n >= 3 || f2.n >= 3) {
        if (f1.n >= 2 && f2.n >= 2) {
            MeVector3 m1, m2;
            MeReal a1 = f1.n >= 3 ? polygonNormal(&f1, m1) : -ME_R(1.0);
            MeReal a2 = f2.n >= 3 ? polygonNormal(&f2, m2) : -ME_R(1.0);
            MeBool firstRef = a1 >= a2;
            if (refSide && *refSide == 1 && a1 >= ME_R(0.0) && a1 >= a2 - (ME_R(1.0) - MCD_NF_FEATURE_COS))
                firstRef = METRUE; /* the last frame's reference side, while its face is as aligned */
            else if (refSide && *refSide == 2 && a2 >= ME_R(0.0) && a2 >= a1 - (ME_R(1.0) - MCD_NF_FEATURE_COS))
                firstRef = MEFALSE;
            if (refSide)
                *refSide = firstRef ? 1 : 2;
            if (firstRef)
                count = clipFaces(&f1, &f2, d->normal, METRUE, tolerance, buf);
            else
                count = clipFaces(&f2, &f1, d->normal, MEFALSE, tolerance, buf);
        }
    } else if (f1.n == 2 && f2.n == 2) {
        count = clipSegments(&f1, &f2, d->normal, tolerance, s1->size + s2->size, buf);
    }
    if (count == 0) /* a vertex, crossing edges, or clipping lost everything: one point */
        count = singlePoint(&f1, &f2, d, tolerance, buf);
    if (maxContacts > MCD_NF_MAX_CONTACTS)
        maxContacts = MCD_NF_MAX_CONTACTS;
    if (count > 0)
        count = McdNfReduce(buf, count, maxContacts);
    for (k = 0; k < count; k++)
        contacts[k] = buf[k];
    return count;
}

/* Size: McdNearfieldFn's signature. */
int McdNfConvexConvex(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                      MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    McdNfShape s1, s2;
    McdNfDistance d;
    (void)cache;
    if (maxContacts <= 0)
        return 0;
    McdNfShapeInit(&s1, g1, tm1);
    McdNfShapeInit(&s2, g2, tm2);
    McdNfCoreDistance(&s1, &s2, &d);
    if (d.distance - s1.radius - s2.radius > tolerance)
        return 0;
    if (d.distance > ME_R(0.0)) /* apart cores, but within the tolerance: contacts need the exact normal */
        McdNfRefineSeparated(&s1, &s2, &d);
    return McdNfManifold(&s1, &s2, &d, tolerance, contacts, maxContacts);
}
