/* Mdt.h -- Karma Dynamics: worlds, bodies, constraints and the step. */
#ifndef MDT_H
#define MDT_H

#include "MeMath.h"
#include "MeMessage.h"
#include "MdtBody.h"
#include "MdtTypes.h"
#include "MdtWorld.h"

#endif /* MDT_H */
