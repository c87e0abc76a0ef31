/* RGeometry.h -- the graphics of collision geometry (Karma 1.2's header name): RGraphicCreateFromModel,
 * RGraphicCreateFromGeometry and RGraphicAggregateCreate, declared in MeViewer.h. */
#ifndef R_GEOMETRY_H
#define R_GEOMETRY_H

#include "MeViewer.h"

#endif /* R_GEOMETRY_H */
