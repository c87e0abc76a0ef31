/* Mcd.h -- Karma Collision: framework, geometries, models, pairs and queries. */
#ifndef MCD_H
#define MCD_H

#include "McdBox.h"
#include "McdCTypes.h"
#include "McdCone.h"
#include "McdContact.h"
#include "McdContinuous.h"
#include "McdConvexMesh.h"
#include "McdCullingTable.h"
#include "McdCylinder.h"
#include "McdFrame.h"
#include "McdGeometry.h"
#include "McdGeometryTypes.h"
#include "McdInteraction.h"
#include "McdInteractionTable.h"
#include "McdInteractions.h"
#include "McdLineSegment.h"
#include "McdModel.h"
#include "McdModelPair.h"
#include "McdModelPairContainer.h"
#include "McdNull.h"
#include "McdPlane.h"
#include "McdPrimitives.h"
#include "McdRGHeightField.h"
#include "McdSphere.h"
#include "McdSpace.h"
#include "McdSphyl.h"
#include "McdTriangleList.h"
#include "McdTriangleMesh.h"
#include "McdTypes.h"

#endif /* MCD_H */
