/* linear2.c -- the Linear2 joint: its API and its rows (2: body 0's point on body 1's line,
 * φ_k = (p0 − p1)·n_k for the two directions n_k of body 1's frame perpendicular to the line). */
#include <karma/MdtLinear2.h>

#include "joint_parts.h"

static void reset(MdtConstraintData *c) { MdtConstraintResetFrames(c); }

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    MeVector3 f[3];
    MdtBclWorldFrame(c, 1, f);
    for (int k = 1; k < 3; k++) {
        MdtRow row;
        MdtRowInit(&row);
        MdtBclPointAlongRow(&row, c, f[k], METRUE);
        MdtRowWriterAdd(w, &row);
    }
}

static const MdtConstraintClass linear2Class = {"Linear2", 2, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(Linear2, MdtBclLINEAR2, linear2Class)

void MdtLinear2SetDirection(MdtLinear2ID j, MeReal x, MeReal y, MeReal z)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclLINEAR2, ME_NOTHING);
    /* Both frames, so that body 0's frame reports the same direction (only body 1's is used). */
    if (MdtBclSetBodyAxis(c, 1, x, y, z, __func__))
        MdtBclSetBodyAxis(c, 0, x, y, z, __func__);
}

void MdtLinear2GetDirection(MdtLinear2ID j, MeVector3 direction)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclLINEAR2, ME_NOTHING);
    ME_CHECK_NOT_NULL(direction, ME_NOTHING);
        MdtConstraintWorldPrimary(c, 1, direction);
}
