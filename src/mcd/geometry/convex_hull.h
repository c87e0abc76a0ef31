/* convex_hull.h -- the convex hull of a point cloud as polygons (internal).
 *
 * Built by Quickhull in double precision, then coplanar triangles are merged into convex polygons.
 * Tolerance: a point within `tolerance` of a face's plane counts as on it (docs/collision.md). */
#ifndef MCD_CONVEX_HULL_H
#define MCD_CONVEX_HULL_H

#include <karma/MeMath.h>

/* Points closer than this fraction of the cloud's bounding-box diagonal to a face's plane count as
 * on it (plus the rounding of MeReal coordinates, see McdHullTolerance). */
#define MCD_HULL_REL_TOL 1e-5

typedef struct McdHull {
    int vertexCount, polygonCount, edgeCount;
    MeVector3 *vertices;   /* the hull's vertices (input points, unchanged) */
    int *polygonStart;     /* polygonCount + 1 offsets into polygonVertices */
    int *polygonVertices;  /* vertex indices of each polygon, counter-clockwise seen from outside */
    MeVector3 *normals;    /* outward unit normal of each polygon */
    MeReal *offsets;       /* each polygon's plane: normal . x = offset (every vertex on or below it) */
    int *edges;            /* 2 * edgeCount vertex indices, each edge once */
    int *neighbourStart;   /* vertexCount + 1 offsets into neighbours */
    int *neighbours;       /* vertices joined to each vertex by an edge */
    int *vertexPolygonStart; /* vertexCount + 1 offsets into vertexPolygons */
    int *vertexPolygons;   /* polygons around each vertex */
    MeVector3 centre;      /* bounding sphere of the vertices */
    MeReal radius;
    MeReal tolerance;      /* the build's tolerance (m) */
    /* unit-density mass properties of the solid (the geometry fills them in; see convex_mesh.c) */
    MeReal volume;
    MeVector3 centreOfMass;
    MeMatrix3 inertia;     /* about the centre of mass */
} McdHull;

/** Outcome of a build. */
typedef enum McdHullStatus {
    MCD_HULL_OK = 0,
    MCD_HULL_FLAT,         /* fewer than 4 points, or all within tolerance of a line or a plane */
    MCD_HULL_NO_MEMORY
} McdHullStatus;

/** The tolerance the build of these points uses (m): MCD_HULL_REL_TOL times the bounding box's
 *  diagonal, plus 8 MeReal epsilons of the largest coordinate. Points must be finite. */
double McdHullTolerance(const MeVector3 *points, int n);
/** Build the hull of n finite points into *hull (arrays from MeMemoryCreate; free with McdHullFree). */
McdHullStatus McdHullBuild(const MeVector3 *points, int n, McdHull *hull);
/** Index of the vertex farthest along dir (local), climbing the vertex graph from vertex `start` to
 *  the best neighbour while it is farther (on a convex polyhedron, a vertex no neighbour improves on
 *  is the farthest; ties: one of them). In convex_mesh.c. */
int McdHullClimb(const McdHull *h, const MeVector3 dir, int start);
/** First entry of the segment p0 -> p1 (local) into the hull h rounded by r > 0, exactly (t in [0, 1],
 *  outward unit normal there; t = 0 and normal -(p1 - p0) when p0 is inside); 0 on a miss. In
 *  convex_segment.c. */
int McdRoundedHullSegment(const McdHull *h, MeReal r, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                          MeVector3 normal);
/** Free the arrays of a built hull (the struct itself is the caller's). */
void McdHullFree(McdHull *hull);

#endif /* MCD_CONVEX_HULL_H */
