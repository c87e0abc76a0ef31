/* McdSphere.h -- a sphere centred on its origin. */
#ifndef MCD_SPHERE_H
#define MCD_SPHERE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdSphereID;

/** A sphere of `radius` (> 0, finite). NULL (reported) on bad input or a full pool. */
ME_API McdSphereID McdSphereCreate(McdFrameworkID fw, MeReal radius);
ME_API MeReal McdSphereGetRadius(McdSphereID s);
ME_API void McdSphereSetRadius(McdSphereID s, MeReal radius);

ME_EXTERN_C_END

#endif /* MCD_SPHERE_H */
