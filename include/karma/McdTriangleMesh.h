/* McdTriangleMesh.h -- a static triangle mesh that owns its triangles (an addition to Karma 1.2).
 *
 * The vertices and the indices are copied at creation. A bounding-volume hierarchy (an AABB tree,
 * median split on the longest axis, up to 4 triangles per leaf) is built once, so a pair or a
 * segment visits O(log n) nodes. Adjacency is computed at creation from shared vertex indices: an
 * edge with one triangle (a boundary), more than two (non-manifold) or two meeting at a convex angle
 * of more than 2 degrees may give contact normals; a flat or concave internal edge never does (no
 * snagging when sliding across it). Triangles are two-sided; a contact's element2 is the triangle's
 * index cast to a pointer: (void *)(intptr_t)index. Meshes are static: no mass, no support point. */
#ifndef MCD_TRIANGLE_MESH_H
#define MCD_TRIANGLE_MESH_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdTriangleMeshID;

/** A mesh of triangleCount triangles (>= 1) over vertexCount vertices (>= 3, finite, within 1e7
 *  lengthScale of the origin); `indices` holds 3 vertex numbers per triangle (0 ... vertexCount-1,
 *  counter-clockwise seen from the front). Both arrays are copied. NULL (reported) for an empty
 *  mesh, an index out of range, a vertex that is not finite or a triangle of zero area. */
ME_API McdTriangleMeshID McdTriangleMeshCreate(McdFrameworkID fw, const MeVector3 *vertices, int vertexCount,
                                               const int *indices, int triangleCount);
/** Number of triangles; 0 for an invalid ID or another type (reported). */
ME_API int McdTriangleMeshGetTriangleCount(McdTriangleMeshID g);
/** The vertices of triangle `index` (local), and its flags (McdTriangleFlags: the edges in use).
 *  Returns 0, and writes nothing, for an index out of range or an invalid ID (reported). */
ME_API int McdTriangleMeshGetTriangle(McdTriangleMeshID g, int index, MeVector3 v0, MeVector3 v1, MeVector3 v2,
                                      int *flags);
/** The triangles whose boxes overlap the local box [min, max], up to maxCount indices into
 *  `out`; returns how many overlap (which may exceed maxCount). Uses the hierarchy. */
ME_API int McdTriangleMeshQueryBox(McdTriangleMeshID g, const MeVector3 min, const MeVector3 max, int *out,
                                   int maxCount);
/** The triangle mesh's type number (kMcdGeometryTypeTriangleMesh). */
ME_API MeI16 McdTriangleMeshGetTypeId(void);

ME_EXTERN_C_END

#endif /* MCD_TRIANGLE_MESH_H */
