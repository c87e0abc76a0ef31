/* McdFrame.h -- the collision framework: type and interaction tables, pools, defaults.
 *
 * McdInit creates a framework: a pool of `modelCount` models, a pool of geometries, room for
 * `geoTypeMaxCount` user geometry types besides the built-in ones, and the interaction table of pair
 * tests. The built-in types (Null, Sphere, Box, Plane, Cylinder, Sphyl, Cone) are always known;
 * McdPrimitivesRegisterTypes is kept for Karma code and does nothing more. Pair tests are added by
 * McdPrimitivesRegisterInteractions (all primitive pairs); a pair of types without a test gives no
 * contacts and is reported once.
 *
 * Defaults: contact tolerance 0.005 * lengthScale (docs/decisions.md), request {contactMaxCount 4,
 * faceNormalsFirst 0}. */
#ifndef MCD_FRAME_H
#define MCD_FRAME_H

#include "McdLineSegment.h"
#include "McdTypes.h"
#include "MeMemory.h"

ME_EXTERN_C_BEGIN

/* A library built with the other precision does not have this symbol: link errors, not corruption. */
#define McdInit ME_PRECISION_SYMBOL(McdInit)

/** Create a framework. `geoTypeMaxCount` user geometry types may be registered besides the
 *  built-in ones; `modelCount` models and geometries may exist at once; `instanceCount` is the
 *  size of the geometry-instance pool (aggregate children); `lengthScale` (> 0) is a typical object
 *  size from which the default contact tolerance derives. NULL (reported) on bad arguments. */
ME_API McdFrameworkID McdInit(int geoTypeMaxCount, int modelCount, int instanceCount, MeReal lengthScale);
/** Run the registered term actions (last registered first), then free every model and geometry. */
ME_API void McdTerm(McdFrameworkID fw);
/** Whether fw is a live framework ID (no message). */
ME_API MeBool McdFrameworkIsValid(McdFrameworkID fw);

/** Called by McdTerm before anything is freed (spaces, bridges and user code tidy up here). */
typedef void (*McdFrameworkTermActionFn)(McdFrameworkID fw, void *data);
/** Karma's form: register `action` (McdTermAction: the framework only) to run at McdTerm; at most
 *  16 term actions of either form per framework (reported when full). */
ME_API void McdFrameworkRegisterTermAction(McdFrameworkID fw, McdTermAction action);
/** Our form, with a pointer handed back to `fn`. Returns METRUE when registered. */
ME_API MeBool McdFrameworkAddTermAction(McdFrameworkID fw, McdFrameworkTermActionFn fn, void *data);
/** Destroy every model (taking it out of its space first: its pairs say Goodbye at the space's next
 *  McdSpaceEndChanges) and then every geometry of the framework, whatever references they hold. */
ME_API void McdFrameworkDestroyAllModelsAndGeometries(McdFrameworkID fw);

/** The framework's lengthScale (metres), as given to McdInit. */
ME_API MeReal McdFrameworkGetLengthScale(McdFrameworkID fw);

/** What the framework's pair tests and segment queries could not do exactly, since McdInit. Every
 *  count is of an answer that was replaced by a defined one, never handed on: */
typedef struct McdFrameworkCounters {
    unsigned long pairFallbacks;    /**< pair tests whose arithmetic degenerated (NaN, overflow) and
                                         that gave no contact or took the general path instead */
    unsigned long droppedContacts;  /**< contacts dropped on their way out of McdIntersect because a
                                         value was not finite or the normal not of unit length */
    unsigned long segmentFallbacks; /**< segment queries whose hit was not finite: reported as a miss */
} McdFrameworkCounters;
/** Copy the framework's counters into *counters (not NULL; reported and left unchanged otherwise).
 *  An addition (docs/api_changes.md). */
ME_API void McdFrameworkGetCounters(McdFrameworkID fw, McdFrameworkCounters *counters);
/** Contact tolerance given to new models (>= 0, finite). */
ME_API void McdFrameworkSetDefaultContactTolerance(McdFrameworkID fw, MeReal tolerance);
/** Contact tolerance given to new models (m); 0 for an invalid ID (reported). */
ME_API MeReal McdFrameworkGetDefaultContactTolerance(McdFrameworkID fw);
/** What "pool full" messages tell the application to raise (strings that outlive the framework, such as
 *  literals; a NULL one keeps its current name): the model pool, the geometry pool, the user types; for
 *  a layer that made the framework on the application's behalf (MstUniverseCreate). */
ME_API void McdFrameworkSetSizeNames(McdFrameworkID fw, const char *models, const char *geometries, const char *types);
/** The request used by pairs whose `request` is NULL; the application may change it in place. */
ME_API McdRequest *McdFrameworkGetDefaultRequestPtr(McdFrameworkID fw);
/** Make `request` (the application's; it must outlive its use) the default request; NULL restores
 *  the framework's own. */
ME_API void McdFrameworkSetDefaultRequestPtr(McdFrameworkID fw, McdRequest *request);
/** Number of live models in the framework's pool; 0 for an invalid ID (reported). */
ME_API int McdFrameworkGetModelCount(McdFrameworkID fw);
/** Number of live models of the framework with an intersect callback (McdModelSetIntersectCallback);
 *  0 for an invalid ID (reported). For a bridge that must know whether pair tests call the
 *  application (Mst runs them beside its conversion only when none do). An addition. */
ME_API int McdFrameworkGetIntersectCallbackCount(McdFrameworkID fw);
/** Number of live geometries in the framework's pool; 0 for an invalid ID (reported). */
ME_API int McdFrameworkGetGeometryCount(McdFrameworkID fw);
/** Size of the model pool given to McdInit; 0 for an invalid ID (reported). */
ME_API int McdFrameworkGetInstanceMaxCount(McdFrameworkID fw);

/* ---- geometry types ------------------------------------------------------------------------ */

/** The protocol every geometry type follows (built-in types too). `data` is the geometry's shape
 *  data: for a user type, the pointer given to McdUserGeometryCreate. Local frame = the geometry's
 *  own frame (origin at its centre of mass for the built-in types). */
typedef struct McdGeometryTypeDesc {
    const char *typeName; /**< required; a string literal (kept, not copied) */
    /** Release the shape data (optional; called by McdGeometryDestroy and McdTerm). */
    void (*destroy)(McdGeometryID g, void *data);
    /** Required: the tightest axis-aligned box of the geometry placed at `tm` (world). */
    void (*getAABB)(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner);
    /** Required: a sphere (local centre, radius) containing the geometry. */
    void (*getBSphere)(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius);
    /** Required: the support ("maximum") point: a local point of the geometry farthest along the
     *  local direction `dir` (not necessarily unit). */
    void (*maximumPoint)(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point);
    /** Required: mass properties for unit density: `relTM` = the centre-of-mass frame in the local
     *  frame, `inertia` about the centre of mass in that frame's axes, `volume`. */
    void (*getMassProperties)(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
    /** Optional (NULL: segments never hit): first entry of the local segment p0 -> p1. Returns
     *  non-zero on a hit with *t in [0, 1] (0 when p0 is inside) and the local outward unit normal. */
    int (*lineSegIntersect)(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                            MeVector3 normal);
    /** Optional: draw the geometry at `tm` (debug viewers). */
    void (*debugDraw)(McdGeometryID g, void *data, MeMatrix4 tm, const float colour[3]);
} McdGeometryTypeDesc;

/** Register a user geometry type (Karma's McdFrameworkRegisterGeometryType took nine arguments and
 *  a struct embedded in the user's; see docs/api_changes.md). Returns its type number
 *  (>= kMcdGeometryBuiltInTypes), or -1 (reported) when `geoTypeMaxCount` types are already
 *  registered or a required function is NULL. */
ME_API int McdFrameworkRegisterUserGeometryType(McdFrameworkID fw, const McdGeometryTypeDesc *desc);
/** Number of geometry type numbers in use (built-in and user; kMcdGeometryBuiltInTypes with no
 *  user type). */
ME_API MeI16 McdFrameworkGetRegisteredTypeCount(McdFrameworkID fw);
/** Name of a registered type number, or NULL when unknown. */
ME_API const char *McdFrameworkGetTypeName(McdFrameworkID fw, int typeId);
/** Whether `typeId` names a registered type. */
ME_API MeBool McdFrameworkTypeIsRegistered(McdFrameworkID fw, int typeId);
/** Whether `typeId` is a number the framework has room for (registered or not). */
ME_API MeBool McdFrameworkTypeIsValid(McdFrameworkID fw, int typeId);
/** List the registered types through MeInfo. */
ME_API void McdFrameworkShowTypes(McdFrameworkID fw);
/** Print which pairs of types have a test, through MeInfo. */
ME_API void McdFrameworkPrintInteractionTable(McdFramework *fw);
/** Whether "no test for this pair of types" has been reported (non-zero) and set it (0: report
 *  again at the next such pair). The order of the two types does not matter. */
ME_API void McdFrameworkSetInteractionsWarned(McdFramework *fw, int geoType1, int geoType2, int count);
/** Non-zero once "no test for this pair of types" has been reported; 0 for bad types (reported). */
ME_API int McdFrameworkGetInteractionsWarned(McdFramework *fw, int geoType1, int geoType2);
/** The table's entry for (geoType1, geoType2), refreshed at each call (see McdInteractions in
 *  McdTypes.h); the pointer stays valid until McdTerm. NULL (reported) for unknown types. */
ME_API McdInteractions *McdFrameworkGetInteractions(McdFramework *fw, int geoType1, int geoType2);
/** Replace the segment test of a type (NULL: back to the built-in one). */
ME_API void McdFrameworkSetLineSegInteraction(McdFramework *fw, int geoType, McdLineSegIntersectFnPtr isectfn);
/** The segment test of a type: the one set, the built-in one, or NULL when the type has none. */
ME_API McdLineSegIntersectFnPtr McdFrameworkGetLineSegInteraction(McdFramework *fw, int geoType);

/** A pair test written by the application (for user types): contacts between g1 at tm1 and g2 at
 *  tm2 (world), normals from g2 towards g1, separation < 0 when overlapping, only contacts with
 *  separation <= tolerance; at most maxContacts written; returns the count. `data` as in the
 *  geometry protocol (the user's pointer for user types, the shape data for built-in ones). */
typedef int (*McdUserIntersectFn)(McdGeometryID g1, void *data1, MeMatrix4 tm1, McdGeometryID g2, void *data2,
                                  MeMatrix4 tm2, MeReal tolerance, McdContact *contacts, int maxContacts);
/** Register `fn` as the pair test of (type1, type2), taking its models in that order (McdHello
 *  handles pairs the other way round); NULL removes it. METRUE when both types are registered. */
ME_API MeBool McdFrameworkSetUserInteraction(McdFrameworkID fw, int type1, int type2, McdUserIntersectFn fn);

/** Karma's registration calls. The built-in types are always registered (these return METRUE);
 *  McdPrimitivesRegisterInteractions adds the pair tests of every pair of primitives. */
ME_API MeBool McdPrimitivesRegisterTypes(McdFrameworkID fw);
/** Register the pair tests of every pair of primitive types; MEFALSE (reported) for an invalid ID. */
ME_API MeBool McdPrimitivesRegisterInteractions(McdFrameworkID fw);
/** Number of primitive types (Null, Sphere, Box, Plane, Cylinder, Sphyl, Cone). */
ME_API int McdPrimitivesGetTypeCount(void);

ME_EXTERN_C_END

#endif /* MCD_FRAME_H */
