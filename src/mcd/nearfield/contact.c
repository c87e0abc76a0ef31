/* contact.c -- writing contacts and reducing a contact set to a few well-spread points (internal). */
#include <math.h>

#include "nearfield.h"

void McdNfToWorld(MeVector3 out, MeMatrix4 tm, const MeVector3 local)
{
    MeMatrix4TMTransform(out, tm, local);
}

void McdNfPerpendicular(MeVector3 out, const MeVector3 n)
{
    /* Cross with the axis least aligned with n: well conditioned for every n. */
    MeReal ax = MeFabs(n[0]), ay = MeFabs(n[1]), az = MeFabs(n[2]);
    MeVector3 e = {ME_R(0.0), ME_R(0.0), ME_R(0.0)};
    if (ax <= ay && ax <= az)
        e[0] = ME_R(1.0);
    else if (ay <= az)
        e[1] = ME_R(1.0);
    else
        e[2] = ME_R(1.0);
    MeVector3Cross(out, n, e);
    MeVector3Normalize(out);
}

/* Size: the contact array being filled (contacts, count, maxContacts), then the pair of points, normal,
 * tolerance and dimension of the contact written: every pair test calls it so. */
int McdNfAddPair(McdContact *contacts, int count, int maxContacts, const MeVector3 on1, const MeVector3 on2,
                 const MeVector3 normal, MeReal tolerance, int dims)
{
    MeVector3 d;
    McdContact *c;
    MeReal sep;
    MeVector3Subtract(d, on1, on2); /* the normal points from surface 2 towards surface 1 */
    sep = MeVector3Dot(d, normal);
    /* A NaN or infinite component of on1 or on2 makes a term of the dot product, and so sep, NaN or
     * infinite: sep alone tells whether both points are finite. */
    if (isnan(sep) || (sep <= tolerance && !isfinite(sep))) {
        McdNfCountFallback(); /* NaN or overflow: the contact is dropped */
        return 0;
    }
    if (!(sep <= tolerance) || count >= maxContacts)
        return 0;
    c = &contacts[count];
    MeVector3Lerp(c->position, on1, on2, ME_R(0.5));
    MeVector3Copy(c->normal, normal);
    c->separation = sep;
    c->dims = (MeI16)dims;
    c->pad_ = 0;
    c->element1 = NULL;
    c->element2 = NULL;
    return 1;
}

/* Twice the signed area of triangle (a, b, c) seen along n. */
static MeReal signedArea(const MeVector3 a, const MeVector3 b, const MeVector3 c, const MeVector3 n)
{
    MeVector3 u, v, w;
    MeVector3Subtract(u, b, a);
    MeVector3Subtract(v, c, a);
    MeVector3Cross(w, u, v);
    return MeVector3Dot(w, n);
}

/* A NaN value never wins a search (comparisons with NaN are false); this makes it lose explicitly. */
static MeReal orLowest(MeReal v) { return isnan(v) ? -MEINFINITY : v; }

/* The unused index of contacts[0..n) with the greatest value(i) (ties: the first); -1 when every
 * index is used. A NaN value counts as the lowest, so some index is always found. */
#define ARGMAX_UNUSED(result, n, used, valueExpr)                                                       \
    do {                                                                                                \
        MeReal bestV_ = -MEINFINITY;                                                                    \
        int i_;                                                                                         \
        (result) = -1;                                                                                  \
        for (i_ = 0; i_ < (n); i_++) {                                                                  \
            MeReal v_;                                                                                  \
            if ((used)[i_])                                                                             \
                continue;                                                                               \
            v_ = orLowest(valueExpr);                                                                   \
            if ((result) < 0 || v_ > bestV_) {                                                          \
                bestV_ = v_;                                                                            \
                (result) = i_;                                                                          \
            }                                                                                           \
        }                                                                                               \
    } while (0)

int McdNfReduce(McdContact *contacts, int n, int keep)
{
    McdContact tmp[64];
    int chosen[4], used[64] = {0}, k = 0, i, best;
    MeReal bestValue;
    const MeReal *nrm = contacts[0].normal;
    if (n <= keep)
        return n;
    if (n > 64)
        n = 64;
    if (keep > 4)
        keep = 4;
    /* 1: the deepest point (ties: the first, so the result is deterministic). */
    ARGMAX_UNUSED(best, n, used, -contacts[i_].separation);
    chosen[k++] = best;
    used[best] = 1;
    /* 2: the farthest from it (n > keep >= 1 leaves an unused index). */
    if (k < keep) {
        ARGMAX_UNUSED(best, n, used, MeVector3DistanceSqr(contacts[i_].position, contacts[chosen[0]].position));
        chosen[k++] = best;
        used[best] = 1;
    }
    /* 3: the largest triangle with those two. */
    if (k < keep) {
        ARGMAX_UNUSED(best, n, used,
                      MeFabs(signedArea(contacts[chosen[0]].position, contacts[chosen[1]].position,
                                        contacts[i_].position, nrm)));
        chosen[k++] = best;
        used[best] = 1;
    }
    /* 4: the point that adds the most area outside the triangle (none when all are inside). */
    if (k < keep) {
        const MeReal *p0 = contacts[chosen[0]].position, *p1 = contacts[chosen[1]].position,
                     *p2 = contacts[chosen[2]].position;
        MeReal orient = signedArea(p0, p1, p2, nrm) >= ME_R(0.0) ? ME_R(1.0) : -ME_R(1.0);
        best = -1;
        bestValue = ME_R(0.0);
        for (i = 0; i < n; i++) {
            MeReal a0, a1, a2, add;
            if (used[i])
                continue;
            a0 = orient * signedArea(p0, p1, contacts[i].position, nrm);
            a1 = orient * signedArea(p1, p2, contacts[i].position, nrm);
            a2 = orient * signedArea(p2, p0, contacts[i].position, nrm);
            add = -MeMIN3(a0, a1, a2);
            if (add > bestValue) {
                bestValue = add;
                best = i;
            }
        }
        if (best >= 0)
            chosen[k++] = best;
    }
    for (i = 0; i < k; i++)
        tmp[i] = contacts[chosen[i]];
    for (i = 0; i < k; i++)
        contacts[i] = tmp[i];
    return k;
}

void McdNfSegmentSegment(const MeVector3 p0, const MeVector3 p1, const MeVector3 q0, const MeVector3 q1,
                         MeReal *s, MeReal *t)
{
    /* Closest points of two segments (the clamped normal equations, Ericson 5.1.9). */
    MeVector3 d1, d2, r;
    MeReal a, e, f, c, b, denom, ss, tt;
    MeVector3Subtract(d1, p1, p0);
    MeVector3Subtract(d2, q1, q0);
    MeVector3Subtract(r, p0, q0);
    a = MeVector3Dot(d1, d1);
    e = MeVector3Dot(d2, d2);
    f = MeVector3Dot(d2, r);
    if (a <= ME_MIN_EPSILON && e <= ME_MIN_EPSILON) {
        *s = *t = ME_R(0.0);
        return;
    }
    if (a <= ME_MIN_EPSILON) {
        *s = ME_R(0.0);
        *t = MeCLAMP(f / e, ME_R(0.0), ME_R(1.0));
        return;
    }
    c = MeVector3Dot(d1, r);
    if (e <= ME_MIN_EPSILON) {
        *t = ME_R(0.0);
        *s = MeCLAMP(-c / a, ME_R(0.0), ME_R(1.0));
        return;
    }
    b = MeVector3Dot(d1, d2);
    denom = a * e - b * b;
    /* Parallel segments: any s works; take the middle of the overlap for a stable answer. */
    if (denom > ME_MIN_EPSILON * a * e)
        ss = MeCLAMP((b * f - c * e) / denom, ME_R(0.0), ME_R(1.0));
    else {
        /* project q0 and q1 on segment 1 and take the middle of the common part */
        MeReal u0 = -c / a, u1 = (b - c) / a;
        MeReal lo = MeMAX(ME_R(0.0), MeMIN(u0, u1)), hi = MeMIN(ME_R(1.0), MeMAX(u0, u1));
        ss = lo <= hi ? ME_R(0.5) * (lo + hi) : (u0 + u1 < ME_R(1.0) ? ME_R(0.0) : ME_R(1.0));
        ss = MeCLAMP(ss, ME_R(0.0), ME_R(1.0));
    }
    tt = (b * ss + f) / e;
    if (tt < ME_R(0.0)) {
        tt = ME_R(0.0);
        ss = MeCLAMP(-c / a, ME_R(0.0), ME_R(1.0));
    } else if (tt > ME_R(1.0)) {
        tt = ME_R(1.0);
        ss = MeCLAMP((b - c) / a, ME_R(0.0), ME_R(1.0));
    }
    *s = ss;
    *t = tt;
}
