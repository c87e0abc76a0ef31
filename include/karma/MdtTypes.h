/* MdtTypes.h -- the IDs and callback types of Karma Dynamics (Mdt).
 *
 * IDs are opaque, checked handles: NULL means "none" (or "the world" where a joint takes a body),
 * and a destroyed, stale or foreign ID is reported through the message hook and ignored, in every
 * build. Never cast an ID to a pointer and dereference it. */
#ifndef MDT_TYPES_H
#define MDT_TYPES_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct MdtWorldHandle_ *MdtWorldID;           /**< a dynamics world */
typedef struct MdtBodyHandle_ *MdtBodyID;             /**< a rigid body of a world */
typedef struct MdtConstraintHandle_ *MdtConstraintID; /**< any constraint: joint, contact, contact group */

/* Each constraint type has an ID type of its own; Mdt<Type>QuaConstraint converts it to an
 * MdtConstraintID and MdtConstraintDCast<Type> converts back (NULL if the type differs). */
typedef struct MdtBSJointHandle_ *MdtBSJointID;
typedef struct MdtHingeHandle_ *MdtHingeID;
typedef struct MdtPrismaticHandle_ *MdtPrismaticID;
typedef struct MdtUniversalHandle_ *MdtUniversalID;
typedef struct MdtAngular3Handle_ *MdtAngular3ID;
typedef struct MdtCarWheelHandle_ *MdtCarWheelID;
typedef struct MdtLinear1Handle_ *MdtLinear1ID;
typedef struct MdtLinear2Handle_ *MdtLinear2ID;
typedef struct MdtFixedPathHandle_ *MdtFixedPathID;
typedef struct MdtRPROJointHandle_ *MdtRPROJointID;
typedef struct MdtSkeletalHandle_ *MdtSkeletalID;
typedef struct MdtSpring6Handle_ *MdtSpring6ID;
typedef struct MdtSpringHandle_ *MdtSpringID;
typedef struct MdtConeLimitHandle_ *MdtConeLimitID;
typedef struct MdtContactHandle_ *MdtContactID;
typedef struct MdtContactGroupHandle_ *MdtContactGroupID;
typedef struct MdtUserConstraintHandle_ *MdtUserConstraintID;

/** The constraint types, in Karma's order (the order is part of the API: it indexes dispatch). */
typedef enum MdtBclJointType {
    MdtBclBSJOINT = 0,
    MdtBclHINGE,
    MdtBclPRISMATIC,
    MdtBclCARWHEEL,
    MdtBclCONTACT,
    MdtBclCONTACTGROUP,
    MdtBclFIXEDPATH,
    MdtBclRPROJOINT,
    MdtBclUNIVERSAL,
    MdtBclSKELETAL,
    MdtBclLINEAR1,
    MdtBclLINEAR2,
    MdtBclANGULAR3,
    MdtBclSPRING6,
    MdtBclSPRING,
    MdtBclCONELIMIT,
    MdtBclUSER,
    MdtBclJOINT_TYPE_COUNT
} MdtBclJointType;

/** Called when the world enables or disables a body (the bridge freezes/unfreezes its model). */
typedef void (*MdtBodyEnableCBPtr)(MdtBodyID body, void *userData);
/** Called when a contact group is destroyed (the bridge clears its pair's reference). */
typedef void (*MdtContactGroupDestroyCBPtr)(MdtContactGroupID group, void *userData);
/** Called for each constraint by the ForAll iterators. */
typedef void (*MdtConstraintIteratorCBPtr)(MdtConstraintID constraint, void *userData);

ME_EXTERN_C_END

#endif /* MDT_TYPES_H */
