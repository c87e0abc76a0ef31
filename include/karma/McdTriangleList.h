/* McdTriangleList.h -- static terrain given by the application, triangle by triangle (Karma 1.2).
 *
 * The geometry holds a bounding box and a generator callback. When a pair with another model is
 * tested, the generator receives the other model's bounding sphere (centre `pos` and `radius`, in
 * the triangle list's frame) and fills up to `maxTriangles` McdUserTriangle records with the
 * triangles near it; their vertices and normals are read in the triangle list's frame and must stay
 * valid until the pair test returns. Triangle lists are static: no mass, no support point. */
#ifndef MCD_TRIANGLE_LIST_H
#define MCD_TRIANGLE_LIST_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Per-triangle flags. An edge "in use" may give the contact normal (a boundary or a sharp edge);
 *  an edge not in use never does (an internal edge of a flat or concave floor: no snagging). A
 *  triangle that is not two-sided pushes only along +normal (its solid side is behind it). */
typedef enum {
    kMcdTriangleUseSmallestPenetration = 1, /**< the least-penetration normal (else the face normal first) */
    kMcdTriangleTwoSided = 2,               /**< solid on neither side: pushes out of either face */
    kMcdTriangleUseEdge0 = 4,               /**< edge v1 - v0 in use */
    kMcdTriangleUseEdge1 = 8,               /**< edge v2 - v1 in use */
    kMcdTriangleUseEdge2 = 16,              /**< edge v0 - v2 in use */
    kMcdTriangleUseEdges = 28,
    kMcdTriangleStandard = 31               /**< Karma 1.0's triangles: every edge, two-sided */
} McdTriangleFlags;

/** One triangle given by the generator: pointers to its vertices and to its unit normal (right-hand
 *  rule over v0, v1, v2), the application's tag (reported as the contact's element2), its flags. */
typedef struct _McdUserTriangle {
    MeVector3 *vertices[3];
    MeVector3 *normal;
    union {
        void *ptr;
        int tag;
    } triangleData;
    McdTriangleFlags flags;
} McdUserTriangle;

/** The generator: fill at most maxTriangles records near the sphere (pos, radius) given in the
 *  triangle list's frame; return how many were filled. `modelTriListPair` is the pair being tested
 *  (either model may be the triangle list); for a segment query both models are the triangle list's. */
typedef int (*McdTriangleListFnPtr)(McdModelPair *modelTriListPair, McdUserTriangle *triangle, MeVector3 pos,
                                    MeReal radius, int maxTriangles);

/** A triangle list bounded by the local box [min, max] (each side > 0 and finite, within the size
 *  range), taking at most triangleMaxCount (1 ... 65536) triangles per pair from `generator` (not
 *  NULL). NULL (reported) otherwise. */
ME_API McdTriangleListID McdTriangleListCreate(McdFrameworkID fw, MeVector3 min, MeVector3 max, int triangleMaxCount,
                                               McdTriangleListFnPtr generator);
/** Change the number of triangles asked for per pair (1 ... 65536; others reported and ignored). */
ME_API void McdTriangleListSetMaxTriangles(McdTriangleListID g, int max);
/** The number of triangles asked for per pair; 0 for an invalid ID or another type (reported). */
ME_API int McdTriangleListGetMaxTriangles(McdTriangleListID g);
/** Change the local bounding box (checked as at creation; reaches models at their next update). */
ME_API void McdTriangleListSetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max);
/** The local bounding box into min and max. */
ME_API void McdTriangleListGetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max);
/** Replace the generator (not NULL). */
ME_API void McdTriangleListSetGenerator(McdTriangleListID g, McdTriangleListFnPtr f);
/** The generator; NULL for an invalid ID or another type (reported). */
ME_API McdTriangleListFnPtr McdTriangleListGetGenerator(McdTriangleListID g);
/** The application's pointer (NULL until set). */
ME_API void *McdTriangleListGetUserData(McdTriangleListID g);
/** Keep an application pointer with the triangle list (the generator finds it through the pair). */
ME_API void McdTriangleListSetUserData(McdTriangleListID g, void *data);
/** The triangle list's type number (kMcdGeometryTypeTriangleList). */
ME_API MeI16 McdTriangleListGetTypeId(void);

ME_EXTERN_C_END

#endif /* MCD_TRIANGLE_LIST_H */
