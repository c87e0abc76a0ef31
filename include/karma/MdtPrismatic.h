/* MdtPrismatic.h -- prismatic (slider) joint: body 0 slides relative to body 1 (or the world) along
 * a shared axis; relative rotation is locked. 5 rows, plus 1 when its limit acts.
 *
 * The displacement, read through the limit (MdtLimitGetPosition(MdtPrismaticGetLimit(j))), is the
 * travel of body 0's attachment point relative to body 1's along the axis (metres), zero at the
 * relative position the bodies had when the axis was set (MdtPrismaticSetAxis), or when the joint
 * was first stepped if the axis was never set. Rate: the relative velocity along the axis.
 * Defaults: axis (1,0,0) (docs/karma12.md decision D2); the limit's defaults (MdtLimit.h). */
#ifndef MDT_PRISMATIC_H
#define MDT_PRISMATIC_H

#include "MdtConstraint.h"
#include "MdtLimit.h"

ME_EXTERN_C_BEGIN

/** A new disabled prismatic joint, or NULL when the constraint pool is full. */
ME_API MdtPrismaticID MdtPrismaticCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtPrismaticReset(MdtPrismaticID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtPrismaticQuaConstraint(MdtPrismaticID j);
/** The joint behind a constraint ID, or NULL if it is not a prismatic joint. */
ME_API MdtPrismaticID MdtConstraintDCastPrismatic(MdtConstraintID c);
/** Sliding axis in world coordinates (set the bodies first); the current relative position becomes
 *  displacement 0. A zero axis is refused (ME_ERR_ZERO_AXIS). */
ME_API void MdtPrismaticSetAxis(MdtPrismaticID j, MeReal x, MeReal y, MeReal z);
/** The joint's limit (lives as long as the joint). */
ME_API MdtLimitID MdtPrismaticGetLimit(MdtPrismaticID j);
/** Copy a limit's settings (stops, motor, lock, activation) into the joint. */
ME_API void MdtPrismaticSetLimit(MdtPrismaticID j, const MdtLimit *limit);

#define MdtPrismaticDestroy(j) MdtConstraintDestroy(MdtPrismaticQuaConstraint(j))
#define MdtPrismaticEnable(j) MdtConstraintEnable(MdtPrismaticQuaConstraint(j))
#define MdtPrismaticDisable(j) MdtConstraintDisable(MdtPrismaticQuaConstraint(j))
#define MdtPrismaticIsEnabled(j) MdtConstraintIsEnabled(MdtPrismaticQuaConstraint(j))
#define MdtPrismaticSetSortKey(j, k) MdtConstraintSetSortKey(MdtPrismaticQuaConstraint(j), (k))
#define MdtPrismaticGetSortKey(j) MdtConstraintGetSortKey(MdtPrismaticQuaConstraint(j))
#define MdtPrismaticSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtPrismaticQuaConstraint(j), (b1), (b2))
#define MdtPrismaticGetBody(j, i) MdtConstraintGetBody(MdtPrismaticQuaConstraint(j), (i))
#define MdtPrismaticGetAxis(j, a) MdtConstraintBodyGetAxis(MdtPrismaticQuaConstraint(j), 1, (a))
#define MdtPrismaticGetForce(j, i, f) MdtConstraintGetForce(MdtPrismaticQuaConstraint(j), (i), (f))
#define MdtPrismaticGetTorque(j, i, t) MdtConstraintGetTorque(MdtPrismaticQuaConstraint(j), (i), (t))
#define MdtPrismaticSetUserData(j, d) MdtConstraintSetUserData(MdtPrismaticQuaConstraint(j), (d))
#define MdtPrismaticGetUserData(j) MdtConstraintGetUserData(MdtPrismaticQuaConstraint(j))
#define MdtPrismaticGetWorld(j) MdtConstraintGetWorld(MdtPrismaticQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_PRISMATIC_H */
