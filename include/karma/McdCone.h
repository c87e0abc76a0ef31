/* McdCone.h -- a cone (or truncated cone) along local z.
 *
 * The lower disc (lowerRadius) lies below the upper one (upperRadius; 0 for a pointed cone) by
 * `length`. As for every geometry, the origin is the centre of mass: for a pointed cone the base is
 * at z = -length/4 and the apex at z = 3 length/4. */
#ifndef MCD_CONE_H
#define MCD_CONE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdConeID;

/** A pointed cone of `length` and base radius `lowerRadius` (both > 0, finite). */
ME_API McdConeID McdConeCreate(McdFrameworkID fw, MeReal length, MeReal lowerRadius);
/** Change every dimension: length > 0, lowerRadius > 0, 0 <= upperRadius <= lowerRadius. */
ME_API void McdConeSetGeometricalParameters(McdConeID c, MeReal length, MeReal lowerRadius, MeReal upperRadius);
/** Length along z, lower disc to upper disc or tip (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdConeGetLength(McdConeID c);
/** Radius of the base disc (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdConeGetLowerRadius(McdConeID c);
/** Radius of the upper disc (m, 0 for a pointed cone); 0 for an invalid ID or another type. */
ME_API MeReal McdConeGetUpperRadius(McdConeID c);
/** z of the lower and upper discs in the cone's frame (origin at the centre of mass). */
ME_API MeReal McdConeGetLowerZ(McdConeID c);
/** z of the upper disc or tip in the cone's frame (m); 0 for an invalid ID or another type. */
ME_API MeReal McdConeGetUpperZ(McdConeID c);
/** Karma's offset of the cone's frame: the z of the lower disc (-length/4 for a pointed cone), where
 *  a viewer puts the base of the cone it draws. */
ME_API MeReal McdConeGetZOffset(McdConeID c);

ME_EXTERN_C_END

#endif /* MCD_CONE_H */
