/* bsjoint.c -- the ball and socket joint: its API and its rows (3: the two points coincide). */
#include <karma/MdtBSJoint.h>

#include "../constraint.h"

static void reset(MdtConstraint *c) { MdtConstraintResetFrames(c); }

static void addRows(MdtConstraint *c, MdtRowWriter *w) { MdtBclAddPointRows(w, c); }

static const MdtConstraintClass bsJointClass = {"BSJoint", 3, reset, NULL, addRows, NULL, NULL};

MdtBSJointID MdtBSJointCreate(MdtWorldID w)
{
    MdtConstraint *c = MdtConstraintCreateInternal(w, MdtBclBSJOINT, &bsJointClass, __func__);
    return c ? (MdtBSJointID)c->id : NULL;
}

void MdtBSJointReset(MdtBSJointID j)
{
    MdtConstraint *c = MdtConstraintFromIDOfType(j, MdtBclBSJOINT, __func__);
    if (c)
        reset(c);
}

MdtConstraintID MdtBSJointQuaConstraint(MdtBSJointID j) { return (MdtConstraintID)j; }

MdtBSJointID MdtConstraintDCastBSJoint(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclBSJOINT ? (MdtBSJointID)c : NULL;
}
