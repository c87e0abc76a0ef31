/* McdPlane.h -- an infinite plane through the local origin with normal local +z.
 *
 * The solid side is z <= 0 (a half-space): models above are pushed up, a line segment starting
 * below it starts inside. Planes are for static models only (they have no finite mass).
 *
 * In a y-up world (Karma's samples, every scene here) turn the plane by -pi/2 about x, so that its
 * normal, local z, is world +y. The transform's rows are the plane's axes in the world:
 *
 *     static MeMatrix4 groundTM = {{1, 0, 0, 0},     local x -> world x
 *                                  {0, 0, -1, 0},    local y -> world -z
 *                                  {0, 1, 0, 0},     local z (the normal) -> world y
 *                                  {0, 0, 0, 1}};    through the origin: the ground is y = 0
 *     MstFixedModelCreate(universe, McdPlaneCreate(framework), groundTM);
 *
 * Unrotated, the plane is the floor z = 0 of a z-up world: under y-up gravity, bodies fall past it. */
#ifndef MCD_PLANE_H
#define MCD_PLANE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdPlaneID;

/** A plane geometry (see above for y up); NULL (reported) when the framework's geometry pool is full. */
ME_API McdPlaneID McdPlaneCreate(McdFrameworkID fw);
/** The plane's unit normal in the world for the plane placed at `tm` (NULL: local, (0, 0, 1)). */
ME_API void McdPlaneGetNormal(McdPlaneID p, MeMatrix4 tm, MeVector3 normal);
/** Signed distance from the world point `point` to the plane placed at `tm` (NULL: identity);
 *  positive above (on the normal's side). */
ME_API MeReal McdPlaneGetDistanceToPoint(McdPlaneID p, MeMatrix4 tm, const MeVector3 point);

ME_EXTERN_C_END

#endif /* MCD_PLANE_H */
