/* MdtBSJoint.h -- ball and socket joint: a point of body 0 held on a point of body 1 (or of the
 * world); rotation is free. 3 rows. Add an MdtConeLimit to limit the swing.
 * Defaults: positions (0,0,0) in each body, primary axis (1,0,0), orthogonal (0,1,0). */
#ifndef MDT_BSJOINT_H
#define MDT_BSJOINT_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled ball and socket joint, or NULL when the constraint pool is full. */
ME_API MdtBSJointID MdtBSJointCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtBSJointReset(MdtBSJointID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtBSJointQuaConstraint(MdtBSJointID j);
/** The joint behind a constraint ID, or NULL if it is not a ball and socket joint. */
ME_API MdtBSJointID MdtConstraintDCastBSJoint(MdtConstraintID c);

#define MdtBSJointDestroy(j) MdtConstraintDestroy(MdtBSJointQuaConstraint(j))
#define MdtBSJointEnable(j) MdtConstraintEnable(MdtBSJointQuaConstraint(j))
#define MdtBSJointDisable(j) MdtConstraintDisable(MdtBSJointQuaConstraint(j))
#define MdtBSJointIsEnabled(j) MdtConstraintIsEnabled(MdtBSJointQuaConstraint(j))
#define MdtBSJointSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtBSJointQuaConstraint(j), (b1), (b2))
#define MdtBSJointGetBody(j, i) MdtConstraintGetBody(MdtBSJointQuaConstraint(j), (i))
#define MdtBSJointSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtBSJointQuaConstraint(j), (x), (y), (z))
#define MdtBSJointGetPosition(j, p) MdtConstraintGetPosition(MdtBSJointQuaConstraint(j), (p))
#define MdtBSJointGetForce(j, i, f) MdtConstraintGetForce(MdtBSJointQuaConstraint(j), (i), (f))
#define MdtBSJointGetTorque(j, i, t) MdtConstraintGetTorque(MdtBSJointQuaConstraint(j), (i), (t))
#define MdtBSJointSetUserData(j, d) MdtConstraintSetUserData(MdtBSJointQuaConstraint(j), (d))
#define MdtBSJointGetUserData(j) MdtConstraintGetUserData(MdtBSJointQuaConstraint(j))
#define MdtBSJointSetSortKey(j, k) MdtConstraintSetSortKey(MdtBSJointQuaConstraint(j), (k))
#define MdtBSJointGetWorld(j) MdtConstraintGetWorld(MdtBSJointQuaConstraint(j))

/* Karma 1.2's name for the sort key getter. */
#define MdtBSJointGetSortKey(j) MdtConstraintGetSortKey(MdtBSJointQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_BSJOINT_H */
