/* MdtSkeletal.h -- skeletal joint, for limbs: a ball and socket (3 rows) with a swing limit and a
 * twist limit, each with its own stiffness and damping (the limits of a shoulder or a hip).
 * The bone is body 0's primary axis a0; the cone is set in body 1's frame: its axis is body 1's
 * primary axis, the primary half-angle limits the swing towards body 1's orthogonal axis and the
 * secondary half-angle towards primary × orthogonal (an elliptical cone). Twist is body 0's rotation
 * about the bone relative to body 1, measured by the swing-twist decomposition of the relative
 * rotation; MdtSkeletalZeroTwist makes the present twist the zero.
 * Cone options: Free (no swing limit), Slot (the bone stays in the plane of body 1's primary and
 * orthogonal axes, within ± the primary angle), Cone (elliptical cone), Fixed (swing locked).
 * Twist options: Free, Limited (|twist| ≤ the twist angle), Fixed (twist locked).
 * Limits write rows only at the limit. "Combined limits" writes at most one limit row per step, the
 * most violated of swing and twist (relative to its angle), to save a row.
 * Rows: at most 6 (3 + 2 for a Slot or Fixed cone + 1 for twist; Karma lists 5, docs/decisions.md).
 * Defaults: position (0,0,0), axes (1,0,0)/(0,1,0) in both bodies; cone option Cone, twist option
 * Limited; primary, secondary and twist angles π/4 (decision D6); stiffness MEINFINITY (hard) and
 * damping 0 for cone and twist; combined limits off. Karma marks this joint experimental. */
#ifndef MDT_SKELETAL_H
#define MDT_SKELETAL_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled skeletal joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtSkeletalID MdtSkeletalCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtSkeletalReset(MdtSkeletalID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtSkeletalQuaConstraint(MdtSkeletalID j);
/** The skeletal joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtSkeletalID MdtConstraintDCastSkeletal(MdtConstraintID c);

typedef enum MdtSkeletalConeOption {
    MdtSkeletalConeOptionFree = 0,
    MdtSkeletalConeOptionSlot,
    MdtSkeletalConeOptionCone,
    MdtSkeletalConeOptionFixed
} MdtSkeletalConeOption;

typedef enum MdtSkeletalTwistOption {
    MdtSkeletalTwistOptionFree = 0,
    MdtSkeletalTwistOptionLimited,
    MdtSkeletalTwistOptionFixed
} MdtSkeletalTwistOption;

/** Swing half-angle towards body 1's orthogonal axis, rad, in [0, π]. */
ME_API void MdtSkeletalSetConePrimaryLimitAngle(MdtSkeletalID j, MeReal angle);
/** Swing half-angle towards body 1's orthogonal axis (rad); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetConePrimaryLimitAngle(MdtSkeletalID j);
/** Swing half-angle towards primary × orthogonal, rad, in [0, π]. */
ME_API void MdtSkeletalSetConeSecondaryLimitAngle(MdtSkeletalID j, MeReal angle);
/** Swing half-angle towards primary × orthogonal (rad); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetConeSecondaryLimitAngle(MdtSkeletalID j);
/** Largest |twist|, rad, in [0, π]. */
ME_API void MdtSkeletalSetTwistLimitAngle(MdtSkeletalID j, MeReal angle);
/** Largest |twist| (rad); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetTwistLimitAngle(MdtSkeletalID j);
/** Stiffness (N·m/rad, MEINFINITY = hard) and damping (N·m·s/rad) of the swing limit past the cone. */
ME_API void MdtSkeletalSetConeStiffness(MdtSkeletalID j, MeReal stiffness);
/** Stiffness of the swing limit (N·m/rad, MEINFINITY: hard); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetConeStiffness(MdtSkeletalID j);
/** Damping of the swing limit (N·m·s/rad, ≥ 0); NaN or negative refused (ME_ERR_NEGATIVE_VALUE). */
ME_API void MdtSkeletalSetConeDamping(MdtSkeletalID j, MeReal damping);
/** Damping of the swing limit (N·m·s/rad); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetConeDamping(MdtSkeletalID j);
/** Stiffness and damping of the twist limit. */
ME_API void MdtSkeletalSetTwistStiffness(MdtSkeletalID j, MeReal stiffness);
/** Stiffness of the twist limit (N·m/rad, MEINFINITY: hard); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetTwistStiffness(MdtSkeletalID j);
/** Damping of the twist limit (N·m·s/rad, ≥ 0); NaN or negative refused (ME_ERR_NEGATIVE_VALUE). */
ME_API void MdtSkeletalSetTwistDamping(MdtSkeletalID j, MeReal damping);
/** Damping of the twist limit (N·m·s/rad); 0 for an invalid ID. */
ME_API MeReal MdtSkeletalGetTwistDamping(MdtSkeletalID j);
/** Shape of the swing limit; a value outside MdtSkeletalConeOption refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void MdtSkeletalSetConeLimitOption(MdtSkeletalID j, MdtSkeletalConeOption option);
/** Shape of the swing limit; MdtSkeletalConeOptionFree for an invalid ID. */
ME_API MdtSkeletalConeOption MdtSkeletalGetConeLimitOption(MdtSkeletalID j);
/** Twist limit on or off; a value outside MdtSkeletalTwistOption refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void MdtSkeletalSetTwistLimitOption(MdtSkeletalID j, MdtSkeletalTwistOption option);
/** The twist limit option; MdtSkeletalTwistOptionFree for an invalid ID. */
ME_API MdtSkeletalTwistOption MdtSkeletalGetTwistLimitOption(MdtSkeletalID j);
/** One limit row at most (the most violated), instead of one for swing and one for twist. */
ME_API void MdtSkeletalEnableCombinedLimits(MdtSkeletalID j, MeBool enable);
/** Whether swing and twist share one limit row; MEFALSE for an invalid ID. */
ME_API MeBool MdtSkeletalCombinedLimitsAreEnabled(MdtSkeletalID j);
/** Make the present twist the zero of the twist angle (turns body 0's orthogonal axis about the bone). */
ME_API void MdtSkeletalZeroTwist(MdtSkeletalID j);
/** Present twist, rad (−π ... π). */
ME_API MeReal MdtSkeletalGetTwistAngle(MdtSkeletalID j);
/** Present swing: angle between the bone and the cone's axis, rad (0 ... π). */
ME_API MeReal MdtSkeletalGetSwingAngle(MdtSkeletalID j);

/* The common constraint API under this type's names. */
#define MdtSkeletalDestroy(j) MdtConstraintDestroy(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalEnable(j) MdtConstraintEnable(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalDisable(j) MdtConstraintDisable(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalIsEnabled(j) MdtConstraintIsEnabled(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtSkeletalQuaConstraint(j), (b1), (b2))
#define MdtSkeletalGetBody(j, i) MdtConstraintGetBody(MdtSkeletalQuaConstraint(j), (i))
#define MdtSkeletalSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtSkeletalQuaConstraint(j), (x), (y), (z))
#define MdtSkeletalGetPosition(j, p) MdtConstraintGetPosition(MdtSkeletalQuaConstraint(j), (p))
#define MdtSkeletalSetAxis(j, x, y, z) MdtConstraintSetAxis(MdtSkeletalQuaConstraint(j), (x), (y), (z))
#define MdtSkeletalSetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtSkeletalQuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtSkeletalGetAxes(j, p, o) MdtConstraintGetAxes(MdtSkeletalQuaConstraint(j), (p), (o))
#define MdtSkeletalGetForce(j, i, f) MdtConstraintGetForce(MdtSkeletalQuaConstraint(j), (i), (f))
#define MdtSkeletalGetTorque(j, i, t) MdtConstraintGetTorque(MdtSkeletalQuaConstraint(j), (i), (t))
#define MdtSkeletalSetUserData(j, d) MdtConstraintSetUserData(MdtSkeletalQuaConstraint(j), (d))
#define MdtSkeletalGetUserData(j) MdtConstraintGetUserData(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalSetSortKey(j, k) MdtConstraintSetSortKey(MdtSkeletalQuaConstraint(j), (k))
#define MdtSkeletalGetSortKey(j) MdtConstraintGetSortKey(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalGetWorld(j) MdtConstraintGetWorld(MdtSkeletalQuaConstraint(j))
#define MdtSkeletalGetRowCount(j) MdtConstraintGetRowCount(MdtSkeletalQuaConstraint(j))

/* Karma 1.2's names for the limit options and the per-body axes. */
#define MdtSkeletalSetConeOption(j, option) MdtSkeletalSetConeLimitOption((j), (option))
#define MdtSkeletalGetConeOption(j) MdtSkeletalGetConeLimitOption(j)
#define MdtSkeletalSetTwistOption(j, option) MdtSkeletalSetTwistLimitOption((j), (option))
#define MdtSkeletalGetTwistOption(j) MdtSkeletalGetTwistLimitOption(j)
#define MdtSkeletalBodyGetAxis(j, i, a) MdtConstraintBodyGetAxis(MdtSkeletalQuaConstraint(j), (i), (a))
#define MdtSkeletalBodyGetAxes(j, i, p, o) MdtConstraintBodyGetAxes(MdtSkeletalQuaConstraint(j), (i), (p), (o))
#define MdtSkeletalBodySetAxes(j, i, px, py, pz, ox, oy, oz)                                            \
    MdtConstraintBodySetAxes(MdtSkeletalQuaConstraint(j), (i), (px), (py), (pz), (ox), (oy), (oz))

ME_EXTERN_C_END

#endif /* MDT_SKELETAL_H */
