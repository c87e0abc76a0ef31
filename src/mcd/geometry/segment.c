/* segment.c -- line intervals: where a line is inside simple solids, for the segment tests.
 *
 * Each built-in shape is convex, so the parameters t at which the line p0 + t d lies inside it form
 * one interval. A shape is an intersection of parts (slabs, a ball, a cone or cylinder surface):
 * the interval is the intersection of the parts' intervals, and the outward normal at its start is
 * that of the part entered last. */
#include "geometry.h"

void McdLineIntervalAll(McdLineInterval *iv)
{
    iv->tIn = -MEINFINITY;
    iv->tOut = MEINFINITY;
    MeVector3Set(iv->nIn, 0, 0, 0);
}

static void setEmpty(McdLineInterval *iv)
{
    iv->tIn = MEINFINITY;
    iv->tOut = -MEINFINITY;
}

/* Intersect with [tIn, tOut], whose start has normal n. */
static void clip(McdLineInterval *iv, MeReal tIn, MeReal tOut, const MeVector3 n)
{
    if (tIn > iv->tIn) {
        iv->tIn = tIn;
        MeVector3Copy(iv->nIn, n);
    }
    if (tOut < iv->tOut)
        iv->tOut = tOut;
}

void McdLineIntervalSlab(McdLineInterval *iv, const MeVector3 p0, const MeVector3 d, int axis, MeReal lo, MeReal hi)
{
    MeVector3 n = {0, 0, 0};
    MeReal x = p0[axis], v = d[axis];
    if (v == 0) {
        if (x < lo || x > hi)
            setEmpty(iv);
        return;
    }
    MeReal tLo = lo == -MEINFINITY ? (v > 0 ? -MEINFINITY : MEINFINITY) : (lo - x) / v;
    MeReal tHi = (hi - x) / v;
    if (v > 0) {
        n[axis] = -1;
        clip(iv, tLo, tHi, n);
    } else {
        n[axis] = 1;
        clip(iv, tHi, tLo, n);
    }
}

/* Roots of a t^2 + b t + c = 0 (a != 0) with disc >= 0, in increasing order, computed stably. */
static void roots(MeReal a, MeReal b, MeReal c, MeReal disc, MeReal *r1, MeReal *r2)
{
    MeReal q = ME_R(-0.5) * (b + (b >= 0 ? MeSqrt(disc) : -MeSqrt(disc)));
    MeReal x1 = q / a, x2 = q != 0 ? c / q : x1;
    *r1 = x1 < x2 ? x1 : x2;
    *r2 = x1 < x2 ? x2 : x1;
}

void McdLineIntervalBall(McdLineInterval *iv, const MeVector3 p0, const MeVector3 d, const MeVector3 centre, MeReal r)
{
    MeVector3 m;
    MeVector3Subtract(m, p0, centre);
    MeReal a = MeVector3Dot(d, d), b = 2 * MeVector3Dot(m, d), c = MeVector3Dot(m, m) - r * r;
    if (a == 0) {
        if (c > 0)
            setEmpty(iv);
        return;
    }
    MeReal disc = b * b - 4 * a * c;
    if (disc < 0) {
        setEmpty(iv);
        return;
    }
    MeReal t1, t2;
    roots(a, b, c, disc, &t1, &t2);
    MeVector3 n;
    MeVector3ScaleAndAdd(n, m, t1, d);
    if (!MeVector3NormalizeSafe(n))
        MeVector3Set(n, 0, 0, 1);
    clip(iv, t1, t2, n);
}

/* Outward normal of the cone surface x^2 + y^2 = (alpha + beta z)^2 at p. */
static void coneNormal(const MeVector3 p, MeReal alpha, MeReal beta, MeVector3 n)
{
    MeReal rho = alpha + beta * p[2];
    MeVector3Set(n, p[0], p[1], -rho * beta);
    if (!MeVector3NormalizeSafe(n))
        MeVector3Set(n, 0, 0, 1); /* the apex: any direction of the cap will do */
}

void McdLineIntervalCone(McdLineInterval *iv, const MeVector3 p0, const MeVector3 d, MeReal alpha, MeReal beta)
{
    if (iv->tIn > iv->tOut)
        return;
    /* q(t) = x^2 + y^2 - (alpha + beta z)^2 along the line; inside where q <= 0. */
    MeReal rho0 = alpha + beta * p0[2], rhoD = beta * d[2];
    MeReal a = d[0] * d[0] + d[1] * d[1] - rhoD * rhoD;
    MeReal b = 2 * (p0[0] * d[0] + p0[1] * d[1] - rho0 * rhoD);
    MeReal c = p0[0] * p0[0] + p0[1] * p0[1] - rho0 * rho0;
    /* Up to two pieces where q <= 0; within the slab already applied (where alpha + beta z >= 0)
     * they lie in the convex solid, so their hull, clipped to the slab, is the answer. */
    MeReal piece[2][2];
    int count = 0;
    if (a == 0) {
        if (b > 0) {
            piece[0][0] = -MEINFINITY, piece[0][1] = -c / b, count = 1;
        } else if (b < 0) {
            piece[0][0] = -c / b, piece[0][1] = MEINFINITY, count = 1;
        } else if (c <= 0) {
            piece[0][0] = -MEINFINITY, piece[0][1] = MEINFINITY, count = 1;
        }
    } else {
        MeReal disc = b * b - 4 * a * c;
        if (disc < 0) {
            if (a < 0)
                piece[0][0] = -MEINFINITY, piece[0][1] = MEINFINITY, count = 1;
        } else {
            MeReal r1, r2;
            roots(a, b, c, disc, &r1, &r2);
            if (a > 0) {
                piece[0][0] = r1, piece[0][1] = r2, count = 1;
            } else {
                piece[0][0] = -MEINFINITY, piece[0][1] = r1;
                piece[1][0] = r2, piece[1][1] = MEINFINITY, count = 2;
            }
        }
    }
    MeReal lo = MEINFINITY, hi = -MEINFINITY;
    for (int i = 0; i < count; i++) {
        MeReal s = piece[i][0] > iv->tIn ? piece[i][0] : iv->tIn;
        MeReal e = piece[i][1] < iv->tOut ? piece[i][1] : iv->tOut;
        if (s <= e) {
            lo = s < lo ? s : lo;
            hi = e > hi ? e : hi;
        }
    }
    if (lo > hi) {
        setEmpty(iv);
        return;
    }
    if (lo > iv->tIn) { /* entered through the curved surface */
        MeVector3 p, n;
        MeVector3ScaleAndAdd(p, p0, lo, d);
        coneNormal(p, alpha, beta, n);
        iv->tIn = lo;
        MeVector3Copy(iv->nIn, n);
    }
    iv->tOut = hi;
}

MeBool McdLineIntervalToSegmentHit(const McdLineInterval *iv, const MeVector3 d, MeReal *t, MeVector3 normal)
{
    if (iv->tIn > iv->tOut || iv->tOut < 0 || iv->tIn > 1)
        return MEFALSE;
    if (iv->tIn <= 0) { /* p0 inside: Karma's rule, distance 0 */
        *t = 0;
        MeVector3Set(normal, -d[0], -d[1], -d[2]);
        if (!MeVector3NormalizeSafe(normal))
            MeVector3Set(normal, 0, 0, 1);
        return METRUE;
    }
    *t = iv->tIn;
    MeVector3Copy(normal, iv->nIn);
    return METRUE;
}
