/* box_box.c -- box against box by the separating-axis test (internal).
 *
 * Fifteen candidate axes: the three face normals of each box and the nine cross products of their
 * edges (Gottschalk et al. 1996; Ericson 4.4). Overlapping boxes: the axis of least overlap is the
 * contact axis (a face axis unless an edge axis is clearly better and not nearly along the face
 * axis, which keeps resting contacts steady); a face contact clips the other box's most anti-parallel
 * face against the reference face (Sutherland-Hodgman) and keeps up to four points, an edge contact
 * gives the closest points of the two edges. Boxes apart by less than the tolerance are measured by
 * clipping too when a face axis separates them most and the clipped face holds the nearest point (the
 * axis's separation is then the true distance); otherwise they go to the general path (GJK), which
 * measures the true distance, not only its projection on the fifteen axes. */
#include <math.h>

#include "nearfield.h"

/* Prefer a face axis unless an edge axis overlaps less than this fraction of it. */
#define EDGE_BIAS ME_R(0.999)
/* An edge axis whose cosine with the face axis is above this (within about 8 degrees), and which
 * overlaps less than the face axis by under EDGE_FACE_DEPTH of the pair's size, is the face's contact:
 * the depth stays within the accuracy asked of box-box (10^-3 of the size, with EDGE_BIAS). */
#define EDGE_FACE_COS ME_R(0.99)
#define EDGE_FACE_DEPTH ME_R(2e-4)

typedef struct Box {
    const MeReal *c;   /* centre */
    const MeReal *ax[3];
    const MeReal *h;   /* half extents */
} Box;

/* Clip polygon `in` (n points, at most 16: faceContact's buffers) by the plane o.x <= off into `out`; returns the count
 * written, or -1 when every point is inside (`out` not written: the clip would copy `in`), the
 * common case for a box resting within a larger one's face. */
static int clipPlane(MeVector3 *in, int n, MeVector3 *out, const MeVector3 o, MeReal off)
{
    MeReal dist[16];
    int i, m = 0, outside = 0;
    for (i = 0; i < n; i++) {
        dist[i] = MeVector3Dot(o, in[i]) - off;
        outside |= !(dist[i] <= ME_R(0.0));
    }
    if (!outside)
        return -1;
    for (i = 0; i < n; i++) {
        const int next = i + 1 < n ? i + 1 : 0;
        const MeReal sp = dist[i], sq = dist[next];
        if (sp <= ME_R(0.0))
            MeVector3Copy(out[m++], in[i]);
        if ((sp < ME_R(0.0) && sq > ME_R(0.0)) || (sp > ME_R(0.0) && sq < ME_R(0.0)))
            MeVector3Lerp(out[m++], in[i], in[next], sp / (sp - sq));
    }
    return m;
}

/* clipPlane of poly[*cur] (cnt points) into poly[1 - *cur], which becomes the current polygon
 * unless every point was inside; returns the count. */
static int clipCurrent(MeVector3 poly[2][16], int *cur, int cnt, const MeVector3 o, MeReal off)
{
    const int m = clipPlane(poly[*cur], cnt, poly[1 - *cur], o, off);
    if (m < 0)
        return cnt;
    *cur = 1 - *cur;
    return m;
}

/* Points of a clipped face closer together than `radius`: the one deeper kept (the slack turns a
 * touching edge or corner into a sliver of near-equal points). Returns the count left. */
static int mergeNear(McdContact *c, int n, MeReal radius)
{
    int kept = 0;
    for (int i = 0; i < n; i++) {
        int j = 0;
        while (j < kept && MeVector3DistanceSqr(c[j].position, c[i].position) > radius * radius)
            j++;
        if (j == kept)
            c[kept++] = c[i];
        else if (c[i].separation < c[j].separation)
            c[j] = c[i];
    }
    return kept;
}

/* Point p (clipped with the slack) moved onto the reference face's extent along its two side axes
 * (centre[i - 1]: the box's centre along side axis (k + i) % 3): a sliver's points land on the edge or
 * corner itself. */
static void clampToFace(const Box *ref, int k, const MeReal centre[2], MeVector3 p)
{
    for (int i = 1; i < 3; i++) {
        const MeReal *e = ref->ax[(k + i) % 3];
        const MeReal he = ref->h[(k + i) % 3], d = MeVector3Dot(e, p) - centre[i - 1];
        if (d > he)
            MeVector3MultiplyAdd(p, he - d, e);
        else if (d < -he)
            MeVector3MultiplyAdd(p, -he - d, e);
    }
}

/* Face contact: reference box `ref` with face normal nr (unit, pointing towards `inc`) along axis k; the
 * face's sides moved out by `slack` (rounding) for the clipping, so that boxes touching edge to edge or
 * corner to corner clip to their edge or corner instead of to nothing, and the points then put back
 * onto the face. */
/* Size: the reference face (box, axis, normal), the incident box, the order, tolerance, slack, output. */
static int faceContact(const Box *ref, int k, const MeVector3 nr, const Box *inc, MeBool refIsFirst,
                       MeReal tol, MeReal slack, McdContact *out)
{
    MeVector3 poly[2][16], fc, n;
    int j = 0, i, cnt = 4, cur = 0, count = 0;
    MeReal best = -ME_R(1.0), sj, off, centre[2];
    /* incident face: the face of `inc` whose normal is most anti-parallel to nr */
    for (i = 0; i < 3; i++) {
        MeReal d = MeFabs(MeVector3Dot(nr, inc->ax[i]));
        if (d > best) {
            best = d;
            j = i;
        }
    }
    sj = MeVector3Dot(nr, inc->ax[j]) > ME_R(0.0) ? -ME_R(1.0) : ME_R(1.0);
    {
        int a = (j + 1) % 3, b = (j + 2) % 3;
        static const MeReal u[4] = {ME_R(1.0), -ME_R(1.0), -ME_R(1.0), ME_R(1.0)};
        static const MeReal v[4] = {ME_R(1.0), ME_R(1.0), -ME_R(1.0), -ME_R(1.0)};
        for (i = 0; i < 4; i++) {
            MeVector3Copy(poly[0][i], inc->c);
            MeVector3MultiplyAdd(poly[0][i], sj * inc->h[j], inc->ax[j]);
            MeVector3MultiplyAdd(poly[0][i], u[i] * inc->h[a], inc->ax[a]);
            MeVector3MultiplyAdd(poly[0][i], v[i] * inc->h[b], inc->ax[b]);
        }
    }
    /* the four side planes of the reference face */
    for (i = 1; i < 3; i++)
        centre[i - 1] = MeVector3Dot(ref->ax[(k + i) % 3], ref->c);
    for (i = 1; i < 3 && cnt > 0; i++) {
        const MeReal *e = ref->ax[(k + i) % 3];
        MeReal ce = centre[i - 1], he = ref->h[(k + i) % 3] + slack;
        MeVector3 me;
        cnt = clipCurrent(poly, &cur, cnt, e, ce + he);
        MeVector3MultiplyScalar(me, e, -ME_R(1.0));
        cnt = clipCurrent(poly, &cur, cnt, me, -ce + he);
    }
    MeVector3ScaleAndAdd(fc, ref->c, ref->h[k], nr);
    off = MeVector3Dot(fc, nr);
    /* the contact normal points from box 2 towards box 1 */
    if (refIsFirst)
        MeVector3MultiplyScalar(n, nr, -ME_R(1.0));
    else
        MeVector3Copy(n, nr);
    for (i = 0; i < cnt; i++) {
        MeReal sep;
        clampToFace(ref, k, centre, poly[cur][i]);
        sep = MeVector3Dot(poly[cur][i], nr) - off;
        MeVector3 onRef;
        MeVector3ScaleAndAdd(onRef, poly[cur][i], -sep, nr);
        if (refIsFirst)
            count += McdNfAddPair(out, count, 16, onRef, poly[cur][i], n, tol, 2);
        else
            count += McdNfAddPair(out, count, 16, poly[cur][i], onRef, n, tol, 2);
    }
    return mergeNear(out, count, 4 * slack); /* a sliver is the slack and rounding wide */
}

/* The edge of box b parallel to axis i that supports direction d. */
static void supportEdge(const Box *b, int i, const MeVector3 d, MeVector3 e0, MeVector3 e1)
{
    int l;
    MeVector3Copy(e0, b->c);
    for (l = 0; l < 3; l++)
        if (l != i)
            MeVector3MultiplyAdd(e0, MeVector3Dot(d, b->ax[l]) >= ME_R(0.0) ? b->h[l] : -b->h[l], b->ax[l]);
    MeVector3Copy(e1, e0);
    MeVector3MultiplyAdd(e0, -b->h[i], b->ax[i]);
    MeVector3MultiplyAdd(e1, b->h[i], b->ax[i]);
}

/* The contact along face axis faceAxis (A's 0-2, B's 3-5; ta, tb: B's centre from A's in each box's
 * axes): the incident face clipped against the reference face, reduced to at most maxContacts
 * (and MCD_NF_MAX_CONTACTS) in `out`; returns the count (0: rounding clipped everything away). */
/* Size: both boxes, the axis and the offsets it is judged by, and the output. */
static int faceAxisContacts(const Box *A, const Box *B, int faceAxis, const MeReal ta[3], const MeReal tb[3],
                            MeReal tolerance, MeReal slack, McdContact *out, int maxContacts)
{
    McdContact buf[16];
    MeVector3 nr;
    const Box *ref = faceAxis < 3 ? A : B, *inc = faceAxis < 3 ? B : A;
    const int axis = faceAxis % 3;
    const MeReal side = faceAxis < 3 ? ta[axis] : -tb[axis];
    int count, k;
    MeVector3Copy(nr, ref->ax[axis]);
    if (side < ME_R(0.0))
        MeVector3Scale(nr, -ME_R(1.0));
    count = faceContact(ref, axis, nr, inc, faceAxis < 3, tolerance, slack, buf);
    if (count == 0)
        return 0;
    count = McdNfReduce(buf, count, MeMIN(maxContacts, MCD_NF_MAX_CONTACTS));
    for (k = 0; k < count; k++)
        out[k] = buf[k];
    return count;
}

/* The contact of edge A_i x B_j, the overlap along it edgeBest (T: B's centre from A's): the closest
 * points of the two supporting edges, one pair. */
/* Size: both boxes, the edge pair and its overlap, the centres' offset and the output. */
static int edgeContact(const Box *A, const Box *B, int edgeI, int edgeJ, MeReal edgeBest, const MeVector3 T,
                       MeReal tolerance, McdContact *contacts, int maxContacts)
{
    MeVector3 edgeAxis, a0, a1, b0, b1, pa, pb, negAxis, on1, on2;
    MeReal s, t;
    MeVector3Cross(edgeAxis, A->ax[edgeI], B->ax[edgeJ]);
    MeVector3Normalize(edgeAxis);
    if (MeVector3Dot(edgeAxis, T) < ME_R(0.0))
        MeVector3Scale(edgeAxis, -ME_R(1.0));
    MeVector3MultiplyScalar(negAxis, edgeAxis, -ME_R(1.0));
    supportEdge(A, edgeI, edgeAxis, a0, a1);
    supportEdge(B, edgeJ, negAxis, b0, b1);
    McdNfSegmentSegment(a0, a1, b0, b1, &s, &t);
    MeVector3Lerp(pa, a0, a1, s);
    MeVector3Lerp(pb, b0, b1, t);
    /* the edges' points lie along the axis to rounding; pair them straight along it */
    MeVector3Lerp(on1, pa, pb, ME_R(0.5));
    MeVector3Copy(on2, on1);
    MeVector3MultiplyAdd(on1, ME_R(0.5) * edgeBest, edgeAxis);
    MeVector3MultiplyAdd(on2, -ME_R(0.5) * edgeBest, edgeAxis);
    return McdNfAddPair(contacts, 0, maxContacts, on1, on2, negAxis, tolerance, 0); /* B towards A */
}

/* Whether edge axis A_i x B_j lies within EDGE_FACE_COS of face axis faceAxis (A's 0-2, B's 3-5). Both
 * edges then lie nearly in the face's plane: the boxes touch face to face, tilted a little, and their
 * contact is the clipped face, up to four points. Taken as an edge contact it was one point where two
 * edges cross, and a box resting so switched between the two from step to step as the tilt changed
 * by a trace, rocking on the one point and walking down its support (issue 17 point 6). */
static MeBool edgeAxisNearFace(const Box *A, const Box *B, int i, int j, int faceAxis)
{
    MeVector3 axis;
    const MeReal *face = faceAxis < 3 ? A->ax[faceAxis] : B->ax[faceAxis - 3];
    MeVector3Cross(axis, A->ax[i], B->ax[j]);
    return MeFabs(MeVector3Dot(axis, face)) > EDGE_FACE_COS * MeVector3Magnitude(axis);
}

/* Size: McdNearfieldFn's signature. */
int McdNfBoxBox(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, MeReal tolerance,
                McdContact *contacts, int maxContacts, void **cache)
{
    Box A, B;
    MeReal R[3][3], AR[3][3], ta[3], tb[3], faceBest = MEINFINITY, edgeBest = MEINFINITY;
    MeReal size, slack;
    MeVector3 T;
    int i, j, faceAxis = 0, edgeI = -1, edgeJ = -1;
    MeBool separated = MEFALSE;
    if (maxContacts <= 0)
        return 0;
    A.c = tm1[3];
    B.c = tm2[3];
    A.h = g1->u.box.radii;
    B.h = g2->u.box.radii;
    for (i = 0; i < 3; i++) {
        A.ax[i] = tm1[i];
        B.ax[i] = tm2[i];
    }
    size = MeVector3Magnitude(A.h) + MeVector3Magnitude(B.h);
    /* rounding of the boxes' coordinates: relative to their size and to their distance from the origin */
    slack = MCD_NF_REL_EPS * (size + MeFabs(A.c[0]) + MeFabs(A.c[1]) + MeFabs(A.c[2]));
    MeVector3Subtract(T, B.c, A.c);
    for (i = 0; i < 3; i++) {
        ta[i] = MeVector3Dot(T, A.ax[i]);
        tb[i] = MeVector3Dot(T, B.ax[i]);
        for (j = 0; j < 3; j++) {
            R[i][j] = MeVector3Dot(A.ax[i], B.ax[j]);
            AR[i][j] = MeFabs(R[i][j]);
        }
    }
    /* face axes of A (0-2) and of B (3-5) */
    for (i = 0; i < 6; i++) {
        MeReal o;
        if (i < 3)
            o = A.h[i] + B.h[0] * AR[i][0] + B.h[1] * AR[i][1] + B.h[2] * AR[i][2] - MeFabs(ta[i]);
        else
            o = A.h[0] * AR[0][i - 3] + A.h[1] * AR[1][i - 3] + A.h[2] * AR[2][i - 3] + B.h[i - 3] - MeFabs(tb[i - 3]);
        if (isnan(o)) { /* degenerate arithmetic: no axis can be trusted */
            McdNfCountFallback();
            return 0;
        }
        if (o < -tolerance)
            return 0;
        if (o < ME_R(0.0))
            separated = METRUE;
        if (o < faceBest) {
            faceBest = o;
            faceAxis = i;
        }
    }
    /* edge axes A_i x B_j */
    for (i = 0; i < 3; i++) {
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (j = 0; j < 3; j++) {
            int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            MeReal len = MeSqrt(MeMAX(ME_R(0.0), ME_R(1.0) - R[i][j] * R[i][j])), ra, rb, dist, o;
            if (!(len >= MCD_NF_PARALLEL_SIN)) /* parallel edges (to rounding): the face axes cover it */
                continue;
            ra = A.h[i1] * AR[i2][j] + A.h[i2] * AR[i1][j];
            rb = B.h[j1] * AR[i][j2] + B.h[j2] * AR[i][j1];
            dist = MeFabs(ta[i2] * R[i1][j] - ta[i1] * R[i2][j]);
            o = (ra + rb - dist) / len;
            if (isnan(o)) {
                McdNfCountFallback();
                return 0;
            }
            if (o < -tolerance)
                return 0;
            if (o < ME_R(0.0))
                separated = METRUE;
            if (o < edgeBest) {
                edgeBest = o;
                edgeI = i;
                edgeJ = j;
            }
        }
    }
    if (separated && faceBest <= edgeBest + slack) {
        /* Apart, a face axis separating them most (to rounding: an edge axis of aligned boxes is a face
         * axis): when the clipped incident face holds the incident box's nearest point (its separation
         * is the axis's), that separation is the exact distance (no point of the boxes is nearer along
         * the axis, and that one lies over the face), so the clipped face is the contact without the
         * general path: boxes side by side in a touching stack are apart or overlapping by rounding,
         * and take the same path either way. */
        const int count = faceAxisContacts(&A, &B, faceAxis, ta, tb, tolerance, slack, contacts, maxContacts);
        MeReal nearest = MEINFINITY;
        for (int k = 0; k < count; k++)
            nearest = MeMIN(nearest, contacts[k].separation);
        if (count > 0 && nearest <= -faceBest + slack)
            return count;
    }
    if (separated) { /* within the tolerance but apart: the exact distance and its features */
        int count = McdNfConvexConvex(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, cache), k;
        /* A separating axis proves the boxes apart, so a contact that claims an overlap is the general
         * path failing on nearly touching faces (it returned 0.63 m of depth along a wrong normal between
         * side-by-side boxes 1 mm apart, issue 17): then a separating face axis measures the contact by
         * clipping, and an edge axis (boxes apart edge to edge) gives none. */
        for (k = 0; k < count; k++)
            if (!(contacts[k].separation >= -MCD_NF_REL_EPS * size))
                break;
        if (k == count)
            return count;
        if (faceBest > edgeBest)
            return 0;
    } else if (edgeI >= 0 && edgeBest < EDGE_BIAS * faceBest - MCD_NF_FEATURE_EPS * size &&
               !(faceBest - edgeBest < EDGE_FACE_DEPTH * size && edgeAxisNearFace(&A, &B, edgeI, edgeJ, faceAxis))) {
        return edgeContact(&A, &B, edgeI, edgeJ, edgeBest, T, tolerance, contacts, maxContacts);
    }
    {
        const int count = faceAxisContacts(&A, &B, faceAxis, ta, tb, tolerance, slack, contacts, maxContacts);
        if (count == 0) /* rounding clipped everything away: the general path */
            return McdNfConvexConvex(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, cache);
        return count;
    }
}
