/* McdSphyl.h -- a sphyl (capsule): a cylinder along local z capped by two hemispheres.
 *
 * `height` is the length of the cylindrical part only (Karma's convention); the total length is
 * height + 2 * radius. The origin is at the centre. */
#ifndef MCD_SPHYL_H
#define MCD_SPHYL_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdSphylID;

/** A sphyl of `radius` (> 0) and cylinder part `height` (>= 0; 0 makes a sphere), both finite. */
ME_API McdSphylID McdSphylCreate(McdFrameworkID fw, MeReal radius, MeReal height);
ME_API MeReal McdSphylGetRadius(McdSphylID s);
ME_API void McdSphylSetRadius(McdSphylID s, MeReal radius);
ME_API MeReal McdSphylGetHeight(McdSphylID s);
ME_API void McdSphylSetHeight(McdSphylID s, MeReal height);
ME_API MeReal McdSphylGetHalfHeight(McdSphylID s);

ME_EXTERN_C_END

#endif /* MCD_SPHYL_H */
