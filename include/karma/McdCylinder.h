/* McdCylinder.h -- a solid cylinder along local z, its origin at half height. */
#ifndef MCD_CYLINDER_H
#define MCD_CYLINDER_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdCylinderID;

/** A cylinder of `radius` and full `height` (both > 0, finite), z in [-height/2, height/2]. */
ME_API McdCylinderID McdCylinderCreate(McdFrameworkID fw, MeReal radius, MeReal height);
/** Radius (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdCylinderGetRadius(McdCylinderID c);
/** Radius (m, > 0, finite, within 1e-6 ... 1e6 lengthScale); else refused (ME_ERR_MCD_DEGENERATE_GEOMETRY / _SIZE_RANGE). */
ME_API void McdCylinderSetRadius(McdCylinderID c, MeReal radius);
/** Full height along z (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdCylinderGetHeight(McdCylinderID c);
/** Full height (m, > 0, finite, within 1e-6 ... 1e6 lengthScale); else refused, cylinder unchanged. */
ME_API void McdCylinderSetHeight(McdCylinderID c, MeReal height);
/** Half the height (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdCylinderGetHalfHeight(McdCylinderID c);
/** Set radius and full height at once (both > 0, finite). */
ME_API void McdCylinderSetGeometricalParameters(McdCylinderID c, MeReal inRadius, MeReal inHeight);
/** x and y extent of the cylinder placed at `tm` (NULL: identity): {min x, max x, min y, max y}. */
ME_API void McdCylinderGetXYAABB(McdCylinderID c, MeMatrix4 tm, MeReal bounds[4]);
/** The cylinder's point farthest along the local direction inDir, in the local frame. */
ME_API void McdCylinderMaximumPointLocal(McdCylinderID c, MeReal *inDir, MeReal *outPoint);

ME_EXTERN_C_END

#endif /* MCD_CYLINDER_H */
