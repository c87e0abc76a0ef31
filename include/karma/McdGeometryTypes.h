/* McdGeometryTypes.h -- Karma 1.2's header name: the geometry type numbers and every primitive geometry's header. */
#ifndef MCD_GEOMETRY_TYPES_H
#define MCD_GEOMETRY_TYPES_H

#include "McdTypes.h"
#include "McdBox.h"
#include "McdCone.h"
#include "McdCylinder.h"
#include "McdNull.h"
#include "McdPlane.h"
#include "McdSphere.h"
#include "McdSphyl.h"

#endif /* MCD_GEOMETRY_TYPES_H */
