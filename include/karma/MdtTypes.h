/* MdtTypes.h -- the IDs and callback types of Karma Dynamics (Mdt).
 *
 * IDs are opaque, checked handles: NULL means "none" (or "the world" where a joint takes a body),
 * and a destroyed, stale or foreign ID is reported through the message hook and ignored, in every
 * build. Never cast an ID to a pointer and dereference it. */
#ifndef MDT_TYPES_H
#define MDT_TYPES_H

#include "MdtBcl.h"
#include "MdtDefaults.h"
#include "MeChunk.h"
#include "MePool.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/* Karma 1.2's struct names, usable in declarations (`MdtWorld *w`, `MdtBody *b`). The structs are
 * never defined: an ID is a checked handle with the type of a pointer to one of them. The library's
 * own records have other names. */
typedef struct MdtWorld MdtWorld;
typedef struct MdtBody MdtBody;
typedef struct MdtBaseConstraint MdtBaseConstraint; /**< what any constraint ID points to */
typedef struct MdtBSJoint MdtBSJoint;
typedef struct MdtHinge MdtHinge;
typedef struct MdtPrismatic MdtPrismatic;
typedef struct MdtUniversal MdtUniversal;
typedef struct MdtAngular3 MdtAngular3;
typedef struct MdtCarWheel MdtCarWheel;
typedef struct MdtLinear1 MdtLinear1;
typedef struct MdtLinear2 MdtLinear2;
typedef struct MdtFixedPath MdtFixedPath;
typedef struct MdtRPROJoint MdtRPROJoint;
typedef struct MdtSkeletal MdtSkeletal;
typedef struct MdtSpring6 MdtSpring6;
typedef struct MdtSpring MdtSpring;
typedef struct MdtConeLimit MdtConeLimit;
typedef struct MdtContact MdtContact;
typedef struct MdtContactGroup MdtContactGroup;
typedef struct MdtUserConstraint MdtUserConstraint;

/* Plain structs of Karma 1.2's, defined in MdtMainLoop.h and MdtPartition.h. */
typedef struct MdtPartitionInfo MdtPartitionInfo;
typedef struct MdtPartitionParams MdtPartitionParams;

typedef MdtWorld *MdtWorldID;                   /**< a dynamics world */
typedef MdtBody *MdtBodyID;                     /**< a rigid body of a world */
typedef MdtBaseConstraint *MdtConstraintID;     /**< any constraint: joint, contact, contact group */

/* Each constraint type has an ID type of its own; Mdt<Type>QuaConstraint converts it to an
 * MdtConstraintID and MdtConstraintDCast<Type> converts back (NULL if the type differs). */
typedef MdtBSJoint *MdtBSJointID;
typedef MdtHinge *MdtHingeID;
typedef MdtPrismatic *MdtPrismaticID;
typedef MdtUniversal *MdtUniversalID;
typedef MdtAngular3 *MdtAngular3ID;
typedef MdtCarWheel *MdtCarWheelID;
typedef MdtLinear1 *MdtLinear1ID;
typedef MdtLinear2 *MdtLinear2ID;
typedef MdtFixedPath *MdtFixedPathID;
typedef MdtRPROJoint *MdtRPROJointID;
typedef MdtSkeletal *MdtSkeletalID;
typedef MdtSpring6 *MdtSpring6ID;
typedef MdtSpring *MdtSpringID;
typedef MdtConeLimit *MdtConeLimitID;
typedef MdtContact *MdtContactID;
typedef MdtContactGroup *MdtContactGroupID;
typedef MdtUserConstraint *MdtUserConstraintID;

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

/** What MdtWorldSetDebugDrawing draws through MeDebugDrawAPI.line after each step (bits). */
typedef enum MdtDebugDrawOptions {
    MdtDebugDrawContacts = 0x001,    /**< red: each contact's normal from its position, lengthened by its
                                          penetration (1 + 50·penetration long) */
    MdtDebugDrawContactForce = 0x002 /**< green: the force each contact applied to its body 0 (1 m per N) */
} MdtDebugDrawOptions;

/** Flag of a body index meaning "no body" (the world), as Karma 1.2's constraint rows used it. */
#define MdtBclNO_BODY (-1)

/** Called when the world enables or disables a body (the bridge freezes/unfreezes its model). */
typedef void (*MdtBodyEnableCBPtr)(MdtBodyID body, void *userData);
/** Called when a contact group is destroyed (the bridge clears its pair's reference). */
typedef void (*MdtContactGroupDestroyCBPtr)(MdtContactGroupID group, void *userData);
/** Called for each constraint by the ForAll iterators. */
typedef void (*MdtConstraintIteratorCBPtr)(MdtConstraintID constraint, void *userData);

ME_EXTERN_C_END

#endif /* MDT_TYPES_H */
