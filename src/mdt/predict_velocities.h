/* predict_velocities.h -- the first half of the integrator: each body's velocities before the
 * constraints act (predict_velocities.c; internal, called by the pack stage). */
#ifndef MDT_PREDICT_VELOCITIES_H
#define MDT_PREDICT_VELOCITIES_H

#include "world.h"

/* v*, ω*: velocities after external forces, impulses, gyroscopic term and damping, before
 * constraints. Also records the start-of-step pose. For the step's bodies [start, end) (partition
 * order); each body's prediction reads only it and the world's settings, so ranges may run at once. */
void MdtPredictVelocitiesOf(MdtWorldData *w, int start, int end);

#endif
