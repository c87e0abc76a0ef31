/* hull_arrays.h -- Karma 1.2's McdConvexHull arrays made from the polygons of a built hull, and
 * checked when an application hands them in (internal). */
#ifndef MCD_HULL_ARRAYS_H
#define MCD_HULL_ARRAYS_H

#include <karma/McdQHullTypes.h>

#include "convex_hull.h"

/* A handed-in hull's vertices must lie within this fraction of their bounding box's diagonal (plus
 * the rounding of MeReal coordinates) of their faces' planes, and no farther in front of any face:
 * ten times the build's MCD_HULL_REL_TOL, so every hull McdComputeHull makes passes. */
#define MCD_HULL_CHECK_REL_TOL 1e-4

/** Allocate cnv's arrays and fill them from the built hull h (same vertex and polygon order); MEFALSE
 *  (cnv's pointers NULL, reported in `function`'s name) when memory runs out. */
MeBool McdConvexHullFromHull(const McdHull *h, McdConvexHull *cnv, const char *function);
/** A copy of cnv's vertex positions (MeMemoryCreate: the caller frees it); NULL when memory runs out. */
MeVector3 *McdConvexHullPositions(const McdConvexHull *cnv);
/** Points for a hull: not NULL, at least 4 (ME_ERR_MCD_HULL_FLAT), finite (ME_ERR_NONFINITE_ARGUMENT);
 *  reported in `function`'s name. */
MeBool McdHullCheckPoints(const MeVector3 *points, int n, const char *function);
/** A handed-in hull must be a closed, consistently wound, convex polyhedron: NULL arrays
 *  (ME_ERR_NULL_ARGUMENT), counts, indices, rings, reverse edges or vertex order that disagree
 *  (ME_ERR_MCD_HULL_INCONSISTENT), non-finite values (ME_ERR_NONFINITE_ARGUMENT), a vertex off its
 *  face's plane or in front of another, a normal not unit or against the winding, a reflex polygon
 *  corner (ME_ERR_MCD_HULL_NOT_CONVEX) are reported in `function`'s name. */
MeBool McdConvexHullCheck(const McdConvexHull *cnv, const char *function);

#endif /* MCD_HULL_ARRAYS_H */
