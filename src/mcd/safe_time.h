/* safe_time.h -- conservative time of impact between two moving geometries (internal).
 *
 * A motion is a start transform (the frame a model follows: a body's) moved at a constant linear
 * velocity (of its origin) and angular velocity (about its origin), exactly as
 * MeMatrix4TMUpdateFromVelocities; the geometry sits at `relative` in that frame. McdSafeTimeMotions
 * finds the largest t in [0, maxTime] before which the geometries stay more than `gap` apart
 * (conservative advancement on GJK distances, closed forms for sphere-sphere and sphere-plane). */
#ifndef MCD_SAFE_TIME_H
#define MCD_SAFE_TIME_H

#include "framework.h"

typedef struct McdMotion {
    const McdGeometryData *g;
    MeReal (*start)[4];    /* followed frame at t = 0 */
    MeReal (*relative)[4]; /* geometry in that frame, or NULL (identity) */
    MeVector3 v, w;        /* m/s of the frame's origin, rad/s about it */
    McdModelPair *pair;    /* handed to a triangle list's generator (may be NULL) */
} McdMotion;

/** How McdSafeTimeMotions ended. */
typedef enum McdSafeTimeOutcome {
    MCD_SAFE_NO_METHOD = 0, /* no method for the pair of types: *time = maxTime */
    MCD_SAFE_CLEAR,         /* they stay apart over [0, maxTime]: *time = maxTime */
    MCD_SAFE_HIT            /* they come within gap (+ tolerance) at *time (0: already) */
} McdSafeTimeOutcome;

/** Where a hit came from: the unit direction from a towards b at the time, the point of a nearest b
 *  then (world), and whether a was within gap of b already at the start (a sweep's slop applied). */
typedef struct McdSafeTimeHit {
    MeVector3 normal, point;
    MeBool touching;
} McdSafeTimeHit;

/** What a safe-time search looks for: the window [0, maxTime] (s), how near counts as a hit (gap, m,
 *  >= 0) and, for a sweep, how much further shapes already within gap at the start must approach to
 *  hit (slop >= 0, m); slop < 0: shapes within gap at the start hit at 0 (McdSafeTime). */
typedef struct McdSafeTimeLimits {
    MeReal maxTime, gap, slop;
} McdSafeTimeLimits;

/** Whether a geometry type can be moved by the sweep: convex primitives and convex meshes. */
MeBool McdSafeTimeIsConvex(int type);
/** Conservative time at which a and b come within limits->gap of each other; the stopping tolerance
 *  is MCD_SAFE_TIME_GAP * lengthScale. With slop >= 0 (a sweep), shapes already within gap at the
 *  start hit only when their signed distance (depth when overlapping) falls by slop more; slop < 0:
 *  they hit at 0 (McdSafeTime). `hit` (may be NULL) receives the hit's direction. */
McdSafeTimeOutcome McdSafeTimeMotions(const McdFrameworkData *fw, const McdMotion *a, const McdMotion *b,
                                      const McdSafeTimeLimits *limits, MeReal *time, McdSafeTimeHit *hit);
/** Radius of a ball round the geometry's origin inside it (0 when unknown). */
MeReal McdSafeTimeInnerRadius(const McdGeometryData *g);
/** Radius about the followed frame's origin that holds the geometry placed at `relative` (NULL:
 *  identity). */
MeReal McdSafeTimeReach(const McdGeometryData *g, MeReal (*relative)[4]);

#endif /* MCD_SAFE_TIME_H */
