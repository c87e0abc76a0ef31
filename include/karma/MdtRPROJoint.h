/* MdtRPROJoint.h -- relative position and relative orientation joint: drives body 0's attachment
 * frame to a target orientation relative to body 1's (or the world's), with a target relative angular
 * velocity, and holds the attachment points together (6 rows: 3 linear along body 1's frame axes, 3
 * angular). Used to carry a body or make it follow an animation. Each axis has a strength, the
 * largest force (N) or torque (N·m) it may apply: a finite strength makes the joint soft (it lags
 * behind a target it cannot reach) and breakable.
 * The target q is the orientation of body 0's frame relative to body 1's: q = conj(F1) ⊗ F0 when the
 * target is met. The target angular velocity ω (rad/s) is ω0 − ω1 in body 1's frame coordinates;
 * a target that moves with ω advances as MeQuaternionFiniteRotation(q, ω, h).
 * Defaults: target identity, angular velocity 0, strengths MEINFINITY (rigid); attachment positions
 * 0 and orientations identity in both bodies. */
#ifndef MDT_RPROJOINT_H
#define MDT_RPROJOINT_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled RPRO joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtRPROJointID MdtRPROJointCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtRPROJointReset(MdtRPROJointID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtRPROJointQuaConstraint(MdtRPROJointID j);
/** The RPRO joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtRPROJointID MdtConstraintDCastRPROJoint(MdtConstraintID c);

/** Target relative orientation (unit quaternion w,x,y,z; ME_ERR_QUATERNION_NOT_UNIT otherwise). */
ME_API void MdtRPROJointSetRelativeQuaternion(MdtRPROJointID j, const MeVector4 q);
/** Target relative orientation (unit quaternion w, x, y, z); NULL q refused. */
ME_API void MdtRPROJointGetRelativeQuaternion(MdtRPROJointID j, MeVector4 q);
/** Target relative angular velocity, rad/s, body 1's frame. */
ME_API void MdtRPROJointSetAngularVelocity(MdtRPROJointID j, const MeVector3 w);
/** Target relative angular velocity (rad/s, body 1's frame); NULL w refused. */
ME_API void MdtRPROJointGetAngularVelocity(MdtRPROJointID j, MeVector3 w);
/** Largest force (N) along each linear axis of body 1's frame (≥ 0; MEINFINITY = no cap). */
ME_API void MdtRPROJointSetLinearStrength(MdtRPROJointID j, MeReal sx, MeReal sy, MeReal sz);
/** Force caps along the three linear axes (N); NULL s refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtRPROJointGetLinearStrength(MdtRPROJointID j, MeVector3 s);
/** Largest torque (N·m) about each angular axis (≥ 0; MEINFINITY = no cap). */
ME_API void MdtRPROJointSetAngularStrength(MdtRPROJointID j, MeReal sx, MeReal sy, MeReal sz);
/** Torque caps about the three angular axes (N·m); NULL s refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtRPROJointGetAngularStrength(MdtRPROJointID j, MeVector3 s);
/** Attachment point in body `bodyindex`'s frame (an offset from the body's origin). The body index
 *  comes last, as in Karma 1.2. */
ME_API void MdtRPROJointSetAttachmentPosition(MdtRPROJointID j, MeReal x, MeReal y, MeReal z,
                                              unsigned int bodyindex);
/** Attachment point on body bodyindex, in its frame (m); NULL p or index > 1 refused. */
ME_API void MdtRPROJointGetAttachmentPosition(MdtRPROJointID j, unsigned int bodyindex, MeVector3 p);
/** Attachment frame orientation in body `bodyindex`'s frame (unit quaternion q0 = w); the body
 *  index comes last, as in Karma 1.2. */
ME_API void MdtRPROJointSetAttachmentQuaternion(MdtRPROJointID j, MeReal q0, MeReal q1, MeReal q2, MeReal q3,
                                                unsigned int bodyindex);
/** Attachment orientation on body bodyindex (unit quaternion); NULL q or index > 1 refused. */
ME_API void MdtRPROJointGetAttachmentQuaternion(MdtRPROJointID j, unsigned int bodyindex, MeVector4 q);

/* The common constraint API under this type's names. */
#define MdtRPROJointDestroy(j) MdtConstraintDestroy(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointEnable(j) MdtConstraintEnable(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointDisable(j) MdtConstraintDisable(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointIsEnabled(j) MdtConstraintIsEnabled(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtRPROJointQuaConstraint(j), (b1), (b2))
#define MdtRPROJointGetBody(j, i) MdtConstraintGetBody(MdtRPROJointQuaConstraint(j), (i))
#define MdtRPROJointSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtRPROJointQuaConstraint(j), (x), (y), (z))
#define MdtRPROJointGetPosition(j, p) MdtConstraintGetPosition(MdtRPROJointQuaConstraint(j), (p))
#define MdtRPROJointSetAxis(j, x, y, z) MdtConstraintSetAxis(MdtRPROJointQuaConstraint(j), (x), (y), (z))
#define MdtRPROJointSetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtRPROJointQuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtRPROJointGetAxes(j, p, o) MdtConstraintGetAxes(MdtRPROJointQuaConstraint(j), (p), (o))
#define MdtRPROJointGetForce(j, i, f) MdtConstraintGetForce(MdtRPROJointQuaConstraint(j), (i), (f))
#define MdtRPROJointGetTorque(j, i, t) MdtConstraintGetTorque(MdtRPROJointQuaConstraint(j), (i), (t))
#define MdtRPROJointSetUserData(j, d) MdtConstraintSetUserData(MdtRPROJointQuaConstraint(j), (d))
#define MdtRPROJointGetUserData(j) MdtConstraintGetUserData(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointSetSortKey(j, k) MdtConstraintSetSortKey(MdtRPROJointQuaConstraint(j), (k))
#define MdtRPROJointGetSortKey(j) MdtConstraintGetSortKey(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointGetWorld(j) MdtConstraintGetWorld(MdtRPROJointQuaConstraint(j))
#define MdtRPROJointGetRowCount(j) MdtConstraintGetRowCount(MdtRPROJointQuaConstraint(j))

/* Karma 1.2's names: the target angular velocity (ω0 − ω1 in body 1's frame) and the sort key. */
#define MdtRPROJointSetRelativeAngularVelocity(j, w) MdtRPROJointSetAngularVelocity((j), (w))
#define MdtRPROJointGetRelativeAngularVelocity(j, w) MdtRPROJointGetAngularVelocity((j), (w))
#define MdtRPROSetSortKey(j, k) MdtConstraintSetSortKey(MdtRPROJointQuaConstraint(j), (k))
#define MdtRPROGetSortKey(j) MdtConstraintGetSortKey(MdtRPROJointQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_RPROJOINT_H */
