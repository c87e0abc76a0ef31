/* Mdt.h -- Karma Dynamics: worlds, bodies, constraints and the step. */
#ifndef MDT_H
#define MDT_H

#include "MeMath.h"
#include "MeMessage.h"
#include "MdtBSJoint.h"
#include "MdtBody.h"
#include "MdtCarWheel.h"
#include "MdtConstraint.h"
#include "MdtContact.h"
#include "MdtContactGroup.h"
#include "MdtContactParams.h"
#include "MdtHinge.h"
#include "MdtLimit.h"
#include "MdtPrismatic.h"
#include "MdtSpring.h"
#include "MdtTypes.h"
#include "MdtWorld.h"

#endif /* MDT_H */
