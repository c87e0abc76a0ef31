/* Mdt.h -- Karma Dynamics: worlds, bodies, constraints and the step. */
#ifndef MDT_H
#define MDT_H

#include "MdtAngular3.h"
#include "MdtBSJoint.h"
#include "MdtBody.h"
#include "MdtCarWheel.h"
#include "MdtConeLimit.h"
#include "MdtConstraint.h"
#include "MdtContact.h"
#include "MdtContactGroup.h"
#include "MdtContactParams.h"
#include "MdtFixedPath.h"
#include "MdtHinge.h"
#include "MdtLOD.h"
#include "MdtLimit.h"
#include "MdtLinear1.h"
#include "MdtLinear2.h"
#include "MdtMainLoop.h"
#include "MdtPrismatic.h"
#include "MdtRPROJoint.h"
#include "MdtSkeletal.h"
#include "MdtSpring.h"
#include "MdtSpring6.h"
#include "MdtTaskSystem.h"
#include "MdtTypes.h"
#include "MdtUniversal.h"
#include "MdtUserConstraint.h"
#include "MdtWorld.h"
#include "MeMath.h"
#include "MeMessage.h"

#endif /* MDT_H */
