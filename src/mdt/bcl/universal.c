/* universal.c -- the universal joint: its API and its rows (4: the points coincide, 3; body 0's axis
 * perpendicular to body 1's, 1). */
#include <karma/MdtUniversal.h>

#include "joint_parts.h"

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    MeVector3Set(c->primary[1], 0, 1, 0);
    MeVector3Set(c->orthogonal[1], 0, 0, 1);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    MeVector3 a0, a1;
    MdtBclAddPointRows(w, c);
    MdtConstraintWorldPrimary(c, 0, a0);
    MdtConstraintWorldPrimary(c, 1, a1);
    MdtBclAddPerpendicularRow(w, c, a0, a1);
}

static const MdtConstraintClass universalClass = {"Universal", 4, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(Universal, MdtBclUNIVERSAL, universalClass)

void MdtUniversalSetAxis(MdtUniversalID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclUNIVERSAL, ME_NOTHING);
    if (MdtBclCheckBodyIndex(bodyindex, __func__))
        MdtBclSetBodyAxis(c, (int)bodyindex, x, y, z, __func__);
}

void MdtUniversalGetAxis(MdtUniversalID j, unsigned int bodyindex, MeVector3 axis)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclUNIVERSAL, ME_NOTHING);
    ME_CHECK_NOT_NULL(axis, ME_NOTHING);
    if (MdtBclCheckBodyIndex(bodyindex, __func__))
        MdtConstraintWorldPrimary(c, (int)bodyindex, axis);
}
