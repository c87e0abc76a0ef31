/* MdtBody.h -- rigid bodies: state, mass properties, forces.
 *
 * A body is created disabled, at the origin, with identity orientation, zero velocities, mass
 * massScale and spherical inertia 0.4·mass·lengthScale² (a solid sphere of radius lengthScale).
 * Only enabled bodies are simulated. The body frame is the frame the application sees (position,
 * orientation, transform); the centre of mass may be offset from it (SetCenterOfMass...), and the
 * inertia tensor is expressed about the centre of mass in the body frame.
 *
 * Forces, torques and impulses accumulate until the next step and are cleared by it; on a disabled
 * body they are kept until it is enabled. All vectors are in world coordinates unless the name says
 * "Relative" (body frame). Units: SI by habit (see MePrecision.h). Setters reject NaN or infinite
 * values, non-positive masses, negative damping and non-unit quaternions with a coded warning, and
 * leave the body unchanged. */
#ifndef MDT_BODY_H
#define MDT_BODY_H

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/* ---- lifecycle ---------------------------------------------------------------------------- */
/** A new disabled body, or NULL when the world's body pool is full (raise maxBodies). */
ME_API MdtBodyID MdtBodyCreate(MdtWorldID w);
/** Destroy a body (its constraints must be destroyed or re-attached first). */
ME_API void MdtBodyDestroy(MdtBodyID b);
/** Restore the creation defaults (keeps the world, enabled state and user data). */
ME_API void MdtBodyReset(MdtBodyID b);
/** A disabled copy of `b` (state, mass properties, settings) in world `w`. */
ME_API MdtBodyID MdtBodyCopy(MdtBodyID b, MdtWorldID w);
/** Enable the body so the next step simulates it (invalid ID refused, ME_ERR_INVALID_HANDLE). */
ME_API void MdtBodyEnable(MdtBodyID b);
/** Disable the body: it stays where it is and its pending forces are kept (invalid ID refused). */
ME_API void MdtBodyDisable(MdtBodyID b);
/** Whether the body is simulated; MEFALSE for an invalid ID. */
ME_API MeBool MdtBodyIsEnabled(MdtBodyID b);
/** Whether the body counts as moving for auto-disable under `params`' thresholds (MdtPartition.h):
 *  its squared speed, angular speed, acceleration or angular acceleration (of the last step) is above
 *  its threshold, or it has been enabled for less than alive_time_thresh (unless the partitioner
 *  woke it this step). MdtWorldGetPartitionParams gives the world's thresholds. */
ME_API MeBool MdtBodyIsMovingTest(MdtBodyID b, const MdtPartitionParams *params);
/** Whether `b` is a live body ID (no message). */
ME_API MeBool MdtBodyIsValid(MdtBodyID b);
/** Print the body's state through MeInfo. */
ME_API void MdtBodyLog(MdtBodyID b);

/* ---- accessors ---------------------------------------------------------------------------- */
/** The world that owns the body; NULL for an invalid ID. */
ME_API MdtWorldID MdtBodyGetWorld(MdtBodyID b);
/** Index of the body's partition in the last step, or -1. */
ME_API int MdtBodyGetPartition(MdtBodyID b);
/** Pointer to the body-frame transform; stable for the body's life (renderers keep it). */
ME_API MeMatrix4Ptr MdtBodyGetTransformPtr(MdtBodyID b);
/** Copy the body-frame transform (world from body, m) into m; NULL m refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtBodyGetTransform(MdtBodyID b, MeMatrix4 m);
/** The application pointer set by MdtBodySetUserData (owned by the application); NULL if unset. */
ME_API void *MdtBodyGetUserData(MdtBodyID b);
/** The collision model a bridge linked to this body (McdModelSetBody), as an untyped pointer that Mdt
 *  stores and never follows; NULL if none or for an invalid ID. */
ME_API void *MdtBodyGetModel(MdtBodyID b);
/** Mass (kg); 0 for an invalid ID. */
ME_API MeReal MdtBodyGetMass(MdtBodyID b);
/** Inertia tensor about the centre of mass, body frame (kg·m²). */
ME_API void MdtBodyGetInertiaTensor(MdtBodyID b, MeMatrix3 i);
/** Origin of the body frame, world coordinates (m); NULL p refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtBodyGetPosition(MdtBodyID b, MeVector3 p);
/** Orientation quaternion (w, x, y, z) of the body frame; NULL q refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtBodyGetQuaternion(MdtBodyID b, MeVector4 q);
/** Rotation matrix whose rows are the body's x, y, z axes in world coordinates. */
ME_API void MdtBodyGetOrientation(MdtBodyID b, MeMatrix3 R);
/** Velocity of the centre of mass (m/s). */
ME_API void MdtBodyGetLinearVelocity(MdtBodyID b, MeVector3 v);
/** Pointer to the body's linear velocity (m/s), owned by the body, valid while it lives; NULL for an invalid ID. */
ME_API MeReal *MdtBodyGetLinearVelocityPtr(MdtBodyID b);
/** Angular velocity, world frame (rad/s). */
ME_API void MdtBodyGetAngularVelocity(MdtBodyID b, MeVector3 v);
/** Pointer to the body's angular velocity (rad/s, world frame), owned by the body; NULL for an invalid ID. */
ME_API MeReal *MdtBodyGetAngularVelocityPtr(MdtBodyID b);
/** Velocity of the material point at world position p. */
ME_API void MdtBodyGetVelocityAtPoint(MdtBodyID b, const MeVector3 p, MeVector3 v);
/** Linear/angular acceleration over the last step (read only). */
ME_API void MdtBodyGetLinearAcceleration(MdtBodyID b, MeVector3 a);
/** Angular acceleration over the last step (rad/s², world frame); NULL a refused. */
ME_API void MdtBodyGetAngularAcceleration(MdtBodyID b, MeVector3 a);
/** Fast-spin axis, world frame (default (0,1,0)). */
ME_API void MdtBodyGetFastSpinAxis(MdtBodyID b, MeVector3 v);
/** Whether a fast-spin axis is set (MdtBodySetFastSpinAxis); MEFALSE for an invalid ID. */
ME_API MeBool MdtBodyFastSpinAxisIsEnabled(MdtBodyID b);
/** Linear drag coefficient (N·s/m); 0 for an invalid ID. */
ME_API MeReal MdtBodyGetLinearVelocityDamping(MdtBodyID b);
/** Angular drag coefficient (N·m·s); 0 for an invalid ID. */
ME_API MeReal MdtBodyGetAngularVelocityDamping(MdtBodyID b);
/** Force and torque accumulated for the next step. */
ME_API void MdtBodyGetForce(MdtBodyID b, MeVector3 f);
/** Torque accumulated for the next step (N·m, world frame); NULL t refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtBodyGetTorque(MdtBodyID b, MeVector3 t);
/** ½ m v·v + ½ ω·Iω (J). */
ME_API MeReal MdtBodyGetKineticEnergy(MdtBodyID b);
/** Seconds the body has been enabled since it was last enabled (auto-disable's alive window). */
ME_API MeReal MdtBodyGetEnabledTime(MdtBodyID b);
/** Centre-of-mass frame relative to the body frame (translation in m); NULL t refused. */
ME_API void MdtBodyGetCenterOfMassRelativeTransform(MdtBodyID b, MeMatrix4 t);
/** Centre of mass, world frame. */
ME_API void MdtBodyGetCenterOfMassPosition(MdtBodyID b, MeVector3 pos);
/** Centre of mass, body frame. */
ME_API void MdtBodyGetCenterOfMassRelativePosition(MdtBodyID b, MeVector3 pos);
/** Pointer to the centre-of-mass frame's transform (equals the body transform without offset). */
ME_API MeMatrix4Ptr MdtBodyGetCenterOfMassTransformPtr(MdtBodyID b);
/** The body's determinism order key (MdtBodySetSortKey); 0 for an invalid ID. */
ME_API MeI32 MdtBodyGetSortKey(MdtBodyID b);

/* ---- mutators ----------------------------------------------------------------------------- */
/** Attach an application pointer (not owned, never freed by Karma); invalid ID refused. */
ME_API void MdtBodySetUserData(MdtBodyID b, void *d);
/** Record the collision model linked to this body (for a bridge: McdModelSetBody calls it); untyped,
 *  not owned, never followed by Mdt; NULL unlinks. Invalid body refused (ME_ERR_INVALID_HANDLE). */
ME_API void MdtBodySetModel(MdtBodyID b, void *model);
/** Set position and orientation from a transform (rotation part must be orthonormal). */
ME_API void MdtBodySetTransform(MdtBodyID b, MeMatrix4 tm);
/** Mass (kg, > 0). The inertia tensor is left as it is. */
ME_API void MdtBodySetMass(MdtBodyID b, MeReal mass);
/** Full inertia tensor about the centre of mass in the body frame (symmetric positive definite).
 *  It takes effect once non-spherical inertia is enabled; otherwise its mean diagonal is used. */
ME_API void MdtBodySetInertiaTensor(MdtBodyID b, MeMatrix3 i);
/** Whether I (kg m²) is what MdtBodySetInertiaTensor accepts: finite, symmetric to a relative 1e-4 and
 *  positive definite in MeReal (a tensor whose determinant underflows is refused); NULL refused. */
ME_API MeBool MdtInertiaTensorIsValid(MeMatrix3 I);
/** Spherical inertia i·identity (kg·m², > 0). */
ME_API void MdtBodySetSphericalInertiaTensor(MdtBodyID b, MeReal i);
/** Move the body-frame origin to (x, y, z) in world coordinates (m); NaN or infinite refused (ME_ERR_NONFINITE_ARGUMENT). */
ME_API void MdtBodySetPosition(MdtBodyID b, MeReal x, MeReal y, MeReal z);
/** Orientation from a rotation matrix whose rows are the body axes in world coordinates. */
ME_API void MdtBodySetOrientation(MdtBodyID b, MeMatrix3 R);
/** Orientation quaternion (w, x, y, z), unit within 1e-3 (it is renormalised). */
ME_API void MdtBodySetQuaternion(MdtBodyID b, MeReal qw, MeReal qx, MeReal qy, MeReal qz);
/** Velocity of the centre of mass (m/s, world frame); NaN or infinite refused (ME_ERR_NONFINITE_ARGUMENT). */
ME_API void MdtBodySetLinearVelocity(MdtBodyID b, MeReal dx, MeReal dy, MeReal dz);
/** Angular velocity (rad/s, world frame); NaN or infinite refused (ME_ERR_NONFINITE_ARGUMENT). */
ME_API void MdtBodySetAngularVelocity(MdtBodyID b, MeReal wx, MeReal wy, MeReal wz);
/** Linear drag coefficient c ≥ 0 (N·s/m): force −c·v, integrated implicitly. Default 0. */
ME_API void MdtBodySetLinearVelocityDamping(MdtBodyID b, MeReal d);
/** Angular drag coefficient c ≥ 0 (N·m·s): torque −c·ω, integrated implicitly. Default 0. */
ME_API void MdtBodySetAngularVelocityDamping(MdtBodyID b, MeReal d);
/** Integrate the rotation about this world-frame axis exactly (wheels). As in Karma, set it again
 *  before every step (from the wheel's current axis): the world-frame axis then follows the body. */
ME_API void MdtBodySetFastSpinAxis(MdtBodyID b, MeReal x, MeReal y, MeReal z);
/** Remove the fast-spin axis: the rotation is integrated normally again. */
ME_API void MdtBodySetNoFastSpinAxis(MdtBodyID b);
/** Use the full inertia tensor set by MdtBodySetInertiaTensor instead of its mean diagonal. */
ME_API void MdtBodyEnableNonSphericalInertia(MdtBodyID b);
/** Use the spherical inertia (mean diagonal of the tensor) again. */
ME_API void MdtBodyDisableNonSphericalInertia(MdtBodyID b);
/** Whether the full inertia tensor is used; MEFALSE for an invalid ID. */
ME_API MeBool MdtBodyNonSphericalInertiaIsEnabled(MdtBodyID b);
/** Include the gyroscopic term ω×Iω (needs non-spherical inertia to matter). Off by default. */
ME_API void MdtBodyEnableCoriolisForce(MdtBodyID b);
/** Leave out the gyroscopic term ω×Iω again (the default). */
ME_API void MdtBodyDisableCoriolisForce(MdtBodyID b);
/** Whether the gyroscopic term ω×Iω is integrated; MEFALSE for an invalid ID. */
ME_API MeBool MdtBodyCoriolisForceIsEnabled(MdtBodyID b);
/** Centre of mass at a world position (moves the offset, not the body). */
ME_API void MdtBodySetCenterOfMassPosition(MdtBodyID b, const MeVector3 pos);
/** Centre of mass at a body-frame position. */
ME_API void MdtBodySetCenterOfMassRelativePosition(MdtBodyID b, const MeVector3 pos);
/** Centre-of-mass frame relative to the body frame (only the translation is used: the inertia
 *  tensor is given in the body frame). */
ME_API void MdtBodySetCenterOfMassRelativeTransform(MdtBodyID b, MeMatrix4 t);
/** Order key for determinism (0 ... 2^31−1): constraints and partitions are processed in key order. */
ME_API void MdtBodySetSortKey(MdtBodyID b, MeI32 key);

/* ---- iteration ---------------------------------------------------------------------------- */
/** Bodies of a world in creation-slot order; NULL after the last. */
ME_API MdtBodyID MdtBodyGetFirst(MdtWorldID w);
/** The body after b in creation-slot order, or NULL after the last (or for an invalid ID). */
ME_API MdtBodyID MdtBodyGetNext(MdtBodyID b);

/* ---- forces ------------------------------------------------------------------------------- */
/** Clear the force and torque accumulated for the next step. */
ME_API void MdtBodyResetForces(MdtBodyID b);
/** Clear the linear and angular impulses accumulated for the next step. */
ME_API void MdtBodyResetImpulses(MdtBodyID b);
/** Force through the centre of mass (N), for the next step. */
ME_API void MdtBodyAddForce(MdtBodyID b, MeReal fx, MeReal fy, MeReal fz);
/** Force at a world point: adds the force and the torque (p − com) × f. */
ME_API void MdtBodyAddForceAtPosition(MdtBodyID b, MeReal fx, MeReal fy, MeReal fz, MeReal px, MeReal py, MeReal pz);
/** Add a torque (N·m, world frame) for the next step; NaN or infinite refused (ME_ERR_NONFINITE_ARGUMENT). */
ME_API void MdtBodyAddTorque(MdtBodyID b, MeReal tx, MeReal ty, MeReal tz);
/** Impulse through the centre of mass (N·s): changes momentum by exactly this, whatever the step. */
ME_API void MdtBodyAddImpulse(MdtBodyID b, MeReal ix, MeReal iy, MeReal iz);
/** Impulse (N·s) at world point p (m): adds it and the angular impulse (p − com) × i; NaN or infinite refused. */
ME_API void MdtBodyAddImpulseAtPosition(MdtBodyID b, MeReal ix, MeReal iy, MeReal iz, MeReal px, MeReal py,
                                        MeReal pz);

/* ---- utilities ---------------------------------------------------------------------------- */
/** Inertia tensor of a solid sphere / box (full edge lengths) of mass m about its centre. */
ME_API void MdtMakeInertiaTensorSphere(MeReal mass, MeReal radius, MeMatrix3 i);
/** Inertia tensor (kg·m²) of a solid box of mass m (kg) and full edge lengths dx, dy, dz (m); NULL i refused. */
ME_API void MdtMakeInertiaTensorBox(MeReal mass, MeReal dx, MeReal dy, MeReal dz, MeMatrix3 i);
/** Express a direction given in body `from`'s frame in body `to`'s frame (NULL = world). */
ME_API void MdtConvertVector(MdtBodyID from, const MeVector3 v, MdtBodyID to, MeVector3 out);
/** Express a point given in body `from`'s frame in body `to`'s frame (NULL = world). */
ME_API void MdtConvertPositionVector(MdtBodyID from, const MeVector3 v, MdtBodyID to, MeVector3 out);

ME_EXTERN_C_END

#endif /* MDT_BODY_H */
