/* gjk.c -- distance between two convex cores by the Gilbert-Johnson-Keerthi algorithm (internal).
 *
 * The simplex lives in the Minkowski difference D = core1 - core2; each vertex keeps the two support
 * points it came from, so the closest point of D to the origin gives witness points on both cores
 * (van den Bergen's book; Ericson ch. 9; the closest-point-in-simplex cases as in Ericson 5.1.5). */
#include "nearfield.h"

#if KARMA_DOUBLE
#  define ME_TOL_NF_STEP ME_R(1e-5)
#else
#  define ME_TOL_NF_STEP ME_R(1e-3)
#endif

/* Closest point of the simplex to the origin; keeps only the vertices that carry it and their
 * barycentric weights. Returns MEFALSE when the origin lies inside a tetrahedron. */
typedef struct Bary {
    int n;
    int idx[4];
    MeReal lambda[4];
} Bary;

/* Size: the point's three (index, weight) pairs and their count, each stored as given. */
static void baryPoint(Bary *r, int i, MeReal li, int j, MeReal lj, int k, MeReal lk, int n)
{
    r->n = n;
    r->idx[0] = i;
    r->lambda[0] = li;
    r->idx[1] = j;
    r->lambda[1] = lj;
    r->idx[2] = k;
    r->lambda[2] = lk;
}

static void closestOnSegment(MeVector3 *w, int i, int j, Bary *r)
{
    MeVector3 ab;
    MeReal t, den;
    MeVector3Subtract(ab, w[j], w[i]);
    den = MeVector3Dot(ab, ab);
    t = den > ME_R(0.0) ? -MeVector3Dot(w[i], ab) / den : ME_R(0.0);
    if (t <= ME_R(0.0))
        baryPoint(r, i, ME_R(1.0), 0, ME_R(0.0), 0, ME_R(0.0), 1);
    else if (t >= ME_R(1.0))
        baryPoint(r, j, ME_R(1.0), 0, ME_R(0.0), 0, ME_R(0.0), 1);
    else
        baryPoint(r, i, ME_R(1.0) - t, j, t, 0, ME_R(0.0), 2);
}

static void closestOnTriangle(MeVector3 *w, int ia, int ib, int ic, Bary *r)
{
    const MeReal *a = w[ia], *b = w[ib], *c = w[ic];
    MeVector3 ab, ac;
    MeReal d1, d2, d3, d4, d5, d6, va, vb, vc, den, v, t;
    MeVector3Subtract(ab, b, a);
    MeVector3Subtract(ac, c, a);
    d1 = -MeVector3Dot(ab, a);
    d2 = -MeVector3Dot(ac, a);
    if (d1 <= ME_R(0.0) && d2 <= ME_R(0.0)) {
        baryPoint(r, ia, ME_R(1.0), 0, ME_R(0.0), 0, ME_R(0.0), 1);
        return;
    }
    d3 = -MeVector3Dot(ab, b);
    d4 = -MeVector3Dot(ac, b);
    if (d3 >= ME_R(0.0) && d4 <= d3) {
        baryPoint(r, ib, ME_R(1.0), 0, ME_R(0.0), 0, ME_R(0.0), 1);
        return;
    }
    vc = d1 * d4 - d3 * d2;
    if (vc <= ME_R(0.0) && d1 >= ME_R(0.0) && d3 <= ME_R(0.0)) {
        v = d1 / (d1 - d3);
        baryPoint(r, ia, ME_R(1.0) - v, ib, v, 0, ME_R(0.0), 2);
        return;
    }
    d5 = -MeVector3Dot(ab, c);
    d6 = -MeVector3Dot(ac, c);
    if (d6 >= ME_R(0.0) && d5 <= d6) {
        baryPoint(r, ic, ME_R(1.0), 0, ME_R(0.0), 0, ME_R(0.0), 1);
        return;
    }
    vb = d5 * d2 - d1 * d6;
    if (vb <= ME_R(0.0) && d2 >= ME_R(0.0) && d6 <= ME_R(0.0)) {
        t = d2 / (d2 - d6);
        baryPoint(r, ia, ME_R(1.0) - t, ic, t, 0, ME_R(0.0), 2);
        return;
    }
    va = d3 * d6 - d5 * d4;
    if (va <= ME_R(0.0) && (d4 - d3) >= ME_R(0.0) && (d5 - d6) >= ME_R(0.0)) {
        t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        baryPoint(r, ib, ME_R(1.0) - t, ic, t, 0, ME_R(0.0), 2);
        return;
    }
    den = va + vb + vc;
    if (!(den > ME_R(0.0))) { /* degenerate triangle: fall back to its longest edge */
        closestOnSegment(w, ia, ib, r);
        return;
    }
    v = vb / den;
    t = vc / den;
    baryPoint(r, ia, ME_R(1.0) - v - t, ib, v, ic, t, 3);
}

static MeReal baryDistSqr(MeVector3 *w, const Bary *r)
{
    MeVector3 p = {ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    int k;
    for (k = 0; k < r->n; k++)
        MeVector3MultiplyAdd(p, r->lambda[k], w[r->idx[k]]);
    return MeVector3MagnitudeSqr(p);
}

static MeBool closestOnTetrahedron(MeVector3 *w, Bary *r, MeReal flat)
{
    static const int face[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    MeReal best = MEINFINITY, vol, len = ME_R(0.0);
    MeBool outside = MEFALSE;
    int f, i, j;
    {
        MeVector3 u, v, x;
        MeVector3Subtract(u, w[1], w[0]);
        MeVector3Subtract(v, w[2], w[0]);
        MeVector3Subtract(x, w[3], w[0]);
        vol = MeFabs(MeVector3ScalarTripleProduct(u, v, x));
        for (i = 0; i < 4; i++)
            for (j = i + 1; j < 4; j++)
                len = MeMAX(len, MeVector3DistanceSqr(w[i], w[j]));
        len = MeSqrt(len);
    }
    /* A sliver (nearly flat or with nearly equal vertices): its side tests cannot be trusted, so
     * take the closest point over all faces. */
    if (vol <= ME_R(1e-3) * len * len * len)
        flat = MEINFINITY;
    for (f = 0; f < 4; f++) {
        const MeReal *a = w[face[f][0]], *b = w[face[f][1]], *c = w[face[f][2]], *d = w[face[f][3]];
        MeVector3 ab, ac, nrm, ad;
        MeReal so, sd;
        MeVector3Subtract(ab, b, a);
        MeVector3Subtract(ac, c, a);
        MeVector3Cross(nrm, ab, ac);
        MeVector3Subtract(ad, d, a);
        so = -MeVector3Dot(nrm, a);
        sd = MeVector3Dot(nrm, ad);
        /* origin on the far side of this face, or a flat tetrahedron (signs not to be trusted) */
        if (so * sd <= ME_R(0.0) || MeFabs(sd) <= flat * MeVector3Magnitude(nrm)) {
            Bary cand = {0, {0, 0, 0, 0}, {ME_R(0.0), ME_R(0.0), ME_R(0.0), ME_R(0.0)}};
            MeReal dist;
            closestOnTriangle(w, face[f][0], face[f][1], face[f][2], &cand);
            dist = baryDistSqr(w, &cand);
            outside = METRUE;
            if (dist < best) {
                best = dist;
                *r = cand;
            }
        }
    }
    return outside;
}

/* The point of the simplex closest to the origin, as weights of its vertices, into r. MEFALSE when the
 * origin lies inside the simplex (a tetrahedron). */
static MeBool closestInSimplex(McdNfSimplex *sx, Bary *r, MeReal absEps)
{
    if (sx->n == 1)
        baryPoint(r, 0, ME_R(1.0), 0, ME_R(0.0), 0, ME_R(0.0), 1);
    else if (sx->n == 2)
        closestOnSegment(sx->w, 0, 1, r);
    else if (sx->n == 3)
        closestOnTriangle(sx->w, 0, 1, 2, r);
    else if (!closestOnTetrahedron(sx->w, r, absEps))
        return MEFALSE;
    return METRUE;
}

/* Keep the simplex's vertices that carry the closest point r; v becomes that point and out's p1, p2 its
 * witness points on the two cores. */
static void reduceSimplex(McdNfSimplex *sx, const Bary *r, MeVector3 v, McdNfDistance *out)
{
    McdNfSimplex t = *sx;
    MeVector3 p = {ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    MeVector3 pa = {ME_R(0.0), ME_R(0.0), ME_R(0.0)}, pb = {ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    int k;
    sx->n = r->n;
    for (k = 0; k < r->n; k++) {
        MeVector3Copy(sx->w[k], t.w[r->idx[k]]);
        MeVector3Copy(sx->a[k], t.a[r->idx[k]]);
        MeVector3Copy(sx->b[k], t.b[r->idx[k]]);
        MeVector3MultiplyAdd(p, r->lambda[k], t.w[r->idx[k]]);
    }
    MeVector3Copy(v, p);
    for (k = 0; k < r->n; k++) {
        MeVector3MultiplyAdd(pa, r->lambda[k], sx->a[k]);
        MeVector3MultiplyAdd(pb, r->lambda[k], sx->b[k]);
    }
    MeVector3Copy(out->p1, pa);
    MeVector3Copy(out->p2, pb);
}

MeBool McdNfGjk(const McdNfShape *s1, const McdNfShape *s2, McdNfSimplex *sx, McdNfDistance *out)
{
    const MeReal scale = s1->size + s2->size;
    const MeReal relEps = MCD_NF_REL_EPS, absEps = MCD_NF_REL_EPS * scale;
    MeVector3 v, negv, prevV = {ME_R(0.0), ME_R(0.0), ME_R(0.0)}, prevP1 = {ME_R(0.0), ME_R(0.0), ME_R(0.0)},
              prevP2 = {ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    McdNfSimplex prevSimplex;
    MeReal vv = MEINFINITY;
    int iter, k;
    MeVector3Subtract(v, s1->tm[3], s2->tm[3]);
    if (MeVector3MagnitudeSqr(v) <= absEps * absEps)
        MeVector3Set(v, ME_R(1.0), ME_R(0.0), ME_R(0.0));
    sx->n = 0;
    prevSimplex.n = 0;
    for (iter = 0; iter < 64; iter++) {
        MeVector3 a, b, w;
        Bary r;
        MeReal prev = vv, vw;
        MeBool dup = MEFALSE;
        MeVector3MultiplyScalar(negv, v, -ME_R(1.0));
        McdNfCoreSupport(s1, negv, a);
        McdNfCoreSupport(s2, v, b);
        MeVector3Subtract(w, a, b);
        vw = MeVector3Dot(v, w);
        for (k = 0; k < sx->n; k++)
            if (MeVector3DistanceSqr(sx->w[k], w) <= absEps * absEps * ME_R(1e-4))
                dup = METRUE;
        /* No progress towards the origin: v is the closest point (to the accuracy asked). */
        /* No progress towards the origin (to the accuracy asked, or to rounding of v . w): v is the
         * closest point. */
        if (sx->n > 0 && (dup || vv - vw <= relEps * vv + ME_R(8.0) * ME_MIN_EPSILON * MeSqrt(vv) * MeVector3Magnitude(w)))
            break;
        prevSimplex = *sx;
        MeVector3Copy(sx->w[sx->n], w);
        MeVector3Copy(sx->a[sx->n], a);
        MeVector3Copy(sx->b[sx->n], b);
        sx->n++;
        if (!closestInSimplex(sx, &r, absEps))
            return MEFALSE; /* origin inside: the cores overlap */
        reduceSimplex(sx, &r, v, out);
        vv = MeVector3MagnitudeSqr(v);
        if (vv <= absEps * absEps)
            return MEFALSE; /* touching cores: the direction is not defined, let EPA decide */
        if (vv >= prev) { /* rounding stalled the descent: keep the previous, closer simplex */
            /* the last support point lay beyond the origin (a sliver tetrahedron round it): no
             * separating plane was found, so the cores may overlap: let EPA decide */
            if (vw <= ME_R(0.0))
                return MEFALSE;
            *sx = prevSimplex;
            vv = prev;
            MeVector3Copy(v, prevV);
            MeVector3Copy(out->p1, prevP1);
            MeVector3Copy(out->p2, prevP2);
            break;
        }
        MeVector3Copy(prevV, v);
        MeVector3Copy(prevP1, out->p1);
        MeVector3Copy(prevP2, out->p2);
    }
    out->distance = MeSqrt(vv);
    /* So close that rounding in the simplex (|v| against |w|) may hide an overlap: let EPA decide. */
    if (out->distance <= MCD_NF_TOUCH * scale)
        return MEFALSE;
    MeVector3MultiplyScalar(out->normal, v, -ME_R(1.0) / out->distance);
    return METRUE;
}

/* Support of D = core1 - core2 in direction n. */
static void supportD(const McdNfShape *s1, const McdNfShape *s2, const MeVector3 n, MeVector3 out)
{
    MeVector3 a, b, m;
    MeVector3MultiplyScalar(m, n, -ME_R(1.0));
    McdNfCoreSupport(s1, n, a);
    McdNfCoreSupport(s2, m, b);
    MeVector3Subtract(out, a, b);
}

/* Overlap F(x, y) = h_D(n) along n = normalize(n0 + x u + y v), and its gradient: the support point
 * s(n) is the gradient of h_D, chained through the normalisation. */
/* Size: the pair, the frame (n0, u, v) and the point (x, y) in it, and the two results. */
static MeReal overlapAt(const McdNfShape *s1, const McdNfShape *s2, const MeVector3 n0, const MeVector3 u,
                        const MeVector3 v, MeReal x, MeReal y, MeReal g[2], MeVector3 nOut)
{
    MeVector3 m, sp, du, dv;
    MeReal len;
    MeVector3Copy(m, n0);
    MeVector3MultiplyAdd(m, x, u);
    MeVector3MultiplyAdd(m, y, v);
    len = MeVector3Normalize(m);
    supportD(s1, s2, m, sp);
    MeVector3ScaleAndAdd(du, u, -MeVector3Dot(m, u), m);
    MeVector3ScaleAndAdd(dv, v, -MeVector3Dot(m, v), m);
    g[0] = MeVector3Dot(sp, du) / len;
    g[1] = MeVector3Dot(sp, dv) / len;
    MeVector3Copy(nOut, m);
    return MeVector3Dot(sp, m);
}

/* The overlap h_D(n) along the unit n. */
static MeReal overlapAlong(const McdNfShape *s1, const McdNfShape *s2, const MeVector3 n)
{
    MeVector3 sp;
    supportD(s1, s2, n, sp);
    return MeVector3Dot(sp, n);
}

/* Take the unit n as the normal when the overlap along it is not above the current one (to the
 * accuracy of the method). */
static MeBool tryNormal(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *d, const MeVector3 n)
{
    MeReal F = overlapAlong(s1, s2, n);
    if (!(F <= -d->distance + MCD_NF_REL_EPS * (s1->size + s2->size)))
        return MEFALSE;
    MeVector3Copy(d->normal, n);
    d->distance = -F;
    return METRUE;
}

/* EPA stops when its polytope is within the accuracy of the depth, but on curved cores the depth is
 * flat in the direction (it varies with the square of the angle), so the normal may still be off by
 * ~1e-3 (in float, by ~sqrt(2e-6)). Newton steps on the overlap h_D(n) over directions (gradient from
 * the support point, Hessian by differences) sharpen it; a step is kept only when the overlap goes
 * down. With `axis` (unit), n stays perpendicular to it: a one-dimensional search along the kink of a
 * core whose facing feature is a segment along axis (h_D is not smooth across it). */
static void newtonNormal(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *d, const MeReal *axis)
{
    const MeReal h = ME_TOL_NF_STEP;
    int it;
    if (axis) {
        MeVector3 n;
        MeVector3ScaleAndAdd(n, d->normal, -MeVector3Dot(d->normal, axis), axis);
        if (!MeVector3NormalizeSafe(n) || !tryNormal(s1, s2, d, n))
            axis = NULL; /* not on that kink: smooth there */
    }
    for (it = 0; it < 6; it++) {
        MeVector3 u, v, n0, nNew, tmp;
        MeReal g[2], gx[2], gy[2], F, Fnew, a, b, c, det, dx, dy, step;
        MeVector3Copy(n0, d->normal);
        if (axis) {
            MeVector3Copy(u, axis);
            MeVector3Cross(v, n0, u);
            MeVector3Normalize(v);
        } else {
            McdNfPerpendicular(u, n0);
            MeVector3Cross(v, n0, u);
        }
        F = overlapAt(s1, s2, n0, u, v, ME_R(0.0), ME_R(0.0), g, tmp);
        if (axis)
            g[0] = ME_R(0.0);
        if (MeFabs(g[0]) + MeFabs(g[1]) <= ME_R(1e-3) * MCD_NF_REL_EPS * (s1->size + s2->size))
            break;
        overlapAt(s1, s2, n0, u, v, ME_R(0.0), h, gy, tmp);
        c = (gy[1] - g[1]) / h;
        if (axis) {
            if (!(c > ME_R(0.0)))
                break;
            dx = ME_R(0.0);
            dy = -g[1] / c;
        } else {
            overlapAt(s1, s2, n0, u, v, h, ME_R(0.0), gx, tmp);
            a = (gx[0] - g[0]) / h;
            b = ME_R(0.5) * ((gx[1] - g[1]) / h + (gy[0] - g[0]) / h);
            det = a * c - b * b;
            if (!(a > ME_R(0.0) && det > ME_R(0.0)))
                break; /* not locally convex (a kink or a flat face): nothing to gain */
            dx = -(c * g[0] - b * g[1]) / det;
            dy = -(a * g[1] - b * g[0]) / det;
        }
        step = MeSqrt(dx * dx + dy * dy);
        if (step > ME_R(0.05)) {
            dx *= ME_R(0.05) / step;
            dy *= ME_R(0.05) / step;
        }
        Fnew = overlapAt(s1, s2, n0, u, v, dx, dy, g, nNew);
        if (!(Fnew < F))
            break;
        MeVector3Copy(d->normal, nNew);
        d->distance = -Fnew;
    }
}

/* Unit normal of a feature polygon (sign not fixed). */
static void featureNormal(MeVector3 *p, MeVector3 m)
{
    MeVector3 u, v;
    MeVector3Subtract(u, p[1], p[0]);
    MeVector3Subtract(v, p[2], p[0]);
    MeVector3Cross(m, u, v);
    MeVector3Normalize(m);
}

/* The normal is a face's: if the other core's support point is not over the face (seen along the
 * normal), search across the face edge it lies beyond. */
static void acrossFaceEdge(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *d, MeVector3 *poly, int n,
                           const McdNfShape *other)
{
    const MeBool polyhedral = (other == s2 ? s1 : s2)->type == kMcdGeometryTypeConvexMesh;
    MeVector3 q, m, e, best = {ME_R(0.0), ME_R(0.0), ME_R(0.0)}, away = {ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    MeReal worst = MCD_NF_REL_EPS * (s1->size + s2->size), orient;
    int i;
    if (other == s2)
        MeVector3MultiplyScalar(m, d->normal, -ME_R(1.0));
    else
        MeVector3Copy(m, d->normal);
    McdNfCoreSupport(other, m, q);
    featureNormal(poly, m);
    orient = MeVector3Dot(m, d->normal) >= ME_R(0.0) ? ME_R(1.0) : -ME_R(1.0);
    for (i = 0; i < n; i++) {
        MeVector3 x, dq;
        MeReal out;
        MeVector3Subtract(e, poly[(i + 1) % n], poly[i]);
        MeVector3Subtract(dq, q, poly[i]);
        MeVector3Cross(x, e, dq);
        out = -orient * MeVector3Dot(x, d->normal) / MeMAX(MeVector3Magnitude(e), ME_MIN_EPSILON);
        if (out > worst) {
            worst = out;
            MeVector3Copy(best, e);
            MeVector3Copy(away, dq);
        }
    }
    if (worst > MCD_NF_REL_EPS * (s1->size + s2->size)) {
        /* start tilted slightly beyond the edge, where the face's support is that edge (smooth) */
        McdNfDistance d0 = *d;
        MeVector3Normalize(best);
        MeVector3MultiplyAdd(away, -MeVector3Dot(away, best), best);
        MeVector3MultiplyAdd(away, -MeVector3Dot(away, d->normal), d->normal);
        MeVector3Normalize(away);
        MeVector3MultiplyAdd(d->normal, ME_R(2.0) * ME_TOL_NF_STEP, away);
        MeVector3Normalize(d->normal);
        d->distance = -overlapAlong(s1, s2, d->normal);
        /* a polyhedron's face edge is a kink (box, convex mesh), a disc's rim not */
        newtonNormal(s1, s2, d, (n == 4 || polyhedral) ? best : NULL);
        if (d->distance < d0.distance)
            *d = d0;
    }
}

/* The minimum of h_D over directions lies on the kinks of the cores' supports: where a core's facing
 * feature is a face, the normal is the face's; where both are segments, it is across both; where one
 * is a segment, it is perpendicular to it (then a one-dimensional search); else h_D is smooth there. */
static void refineNormal(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *d)
{
    MeVector3 p1[MCD_NF_MAX_FEATURE], p2[MCD_NF_MAX_FEATURE], h1, h2, m, e1, e2, x;
    int n1, n2;
    MeVector3Subtract(h1, s2->tm[3], s1->tm[3]);
    MeVector3MultiplyScalar(h2, h1, -ME_R(1.0));
    MeVector3MultiplyScalar(m, d->normal, -ME_R(1.0));
    n1 = McdNfCoreFeature(s1, d->normal, h1, p1);
    n2 = McdNfCoreFeature(s2, m, h2, p2);
    if (n1 >= 3 || n2 >= 3) {
        MeVector3 best = {ME_R(0.0), ME_R(0.0), ME_R(1.0)};
        MeReal bestF = MEINFINITY;
        int k, bestK = 0;
        for (k = 0; k < 2; k++) {
            MeReal F;
            if ((k == 0 ? n1 : n2) < 3)
                continue;
            featureNormal(k == 0 ? p1 : p2, m);
            if (MeVector3Dot(m, d->normal) < ME_R(0.0))
                MeVector3Scale(m, -ME_R(1.0));
            F = overlapAlong(s1, s2, m);
            if (F < bestF) {
                bestF = F;
                bestK = k;
                MeVector3Copy(best, m);
            }
        }
        {
            /* The other core's support point must lie over the face; else the minimum is on the kink
             * of the face's nearest edge (the normal tilts across that edge). */
            McdNfDistance d0 = *d;
            MeVector3Copy(d->normal, best);
            d->distance = -bestF;
            acrossFaceEdge(s1, s2, d, bestK == 0 ? p1 : p2, bestK == 0 ? n1 : n2, bestK == 0 ? s2 : s1);
            if (d->distance >= d0.distance - MCD_NF_REL_EPS * (s1->size + s2->size))
                return;
            *d = d0;
        }
        n1 = n1 >= 3 ? 0 : n1; /* not a face contact: search as if smooth there */
        n2 = n2 >= 3 ? 0 : n2;
    }
    if (n1 == 2) {
        MeVector3Subtract(e1, p1[1], p1[0]);
        MeVector3Normalize(e1);
    }
    if (n2 == 2) {
        MeVector3Subtract(e2, p2[1], p2[0]);
        MeVector3Normalize(e2);
    }
    if (n1 == 2 && n2 == 2) {
        MeVector3Cross(x, e1, e2);
        if (MeVector3Magnitude(x) > MCD_NF_FEATURE_SIN) {
            MeVector3Normalize(x);
            if (MeVector3Dot(x, d->normal) < ME_R(0.0))
                MeVector3Scale(x, -ME_R(1.0));
            tryNormal(s1, s2, d, x);
        }
        {
            /* across both, or (when the crossing is beyond a segment's end) on one of the kinks */
            McdNfDistance d1 = *d, d2 = *d;
            newtonNormal(s1, s2, &d1, e1);
            newtonNormal(s1, s2, &d2, e2);
            if (d1.distance > d->distance)
                *d = d1;
            if (d2.distance > d->distance)
                *d = d2;
            return;
        }
    }
    newtonNormal(s1, s2, d, n1 == 2 ? e1 : (n2 == 2 ? e2 : NULL));
}

void McdNfCoreDistance(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *out)
{
    McdNfSimplex sx;
    if (!McdNfGjk(s1, s2, &sx, out)) {
        MeVector3 sp, m;
        MeReal F, Fm;
        McdNfEpa(s1, s2, &sx, out);
        /* Guard against a polytope that rounding turned inside out: the depth must be the overlap
         * along the normal, and the overlap along the opposite direction must not be smaller. */
        supportD(s1, s2, out->normal, sp);
        F = MeVector3Dot(sp, out->normal);
        MeVector3MultiplyScalar(m, out->normal, -ME_R(1.0));
        supportD(s1, s2, m, sp);
        Fm = MeVector3Dot(sp, m);
        if (Fm < F) {
            MeVector3Copy(out->normal, m);
            F = Fm;
        }
        out->distance = -F;
        refineNormal(s1, s2, out);
    }
}

void McdNfRefineSeparated(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *d)
{
    /* GJK's closest points are accurate in distance but, on curved cores, its direction only to about
     * the square root of that accuracy; the distance is -min_n h_D(n) as well, so the same refinement
     * applies (from the lower bound along GJK's direction). */
    d->distance = -overlapAlong(s1, s2, d->normal);
    refineNormal(s1, s2, d);
}
