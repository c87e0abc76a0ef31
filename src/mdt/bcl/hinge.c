/* hinge.c -- the hinge joint: its API and its rows (3 point rows, 2 rows keeping the axes parallel,
 * and the limit/motor row of the hinge angle). */
#include <karma/MdtHinge.h>

#include "limit_internal.h"

typedef struct HingeData {
    MdtLimit limit;
} HingeData;
MDT_CONSTRAINT_DATA_FITS(HingeData);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    MdtLimitInit(&MDT_CONSTRAINT_DATA(c, HingeData)->limit);
}

/* The hinge angle's Jacobian row: body 0's orthogonal axis measured in body 1's frame (o1, a1 × o1). */
static MeReal angleRow(const MdtConstraintData *c, MdtRow *row)
{
    MeVector3 o0, a1, o1, n1;
    MdtConstraintWorldOrthogonal(c, 0, o0);
    MdtConstraintWorldPrimary(c, 1, a1);
    MdtConstraintWorldOrthogonal(c, 1, o1);
    MeVector3Cross(n1, a1, o1);
    MdtRowInit(row);
    return MdtBclAngleRow(row, o1, n1, o0, 0);
}

static int rowCount(const MdtConstraintData *c)
{
    return 5 + (MdtLimitMayAddRow(&MDT_CONSTRAINT_DATA(c, const HingeData)->limit) ? 1 : 0);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    MdtLimit *l = &MDT_CONSTRAINT_DATA(c, HingeData)->limit;
    MdtBclAddPointRows(w, c);
    MdtBclAddParallelAxisRows(w, c);
    MdtRow row;
    MeReal angle = angleRow(c, &row);
    MdtLimitAddRow(l, w, &row, MdtLimitUnwrap(l, angle));
}

/* After the step: the angle and its rate at the new pose, then the motor's stall check. */
static void unpack(MdtConstraintData *c, const MeReal *impulses, int rows, MeReal h)
{
    MdtLimit *l = &MDT_CONSTRAINT_DATA(c, HingeData)->limit;
    MdtRow row;
    MeReal angle = angleRow(c, &row);
    MdtLimitSetMeasured(l, MdtLimitUnwrap(l, angle), MdtRowVelocity(c, &row));
    MdtLimitUnpack(l, impulses, rows, h);
}

static void destroy(MdtConstraintData *c) { MDT_LIMIT_MAGIC(&MDT_CONSTRAINT_DATA(c, HingeData)->limit) = 0; }

static const MdtConstraintClass hingeClass = {"Hinge", 6, reset, rowCount, addRows, unpack, destroy};

MdtHingeID MdtHingeCreate(MdtWorldID w)
{
    MdtConstraintData *c = MdtConstraintCreateInternal(w, MdtBclHINGE, &hingeClass, __func__);
    return c ? (MdtHingeID)c->id : NULL;
}

void MdtHingeReset(MdtHingeID j)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclHINGE, __func__);
    if (c)
        reset(c);
}

MdtConstraintID MdtHingeQuaConstraint(MdtHingeID j) { return (MdtConstraintID)j; }

MdtHingeID MdtConstraintDCastHinge(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclHINGE ? (MdtHingeID)c : NULL;
}

MdtLimitID MdtHingeGetLimit(MdtHingeID j)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclHINGE, __func__);
    return c ? &MDT_CONSTRAINT_DATA(c, HingeData)->limit : NULL;
}

void MdtHingeSetLimit(MdtHingeID j, const MdtLimit *limit)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclHINGE, __func__);
    const MdtLimit *src = MdtLimitCheck(limit, __func__);
    if (c && src && MdtLimitCheckOrder(src, src->limit[0].stop, src->limit[1].stop, __func__))
        MdtLimitCopySettings(&MDT_CONSTRAINT_DATA(c, HingeData)->limit, src);
}
