/* MdtCarWheel.h -- car wheel joint: body 0 is the chassis, body 1 the wheel (attached at its centre).
 *
 * The wheel's centre slides along the steering axis (fixed in the chassis: the suspension), the
 * wheel turns about the steering axis (steering) and about its hinge axis (fixed in the wheel,
 * kept perpendicular to the steering axis). Rows: 2 keep the centre on the suspension line, 1 keeps
 * the axes perpendicular; then the suspension (a spring-damper Kp, Kd about `reference` between hard
 * stops `lo`, `hi` whose softness adds compliance), the steering (a lock at angle 0, or a
 * limited-force motor) and the wheel's limited-force motor, each 1 row when it acts: 6 at most.
 *
 * Set the bodies, then MdtCarWheelSetPosition at the wheel's centre (world) and
 * MdtCarWheelSetSteeringAndHingeAxes(j, steering, hinge) (world; the hinge axis is made
 * perpendicular to the steering axis).
 *  - Suspension height: (p0 − p1)·s, p0 the attachment point on the chassis, p1 on the wheel, s the
 *    steering axis: 0 where the position was set, growing as the wheel drops along −s (m).
 *  - Steering angle: rotation of the wheel about s relative to the chassis (rad, in (−π, π]).
 *  - Hinge angle: rotation of the wheel about its hinge axis relative to the chassis, in [0, 2π).
 *  - Rates: (ω1 − ω0)·s, (ω1 − ω0)·hinge axis, d(height)/dt.
 * Defaults (docs/karma12.md §5.4): steering axis (0,0,1) and hinge axis (0,1,0) in both bodies' frames;
 * steering motor desired velocity 0 with max force 1e9 (holds the steering); steering not locked;
 * hinge motor 0, max force 0 (free); suspension Kp 0, Kd 0, softness 0, lo −1e9, hi 1e9, ref 0. */
#ifndef MDT_CARWHEEL_H
#define MDT_CARWHEEL_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled car wheel joint, or NULL when the constraint pool is full. */
ME_API MdtCarWheelID MdtCarWheelCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtCarWheelReset(MdtCarWheelID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtCarWheelQuaConstraint(MdtCarWheelID j);
/** The joint behind a constraint ID, or NULL if it is not a car wheel joint. */
ME_API MdtCarWheelID MdtConstraintDCastCarWheel(MdtConstraintID c);

/* ---- accessors (world frame; the angles and the height at the current poses) ---- */
/** Steering axis (unit, world frame, fixed in the chassis); NULL v refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtCarWheelGetSteeringAxis(MdtCarWheelID j, MeVector3 v);
/** Steering angle at the current poses (rad); 0, reported (ME_ERR_BAD_STATE), before bodies are set. */
ME_API MeReal MdtCarWheelGetSteeringAngle(MdtCarWheelID j);
/** Steering rate (rad/s); 0, reported (ME_ERR_BAD_STATE), before bodies are set. */
ME_API MeReal MdtCarWheelGetSteeringAngleRate(MdtCarWheelID j);
/** Wheel spin axis (unit, world frame, fixed in the wheel); NULL v refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtCarWheelGetHingeAxis(MdtCarWheelID j, MeVector3 v);
/** Wheel spin angle, 0 ... 2π (rad); 0, reported (ME_ERR_BAD_STATE), before bodies are set. */
ME_API MeReal MdtCarWheelGetHingeAngle(MdtCarWheelID j);
/** Wheel spin rate (rad/s); 0, reported (ME_ERR_BAD_STATE), before bodies are set. */
ME_API MeReal MdtCarWheelGetHingeAngleRate(MdtCarWheelID j);
/** Suspension height along the steering axis (m); 0, reported, before bodies are set. */
ME_API MeReal MdtCarWheelGetSuspensionHeight(MdtCarWheelID j);
/** Rate of change of the suspension height (m/s); 0, reported, before bodies are set. */
ME_API MeReal MdtCarWheelGetSuspensionRate(MdtCarWheelID j);
/** Target steering rate of the steering motor (rad/s); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSteeringMotorDesiredVelocity(MdtCarWheelID j);
/** Torque bound of the steering motor (N·m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSteeringMotorMaxForce(MdtCarWheelID j);
/** Whether the steering is locked at angle 0; MEFALSE for an invalid ID. */
ME_API MeBool MdtCarWheelIsSteeringLocked(MdtCarWheelID j);
/** Target spin rate of the wheel motor (rad/s); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetHingeMotorDesiredVelocity(MdtCarWheelID j);
/** Torque bound of the wheel motor (N·m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetHingeMotorMaxForce(MdtCarWheelID j);
/** Upper hard stop of the suspension height (m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSuspensionHighLimit(MdtCarWheelID j);
/** Lower hard stop of the suspension height (m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSuspensionLowLimit(MdtCarWheelID j);
/** Softness of the suspension stops (m/(N·s)); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSuspensionLimitSoftness(MdtCarWheelID j);
/** Height the suspension spring pulls towards (m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSuspensionReference(MdtCarWheelID j);
/** Suspension spring constant (N/m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSuspensionKp(MdtCarWheelID j);
/** Suspension damping constant (N·s/m); 0 for an invalid ID. */
ME_API MeReal MdtCarWheelGetSuspensionKd(MdtCarWheelID j);

/* ---- mutators ---- */
/** Steering motor: target steering rate (rad/s) and torque bound (N·m, ≥ 0; 0 = free steering). */
ME_API void MdtCarWheelSetSteeringLimitedForceMotor(MdtCarWheelID j, MeReal desiredVelocity, MeReal forceLimit);
/** Lock the steering at angle 0 (replaces the steering motor while locked). */
ME_API void MdtCarWheelSetSteeringLock(MdtCarWheelID j, MeBool lock);
/** Wheel motor: target spin rate (rad/s) and torque bound (N·m, ≥ 0; 0 = free). Brake: v = 0. */
ME_API void MdtCarWheelSetHingeLimitedForceMotor(MdtCarWheelID j, MeReal desiredVelocity, MeReal forceLimit);
/** Suspension: spring Kp (N/m, ≥ 0) and damper Kd (N·s/m, ≥ 0) about the height `reference`,
 *  between hard stops lolimit ≤ hilimit (m) made compliant by limit_softness (≥ 0, added to the stop
 *  rows' ε, m/(N·s)). */
ME_API void MdtCarWheelSetSuspension(MdtCarWheelID j, MeReal Kp, MeReal Kd, MeReal limit_softness, MeReal lolimit,
                                     MeReal hilimit, MeReal reference);

#define MdtCarWheelDestroy(j) MdtConstraintDestroy(MdtCarWheelQuaConstraint(j))
#define MdtCarWheelEnable(j) MdtConstraintEnable(MdtCarWheelQuaConstraint(j))
#define MdtCarWheelDisable(j) MdtConstraintDisable(MdtCarWheelQuaConstraint(j))
#define MdtCarWheelIsEnabled(j) MdtConstraintIsEnabled(MdtCarWheelQuaConstraint(j))
#define MdtCarWheelSetSortKey(j, k) MdtConstraintSetSortKey(MdtCarWheelQuaConstraint(j), (k))
#define MdtCarWheelGetSortKey(j) MdtConstraintGetSortKey(MdtCarWheelQuaConstraint(j))
#define MdtCarWheelSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtCarWheelQuaConstraint(j), (b1), (b2))
#define MdtCarWheelGetBody(j, i) MdtConstraintGetBody(MdtCarWheelQuaConstraint(j), (i))
#define MdtCarWheelSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtCarWheelQuaConstraint(j), (x), (y), (z))
#define MdtCarWheelGetPosition(j, p) MdtConstraintGetPosition(MdtCarWheelQuaConstraint(j), (p))
#define MdtCarWheelSetSteeringAndHingeAxes(j, px, py, pz, ox, oy, oz)                                  \
    MdtConstraintSetAxes(MdtCarWheelQuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtCarWheelGetSteeringAndHingeAxes(j, i, p, o) MdtConstraintBodyGetAxes(MdtCarWheelQuaConstraint(j), (i), (p), (o))
#define MdtCarWheelGetForce(j, i, f) MdtConstraintGetForce(MdtCarWheelQuaConstraint(j), (i), (f))
#define MdtCarWheelGetTorque(j, i, t) MdtConstraintGetTorque(MdtCarWheelQuaConstraint(j), (i), (t))
#define MdtCarWheelSetUserData(j, d) MdtConstraintSetUserData(MdtCarWheelQuaConstraint(j), (d))
#define MdtCarWheelGetUserData(j) MdtConstraintGetUserData(MdtCarWheelQuaConstraint(j))
#define MdtCarWheelGetWorld(j) MdtConstraintGetWorld(MdtCarWheelQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_CARWHEEL_H */
