/* MstBridge.h -- the bridge between Karma Collision (Mcd) and Karma Dynamics (Mdt).
 *
 * The bridge owns the material table: for every pair of materials (symmetric) the contact parameters
 * copied by value into each new dynamics contact, and three optional callbacks. Each step,
 * MstBridgeUpdateContacts reads the space's pairs in chunks and, for each chunk, handles transitions
 * (Hello: order the pair and choose its nearfield test; Goodbye: destroy its contact group) and
 * collisions (nearfield test → McdContacts → MdtContacts in the pair's MdtContactGroup, created when
 * the models first intersect and destroyed at Goodbye; a step without contacts leaves it empty and
 * disabled).
 *
 * Body order: a group's body 0 is model 1's body and body 1 model 2's; when model 1 has no body (it
 * is part of the world) the pair is turned round so that the dynamic body is body 0 and body 1 NULL
 * (the group is marked swapped). Normals point from model 2 towards model 1 and from body 1 towards
 * body 0 alike: copied as they are, negated for a turned-round pair. */
#ifndef MST_BRIDGE_H
#define MST_BRIDGE_H

#include "McdSpace.h"
#include "McdTypes.h"
#include "MdtContactGroup.h"
#include "MdtContactParams.h"
#include "MdtTypes.h"
#include "MstModelDynamics.h"
#include "MstTypes.h"

ME_EXTERN_C_BEGIN

/** A bridge with room for maxMaterials materials (≥ 1; material 0 exists from the start). */
ME_API MstBridgeID MstBridgeCreate(McdFrameworkID frame, int maxMaterials);
/** Destroy the bridge and its buffers and material table (the space, world and models are not touched). */
ME_API void MstBridgeDestroy(MstBridgeID b);
/** Whether b is a live bridge ID (no message). */
ME_API MeBool MstBridgeIsValid(MstBridgeID b);

/** The default material (0): every model starts with it. */
ME_API MstMaterialID MstBridgeGetDefaultMaterial(void);
/** A new material whose pairs start with the default contact parameters (frictionless), or
 *  MST_MATERIAL_INVALID when the table is full (reported, naming the size to raise). */
ME_API MstMaterialID MstBridgeGetNewMaterial(MstBridgeID b);
/** Materials in use, the default one included; 0 for an invalid ID (reported). */
ME_API int MstBridgeGetMaterialCount(MstBridgeID b);
/** The maxMaterials given to MstBridgeCreate; 0 for an invalid ID (reported). */
ME_API int MstBridgeGetMaxMaterials(MstBridgeID b);

/** The parameters used for contacts between materials m1 and m2 (same entry as (m2, m1)); edit them
 *  through the MdtContactParams functions. NULL (reported) for a bad material. */
ME_API MdtContactParamsID MstBridgeGetContactParams(MstBridgeID b, MstMaterialID m1, MstMaterialID m2);

/** Callbacks of a material pair (NULL: none): after a pair test (intersect), per contact made (a
 *  zero return drops the contact) and per pair (a zero return drops the pair's contacts). */
ME_API void MstBridgeSetIntersectCB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2, MstIntersectCBPtr cb);
/** The intersect callback of the material pair, or NULL (also for a bad ID or material, reported). */
ME_API MstIntersectCBPtr MstBridgeGetIntersectCB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2);
/** Callback per contact made for the material pair (NULL: none); a bad ID or material refused. */
ME_API void MstBridgeSetPerContactCB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2, MstPerContactCBPtr cb);
/** The per-contact callback of the material pair, or NULL (also for a bad ID or material, reported). */
ME_API MstPerContactCBPtr MstBridgeGetPerContactCB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2);
/** Callback per pair of models of the material pair (NULL: none); a bad ID or material refused. */
ME_API void MstBridgeSetPerPairCB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2, MstPerPairCBPtr cb);
/** The per-pair callback of the material pair, or NULL (also for a bad ID or material, reported). */
ME_API MstPerPairCBPtr MstBridgeGetPerPairCB(MstBridgeID b, MstMaterialID m1, MstMaterialID m2);

/** Size of the pair container read from the space per chunk (default 128). */
ME_API void MstBridgeSetModelPairBufferSize(MstBridgeID b, int size);
/** Size of the pair container read per chunk; 0 for an invalid ID (reported). */
ME_API int MstBridgeGetModelPairBufferSize(MstBridgeID b);
/** Size of the McdContact buffer one pair test may fill (default 32; at least 1): the only limit on
 *  the contacts one pair makes in a step, an intersect callback's included. */
ME_API void MstBridgeSetContactBufferSize(MstBridgeID b, int size);
/** Size of the contact buffer of one pair test; 0 for an invalid ID (reported). */
ME_API int MstBridgeGetContactBufferSize(MstBridgeID b);

/** The step size (s) the next updates' contacts are for (0, the default: not known). Knowing it, the
 *  bridge leaves out a pair's points apart whose gap cannot close within the step (decision C23);
 *  MstUniverseStep sets its own step for its update. Negative or non-finite sizes are refused. */
ME_API void MstBridgeSetStepSize(MstBridgeID b, MeReal stepSize);
/** The step size set by MstBridgeSetStepSize; 0 when not known or for an invalid ID (reported). */
ME_API MeReal MstBridgeGetStepSize(MstBridgeID b);

/** The whole bridge step: ends the space's change block, reads every pair in chunks, handles
 *  transitions and collisions, and opens a change block again. Call after McdSpaceUpdateAll and
 *  before MdtWorldStep. */
ME_API void MstBridgeUpdateContacts(MstBridgeID b, McdSpaceID space, MdtWorldID world);
/** The Hello and Goodbye pairs of a container: Hello orders the pair and picks its test (McdHello);
 *  Goodbye destroys its contact group and releases the test (McdGoodbye). */
ME_API void MstHandleTransitions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world, MstBridgeID b);
/** Nearfield tests for the Hello and Staying pairs of a container with at least one unfrozen model,
 *  and conversion of their contacts. */
ME_API void MstHandleCollisions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world, MstBridgeID b);
/** Karma 1.2's transitions stage on its own: ends the space's change block, reads every pair and
 *  handles only the Hello and Goodbye ones (MstHandleTransitions), opens a change block again. Call
 *  it after McdSpaceRemoveModel (and McdSpaceUpdateAll) and before destroying the model, so that the
 *  model's pairs say Goodbye and their contact groups go. */
ME_API void MstBridgeUpdateTransitions(MstBridgeID b, McdSpaceID s, MdtWorldID w);
/** The User Guide's name for the collisions stage on one container (decision D7). */
#define MstBridgeUpdateCollisions(b, s, w, pairs) MstHandleCollisions((pairs), (s), (w), (b))

/** Karma 1.2's whole step for a bridge made by MstUniverseCreate: MstUniverseStep of its universe
 *  (collision, contacts, then MdtWorldStep(world, stepSize)). A bridge made by MstBridgeCreate knows
 *  no space or world: the call is refused (ME_ERR_BAD_STATE). */
ME_API void MstBridgeStepAll(MstBridgeID bridge, MeReal stepSize);

/** Install the world handlers that keep models and bodies in step: a disabled body's models are
 *  frozen, an enabled body's unfrozen, and a destroyed contact group is unlinked from its pair.
 *  MstUniverseCreate does this; call it yourself when you build world, space and bridge by hand. */
ME_API void MstSetWorldHandlers(MdtWorldID world);

/** Link counts of the last MstBridgeUpdateContacts: pairs tested, contacts made. */
ME_API int MstBridgeGetLastPairCount(MstBridgeID b);
/** Contacts made by the last MstBridgeUpdateContacts; 0 for an invalid ID (reported). */
ME_API int MstBridgeGetLastContactCount(MstBridgeID b);

ME_EXTERN_C_END

#endif /* MST_BRIDGE_H */
