/* kea_integrate.h -- body prediction and integration around the constraint solve (internal). */
#ifndef MDT_KEA_INTEGRATE_H
#define MDT_KEA_INTEGRATE_H

#include "../world.h"

/* v*, ω*: velocities after external forces, impulses, gyroscopic term and damping, before
 * constraints. Also records the start-of-step pose. For every body of the step's partitions. */
void MdtKeaPredictVelocities(MdtWorldData *w);

#endif
