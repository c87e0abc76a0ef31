/* MeBounding.h -- a bounding sphere of a set of points. */
#ifndef ME_BOUNDING_H
#define ME_BOUNDING_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** centre, *radius = a sphere containing the numPoints points (Ritter's method: within a few per
 *  cent of the smallest). No points give a zero sphere at the origin. */
ME_API void MEAPI MeBoundingSphereCalc(MeVector3 *points, int numPoints, MeVector3 centre, MeReal *radius);

ME_EXTERN_C_END

#endif /* ME_BOUNDING_H */
