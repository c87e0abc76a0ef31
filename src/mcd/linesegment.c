/* linesegment.c -- McdLineSegIntersect: a segment against one model's geometry.
 *
 * The segment is taken into the geometry's frame (the model's transform at its last update), the
 * geometry's own test finds the first entry there, and the answer comes back to the world. */
#include <math.h>

#include <karma/McdLineSegment.h>

#include "../me/check.h"
#include "framework.h"
#include "terrain/terrain.h"

int McdModelLineSegIntersectInternal(const McdModelData *m, const MeVector3 p0, const MeVector3 p1,
                                     McdLineSegIntersectResult *result)
{
    McdLineSegIntersectFnPtr user = m->framework->lineSegFns[m->geometry->type];
    if (user) { /* the application's test for this type (McdFrameworkSetLineSegInteraction) */
        MeVector3 a = {p0[0], p0[1], p0[2]}, b = {p1[0], p1[1], p1[2]};
        return user(McdModelToID(m), a, b, result) != 0;
    }
    if (m->geometry->type == kMcdGeometryTypeTriangleList) /* its generator is given a pair of the model */
        return McdTriangleListModelSegment(m, p0, p1, result);
    MeMatrix4Ptr tm = (MeMatrix4Ptr)m->worldTransform;
    MeVector3 a, b, n;
    MeReal t;
    MeMatrix4TMInverseTransform(a, tm, p0);
    MeMatrix4TMInverseTransform(b, tm, p1);
    if (!McdGeometryLineSegInternal(m->geometry, a, b, &t, n))
        return 0;
    MeVector3 d, position, normal;
    MeVector3Subtract(d, p1, p0);
    MeVector3ScaleAndAdd(position, p0, t, d);
    MeMatrix4TMRotate(normal, tm, n);
    MeReal distance = t * MeVector3Magnitude(d);
    if (!(t >= 0 && t <= 1) || !MeVector3IsValid(position) || !isfinite(distance) ||
        !(MeFabs(MeVector3MagnitudeSqr(normal) - 1) <= ME_R(1e-3))) {
        /* degenerate arithmetic: a miss, counted (McdFrameworkGetCounters), never a NaN handed on */
        atomic_fetch_add(&m->framework->segmentFallbacks, 1);
        return 0;
    }
    result->model = McdModelToID(m);
    MeVector3Copy(result->position, position);
    MeVector3Copy(result->normal, normal);
    result->distance = distance;
    return 1;
}

int McdLineSegIntersect(McdModelID id, const MeVector3 p0, const MeVector3 p1, McdLineSegIntersectResult *result)
{
    McdModelData *m = McdModelFromID(id, __func__);
    if (!m)
        return 0;
    ME_CHECK_NOT_NULL(p0, 0);
    ME_CHECK_NOT_NULL(p1, 0);
    ME_CHECK_NOT_NULL(result, 0);
    ME_CHECK_FINITE3(p0[0], p0[1], p0[2], 0);
    ME_CHECK_FINITE3(p1[0], p1[1], p1[2], 0);
    if (!McdPositionInRange(m->framework, p0) || !McdPositionInRange(m->framework, p1)) {
        ME_REPORT(ME_ERR_MCD_POSITION_RANGE, "the segment's end points must lie within %g of the origin (1e7 times "
                  "lengthScale); call ignored", (double)(MCD_POSITION_MAX * m->framework->lengthScale));
        return 0;
    }
    return McdModelLineSegIntersectInternal(m, p0, p1, result);
}
