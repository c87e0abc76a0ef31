/* Mcd.h -- Karma Collision: framework, geometries, models, pairs and queries. */
#ifndef MCD_H
#define MCD_H

#include "McdBox.h"
#include "McdCone.h"
#include "McdContact.h"
#include "McdCylinder.h"
#include "McdFrame.h"
#include "McdGeometry.h"
#include "McdInteraction.h"
#include "McdLineSegment.h"
#include "McdModel.h"
#include "McdModelPair.h"
#include "McdNull.h"
#include "McdPlane.h"
#include "McdSphere.h"
#include "McdSpace.h"
#include "McdSphyl.h"
#include "McdTypes.h"

#endif /* MCD_H */
