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

/** Called when the world enables or disables a body (the bridge freezes/unfreezes its model). */
typedef void (*MdtBodyEnableCBPtr)(MdtBodyID body, void *userData);
/** Called for each constraint by the ForAll iterators. */
typedef void (*MdtConstraintIteratorCBPtr)(MdtConstraintID constraint, void *userData);

ME_EXTERN_C_END

#endif /* MDT_TYPES_H */
