/* McdQHullTypes.h -- Karma 1.2's convex hull as arrays: vertices, faces and directed edges with
 * their adjacency, as McdConvexMeshCreate takes it and McdConvexMeshGetPolyhedron gives it.
 *
 * Layout (1.2's): every edge is stored twice, once each way. The edges of face f are
 * edge[face[f].firstEdge] ... edge[face[f + 1].firstEdge - 1], a closed ring counter-clockwise seen
 * from outside; each has leftFace f and rightFace the face across it. The edges leaving vertex v are
 * edge[edgeIndex[vertex[v].firstEdgeIndex]] ... (up to vertex[v + 1].firstEdgeIndex), counter-clockwise
 * around v seen from outside. face[numFace] and vertex[numVertex] are sentinels whose firstEdge /
 * firstEdgeIndex is numEdge, so the arrays hold numFace + 1 faces and numVertex + 1 vertices.
 *
 * Arrays come from MeMemoryCreate (McdAllocateHull, McdComputeHull) and are freed, each, by
 * McdDeallocateHull; a convex mesh made by McdConvexMeshCreate takes them over. */
#ifndef MCD_QHULL_TYPES_H
#define MCD_QHULL_TYPES_H

#include "MeMath.h"

ME_EXTERN_C_BEGIN

/** A convex polyhedron as arrays (1.2's McdConvexHull; the struct is copied shallowly). */
typedef struct McdConvexHull {
    struct McdCnvVertex *vertex; /**< numVertex + 1 vertices (last: sentinel) */
    struct McdCnvFace *face;     /**< numFace + 1 faces (last: sentinel) */
    struct McdCnvEdge *edge;     /**< numEdge directed edges, grouped by leftFace, counter-clockwise */
    int *edgeIndex;              /**< numEdge edge numbers, grouped by fromVert, counter-clockwise */
    int numVertex;
    int numFace;
    int numEdge;                 /**< twice the polyhedron's edges */
} McdConvexHull;

/** A hull vertex. */
typedef struct McdCnvVertex {
    MeVector3 position;  /**< local frame, m */
    int firstEdgeIndex;  /**< first of its edges in edgeIndex */
} McdCnvVertex;

/** A hull face (a convex polygon). */
typedef struct McdCnvFace {
    MeVector3 normal; /**< outward unit normal */
    int firstEdge;    /**< first of its edges in edge */
} McdCnvFace;

/** A directed hull edge. */
typedef struct McdCnvEdge {
    MeReal invLength; /**< 1 / its length (1/m) */
    int fromVert;     /**< start vertex */
    int toVert;       /**< end vertex */
    int rightFace;    /**< face on its right (seen from outside) */
    int leftFace;     /**< face on its left: the face whose ring holds it */
} McdCnvEdge;

/** Build the hull of numpoints finite points (local, m) into *cnv, arrays from MeMemoryCreate (free
 *  with McdDeallocateHull); 1 on success, 0 and a report on NULL, fewer than 4 or non-finite points,
 *  or points spanning no volume (ME_ERR_MCD_HULL_FLAT; *cnv then untouched). */
ME_API int McdComputeHull(McdConvexHull *cnv, int numpoints, const MeVector3 *points);
/** First half of McdComputeHull: build the hull and set cnv's numVertex, numFace, numEdge (arrays
 *  untouched); the hull waits for McdGetHullData (one for the process, as 1.2's: a later call
 *  replaces it; threads building hulls at once use McdComputeHull). 1 or 0. */
ME_API int McdComputeHullSizes(McdConvexHull *cnv, int numpoints, const MeVector3 *points);
/** Allocate cnv's four arrays for its counts (faces and vertices with their sentinel); on a negative
 *  count (ME_ERR_ARGUMENT_RANGE) or no memory the pointers are set NULL. */
ME_API void McdAllocateHull(McdConvexHull *cnv);
/** Second half: fill cnv's arrays (allocated by the caller for the counts McdComputeHullSizes set)
 *  with the hull that call built, and let it go; 1, or 0 and a report when none waits
 *  (ME_ERR_BAD_STATE), an array is NULL or the counts differ (ME_ERR_MCD_HULL_INCONSISTENT). */
ME_API int McdGetHullData(McdConvexHull *cnv);
/** Free cnv's four arrays (MeMemoryDestroy) and set them NULL and the counts 0; NULL cnv ignored. */
ME_API void McdDeallocateHull(McdConvexHull *cnv);
/** Fill cnv (allocated for 3 vertices, 1 face, 3 edges) with the triangle p1 p2 p3 (counter-clockwise
 *  seen from its normal's side); a one-sided face, for the application's own use (a convex mesh
 *  needs a volume). */
ME_API void McdGetTriangleHull(McdConvexHull *cnv, const MeVector3 p1, const MeVector3 p2, const MeVector3 p3);

/* Accessors. An index out of range is reported (ME_ERR_ARGUMENT_RANGE) and gives 0, -1 or NULL. */

/** Number of edges (= vertices = neighbour faces) of face `face`. */
ME_API int McdCnvFaceGetCount(const McdConvexHull *cnv, int face);
/** Edge i (counter-clockwise) of face `face`; its rightFace is the neighbour across it. */
ME_API const McdCnvEdge *McdCnvFaceGetEdge(const McdConvexHull *cnv, int face, int i);
/** Index of vertex i of face `face` (the fromVert of its edge i); -1 out of range. */
ME_API int McdCnvFaceGetVertexId(const McdConvexHull *cnv, int face, int i);
/** Vertex i of face `face`. */
ME_API const McdCnvVertex *McdCnvFaceGetVertex(const McdConvexHull *cnv, int face, int i);
/** Position (local, m) of vertex i of face `face`. */
ME_API const MeReal *McdCnvFaceGetVertexPosition(const McdConvexHull *cnv, int face, int i);
/** Number of edges (= neighbour vertices = faces) around vertex `vertex`. */
ME_API int McdCnvVertexGetCount(const McdConvexHull *cnv, int vertex);
/** Index in cnv->edge of edge i (counter-clockwise) leaving vertex `vertex`; -1 out of range. */
ME_API int McdCnvVertexGetEdgeId(const McdConvexHull *cnv, int vertex, int i);
/** Edge i leaving vertex `vertex` (fromVert is `vertex`). */
ME_API const McdCnvEdge *McdCnvVertexGetEdge(const McdConvexHull *cnv, int vertex, int i);
/** Index of neighbour vertex i of vertex `vertex` (the toVert of its edge i); -1 out of range. */
ME_API int McdCnvVertexGetNeighbor(const McdConvexHull *cnv, int vertex, int i);

ME_EXTERN_C_END

#endif /* MCD_QHULL_TYPES_H */
