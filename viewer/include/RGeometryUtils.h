/* RGeometryUtils.h -- helpers for programs that fill a graphic's vertices themselves (Karma 1.2's
 * header name; of its functions, the one 1.2's demos call). */
#ifndef R_GEOMETRY_UTILS_H
#define R_GEOMETRY_UTILS_H

#include "MeViewer.h"

ME_EXTERN_C_BEGIN

/** Set a vertex: position and normal (local frame; the normal as given, not normalised) and texture
 *  coordinates (u, v). Nothing is done for a NULL vertex, position or normal. */
void MEAPI RSetVertex(RObjectVertex *vertex, const MeVector3 position, const MeVector3 normal, AcmeReal u, AcmeReal v);

ME_EXTERN_C_END

#endif /* R_GEOMETRY_UTILS_H */
