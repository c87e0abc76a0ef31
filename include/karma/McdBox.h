/* McdBox.h -- a rectangular box centred on its origin, edges along the local axes.
 *
 * Karma's convention: McdBoxCreate takes the FULL edge lengths; McdBoxGetRadii gives half of them. */
#ifndef MCD_BOX_H
#define MCD_BOX_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdBoxID;

/** A box of full edge lengths dx, dy, dz (each > 0, finite). */
ME_API McdBoxID McdBoxCreate(McdFrameworkID fw, MeReal dx, MeReal dy, MeReal dz);
/** Half edge lengths. */
ME_API void McdBoxGetRadii(McdBoxID b, MeVector3 radii);
/** Full edge lengths. */
ME_API void McdBoxGetDimensions(McdBoxID b, MeReal *dx, MeReal *dy, MeReal *dz);
ME_API void McdBoxSetDimensions(McdBoxID b, MeReal dx, MeReal dy, MeReal dz);

ME_EXTERN_C_END

#endif /* MCD_BOX_H */
