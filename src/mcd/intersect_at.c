/* intersect_at.c -- McdIntersectAt: a pair test with both models moved on by their velocities. */
#include <karma/McdInteraction.h>
#include <karma/MeMath.h>

#include "../me/check.h"
#include "framework.h"

/* The model's geometry-to-world transform `time` from now: its followed transform moved by its
 * velocities (NULL pointers: at rest), then its relative transform. */
static void extrapolate(McdModelData *m, MeReal time, MeMatrix4 out)
{
    static const MeVector3 still = {0, 0, 0};
    MeMatrix4 moved;
    MeMatrix4TMUpdateFromVelocities(moved, ME_R(1e-4), time, m->linearVelocity ? m->linearVelocity : still,
                                    m->angularVelocity ? m->angularVelocity : still, McdModelTransformInternal(m));
    if (m->relativePtr)
        MeMatrix4TMCompound(out, m->relativePtr, moved);
    else if (m->hasRelative)
        MeMatrix4TMCompound(out, m->relativeTransform, moved);
    else
        MeMatrix4Copy(out, moved);
}

MeBool McdIntersectAt(McdModelPairID pair, McdIntersectResult *result, MeReal time)
{
    ME_CHECK_NOT_NULL(pair, MEFALSE);
    ME_CHECK_NOT_NULL(result, MEFALSE);
    ME_CHECK_FINITE(time, MEFALSE);
    McdModelData *m1 = McdModelFromID(pair->model1, __func__), *m2 = McdModelFromID(pair->model2, __func__);
    if (!m1 || !m2)
        return MEFALSE;
    /* The tests read worldTransform: swap the moved transforms in for the call. */
    MeMatrix4 saved1, saved2;
    MeMatrix4Copy(saved1, m1->worldTransform);
    MeMatrix4Copy(saved2, m2->worldTransform);
    extrapolate(m1, time, m1->worldTransform);
    if (m2 != m1)
        extrapolate(m2, time, m2->worldTransform);
    int touch = McdIntersectModels(pair, m1, m2, result, __func__);
    MeMatrix4Copy(m1->worldTransform, saved1);
    MeMatrix4Copy(m2->worldTransform, saved2);
    return touch ? METRUE : MEFALSE;
}
