/* MdtSpring6.h -- six-axis spring: a spring-damper on each of the three linear and three angular
 * axes of the constraint frame (the frame of body 1: primary, orthogonal, primary × orthogonal).
 * Linear axis k pulls body 0's attachment point towards body 1's along axis k (N/m, N·s/m); angular
 * axis k turns body 0's frame back towards body 1's about axis k (N·m/rad, N·m·s/rad). An axis with
 * stiffness MEINFINITY is rigid; with stiffness and damping both 0 it is free (no row). 6 rows at most.
 * Defaults: position (0,0,0), axes (1,0,0) and (0,1,0) in both bodies; every axis stiffness MEINFINITY,
 * damping 0 (rigid until configured, as Angular3: docs/decisions.md). Use
 * MdtConstraintSetWorldLinearVelocity/AngularVelocity for a spring anchored to a moving world frame. */
#ifndef MDT_SPRING6_H
#define MDT_SPRING6_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled six-axis spring, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtSpring6ID MdtSpring6Create(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtSpring6Reset(MdtSpring6ID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtSpring6QuaConstraint(MdtSpring6ID j);
/** The six-axis spring behind a constraint ID, or NULL if it is of another type. */
ME_API MdtSpring6ID MdtConstraintDCastSpring6(MdtConstraintID c);

/** Stiffness / damping of linear axis `axis` (0, 1, 2 = x, y, z of the constraint frame). */
ME_API void MdtSpring6SetLinearStiffness(MdtSpring6ID j, unsigned int axis, MeReal stiffness);
/** Damping of linear axis `axis` (N·s/m, ≥ 0); axis > 2 (ME_ERR_ARGUMENT_RANGE), NaN or negative refused. */
ME_API void MdtSpring6SetLinearDamping(MdtSpring6ID j, unsigned int axis, MeReal damping);
/** Stiffness of linear axis `axis` (N/m); 0 for axis > 2 (reported) or an invalid ID. */
ME_API MeReal MdtSpring6GetLinearStiffness(MdtSpring6ID j, unsigned int axis);
/** Damping of linear axis `axis` (N·s/m); 0 for axis > 2 (reported) or an invalid ID. */
ME_API MeReal MdtSpring6GetLinearDamping(MdtSpring6ID j, unsigned int axis);
/** Stiffness / damping of angular axis `axis`. */
ME_API void MdtSpring6SetAngularStiffness(MdtSpring6ID j, unsigned int axis, MeReal stiffness);
/** Damping of angular axis `axis` (N·m·s/rad, ≥ 0); axis > 2, NaN or negative refused. */
ME_API void MdtSpring6SetAngularDamping(MdtSpring6ID j, unsigned int axis, MeReal damping);
/** Stiffness of angular axis `axis` (N·m/rad); 0 for axis > 2 (reported) or an invalid ID. */
ME_API MeReal MdtSpring6GetAngularStiffness(MdtSpring6ID j, unsigned int axis);
/** Damping of angular axis `axis` (N·m·s/rad); 0 for axis > 2 (reported) or an invalid ID. */
ME_API MeReal MdtSpring6GetAngularDamping(MdtSpring6ID j, unsigned int axis);

/* The common constraint API under this type's names. */
#define MdtSpring6Destroy(j) MdtConstraintDestroy(MdtSpring6QuaConstraint(j))
#define MdtSpring6Enable(j) MdtConstraintEnable(MdtSpring6QuaConstraint(j))
#define MdtSpring6Disable(j) MdtConstraintDisable(MdtSpring6QuaConstraint(j))
#define MdtSpring6IsEnabled(j) MdtConstraintIsEnabled(MdtSpring6QuaConstraint(j))
#define MdtSpring6SetBodies(j, b1, b2) MdtConstraintSetBodies(MdtSpring6QuaConstraint(j), (b1), (b2))
#define MdtSpring6GetBody(j, i) MdtConstraintGetBody(MdtSpring6QuaConstraint(j), (i))
#define MdtSpring6SetPosition(j, x, y, z) MdtConstraintSetPosition(MdtSpring6QuaConstraint(j), (x), (y), (z))
#define MdtSpring6GetPosition(j, p) MdtConstraintGetPosition(MdtSpring6QuaConstraint(j), (p))
#define MdtSpring6SetAxis(j, x, y, z) MdtConstraintSetAxis(MdtSpring6QuaConstraint(j), (x), (y), (z))
#define MdtSpring6SetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtSpring6QuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtSpring6GetAxes(j, p, o) MdtConstraintGetAxes(MdtSpring6QuaConstraint(j), (p), (o))
#define MdtSpring6GetForce(j, i, f) MdtConstraintGetForce(MdtSpring6QuaConstraint(j), (i), (f))
#define MdtSpring6GetTorque(j, i, t) MdtConstraintGetTorque(MdtSpring6QuaConstraint(j), (i), (t))
#define MdtSpring6SetUserData(j, d) MdtConstraintSetUserData(MdtSpring6QuaConstraint(j), (d))
#define MdtSpring6GetUserData(j) MdtConstraintGetUserData(MdtSpring6QuaConstraint(j))
#define MdtSpring6SetSortKey(j, k) MdtConstraintSetSortKey(MdtSpring6QuaConstraint(j), (k))
#define MdtSpring6GetSortKey(j) MdtConstraintGetSortKey(MdtSpring6QuaConstraint(j))
#define MdtSpring6GetWorld(j) MdtConstraintGetWorld(MdtSpring6QuaConstraint(j))
#define MdtSpring6GetRowCount(j) MdtConstraintGetRowCount(MdtSpring6QuaConstraint(j))

/* Karma 1.2's names: velocity of the world at the attachment (body 1 NULL), world frame. */
#define MdtSpring6SetWorldLinearVelocity(j, vx, vy, vz)                                                 \
    MdtConstraintSetWorldLinearVelocity(MdtSpring6QuaConstraint(j), (vx), (vy), (vz))
#define MdtSpring6SetWorldAngularVelocity(j, vx, vy, vz)                                                \
    MdtConstraintSetWorldAngularVelocity(MdtSpring6QuaConstraint(j), (vx), (vy), (vz))
#define MdtSpring6GetWorldLinearVelocity(j, v) MdtConstraintGetWorldLinearVelocity(MdtSpring6QuaConstraint(j), (v))
#define MdtSpring6GetWorldAngularVelocity(j, v) MdtConstraintGetWorldAngularVelocity(MdtSpring6QuaConstraint(j), (v))

ME_EXTERN_C_END

#endif /* MDT_SPRING6_H */
