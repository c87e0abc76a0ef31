/* MdtLinear1.h -- Linear1 joint: the attachment point of body 0 stays in a plane fixed in body 1 (or
 * in the world): the plane through body 1's attachment point, normal to the joint's axis (the
 * primary axis of body 1's frame). 1 row; rotation and motion in the plane are free.
 * Defaults: position (0,0,0), axis (plane normal) (1,0,0). */
#ifndef MDT_LINEAR1_H
#define MDT_LINEAR1_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled Linear1 joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtLinear1ID MdtLinear1Create(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtLinear1Reset(MdtLinear1ID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtLinear1QuaConstraint(MdtLinear1ID j);
/** The Linear1 joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtLinear1ID MdtConstraintDCastLinear1(MdtConstraintID c);

/** The plane's normal, world frame. */
#define MdtLinear1GetAxis(j, a) MdtConstraintBodyGetAxis(MdtLinear1QuaConstraint(j), 1, (a))

/* The common constraint API under this type's names. */
#define MdtLinear1Destroy(j) MdtConstraintDestroy(MdtLinear1QuaConstraint(j))
#define MdtLinear1Enable(j) MdtConstraintEnable(MdtLinear1QuaConstraint(j))
#define MdtLinear1Disable(j) MdtConstraintDisable(MdtLinear1QuaConstraint(j))
#define MdtLinear1IsEnabled(j) MdtConstraintIsEnabled(MdtLinear1QuaConstraint(j))
#define MdtLinear1SetBodies(j, b1, b2) MdtConstraintSetBodies(MdtLinear1QuaConstraint(j), (b1), (b2))
#define MdtLinear1GetBody(j, i) MdtConstraintGetBody(MdtLinear1QuaConstraint(j), (i))
#define MdtLinear1SetPosition(j, x, y, z) MdtConstraintSetPosition(MdtLinear1QuaConstraint(j), (x), (y), (z))
#define MdtLinear1GetPosition(j, p) MdtConstraintGetPosition(MdtLinear1QuaConstraint(j), (p))
#define MdtLinear1SetAxis(j, x, y, z) MdtConstraintSetAxis(MdtLinear1QuaConstraint(j), (x), (y), (z))
#define MdtLinear1SetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtLinear1QuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtLinear1GetAxes(j, p, o) MdtConstraintGetAxes(MdtLinear1QuaConstraint(j), (p), (o))
#define MdtLinear1GetForce(j, i, f) MdtConstraintGetForce(MdtLinear1QuaConstraint(j), (i), (f))
#define MdtLinear1GetTorque(j, i, t) MdtConstraintGetTorque(MdtLinear1QuaConstraint(j), (i), (t))
#define MdtLinear1SetUserData(j, d) MdtConstraintSetUserData(MdtLinear1QuaConstraint(j), (d))
#define MdtLinear1GetUserData(j) MdtConstraintGetUserData(MdtLinear1QuaConstraint(j))
#define MdtLinear1SetSortKey(j, k) MdtConstraintSetSortKey(MdtLinear1QuaConstraint(j), (k))
#define MdtLinear1GetSortKey(j) MdtConstraintGetSortKey(MdtLinear1QuaConstraint(j))
#define MdtLinear1GetWorld(j) MdtConstraintGetWorld(MdtLinear1QuaConstraint(j))
#define MdtLinear1GetRowCount(j) MdtConstraintGetRowCount(MdtLinear1QuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_LINEAR1_H */
