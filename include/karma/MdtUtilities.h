/* MdtUtilities.h -- Karma 1.2's header for the Mdt utilities (inertia tensors of a sphere and a box,
 * vector conversion between body frames), which MdtBody.h declares. */
#ifndef MDT_UTILITIES_H
#define MDT_UTILITIES_H

#include "MdtBody.h"

#endif /* MDT_UTILITIES_H */
