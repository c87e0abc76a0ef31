/* bsjoint.c -- the ball and socket joint: its API and its rows (3: the two points coincide). */
#include <karma/MdtBSJoint.h>

#include "../constraint.h"

static void reset(MdtConstraintData *c) { MdtConstraintResetFrames(c); }

static void addRows(MdtConstraintData *c, MdtRowWriter *w) { MdtBclAddPointRows(w, c); }

static const MdtConstraintClass bsJointClass = {"BSJoint", 3, reset, NULL, addRows, NULL, NULL};

MdtBSJointID MdtBSJointCreate(MdtWorldID w)
{
    MdtConstraintData *c = MdtConstraintCreateInternal(w, MdtBclBSJOINT, &bsJointClass, __func__);
    return c ? (MdtBSJointID)c->id : NULL;
}

void MdtBSJointReset(MdtBSJointID j)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclBSJOINT, __func__);
    if (c)
        reset(c);
}

MdtConstraintID MdtBSJointQuaConstraint(MdtBSJointID j) { return (MdtConstraintID)j; }

MdtBSJointID MdtConstraintDCastBSJoint(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclBSJOINT ? (MdtBSJointID)c : NULL;
}
