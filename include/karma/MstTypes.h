/* MstTypes.h -- the types of Karma's bridge (Mst): universe, its sizes, bridge, material.
 *
 * As in Karma 1.2, an MstUniverseID points to a struct whose fields a program may read
 * (`u->world`, `u->space`, `u->frame`, `u->bridge`, `u->sizes`); treat them as read-only: the
 * library keeps its own copy, so writing them changes nothing but what you read back. The universe
 * functions check the pointer against the table of live universes before they use it (docs/decisions.md,
 * B-universe), so a destroyed or made-up universe ID is reported, not dereferenced. An MstBridgeID is
 * a checked handle like the Mdt and Mcd IDs: `struct MstBridge` is never defined. */
#ifndef MST_TYPES_H
#define MST_TYPES_H

#include "McdTypes.h"
#include "MdtTypes.h"
#include "MeMemory.h"
#include "MePool.h"

ME_EXTERN_C_BEGIN

typedef struct MstUniverse MstUniverse;
typedef struct MstUniverseSizes MstUniverseSizes;
typedef struct MstBridge MstBridge;
typedef struct MstMaterialPair MstMaterialPair; /**< never defined here: use the MstBridge functions */

typedef MstUniverse *MstUniverseID;
typedef MstBridge *MstBridgeID;
/** A material: an index into the bridge's table, unsigned as in Karma 1.2. 0 is the default
 *  material; MST_MATERIAL_INVALID is what MstBridgeGetNewMaterial returns when the table is full. */
typedef unsigned int MstMaterialID;
/** No material: returned when a material cannot be made; refused by every bridge function. */
#define MST_MATERIAL_INVALID ((MstMaterialID)~0u)

/** Called once per colliding pair, after the nearfield test and before conversion (edit or cull
 *  result->contacts / contactCount here). */
typedef void (*MstIntersectCBPtr)(McdIntersectResult *result);
/** Called for each converted contact; return 0 to drop it. */
typedef MeBool (*MstPerContactCBPtr)(McdIntersectResult *result, McdContact *colC, MdtContactID dynC);
/** Called once per pair after conversion; return 0 to drop all the pair's contacts. */
typedef MeBool (*MstPerPairCBPtr)(McdIntersectResult *result, MdtContactGroupID contactGroup);

/** Every pool of a universe, in Karma 1.2's field order. Start from MstUniverseDefaultSizes and
 *  change what you need. Counts above INT_MAX are refused. */
struct MstUniverseSizes {
    unsigned int dynamicBodiesMaxCount;              /**< 100 */
    unsigned int dynamicConstraintsMaxCount;         /**< 500: joints and contacts together */
    unsigned int collisionUserGeometryTypesMaxCount; /**< 0 */
    unsigned int collisionModelsMaxCount;            /**< 100 */
    unsigned int collisionPairsMaxCount;             /**< 500 */
    unsigned int collisionGeometryInstancesMaxCount; /**< 100 (decision D5) */
    unsigned int materialsMaxCount;                  /**< 10 (at least 1: the default material) */
    MeReal lengthScale;                              /**< 1 */
    MeReal massScale;                                /**< 1 */
};

/** Karma's defaults (docs/karma12.md §8): `MstUniverseSizes s = MstUniverseDefaultSizes;` */
ME_API extern const MstUniverseSizes MstUniverseDefaultSizes;

/** What a program may read of a universe (Karma 1.2's fields, in its order). */
struct MstUniverse {
    MstUniverseSizes sizes; /**< as given to MstUniverseCreate */
    MdtWorldID world;       /**< the dynamics world */
    McdFrameworkID frame;   /**< the collision framework */
    McdSpaceID space;       /**< the farfield space */
    MstBridgeID bridge;     /**< the bridge between them */
};

ME_EXTERN_C_END

#endif /* MST_TYPES_H */
