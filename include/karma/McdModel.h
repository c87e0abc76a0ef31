/* McdModel.h -- a geometry placed in the world: the object collision works with.
 *
 * A model holds a geometry, a transform and what the pair tests and the bridge need: a contact
 * tolerance (AABB padding: contacts are reported up to this separation), a material, a sort key (the
 * deterministic order of pairs), user data and an optional body (set by the bridge).
 *
 * Transform: a model either follows a transform owned elsewhere (McdModelSetTransformPtr, e.g. a
 * body's MdtBodyGetTransformPtr) or keeps its own (the default, identity; write it through the
 * pointer McdModelGetTransformPtr returns). An optional relative transform places the geometry in
 * that frame: geometry-to-world = relative * transform. McdModelUpdate (or McdSpaceUpdateAll for
 * models in a space) compounds them and refreshes the AABB; the pair tests and line segment queries
 * use the transform of the last update. */
#ifndef MCD_MODEL_H
#define MCD_MODEL_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Largest sort key (Karma's 15 bits). */
#define MCD_MODEL_SORT_KEY_MAX 32767

/** A model of `geometry` from the framework's model pool; NULL (reported) when full. */
ME_API McdModelID McdModelCreate(McdGeometryID geometry);
/** Destroy a model that is in no space (refused with ME_ERR_MCD_IN_USE otherwise). */
ME_API void McdModelDestroy(McdModelID m);
/** Restore every setting to its default (own identity transform, no relative transform, default
 *  tolerance, material 0, sort key 0, no user data, no body, no callbacks or velocity pointers,
 *  request ID 0); keeps the geometry and the space. */
ME_API void McdModelReset(McdModelID m);
/** Whether m is a live model ID (no message). */
ME_API MeBool McdModelIsValid(McdModelID m);
/** The framework whose pool holds the model; NULL for an invalid ID (ME_ERR_INVALID_HANDLE). */
ME_API McdFrameworkID McdModelGetFramework(McdModelID m);

/** The model's shape: set (the geometry's reference count follows; NULL refused) and get. */
ME_API void McdModelSetGeometry(McdModelID m, McdGeometryID geometry);
/** The model's geometry (shared, reference-counted: not owned by the caller); NULL for an invalid ID. */
ME_API McdGeometryID McdModelGetGeometry(McdModelID m);
/** The root of the model's geometry-instance tree (McdGeometryInstance.h: an aggregate's children
 *  hang under it); NULL for an invalid ID (reported). */
ME_API McdGeometryInstanceID McdModelGetGeometryInstance(McdModelID m);

/** Follow the transform at `tm` (it must outlive the model's use of it); NULL: the model's own. */
ME_API void McdModelSetTransformPtr(McdModelID m, MeMatrix4Ptr tm);
/** The transform followed: the pointer given, or the model's own (never NULL for a valid model). */
ME_API MeMatrix4Ptr McdModelGetTransformPtr(McdModelID m);
/** Place the geometry at `relTM` (a rigid transform) in the model's transform; NULL: none. */
ME_API void McdModelSetRelativeTransform(McdModelID m, MeMatrix4 relTM);
/** The relative transform, or NULL when none is set. The pointer is into the model (models do not
 *  move) or the one given to McdModelSetRelativeTransformPtrs; it is valid until the model is
 *  destroyed or its relative transform changed. */
ME_API MeMatrix4Ptr McdModelGetRelativeTransform(McdModelID m);
/** Karma's pointer form: the model follows `refTM` (as McdModelSetTransformPtr), reads its relative
 *  transform from `relTM` at each update (NULL: none) and writes the geometry-to-world transform
 *  into `compoundTM` at each update (NULL: nowhere). The matrices stay the caller's (`own` is
 *  accepted and ignored: nothing is freed with the model). */
ME_API void McdModelSetRelativeTransformPtrs(McdModelID m, MeMatrix4 relTM, MeMatrix4 refTM, MeMatrix4 compoundTM,
                                             MeBool own);
/** The relative transform followed (NULL when none) and the transform followed. */
ME_API void McdModelGetRelativeTransformPtrs(McdModelID m, MeMatrix4Ptr *relTM, MeMatrix4Ptr *refTM);
/** Geometry-to-world transform of the last update. */
ME_API void McdModelGetWorldTransform(McdModelID m, MeMatrix4 tm);

/** Distance (metres, >= 0, finite) within which the pair tests report contacts for this model. */
ME_API void McdModelSetContactTolerance(McdModelID m, MeReal tolerance);
/** Contact tolerance (m); 0 for an invalid ID. */
ME_API MeReal McdModelGetContactTolerance(McdModelID m);
/** Material index (>= 0) for the bridge's material table. */
ME_API void McdModelSetMaterial(McdModelID m, int material);
/** Material index; 0 for an invalid ID. */
ME_API int McdModelGetMaterial(McdModelID m);
/** Order key of the model's pairs (0 ... MCD_MODEL_SORT_KEY_MAX); outside that range refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void McdModelSetSortKey(McdModelID m, int key);
/** The model's sort key; 0 for an invalid ID. */
ME_API int McdModelGetSortKey(McdModelID m);
/** Attach an application pointer (not owned: Mcd never frees or follows it). */
ME_API void McdModelSetUserData(McdModelID m, void *data);
/** The application pointer of McdModelSetUserData (owned by the application); NULL if none. */
ME_API void *McdModelGetUserData(McdModelID m);
/* The model's dynamics body: McdModelSetBody / McdModelGetBody belong to the bridge (MstBridge.h),
 * since Mcd knows nothing of Mdt. */
/** Karma's raw body slot (the bridge's McdModelSetBody fills it too): an untyped pointer that Mcd
 *  stores and never follows. */
ME_API void *McdModelGetBodyData(McdModelID m);
/** Store an untyped body pointer (not owned, never followed); invalid model refused. */
ME_API void McdModelSetBodyData(McdModelID m, void *body);

/** The type number of the model's geometry. */
ME_API McdGeometryType McdModelGetGeometryType(McdModelID m);
/** Called first by each update of the model (McdModelUpdate, McdSpaceUpdateAll...); an update the
 *  callback itself makes does not call it again. NULL: none (the default). */
ME_API void McdModelSetUpdateCallback(McdModelID m, McdModelUpdateFnPtr fn);
/** The callback set by McdModelSetUpdateCallback, or NULL. */
ME_API McdModelUpdateFnPtr McdModelGetUpdateCallback(McdModelID m);
/** Called by McdIntersect, for each model of the pair that has one, with the pair's result. */
ME_API void McdModelSetIntersectCallback(McdModelID m, McdModelIntersectFnPtr fn);
/** The callback set by McdModelSetIntersectCallback, or NULL. */
ME_API McdModelIntersectFnPtr McdModelGetIntersectCallback(McdModelID m);
/** The model's class for McduRequestTable (>= 0; McdModelGetDefaultRequestID() at creation). */
ME_API void McdModelSetRequestID(McdModelID m, int requestId);
/** The model's class for McduRequestTable; 0 for an invalid ID. */
ME_API int McdModelGetRequestID(McdModelID m);
/** The request ID models start with. */
#define McdModelGetDefaultRequestID() (0)
/** Where the model's velocities live (e.g. a body's): kept for the safe-time queries to come;
 *  NULL (the default) means at rest. Mcd stores the pointers and does not read them yet. */
ME_API void McdModelSetLinearVelocityPtr(McdModelID m, MeReal *velocity);
/** The linear velocity pointer given (m/s; owned by the caller who set it), or NULL. */
ME_API MeReal *McdModelGetLinearVelocityPtr(McdModelID m);
/** Where the model's angular velocity (rad/s) lives; the pointer is stored, not owned (NULL: at rest). */
ME_API void McdModelSetAngularVelocityPtr(McdModelID m, MeReal *velocity);
/** The angular velocity pointer given (rad/s; owned by the caller who set it), or NULL. */
ME_API MeReal *McdModelGetAngularVelocityPtr(McdModelID m);

/** Compound the relative transform with the transform (the geometry-to-world transform). */
ME_API void McdModelCompoundTransforms(McdModelID m);
/** Compound the transforms and recompute the AABB (padded by the contact tolerance). */
ME_API void McdModelUpdate(McdModelID m);
/** AABB of the last update (padded by the contact tolerance). */
ME_API void McdModelGetAABB(McdModelID m, MeVector3 minCorner, MeVector3 maxCorner);
/** World bounding sphere at the last update. */
ME_API void McdModelGetBSphere(McdModelID m, MeVector3 centre, MeReal *radius);
/** Unit-density mass properties in the model's frame (the body frame): the centre of mass `com`,
 *  the inertia about it in the model's axes (the relative transform applied), the volume. */
ME_API MeBool McdModelGetMassProperties(McdModelID m, MeVector3 com, MeMatrix3 inertia, MeReal *volume);
/** The space the model is in, or NULL. */
ME_API McdSpaceID McdModelGetSpace(McdModelID m);

ME_EXTERN_C_END

#endif /* MCD_MODEL_H */
