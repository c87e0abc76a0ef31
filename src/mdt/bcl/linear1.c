/* linear1.c -- the Linear1 joint: its API and its row (1: body 0's point in body 1's plane,
 * φ = (p0 − p1)·n with n the plane normal, fixed in body 1). */
#include <karma/MdtLinear1.h>

#include "joint_parts.h"

static void reset(MdtConstraintData *c) { MdtConstraintResetFrames(c); }

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    MdtRow row;
    MeVector3 n;
    MdtRowInit(&row);
    MdtConstraintWorldPrimary(c, 1, n);
    MdtBclPointAlongRow(&row, c, n, METRUE);
    MdtRowWriterAdd(w, &row);
}

static const MdtConstraintClass linear1Class = {"Linear1", 1, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(Linear1, MdtBclLINEAR1, linear1Class)
