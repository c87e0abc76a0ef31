/* McdConvexMesh.h -- a convex polyhedron (the hull of a point cloud), optionally rounded by a
 * "fatness" radius (every point within `fatness` of the polyhedron belongs to the solid).
 *
 * The vertices stay in the frame they were given in (as Karma 1.2): the geometry's origin is the
 * cloud's origin, and McdGeometryGetMassProperties gives the centre of mass in relTM[3]. Polygons are
 * the hull's faces with coplanar triangles merged (tolerance: docs/collision.md, "Convex meshes"), or
 * the faces of the McdConvexHull given to McdConvexMeshCreate, their vertices counter-clockwise seen
 * from outside. */
#ifndef MCD_CONVEX_MESH_H
#define MCD_CONVEX_MESH_H

#include "McdQHullTypes.h"
#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** The hull of `vertexCount` points (local frame, m), rounded by fatnessRadius (m, >= 0). Points
 *  inside or within the tolerance of the hull are dropped. NULL and a report when the points are
 *  fewer than four or span no volume (ME_ERR_MCD_HULL_FLAT), not finite (ME_ERR_NONFINITE_ARGUMENT),
 *  too small or far (ME_ERR_MCD_SIZE_RANGE), or the fatness is negative or out of range. */
ME_API McdConvexMeshID McdConvexMeshCreateHull(McdFrameworkID fw, const MeVector3 *vertices, int vertexCount,
                                               MeReal fatnessRadius);
/** The convex mesh of a hull given as 1.2's arrays (computed by McdComputeHull or filled by the
 *  application), rounded by fatness (m, >= 0). The geometry takes the arrays over (1.2's shallow copy:
 *  do not free them; McdConvexMeshGetPolyhedron gives them back) and collides with the hull rebuilt
 *  from their vertices. Refused, NULL, the arrays still the caller's: a NULL poly or array, counts,
 *  indices or adjacency that disagree (ME_ERR_MCD_HULL_INCONSISTENT), NaN (ME_ERR_NONFINITE_ARGUMENT),
 *  a hull not convex within 1e-4 of its vertices' bounding-box diagonal (ME_ERR_MCD_HULL_NOT_CONVEX), and what
 *  McdConvexMeshCreateHull refuses. */
ME_API McdConvexMeshID McdConvexMeshCreate(McdFrameworkID fw, McdConvexHull *poly, MeReal fatness);
/** A sphyl (capsule along z: cylinder part `height` >= 0, caps of `radius` > 0, m) as a rounded
 *  polyhedron (within 1e-3 radius + 1e-5 height of the true surface); mass properties exact. */
ME_API McdConvexMeshID McdConvexMeshCreateSphyl(McdFrameworkID fw, MeReal radius, MeReal height);
/** Destroy a convex mesh (McdGeometryDestroy); another type is refused (ME_ERR_WRONG_HANDLE_KIND). */
ME_API void McdConvexMeshDestroy(McdConvexMeshID g);
/** Number of polygons (faces) of the hull; 0 for an invalid ID or another type (reported). */
ME_API int McdConvexMeshGetPolygonCount(McdConvexMeshID g);
/** Number of vertices (= edges) of polygon polyID; 0 when polyID is out of range (reported). */
ME_API int McdConvexMeshGetPolygonVertexCount(McdConvexMeshID g, int polyID);
/** Copy vertex vertexID (counter-clockwise from outside) of polygon polyID (local, m); indices out
 *  of range are refused (ME_ERR_ARGUMENT_RANGE) and coords left unchanged. */
ME_API void McdConvexMeshGetPolygonVertex(McdConvexMeshID g, int polyID, int vertexID, MeVector3 coords);
/** Pointer to vertex vertexID of polygon polyID (valid until the mesh is destroyed); NULL when out of range. */
ME_API const MeReal *McdConvexMeshGetPolygonVertexPtr(McdConvexMeshID g, int polyID, int vertexID);
/** Outward unit normal of polygon polyID (local); out of range refused, normal left unchanged. */
ME_API void McdConvexMeshGetPolygonNormal(McdConvexMeshID g, int polyID, MeVector3 normal);
/** The mesh's hull as 1.2's arrays (owned by the mesh, valid until it is destroyed; its polygon and
 *  vertex numbers are the accessors'); NULL for an invalid ID or another type (reported). */
ME_API const McdConvexHull *McdConvexMeshGetPolyhedron(McdConvexMeshID g);
/** Number of distinct hull vertices (ours: 1.2 reached them through its McdConvexHull); 0 when invalid. */
ME_API int McdConvexMeshGetVertexCount(McdConvexMeshID g);
/** Copy hull vertex `index` (local, m); out of range refused (ME_ERR_ARGUMENT_RANGE). */
ME_API void McdConvexMeshGetVertex(McdConvexMeshID g, int index, MeVector3 position);
/** The rounding radius (m) given at creation; 0 for an invalid ID or another type (reported). */
ME_API MeReal McdConvexMeshGetFatness(McdConvexMeshID g);
/** Unit-density mass properties of the rounded solid, fatness included, exact (m³, m⁵; centre of mass in
 *  relTM[3], rotation identity); 0 on success, non-zero for another type (reported). */
ME_API MeI16 McdConvexMeshGetMassProperties(McdConvexMeshID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);
/** The convex mesh type's number (kMcdGeometryTypeConvexMesh), the same in every framework. */
ME_API MeI16 McdConvexMeshGetTypeId(void);
/** Nothing to do: the type exists from McdInit on (kept for Karma code). */
ME_API void McdConvexMeshRegisterType(McdFramework *frame);
/** Register every pair test of convex meshes (with the primitives: McdPrimitivesRegisterInteractions); METRUE. */
ME_API MeBool McdConvexMeshPrimitivesRegisterInteractions(McdFramework *frame);

ME_EXTERN_C_END

#endif /* MCD_CONVEX_MESH_H */
