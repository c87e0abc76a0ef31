/* world.h -- the dynamics world record (internal).
 *
 * The world owns the body and constraint pools (fixed size, generational slots behind the IDs), the
 * solver settings, the auto-disable settings, the profile and the scratch chunks the step uses. */
#ifndef MDT_WORLD_INTERNAL_H
#define MDT_WORLD_INTERNAL_H

#include <karma/MeChunk.h>
#include <karma/MePool.h>
#include <karma/MeProfile.h>
#include <karma/MdtWorld.h>

#include "body.h"

/* Names of the step's profile sections (docs/step.md). */
#define MDT_SECTION_STEP "Dynamics"
#define MDT_SECTION_PARTITION "Partition"
#define MDT_SECTION_AUTODISABLE "AutoDisable"
#define MDT_SECTION_PACK "Pack"
#define MDT_SECTION_SOLVE "Solve"
#define MDT_SECTION_INTEGRATE "Integrate"
#define MDT_SECTION_UNPACK "Unpack"

typedef struct MdtAutoDisableParams {
    MeBool enabled;
    MeReal velocity, angularVelocity, acceleration, angularAcceleration; /* squared magnitudes */
    MeReal aliveTime;                                                    /* seconds */
} MdtAutoDisableParams;

/* The step's view of the enabled bodies, grouped into partitions (islands). */
typedef struct MdtPartitionOutput {
    int bodyCount;
    MdtBody **bodies;        /* enabled bodies, grouped by partition */
    int partitionCount;
    int *partitionStart;     /* partitionCount + 1 offsets into bodies */
} MdtPartitionOutput;

typedef struct MdtWorld {
    int ownerSlot;           /* registry slot behind the MdtWorldID */
    uintptr_t id;
    MePool bodyPool;
    MePool constraintPool;
    unsigned int maxBodies, maxConstraints;
    MeReal lengthScale, massScale;

    /* settings */
    MeVector3 gravity;
    MeReal epsilon, gamma;
    int maxLCPIterations;
    MdtAutoDisableParams autoDisable;

    /* callbacks */
    MdtBodyEnableCBPtr bodyEnableCB, bodyDisableCB;
    void *bodyEnableData, *bodyDisableData;

    /* step state */
    MeBool locked;           /* inside MdtWorldStep */
    MeReal stepSize;         /* of the step in progress or the last one */
    int enabledBodyCount;
    MdtPartitionOutput partitions;
    MeChunk partitionChunk;  /* body lists and partition offsets */
    MeChunk keaChunk;        /* solver workspace */
    MeProfile profile;
    unsigned long steps;
    MeReal time;
    int lastRowCount;
} MdtWorld;

/* Resolve an ID or report in the caller's name; NULL when invalid. */
MdtWorld *MdtWorldFromID(MdtWorldID id, const char *function);
/* Set every setting to its default for the world's scales. */
void MdtWorldSetDefaults(MdtWorld *w);

/* The stages of the step (docs/step.md), each timed by MdtWorldStep. */
void MdtUpdatePartitions(MdtWorld *w);
void MdtAutoDisable(MdtWorld *w);
void MdtPack(MdtWorld *w);

#endif /* MDT_WORLD_INTERNAL_H */
