/* continuous.h -- the universe's continuous-collision pass (internal): the start poses of the bodies
 * of flagged models (McdModelEnableContinuous), taken before the world steps, and the sweep after it
 * that puts a body that went through something back at its first time of impact. */
#ifndef MST_CONTINUOUS_INTERNAL_H
#define MST_CONTINUOUS_INTERNAL_H

#include <karma/McdTypes.h>
#include <karma/MdtTypes.h>
#include <karma/MstTypes.h>

typedef struct MstSweepStart {
    McdModelID model;
    MdtBodyID body;
    MeMatrix4 start; /* the body's transform before the step */
} MstSweepStart;

typedef struct MstContinuous {
    MstSweepStart *starts;
    int count, capacity;
    McdModelID *models; /* the framework's flagged models, read each step */
    int modelCapacity;
} MstContinuous;

/** Record the start poses of the enabled bodies of the space's flagged models (nothing, and no
 *  scan, when the framework has no flagged model). */
void MstContinuousBeforeStep(MstContinuous *c, McdFrameworkID fw, McdSpaceID space);
/** Sweep each recorded body over the step of `stepSize` s just taken and move it back to its first
 *  time of impact (velocity kept, unless it was touching what it hit and was driven into it all the
 *  same: then its approach along the hit's normal is reflected by the pair's restitution). */
void MstContinuousAfterStep(MstContinuous *c, MstBridgeID bridge, MeReal stepSize);
/** Free the records. */
void MstContinuousFree(MstContinuous *c);

#endif /* MST_CONTINUOUS_INTERNAL_H */
