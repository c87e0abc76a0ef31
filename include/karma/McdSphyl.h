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
/** Radius of the caps and the cylinder part (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdSphylGetRadius(McdSphylID s);
/** Radius (m, > 0, finite, within 1e-6 ... 1e6 lengthScale); else refused (ME_ERR_MCD_DEGENERATE_GEOMETRY / _SIZE_RANGE). */
ME_API void McdSphylSetRadius(McdSphylID s, MeReal radius);
/** Length of the cylinder part along z (m, caps excluded); 0 for an invalid ID or another type. */
ME_API MeReal McdSphylGetHeight(McdSphylID s);
/** Length of the cylinder part (m, ≥ 0, finite; 0 makes a sphere); negative or NaN refused, sphyl unchanged. */
ME_API void McdSphylSetHeight(McdSphylID s, MeReal height);
/** Half the cylinder part's length (m); 0 for an invalid ID or another type (reported). */
ME_API MeReal McdSphylGetHalfHeight(McdSphylID s);

ME_EXTERN_C_END

#endif /* MCD_SPHYL_H */
