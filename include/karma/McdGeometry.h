/* McdGeometry.h -- what every geometry can do, whatever its type.
 *
 * A geometry is a shape in its own local frame; models place it in the world. Geometries are shared
 * by any number of models and are reference counted: McdGeometryDestroy refuses (ME_ERR_MCD_IN_USE)
 * while a model still uses the geometry. Changing a geometry's dimensions takes effect for its models
 * at their next update (McdModelUpdate or McdSpaceUpdateAll).
 *
 * Mass properties are for unit density (mass = volume); scale by the density. */
#ifndef MCD_GEOMETRY_H
#define MCD_GEOMETRY_H

#include "McdFrame.h"
#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Destroy a geometry that no model uses; refused (ME_ERR_MCD_IN_USE) while referenced. */
ME_API void McdGeometryDestroy(McdGeometryID g);
/** Whether g is a live geometry ID (no message). */
ME_API MeBool McdGeometryIsValid(McdGeometryID g);
/** The type number (McdGeometryType or a user type), or -1 for a bad ID. */
ME_API int McdGeometryGetTypeId(McdGeometryID g);
/** Karma's second name for McdGeometryGetTypeId. */
ME_API int McdGeometryGetType(McdGeometryID g);
/** The type's name (static string, not to be freed); NULL for an invalid ID (reported). */
ME_API const char *McdGeometryGetTypeName(McdGeometryID g);
/** Holds on the geometry: models (and aggregates) using it plus references the application took.
 *  McdGeometryDestroy is refused while it is above 0. */
ME_API int McdGeometryGetReferenceCount(McdGeometryID g);
/** Take and release a reference of the application's (models take theirs themselves). Releasing
 *  one that was not taken is refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void McdGeometryIncrementReferenceCount(McdGeometryID g);
/** Release a reference the application took; none held refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void McdGeometryDecrementReferenceCount(McdGeometryID g);
/** Set the count (the models' holds plus the application's); below the models' holds is refused. */
ME_API void McdGeometrySetReferenceCount(McdGeometryID g, int refCount);
/** The segment test of the geometry's type in Karma's form, or NULL when the type has none. */
ME_API McdLineSegIntersectFnPtr McdGeometryGetLineSegIntersectFnPtr(McdGeometryID g);
/** The framework whose pool holds the geometry; NULL for an invalid ID (reported). */
ME_API McdFrameworkID McdGeometryGetFramework(McdGeometryID g);

/** The tightest world axis-aligned box of the geometry placed at `tm` (NULL: identity). Unbounded
 *  directions (planes) give -MEINFINITY / MEINFINITY. */
ME_API void McdGeometryGetAABB(McdGeometryID g, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner);
/** A bounding sphere in the local frame (centre, radius); MEINFINITY for unbounded geometries. */
ME_API void McdGeometryGetBSphere(McdGeometryID g, MeVector3 centre, MeReal *radius);
/** Support point: a point of the geometry placed at `tm` (NULL: identity) farthest along the world
 *  direction `dir`. A plane's support goes 1e15 far (finite) in its unbounded directions. */
ME_API void McdGeometryMaximumPoint(McdGeometryID g, MeMatrix4 tm, const MeVector3 dir, MeVector3 point);
/** Unit-density mass properties: `relTM` (may be NULL) receives the centre-of-mass frame in the
 *  local frame (identity for the primitives: their origin is their centre of mass), `inertia` the
 *  tensor about the centre of mass, `volume` the volume. Returns 0 on success (Karma's convention);
 *  non-zero for geometries without finite mass (planes, null) or bad arguments. */
ME_API MeI16 McdGeometryGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** Draw through the type's debugDraw, if it has one. */
ME_API void McdGeometryDebugDraw(McdGeometryID g, MeMatrix4 tm, const float colour[3]);

/* ---- user geometry types (see McdFrameworkRegisterUserGeometryType in McdFrame.h) ------------------ */

/** Create a geometry of a registered user type holding the application's shape `data`. */
ME_API McdGeometryID McdUserGeometryCreate(McdFrameworkID fw, int type, void *data);
/** The shape data of a user geometry (NULL for built-in types). */
ME_API void *McdUserGeometryGetData(McdGeometryID g);

ME_EXTERN_C_END

#endif /* MCD_GEOMETRY_H */
