/* Mdt.h -- Karma Dynamics: worlds, bodies, constraints and the step. */
#ifndef MDT_H
#define MDT_H

#include "MeMath.h"
#include "MeMessage.h"
#include "MdtAngular3.h"
#include "MdtBSJoint.h"
#include "MdtBody.h"
#include "MdtConeLimit.h"
#include "MdtConstraint.h"
#include "MdtContact.h"
#include "MdtContactGroup.h"
#include "MdtContactParams.h"
#include "MdtFixedPath.h"
#include "MdtLinear1.h"
#include "MdtLinear2.h"
#include "MdtRPROJoint.h"
#include "MdtSkeletal.h"
#include "MdtSpring6.h"
#include "MdtTypes.h"
#include "MdtUniversal.h"
#include "MdtUserConstraint.h"
#include "MdtWorld.h"

#endif /* MDT_H */
