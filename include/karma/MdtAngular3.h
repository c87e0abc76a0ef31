/* MdtAngular3.h -- Angular3 joint: locks the relative orientation of two bodies (or of a body and
 * the world) and leaves their positions free (3 rows). MdtAngular3EnableRotation frees rotation about
 * the joint's axis (the primary axis of the frames): an "Angular2" joint, 2 rows, e.g. to keep a
 * vehicle upright while it can turn. A finite stiffness makes the lock an angular spring (torque
 * ≈ −stiffness·angle − damping·angular rate, per axis); MEINFINITY (default) makes it rigid.
 * Defaults: axis (1,0,0) in both bodies, rotation not enabled, stiffness MEINFINITY, damping 0. */
#ifndef MDT_ANGULAR3_H
#define MDT_ANGULAR3_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled Angular3 joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtAngular3ID MdtAngular3Create(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtAngular3Reset(MdtAngular3ID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtAngular3QuaConstraint(MdtAngular3ID j);
/** The Angular3 joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtAngular3ID MdtConstraintDCastAngular3(MdtConstraintID c);

/** Free (METRUE) or lock (MEFALSE) the rotation about the joint's axis. */
ME_API void MdtAngular3EnableRotation(MdtAngular3ID j, MeBool enable);
/** Whether rotation about the joint's axis is free; MEFALSE for an invalid ID. */
ME_API MeBool MdtAngular3RotationIsEnabled(MdtAngular3ID j);
/** Angular stiffness, N·m/rad (≥ 0; MEINFINITY = rigid). */
ME_API void MdtAngular3SetStiffness(MdtAngular3ID j, MeReal stiffness);
/** Angular stiffness (N·m/rad, MEINFINITY: rigid); 0 for an invalid ID. */
ME_API MeReal MdtAngular3GetStiffness(MdtAngular3ID j);
/** Angular damping, N·m·s/rad (≥ 0); used with a finite stiffness (or alone: a pure damper). */
ME_API void MdtAngular3SetDamping(MdtAngular3ID j, MeReal damping);
/** Angular damping (N·m·s/rad); 0 for an invalid ID. */
ME_API MeReal MdtAngular3GetDamping(MdtAngular3ID j);
/** The joint's axis in body 0, world frame. */
#define MdtAngular3GetAxis(j, a) MdtConstraintBodyGetAxis(MdtAngular3QuaConstraint(j), 0, (a))

/* The common constraint API under this type's names. */
#define MdtAngular3Destroy(j) MdtConstraintDestroy(MdtAngular3QuaConstraint(j))
#define MdtAngular3Enable(j) MdtConstraintEnable(MdtAngular3QuaConstraint(j))
#define MdtAngular3Disable(j) MdtConstraintDisable(MdtAngular3QuaConstraint(j))
#define MdtAngular3IsEnabled(j) MdtConstraintIsEnabled(MdtAngular3QuaConstraint(j))
#define MdtAngular3SetBodies(j, b1, b2) MdtConstraintSetBodies(MdtAngular3QuaConstraint(j), (b1), (b2))
#define MdtAngular3GetBody(j, i) MdtConstraintGetBody(MdtAngular3QuaConstraint(j), (i))
#define MdtAngular3SetAxis(j, x, y, z) MdtConstraintSetAxis(MdtAngular3QuaConstraint(j), (x), (y), (z))
#define MdtAngular3SetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtAngular3QuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtAngular3GetAxes(j, p, o) MdtConstraintGetAxes(MdtAngular3QuaConstraint(j), (p), (o))
#define MdtAngular3GetForce(j, i, f) MdtConstraintGetForce(MdtAngular3QuaConstraint(j), (i), (f))
#define MdtAngular3GetTorque(j, i, t) MdtConstraintGetTorque(MdtAngular3QuaConstraint(j), (i), (t))
#define MdtAngular3SetUserData(j, d) MdtConstraintSetUserData(MdtAngular3QuaConstraint(j), (d))
#define MdtAngular3GetUserData(j) MdtConstraintGetUserData(MdtAngular3QuaConstraint(j))
#define MdtAngular3SetSortKey(j, k) MdtConstraintSetSortKey(MdtAngular3QuaConstraint(j), (k))
#define MdtAngular3GetSortKey(j) MdtConstraintGetSortKey(MdtAngular3QuaConstraint(j))
#define MdtAngular3GetWorld(j) MdtConstraintGetWorld(MdtAngular3QuaConstraint(j))
#define MdtAngular3GetRowCount(j) MdtConstraintGetRowCount(MdtAngular3QuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_ANGULAR3_H */
