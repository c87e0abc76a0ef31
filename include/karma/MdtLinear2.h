/* MdtLinear2.h -- Linear2 joint: the attachment point of body 0 stays on a line fixed in body 1 (a
 * rail): the line through body 1's attachment point along the joint's direction. 2 rows; sliding
 * along the line and rotation are free.
 * Defaults: position (0,0,0); direction (1,0,0) (Karma records (0,0,0), which defines no line:
 * docs/decisions.md). */
#ifndef MDT_LINEAR2_H
#define MDT_LINEAR2_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled Linear2 joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtLinear2ID MdtLinear2Create(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtLinear2Reset(MdtLinear2ID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtLinear2QuaConstraint(MdtLinear2ID j);
/** The Linear2 joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtLinear2ID MdtConstraintDCastLinear2(MdtConstraintID c);

/** The line's direction, world coordinates (set the bodies first). Zero or non-finite directions are
 *  rejected (ME_ERR_ZERO_AXIS, ME_ERR_NONFINITE_ARGUMENT). */
ME_API void MdtLinear2SetDirection(MdtLinear2ID j, MeReal x, MeReal y, MeReal z);
/** The line's direction, world frame. */
ME_API void MdtLinear2GetDirection(MdtLinear2ID j, MeVector3 direction);

/* The common constraint API under this type's names. */
#define MdtLinear2Destroy(j) MdtConstraintDestroy(MdtLinear2QuaConstraint(j))
#define MdtLinear2Enable(j) MdtConstraintEnable(MdtLinear2QuaConstraint(j))
#define MdtLinear2Disable(j) MdtConstraintDisable(MdtLinear2QuaConstraint(j))
#define MdtLinear2IsEnabled(j) MdtConstraintIsEnabled(MdtLinear2QuaConstraint(j))
#define MdtLinear2SetBodies(j, b1, b2) MdtConstraintSetBodies(MdtLinear2QuaConstraint(j), (b1), (b2))
#define MdtLinear2GetBody(j, i) MdtConstraintGetBody(MdtLinear2QuaConstraint(j), (i))
#define MdtLinear2SetPosition(j, x, y, z) MdtConstraintSetPosition(MdtLinear2QuaConstraint(j), (x), (y), (z))
#define MdtLinear2GetPosition(j, p) MdtConstraintGetPosition(MdtLinear2QuaConstraint(j), (p))
#define MdtLinear2GetForce(j, i, f) MdtConstraintGetForce(MdtLinear2QuaConstraint(j), (i), (f))
#define MdtLinear2GetTorque(j, i, t) MdtConstraintGetTorque(MdtLinear2QuaConstraint(j), (i), (t))
#define MdtLinear2SetUserData(j, d) MdtConstraintSetUserData(MdtLinear2QuaConstraint(j), (d))
#define MdtLinear2GetUserData(j) MdtConstraintGetUserData(MdtLinear2QuaConstraint(j))
#define MdtLinear2SetSortKey(j, k) MdtConstraintSetSortKey(MdtLinear2QuaConstraint(j), (k))
#define MdtLinear2GetSortKey(j) MdtConstraintGetSortKey(MdtLinear2QuaConstraint(j))
#define MdtLinear2GetWorld(j) MdtConstraintGetWorld(MdtLinear2QuaConstraint(j))
#define MdtLinear2GetRowCount(j) MdtConstraintGetRowCount(MdtLinear2QuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_LINEAR2_H */
