/* McdPlane.h -- an infinite plane through the local origin with normal local +z.
 *
 * The solid side is z <= 0 (a half-space): models above are pushed up, a line segment starting
 * below it starts inside. Rotate a plane's model by -pi/2 about x for a y-up world. Planes are for
 * static models only (they have no finite mass). */
#ifndef MCD_PLANE_H
#define MCD_PLANE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdPlaneID;

ME_API McdPlaneID McdPlaneCreate(McdFrameworkID fw);
/** The plane's unit normal in the world for the plane placed at `tm` (NULL: local, (0, 0, 1)). */
ME_API void McdPlaneGetNormal(McdPlaneID p, MeMatrix4 tm, MeVector3 normal);
/** Signed distance from the world point `point` to the plane placed at `tm` (NULL: identity);
 *  positive above (on the normal's side). */
ME_API MeReal McdPlaneGetDistanceToPoint(McdPlaneID p, MeMatrix4 tm, const MeVector3 point);

ME_EXTERN_C_END

#endif /* MCD_PLANE_H */
