/* geometry.h -- the built-in geometry types' protocols and shared helpers (internal). */
#ifndef MCD_GEOMETRY_INTERNAL_H
#define MCD_GEOMETRY_INTERNAL_H

#include <karma/McdGeometry.h>

#include "../framework.h"

/* The protocol of each built-in type; McdInit installs them at their type numbers. */
extern const McdGeometryTypeDesc McdNullTypeDesc;
extern const McdGeometryTypeDesc McdSphereTypeDesc;
extern const McdGeometryTypeDesc McdBoxTypeDesc;
extern const McdGeometryTypeDesc McdPlaneTypeDesc;
extern const McdGeometryTypeDesc McdCylinderTypeDesc;
extern const McdGeometryTypeDesc McdSphylTypeDesc;
extern const McdGeometryTypeDesc McdConeTypeDesc;
extern const McdGeometryTypeDesc McdConvexMeshTypeDesc;

/** Index of the convex mesh's hull vertex farthest along the local direction dir (ties: the first). */
int McdConvexMeshSupportIndex(const McdConvexMeshData *c, const MeVector3 dir);

/** A new geometry of `type` from the framework's pool (reported in `function`'s name when full). */
McdGeometryData *McdGeometryNew(McdFrameworkData *fw, int type, const char *function);
/** Resolve a geometry ID that must be of `type` (reported otherwise). */
McdGeometryData *McdGeometryOfType(McdGeometryID id, int type, const char *function);
/** The x and y extent {min x, max x, min y, max y} of the geometry placed at tm (NULL: identity). */
void McdGeometryXYAABB(const McdGeometryData *g, MeMatrix4 tm, MeReal bounds[4], const char *function);
/** The local support point, arguments checked in `function`'s name. */
void McdGeometryMaximumPointLocalChecked(const McdGeometryData *g, const MeReal *dir, MeReal *point,
                                         const char *function);
/** A dimension must be finite and > 0 (or >= 0 when zeroAllowed): ME_ERR_MCD_DEGENERATE_GEOMETRY; and
 *  (unless 0) within MCD_SIZE_MIN..MCD_SIZE_MAX times fw's lengthScale: ME_ERR_MCD_SIZE_RANGE. Reports in
 *  `function`'s name. */
MeBool McdCheckDimension(const McdFrameworkData *fw, MeReal value, const char *name, MeBool zeroAllowed,
                         const char *function);

/** AABB of a local box [lo, hi] placed at tm (exact for boxes). */
void McdAABBOfLocalBox(MeMatrix4 tm, const MeVector3 lo, const MeVector3 hi, MeVector3 minCorner,
                       MeVector3 maxCorner);
/** A shape about local z: the convex hull of the discs of radius rLo at z = zLo and rHi at z = zHi
 *  (in planes normal to z), swept by a sphere of sphereRadius: a cylinder, a cone, or (discs of
 *  radius 0 and a sphere) a sphyl. */
typedef struct McdAxialShape {
    MeReal zLo, rLo, zHi, rHi, sphereRadius;
} McdAxialShape;

/** AABB of an axial shape placed at tm. */
void McdAABBOfAxialShape(MeMatrix4 tm, const McdAxialShape *shape, MeVector3 minCorner, MeVector3 maxCorner);

/* ---- segment tests: the set of t (over the whole line p0 + t d) inside a shape is an interval,
 *      with the outward normal at its start; a convex shape is the intersection of simple parts. */
typedef struct McdLineInterval {
    MeReal tIn, tOut;  /* [tIn, tOut]; tIn > tOut: empty */
    MeVector3 nIn;     /* outward unit normal where the line enters (local) */
} McdLineInterval;

/** The whole line (before any part is intersected). */
void McdLineIntervalAll(McdLineInterval *iv);
/** Intersect with the slab lo <= x_axis <= hi (lo may be -MEINFINITY for a half-space). */
void McdLineIntervalSlab(McdLineInterval *iv, const MeVector3 p0, const MeVector3 d, int axis, MeReal lo, MeReal hi);
/** Intersect with the ball |x - centre| <= r. */
void McdLineIntervalBall(McdLineInterval *iv, const MeVector3 p0, const MeVector3 d, const MeVector3 centre, MeReal r);
/** Intersect with the solid x^2 + y^2 <= (alpha + beta z)^2 restricted to alpha + beta z >= 0 (a cone,
 *  or with beta = 0 an infinite cylinder of radius alpha along z). Pass the slab that bounds z first. */
void McdLineIntervalCone(McdLineInterval *iv, const MeVector3 p0, const MeVector3 d, MeReal alpha, MeReal beta);
/** The first entry of the segment (t in [0,1]) from a line interval: METRUE on a hit; *t = 0 and
 *  normal = -d/|d| when p0 is inside. */
MeBool McdLineIntervalToSegmentHit(const McdLineInterval *iv, const MeVector3 d, MeReal *t, MeVector3 normal);

/** Support point of the disc of radius r at height z (normal z) in direction dir. */
void McdDiscSupport(const MeVector3 dir, MeReal r, MeReal z, MeVector3 point);

/** Mass properties helpers: a diagonal inertia into a full tensor. */
void McdDiagonalInertia(MeMatrix3 inertia, MeReal ixx, MeReal iyy, MeReal izz);

#endif /* MCD_GEOMETRY_INTERNAL_H */
