/* MstUniverse.h -- the simplest way to use Karma: one object holding a collision framework, an
 * axis-sort space, a dynamics world and the bridge, sized once, stepped with one call.
 *
 *     MstUniverseSizes sizes = MstUniverseDefaultSizes;
 *     sizes.dynamicBodiesMaxCount = 200;
 *     MstUniverseID u = MstUniverseCreate(&sizes);
 *     ...
 *     MstUniverseStep(u, 1.0 / 60);   // McdSpaceUpdateAll, MstBridgeUpdateContacts, MdtWorldStep
 */
#ifndef MST_UNIVERSE_H
#define MST_UNIVERSE_H

#include "McdTypes.h"
#include "MdtTaskSystem.h"
#include "MdtTypes.h"
#include "MeProfile.h"
#include "MstBridge.h"
#include "MstTypes.h"

ME_EXTERN_C_BEGIN

/** Karma's defaults as a value (the same as the object MstUniverseDefaultSizes, MstTypes.h). */
ME_API MstUniverseSizes MstUniverseGetDefaultSizes(void);

/** Framework (primitive types and their pair tests registered), space on all three axes, world,
 *  bridge and the world handlers; NULL (reported) when a size is invalid or memory runs out. */
ME_API MstUniverseID MstUniverseCreate(const MstUniverseSizes *sizes);
/** Destroys every body, constraint and model of the universe, then the bridge, space, world and
 *  framework. Geometries belong to the framework and go with it. */
ME_API void MstUniverseDestroy(MstUniverseID u);
/** Whether u is a live universe ID (no message). */
ME_API MeBool MstUniverseIsValid(MstUniverseID u);
/** Exactly McdSpaceUpdateAll, MstBridgeUpdateContacts and MdtWorldStep(world, stepSize); a stepSize that
 *  is not finite or is below MDT_MIN_STEP_SIZE is refused (ME_ERR_STEP_SIZE) before anything runs. */
ME_API void MstUniverseStep(MstUniverseID u, MeReal stepSize);

/** Profile sections of the collision half of MstUniverseStep (the dynamics half is in the world's
 *  profile, MdtWorldGetProfile): "Collision" holds "Farfield" (McdSpaceUpdateAll) and "Nearfield"
 *  (MstBridgeUpdateContacts: pair tests and contact conversion). */
#define MST_SECTION_COLLISION "Collision"
#define MST_SECTION_FARFIELD "Farfield"
#define MST_SECTION_NEARFIELD "Nearfield"
/** The collision half's profile (the sections above). */
ME_API const MeProfile *MstUniverseGetProfile(MstUniverseID u);

/** The universe's parts (owned by it: do not destroy them; NULL, reported, for a bad ID). */
ME_API MdtWorldID MstUniverseGetWorld(MstUniverseID u);
/** The universe's space (owned by the universe: do not destroy it); NULL, reported, for a bad ID. */
ME_API McdSpaceID MstUniverseGetSpace(MstUniverseID u);
/** The universe's bridge (owned by the universe: do not destroy it); NULL, reported, for a bad ID. */
ME_API MstBridgeID MstUniverseGetBridge(MstUniverseID u);
/** The universe's collision framework (owned by the universe); NULL, reported, for a bad ID. */
ME_API McdFrameworkID MstUniverseGetFramework(MstUniverseID u);
/** Step the universe's dynamics on the application's task system (MdtTaskSystem.h): as
 *  MdtWorldSetTaskSystem on its world, refusals (ME_ERR_TASK_CALLBACK, ME_ERR_WORKER_COUNT,
 *  ME_ERR_WORLD_LOCKED) in this call's name, or in the world's caller name when the application set
 *  one. MeThreadPoolAttachUniverse (karma_threads) does it with the default pool. */
ME_API void MstUniverseSetTaskSystem(MstUniverseID u, int workerCount, MdtEnqueueTaskCBPtr enqueue,
                                     MdtFinishTaskCBPtr finish, void *user);

/** A model of `geometry` with a new, **enabled** body whose mass and inertia come from the geometry
 *  at `density` (kg/m³), linked, inserted into the space; NULL (reported) when a pool is full. */
ME_API McdModelID MstModelAndBodyCreate(MstUniverseID u, McdGeometryID geometry, MeReal density);
/** Removes the model from its space and destroys it and its body (and the body's constraints). */
ME_API void MstModelAndBodyDestroy(McdModelID model);
/** A static model (no body) at the transform `tm`, which must outlive the model: inserted, updated
 *  once and frozen. */
ME_API McdModelID MstFixedModelCreate(MstUniverseID u, McdGeometryID geometry, MeMatrix4Ptr tm);
/** Remove a model made by MstFixedModelCreate from its space and destroy it (as MstModelAndBodyDestroy). */
ME_API void MstFixedModelDestroy(McdModelID model);

/** Mass, inertia tensor and centre-of-mass offset of `body` from `model`'s geometry at `density`. */
ME_API void MstAutoSetMassProperties(MdtBodyID body, McdModelID model, MeReal density);
/** The inertia tensor of the model's body from its geometry, keeping the body's mass. */
ME_API void MstAutoSetInertialTensor(McdModelID model);

ME_EXTERN_C_END

#endif /* MST_UNIVERSE_H */
