/* MdtHinge.h -- hinge joint: body 0 turns relative to body 1 (or the world) about a shared axis
 * through a shared point; 5 rows, plus 1 when its limit acts (stop, motor or lock).
 *
 * The hinge angle, read through the limit (MdtLimitGetPosition(MdtHingeGetLimit(j))), is the
 * rotation of body 0 relative to body 1 about the axis (right-hand rule), 0 where the axis was set,
 * counted over several turns (stops may lie beyond ±π). Its rate is (ω0 − ω1)·axis.
 * Defaults: position (0,0,0), axis (1,0,0) in both bodies; the limit's defaults (MdtLimit.h). */
#ifndef MDT_HINGE_H
#define MDT_HINGE_H

#include "MdtConstraint.h"
#include "MdtLimit.h"

ME_EXTERN_C_BEGIN

/** A new disabled hinge, or NULL when the constraint pool is full. */
ME_API MdtHingeID MdtHingeCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtHingeReset(MdtHingeID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtHingeQuaConstraint(MdtHingeID j);
/** The hinge behind a constraint ID, or NULL if it is not a hinge. */
ME_API MdtHingeID MdtConstraintDCastHinge(MdtConstraintID c);
/** The hinge's limit (lives as long as the joint). */
ME_API MdtLimitID MdtHingeGetLimit(MdtHingeID j);
/** Copy a limit's settings (stops, motor, lock, activation) into the hinge. */
ME_API void MdtHingeSetLimit(MdtHingeID j, const MdtLimit *limit);

#define MdtHingeDestroy(j) MdtConstraintDestroy(MdtHingeQuaConstraint(j))
#define MdtHingeEnable(j) MdtConstraintEnable(MdtHingeQuaConstraint(j))
#define MdtHingeDisable(j) MdtConstraintDisable(MdtHingeQuaConstraint(j))
#define MdtHingeIsEnabled(j) MdtConstraintIsEnabled(MdtHingeQuaConstraint(j))
#define MdtHingeSetSortKey(j, k) MdtConstraintSetSortKey(MdtHingeQuaConstraint(j), (k))
#define MdtHingeGetSortKey(j) MdtConstraintGetSortKey(MdtHingeQuaConstraint(j))
#define MdtHingeSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtHingeQuaConstraint(j), (b1), (b2))
#define MdtHingeGetBody(j, i) MdtConstraintGetBody(MdtHingeQuaConstraint(j), (i))
#define MdtHingeSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtHingeQuaConstraint(j), (x), (y), (z))
#define MdtHingeGetPosition(j, p) MdtConstraintGetPosition(MdtHingeQuaConstraint(j), (p))
#define MdtHingeSetAxis(j, x, y, z) MdtConstraintSetAxis(MdtHingeQuaConstraint(j), (x), (y), (z))
#define MdtHingeGetAxis(j, a) MdtConstraintBodyGetAxis(MdtHingeQuaConstraint(j), 0, (a))
#define MdtHingeGetForce(j, i, f) MdtConstraintGetForce(MdtHingeQuaConstraint(j), (i), (f))
#define MdtHingeGetTorque(j, i, t) MdtConstraintGetTorque(MdtHingeQuaConstraint(j), (i), (t))
#define MdtHingeSetUserData(j, d) MdtConstraintSetUserData(MdtHingeQuaConstraint(j), (d))
#define MdtHingeGetUserData(j) MdtConstraintGetUserData(MdtHingeQuaConstraint(j))
#define MdtHingeGetWorld(j) MdtConstraintGetWorld(MdtHingeQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_HINGE_H */
