/* McduDebugDraw.h -- Karma 1.2's wireframe drawing of geometries, models and spaces, through the
 * line hook MeDebugDrawAPI.line (MeDebugDraw.h), which draws nothing until a renderer fills it.
 *
 * Shapes are drawn where `tm` (geometry to world) places them: a box as its 12 edges; a sphere as
 * three great circles (in the local xy, yz and zx planes); a cylinder as its two end circles and 4
 * side lines; a sphyl as a cylinder whose ends are half circles in the local xz and yz planes; a cone
 * as its circles (the upper one when truncated) and 4 side lines; a plane as a square of side
 * 2 x the framework's length scale with its normal; an AABB as 12 edges. Circles have
 * MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS lines. Colours are 0..1. */
#ifndef MCDU_DEBUG_DRAW_H
#define MCDU_DEBUG_DRAW_H

#include "McdCTypes.h"
#include "McdGeometryTypes.h"
#include "McdSpace.h"
#include "MeDebugDraw.h"

ME_EXTERN_C_BEGIN

/** Lines per drawn circle. */
#define MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS 16

/** What McduDebugDrawModel / McduDebugDrawSpace draw (combine with |; 0: the geometry only). */
typedef enum {
    kMcduDebugDrawAABB = 1,        /**< the model's AABB too (of its last update) */
    kMcduDebugDrawDetail = 2,      /**< accepted; the drawing is already complete */
    kMcduDebugDrawEnabledOnly = 4  /**< skip frozen models (the bridge freezes those of disabled bodies) */
} McduDebugDrawFlags;

/** Draw a sphere, a box or a cylinder at `tm` (reported when the geometry is of another type). */
ME_API void MEAPI McduDebugDrawSphere(const McdSphereID sphere, MeMatrix4 tm, const MeReal colour[3]);
/** Draw a box at tm through MeDebugDrawAPI; NULL tm or colour, or another geometry type, refused. */
ME_API void MEAPI McduDebugDrawBox(const McdBoxID box, MeMatrix4 tm, const MeReal colour[3]);
/** Draw a cylinder at tm through MeDebugDrawAPI; NULL tm or colour, or another geometry type, refused. */
ME_API void MEAPI McduDebugDrawCylinder(const McdCylinderID cyl, MeMatrix4 tm, const MeReal colour[3]);
/** Draw a convex mesh through the type's own debugDraw (McdGeometryTypeDesc); another type refused. */
ME_API void MEAPI McduDebugDrawConvex(const McdConvexMeshID convex, MeMatrix4 tm, const MeReal colour[3]);
/** Draw an aggregate's parts at tm through MeDebugDrawAPI; NULL tm or colour, or another type, refused. */
ME_API void MEAPI McduDebugDrawAggregate(const McdAggregateID agg, MeMatrix4 tm, const MeReal colour[3]);
/** The 12 edges of the box from min to max (world). */
ME_API void MEAPI McduDebugDrawAABB(const MeVector3 min, const MeVector3 max, const MeReal colour[3]);
/** Any geometry at `tm`: the built-in shapes as above (Null draws nothing), other types through
 *  their debugDraw (McdGeometryTypeDesc), or their AABB when they have none. */
ME_API void MEAPI McduDebugDrawGeometry(const McdGeometryID geometry, MeMatrix4Ptr tm, const MeReal colour[3]);
/** The model's geometry where its last update placed it, and its AABB with kMcduDebugDrawAABB. */
ME_API void MEAPI McduDebugDrawModel(const McdModelID model, McduDebugDrawFlags flags, const MeReal colour[3]);
/** McduDebugDrawModel on every model of the space. */
ME_API void MEAPI McduDebugDrawSpace(const McdSpaceID space, McduDebugDrawFlags flags, const MeReal colour[3]);

ME_EXTERN_C_END

#endif /* MCDU_DEBUG_DRAW_H */
