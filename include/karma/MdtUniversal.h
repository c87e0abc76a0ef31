/* MdtUniversal.h -- universal (Cardan, Hooke) joint: body 0 and body 1 share a point, and an axis
 * fixed in body 0 is kept perpendicular to an axis fixed in body 1, so that rotation about body 0's
 * axis is passed on to body 1 about its own (4 rows). Like a real Cardan joint it locks up when the
 * two shafts meet at 90 degrees: guard it with an MdtConeLimit.
 * Defaults: position (0,0,0); axis (1,0,0) in body 0 and (0,1,0) in body 1 (each body's frame). */
#ifndef MDT_UNIVERSAL_H
#define MDT_UNIVERSAL_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled universal joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtUniversalID MdtUniversalCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtUniversalReset(MdtUniversalID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtUniversalQuaConstraint(MdtUniversalID j);
/** The universal joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtUniversalID MdtConstraintDCastUniversal(MdtConstraintID c);

/** Body `bodyindex`'s axis as a world direction (stored in that body's frame; set the bodies first).
 *  Zero or non-finite axes are rejected (ME_ERR_ZERO_AXIS, ME_ERR_NONFINITE_ARGUMENT). */
ME_API void MdtUniversalSetAxis(MdtUniversalID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z);
/** Body `bodyindex`'s axis, world frame. */
ME_API void MdtUniversalGetAxis(MdtUniversalID j, unsigned int bodyindex, MeVector3 axis);
/** The joint's primary and orthogonal axes, world directions (Karma 1.2: both bodies' frames). */
#define MdtUniversalSetAxes(j, px, py, pz, ox, oy, oz)                                                  \
    MdtConstraintSetAxes(MdtUniversalQuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
/** Body `bodyindex`'s primary and orthogonal axes, world directions. */
#define MdtUniversalGetAxes(j, bodyindex, p, o)                                                         \
    MdtConstraintBodyGetAxes(MdtUniversalQuaConstraint(j), (bodyindex), (p), (o))

/* The common constraint API under this type's names. */
#define MdtUniversalDestroy(j) MdtConstraintDestroy(MdtUniversalQuaConstraint(j))
#define MdtUniversalEnable(j) MdtConstraintEnable(MdtUniversalQuaConstraint(j))
#define MdtUniversalDisable(j) MdtConstraintDisable(MdtUniversalQuaConstraint(j))
#define MdtUniversalIsEnabled(j) MdtConstraintIsEnabled(MdtUniversalQuaConstraint(j))
#define MdtUniversalSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtUniversalQuaConstraint(j), (b1), (b2))
#define MdtUniversalGetBody(j, i) MdtConstraintGetBody(MdtUniversalQuaConstraint(j), (i))
#define MdtUniversalSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtUniversalQuaConstraint(j), (x), (y), (z))
#define MdtUniversalGetPosition(j, p) MdtConstraintGetPosition(MdtUniversalQuaConstraint(j), (p))
#define MdtUniversalGetForce(j, i, f) MdtConstraintGetForce(MdtUniversalQuaConstraint(j), (i), (f))
#define MdtUniversalGetTorque(j, i, t) MdtConstraintGetTorque(MdtUniversalQuaConstraint(j), (i), (t))
#define MdtUniversalSetUserData(j, d) MdtConstraintSetUserData(MdtUniversalQuaConstraint(j), (d))
#define MdtUniversalGetUserData(j) MdtConstraintGetUserData(MdtUniversalQuaConstraint(j))
#define MdtUniversalSetSortKey(j, k) MdtConstraintSetSortKey(MdtUniversalQuaConstraint(j), (k))
#define MdtUniversalGetSortKey(j) MdtConstraintGetSortKey(MdtUniversalQuaConstraint(j))
#define MdtUniversalGetWorld(j) MdtConstraintGetWorld(MdtUniversalQuaConstraint(j))
#define MdtUniversalGetRowCount(j) MdtConstraintGetRowCount(MdtUniversalQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_UNIVERSAL_H */
