/* MdtLimit.h -- limits and motors on the free coordinate of a joint (hinge angle, prismatic
 * displacement, spring length).
 *
 * An MdtLimit has a lower and an upper MdtSingleLimit (a stop with its stiffness, damping and
 * restitution), a limited-force motor and a lock. A joint that has one (MdtHingeGetLimit,
 * MdtPrismaticGetLimit, MdtSpringGetLimit) adds at most one row for it in a step:
 *  - a **hard stop** (stiffness ≥ the limit's stiffness threshold, MEINFINITY by default): the
 *    coordinate may not pass the stop; arriving faster than a small threshold it bounces back at
 *    `restitution` × its arrival speed;
 *  - a **soft stop** (stiffness below the threshold): past the stop a spring (stiffness k, damping d)
 *    pushes it back; it only pushes, never pulls. A side whose stiffness and damping are both 0 is
 *    no stop at all;
 *  - a **motor** (not at a stop): drives the coordinate's rate to the desired velocity with at most
 *    the maximum force (N, or N·m for angles). At v = 0 it is dry joint friction. A motor pushing
 *    into a hard stop keeps pushing with up to its maximum force there;
 *  - a **lock**: holds the coordinate at the lock position with at most the lock's force (excludes
 *    the motor and the stops).
 * Coordinates are in metres or radians, rates per second. The reported coordinate is the joint's
 * measured one plus an offset (MdtLimitSetPosition); stops, lock and controller use the reported one.
 *
 * The structures are Karma's (`MdtBclLimit` = `MdtLimit`, `MdtBclSingleLimit` = `MdtSingleLimit`),
 * so an application may declare one, MdtLimitReset it, and copy it into a joint (MdtHingeSetLimit).
 * Change them through the functions below, which check their arguments; a limit that was not
 * initialised by MdtLimitReset is refused (ME_ERR_BAD_STATE). A limit obtained from a joint lives as
 * long as the joint. Defaults (MdtLimitReset): stops 0, stiffness MEINFINITY, damping 0,
 * restitution 1, limits inactive, motor off with desired velocity 0 and maximum force 0 (docs/karma12.md
 * decision D4), not locked, offset 0. */
#ifndef MDT_LIMIT_H
#define MDT_LIMIT_H

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** One stop of a limit. */
typedef struct MdtBclSingleLimit {
    MeReal stop;        /**< position of the stop (m or rad); default 0 */
    MeReal stiffness;   /**< N/m or N·m/rad; ≥ the limit's threshold = hard; default MEINFINITY */
    MeReal damping;     /**< N·s/m or N·m·s/rad, soft stops only; default 0 */
    MeReal restitution; /**< 0 ... 1, hard stops only; default 1 */
} MdtBclSingleLimit;

/** The library's own bookkeeping of a limit (the unwrapped measured coordinate, a pending bounce,
 *  this step's row and its kind, the motor's stall, the mark MdtLimitReset sets): no part of the API,
 *  read and written by the library only; its layout may change between releases. */
typedef struct MdtLimitPrivate {
    MeReal reals_[2];
    int ints_[4];
    MeU32 word_;
} MdtLimitPrivate;

/** A joint coordinate's limits, motor and lock, and its measured state. */
typedef struct MdtBclLimit {
    MdtBclSingleLimit limit[2]; /**< [0] lower, [1] upper stop */
    MeReal position;            /**< coordinate reported to the user: measured + offset (read only) */
    MeReal velocity;            /**< rate of the coordinate (read only) */
    MeReal offset;              /**< set through MdtLimitSetPosition */
    MeReal overshoot;           /**< how far past a stop the coordinate is: > 0 above the upper, < 0 below the lower */
    MeReal stiffness_threshold; /**< stops at least this stiff are hard; default MEINFINITY */
    MeReal desired_velocity;    /**< motor target rate */
    MeReal fmax;                /**< motor force bound, ≥ 0 */
    MeReal position_lock;       /**< lock position (reported coordinate) */
    MeReal fmax_lock;           /**< lock force bound, ≥ 0 */
    MeBool limited;             /**< stops active */
    MeBool calculate_position;  /**< track the coordinate (always done here; kept for Karma) */
    MeBool powered;             /**< motor active */
    MeBool locked;              /**< lock active */
    MdtLimitPrivate private_;   /**< the library's bookkeeping (MdtLimitPrivate): do not touch */
} MdtBclLimit;

typedef MdtBclLimit MdtLimit;
typedef MdtBclSingleLimit MdtSingleLimit;
typedef MdtLimit *MdtLimitID;
typedef MdtSingleLimit *MdtSingleLimitID;

/* ---- single limits ------------------------------------------------------------------------- */
/** Stop 0, stiffness MEINFINITY, damping 0, restitution 1. */
ME_API void MdtSingleLimitReset(MdtSingleLimitID sl);
/** Position of the stop (m or rad); NULL sl refused (returns 0). */
ME_API MeReal MdtSingleLimitGetStop(const MdtSingleLimit *sl);
/** Stiffness of the stop (N/m or N·m/rad; MEINFINITY: hard); NULL sl refused (returns 0). */
ME_API MeReal MdtSingleLimitGetStiffness(const MdtSingleLimit *sl);
/** Damping of the stop (N·s/m or N·m·s/rad); NULL sl refused (returns 0). */
ME_API MeReal MdtSingleLimitGetDamping(const MdtSingleLimit *sl);
/** Restitution of a hard stop, 0 ... 1; NULL sl refused (returns 0). */
ME_API MeReal MdtSingleLimitGetRestitution(const MdtSingleLimit *sl);
/** Position of the stop (m or rad; finite). */
ME_API void MdtSingleLimitSetStop(MdtSingleLimitID sl, MeReal stop);
/** Stiffness ≥ 0 (MEINFINITY allowed: hard). */
ME_API void MdtSingleLimitSetStiffness(MdtSingleLimitID sl, MeReal stiffness);
/** Damping ≥ 0, finite. */
ME_API void MdtSingleLimitSetDamping(MdtSingleLimitID sl, MeReal damping);
/** Restitution in 0 ... 1. */
ME_API void MdtSingleLimitSetRestitution(MdtSingleLimitID sl, MeReal restitution);

/* ---- limits -------------------------------------------------------------------------------- */
/** All defaults (see above) and a cleared state. */
ME_API void MdtLimitReset(MdtLimitID l);
/** Clears the measured state only (position tracking, bounce, motor stall), keeping the settings. */
ME_API void MdtLimitResetState(MdtLimitID l);
/** Whether the stops are on; MEFALSE for NULL or an uninitialised limit (reported). */
ME_API MeBool MdtLimitIsActive(const MdtLimit *l);
/** Whether the coordinate is tracked (always, when the stops are on); MEFALSE for a bad limit. */
ME_API MeBool MdtLimitPositionIsCalculated(const MdtLimit *l);
/** Pointer to the lower stop inside the limit (lives as long as the limit); NULL for a bad limit. */
ME_API MdtSingleLimitID MdtLimitGetLowerLimit(MdtLimitID l);
/** Pointer to the upper stop inside the limit (lives as long as the limit); NULL for a bad limit. */
ME_API MdtSingleLimitID MdtLimitGetUpperLimit(MdtLimitID l);
/** Coordinate (measured + offset) and its rate, as of the end of the last step. */
ME_API MeReal MdtLimitGetPosition(const MdtLimit *l);
/** Rate of the coordinate at the end of the last step (m/s or rad/s); 0 for a bad limit. */
ME_API MeReal MdtLimitGetVelocity(const MdtLimit *l);
/** Distance past the stop the coordinate is beyond (> 0 above the upper, < 0 below the lower, else 0). */
ME_API MeReal MdtLimitGetOvershoot(const MdtLimit *l);
/** Stiffness from which a stop is hard; 0 for NULL or an uninitialised limit (reported). */
ME_API MeReal MdtLimitGetStiffnessThreshold(const MdtLimit *l);
/** Whether the motor is on; MEFALSE for NULL or an uninitialised limit (reported). */
ME_API MeBool MdtLimitIsMotorized(const MdtLimit *l);
/** Whether the lock is on; MEFALSE for NULL or an uninitialised limit (reported). */
ME_API MeBool MdtLimitIsLocked(const MdtLimit *l);
/** Motor target rate (m/s or rad/s); 0 for a bad limit. */
ME_API MeReal MdtLimitGetMotorDesiredVelocity(const MdtLimit *l);
/** Motor force bound (N or N·m); 0 for a bad limit. */
ME_API MeReal MdtLimitGetMotorMaxForce(const MdtLimit *l);

/** Copy a single limit into the lower / upper stop (checked like the setters). */
ME_API void MdtLimitSetLowerLimit(MdtLimitID l, const MdtSingleLimit *sl);
/** Copy sl into the upper stop; an invalid stop or one below the lower stop refused, limit unchanged. */
ME_API void MdtLimitSetUpperLimit(MdtLimitID l, const MdtSingleLimit *sl);
/** Declare the current coordinate to be `position` (sets the offset; nothing moves). */
ME_API void MdtLimitSetPosition(MdtLimitID l, MeReal position);
/** Turn the stops on or off. */
ME_API void MdtLimitActivateLimits(MdtLimitID l, MeBool on);
/** Track the coordinate without limiting it (kept for Karma: the coordinate is always tracked). */
ME_API void MdtLimitCalculatePosition(MdtLimitID l, MeBool on);
/** Stops with stiffness ≥ threshold are hard (> 0; default MEINFINITY). */
ME_API void MdtLimitSetStiffnessThreshold(MdtLimitID l, MeReal threshold);
/** Turn the motor on or off (on turns the lock off). */
ME_API void MdtLimitActivateMotor(MdtLimitID l, MeBool on);
/** Motor target rate and force bound (≥ 0). A positive bound turns the motor on, 0 turns it off. */
ME_API void MdtLimitSetLimitedForceMotor(MdtLimitID l, MeReal desiredVelocity, MeReal maxForce);
/** Turn the lock on or off (on turns the motor off). */
ME_API void MdtLimitActivateLock(MdtLimitID l, MeBool on);
/** Lock position (reported coordinate) and force bound (≥ 0; MEINFINITY = rigid); does not activate. */
ME_API void MdtLimitSetLock(MdtLimitID l, MeReal position, MeReal maxForce);
/** Proportional position control through the motor: desired rate = maxSpeed × (desiredPos − position)
 *  / gap, clamped to ±maxSpeed (full speed farther than `gap`), with force bound maxForce; turns the
 *  motor on. gap > 0, maxSpeed ≥ 0, maxForce ≥ 0. Call it every step. */
ME_API void MdtLimitController(MdtLimitID l, MeReal desiredPos, MeReal gap, MeReal maxSpeed, MeReal maxForce);

ME_EXTERN_C_END

#endif /* MDT_LIMIT_H */
