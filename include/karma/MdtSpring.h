/* MdtSpring.h -- spring between an attachment point on body 0 and one on body 1 (or the world):
 * 1 row along the line joining them.
 *
 * The spring is a limit (MdtSpringGetLimit) on the coordinate "length − initial separation", where
 * the initial separation is the distance between the attachment points when they were last set
 * (MdtSpringSetPosition), or when the spring was first stepped. Its lower and upper stops are each
 * hard (a rod: stiffness MEINFINITY), soft (a spring) or absent (stiffness and damping 0): two soft
 * stops at one place make an ordinary spring, a soft upper stop alone a string (slack when
 * compressed). Defaults: both stops soft at 0 (the natural length is the initial separation),
 * stiffness 100 N/m, damping 1 N·s/m, limits active; positions (0,0,0) in each body. */
#ifndef MDT_SPRING_H
#define MDT_SPRING_H

#include "MdtConstraint.h"
#include "MdtLimit.h"

ME_EXTERN_C_BEGIN

/** A new disabled spring, or NULL when the constraint pool is full. */
ME_API MdtSpringID MdtSpringCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtSpringReset(MdtSpringID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtSpringQuaConstraint(MdtSpringID j);
/** The spring behind a constraint ID, or NULL if it is not a spring. */
ME_API MdtSpringID MdtConstraintDCastSpring(MdtConstraintID c);
/** Attachment point on body `bodyindex` (0 or 1), world coordinates (set the bodies first); the
 *  initial separation is measured again. */
ME_API void MdtSpringSetPosition(MdtSpringID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z);
/** Rest length, added to the initial separation (m, finite): both stops are set to it. */
ME_API void MdtSpringSetNaturalLength(MdtSpringID j, MeReal length);
/** Stiffness of both stops (N/m, ≥ 0; MEINFINITY: a rod). */
ME_API void MdtSpringSetStiffness(MdtSpringID j, MeReal stiffness);
/** Damping of both stops (N·s/m, ≥ 0). */
ME_API void MdtSpringSetDamping(MdtSpringID j, MeReal damping);
/** Current distance between the attachment points (m). */
ME_API MeReal MdtSpringGetLength(MdtSpringID j);
/** The natural length set (the lower stop), stiffness and damping (of the lower stop). */
ME_API MeReal MdtSpringGetNaturalLength(MdtSpringID j);
/** Spring stiffness (N/m, of the lower stop); 0 for an invalid ID. */
ME_API MeReal MdtSpringGetStiffness(MdtSpringID j);
/** Spring damping (N·s/m, of the lower stop); 0 for an invalid ID. */
ME_API MeReal MdtSpringGetDamping(MdtSpringID j);
/** The spring's limit (lives as long as the joint). */
ME_API MdtLimitID MdtSpringGetLimit(MdtSpringID j);
/** Copy a limit's settings into the spring. */
ME_API void MdtSpringSetLimit(MdtSpringID j, const MdtLimit *limit);

#define MdtSpringDestroy(j) MdtConstraintDestroy(MdtSpringQuaConstraint(j))
#define MdtSpringEnable(j) MdtConstraintEnable(MdtSpringQuaConstraint(j))
#define MdtSpringDisable(j) MdtConstraintDisable(MdtSpringQuaConstraint(j))
#define MdtSpringIsEnabled(j) MdtConstraintIsEnabled(MdtSpringQuaConstraint(j))
#define MdtSpringSetSortKey(j, k) MdtConstraintSetSortKey(MdtSpringQuaConstraint(j), (k))
#define MdtSpringGetSortKey(j) MdtConstraintGetSortKey(MdtSpringQuaConstraint(j))
#define MdtSpringSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtSpringQuaConstraint(j), (b1), (b2))
#define MdtSpringGetBody(j, i) MdtConstraintGetBody(MdtSpringQuaConstraint(j), (i))
#define MdtSpringGetPosition(j, i, p) MdtConstraintBodyGetPosition(MdtSpringQuaConstraint(j), (i), (p))
#define MdtSpringGetForce(j, i, f) MdtConstraintGetForce(MdtSpringQuaConstraint(j), (i), (f))
#define MdtSpringGetTorque(j, i, t) MdtConstraintGetTorque(MdtSpringQuaConstraint(j), (i), (t))
#define MdtSpringSetUserData(j, d) MdtConstraintSetUserData(MdtSpringQuaConstraint(j), (d))
#define MdtSpringGetUserData(j) MdtConstraintGetUserData(MdtSpringQuaConstraint(j))
#define MdtSpringGetWorld(j) MdtConstraintGetWorld(MdtSpringQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_SPRING_H */
