/* McdGeometryInstance.h -- Karma 1.2's geometry instances: a geometry placed in the world inside a
 * model. A model's root instance (McdModelGetGeometryInstance) stands for its geometry; an aggregate's
 * instance has one child per element slot (McdGeometryInstanceGetChild), taken from McdInit's
 * instanceCount pool. Instances are refreshed by the model's update (McdModelUpdate, the space's
 * update): world transform and AABB. Contacts with an aggregate name the child instance of the element
 * they touch in McdContact.element1 / element2 (cast to McdGeometryInstanceID).
 *
 * IDs are checked handles; a stale one is reported and ignored. Instances belong to their model's tree:
 * its geometry follows the model's (roots) or the aggregate's slot (children). */
#ifndef MCD_GEOMETRY_INSTANCE_H
#define MCD_GEOMETRY_INSTANCE_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Back to defaults: material 0, own transform (no pointer set). */
ME_API void McdGeometryInstanceReset(McdGeometryInstanceID ins);
/** The instance's geometry (NULL for an empty slot). */
ME_API McdGeometryID McdGeometryInstanceGetGeometry(McdGeometryInstanceID ins);
/** A root instance: McdModelSetGeometry of its model. A child follows its aggregate's slot: refused
 *  (ME_ERR_BAD_STATE; use McdAggregateAddElement / RemoveElement). */
ME_API void McdGeometryInstanceSetGeometry(McdGeometryInstanceID ins, McdGeometryID g);
/** A child: its world transform is written to geometryTM (the application's array) from the next
 *  update on; NULL: kept in the instance. A root's transform is the model's: refused (ME_ERR_BAD_STATE). */
ME_API void McdGeometryInstanceSetTransformPtr(const McdGeometryInstanceID ins, const MeMatrix4Ptr geometryTM);
/** The instance's world transform at the last update (a root: the model's geometry-to-world). */
ME_API MeMatrix4Ptr McdGeometryInstanceGetTransformPtr(McdGeometryInstanceID ins);
/** Bounding sphere in world coordinates (centre, radius). */
ME_API void McdGeometryInstanceGetBSphere(McdGeometryInstanceID ins, MeVector3 center, MeReal *radius);
/** Recompute the AABB from the current transform; with finalTM (not NULL, rigid) the box also holds
 *  the geometry at finalTM. `tight` is ignored: the boxes are always the tightest. */
ME_API void McdGeometryInstanceUpdateAABB(McdGeometryInstanceID ins, const MeMatrix4Ptr finalTM, MeBool tight);
/** The point of the placed geometry farthest along the world direction inDir. */
ME_API void McdGeometryInstanceMaximumPoint(McdGeometryInstanceID ins, MeReal *const inDir, MeReal *const outPoint);
/** The AABB at the last update (model's: without the contact tolerance). */
ME_API void McdGeometryInstanceGetAABB(McdGeometryInstanceID ins, MeVector3 minCorner, MeVector3 maxCorner);
/** Material of the instance (a root's: the model's, McdModelSetMaterial). */
ME_API void McdGeometryInstanceSetMaterial(McdGeometryInstanceID ins, int material);
/** The instance's material (a root's: the model's); 0 for an invalid ID (reported). */
ME_API unsigned int McdGeometryInstanceGetMaterial(McdGeometryInstanceID ins);
/** Child i (slot i of the instance's aggregate), or NULL (no such child, or not an aggregate). */
ME_API McdGeometryInstanceID McdGeometryInstanceGetChild(McdGeometryInstanceID ins, int i);
/** Whether the two instances' AABBs overlap. */
ME_API MeBool McdGeometryInstanceOverlap(McdGeometryInstanceID ins1, McdGeometryInstanceID ins2);
/** The type of the instance's geometry (kMcdGeometryTypeNull for an empty slot). */
ME_API McdGeometryType McdGeometryInstanceGetGeometryType(McdGeometryInstanceID ins);

ME_EXTERN_C_END

#endif /* MCD_GEOMETRY_INSTANCE_H */
