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
/** Half edge lengths: a pointer to the box's own three (NULL for a bad ID). It stays valid, and
 *  follows McdBoxSetDimensions, until the geometry is destroyed; read it, do not write it. */
ME_API MeReal *McdBoxGetRadii(McdBoxID b);
/** x and y extent of the box placed at `tm` (NULL: identity): {min x, max x, min y, max y}. */
ME_API void McdBoxGetXYAABB(McdBoxID b, MeMatrix4 tm, MeReal bounds[4]);
/** The box's point farthest along the local direction inDir, in the local frame. */
ME_API void McdBoxMaximumPointLocal(McdBoxID b, MeReal *inDir, MeReal *outPoint);
/** Full edge lengths. */
ME_API void McdBoxGetDimensions(McdBoxID b, MeReal *dx, MeReal *dy, MeReal *dz);
/** Full edge lengths (m, each > 0, finite, within 1e-6 ... 1e6 lengthScale); else refused, box unchanged. */
ME_API void McdBoxSetDimensions(McdBoxID b, MeReal dx, MeReal dy, MeReal dz);

ME_EXTERN_C_END

#endif /* MCD_BOX_H */
