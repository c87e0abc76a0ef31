/* MdtConeLimit.h -- cone limit: keeps the angle between an axis of body 0 and an axis of body 1 (the
 * primary axes of their frames) at most the cone's half-angle. Use it with a joint that leaves the
 * swing free (MdtBSJoint, MdtUniversal, MdtAngular3 with rotation, MdtRPROJoint); it does not limit
 * twist. 1 row, written only at the limit (or when the limit will be reached within the step).
 * Below about 5 degrees the limit becomes unreliable (the axis direction is ill-defined near 0).
 * Defaults: half-angle π (no limit), stiffness MEINFINITY, damping MEINFINITY (a hard stop); axes
 * (1,0,0) in both bodies. A finite stiffness and damping make the stop a spring past the limit. */
#ifndef MDT_CONELIMIT_H
#define MDT_CONELIMIT_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled cone limit, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtConeLimitID MdtConeLimitCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtConeLimitReset(MdtConeLimitID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtConeLimitQuaConstraint(MdtConeLimitID j);
/** The cone limit behind a constraint ID, or NULL if it is of another type. */
ME_API MdtConeLimitID MdtConstraintDCastConeLimit(MdtConstraintID c);

/** Half-angle of the cone, rad, in [0, π] (π: no limit). */
ME_API void MdtConeLimitSetConeHalfAngle(MdtConeLimitID j, MeReal theta);
/** Half-angle of the cone (rad); 0 for an invalid ID. */
ME_API MeReal MdtConeLimitGetConeHalfAngle(MdtConeLimitID j);
/** Stiffness past the limit, N·m/rad (≥ 0; MEINFINITY = hard stop). */
ME_API void MdtConeLimitSetStiffness(MdtConeLimitID j, MeReal stiffness);
/** Stiffness past the limit (N·m/rad, MEINFINITY: hard); 0 for an invalid ID. */
ME_API MeReal MdtConeLimitGetStiffness(MdtConeLimitID j);
/** Damping past the limit, N·m·s/rad (≥ 0; MEINFINITY = hard stop). */
ME_API void MdtConeLimitSetDamping(MdtConeLimitID j, MeReal damping);
/** Damping past the limit (N·m·s/rad); 0 for an invalid ID. */
ME_API MeReal MdtConeLimitGetDamping(MdtConeLimitID j);
/** The angle between the two axes now, rad (0 ... π). */
ME_API MeReal MdtConeLimitGetAngle(MdtConeLimitID j);

/* The common constraint API under this type's names. */
#define MdtConeLimitDestroy(j) MdtConstraintDestroy(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitEnable(j) MdtConstraintEnable(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitDisable(j) MdtConstraintDisable(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitIsEnabled(j) MdtConstraintIsEnabled(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtConeLimitQuaConstraint(j), (b1), (b2))
#define MdtConeLimitGetBody(j, i) MdtConstraintGetBody(MdtConeLimitQuaConstraint(j), (i))
#define MdtConeLimitSetAxis(j, x, y, z) MdtConstraintSetAxis(MdtConeLimitQuaConstraint(j), (x), (y), (z))
#define MdtConeLimitSetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtConeLimitQuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtConeLimitGetAxes(j, p, o) MdtConstraintGetAxes(MdtConeLimitQuaConstraint(j), (p), (o))
#define MdtConeLimitGetForce(j, i, f) MdtConstraintGetForce(MdtConeLimitQuaConstraint(j), (i), (f))
#define MdtConeLimitGetTorque(j, i, t) MdtConstraintGetTorque(MdtConeLimitQuaConstraint(j), (i), (t))
#define MdtConeLimitSetUserData(j, d) MdtConstraintSetUserData(MdtConeLimitQuaConstraint(j), (d))
#define MdtConeLimitGetUserData(j) MdtConstraintGetUserData(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitSetSortKey(j, k) MdtConstraintSetSortKey(MdtConeLimitQuaConstraint(j), (k))
#define MdtConeLimitGetSortKey(j) MdtConstraintGetSortKey(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitGetWorld(j) MdtConstraintGetWorld(MdtConeLimitQuaConstraint(j))
#define MdtConeLimitGetRowCount(j) MdtConstraintGetRowCount(MdtConeLimitQuaConstraint(j))

/* Karma 1.2's names for the per-body axes and the cone's axis (body 1's primary axis). */
#define MdtConeLimitBodyGetAxes(j, i, p, o) MdtConstraintBodyGetAxes(MdtConeLimitQuaConstraint(j), (i), (p), (o))
#define MdtConeLimitBodySetAxes(j, i, px, py, pz, ox, oy, oz)                                           \
    MdtConstraintBodySetAxes(MdtConeLimitQuaConstraint(j), (i), (px), (py), (pz), (ox), (oy), (oz))
#define MdtConeLimitBodySetAxesRel(j, i, px, py, pz, ox, oy, oz)                                        \
    MdtConstraintBodySetAxesRel(MdtConeLimitQuaConstraint(j), (i), (px), (py), (pz), (ox), (oy), (oz))
#define MdtConeLimitGetAxis(j, a) MdtConstraintGetAxis(MdtConeLimitQuaConstraint(j), (a))

ME_EXTERN_C_END

#endif /* MDT_CONELIMIT_H */
