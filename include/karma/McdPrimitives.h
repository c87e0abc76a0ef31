/* McdPrimitives.h -- Karma 1.2's per-type and per-pair names for the primitive geometries.
 *
 * Karma generated, for each geometry type T, T##GetTypeId, T##RegisterType, T##Destroy,
 * T##GetBSphere, T##GetMassProperties, T##GetTypeName and T##DebugDraw, and for each pair of types a
 * registration and an intersect function. Here the built-in types exist from McdInit on and the
 * generic calls do the work: the per-type functions below check the geometry's type and call the
 * generic ones; the per-pair names are macros onto McdPrimitivesRegisterInteractions (which
 * registers every primitive pair at once) and McdIntersect. T##UpdateAABB and T##MaximumPoint took
 * geometry instances: McdGeometryInstanceUpdateAABB / MaximumPoint do it for every type
 * (docs/api_changes.md). */
#ifndef MCD_PRIMITIVES_H
#define MCD_PRIMITIVES_H

#include "McdBox.h"
#include "McdCone.h"
#include "McdCylinder.h"
#include "McdFrame.h"
#include "McdGeometry.h"
#include "McdInteraction.h"
#include "McdNull.h"
#include "McdPlane.h"
#include "McdSphere.h"
#include "McdSphyl.h"

ME_EXTERN_C_BEGIN

/* Karma's per-type functions of each primitive T (Sphere, Box, ...): T##GetTypeId() gives the type
 * number; T##RegisterType(fw) has nothing to do (built in); T##Destroy is McdGeometryDestroy; the
 * others are the generic calls. Each refuses (ME_ERR_WRONG_HANDLE_KIND) a geometry of another type. */

/* The null type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The null type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdNullGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdNullRegisterType(McdFramework *frame);
/** Destroy a null geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdNullDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a null in its own frame; another type refused. */
ME_API void McdNullGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Non-zero always: a null has no finite mass (another type is also refused, ME_ERR_WRONG_HANDLE_KIND). */
ME_API MeI16 McdNullGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdNullGetTypeName(McdGeometryID g);
/** Draw a null at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdNullDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);

/* The sphere type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The sphere type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdSphereGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdSphereRegisterType(McdFramework *frame);
/** Destroy a sphere geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdSphereDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a sphere in its own frame; another type refused. */
ME_API void McdSphereGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Unit-density mass properties of a sphere (m³, m⁵); 0 on success, non-zero for another type (reported). */
ME_API MeI16 McdSphereGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdSphereGetTypeName(McdGeometryID g);
/** Draw a sphere at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdSphereDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);

/* The box type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The box type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdBoxGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdBoxRegisterType(McdFramework *frame);
/** Destroy a box geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdBoxDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a box in its own frame; another type refused. */
ME_API void McdBoxGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Unit-density mass properties of a box (m³, m⁵); 0 on success, non-zero for another type (reported). */
ME_API MeI16 McdBoxGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdBoxGetTypeName(McdGeometryID g);
/** Draw a box at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdBoxDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);

/* The plane type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The plane type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdPlaneGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdPlaneRegisterType(McdFramework *frame);
/** Destroy a plane geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdPlaneDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a plane in its own frame; another type refused. */
ME_API void McdPlaneGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Non-zero always: a plane has no finite mass (another type is also refused, ME_ERR_WRONG_HANDLE_KIND). */
ME_API MeI16 McdPlaneGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdPlaneGetTypeName(McdGeometryID g);
/** Draw a plane at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdPlaneDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);

/* The cylinder type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The cylinder type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdCylinderGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdCylinderRegisterType(McdFramework *frame);
/** Destroy a cylinder geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdCylinderDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a cylinder in its own frame; another type refused. */
ME_API void McdCylinderGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Unit-density mass properties of a cylinder (m³, m⁵); 0 on success, non-zero for another type (reported). */
ME_API MeI16 McdCylinderGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdCylinderGetTypeName(McdGeometryID g);
/** Draw a cylinder at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdCylinderDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);

/* The sphyl type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The sphyl type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdSphylGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdSphylRegisterType(McdFramework *frame);
/** Destroy a sphyl geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdSphylDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a sphyl in its own frame; another type refused. */
ME_API void McdSphylGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Unit-density mass properties of a sphyl (m³, m⁵); 0 on success, non-zero for another type (reported). */
ME_API MeI16 McdSphylGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdSphylGetTypeName(McdGeometryID g);
/** Draw a sphyl at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdSphylDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);

/* The cone type's number and its per-type functions (Karma 1.2's names; the generic calls do the same). */
/** The cone type's number (kMcdGeometryType...), the same in every framework. */
ME_API MeI16 McdConeGetTypeId(void);
/** Register every primitive type and pair test with frame (as McdPrimitivesRegisterTypes). */
ME_API void McdConeRegisterType(McdFramework *frame);
/** Destroy a cone geometry (McdGeometryDestroy); another type refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdConeDestroy(McdGeometryID g);
/** Bounding sphere (centre and radius, m) of a cone in its own frame; another type refused. */
ME_API void McdConeGetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius);
/** Unit-density mass properties of a cone (m³, m⁵); 0 on success, non-zero for another type (reported). */
ME_API MeI16 McdConeGetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The type's name (static string, not to be freed); NULL for another type (ME_ERR_WRONG_HANDLE_KIND). */
ME_API char *McdConeGetTypeName(McdGeometryID g);
/** Draw a cone at tm through MeDebugDrawAPI (colour NULL: white); another type refused. */
ME_API void McdConeDebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3]);


/** Karma's partial registrations: every primitive type and pair test is registered here. */
#define McdSphereBoxPlaneRegisterTypes(frame) ((void)McdPrimitivesRegisterTypes(frame))
#define McdSphereBoxPlaneRegisterInteractions(frame) ((void)McdPrimitivesRegisterInteractions(frame))
#define McdConePrimitivesRegisterInteractions(frame) McdPrimitivesRegisterInteractions(frame)

/* Per pair: registration (all primitive pairs at once) and the test itself (McdIntersect, after
 * McdHello as in Karma). */
#define McdSphereSphereRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdSpherePlaneRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdBoxSphereRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdBoxBoxRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdBoxPlaneRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdCylinderSphereRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdCylinderCylinderRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdBoxCylinderRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdCylinderPlaneRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdSphylPlaneRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdSphylSphereRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdSphylSphylRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdSphylBoxRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdSphylCylinderRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdConePlaneRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdConeSphereRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdConeBoxRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdConeConeRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)
#define McdConeCylinderRegisterInteraction(frame) McdPrimitivesRegisterInteractions(frame)

#define McdSphereSphereIntersect(p, result) McdIntersect((p), (result))
#define McdSpherePlaneIntersect(p, result) McdIntersect((p), (result))
#define McdBoxSphereIntersect(p, result) McdIntersect((p), (result))
#define McdBoxBoxIntersect(p, result) McdIntersect((p), (result))
#define McdBoxPlaneIntersect(p, result) McdIntersect((p), (result))
#define McdCylinderSphereIntersect(p, result) McdIntersect((p), (result))
#define McdCylinderCylinderIntersect(p, result) McdIntersect((p), (result))
#define McdBoxCylinderIntersect(p, result) McdIntersect((p), (result))
#define McdCylinderPlaneIntersect(p, result) McdIntersect((p), (result))
#define McdSphylPlaneIntersect(p, result) McdIntersect((p), (result))
#define McdSphylSphereIntersect(p, result) McdIntersect((p), (result))
#define McdSphylSphylIntersect(p, result) McdIntersect((p), (result))
#define McdSphylBoxIntersect(p, result) McdIntersect((p), (result))
#define McdSphylCylinderIntersect(p, result) McdIntersect((p), (result))
#define McdConePlaneIntersect(p, result) McdIntersect((p), (result))
#define McdConeSphereIntersect(p, result) McdIntersect((p), (result))
#define McdConeBoxIntersect(p, result) McdIntersect((p), (result))
#define McdConeConeIntersect(p, result) McdIntersect((p), (result))
#define McdConeCylinderIntersect(p, result) McdIntersect((p), (result))

/* Line segments need no registration here (every primitive answers McdLineSegIntersect). */
#define McdSphereLineSegmentRegisterInteraction(frame) McdPrimitivesRegisterTypes(frame)
#define McdBoxLineSegmentRegisterInteraction(frame) McdPrimitivesRegisterTypes(frame)
#define McdPlaneLineSegmentRegisterInteraction(frame) McdPrimitivesRegisterTypes(frame)
#define McdCylinderLineSegmentRegisterInteraction(frame) McdPrimitivesRegisterTypes(frame)
#define McdSphylLineSegmentRegisterInteraction(frame) McdPrimitivesRegisterTypes(frame)
#define McdConeLineSegmentRegisterInteraction(frame) McdPrimitivesRegisterTypes(frame)

ME_EXTERN_C_END

#endif /* MCD_PRIMITIVES_H */
