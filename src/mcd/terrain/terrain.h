/* terrain.h -- static triangle geometries: the triangle list (Karma's generator callback), the
 * triangle mesh (owned triangles, an AABB tree) and the regular-grid height field (internal).
 *
 * Each gives its triangles near a local box to a visitor; terrain/collide.c turns every triangle
 * into contacts with a convex primitive (GJK/EPA and the clipped manifold on a triangle core) with
 * the internal edges suppressed, and reduces them to at most four. */
#ifndef MCD_TERRAIN_H
#define MCD_TERRAIN_H

#include <karma/McdFrame.h>
#include <karma/McdRGHeightField.h>
#include <karma/McdTriangleList.h>
#include <karma/McdTriangleMesh.h>

#include "../framework.h"
#include "../nearfield/nearfield.h"

/* An edge between two triangles whose normals differ by more than this sine (2 degrees) at a convex
 * angle gives contact normals; flatter or concave internal edges do not. */
#define MCD_TERRAIN_ACTIVE_EDGE_SIN ME_R(0.035)
/* A segment may end this far (as a fraction of its length) past a triangle and still hit it. */
#define MCD_TERRAIN_SEGMENT_SLACK ME_R(1e-6)
/* Contacts whose depths differ by less than this times the convex's size are equally deep when the
 * set is reduced to four (a flat floor's contacts differ by rounding only). */
#define MCD_TERRAIN_DEPTH_TIE ME_R(1e-4)
/* Triangles per leaf of a mesh's tree. */
#define MCD_TERRAIN_LEAF_SIZE 4
/* Largest triangleMaxCount of a triangle list, grid side of a height field. */
#define MCD_TERRAIN_MAX_TRIANGLES 65536
#define MCD_TERRAIN_MAX_GRID 65536

/** One triangle handed to a visitor, in the terrain's frame. */
typedef struct McdTerrainTriangle {
    MeVector3 v[3];
    MeVector3 normal; /* unit, right-hand rule over v0 v1 v2 */
    int flags;        /* McdTriangleFlags */
    void *element;    /* the contact's element2 */
} McdTerrainTriangle;

/** A node of a mesh's AABB tree: a leaf when count > 0 (triangles order[first ... first+count-1]),
 *  else an inner node whose children are first and first + 1. */
typedef struct McdBvhNode {
    MeVector3 lo, hi;
    int first, count;
} McdBvhNode;

typedef struct McdTriangleListShape {
    MeVector3 lo, hi;
    int maxTriangles;
    McdTriangleListFnPtr generator;
    void *userData;
} McdTriangleListShape;

typedef struct McdTriangleMeshShape {
    MeVector3 *vertices;
    int vertexCount;
    int *indices;          /* 3 per triangle */
    MeVector3 *normals;    /* per triangle */
    unsigned char *flags;  /* per triangle: McdTriangleFlags (edges in use, smallest penetration, two-sided) */
    int triangleCount;
    McdBvhNode *nodes;
    int nodeCount;
    int *order;            /* triangle numbers in leaf order */
} McdTriangleMeshShape;

typedef struct McdHeightFieldShape {
    MeReal *heights;       /* nx * ny */
    unsigned char *holes;  /* (nx-1) * (ny-1), or NULL */
    int nx, ny;
    MeReal dx, dy, x0, y0;
    MeReal zMin, zMax;
} McdHeightFieldShape;

typedef struct McdTerrainData {
    union {
        McdTriangleListShape list;
        McdTriangleMeshShape mesh;
        McdHeightFieldShape field;
    } s;
} McdTerrainData;

extern const McdGeometryTypeDesc McdTriangleListTypeDesc;
extern const McdGeometryTypeDesc McdTriangleMeshTypeDesc;
extern const McdGeometryTypeDesc McdRGHeightFieldTypeDesc;

/** A visitor of triangles; returns MEFALSE to stop. */
typedef MeBool (*McdTerrainVisitFn)(void *ctx, const McdTerrainTriangle *t);

/** Mass properties of a static terrain: none (volume 0, identity frame, zero inertia). */
void McdTerrainMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume);

/** The part of a terrain asked for, in its frame: the box [lo, hi], and the sphere (centre, radius)
 *  that holds it, for a triangle list's generator. */
typedef struct McdTerrainRegion {
    MeVector3 lo, hi, centre;
    MeReal radius;
} McdTerrainRegion;

/** Hand the triangles of g (a terrain type) that may touch the region to visit. `pair` goes to the
 *  triangle list's generator. */
void McdTerrainForEach(const McdGeometryData *g, const McdTerrainRegion *region, McdModelPair *pair,
                       McdTerrainVisitFn visit, void *ctx);
/** Each terrain type's own enumeration (as McdTerrainForEach). */
void McdTriangleListForEach(const McdTriangleListShape *s, const MeVector3 centre, MeReal radius, McdModelPair *pair,
                            McdTerrainVisitFn visit, void *ctx);
void McdTriangleMeshForEach(const McdTriangleMeshShape *s, const MeVector3 lo, const MeVector3 hi,
                            McdTerrainVisitFn visit, void *ctx);
void McdHeightFieldForEach(const McdHeightFieldShape *s, const MeVector3 lo, const MeVector3 hi,
                           McdTerrainVisitFn visit, void *ctx);

/** First hit of the local segment p0 -> p1 on the triangles near it: METRUE with t in [0, 1] and
 *  the unit normal facing the segment (one-sided triangles are hit from the front only). */
MeBool McdTerrainSegment(const McdGeometryData *g, const MeVector3 p0, const MeVector3 p1, McdModelPair *pair,
                         MeReal *t, MeVector3 normal);
/** Segment query of a model whose geometry is a triangle list (its generator needs the model):
 *  0 or 1 as McdModelLineSegIntersectInternal. */
int McdTriangleListModelSegment(const McdModelData *m, const MeVector3 p0, const MeVector3 p1,
                                McdLineSegIntersectResult *result);

/** First hit of the segment p0 + t d, t in [0, tMax), on one triangle: METRUE and *t. */
MeBool McdTerrainSegmentTriangle(const McdTerrainTriangle *tri, const MeVector3 p0, const MeVector3 d, MeReal tMax,
                                 MeReal *t);

/** The pair test of a convex primitive (g1) against a terrain geometry (g2). */
int McdNfConvexTerrain(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                       MeReal tolerance, McdContact *contacts, int maxContacts, void **cache);

/** The terrain pair tests (registered with the primitives' by McdPrimitivesRegisterInteractions). */
const McdNfPairEntry *McdTerrainPairTable(int *count);

/** Shared checks: a local box must have finite corners with lo < hi on each axis (sizes within
 *  the framework's range): ME_ERR_MCD_DEGENERATE_GEOMETRY / ME_ERR_MCD_SIZE_RANGE otherwise. */
MeBool McdTerrainCheckBox(const McdFrameworkData *fw, const MeVector3 lo, const MeVector3 hi, const char *function);
/** The terrain data of g when it is of `type` (reported in `function` otherwise), or NULL. */
McdTerrainData *McdTerrainOfType(McdGeometryID id, int type, const char *function);

#endif /* MCD_TERRAIN_H */
