/* McdCylinder.h -- a solid cylinder along local z, its origin at half height. */
#ifndef MCD_CYLINDER_H
#define MCD_CYLINDER_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdCylinderID;

/** A cylinder of `radius` and full `height` (both > 0, finite), z in [-height/2, height/2]. */
ME_API McdCylinderID McdCylinderCreate(McdFrameworkID fw, MeReal radius, MeReal height);
ME_API MeReal McdCylinderGetRadius(McdCylinderID c);
ME_API void McdCylinderSetRadius(McdCylinderID c, MeReal radius);
ME_API MeReal McdCylinderGetHeight(McdCylinderID c);
ME_API void McdCylinderSetHeight(McdCylinderID c, MeReal height);
ME_API MeReal McdCylinderGetHalfHeight(McdCylinderID c);

ME_EXTERN_C_END

#endif /* MCD_CYLINDER_H */
