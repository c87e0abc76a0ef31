/* MdtFixedPath.h -- fixed-path joint: a ball and socket whose attachment points move along paths
 * the application prescribes (3 rows), e.g. a pendulum hung from an animated pivot. Each step, set
 * the attachment's position (MdtFixedPathSetPosition) **and** its velocity along the path
 * (MdtFixedPathSetVelocity): the velocity makes the joint follow the path without lagging a step
 * behind it. Defaults: positions and velocities (0,0,0). */
#ifndef MDT_FIXEDPATH_H
#define MDT_FIXEDPATH_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled fixed-path joint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtFixedPathID MdtFixedPathCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtFixedPathReset(MdtFixedPathID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtFixedPathQuaConstraint(MdtFixedPathID j);
/** The fixed-path joint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtFixedPathID MdtConstraintDCastFixedPath(MdtConstraintID c);

/** Attachment point on body `bodyindex` (0 or 1; 1 is the world when body 1 is NULL), world
 *  coordinates at the time of the call; stored in that body's frame. */
ME_API void MdtFixedPathSetPosition(MdtFixedPathID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z);
/** Attachment point on body `bodyindex`, world frame. */
ME_API void MdtFixedPathGetPosition(MdtFixedPathID j, unsigned int bodyindex, MeVector3 p);
/** Velocity (m/s) of the attachment point on body `bodyindex` along its path, relative to that body,
 *  world coordinates at the time of the call (stored in that body's frame, so it turns with it). */
ME_API void MdtFixedPathSetVelocity(MdtFixedPathID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z);
/** That velocity, world frame. */
ME_API void MdtFixedPathGetVelocity(MdtFixedPathID j, unsigned int bodyindex, MeVector3 v);

/* The common constraint API under this type's names. */
#define MdtFixedPathDestroy(j) MdtConstraintDestroy(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathEnable(j) MdtConstraintEnable(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathDisable(j) MdtConstraintDisable(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathIsEnabled(j) MdtConstraintIsEnabled(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtFixedPathQuaConstraint(j), (b1), (b2))
#define MdtFixedPathGetBody(j, i) MdtConstraintGetBody(MdtFixedPathQuaConstraint(j), (i))
#define MdtFixedPathGetForce(j, i, f) MdtConstraintGetForce(MdtFixedPathQuaConstraint(j), (i), (f))
#define MdtFixedPathGetTorque(j, i, t) MdtConstraintGetTorque(MdtFixedPathQuaConstraint(j), (i), (t))
#define MdtFixedPathSetUserData(j, d) MdtConstraintSetUserData(MdtFixedPathQuaConstraint(j), (d))
#define MdtFixedPathGetUserData(j) MdtConstraintGetUserData(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathSetSortKey(j, k) MdtConstraintSetSortKey(MdtFixedPathQuaConstraint(j), (k))
#define MdtFixedPathGetSortKey(j) MdtConstraintGetSortKey(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathGetWorld(j) MdtConstraintGetWorld(MdtFixedPathQuaConstraint(j))
#define MdtFixedPathGetRowCount(j) MdtConstraintGetRowCount(MdtFixedPathQuaConstraint(j))

ME_EXTERN_C_END

#endif /* MDT_FIXEDPATH_H */
