/* body.h -- the rigid body record (internal).
 *
 * State is kept for the centre-of-mass (COM) frame, which is what the integrator advances:
 * comTM (rotation = the body's, translation = COM in world), linear velocity of the COM and world
 * angular velocity. The body frame the application sees (bodyTM) differs from the COM frame only by
 * the fixed offset `comOffset` (body frame) and is recomputed whenever the state changes.
 * Quaternion q (w,x,y,z) is the authoritative orientation; both TMs derive from it. */
#ifndef MDT_BODY_INTERNAL_H
#define MDT_BODY_INTERNAL_H

#include <stdint.h>

#include <karma/MdtBody.h>
#include <karma/MeMath.h>

struct MdtWorldData;

/* Blocks the rest window is cut into (mdt/rest_window.c); one more holds the block being filled. */
#define MDT_REST_BLOCKS 8

typedef struct MdtBodyData {
    uintptr_t id;            /* this body's own checked ID */
    struct MdtWorldData *world;
    int slot;                /* index in the world's body pool */

    /* state */
    MeMatrix4 bodyTM;        /* body frame; renderers hold a pointer to this */
    MeMatrix4 comTM;         /* centre-of-mass frame */
    MeVector4 q;             /* orientation (w,x,y,z), unit */
    MeVector3 vel;           /* COM velocity, world */
    MeVector3 velrot;        /* angular velocity, world */
    MeVector3 accel;         /* over the last step (read only) */
    MeVector3 accelrot;

    /* mass properties */
    MeReal mass, invMass;
    MeMatrix3 inertia;       /* about the COM, body frame, as set by the application */
    MeMatrix3 invInertia;    /* inverse of the inertia in use (full or spherical), body frame */
    MeVector3 comOffset;     /* COM in the body frame */
    MeBool nonSpherical;     /* use the full tensor (else the mean of its diagonal) */
    MeReal inertiaBound;     /* at least the largest eigenvalue of the inertia in use (the runaway check's
                                bound; to MeReal's rounding) */
    MeBool coriolis;         /* include the gyroscopic term */

    /* settings */
    MeReal linearDamping, angularDamping;
    MeVector3 fastSpinAxis;  /* world frame, unit */
    MeBool useFastSpin;
    MeI32 sortKey;
    void *userData;
    void *model;             /* the collision model a bridge linked to this body (MdtBodySetModel; opaque to Mdt), or NULL */

    /* accumulators, cleared by each step that simulates the body */
    MeVector3 force, torque;
    MeVector3 impulse, angularImpulse;

    /* bookkeeping for the step */
    MeBool enabled;
    MeBool enabledByPartitioner; /* woken by a constraint this step: exempt from auto-disable */
    MeReal enabledTime;          /* seconds simulated since last enabled */
    int partition;               /* index in the last step's partitions, or -1 */
    int stepIndex;               /* position in the step's body arrays, or -1 */
    unsigned long visitStamp;    /* partitioner: step in which it was last visited */
    MeVector3 velStar, velrotStar; /* velocities with external forces applied, before constraints */
    MeVector3 stepStartCom;        /* pose at the start of the step, restored if the step fails */
    MeVector4 stepStartQ;
    MeBool speedWarned;            /* reported over a speed limit, not yet back under both */
    MeBool energyWarned;           /* in a partition reported for an energy jump that has not calmed */

    /* rest window (rest_window.c): sums of velocity and angular velocity over blocks of steps since
     * the body was enabled or its velocity set; a ring of MDT_REST_BLOCKS + 1 blocks, the newest being
     * filled */
    MeReal restSum[MDT_REST_BLOCKS + 1][6];
    int restCount[MDT_REST_BLOCKS + 1]; /* steps summed in each block */
    int restNewest;                     /* ring index of the block being filled */
    int restFull;                       /* complete blocks (saturates at MDT_REST_BLOCKS) */

    /* constraints attached to this body: a singly linked list through the constraints (later) */
    void *firstConstraint;
} MdtBodyData;

/* Resolve an ID or report in the caller's name; NULL when invalid. */
MdtBodyData *MdtBodyFromID(MdtBodyID id, const char *function);
/* Recompute bodyTM and comTM from q, the COM position and the offset. */
void MdtBodyUpdateTransforms(MdtBodyData *b, const MeVector3 comPosition);
/* World-frame inverse inertia tensor (symmetric) of the body's current orientation. */
void MdtBodyWorldInverseInertia(const MdtBodyData *b, MeMatrix3 out);
/* World-frame inertia tensor. */
void MdtBodyWorldInertia(const MdtBodyData *b, MeMatrix3 out);
/* Enable or disable, calling the world's callbacks (used by the partitioner and auto-disable). */
void MdtBodySetEnabledInternal(MdtBodyData *b, MeBool enabled);

#endif /* MDT_BODY_INTERNAL_H */
