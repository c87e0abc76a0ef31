/* bounding.c -- MeBoundingSphereCalc: Ritter's approximate bounding sphere (Graphics Gems, 1990). */
#include <karma/MeBounding.h>
#include <karma/MeMath.h>

/* The point farthest from `from`. */
static int farthestFrom(const MeVector3 *points, int numPoints, const MeVector3 from)
{
    int i, best = 0;
    MeReal bestDistance = ME_R(-1.0);
    for (i = 0; i < numPoints; i++) {
        MeReal d = MeVector3DistanceSqr(points[i], from);
        if (d > bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

void MEAPI MeBoundingSphereCalc(MeVector3 *points, int numPoints, MeVector3 centre, MeReal *radius)
{
    int i, a, b;
    MeReal r;
    MeVector3Set(centre, ME_R(0.0), ME_R(0.0), ME_R(0.0));
    if (!points || numPoints <= 0) {
        if (radius)
            *radius = ME_R(0.0);
        return;
    }
    /* A first diameter between two far-apart points, then grow the sphere to take in every point
     * left outside, moving the centre towards it by half the excess. */
    a = farthestFrom((const MeVector3 *)points, numPoints, points[0]);
    b = farthestFrom((const MeVector3 *)points, numPoints, points[a]);
    MeVector3Add(centre, points[a], points[b]);
    MeVector3Scale(centre, ME_R(0.5));
    r = ME_R(0.5) * MeVector3Distance(points[a], points[b]);
    for (i = 0; i < numPoints; i++) {
        MeReal d = MeVector3Distance(points[i], centre);
        if (d > r) {
            MeReal grown = ME_R(0.5) * (r + d);
            MeReal shift = (grown - r) / d;
            centre[0] += (points[i][0] - centre[0]) * shift;
            centre[1] += (points[i][1] - centre[1]) * shift;
            centre[2] += (points[i][2] - centre[2]) * shift;
            r = grown;
        }
    }
    if (radius)
        *radius = r;
}
