/* RConvex.h -- the graphic of a convex mesh (Karma 1.2's header name). */
#ifndef R_CONVEX_H
#define R_CONVEX_H

#include <karma/McdConvexMesh.h>

#include "MeViewer.h"

ME_EXTERN_C_BEGIN

/** The polygons of convex mesh `conv` (local frame, m), each flat-shaded with its outward normal,
 *  coloured, following `matrix` (may be NULL), put in the 3D list. The rounding (fatness) is not
 *  drawn, as in Karma 1.2. NULL (with a message) for a NULL context or a geometry that is not a
 *  convex mesh. */
RGraphic *MEAPI RGraphicConvexCreate(RRender *const rc, const McdConvexMeshID conv, const float color[4],
                                     const MeMatrix4Ptr matrix);

ME_EXTERN_C_END

#endif /* R_CONVEX_H */
