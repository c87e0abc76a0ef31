/* McdSphere.h -- a sphere centred on its origin. */
#ifndef MCD_SPHERE_H
#define MCD_SPHERE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdSphereID;

/** A sphere of `radius` (> 0, finite). NULL (reported) on bad input or a full pool. */
ME_API McdSphereID McdSphereCreate(McdFrameworkID fw, MeReal radius);
/** Radius (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdSphereGetRadius(McdSphereID s);
/** Radius (m, > 0, finite, within 1e-6 ... 1e6 lengthScale); else refused (ME_ERR_MCD_DEGENERATE_GEOMETRY / _SIZE_RANGE). */
ME_API void McdSphereSetRadius(McdSphereID s, MeReal radius);

ME_EXTERN_C_END

#endif /* MCD_SPHERE_H */
